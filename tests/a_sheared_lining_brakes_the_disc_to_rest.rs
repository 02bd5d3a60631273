//! The joint's near-stop path with the lining's patches (`pads.shear_*`;
//! docs/scenes.md, "A disc braked to standstill"): with patches the friction
//! reaches the joint only through the patches' forces, yet the brake bench
//! clamped above its drive's limit decelerates at the closed form
//! (2μN₀r − τ_max)/J, J = ½πρh(b⁴ − a⁴) of the annulus, and comes to rest
//! at the time it gives. What happens at rest is docs/scenes.md's limit
//! (the joint's explicit update against stiff patches), not a result.

mod support;

use annular_plate::config::IntegratorKind;
use annular_plate::dynamics::load_models::pad_config::PadsConfig;
use annular_plate::dynamics::load_models::pad_outputs::PadOutputs;
use annular_plate::dynamics::Simulation;
use std::f64::consts::PI;
use support::scene_files as scenes;

const CLAMP: f64 = 16_000.0;

/// The bench at 25 rad/s with patches (k_t = 1e6 N/m, c_t = 100 N·s/m) on
/// RK4, clamped at 16 kN after 0.1 s, for `steps` more steps: per step
/// (time, Ω); the closed-form deceleration and J.
struct Braked {
    times: Vec<f64>,
    speeds: Vec<f64>,
    deceleration: f64,
    inertia: f64,
}

fn braked(steps: usize) -> Braked {
    let mut c = scenes::load("brake_bench.yaml");
    c.section_mut::<PadsConfig>().unwrap().shear = Some((1.0e6, 100.0));
    c.simulation.integrator = IntegratorKind::Rk4;
    let p = &c.plate;
    let inertia =
        0.5 * PI * p.density * p.thickness * (p.outer_radius.powi(4) - p.inner_radius.powi(4));
    let mu = c.section::<PadsConfig>().unwrap().friction_coefficient;
    let torque = c.joint.max_torque.unwrap();
    let mut sim = Simulation::new(c).unwrap();
    let radius = sim.scene().ale_nodes[0].radius;
    assert!(sim
        .scene()
        .ale_nodes
        .iter()
        .all(|n| (n.radius - radius).abs() < 1e-12));
    for _ in 0..100 {
        sim.step().unwrap();
    }
    sim.set_pad_clamp_force(0, CLAMP).unwrap();
    let capacity = 2.0 * mu * CLAMP * radius;
    let (mut speeds, mut times) = (vec![sim.joint().velocity], vec![sim.time()]);
    for _ in 0..steps {
        sim.step().unwrap();
        speeds.push(sim.joint().velocity);
        times.push(sim.time());
        assert!(sim.q_ale().iter().all(|q| q.is_finite()));
        assert!(sim
            .pad_patch_deflections()
            .iter()
            .all(|x| x.iter().all(|v| v.is_finite())));
    }
    Braked {
        times,
        speeds,
        deceleration: (capacity - torque) / inertia,
        inertia,
    }
}

impl Braked {
    /// When Ω first falls below `w`, interpolated between steps.
    fn crossing(&self, w: f64) -> f64 {
        let k = self
            .speeds
            .iter()
            .position(|&s| s < w)
            .unwrap_or_else(|| panic!("slows below {w}"));
        let f = (self.speeds[k - 1] - w) / (self.speeds[k - 1] - self.speeds[k]);
        self.times[k - 1] + f * (self.times[k] - self.times[k - 1])
    }
}

#[test]
fn the_bench_with_sheared_pads_decelerates_at_the_closed_form_and_stops_when_it_says() {
    let b = braked(200);
    let measured = 15.0 / (b.crossing(5.0) - b.crossing(20.0));
    println!(
        "J = {:.5} kg·m²: deceleration {measured:.3} rad/s², closed form {:.3}",
        b.inertia, b.deceleration
    );
    assert!(
        (measured / b.deceleration - 1.0).abs() < 2e-3,
        "{measured} vs {}",
        b.deceleration
    );
    let stop = b.crossing(0.05) - b.times[0];
    let expected = (b.speeds[0] - 0.05) / b.deceleration;
    println!("Ω < 0.05 rad/s after {stop:.5} s, closed form {expected:.5} s");
    assert!((stop - expected).abs() < 2e-3, "{stop} vs {expected}");
    let before = b.speeds.iter().position(|&w| w < 0.05).unwrap();
    assert!(
        b.speeds[..before].windows(2).all(|w| w[1] <= w[0] + 1e-12),
        "not monotone before rest"
    );
}
