//! The house's promises about state and load models: a saved `State` is
//! everything that evolves (a fresh stepper steps it on bit for bit), and a
//! load model added through the registry (the point spring of
//! docs/architecture.md) acts as its closed form says.

mod support;

use annular_plate::config::{Config, IntegratorKind, NodePosition, PlateTheory, WrenchConfig};
use annular_plate::dynamics::load_models::pad_config::PadsConfig;
use annular_plate::dynamics::load_models::point_spring::SpringsConfig;
use annular_plate::dynamics::{Simulation, Stepper};
use support::scene_files;

/// Run `sim` for `steps`, returning the state after `at` steps and after all.
fn run(
    sim: &mut Simulation,
    at: usize,
    steps: usize,
) -> (
    annular_plate::dynamics::State,
    annular_plate::dynamics::State,
) {
    let mut saved = None;
    for s in 0..steps {
        if s == at {
            saved = Some(sim.state().clone());
        }
        sim.step().unwrap();
    }
    (saved.unwrap(), sim.state().clone())
}

/// Step `state` `steps` times under `sim`'s scene, settings and inputs with
/// a new stepper (no scratch or cache from the run that saved it).
fn step_with_a_fresh_stepper(
    sim: &Simulation,
    state: &mut annular_plate::dynamics::State,
    steps: usize,
) {
    let mut stepper = Stepper::new(sim.scene());
    for _ in 0..steps {
        stepper
            .step(sim.scene(), sim.settings(), state, sim.inputs())
            .unwrap();
    }
}

#[test]
fn a_saved_state_stepped_by_a_fresh_stepper_replays_the_run_bit_for_bit() {
    // The lathe (a tool with memory: its machined surface), the squeal scene
    // (pads, RK4 stages) and the swash plate (links, Lagrangian coordinates).
    for (file, at, steps) in [
        ("lathe.yaml", 300, 700),
        ("brake_squeal.yaml", 50, 150),
        ("swash_plate.yaml", 100, 300),
    ] {
        let mut sim = Simulation::new(scene_files::load(file)).unwrap();
        let (mut replay, end) = run(&mut sim, at, steps);
        step_with_a_fresh_stepper(&sim, &mut replay, steps - at);
        assert_eq!(replay, end, "{file}: the replayed state differs");
        // And restored into the facade, it continues like the original.
        let mut again = Simulation::new(scene_files::load(file)).unwrap();
        let (saved, _) = run(&mut again, at, at + 1);
        let mut restored = Simulation::new(scene_files::load(file)).unwrap();
        restored.restore(saved);
        for _ in at..steps {
            restored.step().unwrap();
        }
        assert_eq!(
            restored.state(),
            &end,
            "{file}: the restored simulation differs"
        );
        assert_eq!(restored.step_count(), steps as u64);
    }
}

/// The lathe disc with only its ⟨0, 0⟩ mode, a spring and a load under ALE node 1.
fn one_mode_with_spring(stiffness: f64, damping_ratio: f64) -> Config {
    let mut c = Config::default();
    c.plate.nodal_diameters = vec![0];
    c.plate.nodal_circles = vec![0];
    c.plate.damping = vec![damping_ratio];
    c.joint.speed = 0.0;
    c.nodes.ale = vec![NodePosition {
        radial: 1.0,
        angular: 0.0,
    }];
    c.set_section(SpringsConfig {
        nodes: vec![0],
        stiffness,
        damping: 0.0,
    });
    c.simulation.integrator = IntegratorKind::Rk4;
    c.simulation.rate_hz = 20_000.0;
    c
}

#[test]
fn a_point_spring_carries_its_share_of_a_static_load() {
    // One mode: m q̈ + K q = φ (F − k_s φ q), so at rest q = φ F / (K + k_s φ²).
    let (k_s, force) = (2.0e7, -500.0);
    let mut c = one_mode_with_spring(k_s, 0.3);
    c.loads.ale = vec![WrenchConfig {
        force: [0.0, 0.0, force],
        moment: [0.0; 3],
    }];
    let mut sim = Simulation::new(c).unwrap();
    let phi = sim.scene().ale_nodes[0].shapes[0].w;
    let stiffness = sim.model().body().modal_stiffness[0];
    for _ in 0..20_000 {
        sim.step().unwrap();
    }
    let expected = phi * phi * force / (stiffness + k_s * phi * phi);
    // the modal part (uz less the residual flexibility, docs/residual_flexibility.md)
    let w = sim.ale_node(0).uz - sim.residual_deflection(0);
    assert!(
        (w - expected).abs() < 1e-9 * expected.abs(),
        "w = {w:e}, closed form {expected:e}"
    );
    // The spring's reaction is the part of the load the plate does not carry.
    let reaction = sim.ale_model_wrench(0).force[2];
    assert!(
        (reaction + k_s * w).abs() < 1e-9 * (k_s * w).abs(),
        "{reaction} vs {}",
        -k_s * w
    );
}

#[test]
fn a_point_spring_raises_the_frequency_to_the_closed_form() {
    // Free vibration, undamped: ω_s² = (K + k_s φ²) / m.
    let k_s = 2.0e7;
    let mut c = one_mode_with_spring(k_s, 0.0);
    c.initial.q = vec![1e-6];
    let mut sim = Simulation::new(c).unwrap();
    let phi = sim.scene().ale_nodes[0].shapes[0].w;
    let body = sim.model().body();
    let expected = ((body.modal_stiffness[0] + k_s * phi * phi) / body.modal_mass[0]).sqrt();
    // Upward zero crossings of q, linearly interpolated, over many periods.
    let (mut crossings, mut last) = (Vec::new(), (0.0, sim.q_lagrange()[0]));
    for _ in 0..40_000 {
        sim.step().unwrap();
        let now = (sim.time(), sim.q_lagrange()[0]);
        if last.1 < 0.0 && now.1 >= 0.0 {
            crossings.push(last.0 + (now.0 - last.0) * (-last.1) / (now.1 - last.1));
        }
        last = now;
    }
    let periods = (crossings.len() - 1) as f64;
    let omega = std::f64::consts::TAU * periods / (crossings.last().unwrap() - crossings[0]);
    assert!(periods > 20.0, "{periods} periods");
    assert!(
        (omega - expected).abs() < 1e-5 * expected,
        "ω = {omega}, closed form {expected}"
    );
    let bare = sim.model().modes()[0].omega;
    assert!(
        expected > 1.001 * bare,
        "the spring stiffens the mode: {expected} vs {bare}"
    );
}

#[test]
fn a_saved_state_on_contact_exponential_carries_its_span_length_and_replays_bit_for_bit() {
    // brake_squeal with a rigid lining: the friction direction's remainder
    // makes the spans third-order and shorter than a step. The step starts
    // from the span length in the State, so a fresh stepper continues alike.
    // Kirchhoff theory: the Mindlin scene (as shipped) re-refines from whole
    // steps at step 400 to the same state bit for bit, so the last check
    // below could not fail there.
    let config = || {
        let mut c = scene_files::load("brake_squeal.yaml");
        c.plate.theory = PlateTheory::Kirchhoff;
        c.section_mut::<PadsConfig>().unwrap().shear = None;
        c.simulation.integrator = IntegratorKind::ContactExponential;
        c.simulation.contact_tolerance = 1.0e-6;
        c
    };
    let (at, steps) = (400, 600);
    let mut sim = Simulation::new(config()).unwrap();
    let (mut replay, end) = run(&mut sim, at, steps);
    assert!(
        replay.contact_spans.level > 0 && replay.contact_spans.third_order,
        "the saved state carries shortened third-order spans: {:?}",
        replay.contact_spans
    );
    step_with_a_fresh_stepper(&sim, &mut replay, steps - at);
    assert_eq!(replay, end, "the replayed state differs");
    // Started from whole-step spans instead, the run differs: the carried
    // length is part of what the state replays.
    let mut from_whole = Simulation::new(config()).unwrap();
    let (mut forgotten, _) = run(&mut from_whole, at, at + 1);
    forgotten.contact_spans = Default::default();
    step_with_a_fresh_stepper(&sim, &mut forgotten, steps - at);
    assert_ne!(forgotten.q, end.q, "the span length has no effect");
}

#[test]
fn a_saved_lathe_state_on_contact_exponential_replays_its_cut_bit_for_bit() {
    // The tool's cut within the step reads the machined surface, so its
    // pieces are linearised at each step's own state: a fresh stepper from
    // a state saved in the cut (first contact at 0.25 s) takes the same steps.
    let mut config = scene_files::load("lathe.yaml");
    config.simulation.integrator = IntegratorKind::ContactExponential;
    let (at, steps) = (270, 290);
    let mut sim = Simulation::new(config).unwrap();
    let (mut replay, end) = run(&mut sim, at, steps);
    assert!(end.q.iter().any(|q| *q != 0.0), "the tool has not cut");
    step_with_a_fresh_stepper(&sim, &mut replay, steps - at);
    assert_eq!(replay, end, "the replayed state differs");
}
