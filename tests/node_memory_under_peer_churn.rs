//! Peers joining and leaving do not grow the node for good (issue 14, item 5;
//! issue 10 measured 22.7 → 52 MB over 8 rounds of 20 Cyclone peers, half of
//! them killed, never released).
//!
//! A killed reliable subscriber stays matched until its lease expires
//! (Cyclone DDS: 10 s); RustDDS keeps what it has not acknowledged (≤ 8,192
//! samples per writer) and frees it at the expiry, and the node hands the
//! freed heap back to the OS (src/ros/heap.rs). Measured: the node's resident
//! memory once the leases have expired, against the same after a warm-up.

#![cfg(feature = "ros")]

#[path = "peer/harness.rs"]
mod harness;

use harness::{peer, start_node, Netns, NodeProcess};
use serde_json::json;
use std::time::Duration;

/// Resident set size of the node, kB (/proc/PID/status).
fn rss_kb(node: &NodeProcess) -> u64 {
    let status = std::fs::read_to_string(format!("/proc/{}/status", node.pid())).expect("the node's /proc status");
    let line = status.lines().find(|l| l.starts_with("VmRSS:")).expect("VmRSS");
    line.split_whitespace().nth(1).unwrap().parse().unwrap()
}

/// `peers` participants subscribe /joint_states and /tf until each has a
/// sample, then leave cleanly; as many again vanish without a goodbye.
fn churn_round(ns: &Netns, node: &NodeProcess, peers: usize) {
    for clean in [true, false] {
        let out = peer(ns, node, "churn", "/annular_plate", json!({"peers": peers, "clean": clean, "domain": node.domain}));
        assert_eq!(out["joined"], json!(peers), "{out}");
    }
}

/// Cyclone's default lease (10 s), RustDDS's cleanup period and the node's
/// heap trim (5 s), with room for a loaded machine.
const EXPIRY: Duration = Duration::from_secs(20);

#[test]
fn killed_and_departed_peers_leave_no_lasting_memory_behind() {
    let ns = Netns::new();
    let node = start_node(&ns, 41, &[]);
    // Warm-up: the first peers create what every later one reuses.
    churn_round(&ns, &node, 8);
    std::thread::sleep(EXPIRY);
    let warm = rss_kb(&node);
    let mut during = vec![];
    for _ in 0..4 {
        churn_round(&ns, &node, 8);
        during.push(rss_kb(&node));
    }
    std::thread::sleep(EXPIRY);
    let after = rss_kb(&node);
    println!("node RSS: after warm-up {warm} kB; during 4 rounds of 8 + 8 killed peers {during:?} kB; leases expired {after} kB");
    // Measured here: 17.3 → 17.1 MB (during the rounds up to 25.6 MB); with the
    // trim thread disabled the same run went 30.2 → 36.6 MB and stayed.
    assert!(after < warm + 3_000, "{warm} → {after} kB");
}
