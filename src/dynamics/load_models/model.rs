//! What a load model is: the [`LoadModel`] trait, what it sees
//! ([`LoadContext`], [`SceneNodes`]), what it declares ([`CommandSpec`],
//! [`Coupling`]) and where it writes ([`ModelOut`]).

use super::linear::{LinearContext, LinearOut, LinearStates, OperatingPoint};
use super::outputs::{OutputContext, Outputs};
use super::undo::SlotUndo;
use crate::config::{Config, LimitsConfig, ModelParameters};
use crate::dynamics::contact_compliance::HeldDeflection;
use crate::dynamics::error::{InputError, SimulationError};
use crate::dynamics::in_plane::InPlaneDynamics;
use crate::dynamics::joint::FrictionTorque;
use crate::dynamics::node_frame::{NodeFrame, NodeShape};
use crate::dynamics::residual::ResidualCompliance;
use crate::dynamics::wrench::Wrench;
use std::any::Any;
use std::fmt::Debug;

/// Builds a load model from a configuration, `None` when the scene does not use it.
pub type Builder = fn(&Config, &SceneNodes) -> Option<Box<dyn LoadModel>>;

/// A model as the registry lists it: its builder, its declared outputs and
/// its declared parameters (a `const` in the model's file, so the registry
/// line is its name).
#[derive(Debug, Clone, Copy)]
pub struct Registration {
    /// Builds the model of a scene (None when its section is off).
    pub build: Builder,
    /// Its declared outputs.
    pub outputs: &'static Outputs,
    /// Its parameters: sections (keys, types, units, defaults, rules, texts)
    /// and the reader that makes its validated section of the `Config`.
    pub parameters: &'static ModelParameters,
}

/// What a model's builder sees of the scene: the node frames and modal masses.
pub struct SceneNodes<'a> {
    /// The ALE node frames.
    pub ale: &'a [NodeFrame],
    /// The Lagrangian node frames.
    pub lagrange: &'a [NodeFrame],
    /// Modal masses m_i, kg, in the model's mode order.
    pub modal_mass: &'a [f64],
    /// The residual compliance among the node frames (`plate.residual_flexibility`),
    /// for contacts in series with it (`dynamics::contact_compliance`).
    pub residual: Option<&'a ResidualCompliance>,
}

/// The kinematics a model is evaluated at (substep start or an RK4 stage).
#[derive(Clone, Copy)]
pub struct LoadContext<'a> {
    /// The ALE node frames.
    pub ale_nodes: &'a [NodeFrame],
    /// The Lagrangian node frames.
    pub lagrange_nodes: &'a [NodeFrame],
    /// Amplitudes and rates in the ALE description (eq. 20).
    pub q_ale: &'a [f64],
    /// Their rates, m/s.
    pub q_dot_ale: &'a [f64],
    /// Joint angle χ (wrapped to [0, 2π), rad) and speed Ω (rad/s).
    pub chi: f64,
    /// Joint speed Ω, rad/s.
    pub speed: f64,
    /// The residual deflection of the held wrenches (None with
    /// `plate.residual_flexibility: false`): contacts add it to the modal
    /// deflection they act on (`dynamics::contact_compliance`).
    pub held: Option<HeldDeflection<'a>>,
}

/// The rule a command value must meet.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum CommandRule {
    /// Finite, in [0, `limits.max_force`] (a clamp force).
    NonNegativeForce,
    /// Finite, |v| ≤ the limit.
    MagnitudeAtMost(f64),
}

/// One command of a load model, as the node and recorder discover it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CommandSpec {
    /// What one instance is called (`pad`, `tool`).
    pub instance: &'static str,
    /// The command in words (`clamp force`, `feed rate`).
    pub name: &'static str,
    /// The name token of its topic (`clamp_force`: `~/pad_<j>/clamp_force`; `feed`: `~/tool_feed`).
    pub token: &'static str,
    /// SI unit of its value (`N`, `m/s`).
    pub unit: &'static str,
    /// Instances are numbered (`pad_1`, `pad_2`, …) rather than one.
    pub indexed: bool,
    /// The rule a value must satisfy.
    pub rule: CommandRule,
}

impl CommandSpec {
    /// The command of instance `instance` (0-based) in words: `pad_2 clamp force`, `tool feed rate`.
    pub fn what(&self, instance: usize) -> String {
        if self.indexed {
            format!("{}_{} {}", self.instance, instance + 1, self.name)
        } else {
            format!("{} {}", self.instance, self.name)
        }
    }

    /// Check `value` for instance `instance` (0-based) against the rule.
    pub fn check(
        &self,
        instance: usize,
        value: f64,
        limits: &LimitsConfig,
    ) -> Result<(), InputError> {
        if !value.is_finite() {
            return Err(InputError::NonFinite {
                what: self.what(instance),
                value,
            });
        }
        match self.rule {
            CommandRule::NonNegativeForce if !(0.0..=limits.max_force).contains(&value) => {
                Err(InputError::Absurd {
                    what: format!(
                        "{} (must lie in [0, limits.max_force])",
                        self.what(instance)
                    ),
                    value,
                    limit: limits.max_force,
                })
            }
            CommandRule::MagnitudeAtMost(limit) if value.abs() > limit => Err(InputError::Absurd {
                what: self.what(instance),
                value,
                limit,
            }),
            _ => Ok(()),
        }
    }
}

/// How strongly a memoryless model couples the modes, for the integrators'
/// step checks: the largest eigenvalues of M^(−½) K M^(−½) (1/s²) and
/// M^(−½) C M^(−½) (1/s) with every contact closed, and the fastest
/// relaxation of the model's massless states.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Coupling {
    /// Largest eigenvalue of M^(−½) K M^(−½), 1/s².
    pub stiffness_rate_sq: f64,
    /// Largest eigenvalue of M^(−½) C M^(−½), 1/s.
    pub damping_rate: f64,
    /// Fastest rate at which a massless continuous state relaxes on its own
    /// (the lining patch's k_t/c_t), 1/s: a real eigenvalue, which RK4 keeps
    /// stable and monotone per inner step but need not resolve like a mode.
    pub relaxation_rate: f64,
}

/// Where a model writes its forces at one instant.
pub struct ModelOut<'a> {
    /// Wrenches per node frame, in the node frame's axes (summed over the models).
    pub ale: &'a mut [Wrench],
    /// Wrenches per Lagrangian node frame, in its axes.
    pub lagrange: &'a mut [Wrench],
    /// Whether the node's model wrench follows the deformed surface.
    pub ale_follower: &'a mut [bool],
    /// Whether the Lagrangian node's model wrench follows the deformed surface.
    pub lagrange_follower: &'a mut [bool],
    /// This model's friction terms of the joint torque ([`LoadModel::friction_terms`] of them).
    pub friction: &'a mut [FrictionTorque],
    /// This model's scratch ([`LoadModel::new_scratch`]).
    pub scratch: &'a mut dyn Any,
    /// The rates of its continuous states ([`LoadModel::continuous_states`] of them).
    pub rates: &'a mut [f64],
    /// Its switching functions at this instant ([`LoadModel::switching_functions`] of them).
    pub switching: &'a mut [f64],
}

/// A load model (see the module docs). Only [`LoadModel::name`],
/// [`LoadModel::evaluate`] and [`LoadModel::as_any`] are required; a model
/// with outputs declares them in its [`Registration`] and writes them in
/// [`LoadModel::write_outputs`].
pub trait LoadModel: Debug + Send + Sync {
    /// The configuration section (`pads`, `tool`, `links`, `springs`).
    fn name(&self) -> &'static str;

    /// For downcasting to the concrete model (only in the model's own files).
    fn as_any(&self) -> &dyn Any;

    /// Whether the model is right for Mindlin modes (`plate.theory: mindlin`):
    /// it reads only the deflection w at its nodes and applies only F_z there.
    /// A model that uses the slope or the face kinematics says no (the
    /// default), and the scene is refused naming its section.
    fn takes_mindlin_modes(&self) -> bool {
        false
    }

    /// Take the scene's in-plane modes (`plate.in_plane_nodal_diameters`): a
    /// model whose in-plane forces do their work on them keeps what it reads
    /// of `ip` (its wrenches' F_x, F_y act on them through the node loads).
    /// The default refuses, naming the model's section: its forces do not
    /// act on the in-plane modes.
    fn attach_in_plane(&mut self, _ip: &InPlaneDynamics) -> Result<(), SimulationError> {
        Err(SimulationError::InPlaneKeyNotWired {
            key: self.name(),
            why: "its forces do not act on the in-plane modes yet",
        })
    }

    /// Its commands (held in `LoadCommands`, one value per instance and command).
    fn commands(&self) -> &[CommandSpec] {
        &[]
    }

    /// Instances of command `command` (pads: one clamp force per pad).
    fn instances(&self, _command: usize) -> usize {
        1
    }

    /// Initial values of its commands, in [`LoadModel::commands`] order × instances.
    fn initial_commands(&self) -> Vec<f64> {
        Vec::new()
    }

    /// Its slot in the `State` at t = 0.
    fn initial_state(&self) -> Vec<f64> {
        Vec::new()
    }

    /// Scratch for [`LoadModel::evaluate`], allocated once.
    fn new_scratch(&self) -> Box<dyn Any + Send + Sync> {
        Box::new(())
    }

    /// Friction terms it adds to the joint torque (solved at the step's end near standstill).
    fn friction_terms(&self) -> usize {
        0
    }

    /// Its force within a substep is a function of the elastic state: RK4
    /// re-evaluates it at every stage and `contact_exponential` takes it
    /// into its step (memoryless models, and the tool on `contact_exponential`).
    fn stage_dependent(&self) -> bool {
        false
    }

    /// Entries at the start of its slot that are continuous state — an ODE
    /// ẋ = f(x, elastic state) RK4 integrates with the modes at every stage
    /// ([`LoadModel::evaluate`] writes f into `out.rates`; the other
    /// integrators refuse such a model). Default: none.
    fn continuous_states(&self) -> usize {
        0
    }

    /// The last of its continuous states that are rates (the differences'
    /// and the error's scale is then the thickness over h): by default the
    /// second half after their positions, the middle one of an odd count too.
    fn continuous_rates(&self) -> usize {
        let n = self.continuous_states();
        n - n / 2
    }

    /// Switching functions of a piecewise law: values whose signs select the
    /// piece (a contact's normal force before lift-off: > 0 closed), written
    /// by [`LoadModel::evaluate`] into `out.switching`. While no sign changes,
    /// the law is one smooth piece in the elastic state (affine for linear
    /// springs), so `contact_exponential` can take its linearisation into the
    /// exponential and locate the instants where a sign changes. Default: none.
    fn switching_functions(&self) -> usize {
        0
    }

    /// Its coupling rates (stiff contacts); zero for prescribed forces.
    fn coupling(&self) -> Coupling {
        Coupling::default()
    }

    /// Names of the parameters that set [`LoadModel::coupling`], for error messages.
    fn coupling_keys(&self) -> &'static str {
        ""
    }

    /// A bound, 1/s, on the largest eigenvalue of M^(−½) C M^(−½) for the
    /// damping C = −∂F/∂q̇ its law has at the state of its last
    /// [`LoadModel::evaluate`] (whose scratch, `scratch`, it may use), beyond the
    /// constant [`LoadModel::coupling`]: a damping that grows as the state
    /// changes (the face friction's μN/|V| as the sliding slows). The
    /// integrators that hold its forces over a substep must resolve it.
    /// Default: none.
    fn held_damping_rate(&self, _ctx: &LoadContext, _scratch: &mut dyn Any) -> f64 {
        0.0
    }

    /// Whether [`LoadModel::evaluate`] at `ctx` reads the joint angle χ
    /// (`ctx.chi`); an evaluation that does not is the same at any χ.
    /// Default: it does.
    fn reads_joint_angle(&self, _ctx: &LoadContext) -> bool {
        true
    }

    /// Before the substep of length `h` (models with memory hold a force over it).
    fn begin_substep(&self, _ctx: &LoadContext, _slot: &mut [f64], _h: f64) {}

    /// Its wrenches at one instant, added into `out`.
    fn evaluate(&self, ctx: &LoadContext, slot: &[f64], commands: &[f64], out: ModelOut);

    /// After the substep of length `h`, at the kinematics of its end: advance its state.
    fn commit_substep(&self, _ctx: &LoadContext, _slot: &mut [f64], _commands: &[f64], _h: f64) {}

    /// Whether its law within a substep reads memory that only
    /// [`LoadModel::commit_substep`] changes (the tool's machined surface and
    /// holder): `contact_exponential` then linearises every step's piece at
    /// that step's own state, never at the origin. Default: no.
    fn law_reads_memory(&self) -> bool {
        false
    }

    /// The part of its slot (`..n` of `slot_len` entries) the stepper copies
    /// before a step so that it can undo it (see [`super::undo`]); the entries
    /// beyond it change only in [`LoadModel::commit_substep`] and only where
    /// [`LoadModel::save_changes`] saved them. Default: the whole slot.
    fn undo_head(&self, slot_len: usize) -> usize {
        slot_len
    }

    /// Just before [`LoadModel::commit_substep`]: save every entry beyond
    /// [`LoadModel::undo_head`] the commit will change. Default: none (the
    /// whole slot is the head).
    fn save_changes(&self, _slot: &[f64], _undo: &mut SlotUndo) {}

    /// Values of output channel `channel` ([`Registration::outputs`]) in
    /// this scene: 1 for a scalar, the instances for a sequence.
    fn channel_len(&self, _channel: usize) -> usize {
        1
    }

    /// Its outputs at the current state: every channel in declared order,
    /// [`LoadModel::channel_len`] values each, into `out`.
    fn write_outputs(&self, _at: &OutputContext, _out: &mut [f64]) {}

    /// The states it adds to the linear stability analysis ([`super::linear`]):
    /// coordinates (each with its rate) and first-order states. Default: none.
    fn linear_states(&self) -> LinearStates {
        LinearStates::default()
    }

    /// Refuse, naming the key, what [`LoadModel::add_linear_terms`] does not
    /// carry in this scene (with the in-plane modes attached). Default: all.
    fn check_linear(&self) -> Result<(), SimulationError> {
        Ok(())
    }

    /// Its first-order terms about steady motion at constant Ω, added into
    /// `out.a` on the modes' rows and columns and on its own states'
    /// ([`super::linear`]). Default: none — not part of the linearisation.
    fn add_linear_terms(&self, _ctx: &LinearContext, _out: LinearOut) {}

    /// The friction coefficient and clamp forces it starts with, for a model
    /// whose friction can make the plate squeal (the stability analysis maps
    /// over them, [`super::linear`]); None otherwise.
    fn operating_point(&self) -> Option<OperatingPoint> {
        None
    }

    /// Whether its slot is finite, for the divergence guard after every step
    /// (a model whose slot holds values derived from others may check only
    /// those others).
    fn slot_is_finite(&self, slot: &[f64]) -> bool {
        slot.iter().all(|v| v.is_finite())
    }
}

/// Surface kinematics under a contact point: deflection w (m) and its rate at
/// the fixed point, ∂w/∂t|θ (m/s).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct SurfaceKinematics {
    /// Deflection w, m.
    pub w: f64,
    /// Its rate at the fixed point, ∂w/∂t|θ, m/s.
    pub w_dot: f64,
}

/// Deflection and its rate at a fixed point for amplitudes in the node's own description.
#[inline]
pub fn surface_kinematics(node: &NodeFrame, q: &[f64], q_dot: &[f64]) -> SurfaceKinematics {
    let mut s = SurfaceKinematics::default();
    for ((shape, &qi), &vi) in node.shapes.iter().zip(q).zip(q_dot) {
        s.w += shape.w * qi;
        s.w_dot += shape.w * vi;
    }
    s
}

/// [`contact_rate`] of contacts at the given ALE nodes (0-based) of the scene.
pub fn ale_contact_rate(nodes: &SceneNodes, ale: &[usize]) -> f64 {
    let shapes: Vec<&[NodeShape]> = ale
        .iter()
        .map(|&j| nodes.ale[j].shapes.as_slice())
        .collect();
    contact_rate(&shapes, nodes.modal_mass)
}

/// Largest eigenvalue of M^(−½) (Σ_c w_c w_cᵀ) M^(−½), w_c the mode shapes at contact c.
pub fn contact_rate(shapes: &[&[NodeShape]], modal_mass: &[f64]) -> f64 {
    let n = modal_mass.len();
    let mut a = faer::Mat::<f64>::zeros(n, n);
    for s in shapes {
        for i in 0..n {
            for m in 0..n {
                a[(i, m)] += s[i].w * s[m].w / (modal_mass[i] * modal_mass[m]).sqrt();
            }
        }
    }
    a.self_adjoint_eigenvalues(faer::Side::Lower)
        .ok()
        .and_then(|ev| ev.last().copied())
        .unwrap_or(0.0)
        .max(0.0)
}
