//! Unit tests of the pads' contact law (`pad.rs`, `pad_contact_law.rs`).

use super::*;

fn pads(caliper: Caliper, lift_off: bool) -> Pads {
    Pads {
        contacts: vec![
            PadContactPoint {
                node: 0,
                pad: 0,
                radius: 0.12,
                angle: 0.3,
                sin_cos: 0.3f64.sin_cos(),
                face_z: [0.009, -0.009],
            },
            PadContactPoint {
                node: 1,
                pad: 0,
                radius: 0.12,
                angle: 0.5,
                sin_cos: 0.5f64.sin_cos(),
                face_z: [0.009, -0.009],
            },
        ],
        contacts_per_pad: vec![2],
        stiffness: 1.0e6,
        damping: 50.0,
        friction_coefficient: 0.5,
        lift_off,
        follower_friction: true,
        caliper,
        contact_surface: ContactSurface::MidPlane,
        friction_excess: 0.0,
        stribeck_speed: 1.0,
        initial_clamp_force: vec![1000.0],
        coupling: Coupling::default(),
        friction_gram: Vec::new(),
        series: None,
        mass: 0.0,
        backing_stiffness: 0.0,
        shear: None,
        theory: PlateTheory::Kirchhoff,
        in_plane: None,
    }
}

fn forces(p: &Pads, kin: [SurfaceKinematics; 2], speed: f64) -> [ContactForces; 2] {
    let mut out = [ContactForces::default(); 2];
    p.forces(&[1000.0], &kin, speed, &mut out, &mut [false; 2]);
    out
}

const REST: SurfaceKinematics = SurfaceKinematics { w: 0.0, w_dot: 0.0 };

#[test]
fn undeformed_disc_feels_no_axial_force_and_the_clamp_force_in_friction() {
    for caliper in [Caliper::Fixed, Caliper::Floating] {
        let p = pads(caliper, false);
        // Clamp force 1000 N over 2 points: 500 N per point and face.
        let f = forces(&p, [REST; 2], 25.0);
        assert!((f[0].top - 500.0).abs() < 1e-9 && (f[0].bottom - 500.0).abs() < 1e-9);
        assert_eq!(f[0].axial, 0.0);
        assert!(
            (f[0].tangential + 0.5 * 1000.0).abs() < 1e-9,
            "{}",
            f[0].tangential
        );
        // Friction opposes the sliding: e_θ at θ, and reverses with Ω.
        let w = Pads::wrench(&p.contacts[0], &f[0]);
        assert!(
            (w.force[0] - 500.0 * 0.3f64.sin()).abs() < 1e-9
                && (w.force[1] + 500.0 * 0.3f64.cos()).abs() < 1e-9
        );
        let back = forces(&p, [REST; 2], -25.0);
        assert!((back[0].tangential - 500.0).abs() < 1e-9);
    }
}

#[test]
fn a_fixed_caliper_restores_with_twice_the_contact_stiffness_and_damping() {
    let s = SurfaceKinematics {
        w: 1e-5,
        w_dot: 0.02,
    };
    let f = forces(&pads(Caliper::Fixed, false), [s, REST], 25.0);
    assert!(
        (f[0].axial - (-2.0 * 1.0e6 * 1e-5 - 2.0 * 50.0 * 0.02)).abs() < 1e-9,
        "{}",
        f[0].axial
    );
    // Linear springs: the sum of the normal forces, hence friction, does not change.
    assert!((f[0].top + f[0].bottom - 1000.0).abs() < 1e-9);
}

#[test]
fn a_floating_caliper_acts_on_the_deformation_relative_to_the_pad_mean() {
    let s = SurfaceKinematics {
        w: 1e-5,
        w_dot: 0.02,
    };
    let f = forces(&pads(Caliper::Floating, false), [s, REST], 25.0);
    // w − w̄ = ±0.5e-5, ẇ − ẇ̄ = ±0.01: F_z = −2 k (w − w̄) − 2 c (ẇ − ẇ̄).
    let expected = -2.0 * 1.0e6 * 0.5e-5 - 2.0 * 50.0 * 0.01;
    assert!(
        (f[0].axial - expected).abs() < 1e-9 && (f[1].axial + expected).abs() < 1e-9,
        "{f:?}"
    );
    for face in [f[0].top + f[1].top, f[0].bottom + f[1].bottom] {
        assert!(
            (face - 1000.0).abs() < 1e-9,
            "each face carries the clamp force"
        );
    }
}

#[test]
fn lift_off_releases_the_contacts_that_would_pull() {
    // Fixed: δ₀ = 500 N / 1e6 N/m = 0.5 mm; deflect by 0.8 mm: the bottom face lifts off.
    let s = SurfaceKinematics {
        w: 8e-4,
        w_dot: 0.0,
    };
    let f = forces(&pads(Caliper::Fixed, true), [s, REST], 25.0);
    assert_eq!(f[0].bottom, 0.0);
    assert!((f[0].top - 1.0e6 * 1.3e-3).abs() < 1e-9);
    let linear = forces(&pads(Caliper::Fixed, false), [s, REST], 25.0);
    assert!(linear[0].bottom < 0.0, "without lift-off the spring pulls");
    // Floating: deflect one point by 1.5 mm (more than the 1 mm it takes
    // with the other at rest): the bottom pad leaves the raised point and
    // carries the clamp force on the other; the top pad only on the raised one.
    let s = SurfaceKinematics {
        w: 1.5e-3,
        w_dot: 0.0,
    };
    let f = forces(&pads(Caliper::Floating, true), [s, REST], 25.0);
    assert_eq!(f[0].bottom, 0.0);
    assert!((f[1].bottom - 1000.0).abs() < 1e-9, "{f:?}");
    assert!((f[0].top - 1000.0).abs() < 1e-9 && f[1].top == 0.0, "{f:?}");
}

#[test]
fn a_tilt_held_in_space_leaves_both_faces_friction_along_minus_e_theta_without_a_couple() {
    let mut p = pads(Caliper::Fixed, false);
    p.contact_surface = ContactSurface::Faces;
    let (speed, n) = (30.0, 500.0);
    for follower in [false, true] {
        p.follower_friction = follower;
        for contact in &p.contacts {
            let node = super::super::face_friction::rigid_tilt_frame(
                contact.radius,
                contact.angle,
                4e-3,
            );
            let k = super::super::face_friction::face_kinematics(&node, &[1.0], &[0.0], speed);
            let mut f = ContactForces {
                top: n,
                bottom: n,
                ..ContactForces::default()
            };
            let w = p.face_wrench(contact, &mut f, &k, speed);
            let (s, c) = contact.sin_cos;
            let radial = c * w.force[0] + s * w.force[1];
            assert!(radial.abs() < 1e-12, "radial friction {radial} N");
            // Both faces slide at Ω r e_θ in-plane: equal forces, no couple.
            assert!(
                w.moment[0].abs() < 1e-12 && w.moment[1].abs() < 1e-12,
                "{w:?}"
            );
            if !follower {
                let expected = -2.0
                    * 0.5
                    * n
                    * (speed * contact.radius / FRICTION_REGULARISATION_SPEED).tanh();
                assert!((f.tangential - expected).abs() < 1e-9, "{}", f.tangential);
            }
        }
    }
}
