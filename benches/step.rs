//! One output step per integrator, coordinates and mode count; and the paper's
//! lathe scenario length (5.5 s) at a 10 kHz step (paper: 44.7 CPU-s).

use annular_plate::config::{Config, Coordinates, IntegratorKind, NodePosition, WrenchConfig};
use annular_plate::dynamics::load_models::pad_outputs::PadOutputs;
use annular_plate::dynamics::Simulation;
use criterion::{criterion_group, criterion_main, Criterion};

/// The lathe disc (30 modes unless changed) at 100 m/min with one ALE rim load.
fn lathe(
    integrator: IntegratorKind,
    coords: Coordinates,
    kmax: u32,
    lmax: u32,
    rate: f64,
) -> Simulation {
    lathe_with(integrator, coords, kmax, lmax, rate, |_| {})
}

fn lathe_with(
    integrator: IntegratorKind,
    coords: Coordinates,
    kmax: u32,
    lmax: u32,
    rate: f64,
    extra: impl Fn(&mut Config),
) -> Simulation {
    let mut c = Config::default();
    c.plate.nodal_diameters = (0..=kmax).collect();
    c.plate.nodal_circles = (0..=lmax).collect();
    c.plate.damping = vec![0.02];
    c.joint.speed = 100.0 / 60.0 / 0.15;
    c.nodes.ale.push(NodePosition {
        radial: 1.0,
        angular: 0.0,
    });
    c.loads.ale.push(WrenchConfig {
        force: [0.0, 50.0, -300.0],
        moment: [0.0; 3],
    });
    c.simulation.integrator = integrator;
    c.simulation.coordinates = coords;
    c.simulation.rate_hz = rate;
    extra(&mut c);
    Simulation::new(c).unwrap()
}

fn steps(c: &mut Criterion) {
    for (integrator, coords) in [
        (IntegratorKind::Exponential, Coordinates::Ale),
        (IntegratorKind::Exponential, Coordinates::Lagrangian),
        (IntegratorKind::ImplicitMidpoint, Coordinates::Ale),
        (IntegratorKind::ImplicitMidpoint, Coordinates::Lagrangian),
    ] {
        for (kmax, lmax) in [(7, 1), (2, 0), (20, 3)] {
            let mut sim = lathe(integrator, coords, kmax, lmax, 10_000.0);
            let n = sim.model().n_modes();
            c.bench_function(
                &format!("step/{}/{:?}/{n}_modes", integrator.name(), coords).to_lowercase(),
                |b| b.iter(|| sim.step().unwrap()),
            );
        }
    }
    // RK4 sub-steps itself: at 10 kHz the 18.8 kHz mode needs ~59 substeps.
    let mut sim = lathe(IntegratorKind::Rk4, Coordinates::Ale, 7, 1, 10_000.0);
    c.bench_function("step/rk4/ale/30_modes", |b| b.iter(|| sim.step().unwrap()));

    // What each effect costs (exponential, ALE, 30 modes, one ALE load).
    type Effect = (&'static str, fn(&mut Config));
    let effects: [Effect; 4] = [
        ("fixed_base", |_| {}),
        ("gravity", |c| c.gravity = [0.0, 0.0, -9.81]),
        ("off_axis_rotation", |c| {
            c.reference.angular_velocity = [2.0, 1.0, 0.0]
        }),
        ("follower_loads", |c| c.loads.follower = true),
    ];
    for (name, apply) in effects {
        let mut sim = lathe_with(
            IntegratorKind::Exponential,
            Coordinates::Ale,
            7,
            1,
            10_000.0,
            apply,
        );
        c.bench_function(&format!("effects/{name}"), |b| {
            b.iter(|| sim.step().unwrap())
        });
    }

    // Centrifugal stiffening: at constant speed the per-k block
    // propagators are cached; in a spin-up (a slow ramp at 1 rad/s², so the
    // speed changes every substep for the whole run) they are rebuilt every substep.
    let stiff = |c: &mut Config| c.centrifugal.stiffening = true;
    let mut sim = lathe_with(
        IntegratorKind::Exponential,
        Coordinates::Ale,
        7,
        1,
        10_000.0,
        stiff,
    );
    c.bench_function("effects/centrifugal_stiffening", |b| {
        b.iter(|| sim.step().unwrap())
    });
    for (name, stiffening) in [
        ("effects/spin_up", false),
        ("effects/spin_up_centrifugal_stiffening", true),
    ] {
        let mut sim = lathe_with(
            IntegratorKind::Exponential,
            Coordinates::Ale,
            7,
            1,
            10_000.0,
            |c| {
                c.centrifugal.stiffening = stiffening;
                c.joint.max_acceleration = 1.0;
            },
        );
        sim.set_speed_command(5000.0).unwrap();
        c.bench_function(name, |b| b.iter(|| sim.step().unwrap()));
    }

    in_plane_modes(c);

    let mut group = c.benchmark_group("scenario");
    group.sample_size(10);
    group.bench_function("lathe_30_modes_5.5s_at_10kHz_exponential", |b| {
        b.iter(|| {
            let mut sim = lathe(
                IntegratorKind::Exponential,
                Coordinates::Ale,
                7,
                1,
                10_000.0,
            );
            for _ in 0..55_000 {
                sim.step().unwrap();
            }
            sim.q_ale()[0]
        })
    });
    group.finish();
}

/// The step cost of in-plane modes against bending modes: the lathe disc
/// (30 bending modes, one ALE rim load, exponential, 10 kHz) with 16
/// in-plane modes added (k = 0..3, l = 0, 1: the torsional and radial
/// families and three pairs, their spin terms at the lathe's speed), against
/// the same disc with 15 bending modes added (l = 2 for k = 0..7). The cost
/// per added mode is the difference to the base over the modes added.
fn in_plane_modes(c: &mut Criterion) {
    let cases: [(&str, u32, &[u32]); 3] = [
        ("in_plane/base_30_bending", 1, &[]),
        ("in_plane/plus_16_in_plane", 1, &[0, 1, 2, 3]),
        ("in_plane/plus_15_bending", 2, &[]),
    ];
    for (name, lmax, in_plane) in cases {
        let mut sim = lathe_with(
            IntegratorKind::Exponential,
            Coordinates::Ale,
            7,
            lmax,
            10_000.0,
            |c| {
                c.plate.in_plane_nodal_diameters = in_plane.to_vec();
                c.plate.in_plane_orders = vec![0, 1];
            },
        );
        c.bench_function(name, |b| b.iter(|| sim.step().unwrap()));
    }
}

/// The shipped scene `config/<file>` with `integrator` (None: as shipped),
/// pads removed with `bare` (the same plate).
fn scene(file: &str, integrator: Option<IntegratorKind>, bare: bool) -> Simulation {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("config")
        .join(file);
    let mut c = Config::from_params_file(&path, "annular_plate").unwrap();
    if let Some(i) = integrator {
        c.simulation.integrator = i;
    }
    if bare {
        c.load_models.remove("pads");
    }
    Simulation::new(c).unwrap()
}

/// Every shipped scene per output step: as shipped; with RK4 at its default
/// step limit; the same plate with its pads removed on the exponential
/// integrator (the brake scenes' floor). The
/// brake bench also clamped at 8 kN (its working state).
fn scenes(c: &mut Criterion) {
    let files = [
        "brake_bench.yaml",
        "brake_in_plane.yaml",
        "brake_squeal.yaml",
        "brake_squeal_paper.yaml",
        "lathe.yaml",
        "swash_plate.yaml",
    ];
    for file in files {
        let name = file.trim_end_matches(".yaml");
        let mut sim = scene(file, None, false);
        for _ in 0..50 {
            sim.step().unwrap();
        }
        c.bench_function(&format!("scene/{name}/shipped"), |b| {
            b.iter(|| sim.step().unwrap())
        });
        if sim.pad_count() == 0 {
            continue;
        }
        let mut rk4 = scene(file, Some(IntegratorKind::Rk4), false);
        c.bench_function(&format!("scene/{name}/rk4"), |b| {
            b.iter(|| rk4.step().unwrap())
        });
        let mut bare = scene(file, Some(IntegratorKind::Exponential), true);
        c.bench_function(&format!("scene/{name}/pads_removed_exponential"), |b| {
            b.iter(|| bare.step().unwrap())
        });
    }
    let mut clamped = scene("brake_bench.yaml", None, false);
    clamped.set_pad_clamp_force(0, 8000.0).unwrap();
    for _ in 0..50 {
        clamped.step().unwrap();
    }
    c.bench_function("scene/brake_bench/clamped_8kN", |b| {
        b.iter(|| clamped.step().unwrap())
    });
}

criterion_group!(benches, steps, scenes);
criterion_main!(benches);
