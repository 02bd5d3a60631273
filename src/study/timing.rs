//! Wall-clock measurements for the study: the minimum over repeats within a
//! time budget (the minimum is the least disturbed by other processes on a
//! shared machine; the errors never depend on it).

use std::time::{Duration, Instant};

/// Seconds per call of `f`: `f` is called once, then repeated until `budget`
/// has passed (at least `min_repeats` calls in all, at most `max_repeats`);
/// the fastest call counts.
pub fn min_time(
    budget: Duration,
    min_repeats: usize,
    max_repeats: usize,
    mut f: impl FnMut(),
) -> f64 {
    let start = Instant::now();
    let mut best = f64::INFINITY;
    let mut calls = 0;
    loop {
        let t = Instant::now();
        f();
        best = best.min(t.elapsed().as_secs_f64());
        calls += 1;
        if calls >= max_repeats || (calls >= min_repeats && start.elapsed() >= budget) {
            return best;
        }
    }
}

/// Seconds per unit of work for a cheap operation: `f(n)` performs `n` units;
/// batches are sized to last ≳ 1/20 of the budget, the fastest batch counts.
pub fn min_time_per_unit(budget: Duration, mut f: impl FnMut(usize)) -> f64 {
    // Size a batch from one probing call.
    let t = Instant::now();
    f(1);
    let one = t.elapsed().as_secs_f64().max(1e-9);
    let target = (budget.as_secs_f64() / 20.0).max(2e-4);
    let n = ((target / one).ceil() as usize).clamp(1, 1_000_000);
    min_time(budget, 3, 1000, || f(n)) / n as f64
}
