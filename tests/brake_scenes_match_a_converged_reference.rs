//! Experiment harness (to become the accuracy test).
mod support;

use annular_plate::config::Config;
use annular_plate::dynamics::Simulation;
use support::scene_files as scenes;

fn with(file: &str, integrator: &str, extra: &str) -> Config {
    let text = scenes::text(file);
    let text = text.replacen("    joint:\n", "    initial:\n      q: [1.0e-5, 1.0e-5, 0.0, 1.0e-5, 0.0, 1.0e-5, 0.0, 1.0e-5, 0.0]\n    joint:\n", 1);
    let text = if std::env::var("NOFOL").is_ok() {
        text.replacen(
            "lift_off: true",
            "lift_off: true\n      follower_friction: false",
            1,
        )
    } else {
        text
    };
    let text = if std::env::var("NOMU").is_ok() {
        text.replacen("friction_coefficient: 0.4", "friction_coefficient: 0.0", 1)
    } else {
        text
    };
    let text = if std::env::var("NORES").is_ok() {
        text.replacen(
            "damping: [0.005]",
            "damping: [0.005]\n      residual_flexibility: false",
            1,
        )
    } else {
        text
    };
    let text = text.replacen(
        "integrator: rk4",
        &format!("integrator: {integrator}\n      {extra}"),
        1,
    );
    Config::from_yaml_str(&text, scenes::NODE).unwrap()
}

fn run(cfg: Config, steps: usize, clamp: impl Fn(usize) -> f64) -> (Vec<Vec<f64>>, f64) {
    let mut sim = Simulation::new(cfg).unwrap();
    let n = sim.q_ale().len();
    let q0: Vec<f64> = (0..n)
        .map(|i| if i % 2 == 1 { 1e-5 } else { 0.0 })
        .collect();
    let _ = q0;
    let mut out = vec![];
    let t = std::time::Instant::now();
    for s in 0..steps {
        for p in 0..sim.pad_count() {
            sim.set_pad_clamp_force(p, clamp(s)).unwrap();
        }
        if s == 30 && std::env::var("CE").is_ok() {
            std::env::set_var("CE_DEBUG", "1");
        }
        if s == 31 {
            std::env::remove_var("CE_DEBUG");
        }
        let t0 = std::time::Instant::now();
        sim.step().unwrap();
        if sim.contact_report() != Default::default()
            && (s % 10 == 0 || s < 3 || s > 148 && s < 156)
        {
            println!(
                "step {s}: {:?} {:.1} us",
                sim.contact_report(),
                t0.elapsed().as_secs_f64() * 1e6
            );
        }
        let mut row = sim.q_ale().to_vec();
        row.push(sim.joint().velocity);
        out.push(row);
    }
    (out, t.elapsed().as_secs_f64() / steps as f64)
}

#[test]
fn experiment() {
    let clamp = |s: usize| {
        if s < 50 {
            160.0 * s as f64
        } else if s < 150 {
            8000.0
        } else {
            0.0
        }
    };
    let steps = 200;
    let (r, tr) = run(
        with("brake_bench.yaml", "rk4", "rk4_step_limit: 0.0125"),
        steps,
        clamp,
    );
    let (c, tc) = run(
        with("brake_bench.yaml", "contact_exponential", ""),
        steps,
        clamp,
    );
    let (o, to) = run(
        with("brake_bench.yaml", "rk4", "rk4_step_limit: 0.00625"),
        steps,
        clamp,
    );
    let m = r[0].len();
    for i in 0..m {
        let peak = r.iter().map(|x| x[i].abs()).fold(0.0, f64::max);
        let ec = r
            .iter()
            .zip(&c)
            .map(|(a, b)| (a[i] - b[i]).abs())
            .fold(0.0, f64::max);
        let eo = r
            .iter()
            .zip(&o)
            .map(|(a, b)| (a[i] - b[i]).abs())
            .fold(0.0, f64::max);
        println!(
            "{i}: peak {peak:e} contact {:e} rk4 {:e}",
            ec / peak.max(1e-300),
            eo / peak.max(1e-300)
        );
    }
    for s in 0..12 {
        println!(
            "step {s}: err8 {:e} err7 {:e}",
            (r[s][8] - c[s][8]).abs(),
            (r[s][7] - c[s][7]).abs()
        );
    }
    println!("per step: ref {tr:e} contact {tc:e} rk4 {to:e}");
}

#[test]
fn timing() {
    for (name, integ) in [
        ("brake_bench.yaml", "contact_exponential"),
        ("brake_bench.yaml", "rk4"),
    ] {
        let mut sim = Simulation::new(with(name, integ, "")).unwrap();
        for p in 0..sim.pad_count() {
            sim.set_pad_clamp_force(p, 8000.0).unwrap();
        }
        for _ in 0..100 {
            sim.step().unwrap();
        }
        let t = std::time::Instant::now();
        let mut sw = 0;
        let mut b = 0;
        let mut hv = 0;
        for _ in 0..2000 {
            sim.step().unwrap();
            let r = sim.contact_report();
            sw += r.switches;
            b += r.builds;
            hv += r.halvings;
        }
        println!(
            "{name} {integ}: {:.2} us/step switches {sw} builds {b} halvings {hv}",
            t.elapsed().as_secs_f64() / 2000.0 * 1e6
        );
    }
}

fn plain(file: &str, integrator: &str, extra: &str) -> Config {
    let text = scenes::text(file);
    let text = if std::env::var("NOFOL").is_ok() {
        text.replacen("follower_friction: true", "follower_friction: false", 1)
    } else {
        text
    };
    let text = if std::env::var("NOLIFT").is_ok() {
        text.replacen("lift_off: true", "lift_off: false", 1)
    } else {
        text
    };
    let text = if extra.contains("rk4_step_limit") {
        text.replacen("rk4_step_limit: 0.1 ", "rk4_step_limit: 0.2 ", 1)
            .replacen("rk4_step_limit: 0.2 ", &format!("{extra} "), 1)
    } else {
        text
    };
    let extra = if text.contains(extra) { "" } else { extra };
    let text = text.replacen(
        "integrator: rk4",
        &format!("integrator: {integrator}\n      {extra}"),
        1,
    );
    Config::from_yaml_str(&text, scenes::NODE).unwrap()
}

#[test]
fn squeal_scenes() {
    let which = std::env::var("SCENE").unwrap_or("brake_squeal.yaml".into());
    let steps: usize = std::env::var("STEPS")
        .map(|s| s.parse().unwrap())
        .unwrap_or(3000);
    for (file, steps, limit) in [(which.as_str(), steps, "rk4_step_limit: 0.00625")] {
        let mut runs = vec![];
        let tol = std::env::var("TOL").unwrap_or("1e-9".into());
        let ce = format!("contact_tolerance: {tol}");
        for (integ, extra) in [
            ("rk4", limit),
            ("contact_exponential", ce.as_str()),
            ("rk4", ""),
        ] {
            let mut sim = Simulation::new(plain(file, integ, extra)).unwrap();
            let mut out = vec![];
            let t = std::time::Instant::now();
            let (mut sw, mut b, mut hv) = (0, 0, 0);
            for _ in 0..steps {
                sim.step().unwrap();
                let r = sim.contact_report();
                sw += r.switches;
                b += r.builds;
                hv += r.halvings;
                out.push(sim.q_ale().to_vec());
            }
            println!(
                "{file} {integ} {extra}: {:.2} us/step switches {sw} builds {b} halvings {hv}",
                t.elapsed().as_secs_f64() / steps as f64 * 1e6
            );
            runs.push(out);
        }
        let m = runs[0][0].len();
        for i in 0..m {
            let peak = runs[0].iter().map(|x| x[i].abs()).fold(0.0, f64::max);
            let e1 = runs[0]
                .iter()
                .zip(&runs[1])
                .map(|(a, b)| (a[i] - b[i]).abs())
                .fold(0.0, f64::max);
            let e2 = runs[0]
                .iter()
                .zip(&runs[2])
                .map(|(a, b)| (a[i] - b[i]).abs())
                .fold(0.0, f64::max);
            println!(
                "{file} mode {i}: peak {peak:.3e} contact {:.2e} rk4 {:.2e}",
                e1 / peak,
                e2 / peak
            );
        }
    }
}
