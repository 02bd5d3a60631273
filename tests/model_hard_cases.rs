//! scratch measurements (to be replaced)
mod support;

use annular_plate::config::{Boundary, PlateConfig};
use annular_plate::model::PlateModel;
use support::exact_plate::{Annulus, Edge, Material};

fn edge(b: Boundary) -> Edge {
    match b {
        Boundary::Free => Edge::Free,
        Boundary::Supported => Edge::Supported,
        Boundary::Clamped => Edge::Clamped,
    }
}

fn plate(ri: f64, ra: f64, inner: Boundary, outer: Boundary, ks: Vec<u32>, ls: Vec<u32>, splines: usize) -> PlateConfig {
    let mut c = PlateConfig::lathe_disc();
    c.inner_radius = ri;
    c.outer_radius = ra;
    c.inner_boundary = inner;
    c.outer_boundary = outer;
    c.nodal_diameters = ks;
    c.nodal_circles = ls;
    c.radial_splines = splines;
    c
}

/// First `count` λ (elastic and rigid, index = l) for k.
fn lambdas(a: &Annulus, k: u32, count: usize) -> Vec<f64> {
    let step = a.default_step();
    let mut lo = Annulus::LAMBDA_MIN_TIMES_RA / a.outer_radius;
    let mut v = Vec::new();
    if a.has_rigid_body_mode(k) {
        v.push(0.0);
    }
    while v.len() < count {
        let hi = lo + 200.0 * step;
        v.extend(a.determinant_roots(k, lo, hi, step));
        lo = hi;
    }
    v.truncate(count);
    v
}

#[test]
fn measure_high_k() {
    let t0 = std::time::Instant::now();
    let mat = Material::steel(0.01);
    for (name, ri, inner, outer) in [("clamped-free 0.5", 0.075, Boundary::Clamped, Boundary::Free), ("free-free 0.5", 0.075, Boundary::Free, Boundary::Free)] {
        let a = Annulus::new(ri, 0.15, 0.3, edge(inner), edge(outer));
        let ks: Vec<u32> = (0..=60).collect();
        let exact: Vec<Vec<f64>> = ks.iter().map(|&k| lambdas(&a, k, 11)).collect();
        println!("{name}: exact in {:?}; λ r_a max {}", t0.elapsed(), exact[60][10] * 0.15);
        for splines in [32, 48, 64, 96, 128, 192] {
            let t1 = std::time::Instant::now();
            let m = PlateModel::new(&plate(ri, 0.15, inner, outer, ks.clone(), (0..=10).collect(), splines)).unwrap();
            let build = t1.elapsed();
            let mut per_k = vec![0.0f64; 61];
            let mut per_l = vec![0.0f64; 11];
            for md in m.modes() {
                let fe = mat.frequency_hz(exact[md.k as usize][md.l as usize]);
                let e = (md.frequency_hz - fe) / fe;
                per_k[md.k as usize] = per_k[md.k as usize].max(e.abs());
                per_l[md.l as usize] = per_l[md.l as usize].max(e.abs());
                if e < -1e-9 { println!("  BELOW exact: k {} l {} e {e:e}", md.k, md.l); }
            }
            let sel = [0usize, 5, 10, 20, 30, 40, 50, 60];
            println!("  n={splines} ({build:?}): per k {:?}", sel.iter().map(|&k| format!("{k}:{:.2e}", per_k[k])).collect::<Vec<_>>());
            println!("     per l {:?}", per_l.iter().enumerate().map(|(l, e)| format!("{l}:{:.2e}", e)).collect::<Vec<_>>());
            // l=0 only, per k
            let e60: Vec<String> = (0..=10).map(|l| { let md = m.modes().iter().find(|x| x.k == 60 && x.l == l).unwrap(); let fe = mat.frequency_hz(exact[60][l as usize]); format!("{:.2e}", (md.frequency_hz - fe) / fe) }).collect();
            println!("     k=60 per l {:?}", e60);
        }
    }
}

/// Rayleigh quotient of a library radial shape, own quadrature (12-pt GL, 8 cells per span).
fn library_rq(m: &PlateModel, idx: usize, nu: f64) -> f64 {
    let s = &m.radial_shapes()[idx];
    let kk = (s.k as f64).powi(2);
    let (xs, ws) = support::exact_plate::gauss_legendre(12);
    let b = s.basis();
    let (mut u, mut t) = (0.0, 0.0);
    for sp in 0..b.spans() {
        let (a0, a1) = b.span_bounds(sp);
        let cells = ((a1 / a0).ln() / 1.1f64.ln()).ceil().max(1.0) as usize;
        let ratio = (a1 / a0).powf(1.0 / cells as f64);
        let mut c0 = a0;
        for c in 0..cells {
            let c1 = if c + 1 == cells { a1 } else { c0 * ratio };
            for (x, w) in xs.iter().zip(&ws) {
                let r = 0.5 * (c0 + c1) + 0.5 * (c1 - c0) * x;
                let wr = 0.5 * (c1 - c0) * w * r;
                let [v, d1, d2, _] = s.eval(r);
                let p = d1 / r - kk * v / (r * r);
                let q = d1 / r - v / (r * r);
                u += wr * ((d2 + p).powi(2) - 2.0 * (1.0 - nu) * (d2 * p - kk * q * q));
                t += wr * v * v;
            }
            c0 = c1;
        }
    }
    u / t
}

#[test]
fn measure_floor() {
    let mat = Material::steel(0.01);
    let d_over_rhoh = mat.rigidity() / (mat.density * mat.thickness);
    for (ri, inner, outer) in [(0.075, Boundary::Free, Boundary::Free), (0.075, Boundary::Clamped, Boundary::Free)] {
        let a = Annulus::new(ri, 0.15, 0.3, edge(inner), edge(outer));
        for splines in [64, 128, 192, 256, 400] {
            let m = PlateModel::new(&plate(ri, 0.15, inner, outer, vec![2, 3, 30, 60], vec![0, 1], splines)).unwrap();
            for md in m.modes().iter().filter(|x| x.shape != annular_plate::model::AngularShape::Sin) {
                let lam = lambdas(&a, md.k, md.l as usize + 1)[md.l as usize];
                let sh = a.radial_shape(md.k, lam);
                let rq_exact = sh.rayleigh_quotient();
                let rq_lib = library_rq(&m, md.radial, 0.3);
                let w2 = md.omega.powi(2) / d_over_rhoh;
                println!("{:?}-{:?} n={splines} k={} l={}: lib ω² vs λ⁴ {:.3e}; lib RQ vs λ⁴ {:.3e}; exact RQ vs λ⁴ {:.3e}", inner, outer, md.k, md.l, w2 / lam.powi(4) - 1.0, rq_lib / lam.powi(4) - 1.0, rq_exact / lam.powi(4) - 1.0);
            }
        }
    }
}

#[test]
fn print_lambdas() {
    for (inner, outer) in [(Boundary::Clamped, Boundary::Free), (Boundary::Free, Boundary::Free)] {
        let a = Annulus::new(0.075, 0.15, 0.3, edge(inner), edge(outer));
        for k in [0u32, 30, 60] {
            println!("LAM {:?} {:?} {k} {:?}", inner, outer, lambdas(&a, k, 11).iter().map(|l| format!("{l:.17e}")).collect::<Vec<_>>().join(" "));
        }
    }
}
