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
    pub sec: i32,
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

    pub fn to_nanos(self) -> i64 {
        self.sec as i64 * 1_000_000_000 + self.nanosec as i64
    }

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
    pub stamp: Time,
    pub frame_id: String,
}
ros_message!(Header, "std_msgs", "Header");

/// std_msgs/Float64.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
pub struct Float64 {
    pub data: f64,
}
ros_message!(Float64, "std_msgs", "Float64");

// ---- geometry_msgs ----------------------------------------------------------

/// geometry_msgs/Vector3.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
pub struct Vector3 {
    pub x: f64,
    pub y: f64,
    pub z: f64,
}

impl Vector3 {
    pub fn from_array(a: [f64; 3]) -> Vector3 {
        Vector3 {
            x: a[0],
            y: a[1],
            z: a[2],
        }
    }
    pub fn to_array(self) -> [f64; 3] {
        [self.x, self.y, self.z]
    }
}

/// geometry_msgs/Quaternion.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Quaternion {
    pub x: f64,
    pub y: f64,
    pub z: f64,
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
    pub translation: Vector3,
    pub rotation: Quaternion,
}

/// geometry_msgs/TransformStamped.
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
pub struct TransformStamped {
    pub header: Header,
    pub child_frame_id: String,
    pub transform: Transform,
}
ros_message!(TransformStamped, "geometry_msgs", "TransformStamped");

/// geometry_msgs/Wrench.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
pub struct Wrench {
    pub force: Vector3,
    pub torque: Vector3,
}
ros_message!(Wrench, "geometry_msgs", "Wrench");

/// geometry_msgs/WrenchStamped.
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
pub struct WrenchStamped {
    pub header: Header,
    pub wrench: Wrench,
}
ros_message!(WrenchStamped, "geometry_msgs", "WrenchStamped");

// ---- tf2_msgs, sensor_msgs, rosgraph_msgs ------------------------------------

/// tf2_msgs/TFMessage (on `/tf` and `/tf_static`).
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
pub struct TFMessage {
    pub transforms: Vec<TransformStamped>,
}
ros_message!(TFMessage, "tf2_msgs", "TFMessage");

/// sensor_msgs/JointState.
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
pub struct JointState {
    pub header: Header,
    pub name: Vec<String>,
    pub position: Vec<f64>,
    pub velocity: Vec<f64>,
    pub effort: Vec<f64>,
}
ros_message!(JointState, "sensor_msgs", "JointState");

/// rosgraph_msgs/Clock: the only type `/clock` carries (see `messages/clock.rs`).
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
pub struct Clock {
    pub clock: Time,
}
ros_message!(Clock, "rosgraph_msgs", "Clock");

// ---- diagnostic_msgs ----------------------------------------------------------

/// diagnostic_msgs/KeyValue.
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
pub struct KeyValue {
    pub key: String,
    pub value: String,
}

/// diagnostic_msgs/DiagnosticStatus.
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
pub struct DiagnosticStatus {
    /// [`DiagnosticStatus::OK`] … [`DiagnosticStatus::STALE`] (`byte` in the .msg).
    pub level: u8,
    pub name: String,
    pub message: String,
    pub hardware_id: String,
    pub values: Vec<KeyValue>,
}

impl DiagnosticStatus {
    pub const OK: u8 = 0;
    pub const WARN: u8 = 1;
    pub const ERROR: u8 = 2;
    pub const STALE: u8 = 3;
}

/// diagnostic_msgs/DiagnosticArray.
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
pub struct DiagnosticArray {
    pub header: Header,
    pub status: Vec<DiagnosticStatus>,
}
ros_message!(DiagnosticArray, "diagnostic_msgs", "DiagnosticArray");

// ---- std_srvs -------------------------------------------------------------------

/// std_srvs/Trigger request. The .srv request is empty; ROS 2's IDL gives an
/// empty structure one `uint8 structure_needs_at_least_one_member`.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
pub struct TriggerRequest {
    pub structure_needs_at_least_one_member: u8,
}
impl Message for TriggerRequest {}

/// std_srvs/Trigger response.
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
pub struct TriggerResponse {
    pub success: bool,
    pub message: String,
}
impl Message for TriggerResponse {}

/// std_srvs/SetBool request.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
pub struct SetBoolRequest {
    pub data: bool,
}
impl Message for SetBoolRequest {}

/// std_srvs/SetBool response.
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
pub struct SetBoolResponse {
    pub success: bool,
    pub message: String,
}
impl Message for SetBoolResponse {}

// ---- annular_plate (msg/, srv/) ------------------------------------------------

/// annular_plate/msg/ModalAmplitudes (`msg/ModalAmplitudes.msg`).
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
pub struct ModalAmplitudes {
    pub header: Header,
    pub step: u64,
    pub sim_time: f64,
    pub input_stamp: Time,
    pub k: Vec<u32>,
    pub l: Vec<u32>,
    pub shape: Vec<u8>,
    pub frequency_hz: Vec<f64>,
    pub q_lagrange: Vec<f64>,
    pub q_dot_lagrange: Vec<f64>,
    pub q_ale: Vec<f64>,
    pub q_dot_ale: Vec<f64>,
}
ros_message!(ModalAmplitudes, "annular_plate", "ModalAmplitudes");

impl ModalAmplitudes {
    pub const SHAPE_AXISYMMETRIC: u8 = 0;
    pub const SHAPE_COS: u8 = 1;
    pub const SHAPE_SIN: u8 = 2;
}

/// annular_plate/msg/CriticalSpeeds (`msg/CriticalSpeeds.msg`).
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
pub struct CriticalSpeeds {
    pub centrifugal_stiffening: bool,
    pub k: Vec<u32>,
    pub l: Vec<u32>,
    pub rad_s: Vec<f64>,
}
ros_message!(CriticalSpeeds, "annular_plate", "CriticalSpeeds");

/// annular_plate/msg/NodeWrench (`msg/NodeWrench.msg`).
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
pub struct NodeWrench {
    pub kind: u8,
    pub index: u32,
    pub wrench: Wrench,
}
ros_message!(NodeWrench, "annular_plate", "NodeWrench");

impl NodeWrench {
    pub const ALE: u8 = 0;
    pub const LAGRANGE: u8 = 1;
}

/// annular_plate/msg/NodeWrenchArray (`msg/NodeWrenchArray.msg`).
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
pub struct NodeWrenchArray {
    pub header: Header,
    pub wrenches: Vec<NodeWrench>,
}
ros_message!(NodeWrenchArray, "annular_plate", "NodeWrenchArray");

/// annular_plate/msg/PadClampForces (`msg/PadClampForces.msg`).
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
pub struct PadClampForces {
    pub header: Header,
    pub pad: Vec<u32>,
    pub clamp_force: Vec<f64>,
}
ros_message!(PadClampForces, "annular_plate", "PadClampForces");

/// annular_plate/srv/Step request (`srv/Step.srv`).
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
pub struct StepRequest {
    pub steps: u32,
}
impl Message for StepRequest {}

/// annular_plate/srv/Step response.
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
pub struct StepResponse {
    pub success: bool,
    pub message: String,
    pub step: u64,
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
