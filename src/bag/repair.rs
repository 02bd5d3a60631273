//! `annular_plate bag repair DIR`: a recording that was killed (SIGKILL, a
//! power cut) leaves an MCAP file without its summary and end magic, and a
//! metadata.yaml from its last checkpoint. Repair reads every complete
//! message up to where the file breaks off (the writer closes a chunk and
//! rewrites metadata.yaml every `CHECKPOINT_PERIOD` (0.5 s),
//! so at most that much is lost) and writes them into a complete MCAP file
//! of a fresh name beside it, `<stem>.repaired.mcap` (`-2`, `-3`, … if that
//! name is taken by a file it cannot use).
//!
//! - It streams: the damaged file is read in [`READ_BLOCK`] pieces through
//!   mcap's sans-io reader; memory is bounded by one record
//!   ([`MAX_RECORD_BYTES`]), not by the file. A record longer than that, an
//!   invalid opcode (a zero-filled tail) or a record that does not parse is
//!   where the file breaks off.
//! - It touches nothing it did not write: the damaged file stays as it is,
//!   byte for byte, and so does any other file (an old `<name>.broken`).
//!   When every repaired file is complete and verified (read back: its
//!   message count, its footer and end magic), metadata.yaml is replaced
//!   atomically by one that lists every file of the bag — the intact ones
//!   as they are (their topics and counts read from their records), the
//!   damaged ones by their repaired files — with the counts summed; the
//!   checkpoint's metadata.yaml is first copied to a fresh
//!   `metadata.yaml.before-repair`.
//! - Every damaged `.mcap` of the directory is repaired; a file that does not
//!   start with the MCAP magic (text, garbage, an empty file) is refused.
//! - It is idempotent: a damaged file with a complete repaired file
//!   (`<stem>.repaired.mcap`, or `-2`, … when that name was taken) is
//!   repaired already, and a repair's output is never taken for an original;
//!   a bag whose every file is complete or repaired is left as it is.

use super::metadata::{write_combined_metadata, Metadata, TopicCount};
use super::writer::{BagError, BagSummary, BagWriter, TopicId};
use std::collections::BTreeMap;
use std::fs::File;
use std::io::Read;
use std::path::{Path, PathBuf};

/// Bytes read from the damaged file at a time.
pub const READ_BLOCK: usize = 1 << 20;
/// The longest record repair accepts (the recorder's chunks are far smaller).
pub const MAX_RECORD_BYTES: usize = 64 << 20;
/// The most `.mcap` files of one directory.
const MAX_FILES: usize = 10_000;

/// What `repair` did.
#[derive(Debug)]
pub enum Repair {
    /// Every file was complete (or repaired before): nothing changed.
    AlreadyComplete {
        /// The directory's `.mcap` files.
        files: Vec<PathBuf>,
    },
    /// Damaged files repaired into new files beside them (originals untouched).
    Repaired {
        /// Each repaired file (the new one) and what it holds.
        repaired: Vec<(PathBuf, BagSummary)>,
    },
}

fn io(path: &Path) -> impl FnOnce(std::io::Error) -> BagError + '_ {
    move |source| BagError::Io {
        path: path.to_path_buf(),
        source,
    }
}

fn mcap_err(path: &Path, message: impl Into<String>) -> BagError {
    BagError::Mcap {
        path: path.to_path_buf(),
        message: message.into(),
    }
}

fn mcap_files(dir: &Path) -> Result<Vec<PathBuf>, BagError> {
    let mut files = Vec::new();
    for entry in std::fs::read_dir(dir).map_err(io(dir))? {
        let p = entry.map_err(io(dir))?.path();
        if p.extension().is_some_and(|e| e == "mcap") && p.is_file() {
            files.push(p);
            if files.len() > MAX_FILES {
                return Err(mcap_err(dir, format!("more than {MAX_FILES} .mcap files")));
            }
        }
    }
    files.sort();
    if files.is_empty() {
        return Err(mcap_err(dir, "no .mcap file in the bag directory"));
    }
    Ok(files)
}

/// The state of one file, from its first and last bytes only.
#[derive(Debug, PartialEq)]
enum Kind {
    Complete,
    Damaged,
}

fn kind(path: &Path) -> Result<Kind, BagError> {
    use std::io::{Seek, SeekFrom};
    let mut f = File::open(path).map_err(io(path))?;
    let len = f.metadata().map_err(io(path))?.len();
    let mut head = [0u8; 8];
    let n = f.read(&mut head).map_err(io(path))?;
    if n < 8 || head != mcap::MAGIC[..] {
        return Err(mcap_err(
            path,
            format!("not an MCAP file (it does not start with the MCAP magic; {len} bytes): refused, nothing written"),
        ));
    }
    // A complete file ends with the footer record (opcode 0x02, length 20) and the magic.
    const TAIL: u64 = 1 + 8 + 20 + 8;
    if len < 8 + TAIL {
        return Ok(Kind::Damaged);
    }
    let mut tail = [0u8; TAIL as usize];
    f.seek(SeekFrom::Start(len - TAIL)).map_err(io(path))?;
    f.read_exact(&mut tail).map_err(io(path))?;
    let footer =
        tail[0] == 0x02 && tail[1..9] == 20u64.to_le_bytes() && tail[29..] == mcap::MAGIC[..];
    Ok(if footer {
        Kind::Complete
    } else {
        Kind::Damaged
    })
}

/// Calls `record(opcode, body)` for each record of `path` (inside chunks
/// too) until the file ends or breaks off; reads [`READ_BLOCK`] at a time.
/// Returns whether it ended cleanly (a complete file) or broke off.
fn stream_records(
    path: &Path,
    mut record: impl FnMut(u8, &[u8]) -> Result<bool, BagError>,
) -> Result<bool, BagError> {
    use mcap::sans_io::linear_reader::{LinearReadEvent, LinearReader, LinearReaderOptions};
    let mut file = File::open(path).map_err(io(path))?;
    let options = LinearReaderOptions::default()
        .with_record_length_limit(MAX_RECORD_BYTES)
        .with_prevalidate_chunk_crcs(true);
    let mut reader = LinearReader::new_with_options(options);
    // Bytes fed since the last record: a record that needs more than the limit is where the file breaks off.
    let mut pending = 0usize;
    while let Some(event) = reader.next_event() {
        match event {
            Ok(LinearReadEvent::ReadRequest(want)) => {
                if pending > MAX_RECORD_BYTES {
                    return Ok(false);
                }
                let buf = reader.insert(want.clamp(1, READ_BLOCK));
                let n = file.read(buf).map_err(io(path))?;
                reader.notify_read(n);
                pending += n;
            }
            Ok(LinearReadEvent::Record { data, opcode }) => {
                pending = 0;
                // 0x00 is no MCAP record: a zero-filled (sparse) tail.
                if opcode == 0 || opcode > 0x0F {
                    return Ok(false);
                }
                if !record(opcode, data)? {
                    return Ok(false);
                }
            }
            Err(_) => return Ok(false),
        }
    }
    Ok(true)
}

/// Copy every complete message of the damaged `source` into `writer`.
fn copy_messages(source: &Path, writer: &mut BagWriter) -> Result<u64, BagError> {
    use mcap::records::Record;
    let mut schemas: BTreeMap<u16, (String, Vec<u8>)> = BTreeMap::new();
    let mut channels: BTreeMap<u16, (String, u16, String)> = BTreeMap::new();
    let mut topics: BTreeMap<u16, TopicId> = BTreeMap::new();
    let mut count = 0;
    stream_records(source, |opcode, body| {
        let Ok(rec) = mcap::parse_record(opcode, body) else {
            return Ok(false);
        };
        match rec {
            Record::Schema { header, data } => {
                schemas.insert(header.id, (header.name, data.into_owned()));
            }
            Record::Channel(c) => {
                let qos = c
                    .metadata
                    .get("offered_qos_profiles")
                    .cloned()
                    .unwrap_or_default();
                channels.insert(c.id, (c.topic, c.schema_id, qos));
            }
            Record::Message { header, data } => {
                let topic = match topics.get(&header.channel_id) {
                    Some(&t) => t,
                    None => {
                        let Some((name, schema_id, qos)) = channels.get(&header.channel_id) else {
                            return Ok(false);
                        };
                        let (type_name, schema) =
                            schemas.get(schema_id).cloned().unwrap_or_default();
                        let t =
                            writer.add_topic_with_schema(name, &type_name, &schema, qos.clone())?;
                        topics.insert(header.channel_id, t);
                        t
                    }
                };
                writer.write_raw(topic, header.log_time, &data)?;
                count += 1;
            }
            _ => {}
        }
        Ok(true)
    })?;
    Ok(count)
}

/// Read the repaired file back: complete, with `expected` messages.
fn verify(path: &Path, expected: u64) -> Result<(), BagError> {
    if kind(path)? != Kind::Complete {
        return Err(mcap_err(
            path,
            "the repaired file has no footer: left in place, metadata.yaml not changed",
        ));
    }
    let mut count = 0u64;
    let clean = stream_records(path, |opcode, _| {
        count += u64::from(opcode == 0x05);
        Ok(true)
    })?;
    if !clean || count != expected {
        return Err(mcap_err(path, format!("read back {count} messages of {expected} written: left in place, metadata.yaml not changed")));
    }
    Ok(())
}

/// The repaired file of a damaged `source`.
#[derive(Debug, PartialEq)]
enum Repaired {
    /// A complete one exists (an earlier repair wrote it).
    Done(String),
    /// To be written under this fresh name.
    ToWrite(String),
}

/// `<stem>.repaired.mcap` beside `source`, then `<stem>.repaired-2.mcap`, …:
/// the first that is complete is the repair done before; else the first free
/// name (a name taken by an incomplete file is skipped, never overwritten).
fn repaired_file(source: &Path) -> Result<Repaired, BagError> {
    let stem = source
        .file_stem()
        .map(|s| s.to_string_lossy().into_owned())
        .unwrap_or_default();
    let dir = source.parent().unwrap_or(Path::new("."));
    for name in repaired_names(&stem) {
        let path = dir.join(&name);
        if !path.exists() {
            return Ok(Repaired::ToWrite(name));
        }
        if kind(&path).is_ok_and(|k| k == Kind::Complete) {
            return Ok(Repaired::Done(name));
        }
    }
    Err(mcap_err(source, "no free name for the repaired file"))
}

/// The names `bag repair` gives the repaired file of `<stem>.mcap`.
fn repaired_names(stem: &str) -> impl Iterator<Item = String> + '_ {
    std::iter::once(format!("{stem}.repaired.mcap"))
        .chain((2..MAX_FILES).map(move |i| format!("{stem}.repaired-{i}.mcap")))
}

/// Whether `name` is one of the names repair gives a file of `files`.
fn is_repair_output(name: &str, files: &[PathBuf]) -> bool {
    let Some((stem, suffix)) = name.rsplit_once(".repaired") else {
        return false;
    };
    let numbered = suffix
        .strip_prefix('-')
        .and_then(|s| s.strip_suffix(".mcap"))
        .is_some_and(|n| !n.is_empty() && n.bytes().all(|b| b.is_ascii_digit()));
    (suffix == ".mcap" || numbered)
        && files
            .iter()
            .any(|f| f.file_name().is_some_and(|n| *n == *format!("{stem}.mcap")))
}

/// The metadata.yaml part of a complete file, from its records (streamed):
/// its topics with their types, QoS and counts, its first and last log time.
fn metadata_of(path: &Path) -> Result<Metadata, BagError> {
    use mcap::records::Record;
    let mut schemas: BTreeMap<u16, String> = BTreeMap::new();
    let mut channels: BTreeMap<u16, TopicCount> = BTreeMap::new();
    let mut channel_schema: BTreeMap<u16, u16> = BTreeMap::new();
    let mut span: Option<(u64, u64)> = None;
    let clean = stream_records(path, |opcode, body| {
        let Ok(rec) = mcap::parse_record(opcode, body) else {
            return Ok(false);
        };
        match rec {
            Record::Schema { header, .. } => {
                schemas.insert(header.id, header.name);
            }
            Record::Channel(c) => {
                channel_schema.insert(c.id, c.schema_id);
                channels.entry(c.id).or_insert(TopicCount {
                    name: c.topic.clone(),
                    type_name: String::new(),
                    qos: c
                        .metadata
                        .get("offered_qos_profiles")
                        .cloned()
                        .unwrap_or_default(),
                    count: 0,
                });
            }
            Record::Message { header, .. } => {
                let Some(t) = channels.get_mut(&header.channel_id) else {
                    return Ok(false);
                };
                t.count += 1;
                let time = header.log_time;
                span = Some(span.map_or((time, time), |(a, b)| (a.min(time), b.max(time))));
            }
            _ => {}
        }
        Ok(true)
    })?;
    if !clean {
        return Err(mcap_err(path, "ends with a footer but does not read to its end: not listed, metadata.yaml not changed"));
    }
    let topics = channels
        .into_iter()
        .map(|(id, mut t)| {
            t.type_name = channel_schema
                .get(&id)
                .and_then(|s| schemas.get(s))
                .cloned()
                .unwrap_or_default();
            t
        })
        .collect();
    let name = path
        .file_name()
        .map(|n| n.to_string_lossy().into_owned())
        .unwrap_or_default();
    Ok(Metadata::for_file(name, topics, span))
}

/// A fresh name `base`, `base-2`, … in `dir`.
fn fresh(dir: &Path, base: &str) -> PathBuf {
    std::iter::once(base.to_string())
        .chain((2..).map(|i| format!("{base}-{i}")))
        .map(|n| dir.join(n))
        .find(|p| !p.exists())
        .expect("a free name")
}

/// Repair the bag directory `dir` (see the module documentation).
pub fn repair(dir: &Path) -> Result<Repair, BagError> {
    let files = mcap_files(dir)?;
    // Every original (not a repair's output) with its state.
    let mut originals = Vec::new();
    for f in &files {
        let name = f.file_name().map(|n| n.to_string_lossy().into_owned());
        if name.is_some_and(|n| is_repair_output(&n, &files)) {
            continue;
        }
        let repaired = match kind(f)? {
            Kind::Complete => None,
            Kind::Damaged => Some(repaired_file(f)?),
        };
        originals.push((f.clone(), repaired));
    }
    let to_write = originals
        .iter()
        .any(|(_, r)| matches!(r, Some(Repaired::ToWrite(_))));
    if !to_write && dir.join("metadata.yaml").is_file() {
        return Ok(Repair::AlreadyComplete { files });
    }
    // metadata.yaml lists every file in the order of the originals: an
    // intact one as it is, a damaged one by its repaired file.
    let mut repaired = Vec::new();
    let mut parts = Vec::new();
    for (source, state) in originals {
        match state {
            None => parts.push(metadata_of(&source)?),
            Some(Repaired::Done(name)) => parts.push(metadata_of(&dir.join(name))?),
            Some(Repaired::ToWrite(name)) => {
                let mut writer = BagWriter::create_file(dir, name.clone())?.without_checkpoints();
                let count = copy_messages(&source, &mut writer)?;
                let (summary, metadata) = writer.finish_file()?;
                verify(&dir.join(&name), count)?;
                repaired.push((source, summary));
                parts.push(metadata);
            }
        }
    }
    let meta = dir.join("metadata.yaml");
    if meta.is_file() {
        let keep = fresh(dir, "metadata.yaml.before-repair");
        std::fs::copy(&meta, &keep).map_err(io(&keep))?;
    }
    write_combined_metadata(dir, parts)?;
    Ok(Repair::Repaired { repaired })
}
