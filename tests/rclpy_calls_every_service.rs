//! The node's own services (`~/reset`, `~/set_paused`, `~/step`) and the
//! simulation_interfaces ones (`~/reset_simulation`, `~/step_simulation`,
//! `~/get_simulation_state`, `~/set_simulation_state`) called from a real
//! rclpy (ROS 2 Jazzy wheels, rmw_fastrtps_cpp; the simulation_interfaces
//! types built from the released definitions in tests/rclpy/interfaces), each
//! call on a fresh client as `ros2 service call` makes it. The answers are
//! those docs/ros.md ("Services") gives; the reply times are printed.

#![cfg(feature = "ros")]

#[path = "peer/harness.rs"]
mod harness;
#[path = "peer/rclpy.rs"]
mod rclpy;

use harness::{start_node, Netns};
use rclpy::{quantiles, rclpy_peer};
use serde_json::json;

// simulation_interfaces/msg/Result and SimulationState codes.
const FEATURE_UNSUPPORTED: u64 = 0;
const OK: u64 = 1;
const OPERATION_FAILED: u64 = 4;
const ALREADY_IN_TARGET_STATE: u64 = 101;
const PLAYING: u64 = 1;
const PAUSED: u64 = 2;

#[test]
fn the_nodes_own_and_the_simulation_interfaces_services_answer_rclpy_as_documented() {
    let ns = Netns::new();
    let node = start_node(&ns, 171, &[]);
    let out = rclpy_peer(
        &ns,
        &node,
        "services",
        "/annular_plate",
        json!({"timeout": 20.0}),
    );
    let latencies: Vec<f64> = out["_latency"]
        .as_object()
        .unwrap()
        .values()
        .map(|v| v.as_f64().unwrap())
        .collect();
    if let Some((n, min, p50, p90, _, max)) = quantiles(&latencies) {
        println!(
            "{n} calls, each on a fresh client: first reply min {:.1} ms, p50 {:.1} ms, p90 {:.1} ms, max {:.1} ms",
            min * 1e3,
            p50 * 1e3,
            p90 * 1e3,
            max * 1e3
        );
    }
    let code = |k: &str| {
        out[k]["result"]
            .as_u64()
            .unwrap_or_else(|| panic!("{k}: {}", out[k]))
    };
    // Running.
    assert_eq!(
        (
            out["get_state_running"]["state"].as_u64(),
            code("get_state_running")
        ),
        (Some(PLAYING), OK)
    );
    assert_eq!(
        out["step_running"]["success"], false,
        "~/step is refused while running: {}",
        out["step_running"]
    );
    assert_eq!(
        code("step_simulation_running"),
        OPERATION_FAILED,
        "as the standard says"
    );
    // Paused and stepped: 10 by ~/step, 15 by ~/step_simulation.
    assert_eq!(out["pause"]["success"], true);
    assert_eq!(
        (
            out["get_state_paused"]["state"].as_u64(),
            code("get_state_paused")
        ),
        (Some(PAUSED), OK)
    );
    assert_eq!(out["step"]["success"], true);
    assert_eq!(code("step_simulation"), OK, "{}", out["step_simulation"]);
    let (s10, s25) = (
        out["step"]["step"].as_u64().unwrap(),
        out["step_after"]["step"].as_u64().unwrap(),
    );
    assert_eq!(s25, s10 + 15, "step_simulation steps: {out}");
    assert!((out["step_after"]["sim_time"].as_f64().unwrap() - s25 as f64 * 1e-3).abs() < 1e-9);
    assert_eq!(code("set_paused_again"), ALREADY_IN_TARGET_STATE);
    // Resets: ~/reset and reset_simulation (SCOPE_ALL) to step 0; SCOPE_TIME alone unsupported.
    assert_eq!(out["reset"]["success"], true);
    assert_eq!(out["step_after_reset"]["step"], 0);
    assert_eq!(code("step_simulation_2"), OK);
    assert_eq!(code("reset_time_only"), FEATURE_UNSUPPORTED);
    assert_eq!(code("reset_simulation"), OK);
    assert_eq!(out["step_after_reset_simulation"]["step"], 0);
    // Play, stop (pauses and resets), quit (unsupported), resume.
    assert_eq!(code("play"), OK);
    assert_eq!(out["get_state_playing"]["state"], PLAYING);
    assert_eq!(code("stop"), OK);
    assert_eq!(out["get_state_stopped"]["state"], PAUSED);
    assert!(
        out["get_state_stopped"]["message"]
            .as_str()
            .unwrap()
            .starts_with("step 0,"),
        "{}",
        out["get_state_stopped"]
    );
    assert_eq!(code("quit"), FEATURE_UNSUPPORTED);
    assert_eq!(out["resume"]["success"], true);
}
