//! The exact Mindlin solution of the annular plate per nodal-diameter number
//! k — written for the tests, sharing no numerics with the library (Bessel
//! functions from `bessel.rs`).
//!
//! Mindlin's equations (γ = ψ + ∇w, S = κGh, I = ρh³/12)
//!   S (∇²w + div ψ) + ρh ω² w = 0,
//!   D/2 [(1 − ν) ∇²ψ + (1 + ν) ∇ div ψ] − S (ψ + ∇w) + I ω² ψ = 0
//! split with ψ = ∇φ + curl(H ẑ) into
//!   w = W₁ + W₂, φ = (σ₁ − 1) W₁ + (σ₂ − 1) W₂, (∇² + δᵢ²) Wᵢ = 0,
//!   σᵢ = ρω² / (κG δᵢ²), δ₁,₂² roots of
//!   δ⁴ − (P/S + Iω²/D) δ² + P (Iω² − S)/(S D) = 0, P = ρhω²,
//!   (∇² + δ₃²) H = 0, δ₃² = 2 (Iω² − S) / (D (1 − ν)).
//! δ₁² > 0 always; below the thickness-shear cut-off ω_c = √(S/I) δ₂², δ₃² < 0
//! (modified Bessel I_k, K_k of |δ| r), above it J_k, Y_k. With
//! Wᵢ = Zᵢ(r) cos kθ, H = Z₃(r) sin kθ:
//!   W = Z₁ + Z₂, Ψ_r = Σ (σᵢ − 1) Zᵢ' + k Z₃/r, Ψ_θ = −k Σ (σᵢ − 1) Zᵢ/r − Z₃'
//! (ψ_θ = Ψ_θ sin kθ). Edge rows: clamped W, Ψ_r, Ψ_θ; free Q_r, M_r, M_rθ;
//! supported W, Ψ_θ, M_r; supported_soft W, M_r, M_rθ — a 6×6 determinant
//! (4×4 for k = 0, where H carries only the decoupled ψ_θ and is left out).
#![allow(dead_code)]

use super::bessel::{i_scaled_val_der, jy_val_der, k_scaled_val_der, ValDer};
use super::exact_plate::bisect;
use annular_plate::config::{Boundary, PlateConfig};

/// An edge of the exact solution.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Edge {
    Free,
    SupportedSoft,
    Supported,
    Clamped,
}

impl Edge {
    pub const ALL: [Edge; 4] = [
        Edge::Free,
        Edge::SupportedSoft,
        Edge::Supported,
        Edge::Clamped,
    ];

    pub fn name(self) -> &'static str {
        match self {
            Edge::Free => "free",
            Edge::SupportedSoft => "supported_soft",
            Edge::Supported => "supported",
            Edge::Clamped => "clamped",
        }
    }

    fn rows(self) -> [Quantity; 3] {
        use Quantity::*;
        match self {
            Edge::Free => [ShearForce, Moment, TwistingMoment],
            Edge::SupportedSoft => [Deflection, Moment, TwistingMoment],
            Edge::Supported => [Deflection, Moment, RotationTheta],
            Edge::Clamped => [Deflection, RotationR, RotationTheta],
        }
    }
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Quantity {
    Deflection,
    RotationR,
    RotationTheta,
    ShearForce,
    Moment,
    TwistingMoment,
}

/// A Mindlin annulus.
#[derive(Debug, Clone, Copy)]
pub struct MindlinAnnulus {
    pub youngs_modulus: f64,
    pub poisson_ratio: f64,
    pub density: f64,
    pub thickness: f64,
    pub shear_correction: f64,
    pub inner_radius: f64,
    pub outer_radius: f64,
    pub inner: Edge,
    pub outer: Edge,
}

/// Radial functions of one column at one radius: W, W', Ψ_r, Ψ_r', Ψ_θ, Ψ_θ'.
struct Fields {
    w: f64,
    w_r: f64,
    psi_r: f64,
    psi_r_r: f64,
    psi_t: f64,
    psi_t_r: f64,
}

impl MindlinAnnulus {
    /// The annulus of a configuration's plate (its material, geometry,
    /// shear correction and edges; the theory key is not read).
    pub fn of_plate(p: &PlateConfig) -> MindlinAnnulus {
        let edge = |b: Boundary| match b {
            Boundary::Free => Edge::Free,
            Boundary::Supported => Edge::Supported,
            Boundary::Clamped => Edge::Clamped,
            Boundary::SupportedSoft => Edge::SupportedSoft,
        };
        MindlinAnnulus {
            youngs_modulus: p.youngs_modulus,
            poisson_ratio: p.poisson_ratio,
            density: p.density,
            thickness: p.thickness,
            shear_correction: p.shear_correction,
            inner_radius: p.inner_radius,
            outer_radius: p.outer_radius,
            inner: edge(p.inner_boundary),
            outer: edge(p.outer_boundary),
        }
    }
}

impl MindlinAnnulus {
    pub fn rigidity(&self) -> f64 {
        let (e, h, nu) = (self.youngs_modulus, self.thickness, self.poisson_ratio);
        e * h.powi(3) / (12.0 * (1.0 - nu * nu))
    }
    fn shear(&self) -> f64 {
        self.shear_correction * self.youngs_modulus / (2.0 * (1.0 + self.poisson_ratio))
            * self.thickness
    }
    fn inertia(&self) -> f64 {
        self.density * self.thickness.powi(3) / 12.0
    }
    /// The thickness-shear cut-off ω_c = √(κGh / (ρh³/12)), rad/s.
    pub fn cutoff(&self) -> f64 {
        (self.shear() / self.inertia()).sqrt()
    }

    /// Signed δ₁², δ₂², δ₃² at ω.
    pub fn wave_numbers(&self, omega: f64) -> [f64; 3] {
        let (d, s, i) = (self.rigidity(), self.shear(), self.inertia());
        let p = self.density * self.thickness * omega * omega;
        let a = p / s + i * omega * omega / d;
        let b = p * (i * omega * omega - s) / (s * d);
        let disc = (p / s - i * omega * omega / d).powi(2) + 4.0 * p / d;
        let d1 = 0.5 * (a + disc.sqrt());
        let d3 = 2.0 * (i * omega * omega - s) / (d * (1.0 - self.poisson_ratio));
        [d1, b / d1, d3]
    }

    /// The edge matrix at ω (rows: inner then outer conditions).
    pub fn matrix(&self, k: u32, omega: f64) -> Vec<Vec<f64>> {
        let deltas = self.wave_numbers(omega);
        let p_over_s = self.density * omega * omega
            / (self.shear_correction * self.youngs_modulus / (2.0 * (1.0 + self.poisson_ratio)));
        let potentials = if k == 0 { 2 } else { 3 };
        let (ri, ra) = (self.inner_radius, self.outer_radius);
        let mut rows = Vec::new();
        for (edge, r) in [(self.inner, ri), (self.outer, ra)] {
            for q in edge.rows() {
                if k == 0 && matches!(q, Quantity::RotationTheta | Quantity::TwistingMoment) {
                    continue;
                }
                let mut row = Vec::with_capacity(2 * potentials);
                for (p, &d2) in deltas.iter().enumerate().take(potentials) {
                    for second_kind in [false, true] {
                        let z = cylinder(k, d2, r, ri, ra, second_kind);
                        let f = if p < 2 {
                            w_potential(k, d2, r, z, p_over_s / d2 - 1.0)
                        } else {
                            h_potential(k, d2, r, z)
                        };
                        row.push(self.quantity(q, &f, k, r));
                    }
                }
                rows.push(row);
            }
        }
        rows
    }

    fn quantity(&self, q: Quantity, f: &Fields, k: u32, r: f64) -> f64 {
        let (kf, nu) = (k as f64, self.poisson_ratio);
        match q {
            Quantity::Deflection => f.w,
            Quantity::RotationR => f.psi_r,
            Quantity::RotationTheta => f.psi_t,
            Quantity::ShearForce => f.psi_r + f.w_r,
            Quantity::Moment => f.psi_r_r + nu * (f.psi_r + kf * f.psi_t) / r,
            Quantity::TwistingMoment => f.psi_t_r - (f.psi_t + kf * f.psi_r) / r,
        }
    }

    /// The edge determinant at ω (Gaussian elimination, partial pivoting;
    /// rows equilibrated — positive factors do not move its roots).
    pub fn determinant(&self, k: u32, omega: f64) -> f64 {
        let mut a = self.matrix(k, omega);
        for row in a.iter_mut() {
            let m = row.iter().fold(0.0f64, |m, v| m.max(v.abs()));
            if m > 0.0 {
                row.iter_mut().for_each(|v| *v /= m);
            }
        }
        let n = a.len();
        let mut det = 1.0;
        for c in 0..n {
            let p = (c..n)
                .max_by(|&i, &j| a[i][c].abs().total_cmp(&a[j][c].abs()))
                .unwrap();
            if p != c {
                a.swap(p, c);
                det = -det;
            }
            let piv = a[c][c];
            det *= piv;
            if piv == 0.0 {
                return 0.0;
            }
            let pivot_row = a[c].clone();
            for row in a.iter_mut().skip(c + 1) {
                let f = row[c] / piv;
                for (x, p) in row[c..].iter_mut().zip(&pivot_row[c..]) {
                    *x -= f * p;
                }
            }
        }
        det
    }

    /// λ = (ρh ω² / D)^{1/4} of ω and back.
    pub fn omega_of_lambda(&self, lambda: f64) -> f64 {
        lambda * lambda * (self.rigidity() / (self.density * self.thickness)).sqrt()
    }

    /// The lowest `count` roots ω of the determinant for k (rigid-body ω = 0
    /// not included): sign changes on a grid uniform in λ with `per_width`
    /// points per π/(r_a − r_i), then bisection to machine precision. Panics
    /// if they are not all below the thickness-shear cut-off.
    pub fn roots(&self, k: u32, count: usize, per_width: usize) -> Vec<f64> {
        let width = self.outer_radius - self.inner_radius;
        let step = std::f64::consts::PI / width / per_width as f64;
        let f = |lambda: f64| self.determinant(k, self.omega_of_lambda(lambda));
        let mut roots = Vec::new();
        let mut lo = 0.5 * step;
        let mut f_lo = f(lo);
        while roots.len() < count {
            let hi = lo + step;
            assert!(
                self.omega_of_lambda(hi) < self.cutoff(),
                "k = {k}: only {} roots below the thickness-shear cut-off",
                roots.len()
            );
            let f_hi = f(hi);
            if f_lo == 0.0 {
                roots.push(lo);
            } else if f_lo.signum() != f_hi.signum() {
                roots.push(bisect(&f, lo, hi, f_lo));
            }
            lo = hi;
            f_lo = f_hi;
        }
        roots.into_iter().map(|l| self.omega_of_lambda(l)).collect()
    }
}

/// Z, Z' of the first (J or I) or second (Y or K) kind of order k for the
/// signed wave number δ² at r. I is scaled by e^{−|δ| r_a}, K by e^{|δ| r_i}
/// (positive column factors: the determinant's roots stay).
fn cylinder(k: u32, d2: f64, r: f64, ri: f64, ra: f64, second_kind: bool) -> ValDer {
    let n = k as usize;
    let q = d2.abs().sqrt();
    let x = q * r;
    let (v, factor) = if d2 > 0.0 {
        let (j, y) = jy_val_der(n, x);
        (if second_kind { y } else { j }, 1.0)
    } else if second_kind {
        (k_scaled_val_der(n, x), (-q * (r - ri)).exp())
    } else {
        (i_scaled_val_der(n, x), (q * (r - ra)).exp())
    };
    ValDer {
        value: v.value * factor,
        deriv: v.deriv * q * factor,
    }
}

/// Z'' from the (modified) Bessel equation Z'' + Z'/r − k² Z/r² = −δ² Z.
fn second_derivative(k: u32, d2: f64, r: f64, z: ValDer) -> f64 {
    let k2 = (k * k) as f64;
    -z.deriv / r + (k2 / (r * r) - d2) * z.value
}

/// The fields of w = Z cos kθ, φ = c Z cos kθ (c = σ − 1).
fn w_potential(k: u32, d2: f64, r: f64, z: ValDer, c: f64) -> Fields {
    let kf = k as f64;
    let zpp = second_derivative(k, d2, r, z);
    Fields {
        w: z.value,
        w_r: z.deriv,
        psi_r: c * z.deriv,
        psi_r_r: c * zpp,
        psi_t: -kf * c * z.value / r,
        psi_t_r: -kf * c * (z.deriv / r - z.value / (r * r)),
    }
}

/// The fields of H = Z sin kθ: ψ_r = (1/r) ∂H/∂θ, ψ_θ = −∂H/∂r.
fn h_potential(k: u32, d2: f64, r: f64, z: ValDer) -> Fields {
    let kf = k as f64;
    let zpp = second_derivative(k, d2, r, z);
    Fields {
        w: 0.0,
        w_r: 0.0,
        psi_r: kf * z.value / r,
        psi_r_r: kf * (z.deriv / r - z.value / (r * r)),
        psi_t: -z.deriv,
        psi_t_r: -zpp,
    }
}

/// The radial fields (W, Ψ_r, Ψ_θ) of a mode at one radius (any scale).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ModeFields {
    pub w: f64,
    pub psi_r: f64,
    pub psi_theta: f64,
}

/// The exact mode of k at its root ω: the edge matrix's null vector
/// (its right singular vector of the smallest singular value) weighting the
/// potentials' columns, evaluated anywhere in [r_i, r_a].
pub struct ExactMode {
    annulus: MindlinAnnulus,
    k: u32,
    omega: f64,
    weights: Vec<f64>,
}

impl MindlinAnnulus {
    /// The exact mode shape of k at the root `omega` (from [`MindlinAnnulus::roots`]).
    pub fn mode(&self, k: u32, omega: f64) -> ExactMode {
        let rows = self.matrix(k, omega);
        let n = rows.len();
        let mut a = nalgebra::DMatrix::from_fn(n, n, |i, j| rows[i][j]);
        for mut row in a.row_iter_mut() {
            let m = row.amax();
            if m > 0.0 {
                row /= m;
            }
        }
        let svd = a.svd(false, true);
        let v_t = svd.v_t.expect("right singular vectors");
        let smallest = (0..n)
            .min_by(|&i, &j| svd.singular_values[i].total_cmp(&svd.singular_values[j]))
            .unwrap();
        ExactMode {
            annulus: *self,
            k,
            omega,
            weights: v_t.row(smallest).iter().copied().collect(),
        }
    }
}

impl ExactMode {
    /// W, Ψ_r, Ψ_θ at r (w = W cos kθ, ψ_r = Ψ_r cos kθ, ψ_θ = Ψ_θ sin kθ).
    pub fn fields(&self, r: f64) -> ModeFields {
        let p = &self.annulus;
        let deltas = p.wave_numbers(self.omega);
        let p_over_s = p.density * self.omega * self.omega
            / (p.shear_correction * p.youngs_modulus / (2.0 * (1.0 + p.poisson_ratio)));
        let potentials = if self.k == 0 { 2 } else { 3 };
        let mut out = ModeFields {
            w: 0.0,
            psi_r: 0.0,
            psi_theta: 0.0,
        };
        let mut c = self.weights.iter();
        for (q, &d2) in deltas.iter().enumerate().take(potentials) {
            for second_kind in [false, true] {
                let z = cylinder(self.k, d2, r, p.inner_radius, p.outer_radius, second_kind);
                let f = if q < 2 {
                    w_potential(self.k, d2, r, z, p_over_s / d2 - 1.0)
                } else {
                    h_potential(self.k, d2, r, z)
                };
                let weight = c.next().unwrap();
                out.w += weight * f.w;
                out.psi_r += weight * f.psi_r;
                out.psi_theta += weight * f.psi_t;
            }
        }
        out
    }

    /// c_k ∫ [ρh W² + ρh³/12 (Ψ_r² + Ψ_θ²)] r dr for the shape's scale
    /// (Gauss–Legendre, 4 points on each of `cells` cells).
    pub fn modal_mass(&self, cells: usize) -> f64 {
        let p = &self.annulus;
        let (rho_h, rot) = (p.density * p.thickness, p.inertia());
        let sum = super::quadrature::radial(p.inner_radius, p.outer_radius, cells, |r| {
            let f = self.fields(r);
            (rho_h * f.w * f.w + rot * (f.psi_r * f.psi_r + f.psi_theta * f.psi_theta)) * r
        });
        let c_k = if self.k == 0 { 2.0 } else { 1.0 } * std::f64::consts::PI;
        c_k * sum
    }
}
