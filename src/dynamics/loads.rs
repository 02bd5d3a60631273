//! Generalized forces of node wrenches and of the reference-frame motion.
//!
//! A wrench (F, M) at a node, in the node frame's axes (parallel to the ALE
//! frame A for ALE nodes, to the plate frame B for Lagrangian nodes, turned by
//! the surface slope when loads follow the surface), does virtual work on
//! mode i through the deflection w_i and the surface tilt (θ_x, θ_y) there:
//!
//! f_i = w_i F_z + θ_x,i M_x + θ_y,i M_y.
//!
//! A follower force turns with the deformed surface, F ↦ F + θ × F, so its
//! in-plane part (friction) gets the normal component θ_x F_y − θ_y F_x
//! (paper 5.3). ALE-node forces are generalized forces on the ALE modes of
//! eq. (18), constant in frame A; Lagrangian ones act on the modes of (13).
//! About the axis every wrench gives τ_z = x F_y − y F_x + M_z.
//!
//! In-plane modes (`plate.in_plane_nodal_diameters`) take the in-plane
//! components of the held wrenches and of the load models' (the pads'
//! friction on the faces): f_i = u_x,i F_x + u_y,i F_y ([`super::in_plane`]).
//!
//! A frame on a face (z = ±h/2, `nodes.*_surface`) moves in-plane by −z∇w
//! (Kirchhoff), so its in-plane force F_t does the virtual work −z F_t·∇w_i:
//! the moment z e_z × F about the mid-plane point, added to M. Under Mindlin
//! theory the tilt is the rotation of the normal, θ = (−ψ_y, ψ_x): a moment
//! works on ψ, and the face moves by z ψ (`NodeFrame::new`).

use super::commands::Inputs;
use super::load_models::ModelWrenches;
use super::scene::{NodeFrame, Scene};
use super::wrench::Wrench;

/// Generalized forces for one step, split by the frame they are constant in.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct StepLoads {
    /// Constant in the ALE frame A (pairs: f̄ of ALE nodes and the off-axis
    /// rotation); for k = 0 modes the whole axisymmetric force.
    pub ale_frame: Vec<f64>,
    /// Constant in the plate frame B (pairs only: Lagrangian nodes).
    pub plate_frame: Vec<f64>,
    /// Torque of all node wrenches about the axis, N·m.
    pub axial_torque: f64,
}

impl StepLoads {
    pub fn new(n: usize) -> StepLoads {
        StepLoads {
            ale_frame: vec![0.0; n],
            plate_frame: vec![0.0; n],
            axial_torque: 0.0,
        }
    }
}

fn add_node(node: &NodeFrame, w: &Wrench, q_own: &[f64], follower: bool, out: &mut [f64]) -> f64 {
    let f = w.force;
    let mut fz = f[2];
    if follower {
        let t = node.deflection(q_own).tilt;
        fz += t[0] * f[1] - t[1] * f[0];
    }
    let face = node.face_moment(&f);
    let (mx, my) = (w.moment[0] + face[0], w.moment[1] + face[1]);
    for (o, s) in out.iter_mut().zip(&node.shapes) {
        *o += s.w * fz + s.tilt[0] * mx + s.tilt[1] * my;
    }
    let p = node.position();
    p[0] * f[1] - p[1] * f[0] + w.moment[2]
}

/// Fill `out` with the node wrenches' generalized forces and axial torque,
/// given the amplitudes in both descriptions (follower loads need the slope):
/// the user's held wrenches (following the surface with `loads.follower`) and
/// the load models' wrenches `models` (each node with its own follower choice).
/// The reference motion is added separately ([`add_reference_motion`]), as it
/// depends on the joint speed over the step.
pub fn compute(
    scene: &Scene,
    inputs: &Inputs,
    models: &ModelWrenches,
    q_ale: &[f64],
    q_lagrange: &[f64],
    out: &mut StepLoads,
) {
    out.ale_frame.iter_mut().for_each(|v| *v = 0.0);
    out.plate_frame.iter_mut().for_each(|v| *v = 0.0);
    let follower = scene.effects.follower_loads;
    let mut torque = 0.0;
    for (node, w) in scene.ale_nodes.iter().zip(&inputs.ale) {
        if *w != Wrench::default() {
            torque += add_node(node, w, q_ale, follower, &mut out.ale_frame);
        }
    }
    for (node, w) in scene.lagrange_nodes.iter().zip(&inputs.lagrange) {
        if *w != Wrench::default() {
            torque += add_node(node, w, q_lagrange, follower, &mut out.plate_frame);
        }
    }
    if let Some(ip) = &scene.in_plane {
        for (shapes, w) in ip.ale_nodes.iter().zip(&inputs.ale) {
            ip.add_node_force(shapes, &w.force, &mut out.ale_frame);
        }
        for (shapes, w) in ip.lagrange_nodes.iter().zip(&inputs.lagrange) {
            ip.add_node_force(shapes, &w.force, &mut out.plate_frame);
        }
    }
    if !scene.load_models.is_empty() {
        for ((node, w), &f) in scene
            .ale_nodes
            .iter()
            .zip(&models.ale)
            .zip(&models.ale_follower)
        {
            if *w != Wrench::default() {
                torque += add_node(node, w, q_ale, f, &mut out.ale_frame);
            }
        }
        for ((node, w), &f) in scene
            .lagrange_nodes
            .iter()
            .zip(&models.lagrange)
            .zip(&models.lagrange_follower)
        {
            if *w != Wrench::default() {
                torque += add_node(node, w, q_lagrange, f, &mut out.plate_frame);
            }
        }
        if let Some(ip) = &scene.in_plane {
            for (shapes, w) in ip.ale_contacts.iter().zip(&models.ale) {
                ip.add_contact_force(shapes, &w.force, &mut out.ale_frame);
            }
            for (shapes, w) in ip.lagrange_nodes.iter().zip(&models.lagrange) {
                ip.add_node_force(shapes, &w.force, &mut out.plate_frame);
            }
        }
    }
    // k = 0 modes are the same in both descriptions: keep their force in one place.
    for &i in &scene.layout.axisymmetric {
        out.ale_frame[i] += out.plate_frame[i];
        out.plate_frame[i] = 0.0;
    }
    out.axial_torque = torque;
}

/// Inertia forces of the reference motion on the elastic modes (eq. 11, q rows):
/// −C_t (a_R − g) on k = 0 modes, and for a frame turning at constant ω_A
/// the k = 1 pairs' force in the ALE frame, f̄ = −s (2Ω + ω_z)(ω_x, ω_y)
/// (Coriolis and centrifugal acceleration (2Ω + ω_z) ω_x x of the spinning
/// material; s = ρh π ∫ R r² dr). A Mindlin mode's face displacement z ψ
/// adds the in-plane centrifugal acceleration z ω_z (ω_x, ω_y) of ω × (ω × c)
/// through its rotary moment p = ρh³/12 ∫ ψ dA: f̄ −= p ω_z (ω_x, ω_y)
/// (zero under Kirchhoff theory, docs/mindlin.md). The softening
/// (ω_x² + ω_y²) M_e q enters the integrators' stiffness instead. The
/// in-plane k = 1 modes take the in-plane specific force, −C·(a_R − g)_xy
/// in the ALE frame (C = ∫ ρh u dA, `InPlaneModeDyn::first_moment`).
pub fn add_reference_motion(scene: &Scene, speed: f64, ale_frame: &mut [f64]) {
    let body = scene.model.body();
    if scene.effects.axial_body_force {
        let fz = scene.reference.specific_force[2];
        // The in-plane modes (after the bending ones) have no axial moment.
        for &i in &scene.layout.axisymmetric {
            if let Some(c) = body.first_moments.get(i) {
                ale_frame[i] -= c[2] * fz;
            }
        }
    }
    let f = scene.reference.specific_force;
    if let Some(ip) = scene
        .in_plane
        .as_ref()
        .filter(|_| f[0] != 0.0 || f[1] != 0.0)
    {
        for (i, m) in ip.modes.iter().enumerate() {
            let [cx, cy] = m.first_moment;
            ale_frame[ip.offset + i] -= cx * f[0] + cy * f[1];
        }
    }
    if scene.effects.off_axis_rotation {
        let w = scene.reference.angular_velocity;
        let rate = 2.0 * speed + w[2];
        for p in scene.layout.pairs.iter().filter(|p| p.k == 1) {
            let s = body.first_moments[p.cos][0];
            ale_frame[p.cos] -= s * rate * w[0];
            ale_frame[p.sin] -= s * rate * w[1];
            let rotary = body.rotary_moments[p.cos][0];
            if rotary != 0.0 {
                ale_frame[p.cos] -= rotary * w[2] * w[0];
                ale_frame[p.sin] -= rotary * w[2] * w[1];
            }
        }
    }
}
