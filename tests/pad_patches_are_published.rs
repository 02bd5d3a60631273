//! The lining's patch deflections (`pads.shear_stiffness`; docs/scenes.md,
//! "Pad shear") are outputs of the pads, per contact point: the declared
//! channels that ~/pad_states, its bags and the CSV's `contact{c}_patch_*`
//! columns carry are the patch states of the `State` (which count from steady
//! sliding, x_θ = μ N₀/(n k_t), added here), and each face's speed
//! relative to its patch is `contact{c}_slip_*`. At steady sliding the
//! tangential patch carries the friction, k_t x_θ = μ N₀/n. Without the keys
//! the channels are empty and the CSV has no contact columns.

mod support;

use annular_plate::config::{Config, Params};
use annular_plate::dynamics::load_models::pad::{Pads, FRICTION_REGULARISATION_SPEED};
use annular_plate::dynamics::load_models::pad_config::PadsConfig;
use annular_plate::dynamics::load_models::pad_outputs::PadOutputs;
use annular_plate::dynamics::Simulation;
use support::scene_files;

const K_T: f64 = 1.07e6;
const C_T: f64 = 11.2;

/// The overrides (`key`, `value`) of a scene on RK4 with or without the
/// lining's patches.
fn overrides(shear: bool) -> Vec<(&'static str, String)> {
    let mut o = vec![("simulation.integrator", "rk4".to_string())];
    if shear {
        o.push(("pads.shear_stiffness", K_T.to_string()));
        o.push(("pads.shear_damping", C_T.to_string()));
    }
    o
}

fn config(file: &str, shear: bool) -> Config {
    let mut params = Params::from_file(&scene_files::path(file), scene_files::NODE).unwrap();
    for (k, v) in overrides(shear) {
        params.set_override(k, &v).unwrap();
    }
    Config::from_params(&params).unwrap()
}

/// The channel `name` of the pads at the current state.
fn channel<'a>(sim: &'a Simulation, name: &str) -> &'a [f64] {
    sim.find_channel("pads", name)
        .unwrap_or_else(|| panic!("the pads declare {name}"))
}

const PATCHES: [&str; 4] = [
    "contact_patch_top_radial",
    "contact_patch_top_tangential",
    "contact_patch_bottom_radial",
    "contact_patch_bottom_tangential",
];

/// Steady sliding under the initial clamp force at the initial speed:
/// x_θ = μ (N₀/n) τ(Ω r)/k_t, m (every contact on one radius and pad).
fn steady_sliding(c: &Config) -> f64 {
    let pads = c.section::<PadsConfig>().unwrap();
    let n = pads.contacts.len() as f64;
    let r = Simulation::new(c.clone()).unwrap().scene().ale_nodes[0].radius;
    pads.friction_coefficient * (pads.clamp_force[0] / n) / K_T
        * (c.joint.speed * r / FRICTION_REGULARISATION_SPEED).tanh()
}

/// The deflections of contact `c` from the State: its patch states, which
/// count from steady sliding (docs/scenes.md, "Pad shear").
fn state_patches(sim: &Simulation, c: usize) -> [f64; 4] {
    let (model, pads) = sim.scene().load_models.find::<Pads>().unwrap();
    let slot = &sim.state().load_models.slots[model][pads.pad_states()..];
    assert_eq!(slot.len(), pads.patch_states());
    let x0 = steady_sliding(sim.config());
    [
        slot[4 * c],
        slot[4 * c + 1] + x0,
        slot[4 * c + 2],
        slot[4 * c + 3] + x0,
    ]
}

fn close(a: f64, b: f64, scale: f64) -> bool {
    (a - b).abs() <= 1e-12 * scale
}

#[test]
fn at_steady_sliding_each_tangential_patch_carries_mu_n_over_k_t() {
    let mut c = config("brake_squeal.yaml", true);
    c.initial.q.iter_mut().for_each(|q| *q = 0.0);
    let mut sim = Simulation::new(c.clone()).unwrap();
    for _ in 0..50 {
        sim.step().unwrap();
    }
    let v = c.joint.speed * sim.scene().ale_nodes[0].radius;
    let tangential = steady_sliding(&c);
    for (k, name) in PATCHES.iter().enumerate() {
        let expected = if k % 2 == 1 { tangential } else { 0.0 };
        for (c, x) in channel(&sim, name).iter().enumerate() {
            assert!(
                (x - expected).abs() < 1e-9 * tangential,
                "{name}[{c}] = {x} m, steady sliding {expected} m"
            );
        }
    }
    for face in ["contact_slip_top", "contact_slip_bottom"] {
        for s in channel(&sim, face) {
            assert!((s - v).abs() < 1e-9 * v, "{face}: {s} vs V = {v} m/s");
        }
    }
    println!("x_θ = {tangential:.6e} m (μ N₀/(n k_t)), slip {v} m/s");
}

#[test]
fn the_published_deflections_are_the_states_and_empty_without_the_keys() {
    let mut sim = Simulation::new(config("brake_squeal.yaml", true)).unwrap();
    for _ in 0..200 {
        sim.step().unwrap();
    }
    let n = sim.scene().ale_nodes.len();
    let x0 = steady_sliding(sim.config());
    let mut moved = 0.0f64;
    for (k, name) in PATCHES.iter().enumerate() {
        let values = channel(&sim, name);
        assert_eq!(values.len(), n, "{name}: one per contact point");
        for (c, x) in values.iter().enumerate() {
            let state = state_patches(&sim, c)[k];
            assert!(close(*x, state, x0), "{name}[{c}]: {x} vs {state}");
            assert_eq!(*x, sim.pad_patch_deflections()[c][k], "{name}[{c}]");
        }
        if k == 0 {
            moved = values.iter().fold(0.0, |a, x| a.max(x.abs()));
        }
    }
    assert!(
        moved > 1e-6 * x0,
        "the vibration moves the patches radially"
    );
    assert_eq!(sim.pad_patch_deflections().len(), n);
    for file in ["brake_squeal_paper.yaml", "brake_bench.yaml"] {
        let rigid = Simulation::new(config(file, false)).unwrap();
        assert!(rigid
            .config()
            .section::<PadsConfig>()
            .unwrap()
            .shear
            .is_none());
        for name in PATCHES
            .iter()
            .chain(&["contact_slip_top", "contact_slip_bottom"])
        {
            assert!(channel(&rigid, name).is_empty(), "{file}: {name}");
        }
        assert!(rigid.pad_patch_deflections().is_empty());
    }
}

/// `simulate --csv -` on the scene with `overrides`: header and last row.
fn simulate(file: &str, shear: bool, duration: f64) -> (Vec<String>, Vec<f64>) {
    let mut args: Vec<String> = [
        "simulate",
        scene_files::path(file).to_str().unwrap(),
        "--duration",
        &duration.to_string(),
        "--csv",
        "-",
        "--quiet",
    ]
    .map(String::from)
    .to_vec();
    for (k, v) in overrides(shear) {
        args.extend(["-p".to_string(), format!("{k}:={v}")]);
    }
    let args: Vec<&str> = args.iter().map(String::as_str).collect();
    let (ok, out, err) = support::cli::run(&args);
    assert!(ok, "{err}");
    let mut lines = out.lines();
    let header = lines.next().unwrap().split(',').map(String::from).collect();
    let last = lines
        .last()
        .unwrap()
        .split(',')
        .map(|v| v.parse().unwrap())
        .collect();
    (header, last)
}

#[test]
fn the_csv_columns_hold_the_states_patches_per_contact_point() {
    let mut sim = Simulation::new(config("brake_squeal.yaml", true)).unwrap();
    let steps = 100;
    for _ in 0..steps {
        sim.step().unwrap();
    }
    let (header, row) = simulate("brake_squeal.yaml", true, steps as f64 * sim.dt());
    assert_eq!(row[0], sim.time(), "the same steps");
    let n = sim.scene().ale_nodes.len();
    let x0 = steady_sliding(sim.config());
    let column = |name: &str| -> f64 {
        let i = header.iter().position(|h| h == name);
        row[i.unwrap_or_else(|| panic!("no column {name}"))]
    };
    let quantities = PATCHES.map(|p| p.strip_prefix("contact_").unwrap());
    for c in 0..n {
        for (k, q) in quantities.iter().enumerate() {
            let name = format!("contact{}_{q}", c + 1);
            let state = state_patches(&sim, c)[k];
            assert!(
                close(column(&name), state, x0),
                "{name}: {} vs {state}",
                column(&name)
            );
            assert_eq!(column(&name), channel(&sim, PATCHES[k])[c], "{name}");
        }
        for (face, q) in ["contact_slip_top", "contact_slip_bottom"]
            .iter()
            .enumerate()
        {
            let name = format!("contact{}_{}", c + 1, &q["contact_".len()..]);
            assert_eq!(column(&name), channel(&sim, q)[c], "{name} (face {face})");
        }
    }
    assert_eq!(
        header.iter().filter(|h| h.starts_with("contact")).count(),
        6 * n
    );
    let (rigid, _) = simulate("brake_squeal_paper.yaml", false, 0.001);
    assert!(!rigid.iter().any(|h| h.starts_with("contact")), "{rigid:?}");
}
