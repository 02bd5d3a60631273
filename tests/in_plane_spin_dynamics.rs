//! The in-plane modes spinning in the dynamics (docs/in_plane.md, "In the
//! dynamics"): the stepped disc's turning-frame frequencies at 1000 and
//! 3000 rad/s against the independent Chebyshev collocation of the strong
//! form (`support::in_plane_spinning_exact`), the two descriptions agreeing
//! at speed, RK4 converging to the exponential step at fourth order, and the
//! implicit midpoint rule (which does not carry the spin terms) refused at
//! speed with the key named; centrifugal stiffening of the bending modes
//! beside them; an in-plane amplitude beyond the deflection limit stops the
//! run.

mod support;

use annular_plate::config::{
    Boundary, Config, Coordinates, IntegratorKind, NodePosition, WrenchConfig,
};
use annular_plate::dynamics::Simulation;
use faer::Mat;
use support::in_plane_spinning_exact::{roots, SpinningAnnulus};
use support::lame::Lame;

/// The brake bench disc (clamped hub: in-plane fixed at r_i, free rim) with
/// one bending mode and the in-plane modes `k` × `orders`, undamped, turning
/// at `speed` (held), Lagrangian description.
fn disc(k: &[u32], orders: &[u32], speed: f64, rate_hz: f64) -> Config {
    let mut c = Config::default();
    let p = &mut c.plate;
    (p.inner_radius, p.outer_radius, p.thickness) = (0.07, 0.153, 0.0181);
    (p.density, p.youngs_modulus, p.poisson_ratio) = (7850.0, 2.1e11, 0.3);
    (p.inner_boundary, p.outer_boundary) = (Boundary::Clamped, Boundary::Free);
    p.nodal_diameters = vec![0];
    p.nodal_circles = vec![0];
    p.damping = vec![0.0];
    p.in_plane_nodal_diameters = k.to_vec();
    p.in_plane_orders = orders.to_vec();
    c.gravity = [0.0; 3];
    c.joint.speed = speed;
    c.joint.max_acceleration = 1e9;
    c.simulation.rate_hz = rate_hz;
    c.simulation.substeps = 1;
    c.simulation.integrator = IntegratorKind::Exponential;
    c.simulation.coordinates = Coordinates::Lagrangian;
    c
}

/// The state indices of the in-plane modes of k.
fn block(sim: &Simulation, k: u32) -> Vec<usize> {
    let ip = sim.scene().in_plane.as_ref().expect("in-plane modes");
    (0..ip.modes.len())
        .filter(|&j| ip.modes[j].k == k)
        .map(|j| ip.offset + j)
        .collect()
}

/// The turning-frame frequencies (rad/s, positive, ascending) of the
/// in-plane modes of k read from the simulation: one step of free vibration
/// from each unit initial amplitude and rate gives the step's map Φ of
/// (q, q̇) column by column; its eigenvalues are e^{±iωh}.
fn stepped_frequencies(c: &Config, k: u32) -> Vec<f64> {
    let mut sim = Simulation::new(c.clone()).unwrap();
    let idx = block(&sim, k);
    let (n, h) = (idx.len(), sim.dt());
    let rate_scale = 1e5;
    let start = sim.state().clone();
    let mut phi = Mat::<f64>::zeros(2 * n, 2 * n);
    for col in 0..2 * n {
        let mut s = start.clone();
        s.q.fill(0.0);
        s.q_dot.fill(0.0);
        if col < n {
            s.q[idx[col]] = 1e-6;
        } else {
            s.q_dot[idx[col - n]] = 1e-6 * rate_scale;
        }
        s.rederive(sim.scene());
        sim.restore(s);
        sim.step().unwrap();
        for (r, &i) in idx.iter().enumerate() {
            phi[(r, col)] = sim.q_lagrange()[i] / 1e-6;
            phi[(n + r, col)] = sim.q_dot_lagrange()[i] / (1e-6 * rate_scale);
        }
    }
    let mut w: Vec<f64> = phi
        .eigenvalues()
        .expect("eigenvalues of a finite matrix")
        .into_iter()
        .map(|z| z.im.atan2(z.re) / h)
        .filter(|&w| w > 0.0)
        .collect();
    w.sort_by(f64::total_cmp);
    w
}

/// The lowest forward and backward turning-frame frequencies of k (rad/s)
/// from the collocation (at k = 0 the two lowest: the roots pair as ±ω).
fn reference(c: &Config, k: u32, speed: f64) -> [f64; 2] {
    let p = &c.plate;
    let a = SpinningAnnulus::of(p, true);
    let mut r: Vec<f64> = roots(&a, &Lame::new(p, true), k, speed, 48)
        .into_iter()
        .filter(|&(re, im)| im.abs() < 1e-6 * re.abs().max(1.0))
        .map(|(re, _)| re)
        .collect();
    r.sort_by(f64::total_cmp);
    let backward: Vec<f64> = r.iter().copied().filter(|&w| w > 0.0).collect();
    if k == 0 {
        return [backward[0], backward[1]];
    }
    let forward = r
        .iter()
        .filter(|&&w| w < 0.0)
        .map(|w| -w)
        .fold(f64::INFINITY, f64::min);
    [forward, backward[0]]
}

/// The largest relative distance from each reference to the nearest stepped frequency.
fn deviation(stepped: &[f64], exact: &[f64; 2]) -> f64 {
    exact
        .iter()
        .map(|&e| {
            stepped
                .iter()
                .map(|&w| (w - e).abs() / e)
                .fold(f64::INFINITY, f64::min)
        })
        .fold(0.0, f64::max)
}

#[test]
fn stepped_spinning_frequencies_match_the_collocation_up_to_the_modal_truncation() {
    let ks = [0, 1, 2];
    let few = [0];
    let many = [0, 1, 2, 3, 4, 5];
    let mut worst = 0.0f64;
    for speed in [1000.0, 3000.0] {
        for k in ks {
            let c_few = disc(&ks, &few, speed, 2e6);
            let c_many = disc(&ks, &many, speed, 2e6);
            let exact = reference(&c_many, k, speed);
            let (w_few, w_many) = (
                stepped_frequencies(&c_few, k),
                stepped_frequencies(&c_many, k),
            );
            let (d_few, d_many) = (deviation(&w_few, &exact), deviation(&w_many, &exact));
            println!(
                "Ω {speed} rad/s, k {k}: collocation {:.2} / {:.2}, stepped (6 orders) nearest deviation {d_many:.2e}, (1 order) {d_few:.2e}",
                exact[0], exact[1]
            );
            // The spin split itself is resolved: forward and backward differ by far more than the deviation.
            assert!((exact[1] - exact[0]).abs() / exact[0] > 100.0 * d_many || k == 0);
            assert!(
                d_many <= d_few,
                "more orders move away: {d_many:e} > {d_few:e}"
            );
            worst = worst.max(d_many);
        }
    }
    // Measured: 8.6e-8 (k = 1 at 3000 rad/s); one order per k is 1.8e-3 off.
    println!("worst deviation with 6 orders {worst:.2e}");
    assert!(worst < 2e-7, "{worst:e}");
}

/// A run of `steps` under a space-fixed in-plane force at the rim: the
/// Lagrangian amplitudes at every step.
fn loaded_run(
    speed: f64,
    rate_hz: f64,
    steps: usize,
    coordinates: Coordinates,
    integrator: IntegratorKind,
) -> Vec<Vec<f64>> {
    let mut c = disc(&[0, 1, 2], &[0, 1], speed, rate_hz);
    c.plate.damping = vec![0.02];
    c.simulation.coordinates = coordinates;
    c.simulation.integrator = integrator;
    // One RK4 step per output step (h·λ_max ≈ 0.4 at 500 kHz), so the rate sets RK4's step.
    c.simulation.rk4_step_limit = 2.0;
    c.nodes.ale.push(NodePosition {
        radial: 1.0,
        angular: 0.1,
    });
    c.loads.ale.push(WrenchConfig {
        force: [300.0, -1000.0, 0.0],
        moment: [0.0; 3],
    });
    let mut sim = Simulation::new(c).unwrap();
    (0..steps)
        .map(|_| {
            sim.step().unwrap();
            sim.q_lagrange().to_vec()
        })
        .collect()
}

fn largest(a: &[Vec<f64>]) -> f64 {
    a.iter().flatten().fold(0.0f64, |m, v| m.max(v.abs()))
}

fn worst_difference(a: &[Vec<f64>], b: &[Vec<f64>], every: usize) -> f64 {
    a.iter()
        .zip(b.iter().skip(every - 1).step_by(every))
        .flat_map(|(x, y)| x.iter().zip(y))
        .fold(0.0f64, |m, (x, y)| m.max((x - y).abs()))
}

#[test]
fn ale_and_lagrangian_descriptions_agree_at_speed() {
    let speed = 3000.0;
    let (rate, steps) = (1e6, 2000);
    let ale = loaded_run(
        speed,
        rate,
        steps,
        Coordinates::Ale,
        IntegratorKind::Exponential,
    );
    let lagrange = loaded_run(
        speed,
        rate,
        steps,
        Coordinates::Lagrangian,
        IntegratorKind::Exponential,
    );
    let rk4_ale = loaded_run(speed, rate, steps, Coordinates::Ale, IntegratorKind::Rk4);
    let rk4 = loaded_run(
        speed,
        rate,
        steps,
        Coordinates::Lagrangian,
        IntegratorKind::Rk4,
    );
    let scale = largest(&lagrange);
    let d_exp = worst_difference(&ale, &lagrange, 1) / scale;
    // RK4 integrates the ALE equations themselves (the spin terms with q̄̇ − kΩJq̄).
    let d_rk4 = worst_difference(&rk4_ale, &rk4, 1) / scale;
    println!("Ω {speed} rad/s, largest amplitude {scale:.3e} m: exponential ALE vs Lagrangian {d_exp:.2e}, RK4 ALE vs Lagrangian {d_rk4:.2e}");
    assert!(scale > 1e-9);
    assert!(d_exp < 1e-9, "{d_exp:e}");
    assert!(d_rk4 < 1e-6, "{d_rk4:e}");
}

#[test]
fn rk4_converges_to_the_exponential_step_at_fourth_order() {
    let speed = 3000.0;
    let (rate, steps) = (5e5, 1000);
    let exact = loaded_run(
        speed,
        rate,
        steps,
        Coordinates::Lagrangian,
        IntegratorKind::Exponential,
    );
    let scale = largest(&exact);
    let error = |refine: usize| {
        let rk4 = loaded_run(
            speed,
            rate * refine as f64,
            steps * refine,
            Coordinates::Lagrangian,
            IntegratorKind::Rk4,
        );
        worst_difference(&exact, &rk4, refine) / scale
    };
    let (e1, e2) = (error(1), error(2));
    println!("Ω {speed} rad/s: RK4 against exponential {e1:.2e} at {rate} Hz, {e2:.2e} at twice the rate (ratio {:.1})", e1 / e2);
    assert!(e2 < 1e-4, "{e2:e}");
    assert!(e1 / e2 > 12.0 && e1 / e2 < 20.0, "ratio {}", e1 / e2);
}

/// The disc with bending k = 0, 2 × l = 0, 1 (G_k couples the l of one k),
/// in-plane modes `k` (orders 0, 1), centrifugal stiffening `stiffening`, at
/// 1000 rad/s under a held rim force with radial, tangential and axial
/// parts: the Lagrangian amplitudes of 400 steps at 20 kHz.
fn stiffened_run(k: &[u32], stiffening: bool, integrator: IntegratorKind) -> Vec<Vec<f64>> {
    let mut c = disc(k, &[0, 1], 1000.0, 20_000.0);
    c.plate.nodal_diameters = vec![0, 2];
    c.plate.nodal_circles = vec![0, 1];
    c.plate.damping = vec![0.02];
    c.centrifugal.stiffening = stiffening;
    c.simulation.integrator = integrator;
    c.simulation.rk4_step_limit = 0.01;
    c.nodes.ale.push(NodePosition {
        radial: 1.0,
        angular: 0.1,
    });
    c.loads.ale.push(WrenchConfig {
        force: [300.0, -1000.0, 200.0],
        moment: [0.0; 3],
    });
    let mut sim = Simulation::new(c).unwrap();
    (0..400)
        .map(|_| {
            sim.step().unwrap();
            sim.q_lagrange().to_vec()
        })
        .collect()
}

/// The largest difference over `modes` of two runs, and the largest |b| there.
fn worst_over(a: &[Vec<f64>], b: &[Vec<f64>], modes: std::ops::Range<usize>) -> (f64, f64) {
    let pick = |r: &Vec<f64>| r[modes.clone()].to_vec();
    let (a, b): (Vec<_>, Vec<_>) = (a.iter().map(pick).collect(), b.iter().map(pick).collect());
    (worst_difference(&a, &b, 1), largest(&b))
}

/// Centrifugal stiffening beside the in-plane modes: the bending modes
/// stiffen (their G_k), the in-plane modes keep their spin terms, which
/// already carry the prestress. On the exponential step the bending
/// amplitudes equal those without in-plane modes and the in-plane ones
/// those without stiffening, bit for bit; RK4 (its own equations, stage by
/// stage) agrees with both together within 1e-6 of the largest; the
/// stiffening moves the bending by more than 1 %.
#[test]
fn centrifugal_stiffening_acts_on_the_bending_beside_the_in_plane_modes() {
    let exp = IntegratorKind::Exponential;
    let both = stiffened_run(&[0, 1], true, exp);
    let bending_only = stiffened_run(&[], true, exp);
    let unstiffened = stiffened_run(&[0, 1], false, exp);
    let rk4 = stiffened_run(&[0, 1], true, IntegratorKind::Rk4);
    let (n, all) = (bending_only[0].len(), both[0].len());
    let (bending, bending_peak) = worst_over(&both, &bending_only, 0..n);
    let (in_plane, in_plane_peak) = worst_over(&both, &unstiffened, n..all);
    let (stiffened, _) = worst_over(&both, &unstiffened, 0..n);
    let rk4_error = worst_difference(&rk4, &both, 1) / largest(&both);
    println!(
        "bending {bending:e} of {bending_peak:.3e} m; in-plane {in_plane:e} of {in_plane_peak:.3e} m; \
         the stiffening moves the bending by {:.2e} of it; RK4 against exponential {rk4_error:.2e}",
        stiffened / bending_peak
    );
    assert!(bending_peak > 1e-9 && in_plane_peak > 1e-10);
    assert_eq!(bending, 0.0);
    assert_eq!(in_plane, 0.0);
    assert!(stiffened > 1e-2 * bending_peak, "{stiffened:e}");
    assert!(rk4_error < 1e-6, "{rk4_error:e}");
}

/// The stiffened implicit midpoint rule steps the bending blocks only:
/// refused with in-plane modes, naming the key.
#[test]
fn stiffening_with_in_plane_modes_on_the_implicit_midpoint_rule_is_refused() {
    let mut c = disc(&[1], &[0], 10.0, 1e4);
    c.centrifugal.stiffening = true;
    c.simulation.integrator = IntegratorKind::ImplicitMidpoint;
    let message = Simulation::new(c).err().expect("refused").to_string();
    assert!(
        message.contains("plate.centrifugal_stiffening"),
        "{message}"
    );
}

/// RK4's inner step resolves the spinning in-plane modes: h_inner times
/// the largest turning-frame frequency of the retained modes (read from
/// the exponential step's map, which the collocation test above checks)
/// stays within `simulation.rk4_step_limit`, at speeds where the Coriolis
/// coupling splits the waves by up to 2Ω.
#[test]
fn rk4_inner_steps_resolve_the_spinning_in_plane_frequencies() {
    for speed in [3000.0, 9000.0] {
        let exp = disc(&[0, 1, 2], &[0, 1, 2], speed, 1e6);
        let fastest = [0, 1, 2]
            .iter()
            .flat_map(|&k| stepped_frequencies(&exp, k))
            .fold(0.0f64, f64::max);
        let mut rk4 = disc(&[0, 1, 2], &[0, 1, 2], speed, 1e4);
        rk4.simulation.integrator = IntegratorKind::Rk4;
        let limit = rk4.simulation.rk4_step_limit;
        let mut sim = Simulation::new(rk4).unwrap();
        sim.step().unwrap();
        let h_inner = sim.dt() / sim.inner_substeps() as f64;
        println!(
            "Ω {speed} rad/s: fastest turning-frame frequency {fastest:.1} rad/s, {} inner steps: h·ω = {:.4} (limit {limit})",
            sim.inner_substeps(),
            h_inner * fastest
        );
        assert!(h_inner * fastest <= limit, "{}", h_inner * fastest);
    }
}

#[test]
fn the_implicit_midpoint_rule_is_refused_at_speed_naming_the_key() {
    let mut c = disc(&[1], &[0], 3000.0, 1e6);
    c.simulation.integrator = IntegratorKind::ImplicitMidpoint;
    let message = Simulation::new(c).err().expect("refused").to_string();
    assert!(message.contains("simulation.integrator"), "{message}");
    assert!(message.contains("joint.speed"), "{message}");
}

#[test]
fn an_in_plane_amplitude_beyond_the_deflection_limit_is_a_divergence() {
    let mut c = disc(&[1], &[0], 3000.0, 1e6);
    c.limits.max_deflection_thicknesses = 1.0;
    c.nodes.lagrange.push(NodePosition {
        radial: 1.0,
        angular: 0.0,
    });
    c.loads.lagrange.push(WrenchConfig {
        force: [1e11, 0.0, 0.0],
        moment: [0.0; 3],
    });
    let mut sim = Simulation::new(c).unwrap();
    let message = (0..200)
        .find_map(|_| sim.step().err())
        .expect("diverged")
        .to_string();
    assert!(
        message.contains("in-plane mode ⟨k = 1, l = 0⟩"),
        "{message}"
    );
}
