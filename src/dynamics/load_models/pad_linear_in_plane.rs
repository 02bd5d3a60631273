//! The pads' friction on the in-plane modes in the linear stability analysis
//! (`plate.in_plane_nodal_diameters`; `pad_linear.rs` for the bending modes,
//! `pad_in_plane.rs` and `face_friction.rs` for the law the simulation steps).
//!
//! Each face f of a contact at (r, θ) slides with
//! v_f = V e_θ − z_f D(∇w)/Dt + D u/Dt (and the follower part along e_z),
//! V = Ωr, and carries the friction
//! F_f = −N_f g(|v_f|) v_f/|v_f|, g(v) = μ(v) tanh(v/v_reg); in-plane mode j
//! takes the work u_j·(F_t + F_b). About the preloaded state (N_f = p per face,
//! v_f = V e_θ) the first-order change of F_f is
//!
//!   δF_f = −p (g′ (e_θ·δv_f) e_θ + (g/|V|) (e_r·δv_f) e_r) − g sign V δN_f e_θ,
//!
//! g′ = dg/d|v| (the same g/|V| and g′ as the bending face terms of
//! `pad_linear.rs`). With D u/Dt = Σ_m (q̄̇_m u_m + Ω q̄_m ∂u_m/∂θ)
//! (`InPlaneDynamics::ale_contacts`: u and ∂u/∂θ in Cartesian components)
//! the in-plane modes get, per contact,
//!
//!   f_j −= 2p (g′ u_θ,j (e_θ·D u/Dt) + (g/|V|) u_r,j (e_r·D u/Dt)),
//!   f_j −= g sign V (δN_t + δN_b) u_θ,j,
//!
//! u_r,j = e_r·u_j, u_θ,j = e_θ·u_j at the contact. The two faces lie at
//! z = ±h/2 with the same preload, so the bending part −z_f D(∇w)/Dt of δv_f
//! cancels in F_t + F_b, and the in-plane part D u/Dt, the same at both
//! faces, gives no moment Σ z_f e_z × δF_f: to first order the bending modes
//! do not drive the in-plane ones through the sliding velocity, nor the
//! in-plane ones the bending ones. The normal forces couple them only
//! through their sum: a massless pad's faces change by ∓δN (δN_t + δN_b = 0,
//! `pad_linear.rs`), a massive pad's by (S ∓ F)/2 with
//! S = k_c (ξ_t + ξ_b) + c_c (ξ̇_t + ξ̇_b) (`pad_linear_mass.rs`): the pads'
//! compressions drive the in-plane modes, which act back on nothing. The
//! linearised in-plane modes are therefore damped by the friction (g/|V|
//! radially, g′ tangentially) but not made unstable by the bending modes:
//! the eigenvalues are those of the bending system and of the in-plane
//! system apart (docs/in_plane.md, "Stability"). At the mid-plane
//! (`pads.contact_surface: midplane`) the friction −μ N tanh(V/v_reg) e_θ
//! reads no in-plane rate; only the massive pads' S term is there.

use super::linear::{LinearContext, LinearOut};
use super::pad::{Pads, FRICTION_REGULARISATION_SPEED};
use super::pad_config::ContactSurface;
use super::pad_linear::ClosedContact;

impl Pads {
    /// The in-plane modes' rows of one closed contact (module docs); nothing
    /// without in-plane modes.
    pub(super) fn add_in_plane_terms(
        &self,
        ctx: &LinearContext,
        out: &mut LinearOut,
        c: &ClosedContact,
    ) {
        let Some(ip) = ctx.in_plane else {
            return;
        };
        let n = out.at.modes;
        let shapes = &ip.ale_contacts[c.contact.node];
        let (s, co) = c.contact.sin_cos;
        let radial = |u: [f64; 2]| co * u[0] + s * u[1];
        let tangential = |u: [f64; 2]| -s * u[0] + co * u[1];
        let rows = || shapes.iter().enumerate().map(|(j, sh)| (ip.offset + j, sh));
        if self.contact_surface == ContactSurface::Faces {
            let (g_over_v, g_slope) = self.face_friction_slopes(ctx, c);
            let both = 2.0 * c.preload;
            for (i, [u_i, _]) in rows() {
                let (ur, ut) = (radial(*u_i), tangential(*u_i));
                for (m, [u_m, turn_m]) in rows() {
                    let on_rate = g_over_v * ur * radial(*u_m) + g_slope * ut * tangential(*u_m);
                    let on_q = g_over_v * ur * radial(*turn_m) + g_slope * ut * tangential(*turn_m);
                    out.a[(n + i, n + m)] -= both * on_rate / ctx.modal_mass[i];
                    out.a[(n + i, m)] -= both * ctx.speed * on_q / ctx.modal_mass[i];
                }
            }
        }
        if self.is_massive() {
            // F_θ per unit δN_t + δN_b, and S per unit ξ, ξ̇ of the contact's pad.
            let per_normal = -c.mu * Pads::sliding_sign(ctx.speed, c.contact.radius);
            let pad = 2 * c.contact.pad;
            for (i, [u_i, _]) in rows() {
                let f = per_normal * tangential(*u_i) / ctx.modal_mass[i];
                for face in [pad, pad + 1] {
                    out.a[(n + i, out.at.coordinates + face)] += f * self.stiffness;
                    out.a[(n + i, out.at.rates + face)] += f * self.damping;
                }
            }
        }
    }

    /// g/|V| and g′ = dg/d|v| of the face friction g(v) = μ(v) tanh(v/v_reg)
    /// at the contact's sliding speed |V| = |Ωr|.
    pub(super) fn face_friction_slopes(
        &self,
        ctx: &LinearContext,
        c: &ClosedContact,
    ) -> (f64, f64) {
        let v = (ctx.speed * c.contact.radius).abs();
        let x = v / FRICTION_REGULARISATION_SPEED;
        let law = self.friction_law(ctx.friction_coefficient);
        let mu_v = law.mu(v);
        (
            Pads::friction_per_speed(mu_v, v),
            mu_v / (FRICTION_REGULARISATION_SPEED * x.cosh().powi(2)) + law.slope(v) * x.tanh(),
        )
    }
}
