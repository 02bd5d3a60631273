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

pub(crate) mod block_exponential;
pub(crate) mod contact_exponential;
pub(crate) mod equations;
pub(crate) mod exponential;
pub(crate) mod implicit_midpoint;
pub(crate) mod phi;
pub(crate) mod piece;
pub(crate) mod rk4;
pub(crate) mod stiffened_midpoint;
