//! Centrifugal stiffening of Mindlin plates (`plate.theory: mindlin`,
//! `plate.centrifugal_stiffening: true`, docs/mindlin.md) against solutions
//! written here:
//!
//! * the Southwell coefficient of the model's mode (projected G_ll / m) and
//!   the slope of the Mindlin spinning spectrum (`campbell`) against the
//!   Rayleigh quotient λ = c_k h ∫ (σ_r W'² + σ_θ k² W²/r²) r dr / m of the
//!   exact Mindlin mode (`tests/support/mindlin_exact.rs`; m with the rotary
//!   inertia) in the textbook Lamé prestress (`tests/support/lame.rs`);
//! * a free vibration of one mode at constant speed rings at
//!   √(ω₀² + λΩ²) of the exact mode;
//! * the thin limit: the stiffened Mindlin spectrum at a high speed tends to
//!   the stiffened Kirchhoff spectrum as h → 0;
//! * `campbell` takes the key under Mindlin and, at rest, gives `modes`.
//!
//! Run with `-- --nocapture` for the tables.

mod support;

use annular_plate::config::{
    Boundary, CentrifugalConfig, Config, Coordinates, InPlaneInner, InPlaneOuter, IntegratorKind,
    PlateConfig, PlateTheory,
};
use annular_plate::dynamics::Simulation;
use annular_plate::model::AngularShape;
use annular_plate::model::{ModalGeometricStiffness, PlateModel, SpinningSpectrum};
use support::lame::{inner_fixed, Lame};
use support::mindlin_exact::MindlinAnnulus;
use support::quadrature::radial;

fn on() -> CentrifugalConfig {
    CentrifugalConfig {
        stiffening: true,
        in_plane_inner: InPlaneInner::Auto,
        in_plane_outer: InPlaneOuter::Free,
    }
}

/// The bench disc (steel, r_i = 0.07 m, r_a = 0.153 m) `h` thick under
/// Mindlin theory, with the given edges and ⟨k, l⟩.
fn disc(h: f64, inner: Boundary, outer: Boundary, ks: Vec<u32>, ls: Vec<u32>) -> PlateConfig {
    let mut p = Config::default().plate;
    p.inner_radius = 0.07;
    p.outer_radius = 0.153;
    p.thickness = h;
    p.youngs_modulus = 2.1e11;
    p.poisson_ratio = 0.3;
    p.density = 7850.0;
    p.inner_boundary = inner;
    p.outer_boundary = outer;
    p.nodal_diameters = ks;
    p.nodal_circles = ls;
    p.damping = vec![0.0];
    p.theory = PlateTheory::Mindlin;
    p.residual_flexibility = false;
    p
}

/// The exact Mindlin mode's Southwell coefficient and ω₀ (rad/s).
fn exact_southwell(p: &PlateConfig, k: u32, l: u32) -> (f64, f64) {
    let annulus = MindlinAnnulus::of_plate(p);
    let omega0 = annulus.roots(k, l as usize + 1, 64)[l as usize];
    let mode = annulus.mode(k, omega0);
    let lame = Lame::new(p, inner_fixed(p));
    // W' by the fourth-order central difference (step 1e-5 of the width).
    let d = 1e-5 * (p.outer_radius - p.inner_radius);
    let w = |r: f64| mode.fields(r).w;
    let slope =
        |r: f64| (8.0 * (w(r + d) - w(r - d)) - (w(r + 2.0 * d) - w(r - 2.0 * d))) / (12.0 * d);
    let k2 = (k as f64).powi(2);
    let c_k = if k == 0 { 2.0 } else { 1.0 } * std::f64::consts::PI;
    let g = c_k
        * p.thickness
        * radial(p.inner_radius, p.outer_radius, 400, |r| {
            let (sr, st, _) = lame.at(r);
            let (v, s) = (w(r), slope(r));
            (sr * s * s + st * k2 * v * v / (r * r)) * r
        });
    (g / mode.modal_mass(400), omega0)
}

#[test]
fn southwell_coefficients_of_mindlin_modes_are_the_exact_modes_rayleigh_quotients() {
    let cases = [
        (
            "bench disc, supported–free",
            Boundary::Supported,
            Boundary::Free,
            vec![(0, 0), (2, 0), (3, 0), (5, 0), (0, 1), (2, 1)],
        ),
        (
            "bench disc, clamped–free",
            Boundary::Clamped,
            Boundary::Free,
            vec![(0, 0), (2, 0), (4, 0), (1, 1)],
        ),
    ];
    println!("case | ⟨k,l⟩ | λ exact | projected G_ll/m | slope of the spectrum | rel. diffs | Kirchhoff λ");
    for (name, inner, outer, modes) in cases {
        let ks: Vec<u32> = modes.iter().map(|m| m.0).collect();
        let p = disc(0.0181, inner, outer, ks, vec![0, 1]);
        let model = PlateModel::new(&p).unwrap();
        let projected = ModalGeometricStiffness::new(&model, &on());
        let mut kirchhoff_plate = p.clone();
        kirchhoff_plate.theory = PlateTheory::Kirchhoff;
        let kirchhoff = PlateModel::new(&kirchhoff_plate).unwrap();
        let kirchhoff_g = ModalGeometricStiffness::new(&kirchhoff, &on());
        for (k, l) in modes {
            let (exact, omega0) = exact_southwell(&p, k, l);
            let spectrum = SpinningSpectrum::new(&p, &on(), k, l as usize + 1);
            let spin = (1e-2 * omega0 * omega0 / exact.abs()).sqrt();
            let w2 = |s: f64| spectrum.omega_squared(s).unwrap()[l as usize];
            let slope = |s: f64| (w2(s) - w2(0.0)) / (s * s);
            let slope = (4.0 * slope(0.5 * spin) - slope(spin)) / 3.0;
            let proj = projected.southwell(&model, k, l).unwrap();
            let thin = kirchhoff_g.southwell(&kirchhoff, k, l).unwrap();
            let rel = |x: f64| (x - exact).abs() / exact.abs();
            println!(
                "{name} | ⟨{k},{l}⟩ | {exact:.9} | {proj:.9} | {slope:.9} | {:.1e} {:.1e} | {thin:.6}",
                rel(proj),
                rel(slope)
            );
            assert!(
                rel(proj) < 1e-5,
                "{name} ⟨{k},{l}⟩: projected {proj} vs exact {exact}"
            );
            assert!(
                rel(slope) < 1e-5,
                "{name} ⟨{k},{l}⟩: slope {slope} vs exact {exact}"
            );
            // Hellmann–Feynman: the discrete eigenvalue's slope is its own eigenvector's projection.
            assert!(
                (slope - proj).abs() < 1e-6 * exact.abs(),
                "{name} ⟨{k},{l}⟩"
            );
            // ω at rest is the exact root (the model's accuracy, docs/mindlin.md).
            assert!((w2(0.0).sqrt() - omega0).abs() < 1e-6 * omega0);
            // Not Kirchhoff's: the thick disc's coefficient differs from the thin theory's.
            assert!(
                (thin - exact).abs() > 1e-3 * exact.abs(),
                "{name} ⟨{k},{l}⟩: {thin} vs {exact}"
            );
        }
    }
}

/// ω of a sampled free vibration q_j = A cos(ω jτ + φ): least squares of the
/// three-term recurrence q_{j+1} + q_{j−1} = 2 cos(ωτ) q_j.
fn recurrence_frequency(q: &[f64], tau: f64) -> f64 {
    let (num, den) = q.windows(3).fold((0.0, 0.0), |(n, d), w| {
        (n + w[1] * (w[0] + w[2]), d + 2.0 * w[1] * w[1])
    });
    (num / den).acos() / tau
}

#[test]
fn a_free_wave_on_a_spinning_mindlin_plate_rings_at_the_exact_modes_stiffened_frequency() {
    // ⟨2, 0⟩ of the bench disc alone, turning at 3000 rad/s, integrated in
    // rotating-frame coordinates (no gyroscopic term on a transverse mode):
    // m q̈ + (m ω₀² + Ω² G) q = 0.
    let (speed, rate) = (3000.0, 40_000.0);
    let p = disc(
        0.0181,
        Boundary::Supported,
        Boundary::Free,
        vec![2],
        vec![0],
    );
    let (lambda, omega0) = exact_southwell(&p, 2, 0);
    let expected = (omega0 * omega0 + lambda * speed * speed).sqrt();
    for integrator in [IntegratorKind::Exponential, IntegratorKind::Rk4] {
        let mut c = Config {
            plate: p.clone(),
            centrifugal: on(),
            ..Default::default()
        };
        c.joint.speed = speed;
        c.simulation.realtime_factor = 0.0;
        c.simulation.rate_hz = rate;
        c.simulation.coordinates = Coordinates::Lagrangian;
        c.simulation.integrator = integrator;
        let cos = |sim: &Simulation| {
            sim.model()
                .modes()
                .iter()
                .position(|m| m.shape == AngularShape::Cos)
                .unwrap()
        };
        let probe = Simulation::new(c.clone()).expect("a stiffened Mindlin scene runs");
        let mut q = vec![0.0; probe.model().n_modes()];
        q[cos(&probe)] = 1e-6;
        c.initial.q = q;
        let mut sim = Simulation::new(c).unwrap();
        let i = cos(&sim);
        let mut history = vec![sim.q_lagrange()[i]];
        for _ in 0..2000 {
            sim.step().unwrap();
            history.push(sim.q_lagrange()[i]);
        }
        let w = recurrence_frequency(&history, 1.0 / rate);
        let rel = (w - expected) / expected;
        println!(
            "{integrator:?}: simulated {w:.6} rad/s, √(ω₀² + λΩ²) of the exact mode {expected:.6} ({rel:.1e}), at rest {omega0:.3}"
        );
        // Not vacuous: the prestress raises ω by more than 1 %.
        assert!(expected > 1.01 * omega0);
        // The exponential is exact for the modal equation; RK4's own error
        // at its inner step stays below (hω)⁴/120 ≤ 1.3e-5 (docs/dynamics.md).
        let bound = match integrator {
            IntegratorKind::Rk4 => 1.3e-5,
            _ => 1e-6,
        };
        assert!(rel.abs() < bound, "{integrator:?}: {w} vs {expected}");
    }
}

#[test]
fn the_stiffened_mindlin_spectrum_tends_to_kirchhoff_s_as_the_plate_thins() {
    // Clamped–clamped (no free-edge boundary layer, docs/mindlin.md "Thin
    // limit"), ⟨2, 0⟩ at the speed where the prestress doubles ω₀², for
    // h/b = 0.024, 0.012, 0.006: the relative difference falls like (h/b)².
    let mut previous: Option<f64> = None;
    println!("h/b | Mindlin ω | Kirchhoff ω | rel. diff");
    for hb in [0.024, 0.012, 0.006] {
        let h = hb * (0.153 - 0.07);
        let p = disc(h, Boundary::Clamped, Boundary::Clamped, vec![2], vec![0]);
        let mut thin = p.clone();
        thin.theory = PlateTheory::Kirchhoff;
        let mindlin = SpinningSpectrum::new(&p, &on(), 2, 1);
        let kirchhoff = SpinningSpectrum::new(&thin, &on(), 2, 1);
        let w0 = kirchhoff.omega_squared(0.0).unwrap()[0];
        let lambda = ModalGeometricStiffness::new(&PlateModel::new(&thin).unwrap(), &on())
            .southwell(&PlateModel::new(&thin).unwrap(), 2, 0)
            .unwrap();
        let speed = (w0 / lambda).sqrt();
        let (wm, wk) = (
            mindlin.omega_squared(speed).unwrap()[0].sqrt(),
            kirchhoff.omega_squared(speed).unwrap()[0].sqrt(),
        );
        let diff = (wm - wk).abs() / wk;
        println!("{hb} | {wm:.6} | {wk:.6} | {diff:.2e}");
        assert!(wm < wk, "shear and rotary inertia soften: {wm} vs {wk}");
        if let Some(p) = previous {
            assert!(diff < p / 3.0, "{p:e} → {diff:e}");
        }
        previous = Some(diff);
    }
    assert!(previous.unwrap() < 1e-3);
}

#[test]
fn campbell_takes_stiffening_under_mindlin_and_gives_modes_at_rest() {
    let dir = support::cli::scratch_dir("mindlin_stiffening");
    let file = dir.join("disc.yaml");
    std::fs::write(
        &file,
        "annular_plate:\n  ros__parameters:\n    plate:\n      inner_radius: 0.07\n      outer_radius: 0.153\n      thickness: 0.0181\n      youngs_modulus: 2.1e11\n      poisson_ratio: 0.3\n      density: 7850.0\n      inner_boundary: supported\n      outer_boundary: free\n      nodal_diameters: [2, 3]\n      nodal_circles: [0]\n      theory: mindlin\n      centrifugal_stiffening: true\n",
    )
    .unwrap();
    let (ok, text, err) = support::cli::run(&[
        "campbell",
        file.to_str().unwrap(),
        "--json",
        "--speeds",
        "0:2000:3",
    ]);
    assert!(ok, "{err}");
    let json: serde_json::Value = serde_json::from_str(&text).unwrap();
    let p = disc(
        0.0181,
        Boundary::Supported,
        Boundary::Free,
        vec![2, 3],
        vec![0],
    );
    let annulus = MindlinAnnulus::of_plate(&p);
    for m in json["modes"].as_array().unwrap() {
        let k = m["k"].as_u64().unwrap() as u32;
        let f: Vec<f64> = m["rotating_hz"]
            .as_array()
            .unwrap()
            .iter()
            .map(|v| v.as_f64().unwrap())
            .collect();
        let exact = annulus.roots(k, 1, 64)[0] / std::f64::consts::TAU;
        let (lambda, _) = exact_southwell(&p, k, 0);
        let first_order =
            |s: f64| (f[0].powi(2) + lambda * (s / std::f64::consts::TAU).powi(2)).sqrt();
        println!(
            "⟨{k},0⟩: {f:?} Hz; exact at rest {exact:.4}, first order at 2000 rad/s {:.4}",
            first_order(2000.0)
        );
        assert!(
            (f[0] - exact).abs() < 1e-6 * exact,
            "⟨{k},0⟩ at rest: {} vs {exact}",
            f[0]
        );
        // Stiffened: above the rest value, within the second-order remainder of the first-order estimate.
        assert!(f[2] > f[0] * 1.001);
        assert!((f[2] - first_order(2000.0)).abs() < 0.01 * (f[2] - f[0]));
    }
}
