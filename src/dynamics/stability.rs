//! Linear stability of a spinning plate with its load models: the flutter
//! instability of the paper's brake-squeal model (section 5.3, Fig. 17).
//!
//! About the undeformed state at constant joint speed Ω, in ALE coordinates
//! y = (q̄, q̄̇) (docs/dynamics.md), the equations are linear and
//! time-invariant — space-fixed loads are constant in the ALE frame:
//!
//!   q̄̈ = per pair: 2kΩ J q̄̇ + 2ζωkΩ J q̄ + (k²Ω² − ω_eff²) q̄ − 2ζω q̄̇
//!        + the centrifugal stiffening + the load models' terms,
//!
//! each load model adding its first-order terms and its own states to y.
//!
//! The in-plane modes (`plate.in_plane_nodal_diameters`; docs/in_plane.md,
//! "Stability") follow the same way from their turning-frame equations per k
//! (`in_plane_spin.rs`, (S1)): M q̈ + (D + ΩG) q̇ + K̃ q = f, K̃ = K + Ω²K_Ω,
//! M, D = 2ζωM, K = ω²M diagonal, G skew. A k ≥ 1 pair's ALE amplitudes are
//! x̄ = R(kΩt) x of the body ones, R(φ) = cos φ I + sin φ 𝒥, 𝒥 x = (−x_s,
//! x_c) the pair's quarter turn (𝒥² = −I; M, D, K and K_Ω act alike on
//! both partners and G = [[0, 2B], [−2B, 0]] over [cos; sin], so all commute
//! with 𝒥). With x = R(−kΩt) x̄:
//! ẋ = R(−kΩt)(x̄̇ − kΩ𝒥 x̄), ẍ = R(−kΩt)(x̄̈ − 2kΩ𝒥 x̄̇ − k²Ω² x̄), so
//!
//!   M x̄̈ = (2kΩM𝒥 − ΩG − D) x̄̇ + (k²Ω²M + kΩ²G𝒥 + kΩD𝒥 − K̃) x̄ + f̄,
//!
//! the terms the step uses in ALE (`InPlaneSpinBlock::row_acceleration`
//! with Coordinates::Ale: Ω G and D act on the Lagrangian rate in ALE axes,
//! x̄̇ − kΩ𝒥 x̄). k = 0 (G couples the radial and torsional families) has
//! no turn: M x̄̈ = −(D + ΩG) x̄̇ − K̃ x̄. The bending pairs' terms are those
//! of the first equation with G = K_Ω = 0; the torsional modes' coupling
//! with the joint drops out with the speed held. Every load model adds its
//! first-order terms and its own states to y
//! (`LoadModel::add_linear_terms`, `load_models::linear`): the brake pads
//! their contact springs, dampers and friction (`load_models/pad_linear.rs`),
//! massive pads their compressions, the lining's patches one first-order
//! state per contact. A model that adds nothing (the tool, a delay; the held
//! user wrenches) is not part of the linearisation, nor is the joint speed
//! (held constant). [`linear_system`] assembles the real matrix from the same
//! node data the simulation uses; faer gives its eigenvalues. The analysis
//! maps over the friction coefficient μ and the clamp forces; a model whose
//! friction can make the plate squeal gives the ones it starts with
//! (`LoadModel::operating_point`).

use super::integrators::equations::mode_constants;
use super::load_models::{LinearContext, LinearOut, OperatingPoint, StateLayout};
use super::scene::Scene;
use faer::Mat;
use nalgebra::Complex;

/// The matrix A of ẏ = A y, y = (q̄, q̄̇) and the load models' states
/// (`load_models::linear`: with massive pads their compressions ξ and rates
/// ξ̇, with the lining's patches one ζ per contact), at speed Ω with friction
/// coefficient μ and clamp forces `clamp_force` (one per pad).
pub fn linear_system(
    scene: &Scene,
    speed: f64,
    friction_coefficient: f64,
    clamp_force: &[f64],
) -> Mat<f64> {
    let n = scene.n_modes();
    let layout = state_layout(scene);
    let mut a = Mat::<f64>::zeros(layout.len, layout.len);
    for i in 0..n {
        a[(i, n + i)] = 1.0;
    }
    let consts = mode_constants(scene);
    for &i in &scene.layout.axisymmetric {
        a[(n + i, i)] = -consts[i].omega_eff_sq;
        a[(n + i, n + i)] = -consts[i].damping_rate;
    }
    for p in &scene.layout.pairs {
        let c = consts[p.cos];
        let (ic, is) = (n + p.cos, n + p.sin);
        let kw = p.k as f64 * speed;
        let stiff = kw * kw - c.omega_eff_sq;
        let skew = c.damping_rate * kw;
        a[(ic, p.cos)] = stiff;
        a[(ic, p.sin)] = -skew;
        a[(is, p.cos)] = skew;
        a[(is, p.sin)] = stiff;
        a[(ic, ic)] = -c.damping_rate;
        a[(ic, is)] = -2.0 * kw;
        a[(is, ic)] = 2.0 * kw;
        a[(is, is)] = -c.damping_rate;
    }
    if let Some(s) = &scene.stiffening {
        s.add_to_system(speed * speed, n, |r, c, v| a[(r, c)] += v);
    }
    if let Some(ip) = &scene.in_plane {
        for block in &ip.spin.blocks {
            block.add_ale_system(speed, n, |r, c, v| a[(r, c)] += v);
        }
    }
    let modal_mass: Vec<f64> = consts.iter().map(|c| c.mass).collect();
    let ctx = LinearContext {
        ale_nodes: &scene.ale_nodes,
        in_plane: scene.in_plane.as_ref(),
        modal_mass: &modal_mass,
        speed,
        friction_coefficient,
        clamp_force,
    };
    for (model, &at) in scene.load_models.models().iter().zip(&layout.models) {
        model.add_linear_terms(&ctx, LinearOut { a: &mut a, at });
    }
    a
}

/// Where the load models' states lie in y.
fn state_layout(scene: &Scene) -> StateLayout {
    let models = scene.load_models.models();
    StateLayout::new(models.iter().map(|m| m.linear_states()), scene.n_modes())
}

/// [`linear_system`] for the balanced state (s q̄, q̄̇), s ≈ the highest
/// frequency: the same eigenvalues, but the blocks are of one magnitude
/// (ω instead of ω² and 1), so the growth rates — some 1e-5 of ω near a
/// threshold — keep their accuracy. Returns the matrix and s.
fn balanced_system(
    scene: &Scene,
    speed: f64,
    friction_coefficient: f64,
    clamp_force: &[f64],
) -> (Mat<f64>, f64) {
    let mut a = linear_system(scene, speed, friction_coefficient, clamp_force);
    let n = scene.n_modes();
    let s = (0..n)
        .map(|i| a[(n + i, i)].abs())
        .fold(1.0, f64::max)
        .sqrt();
    let layout = state_layout(scene);
    let len = a.nrows();
    for r in 0..len {
        for c in 0..len {
            match (layout.is_position(r), layout.is_position(c)) {
                (true, false) => a[(r, c)] *= s,
                (false, true) => a[(r, c)] /= s,
                _ => {}
            }
        }
    }
    (a, s)
}

/// Eigenvalues of [`linear_system`], largest real part first.
pub fn eigenvalues(
    scene: &Scene,
    speed: f64,
    friction_coefficient: f64,
    clamp_force: &[f64],
) -> Vec<Complex<f64>> {
    let (a, _) = balanced_system(scene, speed, friction_coefficient, clamp_force);
    let mut ev: Vec<Complex<f64>> = a
        .eigenvalues()
        .expect("the eigenvalues of a finite real matrix")
        .into_iter()
        .map(|z| Complex::new(z.re, z.im))
        .collect();
    ev.sort_by(|x, y| y.re.total_cmp(&x.re));
    ev
}

/// max Re λ, 1/s: positive means a growing vibration (flutter).
pub fn growth_rate(
    scene: &Scene,
    speed: f64,
    friction_coefficient: f64,
    clamp_force: &[f64],
) -> f64 {
    eigenvalues(scene, speed, friction_coefficient, clamp_force)[0].re
}

/// max Re λ for the scene's own friction coefficient and initial clamp forces.
pub fn max_growth_rate(scene: &Scene, speed: f64) -> f64 {
    let (mu, clamp) = configured(scene);
    growth_rate(scene, speed, mu, &clamp)
}

/// The scene's friction coefficient and the clamp forces it starts with
/// (0 and none without a model whose friction can make the plate squeal).
pub(crate) fn configured(scene: &Scene) -> (f64, Vec<f64>) {
    operating_point(scene).map_or((0.0, Vec::new()), |p| {
        (p.friction_coefficient, p.clamp_force)
    })
}

/// The operating point the scene starts with: the first load model's whose
/// friction can make the plate squeal (`LoadModel::operating_point`).
pub fn operating_point(scene: &Scene) -> Option<OperatingPoint> {
    scene
        .load_models
        .models()
        .iter()
        .find_map(|m| m.operating_point())
}

/// The smallest friction coefficient in [0, mu_max] at which the linearised
/// system becomes unstable (max Re λ crosses zero), for the scene's clamp
/// forces at speed Ω: a scan in 200 steps, then bisection to 1e-9 relative.
/// `None` if stable up to `mu_max`; `Some(0.0)` if unstable without friction.
pub fn friction_threshold(scene: &Scene, speed: f64, mu_max: f64) -> Option<f64> {
    let (_, clamp) = configured(scene);
    let rate = |mu: f64| growth_rate(scene, speed, mu, &clamp);
    if rate(0.0) > 0.0 {
        return Some(0.0);
    }
    const SCAN: usize = 200;
    let mut lo = 0.0;
    for j in 1..=SCAN {
        let mu = mu_max * j as f64 / SCAN as f64;
        if rate(mu) > 0.0 {
            let mut hi = mu;
            while hi - lo > 1e-9 * hi {
                let mid = 0.5 * (lo + hi);
                if rate(mid) > 0.0 {
                    hi = mid;
                } else {
                    lo = mid;
                }
            }
            return Some(0.5 * (lo + hi));
        }
        lo = mu;
    }
    None
}

/// The least stable eigenvalue of [`linear_system`] and its eigenvector over
/// y = (q̄, q̄̇, ξ, ξ̇, ζ) (the load models' states after the modes'; complex:
/// a real motion is Re(v e^{λt})).
#[derive(Debug, Clone, PartialEq)]
pub struct CriticalMode {
    /// λ: Re λ the growth rate (1/s), Im λ the circular frequency (rad/s).
    pub eigenvalue: Complex<f64>,
    /// The right eigenvector v over y.
    pub vector: Vec<Complex<f64>>,
}

/// Whether the configuration has a load model whose friction can make the
/// plate squeal (pads: `pads.*` or `calipers.*`).
pub fn can_squeal(config: &crate::config::Config) -> bool {
    config.load_models.can_squeal()
}

/// The squeal frequency of a simulation's scene, Hz: |Im λ|/2π of the least
/// stable mode ([`critical_mode`]) at the configured speed, friction
/// coefficient and clamp forces ([`operating_point`]); `None` without a
/// model whose friction can make the plate squeal.
pub fn squeal_frequency(sim: &super::Simulation) -> Option<f64> {
    let point = operating_point(sim.scene())?;
    let mode = critical_mode(
        sim.scene(),
        sim.config().joint.speed,
        point.friction_coefficient,
        &point.clamp_force,
    );
    Some(mode.eigenvalue.im.abs() / std::f64::consts::TAU)
}

/// The eigenvalue with the largest real part (positive imaginary part among a
/// conjugate pair) and its eigenvector.
pub fn critical_mode(
    scene: &Scene,
    speed: f64,
    friction_coefficient: f64,
    clamp_force: &[f64],
) -> CriticalMode {
    let (a, scale) = balanced_system(scene, speed, friction_coefficient, clamp_force);
    let eig = a
        .eigen()
        .expect("the eigendecomposition of a finite real matrix");
    let s = eig.S();
    let u = eig.U();
    let layout = state_layout(scene);
    let n = a.nrows();
    let best = (0..n)
        .max_by(|&i, &j| {
            let (x, y) = (s[i], s[j]);
            x.re.total_cmp(&y.re).then(x.im.total_cmp(&y.im))
        })
        .expect("a non-empty system");
    CriticalMode {
        eigenvalue: Complex::new(s[best].re, s[best].im),
        vector: (0..n)
            .map(|r| {
                Complex::new(u[(r, best)].re, u[(r, best)].im)
                    / if layout.is_position(r) { scale } else { 1.0 }
            })
            .collect(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::config::{Boundary, Config};
    use crate::model::PlateModel;

    fn disc(damping: f64) -> Scene {
        let mut c = Config::default();
        c.plate.inner_radius = 0.07;
        c.plate.outer_radius = 0.153;
        c.plate.thickness = 0.0181;
        c.plate.inner_boundary = Boundary::Supported;
        c.plate.nodal_diameters = vec![0, 1, 2];
        c.plate.nodal_circles = vec![0];
        c.plate.damping = vec![damping];
        let model = PlateModel::new(&c.plate).unwrap();
        Scene::new(&c, model)
    }

    #[test]
    fn without_pads_the_eigenvalues_are_the_ale_frequencies_omega_plus_minus_k_omega() {
        let (zeta, speed) = (0.01, 300.0);
        let scene = disc(zeta);
        let mut expected: Vec<Complex<f64>> = Vec::new();
        for m in scene.model.modes() {
            let (re, wd) = (-zeta * m.omega, m.omega * (1.0 - zeta * zeta).sqrt());
            if m.k == 0 {
                expected.extend([Complex::new(re, wd), Complex::new(re, -wd)]);
            } else if m.shape == crate::model::AngularShape::Cos {
                // ν = λ − ikΩ solves ν² + 2ζων + ω² = 0 (docs/dynamics.md); the conjugates too.
                let kw = m.k as f64 * speed;
                for im in [kw + wd, kw - wd] {
                    expected.extend([Complex::new(re, im), Complex::new(re, -im)]);
                }
            }
        }
        let got = eigenvalues(&scene, speed, 0.0, &[]);
        assert_eq!(got.len(), expected.len());
        for e in &expected {
            let nearest = got
                .iter()
                .map(|g| (g - e).norm())
                .fold(f64::INFINITY, f64::min);
            assert!(nearest < 1e-9 * e.norm(), "{e} not among {got:?}");
        }
    }
}
