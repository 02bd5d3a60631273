//! The lining's patches in the linear stability analysis (`pad_linear.rs`;
//! `pad_shear.rs`, docs/scenes.md "Pad shear").
//!
//! About steady sliding at V = Ωr with constant μ the tangential force stays
//! μN whatever the patch does, so a patch enters only through the sliding
//! direction. Per contact, with a = N₀ g/|V| (g = μ τ(|V|), N₀ the preload
//! per face) and the face point's radial velocity v_r = −z R,
//! R = D(∂_r w)/Dt − Ω ∂_θ w / r, each face's radial patch deflection is
//! −z ζ with one ζ per contact (both faces see the same a):
//!
//!   (c_t + a) ζ̇ = a R − k_t ζ,
//!
//! and the radial friction acts on R − ζ̇ in place of R: the rigid term
//! f_i −= (h²/2) a ∂_r w_i R gains + (h²/2) a ∂_r w_i ζ̇. Eliminating ζ
//! gives the filter a → a H(λ), H = (k_t + c_t λ)/(k_t + (c_t + a) λ); as
//! state the eigenproblem stays linear. The tangential deflections follow
//! μ δN through k_t + c_t λ and act on nothing (their eigenvalue −k_t/c_t):
//! they are left out.

use super::linear::{LinearContext, LinearOut};
use super::pad::Pads;
use super::pad_linear::ClosedContact;
use super::pad_patch::PatchLaw;

impl Pads {
    /// Patches in the linear system: one ζ per contact with `pads.shear_stiffness`
    /// (the pads' first-order states, [`super::linear`]).
    pub(super) fn patch_dofs(&self) -> usize {
        self.shear.map_or(0, |_| self.contacts.len())
    }

    /// ζ̇ = −k_t/c_t ζ for every contact (the open ones keep it).
    pub(super) fn add_patch_relaxation(&self, out: &mut LinearOut) {
        if let Some(law) = self.shear {
            for ci in 0..self.contacts.len() {
                let z = out.at.first_order + ci;
                out.a[(z, z)] = -law.stiffness / law.damping;
            }
        }
    }

    /// Contact `c`'s patch (module docs) at its preload per face, speed Ω
    /// and μ(V) into `out`.
    pub(super) fn add_patch_terms(
        &self,
        law: &PatchLaw,
        ctx: &LinearContext,
        out: &mut LinearOut,
        c: &ClosedContact,
    ) {
        let n = out.at.modes;
        let (speed, preload, mu) = (ctx.speed, c.preload, c.mu);
        let mass = ctx.modal_mass;
        let node = c.node;
        let h = c.contact.face_z[0] - c.contact.face_z[1];
        let (s, co) = c.contact.sin_cos;
        let v = (speed * c.contact.radius).abs();
        let damp = preload * Pads::friction_per_speed(mu, v);
        let lever = 0.5 * h * h * damp;
        let denom = law.damping + damp;
        let (share, relax) = (damp / denom, law.stiffness / denom);
        let z = out.at.first_order + c.index;
        let a = &mut *out.a;
        a[(z, z)] = -relax;
        let radial = |g: [f64; 2]| co * g[0] + s * g[1];
        for m in 0..n {
            let (dr, drt) = (radial(node.gradient(m)), radial(node.gradient_phi[m]));
            // ζ̇ ∋ share R, R = Σ_m (∂_r w_m q̄̇_m + Ω ∂_θ(∂_r w)_m q̄_m) (the rigid terms' R).
            a[(z, n + m)] += share * dr;
            a[(z, m)] += share * speed * drt;
            for i in 0..n {
                let on = lever * radial(node.gradient(i)) / mass[i];
                a[(n + i, n + m)] += on * share * dr;
                a[(n + i, m)] += on * share * speed * drt;
            }
        }
        for i in 0..n {
            a[(n + i, z)] -= lever * radial(node.gradient(i)) / mass[i] * relax;
        }
    }
}
