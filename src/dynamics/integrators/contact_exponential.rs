//! `contact_exponential`: one step of ẏ = f(y) for a right-hand side that is
//! smooth on pieces selected by the signs of switching functions s(y) — the
//! stiff contacts of the load models (springs and dampers in series with
//! the residual flexibility, lift-off, a floating caliper's balance).
//!
//! On the piece of the step's start y_r the right-hand side is linearised,
//! f(y) ≈ f(y_r) + J (y − y_r), J by differences of f inside the piece (exact
//! for an affine piece), and the step is the exponential Euler step
//! y = y_r + F(t) f(y_r), F(t) = ∫₀ᵗ e^{τJ} dτ ([`super::piece`]): exact for
//! an affine piece however stiff, and stable (it is the exact flow of the
//! linearisation). What f holds beyond its linearisation (the friction
//! direction, follower terms) is held at its value at y_r over a span, spans
//! halved until its estimated error meets the tolerance; a span that passes
//! carries its second-order correction G(T) Δg / T (the remainder linear in
//! time over the span).
//!
//! The switching functions are affine on the piece too, s(y) ≈ s(y_r) +
//! S (y − y_r), and are sampled along the step every τ_m (τ_m ρ ≤ 1/4, ρ the
//! fastest rate). Where a sign changes, the instant is bisected on the
//! dyadic grid down to h / 2^L; the step restarts there from f of the true
//! law (a new piece), and so on to the step's end. A contact that closes and
//! opens again within one sample interval is not seen.
//!
//! The tables of a piece depend on the piece and on what the caller holds
//! over the step (step, joint speed and acceleration, commands): they are
//! kept in a small cache under that key, least recently used replaced, so a
//! step on a known piece costs one evaluation of f and matrix–vector
//! products.

use super::piece::{BuildScratch, PieceTables};

mod remainder;
mod switches;

/// Pieces kept at most (a limit cycle of 18 contacts visits dozens; chatter two).
pub(crate) const CACHE_PIECES: usize = 64;

/// Pieces kept at least, however large.
const MIN_CACHE_PIECES: usize = 4;

/// Memory the cache's tables may take: fewer pieces are kept when each is large.
const CACHE_BYTES: usize = 128 << 20;

/// Unknowns beyond which `contact_exponential` is refused: a piece holds
/// 4·levels + 5 matrices of n² (0.5 MB each at n = 256) and its build costs
/// O(n³) per level.
pub const MAX_UNKNOWNS: usize = 256;

/// Pieces the cache keeps for n unknowns and `levels` dyadic levels: as many
/// as fit [`CACHE_BYTES`], within [`MIN_CACHE_PIECES`]..=[`CACHE_PIECES`].
pub(crate) fn cache_pieces(n: usize, levels: usize) -> usize {
    let piece_bytes = (4 * (levels + 1) + 1) * n * n * std::mem::size_of::<f64>();
    (CACHE_BYTES / piece_bytes.max(1)).clamp(MIN_CACHE_PIECES, CACHE_PIECES)
}

/// Size of the differences that give J relative to the largest entry of the
/// unknown's block (inside the piece: checked; large, so that the law's
/// rounding stays small against the change it measures).
const DIFFERENCE: f64 = 1.0e-3;

/// Terms of the flow's series within a unit (τρ ≤ 1/4: (1/4)^13/13! < 1e-17).
const SERIES_TERMS: usize = 12;

/// The differences' scale where y is 0 (at the origin), in units of the
/// state's floor `scale`: 1e-3 of the thickness for amplitudes, so that the
/// law's rounding stays small against the change it measures.
const ORIGIN_SCALE: f64 = 1.0e3;

/// A span whose error is below tolerance / COARSEN is followed by spans
/// twice as long: the held remainder's error grows as the span squared, so
/// the next span's is then predicted at half the tolerance.
const COARSEN: f64 = 8.0;

/// Spans whose held remainder's estimated error exceeds this fraction of
/// the tolerance carry its second-order correction (one more evaluation);
/// below it the held step meets the tolerance with margin (affine pieces:
/// the remainder is rounding).
const CORRECTED: f64 = 1.0e-3;

/// A third-order span whose error estimate is below tolerance / COARSEN_THIRD
/// is followed by spans twice as long: its estimate grows as the span cubed.
/// (Without the margin, 8: brake_squeal with a rigid lining takes 14.7
/// evaluations a step in its limit cycle instead of 18.8, but
/// brake_squeal_paper's limit cycle moves from 2.7e-5 to 5.3e-5 of the
/// converged reference.)
const COARSEN_THIRD: f64 = 16.0;

/// What a step did, for diagnostics and tests.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct StepReport {
    /// Switching instants located in the step.
    pub switches: usize,
    /// Pieces whose tables were built in the step.
    pub builds: usize,
    /// Spans halved because the held remainder's error passed the tolerance.
    pub halvings: usize,
    /// Evaluations of the right-hand side in the step.
    pub evaluations: usize,
    /// More than [`MAX_EVENTS`] switches: the rest of the step was taken
    /// span by span without locating switches (`Simulation::unlocated_steps`
    /// counts such steps; `simulate` and the node warn of them).
    pub unlocated: bool,
    /// The fastest rate (1/s) of a piece whose switching functions the
    /// levels L could not sample every quarter radian (0: none). The stepper
    /// sizes L from the scene's rates at rest, so only speed-dependent terms
    /// beyond that bound reach it, and it refuses the step.
    pub undersampled_rate: f64,
}

/// Switches per step beyond which the step stops locating (Zeno-like chatter).
pub const MAX_EVENTS: usize = 4096;

/// What the spans of the last step learnt, carried to the next step in the
/// [`State`](crate::dynamics::State) (not in the integrator: a saved state
/// then replays bit for bit with a fresh stepper): the next step starts at
/// the span length and the order the last one ended with, instead of
/// halving its way down from one whole step again.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct ContactSpans {
    /// Spans are h / 2^level long (at most the integrator's levels L).
    pub level: u8,
    /// The held remainder was more than rounding at the last step's end:
    /// spans are taken at third order from the step's start.
    pub third_order: bool,
}

#[derive(Debug, Clone, PartialEq)]
struct Entry {
    key: Vec<u64>,
    valid: bool,
    last_used: u64,
    /// Linearised at a step's own state (its piece excludes the origin):
    /// dropped when the next step begins.
    this_step_only: bool,
    tables: PieceTables,
}

/// Scratch and the cache of piece tables, allocated once.
#[derive(Debug, Clone, PartialEq)]
pub struct ContactExponential {
    n: usize,
    ns: usize,
    /// L: switching instants are located to h / 2^L.
    levels: usize,
    entries: Vec<Entry>,
    /// Every piece linearised at the step's own state (the law reads memory
    /// the key does not hold: [`ContactExponential::linearise_at_state`]).
    at_state_only: bool,
    clock: u64,
    build: BuildScratch,
    key: Vec<u64>,
    y_r: Vec<f64>,
    f_r: Vec<f64>,
    s_r: Vec<f64>,
    y_a: Vec<f64>,
    y_b: Vec<f64>,
    f_a: Vec<f64>,
    s_t: Vec<f64>,
    diff: Vec<f64>,
    /// Per-component floor of the differences' size and of the error's scale.
    scale: Vec<f64>,
    /// Boundaries of the blocks whose largest entry is the error's scale.
    blocks: Vec<usize>,
    f_end: Vec<f64>,
    s_end: Vec<f64>,
    /// The flow's series within a unit: J^(k−1) f_a, S J^(k−1) f_a, s at y_a.
    series: Vec<f64>,
    series_s: Vec<f64>,
    s_a: Vec<f64>,
    /// The instant (s from y_a) y_b was last taken at along the series.
    series_t: f64,
    /// The remainder's change over a span and the error it makes.
    dg: Vec<f64>,
    /// The switching functions within their bound's reach of a sign change.
    near: Vec<usize>,
    /// The remainder's change at a third-order span's midpoint, and scratch.
    d_a: Vec<f64>,
    work: Vec<f64>,
    err: Vec<f64>,
}

impl ContactExponential {
    /// For n unknowns, ns switching functions and steps located to h / 2^levels.
    pub fn new(n: usize, ns: usize, levels: usize) -> ContactExponential {
        ContactExponential {
            n,
            ns,
            levels,
            entries: (0..cache_pieces(n, levels))
                .map(|_| Entry {
                    key: Vec::with_capacity(64),
                    valid: false,
                    last_used: 0,
                    this_step_only: false,
                    tables: PieceTables::new(n, ns, levels + 1),
                })
                .collect(),
            at_state_only: false,
            clock: 0,
            build: BuildScratch::new(n, ns),
            key: Vec::with_capacity(64),
            y_r: vec![0.0; n],
            f_r: vec![0.0; n],
            s_r: vec![0.0; ns],
            y_a: vec![0.0; n],
            y_b: vec![0.0; n],
            f_a: vec![0.0; n],
            s_t: vec![0.0; ns],
            diff: vec![0.0; n],
            scale: vec![0.0; n],
            blocks: vec![0, n],
            f_end: vec![0.0; n],
            s_end: vec![0.0; ns],
            series: vec![0.0; SERIES_TERMS * n],
            series_s: vec![0.0; SERIES_TERMS * ns],
            s_a: vec![0.0; ns],
            series_t: 0.0,
            dg: vec![0.0; n],
            near: Vec::with_capacity(ns),
            d_a: vec![0.0; n],
            work: vec![0.0; n],
            err: vec![0.0; n],
        }
    }

    /// The levels L for a step h whose switching instants are wanted to
    /// `resolution` (s): h / 2^L ≤ resolution, at least 4.
    pub fn levels_for(h: f64, resolution: f64) -> usize {
        ((h / resolution).log2().ceil().max(4.0) as usize).min(40)
    }

    /// Linearise every piece at the step's own state, never at the origin:
    /// for a law that reads memory besides y and the held key (the tool's
    /// machined surface), whose tables at the origin would depend on when
    /// they were built.
    pub fn linearise_at_state(&mut self, at_state_only: bool) {
        self.at_state_only = at_state_only;
    }

    /// The per-component floor of the differences' size and of the error's
    /// scale (the scale of y where it is 0), and the boundaries of the blocks
    /// of like quantities (amplitudes, rates) whose largest entry scales the
    /// error.
    pub fn set_scale(&mut self, scale: &[f64], blocks: &[usize]) {
        self.scale.copy_from_slice(scale);
        self.blocks.clear();
        self.blocks.extend_from_slice(blocks);
    }

    /// Advance `y` over h. `eval(y, f, s)` writes f(y) and the switching
    /// functions at y; `held` is everything the caller holds over the step
    /// that f depends on besides y (bit patterns: the cache key); `tolerance`
    /// bounds the local error of the held remainder relative to the state's
    /// scale (spans are halved until it holds).
    pub fn step(
        &mut self,
        h: f64,
        y: &mut [f64],
        held: &[u64],
        tolerance: f64,
        spans: &mut ContactSpans,
        eval: &mut impl FnMut(&[f64], &mut [f64], &mut [f64]),
    ) -> StepReport {
        let mut report = StepReport::default();
        let mut count = 0usize;
        let mut counted = |y: &[f64], f: &mut [f64], s: &mut [f64]| {
            count += 1;
            eval(y, f, s)
        };
        let eval = &mut counted;
        let total: u64 = 1 << self.levels;
        let unit = h / total as f64;
        // Time from the step's start in units of h / 2^L: a switch restarts
        // the step at its instant, which need not lie on the grid.
        let mut pos = 0.0f64;
        let mut span_level = (spans.level as usize).min(self.levels);
        // Whether a span found its held remainder's estimate above
        // CORRECTED × tolerance (not an affine piece's rounding): the rest
        // of the step is then taken by [`Self::third_order_span`].
        let mut nonlinear = spans.third_order;
        // The last third-order span's estimate: below CORRECTED × tolerance
        // the next step starts on the held remainder again.
        let mut third_error = f64::INFINITY;
        // (pos, units): from the start at pos, no switch within units.
        let mut clear = (-1.0f64, 0u64);
        for entry in self.entries.iter_mut().filter(|e| e.this_step_only) {
            entry.valid = false;
        }
        self.y_r.copy_from_slice(y);
        eval(&self.y_r, &mut self.f_r, &mut self.s_r);
        loop {
            let remaining = total as f64 - pos;
            if remaining <= 1e-9 {
                break;
            }
            let e = self.piece(h, held, eval, &mut report);
            let events = report.switches;
            let whole = (remaining.floor() as u64).min(total >> span_level);
            if events >= MAX_EVENTS {
                // Zeno-like chatter: finish the step piece by piece without
                // locating (each span starts from the true law).
                report.unlocated = true;
                let span = whole.max(1).min(remaining.ceil() as u64);
                self.advance_from_rest(e, span);
                self.y_r.copy_from_slice(&self.y_a);
                eval(&self.y_r, &mut self.f_r, &mut self.s_r);
                pos += span as f64;
                continue;
            }
            // A span tried again from the same start (after a failed
            // check) needs no new scan where the last one found none at the
            // same samples: within its reach and ending on a sample.
            let spacing = 1u64 << (self.levels - self.entries[e].tables.sample_level());
            let scanned = clear.0 == pos && whole <= clear.1 && whole.is_multiple_of(spacing);
            let found = if whole == 0 || scanned {
                None
            } else {
                let found = self.first_switch(e, whole);
                if found.is_none() {
                    clear = (pos, whole);
                }
                found
            };
            if nonlinear && whole >= 2 && found.is_none() {
                // The largest dyadic span within `whole` (a span after a
                // switch may start off the grid).
                let span = 1u64 << (63 - whole.leading_zeros());
                let error = self.third_order_span(e, span, unit, eval);
                if error > tolerance && span_level < self.levels {
                    let finer = ((error / tolerance).log2() / 3.0).ceil().max(1.0) as usize;
                    span_level = (span_level + finer).min(self.levels);
                    report.halvings += 1;
                    continue;
                }
                eval(&self.y_b, &mut self.f_end, &mut self.s_end);
                third_error = error;
                pos += span as f64;
                self.y_r.copy_from_slice(&self.y_b);
                std::mem::swap(&mut self.f_r, &mut self.f_end);
                std::mem::swap(&mut self.s_r, &mut self.s_end);
                if error < tolerance / COARSEN_THIRD && span_level > 0 {
                    span_level -= 1;
                }
                continue;
            }
            let (end, switched) = if whole == 0 {
                // The step's last fraction of a unit: the flow's series.
                self.y_a.copy_from_slice(&self.y_r);
                self.within_unit(e, remaining, unit)
            } else {
                match found {
                    None => {
                        self.advance_from_rest(e, whole);
                        self.y_b.copy_from_slice(&self.y_a);
                        (whole as f64, false)
                    }
                    Some((a, b)) => {
                        let a = self.bisect(e, a, b);
                        // The remainder's error up to the switch, on the old
                        // piece (f at y_a is still of it).
                        if a > 1 && tolerance < 1.0 {
                            self.y_b.copy_from_slice(&self.y_a);
                            eval(&self.y_b, &mut self.f_end, &mut self.s_end);
                            let error = self.held_error(e, a as f64, unit);
                            if error > tolerance && span_level < self.levels {
                                span_level += 1;
                                report.halvings += 1;
                                continue;
                            }
                        }
                        let (theta, switched) = self.within_unit(e, 1.0, unit);
                        (a as f64 + theta, switched)
                    }
                }
            };
            eval(&self.y_b, &mut self.f_end, &mut self.s_end);
            let end = if switched {
                end + self.confirm_switch(unit, eval)
            } else {
                end
            };
            // A span that ends at a switch is no longer than the spans that
            // pass the check (and f(y_b) is of the next piece): not checked.
            let error = if switched {
                0.0
            } else {
                self.held_error(e, end, unit)
            };
            if error > CORRECTED * tolerance && !nonlinear && !switched && end >= 2.0 {
                // The held remainder is more than rounding: this step's
                // spans are taken at third order from here on (the same
                // span again first).
                nonlinear = true;
                continue;
            }
            if error > tolerance && span_level < self.levels && end > 1.0 {
                span_level += 1;
                report.halvings += 1;
                continue;
            }
            if !switched && error > CORRECTED * tolerance {
                self.correct_remainder(e, end, unit, eval);
            }
            report.switches += switched as usize;
            pos += end;
            self.y_r.copy_from_slice(&self.y_b);
            std::mem::swap(&mut self.f_r, &mut self.f_end);
            std::mem::swap(&mut self.s_r, &mut self.s_end);
            if error < tolerance / COARSEN && span_level > 0 && !switched {
                span_level -= 1;
            }
        }
        y.copy_from_slice(&self.y_r);
        *spans = ContactSpans {
            level: span_level as u8,
            third_order: nonlinear && third_error >= CORRECTED * tolerance,
        };
        report.evaluations = count;
        report
    }

    /// The entry for the piece of (y_r, s_r) under `held`: found, or built.
    fn piece(
        &mut self,
        h: f64,
        held: &[u64],
        eval: &mut impl FnMut(&[f64], &mut [f64], &mut [f64]),
        report: &mut StepReport,
    ) -> usize {
        self.key.clear();
        self.key.push(h.to_bits());
        self.key.extend_from_slice(held);
        for chunk in self.s_r.chunks(64) {
            let bits = chunk
                .iter()
                .enumerate()
                .fold(0u64, |b, (i, &s)| b | (((s > 0.0) as u64) << i));
            self.key.push(bits);
        }
        self.clock += 1;
        if let Some(i) = self
            .entries
            .iter()
            .position(|e| e.valid && e.key == self.key)
        {
            self.entries[i].last_used = self.clock;
            return i;
        }
        let i = (0..self.entries.len())
            .min_by_key(|&i| (self.entries[i].valid, self.entries[i].last_used))
            .unwrap_or(0);
        // Linearised at the origin (the undeformed disc) where it lies in the
        // piece, else at y_r: a piece's tables are then a function of its key
        // alone, or kept for this step only — so a saved state replays bit for
        // bit with a fresh cache.
        let at_origin = !self.at_state_only && {
            self.y_b.iter_mut().for_each(|v| *v = 0.0);
            eval(&self.y_b, &mut self.f_end, &mut self.s_end);
            same_piece(&self.s_r, &self.s_end)
        };
        if at_origin {
            std::mem::swap(&mut self.y_r, &mut self.y_b);
            std::mem::swap(&mut self.f_r, &mut self.f_end);
            std::mem::swap(&mut self.s_r, &mut self.s_end);
        }
        self.jacobian(i, eval, at_origin);
        if at_origin {
            std::mem::swap(&mut self.y_r, &mut self.y_b);
            std::mem::swap(&mut self.f_r, &mut self.f_end);
            std::mem::swap(&mut self.s_r, &mut self.s_end);
        }
        let entry = &mut self.entries[i];
        entry.tables.build(h, &mut self.build);
        if !entry.tables.samples_every_quarter_radian(h) {
            report.undersampled_rate = report.undersampled_rate.max(entry.tables.rate());
        }
        if at_origin {
            entry.tables.fill_sample_table(&mut self.build);
        }
        entry.key.clear();
        entry.key.extend_from_slice(&self.key);
        entry.valid = true;
        entry.this_step_only = !at_origin;
        entry.last_used = self.clock;
        report.builds += 1;
        i
    }

    /// J and S of entry `i` by forward differences at y_r, each kept inside
    /// the piece of y_r (the other side, then smaller, where it leaves it).
    fn jacobian(
        &mut self,
        i: usize,
        eval: &mut impl FnMut(&[f64], &mut [f64], &mut [f64]),
        at_origin: bool,
    ) {
        let (n, ns) = (self.n, self.ns);
        for w in self.blocks.windows(2) {
            let r = w[0]..w[1];
            let size = if at_origin {
                0.0
            } else {
                self.y_r[r.clone()]
                    .iter()
                    .fold(0.0f64, |m, v| m.max(v.abs()))
            };
            for i in r {
                self.diff[i] = DIFFERENCE * size.max(ORIGIN_SCALE * self.scale[i]);
            }
        }
        for col in 0..n {
            let base = self.diff[col];
            let mut delta = base;
            for attempt in 0..6 {
                self.y_a.copy_from_slice(&self.y_r);
                self.y_a[col] += delta;
                eval(&self.y_a, &mut self.f_a, &mut self.s_t);
                if same_piece(&self.s_r, &self.s_t) || attempt == 5 {
                    break;
                }
                delta = if attempt % 2 == 0 {
                    -delta
                } else {
                    -delta * 1e-3
                };
            }
            let t = &mut self.entries[i].tables;
            for row in 0..n {
                t.jac[row * n + col] = (self.f_a[row] - self.f_r[row]) / delta;
            }
            for row in 0..ns {
                let d = self.s_t[row] - self.s_r[row];
                t.s_rows[row * n + col] = if d.is_finite() { d / delta } else { 0.0 };
            }
        }
    }
}

/// out += c m x (m square).
fn mul_add_scaled(m: &[f64], x: &[f64], c: f64, out: &mut [f64]) {
    let n = x.len();
    for (o, row) in out.iter_mut().zip(m.chunks_exact(n)) {
        *o += c * row.iter().zip(x).map(|(a, b)| a * b).sum::<f64>();
    }
}

/// Whether two sets of switching functions select the same piece.
fn same_piece(a: &[f64], b: &[f64]) -> bool {
    a.iter().zip(b).all(|(x, y)| (*x > 0.0) == (*y > 0.0))
}

#[cfg(test)]
mod tests;
