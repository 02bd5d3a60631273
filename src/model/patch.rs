//! Load patches and the banded static solves behind patch compliances
//! (docs/residual_flexibility.md, "Under Mindlin theory"; docs/in_plane.md,
//! "Statics and residual flexibility").
//!
//! Where a point force's displacement is logarithmically infinite (the shear
//! of a Mindlin plate, any in-plane force), a node with residual flexibility
//! stands for a small load patch: the annular sector |r − r₀| ≤ c (clipped to
//! [r_i, r_a]), |θ − θ₀| ≤ β = min(c/r₀, π). Its force is spread uniformly
//! per unit area over the patch and its displacement is the patch mean; the
//! two are work-conjugate, so the compliance is symmetric (Maxwell–Betti).
//! Per harmonic k the patch mean of f(r) cos kθ (or sin kθ) is the radial mean
//! f̄ times cos kθ₀ (sin kθ₀) times sinc kβ ([`LoadPatch::angular_factor`]).
//!
//! Per harmonic the static stiffness is banded; [`band_cholesky`] and
//! [`band_solve`] factor and solve it. The series over k stops by
//! [`remainder_below`].

use crate::model::bspline::BSplineBasis;
use crate::model::quadrature::radial_points;

/// A node's load patch (module doc).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LoadPatch {
    /// r₀, m.
    pub centre: f64,
    /// The radial interval [r₀ − c, r₀ + c] ∩ [r_i, r_a], m.
    pub radial: (f64, f64),
    /// β = min(c/r₀, π), rad.
    pub half_angle: f64,
}

impl LoadPatch {
    /// The patch of half-width `c` (m) at radius `centre` of the annulus [`ri`, `ra`].
    pub fn new(ri: f64, ra: f64, centre: f64, c: f64) -> LoadPatch {
        let centre = centre.clamp(ri, ra);
        LoadPatch {
            centre,
            radial: ((centre - c).max(ri), (centre + c).min(ra)),
            half_angle: (c / centre).min(std::f64::consts::PI),
        }
    }

    /// sinc kβ = sin kβ / (kβ): the angular mean of cos k(θ − θ₀) over the patch.
    pub fn angular_factor(&self, k: u32) -> f64 {
        let x = k as f64 * self.half_angle;
        if x == 0.0 {
            1.0
        } else {
            x.sin() / x
        }
    }

    /// ∫ f r dr / ∫ r dr over the radial interval, by Gauss–Legendre on
    /// `breaks` (the B-spline breakpoints: exact for the spline pieces).
    pub fn radial_mean(&self, breaks: &[f64], f: impl Fn(f64) -> f64) -> f64 {
        let sum: f64 = patch_points(breaks, self)
            .iter()
            .map(|&(r, w)| w * r * f(r))
            .sum();
        sum / self.area_factor()
    }

    /// ∫ r dr over the radial interval, m².
    fn area_factor(&self) -> f64 {
        let (lo, hi) = self.radial;
        0.5 * (hi * hi - lo * lo)
    }

    /// The patch means m_j of the B-splines of `basis` (the load vector of a
    /// unit force spread over the patch), indexed by B-spline.
    pub(crate) fn spline_means(&self, basis: &BSplineBasis) -> Vec<f64> {
        let mut out = vec![0.0; basis.len()];
        let area = self.area_factor();
        for (r, w) in patch_points(&breakpoints(basis), self) {
            let s = basis.span_of(r);
            let d = basis.eval_span(s, r);
            for (j, v) in d[0].iter().enumerate() {
                out[s + j] += w * r * v / area;
            }
        }
        out
    }
}

/// Quadrature points (r, weight) of the patch's radial interval, split at `breaks`.
fn patch_points(breaks: &[f64], patch: &LoadPatch) -> Vec<(f64, f64)> {
    let (lo, hi) = patch.radial;
    let mut cuts: Vec<f64> = breaks
        .iter()
        .copied()
        .filter(|&x| x > lo && x < hi)
        .collect();
    cuts.insert(0, lo);
    cuts.push(hi);
    let mut pts = Vec::new();
    for pair in cuts.windows(2) {
        radial_points(pair[0], pair[1], &mut pts);
    }
    pts
}

/// The breakpoints of a basis.
pub(crate) fn breakpoints(basis: &BSplineBasis) -> Vec<f64> {
    let mut out: Vec<f64> = (0..basis.spans()).map(|s| basis.span_bounds(s).0).collect();
    out.push(basis.interval().1);
    out
}

/// Cholesky factor of the symmetric n × n band matrix of half-bandwidth
/// `bw` whose entry A(j, j + d) is `entry(j, d)`: l[i (bw + 1) + d] =
/// L(i, i − d); None if not positive definite.
pub(crate) fn band_cholesky(
    n: usize,
    bw: usize,
    entry: impl Fn(usize, usize) -> f64,
    l: &mut Vec<f64>,
) -> Option<()> {
    let w = bw + 1;
    l.clear();
    l.resize(n * w, 0.0);
    for i in 0..n {
        for j in i.saturating_sub(bw)..=i {
            let mut s = entry(j, i - j);
            for m in i.saturating_sub(bw)..j {
                s -= l[i * w + i - m] * l[j * w + j - m];
            }
            if j == i {
                if !(s > 0.0 && s < f64::INFINITY) {
                    return None;
                }
                l[i * w] = s.sqrt();
            } else {
                l[i * w + i - j] = s / l[j * w];
            }
        }
    }
    Some(())
}

/// Solve L Lᵀ x = b in place (L from [`band_cholesky`], half-bandwidth `bw`).
pub(crate) fn band_solve(l: &[f64], bw: usize, x: &mut [f64]) {
    let (n, w) = (x.len(), bw + 1);
    for i in 0..n {
        let mut s = x[i];
        for m in i.saturating_sub(bw)..i {
            s -= l[i * w + i - m] * x[m];
        }
        x[i] = s / l[i * w];
    }
    for i in (0..n).rev() {
        let mut s = x[i];
        for m in i + 1..(i + w).min(n) {
            s -= l[m * w + m - i] * x[m];
        }
        x[i] = s / l[i * w];
    }
}

/// Whether the remainder of a patch series beyond harmonic k is below `tol`
/// of every diagonal compliance: `diagonals` gives, per patch (and load
/// component), the raw harmonic k (before the sinc factors), the patch's β
/// and the sum so far. The terms are at most raw (kβ)⁻² and fall like k⁻⁴
/// (so the remainder is below k/3 times that), for every pair by
/// Cauchy–Schwarz.
pub(crate) fn remainder_below(
    k: u32,
    tol: f64,
    mut diagonals: impl Iterator<Item = (f64, f64, f64)>,
) -> bool {
    let kf = k as f64;
    diagonals.all(|(raw, beta, total)| {
        let envelope = (1.0 / (kf * beta).powi(2)).min(1.0);
        kf >= 8.0 && kf / 3.0 * raw.abs() * envelope < tol * total.abs()
    })
}
