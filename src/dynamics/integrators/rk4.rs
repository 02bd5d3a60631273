//! Classical Runge–Kutta 4 on the modal ODE — the explicit reference method.
//! Its stability interval on the imaginary axis ends at 2√2; as a reference
//! it must also be accurate, so the stepper sub-steps until
//! h·λ_max ≤ `simulation.rk4_step_limit`
//! ([`DEFAULT_RK4_STEP_LIMIT`](crate::config::DEFAULT_RK4_STEP_LIMIT) by
//! default), λ_max bounding |ω_eff| + 2ζω + kΩ (per substep the fastest mode
//! then loses ≤ 9e-7 of its energy and ≤ 3e-6 rad of phase). RK4 damps an oscillation at ω
//! by (hω)⁶/144 per step in amplitude: at 0.2 that is 4.4e-7, which matters
//! only for weakly damped instabilities (the brake-squeal scene uses 0.1).

/// y ← y + h/6 (k1 + 2k2 + 2k3 + k4) with `f(t, y, dy)` the right-hand side.
/// Scratch vectors have y's length; no allocation.
pub fn step(
    t: f64,
    h: f64,
    y: &mut [f64],
    scratch: &mut [Vec<f64>; 5],
    mut f: impl FnMut(f64, &[f64], &mut [f64]),
) {
    let [k1, k2, k3, k4, tmp] = scratch;
    f(t, y, k1);
    for ((t, y), k) in tmp.iter_mut().zip(y.iter()).zip(k1.iter()) {
        *t = y + 0.5 * h * k;
    }
    f(t + 0.5 * h, tmp, k2);
    for ((t, y), k) in tmp.iter_mut().zip(y.iter()).zip(k2.iter()) {
        *t = y + 0.5 * h * k;
    }
    f(t + 0.5 * h, tmp, k3);
    for ((t, y), k) in tmp.iter_mut().zip(y.iter()).zip(k3.iter()) {
        *t = y + h * k;
    }
    f(t + h, tmp, k4);
    for (i, yi) in y.iter_mut().enumerate() {
        *yi += h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]);
    }
}
