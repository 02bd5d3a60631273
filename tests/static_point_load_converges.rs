//! A constant node force gives the static solution of the mode set, and that
//! converges to the exact Kirchhoff plate solution as k and l grow (paper
//! section 5.1, Fig. 10). The exact solution (`tests/support/static_plate.rs`)
//! is a Fourier series in θ of closed-form radial solutions, independent of the
//! library's numerics.
//!
//! Two cases: the paper's lathe disc (clamped inside, free outside, force on the
//! rim like the cutting tool) and a supported-inside, free-outside disc with the
//! force at mid-radius.
//!
//! * `exact_solution_checks_itself`: residuals and backward errors of the per-k
//!   solves, Clapeyron's theorem against the energy functional of DESIGN.md,
//!   the k = 0 term against a direct integration and Roark's closed forms,
//!   Maxwell–Betti reciprocity, convergence of the series in k.
//! * `modal_static_deflection_converges_to_exact`: per harmonic (all l) the
//!   library agrees with the exact W_k; the error under the load decreases
//!   monotonically in k_max and l_max; the paper's set and a large set.
//! * `smallest_mode_sets_for_one_and_a_tenth_percent`: exhaustive search of
//!   (k_max, l_max) for 1 % and 0.1 % error under the load (docs/static_convergence.md).
//! * `stepper_settles_to_the_modal_static_value`: a held ALE node force, heavy
//!   damping, every integrator; at rest in both coordinate descriptions, and at
//!   10 rad/s (ALE description) the steady state is the closed-form one of each
//!   ALE mode pair.
//!
//! Run with `-- --nocapture` for the tables.

mod support;

use annular_plate::config::{
    Boundary, Config, Coordinates, IntegratorKind, NodePosition, PlateConfig, WrenchConfig,
};
use annular_plate::dynamics::Simulation;
use annular_plate::model::PlateModel;
use std::collections::BTreeMap;
use support::exact_plate::Edge;
use support::library_plate::edge;
use support::static_plate::StaticAnnulus;

/// Harmonics summed directly in the exact series (a fitted k⁻³ tail follows).
const K_DIRECT: u32 = 2000;
/// Radial B-splines of the convergence studies: enough for the radial functions
/// used here to be converged (from 96 to 128 splines the error under the load of
/// the sets asserted on changes by < 2e-8, at the grid corner k = 200, l = 26 by
/// 1.3e-7; with the default 32 it is off by 2e-6 at k_max ≈ 60, l_max = 8; see
/// docs/static_convergence.md).
const SPLINES: usize = 96;

#[derive(Debug, Clone, Copy)]
struct Case {
    name: &'static str,
    inner: Boundary,
    outer: Boundary,
    /// ξ_r of the loaded node.
    xi: f64,
}

const LATHE: Case = Case {
    name: "lathe disc: clamped–free, force at r_a",
    inner: Boundary::Clamped,
    outer: Boundary::Free,
    xi: 1.0,
};
const SUPPORTED: Case = Case {
    name: "supported–free, force at mid-radius",
    inner: Boundary::Supported,
    outer: Boundary::Free,
    xi: 0.5,
};

fn plate(case: Case, k_max: u32, l_max: u32, splines: usize) -> PlateConfig {
    let mut cfg = PlateConfig::lathe_disc();
    cfg.inner_boundary = case.inner;
    cfg.outer_boundary = case.outer;
    cfg.nodal_diameters = (0..=k_max).collect();
    cfg.nodal_circles = (0..=l_max).collect();
    cfg.radial_splines = annular_plate::config::RadialSplines::Fixed(splines);
    cfg
}

fn load_radius(cfg: &PlateConfig, xi: f64) -> f64 {
    cfg.inner_radius + xi * (cfg.outer_radius - cfg.inner_radius)
}

fn annulus_of(cfg: &PlateConfig, inner: Edge, outer: Edge) -> StaticAnnulus {
    let d = annular_plate::model::bending_rigidity(
        cfg.youngs_modulus,
        cfg.thickness,
        cfg.poisson_ratio,
    );
    StaticAnnulus::new(
        cfg.inner_radius,
        cfg.outer_radius,
        cfg.poisson_ratio,
        d,
        inner,
        outer,
    )
}

fn annulus(case: Case) -> StaticAnnulus {
    annulus_of(
        &plate(case, 0, 0, SPLINES),
        edge(case.inner),
        edge(case.outer),
    )
}

/// Per ⟨k, l⟩: the static deflection under a unit force at (r0, φ = 0),
/// Σ over the cos/sin pair of w_i(r0, 0)² / K_ii, m/N.
fn contributions(model: &PlateModel, r0: f64) -> BTreeMap<(u32, u32), f64> {
    let stiffness = &model.body().modal_stiffness;
    let mut out = BTreeMap::new();
    for (i, m) in model.modes().iter().enumerate() {
        let w = model.mode_shape(i, r0, 0.0).w;
        *out.entry((m.k, m.l)).or_insert(0.0) += w * w / stiffness[i];
    }
    out
}

fn modal_deflection(cfg: &PlateConfig, r0: f64) -> f64 {
    let model = PlateModel::new(cfg).expect("model");
    contributions(&model, r0).values().sum()
}

/// Error of the modal static deflection under the load, 1 − modal/exact
/// (both truncations are Ritz lower bounds: the error is positive).
fn error(modal: f64, exact: f64) -> f64 {
    1.0 - modal / exact
}

fn exact_under_load(case: Case) -> f64 {
    let a = annulus(case);
    let r0 = load_radius(&plate(case, 0, 0, SPLINES), case.xi);
    a.series(r0, 1.0, r0, 0.0, K_DIRECT).value()
}

// ---------------------------------------------------------------------------

#[test]
fn exact_solution_checks_itself() {
    let base = PlateConfig::lathe_disc();
    let (ri, ra) = (base.inner_radius, base.outer_radius);
    let combos = [
        (Edge::Clamped, Edge::Free),
        (Edge::Supported, Edge::Free),
        (Edge::Clamped, Edge::Clamped),
        (Edge::Supported, Edge::Supported),
        (Edge::Free, Edge::Clamped),
        (Edge::Free, Edge::Supported),
        (Edge::Clamped, Edge::Supported),
    ];
    // interior load radii, plus an edge where that edge is free (a force on a
    // supported or clamped edge goes straight into the support)
    let radii = |inner: Edge, outer: Edge| {
        let mut v = vec![
            ri + 0.3 * (ra - ri),
            ri + 0.5 * (ra - ri),
            ri + 0.85 * (ra - ri),
        ];
        if inner == Edge::Free {
            v.push(ri);
        }
        if outer == Edge::Free {
            v.push(ra);
        }
        v
    };
    let ks = [0u32, 1, 2, 3, 7, 30, 100, 1000, 2000];

    // (1) per-k conditions, backward error, Clapeyron U = ½ P W(r0).
    let (mut worst_res, mut worst_be, mut worst_clap): (f64, f64, f64) = (0.0, 0.0, 0.0);
    for &(inner, outer) in &combos {
        let a = annulus_of(&base, inner, outer);
        for r0 in radii(inner, outer) {
            for &k in &ks {
                let h = a.harmonic(k, r0, 1.0);
                let res = h
                    .condition_residuals()
                    .iter()
                    .fold(0.0_f64, |m, v| m.max(*v));
                assert!(
                    h.at_load() > 0.0,
                    "{inner:?}-{outer:?} r0 {r0} k {k}: W_k(r0) = {} must be > 0",
                    h.at_load()
                );
                worst_res = worst_res.max(res);
                worst_be = worst_be.max(h.backward_error);
                if k <= 100 {
                    let clap = (h.strain_energy(48) / (0.5 * h.force * h.at_load()) - 1.0).abs();
                    worst_clap = worst_clap.max(clap);
                }
            }
        }
    }
    println!("per-k solves over 7 edge combinations x 4 load radii (3 interior, 1 free edge) x k in {ks:?}:");
    println!("  worst condition residual {worst_res:.2e}, backward error {worst_be:.2e}, |U/(P W/2) - 1| (k <= 100) {worst_clap:.2e}");
    assert!(worst_res < 1e-12, "condition residual {worst_res:e}");
    assert!(worst_be < 1e-15, "backward error {worst_be:e}");
    assert!(worst_clap < 1e-11, "Clapeyron {worst_clap:e}");

    // (2) the k = 0 term is the ring load (total P on the circle r0): two closed forms.
    let p = 1.0;
    let lathe = annulus(LATHE);
    let ring = lathe.harmonic(0, ra, p);
    let mut worst_ring: f64 = 0.0;
    for r in [ri + 0.25 * (ra - ri), ri + 0.5 * (ra - ri), ra] {
        let w = ring.eval(r)[0];
        let by_integration = lathe.ring_load_at_free_edge_by_integration(p, r);
        let roark = lathe.roark_ring_load_free_outer(p, ra, r);
        println!("  clamped-free ring load at r_a, w({r:.4}): series k=0 {w:.12e}, direct integration {by_integration:.12e}, Roark 1L {roark:.12e}");
        worst_ring = worst_ring
            .max((w / by_integration - 1.0).abs())
            .max((w / roark - 1.0).abs());
    }
    for (case, ro) in [
        (LATHE, ri + 0.5 * (ra - ri)),
        (SUPPORTED, ri + 0.5 * (ra - ri)),
        (SUPPORTED, ra),
    ] {
        let a = annulus(case);
        let h = a.harmonic(0, ro, p);
        for r in [ri + 0.2 * (ro - ri), ri + 0.7 * (ro - ri), ro] {
            let w = h.eval(r)[0];
            let roark = a.roark_ring_load_free_outer(p, ro, r);
            println!(
                "  {}: ring load at {ro:.4}, w({r:.4}): series k=0 {w:.12e}, Roark {roark:.12e}",
                case.name
            );
            worst_ring = worst_ring.max((w / roark - 1.0).abs());
        }
    }
    println!("  worst relative difference of the ring-load closed forms: {worst_ring:.2e}");
    assert!(
        worst_ring < 1e-11,
        "ring load closed forms differ by {worst_ring:e}"
    );

    // (3) Maxwell–Betti: W_k(r1 | force at r2) = W_k(r2 | force at r1).
    let mut worst_recip: f64 = 0.0;
    for &(inner, outer) in &combos {
        let a = annulus_of(&base, inner, outer);
        let rs = radii(inner, outer);
        let pairs = rs
            .iter()
            .enumerate()
            .flat_map(|(i, &r1)| rs[i + 1..].iter().map(move |&r2| (r1, r2)));
        for (r1, r2) in pairs {
            for &k in &[0u32, 1, 2, 5, 20] {
                let w12 = a.harmonic(k, r2, 1.0).eval(r1)[0];
                let w21 = a.harmonic(k, r1, 1.0).eval(r2)[0];
                let scale = a
                    .harmonic(k, r1, 1.0)
                    .at_load()
                    .max(a.harmonic(k, r2, 1.0).at_load());
                worst_recip = worst_recip.max((w12 - w21).abs() / scale);
            }
        }
    }
    println!("  worst reciprocity defect |W(r1|r2) - W(r2|r1)| / max W(ri|ri): {worst_recip:.2e}");
    assert!(worst_recip < 1e-12, "reciprocity defect {worst_recip:e}");

    // (4) convergence of the series under the load.
    for case in [LATHE, SUPPORTED] {
        let a = annulus(case);
        let r0 = load_radius(&base, case.xi);
        let s1 = a.series(r0, 1.0, r0, 0.0, K_DIRECT / 2);
        let s2 = a.series(r0, 1.0, r0, 0.0, K_DIRECT);
        println!("{}: exact deflection under the load (m/N)", case.name);
        println!("  {:>6} {:>18} {:>12}", "K", "sum k <= K", "rel. to limit");
        for kk in [7u32, 15, 30, 60, 100, 250, 500, 1000, 2000] {
            println!(
                "  {kk:>6} {:>18.12e} {:>12.3e}",
                s2.partial(kk),
                s2.partial(kk) / s2.value() - 1.0
            );
        }
        println!(
            "  + tail (A k^-3 + B k^-4, A = {:.6e}, B = {:.6e}) {:.3e}: {:.12e}; with K = {}: {:.12e}",
            s2.tail_fit.0,
            s2.tail_fit.1,
            s2.tail,
            s2.value(),
            K_DIRECT / 2,
            s1.value()
        );
        let k = K_DIRECT as f64;
        let decay = s2.terms[K_DIRECT as usize] * k * k * k / s2.tail_fit.0;
        assert!(
            (decay - 1.0).abs() < 1e-3,
            "terms do not decay like k^-3: k^3 W_k / A = {decay}"
        );
        let agreement = (s1.value() / s2.value() - 1.0).abs();
        assert!(
            agreement < 1e-11,
            "series with K = {} and {} differ by {agreement:e}",
            K_DIRECT / 2,
            K_DIRECT
        );
        assert!(s2.tail.abs() / s2.value() < 1e-6);
    }
}

// ---------------------------------------------------------------------------

#[test]
fn modal_static_deflection_converges_to_exact() {
    for case in [LATHE, SUPPORTED] {
        let exact = exact_under_load(case);
        let a = annulus(case);
        let r0 = load_radius(&plate(case, 0, 0, SPLINES), case.xi);
        println!(
            "=== {}: exact w/P under the load {exact:.10e} m/N",
            case.name
        );

        // (1) per harmonic, with (nearly) all radial functions: the library's W_k(r0)
        // is the exact one up to the radial discretisation.
        let (splines, l_all) = (SPLINES, 50u32);
        let model = PlateModel::new(&plate(case, 10, l_all, splines)).expect("model");
        let c = contributions(&model, r0);
        println!("  per harmonic, {splines} splines, l <= {l_all}: 1 - library/exact");
        for k in [0u32, 1, 2, 3, 5, 7, 10] {
            let lib: f64 = c
                .iter()
                .filter(|((kk, _), _)| *kk == k)
                .map(|(_, v)| v)
                .sum();
            let ex = a.harmonic(k, r0, 1.0).at_load();
            let e = error(lib, ex);
            println!("    k {k:2}: exact {ex:.6e}  library {lib:.6e}  error {e:+.3e}");
            // measured: lathe k <= 3 4.8e-7, k <= 10 1.3e-5; supported k <= 3 5.8e-7, k <= 10 3.4e-5
            let bound = match (case.inner, k) {
                (_, 0..=3) => 1e-6,
                (Boundary::Clamped, _) => 2e-5,
                (_, _) => 5e-5,
            };
            assert!(e > -1e-9 && e < bound, "{}: harmonic k = {k}: error {e:e} (bound {bound:e}; a Ritz value cannot exceed the exact one)", case.name);
        }

        // (2) monotone in k_max at l_max = 8, and in l_max at k_max = 30 (nested mode sets).
        let l_fixed = 8;
        let mut last = f64::INFINITY;
        print!("  l_max = {l_fixed}, k_max = ");
        for k_max in [1u32, 3, 7, 15, 30] {
            let e = error(
                modal_deflection(&plate(case, k_max, l_fixed, SPLINES), r0),
                exact,
            );
            print!("{k_max}: {e:.4e}  ");
            assert!(
                e > 0.0 && e < last,
                "{}: error {e:e} at k_max {k_max} does not decrease (previous {last:e})",
                case.name
            );
            last = e;
        }
        println!();
        let mut last = f64::INFINITY;
        print!("  k_max = 30, l_max = ");
        for l_max in [0u32, 1, 2, 4] {
            let e = error(
                modal_deflection(&plate(case, 30, l_max, SPLINES), r0),
                exact,
            );
            print!("{l_max}: {e:.4e}  ");
            assert!(
                e > 0.0 && e < last,
                "{}: error {e:e} at l_max {l_max} does not decrease (previous {last:e})",
                case.name
            );
            last = e;
        }
        println!();

        // (3) the paper's set (k = 0..7, l = 0, 1: 30 modes) and a large set (k <= 60, l <= 8).
        let paper_cfg = plate(case, 7, 1, SPLINES);
        assert_eq!(paper_cfg.mode_count(), 30);
        let f_top = PlateModel::new(&paper_cfg)
            .expect("model")
            .modes()
            .iter()
            .map(|m| m.frequency_hz)
            .fold(0.0, f64::max);
        println!("  paper set: highest frequency {f_top:.0} Hz");
        let paper = error(modal_deflection(&paper_cfg, r0), exact);
        let large = error(modal_deflection(&plate(case, 60, 8, SPLINES), r0), exact);
        let k_tail: f64 = a.series(r0, 1.0, r0, 0.0, K_DIRECT).value()
            - a.series(r0, 1.0, r0, 0.0, K_DIRECT).partial(60);
        println!(
            "  paper set k 0..7, l 0..1 (30 modes): error {paper:.4e}; large set k <= 60, l <= 8 ({} modes): error {large:.4e} \
             (of which the exact harmonics k > 60: {:.4e})",
            plate(case, 60, 8, SPLINES).mode_count(),
            k_tail / exact
        );
        // measured: lathe 5.313e-2 and 1.139e-3; supported 9.067e-3 and 2.918e-4
        let (paper_expected, large_bound) = match case.inner {
            Boundary::Clamped => (5.313e-2, 1.2e-3),
            _ => (9.067e-3, 3.1e-4),
        };
        assert!(
            (paper / paper_expected - 1.0).abs() < 0.02,
            "{}: paper set error {paper:e}, measured {paper_expected:e}",
            case.name
        );
        assert!(
            large > k_tail / exact && large < large_bound,
            "{}: large set error {large:e} (bound {large_bound:e})",
            case.name
        );
    }
}

// ---------------------------------------------------------------------------

/// Smallest mode sets reaching the targets, as documented in docs/static_convergence.md:
/// (case, target, k_max, l_max).
const DOCUMENTED: [(&str, f64, u32, u32); 4] = [
    ("lathe", 1e-2, 21, 2),
    ("lathe", 1e-3, 62, 9),
    ("supported", 1e-2, 7, 1),
    ("supported", 1e-3, 23, 5),
];

#[test]
fn smallest_mode_sets_for_one_and_a_tenth_percent() {
    // Every ⟨k, l⟩ mode is the same whichever others are requested (one eigenproblem
    // per k on the full radial basis), so one model with k <= 200 (the largest
    // accepted), l <= 50 (the largest accepted) gives the
    // error of every rectangular set (k_max, l_max) by partial sums. The error falls
    // in both k_max and l_max; for each l_max the smallest sufficient k_max is found,
    // and the set with the fewest modes wins.
    const K_GRID: u32 = 200;
    const L_GRID: u32 = 50;
    for (case, tag) in [(LATHE, "lathe"), (SUPPORTED, "supported")] {
        let cfg = plate(case, K_GRID, L_GRID, SPLINES);
        let r0 = load_radius(&cfg, case.xi);
        let exact = exact_under_load(case);
        let a = annulus(case);
        let exact_terms = a.series(r0, 1.0, r0, 0.0, K_DIRECT);
        let model = PlateModel::new(&cfg).expect("model");
        let c = contributions(&model, r0);
        // cumulative[l][k] = Σ_{k' <= k, l' <= l}
        let mut cumulative = vec![vec![0.0; K_GRID as usize + 1]; L_GRID as usize + 1];
        for l in 0..=L_GRID as usize {
            for k in 0..=K_GRID as usize {
                let own = c.get(&(k as u32, l as u32)).copied().unwrap_or(0.0);
                let left = if k > 0 { cumulative[l][k - 1] } else { 0.0 };
                let below = if l > 0 { cumulative[l - 1][k] } else { 0.0 };
                let diag = if k > 0 && l > 0 {
                    cumulative[l - 1][k - 1]
                } else {
                    0.0
                };
                cumulative[l][k] = own + left + below - diag;
            }
        }
        let err = |k: u32, l: u32| error(cumulative[l as usize][k as usize], exact);
        let modes = |k: u32, l: u32| (2 * k + 1) * (l + 1);

        println!(
            "=== {}: error under the load, {SPLINES} radial splines",
            case.name
        );
        let ls = [0u32, 1, 2, 3, 4, 6, 8, 12, 18, 30, 50];
        print!("  {:>6}", "k_max");
        for l in ls {
            print!(" {:>9}", format!("l<={l}"));
        }
        println!();
        for k in [
            0u32, 1, 3, 5, 7, 10, 15, 20, 30, 40, 50, 60, 80, 100, 150, 200,
        ] {
            print!("  {k:>6}");
            for l in ls {
                print!(" {:>9.3e}", err(k, l));
            }
            println!();
        }

        for target in [1e-2, 1e-3] {
            // the exact harmonics beyond k_max alone: no l_max can do better
            let k_floor = (0..=K_DIRECT)
                .find(|&k| error(exact_terms.partial(k), exact) <= target)
                .expect("floor");
            let mut best: Option<(u32, u32, u32)> = None;
            println!(
                "  target {:.1} %: exact harmonics alone need k_max >= {k_floor}",
                target * 100.0
            );
            // printed: the l_max at which the smallest sufficient k_max drops (the front)
            let mut last_k = None;
            for l in 0..=L_GRID {
                if let Some(k) = (0..=K_GRID).find(|&k| err(k, l) <= target) {
                    if last_k != Some(k) {
                        println!(
                            "    l_max {l:2}: k_max {k:3}, {:4} modes, error {:.4e}",
                            modes(k, l),
                            err(k, l)
                        );
                    }
                    last_k = Some(k);
                    if best.is_none_or(|(m, _, _)| modes(k, l) < m) {
                        best = Some((modes(k, l), k, l));
                    }
                }
            }
            let (m, k, l) = best.expect("target reachable");
            // exhaustive: any l_max beyond the grid needs at least (2 k_floor + 1)(L_GRID + 2) modes
            assert!(
                modes(k_floor, L_GRID + 1) > m,
                "search not exhaustive in l_max"
            );
            println!(
                "    smallest: k_max {k}, l_max {l} ({m} modes), error {:.4e}",
                err(k, l)
            );
            let documented = DOCUMENTED
                .iter()
                .find(|d| d.0 == tag && d.1 == target)
                .expect("documented");
            assert_eq!(
                (k, l),
                (documented.2, documented.3),
                "{} {target}: docs/static_convergence.md is out of date",
                case.name
            );

            // the found set and its two smaller neighbours, built as models of their own
            let own = error(modal_deflection(&plate(case, k, l, SPLINES), r0), exact);
            assert!(
                (own - err(k, l)).abs() < 1e-12,
                "set built alone {own:e} vs partial sums {:e}",
                err(k, l)
            );
            assert!(own <= target);
            if k > 0 {
                let e = error(modal_deflection(&plate(case, k - 1, l, SPLINES), r0), exact);
                assert!(
                    e > target,
                    "k_max {} already reaches {target}: {e:e}",
                    k - 1
                );
            }
            if l > 0 {
                let e = error(modal_deflection(&plate(case, k, l - 1, SPLINES), r0), exact);
                assert!(
                    e > target,
                    "l_max {} already reaches {target}: {e:e}",
                    l - 1
                );
            }
        }
    }
}

// ---------------------------------------------------------------------------

#[test]
fn stepper_settles_to_the_modal_static_value() {
    let force = 100.0; // N, pushing the plate down (−z)
    for case in [LATHE, SUPPORTED] {
        let mut base = Config {
            plate: plate(case, 7, 1, SPLINES),
            ..Config::default()
        };
        base.plate.damping = vec![0.9];
        base.nodes.ale = vec![NodePosition {
            radial: case.xi,
            angular: 0.0,
        }];
        base.loads.ale = vec![WrenchConfig {
            force: [0.0, 0.0, -force],
            moment: [0.0; 3],
        }];
        let model = PlateModel::new(&base.plate).expect("model");
        let r0 = model.radius_at(case.xi);
        let body = model.body();
        let modal_static = -force * contributions(&model, r0).values().sum::<f64>();
        println!(
            "=== {}: paper set, modal static w = {modal_static:.10e} m under {force} N",
            case.name
        );

        for speed in [0.0, 10.0] {
            // Steady state of each ALE pair at constant Ω (the gyroscopic term needs q̇):
            // [K − k²Ω²M, ±kΩD; ∓kΩD, K − k²Ω²M] q = f, f on the cos mode only.
            let steady: f64 = model
                .modes()
                .iter()
                .enumerate()
                .map(|(i, m)| {
                    let w = model.mode_shape(i, r0, 0.0).w;
                    let kw = m.k as f64 * speed;
                    let k_eff = body.modal_stiffness[i] - kw * kw * body.modal_mass[i];
                    let circ = kw * body.modal_damping[i];
                    -force * w * w * k_eff / (k_eff * k_eff + circ * circ)
                })
                .sum();
            for integrator in [
                IntegratorKind::Exponential,
                IntegratorKind::ImplicitMidpoint,
                IntegratorKind::Rk4,
            ] {
                // spinning: only the ALE description sees a constant load (in Lagrangian
                // coordinates the load travels at kΩ and a step holds it constant)
                let descriptions: &[Coordinates] = if speed == 0.0 {
                    &[Coordinates::Ale, Coordinates::Lagrangian]
                } else {
                    &[Coordinates::Ale]
                };
                for &coordinates in descriptions {
                    let mut c = base.clone();
                    c.joint.speed = speed;
                    c.simulation.integrator = integrator;
                    c.simulation.coordinates = coordinates;
                    // the exponential integrator is exact for a held load; the others need a
                    // step that resolves the modes for their damping to act
                    let (rate, steps) = match integrator {
                        IntegratorKind::Exponential => (1000.0, 200),
                        _ => (20000.0, 4000),
                    };
                    c.simulation.rate_hz = rate;
                    let mut sim = Simulation::new(c).expect("simulation");
                    for _ in 0..steps {
                        sim.step().expect("step");
                    }
                    // the modal part (uz less the residual flexibility, docs/residual_flexibility.md)
                    let mut node = sim.ale_node(0);
                    node.uz -= sim.residual_deflection(0);
                    let vs_static = node.uz / modal_static - 1.0;
                    let vs_steady = node.uz / steady - 1.0;
                    println!(
                        "  Ω = {speed:4} rad/s {:>17} {:>10}: w = {:.10e} m after {:.2} s, rel. to static {vs_static:+.3e}, to the pair steady state {vs_steady:+.3e}",
                        integrator.name(),
                        format!("{coordinates:?}"),
                        node.uz,
                        sim.time()
                    );
                    // measured: |vs_steady| <= 7e-15 everywhere
                    assert!(
                        vs_steady.abs() < 1e-12,
                        "{} {integrator:?} {coordinates:?} Ω {speed}: {vs_steady:e}",
                        case.name
                    );
                    assert!(
                        node.uz_dot.abs() < 1e-12,
                        "not settled: dw/dt = {:e} m/s",
                        node.uz_dot
                    );
                    if speed == 0.0 {
                        assert!(vs_static.abs() < 1e-12, "{}: {vs_static:e}", case.name);
                    }
                }
            }
        }
    }
}
