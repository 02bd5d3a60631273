//! The integrators that hold the loads over a substep: the exact modal
//! exponential (Lagrangian description, the ALE one derived at the
//! substep's end) and the implicit midpoint rule.

use super::in_plane_exponential;
use super::{Stepper, SubstepMotion};
use crate::dynamics::ale::{harmonics, lagrange_to_ale, pair_to_ale};
use crate::dynamics::integrators::equations::{ModalEquations, ReferenceMotion};
use crate::dynamics::integrators::exponential::ModePropagator;
use crate::dynamics::integrators::{block_exponential, implicit_midpoint};
use crate::dynamics::scene::Scene;
use crate::dynamics::state::{JointAngle, State};
use nalgebra::Complex;

impl Stepper {
    /// The exponential step's harmonics of χ into `exp_harm` (kept when they
    /// are already of χ).
    pub(super) fn exp_harmonics(&mut self, chi: &JointAngle, k_max: u32) {
        if self.exp_harm_at != Some(*chi) {
            harmonics(chi, k_max, &mut self.exp_harm);
            self.exp_harm_at = Some(*chi);
        }
    }

    /// Exact step of the Lagrangian description over the substep (the loads
    /// held), then the ALE one derived at χ1: both written into `state`.
    pub(super) fn exponential(&mut self, scene: &Scene, state: &mut State, joint: &SubstepMotion) {
        let SubstepMotion {
            h,
            chi0,
            speed_mean,
            chi1,
            speed1,
            ..
        } = *joint;
        self.exp_harmonics(&chi0, scene.layout.k_max);
        if let Some(stiffening) = &scene.stiffening {
            let substep = block_exponential::JointSubstep {
                h,
                harmonics_start: &self.exp_harm,
                speed_mean,
                speed_end: speed1,
            };
            let (lagrange_q, lagrange_v, ..) = state.lagrange_and_ale_mut();
            block_exponential::advance(
                stiffening,
                &mut self.stiffened,
                &self.consts,
                substep,
                &self.loads,
                lagrange_q,
                lagrange_v,
            );
            // The in-plane modes (no bending stiffness of theirs: their spin
            // terms carry the prestress) step by their own blocks.
            if scene.in_plane.is_some() {
                harmonics(&chi1, scene.layout.k_max, &mut self.exp_harm_next);
                self.advance_in_plane(scene, state, joint);
            }
            return self.derive_ale(scene, state, chi1, speed1);
        }
        if self.propagators_for != Some((h, speed_mean)) {
            let soft = scene.off_axis_rate_squared();
            for (i, (k, mass, damping, omega)) in scene.elastic_modes().enumerate() {
                let nu = k as f64 * speed_mean;
                let p = &mut self.propagators[i];
                if p.h != h || p.nu != nu {
                    *p = ModePropagator::new(mass, damping, omega, soft, h, nu);
                }
            }
            self.propagators_for = Some((h, speed_mean));
        }
        // Each mode's new Lagrangian (q, q̇) at χ1 and, from it, its ALE one
        // (the same operations as `derive_ale`, while the pair is at hand).
        harmonics(&chi1, scene.layout.k_max, &mut self.exp_harm_next);
        let (lagrange_q, lagrange_v, ale_q, ale_v) = state.lagrange_and_ale_mut();
        // All of length n, so one index check serves every array (the compiler merges them).
        let n = lagrange_q.len();
        let (lagrange_v, ale_q, ale_v) = (&mut lagrange_v[..n], &mut ale_q[..n], &mut ale_v[..n]);
        let (propagators, ale_frame, plate_frame) = (
            &self.propagators[..n],
            &self.loads.ale_frame[..n],
            &self.loads.plate_frame[..n],
        );
        let harmonics_len = self.exp_harm.len();
        let (harm0, harm1) = (&self.exp_harm[..], &self.exp_harm_next[..harmonics_len]);
        // The in-plane modes (after the bending ones in the layout) step by their spin blocks.
        let bending_end = scene.in_plane.as_ref().map_or(n, |ip| ip.offset);
        let lay = &scene.layout;
        let axisymmetric =
            &lay.axisymmetric[..lay.axisymmetric.partition_point(|&i| i < bending_end)];
        let pairs = &lay.pairs[..lay.pairs.partition_point(|p| p.cos < bending_end)];
        for &i in axisymmetric {
            let (q, qd) = propagators[i].advance(
                lagrange_q[i],
                lagrange_v[i],
                ale_frame[i],
                Complex::new(0.0, 0.0),
            );
            lagrange_q[i] = q;
            lagrange_v[i] = qd;
            ale_q[i] = q;
            ale_v[i] = qd;
        }
        for p in pairs {
            let (co, si) = harm0[p.k as usize];
            let e0 = Complex::new(co, si);
            let (fc, fs) = (ale_frame[p.cos], ale_frame[p.sin]);
            let gc = Complex::new(fc, -fs) * e0;
            let gs = Complex::new(fs, fc) * e0;
            let (qc, vc) = propagators[p.cos].advance(
                lagrange_q[p.cos],
                lagrange_v[p.cos],
                plate_frame[p.cos],
                gc,
            );
            let (qs, vs) = propagators[p.sin].advance(
                lagrange_q[p.sin],
                lagrange_v[p.sin],
                plate_frame[p.sin],
                gs,
            );
            lagrange_q[p.cos] = qc;
            lagrange_v[p.cos] = vc;
            lagrange_q[p.sin] = qs;
            lagrange_v[p.sin] = vs;
            let [bar_c, bar_s, dot_c, dot_s] =
                pair_to_ale(harm1[p.k as usize], p.k as f64 * speed1, [qc, qs], [vc, vs]);
            ale_q[p.cos] = bar_c;
            ale_q[p.sin] = bar_s;
            ale_v[p.cos] = dot_c;
            ale_v[p.sin] = dot_s;
        }
        self.advance_in_plane(scene, state, joint);
        // Every mode is axisymmetric or in a pair (model::build), so both descriptions are whole.
        std::mem::swap(&mut self.exp_harm, &mut self.exp_harm_next);
        self.exp_harm_at = Some(chi1);
    }

    /// The in-plane modes' exact step by their spin blocks, the harmonics of
    /// χ0 in `exp_harm` and of χ1 in `exp_harm_next`.
    fn advance_in_plane(&mut self, scene: &Scene, state: &mut State, joint: &SubstepMotion) {
        let Some(ip) = &scene.in_plane else {
            return;
        };
        let (lagrange_q, lagrange_v, ale_q, ale_v) = state.lagrange_and_ale_mut();
        in_plane_exponential::advance(
            ip,
            &mut self.in_plane_spin,
            &self.consts,
            block_exponential::JointSubstep {
                h: joint.h,
                harmonics_start: &self.exp_harm,
                speed_mean: joint.speed_mean,
                speed_end: joint.speed1,
            },
            &self.exp_harm_next,
            &self.loads,
            in_plane_exponential::Amplitudes {
                lagrange_q,
                lagrange_v,
                ale_q,
                ale_v,
            },
        );
    }

    /// The exponential step's result is the Lagrangian description at χ1:
    /// derive the ALE one.
    pub(super) fn derive_ale(
        &mut self,
        scene: &Scene,
        state: &mut State,
        chi1: JointAngle,
        speed1: f64,
    ) {
        let (lagrange_q, lagrange_v, ale_q, ale_v) = state.lagrange_and_ale_mut();
        ale_q.copy_from_slice(lagrange_q);
        ale_v.copy_from_slice(lagrange_v);
        self.exp_harmonics(&chi1, scene.layout.k_max);
        lagrange_to_ale(&scene.layout, &self.exp_harm, speed1, ale_q, ale_v);
    }

    /// The implicit midpoint rule over the substep in `inner` equal steps,
    /// the loads held, each step's joint angle and speed at its midpoint (χ
    /// quadratic in time under constant α).
    pub(super) fn implicit_midpoint(
        &mut self,
        scene: &Scene,
        state: &mut State,
        inner: usize,
        joint: &SubstepMotion,
    ) {
        let SubstepMotion {
            h,
            chi0,
            speed0,
            alpha,
            ..
        } = *joint;
        let hi = h / inner as f64;
        let equations = ModalEquations {
            scene,
            consts: &self.consts,
            coords: state.coordinates,
        };
        for j in 0..inner {
            let t_mid = (j as f64 + 0.5) * hi;
            let mut chi_mid = chi0;
            chi_mid.advance(speed0 * t_mid + 0.5 * alpha * t_mid * t_mid);
            harmonics(&chi_mid, scene.layout.k_max, &mut self.harm_end);
            let mid = ReferenceMotion {
                harmonics: &self.harm_end,
                speed: speed0 + alpha * t_mid,
                accel: alpha,
            };
            if scene.stiffening.is_some() {
                self.stiffened_midpoint.advance(
                    equations,
                    hi,
                    mid,
                    &self.loads,
                    &mut state.q,
                    &mut state.q_dot,
                );
            } else {
                implicit_midpoint::advance(
                    equations,
                    hi,
                    mid,
                    &self.loads,
                    &mut state.q,
                    &mut state.q_dot,
                );
            }
        }
    }
}
