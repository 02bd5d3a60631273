//! Residual flexibility on a spinning disc: a space-fixed
//! transverse force on the rim of the lathe disc turning at 0.5 and 0.9 times
//! its lowest critical speed. The steady deflection under the force in the
//! ALE description solves, per mode, (K_i − k²Ω² M_i) q_i = f_i (constant
//! amplitudes: no gyroscopic or damping term acts).
//!
//! * 30 modes + the static residual against a reference of 300 modes (k ≤ 37,
//!   l ≤ 3) whose own truncation is closed with the *exact* static remainder
//!   (the Fourier-series plate of `tests/support/static_plate.rs` minus the 300
//!   modes' static part); the truncated modes of that reference have critical
//!   speeds over 10× the lowest, so its remainder is static to a good
//!   approximation. The pure 300-mode value is printed too.
//! * The simulation's output carries it in both descriptions: the ALE and the
//!   Lagrangian integration of the same run report the same `uz` at the ALE node.
//!
//! Run with `-- --nocapture` for the numbers.

mod support;

use annular_plate::config::{
    Config, Coordinates, IntegratorKind, NodePosition, PlateConfig, WrenchConfig,
};
use annular_plate::dynamics::Simulation;
use annular_plate::model::PlateModel;
use support::exact_plate::Edge;
use support::static_plate::StaticAnnulus;

/// Lowest critical speed ω_kl / k over the modes with k ≥ 1, rad/s.
fn lowest_critical_speed(model: &PlateModel) -> f64 {
    model
        .modes()
        .iter()
        .filter(|m| m.k > 0)
        .map(|m| m.omega / m.k as f64)
        .fold(f64::INFINITY, f64::min)
}

/// Steady ALE deflection per unit force at (r0, 0) at speed Ω: Σ w_i² / (K_i − k²Ω² M_i), and the static Σ w_i² / K_i.
fn steady(model: &PlateModel, r0: f64, speed: f64) -> (f64, f64) {
    let b = model.body();
    let mut dynamic = 0.0;
    let mut stat = 0.0;
    for (i, m) in model.modes().iter().enumerate() {
        let w = model.mode_shape(i, r0, 0.0).w;
        let kw = m.k as f64 * speed;
        dynamic += w * w / (b.modal_stiffness[i] - kw * kw * b.modal_mass[i]);
        stat += w * w / b.modal_stiffness[i];
    }
    (dynamic, stat)
}

fn plate(k_max: u32, l_max: u32, splines: usize) -> PlateConfig {
    let mut p = PlateConfig::lathe_disc();
    p.nodal_diameters = (0..=k_max).collect();
    p.nodal_circles = (0..=l_max).collect();
    p.radial_splines = annular_plate::config::RadialSplines::Fixed(splines);
    p
}

#[test]
fn thirty_modes_plus_residual_match_a_300_mode_reference_on_a_spinning_disc() {
    let paper = PlateModel::new(&plate(7, 1, 32)).expect("model");
    let big_cfg = plate(37, 3, 64);
    assert!(big_cfg.mode_count() >= 300);
    let big = PlateModel::new(&big_cfg).expect("model");
    let r0 = paper.plate().outer_radius;
    let critical = lowest_critical_speed(&paper);
    let big_truncated_critical = {
        // the lowest critical speed of the modes the reference leaves out: ⟨k, 4⟩ and ⟨38, 0⟩
        let mut c = plate(38, 4, 64);
        c.nodal_diameters = (1..=38).collect();
        let m = PlateModel::new(&c).expect("model");
        m.modes()
            .iter()
            .filter(|x| x.l == 4 || x.k == 38)
            .map(|x| x.omega / x.k as f64)
            .fold(f64::INFINITY, f64::min)
    };
    let d = annular_plate::model::bending_rigidity(
        big_cfg.youngs_modulus,
        big_cfg.thickness,
        big_cfg.poisson_ratio,
    );
    let exact_static = StaticAnnulus::new(
        big_cfg.inner_radius,
        r0,
        big_cfg.poisson_ratio,
        d,
        Edge::Clamped,
        Edge::Free,
    )
    .series(r0, 1.0, r0, 0.0, 2000)
    .value();
    let h = paper.static_harmonics(&[r0]);
    let residual = paper.residual_kernel(&h, 0, 0).at(0.0);
    println!("lowest critical speed {critical:.2} rad/s; the reference's truncated modes' lowest: {big_truncated_critical:.1} rad/s");
    println!(
        "{:>6} {:>14} {:>14} {:>10} {:>10} {:>12}",
        "Ω/Ωc", "reference m/N", "300 modes", "30 modes", "+ residual", "300 vs ref"
    );
    for ratio in [0.0, 0.5, 0.9] {
        let speed = ratio * critical;
        let (big_dyn, big_stat) = steady(&big, r0, speed);
        let reference = big_dyn + (exact_static - big_stat);
        let (paper_dyn, _) = steady(&paper, r0, speed);
        let corrected = paper_dyn + residual;
        let (e30, ec, e300) = (
            paper_dyn / reference - 1.0,
            corrected / reference - 1.0,
            big_dyn / reference - 1.0,
        );
        println!(
            "{ratio:>6} {reference:>14.6e} {big_dyn:>14.6e} {:>9.3}% {:>9.4}% {:>11.4}%",
            100.0 * e30,
            100.0 * ec,
            100.0 * e300
        );
        assert!(
            ec.abs() < 5e-3,
            "Ω = {ratio} Ωc: 30 modes + residual off by {:.3} %",
            100.0 * ec
        );
        assert!(
            e30.abs() > 2.0 * ec.abs(),
            "Ω = {ratio} Ωc: the correction must help ({e30:e} vs {ec:e})"
        );
    }
}

#[test]
fn ale_and_lagrangian_runs_report_the_same_corrected_deflection() {
    let force = -100.0;
    let model = PlateModel::new(&PlateConfig::lathe_disc()).expect("model");
    let speed = 0.5 * lowest_critical_speed(&model);
    let mut base = Config {
        plate: PlateConfig::lathe_disc(),
        ..Config::default()
    };
    base.plate.damping = vec![0.05];
    base.joint.speed = speed;
    base.nodes.ale = vec![NodePosition {
        radial: 1.0,
        angular: 0.0,
    }];
    base.nodes.lagrange = vec![NodePosition {
        radial: 1.0,
        angular: 0.25,
    }];
    base.loads.ale = vec![WrenchConfig {
        force: [0.0, 0.0, force],
        moment: [0.0; 3],
    }];
    base.simulation.integrator = IntegratorKind::Exponential;
    let mut out = Vec::new();
    for coordinates in [Coordinates::Ale, Coordinates::Lagrangian] {
        let mut c = base.clone();
        c.simulation.coordinates = coordinates;
        let mut sim = Simulation::new(c).expect("simulation");
        for _ in 0..300 {
            sim.step().expect("step");
        }
        let (ale, lag) = (sim.ale_node(0).uz, sim.lagrange_node(0).uz);
        let (r_ale, r_lag) = (sim.residual_deflection(0), sim.residual_deflection(1));
        println!("{coordinates:?}: ale uz {ale:.12e} (residual {r_ale:.6e}), lagrange uz {lag:.12e} (residual {r_lag:.6e})");
        assert!(
            r_ale < 0.0 && r_ale.abs() > 0.03 * ale.abs(),
            "the residual under the force is the 5 % the modes miss"
        );
        out.push((ale, lag));
    }
    let (a, l) = (out[0], out[1]);
    let scale = a.0.abs();
    assert!(
        (a.0 - l.0).abs() < 1e-9 * scale && (a.1 - l.1).abs() < 1e-9 * scale,
        "ALE {a:?} vs Lagrangian {l:?}"
    );
}
