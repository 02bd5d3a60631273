//! The default scene, the brake test bench (`config/brake_bench.yaml`): pads
//! whose clamp force a script commands brake a torque-limited drive; held long
//! enough they bring the disc to rest.

mod support;

use annular_plate::dynamics::load_models::pad_outputs::PadOutputs;
use annular_plate::dynamics::Simulation;
use support::scene_files as scenes;

#[test]
fn a_disc_braked_to_standstill_comes_to_rest_without_chattering() {
    let mut sim = Simulation::new(scenes::load("brake_bench.yaml")).unwrap();
    assert!(sim.pad_count() >= 1);
    for _ in 0..200 {
        sim.step().unwrap();
    }
    let start = sim.joint().velocity;
    assert!(
        (start - 25.0).abs() < 1e-9,
        "bench runs at 25 rad/s: {start}"
    );
    // 20 kN per face: 2μN r ≈ 1.9 kN·m, above the drive's 1.5 kN·m limit.
    for pad in 0..sim.pad_count() {
        sim.set_pad_clamp_force(pad, 20_000.0).unwrap();
    }
    let mut speeds = vec![];
    for _ in 0..2000 {
        sim.step().unwrap();
        speeds.push(sim.joint().velocity);
    }
    let stop = speeds
        .iter()
        .position(|&w| w.abs() < 0.05)
        .expect("the disc must come to rest");
    let after = &speeds[stop..];
    let (lo, hi) = after
        .iter()
        .fold((f64::MAX, f64::MIN), |(lo, hi), &w| (lo.min(w), hi.max(w)));
    println!(
        "stopped after {} ms; afterwards Ω in [{lo:e}, {hi:e}] rad/s",
        stop + 1
    );
    // Decelerating monotonically to rest, never reversing: friction cannot drive the disc backwards.
    assert!(
        speeds[..stop].windows(2).all(|w| w[1] <= w[0] + 1e-12),
        "not monotone before rest"
    );
    assert!(
        lo > -0.05 && hi < 0.05,
        "chatter at standstill: [{lo}, {hi}]"
    );
    // At rest the drive's limit torque is held by the regularised friction,
    // −Σ μ N r tanh(Ω r / v_reg): Ω = atanh(τ_max / 2μN r) · v_reg / r (every contact at one r).
    let p = sim.pad_output(0);
    let r = p.friction_torque / p.friction_force;
    let capacity = 2.0 * 0.4 * 20_000.0 * r;
    let expected = (1500.0 / capacity).atanh() * 1.0e-3 / r;
    let last = *speeds.last().unwrap();
    println!("at rest: Ω = {last:e} rad/s, closed form {expected:e}");
    assert!(
        (last - expected).abs() < 1e-6 * expected,
        "{last} vs {expected}"
    );
    assert_eq!(sim.joint().effort, 1500.0);
    assert!(sim.q_ale().iter().all(|q| q.is_finite()));
}
