//! The ROS side's data, shared by the node (`ros`) and the recorder (`bag`),
//! which never import each other: the message structs (`msg/*.msg` and the
//! standard types they use), the building of the output messages from a
//! simulation, topic names and QoS profiles, ROS name resolution and the
//! node's `ros.*` settings, the step clock's stamps, the diagnostics
//! messages and the input counters they report.
//!
//! Data flows one way: `dynamics` → `messages` → `ros` / `bag` / `cli`.

pub mod clock;
pub mod clock_follower;
pub mod critical_speeds;
pub mod diagnostics;
pub mod input_stats;
pub mod marker;
pub mod model_states;
pub mod names;
pub mod outputs;
pub mod qos;
pub mod settings;
pub mod simulation_interfaces;
pub mod topics;
pub mod types;
pub mod visualization;

pub use names::DEFAULT_NODE_NAME;
pub use types::RosType;
