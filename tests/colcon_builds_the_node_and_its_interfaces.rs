//! `colcon build` of the package (CMakeLists.txt, package.xml) with the
//! ROS 2 Jazzy build wheels from PyPI (the venv of scripts/rclpy_env.sh, no
//! ROS installation): it builds the node with cargo into the checkout's own
//! target/ (CARGO_TARGET_DIR) and installs it as lib/annular_plate/annular_plate
//! — the file cargo built, so the installed node is this checkout's — with
//! the interfaces (importable from Python), the launch files, the example
//! and the scenes. How long colcon took, and whether cargo compiled anything,
//! is printed.

#![cfg(feature = "ros")]

#[path = "peer/harness.rs"]
mod harness;
#[path = "peer/rclpy.rs"]
mod rclpy;

use harness::repo;
use std::process::{Command, Stdio};
use std::time::Instant;

fn sh(script: &str) -> std::process::Output {
    Command::new("bash")
        .arg("-c")
        .arg(script)
        .stdin(Stdio::null())
        .output()
        .expect("cannot run bash")
}

#[test]
fn colcon_build_installs_the_node_built_by_cargo_with_the_interfaces_launch_files_and_scenes() {
    rclpy::env_script(); // the venv with colcon and the build wheels
    let venv = repo().join("target/rclpy-venv");
    let ws = repo().join("target/colcon-node-ws");
    let _ = std::fs::remove_dir_all(&ws);
    std::fs::create_dir_all(ws.join("src")).unwrap();
    std::os::unix::fs::symlink(repo(), ws.join("src/annular_plate")).unwrap();

    let t0 = Instant::now();
    let build = sh(&format!(
        r#"set -e; set +u; . "{venv}/bin/activate"; export AMENT_PREFIX_PATH="{venv}"; cd "{ws}"
           colcon build --event-handlers console_direct+ --cmake-args -DBUILD_TESTING=OFF"#,
        venv = venv.display(),
        ws = ws.display()
    ));
    let seconds = t0.elapsed().as_secs_f64();
    let log = format!(
        "{}{}",
        String::from_utf8_lossy(&build.stdout),
        String::from_utf8_lossy(&build.stderr)
    );
    assert!(
        build.status.success(),
        "colcon build failed ({}):\n{log}",
        build.status
    );
    // cargo's "Compiling name vX.Y.Z" (not Python's "Compiling '…py'…" of the install step).
    let compiled = log
        .lines()
        .filter(|l| {
            l.trim_start().starts_with("Compiling ") && !l.contains('\'') && l.contains(" v")
        })
        .count();
    println!(
        "colcon build (node and interfaces) took {seconds:.1} s; cargo compiled {compiled} crates{}",
        if compiled == 0 { " (the node was up to date in target/)" } else { "" }
    );
    assert!(
        log.contains("cargo build --release: the annular_plate node"),
        "colcon ran cargo:\n{log}"
    );

    let install = ws.join("install/annular_plate");
    let node = install.join("lib/annular_plate/annular_plate");
    assert!(
        node.exists(),
        "no {} after colcon build:\n{log}",
        node.display()
    );
    assert_eq!(
        std::fs::read(&node).unwrap(),
        std::fs::read(repo().join("target/release/annular_plate")).unwrap(),
        "the installed node is the one cargo built in target/release"
    );
    let help = Command::new(&node)
        .arg("--help")
        .output()
        .expect("run the installed node");
    assert!(
        help.status.success(),
        "installed `annular_plate --help`: {}",
        String::from_utf8_lossy(&help.stderr)
    );
    // The installed node on the installed scene.
    let modes = Command::new(&node)
        .arg("modes")
        .arg(install.join("share/annular_plate/config/brake_bench.yaml"))
        .output()
        .expect("run the installed node");
    assert!(
        modes.status.success(),
        "installed `annular_plate modes` on the installed scene: {}",
        String::from_utf8_lossy(&modes.stderr)
    );
    assert!(!modes.stdout.is_empty());
    for f in [
        "lib/annular_plate/brake_load_example.py",
        "share/annular_plate/launch-scripts/brake_bench.launch.py",
        "share/annular_plate/launch-scripts/scene.launch.py",
        "share/annular_plate/config/brake_bench.yaml",
        "share/annular_plate/config/lathe.yaml",
        "share/annular_plate/msg/PadClampForces.msg",
        "share/annular_plate/srv/Step.srv",
        "share/ament_index/resource_index/packages/annular_plate",
    ] {
        assert!(install.join(f).exists(), "{f} not installed");
    }
    let import = sh(&format!(
        r#"set -e; set +u; . "{venv}/bin/activate"; . "{ws}/install/setup.sh"
           python3 -c 'from annular_plate.msg import CriticalSpeeds, ModalAmplitudes, NodeWrench, NodeWrenchArray, PadClampForces, PadStates, ToolState
from annular_plate.srv import Step
print(Step.Request(steps=3).steps, PadClampForces().pad)'"#,
        venv = venv.display(),
        ws = ws.display()
    ));
    assert!(
        import.status.success(),
        "the installed interfaces do not import: {}",
        String::from_utf8_lossy(&import.stderr)
    );
    assert_eq!(
        String::from_utf8_lossy(&import.stdout).trim(),
        "3 array('I')"
    );
}
