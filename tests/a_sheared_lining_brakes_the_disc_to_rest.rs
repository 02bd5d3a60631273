//! The joint's near-stop path with the lining's patches (`pads.shear_*`;
//! docs/scenes.md, "A disc braked to standstill"): with patches the friction
//! reaches the joint only through the patches' forces, yet the brake bench
//! clamped above its drive's limit decelerates at the closed form
//! (2μN₀r − τ_max)/J, J = ½πρh(b⁴ − a⁴) of the annulus, and comes to rest
//! at the time it gives. At rest the joint speed, integrated with the
//! patches inside the step (RK4's stages; in `contact_exponential`'s state),
//! settles at the closed-form creep Ω = atanh(τ_max / Σ μ N r) · v_reg / r,
//! as RK4 in eight substeps a step does.

mod support;

use annular_plate::config::IntegratorKind;
use annular_plate::dynamics::load_models::pad::FRICTION_REGULARISATION_SPEED;
use annular_plate::dynamics::load_models::pad_config::PadsConfig;
use annular_plate::dynamics::load_models::pad_outputs::PadOutputs;
use annular_plate::dynamics::Simulation;
use std::f64::consts::PI;
use support::scene_files as scenes;

const CLAMP: f64 = 16_000.0;

/// The bench at 25 rad/s with patches (k_t = 1e6 N/m, c_t = 100 N·s/m),
/// clamped at 16 kN after 0.1 s, for `steps` more steps: per step
/// (time, Ω); the closed-form deceleration, J and creep.
struct Braked {
    times: Vec<f64>,
    speeds: Vec<f64>,
    deceleration: f64,
    inertia: f64,
    /// Ω = atanh(τ_max / Σ μ N r) · v_reg / r.
    creep: f64,
}

/// [`Braked`] on `integrator`, each 1 ms step in `substeps` substeps.
fn braked_in(steps: usize, substeps: u32, integrator: IntegratorKind) -> Braked {
    let mut c = scenes::load("brake_bench.yaml");
    c.section_mut::<PadsConfig>().unwrap().shear = Some((1.0e6, 100.0));
    c.simulation.integrator = integrator;
    c.simulation.substeps = substeps;
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
        creep: (torque / capacity).atanh() * FRICTION_REGULARISATION_SPEED / radius,
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
    for integrator in [IntegratorKind::Rk4, IntegratorKind::ContactExponential] {
        decelerates_and_stops(&braked_in(200, 1, integrator));
    }
}

fn decelerates_and_stops(b: &Braked) {
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

#[test]
fn braked_to_rest_the_disc_settles_at_the_closed_form_creep_without_a_saw() {
    // The converged reference: RK4 in eight substeps a step.
    let reference = braked_in(500, 8, IntegratorKind::Rk4);
    let largest = |v: &mut dyn Iterator<Item = f64>| v.fold(0.0f64, |m, x| m.max(x.abs()));
    let jump = |s: &[f64]| largest(&mut s.windows(2).map(|w| w[1] - w[0]));
    assert!(
        (reference.creep - 1.88e-2).abs() < 1e-4,
        "{}",
        reference.creep
    );
    for integrator in [IntegratorKind::Rk4, IntegratorKind::ContactExponential] {
        let b = braked_in(500, 1, integrator);
        let name = integrator.name();
        let rest = b.speeds.iter().position(|&w| w < 0.05).unwrap();
        // The 1 ms step over the whole time at rest: the joint and the
        // patches meet inside the step, so the disc's ringing on the patches
        // is the converged one and no step saws.
        let off = largest(
            &mut b.speeds[rest..]
                .iter()
                .zip(&reference.speeds[rest..])
                .map(|(a, r)| a - r),
        );
        let (steps, converged) = (jump(&b.speeds[rest..]), jump(&reference.speeds[rest..]));
        println!(
            "{name} at rest: |Ω − Ω_ref| ≤ {off:.2e} rad/s; largest |ΔΩ| a step {steps:.5} rad/s, reference {converged:.5}"
        );
        assert!(off < 1e-4, "{name}: {off}");
        assert!(
            (steps - converged).abs() < 1e-4,
            "{name}: {steps} vs {converged}"
        );
        // The last 50 ms (0.55–0.6 s after the clamp): settled at the creep.
        let tail = &b.speeds[b.speeds.len() - 50..];
        let from_creep = largest(&mut tail.iter().map(|w| w / b.creep - 1.0));
        println!(
            "{name}: creep {:.6e} rad/s (closed form); last 50 ms within {from_creep:.1e} of it, |ΔΩ| ≤ {:.1e} rad/s a step",
            b.creep,
            jump(tail)
        );
        assert!(from_creep < 1e-4, "{name}: {from_creep}");
        assert!(jump(tail) < 1e-5, "{name}: {}", jump(tail));
    }
}
