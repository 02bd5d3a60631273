//! Model build time: the lathe mode set (k = 0..7, l = 0, 1; target well under
//! 10 ms) and a large one (k = 0..60, l = 0..10; target under 100 ms), with
//! the default `plate.radial_splines: auto` (tolerance 1e-6) and with a fixed
//! 32 splines (`plate.radial_splines: 32`).

use annular_plate::config::{PlateConfig, RadialSplines};
use annular_plate::model::PlateModel;
use criterion::{criterion_group, criterion_main, Criterion};
use std::hint::black_box;

fn build(c: &mut Criterion) {
    let lathe = PlateConfig::lathe_disc();
    c.bench_function("model_build/lathe_k0-7_l0-1_auto", |b| {
        b.iter(|| PlateModel::new(black_box(&lathe)).unwrap())
    });
    let mut large = PlateConfig::lathe_disc();
    large.nodal_diameters = (0..=60).collect();
    large.nodal_circles = (0..=10).collect();
    c.bench_function("model_build/k0-60_l0-10_auto", |b| {
        b.iter(|| PlateModel::new(black_box(&large)).unwrap())
    });
    let fixed = |mut p: PlateConfig, n: usize| {
        p.radial_splines = RadialSplines::Fixed(n);
        p
    };
    let lathe32 = fixed(lathe.clone(), 32);
    c.bench_function("model_build/lathe_k0-7_l0-1_32_splines", |b| {
        b.iter(|| PlateModel::new(black_box(&lathe32)).unwrap())
    });
    let large32 = fixed(large.clone(), 32);
    c.bench_function("model_build/k0-60_l0-10_32_splines", |b| {
        b.iter(|| PlateModel::new(black_box(&large32)).unwrap())
    });
    for splines in [16, 24, 48, 64] {
        let p = fixed(PlateConfig::lathe_disc(), splines);
        c.bench_function(&format!("model_build/lathe_{splines}_splines"), |b| {
            b.iter(|| PlateModel::new(black_box(&p)).unwrap())
        });
    }
}

criterion_group!(benches, build);
criterion_main!(benches);
