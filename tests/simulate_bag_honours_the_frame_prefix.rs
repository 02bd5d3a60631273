//! `simulate --bag` records with the scene's `ros.frame_prefix` and
//! `ros.world_frame`, as `run` publishes them. The bag's chunks are uncompressed MCAP, so the CDR strings of
//! the frame and joint names are in the file as they are on the wire:
//! every node frame and the joint carry the prefix, the tilt transform
//! hangs from the scene's world frame.

#![cfg(feature = "ros")]

mod support;

use std::path::{Path, PathBuf};
use support::scene_files;

fn count(hay: &[u8], needle: &[u8]) -> usize {
    hay.windows(needle.len()).filter(|w| *w == needle).count()
}

/// The bag's one MCAP file.
fn mcap_bytes(dir: &Path) -> Vec<u8> {
    let file: PathBuf = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .find(|p| p.extension().is_some_and(|e| e == "mcap"))
        .unwrap_or_else(|| panic!("no .mcap in {}", dir.display()));
    std::fs::read(file).unwrap()
}

fn simulate_bag(scene: &Path, dir: &Path) {
    let (ok, _, err) = support::cli::run(&[
        "simulate",
        scene.to_str().unwrap(),
        "--duration",
        "0.01",
        "--quiet",
        "--bag",
        dir.to_str().unwrap(),
    ]);
    assert!(ok, "{err}");
}

#[test]
fn a_simulate_bag_carries_the_scenes_frame_prefix_and_world_frame() {
    let tmp = std::env::temp_dir().join(format!("annular_plate_bag_prefix_{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&tmp);
    std::fs::create_dir_all(&tmp).unwrap();
    let scene = tmp.join("prefixed.yaml");
    let text = scene_files::text("brake_bench.yaml");
    let text = text.replacen(
        "ros__parameters:\n",
        "ros__parameters:\n    ros.frame_prefix: left/\n    ros.world_frame: map\n",
        1,
    );
    assert!(
        text.contains("ros.frame_prefix: left/"),
        "the scene gained the keys"
    );
    std::fs::write(&scene, text).unwrap();

    let (prefixed, plain) = (tmp.join("prefixed_bag"), tmp.join("plain_bag"));
    simulate_bag(&scene, &prefixed);
    simulate_bag(&scene_files::path("brake_bench.yaml"), &plain);
    let (with, without) = (mcap_bytes(&prefixed), mcap_bytes(&plain));

    // A CDR string ends in NUL (the message definitions in the file mention
    // the frames in comments, not so terminated).
    for frame in [
        "plate_rotor",
        "plate_base",
        "plate_ale_1",
        "plate_lagrange_1",
        "plate_joint",
    ] {
        let all = count(&with, format!("{frame}\0").as_bytes());
        assert!(all > 0, "{frame} is in the bag");
        assert_eq!(
            count(&with, format!("left/{frame}\0").as_bytes()),
            all,
            "every {frame} carries the prefix"
        );
        assert_eq!(
            count(&without, format!("left/{frame}\0").as_bytes()),
            0,
            "no prefix without the key"
        );
        assert!(count(&without, format!("{frame}\0").as_bytes()) > 0);
    }
    // /tf_static: world frame -> plate_base.
    assert!(count(&with, b"map\0") >= 1, "the scene's world frame");
    assert_eq!(count(&without, b"map\0"), 0);
    assert!(count(&without, b"world\0") >= 1);
    std::fs::remove_dir_all(&tmp).unwrap();
}
