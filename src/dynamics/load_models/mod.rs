//! Load models: forces that act at the integration rate, inside the step —
//! which a ROS topic cannot — such as the paper's three applications (section
//! 5): brake pads ([`pad`], 5.3), the lathe tool ([`tool`], 5.1) and the swash
//! plate's pitch links ([`pitch_link`], 5.2), and a space-fixed point
//! spring-damper ([`point_spring`], the example of docs/architecture.md).
//!
//! A load model is a [`LoadModel`] implementation in its own file, registered
//! once in [`REGISTRY`]. The split follows the rest of `dynamics`: its
//! parameters live in the immutable [`Scene`](super::Scene) (the boxed model),
//! its internal state in a slot of the [`State`](super::State) (plain numbers,
//! so reset, checkpoint and replay stay copies), its commands in the
//! [`Inputs`](super::Inputs) ([`LoadCommands`], described by
//! [`CommandSpec`]s the node and the recorder discover), and its scratch (and
//! the quantities its outputs read) in [`ModelWrenches`].
//!
//! Every substep the stepper calls [`LoadModel::begin_substep`] (models with
//! memory: the tool's held cut), then evaluates every model from the node
//! kinematics ([`LoadContext`]) into node wrenches, which the node-load
//! computation adds on top of the user's held wrenches, each with its own
//! follower choice. Memoryless models ([`LoadModel::stage_dependent`]) are
//! re-evaluated by RK4 at every stage, by the other integrators at the substep
//! start. After the substep, [`LoadModel::commit_substep`] advances the state.

pub mod pad;
pub mod pitch_link;
pub mod point_spring;
pub mod tool;

pub use pad::{ContactForces, PadContactPoint, PadScratch, Pads, SurfaceKinematics};
pub use pitch_link::PitchLinks;
pub use point_spring::PointSprings;
pub use tool::{Tool, ToolStep};

use super::error::{InputError, SimulationError};
use super::joint::FrictionTorque;
use super::scene::NodeFrame;
use super::wrench::Wrench;
use crate::config::{Config, IntegratorKind, LimitsConfig};
use std::any::Any;
use std::fmt::Debug;
use std::ops::Range;

/// Builds a load model from a configuration, `None` when the scene does not use it.
pub type Builder = fn(&Config, &SceneNodes) -> Option<Box<dyn LoadModel>>;

/// Every load model, once, in evaluation order. A new model: its file and one line here.
pub const REGISTRY: &[Builder] = &[pad::build, tool::build, pitch_link::build, point_spring::build];

/// What a model's builder sees of the scene: the node frames and modal masses.
pub struct SceneNodes<'a> {
    pub ale: &'a [NodeFrame],
    pub lagrange: &'a [NodeFrame],
    pub modal_mass: &'a [f64],
}

/// The kinematics a model is evaluated at (substep start or an RK4 stage).
#[derive(Clone, Copy)]
pub struct LoadContext<'a> {
    pub ale_nodes: &'a [NodeFrame],
    pub lagrange_nodes: &'a [NodeFrame],
    /// Amplitudes and rates in the ALE description (eq. 20).
    pub q_ale: &'a [f64],
    pub q_dot_ale: &'a [f64],
    /// Joint angle χ (wrapped to [0, 2π), rad) and speed Ω (rad/s).
    pub chi: f64,
    pub speed: f64,
}

/// The rule a command value must meet.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum CommandRule {
    /// Finite, in [0, `limits.max_force`] (a clamp force).
    NonNegativeForce,
    /// Finite, |v| ≤ the limit.
    MagnitudeAtMost(f64),
}

/// One command of a load model, as the node and recorder discover it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CommandSpec {
    /// What one instance is called (`pad`, `tool`).
    pub instance: &'static str,
    /// The command in words (`clamp force`, `feed rate`).
    pub name: &'static str,
    /// The name token of its topic (`clamp_force`: `~/pad_<j>/clamp_force`; `feed`: `~/tool_feed`).
    pub token: &'static str,
    pub unit: &'static str,
    /// Instances are numbered (`pad_1`, `pad_2`, …) rather than one.
    pub indexed: bool,
    pub rule: CommandRule,
}

impl CommandSpec {
    /// The command of instance `instance` (0-based) in words: `pad_2 clamp force`, `tool feed rate`.
    pub fn what(&self, instance: usize) -> String {
        if self.indexed {
            format!("{}_{} {}", self.instance, instance + 1, self.name)
        } else {
            format!("{} {}", self.instance, self.name)
        }
    }

    /// Check `value` for instance `instance` (0-based) against the rule.
    pub fn check(&self, instance: usize, value: f64, limits: &LimitsConfig) -> Result<(), InputError> {
        if !value.is_finite() {
            return Err(InputError::NonFinite { what: self.what(instance), value });
        }
        match self.rule {
            CommandRule::NonNegativeForce if !(0.0..=limits.max_force).contains(&value) => Err(InputError::Absurd {
                what: format!("{} (must lie in [0, limits.max_force])", self.what(instance)),
                value,
                limit: limits.max_force,
            }),
            CommandRule::MagnitudeAtMost(limit) if value.abs() > limit => {
                Err(InputError::Absurd { what: self.what(instance), value, limit })
            }
            _ => Ok(()),
        }
    }
}

/// How strongly a memoryless model couples the modes, for the integrators'
/// step checks: the largest eigenvalues of M^(−½) K M^(−½) (1/s²) and
/// M^(−½) C M^(−½) (1/s) with every contact closed.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Coupling {
    pub stiffness_rate_sq: f64,
    pub damping_rate: f64,
}

/// Where a model writes its forces at one instant.
pub struct ModelOut<'a> {
    /// Wrenches per node frame, in the node frame's axes (summed over the models).
    pub ale: &'a mut [Wrench],
    pub lagrange: &'a mut [Wrench],
    /// Whether the node's model wrench follows the deformed surface.
    pub ale_follower: &'a mut [bool],
    pub lagrange_follower: &'a mut [bool],
    /// This model's friction terms of the joint torque ([`LoadModel::friction_terms`] of them).
    pub friction: &'a mut [FrictionTorque],
    /// This model's scratch ([`LoadModel::new_scratch`]).
    pub scratch: &'a mut dyn Any,
}

/// A load model (see the module docs). Only [`LoadModel::name`],
/// [`LoadModel::evaluate`] and [`LoadModel::as_any`] are required.
pub trait LoadModel: Debug + Send + Sync {
    /// The configuration section (`pads`, `tool`, `links`, `springs`).
    fn name(&self) -> &'static str;

    /// For downcasting to the concrete model (the outputs of pads and tool).
    fn as_any(&self) -> &dyn Any;

    /// Its commands (held in [`LoadCommands`], one value per instance and command).
    fn commands(&self) -> &[CommandSpec] {
        &[]
    }

    /// Instances of command `command` (pads: one clamp force per pad).
    fn instances(&self, _command: usize) -> usize {
        1
    }

    /// Initial values of its commands, in [`LoadModel::commands`] order × instances.
    fn initial_commands(&self) -> Vec<f64> {
        Vec::new()
    }

    /// Its slot in the [`State`](super::State) at t = 0.
    fn initial_state(&self) -> Vec<f64> {
        Vec::new()
    }

    /// Scratch for [`LoadModel::evaluate`], allocated once.
    fn new_scratch(&self) -> Box<dyn Any + Send + Sync> {
        Box::new(())
    }

    /// Friction terms it adds to the joint torque (solved at the step's end near standstill).
    fn friction_terms(&self) -> usize {
        0
    }

    /// Memoryless and dependent on the elastic state: RK4 re-evaluates it at every stage.
    fn stage_dependent(&self) -> bool {
        false
    }

    /// Its coupling rates (stiff contacts); zero for prescribed forces.
    fn coupling(&self) -> Coupling {
        Coupling::default()
    }

    /// Names of the parameters that set [`LoadModel::coupling`], for error messages.
    fn coupling_keys(&self) -> &'static str {
        ""
    }

    /// Before the substep of length `h` (models with memory hold a force over it).
    fn begin_substep(&self, _ctx: &LoadContext, _slot: &mut [f64], _h: f64) {}

    /// Its wrenches at one instant, added into `out`.
    fn evaluate(&self, ctx: &LoadContext, slot: &[f64], commands: &[f64], out: ModelOut);

    /// After the substep of length `h`: advance its state.
    fn commit_substep(&self, _slot: &mut [f64], _commands: &[f64], _h: f64) {}
}

/// The scene's load models (immutable) with the layout of their commands.
#[derive(Debug, Default)]
pub struct LoadModels {
    models: Vec<Box<dyn LoadModel>>,
    /// Per model, per command: the range of its instances in the model's command values.
    command_ranges: Vec<Vec<Range<usize>>>,
    friction_ranges: Vec<Range<usize>>,
    /// The sum of the models' couplings (a bound for any set of closed contacts).
    coupling: Coupling,
}

/// The load models' state (part of [`State`](super::State)): one slot per model.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct LoadModelState {
    pub slots: Vec<Vec<f64>>,
}

impl LoadModelState {
    /// Copy `other` into `self` reusing the buffers.
    pub fn copy_from(&mut self, other: &LoadModelState) {
        if self.slots.len() != other.slots.len() {
            self.slots.resize_with(other.slots.len(), Vec::new);
        }
        for (a, b) in self.slots.iter_mut().zip(&other.slots) {
            a.clear();
            a.extend_from_slice(b);
        }
    }

    pub fn is_finite(&self) -> bool {
        self.slots.iter().flatten().all(|v| v.is_finite())
    }
}

/// Commands of the load models (part of [`Inputs`](super::Inputs)): per model its values.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct LoadCommands {
    pub values: Vec<Vec<f64>>,
}

/// Wrenches the load models apply at one instant, per node, with the
/// follower choice per node, the joint friction terms, and each model's
/// scratch (scratch space allocated once).
#[derive(Debug)]
pub struct ModelWrenches {
    pub ale: Vec<Wrench>,
    pub lagrange: Vec<Wrench>,
    pub ale_follower: Vec<bool>,
    pub lagrange_follower: Vec<bool>,
    /// τ_f(Ω) = −Σ capacity · tanh(Ω · slope) of all models, so the joint can
    /// solve its step with the friction at the step's end.
    pub friction: Vec<FrictionTorque>,
    scratch: Vec<Box<dyn Any + Send + Sync>>,
}

impl ModelWrenches {
    /// Scratch for the nodes of `scene` and its models.
    pub fn new(scene: &super::Scene) -> ModelWrenches {
        let (n_ale, n_lagrange) = (scene.ale_nodes.len(), scene.lagrange_nodes.len());
        let lm = &scene.load_models;
        ModelWrenches {
            ale: vec![Wrench::default(); n_ale],
            lagrange: vec![Wrench::default(); n_lagrange],
            ale_follower: vec![false; n_ale],
            lagrange_follower: vec![false; n_lagrange],
            friction: vec![FrictionTorque::default(); lm.friction_ranges.last().map_or(0, |r| r.end)],
            scratch: lm.models.iter().map(|m| m.new_scratch()).collect(),
        }
    }

    /// The scratch of model `index` as its concrete type.
    pub fn scratch<T: 'static>(&self, index: usize) -> Option<&T> {
        self.scratch.get(index)?.downcast_ref::<T>()
    }

    fn clear(&mut self) {
        self.ale.iter_mut().for_each(|w| *w = Wrench::default());
        self.lagrange.iter_mut().for_each(|w| *w = Wrench::default());
        self.friction.iter_mut().for_each(|f| *f = FrictionTorque::default());
    }
}

/// Deflection and its rate at a fixed point for amplitudes in the node's own description.
#[inline]
pub fn surface_kinematics(node: &NodeFrame, q: &[f64], q_dot: &[f64]) -> SurfaceKinematics {
    let mut s = SurfaceKinematics::default();
    for ((shape, &qi), &vi) in node.shapes.iter().zip(q).zip(q_dot) {
        s.w += shape.w * qi;
        s.w_dot += shape.w * vi;
    }
    s
}

/// Largest eigenvalue of M^(−½) (Σ_c w_c w_cᵀ) M^(−½), w_c the mode shapes at contact c.
pub fn contact_rate(shapes: &[&[super::scene::NodeShape]], modal_mass: &[f64]) -> f64 {
    let n = modal_mass.len();
    let mut a = faer::Mat::<f64>::zeros(n, n);
    for s in shapes {
        for i in 0..n {
            for m in 0..n {
                a[(i, m)] += s[i].w * s[m].w / (modal_mass[i] * modal_mass[m]).sqrt();
            }
        }
    }
    a.self_adjoint_eigenvalues(faer::Side::Lower).ok().and_then(|ev| ev.last().copied()).unwrap_or(0.0).max(0.0)
}

/// Largest h × (coupling rate) the integrators that hold a model's forces over a substep accept.
pub const HELD_COUPLING_LIMIT: f64 = 0.5;

impl LoadModels {
    /// The registered models a configuration switches on.
    pub fn new(config: &Config, nodes: &SceneNodes) -> LoadModels {
        let models: Vec<Box<dyn LoadModel>> = REGISTRY.iter().filter_map(|build| build(config, nodes)).collect();
        let mut friction_ranges = Vec::with_capacity(models.len());
        let mut end = 0;
        for m in &models {
            friction_ranges.push(end..end + m.friction_terms());
            end += m.friction_terms();
        }
        let command_ranges = models
            .iter()
            .map(|m| {
                let mut start = 0;
                (0..m.commands().len())
                    .map(|c| {
                        let r = start..start + m.instances(c);
                        start = r.end;
                        r
                    })
                    .collect()
            })
            .collect();
        let coupling = models.iter().map(|m| m.coupling()).fold(Coupling::default(), |a, c| Coupling {
            stiffness_rate_sq: a.stiffness_rate_sq + c.stiffness_rate_sq,
            damping_rate: a.damping_rate + c.damping_rate,
        });
        LoadModels { models, command_ranges, friction_ranges, coupling }
    }

    pub fn is_empty(&self) -> bool {
        self.models.is_empty()
    }

    /// The models, in evaluation order.
    pub fn models(&self) -> &[Box<dyn LoadModel>] {
        &self.models
    }

    /// Index and concrete type of the model of type `T`, if the scene has one.
    pub fn find<T: 'static>(&self) -> Option<(usize, &T)> {
        self.models.iter().enumerate().find_map(|(i, m)| m.as_any().downcast_ref::<T>().map(|t| (i, t)))
    }

    /// Index of the model named `name` (`pads`, `tool`, …).
    pub fn position(&self, name: &str) -> Option<usize> {
        self.models.iter().position(|m| m.name() == name)
    }

    /// Instances of command `command` of model `model` (0 if either does not exist).
    pub fn instances(&self, model: usize, command: usize) -> usize {
        self.command_ranges.get(model).and_then(|c| c.get(command)).map_or(0, |r| r.len())
    }

    /// Index of command `command`, instance `instance` in the model's command values.
    pub fn command_index(&self, model: usize, command: usize, instance: usize) -> Option<usize> {
        let r = self.command_ranges.get(model)?.get(command)?;
        (instance < r.len()).then_some(r.start + instance)
    }

    /// Models RK4 evaluates at every stage.
    pub fn stage_dependent(&self) -> bool {
        self.models.iter().any(|m| m.stage_dependent())
    }

    /// The summed coupling rates of all models.
    pub fn coupling(&self) -> Coupling {
        self.coupling
    }

    /// Refuse integrators that hold a stiff model's forces over a substep of `h`.
    pub fn check_integrator(&self, integrator: IntegratorKind, h: f64) -> Result<(), SimulationError> {
        if integrator == IntegratorKind::Rk4 {
            return Ok(());
        }
        for m in &self.models {
            let c = m.coupling();
            let rate = c.stiffness_rate_sq.sqrt() + c.damping_rate;
            if h * rate > HELD_COUPLING_LIMIT {
                return Err(SimulationError::ModelTooStiffForIntegrator {
                    model: m.name(),
                    keys: m.coupling_keys(),
                    integrator: integrator.name(),
                    rate,
                    step: h,
                    limit: HELD_COUPLING_LIMIT,
                });
            }
        }
        Ok(())
    }

    /// The commands the scene starts with.
    pub fn initial_commands(&self) -> LoadCommands {
        LoadCommands { values: self.models.iter().map(|m| m.initial_commands()).collect() }
    }

    /// Put `commands` back to the initial ones, reusing the buffers.
    pub fn reset_commands(&self, commands: &mut LoadCommands) {
        commands.values.resize_with(self.models.len(), Vec::new);
        for (v, m) in commands.values.iter_mut().zip(&self.models) {
            v.clear();
            v.extend(m.initial_commands());
        }
    }

    /// The state the scene starts with.
    pub fn initial_state(&self) -> LoadModelState {
        LoadModelState { slots: self.models.iter().map(|m| m.initial_state()).collect() }
    }

    /// Before a substep of length `h`.
    pub fn begin_substep(&self, ctx: &LoadContext, state: &mut LoadModelState, h: f64) {
        for (m, slot) in self.models.iter().zip(state.slots.iter_mut()) {
            m.begin_substep(ctx, slot, h);
        }
    }

    /// After a substep of length `h`.
    pub fn commit_substep(&self, state: &mut LoadModelState, commands: &LoadCommands, h: f64) {
        for ((m, slot), c) in self.models.iter().zip(state.slots.iter_mut()).zip(&commands.values) {
            m.commit_substep(slot, c, h);
        }
    }

    /// Fill `out` with the wrenches of all models at one instant.
    pub fn evaluate(&self, ctx: &LoadContext, state: &LoadModelState, commands: &LoadCommands, out: &mut ModelWrenches) {
        out.clear();
        let ModelWrenches { ale, lagrange, ale_follower, lagrange_follower, friction, scratch } = out;
        for (i, m) in self.models.iter().enumerate() {
            let slot_out = ModelOut {
                ale: ale.as_mut_slice(),
                lagrange: lagrange.as_mut_slice(),
                ale_follower: ale_follower.as_mut_slice(),
                lagrange_follower: lagrange_follower.as_mut_slice(),
                friction: &mut friction[self.friction_ranges[i].clone()],
                scratch: scratch[i].as_mut(),
            };
            m.evaluate(ctx, &state.slots[i], &commands.values[i], slot_out);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::dynamics::scene::NodeShape;

    #[test]
    fn command_rules_name_the_instance_and_keep_the_limits() {
        let clamp = CommandSpec { instance: "pad", name: "clamp force", token: "clamp_force", unit: "N", indexed: true, rule: CommandRule::NonNegativeForce };
        let limits = LimitsConfig::default();
        assert_eq!(clamp.check(0, 250.0, &limits), Ok(()));
        assert_eq!(clamp.check(0, limits.max_force, &limits), Ok(()));
        for bad in [f64::NAN, f64::INFINITY, -1.0, 2.0 * limits.max_force] {
            let e = clamp.check(0, bad, &limits).unwrap_err();
            assert!(e.to_string().contains("pad_1 clamp force"), "{e}");
        }
        let feed = CommandSpec { instance: "tool", name: "feed rate", token: "feed", unit: "m/s", indexed: false, rule: CommandRule::MagnitudeAtMost(1.0) };
        assert!(feed.check(0, -0.5, &limits).is_ok());
        assert!(feed.check(0, 1.5, &limits).unwrap_err().to_string().starts_with("tool feed rate"));
    }

    #[test]
    fn the_contact_rate_is_the_largest_eigenvalue_of_the_mass_scaled_contact_stiffness() {
        // Two modes, two contacts: Σ w wᵀ = [[1, 0], [0, 4]] + [[1, 1], [1, 1]] over masses (2, 1).
        let shapes = [
            vec![NodeShape { w: 1.0, tilt: [0.0; 2] }, NodeShape { w: 2.0, tilt: [0.0; 2] }],
            vec![NodeShape { w: 1.0, tilt: [0.0; 2] }, NodeShape { w: -1.0, tilt: [0.0; 2] }],
        ];
        let refs: Vec<&[NodeShape]> = shapes.iter().map(|s| s.as_slice()).collect();
        let lam = contact_rate(&refs, &[2.0, 1.0]);
        // M^(−½) A M^(−½) = [[1, 1/√2], [1/√2, 5]]: eigenvalues 3 ± √(4 + 1/2).
        let expected = 3.0 + 4.5f64.sqrt();
        assert!((lam - expected).abs() < 1e-12, "{lam} vs {expected}");
    }
}
