//! Axis 3: trajectory error against integrator and step, with the wall time
//! per simulated second.
//!
//! The scene runs from t = 0 for `duration` with each integrator at each
//! output rate (one substep per step; `rk4` still sub-steps itself below its
//! stability limit, as it always does). The modal amplitudes (ALE description)
//! are sampled every 1/`sample_rate_hz` and compared with a reference run:
//!
//! error = max_t ‖q(t) − q_ref(t)‖₂ / max_t ‖q_ref(t)‖₂
//!
//! (the 2-norm is the same in the Lagrangian description: eq. (20) turns each
//! pair by an orthogonal rotation). **Reference:** the `exponential` integrator
//! at `reference_rate_hz`. **Checks:** `rk4` at the same rate (an explicit
//! method sharing no integration code with it), and `exponential` at half the
//! rate (a step error both methods share — a load model updated once per step —
//! shows there: for a method of order p ≥ 1 the difference from the half rate
//! is ≥ (2ᵖ − 1) × the reference's own error). The larger difference is the
//! reference's uncertainty, added to every error before a setting is
//! recommended.
//!
//! On a scene whose load models switch (pads that lift off and touch down)
//! the reference is `rk4` instead, which evaluates the contact springs at
//! every stage, with its inner substep 16× below the default
//! (`simulation.rk4_step_limit` 0.0125); its checks are
//! `rk4` at half that inner step and `contact_exponential` at the tightest
//! `simulation.contact_tolerance`, and `contact_exponential` (at the scene's
//! own tolerance) joins the integrators compared.

use super::timing::min_time;
use super::{mark_pareto, recommend, Candidate, Recommendation, StudyError, StudyPlan};
use crate::config::{Config, IntegratorKind};
use crate::dynamics::{Simulation, SimulationError};
use serde::Serialize;

/// Sampled ALE amplitudes: one vector per sample time (t = 0 included).
pub type Samples = Vec<Vec<f64>>;

/// Why a run gave no trajectory.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum RunStatus {
    /// The run completed (not an error: the row's status when it has a trajectory).
    Ok,
    /// `rk4` would need more substeps than it allows.
    Refused,
    /// The divergence guard stopped the run.
    Diverged,
}

/// The scene with one integrator at one rate.
pub fn scene_at(config: &Config, integrator: IntegratorKind, rate_hz: f64) -> Config {
    let mut c = config.clone();
    c.simulation.integrator = integrator;
    c.simulation.rate_hz = rate_hz;
    c.simulation.substeps = 1;
    c
}

/// Steps per sample for `rate_hz`, which must be a whole multiple of the sample rate.
fn steps_per_sample(rate_hz: f64, sample_rate_hz: f64) -> Result<u64, StudyError> {
    let m = rate_hz / sample_rate_hz;
    if m < 1.0 - 1e-9 || (m - m.round()).abs() > 1e-9 * m {
        return Err(StudyError::BadPlan {
            detail: format!(
                "rate {rate_hz} Hz is not a whole multiple of the sample rate {sample_rate_hz} Hz"
            ),
        });
    }
    Ok(m.round() as u64)
}

/// Run `config` for `samples` samples of `every` steps, recording the ALE amplitudes.
pub fn record(
    config: &Config,
    every: u64,
    samples: usize,
) -> Result<(Samples, Simulation), (RunStatus, String)> {
    let mut sim = match Simulation::new(config.clone()) {
        Ok(s) => s,
        Err(
            e @ (SimulationError::TooManySubsteps { .. }
            | SimulationError::ModelTooStiffForIntegrator { .. }
            | SimulationError::ContinuousStateNeedsRk4 { .. }
            | SimulationError::TooManyContactUnknowns { .. }
            | SimulationError::InPlaneKeyNotWired { .. }
            | SimulationError::InPlaneSpin { .. }),
        ) => return Err((RunStatus::Refused, e.to_string())),
        Err(e) => return Err((RunStatus::Diverged, e.to_string())),
    };
    let mut out = Vec::with_capacity(samples + 1);
    out.push(sim.q_ale().to_vec());
    for _ in 0..samples {
        for _ in 0..every {
            sim.step()
                .map_err(|e| (RunStatus::Diverged, e.to_string()))?;
        }
        out.push(sim.q_ale().to_vec());
    }
    Ok((out, sim))
}

/// max_t ‖a(t) − b(t)‖₂ / max_t ‖b(t)‖₂.
pub fn relative_error(a: &Samples, b: &Samples) -> f64 {
    let norm = |v: &[f64]| v.iter().map(|x| x * x).sum::<f64>().sqrt();
    let scale = b.iter().map(|v| norm(v)).fold(0.0, f64::max);
    let diff = a
        .iter()
        .zip(b)
        .map(|(x, y)| {
            x.iter()
                .zip(y)
                .map(|(p, q)| (p - q) * (p - q))
                .sum::<f64>()
                .sqrt()
        })
        .fold(0.0, f64::max);
    diff / scale
}

/// [`relative_error`] of the amplitudes from index `offset` on (the
/// in-plane modes); None where the reference leaves them at rest.
fn in_plane_error(a: &Samples, b: &Samples, offset: usize) -> Option<f64> {
    let tail = |s: &Samples| -> Samples { s.iter().map(|v| v[offset..].to_vec()).collect() };
    let reference = tail(b);
    let moves = reference.iter().flatten().any(|&x| x != 0.0);
    moves.then(|| relative_error(&tail(a), &reference))
}

/// One integrator at one output rate.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct TrajectoryRow {
    /// `simulation.integrator`.
    pub integrator: &'static str,
    /// `simulation.rate_hz`, Hz.
    pub rate_hz: f64,
    /// Whether the run gave a trajectory.
    pub status: RunStatus,
    /// The refusal or divergence message.
    pub detail: Option<String>,
    /// max_t ‖q(t) − q_ref(t)‖₂ / max_t ‖q_ref(t)‖₂ (None: no trajectory).
    pub relative_error: Option<f64>,
    /// The same over the in-plane amplitudes alone (absent without in-plane
    /// modes, where the reference leaves them at rest, or without a
    /// trajectory): µm beside the bending's mm, they would not show in
    /// `relative_error`.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub in_plane_relative_error: Option<f64>,
    /// Wall time / simulated time (the fastest of repeated runs).
    pub wall_s_per_simulated_s: Option<f64>,
    /// On the error-vs-cost Pareto front of this axis.
    pub pareto: bool,
}

/// A run compared with the reference.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Check {
    /// `simulation.integrator` of the check run.
    pub integrator: &'static str,
    /// Its output rate, Hz.
    pub rate_hz: f64,
    /// Its relative difference from the reference (the errors' measure).
    pub difference: f64,
}

/// The reference run.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct TrajectoryReference {
    /// `simulation.integrator` of the reference run.
    pub integrator: &'static str,
    /// Its output rate, Hz.
    pub rate_hz: f64,
    /// The reference run again with another method, and with the same method at twice the step.
    pub checks: Vec<Check>,
    /// The larger difference of the checks (same measure as the errors).
    pub uncertainty: f64,
    /// max_t ‖q_ref(t)‖₂, m.
    pub peak_amplitude_m: f64,
}

/// A setting of this axis: an integrator at an output rate.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct IntegratorSetting {
    /// `simulation.integrator`.
    pub integrator: &'static str,
    /// `simulation.rate_hz`, Hz.
    pub rate_hz: f64,
}

/// Axis 3: trajectory error against integrator and rate, cost = wall time per simulated second.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct TrajectoryAxis {
    /// What the axis varies, in words.
    pub what: &'static str,
    /// How the error is measured, in words.
    pub error_measure: &'static str,
    /// How the cost is measured, in words.
    pub cost_measure: &'static str,
    /// Simulated time of every run, s.
    pub duration_s: f64,
    /// Rate at which the ALE amplitudes are compared, Hz.
    pub sample_rate_hz: f64,
    /// Elastic modes of the scene.
    pub modes: usize,
    /// The plan's integrators this scene is studied with (`contact_exponential`
    /// only where its load models switch); each runs at every rate.
    pub integrators: Vec<&'static str>,
    /// The reference run the errors are measured against.
    pub reference: TrajectoryReference,
    /// One row per integrator and rate.
    pub rows: Vec<TrajectoryRow>,
    /// One per plan target.
    pub recommendations: Vec<Recommendation<IntegratorSetting>>,
    /// The scene's own integrator and rate.
    pub default_setting: IntegratorSetting,
    /// What the axis changed or could not measure, in words.
    pub notes: Vec<String>,
}

/// Measure axis 3: every integrator at every rate against the reference run.
pub(crate) fn run(
    config: &Config,
    plan: &StudyPlan,
    tick: &mut dyn FnMut(&str),
) -> Result<TrajectoryAxis, StudyError> {
    let samples = (plan.duration_s * plan.sample_rate_hz).round() as usize;
    if samples == 0 {
        return Err(StudyError::BadPlan {
            detail: format!(
                "duration {} s is shorter than one sample ({} Hz)",
                plan.duration_s, plan.sample_rate_hz
            ),
        });
    }
    let duration = samples as f64 / plan.sample_rate_hz;
    let ref_rate = plan.trajectory_reference_rate_hz;
    let mut notes = Vec::new();
    let mut scene = config.clone();
    let reference_why = reference_kind(&scene, ref_rate);
    let ref_integrator = match reference_why {
        ReferenceWhy::Smooth => IntegratorKind::Exponential,
        ReferenceWhy::LoadModelState | ReferenceWhy::StiffContacts => IntegratorKind::Rk4,
    };
    tick(&format!(
        "reference: {} at {ref_rate} Hz",
        ref_integrator.name()
    ));
    let reference_run = |scene: &Config| -> Result<Samples, StudyError> {
        let every = steps_per_sample(ref_rate, plan.sample_rate_hz)?;
        record(
            &reference_at(scene, reference_why, ref_rate),
            every,
            samples,
        )
        .map(|(s, _)| s)
        .map_err(|(_, detail)| StudyError::NoResponse {
            detail: format!("the reference run failed: {detail}"),
        })
    };
    let mut reference = reference_run(&scene)?;
    let peak = |s: &Samples| {
        s.iter()
            .map(|v| v.iter().map(|x| x * x).sum::<f64>().sqrt())
            .fold(0.0, f64::max)
    };
    if peak(&reference) == 0.0 {
        let (loaded, case) = super::response::load_case(&scene);
        scene = loaded;
        notes.push(format!(
            "the scene stays at rest without a load; {}",
            case.note.unwrap_or_default()
        ));
        reference = reference_run(&scene)?;
    }
    let checks = match reference_why {
        ReferenceWhy::Smooth => {
            exponential_checks(&scene, plan, samples, &reference, &mut notes, tick)?
        }
        ReferenceWhy::LoadModelState => {
            notes.push("the scene's load models have state only rk4 integrates (pads.mass): the reference is rk4, checked against rk4 at half its inner step".into());
            vec![rk4_half_step_check(
                &scene,
                reference_why,
                plan,
                samples,
                &reference,
                tick,
            )?]
        }
        ReferenceWhy::StiffContacts => {
            notes.push("the scene's load models switch (contacts that lift off): the reference is rk4 with simulation.rk4_step_limit 0.0125 (16× below the default), which resolves the contact springs at every stage, checked against rk4 at half its inner step and against contact_exponential at the tightest simulation.contact_tolerance".into());
            vec![
                rk4_half_step_check(&scene, reference_why, plan, samples, &reference, tick)?,
                contact_exponential_check(&scene, plan, samples, &reference, tick)?,
            ]
        }
    };
    let uncertainty = checks.iter().map(|c| c.difference).fold(0.0, f64::max);
    let modes = reference.first().map_or(0, |v| v.len());

    let mut rows = Vec::new();
    let integrators = compared(plan, reference_why);
    for &integrator in &integrators {
        for &rate in &plan.rates_hz {
            tick(&format!("{} at {rate} Hz", integrator.name()));
            let every = steps_per_sample(rate, plan.sample_rate_hz)?;
            let cfg = scene_at(&scene, integrator, rate);
            let row = match record(&cfg, every, samples) {
                Ok((s, mut sim)) => {
                    let steps = every * samples as u64;
                    let wall = min_time(plan.timing_budget, 2, 1000, || {
                        sim.reset();
                        for _ in 0..steps {
                            if sim.step().is_err() {
                                break;
                            }
                        }
                    });
                    TrajectoryRow {
                        integrator: integrator.name(),
                        rate_hz: rate,
                        status: RunStatus::Ok,
                        detail: None,
                        relative_error: Some(relative_error(&s, &reference)),
                        in_plane_relative_error: sim
                            .scene()
                            .in_plane
                            .as_ref()
                            .and_then(|ip| in_plane_error(&s, &reference, ip.offset)),
                        wall_s_per_simulated_s: Some(wall / duration),
                        pareto: false,
                    }
                }
                Err((status, detail)) => TrajectoryRow {
                    integrator: integrator.name(),
                    rate_hz: rate,
                    status,
                    detail: Some(detail),
                    relative_error: None,
                    in_plane_relative_error: None,
                    wall_s_per_simulated_s: None,
                    pareto: false,
                },
            };
            rows.push(row);
        }
    }
    let ok: Vec<usize> = (0..rows.len())
        .filter(|&i| rows[i].status == RunStatus::Ok)
        .collect();
    let points: Vec<(f64, f64)> = ok
        .iter()
        .map(|&i| {
            (
                rows[i].relative_error.unwrap(),
                rows[i].wall_s_per_simulated_s.unwrap(),
            )
        })
        .collect();
    for (&i, p) in ok.iter().zip(mark_pareto(&points)) {
        rows[i].pareto = p;
    }
    let default_setting = IntegratorSetting {
        integrator: config.simulation.integrator.name(),
        rate_hz: config.simulation.rate_hz,
    };
    let recommendations = recommend(
        &plan.targets,
        ok.iter().map(|&i| {
            let r = &rows[i];
            let setting = IntegratorSetting {
                integrator: r.integrator,
                rate_hz: r.rate_hz,
            };
            Candidate {
                error: r.relative_error.unwrap(),
                uncertainty,
                cost: r.wall_s_per_simulated_s.unwrap(),
                is_default: setting == default_setting,
                setting,
            }
        }),
    );
    Ok(TrajectoryAxis {
        what: "modal-amplitude trajectory from rest under the scene's loads, against integrator and output rate",
        error_measure: "max over sample times of ‖q − q_ref‖₂ / max over sample times of ‖q_ref‖₂ (ALE amplitudes)",
        cost_measure: "wall time per simulated second, s/s",
        duration_s: duration,
        sample_rate_hz: plan.sample_rate_hz,
        modes,
        integrators: integrators.iter().map(|i| i.name()).collect(),
        reference: TrajectoryReference {
            integrator: ref_integrator.name(),
            rate_hz: ref_rate,
            checks,
            uncertainty,
            peak_amplitude_m: peak(&reference),
        },
        rows,
        recommendations,
        default_setting,
        notes,
    })
}

/// The plan's integrators `config` is compared with: `contact_exponential`
/// only where its load models switch.
pub(crate) fn integrators(config: &Config, plan: &StudyPlan) -> Vec<IntegratorKind> {
    compared(
        plan,
        reference_kind(config, plan.trajectory_reference_rate_hz),
    )
}

fn compared(plan: &StudyPlan, why: ReferenceWhy) -> Vec<IntegratorKind> {
    plan.integrators
        .iter()
        .copied()
        .filter(|&i| i != IntegratorKind::ContactExponential || why == ReferenceWhy::StiffContacts)
        .collect()
}

/// Why the reference is the integrator it is.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum ReferenceWhy {
    /// `exponential`: the scene's forces are smooth in the state.
    Smooth,
    /// `rk4`: the load models have state of their own that only rk4
    /// integrates (massive pads).
    LoadModelState,
    /// `rk4`: the load models switch (contacts that lift off and touch
    /// down), which `exponential` holds over a step; `contact_exponential`
    /// joins the integrators compared.
    StiffContacts,
}

fn reference_kind(scene: &Config, rate_hz: f64) -> ReferenceWhy {
    if let Err(SimulationError::ContinuousStateNeedsRk4 { .. }) =
        Simulation::new(scene_at(scene, IntegratorKind::Exponential, rate_hz))
    {
        return ReferenceWhy::LoadModelState;
    }
    match Simulation::new(scene_at(scene, IntegratorKind::Rk4, rate_hz)) {
        Ok(sim) if sim.scene().load_models.switching_functions() > 0 => ReferenceWhy::StiffContacts,
        _ => ReferenceWhy::Smooth,
    }
}

/// `simulation.rk4_step_limit` of the reference on a scene with stiff
/// contacts: 16× below the default, so the inner substep resolves the
/// contact springs' fastest rate 16 times finer than a plain rk4 run.
const REFERENCE_RK4_STEP_LIMIT: f64 = 0.0125;

/// The reference run's scene: its integrator at `rate_hz`, with the inner
/// step refined on a scene with stiff contacts.
fn reference_at(scene: &Config, why: ReferenceWhy, rate_hz: f64) -> Config {
    match why {
        ReferenceWhy::Smooth => scene_at(scene, IntegratorKind::Exponential, rate_hz),
        ReferenceWhy::LoadModelState => scene_at(scene, IntegratorKind::Rk4, rate_hz),
        ReferenceWhy::StiffContacts => {
            let mut c = scene_at(scene, IntegratorKind::Rk4, rate_hz);
            c.simulation.rk4_step_limit = c.simulation.rk4_step_limit.min(REFERENCE_RK4_STEP_LIMIT);
            c
        }
    }
}

/// The tightest `simulation.contact_tolerance` the contact check runs at.
const CHECK_CONTACT_TOLERANCE: f64 = 1e-12;

/// An independent check of an rk4 reference on a scene with stiff contacts:
/// `contact_exponential` at the same rate (it shares only the right-hand
/// side with rk4: it treats the contact springs exactly on their active set
/// and locates each lift-off and touch-down).
fn contact_exponential_check(
    scene: &Config,
    plan: &StudyPlan,
    samples: usize,
    reference: &Samples,
    tick: &mut dyn FnMut(&str),
) -> Result<Check, StudyError> {
    let mut tight = scene_at(
        scene,
        IntegratorKind::ContactExponential,
        plan.trajectory_reference_rate_hz,
    );
    tight.simulation.contact_tolerance = CHECK_CONTACT_TOLERANCE;
    check_run(
        &tight,
        IntegratorKind::ContactExponential.name(),
        plan,
        samples,
        reference,
        tick,
    )
}

/// `config` run at the reference rate as a check of the reference.
fn check_run(
    config: &Config,
    name: &'static str,
    plan: &StudyPlan,
    samples: usize,
    reference: &Samples,
    tick: &mut dyn FnMut(&str),
) -> Result<Check, StudyError> {
    let rate_hz = plan.trajectory_reference_rate_hz;
    tick(&format!("check: {name} at {rate_hz} Hz"));
    let s = record(
        config,
        steps_per_sample(rate_hz, plan.sample_rate_hz)?,
        samples,
    )
    .map_err(|(_, detail)| StudyError::NoResponse {
        detail: format!("the check run ({name}) failed: {detail}"),
    })?;
    Ok(Check {
        integrator: name,
        rate_hz,
        difference: relative_error(&s.0, reference),
    })
}

/// Two independent checks of an exponential reference: another method at the
/// same step (rk4 shares no integration code with it), and the same method
/// at twice the step (catches step errors both methods share, e.g. a load
/// model updated once per step). Their larger difference is the uncertainty.
fn exponential_checks(
    scene: &Config,
    plan: &StudyPlan,
    samples: usize,
    reference: &Samples,
    notes: &mut Vec<String>,
    tick: &mut dyn FnMut(&str),
) -> Result<Vec<Check>, StudyError> {
    let ref_rate = plan.trajectory_reference_rate_hz;
    let run_check =
        |integrator: IntegratorKind, rate: f64| -> Result<Result<Samples, String>, StudyError> {
            Ok(record(
                &scene_at(scene, integrator, rate),
                steps_per_sample(rate, plan.sample_rate_hz)?,
                samples,
            )
            .map(|(s, _)| s)
            .map_err(|(_, d)| d))
        };
    let mut checks = Vec::new();
    tick(&format!("check: rk4 at {ref_rate} Hz"));
    match run_check(IntegratorKind::Rk4, ref_rate)? {
        Ok(s) => checks.push(Check {
            integrator: IntegratorKind::Rk4.name(),
            rate_hz: ref_rate,
            difference: relative_error(&s, reference),
        }),
        Err(detail) => notes.push(format!(
            "rk4 could not run as a check of the reference ({detail})"
        )),
    }
    let half = ref_rate / 2.0;
    tick(&format!("check: exponential at {half} Hz"));
    match run_check(IntegratorKind::Exponential, half)? {
        Ok(s) => checks.push(Check {
            integrator: IntegratorKind::Exponential.name(),
            rate_hz: half,
            difference: relative_error(&s, reference),
        }),
        Err(detail) => {
            return Err(StudyError::NoResponse {
                detail: format!("the check run at {half} Hz failed: {detail}"),
            })
        }
    }
    Ok(checks)
}

/// The check of an rk4 reference: rk4 at the same rate with half its inner
/// step (`simulation.rk4_step_limit` halved, so the step halves also where
/// the stability bound, not the rate, sets it); for order 4 the difference
/// is 15/16 of the reference's own error.
fn rk4_half_step_check(
    scene: &Config,
    reference_why: ReferenceWhy,
    plan: &StudyPlan,
    samples: usize,
    reference: &Samples,
    tick: &mut dyn FnMut(&str),
) -> Result<Check, StudyError> {
    let mut finer = reference_at(scene, reference_why, plan.trajectory_reference_rate_hz);
    finer.simulation.rk4_step_limit *= 0.5;
    check_run(
        &finer,
        "rk4, half the inner step",
        plan,
        samples,
        reference,
        tick,
    )
}
