//! `bag repair` streams (memory bounded by a record, not the file: a sparse
//! 16 GiB damaged file is repaired in seconds within 100 MB), writes the
//! repaired file under a fresh name and touches nothing it did not write
//! (the damaged file and an old `.broken` are still there byte for byte),
//! refuses what is not MCAP with exit ≠ 0 writing nothing, repairs every
//! damaged file of the directory, and is idempotent; metadata.yaml then lists
//! every file (the intact ones and the repaired ones), as an independent
//! rosbag2 reader (rosbags) reads it.

#[path = "peer/harness.rs"]
mod harness;
mod support;

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::time::Duration;
use support::bounded_run::run_bounded;

const SCENE: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/config/brake_bench.yaml");

fn fresh_dir(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!(
        "annular_plate_repair_{}_{name}",
        std::process::id()
    ));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// A finished bag of 0.5 s in `parent/bag`, its MCAP cut to two thirds (no summary, a partial record).
fn damaged_bag(parent: &Path) -> (PathBuf, PathBuf) {
    let bag = parent.join("bag");
    let r = run_bounded(
        &[
            "simulate",
            SCENE,
            "--duration",
            "0.5",
            "--bag",
            bag.to_str().unwrap(),
            "--quiet",
        ],
        Duration::from_secs(120),
        None,
    );
    assert_eq!(r.code, Some(0), "{r:?}");
    let mcap = bag.join("bag_0.mcap");
    let len = std::fs::metadata(&mcap).unwrap().len();
    std::fs::OpenOptions::new()
        .write(true)
        .open(&mcap)
        .unwrap()
        .set_len(len * 2 / 3)
        .unwrap();
    (bag, mcap)
}

fn snapshot(dir: &Path) -> BTreeMap<String, Vec<u8>> {
    std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| std::fs::metadata(p).unwrap().len() < 1 << 30)
        .map(|p| {
            (
                p.file_name().unwrap().to_string_lossy().into_owned(),
                std::fs::read(&p).unwrap(),
            )
        })
        .collect()
}

fn message_count(dir: &Path) -> u64 {
    let text = std::fs::read_to_string(dir.join("metadata.yaml")).unwrap();
    text.lines()
        .find_map(|l| {
            l.trim()
                .strip_prefix("message_count: ")
                .and_then(|v| v.trim().parse().ok())
        })
        .unwrap()
}

fn repair(dir: &Path) -> support::bounded_run::Bounded {
    run_bounded(
        &["bag", "repair", dir.to_str().unwrap()],
        Duration::from_secs(60),
        None,
    )
}

#[test]
fn a_repair_keeps_the_damaged_file_and_an_old_broken_one_byte_for_byte_and_is_idempotent() {
    let (bag, mcap) = damaged_bag(&fresh_dir("keep"));
    std::fs::write(
        bag.join("bag_0.mcap.broken"),
        b"an earlier repair's damaged file",
    )
    .unwrap();
    let before = snapshot(&bag);
    let r = repair(&bag);
    assert_eq!(r.code, Some(0), "{r:?}");
    let after = snapshot(&bag);
    for (name, bytes) in &before {
        if name != "metadata.yaml" {
            assert!(after.get(name) == Some(bytes), "{name} changed");
        }
    }
    assert_eq!(
        after.get("metadata.yaml.before-repair"),
        before.get("metadata.yaml"),
        "the checkpoint's metadata.yaml is kept"
    );
    assert!(after.contains_key("bag_0.repaired.mcap"));
    let text = std::fs::read_to_string(bag.join("metadata.yaml")).unwrap();
    assert!(
        text.contains("bag_0.repaired.mcap") && !text.contains("- bag_0.mcap"),
        "{text}"
    );
    assert!(
        message_count(&bag) > 100,
        "the messages before the cut are kept"
    );
    assert!(std::fs::metadata(&mcap).unwrap().len() > 0);
    // Again: nothing to do, nothing changed.
    let again = repair(&bag);
    assert_eq!(again.code, Some(0), "{again:?}");
    assert!(
        again.stderr.contains("nothing to repair"),
        "{}",
        again.stderr
    );
    assert_eq!(snapshot(&bag), after);
}

#[test]
fn a_sparse_file_far_beyond_memory_is_repaired_in_bounded_memory_and_time() {
    let (bag, mcap) = damaged_bag(&fresh_dir("sparse"));
    // 16 GiB: the cut bag followed by a zero-filled (sparse) tail.
    std::fs::OpenOptions::new()
        .write(true)
        .open(&mcap)
        .unwrap()
        .set_len(16 << 30)
        .unwrap();
    let r = repair(&bag);
    assert_eq!(r.code, Some(0), "{r:?}");
    assert!(
        r.peak_kib < 100_000,
        "peak {} KiB for a 16 GiB file",
        r.peak_kib
    );
    assert!(r.elapsed < Duration::from_secs(30), "{:?}", r.elapsed);
    assert!(message_count(&bag) > 100);
    assert_eq!(
        std::fs::metadata(&mcap).unwrap().len(),
        16 << 30,
        "the damaged file is left as it was"
    );
}

#[test]
fn what_is_not_mcap_is_refused_and_nothing_is_written() {
    for (name, bytes) in [
        ("empty", &b""[..]),
        ("text", &b"hello, this is not a bag\n"[..]),
        ("garbage", &[0xffu8; 4096][..]),
    ] {
        let dir = fresh_dir(name);
        std::fs::write(dir.join("x.mcap"), bytes).unwrap();
        let before = snapshot(&dir);
        let r = repair(&dir);
        assert!(r.code.is_some_and(|c| c != 0), "{name}: {r:?}");
        assert!(
            r.stderr.contains("not an MCAP file") && r.stderr.contains("x.mcap"),
            "{name}: {}",
            r.stderr
        );
        assert_eq!(snapshot(&dir), before, "{name}: nothing written");
    }
}

#[test]
fn every_damaged_file_of_the_directory_is_repaired() {
    let (bag, mcap) = damaged_bag(&fresh_dir("two"));
    std::fs::copy(&mcap, bag.join("bag_1.mcap")).unwrap();
    let r = repair(&bag);
    assert_eq!(r.code, Some(0), "{r:?}");
    assert!(r.stderr.matches("repaired ").count() == 2, "{}", r.stderr);
    let text = std::fs::read_to_string(bag.join("metadata.yaml")).unwrap();
    assert!(
        text.contains("bag_0.repaired.mcap") && text.contains("bag_1.repaired.mcap"),
        "{text}"
    );
    let one = std::fs::read_to_string(bag.join("metadata.yaml")).unwrap();
    assert!(one.contains("message_count"));
}

/// The files metadata.yaml lists (`relative_file_paths`) and its total count.
fn listed(meta: &serde_json::Value) -> (Vec<String>, u64) {
    let info = &meta["rosbag2_bagfile_information"];
    let paths = info["relative_file_paths"]
        .as_array()
        .unwrap()
        .iter()
        .map(|p| p.as_str().unwrap().to_string())
        .collect();
    (paths, info["message_count"].as_u64().unwrap())
}

#[test]
fn after_repair_metadata_lists_the_intact_and_the_repaired_files_and_a_reader_reads_them_all() {
    let parent = fresh_dir("three");
    let (bag, mcap) = damaged_bag(&parent);
    // A second damaged file: the same recording cut shorter.
    let second = bag.join("bag_1.mcap");
    std::fs::copy(&mcap, &second).unwrap();
    let len = std::fs::metadata(&second).unwrap().len();
    std::fs::OpenOptions::new()
        .write(true)
        .open(&second)
        .unwrap()
        .set_len(len / 2)
        .unwrap();
    // An intact file: another, finished recording of 0.3 s.
    let intact = parent.join("intact");
    let r = run_bounded(
        &[
            "simulate",
            SCENE,
            "--duration",
            "0.3",
            "--bag",
            intact.to_str().unwrap(),
            "--quiet",
        ],
        Duration::from_secs(120),
        None,
    );
    assert_eq!(r.code, Some(0), "{r:?}");
    std::fs::copy(intact.join("intact_0.mcap"), bag.join("bag_2.mcap")).unwrap();
    let intact_count = message_count(&intact);

    let r = repair(&bag);
    assert_eq!(r.code, Some(0), "{r:?}");
    assert_eq!(r.stderr.matches("repaired ").count(), 2, "{}", r.stderr);

    let read = harness::read_bag(&bag, "rosbags", &[]);
    let (paths, total) = listed(&read["metadata_yaml"]);
    assert_eq!(
        paths,
        ["bag_0.repaired.mcap", "bag_1.repaired.mcap", "bag_2.mcap"],
        "every file, the damaged ones by their repaired files"
    );
    let info = &read["metadata_yaml"]["rosbag2_bagfile_information"];
    let files = info["files"].as_array().unwrap();
    let per_file: Vec<u64> = files
        .iter()
        .map(|f| f["message_count"].as_u64().unwrap())
        .collect();
    assert_eq!(
        files
            .iter()
            .map(|f| f["path"].as_str().unwrap())
            .collect::<Vec<_>>(),
        paths
    );
    assert_eq!(per_file.iter().sum::<u64>(), total);
    assert_eq!(per_file[2], intact_count, "the intact file counted whole");
    assert!(
        per_file[1] > 0 && per_file[1] < per_file[0],
        "the shorter cut keeps fewer: {per_file:?}"
    );
    // The reader's view (as `ros2 bag info` and `ros2 bag play` use it):
    // every message listed is there and decodes, topic by topic.
    assert_eq!(read["rosbags_metadata"]["message_count"], total);
    assert_eq!(
        read["undecodable"].as_array().unwrap().len(),
        0,
        "{}",
        read["undecodable"]
    );
    let topics = read["topics"].as_object().unwrap();
    let decoded: u64 = topics.values().map(|t| t["count"].as_u64().unwrap()).sum();
    assert_eq!(decoded, total, "messages read = messages listed");
    for c in read["connections"].as_array().unwrap() {
        let topic = c["topic"].as_str().unwrap();
        assert_eq!(
            c["msgcount"], topics[topic]["count"],
            "{topic}: the listed count is what is read"
        );
    }
    let topic_sum: u64 = info["topics_with_message_count"]
        .as_array()
        .unwrap()
        .iter()
        .map(|t| t["message_count"].as_u64().unwrap())
        .sum();
    assert_eq!(topic_sum, total);

    // Idempotent: a second repair changes nothing.
    let after = snapshot(&bag);
    let again = repair(&bag);
    assert_eq!(again.code, Some(0), "{again:?}");
    assert!(
        again.stderr.contains("nothing to repair"),
        "{}",
        again.stderr
    );
    assert_eq!(
        snapshot(&bag),
        after,
        "the second repair changed the directory"
    );
}

#[test]
fn an_incomplete_file_under_the_repaired_name_is_skipped_not_repaired_and_repair_stays_idempotent()
{
    let (bag, mcap) = damaged_bag(&fresh_dir("taken"));
    // An interrupted earlier repair: its output cut short.
    let bytes = std::fs::read(&mcap).unwrap();
    std::fs::write(bag.join("bag_0.repaired.mcap"), &bytes[..bytes.len() / 3]).unwrap();
    let before = snapshot(&bag);
    let r = repair(&bag);
    assert_eq!(r.code, Some(0), "{r:?}");
    assert_eq!(
        r.stderr.matches("repaired ").count(),
        1,
        "only the original is repaired: {}",
        r.stderr
    );
    let after = snapshot(&bag);
    assert_eq!(
        after.get("bag_0.repaired.mcap"),
        before.get("bag_0.repaired.mcap"),
        "the incomplete file is left as it was"
    );
    assert!(
        after.contains_key("bag_0.repaired-2.mcap"),
        "{:?}",
        after.keys()
    );
    let text = std::fs::read_to_string(bag.join("metadata.yaml")).unwrap();
    assert!(
        text.contains("- bag_0.repaired-2.mcap") && !text.contains("- bag_0.repaired.mcap"),
        "{text}"
    );
    let again = repair(&bag);
    assert!(
        again.stderr.contains("nothing to repair"),
        "{}",
        again.stderr
    );
    assert_eq!(snapshot(&bag), after);
}
