//! The modal equations of motion in either description, for the integrators
//! that work on the ODE itself (implicit midpoint, RK4).
//!
//! Lagrangian, per mode (eq. 12 plus the reference-motion terms of eq. 11):
//!   m (q̈ + 2ζω q̇ + ω_eff² q) = f_B + [R(kχ)ᵀ f̄]
//! ALE, per pair, from q = Rᵀ(kχ) q̄ (docs/ale.md):
//!   q̄̈ = f̄_tot/m + 2kΩ J q̄̇ + kΩ̇ J q̄ + k²Ω² q̄ − 2ζω (q̄̇ − kΩ J q̄) − ω_eff² q̄
//! (gyroscopic 2kΩ, softening k²Ω², circulatory 2ζωkΩ and the kΩ̇ term),
//! with f̄_tot = f̄ + R(kχ) f_B and J = [[0, −1], [1, 0]].

use crate::config::Coordinates;
use crate::dynamics::loads::StepLoads;
use crate::dynamics::scene::{ModePair, Scene};

/// The modal equations of motion of a scene: its modes, their constants and
/// the description (Lagrangian or ALE) the amplitudes are in.
#[derive(Debug, Clone, Copy)]
pub struct ModalEquations<'a> {
    pub scene: &'a Scene,
    pub consts: &'a [ModeConstants],
    pub coords: Coordinates,
}

/// The floating frame's reference motion at one instant: the harmonics
/// (cos kχ, sin kχ) of the joint angle χ for every k, the joint speed Ω and
/// its acceleration α = Ω̇.
#[derive(Debug, Clone, Copy)]
pub struct ReferenceMotion<'a> {
    pub harmonics: &'a [(f64, f64)],
    pub speed: f64,
    pub accel: f64,
}

/// Per-mode constants.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ModeConstants {
    pub mass: f64,
    /// 2ζω.
    pub damping_rate: f64,
    /// ω² − (ω_x² + ω_y²).
    pub omega_eff_sq: f64,
}

pub fn mode_constants(scene: &Scene) -> Vec<ModeConstants> {
    let soft = scene.off_axis_rate_squared();
    scene
        .elastic_modes()
        .map(|(_, mass, damping, omega)| ModeConstants {
            mass,
            damping_rate: 2.0 * damping * omega,
            omega_eff_sq: omega * omega - soft,
        })
        .collect()
}

/// A pair's total force (cos, sin) resolved in `coords`, at the instant whose
/// (cos kχ, sin kχ) is `harm_k`: Lagrangian f = f_B + Rᵀ f̄, ALE f̄ + R f_B.
#[inline]
pub fn pair_force(
    coords: Coordinates,
    harm_k: (f64, f64),
    p: &ModePair,
    ale_frame: &[f64],
    plate_frame: &[f64],
) -> (f64, f64) {
    let (co, si) = harm_k;
    let (ic, is) = (p.cos, p.sin);
    match coords {
        Coordinates::Lagrangian => (
            plate_frame[ic] + co * ale_frame[ic] + si * ale_frame[is],
            plate_frame[is] - si * ale_frame[ic] + co * ale_frame[is],
        ),
        Coordinates::Ale => (
            ale_frame[ic] + co * plate_frame[ic] - si * plate_frame[is],
            ale_frame[is] + si * plate_frame[ic] + co * plate_frame[is],
        ),
    }
}

/// Accelerations for amplitudes (q, v) in the equations' description, at the
/// reference motion of the instant, under the loads split by frame. Writes q̈
/// into `acc`.
pub fn accelerations(
    equations: ModalEquations<'_>,
    motion: ReferenceMotion<'_>,
    loads: &StepLoads,
    q: &[f64],
    v: &[f64],
    acc: &mut [f64],
) {
    let ModalEquations {
        scene,
        consts,
        coords,
    } = equations;
    let ReferenceMotion {
        harmonics: harm,
        speed,
        accel,
    } = motion;
    let (ale_frame, plate_frame) = (&loads.ale_frame[..], &loads.plate_frame[..]);
    let lay = &scene.layout;
    for &i in &lay.axisymmetric {
        let c = consts[i];
        acc[i] = ale_frame[i] / c.mass - c.damping_rate * v[i] - c.omega_eff_sq * q[i];
    }
    for p in &lay.pairs {
        let (fc, fs) = pair_force(coords, harm[p.k as usize], p, ale_frame, plate_frame);
        let (ic, is) = (p.cos, p.sin);
        let c = consts[ic];
        match coords {
            Coordinates::Lagrangian => {
                acc[ic] = fc / c.mass - c.damping_rate * v[ic] - c.omega_eff_sq * q[ic];
                acc[is] = fs / c.mass - c.damping_rate * v[is] - c.omega_eff_sq * q[is];
            }
            Coordinates::Ale => {
                let kw = p.k as f64 * speed;
                let ka = p.k as f64 * accel;
                let stiff = kw * kw - c.omega_eff_sq;
                let skew = ka + c.damping_rate * kw; // coefficient of J q̄
                                                     // J x = (−x_s, x_c)
                acc[ic] = fc / c.mass + 2.0 * kw * (-v[is]) + skew * (-q[is]) + stiff * q[ic]
                    - c.damping_rate * v[ic];
                acc[is] = fs / c.mass + 2.0 * kw * v[ic] + skew * q[ic] + stiff * q[is]
                    - c.damping_rate * v[is];
            }
        }
    }
    // Centrifugal stiffening: −Ω² M⁻¹ G_k q in either description (it commutes with R(kχ)).
    if let Some(s) = &scene.stiffening {
        s.subtract_accelerations(speed * speed, q, acc);
    }
    // In-plane modes: −M⁻¹ (Ω G q̇ + Ω² K_Ω q), q̇ the Lagrangian velocity in `coords`' axes.
    if let Some(ip) = &scene.in_plane {
        ip.spin.subtract_accelerations(coords, speed, q, v, acc);
    }
}
