//! The pads' contact law (paper 5.3): the normal forces of both faces at a
//! contact point from the surface kinematics under it and the caliper
//! (`pads.caliper`), the friction μN, and the wrench they make at the node —
//! at the mid-plane node or, with `pads.contact_surface: faces`, on each face
//! (`face_friction.rs` for the faces' kinematics and μ(v)). The model that
//! uses it, its builder and its registration are in `pad.rs`.

use super::face_friction::{friction_force, sliding_velocity, FaceKinematics, FrictionLaw};
use super::model::SurfaceKinematics;
use super::pad::{ContactForces, PadContactPoint, Pads, FRICTION_REGULARISATION_SPEED};
use super::pad_config::Caliper;
use crate::dynamics::wrench::Wrench;

impl Pads {
    /// Forces at every contact point (`out[c]` for `self.contacts[c]`) for the
    /// pads' clamp forces, the surface kinematics `kin[c]` under each contact
    /// and the joint speed Ω. `closed` is scratch of the contacts' length.
    pub fn forces(
        &self,
        clamp_force: &[f64],
        kin: &[SurfaceKinematics],
        speed: f64,
        out: &mut [ContactForces],
        closed: &mut [bool],
    ) {
        let (k, c) = (self.stiffness, self.damping);
        match self.caliper {
            Caliper::Fixed => {
                for ((contact, s), f) in self.contacts.iter().zip(kin).zip(out.iter_mut()) {
                    let u = clamp_force[contact.pad] / self.contacts_per_pad[contact.pad] as f64;
                    f.top = u + k * s.w + c * s.w_dot;
                    f.bottom = u - k * s.w - c * s.w_dot;
                }
            }
            Caliper::Floating => {
                for (pad, &clamp) in clamp_force.iter().enumerate().take(self.pad_count()) {
                    for sign in [1.0, -1.0] {
                        let u = self.backing_force(pad, clamp, sign, kin, closed);
                        for ((contact, s), f) in self.contacts.iter().zip(kin).zip(out.iter_mut()) {
                            if contact.pad == pad {
                                // Pressed with nothing, a floating pad exerts
                                // nothing on any active set (Σ N = 0, N ≥ 0).
                                let n = if clamp > 0.0 || !self.lift_off {
                                    u + sign * (k * s.w + c * s.w_dot)
                                } else {
                                    0.0
                                };
                                if sign > 0.0 {
                                    f.top = n;
                                } else {
                                    f.bottom = n;
                                }
                            }
                        }
                    }
                }
            }
        }
        self.net_and_friction(speed, out);
    }

    /// Lift-off (N ≥ 0 with `pads.lift_off`), the net axial force and the
    /// friction of the normal forces in `out`.
    pub(super) fn net_and_friction(&self, speed: f64, out: &mut [ContactForces]) {
        // sign(Ω) at the last radius: contacts on one radius share it.
        let mut sign = (f64::NAN, 0.0);
        for (contact, f) in self.contacts.iter().zip(out.iter_mut()) {
            if contact.radius != sign.0 {
                sign = (contact.radius, Self::sliding_sign(speed, contact.radius));
            }
            f.margin = [f.top.max(-f64::MAX), f.bottom.max(-f64::MAX)];
            if self.lift_off {
                f.top = f.top.max(0.0);
                f.bottom = f.bottom.max(0.0);
            }
            f.axial = f.bottom - f.top;
            f.tangential = -self.friction_coefficient * (f.top + f.bottom) * sign.1;
        }
    }

    /// u of a floating pad's face (`sign` +1 top, −1 bottom): Σ_c N_c = N₀
    /// over the contacts that stay closed, N_c = u + sign (k_c w + c_c ẇ).
    fn backing_force(
        &self,
        pad: usize,
        clamp: f64,
        sign: f64,
        kin: &[SurfaceKinematics],
        closed: &mut [bool],
    ) -> f64 {
        let e = |s: &SurfaceKinematics| sign * (self.stiffness * s.w + self.damping * s.w_dot);
        for (flag, contact) in closed.iter_mut().zip(&self.contacts) {
            *flag = contact.pad == pad;
        }
        loop {
            let (mut sum, mut count) = (0.0, 0usize);
            for ((s, &on), _) in kin.iter().zip(closed.iter()).zip(&self.contacts) {
                if on {
                    sum += e(s);
                    count += 1;
                }
            }
            if count == 0 {
                return f64::NEG_INFINITY;
            }
            let u = (clamp - sum) / count as f64;
            if !self.lift_off {
                return u;
            }
            // Open the contacts that would pull; u only falls as they open, so
            // the open ones stay open: at most n passes.
            let mut opened = false;
            for (s, on) in kin.iter().zip(closed.iter_mut()) {
                if *on && u + e(s) < 0.0 {
                    *on = false;
                    opened = true;
                }
            }
            if !opened {
                return u;
            }
        }
    }

    /// The wrench of `f` on the disc in the ALE node frame (axes of frame A).
    #[inline]
    pub fn wrench(contact: &PadContactPoint, f: &ContactForces) -> Wrench {
        let (s, c) = contact.sin_cos;
        // e_θ = (−sin θ, cos θ, 0)
        Wrench {
            force: [-s * f.tangential, c * f.tangential, f.axial],
            moment: [0.0; 3],
        }
    }
}

impl Pads {
    /// The wrench of both faces' friction and the normal forces at the node
    /// (`pads.contact_surface: faces`): F = F_t + F_b + (N_b − N_t) e_z,
    /// M = Σ_f z_f e_z × F_f about the node. Sets `f.tangential` to the
    /// friction's e_θ component.
    pub fn face_wrench(
        &self,
        contact: &PadContactPoint,
        f: &mut ContactForces,
        k: &FaceKinematics,
        speed: f64,
    ) -> Wrench {
        let mut w = Wrench::default();
        let (s, c) = contact.sin_cos;
        f.tangential = 0.0;
        for (normal, z) in [(f.top, contact.face_z[0]), (f.bottom, contact.face_z[1])] {
            let v = sliding_velocity(
                k,
                z + self.node_z(contact),
                contact.radius,
                contact.sin_cos,
                speed,
                self.follower_friction,
            );
            let law = self.friction_law(self.friction_coefficient);
            let fr = friction_force(&law, normal, v, FRICTION_REGULARISATION_SPEED);
            for (wa, fa) in w.force.iter_mut().zip(&fr) {
                *wa += fa;
            }
            w.moment[0] -= z * fr[1];
            w.moment[1] += z * fr[0];
            f.tangential += -s * fr[0] + c * fr[1];
        }
        w.force[2] += f.axial;
        w
    }

    /// The face friction law with μ = `kinetic` (the configured μ_s − μ kept).
    pub fn friction_law(&self, kinetic: f64) -> FrictionLaw {
        FrictionLaw {
            kinetic,
            excess: self.friction_excess,
            stribeck_speed: self.stribeck_speed,
        }
    }

    /// z of the contact's node frame (the faces are at node z + face_z).
    pub(super) fn node_z(&self, contact: &PadContactPoint) -> f64 {
        0.5 * (self.thickness_from(contact)) - contact.face_z[0]
    }

    fn thickness_from(&self, contact: &PadContactPoint) -> f64 {
        contact.face_z[0] - contact.face_z[1]
    }
}
