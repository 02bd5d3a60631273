//! Exact static deflection of an annular Mindlin plate under a uniform load
//! on an annular-sector patch, read as the mean over another patch — written
//! for the tests, sharing no numerics with the library (no B-splines, no
//! modes): per harmonic k the closed-form solutions of Mindlin's static
//! equations, a radial line load matched at its radius, integrated over the
//! two patches by Gauss–Legendre.
//!
//! Mindlin's static equations (S = κGh):
//!   S (∇²w + div ψ) + p = 0,
//!   D/2 [(1 − ν) ∇²ψ + (1 + ν) ∇ div ψ] − S (ψ + ∇w) = 0.
//! With ψ = ∇F + curl(Φ ẑ) the second splits into a gradient,
//! ∇[D ∇²F − S (F + w)] = 0, and a curl, D (1 − ν)/2 ∇²Φ − S Φ = 0; so
//! without load w = −F + (D/S) ∇²F with F biharmonic (then the first holds:
//! S ∇²(w + F) = D ∇⁴F = 0) and (∇² − λ²) Φ = 0, λ² = 2S / (D (1 − ν)) = 12κ/h².
//! Per harmonic (F = f cos kθ, Φ = φ sin kθ; w = W cos kθ, ψ_r = Ψ_r cos kθ,
//! ψ_θ = Ψ_θ sin kθ):
//!   f ∈ {r^k, r^{−k}, r^{k+2}, r^{2−k}} (k ≥ 2), {r, r⁻¹, r³, r ln r} (k = 1),
//!   {1, ln r, r², r² ln r} (k = 0);  φ ∈ {I_k(λr), K_k(λr)};
//!   W = −f + (D/S)(f'' + f'/r − k² f/r²),  Ψ_r = f' + kφ/r,  Ψ_θ = −kf/r − φ',
//!   M_r = D [Ψ_r' + ν (Ψ_r + kΨ_θ)/r],  M_rθ = D (1 − ν)/2 [Ψ_θ' − (Ψ_θ + kΨ_r)/r],
//!   Q_r = S (Ψ_r + W').
//! A line load of unit intensity (N/m per unit of the harmonic) at r = s:
//! W, Ψ_r, Ψ_θ, M_r, M_rθ continuous, Q_r jumps by −1; edges as in
//! `mindlin_exact.rs` (clamped W = Ψ_r = Ψ_θ = 0, supported W = Ψ_θ = M_r = 0,
//! supported_soft W = M_r = M_rθ = 0, free Q_r = M_r = M_rθ = 0). For k = 0
//! the φ family decouples and solves to zero. 12 unknowns per (k, s), solved
//! equilibrated with one refinement step; each segment's functions are
//! anchored where they are largest (`(r/b)^k`, `(r/a)^{−k}`, I_k(λr)/I_k(λb),
//! K_k(λr)/K_k(λa)) so nothing overflows; I_k, K_k for k ≥ [`DEBYE_ORDER`]
//! by Debye's uniform expansion (ratios only).
//!
//! A force F spread per unit area over the patch b (radii [b₀, b₁], angles
//! θ_b ± β_b) has the harmonic load p_k(r) = F sinc(kβ_b)/(c_k S_b) on
//! [b₀, b₁], S = (b₁² − b₀²)/2; the mean of w over patch a is
//!   C = Σ_k cos kΔθ sinc(kβ_a) sinc(kβ_b) /(c_k S_a S_b) ∫_b ds ∫_a r G_k(r, s) dr.
#![allow(dead_code)]

use super::bessel::{i_scaled_val_der, k_scaled_val_der};
use super::mindlin_exact::Edge;
use super::static_plate::{gauss_legendre, power, power_pair, solve_refined};
use annular_plate::config::{Boundary, PlateConfig};
use std::f64::consts::PI;

/// From this order on, I_k and K_k ratios by Debye's expansion.
pub const DEBYE_ORDER: u32 = 40;
/// Gauss–Legendre points per quadrature piece.
const GAUSS: usize = 8;

/// An annular-sector patch.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Patch {
    pub lo: f64,
    pub hi: f64,
    /// Half-angle β, rad.
    pub beta: f64,
}

impl Patch {
    /// |r − r0| ≤ c clipped to [ri, ra], |θ − θ0| ≤ min(c/r0, π).
    pub fn new(ri: f64, ra: f64, r0: f64, c: f64) -> Patch {
        Patch {
            lo: (r0 - c).max(ri),
            hi: (r0 + c).min(ra),
            beta: (c / r0).min(PI),
        }
    }
    pub fn area_factor(&self) -> f64 {
        0.5 * (self.hi * self.hi - self.lo * self.lo)
    }
    pub fn sinc(&self, k: u32) -> f64 {
        let x = k as f64 * self.beta;
        if x == 0.0 {
            1.0
        } else {
            x.sin() / x
        }
    }
}

/// A Mindlin annulus in statics.
#[derive(Debug, Clone, Copy)]
pub struct MindlinStatic {
    pub ri: f64,
    pub ra: f64,
    pub nu: f64,
    /// D, N·m.
    pub d: f64,
    /// S = κGh, N/m.
    pub s: f64,
    pub inner: Edge,
    pub outer: Edge,
}

impl MindlinStatic {
    pub fn of_plate(p: &PlateConfig) -> MindlinStatic {
        let edge = |b: Boundary| match b {
            Boundary::Free => Edge::Free,
            Boundary::Supported => Edge::Supported,
            Boundary::Clamped => Edge::Clamped,
            Boundary::SupportedSoft => Edge::SupportedSoft,
        };
        let (e, h, nu) = (p.youngs_modulus, p.thickness, p.poisson_ratio);
        MindlinStatic {
            ri: p.inner_radius,
            ra: p.outer_radius,
            nu,
            d: e * h.powi(3) / (12.0 * (1.0 - nu * nu)),
            s: p.shear_correction * e / (2.0 * (1.0 + nu)) * h,
            inner: edge(p.inner_boundary),
            outer: edge(p.outer_boundary),
        }
    }

    pub fn lambda(&self) -> f64 {
        (2.0 * self.s / (self.d * (1.0 - self.nu))).sqrt()
    }

    /// [f, f', f'', f'''] of the four F functions on segment [a, b].
    fn f_basis(&self, k: u32, a: f64, b: f64, r: f64) -> [[f64; 4]; 4] {
        let kf = k as f64;
        match k {
            0 => [
                power(0.0, r, b),
                power_log(0.0, r, b),
                power(2.0, r, b),
                power_log(2.0, r, b),
            ],
            1 => [
                power(1.0, r, b),
                power(-1.0, r, b),
                power(3.0, r, b),
                power_log(1.0, r, b),
            ],
            _ => [
                power(kf, r, b),
                power(-kf, r, a),
                power_pair(kf, r, b),
                power_pair(-kf, r, a),
            ],
        }
    }

    /// [φ, φ', φ''] of I_k(λr)/I_k(λb) and K_k(λr)/K_k(λa).
    fn phi_basis(&self, k: u32, a: f64, b: f64, r: f64) -> [[f64; 3]; 2] {
        let l = self.lambda();
        let (i, di) = ratio_i(k, l * r, l * b);
        let (kk, dk) = ratio_k(k, l * r, l * a);
        let second = |v: f64, d: f64| -d / r + ((k * k) as f64 / (r * r) + l * l) * v;
        [
            [i, l * di, second(i, l * di)],
            [kk, l * dk, second(kk, l * dk)],
        ]
    }

    /// [W, Ψ_r, Ψ_θ, M_r, M_rθ, Q_r] of the six functions of segment [a, b] at r.
    fn fields(&self, k: u32, a: f64, b: f64, r: f64) -> [[f64; 6]; 6] {
        let kf = k as f64;
        let (d, s, nu) = (self.d, self.s, self.nu);
        let delta = d / s;
        let mut out = [[0.0; 6]; 6];
        for (j, f) in self.f_basis(k, a, b, r).iter().enumerate() {
            let [f0, f1, f2, f3] = *f;
            let w = -f0 + delta * (f2 + f1 / r - kf * kf * f0 / (r * r));
            let w1 = -f1
                + delta
                    * (f3 + f2 / r - f1 / (r * r) - kf * kf * f1 / (r * r)
                        + 2.0 * kf * kf * f0 / (r * r * r));
            let (pr, pr1) = (f1, f2);
            let (pt, pt1) = (-kf * f0 / r, -kf * f1 / r + kf * f0 / (r * r));
            out[j] = self.quantities(kf, r, [w, w1, pr, pr1, pt, pt1], (d, s, nu));
        }
        for (j, p) in self.phi_basis(k, a, b, r).iter().enumerate() {
            let [p0, p1, p2] = *p;
            let (pr, pr1) = (kf * p0 / r, kf * p1 / r - kf * p0 / (r * r));
            let (pt, pt1) = (-p1, -p2);
            out[4 + j] = self.quantities(kf, r, [0.0, 0.0, pr, pr1, pt, pt1], (d, s, nu));
        }
        out
    }

    /// [W, Ψ_r, Ψ_θ, M_r, M_rθ, Q_r] from W, W', Ψ_r, Ψ_r', Ψ_θ, Ψ_θ'.
    fn quantities(&self, k: f64, r: f64, v: [f64; 6], (d, s, nu): (f64, f64, f64)) -> [f64; 6] {
        let [w, w1, pr, pr1, pt, pt1] = v;
        [
            w,
            pr,
            pt,
            d * (pr1 + nu * (pr + k * pt) / r),
            0.5 * d * (1.0 - nu) * (pt1 - (pt + k * pr) / r),
            s * (pr + w1),
        ]
    }

    /// W of the F functions of segment [a, b] at r.
    fn w_basis(&self, k: u32, a: f64, b: f64, r: f64) -> [f64; 4] {
        let kf = k as f64;
        let delta = self.d / self.s;
        self.f_basis(k, a, b, r)
            .map(|[f0, f1, f2, _]| -f0 + delta * (f2 + f1 / r - kf * kf * f0 / (r * r)))
    }

    /// The line-load solution of harmonic k at radius s: the coefficients of
    /// segment [r_i, s] then [s, r_a], and the solve's backward error.
    pub fn line_load(&self, k: u32, s: f64) -> ([f64; 12], f64) {
        let (ri, ra) = (self.ri, self.ra);
        let rows = |edge: Edge| -> [usize; 3] {
            match edge {
                Edge::Free => [5, 3, 4],
                Edge::SupportedSoft => [0, 3, 4],
                Edge::Supported => [0, 3, 2],
                Edge::Clamped => [0, 1, 2],
            }
        };
        let mut m = [[0.0; 12]; 12];
        let mut rhs = [0.0; 12];
        let fi = self.fields(k, ri, s, ri);
        let f1 = self.fields(k, ri, s, s);
        let f2 = self.fields(k, s, ra, s);
        let fa = self.fields(k, s, ra, ra);
        for (row, &q) in rows(self.inner).iter().enumerate() {
            for j in 0..6 {
                m[row][j] = fi[j][q];
            }
        }
        for q in 0..6 {
            for j in 0..6 {
                m[3 + q][j] = -f1[j][q];
                m[3 + q][6 + j] = f2[j][q];
            }
        }
        rhs[8] = -1.0;
        for (row, &q) in rows(self.outer).iter().enumerate() {
            for j in 0..6 {
                m[9 + row][6 + j] = fa[j][q];
            }
        }
        solve_refined(&m, &rhs)
    }

    /// ∫_a r G_k(r, s) dr for the line load at s.
    fn read_integral(&self, k: u32, s: f64, coefficients: &[f64; 12], a: &Patch) -> f64 {
        let scale = s / (k as f64 + 1.0);
        pieces(a.lo, a.hi, &[s, a.lo, a.hi], scale)
            .into_iter()
            .map(|(r, w)| {
                let (seg, lo, hi) = if r <= s {
                    (0, self.ri, s)
                } else {
                    (1, s, self.ra)
                };
                let basis = self.w_basis(k, lo, hi, r);
                let value: f64 = (0..4).map(|j| coefficients[6 * seg + j] * basis[j]).sum();
                w * r * value
            })
            .sum()
    }

    /// The harmonic k of the compliance between the load patch and each
    /// read patch (without cos kΔθ), m/N, and the worst backward error.
    pub fn harmonic(&self, k: u32, load: &Patch, reads: &[Patch]) -> (Vec<f64>, f64) {
        let ck = if k == 0 { 2.0 * PI } else { PI };
        let scale = 0.5 * (load.lo + load.hi) / (k as f64 + 1.0);
        let mut targets = vec![load.lo, load.hi];
        for a in reads {
            targets.extend([a.lo, a.hi]);
        }
        let mut sums = vec![0.0; reads.len()];
        let mut worst: f64 = 0.0;
        for (s, ws) in pieces(load.lo, load.hi, &targets, scale) {
            let (c, be) = self.line_load(k, s);
            worst = worst.max(be);
            for (sum, a) in sums.iter_mut().zip(reads) {
                *sum += ws * self.read_integral(k, s, &c, a);
            }
        }
        let terms = sums
            .iter()
            .zip(reads)
            .map(|(v, a)| {
                v * load.sinc(k) * a.sinc(k) / (ck * load.area_factor() * a.area_factor())
            })
            .collect();
        (terms, worst)
    }

    /// Σ_k cos kΔθ · harmonic k for each (read patch, Δθ), to the first k ≥
    /// 8 where every term's envelope times k/3 (the terms fall like k⁻⁴) is
    /// below `tol` of the largest sum, at most `k_max`; returns the sums, the
    /// harmonics used and the worst backward error.
    pub fn series(
        &self,
        load: &Patch,
        reads: &[(Patch, f64)],
        tol: f64,
        k_max: u32,
    ) -> (Vec<f64>, u32, f64) {
        let patches: Vec<Patch> = reads.iter().map(|r| r.0).collect();
        let mut sums = vec![0.0; reads.len()];
        let mut worst: f64 = 0.0;
        for k in 0..=k_max {
            let (terms, be) = self.harmonic(k, load, &patches);
            worst = worst.max(be);
            let mut bound: f64 = 0.0;
            for ((sum, t), (a, delta)) in sums.iter_mut().zip(&terms).zip(reads) {
                *sum += t * (k as f64 * delta).cos();
                let envelope = |p: &Patch| (1.0 / (k as f64 * p.beta)).min(1.0);
                let raw = t.abs() / (a.sinc(k).abs() * load.sinc(k).abs()).max(1e-300);
                bound = bound.max(raw * envelope(a) * envelope(load));
            }
            let largest = sums.iter().fold(0.0_f64, |m, v| m.max(v.abs()));
            let done = k >= 8 && (k as f64 / 3.0) * bound < tol * largest;
            if done {
                return (sums, k, worst);
            }
        }
        (sums, k_max, worst)
    }
}

/// [f, f', f'', f'''] of (r/c)^n ln(r/c).
fn power_log(n: f64, r: f64, c: f64) -> [f64; 4] {
    let x = r / c;
    let l = x.ln();
    let p = |m: f64| x.powf(m);
    [
        p(n) * l,
        p(n - 1.0) * (n * l + 1.0) / c,
        p(n - 2.0) * (n * (n - 1.0) * l + 2.0 * n - 1.0) / (c * c),
        p(n - 3.0) * (n * (n - 1.0) * (n - 2.0) * l + 3.0 * n * n - 6.0 * n + 2.0) / (c * c * c),
    ]
}

/// Quadrature points (x, w) on [lo, hi]: Gauss–Legendre pieces split at the
/// targets inside and graded geometrically towards each, down to `scale`/4.
pub fn pieces(lo: f64, hi: f64, targets: &[f64], scale: f64) -> Vec<(f64, f64)> {
    let mut cuts = vec![lo, hi];
    for &t in targets {
        if t < lo || t > hi {
            continue;
        }
        cuts.push(t);
        let mut d = 0.25 * scale;
        while d < hi - lo {
            cuts.push(t - d);
            cuts.push(t + d);
            d *= 2.0;
        }
    }
    cuts.retain(|&x| x >= lo && x <= hi);
    cuts.sort_by(f64::total_cmp);
    cuts.dedup_by(|a, b| (*a - *b).abs() <= 1e-12 * (hi - lo));
    let (x, w) = gauss_legendre(GAUSS);
    let mut out = Vec::new();
    for pair in cuts.windows(2) {
        let (mid, half) = (0.5 * (pair[0] + pair[1]), 0.5 * (pair[1] - pair[0]));
        for (xi, wi) in x.iter().zip(&w) {
            out.push((mid + half * xi, half * wi));
        }
    }
    out
}

/// (I_k(x)/I_k(x0), I_k'(x)/I_k(x0)).
pub fn ratio_i(k: u32, x: f64, x0: f64) -> (f64, f64) {
    if k < DEBYE_ORDER {
        let (a, b) = (
            i_scaled_val_der(k as usize, x),
            i_scaled_val_der(k as usize, x0),
        );
        let e = (x - x0).exp();
        return (a.value / b.value * e, a.deriv / b.value * e);
    }
    debye_ratio(k, x, x0, false)
}

/// The ratios of [`ratio_i`] (`second_kind` false) or [`ratio_k`] by Debye's expansion.
pub fn debye_ratio(k: u32, x: f64, x0: f64, second_kind: bool) -> (f64, f64) {
    let (la, ua, va) = debye(k, x, second_kind);
    let (lb, ub, _) = debye(k, x0, second_kind);
    let ratio = (la - lb).exp() * ua / ub;
    let z = x / k as f64;
    let sign = if second_kind { -1.0 } else { 1.0 };
    (ratio, sign * ratio * (1.0 + z * z).sqrt() / z * va / ua)
}

/// (K_k(x)/K_k(x0), K_k'(x)/K_k(x0)).
pub fn ratio_k(k: u32, x: f64, x0: f64) -> (f64, f64) {
    if k < DEBYE_ORDER {
        let (a, b) = (
            k_scaled_val_der(k as usize, x),
            k_scaled_val_der(k as usize, x0),
        );
        let e = (x0 - x).exp();
        return (a.value / b.value * e, a.deriv / b.value * e);
    }
    debye_ratio(k, x, x0, true)
}

/// Debye's uniform expansion of I_ν(νz) (or K_ν(νz)): the exponent ±νη −
/// ¼ ln(1 + z²) (the ν-only factors cancel in ratios), Σ (±1)^j u_j(t)/ν^j
/// and Σ (±1)^j v_j(t)/ν^j (the derivative's series), t = 1/√(1 + z²).
fn debye(k: u32, x: f64, second_kind: bool) -> (f64, f64, f64) {
    let nu = k as f64;
    let z = x / nu;
    let q = (1.0 + z * z).sqrt();
    let t = 1.0 / q;
    let eta = q + (z / (1.0 + q)).ln();
    let t2 = t * t;
    let u = [
        1.0,
        t * (3.0 - 5.0 * t2) / 24.0,
        t2 * (81.0 - 462.0 * t2 + 385.0 * t2 * t2) / 1152.0,
        t * t2 * (30375.0 - 369603.0 * t2 + 765765.0 * t2 * t2 - 425425.0 * t2 * t2 * t2)
            / 414720.0,
        t2 * t2
            * (4465125.0 - 94121676.0 * t2 + 349922430.0 * t2 * t2 - 446185740.0 * t2 * t2 * t2
                + 185910725.0 * t2 * t2 * t2 * t2)
            / 39813120.0,
    ];
    let v = [
        1.0,
        t * (-9.0 + 7.0 * t2) / 24.0,
        t2 * (-135.0 + 594.0 * t2 - 455.0 * t2 * t2) / 1152.0,
        t * t2 * (-42525.0 + 451737.0 * t2 - 883575.0 * t2 * t2 + 475475.0 * t2 * t2 * t2)
            / 414720.0,
        t2 * t2
            * (-4343625.0 + 91020375.0 * t2 - 337334338.0 * t2 * t2 + 429585840.0 * t2 * t2 * t2
                - 178738975.0 * t2 * t2 * t2 * t2)
            / 39813120.0,
    ];
    let sign: f64 = if second_kind { -1.0 } else { 1.0 };
    let series = |c: &[f64; 5]| {
        let mut s = 0.0;
        for (j, cj) in c.iter().enumerate().rev() {
            s += sign.powi(j as i32) * cj / nu.powi(j as i32);
        }
        s
    };
    let exponent = sign * nu * eta - 0.25 * (1.0 + z * z).ln();
    (exponent, series(&u), series(&v))
}
