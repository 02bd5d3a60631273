//! Command-line front ends: `modes` and `simulate` (the node is `ros::run_node`).

pub mod campbell;
pub mod error;
pub mod modes;
pub mod plot;
pub mod record;
pub mod simulate;
pub mod stability;
pub mod study;

use self::error::{CliError, CliResult};
use crate::config::Config;
use std::path::Path;

/// Node name whose entry the CLI reads from a params file (and `/**`).
pub const DEFAULT_NODE_NAME: &str = "annular_plate";

/// Read and validate a params file, printing the geometry notes of paper 4.2 to stderr.
pub fn load_config(path: &Path) -> CliResult<Config> {
    let config = Config::from_params_file(path, DEFAULT_NODE_NAME).map_err(|e| CliError::Usage(format!("{}: {e}", path.display())))?;
    for note in config.plate.geometry_notes() {
        eprintln!("note: {note}");
    }
    Ok(config)
}
