//! Node frames moving with the in-plane displacement u (docs/in_plane.md,
//! "Node frames"): a held in-plane force at a rim node of the bench disc,
//! settled, against the exact plane-stress patch compliance
//! (`tests/support/in_plane_static.rs`, no B-splines, no modes) with the
//! in-plane residual flexibility, where the modes alone are far off; a
//! Lagrangian and an ALE frame at the same point at one instant; the frames'
//! velocities against central differences of their positions.
//!
//! Run with `-- --nocapture` for the figures.

mod support;

use annular_plate::config::{Config, Coordinates, NodePosition, WrenchConfig};
use annular_plate::dynamics::load_models::pad_config::{
    Caliper, ContactSurface, PadContact, PadsConfig,
};
use annular_plate::dynamics::{NodeOutput, Simulation};
use std::f64::consts::PI;
use support::in_plane_exact::Edge;
use support::in_plane_static::InPlaneStatic;
use support::mindlin_static::Patch;
use support::torsion_disc::{self, E, H, NU, RA, RI};

/// The brake bench disc (clamped hub: in-plane fixed at r_i, free rim), one
/// bending mode and the in-plane modes k = 0, 1, 2, l = 0, one damping ratio
/// for all, at rest, with residual flexibility (each node a load patch).
fn disc(zeta: f64, rate_hz: f64) -> Config {
    let mut c = torsion_disc::disc(&[0, 1, 2], &[0], rate_hz);
    c.plate.damping = vec![zeta];
    c.plate.residual_flexibility = true;
    c
}

fn node(radial: f64, angular: f64) -> NodePosition {
    NodePosition { radial, angular }
}

fn wrench(fx: f64, fy: f64) -> WrenchConfig {
    WrenchConfig {
        force: [fx, fy, 0.0],
        moment: [0.0; 3],
    }
}

/// The exact patch compliance at the rim patch under the rim patch
/// (rows ū_r, ū_θ; columns F_r, F_θ), m/N.
fn exact_rim_compliance() -> [[f64; 2]; 2] {
    let plate = InPlaneStatic::new(E, NU, H, RI, RA, Edge::Fixed, Edge::Free);
    let patch = Patch::new(RI, RA, RA, H);
    let (c, k_used, backward) = plate.series(&patch, &[(patch, 0.0)], 1e-7, 3000);
    assert!(k_used < 3000, "exact series not converged");
    assert!(backward < 1e-12, "backward error {backward:e}");
    c[0]
}

#[test]
fn a_held_in_plane_force_at_the_rim_settles_at_the_exact_patch_displacement() {
    let exact = exact_rim_compliance();
    let force = 1000.0;
    // Node at φ = 0: x is radial, y tangential.
    for (name, f, column) in [("radial", [force, 0.0], 0), ("tangential", [0.0, force], 1)] {
        let mut c = disc(0.7, 20_000.0);
        c.nodes.lagrange.push(node(1.0, 0.0));
        c.loads.lagrange.push(wrench(f[0], f[1]));
        let mut sim = Simulation::new(c).unwrap();
        for _ in 0..400 {
            sim.step().unwrap();
        }
        let out = sim.lagrange_node(0);
        let ip = sim.scene().in_plane.as_ref().unwrap();
        let modes = ip
            .node_motion(
                &ip.lagrange_nodes[0],
                None,
                sim.q_lagrange(),
                sim.q_dot_lagrange(),
                0.0,
            )
            .u;
        let want = [exact[0][column] * force, exact[1][column] * force];
        let scale = want[column].abs();
        let err = |u: [f64; 2]| (u[0] - want[0]).abs().max((u[1] - want[1]).abs()) / scale;
        let (total, modal) = (err(out.in_plane.u), err(modes));
        let pose = out.pose.translation;
        let moved = [pose[0] - RA, pose[1]];
        println!(
            "{name} {force} N at the rim: exact (u_r, u_θ) = ({:.6e}, {:.6e}) m; node frame ({:.6e}, {:.6e}) m: {total:.2e}; modes alone ({:.6e}, {:.6e}): {modal:.2e}; rate {:.1e} m/s",
            want[0], want[1], out.in_plane.u[0], out.in_plane.u[1], modes[0], modes[1],
            out.in_plane.u_dot[0].abs().max(out.in_plane.u_dot[1].abs()),
        );
        assert!(total < 1e-3, "{name}: {total:e}");
        assert!(modal > 0.05, "{name}: the modes alone are {modal:e} off");
        // The pose's translation is the undeformed point moved by u.
        for (m, u) in moved.iter().zip(out.in_plane.u) {
            assert!(
                (m - u).abs() < 1e-8 * scale,
                "{moved:?} vs {:?}",
                out.in_plane.u
            );
        }
    }
}

/// (F_r, F_θ) or (u_r, u_θ) of Cartesian `v` at polar angle `theta`.
fn polar(v: [f64; 2], theta: f64) -> [f64; 2] {
    let (s, c) = theta.sin_cos();
    [c * v[0] + s * v[1], -s * v[0] + c * v[1]]
}

/// Two contacts of one pad (radial, angular fraction of a turn) on a fixed
/// caliper, 2 kN per face, μ = 0.5, friction on the faces.
const PAD: [(f64, f64); 2] = [(0.5, 0.02), (0.9, 0.06)];

/// Steady braking at Ω = 0.5 rad/s, settled after 10 ms: each pad frame's
/// in-plane displacement (modes + residual) against the exact patch
/// compliances of `tests/support/in_plane_static.rs` under the friction the
/// step used (the published model wrenches), summed over both contacts; the
/// modes alone are far off.
#[test]
fn steady_braking_with_residual_flexibility_deflects_the_pad_frames_to_the_exact_static() {
    let mut c = disc(0.4, 100_000.0);
    c.plate.residual_flexibility = true;
    c.joint.speed = 0.5;
    c.simulation.coordinates = Coordinates::Ale;
    for &(radial, angular) in &PAD {
        c.nodes.ale.push(node(radial, angular));
    }
    c.set_section(PadsConfig {
        contacts: (0..PAD.len())
            .map(|node| PadContact { node, pad: 0 })
            .collect(),
        clamp_force: vec![4000.0],
        contact_stiffness: 1.0e7,
        contact_damping: 0.0,
        friction_coefficient: 0.5,
        lift_off: false,
        follower_friction: true,
        caliper: Caliper::Fixed,
        contact_surface: ContactSurface::Faces,
        static_friction_coefficient: None,
        stribeck_speed: 1.0,
        mass: 0.0,
        backing_stiffness: None,
        shear: None,
    });
    let mut sim = Simulation::new(c).unwrap();
    for _ in 0..1000 {
        sim.step().unwrap();
    }
    let at = |j: usize| {
        let (radial, angular) = PAD[j];
        (RI + radial * (RA - RI), angular * 2.0 * PI)
    };
    // The friction the step used, polar at each contact.
    let forces: Vec<[f64; 2]> = (0..PAD.len())
        .map(|b| {
            let f = sim.ale_model_wrench(b).force;
            polar([f[0], f[1]], at(b).1)
        })
        .collect();
    let plate = InPlaneStatic::new(E, NU, H, RI, RA, Edge::Fixed, Edge::Free);
    let patches: Vec<Patch> = (0..PAD.len())
        .map(|j| Patch::new(RI, RA, at(j).0, H))
        .collect();
    let mut exact = vec![[0.0; 2]; PAD.len()];
    for (b, f) in forces.iter().enumerate() {
        let reads: Vec<(Patch, f64)> = (0..PAD.len())
            .map(|a| (patches[a], at(a).1 - at(b).1))
            .collect();
        let (cs, k_used, backward) = plate.series(&patches[b], &reads, 1e-7, 3000);
        assert!(k_used < 3000 && backward < 1e-12, "{k_used}, {backward:e}");
        for (u, m) in exact.iter_mut().zip(&cs) {
            u[0] += m[0][0] * f[0] + m[0][1] * f[1];
            u[1] += m[1][0] * f[0] + m[1][1] * f[1];
        }
    }
    let ip = sim.scene().in_plane.as_ref().unwrap();
    for (a, want) in exact.iter().enumerate() {
        let theta = at(a).1;
        let total = polar(sim.ale_node(a).in_plane.u, theta);
        let modal = ip.node_motion(&ip.ale_nodes[a], None, sim.q_ale(), sim.q_dot_ale(), 0.0);
        let modal = polar(modal.u, theta);
        let scale = want[0].abs().max(want[1].abs());
        let err = |u: [f64; 2]| (u[0] - want[0]).abs().max((u[1] - want[1]).abs()) / scale;
        println!(
            "pad contact {a}: friction (F_r, F_θ) = ({:.4e}, {:.4e}) N; exact (u_r, u_θ) = ({:.6e}, {:.6e}) m; node frame ({:.6e}, {:.6e}): {:.2e}; modes alone ({:.6e}, {:.6e}): {:.2e}",
            forces[a][0], forces[a][1], want[0], want[1], total[0], total[1], err(total),
            modal[0], modal[1], err(modal),
        );
        assert!(forces[a][1].abs() > 1000.0, "no friction: {:?}", forces[a]);
        assert!(err(total) < 1e-5, "contact {a}: {:e}", err(total));
        assert!(
            err(modal) > 1e-2,
            "contact {a}: modes alone {:e}",
            err(modal)
        );
    }
}

/// (x, y) of `p` turned about z by `a`.
fn turned(p: [f64; 2], a: f64) -> [f64; 2] {
    let (s, c) = a.sin_cos();
    [c * p[0] - s * p[1], s * p[0] + c * p[1]]
}

/// A disc turning at 10 rad/s with an ALE node at θ = 0.2π and a Lagrangian
/// node at φ = 0 (both at the rim), loaded in-plane at both and at a second
/// Lagrangian node at mid-radius, the joint angle set so that the Lagrangian
/// node passes under the ALE node after `steps` steps of 1/`rate` s.
fn passing(residual: bool, rate: f64, steps: usize) -> Simulation {
    let (speed, theta) = (10.0, 0.2 * PI);
    let mut c = disc(0.05, rate);
    c.plate.residual_flexibility = residual;
    c.joint.speed = speed;
    c.joint.initial_position = theta - speed * steps as f64 / rate;
    c.nodes.ale.push(node(1.0, 0.1));
    c.loads.ale.push(wrench(300.0, -800.0));
    c.nodes.lagrange.push(node(1.0, 0.0));
    c.loads.lagrange.push(wrench(-500.0, 400.0));
    c.nodes.lagrange.push(node(0.5, 0.3));
    c.loads.lagrange.push(wrench(700.0, 200.0));
    Simulation::new(c).unwrap()
}

#[test]
fn a_lagrangian_and_an_ale_frame_at_the_same_point_agree() {
    let (rate, steps) = (1e6, 300);
    let mut sim = passing(true, rate, steps);
    for _ in 0..steps {
        sim.step().unwrap();
    }
    let chi = sim.joint().position;
    let (ale, lag) = (sim.ale_node(0), sim.lagrange_node(0));
    let u_lag = turned(lag.in_plane.u, chi);
    let v_lag = turned(lag.in_plane.u_dot, chi);
    let p_lag = turned([lag.pose.translation[0], lag.pose.translation[1]], chi);
    let (u_ale, v_ale) = (ale.in_plane.u, ale.in_plane.material_u_dot);
    let p_ale = ale.pose.translation;
    let (su, sv) = (
        u_ale[0].abs().max(u_ale[1].abs()),
        v_ale[0].abs().max(v_ale[1].abs()),
    );
    let (mut du, mut dp, mut dv) = (0.0f64, 0.0f64, 0.0f64);
    for a in 0..2 {
        du = du.max((u_ale[a] - u_lag[a]).abs() / su);
        dp = dp.max((p_ale[a] - p_lag[a]).abs() / su);
        dv = dv.max((v_ale[a] - v_lag[a]).abs() / sv);
    }
    println!(
        "χ = {chi:.6} rad: u ALE ({:.6e}, {:.6e}) m, Lagrangian turned ({:.6e}, {:.6e}) m: {du:.1e}; positions {dp:.1e}; material rate ALE ({:.6e}, {:.6e}) m/s, Lagrangian turned ({:.6e}, {:.6e}): {dv:.1e}; ALE frame's own rate ({:.3e}, {:.3e}) m/s",
        u_ale[0], u_ale[1], u_lag[0], u_lag[1], v_ale[0], v_ale[1], v_lag[0], v_lag[1],
        ale.in_plane.u_dot[0], ale.in_plane.u_dot[1],
    );
    assert!((chi - 0.2 * PI).abs() < 1e-12, "χ = {chi}");
    assert!(
        su > 1e-8 && sv > 1e-5,
        "nothing moved: {su:e} m, {sv:e} m/s"
    );
    assert!(du < 1e-6, "{du:e}");
    assert!(dp < 1e-6, "{dp:e}");
    assert!(dv < 1e-6, "{dv:e}");
    assert!((ale.pose.translation[2] - lag.pose.translation[2]).abs() <= 1e-6 * su);
}

/// Central difference of the frames' in-plane positions over two steps.
fn central(before: &NodeOutput, after: &NodeOutput, h: f64) -> [f64; 2] {
    let (a, b) = (after.pose.translation, before.pose.translation);
    [(a[0] - b[0]) / (2.0 * h), (a[1] - b[1]) / (2.0 * h)]
}

#[test]
fn node_frame_velocities_are_the_rates_of_their_positions() {
    frame_velocities_are_the_rates_of_their_positions(false);
}

/// The same with the in-plane residual flexibility: the Lagrangian frames'
/// residual under the ALE node's held force (and the ALE frame's under the
/// Lagrangian ones') turns with χ, and its rate is in their velocities.
/// Measured: 1.1e-5 to 1.7e-5 (the central difference's own error, as
/// without the residual); leaving the residual's rate out gives 7.9e-5 to
/// 1.2e-4, hence the bound 4e-5 here.
#[test]
fn node_frame_velocities_carry_the_rate_of_the_turning_residual() {
    frame_velocities_are_the_rates_of_their_positions(true);
}

fn frame_velocities_are_the_rates_of_their_positions(residual: bool) {
    let bound = if residual { 4e-5 } else { 1e-3 };
    let (rate, steps) = (4e6, 1200);
    let h = 1.0 / rate;
    let mut sim = passing(residual, rate, steps);
    for _ in 0..steps - 1 {
        sim.step().unwrap();
    }
    let before = [sim.ale_node(0), sim.lagrange_node(0), sim.lagrange_node(1)];
    sim.step().unwrap();
    let now = [sim.ale_node(0), sim.lagrange_node(0), sim.lagrange_node(1)];
    sim.step().unwrap();
    let after = [sim.ale_node(0), sim.lagrange_node(0), sim.lagrange_node(1)];
    for (j, name) in ["ALE", "Lagrangian rim", "Lagrangian mid-radius"]
        .iter()
        .enumerate()
    {
        let fd = central(&before[j], &after[j], h);
        let v = now[j].in_plane.u_dot;
        let scale = v[0].abs().max(v[1].abs());
        let err = (fd[0] - v[0]).abs().max((fd[1] - v[1]).abs()) / scale;
        println!(
            "{name}: velocity ({:.6e}, {:.6e}) m/s, central difference ({:.6e}, {:.6e}): {err:.1e}",
            v[0], v[1], fd[0], fd[1]
        );
        assert!(scale > 1e-5, "{name}: nothing moved");
        assert!(err < bound, "{name}: {err:e}");
    }
}

/// `simulate --csv` writes each node's in-plane displacement after the `uz`
/// columns (`ale{j}_ux`, `ale{j}_uy`): config/brake_in_plane.yaml's three
/// ALE contact nodes after 10 ms, the last row against the library's node
/// outputs at the same step, bit for bit (shortest round-trip digits).
#[test]
fn the_csv_carries_the_nodes_in_plane_displacement() {
    let scene = concat!(env!("CARGO_MANIFEST_DIR"), "/config/brake_in_plane.yaml");
    let dir = support::cli::scratch_dir("in_plane_node_frames_csv");
    let csv = dir.join("out.csv");
    let (ok, _, stderr) = support::cli::run(&[
        "simulate",
        scene,
        "--duration",
        "0.01",
        "--csv",
        csv.to_str().unwrap(),
        "--quiet",
    ]);
    assert!(ok, "{stderr}");
    let text = std::fs::read_to_string(&csv).unwrap();
    let header: Vec<&str> = text.lines().next().unwrap().split(',').collect();
    let last: Vec<f64> = text
        .lines()
        .last()
        .unwrap()
        .split(',')
        .map(|v| v.parse().unwrap())
        .collect();
    let config = Config::from_params_file(std::path::Path::new(scene), "annular_plate").unwrap();
    let mut sim = Simulation::new(config.clone()).unwrap();
    for _ in 0..(0.01 * config.simulation.rate_hz).round() as usize {
        sim.step().unwrap();
    }
    assert_eq!(sim.n_ale_nodes(), 3);
    for j in 0..sim.n_ale_nodes() {
        let u = sim.ale_node(j).in_plane.u;
        for (axis, want) in ["ux", "uy"].iter().zip(u) {
            let name = format!("ale{}_{axis}", j + 1);
            let at = header.iter().position(|h| *h == name).unwrap();
            println!("{name} = {:e} m", last[at]);
            assert_eq!(last[at], want, "{name}");
        }
        assert!(u[0] != 0.0 || u[1] != 0.0, "node {j} did not move in-plane");
    }
    let _ = std::fs::remove_dir_all(&dir);
}
