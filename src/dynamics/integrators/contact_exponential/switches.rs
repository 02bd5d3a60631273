//! Locating a piece's switches: the sample scan (from the piece's table, or
//! along its flow), bisection on the dyadic grid to one unit, the instant
//! within the unit from the flow's Taylor series.

use super::{same_piece, ContactExponential};
use crate::dynamics::integrators::piece::mul_add;

impl ContactExponential {
    /// The first sample interval (a, b] (units of h / 2^L from y_r) in which
    /// a switching function changes sign, within `remaining` units.
    pub(super) fn first_switch(&mut self, e: usize, remaining: u64) -> Option<(u64, u64)> {
        let t = &self.entries[e].tables;
        let m = t.sample_level();
        let spacing = 1u64 << (self.levels - m);
        if !t.has_samples() {
            return self.first_switch_along_flow(e, remaining);
        }
        // No sign can change where every |s_i| exceeds its bound's reach (or
        // where s_i cannot move: a pad pressed with nothing).
        let reach = self.f_r.iter().map(|v| v * v).sum::<f64>().sqrt();
        let far = self
            .s_r
            .iter()
            .zip(t.bound())
            .all(|(s, b)| s.abs() > b * reach || b * reach == 0.0);
        if far && remaining == 1 << self.levels {
            return None;
        }
        // Only the functions within their bound's reach can change sign at
        // a sample (|S F(i τ_m) f_r| ≤ bound ‖f_r‖ / 2 there): the others'
        // rows are skipped, with the same decisions.
        self.near.clear();
        self.near.extend(
            self.s_r
                .iter()
                .zip(t.bound())
                .enumerate()
                .filter(|(_, (s, b))| !(s.abs() > *b * reach || *b * reach == 0.0))
                .map(|(i, _)| i),
        );
        let n = self.n;
        let mut last = 0;
        for i in 1..=(1usize << m) {
            let at = i as u64 * spacing;
            if at > remaining {
                break;
            }
            let sampled = t.sampled(i);
            for &row in &self.near {
                let moved = sampled[row * n..(row + 1) * n]
                    .iter()
                    .zip(&self.f_r)
                    .map(|(a, b)| a * b)
                    .sum::<f64>();
                if (self.s_r[row] + moved > 0.0) != (self.s_r[row] > 0.0) {
                    return Some((last, at));
                }
            }
            last = at;
        }
        self.end_check(e, last, remaining)
    }

    /// [`Self::first_switch`] for a piece without a sample table (kept for
    /// this step only): the flow stepped from sample to sample, y ← y +
    /// F(τ_m) (f_r + J (y − y_r)), and s = s_r + S (y − y_r) at each.
    pub(super) fn first_switch_along_flow(
        &mut self,
        e: usize,
        remaining: u64,
    ) -> Option<(u64, u64)> {
        let m = self.entries[e].tables.sample_level();
        let spacing = 1u64 << (self.levels - m);
        self.y_a.copy_from_slice(&self.y_r);
        let mut last = 0;
        for i in 1..=(1u64 << m) {
            let at = i * spacing;
            if at > remaining {
                break;
            }
            self.advance_a(e, m);
            self.switching_at_a(e);
            if !same_piece(&self.s_r, &self.s_t) {
                return Some((last, at));
            }
            last = at;
        }
        self.end_check(e, last, remaining)
    }

    /// Whether the piece leaves between the last sample `last` and `remaining`.
    pub(super) fn end_check(&mut self, e: usize, last: u64, remaining: u64) -> Option<(u64, u64)> {
        if last == remaining {
            return None;
        }
        self.advance_from_rest(e, remaining);
        self.switching_at_a(e);
        (!same_piece(&self.s_r, &self.s_t)).then_some((last, remaining))
    }

    /// y_a = y(units) on the piece from y_r: one table level per binary
    /// digit (the first from f_r itself).
    pub(super) fn advance_from_rest(&mut self, e: usize, units: u64) {
        self.y_a.copy_from_slice(&self.y_r);
        let mut first = true;
        for bit in (0..=self.levels).rev() {
            if units & (1 << bit) == 0 {
                continue;
            }
            if first {
                mul_add(
                    self.entries[e].tables.f(self.levels - bit),
                    &self.f_r,
                    &mut self.y_a,
                );
                first = false;
            } else {
                self.advance_a(e, self.levels - bit);
            }
        }
    }

    /// y_a ← y_a + F(τ_j) (f_r + J (y_a − y_r)).
    pub(super) fn advance_a(&mut self, e: usize, j: usize) {
        let t = &self.entries[e].tables;
        self.f_a.copy_from_slice(&self.f_r);
        for ((d, a), r) in self.diff.iter_mut().zip(&self.y_a).zip(&self.y_r) {
            *d = a - r;
        }
        mul_add(&t.jac, &self.diff, &mut self.f_a);
        mul_add(t.f(j), &self.f_a, &mut self.y_a);
    }

    /// s_t = s_r + S (y_a − y_r).
    pub(super) fn switching_at_a(&mut self, e: usize) {
        for ((d, a), r) in self.diff.iter_mut().zip(&self.y_a).zip(&self.y_r) {
            *d = a - r;
        }
        self.s_t.copy_from_slice(&self.s_r);
        mul_add(&self.entries[e].tables.s_rows, &self.diff, &mut self.s_t);
    }

    /// Bisect the switch in (a, b] to one unit: leaves y_a at a (on the old
    /// piece), the switch in (a, a + 1], and returns a.
    pub(super) fn bisect(&mut self, e: usize, mut a: u64, mut b: u64) -> u64 {
        self.advance_from_rest(e, a);
        while b - a > 1 {
            let half = 1u64 << (63 - ((b - a) / 2).leading_zeros());
            self.y_b.copy_from_slice(&self.y_a);
            self.advance_a(e, self.levels - half.trailing_zeros() as usize);
            self.switching_at_a(e);
            if same_piece(&self.s_r, &self.s_t) {
                a += half;
            } else {
                b = a + half;
                self.y_a.copy_from_slice(&self.y_b);
            }
        }
        a
    }

    /// From y_a over at most `span` (≤ 1) units on the piece: the flow as its
    /// series y(θτ) = y_a + Σ_k (θτ)^k / k! J^(k−1) f_a (τ the unit; τ ρ ≤ 1/4
    /// per sub-span, so the series converges to rounding), the first instant
    /// θ where a switching function changes sign found on the polynomial by
    /// bisection. Leaves y(θ) in y_b; returns θ and whether it is a switch.
    pub(super) fn within_unit(&mut self, e: usize, span: f64, unit: f64) -> (f64, bool) {
        let rate = self.entries[e].tables.rate();
        let pieces = ((span * unit * rate / 0.25).ceil() as usize).clamp(1, 64);
        let sub = span / pieces as f64;
        for piece in 0..pieces {
            self.series_at_a(e);
            if let Some(t) = self.first_root(sub * unit) {
                self.series_to_b(t);
                return (piece as f64 * sub + t / unit, true);
            }
            self.series_to_b(sub * unit);
            self.y_a.copy_from_slice(&self.y_b);
        }
        (span, false)
    }

    /// The law has not left the piece at the located root (rounding): step
    /// on along the series, 1e-6 of a unit and then four times as far each
    /// time, until it has (at most 8 times: 0.022 units). Leaves y_b, f_end,
    /// s_end there; returns the units added.
    pub(super) fn confirm_switch(
        &mut self,
        unit: f64,
        eval: &mut impl FnMut(&[f64], &mut [f64], &mut [f64]),
    ) -> f64 {
        let mut extra = 0.0;
        let mut step = 1.0e-6;
        for _ in 0..8 {
            if !same_piece(&self.s_r, &self.s_end) {
                break;
            }
            extra += step;
            step *= 4.0;
            self.series_to_b(self.series_t + extra * unit);
            eval(&self.y_b, &mut self.f_end, &mut self.s_end);
        }
        extra
    }

    /// The series' vectors at y_a: z_k = J^(k−1) f_a with f_a = f_r + J (y_a − y_r),
    /// S z_k, and s at y_a.
    pub(super) fn series_at_a(&mut self, e: usize) {
        let (n, ns) = (self.n, self.ns);
        let t = &self.entries[e].tables;
        for ((d, a), r) in self.diff.iter_mut().zip(&self.y_a).zip(&self.y_r) {
            *d = a - r;
        }
        self.s_a.copy_from_slice(&self.s_r);
        mul_add(&t.s_rows, &self.diff, &mut self.s_a);
        let (first, rest) = self.series.split_at_mut(n);
        first.copy_from_slice(&self.f_r);
        mul_add(&t.jac, &self.diff, first);
        let mut prev: &[f64] = first;
        for z in rest.chunks_exact_mut(n) {
            z.iter_mut().for_each(|v| *v = 0.0);
            mul_add(&t.jac, prev, z);
            prev = z;
        }
        for (w, z) in self
            .series_s
            .chunks_exact_mut(ns.max(1))
            .zip(self.series.chunks_exact(n))
        {
            w.iter_mut().for_each(|v| *v = 0.0);
            mul_add(&t.s_rows, z, &mut w[..ns]);
        }
    }

    /// The earliest t in (0, t_end] at which s leaves the piece of y_r along
    /// the series, if it does: bisection on the polynomial, the returned
    /// instant just past the root.
    pub(super) fn first_root(&mut self, t_end: f64) -> Option<f64> {
        let mut first: Option<f64> = None;
        for i in 0..self.ns {
            let on = self.s_r[i] > 0.0;
            if (self.series_s_at(i, t_end) > 0.0) == on {
                continue;
            }
            let (mut lo, mut hi) = (0.0, t_end);
            for _ in 0..80 {
                let mid = 0.5 * (lo + hi);
                if mid <= lo || mid >= hi {
                    break;
                }
                if (self.series_s_at(i, mid) > 0.0) == on {
                    lo = mid;
                } else {
                    hi = mid;
                }
            }
            first = Some(first.map_or(hi, |f| f.min(hi)));
        }
        first
    }

    /// s_i along the series at t.
    pub(super) fn series_s_at(&self, i: usize, t: f64) -> f64 {
        let ns = self.ns;
        let mut c = 1.0;
        let mut v = self.s_a[i];
        for (k, w) in self.series_s.chunks_exact(ns).enumerate() {
            c *= t / (k + 1) as f64;
            v += c * w[i];
        }
        v
    }

    /// y_b = y_a + Σ_k t^k/k! z_k.
    pub(super) fn series_to_b(&mut self, t: f64) {
        self.series_t = t;
        self.y_b.copy_from_slice(&self.y_a);
        let mut c = 1.0;
        for (k, z) in self.series.chunks_exact(self.n).enumerate() {
            c *= t / (k + 1) as f64;
            for (b, zi) in self.y_b.iter_mut().zip(z) {
                *b += c * zi;
            }
        }
    }
}
