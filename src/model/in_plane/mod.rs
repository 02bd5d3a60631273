//! In-plane (plane-stress) modes of the annular plate: the mid-plane's own
//! vibration u = u_r e_r + u_θ e_θ, a second mode family beside the bending
//! modes, by the same radial B-spline Ritz machinery (docs/in_plane.md).
//! `modes` lists them, `simulate` and `run` carry them
//! (the dynamics' in-plane module), `campbell` adds their spinning waves
//! ([`in_plane_campbell`]); the analyses that do not carry them refuse
//! `plate.in_plane_nodal_diameters` ([`crate::model::PlateModel::new`]).
//! For the spinning disc, `spin` gives
//! the turning-frame equations' Coriolis and spin stiffness terms per k
//! ([`InPlaneDiscretisation::assemble_spin`]) and `spectrum` their forward
//! and backward waves ([`InPlaneDiscretisation::spectrum`]).
//!
//! # Fields and energies
//!
//! Plane stress in the plate's material, thickness h. Strains
//!
//! ε_r = ∂u_r/∂r,  ε_θ = (u_r + ∂u_θ/∂θ)/r,  γ_rθ = (1/r) ∂u_r/∂θ + ∂u_θ/∂r − u_θ/r,
//!
//! stresses σ_rr = Ē (ε_r + ν ε_θ), σ_θθ = Ē (ε_θ + ν ε_r), σ_rθ = G γ_rθ
//! with Ē = E/(1 − ν²) and G = E/(2 (1 + ν)).
//!
//! # Harmonic k and the weak form
//!
//! Per nodal-diameter number k ≥ 1 the cos partner is
//! u_r = U(r) cos kθ, u_θ = V(r) sin kθ; the sin partner, the cos partner
//! turned by a quarter wave, is u_r = U sin kθ, u_θ = −V cos kθ. For k = 0
//! the problem splits into the torsional family (u_θ = V(r), u_r = 0) and
//! the radial family (u_r = U(r), u_θ = 0). With c_k = 2π (k = 0), π
//! (k ≥ 1) the energies are
//!
//! U = c_k/2 ∫ h [ Ē (e_r² + e_θ² + 2ν e_r e_θ) + G e_rθ² ] r dr,
//! T = c_k/2 ∫ ρh (U̇² + V̇²) r dr,
//!
//! e_r = U',  e_θ = (U + k V)/r,  e_rθ = V' − V/r − k U/r,
//!
//! and the modes are the stationary points of U − ω² T. Edges: `fixed`
//! U = V = 0 (essential); `free` σ_rr = σ_rθ = 0 (natural).
//!
//! # Discretisation and convergence
//!
//! U and V each on the same uniform cubic B-splines; a fixed edge drops the
//! edge B-spline of both. The energy has first derivatives only, so the
//! frequencies converge as the sixth power of the spline spacing
//! (docs/in_plane.md gives the measured errors per count).
//!
//! # Numbering and normalisation
//!
//! l is the index in ascending frequency per k and family. The rigid-body
//! motions of a free–free annulus — the rotation (k = 0 torsional, l = 0)
//! and the translations (k = 1, l = 0) — are left out, as the bending
//! modes' rigid ⟨0, 0⟩ and ⟨1, 0⟩ are. The shapes are scaled to
//! max(|U|, |V|) = 1 over [r_i, r_a], positive at that peak (an amplitude
//! is the peak in-plane displacement in metres); the modal mass is
//! c_k ∫ ρh (U² + V²) r dr.

mod assembly;
mod campbell;
mod error;
mod model;
mod residual;
mod spectrum;
mod spin;

pub use assembly::InPlaneDiscretisation;
pub use campbell::{in_plane_campbell, InPlaneCampbell, InPlaneCampbellWave, InPlaneCriticalSpeed};
pub use error::InPlaneError;
pub use model::{in_plane_plate, InPlaneEntry, InPlaneShape, InPlaneTable};
pub use residual::{
    modal_kernel, patch_means, residual_kernel, InPlaneKernel, InPlanePatchHarmonics, LoadPatch,
    MAX_HARMONICS, TOLERANCE,
};
pub use spectrum::{InPlaneSpectrum, InPlaneWaves};
pub use spin::{spin_blocks, InPlaneSpin};

use super::bspline::BSplineBasis;
use super::modes::RadialShape;
use super::resolution::lowest_pairs;

/// Cubic B-splines per field for `plate.radial_splines: auto`: the exact
/// in-plane frequencies of k ≤ 8, l ≤ 2 are met to 1e-6 relative with all
/// four edge pairs (docs/in_plane.md).
pub const DEFAULT_SPLINES: usize = 60;
/// The fewest B-splines per field.
pub const MIN_SPLINES: usize = 6;
/// The most B-splines per field (bounds the eigenproblem).
pub const MAX_SPLINES: usize = 400;

/// An in-plane edge condition.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum InPlaneEdge {
    /// u = 0.
    Fixed,
    /// σ_rr = σ_rθ = 0 (natural).
    Free,
}

impl InPlaneEdge {
    /// `fixed` or `free`.
    pub fn name(self) -> &'static str {
        match self {
            InPlaneEdge::Fixed => "fixed",
            InPlaneEdge::Free => "free",
        }
    }
}

/// Which fields a family carries.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum InPlaneFamily {
    /// k = 0, u_θ = V(r) only.
    Torsional,
    /// k = 0, u_r = U(r) only.
    Radial,
    /// k ≥ 1: U and V coupled.
    Coupled,
}

impl InPlaneFamily {
    /// The families of k: torsional and radial for k = 0, coupled otherwise.
    pub fn of(k: u32) -> &'static [InPlaneFamily] {
        if k == 0 {
            &[InPlaneFamily::Torsional, InPlaneFamily::Radial]
        } else {
            &[InPlaneFamily::Coupled]
        }
    }

    /// `torsional`, `radial` or `coupled`.
    pub fn name(self) -> &'static str {
        match self {
            InPlaneFamily::Torsional => "torsional",
            InPlaneFamily::Radial => "radial",
            InPlaneFamily::Coupled => "coupled",
        }
    }

    /// The fields (0: U, 1: V) it carries.
    pub(crate) fn fields(self) -> &'static [usize] {
        match self {
            InPlaneFamily::Torsional => &[1],
            InPlaneFamily::Radial => &[0],
            InPlaneFamily::Coupled => &[0, 1],
        }
    }
}

/// The plate in plain numbers (SI units) with its in-plane edges.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct InPlanePlate {
    /// E, Pa.
    pub youngs_modulus: f64,
    /// ν.
    pub poisson_ratio: f64,
    /// ρ, kg/m³.
    pub density: f64,
    /// h, m.
    pub thickness: f64,
    /// r_i, m.
    pub inner_radius: f64,
    /// r_a, m.
    pub outer_radius: f64,
    /// The condition at r_i.
    pub inner_edge: InPlaneEdge,
    /// The condition at r_a.
    pub outer_edge: InPlaneEdge,
}

impl InPlanePlate {
    /// Every number finite and in range: E, ρ, h, r_i > 0, −1 < ν < 0.5,
    /// r_i < r_a.
    pub fn validate(&self) -> Result<(), InPlaneError> {
        let positive = [
            ("youngs_modulus", self.youngs_modulus),
            ("density", self.density),
            ("thickness", self.thickness),
            ("inner_radius", self.inner_radius),
        ];
        super::annulus::check_annulus(
            &positive,
            self.poisson_ratio,
            self.inner_radius,
            self.outer_radius,
        )
        .map_err(|(name, value, rule)| InPlaneError::invalid(name, value, rule))
    }

    /// Ē = E / (1 − ν²), Pa.
    pub fn membrane_modulus(&self) -> f64 {
        self.youngs_modulus / (1.0 - self.poisson_ratio * self.poisson_ratio)
    }

    /// G = E / (2 (1 + ν)), Pa.
    pub fn shear_modulus(&self) -> f64 {
        self.youngs_modulus / (2.0 * (1.0 + self.poisson_ratio))
    }

    /// Whether ⟨k, l⟩ of `family` is a rigid-body motion: a free–free
    /// annulus's rotation (k = 0 torsional) and translation (k = 1), l = 0.
    pub fn is_rigid_body(&self, k: u32, family: InPlaneFamily, l: u32) -> bool {
        self.inner_edge == InPlaneEdge::Free
            && self.outer_edge == InPlaneEdge::Free
            && l == 0
            && (family == InPlaneFamily::Torsional || k == 1)
    }
}

/// U, U', V, V' of an in-plane mode at one radius.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct InPlaneRadialValue {
    /// U, m (unit peak).
    pub u: f64,
    /// U'.
    pub u_r: f64,
    /// V, m.
    pub v: f64,
    /// V'.
    pub v_r: f64,
}

/// One in-plane mode ⟨k, l⟩ of a family: frequency, modal mass, U and V.
#[derive(Debug, Clone, PartialEq)]
pub struct InPlaneMode {
    /// Nodal diameters.
    pub k: u32,
    /// Index in ascending frequency for this k and family (rigid-body ones
    /// counted, then left out).
    pub l: u32,
    /// Torsional, radial (k = 0) or coupled (k ≥ 1).
    pub family: InPlaneFamily,
    /// ω, rad/s.
    pub omega: f64,
    /// ω/2π, Hz.
    pub frequency_hz: f64,
    /// c_k ∫ ρh (U² + V²) r dr for the unit-peak shape, kg.
    pub modal_mass: f64,
    /// The B-spline basis of U and V.
    pub basis: BSplineBasis,
    /// B-spline coefficients of U (zeros for the torsional family).
    pub u: Vec<f64>,
    /// B-spline coefficients of V (zeros for the radial family).
    pub v: Vec<f64>,
}

impl InPlaneMode {
    /// U, U', V, V' at r (clamped to [r_i, r_a]).
    pub fn eval(&self, r: f64) -> InPlaneRadialValue {
        let (a, b) = self.basis.interval();
        let r = r.clamp(a, b);
        let [u, u_r, ..] = self.basis.eval_combination(&self.u, r);
        let [v, v_r, ..] = self.basis.eval_combination(&self.v, r);
        InPlaneRadialValue { u, u_r, v, v_r }
    }
}

/// The in-plane modes ⟨k, l⟩ of `family`, l = 0 … `orders` − 1 (rigid-body
/// ones left out), on `splines` cubic B-splines per field, ascending in
/// frequency.
pub fn in_plane_modes(
    plate: &InPlanePlate,
    k: u32,
    family: InPlaneFamily,
    orders: usize,
    splines: usize,
) -> Result<Vec<InPlaneMode>, InPlaneError> {
    InPlaneDiscretisation::new(plate, splines)?.modes(k, family, orders)
}

impl InPlaneDiscretisation {
    /// The modes ⟨k, l⟩ of `family`, l = 0 … `orders` − 1, on this
    /// discretisation. `family` must be one of [`InPlaneFamily::of`]`(k)`.
    pub fn modes(
        &self,
        k: u32,
        family: InPlaneFamily,
        orders: usize,
    ) -> Result<Vec<InPlaneMode>, InPlaneError> {
        debug_assert!(InPlaneFamily::of(k).contains(&family));
        let n_free = self.n_free(family);
        if orders == 0 || orders > n_free / 2 {
            return Err(InPlaneError::Orders {
                orders,
                max: n_free / 2,
            });
        }
        let plate = self.plate();
        let (kk, mm) = self.assemble(k, family);
        // The squared frequency scale of a shear wave across the annulus.
        let width = plate.outer_radius - plate.inner_radius;
        let sigma = plate.shear_modulus() / (plate.density * width * width);
        let pairs = lowest_pairs(&kk, &mm, sigma, orders).map_err(|e| InPlaneError::Eigen {
            k,
            family: family.name(),
            reason: e.to_string(),
        })?;
        let mut out = Vec::with_capacity(orders);
        for l in 0..orders as u32 {
            if plate.is_rigid_body(k, family, l) {
                continue;
            }
            let w2 = pairs.omega_squared[l as usize];
            let col = pairs.vectors.col(l as usize);
            let [u, v] = self.expand(family, (0..col.nrows()).map(|i| col[i]));
            let peak = self.peak(&u, &v);
            if !(w2.is_finite() && w2 > 0.0 && peak.is_finite() && peak != 0.0) {
                return Err(InPlaneError::NonFiniteMode {
                    k,
                    l,
                    omega_squared: w2,
                });
            }
            let scale = |c: Vec<f64>| c.into_iter().map(|x| x / peak).collect();
            let omega = w2.sqrt();
            out.push(InPlaneMode {
                k,
                l,
                family,
                omega,
                frequency_hz: omega / std::f64::consts::TAU,
                modal_mass: 1.0 / (peak * peak),
                basis: self.basis().clone(),
                u: scale(u),
                v: scale(v),
            });
        }
        Ok(out)
    }

    /// The value of U or V largest in magnitude over [r_i, r_a] (U's when
    /// they tie), found as the bending shapes' peak is.
    fn peak(&self, u: &[f64], v: &[f64]) -> f64 {
        let shape = |c: &[f64]| RadialShape {
            k: 0,
            l: 0,
            omega: 0.0,
            basis: self.basis().clone(),
            coefficients: c.to_vec(),
        };
        let (_, pu) = shape(u).peak();
        let (_, pv) = shape(v).peak();
        if pv.abs() > pu.abs() {
            pv
        } else {
            pu
        }
    }
}
