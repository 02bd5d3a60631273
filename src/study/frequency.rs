//! Axis 1: natural-frequency error against `plate.radial_splines`, with the
//! model build time.
//!
//! For each spline count, and for `auto` (per k the count whose estimated
//! error reaches `plate.frequency_tolerance`, the default; under Mindlin
//! theory 120 per field), the plate's requested ⟨k, l⟩ are computed and compared
//! with a reference model of the same plate at `spline_reference_factor` × the
//! largest count studied. The reference's own error is bounded by its
//! difference from a model at half its spline count: the Ritz frequencies
//! converge from above at O(n⁻⁴), so that difference is ≈ 15× the reference's
//! discretisation error — as long as round-off does not dominate, which it
//! does beyond ~128 splines (docs/study.md), hence the full plan's factor 2.
//! Under Mindlin theory the counts are per field (w, ψ_r, ψ_θ) and the
//! reference is chosen and checked as [`reference_splines`] says.

use super::timing::min_time;
use super::{mark_pareto, recommend, Candidate, Recommendation, StudyError, StudyPlan};
use crate::config::{PlateConfig, PlateTheory, RadialSplines};
use crate::model::{mindlin, PlateModel};
use serde::Serialize;
use std::collections::BTreeMap;

/// ⟨k, l⟩ of a mode.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub struct ModeId {
    /// Nodal diameters.
    pub k: u32,
    /// Nodal circles.
    pub l: u32,
}

/// One spline count.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct FrequencyRow {
    /// A fixed count, or `auto` (per k the count reaching `plate.frequency_tolerance`).
    pub radial_splines: RadialSplines,
    /// max over the requested ⟨k, l⟩ of |f − f_ref| / f_ref.
    pub max_relative_error: f64,
    /// Where that maximum occurs.
    pub worst_mode: ModeId,
    /// Model build time (`PlateModel::new`), s: the fastest of repeated builds.
    pub build_time_s: f64,
    /// On the error-vs-time Pareto front of this axis.
    pub pareto: bool,
}

/// The reference model.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct FrequencyReference {
    /// Radial splines of the reference model (per field under Mindlin theory).
    pub radial_splines: usize,
    /// The half-resolution model used to bound the reference's own error.
    pub check_radial_splines: usize,
    /// Under Mindlin theory, the double-resolution model that also bounds it
    /// (its round-off; absent under Kirchhoff theory).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub finer_check_radial_splines: Option<usize>,
    /// max relative |f_ref − f_check| / f_ref (under Mindlin theory the larger
    /// of both checks'): an upper bound of the reference's error.
    pub uncertainty: f64,
    /// The reference frequencies, Hz, per ⟨k, l⟩ (each pair listed once).
    pub frequencies_hz: Vec<(ModeId, f64)>,
}

/// A setting of this axis: `plate.radial_splines`.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct FrequencySetting {
    /// A fixed count or `auto`.
    pub radial_splines: RadialSplines,
}

/// Axis 1: natural-frequency error against `plate.radial_splines`, cost = model build time.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct FrequencyAxis {
    /// What the axis varies, in words.
    pub what: &'static str,
    /// How the error is measured, in words.
    pub error_measure: &'static str,
    /// How the cost is measured, in words.
    pub cost_measure: &'static str,
    /// The reference model the errors are measured against.
    pub reference: FrequencyReference,
    /// One row per spline count measured (`auto` included).
    pub rows: Vec<FrequencyRow>,
    /// One per plan target.
    pub recommendations: Vec<Recommendation<FrequencySetting>>,
    /// The scene's own `plate.radial_splines`.
    pub default_setting: FrequencySetting,
}

/// Frequencies (rad/s) per ⟨k, l⟩.
pub(crate) type Omegas = BTreeMap<(u32, u32), f64>;

/// Frequencies (rad/s) per ⟨k, l⟩ of a model.
pub(crate) fn omegas(model: &PlateModel) -> Omegas {
    model
        .radial_shapes()
        .iter()
        .map(|s| ((s.k, s.l), s.omega))
        .collect()
}

fn with_splines(plate: &PlateConfig, n: usize) -> PlateConfig {
    let mut p = plate.clone();
    p.radial_splines = RadialSplines::Fixed(n);
    p
}

/// max over the modes of `reference` of |got − ref| / ref, and where (the
/// first key when nothing differs; `reference` is not empty).
pub(crate) fn max_error<K: Ord + Copy>(
    got: &BTreeMap<K, f64>,
    reference: &BTreeMap<K, f64>,
) -> (f64, K) {
    let first = *reference.keys().next().expect("a requested mode");
    let mut worst = (-1.0, first);
    for (&id, &w_ref) in reference {
        let e = (got[&id] - w_ref).abs() / w_ref;
        if e > worst.0 {
            worst = (e, id);
        }
    }
    worst
}

/// The spline counts studied for this plate: the plan's, less those below
/// the plate's minimum (highest requested nodal circle and edge conditions).
pub(crate) fn spline_grid(plate: &PlateConfig, plan: &StudyPlan) -> Vec<usize> {
    let min = match plate.theory {
        PlateTheory::Kirchhoff => plate.min_radial_splines(),
        PlateTheory::Mindlin => plate.min_radial_splines().max(mindlin::MIN_SPLINES),
    };
    let mut grid: Vec<usize> = plan.splines.iter().copied().filter(|&n| n >= min).collect();
    if grid.is_empty() {
        grid = vec![min, 2 * min, 4 * min];
    }
    grid.sort_unstable();
    grid.dedup();
    grid
}

/// The reference's spline count and, under Mindlin theory, its finer check.
///
/// Kirchhoff: `spline_reference_factor` × the largest count (at most 400).
/// Mindlin: 2 × the largest count, at most [`mindlin::DEFAULT_SPLINES`]
/// (`auto`'s 120 per field) — beyond about 100 per field round-off outgrows
/// the discretisation error (bench disc, k ≤ 4, l ≤ 1, against the exact
/// roots: 64: 1.3e-8, 96: 5.9e-9, 120: 1.9e-8, 240: 1.4e-7; docs/study.md),
/// so the reference is also checked against twice its count, which shows
/// that round-off.
fn reference_splines(
    plate: &PlateConfig,
    plan: &StudyPlan,
    largest: usize,
) -> (usize, Option<usize>) {
    match plate.theory {
        PlateTheory::Kirchhoff => (
            (plan.spline_reference_factor * largest).min(crate::study::MAX_RADIAL_SPLINES),
            None,
        ),
        PlateTheory::Mindlin => {
            let n = (2 * largest).min(mindlin::DEFAULT_SPLINES);
            (n, Some((2 * n).min(crate::study::MAX_RADIAL_SPLINES)))
        }
    }
}

/// The reference frequencies per ⟨k, l⟩ at `splines` and their uncertainty:
/// the largest relative difference from the model at `check` (and at `finer`).
pub(crate) fn reference(
    plate: &PlateConfig,
    splines: usize,
    check: usize,
    finer: Option<usize>,
) -> Result<(Omegas, f64), StudyError> {
    let w_ref = omegas(&PlateModel::new(&with_splines(plate, splines))?);
    let (mut uncertainty, _) = max_error(
        &omegas(&PlateModel::new(&with_splines(plate, check))?),
        &w_ref,
    );
    if let Some(n) = finer {
        let (e, _) = max_error(&omegas(&PlateModel::new(&with_splines(plate, n))?), &w_ref);
        uncertainty = uncertainty.max(e);
    }
    Ok((w_ref, uncertainty))
}

pub(crate) fn run(
    plate: &PlateConfig,
    plan: &StudyPlan,
    tick: &mut dyn FnMut(&str),
) -> Result<FrequencyAxis, StudyError> {
    let grid = spline_grid(plate, plan);
    let largest = *grid.last().ok_or(StudyError::EmptyGrid {
        axis: "radial_splines",
    })?;
    let (reference_splines, finer_check) = reference_splines(plate, plan, largest);
    let check_splines = reference_splines / 2;
    tick(&format!(
        "reference model, {reference_splines} radial splines"
    ));
    let (w_ref, uncertainty) = reference(plate, reference_splines, check_splines, finer_check)?;

    let mut rows = Vec::new();
    let settings = grid
        .iter()
        .map(|&n| RadialSplines::Fixed(n))
        .chain(std::iter::once(RadialSplines::Auto));
    for setting in settings {
        tick(&format!("{setting} radial splines"));
        let mut p = plate.clone();
        p.radial_splines = setting;
        let model = PlateModel::new(&p)?;
        let (e, (k, l)) = max_error(&omegas(&model), &w_ref);
        let build_time_s = min_time(plan.timing_budget, 3, 10_000, || {
            std::hint::black_box(PlateModel::new(std::hint::black_box(&p)).ok());
        });
        rows.push(FrequencyRow {
            radial_splines: setting,
            max_relative_error: e,
            worst_mode: ModeId { k, l },
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
    Ok(FrequencyAxis {
        what: "natural-frequency error of the requested ⟨k, l⟩ against plate.radial_splines",
        error_measure:
            "max over the requested ⟨k, l⟩ of |f − f_ref| / f_ref, f_ref from the reference model",
        cost_measure: "model build time (PlateModel::new), s",
        reference: FrequencyReference {
            radial_splines: reference_splines,
            check_radial_splines: check_splines,
            finer_check_radial_splines: finer_check,
            uncertainty,
            frequencies_hz: w_ref
                .iter()
                .map(|(&(k, l), &w)| (ModeId { k, l }, w / std::f64::consts::TAU))
                .collect(),
        },
        rows,
        recommendations,
        default_setting: FrequencySetting {
            radial_splines: plate.radial_splines,
        },
    })
}
