//! The lining's tangential patch at one contact face (`pad_shear.rs` puts
//! one on every face of the pads; docs/scenes.md, "Pad shear"): a massless
//! spring k_t parallel to a damper c_t carrying the face's friction. With
//! x the patch's in-plane deflection, v = (v_∥, v_n) the face point's
//! sliding velocity against the backing plate and U = (v_∥ − ẋ, v_n) its
//! velocity relative to the patch, the friction on the disc is
//! −μN τ(|U|) U/|U| (τ(s) = tanh(s/v_reg)) and
//!
//!   k_t x + c_t ẋ = μN τ(|U|) u/|U|,   u = v_∥ − ẋ.
//!
//! The right side is parallel to u, so u is parallel to p = c_t v_∥ + k_t x
//! and its length s solves the scalar equation
//!
//!   μN τ(R) s/R + c_t s = |p|,   R = √(s² + v_n²),
//!
//! whose left side increases with s (the gradient of a convex potential
//! along a ray, plus c_t s): one root in [max(0, (|p| − μN)/c_t), |p|/c_t],
//! found by Newton's method kept inside the bracket. Then ẋ = v_∥ − u and
//! the disc feels −(k_t x + c_t ẋ) in-plane. A face with N ≤ 0 carries no
//! friction and its patch relaxes at k_t/c_t.

/// k_t, c_t of every contact face's patch, and the joint speed the patches
/// start sliding at.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PatchLaw {
    /// k_t per contact point and face, N/m.
    pub stiffness: f64,
    /// c_t per contact point and face, N·s/m.
    pub damping: f64,
    /// Ω at t = 0 (`joint.speed`), rad/s: the patches start at steady sliding.
    pub initial_speed: f64,
}

/// One face's patch at one instant: its rate and the friction on the disc.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct PatchFace {
    /// ẋ (radial, tangential), m/s.
    pub rate: [f64; 2],
    /// Friction on the disc (radial, tangential, normal), N.
    pub force: [f64; 3],
    /// |U|, the speed of the face relative to the patch, m/s.
    pub slip: f64,
}

/// Newton iterations at most (the bracket halves when a step leaves it).
const MAX_ITERATIONS: usize = 200;

/// τ(R)/R, the share s²/R² and R/v_reg at R = √(s² + v_n²) (R → 0: 1/v_reg, 1).
fn tau_over_r(s: f64, normal_speed: f64, v_reg: f64) -> (f64, f64, f64) {
    let r = (s * s + normal_speed * normal_speed).sqrt();
    let x = r / v_reg;
    if x < 1e-8 {
        return (1.0 / v_reg, 1.0, x);
    }
    (x.tanh() / r, s * s / (r * r), x)
}

impl PatchLaw {
    /// The patch of one face: deflection `x` (radial, tangential), normal
    /// force `normal`, friction coefficient `mu` and the face point's sliding
    /// velocity `v` (radial, tangential, normal) against the backing plate,
    /// regularised below `v_reg` (module docs).
    pub fn face(&self, x: [f64; 2], normal: f64, mu: f64, v: [f64; 3], v_reg: f64) -> PatchFace {
        let (k, c) = (self.stiffness, self.damping);
        let capacity = mu * normal.max(0.0);
        let p = [c * v[0] + k * x[0], c * v[1] + k * x[1]];
        let p_len = p[0].hypot(p[1]);
        let s = self.relative_speed(p_len, capacity, v[2], v_reg);
        let (t_over_r, _, _) = tau_over_r(s, v[2], v_reg);
        let u = if p_len > 0.0 {
            [s * p[0] / p_len, s * p[1] / p_len]
        } else {
            [0.0; 2]
        };
        let scale = -capacity * t_over_r;
        PatchFace {
            rate: [v[0] - u[0], v[1] - u[1]],
            force: [scale * u[0], scale * u[1], scale * v[2]],
            slip: (s * s + v[2] * v[2]).sqrt(),
        }
    }

    /// s ≥ 0 with μN τ(R) s/R + c_t s = |p| (module docs).
    fn relative_speed(&self, p_len: f64, capacity: f64, normal_speed: f64, v_reg: f64) -> f64 {
        let c = self.damping;
        let (mut lo, mut hi) = (((p_len - capacity) / c).max(0.0), p_len / c);
        let residual = |s: f64| {
            let (t_over_r, share, x) = tau_over_r(s, normal_speed, v_reg);
            let sech2 = 1.0 / x.cosh().powi(2);
            let slope = t_over_r * (1.0 - share) + sech2 / v_reg * share;
            (
                capacity * t_over_r * s + c * s - p_len,
                capacity * slope + c,
            )
        };
        let mut s = lo;
        for _ in 0..MAX_ITERATIONS {
            let (f, df) = residual(s);
            if f == 0.0 {
                return s;
            }
            if f < 0.0 {
                lo = s;
            } else {
                hi = s;
            }
            let mut next = s - f / df;
            if !(next > lo && next < hi) {
                next = 0.5 * (lo + hi);
            }
            if (next - s).abs() <= 1e-15 * next.abs().max(v_reg) {
                return next;
            }
            s = next;
        }
        s
    }
}

/// One contact's patches in the step: their deflections (4 entries: radial
/// and tangential, top then bottom face, from the slot's origin), where
/// their rates go, and where the faces' slip speeds go.
pub(super) struct PatchSlot<'a> {
    pub(super) x: &'a [f64],
    pub(super) rates: &'a mut [f64],
    pub(super) slip: &'a mut [f64; 2],
}

#[cfg(test)]
mod tests {
    use super::*;

    const V_REG: f64 = 1.0e-3;

    const LAW: PatchLaw = PatchLaw {
        stiffness: 1.0e6,
        damping: 20.0,
        initial_speed: 3.0,
    };

    #[test]
    fn a_patch_in_steady_sliding_holds_mu_n_and_does_not_move() {
        let (n, mu, v) = (300.0, 0.5, 0.36);
        let x = [0.0, mu * n * (v / V_REG).tanh() / LAW.stiffness];
        let p = LAW.face(x, n, mu, [0.0, v, 0.0], V_REG);
        assert!(p.rate[0].abs() < 1e-15 && p.rate[1].abs() < 1e-12, "{p:?}");
        assert!((p.force[1] + mu * n).abs() < 1e-9, "{p:?}");
        assert!((p.slip - v).abs() < 1e-12);
    }

    #[test]
    fn the_patch_balances_its_spring_and_damper_against_the_friction() {
        let (n, mu) = (300.0, 0.5);
        for (x, v) in [
            ([1e-5, 2e-5], [0.01, 0.3, 0.002]),
            ([-4e-5, 1e-4], [-0.2, 0.05, 0.0]),
            ([1e-7, 0.0], [0.0, 1e-6, 0.0]),
            ([0.0, 0.0], [0.0, 0.0, 0.0]),
        ] {
            let p = LAW.face(x, n, mu, v, V_REG);
            // k_t x + c_t ẋ = −(in-plane friction on the disc).
            for a in 0..2 {
                let spring = LAW.stiffness * x[a] + LAW.damping * p.rate[a];
                assert!(
                    (spring + p.force[a]).abs() < 1e-9 * (1.0 + mu * n),
                    "{x:?} {v:?}: {spring} vs {}",
                    p.force[a]
                );
            }
            // |F| = μN τ(|U|) along U.
            let f = (p.force[0].powi(2) + p.force[1].powi(2) + p.force[2].powi(2)).sqrt();
            let expected = mu * n * (p.slip / V_REG).tanh();
            assert!(
                (f - expected).abs() < 1e-9 * (1.0 + expected),
                "{f} vs {expected}"
            );
        }
    }

    #[test]
    fn a_face_without_normal_force_lets_its_patch_relax() {
        let p = LAW.face([1e-5, -2e-5], 0.0, 0.5, [0.1, 0.3, 0.0], V_REG);
        assert_eq!(p.force, [0.0; 3]);
        let tau = LAW.stiffness / LAW.damping;
        assert!((p.rate[0] + tau * 1e-5).abs() < 1e-9 && (p.rate[1] - tau * 2e-5).abs() < 1e-9);
    }
}
