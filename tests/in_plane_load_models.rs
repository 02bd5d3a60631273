//! The load models that push along the axis only — springs, dampers, pitch
//! links and the lathe's tool (its feed force) — with in-plane modes
//! (`plate.in_plane_nodal_diameters`): they do no work on the in-plane modes
//! and the in-plane modes do not move what they read, so the bending motion
//! is the one without in-plane modes, and the in-plane motion is the one
//! without the models, step for step. The tool's main cutting force
//! (`tool.cutting_specific_force`) brakes the joint by F_c r_a and twists the
//! disc to the exact static of a tangential rim force.

mod support;

use annular_plate::config::Config;
use annular_plate::dynamics::load_models::tool::ToolOutputs;
use annular_plate::dynamics::{Simulation, Wrench};
use support::in_plane_modes::{exact_torsion, patch_mean};

/// A disc with ⟨k = 0, 1, 2; l = 0⟩ bending modes turning at 10 rad/s, a
/// spring under an ALE rim node, a damper under an ALE node at mid-radius and
/// a pitch link at a material rim point (`models` false: none of them),
/// with in-plane modes `in_plane` (k, one order each).
fn scene(in_plane: &str, models: bool) -> Config {
    let sections = if models {
        "    springs:
      ale_nodes: [1]
      stiffness: 1.0e6
      damping: 20.0
    dampers:
      ale_nodes: [2]
      damping: 300.0
    links:
      lagrange_nodes: [1]
      mean_force: 100.0
      cyclic_force: 50.0
"
    } else {
        ""
    };
    let text = format!(
        "/**:
  ros__parameters:
    plate:
      nodal_diameters: [0, 1, 2]
      nodal_circles: [0]
      damping: [0.01]
      in_plane_nodal_diameters: {in_plane}
      in_plane_orders: [0]
    nodes:
      ale_radial: [1.0, 0.5]
      ale_angular: [0.0, 0.25]
      lagrange_radial: [1.0]
      lagrange_angular: [0.5]
    joint:
      speed: 10.0
{sections}    simulation:
      integrator: exponential
      rate_hz: 10000.0
    initial:
      q: [1.0e-6, 1.0e-6, 0.0, 1.0e-6, 0.0]
"
    );
    Config::from_yaml_str(&text, "annular_plate").unwrap()
}

/// Per step the ALE amplitudes, with a tangential and a radial force held
/// at the rim node from the start.
fn run(config: Config, steps: usize) -> Vec<Vec<f64>> {
    let mut sim = Simulation::new(config).unwrap();
    let held = Wrench {
        force: [300.0, -800.0, 0.0],
        moment: [0.0; 3],
    };
    sim.set_ale_wrench(0, held).unwrap();
    (0..steps)
        .map(|_| {
            sim.step().unwrap();
            sim.q_ale().to_vec()
        })
        .collect()
}

/// The largest |a − b| over the runs against the largest |b|.
fn worst(a: &[Vec<f64>], b: &[Vec<f64>], range: std::ops::Range<usize>) -> (f64, f64) {
    let peak = b
        .iter()
        .flat_map(|r| &r[range.clone()])
        .fold(0.0f64, |m, v| m.max(v.abs()));
    let diff = a
        .iter()
        .zip(b)
        .flat_map(|(x, y)| x[range.clone()].iter().zip(&y[range.clone()]))
        .fold(0.0f64, |m, (x, y)| m.max((x - y).abs()));
    (diff, peak)
}

/// Springs, dampers and links with in-plane modes: the bending amplitudes
/// are those of the scene without in-plane modes, and the in-plane
/// amplitudes under the held in-plane force those of the scene without the
/// models — which move the bending by far more than the test's bound.
#[test]
fn springs_dampers_and_links_act_on_the_bending_alone() {
    let steps = 400;
    let with_both = run(scene("[0, 1]", true), steps);
    let bending_only = run(scene("[]", true), steps);
    let in_plane_only = run(scene("[0, 1]", false), steps);
    let n = bending_only[0].len();
    let (bending, peak) = worst(&with_both, &bending_only, 0..n);
    let all = with_both[0].len();
    let (in_plane, in_plane_peak) = worst(&with_both, &in_plane_only, n..all);
    let (moved, _) = worst(&with_both, &in_plane_only, 0..n);
    println!(
        "bending: {bending:.2e} m of {peak:.3e} m against the scene without in-plane modes; \
         in-plane: {in_plane:.2e} m of {in_plane_peak:.3e} m against the scene without the models; \
         the models move the bending by {moved:.3e} m"
    );
    assert!(
        peak > 1e-7 && in_plane_peak > 1e-9,
        "{peak:e} {in_plane_peak:e}"
    );
    assert!(
        moved > 1e-3 * peak,
        "the models must act on the bending: {moved:e}"
    );
    assert!(bending <= 1e-12 * peak, "{bending:e}");
    assert!(in_plane <= 1e-12 * in_plane_peak, "{in_plane:e}");
}

/// The lathe (config/lathe.yaml) with in-plane modes k = 0, 1: through the
/// start of the cut (the tip reaches the face at 0.25 s) the bending
/// amplitudes are those without in-plane modes and the feed force, along
/// the axis, leaves the in-plane modes at rest.
#[test]
fn the_tool_cuts_as_without_in_plane_modes_and_leaves_them_at_rest() {
    let lathe = support::scene_files::text("lathe.yaml");
    let with = lathe.replacen(
        "      nodal_circles: [0, 1]\n",
        "      nodal_circles: [0, 1]\n      in_plane_nodal_diameters: [0, 1]\n",
        1,
    );
    assert_ne!(with, lathe);
    let steps = 400;
    let run = |text: &str| {
        let config = Config::from_yaml_str(text, support::scene_files::NODE).unwrap();
        let mut sim = Simulation::new(config).unwrap();
        (0..steps)
            .map(|_| {
                sim.step().unwrap();
                sim.q_ale().to_vec()
            })
            .collect::<Vec<_>>()
    };
    let (a, b) = (run(&with), run(&lathe));
    let n = b[0].len();
    let (bending, peak) = worst(&a, &b, 0..n);
    let in_plane = a
        .iter()
        .flat_map(|r| &r[n..])
        .fold(0.0f64, |m, v| m.max(v.abs()));
    println!("bending {bending:.2e} m of {peak:.3e} m; in-plane largest {in_plane:e} m");
    assert!(a[0].len() > n, "the in-plane modes are in the state");
    assert!(peak > 1e-7, "the tool must cut: {peak:e}");
    assert!(bending <= 1e-12 * peak, "{bending:e}");
    assert_eq!(in_plane, 0.0);
}

/// config/lathe.yaml with Kienzle's main cutting force (k_c1.1 = 2000 N/mm²,
/// m_c = 0.25) and the in-plane modes k = 0, l = 0, 1.2 s (the cut meets its
/// own surface from 0.815 s on): the drive holding the speed carries the
/// cutting torque, effort = F_c r_a with F_c = k_c1.1 b h^(1−m_c) (1 mm)^m_c
/// of the chip h the tool reports (within 1 % of the steady 2π v_f/Ω: the
/// regeneration settles by 1.4 s), and the first torsional mode holds the
/// static twist of the tangential rim force, −F_c V̄/(m ω²), V, m and ω of
/// the exact torsional mode (Bessel functions), V̄ V's mean over the node's
/// load patch (the scene has residual flexibility). Without the key the
/// effort is 0.
#[test]
fn the_main_cutting_force_brakes_the_joint_and_twists_the_disc() {
    let lathe = support::scene_files::text("lathe.yaml");
    let with = lathe
        .replacen(
            "      nodal_circles: [0, 1]\n",
            "      nodal_circles: [0, 1]\n      in_plane_nodal_diameters: [0]\n      in_plane_orders: [0]\n",
            1,
        )
        .replacen(
            "      force_exponent: 0.7013     # m_f\n",
            "      force_exponent: 0.7013     # m_f\n      cutting_specific_force: 2.0e9\n      cutting_exponent: 0.25\n",
            1,
        );
    let config = Config::from_yaml_str(&with, support::scene_files::NODE).unwrap();
    let (specific, exponent) = (2.0e9, 0.25);
    let mut sim = Simulation::new(config.clone()).unwrap();
    for _ in 0..1200 {
        sim.step().unwrap();
    }
    let speed = config.joint.speed;
    let tool = sim.tool_output().unwrap();
    let steady = std::f64::consts::TAU * tool.feed_rate / speed;
    let chip = tool.chip;
    let b = 0.001;
    let force = specific * b * chip.powf(1.0 - exponent) * 1.0e-3f64.powf(exponent);
    let ra = config.plate.outer_radius;
    let effort = sim.joint().effort;
    let ip = sim.scene().in_plane.as_ref().unwrap();
    let index = ip.offset + ip.torsional[0];
    let t = exact_torsion(&config.plate, 0);
    // The lathe has residual flexibility: the force is spread over the node's load patch.
    let twist = -force * patch_mean(&config, &t, ra) / (t.mass * t.omega * t.omega);
    let got = sim.q_ale()[index];
    let (effort_error, twist_error) = (
        (effort / (force * ra) - 1.0).abs(),
        (got / twist - 1.0).abs(),
    );
    println!(
        "chip {chip:.6e} m (2π v_f/Ω {steady:.6e} m), F_c {force:.3} N: effort {effort:.6} N·m against F_c r_a {:.6} N·m ({effort_error:.2e}); twist {got:.6e} m against {twist:.6e} m ({twist_error:.2e})",
        force * ra
    );
    assert!(
        (chip / steady - 1.0).abs() < 1e-2,
        "not cutting steadily: {chip:e}"
    );
    assert!(effort_error < 1e-6, "{effort_error:e}");
    assert!(twist_error < 1e-4, "{twist_error:e}");
    let mut plain =
        Simulation::new(Config::from_yaml_str(&lathe, support::scene_files::NODE).unwrap())
            .unwrap();
    for _ in 0..400 {
        plain.step().unwrap();
    }
    assert_eq!(plain.joint().effort, 0.0);
}
