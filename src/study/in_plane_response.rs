//! The in-plane response axis (with `plate.in_plane_nodal_diameters` and a
//! held in-plane force): the in-plane static displacement at the load against
//! the in-plane orders l = 0..l_max of the scene's nodal diameters, with and
//! without `plate.residual_flexibility`, with the stepper's cost per step.
//!
//! **Response.** The scene's space-fixed (ALE) node wrenches' in-plane forces
//! (F_x, F_y), held, at rest (Ω = 0: the in-plane spin terms change the
//! response of a spinning scene, which `notes` then says). The response is
//! the in-plane displacement (u_r, u_θ) at the first ALE node with an
//! in-plane force, read as `simulate` reads it: with the residual
//! flexibility the node's load-patch means of the retained modes
//! (`modal_kernel`, src/model/in_plane/residual.rs) plus the residual of the
//! modes left out (`residual_kernel`, the same compliance the dynamics use,
//! src/dynamics/in_plane_residual.rs); without it the modes' point values at
//! the nodes (docs/in_plane.md, "Node frames"). Each retained ⟨k, l⟩ (a
//! cos/sin pair for k ≥ 1) carries X(a) Y(b) / (ω² m) of the compliance.
//!
//! **Reference.** An in-plane point force's displacement is logarithmically
//! infinite under it, so the reference is the patch-mean response of a large
//! mode set k ≤ K, l ≤ L (the plan's `response_reference`, L capped by the
//! scene's B-splines per field) on the scene's in-plane discretisation. Its
//! own truncation error is estimated, per component, from the nested sets
//! (K/4, L/4), (K/2, L/2), (K, L) as for axis 2 (src/study/response.rs: a
//! geometric tail by Aitken times Roache's safety factor 1.25 where the
//! differences shrink by a ratio above 1.2, the larger difference otherwise).
//! With the residual the reference is (K, L) plus its residual: at rest
//! that is the static series of the discretisation (`patch_harmonics`)
//! whatever the set, so the modal truncation does not enter; its uncertainty
//! is the safety factor times the larger of its change from (K/2, L/2) and
//! its change from the static series on half as many B-splines per field
//! (twice as many where half would be below the in-plane minimum, 6).

pub use super::in_plane_compliance::InPlaneLoadCase;
use super::in_plane_compliance::{add, load_case, nested_uncertainty, relative, InPlaneStatics};
use super::response::SAFETY_FACTOR;
use super::timing::min_time_per_unit;
use super::{mark_pareto, recommend, Candidate, Recommendation, StudyError, StudyPlan};
use crate::config::{Config, RadialSplines};
use crate::dynamics::{Simulation, SimulationError};
use crate::model::in_plane::{
    self, in_plane_plate, InPlaneDiscretisation, InPlaneFamily, InPlaneTable,
};
use crate::model::ModelError;
use serde::Serialize;

/// Why the axis is absent with in-plane modes but no in-plane load (in `notes`).
pub const NO_IN_PLANE_LOAD_NOTE: &str = "in_plane_mode_count is skipped: no ALE node wrench has an in-plane force (force x or y), so the in-plane modes have no static response to compare";

/// One set: the scene's nodal diameters, orders l = 0..l_max.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct InPlaneResponseRow {
    /// Highest in-plane order l of the set (`plate.in_plane_orders` = 0..l_max).
    pub l_max: u32,
    /// In-plane modes in the set (a cos/sin pair counts two).
    pub modes: usize,
    /// (u_r, u_θ) at the point without the residual (the modes' point values), m.
    pub response_m: [f64; 2],
    /// |u − u_ref| / |u_ref| (Euclidean norms of the two components).
    pub relative_error: f64,
    /// (u_r, u_θ) with the residual (patch means plus the residual), m.
    pub response_with_residual_m: [f64; 2],
    /// Its error against the reference with its residual.
    pub relative_error_with_residual: f64,
    /// Wall time of one `Simulation::step` of the scene with this set,
    /// `plate.residual_flexibility: false`, s (None: the scene refused it; `notes`).
    pub step_time_s: Option<f64>,
    /// The same with `plate.residual_flexibility: true`, s.
    pub step_time_with_residual_s: Option<f64>,
    /// On the axis' Pareto front, without the residual.
    pub pareto: bool,
    /// On the axis' Pareto front, with the residual.
    pub pareto_with_residual: bool,
}

/// The reference set (K, L).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct InPlaneResponseReference {
    /// K: highest nodal diameter of the reference set.
    pub k_max: u32,
    /// L: highest order of the reference set.
    pub l_max: u32,
    /// B-splines per field of every mode (the scene's).
    pub radial_splines: usize,
    /// Its patch-mean (u_r, u_θ) at the point, m.
    pub response_m: [f64; 2],
    /// The same plus its residual, m.
    pub response_with_residual_m: [f64; 2],
    /// The nested sets used for the uncertainty: ((k, l), (u_r, u_θ)).
    pub nested: Vec<((u32, u32), [f64; 2])>,
    /// Estimated relative truncation error of the reference (module docs).
    pub uncertainty: f64,
    /// How that uncertainty was estimated, in words.
    pub uncertainty_method: String,
    /// Estimated relative error of the reference with its residual (module docs).
    pub uncertainty_with_residual: f64,
    /// B-splines per field of the static series that bounds that error.
    pub check_radial_splines: usize,
}

/// A setting of this axis: the in-plane orders, with or without the residual.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct InPlaneOrdersSetting {
    /// `plate.in_plane_orders` = 0..l_max (the scene's nodal diameters).
    pub l_max: u32,
    /// In-plane modes in the set.
    pub modes: usize,
    /// `plate.residual_flexibility`.
    pub residual_flexibility: bool,
}

/// The in-plane static response against the in-plane orders.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct InPlaneResponseAxis {
    /// What the axis varies, in words.
    pub what: &'static str,
    /// How the error is measured, in words.
    pub error_measure: &'static str,
    /// How the cost is measured, in words.
    pub cost_measure: &'static str,
    /// Where the response is read and which forces act.
    pub load_case: InPlaneLoadCase,
    /// The scene's `plate.in_plane_nodal_diameters` every row keeps.
    pub nodal_diameters: Vec<u32>,
    /// The reference the errors are measured against.
    pub reference: InPlaneResponseReference,
    /// One row per l_max of the plan's `l_max` (≤ L).
    pub rows: Vec<InPlaneResponseRow>,
    /// One per plan target.
    pub recommendations: Vec<Recommendation<InPlaneOrdersSetting>>,
    /// The scene's own setting (None: its orders are not 0..l_max).
    pub default_setting: Option<InPlaneOrdersSetting>,
    /// What the axis changed or left out of the scene.
    pub notes: Vec<String>,
}

/// The axis for `config` (None without in-plane modes; None and a note
/// without an in-plane force).
pub fn run(
    config: &Config,
    plan: &StudyPlan,
    tick: &mut dyn FnMut(&str),
    notes: &mut Vec<String>,
) -> Result<Option<InPlaneResponseAxis>, StudyError> {
    let plate = &config.plate;
    if plate.in_plane_nodal_diameters.is_empty() {
        return Ok(None);
    }
    let Some(case) = load_case(config) else {
        notes.push(NO_IN_PLANE_LOAD_NOTE.to_string());
        return Ok(None);
    };
    let mut axis_notes = Vec::new();
    if config.joint.speed != 0.0 {
        axis_notes.push(format!("the response is the static one at rest; the scene spins at {} rad/s, where the in-plane spin terms (Coriolis, prestress, centrifugal) change it", config.joint.speed));
    }
    if config
        .loads
        .lagrange
        .iter()
        .any(|w| w.force[..2] != [0.0; 2])
    {
        axis_notes.push(
            "Lagrangian-node in-plane forces turn with the plate: this axis leaves them out".into(),
        );
    }
    let splines = match plate.radial_splines {
        RadialSplines::Auto => in_plane::DEFAULT_SPLINES,
        RadialSplines::Fixed(n) => n,
    };
    let k_ref = plan
        .response_reference
        .0
        .max(*plate.in_plane_nodal_diameters.iter().max().unwrap_or(&0));
    // At most half the free coefficients per field are orders (two edge B-splines may go).
    let l_ref = plan.response_reference.1.min((splines as u32 - 2) / 2 - 1);
    tick(&format!(
        "in-plane reference k ≤ {k_ref}, l ≤ {l_ref}, {splines} splines per field"
    ));
    let model_error = |e| StudyError::Model(ModelError::InPlane(e));
    let disc = InPlaneDiscretisation::new(&in_plane_plate(plate, &config.centrifugal), splines)
        .map_err(model_error)?;
    let mut modes = Vec::new();
    for k in 0..=k_ref {
        for &family in InPlaneFamily::of(k) {
            modes.extend(
                disc.modes(k, family, l_ref as usize + 1)
                    .map_err(model_error)?,
            );
        }
    }
    let statics = InPlaneStatics::new(&disc, modes, &case);
    let set = |k_max: u32, l_max: u32| move |k: u32, l: u32| k <= k_max && l <= l_max;
    let nested: Vec<((u32, u32), [f64; 2])> = [4, 2, 1]
        .iter()
        .map(|&d| {
            let (k, l) = (k_ref / d, l_ref / d);
            ((k, l), statics.modal(&set(k, l), true))
        })
        .collect();
    let reference = nested[2].1;
    if !(reference[0].hypot(reference[1]) > 0.0 && reference.iter().all(|x| x.is_finite())) {
        return Err(StudyError::NoResponse {
            detail: format!("the in-plane static displacement at the load is {reference:?} m"),
        });
    }
    let (uncertainty, uncertainty_method) = nested_uncertainty(&nested);
    let reference_with_residual = add(reference, statics.residual(&set(k_ref, l_ref)));
    let (k_half, l_half) = nested[1].0;
    let half_with_residual = add(nested[1].1, statics.residual(&set(k_half, l_half)));
    // At rest modes + residual is the static series of the discretisation,
    // whatever the set: its error is the B-splines', bounded by its change
    // from half as many splines per field.
    // (Twice as many where half would be below the in-plane minimum.)
    let check_splines = if splines / 2 >= in_plane::MIN_SPLINES {
        splines / 2
    } else {
        2 * splines
    };
    let coarse = InPlaneDiscretisation::new(disc.plate(), check_splines).map_err(model_error)?;
    let coarse_static = statics.static_series(&coarse);
    let static_change = relative(coarse_static, reference_with_residual);
    let uncertainty_with_residual =
        SAFETY_FACTOR * static_change.max(relative(half_with_residual, reference_with_residual));

    let scene_k = &plate.in_plane_nodal_diameters;
    let mut rows = Vec::new();
    for &l_max in plan.l_max.iter().filter(|&&l| l <= l_ref) {
        tick(&format!("in-plane orders l ≤ {l_max}"));
        let keep = |k: u32, l: u32| scene_k.contains(&k) && l <= l_max;
        let r = statics.modal(&keep, false);
        let rc = add(statics.modal(&keep, true), statics.residual(&keep));
        let count = statics.count(&keep);
        let mut time = |with_residual| match step_time(config, l_max, with_residual, plan) {
            Ok(t) => Some(t),
            Err(e) => {
                axis_notes.push(format!("in-plane orders l ≤ {l_max} (residual flexibility {with_residual}) not timed: {e}"));
                None
            }
        };
        let times = [time(false), time(true)];
        rows.push(InPlaneResponseRow {
            l_max,
            modes: count,
            response_m: r,
            relative_error: relative(r, reference),
            response_with_residual_m: rc,
            relative_error_with_residual: relative(rc, reference_with_residual),
            step_time_s: times[0],
            step_time_with_residual_s: times[1],
            pareto: false,
            pareto_with_residual: false,
        });
    }
    mark_rows(&mut rows);
    let default_setting = default_orders(config)?;
    let recommendations = recommend(
        &plan.targets,
        rows.iter().flat_map(|r| {
            [false, true].into_iter().filter_map(|with_residual| {
                let (error, uncertainty, cost) = if with_residual {
                    (
                        r.relative_error_with_residual,
                        uncertainty_with_residual,
                        r.step_time_with_residual_s?,
                    )
                } else {
                    (r.relative_error, uncertainty, r.step_time_s?)
                };
                let setting = InPlaneOrdersSetting {
                    l_max: r.l_max,
                    modes: r.modes,
                    residual_flexibility: with_residual,
                };
                Some(Candidate {
                    error,
                    uncertainty,
                    cost,
                    is_default: default_setting.as_ref() == Some(&setting),
                    setting,
                })
            })
        }),
    );
    Ok(Some(InPlaneResponseAxis {
        what: "in-plane static displacement at the first in-plane-loaded ALE node under the held in-plane forces, at rest, against the in-plane orders l ≤ l_max of the scene's nodal diameters",
        error_measure: "|u − u_ref| / |u_ref| of (u_r, u_θ) at the node, u_ref the patch-mean response of the reference set (with the residual: plus its residual)",
        cost_measure: "wall time per Simulation::step of the scene with those in-plane orders (its integrator and rate), s",
        load_case: case,
        nodal_diameters: scene_k.clone(),
        reference: InPlaneResponseReference {
            k_max: k_ref,
            l_max: l_ref,
            radial_splines: splines,
            response_m: reference,
            response_with_residual_m: reference_with_residual,
            nested,
            uncertainty,
            uncertainty_method,
            uncertainty_with_residual,
            check_radial_splines: check_splines,
        },
        rows,
        recommendations,
        default_setting,
        notes: axis_notes,
    }))
}

/// Seconds per `Simulation::step` of the scene with in-plane orders 0..=l_max.
fn step_time(
    config: &Config,
    l_max: u32,
    residual_flexibility: bool,
    plan: &StudyPlan,
) -> Result<f64, SimulationError> {
    let mut scene = config.clone();
    scene.plate.in_plane_orders = (0..=l_max).collect();
    scene.plate.residual_flexibility = residual_flexibility;
    let mut sim = Simulation::new(scene)?;
    Ok(min_time_per_unit(plan.timing_budget, |n| {
        for _ in 0..n {
            if sim.step().is_err() {
                sim.reset();
            }
        }
    }))
}

/// Both variants of every row compete for the Pareto front; untimed ones take no part.
fn mark_rows(rows: &mut [InPlaneResponseRow]) {
    let points: Vec<(f64, f64)> = rows
        .iter()
        .map(|r| (r.relative_error, r.step_time_s.unwrap_or(f64::INFINITY)))
        .chain(rows.iter().map(|r| {
            (
                r.relative_error_with_residual,
                r.step_time_with_residual_s.unwrap_or(f64::INFINITY),
            )
        }))
        .collect();
    let front = mark_pareto(&points);
    let n = rows.len();
    for (i, r) in rows.iter_mut().enumerate() {
        r.pareto = front[i] && r.step_time_s.is_some();
        r.pareto_with_residual = front[n + i] && r.step_time_with_residual_s.is_some();
    }
}

/// The scene's own orders and `plate.residual_flexibility`, if its orders are 0..l_max.
fn default_orders(config: &Config) -> Result<Option<InPlaneOrdersSetting>, StudyError> {
    let orders = &config.plate.in_plane_orders;
    let Some(&l_max) = orders.iter().max() else {
        return Ok(None);
    };
    if !orders.iter().copied().eq(0..=l_max) {
        return Ok(None);
    }
    let table = InPlaneTable::new(&config.plate, &config.centrifugal)
        .map_err(|e| StudyError::Model(ModelError::InPlane(e)))?;
    Ok(Some(InPlaneOrdersSetting {
        l_max,
        modes: table.entries.len(),
        residual_flexibility: config.plate.residual_flexibility,
    }))
}
