//! Conservation and the rigid-body limit: undamped free vibration keeps its
//! energy over 10⁶ steps, and with the modes frozen (no elastic excitation)
//! the plate turns as the rigid annulus of Newton–Euler about its axis.

mod support;

use annular_plate::config::{Coordinates, IntegratorKind, NodePosition, WrenchConfig};
use annular_plate::dynamics::{Simulation, Wrench};
use std::f64::consts::PI;
use support::scenes::*;

fn free_vibration_energy_drift(
    integrator: IntegratorKind,
    coordinates: Coordinates,
    steps: usize,
) -> (f64, f64) {
    let mut c = integrated(lathe(), integrator, coordinates, 1000.0);
    c.plate.damping = vec![0.0];
    c.joint.speed = 100.0;
    // Energy conservation is a property of the midpoint map at any h: one inner
    // step per step (unresolved on purpose), as before sub-stepping existed.
    c.simulation.midpoint_step_limit = 1e6;
    let mut sim = Simulation::new(c).unwrap();
    let mut state = sim.state().clone();
    for (i, (q, v)) in state.q.iter_mut().zip(state.q_dot.iter_mut()).enumerate() {
        *q = 1e-6 * ((i * 37 % 11) as f64 - 5.0);
        *v = 1e-3 * ((i * 17 % 7) as f64 - 3.0);
    }
    state.rederive(sim.scene());
    sim.restore(state);
    let e0 = sim.modal_energy();
    let mut worst: f64 = 0.0;
    for s in 0..steps {
        sim.step().unwrap();
        if s % 1000 == 0 {
            worst = worst.max((sim.modal_energy() - e0).abs() / e0);
        }
    }
    let end = (sim.modal_energy() - e0).abs() / e0;
    (worst.max(end), e0)
}

#[test]
fn undamped_free_vibration_keeps_its_energy_over_a_million_steps() {
    for (integrator, coords) in [
        (IntegratorKind::Exponential, Coordinates::Ale),
        (IntegratorKind::Exponential, Coordinates::Lagrangian),
        (IntegratorKind::ImplicitMidpoint, Coordinates::Lagrangian),
        (IntegratorKind::ImplicitMidpoint, Coordinates::Ale),
    ] {
        let (drift, e0) = free_vibration_energy_drift(integrator, coords, 1_000_000);
        println!(
            "{integrator:?}/{coords:?}: E0 = {e0:e} J, max relative drift over 1e6 steps {drift:e}"
        );
        assert!(drift < 1e-9, "{integrator:?}/{coords:?}: {drift:e}");
    }
}

#[test]
fn rk4_never_gains_energy_in_free_vibration() {
    let mut c = integrated(
        lathe(),
        IntegratorKind::Rk4,
        Coordinates::Lagrangian,
        1000.0,
    );
    c.plate.damping = vec![0.0];
    let mut sim = Simulation::new(c).unwrap();
    let mut state = sim.state().clone();
    state
        .q
        .iter_mut()
        .enumerate()
        .for_each(|(i, q)| *q = 1e-6 * (1.0 + i as f64 % 3.0));
    state.rederive(sim.scene());
    sim.restore(state);
    let mut e = sim.modal_energy();
    let e0 = e;
    for _ in 0..200 {
        sim.step().unwrap();
        let e1 = sim.modal_energy();
        assert!(e1 <= e * (1.0 + 1e-13), "energy grew: {e} → {e1}");
        e = e1;
    }
    println!(
        "rk4 ({} substeps per step): energy {e0:e} → {e:e} J over 200 steps",
        sim.inner_substeps()
    );
    assert!(
        e > 0.9 * e0,
        "rk4 as a reference must not damp strongly: {e0:e} → {e:e}"
    );
}

/// Annulus polar inertia, closed form.
fn polar_inertia(c: &annular_plate::config::Config) -> f64 {
    let p = &c.plate;
    let m = p.density * p.thickness * PI * (p.outer_radius.powi(2) - p.inner_radius.powi(2));
    0.5 * m * (p.outer_radius.powi(2) + p.inner_radius.powi(2))
}

#[test]
fn braking_torque_decelerates_the_plate_as_a_rigid_annulus() {
    // A tangential (friction) force on an ALE node at the rim, no normal force:
    // the modes stay at rest, the plate is a rigid body turning about z.
    let mut c = lathe();
    c.joint.speed = 50.0;
    c.joint.max_torque = Some(1.0);
    c.nodes.ale.push(NodePosition {
        radial: 1.0,
        angular: 0.25,
    });
    // At θ = 90° the tangential direction of +Ω is −x: a +x force brakes.
    let f = 40.0;
    c.loads.ale.push(WrenchConfig {
        force: [f, 0.0, 0.0],
        moment: [0.0; 3],
    });
    let j = polar_inertia(&c);
    let r = c.plate.outer_radius;
    let mut sim = Simulation::new(c).unwrap();
    assert!((sim.scene().polar_inertia - j).abs() < 1e-12 * j);
    let t_end = 0.5;
    let steps = (t_end / sim.dt()) as usize;
    for _ in 0..steps {
        sim.step().unwrap();
    }
    // Drive saturates at +1 N·m holding 50 rad/s against −f·r.
    let alpha = (1.0 - f * r) / j;
    let expected_speed = 50.0 + alpha * t_end;
    let expected_angle = 50.0 * t_end + 0.5 * alpha * t_end * t_end;
    let jo = sim.joint();
    println!(
        "Ω = {} (expect {expected_speed}), χ = {} (expect {expected_angle}), effort {}",
        jo.velocity, jo.position, jo.effort
    );
    assert!((jo.velocity - expected_speed).abs() < 1e-10 * 50.0);
    assert!((jo.position - expected_angle).abs() < 1e-10 * expected_angle);
    assert_eq!(jo.effort, 1.0);
    assert!(
        sim.q_lagrange().iter().all(|q| *q == 0.0),
        "in-plane loads must not excite the transverse modes"
    );
}

#[test]
fn stiff_drive_effort_is_the_newton_euler_torque() {
    let mut c = lathe();
    c.joint.speed = 0.0;
    c.joint.max_acceleration = 80.0;
    let j = polar_inertia(&c);
    let mut sim = Simulation::new(c).unwrap();
    sim.set_speed_command(10.0).unwrap();
    sim.step().unwrap();
    assert!((sim.joint().effort - j * 80.0).abs() < 1e-12 * j * 80.0);
    // with a braking tangential wrench the drive also supplies that torque
    sim.set_speed_command(sim.joint().velocity).unwrap();
    let mut c2 = lathe();
    c2.nodes.ale.push(NodePosition {
        radial: 0.5,
        angular: 0.0,
    });
    let mut sim2 = Simulation::new(c2).unwrap();
    sim2.set_ale_wrench(
        0,
        Wrench {
            force: [0.0, -30.0, 0.0],
            moment: [0.0, 0.0, 2.0],
        },
    )
    .unwrap();
    sim2.step().unwrap();
    let r = 0.075 + 0.5 * 0.075;
    assert!((sim2.joint().effort - (30.0 * r - 2.0)).abs() < 1e-12);
}
