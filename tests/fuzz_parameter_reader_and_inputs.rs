//! A bounded mutation fuzzer, run by every `cargo test`: parameter files made
//! from the shipped scenes and the inputs that once broke the reader (the
//! seeds), mutated many thousand times, go through the reader, the validator
//! and the model build; random commands go through the input contract. No
//! case may panic, take more than a second, or be refused without naming a
//! key, a line or a limit. The generator is seeded, so a failure reproduces;
//! `FUZZ_CASES` raises the count.

mod support;

use annular_plate::config::{Config, ConfigError};
use annular_plate::dynamics::{Command, NodeKind, Simulation, Wrench};
use annular_plate::model::PlateModel;
use std::panic::{catch_unwind, AssertUnwindSafe};
use std::time::{Duration, Instant};
use support::scene_files;

const NODE: &str = "annular_plate";

/// xorshift64*: small, seeded, the same on every machine.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        self.0.wrapping_mul(0x2545_f491_4f6c_dd1d)
    }
    fn below(&mut self, n: usize) -> usize {
        (self.next() % n as u64) as usize
    }
    fn pick<'a, T>(&mut self, items: &'a [T]) -> &'a T {
        &items[self.below(items.len())]
    }
}

/// Inputs that once broke the reader, as seeds.
fn seeds() -> Vec<String> {
    let plate = |line: &str| format!("annular_plate:\n  ros__parameters:\n    plate:\n      {line}\n");
    let mut s: Vec<String> = ["brake_bench.yaml", "brake_squeal.yaml", "brake_squeal_paper.yaml", "design_example.yaml", "lathe.yaml", "swash_plate.yaml"]
        .iter()
        .map(|f| scene_files::text(f))
        .collect();
    s.push(plate(&format!("damping: {}{}", "[".repeat(20_000), "]".repeat(20_000))));
    for line in ["density: 1.0e-308", "youngs_modulus: 1.0e+308", "youngs_modulus: 1.0e-308", "thickness: 5.0e-324"] {
        s.push(plate(line));
    }
    s
}

const NUMBERS: &[&str] = &[
    "0", "-0.0", "1", "-1", "1.0e308", "-1.0e308", "5.0e-324", "1.0e-308", ".nan", ".inf", "-.inf", "1e400", "99999999999999999999", "0x10",
    "2.5", "1e-12", "[]", "[1, 2]", "{a: 1}", "\"1.0\"", "true", "~",
];
const JUNK: &[&str] = &["[", "]", "{", "}", ":", "- ", "#", "\"", "'", "&a", "*a", "!!float", "\t", "  ", "\n", "ros__parameters:", "/**:"];

/// One random edit of the text.
fn mutate(text: &str, rng: &mut Rng) -> String {
    let mut lines: Vec<String> = text.lines().map(str::to_string).collect();
    if lines.is_empty() {
        return JUNK[rng.below(JUNK.len())].to_string();
    }
    let i = rng.below(lines.len());
    match rng.below(7) {
        0 => {
            // A value replaced: after the first ": " of the line.
            if let Some(p) = lines[i].find(": ") {
                lines[i] = format!("{}: {}", &lines[i][..p], rng.pick(NUMBERS));
            }
        }
        1 => {
            lines.remove(i);
        }
        2 => {
            let l = lines[i].clone();
            lines.insert(i, l);
        }
        3 => {
            let at = rng.below(lines[i].len() + 1);
            let at = (0..=at).rev().find(|&a| lines[i].is_char_boundary(a)).unwrap_or(0);
            let junk = JUNK[rng.below(JUNK.len())];
            lines[i].insert_str(at, junk);
        }
        4 => lines[i] = format!("{}{}", " ".repeat(rng.below(9)), lines[i].trim_start()),
        5 => {
            let keys = Config::known_keys();
            let key = rng.pick(&keys).to_string();
            lines.insert(i, format!("    {key}: {}", rng.pick(NUMBERS)));
        }
        _ => lines.truncate(i),
    }
    lines.join("\n")
}

/// What a refusal must say: a key (known, or as the file spells it), a line,
/// a limit or the file's structure.
fn names_where(e: &ConfigError, input: &str) -> bool {
    let text = e.to_string();
    let keys = Config::known_keys();
    let key_of = |l: &str| l.trim_end().strip_suffix(':').map(str::to_string).or_else(|| l.split_once(": ").map(|(k, _)| k.to_string()));
    let file_keys: Vec<String> = input.lines().filter_map(key_of).filter_map(|k| k.split_whitespace().last().map(str::to_string)).filter(|k| k.len() > 1).collect();
    keys.iter().any(|k| text.contains(k))
        || file_keys.iter().any(|k| text.contains(k.as_str()))
        || annular_plate::config::table::SECTIONS.iter().any(|s| !s.name.is_empty() && text.starts_with(s.name))
        || text.contains("line")
        || text.contains("ros__parameters")
        || text.contains("entry")
        || text.contains("parameter")
}

/// Read, validate and build one file; the refusal (if any) as text.
fn one_case(text: &str) -> Result<(), String> {
    let config = Config::from_yaml_str(text, NODE).map_err(|e| {
        assert!(names_where(&e, text), "refusal names no key, line or limit: {e}\n--- input ---\n{}", &text[..text.len().min(2000)]);
        e.to_string()
    })?;
    // Bounded work: large mode sets are what the model tests are for.
    if config.plate.mode_count() * config.plate.radial_splines.fixed().unwrap_or(200) <= 20_000 {
        PlateModel::new(&config.plate).map_err(|e| {
            let t = e.to_string();
            assert!(t.contains("plate."), "model refusal names no key: {t}");
            t
        })?;
    }
    Ok(())
}

#[test]
fn mutated_parameter_files_never_panic_hang_or_refuse_without_saying_where() {
    let cases: usize = std::env::var("FUZZ_CASES").ok().and_then(|v| v.parse().ok()).unwrap_or(10_000);
    let mut rng = Rng(0x9e37_79b9_7f4a_7c15);
    let seeds = seeds();
    let (mut accepted, mut refused) = (0, 0);
    for case in 0..cases {
        let mut text = rng.pick(&seeds).clone();
        for _ in 0..1 + rng.below(4) {
            text = mutate(&text, &mut rng);
        }
        let start = Instant::now();
        let outcome = catch_unwind(AssertUnwindSafe(|| one_case(&text)));
        let took = start.elapsed();
        let outcome = outcome.unwrap_or_else(|_| panic!("case {case} panicked on:\n{}", &text[..text.len().min(2000)]));
        assert!(took < Duration::from_secs(1), "case {case} took {took:?}:\n{}", &text[..text.len().min(2000)]);
        match outcome {
            Ok(()) => accepted += 1,
            Err(_) => refused += 1,
        }
    }
    // The mutations reach both sides of the validator.
    assert!(accepted > cases / 20 && refused > cases / 5, "{accepted} accepted, {refused} refused");
}

#[test]
fn random_commands_are_refused_or_held_never_half_applied() {
    let mut sim = Simulation::new(scene_files::load("brake_bench.yaml")).unwrap();
    let mut rng = Rng(0x2545_f491_4f6c_dd1d);
    let special = [f64::NAN, f64::INFINITY, -f64::INFINITY, f64::MAX, -f64::MAX, f64::MIN_POSITIVE, 0.0, -0.0, 1e7, 1e12];
    let value = |rng: &mut Rng| if rng.below(3) == 0 { special[rng.below(special.len())] } else { f64::from_bits(rng.next()) };
    for _ in 0..20_000 {
        let command = match rng.below(3) {
            0 => Command::Speed(value(&mut rng)),
            1 => {
                let kind = if rng.below(2) == 0 { NodeKind::Ale } else { NodeKind::Lagrange };
                let wrench = Wrench { force: [value(&mut rng), value(&mut rng), value(&mut rng)], moment: [value(&mut rng), 0.0, value(&mut rng)] };
                Command::Wrench { kind, node: rng.below(25), wrench }
            }
            _ => Command::Load { model: rng.below(3), command: rng.below(2), instance: rng.below(4), value: value(&mut rng) },
        };
        let before = sim.inputs().clone();
        match sim.command(command) {
            Ok(()) => {
                let i = sim.inputs();
                let held = match command {
                    Command::Speed(v) => i.speed_command == v,
                    Command::Wrench { kind: NodeKind::Ale, node, wrench } => i.ale[node] == wrench,
                    Command::Wrench { kind: NodeKind::Lagrange, node, wrench } => i.lagrange[node] == wrench,
                    Command::Load { model, instance, value, .. } => i.commands.values[model][instance] == value,
                };
                assert!(held, "an accepted command is held as given: {command:?}");
            }
            Err(e) => {
                assert_eq!(*sim.inputs(), before, "a refused command changed the inputs: {command:?}");
                assert!(!e.to_string().is_empty());
            }
        }
    }
    // Every held value is finite: no NaN can reach the state.
    let i = sim.inputs();
    assert!(i.speed_command.is_finite());
    assert!(i.ale.iter().chain(&i.lagrange).all(|w| w.force.iter().chain(&w.moment).all(|v| v.is_finite())));
    assert!(i.commands.values.iter().flatten().all(|v| v.is_finite()));
    sim.step().unwrap();
    assert!(sim.state().is_finite());
}
