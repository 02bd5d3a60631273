//! The lathe tool and the pitch links on a Mindlin plate (`plate.theory:
//! mindlin`, docs/mindlin.md): both apply only F_z and the tool reads only the
//! axial displacement w under it, which is the same for a face point in either
//! theory. Checked against the exact Mindlin modes
//! (`tests/support/mindlin_exact.rs`): the steady deflection under the tool
//! (the steady ALE response to the feed force) and the static deflection
//! under a link's force.

mod support;

use annular_plate::config::{Boundary, Config, NodePosition, PlateTheory};
use annular_plate::dynamics::load_models::pitch_link::LinksConfig;
use annular_plate::dynamics::load_models::tool::ToolOutputs;
use annular_plate::dynamics::Simulation;
use annular_plate::model::AngularShape;
use std::f64::consts::TAU;
use support::mindlin_exact::MindlinAnnulus;
use support::scene_files::{self as scenes, run_to};

/// Σ over the model's cos (and k = 0) modes ⟨k, l⟩ of the exact Mindlin
/// mode's W(r)² F a / (m (a² + b²)), a = ω² − k²Ω², b = 2ζωkΩ: the steady
/// ALE deflection at (r, θ = 0) under a space-fixed force F there
/// (docs/dynamics.md; at Ω = 0 the static modal sum).
fn exact_steady(sim: &Simulation, r: f64, force: f64, speed: f64) -> f64 {
    let annulus = MindlinAnnulus::of_plate(&sim.config().plate);
    sim.model()
        .modes()
        .iter()
        .filter(|m| m.shape != AngularShape::Sin)
        .map(|m| {
            let omega = annulus.roots(m.k, m.l as usize + 1, 64)[m.l as usize];
            let mode = annulus.mode(m.k, omega);
            let (w, mass) = (mode.fields(r).w, mode.modal_mass(400));
            let k = m.k as f64;
            let a = omega * omega - k * k * speed * speed;
            let b = 2.0 * m.damping * omega * k * speed;
            w * w * force * a / (mass * (a * a + b * b))
        })
        .sum()
}

/// config/lathe.yaml (the paper's disc, 10 mm thick, clamped inside) under
/// `theory`, without residual flexibility, cut to 3 s: the deflection under
/// the tool, the steady response its feed force gives on the exact Mindlin
/// modes, and the feed force.
fn lathe_after_3_s(theory: PlateTheory) -> (f64, f64, f64) {
    let mut c = scenes::load("lathe.yaml");
    c.plate.theory = theory;
    c.plate.residual_flexibility = false;
    let mut sim = Simulation::new(c).expect("the tool takes Mindlin modes");
    run_to(&mut sim, 3.0);
    let speed = sim.config().joint.speed;
    let force = sim.tool_output().unwrap().feed_force;
    let r_a = sim.model().plate().outer_radius;
    let expected = exact_steady(&sim, r_a, -force, speed);
    (sim.ale_node(0).uz, expected, force)
}

#[test]
fn the_deflection_under_the_tool_is_the_steady_response_of_the_exact_mindlin_modes() {
    let (got, expected, force) = lathe_after_3_s(PlateTheory::Mindlin);
    let speed = scenes::load("lathe.yaml").joint.speed;
    // Steady cut: eq. (21) at the feed per revolution, b = 1 mm.
    let chip_mm = TAU * 0.002 / speed * 1e3;
    let kienzle = chip_mm.powf(1.0 - 0.7013) * 351.0;
    let error = (got - expected).abs() / expected.abs();
    println!(
        "feed force {force:.3} N (eq. 21: {kienzle:.3} N); deflection under the tool {got:.6e} m, exact Mindlin steady response {expected:.6e} m: {error:.2e}"
    );
    assert!((force - kienzle).abs() < 1e-3 * kienzle);
    assert!(error < 1e-5, "{error:e}");
    // Not vacuous: the Kirchhoff disc deflects measurably less.
    let (kirchhoff, ..) = lathe_after_3_s(PlateTheory::Kirchhoff);
    println!("Kirchhoff: {kirchhoff:.6e} m");
    assert!((kirchhoff - got).abs() > 1e-2 * got.abs());
}

#[test]
fn a_link_s_force_deflects_a_mindlin_plate_by_the_exact_static_modal_sum() {
    // The bench disc (h = 18.1 mm, hard support inside, free outside) at rest,
    // heavily damped, one link at a material point on the rim.
    let run = |force: f64| {
        let mut c = Config::default();
        c.plate.inner_radius = 0.07;
        c.plate.outer_radius = 0.153;
        c.plate.thickness = 0.0181;
        c.plate.inner_boundary = Boundary::Supported;
        c.plate.outer_boundary = Boundary::Free;
        c.plate.nodal_diameters = vec![0, 1, 2, 3, 4];
        c.plate.nodal_circles = vec![0, 1];
        c.plate.damping = vec![0.7];
        c.plate.theory = PlateTheory::Mindlin;
        c.plate.residual_flexibility = false;
        c.joint.speed = 0.0;
        c.nodes.lagrange.push(NodePosition {
            radial: 1.0,
            angular: 0.0,
        });
        c.set_section(LinksConfig {
            nodes: vec![0],
            mean_force: force,
            cyclic_force: 0.0,
            cyclic_phase: 0.0,
        });
        c.simulation.realtime_factor = 0.0;
        let mut sim = Simulation::new(c).expect("links take Mindlin modes");
        run_to(&mut sim, 0.2);
        (sim.lagrange_node(0).uz, sim)
    };
    let force = 800.0;
    // The difference to the same run without the force: the link's share alone.
    let (loaded, sim) = run(force);
    let (unloaded, _) = run(0.0);
    let got = loaded - unloaded;
    let expected = exact_steady(&sim, 0.153, force, 0.0);
    let error = (got - expected).abs() / expected.abs();
    println!(
        "rim deflection {got:.9e} m, exact Mindlin static modal sum {expected:.9e} m: {error:.2e}"
    );
    assert!(error < 1e-6, "{error:e}");
}
