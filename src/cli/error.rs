//! Why a command-line front end failed: an enum with context (the file, the
//! option, the underlying error). `main.rs` prints it with its causes.

use crate::config::ConfigError;
use crate::dynamics::StepError;
use crate::model::ModelError;
use crate::study::StudyError;
use thiserror::Error;

#[derive(Debug, Error)]
pub enum CliError {
    /// A scene or parameter file (`source`: its path, or `-p …`).
    #[error("{source_name}: {error}")]
    Config {
        source_name: String,
        error: ConfigError,
    },
    #[error(transparent)]
    Model(#[from] ModelError),
    #[error(transparent)]
    Step(#[from] StepError),
    #[error("study of {source_name}: {error}")]
    Study {
        source_name: String,
        error: StudyError,
    },
    /// `--bag DIR`.
    #[error("--bag: {0}")]
    Bag(String),
    /// Reading or writing a file.
    #[error("cannot {what} {path}: {error}")]
    Io {
        what: &'static str,
        path: String,
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
    Interrupted { time: f64, steps: u64 },
    /// The picture back end failed.
    #[error("drawing failed: {0}")]
    Draw(String),
}

/// `Result` of the command-line front ends.
pub type CliResult<T> = Result<T, CliError>;
