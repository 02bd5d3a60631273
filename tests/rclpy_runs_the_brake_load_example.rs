//! `launch-scripts/brake_load_example.py`, unmodified, run with rclpy (ROS 2
//! Jazzy wheels, rmw_fastrtps_cpp) against the node recording the run
//! (`annular_plate run --record DIR`); its printed summary checked against the
//! bag, read with rosbags (tests/peer/bag_read.py, types rebuilt from the bag):
//!
//! - the largest brake torque and the minimum speed it prints equal the
//!   bag's largest −Σ `friction_torque` of `~/pad_states` and smallest
//!   `/joint_states` velocity to the printed digits (the script takes both
//!   over every state it receives, depth 1000);
//! - the speed dip in the bag (25 rad/s − its minimum), and the printed
//!   one, agree within 2 % with the closed form of the script's docstring,
//!   Δω = ∫ max(0, 2 μ N(t) r − 1500 N·m) / J dt (μ = 0.4, r = 0.1198 m,
//!   J = 0.117 kg·m²), evaluated on the clamp-force history in the bag
//!   (`PadStates.clamp_force`) integrated over `PadStates.sim_time` — the
//!   script's profile is wall-clock timed, and on a loaded machine the node
//!   may run slower than real time, so only the simulated-time integral of
//!   what was applied predicts the dip.

#![cfg(feature = "ros")]

#[path = "peer/harness.rs"]
mod harness;
#[path = "peer/rclpy.rs"]
mod rclpy;

use harness::{fresh_dir, repo, start_node_with, Netns};
use rclpy::run_python;
use serde_json::Value;
use std::ffi::OsStr;
use std::process::{Command, Stdio};
use std::time::Duration;

const PADS: &str = "/annular_plate/pad_states";

/// The number after `key` in the summary line.
fn number_after(line: &str, key: &str) -> (f64, usize) {
    let rest = &line[line
        .find(key)
        .unwrap_or_else(|| panic!("no `{key}` in `{line}`"))
        + key.len()..];
    let text = rest.split_whitespace().next().unwrap();
    let decimals = text.split('.').nth(1).map_or(0, |d| d.len());
    (
        text.parse()
            .unwrap_or_else(|e| panic!("`{text}` after `{key}`: {e}")),
        decimals,
    )
}

fn round_to(x: f64, decimals: usize) -> String {
    format!("{x:.decimals$}")
}

#[test]
fn the_brake_load_example_runs_unmodified_and_its_summary_matches_the_nodes_bag() {
    let ns = Netns::new();
    let bag = fresh_dir("rclpy_brake_load_example");
    let mut node = start_node_with(&ns, 181, &[OsStr::new("--record"), bag.as_os_str()], &[]);
    let script = repo().join("launch-scripts/brake_load_example.py");
    let run = run_python(&ns, 181, &[script.as_os_str()], Duration::from_secs(180));
    let context = format!(
        "--- example stdout\n{}\n--- example stderr\n{}\n--- node stderr\n{}",
        run.stdout,
        run.stderr,
        node.stderr()
    );
    assert!(
        run.success(),
        "the example failed or timed out ({:?}, {:.1} s):\n{context}",
        run.status,
        run.seconds
    );
    node.signal("INT");
    let status = node
        .wait_exit(Duration::from_secs(20))
        .unwrap_or_else(|| panic!("the node did not stop:\n{context}"));
    assert!(status.success(), "node exit {status}:\n{context}");
    println!(
        "the example ran {:.1} s; its last lines:\n{}",
        run.seconds,
        run.stdout
            .lines()
            .rev()
            .take(3)
            .collect::<Vec<_>>()
            .join("\n")
    );

    let summary = run
        .stdout
        .lines()
        .find(|l| l.starts_with("minimum speed "))
        .unwrap_or_else(|| panic!("no summary line:\n{context}"));
    let (min_speed, speed_digits) = number_after(summary, "minimum speed ");
    let (max_brake, brake_digits) = number_after(summary, "largest brake torque ");

    // The bag, with rosbags from the rclpy venv.
    let python = repo().join("target/rclpy-venv/bin/python");
    let out = Command::new(&python)
        .arg(repo().join("tests/peer/bag_read.py"))
        .arg(&bag)
        .args(["--reader", "rosbags", "--full", "/joint_states", PADS])
        .stdin(Stdio::null())
        .output()
        .expect("cannot run tests/peer/bag_read.py");
    assert!(
        out.status.success(),
        "bag_read.py: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    let d: Value = serde_json::from_slice(&out.stdout).expect("bag_read.py prints JSON");
    let joints = d["topics"]["/joint_states"]["messages"]
        .as_array()
        .expect("/joint_states in the bag");
    let pads = d["topics"][PADS]["messages"]
        .as_array()
        .expect("~/pad_states in the bag");
    let speeds: Vec<f64> = joints
        .iter()
        .map(|m| m["velocity"][0].as_f64().unwrap())
        .collect();
    let brakes: Vec<f64> = pads
        .iter()
        .map(|m| {
            -m["friction_torque"]
                .as_array()
                .unwrap()
                .iter()
                .map(|x| x.as_f64().unwrap())
                .sum::<f64>()
        })
        .collect();
    let bag_min = speeds.iter().cloned().fold(f64::INFINITY, f64::min);
    let bag_max_brake = brakes.iter().cloned().fold(f64::NEG_INFINITY, f64::max);

    assert_eq!(
        round_to(bag_max_brake, brake_digits),
        round_to(max_brake, brake_digits),
        "largest brake torque: printed vs the bag's"
    );
    assert_eq!(
        round_to(bag_min, speed_digits),
        round_to(min_speed, speed_digits),
        "minimum speed: printed vs the bag's"
    );

    // The closed form on the applied clamp forces, over simulated time.
    let (mu, r, t_max, j) = (0.4, 0.1198, 1500.0, 0.117);
    let mut closed = 0.0;
    for w in pads.windows(2) {
        let n = w[0]["clamp_force"][0].as_f64().unwrap();
        let dt = w[1]["sim_time"].as_f64().unwrap() - w[0]["sim_time"].as_f64().unwrap();
        closed += (2.0 * mu * n * r - t_max).max(0.0) / j * dt;
    }
    let start = speeds[0];
    let (bag_dip, printed_dip) = (start - bag_min, start - min_speed);
    let wall = run.seconds;
    let sim = pads.last().unwrap()["sim_time"].as_f64().unwrap();
    println!(
        "speed dip: bag {bag_dip:.4} rad/s, printed {printed_dip:.3} rad/s, closed form on the bag's clamp forces {closed:.4} rad/s \
         ({:+.3} % / {:+.3} %); printed minimum {min_speed} vs the bag's {bag_min:.4}; largest brake torque {max_brake} N m; \
         {} joint states, {} pad states over {sim:.3} s simulated ({wall:.1} s of the example's wall time)",
        100.0 * (bag_dip / closed - 1.0),
        100.0 * (printed_dip / closed - 1.0),
        speeds.len(),
        pads.len()
    );
    assert_eq!(start, 25.0, "the bench starts at 25 rad/s");
    assert!(
        closed > 1.0,
        "the default profile brakes beyond the drive's torque: closed form {closed}"
    );
    assert!(
        (bag_dip / closed - 1.0).abs() <= 0.02,
        "the bag's dip {bag_dip} vs the closed form {closed}"
    );
    assert!(
        (printed_dip / closed - 1.0).abs() <= 0.02,
        "the printed dip {printed_dip} vs the closed form {closed}"
    );
}
