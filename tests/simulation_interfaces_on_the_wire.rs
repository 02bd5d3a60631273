//! The ROS 2 standard `simulation_interfaces` services (reset, step N,
//! set/get simulation state) from the Cyclone DDS peer (tests/peer/peer.py,
//! `simulation_interfaces`), under their ROS 2 wire names — the calls a
//! tool written for Gazebo makes. The stepped state is checked against the
//! offline simulation.

#![cfg(feature = "ros")]

#[path = "peer/harness.rs"]
mod harness;

use annular_plate::dynamics::{Simulation, Wrench};
use annular_plate::ros::NodeSetup;
use harness::{floats, peer, scene, start_node, Netns};
use serde_json::{json, Value};

const OK: u64 = 1;
const FEATURE_UNSUPPORTED: u64 = 0;
const OPERATION_FAILED: u64 = 4;
const ALREADY_IN_TARGET_STATE: u64 = 101;
const PLAYING: u64 = 1;
const PAUSED: u64 = 2;

fn code(v: &Value) -> u64 {
    v["result"]["result"]
        .as_u64()
        .unwrap_or_else(|| panic!("no result code in {v}"))
}

fn state(v: &Value) -> u64 {
    assert_eq!(code(v), OK, "{v}");
    v["state"]["state"].as_u64().unwrap()
}

fn message(v: &Value) -> &str {
    v["result"]["error_message"].as_str().unwrap()
}

#[test]
fn reset_step_pause_resume_and_state_query_through_simulation_interfaces() {
    let ns = Netns::new();
    let args = [
        "-p",
        "ros.start_paused:=true",
        "-p",
        "ros.publish_clock:=true",
        "-p",
        "ros.diagnostics_period:=0.05",
    ];
    let node = start_node(&ns, 62, &args);
    let w = [0.0, 0.0, -500.0, 0.0, 0.0, 0.0];
    let steps = 40;
    let out = peer(
        &ns,
        &node,
        "simulation_interfaces",
        "/annular_plate",
        json!({"node": 2, "wrench": w, "steps": steps}),
    );

    assert_eq!(
        state(&out["initial"]),
        PAUSED,
        "started paused (ros.start_paused)"
    );
    assert_eq!(code(&out["step"]), OK, "{}", out["step"]);
    assert_eq!(
        state(&out["after_step"]),
        PAUSED,
        "StepSimulation returns to paused"
    );

    // The stepped state is the offline simulation's after the same wrench and steps.
    let cli: Vec<String> = std::iter::once("--ros-args")
        .chain(args)
        .map(String::from)
        .collect();
    let mut sim = Simulation::new(NodeSetup::load(Some(&scene()), &cli).unwrap().config).unwrap();
    sim.set_ale_wrench(
        1,
        Wrench {
            force: [w[0], w[1], w[2]],
            moment: [w[3], w[4], w[5]],
        },
    )
    .unwrap();
    for _ in 0..steps {
        sim.step().unwrap();
    }
    let q_ale = floats(&out["modal"]["q_ale"]);
    assert!(
        q_ale.iter().any(|q| q.abs() > 1e-12),
        "the wrench moved the plate: {q_ale:?}"
    );
    for (i, (a, b)) in q_ale.iter().zip(sim.q_ale()).enumerate() {
        assert!(
            (a - b).abs() <= 1e-15 + 1e-9 * a.abs().max(b.abs()),
            "q_ale[{i}]: node {a} vs offline {b}"
        );
    }

    assert_eq!(code(&out["play"]), OK);
    assert_eq!(state(&out["playing"]), PLAYING);
    assert_eq!(
        code(&out["step_while_playing"]),
        OPERATION_FAILED,
        "stepping a playing simulation fails, as the standard says"
    );
    assert_eq!(code(&out["play_again"]), ALREADY_IN_TARGET_STATE);
    assert_eq!(code(&out["pause"]), OK);
    assert_eq!(state(&out["paused"]), PAUSED);
    assert_eq!(
        message(&out["paused"]),
        message(&out["still_paused"]),
        "paused: the step count holds"
    );
    assert_eq!(code(&out["pause_again"]), ALREADY_IN_TARGET_STATE);

    assert_eq!(
        code(&out["reset_time_only"]),
        FEATURE_UNSUPPORTED,
        "ROS time never goes back: {}",
        out["reset_time_only"]
    );
    assert_eq!(code(&out["reset"]), OK);
    assert!(
        message(&out["after_reset"]).starts_with("step 0, t = 0 s"),
        "{}",
        out["after_reset"]
    );
    assert_eq!(code(&out["step_after_reset"]), OK);
    assert!(
        message(&out["after_reset_step"]).starts_with("step 5, t = 0.005 s"),
        "{}",
        out["after_reset_step"]
    );

    assert_eq!(code(&out["play_before_stop"]), OK);
    assert_eq!(code(&out["stop"]), OK, "{}", out["stop"]);
    assert_eq!(state(&out["stopped"]), PAUSED, "STOPPED = paused and reset");
    assert!(
        message(&out["stopped"]).starts_with("step 0, t = 0 s"),
        "{}",
        out["stopped"]
    );
    assert_eq!(code(&out["quit"]), FEATURE_UNSUPPORTED);
    assert_eq!(code(&out["bad_state"]), OPERATION_FAILED);
    assert!(
        message(&out["bad_state"]).contains("state.state = 9"),
        "{}",
        out["bad_state"]
    );
}
