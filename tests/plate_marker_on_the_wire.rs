//! `~/plate_marker`, the deformed plate for RViz and Foxglove, checked where
//! a user sees it: decoded by an independent DDS implementation (Cyclone DDS,
//! tests/peer/peer.py), against the modal sum w = Σ q_i w_i of the model
//! evaluated here at each vertex, and read back from the node's own
//! recording and from `simulate --bag` with `rosbags` (types rebuilt from the
//! bag, as Foxglove and `ros2 bag play` do).

#![cfg(feature = "ros")]

#[path = "peer/harness.rs"]
mod harness;

use annular_plate::dynamics::Simulation;
use annular_plate::ros::NodeSetup;
use harness::{fresh_dir, node_binary, peer, read_bag, scene, start_node_with, Netns};
use serde_json::{json, Value};
use std::collections::BTreeMap;
use std::ffi::OsStr;
use std::time::Duration;

const TOPIC: &str = "/annular_plate/plate_marker";
/// A held rim load on ALE node 1 and one on the Lagrangian node: the plate
/// deflects and two arrows are drawn (the pads stay open).
/// On the Kirchhoff disc: the picture check below counts the reddish and
/// bluish pixels of the deflection these loads give it.
const ARGS: [&str; 10] = [
    "-p",
    "plate.theory:=kirchhoff",
    "-p",
    "ros.start_paused:=true",
    "-p",
    "ros.publish_clock:=true",
    "-p",
    "loads.ale_wrench:=[0.0, 40.0, -500.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0]",
    "-p",
    "loads.lagrange_wrench:=[0.0, 0.0, 200.0, 0.0, 0.0, 0.0]",
];

/// The documented colour map (docs/ros.md), written out here: blue at
/// t = −1, light grey at 0, red at +1, linear in each half.
fn documented_colour(t: f64) -> [f64; 3] {
    let (blue, grey, red) = (
        [0.230, 0.299, 0.754],
        [0.865, 0.865, 0.865],
        [0.706, 0.016, 0.150],
    );
    let t = t.clamp(-1.0, 1.0);
    let (end, u) = if t < 0.0 { (blue, -t) } else { (red, t) };
    std::array::from_fn(|i| grey[i] + (end[i] - grey[i]) * u)
}

fn number_after(text: &str, key: &str) -> f64 {
    let rest = text
        .split(&format!("{key}="))
        .nth(1)
        .unwrap_or_else(|| panic!("no {key}= in {text:?}"));
    rest.split_whitespace().next().unwrap().parse().unwrap()
}

fn xyz(p: &Value) -> [f64; 3] {
    [
        p["x"].as_f64().unwrap(),
        p["y"].as_f64().unwrap(),
        p["z"].as_f64().unwrap(),
    ]
}

/// Everything the marker promises about one state, against the model here;
/// returns its scale and the largest |w| at its vertices.
fn check_marker(
    sim: &Simulation,
    array: &Value,
    q: &[f64],
    forces: &[(String, [f64; 3])],
) -> (f64, f64) {
    let markers = array["markers"].as_array().unwrap();
    assert_eq!(markers[0]["action"], json!(3), "DELETEALL first");
    let mesh = &markers[1];
    assert_eq!(
        (mesh["type"].as_i64(), mesh["header"]["frame_id"].as_str()),
        (Some(11), Some("plate_rotor"))
    );
    let points = mesh["points"].as_array().unwrap();
    let colors = mesh["colors"].as_array().unwrap();
    assert_eq!(
        points.len(),
        3 * 2 * 8 * 128,
        "2 × rings × sectors triangles"
    );
    assert_eq!(colors.len(), points.len());
    let text = mesh["text"].as_str().unwrap();
    let (scale, colour_ref) = (
        number_after(text, "scale"),
        number_after(text, "colour_ref_m"),
    );
    let model = sim.model();
    let (ri, ra) = (model.plate().inner_radius, model.plate().outer_radius);
    let mut worst: f64 = 0.0;
    let mut z_max: f64 = 0.0;
    let mut w_max: f64 = 0.0;
    for (p, c) in points.iter().zip(colors) {
        let [x, y, z] = xyz(p);
        let (r, phi) = (x.hypot(y), y.atan2(x));
        assert!(
            r >= ri * (1.0 - 1e-12) && r <= ra * (1.0 + 1e-12),
            "vertex off the plate: r = {r}"
        );
        let w = model.deflection(q, r, phi).w;
        worst = worst.max((z - scale * w).abs());
        w_max = w_max.max(w.abs());
        z_max = z_max.max(z.abs());
        let want = documented_colour(w / colour_ref);
        let got = [
            c["r"].as_f64().unwrap(),
            c["g"].as_f64().unwrap(),
            c["b"].as_f64().unwrap(),
        ];
        for i in 0..3 {
            assert!(
                (got[i] - want[i]).abs() < 1e-5,
                "colour {got:?} for w/ref = {}: want {want:?}",
                w / colour_ref
            );
        }
    }
    println!("marker: scale {scale:e}, colour_ref {colour_ref:e} m, largest |z| {z_max:e} m, worst |z − scale·Σ q w| {worst:e} m");
    assert!(z_max > 1e-3, "the plate is drawn deflected");
    assert!(worst <= 1e-12 * z_max.max(1e-300) * 100.0, "{worst:e}");
    let arrows: Vec<&Value> = markers[2..].iter().collect();
    assert_eq!(
        arrows.len(),
        forces.len(),
        "one arrow per node frame with a force"
    );
    let force_scale = number_after(text, "force_scale_m_per_n");
    let f_max = forces
        .iter()
        .map(|(_, f)| f.iter().map(|v| v * v).sum::<f64>().sqrt())
        .fold(0.0, f64::max);
    assert!(
        (force_scale * f_max - 0.25 * ra).abs() < 1e-12,
        "the largest force is drawn r_a / 4 long"
    );
    for (arrow, (frame, f)) in arrows.iter().zip(forces) {
        assert_eq!(
            (arrow["type"].as_i64(), arrow["header"]["frame_id"].as_str()),
            (Some(0), Some(frame.as_str()))
        );
        let pts = arrow["points"].as_array().unwrap();
        let (tail, head) = (xyz(&pts[0]), xyz(&pts[1]));
        assert_eq!(head, [0.0; 3], "the arrow ends at the node frame's origin");
        for i in 0..3 {
            assert!(
                (tail[i] + force_scale * f[i]).abs() < 1e-12,
                "arrow {tail:?} for force {f:?}"
            );
        }
    }
    (scale, w_max)
}

/// Forces at the node frames of the offline simulation (held + load models), non-zero only.
fn node_forces(sim: &Simulation) -> Vec<(String, [f64; 3])> {
    let mut out = vec![];
    for j in 0..sim.n_ale_nodes() {
        let (a, b) = (sim.inputs().ale[j].force, sim.ale_model_wrench(j).force);
        out.push((
            format!("plate_ale_{}", j + 1),
            [a[0] + b[0], a[1] + b[1], a[2] + b[2]],
        ));
    }
    for j in 0..sim.n_lagrange_nodes() {
        let (a, b) = (
            sim.inputs().lagrange[j].force,
            sim.lagrange_model_wrench(j).force,
        );
        out.push((
            format!("plate_lagrange_{}", j + 1),
            [a[0] + b[0], a[1] + b[1], a[2] + b[2]],
        ));
    }
    out.retain(|(_, f)| f.iter().any(|v| *v != 0.0));
    out
}

/// Markers of a bag by header stamp (ns).
fn bag_markers(bag: &Value) -> BTreeMap<i64, Value> {
    let t = &bag["topics"][TOPIC];
    assert_eq!(t["type"], json!("visualization_msgs/msg/MarkerArray"));
    t["messages"]
        .as_array()
        .expect("full messages")
        .iter()
        .map(|m| {
            let s = &m["markers"][1]["header"]["stamp"];
            (
                s["sec"].as_i64().unwrap() * 1_000_000_000 + s["nanosec"].as_i64().unwrap(),
                m.clone(),
            )
        })
        .collect()
}

#[test]
fn rviz_sees_the_modal_sum_and_the_recordings_hold_the_same_markers() {
    let ns = Netns::new();
    let dir = fresh_dir("plate_marker_record");
    let mut node = start_node_with(&ns, 44, &[OsStr::new("--record"), dir.as_os_str()], &ARGS);
    // 30 Hz at 1 kHz: a marker every 33 steps.
    let out = peer(
        &ns,
        &node,
        "marker",
        "/annular_plate",
        json!({"steps": 66, "expect": 2}),
    );
    node.signal("INT");
    assert!(
        node.wait_exit(Duration::from_secs(10))
            .is_some_and(|s| s.success()),
        "{}",
        node.stderr()
    );

    let args: Vec<String> = ARGS.iter().map(|s| s.to_string()).collect();
    let setup = NodeSetup::load(Some(&scene()), &args).unwrap();
    let mut sim = Simulation::new(setup.config.clone()).unwrap();
    let live = out["markers"].as_array().unwrap();
    assert!(live.len() >= 2, "{out:.300}");
    let mut checked = 0;
    // The marker at step 0 (before the peer joined) drew a flat plate.
    let mut largest_w: f64 = 0.0;
    for m in live {
        let stamp = m["stamp_ns"].as_i64().unwrap();
        let step = (stamp as f64 * 1e-9 / sim.dt()).round() as u64;
        assert_eq!(
            step % 33,
            0,
            "markers come with every 33rd step: stamp {stamp} ns"
        );
        let q: Vec<f64> = m["q_lagrange"]
            .as_array()
            .expect("the modal amplitudes of the marker's stamp")
            .iter()
            .map(|v| v.as_f64().unwrap())
            .collect();
        while sim.step_count() < step {
            sim.step().unwrap();
        }
        assert_eq!(
            q,
            sim.q_lagrange(),
            "the node's state at the marker's stamp is the offline one"
        );
        let (scale, w_max) = check_marker(&sim, &m["marker"], &q, &node_forces(&sim));
        // Auto scale: the largest |w| of the last second (every marker so far) drawn as 5 % of r_a.
        largest_w = largest_w.max(w_max);
        let ra = sim.model().plate().outer_radius;
        assert!(
            (scale * largest_w / (0.05 * ra) - 1.0).abs() < 1e-12,
            "scale {scale:e}, largest |w| {largest_w:e}"
        );
        checked += 1;
    }
    assert!(checked >= 2);

    // The node's own recording holds the very markers the peer saw.
    let recorded = bag_markers(&read_bag(&dir, "rosbags", &[TOPIC]));
    // `simulate --bag` on the same scene: the same markers at the same stamps.
    let scene_file = dir.with_file_name("plate_marker_scene.yaml");
    let text = std::fs::read_to_string(scene())
        .unwrap()
        .replace("theory: mindlin", "theory: kirchhoff")
        .replace(
        "    pads:",
        "    loads:\n      ale_wrench: [0.0, 40.0, -500.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0]\n      lagrange_wrench: [0.0, 0.0, 200.0, 0.0, 0.0, 0.0]\n    pads:",
    );
    std::fs::write(&scene_file, text).unwrap();
    let offline_dir = fresh_dir("plate_marker_simulate");
    let status = std::process::Command::new(node_binary())
        .args(["simulate", "--quiet", "--duration", "0.07", "--bag"])
        .arg(&offline_dir)
        .arg(&scene_file)
        .status()
        .unwrap();
    assert!(status.success());
    let offline = bag_markers(&read_bag(&offline_dir, "rosbags", &[TOPIC]));
    assert_eq!(
        offline.keys().copied().collect::<Vec<_>>(),
        vec![0, 33_000_000, 66_000_000],
        "simulate --bag: a marker every 33 steps"
    );
    // `plot marker` draws the bag's last marker without RViz: red where the
    // plate deflects up, blue where down (the mesh's own colours).
    let png = offline_dir.with_file_name("plate_marker.png");
    let status = std::process::Command::new(node_binary())
        .args(["plot", "marker"])
        .arg(&offline_dir)
        .arg("--out")
        .arg(&png)
        .status()
        .unwrap();
    assert!(status.success());
    let img = image::open(&png).unwrap().to_rgb8();
    let reddish = img
        .pixels()
        .filter(|p| p[0] as i32 - p[2] as i32 > 60)
        .count();
    let bluish = img
        .pixels()
        .filter(|p| p[2] as i32 - p[0] as i32 > 60)
        .count();
    println!("plot marker: {reddish} reddish and {bluish} bluish pixels");
    assert!(reddish > 1000 && bluish > 1000);
    for m in live {
        let stamp = m["stamp_ns"].as_i64().unwrap();
        let from_wire = &m["marker"];
        assert_eq!(
            recorded.get(&stamp),
            Some(from_wire),
            "run --record: the marker at {stamp} ns as published"
        );
        assert_eq!(
            offline.get(&stamp),
            Some(from_wire),
            "simulate --bag: the marker at {stamp} ns as the node's"
        );
    }
}
