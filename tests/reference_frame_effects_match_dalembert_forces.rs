//! The reference-frame terms of eq. (11) — gravity / base acceleration on the
//! k = 0 modes, Coriolis and centrifugal forces of a frame turning off-axis on
//! the k = 1 modes, centrifugal softening — against d'Alembert forces computed
//! here directly from the kinematics of eq. (8), by quadrature over the plate.

mod support;

use annular_plate::config::{Config, Coordinates, IntegratorKind};
use annular_plate::dynamics::Simulation;
use nalgebra::Vector3;
use support::scenes::*;

/// ∫∫ f(r, θ) r dr dθ over the plate (Gauss–Legendre × trapezoid).
fn integrate(c: &Config, f: impl Fn(f64, f64) -> f64) -> f64 {
    support::quadrature::annulus(c.plate.inner_radius, c.plate.outer_radius, 40, 48, f)
}

fn settled(c: Config) -> Simulation {
    let mut sim = Simulation::new(c).unwrap();
    for _ in 0..200 {
        sim.step().unwrap();
    }
    sim
}

#[test]
fn a_frame_turning_about_a_skew_axis_loads_the_resting_plate_by_its_dalembert_forces() {
    let w = Vector3::new(300.0, -200.0, 150.0);
    let g = Vector3::new(0.0, 0.0, -9.81);
    let mut c = integrated(
        lathe(),
        IntegratorKind::Exponential,
        Coordinates::Lagrangian,
        1000.0,
    );
    c.plate.damping = vec![0.5];
    c.plate.nodal_diameters = vec![0, 1, 2];
    c.reference.angular_velocity = [w.x, w.y, w.z];
    c.gravity = [g.x, g.y, g.z];
    let rho_h = c.plate.density * c.plate.thickness;
    let sim = settled(c.clone());
    let model = sim.model();
    let scale = sim.q_lagrange().iter().fold(0.0f64, |a, q| a.max(q.abs()));
    for (i, m) in model.modes().iter().enumerate() {
        // −ρh a_z + ρh g_z with a = ω × (ω × p) at the mid-plane point p.
        let f = integrate(&c, |r, th| {
            let p = Vector3::new(r * th.cos(), r * th.sin(), 0.0);
            let a = w.cross(&w.cross(&p));
            rho_h * (g.z - a.z) * model.mode_shape(i, r, th).w
        });
        // Softening: the deflected point's centripetal acceleration −(ω_x² + ω_y²) w.
        let k_eff = m.modal_mass * (m.omega.powi(2) - (w.x * w.x + w.y * w.y));
        let expected = f / k_eff;
        let got = sim.q_lagrange()[i];
        println!(
            "mode {i} ⟨{}, {}⟩ {:?}: q = {got:e}, d'Alembert {expected:e}",
            m.k, m.l, m.shape
        );
        assert!((got - expected).abs() < 1e-9 * scale, "mode {i}");
        if m.k >= 2 {
            assert!(got.abs() < 1e-25);
        }
    }
    assert!(
        sim.q_lagrange().iter().filter(|q| q.abs() > 1e-12).count() >= 3,
        "the test must load k = 0 and both k = 1 modes"
    );
}

#[test]
fn a_spinning_plate_in_a_precessing_frame_carries_the_coriolis_load_in_ale_coordinates() {
    let omega = 120.0; // joint speed
    let w = Vector3::new(40.0, 25.0, 10.0);
    let mut c = integrated(
        lathe(),
        IntegratorKind::Exponential,
        Coordinates::Ale,
        1000.0,
    );
    c.plate.damping = vec![0.5];
    c.plate.nodal_diameters = vec![0, 1, 2];
    c.joint.speed = omega;
    c.reference.angular_velocity = [w.x, w.y, w.z];
    let rho_h = c.plate.density * c.plate.thickness;
    let sim = settled(c.clone());
    let model = sim.model();
    // ALE-frame d'Alembert force: material at p (in A) moves with v = Ω e_z × p;
    // a_z = (ω × (ω × p))_z + 2 (ω × v)_z.
    let force = |i: usize| {
        integrate(&c, |r, th| {
            let p = Vector3::new(r * th.cos(), r * th.sin(), 0.0);
            let v = Vector3::new(0.0, 0.0, omega).cross(&p);
            let a = w.cross(&w.cross(&p)) + 2.0 * w.cross(&v);
            -rho_h * a.z * model.mode_shape(i, r, th).w
        })
    };
    let soft = w.x * w.x + w.y * w.y;
    let scale = sim.q_ale().iter().fold(0.0f64, |a, q| a.max(q.abs()));
    for (i, m) in model.modes().iter().enumerate() {
        let q = sim.q_ale()[i];
        match m.k {
            0 => {
                let expected = force(i) / (m.modal_mass * (m.omega.powi(2) - soft));
                assert!(
                    (q - expected).abs() < 1e-9 * scale,
                    "k = 0: {q:e} vs {expected:e}"
                );
            }
            1 if m.shape == annular_plate::model::AngularShape::Cos => {
                let j = m.partner.unwrap();
                let (fc, fs) = (force(i) / m.modal_mass, force(j) / m.modal_mass);
                // Steady ALE pair: [(ω_eff² − k²Ω²) I − 2ζωkΩ J] q̄ = f̄/m (docs/dynamics.md).
                let a = m.omega.powi(2) - soft - omega * omega;
                let b = 2.0 * m.damping * m.omega * omega;
                let det = a * a + b * b;
                let (qc, qs) = ((a * fc - b * fs) / det, (b * fc + a * fs) / det);
                println!(
                    "k = 1: q̄ = ({q:e}, {:e}), d'Alembert ({qc:e}, {qs:e})",
                    sim.q_ale()[j]
                );
                assert!(
                    (q - qc).abs() < 1e-9 * qc.hypot(qs)
                        && (sim.q_ale()[j] - qs).abs() < 1e-9 * qc.hypot(qs)
                );
                assert!(qc.hypot(qs) > 1e-9, "the Coriolis load must be felt");
            }
            1 => {}
            _ => assert!(q.abs() < 1e-25),
        }
    }
}
