//! Errors of the dynamics layer, as enums with context: a step that could not
//! be taken, a scene the integrators refuse, an input refused before it could
//! reach the state.

use super::node_frame::NodeKind;
use crate::model::{AngularShape, ModelError};
use thiserror::Error;

/// Why a step was undone: the divergence guard's findings.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum Divergence {
    #[error("a state variable became NaN or infinite")]
    NonFinite,
    #[error(
        "mode {} ⟨k = {k}, l = {l}, {}⟩ reached {value:e} m, beyond limits.max_deflection_thicknesses × thickness = {limit:e} m",
        mode + 1,
        shape.name()
    )]
    ModeBeyondLimit {
        mode: usize,
        k: u32,
        l: u32,
        shape: AngularShape,
        value: f64,
        limit: f64,
    },
    #[error("joint speed {speed} rad/s beyond limits.max_speed")]
    SpeedBeyondLimit { speed: f64, limit: f64 },
}

/// A step that could not be taken; the state is left as it was before the step.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum StepError {
    #[error("the simulation diverged at t = {time} s: {cause}")]
    Diverged { time: f64, cause: Divergence },
    #[error("{integrator} would need {needed} substeps of a {step:e} s step to resolve the highest mode at the current speed (limit {limit}): use exponential, or raise simulation.rate_hz / simulation.substeps")]
    TooManySubsteps {
        integrator: &'static str,
        needed: usize,
        limit: usize,
        step: f64,
    },
}

/// A scene the chosen integrator cannot run.
#[derive(Debug, Error)]
pub enum SimulationError {
    #[error(transparent)]
    Model(#[from] ModelError),
    /// An integrator that would need more than `MAX_INNER_SUBSTEPS`
    /// substeps to keep h·λ_max below its step limit (docs/hard_cases.md).
    #[error("simulation.integrator = {integrator} would need {needed} substeps per step of {step:e} s to keep h·λ_max ≤ {step_limit} ({limit_key}) for the highest mode ({frequency_hz:.0} Hz) at {speed} rad/s (limit {limit} substeps): use exponential, or raise simulation.rate_hz / simulation.substeps or {limit_key}")]
    TooManySubsteps {
        integrator: &'static str,
        limit_key: &'static str,
        step_limit: f64,
        needed: usize,
        limit: usize,
        step: f64,
        frequency_hz: f64,
        speed: f64,
    },
    /// A load model with stiff contacts whose forces an integrator would hold over a substep.
    #[error("the {model} ({keys}) couple the modes at rates up to {rate:.0} 1/s, but simulation.integrator = {integrator} holds their forces over a substep of {step:e} s (h × rate = {:.2} > {limit}): use simulation.integrator: rk4, which evaluates the {model} at every stage, or raise simulation.rate_hz / simulation.substeps", step * rate)]
    ModelTooStiffForIntegrator {
        model: &'static str,
        keys: &'static str,
        integrator: &'static str,
        rate: f64,
        step: f64,
        limit: f64,
    },
    /// More unknowns than `contact_exponential` tabulates per active set
    /// (`contact_exponential::MAX_UNKNOWNS`).
    #[error("simulation.integrator = contact_exponential tabulates matrices over all unknowns for each active set of the contacts: {modes} modes give {unknowns} unknowns, beyond its limit of {limit}: request fewer modes (plate.nodal_diameters, plate.nodal_circles) or use simulation.integrator: rk4")]
    TooManyContactUnknowns {
        modes: usize,
        unknowns: usize,
        limit: usize,
    },
    /// A load model with state of its own that evolves with the modes (massive pads).
    #[error("the {model} have state of their own ({keys}) that only simulation.integrator: rk4 integrates with the modes; simulation.integrator = {integrator} is refused")]
    ContinuousStateNeedsRk4 {
        model: &'static str,
        keys: &'static str,
        integrator: &'static str,
    },
}

/// An input refused before it reached the state. The state and every other
/// held input are unchanged.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum InputError {
    #[error("{what} is not finite ({value})")]
    NonFinite { what: String, value: f64 },
    #[error("{what} = {value:e} exceeds the plausibility limit {limit:e} (limits.*)")]
    Absurd {
        what: String,
        value: f64,
        limit: f64,
    },
    #[error("there is no {} node {index} (1-based; this scene has {count})", kind.name())]
    NoSuchNode {
        kind: NodeKind,
        index: usize,
        count: usize,
    },
    #[error("speed command {value} is not finite")]
    SpeedNotFinite { value: f64 },
    #[error("speed command {value:e} rad/s exceeds limits.max_speed = {limit:e}")]
    SpeedBeyondLimit { value: f64, limit: f64 },
    /// A load-model command for an instance (a pad) the scene does not have.
    #[error("there is no {instance} {index} ({instance}s count from 1; this scene has {count})")]
    NoSuchInstance {
        instance: &'static str,
        index: usize,
        count: usize,
    },
    /// A command of a load model the scene does not use.
    #[error("this scene has no {model} ({key})")]
    NoSuchModel {
        model: &'static str,
        key: &'static str,
    },
    /// A load-model index beyond the scene's models.
    #[error("there is no load model {index} (0-based; this scene has {count})")]
    NoSuchLoadModel { index: usize, count: usize },
    /// A command index beyond a model's commands.
    #[error("the {model} have no command {index} (0-based; they have {count})")]
    NoSuchCommand {
        model: &'static str,
        index: usize,
        count: usize,
    },
}

/// A refused entry of a batch: which one, and why (nothing of the batch was applied).
#[derive(Debug, Clone, PartialEq, Error)]
pub enum BatchError {
    #[error("entry {position}: {error}")]
    Invalid { position: usize, error: InputError },
    #[error("entry {position} names the same target as entry {first}")]
    Duplicate { position: usize, first: usize },
}

/// A pad or tool command refused by the convenience setters of
/// [`Simulation`](super::Simulation); the held commands are unchanged.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum LoadCommandError {
    #[error(transparent)]
    Input(#[from] InputError),
    #[error("there is no pad {index} (pads count from 1; this scene has {count})")]
    NoSuchPad { index: usize, count: usize },
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
