//! Axis 2: the steady response at the load point against the mode count
//! (k = 0..k_max, l = 0..l_max), with the stepper's cost per step.
//!
//! **Response.** The scene's space-fixed (ALE) node wrenches, held, at the
//! scene's constant joint speed Ω: each ALE mode pair settles at
//! [(ω² − k²Ω²) I − 2ζωkΩ J] q̄ = f̄ / m (docs/dynamics.md), a k = 0 mode at
//! q̄ = f̄ / (m ω²); at Ω = 0 this is the static deflection. The response is the
//! deflection Σ w_i q̄_i at the load point. It is what `simulate` settles to
//! (asserted in `tests/study_recommendations_hold.rs` by running the stepper).
//!
//! **Why this axis.** Under a point load the harmonics k decay only like k⁻³
//! (docs/static_convergence.md), so the truncation error falls like k_max⁻²
//! and higher k also need more nodal circles l.
//!
//! **Reference.** Every ⟨k, l⟩ mode is the same whichever others are requested
//! (one eigenproblem per k on the full radial basis), so one large model with
//! k ≤ K, l ≤ L gives the response of every rectangular set by partial sums.
//! The reference is the set (K, L) itself. Its own truncation error is
//! estimated from the nested sets (K/4, L/4), (K/2, L/2), (K, L): with
//! differences d₁, d₂ and ratio ρ = d₁/d₂ > 1.2 (same sign) the remaining tail
//! is ≈ d₂/(ρ − 1) (geometric, Aitken); times the safety factor 1.25 of a
//! three-level grid-convergence index (Roache) that is the uncertainty;
//! otherwise the larger difference is taken. The uncertainty is added to every
//! error before a setting is recommended.
//!
//! **With residual flexibility** (`plate.residual_flexibility`,
//! docs/residual_flexibility.md): each set's response plus the static
//! deflection of the modes it leaves out under the loads' transverse forces
//! (moments stay modal), against the reference plus its own residual. Its
//! uncertainty is the larger of the modal reference's (the correction replaces
//! the tail that uncertainty bounds) and the safety factor times the change of
//! the corrected response from the nested set (K/2, L/2) to (K, L) (what the
//! spin does to the left-out modes). Both variants of every set are timed and
//! compete for every target: each set once with the correction off, once on.

use super::timing::min_time_per_unit;
use super::{mark_pareto, recommend, Candidate, Recommendation, StudyError, StudyPlan};
use crate::config::{Config, IntegratorKind, NodePosition, RadialSplines, WrenchConfig};
use crate::dynamics::{Simulation, SimulationError};
use crate::model::{AngularShape, PlateModel};
use serde::Serialize;
use std::f64::consts::TAU;

/// Safety factor on the estimated tail of the reference (Roache's GCI, three levels).
pub(crate) const SAFETY_FACTOR: f64 = 1.25;

/// Where the response is read and which wrenches act.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct LoadCase {
    /// ξ of the point where the response is read (the first loaded ALE node).
    pub point: NodePosition,
    /// 1-based ALE node number of that point (in the scene the axis runs on).
    pub ale_node: usize,
    /// The ALE nodes and their wrenches (fx fy fz mx my mz in the node frame).
    pub loads: Vec<(NodePosition, [f64; 6])>,
    /// The joint's speed Ω, rad/s.
    pub speed_rad_s: f64,
    /// What was added because the scene had no ALE load (empty otherwise).
    pub note: Option<String>,
}

/// The load case of `config`: its ALE wrenches, or a unit force if it has none.
/// Returns the (possibly extended) configuration and the case.
pub fn load_case(config: &Config) -> (Config, LoadCase) {
    let mut c = config.clone();
    let loaded: Vec<usize> = (0..c.nodes.ale.len())
        .filter(|&j| {
            c.loads
                .ale
                .get(j)
                .is_some_and(|w| *w != WrenchConfig::default())
        })
        .collect();
    let mut note = None;
    let point_index = if let Some(&j) = loaded.first() {
        j
    } else {
        let j = if c.nodes.ale.is_empty() {
            c.nodes.ale.push(NodePosition {
                radial: 1.0,
                angular: 0.0,
            });
            note = Some("the scene has no ALE node: a 1 N force (−z) at ξ = (1, 0) (rim, θ = 0) was added as the load".to_string());
            0
        } else {
            note = Some("the scene's ALE nodes carry no load: a 1 N force (−z) at ALE node 1 was added as the load".to_string());
            0
        };
        c.loads
            .ale
            .resize(c.nodes.ale.len(), WrenchConfig::default());
        c.loads.ale[j] = WrenchConfig {
            force: [0.0, 0.0, -1.0],
            moment: [0.0; 3],
        };
        j
    };
    let loads = (0..c.nodes.ale.len())
        .filter_map(|j| {
            let w = c.loads.ale.get(j).copied().unwrap_or_default();
            (w != WrenchConfig::default()).then(|| {
                (
                    c.nodes.ale[j],
                    [
                        w.force[0],
                        w.force[1],
                        w.force[2],
                        w.moment[0],
                        w.moment[1],
                        w.moment[2],
                    ],
                )
            })
        })
        .collect();
    let case = LoadCase {
        point: c.nodes.ale[point_index],
        ale_node: point_index + 1,
        loads,
        speed_rad_s: c.joint.speed,
        note,
    };
    (c, case)
}

/// Per ⟨k, l⟩ contribution of a model to the steady response at the load point.
/// Indexed `[k][l]`; modes the model lacks (rigid-body) contribute 0.
pub fn contributions(
    model: &PlateModel,
    case: &LoadCase,
    damping: f64,
    off_axis_rate_squared: f64,
) -> Vec<Vec<f64>> {
    let k_max = model.modes().iter().map(|m| m.k).max().unwrap_or(0) as usize;
    let l_max = model.modes().iter().map(|m| m.l).max().unwrap_or(0) as usize;
    let mut out = vec![vec![0.0; l_max + 1]; k_max + 1];
    let omega_spin = case.speed_rad_s;
    let at = |xi: NodePosition| (model.radius_at(xi.radial), xi.angular * TAU);
    let (rp, tp) = at(case.point);
    // Generalized ALE force of mode i.
    let force = |i: usize| -> f64 {
        case.loads
            .iter()
            .map(|&(xi, w)| {
                let (r, t) = at(xi);
                let s = model.mode_shape(i, r, t);
                let tilt = s.tilt(r, t);
                s.w * w[2] + tilt[0] * w[3] + tilt[1] * w[4]
            })
            .sum()
    };
    for (i, m) in model.modes().iter().enumerate() {
        let w_eff2 = m.omega * m.omega - off_axis_rate_squared;
        match m.shape {
            AngularShape::Axisymmetric => {
                let q = force(i) / (m.modal_mass * w_eff2);
                out[0][m.l as usize] += q * model.mode_shape(i, rp, tp).w;
            }
            AngularShape::Cos => {
                let j = m.partner.expect("a cos mode has its sin partner");
                let kf = m.k as f64;
                let a = w_eff2 - kf * kf * omega_spin * omega_spin;
                let b = 2.0 * damping * m.omega * kf * omega_spin;
                let (fc, fs) = (force(i) / m.modal_mass, force(j) / m.modal_mass);
                // [[a, b], [−b, a]] (q_c, q_s) = (f_c, f_s)
                let det = a * a + b * b;
                let qc = (a * fc - b * fs) / det;
                let qs = (b * fc + a * fs) / det;
                out[m.k as usize][m.l as usize] +=
                    qc * model.mode_shape(i, rp, tp).w + qs * model.mode_shape(j, rp, tp).w;
            }
            AngularShape::Sin => {}
        }
    }
    out
}

/// The response of the set k ≤ k_max, l ≤ l_max from per-⟨k, l⟩ contributions.
pub fn partial_sum(c: &[Vec<f64>], k_max: u32, l_max: u32) -> f64 {
    c.iter()
        .take(k_max as usize + 1)
        .map(|row| row.iter().take(l_max as usize + 1).sum::<f64>())
        .sum()
}

/// The damping ratio the axis uses for every mode: the scene's, if one for
/// all; otherwise the mean of its per-mode list.
pub(crate) fn scalar_damping(config: &Config) -> (f64, Option<String>) {
    let d = &config.plate.damping;
    if d.len() == 1 {
        (d[0], None)
    } else {
        let mean = d.iter().sum::<f64>() / d.len() as f64;
        (mean, Some(format!("the scene gives one damping ratio per mode; every mode set here uses their mean, ζ = {mean}")))
    }
}

/// One mode set k = 0..k_max, l = 0..l_max.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ResponseRow {
    /// Highest nodal diameter k of the set.
    pub k_max: u32,
    /// Highest nodal circle l of the set.
    pub l_max: u32,
    /// Elastic modes in the set.
    pub modes: usize,
    /// Steady deflection at the load point, m.
    pub response_m: f64,
    /// |response − reference| / |reference|.
    pub relative_error: f64,
    /// The response plus the residual flexibility of the modes the set leaves out, m.
    pub response_with_residual_m: f64,
    /// Its error against the reference plus the reference's own residual.
    pub relative_error_with_residual: f64,
    /// Wall time of one `Simulation::step` with this mode set (the scene's
    /// integrator, rate and loads; `plate.residual_flexibility: false`), s:
    /// the fastest of repeated batches. `None` where the scene's integrator
    /// refuses the set (`contact_exponential` beyond its unknowns): such a
    /// set is not recommended.
    pub step_time_s: Option<f64>,
    /// The same with `plate.residual_flexibility: true`, s.
    pub step_time_with_residual_s: Option<f64>,
    /// On the axis' Pareto front (both variants of every set compete), without the correction.
    pub pareto: bool,
    /// On the axis' Pareto front, with the correction.
    pub pareto_with_residual: bool,
}

/// The reference mode set (K, L).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ResponseReference {
    /// K: highest nodal diameter of the reference set.
    pub k_max: u32,
    /// L: highest nodal circle of the reference set.
    pub l_max: u32,
    /// Elastic modes in the reference set.
    pub modes: usize,
    /// Radial splines of its model.
    pub radial_splines: usize,
    /// Its steady deflection at the load point, m.
    pub response_m: f64,
    /// The response plus the reference set's residual flexibility, m.
    pub response_with_residual_m: f64,
    /// The nested sets used for the uncertainty: ((k, l), response).
    pub nested: Vec<((u32, u32), f64)>,
    /// Estimated relative truncation error of the reference (see module docs).
    pub uncertainty: f64,
    /// How that uncertainty was estimated, in words.
    pub uncertainty_method: String,
    /// Estimated relative error of the reference plus its residual (see module docs).
    pub uncertainty_with_residual: f64,
}

/// A setting of this axis: a rectangular mode set, with or without the residual flexibility.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ModeSetSetting {
    /// Highest nodal diameter k (`plate.nodal_diameters` = 0..k_max).
    pub k_max: u32,
    /// Highest nodal circle l (`plate.nodal_circles` = 0..l_max).
    pub l_max: u32,
    /// Elastic modes in the set.
    pub modes: usize,
    /// Radial splines the errors were measured with (enough for every ⟨k, l⟩ of the grid).
    pub radial_splines: usize,
    /// `plate.residual_flexibility`: the truncated modes' static deflection added.
    pub residual_flexibility: bool,
}

/// The scene's own mode set, if it is rectangular (k = 0..k_max, l = 0..l_max).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct DefaultModeSet {
    /// Highest nodal diameter k.
    pub k_max: u32,
    /// Highest nodal circle l.
    pub l_max: u32,
    /// The scene's `plate.residual_flexibility`.
    pub residual_flexibility: bool,
}

/// Axis 2: steady deflection at the load point against the mode set, cost = wall time per step.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ResponseAxis {
    /// What the axis varies, in words.
    pub what: &'static str,
    /// How the error is measured, in words.
    pub error_measure: &'static str,
    /// How the cost is measured, in words.
    pub cost_measure: &'static str,
    /// Where the response is read and which wrenches act.
    pub load_case: LoadCase,
    /// The modal damping ratio ζ every mode set uses.
    pub damping: f64,
    /// The reference mode set the errors are measured against.
    pub reference: ResponseReference,
    /// One row per mode set of the grid (k_max ≤ K, l_max ≤ L).
    pub rows: Vec<ResponseRow>,
    /// One per plan target.
    pub recommendations: Vec<Recommendation<ModeSetSetting>>,
    /// The scene's own mode set and `plate.residual_flexibility` (None: not a rectangular set).
    pub default_setting: Option<DefaultModeSet>,
    /// What the axis changed or left out of the scene (loads added or dropped, damping averaged).
    pub notes: Vec<String>,
}

/// The scene's own rectangular mode set, if it is one.
pub(crate) fn default_mode_set(config: &Config) -> Option<DefaultModeSet> {
    let p = &config.plate;
    let k_max = *p.nodal_diameters.iter().max()?;
    let l_max = *p.nodal_circles.iter().max()?;
    let rectangular = p.nodal_diameters.iter().copied().eq(0..=k_max)
        && p.nodal_circles.iter().copied().eq(0..=l_max);
    rectangular.then_some(DefaultModeSet {
        k_max,
        l_max,
        residual_flexibility: p.residual_flexibility,
    })
}

/// The scene restricted to a rectangular mode set (for timing its steps).
pub fn scene_with_set(config: &Config, k_max: u32, l_max: u32, damping: f64) -> Config {
    let mut c = config.clone();
    c.plate.nodal_diameters = (0..=k_max).collect();
    c.plate.nodal_circles = (0..=l_max).collect();
    c.plate.damping = vec![damping];
    c.plate.radial_splines = c
        .plate
        .radial_splines
        .at_least(c.plate.min_radial_splines());
    c
}

/// Measure axis 2: every mode set of the plan against the reference set.
pub(crate) fn run(
    config: &Config,
    plan: &StudyPlan,
    tick: &mut dyn FnMut(&str),
) -> Result<ResponseAxis, StudyError> {
    let (scene, case) = load_case(config);
    let (damping, damping_note) = scalar_damping(&scene);
    let mut notes: Vec<String> = case.note.iter().cloned().chain(damping_note).collect();
    if !scene
        .loads
        .lagrange
        .iter()
        .all(|w| *w == WrenchConfig::default())
    {
        notes.push("Lagrangian-node loads turn with the plate and have no steady state in the space-fixed frame: this axis leaves them out".into());
    }
    let (k_ref, l_ref) = (plan.response_reference.0, plan.response_reference.1);
    let mut big = scene.plate.clone();
    big.nodal_diameters = (0..=k_ref).collect();
    big.nodal_circles = (0..=l_ref).collect();
    big.damping = vec![damping];
    let splines = plan.response_splines.max(big.min_radial_splines());
    big.radial_splines = RadialSplines::Fixed(splines);
    tick(&format!(
        "reference model k ≤ {k_ref}, l ≤ {l_ref}, {splines} radial splines"
    ));
    let model = PlateModel::new(&big)?;
    let w = scene.reference.angular_velocity;
    let soft = w[0] * w[0] + w[1] * w[1];
    let contrib = contributions(&model, &case, damping, soft);
    let reference = partial_sum(&contrib, k_ref, l_ref);
    if reference == 0.0 || !reference.is_finite() {
        return Err(StudyError::NoResponse {
            detail: format!("the steady deflection at the load point is {reference:e} m"),
        });
    }
    let residual_case = case.clone();
    let residual = residual_of_sets(&model, &residual_case);
    let reference_with_residual = reference + residual(k_ref, l_ref);
    // Nested sets for the reference's own error.
    let nested: Vec<((u32, u32), f64)> = [4, 2, 1]
        .iter()
        .map(|&d| {
            (
                (k_ref / d, l_ref / d),
                partial_sum(&contrib, k_ref / d, l_ref / d),
            )
        })
        .collect();
    let (tail, uncertainty_method) =
        nested_tail(nested[1].1 - nested[0].1, nested[2].1 - nested[1].1);
    let uncertainty = tail / reference.abs();

    // The corrected reference: its change from the nested set (K/2, L/2) is what
    // the spin does to the modes between them; the modal uncertainty bounds the
    // tail the correction replaces.
    let (k_half, l_half) = nested[1].0;
    let half_with_residual = nested[1].1 + residual(k_half, l_half);
    let uncertainty_with_residual = uncertainty.max(
        SAFETY_FACTOR * (reference_with_residual - half_with_residual).abs()
            / reference_with_residual.abs(),
    );

    let mut rows = Vec::new();
    let mut rk4_fallback_noted = false;
    let mut contact_refusal_noted = false;
    for &l_max in plan.l_max.iter().filter(|&&l| l <= l_ref) {
        for &k_max in plan.k_max.iter().filter(|&&k| k <= k_ref) {
            tick(&format!("modes k ≤ {k_max}, l ≤ {l_max}"));
            let r = partial_sum(&contrib, k_max, l_max);
            let mut times = [None; 2];
            // One mode per ⟨0, l⟩, a cos/sin pair per ⟨k ≥ 1, l⟩.
            let mut modes = (l_max as usize + 1) * (2 * k_max as usize + 1);
            for (with_residual, time) in [false, true].into_iter().zip(times.iter_mut()) {
                let mut set = scene_with_set(&scene, k_max, l_max, damping);
                set.plate.residual_flexibility = with_residual;
                let mut sim = match Simulation::new(set.clone()) {
                    Err(e @ SimulationError::TooManyContactUnknowns { .. }) => {
                        if !contact_refusal_noted {
                            notes.push(format!("the larger mode sets are not timed: {e}"));
                            contact_refusal_noted = true;
                        }
                        continue;
                    }
                    Err(SimulationError::TooManySubsteps { .. }) => {
                        set.simulation.integrator = IntegratorKind::Exponential;
                        if !rk4_fallback_noted {
                            notes.push("rk4 refuses the larger mode sets at the scene's rate: their cost per step is the exponential integrator's".into());
                            rk4_fallback_noted = true;
                        }
                        Simulation::new(set)?
                    }
                    other => other?,
                };
                *time = Some(min_time_per_unit(plan.timing_budget, |n| {
                    for _ in 0..n {
                        if sim.step().is_err() {
                            sim.reset();
                        }
                    }
                }));
                modes = sim.model().n_modes();
            }
            let rc = r + residual(k_max, l_max);
            rows.push(ResponseRow {
                k_max,
                l_max,
                modes,
                response_m: r,
                relative_error: (r - reference).abs() / reference.abs(),
                response_with_residual_m: rc,
                relative_error_with_residual: (rc - reference_with_residual).abs()
                    / reference_with_residual.abs(),
                step_time_s: times[0],
                step_time_with_residual_s: times[1],
                pareto: false,
                pareto_with_residual: false,
            });
        }
    }
    // Untimed sets (refused by the scene's integrator) take no part.
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
    let default_setting = default_mode_set(config);
    let is_default = |k_max: u32, l_max: u32, residual_flexibility: bool| {
        default_setting.as_ref().is_some_and(|d| {
            d.k_max == k_max && d.l_max == l_max && d.residual_flexibility == residual_flexibility
        })
    };
    let recommendations = recommend(
        &plan.targets,
        rows.iter().flat_map(|r| {
            [false, true].into_iter().filter_map(|with_residual| {
                let cost = if with_residual {
                    r.step_time_with_residual_s
                } else {
                    r.step_time_s
                }?;
                Some(Candidate {
                    error: if with_residual {
                        r.relative_error_with_residual
                    } else {
                        r.relative_error
                    },
                    uncertainty: if with_residual {
                        uncertainty_with_residual
                    } else {
                        uncertainty
                    },
                    cost,
                    setting: ModeSetSetting {
                        k_max: r.k_max,
                        l_max: r.l_max,
                        modes: r.modes,
                        radial_splines: splines,
                        residual_flexibility: with_residual,
                    },
                    is_default: is_default(r.k_max, r.l_max, with_residual),
                })
            })
        }),
    );
    Ok(ResponseAxis {
        what: "steady deflection at the load point under the held space-fixed loads, against the mode set k ≤ k_max, l ≤ l_max",
        error_measure: "|w − w_ref| / |w_ref| at the load point, w_ref from the reference mode set",
        cost_measure: "wall time per Simulation::step with that mode set (the scene's integrator and rate), s",
        load_case: case,
        damping,
        reference: ResponseReference {
            k_max: k_ref,
            l_max: l_ref,
            modes: model.n_modes(),
            radial_splines: splines,
            response_m: reference,
            response_with_residual_m: reference_with_residual,
            nested,
            uncertainty,
            uncertainty_method,
            uncertainty_with_residual,
        },
        rows,
        recommendations,
        default_setting,
        notes,
    })
}

/// The estimated truncation error of the finest of three nested sets whose
/// responses differ by d₁ (coarse to middle) and d₂ (middle to finest), and
/// how it was estimated (module docs).
pub(crate) fn nested_tail(d1: f64, d2: f64) -> (f64, String) {
    if d1 * d2 > 0.0 && (d1 / d2) > 1.2 {
        let rho = d1 / d2;
        (
            SAFETY_FACTOR * (d2 / (rho - 1.0)).abs(),
            format!("geometric tail of the nested sets, ratio of differences ρ = {rho:.2}: {SAFETY_FACTOR} |d₂|/(ρ − 1)"),
        )
    } else {
        (
            d1.abs().max(d2.abs()),
            "nested sets not in a geometric regime: the larger difference".to_string(),
        )
    }
}

/// The residual flexibility at the load point of the set k ≤ k_max, l ≤ l_max
/// of `model`'s modes under the load case's transverse forces, m.
fn residual_of_sets<'a>(
    model: &'a PlateModel,
    case: &'a LoadCase,
) -> impl Fn(u32, u32) -> f64 + 'a {
    let at = |xi: NodePosition| (model.radius_at(xi.radial), xi.angular * TAU);
    let (rp, tp) = at(case.point);
    let mut radii = vec![rp];
    radii.extend(case.loads.iter().map(|&(xi, _)| at(xi).0));
    let harmonics = model.static_harmonics(&radii);
    move |k_max, l_max| {
        case.loads
            .iter()
            .enumerate()
            .filter(|(_, (_, w))| w[2] != 0.0)
            .map(|(j, &(xi, w))| {
                let kernel =
                    model.residual_kernel_of(&harmonics, 0, j + 1, |k, l| k <= k_max && l <= l_max);
                w[2] * kernel.at(tp - at(xi).1)
            })
            .sum()
    }
}
