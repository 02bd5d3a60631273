//! The characteristic quartic of one ALE mode pair under one contact at
//! θ = 0 and its Routh–Hurwitz condition: the closed form of the one-contact
//! squeal thresholds (tests/pad_friction_on_the_faces.rs for Kirchhoff
//! modes, tests/mindlin_pads.rs for Mindlin ones), mass-normalised:
//!
//!   q̈_c + (d₀ + β) q̇_c + G q̇_s + (K₀ + κ) q_c + A q_s = 0
//!   q̈_s + (d₀ + γ) q̇_s − G q̇_c + K₀ q_s − B q_c = 0
#![allow(dead_code)]

/// The pair's terms (each test writes them from its own kinematics).
pub struct PairTerms {
    /// ω² − k²Ω².
    pub k0: f64,
    /// The contact springs on the cos mode.
    pub kappa: f64,
    /// 2ζω.
    pub d0: f64,
    /// The cos mode's added damping (the sliding direction).
    pub beta: f64,
    /// The sin mode's added damping (the friction's speed slope).
    pub gamma: f64,
    /// 2kΩ.
    pub g: f64,
    /// A: q_s on the cos mode.
    pub a: f64,
    /// B: q_c on the sin mode (with the sign above).
    pub b: f64,
}

impl PairTerms {
    /// λ⁴ + a₁λ³ + a₂λ² + a₃λ + a₄: (a₁, a₂, a₃, a₄).
    pub fn quartic(&self) -> [f64; 4] {
        let PairTerms {
            k0,
            kappa,
            d0,
            beta,
            gamma,
            g,
            a,
            b,
        } = *self;
        [
            2.0 * d0 + beta + gamma,
            2.0 * k0 + kappa + (d0 + beta) * (d0 + gamma) + g * g,
            (d0 + beta) * k0 + (d0 + gamma) * (k0 + kappa) + g * (a + b),
            (k0 + kappa) * k0 + a * b,
        ]
    }
}

/// Routh–Hurwitz: a quartic with positive coefficients is stable iff a₁a₂a₃ − a₁²a₄ − a₃² > 0.
pub fn hurwitz(a: [f64; 4]) -> f64 {
    a[0] * a[1] * a[2] - a[0] * a[0] * a[3] - a[2] * a[2]
}

/// The μ in (0, `hi`) where the quartic `at(μ)` turns unstable, by bisection to 1e-12.
pub fn threshold(hi: f64, at: impl Fn(f64) -> [f64; 4]) -> f64 {
    let q = |mu: f64| hurwitz(at(mu));
    let (mut lo, mut hi) = (0.0, hi);
    assert!(
        q(lo) > 0.0 && q(hi) < 0.0,
        "no sign change of the Hurwitz determinant"
    );
    while hi - lo > 1e-12 {
        let mid = 0.5 * (lo + hi);
        if q(mid) > 0.0 {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    0.5 * (lo + hi)
}
