//! The command-line contract of DESIGN.md: `modes FILE [--json]` and
//! `simulate FILE --duration S --csv OUT`, and clear errors on bad input.

mod support;

use annular_plate::config::Config;
use annular_plate::dynamics::Simulation;
use std::process::Command;
use support::cli::{run, BIN};

fn write_params(name: &str, body: &str) -> std::path::PathBuf {
    let p = support::cli::scratch_dir("cli").join(name);
    std::fs::write(&p, body).unwrap();
    p
}

const LATHE: &str = "annular_plate:\n  ros__parameters:\n    plate:\n      density: 7800.0\n      nodal_diameters: [0, 1, 2, 3, 4, 5]\n      nodal_circles: [0]\n";

#[test]
fn modes_json_lists_the_paper_table_1_disc_sorted_with_pairs() {
    let f = write_params("t1.yaml", LATHE);
    let (ok, out, err) = run(&["modes", f.to_str().unwrap(), "--json"]);
    assert!(ok, "{err}");
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    let modes = v["modes"].as_array().unwrap();
    assert_eq!(modes.len(), 11);
    let f_hz: Vec<f64> = modes
        .iter()
        .map(|m| m["frequency_hz"].as_f64().unwrap())
        .collect();
    assert!(f_hz.windows(2).all(|w| w[0] <= w[1]), "sorted by frequency");
    // Paper Table 1 (Modelica / Ansys): 1449/1451, 1478/1480 ×2, 1635/1637 ×2, …
    let expected = [
        1449.0, 1478.0, 1478.0, 1635.0, 1635.0, 2064.0, 2064.0, 2847.0, 2847.0, 3974.0,
    ];
    for (got, want) in f_hz.iter().zip(expected) {
        assert!((got - want).abs() / want < 3e-3, "{got} vs {want}");
    }
    assert_eq!(modes[0]["shape"], "axisymmetric");
    assert_eq!(
        (modes[1]["k"].as_u64(), modes[1]["shape"].as_str()),
        (Some(1), Some("cos"))
    );
    assert_eq!(
        (modes[2]["k"].as_u64(), modes[2]["shape"].as_str()),
        (Some(1), Some("sin"))
    );
    assert_eq!(modes[1]["frequency_hz"], modes[2]["frequency_hz"]);
    assert!(modes.iter().all(|m| m["l"].as_u64() == Some(0)));
}

#[test]
fn modes_table_is_readable() {
    let f = write_params("t2.yaml", LATHE);
    let (ok, text, err) = run(&["modes", f.to_str().unwrap()]);
    assert!(ok, "{err}");
    assert!(
        text.contains("index") && text.contains("frequency_Hz") && text.contains("modal_mass_kg"),
        "{text}"
    );
    assert_eq!(
        text.lines()
            .filter(|l| l.trim_start().starts_with(char::is_numeric))
            .count(),
        11
    );
}

#[test]
fn bad_input_gives_a_message_naming_the_key_and_a_non_zero_exit() {
    for (body, needle) in [
        ("annular_plate:\n  ros__parameters:\n    plate:\n      inner_radius: 0.2\n", "plate.inner_radius"),
        ("annular_plate:\n  ros__parameters:\n    plate:\n      thicknes: 0.01\n", "plate.thicknes"),
        ("annular_plate:\n  ros__parameters:\n    plate:\n      inner_boundary: glued\n", "plate.inner_boundary"),
        ("annular_plate:\n  ros__parameters:\n    plate:\n      poisson_ratio: 0.5\n", "poisson"),
        ("annular_plate:\n  ros__parameters:\n    nodes:\n      ale_radial: [1.2]\n      ale_angular: [0.0]\n", "nodes.ale_radial"),
    ] {
        let f = write_params("bad.yaml", body);
        for sub in [&["modes"][..], &["simulate", "--duration", "0.01", "--csv", "/dev/null", "--quiet"][..]] {
            let mut args: Vec<&str> = vec![sub[0], f.to_str().unwrap()];
            args.extend_from_slice(&sub[1..]);
            let (ok, out, err) = run(&args);
            assert!(!ok, "{body} accepted");
            assert!(err.contains(needle), "stderr for {body} lacks {needle}: {err}");
            assert!(!out.contains("NaN"));
        }
    }
    let (ok, _, err) = run(&["modes", "/nonexistent/params.yaml"]);
    assert!(!ok && err.contains("/nonexistent/params.yaml"), "{err}");
}

#[test]
fn simulate_writes_the_contract_columns_one_row_per_step_matching_the_library() {
    let body = "annular_plate:\n  ros__parameters:\n    plate:\n      nodal_diameters: [0, 1, 2]\n      nodal_circles: [0]\n      damping: [0.02]\n    nodes:\n      ale_radial: [1.0, 0.5]\n      ale_angular: [0.0, 0.5]\n      lagrange_radial: [1.0]\n      lagrange_angular: [0.25]\n    loads:\n      ale_wrench: [0.0, 0.0, -100.0, 0.0, 0.0, 0.0, 0.0, 20.0, 0.0, 0.0, 0.0, 0.0]\n      lagrange_wrench: [0.0, 0.0, 50.0, 0.0, 0.0, 0.0]\n    joint:\n      speed: 11.1\n    simulation:\n      rate_hz: 2000.0\n";
    let f = write_params("sim.yaml", body);
    let csv = f.with_extension("csv");
    let (ok, _, err) = run(&[
        "simulate",
        f.to_str().unwrap(),
        "--duration",
        "0.05",
        "--csv",
        csv.to_str().unwrap(),
        "--quiet",
    ]);
    assert!(ok, "{err}");
    let text = std::fs::read_to_string(&csv).unwrap();
    let mut lines = text.lines();
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    let n = 5;
    let mut expected = vec!["time", "joint_position", "joint_velocity"];
    let names: Vec<String> = (1..=n)
        .map(|i| format!("q{i}"))
        .chain((1..=n).map(|i| format!("qale{i}")))
        .chain(["ale1_uz".into(), "ale2_uz".into(), "lagrange1_uz".into()])
        .collect();
    expected.extend(names.iter().map(|s| s.as_str()));
    assert_eq!(header, expected);
    let rows: Vec<Vec<f64>> = lines
        .map(|l| l.split(',').map(|v| v.parse().unwrap()).collect())
        .collect();
    assert_eq!(rows.len(), 101, "t = 0 plus 100 steps");
    assert!(rows.iter().flatten().all(|v| v.is_finite()));
    // Same numbers as the library in-process.
    let config = Config::from_params_file(&f, "annular_plate").unwrap();
    let mut sim = Simulation::new(config).unwrap();
    for row in rows.iter().skip(1) {
        sim.step().unwrap();
        assert!((row[0] - sim.time()).abs() < 1e-12);
        assert_eq!(row[1], sim.joint().position);
        assert_eq!(row[3..3 + n], sim.q_lagrange()[..]);
        assert_eq!(row[3 + n..3 + 2 * n], sim.q_ale()[..]);
        assert_eq!(row[3 + 2 * n], sim.ale_node(0).uz);
        assert_eq!(row[3 + 2 * n + 2], sim.lagrange_node(0).uz);
    }
}

/// `simulate` with these arguments: (status success, stdout, stderr).
fn simulate_args(args: &[&str]) -> (bool, String, String) {
    let scene = concat!(env!("CARGO_MANIFEST_DIR"), "/config/lathe.yaml");
    let all: Vec<&str> = ["simulate", scene]
        .into_iter()
        .chain(args.iter().copied())
        .collect();
    run(&all)
}

#[test]
fn a_negative_or_sub_step_duration_is_refused_naming_the_rule() {
    let (ok, _, err) = simulate_args(&["--duration", "-1", "--csv", "-"]);
    assert!(
        !ok && err.contains("--duration must be a finite number ≥ 0 s, got -1"),
        "{err}"
    );
    let (ok, _, err) = simulate_args(&["--duration", "0.0004", "--csv", "-"]);
    assert!(
        !ok && err.contains("shorter than one step") && err.contains("0.001 s"),
        "{err}"
    );
    // Zero is the initial state alone; one step is one step.
    let (ok, out, _) = simulate_args(&["--duration", "0", "--csv", "-", "--quiet"]);
    assert!(ok && out.lines().count() == 2, "{out}");
    let (ok, out, _) = simulate_args(&["--duration", "0.001", "--csv", "-", "--quiet"]);
    assert!(ok && out.lines().count() == 3, "{out}");
}

#[test]
fn a_closed_output_pipe_ends_simulate_quietly() {
    use std::io::Read;
    let scene = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("config/lathe.yaml");
    let mut child = Command::new(BIN)
        .arg("simulate")
        .arg(&scene)
        .args(["--duration", "50", "--csv", "-", "--quiet"])
        .stdout(std::process::Stdio::piped())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .unwrap();
    // Read the header and close the pipe, as `| head -1` does.
    let mut first = [0u8; 16];
    child.stdout.take().unwrap().read_exact(&mut first).unwrap();
    let out = child.wait_with_output().unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success(), "exit status {:?}: {err}", out.status);
    assert!(
        !err.contains("Broken pipe") && !err.contains("error"),
        "{err}"
    );
    assert_eq!(&first[..5], b"time,");
}

#[test]
fn output_rate_rows_are_the_every_step_rows_at_those_times_and_a_rate_that_does_not_divide_is_refused(
) {
    let (ok, full, err) = simulate_args(&["--duration", "0.3", "--csv", "-", "--quiet"]);
    assert!(ok, "{err}");
    let (ok, decimated, err) = simulate_args(&[
        "--duration",
        "0.3",
        "--csv",
        "-",
        "--quiet",
        "--output-rate",
        "100",
    ]);
    assert!(ok, "{err}");
    let full: Vec<&str> = full.lines().collect();
    let decimated: Vec<&str> = decimated.lines().collect();
    // Header, t = 0, then every 10th step of the 1 kHz scene: byte-identical rows.
    let expected: Vec<&str> = std::iter::once(full[0])
        .chain(full[1..].iter().step_by(10).copied())
        .collect();
    assert_eq!(decimated.len(), 2 + 30, "{} rows", decimated.len());
    assert_eq!(decimated, expected);
    assert!(decimated[2].starts_with("0.01,"), "{}", decimated[2]);

    // The bag at the same rate: one message per written row on the per-step topics.
    let dir =
        std::env::temp_dir().join(format!("annular_plate_output_rate_{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    let (ok, _, err) = simulate_args(&[
        "--duration",
        "0.3",
        "--bag",
        dir.to_str().unwrap(),
        "--quiet",
        "--output-rate",
        "100",
    ]);
    assert!(ok, "{err}");
    let mcap = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .find(|p| p.extension().is_some_and(|e| e == "mcap"))
        .unwrap();
    let bytes = std::fs::read(mcap).unwrap();
    let clocks: Vec<u64> = mcap::MessageStream::new(&bytes)
        .unwrap()
        .map(|m| m.unwrap())
        .filter(|m| m.channel.topic == "/clock")
        .map(|m| m.log_time)
        .collect();
    std::fs::remove_dir_all(&dir).unwrap();
    assert_eq!(
        clocks,
        (0..=30).map(|i| i * 10_000_000).collect::<Vec<u64>>(),
        "/clock every 10 ms from 0"
    );

    for bad in ["300", "0", "-5", "2000"] {
        let (ok, _, err) =
            simulate_args(&["--duration", "0.1", "--csv", "-", "--output-rate", bad]);
        assert!(
            !ok && err.contains(&format!(
                "--output-rate {bad} Hz does not divide simulation.rate_hz = 1000 Hz"
            )),
            "{bad}: {err}"
        );
    }
}
