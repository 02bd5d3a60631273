//! The linear stability analysis with in-plane modes (docs/in_plane.md,
//! "Stability"): without pads the eigenvalues of `linear_system` are the
//! spinning annulus's in-plane waves of the independent Chebyshev
//! collocation (`support::in_plane_spinning_exact`) seen from space,
//! |ω − kΩ|; with the pads' face friction the bending eigenvalues do not
//! move when the in-plane modes are added (to first order the friction does
//! not couple the two families), while the in-plane ones are damped by it,
//! at the rate a simulation of a small perturbation decays with.

mod support;

use annular_plate::config::{Boundary, Config, Coordinates, IntegratorKind};
use annular_plate::dynamics::stability::{eigenvalues, linear_system, operating_point};
use annular_plate::dynamics::Simulation;
use nalgebra::Complex;
use support::in_plane_spinning_exact::{roots, SpinningAnnulus};
use support::lame::Lame;

const BRAKE: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/config/brake_in_plane.yaml");

/// The brake bench disc (clamped hub: in-plane fixed at r_i, free rim) with
/// one bending mode and the in-plane modes k = 0, 1, 2 of orders 0..=5,
/// undamped, no pads.
fn disc() -> Config {
    let mut c = Config::default();
    let p = &mut c.plate;
    (p.inner_radius, p.outer_radius, p.thickness) = (0.07, 0.153, 0.0181);
    (p.density, p.youngs_modulus, p.poisson_ratio) = (7850.0, 2.1e11, 0.3);
    (p.inner_boundary, p.outer_boundary) = (Boundary::Clamped, Boundary::Free);
    p.nodal_diameters = vec![0];
    p.nodal_circles = vec![0];
    p.damping = vec![0.0];
    p.in_plane_nodal_diameters = vec![0, 1, 2];
    p.in_plane_orders = vec![0, 1, 2, 3, 4, 5];
    c.gravity = [0.0; 3];
    c.simulation.integrator = IntegratorKind::Exponential;
    c.simulation.coordinates = Coordinates::Ale;
    c
}

/// The space-fixed circular frequencies |ω − kΩ| of the lowest
/// collocation roots of k at speed Ω: the two lowest backward waves
/// (ω > 0) and the lowest forward one (ω < 0).
fn space_fixed_waves(c: &Config, k: u32, speed: f64) -> Vec<f64> {
    let p = &c.plate;
    let a = SpinningAnnulus::of(p, true);
    let mut real: Vec<f64> = roots(&a, &Lame::new(p, true), k, speed, 48)
        .into_iter()
        .filter(|&(re, im)| im.abs() < 1e-6 * re.abs().max(1.0))
        .map(|(re, _)| re)
        .collect();
    real.sort_by(|x, y| x.abs().total_cmp(&y.abs()));
    let backward = real.iter().filter(|&&w| w > 0.0).take(2);
    let forward = real.iter().filter(|&&w| w < 0.0).take(1);
    backward
        .chain(forward)
        .map(|w| (w - k as f64 * speed).abs())
        .collect()
}

#[test]
fn without_pads_the_in_plane_eigenvalues_are_the_collocation_s_waves_seen_from_space() {
    let c = disc();
    let sim = Simulation::new(c.clone()).unwrap();
    let mut worst = 0.0f64;
    for speed in [1000.0, 3000.0] {
        let ev = eigenvalues(sim.scene(), speed, 0.0, &[]);
        for z in &ev {
            assert!(
                z.re.abs() < 1e-9 * z.norm(),
                "undamped: {z} at {speed} rad/s"
            );
        }
        for k in [0, 1, 2] {
            for w in space_fixed_waves(&c, k, speed) {
                let nearest = ev
                    .iter()
                    .map(|z| (z.im.abs() - w).abs() / w)
                    .fold(f64::INFINITY, f64::min);
                println!("Ω {speed} rad/s, k {k}: |ω − kΩ| = {w:.3} rad/s, nearest eigenvalue {nearest:.2e} off");
                worst = worst.max(nearest);
            }
        }
    }
    println!("worst {worst:.2e}");
    assert!(worst < 1e-6, "{worst:e}");
}

fn brake(in_plane: bool) -> Config {
    let mut c = Config::from_params_file(std::path::Path::new(BRAKE), "annular_plate").unwrap();
    if !in_plane {
        c.plate.in_plane_nodal_diameters.clear();
    }
    c
}

/// The eigenvalues of the brake scene's `linear_system` at Ω and μ (its clamp forces).
fn brake_eigenvalues(c: &Config, speed: f64, mu: f64) -> Vec<Complex<f64>> {
    let sim = Simulation::new(c.clone()).unwrap();
    let clamp = operating_point(sim.scene()).unwrap().clamp_force;
    eigenvalues(sim.scene(), speed, mu, &clamp)
}

/// The scene's friction coefficient and clamp forces.
fn configured(c: &Config) -> (f64, Vec<f64>) {
    let sim = Simulation::new(c.clone()).unwrap();
    let p = operating_point(sim.scene()).unwrap();
    (p.friction_coefficient, p.clamp_force)
}

#[test]
fn the_face_friction_leaves_the_bending_eigenvalues_and_damps_the_in_plane_ones() {
    for (speed, mu) in [(15.0, 0.4), (15.0, 1.0), (200.0, 1.0)] {
        let with = brake_eigenvalues(&brake(true), speed, mu);
        let without = brake_eigenvalues(&brake(false), speed, mu);
        let free = brake_eigenvalues(&brake(true), speed, 0.0);
        assert_eq!(with.len(), without.len() + 2 * 6, "six in-plane modes");
        let mut worst = 0.0f64;
        for b in &without {
            let nearest = with
                .iter()
                .map(|z| (z - b).norm())
                .fold(f64::INFINITY, f64::min);
            worst = worst.max(nearest / b.norm());
        }
        // The in-plane eigenvalues: those of `with` not among the bending ones.
        let in_plane = |ev: &[Complex<f64>]| -> Vec<Complex<f64>> {
            ev.iter()
                .copied()
                .filter(|z| without.iter().all(|b| (z - b).norm() > 1e-6 * b.norm()))
                .collect()
        };
        let (damped, structural) = (in_plane(&with), in_plane(&free));
        let shift = damped
            .iter()
            .map(|z| {
                structural
                    .iter()
                    .map(|s| (z - s).norm())
                    .fold(f64::INFINITY, f64::min)
            })
            .fold(0.0, f64::max);
        println!("Ω {speed} rad/s, μ {mu}: bending eigenvalues moved by {worst:.2e} (relative); the in-plane ones by up to {shift:.1} 1/s from μ = 0");
        assert!(worst < 1e-9, "{worst:e}");
        assert!(
            shift > 1.0,
            "the friction does not reach the in-plane modes: {shift}"
        );
    }
}

/// The in-plane eigenvalues (Im λ > 0) of the brake scene at its own speed,
/// μ and clamp forces: those of `linear_system` not among the bending ones.
fn in_plane_eigenvalues(c: &Config) -> Vec<Complex<f64>> {
    let (speed, mu) = (c.joint.speed, configured(c).0);
    let mut bending_only = c.clone();
    bending_only.plate.in_plane_nodal_diameters.clear();
    let without = brake_eigenvalues(&bending_only, speed, mu);
    brake_eigenvalues(c, speed, mu)
        .into_iter()
        .filter(|z| z.im > 0.0 && without.iter().all(|b| (z - b).norm() > 1e-6 * b.norm()))
        .collect()
}

/// Re λ of the eigenvalue of `linear_system` nearest `target` and the
/// growth rate a simulation shows for it: a run started on the real part of
/// its right eigenvector v (peak amplitude `amplitude`, m) less a run from
/// rest (the clamp's own transient), projected on its left eigenvector u_L:
/// ln|u_Lᵀ Δy| has slope Re λ whatever the other modes do.
fn simulated_rate(c: &Config, target: Complex<f64>, amplitude: f64, steps: usize) -> (f64, f64) {
    let (speed, (mu, clamp)) = (c.joint.speed, configured(c));
    let base = Simulation::new(c.clone()).unwrap();
    let n = base.scene().n_modes();
    let a = linear_system(base.scene(), speed, mu, &clamp);
    assert_eq!(a.nrows(), 2 * n, "massless pads: y = (q̄, q̄̇)");
    let nearest = |s: faer::ColRef<'_, faer::c64>| {
        (0..2 * n)
            .min_by(|&x, &y| {
                let d = |i: usize| (s[i].re - target.re).hypot(s[i].im - target.im);
                d(x).total_cmp(&d(y))
            })
            .unwrap()
    };
    let right = a.eigen().unwrap();
    let j = nearest(right.S().column_vector());
    let lambda = right.S()[j];
    let v: Vec<f64> = (0..2 * n).map(|r| right.U()[(r, j)].re).collect();
    let left = a.transpose().to_owned().eigen().unwrap();
    let jl = nearest(left.S().column_vector());
    let u: Vec<(f64, f64)> = (0..2 * n)
        .map(|r| (left.U()[(r, jl)].re, left.U()[(r, jl)].im))
        .collect();
    let peak = v[..n].iter().fold(0.0f64, |m, x| m.max(x.abs()));
    let mut perturbed = Simulation::new(c.clone()).unwrap();
    let mut state = perturbed.state().clone();
    for (i, x) in v.iter().enumerate() {
        let x = amplitude * x / peak;
        if i < n {
            state.q[i] += x;
        } else {
            state.q_dot[i - n] += x;
        }
    }
    state.rederive(perturbed.scene());
    perturbed.restore(state);
    let mut base = base;
    let (mut t, mut ln) = (Vec::new(), Vec::new());
    for _ in 0..steps {
        base.step().unwrap();
        perturbed.step().unwrap();
        let dy = perturbed
            .q_ale()
            .iter()
            .chain(perturbed.q_dot_ale())
            .zip(base.q_ale().iter().chain(base.q_dot_ale()))
            .map(|(p, b)| p - b);
        let (re, im) = dy
            .zip(&u)
            .fold((0.0, 0.0), |(re, im), (d, l)| (re + d * l.0, im + d * l.1));
        t.push(perturbed.time());
        ln.push(re.hypot(im).ln());
    }
    (lambda.re, support::fit::least_squares_slope(&t, &ln))
}

#[test]
fn the_in_plane_friction_damping_is_the_decay_a_simulation_shows() {
    // config/brake_in_plane.yaml (15 rad/s, μ = 0.4, 5 kN) stepped at 20 kHz
    // (1 kHz does not resolve decays of 2-7 time constants in 10 ms);
    // 100 kHz gives the same rates to 2e-7.
    let mut c = brake(true);
    c.simulation.rate_hz = 20_000.0;
    let ev = in_plane_eigenvalues(&c);
    assert_eq!(ev.len(), 6);
    let mut worst = 0.0f64;
    for z in ev {
        let (rate, simulated) = simulated_rate(&c, z, 1e-9, 200);
        let error = (simulated / rate - 1.0).abs();
        println!(
            "λ = {:.4} 1/s ± i 2π {:.2} Hz: simulated decay {simulated:.4} 1/s, {error:.2e} off",
            rate,
            z.im / std::f64::consts::TAU
        );
        worst = worst.max(error);
    }
    // Measured 1.6e-5 (the k = 1 pair); the bound of the bending squeal tests is 2e-2.
    assert!(worst < 1e-3, "{worst:e}");
}

/// Massive pads (`pads.mass`): the sum of a pad's face forces changes with
/// its compressions, and the friction −g sign V (δN_t + δN_b) e_θ it adds
/// drives the in-plane modes (docs/in_plane.md, "Stability"). A run started
/// on Re v of the bending or pad eigenvalue whose eigenvector has the
/// largest in-plane part
/// follows Re(v e^{λt}) in its in-plane amplitudes, which the linearisation
/// has from that term alone (without it they are 0 in v).
#[test]
fn massive_pads_drive_the_in_plane_modes_as_the_eigenvector_says() {
    use annular_plate::dynamics::load_models::pad::Pads;
    let mut c = brake(true);
    c.simulation.rate_hz = 100_000.0;
    c.section_mut::<annular_plate::dynamics::load_models::pad_config::PadsConfig>()
        .unwrap()
        .mass = 0.5;
    let (speed, (mu, clamp)) = (c.joint.speed, configured(&c));
    let mut base = Simulation::new(c.clone()).unwrap();
    let scene = base.scene();
    let n = scene.n_modes();
    let ip = scene.in_plane.as_ref().unwrap();
    let in_plane = ip.offset..ip.offset + ip.len();
    let a = linear_system(scene, speed, mu, &clamp);
    let len = a.nrows();
    let eig = a.eigen().unwrap();
    let (s, u) = (eig.S(), eig.U());
    let share = |j: usize| {
        let part = |r: std::ops::Range<usize>| r.map(|i| u[(i, j)].norm()).fold(0.0, f64::max);
        part(in_plane.clone()) / part(0..ip.offset).max(part(2 * n..len))
    };
    // Among the bending and pad eigenvalues (in-plane part below the rest).
    let j = (0..len)
        .filter(|&j| s[j].im > 0.0 && share(j) < 1.0)
        .max_by(|&x, &y| share(x).total_cmp(&share(y)))
        .unwrap();
    let (lambda, v): (Complex<f64>, Vec<Complex<f64>>) = (
        Complex::new(s[j].re, s[j].im),
        (0..len)
            .map(|r| Complex::new(u[(r, j)].re, u[(r, j)].im))
            .collect(),
    );
    println!("λ = {lambda:.3}, in-plane share of v {:.2e}", share(j));
    let peak = v[in_plane.clone()]
        .iter()
        .map(|z| z.norm())
        .fold(0.0, f64::max);
    let v: Vec<Complex<f64>> = v.iter().map(|z| z * (1e-9 / peak)).collect();
    let index = base.scene().load_models.find::<Pads>().unwrap().0;
    let mut perturbed = Simulation::new(c.clone()).unwrap();
    let mut state = perturbed.state().clone();
    for i in 0..n {
        state.q[i] += v[i].re;
        state.q_dot[i] += v[n + i].re;
    }
    let slot = &mut state.load_models.slots[index];
    let faces = slot.len() / 2;
    assert_eq!(2 * n + 2 * faces, len, "y = (q̄, q̄̇, ξ, ξ̇)");
    for f in 0..faces {
        slot[f] += v[2 * n + f].re;
        slot[faces + f] += v[2 * n + faces + f].re;
    }
    state.rederive(perturbed.scene());
    perturbed.restore(state);
    let mut worst = 0.0f64;
    for _ in 0..200 {
        base.step().unwrap();
        perturbed.step().unwrap();
        let t = perturbed.time();
        let e = (lambda * t).exp();
        let scale = in_plane
            .clone()
            .map(|i| (v[i] * e).norm())
            .fold(0.0, f64::max);
        for i in in_plane.clone() {
            let got = perturbed.q_ale()[i] - base.q_ale()[i];
            worst = worst.max((got - (v[i] * e).re).abs() / scale);
        }
    }
    println!("in-plane amplitudes against Re(v e^(λt)) over 2 ms: worst {worst:.2e} of the peak");
    assert!(worst < 1e-3, "{worst:e}");
}

/// The lining's patches run with the in-plane modes in the simulation, but
/// their linearisation carries the bending modes only: the analysis
/// refuses them by key, and takes them without in-plane modes.
#[test]
fn the_stability_analysis_refuses_lining_patches_with_in_plane_modes_by_key() {
    use annular_plate::dynamics::load_models::pad_config::PadsConfig;
    let with_patches = |in_plane| {
        let mut c = brake(in_plane);
        c.section_mut::<PadsConfig>().unwrap().shear = Some((1.0e6, 10.0));
        Simulation::new(c)
            .unwrap()
            .scene()
            .load_models
            .check_linear()
    };
    let error = with_patches(true).unwrap_err().to_string();
    println!("{error}");
    assert!(error.contains("pads.shear_stiffness"), "{error}");
    assert!(with_patches(false).is_ok());
    assert!(Simulation::new(brake(true))
        .unwrap()
        .scene()
        .load_models
        .check_linear()
        .is_ok());
}
