//! The in-plane frequencies of the spinning disc per k: the quadratic
//! eigenproblem of the turning-frame equations (S1) of [`super::spin`]
//! (docs/in_plane.md "Spinning").
//!
//! # Travelling waves
//!
//! For k ≥ 1 the cos and sin partners x_c, x_s obey
//! M ẍ_c + 2ΩB ẋ_s + K̃ x_c = 0 and M ẍ_s − 2ΩB ẋ_c + K̃ x_s = 0 with
//! K̃ = K + Ω² K_Ω; z = x_c − i x_s obeys M z̈ + 2iΩB ż + K̃ z = 0, and
//! z = y e^{iωt} with real y gives
//!
//! (K̃ − ω Ω Γ − ω² M) y = 0,  Γ = 2B,                             (S5)
//!
//! the wave u_r = U cos(kθ + ωt), u_θ = V sin(kθ + ωt): ω > 0 travels
//! against the spin in the turning frame (backward), ω < 0 with it
//! (forward, at |ω|). Seen from space (θ_space = θ + Ωt) the forward wave
//! has |ω| + kΩ, the backward one ω − kΩ, zero at a critical speed.
//!
//! For k = 0, x_r = y_r e^{iωt}, x_t = i y_t e^{iωt} give (S5) with
//! Γ = −2 [[0, C], [Cᵀ, 0]] over [radial; torsional]; its roots come in
//! pairs ±ω (no direction at k = 0), and the Coriolis force couples the
//! radial and torsional families.
//!
//! # Solution
//!
//! (S5) is A v = ω B v with v = (y, ω y/σ), A = [[K̃, 0], [0, σ M]],
//! B = [[Ω Γ, σ M], [M, 0]] (σ a shear-wave frequency of the annulus, to
//! balance the blocks); every ω follows from the eigenvalues μ of the dense
//! (A − s B)⁻¹ B as ω = s + 1/μ, the shift s placed among the lowest ω so
//! that they are the best resolved.
//!
//! # Rigid-body motions
//!
//! A free–free disc keeps them at speed (tests/in_plane_spinning.rs): the
//! rotation (k = 0) at ω = 0 and the translation (k = 1) at ω = +Ω, the
//! disc at rest in space seen from the turning frame, each a double root.
//! The two roots nearest those values are left out.

use super::{InPlaneDiscretisation, InPlaneEdge, InPlaneError, InPlaneFamily};
use crate::model::prestress::LamePrestress;
use faer::linalg::solvers::Solve;
use faer::Mat;

/// The matrices of (S5) for one k over the free coefficients.
#[derive(Debug, Clone)]
pub struct InPlaneSpectrum {
    k: u32,
    stiffness: Mat<f64>,
    mass: Mat<f64>,
    spin_stiffness: Mat<f64>,
    coriolis: Mat<f64>,
    /// σ, rad/s: √(G/ρ) over the annulus's width.
    scale: f64,
    free_free: bool,
}

/// The rotating-frame frequencies of one k at one spin speed, rad/s,
/// ascending, rigid-body motions left out. For k = 0 `forward` and
/// `backward` are the same list.
#[derive(Debug, Clone, PartialEq)]
pub struct InPlaneWaves {
    /// |ω| of the waves travelling with the spin.
    pub forward: Vec<f64>,
    /// ω of the waves travelling against it.
    pub backward: Vec<f64>,
}

impl InPlaneDiscretisation {
    /// The spinning spectrum of k with `prestress` (this discretisation's edges).
    pub fn spectrum(&self, k: u32, prestress: &LamePrestress) -> InPlaneSpectrum {
        let spin = self.assemble_spin(k, prestress);
        let blocks = super::spin_blocks(k);
        let sizes = blocks.map(|f| self.n_free(f));
        let n = sizes[0];
        let (stiffness, mass, coriolis) = if k == 0 {
            let (kr, mr) = self.assemble(0, InPlaneFamily::Radial);
            let (kt, mt) = self.assemble(0, InPlaneFamily::Torsional);
            let all = sizes[0] + sizes[1];
            let diag = |r: &Mat<f64>, t: &Mat<f64>| {
                Mat::<f64>::from_fn(all, all, |i, j| match (i < n, j < n) {
                    (true, true) => r[(i, j)],
                    (false, false) => t[(i - n, j - n)],
                    _ => 0.0,
                })
            };
            // Γ = [[0, G_rt], [−G_tr, 0]] from G = [[0, −2C], [2Cᵀ, 0]].
            let g = &spin.gyroscopic;
            let coriolis = Mat::<f64>::from_fn(all, all, |i, j| match (i < n, j < n) {
                (true, false) => g[(i, j)],
                (false, true) => -g[(i, j)],
                _ => 0.0,
            });
            (diag(&kr, &kt), diag(&mr, &mt), coriolis)
        } else {
            let (kc, mc) = self.assemble(k, InPlaneFamily::Coupled);
            // Γ = 2B, the cos rows' sin columns of G.
            let coriolis = Mat::<f64>::from_fn(n, n, |i, j| spin.gyroscopic[(i, n + j)]);
            (kc, mc, coriolis)
        };
        let m = stiffness.nrows();
        let spin_stiffness = Mat::<f64>::from_fn(m, m, |i, j| spin.spin_stiffness[(i, j)]);
        let p = self.plate();
        let width = p.outer_radius - p.inner_radius;
        InPlaneSpectrum {
            k,
            stiffness,
            mass,
            spin_stiffness,
            coriolis,
            scale: (p.shear_modulus() / p.density).sqrt() / width,
            free_free: p.inner_edge == InPlaneEdge::Free && p.outer_edge == InPlaneEdge::Free,
        }
    }
}

impl InPlaneSpectrum {
    /// The nodal-diameter number.
    pub fn k(&self) -> u32 {
        self.k
    }

    /// The `count` lowest forward and backward frequencies at spin speed Ω
    /// (rad/s, turning frame). An error when the discretisation has fewer,
    /// or when a root is not real (the disc would be unstable).
    pub fn waves(&self, spin: f64, count: usize) -> Result<InPlaneWaves, InPlaneError> {
        let mut roots = self.roots(spin)?;
        if self.free_free && self.k <= 1 {
            // The double rigid root may split into a complex pair by round-off.
            let rigid = if self.k == 0 { 0.0 } else { spin };
            let distance = |z: &faer::c64| (z - faer::c64::new(rigid, 0.0)).norm();
            for _ in 0..2 {
                let Some(nearest) = (0..roots.len())
                    .min_by(|&a, &b| distance(&roots[a]).total_cmp(&distance(&roots[b])))
                else {
                    return Err(InPlaneError::SpinEigen {
                        k: self.k,
                        spin,
                        reason: "fewer than the two rigid-body roots".to_string(),
                    });
                };
                roots.swap_remove(nearest);
            }
        }
        let sigma = self.scale;
        let mut real = Vec::with_capacity(roots.len());
        for z in roots {
            // Roots far above the lowest ones are poorly resolved and never asked for.
            if z.im.abs() > 1e-6 * z.re.abs().max(sigma) && z.norm() < 1e3 * sigma {
                return Err(InPlaneError::SpinEigen {
                    k: self.k,
                    spin,
                    reason: format!(
                        "a complex root {:e} {:+e}i rad/s (the disc is unstable at this speed)",
                        z.re, z.im
                    ),
                });
            }
            real.push(z.re);
        }
        let roots = real;
        let mut backward: Vec<f64> = roots.iter().copied().filter(|&w| w > 0.0).collect();
        let mut forward: Vec<f64> = if self.k == 0 {
            backward.clone()
        } else {
            roots.iter().filter(|&&w| w < 0.0).map(|w| -w).collect()
        };
        for list in [&mut forward, &mut backward] {
            list.sort_by(f64::total_cmp);
            if list.len() < count {
                return Err(InPlaneError::Orders {
                    orders: count,
                    max: list.len(),
                });
            }
            list.truncate(count);
        }
        Ok(InPlaneWaves { forward, backward })
    }

    /// Every root ω of (S5) at Ω (complex as computed), unordered.
    fn roots(&self, spin: f64) -> Result<Vec<faer::c64>, InPlaneError> {
        let n = self.stiffness.nrows();
        let sigma = self.scale;
        let s2 = spin * spin;
        let k_total =
            |i: usize, j: usize| self.stiffness[(i, j)] + s2 * self.spin_stiffness[(i, j)];
        let a = Mat::<f64>::from_fn(2 * n, 2 * n, |i, j| match (i < n, j < n) {
            (true, true) => k_total(i, j),
            (false, false) => sigma * self.mass[(i - n, j - n)],
            _ => 0.0,
        });
        let b = Mat::<f64>::from_fn(2 * n, 2 * n, |i, j| match (i < n, j < n) {
            (true, true) => spin * self.coriolis[(i, j)],
            (true, false) => sigma * self.mass[(i, j - n)],
            (false, true) => self.mass[(i - n, j)],
            (false, false) => 0.0,
        });
        // A shift below the lowest elastic root and off the rigid ones.
        let shift = -0.3 * sigma;
        let shifted = Mat::<f64>::from_fn(2 * n, 2 * n, |i, j| a[(i, j)] - shift * b[(i, j)]);
        let c = shifted.partial_piv_lu().solve(&b);
        let failed = |reason: String| InPlaneError::SpinEigen {
            k: self.k,
            spin,
            reason,
        };
        let mu = c.eigenvalues().map_err(|e| failed(format!("{e:?}")))?;
        let mut roots = Vec::with_capacity(mu.len());
        for z in mu {
            let omega = faer::c64::new(shift, 0.0) + 1.0 / faer::c64::new(z.re, z.im);
            if !(omega.re.is_finite() && omega.im.is_finite()) {
                return Err(failed(format!("a non-finite root {omega}")));
            }
            roots.push(omega);
        }
        Ok(roots)
    }
}
