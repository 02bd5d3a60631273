//! Mass and stiffness of the Mindlin radial problem per nodal-diameter number
//! k (the weak form in [`super`]): cubic B-splines N_j for W, Γ_r, Γ_θ, the
//! essential edge conditions eliminated into the basis.
//!
//! Coefficients are interleaved by B-spline: (W_j, Γ_r,j, Γ_θ,j) for
//! j = 0 … n − 1 (Γ_θ only for k ≥ 1), so the matrices are banded. Each
//! free coefficient is a column of the map T from free to all coefficients
//! (one entry, or two at a clamped edge, where the slope B-spline of W
//! carries Γ_r's edge coefficient N'(edge) with it: Γ_r = W' there). The
//! matrices are Tᵀ K T and Tᵀ M T, assembled directly.

use super::{MindlinEdge, MindlinError, MindlinPlate, MAX_SPLINES, MIN_SPLINES};
use crate::model::bspline::BSplineBasis;
use crate::model::radial::{angular_norm, quadrature_points, QuadPoint};
use faer::Mat;

/// W's, Γ_r's and Γ_θ's coefficients.
const FIELDS: usize = 3;
pub(super) const W: usize = 0;
const GAMMA_R: usize = 1;
const GAMMA_THETA: usize = 2;

/// The radial B-splines of the three fields with their quadrature.
#[derive(Debug, Clone)]
pub struct MindlinDiscretisation {
    plate: MindlinPlate,
    basis: BSplineBasis,
    points: Vec<QuadPoint>,
}

/// Per function at a point: the strains (e_r, e_θ, e_rθ, Γ_r, Γ_θ) and the
/// inertia fields (W, Ψ_r, Ψ_θ).
pub(super) type Kinematics = ([f64; 5], [f64; 3]);

impl MindlinDiscretisation {
    /// `splines` uniform cubic B-splines per field on [r_i, r_a].
    pub fn new(plate: &MindlinPlate, splines: usize) -> Result<Self, MindlinError> {
        plate.validate()?;
        if !(MIN_SPLINES..=MAX_SPLINES).contains(&splines) {
            return Err(MindlinError::Splines {
                splines,
                min: MIN_SPLINES,
                max: MAX_SPLINES,
            });
        }
        let basis = BSplineBasis::new(plate.inner_radius, plate.outer_radius, splines);
        let points = quadrature_points(&basis);
        Ok(MindlinDiscretisation {
            plate: *plate,
            basis,
            points,
        })
    }

    /// The plate.
    pub fn plate(&self) -> &MindlinPlate {
        &self.plate
    }

    /// The quadrature points of the basis (with the B-splines' derivatives).
    pub(super) fn points(&self) -> &[QuadPoint] {
        &self.points
    }

    /// The B-spline basis shared by the three fields.
    pub fn basis(&self) -> &BSplineBasis {
        &self.basis
    }

    pub(super) fn fields(k: u32) -> usize {
        if k == 0 {
            FIELDS - 1
        } else {
            FIELDS
        }
    }

    /// The coefficient index of B-spline j of `field` for k.
    pub(super) fn index(k: u32, field: usize, j: usize) -> usize {
        j * Self::fields(k) + field
    }

    /// The free coefficients of k: the columns of T as (coefficient, factor) lists.
    pub(super) fn free_columns(&self, k: u32) -> Vec<Vec<(usize, f64)>> {
        let n = self.basis.len();
        let fields = Self::fields(k);
        let mut dropped = vec![false; fields * n];
        let mut carried: Vec<(usize, usize, f64)> = Vec::new();
        let s_last = self.basis.spans() - 1;
        let (ri, ra) = self.basis.interval();
        // (edge spline, slope spline, N'_slope at the edge) per edge.
        let edges = [
            (
                self.plate.inner_edge,
                0,
                1,
                self.basis.eval_span(0, ri)[1][1],
            ),
            (
                self.plate.outer_edge,
                n - 1,
                n - 2,
                self.basis.eval_span(s_last, ra)[1][2],
            ),
        ];
        for (edge, e0, e1, slope) in edges {
            let at = |field| Self::index(k, field, e0);
            if edge != MindlinEdge::Free {
                dropped[at(W)] = true;
            }
            if k > 0 && matches!(edge, MindlinEdge::Supported | MindlinEdge::Clamped) {
                dropped[at(GAMMA_THETA)] = true;
            }
            if edge == MindlinEdge::Clamped {
                dropped[at(GAMMA_R)] = true;
                carried.push((Self::index(k, W, e1), at(GAMMA_R), slope));
            }
        }
        (0..fields * n)
            .filter(|&i| !dropped[i])
            .map(|i| {
                let mut col = vec![(i, 1.0)];
                col.extend(
                    carried
                        .iter()
                        .filter(|c| c.0 == i)
                        .map(|&(_, j, factor)| (j, factor)),
                );
                col
            })
            .collect()
    }

    /// The number of free coefficients for nodal-diameter number k.
    pub fn n_free(&self, k: u32) -> usize {
        self.free_columns(k).len()
    }

    /// Strains and inertia fields of B-spline `[v, v', v'']` of `field` at r.
    pub(super) fn kinematics(field: usize, k: f64, r: f64, [v, d1, d2]: [f64; 3]) -> Kinematics {
        match field {
            W => (
                [
                    -d2,
                    (-d1 + k * k * v / r) / r,
                    2.0 * k * (d1 / r - v / (r * r)),
                    0.0,
                    0.0,
                ],
                [v, -d1, k * v / r],
            ),
            GAMMA_R => ([d1, v / r, -k * v / r, v, 0.0], [0.0, v, 0.0]),
            _ => ([0.0, k * v / r, d1 - v / r, 0.0, v], [0.0, 0.0, v]),
        }
    }

    /// (K̄, M̄) for nodal-diameter number k over the free coefficients: the
    /// bilinear forms of U and T of [`super`] (with c_k), symmetric, M̄
    /// positive definite. Each B-spline's contribution goes to the free
    /// coefficients that carry it (the rows of T).
    pub fn assemble(&self, k: u32) -> (Mat<f64>, Mat<f64>) {
        let n = self.basis.len();
        let fields = Self::fields(k);
        let cols = self.free_columns(k);
        let mut carriers: Vec<Vec<(usize, f64)>> = vec![Vec::new(); fields * n];
        for (a, col) in cols.iter().enumerate() {
            for &(g, t) in col {
                carriers[g].push((a, t));
            }
        }
        let mut kk = Mat::<f64>::zeros(cols.len(), cols.len());
        let mut mm = Mat::<f64>::zeros(cols.len(), cols.len());
        let p = &self.plate;
        let (d, nu, shear) = (p.rigidity(), p.poisson_ratio, p.shear_stiffness());
        let (rho_h, inertia) = (p.density * p.thickness, p.rotary_inertia());
        let ck = angular_norm(k);
        let kf = k as f64;
        let mut local: Vec<(usize, Kinematics)> = Vec::with_capacity(4 * FIELDS);
        for q in &self.points {
            let w = q.weight * q.r * ck;
            local.clear();
            for field in 0..fields {
                for j in 0..4 {
                    let f = [q.ders[0][j], q.ders[1][j], q.ders[2][j]];
                    local.push((
                        Self::index(k, field, q.span + j),
                        Self::kinematics(field, kf, q.r, f),
                    ));
                }
            }
            for &(gi, (bi, mi)) in &local {
                for &(gj, (bj, mj)) in &local {
                    let bending = bi[0] * bj[0]
                        + bi[1] * bj[1]
                        + nu * (bi[0] * bj[1] + bi[1] * bj[0])
                        + 0.5 * (1.0 - nu) * bi[2] * bj[2];
                    let shearing = bi[3] * bj[3] + bi[4] * bj[4];
                    let stiff = w * (d * bending + shear * shearing);
                    let mass =
                        w * (rho_h * mi[0] * mj[0] + inertia * (mi[1] * mj[1] + mi[2] * mj[2]));
                    for &(a, ta) in &carriers[gi] {
                        for &(b, tb) in &carriers[gj] {
                            kk[(a, b)] += ta * tb * stiff;
                            mm[(a, b)] += ta * tb * mass;
                        }
                    }
                }
            }
        }
        (kk, mm)
    }

    /// K̄_g for nodal-diameter number k over the free coefficients: the
    /// geometric stiffness of an in-plane prestress (σ_r, σ_θ) = `stresses(r)`
    /// (per unit Ω² for the spinning disc), c_k h ∫ (σ_r w_r δw_r +
    /// σ_θ k² w δw / r²) r dr. It works on the deflection w alone (the
    /// membrane forces turn with the mid-surface's slope ∇w, not with ψ), so
    /// only W's B-splines carry it; the Kirchhoff form of
    /// `RadialDiscretisation::assemble_geometric` (src/model/radial.rs).
    pub fn assemble_geometric(
        &self,
        k: u32,
        thickness: f64,
        stresses: impl Fn(f64) -> (f64, f64),
    ) -> Mat<f64> {
        let n = self.basis.len();
        let cols = self.free_columns(k);
        let mut carriers: Vec<Vec<(usize, f64)>> = vec![Vec::new(); Self::fields(k) * n];
        for (a, col) in cols.iter().enumerate() {
            for &(g, t) in col {
                carriers[g].push((a, t));
            }
        }
        let mut kg = Mat::<f64>::zeros(cols.len(), cols.len());
        let (ck, k2) = (angular_norm(k), (k as f64).powi(2));
        for q in &self.points {
            let (sr, st) = stresses(q.r);
            let w = q.weight * q.r * ck * thickness;
            for i in 0..4 {
                let gi = Self::index(k, W, q.span + i);
                for j in 0..4 {
                    let gj = Self::index(k, W, q.span + j);
                    let form = sr * q.ders[1][i] * q.ders[1][j]
                        + st * k2 * q.ders[0][i] * q.ders[0][j] / (q.r * q.r);
                    for &(a, ta) in &carriers[gi] {
                        for &(b, tb) in &carriers[gj] {
                            kg[(a, b)] += ta * tb * w * form;
                        }
                    }
                }
            }
        }
        kg
    }

    /// B-spline coefficients of W, Γ_r, Γ_θ (zeros for k = 0) from the free ones.
    pub fn expand(&self, k: u32, free: impl Iterator<Item = f64>) -> [Vec<f64>; 3] {
        let n = self.basis.len();
        let mut all = vec![0.0; Self::fields(k) * n];
        for (col, c) in self.free_columns(k).iter().zip(free) {
            for &(g, t) in col {
                all[g] += t * c;
            }
        }
        let field = |f: usize| {
            (0..n)
                .map(|j| {
                    if f < Self::fields(k) {
                        all[Self::index(k, f, j)]
                    } else {
                        0.0
                    }
                })
                .collect()
        };
        [field(W), field(GAMMA_R), field(GAMMA_THETA)]
    }
}
