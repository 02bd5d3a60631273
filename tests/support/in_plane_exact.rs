//! The exact plane-stress solution of the annulus's in-plane vibration per
//! nodal-diameter number k — written for the tests, sharing no numerics with
//! the library (Bessel functions from `bessel.rs`).
//!
//! Navier's equations of plane stress, Ē ∇(div u) − G ∇×∇×u + ρω² u = 0
//! (Ē = E/(1 − ν²), G = E/(2 (1 + ν))), split with the Helmholtz potentials
//! u = ∇φ + ∇×(ψ ẑ) into (∇² + α²) φ = 0, (∇² + β²) ψ = 0 with the
//! dilatational and shear wave numbers α² = ρω²/Ē, β² = ρω²/G. With
//! φ = f(r) cos kθ, ψ = g(r) sin kθ, f, g ∈ {J_k, Y_k} of αr and βr:
//!
//!   u_r = U cos kθ, U = f' + k g/r;   u_θ = V sin kθ, V = −k f/r − g'.
//!
//! Strains ε_r = U', ε_θ = (U + kV)/r, γ_rθ = V' − V/r − kU/r; stresses
//! σ_rr = Ē (ε_r + ν ε_θ), σ_rθ = G γ_rθ. Edge rows: fixed U, V; free
//! σ_rr, σ_rθ — a 4×4 determinant in the four potentials' amplitudes. For
//! k = 0 it splits into the radial family (f only: rows U or σ_rr) and the
//! torsional family (g only: rows V or σ_rθ), two 2×2 determinants.
#![allow(dead_code)]

use super::bessel::jy_val_der;
use super::exact_plate::{bisect, det};

/// An in-plane edge.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Edge {
    Fixed,
    Free,
}

impl Edge {
    pub fn name(self) -> &'static str {
        match self {
            Edge::Fixed => "fixed",
            Edge::Free => "free",
        }
    }
}

/// Which determinant: k ≥ 1 (4×4), or one of k = 0's 2×2 families.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Family {
    Coupled,
    Radial,
    Torsional,
}

/// The annulus in SI units with its in-plane edges.
#[derive(Debug, Clone, Copy)]
pub struct Annulus {
    pub youngs_modulus: f64,
    pub poisson_ratio: f64,
    pub density: f64,
    pub inner_radius: f64,
    pub outer_radius: f64,
    pub inner: Edge,
    pub outer: Edge,
}

/// (U, V, σ_rr/Ē, σ_rθ/G) of one potential at r.
type Row = [f64; 4];

impl Annulus {
    fn e_bar(&self) -> f64 {
        self.youngs_modulus / (1.0 - self.poisson_ratio * self.poisson_ratio)
    }

    fn g(&self) -> f64 {
        self.youngs_modulus / (2.0 * (1.0 + self.poisson_ratio))
    }

    /// (α, β) at ω.
    pub fn wave_numbers(&self, omega: f64) -> (f64, f64) {
        let w2 = self.density * omega * omega;
        ((w2 / self.e_bar()).sqrt(), (w2 / self.g()).sqrt())
    }

    /// Z, Z', Z'' (in r) of Z_k(q r), first or second kind.
    fn cylinder(k: u32, q: f64, r: f64, second_kind: bool) -> [f64; 3] {
        let (j, y) = jy_val_der(k as usize, q * r);
        let z = if second_kind { y } else { j };
        let (v, d) = (z.value, z.deriv * q);
        let kf = k as f64;
        // Bessel's equation: Z'' + Z'/r + (q² − k²/r²) Z = 0.
        let dd = -d / r - (q * q - kf * kf / (r * r)) * v;
        [v, d, dd]
    }

    /// The displacements and stresses of a potential with radial factor
    /// `z` = (Z, Z', Z''), dilatational (φ) or shear (ψ), at r.
    fn fields(&self, k: u32, r: f64, z: [f64; 3], shear: bool) -> Row {
        let kf = k as f64;
        let [v0, d1, d2] = z;
        let (u, du, v, dv) = if shear {
            (kf * v0 / r, kf * d1 / r - kf * v0 / (r * r), -d1, -d2)
        } else {
            (d1, d2, -kf * v0 / r, -kf * d1 / r + kf * v0 / (r * r))
        };
        let nu = self.poisson_ratio;
        let eps_r = du;
        let eps_t = (u + kf * v) / r;
        let gamma = dv - v / r - kf * u / r;
        [u, v, eps_r + nu * eps_t, gamma]
    }

    /// The edge rows' entries (two per edge) of the four potentials
    /// [φ J, φ Y, ψ J, ψ Y] at ω.
    fn columns(&self, k: u32, omega: f64) -> Vec<[f64; 4]> {
        let (alpha, beta) = self.wave_numbers(omega);
        let mut cols = Vec::with_capacity(4);
        for (q, shear) in [(alpha, false), (beta, true)] {
            for second in [false, true] {
                let mut entries = [0.0; 4];
                for (e, (r, edge)) in [
                    (self.inner_radius, self.inner),
                    (self.outer_radius, self.outer),
                ]
                .into_iter()
                .enumerate()
                {
                    let f = self.fields(k, r, Self::cylinder(k, q, r, second), shear);
                    let (a, b) = match edge {
                        Edge::Fixed => (f[0], f[1]),
                        Edge::Free => (f[2], f[3]),
                    };
                    entries[2 * e] = a;
                    entries[2 * e + 1] = b;
                }
                cols.push(entries);
            }
        }
        cols
    }

    /// The edge determinant of `family` at ω (rows scaled per potential
    /// family by positive factors only: the roots stay).
    pub fn determinant(&self, k: u32, family: Family, omega: f64) -> f64 {
        let c = self.columns(k, omega);
        match family {
            Family::Coupled => det(std::array::from_fn::<_, 4, _>(|i| {
                std::array::from_fn::<_, 4, _>(|j| c[j][i])
            })),
            // φ alone: rows U or σ_rr (entries 0 and 2).
            Family::Radial => c[0][0] * c[1][2] - c[1][0] * c[0][2],
            // ψ alone: rows V or σ_rθ (entries 1 and 3).
            Family::Torsional => c[2][1] * c[3][3] - c[3][1] * c[2][3],
        }
    }

    /// The lowest `count` roots ω > 0 of `family`'s determinant: sign
    /// changes on a grid uniform in β with `per_width` points per
    /// π/(r_a − r_i), then bisection.
    pub fn roots(&self, k: u32, family: Family, count: usize, per_width: usize) -> Vec<f64> {
        let width = self.outer_radius - self.inner_radius;
        let step = std::f64::consts::PI / width / per_width as f64;
        let omega_of_beta = |b: f64| b * (self.g() / self.density).sqrt();
        let f = |b: f64| self.determinant(k, family, omega_of_beta(b));
        let mut roots = Vec::new();
        let mut lo = 0.5 * step;
        let mut f_lo = f(lo);
        while roots.len() < count {
            let hi = lo + step;
            let f_hi = f(hi);
            if f_lo == 0.0 {
                roots.push(lo);
            } else if f_lo.signum() != f_hi.signum() {
                roots.push(bisect(&f, lo, hi, f_lo));
            }
            lo = hi;
            f_lo = f_hi;
        }
        roots.into_iter().map(omega_of_beta).collect()
    }
}

/// The torsional frequency equation of a fixed–free annulus in closed form:
/// V = A J₁(βr) + B Y₁(βr) (Bessel's equation of order 1 for u_θ = V(r)),
/// V(r_i) = 0 and τ_rθ ∝ V' − V/r = −β Z₂(βr) = 0 at r_a (A&S 9.1.27:
/// Z₁' − Z₁/x = Z₀ − 2Z₁/x = −Z₂), so
/// J₁(βr_i) Y₂(βr_a) − Y₁(βr_i) J₂(βr_a) = 0. Its lowest root β, by a scan
/// and bisection of its own.
pub fn torsional_fixed_free_beta(ri: f64, ra: f64, order: usize) -> f64 {
    use super::bessel::jy_seq;
    let f = |b: f64| {
        let (ji, yi) = jy_seq(2, b * ri);
        let (ja, ya) = jy_seq(2, b * ra);
        ji[1] * ya[2] - yi[1] * ja[2]
    };
    let step = std::f64::consts::PI / (ra - ri) / 64.0;
    let (mut lo, mut found) = (0.5 * step, 0);
    loop {
        let (f_lo, f_hi) = (f(lo), f(lo + step));
        if f_lo.signum() != f_hi.signum() {
            if found == order {
                return bisect(&f, lo, lo + step, f_lo);
            }
            found += 1;
        }
        lo += step;
    }
}
