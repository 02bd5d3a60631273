//! Quadrature over the annulus for the tests' own integrals.
#![allow(dead_code)]

use std::f64::consts::TAU;

/// 4-point Gauss–Legendre nodes and weights on [−1, 1] (exact to degree 7).
pub const GAUSS_LEGENDRE_4: [(f64, f64); 4] = [
    (-0.861_136_311_594_052_6, 0.347_854_845_137_453_9),
    (-0.339_981_043_584_856_3, 0.652_145_154_862_546_1),
    (0.339_981_043_584_856_3, 0.652_145_154_862_546_1),
    (0.861_136_311_594_052_6, 0.347_854_845_137_453_9),
];

/// ∫_a^b f(r) dr: 4 Gauss–Legendre points on each of `cells` equal cells.
pub fn radial(a: f64, b: f64, cells: usize, f: impl Fn(f64) -> f64) -> f64 {
    let mut sum = 0.0;
    for cell in 0..cells {
        let lo = a + (b - a) * cell as f64 / cells as f64;
        let hi = a + (b - a) * (cell + 1) as f64 / cells as f64;
        for (x, w) in GAUSS_LEGENDRE_4 {
            sum += 0.5 * (hi - lo) * w * f(0.5 * (lo + hi) + 0.5 * (hi - lo) * x);
        }
    }
    sum
}

/// ∫∫ f(r, θ) r dr dθ over a ≤ r ≤ b: [`radial`] on `cells` cells × the
/// trapezoid rule on `n_theta` angles (exact for trigonometric polynomials of
/// degree below `n_theta`).
pub fn annulus(a: f64, b: f64, cells: usize, n_theta: usize, f: impl Fn(f64, f64) -> f64) -> f64 {
    radial(a, b, cells, |r| {
        let ring: f64 = (0..n_theta)
            .map(|j| f(r, TAU * j as f64 / n_theta as f64))
            .sum();
        r * ring * TAU / n_theta as f64
    })
}
