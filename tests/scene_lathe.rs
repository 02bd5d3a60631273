//! The paper's lathe cutting model (section 5.1, Figs. 7–10) as
//! `config/lathe.yaml`: a tool fed along the axis onto the rim of a spinning
//! disc, its feed force from the instantaneous chip (eq. 21), applied at an
//! ALE node. Fig. 9: once the cut is steady the ALE amplitudes of the
//! ⟨k = 1, l = 0⟩ pair are stationary, while the Lagrangian ones turn with the
//! disc at the rotation frequency.

mod support;

use annular_plate::config::{Config, ConfigError};
use annular_plate::dynamics::load_models::pad_outputs::PadOutputs;
use annular_plate::dynamics::load_models::tool::ToolOutputs;
use annular_plate::dynamics::{LoadCommandError, Simulation};
use std::f64::consts::TAU;

use support::scene_files::{self as scenes, run_to};

fn scene() -> Config {
    scenes::load("lathe.yaml")
}

/// Eq. (21) in the paper's units: b and h in mm, k_f1.1 = 351 N/mm², m_f = 0.7013.
fn kienzle(b_mm: f64, h_mm: f64) -> f64 {
    b_mm * h_mm.powf(1.0 - 0.7013) * 351.0
}

/// Index of the ⟨k = 1, l = 0⟩ cos mode and its sin partner.
fn first_pair(sim: &Simulation) -> (usize, usize) {
    let p = sim
        .scene()
        .layout
        .pairs
        .iter()
        .find(|p| p.k == 1 && sim.model().modes()[p.cos].l == 0)
        .unwrap();
    (p.cos, p.sin)
}

#[test]
fn the_tool_reaches_the_disc_at_a_quarter_second_and_then_cuts_the_feed_per_revolution() {
    let mut sim = Simulation::new(scene()).unwrap();
    let speed = sim.config().joint.speed;
    // 0.5 mm clearance at 120 mm/min: first contact at 0.25 s.
    run_to(&mut sim, 0.249);
    assert_eq!(sim.tool_output().unwrap().feed_force, 0.0);
    run_to(&mut sim, 0.252);
    assert!(sim.tool_output().unwrap().feed_force > 0.0);
    // The chip grows over the first revolution: the force rises.
    let mut last = 0.0;
    while sim.time() < 0.25 + TAU / speed {
        let next = sim.time() + 0.01;
        run_to(&mut sim, next);
        let f = sim.tool_output().unwrap().feed_force;
        assert!(
            f >= last,
            "the feed force fell while the chip grows: {f} < {last} at {}",
            sim.time()
        );
        last = f;
    }
    // Steady: the chip is the feed per revolution, the force eq. (21) for it.
    run_to(&mut sim, 2.0);
    let tool = sim.tool_output().unwrap();
    let chip = TAU * 0.002 / speed;
    let force = kienzle(1.0, chip * 1e3);
    println!("steady cut: chip {:.6} mm (feed per revolution {:.6} mm), feed force {:.3} N (eq. 21: {force:.3} N)", tool.chip * 1e3, chip * 1e3, tool.feed_force);
    assert!((tool.chip - chip).abs() < 1e-3 * chip);
    assert!((tool.feed_force - force).abs() < 1e-3 * force);
    // The force pushes the rim down at the tool.
    assert!(sim.ale_node(0).uz < 0.0);
    assert!((sim.ale_model_wrench(0).force[2] + tool.feed_force).abs() < 1e-9 * force);
}

#[test]
fn ale_amplitudes_are_stationary_while_lagrangian_ones_turn_with_the_disc() {
    // Fig. 9: after ≈ 1.23 s the cut is steady.
    let mut sim = Simulation::new(scene()).unwrap();
    let speed = sim.config().joint.speed;
    let (c, s) = first_pair(&sim);
    run_to(&mut sim, 1.23);
    let (mut ale, mut lag_c, mut phase, mut t) = (Vec::new(), Vec::new(), Vec::new(), Vec::new());
    while sim.time() < 5.0 {
        sim.step().unwrap();
        ale.push((sim.q_ale()[c], sim.q_ale()[s]));
        lag_c.push(sim.q_lagrange()[c]);
        // z = q_c + i q_s turns as e^{−ikχ} in the Lagrangian description.
        phase.push(sim.q_lagrange()[s].atan2(sim.q_lagrange()[c]));
        t.push(sim.time());
        let (zl, za) = (
            sim.q_lagrange()[c].hypot(sim.q_lagrange()[s]),
            sim.q_ale()[c].hypot(sim.q_ale()[s]),
        );
        assert!(
            (zl - za).abs() < 1e-12 * za,
            "|z| differs between the descriptions"
        );
    }
    let mean = ale.iter().map(|a| a.0).sum::<f64>() / ale.len() as f64;
    let spread = ale.iter().map(|a| (a.0 - mean).abs()).fold(0.0, f64::max) / mean.abs();
    let sin_part = ale.iter().map(|a| a.1.abs()).fold(0.0, f64::max) / mean.abs();
    let (lo, hi) = lag_c
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), &v| {
            (lo.min(v), hi.max(v))
        });
    println!("ALE ⟨1,0⟩ cos: mean {mean:.6e} m, spread {spread:.2e} (relative), sin part {sin_part:.2e}; Lagrangian cos: {lo:.3e} .. {hi:.3e} m");
    assert!(spread < 2e-3, "ALE amplitude not stationary: {spread}");
    assert!(
        sin_part < 1e-3,
        "a load at θ = 0 does not load the ALE sin mode"
    );
    assert!(
        hi > 0.99 * mean.abs() && lo < -0.99 * mean.abs(),
        "the Lagrangian amplitude does not swing between ±|q̄|"
    );
    // Its phase turns backwards at the rotation speed: fit the unwrapped phase.
    let mut unwrapped = vec![phase[0]];
    for w in phase.windows(2) {
        let mut d = w[1] - w[0];
        d -= TAU * (d / TAU).round();
        unwrapped.push(unwrapped.last().unwrap() + d);
    }
    let slope = support::fit::least_squares_slope(&t, &unwrapped);
    println!("Lagrangian phase rate {slope:.9} rad/s, −Ω = {:.9}", -speed);
    assert!((slope + speed).abs() < 1e-6 * speed);
}

#[test]
fn the_deflection_under_the_tool_is_the_steady_ale_response_to_the_feed_force() {
    // docs/dynamics.md: a space-fixed load F at (r_a, θ = 0) gives per pair
    // q̄_c = a f/(m (a² + b²)), a = ω² − k²Ω², b = 2ζωkΩ, f = F R(r_a); k = 0: f/(mω²).
    let mut sim = Simulation::new(scene()).unwrap();
    run_to(&mut sim, 3.0);
    let speed = sim.config().joint.speed;
    let force = -sim.tool_output().unwrap().feed_force;
    let r_a = sim.model().plate().outer_radius;
    let expected: f64 = sim
        .model()
        .modes()
        .iter()
        .filter(|m| m.shape != annular_plate::model::AngularShape::Sin)
        .map(|m| {
            let rr = sim.model().radial_shapes()[m.radial].value(r_a);
            let (k, w) = (m.k as f64, m.omega);
            let (a, b) = (
                w * w - k * k * speed * speed,
                2.0 * m.damping * w * k * speed,
            );
            rr * a * force * rr / (m.modal_mass * (a * a + b * b))
        })
        .sum();
    // the modal part: uz less the truncated modes' static deflection (docs/residual_flexibility.md)
    let got = sim.ale_node(0).uz - sim.residual_deflection(0);
    println!("deflection under the tool {got:.6e} m (modal; with the residual {:.6e} m), steady ALE response {expected:.6e} m", sim.ale_node(0).uz);
    assert!((got - expected).abs() < 1e-3 * expected.abs());
}

#[test]
fn the_tool_leaves_through_the_far_face_and_the_force_dies_within_a_revolution() {
    let mut sim = Simulation::new(scene()).unwrap();
    let speed = sim.config().joint.speed;
    run_to(&mut sim, 5.2);
    let steady = sim.tool_output().unwrap().feed_force;
    assert!((steady - kienzle(1.0, TAU * 2.0 / speed)).abs() < 1e-3 * steady);
    // The holder passes the −z face (−h/2) at 0.25 + 10 mm / (2 mm/s) = 5.25 s; the tip,
    // pushed back by 18 µm over a disc pushed down by 23 µm, some 20 ms later.
    // One revolution on, the last chip is cut.
    run_to(&mut sim, 5.25 + TAU / speed + 0.05);
    let tool = sim.tool_output().unwrap();
    assert_eq!(tool.feed_force, 0.0, "{tool:?}");
    assert!(tool.tip < -0.005);
}

#[test]
fn feed_commands_change_the_chip_and_bad_ones_are_refused() {
    let mut sim = Simulation::new(scene()).unwrap();
    let speed = sim.config().joint.speed;
    run_to(&mut sim, 1.5);
    sim.set_tool_feed(0.004).unwrap();
    run_to(&mut sim, 1.5 + 1.5 * TAU / speed);
    let chip = sim.tool_output().unwrap().chip;
    assert!((chip - TAU * 0.004 / speed).abs() < 2e-3 * chip, "{chip}");
    for bad in [f64::NAN, 2.0] {
        let e = sim.set_tool_feed(bad).unwrap_err();
        assert!(e.to_string().contains("tool feed rate"), "{e}");
    }
    assert_eq!(
        sim.tool_output().unwrap().feed_rate,
        0.004,
        "a refused command changes nothing"
    );
    assert!(matches!(
        sim.set_pad_clamp_force(0, 1.0),
        Err(LoadCommandError::NoSuchPad { count: 0, .. })
    ));
    // Retract by more than the feed per revolution (2.3 mm): the tool clears the helical shoulder.
    sim.set_tool_feed(-0.01).unwrap();
    let later = sim.time() + 0.3;
    run_to(&mut sim, later);
    assert_eq!(sim.tool_output().unwrap().feed_force, 0.0);
    // Reset restores the cut-free disc and the file's feed.
    sim.reset();
    let t = sim.tool_output().unwrap();
    assert_eq!((t.feed_rate, t.chip, t.feed_force), (0.002, 0.0, 0.0));
    assert!((t.tip - 0.0055).abs() < 1e-12, "{t:?}");
}

#[track_caller]
fn rejected(from: &str, to: &str, key: &str) -> ConfigError {
    scenes::rejected("lathe.yaml", from, to, key)
}

#[test]
fn bad_tool_data_are_refused_naming_the_key() {
    // A tool whose node is not on the rim, or that would cut beyond the annulus.
    let e = rejected("ale_radial: [1.0]", "ale_radial: [0.8]", "tool.ale_node");
    assert!(
        matches!(e, ConfigError::ToolNotOnRim { node: 1, .. }),
        "{e:?}"
    );
    println!("{e}");
    let e = rejected(
        "depth_of_cut: 0.001",
        "depth_of_cut: 0.1",
        "tool.depth_of_cut",
    );
    assert!(
        matches!(e, ConfigError::DepthOfCutBeyondPlate { .. }),
        "{e:?}"
    );
    println!("{e}");
    rejected("ale_radial: [1.0]", "ale_radial: [1.2]", "nodes.ale_radial");
    let e = rejected("ale_node: 1", "ale_node: 2", "tool.ale_node");
    assert!(
        matches!(
            e,
            ConfigError::NoSuchNode {
                node: 2,
                count: 1,
                ..
            }
        ),
        "{e:?}"
    );
    rejected("ale_node: 1", "ale_node: -1", "tool.ale_node");
    let e = rejected("stiffness: 2.0e7", "stiffness: -2.0e7", "tool.stiffness");
    assert!(matches!(e, ConfigError::NotPositive { .. }), "{e:?}");
    rejected("damping: 2.0e3", "damping: -1.0", "tool.damping");
    rejected("feed_rate: 0.002", "feed_rate: 5.0", "tool.feed_rate");
    rejected(
        "start_clearance: 0.0005",
        "start_clearance: -0.001",
        "tool.start_clearance",
    );
    rejected(
        "force_exponent: 0.7013",
        "force_exponent: 1.2",
        "tool.force_exponent",
    );
    rejected(
        "specific_force: 351.0e6",
        "specific_force: 0.0",
        "tool.specific_force",
    );
    rejected(
        "force_exponent: 0.7013",
        "force_exponent: 0.7013\n      cutting_specific_force: -1.0",
        "tool.cutting_specific_force",
    );
    rejected(
        "force_exponent: 0.7013",
        "force_exponent: 0.7013\n      cutting_exponent: 1.0",
        "tool.cutting_exponent",
    );
    // Tool keys without a tool.
    let e = rejected("      ale_node: 1\n", "", "tool.depth_of_cut");
    assert!(
        matches!(
            e,
            ConfigError::KeyWithoutSection {
                enabling_key: "tool.ale_node",
                ..
            }
        ),
        "{e:?}"
    );
}

#[test]
fn the_cli_simulates_the_scene_with_the_tool_columns_after_the_contract_ones() {
    let text = scenes::simulate_csv("lathe.yaml", 0.3);
    let header: Vec<&str> = text.lines().next().unwrap().split(',').collect();
    let contract = 3 + 2 * 30 + 2;
    assert_eq!(&header[contract - 2..contract], ["ale1_uz", "lagrange1_uz"]);
    assert_eq!(
        &header[contract..],
        [
            "joint_effort",
            "tool_tip_z",
            "tool_chip_thickness",
            "tool_feed_force"
        ]
    );
    let last: Vec<f64> = text
        .lines()
        .last()
        .unwrap()
        .split(',')
        .map(|v| v.parse().unwrap())
        .collect();
    assert!(last[header.len() - 1] > 0.0, "cutting at 0.3 s");
}
