//! Test harness for the wire tests: a private network namespace per test,
//! the real node binary inside it, and the Cyclone DDS peer
//! (`tests/peer/peer.py`) next to it.
//!
//! The peer's Python environment is created on first use under
//! `target/peer-venv` from `tests/peer/requirements.txt` (pinned
//! `cyclonedds`). If that is impossible the tests fail — never skip — with
//! the reason.
//!
//! Isolation: every test runs in its own network namespace (`unshare -n`,
//! loopback only; we are root) and on its own ROS_DOMAIN_ID.

#![allow(dead_code)]

use std::ffi::OsStr;
use std::io::{BufRead, BufReader, Read};
use std::path::{Path, PathBuf};
use std::process::{Child, Command, ExitStatus, Stdio};
use std::sync::OnceLock;
use std::time::{Duration, Instant};

pub fn repo() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// The scene every wire test runs: the built-in default, as a file.
pub fn scene() -> PathBuf {
    repo().join("config/brake_bench.yaml")
}

/// The node binary: the package's own `annular_plate`.
pub fn node_binary() -> PathBuf {
    PathBuf::from(env!("CARGO_BIN_EXE_annular_plate"))
}

fn run_ok(cmd: &mut Command, what: &str) -> Result<(), String> {
    let out = cmd
        .output()
        .map_err(|e| format!("{what}: cannot run {cmd:?}: {e}"))?;
    if out.status.success() {
        Ok(())
    } else {
        Err(format!(
            "{what} failed ({}):\n{}\n{}",
            out.status,
            String::from_utf8_lossy(&out.stdout),
            String::from_utf8_lossy(&out.stderr)
        ))
    }
}

/// What the peers import: Cyclone DDS, and the bag readers/writer.
const PEER_IMPORTS: &str = "import cyclonedds.domain, cyclonedds.idl, rosbags.rosbag2, rosbags.highlevel, mcap.reader, mcap_ros2.decoder";

fn peer_ready(python: &Path) -> bool {
    Command::new(python)
        .args(["-c", PEER_IMPORTS])
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .status()
        .map(|s| s.success())
        .unwrap_or(false)
}

fn install_peer() -> Result<PathBuf, String> {
    let venv = repo().join("target/peer-venv");
    let python = venv.join("bin/python");
    let requirements = repo().join("tests/peer/requirements.txt");
    let wanted = std::fs::read_to_string(&requirements)
        .map_err(|e| format!("{}: {e}", requirements.display()))?;
    // The venv remembers the requirements it was made from; a change installs again.
    let stamp = venv.join("requirements.installed");
    let current = std::fs::read_to_string(&stamp).ok();
    if current.as_deref() == Some(wanted.as_str()) && peer_ready(&python) {
        return Ok(python);
    }
    if !python.exists() {
        let _ = std::fs::remove_dir_all(&venv);
        let host_python = std::env::var("PYTHON").unwrap_or_else(|_| "python3".to_string());
        run_ok(
            Command::new(&host_python).args(["-m", "venv"]).arg(&venv),
            "creating the peer's venv",
        )?;
    }
    run_ok(
        Command::new(&python)
            .args([
                "-m",
                "pip",
                "install",
                "--disable-pip-version-check",
                "-q",
                "-r",
            ])
            .arg(&requirements),
        "pip install -r tests/peer/requirements.txt",
    )?;
    if !peer_ready(&python) {
        return Err(format!(
            "tests/peer/requirements.txt was installed but `{PEER_IMPORTS}` fails"
        ));
    }
    std::fs::write(&stamp, wanted).map_err(|e| format!("{}: {e}", stamp.display()))?;
    Ok(python)
}

/// The peer's Python (installs it once per test process).
pub fn python() -> PathBuf {
    static PY: OnceLock<Result<PathBuf, String>> = OnceLock::new();
    match PY.get_or_init(install_peer) {
        Ok(p) => p.clone(),
        Err(e) => panic!(
            "the Cyclone DDS peer cannot be installed (needs python3 with venv and PyPI access): {e}"
        ),
    }
}

/// A private network namespace with only `lo` up, kept alive by a holder process.
pub struct Netns {
    holder: Child,
}

impl Netns {
    pub fn new() -> Netns {
        Netns::start("ip link set lo up")
    }

    /// The same with loopback's MTU set to `mtu` bytes (Linux's default is
    /// 65536; 1500 is what an Ethernet link between two machines gives, so
    /// DDS fragments what is larger than about 1.4 kB, as it would there).
    pub fn with_lo_mtu(mtu: u32) -> Netns {
        Netns::start(&format!("ip link set lo mtu {mtu} && ip link set lo up"))
    }

    fn start(setup: &str) -> Netns {
        let mut holder = Command::new("unshare")
            .args([
                "-n",
                "--",
                "sh",
                "-c",
                &format!("{setup} && echo ready && exec sleep 100000"),
            ])
            .stdout(Stdio::piped())
            .stderr(Stdio::piped())
            .spawn()
            .expect("cannot run `unshare -n` (the wire tests need root and util-linux)");
        let mut line = String::new();
        BufReader::new(holder.stdout.take().expect("piped"))
            .read_line(&mut line)
            .expect("read from unshare");
        if line.trim() != "ready" {
            let mut err = String::new();
            if let Some(mut e) = holder.stderr.take() {
                let _ = e.read_to_string(&mut err);
            }
            panic!("cannot create a network namespace with `unshare -n` (root needed): {err}");
        }
        Netns { holder }
    }

    /// A command that runs inside the namespace.
    pub fn command(&self, program: impl AsRef<OsStr>) -> Command {
        let mut c = Command::new("nsenter");
        c.arg(format!("--net=/proc/{}/ns/net", self.holder.id()))
            .arg("--")
            .arg(program);
        c
    }
}

impl Drop for Netns {
    fn drop(&mut self) {
        let _ = self.holder.kill();
        let _ = self.holder.wait();
    }
}

/// A thread that reads `r` to its end (a child's stdout or stderr) so the
/// child never blocks on a full pipe; join it for the text.
pub fn read_in_background<R: Read + Send + 'static>(mut r: R) -> std::thread::JoinHandle<String> {
    std::thread::spawn(move || {
        let mut s = String::new();
        let _ = r.read_to_string(&mut s);
        s
    })
}

pub fn temp_dir() -> PathBuf {
    let d = repo().join("target/ros-wire-tests");
    std::fs::create_dir_all(&d).expect("create target/ros-wire-tests");
    d
}

/// A running node process.
pub struct NodeProcess {
    child: Child,
    pub stderr_path: PathBuf,
    pub domain: u16,
}

/// Start `annular_plate run <scene> --ros-args <ros_args>` in `ns` on `domain`.
pub fn start_node(ns: &Netns, domain: u16, ros_args: &[&str]) -> NodeProcess {
    start_node_with(ns, domain, &[], ros_args)
}

/// Start `annular_plate run <scene> <run_args> --ros-args <ros_args>` (e.g. `--record DIR`).
pub fn start_node_with(
    ns: &Netns,
    domain: u16,
    run_args: &[&OsStr],
    ros_args: &[&str],
) -> NodeProcess {
    start_node_on(ns, domain, &scene(), run_args, ros_args)
}

/// Start `annular_plate run <scene_file> <run_args> --ros-args <ros_args>` (another scene than the default).
pub fn start_node_on(
    ns: &Netns,
    domain: u16,
    scene_file: &Path,
    run_args: &[&OsStr],
    ros_args: &[&str],
) -> NodeProcess {
    start_node_tagged(ns, domain, "", scene_file, run_args, ros_args)
}

/// The same, for one of several nodes on one domain (`tag` names its stderr file).
pub fn start_node_tagged(
    ns: &Netns,
    domain: u16,
    tag: &str,
    scene_file: &Path,
    run_args: &[&OsStr],
    ros_args: &[&str],
) -> NodeProcess {
    let stderr_path = temp_dir().join(format!("node-domain{domain}{tag}.stderr"));
    let stderr = std::fs::File::create(&stderr_path).expect("create the node's stderr file");
    let mut cmd = ns.command(node_binary());
    cmd.arg("run")
        .arg(scene_file)
        .args(run_args)
        .arg("--ros-args")
        .args(ros_args);
    let child = cmd
        .env("ROS_DOMAIN_ID", domain.to_string())
        .stdin(Stdio::null())
        .stdout(Stdio::null())
        .stderr(stderr)
        .spawn()
        .expect("cannot start the node binary");
    NodeProcess {
        child,
        stderr_path,
        domain,
    }
}

impl NodeProcess {
    pub fn pid(&self) -> u32 {
        self.child.id()
    }

    pub fn stderr(&self) -> String {
        std::fs::read_to_string(&self.stderr_path).unwrap_or_default()
    }

    pub fn signal(&self, sig: &str) {
        let ok = Command::new("kill")
            .args(["-s", sig, &self.pid().to_string()])
            .status()
            .map(|s| s.success());
        assert_eq!(ok.ok(), Some(true), "kill -s {sig} failed");
    }

    /// Wait up to `timeout` for the process to exit.
    pub fn wait_exit(&mut self, timeout: Duration) -> Option<ExitStatus> {
        let end = Instant::now() + timeout;
        while Instant::now() < end {
            if let Ok(Some(s)) = self.child.try_wait() {
                return Some(s);
            }
            std::thread::sleep(Duration::from_millis(5));
        }
        None
    }

    pub fn is_running(&mut self) -> bool {
        matches!(self.child.try_wait(), Ok(None))
    }
}

impl Drop for NodeProcess {
    fn drop(&mut self) {
        if self.is_running() {
            let _ = self.child.kill();
            let _ = self.child.wait();
        }
    }
}

/// Run a peer scenario in `ns` against the node on `domain`; returns its JSON.
pub fn peer(
    ns: &Netns,
    node: &NodeProcess,
    scenario: &str,
    node_name: &str,
    args: serde_json::Value,
) -> serde_json::Value {
    let python = python();
    let mut cmd = ns.command(&python);
    cmd.arg(repo().join("tests/peer/peer.py"))
        .arg(scenario)
        .args([
            "--domain",
            &node.domain.to_string(),
            "--node",
            node_name,
            "--args",
            &args.to_string(),
        ])
        .env(
            "CYCLONEDDS_URI",
            format!(
                "file://{}",
                repo().join("tests/peer/cyclonedds.xml").display()
            ),
        )
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped());
    let mut child = cmd.spawn().expect("cannot start the peer");
    let out_thread = read_in_background(child.stdout.take().expect("piped"));
    let err_thread = read_in_background(child.stderr.take().expect("piped"));
    let end = Instant::now() + Duration::from_secs(120);
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
    let out = out_thread.join().unwrap_or_default();
    let err = err_thread.join().unwrap_or_default();
    if node.stderr().contains("without the `ros` feature") {
        panic!(
            "{} was built without the `ros` feature (a concurrent `cargo build --no-default-features` in the same target dir replaces it); rebuild and rerun",
            node_binary().display()
        );
    }
    let context = || {
        format!(
            "peer `{scenario}`:\n--- stdout\n{out}\n--- stderr\n{err}\n--- node stderr\n{}",
            node.stderr()
        )
    };
    match status {
        Some(s) if s.success() => {}
        Some(s) => panic!("{} failed ({s})", context()),
        None => panic!("{} timed out", context()),
    }
    let last = out
        .lines()
        .rev()
        .find(|l| !l.trim().is_empty())
        .unwrap_or_else(|| panic!("{} printed nothing", context()));
    serde_json::from_str(last).unwrap_or_else(|e| panic!("{}: not JSON: {e}", context()))
}

/// A field of a JSON object as f64 (panics with the path otherwise).
pub fn f(v: &serde_json::Value, path: &str) -> f64 {
    let mut x = v;
    for p in path.split('.') {
        x = match p.parse::<usize>() {
            Ok(i) => &x[i],
            Err(_) => &x[p],
        };
    }
    x.as_f64()
        .unwrap_or_else(|| panic!("{path} is not a number in {v}"))
}

pub fn floats(v: &serde_json::Value) -> Vec<f64> {
    v.as_array()
        .unwrap_or_else(|| panic!("not an array: {v}"))
        .iter()
        .map(|x| x.as_f64().expect("number"))
        .collect()
}

/// Read a bag with `tests/peer/bag_read.py` (`reader`: "rosbags" or
/// "mcap"); the whole decoded messages of the topics in `full`.
pub fn read_bag(path: &Path, reader: &str, full: &[&str]) -> serde_json::Value {
    let python = python();
    let out = Command::new(&python)
        .arg(repo().join("tests/peer/bag_read.py"))
        .arg(path)
        .args(["--reader", reader])
        .arg("--full")
        .args(full)
        .stdin(Stdio::null())
        .output()
        .expect("cannot run tests/peer/bag_read.py");
    assert!(
        out.status.success(),
        "bag_read.py --reader {reader} {} failed ({}):\n{}",
        path.display(),
        out.status,
        String::from_utf8_lossy(&out.stderr)
    );
    let text = String::from_utf8_lossy(&out.stdout);
    serde_json::from_str(text.trim())
        .unwrap_or_else(|e| panic!("bag_read.py printed no JSON ({e}): {text:.2000}"))
}

/// A fresh (not yet existing) path under `target/bag-tests/`.
pub fn fresh_dir(name: &str) -> PathBuf {
    let base = repo().join("target/bag-tests");
    std::fs::create_dir_all(&base).expect("create target/bag-tests");
    let d = base.join(name);
    let _ = std::fs::remove_dir_all(&d);
    d
}
