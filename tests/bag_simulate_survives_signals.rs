//! `simulate --bag` interrupted by SIGINT or SIGTERM finishes its bag like a
//! full run (summary, index, metadata.yaml), so rosbags opens it and finds
//! every step the CSV of the same run holds; the exit status says it was
//! interrupted.

#[path = "peer/harness.rs"]
mod harness;

use harness::{fresh_dir, node_binary, read_bag, repo};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

fn csv_rows(path: &std::path::Path) -> usize {
    std::fs::read_to_string(path).map_or(0, |t| t.lines().count().saturating_sub(1))
}

#[test]
fn an_interrupted_simulate_bag_is_finished_and_holds_every_step_written() {
    for signal in ["INT", "TERM"] {
        let bag = fresh_dir(&format!("interrupted_{signal}"));
        let csv = repo().join(format!("target/bag-tests/interrupted_{signal}.csv"));
        let _ = std::fs::remove_file(&csv);
        let scene = repo().join("config/brake_bench.yaml");
        let child = Command::new(node_binary())
            .args([
                "simulate".as_ref(),
                scene.as_os_str(),
                "--duration".as_ref(),
                "1000".as_ref(),
            ])
            .args([
                "--csv".as_ref(),
                csv.as_os_str(),
                "--bag".as_ref(),
                bag.as_os_str(),
                "--quiet".as_ref(),
            ])
            .stdin(Stdio::null())
            .stderr(Stdio::piped())
            .spawn()
            .unwrap();
        // Let it run a while (the CSV is written through a buffer: wait for some of it).
        let start = Instant::now();
        while csv_rows(&csv) < 500 {
            assert!(
                start.elapsed() < Duration::from_secs(120),
                "simulate wrote nothing in 2 min"
            );
            std::thread::sleep(Duration::from_millis(20));
        }
        let status = Command::new("kill")
            .args([format!("-{signal}"), child.id().to_string()])
            .status()
            .unwrap();
        assert!(status.success());
        let out = child.wait_with_output().unwrap();
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert!(
            !out.status.success(),
            "SIG{signal}: the exit status says the run did not complete"
        );
        assert!(
            stderr.contains("interrupted at t = "),
            "SIG{signal}: {stderr}"
        );
        assert!(
            bag.join("metadata.yaml").is_file(),
            "SIG{signal}: metadata.yaml written"
        );

        let rows = csv_rows(&csv);
        let d = read_bag(&bag, "rosbags", &["/clock"]);
        assert_eq!(
            d["undecodable"],
            serde_json::json!([]),
            "SIG{signal}: every message decodes"
        );
        assert_eq!(
            d["topics"]["/clock"]["count"].as_u64(),
            Some(rows as u64),
            "SIG{signal}: one /clock per CSV row (t = 0 included)"
        );
        assert_eq!(
            d["topics"]["/joint_states"]["count"].as_u64(),
            Some(rows as u64),
            "SIG{signal}: every recorded step"
        );
        assert!((500..1_000_001).contains(&rows), "SIG{signal}: {rows} rows");
    }
}

/// `message_count` of a bag's metadata.yaml (the writer's last checkpoint).
fn metadata_count(dir: &std::path::Path) -> u64 {
    let text = std::fs::read_to_string(dir.join("metadata.yaml")).unwrap_or_default();
    text.lines()
        .find_map(|l| {
            l.trim()
                .strip_prefix("message_count: ")
                .and_then(|v| v.trim().parse().ok())
        })
        .unwrap_or(0)
}

#[test]
fn a_killed_recording_is_repaired_losing_at_most_what_came_after_its_last_checkpoint() {
    let bag = fresh_dir("killed");
    let scene = repo().join("config/brake_bench.yaml");
    let mut child = Command::new(node_binary())
        .args([
            "simulate".as_ref(),
            scene.as_os_str(),
            "--duration".as_ref(),
            "10000".as_ref(),
        ])
        .args(["--bag".as_ref(), bag.as_os_str(), "--quiet".as_ref()])
        .stdin(Stdio::null())
        .spawn()
        .unwrap();
    // Wait for two checkpoints (metadata.yaml rewritten with more messages).
    let start = Instant::now();
    let first = loop {
        let n = metadata_count(&bag);
        if n > 0 {
            break n;
        }
        assert!(
            start.elapsed() < Duration::from_secs(60),
            "no checkpoint in 60 s"
        );
        std::thread::sleep(Duration::from_millis(20));
    };
    while metadata_count(&bag) == first {
        assert!(
            start.elapsed() < Duration::from_secs(60),
            "no second checkpoint"
        );
        std::thread::sleep(Duration::from_millis(20));
    }
    child.kill().unwrap(); // SIGKILL: no chance to finish anything
    child.wait().unwrap();
    let checkpointed = metadata_count(&bag);

    let repaired = Command::new(node_binary())
        .args(["bag".as_ref(), "repair".as_ref(), bag.as_os_str()])
        .output()
        .unwrap();
    assert!(
        repaired.status.success(),
        "{}",
        String::from_utf8_lossy(&repaired.stderr)
    );
    assert!(
        String::from_utf8_lossy(&repaired.stderr).contains("repaired"),
        "{}",
        String::from_utf8_lossy(&repaired.stderr)
    );
    let d = read_bag(&bag, "rosbags", &["/clock"]);
    assert_eq!(
        d["undecodable"],
        serde_json::json!([]),
        "every message decodes"
    );
    let clocks = d["topics"]["/clock"]["count"].as_u64().unwrap();
    let total: u64 = d["connections"]
        .as_array()
        .unwrap()
        .iter()
        .map(|c| c["msgcount"].as_u64().unwrap())
        .sum();
    assert!(
        total >= checkpointed,
        "the repaired bag keeps everything up to the last checkpoint: {total} < {checkpointed}"
    );
    assert_eq!(
        metadata_count(&bag),
        total,
        "metadata.yaml describes the repaired file"
    );
    assert!(
        clocks > 0 && clocks * 5 <= total + 5,
        "/clock is one of the five per-step topics: {clocks} of {total}"
    );
    // A second repair finds nothing to do.
    let again = Command::new(node_binary())
        .args(["bag".as_ref(), "repair".as_ref(), bag.as_os_str()])
        .output()
        .unwrap();
    assert!(
        again.status.success()
            && String::from_utf8_lossy(&again.stderr).contains("nothing to repair")
    );
}
