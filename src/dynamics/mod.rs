//! Rotating-plate dynamics (paper sections 2.2, 3.2, 4.1): the joint, the
//! reference frame, Lagrangian and ALE node frames, wrenches and integrators.
//!
//! Model, state and stepper are kept apart: [`Scene`] (the plate model plus
//! nodes, joint and effects) is immutable, [`State`] is plain data, and the
//! [`Stepper`] borrows both and owns only scratch space allocated once.
//! [`Simulation`] bundles them with the settings and the held inputs for the
//! CLI and the node. Inputs pass one contract ([`commands`]); load models
//! plug in through the [`LoadModel`] trait ([`load_models`]).

pub mod ale;
pub mod angle;
pub mod commands;
pub mod contact_compliance;
pub mod dense;
pub mod error;
pub mod integrators;
pub mod joint;
pub mod layout;
pub mod load_models;
pub mod loads;
pub mod node_frame;
pub mod residual;
pub mod scene;
pub mod simulation;
pub mod stability;
pub mod stability_map;
pub mod stability_pads;
pub mod state;
pub mod stepper;
pub mod stiffening;
pub mod wrench;

pub use commands::{check, check_batch, Checked, CheckedBatch, Command, InputRules, Inputs};
pub use error::{BatchError, Divergence, InputError, LoadCommandError, SimulationError, StepError};
pub use load_models::{
    CommandRule, CommandSpec, LoadCommands, LoadModel, LoadModelState, LoadModels, ModelWrenches,
};
pub use scene::Scene;
pub use simulation::{JointOutput, NodeOutput, Pose, Simulation};
pub use state::{JointAngle, State};
pub use stepper::{Stepper, StepperSettings};
pub use wrench::{NodeKind, Wrench};
