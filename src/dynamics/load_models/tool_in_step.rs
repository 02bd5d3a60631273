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
//! at the rate −v_f (so the law stays autonomous while the tool feeds), and
//! the time τ since the substep's start: the bins are passed one after the
//! other, so the chip at τ is the mean over the bins plus the least-squares
//! slope σ of their heights in the time they are passed, σ (τ − h/2) — exact
//! for the helix a steady cut leaves (the mean alone would read the chip of
//! the substep's middle at its ends, h/2 of a revolution off).
//! Two switching functions bound the law's pieces: max S − ζ over the bins
//! (> 0: the tip is in the material) and ζ + h/2 (> 0: the level follows
//! the tip, not the −z face). The bins are cut at the step's end, at the
//! level interpolated between the substep's start and end where each bin is
//! passed (the step knows the state at its two ends only). Between
//! substeps (the held step's h set to 0 at the commit) the force is the one
//! the last substep ended with.

use super::model::{surface_kinematics, LoadContext, ModelOut};
use super::tool::{Tool, ToolStep, ADVANCE, CHIP, CLOCK, DEFLECTION, FORCE, HOLDER};

impl Tool {
    /// The cut at the instant `ctx` (w), `from_middle` (τ − h/2) into the
    /// substep, with the tip at z = `tip`: the cut, and the unclipped cut
    /// level ζ = tip − w (in series with the residual compliance g:
    /// w = w_free − g f_f). The bins' slope in time enters as a lower tip.
    fn cut_now(
        &self,
        ctx: &LoadContext,
        slot: &[f64],
        held: &ToolStep,
        tip: f64,
        from_middle: f64,
    ) -> (ToolStep, f64) {
        let sweep = held.sweep();
        let tip = tip - Self::surface_slope(slot, held) * from_middle;
        let w = surface_kinematics(&ctx.ale_nodes[self.node], ctx.q_ale, ctx.q_dot_ale).w;
        match self.series {
            None => (self.cut(slot, &sweep, tip, w), tip - w),
            Some(g) => {
                let w_free = w + ctx.held.map_or(0.0, |d| d.at(self.node, ctx.chi));
                let step = self.cut_in_series(slot, &sweep, tip, w_free, g);
                (step, tip - (w_free - g * step.force))
            }
        }
    }

    /// σ: the least-squares slope of the swept bins' heights in the time
    /// each is passed, (j + ½) h / bins for the j-th, m/s (0 for one bin).
    fn surface_slope(slot: &[f64], held: &ToolStep) -> f64 {
        let bins = held.bins;
        if bins < 2 {
            return 0.0;
        }
        let n = bins as f64;
        let mid = 0.5 * (n - 1.0);
        let (mut num, mut den) = (0.0, 0.0);
        for (j, i) in held.swept_entries().enumerate() {
            let x = j as f64 - mid;
            num += x * slot[i];
            den += x * x;
        }
        num / den * n / held.h
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
            self.add_cutting_force(slot[CHIP], ctx.speed, &mut out.ale[self.node]);
            out.rates.fill(0.0);
            return;
        }
        let sweep = held.sweep();
        let from_middle = slot[CLOCK] - 0.5 * held.h;
        let (cut, zeta) = self.cut_now(ctx, slot, &held, Self::tip(slot), from_middle);
        out.ale[self.node].force[2] -= cut.force;
        self.add_cutting_force(cut.chip, ctx.speed, &mut out.ale[self.node]);
        out.rates[0] = if self.damping > 0.0 {
            (cut.force - self.stiffness * slot[DEFLECTION]) / self.damping
        } else {
            0.0
        };
        out.rates[1] = -commands[0];
        out.rates[2] = 1.0;
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
        slot[CLOCK] = 0.0;
        let (end, zeta) = self.cut_now(ctx, slot, start, Self::tip(slot), 0.5 * start.h);
        // The level the tip cuts at the end, without the bins' slope.
        let end_level =
            (zeta + 0.5 * start.h * Self::surface_slope(slot, start)).max(-0.5 * self.thickness);
        let bins = start.bins.max(1) as f64;
        for (j, i) in start.swept_entries().enumerate() {
            let passed = (j as f64 + 0.5) / bins;
            slot[i] = slot[i].min(start.level + passed * (end_level - start.level));
        }
        if self.damping <= 0.0 {
            slot[DEFLECTION] = end.force / self.stiffness;
        }
        slot[CHIP] = end.chip;
        slot[FORCE] = end.force;
        ToolStep { h: 0.0, ..*start }.store(slot);
    }
}
