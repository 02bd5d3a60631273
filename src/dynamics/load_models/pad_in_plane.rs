//! The pads' friction on the in-plane modes (`plate.in_plane_nodal_diameters`
//! with `pads.contact_surface: faces`; docs/in_plane.md, "Pads").
//!
//! An in-plane mode moves the face point under a contact by its u, the same
//! at both faces (u does not vary through the thickness). Under a
//! space-fixed contact at (r, θ) the material slides with its rate
//!
//!   D u/Dt = Σ_i (q̄̇_i u_i + Ω q̄_i ∂u_i/∂θ),
//!
//! D/Dt = ∂/∂t + Ω ∂/∂θ acting on the Cartesian components: ∂u_i/∂θ is the
//! node frames' transport term ∂(u_r, u_θ)/∂θ plus the turn e_z × u_i of the
//! polar basis (`InPlaneDynamics::ale_contacts`: point values, or with
//! `plate.residual_flexibility` the node frames' patch means, so the node
//! frames' in-plane residual and the modes see the same spread friction).
//! It adds to the sliding velocity of both faces ([`super::face_friction`]); the faces' friction F then does the
//! work u_i·F on in-plane mode i through the node loads. The normal forces
//! do no work on the in-plane modes: bending and in-plane motion couple
//! through the friction only.

use super::face_friction::contact_gram;
use crate::dynamics::in_plane::InPlaneDynamics;

/// The in-plane modes under the contact points.
#[derive(Debug, Clone, PartialEq)]
pub struct PadInPlane {
    /// State index of the first in-plane mode.
    offset: usize,
    /// The number of in-plane modes.
    modes: usize,
    /// Per contact point, per in-plane mode: u and ∂u/∂θ in frame A's axes.
    shapes: Vec<[[f64; 2]; 2]>,
    /// U M⁻¹ Uᵀ among the contact points, 2C × 2C, 1/kg (`pad_friction_damping.rs`).
    gram: Vec<f64>,
}

impl PadInPlane {
    /// The in-plane modes under the contacts at ALE nodes `nodes` (friction
    /// on the faces, with or without the lining's patches).
    pub fn attach(ip: &InPlaneDynamics, nodes: impl Iterator<Item = usize>) -> PadInPlane {
        let shapes: Vec<[[f64; 2]; 2]> = nodes
            .flat_map(|n| ip.ale_contacts[n].iter().copied())
            .collect();
        let modes = ip.len();
        let gram = contact_gram(
            |c, i| shapes[c * modes + i][0],
            shapes.len() / modes.max(1),
            ip.modes.iter().map(|m| &m.modal_mass),
        );
        PadInPlane {
            offset: ip.offset,
            modes: ip.len(),
            shapes,
            gram,
        }
    }

    /// U M⁻¹ Uᵀ of the in-plane rows among the contact points, 2C × 2C,
    /// 1/kg: the in-plane modes' share of the face friction's damping bound.
    pub fn gram(&self) -> &[f64] {
        &self.gram
    }

    /// D u/Dt under contact `contact` for ALE amplitudes `q`, rates `q_dot`
    /// (all modes) at speed Ω, m/s.
    #[inline]
    pub fn rate(&self, contact: usize, q: &[f64], q_dot: &[f64], speed: f64) -> [f64; 2] {
        let shapes = &self.shapes[contact * self.modes..(contact + 1) * self.modes];
        let range = self.offset..self.offset + self.modes;
        let mut v = [0.0; 2];
        for ([u, turn], (&qi, &vi)) in shapes
            .iter()
            .zip(q[range.clone()].iter().zip(&q_dot[range]))
        {
            v[0] += vi * u[0] + speed * qi * turn[0];
            v[1] += vi * u[1] + speed * qi * turn[1];
        }
        v
    }
}
