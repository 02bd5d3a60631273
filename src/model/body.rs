//! Body data of the generalized Newton–Euler equations (11) — the SID
//! invariants of the plate (Wallrapp [2]) for the displacement field (13).
//!
//! Kirchhoff assumptions throughout: the deformation's rotary inertia (terms
//! of order h²/r² from the in-plane part of (13)) is neglected, exactly as in
//! M_e; the undeformed inertia tensor J₀ keeps the plate's thickness.
//! Under `plate.theory: mindlin` M_e (the modes' modal mass) includes the
//! rotary inertia and C_t, d_CM are unchanged (z ψ integrates to zero over
//! the thickness), but C_r and J₁ lack ρh³/12 ∫ ψ dA; the dynamics refuse
//! Mindlin modes ([`super::PlateModel::require_kirchhoff`]).
//!
//! With s_i = ρh ∫ w_i (x, y, 1) dA (first moments of the mode shapes):
//! - C_t (n×3), row i = ∫ Φ_iᵀ dm = (0, 0, s_iz): non-zero only for k = 0 modes;
//! - C_r (n×3), row i = ∫ (c × Φ_i)ᵀ dm = (s_iy, −s_ix, 0): non-zero only for k = 1;
//! - J(q) = J₀ + Σ J₁ᵢ qᵢ with J₁ᵢ = −(e_z s_{i,xy}ᵀ + s_{i,xy} e_zᵀ) (xz, yz entries, k = 1);
//! - m d_CM(q) = C_tᵀ q;
//! - M_e = diag(m_i), K_e = diag(m_i ω_i²), D_e = diag(2 ζ_i ω_i m_i).

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
    /// Diagonal of M_e, kg.
    pub modal_mass: Vec<f64>,
    /// Diagonal of K_e, N/m.
    pub modal_stiffness: Vec<f64>,
    /// Diagonal of D_e, N·s/m.
    pub modal_damping: Vec<f64>,
}

impl BodyData {
    /// The body data of `plate` with its modes and their radial shapes.
    pub fn new(plate: &PlateConfig, modes: &[Mode], shapes: &[RadialShape]) -> BodyData {
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
        BodyData {
            mass,
            inertia,
            first_moments,
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

    /// Row i of C_r: ∫ (c × Φ_i)ᵀ dm.
    pub fn rotational_coupling(&self, i: usize) -> [f64; 3] {
        let s = self.first_moments[i];
        [s[1], -s[0], 0.0]
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
        for (qi, s) in q.iter().zip(&self.first_moments) {
            sx += qi * s[0];
            sy += qi * s[1];
        }
        j[0][2] -= sx;
        j[2][0] -= sx;
        j[1][2] -= sy;
        j[2][1] -= sy;
        j
    }
}
