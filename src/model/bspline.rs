//! Cubic B-splines on an open uniform knot vector over [r_i, r_a]
//! (paper section 3.1, Fig. 4; de Boor [9]).
//!
//! `n` basis functions need `n − 3` spans. Knots are uniform, optionally with
//! extra knots graded geometrically towards r_i ([`BSplineBasis::graded`]).
//! Only N_0 is non-zero at r_i and
//! only N_0, N_1 have a non-zero slope there (likewise N_{n−1}, N_{n−2} at
//! r_a), so the essential boundary conditions are imposed by dropping those.

/// Degree of the radial B-splines.
pub const DEGREE: usize = 3;

/// An open uniform cubic B-spline basis on [a, b].
#[derive(Debug, Clone, PartialEq)]
pub struct BSplineBasis {
    a: f64,
    b: f64,
    n: usize,
    knots: Vec<f64>,
}

impl BSplineBasis {
    /// `n ≥ 4` cubic B-splines on [a, b] with uniform knots.
    pub fn new(a: f64, b: f64, n: usize) -> Self {
        Self::graded(a, b, n, 0, 0.0)
    }

    /// `n_uniform` B-splines on uniform knots plus `extra` knots placed
    /// geometrically between a and the first uniform knot, the smallest span
    /// being `smallest` (so `n_uniform + extra` functions in all). Resolves
    /// the boundary layer at a small pinned hole (docs/hard_cases.md).
    pub fn graded(a: f64, b: f64, n_uniform: usize, extra: usize, smallest: f64) -> Self {
        assert!(n_uniform > DEGREE && b > a);
        let spans = n_uniform - DEGREE;
        let h = (b - a) / spans as f64;
        let mut knots = Vec::with_capacity(n_uniform + extra + DEGREE + 1);
        knots.extend(std::iter::repeat_n(a, DEGREE + 1));
        if extra > 0 {
            let q = (smallest / h).min(0.5).powf(1.0 / extra as f64);
            for j in (1..=extra).rev() {
                knots.push(a + h * q.powi(j as i32));
            }
        }
        for i in 1..spans {
            knots.push(a + h * i as f64);
        }
        knots.extend(std::iter::repeat_n(b, DEGREE + 1));
        BSplineBasis {
            a,
            b,
            n: n_uniform + extra,
            knots,
        }
    }

    /// Cubic B-splines on the given strictly increasing breakpoints (first and
    /// last are the interval ends, each repeated to an open knot vector):
    /// `breaks.len() + 2` functions. Used by the residual flexibility's static
    /// solve, whose knots are graded towards the node radii.
    pub fn with_breakpoints(breaks: &[f64]) -> Self {
        assert!(breaks.len() >= 2 && breaks.windows(2).all(|w| w[1] > w[0]));
        let (a, b) = (breaks[0], breaks[breaks.len() - 1]);
        let mut knots = Vec::with_capacity(breaks.len() + 2 * DEGREE);
        knots.extend(std::iter::repeat_n(a, DEGREE));
        knots.extend_from_slice(breaks);
        knots.extend(std::iter::repeat_n(b, DEGREE));
        BSplineBasis {
            a,
            b,
            n: breaks.len() + DEGREE - 1,
            knots,
        }
    }

    /// Greville abscissae ξ*_j = (t_{j+1} + t_{j+2} + t_{j+3})/3: Σ ξ*_j N_j(r) = r.
    pub fn greville(&self) -> Vec<f64> {
        (0..self.n)
            .map(|j| (self.knots[j + 1] + self.knots[j + 2] + self.knots[j + 3]) / 3.0)
            .collect()
    }

    pub fn len(&self) -> usize {
        self.n
    }
    pub fn is_empty(&self) -> bool {
        self.n == 0
    }
    pub fn spans(&self) -> usize {
        self.n - DEGREE
    }
    pub fn interval(&self) -> (f64, f64) {
        (self.a, self.b)
    }
    /// Knot positions bounding span `s`.
    pub fn span_bounds(&self, s: usize) -> (f64, f64) {
        (self.knots[s + DEGREE], self.knots[s + DEGREE + 1])
    }

    /// The span containing x (clamped to the interval).
    pub fn span_of(&self, x: f64) -> usize {
        // Interior knots knots[DEGREE+1 ..= DEGREE+spans−1]: the span is the number ≤ x.
        let interior = &self.knots[DEGREE + 1..DEGREE + self.spans()];
        interior.partition_point(|&t| t <= x)
    }

    /// Values and the first three derivatives of the four basis functions
    /// non-zero on span `s`, at x: `ders[d][j]` is the d-th derivative of
    /// N_{s+j}. (The NURBS Book, algorithm A2.3.)
    pub fn eval_span(&self, s: usize, x: f64) -> [[f64; 4]; 4] {
        const P: usize = DEGREE;
        let i = s + P; // knot index with knots[i] <= x < knots[i+1]
        let u = &self.knots;
        let mut ndu = [[0.0f64; 4]; 4];
        let mut left = [0.0f64; 4];
        let mut right = [0.0f64; 4];
        ndu[0][0] = 1.0;
        for j in 1..=P {
            left[j] = x - u[i + 1 - j];
            right[j] = u[i + j] - x;
            let mut saved = 0.0;
            for r in 0..j {
                ndu[j][r] = right[r + 1] + left[j - r];
                let temp = ndu[r][j - 1] / ndu[j][r];
                ndu[r][j] = saved + right[r + 1] * temp;
                saved = left[j - r] * temp;
            }
            ndu[j][j] = saved;
        }
        let mut ders = [[0.0f64; 4]; 4];
        for j in 0..=P {
            ders[0][j] = ndu[j][P];
        }
        let mut a = [[0.0f64; 4]; 2];
        for r in 0..=P {
            let (mut s1, mut s2) = (0usize, 1usize);
            a[0][0] = 1.0;
            for k in 1..=P {
                let mut d = 0.0;
                let rk = r as isize - k as isize;
                let pk = P - k;
                if r >= k {
                    a[s2][0] = a[s1][0] / ndu[pk + 1][rk as usize];
                    d = a[s2][0] * ndu[rk as usize][pk];
                }
                let j1 = if rk >= -1 { 1 } else { (-rk) as usize };
                let j2 = if (r as isize - 1) <= pk as isize {
                    k - 1
                } else {
                    P - r
                };
                for j in j1..=j2 {
                    let idx = (rk + j as isize) as usize;
                    a[s2][j] = (a[s1][j] - a[s1][j - 1]) / ndu[pk + 1][idx];
                    d += a[s2][j] * ndu[idx][pk];
                }
                if r <= pk {
                    a[s2][k] = -a[s1][k - 1] / ndu[pk + 1][r];
                    d += a[s2][k] * ndu[r][pk];
                }
                ders[k][r] = d;
                std::mem::swap(&mut s1, &mut s2);
            }
        }
        let mut fac = P as f64;
        for (k, row) in ders.iter_mut().enumerate().skip(1) {
            for v in row.iter_mut() {
                *v *= fac;
            }
            fac *= (P - k) as f64;
        }
        ders
    }

    /// Σ c_j N_j and its first three derivatives at x.
    pub fn eval_combination(&self, coefficients: &[f64], x: f64) -> [f64; 4] {
        let s = self.span_of(x);
        let d = self.eval_span(s, x);
        let mut out = [0.0; 4];
        for (order, row) in d.iter().enumerate() {
            out[order] = (0..4).map(|j| coefficients[s + j] * row[j]).sum();
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn partition_of_unity_and_derivatives_sum_to_zero() {
        let b = BSplineBasis::new(0.1, 0.4, 11);
        for k in 0..=200 {
            let x = 0.1 + 0.3 * k as f64 / 200.0;
            let d = b.eval_span(b.span_of(x), x);
            assert!((d[0].iter().sum::<f64>() - 1.0).abs() < 1e-14);
            for row in &d[1..] {
                assert!(row.iter().sum::<f64>().abs() < 1e-8 * 1e3);
            }
        }
    }

    #[test]
    fn reproduces_cubic_polynomials() {
        // Greville-free check: fit by solving for coefficients is not needed —
        // compare derivatives of a spline against finite differences instead.
        let b = BSplineBasis::new(1.0, 2.0, 9);
        let c: Vec<f64> = (0..9).map(|i| ((i * 7 % 5) as f64) - 1.3).collect();
        let h = 1e-5;
        for k in 1..40 {
            let x = 1.0 + k as f64 / 40.0 + 1e-3;
            let v = b.eval_combination(&c, x);
            let vp = b.eval_combination(&c, x + h);
            let vm = b.eval_combination(&c, x - h);
            for order in 0..3 {
                let fd = (vp[order] - vm[order]) / (2.0 * h);
                assert!(
                    (fd - v[order + 1]).abs() < 1e-4 * (1.0 + v[order + 1].abs()),
                    "order {order} at {x}: {fd} vs {}",
                    v[order + 1]
                );
            }
        }
    }

    #[test]
    fn graded_knots_keep_the_partition_of_unity_and_reproduce_r() {
        let b = BSplineBasis::graded(1e-4, 0.15, 20, 8, 2.5e-5);
        assert_eq!(b.len(), 28);
        let g = b.greville();
        for k in 0..=500 {
            let x = 1e-4 + (0.15 - 1e-4) * (k as f64 / 500.0).powi(3);
            let s = b.span_of(x);
            let (lo, hi) = b.span_bounds(s);
            assert!(
                lo <= x && (x < hi || s == b.spans() - 1),
                "{x} not in span {s} [{lo}, {hi})"
            );
            let d = b.eval_span(s, x);
            assert!((d[0].iter().sum::<f64>() - 1.0).abs() < 1e-13);
            let r: f64 = (0..4).map(|j| g[s + j] * d[0][j]).sum();
            assert!((r - x).abs() < 1e-15 * 0.15, "{r} vs {x}");
        }
        assert!((b.span_bounds(0).1 - b.span_bounds(0).0 - 2.5e-5).abs() < 1e-12);
    }

    #[test]
    fn only_first_two_splines_touch_the_inner_edge() {
        let b = BSplineBasis::new(0.5, 1.0, 8);
        let d = b.eval_span(0, 0.5);
        assert_eq!(d[0], [1.0, 0.0, 0.0, 0.0]);
        assert!(d[1][0] != 0.0 && d[1][1] != 0.0 && d[1][2] == 0.0 && d[1][3] == 0.0);
    }
}
