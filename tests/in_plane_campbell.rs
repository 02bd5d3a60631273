//! `campbell` with in-plane modes (docs/in_plane.md, "Campbell diagram"):
//! the in-plane forward and backward waves over the speeds against the
//! independent Chebyshev collocation of the strong form
//! (`tests/support/in_plane_spinning_exact.rs`) at two speeds, the
//! space-fixed frequencies |ω| + kΩ and ω − kΩ, a critical speed against a
//! bisection of the collocation's ω(Ω) = kΩ, none when no backward wave
//! reaches zero inside the range, and the CLI's JSON and table.

mod support;

use annular_plate::config::{Boundary, CentrifugalConfig, PlateConfig};
use annular_plate::model::campbell::campbell;
use annular_plate::model::PlateModel;
use std::f64::consts::TAU;
use support::in_plane_spinning_exact::{roots, SpinningAnnulus};
use support::lame::Lame;

const BENCH: &str = "config/brake_bench.yaml";
const TOLERANCE: f64 = 1e-6;

/// The bench disc's steel and radii, hub clamped (in-plane fixed), rim free,
/// one bending mode and the in-plane modes `k` × l = 0, 1.
fn disc(k: &[u32]) -> (PlateConfig, CentrifugalConfig) {
    let mut plate = PlateConfig::lathe_disc();
    (plate.youngs_modulus, plate.poisson_ratio, plate.density) = (2.1e11, 0.3, 7850.0);
    (plate.thickness, plate.inner_radius, plate.outer_radius) = (0.0181, 0.07, 0.153);
    (plate.inner_boundary, plate.outer_boundary) = (Boundary::Clamped, Boundary::Free);
    plate.nodal_diameters = vec![2];
    plate.nodal_circles = vec![0];
    plate.in_plane_nodal_diameters = k.to_vec();
    plate.in_plane_orders = vec![0, 1];
    (plate, CentrifugalConfig::default())
}

/// The collocation's (forward, backward) `count` lowest waves, rad/s, turning frame.
fn reference(plate: &PlateConfig, k: u32, spin: f64, count: usize) -> (Vec<f64>, Vec<f64>) {
    let a = SpinningAnnulus::of(plate, true);
    let z = roots(&a, &Lame::new(plate, true), k, spin, 48);
    let mut r: Vec<f64> = z
        .into_iter()
        .filter(|&(re, im)| im.abs() < 1e-6 * re.abs().max(1.0))
        .map(|(re, _)| re)
        .collect();
    r.sort_by(f64::total_cmp);
    let backward: Vec<f64> = r.iter().copied().filter(|&w| w > 0.0).take(count).collect();
    let mut forward: Vec<f64> = r.iter().filter(|&&w| w < 0.0).map(|w| -w).collect();
    forward.sort_by(f64::total_cmp);
    forward.truncate(count);
    (forward, backward)
}

fn relative(a: f64, b: f64) -> f64 {
    (a - b).abs() / b.abs()
}

#[test]
fn in_plane_waves_match_the_collocation_at_two_speeds() {
    let (plate, centrifugal) = disc(&[0, 1, 2]);
    let model = PlateModel::bending(&plate).unwrap();
    let speeds = [3000.0, 15000.0];
    let d = campbell(&model, &centrifugal, &speeds).unwrap();
    // k = 0: torsional and radial, two orders each; k = 1, 2: two orders.
    let orders: Vec<(u32, u32)> = d.in_plane.iter().map(|w| (w.k, w.order)).collect();
    assert_eq!(
        orders,
        [
            (0, 0),
            (0, 1),
            (0, 2),
            (0, 3),
            (1, 0),
            (1, 1),
            (2, 0),
            (2, 1)
        ]
    );
    let mut worst: f64 = 0.0;
    for (j, &spin) in speeds.iter().enumerate() {
        for k in 0..=2u32 {
            let waves: Vec<_> = d.in_plane.iter().filter(|w| w.k == k).collect();
            let (fwd, bwd) = reference(&plate, k, spin, waves.len());
            for (i, w) in waves.iter().enumerate() {
                let kw = k as f64 * spin;
                let e = [
                    relative(w.rotating_forward_hz[j] * TAU, fwd[i]),
                    relative(w.rotating_backward_hz[j] * TAU, bwd[i]),
                    relative(w.forward_hz[j] * TAU, fwd[i] + kw),
                    relative(w.backward_hz[j] * TAU, bwd[i] - kw),
                ]
                .into_iter()
                .fold(0.0, f64::max);
                println!(
                    "Ω = {spin:>6} k = {k} order {i}: forward {:.2}, backward {:.2} rad/s (turning frame); worst relative {e:.1e}",
                    fwd[i], bwd[i]
                );
                assert!(e < TOLERANCE, "k = {k} order {i} at {spin}: {e:e}");
                worst = worst.max(e);
            }
        }
    }
    println!("worst over all: {worst:.2e}");
    assert!(
        d.in_plane_critical_speeds.is_empty(),
        "none up to 15 000 rad/s"
    );
}

/// ω_b(Ω) − kΩ of the collocation's lowest backward wave.
fn standing(plate: &PlateConfig, k: u32, spin: f64) -> f64 {
    reference(plate, k, spin, 1).1[0] - k as f64 * spin
}

#[test]
fn a_critical_speed_is_where_the_collocation_backward_wave_stands_still() {
    let (plate, centrifugal) = disc(&[2]);
    let model = PlateModel::bending(&plate).unwrap();
    let speeds: Vec<f64> = (0..=6).map(|i| 10_000.0 * i as f64).collect();
    let d = campbell(&model, &centrifugal, &speeds).unwrap();
    let (mut low, mut high) = (40_000.0, 50_000.0);
    assert!(standing(&plate, 2, low) > 0.0 && standing(&plate, 2, high) < 0.0);
    while high - low > 1e-9 * high {
        let mid = 0.5 * (low + high);
        if standing(&plate, 2, mid) > 0.0 {
            low = mid;
        } else {
            high = mid;
        }
    }
    let exact = 0.5 * (low + high);
    assert_eq!(
        d.in_plane_critical_speeds.len(),
        1,
        "{:?}",
        d.in_plane_critical_speeds
    );
    let c = d.in_plane_critical_speeds[0];
    let e = relative(c.rad_s, exact);
    println!(
        "k = 2 order 0: critical {:.4} rad/s, collocation {exact:.4}: {e:.1e}",
        c.rad_s
    );
    assert_eq!((c.k, c.order), (2, 0));
    assert!(e < TOLERANCE, "{e:e}");
    // The space-fixed backward frequency changes sign across it on the grid.
    let w = &d.in_plane[0];
    assert!(w.backward_hz[4] > 0.0 && w.backward_hz[5] < 0.0);
}

#[test]
fn the_cli_lists_the_in_plane_waves_and_leaves_them_out_without_the_key() {
    let ip = "plate.in_plane_nodal_diameters:=[2]";
    let args = |extra: &[&'static str]| {
        let mut a = vec!["campbell", BENCH, "--speeds", "0:60000:7"];
        a.extend_from_slice(extra);
        a
    };
    let (ok, json, err) = support::cli::run(&args(&["--json", "-p", ip]));
    assert!(ok, "{err}");
    let v: serde_json::Value = serde_json::from_str(&json).unwrap();
    let waves = v["in_plane"].as_array().unwrap();
    assert_eq!(waves.len(), 3, "orders 0, 1, 2 of the bench scene");
    let critical = v["in_plane_critical_speeds"].as_array().unwrap();
    assert_eq!(critical[0]["k"], 2);
    assert_eq!(critical[0]["order"], 0);
    let (ok, text, err) = support::cli::run(&args(&["-p", ip]));
    assert!(ok, "{err}");
    assert!(text.contains("In-plane waves"), "{text}");
    let (ok, plain, err) = support::cli::run(&args(&["--json"]));
    assert!(ok, "{err}");
    let v: serde_json::Value = serde_json::from_str(&plain).unwrap();
    assert!(v.get("in_plane").is_none() && v.get("in_plane_critical_speeds").is_none());
    let (ok, text, err) = support::cli::run(&args(&[]));
    assert!(ok, "{err}");
    assert!(!text.contains("In-plane"), "{text}");
}

#[test]
fn too_many_in_plane_eigensolutions_are_refused_before_any_work() {
    // 121 speeds × 17 k = 2057 eigensolutions, above the bound of 2000.
    let ks = "plate.in_plane_nodal_diameters:=[0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16]";
    let started = std::time::Instant::now();
    let (ok, out, err) =
        support::cli::run(&["campbell", BENCH, "--speeds", "0:1000:121", "-p", ks]);
    let seconds = started.elapsed().as_secs_f64();
    assert!(!ok && out.is_empty(), "{out}");
    assert!(
        err.contains("--speeds") && err.contains("plate.in_plane_nodal_diameters"),
        "{err}"
    );
    println!("refused in {seconds:.2} s: {err}");
}
