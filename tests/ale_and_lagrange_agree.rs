//! The two descriptions of the paper's section 3.2 agree: one run integrated in
//! Lagrangian and in ALE coordinates, transformed with eq. (20), gives the same
//! motion — at constant speed and in a spin-up through a critical speed, where
//! the ALE equations' k·dΩ/dt term matters.

mod support;

use annular_plate::config::{Config, Coordinates, IntegratorKind};
use annular_plate::dynamics::Simulation;
use support::fourth_order::assert_fourth_order;
use support::scenes::*;

/// Run `steps` output steps, returning the ALE and Lagrangian amplitude histories.
fn run(c: Config, steps: usize) -> (Vec<Vec<f64>>, Vec<Vec<f64>>) {
    let mut sim = Simulation::new(c).expect("valid scene");
    let (mut ale, mut lag) = (vec![], vec![]);
    for _ in 0..steps {
        sim.step().expect("stable step");
        ale.push(sim.q_ale().to_vec());
        lag.push(sim.q_lagrange().to_vec());
    }
    (ale, lag)
}

fn history_difference(a: &[Vec<f64>], b: &[Vec<f64>]) -> f64 {
    let flat_a: Vec<f64> = a.iter().flatten().copied().collect();
    let flat_b: Vec<f64> = b.iter().flatten().copied().collect();
    relative_difference(&flat_a, &flat_b)
}

/// Lathe disc at 100 rad/s with a space-fixed rim load and a rotating one.
fn constant_speed_scene() -> Config {
    let mut c = with_ale_load(lathe(), 1.0, 0.0, [0.0, 150.0, -400.0]);
    c = with_lagrange_load(c, 0.5, 0.3, [0.0, 0.0, 250.0]);
    c.joint.speed = 100.0;
    c
}

/// Thin disc spun up from 400 to 600 rad/s at 500 rad/s², through the k = 2
/// critical speed (≈ 495.6 rad/s), under a space-fixed load.
fn spin_up_scene() -> Config {
    let mut c = with_ale_load(thin_disc(vec![0, 1, 2, 3]), 1.0, 0.1, [0.0, 0.0, -20.0]);
    c.joint.speed = 400.0;
    c.joint.max_acceleration = 500.0;
    c
}

fn spin_up_run(
    c: Config,
    integrator: IntegratorKind,
    coords: Coordinates,
    rate: f64,
    steps: usize,
) -> (Vec<Vec<f64>>, Vec<Vec<f64>>) {
    let mut sim = Simulation::new(integrated(c, integrator, coords, rate)).unwrap();
    sim.set_speed_command(600.0).unwrap();
    let (mut ale, mut lag) = (vec![], vec![]);
    for _ in 0..steps {
        sim.step().unwrap();
        ale.push(sim.q_ale().to_vec());
        lag.push(sim.q_lagrange().to_vec());
    }
    assert!(
        (sim.joint().velocity - 600.0).abs() < 1e-9,
        "spin-up did not reach the command: {}",
        sim.joint().velocity
    );
    (ale, lag)
}

#[test]
fn exponential_integrator_agrees_to_round_off_at_constant_speed() {
    let steps = 2000;
    let (ale_a, lag_a) = run(
        integrated(
            constant_speed_scene(),
            IntegratorKind::Exponential,
            Coordinates::Ale,
            1000.0,
        ),
        steps,
    );
    let (ale_l, lag_l) = run(
        integrated(
            constant_speed_scene(),
            IntegratorKind::Exponential,
            Coordinates::Lagrangian,
            1000.0,
        ),
        steps,
    );
    let d_ale = history_difference(&ale_a, &ale_l);
    let d_lag = history_difference(&lag_a, &lag_l);
    println!("constant speed, exponential: ALE {d_ale:e}, Lagrangian {d_lag:e}");
    assert!(d_ale < 1e-12 && d_lag < 1e-12);
    // Not vacuous: the space-fixed load makes the Lagrangian amplitudes oscillate
    // while the ALE ones settle.
    let last = steps - 1;
    assert!(history_difference(&ale_a[last - 10..], &lag_a[last - 10..]) > 0.5);
}

#[test]
fn exponential_integrator_agrees_to_round_off_through_a_critical_speed() {
    let (ale_a, lag_a) = spin_up_run(
        spin_up_scene(),
        IntegratorKind::Exponential,
        Coordinates::Ale,
        1000.0,
        500,
    );
    let (ale_l, lag_l) = spin_up_run(
        spin_up_scene(),
        IntegratorKind::Exponential,
        Coordinates::Lagrangian,
        1000.0,
        500,
    );
    let d = history_difference(&ale_a, &ale_l).max(history_difference(&lag_a, &lag_l));
    println!("spin-up, exponential: {d:e}");
    assert!(d < 1e-11);
}

/// RK4 integrates each description's own ODE: in ALE coordinates the pair
/// equations with the gyroscopic 2kΩ, softening k²Ω², circulatory 2ζωkΩ and
/// kΩ̇ terms; in Lagrangian ones the uncoupled modes under rotating loads.
/// Independent discretisations converge to one motion.
#[test]
fn rk4_on_the_ale_equations_and_on_the_lagrangian_ones_converge_to_one_motion_in_a_spin_up() {
    // From 20 kHz up RK4 takes one micro-step per step here (h·λ_max ≤ 0.2), so
    // the rate sets its step. Measured: 2.2e-6, 1.3e-7, 8.4e-9 (ratio ≈ 16: fourth order).
    let mut finest_ale = vec![];
    let d = assert_fourth_order(
        "spin-up, rk4 ALE vs rk4 Lagrangian",
        &[20_000.0, 40_000.0, 80_000.0],
        |rate| {
            let steps = (0.4 * rate) as usize; // 400 → 600 rad/s
            let (ale_a, lag_a) = spin_up_run(
                spin_up_scene(),
                IntegratorKind::Rk4,
                Coordinates::Ale,
                rate,
                steps,
            );
            let (ale_l, lag_l) = spin_up_run(
                spin_up_scene(),
                IntegratorKind::Rk4,
                Coordinates::Lagrangian,
                rate,
                steps,
            );
            let d = history_difference(&ale_a, &ale_l).max(history_difference(&lag_a, &lag_l));
            finest_ale = ale_a;
            d
        },
    );
    assert!(d < 1.5e-8, "{d:e}");
    // The exponential integrator lies on the same motion; its own error in a
    // spin-up is the O(kαh²) phase of the held load (2.7e-8 at 40 kHz, ÷4 per halving).
    let (ale_e, _) = spin_up_run(
        spin_up_scene(),
        IntegratorKind::Exponential,
        Coordinates::Ale,
        80_000.0,
        32_000,
    );
    let d_e = history_difference(&finest_ale, &ale_e);
    println!("spin-up, rk4 ALE vs exponential at 80 kHz: {d_e:e}");
    assert!(d_e < 2e-8, "{d_e:e}");
}

#[test]
fn implicit_midpoint_descriptions_converge_to_each_other_at_second_order() {
    let diff_at = |rate: f64| {
        let steps = (0.4 * rate) as usize;
        let (a, _) = spin_up_run(
            spin_up_scene(),
            IntegratorKind::ImplicitMidpoint,
            Coordinates::Ale,
            rate,
            steps,
        );
        let (l, _) = spin_up_run(
            spin_up_scene(),
            IntegratorKind::ImplicitMidpoint,
            Coordinates::Lagrangian,
            rate,
            steps,
        );
        history_difference(&a[a.len() - 1..], &l[l.len() - 1..])
    };
    let (d1, d2) = (diff_at(10_000.0), diff_at(20_000.0));
    println!(
        "implicit midpoint ALE vs Lagrangian: {d1:e} at 10 kHz, {d2:e} at 20 kHz, ratio {}",
        d1 / d2
    );
    assert!(
        d1 / d2 > 3.0 && d1 / d2 < 5.0,
        "not second order: {d1:e} → {d2:e}"
    );
}

/// The spin-up scene with centrifugal stiffening: Ω(t)²G_k couples ⟨k, 0⟩
/// with ⟨k, 1⟩ (nodal circles 0 and 1) while the joint accelerates.
fn stiffened_spin_up_scene() -> Config {
    let mut c = spin_up_scene();
    c.plate.nodal_circles = vec![0, 1];
    c.centrifugal.stiffening = true;
    c
}

#[test]
fn with_centrifugal_stiffening_the_exponential_integrator_agrees_to_round_off_in_a_spin_up() {
    // G_k is the same block for the cos and sin families, so it commutes with
    // R(kχ): the ALE equations carry the same −Ω²M⁻¹G_k q̄ as the Lagrangian ones.
    let (ale_a, lag_a) = spin_up_run(
        stiffened_spin_up_scene(),
        IntegratorKind::Exponential,
        Coordinates::Ale,
        1000.0,
        500,
    );
    let (ale_l, lag_l) = spin_up_run(
        stiffened_spin_up_scene(),
        IntegratorKind::Exponential,
        Coordinates::Lagrangian,
        1000.0,
        500,
    );
    let d = history_difference(&ale_a, &ale_l).max(history_difference(&lag_a, &lag_l));
    // Not vacuous: the stiffening changes the motion.
    let (ale_u, _) = spin_up_run(
        spin_up_scene_with_circles(),
        IntegratorKind::Exponential,
        Coordinates::Ale,
        1000.0,
        500,
    );
    let effect = history_difference(&ale_u, &ale_a);
    println!(
        "stiffened spin-up, exponential ALE vs Lagrangian: {d:e}; stiffened vs not: {effect:e}"
    );
    assert!(d < 1e-11, "{d:e}");
    assert!(effect > 1e-2, "{effect:e}");
}

fn spin_up_scene_with_circles() -> Config {
    let mut c = spin_up_scene();
    c.plate.nodal_circles = vec![0, 1];
    c
}

/// With stiffening, RK4 on the ALE equations and on the Lagrangian ones (each
/// with −Ω(t)²M⁻¹G_k q at every stage) converge at fourth order to one
/// motion; the exponential integrator (Ω² held at its substep mean) converges
/// to it at second order.
#[test]
fn with_centrifugal_stiffening_rk4_descriptions_converge_and_the_exponential_follows_at_second_order(
) {
    let mut reference = vec![];
    // From 60 kHz up RK4 takes one inner step per step (h·λ_max ≤ 0.2, λ_max
    // with ⟨3, 1⟩ and the stiffening ≈ 1.2e4 1/s), so the rate sets its step.
    assert_fourth_order(
        "stiffened spin-up, rk4 ALE vs Lagrangian",
        &[60_000.0, 120_000.0, 240_000.0],
        |rate| {
            let steps = (0.4 * rate) as usize;
            let (ale_a, lag_a) = spin_up_run(
                stiffened_spin_up_scene(),
                IntegratorKind::Rk4,
                Coordinates::Ale,
                rate,
                steps,
            );
            let (ale_l, lag_l) = spin_up_run(
                stiffened_spin_up_scene(),
                IntegratorKind::Rk4,
                Coordinates::Lagrangian,
                rate,
                steps,
            );
            let d = history_difference(&ale_a, &ale_l).max(history_difference(&lag_a, &lag_l));
            let inner = {
                let mut sim = Simulation::new(integrated(
                    stiffened_spin_up_scene(),
                    IntegratorKind::Rk4,
                    Coordinates::Ale,
                    rate,
                ))
                .unwrap();
                sim.step().unwrap();
                sim.inner_substeps()
            };
            println!("stiffened spin-up at {rate} Hz: {inner} inner steps");
            reference = ale_a;
            d
        },
    );
    // The exponential integrator against the finest RK4, on the final state.
    let exp_at = |rate: f64| {
        let steps = (0.4 * rate) as usize;
        let (ale_e, _) = spin_up_run(
            stiffened_spin_up_scene(),
            IntegratorKind::Exponential,
            Coordinates::Ale,
            rate,
            steps,
        );
        history_difference(&ale_e[steps - 1..], &reference[reference.len() - 1..])
    };
    let (e1, e2) = (exp_at(10_000.0), exp_at(20_000.0));
    println!("stiffened spin-up, exponential vs rk4 at 240 kHz: {e1:e} at 10 kHz, {e2:e} at 20 kHz (ratio {})", e1 / e2);
    assert!(
        e1 / e2 > 3.0 && e1 / e2 < 5.0,
        "not second order: {e1:e} → {e2:e}"
    );
}
