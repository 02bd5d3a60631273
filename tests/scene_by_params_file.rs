//! The scene a node runs is decided as ROS users expect: a `--params-file`
//! that holds a scene (what `ros2 run … --ros-args --params-file F` and a
//! launch file's `parameters=[F]` give) is the scene — not layered onto the
//! built-in brake bench — and equals `run F`; further parameter files and
//! `-p` override its keys; files with only the node's own keys leave the
//! built-in scene.

mod support;

use annular_plate::config::Config;
use annular_plate::dynamics::load_models::pad_outputs::PadOutputs;
use annular_plate::dynamics::load_models::tool::ToolOutputs;
use annular_plate::dynamics::load_models::tool_config::ToolConfig;
use annular_plate::ros::NodeSetup;
use support::scene_files;

fn args(list: &[&str]) -> Vec<String> {
    std::iter::once("--ros-args")
        .chain(list.iter().copied())
        .map(str::to_string)
        .collect()
}

#[test]
fn every_shipped_scene_through_params_file_alone_is_the_scene_run_file_gives() {
    for file in [
        "brake_bench.yaml",
        "brake_squeal.yaml",
        "brake_squeal_paper.yaml",
        "design_example.yaml",
        "lathe.yaml",
        "swash_plate.yaml",
    ] {
        let path = scene_files::path(file);
        let by_params = NodeSetup::load(None, &args(&["--params-file", path.to_str().unwrap()]))
            .unwrap_or_else(|e| panic!("{file}: {e}"));
        let by_run = NodeSetup::load(Some(&path), &args(&[])).unwrap();
        let expected = Config::from_params_file(&path, scene_files::NODE).unwrap();
        assert_eq!(
            by_params.config, expected,
            "{file}: --params-file gives the file's scene"
        );
        assert_eq!(
            by_run.config, expected,
            "{file}: run FILE gives the file's scene"
        );
        assert_eq!(
            by_params.scene,
            path.display().to_string(),
            "{file}: the scene is named"
        );
    }
}

#[test]
fn later_params_files_and_p_override_the_scene_and_node_only_files_keep_the_built_in_one() {
    let dir = std::env::temp_dir().join(format!("annular_plate_params_{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let speed = dir.join("speed.yaml");
    std::fs::write(&speed, "/**:\n  ros__parameters:\n    joint.speed: 42.0\n").unwrap();
    let node_only = dir.join("node_only.yaml");
    std::fs::write(
        &node_only,
        "/**:\n  ros__parameters:\n    use_sim_time: false\n    ros.frame_prefix: bench/\n",
    )
    .unwrap();
    let lathe = scene_files::path("lathe.yaml");

    let s = NodeSetup::load(
        None,
        &args(&[
            "--params-file",
            lathe.to_str().unwrap(),
            "--params-file",
            speed.to_str().unwrap(),
        ]),
    )
    .unwrap();
    assert_eq!(s.config.joint.speed, 42.0);
    assert!(
        s.config.section::<ToolConfig>().is_some(),
        "still the lathe"
    );
    let s = NodeSetup::load(
        None,
        &args(&[
            "--params-file",
            lathe.to_str().unwrap(),
            "-p",
            "joint.speed:=7.0",
        ]),
    )
    .unwrap();
    assert_eq!(s.config.joint.speed, 7.0);

    // Only the node's own keys: the built-in brake bench with them.
    let s = NodeSetup::load(None, &args(&["--params-file", node_only.to_str().unwrap()])).unwrap();
    assert_eq!(s.scene, "built-in config/brake_bench.yaml");
    assert_eq!(s.settings.frame_prefix, "bench/");
    assert_eq!(
        s.config,
        Config::from_params_file(&scene_files::path("brake_bench.yaml"), scene_files::NODE)
            .unwrap()
    );
    // A file with a scene given after a node-only one is still the scene.
    let s = NodeSetup::load(
        None,
        &args(&[
            "--params-file",
            node_only.to_str().unwrap(),
            "--params-file",
            lathe.to_str().unwrap(),
        ]),
    )
    .unwrap();
    assert!(s.config.section::<ToolConfig>().is_some() && s.settings.frame_prefix == "bench/");
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn the_wildcard_keyed_scenes_apply_to_any_node_name_and_namespace() {
    for file in [
        "brake_bench.yaml",
        "brake_squeal.yaml",
        "brake_squeal_paper.yaml",
        "lathe.yaml",
        "swash_plate.yaml",
    ] {
        let path = scene_files::path(file);
        assert!(
            scene_files::text(file)
                .lines()
                .any(|l| l.starts_with("/**:")),
            "{file} is keyed /**"
        );
        let expected = Config::from_params_file(&path, scene_files::NODE).unwrap();
        for remap in [
            &["-r", "__node:=disc"][..],
            &["-r", "__ns:=/bench", "-r", "__node:=disc"][..],
        ] {
            let mut a = remap.to_vec();
            a.extend(["--params-file", path.to_str().unwrap()]);
            let s = NodeSetup::load(None, &args(&a))
                .unwrap_or_else(|e| panic!("{file} {remap:?}: {e}"));
            assert_eq!(s.config, expected, "{file} {remap:?}");
            let s = NodeSetup::load(Some(&path), &args(remap))
                .unwrap_or_else(|e| panic!("{file} {remap:?}: {e}"));
            assert_eq!(s.config, expected, "{file} {remap:?} (run FILE)");
        }
    }
}

/// What a started node reports of its model: modes (with their frequencies),
/// node counts, pads, tool.
fn model_summary(setup: NodeSetup) -> (usize, Vec<u64>, usize, usize, usize, bool) {
    let sim = annular_plate::dynamics::Simulation::new(setup.config).expect("the model builds");
    let freqs = sim
        .model()
        .modes()
        .iter()
        .map(|m| m.frequency_hz.to_bits())
        .collect();
    (
        sim.model().n_modes(),
        freqs,
        sim.n_ale_nodes(),
        sim.n_lagrange_nodes(),
        sim.pad_count(),
        sim.has_tool(),
    )
}

#[test]
fn each_shipped_scene_builds_the_same_model_through_params_file_launch_args_and_run_file() {
    for file in [
        "brake_bench.yaml",
        "brake_squeal.yaml",
        "brake_squeal_paper.yaml",
        "design_example.yaml",
        "lathe.yaml",
        "swash_plate.yaml",
    ] {
        let path = scene_files::path(file);
        let p = path.to_str().unwrap();
        // What a launch file with node_name:= and namespace:= passes (design_example's
        // exact-name entry is for /annular_plate only, so its launch keeps that name).
        let launch: Vec<&str> = if file == "design_example.yaml" {
            vec!["-r", "__node:=annular_plate", "--params-file", p]
        } else {
            vec![
                "-r",
                "__node:=disc",
                "-r",
                "__ns:=/bench",
                "--params-file",
                p,
            ]
        };
        let by_params = model_summary(NodeSetup::load(None, &args(&["--params-file", p])).unwrap());
        let by_launch = model_summary(
            NodeSetup::load(None, &args(&launch))
                .unwrap_or_else(|e| panic!("{file} {launch:?}: {e}")),
        );
        let by_run = model_summary(NodeSetup::load(Some(&path), &args(&[])).unwrap());
        assert!(
            by_params.0 > 0 && by_params.2 + by_params.3 > 0,
            "{file}: a model with modes and nodes"
        );
        assert_eq!(
            by_launch, by_params,
            "{file}: launch-file arguments vs --params-file alone"
        );
        assert_eq!(by_run, by_params, "{file}: run FILE vs --params-file alone");
    }
}
