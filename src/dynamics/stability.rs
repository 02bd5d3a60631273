//! Linear stability of a spinning plate with brake pads: the flutter
//! instability of the paper's brake-squeal model (section 5.3, Fig. 17).
//!
//! About the undeformed state at constant joint speed Ω, in ALE coordinates
//! y = (q̄, q̄̇) (docs/dynamics.md), the equations are linear and
//! time-invariant — space-fixed pads are constant in the ALE frame:
//!
//!   q̄̈ = M⁻¹(−K_pad + K_fric) q̄ − M⁻¹C_pad q̄̇
//!        + per pair: 2kΩ J q̄̇ + 2ζωkΩ J q̄ + (k²Ω² − ω_eff²) q̄ − 2ζω q̄̇,
//!
//! with, summed over the contact points c (shape values w_i and surface tilt
//! (θ_x, θ_y)_i of mode i at the node, friction force F = (F_x, F_y) at the
//! preload: F_θ = −μ·2N₀/n · sign Ω along e_θ):
//!
//! - K_pad,im = 2 k_c w_i w_m, C_pad,im = 2 c_c w_i w_m (both faces) for a
//!   fixed caliper; with a floating one the pads follow their mean, so
//!   w − w̄ (w̄ the mean over the pad's contact points) replaces w;
//! - K_fric,im = w_i (F_y θ_x,m − F_x θ_y,m): the follower friction's normal
//!   component, (F_θ/r) ∂w/∂θ — not symmetric, hence flutter.
//!
//! With `pads.contact_surface: faces` (docs/scenes.md, "Friction on the
//! faces") each contact adds, with g = μ tanh(|V|/v_reg), V = Ωr, p the
//! preload per face, δN = k_c (w − w̄) + c_c (ẇ − ẇ̄) and Ẇ = ∂w/∂t + Ω ∂w/∂θ:
//!
//! - the friction couple  f_i += h g sign V (1/r) ∂_θ w_i δN,
//! - the sliding direction f_i −= (h²/2) p (g/|V|) ∂_r w_i (D(∂_r w)/Dt − Ω ∂_θ w / r),
//! - the speed slope      f_i −= (h²/2) p g′ (1/r) ∂_θ w_i (D(∂_θ w / r)/Dt + Ω ∂_r w),
//!   g′ = dg/d|v| (μ(v) = μ + (μ_s − μ) e^(−v/v_S) and the regularisation),
//!
//! the face point's radial and tangential velocity over −z, with the polar
//! basis' rotation (`face_friction.rs`; zero for a tilt held in space);
//!
//! (`add_face_terms`); the follower term above is the normal part of the
//! sliding direction and is the same.
//!
//! With `plate.residual_flexibility` the contacts act in series with the
//! residual compliance G among them (`dynamics::contact_compliance`, the same
//! law the simulation steps): the net axial forces are
//! F = −(I + K G)⁻¹ (K W q̄ + C W q̄̇), K = −∂F/∂w of the closed contacts
//! (2k_c (I − P), P the pad means of a floating caliper) and C = (c_c/k_c) K,
//! W the shapes at the contacts; they replace −K_pad q̄ − C_pad q̄̇ (f_i = w_i F)
//! and, as δN = −F/2, the face terms' δN ([`Pads::linear_series_forces`]).
//!
//! The friction force's magnitude does not change to first order (the two
//! faces' spring forces change by ∓k_c w). Lift-off is inactive about a
//! preloaded state; the tool (a delay) and the held user wrenches are not
//! part of the linearisation, nor is the joint speed (held constant).
//! [`linear_system`] assembles the real 2n×2n matrix from the same node data
//! the simulation uses; faer gives its eigenvalues.

use super::integrators::equations::mode_constants;
use super::load_models::pad::FRICTION_REGULARISATION_SPEED;
use super::load_models::pad::{PadContactPoint, Pads};
use super::load_models::pad_config::{Caliper, ContactSurface, PadsConfig};
use super::scene::Scene;
use super::stability_pads::NetForce;
use faer::Mat;
use nalgebra::Complex;

/// The matrix A of ẏ = A y, y = (q̄, q̄̇), at speed Ω with friction
/// coefficient μ and pad clamp forces `clamp_force` (one per pad). With
/// massive pads (`pads.mass`) y = (q̄, q̄̇, ξ, ξ̇): ξ the pads' compressions
/// from rest, per pad (top, bottom) as in their slot ([`pad_dofs`]). With
/// the lining's patches (`pads.shear_stiffness`) one ζ per contact point
/// follows (`stability_shear.rs`).
pub fn linear_system(
    scene: &Scene,
    speed: f64,
    friction_coefficient: f64,
    clamp_force: &[f64],
) -> Mat<f64> {
    let n = scene.n_modes();
    let extra = pad_dofs(scene);
    let len = 2 * n + 2 * extra + patch_dofs(scene);
    let mut a = Mat::<f64>::zeros(len, len);
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
    if let Some((_, pads)) = scene.load_models.find::<Pads>() {
        let mass = &scene.model.body().modal_mass;
        // Per pad the mean shape over its contacts: a floating caliper's pads
        // follow it, so its springs see w − w̄ (docs/scenes.md).
        let mut mean = vec![vec![0.0; n]; pads.pad_count()];
        if pads.caliper == Caliper::Floating && !pads.is_massive() {
            for c in &pads.contacts {
                let share = 1.0 / pads.contacts_per_pad[c.pad] as f64;
                for (m, s) in mean[c.pad].iter_mut().zip(&scene.ale_nodes[c.node].shapes) {
                    *m += share * s.w;
                }
            }
        }
        // In series with G: the contact forces per unit q̄ and q̄̇ (n_c × n).
        let active: Vec<bool> = pads
            .contacts
            .iter()
            .map(|c| !(pads.lift_off && clamp_force[c.pad] <= 0.0))
            .collect();
        let series = pads
            .series
            .as_ref()
            .map(|g| pads.linear_series_forces(g, &scene.ale_nodes, &active));
        super::stability_shear::add_patch_relaxation(&mut a, n, extra, pads);
        for (ci, contact) in pads.contacts.iter().enumerate() {
            let clamp = clamp_force[contact.pad];
            if pads.lift_off && clamp <= 0.0 {
                continue; // touching without preload: not in contact to first order
            }
            let node = &scene.ale_nodes[contact.node];
            let mean = &mean[contact.pad];
            let preload = clamp / pads.contacts_per_pad[contact.pad] as f64;
            // With face friction μ is μ(V) at the sliding speed V = Ωr (equal to μ without μ_s).
            let mu = match pads.contact_surface {
                ContactSurface::Faces => pads
                    .friction_law(friction_coefficient)
                    .mu((speed * contact.radius).abs()),
                ContactSurface::MidPlane => friction_coefficient,
            };
            let f_theta = -mu * 2.0 * preload * Pads::sliding_sign(speed, contact.radius);
            let (s, co) = contact.angle.sin_cos();
            let (fx, fy) = (-s * f_theta, co * f_theta);
            for i in 0..n {
                let wi = node.shapes[i].w;
                let di = wi - mean[i];
                for m in 0..n {
                    let sm = node.shapes[m];
                    let dm = sm.w - mean[m];
                    let mut k = match &series {
                        None => -2.0 * pads.stiffness * di * dm,
                        Some(l) => wi * l.q[ci * n + m],
                    };
                    if pads.follower_friction {
                        k += wi * (fy * sm.tilt[0] - fx * sm.tilt[1]);
                    }
                    a[(n + i, m)] += k / mass[i];
                    let c = match &series {
                        None => 2.0 * pads.damping * di * dm,
                        Some(l) => -wi * l.q_dot[ci * n + m],
                    };
                    a[(n + i, n + m)] -= c / mass[i];
                }
            }
            if pads.contact_surface == ContactSurface::Faces {
                let rows = series
                    .as_ref()
                    .map(|l| (&l.q[ci * n..(ci + 1) * n], &l.q_dot[ci * n..(ci + 1) * n]));
                add_face_terms(
                    &mut a,
                    scene,
                    pads,
                    contact,
                    mean,
                    preload,
                    speed,
                    friction_coefficient,
                    rows,
                );
                if let Some(law) = &pads.shear {
                    super::stability_shear::add_patch_terms(
                        &mut a, scene, law, contact, ci, extra, preload, speed, mu,
                    );
                }
            }
            if pads.is_massive() {
                let couple = match pads.contact_surface {
                    ContactSurface::Faces => {
                        face_couple(pads, contact, speed, friction_coefficient)
                    }
                    ContactSurface::MidPlane => 0.0,
                };
                let net = match &series {
                    Some(l) => NetForce::in_series(l, ci, n, pads),
                    None => NetForce::direct(pads, contact, node),
                };
                super::stability_pads::add_pad_terms(&mut a, scene, pads, contact, couple, &net);
            }
        }
        if pads.is_massive() {
            super::stability_pads::add_pad_identity(&mut a, n, pads);
        }
    }
    a
}

/// Generalised coordinates the massive pads add (2 per pad: top, bottom); 0 for massless pads.
pub fn pad_dofs(scene: &Scene) -> usize {
    scene
        .load_models
        .find::<Pads>()
        .map_or(0, |(_, p)| p.pad_states() / 2)
}

/// First-order states the lining's patches add (one ζ per contact point; `stability_shear.rs`).
pub fn patch_dofs(scene: &Scene) -> usize {
    scene
        .load_models
        .find::<Pads>()
        .map_or(0, |(_, p)| super::stability_shear::patch_dofs(p))
}

/// h μ(V) tanh(V/v_reg): the faces' couple per unit (δN_t − δN_b)/2 (see [`add_face_terms`]).
fn face_couple(pads: &Pads, contact: &PadContactPoint, speed: f64, mu: f64) -> f64 {
    let v = speed * contact.radius;
    let h = contact.face_z[0] - contact.face_z[1];
    h * pads.friction_law(mu).mu(v.abs()) * (v / FRICTION_REGULARISATION_SPEED).tanh()
}

/// The face friction's first-order terms of one contact (module docs) into
/// the rows of `a` (ALE amplitudes y = (q̄, q̄̇)).
#[allow(clippy::too_many_arguments)]
/// `series`: the contact's net axial force per unit q̄ and q̄̇ in series with
/// the residual compliance (δN = −F/2), or None (δN = k_c dn q̄ + c_c dn q̄̇).
fn add_face_terms(
    a: &mut Mat<f64>,
    scene: &Scene,
    pads: &Pads,
    contact: &PadContactPoint,
    mean: &[f64],
    preload: f64,
    speed: f64,
    mu: f64,
    series: Option<(&[f64], &[f64])>,
) {
    let n = scene.n_modes();
    let mass = &scene.model.body().modal_mass;
    let node = &scene.ale_nodes[contact.node];
    let h = contact.face_z[0] - contact.face_z[1];
    let r = contact.radius;
    let (s, c) = contact.sin_cos;
    let v = speed * r;
    let x = v.abs() / FRICTION_REGULARISATION_SPEED;
    let law = pads.friction_law(mu);
    let mu_v = law.mu(v.abs());
    let g_over_v = Pads::friction_per_speed(mu_v, v.abs());
    let g_slope =
        mu_v / (FRICTION_REGULARISATION_SPEED * x.cosh().powi(2)) + law.slope(v.abs()) * x.tanh();
    let couple = h * mu_v * (v / FRICTION_REGULARISATION_SPEED).tanh();
    let lever = 0.5 * h * h * preload;
    // Per mode: ∂_r w, ∂_θ w and the turn of the gradient ∂(∇w)/∂θ in the same
    // components: ∂_r ∂_θ w − ∂_θ w / r and ∂²_θ w + r ∂_r w.
    let radial = |g: [f64; 2]| c * g[0] + s * g[1];
    let angular = |g: [f64; 2]| r * (-s * g[0] + c * g[1]);
    for i in 0..n {
        let (dr_i, dt_i) = (radial(node.gradient(i)), angular(node.gradient(i)));
        for m in 0..n {
            let (dr_m, dt_m) = (radial(node.gradient(m)), angular(node.gradient(m)));
            let (drt_m, dtt_m) = (radial(node.gradient_phi[m]), angular(node.gradient_phi[m]));
            let dn = node.shapes[m].w - mean[m];
            let dn_times = |coef: f64, stiff: f64, row: Option<&[f64]>| match row {
                None => coef * stiff * dn,
                Some(r) => coef * (-0.5 * r[m]),
            };
            // δN = k_c dn q + c_c dn q̇; v_r / −z = dr q̇ + Ω drt q, r v_θ / −z ∋ dt q̇ + Ω dtt q.
            let on_q = dn_times(couple * dt_i / r, pads.stiffness, series.map(|s| s.0))
                - lever * g_over_v * dr_i * speed * drt_m
                - lever * g_slope / (r * r) * dt_i * speed * dtt_m;
            let on_q_dot = dn_times(couple * dt_i / r, pads.damping, series.map(|s| s.1))
                - lever * g_over_v * dr_i * dr_m
                - lever * g_slope / (r * r) * dt_i * dt_m;
            a[(n + i, m)] += on_q / mass[i];
            a[(n + i, n + m)] += on_q_dot / mass[i];
        }
    }
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
    let len = a.nrows();
    let extra = pad_dofs(scene);
    let position = |r: usize| is_position(r, n, extra);
    for r in 0..len {
        for c in 0..len {
            match (position(r), position(c)) {
                (true, false) => a[(r, c)] *= s,
                (false, true) => a[(r, c)] /= s,
                _ => {}
            }
        }
    }
    (a, s)
}

/// Whether entry `r` of y = (q̄, q̄̇, ξ, ξ̇, ζ) (n modes, `extra` pad dofs)
/// is a position (the patches' ζ are balanced with the rates).
fn is_position(r: usize, n: usize, extra: usize) -> bool {
    r < n || (r >= 2 * n && r < 2 * n + extra)
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

/// The scene's friction coefficient and the clamp forces it starts with.
pub(crate) fn configured(scene: &Scene) -> (f64, Vec<f64>) {
    scene
        .load_models
        .find::<Pads>()
        .map(|(_, p)| p)
        .map_or((0.0, Vec::new()), |p| {
            (p.friction_coefficient, p.initial_clamp_force.clone())
        })
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

/// The least stable eigenvalue of [`linear_system`] and its eigenvector
/// y = (q̄, q̄̇) — with massive pads (q̄, q̄̇, ξ, ξ̇), with patches ζ after
/// them — (complex; a real
/// motion is Re(v e^{λt})).
#[derive(Debug, Clone, PartialEq)]
pub struct CriticalMode {
    /// λ: Re λ the growth rate (1/s), Im λ the circular frequency (rad/s).
    pub eigenvalue: Complex<f64>,
    /// The right eigenvector v over y.
    pub vector: Vec<Complex<f64>>,
}

/// Whether the configuration has pads (`pads.*` or `calipers.*`): something can squeal.
pub fn has_pads(config: &crate::config::Config) -> bool {
    config.section::<PadsConfig>().is_some()
}

/// The squeal frequency of a simulation's scene, Hz: |Im λ|/2π of the least
/// stable mode ([`critical_mode`]) at the configured speed, friction
/// coefficient and clamp forces; `None` without pads.
pub fn squeal_frequency(sim: &super::Simulation) -> Option<f64> {
    let pads = sim.config().section::<PadsConfig>()?;
    let mode = critical_mode(
        sim.scene(),
        sim.config().joint.speed,
        pads.friction_coefficient,
        &pads.clamp_force,
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
                    / if is_position(r, scene.n_modes(), pad_dofs(scene)) {
                        scale
                    } else {
                        1.0
                    }
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
