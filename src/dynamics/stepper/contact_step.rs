//! The stepper's `contact_exponential` substep (docs/dynamics.md, "Stiff
//! contacts"): the elastic state in the ALE description — where space-fixed
//! pads make the equations autonomous at a held joint speed — stepped by
//! [`ContactExponential`] with the right-hand side frozen at the substep's
//! mid-instant — or, where the joint is integrated in the step, Ω from y and
//! the drive's law.
//!
//! Under a held acceleration α the step is taken in the frame turning at the
//! mean speed Ω̄ = Ω0 + αh/2 (angle χ̄ = χ0 + Ω̄t), which meets the ALE frame
//! at both ends of the step (χ̄ − χ = −αt(h − t)/2 vanishes at 0 and h): its
//! equations are the ALE ones at Ω̄ with no kΩ̇ term, autonomous for the
//! plate, and the pads sit in it within αh²/8 of their place. The two frames'
//! velocities differ by k(Ω̄ − Ω) J q̄ per pair (q̄̇ = R q̇ + kΩ J q̄), kΩ̇h/2 J q̄
//! at either end: the step adds it on entry and again on exit
//! ([`frame_kick`]). Holding Ω̄ and α in the ALE equations instead spreads
//! the kΩ̇ J q̄ term over the step, which where ωh ≫ 1 does not act as the
//! two kicks do: on the brake bench its difference from the converged
//! reference stopped falling with h (docs/dynamics.md, "Stiff contacts").
//! The load models are evaluated at Ω̄ (their sliding speed).

use super::stage_rhs::StageRhs;
use super::{load_context, JointEnd, Stepper, SubstepMotion};
use crate::config::Coordinates;
use crate::dynamics::ale::{ale_to_lagrange, harmonics};
use crate::dynamics::commands::Inputs;
use crate::dynamics::error::StepError;
use crate::dynamics::integrators::contact_exponential::ContactExponential;
use crate::dynamics::integrators::piece::SAMPLE_ANGLE;
use crate::dynamics::joint::{StageDrive, DRIVE_SWITCHES};
use crate::dynamics::load_models::LoadContext;
use crate::dynamics::scene::Scene;
use crate::dynamics::state::{JointAngle, State};

/// Switching instants are located to within this (s), or h / 2^40.
pub const SWITCH_RESOLUTION: f64 = 2.5e-7;

impl Stepper {
    /// One substep of h from (χ0, Ω0) under α by the contact exponential.
    /// With `stage_drive` the joint's Ω and ∫τ_drive dt ride in y (the
    /// drive's law in f, so J couples the joint with the contacts) and the
    /// joint's end is returned; χ moves at the mean of Ω0 and Ω1.
    pub(super) fn contact_exponential(
        &mut self,
        scene: &Scene,
        state: &mut State,
        inputs: &Inputs,
        joint: &SubstepMotion,
        tolerance: f64,
        stage_drive: Option<StageDrive>,
    ) -> Result<Option<JointEnd>, StepError> {
        let SubstepMotion {
            h,
            chi0,
            speed0,
            alpha,
            ..
        } = *joint;
        let speed_mean = speed0 + 0.5 * alpha * h;
        let mut chi_mid = chi0;
        // Held joint: the frame turning at Ω̄ (its angle at h/2) and the
        // velocities' kick into it; a joint in y: the ALE frame, χ at h/2.
        let kick = match stage_drive {
            None => {
                chi_mid.advance(0.5 * speed_mean * h);
                0.5 * alpha * h
            }
            Some(_) => {
                chi_mid.advance(0.5 * speed0 * h + 0.125 * alpha * h * h);
                0.0
            }
        };
        let m = scene.first_order_unknowns();
        self.contact_prepare(scene, state, h, stage_drive);
        frame_kick(scene, kick, &mut self.y);
        let reads_chi = scene.load_models.reads_joint_angle(&LoadContext {
            chi: chi_mid.angle,
            speed: speed_mean,
            ..load_context(scene, state, inputs)
        });
        self.held_key(scene, inputs, speed_mean, chi_mid, reads_chi);
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
            evaluation,
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
            alpha: 0.0,
            euler_alpha: alpha,
            drive: stage_drive,
            drive_margins: [1.0; DRIVE_SWITCHES],
            base_ale_frame,
            harm,
            views,
            loads,
            model_wrenches,
            evaluation,
            stage_slots: continuous.then_some(stage_slots),
            slots: &state.load_models,
        };
        let mut eval = |yy: &[f64], dy: &mut [f64], s: &mut [f64]| {
            let (yy, joint_y) = yy.split_at(m);
            let (dy, joint_dy) = dy.split_at_mut(m);
            // y's joint entries, when it rides in y: Ω, ∫τ_drive dt.
            let speed = joint_y.first().copied().unwrap_or(speed_mean);
            if let Some(d) = stage.eval(chi_mid, speed, yy, dy) {
                joint_dy.copy_from_slice(&[d.acceleration, d.effort]);
            }
            let (s_models, s_drive) = s.split_at_mut(stage.model_wrenches.switching.len());
            s_models.copy_from_slice(&stage.model_wrenches.switching);
            s_drive.copy_from_slice(&stage.drive_margins[..s_drive.len()]);
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
        self.unlocated_substeps += u64::from(self.last_contact.unlocated);
        if self.last_contact.undersampled_rate > 0.0 {
            return Err(StepError::SwitchesUndersampled {
                rate: self.last_contact.undersampled_rate,
                bound: self.rate_at_rest,
                unit: h / (self.contact_levels.map_or(0, |(l, _)| l) as f64).exp2(),
                speed: speed0,
            });
        }
        let end = stage_drive.map(|_| {
            let speed1 = self.y[m];
            let mut chi1 = chi0;
            chi1.advance(0.5 * (speed0 + speed1) * h);
            JointEnd {
                chi1,
                speed1,
                acceleration: (speed1 - speed0) / h,
                effort: self.y[m + 1] / h,
            }
        });
        frame_kick(scene, kick, &mut self.y);
        let (chi1, speed1) = end.map_or((joint.chi1, joint.speed1), |e| (e.chi1, e.speed1));
        self.contact_finish(scene, state, chi1, speed1);
        Ok(end)
    }

    /// y ← the ALE state and the models' continuous states, then with a
    /// stage drive Ω0 and 0 (∫τ_drive dt); the integrator (re)made for this
    /// h and that many unknowns.
    fn contact_prepare(
        &mut self,
        scene: &Scene,
        state: &State,
        h: f64,
        stage_drive: Option<StageDrive>,
    ) {
        let n = scene.n_modes();
        let models = &scene.load_models;
        let m = scene.first_order_unknowns();
        let size = m + stage_drive.map_or(0, |_| CONTACT_JOINT_UNKNOWNS);
        // Units fine enough to locate a switch to SWITCH_RESOLUTION and to
        // sample the fastest piece every quarter radian (the modes with
        // every contact closed, at rest: λ_max at Ω = 0).
        let unit = SWITCH_RESOLUTION.min(SAMPLE_ANGLE / self.rate_at_rest);
        let levels = ContactExponential::levels_for(h, unit);
        if self.contact_levels != Some((levels, size)) {
            let switches = models.switching_functions() + stage_drive.map_or(0, |_| DRIVE_SWITCHES);
            let mut c = ContactExponential::new(size, switches, levels);
            let (mut scale, mut blocks) = difference_scale(scene, n, m, h);
            if let Some(d) = stage_drive {
                // Ω, ∫τ_drive dt: each its own block.
                scale.extend([
                    1.0e-6 * d.command.abs().max(1.0),
                    1.0e-6 * d.joint.max_torque.unwrap_or(1.0) * h,
                ]);
                blocks.extend([m + 1, m + 2]);
            }
            c.set_scale(&scale, &blocks);
            // Ω in y: the ALE terms (2kΩ, k²Ω²), the spin terms and the
            // friction's sliding speed are not affine in it, so a piece is
            // linearised where the step starts, not at the origin (Ω = 0).
            c.linearise_at_state(models.law_reads_memory() || stage_drive.is_some());
            self.contact = Some(c);
            self.contact_levels = Some((levels, size));
        }
        let (q, v) = state.ale();
        self.y[..n].copy_from_slice(q);
        self.y[n..2 * n].copy_from_slice(v);
        models.gather_continuous(&state.load_models, &mut self.y[2 * n..]);
        if stage_drive.is_some() {
            self.y.extend_from_slice(&[state.speed, 0.0]);
        }
    }

    /// The cache key of what the step holds: Ω̄, the commands, with
    /// follower loads the held wrenches and χ (they then enter J), with
    /// residual flexibility the held wrenches (their residual deflection
    /// moves the contacts' pieces), and χ where the models read it
    /// (`models_chi`: the residual deflection of held normal forces).
    fn held_key(
        &mut self,
        scene: &Scene,
        inputs: &Inputs,
        speed: f64,
        chi: JointAngle,
        models_chi: bool,
    ) {
        let k = &mut self.contact_key;
        k.clear();
        k.push(speed.to_bits());
        for v in inputs.commands.values.iter().flatten() {
            k.push(v.to_bits());
        }
        if scene.effects.follower_loads || models_chi {
            k.push(chi.angle.to_bits());
        }
        if scene.effects.follower_loads || scene.residual.is_some() {
            for w in inputs.ale.iter().chain(&inputs.lagrange) {
                k.extend(w.force.iter().chain(&w.moment).map(|v| v.to_bits()));
            }
        }
    }

    /// Write y back: the ALE state (and the Lagrangian one as primary where
    /// the scene integrates in it, at the substep's end χ1, Ω1), the models'
    /// continuous states; y keeps the elastic unknowns only.
    fn contact_finish(&mut self, scene: &Scene, state: &mut State, chi1: JointAngle, speed1: f64) {
        let n = scene.n_modes();
        let m = scene.first_order_unknowns();
        state.q.copy_from_slice(&self.y[..n]);
        state.q_dot.copy_from_slice(&self.y[n..2 * n]);
        if state.coordinates == Coordinates::Lagrangian {
            harmonics(&chi1, scene.layout.k_max, &mut self.harm);
            ale_to_lagrange(
                &scene.layout,
                &self.harm,
                speed1,
                &mut state.q,
                &mut state.q_dot,
            );
        }
        scene
            .load_models
            .scatter_continuous(&self.y[2 * n..m], &mut state.load_models);
        self.y.truncate(m);
    }
}

/// q̄̇ += k·`kick`·J q̄ per pair of y's amplitudes (J q̄ = (−q̄_s, q̄_c)): the
/// velocities from the ALE frame into the frame turning at Ω̄ at the step's
/// start, and back at its end, with `kick` = Ω̄ − Ω0 = Ω1 − Ω̄ = αh/2.
fn frame_kick(scene: &Scene, kick: f64, y: &mut [f64]) {
    if kick == 0.0 {
        return;
    }
    let n = scene.n_modes();
    let (q, v) = y.split_at_mut(n);
    for p in &scene.layout.pairs {
        let w = p.k as f64 * kick;
        v[p.cos] -= w * q[p.sin];
        v[p.sin] += w * q[p.cos];
    }
}

/// The joint's unknowns after the elastic ones when it rides in y: Ω, ∫τ_drive dt.
const CONTACT_JOINT_UNKNOWNS: usize = 2;

/// The scale of each unknown where it is 0 — 1e-6 of the plate's thickness
/// for amplitudes and the models' continuous positions, that over h for
/// rates (the modal rates, each model's last [`crate::dynamics::load_models::LoadModel::continuous_rates`]
/// states) — and the blocks of like quantities: amplitudes, rates, then per
/// model its positions and its rates.
fn difference_scale(scene: &Scene, n: usize, size: usize, h: f64) -> (Vec<f64>, Vec<usize>) {
    let q = 1.0e-6 * scene.model.plate().thickness;
    let mut scale = vec![q; size];
    scale[n..2 * n].fill(q / h);
    let mut blocks = vec![0, n, 2 * n];
    let mut start = 2 * n;
    for m in scene.load_models.models() {
        let end = start + m.continuous_states();
        let rates = end - m.continuous_rates();
        scale[rates..end].fill(q / h);
        blocks.extend([rates, end]);
        start = end;
    }
    debug_assert_eq!(start, size);
    blocks.dedup();
    (scale, blocks)
}
