//! Body data of the generalized Newton–Euler equations (11) — the SID
//! invariants of the plate (Wallrapp [2]) for the displacement field (13).
//!
//! Kirchhoff theory (`plate.theory: kirchhoff`): the deformation's rotary
//! inertia (terms of order h²/r² from the in-plane part of (13)) is
//! neglected, exactly as in M_e; the undeformed inertia tensor J₀ keeps the
//! plate's thickness. Mindlin theory: the mode's face displacement is z ψ_i,
//! so M_e (the modal mass) holds the rotary inertia, and so do C_r and J₁
//! through the rotary moments p_i = ρh³/12 ∫ ψ_i dA (∫ z² dm per area is
//! ρh³/12; ∫ z dm = 0 leaves C_t and d_CM unchanged). p_i is zero under
//! Kirchhoff theory.
//!
//! With s_i = ρh ∫ w_i (x, y, 1) dA (first moments of the mode shapes) and
//! Φ_i = (z ψ_i, w_i) at the material point c = (x, y, z):
//! - C_t (n×3), row i = ∫ Φ_iᵀ dm = (0, 0, s_iz): non-zero only for k = 0 modes;
//! - C_r (n×3), row i = ∫ (c × Φ_i)ᵀ dm = (s_iy − p_iy, −(s_ix − p_ix), 0): non-zero only for k = 1;
//! - J(q) = J₀ + Σ J₁ᵢ qᵢ with J₁ᵢ = −(e_z (s + p)_{i,xy}ᵀ + (s + p)_{i,xy} e_zᵀ) (xz, yz entries, k = 1);
//! - m d_CM(q) = C_tᵀ q;
//! - M_e = diag(m_i), K_e = diag(m_i ω_i²), D_e = diag(2 ζ_i ω_i m_i).

use super::mindlin::MindlinMode;
use super::modes::{radial_moment, AngularShape, Mode, RadialShape};
use crate::config::PlateConfig;
use std::f64::consts::PI;

/// The flexible body's data in the floating frame: rigid mass and inertia,
/// the modes' first moments and their modal mass, stiffness and damping.
#[derive(Debug, Clone, PartialEq)]
pub struct BodyData {
    /// m, kg.
    pub mass: f64,
    /// J₀ about the plate centre, kg·m², reference-frame axes.
    pub inertia: [[f64; 3]; 3],
    /// s_i = ρh ∫ w_i (x, y, 1) dA per mode.
    pub first_moments: Vec<[f64; 3]>,
    /// p_i = ρh³/12 ∫ ψ_i dA (x, y) per mode, kg·m: the rotary moments of
    /// Mindlin modes (non-zero for k = 1), zero under Kirchhoff theory.
    pub rotary_moments: Vec<[f64; 2]>,
    /// Diagonal of M_e, kg.
    pub modal_mass: Vec<f64>,
    /// Diagonal of K_e, N/m.
    pub modal_stiffness: Vec<f64>,
    /// Diagonal of D_e, N·s/m.
    pub modal_damping: Vec<f64>,
}

impl BodyData {
    /// The body data of `plate` with its modes, their radial shapes and (under
    /// Mindlin theory, else empty) the Mindlin mode of each radial shape.
    pub fn new(
        plate: &PlateConfig,
        modes: &[Mode],
        shapes: &[RadialShape],
        mindlin: &[MindlinMode],
    ) -> BodyData {
        let (ri, ra, h) = (plate.inner_radius, plate.outer_radius, plate.thickness);
        let rho_h = plate.density * h;
        let mass = rho_h * PI * (ra * ra - ri * ri);
        let jzz = 0.5 * mass * (ra * ra + ri * ri);
        let jxx = mass * ((ra * ra + ri * ri) / 4.0 + h * h / 12.0);
        let inertia = [[jxx, 0.0, 0.0], [0.0, jxx, 0.0], [0.0, 0.0, jzz]];
        let first_moments = modes
            .iter()
            .map(|m| {
                let shape = &shapes[m.radial];
                match (m.k, m.shape) {
                    // ∫ R r dr · 2π
                    (0, _) => [0.0, 0.0, rho_h * 2.0 * PI * radial_moment(shape, 1, 1)],
                    // ∫ R cos φ · r cos φ · r dr dφ = π ∫ R r² dr
                    (1, AngularShape::Cos) => [rho_h * PI * radial_moment(shape, 1, 2), 0.0, 0.0],
                    (1, AngularShape::Sin) => [0.0, rho_h * PI * radial_moment(shape, 1, 2), 0.0],
                    _ => [0.0; 3],
                }
            })
            .collect();
        let rotary_moments = modes
            .iter()
            .map(|m| match mindlin.get(m.radial) {
                Some(mode) => rotary_moment(plate, mode, m.shape),
                None => [0.0; 2],
            })
            .collect();
        BodyData {
            mass,
            inertia,
            first_moments,
            rotary_moments,
            modal_mass: modes.iter().map(|m| m.modal_mass).collect(),
            modal_stiffness: modes
                .iter()
                .map(|m| m.modal_mass * m.omega * m.omega)
                .collect(),
            modal_damping: modes
                .iter()
                .map(|m| 2.0 * m.damping * m.omega * m.modal_mass)
                .collect(),
        }
    }

    /// Row i of C_t: ∫ Φ_iᵀ dm.
    pub fn translational_coupling(&self, i: usize) -> [f64; 3] {
        [0.0, 0.0, self.first_moments[i][2]]
    }

    /// Row i of C_r: ∫ (c × Φ_i)ᵀ dm = (s_y − p_y, −(s_x − p_x), 0).
    pub fn rotational_coupling(&self, i: usize) -> [f64; 3] {
        let (s, p) = (self.first_moments[i], self.rotary_moments[i]);
        [s[1] - p[1], -(s[0] - p[0]), 0.0]
    }

    /// Centre of mass d_CM(q) = C_tᵀ q / m (first order).
    pub fn center_of_mass(&self, q: &[f64]) -> [f64; 3] {
        let z: f64 = q
            .iter()
            .zip(&self.first_moments)
            .map(|(qi, s)| qi * s[2])
            .sum();
        [0.0, 0.0, z / self.mass]
    }

    /// J(q) = J₀ + Σ J₁ᵢ qᵢ (first order).
    pub fn inertia_at(&self, q: &[f64]) -> [[f64; 3]; 3] {
        let mut j = self.inertia;
        let (mut sx, mut sy) = (0.0, 0.0);
        for ((qi, s), p) in q.iter().zip(&self.first_moments).zip(&self.rotary_moments) {
            sx += qi * (s[0] + p[0]);
            sy += qi * (s[1] + p[1]);
        }
        j[0][2] -= sx;
        j[2][0] -= sx;
        j[1][2] -= sy;
        j[2][1] -= sy;
        j
    }
}

/// p = ρh³/12 ∫ ψ dA of a Mindlin mode with angular factor `shape`: only
/// k = 1 has a mean rotation. cos: ψ_x = Ψ_r cos² φ − Ψ_θ sin² φ, so
/// ∫ ψ_x dφ = π (Ψ_r − Ψ_θ), ∫ ψ_y dφ = 0; sin: the same along y.
fn rotary_moment(plate: &PlateConfig, mode: &MindlinMode, shape: AngularShape) -> [f64; 2] {
    if mode.k != 1 {
        return [0.0; 2];
    }
    let basis = mode.w.basis();
    let mut points = Vec::new();
    for s in 0..basis.spans() {
        let (lo, hi) = basis.span_bounds(s);
        super::quadrature::radial_points(lo, hi, &mut points);
    }
    let integral: f64 = points
        .iter()
        .map(|&(r, w)| {
            let v = mode.eval(r);
            w * (v.psi_r - v.psi_theta) * r
        })
        .sum();
    let p = plate.density * plate.thickness.powi(3) / 12.0 * PI * integral;
    match shape {
        AngularShape::Sin => [0.0, p],
        _ => [p, 0.0],
    }
}
