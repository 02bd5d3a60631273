//! The membrane prestress of the spinning annulus (DESIGN.md "Spinning
//! prestress"; docs/rotor_dynamics.md): plane stress, per unit Ω².
//!
//! The radial displacement u(r) = A r + B/r + c r³ with
//! c = −(1 − ν²) ρ / (8E) (per unit Ω²) solves the in-plane equilibrium
//! dσ_r/dr + (σ_r − σ_θ)/r + ρΩ² r = 0; with Ē = E/(1 − ν²)
//!
//! σ_r = Ē [(1 + ν) A − (1 − ν) B/r² + (3 + ν) c r²],
//! σ_θ = Ē [(1 + ν) A + (1 − ν) B/r² + (1 + 3ν) c r²].
//!
//! Edges: at r_i either u = 0 (the disc sits on a hub) or σ_r = 0 (a free
//! hole), see [`crate::config::InPlaneInner`]; at r_a σ_r = 0 (a free rim,
//! the default) or u = 0, see [`crate::config::InPlaneOuter`].

use crate::config::{CentrifugalConfig, PlateConfig};

/// The Lamé stresses of the spinning annulus per unit Ω² (Pa per (rad/s)²).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LamePrestress {
    a: f64,
    b: f64,
    c: f64,
    e_bar: f64,
    nu: f64,
    /// u(r_i) = 0 (else σ_r(r_i) = 0).
    pub inner_fixed: bool,
    /// u(r_a) = 0 (else σ_r(r_a) = 0).
    pub outer_fixed: bool,
}

impl LamePrestress {
    /// The prestress of `plate` with the in-plane edge conditions of `centrifugal`.
    pub fn new(plate: &PlateConfig, centrifugal: &CentrifugalConfig) -> LamePrestress {
        let inner_fixed = centrifugal.in_plane_inner.is_fixed(plate.inner_boundary);
        let outer_fixed = centrifugal.in_plane_outer.is_fixed();
        let (ri, ra, nu, e) = (
            plate.inner_radius,
            plate.outer_radius,
            plate.poisson_ratio,
            plate.youngs_modulus,
        );
        let c = -(1.0 - nu * nu) * plate.density / (8.0 * e);
        // σ_r/Ē at r as a row of (A, B) plus the c term; u at r likewise.
        let stress_row = |r: f64| [(1.0 + nu), -(1.0 - nu) / (r * r), (3.0 + nu) * c * r * r];
        let displacement_row = |r: f64| [r, 1.0 / r, c * r * r * r];
        let row = |fixed: bool, r: f64| {
            if fixed {
                displacement_row(r)
            } else {
                stress_row(r)
            }
        };
        let (outer, inner) = (row(outer_fixed, ra), row(inner_fixed, ri));
        // Solve [outer; inner] (A, B) = −(c terms) by Cramer's rule.
        let det = outer[0] * inner[1] - outer[1] * inner[0];
        let a = (-outer[2] * inner[1] + outer[1] * inner[2]) / det;
        let b = (-outer[0] * inner[2] + outer[2] * inner[0]) / det;
        LamePrestress {
            a,
            b,
            c,
            e_bar: e / (1.0 - nu * nu),
            nu,
            inner_fixed,
            outer_fixed,
        }
    }

    /// (σ_r, σ_θ) at radius r, per unit Ω².
    pub fn stresses(&self, r: f64) -> (f64, f64) {
        let (a, b, c, nu) = (self.a, self.b, self.c, self.nu);
        let r2 = r * r;
        let sr = self.e_bar * ((1.0 + nu) * a - (1.0 - nu) * b / r2 + (3.0 + nu) * c * r2);
        let st = self.e_bar * ((1.0 + nu) * a + (1.0 - nu) * b / r2 + (1.0 + 3.0 * nu) * c * r2);
        (sr, st)
    }

    /// Radial displacement u(r) per unit Ω², m/(rad/s)².
    pub fn displacement(&self, r: f64) -> f64 {
        self.a * r + self.b / r + self.c * r * r * r
    }
}
