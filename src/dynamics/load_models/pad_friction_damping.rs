//! The damping the pads' face friction puts on the modes, bounded at the
//! state of the last evaluation ([`LoadModel::held_damping_rate`]).
//!
//! Per face the friction F = −N g(s) v/s with g(s) = μ(s) tanh(s/v_reg) and
//! s = |v| (`face_friction.rs`) answers a change of the sliding velocity v
//! with ∂F/∂v = −N [g(s)/s (I − v̂v̂ᵀ) + g′(s) v̂v̂ᵀ]: across the sliding the
//! direction turns, and g(s)/s → μ/v_reg as s → 0 grows as 1/s while the
//! disc slows (at Ω r ≫ v_reg it is μ/(Ω r)). The face point's in-plane
//! velocity depends on the rates through −z ∇ẇ (the bending modes' tilt
//! rows) and u̇ (the in-plane modes, `pad_in_plane.rs`): J_f = ∂v_f/∂q̇ =
//! −z_f T_c + U_c at face f of contact c. So the friction's damping is
//! C = Σ_f J_fᵀ D_f J_f with ‖D_f‖ ≤ c_f = N_f max(g/s, |g′|), and
//! ‖M^(−½) C M^(−½)‖ is at most the largest eigenvalue of the small matrix
//! B = c^(½) G c^(½) over the faces' two in-plane directions, with the Gram
//! matrix G_fg = J_f M⁻¹ J_gᵀ = z_f z_g T_c M⁻¹ T_dᵀ + U_c M⁻¹ U_dᵀ (the
//! two families share no mode). Gershgorin's row sums of |B| bound that
//! eigenvalue from above. T M⁻¹ Tᵀ and U M⁻¹ Uᵀ among the contacts are made
//! once (2C × 2C each); where an integrator asks for the bound (at each
//! substep's start) it costs one slope of the friction law per face and
//! (4C)² products.
//!
//! The lining's patches (`pad_shear.rs`) carry the friction through their
//! own states, which only RK4 and `contact_exponential` integrate, and are
//! not bounded here.
//!
//! [`LoadModel::held_damping_rate`]: super::model::LoadModel::held_damping_rate

use super::face_friction::{contact_gram, damping_per_normal, sliding_velocity};
use super::model::SceneNodes;
use super::pad::{PadScratch, Pads, FRICTION_REGULARISATION_SPEED};
use super::pad_config::ContactSurface;

impl Pads {
    /// T M⁻¹ Tᵀ of the bending modes' rows ∇φ_i (`NodeFrame::gradient`, in
    /// frame A's axes as the in-plane rows) among the contact points.
    pub(super) fn with_friction_gram(mut self, nodes: &SceneNodes) -> Pads {
        if self.contact_surface != ContactSurface::Faces {
            return self;
        }
        let gradient = |c: usize, i: usize| nodes.ale[self.contacts[c].node].gradient(i);
        self.friction_gram = contact_gram(gradient, self.contacts.len(), nodes.modal_mass.iter());
        self
    }

    /// The Gershgorin bound of B = c^(½) G c^(½) at the normal forces and
    /// face kinematics of the last evaluation at speed Ω = `speed`, 1/s; the
    /// faces' c_f into `ContactForces::damping`.
    pub(super) fn friction_damping_rate(&self, speed: f64, s: &mut PadScratch) -> f64 {
        if self.friction_gram.is_empty() || self.shear.is_some() {
            return 0.0;
        }
        let law = self.friction_law(self.friction_coefficient);
        for ((c, f), k) in self.contacts.iter().zip(s.forces.iter_mut()).zip(&s.faces) {
            let faces = [(f.top, c.face_z[0]), (f.bottom, c.face_z[1])];
            for ((normal, z), damping) in faces.into_iter().zip(f.damping.iter_mut()) {
                let z = z + self.node_z(c);
                let v = sliding_velocity(k, z, c.radius, c.sin_cos, speed, self.follower_friction);
                *damping =
                    normal.abs() * damping_per_normal(&law, v, FRICTION_REGULARISATION_SPEED);
            }
        }
        self.face_gram_bound(|c, f| s.forces[c].damping[f].sqrt())
    }

    /// max over the rows of Σ_cols |r_row G_row,col r_col|: Gershgorin's bound
    /// of the largest eigenvalue of diag(r) G diag(r), G the Gram matrix of
    /// the faces' in-plane velocity rows (two per face), r per face.
    fn face_gram_bound(&self, root: impl Fn(usize, usize) -> f64) -> f64 {
        let n = 2 * self.contacts.len();
        let in_plane = self.in_plane.as_ref().map(|ip| ip.gram());
        let z = |c: usize, f: usize| self.contacts[c].face_z[f] + self.node_z(&self.contacts[c]);
        let mut bound = 0.0f64;
        for (c, f, x) in face_rows(self.contacts.len()) {
            let row = 2 * c + x;
            let sum: f64 = face_rows(self.contacts.len())
                .map(|(d, g, y)| {
                    let col = row * n + 2 * d + y;
                    let u = in_plane.map_or(0.0, |u| u[col]);
                    (z(c, f) * z(d, g) * self.friction_gram[col] + u).abs() * root(d, g)
                })
                .sum();
            bound = bound.max(root(c, f) * sum);
        }
        bound
    }
}

/// (contact, face, direction) of the rows of B.
fn face_rows(contacts: usize) -> impl Iterator<Item = (usize, usize, usize)> + Clone {
    (0..contacts).flat_map(|c| (0..2).flat_map(move |f| (0..2).map(move |x| (c, f, x))))
}
