//! The plate theory as a lever: model error against cost.
//!
//! The scene's requested ⟨k, l⟩ under Kirchhoff and under Mindlin theory
//! (`plate.theory`, docs/mindlin.md) with the same edges, material and
//! `plate.shear_correction`. Mindlin theory is within 0.1–0.9 % of 3-D
//! elasticity for a disc as thick as the bench's (docs/mindlin.md), so
//! Kirchhoff's error is measured against it: e = f_Kirchhoff / f_Mindlin − 1
//! per ⟨k, l⟩.
//!
//! **Reference.** The converged Mindlin frequencies: 120 B-splines per field
//! (`auto`), their uncertainty the larger relative difference from 60 and
//! from 240 per field (discretisation error and round-off,
//! as axis 1 checks its reference). **Kirchhoff** is built as the scene runs it (its
//! `plate.radial_splines`; `auto` when the scene is a Mindlin scene).
//! **Cost**: each theory's model build time (`PlateModel::new` of the scene's
//! mode set, the fastest of repeats, as axis 1 times it), Mindlin at the
//! scene's `plate.radial_splines` if the scene is Mindlin, else `auto`.
//! An edge Kirchhoff theory lacks (`supported_soft`) leaves its side empty.

use super::frequency::{omegas, reference, ModeId};
use super::timing::min_time;
use super::{StudyError, StudyPlan};
use crate::config::{Boundary, PlateConfig, PlateTheory, RadialSplines};
use crate::model::{mindlin, PlateModel};
use serde::Serialize;
use std::f64::consts::TAU;

/// One ⟨k, l⟩ under both theories.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct TheoryRow {
    /// The mode.
    pub mode: ModeId,
    /// Kirchhoff frequency, Hz (None: the edges have no Kirchhoff model).
    pub kirchhoff_hz: Option<f64>,
    /// Converged Mindlin frequency, Hz (the reference).
    pub mindlin_hz: f64,
    /// f_Kirchhoff / f_Mindlin − 1.
    pub kirchhoff_error: Option<f64>,
}

/// What one theory's model costs.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct TheoryCost {
    /// `kirchhoff` or `mindlin`.
    pub theory: &'static str,
    /// The `plate.radial_splines` it was built with (per field under Mindlin theory).
    pub radial_splines: RadialSplines,
    /// Model build time (`PlateModel::new`), s: the fastest of repeated builds.
    pub build_time_s: f64,
}

/// The Mindlin reference.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct MindlinReference {
    /// B-splines per field of the reference.
    pub radial_splines: usize,
    /// The coarser and the finer check (per field).
    pub check_radial_splines: [usize; 2],
    /// Largest relative difference of the reference from either check.
    pub uncertainty: f64,
}

/// Kirchhoff against Mindlin theory on the scene's modes.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct TheoryComparison {
    /// What is compared, in words.
    pub what: &'static str,
    /// How the error is measured, in words.
    pub error_measure: &'static str,
    /// How the cost is measured, in words.
    pub cost_measure: &'static str,
    /// The scene's `plate.theory`.
    pub scene_theory: &'static str,
    /// κ of both Mindlin models (`plate.shear_correction`).
    pub shear_correction: f64,
    /// The converged Mindlin frequencies' model and uncertainty.
    pub mindlin_reference: MindlinReference,
    /// The scene's ⟨k, l⟩, ascending in Mindlin frequency.
    pub rows: Vec<TheoryRow>,
    /// The largest |f_Kirchhoff / f_Mindlin − 1| over the rows.
    pub max_kirchhoff_error: Option<f64>,
    /// Where it occurs.
    pub worst_mode: Option<ModeId>,
    /// Kirchhoff's model (None: the edges have no Kirchhoff model).
    pub kirchhoff: Option<TheoryCost>,
    /// Mindlin's model.
    pub mindlin: TheoryCost,
    /// Mindlin's build time over Kirchhoff's.
    pub mindlin_cost_ratio: Option<f64>,
    /// Why a side is missing, if one is.
    pub note: Option<String>,
}

fn with(plate: &PlateConfig, theory: PlateTheory, splines: RadialSplines) -> PlateConfig {
    let mut p = plate.clone();
    p.theory = theory;
    p.radial_splines = splines;
    p
}

fn cost(plate: &PlateConfig, plan: &StudyPlan) -> Result<(PlateModel, TheoryCost), StudyError> {
    let model = PlateModel::new(plate)?;
    let build_time_s = min_time(plan.timing_budget, 3, 10_000, || {
        std::hint::black_box(PlateModel::new(std::hint::black_box(plate)).ok());
    });
    let cost = TheoryCost {
        theory: plate.theory.name(),
        radial_splines: plate.radial_splines,
        build_time_s,
    };
    Ok((model, cost))
}

pub(crate) fn run(
    plate: &PlateConfig,
    plan: &StudyPlan,
    tick: &mut dyn FnMut(&str),
) -> Result<TheoryComparison, StudyError> {
    tick("Kirchhoff and Mindlin theory");
    let own = |theory| {
        if plate.theory == theory {
            plate.radial_splines
        } else {
            RadialSplines::Auto
        }
    };
    let n = mindlin::DEFAULT_SPLINES;
    let mindlin_plate = with(plate, PlateTheory::Mindlin, own(PlateTheory::Mindlin));
    let (w_ref, uncertainty) = reference(&mindlin_plate, n, n / 2, Some(2 * n))?;
    let (_, mindlin) = cost(&mindlin_plate, plan)?;
    let soft = [plate.inner_boundary, plate.outer_boundary].contains(&Boundary::SupportedSoft);
    let (kirchhoff, note) = if soft {
        (
            None,
            Some(
                "the edge supported_soft has no Kirchhoff model: Kirchhoff's side is empty"
                    .to_string(),
            ),
        )
    } else {
        let kirchhoff_plate = with(plate, PlateTheory::Kirchhoff, own(PlateTheory::Kirchhoff));
        (Some(cost(&kirchhoff_plate, plan)?), None)
    };
    let w_kirchhoff = kirchhoff.as_ref().map(|(m, _)| omegas(m));
    let mut rows: Vec<TheoryRow> = w_ref
        .iter()
        .map(|(&(k, l), &w_m)| {
            let w_k = w_kirchhoff.as_ref().and_then(|w| w.get(&(k, l)).copied());
            TheoryRow {
                mode: ModeId { k, l },
                kirchhoff_hz: w_k.map(|w| w / TAU),
                mindlin_hz: w_m / TAU,
                kirchhoff_error: w_k.map(|w| w / w_m - 1.0),
            }
        })
        .collect();
    rows.sort_by(|a, b| a.mindlin_hz.total_cmp(&b.mindlin_hz));
    let worst = rows
        .iter()
        .filter_map(|r| r.kirchhoff_error.map(|e| (e.abs(), r.mode)))
        .max_by(|a, b| a.0.total_cmp(&b.0));
    let kirchhoff = kirchhoff.map(|(_, c)| c);
    Ok(TheoryComparison {
        what: "the scene's ⟨k, l⟩ under plate.theory kirchhoff and mindlin, same edges",
        error_measure:
            "f_Kirchhoff / f_Mindlin − 1 per ⟨k, l⟩, f_Mindlin the converged Mindlin frequency",
        cost_measure: "model build time (PlateModel::new) of the scene's modes, s",
        scene_theory: plate.theory.name(),
        shear_correction: plate.shear_correction,
        mindlin_reference: MindlinReference {
            radial_splines: n,
            check_radial_splines: [n / 2, 2 * n],
            uncertainty,
        },
        rows,
        max_kirchhoff_error: worst.map(|w| w.0),
        worst_mode: worst.map(|w| w.1),
        mindlin_cost_ratio: kirchhoff
            .as_ref()
            .map(|k| mindlin.build_time_s / k.build_time_s),
        kirchhoff,
        mindlin,
        note,
    })
}
