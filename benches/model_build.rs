//! Model build time: the lathe mode set (k = 0..7, l = 0, 1; target well under
//! 10 ms) and a large one (k = 0..60, l = 0..10; target under 100 ms), with
//! the default `plate.radial_splines: auto` (tolerance 1e-6) and with a fixed
//! 32 splines (`plate.radial_splines: 32`). The Mindlin modes
//! (`model::mindlin`, default 120 splines per field) against the Kirchhoff
//! model of the same disc and mode set (the bench disc, k = 0..10, l = 0..3).

use annular_plate::config::{Boundary, PlateConfig, RadialSplines};
use annular_plate::model::mindlin::{
    mindlin_modes, MindlinEdge, MindlinPlate, DEFAULT_SHEAR_CORRECTION, DEFAULT_SPLINES,
};
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

fn mindlin_against_kirchhoff(c: &mut Criterion) {
    let mut disc = PlateConfig::lathe_disc();
    disc.inner_radius = 0.07;
    disc.outer_radius = 0.153;
    disc.thickness = 0.0181;
    disc.inner_boundary = Boundary::Supported;
    disc.outer_boundary = Boundary::Free;
    disc.nodal_diameters = (0..=10).collect();
    disc.nodal_circles = (0..=3).collect();
    c.bench_function("model_build/bench_disc_k0-10_l0-3_kirchhoff_auto", |b| {
        b.iter(|| PlateModel::new(black_box(&disc)).unwrap())
    });
    let mut fixed = disc.clone();
    fixed.radial_splines = RadialSplines::Fixed(DEFAULT_SPLINES);
    c.bench_function(
        "model_build/bench_disc_k0-10_l0-3_kirchhoff_120_splines",
        |b| b.iter(|| PlateModel::new(black_box(&fixed)).unwrap()),
    );
    let plate = MindlinPlate {
        youngs_modulus: disc.youngs_modulus,
        poisson_ratio: disc.poisson_ratio,
        density: disc.density,
        thickness: disc.thickness,
        inner_radius: disc.inner_radius,
        outer_radius: disc.outer_radius,
        shear_correction: DEFAULT_SHEAR_CORRECTION,
        inner_edge: MindlinEdge::Supported,
        outer_edge: MindlinEdge::Free,
    };
    c.bench_function(
        "model_build/bench_disc_k0-10_l0-3_mindlin_120_splines",
        |b| {
            b.iter(|| {
                (0..=10u32)
                    .map(|k| {
                        mindlin_modes(black_box(&plate), k, 4, DEFAULT_SPLINES)
                            .unwrap()
                            .len()
                    })
                    .sum::<usize>()
            })
        },
    );
}

criterion_group!(benches, build, mindlin_against_kirchhoff);
criterion_main!(benches);
