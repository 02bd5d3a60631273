//! The Mindlin modes of the annular plate (`model::mindlin`) against
//! independent references:
//!
//! * the exact Mindlin solution (`tests/support/mindlin_exact.rs`: three wave
//!   numbers per k, J/Y or I/K per potential, the 6×6 edge determinant, its
//!   roots by bracketing and bisection) for all 16 inner × outer edge pairs,
//!   three radius ratios (the bench disc's among them), k ≤ 10, l ≤ 3: 1e-6
//!   relative at the default resolution;
//! * the brake disc against converged 3-D elasticity (1 % for l = 0, 1.2 %
//!   for l = 1), with the project's Kirchhoff modes as a check of the data;
//! * the thin limit: (ω_Mindlin/ω_Kirchhoff − 1)/(h/b)² converges as h → 0;
//! * symmetric matrices, modes orthogonal in the mass form of the fields,
//!   the modal mass of the unit-peak deflection, the energy of the fields.
//!
//! Run with `-- --nocapture` for the tables.

mod support;

use annular_plate::config::{Boundary, RadialSplines};
use annular_plate::model::mindlin::{
    mindlin_modes, MindlinDiscretisation, MindlinEdge, MindlinPlate, DEFAULT_SHEAR_CORRECTION,
    DEFAULT_SPLINES,
};
use annular_plate::model::{AngularShape, PlateModel};
use support::exact_plate::Material;
use support::library_plate::annulus_config;
use support::mindlin_exact::{Edge, MindlinAnnulus};

const E: f64 = 2.1e11;
const NU: f64 = 0.3;
const RHO: f64 = 7850.0;
/// The bench disc.
const R_I: f64 = 0.07;
const R_A: f64 = 0.153;
const H: f64 = 0.0181;

/// Steel of thickness h (E, ν, ρ above).
fn steel(h: f64) -> Material {
    Material {
        thickness: h,
        density: RHO,
        youngs_modulus: E,
        poisson_ratio: NU,
    }
}

fn library_edge(e: Edge) -> MindlinEdge {
    match e {
        Edge::Free => MindlinEdge::Free,
        Edge::SupportedSoft => MindlinEdge::SupportedSoft,
        Edge::Supported => MindlinEdge::Supported,
        Edge::Clamped => MindlinEdge::Clamped,
    }
}

fn plate(ri: f64, ra: f64, h: f64, inner: MindlinEdge, outer: MindlinEdge) -> MindlinPlate {
    MindlinPlate {
        youngs_modulus: E,
        poisson_ratio: NU,
        density: RHO,
        thickness: h,
        inner_radius: ri,
        outer_radius: ra,
        shear_correction: DEFAULT_SHEAR_CORRECTION,
        inner_edge: inner,
        outer_edge: outer,
    }
}

fn annulus(ri: f64, ra: f64, h: f64, inner: Edge, outer: Edge) -> MindlinAnnulus {
    MindlinAnnulus {
        youngs_modulus: E,
        poisson_ratio: NU,
        density: RHO,
        thickness: h,
        shear_correction: 5.0 / 6.0,
        inner_radius: ri,
        outer_radius: ra,
        inner,
        outer,
    }
}

/// Largest relative deviation of the library's ⟨k, l⟩, k ≤ 10, l ≤ 3, from
/// the exact roots: (error, k, l).
fn worst_against_exact(case: &Case, inner: Edge, outer: Edge, splines: usize) -> (f64, u32, u32) {
    let exact_plate = annulus(case.ri, R_A, case.h, inner, outer);
    let lib = plate(
        case.ri,
        R_A,
        case.h,
        library_edge(inner),
        library_edge(outer),
    );
    let mut worst = (0.0, 0, 0);
    for k in 0..=10u32 {
        let rigid = usize::from(inner == Edge::Free && outer == Edge::Free && k <= 1);
        let roots = exact_plate.roots(k, 4 - rigid, 64);
        let modes = mindlin_modes(&lib, k, 4, splines).unwrap();
        assert_eq!(modes.len(), roots.len(), "k = {k}");
        for (i, (m, exact)) in modes.iter().zip(&roots).enumerate() {
            assert_eq!(m.l as usize, i + rigid, "k = {k}");
            let err = (m.omega - exact).abs() / exact;
            if err > worst.0 || !err.is_finite() {
                worst = (err, k, m.l);
            }
        }
    }
    worst
}

/// A geometry of the exact comparison: r_i (r_a = 0.153 m) and h.
struct Case {
    ri: f64,
    h: f64,
}

/// r_i/r_a = 0.2, the bench disc (0.4575) and 0.7 — the narrow ring at
/// the bench's h/(r_a − r_i) ≈ 0.22 so that ⟨10, 3⟩ stays below the
/// thickness-shear cut-off.
const CASES: [Case; 3] = [
    Case {
        ri: 0.2 * R_A,
        h: H,
    },
    Case { ri: R_I, h: H },
    Case {
        ri: 0.7 * R_A,
        h: 0.01,
    },
];

#[test]
fn frequencies_match_the_exact_mindlin_solution_for_every_edge_pair() {
    let mut failures = Vec::new();
    println!(
        "worst |ω − ω_exact|/ω_exact over k ≤ 10, l ≤ 3 ({DEFAULT_SPLINES} splines per field):"
    );
    for case in &CASES {
        for inner in Edge::ALL {
            for outer in Edge::ALL {
                let (err, k, l) = worst_against_exact(case, inner, outer, DEFAULT_SPLINES);
                println!(
                    "  r_i/r_a = {:.4} h = {} {:>14}-{:<14} {err:.2e} at ⟨{k}, {l}⟩",
                    case.ri / R_A,
                    case.h,
                    inner.name(),
                    outer.name()
                );
                if err.is_nan() || err > 1e-6 {
                    failures.push(format!(
                        "{}-{} r_i = {}: {err:e}",
                        inner.name(),
                        outer.name(),
                        case.ri
                    ));
                }
            }
        }
    }
    assert!(failures.is_empty(), "{failures:#?}");
}

#[test]
fn frequencies_converge_at_fourth_order_in_the_spline_spacing() {
    // The clamped–clamped wide annulus is the hardest case at the default.
    let case = &CASES[0];
    let errors: Vec<(usize, f64)> = [40, 60, 80]
        .into_iter()
        .map(|n| {
            (
                n,
                worst_against_exact(case, Edge::Clamped, Edge::Clamped, n).0,
            )
        })
        .collect();
    for w in errors.windows(2) {
        let ((n0, e0), (n1, e1)) = (w[0], w[1]);
        let order = (e0 / e1).ln() / ((n1 as f64 - 3.0) / (n0 as f64 - 3.0)).ln();
        println!("splines {n0} → {n1}: worst {e0:.2e} → {e1:.2e}, order {order:.2}");
        assert!((3.5..4.5).contains(&order), "order {order}");
    }
}

/// (ω_Mindlin/ω_Kirchhoff − 1)/(h/b)² of the exact solutions, ⟨k, 0⟩ (⟨k, 1⟩ free–free k ≤ 1).
fn exact_thin_ratio(inner: Edge, outer: Edge, k: u32, h: f64) -> f64 {
    use support::exact_plate::{Annulus, Edge as KEdge};
    let kedge = |e: Edge| match e {
        Edge::Clamped => KEdge::Clamped,
        Edge::Supported => KEdge::Supported,
        Edge::Free => KEdge::Free,
        Edge::SupportedSoft => unreachable!("no Kirchhoff counterpart"),
    };
    let kirchhoff = Annulus::new(R_I, R_A, NU, kedge(inner), kedge(outer));
    let lambda = kirchhoff
        .lambdas(k, 400.0)
        .into_iter()
        .find(|&l| l > 1e-6)
        .unwrap();
    let mindlin = annulus(R_I, R_A, h, inner, outer).roots(k, 1, 64)[0];
    (mindlin / steel(h).omega(lambda) - 1.0) / (h / (R_A - R_I)).powi(2)
}

#[test]
fn exact_mindlin_solution_tends_to_the_exact_kirchhoff_one_as_the_plate_thins() {
    // Clamped and hard-supported edges, and any k = 0 mode: the relative
    // difference is O((h/b)²) — its ratio to (h/b)² settles.
    let cases = [
        (Edge::Clamped, Edge::Clamped, 2),
        (Edge::Supported, Edge::Supported, 5),
        (Edge::Clamped, Edge::Supported, 3),
        (Edge::Clamped, Edge::Free, 0),
        (Edge::Supported, Edge::Free, 0),
    ];
    for (inner, outer, k) in cases {
        let cs: Vec<f64> = [0.004, 0.002, 0.001]
            .into_iter()
            .map(|h| exact_thin_ratio(inner, outer, k, h))
            .collect();
        println!(
            "exact {}-{} ⟨{k}⟩ h = 4, 2, 1 mm: (ω_M/ω_K − 1)/(h/b)² = {cs:.5?}",
            inner.name(),
            outer.name()
        );
        assert!(cs.iter().all(|&c| c < 0.0 && c > -10.0), "{cs:?}");
        assert!(((cs[2] - cs[1]) / cs[2]).abs() < 0.01, "{cs:?}");
        assert!(
            (cs[2] - cs[1]).abs() < 0.5 * (cs[1] - cs[0]).abs(),
            "{cs:?}"
        );
    }
    // A free edge with k ≥ 1 has Mindlin's twisting-moment boundary layer:
    // the difference still vanishes, but more slowly than (h/b)².
    let cs: Vec<f64> = [0.004, 0.002, 0.001]
        .into_iter()
        .map(|h| exact_thin_ratio(Edge::Clamped, Edge::Free, 2, h))
        .collect();
    println!("exact clamped-free ⟨2⟩ h = 4, 2, 1 mm: (ω_M/ω_K − 1)/(h/b)² = {cs:.5?}");
    let d: Vec<f64> = cs
        .iter()
        .zip([0.004f64, 0.002, 0.001])
        .map(|(c, h)| c * (h / (R_A - R_I)).powi(2))
        .collect();
    assert!(
        d[1].abs() < 0.5 * d[0].abs() && d[2].abs() < 0.5 * d[1].abs(),
        "{d:?}"
    );
}

/// The bench disc with the given inner edge (outer free), k = 0..6, l = 0, 1.
fn bench_modes(inner: MindlinEdge) -> Vec<Vec<f64>> {
    let p = plate(R_I, R_A, H, inner, MindlinEdge::Free);
    (0..=6)
        .map(|k| {
            mindlin_modes(&p, k, 2, DEFAULT_SPLINES)
                .unwrap()
                .iter()
                .map(|m| m.frequency_hz)
                .collect()
        })
        .collect()
}

fn check_against_3d(
    name: &str,
    modes: &[Vec<f64>],
    l: usize,
    reference: &[f64],
    tol: f64,
) -> Vec<String> {
    let mut failures = Vec::new();
    for (k, (m, &r)) in modes.iter().zip(reference).enumerate() {
        let dev = (m[l] - r) / r;
        println!(
            "  {name:>14} ⟨{k}, {l}⟩: Mindlin {:9.2} Hz, 3-D {r:9.2} Hz, {:+.3} %",
            m[l],
            100.0 * dev
        );
        if dev.is_nan() || dev.abs() > tol {
            failures.push(format!("{name} ⟨{k}, {l}⟩: {:+.3} %", 100.0 * dev));
        }
    }
    failures
}

#[test]
fn brake_disc_matches_three_dimensional_elasticity() {
    const SUPPORTED_L0: [f64; 7] = [745.03, 844.09, 1386.38, 2489.23, 4041.52, 5948.93, 8142.33];
    const SUPPORTED_L1: [f64; 7] = [
        8906.54, 9253.27, 10265.62, 11874.75, 13995.73, 16541.38, 19426.96,
    ];
    const SOFT_L0: [f64; 7] = [745.03, 778.12, 1253.92, 2374.06, 3963.92, 5903.45, 8118.25];
    const CLAMPED_L0: [f64; 7] = [
        2048.46, 2059.40, 2256.26, 2960.88, 4264.96, 6048.51, 8184.86,
    ];
    const CLAMPED_L1: [f64; 7] = [
        11115.8, 11354.6, 12081.8, 13315.7, 15056.6, 17272.5, 19901.7,
    ];
    const KIRCHHOFF_SUPPORTED_L0: [f64; 7] = [751.6, 858.0, 1427.8, 2602.9, 4312.6, 6504.9, 9151.3];

    // The project's Kirchhoff modes reproduce the reference's Kirchhoff column: same disc.
    let ks: Vec<u32> = (0..=6).collect();
    let cfg = annulus_config(
        (R_I, R_A),
        (Boundary::Supported, Boundary::Free),
        &ks,
        &[0],
        steel(H),
    );
    let kirchhoff = PlateModel::new(&cfg).unwrap();
    for (k, &want) in KIRCHHOFF_SUPPORTED_L0.iter().enumerate() {
        let got = kirchhoff
            .modes()
            .iter()
            .find(|m| m.k == k as u32 && m.l == 0)
            .unwrap()
            .frequency_hz;
        println!("  Kirchhoff supported ⟨{k}, 0⟩: {got:.2} Hz, reference {want} Hz");
        assert!(
            (got - want).abs() <= 0.051 + 1e-6 * want,
            "⟨{k}, 0⟩: {got} vs {want}"
        );
    }

    let mut failures = Vec::new();
    let supported = bench_modes(MindlinEdge::Supported);
    failures.extend(check_against_3d(
        "supported",
        &supported,
        0,
        &SUPPORTED_L0,
        0.01,
    ));
    failures.extend(check_against_3d(
        "supported",
        &supported,
        1,
        &SUPPORTED_L1,
        0.012,
    ));
    let soft = bench_modes(MindlinEdge::SupportedSoft);
    failures.extend(check_against_3d("supported_soft", &soft, 0, &SOFT_L0, 0.01));
    let clamped = bench_modes(MindlinEdge::Clamped);
    failures.extend(check_against_3d("clamped", &clamped, 0, &CLAMPED_L0, 0.01));
    failures.extend(check_against_3d("clamped", &clamped, 1, &CLAMPED_L1, 0.012));
    assert!(failures.is_empty(), "{failures:#?}");
}

/// The project's Kirchhoff plate with the Mindlin default's B-splines.
fn kirchhoff_model(
    h: f64,
    (inner, outer): (Boundary, Boundary),
    ks: &[u32],
    ls: &[u32],
) -> PlateModel {
    let mut cfg = annulus_config((R_I, R_A), (inner, outer), ks, ls, steel(h));
    cfg.radial_splines = RadialSplines::Fixed(DEFAULT_SPLINES);
    PlateModel::new(&cfg).unwrap()
}

/// (ω_M/ω_K − 1)/(h/b)² and (m_M/m_K − 1)/(h/b)² of the library's Mindlin
/// and Kirchhoff ⟨k, l⟩ for h/b = 0.2 / 2ⁿ, n = 0 … 5 (below, the
/// difference, ~1e-6, nears the solvers' ~1e-8 floor).
fn thin_ratios(inner: Boundary, outer: Boundary, k: u32, l: u32) -> (Vec<f64>, Vec<f64>) {
    let edge = annular_plate::model::mindlin::mindlin_edge;
    let width = R_A - R_I;
    let mut cs = Vec::new();
    let mut mass_cs = Vec::new();
    for halvings in 0..6 {
        let h = 0.2 * width / f64::from(1 << halvings);
        let km = kirchhoff_model(h, (inner, outer), &[k], &[l]);
        let kmode = km.modes().iter().find(|m| m.l == l).unwrap();
        let p = plate(R_I, R_A, h, edge(inner), edge(outer));
        let mm = mindlin_modes(&p, k, l as usize + 1, DEFAULT_SPLINES).unwrap();
        let mmode = mm.iter().find(|m| m.l == l).unwrap();
        let t = (h / width).powi(2);
        cs.push((mmode.omega / kmode.omega - 1.0) / t);
        mass_cs.push((mmode.modal_mass / kmode.modal_mass - 1.0) / t);
    }
    println!(
        "{}-{} ⟨{k}, {l}⟩ h/b = 0.2 … 0.2/32: (ω_M/ω_K − 1)/(h/b)² = {cs:.4?}; (m_M/m_K − 1)/(h/b)² = {mass_cs:.4?}",
        inner.name(),
        outer.name(),
    );
    (cs, mass_cs)
}

#[test]
fn thin_limit_approaches_the_kirchhoff_modes_as_h_squared() {
    use Boundary::*;
    // Clamped and (hard) supported edges, and the k = 0 modes with a free edge.
    let cases = [
        (Clamped, Clamped, 2, 0),
        (Clamped, Clamped, 5, 1),
        (Supported, Supported, 3, 0),
        (Clamped, Supported, 0, 1),
        (Supported, Clamped, 4, 0),
        (Clamped, Free, 0, 1),
        (Supported, Free, 0, 1),
        (Free, Free, 0, 1),
    ];
    for (inner, outer, k, l) in cases {
        let (cs, mass_cs) = thin_ratios(inner, outer, k, l);
        // Converging: the steps shrink, the last two agree to 1 %.
        let n = cs.len();
        let steps: Vec<f64> = cs.windows(2).map(|w| (w[1] - w[0]).abs()).collect();
        assert!(cs[n - 1] < 0.0, "Mindlin is softer: {cs:?}");
        assert!(
            ((cs[n - 1] - cs[n - 2]) / cs[n - 1]).abs() < 0.01,
            "not converged: {cs:?}"
        );
        assert!(steps[steps.len() - 1] < 0.5 * steps[1], "steps {steps:?}");
        let m = mass_cs.len();
        assert!(
            (mass_cs[m - 1] - mass_cs[m - 2]).abs() < 0.01 * (1.0 + mass_cs[m - 1].abs()),
            "modal mass {mass_cs:?}"
        );
    }
}

#[test]
fn thin_limit_with_a_free_edge_and_nodal_diameters_is_slower_than_h_squared() {
    // The free edge's twisting-moment boundary layer (width ~ h): the
    // relative difference still vanishes — at least halving with h.
    for (k, l) in [(2, 0), (3, 1)] {
        let (cs, _) = thin_ratios(Boundary::Clamped, Boundary::Free, k, l);
        let d: Vec<f64> = cs
            .iter()
            .enumerate()
            .map(|(n, c)| c * (0.2 / f64::from(1 << n)).powi(2))
            .collect();
        let shown: Vec<String> = d.iter().map(|v| format!("{v:.3e}")).collect();
        println!("  relative differences {}", shown.join(", "));
        for w in d.windows(2) {
            assert!(w[1] < 0.0 && w[1].abs() < 0.5 * w[0].abs(), "{d:?}");
        }
    }
}

/// Composite Gauss–Legendre over [r_i, r_a]: (r, weight).
fn quadrature(ri: f64, ra: f64) -> Vec<(f64, f64)> {
    let (xs, ws) = support::exact_plate::gauss_legendre(10);
    let cells = 600;
    let dr = (ra - ri) / cells as f64;
    (0..cells)
        .flat_map(|c| {
            let mid = ri + (c as f64 + 0.5) * dr;
            xs.iter()
                .zip(&ws)
                .map(move |(x, w)| (mid + 0.5 * dr * x, 0.5 * dr * w))
                .collect::<Vec<_>>()
        })
        .collect()
}

#[test]
fn matrices_are_symmetric_and_modes_orthogonal_in_the_mass_and_energy_of_the_fields() {
    for (inner, outer) in [
        (MindlinEdge::Clamped, MindlinEdge::Free),
        (MindlinEdge::Free, MindlinEdge::Free),
        (MindlinEdge::SupportedSoft, MindlinEdge::Supported),
    ] {
        let p = plate(R_I, R_A, H, inner, outer);
        let disc = MindlinDiscretisation::new(&p, 30).unwrap();
        for k in [0u32, 1, 3] {
            let (kk, mm) = disc.assemble(k);
            let n = kk.nrows();
            let scale = |a: &faer::Mat<f64>| (0..n).map(|i| a[(i, i)].abs()).fold(0.0, f64::max);
            for i in 0..n {
                for j in 0..n {
                    assert!((kk[(i, j)] - kk[(j, i)]).abs() <= 1e-14 * scale(&kk));
                    assert!((mm[(i, j)] - mm[(j, i)]).abs() <= 1e-14 * scale(&mm));
                }
            }
            assert!(mm.llt(faer::Side::Lower).is_ok(), "M̄ positive definite");

            // The modes, orthogonal in the mass form of their fields; the
            // modal mass is that of the unit-peak W; the energy U of the
            // fields is ω² times it (derivatives of Ψ by central differences).
            let modes = disc.modes(k, 4).unwrap();
            let ck = if k == 0 {
                2.0 * std::f64::consts::PI
            } else {
                std::f64::consts::PI
            };
            let (rho_h, inertia) = (RHO * H, RHO * H.powi(3) / 12.0);
            let d = E * H.powi(3) / (12.0 * (1.0 - NU * NU));
            let s = DEFAULT_SHEAR_CORRECTION * E / (2.0 * (1.0 + NU)) * H;
            let kf = k as f64;
            let strains = |m: &annular_plate::model::mindlin::MindlinMode, r: f64| {
                let v = m.eval(r);
                let step = 1e-7;
                let (a, b) = (m.eval(r + step), m.eval(r - step));
                let (dpr, dpt) = (
                    (a.psi_r - b.psi_r) / (2.0 * step),
                    (a.psi_theta - b.psi_theta) / (2.0 * step),
                );
                [
                    dpr,
                    (v.psi_r + kf * v.psi_theta) / r,
                    dpt - (v.psi_theta + kf * v.psi_r) / r,
                    v.psi_r + v.w_r,
                    v.psi_theta - kf * v.w / r,
                ]
            };
            let quad = quadrature(R_I, R_A);
            for a in &modes {
                let peak = (0..=20_000)
                    .map(|i| a.eval(R_I + (R_A - R_I) * f64::from(i) / 20_000.0).w.abs())
                    .fold(0.0, f64::max);
                assert!((peak - 1.0).abs() < 1e-6, "peak |W| = {peak}");
                for b in &modes {
                    let (mut mass, mut energy) = (0.0, 0.0);
                    for &(r, w) in &quad {
                        let (va, vb) = (a.eval(r), b.eval(r));
                        mass += w
                            * r
                            * ck
                            * (rho_h * va.w * vb.w
                                + inertia * (va.psi_r * vb.psi_r + va.psi_theta * vb.psi_theta));
                        let (ea, eb) = (strains(a, r), strains(b, r));
                        energy += w
                            * r
                            * ck
                            * (d * (ea[0] * eb[0]
                                + ea[1] * eb[1]
                                + NU * (ea[0] * eb[1] + ea[1] * eb[0])
                                + 0.5 * (1.0 - NU) * ea[2] * eb[2])
                                + s * (ea[3] * eb[3] + ea[4] * eb[4]));
                    }
                    let (want_mass, want_energy) = if a.l == b.l {
                        (a.modal_mass, a.omega * a.omega * a.modal_mass)
                    } else {
                        (0.0, 0.0)
                    };
                    let m_scale = (a.modal_mass * b.modal_mass).sqrt();
                    let e_scale = a.omega * b.omega * m_scale;
                    assert!(
                        (mass - want_mass).abs() < 1e-9 * m_scale,
                        "k {k} l {} {}: mass {mass:e} vs {want_mass:e}",
                        a.l,
                        b.l
                    );
                    assert!(
                        (energy - want_energy).abs() < 1e-5 * e_scale,
                        "k {k} l {} {}: energy {energy:e} vs {want_energy:e}",
                        a.l,
                        b.l
                    );
                }
            }
        }
    }
}

#[test]
fn sine_partner_is_the_cosine_mode_turned_by_a_quarter_wave() {
    let p = plate(R_I, R_A, H, MindlinEdge::Clamped, MindlinEdge::Free);
    for k in [1u32, 3] {
        let m = &mindlin_modes(&p, k, 1, 40).unwrap()[0];
        let quarter = std::f64::consts::FRAC_PI_2 / k as f64;
        for (r, phi) in [(0.09, 0.3), (0.12, 1.1), (0.15, 2.5)] {
            let s = m.field(AngularShape::Sin, r, phi);
            let c = m.field(AngularShape::Cos, r, phi - quarter);
            for (a, b) in [(s.w, c.w), (s.psi_r, c.psi_r), (s.psi_theta, c.psi_theta)] {
                assert!((a - b).abs() < 1e-12 * (1.0 + a.abs()), "{a} vs {b}");
            }
            // ψ_θ of the cos mode is Ψ_θ sin kφ.
            let v = m.eval(r);
            let c0 = m.field(AngularShape::Cos, r, phi);
            assert!((c0.psi_theta - v.psi_theta * (k as f64 * phi).sin()).abs() < 1e-12);
        }
    }
}

#[test]
fn bad_input_is_refused_with_the_field_named() {
    let good = plate(R_I, R_A, H, MindlinEdge::Clamped, MindlinEdge::Free);
    let mut bad = good;
    bad.thickness = f64::NAN;
    let e = mindlin_modes(&bad, 0, 1, 40).unwrap_err().to_string();
    assert!(e.contains("thickness"), "{e}");
    let mut bad = good;
    bad.outer_radius = 0.05;
    assert!(mindlin_modes(&bad, 0, 1, 40)
        .unwrap_err()
        .to_string()
        .contains("outer_radius"));
    let mut bad = good;
    bad.poisson_ratio = 0.5;
    assert!(mindlin_modes(&bad, 0, 1, 40)
        .unwrap_err()
        .to_string()
        .contains("poisson_ratio"));
    assert!(mindlin_modes(&good, 0, 1, 3)
        .unwrap_err()
        .to_string()
        .contains("splines"));
    assert!(mindlin_modes(&good, 0, 1, 100_000)
        .unwrap_err()
        .to_string()
        .contains("splines"));
    assert!(mindlin_modes(&good, 0, 1000, 40)
        .unwrap_err()
        .to_string()
        .contains("orders"));
    assert!(mindlin_modes(&good, 0, 0, 40)
        .unwrap_err()
        .to_string()
        .contains("orders"));
}
