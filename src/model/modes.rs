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

use super::body::BodyData;
use super::bspline::BSplineBasis;
use super::eigen::{lowest_modes, EigenFailure};
use super::radial::{angular_norm, RadialDiscretisation};
use super::{bending_rigidity, ModelError, PlateModel};
use crate::config::{Boundary, PlateConfig};
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
    pub shape: AngularShape,
    /// Circular eigenfrequency ω, rad/s.
    pub omega: f64,
    pub frequency_hz: f64,
    /// Generalized mass m_i = ρh ∫ w_i² dA, kg (for the unit-peak shape).
    pub modal_mass: f64,
    /// Modal damping ratio ζ_i.
    pub damping: f64,
    /// Index into [`PlateModel::radial_shapes`].
    #[serde(skip)]
    pub radial: usize,
    /// Index of the partner of a cos/sin pair (None for k = 0).
    #[serde(skip)]
    pub partner: Option<usize>,
}

/// A radial function R_l(r) = Σ c_j N_j(r) for one ⟨k, l⟩.
#[derive(Debug, Clone, PartialEq)]
pub struct RadialShape {
    pub k: u32,
    pub l: u32,
    pub omega: f64,
    basis: BSplineBasis,
    coefficients: Vec<f64>,
}

impl RadialShape {
    /// R, R', R'', R''' at r (clamped to [r_i, r_a]).
    pub fn eval(&self, r: f64) -> [f64; 4] {
        let (a, b) = self.basis.interval();
        self.basis.eval_combination(&self.coefficients, r.clamp(a, b))
    }
    pub fn value(&self, r: f64) -> f64 {
        self.eval(r)[0]
    }
    pub fn coefficients(&self) -> &[f64] {
        &self.coefficients
    }
    pub fn basis(&self) -> &BSplineBasis {
        &self.basis
    }

    /// Location and value of max |R| (the spline's critical points per span).
    fn peak(&self) -> (f64, f64) {
        let mut best = (self.basis.interval().0, 0.0f64);
        let mut consider = |r: f64| {
            let v = self.value(r);
            if v.abs() > best.1.abs() {
                best = (r, v);
            }
        };
        for s in 0..self.basis.spans() {
            let (lo, hi) = self.basis.span_bounds(s);
            consider(lo);
            consider(hi);
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
                consider(lo + t * (hi - lo));
            }
        }
        best
    }
}

/// Essential conditions leave rigid-body modes only on a free–free plate.
pub fn is_rigid_body(inner: Boundary, outer: Boundary, k: u32, l: u32) -> bool {
    inner == Boundary::Free && outer == Boundary::Free && l == 0 && k <= 1
}

/// Build the plate model (called by [`PlateModel::new`]).
pub(super) fn build(plate: &PlateConfig) -> Result<PlateModel, ModelError> {
    let nu = plate.poisson_ratio;
    let rigidity = bending_rigidity(plate.youngs_modulus, plate.thickness, nu);
    let rho_h = plate.density * plate.thickness;
    let disc = RadialDiscretisation::new(plate, rigidity);
    let max_l = plate.nodal_circles.iter().copied().max().unwrap_or(0);
    if plate.radial_splines < plate.min_radial_splines() {
        return Err(ModelError::TooFewRadialSplines {
            splines: plate.radial_splines,
            bc_inner: plate.inner_boundary.name(),
            bc_outer: plate.outer_boundary.name(),
            max_l,
            min_splines: plate.min_radial_splines(),
        });
    }
    // Shift: a stiffness scale between the width and the outer radius.
    let width = plate.outer_radius - plate.inner_radius;
    let sigma = rigidity / (rho_h * width * width * plate.outer_radius * plate.outer_radius);

    let mut ks: Vec<u32> = plate.nodal_diameters.clone();
    ks.sort_unstable();
    let mut ls: Vec<u32> = plate.nodal_circles.clone();
    ls.sort_unstable();

    let mut radial_shapes = Vec::new();
    let mut skipped = Vec::new();
    struct Entry {
        radial: usize,
        modal_mass: f64,
    }
    let mut entries: Vec<(u32, u32, f64, Entry)> = Vec::new();
    for &k in &ks {
        let (kk, mm) = disc.assemble(k);
        let pairs = lowest_modes(&kk, &mm, sigma, max_l as usize + 1).map_err(|e| match e {
            EigenFailure::MassNotPositiveDefinite(reason) => ModelError::MassNotPositiveDefinite { k, reason },
            EigenFailure::ShiftedNotPositiveDefinite(reason) | EigenFailure::Decomposition(reason) => ModelError::Eigenproblem { k, reason },
        })?;
        for &l in &ls {
            if is_rigid_body(plate.inner_boundary, plate.outer_boundary, k, l) {
                skipped.push((k, l));
                continue;
            }
            let w2 = pairs.omega_squared[l as usize];
            if !w2.is_finite() || w2 <= 0.0 {
                return Err(ModelError::NonFiniteMode { k, l, omega_squared: w2, hint: degenerate_hint(plate) });
            }
            let col = pairs.vectors.col(l as usize);
            let coefficients = disc.expand((0..col.nrows()).map(|i| col[i]));
            let mut shape = RadialShape { k, l, omega: w2.sqrt(), basis: disc.basis.clone(), coefficients };
            let (_, peak) = shape.peak();
            if peak == 0.0 || !peak.is_finite() {
                return Err(ModelError::NonFiniteMode { k, l, omega_squared: w2, hint: degenerate_hint(plate) });
            }
            shape.coefficients.iter_mut().for_each(|c| *c /= peak);
            // The eigenvector was M̄-normalised (M̄ includes ρh c_k): modal mass of the unit-peak shape.
            let modal_mass = 1.0 / (peak * peak);
            debug_assert!((modal_mass - rho_h * angular_norm(k) * radial_moment(&shape, 2, 1)).abs() < 1e-6 * modal_mass);
            radial_shapes.push(shape);
            entries.push((k, l, w2.sqrt(), Entry { radial: radial_shapes.len() - 1, modal_mass }));
        }
    }
    if entries.is_empty() {
        return Err(ModelError::NoElasticModes { skipped });
    }
    // Expand into modes: one per k = 0, a cos/sin pair otherwise; sort by frequency, then k, then cos before sin.
    let mut modes: Vec<Mode> = Vec::new();
    for (k, l, omega, e) in &entries {
        let shapes: &[AngularShape] = if *k == 0 { &[AngularShape::Axisymmetric] } else { &[AngularShape::Cos, AngularShape::Sin] };
        for &shape in shapes {
            modes.push(Mode {
                k: *k,
                l: *l,
                shape,
                omega: *omega,
                frequency_hz: omega / std::f64::consts::TAU,
                modal_mass: e.modal_mass,
                damping: 0.0,
                radial: e.radial,
                partner: None,
            });
        }
    }
    modes.sort_by(|a, b| a.omega.total_cmp(&b.omega).then(a.k.cmp(&b.k)).then(a.shape.cmp(&b.shape)).then(a.l.cmp(&b.l)));
    for i in 0..modes.len() {
        modes[i].damping = if plate.damping.len() == 1 { plate.damping[0] } else { plate.damping.get(i).copied().unwrap_or(0.0) };
        if modes[i].k > 0 {
            modes[i].partner = modes.iter().position(|m| m.k == modes[i].k && m.l == modes[i].l && m.shape != modes[i].shape);
        }
    }
    let body = BodyData::new(plate, &modes, &radial_shapes);
    Ok(PlateModel { plate: plate.clone(), rigidity, modes, radial_shapes, skipped_rigid_body_modes: skipped, body })
}

/// ∫ R^power · r^r_power dr over [r_i, r_a] by Gauss quadrature on the spline spans.
pub fn radial_moment(shape: &RadialShape, power: i32, r_power: i32) -> f64 {
    let mut pts = Vec::new();
    for s in 0..shape.basis.spans() {
        let (lo, hi) = shape.basis.span_bounds(s);
        super::quadrature::radial_points(lo, hi, &mut pts);
    }
    pts.iter().map(|&(r, w)| w * shape.value(r).powi(power) * r.powi(r_power)).sum()
}

fn degenerate_hint(plate: &PlateConfig) -> String {
    let ratio = plate.inner_radius / plate.outer_radius;
    if ratio < 1e-3 {
        format!("r_i/r_a = {ratio:e}: near the circular-plate limit of paper section 4.2")
    } else if 1.0 - ratio < 1e-2 {
        format!("r_i/r_a = {ratio}: near the narrow-ring limit of paper section 4.2")
    } else {
        "check thickness, moduli and density for extreme values".into()
    }
}
