//! RK4 over a substep: sub-stepped below its step limit, the load models
//! and node loads evaluated at every stage, the joint in its unknowns where
//! the drive's law decides within the step.

use super::stage_rhs::StageRhs;
use super::{JointEnd, Stepper, StepperSettings, SubstepMotion};
use crate::dynamics::commands::Inputs;
use crate::dynamics::error::StepError;
use crate::dynamics::integrators::rk4;
use crate::dynamics::joint::{StageDrive, DRIVE_SWITCHES};
use crate::dynamics::scene::Scene;
use crate::dynamics::state::State;

impl Stepper {
    /// RK4 over the substep, sub-stepped below its step limit, the load
    /// models and node loads evaluated at every stage. With `stage_drive` the
    /// joint (χ − χ0, Ω, ∫τ_drive dt) is integrated with the elastic state,
    /// the drive's law at every stage, and its end returned; otherwise the
    /// joint moves under the held α.
    pub(super) fn rk4(
        &mut self,
        scene: &Scene,
        settings: &StepperSettings,
        state: &mut State,
        inputs: &Inputs,
        joint: &SubstepMotion,
        stage_drive: Option<StageDrive>,
    ) -> Result<Option<JointEnd>, StepError> {
        let SubstepMotion {
            h,
            chi0,
            speed0,
            alpha,
            ..
        } = *joint;
        let inner = self.checked_inner_substeps(scene, settings, h, speed0, alpha)?;
        self.last_inner_substeps = self.last_inner_substeps.max(inner);
        let n = scene.n_modes();
        let m = scene.first_order_unknowns();
        let coords = state.coordinates;
        if stage_drive.is_some() {
            self.y.extend_from_slice(&[0.0, speed0, 0.0]);
        }
        self.y[..n].copy_from_slice(&state.q);
        self.y[n..2 * n].copy_from_slice(&state.q_dot);
        let continuous = scene.load_models.continuous_states() > 0;
        if continuous {
            scene
                .load_models
                .gather_continuous(&state.load_models, &mut self.y[2 * n..]);
            self.stage_slots.copy_from(&state.load_models);
        }
        self.base_ale_frame.copy_from_slice(&self.loads.ale_frame);
        let Stepper {
            consts,
            loads,
            base_ale_frame,
            harm,
            views,
            y,
            rk,
            model_wrenches,
            evaluation,
            stage_slots,
            ..
        } = self;
        let mut stage = StageRhs {
            scene,
            inputs,
            consts,
            coords,
            alpha,
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
        let dt = h / inner as f64;
        let mut rhs = |t: f64, yy: &[f64], dy: &mut [f64]| {
            let (yy, joint_y) = yy.split_at(m);
            let (dy, joint_dy) = dy.split_at_mut(m);
            let mut chi = chi0;
            if stage_drive.is_some() {
                // y's joint entries: χ − χ0, Ω, ∫τ_drive dt.
                chi.advance(joint_y[0]);
                let d = stage.eval(chi, joint_y[1], yy, dy).expect("a stage drive");
                joint_dy.copy_from_slice(&[joint_y[1], d.acceleration, d.effort]);
            } else {
                chi.advance(speed0 * t + 0.5 * alpha * t * t);
                stage.eval(chi, speed0 + alpha * t, yy, dy);
            }
        };
        for j in 0..inner {
            rk4::step(j as f64 * dt, dt, y, rk, &mut rhs);
        }
        state.q.copy_from_slice(&y[..n]);
        state.q_dot.copy_from_slice(&y[n..2 * n]);
        if continuous {
            scene
                .load_models
                .scatter_continuous(&y[2 * n..m], &mut state.load_models);
        }
        let end = stage_drive.map(|_| {
            let mut chi1 = chi0;
            chi1.advance(y[m]);
            JointEnd {
                chi1,
                speed1: y[m + 1],
                acceleration: (y[m + 1] - speed0) / h,
                effort: y[m + 2] / h,
            }
        });
        y.truncate(m);
        Ok(end)
    }
}
