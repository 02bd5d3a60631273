//! Centrifugal stiffening: the geometric stiffness of the Lamé prestress
//! ([`LamePrestress`]) per nodal-diameter number k, per unit Ω²
//! (docs/rotor_dynamics.md).
//!
//! Two forms:
//! - [`SpinningSpectrum`]: per k the radial B-spline eigenproblem
//!   (K̄ + Ω² K̄_g) v = ω² M̄ v of the whole radial basis — the rotating-frame
//!   frequencies of the spinning plate, converging in `plate.radial_splines`;
//!   `campbell` and the critical speeds use it.
//! - [`ModalGeometricStiffness`]: K̄_g projected on the retained modes of one
//!   k (it couples their l, never k with k' nor cos with sin): the matrix
//!   G_k[l, l'] = c_k h ∫ (σ_r R_l' R_l'' + σ_θ k² R_l R_l'/r²) r dr of the
//!   unit-peak radial shapes, per unit Ω². Its diagonal over the modal mass is
//!   the Southwell coefficient λ of each mode: ω² ≈ ω₀² + λ Ω² for small Ω.

use super::build::eigen_shift;
use super::eigen::lowest_modes;
use super::mindlin::{self, MindlinDiscretisation};
use super::prestress::LamePrestress;
use super::quadrature::radial_points;
use super::radial::{angular_norm, RadialDiscretisation};
use super::resolution::{self, lowest_pairs};
use super::{ModelError, PlateModel};
use crate::config::{CentrifugalConfig, PlateConfig, PlateTheory};
use faer::Mat;

/// Rotating-frame eigenvalues of one k over spin speed, in the full radial basis.
pub struct SpinningSpectrum {
    k: u32,
    stiffness: Mat<f64>,
    mass: Mat<f64>,
    geometric: Mat<f64>,
    shift: f64,
    count: usize,
    /// Mindlin's banded problem (shift-invert Lanczos where it is large).
    mindlin: bool,
}

impl SpinningSpectrum {
    /// The spectrum of nodal-diameter number k with the `count` lowest l.
    pub fn new(
        plate: &PlateConfig,
        centrifugal: &CentrifugalConfig,
        k: u32,
        count: usize,
    ) -> SpinningSpectrum {
        let prestress = LamePrestress::new(plate, centrifugal);
        let stresses = |r: f64| prestress.stresses(r);
        let mindlin = plate.theory == PlateTheory::Mindlin;
        let ((stiffness, mass), geometric, shift) = if mindlin {
            // `plate.radial_splines` per field, `auto` = `mindlin::DEFAULT_SPLINES`;
            // K̄_g acts on w alone (`MindlinDiscretisation::assemble_geometric`).
            // The centrifugal force on the face displacement z ψ (a softening of
            // the rotary inertia, O((h/r)²)) is left out, as in the modal
            // equations the simulation steps (docs/mindlin.md).
            let splines = plate
                .radial_splines
                .fixed()
                .unwrap_or(mindlin::DEFAULT_SPLINES);
            let mp = mindlin::mindlin_plate(plate);
            let disc = MindlinDiscretisation::new(&mp, splines)
                .expect("the model build has checked the Mindlin plate and its spline count");
            let geometric = disc.assemble_geometric(k, plate.thickness, stresses);
            (disc.assemble(k), geometric, mp.eigen_shift())
        } else {
            let rigidity =
                super::bending_rigidity(plate.youngs_modulus, plate.thickness, plate.poisson_ratio);
            let splines = spectrum_splines(plate, rigidity, k, count);
            let disc = RadialDiscretisation::new(plate, rigidity, splines);
            let geometric = disc.assemble_geometric(k, plate.thickness, stresses);
            (disc.assemble(k), geometric, eigen_shift(plate, rigidity))
        };
        SpinningSpectrum {
            k,
            stiffness,
            mass,
            geometric,
            shift,
            count,
            mindlin,
        }
    }

    /// The nodal-diameter number.
    pub fn k(&self) -> u32 {
        self.k
    }

    /// ω² (rad²/s², rotating frame) of l = 0, 1, … at spin speed Ω (rad/s).
    pub fn omega_squared(&self, spin: f64) -> Result<Vec<f64>, ModelError> {
        let s = spin * spin;
        let n = self.stiffness.nrows();
        let k_total = Mat::<f64>::from_fn(n, n, |i, j| {
            self.stiffness[(i, j)] + s * self.geometric[(i, j)]
        });
        let solve = if self.mindlin {
            lowest_pairs
        } else {
            lowest_modes
        };
        let pairs = solve(&k_total, &self.mass, self.shift, self.count).map_err(|e| {
            ModelError::Eigenproblem {
                k: self.k,
                reason: format!("spinning at {spin} rad/s: {e:?}"),
            }
        })?;
        Ok(pairs.omega_squared)
    }

    /// The critical speed of ⟨k, l⟩: the Ω > 0 where the backward wave stands
    /// still, ω_l(Ω) = kΩ; `None` for k = 0 or where the prestress keeps
    /// ω_l(Ω) > kΩ up to 10⁶ ω_l(0)/k. Bracketed, then bisected to 1e-12 relative.
    pub fn critical_speed(&self, l: usize) -> Result<Option<f64>, ModelError> {
        if self.k == 0 {
            return Ok(None);
        }
        let k2 = (self.k as f64).powi(2);
        let gap = |spin: f64| -> Result<f64, ModelError> {
            Ok(self.omega_squared(spin)?[l] - k2 * spin * spin)
        };
        let w0 = self.omega_squared(0.0)?[l].max(0.0).sqrt();
        let first = w0 / self.k as f64;
        let (mut lo, mut hi) = (0.0, first);
        while gap(hi)? > 0.0 {
            lo = hi;
            hi *= 2.0;
            if hi > 1e6 * first {
                return Ok(None);
            }
        }
        while hi - lo > 1e-12 * hi {
            let mid = 0.5 * (lo + hi);
            if gap(mid)? > 0.0 {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        Ok(Some(0.5 * (lo + hi)))
    }
}

/// The spline count of the spectrum of k: the fixed `plate.radial_splines`,
/// or with `auto` the count the model build chooses for k and `count` l at
/// rest (the largest `auto` uses if the tolerance is not reached there: the
/// model build itself refuses that plate, naming `plate.frequency_tolerance`).
fn spectrum_splines(plate: &PlateConfig, rigidity: f64, k: u32, count: usize) -> usize {
    if let Some(n) = plate.radial_splines.fixed() {
        return n;
    }
    let ls: Vec<u32> = (0..count as u32)
        .filter(|&l| !super::modes::is_rigid_body(plate.inner_boundary, plate.outer_boundary, k, l))
        .collect();
    let sigma = eigen_shift(plate, rigidity);
    let mut discs = resolution::Discretisations::new(plate, rigidity);
    resolution::choose(
        &mut discs,
        sigma,
        k,
        &ls,
        count,
        resolution::first_guess(plate),
    )
    .map_or(resolution::MAX_AUTO_SPLINES, |r| r.resolution.splines)
}

/// K̄_g projected on the retained modes, per k (per unit Ω²).
#[derive(Debug, Clone, PartialEq)]
pub struct ModalGeometricStiffness {
    /// The in-plane prestress of spinning, per unit Ω².
    pub prestress: LamePrestress,
    /// One block per retained k, ascending.
    pub blocks: Vec<GeometricBlock>,
}

/// The retained ⟨k, l⟩ of one k and their geometric stiffness.
#[derive(Debug, Clone, PartialEq)]
pub struct GeometricBlock {
    pub k: u32,
    /// The retained l, ascending, and their radial shapes (indices into [`PlateModel::radial_shapes`]).
    pub ls: Vec<u32>,
    pub radial: Vec<usize>,
    /// G[a·n + b] for l = ls[a], ls[b], N·m/(rad/s)² per unit peak amplitudes (row-major, symmetric).
    pub matrix: Vec<f64>,
}

impl ModalGeometricStiffness {
    /// Project the prestress of `centrifugal` on the retained modes of `model`.
    pub fn new(model: &PlateModel, centrifugal: &CentrifugalConfig) -> ModalGeometricStiffness {
        let plate = model.plate();
        let prestress = LamePrestress::new(plate, centrifugal);
        let shapes = model.radial_shapes();
        let mut ks: Vec<u32> = shapes.iter().map(|s| s.k).collect();
        ks.sort_unstable();
        ks.dedup();
        let blocks = ks
            .into_iter()
            .map(|k| {
                let mut radial: Vec<usize> =
                    (0..shapes.len()).filter(|&i| shapes[i].k == k).collect();
                radial.sort_by_key(|&i| shapes[i].l);
                let ls: Vec<u32> = radial.iter().map(|&i| shapes[i].l).collect();
                // The radial basis of this k (with `auto` each k has its own).
                let basis = shapes[radial[0]].basis();
                let mut points = Vec::new();
                for s in 0..basis.spans() {
                    let (lo, hi) = basis.span_bounds(s);
                    radial_points(lo, hi, &mut points);
                }
                let n = radial.len();
                let k2 = (k as f64).powi(2);
                let scale = angular_norm(k) * plate.thickness;
                let mut matrix = vec![0.0; n * n];
                for &(r, w) in &points {
                    let (sr, st) = prestress.stresses(r);
                    let vals: Vec<[f64; 4]> = radial.iter().map(|&i| shapes[i].eval(r)).collect();
                    for a in 0..n {
                        for b in 0..n {
                            let integrand = sr * vals[a][1] * vals[b][1]
                                + st * k2 * vals[a][0] * vals[b][0] / (r * r);
                            matrix[a * n + b] += scale * w * r * integrand;
                        }
                    }
                }
                GeometricBlock {
                    k,
                    ls,
                    radial,
                    matrix,
                }
            })
            .collect();
        ModalGeometricStiffness { prestress, blocks }
    }

    /// The block of nodal-diameter number k.
    pub fn block(&self, k: u32) -> Option<&GeometricBlock> {
        self.blocks.iter().find(|b| b.k == k)
    }

    /// Southwell coefficient λ = G_ll / m of ⟨k, l⟩ (first-order ω² = ω₀² + λΩ²).
    pub fn southwell(&self, model: &PlateModel, k: u32, l: u32) -> Option<f64> {
        let b = self.block(k)?;
        let a = b.ls.iter().position(|&x| x == l)?;
        let n = b.ls.len();
        let mode = model.modes().iter().find(|m| m.k == k && m.l == l)?;
        Some(b.matrix[a * n + a] / mode.modal_mass)
    }
}
