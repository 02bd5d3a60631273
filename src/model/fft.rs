//! The cosine and sine transforms of a folded harmonic series on a uniform
//! angle grid, by a radix-2 fast Fourier transform.
//!
//! [`cosine_sine_on_grid`] gives, for j = 0..=M,
//!
//!   c_j = Σ_{m=0}^{M} a_m cos(π m j / M),   s_j = Σ_{m=0}^{M} b_m sin(π m j / M),
//!
//! (a DCT-I and a DST-I) in O(M log M) instead of the O(M²) of summing each
//! grid value: the even extension of a (a_m/2 at m and 2M − m for
//! 0 < m < M) has the transform c_j, the odd extension of b the transform
//! −i s_j; both are real sequences of length 2M, taken as one complex
//! sequence z = x + i y, whose transform is Z_j = c_j + s_j and
//! Z_{2M−j} = c_j − s_j.

use std::f64::consts::PI;

/// A complex number as (re, im), for the transform only.
type C = (f64, f64);

/// In-place iterative radix-2 FFT, X_j = Σ_n x_n e^{−2πi nj/N}, N a power of two.
fn fft(x: &mut [C]) {
    let n = x.len();
    debug_assert!(n.is_power_of_two());
    let bits = n.trailing_zeros();
    for i in 0..n {
        let j = i.reverse_bits() >> (usize::BITS - bits);
        if j > i {
            x.swap(i, j);
        }
    }
    // Twiddles e^{−2πi t/N}, each from its own angle (no accumulated rotation).
    let twiddles: Vec<C> = (0..n / 2)
        .map(|t| (-2.0 * PI * t as f64 / n as f64).sin_cos())
        .map(|(s, c)| (c, s))
        .collect();
    let mut len = 2;
    while len <= n {
        let stride = n / len;
        for start in (0..n).step_by(len) {
            for t in 0..len / 2 {
                let (wr, wi) = twiddles[t * stride];
                let (ur, ui) = x[start + t];
                let (vr, vi) = x[start + t + len / 2];
                let (pr, pi) = (vr * wr - vi * wi, vr * wi + vi * wr);
                x[start + t] = (ur + pr, ui + pi);
                x[start + t + len / 2] = (ur - pr, ui - pi);
            }
        }
        len *= 2;
    }
}

/// (c_j, s_j), j = 0..=M, of the module doc for `a`, `b` of length M + 1, M a
/// power of two.
pub fn cosine_sine_on_grid(a: &[f64], b: &[f64]) -> (Vec<f64>, Vec<f64>) {
    let m = a.len() - 1;
    assert!(
        m.is_power_of_two() && b.len() == m + 1,
        "cosine_sine_on_grid: M = {m} must be a power of two"
    );
    let n = 2 * m;
    let mut z = vec![(0.0, 0.0); n];
    z[0].0 = a[0];
    z[m].0 = a[m];
    for k in 1..m {
        z[k] = (0.5 * a[k], 0.5 * b[k]);
        z[n - k] = (0.5 * a[k], -0.5 * b[k]);
    }
    fft(&mut z);
    let mut c = Vec::with_capacity(m + 1);
    let mut s = Vec::with_capacity(m + 1);
    for j in 0..=m {
        // Z_j = c_j + s_j and Z_{N−j} = c_j − s_j (both real up to round-off).
        let (zj, zn) = (z[j].0, z[(n - j) % n].0);
        c.push(0.5 * (zj + zn));
        s.push(0.5 * (zj - zn));
    }
    (c, s)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_transforms_equal_the_direct_sums() {
        for m in [1usize, 2, 8, 64, 256] {
            let a: Vec<f64> = (0..=m)
                .map(|k| 1.0 / (1.0 + k as f64).powi(2) + 0.3 * (k as f64).sin())
                .collect();
            let b: Vec<f64> = (0..=m)
                .map(|k| (0.7 * k as f64).cos() / (1.0 + k as f64))
                .collect();
            let (c, s) = cosine_sine_on_grid(&a, &b);
            let scale: f64 = a.iter().chain(&b).map(|v| v.abs()).sum();
            for j in 0..=m {
                let x = PI * j as f64 / m as f64;
                let dc: f64 = a
                    .iter()
                    .enumerate()
                    .map(|(k, v)| v * (k as f64 * x).cos())
                    .sum();
                let ds: f64 = b
                    .iter()
                    .enumerate()
                    .map(|(k, v)| v * (k as f64 * x).sin())
                    .sum();
                assert!(
                    (c[j] - dc).abs() < 1e-14 * scale,
                    "M = {m}, c_{j}: {} vs {dc}",
                    c[j]
                );
                assert!(
                    (s[j] - ds).abs() < 1e-14 * scale,
                    "M = {m}, s_{j}: {} vs {ds}",
                    s[j]
                );
            }
        }
    }
}
