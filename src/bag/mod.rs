//! Recording: rosbag2 directories (MCAP storage, `metadata.yaml` version 9,
//! `ros2msg` schemas, CDR payloads) of the node's topics, readable by
//! `ros2 bag info` / `ros2 bag play` and by any MCAP reader.
//!
//! - `writer`: the bag layout, independent of the node (any serde message
//!   with a definition in [`schemas`]);
//! - `metadata`: metadata.yaml, for one file or the files of a directory;
//! - [`schemas`]: the message definitions with their dependencies appended;
//! - `recorder`: the node's topics (`recorder::NodeBag`) and the writer
//!   thread of `annular_plate run --record DIR` (`recorder::Recorder`);
//! - `offline`: `annular_plate simulate --bag DIR`;
//! - [`repair`]: `annular_plate bag repair DIR` for a recording that was killed.
//!
//! The messages are built by the messages layer (`messages::outputs`,
//! `messages::diagnostics`), shared with the node; the module comes with the
//! `ros` feature.

mod error;
mod metadata;
pub(crate) mod offline;
pub(crate) mod recorder;
pub mod repair;
pub mod schemas;
pub(crate) mod writer;

pub use error::BagError;
pub(crate) use offline::OfflineRecorder;
pub use writer::{BagSummary, TopicSummary};
