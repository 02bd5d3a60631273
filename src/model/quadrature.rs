//! Gauss–Legendre quadrature on an interval, with geometric subdivision where
//! the 1/r terms of the plate energy vary strongly (spans close to r = 0).

/// 6-point Gauss–Legendre nodes and weights on [−1, 1] (exact to degree 11).
const NODES: [f64; 6] = [
    -0.932_469_514_203_152,
    -0.661_209_386_466_264_5,
    -0.238_619_186_083_196_9,
    0.238_619_186_083_196_9,
    0.661_209_386_466_264_5,
    0.932_469_514_203_152,
];
const WEIGHTS: [f64; 6] = [
    0.171_324_492_379_170_3,
    0.360_761_573_048_138_6,
    0.467_913_934_572_691,
    0.467_913_934_572_691,
    0.360_761_573_048_138_6,
    0.171_324_492_379_170_3,
];

/// Largest ratio r_max / r_min of one quadrature cell. The integrands carry
/// r^-3 at worst; with this ratio six points integrate them to ~1e-13.
const MAX_RADIUS_RATIO: f64 = 1.25;

/// Quadrature points (r, weight) covering [a, b] (0 < a < b): six
/// Gauss–Legendre points per cell, cells split geometrically so that each
/// spans at most a radius ratio of 1.25.
pub fn radial_points(a: f64, b: f64, out: &mut Vec<(f64, f64)>) {
    debug_assert!(a > 0.0 && b > a);
    let cells = ((b / a).ln() / MAX_RADIUS_RATIO.ln()).ceil().max(1.0) as usize;
    let ratio = (b / a).powf(1.0 / cells as f64);
    let mut lo = a;
    for c in 0..cells {
        let hi = if c + 1 == cells { b } else { lo * ratio };
        let mid = 0.5 * (lo + hi);
        let half = 0.5 * (hi - lo);
        for (x, w) in NODES.iter().zip(WEIGHTS.iter()) {
            out.push((mid + half * x, half * w));
        }
        lo = hi;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn integrates_inverse_cube_near_zero() {
        let (a, b) = (1e-4, 0.01);
        let mut pts = vec![];
        radial_points(a, b, &mut pts);
        let s: f64 = pts.iter().map(|(r, w)| w / (r * r * r)).sum();
        let exact = 0.5 * (1.0 / (a * a) - 1.0 / (b * b));
        assert!(((s - exact) / exact).abs() < 1e-12, "{s} vs {exact}");
    }

    #[test]
    fn integrates_polynomials_exactly() {
        let mut pts = vec![];
        radial_points(0.5, 0.8, &mut pts);
        let s: f64 = pts.iter().map(|(r, w)| w * r.powi(11)).sum();
        let exact = (0.8f64.powi(12) - 0.5f64.powi(12)) / 12.0;
        assert!(((s - exact) / exact).abs() < 1e-14);
    }
}
