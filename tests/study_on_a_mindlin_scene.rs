//! `annular_plate study` with Mindlin modes and the plate theory as a lever:
//!
//! * on a Mindlin scene (config/lathe.yaml, h/b = 0.13, clamped–free) the
//!   frequency axis's errors fall with the spline count and its reference
//!   frequencies match the exact Mindlin roots (`tests/support/mindlin_exact.rs`)
//!   within the uncertainty it states; axis 2 is skipped and the JSON says why;
//!   axis 3 runs; the Pareto picture is drawn;
//! * on a Kirchhoff scene (config/brake_bench.yaml, h/b = 0.22) the theory
//!   comparison's Mindlin frequencies match the exact Mindlin roots within its
//!   stated uncertainty, and Kirchhoff's error is what `modes` of the two
//!   theories gives.

mod support;

use annular_plate::config::Config;
use serde_json::Value;
use support::cli::run;
use support::mindlin_exact::MindlinAnnulus;

const LATHE: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/config/lathe.yaml");
const BENCH: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/config/brake_bench.yaml");
const MINDLIN: [&str; 4] = [
    "-p",
    "plate.theory:=mindlin",
    "-p",
    "plate.residual_flexibility:=false",
];

fn json(args: &[&str]) -> Value {
    let (ok, out, err) = run(args);
    assert!(ok, "{err}");
    serde_json::from_str(&out).unwrap_or_else(|e| panic!("not JSON: {e}\n{out}"))
}

/// The exact Mindlin annulus of a scene file (its plate, read by the library's reader).
fn exact(file: &str) -> MindlinAnnulus {
    let text = std::fs::read_to_string(file).unwrap();
    let config = Config::from_yaml_str(&text, "annular_plate").unwrap();
    MindlinAnnulus::of_plate(&config.plate)
}

/// Largest relative deviation of `(⟨k, l⟩, Hz)` pairs from the exact Mindlin roots.
fn worst_against_exact(exact: &MindlinAnnulus, modes: &[(u64, u64, f64)]) -> f64 {
    modes
        .iter()
        .map(|&(k, l, hz)| {
            let root = exact.roots(k as u32, l as usize + 1, 64)[l as usize];
            (hz * std::f64::consts::TAU / root - 1.0).abs()
        })
        .fold(0.0, f64::max)
}

#[test]
fn study_on_a_mindlin_scene_converges_to_the_exact_mindlin_roots() {
    let picture = support::cli::scratch_dir("study_mindlin").join("pareto.png");
    let mut args = vec!["study", LATHE, "--quick", "--quiet", "--json"];
    args.extend(["--plot", picture.to_str().unwrap()]);
    args.extend(MINDLIN);
    let v = json(&args);
    // The Pareto picture is drawn (its second panel the theory lever).
    let png = image::open(&picture).expect("a readable PNG").to_rgb8();
    assert_eq!(png.dimensions(), (1500, 560));

    // Axis 2 is skipped, and the document says why.
    assert!(v["mode_count"].is_null());
    let notes: Vec<&str> = v["notes"]
        .as_array()
        .expect("notes")
        .iter()
        .map(|n| n.as_str().unwrap())
        .collect();
    assert!(
        notes
            .iter()
            .any(|n| n.contains("mode_count (axis 2) is skipped") && n.contains("infinite")),
        "{notes:?}"
    );

    // Axis 1: the fixed counts' errors fall with the count.
    let a = &v["radial_splines"];
    let fixed: Vec<(u64, f64)> = a["rows"]
        .as_array()
        .unwrap()
        .iter()
        .filter_map(|r| {
            Some((
                r["radial_splines"].as_u64()?,
                r["max_relative_error"].as_f64().unwrap(),
            ))
        })
        .collect();
    assert!(fixed.len() >= 3, "{fixed:?}");
    for w in fixed.windows(2) {
        assert!(w[1].1 < w[0].1, "errors fall with the count: {fixed:?}");
    }
    assert!(a["rows"]
        .as_array()
        .unwrap()
        .iter()
        .any(|r| r["radial_splines"] == "auto"));
    // Its reference: 2 × the largest count, checked at half and double.
    let largest = fixed.last().unwrap().0;
    let rf = &a["reference"];
    assert_eq!(rf["radial_splines"].as_u64(), Some((2 * largest).min(120)));
    assert!(rf["finer_check_radial_splines"].as_u64().is_some());
    let uncertainty = rf["uncertainty"].as_f64().unwrap();
    let modes: Vec<(u64, u64, f64)> = rf["frequencies_hz"]
        .as_array()
        .unwrap()
        .iter()
        .map(|p| {
            (
                p[0]["k"].as_u64().unwrap(),
                p[0]["l"].as_u64().unwrap(),
                p[1].as_f64().unwrap(),
            )
        })
        .collect();
    assert_eq!(modes.len(), 16, "k = 0..7, l = 0..1");
    let worst = worst_against_exact(&exact(LATHE), &modes);
    println!(
        "lathe disc under Mindlin: axis 1 errors {fixed:?}; reference ({} splines per field) against the exact roots {worst:.2e}, stated uncertainty {uncertainty:.2e}",
        rf["radial_splines"]
    );
    assert!(worst <= uncertainty, "{worst:e} > {uncertainty:e}");

    // Axis 3 runs on the Mindlin modes.
    assert!(!v["integrator"]["rows"].as_array().unwrap().is_empty());
    assert_eq!(v["theory"]["scene_theory"], "mindlin");
}

/// `modes --json` of a scene: (k, l, Hz) per ⟨k, l⟩ (cos members and k = 0).
fn modes_of(file: &str, overrides: &[&str]) -> Vec<(u64, u64, f64)> {
    let mut args = vec!["modes", file, "--json"];
    args.extend(overrides);
    let doc = json(&args);
    doc["modes"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|m| m["shape"] != "sin")
        .map(|m| {
            (
                m["k"].as_u64().unwrap(),
                m["l"].as_u64().unwrap(),
                m["frequency_hz"].as_f64().unwrap(),
            )
        })
        .collect()
}

#[test]
fn theory_comparison_measures_kirchhoffs_error_against_converged_mindlin() {
    // The bench scene ships Mindlin; its Kirchhoff model is the one compared.
    let v = json(&[
        "study",
        BENCH,
        "--quick",
        "--quiet",
        "--json",
        "-p",
        "plate.theory:=kirchhoff",
    ]);
    let t = &v["theory"];
    let keys: std::collections::BTreeSet<&str> =
        t.as_object().unwrap().keys().map(String::as_str).collect();
    assert_eq!(
        keys,
        [
            "what",
            "error_measure",
            "cost_measure",
            "scene_theory",
            "shear_correction",
            "mindlin_reference",
            "rows",
            "max_kirchhoff_error",
            "worst_mode",
            "kirchhoff",
            "mindlin",
            "mindlin_cost_ratio",
            "note"
        ]
        .into_iter()
        .collect()
    );
    assert_eq!(t["scene_theory"], "kirchhoff");
    let rows = t["rows"].as_array().unwrap();
    let mindlin: Vec<(u64, u64, f64)> = rows
        .iter()
        .map(|r| {
            (
                r["mode"]["k"].as_u64().unwrap(),
                r["mode"]["l"].as_u64().unwrap(),
                r["mindlin_hz"].as_f64().unwrap(),
            )
        })
        .collect();
    assert!(
        mindlin.windows(2).all(|w| w[0].2 <= w[1].2),
        "ascending in Mindlin frequency"
    );
    // The Mindlin reference against the exact Mindlin roots, within its stated uncertainty.
    let uncertainty = t["mindlin_reference"]["uncertainty"].as_f64().unwrap();
    let worst = worst_against_exact(&exact(BENCH), &mindlin);
    println!("bench disc: Mindlin reference against the exact roots {worst:.2e}, stated uncertainty {uncertainty:.2e}");
    assert!(worst <= uncertainty, "{worst:e} > {uncertainty:e}");
    assert!(uncertainty < 1e-6, "{uncertainty:e}");

    // Kirchhoff's error: `modes` of the scene as it is against `modes` under Mindlin theory.
    let kirchhoff = modes_of(BENCH, &["-p", "plate.theory:=kirchhoff"]);
    let mindlin_modes = modes_of(BENCH, &MINDLIN);
    assert_eq!(kirchhoff.len(), rows.len());
    let mut largest: f64 = 0.0;
    for r in rows {
        let (k, l) = (r["mode"]["k"].as_u64(), r["mode"]["l"].as_u64());
        let find = |m: &[(u64, u64, f64)]| {
            m.iter()
                .find(|x| Some(x.0) == k && Some(x.1) == l)
                .unwrap()
                .2
        };
        let want = find(&kirchhoff) / find(&mindlin_modes) - 1.0;
        let got = r["kirchhoff_error"].as_f64().unwrap();
        assert!(
            (got - want).abs() < 1e-12,
            "⟨{k:?}, {l:?}⟩: {got} vs {want}"
        );
        assert_eq!(r["kirchhoff_hz"].as_f64().unwrap(), find(&kirchhoff));
        largest = largest.max(want.abs());
    }
    assert_eq!(t["max_kirchhoff_error"].as_f64().unwrap(), largest);
    // What each costs: both build times measured, the ratio theirs.
    let (tk, tm) = (
        t["kirchhoff"]["build_time_s"].as_f64().unwrap(),
        t["mindlin"]["build_time_s"].as_f64().unwrap(),
    );
    assert!(tk > 0.0 && tm > 0.0);
    assert_eq!(t["mindlin_cost_ratio"].as_f64().unwrap(), tm / tk);
    println!(
        "bench disc: Kirchhoff's largest error {:.4} at ⟨{}, {}⟩; build {tk:.2e} s (Kirchhoff) and {tm:.2e} s (Mindlin)",
        largest, t["worst_mode"]["k"], t["worst_mode"]["l"]
    );
    assert!(largest > 0.01, "the bench disc is thick: {largest}");
}

/// An edge Kirchhoff theory lacks leaves its side of the comparison empty, and says so.
#[test]
fn theory_comparison_on_a_soft_support_has_no_kirchhoff_side() {
    let mut args = vec!["study", BENCH, "--quick", "--quiet", "--json"];
    args.extend(MINDLIN);
    args.extend(["-p", "plate.inner_boundary:=supported_soft"]);
    let v = json(&args);
    let t = &v["theory"];
    assert!(t["kirchhoff"].is_null() && t["max_kirchhoff_error"].is_null());
    assert!(t["note"].as_str().unwrap().contains("supported_soft"));
    assert!(t["rows"]
        .as_array()
        .unwrap()
        .iter()
        .all(|r| r["kirchhoff_error"].is_null() && r["mindlin_hz"].as_f64().unwrap() > 0.0));
}
