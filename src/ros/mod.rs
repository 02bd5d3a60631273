//! The ROS 2 node (ros2-client + tokio; pure-Rust DDS, no ROS installation).
//!
//! `annular_plate run [FILE] [--ros-args ...]` — and `annular_plate` with no
//! arguments, on the built-in brake-bench scene — call [`run_node`], which
//! blocks until SIGINT or SIGTERM. docs/ros.md lists the topics, types, QoS,
//! services and parameters.
//!
//! One concern per file:
//! - `args`: `--ros-args` parsing, name resolution and remapping;
//! - `settings`: the `ros.*` parameters;
//! - `messages`: wire types (standard ROS ones and this package's `msg/`, `srv/`);
//! - `topics`, `qos`: names and QoS of every endpoint;
//! - [`inputs`]: checking and counting incoming messages (no ROS types);
//! - `input_polling`: the input subscriptions, read by the loop at step boundaries;
//! - `outputs`: the per-step messages, preallocated;
//! - `clock`: stamps, `/clock`, pacing; `clock_input`: following an external `/clock` (`use_sim_time`);
//! - `services`, [`params_service`]: reset/pause/step and the parameter services;
//!   `sim_services`: the same through the standard `simulation_interfaces` services;
//! - `diagnostics`: the `/diagnostics` statuses (shared with `simulate --bag`);
//! - [`sim_loop`]: the fixed-rate simulation thread;
//! - `step_aligned_receive`: input datagrams read at step boundaries while they are many;
//! - `marker_thread`: `~/plate_marker`, built and published off the loop;
//! - `critical_speeds`: `~/critical_speeds`, once at start (latched);
//! - `logging`: `/rosout` and stderr;
//! - `heap`: handing freed heap back to the OS after peer churn;
//! - `node`: wiring and shutdown.
//!
//! The physics (`model`, `dynamics`) never imports anything from here.

pub(crate) mod clock_input;
pub(crate) mod critical_speeds;
mod error;
pub(crate) mod heap;
pub(crate) mod input_polling;
pub mod inputs;
pub(crate) mod logging;
pub(crate) mod marker_thread;
mod node;
pub mod params_service;
pub(crate) mod services;
pub mod sim_loop;
pub(crate) mod sim_services;
pub(crate) mod step_aligned_receive;

pub use crate::messages::RosType;
pub use error::NodeError;
pub use node::{run_node, NodeSetup, DEFAULT_NODE_NAME, DEFAULT_SCENE};
