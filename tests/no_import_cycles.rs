//! The module map of docs/architecture.md holds: data flows one way between
//! the top-level modules (config → model → dynamics → messages → ros / bag /
//! cli; study beside messages), and no file imports another that imports it
//! back, directly or around a longer loop.
//!
//! The graph is read from the sources: every `crate::…` and `super::…` path
//! outside `#[cfg(test)]` modules, resolved to the file that defines the
//! module it names. A `mod.rs` declaring and re-exporting its own children is
//! not an import (its children may use what it defines).

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

/// Which top-level modules each may use.
const LAYERS: &[(&str, &[&str])] = &[
    ("config", &[]),
    ("colour_map", &[]),
    ("model", &["config"]),
    ("dynamics", &["config", "model"]),
    ("study", &["config", "model", "dynamics"]),
    ("messages", &["config", "colour_map", "model", "dynamics"]),
    ("bag", &["config", "model", "dynamics", "messages"]),
    ("ros", &["config", "model", "dynamics", "messages", "bag"]),
    (
        "cli",
        &[
            "config",
            "colour_map",
            "model",
            "dynamics",
            "study",
            "messages",
            "bag",
            "ros",
        ],
    ),
];

fn rust_files(dir: &Path, out: &mut Vec<PathBuf>) {
    for entry in std::fs::read_dir(dir).unwrap() {
        let path = entry.unwrap().path();
        if path.is_dir() {
            rust_files(&path, out);
        } else if path.extension().is_some_and(|e| e == "rs") {
            out.push(path);
        }
    }
}

/// `src/dynamics/load_models/pad.rs` → ["dynamics", "load_models", "pad"]; `mod.rs` → its directory.
fn module_of(src: &Path, file: &Path) -> Vec<String> {
    let rel = file.strip_prefix(src).unwrap().with_extension("");
    let mut parts: Vec<String> = rel
        .iter()
        .map(|p| p.to_string_lossy().into_owned())
        .collect();
    if parts
        .last()
        .is_some_and(|p| p == "mod" || p == "lib" || p == "main")
    {
        parts.pop();
    }
    parts
}

/// The code without `#[cfg(test)]` items (test modules sit at the end of a file).
fn without_tests(text: &str) -> &str {
    text.find("#[cfg(test)]").map_or(text, |i| &text[..i])
}

/// Every path starting with `crate::` or `super::`, as segments (braces are
/// expanded one level: `crate::a::{b, c::d}` gives a::b and a::c::d).
fn paths(text: &str, here: &[String]) -> Vec<Vec<String>> {
    let mut out = Vec::new();
    let bytes = text.as_bytes();
    for start in ["crate::", "super::"] {
        let mut from = 0;
        while let Some(i) = text[from..].find(start).map(|i| i + from) {
            from = i + start.len();
            if i > 0
                && (bytes[i - 1].is_ascii_alphanumeric()
                    || bytes[i - 1] == b'_'
                    || bytes[i - 1] == b':')
            {
                continue;
            }
            let mut base: Vec<String> = if start == "crate::" {
                Vec::new()
            } else {
                here[..here.len().saturating_sub(1)].to_vec()
            };
            let mut rest = &text[from..];
            while let Some(r) = rest.strip_prefix("super::") {
                base.pop();
                rest = r;
            }
            let end = rest
                .find(|c: char| !(c.is_alphanumeric() || c == '_' || c == ':'))
                .unwrap_or(rest.len());
            let head: Vec<String> = rest[..end]
                .split("::")
                .filter(|s| !s.is_empty())
                .map(str::to_string)
                .collect();
            let mut full = base.clone();
            full.extend(head);
            if rest[end..].starts_with('{') {
                let close = rest[end..].find('}').map_or(rest.len(), |c| c + end);
                for item in rest[end + 1..close].split(',') {
                    let mut p = full.clone();
                    p.extend(
                        item.trim()
                            .split("::")
                            .filter(|s| !s.is_empty() && *s != "self")
                            .map(|s| s.trim().to_string()),
                    );
                    out.push(p);
                }
            } else {
                out.push(full);
            }
        }
    }
    out
}

/// The longest prefix of `path` that is a module with a file.
fn resolve(path: &[String], modules: &BTreeSet<Vec<String>>) -> Option<Vec<String>> {
    (1..=path.len())
        .rev()
        .map(|n| path[..n].to_vec())
        .find(|p| modules.contains(p))
}

fn graph() -> BTreeMap<Vec<String>, BTreeSet<Vec<String>>> {
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let mut files = Vec::new();
    rust_files(&src, &mut files);
    let modules: BTreeSet<Vec<String>> = files
        .iter()
        .map(|f| module_of(&src, f))
        .filter(|m| !m.is_empty())
        .collect();
    let mut edges: BTreeMap<Vec<String>, BTreeSet<Vec<String>>> = BTreeMap::new();
    for file in &files {
        let here = module_of(&src, file);
        if here.is_empty() {
            continue; // lib.rs and main.rs only declare the top-level modules
        }
        let is_mod = file.file_name().is_some_and(|n| n == "mod.rs");
        let text = std::fs::read_to_string(file).unwrap();
        for p in paths(without_tests(&text), &here) {
            let Some(target) = resolve(&p, &modules) else {
                continue;
            };
            let own_child = is_mod && target.len() == here.len() + 1 && target.starts_with(&here);
            if target != here && !own_child && !here.starts_with(&target) {
                edges.entry(here.clone()).or_default().insert(target);
            }
        }
        edges.entry(here).or_default();
    }
    edges
}

/// A cycle through `start`, if any (depth-first search).
fn cycle(edges: &BTreeMap<Vec<String>, BTreeSet<Vec<String>>>) -> Option<Vec<Vec<String>>> {
    fn visit(
        n: &Vec<String>,
        edges: &BTreeMap<Vec<String>, BTreeSet<Vec<String>>>,
        state: &mut BTreeMap<Vec<String>, u8>,
        stack: &mut Vec<Vec<String>>,
    ) -> Option<Vec<Vec<String>>> {
        state.insert(n.clone(), 1);
        stack.push(n.clone());
        for m in edges.get(n).into_iter().flatten() {
            match state.get(m).copied().unwrap_or(0) {
                1 => {
                    let i = stack.iter().position(|s| s == m).unwrap();
                    let mut c = stack[i..].to_vec();
                    c.push(m.clone());
                    return Some(c);
                }
                0 => {
                    if let Some(c) = visit(m, edges, state, stack) {
                        return Some(c);
                    }
                }
                _ => {}
            }
        }
        stack.pop();
        state.insert(n.clone(), 2);
        None
    }
    let mut state = BTreeMap::new();
    for n in edges.keys() {
        if state.get(n).copied().unwrap_or(0) == 0 {
            if let Some(c) = visit(n, edges, &mut state, &mut Vec::new()) {
                return Some(c);
            }
        }
    }
    None
}

#[test]
fn no_file_imports_another_that_imports_it_back() {
    let edges = graph();
    assert!(
        edges.len() > 40,
        "the source tree was read ({} modules)",
        edges.len()
    );
    if let Some(c) = cycle(&edges) {
        let names: Vec<String> = c.iter().map(|m| m.join("::")).collect();
        panic!("import cycle: {}", names.join(" → "));
    }
}

#[test]
fn data_flows_one_way_between_the_top_level_modules() {
    let allowed: BTreeMap<&str, &[&str]> = LAYERS.iter().copied().collect();
    let mut wrong = Vec::new();
    for (from, targets) in graph() {
        for to in targets {
            let (a, b) = (from[0].as_str(), to[0].as_str());
            if a != b && !allowed.get(a).is_some_and(|ok| ok.contains(&b)) {
                wrong.push(format!("{} uses {}", from.join("::"), to.join("::")));
            }
        }
    }
    assert!(
        wrong.is_empty(),
        "against the layer order:\n{}",
        wrong.join("\n")
    );
}

#[test]
fn the_reader_finds_a_planted_cycle() {
    // The checker itself: two paths naming each other are a cycle, a chain is not.
    let m = |s: &str| s.split("::").map(str::to_string).collect::<Vec<_>>();
    let mut edges: BTreeMap<Vec<String>, BTreeSet<Vec<String>>> = BTreeMap::new();
    edges.entry(m("a::x")).or_default().insert(m("a::y"));
    edges.entry(m("a::y")).or_default().insert(m("a::z"));
    assert!(cycle(&edges).is_none());
    edges.entry(m("a::z")).or_default().insert(m("a::x"));
    assert_eq!(cycle(&edges).unwrap().len(), 4);
    let here = m("dynamics::stepper");
    let found = paths(
        "use super::state::{JointAngle, State};\nlet x = crate::model::PlateModel::new();",
        &here,
    );
    assert!(
        found.contains(&m("dynamics::state::JointAngle"))
            && found.contains(&m("model::PlateModel::new")),
        "{found:?}"
    );
}
