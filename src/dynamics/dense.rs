//! Small dense linear solves on caller-owned scratch (no allocation): the
//! contacts in series with the residual flexibility (`contact_compliance.rs`)
//! and the stiffened implicit midpoint rule's per-k blocks.

use thiserror::Error;

/// Why [`lu_factor`] could not factor a matrix.
#[derive(Debug, Clone, Copy, PartialEq, Error)]
pub enum LuError {
    /// Every candidate pivot of a column is zero: the matrix is singular.
    #[error("singular: no non-zero pivot in column {column} of {n}")]
    ZeroPivot { column: usize, n: usize },
    /// The largest candidate pivot of a column is not finite.
    #[error("pivot {pivot:e} in column {column} of {n} is not finite")]
    NonFinitePivot { column: usize, pivot: f64, n: usize },
}

/// LU factors of A (row-major n × n, in place) with partial pivoting:
/// P A = L U, `perm[i]` the row of A in row i. An error if a column has no
/// usable pivot (A singular, or not finite).
pub fn lu_factor(a: &mut [f64], perm: &mut [usize], n: usize) -> Result<(), LuError> {
    for (i, p) in perm.iter_mut().enumerate() {
        *p = i;
    }
    for col in 0..n {
        let pivot = (col..n)
            .max_by(|&i, &j| a[i * n + col].abs().total_cmp(&a[j * n + col].abs()))
            .unwrap_or(col);
        let value = a[pivot * n + col];
        if value == 0.0 {
            return Err(LuError::ZeroPivot { column: col, n });
        }
        if !value.is_finite() {
            return Err(LuError::NonFinitePivot {
                column: col,
                pivot: value,
                n,
            });
        }
        if pivot != col {
            for j in 0..n {
                a.swap(col * n + j, pivot * n + j);
            }
            perm.swap(col, pivot);
        }
        let p = a[col * n + col];
        for i in col + 1..n {
            let factor = a[i * n + col] / p;
            a[i * n + col] = factor;
            if factor != 0.0 {
                for j in col + 1..n {
                    a[i * n + j] -= factor * a[col * n + j];
                }
            }
        }
    }
    Ok(())
}

/// Solve A x = b with the factors of [`lu_factor`]; b becomes x (`buf`: n values of scratch).
pub fn lu_solve(lu: &[f64], perm: &[usize], b: &mut [f64], buf: &mut [f64], n: usize) {
    // Slices instead of indices (no bounds checks in the loops); the same
    // operations in the same order.
    let (lu, buf) = (&lu[..n * n], &mut buf[..n]);
    for (x, &p) in buf.iter_mut().zip(&perm[..n]) {
        *x = b[p];
    }
    for (i, row) in lu.chunks_exact(n).enumerate() {
        let (solved, rest) = buf.split_at_mut(i);
        let mut v = rest[0];
        for (l, x) in row[..i].iter().zip(solved.iter()) {
            v -= l * x;
        }
        rest[0] = v;
    }
    for (i, row) in lu.chunks_exact(n).enumerate().rev() {
        let (head, solved) = buf.split_at_mut(i + 1);
        let mut v = head[i];
        for (u, x) in row[i + 1..].iter().zip(solved.iter()) {
            v -= u * x;
        }
        head[i] = v / row[i];
    }
    b[..n].copy_from_slice(buf);
}
