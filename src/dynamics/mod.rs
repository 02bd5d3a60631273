//! Rotating-plate dynamics (paper sections 2.2, 3.2, 4.1): the joint, the
//! reference frame, Lagrangian and ALE node frames, wrenches and integrators.
//!
//! Model, state and stepper are kept apart: [`Scene`] (the plate model plus
//! nodes, joint and effects) is immutable, [`State`] is plain data, and the
//! [`Stepper`] borrows both and owns only scratch space allocated once.
//! [`Simulation`] bundles them with the settings and the held inputs for the
//! CLI and the node. Inputs pass one contract (`commands`); load models
//! plug in through the [`LoadModel`] trait ([`load_models`]).

pub(crate) mod ale;
pub(crate) mod angle;
pub(crate) mod commands;
pub(crate) mod contact_compliance;
pub(crate) mod dense;
pub(crate) mod error;
pub(crate) mod in_plane;
pub(crate) mod in_plane_residual;
pub(crate) mod in_plane_spin;
pub(crate) mod integrators;
pub(crate) mod joint;
pub(crate) mod layout;
pub mod load_models;
pub(crate) mod loads;
pub(crate) mod node_frame;
pub(crate) mod node_output;
pub(crate) mod residual;
pub(crate) mod scene;
pub(crate) mod simulation;
pub mod stability;
pub mod stability_map;
pub(crate) mod state;
pub(crate) mod stepper;
pub(crate) mod stiffening;
pub(crate) mod wrench;

pub use commands::{check, check_batch, Checked, CheckedBatch, Command, InputRules, Inputs};
pub use error::{BatchError, Divergence, InputError, LoadCommandError, SimulationError, StepError};
pub use load_models::{
    CommandRule, CommandSpec, LoadCommands, LoadModel, LoadModelState, LoadModels, ModelWrenches,
};
pub use scene::Scene;
pub use simulation::{JointOutput, NodeOutput, Pose, Simulation};
pub use state::{ContactSpans, JointAngle, State};
pub use stepper::{Stepper, StepperSettings};
pub use wrench::{NodeKind, Wrench};
