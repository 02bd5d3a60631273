//! Scenes shared by the dynamics tests, built directly as `Config` values.
#![allow(dead_code)]

use annular_plate::config::{
    Boundary, Config, Coordinates, IntegratorKind, NodePosition, WrenchConfig,
};

/// Thin brake-like disc (supported inside, free outside) whose critical speeds
/// are reachable: ⟨k = 2, l = 0⟩ at 157.8 Hz has Ω_c = ω/2 ≈ 495.6 rad/s.
pub fn thin_disc(nodal_diameters: Vec<u32>) -> Config {
    let mut c = Config::default();
    c.plate.inner_radius = 0.07;
    c.plate.outer_radius = 0.153;
    c.plate.thickness = 0.002;
    c.plate.inner_boundary = Boundary::Supported;
    c.plate.outer_boundary = Boundary::Free;
    c.plate.nodal_diameters = nodal_diameters;
    c.plate.nodal_circles = vec![0];
    c.plate.damping = vec![0.02];
    c.simulation.realtime_factor = 0.0;
    c
}

/// The paper's lathe disc (30 modes), clamped inside, free outside.
pub fn lathe() -> Config {
    let mut c = Config::default();
    c.plate.damping = vec![0.02];
    c
}

pub fn with_ale_load(mut c: Config, radial: f64, angular: f64, force: [f64; 3]) -> Config {
    c.nodes.ale.push(NodePosition { radial, angular });
    c.loads.ale.push(WrenchConfig {
        force,
        moment: [0.0; 3],
    });
    c
}

pub fn with_lagrange_load(mut c: Config, radial: f64, angular: f64, force: [f64; 3]) -> Config {
    c.nodes.lagrange.push(NodePosition { radial, angular });
    c.loads.lagrange.push(WrenchConfig {
        force,
        moment: [0.0; 3],
    });
    c
}

pub fn integrated(
    mut c: Config,
    integrator: IntegratorKind,
    coordinates: Coordinates,
    rate_hz: f64,
) -> Config {
    c.simulation.integrator = integrator;
    c.simulation.coordinates = coordinates;
    c.simulation.rate_hz = rate_hz;
    c
}

/// max |a − b| / max |b|.
pub fn relative_difference(a: &[f64], b: &[f64]) -> f64 {
    let scale = b.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    a.iter()
        .zip(b)
        .fold(0.0f64, |m, (x, y)| m.max((x - y).abs()))
        / scale
}
