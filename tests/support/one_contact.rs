//! The brake disc with only the ⟨k = 2, l = 0⟩ pair and one fixed-caliper
//! contact at θ = 0 on r = 0.1198 m: the scene of the one-contact closed
//! forms (docs/scenes.md "Friction on the faces", "Pad shear").
#![allow(dead_code)]

use annular_plate::config::{Boundary, Config, Coordinates, IntegratorKind, NodePosition};
use annular_plate::dynamics::load_models::pad_config::{
    Caliper, ContactSurface, PadContact, PadsConfig,
};

/// Ω, rad/s.
pub const SPEED: f64 = 25.0;
/// N₀ per face, N.
pub const CLAMP: f64 = 1000.0;
/// k_c per contact point and face, N/m.
pub const STIFFNESS: f64 = 2.0e7;
/// h, m.
pub const THICKNESS: f64 = 0.0181;

/// The scene: friction `mu` on `surface`, the lining's patches `shear`
/// (None: rigid), no residual flexibility (the closed forms are the modal
/// pads'; the contacts in series with it: tests/contacts_in_series_with_residual.rs),
/// RK4 in ALE.
pub fn scene(surface: ContactSurface, mu: f64, shear: Option<(f64, f64)>) -> Config {
    let mut c = Config::default();
    c.plate.inner_radius = 0.07;
    c.plate.outer_radius = 0.153;
    c.plate.thickness = THICKNESS;
    c.plate.inner_boundary = Boundary::Supported;
    c.plate.nodal_diameters = vec![2];
    c.plate.nodal_circles = vec![0];
    c.plate.damping = vec![1e-4];
    c.plate.residual_flexibility = false;
    c.nodes.ale.push(NodePosition {
        radial: 0.6,
        angular: 0.0,
    });
    c.joint.speed = SPEED;
    c.set_section(PadsConfig {
        contacts: vec![PadContact { node: 0, pad: 0 }],
        clamp_force: vec![CLAMP],
        contact_stiffness: STIFFNESS,
        contact_damping: 0.0,
        friction_coefficient: mu,
        lift_off: false,
        follower_friction: true,
        caliper: Caliper::Fixed,
        contact_surface: surface,
        static_friction_coefficient: None,
        stribeck_speed: 1.0,
        mass: 0.0,
        backing_stiffness: None,
        shear,
    });
    c.simulation.integrator = IntegratorKind::Rk4;
    c.simulation.rk4_step_limit = 0.05;
    c.simulation.coordinates = Coordinates::Ale;
    c.simulation.realtime_factor = 0.0;
    c
}
