//! vendor/rustdds is the published rustdds 0.15.1 plus the patch series
//! vendor/rustdds/patches/NNNN-*.patch, and nothing else.
//!
//! The test fetches the crate from crates.io with cargo (a throwaway package
//! under target/ that depends on `rustdds = "=0.15.1"`; cargo checks the
//! registry's checksum and this test the SHA-256 below), unpacks it, keeps
//! the files this project vendors ([`VENDORED`]), applies every patch in
//! order with `git apply` (exact context: a patch that does not apply on the
//! pristine crate plus its predecessors fails), and compares the result with
//! vendor/rustdds byte for byte. vendor/rustdds/PATCH.md and patches/ are the
//! series' own files and take no part in the comparison. It needs `cargo`,
//! `git`, `tar` and `sha256sum` and the network to crates.io; without any of
//! them it fails.
//!
//! To change the fork: edit vendor/rustdds, then write the new or changed
//! patch from the difference between the tree this test rebuilds (left in
//! target/tmp/rustdds-rebuild/tree) and vendor/rustdds (vendor/rustdds/PATCH.md,
//! "Working on the series").

use std::{
    collections::BTreeMap,
    fs,
    path::{Path, PathBuf},
    process::Command,
};

/// SHA-256 of rustdds-0.15.1.crate as crates.io serves it (the checksum its
/// index records for that version).
const CRATE_SHA256: &str = "42683a88b9dc025d7d45771b88d20846443b4901ec4b045ca78b8dd316ab616f";

/// The files and directories of the published crate that vendor/rustdds
/// keeps. The rest (examples/, tests/, interop/, scripts/, .github/, the
/// maintainers' shell scripts and notes, .cargo_vcs_info.json, .gitignore)
/// is not needed to build the crate or run its unit tests; patch 0000 drops
/// the Cargo.toml targets of the examples and tests that go with them.
/// Cargo.lock is the crate's own, which its unit tests run against
/// (`--locked`).
const VENDORED: &[&str] = &[
    "Cargo.lock",
    "Cargo.toml",
    "Cargo.toml.orig",
    "LICENSE.md",
    "README.md",
    "rustfmt.toml",
    "src",
];

/// The series' own files in vendor/rustdds, not part of the crate.
const SERIES_FILES: &[&str] = &["PATCH.md", "patches"];

fn run(cmd: &mut Command) -> String {
    let out = cmd
        .output()
        .unwrap_or_else(|e| panic!("cannot run {cmd:?}: {e}"));
    assert!(
        out.status.success(),
        "{cmd:?} failed ({}):\n{}\n{}",
        out.status,
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8_lossy(&out.stdout).into_owned()
}

/// rustdds-0.15.1.crate from cargo's download cache, fetched there by cargo
/// through a throwaway package if it is not yet.
fn published_crate(work: &Path) -> PathBuf {
    let fetch = work.join("fetch");
    fs::create_dir_all(fetch.join("src")).unwrap();
    // `[workspace]`: its own workspace, so the project's [patch] (which
    // replaces rustdds by vendor/rustdds) does not apply to it.
    fs::write(
        fetch.join("Cargo.toml"),
        "[package]\nname = \"rustdds-pristine-fetch\"\nversion = \"0.0.0\"\nedition = \"2021\"\n\
         publish = false\n\n[dependencies]\nrustdds = \"=0.15.1\"\n\n[workspace]\n",
    )
    .unwrap();
    fs::write(fetch.join("src/lib.rs"), "").unwrap();
    // The project's lock as the starting point: cargo keeps the versions it
    // already has for rustdds's dependencies, so little else is downloaded.
    let project_lock = Path::new(env!("CARGO_MANIFEST_DIR")).join("Cargo.lock");
    if !fetch.join("Cargo.lock").exists() {
        fs::copy(project_lock, fetch.join("Cargo.lock")).unwrap();
    }
    let cargo = std::env::var("CARGO").unwrap_or_else(|_| "cargo".into());
    let host = run(Command::new("rustc").arg("-vV"))
        .lines()
        .find_map(|l| l.strip_prefix("host: ").map(str::to_owned))
        .expect("rustc -vV names the host");
    run(Command::new(&cargo)
        .args(["fetch", "--target", &host, "--manifest-path"])
        .arg(fetch.join("Cargo.toml")));
    let cargo_home = std::env::var_os("CARGO_HOME")
        .map(PathBuf::from)
        .unwrap_or_else(|| PathBuf::from(std::env::var_os("HOME").unwrap()).join(".cargo"));
    let cache = cargo_home.join("registry/cache");
    fs::read_dir(&cache)
        .unwrap_or_else(|e| panic!("{}: {e}", cache.display()))
        .map(|d| d.unwrap().path().join("rustdds-0.15.1.crate"))
        .find(|p| p.exists())
        .unwrap_or_else(|| {
            panic!(
                "cargo fetch left no rustdds-0.15.1.crate in {}",
                cache.display()
            )
        })
}

/// Every file under `root` (relative path → bytes), leaving out the
/// top-level entries in `skip`.
fn files(root: &Path, skip: &[&str]) -> BTreeMap<String, Vec<u8>> {
    fn walk(dir: &Path, root: &Path, out: &mut BTreeMap<String, Vec<u8>>) {
        for entry in fs::read_dir(dir).unwrap() {
            let path = entry.unwrap().path();
            if path.is_dir() {
                walk(&path, root, out);
            } else {
                let rel = path
                    .strip_prefix(root)
                    .unwrap()
                    .to_string_lossy()
                    .into_owned();
                out.insert(rel, fs::read(&path).unwrap());
            }
        }
    }
    let mut out = BTreeMap::new();
    for entry in fs::read_dir(root).unwrap() {
        let path = entry.unwrap().path();
        let name = path.file_name().unwrap().to_string_lossy().into_owned();
        if skip.contains(&name.as_str()) {
            continue;
        }
        if path.is_dir() {
            walk(&path, root, &mut out);
        } else {
            out.insert(name, fs::read(&path).unwrap());
        }
    }
    out
}

/// The series in order: vendor/rustdds/patches/NNNN-*.patch, numbered from
/// 0000 without a gap, each with a `git format-patch` header.
fn series(vendor: &Path) -> Vec<PathBuf> {
    let mut patches: Vec<PathBuf> = fs::read_dir(vendor.join("patches"))
        .unwrap()
        .map(|d| d.unwrap().path())
        .collect();
    patches.sort();
    assert!(!patches.is_empty(), "no patches in vendor/rustdds/patches");
    for (i, p) in patches.iter().enumerate() {
        let name = p.file_name().unwrap().to_string_lossy();
        assert!(
            name.ends_with(".patch") && name.starts_with(&format!("{i:04}-")),
            "{name}: expected {i:04}-*.patch (numbered from 0000 without a gap)"
        );
        let text = fs::read_to_string(p).unwrap();
        assert!(
            text.lines().any(|l| l.starts_with("From: "))
                && text.lines().any(|l| l.starts_with("Subject: [PATCH")),
            "{name}: no From:/Subject: header"
        );
    }
    patches
}

#[test]
fn vendored_rustdds_is_the_published_crate_plus_the_patch_series() {
    let vendor = Path::new(env!("CARGO_MANIFEST_DIR")).join("vendor/rustdds");
    let work = Path::new(env!("CARGO_TARGET_TMPDIR")).join("rustdds-rebuild");
    let patches = series(&vendor);

    let krate = published_crate(&work);
    let sum = run(Command::new("sha256sum").arg(&krate));
    assert_eq!(
        sum.split_whitespace().next(),
        Some(CRATE_SHA256),
        "{} is not the rustdds 0.15.1 this series applies to",
        krate.display()
    );

    let unpacked = work.join("unpacked");
    let tree = work.join("tree");
    for dir in [&unpacked, &tree] {
        if dir.exists() {
            fs::remove_dir_all(dir).unwrap();
        }
        fs::create_dir_all(dir).unwrap();
    }
    run(Command::new("tar")
        .arg("xzf")
        .arg(&krate)
        .arg("-C")
        .arg(&unpacked));
    let published = unpacked.join("rustdds-0.15.1");
    for name in VENDORED {
        run(Command::new("cp")
            .arg("-R")
            .arg(published.join(name))
            .arg(&tree));
    }
    for patch in &patches {
        // Outside any repository (the ceiling stops git from finding the
        // project's), `git apply` patches the files under the current
        // directory, refusing a hunk whose context differs.
        run(Command::new("git")
            .current_dir(&tree)
            .env("GIT_CEILING_DIRECTORIES", &work)
            .args(["apply", "--verbose", "-p1"])
            .arg(patch));
    }

    let rebuilt = files(&tree, &[]);
    let vendored = files(&vendor, SERIES_FILES);
    let only_rebuilt: Vec<_> = rebuilt
        .keys()
        .filter(|k| !vendored.contains_key(*k))
        .collect();
    let only_vendored: Vec<_> = vendored
        .keys()
        .filter(|k| !rebuilt.contains_key(*k))
        .collect();
    let differ: Vec<_> = rebuilt
        .iter()
        .filter(|(k, v)| vendored.get(*k).is_some_and(|w| w != *v))
        .map(|(k, _)| k)
        .collect();
    assert!(
        only_rebuilt.is_empty() && only_vendored.is_empty() && differ.is_empty(),
        "vendor/rustdds is not rustdds 0.15.1 plus its {} patches (rebuilt tree: {}):\n\
         only in the rebuilt tree: {only_rebuilt:?}\nonly in vendor/rustdds: {only_vendored:?}\n\
         different: {differ:?}",
        patches.len(),
        tree.display()
    );
    assert!(
        rebuilt.len() > 100,
        "{} files: not the crate",
        rebuilt.len()
    );
}

/// Whether `text` has `word` as a whole identifier.
fn has_ident(text: &str, word: &str) -> bool {
    let is_ident = |c: char| c.is_alphanumeric() || c == '_';
    text.match_indices(word).any(|(i, _)| {
        !text[..i].chars().next_back().is_some_and(is_ident)
            && !text[i + word.len()..].chars().next().is_some_and(is_ident)
    })
}

/// The public names the series adds: `pub fn|struct|enum|const|type|trait
/// NAME` and the names of `pub use` lines (`pub(crate)` is not public).
fn names_the_series_adds(vendor: &Path) -> Vec<String> {
    let mut names = Vec::new();
    for patch in series(vendor) {
        for line in fs::read_to_string(&patch).unwrap().lines() {
            let Some(added) = line.strip_prefix('+') else {
                continue;
            };
            let Some(item) = added.trim_start().strip_prefix("pub ") else {
                continue;
            };
            if let Some(used) = item.strip_prefix("use ") {
                let list = used.rsplit("::").next().unwrap();
                names.extend(
                    list.trim_matches(|c| matches!(c, '{' | '}' | ';' | ' '))
                        .split(',')
                        .map(|n| n.trim().to_owned()),
                );
            } else if let Some(rest) = ["fn ", "struct ", "enum ", "const ", "type ", "trait "]
                .iter()
                .find_map(|kw| item.strip_prefix(kw))
            {
                let name: String = rest
                    .chars()
                    .take_while(|c| c.is_alphanumeric() || *c == '_')
                    .collect();
                names.push(name);
            }
        }
    }
    names.sort();
    names.dedup();
    names.retain(|n| !n.is_empty());
    names
}

/// Every public name the series adds that the node's code (src/) uses is
/// listed in PATCH.md's section on the fork's API, which says why it is
/// needed; and every name listed there is still used.
#[test]
fn the_node_uses_only_the_fork_api_patch_md_lists() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let vendor = root.join("vendor/rustdds");
    let mut node = String::new();
    fn read_rs(dir: &Path, out: &mut String) {
        for entry in fs::read_dir(dir).unwrap() {
            let path = entry.unwrap().path();
            if path.is_dir() {
                read_rs(&path, out);
            } else if path.extension().is_some_and(|x| x == "rs") {
                out.push_str(&fs::read_to_string(&path).unwrap());
            }
        }
    }
    read_rs(&root.join("src"), &mut node);
    let patch_md = fs::read_to_string(vendor.join("PATCH.md")).unwrap();
    let heading = "## The fork's API that annular_plate uses";
    let start = patch_md
        .find(heading)
        .unwrap_or_else(|| panic!("PATCH.md has no `{heading}`"));
    let section = &patch_md[start + heading.len()..];
    let section = &section[..section.find("\n## ").unwrap_or(section.len())];

    let added = names_the_series_adds(&vendor);
    assert!(
        added.iter().any(|n| n == "defer_wakes"),
        "the series' public names were not found: {added:?}"
    );
    let used: Vec<&String> = added.iter().filter(|n| has_ident(&node, n)).collect();
    let unlisted: Vec<_> = used.iter().filter(|n| !has_ident(section, n)).collect();
    assert!(
        unlisted.is_empty(),
        "src/ uses fork-only API that PATCH.md does not list and justify: {unlisted:?}"
    );
    let stale: Vec<_> = added
        .iter()
        .filter(|n| has_ident(section, n) && !has_ident(&node, n))
        .collect();
    assert!(
        stale.is_empty(),
        "PATCH.md lists fork API that src/ no longer uses: {stale:?}"
    );
}
