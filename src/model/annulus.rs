//! The numbers every annulus model checks before it builds: the material
//! and the radii, finite and in range.

/// The first number out of range, as (name, value, rule).
pub(crate) type OutOfRange = (&'static str, f64, &'static str);

/// Each of `positive` finite and > 0, −1 < ν < 0.5, r_a finite and > r_i.
pub(crate) fn check_annulus(
    positive: &[(&'static str, f64)],
    poisson_ratio: f64,
    inner_radius: f64,
    outer_radius: f64,
) -> Result<(), OutOfRange> {
    for &(name, value) in positive {
        if !(value.is_finite() && value > 0.0) {
            return Err((name, value, "finite and > 0"));
        }
    }
    let nu = poisson_ratio;
    if !(nu.is_finite() && nu > -1.0 && nu < 0.5) {
        return Err(("poisson_ratio", nu, "in (-1, 0.5)"));
    }
    if !(outer_radius.is_finite() && outer_radius > inner_radius) {
        return Err(("outer_radius", outer_radius, "finite and > inner_radius"));
    }
    Ok(())
}
