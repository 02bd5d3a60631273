//! The fixed colour map of transverse deflection, shared by `~/plate_marker`
//! (RViz, Foxglove) and `plot animate`: blue at w = −w_ref through light grey
//! at 0 to red at +w_ref, linear in each half (the end and middle colours of
//! Moreland's "cool to warm" map). Documented in docs/ros.md.

/// RGB at w = −w_ref.
pub const NEGATIVE: [f32; 3] = [0.230, 0.299, 0.754];
/// RGB at w = 0.
pub const ZERO: [f32; 3] = [0.865, 0.865, 0.865];
/// RGB at w = +w_ref.
pub const POSITIVE: [f32; 3] = [0.706, 0.016, 0.150];

/// The colour of `t = w / w_ref`, clamped to [−1, 1] (non-finite: grey).
pub fn rgb(t: f64) -> [f32; 3] {
    let t = if t.is_finite() {
        t.clamp(-1.0, 1.0)
    } else {
        0.0
    };
    let (end, u) = if t < 0.0 {
        (NEGATIVE, -t as f32)
    } else {
        (POSITIVE, t as f32)
    };
    std::array::from_fn(|i| ZERO[i] * (1.0 - u) + end[i] * u)
}

/// As 8-bit RGB.
pub fn rgb8(t: f64) -> [u8; 3] {
    rgb(t).map(|c| (c * 255.0).round() as u8)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ends_and_middle() {
        assert_eq!(rgb(-1.0), NEGATIVE);
        assert_eq!(rgb(0.0), ZERO);
        assert_eq!(rgb(7.0), POSITIVE);
        assert_eq!(rgb(f64::NAN), ZERO);
    }
}
