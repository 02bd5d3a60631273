//! Centrifugal stiffening of the spinning annulus against
//! independent solutions written here:
//!
//! * the Lamé prestress against the textbook stress-function form
//!   σ_r = C₁ + C₂/r² − (3+ν)/8 ρΩ²r², σ_θ = C₁ − C₂/r² − (1+3ν)/8 ρΩ²r²
//!   (Timoshenko & Goodier §32) with its own edge conditions;
//! * the slope d(ω²)/d(Ω²) at small speed against the Southwell coefficient
//!   λ = h∫(σ_r R'² + σ_θ k²R²/r²) r dr / (ρh ∫R² r dr), with the exact
//!   (Bessel) unstiffened mode shape R and Gauss–Legendre quadrature;
//! * the frequencies at high speed against a shooting solution of the
//!   prestressed plate equation D∇⁴w − h[(1/r)(rσ_r w_r)_r + σ_θ w_φφ/r²] = ρhω²w
//!   (RK4 on the radial ODE, determinant of the outer edge conditions), and
//!   their convergence in `plate.radial_splines`;
//! * the issue's first-order estimates of the lathe and swash-plate critical speeds.
//! * in the dynamics: a free vibration at constant speed rings at the Ritz
//!   frequency of the retained modes (exponential: to round-off) and converges
//!   to the shooting solution as l are added; the linearised system's
//!   eigenvalues are the stiffened ω ± kΩ.
//!
//! Run with `-- --nocapture` for the tables.

mod support;

use annular_plate::config::{
    Boundary, CentrifugalConfig, Config, Coordinates, InPlaneInner, InPlaneOuter, IntegratorKind,
    PlateConfig,
};
use annular_plate::dynamics::Simulation;
use annular_plate::model::prestress::LamePrestress;
use annular_plate::model::AngularShape;
use annular_plate::model::{ModalGeometricStiffness, PlateModel, SpinningSpectrum};
use support::exact_plate::{gauss_legendre, Annulus};
use support::lame::{inner_fixed, Lame};
use support::library_plate::edge;

fn lathe() -> PlateConfig {
    PlateConfig::lathe_disc()
}

fn swash() -> PlateConfig {
    let mut p = PlateConfig::lathe_disc();
    p.inner_radius = 0.1;
    p.outer_radius = 0.39;
    p.inner_boundary = Boundary::Supported;
    p.nodal_circles = vec![0];
    p
}

fn free_free() -> PlateConfig {
    let mut p = PlateConfig::lathe_disc();
    p.inner_radius = 0.045;
    p.inner_boundary = Boundary::Free;
    p.nodal_diameters = vec![0, 2, 3];
    p
}

fn on() -> CentrifugalConfig {
    CentrifugalConfig {
        stiffening: true,
        in_plane_inner: InPlaneInner::Auto,
        in_plane_outer: InPlaneOuter::Free,
    }
}

#[test]
fn lame_prestress_matches_the_textbook_stress_function() {
    for (name, p, fixed) in [
        ("lathe, hub", lathe(), true),
        ("lathe, free hole", lathe(), false),
        ("swash, hub", swash(), true),
        ("free–free", free_free(), false),
    ] {
        let cfg = CentrifugalConfig {
            stiffening: true,
            in_plane_inner: if fixed {
                InPlaneInner::Fixed
            } else {
                InPlaneInner::Free
            },
            in_plane_outer: InPlaneOuter::Free,
        };
        let lib = LamePrestress::new(&p, &cfg);
        let exact = Lame::new(&p, fixed);
        let scale = p.density * p.outer_radius.powi(2);
        let mut worst: f64 = 0.0;
        for i in 0..=50 {
            let r = p.inner_radius + (p.outer_radius - p.inner_radius) * i as f64 / 50.0;
            let (sr, st) = lib.stresses(r);
            let (er, et, _) = exact.at(r);
            worst = worst.max((sr - er).abs().max((st - et).abs()) / scale);
        }
        println!("{name}: max |σ − σ_exact| / ρr_a² = {worst:.2e}");
        assert!(worst < 1e-13, "{name}: {worst}");
        // Edge conditions of the library's own solution.
        assert!(lib.stresses(p.outer_radius).0.abs() < 1e-13 * scale);
        if fixed {
            assert!(
                lib.displacement(p.inner_radius).abs()
                    < 1e-13 * p.density * p.outer_radius.powi(3) / p.youngs_modulus
            );
        } else {
            assert!(lib.stresses(p.inner_radius).0.abs() < 1e-13 * scale);
        }
    }
    // The classical free-hole disc: σ_r = (3+ν)/8 ρ (r_i² + r_a² − r_i²r_a²/r² − r²).
    let p = lathe();
    let lib = LamePrestress::new(
        &p,
        &CentrifugalConfig {
            stiffening: true,
            in_plane_inner: InPlaneInner::Free,
            in_plane_outer: InPlaneOuter::Free,
        },
    );
    let (ri, ra, nu) = (p.inner_radius, p.outer_radius, p.poisson_ratio);
    let r = 0.11;
    let classical =
        (3.0 + nu) / 8.0 * p.density * (ri * ri + ra * ra - ri * ri * ra * ra / (r * r) - r * r);
    assert!((lib.stresses(r).0 - classical).abs() < 1e-12 * classical.abs());
    // `auto` follows the bending inner edge.
    assert!(LamePrestress::new(&lathe(), &on()).inner_fixed);
    assert!(LamePrestress::new(&swash(), &on()).inner_fixed);
    assert!(!LamePrestress::new(&free_free(), &on()).inner_fixed);
}

/// The exact unstiffened shape's Southwell coefficient (rad²/s² per (rad/s)²).
fn exact_southwell(p: &PlateConfig, fixed: bool, k: u32, l: u32) -> (f64, f64) {
    let annulus = Annulus::new(
        p.inner_radius,
        p.outer_radius,
        p.poisson_ratio,
        edge(p.inner_boundary),
        edge(p.outer_boundary),
    );
    let lambdas = annulus.lambdas(k, 60.0 / p.outer_radius);
    let lambda = lambdas[l as usize];
    let shape = annulus.radial_shape(k, lambda);
    let lame = Lame::new(p, fixed);
    let (ri, ra) = (p.inner_radius, p.outer_radius);
    let k2 = (k as f64).powi(2);
    let (xs, ws) = gauss_legendre(12);
    let cells = 200;
    let (mut g, mut m) = (0.0, 0.0);
    for c in 0..cells {
        let (c0, c1) = (
            ri + (ra - ri) * c as f64 / cells as f64,
            ri + (ra - ri) * (c + 1) as f64 / cells as f64,
        );
        for (x, w) in xs.iter().zip(&ws) {
            let r = 0.5 * (c0 + c1) + 0.5 * (c1 - c0) * x;
            let wr = 0.5 * (c1 - c0) * w * r;
            let [v, d1, ..] = shape.derivatives(r);
            let (sr, st, _) = lame.at(r);
            g += wr * (sr * d1 * d1 + st * k2 * v * v / (r * r));
            m += wr * v * v;
        }
    }
    let rigidity =
        p.youngs_modulus * p.thickness.powi(3) / (12.0 * (1.0 - p.poisson_ratio.powi(2)));
    let omega0 = lambda * lambda * (rigidity / (p.density * p.thickness)).sqrt();
    (g / (p.density * m), omega0)
}

/// λΩ²/ω₀² at the small speed of the slope (with Richardson extrapolation, the
/// O(Ω⁴) remainder is ~1e-4 of it; a smaller step loses digits to round-off).
const SLOPE_STEP: f64 = 1e-2;

#[test]
fn slope_at_small_speed_is_the_southwell_coefficient_of_the_exact_mode() {
    type Case = (&'static str, PlateConfig, Vec<(u32, u32)>);
    let cases: Vec<Case> = vec![
        (
            "lathe (clamped, hub)",
            lathe(),
            vec![(0, 0), (1, 0), (2, 0), (3, 0), (4, 0), (0, 1), (3, 1)],
        ),
        (
            "swash plate (supported, hub)",
            swash(),
            vec![(0, 0), (1, 0), (2, 0), (3, 0)],
        ),
        (
            "free–free (free hole)",
            free_free(),
            vec![(0, 1), (2, 0), (3, 0)],
        ),
    ];
    println!("case | ⟨k,l⟩ | λ exact (Bessel, Lamé) | slope of the model's ω² | projected G_ll/m | rel. diffs");
    for (name, p, modes) in cases {
        let fixed = inner_fixed(&p);
        let model = PlateModel::new(&p).unwrap();
        let projected = ModalGeometricStiffness::new(&model, &on());
        for (k, l) in modes {
            let (exact, omega0) = exact_southwell(&p, fixed, k, l);
            let spectrum = SpinningSpectrum::new(&p, &on(), k, l as usize + 1);
            // Small speed: λΩ²/ω₀² = SLOPE_STEP.
            let spin = (SLOPE_STEP * omega0 * omega0 / exact.abs().max(1.0)).sqrt();
            let w2 = |s: f64| spectrum.omega_squared(s).unwrap()[l as usize];
            // Richardson over Ω and Ω/2 removes the O(Ω²) curvature term of the slope.
            let slope = |s: f64| (w2(s) - w2(0.0)) / (s * s);
            let slope = (4.0 * slope(0.5 * spin) - slope(spin)) / 3.0;
            let proj = projected.southwell(&model, k, l).unwrap();
            let (e1, e2) = (
                (slope - exact).abs() / exact.abs(),
                (proj - exact).abs() / exact.abs(),
            );
            println!(
                "{name} | ⟨{k},{l}⟩ | {exact:.9} | {slope:.9} | {proj:.9} | {e1:.1e} {e2:.1e}"
            );
            // Measured: ≤ 1.8e-6 (the 32-spline mode shape's error enters λ to first order).
            assert!(
                e1 < 5e-6,
                "{name} ⟨{k},{l}⟩: slope {slope} vs Southwell {exact}"
            );
            assert!(
                e2 < 5e-6,
                "{name} ⟨{k},{l}⟩: projected {proj} vs Southwell {exact}"
            );
            // Hellmann–Feynman: the slope of the discrete eigenvalue is the projection of its own eigenvector.
            assert!(
                (slope - proj).abs() < 1e-6 * exact.abs(),
                "{name} ⟨{k},{l}⟩: slope {slope} vs projected {proj}"
            );
        }
    }
}

#[test]
fn bad_centrifugal_keys_are_refused_with_their_name_and_rule() {
    use annular_plate::config::Config;
    let file = |body: &str| format!("/**:\n  ros__parameters:\n    plate:\n{body}\n");
    let err = Config::from_yaml_str(&file("      in_plane_inner: hub"), "annular_plate")
        .unwrap_err()
        .to_string();
    assert!(
        err.contains("plate.in_plane_inner") && err.contains("fixed") && err.contains("free"),
        "{err}"
    );
    let err = Config::from_yaml_str(&file("      centrifugal_stiffening: 1"), "annular_plate")
        .unwrap_err()
        .to_string();
    assert!(
        err.contains("plate.centrifugal_stiffening") && err.contains("bool"),
        "{err}"
    );
    let c = Config::from_yaml_str(
        &file("      centrifugal_stiffening: true\n      in_plane_inner: free"),
        "annular_plate",
    )
    .unwrap();
    assert_eq!(
        c.centrifugal,
        CentrifugalConfig {
            stiffening: true,
            in_plane_inner: InPlaneInner::Free,
            in_plane_outer: InPlaneOuter::Free,
        }
    );
    assert_eq!(
        Config::default().centrifugal,
        CentrifugalConfig {
            stiffening: false,
            in_plane_inner: InPlaneInner::Auto,
            in_plane_outer: InPlaneOuter::Free,
        }
    );
}

/// Shooting solution of the prestressed plate's radial equation
/// D∇_k⁴R − h[σ_r R'' + (σ_r' + σ_r/r) R' − σ_θ k² R/r²] Ω² = ρhω² R,
/// ∇_k⁴R = R'''' + 2R'''/r − (1+2k²)R''/r² + (1+2k²)R'/r³ + (k⁴ − 4k²)R/r⁴,
/// RK4 from the inner edge (two solutions meeting its conditions) to the free
/// outer edge (M_r = V_r = 0; σ_r(r_a) = 0, so the membrane adds no edge term).
struct Shooting {
    p: PlateConfig,
    lame: Lame,
    k: u32,
    steps: usize,
}

impl Shooting {
    fn new(p: &PlateConfig, k: u32) -> Shooting {
        Shooting {
            p: p.clone(),
            lame: Lame::new(p, inner_fixed(p)),
            k,
            steps: 4000,
        }
    }

    fn rigidity(&self) -> f64 {
        self.p.youngs_modulus * self.p.thickness.powi(3)
            / (12.0 * (1.0 - self.p.poisson_ratio.powi(2)))
    }

    fn rhs(&self, r: f64, y: [f64; 4], spin2: f64, omega2: f64) -> [f64; 4] {
        let k2 = (self.k as f64).powi(2);
        let (d, h, rho) = (self.rigidity(), self.p.thickness, self.p.density);
        let (sr, st, dsr) = self.lame.at(r);
        let [v, d1, d2, d3] = y;
        let bending_rest = 2.0 * d3 / r - (1.0 + 2.0 * k2) * d2 / (r * r)
            + (1.0 + 2.0 * k2) * d1 / r.powi(3)
            + (k2 * k2 - 4.0 * k2) * v / r.powi(4);
        let membrane = h * spin2 * (sr * d2 + (dsr + sr / r) * d1 - st * k2 * v / (r * r));
        [
            d1,
            d2,
            d3,
            -bending_rest + (membrane + rho * h * omega2 * v) / d,
        ]
    }

    fn integrate(&self, mut y: [f64; 4], spin2: f64, omega2: f64) -> [f64; 4] {
        let (ri, ra) = (self.p.inner_radius, self.p.outer_radius);
        let dr = (ra - ri) / self.steps as f64;
        let add = |a: [f64; 4], b: [f64; 4], s: f64| {
            [
                a[0] + s * b[0],
                a[1] + s * b[1],
                a[2] + s * b[2],
                a[3] + s * b[3],
            ]
        };
        for i in 0..self.steps {
            let r = ri + dr * i as f64;
            let k1 = self.rhs(r, y, spin2, omega2);
            let k2 = self.rhs(r + 0.5 * dr, add(y, k1, 0.5 * dr), spin2, omega2);
            let k3 = self.rhs(r + 0.5 * dr, add(y, k2, 0.5 * dr), spin2, omega2);
            let k4 = self.rhs(r + dr, add(y, k3, dr), spin2, omega2);
            for j in 0..4 {
                y[j] += dr / 6.0 * (k1[j] + 2.0 * k2[j] + 2.0 * k3[j] + k4[j]);
            }
        }
        y
    }

    /// Two initial vectors [R, R', R'', R'''] meeting the inner edge's conditions.
    fn starts(&self) -> [[f64; 4]; 2] {
        let (r, nu, k2) = (
            self.p.inner_radius,
            self.p.poisson_ratio,
            (self.k as f64).powi(2),
        );
        match self.p.inner_boundary {
            Boundary::Clamped => [[0.0, 0.0, 1.0, 0.0], [0.0, 0.0, 0.0, 1.0]],
            Boundary::Supported => [[0.0, 1.0, -nu / r, 0.0], [0.0, 0.0, 0.0, 1.0]],
            Boundary::Free => [[1.0, 0.0], [0.0, 1.0]].map(|[v, d1]| {
                let d2 = -nu * (d1 / r - k2 * v / (r * r));
                let d3 = -d2 / r + (1.0 + (2.0 - nu) * k2) * d1 / (r * r)
                    - (3.0 - nu) * k2 * v / r.powi(3);
                [v, d1, d2, d3]
            }),
            Boundary::SupportedSoft => unreachable!("Kirchhoff edges only"),
        }
    }

    /// det of the outer edge's [M_r, V_r] over the two solutions.
    fn determinant(&self, spin2: f64, omega2: f64) -> f64 {
        let (r, nu, k2) = (
            self.p.outer_radius,
            self.p.poisson_ratio,
            (self.k as f64).powi(2),
        );
        let [a, b] = self.starts().map(|y0| {
            let [v, d1, d2, d3] = self.integrate(y0, spin2, omega2);
            let m = d2 + nu * (d1 / r - k2 * v / (r * r));
            let s = d3 + d2 / r - (1.0 + (2.0 - nu) * k2) * d1 / (r * r)
                + (3.0 - nu) * k2 * v / r.powi(3);
            [m, s]
        });
        a[0] * b[1] - a[1] * b[0]
    }

    /// The root of f in [lo, hi] (a sign change on a 40-point scan nearest `guess`, then bisection).
    fn root(f: impl Fn(f64) -> f64, guess: f64, lo: f64, hi: f64) -> f64 {
        let n = 40;
        let xs: Vec<f64> = (0..=n)
            .map(|i| lo + (hi - lo) * i as f64 / n as f64)
            .collect();
        let fs: Vec<f64> = xs.iter().map(|&x| f(x)).collect();
        let (mut a, mut b) = (0..n)
            .filter(|&i| fs[i].signum() != fs[i + 1].signum())
            .map(|i| (xs[i], xs[i + 1]))
            .min_by(|x, y| (x.0 - guess).abs().total_cmp(&(y.0 - guess).abs()))
            .expect("no sign change of the shooting determinant near the model's value");
        let fa = f(a);
        for _ in 0..80 {
            let m = 0.5 * (a + b);
            if f(m).signum() == fa.signum() {
                a = m;
            } else {
                b = m;
            }
        }
        0.5 * (a + b)
    }

    /// ω² at spin speed Ω near `guess`.
    fn omega_squared(&self, spin: f64, guess: f64) -> f64 {
        Self::root(
            |w2| self.determinant(spin * spin, w2),
            guess,
            0.97 * guess,
            1.03 * guess,
        )
    }

    /// The critical speed (ω(Ω) = kΩ) near `guess`.
    fn critical_speed(&self, guess: f64) -> f64 {
        let k2 = (self.k as f64).powi(2);
        Self::root(
            |s| self.determinant(s * s, k2 * s * s),
            guess,
            0.97 * guess,
            1.03 * guess,
        )
    }
}

#[test]
fn shooting_reference_reproduces_the_exact_frequencies_at_rest() {
    for (p, k) in [(lathe(), 3), (swash(), 2), (free_free(), 2)] {
        let annulus = Annulus::new(
            p.inner_radius,
            p.outer_radius,
            p.poisson_ratio,
            edge(p.inner_boundary),
            edge(p.outer_boundary),
        );
        let lambda = annulus.lambdas(k, 60.0 / p.outer_radius)[0];
        let shooting = Shooting::new(&p, k);
        let exact = lambda.powi(4) * shooting.rigidity() / (p.density * p.thickness);
        let shot = shooting.omega_squared(0.0, exact * 1.01);
        println!("k = {k}: ω² shooting {shot:.10e}, Bessel {exact:.10e}");
        assert!((shot - exact).abs() < 1e-9 * exact, "{shot} vs {exact}");
    }
}

#[test]
fn frequencies_at_high_speed_converge_to_the_prestressed_plate_equation() {
    // (plate, k, l, speed): the critical speeds of the issue and beyond.
    let cases = [
        ("lathe", lathe(), 3u32, 0usize, 5540.0),
        ("lathe", lathe(), 3, 1, 5540.0),
        ("lathe", lathe(), 0, 1, 11000.0),
        ("swash plate", swash(), 2, 0, 458.0),
        ("swash plate", swash(), 2, 0, 1400.0),
        ("free–free", free_free(), 3, 0, 4000.0),
    ];
    println!(
        "plate | ⟨k,l⟩ | Ω rad/s | shooting ω Hz | rel. error at radial_splines 12, 16, 24, 32, 48"
    );
    for (name, p, k, l, spin) in cases {
        let reference_guess = SpinningSpectrum::new(&p, &on(), k, l + 1)
            .omega_squared(spin)
            .unwrap()[l];
        let shooting = Shooting::new(&p, k).omega_squared(spin, reference_guess);
        let errors: Vec<f64> = [12usize, 16, 24, 32, 48]
            .iter()
            .map(|&n| {
                let mut q = p.clone();
                q.radial_splines = annular_plate::config::RadialSplines::Fixed(n);
                let w2 = SpinningSpectrum::new(&q, &on(), k, l + 1)
                    .omega_squared(spin)
                    .unwrap()[l];
                ((w2.sqrt() - shooting.sqrt()) / shooting.sqrt()).abs()
            })
            .collect();
        let err_text: Vec<String> = errors.iter().map(|e| format!("{e:.1e}")).collect();
        println!(
            "{name} | ⟨{k},{l}⟩ | {spin} | {:.4} | {}",
            shooting.sqrt() / std::f64::consts::TAU,
            err_text.join(" ")
        );
        // Converges: each refinement reduces the error; the default 32 splines are within 1e-6.
        assert!(
            errors.windows(2).all(|w| w[0] > w[1]),
            "{name} ⟨{k},{l}⟩: not converging: {errors:?}"
        );
        assert!(errors[3] < 1e-6, "{name} ⟨{k},{l}⟩ at {spin}: {errors:?}");
    }
}

#[test]
fn critical_speeds_match_shooting_and_the_issue_estimates() {
    // (plate, k, issue's unstiffened and first-order estimates).
    for (name, p, k, unstiffened, estimate) in [
        ("lathe", lathe(), 3u32, 4304.0, 5540.0),
        ("swash plate", swash(), 2, 302.0, 458.0),
    ] {
        let spectrum = SpinningSpectrum::new(&p, &on(), k, 1);
        let model = spectrum.critical_speed(0).unwrap().unwrap();
        let off = SpinningSpectrum::new(&p, &CentrifugalConfig::default(), k, 1);
        // The stiffening flag does not enter the spectrum: the caller decides; at Ω = 0 both agree.
        let w0 = off.omega_squared(0.0).unwrap()[0].sqrt();
        let shot = Shooting::new(&p, k).critical_speed(model);
        let (sw, _) = exact_southwell(&p, true, k, 0);
        let first_order = w0 / ((k * k) as f64 - sw).sqrt();
        println!(
            "{name} ⟨{k},0⟩: ω₀/k = {:.1}, first-order {first_order:.1}, model {model:.4}, shooting {shot:.4} rad/s (issue: {unstiffened} → ≈{estimate})",
            w0 / k as f64
        );
        assert!((w0 / k as f64 - unstiffened).abs() < 0.5, "{name}: ω₀/k");
        // The issue quotes its estimates to 3–4 digits.
        assert!(
            (first_order - estimate).abs() < 2.0,
            "{name}: first-order estimate {first_order}"
        );
        assert!(
            (model - shot).abs() < 1e-6 * shot,
            "{name}: model {model} vs shooting {shot}"
        );
    }
}

/// A stiffened lathe-disc scene with ⟨k, l⟩ for l < `circles`, undamped, turning at `speed`.
fn stiffened_scene(k: u32, circles: u32, speed: f64) -> Config {
    let mut c = Config::default();
    c.plate.nodal_diameters = vec![k];
    c.plate.nodal_circles = (0..circles).collect();
    c.plate.damping = vec![0.0];
    c.centrifugal = on();
    c.joint.speed = speed;
    c.simulation.realtime_factor = 0.0;
    c
}

/// The Ritz eigenvector of the retained ⟨k, ·⟩ cos family at speed Ω and its
/// ω²: (diag(mω²) + Ω²G) v = ω² diag(m) v from the model's G (only to start
/// the run in one stiffened mode; the frequency is then measured).
fn ritz_mode(sim: &Simulation, speed: f64) -> (Vec<f64>, f64) {
    let model = sim.model();
    let g = ModalGeometricStiffness::new(model, &on());
    let b = &g.blocks[0];
    let n = b.ls.len();
    let modes: Vec<usize> =
        b.ls.iter()
            .map(|&l| {
                model
                    .modes()
                    .iter()
                    .position(|m| m.l == l && m.shape == AngularShape::Cos)
                    .unwrap()
            })
            .collect();
    let m: Vec<f64> = modes.iter().map(|&i| model.modes()[i].modal_mass).collect();
    let s = nalgebra::DMatrix::from_fn(n, n, |a, c| {
        let own = if a == c {
            m[a] * model.modes()[modes[a]].omega.powi(2)
        } else {
            0.0
        };
        (own + speed * speed * b.matrix[a * n + c]) / (m[a] * m[c]).sqrt()
    });
    let eig = s.symmetric_eigen();
    let lowest = (0..n)
        .min_by(|&x, &y| eig.eigenvalues[x].total_cmp(&eig.eigenvalues[y]))
        .unwrap();
    let mut q = vec![0.0; model.n_modes()];
    for a in 0..n {
        q[modes[a]] = 1e-6 * eig.eigenvectors[(a, lowest)] / m[a].sqrt();
    }
    (q, eig.eigenvalues[lowest])
}

/// ω of a sampled free vibration q_j = A cos(ω jτ + φ): least squares of the
/// three-term recurrence q_{j+1} + q_{j−1} = 2 cos(ωτ) q_j.
fn recurrence_frequency(q: &[f64], tau: f64) -> f64 {
    let (num, den) = q.windows(3).fold((0.0, 0.0), |(n, d), w| {
        (n + w[1] * (w[0] + w[2]), d + 2.0 * w[1] * w[1])
    });
    (num / den).acos() / tau
}

#[test]
fn free_vibration_at_constant_speed_rings_at_the_stiffened_frequency() {
    // Lathe ⟨3, 0⟩ at 4000 rad/s (ω₀ = 12,912 rad/s, +16 % from the prestress),
    // integrated in Lagrangian (rotating-frame) coordinates; the retained
    // ⟨3, l⟩, l < L, are the Ritz basis of the prestressed problem.
    let (k, speed, rate) = (3u32, 4000.0, 20_000.0);
    let p = lathe();
    let spectrum = SpinningSpectrum::new(&p, &on(), k, 1)
        .omega_squared(speed)
        .unwrap()[0];
    let shot = Shooting::new(&p, k).omega_squared(speed, spectrum);
    let w_rest = SpinningSpectrum::new(&p, &on(), k, 1)
        .omega_squared(0.0)
        .unwrap()[0]
        .sqrt();
    println!(
        "⟨3,0⟩ at {speed} rad/s: ω at rest {w_rest:.3}, spectrum {:.6}, shooting {:.6} rad/s",
        spectrum.sqrt(),
        shot.sqrt()
    );
    println!("L | integrator | simulated ω | vs Ritz | vs spectrum | vs shooting");
    let mut errors = vec![];
    for circles in [1u32, 2, 4] {
        for integrator in [
            IntegratorKind::Exponential,
            IntegratorKind::Rk4,
            IntegratorKind::ImplicitMidpoint,
        ] {
            let mut c = stiffened_scene(k, circles, speed);
            c.simulation.rate_hz = rate;
            c.simulation.coordinates = Coordinates::Lagrangian;
            c.simulation.integrator = integrator;
            let sim = Simulation::new(c.clone()).expect("a stiffened scene runs");
            let (q0, ritz) = ritz_mode(&sim, speed);
            c.initial.q = q0;
            let mut sim = Simulation::new(c).unwrap();
            let i = sim
                .model()
                .modes()
                .iter()
                .position(|m| m.l == 0 && m.shape == AngularShape::Cos)
                .unwrap();
            let mut history = vec![sim.q_lagrange()[i]];
            for _ in 0..2000 {
                sim.step().unwrap();
                history.push(sim.q_lagrange()[i]);
            }
            let w = recurrence_frequency(&history, 1.0 / rate);
            let rel = |x: f64| (w - x.sqrt()) / x.sqrt();
            println!(
                "{circles} | {integrator:?} | {w:.6} | {:.1e} | {:.1e} | {:.1e}",
                rel(ritz),
                rel(spectrum),
                rel(shot)
            );
            // Not vacuous: the unstiffened frequency is 14 % lower.
            assert!(w > 1.1 * w_rest);
            match integrator {
                // Exact for the modal part: the Ritz frequency of the retained modes to round-off.
                IntegratorKind::Exponential | IntegratorKind::ContactExponential => {
                    assert!(
                        rel(ritz).abs() < 1e-9,
                        "L = {circles}: {w} vs Ritz {}",
                        ritz.sqrt()
                    );
                    errors.push(rel(shot).abs());
                }
                // Their own frequency errors at the inner step they choose
                // (h·λ_max ≤ 0.2 and 0.5 by default, λ_max including the
                // stiffening): RK4 below (hω)⁴/120 ≤ 1.3e-5, the midpoint
                // rule below (hω)²/12 ≤ 2.1e-2 (docs/dynamics.md).
                IntegratorKind::Rk4 => assert!(rel(ritz).abs() < 1.3e-5, "rk4 L = {circles}: {w}"),
                IntegratorKind::ImplicitMidpoint => {
                    assert!(rel(ritz).abs() < 2.1e-2, "midpoint L = {circles}: {w}")
                }
            }
        }
    }
    // The Ritz value converges to the prestressed plate's from above as l are added.
    assert!(errors.windows(2).all(|e| e[1] < e[0]), "{errors:?}");
    assert!(errors[errors.len() - 1] < 1e-5, "{errors:?}");
}

#[test]
fn a_stiffened_scene_runs_and_is_the_unstiffened_one_at_rest() {
    // At Ω = 0 the prestress vanishes: the stiffened run is the unstiffened
    // one (to the round-off of the block propagator); spinning, it differs.
    let run = |stiffening: bool, speed: f64, integrator: IntegratorKind, coords: Coordinates| {
        // The paper's lathe disc (30 modes) under a space-fixed rim load.
        let mut c = Config::default();
        c.simulation.integrator = integrator;
        c.simulation.coordinates = coords;
        c.plate.damping = vec![0.02];
        c.nodes.ale.push(annular_plate::config::NodePosition {
            radial: 1.0,
            angular: 0.3,
        });
        c.loads.ale.push(annular_plate::config::WrenchConfig {
            force: [0.0, 0.0, -100.0],
            moment: [0.0; 3],
        });
        c.centrifugal.stiffening = stiffening;
        c.joint.speed = speed;
        let mut sim = Simulation::new(c).expect("runs");
        for _ in 0..200 {
            sim.step().unwrap();
        }
        sim.q_lagrange().to_vec()
    };
    let scale = |q: &[f64]| q.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    let diff = |a: &[f64], b: &[f64]| {
        a.iter()
            .zip(b)
            .fold(0.0f64, |m, (x, y)| m.max((x - y).abs()))
            / scale(b)
    };
    for integrator in [
        IntegratorKind::Exponential,
        IntegratorKind::ImplicitMidpoint,
        IntegratorKind::Rk4,
    ] {
        for coords in [Coordinates::Ale, Coordinates::Lagrangian] {
            let (on_rest, off_rest) = (
                run(true, 0.0, integrator, coords),
                run(false, 0.0, integrator, coords),
            );
            let (on_spin, off_spin) = (
                run(true, 4000.0, integrator, coords),
                run(false, 4000.0, integrator, coords),
            );
            println!(
                "{integrator:?}/{coords:?}: stiffened vs not: at rest {:.1e}, at 4000 rad/s {:.1e}",
                diff(&on_rest, &off_rest),
                diff(&on_spin, &off_spin)
            );
            assert!(scale(&off_rest) > 0.0);
            assert!(diff(&on_rest, &off_rest) < 1e-10);
            assert!(diff(&on_spin, &off_spin) > 1e-2);
        }
    }
}

#[test]
fn the_linearised_system_carries_the_stiffening_its_eigenvalues_are_the_ritz_frequencies_plus_minus_k_omega(
) {
    // No pads, no damping: in ALE coordinates the eigenvalues are ±i(ω_l(Ω) ± kΩ)
    // with ω_l(Ω) the stiffened Ritz frequencies of the retained ⟨3, l⟩.
    let speed = 4000.0;
    let c = stiffened_scene(3, 2, speed);
    let sim = Simulation::new(c.clone()).unwrap();
    let model = sim.model();
    let g = ModalGeometricStiffness::new(model, &on());
    let b = &g.blocks[0];
    let m: Vec<f64> =
        b.ls.iter()
            .map(|&l| model.modes().iter().find(|x| x.l == l).unwrap().modal_mass)
            .collect();
    let w: Vec<f64> =
        b.ls.iter()
            .map(|&l| model.modes().iter().find(|x| x.l == l).unwrap().omega)
            .collect();
    let s = nalgebra::DMatrix::from_fn(2, 2, |a, x| {
        ((if a == x { m[a] * w[a] * w[a] } else { 0.0 }) + speed * speed * b.matrix[a * 2 + x])
            / (m[a] * m[x]).sqrt()
    });
    let ritz: Vec<f64> = s
        .symmetric_eigen()
        .eigenvalues
        .iter()
        .map(|e| e.sqrt())
        .collect();
    let mut expected: Vec<f64> = ritz
        .iter()
        .flat_map(|&o| [o + 3.0 * speed, (o - 3.0 * speed).abs()])
        .flat_map(|x| [x, x])
        .collect();
    expected.sort_by(f64::total_cmp);
    let mut got: Vec<f64> =
        annular_plate::dynamics::stability::eigenvalues(sim.scene(), speed, 0.0, &[])
            .iter()
            .map(|z| z.im.abs())
            .collect();
    got.sort_by(f64::total_cmp);
    println!("ALE |Im λ|: {got:?}\nexpected: {expected:?}");
    assert_eq!(got.len(), expected.len());
    for (x, y) in got.iter().zip(&expected) {
        assert!((x - y).abs() < 1e-9 * y.max(1.0), "{x} vs {y}");
    }
    // Not vacuous: without stiffening ω₀ ± kΩ, 16 % apart.
    assert!((ritz[0] - w[0]).abs() > 0.1 * w[0]);
}

#[test]
fn cos_and_sin_partners_with_their_own_damping_ring_down_each_at_its_own_rate_with_stiffening() {
    // plate.damping per mode: the cos and sin modes of one ⟨k, l⟩ may differ.
    // The exponential step propagates each family (the cos, the sin modes of
    // k = 3 over l = 0, 1) with its own constants. Reference written here: a
    // fine RK4 on each family's ODE m_a(q̈_a + 2ζ_aω_a q̇_a + ω_a² q_a) + Ω² Σ G_ab q_b = 0.
    let speed = 4000.0;
    let mut c = stiffened_scene(3, 2, speed);
    let n = Simulation::new(c.clone()).unwrap().model().n_modes();
    c.plate.damping = (0..n).map(|i| 0.01 + 0.03 * i as f64).collect();
    c.initial.q = (0..n).map(|i| 1e-6 * (1.0 + i as f64)).collect();
    c.simulation.coordinates = Coordinates::Lagrangian;
    c.simulation.rate_hz = 20_000.0;
    let mut sim = Simulation::new(c).unwrap();
    let steps = 400;
    for _ in 0..steps {
        sim.step().unwrap();
    }
    let model = sim.model();
    let g = ModalGeometricStiffness::new(model, &on());
    let b = &g.blocks[0];
    let mut worst = 0.0f64;
    for shape in [AngularShape::Cos, AngularShape::Sin] {
        let idx: Vec<usize> =
            b.ls.iter()
                .map(|&l| {
                    model
                        .modes()
                        .iter()
                        .position(|m| m.l == l && m.shape == shape)
                        .unwrap()
                })
                .collect();
        let modes: Vec<_> = idx.iter().map(|&i| model.modes()[i].clone()).collect();
        let (mut q, mut v) = (
            idx.iter()
                .map(|&i| 1e-6 * (1.0 + i as f64))
                .collect::<Vec<f64>>(),
            vec![0.0; 2],
        );
        let acc = |q: &[f64], v: &[f64]| -> Vec<f64> {
            (0..2)
                .map(|a| {
                    let m = &modes[a];
                    let gq: f64 = (0..2).map(|x| b.matrix[a * 2 + x] * q[x]).sum();
                    -2.0 * m.damping * m.omega * v[a]
                        - m.omega * m.omega * q[a]
                        - speed * speed * gq / m.modal_mass
                })
                .collect()
        };
        let per_step = 2000;
        let dt = 1.0 / 20_000.0 / per_step as f64;
        for _ in 0..steps * per_step {
            let add = |x: &[f64], d: &[f64], s: f64| vec![x[0] + s * d[0], x[1] + s * d[1]];
            let a1 = acc(&q, &v);
            let (q2, v2) = (add(&q, &v, 0.5 * dt), add(&v, &a1, 0.5 * dt));
            let a2 = acc(&q2, &v2);
            let (q3, v3) = (add(&q, &v2, 0.5 * dt), add(&v, &a2, 0.5 * dt));
            let a3 = acc(&q3, &v3);
            let (q4, v4) = (add(&q, &v3, dt), add(&v, &a3, dt));
            let a4 = acc(&q4, &v4);
            for x in 0..2 {
                q[x] += dt / 6.0 * (v[x] + 2.0 * v2[x] + 2.0 * v3[x] + v4[x]);
                v[x] += dt / 6.0 * (a1[x] + 2.0 * a2[x] + 2.0 * a3[x] + a4[x]);
            }
        }
        let scale = q.iter().fold(0.0f64, |m, y| m.max(y.abs()));
        for (a, &i) in idx.iter().enumerate() {
            let d = (sim.q_lagrange()[i] - q[a]).abs() / scale;
            println!("{shape:?} ⟨3,{a}⟩ ζ = {:.2}: simulated {:.6e}, reference {:.6e}, difference {d:.1e}", modes[a].damping, sim.q_lagrange()[i], q[a]);
            worst = worst.max(d);
        }
    }
    assert!(worst < 1e-10, "{worst:e}");
}
