//! The torsional in-plane modes and the joint over one substep
//! ([`crate::dynamics::in_plane`], "Joint"): a drive that follows its
//! profile puts the Euler force −s α on the modes and feels their reaction
//! in its effort; a torque-limited drive at its limit leaves the joint free
//! under the held torque, and the one torsional mode and Ω are stepped
//! together exactly.

use crate::dynamics::integrators::exponential::ModePropagator;
use crate::dynamics::joint::DriveStep;
use crate::dynamics::loads::StepLoads;
use crate::dynamics::scene::Scene;
use crate::dynamics::state::State;
use nalgebra::Complex;

/// Scratch: the free joint's propagator of the torsional mode (keyed by h).
pub(super) struct InPlaneJoint {
    free: ModePropagator,
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
    /// The joint free under a held torque: the torsional mode's end state.
    Free { mode: usize, q1: f64, v1: f64 },
}

impl InPlaneJoint {
    pub fn new() -> InPlaneJoint {
        InPlaneJoint {
            free: ModePropagator::UNSET,
        }
    }

    /// Decide the substep's joint motion from the drive's step `d` (made with
    /// the reduced inertia and torque): the Euler force into `loads`, or the
    /// free joint's exact step of the torsional mode.
    pub fn begin(
        &mut self,
        scene: &Scene,
        state: &State,
        loads: &mut StepLoads,
        d: &DriveStep,
        h: f64,
    ) -> Twist {
        let rigid = Twist {
            acceleration: d.acceleration,
            effort: d.effort,
            kind: TwistKind::Rigid,
        };
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
        // One torsional mode (InPlaneDynamics::check): (m − s²/J) q̈ + c q̇ + k q = f − s τ/J.
        let j = scene.polar_inertia;
        if self.free.h != h {
            self.free = ip.free_joint_propagator(j, h);
        }
        let local = ip.torsional[0];
        let mode = ip.offset + local;
        let s = ip.modes[local].coupling;
        let torque = d.effort + loads.axial_torque;
        let (q0, v0) = (state.q[mode], state.q_dot[mode]);
        let force = loads.ale_frame[mode] - s * torque / j;
        let (q1, v1) = self.free.advance(q0, v0, force, Complex::new(0.0, 0.0));
        let speed1 = state.speed + (torque * h - s * (v1 - v0)) / j;
        Twist {
            acceleration: (speed1 - state.speed) / h,
            effort: d.effort,
            kind: TwistKind::Free { mode, q1, v1 },
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
            TwistKind::Free { mode, q1, v1 } => {
                state.q[mode] = q1;
                state.q_dot[mode] = v1;
                state.q_other[mode] = q1;
                state.q_dot_other[mode] = v1;
                twist.effort
            }
        }
    }
}
