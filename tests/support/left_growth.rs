//! The growth rate of a pad scene's critical mode measured in a simulation
//! started on it: with u_L the mode's left eigenvector, the coordinate
//! c(t) = u_Lᵀ y(t) of a run started on the real part of its right
//! eigenvector v is ½ (u_Lᵀ v) e^{λt} for the linear system, so ln|c| has
//! slope Re λ whatever the other modes do. y = (q̄, q̄̇) and the pads' own
//! states, laid out in their slot as [`PadLayout`] says.
#![allow(dead_code)]

use annular_plate::config::Config;
use annular_plate::dynamics::load_models::pad::Pads;
use annular_plate::dynamics::load_models::pad_config::PadsConfig;
use annular_plate::dynamics::{stability, Simulation};

/// Where the pads' entries of y (after q̄, q̄̇) lie in their slot.
#[derive(Debug, Clone, Copy)]
pub enum PadLayout {
    /// Massless pads with a rigid lining: y = (q̄, q̄̇).
    Rigid,
    /// Massive pads: y = (q̄, q̄̇, ξ, ξ̇), ξ = x − x₀ per pad face, the slot
    /// holding the compressions x (first half) and their rates (second
    /// half); x₀ = `rest`, m.
    Massive {
        /// x₀ at rest under the clamp force, m.
        rest: f64,
    },
    /// One contact with the lining's patch: y = (q̄, q̄̇, ζ), the top face's
    /// radial patch deflection −(h/2) ζ (slot entry 0) and the bottom's
    /// +(h/2) ζ (entry 2).
    Patch {
        /// h/2, m.
        half_thickness: f64,
    },
}

impl PadLayout {
    /// Writes the pads' part `v` of y into their slot.
    fn start(&self, v: &[f64], slot: &mut [f64]) {
        match *self {
            PadLayout::Rigid => {}
            PadLayout::Massive { rest } => {
                let faces = slot.len() / 2;
                for f in 0..faces {
                    slot[f] = rest + v[f];
                    slot[faces + f] = v[faces + f];
                }
            }
            PadLayout::Patch { half_thickness } => {
                slot[0] = -half_thickness * v[0];
                slot[2] = half_thickness * v[0];
            }
        }
    }

    /// Appends the pads' part of y, read from their slot, to `y`.
    fn read(&self, slot: &[f64], y: &mut Vec<f64>) {
        match *self {
            PadLayout::Rigid => {}
            PadLayout::Massive { rest } => {
                let faces = slot.len() / 2;
                y.extend(slot[..faces].iter().map(|x| x - rest));
                y.extend_from_slice(&slot[faces..]);
            }
            PadLayout::Patch { half_thickness } => y.push(-slot[0] / half_thickness),
        }
    }
}

/// Re λ of the critical mode of scene `c` (at its speed, friction
/// coefficient and clamp forces) and the least-squares slope of ln|u_Lᵀ y|
/// over `steps` steps started on v with a peak modal amplitude of 1 µm.
pub fn left_eigenvector_growth(c: Config, layout: PadLayout, steps: usize) -> (f64, f64) {
    let pads = c
        .section::<PadsConfig>()
        .cloned()
        .expect("a scene with pads");
    let speed = c.joint.speed;
    let (mu, clamp) = (pads.friction_coefficient, pads.clamp_force);
    let mut sim = Simulation::new(c).unwrap();
    let mode = stability::critical_mode(sim.scene(), speed, mu, &clamp);
    let n = sim.model().n_modes();
    let len = mode.vector.len();
    let a = stability::linear_system(sim.scene(), speed, mu, &clamp);
    let eig = a.transpose().to_owned().eigen().unwrap();
    let (s, u) = (eig.S(), eig.U());
    let j = (0..len)
        .min_by(|&x, &y| {
            let d = |i: usize| (s[i].re - mode.eigenvalue.re).hypot(s[i].im - mode.eigenvalue.im);
            d(x).total_cmp(&d(y))
        })
        .unwrap();
    let left: Vec<(f64, f64)> = (0..len).map(|r| (u[(r, j)].re, u[(r, j)].im)).collect();
    let peak = mode.vector[..n]
        .iter()
        .map(|v| v.norm())
        .fold(0.0, f64::max);
    let start: Vec<f64> = mode.vector.iter().map(|v| 1e-6 * v.re / peak).collect();
    let index = sim.scene().load_models.find::<Pads>().map_or(0, |(i, _)| i);
    let mut state = sim.state().clone();
    state.q.copy_from_slice(&start[..n]);
    state.q_dot.copy_from_slice(&start[n..2 * n]);
    layout.start(&start[2 * n..], &mut state.load_models.slots[index]);
    state.rederive(sim.scene());
    sim.restore(state);
    let (mut ts, mut logs) = (Vec::new(), Vec::new());
    let mut y = Vec::with_capacity(len);
    for _ in 0..steps {
        sim.step().unwrap();
        y.clear();
        y.extend_from_slice(sim.q_ale());
        y.extend_from_slice(sim.q_dot_ale());
        layout.read(&sim.state().load_models.slots[index], &mut y);
        let (re, im) = y
            .iter()
            .zip(&left)
            .fold((0.0, 0.0), |(re, im), (y, l)| (re + y * l.0, im + y * l.1));
        ts.push(sim.time());
        logs.push(re.hypot(im).ln());
    }
    let slope = super::fit::least_squares_slope(&ts, &logs);
    (mode.eigenvalue.re, slope)
}
