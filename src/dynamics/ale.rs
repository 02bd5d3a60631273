//! The ALE transformation, eq. (20), and its time derivative.
//!
//! For a mode pair with Lagrangian amplitudes (q_c, q_s) of cos(kφ), sin(kφ)
//! and φ = θ − χ (eq. 15), eq. (17) gives the ALE amplitudes of cos(kθ), sin(kθ):
//!
//! q̄ = R(kχ) q,  R(α) = [[cos α, −sin α], [sin α, cos α]]
//!
//! (eq. 20 with index 1 = sin, 2 = cos). With J = [[0, −1], [1, 0]] and dR/dα = J R:
//! q̄̇ = R q̇ + kΩ J q̄. k = 0 modes are invariant. Generalized forces
//! transform like amplitudes (f̄ = R f), by virtual work.

use super::angle::JointAngle;
use super::layout::ModeLayout;

/// (cos kχ, sin kχ) for k = 0..=k_max from the wrapped angle (Chebyshev recurrence
/// re-anchored every 16 steps to keep round-off at the 1e-15 level).
pub fn harmonics(chi: &JointAngle, k_max: u32, out: &mut Vec<(f64, f64)>) {
    out.clear();
    let (s1, c1) = chi.angle.sin_cos();
    let (mut c, mut s) = (1.0, 0.0);
    for k in 0..=k_max {
        if k % 16 == 0 && k > 0 {
            let (sk, ck) = (k as f64 * chi.angle).sin_cos();
            c = ck;
            s = sk;
        }
        out.push((c, s));
        let (cn, sn) = (c * c1 - s * s1, s * c1 + c * s1);
        c = cn;
        s = sn;
    }
}

/// Rotate each pair (x_c, x_s) by +kχ (Lagrangian → ALE) or −kχ (ALE → Lagrangian).
pub fn rotate_pairs(layout: &ModeLayout, harm: &[(f64, f64)], x: &mut [f64], to_ale: bool) {
    for p in &layout.pairs {
        let (c, s) = harm[p.k as usize];
        let s = if to_ale { s } else { -s };
        let (a, b) = (x[p.cos], x[p.sin]);
        x[p.cos] = c * a - s * b;
        x[p.sin] = s * a + c * b;
    }
}

/// Lagrangian (q, q̇) → ALE (q̄, q̄̇) at angle χ and speed Ω, in place.
/// One pass over the pairs (the same operations, in the same order, as
/// rotating q, then q̇, then adding kΩ J q̄).
pub fn lagrange_to_ale(
    layout: &ModeLayout,
    harm: &[(f64, f64)],
    speed: f64,
    q: &mut [f64],
    q_dot: &mut [f64],
) {
    // Both of length n: one index check serves both.
    let q_dot = &mut q_dot[..q.len()];
    for p in &layout.pairs {
        let (c, s) = harm[p.k as usize];
        let [bar_c, bar_s, dot_c, dot_s] = pair_to_ale(
            (c, s),
            p.k as f64 * speed,
            [q[p.cos], q[p.sin]],
            [q_dot[p.cos], q_dot[p.sin]],
        );
        q_dot[p.cos] = dot_c;
        q_dot[p.sin] = dot_s;
        q[p.cos] = bar_c;
        q[p.sin] = bar_s;
    }
}

/// One pair's Lagrangian (q_c, q_s), (q̇_c, q̇_s) → ALE [q̄_c, q̄_s, q̄̇_c, q̄̇_s]
/// at (cos kχ, sin kχ) and w = kΩ: q̄ = R q, q̄̇ = R q̇ + kΩ J q̄ (eq. 20).
#[inline(always)]
pub fn pair_to_ale((c, s): (f64, f64), w: f64, [qc, qs]: [f64; 2], [vc, vs]: [f64; 2]) -> [f64; 4] {
    let (bar_c, bar_s) = (c * qc - s * qs, s * qc + c * qs);
    [
        bar_c,
        bar_s,
        (c * vc - s * vs) - w * bar_s,
        (s * vc + c * vs) + w * bar_c,
    ]
}

/// ALE (q̄, q̄̇) → Lagrangian (q, q̇): q̇ = Rᵀ (q̄̇ − kΩ J q̄).
pub fn ale_to_lagrange(
    layout: &ModeLayout,
    harm: &[(f64, f64)],
    speed: f64,
    q: &mut [f64],
    q_dot: &mut [f64],
) {
    for p in &layout.pairs {
        let w = p.k as f64 * speed;
        q_dot[p.cos] += w * q[p.sin];
        q_dot[p.sin] -= w * q[p.cos];
    }
    rotate_pairs(layout, harm, q, false);
    rotate_pairs(layout, harm, q_dot, false);
}
