//! A real ROS 2 peer for the wire tests: rclpy from the ROS 2 Jazzy wheels on
//! PyPI (rmw_fastrtps_cpp), with this package's interfaces and the standard
//! ones the wheels lack built by `scripts/rclpy_env.sh` (target/rclpy-venv,
//! target/rclpy-ws). Included next to `harness.rs`:
//!
//! ```ignore
//! #[path = "peer/harness.rs"] mod harness;
//! #[path = "peer/rclpy.rs"] mod rclpy;
//! ```
//!
//! The environment is made once per test process (the script is idempotent
//! and takes a lock, so test binaries never build it twice at once); if it
//! cannot be made the test fails with the script's output — never skips.
//! Every script runs inside the test's network namespace on the node's
//! ROS_DOMAIN_ID with the environment of `target/rclpy-ws/env.sh`.

#![allow(dead_code)]

use crate::harness::{read_in_background, repo, Netns, NodeProcess};
use std::ffi::OsStr;
use std::path::PathBuf;
use std::process::{Command, ExitStatus, Stdio};
use std::sync::OnceLock;
use std::time::{Duration, Instant};

fn make_env() -> Result<PathBuf, String> {
    let t0 = Instant::now();
    let out = Command::new("bash")
        .arg(repo().join("scripts/rclpy_env.sh"))
        .env("CARGO_TARGET_DIR", repo().join("target"))
        .stdin(Stdio::null())
        .output()
        .map_err(|e| format!("cannot run bash scripts/rclpy_env.sh: {e}"))?;
    let text = format!(
        "{}{}",
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    );
    if !out.status.success() {
        return Err(format!(
            "scripts/rclpy_env.sh failed ({}):\n{text}",
            out.status
        ));
    }
    // What the environment costs this run (0.9 s when up to date; pip and
    // colcon on a clean checkout).
    println!(
        "rclpy environment: scripts/rclpy_env.sh took {:.1} s\n{}",
        t0.elapsed().as_secs_f64(),
        text.trim_end()
    );
    let env = repo().join("target/rclpy-ws/env.sh");
    if !env.exists() {
        return Err(format!(
            "scripts/rclpy_env.sh succeeded but wrote no {}:\n{text}",
            env.display()
        ));
    }
    Ok(env)
}

/// `target/rclpy-ws/env.sh` (made on first use).
pub fn env_script() -> PathBuf {
    static ENV: OnceLock<Result<PathBuf, String>> = OnceLock::new();
    match ENV.get_or_init(make_env) {
        Ok(p) => p.clone(),
        Err(e) => panic!("rclpy (ROS 2 Jazzy wheels from PyPI) cannot be installed; the rclpy tests need python3.11 with venv and headers, a C++ compiler and PyPI access: {e}"),
    }
}

/// How a Python run ended.
pub struct PyRun {
    /// None: killed at the timeout.
    pub status: Option<ExitStatus>,
    pub stdout: String,
    pub stderr: String,
    pub seconds: f64,
}

impl PyRun {
    pub fn success(&self) -> bool {
        self.status.map(|s| s.success()).unwrap_or(false)
    }
}

/// A bash command line with the rclpy environment: `bash -c '. ENV; exec "$@"' rclpy args…`.
pub fn command(ns: &Netns, domain: u16, program_and_args: &[&OsStr]) -> Command {
    let env = env_script();
    let mut cmd = ns.command("bash");
    cmd.arg("-c")
        .arg(r#". "$0" && exec "$@""#)
        .arg(&env)
        .args(program_and_args)
        .env("ROS_DOMAIN_ID", domain.to_string())
        .env("ROS_LOG_DIR", repo().join("target/rclpy-logs"))
        .env("RCUTILS_COLORIZED_OUTPUT", "0")
        .env("PYTHONUNBUFFERED", "1")
        .current_dir(repo());
    cmd
}

/// Run `python3 ARGS…` (a script and its arguments) in `ns` on `domain`, at most `timeout`.
pub fn run_python(ns: &Netns, domain: u16, args: &[&OsStr], timeout: Duration) -> PyRun {
    let mut all: Vec<&OsStr> = vec![OsStr::new("python3")];
    all.extend_from_slice(args);
    let mut cmd = command(ns, domain, &all);
    cmd.stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped());
    let t0 = Instant::now();
    let mut child = cmd.spawn().expect("cannot start bash for the rclpy peer");
    let out_thread = read_in_background(child.stdout.take().expect("piped"));
    let err_thread = read_in_background(child.stderr.take().expect("piped"));
    let end = t0 + timeout;
    let status = loop {
        if let Ok(Some(s)) = child.try_wait() {
            break Some(s);
        }
        if Instant::now() > end {
            let _ = child.kill();
            let _ = child.wait();
            break None;
        }
        std::thread::sleep(Duration::from_millis(10));
    };
    PyRun {
        status,
        stdout: out_thread.join().unwrap_or_default(),
        stderr: err_thread.join().unwrap_or_default(),
        seconds: t0.elapsed().as_secs_f64(),
    }
}

/// Run a scenario of `tests/rclpy/peer.py` against `node`; its JSON.
pub fn rclpy_peer(
    ns: &Netns,
    node: &NodeProcess,
    scenario: &str,
    node_name: &str,
    args: serde_json::Value,
) -> serde_json::Value {
    rclpy_peer_timeout(
        ns,
        node,
        scenario,
        node_name,
        args,
        Duration::from_secs(600),
    )
}

pub fn rclpy_peer_timeout(
    ns: &Netns,
    node: &NodeProcess,
    scenario: &str,
    node_name: &str,
    args: serde_json::Value,
    timeout: Duration,
) -> serde_json::Value {
    let script = repo().join("tests/rclpy/peer.py");
    let a = args.to_string();
    let run = run_python(
        ns,
        node.domain,
        &[
            script.as_os_str(),
            OsStr::new(scenario),
            OsStr::new("--node"),
            OsStr::new(node_name),
            OsStr::new("--args"),
            OsStr::new(&a),
        ],
        timeout,
    );
    let context = || {
        format!(
            "rclpy peer `{scenario}` ({:.1} s):\n--- stdout\n{}\n--- stderr\n{}\n--- node stderr\n{}",
            run.seconds,
            run.stdout,
            run.stderr,
            node.stderr()
        )
    };
    match run.status {
        Some(s) if s.success() => {}
        Some(s) => panic!("{} failed ({s})", context()),
        None => panic!("{} timed out", context()),
    }
    let last = run
        .stdout
        .lines()
        .rev()
        .find(|l| !l.trim().is_empty())
        .unwrap_or_else(|| panic!("{} printed nothing", context()));
    serde_json::from_str(last).unwrap_or_else(|e| panic!("{}: not JSON: {e}", context()))
}

/// Quantiles of a sample (sorted copy): (n, min, p50, p90, p99, max).
pub fn quantiles(xs: &[f64]) -> Option<(usize, f64, f64, f64, f64, f64)> {
    if xs.is_empty() {
        return None;
    }
    let mut s = xs.to_vec();
    s.sort_by(|a, b| a.total_cmp(b));
    let q = |p: f64| s[((p * (s.len() - 1) as f64).round() as usize).min(s.len() - 1)];
    Some((s.len(), s[0], q(0.5), q(0.9), q(0.99), s[s.len() - 1]))
}
