//! The lining's shear (`pads.shear_stiffness`, `pads.shear_damping`;
//! docs/scenes.md "Pad shear"): one contact, one mode pair — the linearised
//! model against its characteristic polynomial written out here (the rigid
//! quartic with the radial friction damping filtered by the patch, times the
//! patch's denominator); eigenvalues and simulation agree on growth rates;
//! a stiff lining reproduces the rigid pads' threshold and motion; ALE and
//! Lagrangian descriptions converge to one motion; bad keys are refused.

use annular_plate::config::{Config, IntegratorKind};
use annular_plate::dynamics::load_models::pad_config::{ContactSurface, PadsConfig};
use annular_plate::dynamics::{stability, Simulation};
use annular_plate::model::AngularShape;
use faer::Mat;
use nalgebra::Complex;

mod support;
use support::fourth_order::{assert_fourth_order, descriptions_differ};
use support::left_growth::{left_eigenvector_growth, PadLayout};
use support::one_contact::{self, CLAMP, SPEED, STIFFNESS, THICKNESS};
use support::scenes::relative_difference;

/// k_t, c_t per contact point and face: k_t near a ω (a = μN₀/V ≈ 200 N·s/m,
/// ω ≈ 1e4 1/s), where the patch moves the threshold most.
const SHEAR: (f64, f64) = (1.0e6, 100.0);

/// The one-contact disc (`support::one_contact`) with friction on the faces
/// and the lining's patches `shear` (None: rigid).
fn scene(mu: f64, shear: Option<(f64, f64)>) -> Config {
    one_contact::scene(ContactSurface::Faces, mu, shear)
}

/// Polynomials in λ, lowest power first.
fn mul(a: &[f64], b: &[f64]) -> Vec<f64> {
    let mut out = vec![0.0; a.len() + b.len() - 1];
    for (i, x) in a.iter().enumerate() {
        for (j, y) in b.iter().enumerate() {
            out[i + j] += x * y;
        }
    }
    out
}

fn add(a: &[f64], b: &[f64]) -> Vec<f64> {
    (0..a.len().max(b.len()))
        .map(|i| a.get(i).unwrap_or(&0.0) + b.get(i).unwrap_or(&0.0))
        .collect()
}

/// The characteristic polynomial of the pair under the contact at θ = 0
/// with the patches (k_t, c_t) (mass-normalised ALE amplitudes q_c, q_s; R,
/// R′ the radial shape and its slope at r; m, ω, ζ the pair's modal mass,
/// frequency and damping; p = N₀ the preload per face; V = Ωr; constant μ).
/// Rigid pads (tests/pad_friction_on_the_faces.rs):
///
///   q̈_c + d₀ q̇_c + β (q̇_c + kΩρ q_s) + G q̇_s + (K₀ + κ) q_c + (s + φ) q_s = 0
///   q̈_s + d₀ q̇_s − G q̇_c + K₀ q_s − (s + χ) q_c = 0
///
/// K₀ = ω² − k²Ω², d₀ = 2ζω, s = 2ζωkΩ, G = 2kΩ, κ = 2k_c R²/m,
/// φ = 2μpkR²/(rm), χ = μhk_ckR²/(rm), ρ = 1 − R/(rR′), and
/// β = (h²/2) a R′²/m with a = μp/V the radial friction damping of a face:
/// β (q̇_c + kΩρ q_s) is the faces' radial friction acting on their radial
/// velocity ∓(h/2) R′(q̇_c + kΩρ q_s). With a patch on each face
/// (k_t ξ + c_t ξ̇ = a (v_r − ξ̇), the disc feeling −a (v_r − ξ̇)) the face's
/// radial friction acts on v_r − ξ̇ = H(λ) v_r, H = (k_t + c_t λ)/(k_t + (c_t + a) λ):
/// β → β H(λ). With A₁ = λ² + d₀λ + K₀ + κ, A₂ = λ² + d₀λ + K₀,
/// B₁ = Gλ + s + φ, B₂ = Gλ + s + χ the determinant is
/// (A₁ + βHλ) A₂ + (B₁ + βHkΩρ) B₂; times D = k_t + (c_t + a)λ,
///
///   P(λ) = D (A₁A₂ + B₁B₂) + (k_t + c_t λ) β (λA₂ + kΩρ B₂),
///
/// a quintic (D → N = k_t + c_t λ: the rigid quartic times N).
fn characteristic_polynomial(mu: f64, shear: (f64, f64)) -> Vec<f64> {
    let sim = Simulation::new(scene(mu, None)).unwrap();
    let model = sim.model();
    let r = sim.scene().ale_nodes[0].radius;
    let cos = model
        .modes()
        .iter()
        .position(|m| m.shape == AngularShape::Cos)
        .unwrap();
    let mode = &model.modes()[cos];
    let shape = model.radial_shapes()[mode.radial].eval(r);
    let (rr, rr_slope) = (shape[0], shape[1]);
    let (k, m, w, z) = (mode.k as f64, mode.modal_mass, mode.omega, mode.damping);
    let (h, p, v) = (THICKNESS, CLAMP, SPEED * r);
    let k0 = w * w - k * k * SPEED * SPEED;
    let d0 = 2.0 * z * w;
    let s = 2.0 * z * w * k * SPEED;
    let g = 2.0 * k * SPEED;
    let kappa = 2.0 * STIFFNESS * rr * rr / m;
    let phi = 2.0 * mu * p * k * rr * rr / (r * m);
    let chi = mu * h * STIFFNESS * k * rr * rr / (r * m);
    let a = mu * p / v;
    let beta = 0.5 * h * h * a * rr_slope * rr_slope / m;
    let rho = 1.0 - rr / (r * rr_slope);
    let (kt, ct) = shear;
    let a1 = [k0 + kappa, d0, 1.0];
    let a2 = [k0, d0, 1.0];
    let b1 = [s + phi, g];
    let b2 = [s + chi, g];
    let rigid = add(&mul(&a1, &a2), &mul(&b1, &b2));
    let radial = add(&mul(&[0.0, 1.0], &a2), &mul(&[k * SPEED * rho], &b2));
    add(
        &mul(&[kt, ct + a], &rigid),
        &mul(&[kt, ct], &mul(&[beta], &radial)),
    )
}

/// The roots of a polynomial (lowest power first), largest real part
/// first: the eigenvalues of the companion matrix of p(σλ) (σ = `scale`, so
/// that its coefficients are of one magnitude), polished by Newton's method
/// on p itself.
fn roots(p: &[f64], scale: f64) -> Vec<Complex<f64>> {
    let d = p.len() - 1;
    let scaled: Vec<f64> = p
        .iter()
        .enumerate()
        .map(|(i, c)| c * scale.powi(i as i32))
        .collect();
    let mut c = Mat::<f64>::zeros(d, d);
    for i in 1..d {
        c[(i, i - 1)] = 1.0;
    }
    for i in 0..d {
        c[(i, d - 1)] = -scaled[i] / scaled[d];
    }
    let horner = |z: Complex<f64>| {
        let (mut v, mut dv) = (Complex::new(0.0, 0.0), Complex::new(0.0, 0.0));
        for &a in p.iter().rev() {
            dv = dv * z + v;
            v = v * z + a;
        }
        (v, dv)
    };
    let mut z: Vec<Complex<f64>> = c
        .eigenvalues()
        .unwrap()
        .into_iter()
        .map(|z| {
            let mut z = Complex::new(z.re, z.im) * scale;
            for _ in 0..5 {
                let (v, dv) = horner(z);
                z -= v / dv;
            }
            z
        })
        .collect();
    z.sort_by(|x, y| y.re.total_cmp(&x.re).then(x.im.total_cmp(&y.im)));
    z
}

fn sorted(mut z: Vec<Complex<f64>>) -> Vec<Complex<f64>> {
    z.sort_by(|x, y| y.re.total_cmp(&x.re).then(x.im.total_cmp(&y.im)));
    z
}

#[test]
fn one_contact_one_pair_eigenvalues_are_the_roots_of_the_filtered_quintic() {
    for mu in [0.2, 0.5, 1.0] {
        let sim = Simulation::new(scene(mu, Some(SHEAR))).unwrap();
        let eig = sorted(stability::eigenvalues(sim.scene(), SPEED, mu, &[CLAMP]));
        let closed = roots(&characteristic_polynomial(mu, SHEAR), 1.0e4);
        assert_eq!(eig.len(), 5, "q_c, q_s, their rates and one patch state");
        for (e, c) in eig.iter().zip(&closed) {
            println!("μ = {mu}: eigenvalue {e:.6}, closed form {c:.6}");
            assert!(
                (e - c).norm() < 1e-7 * c.norm().max(1.0),
                "μ = {mu}: {e} vs {c}"
            );
        }
    }
}

/// The friction threshold of the one-contact scene with `shear` (the
/// scene built for `contact_exponential`, which bounds no substeps: a lining
/// as stiff as 1e12 N/m is a fast state for RK4).
fn threshold(shear: Option<(f64, f64)>) -> f64 {
    let mut c = scene(0.0, shear);
    c.simulation.integrator = IntegratorKind::ContactExponential;
    let sim = Simulation::new(c).unwrap();
    stability::friction_threshold(sim.scene(), SPEED, 2.0).expect("squeals below μ = 2")
}

/// Re λ of the critical mode measured in a simulation started on it
/// (`support::left_growth`; the patch's ζ = −x_r/(h/2) of the top face in
/// the state): ln|u_Lᵀ y(t)| has slope Re λ.
fn simulated_growth_rate(mu: f64) -> (f64, f64) {
    let half_thickness = 0.5 * THICKNESS;
    left_eigenvector_growth(
        scene(mu, Some(SHEAR)),
        PadLayout::Patch { half_thickness },
        1000,
    )
}

#[test]
fn eigenvalues_and_simulation_agree_on_growth_rates_with_the_lining_s_patches() {
    let (rigid, sheared) = (threshold(None), threshold(Some(SHEAR)));
    println!(
        "threshold: rigid {rigid:.6}, k_t = {:e}, c_t = {}: {sheared:.6}",
        SHEAR.0, SHEAR.1
    );
    assert!(
        sheared < 0.9 * rigid,
        "the patch filters the radial friction damping: {sheared} vs {rigid}"
    );
    for factor in [0.7, 1.5] {
        let (rate, slope) = simulated_growth_rate(factor * sheared);
        println!("μ = {factor} μ_c: Re λ = {rate:.6} 1/s, simulated {slope:.6} 1/s");
        assert_eq!(rate > 0.0, factor > 1.0);
        assert!(
            (slope - rate).abs() < 0.02 * rate.abs(),
            "simulated {slope} vs eigenvalue {rate}"
        );
    }
}

#[test]
fn a_stiff_lining_has_the_rigid_threshold() {
    let rigid = threshold(None);
    let shift = |kt: f64| {
        let d = (threshold(Some((kt, SHEAR.1))) - rigid).abs() / rigid;
        println!("k_t = {kt:e}: threshold differs from the rigid {rigid:.9} by {d:.3e}");
        d
    };
    // First order in 1/k_t (measured 3.6e-5, 8.5e-8, 1.6e-9: the last at the
    // thresholds' bisection tolerance, 1e-9).
    let (d8, d10, d12) = (shift(1.0e8), shift(1.0e10), shift(1.0e12));
    assert!(d10 < 0.02 * d8, "{d10} after {d8}");
    assert!(d12 < 1e-8, "{d12}");
}

/// q̄ over 0.05 s at 200 kHz, one RK4 step per output (so the rigid and the
/// sheared runs share the step).
fn motion(shear: Option<(f64, f64)>, mu: f64) -> Vec<f64> {
    let mut c = scene(mu, shear);
    c.simulation.rate_hz = 200_000.0;
    c.simulation.rk4_step_limit = 2.5;
    c.initial.q = vec![2e-6, 1e-6];
    let mut sim = Simulation::new(c).unwrap();
    let mut out = Vec::new();
    for _ in 0..10_000 {
        sim.step().unwrap();
        out.extend_from_slice(sim.q_ale());
    }
    out
}

#[test]
fn a_stiff_lining_moves_the_disc_as_the_rigid_pads() {
    let mu = 1.5 * threshold(None);
    let rigid = motion(None, mu);
    let mut last = f64::INFINITY;
    // Along k_t/c_t = 1e5 1/s: the patch's own rate fixed, H(λ) − 1 ≈ −a/c_t.
    for (kt, ct) in [(1.0e9, 1.0e4), (1.0e10, 1.0e5), (1.0e11, 1.0e6)] {
        let d = relative_difference(&motion(Some((kt, ct)), mu), &rigid);
        println!("k_t = {kt:e}, c_t = {ct:e}: max |q̄ − q̄_rigid| / max |q̄_rigid| = {d:.3e}");
        assert!(d < 0.2 * last, "{d} after {last}");
        last = d;
    }
    assert!(last < 1e-3, "{last}");
}

/// RK4 integrates each description's own ODE, the patches' deflections with
/// the modes in both: independent discretisations that converge to one
/// motion at fourth order.
#[test]
fn ale_and_lagrangian_descriptions_converge_to_one_motion_with_the_patches() {
    let mu = 1.5 * threshold(Some(SHEAR));
    let config = scene(mu, Some(SHEAR));
    // the radial patch deflections on the amplitudes' scale
    let patches = |sim: &Simulation, out: &mut Vec<f64>| {
        let slot = &sim.state().load_models.slots[0];
        out.extend([slot[0], slot[2]]);
    };
    let last = assert_fourth_order(
        "lining shear, rk4 ALE vs Lagrangian",
        &[20_000.0, 40_000.0, 80_000.0, 160_000.0],
        // the rate sets RK4's step
        |rate| descriptions_differ(&config, rate, 2.5, patches),
    );
    assert!(last < 5e-7);
}

#[test]
fn bad_shear_data_is_refused_naming_the_key() {
    let file = |integrator: &str, extra: &str| {
        format!(
            "annular_plate:\n  ros__parameters:\n    plate:\n      residual_flexibility: false\n    simulation:\n      integrator: {integrator}\n    nodes:\n      ale_radial: [0.6]\n      ale_angular: [0.0]\n    pads:\n      ale_nodes: [1]\n{extra}"
        )
    };
    let both = "      shear_stiffness: 1.0e6\n      shear_damping: 20.0\n";
    let c = Config::from_yaml_str(&file("rk4", both), "annular_plate").unwrap();
    assert_eq!(
        c.section::<PadsConfig>().unwrap().shear,
        Some((1.0e6, 20.0))
    );
    let c = Config::from_yaml_str(&file("rk4", ""), "annular_plate").unwrap();
    assert_eq!(c.section::<PadsConfig>().unwrap().shear, None);
    let refused = |integrator: &str, extra: &str, needles: &[&str]| {
        let e = Config::from_yaml_str(&file(integrator, extra), "annular_plate")
            .unwrap_err()
            .to_string();
        assert!(needles.iter().all(|n| e.contains(n)), "{extra:?}: {e}");
    };
    for bad in ["-1.0e6", "0.0", ".nan", ".inf"] {
        refused(
            "rk4",
            &format!("      shear_stiffness: {bad}\n      shear_damping: 20.0\n"),
            &["pads.shear_stiffness"],
        );
        refused(
            "rk4",
            &format!("      shear_stiffness: 1.0e6\n      shear_damping: {bad}\n"),
            &["pads.shear_damping"],
        );
    }
    refused(
        "rk4",
        "      shear_stiffness: 1.0e6\n",
        &["pads.shear_stiffness", "pads.shear_damping"],
    );
    refused(
        "rk4",
        "      shear_damping: 20.0\n",
        &["pads.shear_damping", "pads.shear_stiffness"],
    );
    refused(
        "rk4",
        &format!("{both}      contact_surface: mid_plane\n"),
        &["pads.shear_stiffness", "pads.contact_surface"],
    );
    refused(
        "rk4",
        &format!("{both}      static_friction_coefficient: 0.6\n"),
        &["pads.shear_stiffness", "pads.static_friction_coefficient"],
    );
    for integrator in ["exponential", "implicit_midpoint"] {
        refused(
            integrator,
            both,
            &["pads.shear_stiffness", "simulation.integrator"],
        );
    }
    Config::from_yaml_str(&file("contact_exponential", both), "annular_plate").unwrap();
}

/// `contact_exponential` carries the patches in its linearisation: its
/// motion (q̄ and the patches' radial deflections, 0.05 s above threshold)
/// converges to RK4's (at step limit 0.005 on the modes) as its tolerance
/// tightens: measured 2.7e-7, 3.7e-9, 2.4e-9 at 1e-5, 1e-7, 1e-9.
#[test]
fn contact_exponential_carries_the_patches_as_rk4_does() {
    let mu = 1.5 * threshold(Some(SHEAR));
    let run = |integrator: IntegratorKind, tolerance: f64| {
        let mut c = scene(mu, Some(SHEAR));
        c.simulation.integrator = integrator;
        c.simulation.contact_tolerance = tolerance;
        c.simulation.rate_hz = 20_000.0;
        c.simulation.rk4_step_limit = 0.005;
        c.initial.q = vec![2e-6, 1e-6];
        let mut sim = Simulation::new(c).unwrap();
        let mut out = Vec::new();
        for _ in 0..1000 {
            sim.step().unwrap();
            out.extend_from_slice(sim.q_ale());
            let slot = &sim.state().load_models.slots[0];
            out.extend([slot[0], slot[2]]);
        }
        out
    };
    let reference = run(IntegratorKind::Rk4, 1e-6);
    let mut last = f64::INFINITY;
    for tolerance in [1e-5, 1e-7, 1e-9] {
        let d = relative_difference(
            &run(IntegratorKind::ContactExponential, tolerance),
            &reference,
        );
        println!("contact_exponential, tolerance {tolerance:e}: {d:.3e} from rk4");
        assert!(d < last, "{d} after {last}");
        last = d;
    }
    assert!(last < 1e-8, "{last}");
}

/// A configuration built in code passes no reader: the simulation itself
/// refuses an integrator that cannot carry the patches, naming their keys.
#[test]
fn an_integrator_without_continuous_states_is_refused_naming_the_shear_keys() {
    for integrator in [
        IntegratorKind::Exponential,
        IntegratorKind::ImplicitMidpoint,
    ] {
        let mut c = scene(0.3, Some(SHEAR));
        c.simulation.integrator = integrator;
        let e = match Simulation::new(c) {
            Ok(_) => panic!("{} accepted the patches", integrator.name()),
            Err(e) => e.to_string(),
        };
        assert!(
            e.contains("pads.shear_stiffness") && e.contains(integrator.name()),
            "{e}"
        );
    }
}
