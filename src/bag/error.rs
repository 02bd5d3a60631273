//! What can go wrong writing, finishing or repairing a bag.

use std::path::PathBuf;

/// What can go wrong writing a bag.
#[derive(Debug, thiserror::Error)]
pub enum BagError {
    #[error("{0} already exists; give a new directory (as `ros2 bag record -o`)")]
    Exists(PathBuf),
    #[error("{path}: {source}")]
    Io {
        path: PathBuf,
        source: std::io::Error,
    },
    #[error("{path}: MCAP: {message}")]
    Mcap { path: PathBuf, message: String },
    #[error("no message definition for {0}")]
    UnknownType(String),
    #[error("topic {0} added twice")]
    DuplicateTopic(String),
    #[error("topic {topic}: CDR serialization failed: {message}")]
    Cdr { topic: String, message: String },
    #[error("metadata.yaml: {0}")]
    Yaml(String),
}
