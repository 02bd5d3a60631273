use thiserror::Error;

/// Why in-plane modes could not be computed.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum InPlaneError {
    /// A plate number is out of its range.
    #[error("in-plane plate: {name} = {value:e} must be {rule}")]
    InvalidParameter {
        /// The field of [`super::InPlanePlate`].
        name: &'static str,
        /// Its value.
        value: f64,
        /// The rule it breaks.
        rule: &'static str,
    },
    /// The B-spline count per field is out of range.
    #[error("in-plane splines = {splines} must be in {min}..={max}")]
    Splines {
        /// The count asked for.
        splines: usize,
        /// [`super::MIN_SPLINES`].
        min: usize,
        /// [`super::MAX_SPLINES`].
        max: usize,
    },
    /// More orders than the discretisation resolves.
    #[error("in-plane orders = {orders} must be in 1..={max} (half the free coefficients); raise splines")]
    Orders {
        /// The orders asked for.
        orders: usize,
        /// The most this discretisation gives.
        max: usize,
    },
    /// The eigensolver failed.
    #[error("the in-plane eigenproblem for k = {k} ({family}) failed: {reason}")]
    Eigen {
        /// Nodal diameters.
        k: u32,
        /// `torsional`, `radial` or `coupled`.
        family: &'static str,
        /// The solver's failure.
        reason: String,
    },
    /// The spinning spectrum's eigenproblem failed or has a root that is not real.
    #[error("the in-plane spinning spectrum of k = {k} at {spin} rad/s failed: {reason}")]
    SpinEigen {
        /// Nodal diameters.
        k: u32,
        /// Spin speed, rad/s.
        spin: f64,
        /// What went wrong.
        reason: String,
    },
    /// A mode came out non-finite, with ω² ≤ 0 or without displacement.
    #[error("in-plane mode ⟨k = {k}, l = {l}⟩ came out non-finite, with ω² = {omega_squared:e} ≤ 0 or without displacement")]
    NonFiniteMode {
        /// Nodal diameters.
        k: u32,
        /// Order.
        l: u32,
        /// ω², 1/s².
        omega_squared: f64,
    },
}

impl InPlaneError {
    pub(super) fn invalid(name: &'static str, value: f64, rule: &'static str) -> Self {
        InPlaneError::InvalidParameter { name, value, rule }
    }
}
