//! The plate model of Mindlin modes (`plate.theory: mindlin`): the mode
//! table of the requested ⟨k, l⟩ from [`super::mindlin_modes`], with the
//! Kirchhoff model's numbering, cos/sin pairs and normalisation.
//!
//! What changes against the Kirchhoff model (docs/mindlin.md "In the model"):
//! - ω and the radial shape W of w: the stationary points of U − ω² T with
//!   the shear and rotary-inertia terms (module doc of [`super`]);
//! - the modal mass m_i = c_k ∫ [ρh W² + ρh³/12 (Ψ_r² + Ψ_θ²)] r dr (the
//!   rotary inertia of T), so K_e = diag(m_i ω_i²) and D_e = diag(2ζ_i ω_i m_i)
//!   of eq. (11) follow from it;
//! - the radial spline count: `auto` is [`super::DEFAULT_SPLINES`] per field
//!   for every k (its accuracy is measured, not estimated per k), a fixed
//!   `plate.radial_splines` is the count per field.
//!
//! The body data's C_t and d_CM (∫ w dm) are the same in form for Mindlin
//! modes; C_r and J₁ of eq. (11) gain the rotary moments ρh³/12 ∫ ψ dA of
//! the k = 1 modes ([`crate::model::BodyData::rotary_moments`]).

use super::{MindlinDiscretisation, MindlinEdge, MindlinPlate, DEFAULT_SPLINES};
use crate::config::{Boundary, PlateConfig, RadialSplines};
use crate::model::build::{finish, Parts, TableEntry};
use crate::model::modes::is_rigid_body;
use crate::model::resolution::KResolution;
use crate::model::{bending_rigidity, ModelError, PlateModel};

/// The Mindlin edge of a configured edge (`supported` is the hard support).
pub fn mindlin_edge(boundary: Boundary) -> MindlinEdge {
    match boundary {
        Boundary::Free => MindlinEdge::Free,
        Boundary::Supported => MindlinEdge::Supported,
        Boundary::Clamped => MindlinEdge::Clamped,
        Boundary::SupportedSoft => MindlinEdge::SupportedSoft,
    }
}

/// The Mindlin plate of a configuration.
pub fn mindlin_plate(plate: &PlateConfig) -> MindlinPlate {
    MindlinPlate {
        youngs_modulus: plate.youngs_modulus,
        poisson_ratio: plate.poisson_ratio,
        density: plate.density,
        thickness: plate.thickness,
        inner_radius: plate.inner_radius,
        outer_radius: plate.outer_radius,
        shear_correction: plate.shear_correction,
        inner_edge: mindlin_edge(plate.inner_boundary),
        outer_edge: mindlin_edge(plate.outer_boundary),
    }
}

/// The discretisation of a configuration's Mindlin modes: `auto` is
/// [`DEFAULT_SPLINES`] per field, a fixed `plate.radial_splines` the count.
pub(crate) fn discretisation(plate: &PlateConfig) -> Result<MindlinDiscretisation, ModelError> {
    let splines = match plate.radial_splines {
        RadialSplines::Auto => DEFAULT_SPLINES,
        RadialSplines::Fixed(n) => n,
    };
    Ok(MindlinDiscretisation::new(&mindlin_plate(plate), splines)?)
}

/// Build the plate model of Mindlin modes (called by [`PlateModel::new`]).
pub(crate) fn build_model(plate: &PlateConfig) -> Result<PlateModel, ModelError> {
    let disc = discretisation(plate)?;
    let splines = disc.basis().len();
    let mut ks = plate.nodal_diameters.clone();
    ks.sort_unstable();
    let mut ls = plate.nodal_circles.clone();
    ls.sort_unstable();
    let orders = ls.last().map_or(1, |&l| l as usize + 1);

    let (mut radial_shapes, mut mindlin, mut entries) = (Vec::new(), Vec::new(), Vec::new());
    let (mut skipped, mut radial_resolution) = (Vec::new(), Vec::new());
    for &k in &ks {
        let modes = disc.modes(k, orders)?;
        radial_resolution.push(KResolution {
            k,
            splines,
            estimated_error: None,
        });
        for &l in &ls {
            if is_rigid_body(plate.inner_boundary, plate.outer_boundary, k, l) {
                skipped.push((k, l));
                continue;
            }
            let Some(mode) = modes.iter().find(|m| m.l == l) else {
                unreachable!("mindlin_modes returns every elastic l below orders")
            };
            entries.push(TableEntry {
                k,
                l,
                omega: mode.omega,
                radial: radial_shapes.len(),
                modal_mass: mode.modal_mass,
            });
            radial_shapes.push(mode.w.clone());
            mindlin.push(mode.clone());
        }
    }
    finish(
        plate,
        bending_rigidity(plate.youngs_modulus, plate.thickness, plate.poisson_ratio),
        Parts {
            entries,
            radial_shapes,
            skipped,
            radial_resolution,
            mindlin,
        },
    )
}
