//! What docs/ros.md promises a ROS 2 user about topics, checked with a real
//! rclpy (ROS 2 Jazzy wheels from PyPI, rmw_fastrtps_cpp; tests/rclpy/peer.py):
//! every output topic with the QoS users pick — rclpy's default (reliable,
//! volatile, depth 10) and `qos_profile_sensor_data` (best effort) — the
//! latched ones (`/tf_static`, `~/critical_speeds`, `/rosout`) for late
//! joiners, the graph as `ros2 node/topic/service list` sees it, every input
//! topic from rclpy's default publishers with bad input refused and counted,
//! `/clock` both ways, and a renamed, namespaced node.
//!
//! Each test has its own network namespace and ROS_DOMAIN_ID; waits are
//! generous and nothing is timed.

#![cfg(feature = "ros")]

#[path = "peer/harness.rs"]
mod harness;
#[path = "peer/rclpy.rs"]
mod rclpy;

use annular_plate::model::campbell::critical_speeds;
use annular_plate::model::PlateModel;
use annular_plate::ros::NodeSetup;
use harness::{scene, start_node, Netns};
use rclpy::rclpy_peer;
use serde_json::{json, Value};
use std::collections::BTreeMap;

fn strings(v: &Value) -> Vec<String> {
    v.as_array()
        .unwrap_or_else(|| panic!("not an array: {v}"))
        .iter()
        .map(|x| x.as_str().unwrap().to_string())
        .collect()
}

/// The topic -> [type] map of a graph query, as sorted pairs.
fn graph(v: &Value) -> BTreeMap<String, Vec<String>> {
    v.as_object()
        .unwrap_or_else(|| panic!("not an object: {v}"))
        .iter()
        .map(|(k, t)| (k.clone(), strings(t)))
        .collect()
}

fn expect_graph(pairs: &[(&str, &str)]) -> BTreeMap<String, Vec<String>> {
    pairs
        .iter()
        .map(|(t, ty)| (t.to_string(), vec![ty.to_string()]))
        .collect()
}

#[test]
fn every_topic_reaches_rclpy_with_default_and_sensor_data_qos_and_latched_ones_reach_late_joiners()
{
    let ns = Netns::new();
    let node = start_node(&ns, 161, &["-p", "ros.diagnostics_period:=0.2"]);
    let out = rclpy_peer(
        &ns,
        &node,
        "topics",
        "/annular_plate",
        json!({"messages": 20}),
    );

    for (group, want) in [("reliable", 20), ("sensor_data", 20)] {
        for (topic, n) in out["received"][group].as_object().unwrap() {
            let need = if topic == "diagnostics" || topic == "plate_marker" {
                2
            } else {
                want
            };
            assert!(n.as_u64().unwrap() >= need, "{group} {topic}: {n} messages");
        }
    }
    assert_eq!(out["joint_state"]["name"], json!(["plate_joint"]));
    assert_eq!(
        out["joint_state"]["velocity"],
        json!([25.0]),
        "the scene's joint.speed"
    );
    assert_eq!(out["sensor_joint_state_name"], json!(["plate_joint"]));
    assert_eq!(
        strings(&out["tf_children"]),
        [
            "plate_ale_1",
            "plate_ale_2",
            "plate_ale_3",
            "plate_lagrange_1",
            "plate_rotor"
        ]
    );
    assert_eq!(strings(&out["tf_parents"]), ["plate_base", "plate_rotor"]);
    assert_eq!(out["modal"]["frame_id"], "plate_base");
    assert_eq!(
        out["modal"]["modes"], 9,
        "k = 0..4 (cos and sin for k > 0), l = 0"
    );
    assert_eq!(out["modal"]["steps_increasing"], true);
    assert_eq!(
        out["pad_states"],
        json!({"clamp_force": [0.0], "frame_id": "plate_base"})
    );
    for s in [
        "/annular_plate: simulation",
        "/annular_plate: inputs",
        "/annular_plate: critical speeds",
    ] {
        assert!(
            strings(&out["diagnostics"]).contains(&s.to_string()),
            "/diagnostics lacks `{s}`: {}",
            out["diagnostics"]
        );
    }
    assert!(
        out["marker"]["markers"].as_u64().unwrap() >= 2,
        "DELETEALL and the plate: {}",
        out["marker"]
    );
    println!(
        "plate marker: {} B per message through rclpy",
        out["marker"]["bytes"]
    );

    // Late joiners (transient local, depth 1): one message each.
    assert_eq!(
        out["tf_static"],
        json!({"messages": 1, "children": ["plate_base"], "parents": ["world"]})
    );
    let cs = &out["critical_speeds"];
    assert_eq!(cs["messages"], 1);
    let setup = NodeSetup::load(Some(&scene()), &["--ros-args".to_string()]).unwrap();
    let model = PlateModel::new(&setup.config.plate).unwrap();
    let want = critical_speeds(&model, &setup.config.centrifugal).unwrap();
    assert_eq!(cs["k"], json!(want.iter().map(|c| c.k).collect::<Vec<_>>()));
    assert_eq!(cs["l"], json!(want.iter().map(|c| c.l).collect::<Vec<_>>()));
    for (got, c) in cs["rad_s"].as_array().unwrap().iter().zip(&want) {
        let got = got.as_f64().unwrap();
        assert!(
            (got - c.rad_s).abs() <= 1e-12 * c.rad_s,
            "critical speed <{}, {}>: {got} vs {}",
            c.k,
            c.l,
            c.rad_s
        );
    }
    assert!(
        out["rosout"]["messages"].as_u64().unwrap() >= 1,
        "the start-up log line on /rosout: {}",
        out["rosout"]
    );
    assert_eq!(out["rosout"]["names"], json!(["annular_plate"]));

    // The graph (`ros2 node list`, `ros2 topic list -t`, `ros2 node info`).
    assert!(
        out["graph_nodes"]
            .as_array()
            .unwrap()
            .contains(&json!(["annular_plate", "/"])),
        "{}",
        out["graph_nodes"]
    );
    let publishes = expect_graph(&[
        ("/joint_states", "sensor_msgs/msg/JointState"),
        ("/tf", "tf2_msgs/msg/TFMessage"),
        ("/tf_static", "tf2_msgs/msg/TFMessage"),
        (
            "/annular_plate/critical_speeds",
            "annular_plate/msg/CriticalSpeeds",
        ),
        (
            "/annular_plate/modal_amplitudes",
            "annular_plate/msg/ModalAmplitudes",
        ),
        ("/annular_plate/pad_states", "annular_plate/msg/PadStates"),
        (
            "/annular_plate/plate_marker",
            "visualization_msgs/msg/MarkerArray",
        ),
        ("/diagnostics", "diagnostic_msgs/msg/DiagnosticArray"),
        ("/rosout", "rcl_interfaces/msg/Log"),
        // ros2-client's node announces it, as rcl's nodes do.
        ("/parameter_events", "rcl_interfaces/msg/ParameterEvent"),
    ]);
    assert_eq!(
        graph(&out["node_publishes"]),
        publishes,
        "what `ros2 node info /annular_plate` lists as publishers"
    );
    let subscribes = expect_graph(&[
        ("/annular_plate/speed_command", "std_msgs/msg/Float64"),
        (
            "/annular_plate/ale_1/wrench",
            "geometry_msgs/msg/WrenchStamped",
        ),
        (
            "/annular_plate/ale_2/wrench",
            "geometry_msgs/msg/WrenchStamped",
        ),
        (
            "/annular_plate/ale_3/wrench",
            "geometry_msgs/msg/WrenchStamped",
        ),
        (
            "/annular_plate/lagrange_1/wrench",
            "geometry_msgs/msg/WrenchStamped",
        ),
        (
            "/annular_plate/wrenches",
            "annular_plate/msg/NodeWrenchArray",
        ),
        ("/annular_plate/pad_1/clamp_force", "std_msgs/msg/Float64"),
        (
            "/annular_plate/pad_clamp_forces",
            "annular_plate/msg/PadClampForces",
        ),
    ]);
    assert_eq!(
        graph(&out["node_subscribes"]),
        subscribes,
        "what `ros2 node info /annular_plate` lists as subscribers"
    );
    let topics = graph(&out["graph_topics"]);
    for (t, ty) in publishes.iter().chain(subscribes.iter()) {
        assert_eq!(
            topics.get(t),
            Some(ty),
            "`ros2 topic list -t`: one type on {t}"
        );
    }
}

#[test]
fn good_input_from_rclpy_is_applied_and_bad_input_is_refused_and_counted() {
    let ns = Netns::new();
    let node = start_node(&ns, 162, &["-p", "ros.diagnostics_period:=0.1"]);
    let out = rclpy_peer(&ns, &node, "inputs", "/annular_plate", json!({}));
    let good = &out["after_good"];
    for k in [
        "accepted_speed_command",
        "accepted_node_wrench",
        "accepted_wrench_array",
        "accepted_pad_clamp_force",
        "accepted_pad_clamp_forces",
    ] {
        assert_eq!(
            good[k], "1",
            "{k} after one good sample on each input topic: {good}"
        );
    }
    assert_eq!(good["accepted_total"], "5", "{good}");
    assert_eq!(good["rejected_total"], "0", "{good}");
    // NaN speed and NaN wrench, a wrench in a frame not its node's, pad 9 of a
    // one-pad scene, a negative clamp force: each refused whole and counted.
    let bad = &out["after_bad"];
    let want = [
        ("rejected_non_finite", "2"),
        ("rejected_unknown_frame", "1"),
        ("rejected_no_such_node", "1"),
        ("rejected_absurd", "1"),
        ("rejected_malformed_batch", "0"),
        ("rejected_undecodable", "0"),
        ("rejected_total", "5"),
        ("accepted_total", "5"),
    ];
    for (k, v) in want {
        assert_eq!(bad[k], v, "{k}: {bad}");
    }
    // The inputs status is WARN in a report after a rejection, OK in one without.
    let reports: Vec<(u64, u64)> = out["reports"]
        .as_array()
        .unwrap()
        .iter()
        .map(|r| (r[0].as_u64().unwrap(), r[1].as_u64().unwrap()))
        .collect();
    assert!(
        reports.windows(2).any(|w| w[1].0 > w[0].0),
        "no report saw a rejection: {reports:?}"
    );
    for w in reports.windows(2) {
        let want = if w[1].0 > w[0].0 { 1 } else { 0 };
        assert_eq!(
            w[1].1, want,
            "level of the report after {:?} (rejected_total, level): {reports:?}",
            w[0]
        );
    }
    // The node runs on, with the good inputs held.
    assert_eq!(out["step"]["success"], true);
    assert_eq!(
        out["clamp_force"],
        json!([2000.0]),
        "the last good clamp force holds; -5 N was refused"
    );
    let stderr = node.stderr();
    assert!(
        stderr.contains("non-finite") || stderr.contains("NaN") || stderr.contains("rejected"),
        "a rejection is logged: {stderr}"
    );
}

#[test]
fn clock_of_a_node_on_publish_clock_reaches_rclpy_reliable_and_best_effort_and_drives_its_sim_time()
{
    let ns = Netns::new();
    let node = start_node(&ns, 163, &["-p", "ros.publish_clock:=true"]);
    let out = rclpy_peer(
        &ns,
        &node,
        "clock_out",
        "/annular_plate",
        json!({"messages": 50}),
    );
    assert!(
        out["reliable"].as_u64().unwrap() >= 50 && out["best_effort"].as_u64().unwrap() >= 5,
        "{out}"
    );
    assert_eq!(out["monotonic"], true);
    assert_eq!(
        out["clock_types"],
        json!(["rosgraph_msgs/msg/Clock"]),
        "one type on /clock"
    );
    // An rclpy node with use_sim_time follows it: its now() is the node's
    // simulated time (seconds since the start), not the wall clock.
    let follower = out["follower_now_ns"].as_f64().unwrap();
    assert!(
        follower >= out["first_clock_ns"].as_f64().unwrap() && follower < 1e12,
        "the follower's now(): {follower} ns"
    );
    // The outputs are stamped with the same simulated time.
    let stamp = out["modal_stamp_ns"].as_f64().unwrap() * 1e-9;
    assert!(
        (stamp - out["modal_sim_time"].as_f64().unwrap()).abs() < 1e-6,
        "{out}"
    );
}

#[test]
fn clock_published_by_rclpy_drives_a_node_on_use_sim_time() {
    let ns = Netns::new();
    let node = start_node(&ns, 164, &["-p", "use_sim_time:=true"]);
    let out = rclpy_peer(
        &ns,
        &node,
        "clock_in",
        "/annular_plate",
        json!({"origin": 100.0, "dt": 1e-3}),
    );
    assert_eq!(
        out["steps_before_advance"],
        json!([]),
        "no step at the origin"
    );
    assert_eq!(
        out["steps"],
        json!((1..=15).collect::<Vec<u64>>()),
        "5 steps for 5 ms of a reliable clock, 10 more for a best-effort one"
    );
    assert_eq!(out["stamp5_ns"], 100_005_000_000u64);
    assert_eq!(out["stamp15_ns"], 100_015_000_000u64);
    assert!((out["sim_time15"].as_f64().unwrap() - 0.015).abs() < 1e-12);
}

#[test]
fn a_renamed_namespaced_node_shows_under_its_new_names_in_the_rclpy_graph() {
    let ns = Netns::new();
    let node = start_node(&ns, 165, &["-r", "__ns:=/bench", "-r", "__node:=disc"]);
    let services = [
        ("/bench/disc/step", "annular_plate/srv/Step"),
        ("/bench/disc/reset", "std_srvs/srv/Trigger"),
        ("/bench/disc/set_paused", "std_srvs/srv/SetBool"),
        (
            "/bench/disc/reset_simulation",
            "simulation_interfaces/srv/ResetSimulation",
        ),
        (
            "/bench/disc/step_simulation",
            "simulation_interfaces/srv/StepSimulation",
        ),
        (
            "/bench/disc/get_simulation_state",
            "simulation_interfaces/srv/GetSimulationState",
        ),
        (
            "/bench/disc/set_simulation_state",
            "simulation_interfaces/srv/SetSimulationState",
        ),
        (
            "/bench/disc/list_parameters",
            "rcl_interfaces/srv/ListParameters",
        ),
        (
            "/bench/disc/get_parameters",
            "rcl_interfaces/srv/GetParameters",
        ),
        (
            "/bench/disc/get_parameter_types",
            "rcl_interfaces/srv/GetParameterTypes",
        ),
        (
            "/bench/disc/describe_parameters",
            "rcl_interfaces/srv/DescribeParameters",
        ),
        (
            "/bench/disc/set_parameters",
            "rcl_interfaces/srv/SetParameters",
        ),
        (
            "/bench/disc/set_parameters_atomically",
            "rcl_interfaces/srv/SetParametersAtomically",
        ),
    ];
    let names: Vec<&str> = services.iter().map(|(s, _)| *s).collect();
    let out = rclpy_peer(
        &ns,
        &node,
        "names",
        "/bench/disc",
        json!({"joint_states": "/bench/joint_states", "node_name": "disc", "node_namespace": "/bench", "expect_services": names}),
    );
    assert!(
        out["nodes"]
            .as_array()
            .unwrap()
            .contains(&json!(["disc", "/bench"])),
        "{}",
        out["nodes"]
    );
    assert!(
        !out["nodes"]
            .as_array()
            .unwrap()
            .iter()
            .any(|n| n[0] == "annular_plate"),
        "{}",
        out["nodes"]
    );
    let got = graph(&out["services"]);
    for (s, ty) in services {
        assert_eq!(
            got.get(s),
            Some(&vec![ty.to_string()]),
            "`ros2 service list -t`: {s}"
        );
    }
    assert!(
        !got.keys().any(|s| s.starts_with("/annular_plate")),
        "nothing under the old name: {got:?}"
    );
    let publishes = graph(&out["node_topics"]);
    for (t, ty) in [
        ("/bench/joint_states", "sensor_msgs/msg/JointState"),
        (
            "/bench/disc/modal_amplitudes",
            "annular_plate/msg/ModalAmplitudes",
        ),
        ("/bench/disc/pad_states", "annular_plate/msg/PadStates"),
        (
            "/bench/disc/critical_speeds",
            "annular_plate/msg/CriticalSpeeds",
        ),
        ("/tf", "tf2_msgs/msg/TFMessage"),
        ("/tf_static", "tf2_msgs/msg/TFMessage"),
    ] {
        assert_eq!(
            publishes.get(t),
            Some(&vec![ty.to_string()]),
            "`ros2 node info /bench/disc`: {t}"
        );
    }
    let topics = graph(&out["topics"]);
    for t in [
        "/bench/disc/speed_command",
        "/bench/disc/pad_clamp_forces",
        "/bench/disc/ale_1/wrench",
    ] {
        assert!(topics.contains_key(t), "`ros2 topic list`: {t}");
    }
    assert!(
        !topics.keys().any(|t| t.starts_with("/annular_plate")),
        "nothing under the old name: {topics:?}"
    );
    assert_eq!(out["joint_name"], json!(["plate_joint"]));
    assert_eq!(
        out["state"], 1,
        "get_simulation_state under the new name: STATE_PLAYING"
    );
}
