//! The brake bench disc with in-plane modes (clamped hub, free rim), a
//! brake torque at its rim, and its exact torsional modes (Bessel functions,
//! no library numerics): shared by the tests of the in-plane joint.
#![allow(dead_code)]

pub use super::in_plane_modes::Torsion;
use annular_plate::config::{Boundary, Config, IntegratorKind, NodePosition, WrenchConfig};

pub const RI: f64 = 0.07;
pub const RA: f64 = 0.153;
pub const H: f64 = 0.0181;
pub const RHO: f64 = 7850.0;
pub const E: f64 = 2.1e11;
pub const NU: f64 = 0.3;

/// The brake bench disc (clamped hub: in-plane fixed at r_i, free rim) with
/// one bending mode and the in-plane modes `k` × `orders`, undamped, at rest.
/// Without residual flexibility a node force acts at its point (the modes'
/// values there, as the closed forms here take them; with it a node is a
/// load patch, tests/in_plane_node_frames.rs).
pub fn disc(k: &[u32], orders: &[u32], rate_hz: f64) -> Config {
    let mut c = Config::default();
    let p = &mut c.plate;
    (p.inner_radius, p.outer_radius, p.thickness) = (RI, RA, H);
    (p.density, p.youngs_modulus, p.poisson_ratio) = (RHO, E, NU);
    (p.inner_boundary, p.outer_boundary) = (Boundary::Clamped, Boundary::Free);
    p.nodal_diameters = vec![0];
    p.nodal_circles = vec![0];
    p.damping = vec![0.0];
    p.residual_flexibility = false;
    p.in_plane_nodal_diameters = k.to_vec();
    p.in_plane_orders = orders.to_vec();
    c.gravity = [0.0; 3];
    c.joint.speed = 0.0;
    c.joint.max_acceleration = 1e9;
    c.simulation.rate_hz = rate_hz;
    c.simulation.substeps = 1;
    c.simulation.integrator = IntegratorKind::Exponential;
    c
}

/// Rim nodes at φ = 0, π/2, π, 3π/2, each with the tangential force −F e_θ
/// (a brake torque −4 F r_a).
pub fn brake_at_rim(c: &mut Config, force: f64) {
    for j in 0..4 {
        let phi = j as f64 * std::f64::consts::FRAC_PI_2;
        c.nodes.lagrange.push(NodePosition {
            radial: 1.0,
            angular: j as f64 / 4.0,
        });
        let (s, co) = phi.sin_cos();
        c.loads.lagrange.push(WrenchConfig {
            force: [force * s, -force * co, 0.0],
            moment: [0.0; 3],
        });
    }
}

/// The exact torsional mode l of this disc (`in_plane_modes::exact_torsion`).
pub fn exact_torsion(l: usize) -> Torsion {
    super::in_plane_modes::exact_torsion(&disc(&[0], &[0], 1000.0).plate, l)
}

/// The rigid disc's polar inertia ρh π (r_a⁴ − r_i⁴)/2.
pub fn polar_inertia() -> f64 {
    RHO * H * std::f64::consts::PI * (RA.powi(4) - RI.powi(4)) / 2.0
}
