//! Pad friction on the faces (`pads.contact_surface: faces`, docs/scenes.md
//! "Friction on the faces"): one contact, one mode pair — the squeal threshold
//! against the Routh–Hurwitz condition of the pair's quartic written out here
//! from the equations of motion; the eigenvalue analysis and the simulation
//! agree on growth rates; the two descriptions agree to round-off.

use annular_plate::config::Config;
use annular_plate::dynamics::load_models::pad_config::{ContactSurface, PadsConfig};
use annular_plate::dynamics::{stability, Simulation};
use annular_plate::model::AngularShape;

mod support;
use support::fourth_order::{assert_fourth_order, descriptions_differ};
use support::left_growth::{left_eigenvector_growth, PadLayout};
use support::one_contact::{self, CLAMP, SPEED, STIFFNESS};
use support::pair_quartic::{hurwitz, threshold, PairTerms};

/// The one-contact disc (`support::one_contact`), rigid lining.
fn scene(surface: ContactSurface, mu: f64) -> Config {
    one_contact::scene(surface, mu, None)
}

/// The quartic λ⁴ + a₁λ³ + a₂λ² + a₃λ + a₄ of the pair under the contact at
/// θ = 0 (mass-normalised, ALE amplitudes q_c, q_s; R, R′ the radial shape and
/// its slope at r; m, ω, ζ the pair's modal mass, frequency, damping; p = N₀ the
/// preload per face; V = Ωr):
///
///   q̈_c + (d₀ + β) q̇_c + G q̇_s + (K₀ + κ) q_c + (s + φ + βkΩρ) q_s = 0
///   q̈_s + d₀ q̇_s − G q̇_c + K₀ q_s − (s + χ) q_c = 0
///
/// K₀ = ω² − k²Ω², d₀ = 2ζω, s = 2ζωkΩ, G = 2kΩ (the ALE pair, docs/dynamics.md);
/// κ = 2k_c R²/m the two faces' springs (w_c = R, w_s = 0 at θ = 0);
/// φ = 2μp kR²/(r m) the follower (normal) friction on the cos mode from ∂w/∂θ = kR q_s;
/// χ = μ h k_c kR²/(r m) the faces' couple: N_t − N_b = 2k_c R q_c at lever h/2
///   acting on ∂_θ w_s / r = kR/r;
/// β = (h²/2) μ p R′²/(V m) the sliding direction: the faces' radial velocity
///   v_r = ∓(h/2) (D(∂_r w)/Dt − Ω ∂_θ w / r) (the face point's in-plane
///   displacement turns with the plate), D(∂_r w)/Dt = R′(q̇_c + kΩ q_s) and
///   ∂_θ w / r = kR q_s / r, so v_r = ∓(h/2) R′(q̇_c + kΩρ q_s) with
///   ρ = 1 − R/(rR′), turns the friction ±μp δv_r/V.
///
/// With the speed-dependent μ(v) = μ + Δμ e^(−v/v_S) (`stribeck` = (Δμ, v_S)),
/// μ in φ, χ, β is μ(V), and the faces' tangential velocity
/// v_θ = ∓(h/2)(D(∂_θ w / r)/Dt + Ω ∂_r w) = ∓(h/2)(kR/r)(q̇_s − kΩσ q_c),
/// σ = 1 − rR′/(k²R), changes their friction by ∓μ′ p δv_θ at lever ±h/2 on
/// ∂_θ w_s / r: γ = (h²/2) p μ′(V) k²R²/(r² m) adds γ q̇_s − γkΩσ q_c to the
/// q_s equation.
fn quartic(mu: f64, face: bool) -> [f64; 4] {
    quartic_with(mu, face, (0.0, 1.0))
}

fn quartic_with(mu: f64, face: bool, stribeck: (f64, f64)) -> [f64; 4] {
    let sim = Simulation::new(scene(ContactSurface::Faces, mu)).unwrap();
    let model = sim.model();
    let node = &sim.scene().ale_nodes[0];
    let r = node.radius;
    let cos = model
        .modes()
        .iter()
        .position(|m| m.shape == AngularShape::Cos)
        .unwrap();
    let mode = &model.modes()[cos];
    let (rr, rr_slope) = (
        model.radial_shapes()[mode.radial].eval(r)[0],
        model.radial_shapes()[mode.radial].eval(r)[1],
    );
    let (k, m, w, z) = (mode.k as f64, mode.modal_mass, mode.omega, mode.damping);
    let h = 0.0181;
    let p = CLAMP;
    let k0 = w * w - k * k * SPEED * SPEED;
    let d0 = 2.0 * z * w;
    let s = 2.0 * z * w * k * SPEED;
    let g = 2.0 * k * SPEED;
    let v = SPEED * r;
    let (excess, vs) = stribeck;
    let mu_slope = -excess / vs * (-v / vs).exp();
    let mu = mu + excess * (-v / vs).exp();
    let gamma = 0.5 * h * h * p * mu_slope * k * k * rr * rr / (r * r * m);
    let kappa = 2.0 * STIFFNESS * rr * rr / m;
    let phi = 2.0 * mu * p * k * rr * rr / (r * m);
    let (chi, beta) = if face {
        (
            mu * h * STIFFNESS * k * rr * rr / (r * m),
            0.5 * h * h * mu * p * rr_slope * rr_slope / (SPEED * r * m),
        )
    } else {
        (0.0, 0.0)
    };
    // The polar basis' rotation under the face point (docs/scenes.md).
    let rho = 1.0 - rr / (r * rr_slope);
    let sigma = 1.0 - r * rr_slope / (k * k * rr);
    PairTerms {
        k0,
        kappa,
        d0,
        beta,
        gamma,
        g,
        a: s + phi + beta * k * SPEED * rho,
        b: s + chi + gamma * k * SPEED * sigma,
    }
    .quartic()
}

fn closed_form_threshold(face: bool) -> f64 {
    closed_form_threshold_with(face, (0.0, 1.0))
}

fn closed_form_threshold_with(face: bool, stribeck: (f64, f64)) -> f64 {
    threshold(2.0, |mu| quartic_with(mu, face, stribeck))
}

#[test]
fn one_contact_one_pair_threshold_matches_the_routh_hurwitz_closed_form() {
    let sim = Simulation::new(scene(ContactSurface::Faces, 0.0)).unwrap();
    let eig = stability::friction_threshold(sim.scene(), SPEED, 2.0)
        .expect("squeals below μ = 2 with face friction");
    let closed = closed_form_threshold(true);
    println!("faces: threshold μ_c eigenvalues {eig:.9}, Routh–Hurwitz {closed:.9}");
    assert!((eig - closed).abs() < 1e-6 * closed, "{eig} vs {closed}");
    // Without the face terms (the mid-plane model) the same quartic with χ = β = 0.
    let mid = Simulation::new(scene(ContactSurface::MidPlane, 0.0)).unwrap();
    let eig_mid = stability::friction_threshold(mid.scene(), SPEED, 2.0);
    let closed_mid = (hurwitz(quartic(2.0, false)) < 0.0).then(|| closed_form_threshold(false));
    println!("mid-plane: threshold eigenvalues {eig_mid:?}, Routh–Hurwitz {closed_mid:?}");
    match (eig_mid, closed_mid) {
        (Some(e), Some(c)) => assert!((e - c).abs() < 1e-6 * c && c > 2.0 * closed),
        (None, None) => {}
        other => panic!("mid-plane thresholds disagree: {other:?}"),
    }
}

/// Re λ of the critical mode measured in a simulation started on it: the
/// critical mode's coordinate c(t) = u_Lᵀ y(t) (u_L its left eigenvector) is
/// ½ (u_Lᵀ v) e^{λt} for the linear system, so ln|c| has slope Re λ
/// (`support::left_growth`).
fn simulated_growth_rate(mu: f64) -> (f64, f64) {
    simulated_growth_rate_of(scene(ContactSurface::Faces, mu))
}

fn simulated_growth_rate_of(c: Config) -> (f64, f64) {
    left_eigenvector_growth(c, PadLayout::Rigid, 1000)
}

#[test]
fn eigenvalues_and_simulation_agree_on_growth_rates_with_face_friction() {
    let sim = Simulation::new(scene(ContactSurface::Faces, 0.0)).unwrap();
    let mu_c = stability::friction_threshold(sim.scene(), SPEED, 2.0).unwrap();
    for factor in [0.7, 1.5] {
        let (rate, slope) = simulated_growth_rate(factor * mu_c);
        println!("μ = {factor} μ_c: Re λ = {rate:.6} 1/s, simulated {slope:.6} 1/s");
        assert_eq!(rate > 0.0, factor > 1.0);
        assert_eq!(slope > 0.0, factor > 1.0);
        assert!(
            (slope - rate).abs() < 0.02 * rate.abs(),
            "simulated {slope} vs eigenvalue {rate}"
        );
    }
}

/// RK4 integrates each description's own ODE (in ALE coordinates the pair
/// equations with the gyroscopic terms; in Lagrangian ones the uncoupled modes
/// with the pad evaluated at the ALE amplitudes derived at every stage):
/// independent discretisations that must converge to one motion at fourth order.
#[test]
fn ale_and_lagrangian_descriptions_converge_to_one_motion_with_face_friction() {
    let mu = 1.5 * closed_form_threshold(true);
    let config = scene(ContactSurface::Faces, mu);
    // Measured: 1.06e-3, 6.9e-5, 4.3e-6, 2.7e-7 (ratio ≈ 16).
    let last = assert_fourth_order(
        "face friction, rk4 ALE vs Lagrangian",
        &[20_000.0, 40_000.0, 80_000.0, 160_000.0],
        // the rate sets RK4's step (h ω ≤ 0.45)
        |rate| descriptions_differ(&config, rate, 0.5, |_, _| {}),
    );
    assert!(last < 5e-7);
}

/// The paper's squeal scene, config/brake_squeal_paper.yaml (18 contacts on a ring, floating caliper) with the
/// friction on the faces. Per ⟨k, l⟩ pair in the complex amplitude, as for the
/// mid-plane ring (tests/scene_brake_squeal_paper.rs) with N₀ the clamp force, n the
/// contacts, R, R′ the radial shape and slope at r, V = Ωr: the follower and
/// the faces' couple are both circulatory, σ = μ k R² (N₀ + h k_c n/2)/r; the
/// sliding direction adds the damping D = μ (h²/4) N₀ R′²/V on the material
/// rate D(∂_r w)/Dt, whose Ω ∂_θ part is circulatory too and cancels the
/// damping's i D kΩ in the ALE frame; the polar basis' rotation, −Ω ∂_θ w / r
/// in the radial velocity, is circulatory and opposes σ by
/// μ (h²/4) N₀ k R R′/r². The root crosses at σ = (2ζωm + D) ω_p:
///   μ_c = 2ζω m ω_p / (k R² (N₀ + h k_c n/2)/r − (h²/4) N₀ k R R′/r²
///         − (h²/4) N₀ R′² ω_p / V).
#[test]
fn the_ring_of_pads_threshold_with_face_friction_matches_its_closed_form() {
    let mut c = support::scene_files::load("brake_squeal_paper.yaml");
    c.section_mut::<PadsConfig>().unwrap().contact_surface = ContactSurface::Faces;
    let sim = Simulation::new(c.clone()).unwrap();
    let model = sim.model();
    let pads = c.section::<PadsConfig>().unwrap();
    let (n, clamp, kc, h) = (
        pads.contacts.len() as f64,
        pads.clamp_force[0],
        pads.contact_stiffness,
        c.plate.thickness,
    );
    let r = sim.scene().ale_nodes[0].radius;
    let speed = c.joint.speed;
    let mut closed = f64::INFINITY;
    let mut without_direction = f64::INFINITY;
    for m in model
        .modes()
        .iter()
        .filter(|m| m.shape == AngularShape::Cos)
    {
        let [rr, slope, ..] = model.radial_shapes()[m.radial].eval(r);
        let k = m.k as f64;
        let omega_p = (m.omega * m.omega + kc * n * rr * rr / m.modal_mass).sqrt();
        let circulatory = k * rr * rr * (clamp + 0.5 * h * kc * n) / r
            - 0.25 * h * h * clamp * k * rr * slope / (r * r);
        let direction = 0.25 * h * h * clamp * slope * slope * omega_p / (speed * r);
        let mu = 2.0 * m.damping * m.omega * m.modal_mass * omega_p / (circulatory - direction);
        println!(
            "⟨k = {}⟩: closed-form μ_c = {mu:.9} ({:.9} without the sliding direction)",
            m.k,
            2.0 * m.damping * m.omega * m.modal_mass * omega_p / circulatory
        );
        closed = closed.min(mu);
        without_direction =
            without_direction.min(2.0 * m.damping * m.omega * m.modal_mass * omega_p / circulatory);
    }
    let eig =
        stability::friction_threshold(sim.scene(), speed, 0.05).expect("squeals below μ = 0.05");
    println!("ring with face friction: threshold eigenvalues {eig:.9}, closed form {closed:.9}");
    assert!((eig - closed).abs() < 1e-6 * closed, "{eig} vs {closed}");
    // The faces' couple lowers the paper's 0.300423 about 110-fold.
    assert!(0.300423 / eig > 80.0 && 0.300423 / eig < 120.0 && without_direction < closed);
}

/// A friction coefficient falling with the sliding speed feeds the vibration
/// (negative damping through the faces' tangential velocity): with
/// μ(v) = μ + 0.2 e^(−v/v_S), v_S = 2 m/s, the threshold in μ matches the
/// quartic with the μ′ terms, and lies below the constant-μ one.
#[test]
fn a_falling_friction_coefficient_matches_the_closed_form_and_lowers_the_threshold() {
    let (excess, vs) = (0.2, 2.0);
    let mut c = scene(ContactSurface::Faces, 0.0);
    let pads = c.section_mut::<PadsConfig>().unwrap();
    pads.static_friction_coefficient = Some(excess);
    pads.stribeck_speed = vs;
    let sim = Simulation::new(c).unwrap();
    // μ_s − μ is kept at Δμ while the threshold scans μ: friction_threshold
    // scans the scene's μ with the law's excess fixed (static − configured μ = 0.2 − 0).
    let eig = stability::friction_threshold(sim.scene(), SPEED, 2.0).expect("squeals");
    let closed = closed_form_threshold_with(true, (excess, vs));
    let constant = closed_form_threshold(true);
    println!(
        "μ(v): threshold eigenvalues {eig:.9}, closed form {closed:.9}; constant μ {constant:.9}"
    );
    assert!((eig - closed).abs() < 1e-6 * closed, "{eig} vs {closed}");
    assert!(closed < constant);
    // The μ′ term itself matters (not only μ(V) > μ): without it the quartic's threshold differs.
    let v = SPEED * sim.scene().ale_nodes[0].radius;
    let mu_at_v_only = closed_form_threshold(true) - excess * (-v / vs).exp();
    assert!(
        (closed - mu_at_v_only).abs() > 1e-3 * closed,
        "{closed} vs {mu_at_v_only}"
    );
    // The simulation (the nonlinear law at every RK4 stage) grows at the eigenvalue's rate.
    for factor in [0.7, 1.5] {
        let mut c = scene(ContactSurface::Faces, factor * eig);
        let pads = c.section_mut::<PadsConfig>().unwrap();
        pads.static_friction_coefficient = Some(factor * eig + excess);
        pads.stribeck_speed = vs;
        let (rate, slope) = simulated_growth_rate_of(c);
        println!("μ(v), μ = {factor} μ_c: Re λ = {rate:.6} 1/s, simulated {slope:.6} 1/s");
        assert_eq!((rate > 0.0, slope > 0.0), (factor > 1.0, factor > 1.0));
        assert!(
            (slope - rate).abs() < 0.02 * rate.abs(),
            "simulated {slope} vs eigenvalue {rate}"
        );
    }
}

#[test]
fn face_friction_keys_are_read_and_a_speed_law_without_faces_is_refused_naming_the_keys() {
    let file = |extra: &str| {
        format!(
            "annular_plate:\n  ros__parameters:\n    nodes:\n      ale_radial: [0.6]\n      ale_angular: [0.0]\n    pads:\n      ale_nodes: [1]\n{extra}"
        )
    };
    let c = Config::from_yaml_str(&file("      contact_surface: faces\n      static_friction_coefficient: 0.5\n      stribeck_speed: 2.0\n"), "annular_plate").unwrap();
    let p = c.section::<PadsConfig>().cloned().unwrap();
    assert_eq!(
        (
            p.contact_surface,
            p.static_friction_coefficient,
            p.stribeck_speed
        ),
        (ContactSurface::Faces, Some(0.5), 2.0)
    );
    let c = Config::from_yaml_str(&file(""), "annular_plate").unwrap();
    // `faces` is the default; `mid_plane` reproduces the paper.
    assert_eq!(
        (
            c.section::<PadsConfig>().unwrap().contact_surface,
            c.section::<PadsConfig>()
                .unwrap()
                .static_friction_coefficient
        ),
        (ContactSurface::Faces, None)
    );
    let e = Config::from_yaml_str(
        &file("      contact_surface: mid_plane\n      static_friction_coefficient: 0.5\n"),
        "annular_plate",
    )
    .unwrap_err()
    .to_string();
    assert!(
        e.contains("pads.static_friction_coefficient") && e.contains("pads.contact_surface"),
        "{e}"
    );
    let e = Config::from_yaml_str(&file("      contact_surface: rim\n"), "annular_plate")
        .unwrap_err()
        .to_string();
    assert!(
        e.contains("pads.contact_surface") && e.contains("rim"),
        "{e}"
    );
    let e = Config::from_yaml_str(
        &file("      contact_surface: faces\n      stribeck_speed: 0.0\n"),
        "annular_plate",
    )
    .unwrap_err()
    .to_string();
    assert!(e.contains("pads.stribeck_speed"), "{e}");
}
