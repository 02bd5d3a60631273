//! The lining's shear on the pads (`pads.shear_stiffness`,
//! `pads.shear_damping`; docs/scenes.md, "Pad shear"): each contact face
//! carries its friction through a massless tangential patch
//! (`pad_patch.rs`), whose in-plane deflection is state of the pads.
//!
//! Stick is the rigid pads' regularised one: while |k_t x| < μN the relative
//! speed stays below a few v_reg and the patch creeps at the rate
//! k_t/(c_t + μN/v_reg); sliding, the spring force sits at μN and the patch
//! relaxes along the sliding direction at k_t/c_t, the fastest rate the
//! patch adds (in the pads' coupling, so RK4 substeps resolve it;
//! `contact_exponential` takes it into its linearisation). c_t > 0 is
//! required: with c_t = 0 the sliding patch is an algebraic constraint
//! (|k_t x| = μN exactly), infinitely stiff.
//!
//! The joint sees the friction only through the patches' forces in the node
//! loads: the pads declare no implicit friction-torque terms with patches
//! (`joint.rs`), since the rigid law's μN r tanh(Ω r / v_reg) is not the
//! force a sticking patch carries.
//!
//! The slot holds, after the massive pads' states, per contact point
//! (top radial, top tangential, bottom radial, bottom tangential) the
//! patches' deflections from steady sliding under the initial clamp forces
//! at the initial speed ([`Pads::patch_reference`]), m: the state's origin
//! is then the steady sliding the brake starts in, where
//! `contact_exponential` linearises (at x = 0 the patch would be in stick, a
//! linearisation whose rates, ~k_t/(μN/v_reg), are 1e4 times slower than
//! the sliding patch's k_t/c_t: on config/brake_squeal.yaml that took 1.8
//! times the evaluations of the pads).

use super::face_friction::{sliding_velocity, FaceKinematics};
use super::model::Coupling;
use super::pad::{ContactForces, PadContactPoint, Pads, FRICTION_REGULARISATION_SPEED};
use super::pad_patch::{PatchLaw, PatchSlot};
use crate::dynamics::wrench::Wrench;

impl Pads {
    /// Entries of the patches' part of the slot: 4 per contact point with
    /// `pads.shear_stiffness`, else none.
    pub fn patch_states(&self) -> usize {
        self.shear.map_or(0, |_| 4 * self.contacts.len())
    }

    /// The tangential deflection of both faces' patches at `contact` in
    /// steady sliding under the initial clamp force at the initial speed,
    /// x_θ = μ N₀/n τ(|Ω r|) sign Ω / k_t, m: the origin of the slot's patch
    /// states (the patches start there; 0 without patches).
    pub fn patch_reference(&self, contact: &PadContactPoint) -> f64 {
        let Some(law) = self.shear else { return 0.0 };
        let normal =
            self.initial_clamp_force[contact.pad] / self.contacts_per_pad[contact.pad] as f64;
        self.friction_coefficient * normal.max(0.0) / law.stiffness
            * Pads::sliding_sign(law.initial_speed, contact.radius)
    }

    /// The patches' deflections of `contact` from its slot entries `x`
    /// (radial and tangential, top then bottom face), m.
    pub fn patch_deflections(&self, contact: &PadContactPoint, x: &[f64]) -> [f64; 4] {
        let reference = self.patch_reference(contact);
        [x[0], x[1] + reference, x[2], x[3] + reference]
    }

    /// The wrench of both faces' friction through their patches (the
    /// slot's deflections) and the normal forces at the node, as
    /// [`Pads::face_wrench`]; writes the patches' rates and the faces'
    /// relative sliding speeds into the slot.
    pub(super) fn patch_wrench(
        &self,
        law: &PatchLaw,
        contact: &PadContactPoint,
        f: &mut ContactForces,
        k: &FaceKinematics,
        speed: f64,
        slot: PatchSlot<'_>,
    ) -> Wrench {
        let PatchSlot { x, rates, slip } = slot;
        let mut w = Wrench::default();
        let x = self.patch_deflections(contact, x);
        let (s, c) = contact.sin_cos;
        let node_z = 0.5 * (contact.face_z[0] + contact.face_z[1]);
        f.tangential = 0.0;
        for (face, (normal, z)) in [(f.top, contact.face_z[0]), (f.bottom, contact.face_z[1])]
            .into_iter()
            .enumerate()
        {
            // The faces are at node z + face_z: the lever of the velocity is
            // the face's z in the plate (mid-plane at 0).
            let v = sliding_velocity(
                k,
                z - node_z,
                contact.radius,
                contact.sin_cos,
                speed,
                self.follower_friction,
            );
            let polar = [c * v[0] + s * v[1], -s * v[0] + c * v[1], v[2]];
            let patch = law.face(
                [x[2 * face], x[2 * face + 1]],
                normal,
                self.friction_coefficient,
                polar,
                FRICTION_REGULARISATION_SPEED,
            );
            rates[2 * face..2 * face + 2].copy_from_slice(&patch.rate);
            slip[face] = patch.slip;
            let [fr, ft, fz] = patch.force;
            let fx = c * fr - s * ft;
            let fy = s * fr + c * ft;
            w.force[0] += fx;
            w.force[1] += fy;
            w.force[2] += fz;
            w.moment[0] -= z * fy;
            w.moment[1] += z * fx;
            f.tangential += ft;
        }
        w.force[2] += f.axial;
        w
    }

    /// The patches' fastest rate k_t/c_t (the sliding patch's relaxation
    /// along the sliding direction) added to the coupling bound.
    pub(super) fn with_patch_coupling(mut self) -> Pads {
        if let Some(law) = self.shear {
            self.coupling = Coupling {
                relaxation_rate: law.stiffness / law.damping,
                ..self.coupling
            };
        }
        self
    }
}
