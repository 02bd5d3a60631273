//! `annular_plate study [FILE]` on the command line: reproducible errors, a
//! stable JSON document, a readable table, the Pareto picture, clear errors.

mod support;

use serde_json::Value;
use std::collections::BTreeSet;
use std::path::PathBuf;

fn dir() -> PathBuf {
    support::cli::scratch_dir("study")
}

fn study(args: &[&str]) -> (bool, String, String) {
    let all: Vec<&str> = std::iter::once("study")
        .chain(args.iter().copied())
        .collect();
    support::cli::run(&all)
}

fn json(args: &[&str]) -> Value {
    let mut all = vec!["--quick", "--json"];
    all.extend_from_slice(args);
    let (ok, out, err) = study(&all);
    assert!(ok, "{err}");
    serde_json::from_str(&out).unwrap_or_else(|e| panic!("not JSON: {e}\n{out}"))
}

/// The document less everything measured in wall time (and what is chosen by it).
fn without_timings(v: &Value) -> Value {
    const TIMED: [&str; 9] = [
        "build_time_s",
        "mindlin_cost_ratio",
        "step_time_s",
        "step_time_with_residual_s",
        "wall_s_per_simulated_s",
        "wall_time_s",
        "pareto",
        "pareto_with_residual",
        "recommendations",
    ];
    match v {
        Value::Object(m) => Value::Object(
            m.iter()
                .filter(|(k, _)| !TIMED.contains(&k.as_str()))
                .map(|(k, v)| (k.clone(), without_timings(v)))
                .collect(),
        ),
        Value::Array(a) => Value::Array(a.iter().map(without_timings).collect()),
        other => other.clone(),
    }
}

#[test]
fn errors_are_bit_identical_from_run_to_run() {
    let a = json(&[]);
    let b = json(&[]);
    // serde_json prints the shortest representation that reads back to the same
    // f64, so equal documents mean bit-identical errors.
    assert_eq!(without_timings(&a), without_timings(&b));
    // and the timings are real measurements
    let t = a["radial_splines"]["rows"][0]["build_time_s"]
        .as_f64()
        .unwrap();
    assert!(t > 0.0 && t < 1.0, "{t}");
    // a recommendation's claimed error is its measured error plus the reference's uncertainty
    for axis in ["radial_splines", "mode_count", "integrator"] {
        let u = a[axis]["reference"]["uncertainty"].as_f64().unwrap();
        for r in a[axis]["recommendations"].as_array().unwrap() {
            if let (Some(e), Some(c)) = (r["error"].as_f64(), r["claimed_error"].as_f64()) {
                assert_eq!(c, e + u);
                assert!(c <= r["target"].as_f64().unwrap());
            } else {
                assert!(r["setting"].is_null() && r["claimed_error"].is_null());
            }
        }
    }
}

fn keys(v: &Value) -> BTreeSet<&str> {
    v.as_object()
        .unwrap_or_else(|| panic!("not an object: {v}"))
        .keys()
        .map(String::as_str)
        .collect()
}

fn set<'a>(names: &[&'a str]) -> BTreeSet<&'a str> {
    names.iter().copied().collect()
}

#[test]
fn json_schema_is_stable() {
    let v = json(&[]);
    assert_eq!(v["schema"], "annular_plate.study/1");
    assert_eq!(
        keys(&v),
        set(&[
            "schema",
            "scene",
            "plan",
            "radial_splines",
            "mode_count",
            "integrator",
            "theory",
            "wall_time_s"
        ])
    );
    assert_eq!(
        keys(&v["scene"]),
        set(&[
            "source",
            "inner_radius",
            "outer_radius",
            "thickness",
            "inner_boundary",
            "outer_boundary",
            "nodal_diameters",
            "nodal_circles",
            "radial_splines",
            "modes",
            "speed_rad_s",
            "integrator",
            "rate_hz"
        ])
    );
    assert_eq!(v["scene"]["source"], "built-in lathe disc");
    assert_eq!(
        keys(&v["plan"]),
        set(&[
            "splines",
            "spline_reference_factor",
            "k_max",
            "l_max",
            "response_reference",
            "response_splines",
            "integrators",
            "rates_hz",
            "sample_rate_hz",
            "trajectory_reference_rate_hz",
            "duration_s",
            "targets",
            "timing_budget"
        ])
    );
    let recommendation = set(&[
        "target",
        "setting",
        "error",
        "claimed_error",
        "cost",
        "is_default",
    ]);
    let axis = |extra: &[&'static str]| {
        let mut s = set(&[
            "what",
            "error_measure",
            "cost_measure",
            "reference",
            "rows",
            "recommendations",
            "default_setting",
        ]);
        s.extend(extra.iter().copied());
        s
    };

    let a = &v["radial_splines"];
    assert_eq!(keys(a), axis(&[]));
    assert_eq!(
        keys(&a["reference"]),
        set(&[
            "radial_splines",
            "check_radial_splines",
            "uncertainty",
            "frequencies_hz"
        ])
    );
    assert_eq!(
        keys(&a["rows"][0]),
        set(&[
            "radial_splines",
            "max_relative_error",
            "worst_mode",
            "build_time_s",
            "pareto"
        ])
    );
    assert_eq!(keys(&a["rows"][0]["worst_mode"]), set(&["k", "l"]));
    assert_eq!(keys(&a["recommendations"][0]), recommendation);
    assert_eq!(
        keys(&a["recommendations"][0]["setting"]),
        set(&["radial_splines"])
    );
    // `auto` (the default) competes with the fixed counts.
    assert_eq!(a["default_setting"]["radial_splines"], "auto");
    assert!(a["rows"]
        .as_array()
        .unwrap()
        .iter()
        .any(|r| r["radial_splines"] == "auto"));

    let b = &v["mode_count"];
    assert_eq!(keys(b), axis(&["load_case", "damping", "notes"]));
    assert_eq!(
        keys(&b["load_case"]),
        set(&["point", "ale_node", "loads", "speed_rad_s", "note"])
    );
    assert_eq!(
        keys(&b["reference"]),
        set(&[
            "k_max",
            "l_max",
            "modes",
            "radial_splines",
            "response_m",
            "response_with_residual_m",
            "nested",
            "uncertainty",
            "uncertainty_method",
            "uncertainty_with_residual"
        ])
    );
    assert_eq!(
        keys(&b["rows"][0]),
        set(&[
            "k_max",
            "l_max",
            "modes",
            "response_m",
            "relative_error",
            "response_with_residual_m",
            "relative_error_with_residual",
            "step_time_s",
            "step_time_with_residual_s",
            "pareto",
            "pareto_with_residual"
        ])
    );
    assert_eq!(
        keys(&b["default_setting"]),
        set(&["k_max", "l_max", "residual_flexibility"])
    );
    assert_eq!(keys(&b["recommendations"][0]), recommendation);
    let picked = b["recommendations"]
        .as_array()
        .unwrap()
        .iter()
        .find(|r| !r["setting"].is_null())
        .expect("a mode set is recommended");
    assert_eq!(
        keys(&picked["setting"]),
        set(&[
            "k_max",
            "l_max",
            "modes",
            "radial_splines",
            "residual_flexibility"
        ])
    );

    let c = &v["integrator"];
    assert_eq!(
        keys(c),
        axis(&[
            "duration_s",
            "sample_rate_hz",
            "modes",
            "integrators",
            "notes"
        ])
    );
    assert_eq!(
        keys(&c["reference"]),
        set(&[
            "integrator",
            "rate_hz",
            "checks",
            "uncertainty",
            "peak_amplitude_m"
        ])
    );
    assert_eq!(
        keys(&c["reference"]["checks"][0]),
        set(&["integrator", "rate_hz", "difference"])
    );
    assert_eq!(c["reference"]["checks"].as_array().unwrap().len(), 2);
    assert_eq!(
        keys(&c["rows"][0]),
        set(&[
            "integrator",
            "rate_hz",
            "status",
            "detail",
            "relative_error",
            "wall_s_per_simulated_s",
            "pareto"
        ])
    );
    assert_eq!(
        keys(&c["recommendations"][0]["setting"]),
        set(&["integrator", "rate_hz"])
    );
    assert_eq!(c["default_setting"]["integrator"], "exponential");
    let integrators: BTreeSet<&str> = c["rows"]
        .as_array()
        .unwrap()
        .iter()
        .map(|r| r["integrator"].as_str().unwrap())
        .collect();
    assert_eq!(
        integrators,
        set(&["exponential", "implicit_midpoint", "rk4"])
    );
    assert!(c["rows"]
        .as_array()
        .unwrap()
        .iter()
        .all(|r| r["status"] == "ok"));

    // The grids are the quick plan's.
    let rows = |x: &Value| x["rows"].as_array().unwrap().len();
    let plan = &v["plan"];
    let len = |x: &Value| x.as_array().unwrap().len();
    assert_eq!(
        rows(a),
        len(&plan["splines"]) + 1,
        "the plan's counts and auto"
    );
    assert_eq!(rows(b), len(&plan["k_max"]) * len(&plan["l_max"]));
    // contact_exponential is in the plan but runs only where load models switch.
    assert_eq!(
        c["integrators"],
        serde_json::json!(["exponential", "implicit_midpoint", "rk4"])
    );
    assert_eq!(rows(c), len(&c["integrators"]) * len(&plan["rates_hz"]));
    assert_eq!(len(&a["recommendations"]), len(&plan["targets"]));
}

#[test]
fn targets_and_duration_options_are_used() {
    let v = json(&["--targets", "0.3,0.05", "--duration", "0.01"]);
    let t: Vec<f64> = v["plan"]["targets"]
        .as_array()
        .unwrap()
        .iter()
        .map(|x| x.as_f64().unwrap())
        .collect();
    assert_eq!(t, vec![0.3, 0.05]);
    assert_eq!(v["integrator"]["duration_s"], 0.01);
    assert_eq!(
        v["mode_count"]["recommendations"].as_array().unwrap().len(),
        2
    );
}

#[test]
fn table_lists_each_axis_and_the_recommendations() {
    let (ok, out, err) = study(&["--quick"]);
    assert!(ok, "{err}");
    for needle in [
        "Study of built-in lathe disc",
        "1. Natural frequencies vs plate.radial_splines",
        "2. Steady deflection at the load point vs mode set",
        "3. Trajectory vs integrator and output rate",
        "Recommended:",
        "exponential",
        "implicit_midpoint",
        "rk4",
        "reference:",
    ] {
        assert!(out.contains(needle), "missing {needle:?} in\n{out}");
    }
    let recommended = out.split("Recommended:").nth(1).unwrap();
    assert_eq!(
        recommended
            .lines()
            .filter(|l| l.trim_start().starts_with("1e-"))
            .count(),
        4,
        "{recommended}"
    );
}

#[test]
fn plot_option_draws_the_pareto_picture() {
    let png = dir().join("pareto.png");
    let (ok, out, err) = study(&["--quick", "--plot", png.to_str().unwrap()]);
    assert!(ok, "{err}");
    assert!(out.contains("Pareto picture"));
    let img = image::open(&png).unwrap();
    assert_eq!((img.width(), img.height()), (1500, 560));
    let svg = dir().join("pareto.svg");
    let (ok, _, err) = study(&["--quick", "--json", "--plot", svg.to_str().unwrap()]);
    assert!(ok, "{err}");
    let text = std::fs::read_to_string(&svg).unwrap();
    let doc = roxmltree::Document::parse(&text).unwrap();
    assert_eq!(doc.root_element().attribute("width"), Some("1500"));
    assert!(text.contains("Pareto front") && text.contains("relative error"));
}

#[test]
fn bad_input_is_named_with_a_non_zero_exit() {
    let (ok, _, err) = study(&["--quick", "/nonexistent/scene.yaml"]);
    assert!(!ok && err.contains("/nonexistent/scene.yaml"), "{err}");
    let bad = dir().join("bad.yaml");
    std::fs::write(
        &bad,
        "annular_plate:\n  ros__parameters:\n    plate:\n      thicknes: 0.01\n",
    )
    .unwrap();
    let (ok, _, err) = study(&["--quick", bad.to_str().unwrap()]);
    assert!(
        !ok && err.contains("plate.thicknes") && err.contains("bad.yaml"),
        "{err}"
    );
    let (ok, _, err) = study(&["--quick", "--targets", "0,2"]);
    assert!(!ok && err.contains("--targets"), "{err}");
    let (ok, _, err) = study(&["--quick", "--duration", "0"]);
    assert!(!ok && err.contains("--duration"), "{err}");
    let (ok, _, err) = study(&["--quick", "--plot", "/tmp/x.jpg"]);
    assert!(!ok && err.contains(".png or .svg"), "{err}");
}

#[test]
fn a_params_file_is_studied_as_given() {
    // A brake-like disc: supported inside, k ≤ 4, l = 0, two unloaded pad nodes.
    let f = dir().join("disc.yaml");
    std::fs::write(
        &f,
        "/**:\n  ros__parameters:\n    plate:\n      inner_radius: 0.07\n      outer_radius: 0.153\n      thickness: 0.0181\n      inner_boundary: supported\n      nodal_diameters: [0, 1, 2, 3, 4]\n      nodal_circles: [0]\n      damping: [0.005]\n    nodes:\n      ale_radial: [0.6, 0.6]\n      ale_angular: [0.0, 0.5]\n    joint:\n      speed: 25.0\n",
    )
    .unwrap();
    let v = json(&[f.to_str().unwrap()]);
    assert_eq!(v["scene"]["source"], f.to_str().unwrap());
    assert_eq!(v["scene"]["inner_boundary"], "supported");
    assert_eq!(v["scene"]["modes"], 9);
    let note = v["mode_count"]["load_case"]["note"].as_str().unwrap();
    assert!(
        note.contains("1 N") && note.contains("ALE node 1"),
        "{note}"
    );
    assert_eq!(v["mode_count"]["load_case"]["point"]["radial"], 0.6);
    assert!(v["integrator"]["notes"]
        .as_array()
        .unwrap()
        .iter()
        .any(|n| n.as_str().unwrap().contains("at rest")));
    assert!(
        v["integrator"]["reference"]["peak_amplitude_m"]
            .as_f64()
            .unwrap()
            > 0.0
    );
}

/// Massive pads (`pads.mass`) have state only rk4 integrates: the trajectory
/// axis takes rk4 as its reference, checks it against rk4 at half its inner
/// step, and lists the other integrators as refused, naming the key.
#[test]
fn a_scene_with_massive_pads_is_studied_with_an_rk4_reference() {
    let bench = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("config/brake_bench.yaml");
    let v = json(&[
        bench.to_str().unwrap(),
        "-p",
        "pads.mass:=0.3",
        "-p",
        "pads.clamp_force:=[5000.0]",
    ]);
    let t = &v["integrator"];
    assert_eq!(t["reference"]["integrator"], "rk4");
    let checks = t["reference"]["checks"].as_array().unwrap();
    assert_eq!(checks.len(), 1);
    assert_eq!(checks[0]["integrator"], "rk4, half the inner step");
    let d = checks[0]["difference"].as_f64().unwrap();
    assert!(
        d > 0.0 && d < 1e-4,
        "the reference converged: half the step differs by {d}"
    );
    assert!(t["notes"]
        .as_array()
        .unwrap()
        .iter()
        .any(|n| n.as_str().unwrap().contains("pads.mass")));
    for row in t["rows"].as_array().unwrap() {
        if row["integrator"] == "rk4" {
            assert_eq!(row["status"], "ok", "{row}");
            assert!(row["relative_error"].as_f64().unwrap() < 1e-3, "{row}");
        } else {
            assert_eq!(row["status"], "refused", "{row}");
            assert!(
                row["detail"].as_str().unwrap().contains("pads.mass"),
                "{row}"
            );
        }
    }
}

/// The lathe scene file: for the load-point targets 1e-3 and 1e-4 the study
/// recommends a mode set with the residual flexibility (the scene's default),
/// not the ~1,500 modes the modes alone would need; the same advice is in the
/// table. (Its error against the exact plate: tests/study_recommendations_hold.rs.)
#[test]
fn lathe_file_is_advised_the_residual_flexibility_for_load_point_targets() {
    let file = concat!(env!("CARGO_MANIFEST_DIR"), "/config/lathe.yaml");
    let (ok, out, err) = study(&[file, "--json", "--quiet"]);
    assert!(ok, "{err}");
    let v: Value = serde_json::from_str(&out).unwrap();
    let b = &v["mode_count"];
    assert_eq!(b["default_setting"]["residual_flexibility"], true);
    for target in [1e-3, 1e-4] {
        let rec = b["recommendations"]
            .as_array()
            .unwrap()
            .iter()
            .find(|r| r["target"].as_f64() == Some(target))
            .expect("the target is in the plan");
        println!("target {target:e}: {rec}");
        assert_eq!(
            rec["setting"]["residual_flexibility"], true,
            "target {target:e}: {rec}"
        );
        assert!(rec["claimed_error"].as_f64().unwrap() <= target);
    }
    // The residual points are on the front.
    assert!(b["rows"]
        .as_array()
        .unwrap()
        .iter()
        .any(|r| r["pareto_with_residual"] == true));
    let (ok, table, err) = study(&[file, "--quiet"]);
    assert!(ok, "{err}");
    let line = table
        .lines()
        .find(|l| l.trim_start().starts_with("1e-3") || l.trim_start().starts_with("1e-03"))
        .unwrap_or_else(|| panic!("{table}"));
    assert!(line.contains("+ residual"), "{line}");
}
