//! Building the model (paper 3.1): per nodal-diameter number k the radial
//! B-spline discretisation, its eigenproblem, the mode table sorted by
//! frequency, and the body data of eq. (11).

use super::body::BodyData;
use super::eigen::{lowest_modes, EigenPairs};
use super::modes::{is_rigid_body, radial_moment, AngularShape, Mode, RadialShape};
use super::radial::{angular_norm, RadialDiscretisation};
use super::resolution::{self, KResolution, Resolved};
use super::{bending_rigidity, ModelError, PlateModel};
use crate::config::{PlateConfig, PlateTheory, RadialSplines};

/// Build the plate model (called by [`PlateModel::new`]).
pub(super) fn build(plate: &PlateConfig) -> Result<PlateModel, ModelError> {
    if plate.theory == PlateTheory::Mindlin {
        return super::mindlin::build_model(plate);
    }
    let nu = plate.poisson_ratio;
    let rigidity = bending_rigidity(plate.youngs_modulus, plate.thickness, nu);
    let rho_h = plate.density * plate.thickness;
    let max_l = plate.nodal_circles.iter().copied().max().unwrap_or(0);
    if let RadialSplines::Fixed(splines) = plate.radial_splines {
        if splines < plate.min_radial_splines() {
            return Err(ModelError::TooFewRadialSplines {
                splines,
                bc_inner: plate.inner_boundary.name(),
                bc_outer: plate.outer_boundary.name(),
                max_l,
                min_splines: plate.min_radial_splines(),
            });
        }
    }
    let sigma = eigen_shift(plate, rigidity);

    let mut ks: Vec<u32> = plate.nodal_diameters.clone();
    ks.sort_unstable();
    let mut ls: Vec<u32> = plate.nodal_circles.clone();
    ls.sort_unstable();

    let mut radial_shapes = Vec::new();
    let mut skipped = Vec::new();
    let mut radial_resolution = Vec::new();
    let mut entries: Vec<TableEntry> = Vec::new();
    let count = max_l as usize + 1;
    // `auto`: every k's count and eigenpairs first (resolution.rs); fixed: one basis for all k.
    let fixed_disc = plate
        .radial_splines
        .fixed()
        .map(|n| RadialDiscretisation::new(plate, rigidity, n));
    let (mut chosen, mut discs) = match fixed_disc {
        Some(_) => (
            Vec::new(),
            resolution::Discretisations::new(plate, rigidity),
        ),
        None => resolution::choose_all(plate, rigidity, sigma, &ks, count)?,
    };
    chosen.reverse();
    for &k in &ks {
        let (splines, pairs) = match &fixed_disc {
            Some(disc) => {
                radial_resolution.push(KResolution {
                    k,
                    splines: plate.radial_splines.fixed().unwrap_or(0),
                    estimated_error: None,
                });
                (None, fixed(disc, k, sigma, count)?)
            }
            None => {
                let Some(Resolved { pairs, resolution }) = chosen.pop() else {
                    unreachable!("one resolution per k")
                };
                radial_resolution.push(resolution);
                (Some(resolution.splines), pairs)
            }
        };
        let disc = match (splines, &fixed_disc) {
            (Some(splines), _) => discs.get(splines),
            (None, Some(disc)) => disc,
            (None, None) => unreachable!("a fixed count has its discretisation"),
        };
        for &l in &ls {
            if is_rigid_body(plate.inner_boundary, plate.outer_boundary, k, l) {
                skipped.push((k, l));
                continue;
            }
            let w2 = pairs.omega_squared[l as usize];
            if !w2.is_finite() || w2 <= 0.0 {
                return Err(ModelError::NonFiniteMode {
                    k,
                    l,
                    omega_squared: w2,
                    hint: degenerate_hint(plate),
                });
            }
            let col = pairs.vectors.col(l as usize);
            let coefficients = disc.expand((0..col.nrows()).map(|i| col[i]));
            let mut shape = RadialShape {
                k,
                l,
                omega: w2.sqrt(),
                basis: disc.basis.clone(),
                coefficients,
            };
            let (_, peak) = shape.peak();
            if peak == 0.0 || !peak.is_finite() {
                return Err(ModelError::NonFiniteMode {
                    k,
                    l,
                    omega_squared: w2,
                    hint: degenerate_hint(plate),
                });
            }
            shape.coefficients.iter_mut().for_each(|c| *c /= peak);
            // The eigenvector was M̄-normalised (M̄ includes ρh c_k): modal mass of the unit-peak shape.
            let modal_mass = 1.0 / (peak * peak);
            debug_assert!(
                (modal_mass - rho_h * angular_norm(k) * radial_moment(&shape, 2, 1)).abs()
                    < 1e-6 * modal_mass
            );
            radial_shapes.push(shape);
            entries.push(TableEntry {
                k,
                l,
                omega: w2.sqrt(),
                radial: radial_shapes.len() - 1,
                modal_mass,
            });
        }
    }
    finish(
        plate,
        rigidity,
        Parts {
            entries,
            radial_shapes,
            skipped,
            radial_resolution,
            mindlin: Vec::new(),
        },
    )
}

/// What a theory's build hands to [`finish`].
pub(super) struct Parts {
    pub entries: Vec<TableEntry>,
    pub radial_shapes: Vec<RadialShape>,
    pub skipped: Vec<(u32, u32)>,
    pub radial_resolution: Vec<KResolution>,
    pub mindlin: Vec<super::mindlin::MindlinMode>,
}

/// The model of the elastic ⟨k, l⟩: the mode table and the body data.
pub(super) fn finish(
    plate: &PlateConfig,
    rigidity: f64,
    parts: Parts,
) -> Result<PlateModel, ModelError> {
    if parts.entries.is_empty() {
        return Err(ModelError::NoElasticModes {
            skipped: parts.skipped,
        });
    }
    let modes = mode_table(plate, &parts.entries);
    let body = BodyData::new(plate, &modes, &parts.radial_shapes, &parts.mindlin);
    Ok(PlateModel {
        plate: plate.clone(),
        rigidity,
        modes,
        radial_shapes: parts.radial_shapes,
        skipped_rigid_body_modes: parts.skipped,
        body,
        radial_resolution: parts.radial_resolution,
        mindlin: parts.mindlin,
    })
}

/// One elastic ⟨k, l⟩ of the mode table: its ω, radial shape and modal mass.
pub(super) struct TableEntry {
    pub k: u32,
    pub l: u32,
    pub omega: f64,
    pub radial: usize,
    pub modal_mass: f64,
}

/// The mode table (`modes`): one mode per k = 0 entry, a cos/sin pair
/// otherwise, sorted by frequency, with damping and partners.
pub(super) fn mode_table(plate: &PlateConfig, entries: &[TableEntry]) -> Vec<Mode> {
    // Expand into modes: one per k = 0, a cos/sin pair otherwise; sort by frequency, then k, then cos before sin.
    let mut modes: Vec<Mode> = Vec::new();
    for e in entries {
        let shapes: &[AngularShape] = if e.k == 0 {
            &[AngularShape::Axisymmetric]
        } else {
            &[AngularShape::Cos, AngularShape::Sin]
        };
        for &shape in shapes {
            modes.push(Mode {
                k: e.k,
                l: e.l,
                shape,
                omega: e.omega,
                frequency_hz: e.omega / std::f64::consts::TAU,
                modal_mass: e.modal_mass,
                damping: 0.0,
                radial: e.radial,
                partner: None,
            });
        }
    }
    modes.sort_by(|a, b| {
        a.omega
            .total_cmp(&b.omega)
            .then(a.k.cmp(&b.k))
            .then(a.shape.cmp(&b.shape))
            .then(a.l.cmp(&b.l))
    });
    for i in 0..modes.len() {
        modes[i].damping = if plate.damping.len() == 1 {
            plate.damping[0]
        } else {
            plate.damping.get(i).copied().unwrap_or(0.0)
        };
        if modes[i].k > 0 {
            modes[i].partner = modes
                .iter()
                .position(|m| m.k == modes[i].k && m.l == modes[i].l && m.shape != modes[i].shape);
        }
    }
    modes
}

/// A fixed spline count: the dense eigenproblem of k on the shared basis.
fn fixed(
    disc: &RadialDiscretisation,
    k: u32,
    sigma: f64,
    count: usize,
) -> Result<EigenPairs, ModelError> {
    let (kk, mm) = disc.assemble(k);
    lowest_modes(&kk, &mm, sigma, count).map_err(|e| e.for_k(k))
}

/// The shift σ of the eigenproblem (ω² scale): a stiffness scale between
/// the width and the outer radius.
pub(super) fn eigen_shift(plate: &PlateConfig, rigidity: f64) -> f64 {
    let width = plate.outer_radius - plate.inner_radius;
    rigidity
        / (plate.density
            * plate.thickness
            * width
            * width
            * plate.outer_radius
            * plate.outer_radius)
}

fn degenerate_hint(plate: &PlateConfig) -> String {
    let ratio = plate.inner_radius / plate.outer_radius;
    if ratio < 1e-3 {
        format!("r_i/r_a = {ratio:e}: near the circular-plate limit of paper section 4.2")
    } else if 1.0 - ratio < 1e-2 {
        format!("r_i/r_a = {ratio}: near the narrow-ring limit of paper section 4.2")
    } else {
        "check thickness, moduli and density for extreme values".into()
    }
}
