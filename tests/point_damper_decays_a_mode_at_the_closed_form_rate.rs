//! The space-fixed point damper (`dampers.*`) against the closed form of
//! one damped mode, and its keys against bad input.
//!
//! The lathe disc with only its ⟨0, 0⟩ mode and a damper c_d at a rim node:
//! m q̈ + K q = −c_d Φ² q̇ (Φ the mode shape at the node, m and K the modal
//! mass and stiffness from the plate model), whose free decay is
//! q = A e^(σt) cos(ω_d t + φ) with σ = −c_d Φ²/(2m) and ω_d² = K/m − σ².
//! For it Q = q² + ((q̇ − σ q)/ω_d)² = A² e^(2σt) exactly, so the slope of
//! ln Q over the run is 2σ — read at every step, with no peak picking.
//! RK4 runs at h·ω ≤ 0.05, where its own amplitude error per step,
//! (hω)⁶/144, is below 1e-10.

mod support;

use annular_plate::config::{Config, ConfigError};
use annular_plate::dynamics::Simulation;
use support::fit::modal_decay;

/// The one-mode lathe disc with a damper of `damping` N·s/m under its rim node.
fn scene(damping: &str, nodes: &str) -> String {
    format!(
        "/**:
  ros__parameters:
    plate:
      nodal_diameters: [0]
      nodal_circles: [0]
      damping: [0.0]
    nodes:
      ale_radial: [1.0, 0.5]
      ale_angular: [0.0, 0.25]
    dampers:
      ale_nodes: {nodes}
      damping: {damping}
    simulation:
      integrator: rk4
      rate_hz: 20000.0
      rk4_step_limit: 0.05
    initial:
      q: [1.0e-6]
"
    )
}

#[test]
fn a_point_damper_decays_the_mode_at_the_closed_form_rate() {
    for c_d in [200.0, 2000.0] {
        let config =
            Config::from_yaml_str(&scene(&c_d.to_string(), "[1]"), "annular_plate").unwrap();
        let mut sim = Simulation::new(config).unwrap();
        let phi = sim.scene().ale_nodes[0].shapes[0].w;
        let (m, k) = {
            let body = sim.model().body();
            (body.modal_mass[0], body.modal_stiffness[0])
        };
        let sigma = -c_d * phi * phi / (2.0 * m);
        let omega_d = (k / m - sigma * sigma).sqrt();
        let zeta = -sigma / (k / m).sqrt();
        assert!(
            (1e-4..0.2).contains(&zeta),
            "ζ = {zeta}: a light damping the test resolves"
        );
        let (fitted, decayed) = modal_decay(&mut sim, sigma, omega_d, 8000);
        assert!(
            decayed > 0.5,
            "c_d = {c_d}: the run decays ln Q by {decayed} only"
        );
        assert!(
            (fitted - sigma).abs() < 1e-6 * sigma.abs(),
            "c_d = {c_d}: decay rate {fitted:e} 1/s, closed form {sigma:e} 1/s (ζ = {zeta:e})"
        );
    }
}

/// With c_d = 0 the dampers add nothing: the run is the one without them, bit for bit.
#[test]
fn a_damper_without_damping_changes_nothing() {
    let with = Config::from_yaml_str(&scene("0.0", "[1, 2]"), "annular_plate").unwrap();
    let text = scene("0.0", "[1]").replace(
        "    dampers:\n      ale_nodes: [1]\n      damping: 0.0\n",
        "",
    );
    assert!(!text.contains("dampers"));
    let without = Config::from_yaml_str(&text, "annular_plate").unwrap();
    let (mut a, mut b) = (
        Simulation::new(with).unwrap(),
        Simulation::new(without).unwrap(),
    );
    for _ in 0..2000 {
        a.step().unwrap();
        b.step().unwrap();
    }
    assert_eq!(a.q_lagrange(), b.q_lagrange());
    assert_eq!(a.q_dot_lagrange(), b.q_dot_lagrange());
    assert!(a.q_lagrange()[0] != 0.0);
}

fn error(damping: &str, nodes: &str) -> String {
    Config::from_yaml_str(&scene(damping, nodes), "annular_plate")
        .map(|_| ())
        .expect_err("refused")
        .to_string()
}

#[test]
fn bad_damper_keys_are_refused_naming_the_key_and_the_rule() {
    let negative = error("-1.0", "[1]");
    assert!(
        negative.contains("dampers.damping") && negative.contains(">= 0")
            || negative.contains("dampers.damping") && negative.contains("negative"),
        "{negative}"
    );
    let no_node = error("10.0", "[3]");
    assert!(no_node.contains("dampers.ale_nodes[0]"), "{no_node}");
    let twice = error("10.0", "[1, 1]");
    assert!(twice.contains("dampers.ale_nodes"), "{twice}");
    let zero = error("10.0", "[0]");
    assert!(zero.contains("dampers.ale_nodes[0]"), "{zero}");
    let not_a_double = error("\"soft\"", "[1]");
    assert!(not_a_double.contains("dampers.damping"), "{not_a_double}");
    let infinite = error(".inf", "[1]");
    assert!(infinite.contains("dampers.damping"), "{infinite}");
    // Its other key without the enabling one.
    let without = error("10.0", "[]");
    assert!(
        without.contains("dampers.damping") && without.contains("dampers.ale_nodes"),
        "{without}"
    );
    let e = Config::from_yaml_str(&scene("-1.0", "[1]"), "annular_plate").unwrap_err();
    assert!(
        matches!(e, ConfigError::Negative { .. }),
        "a negative damping is the sign rule: {e:?}"
    );
}
