//! The load models (pads, tool, pitch links) keep the fixed-step loop free of
//! allocation, their commands included (a counting global allocator watches).

use annular_plate::config::{Config, Coordinates, IntegratorKind};
use annular_plate::dynamics::load_models::pad_config::PadsConfig;
use annular_plate::dynamics::load_models::pad_outputs::PadOutputs;
use annular_plate::dynamics::load_models::pitch_link::LinkOutputs;
use annular_plate::dynamics::load_models::tool::ToolOutputs;
use annular_plate::dynamics::Simulation;
use std::alloc::{GlobalAlloc, Layout, System};
use std::cell::Cell;
use std::path::Path;
use std::sync::atomic::{AtomicUsize, Ordering};

struct Counting;
static ALLOCATIONS: AtomicUsize = AtomicUsize::new(0);

thread_local! {
    /// Count only on the test's own thread: the test harness's threads allocate
    /// at times of their own.
    static WATCHED: Cell<bool> = const { Cell::new(false) };
}

fn count() {
    if WATCHED.with(Cell::get) {
        ALLOCATIONS.fetch_add(1, Ordering::SeqCst);
    }
}

unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        count();
        unsafe { System.alloc(layout) }
    }
    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        unsafe { System.dealloc(ptr, layout) }
    }
    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        count();
        unsafe { System.realloc(ptr, layout, new_size) }
    }
}

#[global_allocator]
static GLOBAL: Counting = Counting;

fn scene(name: &str) -> Config {
    Config::from_params_file(
        &Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("config")
            .join(name),
        "annular_plate",
    )
    .unwrap()
}

#[test]
fn stepping_the_scenes_with_changing_commands_allocates_nothing() {
    WATCHED.with(|w| w.set(true));
    // The squeal scene also with friction on the faces and μ(v) (below its threshold).
    for (name, faces) in [
        ("brake_squeal_paper.yaml", false),
        ("brake_squeal.yaml", true),
        ("lathe.yaml", false),
        ("swash_plate.yaml", false),
    ] {
        for integrator in [
            IntegratorKind::Rk4,
            IntegratorKind::Exponential,
            IntegratorKind::ImplicitMidpoint,
        ] {
            let mut c = scene(name);
            if faces {
                let pads = c.section_mut::<PadsConfig>().unwrap();
                pads.contact_surface =
                    annular_plate::dynamics::load_models::pad_config::ContactSurface::Faces;
                pads.friction_coefficient = 0.002;
                pads.static_friction_coefficient = Some(0.004);
            }
            if c.section::<PadsConfig>().is_some() && integrator != IntegratorKind::Rk4 {
                continue; // refused: the pads need RK4 at this rate (Simulation::new says so)
            }
            c.simulation.integrator = integrator;
            for coords in [Coordinates::Ale, Coordinates::Lagrangian] {
                c.simulation.coordinates = coords;
                let mut sim = Simulation::new(c.clone()).unwrap();
                sim.step().unwrap(); // warm-up: propagator caches, the backup state's buffers
                let before = ALLOCATIONS.load(Ordering::SeqCst);
                for s in 0..300 {
                    if sim.pad_count() > 0 {
                        sim.set_pad_clamp_force(0, 30_000.0 - s as f64).unwrap();
                    }
                    if sim.has_tool() {
                        sim.set_tool_feed(0.002 + 1e-6 * s as f64).unwrap();
                    }
                    sim.step().unwrap();
                    std::hint::black_box((
                        sim.q_ale()[0],
                        sim.pad_output(0),
                        sim.tool_output(),
                        sim.link_force(0),
                        sim.ale_model_wrench(0),
                    ));
                }
                let after = ALLOCATIONS.load(Ordering::SeqCst);
                assert_eq!(
                    after - before,
                    0,
                    "{name} {integrator:?}/{coords:?} allocated {} times in 300 steps",
                    after - before
                );
                // After a reset the steps reuse the buffers too.
                sim.reset();
                let before = ALLOCATIONS.load(Ordering::SeqCst);
                for _ in 0..10 {
                    sim.step().unwrap();
                }
                assert_eq!(
                    ALLOCATIONS.load(Ordering::SeqCst) - before,
                    0,
                    "{name}: steps after a reset allocated"
                );
            }
        }
    }
}
