//! The lathe tool of the paper's first example (section 5.1, Figs. 7–9).
//!
//! Cylindrical turning of the rim: the tool is fed parallel to the disc axis
//! (towards −z, from the +z face through the thickness) at the feed rate v_f,
//! removing a ring of radial depth b (the depth of cut) from the rim. Its
//! feed force follows eq. (21), f_f = b h^(1−m_f) k_f1.1 with b and h in mm
//! and k_f1.1 in N/mm² — in SI: f_f = k_f1.1 b h^(1−m_f) (1 mm)^(m_f).
//!
//! **Chip model.** The tool acts at an ALE node on the rim (ξ_r = 1), a
//! space-fixed point the disc turns under. The already machined shoulder is
//! kept as a height S(φ) over the material angle φ (4096 bins, in material
//! coordinates: measured from the deflected mid-plane), starting at the +z
//! face (S = h/2). The tool tip's material height is ζ = z_tip − w, with w the
//! deflection under the tool; the chip thickness at a material point is what
//! the tip removes there, h = S(φ) − max(ζ, −h/2) when positive, after which
//! S(φ) = max(ζ, −h/2). So the chip is the tool's advance relative to the
//! surface it left one revolution earlier — its plate deflection included
//! (regeneration) — and is zero before the tip reaches the face and after it
//! has left the −z face. Per substep the tool sweeps the material arc Ω h: the
//! chip is the mean over the bins whose centres it passes, the force is held
//! over the substep (so the bins are cut once per revolution, independent of
//! the step), and then those bins are cut. On `contact_exponential` the cut
//! is instead a function of the state within the substep (`tool_in_step.rs`). In steady cutting at speed Ω the
//! chip is the feed per revolution, h = 2π v_f / Ω.
//!
//! **Tool compliance.** The tip hangs on the holder by a spring k_t and a
//! damper c_t (no mass): the holder moves at −v_f, the feed force pushes the
//! tip back by e, c_t ė + k_t e = f_f (exact over a substep for the held
//! force), z_tip = z_holder + e. The plate gets −f_f along z at the node.
//!
//! **Residual flexibility.** With `plate.residual_flexibility` the chip is cut
//! at the deflection w = w_m + w_e − g f_f: the truncated modes' static
//! deflection under the tool (g, its own residual compliance) and of the held
//! wrenches (w_e) added to the modal one. The force thins its own chip, so
//! f_f = 𝓕(chip(w_m + w_e − g f_f)) is solved within the substep
//! (`dynamics::contact_compliance::solve_monotone`): the residual is a spring
//! in series with the cut.

use super::model::{
    surface_kinematics, CommandRule, CommandSpec, LoadContext, LoadModel, ModelOut, Registration,
    SceneNodes,
};
use super::outputs::{CsvColumn, OutputChannel, OutputContext, Outputs, StateTopic};
use super::tool_config::{ToolConfig, MAX_TOOL_FEED_RATE, PARAMETERS};
use super::tool_step::{bin_entries, Sweep};
pub use super::tool_step::{ToolStep, SURFACE, SURFACE_BINS};
use super::undo::SlotUndo;
use crate::config::{Config, IntegratorKind};
use crate::dynamics::contact_compliance::solve_monotone;
use crate::dynamics::error::LoadCommandError;
use crate::dynamics::{Command, Simulation};
use std::any::Any;


/// Eq. (21)'s reference chip size, m (k_f1.1 is the force per mm² at h = b = 1 mm).
const REFERENCE_CHIP: f64 = 1.0e-3;

/// Tool parameters (immutable; in the `Scene`).
#[derive(Debug, Clone, PartialEq)]
pub struct Tool {
    /// ALE node, 0-based.
    pub node: usize,
    /// θ of the node, rad.
    pub angle: f64,
    /// b, m.
    pub depth_of_cut: f64,
    /// k_t, N/m.
    pub stiffness: f64,
    /// c_t, N·s/m.
    pub damping: f64,
    /// k_f1.1, Pa.
    pub specific_force: f64,
    /// m_f.
    pub force_exponent: f64,
    /// Plate thickness h, m.
    pub thickness: f64,
    /// z of the tool tip at t = 0 (the +z face is at h/2), m.
    pub start_height: f64,
    /// Feed rate the configuration starts with, m/s (the running command is in `Inputs`).
    pub initial_feed_rate: f64,
    /// g, the residual compliance at the tool's node (m/N): the cut in series
    /// with it (`plate.residual_flexibility`; None: on the modal deflection).
    pub series: Option<f64>,
    /// The cut as a function of the state within the substep (on
    /// `contact_exponential`, `tool_in_step.rs`) instead of held over it.
    pub within_step: bool,
    /// (1 mm)^m_f of eq. (21), computed once ([`Tool::reference_factor`]).
    pub reference_factor: f64,
    /// The main cutting force's k_c1.1 (Pa; 0: none), m_c and (1 mm)^m_c
    /// (`tool_cutting.rs`).
    pub cutting: [f64; 3],
}

/// The tool's slot in the [`State`](crate::dynamics::State) (so reset and
/// replay are copies): the tip deflection and the holder's advance within
/// the substep (first: the continuous states on `contact_exponential`), the
/// holder, the last substep's chip and force, the cut held over the current
/// substep, and the shoulder height S per material-angle bin from index
/// [`SURFACE`] on.
pub const DEFLECTION: usize = 0;
/// The holder's advance since the substep's start (0 between substeps), m.
pub const ADVANCE: usize = 1;
/// Time since the substep's start (0 between substeps), s.
pub const CLOCK: usize = 2;
/// z of the tool holder at the substep's start, m.
pub const HOLDER: usize = 3;
/// Chip thickness of the last substep, m.
pub const CHIP: usize = 4;
/// Feed force of the last substep, N.
pub const FORCE: usize = 5;

/// The tool's one command: the feed rate.
pub const FEED_RATE: CommandSpec = CommandSpec {
    instance: "tool",
    name: "feed rate",
    token: "feed",
    unit: "m/s",
    indexed: false,
    rule: CommandRule::MagnitudeAtMost(MAX_TOOL_FEED_RATE),
};

/// The tool's declared outputs: ~/tool_state (`msg/ToolState.msg`) and its
/// CSV columns `tool_tip_z`, `tool_chip_thickness`, `tool_feed_force`.
pub const OUTPUTS: Outputs = Outputs {
    channels: &[
        OutputChannel::scalar("feed_rate", "m/s"),
        OutputChannel::scalar("tip_z", "m"),
        OutputChannel::scalar("chip_thickness", "m"),
        OutputChannel::scalar("feed_force", "N"),
    ],
    column_prefix: "tool",
    numbered: false,
    columns: &[
        CsvColumn::named("tip_z"),
        CsvColumn::named("chip_thickness"),
        CsvColumn::named("feed_force"),
    ],
    topic: Some(StateTopic {
        topic: "~/tool_state",
        package: "annular_plate",
        message: "ToolState",
        definition: include_str!("../../../msg/ToolState.msg"),
    }),
};

/// The tool in the registry.
pub const REGISTRATION: Registration = Registration {
    build,
    outputs: &OUTPUTS,
    parameters: &PARAMETERS,
};

/// The registered builder: a tool where `tool.*` gives its node.
pub fn build(config: &Config, nodes: &SceneNodes) -> Option<Box<dyn LoadModel>> {
    let t = config.section::<ToolConfig>()?;
    Some(Box::new(Tool {
        node: t.node,
        angle: nodes.ale[t.node].angle,
        depth_of_cut: t.depth_of_cut,
        stiffness: t.stiffness,
        damping: t.damping,
        specific_force: t.specific_force,
        force_exponent: t.force_exponent,
        thickness: config.plate.thickness,
        start_height: 0.5 * config.plate.thickness + t.start_clearance,
        initial_feed_rate: t.feed_rate,
        series: nodes.residual.map(|r| r.between(t.node, t.node, 0.0)),
        within_step: config.simulation.integrator == IntegratorKind::ContactExponential,
        reference_factor: Tool::reference_factor(t.force_exponent),
        cutting: [
            t.cutting_specific_force,
            t.cutting_exponent,
            Tool::reference_factor(t.cutting_exponent),
        ],
    }))
}

impl LoadModel for Tool {
    fn name(&self) -> &'static str {
        "tool"
    }
    /// The chip is cut at the axial displacement w of the rim under the
    /// tool, and the feed force is F_z there: a face point moves axially by w
    /// in either plate theory.
    fn takes_mindlin_modes(&self) -> bool {
        true
    }
    /// The feed force is F_z alone and the chip is cut at w: no work on the
    /// in-plane modes, which do not move the tip's level.
    fn attach_in_plane(
        &mut self,
        _ip: &crate::dynamics::in_plane::InPlaneDynamics,
    ) -> Result<(), crate::dynamics::error::SimulationError> {
        Ok(())
    }
    fn as_any(&self) -> &dyn Any {
        self
    }
    fn commands(&self) -> &[CommandSpec] {
        std::slice::from_ref(&FEED_RATE)
    }
    fn initial_commands(&self) -> Vec<f64> {
        vec![self.initial_feed_rate]
    }
    /// On `contact_exponential` the cut follows the state within the substep.
    fn stage_dependent(&self) -> bool {
        self.within_step
    }
    /// The tip deflection, the holder's advance and the clock, within the substep.
    fn continuous_states(&self) -> usize {
        if self.within_step {
            3
        } else {
            0
        }
    }
    /// None is a rate.
    fn continuous_rates(&self) -> usize {
        0
    }
    /// In the cut, and the cut's level above the −z face (`tool_in_step.rs`).
    fn switching_functions(&self) -> usize {
        if self.within_step {
            2
        } else {
            0
        }
    }
    fn law_reads_memory(&self) -> bool {
        self.within_step
    }
    fn initial_state(&self) -> Vec<f64> {
        let mut slot = vec![0.0; SURFACE + SURFACE_BINS];
        slot[HOLDER] = self.start_height;
        slot[SURFACE..].fill(0.5 * self.thickness);
        slot
    }

    /// The cut of the substep, from the deflection under the tool at its start.
    fn begin_substep(&self, ctx: &LoadContext, slot: &mut [f64], h: f64) {
        let w = surface_kinematics(&ctx.ale_nodes[self.node], ctx.q_ale, ctx.q_dot_ale).w;
        let step = match self.series {
            None => self.begin(slot, w, ctx.chi, ctx.speed, h),
            Some(g) => {
                // w_free: without the tool's own force; its force pushes −z.
                let w_free = w + ctx.held.map_or(0.0, |d| d.at(self.node, ctx.chi));
                let sweep = self.sweep(ctx.chi, ctx.speed, h);
                self.cut_in_series(slot, &sweep, Self::tip(slot), w_free, g)
            }
        };
        ToolStep { h, ..step }.store(slot);
    }

    /// The held feed force, along −z at the tool's node; on
    /// `contact_exponential` the cut at the instant (`tool_in_step.rs`).
    fn evaluate(&self, ctx: &LoadContext, slot: &[f64], commands: &[f64], out: ModelOut) {
        if self.within_step {
            return self.evaluate_in_step(ctx, slot, commands, out);
        }
        let step = ToolStep::load(slot);
        out.ale[self.node].force[2] -= step.force;
        self.add_cutting_force(step.chip, ctx.speed, &mut out.ale[self.node]);
    }

    fn commit_substep(&self, ctx: &LoadContext, slot: &mut [f64], commands: &[f64], h: f64) {
        let step = ToolStep::load(slot);
        if self.within_step {
            return self.commit_in_step(ctx, slot, &step, commands[0]);
        }
        self.commit(slot, &step, commands[0], h);
    }

    /// The holder, tip, held cut and last outputs; the surface bins are logged per cut.
    fn undo_head(&self, _slot_len: usize) -> usize {
        SURFACE
    }

    /// The surface bins the held cut will lower (within the substep: every bin swept).
    fn save_changes(&self, slot: &[f64], undo: &mut SlotUndo) {
        let step = ToolStep::load(slot);
        for i in step.swept_entries() {
            if self.within_step {
                undo.save(slot, i);
                continue;
            }
            // Above the level, or NaN: saved.
            if !matches!(
                slot[i].partial_cmp(&step.level),
                Some(std::cmp::Ordering::Less | std::cmp::Ordering::Equal)
            ) {
                undo.save(slot, i);
            }
        }
    }

    /// Feed rate (commanded), tip height, chip and force of the last substep.
    fn write_outputs(&self, at: &OutputContext, out: &mut [f64]) {
        out.copy_from_slice(&[
            at.commands[0],
            Tool::tip(at.slot),
            at.slot[CHIP],
            at.slot[FORCE],
        ]);
    }

    /// The surface bins are minima of cut levels made from the tip and the
    /// deflection (checked with the elastic state): the values before them decide.
    fn slot_is_finite(&self, slot: &[f64]) -> bool {
        slot[..SURFACE].iter().all(|v| v.is_finite())
    }
}

/// The lathe tool at the current state.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct ToolOutput {
    /// z of the tool tip in the reference frame (the +z face is at h/2), m.
    pub tip: f64,
    /// Chip thickness of the last substep, m.
    pub chip: f64,
    /// Feed force of the last substep, N (acts on the plate along −z).
    pub feed_force: f64,
    /// Commanded feed rate, m/s.
    pub feed_rate: f64,
}

/// The tool's typed view of a simulation (for programs and tests that know
/// they drive a lathe; the node and the writers read the declared channels).
pub trait ToolOutputs {
    /// Whether the scene has a lathe tool (`tool.*`).
    fn has_tool(&self) -> bool;
    /// The lathe tool at the current state (`None` without a tool).
    fn tool_output(&self) -> Option<ToolOutput>;
    /// Hold the tool feed rate, m/s (towards −z; negative retracts). Refused
    /// if the scene has no tool or the rate is not finite or beyond 1 m/s.
    fn set_tool_feed(&mut self, rate: f64) -> Result<(), LoadCommandError>;
}

impl ToolOutputs for Simulation {
    fn has_tool(&self) -> bool {
        self.scene().load_models.find::<Tool>().is_some()
    }

    fn tool_output(&self) -> Option<ToolOutput> {
        let (model, _) = self.scene().load_models.find::<Tool>()?;
        let [feed_rate, tip, chip, feed_force] = self.output_values(model).try_into().ok()?;
        Some(ToolOutput {
            tip,
            chip,
            feed_force,
            feed_rate,
        })
    }

    fn set_tool_feed(&mut self, rate: f64) -> Result<(), LoadCommandError> {
        let Some((model, _)) = self.scene().load_models.find::<Tool>() else {
            return Err(LoadCommandError::NoTool);
        };
        self.command(Command::Load {
            model,
            command: 0,
            instance: 0,
            value: rate,
        })
        .map_err(LoadCommandError::from_input)
    }
}

impl Tool {
    /// Eq. (21): feed force for chip thickness h (m).
    pub fn feed_force(&self, chip: f64) -> f64 {
        if chip <= 0.0 {
            return 0.0;
        }
        self.specific_force
            * self.depth_of_cut
            * chip.powf(1.0 - self.force_exponent)
            * self.reference_factor
    }

    /// (1 mm)^m_f, eq. (21)'s unit conversion, m^m_f.
    pub fn reference_factor(force_exponent: f64) -> f64 {
        REFERENCE_CHIP.powf(force_exponent)
    }

    /// z of the tool tip, m.
    pub fn tip(slot: &[f64]) -> f64 {
        slot[HOLDER] + slot[ADVANCE] + slot[DEFLECTION]
    }

    /// The cut of a substep of length h starting at joint angle χ (wrapped, rad)
    /// and speed Ω, with deflection w under the tool.
    pub fn begin(&self, slot: &[f64], w: f64, chi: f64, speed: f64, h: f64) -> ToolStep {
        self.cut(slot, &self.sweep(chi, speed, h), Self::tip(slot), w)
    }

    /// The bins a substep of length h starting at χ with speed Ω sweeps
    /// (whatever the deflection).
    pub(super) fn sweep(&self, chi: f64, speed: f64, h: f64) -> Sweep {
        let n = SURFACE_BINS as i64;
        let width = std::f64::consts::TAU / SURFACE_BINS as f64;
        let phi0 = (self.angle - chi).rem_euclid(std::f64::consts::TAU);
        let sweep = speed * h;
        // Bin centres (b + ½)·width passed by the material angle under the tool.
        let (first_bin, bins, downwards) = if sweep >= 0.0 {
            let hi = (phi0 / width - 0.5).floor() as i64;
            let lo = ((phi0 - sweep) / width - 0.5).floor() as i64 + 1;
            (hi, (hi - lo + 1).min(n), true)
        } else {
            let lo = (phi0 / width - 0.5).ceil() as i64;
            let hi = ((phi0 - sweep) / width - 0.5).ceil() as i64 - 1;
            (lo, (hi - lo + 1).min(n), false)
        };
        Sweep {
            first_bin,
            bins,
            downwards,
        }
    }

    /// Slot indices of the bins the chip is read from: those swept, or the
    /// bin ahead when no centre is passed (a step shorter than a bin).
    pub(super) fn read_entries(sweep: &Sweep) -> impl Iterator<Item = usize> {
        bin_entries(sweep.first_bin, sweep.downwards, sweep.bins.max(1))
    }

    /// The cut of `sweep` with the tip at z = `tip` and deflection w under the tool.
    pub(super) fn cut(&self, slot: &[f64], sweep: &Sweep, tip: f64, w: f64) -> ToolStep {
        let level = (tip - w).max(-0.5 * self.thickness);
        let read = sweep.bins.max(1);
        let chip = Self::read_entries(sweep)
            .map(|i| (slot[i] - level).max(0.0))
            .sum::<f64>()
            / read as f64;
        let Sweep {
            first_bin,
            bins,
            downwards,
        } = *sweep;
        ToolStep {
            force: self.feed_force(chip),
            chip,
            level,
            first_bin,
            bins: bins.max(0),
            downwards,
            h: 0.0,
        }
    }

    /// The cut of `sweep` in series with the residual compliance g: the force
    /// f = 𝓕(chip(w_free − g f)) ([`solve_monotone`]). The root itself is
    /// the force held: 𝓕 re-evaluated there can differ by far more than the
    /// tolerance where the chip vanishes (𝓕 ∝ h^(1−m_f) is vertical at h = 0).
    pub(super) fn cut_in_series(
        &self,
        slot: &[f64],
        sweep: &Sweep,
        tip: f64,
        w_free: f64,
        g: f64,
    ) -> ToolStep {
        let free = self.cut(slot, sweep, tip, w_free).force;
        let f = solve_monotone(free, |f| {
            let step = self.cut(slot, sweep, tip, w_free - g * f);
            (step.force, -g * self.force_slope(slot, sweep, &step))
        });
        ToolStep {
            force: f,
            ..self.cut(slot, sweep, tip, w_free - g * f)
        }
    }

    /// d f_f / d w of `step` (the cut of `sweep`), N/m: raising the plate
    /// under the tool lowers the cut level and so thickens the chip where the
    /// shoulder is above it — f_f = A h^(1−m_f), dh/dw = (bins above the
    /// level)/(bins read); zero where the level is held at the −z face.
    fn force_slope(&self, slot: &[f64], sweep: &Sweep, step: &ToolStep) -> f64 {
        if step.chip <= 0.0 || step.level <= -0.5 * self.thickness {
            return 0.0;
        }
        let above = Self::read_entries(sweep)
            .filter(|&i| slot[i] > step.level)
            .count();
        (1.0 - self.force_exponent) * step.force / step.chip * above as f64
            / sweep.bins.max(1) as f64
    }

    /// Cut the swept bins, move the holder by −v_f h and relax the tip under the held force.
    pub fn commit(&self, slot: &mut [f64], step: &ToolStep, feed_rate: f64, h: f64) {
        for i in step.swept_entries() {
            slot[i] = slot[i].min(step.level);
        }
        let e_static = step.force / self.stiffness;
        slot[DEFLECTION] = if self.damping > 0.0 {
            e_static + (slot[DEFLECTION] - e_static) * (-self.stiffness / self.damping * h).exp()
        } else {
            e_static
        };
        slot[HOLDER] -= feed_rate * h;
        slot[CHIP] = step.chip;
        slot[FORCE] = step.force;
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::TAU;

    fn tool() -> Tool {
        Tool {
            node: 0,
            angle: 0.0,
            depth_of_cut: 2e-3,
            stiffness: 1e12,
            damping: 0.0,
            specific_force: 351e6,
            force_exponent: 0.7013,
            thickness: 0.01,
            start_height: 0.005,
            initial_feed_rate: 0.0,
            series: None,
            within_step: false,
            reference_factor: Tool::reference_factor(0.7013),
            cutting: [0.0, 0.25, 1.0],
        }
    }

    #[test]
    fn feed_force_is_eq_21_in_millimetres() {
        // b = 2 mm, h = 1.131 mm: f = 2 · 1.131^0.2987 · 351 N.
        let f = tool().feed_force(1.131e-3);
        let expected = 2.0 * 1.131f64.powf(1.0 - 0.7013) * 351.0;
        assert!((f - expected).abs() < 1e-9 * expected, "{f} vs {expected}");
        assert_eq!(tool().feed_force(0.0), 0.0);
    }

    #[test]
    fn the_cut_in_series_holds_the_fixed_point_of_eq_21() {
        // Shoulder S = h/2 everywhere, tip 20 µm into it: chip(f) = 2e-5 − g f.
        let t = tool();
        let mut slot = t.initial_state();
        slot[HOLDER] = 0.005 - 2e-5;
        let sweep = t.sweep(0.0, 10.0, 1e-3);
        let g = 1e-9;
        let step = t.cut_in_series(&slot, &sweep, Tool::tip(&slot), 0.0, g);
        // The root by bisection, written out here.
        let (mut lo, mut hi) = (0.0, t.feed_force(2e-5));
        for _ in 0..200 {
            let mid = 0.5 * (lo + hi);
            if mid < t.feed_force(2e-5 - g * mid) {
                lo = mid
            } else {
                hi = mid
            }
        }
        assert!(
            (step.force - lo).abs() < 1e-12 * lo,
            "{} vs {lo}",
            step.force
        );
        assert!((step.chip - (2e-5 - g * step.force)).abs() < 1e-18);
        // The chip a hair above the surface (the cut's first touch): the
        // force cannot exceed the one that closes the chip, 1e-19/g.
        slot[HOLDER] = 0.005 - 1e-19;
        let touch = t.cut_in_series(&slot, &sweep, Tool::tip(&slot), 0.0, g);
        assert!(
            touch.force <= 1e-19 / g * (1.0 + 1e-9) && touch.force >= 0.0,
            "{}",
            touch.force
        );
    }

    #[test]
    fn steady_chip_is_the_feed_per_revolution_for_any_step() {
        // A rigid plate (w = 0) at Ω; after the first revolution the chip is 2π v_f/Ω.
        let (speed, feed) = (100.0 / 60.0 / 0.15, 0.12 / 60.0);
        for h in [1e-3, 3.7e-4, 1e-5] {
            let t = tool();
            let mut s = t.initial_state();
            let s = s.as_mut_slice();
            let mut chi: f64 = 0.0;
            let steps = (3.0 * TAU / speed / h) as usize;
            for _ in 0..steps {
                let step = t.begin(s, 0.0, chi.rem_euclid(TAU), speed, h);
                t.commit(s, &step, feed, h);
                chi += speed * h;
            }
            let expected = TAU * feed / speed;
            // Bins are cut at substep starts: one revolution between two cuts of
            // a bin is T ± h; with substeps shorter than a bin, a bin is read
            // up to one bin width ahead of its cut.
            let tolerance = (h * speed / TAU).max(1.0 / SURFACE_BINS as f64) + 1e-9;
            assert!(
                (s[CHIP] - expected).abs() <= tolerance * expected,
                "h = {h}: chip {} vs {expected}",
                s[CHIP]
            );
        }
    }
}
