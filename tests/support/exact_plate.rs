//! Exact natural frequencies of a free-vibrating annular Kirchhoff plate,
//! independent of the library's numerics (only [`super::bessel`] is used).
//!
//! For `w = R(r) cos(kφ)` the radial ODE (paper eq. 4) has the solutions
//! `R = A J_k(λr) + B Y_k(λr) + C I_k(λr) + D K_k(λr)`. With `z = λr` and `'` = d/dz
//! the edge quantities are (Leissa, NASA SP-160, ch. 2; constant factors dropped):
//!
//! * deflection `R`, slope `R'`,
//! * radial moment `M_r ∝ R'' + ν (R'/z − k² R/z²)`,
//! * Kirchhoff shear `V_r = Q_r + (1/r) ∂M_rφ/∂φ ∝ R''' + R''/z − R'/z² + k² [(3 − ν) R/z³ − (2 − ν) R'/z²]`
//!   (from `V_r = −D [∂(∇²w)/∂r + (1 − ν)(1/r) ∂/∂φ ((1/r) ∂²w/∂r∂φ − (1/r²) ∂w/∂φ)]`),
//!
//! clamped: `R = R' = 0`; supported: `R = M_r = 0`; free: `M_r = V_r = 0`.
//! Second and third z-derivatives come from Bessel's equation itself
//! (`Z'' = −Z'/z ∓ (1 ∓ k²/z²) Z`), so only `Z`, `Z'` are evaluated.
//!
//! Overflow: the I and K columns use the positive, fixed scalings
//! `e^{−λ r_a} I_k(λr) = e^{−λ(r_a − r)} [e^{−z} I_k(z)]` and
//! `e^{+λ r_i} K_k(λr) = e^{−λ(r − r_i)} [e^{z} K_k(z)]`, both bounded on `[r_i, r_a]`;
//! the determinant rows and columns are further divided by their largest entry
//! (positive factors: the sign, hence every root, is unchanged).
//!
//! Roots in λ: a scan with a step far below the asymptotic root spacing
//! `π / (r_a − r_i)`, then bisection to machine precision on each sign change.

#![allow(dead_code)]

use super::bessel;

/// Edge condition (own enum: the support code does not depend on the library).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Edge {
    Free,
    Supported,
    Clamped,
}

impl Edge {
    pub const ALL: [Edge; 3] = [Edge::Free, Edge::Supported, Edge::Clamped];
    pub fn name(self) -> &'static str {
        match self {
            Edge::Free => "free",
            Edge::Supported => "supported",
            Edge::Clamped => "clamped",
        }
    }
    fn rows(self) -> [Quantity; 2] {
        match self {
            Edge::Clamped => [Quantity::Deflection, Quantity::Slope],
            Edge::Supported => [Quantity::Deflection, Quantity::Moment],
            Edge::Free => [Quantity::Moment, Quantity::Shear],
        }
    }
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Quantity {
    Deflection,
    Slope,
    Moment,
    Shear,
}

/// Derivatives `[Z, Z', Z'', Z''']` (d/dz) of the four scaled basis functions at z = λr.
fn basis_derivatives(k: u32, lambda: f64, r: f64, ri: f64, ra: f64) -> [[f64; 4]; 4] {
    let n = k as usize;
    let z = lambda * r;
    let kk = (k as f64) * (k as f64);
    let (j, y) = bessel::jy_val_der(n, z);
    let i = bessel::i_scaled_val_der(n, z);
    let kb = bessel::k_scaled_val_der(n, z);
    let si = (-lambda * (ra - r)).exp(); // e^{−λ r_a} I = si · (e^{−z} I)
    let sk = (-lambda * (r - ri)).exp(); // e^{λ r_i} K = sk · (e^{z} K)
                                         // Oscillatory (J, Y): Z'' = −Z'/z − (1 − k²/z²) Z ; Z''' = −Z''/z + Z'/z² − (1 − k²/z²) Z' − 2k²/z³ Z
    let osc = |v: f64, d: f64| {
        let d2 = -d / z - (1.0 - kk / (z * z)) * v;
        let d3 = -d2 / z + d / (z * z) - (1.0 - kk / (z * z)) * d - 2.0 * kk / (z * z * z) * v;
        [v, d, d2, d3]
    };
    // Modified (I, K): Z'' = −Z'/z + (1 + k²/z²) Z ; Z''' = −Z''/z + Z'/z² + (1 + k²/z²) Z' − 2k²/z³ Z
    let modi = |v: f64, d: f64| {
        let d2 = -d / z + (1.0 + kk / (z * z)) * v;
        let d3 = -d2 / z + d / (z * z) + (1.0 + kk / (z * z)) * d - 2.0 * kk / (z * z * z) * v;
        [v, d, d2, d3]
    };
    let fj = osc(j.value, j.deriv);
    let fy = osc(y.value, y.deriv);
    let fi = modi(i.value, i.deriv).map(|v| v * si);
    let fk = modi(kb.value, kb.deriv).map(|v| v * sk);
    [fj, fy, fi, fk]
}

/// The edge quantity (times a positive power of λ) from `[Z, Z', Z'', Z''']` at z.
fn quantity(q: Quantity, d: &[f64; 4], z: f64, k: u32, nu: f64) -> f64 {
    let kk = (k as f64) * (k as f64);
    match q {
        Quantity::Deflection => d[0],
        Quantity::Slope => d[1],
        Quantity::Moment => d[2] + nu * (d[1] / z - kk * d[0] / (z * z)),
        Quantity::Shear => {
            d[3] + d[2] / z - d[1] / (z * z)
                + kk * ((3.0 - nu) * d[0] / (z * z * z) - (2.0 - nu) * d[1] / (z * z))
        }
    }
}

/// Determinant of a small dense matrix by partial-pivot LU.
pub fn det<const N: usize>(mut a: [[f64; N]; N]) -> f64 {
    let mut d = 1.0;
    for c in 0..N {
        let p = (c..N)
            .max_by(|&x, &y| a[x][c].abs().total_cmp(&a[y][c].abs()))
            .unwrap();
        if a[p][c] == 0.0 {
            return 0.0;
        }
        if p != c {
            a.swap(p, c);
            d = -d;
        }
        d *= a[c][c];
        let pivot = a[c];
        for row in a.iter_mut().skip(c + 1) {
            let f = row[c] / pivot[c];
            for (x, p) in row.iter_mut().zip(&pivot).skip(c) {
                *x -= f * p;
            }
        }
    }
    d
}

/// Divide each row, then each column, by its largest |entry| (positive factors).
/// Returns the column factors used.
fn equilibrate<const N: usize>(a: &mut [[f64; N]; N]) -> [f64; N] {
    for row in a.iter_mut() {
        let m = row.iter().fold(0.0_f64, |m, v| m.max(v.abs()));
        if m > 0.0 {
            row.iter_mut().for_each(|v| *v /= m);
        }
    }
    let mut cols = [1.0; N];
    for (c, col) in cols.iter_mut().enumerate() {
        let m = a.iter().fold(0.0_f64, |m, row| m.max(row[c].abs()));
        if m > 0.0 {
            for row in a.iter_mut() {
                row[c] /= m;
            }
            *col = m;
        }
    }
    cols
}

/// Null vector of a (numerically) singular matrix by complete-pivot elimination.
fn null_vector<const N: usize>(mut a: [[f64; N]; N]) -> [f64; N] {
    let mut colperm: [usize; N] = std::array::from_fn(|i| i);
    for c in 0..N - 1 {
        // complete pivot in the trailing block
        let (mut pr, mut pc, mut best) = (c, c, -1.0);
        for (r, row) in a.iter().enumerate().skip(c) {
            for (cc, v) in row.iter().enumerate().skip(c) {
                if v.abs() > best {
                    best = v.abs();
                    pr = r;
                    pc = cc;
                }
            }
        }
        a.swap(pr, c);
        for row in a.iter_mut() {
            row.swap(pc, c);
        }
        colperm.swap(pc, c);
        let pivot = a[c];
        for row in a.iter_mut().skip(c + 1) {
            let f = row[c] / pivot[c];
            for (x, p) in row.iter_mut().zip(&pivot).skip(c) {
                *x -= f * p;
            }
        }
    }
    // Last unknown (in pivoted order) = 1, back-substitute through the first N−1 rows.
    let mut x = [0.0; N];
    x[N - 1] = 1.0;
    for r in (0..N - 1).rev() {
        let s: f64 = (r + 1..N).map(|c| a[r][c] * x[c]).sum();
        x[r] = -s / a[r][r];
    }
    let mut out = [0.0; N];
    for (i, &p) in colperm.iter().enumerate() {
        out[p] = x[i];
    }
    out
}

/// Null vector of the equilibrated 4×4 frequency matrix at a root, with the Y and K
/// coefficients (which dominate at the inner edge and may be tiny) obtained with
/// relative precision: the two inner-edge rows give (B, D) in terms of (A, C), the
/// two outer-edge rows then form a singular 2×2 whose null vector is (A, C).
/// `None` if the inner 2×2 in (Y, K) is ill-conditioned (then use complete pivoting).
fn two_stage_null_vector(m: &[[f64; 4]; 4]) -> Option<[f64; 4]> {
    // inner rows 0, 1: [a_J a_Y a_I a_K]
    let (y0, k0, y1, k1) = (m[0][1], m[0][3], m[1][1], m[1][3]);
    let d = y0 * k1 - k0 * y1;
    let norm = (y0.abs() + k0.abs()) * (y1.abs() + k1.abs());
    if norm == 0.0 || d.abs() < 1e-6 * norm {
        return None;
    }
    // (B, D) = −S⁻¹ (J-col · A + I-col · C), S = [[y0, k0], [y1, k1]]
    let solve = |r0: f64, r1: f64| ((k1 * r0 - k0 * r1) / d, (-y1 * r0 + y0 * r1) / d);
    let (bj, dj) = solve(-m[0][0], -m[1][0]); // per unit A
    let (bi, di) = solve(-m[0][2], -m[1][2]); // per unit C
                                              // outer rows 2, 3 with B, D eliminated: [[p, q], [s, t]] (A, C)ᵀ = 0
    let row = |r: usize| {
        (
            m[r][0] + m[r][1] * bj + m[r][3] * dj,
            m[r][2] + m[r][1] * bi + m[r][3] * di,
        )
    };
    let (p, q) = row(2);
    let (s, t) = row(3);
    // null vector of the (numerically) singular 2×2 from its larger row
    let (a, c) = if p.abs() + q.abs() >= s.abs() + t.abs() {
        (-q, p)
    } else {
        (-t, s)
    };
    if a == 0.0 && c == 0.0 {
        return None;
    }
    Some([a, a * bj + c * bi, c, a * dj + c * di])
}

/// An annulus `r_i < r < r_a` with its edge conditions (geometry and ν only:
/// λ does not depend on E, ρ or h).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Annulus {
    pub inner_radius: f64,
    pub outer_radius: f64,
    pub poisson_ratio: f64,
    pub inner: Edge,
    pub outer: Edge,
}

/// One exact mode: k nodal diameters, l nodal circles, λ in 1/m.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ExactMode {
    pub k: u32,
    pub l: u32,
    pub lambda: f64,
}

impl Annulus {
    pub fn new(
        inner_radius: f64,
        outer_radius: f64,
        poisson_ratio: f64,
        inner: Edge,
        outer: Edge,
    ) -> Self {
        assert!(0.0 < inner_radius && inner_radius < outer_radius);
        Annulus {
            inner_radius,
            outer_radius,
            poisson_ratio,
            inner,
            outer,
        }
    }

    /// Free–free plates have rigid-body modes for k = 0 (translation) and k = 1 (tilt).
    pub fn has_rigid_body_mode(&self, k: u32) -> bool {
        self.inner == Edge::Free && self.outer == Edge::Free && k <= 1
    }

    /// The 4×4 frequency matrix (rows: inner conditions, outer conditions; columns J, Y, I, K)
    /// before equilibration.
    pub fn matrix(&self, k: u32, lambda: f64) -> [[f64; 4]; 4] {
        let (ri, ra, nu) = (self.inner_radius, self.outer_radius, self.poisson_ratio);
        let di = basis_derivatives(k, lambda, ri, ri, ra);
        let da = basis_derivatives(k, lambda, ra, ri, ra);
        let mut m = [[0.0; 4]; 4];
        for (row, q) in self.inner.rows().iter().enumerate() {
            for f in 0..4 {
                m[row][f] = quantity(*q, &di[f], lambda * ri, k, nu);
            }
        }
        for (row, q) in self.outer.rows().iter().enumerate() {
            for f in 0..4 {
                m[2 + row][f] = quantity(*q, &da[f], lambda * ra, k, nu);
            }
        }
        m
    }

    /// The frequency determinant, equilibrated (same sign and roots as the true one,
    /// never overflows).
    pub fn determinant(&self, k: u32, lambda: f64) -> f64 {
        let mut m = self.matrix(k, lambda);
        equilibrate(&mut m);
        det(m)
    }

    /// The asymptotic spacing of consecutive roots in λ for fixed k: π/(r_a − r_i).
    pub fn root_spacing(&self) -> f64 {
        std::f64::consts::PI / (self.outer_radius - self.inner_radius)
    }

    /// Default scan step in λ: 1/100 of the asymptotic root spacing.
    pub fn default_step(&self) -> f64 {
        self.root_spacing() / 100.0
    }

    /// Roots λ of the determinant in `(lambda_min, lambda_max]`, by a scan with
    /// step `step` and bisection to machine precision.
    pub fn determinant_roots(
        &self,
        k: u32,
        lambda_min: f64,
        lambda_max: f64,
        step: f64,
    ) -> Vec<f64> {
        let mut roots = Vec::new();
        let n = ((lambda_max - lambda_min) / step).ceil() as usize;
        let f = |l: f64| self.determinant(k, l);
        let mut a = lambda_min;
        let mut fa = f(a);
        for i in 1..=n {
            let b = (lambda_min + i as f64 * step).min(lambda_max);
            let fb = f(b);
            if fb == 0.0 {
                roots.push(b);
            } else if fa != 0.0 && fa.signum() != fb.signum() {
                roots.push(bisect(&f, a, b, fa));
            }
            a = b;
            fa = fb;
        }
        roots
    }

    /// Lowest λ searched above zero, as a fraction of 1/r_a (a rigid-body root sits at 0;
    /// the lowest elastic root of any case here is at λ r_a > 1).
    pub const LAMBDA_MIN_TIMES_RA: f64 = 0.05;

    /// Per k, the ascending λ up to `lambda_max`: index = l = nodal circles.
    /// For the free–free plate and k ≤ 1 index 0 is the rigid-body mode, λ = 0.
    pub fn lambdas(&self, k: u32, lambda_max: f64) -> Vec<f64> {
        self.lambdas_with_step(k, lambda_max, self.default_step())
    }

    pub fn lambdas_with_step(&self, k: u32, lambda_max: f64, step: f64) -> Vec<f64> {
        let lo = Self::LAMBDA_MIN_TIMES_RA / self.outer_radius;
        let mut v = Vec::new();
        if self.has_rigid_body_mode(k) {
            v.push(0.0);
        }
        v.extend(self.determinant_roots(k, lo, lambda_max, step));
        v
    }

    /// The `count` lowest elastic modes by frequency, each ⟨k, l⟩ once
    /// (ties by k then l), with l = index in [`Annulus::lambdas`].
    pub fn lowest_modes(&self, count: usize) -> Vec<ExactMode> {
        // Grow the search bound until it holds `count` elastic modes. Below the bound
        // the set is complete: every root per k is found, and k runs until three
        // consecutive k ≥ 2 have none (the lowest root rises with k).
        let mut lambda_max = 8.0 / self.outer_radius;
        loop {
            let mut modes = Vec::new();
            let mut empty_run = 0;
            let mut k = 0u32;
            while empty_run < 3 {
                let ls = self.lambdas(k, lambda_max);
                let mut elastic = 0;
                for (l, &lam) in ls.iter().enumerate() {
                    if lam > 0.0 {
                        modes.push(ExactMode {
                            k,
                            l: l as u32,
                            lambda: lam,
                        });
                        elastic += 1;
                    }
                }
                if elastic == 0 && k >= 2 {
                    empty_run += 1;
                } else {
                    empty_run = 0;
                }
                k += 1;
                assert!(
                    k < 400,
                    "no end to the nodal diameters below λ = {lambda_max}"
                );
            }
            if modes.len() >= count {
                modes.sort_by(|a, b| {
                    a.lambda
                        .total_cmp(&b.lambda)
                        .then(a.k.cmp(&b.k))
                        .then(a.l.cmp(&b.l))
                });
                modes.truncate(count);
                return modes;
            }
            lambda_max *= 1.5;
        }
    }

    /// The exact radial shape at a root λ (normalised so max |R| ≈ 1 on [r_i, r_a], sampled).
    pub fn radial_shape(&self, k: u32, lambda: f64) -> ExactRadialShape {
        let (ri, ra) = (self.inner_radius, self.outer_radius);
        if lambda == 0.0 {
            assert!(self.has_rigid_body_mode(k));
            // translation R = 1, tilt R = r / r_a
            return ExactRadialShape {
                annulus: *self,
                k,
                lambda,
                coeffs: [0.0; 4],
                rigid: true,
                scale: 1.0,
            };
        }
        let mut m = self.matrix(k, lambda);
        let cols = equilibrate(&mut m);
        let c = two_stage_null_vector(&m).unwrap_or_else(|| null_vector(m));
        let coeffs = std::array::from_fn(|i| c[i] / cols[i]);
        let mut shape = ExactRadialShape {
            annulus: *self,
            k,
            lambda,
            coeffs,
            rigid: false,
            scale: 1.0,
        };
        let n = 400; // normalisation only: the sampled max is within ~1e-4 of the true one
        let max = (0..=n)
            .map(|i| shape.value(ri + (ra - ri) * i as f64 / n as f64).abs())
            .fold(0.0, f64::max);
        shape.scale = 1.0 / max;
        shape
    }
}

/// A root of `f` in [a, b] (f(a) = fa, f(b) of the other sign) by bisection to machine precision.
pub fn bisect(f: &impl Fn(f64) -> f64, mut a: f64, mut b: f64, mut fa: f64) -> f64 {
    for _ in 0..200 {
        let m = 0.5 * (a + b);
        if m <= a || m >= b {
            break;
        }
        let fm = f(m);
        if fm == 0.0 {
            return m;
        }
        if fm.signum() == fa.signum() {
            a = m;
            fa = fm;
        } else {
            b = m;
        }
    }
    0.5 * (a + b)
}

/// `R(r)` of an exact mode.
#[derive(Debug, Clone, Copy)]
pub struct ExactRadialShape {
    pub annulus: Annulus,
    pub k: u32,
    pub lambda: f64,
    /// Coefficients of J_k(λr), Y_k(λr), e^{−λ r_a} I_k(λr), e^{λ r_i} K_k(λr).
    pub coeffs: [f64; 4],
    rigid: bool,
    scale: f64,
}

impl ExactRadialShape {
    /// `[R, dR/dr, d²R/dr², d³R/dr³]` at r.
    pub fn derivatives(&self, r: f64) -> [f64; 4] {
        let a = &self.annulus;
        if self.rigid {
            return if self.k == 0 {
                [1.0, 0.0, 0.0, 0.0]
            } else {
                [r / a.outer_radius, 1.0 / a.outer_radius, 0.0, 0.0]
            };
        }
        let d = basis_derivatives(self.k, self.lambda, r, a.inner_radius, a.outer_radius);
        let mut out = [0.0; 4];
        for (order, o) in out.iter_mut().enumerate() {
            let s: f64 = (0..4).map(|f| self.coeffs[f] * d[f][order]).sum();
            *o = self.scale * s * self.lambda.powi(order as i32);
        }
        out
    }

    pub fn value(&self, r: f64) -> f64 {
        self.derivatives(r)[0]
    }

    /// The four edge conditions' residuals: each conditioned quantity (deflection,
    /// slope, moment, shear in the determinant's z-normalisation) at its edge, relative
    /// to the largest single term (coefficient × derivative) at either edge — that is,
    /// relative to the size of the mode at its edges. An edge where the mode is tiny
    /// (e.g. the inner edge of a high-k mode) is judged on the mode's scale, not its own.
    pub fn edge_residuals(&self) -> [f64; 4] {
        let a = &self.annulus;
        let edges = [(a.inner_radius, a.inner), (a.outer_radius, a.outer)];
        let mut size: f64 = 0.0;
        let mut raw = [0.0; 4];
        for (e, &(r, edge)) in edges.iter().enumerate() {
            let d = basis_derivatives(self.k, self.lambda, r, a.inner_radius, a.outer_radius);
            let z = self.lambda * r;
            for (&coeff, df) in self.coeffs.iter().zip(&d) {
                for q in [
                    Quantity::Deflection,
                    Quantity::Slope,
                    Quantity::Moment,
                    Quantity::Shear,
                ] {
                    size = size.max((coeff * quantity(q, df, z, self.k, a.poisson_ratio)).abs());
                }
                for &dd in df {
                    size = size.max((coeff * dd).abs());
                }
            }
            for (i, q) in edge.rows().iter().enumerate() {
                raw[2 * e + i] = (0..4)
                    .map(|f| self.coeffs[f] * quantity(*q, &d[f], z, self.k, a.poisson_ratio))
                    .sum::<f64>();
            }
        }
        raw.map(|v| v.abs() / size)
    }
}

impl ExactRadialShape {
    /// The Rayleigh quotient `U / T` of this shape with the plate energy (DESIGN.md):
    /// `∫ [(R'' + R'/r − k²R/r²)² − 2(1−ν)(R''(R'/r − k²R/r²) − k²(R'/r − R/r²)²)] r dr / ∫ R² r dr`.
    /// For an exact mode it equals λ⁴ only if the edge conditions are the natural ones of
    /// this energy (the boundary terms of the integration by parts vanish): an independent
    /// check of the moment and shear operators and of λ itself (second-order in shape errors).
    pub fn rayleigh_quotient(&self) -> f64 {
        let a = &self.annulus;
        let (ri, ra) = (a.inner_radius, a.outer_radius);
        let nu = a.poisson_ratio;
        let kk = (self.k as f64).powi(2);
        // Composite Gauss–Legendre: cells much shorter than a wavelength.
        // ≤ 1 radian of oscillation per cell, and cells no wider than 1/4 of their
        // distance from r = 0 (the 1/r terms), 12 points each: ~1e-15.
        let cells = ((self.lambda * (ra - ri)).ceil() as usize + 2)
            .max((4.0 * (ra - ri) / ri).ceil() as usize);
        let (xs, ws) = gauss_legendre(12);
        let (mut u, mut t) = (0.0, 0.0);
        for c in 0..cells {
            let (c0, c1) = (
                ri + (ra - ri) * c as f64 / cells as f64,
                ri + (ra - ri) * (c + 1) as f64 / cells as f64,
            );
            for (x, w) in xs.iter().zip(&ws) {
                let r = 0.5 * (c0 + c1) + 0.5 * (c1 - c0) * x;
                let wr = 0.5 * (c1 - c0) * w * r;
                let [v, d1, d2, _] = self.derivatives(r);
                let p = d1 / r - kk * v / (r * r);
                let q = d1 / r - v / (r * r);
                u += wr * ((d2 + p).powi(2) - 2.0 * (1.0 - nu) * (d2 * p - kk * q * q));
                t += wr * v * v;
            }
        }
        u / t
    }
}

/// Gauss–Legendre nodes and weights on [−1, 1] (Newton on P_n).
pub fn gauss_legendre(n: usize) -> (Vec<f64>, Vec<f64>) {
    let mut xs = vec![0.0; n];
    let mut ws = vec![0.0; n];
    for i in 0..n {
        let mut x = (std::f64::consts::PI * (i as f64 + 0.75) / (n as f64 + 0.5)).cos();
        for _ in 0..100 {
            let (mut p0, mut p1) = (1.0, x);
            for m in 2..=n {
                let p2 = ((2 * m - 1) as f64 * x * p1 - (m - 1) as f64 * p0) / m as f64;
                p0 = p1;
                p1 = p2;
            }
            let dp = n as f64 * (x * p1 - p0) / (x * x - 1.0);
            let dx = p1 / dp;
            x -= dx;
            if dx.abs() < 1e-16 {
                let (mut p0, mut p1) = (1.0, x);
                for m in 2..=n {
                    let p2 = ((2 * m - 1) as f64 * x * p1 - (m - 1) as f64 * p0) / m as f64;
                    p0 = p1;
                    p1 = p2;
                }
                let dp = n as f64 * (x * p1 - p0) / (x * x - 1.0);
                ws[i] = 2.0 / ((1.0 - x * x) * dp * dp);
                break;
            }
        }
        xs[i] = x;
    }
    (xs, ws)
}

/// Sign changes of `f` in the open interval (a, b), sampled at `samples` interior
/// points; values below `1e-8 · max|f|` count as zero (no sign) so that a clamped
/// or supported edge's roundoff does not create spurious nodes.
pub fn count_sign_changes(f: impl Fn(f64) -> f64, a: f64, b: f64, samples: usize) -> usize {
    let vals: Vec<f64> = (1..samples)
        .map(|i| f(a + (b - a) * i as f64 / samples as f64))
        .collect();
    let max = vals.iter().fold(0.0_f64, |m, v| m.max(v.abs()));
    let mut last = 0.0_f64;
    let mut changes = 0;
    for v in vals {
        if v.abs() <= 1e-8 * max {
            continue;
        }
        if last != 0.0 && v.signum() != last.signum() {
            changes += 1;
        }
        last = v;
    }
    changes
}

/// Material and thickness: turns λ into frequencies.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Material {
    pub thickness: f64,
    pub density: f64,
    pub youngs_modulus: f64,
    pub poisson_ratio: f64,
}

impl Material {
    pub fn steel(thickness: f64) -> Self {
        Material {
            thickness,
            density: 7850.0,
            youngs_modulus: 2.1e11,
            poisson_ratio: 0.3,
        }
    }
    /// D = E h³ / (12 (1 − ν²)).
    pub fn rigidity(&self) -> f64 {
        self.youngs_modulus * self.thickness.powi(3)
            / (12.0 * (1.0 - self.poisson_ratio * self.poisson_ratio))
    }
    /// ω = λ² sqrt(D / (ρ h)), rad/s.
    pub fn omega(&self, lambda: f64) -> f64 {
        lambda * lambda * (self.rigidity() / (self.density * self.thickness)).sqrt()
    }
    /// f = ω / 2π, Hz.
    pub fn frequency_hz(&self, lambda: f64) -> f64 {
        self.omega(lambda) / (2.0 * std::f64::consts::PI)
    }
}

/// A solid circular plate of radius a (R = A J_k(λr) + C I_k(λr)): a check of the
/// edge operators against the classical tables, independent of the annulus.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CircularPlate {
    pub radius: f64,
    pub poisson_ratio: f64,
    pub edge: Edge,
}

impl CircularPlate {
    pub fn determinant(&self, k: u32, lambda: f64) -> f64 {
        let a = self.radius;
        // Reuse the annulus basis with r_i = r_a = a: J column and the scaled I column
        // (e^{−λa} I_k(λa)); Y and K are excluded (singular at the centre).
        let d = basis_derivatives(k, lambda, a, a, a);
        let z = lambda * a;
        let mut m = [[0.0; 2]; 2];
        for (row, q) in self.edge.rows().iter().enumerate() {
            m[row][0] = quantity(*q, &d[0], z, k, self.poisson_ratio);
            m[row][1] = quantity(*q, &d[2], z, k, self.poisson_ratio);
        }
        equilibrate(&mut m);
        det(m)
    }

    /// Ascending roots λ a (dimensionless) up to `x_max`; rigid-body modes of the free
    /// plate (k = 0, 1) are not included.
    pub fn roots(&self, k: u32, x_max: f64) -> Vec<f64> {
        let a = self.radius;
        let f = |x: f64| self.determinant(k, x / a);
        let step = 0.005;
        let mut out = Vec::new();
        let mut x0 = 0.05;
        let mut f0 = f(x0);
        while x0 < x_max {
            let x1 = x0 + step;
            let f1 = f(x1);
            if f1 == 0.0 {
                out.push(x1);
            } else if f0 != 0.0 && f0.signum() != f1.signum() {
                out.push(bisect(&f, x0, x1, f0));
            }
            x0 = x1;
            f0 = f1;
        }
        out
    }
}
