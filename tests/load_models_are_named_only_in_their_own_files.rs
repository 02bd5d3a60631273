//! Outside a load model's own files no code names its concrete types or its
//! message: the node, the CSV writer, the recorder, the messages, the linear
//! stability analysis and the `Simulation` facade reach every model through
//! its declaration (the registry's outputs: channels, CSV columns, topic; the
//! trait's linearisation). Read from the sources, with no exception:
//!
//! - the names a model owns are the types its files define (`struct`,
//!   `enum`, `trait`, `type`) and the message its declared topic names
//!   (`message: "PadStates"`);
//! - no other file under src/ spells one of them in code (comments aside);
//! - only a model's own files downcast to it (`find::<`, `scratch::<`, and
//!   `section::<` for its validated parameter section);
//! - so its parameter section's type (`PadsConfig`, `ToolConfig`, …), which
//!   its own files define, is named nowhere else either.

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

/// Each model's own files, under src/dynamics/load_models/.
const FAMILIES: &[(&str, &[&str])] = &[
    (
        "pads",
        &[
            "pad.rs",
            "pad_config.rs",
            "pad_calipers.rs",
            "pad_contact_law.rs",
            "pad_in_plane.rs",
            "pad_friction_damping.rs",
            "pad_tests.rs",
            "pad_linear.rs",
            "pad_linear_in_plane.rs",
            "pad_linear_mass.rs",
            "pad_linear_shear.rs",
            "pad_mass.rs",
            "pad_series.rs",
            "pad_shear.rs",
            "pad_patch.rs",
            "pad_outputs.rs",
            "face_friction.rs",
        ],
    ),
    (
        "tool",
        &[
            "tool.rs",
            "tool_config.rs",
            "tool_cutting.rs",
            "tool_in_step.rs",
            "tool_step.rs",
        ],
    ),
    ("links", &["pitch_link.rs"]),
    ("springs", &["point_spring.rs"]),
    ("dampers", &["point_damper.rs"]),
];

/// The machinery that defines the downcast for the models' own use.
const GENERIC: &[&str] = &[
    "src/dynamics/load_models/mod.rs",
    "src/dynamics/load_models/model.rs",
    "src/config/model_sections.rs",
];

fn repo() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

fn sources(dir: &Path, out: &mut BTreeMap<String, String>) {
    for e in std::fs::read_dir(dir).unwrap() {
        let p = e.unwrap().path();
        if p.is_dir() {
            sources(&p, out);
        } else if p.extension().is_some_and(|x| x == "rs") {
            let rel = p.strip_prefix(repo()).unwrap().to_string_lossy();
            out.insert(rel.replace('\\', "/"), std::fs::read_to_string(&p).unwrap());
        }
    }
}

/// The text without comments (`//` to the end of a line, outside strings).
fn code(text: &str) -> String {
    let mut out = String::new();
    for line in text.lines() {
        let mut in_str = false;
        let mut prev = ' ';
        let mut end = line.len();
        for (i, c) in line.char_indices() {
            if c == '"' && prev != '\\' {
                in_str = !in_str;
            }
            if !in_str && c == '/' && prev == '/' {
                end = i - 1;
                break;
            }
            prev = c;
        }
        out.push_str(&line[..end]);
        out.push('\n');
    }
    out
}

fn is_ident(c: char) -> bool {
    c.is_alphanumeric() || c == '_'
}

/// Whether `text` has `word` as a whole identifier.
fn names(text: &str, word: &str) -> bool {
    text.match_indices(word).any(|(i, _)| {
        let before = text[..i].chars().next_back().is_none_or(|c| !is_ident(c));
        let after = text[i + word.len()..]
            .chars()
            .next()
            .is_none_or(|c| !is_ident(c));
        before && after
    })
}

/// The names a model's files own: their types and their topic's message.
fn owned(files: &[&String]) -> Vec<String> {
    let mut out = Vec::new();
    for text in files {
        let words: Vec<&str> = text.split(|c: char| !is_ident(c)).collect();
        for w in words.windows(2) {
            let defines = matches!(w[0], "struct" | "enum" | "trait" | "type");
            if defines && w[1].starts_with(char::is_uppercase) {
                out.push(w[1].to_string());
            }
        }
        for part in text.split("message: \"").skip(1) {
            out.push(part.split('"').next().unwrap().to_string());
        }
    }
    out.sort();
    out.dedup();
    out
}

fn family_files(family: &str) -> Vec<String> {
    let (_, files) = FAMILIES.iter().find(|(f, _)| *f == family).unwrap();
    files
        .iter()
        .map(|f| format!("src/dynamics/load_models/{f}"))
        .collect()
}

#[test]
fn no_file_outside_a_model_names_its_types_or_its_message() {
    let mut src = BTreeMap::new();
    sources(&repo().join("src"), &mut src);
    let mut offences = Vec::new();
    for (family, _) in FAMILIES {
        let own = family_files(family);
        let texts: Vec<&String> = own.iter().map(|f| &src[f]).collect();
        let words = owned(&texts);
        assert!(!words.is_empty(), "{family} owns no names");
        for (path, text) in &src {
            if own.contains(path) {
                continue;
            }
            let code = code(text);
            for w in words.iter().filter(|w| names(&code, w)) {
                offences.push(format!("{path} names {w} ({family})"));
            }
        }
    }
    assert!(offences.is_empty(), "{}", offences.join("\n"));
}

#[test]
fn only_a_model_downcasts_to_itself() {
    let mut src = BTreeMap::new();
    sources(&repo().join("src"), &mut src);
    let own: Vec<String> = FAMILIES.iter().flat_map(|(f, _)| family_files(f)).collect();
    for (path, text) in &src {
        if own.contains(path) || GENERIC.contains(&path.as_str()) {
            continue;
        }
        let code = code(text);
        for pattern in [
            "find::<",
            "scratch::<",
            ".as_any()",
            "section::<",
            "section_mut::<",
        ] {
            assert!(!code.contains(pattern), "{path} downcasts ({pattern})");
        }
    }
}

/// The parameter sections are among the names the models own (so the scan
/// above keeps them out of every other file).
#[test]
fn each_model_owns_its_parameter_section() {
    let mut src = BTreeMap::new();
    sources(&repo().join("src"), &mut src);
    for (family, section) in [
        ("pads", "PadsConfig"),
        ("pads", "PadContact"),
        ("pads", "Caliper"),
        ("pads", "ContactSurface"),
        ("tool", "ToolConfig"),
        ("links", "LinksConfig"),
        ("springs", "SpringsConfig"),
        ("dampers", "DampersConfig"),
    ] {
        let files = family_files(family);
        let texts: Vec<&String> = files.iter().map(|f| &src[f]).collect();
        assert!(
            owned(&texts).iter().any(|w| w == section),
            "{family} does not define {section}"
        );
    }
}

#[test]
fn the_scan_sees_what_it_looks_for() {
    assert!(names("let p: Pads = x;", "Pads"));
    assert!(!names("let p: PadsX = x;", "Pads"));
    assert!(!names(&code("let x = 1; // Pads"), "Pads"));
    assert!(names(&code("let t = \"a//b\"; Tool::tip()"), "Tool"));
    let text = "pub struct Pads {}\nconst O: X = X { message: \"PadStates\" };".to_string();
    assert_eq!(owned(&[&text]), ["PadStates", "Pads"]);
}
