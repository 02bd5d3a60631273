//! The standard types of `~/plate_marker` (visualization_msgs/MarkerArray as
//! in ROS 2 Humble and Jazzy), plain serde structs in `.msg` field order like
//! those in [`types`](super::types); `tests/ros_messages_match_msg_files.rs`
//! checks them against the upstream definitions.

use super::types::{Header, Quaternion, RosType, Vector3};
use ros2_client::Message;
use serde::{Deserialize, Serialize};

/// builtin_interfaces/Duration.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
pub struct Duration {
    /// Whole seconds.
    pub sec: i32,
    /// Nanoseconds within the second, 0 ..< 1e9.
    pub nanosec: u32,
}

/// std_msgs/ColorRGBA (each component 0..1).
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
pub struct ColorRGBA {
    /// Red, 0..1.
    pub r: f32,
    /// Green, 0..1.
    pub g: f32,
    /// Blue, 0..1.
    pub b: f32,
    /// Opacity, 0..1 (1 opaque).
    pub a: f32,
}

/// geometry_msgs/Point.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
pub struct Point {
    /// x, m.
    pub x: f64,
    /// y, m.
    pub y: f64,
    /// z, m.
    pub z: f64,
}

/// geometry_msgs/Pose.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
pub struct Pose {
    /// Origin in the parent frame, m.
    pub position: Point,
    /// Orientation in the parent frame (unit quaternion).
    pub orientation: Quaternion,
}

/// sensor_msgs/CompressedImage (a marker's optional texture; empty here).
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
pub struct CompressedImage {
    /// Stamp and frame of the image.
    pub header: Header,
    /// Encoding (`jpeg`, `png`; empty here).
    pub format: String,
    /// The encoded image (empty here).
    pub data: Vec<u8>,
}

/// visualization_msgs/UVCoordinate.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
pub struct UVCoordinate {
    /// Texture coordinate u, 0..1.
    pub u: f32,
    /// Texture coordinate v, 0..1.
    pub v: f32,
}

/// visualization_msgs/MeshFile (empty here).
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
pub struct MeshFile {
    /// The mesh's file name (empty here).
    pub filename: String,
    /// The mesh file's bytes (empty here).
    pub data: Vec<u8>,
}

/// visualization_msgs/Marker.
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
pub struct Marker {
    /// Stamp, and the frame the points are expressed in.
    pub header: Header,
    /// Namespace; with `id` it names the marker.
    pub ns: String,
    /// Id within `ns`; a marker with the same `ns` and `id` replaces it.
    pub id: i32,
    /// [`Marker::ARROW`], [`Marker::TRIANGLE_LIST`], …
    #[serde(rename = "type")]
    pub kind: i32,
    /// [`Marker::ADD`] (add or replace) or [`Marker::DELETEALL`].
    pub action: i32,
    /// Pose of the points' frame relative to `header.frame_id`.
    pub pose: Pose,
    /// Scale per axis; what it scales depends on `kind` (see
    /// visualization_msgs/Marker).
    pub scale: Vector3,
    /// Colour when `colors` is empty.
    pub color: ColorRGBA,
    /// How long the marker lives (zero: until replaced).
    pub lifetime: Duration,
    /// Whether the marker follows its frame over time.
    pub frame_locked: bool,
    /// The vertices (three per triangle; start and end for an arrow), m.
    pub points: Vec<Point>,
    /// One colour per point (or empty).
    pub colors: Vec<ColorRGBA>,
    /// Texture URI (empty here).
    pub texture_resource: String,
    /// Embedded texture (empty here).
    pub texture: CompressedImage,
    /// Texture coordinates per point (empty here).
    pub uv_coordinates: Vec<UVCoordinate>,
    /// Text of a text marker (empty here).
    pub text: String,
    /// Mesh URI of a mesh marker (empty here).
    pub mesh_resource: String,
    /// Embedded mesh (empty here).
    pub mesh_file: MeshFile,
    /// Whether a mesh uses its own materials (false here).
    pub mesh_use_embedded_materials: bool,
}

impl Marker {
    /// `kind`: an arrow.
    pub const ARROW: i32 = 0;
    /// `kind`: a list of triangles, three points each.
    pub const TRIANGLE_LIST: i32 = 11;
    /// `action`: add, or replace the marker with the same `ns` and `id`.
    pub const ADD: i32 = 0;
    /// `action`: delete every marker of this display.
    pub const DELETEALL: i32 = 3;
}

/// visualization_msgs/MarkerArray.
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
pub struct MarkerArray {
    /// The markers, drawn together.
    pub markers: Vec<Marker>,
}

impl Message for Marker {}
impl RosType for Marker {
    const PACKAGE: &'static str = "visualization_msgs";
    const NAME: &'static str = "Marker";
}
impl Message for MarkerArray {}
impl RosType for MarkerArray {
    const PACKAGE: &'static str = "visualization_msgs";
    const NAME: &'static str = "MarkerArray";
}
