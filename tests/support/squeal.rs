//! A squeal scene started on its critical eigenvector: the growth rate the
//! simulation shows, to compare with the eigenvalue's real part.
#![allow(dead_code)]

use annular_plate::dynamics::load_models::pad_config::PadsConfig;
use annular_plate::dynamics::{stability, Simulation};

/// The critical mode's eigenvalue (Re λ, Im λ) and the simulated growth.
pub struct Growth {
    /// Re λ of the linear stability analysis, 1/s.
    pub rate: f64,
    /// Im λ, rad/s.
    pub omega: f64,
    /// Nodal diameters of the pair that carries most of the mode.
    pub k: u32,
    /// Least-squares slope of ln|z̄| of that pair over the run, 1/s.
    pub simulated: f64,
}

/// Starts `sim` on the real part of the critical eigenvector at its speed,
/// friction coefficient and clamp forces (peak amplitude `peak` m), steps
/// `steps` times and fits the growth of the critical pair's ALE amplitude
/// |z̄| = |(q̄_cos, q̄_sin)| — for a linear run exactly e^{Re λ t}.
pub fn simulated_growth(sim: &mut Simulation, peak: f64, steps: usize) -> Growth {
    let pads = sim
        .config()
        .section::<PadsConfig>()
        .cloned()
        .expect("a scene with pads");
    let mode = stability::critical_mode(
        sim.scene(),
        sim.config().joint.speed,
        pads.friction_coefficient,
        &pads.clamp_force,
    );
    let n = sim.model().n_modes();
    let top = mode.vector[..n]
        .iter()
        .map(|v| v.norm())
        .fold(0.0, f64::max);
    let mut state = sim.state().clone();
    for i in 0..n {
        state.q[i] = peak * mode.vector[i].re / top;
        state.q_dot[i] = peak * mode.vector[n + i].re / top;
    }
    state.rederive(sim.scene());
    sim.restore(state);
    let pair = sim
        .scene()
        .layout
        .pairs
        .iter()
        .copied()
        .max_by(|a, b| {
            mode.vector[a.cos]
                .norm()
                .total_cmp(&mode.vector[b.cos].norm())
        })
        .unwrap();
    let (mut ts, mut logs) = (Vec::new(), Vec::new());
    for _ in 0..steps {
        sim.step().unwrap();
        ts.push(sim.time());
        logs.push(sim.q_ale()[pair.cos].hypot(sim.q_ale()[pair.sin]).ln());
    }
    let simulated = super::fit::least_squares_slope(&ts, &logs);
    Growth {
        rate: mode.eigenvalue.re,
        omega: mode.eigenvalue.im,
        k: pair.k,
        simulated,
    }
}
