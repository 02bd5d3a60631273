//! The pads in the linear stability analysis: the flutter instability of the
//! paper's brake-squeal model (section 5.3, Fig. 17; `dynamics::stability`
//! assembles the plate's terms, [`super::linear`] the layout).
//!
//! About the undeformed state at constant joint speed Ω, in ALE coordinates
//! y = (q̄, q̄̇) (docs/dynamics.md), space-fixed pads are constant and add
//!
//!   q̄̈ ∋ M⁻¹(−K_pad + K_fric) q̄ − M⁻¹C_pad q̄̇,
//!
//! with, summed over the contact points c (shape values w_i and surface tilt
//! (θ_x, θ_y)_i of mode i at the node, friction force F = (F_x, F_y) at the
//! preload: F_θ = −μ·2N₀/n · sign Ω along e_θ):
//!
//! - K_pad,im = 2 k_c w_i w_m, C_pad,im = 2 c_c w_i w_m (both faces) for a
//!   fixed caliper; with a floating one the pads follow their mean, so
//!   w − w̄ (w̄ the mean over the pad's contact points) replaces w;
//! - K_fric,im = w_i (F_y θ_x,m − F_x θ_y,m): the follower friction's normal
//!   component, (F_θ/r) ∂w/∂θ — not symmetric, hence flutter (under Mindlin
//!   theory taken from ∂w_m/∂θ: the tilt is then ψ, not the slope).
//!
//! With `pads.contact_surface: faces` (docs/scenes.md, "Friction on the
//! faces") each contact adds, with g = μ tanh(|V|/v_reg), V = Ωr, p the
//! preload per face, δN = k_c (w − w̄) + c_c (ẇ − ẇ̄) and Ẇ = ∂w/∂t + Ω ∂w/∂θ:
//!
//! - the friction couple  f_i += h g sign V (1/r) ∂_θ w_i δN,
//! - the sliding direction f_i −= (h²/2) p (g/|V|) ∂_r w_i (D(∂_r w)/Dt − Ω ∂_θ w / r),
//! - the speed slope      f_i −= (h²/2) p g′ (1/r) ∂_θ w_i (D(∂_θ w / r)/Dt + Ω ∂_r w),
//!   g′ = dg/d|v| (μ(v) = μ + (μ_s − μ) e^(−v/v_S) and the regularisation),
//!
//! the face point's radial and tangential velocity over −z, with the polar
//! basis' rotation (`face_friction.rs`; zero for a tilt held in space);
//! under Mindlin theory ∂_r w, ∂_θ w / r and their turn are those of −ψ
//! (the face point moves by z ψ: the node frames' gradient, docs/mindlin.md);
//!
//! (`add_face_terms`); the follower term above is the normal part of the
//! sliding direction and is the same.
//!
//! With `plate.residual_flexibility` the contacts act in series with the
//! residual compliance G among them (`dynamics::contact_compliance`, the same
//! law the simulation steps): the net axial forces are
//! F = −(I + K G)⁻¹ (K W q̄ + C W q̄̇), K = −∂F/∂w of the closed contacts
//! (2k_c (I − P), P the pad means of a floating caliper) and C = (c_c/k_c) K,
//! W the shapes at the contacts; they replace −K_pad q̄ − C_pad q̄̇ (f_i = w_i F)
//! and, as δN = −F/2, the face terms' δN ([`Pads::linear_series_forces`]).
//!
//! The friction force's magnitude does not change to first order (the two
//! faces' spring forces change by ∓k_c w). Lift-off is inactive about a
//! preloaded state: a contact with no clamp force is open. Massive pads add
//! their compressions as coordinates (`pad_linear_mass.rs`), the lining's
//! patches one first-order state per contact (`pad_linear_shear.rs`).

use super::linear::{LinearContext, LinearOut, LinearStates, OperatingPoint};
use super::pad::{PadContactPoint, Pads, FRICTION_REGULARISATION_SPEED};
use super::pad_config::{Caliper, ContactSurface};
use super::pad_linear_mass::NetForce;
use super::pad_series::LinearSeriesForces;
use crate::config::PlateTheory;
use crate::dynamics::node_frame::NodeFrame;

/// One closed contact at the operating point.
pub(super) struct ClosedContact<'a> {
    /// The contact point.
    pub contact: &'a PadContactPoint,
    /// Its index among the pads' contacts.
    pub index: usize,
    /// Its ALE node frame.
    pub node: &'a NodeFrame,
    /// Per mode the mean shape w̄ over its pad's contacts (a floating
    /// caliper's massless pads follow it; zero otherwise).
    pub mean: &'a [f64],
    /// The preload per face, N₀/n, N.
    pub preload: f64,
    /// μ at its sliding speed |V| = |Ω r| (the friction coefficient at the mid-plane).
    pub mu: f64,
}

impl Pads {
    /// Massive pads: two coordinates per pad (top, bottom); the lining's
    /// patches: one first-order state per contact (`pad_linear_shear.rs`).
    pub(super) fn linear_state_count(&self) -> LinearStates {
        LinearStates {
            coordinates: self.pad_states() / 2,
            first_order: self.patch_dofs(),
        }
    }

    /// The configured friction coefficient and initial clamp forces.
    pub(super) fn configured_operating_point(&self) -> OperatingPoint {
        OperatingPoint {
            friction_coefficient: self.friction_coefficient,
            clamp_force: self.initial_clamp_force.clone(),
        }
    }

    /// The pads' first-order terms (module docs) into `out`.
    pub(super) fn add_linear(&self, ctx: &LinearContext, mut out: LinearOut) {
        let mean = self.pad_means(ctx, out.at.modes);
        // In series with G: the contact forces per unit q̄ and q̄̇ (n_c × n).
        let active: Vec<bool> = self
            .contacts
            .iter()
            .map(|c| !(self.lift_off && ctx.clamp_force[c.pad] <= 0.0))
            .collect();
        let series = self
            .series
            .as_ref()
            .map(|g| self.linear_series_forces(g, ctx.ale_nodes, &active));
        self.add_patch_relaxation(&mut out);
        for (ci, contact) in self.contacts.iter().enumerate() {
            let clamp = ctx.clamp_force[contact.pad];
            if self.lift_off && clamp <= 0.0 {
                continue; // touching without preload: not in contact to first order
            }
            // With face friction μ is μ(V) at the sliding speed V = Ωr (equal to μ without μ_s).
            let mu = match self.contact_surface {
                ContactSurface::Faces => self
                    .friction_law(ctx.friction_coefficient)
                    .mu((ctx.speed * contact.radius).abs()),
                ContactSurface::MidPlane => ctx.friction_coefficient,
            };
            let c = ClosedContact {
                contact,
                index: ci,
                node: &ctx.ale_nodes[contact.node],
                mean: &mean[contact.pad],
                preload: clamp / self.contacts_per_pad[contact.pad] as f64,
                mu,
            };
            self.add_contact_terms(ctx, &mut out, &c, series.as_ref());
            self.add_in_plane_terms(ctx, &mut out, &c);
            if self.contact_surface == ContactSurface::Faces {
                self.add_face_terms(ctx, &mut out, &c, series.as_ref());
                if let Some(law) = &self.shear {
                    self.add_patch_terms(law, ctx, &mut out, &c);
                }
            }
            if self.is_massive() {
                let couple = match self.contact_surface {
                    ContactSurface::Faces => {
                        self.face_couple(contact, ctx.speed, ctx.friction_coefficient)
                    }
                    ContactSurface::MidPlane => 0.0,
                };
                let nb = c.node.shapes.len();
                let net = match &series {
                    Some(l) => NetForce::in_series(l, ci, nb, self),
                    None => NetForce::direct(self, contact, c.node),
                };
                self.add_pad_terms(ctx, &mut out, contact, couple, &net);
            }
        }
        if self.is_massive() {
            self.add_pad_identity(&mut out);
        }
    }

    /// Per pad the mean shape over its contacts: a floating caliper's pads
    /// follow it, so its springs see w − w̄ (docs/scenes.md); zero otherwise.
    fn pad_means(&self, ctx: &LinearContext, n: usize) -> Vec<Vec<f64>> {
        let mut mean = vec![vec![0.0; n]; self.pad_count()];
        if self.caliper == Caliper::Floating && !self.is_massive() {
            for c in &self.contacts {
                let share = 1.0 / self.contacts_per_pad[c.pad] as f64;
                for (m, s) in mean[c.pad].iter_mut().zip(&ctx.ale_nodes[c.node].shapes) {
                    *m += share * s.w;
                }
            }
        }
        mean
    }

    /// The contact springs and dampers (K_pad, C_pad, or the net forces in
    /// series with G) and the follower friction K_fric of one contact.
    fn add_contact_terms(
        &self,
        ctx: &LinearContext,
        out: &mut LinearOut,
        c: &ClosedContact,
        series: Option<&LinearSeriesForces>,
    ) {
        let n = out.at.modes;
        let mass = ctx.modal_mass;
        let (ci, mean, node) = (c.index, c.mean, c.node);
        let nb = node.shapes.len();
        let f_theta = -c.mu * 2.0 * c.preload * Pads::sliding_sign(ctx.speed, c.contact.radius);
        let (s, co) = c.contact.angle.sin_cos();
        let (fx, fy) = (-s * f_theta, co * f_theta);
        for i in 0..nb {
            let wi = node.shapes[i].w;
            let di = wi - mean[i];
            for (m, (&sm, &mean_m)) in node.shapes.iter().zip(mean).enumerate() {
                let dm = sm.w - mean_m;
                let mut k = match series {
                    None => -2.0 * self.stiffness * di * dm,
                    Some(l) => wi * l.q[ci * nb + m],
                };
                if self.follower_friction {
                    k += wi * self.follower_normal(node, m, sm.tilt, [fx, fy], f_theta);
                }
                out.a[(n + i, m)] += k / mass[i];
                let damping = match series {
                    None => 2.0 * self.damping * di * dm,
                    Some(l) => -wi * l.q_dot[ci * nb + m],
                };
                out.a[(n + i, n + m)] -= damping / mass[i];
            }
        }
    }

    /// The follower friction's normal force per unit q̄_m at the node:
    /// F·∇w_m = (F_θ / r) ∂w_m/∂θ, from the surface tilt (F_y θ_x − F_x θ_y)
    /// under Kirchhoff theory, from ∂w_m/∂θ under Mindlin theory (whose tilt
    /// is the rotation ψ of the normal, not the slope).
    fn follower_normal(
        &self,
        node: &NodeFrame,
        m: usize,
        tilt: [f64; 2],
        [fx, fy]: [f64; 2],
        f_theta: f64,
    ) -> f64 {
        match self.theory {
            PlateTheory::Kirchhoff => fy * tilt[0] - fx * tilt[1],
            PlateTheory::Mindlin => f_theta * node.w_phi[m] / node.radius,
        }
    }

    /// h μ(V) tanh(V/v_reg): the faces' couple per unit (δN_t − δN_b)/2 (see `add_face_terms`).
    fn face_couple(&self, contact: &PadContactPoint, speed: f64, mu: f64) -> f64 {
        let v = speed * contact.radius;
        let h = contact.face_z[0] - contact.face_z[1];
        h * self.friction_law(mu).mu(v.abs()) * (v / FRICTION_REGULARISATION_SPEED).tanh()
    }

    /// The face friction's first-order terms of one contact (module docs) on
    /// the modes' rows. `series`: the net axial forces per unit q̄ and q̄̇ in
    /// series with the residual compliance (δN = −F/2), or None
    /// (δN = k_c dn q̄ + c_c dn q̄̇).
    fn add_face_terms(
        &self,
        ctx: &LinearContext,
        out: &mut LinearOut,
        c: &ClosedContact,
        series: Option<&LinearSeriesForces>,
    ) {
        let n = out.at.modes;
        let nb = c.node.shapes.len();
        let ci = c.index;
        let series = series.map(|l| {
            (
                &l.q[ci * nb..(ci + 1) * nb],
                &l.q_dot[ci * nb..(ci + 1) * nb],
            )
        });
        let (speed, mean, preload) = (ctx.speed, c.mean, c.preload);
        let mass = ctx.modal_mass;
        let node = c.node;
        let h = c.contact.face_z[0] - c.contact.face_z[1];
        let r = c.contact.radius;
        let (s, co) = c.contact.sin_cos;
        let (g_over_v, g_slope) = self.face_friction_slopes(ctx, c);
        let couple = h * c.mu * Pads::sliding_sign(speed, r);
        let lever = 0.5 * h * h * preload;
        // Per mode: ∂_r w, ∂_θ w and the turn of the gradient ∂(∇w)/∂θ in the same
        // components: ∂_r ∂_θ w − ∂_θ w / r and ∂²_θ w + r ∂_r w.
        let radial = |g: [f64; 2]| co * g[0] + s * g[1];
        let angular = |g: [f64; 2]| r * (-s * g[0] + co * g[1]);
        for (i, &mass_i) in mass.iter().enumerate().take(nb) {
            let (dr_i, dt_i) = (radial(node.gradient(i)), angular(node.gradient(i)));
            for m in 0..nb {
                let (dr_m, dt_m) = (radial(node.gradient(m)), angular(node.gradient(m)));
                let (drt_m, dtt_m) = (radial(node.gradient_phi[m]), angular(node.gradient_phi[m]));
                let dn = node.shapes[m].w - mean[m];
                let dn_times = |coef: f64, stiff: f64, row: Option<&[f64]>| match row {
                    None => coef * stiff * dn,
                    Some(r) => coef * (-0.5 * r[m]),
                };
                // δN = k_c dn q + c_c dn q̇; v_r / −z = dr q̇ + Ω drt q, r v_θ / −z ∋ dt q̇ + Ω dtt q.
                let on_q = dn_times(couple * dt_i / r, self.stiffness, series.map(|s| s.0))
                    - lever * g_over_v * dr_i * speed * drt_m
                    - lever * g_slope / (r * r) * dt_i * speed * dtt_m;
                let on_q_dot = dn_times(couple * dt_i / r, self.damping, series.map(|s| s.1))
                    - lever * g_over_v * dr_i * dr_m
                    - lever * g_slope / (r * r) * dt_i * dt_m;
                out.a[(n + i, m)] += on_q / mass_i;
                out.a[(n + i, n + m)] += on_q_dot / mass_i;
            }
        }
    }
}
