//! Pads with mass (`pads.mass`, docs/scenes.md "Pad mass"): one contact, one
//! mode pair — the coupled frequencies against the characteristic polynomial
//! written out here, the friction threshold against the test's own 3-DOF
//! eigen-solve, the eigenvalue growth rate against a simulation; the massless
//! thresholds as the mass vanishes; the two descriptions agree; bad input is
//! refused naming the key.

use annular_plate::config::{Boundary, Config, Coordinates, IntegratorKind, NodePosition};
use annular_plate::dynamics::load_models::pad_config::{
    Caliper, ContactSurface, PadContact, PadsConfig,
};
use annular_plate::dynamics::{stability, Simulation};
use annular_plate::model::AngularShape;
use faer::Mat;

mod support;
use support::fourth_order::{assert_fourth_order, descriptions_differ};
use support::left_growth::{left_eigenvector_growth, PadLayout};

const SPEED: f64 = 25.0;
const CLAMP: f64 = 1000.0;
const STIFFNESS: f64 = 2.0e7;
const PAD_MASS: f64 = 0.2;
const BACKING: f64 = 3.0e7;
/// c_c per contact and face, N·s/m (the test bench's): it damps the pads' own modes.
const DAMPING: f64 = 50.0;

/// The brake disc with only the ⟨k = 2, l = 0⟩ pair and one pad of contacts
/// at the angles `angles` on r = 0.1198 m (the scene of
/// tests/pad_friction_on_the_faces.rs, with pad mass).
fn scene(caliper: Caliper, mass: f64, backing: Option<f64>, mu: f64, angles: &[f64]) -> Config {
    let mut c = Config::default();
    c.plate.inner_radius = 0.07;
    c.plate.outer_radius = 0.153;
    c.plate.thickness = 0.0181;
    c.plate.inner_boundary = Boundary::Supported;
    c.plate.nodal_diameters = vec![2];
    c.plate.nodal_circles = vec![0];
    c.plate.damping = vec![1e-4];
    c.plate.residual_flexibility = false;
    for &a in angles {
        c.nodes.ale.push(NodePosition {
            radial: 0.6,
            angular: a,
        });
    }
    c.joint.speed = SPEED;
    c.set_section(PadsConfig {
        contacts: (0..angles.len())
            .map(|node| PadContact { node, pad: 0 })
            .collect(),
        clamp_force: vec![CLAMP],
        contact_stiffness: STIFFNESS,
        contact_damping: DAMPING,
        friction_coefficient: mu,
        lift_off: false,
        follower_friction: true,
        caliper,
        contact_surface: ContactSurface::Faces,
        static_friction_coefficient: None,
        stribeck_speed: 1.0,
        mass,
        backing_stiffness: backing,
        shear: None,
    });
    c.simulation.integrator = IntegratorKind::Rk4;
    c.simulation.rk4_step_limit = 0.05;
    c.simulation.coordinates = Coordinates::Ale;
    c.simulation.realtime_factor = 0.0;
    c
}

/// The pair's data at the contact (θ = 0): R, R′, k, modal mass, ω, ζ, r.
struct Pair {
    rr: f64,
    slope: f64,
    k: f64,
    m: f64,
    w: f64,
    z: f64,
    r: f64,
}

fn pair(sim: &Simulation) -> Pair {
    let model = sim.model();
    let r = sim.scene().ale_nodes[0].radius;
    let mode = model
        .modes()
        .iter()
        .find(|m| m.shape == AngularShape::Cos)
        .unwrap();
    let [rr, slope, ..] = model.radial_shapes()[mode.radial].eval(r);
    Pair {
        rr,
        slope,
        k: mode.k as f64,
        m: mode.modal_mass,
        w: mode.omega,
        z: mode.damping,
        r,
    }
}

/// (a) Without speed and friction, one contact at θ = 0 on the cos mode
/// (w = R q_c) and a pad per face: with a = (ξ_b − ξ_t)/2 the disc and the
/// pads' antisymmetric motion couple,
///
///   M q̈ + (M ω² + 2k_c R²) q − 2k_c R a = 0,   m_p ä + (k_c + k_b) a − k_c R q = 0,
///
/// so s = λ² solves M m_p s² + [M (k_c + k_b) + m_p (M ω² + 2k_c R²)] s +
/// (M ω² + 2k_c R²)(k_c + k_b) − 2k_c² R² = 0; the pads' symmetric motion
/// (s = −(k_c + k_b)/m_p) and the sin mode (s = −ω²) stay alone.
#[test]
fn one_pad_on_one_mode_pair_has_the_frequencies_of_its_characteristic_polynomial() {
    for (caliper, backing) in CALIPERS {
        let mut c = scene(caliper, PAD_MASS, backing, 0.0, &[0.0]);
        c.plate.damping = vec![0.0];
        c.section_mut::<PadsConfig>().unwrap().contact_damping = 0.0;
        c.joint.speed = 0.0;
        let sim = Simulation::new(c).unwrap();
        let p = pair(&sim);
        let (kc, kb, mp) = (STIFFNESS, backing.unwrap_or(0.0), PAD_MASS);
        let disc = p.m * p.w * p.w + 2.0 * kc * p.rr * p.rr;
        let (a2, a1, a0) = (
            p.m * mp,
            p.m * (kc + kb) + mp * disc,
            disc * (kc + kb) - 2.0 * kc * kc * p.rr * p.rr,
        );
        let root = (a1 * a1 - 4.0 * a2 * a0).sqrt();
        let s = [
            (-a1 + root) / (2.0 * a2),
            (-a1 - root) / (2.0 * a2),
            -(kc + kb) / mp,
            -p.w * p.w,
        ];
        let mut expected: Vec<f64> = s.iter().map(|s| (-s).sqrt()).collect();
        expected.sort_by(f64::total_cmp);
        let mut got: Vec<f64> = stability::eigenvalues(sim.scene(), 0.0, 0.0, &[CLAMP])
            .iter()
            .filter(|l| l.im > 0.0)
            .map(|l| l.im)
            .collect();
        got.sort_by(f64::total_cmp);
        println!("{caliper:?}: frequencies {got:?} rad/s, closed form {expected:?}");
        assert_eq!(got.len(), 4);
        for (g, e) in got.iter().zip(&expected) {
            assert!((g - e).abs() < 1e-9 * e, "{g} vs {e}");
        }
        let all = stability::eigenvalues(sim.scene(), 0.0, 0.0, &[CLAMP]);
        assert!(all.iter().all(|l| l.re.abs() < 1e-6), "undamped: {all:?}");
    }
}

/// (b) The test's own equations of the pair and the pad at speed Ω with face
/// friction (the quartic of tests/pad_friction_on_the_faces.rs with the pad's
/// coordinate a = (ξ_b − ξ_t)/2 where the massless fixed caliper has a = 0):
/// the faces' springs act on R q_c − a, so κ q_c → κ (q_c − a/R) and the
/// couple's χ q_c → χ (q_c − a/R), each with its damping ε = c_c/k_c times
/// the rates; the pad: m_p ä = −(k_c + k_b) a − c_c ȧ + k_c R q_c + c_c R q̇_c.
/// The sliding direction's circulatory part is βkΩρ, ρ = 1 − R/(rR′) (the
/// face point's radial velocity carries the basis' rotation −Ω ∂_θ w / r).
/// Returns max Re λ of the 6×6 first-order system (q_c, q_s, a and rates).
/// In series with the residual flexibility k_c, c_c are divided by 1 + 2k_c γ.
fn own_growth_rate(sim: &Simulation, mu: f64, backing: f64) -> f64 {
    let p = pair(sim);
    // In series with the residual compliance γ = G(0, 0) at the contact the
    // net force (k_c (ξ_b − ξ_t − 2w) + …) is divided by 1 + 2k_c γ: k_c and
    // c_c act as k_c/(1 + 2k_c γ), c_c/(1 + 2k_c γ) (not k_b).
    let series = sim
        .scene()
        .residual
        .as_ref()
        .map_or(1.0, |g| 1.0 + 2.0 * STIFFNESS * g.between(0, 0, 0.0));
    let (h, pre, kc, mp, cc) = (
        0.0181,
        CLAMP,
        STIFFNESS / series,
        PAD_MASS,
        DAMPING / series,
    );
    let eps = cc / kc;
    let (k, m) = (p.k, p.m);
    let k0 = p.w * p.w - k * k * SPEED * SPEED;
    let d0 = 2.0 * p.z * p.w;
    let s = 2.0 * p.z * p.w * k * SPEED;
    let g = 2.0 * k * SPEED;
    let v = SPEED * p.r;
    let mu = mu * (v / 1e-3).tanh();
    let kappa = 2.0 * kc * p.rr * p.rr / m;
    let phi = 2.0 * mu * pre * k * p.rr * p.rr / (p.r * m);
    let chi = mu * h * kc * k * p.rr * p.rr / (p.r * m);
    let beta = 0.5 * h * h * mu * pre * p.slope * p.slope / (v * m);
    let mut a = Mat::<f64>::zeros(6, 6);
    for i in 0..3 {
        a[(i, 3 + i)] = 1.0;
    }
    // q̈_c = −(d₀ + β) q̇_c − G q̇_s − K₀ q_c − κ (q_c − a/R) − κε (q̇_c − ȧ/R) − (s + φ + βkΩρ) q_s
    let rho = 1.0 - p.rr / (p.r * p.slope);
    a[(3, 3)] = -(d0 + beta) - kappa * eps;
    a[(3, 5)] = kappa * eps / p.rr;
    a[(3, 4)] = -g;
    a[(3, 0)] = -k0 - kappa;
    a[(3, 2)] = kappa / p.rr;
    a[(3, 1)] = -(s + phi + beta * k * SPEED * rho);
    // q̈_s = −d₀ q̇_s + G q̇_c − K₀ q_s + s q_c + χ (q_c − a/R) + χε (q̇_c − ȧ/R)
    a[(4, 4)] = -d0;
    a[(4, 3)] = g + chi * eps;
    a[(4, 5)] = -chi * eps / p.rr;
    a[(4, 1)] = -k0;
    a[(4, 0)] = s + chi;
    a[(4, 2)] = -chi / p.rr;
    // ä = (−(k_c + k_b) a − c_c ȧ + k_c R q_c + c_c R q̇_c)/m_p
    a[(5, 2)] = -(kc + backing) / mp;
    a[(5, 5)] = -cc / mp;
    a[(5, 0)] = kc * p.rr / mp;
    a[(5, 3)] = cc * p.rr / mp;
    // Balanced (s q, q̇), s² the largest stiffness entry: the same
    // eigenvalues with blocks of one magnitude, so Re λ keeps its digits.
    let scale = (0..3)
        .map(|i| a[(3 + i, i)].abs())
        .fold(1.0, f64::max)
        .sqrt();
    for i in 0..3 {
        for j in 0..3 {
            a[(i, 3 + j)] *= scale;
            a[(3 + i, j)] /= scale;
        }
    }
    a.eigenvalues()
        .unwrap()
        .iter()
        .map(|l| l.re)
        .fold(f64::NEG_INFINITY, f64::max)
}

fn own_threshold(sim: &Simulation, backing: f64) -> f64 {
    let (mut lo, mut hi) = (0.0, 20.0);
    assert!(own_growth_rate(sim, lo, backing) < 0.0 && own_growth_rate(sim, hi, backing) > 0.0);
    while hi - lo > 1e-12 {
        let mid = 0.5 * (lo + hi);
        if own_growth_rate(sim, mid, backing) > 0.0 {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    0.5 * (lo + hi)
}

/// `scene` with the contacts in series with the residual flexibility
/// (`plate.residual_flexibility: true`, the default).
fn in_series(mut c: Config) -> Config {
    c.plate.residual_flexibility = true;
    c
}

/// Modal pads, and pads in series with the residual flexibility.
const DESCRIPTIONS: [fn(Config) -> Config; 2] = [|c| c, in_series];

/// The fixed caliper (with its backing stiffness) and the floating one.
const CALIPERS: [(Caliper, Option<f64>); 2] =
    [(Caliper::Fixed, Some(BACKING)), (Caliper::Floating, None)];

/// A description: the configuration put into it.
type Description = fn(Config) -> Config;

/// Each caliper with each description.
fn calipers_and_descriptions() -> impl Iterator<Item = ((Caliper, Option<f64>), Description)> {
    CALIPERS
        .into_iter()
        .flat_map(|c| DESCRIPTIONS.map(|d| (c, d)))
}

#[test]
fn the_friction_threshold_with_pad_mass_matches_the_tests_own_eigen_solve() {
    for ((caliper, backing), series) in calipers_and_descriptions() {
        let sim = Simulation::new(series(scene(caliper, PAD_MASS, backing, 0.0, &[0.0]))).unwrap();
        let eig =
            stability::friction_threshold(sim.scene(), SPEED, 20.0).expect("squeals below μ = 20");
        let own = own_threshold(&sim, backing.unwrap_or(0.0));
        let massless = Simulation::new(series(scene(caliper, 0.0, None, 0.0, &[0.0]))).unwrap();
        let without = stability::friction_threshold(massless.scene(), SPEED, 50.0);
        println!(
            "{caliper:?}, in series {}, m_p = {PAD_MASS} kg: threshold",
            sim.scene().residual.is_some()
        );
        println!("  μ_c {eig:.9}, own 3-DOF eigen-solve {own:.9} (massless pads: {without:?})");
        assert!((eig - own).abs() < 1e-8 * own, "{eig} vs {own}");
    }
}

/// Re λ of the critical mode and the slope of ln|u_Lᵀ y(t)| in a simulation
/// started on its eigenvector (`support::left_growth`), y = (q̄, q̄̇, ξ, ξ̇)
/// with ξ the pads' compressions from rest (their slot minus
/// x₀ = N₀/(n k_c)).
fn simulated_growth_rate(c: Config, steps: usize) -> (f64, f64) {
    let p = c.section::<PadsConfig>().unwrap();
    let contacts = p.contacts.iter().filter(|c| c.pad == 0).count();
    let rest = CLAMP / (contacts as f64 * p.contact_stiffness);
    left_eigenvector_growth(c, PadLayout::Massive { rest }, steps)
}

#[test]
fn eigenvalues_and_simulation_agree_on_growth_rates_with_pad_mass() {
    for ((caliper, backing), series) in calipers_and_descriptions() {
        let sim = Simulation::new(series(scene(caliper, PAD_MASS, backing, 0.0, &[0.0]))).unwrap();
        let mu_c = stability::friction_threshold(sim.scene(), SPEED, 20.0).unwrap();
        for factor in [0.7, 1.5] {
            // At most e² of growth or decay: the fit stays in the linear range.
            let lam = stability::growth_rate(sim.scene(), SPEED, factor * mu_c, &[CLAMP]);
            let steps = (2.0 / lam.abs() * 1000.0).min(1000.0) as usize;
            let (rate, slope) = simulated_growth_rate(
                series(scene(caliper, PAD_MASS, backing, factor * mu_c, &[0.0])),
                steps,
            );
            println!(
                "{caliper:?}, in series {}, μ",
                sim.scene().residual.is_some()
            );
            println!(
                "  μ = {factor} μ_c = {:.6}: Re λ = {rate:.6} 1/s, simulated {slope:.6} 1/s",
                factor * mu_c
            );
            assert_eq!((rate > 0.0, slope > 0.0), (factor > 1.0, factor > 1.0));
            assert!(
                (slope - rate).abs() < 0.02 * rate.abs(),
                "simulated {slope} vs eigenvalue {rate}"
            );
        }
    }
}

/// (c) As m_p → 0 a floating caliper's pads follow the mean deflection under
/// them: three contacts on one pad, the threshold tends to the massless one.
#[test]
fn vanishing_pad_mass_converges_to_the_massless_thresholds() {
    for series in DESCRIPTIONS {
        vanishing_mass_in(series);
    }
}

fn vanishing_mass_in(series: fn(Config) -> Config) {
    let angles = [-0.2, 0.0, 0.2];
    let massless =
        Simulation::new(series(scene(Caliper::Floating, 0.0, None, 0.0, &angles))).unwrap();
    let target = stability::friction_threshold(massless.scene(), SPEED, 2.0)
        .expect("the massless floating pad squeals");
    let mut previous = f64::INFINITY;
    for mass in [1e-1, 1e-2, 1e-3, 1e-4] {
        let sim =
            Simulation::new(series(scene(Caliper::Floating, mass, None, 0.0, &angles))).unwrap();
        let mu = stability::friction_threshold(sim.scene(), SPEED, 2.0).unwrap();
        let d = (mu - target).abs() / target;
        println!("floating, in series {}, m_p = {mass:e} kg: μ_c = {mu:.9} (massless {target:.9}, relative difference {d:e})", sim.scene().residual.is_some());
        assert!(d < previous, "not converging: {d:e} after {previous:e}");
        previous = d;
    }
    assert!(previous < 1e-3, "{previous:e}");
    // A fixed caliper's massive pad with a stiff backing tends to the massless fixed caliper.
    let massless = Simulation::new(series(scene(Caliper::Fixed, 0.0, None, 0.0, &angles))).unwrap();
    let target = stability::friction_threshold(massless.scene(), SPEED, 5.0).unwrap();
    let mut previous = f64::INFINITY;
    for (mass, backing) in [(1e-2, 1e9), (1e-3, 1e10), (1e-4, 1e11)] {
        let mut c = series(scene(Caliper::Fixed, mass, Some(backing), 0.0, &angles));
        c.simulation.rate_hz = 1.0e5; // only for the stepper's check at construction: the analysis is linear
        let sim = Simulation::new(c).unwrap();
        let mu = stability::friction_threshold(sim.scene(), SPEED, 5.0).unwrap();
        let d = (mu - target).abs() / target;
        println!("fixed, m_p = {mass:e} kg, k_b = {backing:e} N/m: μ_c = {mu:.9} (massless {target:.9}, relative difference {d:e})");
        assert!(d < previous, "not converging: {d:e} after {previous:e}");
        previous = d;
    }
    assert!(previous < 1e-3, "{previous:e}");
}

/// (d) RK4 integrates each description's own ODE, the pads' states with
/// either: independent discretisations converging to one motion at fourth order.
#[test]
fn ale_and_lagrangian_descriptions_converge_to_one_motion_with_massive_pads() {
    for series in DESCRIPTIONS {
        descriptions_converge_in(series);
    }
}

fn descriptions_converge_in(series: fn(Config) -> Config) {
    let sim = Simulation::new(series(scene(
        Caliper::Fixed,
        PAD_MASS,
        Some(BACKING),
        0.0,
        &[0.0],
    )))
    .unwrap();
    let mu = 1.5 * stability::friction_threshold(sim.scene(), SPEED, 2.0).unwrap();
    let config = series(scene(Caliper::Fixed, PAD_MASS, Some(BACKING), mu, &[0.0]));
    // pad travel on the amplitudes' scale
    let travel = |sim: &Simulation, out: &mut Vec<f64>| {
        out.extend(sim.state().load_models.slots[0].iter().map(|x| x * 0.1));
    };
    let last = assert_fourth_order(
        "massive pads, rk4 ALE vs Lagrangian",
        &[20_000.0, 40_000.0, 80_000.0, 160_000.0],
        // One RK4 step per output step: the rate sets h (the pads' coupling
        // bound would otherwise set an inner step independent of the rate).
        |rate| descriptions_differ(&config, rate, 2.5, travel),
    );
    assert!(last < 5e-7);
}

/// (e) Bad pad data is refused naming the key and the rule.
#[test]
fn bad_pad_mass_data_is_refused_naming_the_key() {
    let file = |extra: &str| {
        format!(
            "annular_plate:\n  ros__parameters:\n    plate:\n      residual_flexibility: false\n    simulation:\n      integrator: rk4\n    nodes:\n      ale_radial: [0.6]\n      ale_angular: [0.0]\n    pads:\n      ale_nodes: [1]\n{extra}"
        )
    };
    let c = Config::from_yaml_str(&file("      mass: 0.3\n"), "annular_plate").unwrap();
    assert_eq!(
        (
            c.section::<PadsConfig>().unwrap().mass,
            c.section::<PadsConfig>().unwrap().backing_stiffness
        ),
        (0.3, None)
    );
    let c = Config::from_yaml_str(
        &file("      mass: 0.3\n      caliper: fixed\n      backing_stiffness: 1.0e8\n"),
        "annular_plate",
    )
    .unwrap();
    assert_eq!(
        c.section::<PadsConfig>()
            .cloned()
            .unwrap()
            .backing_stiffness,
        Some(1.0e8)
    );
    let refused = |extra: &str, needles: &[&str]| {
        let e = Config::from_yaml_str(&file(extra), "annular_plate")
            .unwrap_err()
            .to_string();
        assert!(needles.iter().all(|n| e.contains(n)), "{extra:?}: {e}");
    };
    refused("      mass: -0.1\n", &["pads.mass"]);
    refused("      mass: .nan\n", &["pads.mass"]);
    refused("      mass: .inf\n", &["pads.mass"]);
    refused(
        "      mass: 0.3\n      caliper: fixed\n",
        &["pads.backing_stiffness", "pads.caliper: fixed"],
    );
    refused(
        "      mass: 0.3\n      backing_stiffness: 1.0e8\n",
        &["pads.backing_stiffness", "floating"],
    );
    refused(
        "      backing_stiffness: 1.0e8\n",
        &["pads.backing_stiffness", "pads.mass"],
    );
    refused(
        "      mass: 0.3\n      caliper: fixed\n      backing_stiffness: 0.0\n",
        &["pads.backing_stiffness"],
    );
    refused(
        "      mass: 0.3\n      caliper: fixed\n      backing_stiffness: -5.0\n",
        &["pads.backing_stiffness"],
    );
    let other = |plate: &str, integrator: &str| {
        format!(
            "annular_plate:\n  ros__parameters:\n    plate:\n      residual_flexibility: {plate}\n    simulation:\n      integrator: {integrator}\n    nodes:\n      ale_radial: [0.6]\n      ale_angular: [0.0]\n    pads:\n      ale_nodes: [1]\n      mass: 0.3\n"
        )
    };
    for integrator in ["exponential", "implicit_midpoint"] {
        let e = Config::from_yaml_str(&other("false", integrator), "annular_plate")
            .unwrap_err()
            .to_string();
        assert!(
            e.contains("pads.mass") && e.contains("simulation.integrator: rk4"),
            "{e}"
        );
    }
    // In series with the residual flexibility (the default) massive pads are accepted.
    assert_eq!(
        Config::from_yaml_str(&other("true", "rk4"), "annular_plate")
            .unwrap()
            .section::<PadsConfig>()
            .unwrap()
            .mass,
        0.3
    );
    // A configuration built in code is refused by the simulation, naming the key.
    let mut c = scene(Caliper::Floating, PAD_MASS, None, 0.3, &[0.0]);
    c.simulation.integrator = IntegratorKind::Exponential;
    let e = Simulation::new(c).err().expect("refused").to_string();
    assert!(e.contains("pads.mass") && e.contains("rk4"), "{e}");
}

/// The shipped squeal scene (config/brake_squeal.yaml) with a rigid lining,
/// modal pads (`plate.residual_flexibility: false`, which massive pads need) and pad
/// masses of 0.1–1 kg: the thresholds of docs/scenes.md "Pad mass", and a
/// vanishing mass gives back the massless threshold.
#[test]
fn the_shipped_squeal_scene_thresholds_with_pad_mass() {
    let mut c = support::scene_files::load("brake_squeal.yaml");
    c.plate.residual_flexibility = false;
    c.section_mut::<PadsConfig>().unwrap().shear = None;
    let speed = c.joint.speed;
    let massless = Simulation::new(c.clone()).unwrap();
    let target = stability::friction_threshold(massless.scene(), speed, 2.0)
        .expect("the shipped scene squeals below μ = 2");
    let f0 = stability::critical_mode(
        massless.scene(),
        speed,
        target,
        &c.section::<PadsConfig>().unwrap().clamp_force,
    )
    .eigenvalue
    .im / std::f64::consts::TAU;
    println!("massless: μ_c = {target:.6}, {f0:.1} Hz");
    for mass in [1e-4, 0.1, 0.2, 0.3, 0.5, 1.0] {
        let mut m = c.clone();
        m.section_mut::<PadsConfig>().unwrap().mass = mass;
        let sim = Simulation::new(m.clone()).unwrap();
        let mu = stability::friction_threshold(sim.scene(), speed, 2.0);
        let f = mu.map(|mu| {
            stability::critical_mode(
                sim.scene(),
                speed,
                mu,
                &m.section::<PadsConfig>().unwrap().clamp_force,
            )
            .eigenvalue
            .im / std::f64::consts::TAU
        });
        let rate = stability::growth_rate(
            sim.scene(),
            speed,
            0.5,
            &m.section::<PadsConfig>().unwrap().clamp_force,
        );
        println!("m_p = {mass} kg: μ_c = {mu:?}, {f:?} Hz; Re λ at μ = 0.5: {rate:.3} 1/s");
        if mass == 1e-4 {
            let mu = mu.unwrap();
            assert!(
                (mu - target).abs() < 1e-3 * target,
                "{mu} vs massless {target}"
            );
        }
        // The 18 points round the whole disc: Σ_c w_c = 0 for every k ≥ 1 mode,
        // so a rigid pad's axial motion is not excited and the mass has no effect.
        assert!(
            (mu.unwrap() - target).abs() < 1e-9 * target,
            "{mu:?} vs massless {target}"
        );
    }
    // The shipped file as it is, in series with the residual flexibility:
    // the ring again leaves the threshold to the massless one.
    let mut shipped = support::scene_files::load("brake_squeal.yaml");
    shipped.section_mut::<PadsConfig>().unwrap().shear = None;
    let clamp = shipped.section::<PadsConfig>().unwrap().clamp_force.clone();
    let massless = stability::friction_threshold(
        Simulation::new(shipped.clone()).unwrap().scene(),
        speed,
        2.0,
    )
    .unwrap();
    let mut heavy = shipped.clone();
    heavy.section_mut::<PadsConfig>().unwrap().mass = 0.3;
    let sim = Simulation::new(heavy).unwrap();
    let mu = stability::friction_threshold(sim.scene(), speed, 2.0).unwrap();
    println!("in series, m_p = 0.3 kg: μ_c = {mu:.9} (massless {massless:.9}); Re λ at μ = 0.5: {:.3} 1/s", stability::growth_rate(sim.scene(), speed, 0.5, &clamp));
    assert!(
        (mu - massless).abs() < 1e-9 * massless,
        "{mu} vs massless {massless}"
    );
    // The same pad data on a 60° arc (the 18 points at the centres of equal
    // sub-arcs about θ = 0): there the pad's axial motion couples.
    for (caliper, backing) in [(Caliper::Floating, None), (Caliper::Fixed, Some(2.0e8))] {
        let mut arc = c.clone();
        for (i, node) in arc.nodes.ale.iter_mut().enumerate() {
            node.angular = ((i as f64 + 0.5) / 18.0 - 0.5) * 60.0 / 360.0;
        }
        arc.section_mut::<PadsConfig>().unwrap().caliper = caliper;
        let clamp = arc.section::<PadsConfig>().unwrap().clamp_force.clone();
        let mut massless_mu = None;
        for mass in [0.0, 1e-4, 0.1, 0.2, 0.3, 0.5, 1.0] {
            let mut m = arc.clone();
            m.section_mut::<PadsConfig>().unwrap().mass = mass;
            m.section_mut::<PadsConfig>().unwrap().backing_stiffness =
                if mass > 0.0 { backing } else { None };
            let sim = Simulation::new(m).unwrap();
            let mu = stability::friction_threshold(sim.scene(), speed, 5.0);
            let f = mu.map(|mu| {
                stability::critical_mode(sim.scene(), speed, mu, &clamp)
                    .eigenvalue
                    .im
                    / std::f64::consts::TAU
            });
            println!(
                "60° arc, {caliper:?} (k_b {backing:?}), m_p = {mass} kg: μ_c = {mu:?}, {f:?} Hz"
            );
            if mass == 0.0 {
                massless_mu = mu;
            }
            if mass == 1e-4 && caliper == Caliper::Floating {
                match (mu, massless_mu) {
                    (Some(mu), Some(target)) => assert!(
                        (mu - target).abs() < 1e-3 * target,
                        "{mu} vs massless {target}"
                    ),
                    (None, None) => {}
                    other => {
                        panic!("m_p → 0 does not give the massless floating caliper: {other:?}")
                    }
                }
            }
        }
    }
}

/// `simulate` writes the massive pads' compressions (m), x₀ = N₀/(n k_c) at
/// rest, and no such columns for massless pads.
#[test]
fn simulate_writes_the_massive_pads_compressions() {
    let run = |extra: &[&str]| {
        let out = std::process::Command::new(env!("CARGO_BIN_EXE_annular_plate"))
            .arg("simulate")
            .arg(support::scene_files::path("brake_squeal.yaml"))
            .args([
                "--duration",
                "0",
                "--csv",
                "-",
                "--quiet",
                "-p",
                "plate.residual_flexibility:=false",
            ])
            .args(extra)
            .output()
            .unwrap();
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        String::from_utf8(out.stdout).unwrap()
    };
    let text = run(&["-p", "pads.mass:=0.3"]);
    let mut lines = text.lines();
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    let row: Vec<f64> = lines
        .next()
        .unwrap()
        .split(',')
        .map(|v| v.parse().unwrap())
        .collect();
    let x0 = 5000.0 / (18.0 * 2.78e6);
    for name in ["pad1_top_compression", "pad1_bottom_compression"] {
        let i = header
            .iter()
            .position(|h| *h == name)
            .unwrap_or_else(|| panic!("no {name} in {header:?}"));
        assert_eq!(annular_plate::cli::simulate::column_unit(name), Some("m"));
        assert!(
            (row[i] - x0).abs() < 1e-15,
            "{name} = {} vs x₀ = {x0}",
            row[i]
        );
    }
    assert!(!run(&[]).lines().next().unwrap().contains("compression"));
}
