//! The fixed-step stepper: borrows the immutable [`Scene`] and the plain
//! [`State`], owns only scratch space allocated once (no allocation per step).
//!
//! Each substep: the load models (pads, tool, links) from the node kinematics,
//! then node loads at the step start (follower loads use the current
//! deflection), the joint drive → constant joint acceleration α over the
//! substep (χ exact and quadratic in time), then the elastic coordinates by
//! the chosen integrator, then the tool's state (the surface it cut). RK4
//! re-evaluates the memoryless load models (pads, links) at every stage. A
//! step that produces a non-finite or implausible state is undone and reported.

use super::ale::{ale_to_lagrange, harmonics, lagrange_to_ale};
use super::integrators::equations::{accelerations, mode_constants, ModeConstants};
use super::integrators::exponential::ModePropagator;
use super::integrators::{implicit_midpoint, rk4};
use super::joint::drive;
use super::load_models::{surface_kinematics, ModelWrenches};
use super::loads::{add_reference_motion, compute as node_loads, Inputs, StepLoads};
use super::scene::Scene;
use super::simulation::StepError;
use super::state::{JointAngle, State};
use crate::config::{Coordinates, IntegratorKind};
use nalgebra::Complex;

/// Both descriptions of the elastic state at one instant.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Views {
    pub q_lagrange: Vec<f64>,
    pub q_dot_lagrange: Vec<f64>,
    pub q_ale: Vec<f64>,
    pub q_dot_ale: Vec<f64>,
}

impl Views {
    pub fn new(n: usize) -> Views {
        Views { q_lagrange: vec![0.0; n], q_dot_lagrange: vec![0.0; n], q_ale: vec![0.0; n], q_dot_ale: vec![0.0; n] }
    }

    /// Fill both descriptions from the state (`harm` is scratch).
    pub fn update(&mut self, scene: &Scene, state: &State, harm: &mut Vec<(f64, f64)>) {
        harmonics(&state.chi, scene.layout.k_max, harm);
        self.q_lagrange.copy_from_slice(&state.q);
        self.q_dot_lagrange.copy_from_slice(&state.q_dot);
        self.q_ale.copy_from_slice(&state.q);
        self.q_dot_ale.copy_from_slice(&state.q_dot);
        match state.coordinates {
            Coordinates::Lagrangian => lagrange_to_ale(&scene.layout, harm, state.speed, &mut self.q_ale, &mut self.q_dot_ale),
            Coordinates::Ale => ale_to_lagrange(&scene.layout, harm, state.speed, &mut self.q_lagrange, &mut self.q_dot_lagrange),
        }
    }
}

/// Integrator settings (one documented plain struct, like rapier's IntegrationParameters).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StepperSettings {
    pub integrator: IntegratorKind,
    /// Output step, s.
    pub dt: f64,
    pub substeps: u32,
    /// RK4: h·λ_max per inner step (`simulation.rk4_step_limit`).
    pub rk4_step_limit: f64,
}

pub struct Stepper {
    settings: StepperSettings,
    consts: Vec<ModeConstants>,
    loads: StepLoads,
    base_ale_frame: Vec<f64>,
    harm: Vec<(f64, f64)>,
    harm_end: Vec<(f64, f64)>,
    views: Views,
    propagators: Vec<ModePropagator>,
    y: Vec<f64>,
    rk: [Vec<f64>; 5],
    backup: State,
    /// RK4 substeps used in the last step (1 for the other integrators).
    last_inner_substeps: usize,
    /// Wrenches of the load models at the last evaluation.
    model_wrenches: ModelWrenches,
}

impl Stepper {
    pub fn new(scene: &Scene, settings: StepperSettings) -> Stepper {
        let n = scene.n_modes();
        let k = scene.layout.k_max as usize + 1;
        Stepper {
            settings,
            consts: mode_constants(scene),
            loads: StepLoads::new(n),
            base_ale_frame: vec![0.0; n],
            harm: Vec::with_capacity(k),
            harm_end: Vec::with_capacity(k),
            views: Views::new(n),
            propagators: vec![ModePropagator::UNSET; n],
            y: vec![0.0; 2 * n],
            rk: std::array::from_fn(|_| vec![0.0; 2 * n]),
            backup: State::new(n, Coordinates::Ale, 0.0, 0.0),
            last_inner_substeps: 1,
            model_wrenches: ModelWrenches::new(scene),
        }
    }

    /// Both descriptions of the state after the last step (or [`Stepper::sync_views`]).
    pub fn views(&self) -> &Views {
        &self.views
    }

    /// Refill both descriptions from `state` (after a reset or restore).
    pub fn sync_views(&mut self, scene: &Scene, state: &State) {
        self.views.update(scene, state, &mut self.harm);
    }

    pub fn last_inner_substeps(&self) -> usize {
        self.last_inner_substeps
    }

    pub fn settings(&self) -> StepperSettings {
        self.settings
    }

    /// Substep length h = dt / substeps.
    pub fn h(&self) -> f64 {
        self.settings.dt / self.settings.substeps as f64
    }

    /// RK4 substeps a step of h needs at speeds up to |Ω| (the pads' stiffness
    /// and damping included, as bounded in [`LoadModels`](super::LoadModels)).
    pub fn rk4_substeps(&self, scene: &Scene, h: f64, speed: f64) -> usize {
        let lm = &scene.load_models;
        let lam = scene
            .model
            .modes()
            .iter()
            .zip(&self.consts)
            .map(|(m, c)| (c.omega_eff_sq.abs() + lm.pad_stiffness_rate_sq).sqrt() + c.damping_rate + lm.pad_damping_rate + m.k as f64 * speed.abs())
            .fold(0.0, f64::max);
        ((h * lam / self.settings.rk4_step_limit).ceil() as usize).max(1)
    }

    /// Advance one output step. On error the state is as before the call.
    pub fn step(&mut self, scene: &Scene, state: &mut State, inputs: &Inputs) -> Result<(), StepError> {
        self.backup.copy_from(state);
        let h = self.h();
        let t0 = state.time;
        self.last_inner_substeps = 1;
        for _ in 0..self.settings.substeps {
            if let Err(e) = self.substep(scene, state, inputs, h) {
                state.copy_from(&self.backup);
                self.sync_views(scene, state);
                return Err(e);
            }
        }
        state.time = t0 + self.settings.dt;
        if let Err(e) = check(scene, state) {
            state.copy_from(&self.backup);
            self.sync_views(scene, state);
            return Err(e);
        }
        Ok(())
    }

    /// One substep. On entry `self.views` and `self.harm` describe `state`
    /// (kept so by every step and by [`Stepper::sync_views`]); on exit too.
    fn substep(&mut self, scene: &Scene, state: &mut State, inputs: &Inputs, h: f64) -> Result<(), StepError> {
        let models = &scene.load_models;
        let tool_step = match (&models.tool, &state.load_models.tool) {
            (Some(tool), Some(ts)) => {
                let w = surface_kinematics(&scene.ale_nodes[tool.node], &self.views.q_ale, &self.views.q_dot_ale).w;
                Some(tool.begin(ts, w, state.chi.angle, state.speed, h))
            }
            _ => None,
        };
        let tool_force = tool_step.map_or(0.0, |s| s.force);
        if !models.is_empty() {
            // Prescribed link forces at the substep's mid-angle (held by the non-RK4 integrators).
            let chi_mid = state.chi.angle + 0.5 * state.speed * h;
            let v = &self.views;
            models.evaluate(&scene.ale_nodes, &v.q_ale, &v.q_dot_ale, chi_mid, state.speed, &inputs.commands, tool_force, &mut self.model_wrenches);
        }
        node_loads(scene, inputs, &self.model_wrenches, &self.views.q_ale, &self.views.q_lagrange, &mut self.loads);
        let d = drive(&scene.joint, scene.polar_inertia, state.speed, inputs.speed_command, self.loads.axial_torque, &self.model_wrenches.friction, h);
        let (speed0, alpha) = (state.speed, d.acceleration);
        let speed_mean = speed0 + 0.5 * alpha * h;
        let chi0 = state.chi;
        let mut chi1 = chi0;
        chi1.advance(speed_mean * h);
        let speed1 = speed0 + alpha * h;

        match self.settings.integrator {
            IntegratorKind::Exponential => {
                add_reference_motion(scene, speed_mean, &mut self.loads.ale_frame);
                self.exponential(scene, h, speed_mean);
                // The result is the Lagrangian view at χ1: derive the ALE one.
                let v = &mut self.views;
                v.q_ale.copy_from_slice(&v.q_lagrange);
                v.q_dot_ale.copy_from_slice(&v.q_dot_lagrange);
                harmonics(&chi1, scene.layout.k_max, &mut self.harm);
                lagrange_to_ale(&scene.layout, &self.harm, speed1, &mut v.q_ale, &mut v.q_dot_ale);
                let (q, q_dot) = match state.coordinates {
                    Coordinates::Lagrangian => (&v.q_lagrange, &v.q_dot_lagrange),
                    Coordinates::Ale => (&v.q_ale, &v.q_dot_ale),
                };
                state.q.copy_from_slice(q);
                state.q_dot.copy_from_slice(q_dot);
            }
            IntegratorKind::ImplicitMidpoint => {
                add_reference_motion(scene, speed_mean, &mut self.loads.ale_frame);
                let mut chi_mid = chi0;
                chi_mid.advance(0.5 * h * speed0 + 0.125 * alpha * h * h);
                harmonics(&chi_mid, scene.layout.k_max, &mut self.harm_end);
                implicit_midpoint::advance(
                    scene,
                    &self.consts,
                    state.coordinates,
                    h,
                    &self.harm_end,
                    speed_mean,
                    alpha,
                    &self.loads.ale_frame,
                    &self.loads.plate_frame,
                    &mut state.q,
                    &mut state.q_dot,
                );
            }
            IntegratorKind::Rk4 => self.rk4(scene, state, inputs, h, chi0, speed0, alpha, tool_force)?,
        }
        if let (Some(step), Some(tool), Some(ts)) = (tool_step, &models.tool, &mut state.load_models.tool) {
            tool.commit(ts, &step, inputs.commands.feed_rate, h);
        }
        state.chi = chi1;
        state.speed = speed1;
        state.acceleration = alpha;
        state.effort = d.effort;
        state.time += h;
        if self.settings.integrator != IntegratorKind::Exponential {
            self.views.update(scene, state, &mut self.harm);
        }
        Ok(())
    }

    /// Exact step of the Lagrangian view (in `self.views`) over h.
    fn exponential(&mut self, scene: &Scene, h: f64, speed_mean: f64) {
        let soft = scene.off_axis_rate_squared();
        let v = &mut self.views;
        let f = &self.loads;
        for (i, m) in scene.model.modes().iter().enumerate() {
            let nu = m.k as f64 * speed_mean;
            let p = &mut self.propagators[i];
            if p.h != h || p.nu != nu {
                *p = ModePropagator::new(m.modal_mass, m.damping, m.omega, soft, h, nu);
            }
        }
        for &i in &scene.layout.axisymmetric {
            let (q, qd) = self.propagators[i].advance(v.q_lagrange[i], v.q_dot_lagrange[i], f.ale_frame[i], Complex::new(0.0, 0.0));
            v.q_lagrange[i] = q;
            v.q_dot_lagrange[i] = qd;
        }
        for p in &scene.layout.pairs {
            let (co, si) = self.harm[p.k as usize];
            let e0 = Complex::new(co, si);
            let (fc, fs) = (f.ale_frame[p.cos], f.ale_frame[p.sin]);
            let gc = Complex::new(fc, -fs) * e0;
            let gs = Complex::new(fs, fc) * e0;
            for (idx, g) in [(p.cos, gc), (p.sin, gs)] {
                let (q, qd) = self.propagators[idx].advance(v.q_lagrange[idx], v.q_dot_lagrange[idx], f.plate_frame[idx], g);
                v.q_lagrange[idx] = q;
                v.q_dot_lagrange[idx] = qd;
            }
        }
    }

    #[allow(clippy::too_many_arguments)]
    fn rk4(&mut self, scene: &Scene, state: &mut State, inputs: &Inputs, h: f64, chi0: JointAngle, speed0: f64, alpha: f64, tool_force: f64) -> Result<(), StepError> {
        let speed_max = speed0.abs().max((speed0 + alpha * h).abs());
        let inner = self.rk4_substeps(scene, h, speed_max);
        if inner > rk4::MAX_SUBSTEPS {
            return Err(StepError::ExplicitTooCostly { needed: inner, limit: rk4::MAX_SUBSTEPS, step: h });
        }
        self.last_inner_substeps = self.last_inner_substeps.max(inner);
        let n = scene.n_modes();
        let coords = state.coordinates;
        self.y[..n].copy_from_slice(&state.q);
        self.y[n..].copy_from_slice(&state.q_dot);
        self.base_ale_frame.copy_from_slice(&self.loads.ale_frame);
        let Stepper { consts, loads, base_ale_frame, harm, views, y, rk, model_wrenches, .. } = self;
        let follower = scene.effects.follower_loads;
        let stage_models = scene.load_models.stage_dependent();
        let dt = h / inner as f64;
        let mut rhs = |t: f64, yy: &[f64], dy: &mut [f64]| {
            let mut chi = chi0;
            chi.advance(speed0 * t + 0.5 * alpha * t * t);
            let speed = speed0 + alpha * t;
            harmonics(&chi, scene.layout.k_max, harm);
            let (q, v) = yy.split_at(n);
            if follower || stage_models {
                let st = StateView { q, v, coords, speed };
                st.fill(scene, harm, views);
                if stage_models {
                    let models = &scene.load_models;
                    models.evaluate(&scene.ale_nodes, &views.q_ale, &views.q_dot_ale, chi.angle, speed, &inputs.commands, tool_force, model_wrenches);
                }
                node_loads(scene, inputs, model_wrenches, &views.q_ale, &views.q_lagrange, loads);
            } else {
                loads.ale_frame.copy_from_slice(base_ale_frame);
            }
            add_reference_motion(scene, speed, &mut loads.ale_frame);
            let (dq, dv) = dy.split_at_mut(n);
            dq.copy_from_slice(v);
            accelerations(scene, consts, coords, harm, speed, alpha, q, v, &loads.ale_frame, &loads.plate_frame, dv);
        };
        for j in 0..inner {
            rk4::step(j as f64 * dt, dt, y, rk, &mut rhs);
        }
        state.q.copy_from_slice(&y[..n]);
        state.q_dot.copy_from_slice(&y[n..]);
        Ok(())
    }
}

/// Amplitudes and rates in one description, for filling both views mid-step.
struct StateView<'a> {
    q: &'a [f64],
    v: &'a [f64],
    coords: Coordinates,
    speed: f64,
}

impl StateView<'_> {
    fn fill(&self, scene: &Scene, harm: &[(f64, f64)], views: &mut Views) {
        for buf in [&mut views.q_lagrange, &mut views.q_ale] {
            buf.copy_from_slice(self.q);
        }
        for buf in [&mut views.q_dot_lagrange, &mut views.q_dot_ale] {
            buf.copy_from_slice(self.v);
        }
        match self.coords {
            Coordinates::Lagrangian => lagrange_to_ale(&scene.layout, harm, self.speed, &mut views.q_ale, &mut views.q_dot_ale),
            Coordinates::Ale => ale_to_lagrange(&scene.layout, harm, self.speed, &mut views.q_lagrange, &mut views.q_dot_lagrange),
        }
    }
}

/// Divergence guard: everything finite, amplitudes within the plausibility limit.
fn check(scene: &Scene, state: &State) -> Result<(), StepError> {
    if !state.is_finite() {
        return Err(StepError::Diverged { time: state.time, detail: "a state variable became NaN or infinite".into() });
    }
    let limit = scene.limits.max_deflection_thicknesses * scene.model.plate().thickness;
    if let Some((i, q)) = state.q.iter().enumerate().find(|(_, q)| q.abs() > limit) {
        let m = &scene.model.modes()[i];
        return Err(StepError::Diverged {
            time: state.time,
            detail: format!(
                "mode {} ⟨k = {}, l = {}, {}⟩ reached {q:e} m, beyond limits.max_deflection_thicknesses × thickness = {limit:e} m",
                i + 1,
                m.k,
                m.l,
                m.shape.name()
            ),
        });
    }
    if state.speed.abs() > scene.limits.max_speed * 1.5 {
        return Err(StepError::Diverged { time: state.time, detail: format!("joint speed {} rad/s beyond limits.max_speed", state.speed) });
    }
    Ok(())
}
