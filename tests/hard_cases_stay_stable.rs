//! Hard cases stay numerically stable or are refused clearly — never a NaN.

mod support;

use annular_plate::config::{Boundary, Config, Coordinates, IntegratorKind};
use annular_plate::dynamics::load_models::tool::SURFACE;
use annular_plate::dynamics::{InputError, JointAngle, NodeKind, Simulation, StepError, Wrench};
use support::scenes::*;

/// Lathe disc at its cutting speed with a rim load: the 18.8 kHz ⟨7, 1⟩ mode
/// is stepped at 1 kHz (ωh ≈ 118).
fn lathe_at_1khz(integrator: IntegratorKind) -> Simulation {
    Simulation::new(lathe_config_at_1khz(integrator)).unwrap()
}

fn lathe_config_at_1khz(integrator: IntegratorKind) -> Config {
    let mut c = integrated(
        with_ale_load(lathe(), 1.0, 0.0, [0.0, 80.0, -300.0]),
        integrator,
        Coordinates::Ale,
        1000.0,
    );
    c.joint.speed = 100.0 / 60.0 / 0.15; // 100 m/min at the rim
    c
}

#[test]
fn unresolved_midpoint_on_request_is_stable_and_settles_to_the_same_state() {
    let mut exp = lathe_at_1khz(IntegratorKind::Exponential);
    // A huge step limit accepts the unresolved modes on purpose (A-stability alone).
    let mut unresolved = lathe_config_at_1khz(IntegratorKind::ImplicitMidpoint);
    unresolved.simulation.midpoint_step_limit = 1e6;
    let mut mid = Simulation::new(unresolved).unwrap();
    assert_eq!(mid.settings().step_limit().map(|l| l.0), Some(1e6));
    let top = exp.model().modes().last().unwrap().clone();
    assert_eq!((top.k, top.l), (7, 1));
    assert!(
        (top.frequency_hz - 18_800.0).abs() < 200.0,
        "{}",
        top.frequency_hz
    );
    let mut diffs = vec![];
    for s in 1..=8000 {
        exp.step().unwrap();
        mid.step().unwrap();
        assert!(exp
            .q_ale()
            .iter()
            .chain(mid.q_ale())
            .all(|q| q.is_finite() && q.abs() < 1e-4));
        if s % 1000 == 0 {
            diffs.push(relative_difference(mid.q_ale(), exp.q_ale()));
        }
    }
    // The exponential integrator damps every mode exactly; the midpoint rule damps
    // the unresolved ones (ωh up to 118) only weakly, so its transient rings
    // down second by second towards the same steady state (measured 5.8e-3 →
    // 1.4e-5 over 8 s).
    println!("implicit midpoint vs exponential each second: {diffs:?}");
    assert!(diffs.windows(2).all(|w| w[1] < w[0]), "{diffs:?}");
    assert!(*diffs.last().unwrap() < 3e-5);
    assert_eq!(mid.inner_substeps(), 1);
}

/// The one criterion of docs/hard_cases.md: h·λ_max ≤ the integrator's step
/// limit, by sub-stepping. The midpoint rule at its default limit 0.5 resolves
/// the ⟨7, 1⟩ mode at 1 kHz (ωh ≈ 118) and follows the exact integrator with
/// its documented second-order error: halving the limit quarters it.
#[test]
fn midpoint_sub_steps_to_resolve_the_highest_mode_with_second_order_error() {
    let worst_over_30_ms = |limit: f64| {
        let mut c = lathe_config_at_1khz(IntegratorKind::ImplicitMidpoint);
        c.simulation.midpoint_step_limit = limit;
        let mut mid = Simulation::new(c).unwrap();
        let mut exp = lathe_at_1khz(IntegratorKind::Exponential);
        let mut worst: f64 = 0.0;
        for _ in 0..30 {
            mid.step().unwrap();
            exp.step().unwrap();
            worst = worst.max(relative_difference(mid.q_lagrange(), exp.q_lagrange()));
        }
        let omega_top = mid.model().modes().last().unwrap().omega;
        let needed = (1e-3 * omega_top / limit).ceil() as usize;
        println!("limit {limit}: {} substeps per 1 ms step (ω_max h / limit = {needed}); worst difference over 30 ms {worst:e}", mid.inner_substeps());
        assert!(mid.inner_substeps() >= needed && mid.inner_substeps() < needed + needed / 10);
        worst
    };
    let (coarse, fine) = (worst_over_30_ms(0.5), worst_over_30_ms(0.25));
    // Measured 2.8e-3 at 0.5 (unresolved, limit 1e6: 5.8e-3 still after a second).
    assert!(coarse < 5e-3, "{coarse:e}");
    let order = (coarse / fine).log2();
    println!("observed order {order:.3}");
    assert!((order - 2.0).abs() < 0.2, "{order}");
}

/// The hardening issue's case: a ring r_i/r_a = 0.98 at 1 kHz (h·ω up to 3.8e4).
/// Unresolved, the midpoint rule saws between 0 and twice the deflection at
/// every step; at its step limit it sub-steps (≈ 80,000 per step) and gives
/// the static deflection of the modal closed form from the first step (the
/// 2 % damping rings every mode down within microseconds); rk4 refuses clearly.
#[test]
fn narrow_ring_midpoint_resolves_or_is_refused_never_saws() {
    let make = |integrator, limit: f64| {
        let mut c = integrated(
            with_ale_load(lathe(), 1.0, 0.0, [0.0, 0.0, -100.0]),
            integrator,
            Coordinates::Ale,
            1000.0,
        );
        c.plate.inner_radius = 0.147;
        c.simulation.midpoint_step_limit = limit;
        c.joint.speed = 10.0;
        Simulation::new(c)
    };
    let mut mid = make(IntegratorKind::ImplicitMidpoint, 0.5).unwrap();
    let mut unresolved = make(IntegratorKind::ImplicitMidpoint, 1e6).unwrap();
    let static_w: f64 = {
        let m = mid.model();
        (0..m.n_modes())
            .map(|i| -100.0 * m.mode_shape(i, 0.15, 0.0).w.powi(2) / m.body().modal_stiffness[i])
            .sum()
    };
    let top_hz = mid.model().modes().last().unwrap().frequency_hz;
    assert!(top_hz > 5e6, "{top_hz}");
    for s in 0..4 {
        mid.step().unwrap();
        unresolved.step().unwrap();
        // the modal part (uz less the residual flexibility's static correction, docs/residual_flexibility.md)
        let (w, u) = (
            mid.ale_node(0).uz - mid.residual_deflection(0),
            unresolved.ale_node(0).uz - unresolved.residual_deflection(0),
        );
        println!(
            "step {s}: static {static_w:e}, resolved {w:e} ({} substeps), unresolved {u:e}",
            mid.inner_substeps()
        );
        assert!(
            ((w - static_w) / static_w).abs() < 1e-9,
            "{w:e} vs {static_w:e}"
        );
        assert!(
            ((u - static_w) / static_w).abs() > 0.9,
            "the unresolved rule saws: {u:e}"
        );
    }
    let err = make(IntegratorKind::Rk4, 0.5)
        .err()
        .expect("rk4 refuses")
        .to_string();
    assert!(
        err.contains("simulation.rk4_step_limit") && err.contains("use exponential"),
        "{err}"
    );
    // Beyond the substep limit the midpoint rule is refused the same way.
    let mut tight = integrated(
        with_ale_load(lathe(), 1.0, 0.0, [0.0, 0.0, -100.0]),
        IntegratorKind::ImplicitMidpoint,
        Coordinates::Ale,
        1000.0,
    );
    tight.plate.inner_radius = 0.147;
    tight.simulation.midpoint_step_limit = 0.1;
    let err = Simulation::new(tight).err().expect("refused").to_string();
    println!("{err}");
    assert!(
        err.contains("implicit_midpoint")
            && err.contains("simulation.midpoint_step_limit")
            && err.contains("substeps"),
        "{err}"
    );
}

#[test]
fn rk4_substeps_itself_below_its_limit_and_agrees_with_the_exact_integrator() {
    let mut rk = lathe_at_1khz(IntegratorKind::Rk4);
    let mut exp = lathe_at_1khz(IntegratorKind::Exponential);
    for _ in 0..30 {
        rk.step().unwrap();
        exp.step().unwrap();
    }
    let omega_top = rk.model().modes().last().unwrap().omega;
    let needed = (1e-3 * omega_top / 0.2).ceil() as usize;
    println!(
        "rk4 used {} substeps per 1 ms step (ω_max h / 0.2 = {needed})",
        rk.inner_substeps()
    );
    assert!(rk.inner_substeps() >= needed);
    let d = relative_difference(rk.q_lagrange(), exp.q_lagrange());
    println!("rk4 vs exponential after 30 ms: {d:e}");
    assert!(d < 1e-6, "{d:e}");
}

#[test]
fn rk4_refuses_a_step_it_cannot_afford_and_says_why() {
    let c = integrated(lathe(), IntegratorKind::Rk4, Coordinates::Ale, 0.01);
    let err = Simulation::new(c).err().expect("refused").to_string();
    println!("{err}");
    assert!(
        err.contains("rk4") && err.contains("substeps") && err.contains("Hz"),
        "{err}"
    );
}

#[test]
fn speeds_near_and_beyond_a_critical_speed_stay_bounded() {
    // Thin disc, lowest critical speed: ⟨2, 0⟩ at Ω_c = ω/2.
    let omega_c = Simulation::new(thin_disc(vec![0, 1, 2, 3]))
        .unwrap()
        .model()
        .modes()
        .iter()
        .find(|m| m.k == 2)
        .unwrap()
        .omega
        / 2.0;
    for ratio in [0.99, 1.5] {
        for integrator in [
            IntegratorKind::Exponential,
            IntegratorKind::ImplicitMidpoint,
        ] {
            let mut c = integrated(
                with_ale_load(thin_disc(vec![0, 1, 2, 3]), 1.0, 0.0, [0.0, 0.0, -20.0]),
                integrator,
                Coordinates::Ale,
                1000.0,
            );
            c.joint.speed = ratio * omega_c;
            let mut sim = Simulation::new(c).unwrap();
            let static_max: f64 = {
                let m = sim.model();
                (0..m.n_modes())
                    .map(|i| {
                        (20.0 * m.mode_shape(i, 0.153, 0.0).w.powi(2) / m.body().modal_stiffness[i])
                            .abs()
                    })
                    .sum()
            };
            let mut peak: f64 = 0.0;
            for _ in 0..3000 {
                sim.step().unwrap();
                peak = peak.max(sim.ale_node(0).uz.abs());
            }
            // Dynamic amplification of any mode is at most 1/(2ζ) = 25 (one-mode closed form).
            println!("Ω = {ratio} Ω_c, {integrator:?}: peak |w| under the load {peak:e} m (static sum {static_max:e})");
            assert!(peak.is_finite() && peak <= 25.0 * static_max);
        }
    }
}

#[test]
fn joint_angle_beyond_1e9_rad_loses_no_precision_in_the_ale_transform() {
    let far = 1.0e9 + 0.3;
    let near = JointAngle::from_radians(far).angle;
    let make = |chi0: f64| {
        let mut c = with_lagrange_load(
            with_ale_load(lathe(), 1.0, 0.0, [0.0, 0.0, -300.0]),
            0.7,
            0.2,
            [0.0, 0.0, 150.0],
        );
        c.joint.speed = 200.0;
        c.joint.initial_position = chi0;
        Simulation::new(c).unwrap()
    };
    let (mut a, mut b) = (make(far), make(near));
    for _ in 0..2000 {
        a.step().unwrap();
        b.step().unwrap();
    }
    let d = relative_difference(a.q_ale(), b.q_ale())
        .max(relative_difference(a.q_lagrange(), b.q_lagrange()));
    println!(
        "χ0 = {far} vs its wrapped angle {near}: amplitudes differ by {d:e}; χ = {}",
        a.joint().position
    );
    assert!(d < 1e-12, "{d:e}");
    assert!(a.joint().position > 1e9);
    // What a naive f64 χ would cost: cos(7χ) at 1e9 rad is off by ~7 ulp(1e9) ≈ 8e-7.
    assert!((7.0 * far).cos() != (7.0 * near).cos());
}

#[test]
fn tiny_and_narrow_geometries_simulate_without_nan() {
    for (ri, ra, inner, outer) in [
        (1.5e-5, 0.15, Boundary::Free, Boundary::Clamped),
        (0.147, 0.15, Boundary::Clamped, Boundary::Free),
        (0.147, 0.15, Boundary::Free, Boundary::Free),
    ] {
        for thickness in [1e-4, 0.1] {
            // Stiffness scales with h³: keep the load in the linear range (w ≪ 1000 h).
            let mut c = with_ale_load(
                lathe(),
                0.5,
                0.0,
                [0.0, 0.0, -(thickness / 0.01f64).powi(3)],
            );
            c.plate.inner_radius = ri;
            c.plate.outer_radius = ra;
            c.plate.inner_boundary = inner;
            c.plate.outer_boundary = outer;
            c.plate.thickness = thickness;
            c.joint.speed = 10.0;
            let mut sim = Simulation::new(c).expect("valid extreme geometry builds");
            assert!(sim
                .model()
                .modes()
                .iter()
                .all(|m| m.omega.is_finite() && m.omega > 0.0));
            for _ in 0..200 {
                sim.step().unwrap();
            }
            assert!(sim
                .q_ale()
                .iter()
                .chain(sim.q_lagrange())
                .all(|q| q.is_finite()));
            println!(
                "r_i/r_a = {}, h = {thickness}: {} modes {:.4e}..{:.4e} Hz, w = {:e}",
                ri / ra,
                sim.model().n_modes(),
                sim.model().modes()[0].frequency_hz,
                sim.model().modes().last().unwrap().frequency_hz,
                sim.ale_node(0).uz
            );
        }
    }
}

#[test]
fn bad_inputs_are_refused_by_name_and_leave_the_state_untouched() {
    let make = || {
        let mut c = with_ale_load(lathe(), 1.0, 0.0, [0.0, 0.0, -100.0]);
        c.joint.speed = 20.0;
        Simulation::new(c).unwrap()
    };
    let (mut clean, mut poked) = (make(), make());
    clean.step().unwrap();
    poked.step().unwrap();
    let bad = [
        (
            Wrench {
                force: [f64::NAN, 0.0, 0.0],
                moment: [0.0; 3],
            },
            "force.x",
        ),
        (
            Wrench {
                force: [0.0; 3],
                moment: [0.0, f64::INFINITY, 0.0],
            },
            "moment.y",
        ),
        (
            Wrench {
                force: [0.0, 0.0, -1e12],
                moment: [0.0; 3],
            },
            "|force|",
        ),
        (
            Wrench {
                force: [0.0; 3],
                moment: [0.0, 0.0, 5e9],
            },
            "|moment|",
        ),
    ];
    for (w, part) in bad {
        let e = poked.set_ale_wrench(0, w).unwrap_err();
        println!("{e}");
        assert!(
            e.to_string().contains("ale_1 wrench") && e.to_string().contains(part),
            "{e}"
        );
    }
    let e = poked.set_ale_wrench(3, Wrench::default()).unwrap_err();
    assert_eq!(
        e,
        InputError::NoSuchNode {
            kind: NodeKind::Ale,
            index: 4,
            count: 1
        }
    );
    let e = poked.set_lagrange_wrench(0, Wrench::default()).unwrap_err();
    assert!(matches!(
        e,
        InputError::NoSuchNode {
            kind: NodeKind::Lagrange,
            count: 0,
            ..
        }
    ));
    assert!(poked
        .set_speed_command(f64::NAN)
        .unwrap_err()
        .to_string()
        .contains("speed command"));
    assert!(poked
        .set_speed_command(1e9)
        .unwrap_err()
        .to_string()
        .contains("speed command"));
    assert_eq!(poked.state(), clean.state());
    for _ in 0..50 {
        clean.step().unwrap();
        poked.step().unwrap();
    }
    assert_eq!(
        poked.state(),
        clean.state(),
        "a refused input changed the trajectory"
    );
}

#[test]
fn divergence_is_detected_reported_and_leaves_the_last_finite_state() {
    // A reference frame turning off-axis faster than the lowest mode: the
    // centrifugal softening makes it unstable — a real instability, reported.
    let mut c = with_ale_load(thin_disc(vec![0, 1, 2]), 1.0, 0.0, [0.0, 0.0, -20.0]);
    c.reference.angular_velocity = [800.0, 0.0, 0.0];
    let mut sim = Simulation::new(c).unwrap();
    let mut error = None;
    for _ in 0..100_000 {
        match sim.step() {
            Ok(()) => assert!(sim.q_ale().iter().all(|q| q.is_finite())),
            Err(e) => {
                error = Some(e);
                break;
            }
        }
    }
    let e = error.expect("divergence must be detected");
    println!("{e}");
    assert!(matches!(e, StepError::Diverged { .. }));
    assert!(e.to_string().contains("max_deflection_thicknesses"));
    assert!(sim.state().is_finite());
    let before = sim.state().clone();
    assert!(sim.step().is_err());
    assert_eq!(sim.state(), &before);
}

#[test]
fn a_diverged_lathe_step_is_undone_with_every_surface_bin_it_cut() {
    // The lathe scene with 4 substeps per step: a step cuts several bins of
    // the tool's 4096-bin surface, which the stepper logs instead of copying.
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("config/lathe.yaml");
    let mut c = Config::from_params_file(&path, "annular_plate").unwrap();
    c.simulation.substeps = 4;
    let thickness = c.plate.thickness;
    let max_q =
        |state: &annular_plate::dynamics::State| state.q.iter().fold(0.0f64, |m, q| m.max(q.abs()));
    // Reference run: a step after the tool reaches the face (0.25 s) that
    // grows the largest |q| and lowers surface bins.
    let mut reference = Simulation::new(c.clone()).unwrap();
    let (before, limit) = loop {
        let before = reference.state().clone();
        reference.step().unwrap();
        let (q0, q1) = (max_q(&before), max_q(reference.state()));
        let cut = reference.state().load_models.slots[0][SURFACE..]
            != before.load_models.slots[0][SURFACE..];
        if before.time > 0.3 && q1 > q0 && cut {
            break (before, 0.5 * (q0 + q1) / thickness);
        }
        assert!(reference.time() < 2.0, "no growing cut found");
    };
    let bins_cut = reference.state().load_models.slots[0][SURFACE..]
        .iter()
        .zip(&before.load_models.slots[0][SURFACE..])
        .filter(|(a, b)| a != b)
        .count();
    assert!(bins_cut > 0);
    // From the same state with the amplitude limit between: the step is
    // refused and every value, surface bins included, is as before it — bit for bit.
    c.limits.max_deflection_thicknesses = limit;
    let mut guarded = Simulation::new(c).unwrap();
    guarded.restore(before.clone());
    let e = guarded.step().unwrap_err();
    assert!(matches!(e, StepError::Diverged { .. }), "{e}");
    assert!(
        guarded.state() == &before,
        "the refused step left changes ({bins_cut} bins were cut in it)"
    );
    assert!(guarded.step().is_err());
    assert!(guarded.state() == &before);
}

/// The fuzz test's held inputs on the bench (a clamp force at rounding
/// level, 1.1e-255 N, a speed command of −8.3e-278 rad/s, a 10 MN radial
/// force on node 1 with 1.2e-123 N axially): the contacts switch at rounding level, past the 4096 a
/// substep that `contact_exponential` locates. The step is finished span by
/// span, stays finite, is counted, and the warning names what to change.
#[test]
fn rounding_level_chatter_is_finished_counted_and_warned_of() {
    use annular_plate::dynamics::load_models::pad_outputs::PadOutputs;
    let mut sim = Simulation::new(support::scene_files::load("brake_bench.yaml")).unwrap();
    sim.set_pad_clamp_force(0, 1.1054868701845855e-255).unwrap();
    sim.set_speed_command(-8.273667864747689e-278).unwrap();
    let radial = Wrench {
        force: [1.0e7, 0.0, -1.233233025687852e-123],
        moment: [0.0; 3],
    };
    sim.set_ale_wrench(0, radial).unwrap();
    assert_eq!(sim.unlocated_substeps(), 0);
    sim.step().unwrap();
    let report = sim.contact_report();
    println!("{report:?}");
    assert!(report.unlocated && report.switches == 4096);
    assert!(sim.state().is_finite());
    assert_eq!(sim.unlocated_substeps(), 1);
    let warning = sim.unlocated_warning();
    assert!(
        warning.starts_with("1 contact_exponential substeps"),
        "{warning}"
    );
    assert!(warning.contains("simulation.rate_hz") && warning.contains("rk4"));
}
