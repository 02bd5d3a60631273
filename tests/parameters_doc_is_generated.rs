//! Each parameter is declared once (`src/config/table.rs`): the reference in
//! docs/parameters.md and the key index in the README are what the table
//! generates (`UPDATE_DOCS=1` rewrites them), and every declared default is
//! what validation yields when the key is left out.

mod support;

use annular_plate::config::table::Value;
use annular_plate::config::{Config, Params};
use annular_plate::dynamics::load_models::PARAMETERS;
use annular_plate::messages::settings::RosSettings;
use std::path::Path;
use support::scene_files;

const BEGIN: &str = "<!-- generated from src/config/table.rs: begin -->\n";
const END: &str = "<!-- generated from src/config/table.rs: end -->";

/// Check (or with UPDATE_DOCS rewrite) the generated block of `file`.
fn generated_block(file: &str, generated: &str) {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join(file);
    let text = std::fs::read_to_string(&path).unwrap();
    let start = text
        .find(BEGIN)
        .unwrap_or_else(|| panic!("{file} has no `{}` marker", BEGIN.trim()))
        + BEGIN.len();
    let end = text[start..]
        .find(END)
        .unwrap_or_else(|| panic!("{file} has no end marker"))
        + start;
    if std::env::var_os("UPDATE_DOCS").is_some() {
        std::fs::write(
            &path,
            format!("{}{generated}{}", &text[..start], &text[end..]),
        )
        .unwrap();
        return;
    }
    let now = &text[start..end];
    for (i, (a, b)) in now.lines().zip(generated.lines()).enumerate() {
        assert_eq!(a, b, "{file}: line {} of the generated block differs from the table; run UPDATE_DOCS=1 cargo test --release --test parameters_doc_is_generated", i + 1);
    }
    assert_eq!(now, generated, "{file}: the generated block differs from the table; run UPDATE_DOCS=1 cargo test --release --test parameters_doc_is_generated");
}

#[test]
fn docs_parameters_md_is_what_the_table_generates() {
    generated_block("docs/parameters.md", &PARAMETERS.reference_markdown());
}

#[test]
fn the_readme_key_index_is_what_the_table_generates() {
    generated_block("README.md", &PARAMETERS.key_index_markdown());
}

#[test]
fn every_key_is_declared_once() {
    let keys: Vec<&str> = PARAMETERS.params().map(|p| p.key).collect();
    let mut unique = keys.clone();
    unique.sort();
    unique.dedup();
    assert_eq!(unique.len(), keys.len(), "a key is declared twice");
    assert_eq!(
        Config::known_keys(),
        keys,
        "the validator accepts exactly the declared keys"
    );
}

/// The base a section's default is checked on: a shipped scene that switches
/// the section on (load models), or nothing.
fn base_for(section: &str) -> Params {
    let file = match section {
        "pads" => Some("brake_bench.yaml"),
        "tool" => Some("lathe.yaml"),
        "links" => Some("swash_plate.yaml"),
        _ => None,
    };
    match (file, section) {
        (Some(f), _) => Params::from_file(&scene_files::path(f), scene_files::NODE).unwrap(),
        (None, "calipers") => {
            let text = "annular_plate:\n  ros__parameters:\n    calipers: {angles_deg: [0.0], inner_radius: 0.09, outer_radius: 0.14}\n";
            Params::from_yaml_str(text, scene_files::NODE).unwrap()
        }
        // Any other load model that names nodes: one node of each kind, the first one.
        (None, s)
            if PARAMETERS
                .enabled_by(s)
                .is_some_and(|k| k.ends_with("_nodes")) =>
        {
            let key = PARAMETERS.enabled_by(s).unwrap();
            let text = format!("annular_plate:\n  ros__parameters:\n    nodes: {{ale_radial: [1.0], ale_angular: [0.0], lagrange_radial: [1.0], lagrange_angular: [0.0]}}\n    {key}: [1]\n");
            Params::from_yaml_str(&text, scene_files::NODE).unwrap()
        }
        _ => Params::new(),
    }
}

#[test]
fn every_declared_default_is_what_leaving_the_key_out_yields() {
    let mut checked = 0;
    for section in PARAMETERS.sections() {
        let base = base_for(section.name);
        for p in section.params {
            let Some(value) = p.default.to_param() else {
                continue;
            };
            if base.get(p.key).is_some() {
                continue; // the scene sets it: its default is not what the scene runs
            }
            let mut with = base.clone();
            with.set(p.key, value).unwrap();
            if section.name == "ros" || p.key == "use_sim_time" {
                assert_eq!(
                    RosSettings::from_params(&with).unwrap(),
                    RosSettings::from_params(&base).unwrap(),
                    "{}",
                    p.key
                );
            } else {
                assert_eq!(
                    Config::from_params(&with).unwrap(),
                    Config::from_params(&base).unwrap(),
                    "{}: the declared default {:?} is not the default",
                    p.key,
                    p.default
                );
            }
            checked += 1;
        }
    }
    assert!(checked >= 50, "{checked} defaults checked");
    // A default that is not the default is found: the check can fail.
    let mut wrong = Params::new();
    wrong
        .set("plate.thickness", Value::Double(0.02).to_param().unwrap())
        .unwrap();
    assert_ne!(
        Config::from_params(&wrong).unwrap(),
        Config::from_params(&Params::new()).unwrap()
    );
}
