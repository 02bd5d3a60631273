//! The scene files of `config/`, as the scene tests read, break and run them.
#![allow(dead_code)]

use annular_plate::config::{Config, ConfigError};
use annular_plate::dynamics::Simulation;
use std::path::{Path, PathBuf};

/// The node entry the scene files are read for.
pub const NODE: &str = "annular_plate";

pub fn path(file: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("config")
        .join(file)
}

pub fn text(file: &str) -> String {
    std::fs::read_to_string(path(file)).unwrap()
}

pub fn load(file: &str) -> Config {
    Config::from_params_file(&path(file), NODE)
        .unwrap_or_else(|e| panic!("config/{file} is valid: {e}"))
}

/// The scene file with `from` replaced by `to`; must be rejected naming `key`.
#[track_caller]
pub fn rejected(file: &str, from: &str, to: &str, key: &str) -> ConfigError {
    let text = text(file);
    assert!(text.contains(from), "config/{file} has no `{from}`");
    let e = Config::from_yaml_str(&text.replacen(from, to, 1), NODE)
        .expect_err("a bad scene file was accepted");
    assert!(
        e.to_string().contains(key),
        "the message does not name {key}: {e}"
    );
    e
}

/// `annular_plate simulate config/<file> --duration S --csv -`: the CSV text.
pub fn simulate_csv(file: &str, duration: f64) -> String {
    let (ok, out, err) = super::cli::run(&[
        "simulate",
        path(file).to_str().unwrap(),
        "--duration",
        &duration.to_string(),
        "--csv",
        "-",
        "--quiet",
    ]);
    assert!(ok, "{err}");
    out
}

/// Step until `t` (s).
pub fn run_to(sim: &mut Simulation, t: f64) {
    while sim.time() < t - 0.5 * sim.dt() {
        sim.step().unwrap();
    }
}
