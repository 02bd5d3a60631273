//! Why the node could not start or ended with an error: enums with context
//! (which file, topic or service; the underlying error). `main.rs` prints
//! them; nothing here panics.

use crate::bag::BagError;
use crate::config::ConfigError;
use crate::dynamics::SimulationError;
use crate::messages::names::ArgsError;
use crate::messages::settings::SettingsError;
use thiserror::Error;

/// Why the node could not start or stopped with an error (`annular_plate run`).
#[derive(Debug, Error)]
pub enum NodeError {
    /// `--ros-args`, a node or topic name, `ROS_DOMAIN_ID`.
    #[error(transparent)]
    Args(#[from] ArgsError),
    /// A scene or parameter file (`source`: its path, `-p` or the built-in scene).
    #[error("{source_name}: {error}")]
    Config {
        /// The file's path, `-p` or the built-in scene.
        source_name: String,
        /// The key and the rule it breaks.
        error: ConfigError,
    },
    /// The node's own `ros.*` settings in the scene.
    #[error("{scene}: {error}")]
    Settings {
        /// The scene's source.
        scene: String,
        /// The `ros.*` key and the rule it breaks.
        error: SettingsError,
    },
    /// The scene cannot be simulated as configured.
    #[error("{scene}: {error}")]
    Simulation {
        /// The scene's source.
        scene: String,
        /// Why the simulation refuses it.
        error: SimulationError,
    },
    /// `--record DIR`.
    #[error("--record: {0}")]
    Record(String),
    /// The bag of `--record DIR` could not be created or written.
    #[error("--record: {0}")]
    Bag(#[from] BagError),
    /// A DDS entity could not be created (`what`: the domain, node, topic or service).
    #[error("{what}: {detail}")]
    Dds {
        /// The entity.
        what: String,
        /// The DDS layer's message.
        detail: String,
    },
    /// An operating-system resource (runtime, thread, signal handler).
    #[error("{what}: {error}")]
    System {
        /// The resource.
        what: &'static str,
        /// The operating system's error.
        error: std::io::Error,
    },
    /// The simulation thread panicked or could not be joined.
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
