//! The lathe tool's chip contact on `contact_exponential` (docs/dynamics.md,
//! "The tool's chip contact"): at 1 kHz without substeps, the cut taken as a
//! function of the state within the step converges where `exponential`,
//! holding the cut over the substep, needs 16–64 substeps. Each cut of the
//! table (the shipped one, b = 5 mm, a feed of 0.2 mm/s, both) is run from
//! its first contact through its entry transient (the held cut's largest
//! errors, 10–30 ms into the cut) and one revolution on against the converged run, `exponential` in 1024
//! substeps, written separately as the reference; the finer feeds start
//! 0.05 mm above the face so that they too reach it at 0.25 s.

mod support;

use annular_plate::config::Config;
use annular_plate::dynamics::load_models::tool::ToolOutputs;
use annular_plate::dynamics::Simulation;
use support::scene_files::{text, NODE};

/// The run's end, s: 0.65 s of cutting, beyond one revolution (0.565 s),
/// so that the cut meets the surface it left.
const DURATION: f64 = 0.9;

/// The lathe with `edits` (text replacements of config/lathe.yaml) on
/// `integrator` in `substeps` substeps.
fn lathe(edits: &[(&str, &str)], integrator: &str, substeps: u32) -> Config {
    let mut yaml = text("lathe.yaml");
    for (from, to) in edits {
        assert!(yaml.contains(from), "config/lathe.yaml has no `{from}`");
        yaml = yaml.replacen(from, to, 1);
    }
    let simulation =
        format!("integrator: {integrator}\n      substeps: {substeps}\n      coordinates: ale");
    yaml = yaml.replacen(
        "integrator: exponential\n      coordinates: ale",
        &simulation,
        1,
    );
    Config::from_yaml_str(&yaml, NODE).unwrap()
}

/// Deflection under the tool and feed force at every step.
fn run(config: Config) -> Vec<[f64; 2]> {
    let mut sim = Simulation::new(config).unwrap();
    let mut out = Vec::new();
    while sim.time() < DURATION - 0.5 * sim.dt() {
        sim.step().unwrap();
        let force = sim.tool_output().unwrap().feed_force;
        out.push([sim.ale_node(0).uz, force]);
    }
    out
}

/// The largest error of column `c` of `run` against `reference`, over the
/// reference's peak in it.
fn error(run: &[[f64; 2]], reference: &[[f64; 2]], c: usize) -> f64 {
    let peak = reference.iter().map(|r| r[c].abs()).fold(0.0, f64::max);
    assert!(peak > 0.0, "the tool never cut");
    let worst = run
        .iter()
        .zip(reference)
        .map(|(a, b)| (a[c] - b[c]).abs())
        .fold(0.0, f64::max);
    worst / peak
}

/// (deflection, feed force) errors of `run` against `reference`.
fn errors(run: &[[f64; 2]], reference: &[[f64; 2]]) -> (f64, f64) {
    (error(run, reference, 0), error(run, reference, 1))
}

/// One cut: `contact_exponential` at 1 kHz within `bound` of the converged
/// run (deflection and force), and `exponential` at 1 kHz far outside it.
fn converges(name: &str, edits: &[(&str, &str)], bound: f64) {
    let reference = run(lathe(edits, "exponential", 1024));
    let contact = errors(&run(lathe(edits, "contact_exponential", 1)), &reference);
    let held = errors(&run(lathe(edits, "exponential", 1)), &reference);
    println!(
        "{name}: contact_exponential at 1 kHz {:.2e} / {:.2e}, exponential {:.2e} / {:.2e} \
         (deflection / feed force, of the peak)",
        contact.0, contact.1, held.0, held.1
    );
    assert!(
        contact.0 < bound && contact.1 < bound,
        "{name}: {contact:?}"
    );
    assert!(held.0 > 100.0 * bound, "{name}: the held cut {held:?}");
}

const FINE_FEED: [(&str, &str); 2] = [
    ("feed_rate: 0.002 ", "feed_rate: 0.0002 "),
    ("start_clearance: 0.0005 ", "start_clearance: 0.00005 "),
];

#[test]
fn the_shipped_cut_at_1_khz_converges_on_contact_exponential() {
    converges("shipped", &[], 1e-4);
}

#[test]
fn a_5_mm_cut_at_1_khz_converges_on_contact_exponential() {
    converges(
        "b = 5 mm",
        &[("depth_of_cut: 0.001 ", "depth_of_cut: 0.005 ")],
        1e-4,
    );
}

#[test]
fn a_fine_feed_at_1_khz_converges_on_contact_exponential() {
    converges("feed 0.2 mm/s", &FINE_FEED, 1e-4);
}

#[test]
fn a_5_mm_cut_at_a_fine_feed_at_1_khz_converges_on_contact_exponential() {
    let mut edits = FINE_FEED.to_vec();
    edits.push(("depth_of_cut: 0.001 ", "depth_of_cut: 0.005 "));
    converges("b = 5 mm, feed 0.2 mm/s", &edits, 1e-4);
}
