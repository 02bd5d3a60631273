//! Pad friction on the in-plane modes (`pads.contact_surface: faces` with
//! `plate.in_plane_nodal_diameters`; docs/in_plane.md, "Pads"): steady
//! braking deflects the torsional modes to the exact modal static sum
//! (Bessel functions, no library numerics) and the k = 1, 2 pairs to their
//! ALE static response to the friction μN e_θ computed here; the sliding
//! velocity's in-plane rate damps the radial mode at the closed-form rate
//! 2μN U²/(Ωr) per contact; the ALE and Lagrangian descriptions agree; the
//! friction at the mid-plane (the paper's model) deflects them to its own
//! static; the lining's patches carry the same friction in steady sliding;
//! where the sliding is so slow that `exponential`'s held friction no longer
//! resolves its damping, the step is refused and RK4 meets the steady state.

mod support;

use annular_plate::config::{Boundary, Config, Coordinates, IntegratorKind, NodePosition};
use annular_plate::dynamics::load_models::pad_config::{
    Caliper, ContactSurface, PadContact, PadsConfig,
};
use annular_plate::dynamics::{Simulation, Wrench};
use annular_plate::model::in_plane::InPlaneShape;
use support::in_plane_modes::{exact_torsion, patch_mean, test_modes, TestMode};

const RI: f64 = 0.07;
const RA: f64 = 0.153;
const H: f64 = 0.0181;
const RHO: f64 = 7850.0;
const E: f64 = 2.1e11;
const NU: f64 = 0.3;
/// Ω, rad/s: below the bound 10⁻³ ω_min/2 = 17.9 rad/s of the in-plane
/// modes without their spin terms.
const SPEED: f64 = 10.0;
/// v_reg of the regularised friction, m/s (documented in docs/scenes.md).
const REGULARISATION_SPEED: f64 = 1.0e-3;
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
    (RI + radial * (RA - RI), angular * std::f64::consts::TAU)
}

/// The normal force per face at a contact: the clamp force shared by the
/// pad's two points (fixed caliper, undeformed disc), N.
fn normal_per_face() -> f64 {
    CLAMP / 2.0
}

/// The steady state of the pads' friction on the modes `modes`, solved
/// here by fixed-point iteration: at contact (r, θ) both faces slide with
/// v = Ω r e_θ + Ω Σ q̄_i ∂u_i/∂θ (polar: v_r = Ω Σ q̄ (∂_θ u_r − u_θ),
/// v_θ = Ω r + Ω Σ q̄ (∂_θ u_θ + u_r), the twisted material turning with the
/// disc), friction −μ(N_t + N_b) tanh(|v|/v_reg) v/|v| (v_reg = 1 mm/s:
/// the factor is 1 in f64 at 0.5 rad/s, 1 − 1e-5 at 0.05 rad/s), generalized
/// force u_i·F; k = 0 modes q = f/(mω²), k ≥ 1 pairs the ALE static
/// (K₀ I − s J) q̄ = f̄/m, K₀ = ω² − k²Ω², s = 2ζωkΩ (the pair seen from
/// space, docs/dynamics.md). Returns q̄ by state index.
fn steady_braking(
    modes: &[TestMode],
    zeta: f64,
    n: usize,
    speed: f64,
    surface: ContactSurface,
) -> Vec<f64> {
    let friction = 2.0 * MU * normal_per_face();
    let mut q = vec![0.0; n];
    for _ in 0..6 {
        let mut f = vec![0.0; n];
        for j in 0..CONTACTS.len() {
            let (r, theta) = contact_point(j);
            let (mut vr, mut vt) = (0.0, speed * r);
            // At the mid-plane the friction keeps to −e_θ (the paper's model).
            for m in modes.iter().filter(|_| surface == ContactSurface::Faces) {
                let [ur, ut, dur, dut] = (m.polar)(r, theta);
                vr += speed * q[m.index] * (dur - ut);
                vt += speed * q[m.index] * (dut + ur);
            }
            let speed = vr.hypot(vt);
            let g = friction * (speed / REGULARISATION_SPEED).tanh() / speed;
            let (fr, ft) = (-g * vr, -g * vt);
            for m in modes {
                let [ur, ut, ..] = (m.polar)(r, theta);
                f[m.index] += fr * ur + ft * ut;
            }
        }
        let mut next = vec![0.0; n];
        for (a, m) in modes.iter().enumerate() {
            if m.k == 0 {
                next[m.index] = f[m.index] / (m.mass * m.omega * m.omega);
                continue;
            }
            // The cos mode is followed by its sin partner in the table.
            let Some(partner) = modes[a + 1..]
                .iter()
                .find(|p| p.k == m.k && p.omega == m.omega)
            else {
                continue;
            };
            let kk = f64::from(m.k);
            let k0 = m.omega * m.omega - kk * kk * speed * speed;
            let s = 2.0 * zeta * m.omega * kk * speed;
            let det = (k0 * k0 + s * s) * m.mass;
            let (fc, fs) = (f[m.index], f[partner.index]);
            next[m.index] = (k0 * fc - s * fs) / det;
            next[partner.index] = (s * fc + k0 * fs) / det;
        }
        q = next;
    }
    q
}

/// Steady braking: the pads' friction at each contact deflects the modes
/// to the steady state solved in the test ([`steady_braking`]): the
/// torsional modes against the exact solution's V, m, ω; the pairs and the
/// radial modes (which take only the small radial friction of the turning
/// twist) from the mode shapes. The bending mode takes nothing (equal
/// faces: no couple, no net axial force).
#[test]
fn steady_braking_deflects_the_in_plane_modes_to_their_static_response_to_the_friction() {
    steady_braking_matches_the_static_response(ContactSurface::Faces);
}

/// The same with the friction at the mid-plane (the paper's model): along
/// −e_θ at each contact whatever the twist, so the radial modes take
/// nothing from a turned sliding direction.
#[test]
fn mid_plane_friction_deflects_the_in_plane_modes_to_their_static_response() {
    steady_braking_matches_the_static_response(ContactSurface::MidPlane);
}

/// At 0.05 rad/s the faces' friction damps the radial motion by μN/(Ωr)
/// per face, ten times more than at 0.5 rad/s: `exponential`, which holds
/// the pads' forces over its 10 µs substep, no longer resolves it and
/// refuses the step naming the integrator; RK4, which evaluates the pads at
/// every stage and counts that damping in its inner substeps, meets the
/// same steady state.
#[test]
fn slow_sliding_is_refused_where_held_friction_forces_do_not_resolve_their_damping() {
    let mut config = disc(&[0, 1, 2], &[0, 1, 2], 0.4);
    config.joint.speed = 0.05;
    let mut sim = Simulation::new(config.clone()).unwrap();
    let error = sim.step().unwrap_err().to_string();
    println!("{error}");
    assert!(
        error.contains("simulation.integrator = exponential"),
        "{error}"
    );
    assert!(error.contains("μN/|V|"), "{error}");
    assert_eq!(sim.state().steps, 0);
    config.simulation.integrator = IntegratorKind::Rk4;
    steady_braking_matches_the_static_response_of(config, ContactSurface::Faces, 0.02);
}

fn steady_braking_matches_the_static_response(surface: ContactSurface) {
    let mut config = disc(&[0, 1, 2], &[0, 1, 2], 0.4);
    // The static here leaves out the in-plane spin terms (Coriolis, spin
    // stiffness; tests/in_plane_spin_dynamics.rs): they move the steady
    // state by 8.0e-8 of the largest amplitude at 10 rad/s, as (Ω/ω)², so
    // at 0.5 rad/s by 2e-10. The sliding direction's turn by the twisted
    // material, Ω q ∂u/∂θ against Ω r, does not depend on the speed.
    config.joint.speed = 0.5;
    steady_braking_matches_the_static_response_of(config, surface, 0.02);
}

/// Run `config` with `surface` for `settle` seconds and compare every
/// in-plane amplitude with [`steady_braking`].
fn steady_braking_matches_the_static_response_of(
    mut config: Config,
    surface: ContactSurface,
    settle: f64,
) {
    let zeta = config.plate.damping[0];
    config.section_mut::<PadsConfig>().unwrap().contact_surface = surface;
    let mut sim = Simulation::new(config.clone()).unwrap();
    for _ in 0..(settle * config.simulation.rate_hz).round() as usize {
        sim.step().unwrap();
    }
    let q = sim.q_ale().to_vec();
    let modes = test_modes(&config, &sim);
    let expected = steady_braking(&modes, zeta, q.len(), config.joint.speed, surface);
    let scale = q.iter().fold(0.0f64, |a, v| a.max(v.abs()));
    let ip = sim.scene().in_plane.as_ref().unwrap();
    let mut worst = 0.0f64;
    for (m, dyn_mode) in modes.iter().zip(&ip.modes) {
        let (got, want) = (q[m.index], expected[m.index]);
        let error = (got - want).abs() / scale;
        println!(
            "{} k = {}, l = {}: q̄ = {got:.9e} m, steady state {want:.9e} m: {error:.2e} of the largest",
            dyn_mode.shape.name(),
            m.k,
            dyn_mode.l
        );
        worst = worst.max(error);
    }
    // The twist alone, against the exact torsional modes with the friction
    // taken tangential: f = −μ(N_t + N_b) Σ tanh(Ω r_c/v_reg) V(r_c).
    let friction = 2.0 * MU * normal_per_face();
    let t = exact_torsion(&config.plate, 0);
    let regularised = |r: f64| (config.joint.speed * r / REGULARISATION_SPEED).tanh();
    let tangential: f64 = (0..CONTACTS.len())
        .map(|j| contact_point(j).0)
        .map(|r| -friction * regularised(r) * (t.v)(r))
        .sum::<f64>()
        / (t.mass * t.omega * t.omega);
    let index = modes[ip.torsional[0]].index;
    let twist = (q[index] / tangential - 1.0).abs();
    println!(
        "largest amplitude {scale:.3e} m; torsional l = 0 against −μN ΣV/(mω²): {twist:.2e}; bending {:.2e} m; worst {worst:.2e}",
        q[0]
    );
    assert!(worst < 1e-9, "{worst:e}");
    assert!(twist < 1e-9, "{twist:e}");
    assert!(q[0].abs() < 1e-9 * scale, "{:e}", q[0]);
}

/// The in-plane rate in the sliding velocity: a radial velocity u̇_r turns
/// the friction of each face by −μN u̇_r/(Ωr) (|v| ≫ 1 mm/s), a damper
/// 2μN/(Ωr) per contact on the two faces. On the k = 0 radial mode (ζ = 0)
/// that is the decay rate σ = Σ_c 2μN U(r_c)²/(Ω r_c) / (2m). Kicked by a
/// held radial force at contact 0 that is then released, the envelope
/// ln(q² + (q̇/ω)²) of the mode falls at 2σ (RK4 at 1 MHz, ωh = 0.1).
#[test]
fn friction_damps_the_radial_mode_at_the_closed_form_rate() {
    let mut config = disc(&[0], &[0], 0.0);
    config.simulation.rate_hz = 1.0e6;
    config.simulation.integrator = IntegratorKind::Rk4;
    let mut sim = Simulation::new(config.clone()).unwrap();
    let ip = sim.scene().in_plane.clone().unwrap();
    let j = ip
        .modes
        .iter()
        .position(|m| m.shape == InPlaneShape::Radial)
        .unwrap();
    let index = ip.offset + j;
    let modes = test_modes(&config, &sim);
    let radial = modes.iter().find(|m| m.index == index).unwrap();
    let damper: f64 = (0..CONTACTS.len())
        .map(|c| {
            let (r, theta) = contact_point(c);
            let u = (radial.polar)(r, theta)[0];
            2.0 * MU * normal_per_face() * u * u / (SPEED * r)
        })
        .sum();
    let sigma = damper / (2.0 * radial.mass);
    let (_, theta) = contact_point(0);
    let (s, c) = theta.sin_cos();
    let kick = 5000.0;
    sim.set_ale_wrench(
        0,
        Wrench {
            force: [kick * c, kick * s, 0.0],
            moment: [0.0; 3],
        },
    )
    .unwrap();
    for _ in 0..20 {
        sim.step().unwrap();
    }
    sim.set_ale_wrench(0, Wrench::default()).unwrap();
    let (mut t, mut ln_e) = (Vec::new(), Vec::new());
    for _ in 0..20_000 {
        sim.step().unwrap();
        let (q, v) = (sim.q_ale()[index], sim.q_dot_ale()[index]);
        let rotated = v / radial.omega;
        t.push(sim.time());
        ln_e.push((q * q + rotated * rotated).ln());
    }
    let fitted = -0.5 * support::fit::least_squares_slope(&t, &ln_e);
    let error = (fitted / sigma - 1.0).abs();
    println!(
        "radial mode: ω = {:.1} rad/s, closed-form decay {sigma:.6} 1/s, fitted {fitted:.6} 1/s: {error:.2e}; ln fell {:.3}",
        radial.omega,
        ln_e[0] - ln_e[ln_e.len() - 1]
    );
    assert!(error < 1e-3, "{error:e}");
}

/// The pads on the in-plane pairs k = 1, 2 (with friction also on the
/// torsional mode), started by the clamp force at t = 0: the ALE and the
/// Lagrangian descriptions (RK4) give the same Lagrangian amplitudes.
#[test]
fn ale_and_lagrangian_descriptions_agree_with_pads_on_the_in_plane_modes() {
    ale_and_lagrangian_agree_on_the_in_plane_modes(None);
}

/// The same with the lining's patches, whose sliding velocity reads the
/// in-plane rate in either description.
#[test]
fn ale_and_lagrangian_descriptions_agree_with_lining_patches_on_the_in_plane_modes() {
    ale_and_lagrangian_agree_on_the_in_plane_modes(Some((1.0e6, 10.0)));
}

fn ale_and_lagrangian_agree_on_the_in_plane_modes(shear: Option<(f64, f64)>) {
    let run = |coordinates| {
        let mut c = disc(&[0, 1, 2], &[0], 0.05);
        c.section_mut::<PadsConfig>().unwrap().shear = shear;
        c.simulation.rate_hz = 1.0e6;
        c.simulation.integrator = IntegratorKind::Rk4;
        c.simulation.coordinates = coordinates;
        let mut sim = Simulation::new(c).unwrap();
        let mut history = vec![];
        for _ in 0..2000 {
            sim.step().unwrap();
            history.push(sim.q_lagrange().to_vec());
        }
        history
    };
    let ale = run(Coordinates::Ale);
    let lagrange = run(Coordinates::Lagrangian);
    let scale = ale.iter().flatten().fold(0.0f64, |a, v| a.max(v.abs()));
    let worst = ale
        .iter()
        .flatten()
        .zip(lagrange.iter().flatten())
        .fold(0.0f64, |m, (x, y)| m.max((x - y).abs()))
        / scale;
    println!("largest amplitude {scale:.3e} m; ALE vs Lagrangian {worst:.2e} of it");
    assert!(scale > 1e-8);
    assert!(worst < 1e-6, "{worst:e}");
}

/// The lining's patches (k_t ∥ c_t per face, `pads.shear_stiffness`) in
/// steady sliding carry the friction μN along the sliding direction, ẋ = 0:
/// the in-plane modes reach the same steady state as under the rigid
/// lining ([`steady_braking`]), the patches' face velocity reading the
/// in-plane rate as the rigid law does (RK4, which integrates the patches).
/// Radially a patch creeps at k_t/(c_t + μN/(Ω r)) (`pad_patch.rs`), 1e2 1/s
/// here, so the run settles for 0.25 s.
#[test]
fn lining_patches_carry_the_friction_to_the_in_plane_modes_in_steady_sliding() {
    let mut config = disc(&[0, 1, 2], &[0, 1, 2], 0.4);
    config.section_mut::<PadsConfig>().unwrap().shear = Some((1.0e6, 10.0));
    config.simulation.integrator = IntegratorKind::Rk4;
    config.simulation.rate_hz = 20_000.0;
    config.joint.speed = 0.5;
    // The patches creep radially at k_t/(c_t + μN/(Ω r)) ≈ 100 1/s: 0.25 s
    // leaves e^(−25) of their start.
    steady_braking_matches_the_static_response_of(config, ContactSurface::Faces, 0.25);
}

/// config/brake_in_plane.yaml (the bench with in-plane k = 0, 1, 2, l = 0,
/// clamped at 5 kN per face from the start, 15 rad/s): after 0.3 s the first
/// torsional mode holds the exact modal static twist under the three
/// contacts' friction −2μN e_θ, spread over the nodes' load patches (the
/// scene has residual flexibility) (N = 5 kN/3 per face and contact, the
/// floating caliper's share on the undeformed disc; the bending stays at
/// rest under equal faces) within 1e-6 — the static at rest, which the spin
/// terms move by (Ω/ω_min)² = 1.8e-7 at 15 rad/s — and the drive's effort
/// is the friction torque 2μN₀ r.
#[test]
fn the_in_plane_brake_scene_twists_the_disc_to_the_exact_static_sum() {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/config/brake_in_plane.yaml");
    let config = Config::from_params_file(std::path::Path::new(path), "annular_plate").unwrap();
    let mut sim = Simulation::new(config.clone()).unwrap();
    let steps = (0.3 * config.simulation.rate_hz) as usize;
    for _ in 0..steps {
        sim.step().unwrap();
    }
    let ip = sim.scene().in_plane.as_ref().unwrap();
    let index = ip.offset + ip.torsional[0];
    let t = exact_torsion(&config.plate, 0);
    let clamp = config.section::<PadsConfig>().unwrap().clamp_force[0];
    let mu = config.section::<PadsConfig>().unwrap().friction_coefficient;
    let per_face = clamp / sim.scene().ale_nodes.len() as f64;
    let force: f64 = sim
        .scene()
        .ale_nodes
        .iter()
        .map(|n| -2.0 * mu * per_face * patch_mean(&config, &t, n.radius))
        .sum();
    let expected = force / (t.mass * t.omega * t.omega);
    let got = sim.q_ale()[index];
    let error = (got / expected - 1.0).abs();
    let radius = sim.scene().ale_nodes[0].radius;
    let torque = 2.0 * mu * clamp * radius;
    let effort = sim.joint().effort;
    println!(
        "torsional q = {got:.9e} m, exact {expected:.9e} m: {error:.2e}; effort {effort:.4} N·m, 2μN₀r = {torque:.4} N·m"
    );
    assert!(error < 1e-6, "{error:e}");
    assert!((effort / torque - 1.0).abs() < 1e-6, "{effort}");
}

/// `simulate --output-rate` of config/brake_in_plane.yaml: the aliasing
/// check takes the least stable mode of the stability analysis with the
/// in-plane modes in (the bending ⟨0, 0⟩ at 744.5 Hz, docs/in_plane.md,
/// "Stability"), so 100 Hz is refused naming it; with `--allow-aliasing`
/// the run writes its rows.
#[test]
fn simulate_with_an_output_rate_runs_the_in_plane_brake_scene() {
    let dir = support::cli::scratch_dir("in_plane_pads_output_rate");
    let csv = dir.join("out.csv");
    let scene = concat!(env!("CARGO_MANIFEST_DIR"), "/config/brake_in_plane.yaml");
    let args = [
        "simulate",
        scene,
        "--duration",
        "0.1",
        "--output-rate",
        "100",
        "--csv",
        csv.to_str().unwrap(),
        "--quiet",
    ];
    let (ok, _, stderr) = support::cli::run(&args);
    assert!(!ok && stderr.contains("744.5 Hz"), "{stderr}");
    assert!(!csv.exists());
    let (ok, _, stderr) = support::cli::run(&[&args[..], &["--allow-aliasing"]].concat());
    assert!(ok, "{stderr}");
    assert!(!stderr.contains("panicked"), "{stderr}");
    let rows = std::fs::read_to_string(&csv).unwrap().lines().count();
    println!("{rows} lines");
    assert_eq!(rows, 1 + 11, "header and t = 0, 0.01, …, 0.1");
    let _ = std::fs::remove_dir_all(&dir);
}

/// config/brake_in_plane.yaml at 200 rad/s, where the in-plane spin terms
/// act (Coriolis coupling 2Ω between u_r and u_θ, the spin stiffness):
/// `contact_exponential` (the scene's integrator, the spin terms in its
/// linearisation by differences of f) against RK4 at a step limit of 0.05
/// (the same equations stage by stage), 0.05 s from the clamp at rest. The
/// two agree on every ALE amplitude, bending and in-plane, within 1e-6 of
/// the largest.
#[test]
fn contact_exponential_and_rk4_agree_on_the_in_plane_brake_scene_at_speed() {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/config/brake_in_plane.yaml");
    let mut config = Config::from_params_file(std::path::Path::new(path), "annular_plate").unwrap();
    config.joint.speed = 200.0;
    let run = |integrator: IntegratorKind| {
        let mut c = config.clone();
        c.simulation.integrator = integrator;
        c.simulation.rk4_step_limit = 0.05;
        let mut sim = Simulation::new(c).unwrap();
        let mut history = Vec::new();
        for _ in 0..(0.05 * config.simulation.rate_hz) as usize {
            sim.step().unwrap();
            history.push(sim.q_ale().to_vec());
        }
        history
    };
    let (a, b) = (
        run(IntegratorKind::ContactExponential),
        run(IntegratorKind::Rk4),
    );
    let peak = b.iter().flatten().fold(0.0f64, |m, v| m.max(v.abs()));
    let worst = a
        .iter()
        .flatten()
        .zip(b.iter().flatten())
        .fold(0.0f64, |m, (x, y)| m.max((x - y).abs()));
    println!(
        "largest amplitude {peak:.3e} m; contact_exponential against RK4: {:.2e} of it",
        worst / peak
    );
    assert!(peak > 1e-7, "{peak:e}");
    assert!(worst < 1e-6 * peak, "{:e}", worst / peak);
}

/// A commanded slow-down of config/brake_in_plane.yaml with frictionless
/// pads (μ = 0: springs on the faces, no torque): the joint decelerates at
/// its limit α = −50 rad/s², and the torsional mode carries the Euler force
/// −s α to its quasi-static twist −s α/(m ω²), with the pads evaluated
/// within the step (`contact_exponential`, RK4), 0.1 s into the ramp. The
/// spin terms move it by (Ω/ω)² ≤ 2e-7. (Both integrators recompute the
/// node loads at each evaluation, which once dropped the Euler force.)
#[test]
fn the_euler_force_twists_the_disc_under_a_commanded_ramp_with_pads_in_the_step() {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/config/brake_in_plane.yaml");
    let mut config = Config::from_params_file(std::path::Path::new(path), "annular_plate").unwrap();
    config
        .section_mut::<PadsConfig>()
        .unwrap()
        .friction_coefficient = 0.0;
    for integrator in [IntegratorKind::ContactExponential, IntegratorKind::Rk4] {
        let mut c = config.clone();
        c.simulation.integrator = integrator;
        let mut sim = Simulation::new(c).unwrap();
        sim.set_speed_command(5.0).unwrap();
        for _ in 0..100 {
            sim.step().unwrap();
        }
        let ip = sim.scene().in_plane.as_ref().unwrap();
        let j = ip.torsional[0];
        let m = &ip.modes[j];
        let alpha = sim.state().acceleration;
        let expected = -m.coupling * alpha / (m.modal_mass * m.omega * m.omega);
        let got = sim.q_ale()[ip.offset + j];
        let error = (got / expected - 1.0).abs();
        println!(
            "{integrator:?}: α = {alpha} rad/s², torsional q = {got:.6e} m, −sα/(mω²) = {expected:.6e} m: {error:.2e}"
        );
        assert!((alpha + 50.0).abs() < 1e-9, "{alpha}");
        assert!(error < 1e-5, "{integrator:?}: {error:e}");
    }
}
