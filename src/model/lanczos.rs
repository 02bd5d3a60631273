//! The lowest eigenpairs of the radial eigenproblem (14), K̄ v = ω² M̄ v, for
//! many B-splines: shift-invert Lanczos on a sparse (envelope) Cholesky factor.
//!
//! Same operator as [`super::eigen::lowest_modes`]: with A = K̄ + σM̄ = L Lᵀ,
//! C = L⁻¹ M̄ L⁻ᵀ has eigenvalues μ = 1/(ω² + σ), and the lowest ω² are the
//! largest μ. The dense solver reduces all of C (O(n³)); here C is only
//! applied to vectors (two triangular solves and a product with M̄, O(n) for
//! the banded B-spline matrices), and a Lanczos recurrence with full
//! reorthogonalisation finds the largest μ to a residual of
//! [`RESIDUAL_TOLERANCE`] (O(n m²) for m steps, m ≈ 2 × count + 20).
//! Used by the `auto` radial resolution (docs/convergence.md).
//!
//! The matrices are stored by their envelope in reversed order (index
//! n − 1 − i): the cubic B-spline matrices are banded (|i − j| ≤ 3), and a
//! free–free ring's two rigid-like functions (slots 0 and 1, coupled to every
//! B-spline) become the last two rows, so L keeps the envelope of A.

use super::eigen::{CholeskyError, EigenFailure, EigenPairs, PivotError};
use faer::{Mat, Side};

/// Ritz pairs are accepted when ‖C u − θ u‖ ≤ this × θ.
pub const RESIDUAL_TOLERANCE: f64 = 1e-11;

/// A symmetric matrix by the envelope of its lower triangle, in reversed order.
struct Envelope {
    /// first[i]: the first column of row i with a non-zero entry (≤ i).
    first: Vec<usize>,
    /// start[i]: offset of row i's entries (columns first[i]..=i) in `values`.
    start: Vec<usize>,
    values: Vec<f64>,
}

impl Envelope {
    /// The envelopes of the reversed matrices a + shift·b and b (A'(i, j) =
    /// a(n−1−i, n−1−j)), over the union of their non-zero patterns.
    fn reversed_pair(a: &Mat<f64>, b: &Mat<f64>, shift: f64) -> (Envelope, Envelope) {
        let n = a.nrows();
        let rev = |m: &Mat<f64>, i: usize, j: usize| m[(n - 1 - i, n - 1 - j)];
        let mut first = Vec::with_capacity(n);
        let mut start = Vec::with_capacity(n);
        let (mut va, mut vb) = (Vec::new(), Vec::new());
        for i in 0..n {
            let f = (0..i)
                .find(|&j| rev(a, i, j) != 0.0 || rev(b, i, j) != 0.0)
                .unwrap_or(i);
            first.push(f);
            start.push(va.len());
            va.extend((f..=i).map(|j| rev(a, i, j) + shift * rev(b, i, j)));
            vb.extend((f..=i).map(|j| rev(b, i, j)));
        }
        (
            Envelope {
                first: first.clone(),
                start: start.clone(),
                values: va,
            },
            Envelope {
                first,
                start,
                values: vb,
            },
        )
    }

    fn n(&self) -> usize {
        self.first.len()
    }

    fn get(&self, i: usize, j: usize) -> f64 {
        debug_assert!(j <= i);
        if j < self.first[i] {
            0.0
        } else {
            self.values[self.start[i] + j - self.first[i]]
        }
    }

    /// y = A x (A symmetric, stored by its lower envelope).
    fn mul(&self, x: &[f64], y: &mut [f64]) {
        y.iter_mut().for_each(|v| *v = 0.0);
        for i in 0..self.n() {
            let f = self.first[i];
            let row = &self.values[self.start[i]..=self.start[i] + i - f];
            let mut s = row[i - f] * x[i];
            for (j, &a) in (f..i).zip(row) {
                s += a * x[j];
                y[j] += a * x[i];
            }
            y[i] += s;
        }
    }

    /// Cholesky factor A = L Lᵀ in place (L keeps the envelope of A).
    fn factor(mut self) -> Result<Envelope, PivotError> {
        for i in 0..self.n() {
            let fi = self.first[i];
            for j in fi..=i {
                let fj = self.first[j].max(fi);
                let mut s = self.get(i, j);
                for m in fj..j {
                    s -= self.get(i, m) * self.get(j, m);
                }
                let idx = self.start[i] + j - fi;
                if j < i {
                    self.values[idx] = s / self.get(j, j);
                } else if s > 0.0 && s.is_finite() {
                    self.values[idx] = s.sqrt();
                } else {
                    return Err(PivotError {
                        pivot: s,
                        row: i,
                        n: self.n(),
                    });
                }
            }
        }
        Ok(self)
    }

    /// x ← L⁻¹ x.
    fn solve_lower(&self, x: &mut [f64]) {
        for i in 0..self.n() {
            let f = self.first[i];
            let row = &self.values[self.start[i]..=self.start[i] + i - f];
            let s: f64 = (f..i).zip(row).map(|(j, &l)| l * x[j]).sum();
            x[i] = (x[i] - s) / row[i - f];
        }
    }

    /// x ← L⁻ᵀ x.
    fn solve_upper(&self, x: &mut [f64]) {
        for i in (0..self.n()).rev() {
            let f = self.first[i];
            let row = &self.values[self.start[i]..=self.start[i] + i - f];
            x[i] /= row[i - f];
            let xi = x[i];
            for (j, &l) in (f..i).zip(row) {
                x[j] -= l * xi;
            }
        }
    }
}

fn dot(a: &[f64], b: &[f64]) -> f64 {
    a.iter().zip(b).map(|(x, y)| x * y).sum()
}

/// The `count` lowest eigenpairs of K v = ω² M v with shift `sigma` > 0
/// (ω² ascending, M-orthonormal vectors), or `None` when the recurrence
/// cannot deliver them (an invariant subspace before `count` converged
/// pairs); the caller then solves densely.
pub fn lowest_modes_lanczos(
    k: &Mat<f64>,
    m: &Mat<f64>,
    sigma: f64,
    count: usize,
) -> Result<Option<EigenPairs>, EigenFailure> {
    let n = k.nrows();
    let count = count.min(n);
    let (shifted, mass) = Envelope::reversed_pair(k, m, sigma);
    mass.clone_factor()
        .map_err(|e| EigenFailure::MassNotPositiveDefinite(CholeskyError::Envelope(e)))?;
    let l = shifted
        .factor()
        .map_err(|e| EigenFailure::ShiftedNotPositiveDefinite(CholeskyError::Envelope(e)))?;
    let apply = |q: &[f64], out: &mut [f64], tmp: &mut [f64]| {
        tmp.copy_from_slice(q);
        l.solve_upper(tmp);
        mass.mul(tmp, out);
        l.solve_lower(out);
    };
    // Deterministic start vector with every component non-zero.
    let mut seed = 0x9E37_79B9_7F4A_7C15u64;
    let mut q0: Vec<f64> = (0..n)
        .map(|_| {
            seed = seed
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            0.5 + (seed >> 11) as f64 / (1u64 << 53) as f64
        })
        .collect();
    let norm = dot(&q0, &q0).sqrt();
    q0.iter_mut().for_each(|x| *x /= norm);
    let mut basis: Vec<Vec<f64>> = vec![q0];
    let (mut alpha, mut beta): (Vec<f64>, Vec<f64>) = (Vec::new(), Vec::new());
    let mut w = vec![0.0; n];
    let mut tmp = vec![0.0; n];
    let mut next_check = (count + 10).min(n);
    loop {
        let j = basis.len() - 1;
        apply(&basis[j], &mut w, &mut tmp);
        let a = dot(&basis[j], &w);
        alpha.push(a);
        // Full reorthogonalisation (classical Gram–Schmidt against every
        // vector), repeated while it removes more than half of w ("twice is
        // enough", Parlett ch. 6.9).
        w.iter_mut().zip(&basis[j]).for_each(|(x, y)| *x -= a * y);
        if j > 0 {
            let (bp, qp) = (beta[j - 1], &basis[j - 1]);
            w.iter_mut().zip(qp).for_each(|(x, y)| *x -= bp * y);
        }
        let mut b = dot(&w, &w).sqrt();
        for _ in 0..3 {
            let before = b;
            for q in &basis {
                let c = dot(q, &w);
                w.iter_mut().zip(q).for_each(|(x, y)| *x -= c * y);
            }
            b = dot(&w, &w).sqrt();
            if b > 0.5 * before {
                break;
            }
        }
        let steps = j + 1;
        if steps >= next_check || steps == n || b <= 1e-13 * a.abs() {
            let recurrence = Recurrence {
                alpha: &alpha,
                beta: &beta,
                b_last: b,
                basis: &basis,
            };
            if let Some(pairs) = ritz_pairs(recurrence, count, &l, &mass, sigma)? {
                return Ok(Some(pairs));
            }
            if steps == n || b <= 1e-13 * a.abs() {
                return Ok(None);
            }
            next_check = (steps + 3).min(n);
        }
        beta.push(b);
        basis.push(w.iter().map(|x| x / b).collect());
    }
}

impl Envelope {
    /// Factor a copy (only to check positive definiteness).
    fn clone_factor(&self) -> Result<Envelope, PivotError> {
        Envelope {
            first: self.first.clone(),
            start: self.start.clone(),
            values: self.values.clone(),
        }
        .factor()
    }
}

/// The Lanczos recurrence after m steps: the tridiagonal T's diagonal α and
/// off-diagonal β, the norm of the next residual and the m basis vectors.
struct Recurrence<'a> {
    alpha: &'a [f64],
    beta: &'a [f64],
    b_last: f64,
    basis: &'a [Vec<f64>],
}

/// The `count` largest Ritz pairs of the tridiagonal (α, β) if all have
/// converged (residual `b_last |s_last|` ≤ [`RESIDUAL_TOLERANCE`] θ), mapped
/// back to ω² and M-normalised eigenvectors of the original order (`l` the
/// factor of K + σM, `mass` M).
fn ritz_pairs(
    recurrence: Recurrence<'_>,
    count: usize,
    l: &Envelope,
    mass: &Envelope,
    sigma: f64,
) -> Result<Option<EigenPairs>, EigenFailure> {
    let Recurrence {
        alpha,
        beta,
        b_last,
        basis,
    } = recurrence;
    let m = alpha.len();
    if m < count {
        return Ok(None);
    }
    let t = Mat::<f64>::from_fn(m, m, |i, j| {
        if i == j {
            alpha[i]
        } else if i + 1 == j {
            beta[i]
        } else if j + 1 == i {
            beta[j]
        } else {
            0.0
        }
    });
    let evd = t
        .self_adjoint_eigen(Side::Lower)
        .map_err(EigenFailure::Decomposition)?;
    let (s, u) = (evd.S(), evd.U());
    let wanted: Vec<usize> = (0..count).map(|c| m - 1 - c).collect();
    if wanted
        .iter()
        .any(|&idx| (b_last * u[(m - 1, idx)]).abs() > RESIDUAL_TOLERANCE * s[idx].abs())
    {
        return Ok(None);
    }
    let n = l.n();
    let mut omega_squared = Vec::with_capacity(count);
    let mut vectors = Mat::<f64>::zeros(n, count);
    let mut y = vec![0.0; n];
    let mut my = vec![0.0; n];
    for (col, &idx) in wanted.iter().enumerate() {
        omega_squared.push(1.0 / s[idx] - sigma);
        y.iter_mut().for_each(|v| *v = 0.0);
        for (q, c) in basis.iter().zip((0..m).map(|r| u[(r, idx)])) {
            y.iter_mut().zip(q).for_each(|(v, x)| *v += c * x);
        }
        l.solve_upper(&mut y);
        mass.mul(&y, &mut my);
        let scale = 1.0 / dot(&y, &my).sqrt();
        for i in 0..n {
            vectors[(n - 1 - i, col)] = y[i] * scale;
        }
    }
    Ok(Some(EigenPairs {
        omega_squared,
        vectors,
    }))
}
