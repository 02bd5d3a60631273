//! Pad friction on the faces of the disc (`pads.contact_surface: faces`;
//! docs/scenes.md, "Friction on the faces").
//!
//! A Kirchhoff face point at z = ±h/2 moves in-plane by −z∇w. Under a
//! space-fixed pad at (r, θ) (an ALE node) the face material slides with
//!
//!   v = Ω r e_θ − z ∇Ẇ + Ω ∂w/∂θ e_z,   Ẇ = Dw/Dt = ∂w/∂t + Ω ∂w/∂θ,
//!
//! relative to the pad (whose contact point follows the gap at ∂w/∂t): the
//! rotation, the vibration's in-plane velocity and the normal part of the
//! sliding along the tilted surface (the paper's follower direction). In the
//! ALE description ∇Ẇ = Σ_i (q̄̇_i ∇w_i + Ω q̄_i ∇(∂w_i/∂θ)) — the rotation of
//! the gradient's axes cancels against the rigid turn of the displacement
//! (docs/scenes.md). Friction is regularised Coulomb along v:
//!
//!   F = −μ N tanh(|v| / v_reg) v/|v|,
//!
//! and acts at the face, so its in-plane part does the virtual work
//! −z F·∇w_i: the moment z e_z × F about the mid-plane point.

use crate::dynamics::node_frame::NodeFrame;

/// The vibration's velocity terms under a contact point (ALE amplitudes).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct FaceKinematics {
    /// ∇Ẇ = ∇(∂w/∂t + Ω ∂w/∂θ) in frame A's Cartesian axes, 1/s.
    pub grad_material_rate: [f64; 2],
    /// Ω ∂w/∂θ: the normal part of the sliding velocity, m/s.
    pub normal_rate: f64,
}

/// [`FaceKinematics`] at an ALE node for ALE amplitudes and rates at speed Ω.
#[inline]
pub fn face_kinematics(node: &NodeFrame, q: &[f64], q_dot: &[f64], speed: f64) -> FaceKinematics {
    let mut k = FaceKinematics::default();
    let mut w_theta = 0.0;
    for (i, (&qi, &vi)) in q.iter().zip(q_dot).enumerate() {
        let g = node.gradient(i);
        let gp = node.w_phi_grad[i];
        k.grad_material_rate[0] += vi * g[0] + speed * qi * gp[0];
        k.grad_material_rate[1] += vi * g[1] + speed * qi * gp[1];
        w_theta += qi * node.w_phi[i];
    }
    k.normal_rate = speed * w_theta;
    k
}

/// The sliding velocity of the face at `z` under the contact at radius `r`,
/// (sin θ, cos θ) = `sin_cos`, relative to the pad (normal part only with
/// `follower`), m/s.
#[inline]
pub fn sliding_velocity(
    k: &FaceKinematics,
    z: f64,
    radius: f64,
    sin_cos: (f64, f64),
    speed: f64,
    follower: bool,
) -> [f64; 3] {
    let (s, c) = sin_cos;
    let v = speed * radius;
    [
        -s * v - z * k.grad_material_rate[0],
        c * v - z * k.grad_material_rate[1],
        if follower { k.normal_rate } else { 0.0 },
    ]
}

/// The friction coefficient as a function of the sliding speed:
/// μ(v) = μ + (μ_s − μ) e^(−v/v_S) (a Stribeck-type fall from μ_s at rest to
/// μ; `excess` = μ_s − μ = 0: constant μ).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FrictionLaw {
    /// μ, the coefficient at sliding speeds ≫ v_S.
    pub kinetic: f64,
    /// μ_s − μ.
    pub excess: f64,
    /// v_S, m/s.
    pub stribeck_speed: f64,
}

impl FrictionLaw {
    /// μ(v) at sliding speed `v` ≥ 0.
    #[inline]
    pub fn mu(&self, v: f64) -> f64 {
        if self.excess == 0.0 {
            return self.kinetic;
        }
        self.kinetic + self.excess * (-v / self.stribeck_speed).exp()
    }

    /// dμ/dv at `v` ≥ 0, s/m.
    pub fn slope(&self, v: f64) -> f64 {
        -self.excess / self.stribeck_speed * (-v / self.stribeck_speed).exp()
    }
}

/// Regularised Coulomb friction on the disc for normal force `normal` (≥ 0)
/// and sliding velocity `v`: −μ(|v|) N tanh(|v|/v_reg) v/|v|, N.
#[inline]
pub fn friction_force(
    law: &FrictionLaw,
    normal: f64,
    v: [f64; 3],
    regularisation_speed: f64,
) -> [f64; 3] {
    let speed = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
    if speed == 0.0 {
        return [0.0; 3];
    }
    let scale = -law.mu(speed) * normal * (speed / regularisation_speed).tanh() / speed;
    [scale * v[0], scale * v[1], scale * v[2]]
}
