//! Published frequency parameters λ²a² = ω a² sqrt(ρh/D) (a = outer radius) against
//! the exact Bessel solution (`tests/support/exact_plate.rs`) and the library.
//!
//! Tolerances: a printed value stands for everything that rounds to it, so the exact
//! solution must lie within half a unit of the last printed digit. The library must
//! meet the same band widened by its own accuracy requirement, 1e-4 relative (the
//! requirement checked against the exact solution in `frequencies_match_exact_bessel.rs`).
//!
//! The library cannot model a solid plate (r_i = 0 is singular, paper section 4); the
//! circular-plate tables are checked on an annulus with a free hole of r_i/r_a = 1e-4,
//! whose effect on these λ²a² is below 1e-8 relative (a free hole perturbs the
//! frequencies at O((r_i/r_a)²); the exact annulus is checked against the table too).

mod support;

use annular_plate::config::Boundary;
use annular_plate::model::PlateModel;
use support::exact_plate::{Annulus, CircularPlate, Edge, Material};
use support::library_plate;

const OUTER_RADIUS: f64 = 0.15;
const LIBRARY_REL_TOL: f64 = 1e-4;

/// (k nodal diameters, l nodal circles, published λ²a², half a unit of its last printed digit)
type Entry = (u32, u32, f64, f64);

fn material() -> Material {
    Material::steel(0.01)
}

/// λ²a² of the library's ⟨k, l⟩ (both members of a cos/sin pair must agree).
fn library_lambda2(model: &PlateModel, k: u32, l: u32, a: f64, m: Material) -> f64 {
    let modes: Vec<_> = model
        .modes()
        .iter()
        .filter(|md| md.k == k && md.l == l)
        .collect();
    assert_eq!(
        modes.len(),
        if k == 0 { 1 } else { 2 },
        "library modes for ⟨{k},{l}⟩"
    );
    let unit = m.omega(1.0); // ω for λ = 1/m, i.e. sqrt(D/ρh)
    let v: Vec<f64> = modes.iter().map(|md| md.omega / unit * a * a).collect();
    assert!(
        (v[0] - v[v.len() - 1]).abs() <= 1e-12 * v[0],
        "cos/sin pair of ⟨{k},{l}⟩ differ: {v:?}"
    );
    v[0]
}

fn library_model(
    ratio: f64,
    inner: Boundary,
    outer: Boundary,
    entries: &[Entry],
    nu: f64,
) -> PlateModel {
    let m = Material {
        poisson_ratio: nu,
        ..material()
    };
    let mut ks: Vec<u32> = entries.iter().map(|e| e.0).collect();
    ks.sort_unstable();
    ks.dedup();
    let mut ls: Vec<u32> = entries.iter().map(|e| e.1).collect();
    ls.sort_unstable();
    ls.dedup();
    let cfg = library_plate::annulus_config(
        (ratio * OUTER_RADIUS, OUTER_RADIUS),
        (inner, outer),
        &ks,
        &ls,
        m,
    );
    PlateModel::new(&cfg).expect("library model")
}

/// Check one table: the exact solid/annular solution and the library against it.
fn check_table(
    name: &str,
    entries: &[Entry],
    exact: impl Fn(u32, u32) -> f64,
    library: Option<(&PlateModel, f64)>,
) -> Vec<String> {
    let mut problems = Vec::new();
    println!("{name}");
    println!(
        "{:>3} {:>3} {:>11} {:>13} {:>13}",
        "k", "l", "published", "exact", "library"
    );
    for &(k, l, published, half_unit) in entries {
        let ex = exact(k, l);
        let lib = library.map(|(m, a)| library_lambda2(m, k, l, a, material()));
        // print the published value with exactly its printed digits
        let decimals = (-(2.0 * half_unit).log10()).round().max(0.0) as usize;
        println!(
            "{k:>3} {l:>3} {:>11} {ex:>13.6} {:>13}",
            format!("{published:.decimals$}"),
            lib.map(|v| format!("{v:.6}")).unwrap_or_else(|| "-".into())
        );
        if (ex - published).abs() > half_unit * (1.0 + 1e-9) {
            problems.push(format!(
                "{name} ⟨{k},{l}⟩: exact {ex:.6} outside published {published} ± {half_unit}"
            ));
        }
        if let Some(v) = lib {
            let tol = half_unit + LIBRARY_REL_TOL * published;
            if (v - published).abs() > tol {
                problems.push(format!(
                    "{name} ⟨{k},{l}⟩: library {v:.6} outside published {published} ± {tol:.2e}"
                ));
            }
        }
    }
    problems
}

/// Clamped circular plate. Source: A. W. Leissa, *Vibration of Plates*, NASA SP-160
/// (1969), Table 2.1 (values of λ²a² for a clamped circular plate, exact Bessel-function
/// solution; independent of ν). The report is in the stored pages (it.scribd.com,
/// document 384324202, "NASA SP-160 Vibration of Plates").
#[test]
fn clamped_circular_plate_leissa_table_2_1() {
    let table: [Entry; 8] = [
        (0, 0, 10.2158, 5e-5),
        (1, 0, 21.260, 5e-4),
        (2, 0, 34.877, 5e-4),
        (0, 1, 39.771, 5e-4),
        (3, 0, 51.030, 5e-4),
        (1, 1, 60.829, 5e-4),
        (2, 1, 84.583, 5e-4),
        (0, 2, 89.104, 5e-4),
    ];
    let solid = CircularPlate {
        radius: 1.0,
        poisson_ratio: 0.3,
        edge: Edge::Clamped,
    };
    let mut problems = check_table(
        "Leissa Table 2.1, clamped circular plate (exact solid plate)",
        &table,
        |k, l| solid.roots(k, 12.0)[l as usize].powi(2),
        None,
    );

    let ratio = 1e-4;
    let annulus = Annulus::new(
        ratio * OUTER_RADIUS,
        OUTER_RADIUS,
        0.3,
        Edge::Free,
        Edge::Clamped,
    );
    let model = library_model(ratio, Boundary::Free, Boundary::Clamped, &table, 0.3);
    problems.extend(check_table(
        "same, annulus with a free hole r_i/r_a = 1e-4 (exact annulus; library, default radial_splines)",
        &table,
        |k, l| (annulus.lambdas(k, 12.0 / OUTER_RADIUS)[l as usize] * OUTER_RADIUS).powi(2),
        Some((&model, OUTER_RADIUS)),
    ));
    assert!(problems.is_empty(), "{}", problems.join("\n"));
}

/// Simply supported circular plate, ν = 0.3. Source: A. W. Leissa and Y. Narita,
/// "Natural frequencies of simply supported circular plates", J. Sound Vib. 70(2),
/// 221–229 (1980): six-significant-figure λ²a² for n + s ≤ 10 and ν = 0…0.5 (paper
/// located in the stored pages, ja.scribd.com document 269740077).
#[test]
fn simply_supported_circular_plate_leissa_narita_1980() {
    let table: [Entry; 8] = [
        (0, 0, 4.93515, 5e-6),
        (1, 0, 13.8982, 5e-5),
        (2, 0, 25.6133, 5e-5),
        (0, 1, 29.7200, 5e-5),
        (3, 0, 39.9573, 5e-5),
        (1, 1, 48.4789, 5e-5),
        (2, 1, 70.1170, 5e-5),
        (0, 2, 74.1561, 5e-5),
    ];
    let solid = CircularPlate {
        radius: 1.0,
        poisson_ratio: 0.3,
        edge: Edge::Supported,
    };
    let mut problems = check_table(
        "Leissa & Narita 1980, simply supported circular plate, ν = 0.3 (exact solid plate)",
        &table,
        |k, l| solid.roots(k, 12.0)[l as usize].powi(2),
        None,
    );

    let ratio = 1e-4;
    let annulus = Annulus::new(
        ratio * OUTER_RADIUS,
        OUTER_RADIUS,
        0.3,
        Edge::Free,
        Edge::Supported,
    );
    let model = library_model(ratio, Boundary::Free, Boundary::Supported, &table, 0.3);
    problems.extend(check_table(
        "same, annulus with a free hole r_i/r_a = 1e-4 (exact annulus; library, default radial_splines)",
        &table,
        |k, l| (annulus.lambdas(k, 12.0 / OUTER_RADIUS)[l as usize] * OUTER_RADIUS).powi(2),
        Some((&model, OUTER_RADIUS)),
    ));
    assert!(problems.is_empty(), "{}", problems.join("\n"));
}

/// Annular plate clamped at the inner and free at the outer edge, b/a = 0.5, ν = 0.3
/// (the paper's Table 1 geometry). Source: R. D. Blevins, *Formulas for Natural Frequency
/// and Mode Shape* (1979), annular-plate table, as transcribed in the FeenoX test
/// `tests/annulus-modal.fee` (github.com/seamplex/feenox): λ²a² = 13.0, 13.3, 14.7, 18.5
/// for k = 0, 1, 2, 3 (l = 0).
///
/// The k = 3 entry, 18.5, is NOT checked against its printed digits: the exact value is
/// 18.562 (ν = 0.3; 18.34 would need ν = 0.33), outside 18.5 ± 0.05. The exact value is
/// corroborated by the paper's own Ansys result (2065 Hz ⇒ λ²a² ≈ 18.59, a slightly stiff
/// shell model 0.1–0.3 % above exact for all of Table 1) and by the library, which
/// converges to it from above at the h⁴ rate. So the published 18.5 is low by 0.06
/// (0.3 %), more than its rounding allows; it is printed below for the record.
#[test]
fn clamped_free_annulus_blevins_b_over_a_0_5() {
    let table: [Entry; 3] = [(0, 0, 13.0, 0.05), (1, 0, 13.3, 0.05), (2, 0, 14.7, 0.05)];
    let ratio = 0.5;
    let annulus = Annulus::new(
        ratio * OUTER_RADIUS,
        OUTER_RADIUS,
        0.3,
        Edge::Clamped,
        Edge::Free,
    );
    let exact = |k: u32, l: u32| {
        (annulus.lambdas(k, 12.0 / OUTER_RADIUS)[l as usize] * OUTER_RADIUS).powi(2)
    };
    let model = library_model(
        ratio,
        Boundary::Clamped,
        Boundary::Free,
        &[
            (0, 0, 0.0, 0.0),
            (1, 0, 0.0, 0.0),
            (2, 0, 0.0, 0.0),
            (3, 0, 0.0, 0.0),
        ],
        0.3,
    );
    let problems = check_table(
        "Blevins (1979), annular plate clamped inside, free outside, b/a = 0.5, ν = 0.3",
        &table,
        exact,
        Some((&model, OUTER_RADIUS)),
    );
    println!(
        "k=3: published 18.5 (not asserted, see the doc comment), exact {:.6}, library {:.6}",
        exact(3, 0),
        library_lambda2(&model, 3, 0, OUTER_RADIUS, material())
    );
    assert!(problems.is_empty(), "{}", problems.join("\n"));
}
