//! Brake pads in series with the residual flexibility
//! (`dynamics::contact_compliance`, docs/residual_flexibility.md): with
//! `plate.residual_flexibility` each contact point acts on the modal
//! deflection plus the truncated modes' static deflection of the pads' own
//! net axial forces (G among the contact points, constant: ALE frames) and
//! of the held wrenches. Lift-off and the floating caliper's balance are
//! solved with it (active set); the dampers act on the modal rate.

use super::model::{Coupling, LoadContext, SurfaceKinematics};
use super::pad::{held_normal_forces, PadScratch, Pads};
use super::pad_config::Caliper;
use crate::dynamics::contact_compliance::{stiffness_rate, ContactCompliance};
use crate::dynamics::node_frame::{NodeFrame, NodeShape};

impl Pads {
    /// The coupling bound in series with G, every contact closed, fixed
    /// caliper: K_eff = (I + K G)⁻¹ K with K = 2k_c (bounded by G⁻¹ however
    /// stiff k_c), the dampers' likewise (c_c/k_c) K_eff. Massive pads: K =
    /// 4k_c on the disc's side (k_c (x + w)² ≤ 2k_c x² + 2k_c w² per face)
    /// plus the pads' own rates (`pad_mass.rs`).
    pub(super) fn series_coupling(
        &self,
        g: &ContactCompliance,
        shapes: &[&[NodeShape]],
        modal_mass: &[f64],
    ) -> Coupling {
        let n = self.contacts.len();
        let per_face = if self.is_massive() { 4.0 } else { 2.0 };
        let k: Vec<f64> = (0..n * n)
            .map(|i| {
                if i % (n + 1) == 0 {
                    per_face * self.stiffness
                } else {
                    0.0
                }
            })
            .collect();
        let rate = stiffness_rate(shapes, &g.series_stiffness(&k), modal_mass);
        let disc = Coupling {
            stiffness_rate_sq: rate,
            damping_rate: self.damping / self.stiffness * rate,
            relaxation_rate: 0.0,
        };
        if self.is_massive() {
            let own = self.pad_own_coupling();
            return Coupling {
                stiffness_rate_sq: disc.stiffness_rate_sq + own.stiffness_rate_sq,
                damping_rate: disc.damping_rate + own.damping_rate,
                relaxation_rate: 0.0,
            };
        }
        disc
    }

    /// The contact forces in series with the residual compliance G among the
    /// contact points (`dynamics::contact_compliance`): each contact acts on
    /// w = w_m + w_e + G F (F the net axial forces N_b − N_t, w_e the held
    /// wrenches' residual), lift-off and the floating caliper's balance
    /// solved with it; the dampers act on the modal rate. Leaves the
    /// kinematics acted on and the forces in `s`.
    /// With massive pads (`pad_mass.rs`) the contacts act between the pads'
    /// state `slot` and the disc, so the law is theirs and no balance is solved.
    pub(super) fn series_forces(
        &self,
        g: &ContactCompliance,
        ctx: &LoadContext,
        clamp_force: &[f64],
        slot: &[f64],
        s: &mut PadScratch,
    ) {
        let PadScratch {
            kinematics,
            forces,
            closed,
            series,
            axial,
            w_free,
            tried,
            ..
        } = s;
        let held = held_normal_forces(ctx);
        for ((w, c), k) in w_free.iter_mut().zip(&self.contacts).zip(kinematics.iter()) {
            *w = k.w + held.map_or(0.0, |h| h.at(c.node, ctx.chi));
        }
        let law = |w: &[f64], f: &mut [f64], active: &mut [bool]| {
            for ((t, &wc), m) in tried.iter_mut().zip(w).zip(kinematics.iter()) {
                *t = SurfaceKinematics {
                    w: wc,
                    w_dot: m.w_dot,
                };
            }
            if self.is_massive() {
                self.massive_forces(slot, tried, ctx.speed, forces);
            } else {
                self.forces(clamp_force, tried, ctx.speed, forces, closed);
            }
            for ((fc, out), on) in f
                .iter_mut()
                .zip(forces.iter())
                .zip(active.chunks_exact_mut(2))
            {
                *fc = out.axial;
                on[0] = !self.lift_off || out.top > 0.0;
                on[1] = !self.lift_off || out.bottom > 0.0;
            }
        };
        // Singular I − J G: the law's last forces stand (the step check judges what follows).
        let _singular = g.solve(w_free, axial, series, law, |active, jacobian| {
            self.axial_jacobian(active, jacobian)
        });
        kinematics.copy_from_slice(tried);
    }

    /// ∂(N_b − N_t)_c/∂w_d (row-major) with the faces `closed[2c + face]`
    /// (top 0, bottom 1) in contact: −k_c per closed face, and with a
    /// floating caliper of massless pads +k_c/n for the n closed contacts of
    /// the pad's face (its backing force u follows their mean; a massive
    /// pad's position is state, held during the solve).
    pub(super) fn axial_jacobian(&self, closed: &[bool], jacobian: &mut [f64]) {
        let n = self.contacts.len();
        let k = self.stiffness;
        jacobian.iter_mut().for_each(|v| *v = 0.0);
        for face in [0, 1] {
            let on = |c: usize| closed[2 * c + face];
            for (c, contact) in self.contacts.iter().enumerate() {
                if !on(c) {
                    continue;
                }
                jacobian[c * n + c] -= k;
                if self.caliper == Caliper::Floating && !self.is_massive() {
                    let members = |d: &usize| self.contacts[*d].pad == contact.pad && on(*d);
                    let count = (0..n).filter(members).count() as f64;
                    for d in (0..n).filter(members) {
                        jacobian[c * n + d] += k / count;
                    }
                }
            }
        }
    }

    /// The linearised net axial forces F = −(I + K G)⁻¹ (K W q̄ + C W q̄̇) of
    /// the contacts `active` (the others open), for the stability analysis.
    /// K = −∂F/∂w with every active face closed, C = (c_c/k_c) K; W the
    /// shapes at `nodes`. Massive pads add (I + K G)⁻¹ k_c (ξ_b − ξ_t) and
    /// its rate (K = 2k_c: no balance among the contacts).
    pub fn linear_series_forces(
        &self,
        g: &ContactCompliance,
        nodes: &[NodeFrame],
        active: &[bool],
    ) -> LinearSeriesForces {
        let nc = self.contacts.len();
        let closed: Vec<bool> = active.iter().flat_map(|&a| [a, a]).collect();
        let mut jacobian = vec![0.0; nc * nc];
        self.axial_jacobian(&closed, &mut jacobian);
        let k: Vec<f64> = jacobian.iter().map(|j| -j).collect();
        let keff = g.series_stiffness(&k);
        let n = nodes.first().map_or(0, |nd| nd.shapes.len());
        let mut q = vec![0.0; nc * n];
        for c in 0..nc {
            for (d, contact) in self.contacts.iter().enumerate() {
                let kcd = keff[c * nc + d];
                for (m, s) in nodes[contact.node].shapes.iter().enumerate() {
                    q[c * n + m] -= kcd * s.w;
                }
            }
        }
        let ratio = self.damping / self.stiffness;
        let q_dot = q.iter().map(|f| ratio * f).collect();
        let pads = self.pad_states() / 2;
        let mut pad = vec![0.0; nc * pads];
        for c in 0..nc * self.is_massive() as usize {
            for (d, contact) in self.contacts.iter().enumerate() {
                // (I + K G)⁻¹ k_c = K_eff / 2 on ξ_b − ξ_t of contact d's pad
                // (K_eff's column of an open contact is 0).
                let half = 0.5 * keff[c * nc + d];
                pad[c * pads + 2 * contact.pad] -= half;
                pad[c * pads + 2 * contact.pad + 1] += half;
            }
        }
        LinearSeriesForces { q, q_dot, pad }
    }
}

/// [`Pads::linear_series_forces`]: each contact's net axial force per unit
/// q̄ and q̄̇ (n_c × n, row-major) and, with massive pads, per unit ξ
/// (n_c × 2 per pad; per unit ξ̇ it is c_c/k_c of it).
#[derive(Debug, Clone, PartialEq)]
pub struct LinearSeriesForces {
    /// Per unit q̄: n_c × n, row-major, N/m.
    pub q: Vec<f64>,
    /// Per unit q̄̇: n_c × n, row-major, N s/m.
    pub q_dot: Vec<f64>,
    /// Per unit ξ of a massive pad: n_c × 2 per pad, N/m (empty for massless pads).
    pub pad: Vec<f64>,
}
