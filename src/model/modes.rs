//! The mode table (paper eq. (13), section 4.1): exactly the requested
//! ⟨k, l⟩ = nodal diameters × nodal circles, a cos/sin pair per k ≥ 1 and one
//! axisymmetric mode per k = 0, sorted by frequency.
//!
//! Numbering: l is the index of the radial eigenfunction for that k in
//! ascending frequency, which is its number of nodal circles. A free–free
//! plate's ⟨0, 0⟩ (translation) and ⟨1, 0⟩ (tilt) are rigid-body motions:
//! the floating frame of reference and the joint carry those, so they are not
//! elastic modes and are left out (reported by
//! [`PlateModel::skipped_rigid_body_modes`]).
//!
//! Normalisation: each R_l has max |R_l(r)| = 1 over [r_i, r_a], positive at
//! that peak, so a modal amplitude is the peak transverse displacement in metres.

use super::bspline::BSplineBasis;
use crate::config::Boundary;
use serde::Serialize;

/// Angular factor Θ(kφ) of a mode.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum AngularShape {
    /// k = 0: Θ = 1.
    Axisymmetric,
    /// Θ = cos(kφ).
    Cos,
    /// Θ = sin(kφ).
    Sin,
}

impl AngularShape {
    /// `cos` or `sin`.
    pub fn name(self) -> &'static str {
        match self {
            AngularShape::Axisymmetric => "axisymmetric",
            AngularShape::Cos => "cos",
            AngularShape::Sin => "sin",
        }
    }

    /// Θ(kφ) and dΘ/dφ.
    #[inline]
    pub fn eval(self, k: u32, phi: f64) -> (f64, f64) {
        let kf = k as f64;
        match self {
            AngularShape::Axisymmetric => (1.0, 0.0),
            AngularShape::Cos => {
                let (s, c) = (kf * phi).sin_cos();
                (c, -kf * s)
            }
            AngularShape::Sin => {
                let (s, c) = (kf * phi).sin_cos();
                (s, kf * c)
            }
        }
    }
}

/// One elastic mode of the plate.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Mode {
    /// Nodal diameters.
    pub k: u32,
    /// Nodal circles.
    pub l: u32,
    /// cos kφ or sin kφ.
    pub shape: AngularShape,
    /// Circular eigenfrequency ω, rad/s.
    pub omega: f64,
    /// ω/2π, Hz.
    pub frequency_hz: f64,
    /// Generalized mass m_i = ρh ∫ w_i² dA, kg (for the unit-peak shape);
    /// under Mindlin theory plus the rotary inertia ρh³/12 ∫ ψ_i·ψ_i dA.
    pub modal_mass: f64,
    /// Modal damping ratio ζ_i.
    pub damping: f64,
    /// Index into `PlateModel::radial_shapes`.
    #[serde(skip)]
    pub radial: usize,
    /// Index of the partner of a cos/sin pair (None for k = 0).
    #[serde(skip)]
    pub partner: Option<usize>,
}

/// A radial function R_l(r) = Σ c_j N_j(r) for one ⟨k, l⟩.
#[derive(Debug, Clone, PartialEq)]
pub struct RadialShape {
    /// Nodal diameters.
    pub k: u32,
    /// Nodal circles.
    pub l: u32,
    /// Circular eigenfrequency ω, rad/s.
    pub omega: f64,
    pub(super) basis: BSplineBasis,
    pub(super) coefficients: Vec<f64>,
}

impl RadialShape {
    /// R, R', R'', R''' at r (clamped to [r_i, r_a]).
    pub fn eval(&self, r: f64) -> [f64; 4] {
        let (a, b) = self.basis.interval();
        self.basis
            .eval_combination(&self.coefficients, r.clamp(a, b))
    }
    /// R(r) (clamped to [r_i, r_a]).
    pub fn value(&self, r: f64) -> f64 {
        self.eval(r)[0]
    }
    /// The coefficients c_j of the B-splines N_j.
    pub fn coefficients(&self) -> &[f64] {
        &self.coefficients
    }
    /// The B-spline basis N_j.
    pub fn basis(&self) -> &BSplineBasis {
        &self.basis
    }

    /// Location and value of max |R| (the spline's critical points per span).
    pub(super) fn peak(&self) -> (f64, f64) {
        let mut best = (self.basis.interval().0, 0.0f64);
        let consider = |best: &mut (f64, f64), r: f64| {
            let v = self.value(r);
            if v.abs() > best.1.abs() {
                *best = (r, v);
            }
        };
        // |R| ≤ max |c_j| of the span's four B-splines (convex hull): spans
        // that cannot beat the best value so far are skipped, largest first.
        let bound = |s: usize| {
            self.coefficients[s..s + 4]
                .iter()
                .fold(0.0f64, |m, c| m.max(c.abs()))
        };
        let mut spans: Vec<usize> = (0..self.basis.spans()).collect();
        spans.sort_by(|&a, &b| bound(b).total_cmp(&bound(a)).then(a.cmp(&b)));
        for s in spans {
            if bound(s) < best.1.abs() {
                break;
            }
            let (lo, hi) = self.basis.span_bounds(s);
            consider(&mut best, lo);
            consider(&mut best, hi);
            // R' is a quadratic on the span: fit it from three points, take its roots.
            let d = |t: f64| self.eval(lo + t * (hi - lo))[1];
            let (d0, d1, d2) = (d(0.0), d(0.5), d(1.0));
            let qa = 2.0 * (d0 - 2.0 * d1 + d2);
            let qb = -3.0 * d0 + 4.0 * d1 - d2;
            let qc = d0;
            let mut roots = [f64::NAN; 2];
            if qa.abs() > 1e-14 * (qb.abs() + qc.abs()) {
                let disc = qb * qb - 4.0 * qa * qc;
                if disc >= 0.0 {
                    let sq = disc.sqrt();
                    roots = [(-qb - sq) / (2.0 * qa), (-qb + sq) / (2.0 * qa)];
                }
            } else if qb != 0.0 {
                roots[0] = -qc / qb;
            }
            for t in roots.into_iter().filter(|t| (0.0..=1.0).contains(t)) {
                consider(&mut best, lo + t * (hi - lo));
            }
        }
        best
    }
}

/// Essential conditions leave rigid-body modes only on a free–free plate.
pub fn is_rigid_body(inner: Boundary, outer: Boundary, k: u32, l: u32) -> bool {
    inner == Boundary::Free && outer == Boundary::Free && l == 0 && k <= 1
}

/// ∫ R^power · r^r_power dr over [r_i, r_a] by Gauss quadrature on the spline spans.
pub fn radial_moment(shape: &RadialShape, power: i32, r_power: i32) -> f64 {
    let mut pts = Vec::new();
    for s in 0..shape.basis.spans() {
        let (lo, hi) = shape.basis.span_bounds(s);
        super::quadrature::radial_points(lo, hi, &mut pts);
    }
    pts.iter()
        .map(|&(r, w)| w * shape.value(r).powi(power) * r.powi(r_power))
        .sum()
}
