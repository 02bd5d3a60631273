//! Node frames on a face (`nodes.ale_surface`, `nodes.lagrange_surface`):
//! a Kirchhoff face point at z moves in-plane by −z∇w, so an in-plane force F
//! there does the virtual work −z F·∇w_i on mode i, and the frame's pose is
//! the displaced face point (docs/dynamics.md, "Node frames on a face").
//! Checked against the mode shapes' gradient by central differences (not the
//! tilt the code uses), in a static solution; and the two descriptions still
//! agree to round-off with face frames.

mod support;

use annular_plate::config::{
    Config, Coordinates, IntegratorKind, NodePosition, Surface, WrenchConfig,
};
use annular_plate::dynamics::Simulation;
use annular_plate::model::PlateModel;
use support::scenes::*;

/// ∇w_i at (r, φ) in the plate's Cartesian axes by central differences of w_i.
fn gradient(model: &PlateModel, i: usize, r: f64, phi: f64) -> [f64; 2] {
    let (x, y) = (r * phi.cos(), r * phi.sin());
    let w = |x: f64, y: f64| model.mode_shape(i, x.hypot(y), y.atan2(x)).w;
    let e = 1e-6;
    [
        (w(x + e, y) - w(x - e, y)) / (2.0 * e),
        (w(x, y + e) - w(x, y - e)) / (2.0 * e),
    ]
}

/// A thin disc at rest, heavily damped, with a held wrench at a face node:
/// run to its static solution.
fn static_scene(surface: Surface, force: [f64; 3]) -> Config {
    let mut c = thin_disc(vec![0, 1, 2, 3]);
    c.plate.damping = vec![0.5];
    c.joint.speed = 0.0;
    c.nodes.lagrange.push(NodePosition {
        radial: 0.8,
        angular: 0.1,
    });
    c.nodes.lagrange_surface = vec![surface];
    c.loads.lagrange.push(WrenchConfig {
        force,
        moment: [0.0; 3],
    });
    integrated(
        c,
        IntegratorKind::Exponential,
        Coordinates::Lagrangian,
        1000.0,
    )
}

fn settle(c: Config) -> Simulation {
    let mut sim = Simulation::new(c).expect("valid scene");
    for _ in 0..2000 {
        sim.step().expect("stable step");
    }
    sim
}

#[test]
fn an_in_plane_force_on_a_face_bends_the_plate_by_minus_z_f_dot_grad_w() {
    let force = [300.0, -200.0, 4.0];
    for (surface, z) in [(Surface::Top, 0.001), (Surface::Bottom, -0.001)] {
        let sim = settle(static_scene(surface, force));
        let model = sim.model();
        let node = &sim.scene().lagrange_nodes[0];
        let (r, phi) = (node.radius, node.angle);
        let mut worst: f64 = 0.0;
        let mut largest_face_share: f64 = 0.0;
        for (i, mode) in model.modes().iter().enumerate() {
            let g = gradient(model, i, r, phi);
            let face = -z * (force[0] * g[0] + force[1] * g[1]);
            let f = model.mode_shape(i, r, phi).w * force[2] + face;
            let stiffness = model.body().modal_mass[i] * mode.omega * mode.omega;
            let expected = f / stiffness;
            worst = worst.max((sim.q_lagrange()[i] - expected).abs());
            largest_face_share = largest_face_share.max((face / stiffness).abs());
        }
        let scale = sim.q_lagrange().iter().fold(0.0f64, |m, q| m.max(q.abs()));
        println!("{surface:?}: static amplitudes within {:e} of −z F·∇w_i / K_i (largest {scale:e}, face share {largest_face_share:e})", worst);
        assert!(worst < 1e-6 * scale, "{worst:e} vs {scale:e}");
        // Not vacuous: the face's couple is a visible part of the response.
        assert!(
            largest_face_share > 0.2 * scale,
            "{largest_face_share:e} vs {scale:e}"
        );
    }
}

#[test]
fn opposite_faces_with_equal_in_plane_forces_do_not_bend_the_plate() {
    // Equal in-plane forces on both faces are a membrane load: no bending.
    let mut c = static_scene(Surface::Top, [300.0, -200.0, 0.0]);
    c.nodes.lagrange.push(NodePosition {
        radial: 0.8,
        angular: 0.1,
    });
    c.nodes.lagrange_surface.push(Surface::Bottom);
    c.loads.lagrange.push(WrenchConfig {
        force: [300.0, -200.0, 0.0],
        moment: [0.0; 3],
    });
    let both = settle(c);
    let top = settle(static_scene(Surface::Top, [300.0, -200.0, 0.0]));
    let scale = top.q_lagrange().iter().fold(0.0f64, |m, q| m.max(q.abs()));
    let rest = both.q_lagrange().iter().fold(0.0f64, |m, q| m.max(q.abs()));
    assert!(scale > 1e-8, "one face alone bends the plate: {scale:e}");
    assert!(rest < 1e-12 * scale, "{rest:e}");
}

#[test]
fn a_face_frame_s_pose_is_the_displaced_face_point() {
    let sim = settle(static_scene(Surface::Top, [300.0, -200.0, 40.0]));
    let model = sim.model();
    let node = &sim.scene().lagrange_nodes[0];
    let (r, phi, z) = (node.radius, node.angle, 0.001);
    let q = sim.q_lagrange();
    let (mut w, mut g) = (0.0, [0.0; 2]);
    for (i, qi) in q.iter().enumerate() {
        w += model.mode_shape(i, r, phi).w * qi;
        let gi = gradient(model, i, r, phi);
        g[0] += gi[0] * qi;
        g[1] += gi[1] * qi;
    }
    // The pose's z also carries the truncated modes' static deflection of the
    // node's 40 N transverse force (plate.residual_flexibility; tested in
    // tests/residual_flexibility_static.rs): only the modal part is face kinematics.
    let residual = sim.residual_deflection(sim.n_ale_nodes());
    let expected = [
        r * phi.cos() - z * g[0],
        r * phi.sin() - z * g[1],
        z + w + residual,
    ];
    let got = sim.lagrange_node_pose(0).translation;
    for a in 0..3 {
        assert!(
            (got[a] - expected[a]).abs() < 1e-12 + 1e-7 * (z * g[0].hypot(g[1])),
            "axis {a}: {got:?} vs {expected:?}"
        );
    }
    // The in-plane shift is there (not a mid-plane pose).
    assert!((got[0] - r * phi.cos()).abs() > 1e-3 * (z * g[0].hypot(g[1])));
    assert!(z * g[0].hypot(g[1]) > 1e-9);
}

/// The lathe disc at 100 rad/s with in-plane and normal forces on face frames:
/// a space-fixed one on the top face, a material one on the bottom face.
fn face_scene(surfaces: [Surface; 2]) -> Config {
    let mut c = with_ale_load(lathe(), 1.0, 0.0, [120.0, 150.0, -400.0]);
    c = with_lagrange_load(c, 0.5, 0.3, [-80.0, 60.0, 250.0]);
    c.nodes.ale_surface = vec![surfaces[0]];
    c.nodes.lagrange_surface = vec![surfaces[1]];
    c.joint.speed = 100.0;
    c
}

fn history(c: Config, coordinates: Coordinates) -> Vec<f64> {
    let mut sim = Simulation::new(integrated(
        c,
        IntegratorKind::Exponential,
        coordinates,
        1000.0,
    ))
    .unwrap();
    let mut out = Vec::new();
    for _ in 0..2000 {
        sim.step().unwrap();
        out.extend_from_slice(sim.q_ale());
        out.extend_from_slice(sim.q_lagrange());
    }
    out
}

#[test]
fn ale_and_lagrangian_descriptions_agree_to_round_off_with_face_frames() {
    let faces = [Surface::Top, Surface::Bottom];
    let ale = history(face_scene(faces), Coordinates::Ale);
    let lagrange = history(face_scene(faces), Coordinates::Lagrangian);
    let d = relative_difference(&ale, &lagrange);
    println!("face frames, ALE vs Lagrangian: {d:e}");
    assert!(d < 1e-12, "{d:e}");
    // Not vacuous: the faces change the motion against mid-plane frames.
    let mid = history(face_scene([Surface::Mid, Surface::Mid]), Coordinates::Ale);
    assert!(relative_difference(&ale, &mid) > 1e-3);
}

#[test]
fn surfaces_are_read_from_the_file_and_bad_ones_are_refused_naming_the_key() {
    let file = |surfaces: &str| {
        format!(
            "annular_plate:\n  ros__parameters:\n    nodes:\n      ale_radial: [0.5, 1.0]\n      ale_angular: [0.0, 0.5]\n      ale_surface: {surfaces}\n"
        )
    };
    let c = Config::from_yaml_str(&file("[top, bottom]"), "annular_plate").unwrap();
    assert_eq!(c.nodes.ale_surface, vec![Surface::Top, Surface::Bottom]);
    assert_eq!(
        Config::from_yaml_str(&file("[]"), "annular_plate")
            .unwrap()
            .nodes
            .ale_surface,
        vec![Surface::Mid; 2]
    );
    let e = Config::from_yaml_str(&file("[top]"), "annular_plate")
        .unwrap_err()
        .to_string();
    assert!(
        e.contains("nodes.ale_surface") && e.contains("nodes.ale_radial"),
        "{e}"
    );
    let e = Config::from_yaml_str(&file("[top, side]"), "annular_plate")
        .unwrap_err()
        .to_string();
    assert!(
        e.contains("nodes.ale_surface[1]") && e.contains("side"),
        "{e}"
    );
    let e = Config::from_yaml_str(&file("[1.0, 2.0]"), "annular_plate")
        .unwrap_err()
        .to_string();
    assert!(e.contains("nodes.ale_surface"), "{e}");
}
