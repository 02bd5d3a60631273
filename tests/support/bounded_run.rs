//! Run the binary with a time limit and measure its peak memory (VmHWM of
//! /proc/<pid>/status, polled while it runs).
#![allow(dead_code)]

use std::io::Read;
use std::process::{Child, Command, Stdio};
use std::time::{Duration, Instant};

pub const BIN: &str = env!("CARGO_BIN_EXE_annular_plate");

/// The outcome of a bounded run.
#[derive(Debug)]
pub struct Bounded {
    /// `None`: killed at the time limit.
    pub code: Option<i32>,
    pub stdout: String,
    pub stderr: String,
    /// Peak resident memory, KiB.
    pub peak_kib: u64,
    pub elapsed: Duration,
}

fn vm_hwm_kib(pid: u32) -> Option<u64> {
    let status = std::fs::read_to_string(format!("/proc/{pid}/status")).ok()?;
    let line = status.lines().find(|l| l.starts_with("VmHWM:"))?;
    line.split_whitespace().nth(1)?.parse().ok()
}

/// Run `annular_plate args…` for at most `limit`, stdin from `/dev/null`
/// unless `stdin` writes it (on a thread).
pub fn run_bounded(
    args: &[&str],
    limit: Duration,
    stdin: Option<Box<dyn FnOnce(std::process::ChildStdin) + Send>>,
) -> Bounded {
    let mut cmd = Command::new(BIN);
    cmd.args(args).stdout(Stdio::piped()).stderr(Stdio::piped());
    cmd.stdin(if stdin.is_some() {
        Stdio::piped()
    } else {
        Stdio::null()
    });
    let mut child: Child = cmd.spawn().unwrap();
    if let (Some(feed), Some(pipe)) = (stdin, child.stdin.take()) {
        std::thread::spawn(move || feed(pipe));
    }
    let mut out = child.stdout.take().unwrap();
    let mut err = child.stderr.take().unwrap();
    let out_thread = std::thread::spawn(move || {
        let mut s = Vec::new();
        let _ = out.read_to_end(&mut s);
        s
    });
    let err_thread = std::thread::spawn(move || {
        let mut s = Vec::new();
        let _ = err.read_to_end(&mut s);
        s
    });
    let start = Instant::now();
    let mut peak = 0;
    let code = loop {
        if let Some(kib) = vm_hwm_kib(child.id()) {
            peak = peak.max(kib);
        }
        if let Some(status) = child.try_wait().unwrap() {
            break status.code();
        }
        if start.elapsed() > limit {
            let _ = child.kill();
            let _ = child.wait();
            break None;
        }
        std::thread::sleep(Duration::from_millis(5));
    };
    let elapsed = start.elapsed();
    Bounded {
        code,
        stdout: String::from_utf8_lossy(&out_thread.join().unwrap()).into(),
        stderr: String::from_utf8_lossy(&err_thread.join().unwrap()).into(),
        peak_kib: peak,
        elapsed,
    }
}
