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
        let mut child = Command::new(node_binary())
            .args(["simulate".as_ref(), scene.as_os_str(), "--duration".as_ref(), "1000".as_ref()])
            .args(["--csv".as_ref(), csv.as_os_str(), "--bag".as_ref(), bag.as_os_str(), "--quiet".as_ref()])
            .stdin(Stdio::null())
            .stderr(Stdio::piped())
            .spawn()
            .unwrap();
        // Let it run a while (the CSV is written through a buffer: wait for some of it).
        let start = Instant::now();
        while csv_rows(&csv) < 500 {
            assert!(start.elapsed() < Duration::from_secs(120), "simulate wrote nothing in 2 min");
            std::thread::sleep(Duration::from_millis(20));
        }
        let status = Command::new("kill").args([format!("-{signal}"), child.id().to_string()]).status().unwrap();
        assert!(status.success());
        let out = child.wait_with_output().unwrap();
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert!(!out.status.success(), "SIG{signal}: the exit status says the run did not complete");
        assert!(stderr.contains("interrupted at t = "), "SIG{signal}: {stderr}");
        assert!(bag.join("metadata.yaml").is_file(), "SIG{signal}: metadata.yaml written");

        let rows = csv_rows(&csv);
        let d = read_bag(&bag, "rosbags", &["/clock"]);
        assert_eq!(d["undecodable"], serde_json::json!([]), "SIG{signal}: every message decodes");
        assert_eq!(d["topics"]["/clock"]["count"].as_u64(), Some(rows as u64), "SIG{signal}: one /clock per CSV row (t = 0 included)");
        assert_eq!(d["topics"]["/joint_states"]["count"].as_u64(), Some(rows as u64), "SIG{signal}: every recorded step");
        assert!(rows >= 500 && rows < 1_000_001, "SIG{signal}: {rows} rows");
    }
}
