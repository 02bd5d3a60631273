//! The right-hand side of the elastic ODE at one instant — RK4's stages and
//! the frozen instant of `contact_exponential`: the load models evaluated
//! at the instant's kinematics, the node loads, the reference motion and the
//! modal accelerations (eq. 12 with eq. 11's reference-motion terms), and
//! where the joint is integrated in the step, the drive's law at the instant.

use super::model_evaluation::ModelEvaluation;
use super::{StateView, Views};
use crate::config::Coordinates;
use crate::dynamics::ale::harmonics;
use crate::dynamics::commands::Inputs;
use crate::dynamics::integrators::equations::{
    accelerations, ModalEquations, ModeConstants, ReferenceMotion,
};
use crate::dynamics::joint::{DriveStep, StageDrive, DRIVE_SWITCHES};
use crate::dynamics::load_models::{LoadContext, LoadModelState, ModelWrenches};
use crate::dynamics::loads::{add_reference_motion, compute as node_loads, StepLoads};
use crate::dynamics::scene::Scene;
use crate::dynamics::state::JointAngle;

/// What the right-hand side reads besides y = (q, q̇, the models' continuous states).
pub(super) struct StageRhs<'a> {
    pub scene: &'a Scene,
    pub inputs: &'a Inputs,
    pub consts: &'a [ModeConstants],
    /// The description y is in.
    pub coords: Coordinates,
    /// Joint acceleration α (the kΩ̇ term of the ALE equations) when held.
    pub alpha: f64,
    /// The held joint acceleration whose Euler force −s α acts on the
    /// torsional in-plane modes (the joint's own, also where `alpha` is
    /// that of a frame turning at the mean speed).
    pub euler_alpha: f64,
    /// The drive's law at each instant instead of `alpha`: the joint
    /// integrated in the step (`joint_in_y` in in_plane_joint.rs).
    pub drive: Option<StageDrive<'a>>,
    /// The drive law's switching functions at the last evaluation
    /// ([`StageDrive::margins`]; with `drive`).
    pub drive_margins: [f64; DRIVE_SWITCHES],
    /// The node loads at the substep start (used when nothing in them depends on y).
    pub base_ale_frame: &'a [f64],
    pub harm: &'a mut Vec<(f64, f64)>,
    pub views: &'a mut Views,
    pub loads: &'a mut StepLoads,
    pub model_wrenches: &'a mut ModelWrenches,
    /// What `model_wrenches` holds the evaluation of.
    pub evaluation: &'a mut ModelEvaluation,
    /// The models' slots with y's continuous states scattered in (None: the models have none).
    pub stage_slots: Option<&'a mut LoadModelState>,
    pub slots: &'a LoadModelState,
}

impl StageRhs<'_> {
    /// ẏ at joint angle χ and speed Ω into `dy`; with a drive, its law at
    /// the instant's axial torque (dΩ/dt and the drive torque).
    pub fn eval(
        &mut self,
        chi: JointAngle,
        speed: f64,
        y: &[f64],
        dy: &mut [f64],
    ) -> Option<DriveStep> {
        let scene = self.scene;
        let n = scene.n_modes();
        harmonics(&chi, scene.layout.k_max, self.harm);
        let (q, rest) = y.split_at(n);
        let (v, s) = rest.split_at(n);
        let stage_models = scene.load_models.stage_dependent();
        if scene.effects.follower_loads || stage_models {
            let st = StateView {
                q,
                v,
                coords: self.coords,
                speed,
            };
            st.fill(scene, self.harm, self.views);
            if stage_models {
                let ctx = LoadContext {
                    ale_nodes: &scene.ale_nodes,
                    lagrange_nodes: &scene.lagrange_nodes,
                    q_ale: &self.views.q_ale,
                    q_dot_ale: &self.views.q_dot_ale,
                    chi: chi.angle,
                    speed,
                    held: scene.held_deflection(self.inputs),
                };
                let slots = match self.stage_slots.as_deref_mut() {
                    Some(stage) => {
                        scene.load_models.scatter_continuous(s, stage);
                        &*stage
                    }
                    None => self.slots,
                };
                self.evaluation.evaluate(
                    &scene.load_models,
                    &ctx,
                    slots,
                    &self.inputs.commands,
                    self.model_wrenches,
                );
            }
            node_loads(
                scene,
                self.inputs,
                self.model_wrenches,
                &self.views.q_ale,
                &self.views.q_lagrange,
                self.loads,
            );
            // The Euler force −s α of the imposed joint acceleration on the
            // torsional modes (`base_ale_frame` has it from the substep's start).
            if let (Some(ip), None) = (&scene.in_plane, self.drive) {
                ip.add_euler_force(self.euler_alpha, &mut self.loads.ale_frame);
            }
        } else {
            self.loads.ale_frame.copy_from_slice(self.base_ale_frame);
        }
        let drive = self.drive.map(|d| self.joint_law(d, speed, q, v));
        add_reference_motion(scene, speed, &mut self.loads.ale_frame);
        let (dq, rest) = dy.split_at_mut(n);
        let (dv, ds) = rest.split_at_mut(n);
        dq.copy_from_slice(v);
        let equations = ModalEquations {
            scene,
            consts: self.consts,
            coords: self.coords,
        };
        let motion = ReferenceMotion {
            harmonics: self.harm,
            speed,
            accel: drive.map_or(self.alpha, |d| d.acceleration),
        };
        accelerations(equations, motion, self.loads, q, v, dv);
        ds.copy_from_slice(&self.model_wrenches.rates);
        drive
    }

    /// The drive's law at the instant. With torsional in-plane modes it
    /// decides with the reduced inertia and load torque of the instant's
    /// state (`InPlaneDynamics::reduced_joint`, exact for the coupled
    /// J Ω̇ + Σ s q̈ = τ, m q̈ + s Ω̇ + … = f), and the modes feel the Euler
    /// force −s Ω̇ of the acceleration it gives — a torque-limited drive at
    /// its limit so leaves the joint free with every torsional mode. The
    /// k = 0 amplitudes are the same in both descriptions.
    fn joint_law(&mut self, d: StageDrive, speed: f64, q: &[f64], v: &[f64]) -> DriveStep {
        let torque = self.loads.axial_torque;
        let Some(ip) = self
            .scene
            .in_plane
            .as_ref()
            .filter(|ip| !ip.torsional.is_empty())
        else {
            self.drive_margins = d.margins(speed, torque);
            return d.at(speed, torque);
        };
        let f = &self.loads.ale_frame;
        let (inertia, torque) = ip.reduced_joint(d.polar_inertia, torque, speed, f, q, v);
        let reduced = StageDrive {
            polar_inertia: inertia,
            ..d
        };
        self.drive_margins = reduced.margins(speed, torque);
        let step = reduced.at(speed, torque);
        ip.add_euler_force(step.acceleration, &mut self.loads.ale_frame);
        step
    }
}
