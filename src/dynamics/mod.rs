//! Rotating-plate dynamics (paper sections 2.2, 3.2, 4.1): the joint, the
//! reference frame, Lagrangian and ALE node frames, wrenches and integrators.
//!
//! Model, state and stepper are kept apart: [`Scene`] (the plate model plus
//! nodes, joint and effects) is immutable, [`State`] is plain data, and the
//! [`Stepper`] borrows both and owns only scratch space allocated once.
//! [`Simulation`] bundles them with the held inputs for the CLI and the node.

pub mod ale;
pub mod integrators;
pub mod joint;
pub mod load_models;
pub mod loads;
pub mod scene;
pub mod simulation;
pub mod stability;
pub mod state;
pub mod stepper;
pub mod wrench;

pub use load_models::{check_clamp_force, check_feed_rate, LoadCommandError, LoadCommands, LoadModelState, LoadModels, ModelWrenches};
pub use loads::Inputs;
pub use scene::Scene;
pub use simulation::{JointOutput, NodeOutput, PadOutput, Pose, Simulation, SimulationError, StepError, ToolOutput};
pub use state::{JointAngle, State};
pub use stepper::{Stepper, StepperSettings, Views};
pub use wrench::{InputError, NodeKind, Wrench};
