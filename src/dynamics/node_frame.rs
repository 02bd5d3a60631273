//! Node frames (paper section 4.1): material points turning with the plate
//! (Lagrangian) and space-fixed points the plate slides under (ALE), with the
//! mode shapes evaluated once at their points.

use crate::config::NodePosition;
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
    /// Per mode: w_i, and the surface tilt (θ_x, θ_y) = (∂w_i/∂y, −∂w_i/∂x).
    pub shapes: Vec<NodeShape>,
    /// Per mode ∂w_i/∂φ (for the material velocity under an ALE point).
    pub w_phi: Vec<f64>,
    /// Per mode ∇(∂w_i/∂φ) in the parent frame's Cartesian axes, 1/m·m (the
    /// in-plane velocity of a face point under an ALE node, docs/scenes.md).
    pub w_phi_grad: Vec<[f64; 2]>,
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
    /// The frame at `p` on the surface at `z` (0: the mid-plane).
    pub(super) fn new(model: &PlateModel, kind: NodeKind, p: NodePosition, z: f64) -> NodeFrame {
        let radius = model.radius_at(p.radial);
        let angle = p.angular * TAU;
        let values: Vec<ShapeValue> = (0..model.n_modes())
            .map(|i| model.mode_shape(i, radius, angle))
            .collect();
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
            w_phi_grad: (0..model.n_modes())
                .map(|i| angular_rate_gradient(model, i, radius, angle))
                .collect(),
            z,
            xy: [radius * angle.cos(), radius * angle.sin()],
        }
    }

    /// Position of the mid-plane point under the frame in the node's parent frame (undeformed).
    pub fn position(&self) -> [f64; 3] {
        [self.xy[0], self.xy[1], 0.0]
    }

    /// Position of the frame's point for the deflection `d` there: the
    /// Kirchhoff face point at z is displaced by w along the axis and by
    /// −z∇w in-plane, ∇w = (∂w/∂x, ∂w/∂y) = (−θ_y, θ_x).
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

/// ∇(∂w_i/∂φ) at (r, φ): with w_i = R(r) Θ(φ), ∂_r ∂_φ w_i = R′ Θ′ and
/// (1/r) ∂²_φ w_i = −k² R Θ / r, turned into Cartesian axes.
fn angular_rate_gradient(model: &PlateModel, i: usize, r: f64, phi: f64) -> [f64; 2] {
    let m = &model.modes()[i];
    let rr = model.radial_shapes()[m.radial].eval(r);
    let (t, dt) = m.shape.eval(m.k, phi);
    let k2 = (m.k * m.k) as f64;
    let (radial, tangential) = (rr[1] * dt, -k2 * rr[0] * t / r);
    let (s, c) = phi.sin_cos();
    [c * radial - s * tangential, s * radial + c * tangential]
}
