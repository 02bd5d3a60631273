//! The ROS side's data, shared by the node (`ros`) and the recorder (`bag`),
//! which never import each other: the message structs (`msg/*.msg` and the
//! standard types they use), the building of the output messages from a
//! simulation, topic names and QoS profiles, ROS name resolution and the
//! node's `ros.*` settings, the step clock's stamps, the diagnostics
//! messages and the input counters they report.
//!
//! Data flows one way: `dynamics` → `messages` → `ros` / `bag` / `cli`.

pub mod clock;
pub(crate) mod clock_follower;
pub(crate) mod critical_speeds;
pub(crate) mod diagnostics;
pub(crate) mod input_stats;
pub(crate) mod marker;
pub(crate) mod model_states;
pub(crate) mod names;
pub mod outputs;
pub(crate) mod qos;
pub mod settings;
pub mod simulation_interfaces;
pub(crate) mod topics;
pub mod types;
pub mod visualization;

pub use names::DEFAULT_NODE_NAME;
pub use types::RosType;
