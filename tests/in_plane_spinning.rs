//! The in-plane equations of the spinning disc in the turning frame
//! (docs/in_plane.md "Spinning"): M ü + Ω G u̇ + (K + Ω² K_Ω) u = f.
//! The rigid motions of a free–free disc stay rigid at speed — the rotation
//! u_θ = r an equilibrium, the translation turning backwards at Ω in the
//! turning frame (it stands still in space) — G is skew, K_Ω symmetric, and
//! the modal projection is the full one on the modes.

use annular_plate::config::{Boundary, CentrifugalConfig, InPlaneInner, InPlaneOuter, PlateConfig};
use annular_plate::model::in_plane::{
    in_plane_plate, InPlaneDiscretisation, InPlaneFamily, DEFAULT_SPLINES,
};
use annular_plate::model::prestress::LamePrestress;
use faer::Mat;

mod support;

use support::in_plane_exact::{Annulus, Edge, Family};
use support::in_plane_spinning_exact::{roots, SpinningAnnulus};
use support::lame::Lame;

/// The bench disc's steel and radii with the in-plane edges given.
fn disc(inner: InPlaneInner, outer: InPlaneOuter) -> (PlateConfig, CentrifugalConfig) {
    let mut plate = PlateConfig::lathe_disc();
    plate.youngs_modulus = 2.1e11;
    plate.poisson_ratio = 0.3;
    plate.density = 7850.0;
    plate.thickness = 0.0181;
    plate.inner_radius = 0.07;
    plate.outer_radius = 0.153;
    plate.inner_boundary = Boundary::Free;
    let centrifugal = CentrifugalConfig {
        in_plane_inner: inner,
        in_plane_outer: outer,
        ..CentrifugalConfig::default()
    };
    (plate, centrifugal)
}

fn discretisation(plate: &PlateConfig, c: &CentrifugalConfig) -> InPlaneDiscretisation {
    InPlaneDiscretisation::new(&in_plane_plate(plate, c), DEFAULT_SPLINES).unwrap()
}

fn times(a: &Mat<f64>, x: &[f64]) -> Vec<f64> {
    (0..a.nrows())
        .map(|i| (0..a.ncols()).map(|j| a[(i, j)] * x[j]).sum())
        .collect()
}

fn norm(x: &[f64]) -> f64 {
    x.iter().map(|v| v * v).sum::<f64>().sqrt()
}

fn block(x: &[f64], n: usize, at: usize) -> Vec<f64> {
    let mut out = vec![0.0; 2 * n];
    out[at..at + n].copy_from_slice(x);
    out
}

#[test]
fn a_free_free_rigid_rotation_is_an_equilibrium_at_any_speed() {
    let (plate, c) = disc(InPlaneInner::Free, InPlaneOuter::Free);
    let d = discretisation(&plate, &c);
    let spin = d.assemble_spin(0, &LamePrestress::new(&plate, &c));
    let (k_t, m_t) = d.assemble(0, InPlaneFamily::Torsional);
    let n = k_t.nrows();
    // V = r: the B-spline coefficients of a linear function are the Greville abscissae.
    let v = d.basis().greville();
    let y = block(&v, n, n);
    let softening = norm(&times(&m_t, &v));
    // The first elastic torsional ω², for the scale of K.
    let w1 = d.modes(0, InPlaneFamily::Torsional, 2).unwrap()[0].omega;
    let k_omega = times(&spin.spin_stiffness, &y);
    let k_y = times(&k_t, &v);
    println!(
        "rigid rotation: |K y| / (ω₁² |M y|) = {:.2e}, |K_Ω y| / |M y| = {:.2e}",
        norm(&k_y) / (w1 * w1 * softening),
        norm(&k_omega) / softening
    );
    assert!(norm(&k_y) / (w1 * w1 * softening) < 1e-12, "K y = 0");
    assert!(norm(&k_omega) / softening < 1e-9, "K_σ y = M y");
}

#[test]
fn a_free_free_translation_stands_still_in_space() {
    let (plate, c) = disc(InPlaneInner::Free, InPlaneOuter::Free);
    let d = discretisation(&plate, &c);
    let spin = d.assemble_spin(1, &LamePrestress::new(&plate, &c));
    let (k_c, m_c) = d.assemble(1, InPlaneFamily::Coupled);
    let n = k_c.nrows();
    // U = 1, V = −1 (interleaved): u = e_x for the cos partner, e_y for the sin one.
    let y: Vec<f64> = (0..n)
        .map(|i| if i % 2 == 0 { 1.0 } else { -1.0 })
        .collect();
    let my = norm(&times(&m_c, &y));
    let speed: f64 = 3000.0;
    // x_c = y cos Ωt, x_s = −y sin Ωt: e_x turned by −Ωt.
    let mut worst: f64 = 0.0;
    for t in [0.0, 1.3e-4, 4.1e-4] {
        let (s, co) = (speed * t).sin_cos();
        let x: Vec<f64> = (0..2 * n)
            .map(|i| if i < n { y[i] * co } else { -y[i - n] * s })
            .collect();
        let xd: Vec<f64> = (0..2 * n)
            .map(|i| {
                if i < n {
                    -speed * y[i] * s
                } else {
                    -speed * y[i - n] * co
                }
            })
            .collect();
        let xdd: Vec<f64> = x.iter().map(|v| -speed * speed * v).collect();
        let mut residual = vec![0.0; 2 * n];
        for at in [0, n] {
            let acc = times(&m_c, &xdd[at..at + n]);
            let el = times(&k_c, &x[at..at + n]);
            for i in 0..n {
                residual[at + i] += acc[i] + el[i];
            }
        }
        let g = times(&spin.gyroscopic, &xd);
        let ks = times(&spin.spin_stiffness, &x);
        for i in 0..2 * n {
            residual[i] += speed * g[i] + speed * speed * ks[i];
        }
        worst = worst.max(norm(&residual) / (speed * speed * my));
    }
    println!("translation at {speed} rad/s: |residual| / (Ω² |M y|) = {worst:.2e}");
    assert!(worst < 1e-9);
}

#[test]
fn the_coriolis_matrix_is_skew_and_the_spin_stiffness_symmetric() {
    for (inner, outer) in [
        (InPlaneInner::Fixed, InPlaneOuter::Free),
        (InPlaneInner::Free, InPlaneOuter::Free),
    ] {
        let (plate, c) = disc(inner, outer);
        let d = discretisation(&plate, &c);
        for k in 0..3 {
            let s = d.assemble_spin(k, &LamePrestress::new(&plate, &c));
            let (g, ko) = (&s.gyroscopic, &s.spin_stiffness);
            let scale_g = (0..g.nrows())
                .flat_map(|i| (0..g.ncols()).map(move |j| (i, j)))
                .map(|(i, j)| g[(i, j)].abs())
                .fold(0.0, f64::max);
            let scale_k = (0..ko.nrows())
                .map(|i| ko[(i, i)].abs())
                .fold(0.0, f64::max);
            let mut skew: f64 = 0.0;
            let mut sym: f64 = 0.0;
            for i in 0..g.nrows() {
                for j in 0..g.ncols() {
                    skew = skew.max((g[(i, j)] + g[(j, i)]).abs());
                    sym = sym.max((ko[(i, j)] - ko[(j, i)]).abs());
                }
            }
            assert!(
                scale_g > 0.0,
                "k = {k}: the Coriolis force couples the partners"
            );
            assert!(skew == 0.0, "k = {k}: G + Gᵀ = {skew:e}");
            assert!(sym <= 1e-12 * scale_k, "k = {k}: K_Ω − K_Ωᵀ = {sym:e}");
        }
    }
}

#[test]
fn the_modal_spin_terms_are_the_full_ones_on_the_modes() {
    let (plate, c) = disc(InPlaneInner::Fixed, InPlaneOuter::Free);
    let d = discretisation(&plate, &c);
    let prestress = LamePrestress::new(&plate, &c);
    for k in [0, 2] {
        let mut modes = Vec::new();
        for &f in InPlaneFamily::of(k) {
            modes.extend(d.modes(k, f, 2).unwrap());
        }
        let full = d.assemble_spin(k, &prestress);
        let modal = d.modal_spin(k, &prestress, &modes);
        // The modal coordinates' vectors, written from the families' expansion.
        let n0 = if k == 0 {
            d.n_free(InPlaneFamily::Radial)
        } else {
            d.n_free(InPlaneFamily::Coupled)
        };
        let mut columns: Vec<Vec<f64>> = Vec::new();
        let partners = if k == 0 { 1 } else { 2 };
        for p in 0..partners {
            for m in &modes {
                let at = if k == 0 {
                    usize::from(m.family == InPlaneFamily::Torsional) * n0
                } else {
                    p * n0
                };
                let mut col = vec![0.0; full.gyroscopic.nrows()];
                let mut i = 0;
                for j in 0..d.basis().len() {
                    // Free coefficients: every B-spline but the fixed hub's first.
                    if j == 0 {
                        continue;
                    }
                    let fields: &[usize] = match m.family {
                        InPlaneFamily::Radial => &[0],
                        InPlaneFamily::Torsional => &[1],
                        InPlaneFamily::Coupled => &[0, 1],
                    };
                    for &f in fields {
                        col[at + i] = if f == 0 { m.u[j] } else { m.v[j] };
                        i += 1;
                    }
                }
                columns.push(col);
            }
        }
        let project = |mat: &Mat<f64>| {
            Mat::<f64>::from_fn(columns.len(), columns.len(), |a, b| {
                let mb = times(mat, &columns[b]);
                columns[a].iter().zip(mb).map(|(x, y)| x * y).sum()
            })
        };
        let mut worst: f64 = 0.0;
        for (got, full) in [
            (&modal.spin_stiffness, &full.spin_stiffness),
            (&modal.gyroscopic, &full.gyroscopic),
        ] {
            let want = project(full);
            let scale = (0..want.nrows())
                .flat_map(|a| (0..want.ncols()).map(move |b| (a, b)))
                .map(|(a, b)| want[(a, b)].abs())
                .fold(0.0, f64::max);
            assert_eq!((got.nrows(), got.ncols()), (want.nrows(), want.ncols()));
            for a in 0..want.nrows() {
                for b in 0..want.ncols() {
                    worst = worst.max((got[(a, b)] - want[(a, b)]).abs() / scale);
                }
            }
        }
        println!("k = {k}: modal against full projection {worst:.1e}");
        assert!(worst < 1e-12, "k = {k}: {worst:e}");
    }
}

const SPEEDS: [f64; 3] = [1000.0, 3000.0, 15000.0];
const ORDERS: usize = 2;
const TOLERANCE: f64 = 1e-6;
const EDGES: [(InPlaneInner, InPlaneOuter, bool); 2] = [
    (InPlaneInner::Fixed, InPlaneOuter::Free, true),
    (InPlaneInner::Free, InPlaneOuter::Free, false),
];

/// The collocation's (forward, backward) lowest `ORDERS` waves, rigid roots
/// (ω = 0 for k = 0, ω = Ω for k = 1 of a free–free disc) left out.
fn reference_waves(
    plate: &PlateConfig,
    inner_fixed: bool,
    k: u32,
    spin: f64,
    n: usize,
) -> (Vec<f64>, Vec<f64>) {
    let a = SpinningAnnulus::of(plate, inner_fixed);
    let mut z = roots(&a, &Lame::new(plate, inner_fixed), k, spin, n);
    if !inner_fixed && k <= 1 {
        // The double rigid root, possibly split into a complex pair by round-off.
        let rigid = if k == 0 { 0.0 } else { spin };
        z.sort_by(|x, y| {
            (x.0 - rigid)
                .hypot(x.1)
                .total_cmp(&(y.0 - rigid).hypot(y.1))
        });
        z.drain(..2);
    }
    let mut r: Vec<f64> = z
        .into_iter()
        .filter(|&(re, im)| im.abs() < 1e-6 * re.abs().max(1.0))
        .map(|(re, _)| re)
        .collect();
    r.sort_by(f64::total_cmp);
    let backward: Vec<f64> = r
        .iter()
        .copied()
        .filter(|&w| w > 0.0)
        .take(ORDERS)
        .collect();
    let mut forward: Vec<f64> = r.iter().filter(|&&w| w < 0.0).map(|w| -w).collect();
    forward.sort_by(f64::total_cmp);
    forward.truncate(ORDERS);
    (forward, backward)
}

fn relative(a: &[f64], b: &[f64]) -> f64 {
    assert_eq!(a.len(), b.len());
    a.iter()
        .zip(b)
        .map(|(x, y)| (x - y).abs() / y.abs())
        .fold(0.0, f64::max)
}

#[test]
fn spinning_waves_match_an_independent_collocation_solution() {
    let mut overall: f64 = 0.0;
    for (inner, outer, inner_fixed) in EDGES {
        let (plate, c) = disc(inner, outer);
        let d = discretisation(&plate, &c);
        let prestress = LamePrestress::new(&plate, &c);
        for k in 0..=4 {
            let spectrum = d.spectrum(k, &prestress);
            for spin in SPEEDS {
                let got = spectrum.waves(spin, ORDERS).unwrap();
                let (fwd, bwd) = reference_waves(&plate, inner_fixed, k, spin, 48);
                let (fwd64, bwd64) = reference_waves(&plate, inner_fixed, k, spin, 64);
                let own = relative(&fwd, &fwd64).max(relative(&bwd, &bwd64));
                let e = relative(&got.forward, &fwd).max(relative(&got.backward, &bwd));
                println!(
                    "{}–free k = {k} Ω = {spin:>5}: forward {:.1} {:.1}, backward {:.1} {:.1} rad/s; \
                     library {e:.1e}, collocation 48 vs 64 points {own:.1e}",
                    if inner_fixed { "fixed" } else { "free" },
                    fwd[0],
                    fwd[1],
                    bwd[0],
                    bwd[1]
                );
                assert!(own < 1e-9, "the reference is converged");
                assert!(e < TOLERANCE, "k = {k} at {spin} rad/s: {e:e}");
                overall = overall.max(e);
            }
        }
    }
    println!("worst over all: {overall:.2e}");
}

#[test]
fn at_rest_both_waves_are_the_exact_plane_stress_modes() {
    let mut overall: f64 = 0.0;
    for (inner, outer, inner_fixed) in EDGES {
        let (plate, c) = disc(inner, outer);
        let d = discretisation(&plate, &c);
        let prestress = LamePrestress::new(&plate, &c);
        let exact = Annulus {
            youngs_modulus: plate.youngs_modulus,
            poisson_ratio: plate.poisson_ratio,
            density: plate.density,
            inner_radius: plate.inner_radius,
            outer_radius: plate.outer_radius,
            inner: if inner_fixed { Edge::Fixed } else { Edge::Free },
            outer: Edge::Free,
        };
        for k in 0..=4 {
            let mut want = if k == 0 {
                let mut both = exact.roots(0, Family::Torsional, ORDERS, 40);
                both.extend(exact.roots(0, Family::Radial, ORDERS, 40));
                both
            } else {
                exact.roots(k, Family::Coupled, ORDERS, 40)
            };
            want.sort_by(f64::total_cmp);
            want.truncate(ORDERS);
            let got = d.spectrum(k, &prestress).waves(0.0, ORDERS).unwrap();
            let e = relative(&got.forward, &want).max(relative(&got.backward, &want));
            println!(
                "at rest, {}–free k = {k}: {:.1} {:.1} rad/s, {e:.1e}",
                if inner_fixed { "fixed" } else { "free" },
                got.forward[0],
                got.forward[1]
            );
            overall = overall.max(e);
            assert!(e < TOLERANCE, "k = {k}: {e:e}");
        }
    }
    println!("at rest, worst against the exact solution: {overall:.2e}");
}
