//! The fixed-step loop allocates nothing: scratch space is allocated once when
//! the stepper is built (a counting global allocator watches the steps).

use annular_plate::config::{Config, Coordinates, IntegratorKind, NodePosition, WrenchConfig};
use annular_plate::dynamics::load_models::pad_config::{
    Caliper, ContactSurface, PadContact, PadsConfig,
};
use annular_plate::dynamics::{Simulation, Wrench};
use std::alloc::{GlobalAlloc, Layout, System};
use std::cell::Cell;

/// Counts allocations made on this thread only (the test harness's own
/// threads allocate at will).
struct Counting;

thread_local! {
    static ALLOCATIONS: Cell<usize> = const { Cell::new(0) };
}

fn allocations() -> usize {
    ALLOCATIONS.with(|c| c.get())
}

unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        let _ = ALLOCATIONS.try_with(|c| c.set(c.get() + 1));
        unsafe { System.alloc(layout) }
    }
    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        unsafe { System.dealloc(ptr, layout) }
    }
    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        let _ = ALLOCATIONS.try_with(|c| c.set(c.get() + 1));
        unsafe { System.realloc(ptr, layout, new_size) }
    }
}

#[global_allocator]
static GLOBAL: Counting = Counting;

#[test]
fn stepping_with_changing_inputs_allocates_nothing() {
    for (integrator, stiffening) in [
        IntegratorKind::Exponential,
        IntegratorKind::ImplicitMidpoint,
        IntegratorKind::Rk4,
    ]
    .into_iter()
    .flat_map(|i| [(i, false), (i, true)])
    {
        // Without follower loads the node loads of held wrenches are kept and reused while the wrenches stay the same.
        for (coords, follower) in [Coordinates::Ale, Coordinates::Lagrangian]
            .into_iter()
            .flat_map(|c| [(c, true), (c, false)])
        {
            let mut c = Config::default();
            // Centrifugal stiffening: the per-k block propagators are rebuilt every substep of the ramp.
            c.centrifugal.stiffening = stiffening;
            c.plate.damping = vec![0.02];
            c.joint.speed = 20.0;
            c.loads.follower = follower;
            c.gravity = [0.0, 0.0, -9.81];
            c.reference.angular_velocity = [0.5, 0.0, 0.0];
            c.simulation.integrator = integrator;
            c.simulation.coordinates = coords;
            c.simulation.rate_hz = 10_000.0;
            c.simulation.substeps = 2;
            c.nodes.ale.push(NodePosition {
                radial: 1.0,
                angular: 0.0,
            });
            c.nodes.lagrange.push(NodePosition {
                radial: 0.5,
                angular: 0.5,
            });
            c.loads.ale.push(WrenchConfig {
                force: [0.0, 30.0, -100.0],
                moment: [0.0; 3],
            });
            let mut sim = Simulation::new(c).unwrap();
            sim.step().unwrap(); // warm-up: propagator caches
            let before = allocations();
            for s in 0..500 {
                sim.set_ale_wrench(
                    0,
                    Wrench {
                        force: [0.0, 30.0, -100.0 - s as f64],
                        moment: [0.0; 3],
                    },
                )
                .unwrap();
                sim.set_lagrange_wrench(
                    0,
                    Wrench {
                        force: [0.0, 0.0, 5.0],
                        moment: [0.1, 0.0, 0.0],
                    },
                )
                .unwrap();
                sim.set_speed_command(20.0 + 0.01 * s as f64).unwrap();
                sim.step().unwrap();
                std::hint::black_box((sim.q_ale()[0], sim.ale_node(0).uz, sim.joint()));
            }
            let after = allocations();
            assert_eq!(after - before, 0, "{integrator:?}/{coords:?}, stiffening {stiffening}, follower {follower}: allocated {} times in 500 steps", after - before);
        }
    }
}

/// In-plane modes (k = 0, 1, 2) on every integrator, both descriptions, with
/// the torsional modes against a speed-following drive and, on the
/// exponential and RK4, against a torque-limited one (the free k = 0 block's
/// exponential recomputed every step of the spin-up, on scratch sized once;
/// RK4 with the joint in its unknowns).
#[test]
fn stepping_with_in_plane_modes_allocates_nothing() {
    for integrator in [
        IntegratorKind::Exponential,
        IntegratorKind::ImplicitMidpoint,
        IntegratorKind::Rk4,
    ] {
        for coords in [Coordinates::Ale, Coordinates::Lagrangian] {
            for torque_limited in [false, true] {
                if torque_limited && integrator == IntegratorKind::ImplicitMidpoint {
                    continue;
                }
                let mut c = Config::default();
                c.plate.damping = vec![0.02];
                c.plate.in_plane_nodal_diameters = vec![0, 1, 2];
                c.plate.in_plane_orders = vec![0, 1];
                c.joint.max_torque = torque_limited.then_some(5.0);
                // At brake speed where the spin terms are built (their block
                // exponentials recomputed every step of the spin-up below).
                let speed = if integrator == IntegratorKind::ImplicitMidpoint {
                    2.0
                } else {
                    2000.0
                };
                c.joint.speed = speed;
                c.simulation.integrator = integrator;
                c.simulation.coordinates = coords;
                c.simulation.rate_hz = 20_000.0;
                c.nodes.ale.push(NodePosition {
                    radial: 1.0,
                    angular: 0.0,
                });
                c.nodes.lagrange.push(NodePosition {
                    radial: 0.5,
                    angular: 0.5,
                });
                let mut sim = Simulation::new(c).unwrap();
                sim.step().unwrap();
                let before = allocations();
                for s in 0..200 {
                    let wrench = Wrench {
                        force: [10.0, -50.0 - s as f64, -100.0],
                        moment: [0.0; 3],
                    };
                    sim.set_ale_wrench(0, wrench).unwrap();
                    sim.set_lagrange_wrench(0, wrench).unwrap();
                    sim.set_speed_command(speed + 0.01 * s as f64).unwrap();
                    sim.step().unwrap();
                    std::hint::black_box((sim.q_ale()[0], sim.joint()));
                }
                let after = allocations();
                assert_eq!(
                    after - before,
                    0,
                    "{integrator:?}/{coords:?}, torque-limited {torque_limited}: allocated {} times",
                    after - before
                );
            }
        }
    }
}

/// Pads with friction on the faces acting on in-plane modes (k = 0, 1, 2),
/// on every integrator that takes them, both descriptions: the in-plane
/// rate under each contact is summed in place, so stepping allocates nothing.
#[test]
fn stepping_with_pads_on_in_plane_modes_allocates_nothing() {
    for integrator in [
        IntegratorKind::Exponential,
        IntegratorKind::ContactExponential,
        IntegratorKind::Rk4,
    ] {
        for coords in [Coordinates::Ale, Coordinates::Lagrangian] {
            let mut c = Config::default();
            c.plate.damping = vec![0.02];
            c.plate.in_plane_nodal_diameters = vec![0, 1, 2];
            c.plate.in_plane_orders = vec![0];
            c.joint.speed = 10.0;
            c.simulation.integrator = integrator;
            c.simulation.coordinates = coords;
            c.simulation.rate_hz = 100_000.0;
            for angular in [0.0, 0.2] {
                c.nodes.ale.push(NodePosition {
                    radial: 0.6,
                    angular,
                });
            }
            c.set_section(PadsConfig {
                contacts: vec![
                    PadContact { node: 0, pad: 0 },
                    PadContact { node: 1, pad: 0 },
                ],
                clamp_force: vec![1000.0],
                contact_stiffness: 1.0e6,
                contact_damping: 5.0,
                friction_coefficient: 0.4,
                lift_off: true,
                follower_friction: true,
                caliper: Caliper::Floating,
                contact_surface: ContactSurface::Faces,
                static_friction_coefficient: None,
                stribeck_speed: 1.0,
                mass: 0.0,
                backing_stiffness: None,
                shear: None,
            });
            let mut sim = Simulation::new(c).unwrap();
            sim.step().unwrap();
            let before = allocations();
            for _ in 0..200 {
                sim.step().unwrap();
                std::hint::black_box((sim.q_ale()[0], sim.joint()));
            }
            let after = allocations();
            assert_eq!(
                after - before,
                0,
                "{integrator:?}/{coords:?}: allocated {} times in 200 steps",
                after - before
            );
        }
    }
}

/// Massive pads (`pads.mass`), on the modal deflection and in series with the
/// residual flexibility: their states ride in RK4's state vector and the
/// stage slots are scratch, so stepping still allocates nothing.
#[test]
fn stepping_with_massive_pads_allocates_nothing() {
    for (caliper, backing) in [(Caliper::Floating, None), (Caliper::Fixed, Some(3.0e7))] {
        for (coords, residual) in [
            (Coordinates::Ale, false),
            (Coordinates::Lagrangian, false),
            (Coordinates::Ale, true),
            (Coordinates::Lagrangian, true),
        ] {
            let mut c = Config::default();
            c.plate.damping = vec![0.02];
            c.plate.residual_flexibility = residual;
            c.joint.speed = 20.0;
            // With the patches, a torque-limited drive: RK4 carries the joint in its state.
            c.joint.max_torque = (caliper == Caliper::Fixed).then_some(1.0);
            c.simulation.integrator = IntegratorKind::Rk4;
            c.simulation.coordinates = coords;
            c.simulation.rate_hz = 10_000.0;
            c.nodes.ale.push(NodePosition {
                radial: 0.6,
                angular: 0.0,
            });
            c.nodes.ale.push(NodePosition {
                radial: 0.6,
                angular: 0.2,
            });
            c.set_section(PadsConfig {
                contacts: vec![
                    PadContact { node: 0, pad: 0 },
                    PadContact { node: 1, pad: 0 },
                ],
                clamp_force: vec![1000.0],
                contact_stiffness: 2.0e7,
                contact_damping: 50.0,
                friction_coefficient: 0.4,
                lift_off: true,
                follower_friction: true,
                caliper,
                contact_surface: ContactSurface::Faces,
                static_friction_coefficient: None,
                stribeck_speed: 1.0,
                mass: 0.3,
                backing_stiffness: backing,
                // The lining's patches on one of the two (their step allocates nothing either).
                shear: (caliper == Caliper::Fixed).then_some((1.0e6, 20.0)),
            });
            let mut sim = Simulation::new(c).unwrap();
            sim.step().unwrap();
            let before = allocations();
            for _ in 0..200 {
                sim.step().unwrap();
                std::hint::black_box((sim.q_ale()[0], sim.joint()));
            }
            let after = allocations();
            assert_eq!(
                after - before,
                0,
                "{caliper:?}/{coords:?}/in series {residual}: allocated {} times in 200 steps",
                after - before
            );
            assert!(
                sim.state().load_models.slots[0].iter().any(|&v| v != 0.0),
                "the pads' states are in the state"
            );
        }
    }
}

/// config/lathe.yaml on `contact_exponential`: the tool's chip contact within
/// the step (pieces built at the step's own state every step, the swept
/// bins cut at the step's end) allocates nothing once the tool is in the cut.
#[test]
fn stepping_the_lathe_s_cut_on_contact_exponential_allocates_nothing() {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/config/lathe.yaml");
    let mut c = Config::from_params_file(std::path::Path::new(path), "annular_plate").unwrap();
    c.simulation.integrator = IntegratorKind::ContactExponential;
    let mut sim = Simulation::new(c.clone()).unwrap();
    // The tool reaches the face at 0.25 s; step a few milliseconds into the cut.
    for _ in 0..(0.255 * c.simulation.rate_hz) as usize {
        sim.step().unwrap();
    }
    let before = allocations();
    for _ in 0..5 {
        sim.step().unwrap();
    }
    let during = allocations() - before;
    let deflection = sim.q_ale().iter().fold(0.0f64, |m, v| m.max(v.abs()));
    println!("largest amplitude in the cut {deflection:.3e} m; {during} allocations");
    assert!(
        deflection > 1e-7,
        "the tool is not in the cut: {deflection:e}"
    );
    assert_eq!(during, 0, "{during} allocations in 5 steps of the cut");
}
