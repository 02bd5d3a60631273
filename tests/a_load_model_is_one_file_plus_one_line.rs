//! A load model is one file plus one line: the space-fixed point damper
//! (`src/dynamics/load_models/point_damper.rs`) is named — its module, its
//! types, its section and keys — in no hand-written file of the repository
//! but its own, except for exactly one line of the registry. Its parameters
//! reach the table, the checker, the parameter services and the reference
//! through that line alone (the generated docs/parameters.md and the
//! generated key index of the README are not hand-written; tests/ is where
//! the model is tested).
//!
//! Read from the working tree, not from git history (a shallow clone has none).

use std::path::{Path, PathBuf};

const OWN_FILE: &str = "src/dynamics/load_models/point_damper.rs";
const REGISTRY_FILE: &str = "src/dynamics/load_models/mod.rs";

/// What names the damper: its module, its types, its section and its keys.
const NAMES: &[&str] = &[
    "point_damper",
    "PointDampers",
    "DampersConfig",
    "\"dampers\"",
    "dampers.ale_nodes",
    "dampers.damping",
];

/// Not hand-written, or not the program: build output, vendored crates,
/// tests, the generated parameter reference.
const SKIPPED_DIRS: &[&str] = &["target", "vendor", "tests", ".git"];
const GENERATED: &[&str] = &["docs/parameters.md"];

/// The README's key index is generated between these markers.
const BEGIN: &str = "<!-- generated from src/config/table.rs: begin -->";
const END: &str = "<!-- generated from src/config/table.rs: end -->";

fn repo() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

fn text_files(dir: &Path, out: &mut Vec<(String, String)>) {
    for e in std::fs::read_dir(dir).unwrap() {
        let p = e.unwrap().path();
        let rel = p
            .strip_prefix(repo())
            .unwrap()
            .to_string_lossy()
            .replace('\\', "/");
        if p.is_dir() {
            if !SKIPPED_DIRS.contains(&rel.as_str()) {
                text_files(&p, out);
            }
        } else if let Ok(text) = std::fs::read_to_string(&p) {
            if !GENERATED.contains(&rel.as_str()) {
                out.push((rel, text));
            }
        }
    }
}

/// The text without a generated block between the markers.
fn hand_written(text: &str) -> String {
    match (text.find(BEGIN), text.find(END)) {
        (Some(a), Some(b)) if a < b => format!("{}{}", &text[..a], &text[b..]),
        _ => text.to_string(),
    }
}

fn names_the_damper(line: &str) -> bool {
    NAMES.iter().any(|n| line.contains(n))
}

#[test]
fn the_point_damper_is_its_file_plus_one_registry_line() {
    let mut files = Vec::new();
    text_files(&repo(), &mut files);
    assert!(
        files.iter().any(|(p, _)| p == OWN_FILE),
        "{OWN_FILE} is missing"
    );
    assert!(files.len() > 50, "the scan saw only {} files", files.len());
    let mut outside = Vec::new();
    let mut registry_lines = Vec::new();
    for (path, text) in &files {
        if path == OWN_FILE {
            continue;
        }
        for (i, line) in hand_written(text).lines().enumerate() {
            if !names_the_damper(line) {
                continue;
            }
            if path == REGISTRY_FILE {
                registry_lines.push(line.trim().to_string());
            } else {
                outside.push(format!("{path}:{}: {}", i + 1, line.trim()));
            }
        }
    }
    assert!(
        outside.is_empty(),
        "the point damper is named outside its file:\n{}",
        outside.join("\n")
    );
    assert_eq!(
        registry_lines,
        vec!["point_damper,".to_string()],
        "the registry names the damper in exactly one line"
    );
}

/// Through that one line its keys are declared, checked and documented.
#[test]
fn the_one_line_brings_the_keys_to_the_table_and_the_reference() {
    use annular_plate::dynamics::load_models::PARAMETERS;
    for key in ["dampers.ale_nodes", "dampers.damping"] {
        assert!(PARAMETERS.find(key).is_some(), "{key} is not declared");
    }
    assert_eq!(PARAMETERS.enabled_by("dampers"), Some("dampers.ale_nodes"));
    let reference = std::fs::read_to_string(repo().join("docs/parameters.md")).unwrap();
    assert!(reference.contains("`dampers.damping`"));
}

#[test]
fn the_scan_sees_a_name_and_skips_the_generated_block() {
    assert!(names_the_damper("use super::point_damper::X;"));
    assert!(!names_the_damper("point springs and pad dampers"));
    let text = format!("a\n{BEGIN}\n| `dampers.damping` |\n{END}\nb");
    assert!(!hand_written(&text).lines().any(names_the_damper));
}
