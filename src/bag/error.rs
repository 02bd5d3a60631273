//! What can go wrong writing, finishing or repairing a bag.

use std::path::PathBuf;

/// What can go wrong writing a bag.
#[derive(Debug, thiserror::Error)]
pub enum BagError {
    /// The bag directory already exists (a bag is never written over).
    #[error("{0} already exists; give a new directory (as `ros2 bag record -o`)")]
    Exists(PathBuf),
    /// Reading or writing a file failed.
    #[error("{path}: {source}")]
    Io {
        /// The file or directory.
        path: PathBuf,
        /// The operating system's error.
        source: std::io::Error,
    },
    /// The MCAP writer or reader failed.
    #[error("{path}: MCAP: {message}")]
    Mcap {
        /// The MCAP file.
        path: PathBuf,
        /// The `mcap` crate's message.
        message: String,
    },
    /// A topic's ROS type has no definition in [`schemas`](super::schemas).
    #[error("no message definition for {0}")]
    UnknownType(String),
    /// The same topic name was added twice.
    #[error("topic {0} added twice")]
    DuplicateTopic(String),
    /// A message could not be serialized to CDR.
    #[error("topic {topic}: CDR serialization failed: {message}")]
    Cdr {
        /// The topic.
        topic: String,
        /// The serializer's message.
        message: String,
    },
    /// metadata.yaml could not be written or read.
    #[error("metadata.yaml: {0}")]
    Yaml(String),
}
