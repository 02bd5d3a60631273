//! `plate.theory` and `plate.shear_correction`: their defaults, their rules,
//! and the `supported_soft` edge that only Mindlin theory has.

use annular_plate::config::{Boundary, Config, ConfigError, PlateTheory};

const NODE: &str = "annular_plate";

fn config_with(body: &str) -> Result<Config, ConfigError> {
    let mut text = String::from("annular_plate:\n  ros__parameters:\n");
    for line in body.lines() {
        text.push_str("    ");
        text.push_str(line);
        text.push('\n');
    }
    Config::from_yaml_str(&text, NODE)
}

/// The message of the refusal of `body`, which must name every one of `keys`.
#[track_caller]
fn refused(body: &str, keys: &[&str]) -> String {
    let message = match config_with(body) {
        Ok(_) => panic!("accepted, but should be refused:\n{body}"),
        Err(e) => e.to_string(),
    };
    for key in keys {
        assert!(
            message.contains(key),
            "message does not name {key}: {message}"
        );
    }
    message
}

#[test]
fn kirchhoff_with_five_sixths_is_the_default() {
    let c = config_with("plate.thickness: 0.01").expect("accepted");
    assert_eq!(c.plate.theory, PlateTheory::Kirchhoff);
    assert_eq!(c.plate.shear_correction, 5.0 / 6.0);
}

#[test]
fn mindlin_takes_every_edge_including_the_soft_support() {
    for edge in Boundary::ALL {
        let c = config_with(&format!(
            "plate.theory: mindlin\nplate.inner_boundary: {}\nplate.outer_boundary: free\nplate.shear_correction: 1.0",
            edge.name()
        ))
        .unwrap_or_else(|e| panic!("{}: {e}", edge.name()));
        assert_eq!(c.plate.theory, PlateTheory::Mindlin);
        assert_eq!(c.plate.inner_boundary, edge);
        assert_eq!(c.plate.shear_correction, 1.0);
    }
}

#[test]
fn the_soft_support_under_kirchhoff_names_the_theory_and_the_edge_key() {
    for key in ["plate.inner_boundary", "plate.outer_boundary"] {
        refused(
            &format!("{key}: supported_soft"),
            &[key, "plate.theory", "supported_soft"],
        );
        refused(
            &format!("plate.theory: kirchhoff\n{key}: supported_soft"),
            &[key, "plate.theory"],
        );
    }
}

#[test]
fn an_unknown_theory_is_refused_with_the_choices() {
    let m = refused(
        "plate.theory: reissner",
        &["plate.theory", "kirchhoff", "mindlin"],
    );
    assert!(m.contains("reissner"), "{m}");
    refused("plate.theory: 3", &["plate.theory"]);
}

#[test]
fn the_shear_correction_must_lie_in_zero_to_one() {
    for bad in ["0.0", "-0.5", "1.5", ".nan", "2"] {
        refused(
            &format!("plate.theory: mindlin\nplate.shear_correction: {bad}"),
            &["plate.shear_correction"],
        );
    }
    for good in ["0.8224670334241132", "1.0", "0.5"] {
        config_with(&format!(
            "plate.theory: mindlin\nplate.shear_correction: {good}"
        ))
        .unwrap_or_else(|e| panic!("{good}: {e}"));
    }
}

/// The geometry note that a plate thicker than a quarter of its width is
/// outside Kirchhoff theory speaks of a Kirchhoff model: a Mindlin plate of
/// the same geometry does not get it.
#[test]
fn the_thick_plate_note_is_given_to_kirchhoff_plates_only() {
    let mut c = Config::default();
    c.plate.inner_radius = 0.07;
    c.plate.outer_radius = 0.153;
    c.plate.thickness = 0.03; // > (0.153 − 0.07) / 4
    let thick = |notes: Vec<String>| notes.iter().any(|n| n.contains("outside Kirchhoff"));
    assert!(thick(c.plate.geometry_notes()));
    c.plate.theory = PlateTheory::Mindlin;
    assert!(!thick(c.plate.geometry_notes()));
}
