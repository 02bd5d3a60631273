//! Residual flexibility: the paper's 30 modes plus the static
//! correction of the truncated modes reproduce the exact static deflection of
//! the Kirchhoff plate under a point force to 0.1 %, under the load and away
//! from it, where the 30 modes alone are several per cent off.
//!
//! The exact solution is the independent Fourier series of
//! `tests/support/static_plate.rs` (closed-form radial solutions per harmonic,
//! no B-splines, no modes). The library's side is
//! `Σ_i w_i(a) w_i(b) / K_ii` (the modal static response) plus
//! `PlateModel::residual_kernel` at the angle between the points.
//!
//! Run with `-- --nocapture` for the table.

mod support;

use annular_plate::config::{Boundary, PlateConfig};
use annular_plate::model::PlateModel;
use std::f64::consts::PI;
use support::exact_plate::Edge;
use support::library_plate::edge;
use support::static_plate::StaticAnnulus;

/// Harmonics of the exact series.
const K_EXACT: u32 = 2000;

struct Case {
    name: &'static str,
    inner: Boundary,
    outer: Boundary,
    /// ξ_r of the force.
    xi_load: f64,
    /// Points (ξ_r, Δθ from the force) where the deflection is compared.
    points: &'static [(f64, f64)],
}

const AROUND: &[(f64, f64)] = &[(1.0, 0.0), (1.0, 0.5 * PI), (1.0, PI)];

fn radius(cfg: &PlateConfig, xi: f64) -> f64 {
    cfg.inner_radius + xi * (cfg.outer_radius - cfg.inner_radius)
}

/// Exact deflection at (r, Δθ) per unit force at r0 (direct sum plus the
/// fitted tail under the load; away from it the direct sum, whose remainder
/// is below the tail's size there, ~1e-7 relative).
fn exact(a: &StaticAnnulus, r0: f64, r: f64, dtheta: f64) -> f64 {
    let s = a.series(r0, 1.0, r, dtheta, K_EXACT);
    if dtheta == 0.0 && r == r0 {
        s.value()
    } else {
        s.direct
    }
}

/// (modal, modal + residual) deflection at (r, Δθ) per unit force at r0.
fn library(model: &PlateModel, r0: f64, r: f64, dtheta: f64) -> (f64, f64) {
    let k = &model.body().modal_stiffness;
    let modal: f64 = (0..model.n_modes())
        .map(|i| model.mode_shape(i, r, dtheta).w * model.mode_shape(i, r0, 0.0).w / k[i])
        .sum();
    let h = model.static_harmonics(&[r, r0]);
    let residual = model.residual_kernel(&h, 0, 1).at(dtheta);
    (modal, modal + residual)
}

fn check(case: &Case) -> (f64, f64) {
    let mut cfg = PlateConfig::lathe_disc();
    cfg.inner_boundary = case.inner;
    cfg.outer_boundary = case.outer;
    assert_eq!(cfg.mode_count(), 30, "the paper's 30 modes");
    let d = annular_plate::model::bending_rigidity(
        cfg.youngs_modulus,
        cfg.thickness,
        cfg.poisson_ratio,
    );
    let a = StaticAnnulus::new(
        cfg.inner_radius,
        cfg.outer_radius,
        cfg.poisson_ratio,
        d,
        edge(case.inner),
        edge(case.outer),
    );
    let model = PlateModel::new(&cfg).expect("model");
    let r0 = radius(&cfg, case.xi_load);
    let under = exact(&a, r0, r0, 0.0);
    println!(
        "=== {}: force at xi_r = {}, exact w/P under it {under:.6e} m/N",
        case.name, case.xi_load
    );
    println!(
        "  {:>5} {:>7} {:>13} {:>11} {:>11}",
        "xi_r", "dtheta", "exact m/N", "30 modes", "+ residual"
    );
    let (mut worst_modal, mut worst_corrected): (f64, f64) = (0.0, 0.0);
    for &(xi, dth) in case.points {
        let r = radius(&cfg, xi);
        let ex = exact(&a, r0, r, dth);
        let (modal, corrected) = library(&model, r0, r, dth);
        let (em, ec) = ((modal - ex) / under, (corrected - ex) / under);
        println!(
            "  {xi:>5} {:>6.0}° {ex:>13.6e} {:>10.4}% {:>10.5}%",
            dth.to_degrees(),
            100.0 * em,
            100.0 * ec
        );
        worst_modal = worst_modal.max(em.abs());
        worst_corrected = worst_corrected.max(ec.abs());
    }
    (worst_modal, worst_corrected)
}

#[test]
fn thirty_modes_plus_residual_match_the_exact_static_plate() {
    let cases = [
        Case {
            name: "lathe disc, clamped-free, force on the rim",
            inner: Boundary::Clamped,
            outer: Boundary::Free,
            xi_load: 1.0,
            points: AROUND,
        },
        Case {
            name: "lathe disc, clamped-free, force at mid-radius",
            inner: Boundary::Clamped,
            outer: Boundary::Free,
            xi_load: 0.5,
            points: &[
                (0.5, 0.0),
                (0.5, 0.5 * PI),
                (0.5, PI),
                (1.0, 0.0),
                (0.25, 0.3),
            ],
        },
        Case {
            name: "supported-free, force on the rim",
            inner: Boundary::Supported,
            outer: Boundary::Free,
            xi_load: 1.0,
            points: AROUND,
        },
        Case {
            name: "free-clamped, force on the inner (free) edge",
            inner: Boundary::Free,
            outer: Boundary::Clamped,
            xi_load: 0.0,
            points: &[(0.0, 0.0), (0.0, 0.5 * PI), (0.0, PI), (0.5, 0.2)],
        },
        Case {
            name: "clamped-clamped, force at mid-radius",
            inner: Boundary::Clamped,
            outer: Boundary::Clamped,
            xi_load: 0.5,
            points: &[(0.5, 0.0), (0.5, 0.5 * PI), (0.5, PI), (0.7, 0.1)],
        },
    ];
    for case in &cases {
        let (modal, corrected) = check(case);
        println!(
            "  worst |error| / exact under the load: 30 modes {:.3} %, with the residual {:.4} %",
            100.0 * modal,
            100.0 * corrected
        );
        // the issue asks 0.1 %; measured ≤ 6e-6 over these cases
        assert!(
            corrected < 1e-4,
            "{}: 30 modes + residual off by {:.4} % of the deflection under the load",
            case.name,
            100.0 * corrected
        );
        assert!(
            modal > 10.0 * corrected,
            "{}: the correction must matter ({modal:e} vs {corrected:e})",
            case.name
        );
    }
}

/// The library's static harmonics g_k (graded B-spline Ritz solve) against the
/// exact W_k(r0) under a rim load: Ritz values, so never above the exact ones;
/// measured ≤ 9.3e-7 below for k ≤ 100 (after the base breakpoints), 1.6e-4
/// at k ≥ 300 (the summed harmonics beyond 256 carry 4e-5 of the total).
#[test]
fn static_harmonics_match_the_exact_ones_per_k() {
    let cfg = PlateConfig::lathe_disc();
    let d = annular_plate::model::bending_rigidity(
        cfg.youngs_modulus,
        cfg.thickness,
        cfg.poisson_ratio,
    );
    let a = StaticAnnulus::new(
        cfg.inner_radius,
        cfg.outer_radius,
        cfg.poisson_ratio,
        d,
        Edge::Clamped,
        Edge::Free,
    );
    let model = PlateModel::new(&cfg).expect("model");
    let r0 = cfg.outer_radius;
    let h = model.static_harmonics(&[r0]);
    for k in [0u32, 1, 2, 5, 10, 30, 100, 300, 512, 1000, 1024] {
        let ex = a.harmonic(k, r0, 1.0).at_load();
        let rel = h.get(k, 0, 0) / ex - 1.0;
        println!(
            "k {k:4}: library {:.10e} exact {ex:.10e} rel {rel:+.3e}",
            h.get(k, 0, 0)
        );
        let bound = if k <= 100 { 3e-6 } else { 3e-4 };
        assert!(
            rel < 1e-9 && rel > -bound,
            "k = {k}: relative error {rel:e} (bound {bound:e}, never above the exact)"
        );
    }
}

/// The node outputs carry the correction: a held rim force on an ALE node of
/// the lathe disc at rest, the modes at their static solution; the ALE node's
/// and two Lagrangian rim nodes' `uz` (at 90° and 180°, through the angle
/// tables of mixed pairs, and with the plate turned by χ) against the exact
/// plate; with `plate.residual_flexibility: false` the modal value.
#[test]
fn node_outputs_add_the_residual_deflection() {
    use annular_plate::config::{Config, NodePosition, WrenchConfig};
    use annular_plate::dynamics::Simulation;
    let force = -100.0;
    let chi = 0.3;
    let mut base = Config {
        plate: PlateConfig::lathe_disc(),
        ..Config::default()
    };
    base.joint.initial_position = chi;
    base.nodes.ale = vec![NodePosition {
        radial: 1.0,
        angular: 0.0,
    }];
    // material points that sit 90° and 180° from the force at χ
    let at = |dth: f64| NodePosition {
        radial: 1.0,
        angular: ((dth - chi) / std::f64::consts::TAU).rem_euclid(1.0),
    };
    base.nodes.lagrange = vec![at(0.5 * PI), at(PI)];
    base.loads.ale = vec![WrenchConfig {
        force: [0.0, 0.0, force],
        moment: [0.0; 3],
    }];
    let model = PlateModel::new(&base.plate).expect("model");
    let r0 = base.plate.outer_radius;
    // static modal amplitudes, Lagrangian description: the force sits at φ = −χ on the plate
    base.initial.q = (0..model.n_modes())
        .map(|i| force * model.mode_shape(i, r0, -chi).w / model.body().modal_stiffness[i])
        .collect();
    let d = annular_plate::model::bending_rigidity(
        base.plate.youngs_modulus,
        base.plate.thickness,
        base.plate.poisson_ratio,
    );
    let a = StaticAnnulus::new(
        base.plate.inner_radius,
        r0,
        base.plate.poisson_ratio,
        d,
        Edge::Clamped,
        Edge::Free,
    );
    let under = force * exact(&a, r0, r0, 0.0);
    let expected = [
        under,
        force * exact(&a, r0, r0, 0.5 * PI),
        force * exact(&a, r0, r0, PI),
    ];
    for residual in [true, false] {
        let mut c = base.clone();
        c.plate.residual_flexibility = residual;
        let sim = Simulation::new(c).expect("simulation");
        let got = [
            sim.ale_node(0).uz,
            sim.lagrange_node(0).uz,
            sim.lagrange_node(1).uz,
        ];
        let z = [
            sim.ale_node_pose(0).translation[2],
            sim.lagrange_node_pose(0).translation[2],
            sim.lagrange_node_pose(1).translation[2],
        ];
        let worst = got
            .iter()
            .zip(&expected)
            .map(|(g, e)| ((g - e) / under).abs())
            .fold(0.0, f64::max);
        println!("residual_flexibility {residual}: uz {got:?} exact {expected:?}; worst {:.4} % of w under the load", 100.0 * worst);
        assert_eq!(got, z, "the pose carries uz");
        if residual {
            assert!(worst < 1e-4, "with the residual: {worst:e}");
        } else {
            assert!(
                worst > 0.05,
                "30 modes alone are 5.3 % off under the load: {worst:e}"
            );
        }
    }
}
