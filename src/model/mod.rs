//! The annular Kirchhoff plate as a modal flexible body (paper sections 2.1, 2.2, 3.1, 4).
//!
//! [`PlateModel::new`] discretises the radial ODE (4) with cubic B-splines
//! (`bspline`), assembles mass and stiffness per nodal-diameter number k
//! (`radial`), solves the symmetric-definite eigenproblem (14) (`eigen`),
//! keeps exactly the requested ⟨k, l⟩ modes (`modes`), evaluates mode shapes
//! and the displacement field (13) (`shape`) and integrates the body data of
//! eq. (11) (`body`). Immutable once built; no ROS, no time stepping.
//! [`mindlin`] computes the thick-plate (Mindlin) modes per k by the same
//! radial machinery; with `plate.theory: mindlin` the model's modes are
//! those (docs/mindlin.md); the dynamics and `stability` take them (node
//! frames turned by ψ, body data with the rotary inertia), `plot` draws
//! their w, `study` measures them. [`in_plane`]
//! computes the in-plane (plane-stress) modes by the same machinery; `modes`
//! lists them ([`PlateModel::bending_and_in_plane`]), the dynamics carry them
//! ([`PlateModel::bending`]), and [`PlateModel::new`] refuses them for the
//! analyses that do not (docs/in_plane.md).

mod annulus;
pub(crate) mod body;
pub(crate) mod bspline;
mod build;
pub mod campbell;
pub(crate) mod eigen;
mod error;
pub(crate) mod fft;
pub mod in_plane;
pub(crate) mod lanczos;
pub mod mindlin;
pub(crate) mod modes;
pub mod nodal_lines;
pub(crate) mod patch;
pub mod prestress;
pub(crate) mod quadrature;
pub(crate) mod radial;
pub(crate) mod residual;
pub(crate) mod resolution;
pub(crate) mod shape;
pub(crate) mod spinning;

pub use body::BodyData;
pub use error::ModelError;
pub use modes::{AngularShape, Mode, RadialShape};
pub use residual::{ResidualKernel, StaticHarmonics};
pub use resolution::KResolution;
pub use shape::ShapeValue;
pub use spinning::{ModalGeometricStiffness, SpinningSpectrum};

use crate::config::{PlateConfig, PlateTheory};

/// Refuse a non-empty `plate.in_plane_nodal_diameters` where a model of
/// the bending modes alone is asked for ([`PlateModel::new`]).
pub fn refuse_in_plane(plate: &PlateConfig) -> Result<(), ModelError> {
    if plate.in_plane_nodal_diameters.is_empty() {
        return Ok(());
    }
    Err(ModelError::InPlaneNotWired {
        nodal_diameters: plate.in_plane_nodal_diameters.clone(),
    })
}

/// Bending rigidity D = E h³ / (12 (1 − ν²)), eq. (2) (defined with the
/// configuration, whose validation checks its range).
pub use crate::config::bending_rigidity;

/// The immutable plate model: modes, shapes and body data.
#[derive(Debug, Clone)]
pub struct PlateModel {
    plate: PlateConfig,
    rigidity: f64,
    modes: Vec<Mode>,
    radial_shapes: Vec<RadialShape>,
    skipped_rigid_body_modes: Vec<(u32, u32)>,
    body: BodyData,
    radial_resolution: Vec<KResolution>,
    /// Under Mindlin theory the mode of each radial shape (same index); empty under Kirchhoff.
    mindlin: Vec<mindlin::MindlinMode>,
}

impl PlateModel {
    /// Build the model for a validated plate configuration. Refuses a
    /// non-empty `plate.in_plane_nodal_diameters` before any work
    /// ([`refuse_in_plane`]): the analyses built on this model do not carry
    /// in-plane modes.
    pub fn new(plate: &PlateConfig) -> Result<PlateModel, ModelError> {
        refuse_in_plane(plate)?;
        build::build(plate)
    }

    /// The bending model of `plate` whatever its in-plane keys: the
    /// dynamics (`simulate`, `run`) add the in-plane modes themselves
    /// (`dynamics::in_plane`).
    pub fn bending(plate: &PlateConfig) -> Result<PlateModel, ModelError> {
        build::build(plate)
    }

    /// The bending model of `plate` whatever its in-plane keys, with the
    /// in-plane mode table of `plate.in_plane_*` and the in-plane edges of
    /// `edges` (`modes`, which lists both).
    pub fn bending_and_in_plane(
        plate: &PlateConfig,
        edges: &crate::config::CentrifugalConfig,
    ) -> Result<(PlateModel, in_plane::InPlaneTable), ModelError> {
        let bending = build::build(plate)?;
        let table = in_plane::InPlaneTable::new(plate, edges)?;
        Ok((bending, table))
    }

    /// The plate the model is of.
    pub fn plate(&self) -> &PlateConfig {
        &self.plate
    }

    /// D of eq. (2), N·m.
    pub fn rigidity(&self) -> f64 {
        self.rigidity
    }

    /// Mass per unit area ρ̂ = ρ h, kg/m².
    pub fn areal_density(&self) -> f64 {
        self.plate.density * self.plate.thickness
    }

    /// The elastic modes, sorted by frequency (ties: k, then cos before sin).
    pub fn modes(&self) -> &[Mode] {
        &self.modes
    }

    /// The number of elastic modes.
    pub fn n_modes(&self) -> usize {
        self.modes.len()
    }

    /// The radial functions R_l(r) (one per distinct ⟨k, l⟩), indexed by [`Mode::radial`].
    pub fn radial_shapes(&self) -> &[RadialShape] {
        &self.radial_shapes
    }

    /// ⟨k, l⟩ combinations requested but not elastic: a free–free plate's
    /// rigid-body translation ⟨0, 0⟩ and tilt ⟨1, 0⟩, which the floating frame
    /// and the joint carry instead.
    pub fn skipped_rigid_body_modes(&self) -> &[(u32, u32)] {
        &self.skipped_rigid_body_modes
    }

    /// The radial spline count used per requested k, ascending in k (with
    /// `plate.radial_splines: auto` also its estimated frequency error).
    pub fn radial_resolution(&self) -> &[KResolution] {
        &self.radial_resolution
    }

    /// The plate theory the modes are of (`plate.theory`).
    pub fn theory(&self) -> PlateTheory {
        self.plate.theory
    }

    /// Under Mindlin theory the Mindlin mode (w, ψ_r, ψ_θ) of radial shape
    /// `radial` ([`Mode::radial`]); `None` under Kirchhoff theory.
    pub fn mindlin_mode(&self, radial: usize) -> Option<&mindlin::MindlinMode> {
        self.mindlin.get(radial)
    }

    /// Body data of eq. (11).
    pub fn body(&self) -> &BodyData {
        &self.body
    }

    /// Radius of a node at radial coordinate ξ_r ∈ [0, 1].
    pub fn radius_at(&self, xi_radial: f64) -> f64 {
        self.plate.inner_radius + xi_radial * (self.plate.outer_radius - self.plate.inner_radius)
    }
}
