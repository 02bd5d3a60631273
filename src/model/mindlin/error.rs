use thiserror::Error;

/// Why Mindlin modes could not be computed.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum MindlinError {
    /// A plate number is out of its range.
    #[error("mindlin plate: {name} = {value:e} must be {rule}")]
    InvalidParameter {
        /// The field of [`super::MindlinPlate`].
        name: &'static str,
        /// Its value.
        value: f64,
        /// The rule it breaks.
        rule: &'static str,
    },
    /// The B-spline count per field is out of range.
    #[error("mindlin splines = {splines} must be in {min}..={max}")]
    Splines {
        /// The count asked for.
        splines: usize,
        /// [`super::MIN_SPLINES`].
        min: usize,
        /// [`super::MAX_SPLINES`].
        max: usize,
    },
    /// More radial orders than the discretisation resolves.
    #[error("mindlin orders = {orders} must be in 1..={max} (half the free coefficients); raise splines")]
    Orders {
        /// The orders asked for.
        orders: usize,
        /// The most this discretisation gives.
        max: usize,
    },
    /// The eigensolver failed.
    #[error("the mindlin eigenproblem for k = {k} failed: {reason}")]
    Eigen {
        /// Nodal diameters.
        k: u32,
        /// The solver's failure.
        reason: String,
    },
    /// A mode came out non-finite, with ω² ≤ 0 or without deflection.
    #[error("mindlin mode ⟨k = {k}, l = {l}⟩ came out non-finite, with ω² = {omega_squared:e} ≤ 0 or without deflection")]
    NonFiniteMode {
        /// Nodal diameters.
        k: u32,
        /// Radial order.
        l: u32,
        /// ω², 1/s².
        omega_squared: f64,
    },
}

impl MindlinError {
    pub(super) fn invalid(name: &'static str, value: f64, rule: &'static str) -> Self {
        MindlinError::InvalidParameter { name, value, rule }
    }
}
