//! Residual flexibility of truncated Mindlin modes over load patches
//! (docs/residual_flexibility.md, "Under Mindlin theory").
//!
//! A Mindlin plate's deflection under a point force is infinite at the force
//! (the shear part −F ln ρ / (2π κGh)), so under Mindlin theory a node with
//! residual flexibility stands for a small load patch: the annular sector
//! |r − r₀| ≤ c (clipped to [r_i, r_a]), |θ − θ₀| ≤ β = min(c/r₀, π), with
//! c = `plate.residual_patch_radius`. Its transverse force is spread
//! uniformly per unit area over the patch and its deflection is the patch
//! mean: the two are work-conjugate, so the compliance is symmetric
//! (Maxwell–Betti). Per harmonic k the mean of W(r) cos kθ over the patch is
//!
//! W̄ cos kθ₀ · sinc kβ,  W̄ = ∫ W r dr / ∫ r dr over [r₀ − c, r₀ + c] ∩ [r_i, r_a],
//!
//! and a force F on the patch has the generalised force F W̄ sinc kβ on the
//! mode — the same number. The static compliance between patches a and b
//! is, as the point-force series of [`crate::model::residual`],
//!
//! C = Σ_k s_k(a) s_k(b) m_aᵀ K̄_k⁻¹ m_b cos kΔθ,  s_k = sinc kβ,
//!
//! with K̄_k the Mindlin stiffness of the weak form in [`super`] (with c_k) on
//! the modes' own B-splines and m the patch means of the W B-splines (the
//! load vector of a uniform patch load). The retained modes carry
//! Σ_l s_a s_b W̄_kl(a) W̄_kl(b) / K_kl of each harmonic, the residual is the
//! rest. With the patch the terms fall like k⁻⁴ (sinc² times the shear
//! compliance r²/(κGh k²)); they are summed until the envelope of what is
//! left is below [`TOLERANCE`] of the compliance (no fitted tail).
//!
//! K̄_k / c_k = Σ_{p=0}^{4} k^p K_p for k ≥ 1 (the strains are quadratic in
//! k): the five band matrices are assembled once and each k costs one band
//! Cholesky (bandwidth ≤ 11 for the interleaved coefficients).
//!
//! A free–free plate has no static solution for k = 0, 1 (rigid-body
//! motions): those harmonics get no residual, as for Kirchhoff.

use super::assembly::{Kinematics, W};
use super::MindlinDiscretisation;
pub use crate::model::patch::LoadPatch;
use crate::model::patch::{band_cholesky, band_solve, breakpoints, remainder_below};
use crate::model::radial::angular_norm;
use crate::model::{AngularShape, ModelError, PlateModel, ResidualKernel};

/// The most harmonics summed.
pub const MAX_HARMONICS: u32 = 8192;
/// The series stops when the envelope of its remainder is below this
/// fraction of the static compliance at every patch (the bench disc: 400–800
/// harmonics; tests/mindlin_residual_flexibility.rs measures the sum within
/// 4e-7 of the exact series).
pub const TOLERANCE: f64 = 1e-8;

/// Symmetric band matrix: a[i][d] = A(i, i + d), d = 0..=bw.
type Band = Vec<Vec<f64>>;

/// The static Mindlin harmonics between all pairs of a set of patches.
#[derive(Debug, Clone)]
pub struct PatchHarmonics {
    /// The patches.
    pub patches: Vec<LoadPatch>,
    /// g[k][a · n + b] = s_k(a) s_k(b) m_aᵀ K̄_k⁻¹ m_b, m/N.
    g: Vec<Vec<f64>>,
    /// Harmonics without a static solution (free–free k = 0, 1).
    pub skipped: Vec<u32>,
}

impl PatchHarmonics {
    /// The harmonic k between patches a and b, m/N (0 for a skipped one).
    pub fn get(&self, k: u32, a: usize, b: usize) -> f64 {
        self.g[k as usize][a * self.patches.len() + b]
    }

    /// The number of harmonics summed (k = 0..len).
    pub fn len(&self) -> usize {
        self.g.len()
    }

    /// No harmonics (never: k = 0 is always there).
    pub fn is_empty(&self) -> bool {
        self.g.is_empty()
    }

    /// The static compliance between patches a and b at angle difference Δθ, m/N.
    pub fn compliance(&self, a: usize, b: usize, delta: f64) -> f64 {
        (0..self.len() as u32)
            .map(|k| self.get(k, a, b) * (k as f64 * delta).cos())
            .sum()
    }
}

/// The stiffness of the free coefficients of k = 0 (one band) or of k ≥ 1
/// (K_p, p = 0..=4, with K̄_k / c_k = Σ k^p K_p), with the free columns.
struct PowerBands {
    columns: Vec<Vec<(usize, f64)>>,
    bw: usize,
    parts: Vec<Band>,
}

impl PowerBands {
    fn new(disc: &MindlinDiscretisation, harmonic: bool) -> PowerBands {
        let k_struct = u32::from(harmonic);
        let fields = MindlinDiscretisation::fields(k_struct);
        let n_all = fields * disc.basis().len();
        let columns = disc.free_columns(k_struct);
        let mut carriers: Vec<Vec<(usize, f64)>> = vec![Vec::new(); n_all];
        for (a, col) in columns.iter().enumerate() {
            for &(g, t) in col {
                carriers[g].push((a, t));
            }
        }
        let n = columns.len();
        let mut bw = 0;
        for s in 0..disc.basis().spans() {
            let frees = (0..fields)
                .flat_map(|f| (0..4).map(move |j| MindlinDiscretisation::index(k_struct, f, s + j)))
                .flat_map(|g| carriers[g].iter().map(|c| c.0));
            let (lo, hi) = frees.fold((usize::MAX, 0), |(lo, hi), a| (lo.min(a), hi.max(a)));
            if hi >= lo {
                bw = bw.max(hi - lo);
            }
        }
        let powers = if harmonic { 5 } else { 1 };
        let mut parts: Vec<Band> = vec![vec![vec![0.0; bw + 1]; n]; powers];
        let p = disc.plate();
        let (d, nu, shear) = (p.rigidity(), p.poisson_ratio, p.shear_stiffness());
        let form = |bi: &[f64; 5], bj: &[f64; 5]| {
            d * (bi[0] * bj[0]
                + bi[1] * bj[1]
                + nu * (bi[0] * bj[1] + bi[1] * bj[0])
                + 0.5 * (1.0 - nu) * bi[2] * bj[2])
                + shear * (bi[3] * bj[3] + bi[4] * bj[4])
        };
        // Per function: the strains' coefficients of k⁰, k¹, k².
        let mut local: Vec<(usize, [[f64; 5]; 3])> = Vec::with_capacity(12);
        for q in disc.points() {
            local.clear();
            for field in 0..fields {
                for j in 0..4 {
                    let f = [q.ders[0][j], q.ders[1][j], q.ders[2][j]];
                    let at = |k: f64| -> [f64; 5] {
                        let (b, _): Kinematics =
                            MindlinDiscretisation::kinematics(field, k, q.r, f);
                        b
                    };
                    let (s0, sp, sm) = (at(0.0), at(1.0), at(-1.0));
                    let c1 = std::array::from_fn(|i| 0.5 * (sp[i] - sm[i]));
                    let c2 = std::array::from_fn(|i| 0.5 * (sp[i] + sm[i]) - s0[i]);
                    local.push((
                        MindlinDiscretisation::index(k_struct, field, q.span + j),
                        [s0, c1, c2],
                    ));
                }
            }
            let w = q.weight * q.r;
            for &(gi, si) in &local {
                for &(gj, sj) in &local {
                    for (pi, bi) in si.iter().enumerate().take(if harmonic { 3 } else { 1 }) {
                        for (pj, bj) in sj.iter().enumerate().take(if harmonic { 3 } else { 1 }) {
                            let value = w * form(bi, bj);
                            if value == 0.0 {
                                continue;
                            }
                            for &(a, ta) in &carriers[gi] {
                                for &(b, tb) in &carriers[gj] {
                                    if b >= a {
                                        parts[pi + pj][a][b - a] += ta * tb * value;
                                    }
                                }
                            }
                        }
                    }
                }
            }
        }
        PowerBands { columns, bw, parts }
    }

    /// The load vector of a patch over the free coefficients: the patch
    /// means m_j of the W B-splines, carried by each free column.
    fn load(&self, disc: &MindlinDiscretisation, harmonic: bool, patch: &LoadPatch) -> Vec<f64> {
        let k_struct = u32::from(harmonic);
        let basis = disc.basis();
        let mut global = vec![0.0; MindlinDiscretisation::fields(k_struct) * basis.len()];
        for (j, m) in patch.spline_means(basis).into_iter().enumerate() {
            global[MindlinDiscretisation::index(k_struct, W, j)] = m;
        }
        self.columns
            .iter()
            .map(|col| col.iter().map(|&(g, t)| t * global[g]).sum())
            .collect()
    }

    /// Cholesky factor of c_k Σ k^p K_p ([`band_cholesky`]); None if not
    /// positive definite.
    fn factor(&self, k: u32, l: &mut Vec<f64>) -> Option<()> {
        let ck = angular_norm(k);
        let kf = k as f64;
        let powers: Vec<f64> = (0..self.parts.len())
            .map(|p| ck * kf.powi(p as i32))
            .collect();
        let entry = |j: usize, d: usize| -> f64 {
            self.parts
                .iter()
                .zip(&powers)
                .map(|(part, c)| c * part[j][d])
                .sum()
        };
        band_cholesky(self.columns.len(), self.bw, entry, l)
    }
}

/// The static Mindlin harmonics between all pairs of `patches`, summed to
/// `TOLERANCE` (module doc).
pub fn patch_harmonics(disc: &MindlinDiscretisation, patches: &[LoadPatch]) -> PatchHarmonics {
    let plate = disc.plate();
    let free_free = plate.inner_edge == super::MindlinEdge::Free
        && plate.outer_edge == super::MindlinEdge::Free;
    let np = patches.len();
    let (mut g, mut skipped) = (Vec::new(), Vec::new());
    let mut l = Vec::new();
    let mut totals = vec![0.0; np];
    for harmonic in [false, true] {
        let bands = PowerBands::new(disc, harmonic);
        let loads: Vec<Vec<f64>> = patches
            .iter()
            .map(|p| bands.load(disc, harmonic, p))
            .collect();
        let mut k = u32::from(harmonic);
        loop {
            let mut gk = vec![0.0; np * np];
            if (free_free && k <= 1) || bands.factor(k, &mut l).is_none() {
                skipped.push(k);
                g.push(gk);
            } else {
                for b in 0..np {
                    let mut x = loads[b].clone();
                    band_solve(&l, bands.bw, &mut x);
                    for a in 0..np {
                        let v: f64 = loads[a].iter().zip(&x).map(|(u, v)| u * v).sum();
                        gk[a * np + b] = v;
                    }
                }
                for a in 0..np {
                    for b in a + 1..np {
                        let m = 0.5 * (gk[a * np + b] + gk[b * np + a]);
                        gk[a * np + b] = m;
                        gk[b * np + a] = m;
                    }
                }
                let raw: Vec<f64> = (0..np).map(|a| gk[a * np + a]).collect();
                for a in 0..np {
                    for b in 0..np {
                        gk[a * np + b] *=
                            patches[a].angular_factor(k) * patches[b].angular_factor(k);
                    }
                }
                for a in 0..np {
                    totals[a] += gk[a * np + a];
                }
                g.push(gk);
                let diagonals = raw
                    .iter()
                    .zip(patches)
                    .zip(&totals)
                    .map(|((&g, p), &t)| (g, p.half_angle, t));
                if harmonic && remainder_below(k, TOLERANCE, diagonals) {
                    break;
                }
            }
            if !harmonic || k >= MAX_HARMONICS {
                break;
            }
            k += 1;
        }
    }
    PatchHarmonics {
        patches: patches.to_vec(),
        g,
        skipped,
    }
}

impl PlateModel {
    /// The static Mindlin harmonics between the patches of half-width `c`
    /// (m) at `radii` (module doc).
    pub fn mindlin_patch_harmonics(
        &self,
        radii: &[f64],
        c: f64,
    ) -> Result<PatchHarmonics, ModelError> {
        let plate = self.plate();
        let disc = super::model::discretisation(plate)?;
        let patches: Vec<LoadPatch> = radii
            .iter()
            .map(|&r| LoadPatch::new(plate.inner_radius, plate.outer_radius, r, c))
            .collect();
        Ok(patch_harmonics(&disc, &patches))
    }

    /// The residual compliance between patches a and b of `h`: the static
    /// harmonics less the retained Mindlin modes' patch means.
    pub fn mindlin_residual_kernel(
        &self,
        h: &PatchHarmonics,
        a: usize,
        b: usize,
    ) -> ResidualKernel {
        let (pa, pb) = (h.patches[a], h.patches[b]);
        let mut coefficients: Vec<f64> = (0..h.len() as u32).map(|k| h.get(k, a, b)).collect();
        let stiffness = &self.body().modal_stiffness;
        for (i, m) in self.modes().iter().enumerate() {
            if m.shape == AngularShape::Sin || h.skipped.contains(&m.k) || m.k as usize >= h.len() {
                continue;
            }
            let (wa, wb) = (
                self.patch_mean_w(m.radial, &pa),
                self.patch_mean_w(m.radial, &pb),
            );
            coefficients[m.k as usize] -=
                pa.angular_factor(m.k) * pb.angular_factor(m.k) * wa * wb / stiffness[i];
        }
        ResidualKernel {
            coefficients,
            tail_fit: None,
        }
    }

    /// W̄: the radial patch mean of radial shape `radial`'s W.
    pub fn patch_mean_w(&self, radial: usize, patch: &LoadPatch) -> f64 {
        let shape = &self.radial_shapes()[radial];
        let breaks = breakpoints(shape.basis());
        patch.radial_mean(&breaks, |r| shape.eval(r)[0])
    }

    /// The node's patch of half-width `c` at radius r under Mindlin theory.
    pub fn load_patch(&self, r: f64, c: f64) -> LoadPatch {
        let plate = self.plate();
        LoadPatch::new(plate.inner_radius, plate.outer_radius, r, c)
    }
}
