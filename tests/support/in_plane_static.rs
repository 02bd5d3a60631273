//! Exact static in-plane (plane-stress) displacement of an annulus under a
//! uniform load on an annular-sector patch, read as the mean over another
//! patch — written for the tests, sharing no numerics with the library (no
//! B-splines, no modes): per harmonic k the closed-form static solutions, a
//! radial line load matched at its radius, integrated over the two patches
//! by Gauss–Legendre (the patches and quadrature pieces of
//! `mindlin_static.rs`).
//!
//! Per harmonic (cos partner u_r = U cos kθ, u_θ = V sin kθ) with Ē' = Ēh,
//! G' = Gh, γ = G/Ē = (1 − ν)/2 the resultants are
//!   N_r = Ē' (U' + ν (U + kV)/r),  N_θ = Ē' ((U + kV)/r + ν U'),
//!   N_rθ = G' (V' − V/r − kU/r),
//! and equilibrium without load is
//!   (r N_r)' − N_θ + k N_rθ = 0,  (r N_rθ)' + N_rθ − k N_θ = 0.
//! U = a rⁿ, V = b rⁿ solves them when
//!   [n² − 1 − γk²] a + k [nν − 1 + γ(n − 1)] b = 0,
//!   −k [γ(n + 1) + 1 + νn] a + [γ(n² − 1) − k²] b = 0,
//! whose determinant vanishes at n = ±k ± 1. k ≥ 2: the four powers, each
//! with its null vector (a, b). k = 1: n = 2, −2, the rigid translation
//! (U, V) = (1, −1) at the double root n = 0 and its partner
//! U = ln r + t, V = −ln r, t = −(ν + γ)/(1 + γ) (substituted: the ln r
//! terms cancel and the constants give t). k = 0: U ∈ {r, 1/r} (radial),
//! V ∈ {r, 1/r} (torsional), V = r the rigid rotation.
//!
//! A line load of unit intensity (N/m per unit of the harmonic: radial
//! cos kθ or tangential sin kθ) at r = s: U, V continuous, N_r (radial) or
//! N_rθ (tangential) jumps by −1; edges fixed U = V = 0, free
//! N_r = N_rθ = 0. Eight unknowns per (k, s, component). Growing powers are
//! anchored at the segment's outer end, decaying ones at its inner end, so
//! nothing overflows.
//!
//! A force F spread per unit area over patch b has the harmonic load
//! F sinc(kβ_b)/(c_k S_b) on [b₀, b₁] (S = (b₁² − b₀²)/2); the mean of a
//! displacement component over patch a is, per harmonic,
//!   sinc(kβ_a) sinc(kβ_b)/(c_k S_a S_b) ∫_b ds ∫_a r G_k(r, s) dr.
#![allow(dead_code)]

use super::in_plane_exact::Edge;
use super::mindlin_static::{pieces, Patch};
use super::static_plate::{gauss_legendre, solve_refined};
use std::f64::consts::PI;

/// An annulus in plane-stress statics.
#[derive(Debug, Clone, Copy)]
pub struct InPlaneStatic {
    pub ri: f64,
    pub ra: f64,
    pub nu: f64,
    /// Ē h, N/m.
    pub eh: f64,
    /// G h, N/m.
    pub gh: f64,
    pub inner: Edge,
    pub outer: Edge,
}

/// U, U', V, V' of one homogeneous solution at r.
type Shape = [f64; 4];

impl InPlaneStatic {
    pub fn new(e: f64, nu: f64, h: f64, ri: f64, ra: f64, inner: Edge, outer: Edge) -> Self {
        InPlaneStatic {
            ri,
            ra,
            nu,
            eh: e * h / (1.0 - nu * nu),
            gh: e * h / (2.0 * (1.0 + nu)),
            inner,
            outer,
        }
    }

    fn gamma(&self) -> f64 {
        0.5 * (1.0 - self.nu)
    }

    /// The null vector (a, b) of the power n for k, max(|a|, |b|) = 1; the
    /// other equation's residual is asserted to vanish.
    fn null_vector(&self, k: f64, n: f64) -> (f64, f64) {
        let (g, nu) = (self.gamma(), self.nu);
        let m = [
            [n * n - 1.0 - g * k * k, k * (n * nu - 1.0 + g * (n - 1.0))],
            [
                -k * (g * (n + 1.0) + 1.0 + nu * n),
                g * (n * n - 1.0) - k * k,
            ],
        ];
        let norm = |row: [f64; 2]| row[0].abs().max(row[1].abs());
        let (use_row, other) = if norm(m[0]) >= norm(m[1]) {
            (m[0], m[1])
        } else {
            (m[1], m[0])
        };
        let (a, b) = (use_row[1], -use_row[0]);
        let scale = a.abs().max(b.abs());
        let (a, b) = (a / scale, b / scale);
        let residual = (other[0] * a + other[1] * b).abs();
        assert!(
            residual <= 1e-12 * norm(other).max(1.0),
            "n = {n} is no root for k = {k}"
        );
        (a, b)
    }

    /// The four homogeneous solutions of segment [lo, hi] at r.
    fn shapes(&self, k: u32, lo: f64, hi: f64, r: f64) -> [Shape; 4] {
        let kf = k as f64;
        let power = |n: f64, anchor: f64, (a, b): (f64, f64)| -> Shape {
            let p = (r / anchor).powf(n);
            [a * p, a * n * p / r, b * p, b * n * p / r]
        };
        match k {
            0 => [
                power(1.0, hi, (1.0, 0.0)),
                power(-1.0, lo, (1.0, 0.0)),
                power(1.0, hi, (0.0, 1.0)),
                power(-1.0, lo, (0.0, 1.0)),
            ],
            1 => {
                let g = self.gamma();
                let t = -(self.nu + g) / (1.0 + g);
                let l = (r / hi).ln();
                [
                    power(2.0, hi, self.null_vector(kf, 2.0)),
                    power(-2.0, lo, self.null_vector(kf, -2.0)),
                    [1.0, 0.0, -1.0, 0.0],
                    [l + t, 1.0 / r, -l, -1.0 / r],
                ]
            }
            _ => [
                power(kf + 1.0, hi, self.null_vector(kf, kf + 1.0)),
                power(kf - 1.0, hi, self.null_vector(kf, kf - 1.0)),
                power(1.0 - kf, lo, self.null_vector(kf, 1.0 - kf)),
                power(-1.0 - kf, lo, self.null_vector(kf, -1.0 - kf)),
            ],
        }
    }

    /// [U, V, N_r, N_rθ] of the four solutions of segment [lo, hi] at r.
    fn fields(&self, k: u32, lo: f64, hi: f64, r: f64) -> [[f64; 4]; 4] {
        let kf = k as f64;
        self.shapes(k, lo, hi, r).map(|[u, u1, v, v1]| {
            [
                u,
                v,
                self.eh * (u1 + self.nu * (u + kf * v) / r),
                self.gh * (v1 - v / r - kf * u / r),
            ]
        })
    }

    /// The line-load solution of harmonic k at radius s for a unit load on
    /// `component` (0: radial, 1: tangential): the coefficients of segment
    /// [r_i, s] then [s, r_a], and the solve's backward error.
    pub fn line_load(&self, k: u32, s: f64, component: usize) -> ([f64; 8], f64) {
        let rows = |edge: Edge| -> [usize; 2] {
            match edge {
                Edge::Fixed => [0, 1],
                Edge::Free => [2, 3],
            }
        };
        let mut m = [[0.0; 8]; 8];
        let mut rhs = [0.0; 8];
        let fi = self.fields(k, self.ri, s, self.ri);
        let f1 = self.fields(k, self.ri, s, s);
        let f2 = self.fields(k, s, self.ra, s);
        let fa = self.fields(k, s, self.ra, self.ra);
        for (row, &q) in rows(self.inner).iter().enumerate() {
            for j in 0..4 {
                m[row][j] = fi[j][q];
            }
        }
        for q in 0..4 {
            for j in 0..4 {
                m[2 + q][j] = -f1[j][q];
                m[2 + q][4 + j] = f2[j][q];
            }
        }
        rhs[4 + component] = -1.0;
        for (row, &q) in rows(self.outer).iter().enumerate() {
            for j in 0..4 {
                m[6 + row][4 + j] = fa[j][q];
            }
        }
        solve_refined(&m, &rhs)
    }

    /// [∫_a r U dr, ∫_a r V dr] of the line-load solution at s.
    fn read_integral(&self, k: u32, s: f64, c: &[f64; 8], a: &Patch) -> [f64; 2] {
        let scale = s / (k as f64 + 1.0);
        let mut out = [0.0; 2];
        for (r, w) in pieces(a.lo, a.hi, &[s, a.lo, a.hi], scale) {
            let (seg, lo, hi) = if r <= s {
                (0, self.ri, s)
            } else {
                (1, s, self.ra)
            };
            let shapes = self.shapes(k, lo, hi, r);
            for (j, sh) in shapes.iter().enumerate() {
                out[0] += w * r * c[4 * seg + j] * sh[0];
                out[1] += w * r * c[4 * seg + j] * sh[2];
            }
        }
        out
    }

    /// The harmonic k between the load patch and each read patch as
    /// [UU, UV, VU, VV] (first letter the displacement read, second the load
    /// component; sincs and c_k included), m/N, and the worst backward error.
    pub fn harmonic(&self, k: u32, load: &Patch, reads: &[Patch]) -> (Vec<[f64; 4]>, f64) {
        let ck = if k == 0 { 2.0 * PI } else { PI };
        let scale = 0.5 * (load.lo + load.hi) / (k as f64 + 1.0);
        let mut targets = vec![load.lo, load.hi];
        for a in reads {
            targets.extend([a.lo, a.hi]);
        }
        let mut sums = vec![[0.0; 4]; reads.len()];
        let mut worst: f64 = 0.0;
        for (s, ws) in pieces(load.lo, load.hi, &targets, scale) {
            for component in 0..2 {
                let (c, be) = self.line_load(k, s, component);
                worst = worst.max(be);
                for (sum, a) in sums.iter_mut().zip(reads) {
                    let [u, v] = self.read_integral(k, s, &c, a);
                    sum[component] += ws * u;
                    sum[2 + component] += ws * v;
                }
            }
        }
        let terms = sums
            .iter()
            .zip(reads)
            .map(|(v, a)| {
                let f = load.sinc(k) * a.sinc(k) / (ck * load.area_factor() * a.area_factor());
                v.map(|x| x * f)
            })
            .collect();
        (terms, worst)
    }

    /// The 2 × 2 patch compliances (row: ū_r, ū_θ at the read patch; column:
    /// F_r, F_θ on the load patch) for each (read patch, Δθ = θ_read −
    /// θ_load), summed over k to the first k ≥ 8 where every diagonal term's
    /// envelope times k/3 (the terms fall like k⁻⁴) is below `tol` of the
    /// largest diagonal sum, at most `k_max`; returns the sums, the harmonics
    /// used and the worst backward error.
    pub fn series(
        &self,
        load: &Patch,
        reads: &[(Patch, f64)],
        tol: f64,
        k_max: u32,
    ) -> (Vec<[[f64; 2]; 2]>, u32, f64) {
        let patches: Vec<Patch> = reads.iter().map(|r| r.0).collect();
        let mut sums = vec![[[0.0; 2]; 2]; reads.len()];
        let mut worst: f64 = 0.0;
        for k in 0..=k_max {
            let (terms, be) = self.harmonic(k, load, &patches);
            worst = worst.max(be);
            let mut bound: f64 = 0.0;
            for ((sum, t), (a, delta)) in sums.iter_mut().zip(&terms).zip(reads) {
                let (s, c) = (k as f64 * delta).sin_cos();
                sum[0][0] += t[0] * c;
                sum[0][1] -= t[1] * s;
                sum[1][0] += t[2] * s;
                sum[1][1] += t[3] * c;
                let envelope = |p: &Patch| (1.0 / (k as f64 * p.beta)).min(1.0);
                let sincs = (a.sinc(k).abs() * load.sinc(k).abs()).max(1e-300);
                let raw = t[0].abs().max(t[3].abs()) / sincs;
                bound = bound.max(raw * envelope(a) * envelope(load));
            }
            let largest = sums
                .iter()
                .fold(0.0_f64, |m, v| m.max(v[0][0].abs()).max(v[1][1].abs()));
            if k >= 8 && (k as f64 / 3.0) * bound < tol * largest {
                return (sums, k, worst);
            }
        }
        (sums, k_max, worst)
    }
}

/// The torsion of an annulus with its hub fixed (u = 0 at r_i) and its rim
/// free under a uniform circumferential load on the ring [lo, hi] of total
/// torque `torque`: the mean of u_θ over the ring (weight r dr), m. With
/// V = r φ and σ_rθ = G r φ', the torque carried through the circle r is
/// 2π r² h σ_rθ: T for r ≤ lo, T (hi³ − r³)/(hi³ − lo³) inside the ring.
pub fn torsion_ring_mean(ri: f64, g: f64, h: f64, lo: f64, hi: f64, torque: f64) -> f64 {
    let a = torque / (4.0 * PI * g * h);
    let phi_lo = a * (1.0 / (ri * ri) - 1.0 / (lo * lo));
    let b = torque / (2.0 * PI * g * h * (hi.powi(3) - lo.powi(3)));
    let phi =
        |r: f64| phi_lo + b * (0.5 * hi.powi(3) * (1.0 / (lo * lo) - 1.0 / (r * r)) - (r - lo));
    let (x, w) = gauss_legendre(16);
    let (mid, half) = (0.5 * (lo + hi), 0.5 * (hi - lo));
    let integral: f64 = x
        .iter()
        .zip(&w)
        .map(|(xi, wi)| {
            let r = mid + half * xi;
            half * wi * r * r * phi(r)
        })
        .sum();
    integral / (0.5 * (hi * hi - lo * lo))
}

/// The rim twist φ(r_a) = T/(4πGh) (1/r_i² − 1/r_a²) of the same disc under
/// a torque T on its rim line.
pub fn torsion_rim_twist(ri: f64, ra: f64, g: f64, h: f64, torque: f64) -> f64 {
    torque / (4.0 * PI * g * h) * (1.0 / (ri * ri) - 1.0 / (ra * ra))
}
