//! The shipped squeal scene, config/brake_squeal.yaml, with the lining's
//! shear it carries from its documented lining data (docs/scenes.md, "Pad shear"):
//! E = 125 MPa, ν = 0.3 → G = 48 MPa; 40 cm² per face, 10 mm thick →
//! G A / t = 1.92e7 N/m per pad face, over the 18 contact points
//! k_t = 1.07e6 N/m; loss factor 0.1 at the 1.52 kHz squeal →
//! c_t = 0.1 k_t / ω = 11.2 N·s/m. The threshold falls from 0.419 to about
//! half; below it a vibration decays; above it (the scene's μ = 0.5) it grows
//! and is bounded — the test finds what bounds it: intervals of stick (a face
//! sliding on its patch at less than 10 v_reg) or lift-off (a face without
//! normal force), and reports the amplitude.

mod support;

use annular_plate::config::{Config, IntegratorKind};
use annular_plate::dynamics::load_models::pad::PadScratch;
use annular_plate::dynamics::load_models::pad::FRICTION_REGULARISATION_SPEED;
use annular_plate::dynamics::load_models::pad_config::PadsConfig;
use annular_plate::dynamics::load_models::pad_outputs::PadOutputs;
use annular_plate::dynamics::{stability, Simulation};
use support::scene_files as scenes;

const SHEAR: (f64, f64) = (1.07e6, 11.2);

/// The shipped scene (its lining data and its integrator, RK4) at μ = `mu`.
fn scene(mu: f64) -> Config {
    let mut c = scenes::load("brake_squeal.yaml");
    assert_eq!(c.simulation.integrator, IntegratorKind::Rk4);
    let pads = c.section_mut::<PadsConfig>().unwrap();
    assert_eq!(pads.shear, Some(SHEAR), "the documented lining data");
    pads.friction_coefficient = mu;
    c
}

fn threshold() -> f64 {
    let sim = Simulation::new(scene(0.5)).unwrap();
    stability::friction_threshold(sim.scene(), sim.config().joint.speed, 2.0)
        .expect("squeals below μ = 2")
}

/// Per 0.1 s window: the largest |q̄|, the share of steps with a face in
/// stick (relative speed < 10 v_reg under a closed face) and the share with
/// a face lifted off.
fn windows(mu: f64, seconds: f64) -> Vec<(f64, f64, f64)> {
    let mut sim = Simulation::new(scene(mu)).unwrap();
    let per = (0.1 / sim.dt()).round() as usize;
    let stick_speed = 10.0 * FRICTION_REGULARISATION_SPEED;
    let mut out = Vec::new();
    for _ in 0..(seconds / 0.1).round() as usize {
        let (mut amp, mut stick, mut lifted) = (0.0f64, 0usize, 0usize);
        for _ in 0..per {
            sim.step().unwrap();
            amp = sim.q_ale().iter().fold(amp, |a, q| a.max(q.abs()));
            let forces = sim.pad_contact_forces();
            let slip = &sim
                .model_wrenches()
                .scratch::<PadScratch>(0)
                .expect("the pads' scratch")
                .slip;
            let closed = |c: usize, face: usize| {
                let f = &forces[c];
                [f.top, f.bottom][face] > 0.0
            };
            if (0..slip.len()).any(|c| (0..2).any(|f| closed(c, f) && slip[c][f] < stick_speed)) {
                stick += 1;
            }
            if forces.iter().any(|f| f.top == 0.0 || f.bottom == 0.0) {
                lifted += 1;
            }
        }
        out.push((amp, stick as f64 / per as f64, lifted as f64 / per as f64));
    }
    out
}

#[test]
fn with_lining_shear_the_threshold_halves_and_the_squeal_is_bounded() {
    let mu_c = threshold();
    println!("threshold with lining shear: μ_c = {mu_c:.6}");
    assert!(mu_c > 0.15 && mu_c < 0.3, "{mu_c}");
    let below = windows(0.8 * mu_c, 0.3);
    println!("μ = 0.8 μ_c: {below:?}");
    assert!(
        below.last().unwrap().0 < 0.5 * below[0].0,
        "decays: {below:?}"
    );
    let above = windows(0.5, 1.5);
    for (j, (amp, stick, lifted)) in above.iter().enumerate() {
        println!(
            "t = {:.1}..{:.1} s: |q̄| {amp:.4e} m, steps with stick {:.3}, with lift-off {:.3}",
            0.1 * j as f64,
            0.1 * (j + 1) as f64,
            stick,
            lifted
        );
    }
    let n = above.len();
    let (amp, _, _) = above[n - 1];
    let start = scene(0.5)
        .initial
        .q
        .iter()
        .fold(0.0f64, |a, q| a.max(q.abs()));
    assert!(amp > 100.0 * start, "it squeals from {start} m: {above:?}");
    // Bounded: the amplitude's change over the last 0.3 s against e^{0.3 Re λ}.
    let change = amp / above[n - 4].0;
    println!("amplitude {amp:.4e} m, ×{change:.4} over the last 0.3 s");
    assert!(change < 1.05, "settles: ×{change}");
    let stick: f64 = above[n - 3..].iter().map(|w| w.1).sum::<f64>() / 3.0;
    let lifted: f64 = above[n - 3..].iter().map(|w| w.2).sum::<f64>() / 3.0;
    println!("last 0.3 s: steps with stick {stick:.3}, with lift-off {lifted:.3}");
    assert!(stick > 0.0 || lifted > 0.0, "bounded by stick or lift-off");
}
