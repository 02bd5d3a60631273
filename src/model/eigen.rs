//! The symmetric-definite generalized eigenproblem (14), K̄ v = ω² M̄ v.
//!
//! Solved in shifted-inverse form so that the low modes keep full relative
//! accuracy even when K̄ spans many orders of magnitude (tiny inner radius,
//! k up to 60, narrow rings): with A = K̄ + σM̄ = L Lᵀ (σ > 0, so A is
//! positive definite even for the rigid-body modes of a free–free plate),
//! C = L⁻¹ M̄ L⁻ᵀ has eigenvalues μ = 1/(ω² + σ); the largest μ, i.e. the
//! lowest ω², are the ones a symmetric eigensolver returns most accurately.

use super::ModelError;
use faer::linalg::solvers::{EvdError, LltError};
use faer::{Mat, Side};
use thiserror::Error;

/// Lowest eigenpairs of (K, M): ω² ascending, with M-orthonormal vectors as columns.
pub struct EigenPairs {
    pub omega_squared: Vec<f64>,
    pub vectors: Mat<f64>,
}

/// The envelope Cholesky factor of the Lanczos solver (`lanczos.rs`) met a
/// pivot that is not positive and finite.
#[derive(Debug, Clone, Copy, PartialEq, Error)]
#[error("pivot {pivot:e} at row {row} of {n}")]
pub struct PivotError {
    /// The pivot's value before its square root.
    pub pivot: f64,
    /// Its row (of the reversed order).
    pub row: usize,
    /// The matrix order.
    pub n: usize,
}

/// Why a Cholesky factor failed: faer's dense one, or the envelope factor
/// of the Lanczos solver.
#[derive(Debug, Clone, Copy, Error)]
pub enum CholeskyError {
    /// faer's dense LLᵀ.
    #[error("{0:?}")]
    Dense(LltError),
    /// The Lanczos solver's envelope factor.
    #[error(transparent)]
    Envelope(#[from] PivotError),
}

/// Why the eigenproblem failed.
#[derive(Debug, Clone, Copy, Error)]
pub enum EigenFailure {
    /// M̄ has no Cholesky factor (the basis is degenerate).
    #[error("the mass matrix is not positive definite: {0}")]
    MassNotPositiveDefinite(CholeskyError),
    /// K̄ + σM̄ has no Cholesky factor.
    #[error("the shifted matrix is not positive definite: {0}")]
    ShiftedNotPositiveDefinite(CholeskyError),
    /// The symmetric eigensolver did not converge.
    #[error("the eigendecomposition failed: {0:?}")]
    Decomposition(EvdError),
}

impl EigenFailure {
    /// The model error of this failure for nodal diameter `k`.
    pub fn for_k(self, k: u32) -> ModelError {
        match self {
            EigenFailure::MassNotPositiveDefinite(e) => ModelError::MassNotPositiveDefinite {
                k,
                reason: e.to_string(),
            },
            EigenFailure::ShiftedNotPositiveDefinite(e) => ModelError::Eigenproblem {
                k,
                reason: e.to_string(),
            },
            EigenFailure::Decomposition(e) => ModelError::Eigenproblem {
                k,
                reason: format!("{e:?}"),
            },
        }
    }
}

/// The `count` lowest eigenpairs of K v = ω² M v with shift `sigma` > 0.
pub fn lowest_modes(
    k: &Mat<f64>,
    m: &Mat<f64>,
    sigma: f64,
    count: usize,
) -> Result<EigenPairs, EigenFailure> {
    let n = k.nrows();
    let count = count.min(n);
    m.llt(Side::Lower)
        .map_err(|e| EigenFailure::MassNotPositiveDefinite(CholeskyError::Dense(e)))?;
    let a = Mat::<f64>::from_fn(n, n, |i, j| k[(i, j)] + sigma * m[(i, j)]);
    let llt = a
        .llt(Side::Lower)
        .map_err(|e| EigenFailure::ShiftedNotPositiveDefinite(CholeskyError::Dense(e)))?;
    let l = llt.L();
    // C = L⁻¹ M L⁻ᵀ: X = L⁻¹ M, then C = (L⁻¹ Xᵀ)ᵀ = L⁻¹ M L⁻ᵀ (M symmetric).
    let mut x = m.to_owned();
    faer::linalg::triangular_solve::solve_lower_triangular_in_place(l, x.as_mut(), faer::Par::Seq);
    let mut xt = x.transpose().to_owned();
    faer::linalg::triangular_solve::solve_lower_triangular_in_place(l, xt.as_mut(), faer::Par::Seq);
    let c = Mat::<f64>::from_fn(n, n, |i, j| 0.5 * (xt[(i, j)] + xt[(j, i)]));
    let evd = c
        .self_adjoint_eigen(Side::Lower)
        .map_err(EigenFailure::Decomposition)?;
    let s = evd.S();
    let u = evd.U();
    // Ascending μ from faer: the largest μ (lowest ω²) are last.
    let mut omega_squared = Vec::with_capacity(count);
    let mut vectors = Mat::<f64>::zeros(n, count);
    for (col, idx) in (0..count).map(|c| (c, n - 1 - c)) {
        let mu = s[idx];
        omega_squared.push(1.0 / mu - sigma);
        // v = L⁻ᵀ y; then scale so that vᵀ M v = 1.
        let mut y = Mat::<f64>::from_fn(n, 1, |i, _| u[(i, idx)]);
        faer::linalg::triangular_solve::solve_upper_triangular_in_place(
            l.transpose(),
            y.as_mut(),
            faer::Par::Seq,
        );
        let mv = m * &y;
        let norm2: f64 = (0..n).map(|i| y[(i, 0)] * mv[(i, 0)]).sum();
        let scale = 1.0 / norm2.sqrt();
        for i in 0..n {
            vectors[(i, col)] = y[(i, 0)] * scale;
        }
    }
    Ok(EigenPairs {
        omega_squared,
        vectors,
    })
}
