//! Contacts in series with the residual flexibility
//! (docs/residual_flexibility.md, "Contacts").
//!
//! A load model whose force depends on the deflection at its node frames —
//! the brake pads' contact springs, the lathe tool's chip — sees there the
//! modal deflection w_m plus the truncated modes' static deflection: that of
//! the held wrenches, w_e ([`HeldDeflection`]), and that of its own forces,
//! G F (G the residual compliance among its frames, [`ContactCompliance`]).
//! The residual acts as a spring in series with the contact: within the step
//! the forces solve
//!
//!   F = 𝓕(w_m + w_e + G F).
//!
//! - Piecewise-linear contact laws (pads: linear springs, lift-off, a
//!   floating caliper's balance): [`ContactCompliance::solve`], an active-set
//!   Newton iteration. On one active set the law is affine,
//!   𝓕(w) = 𝓕(wʲ) + J (w − wʲ), so one step (I − J G) Fʲ⁺¹ = 𝓕(wʲ) − J G Fʲ
//!   is exact; it repeats until the law, evaluated at the new deflections,
//!   has the active set it was solved with. Linear springs: one
//!   solve, two evaluations. For linear springs K this is
//!   F = −(I + K G)⁻¹ K (w_m + w_e − u₀).
//! - A scalar law that falls with the force (the tool's chip):
//!   [`solve_monotone`], a safeguarded Newton root.
//!
//! Only the stiffness is in series: a contact damper acts on the modal rate
//! ẇ_m; the rate of the residual deflection, G Ḟ, is left out (it would make
//! the contact force a state of its own). The damper's force is part of F and
//! so passes through G with the rest.
//!
//! ALE frames keep their angles, so G among ALE frames is constant and is
//! taken once when the scene is built; the held wrenches' part is read per
//! evaluation from [`ResidualCompliance`] (mixed pairs turn with χ).

use super::dense::{lu_factor, lu_solve, LuError};
use super::node_frame::NodeShape;
use super::residual::ResidualCompliance;
use super::wrench::Wrench;

/// Active-set passes before [`ContactCompliance::solve`] keeps its last
/// evaluation (a change of active set per pass; each pass opens or closes contacts).
pub const MAX_ACTIVE_SET_PASSES: usize = 32;

/// The residual compliance among a fixed set of ALE node frames, m/N (constant).
#[derive(Debug, Clone, PartialEq)]
pub struct ContactCompliance {
    n: usize,
    /// G, row-major n × n: deflection at contact c per unit transverse force at contact d.
    g: Vec<f64>,
}

/// Scratch of [`ContactCompliance::solve`], allocated once for n contacts.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct SeriesScratch {
    /// Deflections the law is evaluated at, m.
    pub w: Vec<f64>,
    /// The iterate F, N.
    f: Vec<f64>,
    gf: Vec<f64>,
    jac: Vec<f64>,
    /// The law's active set at `w`.
    active: Vec<bool>,
    /// LU factors (with row permutation) of I − J G and J for the active set
    /// `lu_active`: kept while the active set stays (a deterministic function
    /// of it, so a fresh scratch gives the same numbers).
    lu: Vec<f64>,
    perm: Vec<usize>,
    lu_active: Vec<bool>,
    lu_valid: bool,
    /// Passes of the last solve.
    pub passes: usize,
}

impl SeriesScratch {
    /// For n contacts whose law has `flags` active-set flags.
    pub fn new(n: usize, flags: usize) -> SeriesScratch {
        SeriesScratch {
            w: vec![0.0; n],
            f: vec![0.0; n],
            gf: vec![0.0; n],
            jac: vec![0.0; n * n],
            active: vec![false; flags],
            lu: vec![0.0; n * n],
            perm: vec![0; n],
            lu_active: vec![false; flags],
            lu_valid: false,
            passes: 0,
        }
    }
}

impl ContactCompliance {
    /// G among the ALE node frames `ale_nodes` (0-based ALE indices; the
    /// scene's node numbering has the ALE frames first).
    pub fn among(residual: &ResidualCompliance, ale_nodes: &[usize]) -> ContactCompliance {
        let n = ale_nodes.len();
        let mut g = Vec::with_capacity(n * n);
        for &a in ale_nodes {
            for &b in ale_nodes {
                g.push(residual.between(a, b, 0.0));
            }
        }
        ContactCompliance { n, g }
    }

    /// G from its entries (row-major n × n), m/N.
    pub fn from_matrix(n: usize, g: Vec<f64>) -> ContactCompliance {
        assert_eq!(g.len(), n * n);
        ContactCompliance { n, g }
    }

    pub fn len(&self) -> usize {
        self.n
    }

    pub fn is_empty(&self) -> bool {
        self.n == 0
    }

    /// G_cd, m/N.
    #[inline]
    pub fn at(&self, c: usize, d: usize) -> f64 {
        self.g[c * self.n + d]
    }

    /// The contact forces F = 𝓕(w_free + G F) (module docs) into `force`.
    /// `law(w, force, active)` writes the forces at deflections `w` and the
    /// active set there (any flags that fix the law's affine piece);
    /// `jacobian(active, J)` writes ∂F_c/∂w_d (row-major) on that piece. The
    /// returned forces are the law's last evaluation, at `s.w`; an error when
    /// I − J G of an active set is singular (the forces then those of the
    /// last evaluation before it).
    pub fn solve(
        &self,
        w_free: &[f64],
        force: &mut [f64],
        s: &mut SeriesScratch,
        mut law: impl FnMut(&[f64], &mut [f64], &mut [bool]),
        mut jacobian: impl FnMut(&[bool], &mut [f64]),
    ) -> Result<(), LuError> {
        let n = self.n;
        s.f.iter_mut().for_each(|f| *f = 0.0);
        s.w.copy_from_slice(w_free);
        law(&s.w, force, &mut s.active);
        s.passes = 0;
        while s.passes < MAX_ACTIVE_SET_PASSES {
            s.passes += 1;
            // (I − J G) F = 𝓕(w) − J G F_prev, I − J G factored once per active set.
            if !(s.lu_valid && s.lu_active == s.active) {
                jacobian(&s.active, &mut s.jac);
                for c in 0..n {
                    for d in 0..n {
                        let jg: f64 = (0..n).map(|e| s.jac[c * n + e] * self.g[e * n + d]).sum();
                        s.lu[c * n + d] = if c == d { 1.0 - jg } else { -jg };
                    }
                }
                s.lu_active.copy_from_slice(&s.active);
                let factored = lu_factor(&mut s.lu, &mut s.perm, n);
                s.lu_valid = factored.is_ok();
                factored?;
            }
            if s.passes == 1 {
                // F_prev = 0: the right-hand side is 𝓕(w) itself.
                s.f.copy_from_slice(&force[..n]);
            } else {
                self.apply(&s.f, &mut s.gf);
                for (c, (fc, force_c)) in s.f.iter_mut().zip(force.iter()).enumerate().take(n) {
                    let jgf: f64 = s.jac[c * n..(c + 1) * n]
                        .iter()
                        .zip(&s.gf)
                        .map(|(j, g)| j * g)
                        .sum();
                    *fc = *force_c - jgf;
                }
            }
            lu_solve(&s.lu, &s.perm, &mut s.f, &mut s.gf, n);
            self.apply(&s.f, &mut s.gf);
            for ((w, free), g) in s.w.iter_mut().zip(w_free).zip(&s.gf).take(n) {
                *w = free + g;
            }
            law(&s.w, force, &mut s.active);
            if s.active == s.lu_active {
                return Ok(());
            }
        }
        Ok(())
    }

    /// out = G f.
    fn apply(&self, f: &[f64], out: &mut [f64]) {
        for (c, o) in out.iter_mut().enumerate() {
            *o = self.g[c * self.n..(c + 1) * self.n]
                .iter()
                .zip(f)
                .map(|(g, f)| g * f)
                .sum();
        }
    }

    /// The stiffness a linear contact law ∂F/∂w = −K presents in series with
    /// G: K_eff = (I + K G)⁻¹ K (row-major, n × n), N/m.
    pub fn series_stiffness(&self, k: &[f64]) -> Vec<f64> {
        let n = self.n;
        let mut a: Vec<f64> = (0..n * n)
            .map(|i| {
                let (c, e) = (i / n, i % n);
                (c == e) as u8 as f64
                    + (0..n)
                        .map(|x| k[c * n + x] * self.g[x * n + e])
                        .sum::<f64>()
            })
            .collect();
        let mut perm = vec![0; n];
        // A singular I + K G (no finite stiffness in series): NaN, as the solves give.
        if lu_factor(&mut a, &mut perm, n).is_err() {
            return vec![f64::NAN; n * n];
        }
        let (mut col, mut buf) = (vec![0.0; n], vec![0.0; n]);
        let mut out = vec![0.0; n * n];
        for d in 0..n {
            for c in 0..n {
                col[c] = k[c * n + d];
            }
            lu_solve(&a, &perm, &mut col, &mut buf, n);
            for c in 0..n {
                out[c * n + d] = col[c];
            }
        }
        out
    }
}

/// Largest eigenvalue of M^(−½) Wᵀ K W M^(−½) (1/s²): the coupling rate of a
/// contact stiffness matrix K (n_c × n_c, row-major) at contacts with mode
/// shapes W (one slice per contact).
pub fn stiffness_rate(shapes: &[&[NodeShape]], k: &[f64], modal_mass: &[f64]) -> f64 {
    let n = modal_mass.len();
    let nc = shapes.len();
    let mut a = faer::Mat::<f64>::zeros(n, n);
    for c in 0..nc {
        for d in 0..nc {
            let kcd = k[c * nc + d];
            if kcd == 0.0 {
                continue;
            }
            for i in 0..n {
                for m in 0..n {
                    a[(i, m)] += shapes[c][i].w * kcd * shapes[d][m].w
                        / (modal_mass[i] * modal_mass[m]).sqrt();
                }
            }
        }
    }
    // Symmetrise against round-off (K_eff is symmetric).
    let a = faer::Mat::<f64>::from_fn(n, n, |i, m| 0.5 * (a[(i, m)] + a[(m, i)]));
    a.self_adjoint_eigenvalues(faer::Side::Lower)
        .ok()
        .and_then(|ev| ev.last().copied())
        .unwrap_or(0.0)
        .max(0.0)
}

/// The root f in [0, f_max] of f = 𝓕(f), for a force 𝓕 that does not grow
/// with f and 𝓕(0) = f_max ≥ 0 (the tool: its force pushes the plate away
/// and so thins its own chip). `law(f)` gives 𝓕(f) and its slope 𝓕′(f) ≤ 0.
/// Newton's method on φ(f) = f − 𝓕(f) (φ′ = 1 − 𝓕′ ≥ 1) from f_max down,
/// kept inside the bracket [lo, hi] of the root (bisection when a step leaves
/// it), to 1e-13 of f_max: about four evaluations where the chip law is
/// smooth, instead of a dozen by false position.
pub fn solve_monotone(f_max: f64, law: impl Fn(f64) -> (f64, f64)) -> f64 {
    if f_max <= 0.0 || !f_max.is_finite() {
        return f_max.max(0.0);
    }
    let tolerance = 1e-13 * f_max;
    let (mut lo, mut hi) = (0.0, f_max);
    let mut f = f_max;
    for _ in 0..200 {
        let (force, slope) = law(f);
        let phi = f - force;
        if phi == 0.0 {
            return f;
        }
        if phi < 0.0 {
            lo = f;
        } else {
            hi = f;
        }
        let newton = f - phi / (1.0 - slope.min(0.0));
        let next = if newton > lo && newton < hi {
            newton
        } else {
            0.5 * (lo + hi)
        };
        if (next - f).abs() <= tolerance || hi - lo <= tolerance {
            return next;
        }
        f = next;
    }
    f
}

/// The residual deflection of the held (user) wrenches at a node frame.
#[derive(Debug, Clone, Copy)]
pub struct HeldDeflection<'a> {
    pub compliance: &'a ResidualCompliance,
    /// Held wrenches per ALE and Lagrangian node frame (z force in the node frame).
    pub ale: &'a [Wrench],
    pub lagrange: &'a [Wrench],
}

impl HeldDeflection<'_> {
    /// At node `a` (ALE first, then Lagrangian) at joint angle χ, m.
    pub fn at(&self, a: usize, chi: f64) -> f64 {
        let n_ale = self.ale.len();
        self.compliance.deflection(a, chi, |b| {
            if b < n_ale {
                self.ale[b].force[2]
            } else {
                self.lagrange.get(b - n_ale).map_or(0.0, |w| w.force[2])
            }
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn linear_springs_in_series_with_g_solve_in_one_pass() {
        // Two contacts, K = diag(k1, k2), G symmetric: F = −(I + K G)⁻¹ K w.
        let g = ContactCompliance::from_matrix(2, vec![2e-7, 5e-8, 5e-8, 1e-7]);
        let (k1, k2) = (3e6, 8e6);
        let w = [1e-4, -2e-5];
        let mut s = SeriesScratch::new(2, 1);
        let mut f = [0.0; 2];
        let law = |w: &[f64], f: &mut [f64], on: &mut [bool]| {
            f[0] = -k1 * w[0];
            f[1] = -k2 * w[1];
            on[0] = true;
        };
        g.solve(&w, &mut f, &mut s, law, |_, j| {
            j.copy_from_slice(&[-k1, 0.0, 0.0, -k2])
        })
        .unwrap();
        // By hand: (I + K G) = [[1 + k1 g11, k1 g12], [k2 g21, 1 + k2 g22]].
        let a = [[1.0 + k1 * 2e-7, k1 * 5e-8], [k2 * 5e-8, 1.0 + k2 * 1e-7]];
        let b = [-k1 * w[0], -k2 * w[1]];
        let det = a[0][0] * a[1][1] - a[0][1] * a[1][0];
        let x = [
            (b[0] * a[1][1] - a[0][1] * b[1]) / det,
            (a[0][0] * b[1] - a[1][0] * b[0]) / det,
        ];
        for c in 0..2 {
            assert!((f[c] - x[c]).abs() < 1e-12 * x[c].abs(), "{f:?} vs {x:?}");
        }
        assert_eq!(s.passes, 1);
        // And the series stiffness is the same map.
        let keff = g.series_stiffness(&[k1, 0.0, 0.0, k2]);
        let y = [
            -(keff[0] * w[0] + keff[1] * w[1]),
            -(keff[2] * w[0] + keff[3] * w[1]),
        ];
        for c in 0..2 {
            assert!((y[c] - x[c]).abs() < 1e-12 * x[c].abs(), "{y:?} vs {x:?}");
        }
    }

    #[test]
    fn a_unilateral_contact_finds_its_active_set() {
        // Contact 0 pushes (F = −k (w − δ) only while w < δ), contact 1 linear; through G the
        // push of contact 1 lifts contact 0 off.
        let g = ContactCompliance::from_matrix(2, vec![1e-6, 9e-7, 9e-7, 1e-6]);
        let (k, delta) = (1e7, 1e-4);
        let w_free = [0.0, 0.0];
        let law = |w: &[f64], f: &mut [f64], on: &mut [bool]| {
            let f0 = -k * (w[0] - delta);
            on[0] = f0 >= 0.0;
            f[0] = if on[0] { f0 } else { 0.0 };
            f[1] = 5e3 - k * w[1];
        };
        let jacobian = |on: &[bool], j: &mut [f64]| {
            j.copy_from_slice(&[if on[0] { -k } else { 0.0 }, 0.0, 0.0, -k])
        };
        let mut s = SeriesScratch::new(2, 1);
        let mut f = [0.0; 2];
        g.solve(&w_free, &mut f, &mut s, law, jacobian).unwrap();
        // Contact 0 open: F1 = 5e3 / (1 + k g11) and w0 = g01 F1 ≥ δ.
        let f1 = 5e3 / (1.0 + k * 1e-6);
        assert_eq!(f[0], 0.0, "{f:?}");
        assert!((f[1] - f1).abs() < 1e-9 * f1, "{f:?}");
        assert!(9e-7 * f1 > delta);
        assert!(s.passes >= 2, "the first pass closes both: {}", s.passes);
    }

    #[test]
    fn the_monotone_root_is_the_fixed_point() {
        // 𝓕(f) = a (c − g f)^0.3, the tool's law: f = 𝓕(f).
        let (a, c, g) = (2.0e3, 1e-4, 1e-8);
        let law = |f: f64| {
            if c - g * f > 0.0 {
                a * (c - g * f).powf(0.3)
            } else {
                0.0
            }
        };
        let with_slope = |f: f64| {
            let chip = c - g * f;
            if chip > 0.0 {
                (law(f), -0.3 * law(f) / chip * g)
            } else {
                (0.0, 0.0)
            }
        };
        let f = solve_monotone(law(0.0), with_slope);
        assert!((f - law(f)).abs() < 1e-12 * f, "{f} vs {}", law(f));
        assert!(f < law(0.0));
        // A wrong (zero) slope still converges, by bisection: the bracket holds.
        let f0 = solve_monotone(law(0.0), |f| (law(f), 0.0));
        assert!((f0 - f).abs() < 1e-12 * f, "{f0} vs {f}");
    }
}
