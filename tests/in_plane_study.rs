//! `study` with in-plane modes (docs/study.md, "In-plane modes"): the
//! in-plane frequency axis against the exact plane-stress solution written
//! in `tests/support/in_plane_exact.rs` (its reference within its stated
//! uncertainty, its rows converging), and the trajectory axis measuring the
//! in-plane amplitudes on their own.

mod support;

use annular_plate::config::{InPlaneInner, InPlaneOuter, WrenchConfig};
use annular_plate::study::{self, StudyPlan};
use support::in_plane_exact::{Annulus, Edge, Family};

/// The study's default scene (the lathe disc, clamped hub, free rim) with
/// in-plane k = 0, 1, orders 0, 1, the hub fixed in-plane, and its rim force
/// turned partly tangential so the in-plane modes move.
fn scene() -> annular_plate::config::Config {
    let mut c = study::lathe_scene();
    c.plate.in_plane_nodal_diameters = vec![0, 1];
    c.plate.in_plane_orders = vec![0, 1];
    c.centrifugal.in_plane_inner = InPlaneInner::Fixed;
    c.centrifugal.in_plane_outer = InPlaneOuter::Free;
    c.loads.ale = vec![WrenchConfig {
        force: [0.0, 200.0, -100.0],
        moment: [0.0; 3],
    }];
    c
}

#[test]
fn the_in_plane_axis_converges_to_the_exact_plane_stress_frequencies() {
    let config = scene();
    let report = study::run(&config, "test", &StudyPlan::quick(), &mut |_, _, _| {}).unwrap();
    let axis = report.in_plane_radial_splines.expect("the in-plane axis");
    let p = &config.plate;
    let exact = Annulus {
        youngs_modulus: p.youngs_modulus,
        poisson_ratio: p.poisson_ratio,
        density: p.density,
        inner_radius: p.inner_radius,
        outer_radius: p.outer_radius,
        inner: Edge::Fixed,
        outer: Edge::Free,
    };
    // k = 0 torsional and radial, k = 1 coupled, orders 0 and 1.
    assert_eq!(axis.reference.frequencies_hz.len(), 6);
    let mut worst = 0.0f64;
    for (id, f) in &axis.reference.frequencies_hz {
        let family = match id.family {
            "torsional" => Family::Torsional,
            "radial" => Family::Radial,
            _ => Family::Coupled,
        };
        let f_exact = exact.roots(id.k, family, 2, 40)[id.l as usize] / std::f64::consts::TAU;
        let e = (f - f_exact).abs() / f_exact;
        println!("{id:?}: reference {f:.6} Hz, exact {f_exact:.6} Hz: {e:.2e}");
        worst = worst.max(e);
    }
    println!(
        "reference at {} splines, stated uncertainty {:.2e}, worst against exact {worst:.2e}",
        axis.reference.radial_splines, axis.reference.uncertainty
    );
    // The reference is within what it states (and round-off above it).
    assert!(worst <= axis.reference.uncertainty.max(1e-9), "{worst:e}");
    // Each fixed count's error against the reference, and against the
    // exact solution within the reference's uncertainty, falls with n.
    let fixed: Vec<_> = axis
        .rows
        .iter()
        .filter(|r| r.radial_splines != annular_plate::config::RadialSplines::Auto)
        .collect();
    for pair in fixed.windows(2) {
        println!(
            "{} splines: {:.2e}; {}: {:.2e}",
            pair[0].radial_splines,
            pair[0].max_relative_error,
            pair[1].radial_splines,
            pair[1].max_relative_error
        );
        assert!(pair[1].max_relative_error < pair[0].max_relative_error);
    }
    assert!(
        fixed[0].max_relative_error > 1e-6,
        "the coarsest count shows an error"
    );
    assert!(report
        .notes
        .iter()
        .any(|n| n.contains("in_plane_radial_splines")));
}

#[test]
fn the_trajectory_axis_measures_the_in_plane_amplitudes_on_their_own() {
    let config = scene();
    let report = study::run(&config, "test", &StudyPlan::quick(), &mut |_, _, _| {}).unwrap();
    let ok: Vec<_> = report
        .integrator
        .rows
        .iter()
        .filter(|r| r.relative_error.is_some())
        .collect();
    assert!(!ok.is_empty());
    for r in &ok {
        let e = r
            .in_plane_relative_error
            .expect("the in-plane amplitudes move");
        println!(
            "{} at {} Hz: all {:.2e}, in-plane {e:.2e}",
            r.integrator,
            r.rate_hz,
            r.relative_error.unwrap()
        );
        assert!(e.is_finite());
    }
    // The exponential integrator is exact for held loads: both errors at round-off.
    let exponential = ok.iter().find(|r| r.integrator == "exponential").unwrap();
    assert!(exponential.in_plane_relative_error.unwrap() < 1e-9);
    // The text report shows the in-plane axis and the rows' in-plane errors.
    let text = annular_plate::cli::study::table(&report);
    assert!(text.contains("1b. In-plane frequencies"), "{text}");
    assert!(text.contains("in-plane alone"), "{text}");
}
