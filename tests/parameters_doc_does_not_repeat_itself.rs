//! docs/parameters.md (generated from src/config/table.rs) says each thing
//! once: no paragraph and no sentence of prose appears twice. Table rows are per key and may share wording.

use std::collections::BTreeMap;

#[test]
fn no_paragraph_or_sentence_of_docs_parameters_md_is_repeated() {
    let text = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/docs/parameters.md"))
        .unwrap();
    let prose: Vec<&str> = text
        .split("\n\n")
        .map(str::trim)
        .filter(|p| !p.starts_with('|') && !p.starts_with('#') && p.len() > 60)
        .collect();
    assert!(prose.len() > 5, "the file has prose");
    let mut seen: BTreeMap<String, usize> = BTreeMap::new();
    // A repeated paragraph repeats its sentences: count sentences.
    for p in &prose {
        for sentence in p.split(". ").map(str::trim).filter(|s| s.len() > 60) {
            *seen.entry(sentence.to_string()).or_default() += 1;
        }
    }
    let repeated: Vec<_> = seen
        .iter()
        .filter(|(_, n)| **n > 1)
        .map(|(s, n)| format!("{n}× {s}"))
        .collect();
    assert!(
        repeated.is_empty(),
        "repeated in docs/parameters.md:\n{}",
        repeated.join("\n")
    );
}
