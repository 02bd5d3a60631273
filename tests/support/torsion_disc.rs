//! The brake bench disc with in-plane modes (clamped hub, free rim), a
//! brake torque at its rim, and its exact torsional modes (Bessel functions,
//! no library numerics): shared by the tests of the in-plane joint.
#![allow(dead_code)]

use super::bessel::jy_seq;
use super::in_plane_exact::torsional_fixed_free_beta;
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

/// The exact torsional mode l of the fixed–free annulus: ω, V(r) scaled to
/// a positive unit peak, modal mass m = 2π∫ρh V² r dr and the joint coupling
/// s = 2π∫ρh V r² dr (Simpson, 20 000 cells).
pub struct Torsion {
    pub omega: f64,
    pub v_rim: f64,
    pub mass: f64,
    pub coupling: f64,
}

pub fn exact_torsion(l: usize) -> Torsion {
    let beta = torsional_fixed_free_beta(RI, RA, l);
    let g = E / (2.0 * (1.0 + NU));
    let (ji, yi) = jy_seq(1, beta * RI);
    let raw = |r: f64| {
        let (j, y) = jy_seq(1, beta * r);
        j[1] * yi[1] - y[1] * ji[1]
    };
    let n = 20_000;
    let dr = (RA - RI) / n as f64;
    let peak = (0..=n)
        .map(|i| raw(RI + i as f64 * dr))
        .fold(0.0f64, |a, v| if v.abs() > a.abs() { v } else { a });
    let v = |r: f64| raw(r) / peak;
    let simpson = |f: &dyn Fn(f64) -> f64| {
        (0..=n)
            .map(|i| {
                let w = if i == 0 || i == n {
                    1.0
                } else if i % 2 == 1 {
                    4.0
                } else {
                    2.0
                };
                w * f(RI + i as f64 * dr)
            })
            .sum::<f64>()
            * dr
            / 3.0
    };
    let tau = std::f64::consts::TAU * RHO * H;
    Torsion {
        omega: beta * (g / RHO).sqrt(),
        v_rim: v(RA),
        mass: tau * simpson(&|r| v(r) * v(r) * r),
        coupling: tau * simpson(&|r| v(r) * r * r),
    }
}

/// The rigid disc's polar inertia ρh π (r_a⁴ − r_i⁴)/2.
pub fn polar_inertia() -> f64 {
    RHO * H * std::f64::consts::PI * (RA.powi(4) - RI.powi(4)) / 2.0
}
