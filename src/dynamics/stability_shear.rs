//! The lining's patches in the linear stability analysis (`stability.rs`;
//! `load_models/pad_shear.rs`, docs/scenes.md "Pad shear").
//!
//! About steady sliding at V = Ωr with constant μ the tangential force stays
//! μN whatever the patch does, so a patch enters only through the sliding
//! direction. Per contact, with a = N₀ g/|V| (g = μ τ(|V|), N₀ the preload
//! per face) and the face point's radial velocity v_r = −z R,
//! R = D(∂_r w)/Dt − Ω ∂_θ w / r, each face's radial patch deflection is
//! −z ζ with one ζ per contact (both faces see the same a):
//!
//!   (c_t + a) ζ̇ = a R − k_t ζ,
//!
//! and the radial friction acts on R − ζ̇ in place of R: the rigid term
//! f_i −= (h²/2) a ∂_r w_i R gains + (h²/2) a ∂_r w_i ζ̇. Eliminating ζ
//! gives the filter a → a H(λ), H = (k_t + c_t λ)/(k_t + (c_t + a) λ); as
//! state the eigenproblem stays linear. The tangential deflections follow
//! μ δN through k_t + c_t λ and act on nothing (their eigenvalue −k_t/c_t):
//! they are left out.

use super::load_models::pad::{PadContactPoint, Pads};
use super::load_models::pad_patch::PatchLaw;
use super::scene::Scene;
use faer::Mat;

/// ζ's index in y = (q̄, q̄̇, ξ, ξ̇, ζ) for contact `ci` (`extra` pad dofs).
pub(super) fn patch_index(n: usize, extra: usize, ci: usize) -> usize {
    2 * n + 2 * extra + ci
}

/// Patches in the linear system: one ζ per contact with `pads.shear_stiffness`.
pub fn patch_dofs(pads: &Pads) -> usize {
    pads.shear.map_or(0, |_| pads.contacts.len())
}

/// ζ̇ = −k_t/c_t ζ for every contact (the open ones keep it).
pub(super) fn add_patch_relaxation(a: &mut Mat<f64>, n: usize, extra: usize, pads: &Pads) {
    if let Some(law) = pads.shear {
        for ci in 0..pads.contacts.len() {
            let z = patch_index(n, extra, ci);
            a[(z, z)] = -law.stiffness / law.damping;
        }
    }
}

/// Contact `ci`'s patch (module docs) at preload `preload` per face, speed Ω
/// and friction coefficient μ into `a` (`extra` pad dofs before the ζ).
#[allow(clippy::too_many_arguments)]
pub(super) fn add_patch_terms(
    a: &mut Mat<f64>,
    scene: &Scene,
    law: &PatchLaw,
    contact: &PadContactPoint,
    ci: usize,
    extra: usize,
    preload: f64,
    speed: f64,
    mu: f64,
) {
    let n = scene.n_modes();
    let mass = &scene.model.body().modal_mass;
    let node = &scene.ale_nodes[contact.node];
    let h = contact.face_z[0] - contact.face_z[1];
    let (s, c) = contact.sin_cos;
    let v = (speed * contact.radius).abs();
    let damp = preload * Pads::friction_per_speed(mu, v);
    let lever = 0.5 * h * h * damp;
    let denom = law.damping + damp;
    let (share, relax) = (damp / denom, law.stiffness / denom);
    let z = patch_index(n, extra, ci);
    a[(z, z)] = -relax;
    let radial = |g: [f64; 2]| c * g[0] + s * g[1];
    for m in 0..n {
        let (dr, drt) = (radial(node.gradient(m)), radial(node.gradient_phi[m]));
        // ζ̇ ∋ share R, R = Σ_m (∂_r w_m q̄̇_m + Ω ∂_θ(∂_r w)_m q̄_m) (the rigid terms' R).
        a[(z, n + m)] += share * dr;
        a[(z, m)] += share * speed * drt;
        for i in 0..n {
            let on = lever * radial(node.gradient(i)) / mass[i];
            a[(n + i, n + m)] += on * share * dr;
            a[(n + i, m)] += on * share * speed * drt;
        }
    }
    for i in 0..n {
        a[(n + i, z)] -= lever * radial(node.gradient(i)) / mass[i] * relax;
    }
}
