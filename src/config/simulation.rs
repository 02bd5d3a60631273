//! `simulation.*`: the time integration and the loop's rate.

use serde::Serialize;

/// Time integration scheme (`simulation.integrator`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum IntegratorKind {
    /// Exact exponential per mode / mode pair for loads held over a step.
    Exponential,
    /// Implicit midpoint rule: A-stable, conserves the quadratic energy.
    ImplicitMidpoint,
    /// Classical explicit Runge–Kutta 4, sub-stepping itself below its stability limit.
    Rk4,
    /// The exponential of the load models' linearisation on their active set
    /// (stiff contacts), switches located inside the step.
    ContactExponential,
}

impl IntegratorKind {
    /// The parameter value (`exponential`, `implicit_midpoint`, `rk4`, `contact_exponential`).
    pub fn name(self) -> &'static str {
        match self {
            IntegratorKind::Exponential => "exponential",
            IntegratorKind::ImplicitMidpoint => "implicit_midpoint",
            IntegratorKind::Rk4 => "rk4",
            IntegratorKind::ContactExponential => "contact_exponential",
        }
    }
    /// From the parameter value; `None` for any other text.
    pub fn from_name(s: &str) -> Option<Self> {
        match s {
            "exponential" => Some(IntegratorKind::Exponential),
            "implicit_midpoint" => Some(IntegratorKind::ImplicitMidpoint),
            "rk4" => Some(IntegratorKind::Rk4),
            "contact_exponential" => Some(IntegratorKind::ContactExponential),
            _ => None,
        }
    }
}

/// Coordinates in which the elastic equations are integrated (`simulation.coordinates`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Coordinates {
    /// Modal amplitudes resolved in the rotating plate frame B.
    Lagrangian,
    /// Modal amplitudes resolved in the non-rotating frame A (eq. 20).
    Ale,
}

impl Coordinates {
    /// From the parameter value (`ale`, `lagrangian`); `None` for any other text.
    pub fn from_name(s: &str) -> Option<Self> {
        match s {
            "ale" => Some(Coordinates::Ale),
            "lagrangian" => Some(Coordinates::Lagrangian),
            _ => None,
        }
    }
}

/// `simulation.*`.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct SimulationConfig {
    /// Output rate and fixed step, Hz.
    pub rate_hz: f64,
    /// Integration sub-steps per output step.
    pub substeps: u32,
    /// The time integration scheme (`simulation.integrator`).
    pub integrator: IntegratorKind,
    /// The coordinates the elastic equations are integrated in (`simulation.coordinates`).
    pub coordinates: Coordinates,
    /// 1 = wall clock, 0 = as fast as possible (the node only).
    pub realtime_factor: f64,
    /// Publish every `publish_divisor`-th step (the node only).
    pub publish_divisor: u32,
    /// RK4 sub-steps itself so that h·λ_max stays below this (accuracy of the
    /// explicit reference; its amplitude error per step is (hω)⁶/144).
    pub rk4_step_limit: f64,
    /// The implicit midpoint rule sub-steps itself so that h·λ_max stays below
    /// this (its relative frequency error is 1 − 2·atan(hω/2)/(hω) ≈ (hω)²/12).
    pub midpoint_step_limit: f64,
    /// `contact_exponential` halves its spans until the local error of what
    /// it holds over a span (the friction direction, follower terms) is below
    /// this, relative to the state's scale.
    pub contact_tolerance: f64,
}

/// The declared defaults of the `simulation.*` keys (`config/table.rs`).
impl Default for SimulationConfig {
    fn default() -> Self {
        use super::defaults::{default_f64, default_i64, default_str};
        SimulationConfig {
            rate_hz: const { default_f64("simulation.rate_hz") },
            substeps: const { default_i64("simulation.substeps") } as u32,
            integrator: IntegratorKind::from_name(default_str("simulation.integrator"))
                .expect("the declared integrator default is an integrator"),
            coordinates: Coordinates::from_name(default_str("simulation.coordinates"))
                .expect("the declared coordinates default is a choice"),
            realtime_factor: const { default_f64("simulation.realtime_factor") },
            publish_divisor: const { default_i64("simulation.publish_divisor") } as u32,
            rk4_step_limit: DEFAULT_RK4_STEP_LIMIT,
            midpoint_step_limit: DEFAULT_MIDPOINT_STEP_LIMIT,
            contact_tolerance: const { default_f64("simulation.contact_tolerance") },
        }
    }
}

/// Default of `simulation.rk4_step_limit` (its declaration).
pub const DEFAULT_RK4_STEP_LIMIT: f64 = super::defaults::default_f64("simulation.rk4_step_limit");
/// Default of `simulation.midpoint_step_limit` (its declaration): the fastest
/// retained mode's frequency within 2.0 % (1 − 2·atan(0.25)/0.5), slower
/// ones as (hω)²/12.
pub const DEFAULT_MIDPOINT_STEP_LIMIT: f64 =
    super::defaults::default_f64("simulation.midpoint_step_limit");
/// Smallest `simulation.contact_tolerance` (below it rounding decides).
pub const MIN_CONTACT_TOLERANCE: f64 = 1.0e-14;
/// Largest `simulation.midpoint_step_limit`: large enough to accept unresolved
/// modes on purpose (the rule stays A-stable but rings without numerical damping).
pub const MAX_MIDPOINT_STEP_LIMIT: f64 = 1e6;
/// Largest `simulation.rk4_step_limit`: RK4's stability limit on the imaginary axis is 2√2.
pub const MAX_RK4_STEP_LIMIT: f64 = 2.5;
