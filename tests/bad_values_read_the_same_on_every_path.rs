//! One check for every value (`config::check`): the same bad value given by
//! the scene file, a `--params-file`, `-p`, the CLI's reading of a scene
//! (`Config::from_params_file`), the node's settings (`RosSettings`) and —
//! for the keys that may change at run time — `set_parameters` is refused
//! with the same text, which names the key and the rule.

#![cfg(feature = "ros")]

mod support;

use annular_plate::config::{Config, ParamValue, Params};
use annular_plate::dynamics::load_models::PARAMETERS;
use annular_plate::messages::settings::RosSettings;
use annular_plate::ros::params_service::{effective_parameters, ParamStore, RUNTIME_KEYS};
use annular_plate::ros::NodeSetup;
use ros2_client::parameters::raw;
use ros2_client::ParameterValue as RosValue;
use std::path::{Path, PathBuf};

const BENCH: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/config/brake_bench.yaml");

struct Case {
    key: &'static str,
    /// As a parameter file and `-p` write it.
    text: &'static str,
    /// As `ros2 param set` sends it.
    value: ParamValue,
    /// What the refusal must say besides the key (the rule).
    rule: &'static str,
}

fn cases() -> Vec<Case> {
    let c = |key, text, value, rule| Case {
        key,
        text,
        value,
        rule,
    };
    use ParamValue::*;
    vec![
        c(
            "simulation.realtime_factor",
            "1.0e-30",
            Double(1e-30),
            "0 or in [1e-6, 1e6]",
        ),
        c(
            "simulation.realtime_factor",
            "fast",
            String("fast".into()),
            "must be a double",
        ),
        c(
            "simulation.realtime_factor",
            ".inf",
            Double(f64::INFINITY),
            "finite",
        ),
        c(
            "ros.wrench_timeout",
            "-1.0",
            Double(-1.0),
            "must not be negative",
        ),
        c("ros.wrench_timeout", "true", Bool(true), "must be a double"),
        c(
            "ros.max_clock_jump",
            "0.0",
            Double(0.0),
            "greater than zero",
        ),
        c("ros.max_clock_jump", "2.0e9", Double(2e9), "1e9"),
        c("ros.marker_rings", "0", Integer(0), "greater than zero"),
        c("ros.marker_sectors", "5000", Integer(5000), "4096"),
        c("ros.marker_rings", "2.5", Double(2.5), "must be an integer"),
        c("ros.diagnostics_period", ".nan", Double(f64::NAN), "finite"),
        c(
            "plate.thickness",
            "-0.01",
            Double(-0.01),
            "greater than zero",
        ),
        c(
            "simulation.substeps",
            "1.5",
            Double(1.5),
            "must be an integer",
        ),
        c("simulation.rate_hz", "2.0e6", Double(2e6), "1e6"),
    ]
}

fn dir() -> PathBuf {
    support::cli::scratch_dir("same_refusal")
}

/// A parameter file holding `key: text` for every node: as a scene (the
/// defaults and this key) and as a `--params-file` over the brake bench.
fn params_file(dir: &Path, n: usize, key: &str, text: &str) -> PathBuf {
    let p = dir.join(format!("bad_{n}.yaml"));
    std::fs::write(&p, format!("/**:\n  ros__parameters:\n    {key}: {text}\n")).unwrap();
    p
}

fn ros_args(list: &[&str]) -> Vec<std::string::String> {
    std::iter::once("--ros-args")
        .chain(list.iter().copied())
        .map(str::to_string)
        .collect()
}

fn refusal(what: &str, r: Result<impl Sized, impl std::fmt::Display>) -> std::string::String {
    match r {
        Ok(_) => panic!("{what}: accepted"),
        Err(e) => e.to_string(),
    }
}

#[test]
fn the_same_bad_value_is_refused_with_the_same_text_on_every_path() {
    let dir = dir();
    let bench = Params::from_file(Path::new(BENCH), "/annular_plate").unwrap();
    let settings = RosSettings::from_params(&bench).unwrap();
    for (n, case) in cases().into_iter().enumerate() {
        let Case {
            key,
            text,
            value,
            rule,
        } = case;
        // The one check's text: names the key and the rule.
        let expected = PARAMETERS.check(key, &value).expect_err(key).to_string();
        assert!(
            expected.contains(key) && expected.contains(rule),
            "{key} = {text}: `{expected}` does not name the key and `{rule}`"
        );
        let what = |path: &str| format!("{key} = {text} by {path}");
        let file = params_file(&dir, n, key, text);
        let scene = &file;
        let mut paths = vec![
            (
                "the scene file",
                refusal(&what("scene"), NodeSetup::load(Some(scene), &ros_args(&[]))),
            ),
            (
                "--params-file",
                refusal(
                    &what("--params-file"),
                    NodeSetup::load(
                        Some(Path::new(BENCH)),
                        &ros_args(&["--params-file", file.to_str().unwrap()]),
                    ),
                ),
            ),
            (
                "-p",
                refusal(
                    &what("-p"),
                    NodeSetup::load(
                        Some(Path::new(BENCH)),
                        &ros_args(&["-p", &format!("{key}:={text}")]),
                    ),
                ),
            ),
            (
                "modes/simulate (Config::from_params_file)",
                refusal(
                    &what("Config"),
                    Config::from_params_file(scene, "/annular_plate"),
                ),
            ),
        ];
        if key.starts_with("ros.") {
            let mut given = bench.clone();
            given.set(key, value.clone()).unwrap();
            paths.push((
                "RosSettings",
                refusal(&what("RosSettings"), RosSettings::from_params(&given)),
            ));
        }
        if RUNTIME_KEYS.iter().any(|(k, _)| *k == key) {
            let mut store = ParamStore::new(effective_parameters(&bench, &settings));
            let ros_value = match value.clone() {
                ParamValue::Double(x) => RosValue::Double(x),
                ParamValue::Integer(i) => RosValue::Integer(i),
                ParamValue::Bool(b) => RosValue::Boolean(b),
                ParamValue::String(s) => RosValue::String(s),
                other => panic!("no case sends {other:?}"),
            };
            let (results, changes) = store.set(vec![raw::Parameter {
                name: key.into(),
                value: ros_value.into(),
            }]);
            assert!(
                !results[0].successful && changes.is_empty(),
                "{}",
                what("set_parameters")
            );
            paths.push(("set_parameters", results[0].reason.clone()));
        }
        for (path, text_seen) in &paths {
            assert!(
                text_seen.contains(&expected),
                "{key} = {text} by {path}: `{text_seen}` is not the check's `{expected}`"
            );
        }
        // Before it at most the file that gave the value, not the key again.
        for (path, text_seen) in &paths {
            let prefix = &text_seen[..text_seen.find(&expected).unwrap()];
            assert!(
                (prefix.is_empty() || prefix.ends_with(": ")) && !prefix.contains(key),
                "{key} by {path}: `{text_seen}`"
            );
        }
    }
}

#[test]
fn an_integer_is_not_a_double_by_the_service_and_a_double_is_not_an_integer_anywhere() {
    // rclcpp's rule for typed values: set_parameters with an integer for a
    // double key is refused; a file or `-p` spells numbers as text, and an
    // integer literal for a double key is that double.
    let bench = Params::from_file(Path::new(BENCH), "/annular_plate").unwrap();
    let settings = RosSettings::from_params(&bench).unwrap();
    let mut store = ParamStore::new(effective_parameters(&bench, &settings));
    let (results, _) = store.set(vec![raw::Parameter {
        name: "simulation.realtime_factor".into(),
        value: RosValue::Integer(2).into(),
    }]);
    assert!(!results[0].successful);
    assert_eq!(
        results[0].reason,
        PARAMETERS
            .check("simulation.realtime_factor", &ParamValue::Integer(2))
            .unwrap_err()
            .to_string()
    );
    assert!(
        results[0].reason.contains("must be a double"),
        "{}",
        results[0].reason
    );
    let s = NodeSetup::load(
        Some(Path::new(BENCH)),
        &ros_args(&["-p", "simulation.realtime_factor:=2"]),
    )
    .unwrap();
    assert_eq!(s.config.simulation.realtime_factor, 2.0);
}
