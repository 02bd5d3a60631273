//! φ-functions for exponential integrators: φ₁(z) = (eᶻ − 1)/z and φ₁'(z),
//! entire and evaluated without cancellation near z = 0.

use nalgebra::Complex;

type C = Complex<f64>;

const SERIES_RADIUS: f64 = 0.5;
const TERMS: usize = 18;

/// φ₁(z) = Σ zʲ/(j+1)!.
pub fn phi1(z: C) -> C {
    if z.norm() < SERIES_RADIUS {
        let mut sum = C::new(0.0, 0.0);
        for j in (0..TERMS).rev() {
            // Horner: 1 + z/2 (1 + z/3 (1 + …)).
            sum = sum * z / (j as f64 + 2.0) + C::new(1.0, 0.0);
        }
        sum
    } else {
        (z.exp() - 1.0) / z
    }
}

/// φ₁'(z) = Σ_{j≥1} j z^{j−1}/(j+1)!.
pub fn phi1_prime(z: C) -> C {
    if z.norm() < SERIES_RADIUS {
        let mut sum = C::new(0.0, 0.0);
        let mut pow = C::new(1.0, 0.0);
        let mut fact = 2.0; // (j+1)! for j = 1
        for j in 1..=TERMS {
            sum += pow * (j as f64) / fact;
            pow *= z;
            fact *= j as f64 + 2.0;
        }
        sum
    } else {
        (z.exp() * (z - 1.0) + 1.0) / (z * z)
    }
}

/// sinh(√y)/√y for real y (sin(√−y)/√−y for y < 0), and cosh(√y) (cos).
pub fn cosh_sinhc(y: f64) -> (f64, f64) {
    if y.abs() < 1e-2 {
        // Taylor in y: cosh √y = Σ yⁿ/(2n)!, sinh √y/√y = Σ yⁿ/(2n+1)!.
        let (mut c, mut s, mut t) = (0.0, 0.0, 1.0);
        for n in 0..8 {
            c += t / fact(2 * n);
            s += t / fact(2 * n + 1);
            t *= y;
        }
        (c, s)
    } else if y > 0.0 {
        let r = y.sqrt();
        (r.cosh(), r.sinh() / r)
    } else {
        let r = (-y).sqrt();
        (r.cos(), r.sin() / r)
    }
}

fn fact(n: usize) -> f64 {
    (1..=n).map(|i| i as f64).product()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn phi1_is_continuous_across_the_series_radius() {
        for &z in &[C::new(0.4999, 0.0), C::new(0.0, 0.4999), C::new(-0.3, 0.39)] {
            let inside = phi1(z);
            let outside = (z.exp() - 1.0) / z;
            assert!(
                (inside - outside).norm() < 1e-14,
                "{z}: {inside} vs {outside}"
            );
            let dp = phi1_prime(z);
            let dp_closed = (z.exp() * (z - 1.0) + 1.0) / (z * z);
            assert!((dp - dp_closed).norm() < 1e-12, "{z}: {dp} vs {dp_closed}");
        }
        assert_eq!(phi1(C::new(0.0, 0.0)), C::new(1.0, 0.0));
        assert!((phi1_prime(C::new(0.0, 0.0)) - C::new(0.5, 0.0)).norm() < 1e-16);
    }

    #[test]
    fn cosh_sinhc_matches_closed_forms() {
        for &y in &[-4.0, -0.009, 0.0, 0.009, 4.0] {
            let (c, s) = cosh_sinhc(y);
            let (ce, se) = if y > 0.0 {
                (y.sqrt().cosh(), y.sqrt().sinh() / y.sqrt())
            } else if y < 0.0 {
                ((-y).sqrt().cos(), (-y).sqrt().sin() / (-y).sqrt())
            } else {
                (1.0, 1.0)
            };
            assert!((c - ce).abs() < 1e-15 && (s - se).abs() < 1e-15, "{y}");
        }
    }
}
