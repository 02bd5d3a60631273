//! `study` with in-plane modes (docs/study.md, "In-plane modes"): the
//! in-plane frequency axis against the exact plane-stress solution written
//! in `tests/support/in_plane_exact.rs` (its reference within its stated
//! uncertainty, its rows converging), and the trajectory axis measuring the
//! in-plane amplitudes on their own.

mod support;

use annular_plate::config::{InPlaneInner, InPlaneOuter, WrenchConfig};
use annular_plate::study::{self, StudyPlan};
use std::sync::OnceLock;
use support::in_plane_exact::{Annulus, Edge, Family};
use support::in_plane_static::InPlaneStatic;
use support::mindlin_static::Patch;

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

/// The quick study of [`scene`], run once for all the tests of this file.
fn report() -> &'static study::StudyReport {
    static REPORT: OnceLock<study::StudyReport> = OnceLock::new();
    REPORT.get_or_init(|| {
        let started = std::time::Instant::now();
        // The time from the in-plane response axis' first unit to the next axis'.
        let (mut axis_start, mut axis_time) = (None, 0.0);
        let r = study::run(&scene(), "test", &StudyPlan::quick(), &mut |_, _, what| {
            let in_axis =
                what.starts_with("in-plane reference k") || what.starts_with("in-plane orders");
            match (in_axis, axis_start) {
                (true, None) => axis_start = Some(std::time::Instant::now()),
                (false, Some(t)) => {
                    axis_time = t.elapsed().as_secs_f64();
                    axis_start = None;
                }
                _ => {}
            }
        })
        .unwrap();
        println!(
            "quick study: {:.1} s, of which the in-plane response axis {axis_time:.1} s",
            started.elapsed().as_secs_f64()
        );
        r
    })
}

#[test]
fn the_in_plane_axis_converges_to_the_exact_plane_stress_frequencies() {
    let config = scene();
    let report = report();
    let axis = report
        .in_plane_radial_splines
        .as_ref()
        .expect("the in-plane axis");
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
    let report = report();
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
    let text = annular_plate::cli::study::table(report);
    assert!(text.contains("1b. In-plane frequencies"), "{text}");
    assert!(text.contains("in-plane alone"), "{text}");
}

/// The exact patch compliance (row ū_r, ū_θ at the read patch; column F_r,
/// F_θ on the load patch) of the scene's plate, both patches at the rim node.
fn exact_rim_compliance(config: &annular_plate::config::Config) -> [[f64; 2]; 2] {
    let p = &config.plate;
    let (ri, ra, c) = (
        p.inner_radius,
        p.outer_radius,
        p.residual_patch_half_width(),
    );
    let exact = InPlaneStatic::new(
        p.youngs_modulus,
        p.poisson_ratio,
        p.thickness,
        ri,
        ra,
        Edge::Fixed,
        Edge::Free,
    );
    let patch = Patch::new(ri, ra, ra, c);
    let (sums, k_used, backward) = exact.series(&patch, &[(patch, 0.0)], 1e-6, 3000);
    println!("exact series: {k_used} harmonics");
    assert!(k_used < 3000, "exact series not converged");
    assert!(backward < 1e-12, "backward error {backward:e}");
    sums[0]
}

#[test]
fn the_in_plane_response_axis_meets_the_exact_plane_stress_statics() {
    let config = scene();
    let axis = report()
        .in_plane_mode_count
        .as_ref()
        .expect("the in-plane response axis");
    let started = std::time::Instant::now();
    let g = exact_rim_compliance(&config);
    println!("exact statics: {:.1} s", started.elapsed().as_secs_f64());
    // The rim force (0, 200) N at θ = 0 is tangential: (F_r, F_θ) = (0, 200).
    assert_eq!(axis.load_case.loads.len(), 1);
    let f = axis.load_case.loads[0].1;
    assert!(f[0].abs() < 1e-12 && (f[1] - 200.0).abs() < 1e-12, "{f:?}");
    let exact = [g[0][1] * f[1], g[1][1] * f[1]];
    let rel = |u: [f64; 2]| (u[0] - exact[0]).hypot(u[1] - exact[1]) / exact[0].hypot(exact[1]);
    let r = &axis.reference;
    let (e_ref, e_ref_residual) = (rel(r.response_m), rel(r.response_with_residual_m));
    println!(
        "exact (u_r, u_θ) = ({:.9e}, {:.9e}) m; reference k ≤ {}, l ≤ {}: ({:.9e}, {:.9e}) m, {e_ref:.2e} off, stated {:.2e} ({}); with its residual {e_ref_residual:.2e} off, stated {:.2e}",
        exact[0], exact[1], r.k_max, r.l_max, r.response_m[0], r.response_m[1],
        r.uncertainty, r.uncertainty_method, r.uncertainty_with_residual
    );
    // The reference is within what it states, and states something.
    assert!(e_ref <= r.uncertainty, "{e_ref:e} > {:e}", r.uncertainty);
    assert!(e_ref_residual <= r.uncertainty_with_residual);
    // … and is not far above the error it bounds: a difference of two levels
    // (halved) of a sequence converging with order p ≤ 4 is (2^p − 1) times
    // the finer level's error, times the safety factor 1.25: below 20 times.
    assert!(r.uncertainty < 20.0 * e_ref, "{:e}", r.uncertainty);
    assert!(
        r.uncertainty_with_residual < 20.0 * e_ref_residual,
        "{:e}",
        r.uncertainty_with_residual
    );
    let mut last = f64::INFINITY;
    for row in &axis.rows {
        let exact_error = rel(row.response_with_residual_m);
        println!(
            "l ≤ {} ({} modes): without residual {:.2e}, with {:.2e} (against the exact statics {exact_error:.2e}); step {:?} s, with residual {:?} s",
            row.l_max, row.modes, row.relative_error, row.relative_error_with_residual,
            row.step_time_s, row.step_time_with_residual_s
        );
        // The modes alone fall with l; with the residual they are far closer.
        assert!(
            row.relative_error < last,
            "{:e} after {last:e}",
            row.relative_error
        );
        last = row.relative_error;
        assert!(
            row.relative_error > 1e-2,
            "the scene's k = 0, 1 alone miss k ≥ 2"
        );
        assert!(row.relative_error_with_residual < 1e-6 * row.relative_error);
        assert!(exact_error < 1e-4, "{exact_error:e}");
        assert!(row.step_time_s.is_some() && row.step_time_with_residual_s.is_some());
    }
    assert_eq!(axis.rows.len(), 3);
    // The scene spins: the axis says its response is the one at rest.
    assert!(
        axis.notes.iter().any(|n| n.contains("at rest")),
        "{:?}",
        axis.notes
    );
    let text = annular_plate::cli::study::table(report());
    assert!(text.contains("2b. In-plane static displacement"), "{text}");
    // The recommendations take the residual for every target it meets.
    for rec in &axis.recommendations {
        if let Some(s) = &rec.setting {
            println!(
                "target {:.0e}: l ≤ {}, residual {}",
                rec.target, s.l_max, s.residual_flexibility
            );
        }
    }
}

#[test]
fn the_in_plane_response_axis_is_absent_without_an_in_plane_force() {
    let mut config = scene();
    config.loads.ale[0].force = [0.0, 0.0, -100.0];
    let mut notes = Vec::new();
    let axis = study::in_plane_response::run(&config, &StudyPlan::quick(), &mut |_| {}, &mut notes)
        .unwrap();
    assert!(axis.is_none());
    assert_eq!(notes, [study::in_plane_response::NO_IN_PLANE_LOAD_NOTE]);
    // The scene's report has the axis; its JSON no NaN.
    let json = serde_json::to_string(report()).unwrap();
    assert!(json.contains("\"in_plane_mode_count\":{") && !json.contains("NaN"));
}

/// The axis reads the node as `simulate` does: the scene at rest, damped
/// (ζ = 0.7) and stepped until settled, puts the first loaded ALE node's
/// in-plane displacement where the row of its orders says, with and without
/// the residual flexibility.
#[test]
fn the_in_plane_response_is_where_the_stepped_scene_settles() {
    let axis = report().in_plane_mode_count.as_ref().unwrap();
    let row = axis.rows.iter().find(|r| r.l_max == 1).unwrap();
    for (residual, want) in [
        (false, row.response_m),
        (true, row.response_with_residual_m),
    ] {
        let mut c = scene();
        c.joint.speed = 0.0;
        c.plate.damping = vec![0.7];
        c.plate.residual_flexibility = residual;
        let mut sim = annular_plate::dynamics::Simulation::new(c).unwrap();
        for _ in 0..50 {
            sim.step().unwrap();
        }
        // The node is at θ = 0: x is radial, y tangential.
        let u = sim.ale_node(0).in_plane.u;
        let e = (u[0] - want[0]).hypot(u[1] - want[1]) / want[0].hypot(want[1]);
        println!(
            "residual {residual}: settled ({:.9e}, {:.9e}) m, axis ({:.9e}, {:.9e}) m: {e:.2e}",
            u[0], u[1], want[0], want[1]
        );
        assert!(e < 1e-9, "{e:e}");
    }
}
