//! The in-plane part of the Campbell diagram (docs/in_plane.md, "Campbell
//! diagram"): per k of `plate.in_plane_nodal_diameters` the lowest forward
//! and backward waves of the spinning disc over the speeds
//! ([`InPlaneSpectrum::waves`], eq. (S5) of [`super::spectrum`]), seen in the
//! turning frame and from space, and the critical speeds where a backward
//! wave stands still in space.
//!
//! Per k the diagram follows the n lowest waves of each direction, n the
//! number of in-plane modes of that k with l ≤ the largest of
//! `plate.in_plane_orders` (k = 0: torsional and radial together, which the
//! Coriolis force couples at speed; rigid-body motions left out). Wave
//! `order` i is the i-th lowest at each speed. The spin terms (Coriolis,
//! centrifugal softening, the Lamé prestress with the in-plane edges) are
//! always in: they are the in-plane physics of the spinning disc, whatever
//! `plate.centrifugal_stiffening` says of the bending modes.
//!
//! Seen from space the forward wave has |ω| + kΩ, the backward one ω − kΩ
//! (signed: negative beyond its critical speed). A critical speed is the Ω
//! where ω(Ω) = kΩ: found between two speeds of the diagram whose backward
//! space-fixed frequencies change sign, then bisected to 1e-12 relative.

use super::{in_plane_plate, InPlaneDiscretisation, InPlaneError, InPlaneFamily, InPlaneSpectrum};
use crate::config::{CentrifugalConfig, PlateConfig, RadialSplines};
use crate::model::prestress::LamePrestress;
use serde::Serialize;
use std::f64::consts::TAU;

/// One in-plane wave order of one k over the speeds, Hz.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct InPlaneCampbellWave {
    /// Nodal diameters.
    pub k: u32,
    /// The wave's rank in ascending frequency at each speed, from 0.
    pub order: u32,
    /// |ω| of the forward wave in the turning frame at each speed, Hz.
    pub rotating_forward_hz: Vec<f64>,
    /// ω of the backward wave in the turning frame at each speed, Hz.
    pub rotating_backward_hz: Vec<f64>,
    /// The forward wave seen from space, (|ω| + kΩ)/2π, Hz.
    pub forward_hz: Vec<f64>,
    /// The backward wave seen from space, (ω − kΩ)/2π (signed), Hz.
    pub backward_hz: Vec<f64>,
}

/// Where the backward wave `order` of k stands still in space.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct InPlaneCriticalSpeed {
    /// Nodal diameters (≥ 1).
    pub k: u32,
    /// The wave's rank, as in [`InPlaneCampbellWave::order`].
    pub order: u32,
    /// The speed, rad/s.
    pub rad_s: f64,
}

/// The in-plane waves and critical speeds over `speeds` (rad/s), ascending k then order.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct InPlaneCampbell {
    /// The waves.
    pub waves: Vec<InPlaneCampbellWave>,
    /// The critical speeds inside the speed range (none when no backward wave reaches 0).
    pub critical_speeds: Vec<InPlaneCriticalSpeed>,
}

/// Bisection steps for a critical speed: halves the bracket to 1e-12 of it and stops.
const BISECTIONS: usize = 60;

/// The in-plane Campbell diagram of `plate` (empty without
/// `plate.in_plane_nodal_diameters`) over ascending `speeds`.
pub fn in_plane_campbell(
    plate: &PlateConfig,
    centrifugal: &CentrifugalConfig,
    speeds: &[f64],
) -> Result<InPlaneCampbell, InPlaneError> {
    let mut out = InPlaneCampbell::default();
    if plate.in_plane_nodal_diameters.is_empty() {
        return Ok(out);
    }
    let ip = in_plane_plate(plate, centrifugal);
    let splines = match plate.radial_splines {
        RadialSplines::Auto => super::DEFAULT_SPLINES,
        RadialSplines::Fixed(n) => n,
    };
    let disc = InPlaneDiscretisation::new(&ip, splines)?;
    let prestress = LamePrestress::new(plate, centrifugal);
    let orders = plate.in_plane_orders.iter().max().map_or(1, |&l| l + 1);
    let mut ks = plate.in_plane_nodal_diameters.clone();
    ks.sort_unstable();
    for k in ks {
        let count: usize = InPlaneFamily::of(k)
            .iter()
            .map(|&f| (0..orders).filter(|&l| !ip.is_rigid_body(k, f, l)).count())
            .sum();
        let spectrum = disc.spectrum(k, &prestress);
        let per_speed = speeds
            .iter()
            .map(|&w| spectrum.waves(w, count))
            .collect::<Result<Vec<_>, _>>()?;
        let shift = |w: f64| k as f64 * w;
        for i in 0..count {
            let fwd: Vec<f64> = per_speed.iter().map(|s| s.forward[i]).collect();
            let bwd: Vec<f64> = per_speed.iter().map(|s| s.backward[i]).collect();
            let standing = |j: usize| bwd[j] - shift(speeds[j]);
            if k >= 1 {
                let crossing = (0..speeds.len()).find(|&j| {
                    standing(j) == 0.0 || (j > 0 && standing(j - 1) > 0.0 && standing(j) < 0.0)
                });
                if let Some(j) = crossing {
                    let rad_s = if standing(j) == 0.0 {
                        speeds[j]
                    } else {
                        bisect(&spectrum, i, count, speeds[j - 1], speeds[j])?
                    };
                    out.critical_speeds.push(InPlaneCriticalSpeed {
                        k,
                        order: i as u32,
                        rad_s,
                    });
                }
            }
            out.waves.push(InPlaneCampbellWave {
                k,
                order: i as u32,
                forward_hz: fwd
                    .iter()
                    .zip(speeds)
                    .map(|(f, &w)| (f + shift(w)) / TAU)
                    .collect(),
                backward_hz: (0..speeds.len()).map(|j| standing(j) / TAU).collect(),
                rotating_forward_hz: fwd.iter().map(|f| f / TAU).collect(),
                rotating_backward_hz: bwd.iter().map(|f| f / TAU).collect(),
            });
        }
    }
    Ok(out)
}

/// The Ω in [low, high] where backward wave `order` (of `count`) has ω = kΩ,
/// given ω > kΩ at `low` and ω < kΩ at `high`.
fn bisect(
    spectrum: &InPlaneSpectrum,
    order: usize,
    count: usize,
    mut low: f64,
    mut high: f64,
) -> Result<f64, InPlaneError> {
    let k = spectrum.k() as f64;
    for _ in 0..BISECTIONS {
        if high - low <= 1e-12 * high {
            break;
        }
        let mid = 0.5 * (low + high);
        if spectrum.waves(mid, count)?.backward[order] > k * mid {
            low = mid;
        } else {
            high = mid;
        }
    }
    Ok(0.5 * (low + high))
}
