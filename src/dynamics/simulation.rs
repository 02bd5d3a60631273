//! The facade the CLI and the ROS node drive: scene + state + stepper +
//! settings + held inputs, with the outputs derived from the state.

use crate::config::{Config, Coordinates, IntegratorKind, PlateTheory};
use crate::model::{ModelError, PlateModel};

use super::ale::{harmonics, lagrange_to_ale};
use super::commands::Inputs;
use super::commands::{check, check_batch, Checked, CheckedBatch, Command};
use super::error::{BatchError, InputError, SimulationError, StepError};
use super::in_plane::InPlaneNodeMotion;
use super::integrators::contact_exponential::MAX_UNKNOWNS;
use super::integrators::MAX_INNER_SUBSTEPS;
use super::load_models::ModelWrenches;
pub use super::node_output::{NodeOutput, Pose};
use super::scene::Scene;
use super::state::State;
use super::stepper::{Stepper, StepperSettings};
use super::wrench::{NodeKind, Wrench};

/// The rotational joint at the axis: angle χ (unwrapped), speed Ω, drive torque.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct JointOutput {
    /// Joint angle χ (unwrapped), rad.
    pub position: f64,
    /// Joint speed Ω, rad/s.
    pub velocity: f64,
    /// Drive torque, N m.
    pub effort: f64,
}

/// A running simulation: the configuration, the immutable scene, the state,
/// the stepper and the held inputs (what the CLI and the node drive).
pub struct Simulation {
    /// The configuration it was built from.
    config: Config,
    /// The immutable scene: model, nodes, joint, effects and load models.
    scene: Scene,
    /// The stepper's settings (step, substeps, integrator).
    settings: StepperSettings,
    /// The current state.
    state: State,
    initial: State,
    stepper: Stepper,
    /// The held inputs.
    inputs: Inputs,
    /// Each load model's declared output channels at the current state (derived).
    output_values: Vec<Vec<f64>>,
}

impl Simulation {
    /// Build the model, the scene and the stepper of a validated configuration, at its initial state.
    pub fn new(config: Config) -> Result<Simulation, SimulationError> {
        let model = PlateModel::bending(&config.plate)?;
        let mut scene = Scene::new(&config, model);
        scene.add_in_plane(&config)?;
        check_mindlin_scene(&config, &scene)?;
        let settings = StepperSettings::from_config(&config);
        let stepper = Stepper::new(&scene);
        check_inner_substeps(&config, &scene, &settings, &stepper)?;
        check_contact_unknowns(&scene, &settings)?;
        scene
            .load_models
            .check_integrator(settings.integrator, settings.h())?;
        let initial = initial_state(&config, &scene);
        let mut inputs = Inputs::default();
        reset_inputs(&config, &scene, &mut inputs);
        let mut sim = Simulation {
            state: initial.clone(),
            initial,
            stepper,
            inputs,
            output_values: scene.load_models.new_output_values(),
            scene,
            settings,
            config,
        };
        sim.refresh_model_outputs();
        Ok(sim)
    }

    /// The configuration it was built from.
    pub fn config(&self) -> &Config {
        &self.config
    }
    /// The plate model (modes, frequencies, modal matrices).
    pub fn model(&self) -> &PlateModel {
        &self.scene.model
    }
    /// The immutable scene: model, nodes, joint, effects and load models.
    pub fn scene(&self) -> &Scene {
        &self.scene
    }
    /// The stepper's settings (step, substeps, integrator).
    pub fn settings(&self) -> &StepperSettings {
        &self.settings
    }
    /// The current state.
    pub fn state(&self) -> &State {
        &self.state
    }
    /// Inner substeps per substep in the last step (1 for the exponential integrator).
    pub fn inner_substeps(&self) -> usize {
        self.stepper.last_inner_substeps()
    }
    /// What the last `contact_exponential` substep did: switching instants
    /// located and piece tables built.
    pub fn contact_report(&self) -> super::stepper::ContactReport {
        self.stepper.last_contact()
    }
    /// `contact_exponential` substeps finished without locating their
    /// switches (Zeno-like chatter, more than 4096 in one substep) since the
    /// simulation was made: `simulate` and the node warn of them.
    pub fn unlocated_substeps(&self) -> u64 {
        self.stepper.unlocated_substeps()
    }
    /// The warning of [`Simulation::unlocated_substeps`], for `simulate` and the node.
    pub fn unlocated_warning(&self) -> String {
        format!(
            "{} contact_exponential substeps met more than {} switches of the contacts (Zeno-like chatter: a contact closing and opening ever faster, as at a clamp force near zero) and were finished span by span without locating them, each ending within h/2^L (at most 2.5e-7 s) of its end; raise simulation.rate_hz or use simulation.integrator: rk4 for an exact account",
            self.unlocated_substeps(),
            super::integrators::contact_exponential::MAX_EVENTS
        )
    }
    /// The held inputs.
    pub fn inputs(&self) -> &Inputs {
        &self.inputs
    }
    /// Simulated time since the start (or the last reset), s.
    pub fn time(&self) -> f64 {
        self.state.time
    }
    /// Output steps since start or the last reset.
    pub fn step_count(&self) -> u64 {
        self.state.steps
    }
    /// The output step 1/rate_hz, s.
    pub fn dt(&self) -> f64 {
        self.settings.dt
    }
    /// ALE nodes of the scene.
    pub fn n_ale_nodes(&self) -> usize {
        self.scene.ale_nodes.len()
    }
    /// Lagrangian nodes of the scene.
    pub fn n_lagrange_nodes(&self) -> usize {
        self.scene.lagrange_nodes.len()
    }

    /// Back to t = 0 with the parameter file's speed and loads.
    pub fn reset(&mut self) {
        self.state.copy_from(&self.initial);
        reset_inputs(&self.config, &self.scene, &mut self.inputs);
        self.refresh_model_outputs();
    }

    /// Evaluate the load models at the current state for the outputs (a
    /// model with memory reports the force it held over the last substep);
    /// the stepper's wrenches then are of the current state.
    fn refresh_model_outputs(&mut self) {
        let lm = &self.scene.load_models;
        if lm.is_empty() {
            return;
        }
        let wrenches = self
            .stepper
            .model_wrenches_at(&self.scene, &self.state, &self.inputs);
        lm.write_outputs(
            &self.state.load_models,
            &self.inputs.commands,
            wrenches,
            self.state.chi.angle,
            &mut self.output_values,
        );
    }

    /// Replace the state (a checkpoint taken with `state().clone()`, stepped
    /// on from exactly where it was). After editing its amplitudes by hand,
    /// call [`State::rederive`] first.
    pub fn restore(&mut self, state: State) {
        assert_eq!(state.q.len(), self.scene.n_modes());
        self.state = state;
        self.refresh_model_outputs();
    }

    /// Advance one output step (1/rate_hz). On error the state is unchanged.
    pub fn step(&mut self) -> Result<(), StepError> {
        let stepped = self
            .stepper
            .step(&self.scene, &self.settings, &mut self.state, &self.inputs);
        // Also after a refused step: the stepper's wrenches are of its trials.
        self.refresh_model_outputs();
        stepped
    }

    // ---- inputs: one contract (dynamics::commands) ---------------------------

    /// Check a command against the scene's rules (nothing is held yet).
    pub fn check(&self, command: Command) -> Result<Checked, InputError> {
        check(&self.scene.rules, command)
    }

    /// Check a batch whole (nothing is held yet).
    pub fn check_batch(
        &self,
        commands: impl IntoIterator<Item = Command>,
    ) -> Result<CheckedBatch, BatchError> {
        check_batch(&self.scene.rules, commands)
    }

    /// Hold a checked command until replaced.
    pub fn apply(&mut self, checked: Checked) {
        let load = matches!(checked.command(), Command::Load { .. });
        self.inputs.apply(checked);
        if load {
            self.refresh_model_outputs();
        }
    }

    /// Hold every command of a checked batch.
    pub fn apply_batch(&mut self, batch: &CheckedBatch) {
        self.inputs.apply_batch(batch);
        if batch
            .iter()
            .any(|c| matches!(c.command(), Command::Load { .. }))
        {
            self.refresh_model_outputs();
        }
    }

    /// Check and hold one command.
    pub fn command(&mut self, command: Command) -> Result<(), InputError> {
        let checked = self.check(command)?;
        self.apply(checked);
        Ok(())
    }

    /// Command the joint speed Ω (rad/s), held until replaced.
    pub fn set_speed_command(&mut self, omega: f64) -> Result<(), InputError> {
        self.command(Command::Speed(omega))
    }

    /// Hold a wrench on ALE node `node` (0-based) until replaced.
    pub fn set_ale_wrench(&mut self, node: usize, wrench: Wrench) -> Result<(), InputError> {
        self.command(Command::Wrench {
            kind: NodeKind::Ale,
            node,
            wrench,
        })
    }

    /// Hold a wrench on Lagrangian node `node` (0-based) until replaced.
    pub fn set_lagrange_wrench(&mut self, node: usize, wrench: Wrench) -> Result<(), InputError> {
        self.command(Command::Wrench {
            kind: NodeKind::Lagrange,
            node,
            wrench,
        })
    }

    // ---- load models (paper section 5; docs/scenes.md) ----------------------

    /// The values of model `model`'s output channels at the current state,
    /// laid out as `scene().load_models.outputs(model)` declares.
    pub fn output_values(&self, model: usize) -> &[f64] {
        &self.output_values[model]
    }

    /// Channel `channel` of model `model` at the current state.
    pub fn channel(&self, model: usize, channel: usize) -> &[f64] {
        let (_, layout) = self.scene.load_models.outputs(model);
        &self.output_values[model][layout.ranges[channel].clone()]
    }

    /// The channel named `channel` of the model of section `model` (`pads`,
    /// `clamp_force`), if the scene has both.
    pub fn find_channel(&self, model: &str, channel: &str) -> Option<&[f64]> {
        let lm = &self.scene.load_models;
        let i = lm.names().position(|n| n == model)?;
        Some(self.channel(i, lm.outputs(i).0.channel(channel)?))
    }

    /// The load models' wrenches and scratch at the current state.
    pub fn model_wrenches(&self) -> &ModelWrenches {
        self.stepper.model_wrenches()
    }

    /// The wrench the load models apply at ALE node `j` (0-based) at the current
    /// state, in its node frame (on top of the held user wrench).
    pub fn ale_model_wrench(&self, j: usize) -> Wrench {
        self.model_wrenches()
            .ale
            .get(j)
            .copied()
            .unwrap_or_default()
    }

    /// The wrench the load models apply at Lagrangian node `j` (0-based), in its node frame.
    pub fn lagrange_model_wrench(&self, j: usize) -> Wrench {
        self.model_wrenches()
            .lagrange
            .get(j)
            .copied()
            .unwrap_or_default()
    }

    // ---- outputs ------------------------------------------------------------

    /// The joint's angle, speed and drive torque.
    pub fn joint(&self) -> JointOutput {
        JointOutput {
            position: self.state.chi.radians(),
            velocity: self.state.speed,
            effort: self.state.effort,
        }
    }

    /// χ wrapped to (−π, π], for the plate_base → plate_rotor transform.
    pub fn rotor_angle(&self) -> f64 {
        self.state.chi.wrapped()
    }

    /// ALE node `j` (0-based), in plate_base.
    pub fn ale_node(&self, j: usize) -> NodeOutput {
        let (q, q_dot) = self.state.ale();
        NodeOutput::of(
            &self.scene.ale_nodes[j],
            q,
            q_dot,
            self.state.speed,
            self.residual_deflection(j),
            self.in_plane_motion(j),
        )
    }

    /// Lagrangian node `j` (0-based), in plate_rotor.
    pub fn lagrange_node(&self, j: usize) -> NodeOutput {
        let (q, q_dot) = self.state.lagrange();
        let a = self.scene.ale_nodes.len() + j;
        NodeOutput::of(
            &self.scene.lagrange_nodes[j],
            q,
            q_dot,
            self.state.speed,
            self.residual_deflection(a),
            self.in_plane_motion(a),
        )
    }

    /// The in-plane motion of node `a` (ALE first, then Lagrangian), with
    /// the in-plane residual under the held in-plane forces and its rates
    /// (None without in-plane modes; docs/in_plane.md, "Node frames").
    fn in_plane_motion(&self, a: usize) -> Option<InPlaneNodeMotion> {
        let ip = self.scene.in_plane.as_ref()?;
        let n_ale = self.scene.ale_nodes.len();
        let speed = self.state.speed;
        let mut motion = if a < n_ale {
            let (q, q_dot) = self.state.ale();
            ip.node_motion(&ip.ale_nodes[a], Some(&ip.ale_turn[a]), q, q_dot, speed)
        } else {
            let (q, q_dot) = self.state.lagrange();
            ip.node_motion(&ip.lagrange_nodes[a - n_ale], None, q, q_dot, speed)
        };
        if let Some(r) = &ip.residual {
            let chi = self.state.chi.wrapped();
            let force = |b| self.in_plane_node_force(b);
            let u = r.displacement(a, chi, force);
            let (frame, material) = r.rates(a, chi, speed, a < n_ale, force);
            motion.u = [motion.u[0] + u[0], motion.u[1] + u[1]];
            motion.u_dot = [motion.u_dot[0] + frame[0], motion.u_dot[1] + frame[1]];
            motion.material_u_dot = [
                motion.material_u_dot[0] + material[0],
                motion.material_u_dot[1] + material[1],
            ];
        }
        Some(motion)
    }

    /// In-plane force (F_x, F_y) (N) at node `b` (ALE first, then
    /// Lagrangian), in its parent frame's axes: the held wrench plus the load
    /// models'.
    fn in_plane_node_force(&self, b: usize) -> [f64; 2] {
        let n_ale = self.scene.ale_nodes.len();
        let (held, model) = if b < n_ale {
            (self.inputs.ale.get(b), self.ale_model_wrench(b))
        } else {
            (
                self.inputs.lagrange.get(b - n_ale),
                self.lagrange_model_wrench(b - n_ale),
            )
        };
        let f = held.map_or([0.0; 3], |w| w.force);
        [f[0] + model.force[0], f[1] + model.force[1]]
    }

    /// The `uz` of [`Simulation::ale_node`] alone (m; the same sums, bit for
    /// bit, without the rest of the node's kinematics: the CSV's column).
    pub fn ale_node_uz(&self, j: usize) -> f64 {
        self.scene.ale_nodes[j].deflection_w(self.state.ale().0) + self.residual_deflection(j)
    }

    /// The `uz` of [`Simulation::lagrange_node`] alone (m).
    pub fn lagrange_node_uz(&self, j: usize) -> f64 {
        self.scene.lagrange_nodes[j].deflection_w(self.state.lagrange().0)
            + self.residual_deflection(self.scene.ale_nodes.len() + j)
    }

    /// The in-plane displacement (u_x, u_y) of [`Simulation::ale_node`] alone
    /// (m, in plate_base axes; None without in-plane modes: the CSV's columns).
    pub fn ale_node_in_plane_u(&self, j: usize) -> Option<[f64; 2]> {
        self.in_plane_motion(j).map(|m| m.u)
    }

    /// The in-plane displacement of [`Simulation::lagrange_node`] alone (m,
    /// in plate_rotor axes).
    pub fn lagrange_node_in_plane_u(&self, j: usize) -> Option<[f64; 2]> {
        self.in_plane_motion(self.scene.ale_nodes.len() + j)
            .map(|m| m.u)
    }

    /// Transverse force (N) at node `b` (ALE first, then Lagrangian): the held
    /// wrench plus the load models', z in the node frame.
    pub fn transverse_node_force(&self, b: usize) -> f64 {
        let n_ale = self.scene.ale_nodes.len();
        if b < n_ale {
            self.inputs.ale.get(b).map_or(0.0, |w| w.force[2]) + self.ale_model_wrench(b).force[2]
        } else {
            self.inputs
                .lagrange
                .get(b - n_ale)
                .map_or(0.0, |w| w.force[2])
                + self.lagrange_model_wrench(b - n_ale).force[2]
        }
    }

    /// The truncated modes' static deflection at node `a` (ALE first, then
    /// Lagrangian) under the current transverse node forces, m (0 with
    /// `plate.residual_flexibility: false`).
    pub fn residual_deflection(&self, a: usize) -> f64 {
        match &self.scene.residual {
            Some(r) => r.deflection(a, self.state.chi.wrapped(), |b| {
                self.transverse_node_force(b)
            }),
            None => 0.0,
        }
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
        self.state.lagrange().0
    }
    /// Modal rates (m/s), Lagrangian description.
    pub fn q_dot_lagrange(&self) -> &[f64] {
        self.state.lagrange().1
    }
    /// Modal amplitudes (m) in the ALE description (eq. 20).
    pub fn q_ale(&self) -> &[f64] {
        self.state.ale().0
    }
    /// Modal rates (m/s), ALE description.
    pub fn q_dot_ale(&self) -> &[f64] {
        self.state.ale().1
    }
    /// Elastic energy ½ Σ m_i (q̇_i² + ω_i² q_i²) (Lagrangian description, bending and in-plane modes), J.
    pub fn modal_energy(&self) -> f64 {
        let b = self.scene.model.body();
        let (q, q_dot) = self.state.lagrange();
        let bending: f64 = (0..self.scene.model.n_modes())
            .map(|i| {
                0.5 * (b.modal_mass[i] * q_dot[i].powi(2) + b.modal_stiffness[i] * q[i].powi(2))
            })
            .sum();
        let in_plane: f64 = self
            .scene
            .in_plane
            .iter()
            .map(|ip| {
                ip.modes
                    .iter()
                    .enumerate()
                    .map(|(j, m)| {
                        let i = ip.offset + j;
                        0.5 * m.modal_mass * (q_dot[i].powi(2) + m.omega.powi(2) * q[i].powi(2))
                    })
                    .sum::<f64>()
            })
            .sum();
        bending + in_plane
    }
}

/// The state a configuration starts from: at rest elastically (or at
/// `initial.*`, given Lagrangian), both descriptions consistent.
fn initial_state(config: &Config, scene: &Scene) -> State {
    let n = scene.n_modes();
    let mut initial = State::new(
        n,
        config.simulation.coordinates,
        config.joint.initial_position,
        config.joint.speed,
    );
    initial.load_models = scene.load_models.initial_state();
    if !config.initial.q.is_empty() || !config.initial.q_dot.is_empty() {
        // initial.* are Lagrangian; the state may be kept in ALE coordinates.
        let mut q = config.initial.q.clone();
        let mut q_dot = config.initial.q_dot.clone();
        q.resize(n, 0.0);
        q_dot.resize(n, 0.0);
        if initial.coordinates == Coordinates::Ale {
            let mut harm = Vec::new();
            harmonics(&initial.chi, scene.layout.k_max, &mut harm);
            lagrange_to_ale(&scene.layout, &harm, initial.speed, &mut q, &mut q_dot);
        }
        initial.q = q;
        initial.q_dot = q_dot;
    }
    initial.rederive(scene);
    initial
}

/// The inputs a configuration starts with: its speed, held loads and the load models' commands.
fn reset_inputs(config: &Config, scene: &Scene, inputs: &mut Inputs) {
    inputs.speed_command = config.joint.speed;
    let to_wrench = |w: &crate::config::WrenchConfig| Wrench {
        force: w.force,
        moment: w.moment,
    };
    inputs.ale = (0..scene.ale_nodes.len())
        .map(|j| config.loads.ale.get(j).map(to_wrench).unwrap_or_default())
        .collect();
    inputs.lagrange = (0..scene.lagrange_nodes.len())
        .map(|j| {
            config
                .loads
                .lagrange
                .get(j)
                .map(to_wrench)
                .unwrap_or_default()
        })
        .collect();
    scene.load_models.reset_commands(&mut inputs.commands);
}

/// Under Mindlin theory, refuse the keys whose terms are Kirchhoff's:
/// follower loads and the load models
/// that do not take Mindlin modes ([`LoadModel::takes_mindlin_modes`],
/// named by their section).
///
/// [`LoadModel::takes_mindlin_modes`]: super::load_models::LoadModel::takes_mindlin_modes
fn check_mindlin_scene(config: &Config, scene: &Scene) -> Result<(), ModelError> {
    if scene.model.theory() != PlateTheory::Mindlin {
        return Ok(());
    }
    let refuse = |key, why| Err(ModelError::MindlinKeyNotWired { key, why });
    if config.loads.follower {
        return refuse(
            "loads.follower",
            "a follower force turns with the surface normal (the slope ∇w), and Mindlin node frames turn with the rotation ψ",
        );
    }
    let lm = &scene.load_models;
    for (model, name) in lm.models().iter().zip(lm.names()) {
        if !model.takes_mindlin_modes() {
            return refuse(
                name,
                "the load model uses the slope or the face kinematics of Kirchhoff modes",
            );
        }
    }
    Ok(())
}

/// Refuse `contact_exponential` on a scene with stiff contacts and more
/// unknowns than it tabulates ([`MAX_UNKNOWNS`]).
fn check_contact_unknowns(
    scene: &Scene,
    settings: &StepperSettings,
) -> Result<(), SimulationError> {
    let models = &scene.load_models;
    if settings.integrator != IntegratorKind::ContactExponential || !models.stage_dependent() {
        return Ok(());
    }
    let unknowns = scene.first_order_unknowns();
    if unknowns <= MAX_UNKNOWNS {
        return Ok(());
    }
    Err(SimulationError::TooManyContactUnknowns {
        modes: scene.n_modes(),
        unknowns,
        limit: MAX_UNKNOWNS,
    })
}

/// Refuse a scene whose integrator would need more than
/// [`MAX_INNER_SUBSTEPS`] inner substeps at the configured speed to resolve the
/// fastest mode (the same criterion the stepper applies per step).
fn check_inner_substeps(
    config: &Config,
    scene: &Scene,
    settings: &StepperSettings,
    stepper: &Stepper,
) -> Result<(), SimulationError> {
    let Some((step_limit, limit_key)) = settings.step_limit() else {
        return Ok(());
    };
    let speed = config.joint.speed.abs();
    let needed = stepper.inner_substeps(scene, settings, settings.h(), speed);
    if needed <= MAX_INNER_SUBSTEPS {
        return Ok(());
    }
    Err(SimulationError::TooManySubsteps {
        integrator: settings.integrator.name(),
        limit_key,
        step_limit,
        needed,
        limit: MAX_INNER_SUBSTEPS,
        step: settings.h(),
        frequency_hz: scene
            .model
            .modes()
            .iter()
            .map(|m| m.frequency_hz)
            .fold(0.0, f64::max),
        speed,
    })
}
