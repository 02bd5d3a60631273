//! The documents and the code comments say what is true now and how to check
//! it; how the project was made is in `git log`. No work-session diaries, no
//! machine-load narratives, no references to an issue tracker a reader cannot
//! see, no dates of runs — and the README stays a manual of a readable length.

use std::path::{Path, PathBuf};

fn repo() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// README.md, docs/*.md, vendor/rustdds/PATCH.md, every file under src/, benches/ and tests/ (but this one).
fn files() -> Vec<PathBuf> {
    fn walk(dir: &Path, out: &mut Vec<PathBuf>) {
        for e in std::fs::read_dir(dir).unwrap() {
            let p = e.unwrap().path();
            if p.is_dir() {
                walk(&p, out);
            } else if matches!(
                p.extension().and_then(|x| x.to_str()),
                Some("rs" | "md" | "py" | "sh")
            ) {
                out.push(p);
            }
        }
    }
    let r = repo();
    let mut out = vec![r.join("README.md"), r.join("vendor/rustdds/PATCH.md")];
    for d in ["docs", "src", "benches", "tests"] {
        walk(&r.join(d), &mut out);
    }
    out.retain(|p| !p.ends_with(file!().rsplit('/').next().unwrap()));
    out
}

/// Lines matching `bad`, as "file:line: text".
fn hits(bad: impl Fn(&str) -> bool) -> Vec<String> {
    let mut out = Vec::new();
    for f in files() {
        let text = std::fs::read_to_string(&f).unwrap();
        for (i, line) in text.lines().enumerate() {
            if bad(line) {
                out.push(format!(
                    "{}:{}: {}",
                    f.strip_prefix(repo()).unwrap().display(),
                    i + 1,
                    line.trim()
                ));
            }
        }
    }
    out
}

/// Whole words only: `word` at a word boundary, case-insensitive.
fn has_word(line: &str, word: &str) -> bool {
    let lower = line.to_lowercase();
    lower.match_indices(word).any(|(i, _)| {
        let before = lower[..i].chars().next_back();
        !before.is_some_and(|c| c.is_alphanumeric() || c == '_')
    })
}

#[test]
fn no_session_diaries_agents_or_load_narratives() {
    // Technical uses a reader would need would be listed here; there are none.
    const ALLOWED: [&str; 0] = [];
    let found = hits(|l| {
        ["session", "agent", "load average"]
            .iter()
            .any(|w| has_word(l, w))
            && !ALLOWED.iter().any(|a| l.contains(a))
    });
    assert!(
        found.is_empty(),
        "narrative of how the project was made:\n{}",
        found.join("\n")
    );
}

#[test]
fn no_references_to_issue_numbers() {
    let found = hits(|l| {
        let lower = l.to_lowercase();
        lower.match_indices("issue").any(|(i, _)| {
            let rest = lower[i + 5..]
                .trim_start_matches('s')
                .trim_start_matches([' ', '#']);
            rest.starts_with(|c: char| c.is_ascii_digit())
        })
    });
    assert!(
        found.is_empty(),
        "\"issue N\" points at a tracker the reader cannot see:\n{}",
        found.join("\n")
    );
}

#[test]
fn no_dates_of_runs() {
    // A date yyyy-mm-dd (the year 20xx).
    let is_date = |w: &[u8]| {
        w.len() == 10
            && w[..2] == *b"20"
            && w[4] == b'-'
            && w[7] == b'-'
            && [0, 1, 2, 3, 5, 6, 8, 9]
                .iter()
                .all(|&i| w[i].is_ascii_digit())
    };
    let found = hits(|l| l.as_bytes().windows(10).any(is_date));
    assert!(
        found.is_empty(),
        "dates belong in commit messages:\n{}",
        found.join("\n")
    );
}

#[test]
fn the_readme_is_a_manual_of_readable_length() {
    let text = std::fs::read_to_string(repo().join("README.md")).unwrap();
    let lines = text.lines().count();
    assert!(
        lines <= 250,
        "README.md has {lines} lines; details belong in docs/"
    );
    for section in [
        "## Quick start",
        "## Drive the running node",
        "## The command line",
        "## Scenes",
        "## Configuration",
        "## License",
    ] {
        assert!(text.contains(section), "README.md lacks `{section}`");
    }
    // The rclpy route without a ROS installation, and the docs with the figures.
    for link in [
        "docs/ros.md#use-from-python-without-a-ros-installation",
        "docs/accuracy.md",
        "docs/performance.md",
    ] {
        assert!(text.contains(link), "README.md does not link {link}");
    }
}
