//! Per-topic wrenches read at step boundaries (RustDDS patch §16,
//! `src/ros/step_aligned_receive.rs`, `ros.input_reception`).
//!
//! A Cyclone DDS peer publishes a WrenchStamped on each of twelve ALE wrench
//! topics every millisecond, as an rclpy script with one publisher per pad
//! does, to the node running free at 1 kHz. With `ros.input_reception:
//! step_aligned` the node reads its input datagrams at step boundaries while
//! the flow lasts (so its DDS thread no longer wakes for each one); it must
//! still accept every sample, apply the newest one, answer a service within a
//! few steps, and go back to reading on arrival once the flow stops. By
//! default it reads on arrival throughout.

#![cfg(feature = "ros")]

#[path = "peer/harness.rs"]
mod harness;

use harness::{f, peer, start_node_on, temp_dir, Netns};
use serde_json::{json, Value};

const TOPICS: usize = 12;

/// One flow at a time: two Python peers and two nodes at once on a loaded
/// 2-core machine could slow the peer below what engages the gate.
static ONE_AT_A_TIME: std::sync::Mutex<()> = std::sync::Mutex::new(());

/// The brake bench's disc with twelve ALE nodes on one radius.
fn scene_with_ale_nodes() -> std::path::PathBuf {
    let angular: Vec<String> = (0..TOPICS)
        .map(|j| format!("{}", j as f64 / TOPICS as f64))
        .collect();
    let text = format!(
        "/**:\n  ros__parameters:\n    plate:\n      inner_radius: 0.07\n      outer_radius: 0.153\n      thickness: 0.0181\n      \
         density: 7850.0\n      youngs_modulus: 2.1e11\n      poisson_ratio: 0.3\n      inner_boundary: supported\n      \
         outer_boundary: free\n      nodal_diameters: [0, 1, 2, 3]\n      nodal_circles: [0]\n      damping: [0.005]\n    \
         nodes:\n      ale_radial: [{}]\n      ale_angular: [{}]\n    simulation:\n      rate_hz: 1000.0\n",
        ["0.6"; TOPICS].join(", "),
        angular.join(", ")
    );
    let path = temp_dir().join("twelve_ale_nodes.yaml");
    std::fs::write(&path, text).expect("write the scene");
    path
}

/// The flow of `seconds` against a node started with `ros_args`.
fn flow(domain: u16, ros_args: &[&str], seconds: f64) -> Value {
    let _one = ONE_AT_A_TIME.lock().unwrap_or_else(|e| e.into_inner());
    let ns = Netns::new();
    let node = start_node_on(&ns, domain, &scene_with_ale_nodes(), &[], ros_args);
    let out = peer(
        &ns,
        &node,
        "per_topic_flow",
        "/annular_plate",
        json!({"topics": TOPICS, "seconds": seconds}),
    );
    let sent = f(&out, "sent") as u64;
    assert!(
        sent as f64 >= 300.0 * seconds,
        "the peer sent only {sent} wrenches in {seconds} s"
    );
    assert_eq!(
        f(&out, "accepted") as u64,
        sent,
        "every wrench sent is accepted once"
    );
    assert_eq!(f(&out, "rejected_total"), 0.0);
    // The newest wrench is the one applied: its stamp is echoed in the state.
    assert_eq!(f(&out, "last_input_stamp.sec"), 1.0);
    assert_eq!(f(&out, "last_input_stamp.nanosec") as u64, sent - 1);
    out
}

fn receptions(out: &Value) -> Vec<&str> {
    out["during"]
        .as_array()
        .unwrap()
        .iter()
        .filter_map(|v| v.as_str())
        .collect()
}

#[test]
fn per_topic_wrenches_are_read_at_step_boundaries_and_none_is_lost() {
    let args = [
        "-p",
        "ros.diagnostics_period:=0.1",
        "-p",
        "ros.input_reception:=step_aligned",
    ];
    let out = flow(71, &args, 3.0);
    assert_eq!(
        out["before"], "on arrival",
        "no inputs yet: datagrams are read as they arrive"
    );
    let during = receptions(&out);
    assert!(
        during.contains(&"at step boundaries"),
        "twelve wrenches a step must switch the node to step-aligned reception; /diagnostics said {during:?}"
    );
    assert_eq!(
        out["after"], "on arrival",
        "once the flow stops the node reads on arrival again"
    );

    // A service call while the node reads at step boundaries waits for at
    // most one step or the gate's 2-ms hold on the node's side; the bound
    // leaves room for Python and a loaded machine.
    let service_s = f(&out, "service_s");
    eprintln!(
        "{} wrenches sent, all accepted; service round trip while step-aligned: {:.1} ms",
        out["sent"],
        service_s * 1e3
    );
    assert!(
        service_s < 0.5,
        "a service call took {service_s} s while reading at step boundaries"
    );
}

#[test]
fn by_default_input_datagrams_are_read_on_arrival() {
    let out = flow(72, &["-p", "ros.diagnostics_period:=0.1"], 1.5);
    let during = receptions(&out);
    assert!(
        !during.is_empty() && during.iter().all(|r| *r == "on arrival"),
        "/diagnostics said {during:?}"
    );
    assert!(
        out["service_s"].is_null(),
        "the peer times a service only once step-aligned"
    );
}
