use thiserror::Error;

/// Why a plate model could not be built.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum ModelError {
    #[error("plate.radial_splines = {splines} is too few for nodal circles up to l = {max_l} with {bc_inner}–{bc_outer} edges: use radial_splines ≥ {min_splines}")]
    TooFewRadialSplines {
        splines: usize,
        bc_inner: &'static str,
        bc_outer: &'static str,
        max_l: u32,
        min_splines: usize,
    },
    #[error("the mass matrix for k = {k} is not positive definite (B-spline basis degenerate: {reason}); check plate.inner_radius, plate.outer_radius and plate.radial_splines")]
    MassNotPositiveDefinite { k: u32, reason: String },
    #[error("the eigenproblem for k = {k} failed ({reason}): the plate (plate.inner_radius, plate.outer_radius, plate.thickness, plate.youngs_modulus, plate.density) or its discretisation (plate.radial_splines) is outside what double precision can resolve")]
    Eigenproblem { k: u32, reason: String },
    #[error("mode ⟨k = {k}, l = {l}⟩ came out non-finite or negative (ω² = {omega_squared:e}): the geometry or material (plate.inner_radius, plate.outer_radius, plate.thickness, plate.youngs_modulus, plate.density) is outside what double precision can resolve ({hint})")]
    NonFiniteMode {
        k: u32,
        l: u32,
        omega_squared: f64,
        hint: String,
    },
    #[error("plate.frequency_tolerance = {tolerance:e} is not reached for k = {k} with plate.radial_splines: auto: {splines} B-splines (the most auto uses) reach an estimated {reached:.2e}; raise plate.frequency_tolerance above {reached:.1e} or fix plate.radial_splines (docs/convergence.md)")]
    FrequencyToleranceNotReached {
        k: u32,
        tolerance: f64,
        reached: f64,
        splines: usize,
    },
    #[error("the selected nodal diameters × nodal circles leave no elastic mode (only rigid-body modes {skipped:?} of the free–free plate)")]
    NoElasticModes { skipped: Vec<(u32, u32)> },
}
