//! The fixed-step stepper: borrows the immutable [`Scene`] and the plain
//! [`State`], owns only scratch space allocated once (no allocation per step).
//!
//! Each substep: the load models (pads, tool, links) from the node kinematics,
//! then node loads at the step start (follower loads use the current
//! deflection), the joint drive → constant joint acceleration α over the
//! substep (χ exact and quadratic in time), then the elastic coordinates by
//! the chosen integrator, then the tool's state (the surface it cut). RK4
//! re-evaluates the memoryless load models (pads, links) at every stage.
//! Where `joint_in_y` holds (a torque-limited drive against the lining's
//! patches, or with torsional in-plane modes), RK4 and `contact_exponential`
//! instead integrate the joint with the elastic state, the drive's law at
//! every evaluation. A
//! step that produces a non-finite or implausible state is undone and reported.

use super::ale::lagrange_to_ale;
use super::commands::Inputs;
use super::error::StepError;
use super::integrators::block_exponential;
use super::integrators::contact_exponential::ContactExponential;
use super::integrators::equations::{mode_constants, ModeConstants};
use super::integrators::exponential::ModePropagator;
use super::integrators::stiffened_midpoint::StiffenedMidpoint;

use super::joint::{drive, friction_band_rate, StageDrive};
use super::load_models::{LoadContext, LoadModelState, LoadModelUndo, ModelWrenches};
use super::loads::{add_reference_motion, compute as node_loads, StepLoads};
use super::scene::Scene;
use super::state::{JointAngle, State};
use super::wrench::Wrench;
use crate::config::{Config, Coordinates, IntegratorKind};
use divergence::check;
use in_plane_joint::{joint_in_y, InPlaneJoint, Twist};
use model_evaluation::ModelEvaluation;

mod contact_step;
mod divergence;
mod held_load_steps;
mod in_plane_exponential;
mod in_plane_joint;
mod model_evaluation;
mod rk4_step;
mod stage_rhs;
mod substep_limits;

pub use super::integrators::contact_exponential::StepReport as ContactReport;

/// Both descriptions of the elastic state mid-step (RK4 stages): scratch.
#[derive(Debug, Clone, PartialEq, Default)]
struct Views {
    q_lagrange: Vec<f64>,
    q_dot_lagrange: Vec<f64>,
    q_ale: Vec<f64>,
    q_dot_ale: Vec<f64>,
}

impl Views {
    fn new(n: usize) -> Views {
        Views {
            q_lagrange: vec![0.0; n],
            q_dot_lagrange: vec![0.0; n],
            q_ale: vec![0.0; n],
            q_dot_ale: vec![0.0; n],
        }
    }
}

/// How the stepper integrates (one documented plain struct, like rapier's
/// `IntegrationParameters`): what `simulation.*` sets.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StepperSettings {
    /// `simulation.integrator`: exponential (exact per mode for held loads),
    /// implicit_midpoint or rk4 (docs/dynamics.md).
    pub integrator: IntegratorKind,
    /// Output step 1 / `simulation.rate_hz`, s.
    pub dt: f64,
    /// `simulation.substeps`: substeps of dt / substeps per output step.
    pub substeps: u32,
    /// RK4: largest h·λ_max per inner step (`simulation.rk4_step_limit`).
    pub rk4_step_limit: f64,
    /// Implicit midpoint: largest h·λ_max per inner step (`simulation.midpoint_step_limit`).
    pub midpoint_step_limit: f64,
    /// Contact exponential: the local error bound of the held remainder
    /// (`simulation.contact_tolerance`).
    pub contact_tolerance: f64,
}

impl Default for StepperSettings {
    /// The defaults of `simulation.*`: exponential at 1 kHz, one substep.
    fn default() -> Self {
        StepperSettings::from_config(&Config::default())
    }
}

impl StepperSettings {
    /// The settings a configuration asks for.
    pub fn from_config(config: &Config) -> StepperSettings {
        let s = &config.simulation;
        StepperSettings {
            integrator: s.integrator,
            dt: 1.0 / s.rate_hz,
            substeps: s.substeps,
            rk4_step_limit: s.rk4_step_limit,
            midpoint_step_limit: s.midpoint_step_limit,
            contact_tolerance: s.contact_tolerance,
        }
    }

    /// The integrator's largest h·λ_max per inner step and the parameter that
    /// sets it; `None` for the exponential integrator, exact for the modes at
    /// any step. One criterion for all (docs/hard_cases.md).
    pub fn step_limit(&self) -> Option<(f64, &'static str)> {
        match self.integrator {
            IntegratorKind::Exponential | IntegratorKind::ContactExponential => None,
            IntegratorKind::ImplicitMidpoint => {
                Some((self.midpoint_step_limit, "simulation.midpoint_step_limit"))
            }
            IntegratorKind::Rk4 => Some((self.rk4_step_limit, "simulation.rk4_step_limit")),
        }
    }

    /// Substep length h = dt / substeps.
    pub fn h(&self) -> f64 {
        self.dt / self.substeps as f64
    }
}

/// Scratch space for stepping a scene, allocated once: no state, no settings.
pub struct Stepper {
    consts: Vec<ModeConstants>,
    loads: StepLoads,
    base_ale_frame: Vec<f64>,
    harm: Vec<(f64, f64)>,
    harm_end: Vec<(f64, f64)>,
    /// The exponential step's harmonics (cos kχ, sin kχ) and the angle they
    /// are of: a step ends where the next one starts, so its χ1 harmonics are
    /// the next step's χ0 ones (computed once, not twice).
    exp_harm: Vec<(f64, f64)>,
    exp_harm_at: Option<JointAngle>,
    /// χ1's harmonics while a step is computed.
    exp_harm_next: Vec<(f64, f64)>,
    /// The (h, Ω̄) every propagator in `propagators` is for: a step at the
    /// same substep and mean speed skips checking them mode by mode.
    propagators_for: Option<(f64, f64)>,
    /// The node loads of the held wrenches when nothing else enters them (no
    /// follower loads, no load models), with the wrenches they are of.
    held_loads: Option<HeldLoads>,
    /// Both descriptions at an RK4 stage.
    views: Views,
    /// Per-mode exact propagators, keyed by (h, kΩ): recomputed when either changes.
    propagators: Vec<ModePropagator>,
    /// RK4's and the contact exponential's state (q, q̇, the load models'
    /// continuous states; within a step that integrates the joint, then its
    /// entries, at most [`JOINT_UNKNOWNS`], in capacity reserved) and RK4's stages.
    y: Vec<f64>,
    rk: [Vec<f64>; 5],
    /// The load models' slots at an RK4 stage (models with continuous states).
    stage_slots: LoadModelState,
    /// The state before the step (the load models' slots apart) and the log
    /// of what the step changed in those slots: a diverged step is undone.
    backup: State,
    undo: LoadModelUndo,
    /// Inner substeps used in the last step (1 for the exponential integrator).
    last_inner_substeps: usize,
    /// The load models' damping at the current substep's start, 1/s
    /// (`LoadModels::held_damping_rate`; set by each substep before use).
    held_damping_rate: f64,
    /// Wrenches of the load models at the last evaluation, and what it was of.
    model_wrenches: ModelWrenches,
    evaluation: ModelEvaluation,
    /// Centrifugal stiffening: one exact propagator per family of each
    /// k-block (cos, sin) and the implicit midpoint's block scratch; empty
    /// when off.
    stiffened: Vec<block_exponential::BlockPropagator>,
    stiffened_midpoint: StiffenedMidpoint,
    /// `contact_exponential`: the integrator and its piece cache (made at
    /// the first step, for its h's levels), the key of what a step holds,
    /// and what the last step did.
    contact: Option<ContactExponential>,
    /// The levels and unknowns `contact` is made for.
    contact_levels: Option<(usize, usize)>,
    contact_key: Vec<u64>,
    last_contact: ContactReport,
    /// `contact_exponential` substeps finished without locating their
    /// switches past `MAX_EVENTS` (Zeno-like chatter), since the stepper was made.
    unlocated_substeps: u64,
    /// λ_max at Ω = 0 (the modes with every contact closed): the rate
    /// `contact_exponential`'s levels sample every quarter radian.
    rate_at_rest: f64,
    /// The torsional in-plane modes' coupling with the joint over a substep.
    in_plane_joint: InPlaneJoint,
    /// The in-plane modes' exact propagators with their spin terms, one per k.
    in_plane_spin: Vec<block_exponential::BlockPropagator>,
}

impl Stepper {
    /// Scratch sized for the scene: no allocation per step.
    pub fn new(scene: &Scene) -> Stepper {
        let n = scene.n_modes();
        let k = scene.layout.k_max as usize + 1;
        let mut stepper = Stepper {
            consts: mode_constants(scene),
            loads: StepLoads::new(n),
            base_ale_frame: vec![0.0; n],
            harm: Vec::with_capacity(k),
            harm_end: Vec::with_capacity(k),
            exp_harm: Vec::with_capacity(k),
            exp_harm_at: None,
            exp_harm_next: Vec::with_capacity(k),
            propagators_for: None,
            held_loads: None,
            views: Views::new(n),
            propagators: vec![ModePropagator::UNSET; n],
            y: {
                let mut y = Vec::with_capacity(scene.first_order_unknowns() + JOINT_UNKNOWNS);
                y.resize(scene.first_order_unknowns(), 0.0);
                y
            },
            rk: std::array::from_fn(|_| vec![0.0; scene.first_order_unknowns() + JOINT_UNKNOWNS]),
            stage_slots: scene.load_models.initial_state(),
            backup: State::new(n, Coordinates::Ale, 0.0, 0.0),
            undo: LoadModelUndo::new(&scene.load_models),
            last_inner_substeps: 1,
            held_damping_rate: 0.0,
            model_wrenches: scene.model_wrenches(),
            evaluation: ModelEvaluation::with_capacity(model_evaluation::key_len(scene)),
            stiffened: scene
                .stiffening
                .iter()
                .flat_map(|s| &s.blocks)
                .flat_map(|b| {
                    b.families()
                        .map(|f| block_exponential::BlockPropagator::new(f.len()))
                })
                .collect(),
            stiffened_midpoint: StiffenedMidpoint::new(scene.stiffening.as_ref()),
            contact: None,
            contact_levels: None,
            contact_key: Vec::with_capacity(64),
            last_contact: ContactReport::default(),
            unlocated_substeps: 0,
            rate_at_rest: 0.0,
            in_plane_joint: InPlaneJoint::new(scene),
            in_plane_spin: in_plane_exponential::propagators(scene.in_plane.as_ref()),
        };
        stepper.rate_at_rest = stepper.lambda_max(scene, 0.0);
        stepper
    }

    /// The most inner substeps a substep of the last step took (RK4 and the
    /// implicit midpoint rule sub-step to their step limit).
    pub fn last_inner_substeps(&self) -> usize {
        self.last_inner_substeps
    }

    /// What the last `contact_exponential` substep did (switches located, pieces built).
    pub fn last_contact(&self) -> ContactReport {
        self.last_contact
    }

    /// `contact_exponential` substeps finished span by span without locating
    /// their switches (more than `MAX_EVENTS` in one substep: Zeno-like
    /// chatter) since the stepper was made.
    pub fn unlocated_substeps(&self) -> u64 {
        self.unlocated_substeps
    }

    /// Advance `state` by one output step (dt) under `inputs`. On error the
    /// state is as before the call.
    pub fn step(
        &mut self,
        scene: &Scene,
        settings: &StepperSettings,
        state: &mut State,
        inputs: &Inputs,
    ) -> Result<(), StepError> {
        self.backup.copy_from_except_load_models(state);
        self.undo.begin(&scene.load_models, &state.load_models);
        let h = settings.h();
        self.last_inner_substeps = 1;
        let mut result = Ok(());
        for _ in 0..settings.substeps {
            result = self.substep(scene, settings, state, inputs, h);
            if result.is_err() {
                break;
            }
        }
        if result.is_ok() {
            state.steps += 1;
            // Time as a count of steps: no drift from repeated addition.
            state.time = state.steps as f64 * settings.dt;
            result = check(scene, state);
        }
        if result.is_err() {
            state.copy_from_except_load_models(&self.backup);
            self.undo.restore(&mut state.load_models);
        }
        result
    }

    /// One substep: load models and node loads at its start, the joint, the
    /// elastic coordinates, the models' memory. On exit both descriptions in
    /// `state` describe its end.
    fn substep(
        &mut self,
        scene: &Scene,
        settings: &StepperSettings,
        state: &mut State,
        inputs: &Inputs,
        h: f64,
    ) -> Result<(), StepError> {
        let models = &scene.load_models;
        if !models.is_empty() {
            let mut slots = std::mem::take(&mut state.load_models);
            let mut ctx = load_context(scene, state, inputs);
            models.begin_substep(&ctx, &mut slots, h);
            // Prescribed forces at the substep's mid-angle (held by the non-RK4 integrators).
            ctx.chi = state.chi.angle + 0.5 * state.speed * h;
            self.evaluation.evaluate(
                models,
                &ctx,
                &slots,
                &inputs.commands,
                &mut self.model_wrenches,
            );
            if settings.integrator != IntegratorKind::ContactExponential {
                self.held_damping_rate = models.held_damping_rate(&ctx, &mut self.model_wrenches);
            }
            state.load_models = slots;
        }
        self.node_loads(scene, state, inputs);
        let (inertia, load_torque) = match &scene.in_plane {
            Some(ip) => {
                let (q, q_dot) = state.lagrange();
                let f = &self.loads.ale_frame;
                ip.reduced_joint(
                    scene.polar_inertia,
                    self.loads.axial_torque,
                    state.speed,
                    f,
                    q,
                    q_dot,
                )
            }
            None => (scene.polar_inertia, self.loads.axial_torque),
        };
        let d = drive(
            &scene.joint,
            inertia,
            state.speed,
            inputs.speed_command,
            load_torque,
            &self.model_wrenches.friction,
            h,
        );
        let stiff_models = models.stage_dependent();
        let friction = &self.model_wrenches.friction;
        let joint_in_y = joint_in_y(scene, settings.integrator, stiff_models, friction);
        if joint_in_y && settings.integrator == IntegratorKind::Rk4 {
            // The joint's friction band in RK4's stages (the held drive solves it implicitly).
            let speed_min = state.speed.abs() - 2.0 * d.acceleration.abs() * h;
            self.held_damping_rate += friction_band_rate(friction, inertia, speed_min);
        }
        let twist = if joint_in_y {
            Twist::rigid(&d)
        } else {
            self.in_plane_joint
                .begin(scene, state, &mut self.loads, &self.consts, &d, h)
        };
        let joint = SubstepMotion::new(h, state.chi, state.speed, twist.acceleration);
        let stage_drive = joint_in_y.then_some(StageDrive {
            joint: &scene.joint,
            polar_inertia: scene.polar_inertia,
            command: inputs.speed_command,
            h,
        });
        let mut joint_end = None;
        match settings.integrator {
            IntegratorKind::ContactExponential if stiff_models => {
                let tolerance = settings.contact_tolerance;
                joint_end =
                    self.contact_exponential(scene, state, inputs, &joint, tolerance, stage_drive)?;
            }
            IntegratorKind::Exponential | IntegratorKind::ContactExponential => {
                self.check_held_damping(settings, h, state.speed)?;
                add_reference_motion(scene, joint.speed_mean, &mut self.loads.ale_frame);
                self.exponential(scene, state, &joint);
            }
            IntegratorKind::ImplicitMidpoint => {
                self.check_held_damping(settings, h, state.speed)?;
                add_reference_motion(scene, joint.speed_mean, &mut self.loads.ale_frame);
                let inner =
                    self.checked_inner_substeps(scene, settings, h, joint.speed0, joint.alpha)?;
                self.last_inner_substeps = self.last_inner_substeps.max(inner);
                self.implicit_midpoint(scene, state, inner, &joint);
            }
            IntegratorKind::Rk4 => {
                joint_end = self.rk4(scene, settings, state, inputs, &joint, stage_drive)?;
            }
        }
        let end = joint_end.unwrap_or(JointEnd {
            chi1: joint.chi1,
            speed1: joint.speed1,
            acceleration: joint.alpha,
            effort: self.in_plane_joint.end(scene, state, twist, h),
        });
        state.chi = end.chi1;
        state.speed = end.speed1;
        state.acceleration = end.acceleration;
        state.effort = end.effort;
        state.time += h;
        let exact_both = match settings.integrator {
            IntegratorKind::Exponential => true,
            IntegratorKind::ContactExponential => !stiff_models,
            _ => false,
        };
        if !exact_both {
            state.rederive_with(&scene.layout, &mut self.harm);
        }
        if !models.is_empty() {
            models.save_changes(&state.load_models, &mut self.undo);
            let mut slots = std::mem::take(&mut state.load_models);
            models.commit_substep(
                &load_context(scene, state, inputs),
                &mut slots,
                &inputs.commands,
                h,
            );
            state.load_models = slots;
        }
        Ok(())
    }

    /// The node loads at the substep start into `self.loads`. When they depend
    /// on the wrenches alone (no follower loads, no load models) they are
    /// computed once per set of held wrenches and copied (the same numbers:
    /// [`node_loads`] of the same inputs).
    fn node_loads(&mut self, scene: &Scene, state: &State, inputs: &Inputs) {
        let (q_ale, _) = state.ale();
        let (q_lagrange, _) = state.lagrange();
        if scene.effects.follower_loads || !scene.load_models.is_empty() {
            return node_loads(
                scene,
                inputs,
                &self.model_wrenches,
                q_ale,
                q_lagrange,
                &mut self.loads,
            );
        }
        let fresh = !self
            .held_loads
            .as_ref()
            .is_some_and(|held| held.is_of(inputs));
        let held = self.held_loads.get_or_insert_with(|| HeldLoads {
            ale: Vec::new(),
            lagrange: Vec::new(),
            loads: StepLoads::new(scene.n_modes()),
        });
        if fresh {
            node_loads(
                scene,
                inputs,
                &self.model_wrenches,
                q_ale,
                q_lagrange,
                &mut held.loads,
            );
            held.ale.clone_from(&inputs.ale);
            held.lagrange.clone_from(&inputs.lagrange);
        }
        self.loads.ale_frame.copy_from_slice(&held.loads.ale_frame);
        self.loads
            .plate_frame
            .copy_from_slice(&held.loads.plate_frame);
        self.loads.axial_torque = held.loads.axial_torque;
    }
}

/// The joint's entries RK4 carries after the elastic ones when the joint is
/// integrated in the step: χ − χ0, Ω and ∫τ_drive dt.
const JOINT_UNKNOWNS: usize = 3;

/// The joint at a substep's end when it was integrated in the step: the
/// acceleration and drive torque are the substep's means.
#[derive(Debug, Clone, Copy)]
pub(super) struct JointEnd {
    chi1: JointAngle,
    speed1: f64,
    acceleration: f64,
    effort: f64,
}

/// The joint over one substep of h: from angle χ0 and speed Ω0 under the
/// drive's constant acceleration α, to χ1 and Ω1 at its end (Ω̄ the mean speed).
#[derive(Debug, Clone, Copy)]
struct SubstepMotion {
    h: f64,
    chi0: JointAngle,
    speed0: f64,
    alpha: f64,
    speed_mean: f64,
    chi1: JointAngle,
    speed1: f64,
}

impl SubstepMotion {
    fn new(h: f64, chi0: JointAngle, speed0: f64, alpha: f64) -> SubstepMotion {
        let speed_mean = speed0 + 0.5 * alpha * h;
        let mut chi1 = chi0;
        chi1.advance(speed_mean * h);
        SubstepMotion {
            h,
            chi0,
            speed0,
            alpha,
            speed_mean,
            chi1,
            speed1: speed0 + alpha * h,
        }
    }
}

/// Node loads of held wrenches and the wrenches they are of.
struct HeldLoads {
    ale: Vec<Wrench>,
    lagrange: Vec<Wrench>,
    loads: StepLoads,
}

impl HeldLoads {
    /// Whether `inputs` hold the same wrenches, bit for bit.
    fn is_of(&self, inputs: &Inputs) -> bool {
        let same = |a: &[Wrench], b: &[Wrench]| {
            a.len() == b.len()
                && a.iter().zip(b).all(|(x, y)| {
                    x.force
                        .iter()
                        .chain(&x.moment)
                        .zip(y.force.iter().chain(&y.moment))
                        .all(|(u, v)| u.to_bits() == v.to_bits())
                })
        };
        same(&self.ale, &inputs.ale) && same(&self.lagrange, &inputs.lagrange)
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
            Coordinates::Lagrangian => lagrange_to_ale(
                &scene.layout,
                harm,
                self.speed,
                &mut views.q_ale,
                &mut views.q_dot_ale,
            ),
            Coordinates::Ale => super::ale::ale_to_lagrange(
                &scene.layout,
                harm,
                self.speed,
                &mut views.q_lagrange,
                &mut views.q_dot_lagrange,
            ),
        }
    }
}

/// What the load models see at `state`: its ALE amplitudes and rates, χ, Ω
/// and the held wrenches' residual deflection.
fn load_context<'a>(scene: &'a Scene, state: &'a State, inputs: &'a Inputs) -> LoadContext<'a> {
    let (q_ale, q_dot_ale) = state.ale();
    LoadContext {
        ale_nodes: &scene.ale_nodes,
        lagrange_nodes: &scene.lagrange_nodes,
        q_ale,
        q_dot_ale,
        chi: state.chi.angle,
        speed: state.speed,
        held: scene.held_deflection(inputs),
    }
}
