//! `plate.theory: mindlin` in the model and the commands: `modes` lists the
//! Mindlin frequencies of a scene (against the exact Mindlin solution written
//! in `tests/support/mindlin_exact.rs`), `stability` maps a Mindlin scene and
//! refuses its residual flexibility by name, and Kirchhoff scenes too thick
//! for their theory warn (the dynamics with Mindlin modes:
//! tests/mindlin_dynamics.rs; `plot`: tests/plot_pictures.rs; `study`:
//! tests/study_on_a_mindlin_scene.rs).

mod support;

use annular_plate::config::{Config, PlateTheory};
use annular_plate::model::PlateModel;
use support::cli::run;
use support::mindlin_exact::{Edge, MindlinAnnulus};

const BENCH: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/config/brake_bench.yaml");
const NODE: &str = "annular_plate";

/// The bench disc of config/brake_bench.yaml (steel, r_i = 0.07 m,
/// r_a = 0.153 m, h = 18.1 mm, outer edge free), written out here.
fn bench_disc(inner: Edge) -> MindlinAnnulus {
    MindlinAnnulus {
        youngs_modulus: 2.1e11,
        poisson_ratio: 0.3,
        density: 7850.0,
        thickness: 0.0181,
        shear_correction: 5.0 / 6.0,
        inner_radius: 0.07,
        outer_radius: 0.153,
        inner,
        outer: Edge::Free,
    }
}

/// `modes --json` of the bench scene under Mindlin theory with `inner` edge:
/// (k, l, shape, Hz) per mode.
fn mindlin_modes_json(inner: &str) -> (serde_json::Value, Vec<(u32, u32, String, f64)>) {
    let (ok, stdout, stderr) = run(&[
        "modes",
        BENCH,
        "--json",
        "-p",
        "plate.theory:=mindlin",
        "-p",
        &format!("plate.inner_boundary:={inner}"),
        "-p",
        "plate.nodal_diameters:=[0, 1, 2, 3, 4, 5, 6]",
        "-p",
        "plate.nodal_circles:=[0, 1]",
    ]);
    assert!(ok, "modes failed: {stderr}");
    let doc: serde_json::Value = serde_json::from_str(&stdout).expect("json");
    let modes = doc["modes"]
        .as_array()
        .expect("modes")
        .iter()
        .map(|m| {
            (
                m["k"].as_u64().unwrap() as u32,
                m["l"].as_u64().unwrap() as u32,
                m["shape"].as_str().unwrap().to_string(),
                m["frequency_hz"].as_f64().unwrap(),
            )
        })
        .collect();
    (doc, modes)
}

#[test]
fn modes_lists_the_exact_mindlin_frequencies_of_the_bench_disc() {
    for (name, edge) in [
        ("supported", Edge::Supported),
        ("supported_soft", Edge::SupportedSoft),
        ("clamped", Edge::Clamped),
    ] {
        let (doc, modes) = mindlin_modes_json(name);
        assert_eq!(doc["theory"], "mindlin");
        assert_eq!(doc["shear_correction"], 5.0 / 6.0);
        // k = 0: one mode per l, k ≥ 1: a cos/sin pair; 7 k × 2 l.
        assert_eq!(modes.len(), 2 * (1 + 2 * 6), "{name}");
        let exact = bench_disc(edge);
        let mut worst = 0.0f64;
        for k in 0..=6u32 {
            let roots = exact.roots(k, 2, 64);
            for l in 0..2u32 {
                let hz = roots[l as usize] / std::f64::consts::TAU;
                let listed: Vec<f64> = modes
                    .iter()
                    .filter(|m| m.0 == k && m.1 == l)
                    .map(|m| m.3)
                    .collect();
                assert_eq!(
                    listed.len(),
                    if k == 0 { 1 } else { 2 },
                    "{name} ⟨{k}, {l}⟩"
                );
                for f in listed {
                    let rel = (f - hz).abs() / hz;
                    worst = worst.max(rel);
                    assert!(
                        rel < 1e-6,
                        "{name} ⟨{k}, {l}⟩: {f} Hz against exact {hz} Hz ({rel:.2e})"
                    );
                }
            }
        }
        println!("bench disc, inner {name}: worst relative deviation from the exact Mindlin roots {worst:.2e}");
        let listed: Vec<f64> = modes.iter().map(|m| m.3).collect();
        assert!(
            listed.windows(2).all(|w| w[0] <= w[1]),
            "sorted by frequency"
        );
    }
}

#[test]
fn the_mindlin_modal_mass_includes_the_rotary_inertia() {
    let text = std::fs::read_to_string(BENCH).unwrap();
    let mut config = Config::from_yaml_str(&text, NODE).expect("bench");
    config.plate.theory = PlateTheory::Kirchhoff;
    let kirchhoff = PlateModel::new(&config.plate).expect("kirchhoff");
    config.plate.theory = PlateTheory::Mindlin;
    let mindlin = PlateModel::new(&config.plate).expect("mindlin");
    assert_eq!(mindlin.n_modes(), kirchhoff.n_modes());
    for (i, m) in mindlin.modes().iter().enumerate() {
        let mode = mindlin
            .mindlin_mode(m.radial)
            .expect("a Mindlin mode per radial shape");
        assert_eq!((mode.k, mode.l), (m.k, m.l));
        // The translational m_i = c_k ∫ ρh W² r dr alone is smaller: the rotary part is ρh³/12 c_k ∫ Ψ·Ψ r dr > 0.
        let c_k = if m.k == 0 {
            std::f64::consts::TAU
        } else {
            std::f64::consts::PI
        };
        let (mut translational, mut rotary) = (0.0, 0.0);
        let (ri, ra) = (config.plate.inner_radius, config.plate.outer_radius);
        let n = 4000;
        for j in 0..n {
            let r = ri + (j as f64 + 0.5) / n as f64 * (ra - ri);
            let v = mode.eval(r);
            let dr = (ra - ri) / n as f64;
            translational += v.w * v.w * r * dr;
            rotary += (v.psi_r * v.psi_r + v.psi_theta * v.psi_theta) * r * dr;
        }
        let rho_h = config.plate.density * config.plate.thickness;
        let expected = c_k * (rho_h * translational + rho_h * 0.0181f64.powi(2) / 12.0 * rotary);
        assert!(
            (m.modal_mass - expected).abs() < 1e-5 * expected,
            "mode {i}: modal mass {} against the midpoint integral {expected}",
            m.modal_mass
        );
        assert!(rotary > 0.0);
        let k_e = mindlin.body().modal_stiffness[i];
        assert_eq!(k_e, m.modal_mass * m.omega * m.omega);
        assert!(
            m.omega < kirchhoff.modes()[i].omega,
            "Mindlin below Kirchhoff: mode {i}"
        );
    }
}

/// `stability` takes Mindlin modes with the pads (their face kinematics of ψ,
/// tests/mindlin_pads.rs), with the bench scene's residual flexibility (load
/// patches, docs/residual_flexibility.md) and without it.
#[test]
fn stability_maps_a_mindlin_scene_with_and_without_residual_flexibility() {
    let args = |extra: &'static str| {
        vec![
            "stability",
            BENCH,
            "--mu",
            "0.3:0.4:2",
            "--speeds",
            "10:20:2",
            "-p",
            "plate.theory:=mindlin",
            "-p",
            extra,
        ]
    };
    for residual in [
        "plate.residual_flexibility:=true",
        "plate.residual_flexibility:=false",
    ] {
        let (ok, stdout, stderr) = run(&args(residual));
        assert!(ok, "{residual}: {stderr}");
        assert!(!stdout.is_empty(), "{residual}: no map written");
    }
}

/// Kirchhoff's ⟨2, 0⟩ of the bench disc against the exact Mindlin root: the
/// model error the warning reports. The file ships Mindlin theory, so the
/// Kirchhoff model of its disc is asked for with `-p plate.theory:=kirchhoff`.
#[test]
fn modes_warns_of_the_bench_disc_and_not_of_a_thin_plate() {
    let kirchhoff = ["-p", "plate.theory:=kirchhoff"];
    let (ok, _, stderr) = run(&["modes", BENCH, kirchhoff[0], kirchhoff[1]]);
    assert!(ok, "{stderr}");
    let warning = stderr
        .lines()
        .find(|l| l.starts_with("warning:"))
        .unwrap_or_else(|| panic!("no warning for the 18.1 mm bench disc: {stderr}"));
    assert!(warning.contains("plate.theory"), "{warning}");
    println!("{warning}");

    // The number it states: Kirchhoff / exact Mindlin − 1 for the worst of the lowest three ⟨k, l⟩.
    let text = std::fs::read_to_string(BENCH).unwrap();
    let mut config = Config::from_yaml_str(&text, NODE).expect("bench");
    config.plate.theory = PlateTheory::Kirchhoff;
    let model = PlateModel::new(&config.plate).expect("kirchhoff");
    let worst = model
        .thickness_warning()
        .expect("the check runs")
        .expect("the bench disc warns");
    let exact = bench_disc(Edge::Supported).roots(worst.k, worst.l as usize + 1, 64)
        [worst.l as usize]
        / std::f64::consts::TAU;
    let e_exact = worst.kirchhoff_hz / exact - 1.0;
    assert!(
        (worst.relative_error() - e_exact).abs() < 1e-6,
        "{} against {e_exact}",
        worst.relative_error()
    );
    assert!(e_exact > 0.01, "{e_exact}");
    // Mindlin modes (the file as shipped) and a thin Kirchhoff version of the
    // disc (h = 2 mm, h/b = 0.024) do not warn.
    for overrides in [
        vec!["-p", "plate.theory:=mindlin"],
        vec![],
        vec![kirchhoff[0], kirchhoff[1], "-p", "plate.thickness:=0.002"],
    ] {
        let mut args = vec!["modes", BENCH];
        args.extend(&overrides);
        let (ok, _, stderr) = run(&args);
        assert!(ok, "{stderr}");
        assert!(!stderr.contains("warning"), "{overrides:?}: {stderr}");
    }
    let mut thin = config.plate.clone();
    thin.thickness = 0.002;
    let thin_error = PlateModel::new(&thin)
        .unwrap()
        .kirchhoff_thickness_error()
        .unwrap()
        .expect("a Kirchhoff model is checked");
    println!(
        "h = 2 mm: worst of the lowest three ⟨k, l⟩ {:.3} %",
        100.0 * thin_error.relative_error()
    );
    assert!(thin_error.relative_error() < 0.01);
}
