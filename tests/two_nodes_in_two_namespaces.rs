//! Two nodes on one domain in two namespaces (`-r __ns:=/left` and
//! `/right`, both named `disc`, frame prefixes `left/` and `right/`), as two
//! brake discs on one ROS graph: each one's joint_states, its tf frames and
//! its commands stay its own, checked from the Cyclone DDS peer
//! (tests/peer/peer.py, `two_nodes`).

#![cfg(feature = "ros")]

#[path = "peer/harness.rs"]
mod harness;

use annular_plate::dynamics::{Command, Simulation, Wrench};
use annular_plate::ros::NodeSetup;
use harness::{floats, peer, scene, start_node_tagged, Netns};
use serde_json::json;

fn ros_args(side: &str) -> Vec<String> {
    [
        "-r",
        "__node:=disc",
        "-r",
        &format!("__ns:=/{side}"),
        "-p",
        &format!("ros.frame_prefix:={side}/"),
        "-p",
        "ros.start_paused:=true",
    ]
    .iter()
    .map(|s| s.to_string())
    .collect()
}

fn close(a: f64, b: f64, what: &str) {
    assert!(
        (a - b).abs() <= 1e-12 + 1e-9 * a.abs().max(b.abs()),
        "{what}: node {a} vs offline {b}"
    );
}

#[test]
fn two_namespaced_nodes_keep_their_joint_states_frames_and_commands_apart() {
    let ns = Netns::new();
    let (left, right) = (ros_args("left"), ros_args("right"));
    let l: Vec<&str> = left.iter().map(String::as_str).collect();
    let r: Vec<&str> = right.iter().map(String::as_str).collect();
    let _a = start_node_tagged(&ns, 63, "-left", &scene(), &[], &l);
    let node = start_node_tagged(&ns, 63, "-right", &scene(), &[], &r);
    let (speed, fz, steps) = (30.0, -500.0, 100);
    let out = peer(
        &ns,
        &node,
        "two_nodes",
        "/right/disc",
        json!({
            "nodes": [
                {"node": "/left/disc", "ns": "/left", "prefix": "left/"},
                {"node": "/right/disc", "ns": "/right", "prefix": "right/"}
            ],
            "speed": speed, "fz": fz, "steps": steps
        }),
    );

    // The offline predictions: the left disc got the speed and the wrench, the right one nothing.
    let offline = |commanded: bool| {
        let cli: Vec<String> = std::iter::once("--ros-args".to_string())
            .chain(ros_args("left"))
            .collect();
        let mut sim =
            Simulation::new(NodeSetup::load(Some(&scene()), &cli).unwrap().config).unwrap();
        if commanded {
            let checked = sim.check(Command::Speed(speed)).unwrap();
            sim.apply(checked);
            sim.set_ale_wrench(
                1,
                Wrench {
                    force: [0.0, 0.0, fz],
                    moment: [0.0; 3],
                },
            )
            .unwrap();
        }
        for _ in 0..steps {
            sim.step().unwrap();
        }
        sim
    };
    for (name, commanded) in [("/left/disc", true), ("/right/disc", false)] {
        let sim = offline(commanded);
        assert_eq!(
            out["step"][name]["step"], steps,
            "{name}: {}",
            out["step"][name]
        );
        let js = &out["joint_state"][name];
        close(
            floats(&js["velocity"])[0],
            sim.joint().velocity,
            &format!("{name} velocity"),
        );
        close(
            floats(&js["position"])[0],
            sim.joint().position,
            &format!("{name} position"),
        );
        let q = floats(&out["modal"][name]["q_ale"]);
        for (i, (a, b)) in q.iter().zip(sim.q_ale()).enumerate() {
            close(*a, *b, &format!("{name} q_ale[{i}]"));
        }
        assert_eq!(
            q.iter().any(|x| *x != 0.0),
            commanded,
            "{name}: only the commanded disc is bent: {q:?}"
        );
    }
    close(
        floats(&out["joint_state"]["/left/disc"]["velocity"])[0],
        speed,
        "the left disc reached its commanded speed",
    );

    // One /tf tree holding both discs' frames, each under its own prefix.
    let frames: Vec<(String, String)> = out["tf_frames"]
        .as_array()
        .unwrap()
        .iter()
        .map(|p| (p[0].as_str().unwrap().into(), p[1].as_str().unwrap().into()))
        .collect();
    for side in ["left", "right"] {
        assert!(
            frames.contains(&(format!("{side}/plate_base"), format!("{side}/plate_rotor"))),
            "{side}: {frames:?}"
        );
        assert!(
            frames.contains(&(format!("{side}/plate_base"), format!("{side}/plate_ale_1"))),
            "{side}: {frames:?}"
        );
    }
    for (parent, child) in &frames {
        let side = |f: &str| f.split('/').next().unwrap().to_string();
        assert_eq!(
            side(parent),
            side(child),
            "a transform between the two discs: {parent} -> {child}"
        );
        assert!(
            ["left", "right"].contains(&side(child).as_str()),
            "an unprefixed frame: {child}"
        );
    }
}
