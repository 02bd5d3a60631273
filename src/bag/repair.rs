//! `annular_plate bag repair DIR`: a recording that was killed (SIGKILL, a
//! power cut) leaves an MCAP file without its summary and end magic, and a
//! metadata.yaml from its last checkpoint. Repair reads every complete
//! message up to where the file breaks off (the writer closes a chunk and
//! rewrites metadata.yaml every [`CHECKPOINT_PERIOD`](super::writer::CHECKPOINT_PERIOD),
//! so at most that much is lost), writes them into a complete MCAP file of
//! the same name with a fresh metadata.yaml, and keeps the damaged file as
//! `<name>.broken`. A bag that is already complete is left as it is.

use super::writer::{BagError, BagSummary, BagWriter, TopicId};
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

/// What `repair` did.
#[derive(Debug)]
pub enum Repair {
    /// The bag was complete: nothing changed.
    AlreadyComplete { file: PathBuf },
    /// The bag was rewritten; the damaged file is kept beside it.
    Repaired { summary: BagSummary, broken: PathBuf },
}

fn mcap_file(dir: &Path) -> Result<PathBuf, BagError> {
    let io = |e: std::io::Error| BagError::Io { path: dir.to_path_buf(), source: e };
    let mut files: Vec<PathBuf> = std::fs::read_dir(dir)
        .map_err(io)?
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|e| e == "mcap"))
        .collect();
    files.sort();
    files.pop().ok_or_else(|| BagError::Mcap { path: dir.to_path_buf(), message: "no .mcap file in the bag directory".into() })
}

/// Whether `bytes` is a complete MCAP file (summary and end magic readable).
fn is_complete(bytes: &[u8]) -> bool {
    matches!(mcap::read::Summary::read(bytes), Ok(Some(_)))
}

/// Repair the bag directory `dir` (see the module documentation).
pub fn repair(dir: &Path) -> Result<Repair, BagError> {
    let path = mcap_file(dir)?;
    let bytes = std::fs::read(&path).map_err(|e| BagError::Io { path: path.clone(), source: e })?;
    if is_complete(&bytes) && dir.join("metadata.yaml").is_file() {
        return Ok(Repair::AlreadyComplete { file: path });
    }
    let file_name = path.file_name().map(|n| n.to_string_lossy().into_owned()).unwrap_or_default();
    let broken = dir.join(format!("{file_name}.broken"));
    std::fs::rename(&path, &broken).map_err(|e| BagError::Io { path: path.clone(), source: e })?;
    let mut writer = BagWriter::create_file(dir, file_name)?;
    let options = mcap::read::Options::IgnoreEndMagic.into();
    let stream = mcap::MessageStream::new_with_options(&bytes, options).map_err(|e| BagError::Mcap { path: broken.clone(), message: e.to_string() })?;
    let mut topics: BTreeMap<u16, TopicId> = BTreeMap::new();
    // Messages until the first record that is cut off.
    for message in stream.map_while(Result::ok) {
        let channel = &message.channel;
        let topic = match topics.get(&channel.id) {
            Some(&t) => t,
            None => {
                let (type_name, schema) = channel.schema.as_ref().map_or((String::new(), Vec::new()), |s| (s.name.clone(), s.data.to_vec()));
                let qos = channel.metadata.get("offered_qos_profiles").cloned().unwrap_or_default();
                let t = writer.add_topic_with_schema(&channel.topic, &type_name, &schema, qos)?;
                topics.insert(channel.id, t);
                t
            }
        };
        writer.write_raw(topic, message.log_time, &message.data)?;
    }
    let summary = writer.finish()?;
    Ok(Repair::Repaired { summary, broken })
}
