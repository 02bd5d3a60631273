//! Residual flexibility of the truncated modes (the mode-acceleration
//! method's static correction; docs/residual_flexibility.md).
//!
//! A transverse unit force at (r_b, φ_b) deflects the plate at (r_a, φ_a) by
//! the static Green's function
//!
//! G = Σ_{k ≥ 0} g_k(r_a, r_b) cos k(φ_a − φ_b),
//!
//! g_k(r_a, r_b) = N(r_a)ᵀ K̄_k⁻¹ N(r_b) with K̄_k the stiffness of eq. (14)
//! for w = R(r) cos kφ (it carries c_k = ∫cos²kφ dφ, so the k = 0 term is
//! 1/2π of the load and the others 1/π, the Fourier coefficients of a point
//! load). The retained modes carry Σ_l R_kl(r_a) R_kl(r_b) / K_kl of each
//! harmonic (cos and sin partner together: cos kφ_a cos kφ_b + sin kφ_a sin
//! kφ_b = cos kΔφ); the residual compliance is the rest,
//!
//! C(r_a, r_b, Δφ) = Σ_k r_k cos kΔφ,  r_k = g_k − Σ_{l retained} R_kl R_kl / K_kl.
//!
//! g_k comes from its own B-spline Ritz solve on breakpoints graded
//! geometrically towards every radius asked for (a knot at the load radius:
//! the jump of W‴ there is exact in a C² cubic), one banded Cholesky per k
//! (K̄_k = c_k (K₀ + k² K₁ + k⁴ K₂), assembled once). Harmonics k ≤
//! [`HARMONICS`] are summed directly; at equal radii the terms fall like k⁻³
//! (the ρ² ln ρ singularity under a point load) and the rest is a fitted
//! A k⁻³ + B k⁻⁴ tail; at different radii they fall geometrically.
//!
//! A free–free plate has no static solution for k = 0, 1 (rigid-body
//! motions, carried by the floating frame and the joint): those two harmonics
//! get no residual (listed in [`StaticHarmonics::skipped`]).

use super::bspline::BSplineBasis;
use super::quadrature::radial_points;
use super::radial::angular_norm;
use super::{AngularShape, PlateModel};
use crate::config::{Boundary, PlateConfig};

/// Harmonics summed directly.
pub const HARMONICS: u32 = 1024;
/// Uniform spans of the static solve's base breakpoints.
const BASE_SPANS: usize = 64;
/// Ratio of successive graded spans towards a radius.
const GRADING: f64 = 0.8;
/// Smallest graded span at radius r: r / (SMALLEST_SPAN_PER_K · k_band),
/// far below the decay length r/k of the band's highest harmonic k_band.
const SMALLEST_SPAN_PER_K: f64 = 16.0;
/// Highest harmonic of each band; a band has its own breakpoints, graded no
/// finer than it needs (finer spans only add round-off to the low harmonics:
/// stiffness entries grow like span⁻³).
const BANDS: [u32; 5] = [8, 32, 128, 512, HARMONICS];
/// Beyond the direct sum, the fitted tail is summed term by term up to this
/// multiple of [`HARMONICS`] at Δφ ≠ 0 (its remainder is below A/(2 (8K)²)).
const TAIL_MULTIPLE: u32 = 8;

/// The static harmonics g_k(r_a, r_b), k = 0..=`HARMONICS`, for all pairs of a set of radii.
#[derive(Debug, Clone)]
pub struct StaticHarmonics {
    /// The radii, m.
    pub radii: Vec<f64>,
    /// g[k][a · n + b], m/N.
    g: Vec<Vec<f64>>,
    /// Harmonics without a static solution (free–free k = 0, 1).
    pub skipped: Vec<u32>,
}

impl StaticHarmonics {
    /// g_k(r_a, r_b), m/N (0 for a skipped harmonic).
    pub fn get(&self, k: u32, a: usize, b: usize) -> f64 {
        self.g[k as usize][a * self.radii.len() + b]
    }
}

/// The residual compliance between two points as a cosine series in Δφ.
#[derive(Debug, Clone, PartialEq)]
pub struct ResidualKernel {
    /// r_k, k = 0..=`HARMONICS`, m/N.
    pub coefficients: Vec<f64>,
    /// (A, B) of the tail A k⁻³ + B k⁻⁴ beyond the direct sum (equal radii only).
    pub tail_fit: Option<(f64, f64)>,
}

impl ResidualKernel {
    /// C(Δφ) = Σ r_k cos kΔφ + tail, m/N.
    pub fn at(&self, delta: f64) -> f64 {
        if let Some((a, b)) = self.tail_fit {
            if delta.rem_euclid(std::f64::consts::TAU) == 0.0 {
                let kk = self.coefficients.len() as f64;
                return self.coefficients.iter().sum::<f64>()
                    + a * hurwitz_zeta(3.0, kk)
                    + b * hurwitz_zeta(4.0, kk);
            }
        }
        let n = self.series_len();
        cosine_sum(|k| self.term(k), n, delta)
    }

    /// dC/dΔφ = −Σ k r_k sin kΔφ (the tail's terms included).
    pub fn derivative(&self, delta: f64) -> f64 {
        let n = self.series_len();
        -sine_sum(|k| k as f64 * self.term(k), n, delta)
    }

    /// C and dC/dΔφ at Δφ_j = jπ/M, j = 0..=M (`intervals` = M): the same
    /// sums as [`ResidualKernel::at`] and [`ResidualKernel::derivative`] (at
    /// Δφ = 0 the value is `at(0)`, the zeta tail), for the whole grid at
    /// once. On the grid cos kΔφ_j and sin kΔφ_j depend on k only modulo 2M
    /// (cos (2M − m)Δφ_j = cos mΔφ_j, sin (2M − m)Δφ_j = −sin mΔφ_j), so the
    /// terms fold onto m = 0..=M first; the folded cosine and sine series on
    /// the grid are a DCT-I and a DST-I, by FFT for M a power of two
    /// (`model::fft`, O(M log M)), else summed directly (O(M²)) — rather
    /// than O(M · N) for the N = 8 (K + 1) terms of the tail.
    pub fn on_grid(&self, intervals: usize) -> (Vec<f64>, Vec<f64>) {
        let m_max = intervals;
        let period = 2 * m_max;
        let (mut cos_fold, mut sin_fold) = (vec![0.0; m_max + 1], vec![0.0; m_max + 1]);
        for k in 0..self.series_len() {
            let (t, r) = (self.term(k), k % period);
            if r <= m_max {
                cos_fold[r] += t;
                sin_fold[r] += k as f64 * t;
            } else {
                cos_fold[period - r] += t;
                sin_fold[period - r] -= k as f64 * t;
            }
        }
        let (mut values, slopes) = if m_max.is_power_of_two() {
            super::fft::cosine_sine_on_grid(&cos_fold, &sin_fold)
        } else {
            folded_sums(&cos_fold, &sin_fold)
        };
        values[0] = self.at(0.0);
        let slopes = slopes.into_iter().map(|d| -d).collect();
        (values, slopes)
    }

    /// Terms summed at Δφ ≠ 0: the direct ones, then the fitted tail up to
    /// [`TAIL_MULTIPLE`] × [`HARMONICS`] (its remainder is below A/(2 (8K)²)).
    fn series_len(&self) -> usize {
        if self.tail_fit.is_some() {
            TAIL_MULTIPLE as usize * self.coefficients.len()
        } else {
            self.coefficients.len()
        }
    }

    /// r_k, or the fitted A k⁻³ + B k⁻⁴ beyond the direct sum.
    #[inline]
    fn term(&self, k: usize) -> f64 {
        match (self.coefficients.get(k), self.tail_fit) {
            (Some(&c), _) => c,
            (None, Some((a, b))) => {
                let kf = k as f64;
                let k3 = kf * kf * kf;
                a / k3 + b / (k3 * kf)
            }
            (None, None) => 0.0,
        }
    }
}

/// Σ_m a_m cos(π m j/M) and Σ_m b_m sin(π m j/M), j = 0..=M, summed
/// directly (M not a power of two: no FFT), O(M²).
fn folded_sums(a: &[f64], b: &[f64]) -> (Vec<f64>, Vec<f64>) {
    let m_max = a.len() - 1;
    let period = 2 * m_max;
    let step = std::f64::consts::PI / m_max as f64;
    let (cos_table, sin_table): (Vec<f64>, Vec<f64>) = (0..period)
        .map(|i| (i as f64 * step).sin_cos())
        .map(|(s, c)| (c, s))
        .unzip();
    let (mut values, mut slopes) = (Vec::with_capacity(m_max + 1), Vec::with_capacity(m_max + 1));
    for j in 0..=m_max {
        let (mut c, mut d, mut index) = (0.0, 0.0, 0);
        for (x, y) in a.iter().zip(b) {
            c += x * cos_table[index];
            d += y * sin_table[index];
            index += j;
            if index >= period {
                index -= period;
            }
        }
        values.push(c);
        slopes.push(d);
    }
    (values, slopes)
}

/// Σ_{k<n} c(k) cos kx by the recurrence cos (k+1)x = 2 cos x cos kx − cos (k−1)x
/// (Clenshaw): one cosine for the whole sum.
fn cosine_sum(c: impl Fn(usize) -> f64, n: usize, x: f64) -> f64 {
    let cx = x.cos();
    let (mut b1, mut b2) = (0.0, 0.0);
    for k in (1..n).rev() {
        let b0 = c(k) + 2.0 * cx * b1 - b2;
        b2 = b1;
        b1 = b0;
    }
    let first = if n > 0 { c(0) } else { 0.0 };
    first + b1 * cx - b2
}

/// Σ_{1≤k<n} d(k) sin kx by the same recurrence.
fn sine_sum(d: impl Fn(usize) -> f64, n: usize, x: f64) -> f64 {
    let (sx, cx) = x.sin_cos();
    let (mut b1, mut b2) = (0.0, 0.0);
    for k in (1..n).rev() {
        let b0 = d(k) + 2.0 * cx * b1 - b2;
        b2 = b1;
        b1 = b0;
    }
    b1 * sx
}

/// Σ_{k ≥ n} k^{−s} (Euler–Maclaurin; n ≥ 8 gives far below 1e-12 relative).
fn hurwitz_zeta(s: f64, n: f64) -> f64 {
    n.powf(1.0 - s) / (s - 1.0) + 0.5 * n.powf(-s) + s / 12.0 * n.powf(-s - 1.0)
        - s * (s + 1.0) * (s + 2.0) / 720.0 * n.powf(-s - 3.0)
}

impl PlateModel {
    /// The static harmonics g_k between all pairs of `radii` (each in [r_i, r_a]).
    pub fn static_harmonics(&self, radii: &[f64]) -> StaticHarmonics {
        static_harmonics(self.plate(), self.rigidity(), radii)
    }

    /// The residual compliance between radii `a` and `b` of `h`: the static
    /// harmonics less the retained modes' part.
    pub fn residual_kernel(&self, h: &StaticHarmonics, a: usize, b: usize) -> ResidualKernel {
        self.residual_kernel_of(h, a, b, |_, _| true)
    }

    /// The residual compliance of the subset of this model's modes with
    /// `retained(k, l)` (the modes left out count as truncated): for
    /// comparing mode sets from one large model (`study`).
    pub fn residual_kernel_of(
        &self,
        h: &StaticHarmonics,
        a: usize,
        b: usize,
        retained: impl Fn(u32, u32) -> bool,
    ) -> ResidualKernel {
        let (ra, rb) = (h.radii[a], h.radii[b]);
        let mut coefficients: Vec<f64> = (0..=HARMONICS).map(|k| h.get(k, a, b)).collect();
        let stiffness = &self.body().modal_stiffness;
        for (i, m) in self.modes().iter().enumerate() {
            if m.shape == AngularShape::Sin
                || h.skipped.contains(&m.k)
                || m.k > HARMONICS
                || !retained(m.k, m.l)
            {
                continue;
            }
            let shape = &self.radial_shapes()[m.radial];
            coefficients[m.k as usize] -= shape.value(ra) * shape.value(rb) / stiffness[i];
        }
        let width = self.plate().outer_radius - self.plate().inner_radius;
        let tail_fit = ((ra - rb).abs() <= 1e-12 * width).then(|| {
            // A k⁻³ + B k⁻⁴ through the terms at K/2 and K.
            let (k1, k2) = ((HARMONICS / 2) as f64, HARMONICS as f64);
            let (g1, g2) = (h.get(HARMONICS / 2, a, b), h.get(HARMONICS, a, b));
            let (y1, y2) = (g1 * k1.powi(3), g2 * k2.powi(3));
            // y = A + B/k
            let bb = (y1 - y2) / (1.0 / k1 - 1.0 / k2);
            (y2 - bb / k2, bb)
        });
        // The direct sum covers k = 0..=K; the tail starts at K + 1.
        coefficients.truncate(HARMONICS as usize + 1);
        ResidualKernel {
            coefficients,
            tail_fit,
        }
    }
}

/// Breakpoints: uniform, plus geometric grading towards each radius from both sides.
fn breakpoints(ri: f64, ra: f64, radii: &[f64], k_band: u32) -> Vec<f64> {
    let width = ra - ri;
    let h0 = width / BASE_SPANS as f64;
    let mut pts: Vec<f64> = (0..=BASE_SPANS).map(|i| ri + h0 * i as f64).collect();
    for &r in radii {
        pts.push(r);
        let smallest = (r / (SMALLEST_SPAN_PER_K * k_band as f64)).min(0.25 * h0);
        let mut s = 0.5 * h0;
        while s > smallest {
            pts.push(r - s);
            pts.push(r + s);
            s *= GRADING;
        }
        pts.push(r - smallest);
        pts.push(r + smallest);
    }
    pts.retain(|&x| x >= ri && x <= ra);
    pts.sort_by(f64::total_cmp);
    // Keep the ends and the radii exactly; drop points crowding them.
    let tol = 1e-9 * width;
    let keep = |x: f64| x == ri || x == ra || radii.contains(&x);
    let mut out: Vec<f64> = Vec::with_capacity(pts.len());
    for x in pts {
        match out.last() {
            Some(&last) if x - last <= tol => {
                if keep(x) && !keep(last) {
                    *out.last_mut().unwrap() = x;
                }
            }
            _ => out.push(x),
        }
    }
    out
}

/// Banded stiffness of the static solve: K̄_k / c_k = K₀ + k² K₁ + k⁴ K₂ over
/// the free B-splines; band[i][d] = K(i, i + d), d = 0..=3.
struct BandedStiffness {
    basis: BSplineBasis,
    drop_inner: usize,
    n: usize,
    parts: [Vec<[f64; 4]>; 3],
}

impl BandedStiffness {
    fn new(plate: &PlateConfig, rigidity: f64, basis: BSplineBasis) -> Self {
        let drop_inner = plate.inner_boundary.essential_conditions();
        let n = basis.len() - drop_inner - plate.outer_boundary.essential_conditions();
        let nu = plate.poisson_ratio;
        let mut parts = [vec![[0.0; 4]; n], vec![[0.0; 4]; n], vec![[0.0; 4]; n]];
        let mut pts = Vec::new();
        for s in 0..basis.spans() {
            let (lo, hi) = basis.span_bounds(s);
            pts.clear();
            radial_points(lo, hi, &mut pts);
            for &(r, wq) in &pts {
                let d = basis.eval_span(s, r);
                let w = rigidity * wq * r;
                // Per function: a = R'', e = R'/r, f = R/r², c = R'/r − R/r².
                let f4: [[f64; 4]; 4] = std::array::from_fn(|j| {
                    [
                        d[2][j],
                        d[1][j] / r,
                        d[0][j] / (r * r),
                        d[1][j] / r - d[0][j] / (r * r),
                    ]
                });
                for i in 0..4 {
                    let gi = s + i;
                    if gi < drop_inner || gi - drop_inner >= n {
                        continue;
                    }
                    for j in i..4 {
                        let gj = s + j;
                        if gj - drop_inner >= n {
                            continue;
                        }
                        let [ai, ei, fi, ci] = f4[i];
                        let [aj, ej, fj, cj] = f4[j];
                        let k0 = (ai + ei) * (aj + ej) - (1.0 - nu) * (ai * ej + ei * aj);
                        let k1 = -((ai + ei) * fj + fi * (aj + ej))
                            + (1.0 - nu) * (ai * fj + fi * aj)
                            + 2.0 * (1.0 - nu) * ci * cj;
                        let k2 = fi * fj;
                        let (row, dd) = (gi - drop_inner, j - i);
                        parts[0][row][dd] += w * k0;
                        parts[1][row][dd] += w * k1;
                        parts[2][row][dd] += w * k2;
                    }
                }
            }
        }
        BandedStiffness {
            basis,
            drop_inner,
            n,
            parts,
        }
    }

    /// The free B-splines non-zero at r: (free index, value).
    fn load_vector(&self, r: f64) -> [(usize, f64); 4] {
        let s = self.basis.span_of(r);
        let d = self.basis.eval_span(s, r);
        std::array::from_fn(|j| {
            let g = s + j;
            if g < self.drop_inner || g - self.drop_inner >= self.n {
                (usize::MAX, 0.0)
            } else {
                (g - self.drop_inner, d[0][j])
            }
        })
    }

    /// Cholesky factor of K̄_k (lower band: l[i][d] = L(i, i − d)), or None if
    /// not positive definite. Row i: L(i, j) for j = i−3, i−2, i−1, then the
    /// diagonal, each entry's products subtracted in the order of increasing
    /// distance from it.
    fn factor(&self, k: u32, l: &mut Vec<[f64; 4]>) -> Option<()> {
        let (k2, ck) = ((k as f64).powi(2), angular_norm(k));
        let k4 = k2 * k2;
        let n = self.n;
        l.clear();
        l.resize(n, [0.0; 4]);
        let [p0, p1, p2] = &self.parts;
        let a = |i: usize, d: usize| ck * (p0[i][d] + k2 * p1[i][d] + k4 * p2[i][d]);
        for i in 0..n {
            let mut row = [0.0; 4];
            if i >= 3 {
                row[3] = a(i - 3, 3) / l[i - 3][0];
            }
            if i >= 2 {
                let lj = l[i - 2];
                let mut s = a(i - 2, 2);
                if i >= 3 {
                    s -= row[3] * lj[1];
                }
                row[2] = s / lj[0];
            }
            if i >= 1 {
                let lj = l[i - 1];
                let mut s = a(i - 1, 1);
                if i >= 2 {
                    s -= row[2] * lj[1];
                }
                if i >= 3 {
                    s -= row[3] * lj[2];
                }
                row[1] = s / lj[0];
            }
            let mut diag = a(i, 0);
            for r in &row[1..4.min(i + 1)] {
                diag -= r * r;
            }
            // Positive and finite (NaN fails both comparisons).
            if !(diag > 0.0 && diag < f64::INFINITY) {
                return None;
            }
            row[0] = diag.sqrt();
            l[i] = row;
        }
        Some(())
    }
}

/// Solve L Lᵀ x = b in place (band factor from [`BandedStiffness::factor`]).
fn band_solve(l: &[[f64; 4]], x: &mut [f64]) {
    let n = x.len();
    let l = &l[..n];
    for i in 0..n.min(3) {
        let mut s = x[i];
        for d in 1..i + 1 {
            s -= l[i][d] * x[i - d];
        }
        x[i] = s / l[i][0];
    }
    for i in 3..n {
        let li = l[i];
        let s = x[i] - li[1] * x[i - 1] - li[2] * x[i - 2] - li[3] * x[i - 3];
        x[i] = s / li[0];
    }
    for i in (0..n).rev() {
        let mut s = x[i];
        if i + 3 < n {
            s = s - l[i + 1][1] * x[i + 1] - l[i + 2][2] * x[i + 2] - l[i + 3][3] * x[i + 3];
        } else {
            for d in 1..4 {
                if i + d < n {
                    s -= l[i + d][d] * x[i + d];
                }
            }
        }
        x[i] = s / l[i][0];
    }
}

fn static_harmonics(plate: &PlateConfig, rigidity: f64, radii: &[f64]) -> StaticHarmonics {
    let (ri, ra) = (plate.inner_radius, plate.outer_radius);
    let radii: Vec<f64> = radii.iter().map(|r| r.clamp(ri, ra)).collect();
    let nr = radii.len();
    let free_free =
        plate.inner_boundary == Boundary::Free && plate.outer_boundary == Boundary::Free;
    let mut g = Vec::with_capacity(HARMONICS as usize + 1);
    let mut skipped = Vec::new();
    let mut l = Vec::new();
    let mut k = 0;
    for &k_band in &BANDS {
        let stiffness = BandedStiffness::new(
            plate,
            rigidity,
            BSplineBasis::with_breakpoints(&breakpoints(ri, ra, &radii, k_band)),
        );
        let loads: Vec<[(usize, f64); 4]> =
            radii.iter().map(|&r| stiffness.load_vector(r)).collect();
        let mut x = vec![0.0; stiffness.n];
        while k <= k_band {
            let mut gk = vec![0.0; nr * nr];
            if (free_free && k <= 1) || stiffness.factor(k, &mut l).is_none() {
                skipped.push(k);
                g.push(gk);
                k += 1;
                continue;
            }
            for b in 0..nr {
                x.iter_mut().for_each(|v| *v = 0.0);
                for &(i, v) in &loads[b] {
                    if i != usize::MAX {
                        x[i] += v;
                    }
                }
                band_solve(&l, &mut x);
                for a in 0..nr {
                    gk[a * nr + b] = loads[a]
                        .iter()
                        .filter(|(i, _)| *i != usize::MAX)
                        .map(|&(i, v)| v * x[i])
                        .sum();
                }
            }
            // Symmetrise (Maxwell–Betti holds to round-off).
            for a in 0..nr {
                for b in a + 1..nr {
                    let m = 0.5 * (gk[a * nr + b] + gk[b * nr + a]);
                    gk[a * nr + b] = m;
                    gk[b * nr + a] = m;
                }
            }
            g.push(gk);
            k += 1;
        }
    }
    StaticHarmonics { radii, g, skipped }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn band_cholesky_solves_a_banded_system() {
        // A tridiagonal-plus SPD matrix with bandwidth 3.
        let n = 12;
        let dense = |i: usize, j: usize| -> f64 {
            let d = i.abs_diff(j);
            match d {
                0 => 10.0 + i as f64,
                1 => -2.0,
                2 => 0.5,
                3 => -0.25,
                _ => 0.0,
            }
        };
        let bs = BandedStiffness {
            basis: BSplineBasis::new(1.0, 2.0, 4),
            drop_inner: 0,
            n,
            parts: [
                (0..n)
                    .map(|i| std::array::from_fn(|d| if i + d < n { dense(i, i + d) } else { 0.0 }))
                    .collect(),
                vec![[0.0; 4]; n],
                vec![[0.0; 4]; n],
            ],
        };
        let mut l = Vec::new();
        bs.factor(0, &mut l).unwrap();
        let xs: Vec<f64> = (0..n).map(|i| (i as f64 * 0.7).sin()).collect();
        let c0 = angular_norm(0);
        let mut b: Vec<f64> = (0..n)
            .map(|i| (0..n).map(|j| c0 * dense(i, j) * xs[j]).sum())
            .collect();
        band_solve(&l, &mut b);
        for (u, v) in b.iter().zip(&xs) {
            assert!((u - v).abs() < 1e-13, "{u} vs {v}");
        }
    }

    /// The band Cholesky as first written (loops over the band with the
    /// bounds as conditions): the reference the unrolled rows must equal.
    fn factor_loops(bs: &BandedStiffness, k: u32) -> Option<Vec<[f64; 4]>> {
        let (k2, ck) = ((k as f64).powi(2), angular_norm(k));
        let n = bs.n;
        let mut l = vec![[0.0; 4]; n];
        let a = |i: usize, d: usize| {
            ck * (bs.parts[0][i][d] + k2 * bs.parts[1][i][d] + k2 * k2 * bs.parts[2][i][d])
        };
        for i in 0..n {
            for d in (1..4).rev() {
                if d > i {
                    continue;
                }
                let j = i - d;
                let mut s = a(j, d);
                for m in 1..4 {
                    if m + d < 4 && m <= j {
                        s -= l[i][d + m] * l[j][m];
                    }
                }
                l[i][d] = s / l[j][0];
            }
            let mut diag = a(i, 0);
            for r in &l[i][1..4.min(i + 1)] {
                diag -= r * r;
            }
            if diag <= 0.0 || !diag.is_finite() {
                return None;
            }
            l[i][0] = diag.sqrt();
        }
        Some(l)
    }

    fn band_solve_loops(l: &[[f64; 4]], x: &mut [f64]) {
        let n = x.len();
        for i in 0..n {
            let mut s = x[i];
            for d in 1..4.min(i + 1) {
                s -= l[i][d] * x[i - d];
            }
            x[i] = s / l[i][0];
        }
        for i in (0..n).rev() {
            let mut s = x[i];
            for d in 1..4 {
                if i + d < n {
                    s -= l[i + d][d] * x[i + d];
                }
            }
            x[i] = s / l[i][0];
        }
    }

    #[test]
    fn the_unrolled_band_cholesky_equals_the_loop_form_bit_for_bit() {
        // The static solve of a steel annulus graded towards its rim (the
        // lathe disc's residual), every band, and small systems (n < 4).
        let plate = PlateConfig::lathe_disc();
        let rigidity = crate::config::bending_rigidity(
            plate.youngs_modulus,
            plate.thickness,
            plate.poisson_ratio,
        );
        let mut systems = Vec::new();
        for &k_band in &BANDS {
            let basis =
                BSplineBasis::with_breakpoints(&breakpoints(0.075, 0.15, &[0.15, 0.1], k_band));
            systems.push((BandedStiffness::new(&plate, rigidity, basis), k_band));
        }
        for n in 1..6 {
            let dense = |i: usize, j: usize| match i.abs_diff(j) {
                0 => 10.0 + i as f64,
                1 => -2.0,
                2 => 0.5,
                3 => -0.25,
                _ => 0.0,
            };
            let parts = [
                (0..n)
                    .map(|i| std::array::from_fn(|d| if i + d < n { dense(i, i + d) } else { 0.0 }))
                    .collect(),
                vec![[0.1; 4]; n],
                vec![[0.01; 4]; n],
            ];
            systems.push((
                BandedStiffness {
                    basis: BSplineBasis::new(1.0, 2.0, 4),
                    drop_inner: 0,
                    n,
                    parts,
                },
                8,
            ));
        }
        let mut l = Vec::new();
        for (bs, k_band) in &systems {
            for k in [0, 1, 2, 3, k_band / 2 + 1, *k_band] {
                let reference = factor_loops(bs, k);
                assert_eq!(
                    bs.factor(k, &mut l).is_some(),
                    reference.is_some(),
                    "k = {k}, n = {}",
                    bs.n
                );
                let Some(reference) = reference else { continue };
                assert!(
                    l.iter()
                        .flatten()
                        .zip(reference.iter().flatten())
                        .all(|(a, b)| a.to_bits() == b.to_bits()),
                    "factor k = {k}, n = {}",
                    bs.n
                );
                let b: Vec<f64> = (0..bs.n).map(|i| (i as f64 * 0.37 + 0.1).sin()).collect();
                let (mut x, mut y) = (b.clone(), b);
                band_solve(&l, &mut x);
                band_solve_loops(&reference, &mut y);
                assert!(
                    x.iter().zip(&y).all(|(a, b)| a.to_bits() == b.to_bits()),
                    "solve k = {k}, n = {}",
                    bs.n
                );
            }
        }
    }

    #[test]
    fn cosine_and_sine_sums_match_direct_evaluation() {
        let c: Vec<f64> = (0..50).map(|k| 1.0 / (1.0 + k as f64).powi(3)).collect();
        for x in [0.0, 0.3, 1.0, 2.5, 3.1] {
            let direct: f64 = c
                .iter()
                .enumerate()
                .map(|(k, v)| v * (k as f64 * x).cos())
                .sum();
            assert!((cosine_sum(|k| c[k], c.len(), x) - direct).abs() < 1e-14);
            let direct: f64 = c
                .iter()
                .enumerate()
                .skip(1)
                .map(|(k, v)| v * (k as f64 * x).sin())
                .sum();
            assert!((sine_sum(|k| c[k], c.len(), x) - direct).abs() < 1e-14);
        }
    }

    #[test]
    fn the_grid_evaluation_equals_the_clenshaw_sums_at_every_grid_point() {
        // Both ways sum the same 8 × 65 terms: they differ by round-off only.
        // M = 128 by FFT, M = 96 summed directly.
        let coefficients: Vec<f64> = (0..=64).map(|k| 1.0 / (1.0 + k as f64).powi(3)).collect();
        for (tail_fit, m) in [
            (Some((1.0, 0.5)), 96),
            (None, 96),
            (Some((1.0, 0.5)), 128),
            (None, 128),
        ] {
            let kernel = ResidualKernel {
                coefficients: coefficients.clone(),
                tail_fit,
            };
            let (values, slopes) = kernel.on_grid(m);
            assert_eq!((values.len(), slopes.len()), (m + 1, m + 1));
            assert_eq!(values[0], kernel.at(0.0));
            let scale = kernel.at(0.0).abs();
            for j in 0..=m {
                let x = j as f64 * std::f64::consts::PI / m as f64;
                assert!(
                    (values[j] - kernel.at(x)).abs() < 1e-14 * scale,
                    "C at j = {j}: {} vs {}",
                    values[j],
                    kernel.at(x)
                );
                assert!(
                    (slopes[j] - kernel.derivative(x)).abs() < 1e-13 * scale,
                    "C' at j = {j}: {} vs {}",
                    slopes[j],
                    kernel.derivative(x)
                );
            }
        }
    }

    #[test]
    fn kernel_tail_is_summed_away_from_zero_and_its_slope_is_the_derivative() {
        let coefficients: Vec<f64> = (0..=64).map(|k| 1.0 / (1.0 + k as f64).powi(3)).collect();
        let kernel = ResidualKernel {
            coefficients,
            tail_fit: Some((1.0, 0.5)),
        };
        // At Δ = 0 the zeta tail, near it the tail summed to 8 × 65 terms: they differ
        // by the remainder Σ_{k ≥ 520} (k⁻³ + k⁻⁴/2) ≈ 1/(2 · 520²).
        let (at0, near) = (kernel.at(0.0), kernel.at(1e-9));
        let remainder = 1.0 / (2.0 * 520.0f64.powi(2));
        assert!(
            ((at0 - near) - remainder).abs() < 2e-8,
            "{at0} − {near} vs {remainder}"
        );
        for x in [0.2, 1.0, 2.9] {
            let h = 1e-5;
            let fd = (kernel.at(x + h) - kernel.at(x - h)) / (2.0 * h);
            assert!(
                (fd - kernel.derivative(x)).abs() < 1e-6,
                "{fd} vs {}",
                kernel.derivative(x)
            );
        }
    }
}
