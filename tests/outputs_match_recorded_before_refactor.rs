//! The CSV and the bag of every shipped scene are the ones recorded before the
//! restructuring of the house issue (tests/golden/, written by this test with
//! `GOLDEN_RECORD=1` from the code as it was): restructuring changes no number.
//!
//! Each golden file holds, per scene: the row count and an FNV-1a digest of the
//! whole CSV text, every 100th row verbatim (so a difference shows where it
//! starts), and per bag topic the message count and a digest of the log times
//! and CDR payloads. `/diagnostics` is left out of the bag digest: it carries
//! the wall-clock cost of the steps.
//!
//! The brake scenes moved to Mindlin theory: with `-p plate.theory:=kirchhoff`
//! they write their recorded Kirchhoff output unchanged, and their Mindlin
//! output as shipped has golden files of its own (`*_mindlin.txt`).

use std::collections::BTreeMap;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use std::process::Command;

/// Scene file and simulated duration (s): long enough for each scene's events
/// (the lathe's first cut at 0.25 s and the steady cut after one revolution,
/// the swash plate's cycles, the squeal's growth, the bench's clamping).
const SCENES: &[(&str, f64)] = &[
    ("brake_bench.yaml", 2.0),
    ("brake_squeal.yaml", 1.0),
    ("brake_squeal_paper.yaml", 1.0),
    ("design_example.yaml", 1.0),
    ("lathe.yaml", 5.5),
    ("swash_plate.yaml", 5.0),
];

/// Scenes that moved to Mindlin theory after their golden file was recorded:
/// run with `-p plate.theory:=kirchhoff` they still write the recorded output
/// bit for bit (tests/golden/<scene>.txt); as shipped, their Mindlin output is
/// recorded in tests/golden/<scene>_mindlin.txt.
const MINDLIN: &[&str] = &["brake_bench.yaml", "brake_squeal.yaml"];

/// Scenes whose integrator or step count changed since their golden file
/// was recorded run with the settings it was recorded with, per theory (the
/// numbers of the new ones are checked against a converged reference in
/// brake_scenes_match_a_converged_reference.rs). brake_squeal's RK4 substeps
/// were set by its patches' relaxation k_t/c_t, counted as a mode's rate:
/// 62 a step under Kirchhoff theory, which its shipped step limit on the modes
/// alone makes 65 (under Mindlin theory it keeps 61).
const RECORDED_WITH: &[(&str, Theory, &str)] = &[(
    "brake_squeal.yaml",
    Theory::Kirchhoff,
    "simulation.rk4_step_limit:=0.0445",
)];

const ROW_SAMPLE: usize = 100;

/// 64-bit FNV-1a: a digest that is the same on every machine and Rust version.
struct Fnv(u64);

impl Fnv {
    fn new() -> Fnv {
        Fnv(0xcbf2_9ce4_8422_2325)
    }
    fn write(&mut self, bytes: &[u8]) {
        for &b in bytes {
            self.0 ^= b as u64;
            self.0 = self.0.wrapping_mul(0x0100_0000_01b3);
        }
    }
}

fn root() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

/// How a scene is run against a golden file: as shipped, or with Kirchhoff
/// theory pinned.
#[derive(Clone, Copy, PartialEq)]
enum Theory {
    Shipped,
    Kirchhoff,
}

fn simulate(scene: &str, theory: Theory, duration: f64, extra: &[&str]) -> Vec<u8> {
    let file = root().join("config").join(scene);
    let mut recorded: Vec<&str> = RECORDED_WITH
        .iter()
        .filter(|(s, t, _)| *s == scene && *t == theory)
        .flat_map(|(_, _, p)| ["-p", p])
        .collect();
    if let Theory::Kirchhoff = theory {
        recorded.extend(["-p", "plate.theory:=kirchhoff"]);
    }
    let out = Command::new(env!("CARGO_BIN_EXE_annular_plate"))
        .args([
            "simulate",
            file.to_str().unwrap(),
            "--duration",
            &duration.to_string(),
            "--quiet",
        ])
        .args(extra)
        .args(&recorded)
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "simulate {scene}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    out.stdout
}

fn csv_summary(csv: &str) -> String {
    let mut h = Fnv::new();
    h.write(csv.as_bytes());
    let lines: Vec<&str> = csv.lines().collect();
    let mut s = format!("csv rows {} digest {:016x}\n", lines.len(), h.0);
    for (i, line) in lines
        .iter()
        .enumerate()
        .filter(|(i, _)| i % ROW_SAMPLE == 0)
    {
        writeln!(s, "row {i}: {line}").unwrap();
    }
    s
}

fn bag_summary(dir: &Path) -> String {
    let mcap = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .find(|p| p.extension().is_some_and(|e| e == "mcap"))
        .expect("the bag has an .mcap file");
    let bytes = std::fs::read(mcap).unwrap();
    let mut topics: BTreeMap<String, (usize, Fnv)> = BTreeMap::new();
    for message in mcap::MessageStream::new(&bytes).unwrap() {
        let m = message.unwrap();
        let topic = m.channel.topic.clone();
        if topic == "/diagnostics" {
            continue;
        }
        let entry = topics.entry(topic).or_insert_with(|| (0, Fnv::new()));
        entry.0 += 1;
        entry.1.write(&m.log_time.to_le_bytes());
        entry.1.write(&m.publish_time.to_le_bytes());
        entry.1.write(&m.data);
    }
    topics
        .iter()
        .map(|(t, (n, h))| format!("bag {t} messages {n} digest {:016x}\n", h.0))
        .collect()
}

fn golden_path(scene: &str, theory: Theory) -> PathBuf {
    let stem = scene.trim_end_matches(".yaml");
    let name = match theory {
        Theory::Kirchhoff => format!("{stem}.txt"),
        Theory::Shipped if MINDLIN.contains(&scene) => format!("{stem}_mindlin.txt"),
        Theory::Shipped => format!("{stem}.txt"),
    };
    root().join("tests/golden").join(name)
}

fn summary(scene: &str, theory: Theory, duration: f64) -> String {
    let csv = String::from_utf8(simulate(scene, theory, duration, &["--csv", "-"])).unwrap();
    let tmp = std::env::temp_dir().join(format!("golden-bag-{}-{scene}", std::process::id()));
    let _ = std::fs::remove_dir_all(&tmp);
    simulate(scene, theory, duration, &["--bag", tmp.to_str().unwrap()]);
    let bag = bag_summary(&tmp);
    std::fs::remove_dir_all(&tmp).unwrap();
    format!(
        "scene {scene} duration {duration}\n{}{bag}",
        csv_summary(&csv)
    )
}

/// Every scene as shipped, and the scenes that moved to Mindlin theory once
/// more with Kirchhoff theory pinned.
fn runs() -> Vec<(&'static str, Theory, f64)> {
    let mut runs: Vec<_> = SCENES
        .iter()
        .map(|&(scene, duration)| (scene, Theory::Shipped, duration))
        .collect();
    for &(scene, duration) in SCENES.iter().filter(|(s, _)| MINDLIN.contains(s)) {
        runs.push((scene, Theory::Kirchhoff, duration));
    }
    runs
}

#[test]
fn every_shipped_scene_writes_the_csv_and_bag_recorded_before_the_restructuring() {
    let record = std::env::var_os("GOLDEN_RECORD").is_some();
    for (scene, theory, duration) in runs() {
        let now = summary(scene, theory, duration);
        let path = golden_path(scene, theory);
        if record {
            std::fs::create_dir_all(path.parent().unwrap()).unwrap();
            std::fs::write(&path, &now).unwrap();
            continue;
        }
        let before =
            std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
        for (i, (a, b)) in before.lines().zip(now.lines()).enumerate() {
            assert_eq!(
                a,
                b,
                "{scene}: line {} of {} differs from the recorded output",
                i + 1,
                path.display()
            );
        }
        assert_eq!(
            before.lines().count(),
            now.lines().count(),
            "{scene}: line count differs from {}",
            path.display()
        );
    }
}
