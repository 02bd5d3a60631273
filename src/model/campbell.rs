//! The Campbell diagram of the spinning plate (docs/rotor_dynamics.md):
//! per retained ⟨k, l⟩ the rotating-frame frequency f(Ω), the space-fixed
//! forward and backward frequencies f ± kΩ/2π, and the critical speed where
//! the backward frequency reaches zero (ω(Ω) = kΩ).
//!
//! Without `plate.centrifugal_stiffening` f is the plate's own frequency at
//! every speed and the critical speed is ω/k; with it, f(Ω) comes from the
//! full radial spectrum with the prestress ([`SpinningSpectrum`]).
//!
//! With `plate.in_plane_nodal_diameters` the diagram also has the in-plane
//! waves and their critical speeds ([`in_plane_campbell`]).

use super::in_plane::{in_plane_campbell, InPlaneCampbellWave, InPlaneCriticalSpeed};
use super::modes::is_rigid_body;
use super::spinning::SpinningSpectrum;
use super::{ModelError, PlateModel};
use crate::config::CentrifugalConfig;
use serde::Serialize;
use std::f64::consts::TAU;

/// One ⟨k, l⟩ over the speeds, Hz. The backward frequency is signed: it
/// crosses zero at the critical speed and is negative beyond it (the
/// backward wave then travels forward in space).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct CampbellMode {
    /// Nodal diameters.
    pub k: u32,
    /// Nodal circles.
    pub l: u32,
    /// The frequency in the rotating frame at each speed, Hz.
    pub rotating_hz: Vec<f64>,
    /// The forward wave's frequency seen from space at each speed, Hz.
    pub forward_hz: Vec<f64>,
    /// The backward wave's frequency seen from space at each speed, Hz.
    pub backward_hz: Vec<f64>,
}

/// The critical speed of one ⟨k, l⟩ (k ≥ 1).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct CriticalSpeed {
    /// Nodal diameters.
    pub k: u32,
    /// Nodal circles.
    pub l: u32,
    /// The speed, rad/s.
    pub rad_s: f64,
}

/// The diagram: `modes` one per retained ⟨k, l⟩ (ascending k, then l),
/// `critical_speeds` one per ⟨k ≥ 1, l⟩ that has one; the in-plane waves
/// and critical speeds (left out of the JSON when there are none).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct CampbellDiagram {
    /// The speeds of the diagram, rad/s.
    pub speeds_rad_s: Vec<f64>,
    /// The modes' frequencies over the speeds.
    pub modes: Vec<CampbellMode>,
    /// The critical speeds.
    pub critical_speeds: Vec<CriticalSpeed>,
    /// The in-plane waves per k and order (empty without in-plane modes).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub in_plane: Vec<InPlaneCampbellWave>,
    /// The in-plane critical speeds inside the speed range (ascending k, then order).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub in_plane_critical_speeds: Vec<InPlaneCriticalSpeed>,
}

/// The retained ⟨k, l⟩ of `model`, ascending k then l, rigid-body motions left out.
fn retained(model: &PlateModel) -> Vec<(u32, u32, f64)> {
    let mut v: Vec<(u32, u32, f64)> = model
        .radial_shapes()
        .iter()
        .map(|s| (s.k, s.l, s.omega))
        .collect();
    v.sort_by_key(|&(k, l, _)| (k, l));
    v
}

/// The critical speeds of `model` (ω/k without stiffening), ascending k then l.
pub fn critical_speeds(
    model: &PlateModel,
    centrifugal: &CentrifugalConfig,
) -> Result<Vec<CriticalSpeed>, ModelError> {
    let mut out = Vec::new();
    let max_l = model
        .plate()
        .nodal_circles
        .iter()
        .copied()
        .max()
        .unwrap_or(0) as usize;
    let mut spectrum: Option<SpinningSpectrum> = None;
    for (k, l, omega) in retained(model) {
        if k == 0 {
            continue;
        }
        let rad_s = if centrifugal.stiffening {
            if spectrum.as_ref().is_none_or(|s| s.k() != k) {
                spectrum = Some(SpinningSpectrum::new(
                    model.plate(),
                    centrifugal,
                    k,
                    max_l + 1,
                ));
            }
            spectrum
                .as_ref()
                .expect("built above")
                .critical_speed(l as usize)?
        } else {
            Some(omega / k as f64)
        };
        if let Some(rad_s) = rad_s {
            out.push(CriticalSpeed { k, l, rad_s });
        }
    }
    Ok(out)
}

/// The diagram over ascending `speeds` (rad/s).
pub fn campbell(
    model: &PlateModel,
    centrifugal: &CentrifugalConfig,
    speeds: &[f64],
) -> Result<CampbellDiagram, ModelError> {
    let plate = model.plate();
    let max_l = plate.nodal_circles.iter().copied().max().unwrap_or(0) as usize;
    let mut modes = Vec::new();
    let mut spectrum: Option<(u32, Vec<Vec<f64>>)> = None;
    for (k, l, omega) in retained(model) {
        debug_assert!(!is_rigid_body(
            plate.inner_boundary,
            plate.outer_boundary,
            k,
            l
        ));
        let rotating: Vec<f64> = if centrifugal.stiffening {
            if spectrum.as_ref().is_none_or(|(sk, _)| *sk != k) {
                let s = SpinningSpectrum::new(plate, centrifugal, k, max_l + 1);
                let per_speed = speeds
                    .iter()
                    .map(|&w| s.omega_squared(w))
                    .collect::<Result<Vec<_>, _>>()?;
                spectrum = Some((k, per_speed));
            }
            let (_, per_speed) = spectrum.as_ref().expect("built above");
            per_speed
                .iter()
                .map(|w2| w2[l as usize].max(0.0).sqrt() / TAU)
                .collect()
        } else {
            vec![omega / TAU; speeds.len()]
        };
        let shift = |w: f64| k as f64 * w / TAU;
        modes.push(CampbellMode {
            k,
            l,
            forward_hz: rotating
                .iter()
                .zip(speeds)
                .map(|(f, &w)| f + shift(w))
                .collect(),
            backward_hz: rotating
                .iter()
                .zip(speeds)
                .map(|(f, &w)| f - shift(w))
                .collect(),
            rotating_hz: rotating,
        });
    }
    let in_plane = in_plane_campbell(plate, centrifugal, speeds)?;
    Ok(CampbellDiagram {
        speeds_rad_s: speeds.to_vec(),
        modes,
        critical_speeds: critical_speeds(model, centrifugal)?,
        in_plane: in_plane.waves,
        in_plane_critical_speeds: in_plane.critical_speeds,
    })
}
