//! Time integration of the elastic coordinates over one substep (the joint
//! motion over the substep is given: constant acceleration from the drive).
//!
//! - `exponential`: exact per mode for loads held over the step;
//! - `implicit_midpoint`: A-stable, conserves the quadratic energy of the
//!   undamped linear system, second order;
//! - `rk4`: the explicit reference, sub-stepping below its stability limit.

pub mod equations;
pub mod exponential;
pub mod implicit_midpoint;
pub mod phi;
pub mod rk4;
