//! The held remainder: what f holds beyond its piece's linearisation, held
//! at its value at a span's start; its local error estimate, the
//! third-order span that corrects it, and the state's scaled error.

use super::{mul_add_scaled, ContactExponential};
use crate::dynamics::integrators::piece::mul_add;

impl ContactExponential {
    /// The local error of holding f's remainder at its value at y_r over
    /// `units` to y_b: with Δg = f(y_b) − f(y_r) − J (y_b − y_r) the
    /// remainder's change, ½ F(t) Δg (exact for a remainder that changes
    /// linearly in time; F(t) ≈ t I for a span that ends at a switch, an upper
    /// bound for oscillatory pieces), against the state's scale.
    pub(super) fn held_error(&mut self, e: usize, units: f64, unit: f64) -> f64 {
        let t = &self.entries[e].tables;
        let (y_r, f_r) = (&self.y_r, &self.f_r);
        remainder_change(
            &t.jac,
            y_r,
            f_r,
            &self.y_b,
            &self.f_end,
            &mut self.diff,
            &mut self.dg,
        );
        self.err.iter_mut().for_each(|v| *v = 0.0);
        let whole = units as u64;
        if units == whole as f64 && whole.is_power_of_two() {
            let j = self.levels - whole.trailing_zeros() as usize;
            mul_add_scaled(t.f(j), &self.dg, 0.5, &mut self.err);
        } else {
            let half_t = 0.5 * units * unit;
            for (d, g) in self.err.iter_mut().zip(&self.dg) {
                *d = half_t * g;
            }
        }
        self.scaled_error()
    }

    /// One span of `units` (a power of two, at least 2) from y_r, no switch
    /// inside, by the third-order exponential Runge–Kutta step of Cox and
    /// Matthews (ETD3RK) on the piece's linearisation: with the remainder's
    /// changes D_a at y_a = y_r + F(T/2) f_r and D_b at y_b = y_r + F(T)
    /// (f_r + 2 D_a) (each Δg = f − f_r − J (y − y_r)), the remainder taken as
    /// the quadratic in time through 0, D_a, D_b at 0, T/2, T gives
    ///
    ///   y(T) = y_r + F(T) f_r + G(T) (4 D_a − D_b) / T + 4 H(T) (D_b − 2 D_a) / T²,
    ///
    /// left in y_b (f not yet evaluated there). Returns the scaled estimate
    /// of the error of the second-order step y_r + F f_r + G D_b / T it
    /// extends, (2 G / T − 4 H / T²)(2 D_a − D_b) (the remainder's curvature
    /// over the span): the third-order step is more accurate than it.
    pub(super) fn third_order_span(
        &mut self,
        e: usize,
        units: u64,
        unit: f64,
        eval: &mut impl FnMut(&[f64], &mut [f64], &mut [f64]),
    ) -> f64 {
        let j = self.levels - units.trailing_zeros() as usize;
        let t = units as f64 * unit;
        let tables = &self.entries[e].tables;
        self.y_a.copy_from_slice(&self.y_r);
        mul_add(tables.f(j + 1), &self.f_r, &mut self.y_a);
        eval(&self.y_a, &mut self.f_a, &mut self.s_t);
        let tables = &self.entries[e].tables;
        remainder_change(
            &tables.jac,
            &self.y_r,
            &self.f_r,
            &self.y_a,
            &self.f_a,
            &mut self.diff,
            &mut self.d_a,
        );
        for ((w, f), d) in self.work.iter_mut().zip(&self.f_r).zip(&self.d_a) {
            *w = f + 2.0 * d;
        }
        self.y_b.copy_from_slice(&self.y_r);
        mul_add(tables.f(j), &self.work, &mut self.y_b);
        eval(&self.y_b, &mut self.f_end, &mut self.s_end);
        let tables = &self.entries[e].tables;
        remainder_change(
            &tables.jac,
            &self.y_r,
            &self.f_r,
            &self.y_b,
            &self.f_end,
            &mut self.diff,
            &mut self.dg,
        );
        // The curvature 2 D_a − D_b, and the step.
        for ((w, a), b) in self.work.iter_mut().zip(&self.d_a).zip(&self.dg) {
            *w = 2.0 * a - b;
        }
        self.y_b.copy_from_slice(&self.y_r);
        mul_add(tables.f(j), &self.f_r, &mut self.y_b);
        for ((d, a), b) in self.diff.iter_mut().zip(&self.d_a).zip(&self.dg) {
            *d = 4.0 * a - b;
        }
        mul_add_scaled(tables.g(j), &self.diff, 1.0 / t, &mut self.y_b);
        mul_add_scaled(tables.h(j), &self.work, -4.0 / (t * t), &mut self.y_b);
        self.err.iter_mut().for_each(|v| *v = 0.0);
        mul_add_scaled(tables.g(j), &self.work, 2.0 / t, &mut self.err);
        mul_add_scaled(tables.h(j), &self.work, -4.0 / (t * t), &mut self.err);
        self.scaled_error()
    }

    /// The held remainder's second-order correction at the end of a span of
    /// `units` that passed its check: with the remainder taken to change
    /// linearly in time by Δg over the span T (Δg from [`Self::held_error`]),
    /// the flow gains ∫₀ᵀ e^{(T−s)J} Δg s/T ds = G(T) Δg / T. On spans of one
    /// table level; y_b, f_end and s_end then at the corrected state.
    pub(super) fn correct_remainder(
        &mut self,
        e: usize,
        units: f64,
        unit: f64,
        eval: &mut impl FnMut(&[f64], &mut [f64], &mut [f64]),
    ) {
        let whole = units as u64;
        if units != whole as f64 || !whole.is_power_of_two() {
            return;
        }
        let j = self.levels - whole.trailing_zeros() as usize;
        let g = self.entries[e].tables.g(j);
        mul_add_scaled(g, &self.dg, 1.0 / (units * unit), &mut self.y_b);
        eval(&self.y_b, &mut self.f_end, &mut self.s_end);
    }

    /// max over the blocks of |err| over the block's largest |y| (y_r, y_b
    /// and the floor).
    pub(super) fn scaled_error(&self) -> f64 {
        let mut worst = 0.0f64;
        for w in self.blocks.windows(2) {
            let r = w[0]..w[1];
            let scale = self.y_r[r.clone()]
                .iter()
                .chain(&self.y_b[r.clone()])
                .chain(&self.scale[r.clone()])
                .fold(0.0f64, |m, v| m.max(v.abs()));
            let err = self.err[r].iter().fold(0.0f64, |m, v| m.max(v.abs()));
            worst = worst.max(err / scale);
        }
        worst
    }
}

/// Δg = f_x − f_r − J (x − y_r) into `out` (`diff` scratch): the change of
/// f's remainder beyond its linearisation from y_r to x.
fn remainder_change(
    jac: &[f64],
    y_r: &[f64],
    f_r: &[f64],
    x: &[f64],
    f_x: &[f64],
    diff: &mut [f64],
    out: &mut [f64],
) {
    for ((d, a), r) in diff.iter_mut().zip(x).zip(y_r) {
        *d = a - r;
    }
    for (((o, fx), fr), row) in out
        .iter_mut()
        .zip(f_x)
        .zip(f_r)
        .zip(jac.chunks_exact(diff.len()))
    {
        *o = fx - fr - row.iter().zip(diff.iter()).map(|(a, b)| a * b).sum::<f64>();
    }
}
