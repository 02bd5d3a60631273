//! `annular_plate stability`: the squeal scene's documented threshold
//! (0.300423 for config/brake_squeal_paper.yaml at 25 rad/s, docs/scenes.md) from
//! the map, the JSON layout, and shards merged equal to the single run.

mod support;

use serde_json::Value;
use std::path::PathBuf;
use support::cli::run;

const SCENE: &str = concat!(
    env!("CARGO_MANIFEST_DIR"),
    "/config/brake_squeal_paper.yaml"
);

fn dir() -> PathBuf {
    support::cli::scratch_dir("stability")
}

#[test]
fn the_map_reproduces_the_squeal_threshold_at_the_scene_speed() {
    let (ok, out, err) = run(&[
        "stability",
        SCENE,
        "--mu",
        "0:0.6:13",
        "--speeds",
        "25:25:1",
        "--json",
    ]);
    assert!(ok, "{err}");
    let doc: Value = serde_json::from_str(&out).unwrap();
    let mut keys: Vec<&String> = doc.as_object().unwrap().keys().collect();
    keys.sort();
    assert_eq!(
        keys,
        [
            "growth_rate",
            "mode",
            "mu",
            "params_digest",
            "speeds_rad_s",
            "threshold_mu"
        ]
    );
    assert_eq!(doc["speeds_rad_s"], serde_json::json!([25.0]));
    let threshold = doc["threshold_mu"][0].as_f64().unwrap();
    assert!((threshold - 0.300423).abs() < 5e-7, "threshold {threshold}");
    // The library's own threshold search agrees to its bisection tolerance.
    let sim = annular_plate::dynamics::Simulation::new(
        annular_plate::config::Config::from_params_file(SCENE.as_ref(), "annular_plate").unwrap(),
    )
    .unwrap();
    let lib =
        annular_plate::dynamics::stability::friction_threshold(sim.scene(), 25.0, 2.0).unwrap();
    assert!((threshold - lib).abs() < 1e-8 * lib, "{threshold} vs {lib}");
    let rates: Vec<f64> = doc["growth_rate"][0]
        .as_array()
        .unwrap()
        .iter()
        .map(|v| v.as_f64().unwrap())
        .collect();
    assert_eq!(rates.len(), 13);
    // Stable below the threshold (μ = 0.30 is grid point 6), growing above it.
    assert!(
        rates[..7].iter().all(|&r| r <= 0.0) && rates[7..].iter().all(|&r| r > 0.0),
        "{rates:?}"
    );
    // The unstable mode: the scene has k = 1, 2 with l = 0; its frequency is positive.
    let mode = &doc["mode"][0][12];
    assert!(
        matches!(mode["k"].as_u64(), Some(1 | 2))
            && mode["l"] == 0
            && mode["frequency_hz"].as_f64().unwrap() > 0.0,
        "{mode}"
    );
    // The table names the threshold too.
    let (ok, text, _) = run(&[
        "stability",
        SCENE,
        "--mu",
        "0:0.6:13",
        "--speeds",
        "25:25:1",
    ]);
    assert!(ok && text.contains("0.300423"), "{text}");
}

#[test]
fn shards_merged_equal_the_single_run() {
    let grid = ["--mu", "0.2:0.5:7", "--speeds", "5:45:5"];
    let mut args = vec!["stability", SCENE, "--json"];
    args.extend_from_slice(&grid);
    let (ok, single, err) = run(&args);
    assert!(ok, "{err}");
    let mut files = Vec::new();
    for i in [3, 1, 2] {
        let shard = format!("{i}/3");
        let mut args = vec![
            "stability",
            SCENE,
            "--shard",
            shard.as_str(),
            "--threads",
            "1",
        ];
        args.extend_from_slice(&grid);
        let (ok, out, err) = run(&args);
        assert!(ok, "{err}");
        let f = dir().join(format!("shard{i}.json"));
        std::fs::write(&f, out).unwrap();
        files.push(f);
    }
    let mut args = vec!["stability", "merge"];
    args.extend(files.iter().map(|f| f.to_str().unwrap()));
    let (ok, merged, err) = run(&args);
    assert!(ok, "{err}");
    assert_eq!(merged, single, "merged shards differ from the single run");
    // A missing shard is named.
    let (ok, _, err) = run(&[
        "stability",
        "merge",
        files[0].to_str().unwrap(),
        files[1].to_str().unwrap(),
    ]);
    assert!(!ok && err.contains("1..=3"), "{err}");
}

#[test]
fn bad_stability_input_is_named() {
    for (args, needle) in [
        (
            vec!["stability", SCENE, "--mu", "0:1", "--speeds", "25:25:1"],
            "--mu",
        ),
        (
            vec!["stability", SCENE, "--mu", "0:1:3", "--speeds", "25:20:2"],
            "--speeds",
        ),
        (
            vec![
                "stability",
                SCENE,
                "--mu",
                "0:1:3",
                "--speeds",
                "25:25:1",
                "--shard",
                "4/3",
            ],
            "--shard",
        ),
        (
            vec![
                "stability",
                concat!(env!("CARGO_MANIFEST_DIR"), "/config/lathe.yaml"),
                "--mu",
                "0:1:3",
                "--speeds",
                "25:25:1",
            ],
            "no pads",
        ),
    ] {
        let (ok, _, err) = run(&args);
        assert!(!ok && err.contains(needle), "{args:?}: {err}");
    }
}

#[test]
fn the_map_picture_is_red_where_growing_and_blue_where_decaying() {
    use annular_plate::cli::plot::{stability_map, Size, StabilityGrid};
    let out = dir().join("map.png");
    let (ok, json, err) = run(&[
        "stability",
        SCENE,
        "--mu",
        "0:0.6:13",
        "--speeds",
        "5:45:5",
        "--json",
        "--plot",
        out.to_str().unwrap(),
    ]);
    assert!(ok, "{err}");
    let doc: annular_plate::cli::stability::StabilityMap = serde_json::from_str(&json).unwrap();
    let img = image::open(&out).unwrap().to_rgb8();
    assert_eq!(img.dimensions(), (1200, 800));
    let grid = StabilityGrid {
        speeds: &doc.speeds_rad_s,
        mu: &doc.mu,
        growth_rate: &doc.growth_rate,
        threshold_mu: &doc.threshold_mu,
    };
    let again = dir().join("map_again.png");
    let geometry = stability_map(
        &grid,
        &again,
        Size {
            width: 1200,
            height: 800,
        },
    )
    .unwrap();
    assert_eq!(
        std::fs::read(&out).unwrap(),
        std::fs::read(&again).unwrap(),
        "CLI and library draw the same picture"
    );
    assert_eq!(geometry.cells.len(), 5 * 13);
    let (mut red, mut blue) = (0, 0);
    for &(x, y, growing) in &geometry.cells {
        // 6 px below the centre (same cell; clear of the threshold curve and its dots).
        let p = img.get_pixel(x as u32, (y + 6) as u32).0;
        if growing {
            assert!(p[0] > p[2] + 40, "cell at ({x}, {y}) should be red: {p:?}");
            red += 1;
        } else {
            assert!(p[2] > p[0] + 40, "cell at ({x}, {y}) should be blue: {p:?}");
            blue += 1;
        }
    }
    assert_eq!((red, blue), (5 * 6, 5 * 7));
}
