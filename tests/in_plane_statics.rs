//! In-plane statics and residual flexibility (docs/in_plane.md, "Statics
//! and residual flexibility"): the library's static patch compliances, and
//! the retained in-plane modes plus the residual, against exact plane-stress
//! solutions written separately (`tests/support/in_plane_static.rs`: closed
//! forms per harmonic, no B-splines, no modes), where the modes alone are
//! far off.
//!
//! Run with `-- --nocapture` for the tables.

mod support;

use annular_plate::model::in_plane::{
    modal_kernel, residual_kernel, InPlaneDiscretisation, InPlaneEdge, InPlaneFamily, InPlaneMode,
    InPlanePlate, LoadPatch, DEFAULT_SPLINES,
};
use std::f64::consts::PI;
use support::in_plane_exact::Edge;
use support::in_plane_static::{torsion_rim_twist, torsion_ring_mean, InPlaneStatic};
use support::mindlin_static::Patch;

/// Truncation of the exact series, relative to its largest diagonal value:
/// far below the 1e-5 compared.
const EXACT_TOL: f64 = 1e-7;
/// The most harmonics of the exact series.
const K_EXACT: u32 = 3000;

/// The bench disc (config/brake_bench.yaml) with in-plane edges.
fn bench(inner: InPlaneEdge, outer: InPlaneEdge) -> InPlanePlate {
    InPlanePlate {
        youngs_modulus: 2.1e11,
        poisson_ratio: 0.3,
        density: 7850.0,
        thickness: 0.0181,
        inner_radius: 0.07,
        outer_radius: 0.153,
        inner_edge: inner,
        outer_edge: outer,
    }
}

fn edge(e: InPlaneEdge) -> Edge {
    match e {
        InPlaneEdge::Fixed => Edge::Fixed,
        InPlaneEdge::Free => Edge::Free,
    }
}

fn exact_plate(p: &InPlanePlate) -> InPlaneStatic {
    InPlaneStatic::new(
        p.youngs_modulus,
        p.poisson_ratio,
        p.thickness,
        p.inner_radius,
        p.outer_radius,
        edge(p.inner_edge),
        edge(p.outer_edge),
    )
}

/// The modes ⟨k, l⟩, k ≤ `k_max`, l < `orders`, of every family.
fn retained(disc: &InPlaneDiscretisation, k_max: u32, orders: usize) -> Vec<InPlaneMode> {
    let mut out = Vec::new();
    for k in 0..=k_max {
        for &family in InPlaneFamily::of(k) {
            out.extend(disc.modes(k, family, orders).expect("modes"));
        }
    }
    out
}

fn relative(a: [[f64; 2]; 2], b: [[f64; 2]; 2], scale: f64) -> f64 {
    let mut worst: f64 = 0.0;
    for i in 0..2 {
        for j in 0..2 {
            worst = worst.max((a[i][j] - b[i][j]).abs() / scale);
        }
    }
    worst
}

/// Hub fixed, rim free, a uniform circumferential load on the rim ring
/// [r_a − c, r_a]: the k = 0 torsional harmonic of the library's static
/// solve is the closed-form torsion; the torsional modes alone approach it
/// as more orders are retained, modes + residual meet it.
#[test]
fn torsion_of_a_hub_fixed_disc_matches_the_closed_form() {
    let p = bench(InPlaneEdge::Fixed, InPlaneEdge::Free);
    let (ri, ra, h) = (p.inner_radius, p.outer_radius, p.thickness);
    let g = p.shear_modulus();
    // The closed form's ring mean tends to r_a times the rim twist.
    let thin = torsion_ring_mean(ri, g, h, ra - 1e-7, ra, 1.0);
    let rim = ra * torsion_rim_twist(ri, ra, g, h, 1.0);
    assert!((thin - rim).abs() < 1e-6 * rim, "{thin:e} vs {rim:e}");

    let c = h;
    let patch = LoadPatch::new(ri, ra, ra, c);
    let (lo, hi) = patch.radial;
    // A unit tangential force on the patch: its k = 0 part is the ring load
    // of the same total force, torque ∫ r dA-weighted.
    let torque = (hi.powi(3) - lo.powi(3)) / 3.0 / (0.5 * (hi * hi - lo * lo));
    let exact = torsion_ring_mean(ri, g, h, lo, hi, torque);
    let disc = InPlaneDiscretisation::new(&p, DEFAULT_SPLINES).expect("discretisation");
    let harmonics = disc.patch_harmonics(&[patch]);
    let mut last_modal = f64::INFINITY;
    for orders in [1, 2, 4, 8, 16] {
        let modes = disc
            .modes(0, InPlaneFamily::Torsional, orders)
            .expect("modes");
        let modal = modal_kernel(&modes, &patch, &patch, 1, |_, _| false).coefficients[0][3];
        let residual = residual_kernel(&harmonics, &modes, 0, 0).coefficients[0][3];
        let (err_modal, err_total) = (
            (modal - exact).abs() / exact,
            (modal + residual - exact).abs() / exact,
        );
        println!(
            "torsion, {orders:>2} orders: exact {exact:.9e} m/N, modes {modal:.9e} ({err_modal:.1e}), modes + residual {:.9e} ({err_total:.1e})",
            modal + residual
        );
        assert!(modal < exact, "the modal sum approaches from below");
        assert!(err_modal < last_modal, "{err_modal:e} after {last_modal:e}");
        last_modal = err_modal;
        // The k = 0 Ritz solve on DEFAULT_SPLINES: measured 5.6e-8 (the patch
        // edge r_a − c falls inside a span); the issue asks 1e-3.
        assert!(err_total < 1e-6, "{err_total:e}");
        assert!(
            err_modal > 100.0 * err_total,
            "{err_modal:e} vs {err_total:e}"
        );
    }
}

/// Hub fixed with the rim free and with the rim fixed: radial and tangential
/// patch forces at the rim and at mid-radius, read under the load, 90° and
/// 180° away and at the other radius.
#[test]
fn modes_plus_residual_match_the_exact_in_plane_patch_compliance() {
    let mut worst_total: f64 = 0.0;
    for outer in [InPlaneEdge::Free, InPlaneEdge::Fixed] {
        let p = bench(InPlaneEdge::Fixed, outer);
        let exact_plate = exact_plate(&p);
        let (ri, ra, c) = (p.inner_radius, p.outer_radius, p.thickness);
        let mid = 0.5 * (ri + ra);
        let disc = InPlaneDiscretisation::new(&p, DEFAULT_SPLINES).expect("discretisation");
        let modes = retained(&disc, 6, 2);
        for (r_load, r_other) in [(ra, mid), (mid, ra)] {
            let reads = [
                (r_load, 0.0),
                (r_load, 0.5 * PI),
                (r_load, PI),
                (r_other, 0.0),
                (r_other, 0.3),
            ];
            let exact_reads: Vec<(Patch, f64)> = reads
                .iter()
                .map(|&(r, d)| (Patch::new(ri, ra, r, c), d))
                .collect();
            let load = Patch::new(ri, ra, r_load, c);
            let (exact, k_used, backward) =
                exact_plate.series(&load, &exact_reads, EXACT_TOL, K_EXACT);
            assert!(k_used < K_EXACT, "exact series not converged");
            assert!(backward < 1e-12, "backward error {backward:e}");
            let scale = exact[0][0][0].abs().max(exact[0][1][1].abs());
            let patches = [
                LoadPatch::new(ri, ra, r_load, c),
                LoadPatch::new(ri, ra, r_other, c),
            ];
            let h = disc.patch_harmonics(&patches);
            for (&(r, delta), e) in reads.iter().zip(&exact) {
                let a = usize::from(r != r_load);
                let (pa, pb) = (&patches[a], &patches[0]);
                let modal = modal_kernel(&modes, pa, pb, h.len(), |_, _| false).at(delta);
                let residual = residual_kernel(&h, &modes, a, 0).at(delta);
                let total: [[f64; 2]; 2] =
                    std::array::from_fn(|i| std::array::from_fn(|j| modal[i][j] + residual[i][j]));
                let (err_total, err_modal) =
                    (relative(total, *e, scale), relative(modal, *e, scale));
                println!(
                    "outer {:>5} load r {r_load:.4} read r {r:.4} Δθ {delta:.3} ({k_used} exact, {} library harmonics): exact {:.6e} {:.6e} {:.6e} {:.6e} m/N; modes + residual {err_total:.1e}, modes {err_modal:.1e}",
                    outer.name(),
                    h.len(),
                    e[0][0],
                    e[0][1],
                    e[1][0],
                    e[1][1],
                );
                worst_total = worst_total.max(err_total);
                assert!(err_total < 1e-5, "{err_total:e}");
                assert!(
                    err_modal > 10.0 * err_total,
                    "{err_modal:e} vs {err_total:e}"
                );
            }
        }
    }
    println!("worst relative error of modes + residual: {worst_total:.2e} (of the compliance under the load)");
}
