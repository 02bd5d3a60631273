//! The in-plane frequency axis (with `plate.in_plane_nodal_diameters`):
//! the in-plane modes' frequency error against `plate.radial_splines` (the
//! B-splines per field of the plane-stress discretisation, `auto`: 60), with
//! the in-plane table's build time.
//!
//! As axis 1 does for the bending modes, each requested in-plane ⟨k, l⟩
//! (per family at k = 0) is compared with a reference table of the same
//! plate at `spline_reference_factor` × the largest count studied (capped at
//! the in-plane maximum), whose own error is bounded by its difference from
//! the table at half its count: the Ritz frequencies converge from above.

use super::frequency::{max_error, spline_grid, FrequencySetting};
use super::timing::min_time;
use super::{mark_pareto, recommend, Candidate, Recommendation, StudyError, StudyPlan};
use crate::config::{CentrifugalConfig, PlateConfig, RadialSplines};
use crate::model::in_plane::{self, InPlaneShape, InPlaneTable};
use crate::model::ModelError;
use serde::Serialize;
use std::collections::BTreeMap;

/// An in-plane mode: ⟨k, l⟩ and its family (`torsional`, `radial`, `coupled`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Serialize)]
pub struct InPlaneModeId {
    /// Nodal diameters.
    pub k: u32,
    /// Order in ascending frequency for k and family.
    pub l: u32,
    /// `torsional` or `radial` (k = 0), `coupled` (k ≥ 1).
    pub family: &'static str,
}

/// One spline count.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct InPlaneFrequencyRow {
    /// A fixed count per field, or `auto` (60).
    pub radial_splines: RadialSplines,
    /// max over the requested in-plane modes of |f − f_ref| / f_ref.
    pub max_relative_error: f64,
    /// Where that maximum occurs.
    pub worst_mode: InPlaneModeId,
    /// Build time of the in-plane table (`InPlaneTable::new`), s.
    pub build_time_s: f64,
    /// On the error-vs-time Pareto front of this axis.
    pub pareto: bool,
}

/// The reference table.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct InPlaneFrequencyReference {
    /// B-splines per field of the reference.
    pub radial_splines: usize,
    /// The half-resolution table that bounds the reference's error.
    pub check_radial_splines: usize,
    /// max relative |f_ref − f_check| / f_ref: an upper bound of its error.
    pub uncertainty: f64,
    /// The reference frequencies, Hz.
    pub frequencies_hz: Vec<(InPlaneModeId, f64)>,
}

/// The in-plane frequency error against `plate.radial_splines`.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct InPlaneFrequencyAxis {
    /// What the axis varies, in words.
    pub what: &'static str,
    /// How the error is measured, in words.
    pub error_measure: &'static str,
    /// How the cost is measured, in words.
    pub cost_measure: &'static str,
    /// The reference table the errors are measured against.
    pub reference: InPlaneFrequencyReference,
    /// One row per spline count measured (`auto` included).
    pub rows: Vec<InPlaneFrequencyRow>,
    /// One per plan target.
    pub recommendations: Vec<Recommendation<FrequencySetting>>,
    /// The scene's own `plate.radial_splines`.
    pub default_setting: FrequencySetting,
}

/// Frequencies (rad/s) per in-plane mode (a cos/sin pair once).
type Omegas = BTreeMap<InPlaneModeId, f64>;

fn table(
    plate: &PlateConfig,
    edges: &CentrifugalConfig,
    splines: RadialSplines,
) -> Result<InPlaneTable, StudyError> {
    let mut p = plate.clone();
    p.radial_splines = splines;
    InPlaneTable::new(&p, edges).map_err(|e| StudyError::Model(ModelError::InPlane(e)))
}

fn omegas(t: &InPlaneTable) -> Omegas {
    t.entries
        .iter()
        .map(|e| {
            let family = match e.shape {
                InPlaneShape::Torsional => "torsional",
                InPlaneShape::Radial => "radial",
                InPlaneShape::Cos | InPlaneShape::Sin => "coupled",
            };
            let id = InPlaneModeId {
                k: e.k,
                l: e.l,
                family,
            };
            (id, e.omega)
        })
        .collect()
}

/// The axis for `plate` with in-plane edges `edges` (None without in-plane modes).
pub(crate) fn run(
    plate: &PlateConfig,
    edges: &CentrifugalConfig,
    plan: &StudyPlan,
    tick: &mut dyn FnMut(&str),
) -> Result<Option<InPlaneFrequencyAxis>, StudyError> {
    if plate.in_plane_nodal_diameters.is_empty() {
        return Ok(None);
    }
    let grid: Vec<usize> = spline_grid(plate, plan)
        .into_iter()
        .filter(|&n| n >= in_plane::MIN_SPLINES)
        .collect();
    let largest = *grid.last().ok_or(StudyError::EmptyGrid {
        axis: "in-plane radial_splines",
    })?;
    let reference_splines = (plan.spline_reference_factor * largest).min(in_plane::MAX_SPLINES);
    let check_splines = reference_splines / 2;
    tick(&format!(
        "in-plane reference, {reference_splines} splines per field"
    ));
    let w_ref = omegas(&table(
        plate,
        edges,
        RadialSplines::Fixed(reference_splines),
    )?);
    if w_ref.is_empty() {
        return Ok(None);
    }
    let check = omegas(&table(plate, edges, RadialSplines::Fixed(check_splines))?);
    let (uncertainty, _) = max_error(&check, &w_ref);
    let mut rows = Vec::new();
    let settings = grid
        .iter()
        .map(|&n| RadialSplines::Fixed(n))
        .chain(std::iter::once(RadialSplines::Auto));
    for setting in settings {
        tick(&format!("in-plane {setting} splines"));
        let (e, worst) = max_error(&omegas(&table(plate, edges, setting)?), &w_ref);
        let build_time_s = min_time(plan.timing_budget, 3, 10_000, || {
            std::hint::black_box(table(plate, edges, setting).ok());
        });
        rows.push(InPlaneFrequencyRow {
            radial_splines: setting,
            max_relative_error: e,
            worst_mode: worst,
            build_time_s,
            pareto: false,
        });
    }
    let points: Vec<(f64, f64)> = rows
        .iter()
        .map(|r| (r.max_relative_error, r.build_time_s))
        .collect();
    for (r, p) in rows.iter_mut().zip(mark_pareto(&points)) {
        r.pareto = p;
    }
    let recommendations = recommend(
        &plan.targets,
        rows.iter().map(|r| Candidate {
            error: r.max_relative_error,
            uncertainty,
            cost: r.build_time_s,
            setting: FrequencySetting {
                radial_splines: r.radial_splines,
            },
            is_default: r.radial_splines == plate.radial_splines,
        }),
    );
    Ok(Some(InPlaneFrequencyAxis {
        what: "natural-frequency error of the requested in-plane modes against plate.radial_splines (B-splines per field)",
        error_measure: "max over the requested in-plane ⟨k, l⟩ (per family) of |f − f_ref| / f_ref, f_ref from the reference table",
        cost_measure: "build time of the in-plane mode table (InPlaneTable::new), s",
        reference: InPlaneFrequencyReference {
            radial_splines: reference_splines,
            check_radial_splines: check_splines,
            uncertainty,
            frequencies_hz: w_ref
                .iter()
                .map(|(id, &w)| (*id, w / std::f64::consts::TAU))
                .collect(),
        },
        rows,
        recommendations,
        default_setting: FrequencySetting {
            radial_splines: plate.radial_splines,
        },
    }))
}
