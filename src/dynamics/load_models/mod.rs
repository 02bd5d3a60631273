//! Load models: forces that act at the integration rate, inside the step —
//! which a ROS topic cannot — such as the paper's three applications (section
//! 5): brake pads ([`pad`], 5.3), the lathe tool ([`tool`], 5.1) and the swash
//! plate's pitch links ([`pitch_link`], 5.2), and a space-fixed point
//! spring-damper ([`point_spring`], the example of docs/architecture.md).
//!
//! A load model is a [`LoadModel`] implementation in its own file, registered
//! once in [`REGISTRY`] with its declared outputs ([`outputs`]: named, typed
//! channels, CSV columns, a topic), which the node, the CSV writer, the
//! recorder and the messages read without knowing the model, and with its
//! declared parameters (sections of keys and their reader, joined with the
//! configuration's in [`PARAMETERS`]: [`parameters`]), which the validation,
//! the parameter services and docs/parameters.md read the same way. The split follows the rest of `dynamics`: its
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
//! start. After the substep, [`LoadModel::commit_substep`] advances the state
//! (what it changes beyond a model's [`LoadModel::undo_head`] logged first, so
//! that a diverged step is undone without copying the slots: [`undo`]).

pub mod face_friction;
pub mod linear;
pub mod model;
pub mod outputs;
pub mod pad_calipers;
pub mod pad_config;
pub mod pad_contact_law;
mod pad_friction_damping;
pub mod pad_in_plane;
mod pad_linear;
mod pad_linear_in_plane;
mod pad_linear_mass;
mod pad_linear_shear;
pub mod pad_mass;
pub mod pad_outputs;
pub mod pad_patch;
pub mod pad_series;
pub mod pad_shear;
pub mod parameters;
pub mod tool_config;
mod tool_cutting;
mod tool_in_step;
mod tool_step;
pub mod undo;

pub use linear::{
    LinearContext, LinearLayout, LinearOut, LinearStates, OperatingPoint, StateLayout,
};
pub use model::{
    contact_rate, surface_kinematics, Builder, CommandRule, CommandSpec, Coupling, LoadContext,
    LoadModel, ModelOut, Registration, SceneNodes, SurfaceKinematics,
};
pub use outputs::{
    ChannelKind, ChannelLayout, ChannelShape, CsvColumn, OutputChannel, OutputContext, Outputs,
    StateTopic,
};

pub use parameters::PARAMETERS;
pub use undo::{LoadModelUndo, SlotUndo};

use crate::config::{Config, IntegratorKind};
use crate::dynamics::error::SimulationError;
use crate::dynamics::joint::FrictionTorque;
use crate::dynamics::wrench::Wrench;
use std::any::Any;
use std::ops::Range;

/// The registered models: each model's module and its line in [`REGISTRY`]
/// from one name, so a new model is its file and one line here.
macro_rules! registry {
    ($($model:ident),* $(,)?) => {
        $(pub mod $model;)*

        /// Every load model, once, in evaluation order (also the order of
        /// their CSV columns, topics and parameter sections). A new model:
        /// its file and one line in the list below.
        pub const REGISTRY: &[Registration] = &[$($model::REGISTRATION),*];
    };
}

registry! {
    pad,
    tool,
    pitch_link,
    point_spring,
    point_damper,
}

/// The scene's load models (immutable) with the layout of their commands.
#[derive(Debug, Default)]
pub struct LoadModels {
    models: Vec<Box<dyn LoadModel>>,
    /// Per model, its declared outputs and where its channels lie in its values.
    outputs: Vec<(&'static Outputs, ChannelLayout)>,
    /// Per model, per command: the range of its instances in the model's command values.
    command_ranges: Vec<Vec<Range<usize>>>,
    friction_ranges: Vec<Range<usize>>,
    /// Per model, the range of its continuous states among all models'.
    state_ranges: Vec<Range<usize>>,
    /// Per model, the range of its switching functions among all models'.
    switching_ranges: Vec<Range<usize>>,
    /// The sum of the models' couplings (a bound for any set of closed contacts).
    coupling: Coupling,
}

/// The load models' state (part of [`State`](super::State)): one slot per model.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct LoadModelState {
    /// Per model, its state values (empty for a model without state).
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

    /// Whether every value is finite.
    pub fn is_finite(&self) -> bool {
        self.slots.iter().flatten().all(|v| v.is_finite())
    }
}

/// Commands of the load models (part of [`Inputs`](super::Inputs)): per model its values.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct LoadCommands {
    /// Per model, its command values.
    pub values: Vec<Vec<f64>>,
}

/// Wrenches the load models apply at one instant, per node, with the
/// follower choice per node, the joint friction terms, and each model's
/// scratch (scratch space allocated once).
#[derive(Debug)]
pub struct ModelWrenches {
    /// Per ALE node, the models' wrench in its axes.
    pub ale: Vec<Wrench>,
    /// Per Lagrangian node, the models' wrench in its axes.
    pub lagrange: Vec<Wrench>,
    /// Per ALE node, whether that wrench follows the deformed surface.
    pub ale_follower: Vec<bool>,
    /// Per Lagrangian node, whether that wrench follows the deformed surface.
    pub lagrange_follower: Vec<bool>,
    /// τ_f(Ω) = −Σ capacity · tanh(Ω · slope) of all models, so the joint can
    /// solve its step with the friction at the step's end.
    pub friction: Vec<FrictionTorque>,
    /// The rates of the models' continuous states ([`LoadModels::continuous_states`]).
    pub rates: Vec<f64>,
    /// The models' switching functions ([`LoadModels::switching_functions`]).
    pub switching: Vec<f64>,
    scratch: Vec<Box<dyn Any + Send + Sync>>,
}

impl ModelWrenches {
    /// Scratch for `n_ale` and `n_lagrange` node frames and the models `lm`.
    pub fn new(n_ale: usize, n_lagrange: usize, lm: &LoadModels) -> ModelWrenches {
        ModelWrenches {
            ale: vec![Wrench::default(); n_ale],
            lagrange: vec![Wrench::default(); n_lagrange],
            ale_follower: vec![false; n_ale],
            lagrange_follower: vec![false; n_lagrange],
            friction: vec![
                FrictionTorque::default();
                lm.friction_ranges.last().map_or(0, |r| r.end)
            ],
            rates: vec![0.0; lm.continuous_states()],
            switching: vec![0.0; lm.switching_functions()],
            scratch: lm.models.iter().map(|m| m.new_scratch()).collect(),
        }
    }

    /// The scratch of model `index` as its concrete type.
    pub fn scratch<T: 'static>(&self, index: usize) -> Option<&T> {
        self.scratch.get(index)?.downcast_ref::<T>()
    }

    fn clear(&mut self) {
        self.ale.iter_mut().for_each(|w| *w = Wrench::default());
        self.lagrange
            .iter_mut()
            .for_each(|w| *w = Wrench::default());
        self.friction
            .iter_mut()
            .for_each(|f| *f = FrictionTorque::default());
    }
}

/// Largest h × (coupling rate) the integrators that hold a model's forces over a substep accept.
pub const HELD_COUPLING_LIMIT: f64 = 0.5;

/// Largest h × [`LoadModels::held_damping_rate`] the integrators that hold
/// a model's forces over a substep accept: a damper σ held over h decays
/// the motion it damps by 1 − hσ per substep, which stays in [0, 1) (no
/// overshoot) for hσ ≤ 1. The rate is a Gershgorin bound, above the
/// largest true one.
pub const HELD_DAMPING_LIMIT: f64 = 1.0;

impl LoadModels {
    /// The registered models a configuration switches on.
    pub fn new(config: &Config, nodes: &SceneNodes) -> LoadModels {
        let (models, outputs): (Vec<Box<dyn LoadModel>>, Vec<_>) = REGISTRY
            .iter()
            .filter_map(|r| (r.build)(config, nodes).map(|m| (m, r.outputs)))
            .map(|(m, o)| {
                let layout = ChannelLayout::new((0..o.channels.len()).map(|c| m.channel_len(c)));
                (m, (o, layout))
            })
            .unzip();
        let friction_ranges = consecutive_ranges(&models, |m| m.friction_terms());
        let state_ranges = consecutive_ranges(&models, |m| m.continuous_states());
        let switching_ranges = consecutive_ranges(&models, |m| m.switching_functions());
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
        let coupling = models
            .iter()
            .map(|m| m.coupling())
            .fold(Coupling::default(), |a, c| Coupling {
                stiffness_rate_sq: a.stiffness_rate_sq + c.stiffness_rate_sq,
                damping_rate: a.damping_rate + c.damping_rate,
                relaxation_rate: a.relaxation_rate.max(c.relaxation_rate),
            });
        LoadModels {
            models,
            outputs,
            command_ranges,
            friction_ranges,
            state_ranges,
            switching_ranges,
            coupling,
        }
    }

    /// Whether the scene has no load model.
    pub fn is_empty(&self) -> bool {
        self.models.is_empty()
    }

    /// The models, in evaluation order.
    pub fn models(&self) -> &[Box<dyn LoadModel>] {
        &self.models
    }

    /// Give every model the scene's in-plane modes; the first that refuses
    /// them names its key ([`LoadModel::attach_in_plane`]).
    pub fn attach_in_plane(
        &mut self,
        ip: &crate::dynamics::in_plane::InPlaneDynamics,
    ) -> Result<(), SimulationError> {
        self.models
            .iter_mut()
            .try_for_each(|m| m.attach_in_plane(ip))
    }

    /// Model `model`'s declared outputs and the layout of its values.
    pub fn outputs(&self, model: usize) -> (&'static Outputs, &ChannelLayout) {
        let (o, layout) = &self.outputs[model];
        (o, layout)
    }

    /// Every model's output values, zero (filled by [`LoadModels::write_outputs`]).
    pub fn new_output_values(&self) -> Vec<Vec<f64>> {
        self.outputs
            .iter()
            .map(|(_, l)| vec![0.0; l.len()])
            .collect()
    }

    /// Every model's outputs at the state `state`, commands `commands`, the
    /// scratch of the last [`LoadModels::evaluate`] and joint angle `chi`.
    pub fn write_outputs(
        &self,
        state: &LoadModelState,
        commands: &LoadCommands,
        wrenches: &ModelWrenches,
        chi: f64,
        values: &mut [Vec<f64>],
    ) {
        for (i, (m, out)) in self.models.iter().zip(values.iter_mut()).enumerate() {
            let at = OutputContext {
                slot: &state.slots[i],
                commands: &commands.values[i],
                scratch: wrenches.scratch[i].as_ref(),
                chi,
            };
            m.write_outputs(&at, out);
        }
    }

    /// The section names of the models this scene has (`pads`, `tool`).
    pub fn names(&self) -> impl Iterator<Item = &'static str> + '_ {
        self.models.iter().map(|m| m.name())
    }

    /// Index and concrete type of the model of type `T`, if the scene has
    /// one (for the model's own files).
    pub fn find<T: 'static>(&self) -> Option<(usize, &T)> {
        self.models
            .iter()
            .enumerate()
            .find_map(|(i, m)| m.as_any().downcast_ref::<T>().map(|t| (i, t)))
    }

    /// Instances of command `command` of model `model` (0 if either does not exist).
    pub fn instances(&self, model: usize, command: usize) -> usize {
        self.command_ranges
            .get(model)
            .and_then(|c| c.get(command))
            .map_or(0, |r| r.len())
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

    /// Whether any model's law within a substep reads its memory ([`LoadModel::law_reads_memory`]).
    pub fn law_reads_memory(&self) -> bool {
        self.models.iter().any(|m| m.law_reads_memory())
    }

    /// Whether any model's evaluation at `ctx` reads the joint angle χ.
    pub fn reads_joint_angle(&self, ctx: &LoadContext) -> bool {
        self.models.iter().any(|m| m.reads_joint_angle(ctx))
    }

    /// The summed coupling rates of all models.
    pub fn coupling(&self) -> Coupling {
        self.coupling
    }

    /// The summed [`LoadModel::held_damping_rate`] of all models at the
    /// state of their last [`LoadModels::evaluate`] into `wrenches`, 1/s.
    pub fn held_damping_rate(&self, ctx: &LoadContext, wrenches: &mut ModelWrenches) -> f64 {
        self.models
            .iter()
            .zip(wrenches.scratch.iter_mut())
            .map(|(m, s)| m.held_damping_rate(ctx, s.as_mut()))
            .sum()
    }

    /// The first refusal of [`LoadModel::check_linear`] among the models:
    /// what the stability analysis cannot linearise in this scene.
    pub fn check_linear(&self) -> Result<(), SimulationError> {
        self.models.iter().try_for_each(|m| m.check_linear())
    }

    /// Continuous states of all models (RK4 integrates them with the modes).
    pub fn continuous_states(&self) -> usize {
        self.state_ranges.last().map_or(0, |r| r.end)
    }

    /// Switching functions of all models ([`LoadModel::switching_functions`]).
    pub fn switching_functions(&self) -> usize {
        self.switching_ranges.last().map_or(0, |r| r.end)
    }

    /// Copy the models' continuous states out of `state` into `y`.
    pub fn gather_continuous(&self, state: &LoadModelState, y: &mut [f64]) {
        for (r, slot) in self.state_ranges.iter().zip(&state.slots) {
            y[r.clone()].copy_from_slice(&slot[..r.len()]);
        }
    }

    /// Copy `y` into the models' continuous states in `state`.
    pub fn scatter_continuous(&self, y: &[f64], state: &mut LoadModelState) {
        for (r, slot) in self.state_ranges.iter().zip(state.slots.iter_mut()) {
            slot[..r.len()].copy_from_slice(&y[r.clone()]);
        }
    }

    /// Refuse integrators that hold a stiff model's forces over a substep of
    /// `h`, and any but RK4 for models with continuous states.
    pub fn check_integrator(
        &self,
        integrator: IntegratorKind,
        h: f64,
    ) -> Result<(), SimulationError> {
        if matches!(
            integrator,
            IntegratorKind::Rk4 | IntegratorKind::ContactExponential
        ) {
            return Ok(());
        }
        if let Some(m) = self.models.iter().find(|m| m.continuous_states() > 0) {
            return Err(SimulationError::ContinuousStateNeedsRk4 {
                model: m.name(),
                keys: m.coupling_keys(),
                integrator: integrator.name(),
            });
        }
        for m in &self.models {
            let c = m.coupling();
            let rate = c.stiffness_rate_sq.sqrt() + c.damping_rate + c.relaxation_rate;
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
        LoadCommands {
            values: self.models.iter().map(|m| m.initial_commands()).collect(),
        }
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
        LoadModelState {
            slots: self.models.iter().map(|m| m.initial_state()).collect(),
        }
    }

    /// Whether every model's slot is finite (the divergence guard's check).
    pub fn state_is_finite(&self, state: &LoadModelState) -> bool {
        self.models
            .iter()
            .zip(&state.slots)
            .all(|(m, slot)| m.slot_is_finite(slot))
    }

    /// Before a substep of length `h`.
    pub fn begin_substep(&self, ctx: &LoadContext, state: &mut LoadModelState, h: f64) {
        for (m, slot) in self.models.iter().zip(state.slots.iter_mut()) {
            m.begin_substep(ctx, slot, h);
        }
    }

    /// Just before [`LoadModels::commit_substep`]: log what it will change beyond the models' undo heads.
    pub fn save_changes(&self, state: &LoadModelState, undo: &mut LoadModelUndo) {
        for (i, (m, slot)) in self.models.iter().zip(&state.slots).enumerate() {
            m.save_changes(slot, undo.slot(i));
        }
    }

    /// After a substep of length `h`, at the kinematics `ctx` of its end.
    pub fn commit_substep(
        &self,
        ctx: &LoadContext,
        state: &mut LoadModelState,
        commands: &LoadCommands,
        h: f64,
    ) {
        for ((m, slot), c) in self
            .models
            .iter()
            .zip(state.slots.iter_mut())
            .zip(&commands.values)
        {
            m.commit_substep(ctx, slot, c, h);
        }
    }

    /// Fill `out` with the wrenches of all models at one instant.
    pub fn evaluate(
        &self,
        ctx: &LoadContext,
        state: &LoadModelState,
        commands: &LoadCommands,
        out: &mut ModelWrenches,
    ) {
        out.clear();
        let ModelWrenches {
            ale,
            lagrange,
            ale_follower,
            lagrange_follower,
            friction,
            rates,
            switching,
            scratch,
        } = out;
        for (i, m) in self.models.iter().enumerate() {
            let slot_out = ModelOut {
                ale: ale.as_mut_slice(),
                lagrange: lagrange.as_mut_slice(),
                ale_follower: ale_follower.as_mut_slice(),
                lagrange_follower: lagrange_follower.as_mut_slice(),
                friction: &mut friction[self.friction_ranges[i].clone()],
                scratch: scratch[i].as_mut(),
                rates: &mut rates[self.state_ranges[i].clone()],
                switching: &mut switching[self.switching_ranges[i].clone()],
            };
            m.evaluate(ctx, &state.slots[i], &commands.values[i], slot_out);
        }
    }
}

/// Consecutive ranges of `count(model)` entries, one per model.
fn consecutive_ranges(
    models: &[Box<dyn LoadModel>],
    count: impl Fn(&dyn LoadModel) -> usize,
) -> Vec<Range<usize>> {
    let mut end = 0;
    models
        .iter()
        .map(|m| {
            let r = end..end + count(m.as_ref());
            end = r.end;
            r
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::config::LimitsConfig;
    use crate::dynamics::node_frame::NodeShape;

    #[test]
    fn command_rules_name_the_instance_and_keep_the_limits() {
        let clamp = CommandSpec {
            instance: "pad",
            name: "clamp force",
            token: "clamp_force",
            unit: "N",
            indexed: true,
            rule: CommandRule::NonNegativeForce,
        };
        let limits = LimitsConfig::default();
        assert_eq!(clamp.check(0, 250.0, &limits), Ok(()));
        assert_eq!(clamp.check(0, limits.max_force, &limits), Ok(()));
        for bad in [f64::NAN, f64::INFINITY, -1.0, 2.0 * limits.max_force] {
            let e = clamp.check(0, bad, &limits).unwrap_err();
            assert!(e.to_string().contains("pad_1 clamp force"), "{e}");
        }
        let feed = CommandSpec {
            instance: "tool",
            name: "feed rate",
            token: "feed",
            unit: "m/s",
            indexed: false,
            rule: CommandRule::MagnitudeAtMost(1.0),
        };
        assert!(feed.check(0, -0.5, &limits).is_ok());
        assert!(feed
            .check(0, 1.5, &limits)
            .unwrap_err()
            .to_string()
            .starts_with("tool feed rate"));
    }

    #[test]
    fn the_contact_rate_is_the_largest_eigenvalue_of_the_mass_scaled_contact_stiffness() {
        // Two modes, two contacts: Σ w wᵀ = [[1, 0], [0, 4]] + [[1, 1], [1, 1]] over masses (2, 1).
        let shapes = [
            vec![
                NodeShape {
                    w: 1.0,
                    tilt: [0.0; 2],
                },
                NodeShape {
                    w: 2.0,
                    tilt: [0.0; 2],
                },
            ],
            vec![
                NodeShape {
                    w: 1.0,
                    tilt: [0.0; 2],
                },
                NodeShape {
                    w: -1.0,
                    tilt: [0.0; 2],
                },
            ],
        ];
        let refs: Vec<&[NodeShape]> = shapes.iter().map(|s| s.as_slice()).collect();
        let lam = contact_rate(&refs, &[2.0, 1.0]);
        // M^(−½) A M^(−½) = [[1, 1/√2], [1/√2, 5]]: eigenvalues 3 ± √(4 + 1/2).
        let expected = 3.0 + 4.5f64.sqrt();
        assert!((lam - expected).abs() < 1e-12, "{lam} vs {expected}");
    }
}
