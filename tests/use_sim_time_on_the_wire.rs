//! `use_sim_time: true` on the wire: the node follows a `/clock` published
//! by the Cyclone DDS peer (tests/peer/peer.py, `follow_clock`), as a ROS 2
//! node does next to Gazebo or `ros2 bag play --clock`; a /clock that jumps
//! forward beyond `ros.max_clock_jump` re-anchors it (`clock_jump`). Nothing here asserts
//! timing: the peer waits for each condition (generous timeouts) and only
//! checks that nothing happens while the clock stands still.

#![cfg(feature = "ros")]

#[path = "peer/harness.rs"]
mod harness;

use annular_plate::dynamics::Simulation;
use annular_plate::ros::NodeSetup;
use harness::{floats, peer, scene, start_node, Netns};
use serde_json::json;

const MS: i64 = 1_000_000;
const T0: i64 = 100_000 * MS;

#[test]
fn the_node_steps_and_stamps_with_the_peers_clock_and_stands_still_with_it() {
    let ns = Netns::new();
    let args = [
        "-p",
        "use_sim_time:=true",
        "-p",
        "ros.diagnostics_period:=0.05",
    ];
    let node = start_node(&ns, 61, &args);
    let out = peer(
        &ns,
        &node,
        "follow_clock",
        "/annular_plate",
        json!({"t0_ns": T0}),
    );

    // Running, not paused, but without a clock: no step (a wall-clock node would have taken ~1000).
    assert_eq!(out["before_clock"], 0, "{out}");
    assert_eq!(out["before_clock_diag_step"], "0");
    // The first /clock is the origin: its time reported, no step taken.
    assert_eq!(out["origin_diag_step"], "0");
    assert_eq!(out["after_origin"], 0);
    // Half a step of clock: no step; a still clock: no step; paused: the advance is skipped.
    assert_eq!(out["after_half_step"], 5, "5.5 steps of clock give 5 steps");
    assert_eq!(
        out["after_standstill"], 10,
        "the clock stood still at 10 steps"
    );
    assert_eq!(
        out["step_service"]["success"], false,
        "~/step is refused while the clock drives"
    );
    assert!(
        out["step_service"]["message"]
            .as_str()
            .unwrap()
            .contains("use_sim_time"),
        "{}",
        out["step_service"]
    );
    assert_eq!(out["pause"]["success"], true);
    assert_eq!(
        out["while_paused"], 30,
        "paused by ~/set_paused: the clock's advance to 50 ms is not stepped"
    );
    assert_eq!(
        out["after_resume"], 30,
        "resumed: the skipped advance is not caught up"
    );
    assert_eq!(out["final"], 33);

    // Every step published once, in order, stamped with the clock's time on the step grid:
    // t0 + k ms up to step 30, then t0 + 50 ms + (k - 30) ms after the paused stretch.
    let modal = out["modal"].as_array().unwrap();
    let steps: Vec<i64> = modal.iter().map(|m| m["step"].as_i64().unwrap()).collect();
    assert_eq!(
        steps,
        (1..=33).collect::<Vec<_>>(),
        "one state per step, none lost or repeated"
    );
    for m in modal {
        let k = m["step"].as_i64().unwrap();
        let want = if k <= 30 {
            T0 + k * MS
        } else {
            T0 + (k + 20) * MS
        };
        assert_eq!(m["stamp"].as_i64().unwrap(), want, "stamp of step {k}");
        let sim_time = m["sim_time"].as_f64().unwrap();
        assert!(
            (sim_time - k as f64 * 1e-3).abs() < 1e-12,
            "the plate's own time advanced dt per step: step {k} at {sim_time}"
        );
    }

    // The joint state after 33 steps is the offline simulation's after 33 steps.
    let setup = NodeSetup::load(
        Some(&scene()),
        &[
            "--ros-args".to_string(),
            "-p".into(),
            "use_sim_time:=true".into(),
        ],
    )
    .unwrap();
    let mut sim = Simulation::new(setup.config).unwrap();
    for _ in 0..33 {
        sim.step().unwrap();
    }
    let js = &out["last_joint_state"];
    assert!(!js.is_null(), "the joint state stamped t0 + 53 ms arrived");
    let (pos, vel) = (floats(&js["position"])[0], floats(&js["velocity"])[0]);
    let want = sim.joint();
    let close = |a: f64, b: f64| (a - b).abs() <= 1e-12 + 1e-9 * a.abs().max(b.abs());
    assert!(
        close(pos, want.position) && close(vel, want.velocity),
        "node ({pos}, {vel}) vs offline ({}, {})",
        want.position,
        want.velocity
    );
    assert!(
        node.stderr().contains("following /clock"),
        "{}",
        node.stderr()
    );
}

/// 10⁶ s: the jump of one /clock message that once committed the node to
/// 10⁹ catch-up steps.
const JUMP: i64 = 1_000_000 * 1_000_000_000;

#[test]
fn a_clock_jump_beyond_the_bound_re_anchors_the_node_and_warns_with_a_count() {
    let ns = Netns::new();
    let args = [
        "-p",
        "use_sim_time:=true",
        "-p",
        "ros.diagnostics_period:=0.05",
    ];
    let node = start_node(&ns, 64, &args);
    let out = peer(
        &ns,
        &node,
        "clock_jump",
        "/annular_plate",
        json!({"t0_ns": T0, "jump_ns": JUMP}),
    );
    println!(
        "first step after a 1e6 s jump: {:.2} s of wall time after it was sent",
        out["seconds_to_step_after_jump"].as_f64().unwrap()
    );

    // Each step once, in order; after each jump the stamps continue from the
    // new clock time (re-anchored), not from the old one through the gap.
    let modal = out["modal"].as_array().unwrap();
    let steps: Vec<i64> = modal.iter().map(|m| m["step"].as_i64().unwrap()).collect();
    assert_eq!(steps, (1..=13).collect::<Vec<_>>(), "{out}");
    for m in modal {
        let k = m["step"].as_i64().unwrap();
        let want = match k {
            1..=5 => T0 + k * MS,
            6..=10 => T0 + JUMP + (k - 5) * MS,
            _ => T0 + 2 * JUMP + (k - 10) * MS,
        };
        assert_eq!(m["stamp"].as_i64().unwrap(), want, "stamp of step {k}");
    }
    assert!(
        out["max_step_reported"].as_i64().unwrap() <= 13,
        "/diagnostics saw no catch-up steps: {out}"
    );

    // Each jump: a WARN naming the jump and the bound, with the count.
    let warnings = out["warnings"].as_array().unwrap();
    for count in ["1", "2"] {
        let w = warnings
            .iter()
            .find(|w| w["values"]["clock_jumps_forward"] == count)
            .unwrap_or_else(|| panic!("no WARN with clock_jumps_forward = {count}: {out}"));
        let message = w["message"].as_str().unwrap();
        assert!(
            message.contains("/clock jumped forward 1 time(s) beyond ros.max_clock_jump"),
            "{message}"
        );
    }
    let last = &out["last_report"];
    assert_eq!(
        last["values"]["clock_jumps_forward"], "2",
        "the count stays: {last}"
    );
    assert!(
        !last["message"].as_str().unwrap().contains("jumped"),
        "a jump is reported once: {last}"
    );
    let log = node.stderr();
    assert_eq!(
        log.matches("/clock jumped").count(),
        2,
        "one log line per jump:\n{log}"
    );
    assert!(
        log.contains("beyond ros.max_clock_jump = 1 s")
            && log.contains("1 jump(s) so far")
            && log.contains("2 jump(s) so far"),
        "{log}"
    );
}
