//! Mode-shape evaluation at any (r, φ) and the displacement field of eq. (13).

use super::PlateModel;

/// Transverse deflection w and its partial derivatives at a point.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct ShapeValue {
    /// w, m.
    pub w: f64,
    /// ∂w/∂r.
    pub w_r: f64,
    /// ∂w/∂φ.
    pub w_phi: f64,
}

impl ShapeValue {
    /// Rotation vector (small angles) of the surface normal in the local
    /// Cartesian axes of the plate frame at angle φ: θ_x = ∂w/∂y, θ_y = −∂w/∂x.
    pub fn tilt(&self, r: f64, phi: f64) -> [f64; 2] {
        let (s, c) = phi.sin_cos();
        let w_x = c * self.w_r - s / r * self.w_phi;
        let w_y = s * self.w_r + c / r * self.w_phi;
        [w_y, -w_x]
    }
}

impl PlateModel {
    /// w_i, ∂w_i/∂r, ∂w_i/∂φ of mode `i` at (r, φ). In ALE coordinates the same
    /// functions of (r, θ) are the ALE modes c̄ of eq. (18).
    pub fn mode_shape(&self, i: usize, r: f64, phi: f64) -> ShapeValue {
        let m = &self.modes()[i];
        let rr = self.radial_shapes()[m.radial].eval(r);
        let (t, dt) = m.shape.eval(m.k, phi);
        ShapeValue {
            w: rr[0] * t,
            w_r: rr[1] * t,
            w_phi: rr[0] * dt,
        }
    }

    /// The deflection Σ w_i q_i at (r, φ).
    pub fn deflection(&self, q: &[f64], r: f64, phi: f64) -> ShapeValue {
        let mut out = ShapeValue::default();
        for (i, &qi) in q.iter().enumerate() {
            let s = self.mode_shape(i, r, phi);
            out.w += s.w * qi;
            out.w_r += s.w_r * qi;
            out.w_phi += s.w_phi * qi;
        }
        out
    }

    /// The displacement u = Φ q of eq. (13) at (r, φ, z), in the plate frame's
    /// Cartesian axes: u_x = −z (cos φ w_r − sin φ w_φ / r), u_y = −z (sin φ w_r + cos φ w_φ / r), u_z = w.
    pub fn displacement(&self, q: &[f64], r: f64, phi: f64, z: f64) -> [f64; 3] {
        let d = self.deflection(q, r, phi);
        let (s, c) = phi.sin_cos();
        [
            -z * (c * d.w_r - s / r * d.w_phi),
            -z * (s * d.w_r + c / r * d.w_phi),
            d.w,
        ]
    }
}
