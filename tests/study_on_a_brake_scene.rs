//! `annular_plate study` on the brake bench clamped at 8 kN (the scene file
//! starts unclamped): its trajectory axis compares `contact_exponential` with
//! the other integrators against an rk4 reference that resolves the contact
//! springs (`simulation.rk4_step_limit` 0.0125).
//!
//! Checked here against the same equations run by rk4 with its inner step 64×
//! below the default (`rk4_step_limit` 0.003125, four times finer than the
//! study's reference): (1) the reference's error against it is within the
//! uncertainty the study reports; (2) every error the study reports is the
//! error against it to within that uncertainty; (3) every recommended
//! setting, run again on its own, is within its claimed error; (4) the
//! scene's own setting, `contact_exponential` at 1 kHz, is what the study
//! recommends for every target: the cheapest setting that meets it.

mod support;

use annular_plate::config::{Config, IntegratorKind, PlateTheory};
use annular_plate::study::{self, response, trajectory, StudyPlan};
use support::scene_files as scenes;

/// The inner step limit of the run the study is checked against.
const CHECK_RK4_STEP_LIMIT: f64 = 0.003125;

fn clamped_bench() -> Config {
    let text = scenes::text("brake_bench.yaml");
    let from = "clamp_force: [0.0]";
    assert!(
        text.contains(from),
        "config/brake_bench.yaml has no `{from}`"
    );
    let mut c = Config::from_yaml_str(
        &text.replacen(from, "clamp_force: [8000.0]", 1),
        scenes::NODE,
    )
    .unwrap();
    // `study` takes Kirchhoff plates only (docs/mindlin.md); the file ships Mindlin theory.
    c.plate.theory = PlateTheory::Kirchhoff;
    c
}

#[test]
fn study_of_the_clamped_bench_measures_contact_exponential_right_and_recommends_the_scenes_own_setting(
) {
    let config = clamped_bench();
    let mut plan = StudyPlan::quick();
    plan.targets = vec![1e-3, 1e-6, 1e-9];
    let r = study::run(&config, "brake bench clamped", &plan, &mut |_, _, _| {}).unwrap();
    let c = &r.integrator;
    assert_eq!(c.reference.integrator, "rk4");
    assert_eq!(
        c.integrators,
        [
            "exponential",
            "implicit_midpoint",
            "rk4",
            "contact_exponential"
        ]
    );
    assert!(
        c.notes.iter().any(|n| n.contains("switch")),
        "{:?}",
        c.notes
    );
    // The clamp alone leaves the disc flat (the floating caliper balances its
    // faces): the study adds its unit force, as it says.
    assert!(
        c.notes.iter().any(|n| n.contains("1 N force")),
        "{:?}",
        c.notes
    );
    let (loaded, _) = response::load_case(&config);

    let samples = (c.duration_s * c.sample_rate_hz).round() as usize;
    let run = |integrator: IntegratorKind, rate: f64, rk4_step_limit: Option<f64>| {
        let mut scene = trajectory::scene_at(&loaded, integrator, rate);
        if let Some(limit) = rk4_step_limit {
            scene.simulation.rk4_step_limit = limit;
        }
        let every = (rate / c.sample_rate_hz).round() as u64;
        trajectory::record(&scene, every, samples).unwrap().0
    };
    let exact = run(
        IntegratorKind::Rk4,
        c.reference.rate_hz,
        Some(CHECK_RK4_STEP_LIMIT),
    );

    // (1) The reference against the finer run.
    let reference = run(IntegratorKind::Rk4, c.reference.rate_hz, Some(0.0125));
    let reference_error = trajectory::relative_error(&reference, &exact);
    println!(
        "reference error {reference_error:.2e}, reported uncertainty {:.2e}, checks {:?}",
        c.reference.uncertainty, c.reference.checks
    );
    assert!(reference_error <= c.reference.uncertainty);
    assert!(c.reference.uncertainty < 1e-8, "the reference converged");

    // (2) Every reported error.
    let kind = |name: &str| IntegratorKind::from_name(name).unwrap();
    for row in &c.rows {
        let Some(err) = row.relative_error else {
            assert!(
                row.integrator != "contact_exponential" && row.integrator != "rk4",
                "{row:?}"
            );
            continue;
        };
        let e = trajectory::relative_error(&run(kind(row.integrator), row.rate_hz, None), &exact);
        println!(
            "{} {} Hz: study {err:.3e}, here {e:.3e}",
            row.integrator, row.rate_hz
        );
        assert!(
            (err - e).abs() <= c.reference.uncertainty * (1.0 + e),
            "{} {} Hz: study {err} vs here {e}",
            row.integrator,
            row.rate_hz
        );
    }

    // (3) and (4): every target is met by the scene's own setting, and it holds.
    for rec in &c.recommendations {
        let s = rec.setting.as_ref().expect("every target is reached");
        let e = trajectory::relative_error(&run(kind(s.integrator), s.rate_hz, None), &exact);
        let claimed = rec.claimed_error.unwrap();
        println!(
            "target {:.0e}: {} at {} Hz, claimed ≤ {claimed:.2e}, here {e:.2e}",
            rec.target, s.integrator, s.rate_hz
        );
        assert!(e <= claimed && claimed <= rec.target);
        assert!(
            rec.is_default && s.integrator == "contact_exponential" && s.rate_hz == 1e3,
            "{rec:?}"
        );
    }
}
