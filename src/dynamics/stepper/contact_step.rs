//! The stepper's `contact_exponential` substep (docs/dynamics.md, "Stiff
//! contacts"): the elastic state in the ALE description — where space-fixed
//! pads make the equations autonomous at a held joint speed — stepped by
//! [`ContactExponential`] with the right-hand side frozen at the substep's
//! mid-instant (χ at h/2, the mean speed Ω̄, the acceleration α).

use super::stage_rhs::StageRhs;
use super::{Stepper, SubstepMotion};
use crate::config::Coordinates;
use crate::dynamics::ale::{ale_to_lagrange, harmonics};
use crate::dynamics::commands::Inputs;
use crate::dynamics::integrators::contact_exponential::ContactExponential;
use crate::dynamics::scene::Scene;
use crate::dynamics::state::{JointAngle, State};

/// Switching instants are located to within this (s), or h / 2^40.
pub const SWITCH_RESOLUTION: f64 = 2.5e-7;

impl Stepper {
    /// One substep of h from (χ0, Ω0) under α by the contact exponential.
    pub(super) fn contact_exponential(
        &mut self,
        scene: &Scene,
        state: &mut State,
        inputs: &Inputs,
        joint: &SubstepMotion,
        tolerance: f64,
    ) {
        let SubstepMotion {
            h,
            chi0,
            speed0,
            alpha,
            ..
        } = *joint;
        let speed_mean = speed0 + 0.5 * alpha * h;
        let mut chi_mid = chi0;
        chi_mid.advance(0.5 * speed0 * h + 0.125 * alpha * h * h);
        self.contact_prepare(scene, state, h);
        self.held_key(scene, inputs, speed_mean, alpha, chi_mid);
        let continuous = scene.load_models.continuous_states() > 0;
        if continuous {
            self.stage_slots.copy_from(&state.load_models);
        }
        let Stepper {
            consts,
            loads,
            base_ale_frame,
            harm,
            views,
            y,
            model_wrenches,
            stage_slots,
            contact,
            contact_key,
            ..
        } = self;
        let mut stage = StageRhs {
            scene,
            inputs,
            consts,
            coords: Coordinates::Ale,
            alpha,
            base_ale_frame,
            harm,
            views,
            loads,
            model_wrenches,
            stage_slots: continuous.then_some(stage_slots),
            slots: &state.load_models,
        };
        let mut eval = |yy: &[f64], dy: &mut [f64], s: &mut [f64]| {
            stage.eval(chi_mid, speed_mean, yy, dy);
            s.copy_from_slice(&stage.model_wrenches.switching);
        };
        let integrator = contact.as_mut().expect("prepared above");
        self.last_contact = integrator.step(
            h,
            y,
            contact_key,
            tolerance,
            &mut state.contact_spans,
            &mut eval,
        );
        self.contact_finish(scene, state, chi0, speed0, alpha, h);
    }

    /// y ← the ALE state and the models' continuous states; the integrator
    /// (re)made for this h.
    fn contact_prepare(&mut self, scene: &Scene, state: &State, h: f64) {
        let n = scene.n_modes();
        let models = &scene.load_models;
        let size = scene.first_order_unknowns();
        let levels = ContactExponential::levels_for(h, SWITCH_RESOLUTION);
        if self.contact_levels != Some(levels) {
            let mut c = ContactExponential::new(size, models.switching_functions(), levels);
            let (scale, blocks) = difference_scale(scene, n, size, h);
            c.set_scale(&scale, &blocks);
            self.contact = Some(c);
            self.contact_levels = Some(levels);
        }
        let (q, v) = state.ale();
        self.y[..n].copy_from_slice(q);
        self.y[n..2 * n].copy_from_slice(v);
        models.gather_continuous(&state.load_models, &mut self.y[2 * n..]);
    }

    /// The cache key of what the step holds: Ω̄, α, the commands, and with
    /// follower loads the held wrenches and χ (they then enter J).
    fn held_key(
        &mut self,
        scene: &Scene,
        inputs: &Inputs,
        speed: f64,
        alpha: f64,
        chi: JointAngle,
    ) {
        let k = &mut self.contact_key;
        k.clear();
        k.push(speed.to_bits());
        k.push(alpha.to_bits());
        for v in inputs.commands.values.iter().flatten() {
            k.push(v.to_bits());
        }
        if scene.effects.follower_loads {
            k.push(chi.angle.to_bits());
            for w in inputs.ale.iter().chain(&inputs.lagrange) {
                k.extend(w.force.iter().chain(&w.moment).map(|v| v.to_bits()));
            }
        }
    }

    /// Write y back: the ALE state (and the Lagrangian one as primary where
    /// the scene integrates in it), the models' continuous states.
    fn contact_finish(
        &mut self,
        scene: &Scene,
        state: &mut State,
        chi0: JointAngle,
        speed0: f64,
        alpha: f64,
        h: f64,
    ) {
        let n = scene.n_modes();
        state.q.copy_from_slice(&self.y[..n]);
        state.q_dot.copy_from_slice(&self.y[n..2 * n]);
        if state.coordinates == Coordinates::Lagrangian {
            let mut chi1 = chi0;
            chi1.advance((speed0 + 0.5 * alpha * h) * h);
            harmonics(&chi1, scene.layout.k_max, &mut self.harm);
            ale_to_lagrange(
                &scene.layout,
                &self.harm,
                speed0 + alpha * h,
                &mut state.q,
                &mut state.q_dot,
            );
        }
        scene
            .load_models
            .scatter_continuous(&self.y[2 * n..], &mut state.load_models);
    }
}

/// The scale of each unknown where it is 0 — 1e-6 of the plate's thickness
/// for amplitudes and the models' continuous states (positions then rates),
/// that over h for rates — and the blocks of like quantities.
fn difference_scale(scene: &Scene, n: usize, size: usize, h: f64) -> (Vec<f64>, Vec<usize>) {
    let q = 1.0e-6 * scene.model.plate().thickness;
    let half = (size - 2 * n) / 2;
    let blocks = vec![0, n, 2 * n, 2 * n + half, size];
    let scale = (0..size)
        .map(|i| {
            let rate = (n..2 * n).contains(&i) || i >= 2 * n + half;
            if rate {
                q / h
            } else {
                q
            }
        })
        .collect();
    let mut blocks = blocks;
    blocks.dedup();
    (scale, blocks)
}
