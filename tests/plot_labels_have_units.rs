//! Every column a `simulate` CSV can hold has a unit, and `plot csv`'s axis
//! labels carry them for the scene columns too (pads, tool, drive
//! effort).

mod support;

use annular_plate::cli::plot::auto_ylabel;
use annular_plate::cli::simulate::column_unit;
use support::scene_files;

fn names(list: &[&str]) -> Vec<String> {
    list.iter().map(|s| s.to_string()).collect()
}

#[test]
fn every_column_of_every_shipped_scene_has_a_unit() {
    for file in [
        "brake_bench.yaml",
        "brake_squeal.yaml",
        "brake_squeal_paper.yaml",
        "design_example.yaml",
        "lathe.yaml",
        "swash_plate.yaml",
    ] {
        let scene = scene_files::path(file);
        let (ok, text, err) = support::cli::run(&[
            "simulate",
            scene.to_str().unwrap(),
            "--duration",
            "0",
            "--csv",
            "-",
            "--quiet",
        ]);
        assert!(ok, "{file}: {err}");
        let header = text.lines().next().unwrap();
        for column in header.split(',') {
            assert!(
                column_unit(column).is_some(),
                "{file}: column {column} has no unit"
            );
        }
    }
}

#[test]
fn scene_columns_are_labelled_with_their_units() {
    assert_eq!(
        auto_ylabel(&names(&["pad1_normal_force", "pad1_clamp_force"])),
        "pad1_normal_force, pad1_clamp_force (N)"
    );
    assert_eq!(
        auto_ylabel(&names(&["pad1_friction_torque", "joint_effort"])),
        "pad1_friction_torque, joint_effort (N·m)"
    );
    assert_eq!(
        auto_ylabel(&names(&["joint_effort", "pad1_normal_force"])),
        "joint_effort (N·m), pad1_normal_force (N)"
    );
    assert_eq!(
        auto_ylabel(&names(&["tool_tip_z", "tool_chip_thickness"])),
        "tool_tip_z, tool_chip_thickness (m)"
    );
    assert_eq!(
        auto_ylabel(&names(&["tool_feed_force"])),
        "tool_feed_force (N)"
    );
    assert_eq!(
        auto_ylabel(&names(&["qale2"])),
        "ALE modal amplitude (m)",
        "the named labels stay"
    );
    assert_eq!(
        auto_ylabel(&names(&["my_column", "tool_feed_force"])),
        "my_column, tool_feed_force (N)",
        "a foreign column stays bare"
    );
    assert_eq!(column_unit("pad"), None);
    assert_eq!(column_unit("q"), None);
    assert_eq!(column_unit("padx_normal_force"), None);
}
