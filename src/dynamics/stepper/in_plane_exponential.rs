//! The exponential step of the in-plane modes with their spin terms
//! ([`crate::dynamics::in_plane_spin`]): per k one exact propagator of the
//! block m q̈ + (c + Ω̄ G) q̇ + (m ω² + Ω̄² K_Ω) q = f_B + Re[g e^{iνt}] in the
//! turning (Lagrangian) frame, the loads held as for the bending modes
//! (plate-frame ones constant, ALE-frame ones turning at ν = kΩ̄).
//!
//! Ω̄ is the joint's speed at the substep's mid-instant (its mean under the
//! constant α): exact at a held speed; under acceleration the local error is
//! O(h³) (second order). The exponential is cached by (h, Ω̄, ν).

use crate::dynamics::ale::pair_to_ale;
use crate::dynamics::in_plane::InPlaneDynamics;
use crate::dynamics::integrators::block_exponential::{BlockPropagator, JointSubstep};
use crate::dynamics::integrators::equations::ModeConstants;
use crate::dynamics::loads::StepLoads;
use nalgebra::Complex;

/// The Lagrangian and ALE amplitudes and rates the step writes.
pub(super) struct Amplitudes<'a> {
    pub lagrange_q: &'a mut [f64],
    pub lagrange_v: &'a mut [f64],
    pub ale_q: &'a mut [f64],
    pub ale_v: &'a mut [f64],
}

/// One propagator per spin block of `ip` (scratch sized once).
pub(super) fn propagators(ip: Option<&InPlaneDynamics>) -> Vec<BlockPropagator> {
    ip.iter()
        .flat_map(|ip| &ip.spin.blocks)
        .map(|b| BlockPropagator::new(b.len()))
        .collect()
}

/// Advance the in-plane modes' Lagrangian amplitudes over the substep and
/// derive their ALE ones at its end, whose harmonics of χ are `harm_end`.
pub(super) fn advance(
    ip: &InPlaneDynamics,
    props: &mut [BlockPropagator],
    consts: &[ModeConstants],
    substep: JointSubstep<'_>,
    harm_end: &[(f64, f64)],
    loads: &StepLoads,
    out: Amplitudes<'_>,
) {
    let (ale, plate) = (&loads.ale_frame, &loads.plate_frame);
    let Amplitudes {
        lagrange_q,
        lagrange_v,
        ale_q,
        ale_v,
    } = out;
    for (b, p) in ip.spin.blocks.iter().zip(props.iter_mut()) {
        let kf = b.k as f64;
        p.update_spin(
            b,
            consts,
            substep.h,
            substep.speed_mean,
            kf * substep.speed_mean,
        );
        if b.k == 0 {
            p.advance(consts, &b.modes, lagrange_q, lagrange_v, |a| {
                (ale[b.modes[a]], Complex::new(0.0, 0.0))
            });
            for &i in &b.modes {
                ale_q[i] = lagrange_q[i];
                ale_v[i] = lagrange_v[i];
            }
            continue;
        }
        let (co, si) = substep.harmonics_start[b.k as usize];
        let e0 = Complex::new(co, si);
        let half = b.len() / 2;
        // As the scalar step: cos mode (f_c − i f_s) e^{ikχ₀}, sin mode (f_s + i f_c) e^{ikχ₀}.
        p.advance(consts, &b.modes, lagrange_q, lagrange_v, |a| {
            if a < half {
                let (c, s) = (b.modes[a], b.modes[a + half]);
                (plate[c], Complex::new(ale[c], -ale[s]) * e0)
            } else {
                let (c, s) = (b.modes[a - half], b.modes[a]);
                (plate[s], Complex::new(ale[s], ale[c]) * e0)
            }
        });
        for a in 0..half {
            let (c, s) = (b.modes[a], b.modes[a + half]);
            let [bar_c, bar_s, dot_c, dot_s] = pair_to_ale(
                harm_end[b.k as usize],
                kf * substep.speed_end,
                [lagrange_q[c], lagrange_q[s]],
                [lagrange_v[c], lagrange_v[s]],
            );
            ale_q[c] = bar_c;
            ale_q[s] = bar_s;
            ale_v[c] = dot_c;
            ale_v[s] = dot_s;
        }
    }
}
