//! Brake pads on a Mindlin plate (`plate.theory: mindlin`, docs/mindlin.md
//! "Pads and stability"): the face point under a pad moves in-plane by z ψ,
//! so the faces' friction works on the rotation ψ of the normal, while the
//! contact springs and the follower friction's normal part act on w.
//! Checked against the exact Mindlin modes (`tests/support/mindlin_exact.rs`):
//! the steady deflection and twist of the bench disc under a held force and a
//! pad with friction on both faces, the virtual work of the face forces
//! written out here through the thickness; the one-contact, one-pair squeal
//! threshold against the Routh–Hurwitz condition of the pair's quartic with
//! the face couplings z Ψ at the contact radius; the simulated growth rate
//! against the eigenvalue; ALE and Lagrangian agree.

mod support;

use annular_plate::config::{Config, IntegratorKind, NodePosition, PlateTheory, WrenchConfig};
use annular_plate::dynamics::load_models::pad_config::{
    Caliper, ContactSurface, PadContact, PadsConfig,
};
use annular_plate::dynamics::{stability, Simulation};
use nalgebra::{DMatrix, DVector};
use support::fourth_order::{assert_fourth_order, descriptions_differ};
use support::left_growth::{left_eigenvector_growth, PadLayout};
use support::mindlin_exact::{ExactMode, MindlinAnnulus, ModeFields};
use support::one_contact::{self, CLAMP, SPEED, STIFFNESS, THICKNESS};
use support::pair_quartic::{hurwitz, threshold, PairTerms};

/// The one-contact disc (`support::one_contact`: bench disc geometry, hard
/// support inside, ⟨2, 0⟩, a fixed caliper at θ = 0, r = 0.1198 m) under
/// Mindlin theory.
fn scene(surface: ContactSurface, mu: f64) -> Config {
    let mut c = one_contact::scene(surface, mu, None);
    c.plate.theory = PlateTheory::Mindlin;
    c
}

/// One exact mode ⟨k, l⟩: k, ω, modal mass and W, Ψ_r, Ψ_θ at the contact
/// (cos mode: w = W cos kθ, ψ_r = Ψ_r cos kθ, ψ_θ = Ψ_θ sin kθ; the sin mode
/// turned by a quarter wave: W sin kθ, Ψ_r sin kθ, −Ψ_θ cos kθ).
struct Exact {
    k: u32,
    omega: f64,
    mass: f64,
    at: ModeFields,
    /// ∂W/∂r at the contact by central differences.
    slope: f64,
}

fn exact_modes(c: &Config, ks: &[u32], l_count: usize, r: f64) -> Vec<Exact> {
    let annulus = MindlinAnnulus::of_plate(&c.plate);
    let mut out = Vec::new();
    for &k in ks {
        for omega in annulus.roots(k, l_count, 64) {
            let mode: ExactMode = annulus.mode(k, omega);
            out.push(Exact {
                k,
                omega,
                mass: mode.modal_mass(400),
                at: mode.fields(r),
                slope: (mode.fields(r + 1e-6).w - mode.fields(r - 1e-6).w) / 2e-6,
            });
        }
    }
    out
}

/// The face kinematics the test's steady solution uses: the exact Mindlin
/// ψ, or (for the non-vacuity check) Kirchhoff's −∇w of the same W.
#[derive(Clone, Copy, PartialEq)]
enum FaceKinematics {
    Psi,
    MinusGradW,
}

/// The steady ALE state at speed Ω of the modes `modes` under a held force
/// `force` at the contact (r, θ = 0) and the fixed caliper's pad with
/// friction on both faces, solved here: (w, θ_x, θ_y) at the contact.
///
/// At θ = 0 (e_r = x, e_θ = y), with a the cos and b the sin amplitudes:
/// w = Σ W a, ∂_θ w = Σ k W b, ψ_r = Σ Ψ_r a, ψ_θ = −Σ Ψ_θ b. The faces
/// z = ±h/2 press with N = N₀ ± k_c w and slide (material velocity of the
/// face point z ψ in the turning polar basis, at rest in ALE) with
/// v = (z Ω (∂_θ ψ_r − ψ_θ), Ω r, Ω ∂_θ w), ∂_θ ψ_r − ψ_θ = Σ (k Ψ_r + Ψ_θ) b;
/// each face's friction −μ N v/|v| to first order is
/// (−μ N z (∂_θ ψ_r − ψ_θ)/r, −μ N, −μ N ∂_θ w / r). Its virtual work on a
/// mode is F·(z ψ_i) + F_z w_i, the face displacement through the thickness
/// being z ψ: on the cos mode W F_z + Ψ_r Σ z F_r, on the sin mode
/// −Ψ_θ Σ z F_θ. The ALE pair (docs/dynamics.md, damping ζ):
///   m [(ω² − k²Ω²) a + 2ζωkΩ b] = f_cos,  m [−2ζωkΩ a + (ω² − k²Ω²) b] = f_sin.
fn steady_contact(
    modes: &[Exact],
    [r, h, mu, zeta, speed, force]: [f64; 6],
    kinematics: FaceKinematics,
) -> [f64; 3] {
    // Unknowns: per mode a, and b for k ≥ 1.
    let mut index = Vec::new();
    let mut len = 0;
    for m in modes {
        let sin = (m.k > 0).then_some(len + 1);
        index.push((len, sin));
        len += 1 + sin.is_some() as usize;
    }
    // The face kinematics per mode: (Ψ_r, Ψ_θ) or Kirchhoff's (−W′, kW/r).
    let psi = |m: &Exact| -> (f64, f64) {
        match kinematics {
            FaceKinematics::Psi => (m.at.psi_r, m.at.psi_theta),
            FaceKinematics::MinusGradW => (-m.slope, m.k as f64 * m.at.w / r),
        }
    };
    // Rows of the linear functionals of the unknowns at the contact.
    let (mut w, mut w_theta, mut turn) = (vec![0.0; len], vec![0.0; len], vec![0.0; len]);
    for (m, &(c, s)) in modes.iter().zip(&index) {
        let (pr, pt) = psi(m);
        w[c] = m.at.w;
        if let Some(s) = s {
            w_theta[s] = m.k as f64 * m.at.w;
            turn[s] = m.k as f64 * pr + pt;
        }
    }
    let (k_c, n0) = (STIFFNESS, CLAMP);
    // f = g + G x: the generalised forces, affine in the unknowns x.
    let mut g = DVector::zeros(len);
    let mut big_g = DMatrix::zeros(len, len);
    for (m, &(c, s)) in modes.iter().zip(&index) {
        let (pr, pt) = psi(m);
        // Cos mode: W (F + N_b − N_t + F_z,friction) + Ψ_r Σ z F_r.
        g[c] += m.at.w * force;
        for j in 0..len {
            let normal = -2.0 * k_c * w[j] - mu * 2.0 * n0 * w_theta[j] / r;
            let radial = -mu * n0 * 0.5 * h * h * turn[j] / r;
            big_g[(c, j)] += m.at.w * normal + pr * radial;
        }
        // Sin mode: −Ψ_θ Σ z F_θ = −Ψ_θ (−μ (h/2) (N_t − N_b)) = μ h k_c w Ψ_θ.
        if let Some(s) = s {
            for j in 0..len {
                big_g[(s, j)] += mu * h * k_c * w[j] * pt;
            }
        }
    }
    let mut a = DMatrix::zeros(len, len);
    for (m, &(c, s)) in modes.iter().zip(&index) {
        let k = m.k as f64;
        let stiff = m.mass * (m.omega * m.omega - k * k * speed * speed);
        a[(c, c)] = stiff;
        if let Some(s) = s {
            let skew = m.mass * 2.0 * zeta * m.omega * k * speed;
            a[(c, s)] = skew;
            a[(s, c)] = -skew;
            a[(s, s)] = stiff;
        }
    }
    let x = (a - big_g).lu().solve(&g).expect("a regular steady system");
    let (mut out_w, mut theta_x, mut theta_y) = (0.0, 0.0, 0.0);
    for (m, &(c, s)) in modes.iter().zip(&index) {
        out_w += m.at.w * x[c];
        // θ = (−ψ_y, ψ_x) at θ = 0: θ_x = −ψ_θ = Σ Ψ_θ b, θ_y = ψ_r = Σ Ψ_r a.
        theta_y += m.at.psi_r * x[c];
        if let Some(s) = s {
            theta_x += m.at.psi_theta * x[s];
        }
    }
    [out_w, theta_x, theta_y]
}

#[test]
fn a_pad_with_friction_on_both_faces_bends_and_twists_the_disc_by_the_exact_mindlin_modal_sum() {
    let (mu, zeta, speed, force) = (0.5, 0.7, 1.0, -500.0);
    let ks = [0, 1, 2, 3, 4];
    let mut c = scene(ContactSurface::Faces, mu);
    c.plate.nodal_diameters = ks.to_vec();
    c.plate.nodal_circles = vec![0, 1];
    c.plate.damping = vec![zeta];
    c.joint.speed = speed;
    c.loads.ale.push(WrenchConfig {
        force: [0.0, 0.0, force],
        moment: [0.0; 3],
    });
    c.simulation.integrator = IntegratorKind::Rk4;
    c.simulation.rate_hz = 1000.0;
    let mut sim = Simulation::new(c.clone()).expect("pads on a Mindlin plate");
    for _ in 0..30 {
        sim.step().unwrap();
    }
    let out = sim.ale_node(0);
    let r = sim.scene().ale_nodes[0].radius;
    let modes = exact_modes(&c, &ks, 2, r);
    let data = [r, THICKNESS, mu, zeta, speed, force];
    let [w, theta_x, theta_y] = steady_contact(&modes, data, FaceKinematics::Psi);
    let errors = [
        (out.uz - w).abs() / w.abs(),
        (out.tilt[0] - theta_x).abs() / theta_x.abs(),
        (out.tilt[1] - theta_y).abs() / theta_y.abs(),
    ];
    println!(
        "w = {:e} m (exact {w:e}), θ_x = {:e} ({theta_x:e}), θ_y = {:e} ({theta_y:e}): relative errors {errors:?}",
        out.uz, out.tilt[0], out.tilt[1]
    );
    assert!(errors.iter().all(|&e| e < 1e-6), "{errors:?}");
    // Not vacuous: the twist θ_x comes from the faces' couple on ψ_θ; with
    // Kirchhoff's face kinematics (−∇w of the same W) or without friction it
    // is measurably another.
    let [_, kirchhoff_x, _] = steady_contact(&modes, data, FaceKinematics::MinusGradW);
    let [_, frictionless_x, _] = steady_contact(
        &modes,
        [r, THICKNESS, 0.0, zeta, speed, force],
        FaceKinematics::Psi,
    );
    println!("θ_x with −∇w at the faces {kirchhoff_x:e}, without friction {frictionless_x:e}");
    assert!((kirchhoff_x - theta_x).abs() > 1e-3 * theta_x.abs());
    assert!((frictionless_x - theta_x).abs() > 0.5 * theta_x.abs());
}

/// The quartic λ⁴ + a₁λ³ + a₂λ² + a₃λ + a₄ of the ⟨2, 0⟩ pair under the
/// contact at θ = 0, written as tests/pad_friction_on_the_faces.rs writes
/// Kirchhoff's, with the face point moving by z ψ: its radial velocity
/// v_r = z (Dψ_r/Dt − Ω ψ_θ) = z Ψ_r (q̇_c + kΩρ q_s), ρ = 1 + Ψ_θ/(kΨ_r),
/// its tangential one v_θ = z (Dψ_θ/Dt + Ω ψ_r) = −z Ψ_θ (q̇_s − kΩσ q_c),
/// σ = 1 + Ψ_r/(kΨ_θ), and the faces' couple μ (h/2)(N_t − N_b) working on
/// the sin mode's ψ_θ = −Ψ_θ (all at the contact radius; Kirchhoff's
/// Ψ_r = −R′, Ψ_θ = kR/r give that test's quartic):
///
///   q̈_c + (d₀ + β) q̇_c + G q̇_s + (K₀ + κ) q_c + (s + φ + βkΩρ) q_s = 0
///   q̈_s + (d₀ + γ) q̇_s − G q̇_c + K₀ q_s − (s + χ + γkΩσ) q_c = 0
///
/// K₀ = ω² − k²Ω², d₀ = 2ζω, s = 2ζωkΩ, G = 2kΩ; κ = 2k_c W²/m;
/// φ = 2μp kW²/(r m) (the follower's normal part, of ∂w/∂θ = kW q_s);
/// χ = μ h k_c W Ψ_θ / m; β = (h²/2) μ p Ψ_r²/(V m); γ = (h²/2) p μ′ Ψ_θ²/m
/// (μ′ = dμ/dv at V = Ωr: 0 for constant μ). W, Ψ_r, Ψ_θ, ω and m are the
/// exact Mindlin mode's; ζ the scene's.
fn quartic(mu: f64, face: bool) -> [f64; 4] {
    quartic_with(mu, face, FaceKinematics::Psi)
}

/// [`quartic`] with the face kinematics `kinematics` (Kirchhoff's −∇w of
/// the same W: Ψ_r = −W′, Ψ_θ = kW/r).
fn quartic_with(mu: f64, face: bool, kinematics: FaceKinematics) -> [f64; 4] {
    let c = scene(ContactSurface::Faces, mu);
    let r = Simulation::new(c.clone()).unwrap().scene().ale_nodes[0].radius;
    let mode = &exact_modes(&c, &[2], 1, r)[0];
    let (wr, pr, pt) = match kinematics {
        FaceKinematics::Psi => (mode.at.w, mode.at.psi_r, mode.at.psi_theta),
        FaceKinematics::MinusGradW => (mode.at.w, -mode.slope, 2.0 * mode.at.w / r),
    };
    let (k, m, w, z) = (2.0, mode.mass, mode.omega, c.plate.damping[0]);
    let (h, p) = (THICKNESS, CLAMP);
    let k0 = w * w - k * k * SPEED * SPEED;
    let d0 = 2.0 * z * w;
    let s = 2.0 * z * w * k * SPEED;
    let g = 2.0 * k * SPEED;
    let v = SPEED * r;
    let kappa = 2.0 * STIFFNESS * wr * wr / m;
    let phi = 2.0 * mu * p * k * wr * wr / (r * m);
    let (chi, beta) = if face {
        (
            mu * h * STIFFNESS * wr * pt / m,
            0.5 * h * h * mu * p * pr * pr / (v * m),
        )
    } else {
        (0.0, 0.0)
    };
    let gamma = 0.0; // constant μ
    let rho = 1.0 + pt / (k * pr);
    let sigma = 1.0 + pr / (k * pt);
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

/// The μ where [`hurwitz`] changes sign in (0, `hi`), by bisection.
fn closed_form_threshold(face: bool, hi: f64) -> f64 {
    threshold_with(face, hi, FaceKinematics::Psi)
}

fn threshold_with(face: bool, hi: f64, kinematics: FaceKinematics) -> f64 {
    threshold(hi, |mu| quartic_with(mu, face, kinematics))
}

#[test]
fn one_contact_one_pair_thresholds_match_the_routh_hurwitz_closed_form_with_mindlin_faces() {
    let sim = Simulation::new(scene(ContactSurface::Faces, 0.0)).unwrap();
    let eig = stability::friction_threshold(sim.scene(), SPEED, 2.0)
        .expect("squeals below μ = 2 with face friction");
    let closed = closed_form_threshold(true, 2.0);
    println!("faces: threshold μ_c eigenvalues {eig:.9}, Routh–Hurwitz {closed:.9}");
    assert!((eig - closed).abs() < 1e-6 * closed, "{eig} vs {closed}");
    // The mid-plane model: the follower's normal part (of ∂w/∂θ) alone.
    let mid = Simulation::new(scene(ContactSurface::MidPlane, 0.0)).unwrap();
    let hi = 100.0;
    let eig_mid = stability::friction_threshold(mid.scene(), SPEED, hi);
    let closed_mid = (hurwitz(quartic(hi, false)) < 0.0).then(|| closed_form_threshold(false, hi));
    println!("mid-plane: threshold eigenvalues {eig_mid:?}, Routh–Hurwitz {closed_mid:?}");
    match (eig_mid, closed_mid) {
        (Some(e), Some(c)) => assert!((e - c).abs() < 1e-6 * c && c > 2.0 * closed),
        other => panic!("mid-plane thresholds: {other:?}"),
    }
    // Not vacuous: the same mode with Kirchhoff's face kinematics (−∇w of
    // its W) has another threshold.
    let minus_grad_w = threshold_with(true, 2.0, FaceKinematics::MinusGradW);
    println!("faces with −∇w of the same W: Routh–Hurwitz {minus_grad_w:.9}");
    assert!((minus_grad_w - eig).abs() > 1e-3 * eig);
}

#[test]
fn eigenvalues_and_simulation_agree_on_growth_rates_with_pads_on_a_mindlin_plate() {
    let sim = Simulation::new(scene(ContactSurface::Faces, 0.0)).unwrap();
    let mu_c = stability::friction_threshold(sim.scene(), SPEED, 2.0).unwrap();
    for factor in [0.7, 1.5] {
        let (rate, slope) = left_eigenvector_growth(
            scene(ContactSurface::Faces, factor * mu_c),
            PadLayout::Rigid,
            1000,
        );
        println!("μ = {factor} μ_c: Re λ = {rate:.6} 1/s, simulated {slope:.6} 1/s");
        assert_eq!((rate > 0.0, slope > 0.0), (factor > 1.0, factor > 1.0));
        assert!(
            (slope - rate).abs() < 0.02 * rate.abs(),
            "simulated {slope} vs eigenvalue {rate}"
        );
    }
}

/// A floating caliper over three contacts at 0, ±15° (c_c = 50 N·s/m).
fn floating(mu: f64) -> Config {
    let mut c = scene(ContactSurface::Faces, mu);
    c.nodes.ale = [1.0 / 24.0, 0.0, 23.0 / 24.0]
        .map(|angular| NodePosition {
            radial: 0.6,
            angular,
        })
        .to_vec();
    let pads = c.section_mut::<PadsConfig>().unwrap();
    pads.contacts = (0..3).map(|node| PadContact { node, pad: 0 }).collect();
    pads.caliper = Caliper::Floating;
    pads.contact_damping = 50.0;
    c
}

/// A floating caliper's massive pad, m_p = 0.2 kg per face (c_c = 50 N·s/m).
fn massive(mu: f64) -> Config {
    let mut c = scene(ContactSurface::Faces, mu);
    let pads = c.section_mut::<PadsConfig>().unwrap();
    pads.caliper = Caliper::Floating;
    pads.mass = 0.2;
    pads.contact_damping = 50.0;
    c
}

/// The lining's patch, k_t = 1e6 N/m, c_t = 100 N·s/m.
fn patch(mu: f64) -> Config {
    let mut c = one_contact::scene(ContactSurface::Faces, mu, Some((1.0e6, 100.0)));
    c.plate.theory = PlateTheory::Mindlin;
    c
}

/// A scene at friction coefficient μ.
type Build = fn(f64) -> Config;

/// The pads' other laws take the same face kinematics in the simulation and
/// in `stability`: a run started on the critical eigenvector grows at Re λ
/// (within 2 %) below and above each law's own threshold
/// (`support::left_growth`).
#[test]
fn eigenvalues_and_simulation_agree_with_a_floating_caliper_pad_mass_and_patches_on_a_mindlin_plate(
) {
    let cases: [(&str, Build, PadLayout); 3] = [
        ("floating caliper, 3 contacts", floating, PadLayout::Rigid),
        (
            "massive pad",
            massive,
            PadLayout::Massive {
                rest: CLAMP / STIFFNESS,
            },
        ),
        (
            "lining patch",
            patch,
            PadLayout::Patch {
                half_thickness: 0.5 * THICKNESS,
            },
        ),
    ];
    for (name, build, layout) in cases {
        let sim = Simulation::new(build(0.0)).unwrap();
        let mu_c = stability::friction_threshold(sim.scene(), SPEED, 20.0)
            .unwrap_or_else(|| panic!("{name}: no threshold below μ = 20"));
        for factor in [0.7, 1.5] {
            // At most e² of growth or decay: the fit stays in the linear range.
            let lam = stability::growth_rate(sim.scene(), SPEED, factor * mu_c, &[CLAMP]);
            let steps = (2.0 / lam.abs() * 1000.0).min(1000.0) as usize;
            let (rate, slope) = left_eigenvector_growth(build(factor * mu_c), layout, steps);
            println!(
                "{name}: μ_c = {mu_c:.6}; μ = {factor} μ_c: Re λ = {rate:.6} 1/s, simulated {slope:.6} 1/s"
            );
            assert_eq!((rate > 0.0, slope > 0.0), (factor > 1.0, factor > 1.0));
            assert!(
                (slope - rate).abs() < 0.02 * rate.abs(),
                "{name}: simulated {slope} vs eigenvalue {rate}"
            );
        }
    }
}

/// RK4 on each description's own equations (ALE pair equations; Lagrangian
/// modes with the pads evaluated at the derived ALE amplitudes) converges
/// to one motion at fourth order, with friction on the faces and at the
/// mid-plane (the follower's normal part from ∂w/∂θ).
#[test]
fn ale_and_lagrangian_descriptions_converge_to_one_motion_with_pads_on_a_mindlin_plate() {
    for (surface, mu) in [
        (
            ContactSurface::Faces,
            1.5 * closed_form_threshold(true, 2.0),
        ),
        (ContactSurface::MidPlane, 5.0),
    ] {
        let config = scene(surface, mu);
        let last = assert_fourth_order(
            &format!("{surface:?}, μ = {mu:.4}, rk4 ALE vs Lagrangian"),
            &[20_000.0, 40_000.0, 80_000.0, 160_000.0],
            |rate| descriptions_differ(&config, rate, 0.5, |_, _| {}),
        );
        assert!(last < 5e-7, "{last:e}");
    }
}

#[test]
fn pads_on_a_mindlin_plate_take_residual_flexibility() {
    // Their contacts in series with the load patches' residual compliance
    // (docs/residual_flexibility.md, "Under Mindlin theory").
    let mut c = scene(ContactSurface::Faces, 0.3);
    c.plate.residual_flexibility = true;
    if let Err(e) = Simulation::new(c) {
        panic!("refused: {e}");
    }
}
