//! The squeal stability map: the linearised system of
//! [`super::stability`] over friction coefficient × speed — per grid point
//! the largest growth rate, the unstable mode's ⟨k, l⟩ and frequency — and
//! the threshold μ_c(Ω) per speed. Grid points run in parallel over the
//! machine's cores (`std::thread::scope`); a map can be computed in shards
//! of whole speed rows and merged (docs/rotor_dynamics.md).

use super::scene::Scene;
use super::stability::{configured, critical_mode, growth_rate};
use serde::{Deserialize, Serialize};
use std::f64::consts::TAU;

/// The least stable eigenvalue at one grid point.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct GridPoint {
    /// max Re λ, 1/s.
    pub growth_rate: f64,
    /// The mode with the largest amplitude in its eigenvector (peak
    /// displacement): its nodal diameters,
    pub k: u32,
    /// and its nodal circles (its order l for an in-plane mode),
    pub l: u32,
    /// whether it is an in-plane mode (`plate.in_plane_nodal_diameters`).
    pub in_plane: bool,
    /// |Im λ| / 2π, Hz (space-fixed frame: ALE coordinates).
    pub frequency_hz: f64,
}

/// One speed row: a grid point per μ and the threshold.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct SpeedRow {
    /// The joint speed Ω, rad/s.
    pub speed: f64,
    /// One point per friction coefficient μ of the grid.
    pub points: Vec<GridPoint>,
    /// The smallest μ in [μ_first, μ_last] where max Re λ > 0: the first grid
    /// μ with a positive rate, bisected against its stable neighbour to 1e-9
    /// relative (μ_first itself if already unstable there); `None` if none.
    pub threshold_mu: Option<f64>,
}

fn point(scene: &Scene, speed: f64, mu: f64, clamp: &[f64]) -> GridPoint {
    let mode = critical_mode(scene, speed, mu, clamp);
    let n = scene.n_modes();
    let dominant = (0..n)
        .max_by(|&a, &b| mode.vector[a].norm().total_cmp(&mode.vector[b].norm()))
        .unwrap_or(0);
    let bending = scene.model.modes();
    let (k, l, in_plane) = match (bending.get(dominant), &scene.in_plane) {
        (Some(m), _) => (m.k, m.l, false),
        (None, Some(ip)) => {
            let m = &ip.modes[dominant - ip.offset];
            (m.k, m.l, true)
        }
        (None, None) => unreachable!("a dominant index among the scene's modes"),
    };
    GridPoint {
        growth_rate: growth_rate(scene, speed, mu, clamp),
        k,
        l,
        in_plane,
        frequency_hz: mode.eigenvalue.im.abs() / TAU,
    }
}

fn threshold(
    scene: &Scene,
    speed: f64,
    mus: &[f64],
    points: &[GridPoint],
    clamp: &[f64],
) -> Option<f64> {
    let first = points.iter().position(|p| p.growth_rate > 0.0)?;
    if first == 0 {
        return Some(mus[0]);
    }
    let (mut lo, mut hi) = (mus[first - 1], mus[first]);
    while hi - lo > 1e-9 * hi {
        let mid = 0.5 * (lo + hi);
        if growth_rate(scene, speed, mid, clamp) > 0.0 {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    Some(0.5 * (lo + hi))
}

/// The rows of `speeds` × `mus`, grid points spread over `threads` threads.
pub fn stability_map(scene: &Scene, speeds: &[f64], mus: &[f64], threads: usize) -> Vec<SpeedRow> {
    let (_, clamp) = configured(scene); // the linearisation's preload
    let n = speeds.len() * mus.len();
    let threads = threads.clamp(1, n.max(1));
    let next = std::sync::atomic::AtomicUsize::new(0);
    let mut results: Vec<Option<GridPoint>> = vec![None; n];
    std::thread::scope(|s| {
        let workers: Vec<_> = (0..threads)
            .map(|_| {
                s.spawn(|| {
                    let mut mine = Vec::new();
                    loop {
                        let i = next.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
                        if i >= n {
                            break mine;
                        }
                        mine.push((
                            i,
                            point(scene, speeds[i / mus.len()], mus[i % mus.len()], &clamp),
                        ));
                    }
                })
            })
            .collect();
        for w in workers {
            for (i, p) in w.join().expect("a stability worker panicked") {
                results[i] = Some(p);
            }
        }
    });
    speeds
        .iter()
        .enumerate()
        .map(|(r, &speed)| {
            let points: Vec<GridPoint> = results[r * mus.len()..(r + 1) * mus.len()]
                .iter()
                .map(|p| p.expect("every point computed"))
                .collect();
            let threshold_mu = threshold(scene, speed, mus, &points, &clamp);
            SpeedRow {
                speed,
                points,
                threshold_mu,
            }
        })
        .collect()
}

/// The speed rows of shard `index` (0-based) of `count`: a contiguous block,
/// the first `len % count` shards one row longer.
pub fn shard_rows(len: usize, index: usize, count: usize) -> std::ops::Range<usize> {
    let (base, extra) = (len / count, len % count);
    let start = index * base + index.min(extra);
    start..start + base + usize::from(index < extra)
}
