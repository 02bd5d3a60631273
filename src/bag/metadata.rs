//! metadata.yaml of a rosbag2 directory (rosbag2_storage/yaml.hpp, version
//! 9, as Jazzy's `ros2 bag record` writes it): per file and in total the
//! message count, start and duration, the topics with their types, QoS and
//! counts, and the list of files. Written by `BagWriter` for
//! one file and by `bag repair` for the files of a directory together.

use super::error::BagError;
use serde::Serialize;
use std::collections::BTreeMap;
use std::path::Path;

/// rosbag2 metadata version written (Jazzy).
pub const METADATA_VERSION: u32 = 9;

/// The distribution whose bag format this is (`ros_distro` in metadata.yaml).
pub const ROS_DISTRO: &str = "jazzy";

fn io(path: &Path) -> impl FnOnce(std::io::Error) -> BagError + '_ {
    move |source| BagError::Io {
        path: path.to_path_buf(),
        source,
    }
}

/// One topic of one file: name, type, offered QoS (YAML text), messages.
#[derive(Debug, Clone, PartialEq)]
pub(super) struct TopicCount {
    pub name: String,
    pub type_name: String,
    pub qos: String,
    pub count: u64,
}

/// `dir/metadata.yaml`, replaced atomically.
pub(super) fn write_metadata_yaml(dir: &Path, metadata: &Metadata) -> Result<(), BagError> {
    let yaml = serde_yaml_ng::to_string(&MetadataFile {
        rosbag2_bagfile_information: metadata,
    })
    .map_err(|e| BagError::Yaml(e.to_string()))?;
    let meta_path = dir.join("metadata.yaml");
    let tmp = dir.join("metadata.yaml.tmp");
    std::fs::write(&tmp, yaml).map_err(io(&tmp))?;
    std::fs::rename(&tmp, &meta_path).map_err(io(&meta_path))
}

/// Write `dir/metadata.yaml` for the files of `parts` together (`bag repair`
/// of several files): counts summed per topic, the earliest start, the
/// latest end.
pub(super) fn write_combined_metadata(dir: &Path, parts: Vec<Metadata>) -> Result<(), BagError> {
    let mut parts = parts.into_iter();
    let Some(mut all) = parts.next() else {
        return Ok(());
    };
    for m in parts {
        let (a0, a1) = (
            all.starting_time.nanoseconds_since_epoch,
            all.starting_time.nanoseconds_since_epoch + all.duration.nanoseconds,
        );
        let (b0, b1) = (
            m.starting_time.nanoseconds_since_epoch,
            m.starting_time.nanoseconds_since_epoch + m.duration.nanoseconds,
        );
        let (start, end) = match (all.message_count, m.message_count) {
            (0, _) => (b0, b1),
            (_, 0) => (a0, a1),
            _ => (a0.min(b0), a1.max(b1)),
        };
        all.starting_time.nanoseconds_since_epoch = start;
        all.duration.nanoseconds = end - start;
        all.message_count += m.message_count;
        for t in m.topics_with_message_count {
            match all
                .topics_with_message_count
                .iter_mut()
                .find(|a| a.topic_metadata.name == t.topic_metadata.name)
            {
                Some(a) => a.message_count += t.message_count,
                None => all.topics_with_message_count.push(t),
            }
        }
        all.relative_file_paths.extend(m.relative_file_paths);
        all.files.extend(m.files);
    }
    write_metadata_yaml(dir, &all)
}

// ---- metadata.yaml (rosbag2_storage/yaml.hpp, version 9) -----------------------

#[derive(Serialize)]
struct MetadataFile<'a> {
    rosbag2_bagfile_information: &'a Metadata,
}

#[derive(Serialize)]
struct Nanoseconds {
    nanoseconds: u64,
}

#[derive(Serialize)]
struct SinceEpoch {
    nanoseconds_since_epoch: u64,
}

#[derive(Serialize)]
struct TopicMetadata {
    name: String,
    r#type: String,
    serialization_format: String,
    offered_qos_profiles: String,
    type_description_hash: String,
}

#[derive(Serialize)]
struct TopicInformation {
    topic_metadata: TopicMetadata,
    message_count: u64,
}

#[derive(Serialize)]
struct FileInformation {
    path: String,
    starting_time: SinceEpoch,
    duration: Nanoseconds,
    message_count: u64,
}

#[derive(Serialize)]
pub(super) struct Metadata {
    version: u32,
    storage_identifier: String,
    duration: Nanoseconds,
    starting_time: SinceEpoch,
    message_count: u64,
    topics_with_message_count: Vec<TopicInformation>,
    compression_format: String,
    compression_mode: String,
    relative_file_paths: Vec<String>,
    files: Vec<FileInformation>,
    custom_data: BTreeMap<String, String>,
    ros_distro: String,
}

impl Metadata {
    /// The metadata of one file `path` (relative to the bag directory) with
    /// `topics`; `span`: the first and last log time, ns (`None`: no message).
    pub(super) fn for_file(
        path: String,
        topics: Vec<TopicCount>,
        span: Option<(u64, u64)>,
    ) -> Self {
        let (start, duration) = span.map_or((0, 0), |(first, last)| (first, last - first));
        let message_count = topics.iter().map(|t| t.count).sum();
        Metadata {
            version: METADATA_VERSION,
            storage_identifier: "mcap".into(),
            duration: Nanoseconds {
                nanoseconds: duration,
            },
            starting_time: SinceEpoch {
                nanoseconds_since_epoch: start,
            },
            message_count,
            topics_with_message_count: topics
                .into_iter()
                .map(|t| TopicInformation {
                    topic_metadata: TopicMetadata {
                        name: t.name,
                        r#type: t.type_name,
                        serialization_format: "cdr".into(),
                        offered_qos_profiles: t.qos,
                        type_description_hash: String::new(),
                    },
                    message_count: t.count,
                })
                .collect(),
            compression_format: String::new(),
            compression_mode: String::new(),
            relative_file_paths: vec![path.clone()],
            files: vec![FileInformation {
                path,
                starting_time: SinceEpoch {
                    nanoseconds_since_epoch: start,
                },
                duration: Nanoseconds {
                    nanoseconds: duration,
                },
                message_count,
            }],
            custom_data: BTreeMap::new(),
            ros_distro: ROS_DISTRO.into(),
        }
    }

    pub(super) fn message_count(&self) -> u64 {
        self.message_count
    }

    pub(super) fn span(&self) -> (u64, u64) {
        (
            self.starting_time.nanoseconds_since_epoch,
            self.duration.nanoseconds,
        )
    }
}
