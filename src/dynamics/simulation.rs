//! The facade the CLI and the ROS node drive: scene + state + stepper + held inputs.

use crate::config::{Config, IntegratorKind};
use crate::model::{ModelError, PlateModel};
use thiserror::Error;

use super::ale::{harmonics, lagrange_to_ale};
use super::load_models::{LoadCommandError, LoadModels, ModelWrenches, Pads, Tool};
use super::loads::Inputs;
use super::scene::{NodeFrame, Scene};
use super::state::State;
use super::stepper::{Stepper, StepperSettings};
use super::wrench::{InputError, NodeKind, Wrench};

#[derive(Debug, Error)]
pub enum SimulationError {
    #[error(transparent)]
    Model(#[from] ModelError),
    #[error("simulation.integrator = rk4 would need {needed} substeps per step of {step:e} s for the highest mode ({frequency_hz:.0} Hz) at {speed} rad/s (limit {limit}): use exponential or implicit_midpoint, or raise simulation.rate_hz / simulation.substeps")]
    ExplicitTooCostly { needed: usize, limit: usize, step: f64, frequency_hz: f64, speed: f64 },
    #[error("the pads (pads.contact_stiffness, pads.contact_damping) couple the modes at rates up to {rate:.0} 1/s, but simulation.integrator = {integrator} holds their forces over a substep of {step:e} s (h × rate = {:.2} > {limit}): use simulation.integrator: rk4, which evaluates the pads at every stage, or raise simulation.rate_hz / simulation.substeps", step * rate)]
    PadsTooStiffForIntegrator { integrator: &'static str, rate: f64, step: f64, limit: f64 },
}

/// Largest h × (pad coupling rate) the integrators that hold the pad forces over a substep accept.
pub const HELD_PAD_COUPLING_LIMIT: f64 = 0.5;

/// Forces of one pad at the current state (both faces, all its contact points).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct PadOutput {
    /// Commanded clamp force, N.
    pub clamp_force: f64,
    /// Mean normal force of the two faces, summed over the contact points, N
    /// (equals the clamp force on an undeformed disc).
    pub normal_force: f64,
    /// Friction force along e_θ, summed over contacts and faces, N.
    pub friction_force: f64,
    /// Friction torque about the axis, N·m (brakes the plate: opposite to Ω).
    pub friction_torque: f64,
}

/// The lathe tool at the current state.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct ToolOutput {
    /// z of the tool tip in the reference frame (the +z face is at h/2), m.
    pub tip: f64,
    /// Chip thickness of the last substep, m.
    pub chip: f64,
    /// Feed force of the last substep, N (acts on the plate along −z).
    pub feed_force: f64,
    /// Commanded feed rate, m/s.
    pub feed_rate: f64,
}

/// A step that could not be taken; the state is left as it was before the step.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum StepError {
    #[error("the simulation diverged at t = {time} s: {detail}")]
    Diverged { time: f64, detail: String },
    #[error("rk4 would need {needed} substeps of a {step:e} s step (limit {limit}) at the current speed: use exponential or implicit_midpoint")]
    ExplicitTooCostly { needed: usize, limit: usize, step: f64 },
}

/// The rotational joint at the axis: angle χ (unwrapped), speed Ω, drive torque.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct JointOutput {
    pub position: f64,
    pub velocity: f64,
    pub effort: f64,
}

/// A rigid transform: translation (m) and unit quaternion (x, y, z, w).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Pose {
    pub translation: [f64; 3],
    pub rotation: [f64; 4],
}

impl Pose {
    pub const IDENTITY: Pose = Pose { translation: [0.0; 3], rotation: [0.0, 0.0, 0.0, 1.0] };

    /// A rotation about z by `angle`.
    pub fn about_z(angle: f64) -> Pose {
        let (s, c) = (0.5 * angle).sin_cos();
        Pose { translation: [0.0; 3], rotation: [0.0, 0.0, s, c] }
    }
}

/// Kinematics of one node frame.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct NodeOutput {
    /// In the parent frame: plate_base for ALE nodes, plate_rotor for Lagrangian ones.
    pub pose: Pose,
    /// Transverse elastic displacement w, m.
    pub uz: f64,
    /// dw/dt of the frame (for an ALE node: of the space-fixed point), m/s.
    pub uz_dot: f64,
    /// Surface tilt (θ_x, θ_y), rad.
    pub tilt: [f64; 2],
    /// Transverse velocity of the material under the node, m/s (ALE: ∂w/∂t + Ω ∂w/∂θ).
    pub material_uz_dot: f64,
}

pub struct Simulation {
    config: Config,
    scene: Scene,
    state: State,
    initial: State,
    stepper: Stepper,
    inputs: Inputs,
    steps: u64,
    /// The load models' wrenches at the current state (for the outputs).
    model_outputs: ModelWrenches,
}

impl Simulation {
    pub fn new(config: Config) -> Result<Simulation, SimulationError> {
        let model = PlateModel::new(&config.plate)?;
        let scene = Scene::new(&config, model);
        let settings = StepperSettings {
            integrator: config.simulation.integrator,
            dt: 1.0 / config.simulation.rate_hz,
            substeps: config.simulation.substeps,
            rk4_step_limit: config.simulation.rk4_step_limit,
        };
        let stepper = Stepper::new(&scene, settings);
        if settings.integrator == IntegratorKind::Rk4 {
            let speed = config.joint.speed.abs();
            let needed = stepper.rk4_substeps(&scene, stepper.h(), speed);
            if needed > super::integrators::rk4::MAX_SUBSTEPS {
                let f_max = scene.model.modes().iter().map(|m| m.frequency_hz).fold(0.0, f64::max);
                return Err(SimulationError::ExplicitTooCostly {
                    needed,
                    limit: super::integrators::rk4::MAX_SUBSTEPS,
                    step: stepper.h(),
                    frequency_hz: f_max,
                    speed,
                });
            }
        }
        if scene.load_models.pads.is_some() && settings.integrator != IntegratorKind::Rk4 {
            let lm = &scene.load_models;
            let rate = lm.pad_stiffness_rate_sq.sqrt() + lm.pad_damping_rate;
            let h = stepper.h();
            if h * rate > HELD_PAD_COUPLING_LIMIT {
                return Err(SimulationError::PadsTooStiffForIntegrator { integrator: settings.integrator.name(), rate, step: h, limit: HELD_PAD_COUPLING_LIMIT });
            }
        }
        let n = scene.n_modes();
        let mut initial = State::new(n, config.simulation.coordinates, config.joint.initial_position, config.joint.speed);
        initial.load_models = scene.load_models.initial_state();
        if !config.initial.q.is_empty() || !config.initial.q_dot.is_empty() {
            // initial.* are Lagrangian; the state may be kept in ALE coordinates.
            let mut q = config.initial.q.clone();
            let mut q_dot = config.initial.q_dot.clone();
            q.resize(n, 0.0);
            q_dot.resize(n, 0.0);
            if initial.coordinates == crate::config::Coordinates::Ale {
                let mut harm = Vec::new();
                harmonics(&initial.chi, scene.layout.k_max, &mut harm);
                lagrange_to_ale(&scene.layout, &harm, initial.speed, &mut q, &mut q_dot);
            }
            initial.q = q;
            initial.q_dot = q_dot;
        }
        let mut sim = Simulation {
            state: initial.clone(),
            initial,
            stepper,
            inputs: Inputs::default(),
            steps: 0,
            model_outputs: ModelWrenches::new(&scene),
            scene,
            config,
        };
        sim.reset();
        Ok(sim)
    }

    pub fn config(&self) -> &Config {
        &self.config
    }
    pub fn model(&self) -> &PlateModel {
        &self.scene.model
    }
    pub fn scene(&self) -> &Scene {
        &self.scene
    }
    pub fn state(&self) -> &State {
        &self.state
    }
    /// RK4 substeps per substep in the last step (1 for the other integrators).
    pub fn rk4_inner_substeps(&self) -> usize {
        self.stepper.last_inner_substeps()
    }
    pub fn inputs(&self) -> &Inputs {
        &self.inputs
    }
    /// Simulated time since the start (or the last reset), s.
    pub fn time(&self) -> f64 {
        self.state.time
    }
    pub fn step_count(&self) -> u64 {
        self.steps
    }
    /// The output step 1/rate_hz, s.
    pub fn dt(&self) -> f64 {
        1.0 / self.config.simulation.rate_hz
    }
    pub fn n_ale_nodes(&self) -> usize {
        self.scene.ale_nodes.len()
    }
    pub fn n_lagrange_nodes(&self) -> usize {
        self.scene.lagrange_nodes.len()
    }

    /// Back to t = 0 with the parameter file's speed and loads.
    pub fn reset(&mut self) {
        self.state.copy_from(&self.initial);
        self.steps = 0;
        self.inputs.speed_command = self.config.joint.speed;
        let to_wrench = |w: &crate::config::WrenchConfig| Wrench { force: w.force, moment: w.moment };
        self.inputs.ale = (0..self.n_ale_nodes()).map(|j| self.config.loads.ale.get(j).map(to_wrench).unwrap_or_default()).collect();
        self.inputs.lagrange = (0..self.n_lagrange_nodes()).map(|j| self.config.loads.lagrange.get(j).map(to_wrench).unwrap_or_default()).collect();
        LoadModels::reset_commands(&self.config, &mut self.inputs.commands);
        self.stepper.sync_views(&self.scene, &self.state);
        self.refresh_model_outputs();
    }

    /// Evaluate the load models at the current state for the outputs (the
    /// tool's force is the one held over the last substep).
    fn refresh_model_outputs(&mut self) {
        let lm = &self.scene.load_models;
        if lm.is_empty() {
            return;
        }
        let views = self.stepper.views();
        let tool_force = self.state.load_models.tool.as_ref().map_or(0.0, |t| t.force);
        lm.evaluate(&self.scene.ale_nodes, &views.q_ale, &views.q_dot_ale, self.state.chi.angle, self.state.speed, &self.inputs.commands, tool_force, &mut self.model_outputs);
    }

    /// Replace the state (e.g. a checkpoint taken with `state().clone()`).
    pub fn restore(&mut self, state: State, steps: u64) {
        assert_eq!(state.q.len(), self.scene.n_modes());
        self.state = state;
        self.steps = steps;
        self.stepper.sync_views(&self.scene, &self.state);
        self.refresh_model_outputs();
    }

    /// Advance one output step (1/rate_hz). On error the state is unchanged.
    pub fn step(&mut self) -> Result<(), StepError> {
        self.stepper.step(&self.scene, &mut self.state, &self.inputs)?;
        self.steps += 1;
        // Time as a count of steps: no drift from repeated addition.
        self.state.time = self.steps as f64 * self.dt();
        self.refresh_model_outputs();
        Ok(())
    }

    pub fn set_speed_command(&mut self, omega: f64) -> Result<(), InputError> {
        if !omega.is_finite() {
            return Err(InputError::NonFinite { what: "speed command".into(), value: omega });
        }
        if omega.abs() > self.config.limits.max_speed {
            return Err(InputError::Absurd { what: "speed command".into(), value: omega, limit: self.config.limits.max_speed });
        }
        self.inputs.speed_command = omega;
        Ok(())
    }

    /// Hold a wrench on ALE node `node` (0-based) until replaced.
    pub fn set_ale_wrench(&mut self, node: usize, wrench: Wrench) -> Result<(), InputError> {
        self.set_wrench(NodeKind::Ale, node, wrench)
    }

    /// Hold a wrench on Lagrangian node `node` (0-based) until replaced.
    pub fn set_lagrange_wrench(&mut self, node: usize, wrench: Wrench) -> Result<(), InputError> {
        self.set_wrench(NodeKind::Lagrange, node, wrench)
    }

    fn set_wrench(&mut self, kind: NodeKind, node: usize, wrench: Wrench) -> Result<(), InputError> {
        let limits = &self.config.limits;
        let list = match kind {
            NodeKind::Ale => &mut self.inputs.ale,
            NodeKind::Lagrange => &mut self.inputs.lagrange,
        };
        let count = list.len();
        let slot = list.get_mut(node).ok_or(InputError::NoSuchNode { kind, index: node + 1, count })?;
        wrench.validate(|| format!("{}_{} wrench", kind.name(), node + 1), limits.max_force, limits.max_moment)?;
        *slot = wrench;
        Ok(())
    }

    // ---- load models (paper section 5; docs/scenes.md) ----------------------

    /// Number of brake pads (`pads.*`; 0 without pads).
    pub fn pad_count(&self) -> usize {
        self.scene.load_models.pads.as_ref().map_or(0, Pads::pad_count)
    }

    /// Whether the scene has a lathe tool (`tool.*`).
    pub fn has_tool(&self) -> bool {
        self.scene.load_models.tool.is_some()
    }

    /// Number of pitch links (`links.*`; 0 without links).
    pub fn link_count(&self) -> usize {
        self.scene.load_models.links.as_ref().map_or(0, |l| l.nodes.len())
    }

    /// Hold the clamp force of pad `pad` (0-based), N: the force each disc face
    /// is pressed with, shared by the pad's contact points. Refused (and the
    /// held commands unchanged) if the pad does not exist or the force is not
    /// finite, negative or above `limits.max_force`.
    pub fn set_pad_clamp_force(&mut self, pad: usize, newtons: f64) -> Result<(), LoadCommandError> {
        self.scene.load_models.set_clamp_force(&mut self.inputs.commands, pad, newtons, &self.config.limits)?;
        self.refresh_model_outputs();
        Ok(())
    }

    /// Hold the tool feed rate, m/s (towards −z; negative retracts). Refused if
    /// the scene has no tool or the rate is not finite or beyond 1 m/s.
    pub fn set_tool_feed(&mut self, rate: f64) -> Result<(), LoadCommandError> {
        self.scene.load_models.set_feed_rate(&mut self.inputs.commands, rate)
    }

    /// Forces of pad `pad` (0-based) at the current state.
    pub fn pad_output(&self, pad: usize) -> PadOutput {
        let Some(p) = &self.scene.load_models.pads else { return PadOutput::default() };
        let mut out = PadOutput { clamp_force: self.inputs.commands.clamp_force[pad], ..PadOutput::default() };
        for (c, f) in p.contacts.iter().zip(&self.model_outputs.contact_forces).filter(|(c, _)| c.pad == pad) {
            out.normal_force += 0.5 * (f.top + f.bottom);
            out.friction_force += f.tangential;
            out.friction_torque += c.radius * f.tangential;
        }
        out
    }

    /// Forces at every pad contact point (order of `pads.ale_nodes`) at the current state.
    pub fn pad_contact_forces(&self) -> &[super::load_models::ContactForces] {
        &self.model_outputs.contact_forces
    }

    /// The lathe tool at the current state (`None` without a tool).
    pub fn tool_output(&self) -> Option<ToolOutput> {
        let t = self.state.load_models.tool.as_ref()?;
        Some(ToolOutput { tip: Tool::tip(t), chip: t.chip, feed_force: t.force, feed_rate: self.inputs.commands.feed_rate })
    }

    /// Axial force of pitch link `j` (0-based) at the current joint angle, N.
    pub fn link_force(&self, j: usize) -> f64 {
        self.scene.load_models.links.as_ref().map_or(0.0, |l| l.force(j, self.state.chi.angle))
    }

    /// The wrench the load models apply at ALE node `j` (0-based) at the current
    /// state, in its node frame (on top of the held user wrench).
    pub fn ale_model_wrench(&self, j: usize) -> Wrench {
        self.model_outputs.ale.get(j).copied().unwrap_or_default()
    }

    /// The wrench the load models apply at Lagrangian node `j` (0-based), in its node frame.
    pub fn lagrange_model_wrench(&self, j: usize) -> Wrench {
        self.model_outputs.lagrange.get(j).copied().unwrap_or_default()
    }

    pub fn joint(&self) -> JointOutput {
        JointOutput { position: self.state.chi.radians(), velocity: self.state.speed, effort: self.state.effort }
    }

    /// χ wrapped to (−π, π], for the plate_base → plate_rotor transform.
    pub fn rotor_angle(&self) -> f64 {
        self.state.chi.wrapped()
    }

    fn node_output(node: &NodeFrame, q: &[f64], q_dot: &[f64], speed: f64) -> NodeOutput {
        let d = node.deflection(q);
        let uz_dot: f64 = node.shapes.iter().zip(q_dot).map(|(s, v)| s.w * v).sum();
        let material_uz_dot = match node.kind {
            NodeKind::Lagrange => uz_dot,
            NodeKind::Ale => uz_dot + speed * node.w_phi.iter().zip(q).map(|(w, qi)| w * qi).sum::<f64>(),
        };
        let p = node.position();
        NodeOutput {
            pose: Pose { translation: [p[0], p[1], d.w], rotation: tilt_quaternion(d.tilt) },
            uz: d.w,
            uz_dot,
            tilt: d.tilt,
            material_uz_dot,
        }
    }

    /// ALE node `j` (0-based), in plate_base.
    pub fn ale_node(&self, j: usize) -> NodeOutput {
        Self::node_output(&self.scene.ale_nodes[j], &self.stepper.views().q_ale, &self.stepper.views().q_dot_ale, self.state.speed)
    }

    /// Lagrangian node `j` (0-based), in plate_rotor.
    pub fn lagrange_node(&self, j: usize) -> NodeOutput {
        Self::node_output(&self.scene.lagrange_nodes[j], &self.stepper.views().q_lagrange, &self.stepper.views().q_dot_lagrange, self.state.speed)
    }

    /// Pose of ALE node `j` (0-based) in the reference frame (plate_base).
    pub fn ale_node_pose(&self, j: usize) -> Pose {
        self.ale_node(j).pose
    }

    /// Pose of Lagrangian node `j` (0-based) in the plate frame (plate_rotor).
    pub fn lagrange_node_pose(&self, j: usize) -> Pose {
        self.lagrange_node(j).pose
    }

    /// Modal amplitudes (m) in `model().modes()` order, Lagrangian description.
    pub fn q_lagrange(&self) -> &[f64] {
        &self.stepper.views().q_lagrange
    }
    pub fn q_dot_lagrange(&self) -> &[f64] {
        &self.stepper.views().q_dot_lagrange
    }
    /// Modal amplitudes (m) in the ALE description (eq. 20).
    pub fn q_ale(&self) -> &[f64] {
        &self.stepper.views().q_ale
    }
    pub fn q_dot_ale(&self) -> &[f64] {
        &self.stepper.views().q_dot_ale
    }
    /// Elastic energy ½ Σ m_i (q̇_i² + ω_i² q_i²) (Lagrangian description), J.
    pub fn modal_energy(&self) -> f64 {
        let b = self.scene.model.body();
        (0..self.scene.n_modes())
            .map(|i| 0.5 * (b.modal_mass[i] * self.stepper.views().q_dot_lagrange[i].powi(2) + b.modal_stiffness[i] * self.stepper.views().q_lagrange[i].powi(2)))
            .sum()
    }
}

/// Unit quaternion (x, y, z, w) of the small-slope rotation vector (θ_x, θ_y, 0).
pub fn tilt_quaternion(tilt: [f64; 2]) -> [f64; 4] {
    let angle = (tilt[0] * tilt[0] + tilt[1] * tilt[1]).sqrt();
    if angle < 1e-300 {
        return [0.0, 0.0, 0.0, 1.0];
    }
    let (s, c) = (0.5 * angle).sin_cos();
    [tilt[0] / angle * s, tilt[1] / angle * s, 0.0, c]
}
