mod support;

use annular_plate::config::{Boundary, PlateConfig};
use annular_plate::model::PlateModel;
use support::exact_plate::Edge;
use support::static_plate::StaticAnnulus;

fn edge(b: Boundary) -> Edge {
    match b {
        Boundary::Free => Edge::Free,
        Boundary::Supported => Edge::Supported,
        Boundary::Clamped => Edge::Clamped,
    }
}

fn annulus(cfg: &PlateConfig) -> StaticAnnulus {
    let d = annular_plate::model::bending_rigidity(cfg.youngs_modulus, cfg.thickness, cfg.poisson_ratio);
    StaticAnnulus::new(cfg.inner_radius, cfg.outer_radius, cfg.poisson_ratio, d, edge(cfg.inner_boundary), edge(cfg.outer_boundary))
}

#[test]
fn explore() {
    let cfg = PlateConfig::lathe_disc();
    let a = annulus(&cfg);
    let r0 = cfg.outer_radius;
    for k in [0u32, 1, 2, 3, 5, 10, 30, 100, 300, 1000, 2000] {
        let h = a.harmonic(k, r0, 1.0);
        println!("k {k:5} W {:.6e} k^3W {:.6e} be {:.1e} res {:?} U/(PW/2) {:.12}", h.at_load(), h.at_load() * (k as f64).powi(3), h.backward_error,
            h.condition_residuals().map(|v| format!("{v:.0e}")), if k <= 300 { h.strain_energy(40) / (0.5 * h.at_load()) } else { f64::NAN });
    }
    let ring = a.harmonic(0, r0, 1.0).at_load();
    println!("ring k0 {:.12e} integ {:.12e} roark {:.12e}", ring, a.ring_load_at_free_edge_by_integration(1.0, r0), a.roark_ring_load_free_outer(1.0, r0, r0));
    for kd in [250u32, 500, 1000, 2000, 4000] {
        let s = a.series(r0, 1.0, r0, 0.0, kd);
        println!("K {kd} direct {:.12e} tail {:.3e} total {:.12e} fit {:?} be {:.1e}", s.direct, s.tail, s.value(), s.tail_fit, s.worst_backward_error);
    }
}

fn contributions(model: &PlateModel, r0: f64) -> std::collections::BTreeMap<(u32, u32), f64> {
    let mut out = std::collections::BTreeMap::new();
    let kd = &model.body().modal_stiffness;
    for (i, m) in model.modes().iter().enumerate() {
        let w = model.mode_shape(i, r0, 0.0).w;
        *out.entry((m.k, m.l)).or_insert(0.0) += w * w / kd[i];
    }
    out
}

#[test]
fn explore2() {
    for (inner, outer, xi) in [(Boundary::Clamped, Boundary::Free, 1.0), (Boundary::Supported, Boundary::Free, 0.5)] {
        let mut cfg = PlateConfig::lathe_disc();
        cfg.inner_boundary = inner;
        cfg.outer_boundary = outer;
        let a = annulus(&cfg);
        let r0 = cfg.inner_radius + xi * (cfg.outer_radius - cfg.inner_radius);
        let exact = a.series(r0, 1.0, r0, 0.0, 2000);
        println!("=== {inner:?}-{outer:?} r0 {r0} exact {:.10e}", exact.value());
        for (splines, lmax) in [(24usize, 8u32), (24, 18), (48, 40), (96, 50), (200, 50)] {
            cfg.nodal_diameters = (0..=60).collect();
            cfg.nodal_circles = (0..=lmax).collect();
            cfg.radial_splines = splines;
            let t = std::time::Instant::now();
            let model = PlateModel::new(&cfg).unwrap();
            let c = contributions(&model, r0);
            println!("splines {splines} lmax {lmax} build {:?}", t.elapsed());
            let mut tot = 0.0;
            for k in [0u32, 1, 2, 3, 5, 7, 10, 15, 20, 30, 45, 60] {
                let s8: f64 = c.iter().filter(|((kk, l), _)| *kk == k && *l <= 8).map(|(_, v)| v).sum();
                let s1: f64 = c.iter().filter(|((kk, l), _)| *kk == k && *l <= 1).map(|(_, v)| v).sum();
                let sall: f64 = c.iter().filter(|((kk, _), _)| *kk == k).map(|(_, v)| v).sum();
                let e = exact.terms[k as usize];
                println!("  k {k:3} exact {e:.6e} l<=1 {:+.2e} l<=8 {:+.2e} all {:+.2e}", s1 / e - 1.0, s8 / e - 1.0, sall / e - 1.0);
            }
            for v in c.values() { tot += v; }
            println!("  total k<=60 all l {:.8e} rel {:+.4e}; exact partial k<=60 {:.8e}", tot, tot / exact.value() - 1.0, exact.partial(60));
        }
    }
}

#[test]
fn explore3() {
    for (inner, outer, xi) in [(Boundary::Clamped, Boundary::Free, 1.0), (Boundary::Supported, Boundary::Free, 0.5)] {
        let mut cfg = PlateConfig::lathe_disc();
        cfg.inner_boundary = inner;
        cfg.outer_boundary = outer;
        let a = annulus(&cfg);
        let r0 = cfg.inner_radius + xi * (cfg.outer_radius - cfg.inner_radius);
        let exact = a.series(r0, 1.0, r0, 0.0, 2000).value();
        let lmax_all = 18u32;
        cfg.nodal_diameters = (0..=200).collect();
        cfg.nodal_circles = (0..=lmax_all).collect();
        cfg.radial_splines = 24;
        let t = std::time::Instant::now();
        let model = PlateModel::new(&cfg).unwrap();
        let c = contributions(&model, r0);
        println!("=== {inner:?}-{outer:?} exact {exact:.10e} build {:?}", t.elapsed());
        let err = |km: u32, lm: u32| 1.0 - c.iter().filter(|((k, l), _)| *k <= km && *l <= lm).map(|(_, v)| v).sum::<f64>() / exact;
        print!("kmax\\lmax");
        for lm in [0u32, 1, 2, 3, 4, 6, 8, 12, 18] { print!(" {lm:>9}"); }
        println!();
        for km in [0u32, 1, 3, 5, 7, 10, 15, 20, 30, 40, 50, 60, 80, 100, 150, 200] {
            print!("{km:9}");
            for lm in [0u32, 1, 2, 3, 4, 6, 8, 12, 18] { print!(" {:9.3e}", err(km, lm)); }
            println!();
        }
        for target in [1e-2, 1e-3] {
            let mut best = None;
            for lm in 0..=lmax_all {
                if let Some(km) = (0..=200u32).find(|&km| err(km, lm) <= target) {
                    let dof = (2 * km + 1) * (lm + 1);
                    println!("target {target}: lmax {lm} -> kmax {km}, dof {dof}, err {:.4e}", err(km, lm));
                    if best.map_or(true, |(d, _, _)| dof < d) { best = Some((dof, km, lm)); }
                }
            }
            println!("BEST {target}: {best:?}");
        }
    }
}

#[test]
fn explore4() {
    use annular_plate::config::{Config, NodePosition, WrenchConfig, IntegratorKind};
    for (inner, xi) in [(Boundary::Clamped, 1.0), (Boundary::Supported, 0.5)] {
      for speed in [0.0, 10.0] {
       for integ in [IntegratorKind::Exponential, IntegratorKind::ImplicitMidpoint, IntegratorKind::Rk4] {
        let mut c = Config::default();
        c.plate.inner_boundary = inner;
        c.plate.nodal_diameters = (0..=7).collect();
        c.plate.nodal_circles = vec![0, 1];
        c.plate.damping = vec![0.9];
        c.nodes.ale = vec![NodePosition { radial: xi, angular: 0.0 }];
        let p = 100.0;
        c.loads.ale = vec![WrenchConfig { force: [0., 0., -p], moment: [0.; 3] }];
        c.joint.speed = speed;
        c.simulation.integrator = integ; if integ != IntegratorKind::Exponential { c.simulation.rate_hz = 20000.0; }
        let mut sim = annular_plate::dynamics::Simulation::new(c.clone()).unwrap();
        let model = PlateModel::new(&c.plate).unwrap();
        let r0 = model.radius_at(xi);
        let cc = contributions(&model, r0);
        let modal: f64 = -p * cc.values().sum::<f64>();
        let mut spin = 0.0;
        for (i, m) in model.modes().iter().enumerate() {
            let w = model.mode_shape(i, r0, 0.0).w;
            let kk = model.body().modal_stiffness[i] - (m.k as f64 * speed).powi(2) * model.body().modal_mass[i];
            let d = model.body().modal_damping[i] * m.k as f64 * speed;
            spin += -p * w * w * kk / (kk * kk + d * d);
        }
        println!("spin prediction rel to modal {:+.6e}", spin / modal - 1.0);
        let t = std::time::Instant::now();
        let mut hist = vec![];
        let nsteps = if integ == IntegratorKind::Exponential { 400 } else { 4000 }; for n in 0..nsteps { sim.step().unwrap(); if n % (nsteps / 20) == nsteps / 20 - 1 { hist.push(sim.ale_node(0).uz / modal - 1.0); } }
        println!("{inner:?} speed {speed} {integ:?} modal {modal:.10e} uz {:.10e} rel {:+.3e} vs spin-pred {:+.3e} uzdot {:.2e} {:?} hist {:?}", sim.ale_node(0).uz, sim.ale_node(0).uz / modal - 1.0, sim.ale_node(0).uz / spin - 1.0, sim.ale_node(0).uz_dot, t.elapsed(), hist.iter().map(|v| format!("{v:.1e}")).collect::<Vec<_>>());
        }
      }
    }
}
