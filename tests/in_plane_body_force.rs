//! A uniform in-plane body force on the in-plane modes (docs/in_plane.md,
//! "In the dynamics", Reference motion): the k = 1 modes' first moments
//! C = ∫ρh u dA against two facts independent of the library — a free
//! annulus's elastic modes are mass-orthogonal to its rigid translation, so
//! their C vanish, and a hub-fixed disc's modes expand that translation, so
//! Σ C²/m rises to the disc's mass (Bessel's inequality, equal in the limit) —
//! and the gravity of a tilted spin axis reaching them, in both descriptions.
//!
//! Run with `-- --nocapture` for the numbers.

mod support;

use annular_plate::config::{Coordinates, InPlaneInner, IntegratorKind};
use annular_plate::dynamics::Simulation;
use support::torsion_disc::{disc, H, RA, RHO, RI};

/// (C, m) of every k = 1 cos mode of `config` (C along x; the sin partners
/// carry the same along y).
fn moments(c: annular_plate::config::Config) -> Vec<(f64, f64)> {
    let sim = Simulation::new(c).unwrap();
    let ip = sim.scene().in_plane.clone().unwrap();
    ip.modes
        .iter()
        .filter(|m| m.k == 1 && m.shape.name() == "cos")
        .map(|m| (m.first_moment[0], m.modal_mass))
        .collect()
}

fn disc_mass() -> f64 {
    RHO * H * std::f64::consts::PI * (RA * RA - RI * RI)
}

#[test]
fn a_free_annulus_has_no_first_moment_and_a_hub_fixed_one_expands_its_translation() {
    let mass = disc_mass();
    let mut free = disc(&[1], &[1, 2, 3, 4, 5], 1000.0);
    free.centrifugal.in_plane_inner = InPlaneInner::Free;
    let worst_free = moments(free)
        .iter()
        .map(|(c, m)| c.abs() / (m * mass).sqrt())
        .fold(0.0f64, f64::max);
    let mut deficits = vec![];
    for orders in [2u32, 4, 8, 16] {
        let fixed = disc(&[1], &(0..orders).collect::<Vec<_>>(), 1000.0);
        let sum: f64 = moments(fixed).iter().map(|(c, m)| c * c / m).sum();
        deficits.push(1.0 - sum / mass);
    }
    println!(
        "free annulus: |C|/√(mM) ≤ {worst_free:.2e}; hub fixed: 1 − Σ C²/m / M at 2, 4, 8, 16 orders: {deficits:.3?}"
    );
    assert!(worst_free < 1e-9, "{worst_free:e}");
    assert!(deficits.iter().all(|&d| d > 0.0), "Bessel's inequality");
    assert!(
        deficits.windows(2).all(|w| w[1] < 0.7 * w[0]),
        "{deficits:?}"
    );
    assert!(deficits[3] < 0.025, "{deficits:?}");
}

/// The spin axis tilted by 0.6 rad about world x under gravity: the
/// specific force has the in-plane part (0, 9.81 sin 0.6) m/s². At rest the
/// damped disc settles at q = −C·f / (m ω²) per k = 1 mode; at 300 rad/s,
/// where that load turns against the plate, the ALE and Lagrangian
/// descriptions (and RK4) agree.
#[test]
fn the_gravity_of_a_tilted_axis_bends_the_disc_in_its_plane_in_both_descriptions() {
    let tilted = |speed: f64, coordinates, integrator| {
        // At speed k = 1 alone: the spin's own load on k = 0 would dwarf it.
        let k: &[u32] = if speed == 0.0 { &[0, 1, 2] } else { &[1] };
        let mut c = disc(k, &[0, 1], 20_000.0);
        c.reference.tilt = 0.6;
        c.gravity = [0.0, 0.0, -9.81];
        c.plate.damping = vec![if speed == 0.0 { 0.7 } else { 0.05 }];
        c.joint.speed = speed;
        c.simulation.coordinates = coordinates;
        c.simulation.integrator = integrator;
        c
    };
    let mut sim =
        Simulation::new(tilted(0.0, Coordinates::Ale, IntegratorKind::Exponential)).unwrap();
    for _ in 0..4000 {
        sim.step().unwrap();
    }
    let ip = sim.scene().in_plane.clone().unwrap();
    let f = [0.0, 9.81 * 0.6f64.sin()];
    let mut worst = 0.0f64;
    let mut peak = 0.0f64;
    for (j, m) in ip.modes.iter().enumerate() {
        let work = m.first_moment[0] * f[0] + m.first_moment[1] * f[1];
        let exact = -work / (m.modal_mass * m.omega * m.omega);
        let q = sim.q_ale()[ip.offset + j];
        worst = worst.max((q - exact).abs());
        peak = peak.max(exact.abs());
    }
    let run = |coordinates, integrator| {
        let mut sim = Simulation::new(tilted(300.0, coordinates, integrator)).unwrap();
        let offset = sim.scene().in_plane.as_ref().unwrap().offset;
        (0..400)
            .map(|_| {
                sim.step().unwrap();
                sim.q_lagrange()[offset..].to_vec()
            })
            .collect::<Vec<_>>()
    };
    let ale = run(Coordinates::Ale, IntegratorKind::Exponential);
    let lagrange = run(Coordinates::Lagrangian, IntegratorKind::Exponential);
    let rk4 = run(Coordinates::Lagrangian, IntegratorKind::Rk4);
    let rk4_ale = run(Coordinates::Ale, IntegratorKind::Rk4);
    let scale = ale.iter().flatten().fold(0.0f64, |a, v| a.max(v.abs()));
    let diff = |a: &[Vec<f64>], b: &[Vec<f64>]| {
        a.iter()
            .flatten()
            .zip(b.iter().flatten())
            .fold(0.0f64, |m, (x, y)| m.max((x - y).abs()))
            / scale
    };
    // The in-plane amplitudes only (the axial part of gravity bends the disc).
    let (d_desc, d_rk4) = (diff(&ale, &lagrange), diff(&lagrange, &rk4));
    // RK4 integrates each description's own equations.
    let d_rk4_desc = diff(&rk4, &rk4_ale);
    println!(
        "at rest: settled within {:.2e} of −C·f/(mω²) (peak {peak:.3e} m); 300 rad/s: ALE vs Lagrangian {d_desc:.2e} (exponential), {d_rk4_desc:.2e} (RK4), RK4 vs exponential {d_rk4:.2e} of {scale:.3e} m",
        worst / peak
    );
    assert!(d_rk4_desc < 1e-5, "{d_rk4_desc:e}");
    assert!(peak > 0.0 && worst < 1e-9 * peak, "{worst:e} of {peak:e}");
    assert!(scale > 0.1 * peak);
    assert!(d_desc < 1e-9 && d_rk4 < 1e-5, "{d_desc:e} {d_rk4:e}");
}
