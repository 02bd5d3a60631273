//! The brake scenes on `contact_exponential` against the same equations
//! converged: RK4 at `simulation.rk4_step_limit` 0.0125 (16× below its
//! default 0.2; 0.0125 and 0.00625 agree to 3e-8 of the peak on the bench's
//! script). Independent of the integrator under test: RK4 resolves every
//! contact explicitly and evaluates the pads at every stage.

mod support;

use annular_plate::config::{Config, IntegratorKind};
use annular_plate::dynamics::load_models::pad_outputs::PadOutputs;
use annular_plate::dynamics::Simulation;
use support::scene_files as scenes;

/// The reference's RK4 step limit.
const REFERENCE_LIMIT: &str = "0.0125";

/// `config/<file>` with `edits` (from, to) applied and the integrator set.
fn scene(file: &str, integrator: &str, edits: &[(&str, &str)]) -> Config {
    let mut text = scenes::text(file);
    for (from, to) in edits {
        assert!(text.contains(from), "config/{file} has no `{from}`");
        text = text.replacen(from, to, 1);
    }
    let line = text
        .lines()
        .find(|l| l.trim_start().starts_with("integrator:"))
        .expect("the scene names its integrator")
        .to_string();
    let mut with = format!("      integrator: {integrator}");
    let text = match text
        .lines()
        .find(|l| l.trim_start().starts_with("rk4_step_limit:"))
    {
        Some(limit) if integrator == "rk4" => {
            let limit = limit.to_string();
            text.replacen(
                &limit,
                &format!("      rk4_step_limit: {REFERENCE_LIMIT}"),
                1,
            )
        }
        _ => {
            if integrator == "rk4" {
                with += &format!("\n      rk4_step_limit: {REFERENCE_LIMIT}");
            }
            text
        }
    };
    let text = text.replacen(&line, &with, 1);
    Config::from_yaml_str(&text, scenes::NODE).unwrap()
}

/// Per step: the ALE amplitudes, Ω, and every contact's normal forces.
fn run(config: Config, steps: usize, clamp: &dyn Fn(usize) -> f64) -> Vec<Vec<f64>> {
    run_sim(Simulation::new(config).unwrap(), steps, clamp)
}

/// [`run`] on a simulation already made.
fn run_sim(mut sim: Simulation, steps: usize, clamp: &dyn Fn(usize) -> f64) -> Vec<Vec<f64>> {
    (0..steps)
        .map(|s| {
            for p in 0..sim.pad_count() {
                sim.set_pad_clamp_force(p, clamp(s)).unwrap();
            }
            sim.step().unwrap();
            let mut row = sim.q_ale().to_vec();
            row.push(sim.joint().velocity);
            for f in sim.pad_contact_forces() {
                row.extend([f.top, f.bottom]);
            }
            row
        })
        .collect()
}

/// Per column, the largest difference over the run relative to the
/// reference's peak |value| (columns whose peak is 0 compared absolutely).
fn worst_relative(reference: &[Vec<f64>], other: &[Vec<f64>]) -> Vec<f64> {
    (0..reference[0].len())
        .map(|i| {
            let peak = reference.iter().map(|r| r[i].abs()).fold(0.0, f64::max);
            let diff = reference
                .iter()
                .zip(other)
                .map(|(a, b)| (a[i] - b[i]).abs())
                .fold(0.0, f64::max);
            if peak > 0.0 {
                diff / peak
            } else {
                diff
            }
        })
        .collect()
}

/// [`worst_relative`] of `contact_exponential` against the reference on
/// `config/<file>` with `edits`, over `steps` under the clamp script.
fn against_the_reference(
    file: &str,
    edits: &[(&str, &str)],
    steps: usize,
    clamp: &dyn Fn(usize) -> f64,
) -> Vec<f64> {
    let reference = run(scene(file, "rk4", edits), steps, clamp);
    let contact = run(scene(file, "contact_exponential", edits), steps, clamp);
    worst_relative(&reference, &contact)
}

/// The bench's disc vibrating (1e-5 m on every mode), the clamp force
/// ramped to 8 kN (lift-off while it is small), held, released to zero.
const BENCH_INITIAL: (&str, &str) = (
    "    joint:\n",
    "    initial:\n      q: [1.0e-5, 1.0e-5, 0.0, 1.0e-5, 0.0, 1.0e-5, 0.0, 1.0e-5, 0.0]\n    joint:\n",
);

fn bench_script(step: usize) -> f64 {
    match step {
        0..50 => 160.0 * step as f64,
        50..150 => 8000.0,
        _ => 0.0,
    }
}

#[test]
fn brake_bench_ramp_hold_release_within_1e6_of_the_converged_reference() {
    let steps = 200;
    let reference = run(
        scene("brake_bench.yaml", "rk4", &[BENCH_INITIAL]),
        steps,
        &bench_script,
    );
    let contact = run(
        scene("brake_bench.yaml", "contact_exponential", &[BENCH_INITIAL]),
        steps,
        &bench_script,
    );
    let shipped_rk4 = {
        let mut c = scene("brake_bench.yaml", "rk4", &[BENCH_INITIAL]);
        c.simulation.rk4_step_limit = 0.2;
        run(c, steps, &bench_script)
    };
    let errors = worst_relative(&reference, &contact);
    let before = worst_relative(&reference, &shipped_rk4);
    let worst = errors.iter().copied().fold(0.0, f64::max);
    println!(
        "worst over amplitudes, speed and contact forces: contact_exponential {worst:.2e}, rk4 at 0.2 {:.2e}",
        before.iter().copied().fold(0.0, f64::max)
    );
    assert!(worst < 1e-6, "{errors:?}");
}

/// The speed dip under `config/brake_bench.yaml` with `edits` at step rate
/// `rate`: `clamp(ms)` per step over 60 ms, and with `command` that speed
/// commanded. Returns the reference's dip (rad/s) and [`worst_relative`] of
/// `contact_exponential`.
fn speed_dip_at(
    rate: f64,
    edits: &[(&str, &str)],
    clamp: &dyn Fn(f64) -> f64,
    command: Option<f64>,
) -> (f64, Vec<f64>) {
    let per_ms = (rate / 1000.0) as usize;
    let steps = 60 * per_ms;
    let script = |s: usize| clamp((s / per_ms) as f64);
    let rate_line = format!("rate_hz: {rate:.1}");
    let mut all = vec![BENCH_INITIAL, ("rate_hz: 1000.0", rate_line.as_str())];
    all.extend_from_slice(edits);
    let run_with = |integrator: &str| {
        let mut sim = Simulation::new(scene("brake_bench.yaml", integrator, &all)).unwrap();
        if let Some(c) = command {
            sim.set_speed_command(c).unwrap();
        }
        run_sim(sim, steps, &script)
    };
    let reference = run_with("rk4");
    let contact = run_with("contact_exponential");
    let lowest = reference.iter().map(|r| r[9]).fold(f64::MAX, f64::min);
    (
        reference[0][9] - lowest,
        worst_relative(&reference, &contact),
    )
}

fn worst(errors: &[f64]) -> f64 {
    errors.iter().copied().fold(0.0, f64::max)
}

/// Braked just above the drive's limit (16 kN: 2μN r = 1.53 kN·m against
/// 1.5 kN·m), the speed dips by 0.28 rad/s a step. The step is taken in the
/// frame turning at the step's mean speed (the reference turns Ω within the
/// step): an O(h²) difference in the step, so halving the step quarters it.
/// On the shipped Mindlin disc 8.38e-5 → 2.14e-5 of the peak (holding the
/// ALE equations' Ω̄ and Ω̇ instead: 1.18e-4 → 5.00e-5), on the Kirchhoff
/// disc 1.17e-4 → 2.53e-5. (At 4 kHz 9.3e-6 and 1.67e-5: the pads' friction,
/// evaluated at Ω̄, leaves a floor of about 1e-5; docs/dynamics.md.)
#[test]
fn brake_bench_speed_dip_converges_at_second_order_to_the_converged_reference() {
    let clamp = |ms: f64| 1600.0 * ms.min(10.0);
    for theory in [vec![], vec![("theory: mindlin", "theory: kirchhoff")]] {
        let (dip, coarse) = speed_dip_at(1000.0, &theory, &clamp, None);
        let (_, fine) = speed_dip_at(2000.0, &theory, &clamp, None);
        println!(
            "{theory:?}: speed dip {dip:.3} rad/s; worst difference at 1 kHz {:.2e}, at 2 kHz {:.2e}",
            worst(&coarse),
            worst(&fine)
        );
        assert!(dip > 5.0, "the script must slow the disc: {dip}");
        assert!(worst(&fine) < 0.3 * worst(&coarse), "{coarse:?} {fine:?}");
    }
}

/// A commanded speed ramp (25 → 5 rad/s at 500 rad/s²) under frictionless
/// pads clamped at 16 kN: nothing in the pads depends on Ω, so what the step
/// holds is the joint's motion alone. Taken in the frame turning at Ω̄ the
/// difference falls at second order over 1, 2 and 4 kHz (measured 5.03e-4,
/// 1.02e-4, 2.90e-5 of the peak; the ALE equations held at Ω̄ and Ω̇:
/// 9.40e-4, 1.99e-4, 1.36e-4).
#[test]
fn commanded_speed_ramp_converges_at_second_order_to_the_converged_reference() {
    let edits = [
        ("friction_coefficient: 0.4", "friction_coefficient: 0.0"),
        ("max_acceleration: 50.0", "max_acceleration: 500.0"),
    ];
    let errors: Vec<f64> = [1000.0, 2000.0, 4000.0]
        .iter()
        .map(|&rate| {
            let (dip, e) = speed_dip_at(rate, &edits, &|_| 16_000.0, Some(5.0));
            assert!(dip > 19.0, "the command must slow the disc: {dip}");
            worst(&e)
        })
        .collect();
    let shown: Vec<String> = errors.iter().map(|e| format!("{e:.2e}")).collect();
    println!("worst difference at 1, 2, 4 kHz: {}", shown.join(", "));
    for pair in errors.windows(2) {
        assert!(pair[1] < 0.3 * pair[0], "{errors:?}");
    }
}

/// The paper's squeal scene without lift-off: every step one affine piece
/// (mid-plane friction, follower terms linear at constant normal force).
#[test]
fn paper_squeal_without_lift_off_within_1e6_of_the_converged_reference() {
    let edits = [("lift_off: true", "lift_off: false")];
    let errors = against_the_reference("brake_squeal_paper.yaml", &edits, 150, &|_| 30_000.0);
    let worst = errors.iter().copied().fold(0.0, f64::max);
    println!("worst: {worst:.2e}");
    assert!(worst < 1e-6, "{errors:?}");
}

/// The paper's squeal scene as shipped: lift-off at the limit cycle, a
/// dozen switches a step located inside it. Measured 2.7e-5 of the peak
/// after 0.1 s (brief contacts shorter than the sampling are not seen, and
/// the limit cycle amplifies what is missed); RK4 at 0.1 was 4.1e-4 off.
#[test]
fn paper_squeal_limit_cycle_closer_to_the_converged_reference_than_rk4() {
    let steps = 100;
    let shipped = |_: usize| 30_000.0;
    let reference = run(
        scene("brake_squeal_paper.yaml", "rk4", &[]),
        steps,
        &shipped,
    );
    let contact = run(
        scene("brake_squeal_paper.yaml", "contact_exponential", &[]),
        steps,
        &shipped,
    );
    let rk4 = {
        let mut c = scene("brake_squeal_paper.yaml", "rk4", &[]);
        c.simulation.rk4_step_limit = 0.1;
        run(c, steps, &shipped)
    };
    let modes = 4;
    let worst = |e: Vec<f64>| e[..modes].iter().copied().fold(0.0, f64::max);
    let (c, r) = (
        worst(worst_relative(&reference, &contact)),
        worst(worst_relative(&reference, &rk4)),
    );
    println!("amplitudes: contact_exponential {c:.2e}, rk4 at 0.1 {r:.2e}");
    assert!(c < 4e-5 && c < r, "{c} vs {r}");
}

/// brake_squeal's rigid lining (the shear keys commented out) on
/// `contact_exponential` at `contact_tolerance` `tolerance`.
fn rigid_lining(tolerance: &'static str) -> [(&'static str, &'static str); 3] {
    [
        ("      shear_stiffness:", "      # shear_stiffness:"),
        ("      shear_damping:", "      # shear_damping:"),
        ("    simulation:\n", tolerance),
    ]
}

/// brake_squeal with a rigid lining: friction on the faces at 0.36 m/s
/// sliding speed, whose direction is strongly nonlinear in the vibration.
/// Its spans are taken at third order at `contact_tolerance` 1e-6:
/// measured 7.0e-6 of the peak over 0.3 s of its growth (the
/// second-order correction alone: 1.72e-4).
#[test]
fn brake_squeal_face_friction_within_3e5_of_the_converged_reference() {
    let edits = rigid_lining("    simulation:\n      contact_tolerance: 1.0e-6\n");
    let errors = against_the_reference("brake_squeal.yaml", &edits, 3000, &|_| 5000.0);
    let worst = errors.iter().copied().fold(0.0, f64::max);
    println!("worst over amplitudes, speed and contact forces: {worst:.2e}");
    assert!(worst < 3.0e-5, "{errors:?}");
}

/// The rigid lining at `contact_tolerance` 1e-7: within 1e-6 of the peak
/// (measured 3.5e-7 over 0.3 s).
#[test]
fn brake_squeal_at_tolerance_1e7_within_1e6_of_the_converged_reference() {
    let edits = rigid_lining("    simulation:\n      contact_tolerance: 1.0e-7\n");
    let errors = against_the_reference("brake_squeal.yaml", &edits, 3000, &|_| 5000.0);
    let worst = errors.iter().copied().fold(0.0, f64::max);
    println!("worst over amplitudes, speed and contact forces: {worst:.2e}");
    assert!(worst < 1.0e-6, "{errors:?}");
}

/// brake_squeal as shipped, with the lining's patches, on its integrator
/// (RK4 at the scene's `simulation.rk4_step_limit` 0.0425 on its modes,
/// 61 inner steps of 1.64 µs; the patches' relaxation k_t/c_t ≈ 1e5 1/s
/// only keeps h k_t/c_t ≤ 1) over 0.3 s of its growth, against RK4 at a
/// step limit 16× below the scene's: measured 1.78e-4 of the peak;
/// `contact_exponential` at its default `contact_tolerance` 1e-9 measured
/// 9.6e-4 in 386 s (docs/performance.md), which is why the scene ships RK4.
#[test]
fn brake_squeal_with_lining_shear_on_rk4_within_3e4_of_the_converged_reference() {
    let shipped = scenes::load("brake_squeal.yaml");
    assert_eq!(shipped.simulation.integrator, IntegratorKind::Rk4);
    let mut reference = scene("brake_squeal.yaml", "rk4", &[]);
    reference.simulation.rk4_step_limit = shipped.simulation.rk4_step_limit / 16.0;
    let reference = run(reference, 3000, &|_| 5000.0);
    let errors = worst_relative(&reference, &run(shipped, 3000, &|_| 5000.0));
    let worst = errors.iter().copied().fold(0.0, f64::max);
    println!("worst over amplitudes, speed and contact forces: {worst:.2e}");
    assert!(worst < 3.0e-4, "{errors:?}");
}

/// Hard cases on the bench: contacts up to 1e12 N/m (rates RK4 would need
/// millions of substeps for), clamp forces near zero (lift-off chatter) and
/// the rigid-clamp limit: no NaN, and the vibration of the disc stays of the
/// order it started at (friction on the faces can feed it; here it takes
/// out as much as it puts in to within a few per cent over 0.3 s).
#[test]
fn stiff_and_chattering_contacts_stay_bounded() {
    for (stiffness, clamp) in [
        ("2.0e9", 8000.0),
        ("1.0e12", 8000.0),
        ("2.0e7", 1.0),
        ("1.0e12", 0.5),
    ] {
        let edits = [
            BENCH_INITIAL,
            (
                "contact_stiffness: 2.0e7",
                &*format!("contact_stiffness: {stiffness}"),
            ),
            (
                "lift_off: true",
                "lift_off: true\n      follower_friction: false",
            ),
        ];
        let mut sim =
            Simulation::new(scene("brake_bench.yaml", "contact_exponential", &edits)).unwrap();
        let peak0 = sim.q_ale().iter().fold(0.0f64, |m, v| m.max(v.abs()));
        let mut switches = 0;
        let mut peak = 0.0f64;
        for _ in 0..300 {
            sim.set_pad_clamp_force(0, clamp).unwrap();
            sim.step().unwrap();
            switches += sim.contact_report().switches;
            assert!(sim.q_ale().iter().all(|q| q.is_finite()));
            peak = sim.q_ale().iter().fold(peak, |m, v| m.max(v.abs()));
        }
        println!("k_c {stiffness}, clamp {clamp} N: {switches} switches located, peak {peak:.3e} (start {peak0:.3e})");
        assert!(peak <= 1.5 * peak0, "grew: {peak} from {peak0}");
    }
}

/// Its tables grow with the square of the unknowns: beyond its limit the
/// integrator is refused before any work, naming the keys that set the size.
#[test]
fn contact_exponential_refuses_more_unknowns_than_it_tabulates_naming_the_keys() {
    let diameters: Vec<String> = (0..=43).map(|k| k.to_string()).collect();
    let many = format!("nodal_diameters: [{}]", diameters.join(", "));
    let config = scene(
        "brake_bench.yaml",
        "contact_exponential",
        &[
            ("nodal_diameters: [0, 1, 2, 3, 4]", many.as_str()),
            ("nodal_circles: [0]", "nodal_circles: [0, 1]"),
        ],
    );
    let Err(e) = Simulation::new(config) else {
        panic!("174 modes on contact_exponential were accepted")
    };
    let text = e.to_string();
    println!("{text}");
    for part in [
        "174 modes give 348 unknowns",
        "limit of 256",
        "plate.nodal_diameters",
        "plate.nodal_circles",
        "simulation.integrator",
    ] {
        assert!(text.contains(part), "{text}");
    }
    // Within the limit the same scene runs (63 modes: 126 unknowns).
    let within = format!("nodal_diameters: [{}]", diameters[..32].join(", "));
    let config = scene(
        "brake_bench.yaml",
        "contact_exponential",
        &[
            ("nodal_diameters: [0, 1, 2, 3, 4]", within.as_str()),
            ("clamp_force: [0.0]", "clamp_force: [8000.0]"),
        ],
    );
    let mut sim = Simulation::new(config).unwrap();
    for _ in 0..5 {
        sim.step().unwrap();
    }
    assert!(sim.q_ale().iter().all(|q| q.is_finite()));
}
