//! Message and service types on the wire: plain serde structs whose fields
//! follow the `.msg` / `.srv` definitions in order (CDR is positional).
//!
//! ros2-client ships only `builtin_interfaces` and `rcl_interfaces`, so the
//! standard types this node speaks (std_msgs, geometry_msgs, sensor_msgs,
//! tf2_msgs, rosgraph_msgs, diagnostic_msgs, std_srvs) are defined here, next
//! to this package's own `msg/*.msg` and `srv/*.srv`. The test
//! `tests/ros_messages_match_msg_files.rs` checks every struct against its
//! definition (ours parsed from `msg/`, `srv/`; the standard ones against
//! their upstream text).
//!
//! Each top-level type also carries its ROS type name ([`RosType`]), so a
//! topic can never be created with a type name that disagrees with its struct.

use ros2_client::Message;
use serde::{Deserialize, Serialize};

/// The ROS 2 interface name of a top-level message or service type.
pub trait RosType {
    /// Package, e.g. `sensor_msgs`.
    const PACKAGE: &'static str;
    /// Type, e.g. `JointState`.
    const NAME: &'static str;
}

macro_rules! ros_message {
    ($t:ty, $pkg:literal, $name:literal) => {
        impl Message for $t {}
        impl RosType for $t {
            const PACKAGE: &'static str = $pkg;
            const NAME: &'static str = $name;
        }
    };
}

// ---- builtin_interfaces ---------------------------------------------------

/// builtin_interfaces/Time.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Default, Serialize, Deserialize)]
pub struct Time {
    /// Whole seconds (of the Unix epoch for wall time, of simulated time under `/clock`).
    pub sec: i32,
    /// Nanoseconds within the second, 0 ..< 1e9.
    pub nanosec: u32,
}

impl Time {
    /// From nanoseconds (non-negative; negative values clamp to zero).
    pub fn from_nanos(nanos: i64) -> Time {
        let n = nanos.max(0);
        Time {
            sec: (n / 1_000_000_000).min(i32::MAX as i64) as i32,
            nanosec: (n % 1_000_000_000) as u32,
        }
    }

    /// Nanoseconds in all.
    pub fn to_nanos(self) -> i64 {
        self.sec as i64 * 1_000_000_000 + self.nanosec as i64
    }

    /// Seconds in all.
    pub fn to_secs(self) -> f64 {
        self.sec as f64 + self.nanosec as f64 * 1e-9
    }

    /// The wall clock (system time since the Unix epoch).
    pub fn wall_now() -> Time {
        let d = std::time::SystemTime::now()
            .duration_since(std::time::UNIX_EPOCH)
            .unwrap_or_default();
        Time::from_nanos(d.as_nanos().min(i64::MAX as u128) as i64)
    }
}

// ---- std_msgs ---------------------------------------------------------------

/// std_msgs/Header.
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
pub struct Header {
    /// When the data holds.
    pub stamp: Time,
    /// The frame the data is expressed in (empty where unused).
    pub frame_id: String,
}
ros_message!(Header, "std_msgs", "Header");

/// std_msgs/Float64.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
pub struct Float64 {
    /// The value.
    pub data: f64,
}
ros_message!(Float64, "std_msgs", "Float64");

// ---- geometry_msgs ----------------------------------------------------------

/// geometry_msgs/Vector3.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
pub struct Vector3 {
    /// x component.
    pub x: f64,
    /// y component.
    pub y: f64,
    /// z component.
    pub z: f64,
}

impl Vector3 {
    /// From `[x, y, z]`.
    pub fn from_array(a: [f64; 3]) -> Vector3 {
        Vector3 {
            x: a[0],
            y: a[1],
            z: a[2],
        }
    }
    /// As `[x, y, z]`.
    pub fn to_array(self) -> [f64; 3] {
        [self.x, self.y, self.z]
    }
}

/// geometry_msgs/Quaternion.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Quaternion {
    /// x of the vector part.
    pub x: f64,
    /// y of the vector part.
    pub y: f64,
    /// z of the vector part.
    pub z: f64,
    /// The scalar part (1 for the identity rotation).
    pub w: f64,
}

impl Default for Quaternion {
    fn default() -> Self {
        Quaternion {
            x: 0.0,
            y: 0.0,
            z: 0.0,
            w: 1.0,
        }
    }
}

impl Quaternion {
    /// From `[x, y, z, w]`.
    pub fn from_xyzw(q: [f64; 4]) -> Quaternion {
        Quaternion {
            x: q[0],
            y: q[1],
            z: q[2],
            w: q[3],
        }
    }
}

/// geometry_msgs/Transform.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
pub struct Transform {
    /// Translation of the child frame's origin in the parent frame, m.
    pub translation: Vector3,
    /// Rotation from the child frame to the parent frame (unit quaternion).
    pub rotation: Quaternion,
}

/// geometry_msgs/TransformStamped.
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
pub struct TransformStamped {
    /// Stamp, and the parent frame in `frame_id`.
    pub header: Header,
    /// The child frame.
    pub child_frame_id: String,
    /// The child frame's pose in the parent frame.
    pub transform: Transform,
}
ros_message!(TransformStamped, "geometry_msgs", "TransformStamped");

/// geometry_msgs/Wrench.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
pub struct Wrench {
    /// Force, N.
    pub force: Vector3,
    /// Torque (moment), N m.
    pub torque: Vector3,
}
ros_message!(Wrench, "geometry_msgs", "Wrench");

/// geometry_msgs/WrenchStamped.
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
pub struct WrenchStamped {
    /// Stamp, and the frame the wrench is expressed in.
    pub header: Header,
    /// The force and moment.
    pub wrench: Wrench,
}
ros_message!(WrenchStamped, "geometry_msgs", "WrenchStamped");

// ---- tf2_msgs, sensor_msgs, rosgraph_msgs ------------------------------------

/// tf2_msgs/TFMessage (on `/tf` and `/tf_static`).
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
pub struct TFMessage {
    /// The transforms, each parent → child.
    pub transforms: Vec<TransformStamped>,
}
ros_message!(TFMessage, "tf2_msgs", "TFMessage");

/// sensor_msgs/JointState.
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
pub struct JointState {
    /// The step's time; `frame_id` empty.
    pub header: Header,
    /// Joint names, one per entry of the other arrays.
    pub name: Vec<String>,
    /// Joint angles, rad.
    pub position: Vec<f64>,
    /// Joint speeds, rad/s.
    pub velocity: Vec<f64>,
    /// Joint torques, N m.
    pub effort: Vec<f64>,
}
ros_message!(JointState, "sensor_msgs", "JointState");

/// rosgraph_msgs/Clock: the only type `/clock` carries (see `messages/clock.rs`).
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
pub struct Clock {
    /// The simulated time.
    pub clock: Time,
}
ros_message!(Clock, "rosgraph_msgs", "Clock");

// ---- diagnostic_msgs ----------------------------------------------------------

/// diagnostic_msgs/KeyValue.
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
pub struct KeyValue {
    /// The name of the value.
    pub key: String,
    /// The value, as text.
    pub value: String,
}

/// diagnostic_msgs/DiagnosticStatus.
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
pub struct DiagnosticStatus {
    /// [`DiagnosticStatus::OK`] … [`DiagnosticStatus::STALE`] (`byte` in the .msg).
    pub level: u8,
    /// What is reported on (`<node>: <part>`).
    pub name: String,
    /// A one-line summary of the status.
    pub message: String,
    /// The unit reported on (the node's name here).
    pub hardware_id: String,
    /// The measured values, by key.
    pub values: Vec<KeyValue>,
}

impl DiagnosticStatus {
    /// `level`: all is well.
    pub const OK: u8 = 0;
    /// `level`: a warning.
    pub const WARN: u8 = 1;
    /// `level`: an error.
    pub const ERROR: u8 = 2;
    /// `level`: no recent data.
    pub const STALE: u8 = 3;
}

/// diagnostic_msgs/DiagnosticArray.
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
pub struct DiagnosticArray {
    /// When the statuses were taken.
    pub header: Header,
    /// One status per part reported on.
    pub status: Vec<DiagnosticStatus>,
}
ros_message!(DiagnosticArray, "diagnostic_msgs", "DiagnosticArray");

// ---- std_srvs -------------------------------------------------------------------

/// std_srvs/Trigger request. The .srv request is empty; ROS 2's IDL gives an
/// empty structure one `uint8 structure_needs_at_least_one_member`.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
pub struct TriggerRequest {
    /// Always 0: the member ROS 2's IDL gives an empty structure.
    pub structure_needs_at_least_one_member: u8,
}
impl Message for TriggerRequest {}

/// std_srvs/Trigger response.
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
pub struct TriggerResponse {
    /// Whether the request was carried out.
    pub success: bool,
    /// What was done, or why not.
    pub message: String,
}
impl Message for TriggerResponse {}

/// std_srvs/SetBool request.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
pub struct SetBoolRequest {
    /// The value to set.
    pub data: bool,
}
impl Message for SetBoolRequest {}

/// std_srvs/SetBool response.
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
pub struct SetBoolResponse {
    /// Whether the value was set.
    pub success: bool,
    /// What was done, or why not.
    pub message: String,
}
impl Message for SetBoolResponse {}

// ---- annular_plate (msg/, srv/) ------------------------------------------------

/// annular_plate/msg/ModalAmplitudes (`msg/ModalAmplitudes.msg`).
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
pub struct ModalAmplitudes {
    /// The step's time; `frame_id` the reference frame (plate_base).
    pub header: Header,
    /// Output steps since start or the last reset.
    pub step: u64,
    /// Simulated time since start or the last reset, s.
    pub sim_time: f64,
    /// `header.stamp` of the newest stamped input applied before this step (zero: none yet).
    pub input_stamp: Time,
    /// Nodal diameters k, one per elastic mode: the bending modes, then the
    /// in-plane modes (each sorted by frequency).
    pub k: Vec<u32>,
    /// Nodal circles l, per mode.
    pub l: Vec<u32>,
    /// Angular shape per mode: one of the `SHAPE_*` constants.
    pub shape: Vec<u8>,
    /// Natural frequency of the non-rotating plate per mode, Hz.
    pub frequency_hz: Vec<f64>,
    /// Amplitudes in the rotating plate frame (plate_rotor), m (1 = 1 m peak
    /// transverse displacement for a bending mode, in-plane for an in-plane one).
    pub q_lagrange: Vec<f64>,
    /// Their rates, m/s.
    pub q_dot_lagrange: Vec<f64>,
    /// The same deformation seen from the non-rotating reference frame (plate_base), m.
    pub q_ale: Vec<f64>,
    /// Their rates, m/s.
    pub q_dot_ale: Vec<f64>,
}
ros_message!(ModalAmplitudes, "annular_plate", "ModalAmplitudes");

impl ModalAmplitudes {
    /// Bending, k = 0: w ~ R(r).
    pub const SHAPE_AXISYMMETRIC: u8 = 0;
    /// Bending: w ~ R(r) cos(k φ).
    pub const SHAPE_COS: u8 = 1;
    /// Bending: w ~ R(r) sin(k φ).
    pub const SHAPE_SIN: u8 = 2;
    /// In-plane, k = 0: u_φ ~ V(r).
    pub const SHAPE_TORSIONAL: u8 = 3;
    /// In-plane, k = 0: u_r ~ U(r).
    pub const SHAPE_RADIAL: u8 = 4;
    /// In-plane: u_r ~ U(r) cos(k φ), u_φ ~ V(r) sin(k φ).
    pub const SHAPE_IN_PLANE_COS: u8 = 5;
    /// In-plane: u_r ~ U(r) sin(k φ), u_φ ~ −V(r) cos(k φ).
    pub const SHAPE_IN_PLANE_SIN: u8 = 6;
}

/// annular_plate/msg/CriticalSpeeds (`msg/CriticalSpeeds.msg`).
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
pub struct CriticalSpeeds {
    /// Whether the speeds include the spinning prestress's geometric stiffness (`plate.centrifugal_stiffening`; else ω/k).
    pub centrifugal_stiffening: bool,
    /// Nodal diameters k (≥ 1), ascending k then l.
    pub k: Vec<u32>,
    /// Nodal circles l, per entry.
    pub l: Vec<u32>,
    /// Critical speed per entry, rad/s: where the backward wave stands still in space, ω(Ω) = k Ω.
    pub rad_s: Vec<f64>,
}
ros_message!(CriticalSpeeds, "annular_plate", "CriticalSpeeds");

/// annular_plate/msg/NodeWrench (`msg/NodeWrench.msg`).
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
pub struct NodeWrench {
    /// [`NodeWrench::ALE`] or [`NodeWrench::LAGRANGE`].
    pub kind: u8,
    /// Node number j, from 1 (as in the frame name).
    pub index: u32,
    /// N and N m, in that node's frame; held until replaced.
    pub wrench: Wrench,
}
ros_message!(NodeWrench, "annular_plate", "NodeWrench");

impl NodeWrench {
    /// `kind`: the space-fixed node frame `plate_ale_<j>`.
    pub const ALE: u8 = 0;
    /// `kind`: the material node frame `plate_lagrange_<j>`.
    pub const LAGRANGE: u8 = 1;
}

/// annular_plate/msg/NodeWrenchArray (`msg/NodeWrenchArray.msg`).
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
pub struct NodeWrenchArray {
    /// Stamp (echoed as `ModalAmplitudes::input_stamp`); `frame_id` empty.
    pub header: Header,
    /// The wrenches, applied all together or not at all.
    pub wrenches: Vec<NodeWrench>,
}
ros_message!(NodeWrenchArray, "annular_plate", "NodeWrenchArray");

/// annular_plate/msg/PadClampForces (`msg/PadClampForces.msg`).
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
pub struct PadClampForces {
    /// Stamp (echoed as `ModalAmplitudes::input_stamp`); `frame_id` unused.
    pub header: Header,
    /// Pad numbers j, from 1.
    pub pad: Vec<u32>,
    /// Force each face of the disc is pressed with, N, one per entry of `pad`.
    pub clamp_force: Vec<f64>,
}
ros_message!(PadClampForces, "annular_plate", "PadClampForces");

/// annular_plate/srv/Step request (`srv/Step.srv`).
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
pub struct StepRequest {
    /// Output steps to take (1/simulation.rate_hz each); 0 only reports the
    /// state.
    pub steps: u32,
}
impl Message for StepRequest {}

/// annular_plate/srv/Step response.
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
pub struct StepResponse {
    /// Whether the steps were taken.
    pub success: bool,
    /// What was done, or why not.
    pub message: String,
    /// Output steps since start or the last reset, after the request.
    pub step: u64,
    /// Simulated time since start or the last reset, s, after the request.
    pub sim_time: f64,
}
impl Message for StepResponse {}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn time_round_trips_nanos() {
        let t = Time::from_nanos(3_000_000_123);
        assert_eq!(
            t,
            Time {
                sec: 3,
                nanosec: 123
            }
        );
        assert_eq!(t.to_nanos(), 3_000_000_123);
        assert_eq!(Time::from_nanos(-5), Time::default());
    }
}
