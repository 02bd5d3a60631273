//! How many inner substeps an integrator takes, and which substeps the
//! integrators that hold the models' forces refuse: λ_max of the modes with
//! the models' coupling, the in-plane spin terms and a free joint's ω*, and
//! the models' damping at a substep's start.

use super::{Stepper, StepperSettings};
use crate::config::IntegratorKind;
use crate::dynamics::error::StepError;
use crate::dynamics::integrators::MAX_INNER_SUBSTEPS;
use crate::dynamics::load_models::HELD_DAMPING_LIMIT;
use crate::dynamics::scene::Scene;

impl Stepper {
    /// Inner substeps a substep of h needs at speeds up to |Ω| so that
    /// h·λ_max stays below the integrator's step limit (1 for the exponential
    /// integrator).
    pub fn inner_substeps(
        &self,
        scene: &Scene,
        settings: &StepperSettings,
        h: f64,
        speed: f64,
    ) -> usize {
        let Some((limit, _)) = settings.step_limit() else {
            return 1;
        };
        let lambda = self.lambda_max(scene, speed);
        let relaxation = scene.load_models.coupling().relaxation_rate;
        let substeps = |rate: f64, limit: f64| ((h * rate / limit).ceil() as usize).max(1);
        if settings.integrator != IntegratorKind::Rk4 {
            return substeps(lambda + relaxation, limit);
        }
        // RK4 evaluates the models at every stage: their damping at the
        // substep's start needs its stability on the negative real axis,
        // and a massless state's relaxation a monotone decay.
        substeps(lambda, limit)
            .max(substeps(self.held_damping_rate, RK4_DAMPING_LIMIT))
            .max(substeps(relaxation, RK4_RELAXATION_LIMIT))
    }

    /// λ_max = max over the modes of |ω_eff| + 2ζω + kΩ (a torsional mode's
    /// at least the free joint's ω* where the joint may be free), the load models'
    /// coupling included as bounded in [`LoadModels`](super::load_models::LoadModels),
    /// and the in-plane spin terms' Gershgorin bounds (`InPlaneSpinTerms::rate_bounds`, made once).
    pub(super) fn lambda_max(&self, scene: &Scene, speed: f64) -> f64 {
        let c = scene.load_models.coupling();
        let stiffening = scene
            .stiffening
            .as_ref()
            .map_or(0.0, |s| s.rate_bound * speed * speed);
        let (spin_stiffness, coriolis) = scene.in_plane.as_ref().map_or((0.0, 0.0), |ip| {
            let (k, g) = ip.spin.rate_bounds;
            (k * speed * speed, g * speed.abs())
        });
        // A torque-limited drive may leave the joint free: its torsional
        // modes then ring at up to ω* (InPlaneDynamics::free_joint_rate).
        let free = scene
            .in_plane
            .as_ref()
            .map_or(0.0, |ip| ip.free_joint_omega * ip.free_joint_omega);
        scene
            .elastic_modes()
            .zip(&self.consts)
            .enumerate()
            .map(|(i, ((k, ..), mc))| {
                let own = match &scene.in_plane {
                    Some(ip) if ip.coupling_of(i) != 0.0 => mc.omega_eff_sq.abs().max(free),
                    _ => mc.omega_eff_sq.abs(),
                };
                (own + stiffening + spin_stiffness + c.stiffness_rate_sq).sqrt()
                    + mc.damping_rate
                    + c.damping_rate
                    + coriolis
                    + k as f64 * speed.abs()
            })
            .fold(0.0, f64::max)
    }

    /// Refuse a substep of `h` whose held model forces would not resolve the
    /// models' damping at its start (`LoadModels::held_damping_rate`).
    pub(super) fn check_held_damping(
        &self,
        settings: &StepperSettings,
        h: f64,
        speed: f64,
    ) -> Result<(), StepError> {
        let rate = self.held_damping_rate;
        if h * rate > HELD_DAMPING_LIMIT {
            return Err(StepError::HeldDampingTooFast {
                integrator: settings.integrator.name(),
                rate,
                step: h,
                limit: HELD_DAMPING_LIMIT,
                speed,
            });
        }
        Ok(())
    }

    /// The inner substeps for a substep of h from Ω0 under α, or the refusal.
    pub(super) fn checked_inner_substeps(
        &self,
        scene: &Scene,
        settings: &StepperSettings,
        h: f64,
        speed0: f64,
        alpha: f64,
    ) -> Result<usize, StepError> {
        let speed_max = speed0.abs().max((speed0 + alpha * h).abs());
        let inner = self.inner_substeps(scene, settings, h, speed_max);
        if inner > MAX_INNER_SUBSTEPS {
            return Err(StepError::TooManySubsteps {
                integrator: settings.integrator.name(),
                needed: inner,
                limit: MAX_INNER_SUBSTEPS,
                step: h,
            });
        }
        Ok(inner)
    }
}

/// Largest h × (the models' damping at a substep's start) per RK4 inner
/// step: inside RK4's stability interval on the negative real axis,
/// hσ < 2.785 (its stages evaluate the models, so no held force lags).
const RK4_DAMPING_LIMIT: f64 = 2.5;

/// Largest h × (the models' relaxation rate, `Coupling::relaxation_rate`)
/// per RK4 inner step. A massless state relaxing at σ decays by RK4's
/// R(−hσ) = 1 − hσ + (hσ)²/2 − (hσ)³/6 + (hσ)⁴/24 per inner step, which at
/// hσ ≤ 1 is within 2 % of e^(−hσ) and positive: the relaxation is a real
/// eigenvalue that sets no frequency, so RK4 keeps it monotone instead of
/// resolving it to its step limit like a mode.
const RK4_RELAXATION_LIMIT: f64 = 1.0;
