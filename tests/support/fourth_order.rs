//! Two independent fourth-order discretisations (RK4 on the ALE equations and
//! on the Lagrangian ones) converging to one motion: their difference falls
//! by 2⁴ = 16 per halving of the step.
#![allow(dead_code)]

use super::scenes::relative_difference;
use annular_plate::config::{Config, Coordinates};
use annular_plate::dynamics::Simulation;

/// `difference(rate)` at each of `rates` (each twice the one before) must
/// fall at fourth order, a ratio of 12 to 20 per doubling; returns the last.
pub fn assert_fourth_order(
    label: &str,
    rates: &[f64],
    mut difference: impl FnMut(f64) -> f64,
) -> f64 {
    let mut previous: Option<f64> = None;
    for &rate in rates {
        let d = difference(rate);
        println!("{label} at {rate} Hz: {d:e}");
        if let Some(p) = previous {
            assert!(
                p / d > 12.0 && p / d < 20.0,
                "{label}: not converging at fourth order: {p:e} → {d:e}"
            );
        }
        previous = Some(d);
    }
    previous.expect("at least one rate")
}

/// One motion in both descriptions: `config` run in ALE and in Lagrangian
/// coordinates at `rate` (RK4's step set by the rate through
/// `rk4_step_limit`) for 0.05 s from q̄ = (2e-6, 1e-6), sampling q̄ and
/// `extra` after every step; max |Lagrangian − ALE| over the largest ALE
/// value.
pub fn descriptions_differ(
    config: &Config,
    rate: f64,
    rk4_step_limit: f64,
    extra: impl Fn(&Simulation, &mut Vec<f64>),
) -> f64 {
    let run = |coordinates: Coordinates| {
        let mut c = config.clone();
        c.simulation.rate_hz = rate;
        c.simulation.rk4_step_limit = rk4_step_limit;
        c.simulation.coordinates = coordinates;
        c.initial.q = vec![2e-6, 1e-6];
        let mut sim = Simulation::new(c).unwrap();
        let mut out = Vec::new();
        for _ in 0..(0.05 * rate) as usize {
            sim.step().unwrap();
            out.extend_from_slice(sim.q_ale());
            extra(&sim, &mut out);
        }
        out
    };
    relative_difference(&run(Coordinates::Lagrangian), &run(Coordinates::Ale))
}
