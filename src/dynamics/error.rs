//! Errors of the dynamics layer, as enums with context: a step that could not
//! be taken, a scene the integrators refuse, an input refused before it could
//! reach the state.

use super::node_frame::NodeKind;
use crate::model::{AngularShape, ModelError};
use thiserror::Error;

/// Why a step was undone: the divergence guard's findings.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum Divergence {
    /// A state variable became NaN or infinite.
    #[error("a state variable became NaN or infinite")]
    NonFinite,
    /// A modal amplitude beyond `limits.max_deflection_thicknesses` × thickness.
    #[error(
        "mode {} ⟨k = {k}, l = {l}, {}⟩ reached {value:e} m, beyond limits.max_deflection_thicknesses × thickness = {limit:e} m",
        mode + 1,
        shape.name()
    )]
    ModeBeyondLimit {
        /// The mode's index in the model's order (from 0).
        mode: usize,
        /// Its nodal diameters k.
        k: u32,
        /// Its nodal circles l.
        l: u32,
        /// Its angular shape (cos or sin).
        shape: AngularShape,
        /// The amplitude reached, m.
        value: f64,
        /// The limit, m.
        limit: f64,
    },
    /// An in-plane modal amplitude (peak displacement) beyond
    /// `limits.max_deflection_thicknesses` × thickness.
    #[error(
        "in-plane mode ⟨k = {k}, l = {l}⟩ (state index {}) reached {value:e} m, beyond limits.max_deflection_thicknesses × thickness = {limit:e} m",
        mode + 1
    )]
    InPlaneModeBeyondLimit {
        /// The mode's state index (from 0).
        mode: usize,
        /// Its nodal diameters k.
        k: u32,
        /// Its order l.
        l: u32,
        /// The amplitude reached, m.
        value: f64,
        /// The limit, m.
        limit: f64,
    },
    /// The joint speed beyond `limits.max_speed` in magnitude.
    #[error("joint speed {speed} rad/s beyond limits.max_speed")]
    SpeedBeyondLimit {
        /// The joint speed reached, rad/s.
        speed: f64,
        /// limits.max_speed, rad/s.
        limit: f64,
    },
}

/// A step that could not be taken; the state is left as it was before the step.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum StepError {
    /// The divergence guard found the new state implausible; the step was undone.
    #[error("the simulation diverged at t = {time} s: {cause}")]
    Diverged {
        /// The simulated time of the state the guard checked, s.
        time: f64,
        /// What the guard found.
        cause: Divergence,
    },
    /// An explicit integrator would need more substeps than its limit to resolve the highest mode at the current joint speed.
    #[error("{integrator} would need {needed} substeps of a {step:e} s step to resolve the highest mode at the current speed (limit {limit}): use exponential, or raise simulation.rate_hz / simulation.substeps")]
    TooManySubsteps {
        /// The integrator, by its parameter name.
        integrator: &'static str,
        /// The substeps it would need.
        needed: usize,
        /// The largest number of substeps allowed.
        limit: usize,
        /// The step, s.
        step: f64,
    },
    /// The load models' damping at the current state is beyond what an
    /// integrator that holds their forces over a substep resolves
    /// (`LoadModel::held_damping_rate`: the face friction's μN/|V| grows as
    /// the sliding slows).
    #[error("the load models damp the modes at rates up to {rate:.0} 1/s at the current state (the face friction's μN/|V| grows as the sliding slows; Ω = {speed} rad/s), but simulation.integrator = {integrator} holds their forces over a substep of {step:e} s (h × rate = {:.2} > {limit}): use simulation.integrator: contact_exponential or rk4, which evaluate them within the step, or raise simulation.rate_hz / simulation.substeps; the step was undone", step * rate)]
    HeldDampingTooFast {
        /// The integrator, by its parameter name.
        integrator: &'static str,
        /// The damping rate bound, 1/s.
        rate: f64,
        /// The substep, s.
        step: f64,
        /// The largest h × rate accepted.
        limit: f64,
        /// Ω at the substep's start, rad/s.
        speed: f64,
    },
    /// A `contact_exponential` piece faster than the rates its switching
    /// functions' samples were sized for.
    #[error("simulation.integrator = contact_exponential: a piece's fastest rate {rate:.3e} 1/s at Ω = {speed} rad/s is beyond the scene's bound at rest, {bound:.3e} 1/s, that sizes the samples of its switching functions (a quarter radian each, down to {unit:e} s): a contact closing and opening between two samples would be missed; use simulation.integrator: rk4; the step was undone")]
    SwitchesUndersampled {
        /// The piece's fastest rate, 1/s.
        rate: f64,
        /// λ_max at Ω = 0, 1/s.
        bound: f64,
        /// The finest sample interval, s.
        unit: f64,
        /// Ω at the substep's start, rad/s.
        speed: f64,
    },
    /// The joint turned faster than the in-plane modes' bound where their spin terms are not built.
    #[error("the joint speed {speed} rad/s is beyond {limit:.3} rad/s, the bound for in-plane modes (plate.in_plane_nodal_diameters) where their spin terms are not built (simulation.integrator: implicit_midpoint; Coriolis coupling 2Ω/ω_min up to 1e-3); the step was undone")]
    InPlaneSpin {
        /// Ω at the step's end, rad/s.
        speed: f64,
        /// The bound, rad/s.
        limit: f64,
    },
}

/// A scene the chosen integrator cannot run.
#[derive(Debug, Error)]
pub enum SimulationError {
    /// The plate model could not be built.
    #[error(transparent)]
    Model(#[from] ModelError),
    /// An integrator that would need more than `MAX_INNER_SUBSTEPS`
    /// substeps to keep h·λ_max below its step limit (docs/hard_cases.md).
    #[error("simulation.integrator = {integrator} would need {needed} substeps per step of {step:e} s to keep h·λ_max ≤ {step_limit} ({limit_key}) for the highest mode ({frequency_hz:.0} Hz) at {speed} rad/s (limit {limit} substeps): use exponential, or raise simulation.rate_hz / simulation.substeps or {limit_key}")]
    TooManySubsteps {
        /// The integrator, by its parameter name.
        integrator: &'static str,
        /// The key of its step limit h·λ_max.
        limit_key: &'static str,
        /// Its step limit h·λ_max.
        step_limit: f64,
        /// The substeps it would need.
        needed: usize,
        /// The largest number of substeps allowed.
        limit: usize,
        /// The step 1/simulation.rate_hz, s.
        step: f64,
        /// The highest mode's frequency at that speed, Hz.
        frequency_hz: f64,
        /// The joint speed checked, rad/s.
        speed: f64,
    },
    /// A load model with stiff contacts whose forces an integrator would hold over a substep.
    #[error("the {model} ({keys}) couple the modes at rates up to {rate:.0} 1/s, but simulation.integrator = {integrator} holds their forces over a substep of {step:e} s (h × rate = {:.2} > {limit}): use simulation.integrator: rk4, which evaluates the {model} at every stage, or raise simulation.rate_hz / simulation.substeps", step * rate)]
    ModelTooStiffForIntegrator {
        /// The load model, by its plural name.
        model: &'static str,
        /// The keys that set its stiffness.
        keys: &'static str,
        /// The integrator, by its parameter name.
        integrator: &'static str,
        /// The highest coupling rate of its contacts, 1/s.
        rate: f64,
        /// The substep, s.
        step: f64,
        /// The largest h × rate allowed.
        limit: f64,
    },
    /// More unknowns than `contact_exponential` tabulates per active set
    /// (`contact_exponential::MAX_UNKNOWNS`).
    #[error("simulation.integrator = contact_exponential tabulates matrices over all unknowns for each active set of the contacts: {modes} modes give {unknowns} unknowns, beyond its limit of {limit}: request fewer modes (plate.nodal_diameters, plate.nodal_circles) or use simulation.integrator: rk4")]
    TooManyContactUnknowns {
        /// The modes of the model.
        modes: usize,
        /// The unknowns they give.
        unknowns: usize,
        /// The largest number of unknowns tabulated.
        limit: usize,
    },
    /// A key the in-plane modes do not carry yet.
    #[error("{key} with in-plane modes (plate.in_plane_nodal_diameters) is refused: {why} (docs/in_plane.md)")]
    InPlaneKeyNotWired {
        /// The key refused.
        key: &'static str,
        /// Why.
        why: &'static str,
    },
    /// A start faster than the in-plane modes' bound where their spin terms are not built.
    #[error("joint.speed = {speed} rad/s is beyond {limit:.3} rad/s, the bound for in-plane modes (plate.in_plane_nodal_diameters) where their spin terms are not built (simulation.integrator: implicit_midpoint; Coriolis coupling 2Ω/ω_min up to 1e-3)")]
    InPlaneSpin {
        /// joint.speed, rad/s.
        speed: f64,
        /// The bound, rad/s.
        limit: f64,
    },
    /// A load model with state of its own that evolves with the modes (massive pads).
    #[error("the {model} have state of their own ({keys}) that only simulation.integrator: rk4 integrates with the modes; simulation.integrator = {integrator} is refused")]
    ContinuousStateNeedsRk4 {
        /// The load model, by its plural name.
        model: &'static str,
        /// The keys that give it its own state.
        keys: &'static str,
        /// The integrator refused, by its parameter name.
        integrator: &'static str,
    },
}

/// An input refused before it reached the state. The state and every other
/// held input are unchanged.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum InputError {
    /// An input value that is NaN or infinite.
    #[error("{what} is not finite ({value})")]
    NonFinite {
        /// The input, by name.
        what: String,
        /// The value given.
        value: f64,
    },
    /// An input above its plausibility limit (`limits.*`).
    #[error("{what} = {value:e} exceeds the plausibility limit {limit:e} (limits.*)")]
    Absurd {
        /// The input, by name.
        what: String,
        /// Its magnitude, in its unit.
        value: f64,
        /// The limit, in the same unit.
        limit: f64,
    },
    /// A node index (from 1) the scene does not have.
    #[error("there is no {} node {index} (1-based; this scene has {count})", kind.name())]
    NoSuchNode {
        /// Lagrangian or ALE.
        kind: NodeKind,
        /// The index given (from 1).
        index: usize,
        /// The nodes of that kind in the scene.
        count: usize,
    },
    /// A speed command that is NaN or infinite.
    #[error("speed command {value} is not finite")]
    SpeedNotFinite {
        /// The command given, rad/s.
        value: f64,
    },
    /// A speed command beyond `limits.max_speed` in magnitude.
    #[error("speed command {value:e} rad/s exceeds limits.max_speed = {limit:e}")]
    SpeedBeyondLimit {
        /// The command given, rad/s.
        value: f64,
        /// limits.max_speed, rad/s.
        limit: f64,
    },
    /// A load-model command for an instance (a pad) the scene does not have.
    #[error("there is no {instance} {index} ({instance}s count from 1; this scene has {count})")]
    NoSuchInstance {
        /// The kind of instance (`pad`).
        instance: &'static str,
        /// The index given (from 1).
        index: usize,
        /// The instances in the scene.
        count: usize,
    },
    /// A command of a load model the scene does not use.
    #[error("this scene has no {model} ({key})")]
    NoSuchModel {
        /// The load model, by name.
        model: &'static str,
        /// The key that would switch it on.
        key: &'static str,
    },
    /// A load-model index beyond the scene's models.
    #[error("there is no load model {index} (0-based; this scene has {count})")]
    NoSuchLoadModel {
        /// The index given (from 0).
        index: usize,
        /// The load models in the scene.
        count: usize,
    },
    /// A command index beyond a model's commands.
    #[error("the {model} have no command {index} (0-based; they have {count})")]
    NoSuchCommand {
        /// The load model, by its plural name.
        model: &'static str,
        /// The index given (from 0).
        index: usize,
        /// The commands it declares.
        count: usize,
    },
}

/// A refused entry of a batch: which one, and why (nothing of the batch was applied).
#[derive(Debug, Clone, PartialEq, Error)]
pub enum BatchError {
    /// An entry refused on its own.
    #[error("entry {position}: {error}")]
    Invalid {
        /// Its position in the batch (from 0).
        position: usize,
        /// Why it was refused.
        error: InputError,
    },
    /// Two entries name the same target.
    #[error("entry {position} names the same target as entry {first}")]
    Duplicate {
        /// The later entry's position (from 0).
        position: usize,
        /// The earlier entry's position (from 0).
        first: usize,
    },
}

/// A pad or tool command refused by the convenience setters of
/// [`Simulation`](super::Simulation); the held commands are unchanged.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum LoadCommandError {
    /// A refusal of the generic load-model command path.
    #[error(transparent)]
    Input(#[from] InputError),
    /// A pad (from 1) the scene does not have.
    #[error("there is no pad {index} (pads count from 1; this scene has {count})")]
    NoSuchPad {
        /// The pad given (from 1).
        index: usize,
        /// The pads in the scene.
        count: usize,
    },
    /// The scene has no tool (`tool.ale_node` is not given).
    #[error("this scene has no tool (tool.ale_node)")]
    NoTool,
}

impl LoadCommandError {
    /// The pad/tool form of a generic load-command refusal.
    pub fn from_input(e: InputError) -> LoadCommandError {
        match e {
            InputError::NoSuchInstance {
                instance: "pad",
                index,
                count,
            } => LoadCommandError::NoSuchPad { index, count },
            InputError::NoSuchModel { model: "tool", .. } => LoadCommandError::NoTool,
            other => LoadCommandError::Input(other),
        }
    }
}
