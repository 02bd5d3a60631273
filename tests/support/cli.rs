//! The binary as the command-line tests run it, and their scratch directories.
#![allow(dead_code)]

use std::path::PathBuf;
use std::process::Command;

/// The `annular_plate` binary cargo built for the tests.
pub const BIN: &str = env!("CARGO_BIN_EXE_annular_plate");

/// `annular_plate ARGS`: whether it succeeded, its stdout and its stderr.
pub fn run(args: &[&str]) -> (bool, String, String) {
    let out = Command::new(BIN).args(args).output().unwrap();
    (
        out.status.success(),
        String::from_utf8_lossy(&out.stdout).into(),
        String::from_utf8_lossy(&out.stderr).into(),
    )
}

/// A scratch directory of this test process, `annular_plate_<name>_<pid>` in
/// the system's temporary directory, created.
pub fn scratch_dir(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("annular_plate_{name}_{}", std::process::id()));
    std::fs::create_dir_all(&d).unwrap();
    d
}
