//! The stepper makes a load-model evaluation again only where its inputs
//! changed (the step's start, the integrator's start and end and the outputs
//! often see the same state): a run with one stepper is bit for bit the run
//! that steps every step with a fresh stepper, and its published wrenches
//! are a fresh evaluation's, also where the clamp force and the held
//! wrenches change between steps and the pads read the joint angle (a held
//! normal force on the rim, through the residual deflection).

mod support;

use annular_plate::dynamics::{Command, NodeKind, Simulation, Stepper, Wrench};
use support::scene_files;

/// Hold `command` on `sim`.
fn apply(sim: &mut Simulation, command: Command) {
    let checked = sim.check(command).unwrap();
    sim.apply(checked);
}

/// The clamp force of brake_bench's pad.
fn clamp(value: f64) -> Command {
    Command::Load {
        model: 0,
        command: 0,
        instance: 0,
        value,
    }
}

/// A held normal force on the rim's material point (read at χ).
fn rim_force(force: f64) -> Command {
    Command::Wrench {
        kind: NodeKind::Lagrange,
        node: 0,
        wrench: Wrench {
            force: [0.0, 0.0, force],
            moment: [0.0; 3],
        },
    }
}

#[test]
fn one_stepper_steps_and_publishes_as_a_fresh_stepper_every_step() {
    let mut sim = Simulation::new(scene_files::load("brake_bench.yaml")).unwrap();
    assert!(
        sim.scene().residual.is_some(),
        "the scene's pads read the held wrenches' residual deflection"
    );
    // The clamp ramps in, a rim force comes and goes, the clamp is released.
    let script = |step: usize| match step {
        0 => Some(clamp(2000.0)),
        40 => Some(clamp(8000.0)),
        60 => Some(rim_force(-300.0)),
        90 => Some(rim_force(0.0)),
        120 => Some(clamp(0.0)),
        _ => None,
    };
    let mut fresh_state = sim.state().clone();
    let mut clamped_torque = 0.0;
    for step in 0..160 {
        if let Some(command) = script(step) {
            apply(&mut sim, command);
        }
        Stepper::new(sim.scene())
            .step(sim.scene(), sim.settings(), &mut fresh_state, sim.inputs())
            .unwrap();
        sim.step().unwrap();
        assert_eq!(sim.state(), &fresh_state, "step {step}: the states differ");
        let mut fresh = Stepper::new(sim.scene());
        let published = sim.model_wrenches();
        let evaluated = fresh.model_wrenches_at(sim.scene(), sim.state(), sim.inputs());
        assert_eq!(published.ale, evaluated.ale, "step {step}: pad wrenches");
        assert_eq!(
            published.friction, evaluated.friction,
            "step {step}: friction"
        );
        assert_eq!(
            published.switching, evaluated.switching,
            "step {step}: margins"
        );
        if step == 100 {
            clamped_torque = sim.model_wrenches().friction[0].capacity;
        }
    }
    // The comparison ran with the pads pressed: their friction brakes the joint.
    assert!(
        clamped_torque > 100.0,
        "friction capacity {clamped_torque} N m"
    );
}
