//! Pads with mass (`pads.mass`, docs/scenes.md "Pad mass"): each face's pad
//! is a rigid body of mass m_p moving axially between its contact springs and
//! the caliper. Its state is the compression x of its contact springs (the
//! pad's travel into the undeformed disc face, m) and its rate ẋ, per pad and
//! face, integrated with the modes (RK4 at every stage). At contact c of the
//! pad, with the deflection w and its rate ẇ = ∂w/∂t|θ under the contact,
//!
//!   top (+z, pushes −z):    N_t = k_c (x_t + w) + c_c (ẋ_t + ẇ)
//!   bottom (−z, pushes +z): N_b = k_c (x_b − w) + c_c (ẋ_b − ẇ)
//!
//! (N ≥ 0 with `pads.lift_off`), and each pad moves under its backing force B
//! and its contacts (n of them):
//!
//!   m_p ẍ = B − Σ_c N_c,
//!   floating caliper: B = N₀ (the piston's force);
//!   fixed caliper:    B = N₀ − k_b (x − x₀), x₀ = N₀/(n k_c)
//!
//! (k_b = `pads.backing_stiffness`, the caliper's stiffness behind the pad;
//! the caliper is held where the clamp force puts the pad at rest, x = x₀).
//! At rest x = x₀ and every contact carries N₀/n, as the massless pads. As
//! m_p → 0 the floating pad's balance Σ N_c = N₀ is the massless floating
//! caliper's (it follows the mean w̄); the fixed one's becomes k_c in series
//! with k_b, the massless fixed caliper as k_b → ∞.

use super::model::{Coupling, SurfaceKinematics};
use super::pad::{ContactForces, Pads};
use super::pad_config::Caliper;

impl Pads {
    /// Whether the pads have mass (their axial motion is state).
    pub fn is_massive(&self) -> bool {
        self.mass > 0.0
    }

    /// Entries of the pads' slot: per pad (top, bottom) compression x, then
    /// their rates ẋ in the same order; none for massless pads.
    pub fn pad_states(&self) -> usize {
        if self.is_massive() {
            4 * self.pad_count()
        } else {
            0
        }
    }

    /// x₀ = N₀/(n k_c): the compression of pad `pad`'s springs at rest under the clamp force `clamp`, m.
    pub fn rest_compression(&self, pad: usize, clamp: f64) -> f64 {
        clamp / (self.contacts_per_pad[pad] as f64 * self.stiffness)
    }

    /// The slot at rest under the initial clamp forces: x = x₀, ẋ = 0.
    pub fn initial_pad_state(&self) -> Vec<f64> {
        let mut slot = vec![0.0; self.pad_states()];
        if self.is_massive() {
            for (pad, &clamp) in self.initial_clamp_force.iter().enumerate() {
                let x0 = self.rest_compression(pad, clamp);
                slot[2 * pad] = x0;
                slot[2 * pad + 1] = x0;
            }
        }
        slot
    }

    /// The backing force B on pad `pad` at compression `x` under the clamp force `clamp`, N.
    pub fn pad_backing_force(&self, pad: usize, clamp: f64, x: f64) -> f64 {
        match self.caliper {
            Caliper::Floating => clamp,
            Caliper::Fixed => {
                clamp - self.backing_stiffness * (x - self.rest_compression(pad, clamp))
            }
        }
    }

    /// Contact forces of massive pads in the state `slot` (module docs).
    pub(super) fn massive_forces(
        &self,
        slot: &[f64],
        kin: &[SurfaceKinematics],
        speed: f64,
        out: &mut [ContactForces],
    ) {
        let (k, c) = (self.stiffness, self.damping);
        let rates = 2 * self.pad_count();
        for ((contact, s), f) in self.contacts.iter().zip(kin).zip(out.iter_mut()) {
            let (t, b) = (2 * contact.pad, 2 * contact.pad + 1);
            f.top = k * (slot[t] + s.w) + c * (slot[rates + t] + s.w_dot);
            f.bottom = k * (slot[b] - s.w) + c * (slot[rates + b] - s.w_dot);
        }
        self.net_and_friction(speed, out);
    }

    /// The slot's rates: ẋ, and ẍ = (B − Σ_c N_c)/m_p per pad and face.
    pub(super) fn pad_rates(
        &self,
        slot: &[f64],
        clamp_force: &[f64],
        forces: &[ContactForces],
        rates: &mut [f64],
    ) {
        let half = 2 * self.pad_count();
        rates[..half].copy_from_slice(&slot[half..2 * half]);
        for (pad, &clamp) in clamp_force.iter().enumerate().take(self.pad_count()) {
            for face in 0..2 {
                let x = slot[2 * pad + face];
                rates[half + 2 * pad + face] = self.pad_backing_force(pad, clamp, x) / self.mass;
            }
        }
        for (contact, f) in self.contacts.iter().zip(forces) {
            rates[half + 2 * contact.pad] -= f.top / self.mass;
            rates[half + 2 * contact.pad + 1] -= f.bottom / self.mass;
        }
    }

    /// The coupling bound with massive pads: k_c (x + w)² ≤ 2 k_c x² + 2 k_c w²
    /// per face, so twice the disc's contact rate (`lam` the largest
    /// eigenvalue of M^(−½) Σ w wᵀ M^(−½)) plus the pads' own.
    pub(super) fn massive_coupling(&self, lam: f64) -> Coupling {
        let own = self.pad_own_coupling();
        Coupling {
            stiffness_rate_sq: 4.0 * self.stiffness * lam + own.stiffness_rate_sq,
            damping_rate: 4.0 * self.damping * lam + own.damping_rate,
            relaxation_rate: 0.0,
        }
    }

    /// The pads' own rates: (2 n k_c + k_b)/m_p and 2 n c_c/m_p (n the most
    /// contacts of any pad).
    pub(super) fn pad_own_coupling(&self) -> Coupling {
        let n = self.contacts_per_pad.iter().copied().max().unwrap_or(0) as f64;
        Coupling {
            stiffness_rate_sq: (2.0 * n * self.stiffness + self.backing_stiffness) / self.mass,
            damping_rate: 2.0 * n * self.damping / self.mass,
            relaxation_rate: 0.0,
        }
    }
}
