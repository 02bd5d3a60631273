//! `stability merge` joins only the shards of one map: the same effective
//! parameters (the shard's `params_digest`), μ grid and speed grid, each
//! shard well formed, their speeds disjoint and together the whole grid.
//! Anything else is refused naming the shard and the difference, with exit
//! ≠ 0; an endless or huge input is refused after a bounded read.

mod support;

use serde_json::Value;
use std::io::Write;
use std::path::PathBuf;
use std::time::Duration;
use support::bounded_run::run_bounded;

const SCENE: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/config/brake_squeal.yaml");
const GRID: [&str; 4] = ["--mu", "0.2:0.5:3", "--speeds", "5:45:4"];

fn dir() -> PathBuf {
    support::cli::scratch_dir("merge")
}

fn shard(i: usize, n: usize, extra: &[&str]) -> Value {
    let s = format!("{i}/{n}");
    let mut args = vec!["stability", SCENE, "--shard", s.as_str(), "--threads", "1"];
    args.extend_from_slice(&GRID);
    args.extend_from_slice(extra);
    let r = run_bounded(&args, Duration::from_secs(60), None);
    assert_eq!(r.code, Some(0), "{r:?}");
    serde_json::from_str(&r.stdout).unwrap()
}

fn write(name: &str, doc: &Value) -> String {
    let p = dir().join(name);
    std::fs::write(&p, serde_json::to_string_pretty(doc).unwrap()).unwrap();
    p.to_str().unwrap().to_string()
}

fn merge(files: &[&str]) -> support::bounded_run::Bounded {
    let mut args = vec!["stability", "merge"];
    args.extend_from_slice(files);
    run_bounded(&args, Duration::from_secs(30), None)
}

fn refused(files: &[&str], needles: &[&str]) {
    let r = merge(files);
    assert_eq!(r.code, Some(1), "{files:?}: {r:?}");
    for n in needles {
        assert!(r.stderr.contains(n), "`{n}` not in: {}", r.stderr);
    }
}

#[test]
fn shards_of_one_map_merge_and_others_are_refused_naming_the_shard() {
    let (a, b) = (shard(1, 2, &[]), shard(2, 2, &[]));
    let (fa, fb) = (write("a.json", &a), write("b.json", &b));
    let ok = merge(&[&fb, &fa]);
    assert_eq!(ok.code, Some(0), "{ok:?}");
    let merged: Value = serde_json::from_str(&ok.stdout).unwrap();
    assert_eq!(merged["speeds_rad_s"].as_array().unwrap().len(), 4);

    // Computed with another -p: the digest differs.
    let other = write(
        "other.json",
        &shard(2, 2, &["-p", "pads.contact_damping:=1.0"]),
    );
    refused(
        &[&fa, &other],
        &["other.json", "other parameters", "digest"],
    );

    // growth_rate with fewer rows than speeds.
    let mut short = b.clone();
    short["growth_rate"].as_array_mut().unwrap().pop();
    refused(
        &[&fa, &write("short.json", &short)],
        &["short.json", "malformed", "growth_rate rows"],
    );

    // Speeds edited to [1e308, -5].
    let mut edited = b.clone();
    edited["speeds_rad_s"] = serde_json::json!([1e308, -5.0]);
    refused(
        &[&fa, &write("edited.json", &edited)],
        &["edited.json", "not rows 3..4"],
    );

    // The same shard twice (overlapping speeds) and a shard of another μ grid.
    refused(&[&fa, &fa], &["needed once each"]);
    let mut mu = b.clone();
    mu["mu"] = serde_json::json!([0.2, 0.3, 0.4]);
    refused(&[&fa, &write("mu.json", &mu)], &["mu.json", "μ grid"]);

    // A shard of another speed grid with the same count.
    let mut grid = b.clone();
    grid["shard"]["speeds_to"] = serde_json::json!(50.0);
    refused(
        &[&fa, &write("grid.json", &grid)],
        &["grid.json", "--speeds"],
    );

    // A huge shard count is refused without allocating for it.
    let mut count = b.clone();
    count["shard"]["count"] = serde_json::json!(u64::MAX);
    refused(&[&fa, &write("count.json", &count)], &["count.json"]);
}

#[test]
fn an_endless_input_is_refused_after_a_bounded_read() {
    // /dev/zero: not JSON, refused at its first byte.
    let r = merge(&["/dev/zero"]);
    assert_eq!(r.code, Some(1), "{r:?}");
    assert!(
        r.stderr.contains("/dev/zero")
            && r.elapsed < Duration::from_secs(10)
            && r.peak_kib < 100_000,
        "{r:?}"
    );
    // Endless whitespace on a pipe: read up to the shard limit, then refused.
    let feed: Box<dyn FnOnce(std::process::ChildStdin) + Send> = Box::new(|mut pipe| {
        let block = vec![b' '; 1 << 16];
        while pipe.write_all(&block).is_ok() {}
    });
    let r = run_bounded(
        &["stability", "merge", "/dev/stdin"],
        Duration::from_secs(60),
        Some(feed),
    );
    assert_eq!(r.code, Some(1), "{r:?}");
    assert!(
        r.stderr.contains("more than 268435456 bytes"),
        "{}",
        r.stderr
    );
    assert!(
        r.peak_kib < 100_000,
        "peak {} KiB reading an endless input",
        r.peak_kib
    );
}
