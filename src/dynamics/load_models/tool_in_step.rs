//! The tool's cut within the substep, for `contact_exponential`
//! (docs/dynamics.md, "The tool's chip contact").
//!
//! Held over a substep h, the cut lags the deflection by about h/2: a
//! negative damping k_c h/2 with the cut's stiffness k_c = ∂f_f/∂w (eq. 21).
//! Here the feed force at an instant is eq. (21) of the chip over the bins
//! the substep sweeps at the level the tip has then, ζ = z_tip − w
//! (h_chip = mean over the bins of max(S − max(ζ, −h/2), 0)): a function of
//! the elastic state and of two continuous states of the step: the tip
//! deflection e, which relaxes as c_t ė = f_f − k_t e (with c_t = 0 it is
//! held at its start), and the holder's advance since the substep's start,
//! at the rate −v_f (so the law stays autonomous while the tool feeds).
//! Two switching functions bound the law's pieces: max S − ζ over the bins
//! (> 0: the tip is in the material) and ζ + h/2 (> 0: the level follows
//! the tip, not the −z face). The bins are cut at the step's end, at the
//! level interpolated between the substep's start and end where each bin is
//! passed (the step knows the state at its two ends only). Between
//! substeps (the held step's h set to 0 at the commit) the force is the one
//! the last substep ended with.

use super::model::{surface_kinematics, LoadContext, ModelOut};
use super::tool::{Sweep, Tool, ToolStep, ADVANCE, CHIP, DEFLECTION, FORCE, HOLDER};

impl Tool {
    /// The cut at the instant `ctx` (w) with the tip at z = `tip`: the
    /// cut, and the unclipped cut level ζ = tip − w (in series with the
    /// residual compliance g: w = w_free − g f_f).
    fn cut_now(&self, ctx: &LoadContext, slot: &[f64], sweep: &Sweep, tip: f64) -> (ToolStep, f64) {
        let w = surface_kinematics(&ctx.ale_nodes[self.node], ctx.q_ale, ctx.q_dot_ale).w;
        match self.series {
            None => (self.cut(slot, sweep, tip, w), tip - w),
            Some(g) => {
                let w_free = w + ctx.held.map_or(0.0, |d| d.at(self.node, ctx.chi));
                let step = self.cut_in_series(slot, sweep, tip, w_free, g);
                (step, tip - (w_free - g * step.force))
            }
        }
    }

    /// The feed force at the instant, the tip's relaxation rate and the
    /// switching functions (module docs).
    pub(super) fn evaluate_in_step(
        &self,
        ctx: &LoadContext,
        slot: &[f64],
        commands: &[f64],
        out: ModelOut,
    ) {
        let held = ToolStep::load(slot);
        if held.h == 0.0 {
            // Between substeps (the outputs at a step's end): the force the
            // last one ended with.
            out.ale[self.node].force[2] -= slot[FORCE];
            out.rates.fill(0.0);
            return;
        }
        let sweep = held.sweep();
        let (cut, zeta) = self.cut_now(ctx, slot, &sweep, Self::tip(slot));
        out.ale[self.node].force[2] -= cut.force;
        out.rates[0] = if self.damping > 0.0 {
            (cut.force - self.stiffness * slot[DEFLECTION]) / self.damping
        } else {
            0.0
        };
        out.rates[1] = -commands[0];
        let top = Self::read_entries(&sweep)
            .map(|i| slot[i])
            .fold(f64::NEG_INFINITY, f64::max);
        let floor = -0.5 * self.thickness;
        out.switching[0] = top - zeta.max(floor);
        out.switching[1] = zeta - floor;
    }

    /// After the substep (`ctx` at its end, the tip deflection already the
    /// step's): fold the holder's advance into the holder as −v_f h, take the chip and force at the
    /// end, and cut the swept bins at the level interpolated between the
    /// start's (`start.level`) and the end's where each is passed.
    pub(super) fn commit_in_step(
        &self,
        ctx: &LoadContext,
        slot: &mut [f64],
        start: &ToolStep,
        feed_rate: f64,
    ) {
        slot[HOLDER] -= feed_rate * start.h;
        slot[ADVANCE] = 0.0;
        let (end, _) = self.cut_now(ctx, slot, &start.sweep(), Self::tip(slot));
        let bins = start.bins.max(1) as f64;
        for (j, i) in start.swept_entries().enumerate() {
            let passed = (j as f64 + 0.5) / bins;
            slot[i] = slot[i].min(start.level + passed * (end.level - start.level));
        }
        if self.damping <= 0.0 {
            slot[DEFLECTION] = end.force / self.stiffness;
        }
        slot[CHIP] = end.chip;
        slot[FORCE] = end.force;
        ToolStep { h: 0.0, ..*start }.store(slot);
    }
}
