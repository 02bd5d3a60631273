//! `-p NAME:=VALUE` for `modes`, `simulate`, `study`, `campbell` and
//! `stability` as for `plot` and `run`: an override gives exactly what the same value
//! written into the file gives, and a bad one is refused naming the key.

mod support;

use std::path::PathBuf;
use support::cli::run;
use support::scene_files;

fn ok(args: &[&str]) -> String {
    let (ok, out, err) = run(args);
    assert!(ok, "{args:?}: {err}");
    out
}

fn refused(args: &[&str]) -> String {
    let (ok, _, err) = run(args);
    assert!(!ok, "{args:?} was accepted");
    err
}

/// The brake bench with one line of the file replaced.
fn edited(name: &str, from: &str, to: &str) -> PathBuf {
    let text = scene_files::text("brake_bench.yaml");
    assert_eq!(text.matches(from).count(), 1, "{from} is in the file once");
    let path = support::cli::scratch_dir("overrides").join(name);
    std::fs::write(&path, text.replace(from, to)).unwrap();
    path
}

#[test]
fn modes_with_an_override_equal_modes_of_the_edited_file() {
    let bench = scene_files::path("brake_bench.yaml");
    let file = edited("thin.yaml", "thickness: 0.0181", "thickness: 0.012");
    let by_p = ok(&[
        "modes",
        bench.to_str().unwrap(),
        "--json",
        "-p",
        "plate.thickness:=0.012",
    ]);
    let by_file = ok(&["modes", file.to_str().unwrap(), "--json"]);
    let plain = ok(&["modes", bench.to_str().unwrap(), "--json"]);
    assert_eq!(by_p, by_file);
    assert_ne!(by_p, plain, "the override changed the frequencies");
    let fewer = ok(&[
        "modes",
        bench.to_str().unwrap(),
        "--json",
        "--param",
        "plate.nodal_diameters:=[0, 1]",
    ]);
    assert!(
        fewer.len() < plain.len(),
        "fewer nodal diameters, fewer modes"
    );
}

#[test]
fn simulate_with_an_override_equals_simulate_of_the_edited_file() {
    let bench = scene_files::path("brake_bench.yaml");
    let file = edited("fast.yaml", "speed: 25.0", "speed: 40.0");
    let common = ["--duration", "0.01", "--csv", "-", "--quiet"];
    let mut a = vec![
        "simulate",
        bench.to_str().unwrap(),
        "-p",
        "joint.speed:=40.0",
    ];
    a.extend(common);
    let mut b = vec!["simulate", file.to_str().unwrap()];
    b.extend(common);
    let (by_p, by_file) = (ok(&a), ok(&b));
    assert_eq!(by_p, by_file);
    assert!(by_p.lines().count() > 10, "{by_p}");
}

#[test]
fn campbell_and_stability_with_an_override_equal_the_edited_file() {
    let bench = scene_files::path("brake_bench.yaml");
    let file = edited(
        "stiffened.yaml",
        "    plate:\n",
        "    plate:\n      centrifugal_stiffening: true\n",
    );
    // Centrifugal stiffening takes Kirchhoff plates only (docs/mindlin.md);
    // the file ships Mindlin theory.
    let kirchhoff = ["-p", "plate.theory:=kirchhoff"];
    let campbell = |file: &PathBuf, extra: &[&str]| {
        let mut a = vec![
            "campbell",
            file.to_str().unwrap(),
            "--speeds",
            "0:8000:5",
            "--json",
        ];
        a.extend(kirchhoff);
        a.extend(extra);
        ok(&a)
    };
    let by_p = campbell(&bench, &["-p", "plate.centrifugal_stiffening:=true"]);
    let by_file = campbell(&file, &[]);
    let plain = campbell(&bench, &[]);
    assert_eq!(by_p, by_file);
    assert_ne!(by_p, plain, "the override stiffened the plate");
    let squeal = scene_files::path("brake_squeal.yaml");
    let map = |extra: &[&str]| {
        let mut a = vec![
            "stability",
            squeal.to_str().unwrap(),
            "--mu",
            "0.1:0.6:6",
            "--speeds",
            "3:3:1",
            "--json",
            "--threads",
            "1",
        ];
        a.extend(extra);
        ok(&a)
    };
    let threshold = |json: String| -> f64 {
        let v: serde_json::Value = serde_json::from_str(&json).unwrap();
        v["threshold_mu"][0].as_f64().unwrap()
    };
    // docs/scenes.md: with a stiff lining and Kirchhoff theory the rigid
    // pads' closed forms (tests/scene_brake_squeal.rs), 0.419149 with the
    // pads in series with the residual, 0.417610 modal; the file as shipped
    // (Mindlin theory, the lining's shear) 0.201562 and 0.201070.
    let stiff = [
        "-p",
        "pads.shear_stiffness:=1.0e14",
        "-p",
        "pads.shear_damping:=1.0e9",
        "-p",
        "plate.theory:=kirchhoff",
    ];
    let modal = ["-p", "plate.residual_flexibility:=false"];
    let (series, modal_rigid) = (
        threshold(map(&stiff)),
        threshold(map(&[&stiff[..], &modal[..]].concat())),
    );
    assert!(
        (series - 0.419149).abs() < 5e-6 && (modal_rigid - 0.417610).abs() < 5e-6,
        "thresholds: {series}, {modal_rigid}"
    );
    let (shipped, shipped_modal) = (threshold(map(&[])), threshold(map(&modal)));
    assert!(
        (shipped - 0.201562).abs() < 5e-6 && (shipped_modal - 0.201070).abs() < 5e-6,
        "thresholds with the lining's shear: {shipped}, {shipped_modal}"
    );
}

#[test]
fn bad_overrides_are_refused_naming_the_key_or_the_form() {
    let bench = scene_files::path("brake_bench.yaml");
    let b = bench.to_str().unwrap();
    let e = refused(&["modes", b, "-p", "plate.thickness:=-1"]);
    assert!(e.contains("plate.thickness"), "{e}");
    let e = refused(&[
        "simulate",
        b,
        "--duration",
        "0.01",
        "--csv",
        "-",
        "-p",
        "joint.speed",
    ]);
    assert!(e.contains("expected NAME:=VALUE"), "{e}");
    let e = refused(&["study", b, "--quick", "-p", "plate.no_such_key:=1"]);
    assert!(e.contains("plate.no_such_key"), "{e}");
    let e = refused(&["study", "--quick", "-p", "plate.thickness:=0.01"]);
    assert!(
        e.contains("FILE") || e.contains("file"),
        "-p needs a file to override: {e}"
    );
}
