//! `annular_plate campbell`: the issue's JSON schema, critical speeds without
//! stiffening equal to ω/k of the exact (Bessel) frequencies, with stiffening
//! where the backward frequency crosses zero, and the picture.

mod support;

use annular_plate::cli::plot::{self, Size};
use annular_plate::config::{CentrifugalConfig, Config, InPlaneInner, InPlaneOuter};
use annular_plate::model::campbell::campbell;
use annular_plate::model::{PlateModel, SpinningSpectrum};
use serde_json::Value;
use std::f64::consts::TAU;
use std::path::{Path, PathBuf};
use support::cli::run;
use support::exact_plate::{Annulus, Edge, Material};

fn dir() -> PathBuf {
    support::cli::scratch_dir("campbell")
}

/// The lathe disc (clamped–free, r_i/r_a = 0.5), k = 0..4, l = 0, 1.
fn params(name: &str, stiffening: bool) -> PathBuf {
    let body = format!(
        "annular_plate:\n  ros__parameters:\n    plate:\n      nodal_diameters: [0, 1, 2, 3, 4]\n      nodal_circles: [0, 1]\n      centrifugal_stiffening: {stiffening}\n"
    );
    let p = dir().join(name);
    std::fs::write(&p, body).unwrap();
    p
}

fn json(file: &Path, extra: &[&str]) -> Value {
    let mut args = vec!["campbell", file.to_str().unwrap(), "--json"];
    args.extend_from_slice(extra);
    let (ok, out, err) = run(&args);
    assert!(ok, "{err}");
    serde_json::from_str(&out).unwrap()
}

fn floats(v: &Value) -> Vec<f64> {
    v.as_array()
        .unwrap()
        .iter()
        .map(|x| x.as_f64().unwrap())
        .collect()
}

#[test]
fn json_has_the_issue_schema_and_critical_speeds_are_omega_over_k_of_the_exact_frequencies() {
    let doc = json(&params("off.yaml", false), &["--speeds", "0:10000:11"]);
    let keys: Vec<&String> = doc.as_object().unwrap().keys().collect();
    assert_eq!(keys, ["critical_speeds", "modes", "speeds_rad_s"]);
    let speeds = floats(&doc["speeds_rad_s"]);
    assert_eq!(
        speeds,
        (0..=10).map(|i| 1000.0 * i as f64).collect::<Vec<_>>()
    );
    let modes = doc["modes"].as_array().unwrap();
    assert_eq!(modes.len(), 10, "one entry per ⟨k, l⟩");
    let annulus = Annulus::new(0.075, 0.15, 0.3, Edge::Clamped, Edge::Free);
    let steel = Material::steel(0.01);
    for m in modes {
        let mut keys: Vec<&String> = m.as_object().unwrap().keys().collect();
        keys.sort();
        assert_eq!(keys, ["backward_hz", "forward_hz", "k", "l", "rotating_hz"]);
        let (k, l) = (
            m["k"].as_u64().unwrap() as u32,
            m["l"].as_u64().unwrap() as usize,
        );
        let exact_hz = steel.frequency_hz(annulus.lambdas(k, 400.0)[l]);
        let (rot, fwd, bwd) = (
            floats(&m["rotating_hz"]),
            floats(&m["forward_hz"]),
            floats(&m["backward_hz"]),
        );
        for i in 0..speeds.len() {
            assert!(
                (rot[i] - exact_hz).abs() < 1e-6 * exact_hz,
                "⟨{k},{l}⟩: {} vs exact {exact_hz}",
                rot[i]
            );
            let shift = k as f64 * speeds[i] / TAU;
            assert!((fwd[i] - (rot[i] + shift)).abs() < 1e-9 * fwd[i].abs().max(1.0));
            assert!((bwd[i] - (rot[i] - shift)).abs() < 1e-9 * rot[i].abs().max(1.0));
        }
        let critical = doc["critical_speeds"]
            .as_array()
            .unwrap()
            .iter()
            .find(|c| c["k"] == m["k"] && c["l"] == m["l"]);
        if k == 0 {
            assert!(critical.is_none(), "k = 0 has no critical speed");
            continue;
        }
        let rad_s = critical.unwrap()["rad_s"].as_f64().unwrap();
        let exact = TAU * exact_hz / k as f64;
        assert!(
            (rad_s - exact).abs() < 1e-6 * exact,
            "⟨{k},{l}⟩: critical {rad_s} vs ω/k = {exact}"
        );
    }
    assert_eq!(doc["critical_speeds"].as_array().unwrap().len(), 8);
}

#[test]
fn stiffened_critical_speeds_are_where_the_backward_frequency_crosses_zero() {
    let file = params("on.yaml", true);
    let doc = json(&file, &[]);
    let speeds = floats(&doc["speeds_rad_s"]);
    let critical: Vec<(u32, u32, f64)> = doc["critical_speeds"]
        .as_array()
        .unwrap()
        .iter()
        .map(|c| {
            (
                c["k"].as_u64().unwrap() as u32,
                c["l"].as_u64().unwrap() as u32,
                c["rad_s"].as_f64().unwrap(),
            )
        })
        .collect();
    // Default range: 0 to 1.2 × the highest critical speed, 121 speeds.
    let top = critical.iter().map(|c| c.2).fold(0.0, f64::max);
    assert_eq!(speeds.len(), 121);
    assert!((speeds[120] - 1.2 * top).abs() < 1e-9 * top && speeds[0] == 0.0);
    // The lathe disc's ⟨3, 0⟩: 5,536.85 rad/s (the shooting solution of
    // tests/centrifugal_stiffening.rs gives 5,536.845), not ω/k = 4,304.1.
    let c30 = critical.iter().find(|c| c.0 == 3 && c.1 == 0).unwrap().2;
    assert!((c30 - 5536.845).abs() < 0.01, "{c30}");
    let config = Config::from_params_file(&file, "annular_plate").unwrap();
    for m in doc["modes"].as_array().unwrap() {
        let (k, l) = (
            m["k"].as_u64().unwrap() as u32,
            m["l"].as_u64().unwrap() as u32,
        );
        let bwd = floats(&m["backward_hz"]);
        let rot = floats(&m["rotating_hz"]);
        // The rotating frequency rises with speed (tension stiffens).
        assert!(rot.windows(2).all(|w| w[1] > w[0]), "⟨{k},{l}⟩");
        // Sign changes of the backward frequency (a value within round-off of zero counts with the next one).
        let zero = 1e-9 * rot[0];
        let crossings: Vec<usize> = (0..bwd.len() - 1)
            .filter(|&i| bwd[i] > zero && bwd[i + 1] <= zero)
            .collect();
        match critical.iter().find(|c| c.0 == k && c.1 == l) {
            None => assert!(
                crossings.is_empty() || k == 0,
                "⟨{k},{l}⟩ crosses zero without a critical speed"
            ),
            Some(&(_, _, rad_s)) => {
                assert_eq!(crossings.len(), 1, "⟨{k},{l}⟩");
                let i = crossings[0];
                let tol = 1e-9 * rad_s;
                assert!(
                    speeds[i] - tol <= rad_s && rad_s <= speeds[i + 1] + tol,
                    "⟨{k},{l}⟩: {rad_s} not in [{}, {}]",
                    speeds[i],
                    speeds[i + 1]
                );
                // At the critical speed the full spectrum's backward frequency is zero.
                let s = SpinningSpectrum::new(&config.plate, &config.centrifugal, k, 2);
                let w = s.omega_squared(rad_s).unwrap()[l as usize].sqrt();
                assert!(
                    (w - k as f64 * rad_s).abs() < 1e-9 * w,
                    "⟨{k},{l}⟩: ω = {w}, kΩ = {}",
                    k as f64 * rad_s
                );
            }
        }
    }
}

#[test]
fn a_single_speed_and_bad_speed_ranges() {
    let file = params("single.yaml", true);
    let doc = json(&file, &["--speeds", "25:25:1"]);
    assert_eq!(floats(&doc["speeds_rad_s"]), vec![25.0]);
    for bad in [
        "0:100", "a:100:3", "100:0:3", "0:100:0", "-5:100:3", "0:100:1", "0:inf:3",
    ] {
        let (ok, _, err) = run(&["campbell", file.to_str().unwrap(), "--speeds", bad]);
        assert!(
            !ok && err.contains("--speeds") && err.contains(bad),
            "{bad}: {err}"
        );
    }
    let (ok, text, err) = run(&["campbell", file.to_str().unwrap(), "--speeds", "0:6000:4"]);
    assert!(ok, "{err}");
    assert!(
        text.contains("centrifugal stiffening on") && text.contains("5536.847"),
        "{text}"
    );
}

#[test]
fn the_picture_marks_each_critical_speed_on_its_speed_line() {
    let file = params("plot.yaml", true);
    let out = dir().join("campbell.png");
    let (ok, _, err) = run(&[
        "campbell",
        file.to_str().unwrap(),
        "--speeds",
        "0:12000:61",
        "--plot",
        out.to_str().unwrap(),
    ]);
    assert!(ok, "{err}");
    let img = image::open(&out).unwrap().to_rgb8();
    assert_eq!(img.dimensions(), (1200, 800));
    // The same picture in-process gives the marker geometry: a black dot at each critical speed in range.
    let mut plate = Config::from_params_file(&file, "annular_plate").unwrap();
    plate.centrifugal = CentrifugalConfig {
        stiffening: true,
        in_plane_inner: InPlaneInner::Auto,
        in_plane_outer: InPlaneOuter::Free,
    };
    let model = PlateModel::new(&plate.plate).unwrap();
    let speeds: Vec<f64> = (0..=60).map(|i| 200.0 * i as f64).collect();
    let diagram = campbell(&model, &plate.centrifugal, &speeds).unwrap();
    let again = dir().join("campbell_again.png");
    let geometry = plot::campbell(
        &diagram,
        true,
        &again,
        Size {
            width: 1200,
            height: 800,
        },
    )
    .unwrap();
    let in_range = diagram
        .critical_speeds
        .iter()
        .filter(|c| c.rad_s <= 12000.0)
        .count();
    assert!(in_range >= 3, "{:?}", diagram.critical_speeds);
    assert_eq!(geometry.markers.len(), in_range);
    assert_eq!(
        std::fs::read(&out).unwrap(),
        std::fs::read(&again).unwrap(),
        "CLI and library draw the same picture"
    );
    for &(k, l, x, y) in &geometry.markers {
        let dark = (-2..=2)
            .flat_map(|dx| (-2..=2).map(move |dy| (dx, dy)))
            .all(|(dx, dy)| {
                let p = img.get_pixel((x + dx) as u32, (y + dy) as u32);
                p.0.iter().all(|&c| c < 40)
            });
        assert!(dark, "no black marker for ⟨{k},{l}⟩ at ({x}, {y})");
    }
    // Bad output paths are named.
    let (ok, _, err) = run(&[
        "campbell",
        file.to_str().unwrap(),
        "--plot",
        "/nonexistent/dir/c.png",
    ]);
    assert!(!ok && err.contains("/nonexistent/dir"), "{err}");
}

/// With in-plane modes (config/brake_in_plane.yaml: k = 0, 1, 2) the
/// picture adds their waves and rings each in-plane critical speed in range
/// (the backward ⟨2, 0⟩ wave standing still in space near 48.8 krad/s) on its
/// speed line kΩ/2π; the CLI and the library draw the same picture.
#[test]
fn the_picture_rings_each_in_plane_critical_speed_on_its_speed_line() {
    let file = Path::new(env!("CARGO_MANIFEST_DIR")).join("config/brake_in_plane.yaml");
    let out = dir().join("campbell_in_plane.png");
    let (ok, _, err) = run(&[
        "campbell",
        file.to_str().unwrap(),
        "--speeds",
        "0:60000:31",
        "--plot",
        out.to_str().unwrap(),
    ]);
    assert!(ok, "{err}");
    let config = Config::from_params_file(&file, "annular_plate").unwrap();
    let model = PlateModel::bending(&config.plate).unwrap();
    let speeds: Vec<f64> = (0..=30).map(|i| 2000.0 * i as f64).collect();
    let diagram = campbell(&model, &config.centrifugal, &speeds).unwrap();
    assert_eq!(diagram.in_plane.len(), 4, "k = 0 (two orders), 1, 2");
    let again = dir().join("campbell_in_plane_again.png");
    let size = Size {
        width: 1200,
        height: 800,
    };
    let geometry = plot::campbell(&diagram, config.centrifugal.stiffening, &again, size).unwrap();
    assert_eq!(
        std::fs::read(&out).unwrap(),
        std::fs::read(&again).unwrap(),
        "CLI and library draw the same picture"
    );
    assert_eq!(
        geometry.in_plane_markers.len(),
        diagram.in_plane_critical_speeds.len()
    );
    assert!(!geometry.in_plane_markers.is_empty());
    let img = image::open(&out).unwrap().to_rgb8();
    let dark = |x: i32, y: i32| img.get_pixel(x as u32, y as u32).0.iter().all(|&c| c < 60);
    for &(k, order, x, y) in &geometry.in_plane_markers {
        let c = diagram
            .in_plane_critical_speeds
            .iter()
            .find(|c| c.k == k && c.order == order)
            .unwrap();
        println!(
            "in-plane ⟨{k}, {order}⟩ critical at {:.1} rad/s, ring at ({x}, {y})",
            c.rad_s
        );
        // The ring: dark on its circle, in all four directions.
        let r = plot::CRITICAL_MARKER_RADIUS;
        let on_ring = [(r, 0), (-r, 0), (0, r), (0, -r)].iter().all(|&(dx, dy)| {
            (-1..=1).any(|d| dark(x + dx + d * dx.signum(), y + dy + d * dy.signum()))
        });
        assert!(on_ring, "no ring for in-plane ⟨{k},{order}⟩ at ({x}, {y})");
    }
}
