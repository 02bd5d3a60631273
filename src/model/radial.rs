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

use super::bspline::BSplineBasis;
use super::quadrature::radial_points;
use crate::config::PlateConfig;
use faer::Mat;

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
struct QuadPoint {
    span: usize,
    r: f64,
    weight: f64,
    /// ders[d][j]: d-th derivative of N_{span+j}.
    ders: [[f64; 4]; 4],
}

/// The radial basis with its boundary conditions and cached quadrature.
#[derive(Debug, Clone)]
pub struct RadialDiscretisation {
    pub basis: BSplineBasis,
    /// Global B-spline index of each free coefficient.
    pub free: Vec<usize>,
    /// Position in `free` of each global B-spline, or None if dropped.
    slot: Vec<Option<usize>>,
    points: Vec<QuadPoint>,
    rigidity: f64,
    areal_density: f64,
    poisson: f64,
}

impl RadialDiscretisation {
    pub fn new(plate: &PlateConfig, rigidity: f64) -> Self {
        let basis = BSplineBasis::new(plate.inner_radius, plate.outer_radius, plate.radial_splines);
        let n = basis.len();
        let drop_inner = plate.inner_boundary.essential_conditions();
        let drop_outer = plate.outer_boundary.essential_conditions();
        let free: Vec<usize> = (drop_inner..n - drop_outer).collect();
        let mut slot = vec![None; n];
        for (pos, &g) in free.iter().enumerate() {
            slot[g] = Some(pos);
        }
        let mut points = Vec::new();
        let mut buf = Vec::new();
        for s in 0..basis.spans() {
            let (lo, hi) = basis.span_bounds(s);
            buf.clear();
            radial_points(lo, hi, &mut buf);
            for &(r, weight) in &buf {
                points.push(QuadPoint { span: s, r, weight, ders: basis.eval_span(s, r) });
            }
        }
        RadialDiscretisation {
            basis,
            free,
            slot,
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
        for p in &self.points {
            let r = p.r;
            let w = p.weight * r * ck;
            // Per local function: laplacian L, R'' (A), R'/r − k²R/r² (B), R'/r − R/r² (C).
            let mut lap = [0.0; 4];
            let mut a = [0.0; 4];
            let mut b = [0.0; 4];
            let mut c = [0.0; 4];
            for j in 0..4 {
                let (v, d1, d2) = (p.ders[0][j], p.ders[1][j], p.ders[2][j]);
                a[j] = d2;
                b[j] = d1 / r - k2 * v / (r * r);
                c[j] = d1 / r - v / (r * r);
                lap[j] = a[j] + b[j];
            }
            for i in 0..4 {
                let Some(gi) = self.slot[p.span + i] else { continue };
                for j in 0..4 {
                    let Some(gj) = self.slot[p.span + j] else { continue };
                    let stiff = lap[i] * lap[j] - (1.0 - nu) * (a[i] * b[j] + b[i] * a[j]) + 2.0 * (1.0 - nu) * k2 * c[i] * c[j];
                    kk[(gi, gj)] += self.rigidity * w * stiff;
                    mm[(gi, gj)] += self.areal_density * w * p.ders[0][i] * p.ders[0][j];
                }
            }
        }
        (kk, mm)
    }

    /// Expand free coefficients to all B-splines (zeros where dropped).
    pub fn expand(&self, free_coefficients: impl Iterator<Item = f64>) -> Vec<f64> {
        let mut full = vec![0.0; self.basis.len()];
        for (&g, c) in self.free.iter().zip(free_coefficients) {
            full[g] = c;
        }
        full
    }
}
