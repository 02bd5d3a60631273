//! The massive pads' terms of the linear stability analysis
//! (`pad_linear.rs`, docs/scenes.md "Pad mass").
//!
//! With `pads.mass` > 0 the state is y = (q̄, q̄̇, ξ, ξ̇), ξ the pads'
//! compressions from rest (per pad: top, bottom; `pad_mass.rs`): the pads'
//! coordinates and their rates ([`super::linear`]).
//! About the preloaded rest, per contact c (shape values w_i at its node,
//! w = W q̄ + G F with the residual flexibility, W q̄ without):
//!
//!   δN_t = k_c (ξ_t + w) + c_c (ξ̇_t + ẇ),   δN_b = k_c (ξ_b − w) + c_c (ξ̇_b − ẇ),
//!
//! so the net axial force F = δN_b − δN_t is linear in y ([`NetForce`]: in
//! series F = (I + 2k_c G)⁻¹ (k_c (ξ_b − ξ_t) + c_c (ξ̇_b − ξ̇_t) − 2k_c W q̄
//! − 2c_c W q̄̇), the dampers on the modal rate as in the simulation) and
//! δN_t = (S − F)/2, δN_b = (S + F)/2 with S = k_c (ξ_t + ξ_b) + c_c (ξ̇_t + ξ̇_b).
//! The disc's generalised force is f_i = w_i F, the faces' couple acts on
//! (δN_t − δN_b)/2 = −F/2, and each pad obeys m_p ξ̈ = −Σ_c δN_c − k_b ξ
//! (k_b = 0 for a floating caliper, whose piston force does not change).
//! The q̄, q̄̇ columns of the disc's rows are the massless analysis's (fixed
//! caliper); here: the ξ columns and the pads' rows.

use super::linear::{LinearContext, LinearLayout, LinearOut};
use super::pad::{PadContactPoint, Pads};
use super::pad_series::LinearSeriesForces;
use crate::dynamics::node_frame::NodeFrame;

/// Index of pad face `j` (2 pad + face) among y's positions and rates.
fn pad_index(at: &LinearLayout, j: usize) -> (usize, usize) {
    (at.coordinates + j, at.rates + j)
}

/// One contact's net axial force F = δN_b − δN_t per unit q̄, q̄̇ (n each)
/// and ξ, ξ̇ (2 per pad each, in the slot's order).
pub(super) struct NetForce {
    pub q: Vec<f64>,
    pub q_dot: Vec<f64>,
    pub pad: Vec<f64>,
    pub pad_rate: Vec<f64>,
}

impl NetForce {
    /// On the modal deflection: F = k_c (ξ_b − ξ_t − 2w) + c_c (ξ̇_b − ξ̇_t − 2ẇ).
    pub fn direct(pads: &Pads, contact: &PadContactPoint, node: &NodeFrame) -> NetForce {
        let (k, c) = (pads.stiffness, pads.damping);
        let (mut pad, mut pad_rate) = (
            vec![0.0; 2 * pads.pad_count()],
            vec![0.0; 2 * pads.pad_count()],
        );
        let (t, b) = (2 * contact.pad, 2 * contact.pad + 1);
        (pad[t], pad[b], pad_rate[t], pad_rate[b]) = (-k, k, -c, c);
        NetForce {
            q: node.shapes.iter().map(|s| -2.0 * k * s.w).collect(),
            q_dot: node.shapes.iter().map(|s| -2.0 * c * s.w).collect(),
            pad,
            pad_rate,
        }
    }

    /// In series with the residual compliance: row `ci` of [`LinearSeriesForces`].
    pub fn in_series(l: &LinearSeriesForces, ci: usize, n: usize, pads: &Pads) -> NetForce {
        let p = 2 * pads.pad_count();
        let pad: Vec<f64> = l.pad[ci * p..(ci + 1) * p].to_vec();
        let ratio = pads.damping / pads.stiffness;
        NetForce {
            q: l.q[ci * n..(ci + 1) * n].to_vec(),
            q_dot: l.q_dot[ci * n..(ci + 1) * n].to_vec(),
            pad_rate: pad.iter().map(|v| ratio * v).collect(),
            pad,
        }
    }
}

impl Pads {
    /// ξ̇ = ξ̇ and the backing stiffness of every pad face.
    pub(super) fn add_pad_identity(&self, out: &mut LinearOut) {
        for j in 0..2 * self.pad_count() {
            let (x, v) = pad_index(&out.at, j);
            out.a[(x, v)] = 1.0;
            out.a[(v, x)] -= self.backing_stiffness / self.mass;
        }
    }

    /// The terms of contact `contact` that involve the pads' coordinates, and the
    /// pads' equations (module docs), for its net axial force `net`; `couple` =
    /// h μ(V) tanh(V/v_reg) with face friction (0 at the mid-plane).
    pub(super) fn add_pad_terms(
        &self,
        ctx: &LinearContext,
        out: &mut LinearOut,
        contact: &PadContactPoint,
        couple: f64,
        net: &NetForce,
    ) {
        let n = out.at.modes;
        let mass = ctx.modal_mass;
        let node = &ctx.ale_nodes[contact.node];
        let (s, co) = contact.sin_cos;
        let first = pad_index(&out.at, 0);
        let (xt, vt) = pad_index(&out.at, 2 * contact.pad);
        let (xb, vb) = pad_index(&out.at, 2 * contact.pad + 1);
        let a = &mut *out.a;
        for i in 0..node.shapes.len() {
            let g = node.gradient(i);
            // couple ∂_θ w_i / r; f_i = w_i F + arm δN, δN = −F/2.
            let arm = couple * (-s * g[0] + co * g[1]);
            let on_f = (node.shapes[i].w - 0.5 * arm) / mass[i];
            for (j, (&x, &v)) in net.pad.iter().zip(&net.pad_rate).enumerate() {
                a[(n + i, first.0 + j)] += on_f * x;
                a[(n + i, first.1 + j)] += on_f * v;
            }
        }
        let (k, c) = (self.stiffness, self.damping);
        let half = 0.5 / self.mass;
        for (row, sign) in [(vt, 1.0), (vb, -1.0)] {
            // m_p ξ̈ ∋ −δN = −(S ∓ F)/2.
            for x in [xt, xb] {
                a[(row, x)] -= half * k;
            }
            for v in [vt, vb] {
                a[(row, v)] -= half * c;
            }
            for m in 0..net.q.len() {
                a[(row, m)] += sign * half * net.q[m];
                a[(row, n + m)] += sign * half * net.q_dot[m];
            }
            for (j, (&x, &v)) in net.pad.iter().zip(&net.pad_rate).enumerate() {
                a[(row, first.0 + j)] += sign * half * x;
                a[(row, first.1 + j)] += sign * half * v;
            }
        }
    }
}
