//! Time integration of the elastic coordinates over one substep (the joint
//! motion over the substep is given: constant acceleration from the drive).
//!
//! - `exponential`: exact per mode for loads held over the step;
//! - `implicit_midpoint`: A-stable, conserves the quadratic energy of the
//!   undamped linear system, second order;
//! - `rk4`: the explicit reference, sub-stepping below its stability limit.
//!
//! One criterion for all (docs/hard_cases.md): a step must resolve the fastest
//! mode, h·λ_max ≤ the integrator's step limit (`StepperSettings::step_limit`); the stepper
//! sub-steps until it holds and refuses beyond [`MAX_INNER_SUBSTEPS`]. The
//! exponential integrator is exact for the modes at any h (limit ∞).

/// Beyond this many inner substeps per substep a run is refused.
pub const MAX_INNER_SUBSTEPS: usize = 100_000;

pub mod block_exponential;
pub mod contact_exponential;
pub mod equations;
pub mod exponential;
pub mod implicit_midpoint;
pub mod phi;
pub(crate) mod piece;
pub mod rk4;
pub mod stiffened_midpoint;
