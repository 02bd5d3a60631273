//! Contacts see the corrected compliance: with
//! `plate.residual_flexibility` the brake pads act on the modal deflection
//! plus the truncated modes' static deflection of their own forces and the
//! held wrenches — the residual as a spring in series with the contact,
//! solved within the step (src/dynamics/contact_compliance.rs,
//! src/dynamics/load_models/pad_series.rs) — and the linear stability
//! analysis uses the same law.
//!
//! - Static clamp of the brake bench against an exact static solution: the
//!   plate's exact flexibility at the pad points and the load point from the
//!   Fourier-series plate of tests/support/static_plate.rs (no modes), the
//!   contact-spring system solved exactly here.
//! - The squeal threshold of config/brake_squeal_paper.yaml (the paper's data) with and without, the
//!   ring-of-pads closed form with the series stiffness, and the simulated
//!   growth rate against the eigenvalue with the correction on.
//! - The lathe tool pressed into the disc at rest against the exact plate.
//! - A nearly rigid contact (k_c = 1e12 N/m): in series with the residual its
//!   coupling rate is bounded by G⁻¹ however stiff the contact (the explicit
//!   step checks then need far fewer substeps) and the clamp settles on the
//!   exact solution.
//!
//! Run with `-- --nocapture` for the numbers.

mod support;

use annular_plate::config::{Config, IntegratorKind, PlateTheory, WrenchConfig};
use annular_plate::dynamics::load_models::pad_config::{Caliper, PadsConfig};
use annular_plate::dynamics::load_models::tool::ToolOutputs;
use annular_plate::dynamics::load_models::tool_config::ToolConfig;
use annular_plate::dynamics::{stability, Simulation};
use std::f64::consts::TAU;
use support::exact_plate::Edge;
use support::scene_files as scenes;
use support::static_plate::StaticAnnulus;

/// Harmonics of the exact series.
const K_EXACT: u32 = 2000;

/// Transverse force held at the rim (the bench's accelerometer node, φ = 0), N.
const RIM_FORCE: f64 = -1000.0;

/// The brake bench at rest, clamped with 5 kN per face, a rim force held on
/// lagrange_1, heavily damped so it settles in a few hundred steps; under
/// Kirchhoff theory, the exact static plate's (the file ships Mindlin theory).
fn clamped_bench(caliper: Caliper, stiffness: f64, residual: bool) -> Config {
    let mut c = scenes::load("brake_bench.yaml");
    c.plate.theory = PlateTheory::Kirchhoff;
    c.joint.speed = 0.0;
    c.plate.damping = vec![0.5];
    c.plate.residual_flexibility = residual;
    c.loads.lagrange = vec![WrenchConfig {
        force: [0.0, 0.0, RIM_FORCE],
        moment: [0.0; 3],
    }];
    let p = c.section_mut::<PadsConfig>().unwrap();
    p.caliper = caliper;
    p.clamp_force = vec![5000.0];
    p.contact_stiffness = stiffness;
    c
}

/// Exact static solution: (deflections at the contacts, their net axial
/// forces N_b − N_t, deflection under the rim force).
struct Exact {
    w: Vec<f64>,
    force: Vec<f64>,
    w_load: f64,
}

fn exact_clamp(c: &Config) -> Exact {
    let pl = &c.plate;
    let d =
        annular_plate::model::bending_rigidity(pl.youngs_modulus, pl.thickness, pl.poisson_ratio);
    assert_eq!(
        (pl.inner_boundary, pl.outer_boundary),
        (
            annular_plate::config::Boundary::Supported,
            annular_plate::config::Boundary::Free
        )
    );
    let plate = StaticAnnulus::new(
        pl.inner_radius,
        pl.outer_radius,
        pl.poisson_ratio,
        d,
        Edge::Supported,
        Edge::Free,
    );
    let radius = |xi: f64| pl.inner_radius + xi * (pl.outer_radius - pl.inner_radius);
    // Green's function: deflection at (r, θ) per unit force at (r0, θ0); the
    // fitted tail only under the load (elsewhere the direct sum has converged).
    let green = |r0: f64, t0: f64, r: f64, t: f64| {
        let s = plate.series(r0, 1.0, r, t - t0, K_EXACT);
        if r == r0 && t == t0 {
            s.value()
        } else {
            s.direct
        }
    };
    let pads = c.section::<PadsConfig>().unwrap();
    let pts: Vec<(f64, f64)> = pads
        .contacts
        .iter()
        .map(|k| c.nodes.ale[k.node])
        .map(|p| (radius(p.radial), TAU * p.angular))
        .collect();
    let load = c.nodes.lagrange[0];
    let (rl, tl) = (radius(load.radial), TAU * load.angular);
    let n = pts.len();
    let e: Vec<Vec<f64>> = pts
        .iter()
        .map(|&(r, t)| pts.iter().map(|&(r0, t0)| green(r0, t0, r, t)).collect())
        .collect();
    let e_load: Vec<f64> = pts.iter().map(|&(r, t)| green(rl, tl, r, t)).collect();
    // Contact law F = −K w: K = 2k_c I (fixed), 2k_c (I − 1/n) (floating, one pad).
    let k = 2.0 * pads.contact_stiffness;
    let kmat = |i: usize, j: usize| match pads.caliper {
        Caliper::Fixed => {
            if i == j {
                k
            } else {
                0.0
            }
        }
        Caliper::Floating => k * ((i == j) as u8 as f64 - 1.0 / n as f64),
    };
    // (I + K E) F = −K e_load P, by Gaussian elimination (n = 3).
    let mut a: Vec<Vec<f64>> = (0..n)
        .map(|i| {
            (0..n)
                .map(|j| (i == j) as u8 as f64 + (0..n).map(|m| kmat(i, m) * e[m][j]).sum::<f64>())
                .collect()
        })
        .collect();
    let mut b: Vec<f64> = (0..n)
        .map(|i| -(0..n).map(|m| kmat(i, m) * e_load[m]).sum::<f64>() * RIM_FORCE)
        .collect();
    for col in 0..n {
        for row in col + 1..n {
            let f = a[row][col] / a[col][col];
            let (pivot, below) = a.split_at_mut(row);
            for (x, p) in below[0][col..n].iter_mut().zip(&pivot[col][col..n]) {
                *x -= f * p;
            }
            b[row] -= f * b[col];
        }
    }
    let mut force = vec![0.0; n];
    for row in (0..n).rev() {
        force[row] =
            (b[row] - (row + 1..n).map(|j| a[row][j] * force[j]).sum::<f64>()) / a[row][row];
    }
    let w = (0..n)
        .map(|i| (0..n).map(|j| e[i][j] * force[j]).sum::<f64>() + e_load[i] * RIM_FORCE)
        .collect();
    let w_load = pts
        .iter()
        .zip(&force)
        .map(|(&(r0, t0), f)| green(r0, t0, rl, tl) * f)
        .sum::<f64>()
        + green(rl, tl, rl, tl) * RIM_FORCE;
    Exact { w, force, w_load }
}

/// Settled (contact deflections, contact net axial forces, deflection under the rim force).
fn settle(c: Config, seconds: f64) -> (Vec<f64>, Vec<f64>, f64) {
    let mut sim = Simulation::new(c).unwrap();
    let read = |sim: &Simulation| {
        let nodes: Vec<usize> = sim
            .config()
            .section::<PadsConfig>()
            .unwrap()
            .contacts
            .iter()
            .map(|k| k.node)
            .collect();
        let w: Vec<f64> = nodes.iter().map(|&j| sim.ale_node(j).uz).collect();
        let f: Vec<f64> = nodes
            .iter()
            .map(|&j| sim.ale_model_wrench(j).force[2])
            .collect();
        (w, f, sim.lagrange_node(0).uz)
    };
    let steps = (seconds / sim.dt()).round() as usize;
    for _ in 0..steps {
        sim.step().unwrap();
    }
    let before = read(&sim);
    for _ in 0..steps / 4 {
        sim.step().unwrap();
    }
    let after = read(&sim);
    // Settled: the last quarter changed nothing visible.
    assert!(
        (after.2 - before.2).abs() < 1e-9 * after.2.abs(),
        "not settled: {} vs {}",
        before.2,
        after.2
    );
    after
}

fn relative(a: &[f64], b: &[f64]) -> f64 {
    let scale = b.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    a.iter()
        .zip(b)
        .fold(0.0f64, |m, (x, y)| m.max((x - y).abs()))
        / scale
}

#[test]
fn static_clamp_of_the_brake_bench_matches_the_exact_plate_with_contact_springs() {
    for caliper in [Caliper::Fixed, Caliper::Floating] {
        let c = clamped_bench(caliper, 2.0e7, true);
        let exact = exact_clamp(&c);
        let (w, f, wl) = settle(c.clone(), 0.3);
        let (w0, f0, wl0) = settle(clamped_bench(caliper, 2.0e7, false), 0.3);
        println!("{caliper:?} caliper, k_c = 2e7 N/m, rim force {RIM_FORCE} N:");
        println!(
            "  exact:              w = {:?} m, F = {:?} N, w under the force {:.6e} m",
            exact.w, exact.force, exact.w_load
        );
        println!("  with the residual:  w = {w:?}, F = {f:?}, {wl:.6e}");
        println!("  modal only:         w = {w0:?}, F = {f0:?}, {wl0:.6e}");
        let errors = [
            relative(&w, &exact.w),
            relative(&f, &exact.force),
            ((wl - exact.w_load) / exact.w_load).abs(),
        ];
        let errors0 = [
            relative(&w0, &exact.w),
            relative(&f0, &exact.force),
            ((wl0 - exact.w_load) / exact.w_load).abs(),
        ];
        println!("  relative errors (contact w, contact F, w under the force): with {errors:?}, modal only {errors0:?}");
        for (e, e0) in errors.iter().zip(&errors0) {
            assert!(*e < 1e-3, "{caliper:?}: with the correction {errors:?}");
            assert!(*e0 > 10.0 * e, "{caliper:?}: the modal-only clamp should be off by the truncation error: {errors0:?} vs {errors:?}");
        }
    }
}

/// The brake-squeal scene with or without the correction.
fn squeal(residual: bool) -> Config {
    let mut c = scenes::load("brake_squeal_paper.yaml");
    c.plate.residual_flexibility = residual;
    c
}

fn threshold(c: &Config) -> f64 {
    let sim = Simulation::new(c.clone()).unwrap();
    stability::friction_threshold(sim.scene(), c.joint.speed, 2.0)
        .expect("the scene squeals below μ = 2")
}

#[test]
fn squeal_threshold_with_the_series_contacts_matches_the_ring_closed_form() {
    // As tests/scene_brake_squeal.rs for a ring of n equal contacts, with the
    // series stiffness: a ⟨k⟩ wave cos kθ_c is an eigenvector of the circulant
    // G among the contacts with eigenvalue γ_k = Σ_d G(0, d) cos kθ_d, so each
    // face's spring and damper act as k_c/(1 + 2k_c γ_k), c_c/(1 + 2k_c γ_k).
    let (with, without) = (threshold(&squeal(true)), threshold(&squeal(false)));
    println!("brake_squeal_paper.yaml threshold μ_c: with the residual flexibility {with:.6}, modal only {without:.6}");
    for contact_damping in [0.0, 1.0] {
        let mut c = squeal(true);
        c.section_mut::<PadsConfig>().unwrap().contact_damping = contact_damping;
        let sim = Simulation::new(c.clone()).unwrap();
        let g = sim.scene().residual.as_ref().unwrap();
        let model = sim.model();
        let pads = c.section::<PadsConfig>().unwrap();
        let nodes: Vec<usize> = pads.contacts.iter().map(|k| k.node).collect();
        let n = nodes.len() as f64;
        let clamp = pads.clamp_force[0];
        let r = sim.scene().ale_nodes[0].radius;
        let speed = c.joint.speed;
        let mut closed_form = f64::INFINITY;
        for m in model
            .modes()
            .iter()
            .filter(|m| m.shape == annular_plate::model::AngularShape::Cos)
        {
            let k = m.k as f64;
            let gamma: f64 = nodes
                .iter()
                .map(|&d| {
                    g.between(nodes[0], d, 0.0)
                        * (k * (sim.scene().ale_nodes[d].angle
                            - sim.scene().ale_nodes[nodes[0]].angle))
                            .cos()
                })
                .sum();
            let factor = 1.0 / (1.0 + 2.0 * pads.contact_stiffness * gamma);
            let rr = model.radial_shapes()[m.radial].value(r);
            let omega_p = (m.omega * m.omega
                + factor * pads.contact_stiffness * n * rr * rr / m.modal_mass)
                .sqrt();
            let d = factor * contact_damping * n * rr * rr;
            let mu = r * ((2.0 * m.damping * m.omega * m.modal_mass + d) * omega_p + d * k * speed)
                / (clamp * k * rr * rr);
            println!("c_c = {contact_damping}: ⟨k = {}⟩: γ_k = {gamma:.4e} m/N, spring factor {factor:.5}, f_p = {:.2} Hz, closed-form μ_c = {mu:.6}", m.k, omega_p / TAU);
            closed_form = closed_form.min(mu);
        }
        let eig = stability::friction_threshold(sim.scene(), speed, 2.0).unwrap();
        println!("c_c = {contact_damping}: threshold μ_c with the residual: eigenvalues {eig:.9}, closed form {closed_form:.9}");
        assert!(
            (eig - closed_form).abs() < 1e-6 * closed_form,
            "{eig} vs {closed_form}"
        );
    }
    // The values documented in docs/residual_flexibility.md and docs/scenes.md.
    assert!((without - 0.300).abs() < 5e-4, "{without}");
    assert!((with - 0.2983).abs() < 5e-4, "{with}");
}

#[test]
fn with_the_correction_the_simulated_squeal_grows_at_the_eigenvalue_rate() {
    let c = squeal(true);
    let mu_c = threshold(&c);
    for factor in [0.9, 1.1] {
        let mu = factor * mu_c;
        let mut c = c.clone();
        let p = c.section_mut::<PadsConfig>().unwrap();
        p.friction_coefficient = mu;
        p.lift_off = false;
        let mut sim = Simulation::new(c).unwrap();
        let g = support::squeal::simulated_growth(&mut sim, 1e-5, 3000);
        let (rate, slope) = (g.rate, g.simulated);
        println!("with the residual, μ = {factor} μ_c = {mu:.5}: ⟨k = {}⟩ at {:.2} Hz, eigenvalue Re λ = {rate:.6} 1/s, simulated {slope:.6} 1/s", g.k, g.omega / TAU);
        assert_eq!(rate > 0.0, factor > 1.0);
        assert_eq!(
            slope > 0.0,
            factor > 1.0,
            "the simulation disagrees with the eigenvalues about stability"
        );
        assert!(
            (slope - rate).abs() < 2e-2 * rate.abs(),
            "growth rate: simulated {slope} vs eigenvalue {rate}"
        );
    }
}

#[test]
fn a_stiff_contact_in_series_with_the_residual_has_a_bounded_coupling_and_settles_on_the_exact_clamp(
) {
    // Coupling rate of the pads, (1/s)², against k_c: without the residual it
    // grows like k_c; in series with G it is bounded by G⁻¹.
    let rate = |k: f64, residual: bool| {
        let sim = Simulation::new(clamped_bench(Caliper::Fixed, k, residual)).unwrap();
        sim.scene().load_models.coupling().stiffness_rate_sq.sqrt()
    };
    let stiff = 1.0e12;
    let (with, without) = (rate(stiff, true), rate(stiff, false));
    let stiffer = rate(1e14, true);
    println!("pad coupling rate at k_c = 1e12 N/m: with the residual {with:.4e} 1/s, without {without:.4e} 1/s; at 1e14 with {stiffer:.4e}, at 2e7 with {:.4e}", rate(2e7, true));
    assert!(
        (with - stiffer).abs() < 1e-2 * with,
        "bounded by G⁻¹, not by k_c: {with} vs {stiffer}"
    );
    assert!(without > 30.0 * with);
    // RK4 re-evaluates the pads per stage and takes the inner substeps the
    // coupling needs to stay stable (docs/hard_cases.md): a contact this stiff
    // without the residual needs them by the thousand per step.
    let mut c = clamped_bench(Caliper::Fixed, stiff, true);
    c.simulation.integrator = IntegratorKind::Rk4;
    let inner = |c: &Config| {
        let mut sim = Simulation::new(c.clone()).unwrap();
        sim.step().unwrap();
        sim.inner_substeps()
    };
    let mut off = c.clone();
    off.plate.residual_flexibility = false;
    let (n_with, n_without) = (inner(&c), inner(&off));
    println!("RK4 inner substeps per 1 ms step at k_c = 1e12: with the residual {n_with}, without {n_without}");
    assert!(n_without > 10 * n_with);
    let exact = exact_clamp(&c);
    let (w, f, wl) = settle(c.clone(), 0.1);
    let errors = [
        relative(&w, &exact.w),
        relative(&f, &exact.force),
        ((wl - exact.w_load) / exact.w_load).abs(),
    ];
    println!(
        "k_c = 1e12: exact w = {:?}, F = {:?}; simulated w = {w:?}, F = {f:?}; errors {errors:?}",
        exact.w, exact.force
    );
    for e in errors {
        assert!(e < 1e-3, "{errors:?}");
    }
    // The contact exponential takes the stiff contacts into its exponential:
    // the same exact clamp, on the scene's own integrator.
    let mut ce = c.clone();
    ce.simulation.integrator = IntegratorKind::ContactExponential;
    let (w, f, wl) = settle(ce, 0.1);
    let errors = [
        relative(&w, &exact.w),
        relative(&f, &exact.force),
        ((wl - exact.w_load) / exact.w_load).abs(),
    ];
    println!("contact_exponential: simulated w = {w:?}, F = {f:?}; errors {errors:?}");
    for e in errors {
        assert!(e < 1e-3, "{errors:?}");
    }
}

#[test]
fn the_lathe_tool_pressed_into_a_disc_at_rest_matches_the_exact_plate() {
    // The lathe disc at rest (no cutting: Ω = 0 sweeps no bins), the tool fed
    // 0.1 mm into the +z face and held: the feed force of eq. (21) on the
    // chip h/2 − z_holder − f/k_t − C f (tip pushed back by f/k_t, the rim
    // pushed down by C f, C the exact plate's compliance under the tool).
    let mut c = scenes::load("lathe.yaml");
    c.joint.speed = 0.0;
    c.gravity = [0.0; 3];
    let t = c.section_mut::<ToolConfig>().unwrap();
    t.start_clearance = 0.0;
    t.feed_rate = 0.002;
    let feed_time = 0.05;
    let tool = c.section::<ToolConfig>().cloned().unwrap();
    let pl = c.plate.clone();
    let holder = 0.5 * pl.thickness - tool.feed_rate * feed_time;
    let d =
        annular_plate::model::bending_rigidity(pl.youngs_modulus, pl.thickness, pl.poisson_ratio);
    let plate = StaticAnnulus::new(
        pl.inner_radius,
        pl.outer_radius,
        pl.poisson_ratio,
        d,
        Edge::Clamped,
        Edge::Free,
    );
    let compliance = plate
        .series(pl.outer_radius, 1.0, pl.outer_radius, 0.0, K_EXACT)
        .value();
    let law = |chip: f64| {
        if chip > 0.0 {
            tool.specific_force
                * tool.depth_of_cut
                * chip.powf(1.0 - tool.force_exponent)
                * 1e-3f64.powf(tool.force_exponent)
        } else {
            0.0
        }
    };
    let (mut lo, mut hi) = (0.0, law(0.5 * pl.thickness - holder));
    for _ in 0..200 {
        let f = 0.5 * (lo + hi);
        if f - law(0.5 * pl.thickness - holder - f / tool.stiffness - compliance * f) > 0.0 {
            hi = f;
        } else {
            lo = f;
        }
    }
    let f_exact = 0.5 * (lo + hi);
    let w_exact = -compliance * f_exact;
    let run = |residual: bool| {
        let mut c = c.clone();
        c.plate.residual_flexibility = residual;
        let mut sim = Simulation::new(c).unwrap();
        for _ in 0..(feed_time / sim.dt()).round() as usize {
            sim.step().unwrap();
        }
        sim.set_tool_feed(0.0).unwrap();
        for _ in 0..(1.0 / sim.dt()).round() as usize {
            sim.step().unwrap();
        }
        (sim.tool_output().unwrap().feed_force, sim.ale_node(0).uz)
    };
    let ((f, w), (f0, w0)) = (run(true), run(false));
    println!("tool 0.1 mm into the disc at rest: exact f = {f_exact:.6} N, w = {w_exact:.6e} m (C = {compliance:.6e} m/N)");
    println!(
        "  with the residual: f = {f:.6} N ({:.1e}), w = {w:.6e} m ({:.1e})",
        (f - f_exact) / f_exact,
        (w - w_exact) / w_exact
    );
    println!(
        "  modal only:        f = {f0:.6} N ({:.1e}), w = {w0:.6e} m ({:.1e})",
        (f0 - f_exact) / f_exact,
        (w0 - w_exact) / w_exact
    );
    assert!(((f - f_exact) / f_exact).abs() < 1e-4 && ((w - w_exact) / w_exact).abs() < 1e-3);
    assert!(
        ((w0 - w_exact) / w_exact).abs() > 0.01,
        "the 30 modes alone are stiffer under the rim load"
    );
    assert!((f0 - f_exact).abs() > 10.0 * (f - f_exact).abs());
}
