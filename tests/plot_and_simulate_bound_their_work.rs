//! `plot animate` bounds its work before doing it: a long CSV costs its
//! reading and the frames', not a grid evaluation per row; more frames than
//! `--max-frames` are refused at once with the estimate; the estimate is
//! printed before rendering unless `--quiet`. `simulate --csv -` with
//! stdout closed fails instead of exiting 0 having written nothing.

mod support;

use std::io::Write;
use std::time::Duration;
use support::bounded_run::{run_bounded, BIN};

const SCENE: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/config/design_example.yaml");

/// A CSV of the design example's columns with `rows` rows, 1 ms apart, at rest.
fn long_csv(name: &str, rows: usize) -> std::path::PathBuf {
    let dir =
        std::env::temp_dir().join(format!("annular_plate_plot_bounds_{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let small = dir.join(format!("{name}_small.csv"));
    let r = run_bounded(
        &[
            "simulate",
            SCENE,
            "--duration",
            "0.002",
            "--csv",
            small.to_str().unwrap(),
            "--quiet",
        ],
        Duration::from_secs(60),
        None,
    );
    assert_eq!(r.code, Some(0), "{r:?}");
    let header = std::fs::read_to_string(&small)
        .unwrap()
        .lines()
        .next()
        .unwrap()
        .to_string();
    let zeros = vec!["0"; header.split(',').count() - 2].join(",");
    let path = dir.join(format!("{name}_{rows}.csv"));
    let mut f = std::io::BufWriter::new(std::fs::File::create(&path).unwrap());
    writeln!(f, "{header}").unwrap();
    for i in 0..rows {
        writeln!(f, "{},{},{zeros}", i as f64 * 1e-3, i as f64 * 1e-2).unwrap();
    }
    f.flush().unwrap();
    path
}

#[test]
fn too_many_frames_are_refused_at_once_with_the_estimate() {
    let csv = long_csv("refused", 200_000);
    let out = csv.with_extension("gif");
    // 200 s × 25 fps = 5000 frames > --max-frames 1000.
    let r = run_bounded(
        &[
            "plot",
            "animate",
            csv.to_str().unwrap(),
            "--params",
            SCENE,
            "--out",
            out.to_str().unwrap(),
            "--quiet",
            "--max-frames",
            "1000",
        ],
        Duration::from_secs(60),
        None,
    );
    assert_eq!(r.code, Some(1), "{r:?}");
    assert!(
        r.stderr.contains("5000 frames")
            && r.stderr.contains("--max-frames 1000")
            && r.stderr.contains("s of rendering"),
        "{}",
        r.stderr
    );
    assert!(r.elapsed < Duration::from_secs(20), "{:?}", r.elapsed);
    assert!(!out.exists(), "nothing rendered");
}

#[test]
fn a_long_csv_costs_its_frames_not_its_rows_and_the_estimate_comes_first() {
    let csv = long_csv("rendered", 200_000);
    let out = csv.with_extension("gif");
    // 200 s × 0.01 × 25 fps = 50 frames of 200,000 rows.
    let r = run_bounded(
        &[
            "plot",
            "animate",
            csv.to_str().unwrap(),
            "--params",
            SCENE,
            "--out",
            out.to_str().unwrap(),
            "--slowdown",
            "0.01",
            "--size",
            "320x160",
        ],
        Duration::from_secs(120),
        None,
    );
    assert_eq!(r.code, Some(0), "{r:?}");
    assert!(
        r.stderr.contains("50 frames from 200000 rows, about"),
        "{}",
        r.stderr
    );
    assert!(r.elapsed < Duration::from_secs(60), "{:?}", r.elapsed);
}

#[test]
fn simulate_to_a_closed_stdout_fails() {
    let status = std::process::Command::new("sh")
        .args([
            "-c",
            "exec \"$0\" simulate \"$1\" --duration 0.01 --csv - --quiet >&-",
            BIN,
            SCENE,
        ])
        .stderr(std::process::Stdio::piped())
        .output()
        .unwrap();
    assert!(!status.status.success(), "exit 0 with stdout closed");
    assert!(
        String::from_utf8_lossy(&status.stderr).contains("stdout is closed"),
        "{}",
        String::from_utf8_lossy(&status.stderr)
    );
    // Redirected to /dev/null on purpose: written, exit 0.
    let status = std::process::Command::new("sh")
        .args([
            "-c",
            "exec \"$0\" simulate \"$1\" --duration 0.01 --csv - --quiet >/dev/null",
            BIN,
            SCENE,
        ])
        .status()
        .unwrap();
    assert!(status.success());
}
