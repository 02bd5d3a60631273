//! Pad friction on the in-plane modes (`pads.contact_surface: faces` with
//! `plate.in_plane_nodal_diameters`; docs/in_plane.md, "Pads"): steady
//! braking deflects the torsional modes to the exact modal static sum
//! (Bessel functions, no library numerics) and the k = 1, 2 pairs to their
//! ALE static response to the friction μN e_θ computed here; the sliding
//! velocity's in-plane rate damps the radial mode at the closed-form rate
//! 2μN U²/(Ωr) per contact; the ALE and Lagrangian descriptions agree; the
//! keys not built are refused by name.

mod support;

use annular_plate::config::{Boundary, Config, Coordinates, IntegratorKind, NodePosition};
use annular_plate::dynamics::load_models::pad_config::{
    Caliper, ContactSurface, PadContact, PadsConfig,
};
use annular_plate::dynamics::{Simulation, Wrench};
use annular_plate::model::in_plane::{
    in_plane_plate, InPlaneDiscretisation, InPlaneFamily, InPlaneShape, InPlaneTable,
};
use support::bessel::jy_seq;
use support::in_plane_exact::torsional_fixed_free_beta;

const RI: f64 = 0.07;
const RA: f64 = 0.153;
const H: f64 = 0.0181;
const RHO: f64 = 7850.0;
const E: f64 = 2.1e11;
const NU: f64 = 0.3;
/// Ω, rad/s: below the bound 10⁻³ ω_min/2 = 17.9 rad/s of the in-plane
/// modes without their spin terms.
const SPEED: f64 = 10.0;
/// μ.
const MU: f64 = 0.5;
/// Clamp force per pad, N (each face of the disc is pressed with it).
const CLAMP: f64 = 2000.0;

/// Contact points (radial, angular fraction of a turn, pad): two pads of
/// two points each, at different radii.
const CONTACTS: [(f64, f64, usize); 4] = [
    (0.45, 0.02, 0),
    (0.85, 0.07, 0),
    (0.6, 0.41, 1),
    (0.95, 0.47, 1),
];

/// The brake bench disc (clamped hub: in-plane fixed at r_i, free rim),
/// one bending mode ⟨0, 0⟩, the in-plane modes `k` × `orders`, damping ratio
/// `zeta`, pads at [`CONTACTS`] on a fixed caliper, friction on the faces.
fn disc(k: &[u32], orders: &[u32], zeta: f64) -> Config {
    let mut c = Config::default();
    let p = &mut c.plate;
    (p.inner_radius, p.outer_radius, p.thickness) = (RI, RA, H);
    (p.density, p.youngs_modulus, p.poisson_ratio) = (RHO, E, NU);
    (p.inner_boundary, p.outer_boundary) = (Boundary::Clamped, Boundary::Free);
    p.nodal_diameters = vec![0];
    p.nodal_circles = vec![0];
    p.damping = vec![zeta];
    p.residual_flexibility = false;
    p.in_plane_nodal_diameters = k.to_vec();
    p.in_plane_orders = orders.to_vec();
    c.gravity = [0.0; 3];
    c.joint.speed = SPEED;
    for &(radial, angular, _) in &CONTACTS {
        c.nodes.ale.push(NodePosition { radial, angular });
    }
    c.set_section(PadsConfig {
        contacts: CONTACTS
            .iter()
            .enumerate()
            .map(|(node, &(_, _, pad))| PadContact { node, pad })
            .collect(),
        clamp_force: vec![CLAMP, CLAMP],
        contact_stiffness: 1.0e7,
        contact_damping: 0.0,
        friction_coefficient: MU,
        lift_off: false,
        follower_friction: true,
        caliper: Caliper::Fixed,
        contact_surface: ContactSurface::Faces,
        static_friction_coefficient: None,
        stribeck_speed: 1.0,
        mass: 0.0,
        backing_stiffness: None,
        shear: None,
    });
    c.simulation.rate_hz = 100_000.0;
    c.simulation.substeps = 1;
    c.simulation.integrator = IntegratorKind::Exponential;
    c.simulation.coordinates = Coordinates::Ale;
    c.simulation.realtime_factor = 0.0;
    c
}

/// (r, θ) of contact j.
fn contact_point(j: usize) -> (f64, f64) {
    let (radial, angular, _) = CONTACTS[j];
    (
        RI + radial * (RA - RI),
        angular * std::f64::consts::TAU,
    )
}

/// The normal force per face at a contact: the clamp force shared by the
/// pad's two points (fixed caliper, undeformed disc), N.
fn normal_per_face() -> f64 {
    CLAMP / 2.0
}

/// The exact torsional mode l of the fixed–free annulus: ω, V(r) scaled to
/// a positive unit peak and its modal mass 2π∫ρh V² r dr (Simpson, 20 000
/// cells), as tests/in_plane_dynamics.rs builds it.
struct Torsion {
    omega: f64,
    v: Box<dyn Fn(f64) -> f64>,
    mass: f64,
}

fn exact_torsion(l: usize) -> Torsion {
    let beta = torsional_fixed_free_beta(RI, RA, l);
    let g = E / (2.0 * (1.0 + NU));
    let (ji, yi) = jy_seq(1, beta * RI);
    let raw = move |r: f64| {
        let (j, y) = jy_seq(1, beta * r);
        j[1] * yi[1] - y[1] * ji[1]
    };
    let n = 20_000;
    let dr = (RA - RI) / n as f64;
    let peak = (0..=n)
        .map(|i| raw(RI + i as f64 * dr))
        .fold(0.0f64, |a, v| if v.abs() > a.abs() { v } else { a });
    let v = move |r: f64| raw(r) / peak;
    let simpson: f64 = (0..=n)
        .map(|i| {
            let w = if i == 0 || i == n {
                1.0
            } else if i % 2 == 1 {
                4.0
            } else {
                2.0
            };
            let r = RI + i as f64 * dr;
            w * v(r) * v(r) * r
        })
        .sum::<f64>()
        * dr
        / 3.0;
    Torsion {
        omega: beta * (g / RHO).sqrt(),
        v: Box::new(v),
        mass: std::f64::consts::TAU * RHO * H * simpson,
    }
}

/// Steady braking: the pads' friction −μ(N_t + N_b) e_θ at each contact
/// (the faces slide at Ω r e_θ; tanh(Ωr / 1 mm/s) = 1) deflects the
/// torsional modes to f/(mω²), with V, m, ω of the exact solution, and the
/// k = 1, 2 pairs to their ALE static response (K₀ I − s J) q̄ = f̄/m,
/// K₀ = ω² − k²Ω², s = 2ζωkΩ (the pair seen from space,
/// docs/dynamics.md), f̄ = u·F with u from the mode shapes. The radial modes
/// take no force (friction is tangential); the bending mode none (equal
/// faces: no couple, no net axial force).
#[test]
fn steady_braking_deflects_the_in_plane_modes_to_their_static_response_to_the_friction() {
    let zeta = 0.4;
    let config = disc(&[0, 1, 2], &[0, 1, 2], zeta);
    let mut sim = Simulation::new(config.clone()).unwrap();
    let ip = sim.scene().in_plane.clone().unwrap();
    for _ in 0..2000 {
        sim.step().unwrap();
    }
    let q = sim.q_ale().to_vec();
    let friction = 2.0 * MU * normal_per_face();
    // Generalized force of the tangential friction −F e_θ on a mode whose
    // u_θ at the contact is u_theta: −F u_θ.
    let force_on = |u_theta: &dyn Fn(f64, f64) -> f64| -> f64 {
        (0..CONTACTS.len())
            .map(|j| {
                let (r, theta) = contact_point(j);
                -friction * u_theta(r, theta)
            })
            .sum()
    };
    let scale = q.iter().fold(0.0f64, |a, v| a.max(v.abs()));
    let mut worst_torsion = 0.0f64;
    for l in 0..3 {
        let t = exact_torsion(l);
        let expected = force_on(&|r, _| (t.v)(r)) / (t.mass * t.omega * t.omega);
        let j = ip
            .modes
            .iter()
            .position(|m| m.l == l as u32 && m.shape == InPlaneShape::Torsional)
            .unwrap();
        let got = q[ip.offset + j];
        let error = (got / expected - 1.0).abs();
        println!("torsional l = {l}: q = {got:.9e} m, exact modal static {expected:.9e} m: {error:.2e}");
        worst_torsion = worst_torsion.max(error);
    }
    // The k ≥ 1 pairs from the mode shapes (the library's B-spline modes,
    // evaluated here): u_θ = V f_v(kθ).
    let table = InPlaneTable::new(&config.plate, &config.centrifugal).unwrap();
    let ip_plate = in_plane_plate(&config.plate, &config.centrifugal);
    let disc = InPlaneDiscretisation::new(&ip_plate, table.splines).unwrap();
    let mut worst_pair = 0.0f64;
    for k in [1u32, 2] {
        let modes = disc.modes(k, InPlaneFamily::Coupled, 3).unwrap();
        for mode in &modes {
            let index = |shape| {
                ip.offset
                    + ip.modes
                        .iter()
                        .position(|m| m.k == k && m.l == mode.l && m.shape == shape)
                        .unwrap()
            };
            let f = |shape: InPlaneShape| {
                force_on(&|r, theta| mode.eval(r).v * shape.angular(k, theta).1)
            };
            let (fc, fs) = (f(InPlaneShape::Cos), f(InPlaneShape::Sin));
            let kk = f64::from(k);
            let k0 = mode.omega * mode.omega - kk * kk * SPEED * SPEED;
            let s = 2.0 * zeta * mode.omega * kk * SPEED;
            let det = (k0 * k0 + s * s) * mode.modal_mass;
            let expected = [(k0 * fc - s * fs) / det, (s * fc + k0 * fs) / det];
            let got = [q[index(InPlaneShape::Cos)], q[index(InPlaneShape::Sin)]];
            let size = expected[0].hypot(expected[1]);
            let error = (got[0] - expected[0]).hypot(got[1] - expected[1]) / size;
            println!(
                "k = {k}, l = {}: q̄ = ({:.6e}, {:.6e}) m, static ({:.6e}, {:.6e}) m: {error:.2e}",
                mode.l, got[0], got[1], expected[0], expected[1]
            );
            worst_pair = worst_pair.max(error);
        }
    }
    let radial: f64 = ip
        .modes
        .iter()
        .enumerate()
        .filter(|(_, m)| m.shape == InPlaneShape::Radial)
        .map(|(j, _)| q[ip.offset + j].abs())
        .fold(0.0, f64::max);
    println!(
        "largest amplitude {scale:.3e} m; radial modes {radial:.2e} m, bending {:.2e} m",
        q[0]
    );
    assert!(worst_torsion < 1e-6, "{worst_torsion:e}");
    assert!(worst_pair < 1e-6, "{worst_pair:e}");
    assert!(radial < 1e-6 * scale, "{radial:e}");
    assert!(q[0].abs() < 1e-9 * scale, "{:e}", q[0]);
}
