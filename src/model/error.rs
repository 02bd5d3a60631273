use thiserror::Error;

/// Why a plate model could not be built.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum ModelError {
    /// The B-splines cannot resolve the requested nodal circles.
    #[error("plate.radial_splines = {splines} is too few for nodal circles up to l = {max_l} with {bc_inner}–{bc_outer} edges: use radial_splines ≥ {min_splines}")]
    TooFewRadialSplines {
        /// `plate.radial_splines`.
        splines: usize,
        /// The inner edge's condition.
        bc_inner: &'static str,
        /// The outer edge's condition.
        bc_outer: &'static str,
        /// The most nodal circles asked for.
        max_l: u32,
        /// The fewest B-splines that resolve them.
        min_splines: usize,
    },
    #[error("the mass matrix for k = {k} is not positive definite (B-spline basis degenerate: {reason}); check plate.inner_radius, plate.outer_radius and plate.radial_splines")]
    /// The mass matrix of one k has no Cholesky factor.
    MassNotPositiveDefinite {
        /// Nodal diameters.
        k: u32,
        /// The factorisation's failure.
        reason: String,
    },
    #[error("the eigenproblem for k = {k} failed ({reason}): the plate (plate.inner_radius, plate.outer_radius, plate.thickness, plate.youngs_modulus, plate.density) or its discretisation (plate.radial_splines) is outside what double precision can resolve")]
    /// The eigensolver failed for one k.
    Eigenproblem {
        /// Nodal diameters.
        k: u32,
        /// The solver's failure.
        reason: String,
    },
    /// A mode came out non-finite or with ω² < 0.
    #[error("mode ⟨k = {k}, l = {l}⟩ came out non-finite or negative (ω² = {omega_squared:e}): the geometry or material (plate.inner_radius, plate.outer_radius, plate.thickness, plate.youngs_modulus, plate.density) is outside what double precision can resolve ({hint})")]
    NonFiniteMode {
        /// Nodal diameters.
        k: u32,
        /// Nodal circles.
        l: u32,
        /// The eigenvalue ω², 1/s².
        omega_squared: f64,
        /// What to change.
        hint: String,
    },
    /// `radial_splines: auto` does not reach the frequency tolerance.
    #[error("plate.frequency_tolerance = {tolerance:e} is not reached for k = {k} with plate.radial_splines: auto: {splines} B-splines (the most auto uses) reach an estimated {reached:.2e}; raise plate.frequency_tolerance above {reached:.1e} or fix plate.radial_splines (docs/convergence.md)")]
    FrequencyToleranceNotReached {
        /// Nodal diameters.
        k: u32,
        /// `plate.frequency_tolerance`.
        tolerance: f64,
        /// The estimated relative error reached.
        reached: f64,
        /// The B-splines it was reached with.
        splines: usize,
    },
    /// The Mindlin modes could not be computed.
    #[error("plate.theory = mindlin: {0} (plate.radial_splines is the count per field)")]
    Mindlin(#[from] super::mindlin::MindlinError),
    /// A key switched on that the dynamics do not have for Mindlin modes.
    #[error("{key} is not supported with plate.theory = mindlin: {why} (docs/mindlin.md). Switch {key} off or set plate.theory: kirchhoff")]
    MindlinKeyNotWired {
        /// The key or section (`plate.residual_flexibility`, `pads`, …).
        key: &'static str,
        /// What it would use that Mindlin theory does not give.
        why: &'static str,
    },
    /// The in-plane modes could not be computed.
    #[error("plate.in_plane_nodal_diameters: {0} (plate.radial_splines is the count per field, plate.in_plane_orders the orders)")]
    InPlane(super::in_plane::InPlaneError),
    /// In-plane modes selected for an analysis that does not carry them.
    #[error("plate.in_plane_nodal_diameters = {nodal_diameters:?} selects in-plane modes, which this model of the bending modes alone does not carry (the commands build the in-plane modes beside it: docs/in_plane.md). Set plate.in_plane_nodal_diameters: [] here")]
    InPlaneNotWired {
        /// The requested in-plane k.
        nodal_diameters: Vec<u32>,
    },
    /// Only rigid-body modes were selected.
    #[error("the selected nodal diameters × nodal circles leave no elastic mode (only rigid-body modes {skipped:?} of the free–free plate)")]
    NoElasticModes {
        /// The ⟨k, l⟩ of the rigid-body modes left out.
        skipped: Vec<(u32, u32)>,
    },
}

/// The in-plane error as the model's (its text is part of the model error's,
/// so it is not also reported as the source).
impl From<super::in_plane::InPlaneError> for ModelError {
    fn from(e: super::in_plane::InPlaneError) -> Self {
        ModelError::InPlane(e)
    }
}
