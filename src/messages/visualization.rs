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
    pub sec: i32,
    pub nanosec: u32,
}

/// std_msgs/ColorRGBA (each component 0..1).
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
pub struct ColorRGBA {
    pub r: f32,
    pub g: f32,
    pub b: f32,
    pub a: f32,
}

/// geometry_msgs/Point.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
pub struct Point {
    pub x: f64,
    pub y: f64,
    pub z: f64,
}

/// geometry_msgs/Pose.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
pub struct Pose {
    pub position: Point,
    pub orientation: Quaternion,
}

/// sensor_msgs/CompressedImage (a marker's optional texture; empty here).
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
pub struct CompressedImage {
    pub header: Header,
    pub format: String,
    pub data: Vec<u8>,
}

/// visualization_msgs/UVCoordinate.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
pub struct UVCoordinate {
    pub u: f32,
    pub v: f32,
}

/// visualization_msgs/MeshFile (empty here).
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
pub struct MeshFile {
    pub filename: String,
    pub data: Vec<u8>,
}

/// visualization_msgs/Marker.
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
pub struct Marker {
    pub header: Header,
    pub ns: String,
    pub id: i32,
    /// [`Marker::ARROW`], [`Marker::TRIANGLE_LIST`], …
    #[serde(rename = "type")]
    pub kind: i32,
    pub action: i32,
    pub pose: Pose,
    pub scale: Vector3,
    pub color: ColorRGBA,
    pub lifetime: Duration,
    pub frame_locked: bool,
    pub points: Vec<Point>,
    pub colors: Vec<ColorRGBA>,
    pub texture_resource: String,
    pub texture: CompressedImage,
    pub uv_coordinates: Vec<UVCoordinate>,
    pub text: String,
    pub mesh_resource: String,
    pub mesh_file: MeshFile,
    pub mesh_use_embedded_materials: bool,
}

impl Marker {
    pub const ARROW: i32 = 0;
    pub const TRIANGLE_LIST: i32 = 11;
    pub const ADD: i32 = 0;
    pub const DELETEALL: i32 = 3;
}

/// visualization_msgs/MarkerArray.
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
pub struct MarkerArray {
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
