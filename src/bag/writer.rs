//! A rosbag2 directory with MCAP storage, as `ros2 bag record -s mcap`
//! (Jazzy, metadata version 9) leaves it:
//!
//! ```text
//! DIR/
//!   metadata.yaml      rosbag2_bagfile_information: version 9, topics, counts, times
//!   DIR_0.mcap         profile ros2; per type a schema (ros2msg), per topic a
//!                      channel (cdr, offered_qos_profiles); a "rosbag2"
//!                      metadata record with the same information
//! ```
//!
//! A message is stored as the 4-byte CDR encapsulation header `00 01 00 00`
//! (CDR, little endian) and the little-endian CDR of the serde struct, made by
//! the CDR serializer of rustdds (the one that puts the node's messages on
//! the wire), so a bag holds the same bytes a subscriber receives.
//!
//! Times are nanoseconds: the log (receive) time and publish time of each
//! message; `ros2 bag play` replays by log time. Chunks are not compressed
//! (rosbag2's default too).

use super::metadata::{write_metadata_yaml, Metadata, TopicCount};
use super::schemas;
use byteorder::LittleEndian;
use ros2_client::dds::rustdds::cdr_encoding;
use ros2_client::qos::{Durability, History, Liveliness, Reliability};
use ros2_client::QosProfile;
use serde::Serialize;
use std::collections::BTreeMap;
use std::fs::File;
use std::io::{BufWriter, Write};
use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

/// The CDR encapsulation header: representation CDR_LE, no options.
pub const CDR_LE_HEADER: [u8; 4] = [0x00, 0x01, 0x00, 0x00];

pub use super::error::BagError;

/// A topic of the bag, as returned by [`BagWriter::add_topic`].
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct TopicId(usize);

#[derive(Debug)]
struct Topic {
    name: String,
    type_name: String,
    qos: String,
    channel: u16,
    count: u64,
}

/// One topic of a finished bag.
#[derive(Debug, Clone, PartialEq)]
pub struct TopicSummary {
    /// The ROS topic name.
    pub name: String,
    /// Its ROS type, `package/msg/Type`.
    pub type_name: String,
    /// Messages recorded on it.
    pub count: u64,
}

/// What a finished bag holds.
#[derive(Debug, Clone, PartialEq)]
pub struct BagSummary {
    /// The rosbag2 directory.
    pub dir: PathBuf,
    /// The MCAP file, relative to `dir`.
    pub file: String,
    /// Messages in the file, all topics.
    pub message_count: u64,
    /// Log time of the first message, ns (0 for an empty bag).
    pub starting_time: u64,
    /// Last minus first log time, ns.
    pub duration: u64,
    /// Per topic, in the order they were added.
    pub topics: Vec<TopicSummary>,
    /// Size of the MCAP file, bytes.
    pub bytes: u64,
}

/// Writes one rosbag2 directory. Not thread-safe by design: one owner (the
/// CLI loop or the recorder thread) writes.
pub struct BagWriter {
    dir: PathBuf,
    file_name: String,
    mcap: mcap::Writer<BufWriter<File>>,
    topics: Vec<Topic>,
    buf: Vec<u8>,
    first: Option<u64>,
    last: u64,
    count: u64,
    /// When the last chunk was closed and metadata.yaml rewritten.
    checkpoint: Option<Instant>,
    /// Whether writing checkpoints (off for `bag repair`: metadata.yaml is
    /// only replaced once the repaired file is verified).
    checkpoints: bool,
}

/// How often a recording closes its MCAP chunk and rewrites metadata.yaml,
/// so that a killed recording loses at most this much (`bag repair`).
pub const CHECKPOINT_PERIOD: Duration = Duration::from_millis(500);

fn io(path: &Path) -> impl FnOnce(std::io::Error) -> BagError + '_ {
    move |source| BagError::Io {
        path: path.to_path_buf(),
        source,
    }
}

/// rmw's "infinite" duration as rosbag2 stores it (RMW_DURATION_INFINITE).
const INFINITE: (u64, u64) = (9_223_372_036, 854_775_807);

fn duration_yaml(d: Option<Duration>) -> (u64, u64) {
    match d {
        None => INFINITE,
        Some(d) => (d.as_secs(), d.subsec_nanos() as u64),
    }
}

/// The `offered_qos_profiles` text of one publisher (metadata version 9:
/// policies by name), as rosbag2 writes it into the channel metadata and
/// metadata.yaml.
pub fn offered_qos_yaml(qos: &QosProfile) -> String {
    let (history, depth) = match qos.history {
        History::KeepLast { depth } => ("keep_last", depth),
        History::KeepAll => ("keep_all", 0),
    };
    let reliability = match qos.reliability {
        Reliability::BestEffort => "best_effort",
        Reliability::Reliable { .. } => "reliable",
    };
    let durability = match qos.durability {
        Durability::Volatile => "volatile",
        Durability::TransientLocal => "transient_local",
    };
    let liveliness = match qos.liveliness {
        Liveliness::Automatic => "automatic",
        Liveliness::ManualByTopic => "manual_by_topic",
    };
    let (ds, dn) = duration_yaml(qos.deadline);
    let (ls, ln) = duration_yaml(qos.lifespan);
    let (vs, vn) = duration_yaml(qos.liveliness_lease);
    format!(
        "- history: {history}\n  depth: {depth}\n  reliability: {reliability}\n  durability: {durability}\n  \
         deadline:\n    sec: {ds}\n    nsec: {dn}\n  lifespan:\n    sec: {ls}\n    nsec: {ln}\n  \
         liveliness: {liveliness}\n  liveliness_lease_duration:\n    sec: {vs}\n    nsec: {vn}\n  \
         avoid_ros_namespace_conventions: false"
    )
}

impl BagWriter {
    /// Create `dir` (which must not exist) and its MCAP file `<dir name>_0.mcap`.
    pub fn create(dir: &Path) -> Result<BagWriter, BagError> {
        if dir.exists() {
            return Err(BagError::Exists(dir.to_path_buf()));
        }
        std::fs::create_dir_all(dir).map_err(io(dir))?;
        let stem = dir
            .file_name()
            .map(|s| s.to_string_lossy().into_owned())
            .filter(|s| !s.is_empty() && s != "." && s != "..")
            .unwrap_or_else(|| "bag".to_string());
        BagWriter::create_file(dir, format!("{stem}_0.mcap"))
    }

    /// A new MCAP file `file_name` in the existing directory `dir` (`bag repair`).
    pub fn create_file(dir: &Path, file_name: String) -> Result<BagWriter, BagError> {
        let path = dir.join(&file_name);
        let file = File::create(&path).map_err(io(&path))?;
        let mcap = mcap::WriteOptions::new()
            .profile("ros2")
            .library(format!(
                "annular_plate {} (mcap {})",
                env!("CARGO_PKG_VERSION"),
                "0.26"
            ))
            .compression(None)
            .create(BufWriter::with_capacity(1 << 20, file))
            .map_err(|e| BagError::Mcap {
                path: path.clone(),
                message: e.to_string(),
            })?;
        Ok(BagWriter {
            dir: dir.to_path_buf(),
            file_name,
            mcap,
            topics: Vec::new(),
            buf: Vec::with_capacity(64 * 1024),
            first: None,
            last: 0,
            count: 0,
            checkpoint: None,
            checkpoints: true,
        })
    }

    /// No checkpoints: metadata.yaml is left alone until [`Self::finish`].
    pub(super) fn without_checkpoints(mut self) -> Self {
        self.checkpoints = false;
        self
    }

    pub fn dir(&self) -> &Path {
        &self.dir
    }

    fn mcap_error(&self, e: mcap::McapError) -> BagError {
        BagError::Mcap {
            path: self.dir.join(&self.file_name),
            message: e.to_string(),
        }
    }

    /// Add a topic of type `type_name` (`pkg/msg/Type`) offered with `qos`.
    pub fn add_topic(
        &mut self,
        name: &str,
        type_name: &str,
        qos: &QosProfile,
    ) -> Result<TopicId, BagError> {
        let text = schemas::ros2msg(type_name)
            .ok_or_else(|| BagError::UnknownType(type_name.to_string()))?;
        self.add_topic_with_schema(name, type_name, text.as_bytes(), offered_qos_yaml(qos))
    }

    /// Add a topic with its `ros2msg` schema text and `offered_qos_profiles` text as given.
    pub fn add_topic_with_schema(
        &mut self,
        name: &str,
        type_name: &str,
        schema_text: &[u8],
        qos: String,
    ) -> Result<TopicId, BagError> {
        if self.topics.iter().any(|t| t.name == name) {
            return Err(BagError::DuplicateTopic(name.to_string()));
        }
        let schema = self
            .mcap
            .add_schema(type_name, "ros2msg", schema_text)
            .map_err(|e| self.mcap_error(e))?;
        let metadata = BTreeMap::from([("offered_qos_profiles".to_string(), qos.clone())]);
        let channel = self
            .mcap
            .add_channel(schema, name, "cdr", &metadata)
            .map_err(|e| self.mcap_error(e))?;
        self.topics.push(Topic {
            name: name.to_string(),
            type_name: type_name.to_string(),
            qos,
            channel,
            count: 0,
        });
        Ok(TopicId(self.topics.len() - 1))
    }

    /// Serialize `msg` (CDR, little endian) and write it at `log_time` ns.
    pub fn write<T: Serialize>(
        &mut self,
        topic: TopicId,
        log_time: u64,
        msg: &T,
    ) -> Result<(), BagError> {
        let mut buf = std::mem::take(&mut self.buf);
        buf.clear();
        buf.extend_from_slice(&CDR_LE_HEADER);
        let serialized =
            cdr_encoding::to_writer::<T, LittleEndian, _>(&mut buf, msg).map_err(|e| {
                BagError::Cdr {
                    topic: self.topics[topic.0].name.clone(),
                    message: e.to_string(),
                }
            });
        let written = serialized.and_then(|()| self.write_raw(topic, log_time, &buf));
        self.buf = buf;
        written
    }

    /// Write an already serialized message (CDR header included) at `log_time` ns.
    pub fn write_raw(
        &mut self,
        topic: TopicId,
        log_time: u64,
        data: &[u8],
    ) -> Result<(), BagError> {
        let t = &mut self.topics[topic.0];
        let header = mcap::records::MessageHeader {
            channel_id: t.channel,
            sequence: t.count as u32,
            log_time,
            publish_time: log_time,
        };
        t.count += 1;
        self.count += 1;
        self.first = Some(self.first.map_or(log_time, |f| f.min(log_time)));
        self.last = self.last.max(log_time);
        let r = self.mcap.write_to_known_channel(&header, data);
        r.map_err(|e| self.mcap_error(e))?;
        if self.checkpoints
            && self
                .checkpoint
                .is_none_or(|t| t.elapsed() >= CHECKPOINT_PERIOD)
        {
            self.checkpoint()?;
        }
        Ok(())
    }

    /// Close the current chunk (flushed to the file) and rewrite
    /// metadata.yaml with what is in the file now: a recording killed after
    /// this opens with `bag repair` up to here.
    pub fn checkpoint(&mut self) -> Result<(), BagError> {
        self.mcap.flush().map_err(|e| self.mcap_error(e))?;
        write_metadata_yaml(&self.dir, &self.metadata())?;
        self.checkpoint = Some(Instant::now());
        Ok(())
    }

    fn metadata(&self) -> Metadata {
        Metadata::for_file(
            self.file_name.clone(),
            self.topics
                .iter()
                .map(|t| TopicCount {
                    name: t.name.clone(),
                    type_name: t.type_name.clone(),
                    qos: t.qos.clone(),
                    count: t.count,
                })
                .collect(),
            self.first.map(|f| (f, self.last)),
        )
    }

    /// Write the MCAP summary and metadata.yaml; the bag is complete.
    pub fn finish(self) -> Result<BagSummary, BagError> {
        let dir = self.dir.clone();
        let (summary, metadata) = self.finish_file()?;
        write_metadata_yaml(&dir, &metadata)?;
        Ok(summary)
    }

    /// Write the MCAP summary (not metadata.yaml): the file is complete;
    /// its part of metadata.yaml for [`write_combined_metadata`].
    pub(super) fn finish_file(mut self) -> Result<(BagSummary, Metadata), BagError> {
        let metadata = self.metadata();
        let serialized =
            serde_yaml_ng::to_string(&metadata).map_err(|e| BagError::Yaml(e.to_string()))?;
        let record = mcap::records::Metadata {
            name: "rosbag2".into(),
            metadata: BTreeMap::from([("serialized_metadata".to_string(), serialized)]),
        };
        self.mcap
            .write_metadata(&record)
            .map_err(|e| self.mcap_error(e))?;
        self.mcap.finish().map_err(|e| self.mcap_error(e))?;
        let path = self.dir.join(&self.file_name);
        let mut file = self.mcap.into_inner();
        file.flush().map_err(io(&path))?;
        let file = file.into_inner().map_err(|e| BagError::Io {
            path: path.clone(),
            source: e.into_error(),
        })?;
        file.sync_all().map_err(io(&path))?;
        let bytes = file.metadata().map_err(io(&path))?.len();

        let summary = BagSummary {
            dir: self.dir.clone(),
            file: self.file_name.clone(),
            message_count: metadata.message_count(),
            starting_time: metadata.span().0,
            duration: metadata.span().1,
            topics: self
                .topics
                .iter()
                .map(|t| TopicSummary {
                    name: t.name.clone(),
                    type_name: t.type_name.clone(),
                    count: t.count,
                })
                .collect(),
            bytes,
        };
        Ok((summary, metadata))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::messages::qos;
    use crate::messages::types::{Clock, Time};

    fn temp(name: &str) -> PathBuf {
        let d =
            std::env::temp_dir().join(format!("annular_plate-bag-{}-{name}", std::process::id()));
        let _ = std::fs::remove_dir_all(&d);
        d
    }

    #[test]
    fn qos_text_names_the_policies() {
        let s = offered_qos_yaml(&qos::TF_STATIC);
        assert!(s.starts_with("- history: keep_last\n  depth: 1\n  reliability: reliable\n  durability: transient_local\n"));
        assert!(s.contains("deadline:\n    sec: 9223372036\n    nsec: 854775807\n"));
        assert!(s.ends_with("avoid_ros_namespace_conventions: false"));
    }

    #[test]
    fn a_bag_directory_has_metadata_and_an_mcap_file() {
        let dir = temp("small");
        let mut w = BagWriter::create(&dir).unwrap();
        let clock = w
            .add_topic("/clock", "rosgraph_msgs/msg/Clock", &qos::CLOCK)
            .unwrap();
        assert!(matches!(
            w.add_topic("/clock", "rosgraph_msgs/msg/Clock", &qos::CLOCK),
            Err(BagError::DuplicateTopic(_))
        ));
        assert!(matches!(
            w.add_topic("/x", "nav_msgs/msg/Odometry", &qos::CLOCK),
            Err(BagError::UnknownType(_))
        ));
        for n in 0..3i64 {
            let t = Time::from_nanos(n * 1_000_000);
            w.write(clock, t.to_nanos() as u64, &Clock { clock: t })
                .unwrap();
        }
        let s = w.finish().unwrap();
        assert_eq!(
            (s.message_count, s.starting_time, s.duration),
            (3, 0, 2_000_000)
        );
        let name = dir.file_name().unwrap().to_string_lossy().into_owned();
        assert_eq!(s.file, format!("{name}_0.mcap"));
        let mcap = std::fs::read(dir.join(&s.file)).unwrap();
        assert_eq!(&mcap[..8], b"\x89MCAP0\r\n");
        // The third Clock: header, then sec = 0, nanosec = 2 000 000 (little endian).
        let payload = [0u8, 1, 0, 0, 0, 0, 0, 0, 0x80, 0x84, 0x1e, 0];
        assert!(mcap.windows(payload.len()).any(|w| w == payload));
        let meta = std::fs::read_to_string(dir.join("metadata.yaml")).unwrap();
        assert!(
            meta.starts_with(
                "rosbag2_bagfile_information:\n  version: 9\n  storage_identifier: mcap\n"
            ),
            "{meta}"
        );
        assert!(meta.contains("type: rosgraph_msgs/msg/Clock"));
        assert!(matches!(BagWriter::create(&dir), Err(BagError::Exists(_))));
        let _ = std::fs::remove_dir_all(&dir);
    }
}
