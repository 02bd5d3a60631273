//! Command-line front ends: `modes` and `simulate` (the node is `ros::run_node`).

pub mod campbell;
pub mod error;
pub(crate) mod float_text;
pub mod modes;
pub mod plot;
pub mod record;
pub mod simulate;
pub mod stability;
pub mod study;

use self::error::{CliError, CliResult};
use crate::config::{Config, Params};
use std::path::Path;

/// Node name whose entry the CLI reads from a params file (and `/**`).
pub(crate) const DEFAULT_NODE_NAME: &str = "annular_plate";

/// Read and validate a params file, printing the geometry notes of paper 4.2 to stderr.
pub fn load_config(path: &Path) -> CliResult<Config> {
    let config = Config::from_params_file(path, DEFAULT_NODE_NAME)
        .map_err(|e| CliError::Usage(format!("{}: {e}", path.display())))?;
    for note in config.plate.geometry_notes() {
        eprintln!("note: {note}");
    }
    Ok(config)
}

/// The parameters of a params file with `-p NAME:=VALUE` overrides (as after
/// `--ros-args`) applied; each override names itself in an error.
pub(crate) fn params_with_overrides(path: &Path, overrides: &[String]) -> CliResult<Params> {
    let mut params = Params::from_file(path, DEFAULT_NODE_NAME)
        .map_err(|e| CliError::Usage(format!("{}: {e}", path.display())))?;
    for o in overrides {
        let (name, value) = o
            .split_once(":=")
            .ok_or_else(|| CliError::Usage(format!("-p {o:?}: expected NAME:=VALUE")))?;
        params
            .set_override(name.trim(), value.trim())
            .map_err(|e| CliError::Usage(format!("-p {o}: {e}")))?;
    }
    Ok(params)
}

/// [`load_config`] with `-p NAME:=VALUE` overrides (`modes`, `simulate`, `study`, `plot`).
pub fn load_config_with(path: &Path, overrides: &[String]) -> CliResult<Config> {
    if overrides.is_empty() {
        return load_config(path);
    }
    let params = params_with_overrides(path, overrides)?;
    let config = Config::from_params(&params)
        .map_err(|e| CliError::Usage(format!("{} (with -p overrides): {e}", path.display())))?;
    for note in config.plate.geometry_notes() {
        eprintln!("note: {note}");
    }
    Ok(config)
}
