//! Mindlin modes in the dynamics (`plate.theory: mindlin`, docs/mindlin.md):
//! the simulated free vibration and the ALE travelling waves of the bench
//! disc against the exact Mindlin roots (`tests/support/mindlin_exact.rs`);
//! node frames turned by ψ under a static force and moments against a modal
//! sum of the exact Mindlin mode shapes; the rotary inertia of the k = 1
//! modes in the reference-frame terms against d'Alembert forces integrated
//! through the thickness here; a point damper's decay rate from the exact
//! mode shape; ALE and Lagrangian agree; the thin limit is Kirchhoff's; the
//! keys whose terms are Kirchhoff's are refused by name.

mod support;

use annular_plate::config::{
    Boundary, Config, Coordinates, IntegratorKind, NodePosition, PlateTheory, Surface, WrenchConfig,
};
use annular_plate::dynamics::Simulation;
use annular_plate::model::PlateModel;
use nalgebra::{Complex, Vector3};
use support::cli::run;
use support::fit::peak_near;
use support::fourth_order::{assert_fourth_order, descriptions_differ};
use support::mindlin_exact::{Edge, MindlinAnnulus};
use support::scenes::*;

const BENCH: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/config/brake_bench.yaml");
const DESIGN: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/config/design_example.yaml");

/// The bench disc (steel, r_i = 0.07 m, r_a = 0.153 m, hard support inside,
/// free outside) `thickness` thick under Mindlin theory, without residual
/// flexibility, undamped, with the ⟨k, l⟩ asked for.
fn disc(thickness: f64, ks: Vec<u32>, ls: Vec<u32>) -> Config {
    let mut c = Config::default();
    c.plate.inner_radius = 0.07;
    c.plate.outer_radius = 0.153;
    c.plate.thickness = thickness;
    c.plate.youngs_modulus = 2.1e11;
    c.plate.poisson_ratio = 0.3;
    c.plate.density = 7850.0;
    c.plate.inner_boundary = Boundary::Supported;
    c.plate.outer_boundary = Boundary::Free;
    c.plate.nodal_diameters = ks;
    c.plate.nodal_circles = ls;
    c.plate.damping = vec![0.0];
    c.plate.theory = PlateTheory::Mindlin;
    c.plate.residual_flexibility = false;
    c.simulation.realtime_factor = 0.0;
    c
}

/// The same disc for the exact solution, written out.
fn exact(thickness: f64) -> MindlinAnnulus {
    MindlinAnnulus {
        youngs_modulus: 2.1e11,
        poisson_ratio: 0.3,
        density: 7850.0,
        thickness,
        shear_correction: 5.0 / 6.0,
        inner_radius: 0.07,
        outer_radius: 0.153,
        inner: Edge::Supported,
        outer: Edge::Free,
    }
}

/// A node at (ξ_r, ξ_θ) holding `force`, `moment`.
fn node(
    radial: f64,
    angular: f64,
    force: [f64; 3],
    moment: [f64; 3],
) -> (NodePosition, WrenchConfig) {
    (
        NodePosition { radial, angular },
        WrenchConfig { force, moment },
    )
}

/// z = q̄_cos + i q̄_sin of the scene's one pair after each of `steps` steps,
/// from the amplitudes `q` and rates `q_dot` in the scene's own coordinates
/// (`simulation.coordinates`) at χ = 0.
fn pair_history(c: Config, q: [f64; 2], q_dot: [f64; 2], steps: usize) -> (Vec<Complex<f64>>, f64) {
    let mut sim = Simulation::new(c).expect("a Mindlin scene without pads");
    let mut state = sim.state().clone();
    state.q[..2].copy_from_slice(&q);
    state.q_dot[..2].copy_from_slice(&q_dot);
    state.rederive(sim.scene());
    sim.restore(state);
    let dt = sim.dt();
    let mut z = Vec::with_capacity(steps);
    for _ in 0..steps {
        sim.step().unwrap();
        z.push(Complex::new(sim.q_ale()[0], sim.q_ale()[1]));
    }
    (z, dt)
}

#[test]
fn a_free_mindlin_wave_runs_at_the_exact_mindlin_frequency() {
    let h = 0.0181;
    for (k, l) in [(1, 0), (2, 0), (4, 0), (1, 1)] {
        let omega_exact = exact(h).roots(k, l as usize + 1, 64)[l as usize];
        let c = integrated(
            disc(h, vec![k], vec![l]),
            IntegratorKind::Exponential,
            Coordinates::Lagrangian,
            40_000.0,
        );
        let omega_model = PlateModel::new(&c.plate).unwrap().modes()[0].omega;
        let mut kirchhoff = c.plate.clone();
        kirchhoff.theory = PlateTheory::Kirchhoff;
        let omega_kirchhoff = PlateModel::new(&kirchhoff).unwrap().modes()[0].omega;
        // A forward travelling wave: q = a (cos ωt, sin ωt).
        let a = 1e-6;
        let (z, dt) = pair_history(c, [a, 0.0], [0.0, a * omega_model], 8000);
        let got = peak_near(&z, dt, omega_exact, 0.01 * omega_exact);
        let err = (got - omega_exact).abs() / omega_exact;
        println!(
            "⟨{k}, {l}⟩: simulated {got:.6} rad/s, exact Mindlin {omega_exact:.6}, error {err:.1e}; Kirchhoff {omega_kirchhoff:.3} ({:+.2} %)",
            100.0 * (omega_kirchhoff / omega_exact - 1.0)
        );
        assert!(err < 1e-6, "⟨{k}, {l}⟩: {err:e}");
        // The thick disc tells the theories apart (Kirchhoff is ≥ 1 % off here).
        assert!((omega_kirchhoff - omega_exact).abs() > 1e-2 * omega_exact);
    }
}

#[test]
fn at_speed_the_ale_frequencies_of_a_mindlin_pair_split_into_omega_plus_and_minus_k_omega() {
    let h = 0.0181;
    let omega = exact(h).roots(2, 1, 64)[0];
    {
        // What the model leaves out (docs/mindlin.md): the spin's Coriolis force
        // on the face displacement z ψ, a gyroscopic coupling of the pair
        // g = 2ρh³/12 π ∫ Ψ_r Ψ_θ r dr that would move the split by ±gΩ/(2m),
        // a fraction g/(2km) of kΩ.
        let c = disc(h, vec![2], vec![0]);
        let model = PlateModel::new(&c.plate).unwrap();
        let (m, mode) = (&model.modes()[0], model.mindlin_mode(0).unwrap());
        let (a, b, n) = (c.plate.inner_radius, c.plate.outer_radius, 4000);
        let integral: f64 = (0..n)
            .map(|j| {
                let r = a + (b - a) * (j as f64 + 0.5) / n as f64;
                let v = mode.eval(r);
                v.psi_r * v.psi_theta * r * (b - a) / n as f64
            })
            .sum();
        let g = 2.0 * c.plate.density * h.powi(3) / 12.0 * std::f64::consts::PI * integral;
        println!(
            "left out: g/(2km) = {:.2e} for ⟨2, 0⟩",
            g / (2.0 * 2.0 * m.modal_mass)
        );
    }
    for speed in [500.0, 2000.0, 4000.0] {
        let mut c = integrated(
            disc(h, vec![2], vec![0]),
            IntegratorKind::Exponential,
            Coordinates::Ale,
            40_000.0,
        );
        c.joint.speed = speed;
        // q̄ = (a, 0), q̄̇ = 0: both travelling waves at once.
        let (z, dt) = pair_history(c, [1e-6, 0.0], [0.0; 2], 8000);
        let k_omega = 2.0 * speed;
        let forward = peak_near(&z, dt, omega + k_omega, 0.01 * omega);
        let backward = peak_near(&z, dt, -(omega - k_omega), 0.01 * omega);
        let e_f = (forward - (omega + k_omega)).abs() / omega;
        let e_b = (backward + (omega - k_omega)).abs() / omega;
        println!(
            "Ω = {speed}: exact ω = {omega:.4}; forward {forward:.4} (ω + 2Ω, error {e_f:.1e}), backward {backward:.4} (−(ω − 2Ω), error {e_b:.1e})"
        );
        assert!(e_f < 1e-6 && e_b < 1e-6, "Ω = {speed}");
    }
}

/// ∂W/∂r of an exact mode by central differences (Kirchhoff's Ψ_r would be −∂W/∂r).
fn exact_slope(mode: &support::mindlin_exact::ExactMode, r: f64) -> f64 {
    let e = 1e-6;
    (mode.fields(r + e).w - mode.fields(r - e).w) / (2.0 * e)
}

/// The static w, θ_x, θ_y at (r, φ = 0) under F_z, M_x, M_y there, summed
/// over the exact Mindlin modes ⟨k, l < l_count⟩ of the bench disc: cos
/// modes carry w = W and θ_y = ψ_x = Ψ_r, sin modes θ_x = −ψ_y = Ψ_θ, each
/// mode's amplitude f_i / (m_i ω_i²). Also θ_y with the slope −∂w/∂r in
/// place of Ψ_r (what Kirchhoff's node frames would use).
fn exact_static(h: f64, ks: &[u32], l_count: usize, r: f64, f_z: f64, m: [f64; 2]) -> [f64; 4] {
    let annulus = exact(h);
    let mut out = [0.0; 4];
    for &k in ks {
        for omega in annulus.roots(k, l_count, 64) {
            let mode = annulus.mode(k, omega);
            let stiffness = mode.modal_mass(400) * omega * omega;
            let f = mode.fields(r);
            let slope = -exact_slope(&mode, r);
            out[0] += f.w * (f.w * f_z + f.psi_r * m[1]) / stiffness;
            out[2] += f.psi_r * (f.w * f_z + f.psi_r * m[1]) / stiffness;
            out[3] += slope * (f.w * f_z + slope * m[1]) / stiffness;
            if k > 0 {
                out[1] += f.psi_theta * f.psi_theta * m[0] / stiffness;
            }
        }
    }
    out
}

/// The bench disc (k ≤ 4, l ≤ 1), heavily damped, with one ALE node at
/// (ξ_r = 0.6, φ = 0) on `surface` holding `force`, `moment`, settled: its
/// radius and the node's output.
fn settled_node(
    surface: Surface,
    force: [f64; 3],
    moment: [f64; 3],
) -> (f64, annular_plate::dynamics::NodeOutput) {
    let mut c = integrated(
        disc(0.0181, vec![0, 1, 2, 3, 4], vec![0, 1]),
        IntegratorKind::Exponential,
        Coordinates::Lagrangian,
        1000.0,
    );
    c.plate.damping = vec![0.7];
    let (p, w) = node(0.6, 0.0, force, moment);
    c.nodes.ale.push(p);
    c.loads.ale.push(w);
    c.nodes.ale_surface = vec![surface];
    let r = c.plate.inner_radius + 0.6 * (c.plate.outer_radius - c.plate.inner_radius);
    let mut sim = Simulation::new(c).unwrap();
    for _ in 0..200 {
        sim.step().unwrap();
    }
    (r, sim.ale_node(0))
}

#[test]
fn a_static_force_and_moments_at_a_node_deflect_and_turn_it_by_the_exact_mindlin_modal_sum() {
    let (force, moment) = (-500.0, [40.0, 60.0, 0.0]);
    let (r, out) = settled_node(Surface::Mid, [0.0, 0.0, force], moment);
    let [w_z, theta_x, theta_y, theta_y_slope] = exact_static(
        0.0181,
        &[0, 1, 2, 3, 4],
        2,
        r,
        force,
        [moment[0], moment[1]],
    );
    let errors = [
        (out.uz - w_z).abs() / w_z.abs(),
        (out.tilt[0] - theta_x).abs() / theta_x.abs(),
        (out.tilt[1] - theta_y).abs() / theta_y.abs(),
    ];
    println!(
        "w = {:e} m (exact sum {w_z:e}), θ_x = {:e} ({theta_x:e}), θ_y = {:e} ({theta_y:e}; with −∂w/∂r {theta_y_slope:e}); relative errors {errors:?}",
        out.uz, out.tilt[0], out.tilt[1]
    );
    assert!(errors.iter().all(|&e| e < 1e-6), "{errors:?}");
    // Not vacuous: the slope −∂w/∂r, which Kirchhoff's node frames use, is
    // measurably not the rotation ψ of the thick disc.
    assert!((theta_y_slope - theta_y).abs() > 1e-3 * theta_y.abs());
}

#[test]
fn an_in_plane_force_on_a_face_moves_the_face_point_by_z_psi_of_the_exact_modal_sum() {
    // On the top face (z = h/2) an in-plane force F_t acts through the face
    // displacement z ψ: the couple z e_z × F_t = (−z F_y, z F_x) on ψ.
    let (h, force) = (0.0181, [300.0, -200.0, -100.0]);
    let z = 0.5 * h;
    let (r, out) = settled_node(Surface::Top, force, [0.0; 3]);
    let [w_z, theta_x, theta_y, _] = exact_static(
        h,
        &[0, 1, 2, 3, 4],
        2,
        r,
        force[2],
        [-z * force[1], z * force[0]],
    );
    // The face point: (r + z ψ_x, z ψ_y, z + w) with ψ = (θ_y, −θ_x).
    let expected = [r + z * theta_y, -z * theta_x, z + w_z];
    let got = out.pose.translation;
    let moved = [z * theta_y, -z * theta_x, w_z];
    let errors: Vec<f64> = (0..3)
        .map(|a| (got[a] - expected[a]).abs() / moved[a].abs())
        .collect();
    println!("face point {got:?}, exact {expected:?}: errors of the displacement {errors:?}");
    assert!(errors.iter().all(|&e| e < 1e-6), "{errors:?}");
}

/// ∫∫ f(r, θ) r dr dθ over the plate (Gauss–Legendre × trapezoid).
fn integrate(c: &Config, f: impl Fn(f64, f64) -> f64) -> f64 {
    support::quadrature::annulus(c.plate.inner_radius, c.plate.outer_radius, 40, 48, f)
}

#[test]
fn a_frame_turning_about_a_skew_axis_loads_mindlin_modes_by_their_dalembert_forces_through_the_thickness(
) {
    let w = Vector3::new(300.0, -200.0, 150.0);
    let g = Vector3::new(0.0, 0.0, -9.81);
    let mut c = integrated(
        disc(0.0181, vec![0, 1, 2], vec![0]),
        IntegratorKind::Exponential,
        Coordinates::Lagrangian,
        1000.0,
    );
    c.plate.damping = vec![0.5];
    c.reference.angular_velocity = [w.x, w.y, w.z];
    c.gravity = [g.x, g.y, g.z];
    let (rho, h) = (c.plate.density, c.plate.thickness);
    let mut sim = Simulation::new(c.clone()).unwrap();
    for _ in 0..200 {
        sim.step().unwrap();
    }
    let model = sim.model();
    let scale = sim.q_lagrange().iter().fold(0.0f64, |a, q| a.max(q.abs()));
    // Two Gauss points through the thickness integrate the z² terms exactly.
    let zs = [-h / (2.0 * 3f64.sqrt()), h / (2.0 * 3f64.sqrt())];
    for (i, m) in model.modes().iter().enumerate() {
        let mode = model.mindlin_mode(m.radial).expect("Mindlin modes");
        // −∫ ρ Φ_i · (a − g) dV, Φ_i = (z ψ_x, z ψ_y, w) at p = (x, y, z),
        // a = ω × (ω × p); and the share of the face displacement z ψ alone.
        let dalembert = |rotary_only: bool| {
            integrate(&c, |r, th| {
                let f = mode.field(m.shape, r, th);
                let (s, co) = th.sin_cos();
                let psi = Vector3::new(
                    co * f.psi_r - s * f.psi_theta,
                    s * f.psi_r + co * f.psi_theta,
                    0.0,
                );
                zs.iter()
                    .map(|&z| {
                        let p = Vector3::new(r * co, r * s, z);
                        let a = w.cross(&w.cross(&p)) - g;
                        let inplane = z * psi.dot(&a);
                        let transverse = if rotary_only { 0.0 } else { f.w * a.z };
                        -rho * 0.5 * h * (inplane + transverse)
                    })
                    .sum()
            })
        };
        let k_eff = m.modal_mass * (m.omega.powi(2) - (w.x * w.x + w.y * w.y));
        let (expected, rotary) = (dalembert(false) / k_eff, dalembert(true) / k_eff);
        let got = sim.q_lagrange()[i];
        println!(
            "mode {i} ⟨{}, {}⟩ {:?}: q = {got:e}, d'Alembert {expected:e} (of it the rotary inertia {rotary:e})",
            m.k, m.l, m.shape
        );
        assert!((got - expected).abs() < 1e-9 * scale, "mode {i}");
        if m.k == 1 {
            // Not vacuous: the rotary inertia's share is far above the bound.
            assert!(rotary.abs() > 1e-6 * scale, "mode {i}: {rotary:e}");
        }
    }
}

#[test]
fn the_body_data_of_mindlin_modes_hold_the_rotary_inertia_in_c_r_and_j1() {
    let c = disc(0.0181, vec![0, 1, 2], vec![0, 1]);
    let model = PlateModel::new(&c.plate).unwrap();
    let body = model.body();
    let (rho, h) = (c.plate.density, c.plate.thickness);
    let zs = [-h / (2.0 * 3f64.sqrt()), h / (2.0 * 3f64.sqrt())];
    let mut rotary_seen = 0.0f64;
    // kg·m: the largest first moment (the k = 1 modes').
    let scale = body
        .first_moments
        .iter()
        .flatten()
        .fold(0.0f64, |a, v| a.max(v.abs()));
    for (i, m) in model.modes().iter().enumerate() {
        let mode = model.mindlin_mode(m.radial).unwrap();
        // ∫ over the volume of g(c, Φ_i) ρ dV, Φ_i = (z ψ_x, z ψ_y, w) at c = (x, y, z).
        let volume = |g: &dyn Fn(Vector3<f64>, Vector3<f64>) -> f64| {
            integrate(&c, |r, th| {
                let f = mode.field(m.shape, r, th);
                let (s, co) = th.sin_cos();
                let (px, py) = (
                    co * f.psi_r - s * f.psi_theta,
                    s * f.psi_r + co * f.psi_theta,
                );
                zs.iter()
                    .map(|&z| {
                        let (point, phi) = (
                            Vector3::new(r * co, r * s, z),
                            Vector3::new(z * px, z * py, f.w),
                        );
                        rho * 0.5 * h * g(point, phi)
                    })
                    .sum()
            })
        };
        let coupling = body.rotational_coupling(i);
        let mut unit = vec![0.0; model.n_modes()];
        unit[i] = 1.0;
        let j = body.inertia_at(&unit);
        for a in 0..3 {
            let cr = volume(&|p, u| p.cross(&u)[a]);
            assert!(
                (coupling[a] - cr).abs() < 1e-9 * scale,
                "C_r mode {i}, {a}: {} vs {cr}",
                coupling[a]
            );
            for b in 0..3 {
                // J₁ = ∫ (2 c·u δ_ab − c_a u_b − u_a c_b) dm
                let j1 = volume(&|p, u| {
                    let delta = if a == b { 2.0 * p.dot(&u) } else { 0.0 };
                    delta - p[a] * u[b] - u[a] * p[b]
                });
                let got = j[a][b] - body.inertia[a][b];
                assert!(
                    (got - j1).abs() < 1e-9 * scale,
                    "J₁ mode {i}, ({a}, {b}): {got} vs {j1}"
                );
            }
        }
        let p = body.rotary_moments[i];
        rotary_seen = rotary_seen.max(p[0].abs().max(p[1].abs()) / scale);
        println!(
            "mode {i} ⟨{}, {}⟩ {:?}: C_r = {coupling:?}, rotary moment p = {p:?}",
            m.k, m.l, m.shape
        );
    }
    // Not vacuous: the k = 1 modes' rotary moments are far above the bound.
    assert!(rotary_seen > 1e-4, "{rotary_seen:e}");
}

/// A Mindlin scene with loads and moments at an ALE and a Lagrangian node,
/// spinning in a frame that turns off-axis.
fn loaded_spinning_scene(integrator: IntegratorKind) -> Config {
    let mut c = disc(0.0181, vec![0, 1, 2], vec![0]);
    c.simulation.integrator = integrator;
    c.plate.damping = vec![0.02];
    c.joint.speed = 800.0;
    c.reference.angular_velocity = [30.0, -20.0, 10.0];
    let (p, w) = node(0.6, 0.1, [0.0, 0.0, -200.0], [15.0, -10.0, 0.0]);
    c.nodes.ale.push(p);
    c.loads.ale.push(w);
    let (p, w) = node(1.0, 0.3, [0.0, 0.0, 100.0], [-5.0, 8.0, 0.0]);
    c.nodes.lagrange.push(p);
    c.loads.lagrange.push(w);
    c
}

/// The node outputs both descriptions must agree on.
fn node_outputs(sim: &Simulation, out: &mut Vec<f64>) {
    for n in [sim.ale_node(0), sim.lagrange_node(0)] {
        out.extend_from_slice(&[n.uz, n.tilt[0], n.tilt[1]]);
    }
}

#[test]
fn ale_and_lagrangian_descriptions_of_mindlin_modes_agree() {
    let exponential = descriptions_differ(
        &loaded_spinning_scene(IntegratorKind::Exponential),
        1000.0,
        2.5,
        node_outputs,
    );
    println!("exponential, ALE vs Lagrangian: {exponential:e}");
    assert!(exponential < 1e-12, "{exponential:e}");
    let config = loaded_spinning_scene(IntegratorKind::Rk4);
    let last = assert_fourth_order(
        "Mindlin, rk4 ALE vs Lagrangian",
        &[20_000.0, 40_000.0, 80_000.0, 160_000.0],
        |rate| descriptions_differ(&config, rate, 2.5, node_outputs),
    );
    assert!(last < 1e-7, "{last:e}");
}

/// Steady ALE deflection at the rim under a rim load at speed, m.
fn steady_rim_deflection(thickness: f64, theory: PlateTheory) -> f64 {
    let mut c = integrated(
        disc(thickness, vec![0, 1, 2, 3], vec![0]),
        IntegratorKind::Exponential,
        Coordinates::Ale,
        1000.0,
    );
    c.plate.theory = theory;
    c.plate.damping = vec![0.3];
    c.joint.speed = 20.0;
    let (p, w) = node(1.0, 0.0, [0.0, 0.0, -50.0], [0.0; 3]);
    c.nodes.ale.push(p);
    c.loads.ale.push(w);
    let mut sim = Simulation::new(c).unwrap();
    for _ in 0..3000 {
        sim.step().unwrap();
    }
    sim.ale_node(0).uz
}

#[test]
fn a_thin_mindlin_plate_moves_as_the_kirchhoff_plate() {
    let mut previous: Option<f64> = None;
    for h in [0.004, 0.002, 0.001] {
        let mindlin = steady_rim_deflection(h, PlateTheory::Mindlin);
        let kirchhoff = steady_rim_deflection(h, PlateTheory::Kirchhoff);
        let d = (mindlin / kirchhoff - 1.0).abs();
        let b = 0.153 - 0.07;
        println!(
            "h/b = {:.4}: steady rim deflection Mindlin {mindlin:e}, Kirchhoff {kirchhoff:e}, relative difference {d:.2e}",
            h / b
        );
        // Mindlin's plate is the softer (shear), and the difference vanishes
        // with h at least as h/b: the free rim's boundary layer of width ~h
        // (docs/mindlin.md) makes it first order at the rim.
        let per_h = d / (h / b);
        assert!(mindlin.abs() > kirchhoff.abs() && per_h < 0.1, "{d:e}");
        if let Some(p) = previous {
            assert!(per_h < p, "{p:e} → {per_h:e}");
        }
        previous = Some(per_h);
    }
}

#[test]
fn keys_whose_terms_are_kirchhoff_s_are_refused_naming_the_key() {
    let text = std::fs::read_to_string(BENCH).unwrap();
    let mut c = Config::from_yaml_str(&text, "annular_plate").expect("bench");
    c.plate.theory = PlateTheory::Mindlin;
    let refused = |c: &Config| match Simulation::new(c.clone()) {
        Ok(_) => panic!("accepted"),
        Err(e) => e.to_string(),
    };
    // The bench scene's residual flexibility (its pads' contacts in series
    // with the load patches, tests/mindlin_residual_flexibility.rs) is taken.
    assert!(Simulation::new(c.clone()).is_ok());
    let mut follower = disc(0.0181, vec![2], vec![0]);
    follower.loads.follower = true;
    assert!(refused(&follower).contains("loads.follower"));
}

#[test]
fn simulate_and_campbell_run_a_mindlin_scene_without_pads() {
    let dir = support::cli::scratch_dir("mindlin_dynamics");
    let csv = dir.join("out.csv");
    let mindlin = [
        "-p",
        "plate.theory:=mindlin",
        "-p",
        "plate.residual_flexibility:=false",
        "-p",
        "plate.radial_splines:=auto",
    ];
    let mut args = vec![
        "simulate",
        DESIGN,
        "--duration",
        "0.05",
        "--csv",
        csv.to_str().unwrap(),
    ];
    args.extend(mindlin);
    let (ok, _, stderr) = run(&args);
    assert!(ok, "simulate: {stderr}");
    let text = std::fs::read_to_string(&csv).unwrap();
    assert!(text.lines().count() > 50 && !text.contains("NaN"));
    let mut args = vec!["campbell", DESIGN, "--json", "--speeds", "0:100:3"];
    args.extend(mindlin);
    let (ok, stdout, stderr) = run(&args);
    assert!(ok, "campbell: {stderr}");
    let mut args = vec!["modes", DESIGN, "--json"];
    args.extend(mindlin);
    let (ok, modes, stderr) = run(&args);
    assert!(ok, "modes: {stderr}");
    // At Ω = 0 the Campbell diagram's frequencies are the Mindlin modes'.
    let campbell: serde_json::Value = serde_json::from_str(&stdout).unwrap();
    let modes: serde_json::Value = serde_json::from_str(&modes).unwrap();
    println!("campbell: {}", &stdout[..stdout.len().min(400)]);
    let hz = |m: &serde_json::Value| m["frequency_hz"].as_f64().unwrap();
    let lowest_mode = modes["modes"]
        .as_array()
        .unwrap()
        .iter()
        .map(hz)
        .fold(f64::MAX, f64::min);
    let lowest_campbell = campbell["modes"]
        .as_array()
        .unwrap()
        .iter()
        .flat_map(|m| {
            m["forward_hz"]
                .as_array()
                .unwrap()
                .first()
                .and_then(|v| v.as_f64())
        })
        .fold(f64::MAX, f64::min);
    assert!(
        (lowest_campbell - lowest_mode).abs() < 1e-9 * lowest_mode,
        "{lowest_campbell} vs {lowest_mode}"
    );
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn a_point_damper_decays_a_mindlin_mode_at_the_rate_of_the_exact_mode_shape() {
    // m q̈ + K q = −c_d Φ² q̇: σ = −c_d Φ²/(2m), where Φ²/m = W(r_a)²/m is
    // free of the shape's scale — here from the exact Mindlin ⟨0, 0⟩ (with its
    // rotary inertia in m). Q = q² + ((q̇ − σq)/ω_d)² = A² e^(2σt) (as in
    // tests/point_damper_decays_a_mode_at_the_closed_form_rate.rs).
    let (h, r_a) = (0.0181, 0.153);
    let omega = exact(h).roots(0, 1, 64)[0];
    let mode = exact(h).mode(0, omega);
    let phi_sq_over_m = mode.fields(r_a).w.powi(2) / mode.modal_mass(400);
    for c_d in [50.0, 500.0] {
        let text = format!(
            "/**:
  ros__parameters:
    plate:
      theory: mindlin
      inner_radius: 0.07
      outer_radius: {r_a}
      thickness: {h}
      youngs_modulus: 2.1e11
      poisson_ratio: 0.3
      density: 7850.0
      inner_boundary: supported
      outer_boundary: free
      nodal_diameters: [0]
      nodal_circles: [0]
      damping: [0.0]
      residual_flexibility: false
    nodes:
      ale_radial: [1.0]
      ale_angular: [0.0]
    dampers:
      ale_nodes: [1]
      damping: {c_d}
    simulation:
      integrator: rk4
      rate_hz: 20000.0
      rk4_step_limit: 0.02
    initial:
      q: [1.0e-6]
"
        );
        // RK4's own decay at h·ω ≤ 0.02, (hω)⁵ ω/144 ≈ 1e-7 1/s, is far below σ.
        let config = Config::from_yaml_str(&text, "annular_plate").unwrap();
        let mut sim = Simulation::new(config).expect("dampers take Mindlin modes");
        let sigma = -c_d * phi_sq_over_m / 2.0;
        let omega_d = (omega * omega - sigma * sigma).sqrt();
        let (fitted, decayed) = support::fit::modal_decay(&mut sim, sigma, omega_d, 8000);
        let err = (fitted - sigma).abs() / sigma.abs();
        println!("c_d = {c_d}: decay rate {fitted:e} 1/s, exact Mindlin shape {sigma:e} 1/s (ζ = {:.1e}), error {err:.1e}", -sigma / omega);
        assert!(decayed > 0.5, "c_d = {c_d}: ln Q decays by {decayed} only");
        assert!(err < 1e-6, "c_d = {c_d}: {err:e}");
    }
}
