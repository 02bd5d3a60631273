//! Node frames (paper section 4.1): material points turning with the plate
//! (Lagrangian) and space-fixed points the plate slides under (ALE), with the
//! mode shapes evaluated once at their points.

use crate::config::NodePosition;
use crate::model::mindlin::MindlinFieldValue;
use crate::model::{PlateModel, ShapeValue};
use std::f64::consts::TAU;

/// Kind of node frame (paper section 4.1).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum NodeKind {
    /// Material point turning with the plate (`nodes_Lagrange`).
    Lagrange,
    /// Space-fixed point the plate slides under (`nodes_ALE`).
    Ale,
}

impl NodeKind {
    /// The kind's name, as in the configuration.
    pub fn name(self) -> &'static str {
        match self {
            NodeKind::Lagrange => "lagrange",
            NodeKind::Ale => "ale",
        }
    }
}

/// A node frame with the mode shapes evaluated at its point.
#[derive(Debug, Clone, PartialEq)]
pub struct NodeFrame {
    pub kind: NodeKind,
    pub radius: f64,
    /// φ for Lagrangian nodes (plate frame), θ for ALE nodes (ALE frame), rad.
    pub angle: f64,
    /// Per mode: w_i, and the tilt (θ_x, θ_y) = (∂w_i/∂y, −∂w_i/∂x) of the
    /// surface (Kirchhoff), or (−ψ_y, ψ_x) of the normal (Mindlin, [`mindlin_tilt`]).
    pub shapes: Vec<NodeShape>,
    /// Per mode ∂w_i/∂φ (for the material velocity under an ALE point).
    pub w_phi: Vec<f64>,
    /// Per mode ∂(∇w_i)/∂φ: the change of ∇w_i's components in the parent
    /// frame's Cartesian axes along the turn, ∇(∂w_i/∂φ) + e_z × ∇w_i (the
    /// in-plane velocity of a face point under an ALE node, docs/scenes.md).
    pub gradient_phi: Vec<[f64; 2]>,
    /// z of the frame through the thickness: +h/2 (top face), −h/2 (bottom
    /// face) or 0 (mid-plane), m (`nodes.*_surface`).
    pub z: f64,
    /// Undeformed position (r cos, r sin) in the parent frame, m.
    xy: [f64; 2],
}

#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct NodeShape {
    pub w: f64,
    pub tilt: [f64; 2],
}

impl NodeFrame {
    /// The frame at `p` on the surface at `z` (0: the mid-plane). Under
    /// Mindlin theory its tilt and [`NodeFrame::gradient_phi`] are of the
    /// rotation ψ of the normal ([`mindlin_tilt`]), not of the slope ∇w; with
    /// a load patch of half-width `patch` (m; Mindlin with residual
    /// flexibility) its w and ∂w/∂φ are the patch means ([`patch_means`]).
    pub(super) fn new(
        model: &PlateModel,
        kind: NodeKind,
        p: NodePosition,
        z: f64,
        patch: Option<f64>,
    ) -> NodeFrame {
        let radius = model.radius_at(p.radial);
        let angle = p.angular * TAU;
        let values: Vec<ShapeValue> = (0..model.n_modes())
            .map(|i| model.mode_shape(i, radius, angle))
            .collect();
        let gradient_phi = (0..model.n_modes())
            .map(|i| {
                let m = &model.modes()[i];
                let angular = m.shape.eval(m.k, angle);
                if let Some(mode) = model.mindlin_mode(m.radial) {
                    let v = mode.eval(radius);
                    return mindlin_gradient_phi(angle, [v.psi_r, v.psi_theta], angular, m.k);
                }
                let rr = model.radial_shapes()[m.radial].eval(radius);
                let k2 = (m.k * m.k) as f64;
                gradient_phi(radius, angle, [rr[0], rr[1]], angular, k2)
            })
            .collect();
        let mut frame = NodeFrame::from_values(kind, radius, angle, z, &values, gradient_phi);
        for (i, m) in model.modes().iter().enumerate() {
            if let Some(mode) = model.mindlin_mode(m.radial) {
                frame.shapes[i].tilt = mindlin_tilt(&mode.field(m.shape, radius, angle), angle);
            }
        }
        if let Some(c) = patch {
            frame.patch_means(model, c);
        }
        frame
    }

    /// Replace each Mindlin mode's w and ∂w/∂φ at the node by its mean over
    /// the node's load patch of half-width `c` (docs/residual_flexibility.md,
    /// "Under Mindlin theory"): W̄ Θ(φ) sinc kβ and W̄ Θ′(φ) sinc kβ, W̄ the
    /// radial patch mean of W. Tilts stay point values.
    fn patch_means(&mut self, model: &PlateModel, c: f64) {
        let patch = model.load_patch(self.radius, c);
        for (i, m) in model.modes().iter().enumerate() {
            if model.mindlin_mode(m.radial).is_none() {
                continue;
            }
            let mean = model.patch_mean_w(m.radial, &patch) * patch.angular_factor(m.k);
            let (t, dt) = m.shape.eval(m.k, self.angle);
            self.shapes[i].w = mean * t;
            self.w_phi[i] = mean * dt;
        }
    }

    /// The frame at (r, φ) on the surface at `z` from the shapes' values
    /// there and their [`gradient_phi`].
    pub(crate) fn from_values(
        kind: NodeKind,
        radius: f64,
        angle: f64,
        z: f64,
        values: &[ShapeValue],
        gradient_phi: Vec<[f64; 2]>,
    ) -> NodeFrame {
        NodeFrame {
            kind,
            radius,
            angle,
            shapes: values
                .iter()
                .map(|s| NodeShape {
                    w: s.w,
                    tilt: s.tilt(radius, angle),
                })
                .collect(),
            w_phi: values.iter().map(|s| s.w_phi).collect(),
            gradient_phi,
            z,
            xy: [radius * angle.cos(), radius * angle.sin()],
        }
    }

    /// Position of the mid-plane point under the frame in the node's parent frame (undeformed).
    pub fn position(&self) -> [f64; 3] {
        [self.xy[0], self.xy[1], 0.0]
    }

    /// Position of the frame's point for the deflection `d` there: the
    /// face point at z is displaced by w along the axis and by z (θ_y, −θ_x)
    /// in-plane: −z∇w for Kirchhoff modes (∇w = (−θ_y, θ_x)), z ψ for Mindlin ones.
    pub fn surface_position(&self, d: &NodeShape) -> [f64; 3] {
        [
            self.xy[0] + self.z * d.tilt[1],
            self.xy[1] - self.z * d.tilt[0],
            self.z + d.w,
        ]
    }

    /// The moment about the mid-plane point of an in-plane force F at the
    /// frame's z: z e_z × F = (−z F_y, z F_x, 0). Its virtual work through the
    /// tilt, θ_x M_x + θ_y M_y = −z F·∇w, is the face kinematics' share.
    #[inline]
    pub fn face_moment(&self, force: &[f64; 3]) -> [f64; 2] {
        [-self.z * force[1], self.z * force[0]]
    }

    /// ∇w_i in the parent frame's Cartesian axes (from the tilt: (−θ_y, θ_x)).
    #[inline]
    pub fn gradient(&self, i: usize) -> [f64; 2] {
        let t = self.shapes[i].tilt;
        [-t[1], t[0]]
    }

    /// Deflection w and tilt at the node for amplitudes `q` in the node's own description.
    pub fn deflection(&self, q: &[f64]) -> NodeShape {
        let mut out = NodeShape::default();
        for (s, &qi) in self.shapes.iter().zip(q) {
            out.w += s.w * qi;
            out.tilt[0] += s.tilt[0] * qi;
            out.tilt[1] += s.tilt[1] * qi;
        }
        out
    }

    /// The w of [`NodeFrame::deflection`] alone (the same sum, bit for bit).
    pub fn deflection_w(&self, q: &[f64]) -> f64 {
        let mut w = 0.0;
        for (s, &qi) in self.shapes.iter().zip(q) {
            w += s.w * qi;
        }
        w
    }
}

/// ∂(∇w)/∂φ at (r, φ) for w = R(r) Θ(φ) (`radial` = (R, R′), `angular` =
/// (Θ, Θ′), Θ″ = −k² Θ) in Cartesian axes: the gradient is a vector that turns
/// with the plate, so besides ∇(∂w/∂φ) its components change by the basis'
/// rotation e_z × ∇w (docs/scenes.md, "Friction on the faces"). In polar
/// components
///
///   e_r: ∂_r ∂_φ w − (1/r) ∂_φ w = R′Θ′ − RΘ′/r,
///   e_φ: (1/r) ∂²_φ w + ∂_r w     = −k² RΘ/r + R′Θ,
///
/// both zero for a rigid tilt w = α r cos φ, whose gradient is uniform.
pub(crate) fn gradient_phi(
    r: f64,
    phi: f64,
    radial: [f64; 2],
    angular: (f64, f64),
    k2: f64,
) -> [f64; 2] {
    let ([rr, rr_slope], (t, dt)) = (radial, angular);
    let e_r = rr_slope * dt - rr * dt / r;
    let e_phi = -k2 * rr * t / r + rr_slope * t;
    let (s, c) = phi.sin_cos();
    [c * e_r - s * e_phi, s * e_r + c * e_phi]
}

/// The rotation vector (θ_x, θ_y) of a Mindlin normal turned by ψ at angle
/// φ: the face point at z moves in-plane by z ψ = z (θ_y, −θ_x), so
/// θ = (−ψ_y, ψ_x) with ψ_x = cos φ ψ_r − sin φ ψ_θ, ψ_y = sin φ ψ_r + cos φ ψ_θ.
/// A moment M at the node works on the mode through θ·M, the virtual work of
/// the couple on the rotation of the normal (Kirchhoff's limit ψ = −∇w gives
/// [`ShapeValue::tilt`]).
pub(crate) fn mindlin_tilt(f: &MindlinFieldValue, phi: f64) -> [f64; 2] {
    let (s, c) = phi.sin_cos();
    let psi_x = c * f.psi_r - s * f.psi_theta;
    let psi_y = s * f.psi_r + c * f.psi_theta;
    [-psi_y, psi_x]
}

/// [`gradient_phi`] of a Mindlin mode: the turn of g = −ψ (the in-plane
/// face displacement per −z, which is ∇w in Kirchhoff's limit) along φ, for
/// ψ_r = Ψ_r Θ, ψ_θ = −Ψ_θ Θ′/k (`radial` = (Ψ_r, Ψ_θ), `angular` = (Θ, Θ′),
/// Θ″ = −k² Θ). In polar components, as for ∇w:
///
///   e_r: ∂_φ g_r − g_φ = −Ψ_r Θ′ − Ψ_θ Θ′/k,
///   e_φ: ∂_φ g_φ + g_r = −k Ψ_θ Θ − Ψ_r Θ,
///
/// equal to [`gradient_phi`] for Ψ_r = −R′, Ψ_θ = k R/r. For k = 0 only the
/// ψ_r terms remain (no ψ_θ family).
pub(crate) fn mindlin_gradient_phi(
    phi: f64,
    radial: [f64; 2],
    angular: (f64, f64),
    k: u32,
) -> [f64; 2] {
    let ([psi_r, psi_t], (t, dt)) = (radial, angular);
    let (e_r, e_phi) = if k == 0 {
        (-psi_r * dt, -psi_r * t)
    } else {
        let kf = k as f64;
        (-psi_r * dt - psi_t * dt / kf, -kf * psi_t * t - psi_r * t)
    };
    let (s, c) = phi.sin_cos();
    [c * e_r - s * e_phi, s * e_r + c * e_phi]
}

/// The distinct radii of `nodes` in order of first appearance, and each
/// node's index into them: the residual compliances are computed once per
/// radius.
pub(crate) fn distinct_radii(nodes: &[&NodeFrame]) -> (Vec<f64>, Vec<usize>) {
    let mut radii: Vec<f64> = Vec::new();
    let index = nodes
        .iter()
        .map(|nd| match radii.iter().position(|&r| r == nd.radius) {
            Some(i) => i,
            None => {
                radii.push(nd.radius);
                radii.len() - 1
            }
        })
        .collect();
    (radii, index)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// ∇w in Cartesian axes for w = R(r) cos kφ with R = r², from the tilt.
    fn cartesian_gradient(r: f64, phi: f64, k: f64) -> [f64; 2] {
        let (w_r, w_phi) = (2.0 * r * (k * phi).cos(), -k * r * r * (k * phi).sin());
        let v = ShapeValue {
            w: r * r * (k * phi).cos(),
            w_r,
            w_phi,
        };
        let t = v.tilt(r, phi);
        [-t[1], t[0]]
    }

    #[test]
    fn gradient_phi_is_the_turn_of_the_cartesian_gradient_by_central_differences() {
        let (r, k, eps) = (0.13, 3.0, 1e-5);
        for phi in [0.0, 0.4, 1.9, 4.2] {
            let plus = cartesian_gradient(r, phi + eps, k);
            let minus = cartesian_gradient(r, phi - eps, k);
            let fd = [
                (plus[0] - minus[0]) / (2.0 * eps),
                (plus[1] - minus[1]) / (2.0 * eps),
            ];
            let (t, dt) = ((k * phi).cos(), -k * (k * phi).sin());
            let exact = gradient_phi(r, phi, [r * r, 2.0 * r], (t, dt), k * k);
            for a in 0..2 {
                assert!(
                    (fd[a] - exact[a]).abs() < 1e-8,
                    "φ = {phi}: {fd:?} vs {exact:?}"
                );
            }
        }
    }

    #[test]
    fn a_rigid_tilt_s_gradient_does_not_turn() {
        let alpha = 2e-3;
        for phi in [0.0f64, 0.7, 2.5, 5.1] {
            let (t, dt) = (phi.cos(), -phi.sin());
            let g = gradient_phi(0.11, phi, [alpha * 0.11, alpha], (t, dt), 1.0);
            assert!(g[0].abs() < 1e-18 && g[1].abs() < 1e-18, "{g:?}");
        }
    }

    /// Kirchhoff's limit ψ = −∇w (Ψ_r = −R′, Ψ_θ = k R/r) of the Mindlin
    /// tilt and turn is the Kirchhoff tilt and turn of the same w.
    #[test]
    fn the_mindlin_tilt_and_turn_of_psi_equal_to_minus_grad_w_are_kirchhoff_s() {
        use crate::model::AngularShape;
        let (r, k) = (0.13, 3u32);
        let (rr, rr_slope) = (r * r, 2.0 * r);
        let (psi_r, psi_t) = (-rr_slope, k as f64 * rr / r);
        for shape in [AngularShape::Cos, AngularShape::Sin] {
            for phi in [0.0, 0.4, 1.9, 4.2] {
                let (t, dt) = shape.eval(k, phi);
                let kirchhoff = ShapeValue {
                    w: rr * t,
                    w_r: rr_slope * t,
                    w_phi: rr * dt,
                };
                let field = MindlinFieldValue {
                    w: rr * t,
                    psi_r: psi_r * t,
                    psi_theta: -psi_t * dt / k as f64,
                };
                let (a, b) = (mindlin_tilt(&field, phi), kirchhoff.tilt(r, phi));
                let turn_m = mindlin_gradient_phi(phi, [psi_r, psi_t], (t, dt), k);
                let turn_k = gradient_phi(r, phi, [rr, rr_slope], (t, dt), (k * k) as f64);
                for i in 0..2 {
                    assert!(
                        (a[i] - b[i]).abs() < 1e-15,
                        "{shape:?} φ = {phi}: {a:?} vs {b:?}"
                    );
                    assert!(
                        (turn_m[i] - turn_k[i]).abs() < 1e-15,
                        "{turn_m:?} vs {turn_k:?}"
                    );
                }
            }
        }
    }
}
