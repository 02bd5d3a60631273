//! In-plane statics over load patches and the residual flexibility of the
//! truncated in-plane modes (docs/in_plane.md, "Statics and residual
//! flexibility").
//!
//! An in-plane point force's displacement is logarithmically infinite at the
//! force, so a node stands for a load patch ([`LoadPatch`], shared with the
//! Mindlin residual): its radial and tangential force components are spread
//! uniformly per unit area over the patch (constant polar components), its
//! displacement components are the patch means.
//!
//! # The static harmonics
//!
//! Per harmonic k ≥ 1 both partners (cos: u_r = U cos kθ, u_θ = V sin kθ;
//! sin: u_r = U sin kθ, u_θ = −V cos kθ) have the stiffness K̄_k of the weak
//! form in [`super`] (with c_k). A force (F_r, F_θ) on patch b puts the
//! generalised forces s_b (F_r m_U cos kθ_b + F_θ m_V sin kθ_b) on the cos
//! partner and s_b (F_r m_U sin kθ_b − F_θ m_V cos kθ_b) on the sin partner,
//! m_U, m_V the patch means of the U and V B-splines and s = sinc kβ; the
//! patch means of the static displacement at patch a are then, with
//! Δ = θ_a − θ_b and g^{XY}_k(a, b) = s_a s_b m_X(a)ᵀ K̄_k⁻¹ m_Y(b),
//!
//! ū_r = Σ_k (g^{UU}_k F_r cos kΔ − g^{UV}_k F_θ sin kΔ),
//! ū_θ = Σ_k (g^{VU}_k F_r sin kΔ + g^{VV}_k F_θ cos kΔ).
//!
//! For k = 0 the radial family carries g^{UU}_0, the torsional g^{VV}_0
//! (c_0 = 2π). [`InPlaneKernel`] holds the four series per pair of patches.
//! With the patches the terms fall like k⁻⁴ (the 1/k of the line load's
//! plane-stress response, 1/k of its radial mean over the patch, sinc²);
//! they are summed until the envelope of what is left is below [`TOLERANCE`]
//! of every diagonal compliance ([`crate::model::patch::remainder_below`]).
//! Each k costs one band Cholesky (half-bandwidth 7 for the interleaved U,
//! V coefficients).
//!
//! # The residual
//!
//! A retained mode ⟨k, l⟩ (both partners) of stiffness K = ω² m carries
//! s_a s_b X̄(a) Ȳ(b) / K of g^{XY}_k, X̄ its patch-mean U or V; the residual
//! compliance is the static harmonics less that ([`residual_kernel`]). A
//! free–free annulus has no static solution for the rigid motions (k = 0
//! torsional, k = 1): those harmonics get no residual, as for bending.

use super::{InPlaneDiscretisation, InPlaneFamily, InPlaneMode};
pub use crate::model::patch::LoadPatch;
use crate::model::patch::{band_cholesky, band_solve, breakpoints, remainder_below};

/// The most harmonics summed.
pub const MAX_HARMONICS: u32 = 8192;
/// The series stops when the envelope of its remainder is below this
/// fraction of every diagonal static compliance (tests/in_plane_statics.rs
/// measures the sum against the exact series).
pub const TOLERANCE: f64 = 1e-8;

/// Series in k between two patches: per k the coefficients
/// [rr, rθ, θr, θθ] of ū_r = Σ (rr F_r cos kΔ − rθ F_θ sin kΔ),
/// ū_θ = Σ (θr F_r sin kΔ + θθ F_θ cos kΔ) (module doc), m/N.
#[derive(Debug, Clone, PartialEq)]
pub struct InPlaneKernel {
    /// Per harmonic k = 0, 1, …: [g^{UU}, g^{UV}, g^{VU}, g^{VV}].
    pub coefficients: Vec<[f64; 4]>,
}

impl InPlaneKernel {
    /// The compliance matrix at Δ = θ_a − θ_b: row the displacement
    /// component at a (r, θ), column the force component at b (r, θ), m/N.
    pub fn at(&self, delta: f64) -> [[f64; 2]; 2] {
        let mut c = [[0.0; 2]; 2];
        for (k, g) in self.coefficients.iter().enumerate() {
            let (s, co) = (k as f64 * delta).sin_cos();
            c[0][0] += g[0] * co;
            c[0][1] -= g[1] * s;
            c[1][0] += g[2] * s;
            c[1][1] += g[3] * co;
        }
        c
    }
}

/// The static in-plane harmonics between all pairs of a set of patches.
#[derive(Debug, Clone)]
pub struct InPlanePatchHarmonics {
    /// The patches.
    pub patches: Vec<LoadPatch>,
    /// g[k][a · n + b] = [g^{UU}, g^{UV}, g^{VU}, g^{VV}] (with the sincs), m/N.
    g: Vec<Vec<[f64; 4]>>,
    /// Families without a static solution (free–free: k = 0 torsional, k = 1).
    pub skipped: Vec<(u32, InPlaneFamily)>,
}

impl InPlanePatchHarmonics {
    /// Harmonic k between patches a and b (zeros where skipped), m/N.
    pub fn get(&self, k: u32, a: usize, b: usize) -> [f64; 4] {
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

    /// The static series between patches a and b.
    pub fn kernel(&self, a: usize, b: usize) -> InPlaneKernel {
        InPlaneKernel {
            coefficients: (0..self.len() as u32).map(|k| self.get(k, a, b)).collect(),
        }
    }

    /// Whether `family` of k was left out.
    pub fn is_skipped(&self, k: u32, family: InPlaneFamily) -> bool {
        self.skipped.contains(&(k, family))
    }
}

impl InPlaneDiscretisation {
    /// The static in-plane harmonics between all pairs of `patches`, summed
    /// to [`TOLERANCE`] (module doc).
    pub fn patch_harmonics(&self, patches: &[LoadPatch]) -> InPlanePatchHarmonics {
        let np = patches.len();
        let means: Vec<Vec<f64>> = patches
            .iter()
            .map(|p| p.spline_means(self.basis()))
            .collect();
        let mut out = InPlanePatchHarmonics {
            patches: patches.to_vec(),
            g: Vec::new(),
            skipped: Vec::new(),
        };
        let mut totals = vec![[0.0; 2]; np];
        let mut factor = Vec::new();
        for k in 0..=MAX_HARMONICS {
            let mut gk = vec![[0.0; 4]; np * np];
            let mut raw_diagonal = vec![[0.0; 2]; np];
            for &family in InPlaneFamily::of(k) {
                let Some(raw) = self.static_family(k, family, &means, &mut factor) else {
                    out.skipped.push((k, family));
                    continue;
                };
                for a in 0..np {
                    for b in 0..np {
                        let s = patches[a].angular_factor(k) * patches[b].angular_factor(k);
                        for (x, y) in gk[a * np + b].iter_mut().zip(&raw[a * np + b]) {
                            *x += s * y;
                        }
                    }
                    let d = raw[a * np + a];
                    raw_diagonal[a][0] += d[0];
                    raw_diagonal[a][1] += d[3];
                }
            }
            for (a, total) in totals.iter_mut().enumerate() {
                total[0] += gk[a * np + a][0];
                total[1] += gk[a * np + a][3];
            }
            out.g.push(gk);
            let diagonals = (0..np).flat_map(|a| {
                let (raw, total, beta) = (raw_diagonal[a], totals[a], patches[a].half_angle);
                [(raw[0], beta, total[0]), (raw[1], beta, total[1])]
            });
            if k >= 1 && remainder_below(k, TOLERANCE, diagonals) {
                break;
            }
        }
        out
    }

    /// m_X(a)ᵀ K̄_k⁻¹ m_Y(b) of `family` for all pairs as [UU, UV, VU, VV]
    /// (zeros for a field the family lacks), symmetric; None for a rigid
    /// motion of a free–free annulus or a stiffness that is not positive
    /// definite.
    fn static_family(
        &self,
        k: u32,
        family: InPlaneFamily,
        means: &[Vec<f64>],
        factor: &mut Vec<f64>,
    ) -> Option<Vec<[f64; 4]>> {
        if self.plate().is_rigid_body(k, family, 0) {
            return None;
        }
        let fields = family.fields();
        let (kk, _) = self.assemble(k, family);
        let bw = 4 * fields.len() - 1;
        band_cholesky(kk.nrows(), bw, |j, d| kk[(j, j + d)], factor)?;
        // Loads per (patch, field): index 2 a + f.
        let loads: Vec<(usize, usize, Vec<f64>)> = (0..means.len())
            .flat_map(|a| fields.iter().map(move |&f| (a, f)))
            .map(|(a, f)| (a, f, self.field_load(family, f, &means[a])))
            .collect();
        let np = means.len();
        let mut out = vec![[0.0; 4]; np * np];
        for (i, (b, fb, load_b)) in loads.iter().enumerate() {
            let mut x = load_b.clone();
            band_solve(factor, bw, &mut x);
            for (a, fa, load_a) in &loads[..=i] {
                let v: f64 = load_a.iter().zip(&x).map(|(p, q)| p * q).sum();
                out[a * np + b][2 * fa + fb] = v;
                out[b * np + a][2 * fb + fa] = v;
            }
        }
        Some(out)
    }
}

/// The retained modes' share of the static series between patches `pa` and
/// `pb`, on `harmonics` harmonics (modes of a higher k or of a `skip`ped
/// family left out): s_a s_b X̄(a) Ȳ(b) / (ω² m) per mode (module doc).
pub fn modal_kernel(
    modes: &[InPlaneMode],
    pa: &LoadPatch,
    pb: &LoadPatch,
    harmonics: usize,
    skip: impl Fn(u32, InPlaneFamily) -> bool,
) -> InPlaneKernel {
    let mut coefficients = vec![[0.0; 4]; harmonics];
    for m in modes {
        if m.k as usize >= harmonics || skip(m.k, m.family) {
            continue;
        }
        let [ua, va] = patch_means(m, pa);
        let [ub, vb] = patch_means(m, pb);
        let s =
            pa.angular_factor(m.k) * pb.angular_factor(m.k) / (m.omega * m.omega * m.modal_mass);
        let c = &mut coefficients[m.k as usize];
        c[0] += s * ua * ub;
        c[1] += s * ua * vb;
        c[2] += s * va * ub;
        c[3] += s * va * vb;
    }
    InPlaneKernel { coefficients }
}

/// The residual series between patches a and b of `h`: the static harmonics
/// less the retained `modes`' share (module doc).
pub fn residual_kernel(
    h: &InPlanePatchHarmonics,
    modes: &[InPlaneMode],
    a: usize,
    b: usize,
) -> InPlaneKernel {
    let modal = modal_kernel(modes, &h.patches[a], &h.patches[b], h.len(), |k, f| {
        h.is_skipped(k, f)
    });
    let mut kernel = h.kernel(a, b);
    for (c, m) in kernel.coefficients.iter_mut().zip(&modal.coefficients) {
        for (x, y) in c.iter_mut().zip(m) {
            *x -= y;
        }
    }
    kernel
}

/// [Ū, V̄]: the radial patch means of a mode's U and V.
pub fn patch_means(mode: &InPlaneMode, patch: &LoadPatch) -> [f64; 2] {
    let breaks = breakpoints(&mode.basis);
    [
        patch.radial_mean(&breaks, |r| mode.eval(r).u),
        patch.radial_mean(&breaks, |r| mode.eval(r).v),
    ]
}
