//! A torque-limited drive at its limit leaves the joint free with every
//! torsional in-plane mode (docs/in_plane.md, "The joint"): under a brake
//! torque step at the rim, the hub and three torsional modes follow the exact
//! (1 + 3)-degree-of-freedom solution built here from the exact torsional
//! modes (Bessel functions) and a modal superposition of its own — on
//! `exponential` (the k = 0 block stepped exactly with the joint's inertia
//! coupling) and on `rk4` (the joint in RK4's unknowns, the drive's reduced
//! law at every stage). At speed, where the spin terms couple the torsional
//! and radial families, the two integrators and both descriptions agree.
//!
//! Run with `-- --nocapture` for the numbers.

mod support;

use annular_plate::config::{Coordinates, IntegratorKind};
use annular_plate::dynamics::load_models::pad_outputs::PadOutputs;
use annular_plate::dynamics::Simulation;
use nalgebra::{DMatrix, DVector, SymmetricEigen};
use support::torsion_disc::{brake_at_rim, disc, exact_torsion, polar_inertia, RA};

const ORDERS: usize = 3;

/// The exact free-joint response from rest: [J sᵀ; s M] [χ̈; q̈] + [0; K q]
/// = [τ; f]. Eliminating χ̈ = (τ − sᵀq̈)/J leaves (M − s sᵀ/J) q̈ + K q =
/// f − s τ/J =: g, solved by its undamped modes (Cholesky of the reduced mass,
/// symmetric eigenproblem): q(t) = Σ φ (φᵀg/ω²)(1 − cos ωt), and
/// Ω(t) = (τ t − sᵀq̇)/J.
struct FreeJointExact {
    shapes: Vec<DVector<f64>>,
    omegas: Vec<f64>,
    weights: Vec<f64>,
    coupling: DVector<f64>,
    torque: f64,
    inertia: f64,
}

impl FreeJointExact {
    fn new(force: f64, limit: f64) -> FreeJointExact {
        let modes: Vec<_> = (0..ORDERS).map(exact_torsion).collect();
        let inertia = polar_inertia();
        let torque = limit - 4.0 * force * RA;
        let s = DVector::from_iterator(ORDERS, modes.iter().map(|t| t.coupling));
        let mass = DMatrix::from_diagonal(&DVector::from_iterator(
            ORDERS,
            modes.iter().map(|t| t.mass),
        )) - &s * s.transpose() / inertia;
        let stiffness = DMatrix::from_diagonal(&DVector::from_iterator(
            ORDERS,
            modes.iter().map(|t| t.mass * t.omega * t.omega),
        ));
        let g = DVector::from_iterator(
            ORDERS,
            modes
                .iter()
                .map(|t| -4.0 * force * t.v_rim - t.coupling * torque / inertia),
        );
        let l = mass.cholesky().expect("the reduced mass is positive").l();
        let l_inv = l.clone().try_inverse().unwrap();
        let eig = SymmetricEigen::new(&l_inv * stiffness * l_inv.transpose());
        let mut shapes = vec![];
        let mut omegas = vec![];
        let mut weights = vec![];
        for j in 0..ORDERS {
            let phi = l_inv.transpose() * eig.eigenvectors.column(j);
            let w2 = eig.eigenvalues[j];
            weights.push(phi.dot(&g) / w2);
            omegas.push(w2.sqrt());
            shapes.push(phi);
        }
        FreeJointExact {
            shapes,
            omegas,
            weights,
            coupling: s,
            torque,
            inertia,
        }
    }

    /// (q, Ω) at t.
    fn at(&self, t: f64) -> (DVector<f64>, f64) {
        let mut q = DVector::zeros(ORDERS);
        let mut q_dot = DVector::zeros(ORDERS);
        for ((phi, w), a) in self.shapes.iter().zip(&self.omegas).zip(&self.weights) {
            q += phi * (a * (1.0 - (w * t).cos()));
            q_dot += phi * (a * w * (w * t).sin());
        }
        let speed = (self.torque * t - self.coupling.dot(&q_dot)) / self.inertia;
        (q, speed)
    }
}

/// State indices of the torsional modes l = 0, 1, 2.
fn torsional_indices(sim: &Simulation) -> Vec<usize> {
    let ip = sim.scene().in_plane.as_ref().expect("in-plane modes");
    (0..ORDERS as u32)
        .map(|l| {
            let j = ip
                .modes
                .iter()
                .position(|m| m.l == l && m.shape.name() == "torsional")
                .expect("torsional mode l");
            ip.offset + j
        })
        .collect()
}

/// Worst twist and speed errors (relative to their peaks) over 2 ms of a
/// brake torque step on a drive held at its torque limit.
fn free_joint_errors(integrator: IntegratorKind) -> (f64, f64) {
    let (rate, force, limit) = (200_000.0, 1000.0, 50.0);
    let mut c = disc(&[0], &[0, 1, 2], rate);
    c.joint.max_torque = Some(limit);
    c.simulation.integrator = integrator;
    // RK4 within 1e-5 here (its default step limit leaves 7e-4 on ω* h).
    c.simulation.rk4_step_limit = 0.05;
    brake_at_rim(&mut c, force);
    let mut sim = Simulation::new(c).unwrap();
    // Commanded forward, braked backward: the drive pushes at its limit throughout.
    sim.set_speed_command(15.0).unwrap();
    let exact = FreeJointExact::new(force, limit);
    let indices = torsional_indices(&sim);
    let h = 1.0 / rate;
    let (mut dq, mut q_scale, mut d_speed, mut speed_scale) = (0.0f64, 0.0f64, 0.0f64, 0.0f64);
    for step in 1..=400 {
        sim.step().unwrap();
        let (q, speed) = exact.at(step as f64 * h);
        for (a, &i) in indices.iter().enumerate() {
            dq = dq.max((sim.q_lagrange()[i] - q[a]).abs());
            q_scale = q_scale.max(q[a].abs());
        }
        d_speed = d_speed.max((sim.state().speed - speed).abs());
        speed_scale = speed_scale.max(speed.abs());
        assert!((sim.state().effort - limit).abs() < 1e-9 * limit);
    }
    println!(
        "{}: ω* = {:.1?} rad/s; twist {:.2e} of {q_scale:.3e}, speed {:.2e} of {speed_scale:.3} rad/s",
        integrator.name(),
        exact.omegas,
        dq / q_scale,
        d_speed / speed_scale
    );
    (dq / q_scale, d_speed / speed_scale)
}

#[test]
fn three_torsional_modes_on_a_free_joint_follow_the_exact_four_degree_of_freedom_solution() {
    // The free joint's fastest rate, which bounds RK4's substeps.
    let sim = Simulation::new(disc(&[0], &[0, 1, 2], 1.0)).unwrap();
    let ip = sim.scene().in_plane.as_ref().unwrap();
    let exact = FreeJointExact::new(1000.0, 50.0);
    let fastest = exact.omegas.iter().fold(0.0f64, |m, &w| m.max(w));
    let rate_error = (ip.free_joint_rate(polar_inertia()) / fastest - 1.0).abs();
    println!("free joint's fastest rate {fastest:.1} rad/s: library {rate_error:.2e} off");
    assert!(rate_error < 1e-6, "{rate_error:e}");
    for integrator in [IntegratorKind::Exponential, IntegratorKind::Rk4] {
        let (twist, speed) = free_joint_errors(integrator);
        assert!(twist < 1e-4, "{}: twist {twist:e}", integrator.name());
        assert!(speed < 1e-4, "{}: speed {speed:e}", integrator.name());
    }
}

/// The amplitudes of every mode and Ω over `steps`, Lagrangian.
fn history(mut sim: Simulation, steps: usize) -> Vec<Vec<f64>> {
    (0..steps)
        .map(|_| {
            sim.step().unwrap();
            let mut row = sim.q_lagrange().to_vec();
            row.push(sim.state().speed);
            row
        })
        .collect()
}

/// Largest difference of the amplitudes (all but the last entry) relative to
/// their peak in `a`, and of Ω relative to its peak.
fn differences(a: &[Vec<f64>], b: &[Vec<f64>]) -> (f64, f64) {
    let n = a[0].len() - 1;
    let peak = |i: std::ops::Range<usize>| {
        a.iter()
            .flat_map(|r| &r[i.clone()])
            .fold(0.0f64, |m, v| m.max(v.abs()))
    };
    let worst = |i: std::ops::Range<usize>| {
        a.iter()
            .zip(b)
            .flat_map(|(x, y)| x[i.clone()].iter().zip(&y[i.clone()]))
            .fold(0.0f64, |m, (x, y)| m.max((x - y).abs()))
    };
    (worst(0..n) / peak(0..n), worst(n..n + 1) / peak(n..n + 1))
}

/// At 3000 rad/s the spin terms couple the torsional and radial k = 0
/// families (Coriolis 2Ω): with the joint free under the brake torque step,
/// the exponential's exact k = 0 block agrees with RK4's (the joint in its
/// unknowns, the spin terms in its stages) — radial amplitudes included,
/// which a block stepped without its spin terms would leave at rest.
#[test]
fn at_speed_the_free_joint_block_with_its_spin_terms_agrees_with_rk4() {
    let run = |integrator| {
        let mut c = disc(&[0], &[0, 1, 2], 200_000.0);
        c.plate.damping = vec![0.02];
        c.joint.speed = 3000.0;
        c.joint.max_torque = Some(50.0);
        c.simulation.integrator = integrator;
        c.simulation.rk4_step_limit = 0.05;
        brake_at_rim(&mut c, 1000.0);
        let mut sim = Simulation::new(c).unwrap();
        sim.set_speed_command(3100.0).unwrap();
        history(sim, 400)
    };
    let exp = run(IntegratorKind::Exponential);
    let rk4 = run(IntegratorKind::Rk4);
    let sim = Simulation::new(disc(&[0], &[0, 1, 2], 1.0)).unwrap();
    let ip = sim.scene().in_plane.clone().unwrap();
    let peak = |family: &str| {
        exp.iter()
            .flat_map(|r| {
                ip.modes
                    .iter()
                    .enumerate()
                    .filter(|(_, m)| m.shape.name() == family)
                    .map(|(j, _)| r[ip.offset + j].abs())
                    .collect::<Vec<_>>()
            })
            .fold(0.0f64, f64::max)
    };
    let (radial, torsional) = (peak("radial"), peak("torsional"));
    let (dq, ds) = differences(&exp, &rk4);
    println!(
        "peaks: radial {radial:.3e} m, torsional {torsional:.3e} m; exponential vs RK4: amplitudes {dq:.2e}, speed {ds:.2e}"
    );
    assert!(
        radial > 1e-2 * torsional,
        "the spin terms move the radial family"
    );
    assert!(dq < 1e-6 && ds < 1e-9, "{dq:e} {ds:e}");
}

/// config/brake_bench.yaml with the k = 0 in-plane modes, clamped at 20 kN
/// (the friction torque 1916.8 N·m above the drive's 1000 N·m): on RK4 the
/// joint rides in its unknowns and the angular momentum J Ω + Σ s q̇ gains
/// (τ_drive + τ_friction) h per step, the pads' friction entering the joint
/// and the torsional modes alike; on `contact_exponential`, whose located
/// switches of the drive's limit did not converge against the hub's ringing,
/// the drive is refused by key.
#[test]
fn the_brake_bench_with_torsional_modes_keeps_the_momentum_balance_on_rk4_and_is_refused_on_the_contact_step(
) {
    let scene = |integrator| {
        let mut c = support::scene_files::load("brake_bench.yaml");
        c.plate.in_plane_nodal_diameters = vec![0];
        c.joint.max_torque = Some(1000.0);
        c.simulation.integrator = integrator;
        c
    };
    let refused = Simulation::new(scene(IntegratorKind::ContactExponential))
        .err()
        .expect("refused")
        .to_string();
    assert!(refused.contains("joint.max_torque"), "{refused}");
    let mut sim = Simulation::new(scene(IntegratorKind::Rk4)).unwrap();
    sim.set_pad_clamp_force(0, 20_000.0).unwrap();
    let ip = sim.scene().in_plane.clone().unwrap();
    let (j, h) = (sim.scene().polar_inertia, 1e-3);
    let momentum = |sim: &Simulation| j * sim.state().speed + ip.twist_momentum(&sim.state().q_dot);
    let mut worst = 0.0f64;
    for _ in 0..2 {
        let m0 = momentum(&sim);
        sim.step().unwrap();
        let friction = sim.pad_output(0).friction_torque;
        let gained = momentum(&sim) - m0;
        worst =
            worst.max((gained - (sim.state().effort + friction) * h).abs() / (friction.abs() * h));
        assert!(sim.state().effort > 0.0 && sim.state().effort <= 1000.0);
    }
    println!(
        "RK4: momentum balance {worst:.2e} of the friction impulse; speed {:.4} rad/s at 2 ms",
        sim.state().speed
    );
    assert!(worst < 1e-9, "{worst:e}");
}

/// With k = 1 pairs beside the k = 0 block and a space-fixed tangential force
/// at the rim (which twists the disc and drives the pairs), the free joint
/// keeps both descriptions together: ALE against Lagrangian on the
/// exponential step and on RK4 (each its own equations), and RK4 against the
/// exponential step.
#[test]
fn the_free_joint_keeps_the_ale_and_lagrangian_descriptions_together() {
    let run = |coordinates, integrator| {
        let mut c = disc(&[0, 1], &[0, 1], 100_000.0);
        c.plate.damping = vec![0.05];
        c.joint.speed = 12.0;
        c.joint.max_torque = Some(20.0);
        c.simulation.coordinates = coordinates;
        c.simulation.integrator = integrator;
        c.simulation.rk4_step_limit = 0.05;
        c.nodes.ale.push(annular_plate::config::NodePosition {
            radial: 1.0,
            angular: 0.1,
        });
        c.loads.ale.push(annular_plate::config::WrenchConfig {
            force: [300.0, -1000.0, 0.0],
            moment: [0.0; 3],
        });
        let mut sim = Simulation::new(c).unwrap();
        sim.set_speed_command(20.0).unwrap();
        (0..400)
            .map(|_| {
                sim.step().unwrap();
                // At its limit throughout: the joint is free.
                assert!((sim.state().effort - 20.0).abs() < 1e-9);
                let mut row = sim.q_lagrange().to_vec();
                row.push(sim.state().speed);
                row
            })
            .collect::<Vec<_>>()
    };
    let ale = run(Coordinates::Ale, IntegratorKind::Exponential);
    let lagrange = run(Coordinates::Lagrangian, IntegratorKind::Exponential);
    let rk4 = run(Coordinates::Lagrangian, IntegratorKind::Rk4);
    let rk4_ale = run(Coordinates::Ale, IntegratorKind::Rk4);
    let (dq_desc, ds_desc) = differences(&ale, &lagrange);
    let (dq_rk4_desc, ds_rk4_desc) = differences(&rk4, &rk4_ale);
    let (dq_rk4, ds_rk4) = differences(&lagrange, &rk4);
    println!(
        "exponential ALE vs Lagrangian {dq_desc:.2e} / {ds_desc:.2e}; RK4 ALE vs Lagrangian {dq_rk4_desc:.2e} / {ds_rk4_desc:.2e}; RK4 vs exponential {dq_rk4:.2e} / {ds_rk4:.2e} (amplitudes / speed)"
    );
    assert!(dq_desc < 1e-9 && ds_desc < 1e-12, "{dq_desc:e} {ds_desc:e}");
    assert!(
        dq_rk4_desc < 1e-6 && ds_rk4_desc < 1e-9,
        "{dq_rk4_desc:e} {ds_rk4_desc:e}"
    );
    assert!(dq_rk4 < 1e-5 && ds_rk4 < 1e-7, "{dq_rk4:e} {ds_rk4:e}");
}
