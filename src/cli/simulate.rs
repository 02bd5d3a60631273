//! `annular_plate simulate FILE --duration S --csv OUT [--bag DIR]`: an offline run
//! (the bag: `bag::offline`, through `cli::record`).
//!
//! Columns: time, joint_position, joint_velocity, q1..qN (Lagrangian, mode
//! order of `modes`), qale1..qaleN, ale{j}_uz, lagrange{j}_uz (m); with
//! in-plane modes ale{j}_ux, ale{j}_uy, then lagrange{j}_ux, lagrange{j}_uy
//! (m, the nodes' in-plane displacement in their parent frame's axes,
//! docs/in_plane.md); then, only
//! for scenes with load models (docs/scenes.md): joint_effort (N·m) and the
//! CSV columns each model declares (`dynamics::load_models::outputs`), model
//! by model in registry order: pad{p}_clamp_force, pad{p}_normal_force,
//! pad{p}_friction_torque (N, N, N·m) and with `pads.mass`
//! pad{p}_top_compression, pad{p}_bottom_compression (m); tool_tip_z,
//! tool_chip_thickness (m), tool_feed_force (N); link{j}_force (N).

use super::error::{CliError, CliResult};
use super::float_text::{push_display, write_exp, EXP_SLOT};
use crate::dynamics::load_models::outputs::{CsvColumn, Outputs};
use crate::dynamics::load_models::REGISTRY;
use crate::dynamics::{stability, Simulation};
use std::io::Write;
use std::sync::atomic::{AtomicBool, Ordering};

/// The CSV header for a simulation.
pub fn header(sim: &Simulation) -> String {
    // Bending modes, then the in-plane ones (docs/in_plane.md).
    let n = sim.scene().n_modes();
    let mut cols = vec![
        "time".to_string(),
        "joint_position".into(),
        "joint_velocity".into(),
    ];
    cols.extend((1..=n).map(|i| format!("q{i}")));
    cols.extend((1..=n).map(|i| format!("qale{i}")));
    cols.extend((1..=sim.n_ale_nodes()).map(|j| format!("ale{j}_uz")));
    cols.extend((1..=sim.n_lagrange_nodes()).map(|j| format!("lagrange{j}_uz")));
    if sim.scene().in_plane.is_some() {
        for (kind, n) in [
            ("ale", sim.n_ale_nodes()),
            ("lagrange", sim.n_lagrange_nodes()),
        ] {
            cols.extend((1..=n).flat_map(|j| [format!("{kind}{j}_ux"), format!("{kind}{j}_uy")]));
        }
    }
    if !sim.scene().load_models.is_empty() {
        cols.push("joint_effort".into());
    }
    for_each_model_cell(sim, |outputs, column, i, _| {
        cols.push(outputs.column_name(column, i))
    });
    cols.join(",")
}

/// Every CSV cell the load models declare, in column order (model by model in
/// registry order, instance by instance): its declaration, column, instance
/// and value. The header and the rows both walk it, so they stay aligned.
fn for_each_model_cell(sim: &Simulation, mut cell: impl FnMut(&Outputs, &CsvColumn, usize, f64)) {
    let lm = &sim.scene().load_models;
    for m in 0..lm.models().len() {
        let (outputs, layout) = lm.outputs(m);
        let values = sim.output_values(m);
        for i in 0..layout.csv_instances(outputs) {
            for (column, v) in layout.csv_values(outputs, values, i) {
                cell(outputs, column, i, v);
            }
        }
    }
}

/// The unit of a column of [`header`] (for axis labels), `None` for a name
/// that is not one of its columns.
pub fn column_unit(name: &str) -> Option<&'static str> {
    let numbered = |prefix: &str, suffix: &str| {
        name.strip_prefix(prefix)
            .and_then(|r| r.strip_suffix(suffix))
            .is_some_and(|d| !d.is_empty() && d.bytes().all(|c| c.is_ascii_digit()))
    };
    Some(match name {
        "time" => "s",
        "joint_position" => "rad",
        "joint_velocity" => "rad/s",
        "joint_effort" => "N·m",
        _ if numbered("q", "")
            || numbered("qale", "")
            || numbered("ale", "_uz")
            || numbered("lagrange", "_uz")
            || ["_ux", "_uy"]
                .iter()
                .any(|s| numbered("ale", s) || numbered("lagrange", s)) =>
        {
            "m"
        }
        _ => return REGISTRY.iter().find_map(|r| r.outputs.column_unit(name)),
    })
}

/// Formats CSV rows into one reused buffer: shortest round-trip floats
/// (`{}` for time and joint, `{:e}` for the rest, src/cli/float_text.rs), no
/// allocation per row. The buffer is kept at least [`EXP_SLOT`] bytes past
/// the text, so each value is written in place at a cursor (no capacity check
/// or `memcpy` call per value).
pub(crate) struct RowWriter {
    line: Vec<u8>,
    len: usize,
    text: Vec<u8>,
    digits: zmij::Buffer,
}

impl Default for RowWriter {
    fn default() -> RowWriter {
        RowWriter {
            line: vec![0; 4096],
            len: 0,
            text: Vec::with_capacity(64),
            digits: zmij::Buffer::new(),
        }
    }
}

/// Grows `line` to at least `end` + [`EXP_SLOT`] + 1 bytes (doubling: once
/// or twice, for the first rows), so the next value fits past `end`.
fn keep_slot_after(line: &mut Vec<u8>, end: usize) {
    if line.len() < end + EXP_SLOT + 1 {
        line.resize(2 * end.max(line.len()) + EXP_SLOT + 1, 0);
    }
}

/// The [`EXP_SLOT`] + 1 bytes of `line` from `at`.
fn slot(line: &mut Vec<u8>, at: usize) -> &mut [u8; EXP_SLOT + 1] {
    keep_slot_after(line, at);
    (&mut line[at..at + EXP_SLOT + 1])
        .try_into()
        .unwrap_or_else(|_| unreachable!())
}

impl RowWriter {
    fn display(&mut self, v: f64) {
        self.text.clear();
        push_display(&mut self.text, v, &mut self.digits);
        let end = self.len + self.text.len();
        keep_slot_after(&mut self.line, end);
        self.line[self.len..end].copy_from_slice(&self.text);
        self.len = end;
    }

    fn byte(&mut self, c: u8) {
        slot(&mut self.line, self.len)[0] = c;
        self.len += 1;
    }

    fn exp(&mut self, v: f64) {
        let slot = slot(&mut self.line, self.len);
        slot[0] = b',';
        let value: &mut [u8; EXP_SLOT] = (&mut slot[1..])
            .try_into()
            .unwrap_or_else(|_| unreachable!());
        self.len += 1 + write_exp(value, v, &mut self.digits);
    }

    /// The row of the current state, newline included.
    pub fn row(&mut self, sim: &Simulation) -> &[u8] {
        self.len = 0;
        let j = sim.joint();
        self.display(sim.time());
        self.byte(b',');
        self.display(j.position);
        self.byte(b',');
        self.display(j.velocity);
        for &v in sim.q_lagrange().iter().chain(sim.q_ale()) {
            self.exp(v);
        }
        for i in 0..sim.n_ale_nodes() {
            self.exp(sim.ale_node_uz(i));
        }
        for i in 0..sim.n_lagrange_nodes() {
            self.exp(sim.lagrange_node_uz(i));
        }
        for i in 0..sim.n_ale_nodes() {
            if let Some([ux, uy]) = sim.ale_node_in_plane_u(i) {
                self.exp(ux);
                self.exp(uy);
            }
        }
        for i in 0..sim.n_lagrange_nodes() {
            if let Some([ux, uy]) = sim.lagrange_node_in_plane_u(i) {
                self.exp(ux);
                self.exp(uy);
            }
        }
        if !sim.scene().load_models.is_empty() {
            self.exp(j.effort);
        }
        for_each_model_cell(sim, |_, _, _, v| self.exp(v));
        self.byte(b'\n');
        &self.line[..self.len]
    }
}

/// The highest frequency a scene's outputs must resolve, Hz: for a scene with
/// pads the least stable mode of the linear stability analysis at the scene's
/// speed, friction coefficient and clamp forces (`dynamics::stability`) — the
/// squeal — at the space-fixed nodes (|Im λ|/2π of the ALE system). `None`
/// for scenes without pads, and where the analysis refuses the scene (the
/// lining's patches with in-plane modes, `LoadModel::check_linear`).
pub(crate) fn relevant_frequency(sim: &Simulation) -> Option<f64> {
    sim.scene().load_models.check_linear().ok()?;
    stability::squeal_frequency(sim)
}

/// Refuses `--output-rate` `rate` Hz when its Nyquist frequency rate/2 is
/// below `relevant_frequency` (the rows would alias the squeal), naming
/// both, unless `allow_aliasing` (`--allow-aliasing`).
pub fn check_output_rate(sim: &Simulation, rate: f64, allow_aliasing: bool) -> CliResult<()> {
    match relevant_frequency(sim) {
        Some(f) if !allow_aliasing && 0.5 * rate < f => Err(CliError::Usage(format!(
            "--output-rate {rate} Hz would alias: its Nyquist frequency {} Hz is below the {f:.1} Hz of the scene's least stable mode \
             (the squeal frequency of the linear stability analysis); give an output rate above {:.1} Hz that divides simulation.rate_hz, or --allow-aliasing",
            0.5 * rate,
            2.0 * f
        ))),
        _ => Ok(()),
    }
}

/// Run for `duration` seconds writing a row per output step (t = 0 included).
/// `progress` is called with the fraction done.
pub fn run(
    sim: &mut Simulation,
    duration: f64,
    out: &mut impl Write,
    progress: impl FnMut(f64),
) -> CliResult<u64> {
    run_with(
        sim,
        duration,
        1,
        Some(out),
        |_| Ok(()),
        progress,
        &AtomicBool::new(false),
    )
}

/// [`run`] with the CSV optional, writing a row and calling `each` with the
/// state at t = 0 and after every `every`-th step (`simulate --output-rate`;
/// `simulate --bag` records there). When `stop` is set
/// (SIGINT, SIGTERM) the run ends after the current step, everything written
/// so far flushed, and returns the steps done.
pub fn run_with<W: Write + ?Sized>(
    sim: &mut Simulation,
    duration: f64,
    every: u64,
    mut out: Option<&mut W>,
    mut each: impl FnMut(&Simulation) -> CliResult<()>,
    mut progress: impl FnMut(f64),
    stop: &AtomicBool,
) -> CliResult<u64> {
    let steps = (duration / sim.dt()).round() as u64;
    let mut rows = RowWriter::default();
    if let Some(out) = out.as_mut() {
        writeln!(out, "{}", header(sim))?;
        out.write_all(rows.row(sim))?;
    }
    each(sim)?;
    let report_every = (steps / 200).max(1);
    let mut done = 0;
    for s in 1..=steps {
        if stop.load(Ordering::Relaxed) {
            break;
        }
        sim.step()?;
        done = s;
        if s % every != 0 {
            continue;
        }
        if let Some(out) = out.as_mut() {
            out.write_all(rows.row(sim))?;
        }
        each(sim)?;
        if s % report_every == 0 {
            progress(s as f64 / steps as f64);
        }
    }
    if let Some(out) = out.as_mut() {
        out.flush()?;
    }
    Ok(done)
}
