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
//! the step), and then those bins are cut. In steady cutting at speed Ω the
//! chip is the feed per revolution, h = 2π v_f / Ω.
//!
//! **Tool compliance.** The tip hangs on the holder by a spring k_t and a
//! damper c_t (no mass): the holder moves at −v_f, the feed force pushes the
//! tip back by e, c_t ė + k_t e = f_f (exact over a substep for the held
//! force), z_tip = z_holder + e. The plate gets −f_f along z at the node.

/// Bins of the machined-shoulder height S(φ) over one revolution.
pub const SURFACE_BINS: usize = 4096;

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
}

/// Tool state (mutable; in the `State`, so reset and replay are clones).
#[derive(Debug, Clone, PartialEq)]
pub struct ToolState {
    /// z of the holder's (undeflected) tip position, m.
    pub holder: f64,
    /// Tip deflection e (pushed back, +z), m.
    pub deflection: f64,
    /// Shoulder height S per material-angle bin, m.
    pub surface: Vec<f64>,
    /// Chip thickness of the last substep, m.
    pub chip: f64,
    /// Feed force of the last substep, N.
    pub force: f64,
}

/// What one substep cuts, computed at its start.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ToolStep {
    /// Feed force held over the substep, N.
    pub force: f64,
    /// Chip thickness, m.
    pub chip: f64,
    /// Material height of the cut, max(ζ, −h/2), m.
    pub level: f64,
    /// First bin swept and number of bins swept (bins are visited downwards in φ for Ω > 0).
    pub first_bin: i64,
    pub bins: i64,
    pub downwards: bool,
}

impl ToolState {
    /// Copy `other` into `self` reusing the surface buffer.
    pub fn copy_from(&mut self, other: &ToolState) {
        self.holder = other.holder;
        self.deflection = other.deflection;
        self.surface.clear();
        self.surface.extend_from_slice(&other.surface);
        self.chip = other.chip;
        self.force = other.force;
    }
}

impl Tool {
    pub fn initial_state(&self) -> ToolState {
        ToolState { holder: self.start_height, deflection: 0.0, surface: vec![0.5 * self.thickness; SURFACE_BINS], chip: 0.0, force: 0.0 }
    }

    /// Eq. (21): feed force for chip thickness h (m).
    pub fn feed_force(&self, chip: f64) -> f64 {
        if chip <= 0.0 {
            return 0.0;
        }
        self.specific_force * self.depth_of_cut * chip.powf(1.0 - self.force_exponent) * REFERENCE_CHIP.powf(self.force_exponent)
    }

    /// z of the tool tip, m.
    pub fn tip(state: &ToolState) -> f64 {
        state.holder + state.deflection
    }

    /// The cut of a substep of length h starting at joint angle χ (wrapped, rad)
    /// and speed Ω, with deflection w under the tool.
    pub fn begin(&self, state: &ToolState, w: f64, chi: f64, speed: f64, h: f64) -> ToolStep {
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
        let level = (Self::tip(state) - w).max(-0.5 * self.thickness);
        // No centre passed (a step shorter than a bin): read the bin ahead.
        let read = bins.max(1);
        let mut chip = 0.0;
        for j in 0..read {
            let b = if downwards { first_bin - j } else { first_bin + j }.rem_euclid(n) as usize;
            chip += (state.surface[b] - level).max(0.0);
        }
        chip /= read as f64;
        ToolStep { force: self.feed_force(chip), chip, level, first_bin, bins: bins.max(0), downwards }
    }

    /// Cut the swept bins, move the holder by −v_f h and relax the tip under the held force.
    pub fn commit(&self, state: &mut ToolState, step: &ToolStep, feed_rate: f64, h: f64) {
        let n = SURFACE_BINS as i64;
        for j in 0..step.bins {
            let b = if step.downwards { step.first_bin - j } else { step.first_bin + j }.rem_euclid(n) as usize;
            state.surface[b] = state.surface[b].min(step.level);
        }
        let e_static = step.force / self.stiffness;
        state.deflection = if self.damping > 0.0 {
            e_static + (state.deflection - e_static) * (-self.stiffness / self.damping * h).exp()
        } else {
            e_static
        };
        state.holder -= feed_rate * h;
        state.chip = step.chip;
        state.force = step.force;
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
    fn steady_chip_is_the_feed_per_revolution_for_any_step() {
        // A rigid plate (w = 0) at Ω; after the first revolution the chip is 2π v_f/Ω.
        let (speed, feed) = (100.0 / 60.0 / 0.15, 0.12 / 60.0);
        for h in [1e-3, 3.7e-4, 1e-5] {
            let t = tool();
            let mut s = t.initial_state();
            let mut chi: f64 = 0.0;
            let steps = (3.0 * TAU / speed / h) as usize;
            for _ in 0..steps {
                let step = t.begin(&s, 0.0, chi.rem_euclid(TAU), speed, h);
                t.commit(&mut s, &step, feed, h);
                chi += speed * h;
            }
            let expected = TAU * feed / speed;
            // Bins are cut at substep starts: one revolution between two cuts of
            // a bin is T ± h; with substeps shorter than a bin, a bin is read
            // up to one bin width ahead of its cut.
            let tolerance = (h * speed / TAU).max(1.0 / SURFACE_BINS as f64) + 1e-9;
            assert!((s.chip - expected).abs() <= tolerance * expected, "h = {h}: chip {} vs {expected}", s.chip);
        }
    }
}
