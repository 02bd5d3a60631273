//! The in-plane equations of the disc spinning at Ω about z, written in the
//! frame turning with it (docs/in_plane.md "Spinning"):
//!
//! M ü + Ω G u̇ + (K + Ω² K_Ω) u = f,  K_Ω = K_σ − M,          (S1)
//!
//! per nodal-diameter number k on the B-splines of [`super`], G skew, K_Ω
//! symmetric, both per unit Ω (G) and Ω² (K_Ω).
//!
//! # Derivation
//!
//! A material point at X (radius r) is displaced by the steady spin
//! expansion u⁰ (the Lamé solution of [`LamePrestress`], stresses σ⁰ per
//! unit Ω²) and by the small vibration u = u_r e_r + u_θ e_θ, both measured
//! in the turning frame. Its velocity in space is u̇ + Ω ẑ × (X + u⁰ + u), so
//! the kinetic energy per area is ½ ρh |u̇ + Ω ẑ × (X + u⁰ + u)|². Its terms
//! in u, u̇ give through Lagrange's equations
//!
//! - the Coriolis force 2ρhΩ ẑ × u̇ — from ρhΩ u̇·(ẑ × u), whose two halves
//!   (d/dt ∂/∂u̇ and −∂/∂u) add — hence Ω G u̇ with the skew form
//!   G(w, u̇) = 2 ∫ ρh w·(ẑ × u̇) dA = 2 ∫ ρh (w_θ u̇_r − w_r u̇_θ) dA;    (S2)
//! - the centrifugal force ρhΩ² (X + u⁰ + u): its part ρhΩ²(X + u⁰) is the
//!   steady load the prestress carries (the Lamé equilibrium, to first order
//!   in Ω²), its part ρhΩ² u softens: −Ω² M.
//!
//! The strain energy of the prestressed plate, expanded to second order in
//! u about the spinning state with the Green strain ½(∇u + ∇uᵀ + ∇uᵀ∇u),
//! is the linear elastic energy ½ uᵀ K u plus the work of the prestress on
//! the quadratic part of the strain,
//!
//! ½ Ω² ∫ h σ⁰ : (∇uᵀ∇u) dA = ½ Ω² ∫ h Σ_c σ⁰_ij F_ci F_cj dA,         (S3)
//!
//! F = ∇u in the polar frame (c the displacement component). With σ⁰
//! diagonal (σ_r, σ_θ; no shear in the axisymmetric state) and the columns
//! of F, the derivatives along r and along θ,
//!
//! F_·r = (∂u_r/∂r, ∂u_θ/∂r),  F_·θ = ((∂u_r/∂θ − u_θ)/r, (∂u_θ/∂θ + u_r)/r),
//!
//! (S3) is ½ Ω² uᵀ K_σ u with
//!
//! K_σ(w, u) = ∫ h [σ_r F_·r(w)·F_·r(u) + σ_θ F_·θ(w)·F_·θ(u)] dA.     (S4)
//!
//! # Per harmonic
//!
//! For the cos partner u_r = U cos kθ, u_θ = V sin kθ (and equally for the
//! sin partner u_r = U sin kθ, u_θ = −V cos kθ) the θ-integral of (S4) is
//!
//! K_σ = c_k ∫ h [σ_r (U'² + V'²) + σ_θ ((kU + V)² + (U + kV)²)/r²] r dr
//!
//! (as a quadratic form; c_k as in [`super`]); the partners do not couple
//! through K_σ or M. G couples them: with the bilinear mass form
//! m(a, b) = c_k ∫ ρh a b r dr, (S2) gives for k ≥ 1
//!
//! G = [[0, 2B], [−2B, 0]] over [cos; sin],  B((W, Z), (U, V)) = m(W, V) + m(Z, U),
//!
//! and for k = 0, over [radial U; torsional V],
//!
//! G = [[0, −2C], [2Cᵀ, 0]],  C(W, V) = m(W, V).
//!
//! # Checks (tests below)
//!
//! A free–free disc's rigid rotation u_θ = r (k = 0): K u = 0 and
//! K_σ u = M u as vectors by the Lamé equilibrium (integrate (S4) by parts:
//! ∫ h [r σ_r W' + σ_θ W] dr = ∫ h [σ_θ − (r σ_r)'] W dr = ∫ ρh r² W dr
//! when σ_r vanishes at both edges), so it stays an equilibrium at any
//! speed. A free–free disc's translation (k = 1, U = 1, V = −1): K u = 0,
//! K_σ u = 0, so M ü + Ω G u̇ − Ω² M u = 0: the disc at rest in space,
//! seen from the turning frame, turns backwards at Ω.

use super::{InPlaneDiscretisation, InPlaneEdge, InPlaneFamily, InPlaneMode};
use crate::model::prestress::LamePrestress;
use crate::model::radial::angular_norm;
use faer::Mat;

/// The spin terms of one k, (S1): `gyroscopic` G per unit Ω (N·s/m per
/// rad/s over the coefficients, skew), `spin_stiffness` K_Ω = K_σ − M per
/// unit Ω² (symmetric).
#[derive(Debug, Clone)]
pub struct InPlaneSpin {
    /// G, skew.
    pub gyroscopic: Mat<f64>,
    /// K_Ω = K_σ − M, symmetric.
    pub spin_stiffness: Mat<f64>,
}

/// The two families a k's unknowns are made of, in the order of
/// [`InPlaneDiscretisation::assemble_spin`]: the cos and sin partners of the
/// coupled family for k ≥ 1, the radial then the torsional family for k = 0.
pub fn spin_blocks(k: u32) -> [InPlaneFamily; 2] {
    if k == 0 {
        [InPlaneFamily::Radial, InPlaneFamily::Torsional]
    } else {
        [InPlaneFamily::Coupled, InPlaneFamily::Coupled]
    }
}

impl InPlaneDiscretisation {
    /// G and K_Ω of (S1) for k over the free coefficients. Unknowns ordered
    /// [cos partner; sin partner] (each as in [`Self::assemble`] of the
    /// coupled family) for k ≥ 1, [radial family; torsional family] for
    /// k = 0. `prestress` must have this discretisation's edges.
    pub fn assemble_spin(&self, k: u32, prestress: &LamePrestress) -> InPlaneSpin {
        debug_assert_eq!(
            (prestress.inner_fixed, prestress.outer_fixed),
            (
                self.plate().inner_edge == InPlaneEdge::Fixed,
                self.plate().outer_edge == InPlaneEdge::Fixed
            ),
            "the prestress and the in-plane modes share their edges"
        );
        let blocks = spin_blocks(k);
        let sizes = blocks.map(|f| self.n_free(f));
        let n = sizes[0] + sizes[1];
        let mut spin_stiffness = Mat::<f64>::zeros(n, n);
        for (b, &family) in blocks.iter().enumerate() {
            let at = b * sizes[0];
            let k_sigma = self.assemble_prestress(k, family, prestress);
            let (_, mass) = self.assemble(k, family);
            for i in 0..sizes[b] {
                for j in 0..sizes[b] {
                    spin_stiffness[(at + i, at + j)] = k_sigma[(i, j)] - mass[(i, j)];
                }
            }
        }
        let gram = self.mass_gram(k);
        let mut gyroscopic = Mat::<f64>::zeros(n, n);
        let splines = gram.nrows();
        for a in 0..splines {
            for c in 0..splines {
                let m2 = 2.0 * gram[(a, c)];
                if k == 0 {
                    // Radial test a, torsional trial c: −2C; transposed +2Cᵀ.
                    gyroscopic[(a, sizes[0] + c)] = -m2;
                    gyroscopic[(sizes[0] + c, a)] = m2;
                } else {
                    // Cos test (U_a, V_a) against sin trial: 2B swaps U and V.
                    let (ua, va) = (2 * a, 2 * a + 1);
                    let (us, vs) = (sizes[0] + 2 * c, sizes[0] + 2 * c + 1);
                    gyroscopic[(ua, vs)] = m2;
                    gyroscopic[(va, us)] = m2;
                    gyroscopic[(vs, ua)] = -m2;
                    gyroscopic[(us, va)] = -m2;
                }
            }
        }
        InPlaneSpin {
            gyroscopic,
            spin_stiffness,
        }
    }

    /// G and K_Ω projected on in-plane modes of k (their unit-peak U, V):
    /// modal coordinates [cos partners of `modes`; sin partners of `modes`]
    /// for k ≥ 1, `modes` in their order for k = 0 (each radial or
    /// torsional). With the modal masses m and ω of the modes, the modal
    /// equations are diag(m) q̈ + Ω G q̇ + (diag(m ω²) + Ω² K_Ω) q = f.
    pub fn modal_spin(
        &self,
        k: u32,
        prestress: &LamePrestress,
        modes: &[InPlaneMode],
    ) -> InPlaneSpin {
        let full = self.assemble_spin(k, prestress);
        let blocks = spin_blocks(k);
        let offset = [0, self.n_free(blocks[0])];
        let mut columns: Vec<(usize, &InPlaneMode)> = Vec::new();
        for m in modes {
            debug_assert_eq!(m.k, k);
            if k == 0 {
                let b = usize::from(m.family == InPlaneFamily::Torsional);
                columns.push((offset[b], m));
            } else {
                columns.push((offset[0], m));
            }
        }
        if k != 0 {
            columns.extend(modes.iter().map(|m| (offset[1], m)));
        }
        let n = full.gyroscopic.nrows();
        let mut phi = Mat::<f64>::zeros(n, columns.len());
        for (c, &(at, m)) in columns.iter().enumerate() {
            for (i, x) in self.restrict(m.family, &m.u, &m.v).into_iter().enumerate() {
                phi[(at + i, c)] = x;
            }
        }
        let project = |a: &Mat<f64>| phi.transpose() * a * &phi;
        InPlaneSpin {
            gyroscopic: project(&full.gyroscopic),
            spin_stiffness: project(&full.spin_stiffness),
        }
    }

    /// The free coefficients of `family` from the B-spline coefficients of U
    /// and V (the inverse of [`Self::expand`]).
    pub(crate) fn restrict(&self, family: InPlaneFamily, u: &[f64], v: &[f64]) -> Vec<f64> {
        let fields = family.fields();
        let mut out = vec![0.0; self.n_free(family)];
        for j in 0..self.basis().len() {
            let Some(p) = self.free_spline(j) else {
                continue;
            };
            for (s, &f) in fields.iter().enumerate() {
                out[p * fields.len() + s] = if f == 0 { u[j] } else { v[j] };
            }
        }
        out
    }

    /// K_σ of (S4) for k and `family` over its free coefficients.
    fn assemble_prestress(
        &self,
        k: u32,
        family: InPlaneFamily,
        prestress: &LamePrestress,
    ) -> Mat<f64> {
        let fields = family.fields();
        let n = self.n_free(family);
        let mut out = Mat::<f64>::zeros(n, n);
        let kf = k as f64;
        let scale = angular_norm(k) * self.plate().thickness;
        // Per local function: its free index, F_·r and F_·θ (per cos kθ or sin kθ).
        let mut local: Vec<(usize, [f64; 2], [f64; 2])> = Vec::with_capacity(8);
        for q in self.points() {
            let (sr, st) = prestress.stresses(q.r);
            let w = q.weight * q.r * scale;
            local.clear();
            for j in 0..4 {
                let Some(p) = self.free_spline(q.span + j) else {
                    continue;
                };
                let (v, d) = (q.ders[0][j], q.ders[1][j]);
                for (s, &f) in fields.iter().enumerate() {
                    let (along_r, along_theta) = if f == 0 {
                        ([d, 0.0], [kf * v / q.r, v / q.r])
                    } else {
                        ([0.0, d], [v / q.r, kf * v / q.r])
                    };
                    local.push((p * fields.len() + s, along_r, along_theta));
                }
            }
            for &(a, ra, ta) in &local {
                for &(b, rb, tb) in &local {
                    let dot = |x: [f64; 2], y: [f64; 2]| x[0] * y[0] + x[1] * y[1];
                    out[(a, b)] += w * (sr * dot(ra, rb) + st * dot(ta, tb));
                }
            }
        }
        out
    }

    /// m(N_a, N_b) = c_k ∫ ρh N_a N_b r dr over the free B-splines.
    fn mass_gram(&self, k: u32) -> Mat<f64> {
        let n = (0..self.basis().len())
            .filter(|&j| self.free_spline(j).is_some())
            .count();
        let mut out = Mat::<f64>::zeros(n, n);
        let p = self.plate();
        let scale = angular_norm(k) * p.density * p.thickness;
        for q in self.points() {
            let w = q.weight * q.r * scale;
            for a in 0..4 {
                let Some(pa) = self.free_spline(q.span + a) else {
                    continue;
                };
                for b in 0..4 {
                    if let Some(pb) = self.free_spline(q.span + b) {
                        out[(pa, pb)] += w * q.ders[0][a] * q.ders[0][b];
                    }
                }
            }
        }
        out
    }
}
