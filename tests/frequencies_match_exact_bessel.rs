//! The library's B-spline Ritz frequencies against the exact Bessel-function
//! solution of the annular Kirchhoff plate (`tests/support/exact_plate.rs`,
//! written independently of the library's numerics).
//!
//! * all 9 pairs of inner/outer edge conditions × r_i/r_a ∈ {0.1, 0.5, 0.9}:
//!   the first 20 exact elastic ⟨k, l⟩ must be matched to 1e-4 relative, with
//!   l sign changes of R(r) inside the annulus;
//! * the paper's Table 1 disc (section 5.1);
//! * the convergence rate in the number of radial B-splines;
//! * self-checks of the exact solver (root scan, edge residuals, nodal circles).
//!
//! Run with `-- --nocapture` to see the per-case tables.

mod support;

use annular_plate::config::{Boundary, PlateConfig};
use annular_plate::model::{AngularShape, PlateModel};
use support::exact_plate::{count_sign_changes, Annulus, Edge, ExactMode, Material};
use support::library_plate::{self, edge};

const OUTER_RADIUS: f64 = 0.15;
const THICKNESS: f64 = 0.01;
const RATIOS: [f64; 3] = [0.1, 0.5, 0.9];
/// What the B-spline model with the default 24 radial splines must meet.
const REL_TOL: f64 = 1e-4;
const N_MODES: usize = 20;

fn steel() -> Material {
    Material::steel(THICKNESS)
}

fn plate_config(
    ratio: f64,
    inner: Boundary,
    outer: Boundary,
    ks: &[u32],
    ls: &[u32],
    material: Material,
) -> PlateConfig {
    library_plate::annulus_config(
        (ratio * OUTER_RADIUS, OUTER_RADIUS),
        (inner, outer),
        ks,
        ls,
        material,
    )
}

fn distinct_sorted(v: impl Iterator<Item = u32>) -> Vec<u32> {
    let mut v: Vec<u32> = v.collect();
    v.sort_unstable();
    v.dedup();
    v
}

/// Per-⟨k, l⟩ comparison of one library model with the exact modes.
struct Comparison {
    /// (k, l, exact Hz, library Hz, relative error) for every library mode of the exact list
    rows: Vec<(u32, u32, f64, f64, f64)>,
    /// problems found (missing modes, wrong nodal circles, tolerance misses)
    problems: Vec<String>,
}

impl Comparison {
    fn worst(&self) -> Option<&(u32, u32, f64, f64, f64)> {
        self.rows.iter().max_by(|a, b| a.4.total_cmp(&b.4))
    }
}

fn compare(
    model: &PlateModel,
    annulus: &Annulus,
    material: Material,
    exact: &[ExactMode],
    tol: f64,
    check_nodes: bool,
) -> Comparison {
    let mut rows = Vec::new();
    let mut problems = Vec::new();
    for e in exact {
        let f_exact = material.frequency_hz(e.lambda);
        let found: Vec<_> = model
            .modes()
            .iter()
            .filter(|m| m.k == e.k && m.l == e.l)
            .collect();
        let expected_count = if e.k == 0 { 1 } else { 2 };
        if found.len() != expected_count {
            problems.push(format!(
                "⟨k={}, l={}⟩: library returned {} modes, expected {}",
                e.k,
                e.l,
                found.len(),
                expected_count
            ));
        }
        let shapes: Vec<AngularShape> = found.iter().map(|m| m.shape).collect();
        if e.k == 0 && found.len() == 1 && shapes[0] != AngularShape::Axisymmetric {
            problems.push(format!(
                "⟨k=0, l={}⟩: angular shape {:?}, expected Axisymmetric",
                e.l, shapes[0]
            ));
        }
        if e.k > 0 && !(shapes.contains(&AngularShape::Cos) && shapes.contains(&AngularShape::Sin))
        {
            problems.push(format!(
                "⟨k={}, l={}⟩: angular shapes {:?}, expected one Cos and one Sin",
                e.k, e.l, shapes
            ));
        }
        for m in &found {
            let err = (m.frequency_hz - f_exact).abs() / f_exact;
            rows.push((e.k, e.l, f_exact, m.frequency_hz, err));
            if err > tol || !err.is_finite() {
                problems.push(format!(
                    "⟨k={}, l={}⟩ {:?}: library {:.6} Hz, exact {:.6} Hz, relative error {:.3e} > {:.0e}",
                    e.k, e.l, m.shape, m.frequency_hz, f_exact, err, tol
                ));
            }
            let omega_err = (m.omega - 2.0 * std::f64::consts::PI * m.frequency_hz).abs() / m.omega;
            if omega_err > 1e-12 {
                problems.push(format!(
                    "⟨k={}, l={}⟩: omega {} is not 2π·frequency_hz {}",
                    e.k, e.l, m.omega, m.frequency_hz
                ));
            }
            if check_nodes {
                let rs = &model.radial_shapes()[m.radial];
                let circles = count_sign_changes(
                    |r| rs.value(r),
                    annulus.inner_radius,
                    annulus.outer_radius,
                    4000,
                );
                if circles != e.l as usize {
                    problems.push(format!(
                        "⟨k={}, l={}⟩: library R(r) has {} sign changes in (r_i, r_a), expected {}",
                        e.k, e.l, circles, e.l
                    ));
                }
            }
        }
    }
    Comparison { rows, problems }
}

/// The exact λ of ⟨k, 0⟩ … ⟨k, count − 1⟩ (rigid-body λ = 0 included).
fn lambdas_at_least(annulus: &Annulus, k: u32, count: usize) -> Vec<f64> {
    let mut lam_max = annulus.root_spacing() * (count as f64 + 2.0);
    loop {
        let v = annulus.lambdas(k, lam_max);
        if v.len() >= count {
            return v;
        }
        lam_max *= 1.5;
    }
}

fn case_name(ratio: f64, inner: Boundary, outer: Boundary) -> String {
    format!("{:>9}-{:<9} r_i/r_a={}", inner.name(), outer.name(), ratio)
}

#[test]
fn first_20_modes_match_exact_bessel_for_all_edge_pairs_and_radius_ratios() {
    let material = steel();
    let mut all_problems = Vec::new();
    let mut notes: Vec<String> = Vec::new();
    println!("first {N_MODES} exact elastic ⟨k,l⟩ per case vs library (radial_splines = default):");
    println!(
        "{:<34} {:>6} {:>6} {:>14} {:>12}  worst ⟨k,l⟩ (exact Hz)",
        "case (inner-outer)", "max k", "max l", "worst rel err", "all-returned"
    );
    for ratio in RATIOS {
        for inner in Boundary::KIRCHHOFF {
            for outer in Boundary::KIRCHHOFF {
                let name = case_name(ratio, inner, outer);
                let annulus = Annulus::new(
                    ratio * OUTER_RADIUS,
                    OUTER_RADIUS,
                    material.poisson_ratio,
                    edge(inner),
                    edge(outer),
                );
                let exact = annulus.lowest_modes(N_MODES);
                let ks = distinct_sorted(exact.iter().map(|m| m.k));
                let ls = distinct_sorted(exact.iter().map(|m| m.l));
                let cfg = plate_config(ratio, inner, outer, &ks, &ls, material);
                let model = match PlateModel::new(&cfg) {
                    Ok(m) => m,
                    Err(e) => {
                        all_problems.push(format!("{name}: PlateModel::new failed: {e}"));
                        println!("{name:<34} model failed: {e}");
                        continue;
                    }
                };
                // Rigid-body modes: skipped exactly where the free–free plate has them.
                let expected_skipped: Vec<(u32, u32)> = ks
                    .iter()
                    .flat_map(|&k| ls.iter().map(move |&l| (k, l)))
                    .filter(|&(k, l)| l == 0 && annulus.has_rigid_body_mode(k))
                    .collect();
                let mut skipped = model.skipped_rigid_body_modes().to_vec();
                skipped.sort_unstable();
                if skipped != expected_skipped {
                    all_problems.push(format!("{name}: skipped rigid-body modes {skipped:?}, expected {expected_skipped:?}"));
                }
                let cmp = compare(&model, &annulus, material, &exact, REL_TOL, true);
                // Information only: every ⟨k, l⟩ the library returned (the product of the
                // requested k and l goes beyond the first 20 exact modes).
                let max_l = *ls.iter().max().unwrap();
                let mut beyond = 0.0_f64;
                for &k in &ks {
                    let lams = lambdas_at_least(&annulus, k, max_l as usize + 1);
                    for m in model.modes().iter().filter(|m| m.k == k) {
                        let f = material.frequency_hz(lams[m.l as usize]);
                        beyond = beyond.max((m.frequency_hz - f).abs() / f);
                    }
                }
                let (wk, wl, wf, _, werr) = *cmp.worst().unwrap_or(&(0, 0, 0.0, 0.0, f64::NAN));
                println!(
                    "{name:<34} {:>6} {:>6} {:>14.3e} {:>12.3e}  ⟨{wk},{wl}⟩ ({wf:.1} Hz)",
                    ks.last().unwrap(),
                    max_l,
                    werr,
                    beyond
                );
                if !cmp.problems.is_empty() {
                    // Evidence for the report: does the library converge to the exact value?
                    let mut line = format!("{name}: worst error with more radial splines:");
                    for n in [32usize, 48] {
                        let mut fine = cfg.clone();
                        fine.radial_splines = annular_plate::config::RadialSplines::Fixed(n);
                        match PlateModel::new(&fine) {
                            Ok(m) => {
                                let c =
                                    compare(&m, &annulus, material, &exact, f64::INFINITY, false);
                                line += &format!(
                                    " n={n}: {:.3e}",
                                    c.worst().map(|w| w.4).unwrap_or(f64::NAN)
                                );
                            }
                            Err(e) => line += &format!(" n={n}: {e}"),
                        }
                    }
                    println!("    {line}");
                    notes.push(line);
                }
                all_problems.extend(cmp.problems.iter().map(|p| format!("{name}: {p}")));
            }
        }
    }
    assert!(
        all_problems.is_empty(),
        "{} problems:\n{}\n(for comparison, the library with more radial splines:\n{})",
        all_problems.len(),
        all_problems.join("\n"),
        notes.join("\n")
    );
}

/// The paper's Table 1 (section 5.1): r_i = 0.075 m, r_a = 0.15 m, h = 0.01 m,
/// E = 2.1e11 Pa, ν = 0.3, ρ = 7800 kg/m³, clamped inside, free outside.
#[test]
fn paper_table_1_lathe_disc() {
    let material = Material {
        thickness: 0.01,
        density: 7800.0,
        youngs_modulus: 2.1e11,
        poisson_ratio: 0.3,
    };
    let (ri, ra) = (0.075, 0.15);
    let annulus = Annulus::new(ri, ra, material.poisson_ratio, Edge::Clamped, Edge::Free);
    let ansys = [
        1451.0, 1480.0, 1480.0, 1637.0, 1637.0, 2065.0, 2065.0, 2848.0, 2848.0, 3977.0,
    ];
    let modelica = [
        1449.0, 1478.0, 1478.0, 1635.0, 1635.0, 2064.0, 2064.0, 2847.0, 2847.0, 3974.0,
    ];
    // The first 10 frequencies, counting the cos/sin pair of each k ≥ 1 twice.
    let exact_kl = annulus.lowest_modes(10);
    let mut exact10: Vec<(u32, u32, f64)> = Vec::new();
    for m in &exact_kl {
        let f = material.frequency_hz(m.lambda);
        for _ in 0..if m.k == 0 { 1 } else { 2 } {
            exact10.push((m.k, m.l, f));
        }
    }
    exact10.truncate(10);
    println!("Table 1 disc: exact vs the paper (Hz)");
    println!(
        "{:>3} {:>3} {:>12} {:>7} {:>10} {:>9} {:>10}",
        "k", "l", "exact", "Ansys", "Ansys/ex-1", "Modelica", "Mod./ex-1"
    );
    let mut problems = Vec::new();
    for (i, &(k, l, f)) in exact10.iter().enumerate() {
        let da = ansys[i] / f - 1.0;
        let dm = modelica[i] / f - 1.0;
        println!(
            "{k:>3} {l:>3} {f:>12.3} {:>7} {:>9.3}% {:>9} {:>9.3}%",
            ansys[i],
            100.0 * da,
            modelica[i],
            100.0 * dm
        );
        // The exact (thin-plate) value lies 0.1 … 0.3 % below Ansys' Shell63 result.
        // Ansys is printed to whole Hz, so any value in [printed − 0.5, printed + 0.5] is
        // what the table allows: require the interval to meet the 0.1 … 0.3 % band.
        let lo = (ansys[i] - 0.5) / f - 1.0;
        let hi = (ansys[i] + 0.5) / f - 1.0;
        if hi < 1e-3 || lo > 3e-3 {
            problems.push(format!("mode {} ⟨{k},{l}⟩: Ansys {} Hz is {:.3}…{:.3} % above exact {:.3} Hz, outside 0.1…0.3 %", i + 1, ansys[i], 100.0 * lo, 100.0 * hi, f));
        }
    }
    // The same ⟨k, l⟩ in Table 1's order: k = 0..=5, l = 0.
    let kl: Vec<(u32, u32)> = exact10.iter().map(|&(k, l, _)| (k, l)).collect();
    assert_eq!(
        kl,
        vec![
            (0, 0),
            (1, 0),
            (1, 0),
            (2, 0),
            (2, 0),
            (3, 0),
            (3, 0),
            (4, 0),
            (4, 0),
            (5, 0)
        ],
        "exact mode order"
    );

    let mut cfg = PlateConfig::lathe_disc();
    cfg.density = material.density;
    cfg.nodal_diameters = (0..=5).collect();
    cfg.nodal_circles = vec![0];
    let model = PlateModel::new(&cfg).expect("Table 1 model");
    let cmp = compare(&model, &annulus, material, &exact_kl[..6], REL_TOL, true);
    let lib10: Vec<f64> = model
        .modes()
        .iter()
        .take(10)
        .map(|m| m.frequency_hz)
        .collect();
    println!(
        "library (radial_splines = {}): {:?}",
        cfg.radial_splines,
        lib10.iter().map(|f| format!("{f:.2}")).collect::<Vec<_>>()
    );
    if let Some(w) = cmp.worst() {
        println!(
            "library worst relative error vs exact: {:.3e} at ⟨{},{}⟩",
            w.4, w.0, w.1
        );
    }
    problems.extend(cmp.problems);
    assert!(problems.is_empty(), "{}", problems.join("\n"));
}

/// Error vs number of radial B-splines. Cubic B-splines in a Ritz method for a
/// 4th-order problem: eigenvalue (and so relative frequency) error O(h^{2(p+1−m)})
/// = O(h⁴), h = (r_a − r_i)/(n − 3) with n splines (uniform open knot vector).
#[test]
fn error_decreases_at_the_cubic_b_spline_rate() {
    let material = steel();
    let splines = [8usize, 12, 16, 24, 32, 48];
    type Case = (f64, Boundary, Boundary, &'static [u32], &'static [u32]);
    let cases: [Case; 4] = [
        (
            0.5,
            Boundary::Clamped,
            Boundary::Free,
            &[0, 1, 2, 3],
            &[0, 1],
        ),
        (0.1, Boundary::Free, Boundary::Free, &[0, 1, 2, 3], &[0, 1]),
        (
            0.9,
            Boundary::Supported,
            Boundary::Supported,
            &[0, 1, 2, 3],
            &[0, 1],
        ),
        (
            0.5,
            Boundary::Clamped,
            Boundary::Clamped,
            &[0, 1, 2, 3],
            &[0],
        ),
    ];
    let mut problems = Vec::new();
    println!(
        "max relative frequency error over the requested ⟨k,l⟩ vs radial_splines n (h ∝ 1/(n−3)):"
    );
    for (ratio, inner, outer, ks, ls) in cases {
        let annulus = Annulus::new(
            ratio * OUTER_RADIUS,
            OUTER_RADIUS,
            material.poisson_ratio,
            edge(inner),
            edge(outer),
        );
        let exact: Vec<ExactMode> = ks
            .iter()
            .flat_map(|&k| {
                let lams = lambdas_at_least(&annulus, k, ls.len());
                ls.iter().filter_map(move |&l| {
                    let lam = lams[l as usize];
                    (lam > 0.0).then_some(ExactMode { k, l, lambda: lam })
                })
            })
            .collect();
        let mut errs = Vec::new();
        for &n in &splines {
            let mut cfg = plate_config(ratio, inner, outer, ks, ls, material);
            cfg.radial_splines = annular_plate::config::RadialSplines::Fixed(n);
            let model = PlateModel::new(&cfg)
                .unwrap_or_else(|e| panic!("{}: {n} splines: {e}", case_name(ratio, inner, outer)));
            let cmp = compare(&model, &annulus, material, &exact, f64::INFINITY, false);
            problems.extend(
                cmp.problems
                    .iter()
                    .map(|p| format!("{} n={n}: {p}", case_name(ratio, inner, outer))),
            );
            errs.push(cmp.worst().map(|w| w.4).unwrap_or(f64::NAN));
        }
        let mut line = format!("{:<34}", case_name(ratio, inner, outer));
        for (i, (&n, &e)) in splines.iter().zip(&errs).enumerate() {
            line += &format!(" n={n}: {e:.2e}");
            if i > 0 {
                let p = (errs[i - 1] / e).ln()
                    / (((n - 3) as f64) / ((splines[i - 1] - 3) as f64)).ln();
                line += &format!(" (p={p:.2})");
            }
        }
        println!("{line}");
        // The error must fall at every refinement …
        for i in 1..splines.len() {
            // NaN counts as not decreasing.
            if errs[i].partial_cmp(&errs[i - 1]) != Some(std::cmp::Ordering::Less) {
                problems.push(format!(
                    "{}: error did not decrease from n={} ({:.3e}) to n={} ({:.3e})",
                    case_name(ratio, inner, outer),
                    splines[i - 1],
                    errs[i - 1],
                    splines[i],
                    errs[i]
                ));
            }
        }
        // … and at the h⁴ rate over the asymptotic range n = 16 … 48 (least-squares slope of
        // log error vs log h, required within 4 ± 0.5).
        let pts: Vec<(f64, f64)> = splines
            .iter()
            .zip(&errs)
            .filter(|(n, _)| **n >= 16)
            .map(|(&n, &e)| ((1.0 / (n - 3) as f64).ln(), e.ln()))
            .collect();
        let (x, y): (Vec<f64>, Vec<f64>) = pts.into_iter().unzip();
        let slope = support::fit::least_squares_slope(&x, &y);
        println!("{:<34} fitted order over n = 16…48: {slope:.2}", "");
        if !(3.5..=4.5).contains(&slope) {
            problems.push(format!(
                "{}: fitted convergence order {slope:.2} outside 4 ± 0.5",
                case_name(ratio, inner, outer)
            ));
        }
    }
    assert!(problems.is_empty(), "{}", problems.join("\n"));
}

/// The exact solver checks itself: every mode has l nodal circles, satisfies its
/// edge conditions, and a 4× finer scan finds exactly the same roots.
#[test]
fn exact_solver_is_self_consistent() {
    let nu = 0.3;
    let mut worst_residual: f64 = 0.0;
    let mut worst_rayleigh: f64 = 0.0;
    for ratio in RATIOS {
        for inner in Edge::ALL {
            for outer in Edge::ALL {
                let annulus = Annulus::new(ratio * OUTER_RADIUS, OUTER_RADIUS, nu, inner, outer);
                let name = format!("{}-{} {ratio}", inner.name(), outer.name());
                let modes = annulus.lowest_modes(N_MODES);
                let lam_top = modes.last().unwrap().lambda * 1.5;
                let max_k = modes.iter().map(|m| m.k).max().unwrap();
                for k in 0..=max_k + 2 {
                    let coarse = annulus.lambdas(k, lam_top);
                    let fine = annulus.lambdas_with_step(k, lam_top, annulus.default_step() / 4.0);
                    assert_eq!(coarse.len(), fine.len(), "{name} k={k}: root count differs with a 4× finer scan: {coarse:?} vs {fine:?}");
                    for (a, b) in coarse.iter().zip(&fine) {
                        assert!(
                            (a - b).abs() <= 1e-12 * a.max(1.0),
                            "{name} k={k}: root {a} vs {b} with the finer scan"
                        );
                    }
                    // No elastic root hides below the scan start.
                    if let Some(first) = coarse.iter().find(|&&l| l > 0.0) {
                        assert!(
                            first * OUTER_RADIUS > 10.0 * Annulus::LAMBDA_MIN_TIMES_RA,
                            "{name} k={k}: first root λ r_a = {} too close to the scan start",
                            first * OUTER_RADIUS
                        );
                    }
                    for (l, &lam) in coarse.iter().enumerate() {
                        let shape = annulus.radial_shape(k, lam);
                        // 1000 samples: ≥ 50 per half-wave for the l ≤ 6 here
                        let circles = count_sign_changes(
                            |r| shape.value(r),
                            annulus.inner_radius,
                            annulus.outer_radius,
                            1000,
                        );
                        assert_eq!(
                            circles,
                            l,
                            "{name}: exact ⟨k={k}, l={l}⟩ (λ r_a = {}) has {circles} nodal circles",
                            lam * OUTER_RADIUS
                        );
                        if lam == 0.0 {
                            continue;
                        }
                        for (i, res) in shape.edge_residuals().into_iter().enumerate() {
                            worst_residual = worst_residual.max(res);
                            assert!(
                                res < 1e-12,
                                "{name}: ⟨k={k}, l={l}⟩ edge condition {i} residual {res:e}"
                            );
                        }
                        // Rayleigh quotient of the exact shape with the plate energy = λ⁴.
                        let rq = shape.rayleigh_quotient();
                        let rq_err = (rq.sqrt().sqrt() - lam).abs() / lam;
                        worst_rayleigh = worst_rayleigh.max(rq_err);
                        assert!(rq_err < 1e-9, "{name}: ⟨k={k}, l={l}⟩ Rayleigh quotient gives λ = {}, root λ = {lam} (rel {rq_err:e})", rq.sqrt().sqrt());
                    }
                }
                // Modes are sorted and distinct.
                for w in modes.windows(2) {
                    assert!(w[0].lambda <= w[1].lambda && (w[0].k, w[0].l) != (w[1].k, w[1].l));
                }
            }
        }
    }
    println!("exact solver: worst edge-condition residual {worst_residual:.2e}, worst Rayleigh-quotient λ mismatch {worst_rayleigh:.2e}");
}

/// λ depends on the geometry only through r_i/r_a: λ r_a is scale invariant.
#[test]
fn exact_lambda_scales_with_size() {
    for (inner, outer) in [
        (Edge::Free, Edge::Clamped),
        (Edge::Supported, Edge::Free),
        (Edge::Free, Edge::Free),
    ] {
        let a = Annulus::new(0.03, 0.1, 0.3, inner, outer);
        let b = Annulus::new(0.3, 1.0, 0.3, inner, outer);
        for k in 0..4 {
            // roots with λ r_a < 30, searched a little beyond on both
            let la: Vec<f64> = a
                .lambdas(k, 320.0)
                .into_iter()
                .filter(|x| x * 0.1 < 30.0)
                .collect();
            let lb: Vec<f64> = b
                .lambdas(k, 32.0)
                .into_iter()
                .filter(|x| x * 1.0 < 30.0)
                .collect();
            assert_eq!(la.len(), lb.len());
            assert!(la.len() >= 3);
            for (x, y) in la.iter().zip(&lb) {
                assert!(
                    (x * 0.1 - y * 1.0).abs() <= 1e-12 * (x * 0.1).max(1e-300),
                    "{x} vs {y}"
                );
            }
        }
    }
}
