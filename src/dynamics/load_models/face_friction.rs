//! Pad friction on the faces of the disc (`pads.contact_surface: faces`;
//! docs/scenes.md, "Friction on the faces").
//!
//! A Kirchhoff face point at z = ±h/2 moves in-plane by u = −z∇w, a vector
//! that turns with the plate. Under a space-fixed pad at (r, θ) (an ALE node)
//! the face material slides with
//!
//!   v = Ω r e_θ + D u/Dt + Ω ∂w/∂θ e_z,   D/Dt = ∂/∂t + Ω ∂/∂θ,
//!
//! relative to the pad (whose contact point follows the gap at ∂w/∂t): the
//! rotation, the vibration's in-plane velocity and the normal part of the
//! sliding along the tilted surface (the paper's follower direction). D/Dt
//! acts on u's Cartesian components, which change along the turn by the
//! rotation of the polar basis as well: D u/Dt = −z (∇Ẇ + Ω e_z × ∇w),
//! Ẇ = ∂w/∂t + Ω ∂w/∂θ, in polar components
//!
//!   v_r = −z (D(∂_r w)/Dt − Ω ∂_θ w / r),   v_θ ∋ −z (D(∂_θ w / r)/Dt + Ω ∂_r w),
//!
//! zero for a tilt held in space (w = α r cos θ). In the ALE description
//! D(∇w)/Dt = Σ_i (q̄̇_i ∇w_i + Ω q̄_i ∂(∇w_i)/∂θ) with the nodes'
//! `NodeFrame::gradient_phi`. Friction is regularised Coulomb along v:
//!
//!   F = −μ N tanh(|v| / v_reg) v/|v|,
//!
//! and acts at the face, so its in-plane part does the virtual work
//! −z F·∇w_i: the moment z e_z × F about the mid-plane point.
//!
//! With in-plane modes (`plate.in_plane_nodal_diameters`) the face point
//! moves by their u as well, the same at both faces; its material rate
//! D u/Dt = Σ_i (q̄̇_i u_i + Ω q̄_i ∂u_i/∂θ), in Cartesian components, adds to
//! v (`pad_in_plane.rs`), and F's in-plane part does the work u_i·F on in-plane
//! mode i (the node loads, `dynamics::loads`).
//!
//! Under Mindlin theory the face point moves in-plane by u = z ψ (ψ the
//! rotation of the normal, docs/mindlin.md): the node frames' gradient is
//! then −ψ and their `gradient_phi` the turn of −ψ (`NodeFrame::new`), so
//! the same sums give D u/Dt = z Dψ/Dt and the virtual work z F·ψ_i. The
//! normal part Ω ∂w/∂θ stays of w: the pad slides along the deformed
//! mid-surface, whose slope is ∇w in either theory ([`angular_slope`]).

use super::model::SurfaceKinematics;
use crate::dynamics::node_frame::NodeFrame;

/// The vibration's velocity terms under a contact point (ALE amplitudes).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct FaceKinematics {
    /// D(∇w)/Dt = ∇Ẇ + Ω e_z × ∇w in frame A's Cartesian axes, 1/s: the
    /// face point's in-plane velocity is −z times it.
    pub grad_material_rate: [f64; 2],
    /// Ω ∂w/∂θ: the normal part of the sliding velocity, m/s.
    pub normal_rate: f64,
    /// D u/Dt of the in-plane modes in frame A's Cartesian axes, m/s (the
    /// same at both faces; 0 without in-plane modes, `pad_in_plane.rs`).
    pub in_plane_rate: [f64; 2],
}

/// [`SurfaceKinematics`] and [`FaceKinematics`] at an ALE node in one pass
/// over the modes, each sum in the same order as [`surface_kinematics`]
/// (the same numbers), the amplitudes read once.
///
/// [`surface_kinematics`]: super::model::surface_kinematics
#[inline]
pub fn surface_and_face_kinematics(
    node: &NodeFrame,
    q: &[f64],
    q_dot: &[f64],
    speed: f64,
) -> (SurfaceKinematics, FaceKinematics) {
    let mut s = SurfaceKinematics::default();
    let mut k = FaceKinematics::default();
    let mut w_theta = 0.0;
    for (i, ((shape, &qi), &vi)) in node.shapes.iter().zip(q).zip(q_dot).enumerate() {
        s.w += shape.w * qi;
        s.w_dot += shape.w * vi;
        let g = node.gradient(i);
        let gp = node.gradient_phi[i];
        k.grad_material_rate[0] += vi * g[0] + speed * qi * gp[0];
        k.grad_material_rate[1] += vi * g[1] + speed * qi * gp[1];
        w_theta += qi * node.w_phi[i];
    }
    k.normal_rate = speed * w_theta;
    (s, k)
}

/// [`FaceKinematics`] at an ALE node for ALE amplitudes and rates at speed Ω.
#[inline]
pub fn face_kinematics(node: &NodeFrame, q: &[f64], q_dot: &[f64], speed: f64) -> FaceKinematics {
    surface_and_face_kinematics(node, q, q_dot, speed).1
}

/// ∂w/∂θ under an ALE node for ALE amplitudes `q`, m/rad: the deformed
/// surface's slope along the sliding, of w in either plate theory.
#[inline]
pub fn angular_slope(node: &NodeFrame, q: &[f64]) -> f64 {
    node.w_phi.iter().zip(q).map(|(d, qi)| d * qi).sum()
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
        -s * v - z * k.grad_material_rate[0] + k.in_plane_rate[0],
        c * v - z * k.grad_material_rate[1] + k.in_plane_rate[1],
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

/// max(g(s)/s, |g′(s)|) at the sliding velocity `v`, g(s) = μ(s) tanh(s/v_reg):
/// the friction's damping per unit normal force across and along the
/// sliding, s/m; μ(0)/v_reg at rest.
pub fn damping_per_normal(law: &FrictionLaw, v: [f64; 3], regularisation_speed: f64) -> f64 {
    let s = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
    let x = s / regularisation_speed;
    let t = x.tanh();
    let across = if x < 1e-8 {
        law.mu(s) / regularisation_speed
    } else {
        law.mu(s) * t / s
    };
    let along = law.slope(s) * t + law.mu(s) * (1.0 - t * t) / regularisation_speed;
    across.max(along.abs())
}

/// Σ_i a_ci a_diᵀ / m_i over the modes for rows a (2 per contact point),
/// row-major over 2C × 2C: the Gram matrix J M⁻¹ Jᵀ of the faces' sliding
/// velocity rows among the contact points (`pad_friction_damping.rs`).
pub fn contact_gram<'a>(
    rows: impl Fn(usize, usize) -> [f64; 2],
    contacts: usize,
    modal_mass: impl Iterator<Item = &'a f64> + Clone,
) -> Vec<f64> {
    let n = 2 * contacts;
    let mut gram = vec![0.0; n * n];
    for c in 0..contacts {
        for d in 0..contacts {
            for (i, m) in modal_mass.clone().enumerate() {
                let (a, b) = (rows(c, i), rows(d, i));
                for (x, ax) in a.iter().enumerate() {
                    for (y, by) in b.iter().enumerate() {
                        gram[(2 * c + x) * n + 2 * d + y] += ax * by / m;
                    }
                }
            }
        }
    }
    gram
}

/// An ALE frame at (r, θ) whose one "mode" is the rigid tilt w = α r cos θ
/// (a plate tilted about the y axis, held in space by q̄ = 1, q̄̇ = 0).
#[cfg(test)]
pub(crate) fn rigid_tilt_frame(radius: f64, theta: f64, alpha: f64) -> NodeFrame {
    use crate::dynamics::node_frame::{gradient_phi, NodeKind};
    use crate::model::ShapeValue;
    let (s, c) = theta.sin_cos();
    let value = ShapeValue {
        w: alpha * radius * c,
        w_r: alpha * c,
        w_phi: -alpha * radius * s,
    };
    let turn = gradient_phi(radius, theta, [alpha * radius, alpha], (c, -s), 1.0);
    NodeFrame::from_values(NodeKind::Ale, radius, theta, 0.0, &[value], vec![turn])
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_tilt_held_in_space_changes_neither_face_s_sliding_direction_at_any_contact() {
        let (alpha, speed, h) = (3e-3, 40.0, 0.018);
        for radius in [0.08, 0.12, 0.15] {
            for j in 0..12 {
                let theta = j as f64 * std::f64::consts::TAU / 12.0 + 0.1;
                let node = rigid_tilt_frame(radius, theta, alpha);
                let k = face_kinematics(&node, &[1.0], &[0.0], speed);
                assert!(
                    k.grad_material_rate[0].abs() < 1e-15 && k.grad_material_rate[1].abs() < 1e-15,
                    "θ = {theta}: {k:?}"
                );
                // The face material moves with the rigid turn only: Ω r e_θ in-plane
                // and the tilted surface's normal rate Ω ∂w/∂θ = −Ω α r sin θ.
                let (s, c) = theta.sin_cos();
                for z in [0.5 * h, -0.5 * h] {
                    let v = sliding_velocity(&k, z, radius, (s, c), speed, true);
                    let (v_r, v_t) = (c * v[0] + s * v[1], -s * v[0] + c * v[1]);
                    assert!(v_r.abs() < 1e-15, "θ = {theta}, z = {z}: v_r = {v_r}");
                    assert!((v_t - speed * radius).abs() < 1e-13, "v_θ = {v_t}");
                    assert!((v[2] + speed * alpha * radius * s).abs() < 1e-15);
                }
            }
        }
    }

    /// The largest |eigenvalue| of ∂F/∂v per unit normal force, by central
    /// differences of the friction force itself (∂F/∂v is symmetric: F is
    /// the gradient of a potential in v).
    fn jacobian_norm(law: &FrictionLaw, v: [f64; 3]) -> f64 {
        let (d, vr) = (1e-9, 1e-3);
        let mut j = [[0.0; 3]; 3];
        for (a, col) in j.iter_mut().enumerate() {
            let (mut p, mut m) = (v, v);
            p[a] += d;
            m[a] -= d;
            let (fp, fm) = (
                friction_force(law, 1.0, p, vr),
                friction_force(law, 1.0, m, vr),
            );
            for b in 0..3 {
                col[b] = (fp[b] - fm[b]) / (2.0 * d);
            }
        }
        let j = nalgebra::Matrix3::from_fn(|r, c| 0.5 * (j[c][r] + j[r][c]));
        j.symmetric_eigenvalues().amax()
    }

    #[test]
    fn the_damping_per_normal_force_is_the_friction_law_s_largest_slope() {
        let laws = [
            FrictionLaw {
                kinetic: 0.5,
                excess: 0.0,
                stribeck_speed: 1.0,
            },
            FrictionLaw {
                kinetic: 0.4,
                excess: 0.2,
                stribeck_speed: 0.01,
            },
        ];
        for law in &laws {
            for s in [2e-4, 1e-3, 5e-3, 0.05, 1.0, 30.0] {
                let v = [0.6 * s, -0.8 * s, 0.0];
                let got = damping_per_normal(law, v, 1e-3);
                let want = jacobian_norm(law, v);
                assert!(
                    (got / want - 1.0).abs() < 1e-3,
                    "s = {s}: {got} against {want}"
                );
            }
            assert_eq!(damping_per_normal(law, [0.0; 3], 1e-3), law.mu(0.0) / 1e-3);
        }
    }
}
