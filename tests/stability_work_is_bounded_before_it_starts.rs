//! `stability` and `campbell` bound their work before doing it: speeds
//! within the scene's `limits.max_speed`, μ within its rule, the grid's
//! cells (μ × speeds) within `--max-cells` with an estimate of time and
//! memory in the refusal, shards that cannot be empty, a bounded thread
//! count. Each refusal is immediate, names the flag and exits non-zero.

mod support;

use std::time::Duration;
use support::bounded_run::run_bounded;

const SCENE: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/config/brake_squeal.yaml");

fn refused(args: &[&str], needles: &[&str]) {
    let r = run_bounded(args, Duration::from_secs(20), None);
    assert_eq!(r.code, Some(1), "{args:?}: {r:?}");
    for n in needles {
        assert!(r.stderr.contains(n), "{args:?}: `{n}` not in: {}", r.stderr);
    }
    assert!(!r.stderr.contains("panicked"), "{}", r.stderr);
    assert!(
        r.elapsed < Duration::from_secs(10) && r.peak_kib < 200_000,
        "{args:?}: {:?}, {} KiB",
        r.elapsed,
        r.peak_kib
    );
}

#[test]
fn speeds_beyond_the_scene_limit_are_refused_not_decomposed() {
    refused(
        &[
            "stability",
            SCENE,
            "--mu",
            "0:1:3",
            "--speeds",
            "1e300:1e301:2",
        ],
        &["--speeds", "limits.max_speed"],
    );
    refused(
        &["campbell", SCENE, "--speeds", "0:1e308:3"],
        &["--speeds", "limits.max_speed"],
    );
    // limits.max_speed itself is capped, so the bound cannot be lifted to where the eigensolver fails.
    refused(
        &[
            "stability",
            SCENE,
            "--mu",
            "0:1:3",
            "--speeds",
            "1e300:1e301:2",
            "-p",
            "limits.max_speed:=1e301",
        ],
        &["limits.max_speed"],
    );
}

#[test]
fn a_grid_of_too_many_cells_is_refused_with_its_estimate() {
    refused(
        &[
            "stability",
            SCENE,
            "--mu",
            "0.1:0.5:100000",
            "--speeds",
            "10:20:100000",
        ],
        &["--max-cells", "10000000000 cells", "GB"],
    );
    refused(
        &[
            "stability",
            SCENE,
            "--mu",
            "0.1:0.5:1000",
            "--speeds",
            "10:20:10000",
        ],
        &["--max-cells", "10000000 cells"],
    );
    refused(
        &[
            "stability",
            SCENE,
            "--mu",
            "0.1:0.5:10",
            "--speeds",
            "10:20:10",
            "--max-cells",
            "99",
        ],
        &["--max-cells", "100 cells"],
    );
}

#[test]
fn shards_threads_and_mu_are_bounded() {
    refused(
        &[
            "stability",
            SCENE,
            "--mu",
            "0:1:3",
            "--speeds",
            "10:20:4",
            "--shard",
            "1/100",
        ],
        &["--shard 1/100", "n ≤ 4"],
    );
    refused(
        &[
            "stability",
            SCENE,
            "--mu",
            "0:1:3",
            "--speeds",
            "10:20:4",
            "--threads",
            "100000",
        ],
        &["--threads"],
    );
    refused(
        &["stability", SCENE, "--mu", "0:3:3", "--speeds", "10:20:4"],
        &["--mu", "pads.friction_coefficient"],
    );
}

#[test]
fn a_grid_within_the_limits_still_runs() {
    let r = run_bounded(
        &[
            "stability",
            SCENE,
            "--mu",
            "0:1:5",
            "--speeds",
            "10:500:4",
            "--json",
        ],
        Duration::from_secs(60),
        None,
    );
    assert_eq!(r.code, Some(0), "{r:?}");
    let doc: serde_json::Value = serde_json::from_str(&r.stdout).unwrap();
    assert_eq!(doc["growth_rate"].as_array().unwrap().len(), 4);
    assert_eq!(doc["params_digest"].as_str().unwrap().len(), 16);
}
