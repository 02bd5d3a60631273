//! Mass and stiffness of the radial B-spline discretisation per nodal-diameter
//! number k (paper section 3.1, the matrices M̄_e, K̄_e of eq. (14)).
//!
//! For w = R(r) cos(kφ) the Kirchhoff plate energies are (DESIGN.md)
//!
//! U = D/2 c_k ∫ [ (R'' + R'/r − k²R/r²)² − 2(1−ν) ( R''(R'/r − k²R/r²) − k²(R'/r − R/r²)² ) ] r dr,
//! T = ρh/2 c_k ∫ Ṙ² r dr,   c_k = 2π (k = 0), π (k ≥ 1),
//!
//! the same for sin(kφ). Essential conditions are built into the basis
//! (dropped B-splines); natural ones follow from the variational form.
//!
//! Two refinements keep hard geometries accurate (docs/hard_cases.md):
//! - a free–free ring (r_i/r_a ≥ [`RING_RATIO`]) spans {1, r − r_m} with those
//!   exact functions in place of N_0, N_1: the near-rigid radial shapes of a
//!   narrow free ring have energies far below the B-spline stiffness entries,
//!   and summing B-spline coefficients would cancel them away (on a wide plate
//!   the cancellation is harmless and the global functions would only mix the
//!   1/r³ terms of a small hole into every row);
//! - a supported or clamped hole smaller than 1 % of r_a is a point support with
//!   a boundary layer of its own size: [`GRADED_KNOTS`] extra knots are graded
//!   geometrically towards r_i, down to a span of r_i/4.

use super::bspline::BSplineBasis;
use super::quadrature::radial_points;
use crate::config::{Boundary, PlateConfig};
use faer::Mat;

/// Extra knots graded towards a small pinned hole.
pub const GRADED_KNOTS: usize = 12;
/// Holes below this fraction of r_a get graded knots when supported or clamped.
pub const SMALL_HOLE_RATIO: f64 = 0.01;
/// Free–free plates with r_i/r_a at least this use the exact rigid-like functions.
pub const RING_RATIO: f64 = 0.5;

/// c_k = ∫₀^{2π} cos²(kφ) dφ.
pub fn angular_norm(k: u32) -> f64 {
    if k == 0 {
        std::f64::consts::TAU
    } else {
        std::f64::consts::PI
    }
}

/// A quadrature point with the four B-splines non-zero there.
#[derive(Debug, Clone)]
pub(crate) struct QuadPoint {
    pub(crate) span: usize,
    pub(crate) r: f64,
    pub(crate) weight: f64,
    /// ders[d][j]: d-th derivative of N_{span+j}.
    pub(crate) ders: [[f64; 4]; 4],
}

/// The quadrature points of `basis` (`radial_points` per span) with the
/// B-splines' values and derivatives there.
pub(crate) fn quadrature_points(basis: &BSplineBasis) -> Vec<QuadPoint> {
    let mut points = Vec::new();
    let mut buf = Vec::new();
    for s in 0..basis.spans() {
        let (lo, hi) = basis.span_bounds(s);
        buf.clear();
        radial_points(lo, hi, &mut buf);
        points.extend(buf.iter().map(|&(r, weight)| QuadPoint {
            span: s,
            r,
            weight,
            ders: basis.eval_span(s, r),
        }));
    }
    points
}

/// The radial basis with its boundary conditions and cached quadrature.
#[derive(Debug, Clone)]
pub struct RadialDiscretisation {
    pub basis: BSplineBasis,
    /// Global B-spline index of each free coefficient.
    pub free: Vec<usize>,
    /// Position in `free` of each global B-spline, or None if dropped.
    slot: Vec<Option<usize>>,
    /// Free–free: slots 0 and 1 hold R = 1 and R = (r − r_m)/width instead of N_0, N_1.
    rigid_functions: Option<(f64, f64)>,
    points: Vec<QuadPoint>,
    rigidity: f64,
    areal_density: f64,
    poisson: f64,
}

impl RadialDiscretisation {
    /// The basis of `splines` uniform cubic B-splines (plus the graded knots
    /// of a small pinned hole) with the plate's edge conditions.
    pub fn new(plate: &PlateConfig, rigidity: f64, splines: usize) -> Self {
        let (ri, ra) = (plate.inner_radius, plate.outer_radius);
        let pinned_small_hole =
            plate.inner_boundary != Boundary::Free && ri / ra < SMALL_HOLE_RATIO;
        let basis = if pinned_small_hole {
            BSplineBasis::graded(ri, ra, splines, GRADED_KNOTS, 0.25 * ri)
        } else {
            BSplineBasis::new(ri, ra, splines)
        };
        let n = basis.len();
        let drop_inner = plate.inner_boundary.essential_conditions();
        let drop_outer = plate.outer_boundary.essential_conditions();
        let free: Vec<usize> = (drop_inner..n - drop_outer).collect();
        let mut slot = vec![None; n];
        for (pos, &g) in free.iter().enumerate() {
            slot[g] = Some(pos);
        }
        let free_free =
            plate.inner_boundary == Boundary::Free && plate.outer_boundary == Boundary::Free;
        let rigid_functions =
            (free_free && ri / ra >= RING_RATIO).then_some((0.5 * (ri + ra), ra - ri));
        let points = quadrature_points(&basis);
        RadialDiscretisation {
            basis,
            free,
            slot,
            rigid_functions,
            points,
            rigidity,
            areal_density: plate.density * plate.thickness,
            poisson: plate.poisson_ratio,
        }
    }

    pub fn n_free(&self) -> usize {
        self.free.len()
    }

    /// (K̄, M̄) for nodal-diameter number k, over the free coefficients.
    pub fn assemble(&self, k: u32) -> (Mat<f64>, Mat<f64>) {
        let n = self.n_free();
        let mut kk = Mat::<f64>::zeros(n, n);
        let mut mm = Mat::<f64>::zeros(n, n);
        let kf = k as f64;
        let k2 = kf * kf;
        let nu = self.poisson;
        let ck = angular_norm(k);
        // Up to six functions are non-zero at a point: the span's four B-splines,
        // or for a free–free plate the rigid-like pair and the span's others.
        let mut local: [(usize, [f64; 3]); 6] = [(0, [0.0; 3]); 6];
        for p in &self.points {
            let r = p.r;
            let w = p.weight * r * ck;
            let count = self.local_functions(p, &mut local);
            // Per function: R'' (A), R'/r − k²R/r² (B), R'/r − R/r² (C); laplacian A + B.
            let mut abc = [[0.0; 3]; 6];
            for (f, &(_, [v, d1, d2])) in abc.iter_mut().zip(&local[..count]) {
                *f = [d2, d1 / r - k2 * v / (r * r), d1 / r - v / (r * r)];
            }
            for i in 0..count {
                let (gi, [vi, ..]) = local[i];
                let [ai, bi, ci] = abc[i];
                for j in 0..count {
                    let (gj, [vj, ..]) = local[j];
                    let [aj, bj, cj] = abc[j];
                    let stiff = (ai + bi) * (aj + bj) - (1.0 - nu) * (ai * bj + bi * aj)
                        + 2.0 * (1.0 - nu) * k2 * ci * cj;
                    kk[(gi, gj)] += self.rigidity * w * stiff;
                    mm[(gi, gj)] += self.areal_density * w * vi * vj;
                }
            }
        }
        (kk, mm)
    }

    /// The free functions non-zero at a quadrature point: (slot, [R, R', R'']).
    /// Up to six: the span's four B-splines, or for a free–free plate the
    /// rigid-like pair and the span's others.
    fn local_functions(&self, p: &QuadPoint, local: &mut [(usize, [f64; 3]); 6]) -> usize {
        let r = p.r;
        let mut count = 0;
        if let Some((rm, width)) = self.rigid_functions {
            local[0] = (0, [1.0, 0.0, 0.0]);
            local[1] = (1, [(r - rm) / width, 1.0 / width, 0.0]);
            count = 2;
        }
        for j in 0..4 {
            let g = p.span + j;
            if self.rigid_functions.is_some() && g < 2 {
                continue;
            }
            let Some(pos) = self.slot[g] else { continue };
            local[count] = (pos, [p.ders[0][j], p.ders[1][j], p.ders[2][j]]);
            count += 1;
        }
        count
    }

    /// Geometric stiffness K̄_g of the in-plane prestress (σ_r, σ_θ) =
    /// `stresses(r)` for nodal-diameter number k, over the free coefficients:
    /// U_g = ½ c_k h ∫ (σ_r R'² + σ_θ k² R²/r²) r dr (DESIGN.md "Spinning
    /// prestress"; docs/rotor_dynamics.md).
    pub fn assemble_geometric(
        &self,
        k: u32,
        thickness: f64,
        stresses: impl Fn(f64) -> (f64, f64),
    ) -> Mat<f64> {
        let n = self.n_free();
        let mut kg = Mat::<f64>::zeros(n, n);
        let k2 = (k as f64) * (k as f64);
        let ck = angular_norm(k);
        let mut local: [(usize, [f64; 3]); 6] = [(0, [0.0; 3]); 6];
        for p in &self.points {
            let r = p.r;
            let w = p.weight * r * ck * thickness;
            let (sr, st) = stresses(r);
            let count = self.local_functions(p, &mut local);
            for &(gi, [vi, di, _]) in &local[..count] {
                for &(gj, [vj, dj, _]) in &local[..count] {
                    kg[(gi, gj)] += w * (sr * di * dj + st * k2 * vi * vj / (r * r));
                }
            }
        }
        kg
    }

    /// Expand free coefficients to B-spline coefficients of all splines (zeros
    /// where dropped). The rigid-like pair of a free–free plate is re-expressed
    /// in B-splines: 1 = Σ N_j and r = Σ ξ*_j N_j (Greville abscissae).
    pub fn expand(&self, free_coefficients: impl Iterator<Item = f64>) -> Vec<f64> {
        let mut full = vec![0.0; self.basis.len()];
        for (&g, c) in self.free.iter().zip(free_coefficients) {
            full[g] = c;
        }
        if let Some((rm, width)) = self.rigid_functions {
            let (c0, c1) = (full[0], full[1]);
            full[0] = 0.0;
            full[1] = 0.0;
            for (b, xi) in full.iter_mut().zip(self.basis.greville()) {
                *b += c0 + c1 * (xi - rm) / width;
            }
        }
        full
    }
}
