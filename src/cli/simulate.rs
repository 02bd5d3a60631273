//! `annular_plate simulate FILE --duration S --csv OUT`: an offline run.
//!
//! Columns: time, joint_position, joint_velocity, q1..qN (Lagrangian, mode
//! order of `modes`), qale1..qaleN, ale{j}_uz, lagrange{j}_uz (m).

use crate::dynamics::Simulation;
use std::io::Write;

/// The CSV header for a simulation.
pub fn header(sim: &Simulation) -> String {
    let n = sim.model().n_modes();
    let mut cols = vec!["time".to_string(), "joint_position".into(), "joint_velocity".into()];
    cols.extend((1..=n).map(|i| format!("q{i}")));
    cols.extend((1..=n).map(|i| format!("qale{i}")));
    cols.extend((1..=sim.n_ale_nodes()).map(|j| format!("ale{j}_uz")));
    cols.extend((1..=sim.n_lagrange_nodes()).map(|j| format!("lagrange{j}_uz")));
    cols.join(",")
}

/// One CSV row of the current state (shortest round-trip formatting).
pub fn write_row(sim: &Simulation, line: &mut String) {
    use std::fmt::Write as _;
    line.clear();
    let j = sim.joint();
    let _ = write!(line, "{},{},{}", sim.time(), j.position, j.velocity);
    for v in sim.q_lagrange().iter().chain(sim.q_ale()) {
        let _ = write!(line, ",{v:e}");
    }
    for i in 0..sim.n_ale_nodes() {
        let _ = write!(line, ",{:e}", sim.ale_node(i).uz);
    }
    for i in 0..sim.n_lagrange_nodes() {
        let _ = write!(line, ",{:e}", sim.lagrange_node(i).uz);
    }
}

/// Run for `duration` seconds writing a row per output step (t = 0 included).
/// `progress` is called with the fraction done.
pub fn run(sim: &mut Simulation, duration: f64, out: &mut impl Write, mut progress: impl FnMut(f64)) -> anyhow::Result<u64> {
    let steps = (duration / sim.dt()).round() as u64;
    writeln!(out, "{}", header(sim))?;
    let mut line = String::with_capacity(4096);
    write_row(sim, &mut line);
    writeln!(out, "{line}")?;
    let report_every = (steps / 200).max(1);
    for s in 1..=steps {
        sim.step().map_err(|e| anyhow::anyhow!("{e}"))?;
        write_row(sim, &mut line);
        writeln!(out, "{line}")?;
        if s % report_every == 0 {
            progress(s as f64 / steps as f64);
        }
    }
    Ok(steps)
}
