//! Fits the tests share.
#![allow(dead_code)]

use annular_plate::dynamics::Simulation;
use nalgebra::Complex;
use std::f64::consts::PI;

/// The least-squares slope of y against x: Σ(x − x̄)(y − ȳ) / Σ(x − x̄)².
/// With x the times and y = ln|amplitude| of a run, its growth rate (1/s).
pub fn least_squares_slope(x: &[f64], y: &[f64]) -> f64 {
    let n = x.len() as f64;
    let (mx, my) = (x.iter().sum::<f64>() / n, y.iter().sum::<f64>() / n);
    x.iter()
        .zip(y)
        .map(|(x, y)| (x - mx) * (y - my))
        .sum::<f64>()
        / x.iter().map(|x| (x - mx).powi(2)).sum::<f64>()
}

/// The decay of mode 0 of a damped one-mode run over `steps` steps: the
/// fitted rate of ½ ln(q² + ((q̇ − σq)/ω_d)²) (1/s; the envelope of
/// q = Q e^{σt} cos(ω_d t + φ)) and how much that log fell over the run.
pub fn modal_decay(sim: &mut Simulation, sigma: f64, omega_d: f64, steps: usize) -> (f64, f64) {
    let (mut t, mut ln_q) = (Vec::new(), Vec::new());
    for _ in 0..steps {
        sim.step().unwrap();
        let (q, v) = (sim.q_lagrange()[0], sim.q_dot_lagrange()[0]);
        let rotated = (v - sigma * q) / omega_d;
        t.push(sim.time());
        ln_q.push((q * q + rotated * rotated).ln());
    }
    let fitted = 0.5 * least_squares_slope(&t, &ln_q);
    (fitted, ln_q[0] - ln_q[ln_q.len() - 1])
}

/// |Σ z(t) e^{−iνt} w(t)| with a Hann window.
pub fn spectrum(z: &[Complex<f64>], dt: f64, nu: f64) -> f64 {
    let n = z.len() as f64;
    z.iter()
        .enumerate()
        .map(|(j, zj)| {
            let w = 0.5 - 0.5 * (2.0 * PI * j as f64 / n).cos();
            zj * Complex::new(0.0, -nu * j as f64 * dt).exp() * w
        })
        .sum::<Complex<f64>>()
        .norm()
}

/// The spectral peak of z near `guess` (rad/s): grid scan then golden-section refinement.
pub fn peak_near(z: &[Complex<f64>], dt: f64, guess: f64, half_width: f64) -> f64 {
    let (mut best, mut best_v) = (guess, 0.0);
    for j in 0..=400 {
        let nu = guess - half_width + 2.0 * half_width * j as f64 / 400.0;
        let v = spectrum(z, dt, nu);
        if v > best_v {
            best = nu;
            best_v = v;
        }
    }
    let step = 2.0 * half_width / 400.0;
    let (mut a, mut b) = (best - step, best + step);
    let g = (5f64.sqrt() - 1.0) / 2.0;
    for _ in 0..60 {
        let (c, d) = (b - g * (b - a), a + g * (b - a));
        if spectrum(z, dt, c) > spectrum(z, dt, d) {
            b = d;
        } else {
            a = c;
        }
    }
    0.5 * (a + b)
}
