//! Without follower loads and load models the stepper computes the node loads
//! of the held wrenches once and reuses them while the wrenches stay the same
//! (`Stepper::node_loads`). A changed wrench takes effect at the next step:
//! the run that changes its wrenches mid-way ends bit for bit where a fresh
//! simulation (nothing kept) ends from the same state under the new wrenches,
//! and not where the old wrenches would have taken it.

use annular_plate::config::{Config, Coordinates, IntegratorKind, NodePosition, WrenchConfig};
use annular_plate::dynamics::{Simulation, Wrench};

fn scene(integrator: IntegratorKind, coordinates: Coordinates) -> Config {
    let mut c = Config::default();
    c.plate.damping = vec![0.02];
    c.joint.speed = 20.0;
    c.simulation.integrator = integrator;
    c.simulation.coordinates = coordinates;
    c.simulation.rate_hz = 10_000.0;
    c.nodes.ale.push(NodePosition {
        radial: 1.0,
        angular: 0.0,
    });
    c.nodes.lagrange.push(NodePosition {
        radial: 0.5,
        angular: 0.5,
    });
    c.loads.ale.push(WrenchConfig {
        force: [0.0, 30.0, -100.0],
        moment: [0.0; 3],
    });
    c
}

const NEW_ALE: Wrench = Wrench {
    force: [0.0, 10.0, 250.0],
    moment: [0.5, 0.0, 0.0],
};
const NEW_LAGRANGE: Wrench = Wrench {
    force: [0.0, 0.0, -40.0],
    moment: [0.0, 0.2, 0.0],
};

/// q̄ after 20 steps under the file's wrench, then 20 under `then` (None: the file's wrench kept).
fn run(sim: &mut Simulation, then: Option<(Wrench, Wrench)>) -> Vec<f64> {
    for _ in 0..20 {
        sim.step().unwrap();
    }
    if let Some((ale, lagrange)) = then {
        sim.set_ale_wrench(0, ale).unwrap();
        sim.set_lagrange_wrench(0, lagrange).unwrap();
    }
    for _ in 0..20 {
        sim.step().unwrap();
    }
    sim.q_ale().to_vec()
}

#[test]
fn a_changed_wrench_acts_from_the_next_step() {
    for integrator in [
        IntegratorKind::Exponential,
        IntegratorKind::ImplicitMidpoint,
        IntegratorKind::Rk4,
    ] {
        for coords in [Coordinates::Ale, Coordinates::Lagrangian] {
            let mut changed = Simulation::new(scene(integrator, coords)).unwrap();
            let q_changed = run(&mut changed, Some((NEW_ALE, NEW_LAGRANGE)));

            // Reference: the state after the first 20 steps, stepped by a fresh simulation holding the new wrenches.
            let mut first = Simulation::new(scene(integrator, coords)).unwrap();
            for _ in 0..20 {
                first.step().unwrap();
            }
            let mut fresh = Simulation::new(scene(integrator, coords)).unwrap();
            fresh.restore(first.state().clone());
            fresh.set_ale_wrench(0, NEW_ALE).unwrap();
            fresh.set_lagrange_wrench(0, NEW_LAGRANGE).unwrap();
            for _ in 0..20 {
                fresh.step().unwrap();
            }
            assert_eq!(q_changed, fresh.q_ale(), "{integrator:?}/{coords:?}: the changed run against a fresh one from the same state");

            let mut kept = Simulation::new(scene(integrator, coords)).unwrap();
            let q_kept = run(&mut kept, None);
            let moved = q_changed
                .iter()
                .zip(&q_kept)
                .map(|(a, b)| (a - b).abs())
                .fold(0.0, f64::max);
            let scale = q_kept.iter().map(|v| v.abs()).fold(0.0, f64::max);
            assert!(moved > 1e-3 * scale, "{integrator:?}/{coords:?}: the new wrenches changed q̄ by only {moved:e} (scale {scale:e})");
        }
    }
}
