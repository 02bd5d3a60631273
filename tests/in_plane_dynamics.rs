//! In-plane modes carried by the dynamics (docs/in_plane.md, "In the
//! dynamics"): the disc twisting between hub and rim under a brake torque
//! step against the two-degree-of-freedom closed form built here from the
//! exact torsional solution (Bessel functions, no library numerics); the
//! static twist under a held tangential force against the exact modal static
//! sum; ALE and Lagrangian descriptions (and RK4) agreeing on k ≥ 1 pairs
//! under a space-fixed load.

mod support;

use annular_plate::config::{Coordinates, IntegratorKind, NodePosition, WrenchConfig};
use annular_plate::dynamics::Simulation;
use support::torsion_disc::{brake_at_rim, disc, exact_torsion, polar_inertia, RA};

/// The state index of the torsional mode (the in-plane table after the bending modes).
fn torsional_index(sim: &Simulation) -> usize {
    let ip = sim.scene().in_plane.as_ref().expect("in-plane modes");
    ip.offset + ip.torsional[0]
}

/// Mean of cos ω t over the step ending at t.
fn step_mean_cos(omega: f64, t: f64, h: f64) -> f64 {
    ((omega * t).sin() - (omega * (t - h)).sin()) / (omega * h)
}

#[test]
fn a_brake_torque_step_on_a_speed_held_hub_rings_at_the_exact_torsional_frequency() {
    let (rate, force) = (200_000.0, 1000.0);
    let mut c = disc(&[0], &[0], rate);
    brake_at_rim(&mut c, force);
    let mut sim = Simulation::new(c).unwrap();
    let t = exact_torsion(0);
    let i = torsional_index(&sim);
    let f = -4.0 * force * t.v_rim;
    let torque = -4.0 * force * RA;
    let k = t.mass * t.omega * t.omega;
    let (mut worst_q, mut worst_effort, mut crossings) = (0.0f64, 0.0f64, vec![]);
    let h = 1.0 / rate;
    let static_twist = f / k;
    let mut last = (0.0, -static_twist);
    for step in 1..=2000 {
        sim.step().unwrap();
        let time = step as f64 * h;
        let q = sim.q_lagrange()[i];
        let exact = static_twist * (1.0 - (t.omega * time).cos());
        worst_q = worst_q.max((q - exact).abs() / (2.0 * static_twist.abs()));
        // Stiff drive, Ω̇ = 0: effort = s q̈ − τ_loads, the step's mean.
        let effort = t.coupling * f / t.mass * step_mean_cos(t.omega, time, h) - torque;
        let scale = torque.abs() + (t.coupling * f / t.mass).abs();
        worst_effort = worst_effort.max((sim.state().effort - effort).abs() / scale);
        assert_eq!(sim.state().speed, 0.0);
        let x = q - static_twist;
        if last.1 < 0.0 && x >= 0.0 {
            crossings.push(last.0 + h * last.1 / (last.1 - x));
        }
        last = (time, x);
    }
    let measured = (crossings.len() - 1) as f64 / (crossings.last().unwrap() - crossings[0])
        * std::f64::consts::TAU;
    let freq_error = (measured / t.omega - 1.0).abs();
    println!(
        "exact ω = {:.3} rad/s ({:.3} Hz), rung {:.3} rad/s: {:.2e}; twist {:.2e}, effort {:.2e} of scale",
        t.omega,
        t.omega / std::f64::consts::TAU,
        measured,
        freq_error,
        worst_q,
        worst_effort
    );
    assert!(freq_error < 1e-4, "frequency {freq_error:e}");
    assert!(worst_q < 0.01, "twist {worst_q:e}");
    assert!(worst_effort < 0.01, "effort {worst_effort:e}");
}

#[test]
fn a_brake_torque_step_on_a_torque_limited_drive_follows_the_two_degree_of_freedom_closed_form() {
    let (rate, force, limit) = (200_000.0, 1000.0, 50.0);
    let mut c = disc(&[0], &[0], rate);
    c.joint.max_torque = Some(limit);
    brake_at_rim(&mut c, force);
    let mut sim = Simulation::new(c).unwrap();
    // Commanded forward, braked backward: the drive pushes at its limit throughout.
    sim.set_speed_command(15.0).unwrap();
    let t = exact_torsion(0);
    let i = torsional_index(&sim);
    let j = polar_inertia();
    // [J s; s m] [χ̈; q̈] + [0 0; 0 k] [χ; q] = [τ; f], τ = +limit (the drive holds
    // against the brake at its limit) plus the brake torque.
    let f = -4.0 * force * t.v_rim;
    let tau = limit - 4.0 * force * RA;
    let reduced = t.mass - t.coupling * t.coupling / j;
    let k = t.mass * t.omega * t.omega;
    let w = (k / reduced).sqrt();
    let amplitude = (f - t.coupling * tau / j) / k;
    let h = 1.0 / rate;
    let (mut worst_q, mut worst_speed, mut speed_scale) = (0.0f64, 0.0f64, 0.0f64);
    for step in 1..=400 {
        sim.step().unwrap();
        let time = step as f64 * h;
        let q = amplitude * (1.0 - (w * time).cos());
        let q_dot = amplitude * w * (w * time).sin();
        let speed = (tau * time - t.coupling * q_dot) / j;
        worst_q = worst_q.max((sim.q_lagrange()[i] - q).abs() / (2.0 * amplitude.abs()));
        worst_speed = worst_speed.max((sim.state().speed - speed).abs());
        speed_scale = speed_scale.max(speed.abs());
        assert_eq!(sim.state().effort, limit);
    }
    println!(
        "2-dof: ω* = {w:.3} rad/s (clamped hub {:.3}), twist {:.2e}, speed {:.2e} of {speed_scale:.3} rad/s",
        t.omega,
        worst_q,
        worst_speed / speed_scale
    );
    assert!(worst_q < 0.01, "twist {worst_q:e}");
    assert!(worst_speed < 0.01 * speed_scale, "speed {worst_speed:e}");
}

#[test]
fn a_held_tangential_force_twists_the_rim_to_the_exact_modal_static_sum() {
    let force = 2000.0;
    let mut c = disc(&[0], &[0, 1, 2], 100_000.0);
    c.plate.damping = vec![0.4];
    c.nodes.ale.push(NodePosition {
        radial: 1.0,
        angular: 0.0,
    });
    c.loads.ale.push(WrenchConfig {
        force: [0.0, force, 0.0],
        moment: [0.0; 3],
    });
    let mut sim = Simulation::new(c).unwrap();
    let ip = sim.scene().in_plane.clone().unwrap();
    for _ in 0..2000 {
        sim.step().unwrap();
    }
    let mut twist = 0.0;
    let mut exact = 0.0;
    for l in 0..3 {
        let t = exact_torsion(l);
        exact += t.v_rim * t.v_rim * force / (t.mass * t.omega * t.omega);
        let j = ip
            .modes
            .iter()
            .position(|m| m.l == l as u32 && m.shape.name() == "torsional")
            .unwrap();
        twist += t.v_rim * sim.q_lagrange()[ip.offset + j];
    }
    let radial: f64 = ip
        .modes
        .iter()
        .enumerate()
        .filter(|(_, m)| m.shape.name() == "radial")
        .map(|(j, _)| sim.q_lagrange()[ip.offset + j].abs())
        .sum();
    let error = (twist / exact - 1.0).abs();
    println!("static rim twist {twist:.6e} m, exact modal sum {exact:.6e} m: {error:.2e}; radial {radial:e}");
    assert!(error < 1e-6, "{error:e}");
    assert_eq!(radial, 0.0);
}

/// k = 1, 2 pairs under a space-fixed force at a turning disc: the ALE and
/// Lagrangian descriptions (exponential) agree, and RK4 agrees with both.
#[test]
fn ale_and_lagrangian_descriptions_agree_on_in_plane_pairs_under_a_space_fixed_load() {
    let run = |coordinates, integrator| {
        let mut c = disc(&[1, 2], &[0], 100_000.0);
        c.plate.damping = vec![0.05];
        c.joint.speed = 12.0;
        c.simulation.coordinates = coordinates;
        c.simulation.integrator = integrator;
        c.nodes.ale.push(NodePosition {
            radial: 1.0,
            angular: 0.1,
        });
        c.loads.ale.push(WrenchConfig {
            force: [300.0, -1000.0, 0.0],
            moment: [0.0; 3],
        });
        let mut sim = Simulation::new(c).unwrap();
        let mut history = vec![];
        for _ in 0..1000 {
            sim.step().unwrap();
            history.push(sim.q_lagrange().to_vec());
        }
        history
    };
    let ale = run(Coordinates::Ale, IntegratorKind::Exponential);
    let lagrange = run(Coordinates::Lagrangian, IntegratorKind::Exponential);
    let rk4 = run(Coordinates::Lagrangian, IntegratorKind::Rk4);
    let rk4_ale = run(Coordinates::Ale, IntegratorKind::Rk4);
    let scale = ale.iter().flatten().fold(0.0f64, |a, v| a.max(v.abs()));
    let worst = |a: &[Vec<f64>], b: &[Vec<f64>]| {
        a.iter()
            .flatten()
            .zip(b.iter().flatten())
            .fold(0.0f64, |m, (x, y)| m.max((x - y).abs()))
            / scale
    };
    let (d_desc, d_rk4) = (worst(&ale, &lagrange), worst(&lagrange, &rk4));
    // RK4 integrates the ALE equations themselves (gyroscopic 2kΩ, softening k²Ω²).
    let d_rk4_desc = worst(&rk4, &rk4_ale);
    println!("largest amplitude {scale:.3e} m; exponential ALE vs Lagrangian {d_desc:.2e}, exponential vs RK4 {d_rk4:.2e}, RK4 ALE vs Lagrangian {d_rk4_desc:.2e}");
    assert!(scale > 1e-9);
    assert!(d_desc < 1e-9, "{d_desc:e}");
    assert!(d_rk4 < 1e-5, "{d_rk4:e}");
    assert!(d_rk4_desc < 1e-5, "{d_rk4_desc:e}");
}
