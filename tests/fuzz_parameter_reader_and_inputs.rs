//! A bounded mutation fuzzer, run by every `cargo test`: parameter files made
//! from the shipped scenes and the inputs that once broke the reader (the
//! seeds), mutated many thousand times, go through the reader, the validator
//! and the model build; random commands go through the input contract. No
//! case may panic, take more than a second, or be refused without naming a
//! key, a line or a limit. Random parameter-service requests (names, types,
//! values) go through the node's handler in-process; random argument vectors
//! of `stability`, `stability merge`, `campbell`, `bag repair` and `plot` run
//! the binary, each within a time and memory bound, and none may panic.
//! The generator is seeded, so a failure reproduces; `FUZZ_CASES` and
//! `FUZZ_CLI_CASES` raise the counts.

mod support;

use annular_plate::config::{Config, ConfigError};
use annular_plate::dynamics::{Command, NodeKind, Simulation, Wrench};
use annular_plate::model::PlateModel;
use std::panic::{catch_unwind, AssertUnwindSafe};
use std::time::{Duration, Instant};
use support::bounded_run::run_bounded;
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
    let plate =
        |line: &str| format!("annular_plate:\n  ros__parameters:\n    plate:\n      {line}\n");
    let mut s: Vec<String> = [
        "brake_bench.yaml",
        "brake_squeal.yaml",
        "brake_squeal_paper.yaml",
        "design_example.yaml",
        "lathe.yaml",
        "swash_plate.yaml",
    ]
    .iter()
    .map(|f| scene_files::text(f))
    .collect();
    s.push(plate(&format!(
        "damping: {}{}",
        "[".repeat(20_000),
        "]".repeat(20_000)
    )));
    for line in [
        "density: 1.0e-308",
        "youngs_modulus: 1.0e+308",
        "youngs_modulus: 1.0e-308",
        "thickness: 5.0e-324",
    ] {
        s.push(plate(line));
    }
    s
}

const NUMBERS: &[&str] = &[
    "0",
    "-0.0",
    "1",
    "-1",
    "1.0e308",
    "-1.0e308",
    "5.0e-324",
    "1.0e-308",
    ".nan",
    ".inf",
    "-.inf",
    "1e400",
    "99999999999999999999",
    "0x10",
    "2.5",
    "1e-12",
    "[]",
    "[1, 2]",
    "{a: 1}",
    "\"1.0\"",
    "true",
    "~",
];
const JUNK: &[&str] = &[
    "[",
    "]",
    "{",
    "}",
    ":",
    "- ",
    "#",
    "\"",
    "'",
    "&a",
    "*a",
    "!!float",
    "\t",
    "  ",
    "\n",
    "ros__parameters:",
    "/**:",
];

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
            let at = (0..=at)
                .rev()
                .find(|&a| lines[i].is_char_boundary(a))
                .unwrap_or(0);
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
    let key_of = |l: &str| {
        l.trim_end()
            .strip_suffix(':')
            .map(str::to_string)
            .or_else(|| l.split_once(": ").map(|(k, _)| k.to_string()))
    };
    let file_keys: Vec<String> = input
        .lines()
        .filter_map(key_of)
        .filter_map(|k| k.split_whitespace().last().map(str::to_string))
        .filter(|k| k.len() > 1)
        .collect();
    keys.iter().any(|k| text.contains(k))
        || file_keys.iter().any(|k| text.contains(k.as_str()))
        || annular_plate::dynamics::load_models::PARAMETERS
            .sections()
            .any(|s| !s.name.is_empty() && text.starts_with(s.name))
        || text.contains("line")
        || text.contains("ros__parameters")
        || text.contains("entry")
        || text.contains("parameter")
}

/// Read, validate and build one file; the refusal (if any) as text.
fn one_case(text: &str) -> Result<(), String> {
    let config = Config::from_yaml_str(text, NODE).map_err(|e| {
        assert!(
            names_where(&e, text),
            "refusal names no key, line or limit: {e}\n--- input ---\n{}",
            &text[..text.len().min(2000)]
        );
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
    let cases: usize = std::env::var("FUZZ_CASES")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(10_000);
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
        let outcome = outcome.unwrap_or_else(|_| {
            panic!(
                "case {case} panicked on:\n{}",
                &text[..text.len().min(2000)]
            )
        });
        assert!(
            took < Duration::from_secs(1),
            "case {case} took {took:?}:\n{}",
            &text[..text.len().min(2000)]
        );
        match outcome {
            Ok(()) => accepted += 1,
            Err(_) => refused += 1,
        }
    }
    // The mutations reach both sides of the validator.
    assert!(
        accepted > cases / 20 && refused > cases / 5,
        "{accepted} accepted, {refused} refused"
    );
}

#[test]
fn random_commands_are_refused_or_held_never_half_applied() {
    let mut sim = Simulation::new(scene_files::load("brake_bench.yaml")).unwrap();
    let mut rng = Rng(0x2545_f491_4f6c_dd1d);
    let special = [
        f64::NAN,
        f64::INFINITY,
        -f64::INFINITY,
        f64::MAX,
        -f64::MAX,
        f64::MIN_POSITIVE,
        0.0,
        -0.0,
        1e7,
        1e12,
    ];
    let value = |rng: &mut Rng| {
        if rng.below(3) == 0 {
            special[rng.below(special.len())]
        } else {
            f64::from_bits(rng.next())
        }
    };
    for _ in 0..20_000 {
        let command = match rng.below(3) {
            0 => Command::Speed(value(&mut rng)),
            1 => {
                let kind = if rng.below(2) == 0 {
                    NodeKind::Ale
                } else {
                    NodeKind::Lagrange
                };
                let wrench = Wrench {
                    force: [value(&mut rng), value(&mut rng), value(&mut rng)],
                    moment: [value(&mut rng), 0.0, value(&mut rng)],
                };
                Command::Wrench {
                    kind,
                    node: rng.below(25),
                    wrench,
                }
            }
            _ => Command::Load {
                model: rng.below(3),
                command: rng.below(2),
                instance: rng.below(4),
                value: value(&mut rng),
            },
        };
        let before = sim.inputs().clone();
        match sim.command(command) {
            Ok(()) => {
                let i = sim.inputs();
                let held = match command {
                    Command::Speed(v) => i.speed_command == v,
                    Command::Wrench {
                        kind: NodeKind::Ale,
                        node,
                        wrench,
                    } => i.ale[node] == wrench,
                    Command::Wrench {
                        kind: NodeKind::Lagrange,
                        node,
                        wrench,
                    } => i.lagrange[node] == wrench,
                    Command::Load {
                        model,
                        instance,
                        value,
                        ..
                    } => i.commands.values[model][instance] == value,
                };
                assert!(held, "an accepted command is held as given: {command:?}");
            }
            Err(e) => {
                assert_eq!(
                    *sim.inputs(),
                    before,
                    "a refused command changed the inputs: {command:?}"
                );
                assert!(!e.to_string().is_empty());
            }
        }
    }
    // Every held value is finite: no NaN can reach the state.
    let i = sim.inputs();
    assert!(i.speed_command.is_finite());
    assert!(i.ale.iter().chain(&i.lagrange).all(|w| w
        .force
        .iter()
        .chain(&w.moment)
        .all(|v| v.is_finite())));
    assert!(i.commands.values.iter().flatten().all(|v| v.is_finite()));
    sim.step().unwrap();
    assert!(sim.state().is_finite());
}

/// A random ROS parameter value of any type, with the values that broke the node.
fn ros_value(rng: &mut Rng) -> ros2_client::ParameterValue {
    use ros2_client::ParameterValue as V;
    let doubles = [
        5e-324,
        1e-30,
        4.9e-23,
        0.0,
        -0.0,
        1.0,
        1e6,
        1e300,
        f64::MAX,
        -1.0,
        f64::INFINITY,
        f64::NEG_INFINITY,
        f64::NAN,
    ];
    let double = |rng: &mut Rng| {
        if rng.below(2) == 0 {
            *rng.pick(&doubles)
        } else {
            f64::from_bits(rng.next())
        }
    };
    let ints = [0, 1, -1, i64::MAX, i64::MIN, 1 << 53, 8, 4096];
    let int = |rng: &mut Rng| {
        if rng.below(2) == 0 {
            *rng.pick(&ints)
        } else {
            rng.next() as i64
        }
    };
    let strings = [
        "",
        "auto",
        "fast",
        "clamped",
        "enhanced",
        "step_aligned",
        "\u{0}",
        "\u{1F600}",
    ];
    let len = rng.below(4);
    match rng.below(10) {
        0 => V::Boolean(rng.below(2) == 0),
        1 => V::Integer(int(rng)),
        2 => V::Double(double(rng)),
        3 => V::String(rng.pick(&strings).to_string()),
        4 => V::BooleanArray(vec![true; len]),
        5 => V::IntegerArray((0..len).map(|_| int(rng)).collect()),
        6 => V::DoubleArray((0..len).map(|_| double(rng)).collect()),
        7 => V::StringArray((0..len).map(|_| rng.pick(&strings).to_string()).collect()),
        8 => V::ByteArray(vec![0; len]),
        _ => V::NotSet,
    }
}

#[test]
fn random_parameter_service_requests_are_answered_naming_the_key_and_never_stop_the_loop() {
    use annular_plate::messages::clock::Pacer;
    use annular_plate::messages::settings::RosSettings;
    use annular_plate::ros::inputs::StaleWrenches;
    use annular_plate::ros::params_service::{effective_parameters, ParamStore};
    use ros2_client::parameters::raw;
    let cases: usize = std::env::var("FUZZ_CASES")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(10_000);
    let mut rng = Rng(0x51_7cc1_b727_220a);
    let mut sim = Simulation::new(scene_files::load("brake_bench.yaml")).unwrap();
    let dt = sim.dt();
    let (mut factor, mut pacer) = (1.0, Pacer::new(dt, 1.0, Instant::now()));
    let mut stale = StaleWrenches::new(0.0, sim.n_ale_nodes(), sim.n_lagrange_nodes());
    let mut store = ParamStore::new(effective_parameters(
        &annular_plate::config::Params::new(),
        &RosSettings::default(),
    ));
    let keys: Vec<&str> = annular_plate::dynamics::load_models::PARAMETERS
        .params()
        .map(|p| p.key)
        .collect();
    let junk = [
        "",
        ".",
        "simulation.",
        "ros",
        "simulation.realtime_factor ",
        "SIMULATION.REALTIME_FACTOR",
        "a.b.c.d.e",
        "\u{0}",
    ];
    let start = Instant::now();
    let mut accepted = 0;
    for case in 0..cases {
        let requests: Vec<raw::Parameter> = (0..1 + rng.below(3))
            .map(|_| {
                let name = match rng.below(4) {
                    0 => rng.pick(&junk).to_string(),
                    1 => rng
                        .pick(&["simulation.realtime_factor", "ros.wrench_timeout"])
                        .to_string(),
                    _ => rng.pick(&keys).to_string(),
                };
                let mut value: raw::ParameterValue = ros_value(&mut rng).into();
                if rng.below(20) == 0 {
                    value.ptype = rng.next() as u8;
                }
                raw::Parameter { name, value }
            })
            .collect();
        let names: Vec<String> = requests.iter().map(|p| p.name.clone()).collect();
        let outcome = catch_unwind(AssertUnwindSafe(|| {
            let (results, changes) = if rng.below(2) == 0 {
                store.set(requests)
            } else {
                let (r, c) = store.set_atomically(requests);
                (vec![r.result], c)
            };
            (results, changes)
        }));
        let (results, changes) =
            outcome.unwrap_or_else(|_| panic!("case {case} panicked on {names:?}"));
        for (r, name) in results.iter().zip(&names) {
            if !r.successful && results.len() == names.len() {
                assert!(
                    r.reason.contains(name.as_str()),
                    "case {case}: the refusal of `{name}` does not name it: {}",
                    r.reason
                );
            }
        }
        accepted += changes.len();
        for c in changes {
            annular_plate::ros::sim_loop::apply_runtime(
                c,
                &mut factor,
                &mut pacer,
                &mut stale,
                dt,
                Instant::now(),
            );
        }
        pacer.stepped(Instant::now());
        if case % 100 == 0 {
            sim.step()
                .unwrap_or_else(|e| panic!("case {case}: the plate stopped stepping: {e}"));
        }
    }
    assert!(accepted > 0, "some requests are accepted");
    assert!(
        start.elapsed() < Duration::from_secs(30),
        "bounded time: {:?}",
        start.elapsed()
    );
}

/// One of `items`, owned.
fn ps(rng: &mut Rng, items: &[&str]) -> String {
    rng.pick(items).to_string()
}

/// A directory of hostile inputs for the command lines: text, empty and
/// garbage files, a bag dir with a damaged and a garbage MCAP, a small CSV.
fn cli_inputs() -> std::path::PathBuf {
    let d = std::env::temp_dir().join(format!("annular_plate_fuzz_cli_{}", std::process::id()));
    if d.join("ready").exists() {
        return d;
    }
    std::fs::create_dir_all(d.join("bag")).unwrap();
    std::fs::create_dir_all(d.join("empty_dir")).unwrap();
    std::fs::write(d.join("text.txt"), "hello, not what you expect\n").unwrap();
    std::fs::write(d.join("empty.json"), "").unwrap();
    std::fs::write(
        d.join("bag/a.mcap"),
        [
            0x89, b'M', b'C', b'A', b'P', 0x30, b'\r', b'\n', 1, 255, 255, 255, 255, 255, 255, 255,
            127,
        ],
    )
    .unwrap();
    std::fs::write(d.join("bag/b.mcap"), b"garbage").unwrap();
    let csv = "time,joint_position,joint_velocity,q1\n0,0,0,0\n0.5,1,0,0\n1,2,0,1e300\n";
    std::fs::write(d.join("run.csv"), csv).unwrap();
    std::fs::write(d.join("shard.json"), r#"{"params_digest":"x","speeds_rad_s":[1e308,-5],"mu":[0.1],"growth_rate":[[1]],"threshold_mu":[null],"mode":[[]],"shard":{"index":1,"count":18446744073709551615,"speeds_total":2,"speeds_from":0,"speeds_to":1}}"#).unwrap();
    std::fs::write(d.join("ready"), "").unwrap();
    d
}

#[test]
fn random_command_lines_never_panic_hang_or_grow_without_bound() {
    let cases: usize = std::env::var("FUZZ_CLI_CASES")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(60);
    let d = cli_inputs();
    let p = |name: &str| d.join(name).to_string_lossy().into_owned();
    let scenes = [
        scene_files::path("brake_squeal.yaml"),
        scene_files::path("design_example.yaml"),
    ]
    .map(|p| p.to_string_lossy().into_owned());
    let files: Vec<String> = vec![
        scenes[0].clone(),
        scenes[1].clone(),
        "/dev/zero".into(),
        "/nonexistent".into(),
        p("text.txt"),
        p("empty.json"),
        p("empty_dir"),
    ];
    let ranges = [
        "0:1:3",
        "1e300:1e301:2",
        "0:1e308:3",
        "-1:1:2",
        "nan:1:2",
        "0:1:0",
        "0:1:100000",
        "5:5:1",
        "1:0:2",
        "a:b:c",
        "",
        "0:1:18446744073709551616",
        "10:20:4",
        "0:2:3",
    ];
    let overrides = [
        "limits.max_speed:=1e301",
        "simulation.realtime_factor:=1e-30",
        "plate.centrifugal_stiffening:=true",
        "pads.friction_coefficient:=.nan",
        "bogus:=1",
        "limits.max_speed:=1e6",
    ];
    let mut rng = Rng(0x0bad_5eed_1234_5678);
    for case in 0..cases {
        let s = |x: &str| x.to_string();
        let mut args: Vec<String> = match rng.below(6) {
            0 => {
                let mut v = vec![
                    s("stability"),
                    rng.pick(&files).clone(),
                    s("--mu"),
                    ps(&mut rng, &ranges),
                    s("--speeds"),
                    ps(&mut rng, &ranges),
                ];
                // --max-cells bounds what a valid grid may cost; 2000 cells are well under a second.
                v.extend([s("--max-cells"), ps(&mut rng, &["0", "50", "2000"])]);
                if rng.below(2) == 0 {
                    v.extend([
                        s("--shard"),
                        ps(
                            &mut rng,
                            &[
                                "1/100",
                                "0/0",
                                "1/1",
                                "2/3",
                                "18446744073709551615/18446744073709551615",
                                "x",
                            ],
                        ),
                    ]);
                }
                if rng.below(3) == 0 {
                    v.extend([s("--threads"), ps(&mut rng, &["0", "1", "100000", "-1"])]);
                }
                v
            }
            1 => {
                let mut v = vec![s("campbell"), rng.pick(&files).clone()];
                if rng.below(4) != 0 {
                    v.extend([s("--speeds"), ps(&mut rng, &ranges)]);
                }
                v
            }
            2 => {
                let mut v = vec![s("stability"), s("merge")];
                for _ in 0..rng.below(3) {
                    v.push(
                        rng.pick(&[
                            p("shard.json"),
                            s("/dev/zero"),
                            p("text.txt"),
                            p("empty.json"),
                            s("/nonexistent"),
                        ])
                        .clone(),
                    );
                }
                v
            }
            3 => vec![
                s("bag"),
                s("repair"),
                rng.pick(&[p("bag"), p("empty_dir"), s("/nonexistent"), p("text.txt")])
                    .clone(),
            ],
            4 => {
                let csv = rng
                    .pick(&[p("run.csv"), s("/dev/zero"), p("text.txt"), p("empty.json")])
                    .clone();
                let mut v = vec![
                    s("plot"),
                    s("animate"),
                    csv,
                    s("--params"),
                    rng.pick(&files).clone(),
                    s("--out"),
                    d.join(format!("out{case}.gif"))
                        .to_string_lossy()
                        .into_owned(),
                ];
                v.extend([
                    s("--fps"),
                    ps(&mut rng, &["0", "25", "1000000"]),
                    s("--slowdown"),
                    ps(&mut rng, &["1e300", "1e-300", "nan", "1", "4"]),
                ]);
                v.extend([
                    s("--max-frames"),
                    ps(&mut rng, &["0", "10"]),
                    s("--size"),
                    ps(&mut rng, &["100x100", "99x99", "1x1", "100000x100000"]),
                    s("--quiet"),
                ]);
                v
            }
            _ => {
                let csv = rng
                    .pick(&[p("run.csv"), s("/dev/zero"), p("text.txt")])
                    .clone();
                vec![
                    s("plot"),
                    s("csv"),
                    csv,
                    s("--columns"),
                    ps(&mut rng, &["q1", "*", "nope", ""]),
                    s("--out"),
                    d.join(format!("out{case}.png"))
                        .to_string_lossy()
                        .into_owned(),
                ]
            }
        };
        if rng.below(4) == 0
            && matches!(args[0].as_str(), "stability" | "campbell")
            && args[1] != "merge"
        {
            args.extend([s("-p"), ps(&mut rng, &overrides)]);
        }
        let argv: Vec<&str> = args.iter().map(String::as_str).collect();
        let r = run_bounded(&argv, Duration::from_secs(30), None);
        assert!(
            r.code.is_some(),
            "case {case}: {argv:?} still running after 30 s"
        );
        assert!(
            !r.stderr.contains("panicked"),
            "case {case}: {argv:?} panicked:\n{}",
            r.stderr
        );
        assert!(
            matches!(r.code, Some(0..=2)),
            "case {case}: {argv:?} exited {:?}:\n{}",
            r.code,
            r.stderr
        );
        assert!(
            r.peak_kib < 1_000_000,
            "case {case}: {argv:?} peaked at {} KiB",
            r.peak_kib
        );
        if r.code != Some(0) {
            assert!(
                !r.stderr.trim().is_empty(),
                "case {case}: {argv:?} refused without a word"
            );
        }
    }
}
