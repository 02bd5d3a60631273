//! docs/architecture.md names the code as it is: every source file it cites
//! in backticks exists under src/, every function, type or `path::name` it
//! cites is defined in src/ (a test name in tests/), and where it places a
//! function in a file — a numbered step of a walk through the code, or
//! "`name` in `file.rs`" — the function is defined in that file. The
//! functions of its code examples exist too.
//!
//! "Defined" is textual: `fn`, `struct`, `enum`, `trait`, `const`, `static`,
//! `type` or `mod` followed by the name, or a line that starts with the name
//! and a `:`, `,`, `(` or `{` (a field or an enum variant).

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

/// Names from outside this crate the document may cite.
const EXTERNAL: [&str; 2] = [
    "Default",            // std
    "Subscription::take", // ros2-client
];

fn repo() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// Every .rs file under src/ and tests/, by path relative to the repository.
fn sources() -> BTreeMap<String, String> {
    fn walk(root: &Path, dir: &Path, out: &mut BTreeMap<String, String>) {
        for e in std::fs::read_dir(dir).unwrap() {
            let p = e.unwrap().path();
            if p.is_dir() {
                walk(root, &p, out);
            } else if p.extension().is_some_and(|x| x == "rs") {
                let rel = p
                    .strip_prefix(root)
                    .unwrap()
                    .to_string_lossy()
                    .replace('\\', "/");
                out.insert(rel, std::fs::read_to_string(&p).unwrap());
            }
        }
    }
    let mut out = BTreeMap::new();
    walk(&repo(), &repo().join("src"), &mut out);
    walk(&repo(), &repo().join("tests"), &mut out);
    out
}

fn is_ident_char(c: char) -> bool {
    c.is_alphanumeric() || c == '_'
}

/// Whether `text` defines `name` (see the module docs).
fn defines(text: &str, name: &str) -> bool {
    const KEYWORDS: [&str; 8] = [
        "fn", "struct", "enum", "trait", "const", "static", "type", "mod",
    ];
    for line in text.lines() {
        let words: Vec<&str> = line
            .split(|c: char| !is_ident_char(c))
            .filter(|w| !w.is_empty())
            .collect();
        if words
            .windows(2)
            .any(|w| KEYWORDS.contains(&w[0]) && w[1] == name)
        {
            return true;
        }
        // a field or a variant: `[pub[(..)]] name` then `:`, `,`, `(`, `{` or the line's end
        let mut rest = line.trim_start();
        if let Some(r) = rest.strip_prefix("pub") {
            let r = r.trim_start();
            rest = match r.strip_prefix('(') {
                Some(r) => r
                    .split_once(')')
                    .map_or("", |(_, after)| after.trim_start()),
                None => r,
            };
        }
        if let Some(after) = rest.strip_prefix(name) {
            let after = after.trim_start();
            if after.is_empty()
                || after.starts_with([':', ',', '(', '{']) && !after.starts_with("::")
            {
                return true;
            }
        }
    }
    false
}

/// The source files a cited path names: `x/y.rs` or `y.rs` as a suffix under src/, or a path from the root.
fn resolve<'a>(sources: &'a BTreeMap<String, String>, cited: &str) -> Vec<&'a str> {
    sources
        .keys()
        .filter(|p| {
            *p == cited
                || (p.starts_with("src/")
                    && (p.ends_with(&format!("/{cited}")) || **p == format!("src/{cited}")))
        })
        .map(String::as_str)
        .collect()
}

/// A cited name: `a::b::c` or `f(args)`, and whether it looks like code
/// (a path, a call, snake_case with an underscore, or CamelCase).
fn name_of(span: &str) -> Option<Vec<&str>> {
    let head = span.split('(').next().unwrap();
    if head.is_empty()
        || !head.split("::").all(|s| {
            !s.is_empty()
                && s.chars().all(is_ident_char)
                && !s.starts_with(|c: char| c.is_ascii_digit())
        })
    {
        return None;
    }
    if span.contains('(') && !span.ends_with(')') {
        return None;
    }
    let segments: Vec<&str> = head.split("::").collect();
    let last = segments[segments.len() - 1];
    let looks = segments.len() > 1
        || span.contains('(')
        || last.contains('_')
        || last.starts_with(|c: char| c.is_ascii_uppercase());
    looks.then_some(segments)
}

fn spans(text: &str) -> Vec<&str> {
    text.split('`').skip(1).step_by(2).map(str::trim).collect()
}

/// The document without its fenced code blocks, and those blocks.
fn split_code(doc: &str) -> (String, Vec<String>) {
    let (mut prose, mut blocks, mut block) = (String::new(), Vec::new(), None::<String>);
    for line in doc.lines() {
        if line.trim_start().starts_with("```") {
            match block.take() {
                Some(b) => blocks.push(b),
                None => block = Some(String::new()),
            }
        } else if let Some(b) = block.as_mut() {
            b.push_str(line);
            b.push('\n');
        } else {
            prose.push_str(line);
            prose.push('\n');
        }
    }
    (prose, blocks)
}

/// Paragraphs, list items and table rows.
fn segments(prose: &str) -> Vec<String> {
    let mut out: Vec<String> = Vec::new();
    let mut current = String::new();
    for line in prose.lines() {
        let t = line.trim_start();
        let starts_item = t.starts_with("- ")
            || t.starts_with('|')
            || t.split_once(". ")
                .is_some_and(|(n, _)| !n.is_empty() && n.chars().all(|c| c.is_ascii_digit()));
        if t.is_empty() || starts_item {
            if !current.trim().is_empty() {
                out.push(std::mem::take(&mut current));
            }
            current.clear();
        }
        current.push_str(line);
        current.push('\n');
    }
    out.push(current);
    out
}

fn check(doc_path: &str) -> Vec<String> {
    let sources = sources();
    let in_src = |name: &str| {
        sources
            .iter()
            .any(|(p, t)| p.starts_with("src/") && defines(t, name))
    };
    let doc = std::fs::read_to_string(repo().join(doc_path)).unwrap();
    let (prose, blocks) = split_code(&doc);
    let mut problems = Vec::new();

    // Code examples: the functions they show, and the modules whose `build` they register.
    for b in &blocks {
        let words: Vec<&str> = b
            .split(|c: char| !is_ident_char(c))
            .filter(|w| !w.is_empty())
            .collect();
        for w in words.windows(2).filter(|w| w[0] == "fn") {
            if !in_src(w[1]) {
                problems.push(format!(
                    "code example: fn {} is defined nowhere in src/",
                    w[1]
                ));
            }
        }
        for (i, _) in b.match_indices("::build") {
            let module = b[..i].rsplit(|c: char| !is_ident_char(c)).next().unwrap();
            if resolve(&sources, &format!("{module}.rs")).is_empty() {
                problems.push(format!(
                    "code example: {module}::build, but there is no {module}.rs"
                ));
            }
        }
    }

    for seg in segments(&prose) {
        let cited = spans(&seg);
        let mut files: Vec<&str> = Vec::new();
        for s in &cited {
            if s.ends_with(".rs") && !s.contains(' ') {
                let found = resolve(&sources, s);
                if found.is_empty() {
                    problems.push(format!("`{s}`: no such file under src/"));
                }
                files.extend(found);
            } else if s.ends_with('/') && !s.contains(' ') && !s.starts_with('~') {
                let dir = s.trim_end_matches('/');
                if !sources
                    .keys()
                    .any(|p| p.contains(&format!("/{dir}/")) || p.starts_with(&format!("{dir}/")))
                {
                    problems.push(format!("`{s}`: no such directory"));
                }
            }
        }
        let numbered_step = seg
            .trim_start()
            .split_once(". ")
            .is_some_and(|(n, _)| n.chars().all(|c| c.is_ascii_digit()));
        for s in &cited {
            if EXTERNAL.contains(s) {
                continue;
            }
            let Some(segments) = name_of(s) else { continue };
            let pool =
                |name: &str| in_src(name) || files.iter().any(|f| defines(&sources[*f], name));
            if let Some(missing) = segments
                .iter()
                .find(|n| !["crate", "self", "super"].contains(n) && !pool(n))
            {
                problems.push(format!("`{s}`: `{missing}` is defined nowhere in src/"));
                continue;
            }
            // A function placed in a walk step's file is defined there.
            let last = segments[segments.len() - 1];
            let function = last.starts_with(|c: char| c.is_ascii_lowercase());
            if numbered_step
                && function
                && !files.is_empty()
                && !files.iter().any(|f| defines(&sources[*f], last))
            {
                problems.push(format!(
                    "`{s}` is not defined in the step's file(s) {files:?}: {}",
                    seg.trim()
                ));
            }
        }
        // "`name` in `file.rs`"
        for (i, _) in seg.match_indices("` in `") {
            let name = seg[..i].rsplit('`').next().unwrap();
            let file = seg[i + 6..].split('`').next().unwrap();
            let (Some(segments), true) = (name_of(name), file.ends_with(".rs")) else {
                continue;
            };
            let found = resolve(&sources, file);
            let last = segments[segments.len() - 1];
            if !found.is_empty() && !found.iter().any(|f| defines(&sources[*f], last)) {
                problems.push(format!(
                    "`{name}` is said to be in `{file}`, which does not define it"
                ));
            }
        }
    }
    problems
}

#[test]
fn every_name_docs_architecture_md_cites_exists() {
    let problems = check("docs/architecture.md");
    assert!(
        problems.is_empty(),
        "docs/architecture.md is out of date:\n{}",
        problems.join("\n")
    );
}

#[test]
fn the_check_catches_a_stale_name() {
    // What the document once said: a function that no longer exists, and one in the wrong file.
    let sources = sources();
    assert!(!sources.values().any(|t| defines(t, "spawn_input")));
    assert!(defines(
        &sources["src/config/model_sections.rs"],
        "no_other_keys"
    ));
    assert!(!defines(
        &sources["src/config/validate.rs"],
        "no_other_keys"
    ));
    assert!(
        defines(&sources["src/config/mod.rs"], "load_models"),
        "a field counts as defined"
    );
    assert_eq!(name_of("node_wrench(kind, j)"), Some(vec!["node_wrench"]));
    assert_eq!(
        name_of("Simulation::set_tool_feed"),
        Some(vec!["Simulation", "set_tool_feed"])
    );
    assert_eq!(name_of("plate"), None, "a plain word is not a code name");
    assert_eq!(name_of("~/ale_<j>/wrench"), None);
}
