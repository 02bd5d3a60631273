//! The textbook Lamé prestress of a spinning annulus (Timoshenko & Goodier
//! §32), per unit Ω², written independently of `LamePrestress`.
#![allow(dead_code)]

use annular_plate::config::{Boundary, PlateConfig};

/// Textbook Lamé stresses per unit Ω²: (C₁, C₂) from σ_r(r_a) = 0 and, at r_i,
/// σ_r = 0 (free) or u = r(σ_θ − νσ_r)/E = 0 (fixed).
pub struct Lame {
    c1: f64,
    c2: f64,
    rho: f64,
    nu: f64,
}

impl Lame {
    pub fn new(p: &PlateConfig, fixed: bool) -> Lame {
        let (ri, ra, nu, rho) = (p.inner_radius, p.outer_radius, p.poisson_ratio, p.density);
        let (a, b) = ((3.0 + nu) / 8.0 * rho, (1.0 + 3.0 * nu) / 8.0 * rho);
        // Rows: coefficients of (C₁, C₂) and the right-hand side.
        let outer = [1.0, 1.0 / (ra * ra), a * ra * ra];
        let inner = if fixed {
            // σ_θ − νσ_r = (1 − ν)C₁ − (1 + ν)C₂/r² − (b − νa) r² = 0
            [1.0 - nu, -(1.0 + nu) / (ri * ri), (b - nu * a) * ri * ri]
        } else {
            [1.0, 1.0 / (ri * ri), a * ri * ri]
        };
        let det = outer[0] * inner[1] - outer[1] * inner[0];
        let c1 = (outer[2] * inner[1] - outer[1] * inner[2]) / det;
        let c2 = (outer[0] * inner[2] - outer[2] * inner[0]) / det;
        Lame { c1, c2, rho, nu }
    }
    /// σ_r, σ_θ, dσ_r/dr per unit Ω².
    pub fn at(&self, r: f64) -> (f64, f64, f64) {
        let (a, b) = (
            (3.0 + self.nu) / 8.0 * self.rho,
            (1.0 + 3.0 * self.nu) / 8.0 * self.rho,
        );
        let sr = self.c1 + self.c2 / (r * r) - a * r * r;
        let st = self.c1 - self.c2 / (r * r) - b * r * r;
        (sr, st, -2.0 * self.c2 / (r * r * r) - 2.0 * a * r)
    }
}

/// The prestress's in-plane inner condition of `auto`: fixed unless the bending edge is free.
pub fn inner_fixed(p: &PlateConfig) -> bool {
    p.inner_boundary != Boundary::Free
}
