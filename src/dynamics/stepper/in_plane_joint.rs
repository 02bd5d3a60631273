//! The torsional in-plane modes and the joint over one substep
//! ([`crate::dynamics::in_plane`], "Joint"): a drive that follows its
//! profile puts the Euler force −s α on the modes and feels their reaction
//! in its effort; a torque-limited drive at its limit leaves the joint free
//! under the held torque, and the k = 0 block (every torsional mode, the
//! radial family and their spin terms) is stepped exactly with the joint's
//! inertia coupling (`BlockPropagator::update_free_joint`), Ω₁ from the
//! angular momentum. Where the joint rides in y ([`joint_in_y`]) the drive's
//! law couples them at every evaluation instead.

use crate::config::IntegratorKind;
use crate::dynamics::integrators::block_exponential::BlockPropagator;
use crate::dynamics::integrators::equations::ModeConstants;
use crate::dynamics::joint::{integrated_in_step, DriveStep, FrictionTorque};
use crate::dynamics::loads::StepLoads;
use crate::dynamics::scene::Scene;
use crate::dynamics::state::State;
use nalgebra::Complex;

/// Scratch: the k = 0 block stepped with the joint free.
pub(super) struct InPlaneJoint {
    free: Option<FreeBlock>,
}

/// The k = 0 spin block (index `block` among the spin blocks) with the
/// joint free: its exponential, each position's coupling s, and the block's
/// end state over the whole elastic state (only its modes are written).
struct FreeBlock {
    block: usize,
    propagator: BlockPropagator,
    coupling: Vec<f64>,
    q: Vec<f64>,
    v: Vec<f64>,
}

/// What the substep does with the joint and the torsional modes.
#[derive(Debug, Clone, Copy)]
pub(super) struct Twist {
    /// The joint's acceleration over the substep, rad/s².
    pub acceleration: f64,
    /// The drive's torque as the drive law gave it, N·m.
    effort: f64,
    kind: TwistKind,
}

#[derive(Debug, Clone, Copy)]
enum TwistKind {
    /// No torsional in-plane mode.
    Rigid,
    /// Ω̇ = α imposed; the load torque and Σ s q̇ at the start.
    Imposed { load_torque: f64, momentum0: f64 },
    /// The joint free under a held torque: the k = 0 block's end state in
    /// the scratch.
    Free,
}

/// Whether the joint rides in y — RK4's and the contact step's unknowns,
/// the drive's law at every evaluation ([`StageDrive`]): where
/// [`integrated_in_step`] holds, and for a torque-limited drive with
/// torsional in-plane modes (the joint then free with all of them, the
/// reduced law of `StageRhs`). `exponential` (and the contact step without
/// stage-dependent loads) holds the joint and steps the free k = 0 block
/// exactly instead ([`InPlaneJoint::begin`]).
pub(super) fn joint_in_y(
    scene: &Scene,
    integrator: IntegratorKind,
    stage_dependent_loads: bool,
    friction: &[FrictionTorque],
) -> bool {
    let integrates = match integrator {
        IntegratorKind::Rk4 => true,
        IntegratorKind::ContactExponential => stage_dependent_loads,
        IntegratorKind::Exponential | IntegratorKind::ImplicitMidpoint => false,
    };
    let torsional = scene.joint.max_torque.is_some()
        && scene
            .in_plane
            .as_ref()
            .is_some_and(|ip| !ip.torsional.is_empty());
    integrates && (torsional || integrated_in_step(&scene.joint, stage_dependent_loads, friction))
}

impl Twist {
    /// The joint under the drive's step `d` alone: no torsional mode, or the
    /// joint rides in y (its end then comes from y).
    pub fn rigid(d: &DriveStep) -> Twist {
        Twist {
            acceleration: d.acceleration,
            effort: d.effort,
            kind: TwistKind::Rigid,
        }
    }
}

impl InPlaneJoint {
    /// Scratch for `scene`: the k = 0 block's when a torque-limited drive
    /// meets torsional modes.
    pub fn new(scene: &Scene) -> InPlaneJoint {
        let free = scene
            .in_plane
            .as_ref()
            .filter(|ip| scene.joint.max_torque.is_some() && !ip.torsional.is_empty())
            .and_then(|ip| {
                let block = ip.spin.blocks.iter().position(|b| b.k == 0)?;
                let modes = &ip.spin.blocks[block].modes;
                let n = scene.n_modes();
                Some(FreeBlock {
                    block,
                    propagator: BlockPropagator::new(modes.len()),
                    coupling: modes.iter().map(|&i| ip.coupling_of(i)).collect(),
                    q: vec![0.0; n],
                    v: vec![0.0; n],
                })
            });
        InPlaneJoint { free }
    }

    /// Decide the substep's joint motion from the drive's step `d` (made with
    /// the reduced inertia and torque): the Euler force into `loads`, or the
    /// free joint's exact step of the k = 0 block and Ω₁ from the angular
    /// momentum, J Ω₁ + Σ s q̇₁ = J Ω₀ + Σ s q̇₀ + τ h.
    pub fn begin(
        &mut self,
        scene: &Scene,
        state: &State,
        loads: &mut StepLoads,
        consts: &[ModeConstants],
        d: &DriveStep,
        h: f64,
    ) -> Twist {
        let rigid = Twist::rigid(d);
        let Some(ip) = scene
            .in_plane
            .as_ref()
            .filter(|ip| !ip.torsional.is_empty())
        else {
            return rigid;
        };
        let saturated = scene
            .joint
            .max_torque
            .is_some_and(|limit| d.effort.abs() >= limit);
        if !saturated {
            ip.add_euler_force(d.acceleration, &mut loads.ale_frame);
            return Twist {
                kind: TwistKind::Imposed {
                    load_torque: loads.axial_torque,
                    momentum0: ip.twist_momentum(&state.q_dot),
                },
                ..rigid
            };
        }
        let Some(free) = self.free.as_mut() else {
            unreachable!("a torque-limited drive with torsional modes has its k = 0 block (InPlaneJoint::new)")
        };
        // M q̈ + … = f − s τ/J with M − s sᵀ/J (BlockPropagator::update_free_joint),
        // the spin terms at the mean speed the reduced law gives.
        let j = scene.polar_inertia;
        let block = &ip.spin.blocks[free.block];
        let speed_mean = state.speed + 0.5 * d.acceleration * h;
        free.propagator
            .update_free_joint(block, consts, h, speed_mean, &free.coupling, j);
        let torque = d.effort + loads.axial_torque;
        for &i in &block.modes {
            free.q[i] = state.q[i];
            free.v[i] = state.q_dot[i];
        }
        let f = &loads.ale_frame;
        let coupling = &free.coupling;
        free.propagator
            .advance(consts, &block.modes, &mut free.q, &mut free.v, |a| {
                let force = f[block.modes[a]] - coupling[a] * torque / j;
                (force, Complex::new(0.0, 0.0))
            });
        let momentum_change: f64 = block
            .modes
            .iter()
            .zip(coupling)
            .map(|(&i, s)| s * (free.v[i] - state.q_dot[i]))
            .sum();
        let speed1 = state.speed + (torque * h - momentum_change) / j;
        Twist {
            acceleration: (speed1 - state.speed) / h,
            effort: d.effort,
            kind: TwistKind::Free,
        }
    }

    /// After the elastic step: the free joint's torsional mode into both
    /// descriptions; the drive's effort over the substep (the step's mean
    /// J α − τ_loads + Σ s Δq̇ / h when Ω̇ was imposed).
    pub fn end(&self, scene: &Scene, state: &mut State, twist: Twist, h: f64) -> f64 {
        match twist.kind {
            TwistKind::Rigid => twist.effort,
            TwistKind::Imposed {
                load_torque,
                momentum0,
            } => {
                let Some(ip) = &scene.in_plane else {
                    return twist.effort;
                };
                let momentum1 = ip.twist_momentum(&state.q_dot);
                scene.polar_inertia * twist.acceleration - load_torque + (momentum1 - momentum0) / h
            }
            TwistKind::Free => {
                let (Some(free), Some(ip)) = (&self.free, &scene.in_plane) else {
                    return twist.effort;
                };
                for &i in &ip.spin.blocks[free.block].modes {
                    state.q[i] = free.q[i];
                    state.q_dot[i] = free.v[i];
                    state.q_other[i] = free.q[i];
                    state.q_dot_other[i] = free.v[i];
                }
                twist.effort
            }
        }
    }
}
