//! The physics library (`config`, `model`, `dynamics`, `study`) without the
//! default features pulls in none of the ROS, async, plotting or command-line
//! crates. That it compiles so, warning-free, is a gate of `.ci/run` (clippy
//! on `--no-default-features --lib`, sharing the gates' build), not a nested
//! cargo build here.

use std::process::Command;

fn cargo(args: &[&str]) -> String {
    let out = Command::new(env!("CARGO"))
        .args(args)
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .expect("cargo runs");
    assert!(
        out.status.success(),
        "cargo {}: {}",
        args.join(" "),
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8(out.stdout).unwrap()
}

#[test]
fn the_library_without_default_features_has_no_ros_plotting_or_cli_crates() {
    let tree = cargo(&[
        "tree",
        "--locked",
        "--no-default-features",
        "-e",
        "normal",
        "--prefix",
        "none",
        "--format",
        "{p}",
    ]);
    let crates: Vec<&str> = tree
        .lines()
        .filter_map(|l| l.split_whitespace().next())
        .collect();
    assert!(
        crates.contains(&"faer") && crates.contains(&"nalgebra"),
        "the tree was read: {crates:?}"
    );
    for forbidden in [
        "ros2-client",
        "rustdds",
        "tokio",
        "futures",
        "mcap",
        "plotters",
        "clap",
        "indicatif",
        "anyhow",
        "image",
    ] {
        assert!(
            !crates.contains(&forbidden),
            "the physics library depends on {forbidden}"
        );
    }
    // With the default features the same query lists them: the check can fail.
    let full = cargo(&[
        "tree", "--locked", "-e", "normal", "--prefix", "none", "--format", "{p}",
    ]);
    assert!(
        full.lines().any(|l| l.starts_with("plotters "))
            && full.lines().any(|l| l.starts_with("ros2-client "))
    );
}
