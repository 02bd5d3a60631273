//! What one substep of the lathe tool cuts: the bins it sweeps and the cut
//! held over it, stored in the tool's slot (`tool.rs`).

/// Bins of the machined-shoulder height S(φ) over one revolution.
pub const SURFACE_BINS: usize = 4096;

/// The [`ToolStep`] held over the current substep (force, chip, level, first bin, bins, direction, h).
pub(super) const HELD: usize = 6;
/// Shoulder height S of bin b at `SURFACE + b`, m.
pub const SURFACE: usize = 13;
/// The surface bins one substep sweeps: the first, how many, and the direction.
#[derive(Debug, Clone, Copy)]
pub(super) struct Sweep {
    pub(super) first_bin: i64,
    pub(super) bins: i64,
    pub(super) downwards: bool,
}

/// Slot indices of `count` surface bins from `first_bin` on, downwards or
/// upwards in φ (wrapping round the revolution), in the order swept.
pub(super) fn bin_entries(
    first_bin: i64,
    downwards: bool,
    count: i64,
) -> impl Iterator<Item = usize> {
    let n = SURFACE_BINS as i64;
    (0..count).map(move |j| {
        SURFACE
            + if downwards {
                first_bin - j
            } else {
                first_bin + j
            }
            .rem_euclid(n) as usize
    })
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
    /// Number of bins swept.
    pub bins: i64,
    /// Whether the bins are visited downwards in φ (Ω > 0).
    pub downwards: bool,
    /// The substep's length, s.
    pub h: f64,
}

impl ToolStep {
    /// Slot indices of the surface bins the substep sweeps, in the order swept.
    pub(super) fn swept_entries(&self) -> impl Iterator<Item = usize> {
        bin_entries(self.first_bin, self.downwards, self.bins)
    }

    /// The bins it sweeps.
    pub(super) fn sweep(&self) -> Sweep {
        Sweep {
            first_bin: self.first_bin,
            bins: self.bins,
            downwards: self.downwards,
        }
    }

    pub(super) fn store(&self, slot: &mut [f64]) {
        let held = [
            self.force,
            self.chip,
            self.level,
            self.first_bin as f64,
            self.bins as f64,
            if self.downwards { 1.0 } else { 0.0 },
            self.h,
        ];
        slot[HELD..HELD + 7].copy_from_slice(&held);
    }

    pub(super) fn load(slot: &[f64]) -> ToolStep {
        let h = &slot[HELD..HELD + 7];
        ToolStep {
            force: h[0],
            chip: h[1],
            level: h[2],
            first_bin: h[3] as i64,
            bins: h[4] as i64,
            downwards: h[5] != 0.0,
            h: h[6],
        }
    }
}
