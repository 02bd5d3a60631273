//! The manual cannot rot: every `annular_plate` command in a fenced shell
//! block (```sh, ```bash, ```console or unlabelled) of README.md and
//! docs/*.md runs here and succeeds. Synopses with placeholders belong in
//! ```text blocks; lines that call other tools (`cargo`, `ros2`, Python
//! benchmarks) are not run.
//!
//! The rules, per document, its lines in order (a later line may read what an
//! earlier one wrote):
//!
//! * a command line starts, after optional `NAME=value` words, with
//!   `annular_plate` or `target/release/annular_plate`; a trailing `\`
//!   continues it on the next line; ` # …` is a comment; a trailing `&`
//!   (started in the background) is dropped;
//! * it runs through `sh -c` in a fresh directory that has the repository's
//!   `config/` and `docs/` (so outputs land there, not in the repository),
//!   with both names resolving to the binary under test;
//! * `--duration S` above 0.2 s is shortened to 0.2 s, and `study` runs with
//!   `--quick` (the full study is tested by tests/study_*.rs);
//! * `run` (or no subcommand: the node) is started in a private network
//!   namespace (`unshare -n`, loopback only, as the wire tests), left until it
//!   logs that it is up, then stopped with SIGINT, and must exit with 0.

use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

const BIN: &str = env!("CARGO_BIN_EXE_annular_plate");
/// The longest simulated time a documented command is run for, s.
const MAX_DURATION: f64 = 0.2;

fn repo() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// A documented command: where it is and what it says.
#[derive(Debug, Clone, PartialEq)]
struct DocCommand {
    line: usize,
    text: String,
}

/// The `annular_plate` command lines of the shell blocks of `markdown`.
fn commands(markdown: &str) -> Vec<DocCommand> {
    let mut out = Vec::new();
    let mut in_block = false;
    let mut shell = false;
    let mut pending: Option<DocCommand> = None;
    for (i, line) in markdown.lines().enumerate() {
        let t = line.trim();
        if let Some(lang) = t.strip_prefix("```") {
            if in_block {
                in_block = false;
            } else {
                in_block = true;
                shell = matches!(lang.trim(), "" | "sh" | "bash" | "console" | "shell");
            }
            continue;
        }
        if !(in_block && shell) {
            continue;
        }
        let t = t.strip_prefix("$ ").unwrap_or(t);
        let (text, continued) = match t.strip_suffix('\\') {
            Some(head) => (head.trim_end(), true),
            None => (t, false),
        };
        let joined = match pending.take() {
            Some(mut c) => {
                c.text.push(' ');
                c.text.push_str(text);
                c
            }
            None => DocCommand {
                line: i + 1,
                text: text.to_string(),
            },
        };
        if continued {
            pending = Some(joined);
        } else if program(&joined.text).is_some() {
            out.push(joined);
        }
    }
    out
}

/// The words after the `NAME=value` prefix, if the program is annular_plate.
fn program(text: &str) -> Option<Vec<&str>> {
    let mut words: Vec<&str> = strip_comment(text).split_whitespace().collect();
    if words.last() == Some(&"&") {
        words.pop(); // started in the background: the node, run as the others
    }
    let first = words
        .iter()
        .position(|w| !w.contains('=') || w.starts_with('-'))?;
    matches!(
        words[first],
        "annular_plate" | "target/release/annular_plate"
    )
    .then(|| words[first..].to_vec())
}

fn strip_comment(text: &str) -> &str {
    match text.find(" #") {
        Some(i) => &text[..i],
        None if text.starts_with('#') => "",
        None => text,
    }
}

/// The line as the test runs it (the documented rules above).
fn shortened(text: &str) -> String {
    let mut words: Vec<String> = strip_comment(text)
        .split_whitespace()
        .map(str::to_string)
        .collect();
    for i in 0..words.len().saturating_sub(1) {
        if words[i] == "--duration" {
            if let Ok(d) = words[i + 1].parse::<f64>() {
                if d > MAX_DURATION {
                    words[i + 1] = MAX_DURATION.to_string();
                }
            }
        }
    }
    if let Some(p) = words.iter().position(|w| w.ends_with("annular_plate")) {
        if words.get(p + 1).map(String::as_str) == Some("study")
            && !words.iter().any(|w| w == "--quick")
        {
            words.insert(p + 2, "--quick".into());
        }
    }
    words.join(" ")
}

/// Whether the line starts the node (`run`, or no subcommand).
fn starts_the_node(text: &str) -> bool {
    let words = program(text).expect("a command line");
    matches!(
        words.get(1).copied(),
        None | Some("run") | Some("--ros-args")
    )
}

/// A fresh directory with config/ and docs/ and the two names of the binary.
fn workdir(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("annular_plate_docs_{}_{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(d.join("target/release")).unwrap();
    std::fs::create_dir_all(d.join("bin")).unwrap();
    for sub in ["config", "docs"] {
        std::os::unix::fs::symlink(repo().join(sub), d.join(sub)).unwrap();
    }
    std::os::unix::fs::symlink(BIN, d.join("target/release/annular_plate")).unwrap();
    std::os::unix::fs::symlink(BIN, d.join("bin/annular_plate")).unwrap();
    d
}

fn path_with(dir: &Path) -> String {
    format!(
        "{}:{}",
        dir.join("bin").display(),
        std::env::var("PATH").unwrap_or_default()
    )
}

/// Run one offline command; Err with what it printed.
fn run_offline(dir: &Path, line: &str) -> Result<(), String> {
    let out = Command::new("sh")
        .arg("-c")
        .arg(line)
        .current_dir(dir)
        .env("PATH", path_with(dir))
        .output()
        .map_err(|e| e.to_string())?;
    if out.status.success() {
        Ok(())
    } else {
        Err(format!(
            "{}\nstdout: {}\nstderr: {}",
            out.status,
            String::from_utf8_lossy(&out.stdout),
            String::from_utf8_lossy(&out.stderr)
        ))
    }
}

/// Start the node, wait until it is up, stop it with SIGINT: Err with its log.
fn run_node(dir: &Path, line: &str, id: usize) -> Result<(), String> {
    let words = program(line).unwrap();
    let env: Vec<(&str, &str)> = strip_comment(line)
        .split_whitespace()
        .take_while(|w| w.contains('=') && !w.starts_with('-'))
        .filter_map(|w| w.split_once('='))
        .collect();
    let log = dir.join(format!("node_{id}.log"));
    let file = std::fs::File::create(&log).unwrap();
    let mut cmd = Command::new("unshare");
    cmd.args([
        "-n",
        "sh",
        "-c",
        "ip link set lo up && exec \"$0\" \"$@\"",
        BIN,
    ])
    .args(&words[1..]);
    cmd.current_dir(dir)
        .env("PATH", path_with(dir))
        .stdin(Stdio::null())
        .stdout(file.try_clone().unwrap())
        .stderr(file);
    if !env.iter().any(|(k, _)| *k == "ROS_DOMAIN_ID") {
        cmd.env("ROS_DOMAIN_ID", "42");
    }
    for (k, v) in &env {
        cmd.env(k, v);
    }
    let mut child = cmd
        .spawn()
        .map_err(|e| format!("cannot start unshare (root, util-linux, iproute2 needed): {e}"))?;
    let read = || std::fs::read_to_string(&log).unwrap_or_default();
    let started = Instant::now();
    while !read().contains(" up on ROS_DOMAIN_ID") {
        if let Some(status) = child.try_wait().unwrap() {
            return Err(format!(
                "the node ended before it was up: {status}\n{}",
                read()
            ));
        }
        if started.elapsed() > Duration::from_secs(60) {
            let _ = child.kill();
            return Err(format!("the node was not up within 60 s\n{}", read()));
        }
        std::thread::sleep(Duration::from_millis(50));
    }
    std::thread::sleep(Duration::from_millis(500));
    // SAFETY: kill(2) on the child's own pid.
    unsafe { libc_kill(child.id() as i32, 2) };
    let stop = Instant::now();
    loop {
        if let Some(status) = child.try_wait().unwrap() {
            return if status.success() {
                Ok(())
            } else {
                Err(format!("exit {status} after SIGINT\n{}", read()))
            };
        }
        if stop.elapsed() > Duration::from_secs(10) {
            let _ = child.kill();
            return Err(format!("still running 10 s after SIGINT\n{}", read()));
        }
        std::thread::sleep(Duration::from_millis(20));
    }
}

extern "C" {
    #[link_name = "kill"]
    fn libc_kill(pid: i32, sig: i32) -> i32;
}

fn documents() -> Vec<PathBuf> {
    let mut docs: Vec<PathBuf> = std::fs::read_dir(repo().join("docs"))
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|x| x == "md"))
        .collect();
    docs.sort();
    docs.insert(0, repo().join("README.md"));
    docs
}

#[test]
fn every_documented_command_runs() {
    let mut failures = Vec::new();
    let mut ran = 0;
    for doc in documents() {
        let name = doc.file_stem().unwrap().to_string_lossy().into_owned();
        let text = std::fs::read_to_string(&doc).unwrap();
        let cmds = commands(&text);
        if cmds.is_empty() {
            continue;
        }
        let dir = workdir(&name);
        for (i, c) in cmds.iter().enumerate() {
            let line = shortened(&c.text);
            let started = Instant::now();
            let result = if starts_the_node(&c.text) {
                run_node(&dir, &c.text, i)
            } else {
                run_offline(&dir, &line)
            };
            println!(
                "{}:{}: {line}  ({:.1} s, {})",
                doc.strip_prefix(repo()).unwrap().display(),
                c.line,
                started.elapsed().as_secs_f64(),
                if result.is_ok() { "ok" } else { "FAILED" }
            );
            ran += 1;
            if let Err(e) = result {
                failures.push(format!(
                    "{}:{}: `{}`\n{e}",
                    doc.strip_prefix(repo()).unwrap().display(),
                    c.line,
                    c.text
                ));
            }
        }
        let _ = std::fs::remove_dir_all(&dir);
    }
    assert!(ran >= 10, "only {ran} documented commands found");
    assert!(
        failures.is_empty(),
        "documented commands that fail:\n\n{}",
        failures.join("\n\n")
    );
}

#[test]
fn the_rules_find_and_shorten_what_they_should() {
    let md = "text\n```sh\nannular_plate simulate config/lathe.yaml --duration 5.5 --csv a.csv   # a comment\ncargo build --release\nROS_DOMAIN_ID=7 target/release/annular_plate run config/brake_bench.yaml --ros-args \\\n    -r __node:=disc\nros2 topic echo /joint_states\n```\n```text\nannular_plate modes FILE [--json]\n```\n```sh\nannular_plate study config/lathe.yaml --plot p.png\n```\n";
    let c = commands(md);
    assert_eq!(c.len(), 3, "{c:?}");
    assert_eq!(c[0].line, 3);
    assert_eq!(
        shortened(&c[0].text),
        "annular_plate simulate config/lathe.yaml --duration 0.2 --csv a.csv"
    );
    assert!(starts_the_node(&c[1].text) && c[1].text.ends_with("-r __node:=disc"));
    assert!(!starts_the_node(&c[0].text));
    assert_eq!(
        shortened(&c[2].text),
        "annular_plate study --quick config/lathe.yaml --plot p.png"
    );
    assert_eq!(
        shortened("annular_plate simulate x.yaml --duration 0.05"),
        "annular_plate simulate x.yaml --duration 0.05"
    );
}
