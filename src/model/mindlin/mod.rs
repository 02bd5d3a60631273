//! Mindlin (first-order shear deformation) modes of the annular plate: the
//! thick-plate counterpart of the Kirchhoff radial problem (paper eq. (4),
//! section 3.1), by the same radial B-spline Ritz machinery. With
//! `plate.theory: mindlin` they are the model's modes (docs/mindlin.md).
//!
//! # Fields and kinematics
//!
//! Polar coordinates (r, θ) of the plate's mid-plane; θ is the material
//! angle φ of the paper's eq. (3) and of the Kirchhoff modes (w = R cos kφ).
//! Transverse deflection w and the rotations ψ_r, ψ_θ of the normal (face
//! displacement u_r = z ψ_r, u_θ = z ψ_θ; the Kirchhoff limit is
//! ψ_r = −∂w/∂r, ψ_θ = −(1/r) ∂w/∂θ). Curvatures and shear strains:
//!
//! κ_r = ∂ψ_r/∂r,  κ_θ = (ψ_r + ∂ψ_θ/∂θ)/r,  κ_rθ = ∂ψ_θ/∂r − ψ_θ/r + (1/r) ∂ψ_r/∂θ,
//! γ_r = ψ_r + ∂w/∂r,  γ_θ = ψ_θ + (1/r) ∂w/∂θ;
//!
//! moments and shear forces M_r = D (κ_r + ν κ_θ), M_θ = D (κ_θ + ν κ_r),
//! M_rθ = D (1 − ν)/2 κ_rθ, Q_r = κ G h γ_r, Q_θ = κ G h γ_θ with D of
//! eq. (2), G = E / (2 (1 + ν)) and the shear correction κ (default 5/6).
//!
//! # Harmonic k and the weak form
//!
//! Per nodal-diameter number k the cos partner is
//! w = W(r) cos kθ, ψ_r = Ψ_r(r) cos kθ, ψ_θ = Ψ_θ(r) sin kθ (the sin partner
//! w = W sin kθ, ψ_r = Ψ_r sin kθ, ψ_θ = −Ψ_θ cos kθ; in both
//! ψ_θ = −Ψ_θ Θ'(θ)/k with Θ the [`AngularShape`] of w).
//! For k = 0 the ψ_θ family decouples (axisymmetric thickness-twist, no
//! deflection) and is left out. With c_k = 2π (k = 0), π (k ≥ 1) as for the
//! Kirchhoff modes the energies are
//!
//! U = c_k/2 ∫ [ D (e_r² + e_θ² + 2ν e_r e_θ + (1 − ν)/2 e_rθ²) + κGh (Γ_r² + Γ_θ²) ] r dr,
//! T = c_k/2 ∫ [ ρh Ẇ² + ρh³/12 (Ψ̇_r² + Ψ̇_θ²) ] r dr,
//!
//! e_r = Ψ_r',  e_θ = (Ψ_r + k Ψ_θ)/r,  e_rθ = Ψ_θ' − (Ψ_θ + k Ψ_r)/r,
//! Γ_r = Ψ_r + W',  Γ_θ = Ψ_θ − k W/r,
//!
//! and the modes are the stationary points of U − ω² T: the weak form
//! a(u, v) = ω² m(u, v) for all admissible v, with a, m the bilinear forms of
//! U and T. Essential conditions per edge: clamped W = Ψ_r = Ψ_θ = 0;
//! supported (hard) W = Ψ_θ = 0; supported_soft W = 0; free none. The
//! remaining Q_r = M_r = M_rθ = 0 are natural (they follow from the weak form).
//!
//! # Discretisation (locking-free)
//!
//! The unknowns are W and the shear strains Γ_r, Γ_θ, each a sum of the same
//! cubic B-splines N_j (`bspline`), with Ψ_r = −W' + Γ_r, Ψ_θ = k W/r + Γ_θ
//! (the hierarchic Reissner–Mindlin form). The Kirchhoff modes (Γ = 0) are
//! in the space exactly, so the shear stiffness κGh ∝ h cannot lock the
//! bending modes of a thin plate; the bending strains become
//! e_r = −W'' + Γ_r', e_θ = (−W' + k² W/r + Γ_r + k Γ_θ)/r,
//! e_rθ = 2k (W'/r − W/r²) + Γ_θ' − (Γ_θ + k Γ_r)/r — with Γ = 0 exactly
//! the Kirchhoff energy of `radial`. Essential conditions: W = 0 drops W's
//! edge B-spline; Ψ_θ = 0 (with W = 0) drops Γ_θ's; Ψ_r = 0 ties Γ_r's edge
//! coefficient to W' there (Γ_r = W' at a clamped edge), one constraint
//! eliminated into the basis (`assembly`).
//!
//! # Normalisation
//!
//! As for the Kirchhoff modes ([`super::Mode`]): max |W| = 1 over
//! [r_i, r_a], positive at the peak, so a modal amplitude is the peak
//! deflection in metres; the modal mass is
//! c_k ∫ [ρh W² + ρh³/12 (Ψ_r² + Ψ_θ²)] r dr (rotary inertia included).

mod assembly;
mod error;
mod model;
mod residual;
mod warning;

pub use assembly::MindlinDiscretisation;
pub use error::MindlinError;
pub(crate) use model::build_model;
pub use model::{mindlin_edge, mindlin_plate};
pub use residual::{patch_harmonics, LoadPatch, PatchHarmonics};
pub use warning::{ThicknessError, CHECKED_PAIRS, THICKNESS_WARNING_LEVEL};

use super::bspline::BSplineBasis;
use super::modes::{AngularShape, RadialShape};
use super::resolution::lowest_pairs;

/// The shear correction factor κ used unless another is given (Mindlin's
/// π²/12 is the alternative).
pub const DEFAULT_SHEAR_CORRECTION: f64 = 5.0 / 6.0;
/// Cubic B-splines per field by default: the exact Mindlin frequencies of
/// k ≤ 10, l ≤ 3 are met to 1e-6 relative (docs/mindlin.md).
pub const DEFAULT_SPLINES: usize = 120;
/// The fewest B-splines per field.
pub const MIN_SPLINES: usize = 6;
/// The most B-splines per field (bounds the dense eigenproblem).
pub const MAX_SPLINES: usize = 400;

/// An edge condition of the Mindlin plate.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum MindlinEdge {
    /// No essential condition: Q_r = M_r = M_rθ = 0 naturally.
    Free,
    /// w = 0; M_r = M_rθ = 0 naturally.
    SupportedSoft,
    /// Hard support w = ψ_θ = 0; M_r = 0 naturally (Kirchhoff's `supported`).
    Supported,
    /// w = ψ_r = ψ_θ = 0.
    Clamped,
}

impl MindlinEdge {
    /// Every edge condition.
    pub const ALL: [MindlinEdge; 4] = [
        MindlinEdge::Free,
        MindlinEdge::SupportedSoft,
        MindlinEdge::Supported,
        MindlinEdge::Clamped,
    ];

    /// `free`, `supported_soft`, `supported` or `clamped`.
    pub fn name(self) -> &'static str {
        match self {
            MindlinEdge::Free => "free",
            MindlinEdge::SupportedSoft => "supported_soft",
            MindlinEdge::Supported => "supported",
            MindlinEdge::Clamped => "clamped",
        }
    }
}

/// The Mindlin plate in plain numbers (SI units).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MindlinPlate {
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
    /// κ ([`DEFAULT_SHEAR_CORRECTION`]).
    pub shear_correction: f64,
    /// The condition at r_i.
    pub inner_edge: MindlinEdge,
    /// The condition at r_a.
    pub outer_edge: MindlinEdge,
}

impl MindlinPlate {
    /// Every number finite and in range: E, ρ, h, κ > 0, −1 < ν < 0.5,
    /// 0 < r_i < r_a.
    pub fn validate(&self) -> Result<(), MindlinError> {
        let positive = [
            ("youngs_modulus", self.youngs_modulus),
            ("density", self.density),
            ("thickness", self.thickness),
            ("shear_correction", self.shear_correction),
            ("inner_radius", self.inner_radius),
        ];
        super::annulus::check_annulus(
            &positive,
            self.poisson_ratio,
            self.inner_radius,
            self.outer_radius,
        )
        .map_err(|(name, value, rule)| MindlinError::invalid(name, value, rule))
    }

    /// The shift σ of the shift-invert eigensolves, D / (ρh b² r_a²) with
    /// b = r_a − r_i (rad²/s²).
    pub fn eigen_shift(&self) -> f64 {
        let width = self.outer_radius - self.inner_radius;
        self.rigidity()
            / (self.density * self.thickness * width * width * self.outer_radius.powi(2))
    }

    /// D = E h³ / (12 (1 − ν²)), eq. (2).
    pub fn rigidity(&self) -> f64 {
        super::bending_rigidity(self.youngs_modulus, self.thickness, self.poisson_ratio)
    }

    /// G = E / (2 (1 + ν)).
    pub fn shear_modulus(&self) -> f64 {
        self.youngs_modulus / (2.0 * (1.0 + self.poisson_ratio))
    }

    /// κ G h, N/m.
    pub fn shear_stiffness(&self) -> f64 {
        self.shear_correction * self.shear_modulus() * self.thickness
    }

    /// ρh³/12, the rotary inertia per unit area, kg.
    pub fn rotary_inertia(&self) -> f64 {
        self.density * self.thickness.powi(3) / 12.0
    }

    /// Whether ⟨k, l⟩ is a rigid-body motion: a free–free plate's translation
    /// ⟨0, 0⟩ and tilt ⟨1, 0⟩ (left out as for the Kirchhoff modes).
    pub fn is_rigid_body(&self, k: u32, l: u32) -> bool {
        self.inner_edge == MindlinEdge::Free
            && self.outer_edge == MindlinEdge::Free
            && l == 0
            && k <= 1
    }
}

/// The radial fields of a Mindlin mode at one radius.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct MindlinRadialValue {
    /// W, m (unit peak).
    pub w: f64,
    /// W'.
    pub w_r: f64,
    /// Ψ_r = −W' + Γ_r.
    pub psi_r: f64,
    /// Ψ_θ = k W/r + Γ_θ.
    pub psi_theta: f64,
    /// Γ_r, the transverse shear strain γ_r.
    pub gamma_r: f64,
    /// Γ_θ, the transverse shear strain γ_θ.
    pub gamma_theta: f64,
}

/// The fields of a Mindlin mode at one point (r, φ).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct MindlinFieldValue {
    /// w, m.
    pub w: f64,
    /// ψ_r.
    pub psi_r: f64,
    /// ψ_θ.
    pub psi_theta: f64,
}

/// One Mindlin mode ⟨k, l⟩: its frequency, modal mass and radial fields.
#[derive(Debug, Clone, PartialEq)]
pub struct MindlinMode {
    /// Nodal diameters.
    pub k: u32,
    /// Index of the radial eigenfunction for this k in ascending frequency.
    pub l: u32,
    /// ω, rad/s.
    pub omega: f64,
    /// ω/2π, Hz.
    pub frequency_hz: f64,
    /// c_k ∫ [ρh W² + ρh³/12 (Ψ_r² + Ψ_θ²)] r dr for the unit-peak W, kg.
    pub modal_mass: f64,
    /// W as the Kirchhoff code's radial shape (same basis type and normalisation).
    pub w: RadialShape,
    /// B-spline coefficients of Γ_r (on `w`'s basis).
    pub gamma_r: Vec<f64>,
    /// B-spline coefficients of Γ_θ (on `w`'s basis; zeros for k = 0).
    pub gamma_theta: Vec<f64>,
}

impl MindlinMode {
    /// W, W', Ψ_r, Ψ_θ, Γ_r, Γ_θ at r (clamped to [r_i, r_a]).
    pub fn eval(&self, r: f64) -> MindlinRadialValue {
        let basis: &BSplineBasis = self.w.basis();
        let (a, b) = basis.interval();
        let r = r.clamp(a, b);
        let [w, w_r, ..] = self.w.eval(r);
        let gamma_r = basis.eval_combination(&self.gamma_r, r)[0];
        let gamma_theta = basis.eval_combination(&self.gamma_theta, r)[0];
        MindlinRadialValue {
            w,
            w_r,
            psi_r: -w_r + gamma_r,
            psi_theta: self.k as f64 * w / r + gamma_theta,
            gamma_r,
            gamma_theta,
        }
    }

    /// w, ψ_r, ψ_θ at (r, φ) for the angular factor `shape` of w (`Cos` or
    /// `Sin` for k ≥ 1, `Axisymmetric` for k = 0).
    pub fn field(&self, shape: AngularShape, r: f64, phi: f64) -> MindlinFieldValue {
        let v = self.eval(r);
        let (t, dt) = shape.eval(self.k, phi);
        let theta_factor = if self.k == 0 {
            0.0
        } else {
            -dt / self.k as f64
        };
        MindlinFieldValue {
            w: v.w * t,
            psi_r: v.psi_r * t,
            psi_theta: v.psi_theta * theta_factor,
        }
    }
}

/// The Mindlin modes ⟨k, l⟩, l = 0 … `orders` − 1 (rigid-body ones left
/// out), on `splines` cubic B-splines per field, ascending in frequency.
pub fn mindlin_modes(
    plate: &MindlinPlate,
    k: u32,
    orders: usize,
    splines: usize,
) -> Result<Vec<MindlinMode>, MindlinError> {
    let disc = MindlinDiscretisation::new(plate, splines)?;
    disc.modes(k, orders)
}

impl MindlinDiscretisation {
    /// The modes ⟨k, l⟩, l = 0 … `orders` − 1, on this discretisation.
    pub fn modes(&self, k: u32, orders: usize) -> Result<Vec<MindlinMode>, MindlinError> {
        let n_free = self.n_free(k);
        if orders == 0 || orders > n_free / 2 {
            return Err(MindlinError::Orders {
                orders,
                max: n_free / 2,
            });
        }
        let plate = self.plate();
        let (kk, mm) = self.assemble(k);
        let pairs = lowest_pairs(&kk, &mm, plate.eigen_shift(), orders).map_err(|e| {
            MindlinError::Eigen {
                k,
                reason: e.to_string(),
            }
        })?;
        let mut out = Vec::with_capacity(orders);
        for l in 0..orders as u32 {
            if plate.is_rigid_body(k, l) {
                continue;
            }
            let w2 = pairs.omega_squared[l as usize];
            let col = pairs.vectors.col(l as usize);
            let [w, gamma_r, gamma_theta] = self.expand(k, (0..col.nrows()).map(|i| col[i]));
            let mut shape = RadialShape {
                k,
                l,
                omega: w2.max(0.0).sqrt(),
                basis: self.basis().clone(),
                coefficients: w,
            };
            let (_, peak) = shape.peak();
            if !(w2.is_finite() && w2 > 0.0 && peak.is_finite() && peak != 0.0) {
                return Err(MindlinError::NonFiniteMode {
                    k,
                    l,
                    omega_squared: w2,
                });
            }
            shape.coefficients.iter_mut().for_each(|c| *c /= peak);
            let scale = |v: Vec<f64>| v.into_iter().map(|c| c / peak).collect();
            let omega = w2.sqrt();
            out.push(MindlinMode {
                k,
                l,
                omega,
                frequency_hz: omega / std::f64::consts::TAU,
                modal_mass: 1.0 / (peak * peak),
                w: shape,
                gamma_r: scale(gamma_r),
                gamma_theta: scale(gamma_theta),
            });
        }
        Ok(out)
    }
}
