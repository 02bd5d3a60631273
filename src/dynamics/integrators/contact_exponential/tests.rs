//! Unit tests of the contact exponential: exact half sines, the third-order
//! span's error, the cache's memory bound, samples every quarter radian.

use super::*;

/// A bilinear oscillator, ẍ = −ω₁² x below 0 and −ω₂² x above (a contact
/// spring that closes at x = 0), from x = 0, ẋ = 1: exactly a half sine
/// of each frequency in turn, switching at t_k = k-th sum of half periods.
fn bilinear(y: &[f64], f: &mut [f64], s: &mut [f64]) {
    let (w1, w2) = (2.0e3, 3.0e4);
    let w = if y[0] > 0.0 { w2 } else { w1 };
    f[0] = y[1];
    f[1] = -w * w * y[0];
    s[0] = y[0];
}

fn exact(t: f64) -> [f64; 2] {
    let (w1, w2) = (2.0e3, 3.0e4);
    let period = std::f64::consts::PI * (1.0 / w1 + 1.0 / w2);
    let t = t % period;
    let up = std::f64::consts::PI / w2;
    if t < up {
        [(w2 * t).sin() / w2, (w2 * t).cos()]
    } else {
        let u = t - up;
        [-(w1 * u).sin() / w1, -(w1 * u).cos()]
    }
}

/// ẏ = −k y + y² (Bernoulli: 1/y = 1/k + (1/y₀ − 1/k) e^{kt}), strongly
/// nonlinear from y₀ = k/2: the piece's J is −k, the remainder y².
fn bernoulli(y: &[f64], f: &mut [f64], _: &mut [f64]) {
    f[0] = -10.0 * y[0] + y[0] * y[0];
}

fn bernoulli_exact(y0: f64, t: f64) -> f64 {
    let k = 10.0;
    1.0 / (1.0 / k + (1.0 / y0 - 1.0 / k) * (k * t).exp())
}

#[test]
fn a_third_order_span_s_error_falls_as_the_span_to_the_fourth_and_stays_below_its_estimate() {
    let (h, levels, y0) = (0.1, 10, 5.0);
    let mut c = ContactExponential::new(1, 0, levels);
    c.set_scale(&[1e-9], &[0, 1]);
    let mut eval = bernoulli;
    let (mut f, mut s) = ([0.0], [0.0; 0]);
    eval(&[y0], &mut f, &mut s);
    let mut report = StepReport::default();
    let unit = h / (1u64 << levels) as f64;
    let mut errors = Vec::new();
    for units in [64u64, 32, 16, 8] {
        c.y_r[0] = y0;
        c.f_r[0] = f[0];
        let e = c.piece(h, &[], &mut eval, &mut report);
        let estimate = c.third_order_span(e, units, unit, &mut eval);
        let exact = bernoulli_exact(y0, units as f64 * unit);
        let error = (c.y_b[0] - exact).abs() / y0;
        println!("{units} units: error {error:.3e}, estimate {estimate:.3e}");
        assert!(error < estimate, "{units}: {error} vs {estimate}");
        errors.push(error);
    }
    for pair in errors.windows(2) {
        let ratio = pair[0] / pair[1];
        assert!((12.0..20.0).contains(&ratio), "{errors:?}");
    }
}

#[test]
fn the_cache_keeps_its_tables_within_its_memory_bound() {
    // The brake scenes (≤ 40 unknowns) keep every piece.
    assert_eq!(cache_pieces(40, 12), CACHE_PIECES);
    for n in [40, 100, 190, MAX_UNKNOWNS] {
        for levels in [4, 12, 20, 40] {
            let pieces = cache_pieces(n, levels);
            let bytes = pieces * (4 * (levels + 1) + 1) * n * n * 8;
            assert!((MIN_CACHE_PIECES..=CACHE_PIECES).contains(&pieces));
            assert!(
                bytes <= CACHE_BYTES || pieces == MIN_CACHE_PIECES,
                "{n} {levels}: {bytes}"
            );
        }
    }
}

#[test]
fn a_contact_that_closes_and_opens_inside_steps_follows_the_exact_half_sines() {
    let h = 1.0e-3; // the stiff side turns 30 rad per step
    let levels = ContactExponential::levels_for(h, 2.5e-7);
    let mut c = ContactExponential::new(2, 1, levels);
    c.set_scale(&[1e-9, 1e-6], &[0, 1, 2]);
    let mut y = [0.0, 1.0];
    let mut switches = 0;
    let mut worst = 0.0f64;
    let mut spans = ContactSpans::default();
    for step in 1..=40 {
        let r = c.step(h, &mut y, &[], 1e-12, &mut spans, &mut bilinear);
        switches += r.switches;
        let e = exact(step as f64 * h);
        worst = worst
            .max(((y[0] - e[0]) * 2.0e3).abs())
            .max((y[1] - e[1]).abs());
    }
    // Each switch is located to h/2^L ≤ 2.5e-7 s; between switches the flow is exact.
    println!("switches {switches}, worst {worst:e}");
    assert!(worst < 1e-3, "{worst}");
}

/// A fast oscillator, ẍ = −ω² x, from x = 0, ẋ = 1, whose switching
/// function x − 0.95/ω is positive only within ±acos 0.95 = ±0.318 rad of
/// each crest.
fn crests(w: f64) -> impl FnMut(&[f64], &mut [f64], &mut [f64]) {
    move |y, f, s| {
        f[0] = y[1];
        f[1] = -w * w * y[0];
        s[0] = y[0] - 0.95 / w;
    }
}

/// At hω = 1000 a step needs 2^12 samples (a quarter radian each), beyond
/// the 2^8 of a sample table, so the piece is scanned along its flow.
#[test]
fn a_fast_piece_finds_every_brief_crest_sampled_every_quarter_radian() {
    let (h, w) = (1.0e-3, 1.0e6);
    let levels = ContactExponential::levels_for(h, 2.5e-7);
    let mut c = ContactExponential::new(2, 1, levels);
    c.set_scale(&[1e-12, 1e-6], &[0, 1, 2]);
    let mut y = [0.0, 1.0];
    let mut spans = ContactSpans::default();
    let r = c.step(h, &mut y, &[], 1e-12, &mut spans, &mut crests(w));
    // Exactly: each crest t_k = (π/2 + 2πk)/ω enters at t_k − δ and leaves
    // at t_k + δ, δ = acos(0.95)/ω.
    let delta = 0.95f64.acos();
    let tau = std::f64::consts::TAU;
    let exact = (0..)
        .map(|k| std::f64::consts::FRAC_PI_2 + tau * k as f64)
        .take_while(|t| t - delta < w * h)
        .map(|t| 1 + usize::from(t + delta < w * h))
        .sum::<usize>();
    let flow = [(w * h).sin() / w, (w * h).cos()];
    let off = ((y[0] - flow[0]) * w).abs().max((y[1] - flow[1]).abs());
    println!("switches {} exact {exact}, flow {off:e}", r.switches);
    assert_eq!(r.switches, exact);
    assert!(r.undersampled_rate == 0.0 && !r.unlocated);
    assert!(off < 1e-9, "{off:e}");
}

/// At hω = 15000 the crests switch 4774 times in a step: past MAX_EVENTS
/// the step is finished span by span without locating and says so. The
/// law is the same on both sides here, so the spans follow the exact flow;
/// they are whole units from the last located switch, which is off the
/// grid, so the step ends within one unit h/2^L of h.
#[test]
fn chatter_beyond_max_events_is_finished_unlocated_and_says_so() {
    let (h, w) = (1.0e-3, 1.5e7);
    let levels = ContactExponential::levels_for(h, 0.25 / w);
    let mut c = ContactExponential::new(2, 1, levels);
    c.set_scale(&[1e-12, 1e-6], &[0, 1, 2]);
    let mut y = [0.0, 1.0];
    let mut spans = ContactSpans::default();
    let r = c.step(h, &mut y, &[], 1e-12, &mut spans, &mut crests(w));
    assert!(r.unlocated && r.undersampled_rate == 0.0);
    assert_eq!(r.switches, MAX_EVENTS);
    let flow = [(w * h).sin() / w, (w * h).cos()];
    let off = ((y[0] - flow[0]) * w).abs().max((y[1] - flow[1]).abs());
    let unit = h / (levels as f64).exp2();
    println!("flow {off:e}, one unit {:e}", w * unit);
    assert!(off <= w * unit, "{off:e}");
}

/// Levels short of a piece's rate are reported, not sampled in silence.
#[test]
fn a_piece_faster_than_the_levels_is_reported() {
    let (h, w) = (1.0e-3, 1.0e6);
    let mut c = ContactExponential::new(2, 1, 8);
    c.set_scale(&[1e-12, 1e-6], &[0, 1, 2]);
    let mut y = [0.0, 1.0];
    let mut spans = ContactSpans::default();
    let r = c.step(h, &mut y, &[], 1e-12, &mut spans, &mut crests(w));
    println!("rate {:e}", r.undersampled_rate);
    assert!((r.undersampled_rate / w - 1.0).abs() < 0.1);
}
