//! Two independent fourth-order discretisations (RK4 on the ALE equations and
//! on the Lagrangian ones) converging to one motion: their difference falls
//! by 2⁴ = 16 per halving of the step.
#![allow(dead_code)]

/// `difference(rate)` at each of `rates` (each twice the one before) must
/// fall at fourth order, a ratio of 12 to 20 per doubling; returns the last.
pub fn assert_fourth_order(
    label: &str,
    rates: &[f64],
    mut difference: impl FnMut(f64) -> f64,
) -> f64 {
    let mut previous: Option<f64> = None;
    for &rate in rates {
        let d = difference(rate);
        println!("{label} at {rate} Hz: {d:e}");
        if let Some(p) = previous {
            assert!(
                p / d > 12.0 && p / d < 20.0,
                "{label}: not converging at fourth order: {p:e} → {d:e}"
            );
        }
        previous = Some(d);
    }
    previous.expect("at least one rate")
}
