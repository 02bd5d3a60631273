//! Mass and stiffness of the in-plane radial problem per nodal-diameter
//! number k and family (the weak form in [`super`]): cubic B-splines N_j for
//! U and V, the essential edge conditions (`fixed`: U = V = 0) eliminated by
//! dropping the edge B-spline, the only one non-zero at the edge.
//!
//! Coefficients are interleaved by B-spline, (U_j, V_j) for the coupled
//! family of k ≥ 1, U_j alone (radial) or V_j alone (torsional) for k = 0,
//! so the matrices are banded.

use super::{InPlaneEdge, InPlaneError, InPlaneFamily, InPlanePlate, MAX_SPLINES, MIN_SPLINES};
use crate::model::bspline::BSplineBasis;
use crate::model::radial::{angular_norm, quadrature_points, QuadPoint};
use faer::Mat;

/// The radial B-splines of U and V with their quadrature.
#[derive(Debug, Clone)]
pub struct InPlaneDiscretisation {
    plate: InPlanePlate,
    basis: BSplineBasis,
    points: Vec<QuadPoint>,
}

/// The strains (ε_r, ε_θ, γ_rθ) and the displacements (U, V) of one
/// field's B-spline at a point.
type Kinematics = ([f64; 3], [f64; 2]);

impl InPlaneDiscretisation {
    /// `splines` uniform cubic B-splines per field on [r_i, r_a].
    pub fn new(plate: &InPlanePlate, splines: usize) -> Result<Self, InPlaneError> {
        plate.validate()?;
        if !(MIN_SPLINES..=MAX_SPLINES).contains(&splines) {
            return Err(InPlaneError::Splines {
                splines,
                min: MIN_SPLINES,
                max: MAX_SPLINES,
            });
        }
        let basis = BSplineBasis::new(plate.inner_radius, plate.outer_radius, splines);
        let points = quadrature_points(&basis);
        Ok(InPlaneDiscretisation {
            plate: *plate,
            basis,
            points,
        })
    }

    /// The plate.
    pub fn plate(&self) -> &InPlanePlate {
        &self.plate
    }

    /// The B-spline basis shared by U and V.
    pub fn basis(&self) -> &BSplineBasis {
        &self.basis
    }

    /// The quadrature points with the B-splines' values and derivatives.
    pub(super) fn points(&self) -> &[QuadPoint] {
        &self.points
    }

    /// The position of B-spline j among the free B-splines (those not
    /// dropped by a fixed edge), or `None` when it is dropped. A family's
    /// free coefficient of field slot s (0 or 1 within
    /// [`InPlaneFamily::fields`]) of that B-spline is position · fields + s.
    pub(super) fn free_spline(&self, j: usize) -> Option<usize> {
        let n = self.basis.len();
        let inner = usize::from(self.plate.inner_edge == InPlaneEdge::Fixed);
        let outer_fixed = self.plate.outer_edge == InPlaneEdge::Fixed;
        if (j == 0 && inner == 1) || (j == n - 1 && outer_fixed) {
            None
        } else {
            Some(j - inner)
        }
    }

    /// The coefficient index of B-spline j of field f (0: U, 1: V) within
    /// `fields`, or `None` when the family has no such field.
    fn index(fields: &[usize], f: usize, j: usize) -> Option<usize> {
        let at = fields.iter().position(|&g| g == f)?;
        Some(j * fields.len() + at)
    }

    /// The free coefficients: every coefficient but the edge B-splines' of a
    /// fixed edge.
    fn free(&self, family: InPlaneFamily) -> Vec<usize> {
        let n = self.basis.len();
        let fields = family.fields();
        let fixed_spline = |j: usize| {
            (j == 0 && self.plate.inner_edge == InPlaneEdge::Fixed)
                || (j == n - 1 && self.plate.outer_edge == InPlaneEdge::Fixed)
        };
        (0..n * fields.len())
            .filter(|&i| !fixed_spline(i / fields.len()))
            .collect()
    }

    /// The number of free coefficients of `family`.
    pub fn n_free(&self, family: InPlaneFamily) -> usize {
        self.free(family).len()
    }

    /// Strains and displacements of B-spline `[v, v']` of field f (0: U,
    /// 1: V) at r for k: U gives ε_r = U', ε_θ = U/r, γ = −kU/r; V gives
    /// ε_θ = kV/r, γ = V' − V/r.
    fn kinematics(f: usize, k: f64, r: f64, [v, d1]: [f64; 2]) -> Kinematics {
        if f == 0 {
            ([d1, v / r, -k * v / r], [v, 0.0])
        } else {
            ([0.0, k * v / r, d1 - v / r], [0.0, v])
        }
    }

    /// (K̄, M̄) of k and `family` over the free coefficients: the bilinear
    /// forms of U and T of [`super`] (with c_k), symmetric, M̄ positive
    /// definite.
    pub fn assemble(&self, k: u32, family: InPlaneFamily) -> (Mat<f64>, Mat<f64>) {
        let fields = family.fields();
        let free = self.free(family);
        let mut slot = vec![usize::MAX; self.basis.len() * fields.len()];
        for (a, &g) in free.iter().enumerate() {
            slot[g] = a;
        }
        let mut kk = Mat::<f64>::zeros(free.len(), free.len());
        let mut mm = Mat::<f64>::zeros(free.len(), free.len());
        let p = &self.plate;
        let (e_bar, g, nu) = (
            p.membrane_modulus() * p.thickness,
            p.shear_modulus() * p.thickness,
            p.poisson_ratio,
        );
        let rho_h = p.density * p.thickness;
        let ck = angular_norm(k);
        let kf = k as f64;
        let mut local: Vec<(usize, Kinematics)> = Vec::with_capacity(8);
        for q in &self.points {
            let w = q.weight * q.r * ck;
            local.clear();
            for &f in fields {
                for j in 0..4 {
                    let Some(i) = Self::index(fields, f, q.span + j) else {
                        continue;
                    };
                    if slot[i] != usize::MAX {
                        let v = [q.ders[0][j], q.ders[1][j]];
                        local.push((slot[i], Self::kinematics(f, kf, q.r, v)));
                    }
                }
            }
            for &(a, (ea, ua)) in &local {
                for &(b, (eb, ub)) in &local {
                    let stretch =
                        ea[0] * eb[0] + ea[1] * eb[1] + nu * (ea[0] * eb[1] + ea[1] * eb[0]);
                    kk[(a, b)] += w * (e_bar * stretch + g * ea[2] * eb[2]);
                    mm[(a, b)] += w * rho_h * (ua[0] * ub[0] + ua[1] * ub[1]);
                }
            }
        }
        (kk, mm)
    }

    /// B-spline coefficients of U and V (zeros for a field the family lacks)
    /// from the free ones.
    pub fn expand(&self, family: InPlaneFamily, free: impl Iterator<Item = f64>) -> [Vec<f64>; 2] {
        let n = self.basis.len();
        let fields = family.fields();
        let mut all = vec![0.0; n * fields.len()];
        for (&g, c) in self.free(family).iter().zip(free) {
            all[g] = c;
        }
        let field = |f: usize| {
            (0..n)
                .map(|j| Self::index(fields, f, j).map_or(0.0, |i| all[i]))
                .collect()
        };
        [field(0), field(1)]
    }
}

impl InPlaneDiscretisation {
    /// The load vector over the free coefficients of `family` of a force
    /// on field f (0: U, radial; 1: V, tangential) with B-spline weights
    /// `means` (a patch's [`crate::model::patch::LoadPatch::spline_means`]);
    /// zeros when the family lacks the field.
    pub(crate) fn field_load(&self, family: InPlaneFamily, f: usize, means: &[f64]) -> Vec<f64> {
        let fields = family.fields();
        self.free(family)
            .iter()
            .map(|&i| {
                let (j, g) = (i / fields.len(), fields[i % fields.len()]);
                if g == f {
                    means[j]
                } else {
                    0.0
                }
            })
            .collect()
    }
}
