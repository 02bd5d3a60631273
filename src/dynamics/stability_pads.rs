//! The massive pads' terms of the linear stability analysis
//! (the linear system of `stability.rs`, docs/scenes.md "Pad mass").
//!
//! With `pads.mass` > 0 the state is y = (q̄, q̄̇, ξ, ξ̇), ξ the pads'
//! compressions from rest (per pad: top, bottom; `load_models/pad_mass.rs`).
//! About the preloaded rest, per contact c (shape values w_i at its node):
//!
//!   δN_t = k_c (ξ_t + w) + c_c (ξ̇_t + ẇ),   δN_b = k_c (ξ_b − w) + c_c (ξ̇_b − ẇ),
//!
//! the disc's generalised force f_i = w_i (δN_b − δN_t) (its −2k_c w part is
//! the fixed caliper's K_pad of the massless analysis, here for either
//! caliper), the faces' couple acts on (δN_t − δN_b)/2 (the massless
//! analysis's δN), and each pad obeys m_p ξ̈ = −Σ_c δN_c − k_b ξ (k_b = 0
//! for a floating caliper, whose piston force does not change).

use super::load_models::{PadContactPoint, Pads};
use super::scene::Scene;
use faer::Mat;

/// Index of pad face `j` (2 pad + face) among y's positions and rates.
fn pad_index(n: usize, pads: &Pads, j: usize) -> (usize, usize) {
    let p2 = 2 * pads.pad_count();
    (2 * n + j, 2 * n + p2 + j)
}

/// ξ̇ = ξ̇ and the backing stiffness of every pad face.
pub(super) fn add_pad_identity(a: &mut Mat<f64>, n: usize, pads: &Pads) {
    for j in 0..2 * pads.pad_count() {
        let (x, v) = pad_index(n, pads, j);
        a[(x, v)] = 1.0;
        a[(v, x)] -= pads.backing_stiffness / pads.mass;
    }
}

/// The terms of contact `contact` that involve the pads' coordinates, and the
/// pads' equations; `couple` = h μ(V) tanh(V/v_reg) with face friction (0 at
/// the mid-plane).
pub(super) fn add_pad_terms(a: &mut Mat<f64>, scene: &Scene, pads: &Pads, contact: &PadContactPoint, couple: f64) {
    let n = scene.n_modes();
    let mass = &scene.model.body().modal_mass;
    let node = &scene.ale_nodes[contact.node];
    let (k, c) = (pads.stiffness, pads.damping);
    let (s, co) = contact.sin_cos;
    let (xt, vt) = pad_index(n, pads, 2 * contact.pad);
    let (xb, vb) = pad_index(n, pads, 2 * contact.pad + 1);
    for i in 0..n {
        let wi = node.shapes[i].w;
        let g = node.gradient(i);
        let arm = couple * (-s * g[0] + co * g[1]); // couple ∂_θ w_i / r
        // w_i (δN_b − δN_t) ∋ w_i k_c (ξ_b − ξ_t); the couple on (δN_t − δN_b)/2 ∋ k_c (ξ_t − ξ_b)/2.
        let on_x = (-wi + 0.5 * arm) / mass[i];
        a[(n + i, xt)] += k * on_x;
        a[(n + i, xb)] -= k * on_x;
        a[(n + i, vt)] += c * on_x;
        a[(n + i, vb)] -= c * on_x;
    }
    for (x, v, sign) in [(xt, vt, 1.0), (xb, vb, -1.0)] {
        a[(v, x)] -= k / pads.mass;
        a[(v, v)] -= c / pads.mass;
        for m in 0..n {
            let wm = node.shapes[m].w;
            a[(v, m)] -= sign * k * wm / pads.mass;
            a[(v, n + m)] -= sign * c * wm / pads.mass;
        }
    }
}
