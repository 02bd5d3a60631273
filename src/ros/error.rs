//! Why the node could not start or ended with an error: enums with context
//! (which file, topic or service; the underlying error). `main.rs` prints
//! them; nothing here panics.

use crate::bag::BagError;
use crate::config::ConfigError;
use crate::dynamics::SimulationError;
use crate::messages::names::ArgsError;
use crate::messages::settings::SettingsError;
use thiserror::Error;

#[derive(Debug, Error)]
pub enum NodeError {
    /// `--ros-args`, a node or topic name, `ROS_DOMAIN_ID`.
    #[error(transparent)]
    Args(#[from] ArgsError),
    /// A scene or parameter file (`source`: its path, `-p` or the built-in scene).
    #[error("{source_name}: {error}")]
    Config {
        source_name: String,
        error: ConfigError,
    },
    /// The node's own `ros.*` settings in the scene.
    #[error("{scene}: {error}")]
    Settings { scene: String, error: SettingsError },
    /// The scene cannot be simulated as configured.
    #[error("{scene}: {error}")]
    Simulation {
        scene: String,
        error: SimulationError,
    },
    /// `--record DIR`.
    #[error("--record: {0}")]
    Record(String),
    #[error("--record: {0}")]
    Bag(#[from] BagError),
    /// A DDS entity could not be created (`what`: the domain, node, topic or service).
    #[error("{what}: {detail}")]
    Dds { what: String, detail: String },
    /// An operating-system resource (runtime, thread, signal handler).
    #[error("{what}: {error}")]
    System {
        what: &'static str,
        error: std::io::Error,
    },
    #[error("the simulation thread ended abnormally")]
    SimulationThread,
    /// The loop stopped for a reason other than a signal.
    #[error("{0}")]
    Stopped(StopReason),
}

impl NodeError {
    /// A DDS failure with its context.
    pub fn dds(what: impl Into<String>, detail: impl std::fmt::Debug) -> NodeError {
        NodeError::Dds {
            what: what.into(),
            detail: format!("{detail:?}"),
        }
    }
}

/// Why the node stops: a signal asked for it (a clean exit), or the
/// simulation loop ended on its own (an error exit).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum StopReason {
    /// SIGINT or SIGTERM.
    Signal(&'static str),
    /// The simulation loop ended without being asked to.
    LoopEnded,
}

impl std::fmt::Display for StopReason {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            StopReason::Signal(name) => f.write_str(name),
            StopReason::LoopEnded => f.write_str("the simulation loop ended"),
        }
    }
}
