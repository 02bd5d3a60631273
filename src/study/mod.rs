//! Accuracy against cost, measured: `annular_plate study`.
//!
//! Three axes, each an error measured against an independent, finer reference
//! and a cost measured on this machine:
//!
//! 1. `frequency`: natural-frequency error vs `plate.radial_splines`, cost =
//!    model build time;
//! 2. [`response`]: steady deflection at the load point vs the mode set
//!    (k ≤ k_max, l ≤ l_max), cost = wall time per step;
//! 3. [`trajectory`]: trajectory error vs integrator and output rate, cost =
//!    wall time per simulated second;
//!
//! With `plate.in_plane_nodal_diameters` two in-plane axes join them:
//! [`in_plane_frequency`] (axis 1b, frequency error vs splines) and, with an
//! in-plane ALE force, [`in_plane_response`] (axis 2b, the in-plane static
//! displacement vs `plate.in_plane_orders`, with and without the residual
//! flexibility, cost = wall time per step);
//!
//! and the plate theory as a lever ([`theory`]): Kirchhoff's frequency error
//! against converged Mindlin frequencies, with each theory's build time.
//!
//! Under `plate.theory: mindlin` axes 1 and 3 run on the Mindlin modes and
//! axis 2 is skipped (`mode_count` is null, the reason in `notes`): a point
//! force's Mindlin deflection at the force is infinite (the shear deflection
//! −F ln r / (2π κGh)), so the steady deflection at the load point does not
//! converge with the mode set.
//!
//! Every reference carries an uncertainty (its own estimated error), and a
//! setting is recommended for a target error only if its measured error plus
//! that uncertainty is within the target; among those the cheapest measured
//! one wins. Every lever an axis measures competes: `auto` and the fixed
//! spline counts; each mode set with and without the residual flexibility;
//! each integrator at each rate. A recommendation says whether it is the
//! scene's own setting (`is_default`), and each axis names that setting
//! (`default_setting`). The errors are deterministic (bit-identical run to run); only the
//! timings vary. Pure library code: no ROS, no output formatting.

pub(crate) mod frequency;
pub(crate) mod in_plane_compliance;
pub mod in_plane_frequency;
pub mod in_plane_response;
pub mod response;
pub mod theory;
pub(crate) mod timing;
pub mod trajectory;

use crate::config::{Config, IntegratorKind, NodePosition, PlateTheory, WrenchConfig};
use crate::dynamics::SimulationError;
use crate::model::ModelError;
use serde::Serialize;
use std::time::{Duration, Instant};
use thiserror::Error;

pub use frequency::FrequencyAxis;
pub use in_plane_frequency::InPlaneFrequencyAxis;
pub use in_plane_response::InPlaneResponseAxis;
pub use response::ResponseAxis;
pub use theory::TheoryComparison;
pub use trajectory::TrajectoryAxis;

/// Version of the JSON document (`study --json`); bumped on any incompatible change.
pub(crate) const SCHEMA: &str = "annular_plate.study/1";

/// Largest `plate.radial_splines` the configuration accepts.
pub(crate) const MAX_RADIAL_SPLINES: usize = 400;

/// Why axis 2 is skipped under Mindlin theory (in the report's `notes`).
pub const MINDLIN_MODE_COUNT_NOTE: &str = "mode_count (axis 2) is skipped under plate.theory mindlin: a point force's Mindlin deflection is infinite at the force (shear deflection −F ln r / (2π κGh)), so the steady deflection at the load point does not converge with the mode set";

/// What the axes measure with in-plane modes (in the report's `notes`).
pub const IN_PLANE_NOTE: &str = "with plate.in_plane_nodal_diameters: radial_splines, mode_count and theory measure the bending modes; in_plane_radial_splines the in-plane modes' frequencies; in_plane_mode_count (with an in-plane ALE force) their static displacement at rest against plate.in_plane_orders; integrator compares every modal amplitude, bending and in-plane (its rows' in_plane_relative_error the in-plane ones alone)";

/// Why a study could not run.
#[derive(Debug, Error)]
pub enum StudyError {
    /// A model of the grid (or the reference) could not be built.
    #[error(transparent)]
    Model(#[from] ModelError),
    /// A simulation of the grid refused its scene or diverged where a result was needed.
    #[error(transparent)]
    Simulation(#[from] SimulationError),
    /// An axis has no setting left to measure (e.g. every spline count below the plate's minimum).
    #[error("the {axis} grid is empty")]
    EmptyGrid {
        /// The axis: `radial splines`, `mode count` or `integrator`.
        axis: &'static str,
    },
    /// The plan breaks a rule (a non-positive target, a rate that is not a
    /// whole multiple of the sample rate, …).
    #[error("bad study plan: {detail}")]
    BadPlan {
        /// The rule and the offending value.
        detail: String,
    },
    /// The scene gives the response axis no deflection to compare.
    #[error("nothing to measure: {detail}")]
    NoResponse {
        /// Why the response is zero or undefined.
        detail: String,
    },
}

/// What the study measures: the grids, the references and the targets.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct StudyPlan {
    /// Axis 1: radial spline counts (those below the plate's minimum are dropped).
    pub splines: Vec<usize>,
    /// The frequency reference uses this many times the largest count (capped at 400);
    /// its error is bounded by its difference from half as many splines.
    pub spline_reference_factor: usize,
    /// Axis 2: k_max of the rectangular mode sets k = 0..k_max, l = 0..l_max
    /// (k: nodal diameters).
    pub k_max: Vec<u32>,
    /// Axis 2: l_max of those mode sets (l: nodal circles).
    pub l_max: Vec<u32>,
    /// Axis 2: the reference set (K, L).
    pub response_reference: (u32, u32),
    /// Axis 2: radial splines of every mode (enough for l ≤ L).
    pub response_splines: usize,
    /// Axis 3: the integrators compared; `contact_exponential` runs only on
    /// scenes whose load models switch.
    pub integrators: Vec<IntegratorKind>,
    /// Axis 3: output rates (`simulation.rate_hz`, one substep per step), Hz;
    /// whole multiples of `sample_rate_hz`.
    pub rates_hz: Vec<f64>,
    /// Axis 3: rate at which the ALE modal amplitudes are sampled and compared, Hz.
    pub sample_rate_hz: f64,
    /// Axis 3: rate of the reference run, Hz.
    pub trajectory_reference_rate_hz: f64,
    /// Axis 3: simulated time, s.
    pub duration_s: f64,
    /// Target relative errors for the recommendations.
    pub targets: Vec<f64>,
    /// Time spent repeating each timing (the fastest repeat counts).
    #[serde(serialize_with = "serialize_seconds")]
    pub timing_budget: Duration,
}

fn serialize_seconds<S: serde::Serializer>(d: &Duration, s: S) -> Result<S::Ok, S::Error> {
    s.serialize_f64(d.as_secs_f64())
}

impl StudyPlan {
    /// The default study (8 s in release on 2 shared vCPUs).
    pub fn full() -> StudyPlan {
        StudyPlan {
            splines: vec![8, 12, 16, 24, 32, 48, 64],
            // 128: beyond about that many splines the library's frequencies stop
            // improving (round-off, measured against the exact solution in docs/study.md).
            spline_reference_factor: 2,
            k_max: vec![1, 2, 3, 5, 7, 10, 15, 20, 30, 40, 50, 60, 80, 100],
            l_max: vec![0, 1, 2, 3, 4, 6, 8, 12, 16],
            response_reference: (200, 48),
            response_splines: 96,
            integrators: vec![
                IntegratorKind::Exponential,
                IntegratorKind::ImplicitMidpoint,
                IntegratorKind::Rk4,
                IntegratorKind::ContactExponential,
            ],
            rates_hz: vec![1e3, 2e3, 5e3, 1e4, 2e4, 5e4, 1e5],
            sample_rate_hz: 1e3,
            trajectory_reference_rate_hz: 1e6,
            duration_s: 0.05,
            targets: vec![1e-2, 1e-3, 1e-4, 1e-6],
            timing_budget: Duration::from_millis(40),
        }
    }

    /// A small grid for tests and a first look (a few seconds).
    pub fn quick() -> StudyPlan {
        StudyPlan {
            splines: vec![8, 12, 16, 24],
            spline_reference_factor: 4,
            k_max: vec![1, 3, 7, 15],
            l_max: vec![0, 1, 2],
            response_reference: (60, 8),
            response_splines: 48,
            integrators: vec![
                IntegratorKind::Exponential,
                IntegratorKind::ImplicitMidpoint,
                IntegratorKind::Rk4,
                IntegratorKind::ContactExponential,
            ],
            rates_hz: vec![1e3, 2e3, 5e3, 1e4, 2e4],
            sample_rate_hz: 1e3,
            trajectory_reference_rate_hz: 1e5,
            duration_s: 0.02,
            targets: vec![1e-1, 1e-2, 1e-3, 1e-4],
            timing_budget: Duration::from_millis(3),
        }
    }

    /// Work units [`run`] reports through its progress callback for `config`.
    pub fn units(&self, config: &Config) -> usize {
        let a = 2 + frequency::spline_grid(&config.plate, self).len();
        let (k_ref, l_ref) = self.response_reference;
        let b = match config.plate.theory {
            PlateTheory::Kirchhoff => {
                1 + self.k_max.iter().filter(|&&k| k <= k_ref).count()
                    * self.l_max.iter().filter(|&&l| l <= l_ref).count()
            }
            PlateTheory::Mindlin => 0,
        };
        let c = 3 + trajectory::integrators(config, self).len() * self.rates_hz.len();
        let d = if config.plate.in_plane_nodal_diameters.is_empty() {
            0
        } else {
            2 + frequency::spline_grid(&config.plate, self).len() + 1 + self.l_max.len()
        };
        a + b + c + d + 1
    }
}

/// The cheapest measured setting for one target error (None: none in the grid reaches it).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Recommendation<S> {
    /// The target relative error.
    pub target: f64,
    /// The recommended setting (None: no measured setting reaches the target).
    pub setting: Option<S>,
    /// Measured error against the reference.
    pub error: Option<f64>,
    /// error + the reference's uncertainty: what the recommendation claims (≤ target).
    pub claimed_error: Option<f64>,
    /// The setting's measured cost (the axis' cost measure).
    pub cost: Option<f64>,
    /// The recommended setting is the scene's own (what runs without changing the file).
    pub is_default: bool,
}

/// One measured setting offered to [`recommend`].
#[derive(Debug, Clone)]
pub(crate) struct Candidate<S> {
    /// Measured relative error against the reference.
    pub error: f64,
    /// The uncertainty of the reference this error was measured against.
    pub uncertainty: f64,
    /// The measured cost (the axis' cost measure).
    pub cost: f64,
    /// The setting measured.
    pub setting: S,
    /// The scene's own setting.
    pub is_default: bool,
}

/// For each target the cheapest candidate with error + uncertainty ≤ target;
/// ties in cost go to the smaller claimed error.
pub(crate) fn recommend<S: Clone>(
    targets: &[f64],
    candidates: impl Iterator<Item = Candidate<S>>,
) -> Vec<Recommendation<S>> {
    let candidates: Vec<Candidate<S>> = candidates.collect();
    targets
        .iter()
        .map(|&target| {
            let best = candidates
                .iter()
                .filter(|c| {
                    c.error.is_finite() && c.cost.is_finite() && c.error + c.uncertainty <= target
                })
                .min_by(|a, b| {
                    a.cost
                        .total_cmp(&b.cost)
                        .then((a.error + a.uncertainty).total_cmp(&(b.error + b.uncertainty)))
                });
            match best {
                Some(c) => Recommendation {
                    target,
                    setting: Some(c.setting.clone()),
                    error: Some(c.error),
                    claimed_error: Some(c.error + c.uncertainty),
                    cost: Some(c.cost),
                    is_default: c.is_default,
                },
                None => Recommendation {
                    target,
                    setting: None,
                    error: None,
                    claimed_error: None,
                    cost: None,
                    is_default: false,
                },
            }
        })
        .collect()
}

/// Which (error, cost) points no other point beats in both.
pub(crate) fn mark_pareto(points: &[(f64, f64)]) -> Vec<bool> {
    points
        .iter()
        .map(|&(e, c)| {
            e.is_finite()
                && c.is_finite()
                && !points
                    .iter()
                    .any(|&(e2, c2)| (e2 <= e && c2 < c) || (e2 < e && c2 <= c))
        })
        .collect()
}

/// The scene a study runs on, in brief.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct SceneSummary {
    /// The params file, or "built-in lathe disc".
    pub source: String,
    /// r_i, m.
    pub inner_radius: f64,
    /// r_a, m.
    pub outer_radius: f64,
    /// h, m.
    pub thickness: f64,
    /// Boundary condition at r_i (`clamped`, `free`, …).
    pub inner_boundary: &'static str,
    /// Boundary condition at r_a.
    pub outer_boundary: &'static str,
    /// The k of the scene's modes (nodal diameters).
    pub nodal_diameters: Vec<u32>,
    /// The l of the scene's modes (nodal circles).
    pub nodal_circles: Vec<u32>,
    /// The scene's `plate.radial_splines`.
    pub radial_splines: crate::config::RadialSplines,
    /// Elastic modes of the scene's model.
    pub modes: usize,
    /// The joint's speed Ω, rad/s.
    pub speed_rad_s: f64,
    /// The scene's `simulation.integrator`.
    pub integrator: &'static str,
    /// The scene's `simulation.rate_hz`, Hz.
    pub rate_hz: f64,
}

/// Everything `study` measured.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct StudyReport {
    /// The JSON document's version, `annular_plate.study/1`.
    pub schema: &'static str,
    /// The scene studied.
    pub scene: SceneSummary,
    /// The plan measured.
    pub plan: StudyPlan,
    /// Axis 1: natural-frequency error against radial splines.
    pub radial_splines: FrequencyAxis,
    /// With `plate.in_plane_nodal_diameters`: the in-plane modes'
    /// frequency error against radial splines (absent without them).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub in_plane_radial_splines: Option<InPlaneFrequencyAxis>,
    /// With `plate.in_plane_nodal_diameters` and an in-plane ALE force: the
    /// in-plane static displacement error against the in-plane orders
    /// (absent otherwise; without the force `notes` says so).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub in_plane_mode_count: Option<InPlaneResponseAxis>,
    /// Axis 2: steady deflection error against the mode set (None under
    /// Mindlin theory: the deflection at a point force does not converge; `notes`).
    pub mode_count: Option<ResponseAxis>,
    /// Axis 3: trajectory error against integrator and rate.
    pub integrator: TrajectoryAxis,
    /// Kirchhoff against Mindlin theory: model error against cost.
    pub theory: TheoryComparison,
    /// What the study left out and why (absent when empty).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub notes: Vec<String>,
    /// Wall time of the whole study, s.
    pub wall_time_s: f64,
}

/// The default scene: the paper's lathe disc (section 5.1) — r_i = 0.075 m,
/// r_a = 0.15 m, h = 0.01 m, steel, clamped inside, free outside, k = 0..7,
/// l = 0..1, ζ = 0.02 — turning at the cutting speed 100 m/min at the rim
/// (Ω = 100/60/0.15 = 11.1 rad/s) under a 100 N space-fixed feed force on the
/// rim at θ = 0, at 1 kHz with the exponential integrator.
pub fn lathe_scene() -> Config {
    let mut c = Config::default();
    c.plate.damping = vec![0.02];
    c.nodes.ale = vec![NodePosition {
        radial: 1.0,
        angular: 0.0,
    }];
    c.loads.ale = vec![WrenchConfig {
        force: [0.0, 0.0, -100.0],
        moment: [0.0; 3],
    }];
    c.joint.speed = 100.0 / 60.0 / 0.15;
    c.simulation.realtime_factor = 0.0;
    c
}

/// Run the whole study. `progress(done, total, what)` is called before each unit of work.
pub fn run(
    config: &Config,
    source: &str,
    plan: &StudyPlan,
    progress: &mut dyn FnMut(usize, usize, &str),
) -> Result<StudyReport, StudyError> {
    if plan.targets.iter().any(|t| !(t.is_finite() && *t > 0.0)) {
        return Err(StudyError::BadPlan {
            detail: format!("targets must be positive, got {:?}", plan.targets),
        });
    }
    // Axes 1 and 2 and the theory comparison are of the bending modes; the
    // in-plane ones have their own frequency axis and are in every sample of
    // axis 3.
    let mut bending = config.clone();
    bending.plate.in_plane_nodal_diameters.clear();
    let started = Instant::now();
    let total = plan.units(config);
    let mut done = 0usize;
    let mut tick = |what: &str| {
        progress(done, total, what);
        done += 1;
    };
    let model_modes = config.plate.mode_count();
    let radial_splines = frequency::run(&bending.plate, plan, &mut tick)?;
    let in_plane_radial_splines =
        in_plane_frequency::run(&config.plate, &config.centrifugal, plan, &mut tick)?;
    let mut notes = Vec::new();
    if in_plane_radial_splines.is_some() {
        notes.push(IN_PLANE_NOTE.to_string());
    }
    let mode_count = match config.plate.theory {
        PlateTheory::Kirchhoff => Some(response::run(&bending, plan, &mut tick)?),
        PlateTheory::Mindlin => {
            notes.push(MINDLIN_MODE_COUNT_NOTE.to_string());
            None
        }
    };
    let in_plane_mode_count = in_plane_response::run(config, plan, &mut tick, &mut notes)?;
    let integrator = trajectory::run(config, plan, &mut tick)?;
    let theory = theory::run(&bending.plate, plan, &mut tick)?;
    progress(total, total, "done");
    let p = &config.plate;
    Ok(StudyReport {
        schema: SCHEMA,
        scene: SceneSummary {
            source: source.to_string(),
            inner_radius: p.inner_radius,
            outer_radius: p.outer_radius,
            thickness: p.thickness,
            inner_boundary: p.inner_boundary.name(),
            outer_boundary: p.outer_boundary.name(),
            nodal_diameters: p.nodal_diameters.clone(),
            nodal_circles: p.nodal_circles.clone(),
            radial_splines: p.radial_splines,
            modes: model_modes,
            speed_rad_s: config.joint.speed,
            integrator: config.simulation.integrator.name(),
            rate_hz: config.simulation.rate_hz,
        },
        plan: plan.clone(),
        radial_splines,
        in_plane_radial_splines,
        in_plane_mode_count,
        mode_count,
        integrator,
        theory,
        notes,
        wall_time_s: started.elapsed().as_secs_f64(),
    })
}
