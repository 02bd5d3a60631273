//! Exact static deflection of an annular Kirchhoff plate under a transverse
//! point force, written independently of the library's numerics (no B-splines,
//! no eigenmodes: the Fourier series in θ of the closed-form ODE solutions).
//!
//! `D ∇⁴w = p` on `r_i < r < r_a`, a force `P` (N, +z) at `(r₀, θ₀)`:
//! `p = P δ(r − r₀) δ(θ − θ₀) / r`. With `w = Σ_k W_k(r) cos k(θ − θ₀)` and
//! `δ(θ − θ₀) = 1/(2π) + (1/π) Σ_{k≥1} cos k(θ − θ₀)` the k-th load coefficient is
//! `p_k = P δ(r − r₀) / (c_k r₀)`, `c_0 = 2π`, `c_k = π` (k ≥ 1), and
//!
//! ```text
//! D L_k² W_k = p_k,     L_k = d²/dr² + (1/r) d/dr − k²/r².
//! ```
//!
//! Away from r₀, `L_k² W = 0` is an Euler equation with the solutions
//! `r^k, r^{k+2}, r^{−k}, r^{2−k}` (k ≥ 2), `r, r³, r⁻¹, r ln r` (k = 1),
//! `1, r², ln r, r² ln r` (k = 0). `L_k² W = W'''' + (lower derivatives)`, so
//! integrating across r₀: `W, W', W''` are continuous and
//! `D [W''']_{r₀⁻}^{r₀⁺} = P / (c_k r₀)`.
//!
//! Edge quantities (Leissa, NASA SP-160; the natural conditions of the energy
//! in DESIGN.md, checked below by Clapeyron's theorem `U_k = ½ P W_k(r₀)`):
//! `M_r = −D [W'' + ν (W'/r − k² W/r²)]`,
//! `V_r = Q_r + (1/r) ∂M_rθ/∂θ = −D [W''' + W''/r − W'/r² + k² ((3 − ν) W/r³ − (2 − ν) W'/r²)]`.
//! Clamped `W = W' = 0`; supported `W = M_r = 0`; free `M_r = V_r = 0`.
//! A force on an edge (r₀ = r_i or r_a) is the limit of an interior one: the
//! segment beyond it has zero length, and the jump condition turns into the
//! edge shear condition `V_r = P/(c_k r₀)` automatically.
//!
//! Per k: 8 unknowns (4 per segment `[r_i, r₀]`, `[r₀, r_a]`), 8 equations
//! (2 edge conditions at each edge, 4 matching conditions at r₀), solved by
//! Gaussian elimination with partial pivoting on the row- and column-equilibrated
//! matrix plus one step of iterative refinement; the normwise backward error of
//! the equilibrated system is returned. For k ≥ 2 the basis on each segment is anchored where it
//! is largest, `(r/c)^{±k}` and `(r/c)^{±k} ((r/c)² − 1)` (the second is
//! `r^{±k+2}` minus a multiple of the first), so nothing overflows, and the two
//! functions of one pair are not nearly parallel near the anchor even for
//! k in the thousands.
//!
//! The deflection under the load is `Σ_k W_k(r₀)`; the terms decay like k⁻³
//! (the load point singularity `ρ² ln ρ`), so [`StaticAnnulus::series`] sums
//! directly up to a K and adds a fitted `A k⁻³ + B k⁻⁴` tail.

#![allow(dead_code)]

use super::exact_plate::Edge;
use std::f64::consts::PI;

/// Geometry, ν, bending rigidity D and edge conditions.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StaticAnnulus {
    pub inner_radius: f64,
    pub outer_radius: f64,
    pub poisson_ratio: f64,
    /// D = E h³ / (12 (1 − ν²)), N·m.
    pub rigidity: f64,
    pub inner: Edge,
    pub outer: Edge,
}

/// One solved harmonic: `W_k(r)` for the force `P` at radius `r0`.
#[derive(Debug, Clone)]
pub struct Harmonic {
    pub k: u32,
    pub r0: f64,
    annulus: StaticAnnulus,
    /// Coefficients of segment 1 `[r_i, r0]` then segment 2 `[r0, r_a]`.
    coefficients: [f64; 8],
    /// The force P, N.
    pub force: f64,
    /// Normwise backward error of the equilibrated 8×8 solve (after refinement).
    pub backward_error: f64,
}

/// A converged Fourier series of the deflection at one point.
#[derive(Debug, Clone)]
pub struct Series {
    /// Number of harmonics summed directly (k = 0..=k_direct).
    pub k_direct: u32,
    /// Σ_{k ≤ k_direct} W_k(r) cos k(θ − θ₀).
    pub direct: f64,
    /// Fitted tail Σ_{k > k_direct} (A k⁻³ + B k⁻⁴) (only meaningful where the
    /// terms are single-signed; the deflection under the load is).
    pub tail: f64,
    /// (A, B) of the tail fit.
    pub tail_fit: (f64, f64),
    /// Largest backward error of the per-k solves.
    pub worst_backward_error: f64,
    /// Every term W_k(r) cos k(θ − θ₀), k = 0..=k_direct.
    pub terms: Vec<f64>,
}

impl Series {
    pub fn value(&self) -> f64 {
        self.direct + self.tail
    }
    /// Partial sum over k ≤ kmax (no tail).
    pub fn partial(&self, kmax: u32) -> f64 {
        self.terms[..=(kmax as usize).min(self.terms.len() - 1)]
            .iter()
            .sum()
    }
}

/// `[f, f', f'', f''']` of `(r/c)^p`.
pub fn power(p: f64, r: f64, c: f64) -> [f64; 4] {
    let u = (r / c).powf(p);
    [
        u,
        p * u / r,
        p * (p - 1.0) * u / (r * r),
        p * (p - 1.0) * (p - 2.0) * u / (r * r * r),
    ]
}

/// `[f, f', f'', f''']` of `(r/c)^p ((r/c)² − 1)` by Leibniz' rule.
pub fn power_pair(p: f64, r: f64, c: f64) -> [f64; 4] {
    let g = power(p, r, c);
    let v = [
        (r - c) * (r + c) / (c * c),
        2.0 * r / (c * c),
        2.0 / (c * c),
        0.0,
    ];
    [
        g[0] * v[0],
        g[1] * v[0] + g[0] * v[1],
        g[2] * v[0] + 2.0 * g[1] * v[1] + g[0] * v[2],
        g[3] * v[0] + 3.0 * g[2] * v[1] + 3.0 * g[1] * v[2] + g[0] * v[3],
    ]
}

impl StaticAnnulus {
    pub fn new(
        inner_radius: f64,
        outer_radius: f64,
        poisson_ratio: f64,
        rigidity: f64,
        inner: Edge,
        outer: Edge,
    ) -> Self {
        assert!(0.0 < inner_radius && inner_radius < outer_radius);
        assert!(
            !(inner == Edge::Free && outer == Edge::Free),
            "a free–free annulus has rigid-body motions: no static solution"
        );
        StaticAnnulus {
            inner_radius,
            outer_radius,
            poisson_ratio,
            rigidity,
            inner,
            outer,
        }
    }

    /// The four homogeneous solutions of harmonic k on segment `seg` (0: `[r_i, r0]`,
    /// 1: `[r0, r_a]`), each as `[f, f', f'', f''']` at r.
    fn basis(&self, k: u32, seg: usize, r0: f64, r: f64) -> [[f64; 4]; 4] {
        let (ri, ra) = (self.inner_radius, self.outer_radius);
        let l = ra;
        let x = r / l;
        let lnx = x.ln();
        match k {
            0 => [
                [1.0, 0.0, 0.0, 0.0],
                [lnx, 1.0 / r, -1.0 / (r * r), 2.0 / (r * r * r)],
                [x * x, 2.0 * x / l, 2.0 / (l * l), 0.0],
                [
                    x * x * lnx,
                    (2.0 * x * lnx + x) / l,
                    (2.0 * lnx + 3.0) / (l * l),
                    2.0 / (x * l * l * l),
                ],
            ],
            1 => [
                [x, 1.0 / l, 0.0, 0.0],
                [
                    1.0 / x,
                    -l / (r * r),
                    2.0 * l / (r * r * r),
                    -6.0 * l / (r * r * r * r),
                ],
                [
                    x * x * x,
                    3.0 * x * x / l,
                    6.0 * x / (l * l),
                    6.0 / (l * l * l),
                ],
                [
                    x * lnx,
                    (lnx + 1.0) / l,
                    1.0 / (x * l * l),
                    -1.0 / (x * x * l * l * l),
                ],
            ],
            _ => {
                let p = k as f64;
                // growing pair anchored at the segment's right end, decaying pair at its left end
                let (left, right) = if seg == 0 { (ri, r0) } else { (r0, ra) };
                [
                    power(p, r, right),
                    power_pair(p, r, right),
                    power(-p, r, left),
                    power_pair(-p, r, left),
                ]
            }
        }
    }

    /// Edge quantity rows for an edge condition at radius r (the −D factors dropped).
    fn edge_rows(&self, edge: Edge, k: u32, r: f64, f: &[[f64; 4]; 4]) -> [[f64; 4]; 2] {
        let nu = self.poisson_ratio;
        let kk = (k as f64) * (k as f64);
        let deflection = |d: &[f64; 4]| d[0];
        let slope = |d: &[f64; 4]| d[1];
        let moment = |d: &[f64; 4]| d[2] + nu * (d[1] / r - kk * d[0] / (r * r));
        let shear = |d: &[f64; 4]| {
            d[3] + d[2] / r - d[1] / (r * r)
                + kk * ((3.0 - nu) * d[0] / (r * r * r) - (2.0 - nu) * d[1] / (r * r))
        };
        let row = |q: &dyn Fn(&[f64; 4]) -> f64| [q(&f[0]), q(&f[1]), q(&f[2]), q(&f[3])];
        match edge {
            Edge::Clamped => [row(&deflection), row(&slope)],
            Edge::Supported => [row(&deflection), row(&moment)],
            Edge::Free => [row(&moment), row(&shear)],
        }
    }

    /// `M_r / (−D)` and `V_r / (−D)` of a derivative vector at r (for residual checks).
    pub fn moment_and_shear(&self, k: u32, r: f64, d: &[f64; 4]) -> (f64, f64) {
        let nu = self.poisson_ratio;
        let kk = (k as f64) * (k as f64);
        let m = d[2] + nu * (d[1] / r - kk * d[0] / (r * r));
        let v = d[3] + d[2] / r - d[1] / (r * r)
            + kk * ((3.0 - nu) * d[0] / (r * r * r) - (2.0 - nu) * d[1] / (r * r));
        (m, v)
    }

    /// The k-th harmonic for a force `p` (N, +z) at radius `r0`.
    pub fn harmonic(&self, k: u32, r0: f64, p: f64) -> Harmonic {
        let (ri, ra) = (self.inner_radius, self.outer_radius);
        assert!(
            ri <= r0 && r0 <= ra,
            "load radius {r0} outside [{ri}, {ra}]"
        );
        let ck = if k == 0 { 2.0 * PI } else { PI };
        let mut a = [[0.0; 8]; 8];
        let mut b = [0.0; 8];
        let fi = self.basis(k, 0, r0, ri);
        let f1 = self.basis(k, 0, r0, r0);
        let f2 = self.basis(k, 1, r0, r0);
        let fa = self.basis(k, 1, r0, ra);
        for (row, vals) in self.edge_rows(self.inner, k, ri, &fi).iter().enumerate() {
            a[row][..4].copy_from_slice(vals);
        }
        for n in 0..4 {
            for j in 0..4 {
                a[2 + n][j] = -f1[j][n];
                a[2 + n][4 + j] = f2[j][n];
            }
        }
        b[5] = p / (self.rigidity * ck * r0);
        for (row, vals) in self.edge_rows(self.outer, k, ra, &fa).iter().enumerate() {
            a[6 + row][4..].copy_from_slice(vals);
        }
        let (coefficients, backward_error) = solve_refined(&a, &b);
        Harmonic {
            k,
            r0,
            annulus: *self,
            coefficients,
            force: p,
            backward_error,
        }
    }

    /// `Σ_k W_k(r) cos k(θ − θ₀)` for k = 0..=k_direct plus a fitted tail.
    /// The tail fits `A k⁻³ + B k⁻⁴` to the terms at k_direct/2 and k_direct.
    pub fn series(&self, r0: f64, p: f64, r: f64, dtheta: f64, k_direct: u32) -> Series {
        assert!(k_direct >= 8);
        let mut terms = Vec::with_capacity(k_direct as usize + 1);
        let mut worst: f64 = 0.0;
        for k in 0..=k_direct {
            let h = self.harmonic(k, r0, p);
            worst = worst.max(h.backward_error);
            terms.push(h.eval(r)[0] * (k as f64 * dtheta).cos());
        }
        let direct: f64 = terms.iter().sum();
        // A k⁻³ + B k⁻⁴ through (k1, t1), (k2, t2)
        let (k1, k2) = ((k_direct / 2) as f64, k_direct as f64);
        let (t1, t2) = (terms[(k_direct / 2) as usize], terms[k_direct as usize]);
        // t k³ = A + B/k
        let (y1, y2) = (t1 * k1.powi(3), t2 * k2.powi(3));
        let bb = (y1 - y2) / (1.0 / k1 - 1.0 / k2);
        let aa = y2 - bb / k2;
        let n = k2 + 1.0;
        let tail = aa * hurwitz_zeta(3.0, n) + bb * hurwitz_zeta(4.0, n);
        Series {
            k_direct,
            direct,
            tail,
            tail_fit: (aa, bb),
            worst_backward_error: worst,
            terms,
        }
    }

    /// Axisymmetric ring load (total force `p`, +z, spread evenly over the circle r0):
    /// a second, independent derivation by direct integration, for r0 = r_a and a
    /// free outer edge (the edge shear carries the load: `D r F' = −p/(2π)` on the
    /// whole annulus, F = ∇²W). Returns W(r).
    ///
    /// `D (1/r)(r F')' = 0` ⇒ `D r F' = C₁ = −p/(2π)` (free edge loaded by p/(2π r_a) per length),
    /// `F = (C₁/D) ln r + C₂`, `(r W')' = r F` ⇒
    /// `W' = (C₁/D)(r ln r /2 − r/4) + C₂ r/2 + C₃/r`,
    /// `W = (C₁/D)(r² ln r/4 − r²/4) + C₂ r²/4 + C₃ ln r + C₄`;
    /// C₂, C₃, C₄ from the inner edge conditions and `M_r(r_a) = 0`.
    pub fn ring_load_at_free_edge_by_integration(&self, p: f64, r: f64) -> f64 {
        assert_eq!(self.outer, Edge::Free);
        let (ri, ra, nu, d) = (
            self.inner_radius,
            self.outer_radius,
            self.poisson_ratio,
            self.rigidity,
        );
        let c1 = -p / (2.0 * PI) / d;
        // particular part (C₂ = C₃ = C₄ = 0) and the three basis functions, each [W, W', W'']
        let part = |r: f64| {
            let l = r.ln();
            [
                c1 * (r * r * l / 4.0 - r * r / 4.0),
                c1 * (r * l / 2.0 - r / 4.0),
                c1 * (l / 2.0 + 0.25),
            ]
        };
        let b2 = |r: f64| [r * r / 4.0, r / 2.0, 0.5];
        let b3 = |r: f64| [r.ln(), 1.0 / r, -1.0 / (r * r)];
        let b4 = |_r: f64| [1.0, 0.0, 0.0];
        let moment = |v: [f64; 3], r: f64| v[2] + nu * v[1] / r;
        assert!(
            self.inner != Edge::Free,
            "an edge ring load on a free–free annulus is not in equilibrium"
        );
        let inner_rows = |f: &dyn Fn(f64) -> [f64; 3]| -> [f64; 2] {
            let v = f(ri);
            match self.inner {
                Edge::Clamped => [v[0], v[1]],
                Edge::Supported => [v[0], moment(v, ri)],
                Edge::Free => unreachable!(),
            }
        };
        let fs: [&dyn Fn(f64) -> [f64; 3]; 3] = [&b2, &b3, &b4];
        let mut m = [[0.0; 3]; 3];
        let mut rhs = [0.0; 3];
        let ip = inner_rows(&part);
        for (j, f) in fs.iter().enumerate() {
            let rows = inner_rows(*f);
            m[0][j] = rows[0];
            m[1][j] = rows[1];
            m[2][j] = moment(f(ra), ra);
        }
        rhs[0] = -ip[0];
        rhs[1] = -ip[1];
        rhs[2] = -moment(part(ra), ra);
        let c = solve3(m, rhs);
        let pv = part(r);
        pv[0] + c[0] * b2(r)[0] + c[1] * b3(r)[0] + c[2] * b4(r)[0]
    }

    /// Roark's Formulas for Stress and Strain (Table 11.2, case 1: uniform annular
    /// line load w at r_o; general expressions with the plate constants C and the
    /// radial-location functions F, L), for a free outer edge:
    ///
    /// * 1L, inner edge fixed: `y_b = θ_b = 0`, `Q_b = w r_o/b`, `M_ra = 0` ⇒
    ///   `M_rb = −(w a/C₈)(r_o C₉/b − L₉)`;
    /// * 1k, inner edge simply supported: `y_b = M_rb = 0`, `Q_b = w r_o/b`, `M_ra = 0` ⇒
    ///   `θ_b = −(w a²/(D C₇))(r_o C₉/b − L₉)`;
    ///
    /// then `y(r) = y_b + θ_b r F₁ + M_rb r² F₂/D + Q_b r³ F₃/D − w r³ G₃/D`
    /// (`G₃ = 0` for r ≤ r_o). Roark's y is upward, the load w downward; b = r_i,
    /// a = r_a, `C_j = F_j(a)`, `L₉ = (r_o/a){(1+ν)/2 ln(a/r_o) + (1−ν)/4 [1 − (r_o/a)²]}`.
    /// The F functions as tabulated for Table 11.2 (Roark, 7th ed.; also reproduced on
    /// eng-calculations.com's Roark pages). Returns our w(r) (upward) for a total
    /// upward force `p` on the ring r_o, r ≤ r_o.
    pub fn roark_ring_load_free_outer(&self, p: f64, ro: f64, r: f64) -> f64 {
        assert_eq!(self.outer, Edge::Free);
        assert!(r <= ro);
        let (b, a, nu, d) = (
            self.inner_radius,
            self.outer_radius,
            self.poisson_ratio,
            self.rigidity,
        );
        // Roark's load per unit length, downward: an upward p is w = −p/(2π r_o).
        let w = -p / (2.0 * PI * ro);
        let f1 =
            |r: f64| (1.0 + nu) / 2.0 * b / r * (r / b).ln() + (1.0 - nu) / 4.0 * (r / b - b / r);
        let f2 = |r: f64| 0.25 * (1.0 - (b / r).powi(2) * (1.0 + 2.0 * (r / b).ln()));
        let f3 = |r: f64| {
            b / (4.0 * r) * (((b / r).powi(2) + 1.0) * (r / b).ln() + (b / r).powi(2) - 1.0)
        };
        let f7 = |r: f64| 0.5 * (1.0 - nu * nu) * (r / b - b / r);
        let f8 = |r: f64| 0.5 * (1.0 + nu + (1.0 - nu) * (b / r).powi(2));
        let f9 = |r: f64| {
            b / r * ((1.0 + nu) / 2.0 * (r / b).ln() + (1.0 - nu) / 4.0 * (1.0 - (b / r).powi(2)))
        };
        let l9 = ro / a
            * ((1.0 + nu) / 2.0 * (a / ro).ln() + (1.0 - nu) / 4.0 * (1.0 - (ro / a).powi(2)));
        let (c7, c8, c9) = (f7(a), f8(a), f9(a));
        let qb = w * ro / b;
        let y = match self.inner {
            Edge::Clamped => {
                let mrb = -w * a / c8 * (ro * c9 / b - l9);
                mrb * r * r * f2(r) / d + qb * r.powi(3) * f3(r) / d
            }
            Edge::Supported => {
                let theta_b = -w * a * a / (d * c7) * (ro * c9 / b - l9);
                theta_b * r * f1(r) + qb * r.powi(3) * f3(r) / d
            }
            Edge::Free => panic!("free–free: no static solution"),
        };
        y
    }
}

impl Harmonic {
    /// `[W, W', W'', W''']` at r (segment 1 for r ≤ r0, segment 2 beyond).
    pub fn eval(&self, r: f64) -> [f64; 4] {
        self.eval_segment(if r <= self.r0 { 0 } else { 1 }, r)
    }

    pub fn eval_segment(&self, seg: usize, r: f64) -> [f64; 4] {
        let f = self.annulus.basis(self.k, seg, self.r0, r);
        let c = &self.coefficients[4 * seg..4 * seg + 4];
        let mut out = [0.0; 4];
        for j in 0..4 {
            for n in 0..4 {
                out[n] += c[j] * f[j][n];
            }
        }
        out
    }

    /// W_k under the load.
    pub fn at_load(&self) -> f64 {
        self.eval_segment(0, self.r0)[0]
    }

    /// Residuals of the conditions:
    /// `[inner edge (2), continuity of W, W', W'' (3), jump of W''' (1), outer edge (2)]`.
    /// Each is relative to the size its terms have where the solution is largest
    /// (at the load): `|W|`, `(k + 1)|W|/r` for slopes, and the sums of the moduli of
    /// the terms of M_r and V_r there. (Relative to the terms at a far edge, where a
    /// high harmonic has decayed to 1e-300, a residual would only measure underflow.)
    pub fn condition_residuals(&self) -> [f64; 8] {
        let s = &self.annulus;
        let (ri, ra, r0, k) = (s.inner_radius, s.outer_radius, self.r0, self.k);
        let kk = (k as f64) * (k as f64);
        let scale_m =
            |r: f64, d: &[f64; 4]| d[2].abs() + (d[1] / r).abs() + (kk * d[0] / (r * r)).abs();
        let scale_v = |r: f64, d: &[f64; 4]| {
            d[3].abs()
                + (d[2] / r).abs()
                + (d[1] / (r * r)).abs()
                + kk * (3.0 * (d[0] / (r * r * r)).abs() + 2.0 * (d[1] / (r * r)).abs())
        };
        let d1 = self.eval_segment(0, r0);
        let d2 = self.eval_segment(1, r0);
        let w_scale = d1[0].abs().max(d2[0].abs());
        let slope_scale = d1[1]
            .abs()
            .max(d2[1].abs())
            .max((k as f64 + 1.0) * w_scale / r0);
        let curvature_scale = d1[2]
            .abs()
            .max(d2[2].abs())
            .max((kk + 1.0) * w_scale / (r0 * r0));
        let m_scale = scale_m(r0, &d1).max(scale_m(r0, &d2));
        let v_scale = scale_v(r0, &d1).max(scale_v(r0, &d2));
        let edge_residuals = |edge: Edge, r: f64, d: &[f64; 4]| -> [f64; 2] {
            let (m, v) = s.moment_and_shear(k, r, d);
            let m_rel = m.abs() / m_scale.max(scale_m(r, d));
            let v_rel = v.abs() / v_scale.max(scale_v(r, d));
            match edge {
                Edge::Clamped => [d[0].abs() / w_scale, d[1].abs() / slope_scale],
                Edge::Supported => [d[0].abs() / w_scale, m_rel],
                Edge::Free => [m_rel, v_rel],
            }
        };
        let inner = edge_residuals(s.inner, ri, &self.eval_segment(0, ri));
        let outer = edge_residuals(s.outer, ra, &self.eval_segment(1, ra));
        let ck = if k == 0 { 2.0 * PI } else { PI };
        let expected = self.force / (s.rigidity * ck * r0);
        [
            inner[0],
            inner[1],
            (d2[0] - d1[0]).abs() / w_scale,
            (d2[1] - d1[1]).abs() / slope_scale,
            (d2[2] - d1[2]).abs() / curvature_scale,
            ((d2[3] - d1[3]) - expected).abs() / expected.abs(),
            outer[0],
            outer[1],
        ]
    }

    /// Strain energy of this harmonic from the energy functional of DESIGN.md,
    /// `U = D/2 c_k ∫ [(W'' + W'/r − k²W/r²)² − 2(1−ν)(W''(W'/r − k²W/r²) − k²(W'/r − W/r²)²)] r dr`,
    /// by 16-point Gauss–Legendre on `pieces` sub-intervals per segment, graded
    /// geometrically towards r0 (where a high harmonic is concentrated).
    /// Clapeyron: `U = ½ P W_k(r0)` exactly when the ODE, the matching and the
    /// edge conditions are the Euler–Lagrange equations of this functional.
    pub fn strain_energy(&self, pieces: usize) -> f64 {
        let s = &self.annulus;
        let (ri, ra, r0, nu) = (s.inner_radius, s.outer_radius, self.r0, s.poisson_ratio);
        let kk = (self.k as f64) * (self.k as f64);
        let ck = if self.k == 0 { 2.0 * PI } else { PI };
        let (gx, gw) = gauss_legendre(16);
        let density = |d: &[f64; 4], r: f64| {
            let (w, w1, w2) = (d[0], d[1], d[2]);
            let t = w1 / r - kk * w / (r * r);
            let lap = w2 + t;
            let twist = w1 / r - w / (r * r);
            (lap * lap - 2.0 * (1.0 - nu) * (w2 * t - kk * twist * twist)) * r
        };
        let mut total = 0.0;
        for seg in 0..2 {
            let (a, b) = if seg == 0 { (ri, r0) } else { (r0, ra) };
            if b <= a {
                continue;
            }
            // piece j spans distances [(b − a) g^{j+1}, (b − a) g^j] from r0; the last reaches r0
            let g: f64 = 0.5;
            let mut dist: Vec<f64> = (0..pieces).map(|j| (b - a) * g.powi(j as i32)).collect();
            dist.push(0.0);
            for j in 0..pieces {
                let (far, near) = (dist[j], dist[j + 1]);
                let (lo, hi) = if seg == 0 {
                    (b - far, b - near)
                } else {
                    (a + near, a + far)
                };
                let (mid, half) = (0.5 * (lo + hi), 0.5 * (hi - lo));
                for (x, wq) in gx.iter().zip(&gw) {
                    let r = mid + half * x;
                    total += wq * half * density(&self.eval_segment(seg, r), r);
                }
            }
        }
        0.5 * s.rigidity * ck * total
    }
}

/// Σ_{k ≥ n} k^{−s} (Euler–Maclaurin, n ≥ 8: error far below 1e-12 relative).
pub fn hurwitz_zeta(s: f64, n: f64) -> f64 {
    n.powf(1.0 - s) / (s - 1.0) + 0.5 * n.powf(-s) + s / 12.0 * n.powf(-s - 1.0)
        - s * (s + 1.0) * (s + 2.0) / 720.0 * n.powf(-s - 3.0)
}

/// Gauss–Legendre nodes and weights on [−1, 1] (Newton on P_n).
pub fn gauss_legendre(n: usize) -> (Vec<f64>, Vec<f64>) {
    let mut x = vec![0.0; n];
    let mut w = vec![0.0; n];
    for i in 0..n {
        let mut z = (PI * (i as f64 + 0.75) / (n as f64 + 0.5)).cos();
        for _ in 0..100 {
            let (mut p0, mut p1) = (1.0, z);
            for j in 2..=n {
                let p2 = ((2 * j - 1) as f64 * z * p1 - (j - 1) as f64 * p0) / j as f64;
                p0 = p1;
                p1 = p2;
            }
            let dp = n as f64 * (z * p1 - p0) / (z * z - 1.0);
            let dz = p1 / dp;
            z -= dz;
            if dz.abs() < 1e-16 {
                let (mut q0, mut q1) = (1.0, z);
                for j in 2..=n {
                    let q2 = ((2 * j - 1) as f64 * z * q1 - (j - 1) as f64 * q0) / j as f64;
                    q0 = q1;
                    q1 = q2;
                }
                let dq = n as f64 * (z * q1 - q0) / (z * z - 1.0);
                x[i] = z;
                w[i] = 2.0 / ((1.0 - z * z) * dq * dq);
                break;
            }
        }
    }
    (x, w)
}

fn solve3(m: [[f64; 3]; 3], b: [f64; 3]) -> [f64; 3] {
    lu_solve(m, b)
}

/// Partial-pivot LU solve of a small dense system.
fn lu_solve<const N: usize>(mut a: [[f64; N]; N], mut b: [f64; N]) -> [f64; N] {
    for c in 0..N {
        let p = (c..N)
            .max_by(|&x, &y| a[x][c].abs().total_cmp(&a[y][c].abs()))
            .unwrap();
        assert!(a[p][c] != 0.0, "singular system");
        a.swap(p, c);
        b.swap(p, c);
        for r in c + 1..N {
            let f = a[r][c] / a[c][c];
            if f != 0.0 {
                let pivot = a[c];
                for (x, p) in a[r][c..].iter_mut().zip(&pivot[c..]) {
                    *x -= f * p;
                }
                b[r] -= f * b[c];
            }
        }
    }
    let mut x = [0.0; N];
    for r in (0..N).rev() {
        let s: f64 = (r + 1..N).map(|c| a[r][c] * x[c]).sum();
        x[r] = (b[r] - s) / a[r][r];
    }
    x
}

/// Row- and column-equilibrated solve with one step of iterative refinement;
/// returns the solution (of the original system) and the normwise backward error
/// `‖A y − b‖∞ / (‖A‖∞ ‖y‖∞ + ‖b‖∞)` of the equilibrated system.
pub fn solve_refined<const N: usize>(a: &[[f64; N]; N], b: &[f64; N]) -> ([f64; N], f64) {
    let mut s = *a;
    let mut rhs = *b;
    for (row, r) in s.iter_mut().zip(rhs.iter_mut()) {
        let m = row.iter().fold(0.0_f64, |m, v| m.max(v.abs()));
        assert!(m > 0.0, "zero row");
        row.iter_mut().for_each(|v| *v /= m);
        *r /= m;
    }
    let mut cols = [1.0; N];
    for c in 0..N {
        let m = (0..N).fold(0.0_f64, |m, r| m.max(s[r][c].abs()));
        assert!(m > 0.0, "zero column {c}");
        for row in s.iter_mut() {
            row[c] /= m;
        }
        cols[c] = m;
    }
    let mut y = lu_solve(s, rhs);
    let resid = |y: &[f64; N]| -> [f64; N] {
        std::array::from_fn(|i| rhs[i] - (0..N).map(|j| s[i][j] * y[j]).sum::<f64>())
    };
    let dy = lu_solve(s, resid(&y));
    for i in 0..N {
        y[i] += dy[i];
    }
    let r = resid(&y);
    // normwise (a row whose terms all vanish in the exact solution, e.g. the shear
    // row of a free edge for k = 0, makes a componentwise measure meaningless)
    let norm_a = s
        .iter()
        .map(|row| row.iter().map(|v| v.abs()).sum::<f64>())
        .fold(0.0_f64, f64::max);
    let norm_y = y.iter().fold(0.0_f64, |m, v| m.max(v.abs()));
    let norm_b = rhs.iter().fold(0.0_f64, |m, v| m.max(v.abs()));
    let norm_r = r.iter().fold(0.0_f64, |m, v| m.max(v.abs()));
    let be = norm_r / (norm_a * norm_y + norm_b);
    (std::array::from_fn(|j| y[j] / cols[j]), be)
}
