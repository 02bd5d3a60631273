//! Why a command-line front end failed: an enum with context (the file, the
//! option, the underlying error). `main.rs` prints it with its causes.

use crate::config::ConfigError;
use crate::dynamics::StepError;
use crate::model::ModelError;
use crate::study::StudyError;
use thiserror::Error;

/// Why a command of the command line failed; `main.rs` prints it and exits
/// with a failure status.
#[derive(Debug, Error)]
pub enum CliError {
    /// A scene or parameter file (`source`: its path, or `-p …`).
    #[error("{source_name}: {error}")]
    Config {
        /// The file's path, or the `-p …` override.
        source_name: String,
        /// Why it was rejected.
        error: ConfigError,
    },
    /// The plate model could not be built.
    #[error(transparent)]
    Model(#[from] ModelError),
    /// A step of the simulation failed.
    #[error(transparent)]
    Step(#[from] StepError),
    /// A study could not be planned or run.
    #[error("study of {source_name}: {error}")]
    Study {
        /// The scene file's path (or the built-in scene).
        source_name: String,
        /// Why.
        error: StudyError,
    },
    /// `--bag DIR`.
    #[error("--bag: {0}")]
    Bag(String),
    /// Reading or writing a file.
    #[error("cannot {what} {path}: {error}")]
    Io {
        /// What was to be done (`read`, `write`, `create`).
        what: &'static str,
        /// The file.
        path: String,
        /// The operating system's reason.
        error: std::io::Error,
    },
    /// Writing the output (a CSV row, a JSON document) failed.
    #[error(transparent)]
    Write(#[from] std::io::Error),
    /// A CSV that is not what `simulate` writes.
    #[error("{0}")]
    Csv(String),
    /// An option or argument that cannot be used (the message says which and why).
    #[error("{0}")]
    Usage(String),
    /// SIGINT or SIGTERM ended a run early; what was written is complete up to `time`.
    #[error("interrupted at t = {time} s ({steps} steps): the outputs hold every step up to then, the bag finished")]
    Interrupted {
        /// Simulated time reached, s.
        time: f64,
        /// Output steps taken.
        steps: u64,
    },
    /// The picture back end failed.
    #[error("drawing failed: {0}")]
    Draw(String),
}

/// `Result` of the command-line front ends.
pub type CliResult<T> = Result<T, CliError>;
