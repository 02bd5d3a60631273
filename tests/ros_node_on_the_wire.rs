//! The real node binary (`annular_plate run FILE --ros-args ...`) against an
//! independent DDS implementation: Eclipse Cyclone DDS through its Python
//! binding (`tests/peer/peer.py`, ROS 2 wire names and rclpy-style QoS).
//!
//! Each test has its own network namespace (loopback only) and its own
//! ROS_DOMAIN_ID; timing-sensitive checks pause the node and step it, or use
//! simulated time. The offline prediction is the same `Simulation`, run
//! in-process on the configuration the node itself reads
//! (`annular_plate::ros::NodeSetup::load` with the same arguments).

#![cfg(feature = "ros")]

#[path = "peer/harness.rs"]
mod harness;

use annular_plate::dynamics::load_models::pad_outputs::PadOutputs;
use annular_plate::dynamics::load_models::tool::ToolOutputs;
use annular_plate::dynamics::{Simulation, Wrench};
use annular_plate::ros::NodeSetup;
use harness::{f, floats, peer, repo, scene, start_node, start_node_on, Netns};
use serde_json::{json, Value};
use std::time::{Duration, Instant};

const DT: f64 = 1e-3;

/// The configuration the node reads with these ROS arguments.
fn offline(ros_args: &[&str]) -> Simulation {
    offline_on(&scene(), ros_args)
}

/// The same for another scene file.
fn offline_on(scene_file: &std::path::Path, ros_args: &[&str]) -> Simulation {
    let args: Vec<String> = std::iter::once("--ros-args")
        .chain(ros_args.iter().copied())
        .map(String::from)
        .collect();
    let setup = NodeSetup::load(Some(scene_file), &args).expect("the scene loads in-process");
    Simulation::new(setup.config).expect("the model builds")
}

/// The pad states message (JSON) against the in-process simulation's pads.
fn pad_states_match(ps: &Value, sim: &Simulation, what: &str) {
    let n = sim.pad_count();
    assert_eq!(f(ps, "step") as u64, sim.step_count(), "{what}: step");
    let per_pad = |key: &str, get: &dyn Fn(usize) -> f64| {
        let got = floats(&ps[key]);
        let want: Vec<f64> = (0..n).map(get).collect();
        close_all(&got, &want, &format!("{what}: {key}"));
    };
    per_pad("clamp_force", &|p| sim.pad_output(p).clamp_force);
    per_pad("normal_force", &|p| sim.pad_output(p).normal_force);
    per_pad("friction_force", &|p| sim.pad_output(p).friction_force);
    per_pad("friction_torque", &|p| sim.pad_output(p).friction_torque);
    let contacts = sim.pad_contact_forces();
    let pads = sim
        .scene()
        .load_models
        .find::<annular_plate::dynamics::load_models::pad::Pads>()
        .map(|(_, p)| p)
        .expect("the scene has pads");
    let ints = |key: &str| -> Vec<u64> {
        ps[key]
            .as_array()
            .unwrap()
            .iter()
            .map(|x| x.as_u64().unwrap())
            .collect()
    };
    assert_eq!(
        ints("contact_pad"),
        pads.contacts
            .iter()
            .map(|c| c.pad as u64 + 1)
            .collect::<Vec<_>>(),
        "{what}: contact_pad"
    );
    assert_eq!(
        ints("contact_ale_node"),
        pads.contacts
            .iter()
            .map(|c| c.node as u64 + 1)
            .collect::<Vec<_>>(),
        "{what}: contact_ale_node"
    );
    close_all(
        &floats(&ps["contact_normal_top"]),
        &contacts.iter().map(|c| c.top).collect::<Vec<_>>(),
        &format!("{what}: top"),
    );
    close_all(
        &floats(&ps["contact_normal_bottom"]),
        &contacts.iter().map(|c| c.bottom).collect::<Vec<_>>(),
        &format!("{what}: bottom"),
    );
    close_all(
        &floats(&ps["contact_friction"]),
        &contacts.iter().map(|c| c.tangential).collect::<Vec<_>>(),
        &format!("{what}: friction"),
    );
}

/// μ, the friction radius and the drive's torque limit of the brake bench.
fn brake_bench_data(sim: &Simulation) -> (f64, f64, f64) {
    let pads = sim
        .scene()
        .load_models
        .find::<annular_plate::dynamics::load_models::pad::Pads>()
        .map(|(_, p)| p)
        .expect("the brake bench has pads");
    let r = pads.contacts[0].radius;
    assert!(
        pads.contacts.iter().all(|c| (c.radius - r).abs() < 1e-12),
        "one friction radius"
    );
    (
        pads.friction_coefficient,
        r,
        sim.config()
            .joint
            .max_torque
            .expect("the bench's drive is torque limited"),
    )
}

fn close(a: f64, b: f64, what: &str) {
    let tol = 1e-12 + 1e-9 * a.abs().max(b.abs());
    assert!((a - b).abs() <= tol, "{what}: node {a} vs offline {b}");
}

fn close_all(a: &[f64], b: &[f64], what: &str) {
    assert_eq!(a.len(), b.len(), "{what}: lengths differ");
    for (i, (x, y)) in a.iter().zip(b).enumerate() {
        close(*x, *y, &format!("{what}[{i}]"));
    }
}

/// The transform of `child` in a /tf message (JSON).
fn transform<'a>(tf: &'a Value, child: &str) -> &'a Value {
    tf["transforms"]
        .as_array()
        .expect("transforms")
        .iter()
        .find(|t| t["child_frame_id"] == child)
        .unwrap_or_else(|| panic!("no transform to {child} in {tf}"))
}

fn translation(t: &Value) -> [f64; 3] {
    [
        f(t, "transform.translation.x"),
        f(t, "transform.translation.y"),
        f(t, "transform.translation.z"),
    ]
}

fn rotation(t: &Value) -> [f64; 4] {
    [
        f(t, "transform.rotation.x"),
        f(t, "transform.rotation.y"),
        f(t, "transform.rotation.z"),
        f(t, "transform.rotation.w"),
    ]
}

#[test]
fn joint_states_reach_the_peer_and_a_speed_command_shows_in_them() {
    let ns = Netns::new();
    let args = ["-p", "ros.diagnostics_period:=0.05"];
    let node = start_node(&ns, 11, &args);
    let out = peer(
        &ns,
        &node,
        "joint_states",
        "/annular_plate",
        json!({"speed": 30.0, "steps": 100}),
    );

    let first = &out["first"];
    assert_eq!(first["name"], json!(["plate_joint"]));
    assert_eq!(
        floats(&first["velocity"]),
        vec![25.0],
        "the scene's joint.speed"
    );
    assert_eq!(floats(&first["effort"]).len(), 1);

    // Paused after k steps at 25 rad/s; then 30 rad/s commanded and 100 steps:
    // at 50 rad/s^2 the drive needs exactly 100 steps of 1 ms for +5 rad/s.
    let k = f(&out, "before.step") as u64;
    assert_eq!(f(&out, "step.step") as u64, k + 100);
    assert!(out["step"]["success"].as_bool().unwrap());
    let last = &out["last"];
    close(
        floats(&last["velocity"])[0],
        30.0,
        "velocity after the speed command",
    );

    let mut sim = offline(&args);
    for _ in 0..k {
        sim.step().unwrap();
    }
    sim.set_speed_command(30.0).unwrap();
    for _ in 0..100 {
        sim.step().unwrap();
    }
    close(
        floats(&last["position"])[0],
        sim.joint().position,
        "joint position",
    );
    close(
        floats(&last["velocity"])[0],
        sim.joint().velocity,
        "joint velocity",
    );
    assert!(
        out["received_after_step"].as_u64().unwrap() >= 100,
        "every stepped state was published"
    );
}

#[test]
fn an_ale_wrench_moves_that_nodes_tf_and_the_modes_as_the_offline_simulation_predicts() {
    let ns = Netns::new();
    let args = [
        "-p",
        "ros.start_paused:=true",
        "-p",
        "ros.publish_clock:=true",
        "-p",
        "ros.diagnostics_period:=0.05",
    ];
    let node = start_node(&ns, 12, &args);
    let w = [30.0, 0.0, -500.0, 0.0, 0.0, 0.0];
    let steps = 200;
    let out = peer(
        &ns,
        &node,
        "ale_wrench",
        "/annular_plate",
        json!({"node": 2, "wrench": w, "steps": steps, "dt": DT, "frame_id": "plate_ale_2"}),
    );
    assert_eq!(f(&out, "step.step") as u64, steps);

    let mut sim = offline(&args);
    let before = sim.ale_node_pose(1);
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

    let modal = &out["modal"];
    assert_eq!(f(modal, "step") as u64, steps);
    close(f(modal, "sim_time"), sim.time(), "sim_time");
    close_all(
        &floats(&modal["q_lagrange"]),
        sim.q_lagrange(),
        "q_lagrange",
    );
    close_all(
        &floats(&modal["q_dot_lagrange"]),
        sim.q_dot_lagrange(),
        "q_dot_lagrange",
    );
    close_all(&floats(&modal["q_ale"]), sim.q_ale(), "q_ale");
    close_all(&floats(&modal["q_dot_ale"]), sim.q_dot_ale(), "q_dot_ale");
    let freqs: Vec<f64> = sim.model().modes().iter().map(|m| m.frequency_hz).collect();
    close_all(&floats(&modal["frequency_hz"]), &freqs, "frequency_hz");
    assert_eq!(
        f(modal, "input_stamp.sec"),
        7.0,
        "input_stamp echoes the wrench's header stamp"
    );
    assert_eq!(f(modal, "input_stamp.nanosec"), 123.0);

    let tf = &out["tf"];
    for j in 0..sim.n_ale_nodes() {
        let t = transform(tf, &format!("plate_ale_{}", j + 1));
        assert_eq!(t["header"]["frame_id"], "plate_base");
        let p = sim.ale_node_pose(j);
        close_all(
            &translation(t),
            &p.translation,
            &format!("ale_{} translation", j + 1),
        );
        close_all(
            &rotation(t),
            &p.rotation,
            &format!("ale_{} rotation", j + 1),
        );
    }
    let after = sim.ale_node_pose(1);
    let moved = (after.translation[2] - before.translation[2]).abs();
    assert!(
        moved > 1e-9,
        "a 500 N normal force must deflect the plate at ale_2 (moved {moved:e} m)"
    );
    assert!(
        sim.q_ale().iter().any(|q| q.abs() > 1e-12),
        "the modal amplitudes respond to the wrench"
    );
}

#[test]
fn tf_frames_carry_the_prefix_and_the_scene_geometry() {
    let ns = Netns::new();
    let args = [
        "-p",
        "ros.start_paused:=true",
        "-p",
        "ros.publish_clock:=true",
        "-p",
        "ros.frame_prefix:=bench/",
        "-p",
        "ros.diagnostics_period:=0.05",
    ];
    let node = start_node(&ns, 13, &args);
    let out = peer(
        &ns,
        &node,
        "tf",
        "/annular_plate",
        json!({"steps": 37, "dt": DT}),
    );
    let mut sim = offline(&args);
    for _ in 0..37 {
        sim.step().unwrap();
    }
    let cfg = sim.config().clone();
    let tf = &out["tf"];
    let transforms = tf["transforms"].as_array().unwrap();
    assert_eq!(
        transforms.len(),
        1 + cfg.nodes.ale.len() + cfg.nodes.lagrange.len()
    );
    for t in transforms {
        assert_eq!(
            f(t, "header.stamp.nanosec"),
            37e6,
            "sim-time stamp of step 37"
        );
    }
    let rotor = transform(tf, "bench/plate_rotor");
    assert_eq!(rotor["header"]["frame_id"], "bench/plate_base");
    assert_eq!(translation(rotor), [0.0; 3]);
    let q = rotation(rotor);
    let angle = 2.0 * q[2].atan2(q[3]);
    let js = &out["joint_state"];
    assert_eq!(js["name"], json!(["bench/plate_joint"]));
    let position = floats(&js["position"])[0];
    close(position, sim.joint().position, "joint position");
    let wrapped = |a: f64| a.rem_euclid(std::f64::consts::TAU);
    assert!(
        (wrapped(angle) - wrapped(position)).abs() < 1e-9,
        "rotor angle {angle} vs joint {position}"
    );

    let (ri, ra) = (cfg.plate.inner_radius, cfg.plate.outer_radius);
    for (j, n) in cfg.nodes.ale.iter().enumerate() {
        let t = transform(tf, &format!("bench/plate_ale_{}", j + 1));
        assert_eq!(t["header"]["frame_id"], "bench/plate_base");
        let p = translation(t);
        close(
            (p[0] * p[0] + p[1] * p[1]).sqrt(),
            ri + n.radial * (ra - ri),
            "ALE node radius",
        );
        let phi = p[1].atan2(p[0]).rem_euclid(std::f64::consts::TAU);
        assert!(
            (phi - (n.angular * std::f64::consts::TAU)).abs() < 1e-9,
            "ALE node angle"
        );
        close_all(&p, &sim.ale_node_pose(j).translation, "ALE pose");
    }
    for (j, _) in cfg.nodes.lagrange.iter().enumerate() {
        let t = transform(tf, &format!("bench/plate_lagrange_{}", j + 1));
        assert_eq!(
            t["header"]["frame_id"], "bench/plate_rotor",
            "Lagrangian nodes turn with the rotor"
        );
        close_all(
            &translation(t),
            &sim.lagrange_node_pose(j).translation,
            "Lagrange pose",
        );
        close_all(
            &rotation(t),
            &sim.lagrange_node_pose(j).rotation,
            "Lagrange rotation",
        );
    }
}

#[test]
fn tf_static_reaches_a_late_joiner() {
    let ns = Netns::new();
    let node = start_node(&ns, 14, &["-p", "reference.tilt:=0.1"]);
    std::thread::sleep(Duration::from_millis(1500));
    let out = peer(&ns, &node, "tf_static", "/annular_plate", json!({}));
    let ts = out["tf_static"]["transforms"].as_array().unwrap();
    assert_eq!(ts.len(), 1, "all static transforms in one message");
    assert_eq!(ts[0]["header"]["frame_id"], "world");
    assert_eq!(ts[0]["child_frame_id"], "plate_base");
    let r = rotation(&ts[0]);
    close(r[0], (0.05f64).sin(), "tilt quaternion x");
    close(r[3], (0.05f64).cos(), "tilt quaternion w");
    assert_eq!(out["more"], 0, "one message only");
}

#[test]
fn clock_has_one_type_and_monotonic_stamps() {
    let ns = Netns::new();
    let node = start_node(
        &ns,
        15,
        &[
            "-p",
            "ros.publish_clock:=true",
            "-p",
            "simulation.realtime_factor:=2.0",
        ],
    );
    let out = peer(
        &ns,
        &node,
        "clock",
        "/annular_plate",
        json!({"seconds": 2.0}),
    );
    let stamps: Vec<i64> = out["stamps"]
        .as_array()
        .unwrap()
        .iter()
        .map(|s| s.as_i64().unwrap())
        .collect();
    assert!(stamps.len() > 500, "only {} /clock samples", stamps.len());
    let mut exact = 0;
    for w in stamps.windows(2) {
        let d = w[1] - w[0];
        assert!(
            d > 0,
            "/clock went backwards or repeated: {} -> {}",
            w[0],
            w[1]
        );
        assert_eq!(d % 1_000_000, 0, "/clock advances by whole steps of 1 ms");
        exact += (d == 1_000_000) as usize;
    }
    assert!(
        exact * 2 >= stamps.len(),
        "most /clock samples are consecutive steps ({exact} of {})",
        stamps.len()
    );
    assert_eq!(
        out["reset"]["success"], true,
        "a reset in the middle (the clock keeps counting)"
    );
    let endpoints = out["endpoints"].as_array().unwrap();
    assert!(
        endpoints.iter().any(|e| e[0] == "pub"),
        "the node's /clock writer is discovered: {endpoints:?}"
    );
    for e in endpoints {
        assert_eq!(
            e[2], "rosgraph_msgs::msg::dds_::Clock_",
            "one type on /clock: {endpoints:?}"
        );
    }
}

#[test]
fn reset_pause_and_step_services_work() {
    let ns = Netns::new();
    let node = start_node(
        &ns,
        16,
        &[
            "-p",
            "ros.start_paused:=true",
            "-p",
            "ros.diagnostics_period:=0.05",
        ],
    );
    let out = peer(&ns, &node, "services", "/annular_plate", json!({}));
    assert_eq!(f(&out, "initial.step"), 0.0, "started paused");
    assert_eq!(out["step5"]["success"], true);
    assert_eq!(f(&out, "step5.step"), 5.0);
    close(f(&out, "step5.sim_time"), 0.005, "sim_time after 5 steps");
    assert_eq!(f(&out, "step0.step"), 5.0, "step 0 only reports");
    let published: Vec<u64> = out["published_steps"]
        .as_array()
        .unwrap()
        .iter()
        .map(|s| s.as_u64().unwrap())
        .collect();
    assert_eq!(
        published[published.len() - 5..],
        [1, 2, 3, 4, 5],
        "each requested step is published"
    );
    assert_eq!(out["resume"]["success"], true);
    assert_eq!(out["step_while_running"]["success"], false);
    assert!(out["step_while_running"]["message"]
        .as_str()
        .unwrap()
        .contains("pause it first"));
    assert_eq!(out["pause"]["success"], true);
    let paused_at = f(&out, "paused_at");
    assert!(
        paused_at > 5.0 + 100.0,
        "it ran while resumed (step {paused_at})"
    );
    assert_eq!(
        f(&out, "still_paused_at"),
        paused_at,
        "no steps while paused"
    );
    assert_eq!(out["reset"]["success"], true);
    assert_eq!(f(&out, "after_reset.step"), 0.0);
    assert_eq!(f(&out, "after_reset_step3.step"), 3.0);
    close(
        f(&out, "after_reset_step3.sim_time"),
        0.003,
        "sim_time after reset + 3 steps",
    );
}

#[test]
fn bad_inputs_are_rejected_counted_and_the_node_keeps_publishing() {
    let ns = Netns::new();
    let args = [
        "-p",
        "ros.diagnostics_period:=0.05",
        "-p",
        "ros.reject_log_period:=0.0",
    ];
    let mut node = start_node(&ns, 17, &args);
    let out = peer(&ns, &node, "bad_inputs", "/annular_plate", json!({}));
    let sent = out["sent"].as_object().unwrap();
    let diag = &out["diag"];
    let count = |k: &str| {
        diag[k]
            .as_str()
            .unwrap_or_else(|| panic!("{k} missing in {diag}"))
            .parse::<u64>()
            .unwrap()
    };
    let mut total = 0;
    for (reason, n) in sent {
        assert_eq!(
            count(&format!("rejected_{reason}")),
            n.as_u64().unwrap(),
            "rejected_{reason}"
        );
        total += n.as_u64().unwrap();
    }
    assert_eq!(count("rejected_total"), total);
    assert_eq!(count("accepted_total"), 0, "nothing bad was applied");
    assert_eq!(out["inputs_level"], 1, "the inputs status warns");
    assert!(
        out["joint_states_after"].as_u64().unwrap() >= 10,
        "still publishing"
    );
    assert!(
        !out["rosout_rejections"].as_array().unwrap().is_empty(),
        "rejections are logged on /rosout"
    );

    // The state is what it would be without any of those inputs.
    let mut sim = offline(&args);
    let steps = f(&out, "modal.step") as u64;
    for _ in 0..steps {
        sim.step().unwrap();
    }
    close_all(
        &floats(&out["modal"]["q_ale"]),
        sim.q_ale(),
        "q_ale untouched by bad input",
    );
    close(
        floats(&out["last_joint_state"]["velocity"])[0],
        25.0,
        "speed untouched by bad input",
    );
    assert_eq!(
        floats(&out["pad_states"]["clamp_force"]),
        vec![0.0],
        "the pad's clamp force untouched by bad input"
    );
    assert_eq!(
        count("accepted_pad_clamp_force") + count("accepted_pad_clamp_forces"),
        0
    );
    assert!(node.is_running(), "the node survives bad input");
}

#[test]
fn a_stale_wrench_drops_to_zero_after_the_wrench_timeout() {
    let ns = Netns::new();
    let args = [
        "-p",
        "ros.start_paused:=true",
        "-p",
        "ros.wrench_timeout:=0.01",
        "-p",
        "ros.diagnostics_period:=0.05",
    ];
    let node = start_node(&ns, 23, &args);
    let out = peer(
        &ns,
        &node,
        "wrench_timeout",
        "/annular_plate",
        json!({"fz": -800.0, "steps": 40}),
    );
    assert_eq!(out["diag"]["expired_wrenches"], "1");
    // Offline: the wrench acts for 10 steps (0.01 s), then zero.
    let mut sim = offline(&args);
    sim.set_ale_wrench(
        0,
        Wrench {
            force: [0.0, 0.0, -800.0],
            moment: [0.0; 3],
        },
    )
    .unwrap();
    for _ in 0..10 {
        sim.step().unwrap();
    }
    sim.set_ale_wrench(0, Wrench::default()).unwrap();
    for _ in 10..40 {
        sim.step().unwrap();
    }
    close_all(
        &floats(&out["modal"]["q_ale"]),
        sim.q_ale(),
        "q_ale with the wrench expired after 10 steps",
    );
    close_all(
        &floats(&out["modal"]["q_dot_ale"]),
        sim.q_dot_ale(),
        "q_dot_ale",
    );
}

#[test]
fn services_also_speak_the_rmw_cyclonedds_framing() {
    let ns = Netns::new();
    let node = start_node(
        &ns,
        24,
        &[
            "-p",
            "ros.start_paused:=true",
            "-p",
            "ros.service_mapping:=cyclone",
        ],
    );
    let out = peer(&ns, &node, "cyclone_services", "/annular_plate", json!({}));
    let replies = out["replies"].as_array().unwrap();
    for (r, (seq, step)) in replies.iter().zip([(11, 4), (12, 4), (13, 6)]) {
        assert_eq!(
            r["client"], 0x1122334455667788u64,
            "the request id is echoed: {r}"
        );
        assert_eq!(r["seq"], seq);
        assert_eq!(r["success"], true);
        assert_eq!(r["step"], step);
    }
}

#[test]
fn sigint_and_sigterm_exit_cleanly_within_a_second() {
    for (domain, sig) in [(18, "INT"), (19, "TERM")] {
        let ns = Netns::new();
        let mut node = start_node(&ns, domain, &[]);
        let _ = peer(&ns, &node, "first_message", "/annular_plate", json!({}));
        let t0 = Instant::now();
        node.signal(sig);
        let status = node.wait_exit(Duration::from_secs(3));
        let took = t0.elapsed();
        let stderr = node.stderr();
        let status =
            status.unwrap_or_else(|| panic!("SIG{sig}: still running after 3 s\n{stderr}"));
        assert!(status.success(), "SIG{sig}: exit status {status}\n{stderr}");
        assert!(took < Duration::from_secs(1), "SIG{sig}: took {took:?}");
        assert!(stderr.contains("shutting down"), "{stderr}");
        assert!(!stderr.contains("panicked"), "{stderr}");
    }
}

#[test]
fn parameter_services_list_get_describe_and_refuse_to_set_with_a_reason() {
    let ns = Netns::new();
    let node = start_node(
        &ns,
        20,
        &[
            "-p",
            "ros.diagnostics_period:=0.05",
            "-p",
            "joint.speed:=20.0",
        ],
    );
    let names = [
        "plate.thickness",
        "joint.speed",
        "simulation.rate_hz",
        "ros.frame_prefix",
        "use_sim_time",
        "no.such",
    ];
    let out = peer(
        &ns,
        &node,
        "params",
        "/annular_plate",
        json!({"names": names}),
    );
    let list: Vec<&str> = out["list"]
        .as_array()
        .unwrap()
        .iter()
        .map(|v| v.as_str().unwrap())
        .collect();
    for n in [
        "plate.inner_radius",
        "nodes.ale_radial",
        "joint.speed",
        "ros.wrench_timeout",
        "use_sim_time",
    ] {
        assert!(list.contains(&n), "{n} not listed: {list:?}");
    }
    let get = &out["get"];
    assert_eq!(get["plate.thickness"]["double"], 0.0181);
    assert_eq!(get["joint.speed"]["double"], 20.0, "the -p override");
    assert_eq!(get["simulation.rate_hz"]["double"], 1000.0);
    assert_eq!(get["ros.frame_prefix"]["type"], 4);
    assert_eq!(get["use_sim_time"]["type"], 1);
    assert_eq!(get["no.such"]["type"], 0);
    assert_eq!(
        out["types"],
        json!({"plate.thickness": 3, "joint.speed": 3, "simulation.rate_hz": 3, "ros.frame_prefix": 4, "use_sim_time": 1, "no.such": 0})
    );
    assert_eq!(out["describe"]["plate.thickness"]["read_only"], true);
    let set = out["set"].as_array().unwrap();
    assert_eq!(set[0]["ok"], false);
    assert!(
        set[0]["reason"].as_str().unwrap().contains("read only"),
        "{}",
        set[0]
    );
    assert_eq!(
        set[1]["ok"], true,
        "simulation.realtime_factor may change at run time"
    );
    assert_eq!(out["after"][0]["double"], 0.0181);
    assert_eq!(out["after"][1]["double"], 2.0);
    assert_eq!(
        out["diag_realtime_factor"], "2",
        "the loop took the new factor"
    );
}

#[test]
fn the_brake_load_example_works_on_the_wire() {
    let ns = Netns::new();
    let args = [
        "-p",
        "ros.start_paused:=true",
        "-p",
        "ros.publish_clock:=true",
        "-p",
        "ros.diagnostics_period:=0.01",
    ];
    let node = start_node(&ns, 21, &args);
    // The script's profile, shortened: above ~15.65 kN the brake torque 2 mu N r
    // exceeds the drive's 1500 N m; 40 ms at 16 kN take ~11 rad/s off the bare disc.
    let (peak, ramp, hold, release, after, rate) = (16000.0, 0.2, 0.04, 0.2, 0.1, 100.0);
    let out = peer(
        &ns,
        &node,
        "brake_example",
        "/annular_plate",
        json!({"pads": [1], "peak_force": peak, "ramp_s": ramp, "hold_s": hold, "release_s": release, "after_s": after,
               "rate_hz": rate, "dt": DT}),
    );
    let log = out["log"].as_array().unwrap();
    let per_tick = out["steps_per_tick"].as_u64().unwrap();
    assert_eq!(per_tick, 10, "a 100 Hz script tick is 10 steps of 1 ms");
    assert_eq!(log.len() as u64, out["sent"].as_u64().unwrap());
    assert!(log.len() >= 50, "{} ticks", log.len());
    assert_eq!(out["diag"]["rejected_total"], "0");
    assert_eq!(
        out["diag"]["accepted_pad_clamp_forces"],
        out["sent"].to_string()
    );

    // The in-process simulation fed the same commands before the same steps.
    let mut sim = offline(&args);
    let (mu, r, max_torque) = brake_bench_data(&sim);
    let threshold = max_torque / (2.0 * mu * r);
    assert!(
        peak > threshold && threshold > 15_000.0,
        "threshold {threshold} N"
    );
    let (mut speeds, mut forces, mut efforts) = (vec![], vec![], vec![]);
    for (i, e) in log.iter().enumerate() {
        let force = f(e, "force");
        sim.set_pad_clamp_force(0, force).unwrap();
        for _ in 0..per_tick {
            sim.step().unwrap();
        }
        let what = format!("tick {i} (N = {force} N)");
        assert_eq!(f(e, "step") as u64, sim.step_count(), "{what}: step");
        close(
            f(e, "speed"),
            sim.joint().velocity,
            &format!("{what}: speed"),
        );
        close(
            f(e, "effort"),
            sim.joint().effort,
            &format!("{what}: effort"),
        );
        close(
            f(e, "position"),
            sim.joint().position,
            &format!("{what}: position"),
        );
        close_all(&floats(&e["q_ale"]), sim.q_ale(), &format!("{what}: q_ale"));
        close_all(
            &floats(&e["q_dot_ale"]),
            sim.q_dot_ale(),
            &format!("{what}: q_dot_ale"),
        );
        pad_states_match(&e["pad_states"], &sim, &what);
        assert_eq!(
            e["input_stamp"], e["sent_stamp"],
            "{what}: input_stamp echoes the command's header stamp"
        );
        // Floating caliper: each face carries exactly the clamp force.
        let ps = &e["pad_states"];
        close(
            floats(&ps["normal_force"])[0],
            force,
            &format!("{what}: normal force = clamp force"),
        );
        // Friction 2 mu N against the rotation, at the friction radius.
        let torque = floats(&ps["friction_torque"])[0];
        assert!(
            (torque + 2.0 * mu * force * r).abs() <= 1e-6 * (2.0 * mu * force * r) + 1e-9,
            "{what}: friction torque {torque}"
        );
        speeds.push(f(e, "speed"));
        forces.push(force);
        efforts.push(f(e, "effort"));
    }

    // The physics: below the threshold the drive holds 25 rad/s against the
    // brake torque; above it the effort saturates and the disc slows down;
    // released, the drive brings it back at its acceleration limit.
    let first_above = forces
        .iter()
        .position(|&n| n > threshold)
        .expect("the profile exceeds the threshold");
    for i in 0..first_above {
        close(
            speeds[i],
            25.0,
            &format!("tick {i}: the drive holds the speed below the threshold"),
        );
        let brake = 2.0 * mu * forces[i] * r;
        assert!(
            (efforts[i] - brake).abs() <= 1e-6 * brake + 1e-9,
            "tick {i}: effort {} = brake torque {brake}",
            efforts[i]
        );
    }
    let (i_min, v_min) = speeds
        .iter()
        .copied()
        .enumerate()
        .fold((0, f64::MAX), |a, (i, v)| if v < a.1 { (i, v) } else { a });
    assert!(
        v_min < 20.0 && v_min > 1.0,
        "the brake slows the disc (minimum {v_min} rad/s) without stopping it"
    );
    assert!(
        i_min >= first_above,
        "the speed drops only once the brake torque exceeds the drive's"
    );
    for i in first_above..log.len() {
        if forces[i] > threshold * 1.001 {
            close(
                efforts[i],
                max_torque,
                &format!("tick {i}: the drive is at its torque limit"),
            );
            assert!(
                speeds[i] < speeds[i - 1],
                "tick {i}: the speed drops while N > threshold"
            );
        }
    }
    let last = *speeds.last().unwrap();
    assert!(
        last > v_min + 5.0,
        "released, the drive speeds the disc up again ({v_min} -> {last} rad/s)"
    );
    for w in speeds[i_min..].windows(2) {
        assert!(
            w[1] - w[0] <= 50.0 * 0.01 + 1e-9,
            "at most joint.max_acceleration = 50 rad/s^2"
        );
    }
    eprintln!(
        "brake example: threshold {threshold:.0} N; speed 25 -> {v_min:.3} rad/s (tick {i_min}) -> {last:.3} rad/s; {} ticks",
        log.len()
    );
}

#[test]
fn a_clamp_force_on_the_pad_topic_brakes_the_disc_as_the_offline_simulation_predicts() {
    let ns = Netns::new();
    let args = [
        "-p",
        "ros.start_paused:=true",
        "-p",
        "ros.publish_clock:=true",
        "-p",
        "ros.diagnostics_period:=0.02",
    ];
    let node = start_node(&ns, 25, &args);
    let (force, steps) = (16000.0, 30);
    let out = peer(
        &ns,
        &node,
        "pad_clamp_force",
        "/annular_plate",
        json!({"pad": 1, "force": force, "steps": steps, "dt": DT}),
    );
    assert_eq!(f(&out, "step.step") as u64, steps);
    assert_eq!(out["diag"]["accepted_pad_clamp_force"], "1");
    let mut sim = offline(&args);
    sim.set_pad_clamp_force(0, force).unwrap();
    for _ in 0..steps {
        sim.step().unwrap();
    }
    pad_states_match(&out["pad_states"], &sim, "after the steps");
    close(
        floats(&out["joint_state"]["velocity"])[0],
        sim.joint().velocity,
        "speed",
    );
    close(
        floats(&out["joint_state"]["effort"])[0],
        sim.joint().effort,
        "effort",
    );
    close_all(&floats(&out["modal"]["q_ale"]), sim.q_ale(), "q_ale");
    // 16 kN: 2 mu N r = 1533 N m against the drive's 1500 N m, on the disc's polar inertia.
    let (mu, r, max_torque) = brake_bench_data(&sim);
    let decel = (2.0 * mu * force * r - max_torque) / sim.model().body().inertia[2][2];
    let v = sim.joint().velocity;
    let expected = 25.0 - decel * steps as f64 * DT;
    assert!(
        (v - expected).abs() < 0.02 * (25.0 - expected),
        "speed {v} vs {expected}: decelerated at {decel} rad/s^2"
    );
}

#[test]
fn the_tool_feed_topic_drives_the_lathe_tool_as_the_offline_simulation_predicts() {
    let ns = Netns::new();
    let lathe = repo().join("config/lathe.yaml");
    let args = [
        "-p",
        "ros.start_paused:=true",
        "-p",
        "ros.publish_clock:=true",
        "-p",
        "ros.diagnostics_period:=0.02",
    ];
    let node = start_node_on(&ns, 26, &lathe, &[], &args);
    // Ten times the file's feed: the tool reaches the disc after 25 ms and cuts.
    let (feed, steps) = (0.02, 120);
    let out = peer(
        &ns,
        &node,
        "tool_feed",
        "/annular_plate",
        json!({"feed": feed, "steps": steps, "bad": ["nan", "inf", 2.0, -1.5]}),
    );
    let diag = &out["diag"];
    assert_eq!(diag["rejected_non_finite"], "2");
    assert_eq!(diag["rejected_absurd"], "2");
    assert_eq!(diag["accepted_tool_feed"], "1");
    let mut sim = offline_on(&lathe, &args);
    sim.set_tool_feed(feed).unwrap();
    for _ in 0..steps {
        sim.step().unwrap();
    }
    let t = &out["tool_state"];
    let o = sim.tool_output().unwrap();
    assert_eq!(f(t, "step") as u64, steps);
    close(f(t, "feed_rate"), o.feed_rate, "feed_rate");
    close(f(t, "tip_z"), o.tip, "tip_z");
    close(f(t, "chip_thickness"), o.chip, "chip_thickness");
    close(f(t, "feed_force"), o.feed_force, "feed_force");
    assert!(
        o.feed_force > 10.0,
        "the tool cuts (feed force {} N)",
        o.feed_force
    );
    close_all(&floats(&out["modal"]["q_ale"]), sim.q_ale(), "q_ale");
    // A scene with a tool and no pads: tool topics, no pad topics.
    let eps: Vec<(String, String)> = out["endpoints"]
        .as_array()
        .unwrap()
        .iter()
        .map(|e| (e[0].as_str().unwrap().into(), e[1].as_str().unwrap().into()))
        .collect();
    assert!(
        eps.contains(&("sub".into(), "rt/annular_plate/tool_feed".into())),
        "{eps:?}"
    );
    assert!(
        eps.contains(&("pub".into(), "rt/annular_plate/tool_state".into())),
        "{eps:?}"
    );
    assert!(
        !eps.iter().any(|(_, t)| t.contains("pad")),
        "no pad topics without pads: {eps:?}"
    );
}

#[test]
fn names_are_remapped_and_namespaced_as_ros_args_say() {
    let ns = Netns::new();
    let node = start_node(
        &ns,
        22,
        &[
            "-r",
            "__node:=disc",
            "-r",
            "__ns:=/bench",
            "-r",
            "/joint_states:=/bench/joint_states",
            "-p",
            "ros.frame_prefix:=bench/",
        ],
    );
    let out = peer(
        &ns,
        &node,
        "names",
        "/bench/disc",
        json!({"joint_states": "/bench/joint_states"}),
    );
    assert_eq!(out["joint_state"]["name"], json!(["bench/plate_joint"]));
    let eps: Vec<(String, String, String)> = out["endpoints"]
        .as_array()
        .unwrap()
        .iter()
        .map(|e| {
            (
                e[0].as_str().unwrap().into(),
                e[1].as_str().unwrap().into(),
                e[2].as_str().unwrap().into(),
            )
        })
        .collect();
    let has = |kind: &str, topic: &str, ty: &str| {
        assert!(
            eps.iter()
                .any(|(k, t, y)| k == kind && t == topic && y == ty),
            "missing {kind} {topic} [{ty}] in {eps:#?}"
        )
    };
    has(
        "pub",
        "rt/bench/joint_states",
        "sensor_msgs::msg::dds_::JointState_",
    );
    has("pub", "rt/tf", "tf2_msgs::msg::dds_::TFMessage_");
    has("pub", "rt/tf_static", "tf2_msgs::msg::dds_::TFMessage_");
    has(
        "pub",
        "rt/bench/disc/modal_amplitudes",
        "annular_plate::msg::dds_::ModalAmplitudes_",
    );
    has(
        "pub",
        "rt/diagnostics",
        "diagnostic_msgs::msg::dds_::DiagnosticArray_",
    );
    has("pub", "rt/rosout", "rcl_interfaces::msg::dds_::Log_");
    has(
        "sub",
        "rt/bench/disc/speed_command",
        "std_msgs::msg::dds_::Float64_",
    );
    has(
        "sub",
        "rt/bench/disc/ale_1/wrench",
        "geometry_msgs::msg::dds_::WrenchStamped_",
    );
    has(
        "sub",
        "rt/bench/disc/ale_3/wrench",
        "geometry_msgs::msg::dds_::WrenchStamped_",
    );
    has(
        "sub",
        "rt/bench/disc/pad_1/clamp_force",
        "std_msgs::msg::dds_::Float64_",
    );
    has(
        "sub",
        "rt/bench/disc/pad_clamp_forces",
        "annular_plate::msg::dds_::PadClampForces_",
    );
    has(
        "pub",
        "rt/bench/disc/pad_states",
        "annular_plate::msg::dds_::PadStates_",
    );
    has(
        "sub",
        "rt/bench/disc/lagrange_1/wrench",
        "geometry_msgs::msg::dds_::WrenchStamped_",
    );
    has(
        "sub",
        "rt/bench/disc/wrenches",
        "annular_plate::msg::dds_::NodeWrenchArray_",
    );
    has(
        "sub",
        "rq/bench/disc/resetRequest",
        "std_srvs::srv::dds_::Trigger_Request_",
    );
    has(
        "sub",
        "rq/bench/disc/set_pausedRequest",
        "std_srvs::srv::dds_::SetBool_Request_",
    );
    has(
        "sub",
        "rq/bench/disc/stepRequest",
        "annular_plate::srv::dds_::Step_Request_",
    );
    has(
        "pub",
        "rr/bench/disc/stepReply",
        "annular_plate::srv::dds_::Step_Response_",
    );
    has(
        "sub",
        "rq/bench/disc/get_parametersRequest",
        "rcl_interfaces::srv::dds_::GetParameters_Request_",
    );
    has(
        "pub",
        "rr/bench/disc/list_parametersReply",
        "rcl_interfaces::srv::dds_::ListParameters_Response_",
    );
    assert!(
        !eps.iter()
            .any(|(k, t, _)| k == "pub" && t == "rt/joint_states"),
        "/joint_states was remapped"
    );
    assert!(
        !eps.iter().any(|(_, t, _)| t == "rt/clock"),
        "no /clock without simulated time"
    );
    assert!(
        !eps.iter()
            .any(|(_, t, _)| t.contains("ale_4") || t.contains("pad_2")),
        "only the scene's nodes and pads"
    );
    assert!(
        !eps.iter().any(|(_, t, _)| t.contains("tool")),
        "no tool topics without a tool"
    );
}
