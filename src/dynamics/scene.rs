//! The immutable scene: the plate model plus what a configuration adds —
//! node frames (with their mode shapes evaluated once), the joint drive, the
//! reference-frame motion and the set of effects that motion needs.

use crate::config::{Config, JointConfig, LimitsConfig, PlateTheory};
use crate::model::PlateModel;

use super::commands::InputRules;
use super::error::SimulationError;
pub use super::in_plane::InPlaneDynamics;
pub use super::layout::{ModeLayout, ModePair};
use super::load_models::{LoadModels, ModelWrenches, SceneNodes};
pub use super::node_frame::{NodeFrame, NodeKind};
pub use super::residual::ResidualCompliance;
pub use super::stiffening::Stiffening;

/// The effects the reference motion switches on (DESIGN: only what a scene needs).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Effects {
    /// Axial load on the k = 0 modes: −C_t (a_R − g), from gravity or a translating base.
    pub axial_body_force: bool,
    /// k = 1 excitation −C_r ω̇ − ω_z(ω_x s_x + ω_y s_y) and the centrifugal
    /// softening (ω_x² + ω_y²) M_e: the reference frame turns off-axis.
    pub off_axis_rotation: bool,
    /// Node wrenches follow the deformed surface (paper 5.3).
    pub follower_loads: bool,
}

/// The prescribed reference-frame motion, resolved in the reference frame A.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct ReferenceMotion {
    /// ω_A, rad/s.
    pub angular_velocity: [f64; 3],
    /// a_R − g, m/s²: the origin's acceleration less gravity.
    pub specific_force: [f64; 3],
}

/// Everything the stepper needs besides the state and inputs.
#[derive(Debug)]
pub struct Scene {
    /// The plate's modes and body data.
    pub model: PlateModel,
    /// The modes arranged by nodal diameters (axisymmetric ones, cos/sin pairs).
    pub layout: ModeLayout,
    /// The ALE node frames (fixed in space).
    pub ale_nodes: Vec<NodeFrame>,
    /// The Lagrangian node frames (turning with the plate).
    pub lagrange_nodes: Vec<NodeFrame>,
    /// The rotational joint and its drive.
    pub joint: JointConfig,
    /// The bounds a run is stopped at.
    pub limits: LimitsConfig,
    /// The motion of the floating frame's base.
    pub reference: ReferenceMotion,
    /// Which reference-motion and load effects are on.
    pub effects: Effects,
    /// Polar inertia J_zz of the plate about the joint axis, kg·m².
    pub polar_inertia: f64,
    /// Pads, tool, pitch links (paper section 5): only those the configuration gives.
    pub load_models: LoadModels,
    /// The rules every input passes (`commands`).
    pub rules: InputRules,
    /// Residual compliance of the truncated modes between the node frames
    /// (`plate.residual_flexibility`; None when off or without nodes).
    pub residual: Option<ResidualCompliance>,
    /// The geometric stiffness Ω²G_k of the spinning prestress
    /// (`plate.centrifugal_stiffening`; None when off: no cost).
    pub stiffening: Option<Stiffening>,
    /// The in-plane modes after the bending ones (`plate.in_plane_nodal_diameters`;
    /// None without: no cost, [`Scene::add_in_plane`]).
    pub in_plane: Option<InPlaneDynamics>,
}

impl Scene {
    /// The scene of a validated configuration on its built model.
    pub fn new(config: &Config, model: PlateModel) -> Scene {
        let layout = ModeLayout::new(&model);
        let h = config.plate.thickness;
        // Under Mindlin theory a node with residual flexibility is a load patch.
        let patch = (config.plate.residual_flexibility && model.theory() == PlateTheory::Mindlin)
            .then(|| config.plate.residual_patch_half_width());
        let ale_nodes: Vec<NodeFrame> = config
            .nodes
            .ale
            .iter()
            .enumerate()
            .map(|(j, &p)| {
                NodeFrame::new(
                    &model,
                    NodeKind::Ale,
                    p,
                    config.nodes.ale_surface(j).z(h),
                    patch,
                )
            })
            .collect();
        let lagrange_nodes: Vec<NodeFrame> = config
            .nodes
            .lagrange
            .iter()
            .enumerate()
            .map(|(j, &p)| {
                NodeFrame::new(
                    &model,
                    NodeKind::Lagrange,
                    p,
                    config.nodes.lagrange_surface(j).z(h),
                    patch,
                )
            })
            .collect();
        // Gravity is given in world axes; the reference frame is tilted about world x.
        let (st, ct) = config.reference.tilt.sin_cos();
        let g = config.gravity;
        let g_ref = [g[0], ct * g[1] + st * g[2], -st * g[1] + ct * g[2]];
        let a = config.reference.acceleration;
        let specific_force = [a[0] - g_ref[0], a[1] - g_ref[1], a[2] - g_ref[2]];
        let w = config.reference.angular_velocity;
        let has_k0 = !layout.axisymmetric.is_empty();
        let effects = Effects {
            axial_body_force: has_k0 && specific_force[2] != 0.0,
            off_axis_rotation: w[0] != 0.0 || w[1] != 0.0,
            follower_loads: config.loads.follower,
        };
        let polar_inertia = model.body().inertia[2][2];
        let residual = (config.plate.residual_flexibility
            && !(ale_nodes.is_empty() && lagrange_nodes.is_empty()))
        .then(|| ResidualCompliance::new(&model, &ale_nodes, &lagrange_nodes, patch));
        let stiffening = config
            .centrifugal
            .stiffening
            .then(|| Stiffening::new(&model, &config.centrifugal));
        let nodes = SceneNodes {
            ale: &ale_nodes,
            lagrange: &lagrange_nodes,
            modal_mass: &model.body().modal_mass,
            residual: residual.as_ref(),
        };
        let load_models = LoadModels::new(config, &nodes);
        let rules = InputRules::new(
            &config.limits,
            ale_nodes.len(),
            lagrange_nodes.len(),
            &load_models,
        );
        Scene {
            model,
            layout,
            ale_nodes,
            lagrange_nodes,
            joint: config.joint.clone(),
            limits: config.limits.clone(),
            reference: ReferenceMotion {
                angular_velocity: w,
                specific_force,
            },
            effects,
            polar_inertia,
            rules,
            load_models,
            residual,
            stiffening,
            in_plane: None,
        }
    }

    /// Add the in-plane modes `config` selects after the bending ones (the
    /// layout and the node frames' in-plane shapes), refusing what they do
    /// not carry yet (docs/in_plane.md, "In the dynamics").
    pub fn add_in_plane(&mut self, config: &Config) -> Result<(), SimulationError> {
        let Some(mut ip) = InPlaneDynamics::new(
            config,
            self.model.n_modes(),
            &self.ale_nodes,
            &self.lagrange_nodes,
        )?
        else {
            return Ok(());
        };
        ip.check(config, self.load_models.stage_dependent())?;
        if config.joint.max_torque.is_some() {
            ip.free_joint_omega = ip.free_joint_rate(self.polar_inertia);
        }
        self.load_models.attach_in_plane(&ip)?;
        ip.extend_layout(&mut self.layout);
        self.in_plane = Some(ip);
        Ok(())
    }

    /// The residual deflection of the held wrenches `inputs`, for the load
    /// models' contacts (None with `plate.residual_flexibility: false`).
    pub fn held_deflection<'a>(
        &'a self,
        inputs: &'a super::commands::Inputs,
    ) -> Option<super::contact_compliance::HeldDeflection<'a>> {
        self.residual
            .as_ref()
            .map(|compliance| super::contact_compliance::HeldDeflection {
                compliance,
                ale: &inputs.ale,
                lagrange: &inputs.lagrange,
            })
    }

    /// Scratch for the load models' wrenches at this scene's node frames.
    pub fn model_wrenches(&self) -> ModelWrenches {
        ModelWrenches::new(
            self.ale_nodes.len(),
            self.lagrange_nodes.len(),
            &self.load_models,
        )
    }

    /// The number of elastic coordinates: the bending modes, then the in-plane ones.
    pub fn n_modes(&self) -> usize {
        self.model.n_modes() + self.in_plane.as_ref().map_or(0, |ip| ip.len())
    }

    /// Per elastic coordinate (bending, then in-plane): k, modal mass, ζ, ω.
    pub fn elastic_modes(&self) -> impl Iterator<Item = (u32, f64, f64, f64)> + '_ {
        let bending = self
            .model
            .modes()
            .iter()
            .map(|m| (m.k, m.modal_mass, m.damping, m.omega));
        let in_plane = self
            .in_plane
            .iter()
            .flat_map(|ip| &ip.modes)
            .map(|m| (m.k, m.modal_mass, m.damping, m.omega));
        bending.chain(in_plane)
    }

    /// Unknowns of the first-order system `contact_exponential` advances: the
    /// ALE amplitudes and rates of every mode, then the load models'
    /// continuous states.
    pub(crate) fn first_order_unknowns(&self) -> usize {
        2 * self.n_modes() + self.load_models.continuous_states()
    }

    /// Square of the reference frame's off-axis angular velocity, ω_x² + ω_y²
    /// (invariant under the spin about z).
    pub fn off_axis_rate_squared(&self) -> f64 {
        let w = self.reference.angular_velocity;
        if self.effects.off_axis_rotation {
            w[0] * w[0] + w[1] * w[1]
        } else {
            0.0
        }
    }
}
