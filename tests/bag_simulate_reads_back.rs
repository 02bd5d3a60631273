//! `annular_plate simulate FILE --duration S --csv OUT --bag DIR` writes a
//! rosbag2 directory that independent readers take as the node's topics:
//! `rosbags` (with an empty type store, so every type is rebuilt from the
//! definitions stored in the bag) and `mcap` + `mcap-ros2-support` (a second
//! CDR and .msg implementation). The readers are installed by the tests into
//! `target/peer-venv` (tests/peer/requirements.txt); if that is impossible
//! the tests fail, they never skip.
//!
//! Checked against the run: topic list, types, QoS, metadata.yaml, message
//! counts (one per step and t = 0, one /tf_static, /diagnostics once per
//! simulated second), log times and stamps (simulated time from 0), and the
//! values — joint state and modal amplitudes equal to the CSV of the same
//! run, transforms and rates equal to the in-process `Simulation`.

#![cfg(feature = "ros")]

#[path = "peer/harness.rs"]
mod harness;

use annular_plate::dynamics::Simulation;
use harness::{f, floats, fresh_dir, node_binary, read_bag, repo};
use serde_json::Value;
use std::path::{Path, PathBuf};
use std::process::Command;

const DURATION: f64 = 1.2;
const STEPS: u64 = 1200;
const TILT: f64 = 0.2;
const MODAL: &str = "/annular_plate/modal_amplitudes";
const PER_STEP: [&str; 4] = ["/clock", "/joint_states", "/tf", MODAL];

/// The design example with a tilted spin axis (so /tf_static is not the identity).
fn scene() -> PathBuf {
    let text = std::fs::read_to_string(repo().join("config/design_example.yaml"))
        .expect("config/design_example.yaml");
    let d = repo().join("target/bag-tests");
    std::fs::create_dir_all(&d).unwrap();
    let p = d.join("design_example_tilted.yaml");
    write_atomically(
        &p,
        &format!("{}\n    reference:\n      tilt: {TILT}\n", text.trim_end()),
    );
    p
}

/// Tests run in parallel and share scene files: each writes its copy under a
/// name of its own and renames it into place, so no test reads a half-written file.
fn write_atomically(path: &Path, text: &str) {
    std::fs::create_dir_all(path.parent().unwrap()).unwrap();
    let tmp = path
        .with_extension(format!("tmp{:?}", std::thread::current().id()).replace(['(', ')'], ""));
    std::fs::write(&tmp, text).unwrap();
    std::fs::rename(&tmp, path).unwrap();
}

fn simulate(scene: &Path, extra: &[&std::ffi::OsStr]) -> std::process::Output {
    Command::new(node_binary())
        .arg("simulate")
        .arg(scene)
        .args(["--duration", &DURATION.to_string(), "--quiet"])
        .args(extra)
        .output()
        .expect("run annular_plate simulate")
}

/// Equal up to the last bit or two (JSON and CSV numbers are printed shortest-round-trip).
fn same(a: f64, b: f64, what: &str) {
    assert!(
        (a - b).abs() <= 4.5e-16 * a.abs().max(b.abs()),
        "{what}: bag {a} vs expected {b}"
    );
}

fn same_all(a: &[f64], b: &[f64], what: &str) {
    assert_eq!(a.len(), b.len(), "{what}: lengths");
    for (i, (x, y)) in a.iter().zip(b).enumerate() {
        same(*x, *y, &format!("{what}[{i}]"));
    }
}

fn u64s(v: &Value) -> Vec<u64> {
    v.as_array()
        .unwrap_or_else(|| panic!("not an array: {v:.200}"))
        .iter()
        .map(|x| x.as_u64().expect("integer"))
        .collect()
}

struct Csv {
    cols: Vec<String>,
    rows: Vec<Vec<f64>>,
}

impl Csv {
    fn read(p: &Path) -> Csv {
        let text = std::fs::read_to_string(p).unwrap();
        let mut lines = text.lines();
        let cols = lines.next().unwrap().split(',').map(String::from).collect();
        let rows = lines
            .map(|l| l.split(',').map(|x| x.parse().unwrap()).collect())
            .collect();
        Csv { cols, rows }
    }
    fn col(&self, row: usize, name: &str) -> f64 {
        self.rows[row][self
            .cols
            .iter()
            .position(|c| c == name)
            .unwrap_or_else(|| panic!("no column {name}"))]
    }
    fn cols_starting(&self, row: usize, prefix: &str, n: usize) -> Vec<f64> {
        (1..=n)
            .map(|i| self.col(row, &format!("{prefix}{i}")))
            .collect()
    }
}

fn transform<'a>(tf: &'a Value, child: &str) -> &'a Value {
    tf["transforms"]
        .as_array()
        .unwrap()
        .iter()
        .find(|t| t["child_frame_id"] == child)
        .unwrap_or_else(|| panic!("no {child}"))
}

fn pose(t: &Value) -> ([f64; 3], [f64; 4]) {
    let tr = &t["transform"];
    (
        [
            f(tr, "translation.x"),
            f(tr, "translation.y"),
            f(tr, "translation.z"),
        ],
        [
            f(tr, "rotation.x"),
            f(tr, "rotation.y"),
            f(tr, "rotation.z"),
            f(tr, "rotation.w"),
        ],
    )
}

#[test]
fn a_simulate_bag_holds_the_node_topics_with_the_runs_values() {
    let scene = scene();
    let bag = fresh_dir("simulate_bag");
    let csv = repo().join("target/bag-tests/simulate_bag.csv");
    let out = simulate(
        &scene,
        &[
            "--csv".as_ref(),
            csv.as_os_str(),
            "--bag".as_ref(),
            bag.as_os_str(),
        ],
    );
    assert!(
        out.status.success(),
        "simulate --bag failed: {}",
        String::from_utf8_lossy(&out.stderr)
    );

    let d = read_bag(
        &bag,
        "rosbags",
        &[
            MODAL,
            "/joint_states",
            "/tf",
            "/tf_static",
            "/diagnostics",
            "/clock",
        ],
    );
    assert_eq!(
        d["undecodable"],
        serde_json::json!([]),
        "every message decodes"
    );

    // Topics and types (rosbags' view of the bag).
    let expected_types = [
        ("/tf_static", "tf2_msgs/msg/TFMessage"),
        ("/joint_states", "sensor_msgs/msg/JointState"),
        ("/tf", "tf2_msgs/msg/TFMessage"),
        (MODAL, "annular_plate/msg/ModalAmplitudes"),
        (
            "/annular_plate/plate_marker",
            "visualization_msgs/msg/MarkerArray",
        ),
        ("/diagnostics", "diagnostic_msgs/msg/DiagnosticArray"),
        ("/clock", "rosgraph_msgs/msg/Clock"),
    ];
    let conns = d["connections"].as_array().unwrap();
    assert_eq!(conns.len(), expected_types.len(), "{conns:?}");
    let n_diag = STEPS / 1000 + 1;
    for (topic, ty) in expected_types {
        let c = conns
            .iter()
            .find(|c| c["topic"] == topic)
            .unwrap_or_else(|| panic!("no connection {topic}"));
        assert_eq!(c["msgtype"], ty);
        assert_eq!(c["serialization_format"], "cdr");
        assert_eq!(c["msgdef_format"], "MSG");
        let want = match topic {
            "/tf_static" => 1,
            "/diagnostics" => n_diag,
            // Every 33rd step from 0 (30 Hz at 1 kHz).
            "/annular_plate/plate_marker" => STEPS / 33 + 1,
            _ => STEPS + 1,
        };
        assert_eq!(
            c["msgcount"].as_u64(),
            Some(want),
            "{topic} count in the bag's index"
        );
        assert_eq!(
            d["topics"][topic]["count"].as_u64(),
            Some(want),
            "{topic}: messages read"
        );
        let q = &c["qos"][0];
        assert_eq!(q["reliability"], "reliable", "{topic}");
        assert_eq!(q["history"], "keep_last", "{topic}");
        let (durability, depth) = match topic {
            "/tf_static" => ("transient_local", 1),
            "/tf" => ("volatile", 100),
            "/clock" | "/annular_plate/plate_marker" => ("volatile", 1),
            _ => ("volatile", 10),
        };
        assert_eq!(
            (
                q["durability"].as_str().unwrap(),
                q["depth"].as_u64().unwrap()
            ),
            (durability, depth),
            "{topic} QoS"
        );
    }

    // metadata.yaml as written.
    let m = &d["metadata_yaml"]["rosbag2_bagfile_information"];
    assert_eq!(m["version"], 9);
    assert_eq!(m["storage_identifier"], "mcap");
    assert_eq!(m["ros_distro"], "jazzy");
    assert_eq!(m["starting_time"]["nanoseconds_since_epoch"], 0);
    assert_eq!(
        m["duration"]["nanoseconds"].as_u64(),
        Some(STEPS * 1_000_000)
    );
    assert_eq!(
        m["message_count"].as_u64(),
        Some(4 * (STEPS + 1) + 1 + n_diag + STEPS / 33 + 1)
    );
    let file = format!("{}_0.mcap", bag.file_name().unwrap().to_string_lossy());
    assert_eq!(m["relative_file_paths"], serde_json::json!([file]));
    assert!(bag.join(&file).is_file());
    assert_eq!(m["files"][0]["message_count"], m["message_count"]);
    for t in m["topics_with_message_count"].as_array().unwrap() {
        let name = t["topic_metadata"]["name"].as_str().unwrap();
        assert_eq!(t["message_count"], d["topics"][name]["count"], "{name}");
        assert!(t["topic_metadata"]["offered_qos_profiles"]
            .as_str()
            .unwrap()
            .starts_with("- history: keep_last\n"));
    }

    // Times: simulated, from 0, 1 ms per step; log time = stamp; modal step = index.
    let ms: Vec<u64> = (0..=STEPS).map(|k| k * 1_000_000).collect();
    for topic in PER_STEP {
        let t = &d["topics"][topic];
        assert_eq!(u64s(&t["log_times"]), ms, "{topic} log times");
        assert_eq!(u64s(&t["stamps"]), ms, "{topic} stamps");
    }
    assert_eq!(
        u64s(&d["topics"][MODAL]["steps"]),
        (0..=STEPS).collect::<Vec<_>>()
    );
    assert_eq!(u64s(&d["topics"]["/tf_static"]["log_times"]), vec![0]);
    assert_eq!(
        u64s(&d["topics"]["/diagnostics"]["log_times"]),
        (0..n_diag).map(|k| k * 1_000_000_000).collect::<Vec<_>>()
    );

    // Values: the CSV of the same run, and the in-process Simulation.
    let csv = Csv::read(&csv);
    assert_eq!(csv.rows.len() as u64, STEPS + 1);
    let mut sim = Simulation::new(annular_plate::cli::load_config(&scene).unwrap()).unwrap();
    let n = sim.model().n_modes();
    let modal = d["topics"][MODAL]["messages"].as_array().unwrap();
    let joints = d["topics"]["/joint_states"]["messages"].as_array().unwrap();
    let tfs = d["topics"]["/tf"]["messages"].as_array().unwrap();
    let freqs: Vec<f64> = sim.model().modes().iter().map(|m| m.frequency_hz).collect();
    let mut max_q = 0.0f64;
    for k in 0..=STEPS as usize {
        if k > 0 {
            sim.step().unwrap();
        }
        let (js, mo, tf) = (&joints[k], &modal[k], &tfs[k]);
        assert_eq!(js["name"], serde_json::json!(["plate_joint"]));
        same(
            floats(&js["position"])[0],
            csv.col(k, "joint_position"),
            "joint position vs CSV",
        );
        same(
            floats(&js["velocity"])[0],
            csv.col(k, "joint_velocity"),
            "joint velocity vs CSV",
        );
        same(floats(&js["effort"])[0], sim.joint().effort, "joint effort");
        same(f(mo, "sim_time"), csv.col(k, "time"), "sim_time vs CSV");
        same_all(
            &floats(&mo["q_lagrange"]),
            &csv.cols_starting(k, "q", n),
            "q_lagrange vs CSV",
        );
        same_all(
            &floats(&mo["q_ale"]),
            &csv.cols_starting(k, "qale", n),
            "q_ale vs CSV",
        );
        same_all(
            &floats(&mo["q_dot_lagrange"]),
            sim.q_dot_lagrange(),
            "q_dot_lagrange",
        );
        same_all(&floats(&mo["q_dot_ale"]), sim.q_dot_ale(), "q_dot_ale");
        max_q = max_q.max(floats(&mo["q_ale"]).iter().fold(0.0, |a, q| a.max(q.abs())));
        if k == 0 {
            same_all(&floats(&mo["frequency_hz"]), &freqs, "frequency_hz");
            assert_eq!(mo["header"]["frame_id"], "plate_base");
        }
        let (t, r) = pose(transform(tf, "plate_ale_1"));
        let p = sim.ale_node_pose(0);
        same_all(&t, &p.translation, "ale_1 translation");
        same_all(&r, &p.rotation, "ale_1 rotation");
        let (t, r) = pose(transform(tf, "plate_lagrange_1"));
        let p = sim.lagrange_node_pose(0);
        same_all(&t, &p.translation, "lagrange_1 translation");
        same_all(&r, &p.rotation, "lagrange_1 rotation");
        let (_, r) = pose(transform(tf, "plate_rotor"));
        let half = 0.5 * sim.rotor_angle();
        same_all(&r, &[0.0, 0.0, half.sin(), half.cos()], "rotor rotation");
    }
    assert!(
        max_q > 1e-7,
        "the load deforms the plate (max |q_ale| = {max_q})"
    );

    let st = &d["topics"]["/tf_static"]["messages"][0]["transforms"];
    assert_eq!(st.as_array().unwrap().len(), 1);
    assert_eq!(
        (
            st[0]["header"]["frame_id"].as_str(),
            st[0]["child_frame_id"].as_str()
        ),
        (Some("world"), Some("plate_base"))
    );
    let (_, r) = pose(&st[0]);
    same_all(
        &r,
        &[(0.5 * TILT).sin(), 0.0, 0.0, (0.5 * TILT).cos()],
        "tf_static rotation (tilt)",
    );

    let diags = d["topics"]["/diagnostics"]["messages"].as_array().unwrap();
    for (i, dm) in diags.iter().enumerate() {
        let names: Vec<&str> = dm["status"]
            .as_array()
            .unwrap()
            .iter()
            .map(|s| s["name"].as_str().unwrap())
            .collect();
        assert_eq!(
            names,
            vec!["/annular_plate: simulation", "/annular_plate: inputs"]
        );
        let step = dm["status"][0]["values"]
            .as_array()
            .unwrap()
            .iter()
            .find(|v| v["key"] == "step")
            .unwrap();
        assert_eq!(
            step["value"].as_str(),
            Some((i as u64 * 1000).to_string().as_str())
        );
    }

    // The second reader: mcap + mcap-ros2-support on the .mcap file.
    let m2 = read_bag(&bag, "mcap", &[]);
    assert_eq!(m2["undecodable"], serde_json::json!([]));
    assert_eq!(m2["header"]["profile"], "ros2");
    assert!(m2["metadata_records"]
        .as_array()
        .unwrap()
        .iter()
        .any(|r| r["name"] == "rosbag2"));
    for (topic, ty) in expected_types {
        let c = &m2["channels"][topic];
        assert_eq!(
            (c["message_encoding"].as_str(), c["schema"].as_str()),
            (Some("cdr"), Some(ty)),
            "{topic}"
        );
        assert!(c["metadata"]["offered_qos_profiles"]
            .as_str()
            .unwrap()
            .contains("reliability: reliable"));
        assert_eq!(
            m2["topics"][topic]["count"], d["topics"][topic]["count"],
            "{topic}"
        );
        assert_eq!(
            m2["topics"][topic]["log_times"], d["topics"][topic]["log_times"],
            "{topic}"
        );
        assert_eq!(
            m2["topics"][topic]["last"], d["topics"][topic]["last"],
            "{topic}: both readers decode the same"
        );
    }
    for s in m2["schemas"].as_object().unwrap().values() {
        assert_eq!(s["encoding"], "ros2msg");
    }
    let schema = m2["schemas"]
        .as_object()
        .unwrap()
        .values()
        .find(|s| s["name"] == "annular_plate/msg/ModalAmplitudes")
        .unwrap();
    let text = schema["data"].as_str().unwrap();
    assert!(
        text.starts_with(&std::fs::read_to_string(repo().join("msg/ModalAmplitudes.msg")).unwrap())
    );
    assert!(text.contains("\n================================================================================\nMSG: std_msgs/Header\n"));
}

#[test]
fn simulate_refuses_an_existing_bag_and_needs_an_output() {
    let scene = scene();
    let bag = fresh_dir("simulate_exists");
    std::fs::create_dir_all(&bag).unwrap();
    let out = simulate(&scene, &["--bag".as_ref(), bag.as_os_str()]);
    assert!(!out.status.success());
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("already exists"), "{err}");

    let out = simulate(&scene, &[]);
    assert!(!out.status.success());
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("--csv") && err.contains("--bag"), "{err}");

    // --bag alone (no CSV) is enough.
    let bag = fresh_dir("simulate_bag_only");
    let out = simulate(&scene, &["--bag".as_ref(), bag.as_os_str()]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(bag.join("metadata.yaml").is_file());
}

/// Scenes with load models: the pad states (brake bench, clamped) and the
/// tool state (lathe) are in the bag, one per step like the other state
/// topics, with the values of the CSV's scene columns of the same run.
/// config/brake_bench.yaml clamped at 5 kN (it starts unclamped), written
/// as target/bag-tests/`name`.
fn clamped_bench(name: &str) -> PathBuf {
    let text = std::fs::read_to_string(repo().join("config/brake_bench.yaml")).unwrap();
    assert!(
        text.contains("clamp_force: [0.0]"),
        "the bench starts unclamped"
    );
    let bench = repo().join("target/bag-tests").join(name);
    write_atomically(
        &bench,
        &text.replace("clamp_force: [0.0]", "clamp_force: [5000.0]"),
    );
    bench
}

#[test]
fn a_simulate_bag_of_a_scene_with_load_models_holds_their_states() {
    let bench = clamped_bench("brake_bench_clamped.yaml");
    let lathe = repo().join("config/lathe.yaml");
    for (scene, topic, ty, columns) in [
        (
            bench,
            "/annular_plate/pad_states",
            "annular_plate/msg/PadStates",
            [
                ("clamp_force", "pad1_clamp_force"),
                ("normal_force", "pad1_normal_force"),
                ("friction_torque", "pad1_friction_torque"),
            ],
        ),
        (
            lathe,
            "/annular_plate/tool_state",
            "annular_plate/msg/ToolState",
            [
                ("tip_z", "tool_tip_z"),
                ("chip_thickness", "tool_chip_thickness"),
                ("feed_force", "tool_feed_force"),
            ],
        ),
    ] {
        let name = scene.file_stem().unwrap().to_string_lossy().to_string();
        let bag = fresh_dir(&format!("simulate_models_{name}"));
        let csv = repo().join(format!("target/bag-tests/simulate_models_{name}.csv"));
        let out = simulate(
            &scene,
            &[
                "--csv".as_ref(),
                csv.as_os_str(),
                "--bag".as_ref(),
                bag.as_os_str(),
            ],
        );
        assert!(
            out.status.success(),
            "{name}: {}",
            String::from_utf8_lossy(&out.stderr)
        );
        let d = read_bag(&bag, "rosbags", &[topic]);
        assert_eq!(d["undecodable"], serde_json::json!([]), "{name}");
        let conns = d["connections"].as_array().unwrap();
        let c = conns
            .iter()
            .find(|c| c["topic"] == topic)
            .unwrap_or_else(|| panic!("{name}: no {topic} in {conns:?}"));
        assert_eq!(c["msgtype"], ty);
        assert_eq!(
            (
                c["qos"][0]["reliability"].as_str(),
                c["qos"][0]["depth"].as_u64()
            ),
            (Some("reliable"), Some(10))
        );
        assert!(
            !conns.iter().any(|c| c["topic"].as_str().unwrap().ends_with(
                if ty.ends_with("PadStates") {
                    "tool_state"
                } else {
                    "pad_states"
                }
            ))
        );
        let t = &d["topics"][topic];
        assert_eq!(
            u64s(&t["steps"]),
            (0..=STEPS).collect::<Vec<_>>(),
            "{name}: one per step"
        );
        assert_eq!(
            u64s(&t["log_times"]),
            (0..=STEPS).map(|k| k * 1_000_000).collect::<Vec<_>>(),
            "{name}: log times"
        );
        let csv = Csv::read(&csv);
        let msgs = t["messages"].as_array().unwrap();
        assert_eq!(msgs.len(), csv.rows.len());
        for (k, m) in msgs.iter().enumerate() {
            for (field, col) in columns {
                let v = if m[field].is_array() {
                    floats(&m[field])[0]
                } else {
                    f(m, field)
                };
                same(
                    v,
                    csv.col(k, col),
                    &format!("{name} step {k}: {field} vs the CSV's {col}"),
                );
            }
        }
        let last = msgs.last().unwrap();
        let moving = if ty.ends_with("PadStates") {
            floats(&last["friction_torque"])[0].abs()
        } else {
            f(last, "feed_force")
        };
        assert!(moving > 10.0, "{name}: the load model acts ({moving})");
    }
}

/// Massive pads (`pads.mass`): ~/pad_states carries each pad's compressions,
/// equal to the CSV's `pad{p}_top_compression` / `pad{p}_bottom_compression`
/// at every step; massless pads leave those arrays empty.
#[test]
fn a_simulate_bag_of_massive_pads_holds_their_compressions() {
    let bench = clamped_bench("brake_bench_massive.yaml");
    let topic = "/annular_plate/pad_states";
    for mass in ["0.3", "0.0"] {
        let bag = fresh_dir(&format!("simulate_massive_pads_{mass}"));
        let csv = repo().join(format!("target/bag-tests/simulate_massive_pads_{mass}.csv"));
        let p = format!("pads.mass:={mass}");
        let out = simulate(
            &bench,
            &[
                "--csv".as_ref(),
                csv.as_os_str(),
                "--bag".as_ref(),
                bag.as_os_str(),
                "-p".as_ref(),
                p.as_ref(),
            ],
        );
        assert!(
            out.status.success(),
            "m_p = {mass}: {}",
            String::from_utf8_lossy(&out.stderr)
        );
        let d = read_bag(&bag, "rosbags", &[topic]);
        assert_eq!(d["undecodable"], serde_json::json!([]));
        let msgs = d["topics"][topic]["messages"].as_array().unwrap();
        let csv = Csv::read(&csv);
        assert_eq!(msgs.len(), csv.rows.len());
        for (k, m) in msgs.iter().enumerate() {
            let (top, bottom) = (
                floats(&m["pad_compression_top"]),
                floats(&m["pad_compression_bottom"]),
            );
            if mass == "0.0" {
                assert!(
                    top.is_empty() && bottom.is_empty(),
                    "massless pads: no compressions ({top:?})"
                );
                continue;
            }
            same(
                top[0],
                csv.col(k, "pad1_top_compression"),
                &format!("step {k}: top compression"),
            );
            same(
                bottom[0],
                csv.col(k, "pad1_bottom_compression"),
                &format!("step {k}: bottom compression"),
            );
        }
        if mass == "0.3" {
            // At rest x₀ = N₀/(n k_c) with the bench's 3 contacts at 2e7 N/m.
            let x0 = 5000.0 / (3.0 * 2.0e7);
            let first = floats(&msgs[0]["pad_compression_top"])[0];
            assert!((first - x0).abs() < 1e-15, "{first} vs x₀ = {x0}");
        }
    }
}

/// The lining's patches (config/brake_squeal.yaml carries `pads.shear_*`):
/// ~/pad_states carries per contact point the patches' deflections and the
/// faces' slip, equal to the CSV's `contact{c}_…` columns at every step; the
/// first message holds the steady-sliding start, k_t x_θ = μ N₀/n
/// (μ = 0.5, N₀ = 5 kN over 18 points, k_t = 1.07e6 N/m, τ(Ωr) = 1).
#[test]
fn a_simulate_bag_of_sheared_pads_holds_their_patch_deflections() {
    let squeal = repo().join("config/brake_squeal.yaml");
    let topic = "/annular_plate/pad_states";
    let bag = fresh_dir("simulate_sheared_pads");
    let csv = repo().join("target/bag-tests/simulate_sheared_pads.csv");
    let out = simulate(
        &squeal,
        &[
            "--csv".as_ref(),
            csv.as_os_str(),
            "--bag".as_ref(),
            bag.as_os_str(),
        ],
    );
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let d = read_bag(&bag, "rosbags", &[topic]);
    assert_eq!(d["undecodable"], serde_json::json!([]));
    let msgs = d["topics"][topic]["messages"].as_array().unwrap();
    let csv = Csv::read(&csv);
    assert_eq!(msgs.len(), csv.rows.len());
    let fields = [
        "patch_top_radial",
        "patch_top_tangential",
        "patch_bottom_radial",
        "patch_bottom_tangential",
        "slip_top",
        "slip_bottom",
    ];
    for (k, m) in msgs.iter().enumerate() {
        for field in fields {
            let values = floats(&m[format!("contact_{field}").as_str()]);
            assert_eq!(values.len(), 18, "{field}: one per contact point");
            for (c, v) in values.iter().enumerate() {
                let col = format!("contact{}_{field}", c + 1);
                same(*v, csv.col(k, &col), &format!("step {k}: {col}"));
            }
        }
    }
    let x0 = 0.5 * (5000.0 / 18.0) / 1.07e6;
    for field in [
        "contact_patch_top_tangential",
        "contact_patch_bottom_tangential",
    ] {
        for v in floats(&msgs[0][field]) {
            same(v, x0, field);
        }
    }
}
