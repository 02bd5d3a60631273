//! Every configuration rule rejects a bad value with the right error, whose
//! message names the offending key; and well-formed parameter files (the
//! DESIGN.md example, nested or dotted names, `/**` plus a node entry, `-p`
//! overrides) are accepted with the documented meaning.

use annular_plate::config::{
    Boundary, Config, ConfigError, Coordinates, Degeneracy, IntegratorKind, ParamValue, Params,
    PlateConfig,
};

const NODE: &str = "annular_plate";

fn example_path() -> std::path::PathBuf {
    std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("config/design_example.yaml")
}

fn example_text() -> String {
    std::fs::read_to_string(example_path()).expect("config/design_example.yaml is readable")
}

/// A parameter file for the node with `body` (one `key: value` per line,
/// dotted or nested) under `ros__parameters`.
fn file_with(body: &str) -> String {
    let mut text = String::from("annular_plate:\n  ros__parameters:\n");
    for line in body.lines() {
        text.push_str("    ");
        text.push_str(line);
        text.push('\n');
    }
    if body.trim().is_empty() {
        text = String::from("annular_plate:\n  ros__parameters: {}\n");
    }
    text
}

fn config_with(body: &str) -> Result<Config, ConfigError> {
    Config::from_yaml_str(&file_with(body), NODE)
}

/// The error for `body`; its message must name `key`.
#[track_caller]
fn rejected(body: &str, key: &str) -> ConfigError {
    let err = match config_with(body) {
        Ok(_) => panic!("accepted, but should be rejected:\n{body}"),
        Err(e) => e,
    };
    let message = err.to_string();
    assert!(
        message.contains(key),
        "message does not name {key}: {message}"
    );
    err
}

// ---- plate geometry and material --------------------------------------------

#[test]
fn inner_radius_must_be_positive() {
    let e = rejected("plate.inner_radius: -0.01", "plate.inner_radius");
    assert!(
        matches!(&e, ConfigError::NotPositive { key, value } if key == "plate.inner_radius" && *value == -0.01),
        "{e:?}"
    );
    assert!(e.to_string().contains("-0.01"));
}

#[test]
fn outer_radius_must_be_positive() {
    let e = rejected("plate.outer_radius: 0", "plate.outer_radius");
    assert!(
        matches!(&e, ConfigError::NotPositive { key, .. } if key == "plate.outer_radius"),
        "{e:?}"
    );
}

#[test]
fn inner_radius_must_be_below_outer() {
    let e = rejected(
        "plate.inner_radius: 0.2\nplate.outer_radius: 0.15",
        "plate.inner_radius",
    );
    assert!(
        matches!(e, ConfigError::InnerRadiusNotBelowOuter { inner, outer } if inner == 0.2 && outer == 0.15),
        "{e:?}"
    );
    assert!(e.to_string().contains("plate.outer_radius"));
    let e = rejected(
        "plate.inner_radius: 0.15\nplate.outer_radius: 0.15",
        "plate.inner_radius",
    );
    assert!(
        matches!(e, ConfigError::InnerRadiusNotBelowOuter { .. }),
        "{e:?}"
    );
}

#[test]
fn solid_circular_plate_is_rejected() {
    for inner in ["0", "1.0e-10"] {
        let e = rejected(
            &format!("plate.inner_radius: {inner}"),
            "plate.inner_radius",
        );
        assert!(
            matches!(
                e,
                ConfigError::DegenerateGeometry {
                    kind: Degeneracy::SolidCircularPlate,
                    ..
                }
            ),
            "{e:?}"
        );
        let message = e.to_string();
        assert!(
            message.contains("compatib") && message.contains("4.2"),
            "{message}"
        );
    }
    // Just above the limit is accepted, with a note.
    let c = config_with("plate.inner_radius: 2.0e-7\nplate.outer_radius: 0.15\nplate.inner_boundary: free\nplate.outer_boundary: clamped").unwrap();
    let notes = c.plate.geometry_notes();
    assert_eq!(notes.len(), 1, "{notes:?}");
    assert!(notes[0].contains("compatib"), "{notes:?}");
}

#[test]
fn very_narrow_ring_is_rejected() {
    let e = rejected(
        "plate.inner_radius: 0.14999\nplate.outer_radius: 0.15",
        "plate.inner_radius",
    );
    assert!(
        matches!(
            e,
            ConfigError::DegenerateGeometry {
                kind: Degeneracy::NarrowRing,
                ..
            }
        ),
        "{e:?}"
    );
    let message = e.to_string();
    assert!(
        message.contains("plate.outer_radius") && message.contains("infinity"),
        "{message}"
    );
}

#[test]
fn geometry_notes_explain_near_degenerate_geometry() {
    assert!(Config::default().plate.geometry_notes().is_empty());
    let narrow =
        config_with("plate.inner_radius: 0.148\nplate.outer_radius: 0.15\nplate.thickness: 0.0004")
            .unwrap();
    let notes = narrow.plate.geometry_notes();
    assert_eq!(notes.len(), 1, "{notes:?}");
    assert!(notes[0].contains("narrow"), "{notes:?}");
    // A small clamped hole is a point support, not a solid plate: noted as such.
    let clamped = config_with("plate.inner_radius: 0.001").unwrap();
    let notes = clamped.plate.geometry_notes();
    assert_eq!(notes.len(), 1, "{notes:?}");
    assert!(
        notes[0].contains("pinned") && notes[0].contains("not a solid"),
        "{notes:?}"
    );
    // A plate thicker than a quarter of its width is outside Kirchhoff theory: noted.
    let thick = config_with("plate.thickness: 0.03").unwrap();
    let notes = thick.plate.geometry_notes();
    assert!(
        notes.len() == 1 && notes[0].contains("Kirchhoff"),
        "{notes:?}"
    );
    let free = config_with(
        "plate.inner_radius: 0.001\nplate.inner_boundary: free\nplate.outer_boundary: clamped",
    )
    .unwrap();
    assert_eq!(free.plate.geometry_notes().len(), 1);
}

#[test]
fn thickness_density_and_youngs_modulus_must_be_positive() {
    for key in ["plate.thickness", "plate.density", "plate.youngs_modulus"] {
        let e = rejected(&format!("{key}: -1.0"), key);
        assert!(
            matches!(&e, ConfigError::NotPositive { key: k, value } if k == key && *value == -1.0),
            "{e:?}"
        );
        let e = rejected(&format!("{key}: 0"), key);
        assert!(
            matches!(&e, ConfigError::NotPositive { key: k, .. } if k == key),
            "{e:?}"
        );
    }
}

#[test]
fn shear_modulus_must_be_positive() {
    let e = rejected("plate.shear_modulus: 0.0", "plate.shear_modulus");
    assert!(
        matches!(&e, ConfigError::NotPositive { key, .. } if key == "plate.shear_modulus"),
        "{e:?}"
    );
}

#[test]
fn poisson_ratio_must_lie_in_open_interval() {
    for nu in ["0.5", "-1.0", "0.7", "-1.5"] {
        let e = rejected(&format!("plate.poisson_ratio: {nu}"), "plate.poisson_ratio");
        assert!(
            matches!(
                e,
                ConfigError::PoissonRatioOutOfRange {
                    from_shear_modulus: false,
                    ..
                }
            ),
            "{e:?}"
        );
        assert!(e.to_string().contains(nu.trim_end_matches(".0")), "{e}");
    }
    assert!(config_with("plate.poisson_ratio: 0.499").is_ok());
    assert!(config_with("plate.poisson_ratio: -0.999").is_ok());
}

#[test]
fn poisson_ratio_from_shear_modulus_must_lie_in_open_interval() {
    // G ≤ E/3 gives ν ≥ 0.5.
    let e = rejected(
        "plate.youngs_modulus: 2.4e11\nplate.shear_modulus: 6.0e10",
        "plate.shear_modulus",
    );
    assert!(
        matches!(e, ConfigError::PoissonRatioOutOfRange { from_shear_modulus: true, nu } if (nu - 1.0).abs() < 1e-12),
        "{e:?}"
    );
    assert!(e.to_string().contains("plate.youngs_modulus"));
}

#[test]
fn poisson_ratio_and_shear_modulus_are_exclusive() {
    let e = rejected(
        "plate.poisson_ratio: 0.3\nplate.shear_modulus: 8.0769e10",
        "plate.poisson_ratio",
    );
    assert!(
        matches!(e, ConfigError::PoissonAndShearModulus { .. }),
        "{e:?}"
    );
    assert!(e.to_string().contains("plate.shear_modulus"));
}

#[test]
fn poisson_ratio_is_computed_from_shear_modulus() {
    let c = config_with("plate.youngs_modulus: 2.0e11\nplate.shear_modulus: 8.0e10").unwrap();
    assert!(
        (c.plate.poisson_ratio - 0.25).abs() < 1e-14,
        "{}",
        c.plate.poisson_ratio
    );
    let c = config_with("").unwrap();
    assert_eq!(c.plate.poisson_ratio, 0.3);
}

#[test]
fn boundary_names_are_checked() {
    for key in ["plate.inner_boundary", "plate.outer_boundary"] {
        let e = rejected(&format!("{key}: simply_supported"), key);
        assert!(
            matches!(&e, ConfigError::UnknownBoundary { key: k, value } if k == key && value == "simply_supported"),
            "{e:?}"
        );
        let message = e.to_string();
        for name in ["free", "supported", "clamped"] {
            assert!(message.contains(name), "{message}");
        }
    }
    let c = config_with("plate.inner_boundary: supported\nplate.outer_boundary: clamped").unwrap();
    assert_eq!(
        (c.plate.inner_boundary, c.plate.outer_boundary),
        (Boundary::Supported, Boundary::Clamped)
    );
}

// ---- modal selection ---------------------------------------------------------

#[test]
fn nodal_lists_must_not_be_empty() {
    for key in ["plate.nodal_diameters", "plate.nodal_circles"] {
        let e = rejected(&format!("{key}: []"), key);
        assert!(
            matches!(&e, ConfigError::Empty { key: k } if k == key),
            "{e:?}"
        );
    }
}

#[test]
fn nodal_lists_must_not_be_negative() {
    for key in ["plate.nodal_diameters", "plate.nodal_circles"] {
        let e = rejected(&format!("{key}: [0, -1]"), key);
        assert!(
            matches!(&e, ConfigError::Negative { key: k, value } if k == key && *value == -1.0),
            "{e:?}"
        );
        assert!(e.to_string().contains("-1"));
    }
}

#[test]
fn nodal_lists_must_not_repeat() {
    for key in ["plate.nodal_diameters", "plate.nodal_circles"] {
        let e = rejected(&format!("{key}: [0, 1, 1]"), key);
        assert!(
            matches!(&e, ConfigError::Duplicate { key: k, value: 1 } if k == key),
            "{e:?}"
        );
    }
}

#[test]
fn nodal_numbers_have_upper_limits() {
    let e = rejected("plate.nodal_diameters: [201]", "plate.nodal_diameters");
    assert!(
        matches!(&e, ConfigError::AboveMaximum { max, .. } if *max == 200.0),
        "{e:?}"
    );
    assert!(config_with("plate.nodal_diameters: [200]").is_ok());
    let e = rejected(
        "plate.nodal_circles: [51]\nplate.radial_splines: 100",
        "plate.nodal_circles",
    );
    assert!(
        matches!(&e, ConfigError::AboveMaximum { max, .. } if *max == 50.0),
        "{e:?}"
    );
    assert!(config_with("plate.nodal_circles: [50]\nplate.radial_splines: 100").is_ok());
}

#[test]
fn radial_splines_must_resolve_highest_nodal_circle() {
    // clamped–clamped removes 4 B-splines; l up to 3 needs 3 + 4 free: 11 in total.
    let body =
        "plate.inner_boundary: clamped\nplate.outer_boundary: clamped\nplate.nodal_circles: [0, 3]";
    let e = rejected(
        &format!("{body}\nplate.radial_splines: 10"),
        "plate.radial_splines",
    );
    assert!(
        matches!(
            e,
            ConfigError::TooFewRadialSplines {
                splines: 10,
                needed: 11,
                ..
            }
        ),
        "{e:?}"
    );
    assert!(e.to_string().contains("11"));
    let c = config_with(&format!("{body}\nplate.radial_splines: 11")).unwrap();
    assert_eq!(c.plate.min_radial_splines(), 11);
    // free–free removes none; supported removes 1.
    let mut plate = PlateConfig::lathe_disc();
    plate.inner_boundary = Boundary::Free;
    plate.outer_boundary = Boundary::Free;
    plate.nodal_circles = vec![0];
    assert_eq!(plate.min_radial_splines(), 4);
    plate.inner_boundary = Boundary::Supported;
    assert_eq!(plate.min_radial_splines(), 5);
    assert_eq!(Boundary::Clamped.essential_conditions(), 2);
}

#[test]
fn radial_splines_have_bounds() {
    let e = rejected("plate.radial_splines: 401", "plate.radial_splines");
    assert!(matches!(e, ConfigError::AboveMaximum { .. }), "{e:?}");
    let e = rejected("plate.radial_splines: -3", "plate.radial_splines");
    assert!(matches!(e, ConfigError::Negative { .. }), "{e:?}");
    let e = rejected("plate.radial_splines: 24.5", "plate.radial_splines");
    assert!(matches!(e, ConfigError::WrongType { .. }), "{e:?}");
}

#[test]
fn damping_ratios_must_lie_in_unit_interval() {
    for (list, bad) in [("[-0.1]", "-0.1"), ("[0.1, 1.0]", "1")] {
        let e = rejected(
            &format!(
                "plate.damping: {list}\nplate.nodal_diameters: [0]\nplate.nodal_circles: [0, 1]"
            ),
            "plate.damping",
        );
        assert!(matches!(e, ConfigError::DampingOutOfRange { .. }), "{e:?}");
        assert!(e.to_string().contains(bad), "{e}");
    }
}

#[test]
fn damping_has_one_or_one_per_mode() {
    // Defaults: k = 0..7 (1 + 7·2 = 15 per circle), l = 0, 1: 30 modes.
    assert_eq!(Config::default().plate.mode_count(), 30);
    let e = rejected("plate.damping: [0.01, 0.02, 0.03]", "plate.damping");
    assert!(
        matches!(
            e,
            ConfigError::DampingLength {
                len: 3,
                n_modes: 30
            }
        ),
        "{e:?}"
    );
    assert!(e.to_string().contains("30"));
    let per_mode = format!("plate.damping: [{}]", ["0.01"; 30].join(", "));
    assert_eq!(config_with(&per_mode).unwrap().plate.damping.len(), 30);
    // free–free skips ⟨0,0⟩ (1) and ⟨1,0⟩ (2): (1 + 2 + 2)·2 − 3 = 7 modes.
    let free_free = "plate.inner_boundary: free\nplate.outer_boundary: free\nplate.nodal_diameters: [0, 1, 2]\nplate.nodal_circles: [0, 1]";
    let e = rejected(
        &format!("{free_free}\nplate.damping: [{}]", ["0.01"; 10].join(", ")),
        "plate.damping",
    );
    assert!(
        matches!(
            e,
            ConfigError::DampingLength {
                len: 10,
                n_modes: 7
            }
        ),
        "{e:?}"
    );
    let c = config_with(&format!(
        "{free_free}\nplate.damping: [{}]",
        ["0.01"; 7].join(", ")
    ))
    .unwrap();
    assert_eq!(c.plate.mode_count(), 7);
}

#[test]
fn a_selection_of_only_rigid_body_modes_is_rejected() {
    let body = "plate.inner_boundary: free\nplate.outer_boundary: free\nplate.nodal_diameters: [0, 1]\nplate.nodal_circles: [0]";
    let e = rejected(body, "plate.nodal_diameters");
    assert!(
        matches!(&e, ConfigError::NoElasticModes { skipped } if skipped == &vec![(0, 0), (1, 0)]),
        "{e:?}"
    );
}

// ---- nodes and loads ---------------------------------------------------------

#[test]
fn node_coordinates_must_lie_in_unit_interval() {
    for key in [
        "nodes.lagrange_radial",
        "nodes.lagrange_angular",
        "nodes.ale_radial",
        "nodes.ale_angular",
    ] {
        let other = if key.ends_with("radial") {
            key.replace("radial", "angular")
        } else {
            key.replace("angular", "radial")
        };
        let e = rejected(&format!("{key}: [0.5, 1.5]\n{other}: [0.5, 0.5]"), key);
        assert!(
            matches!(&e, ConfigError::NodeOutOfUnitInterval { key: k, index: 1, value } if k == key && *value == 1.5),
            "{e:?}"
        );
        assert!(e.to_string().contains("1.5"));
    }
    assert!(config_with("nodes.ale_radial: [0, 1]\nnodes.ale_angular: [1, 0.25]").is_ok());
}

#[test]
fn node_coordinate_pairs_must_have_equal_length() {
    let e = rejected(
        "nodes.lagrange_radial: [0.5, 1.0]\nnodes.lagrange_angular: [0.0]",
        "nodes.lagrange_radial",
    );
    assert!(
        matches!(
            e,
            ConfigError::LengthMismatch {
                len_a: 2,
                len_b: 1,
                ..
            }
        ),
        "{e:?}"
    );
    assert!(e.to_string().contains("nodes.lagrange_angular"));
    let e = rejected("nodes.ale_angular: [0.5]", "nodes.ale_angular");
    assert!(
        matches!(
            e,
            ConfigError::LengthMismatch {
                len_a: 0,
                len_b: 1,
                ..
            }
        ),
        "{e:?}"
    );
}

#[test]
fn wrenches_have_six_numbers_per_node() {
    let nodes = "nodes.ale_radial: [1.0, 0.5]\nnodes.ale_angular: [0.0, 0.5]";
    let e = rejected(
        &format!("{nodes}\nloads.ale_wrench: [0, 0, -100, 0, 0, 0]"),
        "loads.ale_wrench",
    );
    assert!(
        matches!(&e, ConfigError::WrenchLength { key, len: 6, nodes: 2 } if key == "loads.ale_wrench"),
        "{e:?}"
    );
    assert!(e.to_string().contains("12"));
    let e = rejected(
        "loads.lagrange_wrench: [0, 0, 1, 0, 0, 0]",
        "loads.lagrange_wrench",
    );
    assert!(
        matches!(e, ConfigError::WrenchLength { nodes: 0, .. }),
        "{e:?}"
    );
    let c = config_with(&format!(
        "{nodes}\nloads.ale_wrench: [0, 0, -100, 0, 0, 0, 1, 2, 3, 4, 5, 6]"
    ))
    .unwrap();
    assert_eq!(c.loads.ale.len(), 2);
    assert_eq!(c.loads.ale[0].force, [0.0, 0.0, -100.0]);
    assert_eq!(c.loads.ale[1].moment, [4.0, 5.0, 6.0]);
    // No wrench given: one zero wrench per node.
    let c = config_with(nodes).unwrap();
    assert_eq!(c.loads.ale, vec![Default::default(); 2]);
}

#[test]
fn wrenches_must_be_finite() {
    let body = "nodes.ale_radial: [1.0]\nnodes.ale_angular: [0.0]\nloads.ale_wrench: [0, 0, .nan, 0, 0, 0]";
    let e = rejected(body, "loads.ale_wrench");
    assert!(
        matches!(&e, ConfigError::NonFinite { key } if key == "loads.ale_wrench[2]"),
        "{e:?}"
    );
}

#[test]
fn wrenches_must_respect_limits() {
    let body = "nodes.lagrange_radial: [1.0]\nnodes.lagrange_angular: [0.0]\nlimits.max_force: 1000\nloads.lagrange_wrench: [0, 0, -2000, 0, 0, 0]";
    let e = rejected(body, "loads.lagrange_wrench");
    assert!(
        matches!(e, ConfigError::WrenchAboveLimit { what: "force", .. }),
        "{e:?}"
    );
    assert!(e.to_string().contains("limits.max_force"));
}

#[test]
fn follower_is_a_bool() {
    let e = rejected("loads.follower: 1", "loads.follower");
    assert!(matches!(e, ConfigError::WrongType { .. }), "{e:?}");
    assert!(config_with("loads.follower: true").unwrap().loads.follower);
}

// ---- joint, reference, gravity -----------------------------------------------

#[test]
fn joint_speed_is_limited() {
    let e = rejected(
        "joint.speed: -200.0\nlimits.max_speed: 100.0",
        "joint.speed",
    );
    assert!(
        matches!(e, ConfigError::SpeedAboveLimit { speed, max_speed } if speed == -200.0 && max_speed == 100.0),
        "{e:?}"
    );
    assert!(e.to_string().contains("limits.max_speed"));
    let e = rejected("joint.speed: .inf", "joint.speed");
    assert!(
        matches!(&e, ConfigError::NonFinite { key } if key == "joint.speed"),
        "{e:?}"
    );
}

#[test]
fn joint_limits_must_be_positive() {
    for key in ["joint.max_acceleration", "joint.max_torque"] {
        let e = rejected(&format!("{key}: 0"), key);
        assert!(
            matches!(&e, ConfigError::NotPositive { key: k, .. } if k == key),
            "{e:?}"
        );
    }
    assert_eq!(Config::default().joint.max_torque, None);
    assert_eq!(
        config_with("joint.max_torque: 5").unwrap().joint.max_torque,
        Some(5.0)
    );
}

#[test]
fn joint_initial_position_must_be_finite() {
    let e = rejected("joint.initial_position: .nan", "joint.initial_position");
    assert!(matches!(e, ConfigError::NonFinite { .. }), "{e:?}");
}

#[test]
fn tilt_must_be_below_right_angle() {
    let e = rejected("reference.tilt: 1.6", "reference.tilt");
    assert!(
        matches!(e, ConfigError::TiltOutOfRange { tilt } if tilt == 1.6),
        "{e:?}"
    );
    let e = rejected("reference.tilt: -1.5707963267948966", "reference.tilt");
    assert!(matches!(e, ConfigError::TiltOutOfRange { .. }), "{e:?}");
    assert!(config_with("reference.tilt: -1.5").is_ok());
}

#[test]
fn vectors_have_three_finite_components() {
    for key in [
        "reference.angular_velocity",
        "reference.acceleration",
        "gravity",
    ] {
        let e = rejected(&format!("{key}: [0.0, -9.81]"), key);
        assert!(
            matches!(&e, ConfigError::WrongLength { key: k, len: 2, expected: 3 } if k == key),
            "{e:?}"
        );
        let e = rejected(&format!("{key}: [0.0, .inf, 0.0]"), key);
        assert!(
            matches!(&e, ConfigError::NonFinite { key: k } if k == &format!("{key}[1]")),
            "{e:?}"
        );
    }
    assert_eq!(
        config_with("gravity: [0, 0, -9.81]").unwrap().gravity,
        [0.0, 0.0, -9.81]
    );
}

// ---- simulation and limits ---------------------------------------------------

#[test]
fn rate_must_be_positive_and_bounded() {
    let e = rejected("simulation.rate_hz: 0", "simulation.rate_hz");
    assert!(matches!(e, ConfigError::NotPositive { .. }), "{e:?}");
    let e = rejected("simulation.rate_hz: 2.0e6", "simulation.rate_hz");
    assert!(matches!(e, ConfigError::AboveMaximum { .. }), "{e:?}");
}

#[test]
fn substeps_lie_between_1_and_10000() {
    let e = rejected("simulation.substeps: 0", "simulation.substeps");
    assert!(matches!(e, ConfigError::NotPositive { .. }), "{e:?}");
    let e = rejected("simulation.substeps: 10001", "simulation.substeps");
    assert!(matches!(e, ConfigError::AboveMaximum { .. }), "{e:?}");
    assert_eq!(
        config_with("simulation.substeps: 10000")
            .unwrap()
            .simulation
            .substeps,
        10000
    );
}

#[test]
fn integrator_and_coordinates_names_are_checked() {
    let e = rejected("simulation.integrator: euler", "simulation.integrator");
    assert!(
        matches!(&e, ConfigError::UnknownChoice { value, .. } if value == "euler"),
        "{e:?}"
    );
    let message = e.to_string();
    for name in ["exponential", "implicit_midpoint", "rk4"] {
        assert!(message.contains(name), "{message}");
    }
    let e = rejected("simulation.coordinates: eulerian", "simulation.coordinates");
    assert!(matches!(e, ConfigError::UnknownChoice { .. }), "{e:?}");
    assert!(e.to_string().contains("lagrangian"));
    let c = config_with("simulation.integrator: rk4\nsimulation.coordinates: lagrangian").unwrap();
    assert_eq!(
        (c.simulation.integrator, c.simulation.coordinates),
        (IntegratorKind::Rk4, Coordinates::Lagrangian)
    );
}

#[test]
fn realtime_factor_and_publish_divisor() {
    let e = rejected(
        "simulation.realtime_factor: -1",
        "simulation.realtime_factor",
    );
    assert!(matches!(e, ConfigError::Negative { .. }), "{e:?}");
    assert_eq!(
        config_with("simulation.realtime_factor: 0")
            .unwrap()
            .simulation
            .realtime_factor,
        0.0
    );
    let e = rejected(
        "simulation.publish_divisor: 0",
        "simulation.publish_divisor",
    );
    assert!(matches!(e, ConfigError::NotPositive { .. }), "{e:?}");
}

#[test]
fn limits_must_be_positive() {
    for key in [
        "limits.max_force",
        "limits.max_moment",
        "limits.max_speed",
        "limits.max_deflection_thicknesses",
    ] {
        let e = rejected(&format!("{key}: -5"), key);
        assert!(
            matches!(&e, ConfigError::NotPositive { key: k, value } if k == key && *value == -5.0),
            "{e:?}"
        );
    }
}

#[test]
fn doubles_must_be_finite() {
    let e = rejected("plate.thickness: .nan", "plate.thickness");
    assert!(
        matches!(&e, ConfigError::NonFinite { key } if key == "plate.thickness"),
        "{e:?}"
    );
    let e = rejected("plate.damping: [.inf]", "plate.damping");
    assert!(
        matches!(&e, ConfigError::NonFinite { key } if key == "plate.damping[0]"),
        "{e:?}"
    );
}

// ---- names and types ---------------------------------------------------------

#[test]
fn unknown_keys_are_rejected_with_a_suggestion() {
    let e = rejected("plate.inner_raduis: 0.05", "plate.inner_raduis");
    assert!(
        matches!(&e, ConfigError::UnknownKey { suggestion: Some(s), .. } if s == "plate.inner_radius"),
        "{e:?}"
    );
    assert!(e.to_string().contains("plate.inner_radius"));
    // Nested form too.
    let e = rejected("plate:\n  thicknes: 0.01", "plate.thicknes");
    assert!(
        matches!(&e, ConfigError::UnknownKey { suggestion: Some(s), .. } if s == "plate.thickness"),
        "{e:?}"
    );
    let e = rejected("simulation.speed: 1.0", "simulation.speed");
    assert!(
        matches!(&e, ConfigError::UnknownKey { suggestion: Some(s), .. } if s == "joint.speed"),
        "{e:?}"
    );
    let e = rejected("weather.cloudiness: 0.5", "weather.cloudiness");
    assert!(
        matches!(
            e,
            ConfigError::UnknownKey {
                suggestion: None,
                ..
            }
        ),
        "{e:?}"
    );
}

#[test]
fn wrong_types_are_rejected() {
    let e = rejected("plate.thickness: thin", "plate.thickness");
    assert!(
        matches!(&e, ConfigError::WrongType { found, .. } if found.contains("thin")),
        "{e:?}"
    );
    let e = rejected("plate.nodal_diameters: [0.5, 1.5]", "plate.nodal_diameters");
    assert!(matches!(e, ConfigError::WrongType { .. }), "{e:?}");
    let e = rejected("plate.inner_boundary: [clamped]", "plate.inner_boundary");
    assert!(matches!(e, ConfigError::WrongType { .. }), "{e:?}");
    let e = rejected("gravity: 9.81", "gravity");
    assert!(matches!(e, ConfigError::WrongType { .. }), "{e:?}");
}

#[test]
fn nested_lists_are_rejected() {
    let e = rejected("nodes.ale_radial: [[1.0, 0.0]]", "nodes.ale_radial");
    assert!(
        matches!(&e, ConfigError::NestedList { key } if key == "nodes.ale_radial"),
        "{e:?}"
    );
    let e = rejected("loads:\n  ale_wrench: [{fx: 1}]", "loads.ale_wrench");
    assert!(matches!(e, ConfigError::NestedList { .. }), "{e:?}");
}

#[test]
fn mixed_lists_and_null_values_are_rejected() {
    let e = rejected("plate.damping: [0.1, fast]", "plate.damping");
    assert!(matches!(e, ConfigError::MixedList { .. }), "{e:?}");
    let e = rejected("plate.thickness:", "plate.thickness");
    assert!(matches!(e, ConfigError::MissingValue { .. }), "{e:?}");
}

#[test]
fn a_key_given_nested_and_dotted_is_rejected() {
    let e = rejected(
        "plate:\n  thickness: 0.01\nplate.thickness: 0.02",
        "plate.thickness",
    );
    assert!(matches!(e, ConfigError::DuplicateKey { .. }), "{e:?}");
}

#[test]
fn a_file_without_entry_for_the_node_is_rejected() {
    let text = "other_node:\n  ros__parameters:\n    plate.thickness: 0.01\n/ns/third:\n  ros__parameters: {}\n";
    let e = Config::from_yaml_str(text, NODE).unwrap_err();
    assert!(
        matches!(&e, ConfigError::NoEntryForNode { node, found } if node == NODE && found.len() == 2),
        "{e:?}"
    );
    let message = e.to_string();
    assert!(
        message.contains(NODE) && message.contains("other_node") && message.contains("/ns/third"),
        "{message}"
    );
}

#[test]
fn an_entry_without_ros_parameters_is_rejected() {
    let e = Config::from_yaml_str("annular_plate:\n  plate.thickness: 0.01\n", NODE).unwrap_err();
    assert!(matches!(e, ConfigError::UnexpectedEntryKey { .. }), "{e:?}");
    assert!(e.to_string().contains("ros__parameters"));
    let e = Config::from_yaml_str("annular_plate: 3\n", NODE).unwrap_err();
    assert!(
        matches!(e, ConfigError::MissingRosParameters { .. }),
        "{e:?}"
    );
}

#[test]
fn invalid_yaml_and_missing_files_are_reported() {
    let e = Config::from_yaml_str("annular_plate: [unclosed\n", NODE).unwrap_err();
    assert!(matches!(e, ConfigError::Yaml { .. }), "{e:?}");
    let path = std::path::Path::new("/nonexistent/params.yaml");
    let e = Config::from_params_file(path, NODE).unwrap_err();
    assert!(matches!(e, ConfigError::Io { .. }), "{e:?}");
    assert!(e.to_string().contains("/nonexistent/params.yaml"));
}

// ---- accepted files ----------------------------------------------------------

#[test]
fn design_example_parses_with_shear_modulus() {
    let c = Config::from_params_file(&example_path(), NODE).unwrap();
    assert!(
        (c.plate.poisson_ratio - 0.3).abs() < 1e-4,
        "{}",
        c.plate.poisson_ratio
    );
    assert_eq!(c.plate.inner_radius, 0.075);
    assert_eq!(c.plate.outer_radius, 0.15);
    assert_eq!(c.plate.nodal_diameters, (0..=7).collect::<Vec<u32>>());
    assert_eq!(c.plate.nodal_circles, vec![0, 1]);
    assert_eq!(c.plate.damping, vec![0.02]);
    assert_eq!(c.nodes.ale.len(), 1);
    assert_eq!(c.nodes.lagrange[0].radial, 1.0);
    assert_eq!(c.loads.ale[0].force, [0.0, 0.0, -100.0]);
    assert_eq!(c.joint.speed, 11.1);
    assert_eq!(c.simulation.rate_hz, 1000.0);
    assert!(c.plate.geometry_notes().is_empty());
}

#[test]
fn design_example_parses_with_poisson_ratio() {
    let text = example_text().replace("shear_modulus: 8.0769e10", "poisson_ratio: 0.3");
    assert!(text.contains("poisson_ratio: 0.3"));
    let c = Config::from_yaml_str(&text, NODE).unwrap();
    assert_eq!(c.plate.poisson_ratio, 0.3);
    let from_g = Config::from_yaml_str(&example_text(), NODE).unwrap();
    let mut c2 = c.clone();
    c2.plate.poisson_ratio = from_g.plate.poisson_ratio;
    assert_eq!(c2, from_g);
}

#[test]
fn design_example_entries_match_node_names_as_rclcpp_does() {
    let text = example_text();
    let plain = Config::from_yaml_str(&text, NODE).unwrap();
    // `annular_plate:` is `/annular_plate` (rcl's parser adds the root slash).
    assert_eq!(
        Config::from_yaml_str(&text, "/annular_plate").unwrap(),
        plain
    );
    let e = Config::from_yaml_str(&text, "/bench/annular_plate").unwrap_err();
    assert!(
        matches!(e, ConfigError::NoEntryForNode { .. }),
        "a root-namespace entry is not a namespaced node's: {e:?}"
    );
    // A fully qualified entry, or a wildcard, reaches the namespaced node.
    for entry in [
        "/bench/annular_plate",
        "/**/annular_plate",
        "/bench/*",
        "/**",
    ] {
        let t = text.replacen("annular_plate:", &format!("{entry}:"), 1);
        assert_eq!(
            Config::from_yaml_str(&t, "/bench/annular_plate").unwrap(),
            plain,
            "{entry}"
        );
    }
    let other_ns = text.replacen("annular_plate:", "/other/annular_plate:", 1);
    let e = Config::from_yaml_str(&other_ns, "/bench/annular_plate").unwrap_err();
    assert!(matches!(e, ConfigError::NoEntryForNode { .. }), "{e:?}");
}

#[test]
fn nested_and_dotted_names_give_equal_configs() {
    let nested = file_with(
        "plate:\n  inner_radius: 0.05\n  thickness: 0.004\n  nodal_circles: [0, 2]\nsimulation:\n  integrator: implicit_midpoint\njoint:\n  speed: 3.0",
    );
    let dotted = file_with(
        "plate.inner_radius: 0.05\nplate.thickness: 0.004\nplate.nodal_circles: [0, 2]\nsimulation.integrator: implicit_midpoint\njoint.speed: 3.0",
    );
    let mixed = file_with("plate:\n  inner_radius: 0.05\n  thickness: 0.004\nplate.nodal_circles: [0, 2]\nsimulation.integrator: implicit_midpoint\njoint:\n  speed: 3.0");
    let a = Config::from_yaml_str(&nested, NODE).unwrap();
    let b = Config::from_yaml_str(&dotted, NODE).unwrap();
    let c = Config::from_yaml_str(&mixed, NODE).unwrap();
    assert_eq!(a, b);
    assert_eq!(a, c);
    assert_eq!(a.plate.inner_radius, 0.05);
    assert_ne!(a, Config::default());
}

#[test]
fn wildcard_entry_merges_with_node_entry_and_node_wins() {
    let text = "\
annular_plate:
  ros__parameters:
    plate:
      thickness: 0.02
/**:
  ros__parameters:
    plate:
      thickness: 0.005
      density: 2700.0
    use_sim_time: true
";
    let c = Config::from_yaml_str(text, NODE).unwrap();
    assert_eq!(
        c.plate.thickness, 0.02,
        "node entry wins over /** regardless of order"
    );
    assert_eq!(
        c.plate.density, 2700.0,
        "/** applies where the node entry is silent"
    );
    // /** alone applies to any node.
    let only_wildcard = "/**:\n  ros__parameters:\n    plate.density: 2700.0\n";
    assert_eq!(
        Config::from_yaml_str(only_wildcard, "/ns/whatever")
            .unwrap()
            .plate
            .density,
        2700.0
    );
    let params = Params::from_yaml_str(text, NODE).unwrap();
    assert_eq!(
        params.get("plate.thickness"),
        Some(&ParamValue::Double(0.02))
    );
    assert_eq!(params.get("use_sim_time"), Some(&ParamValue::Bool(true)));
}

#[test]
fn command_line_overrides_win() {
    let mut params = Params::from_file(&example_path(), NODE).unwrap();
    params.set_override("plate.thickness", "0.02").unwrap();
    params
        .set_override("plate.outer_boundary", "supported")
        .unwrap();
    params
        .set_override("plate.nodal_diameters", "[0, 2, 4]")
        .unwrap();
    params.set_override("joint.speed", "-5").unwrap();
    params.set_override("loads.follower", "true").unwrap();
    let c = Config::from_params(&params).unwrap();
    assert_eq!(c.plate.thickness, 0.02);
    assert_eq!(c.plate.outer_boundary, Boundary::Supported);
    assert_eq!(c.plate.nodal_diameters, vec![0, 2, 4]);
    assert_eq!(c.joint.speed, -5.0);
    assert!(c.loads.follower);
    // An override is checked like the file.
    params.set_override("plate.thicknes", "0.02").unwrap();
    let e = Config::from_params(&params).unwrap_err();
    assert!(matches!(e, ConfigError::UnknownKey { .. }), "{e:?}");
    let mut params = Params::new();
    let e = params.set_override("plate.damping", "[[0.1]]").unwrap_err();
    assert!(matches!(e, ConfigError::NestedList { .. }), "{e:?}");
    let e = params.set_override("plate.damping", "{a: 1}").unwrap_err();
    assert!(matches!(e, ConfigError::BadOverride { .. }), "{e:?}");
    assert!(e.to_string().contains("plate.damping"));
    let e = params.set_override("plate..damping", "0.1").unwrap_err();
    assert!(matches!(e, ConfigError::BadParameterName { .. }), "{e:?}");
}

#[test]
fn integers_are_accepted_for_doubles() {
    let c = config_with(
        "plate.density: 7850\nplate.youngs_modulus: 210000000000\nplate.damping: [0]\ngravity: [0, 0, -9]\njoint.speed: 10\nnodes.ale_radial: [1, 0.5]\nnodes.ale_angular: [0, 0]",
    )
    .unwrap();
    assert_eq!(c.plate.density, 7850.0);
    assert_eq!(c.plate.youngs_modulus, 2.1e11);
    assert_eq!(c.plate.damping, vec![0.0]);
    assert_eq!(c.gravity, [0.0, 0.0, -9.0]);
    assert_eq!(c.joint.speed, 10.0);
    assert_eq!(c.nodes.ale[0].radial, 1.0);
}

#[test]
fn empty_list_is_accepted_as_any_array() {
    let c =
        config_with("nodes.ale_radial: []\nnodes.ale_angular: []\nloads.ale_wrench: []").unwrap();
    assert!(c.nodes.ale.is_empty());
    assert!(c.loads.ale.is_empty());
}

#[test]
fn defaults_equal_an_empty_parameter_set() {
    let empty = Config::from_yaml_str("annular_plate:\n  ros__parameters: {}\n", NODE).unwrap();
    assert_eq!(empty, Config::default());
    assert_eq!(
        Config::from_params(&Params::new()).unwrap(),
        Config::default()
    );
    assert_eq!(Config::default().plate, PlateConfig::lathe_disc());
}

#[test]
fn every_known_key_is_documented() {
    let doc =
        std::fs::read_to_string(std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("README.md"))
            .expect("README.md is readable");
    for key in Config::known_keys() {
        assert!(
            doc.contains(&format!("`{key}`")),
            "the README parameter reference does not document `{key}`"
        );
    }
}
