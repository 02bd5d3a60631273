//! In-plane (plane-stress) modes of the annulus (docs/in_plane.md): the
//! library's frequencies against the exact solution written in
//! `tests/support/in_plane_exact.rs` (Helmholtz potentials, J_k/Y_k of the
//! dilatational and shear wave numbers, the 4×4 edge determinant, k = 0's
//! torsional and radial 2×2 ones) for the four edge pairs, k = 0..8, three
//! orders; the exact solver against the torsional closed form and the
//! brake bench disc's frequencies quoted in the project's plan; the modal mass and
//! normalisation; `modes` listing them; every command that would put them
//! into the dynamics refusing them; the keys' rules; the spin prestress
//! with a fixed rim.

mod support;

use annular_plate::config::{CentrifugalConfig, Config, InPlaneInner, InPlaneOuter};
use annular_plate::model::in_plane::{
    InPlaneDiscretisation, InPlaneEdge, InPlaneFamily, InPlanePlate, InPlaneShape, DEFAULT_SPLINES,
};
use annular_plate::model::prestress::LamePrestress;
use support::cli::run;
use support::in_plane_exact::{torsional_fixed_free_beta, Annulus, Edge, Family};

const BENCH: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/config/brake_bench.yaml");
const ORDERS: usize = 3;
const K_MAX: u32 = 8;
const TOLERANCE: f64 = 1e-6;

/// Steel (E 2.1e11, ν 0.3, ρ 7850), 18.1 mm thick, between r_i and r_a.
fn plate(ri: f64, ra: f64, inner: InPlaneEdge, outer: InPlaneEdge) -> InPlanePlate {
    InPlanePlate {
        youngs_modulus: 2.1e11,
        poisson_ratio: 0.3,
        density: 7850.0,
        thickness: 0.0181,
        inner_radius: ri,
        outer_radius: ra,
        inner_edge: inner,
        outer_edge: outer,
    }
}

fn exact_edge(e: InPlaneEdge) -> Edge {
    match e {
        InPlaneEdge::Fixed => Edge::Fixed,
        InPlaneEdge::Free => Edge::Free,
    }
}

/// The same annulus for the exact solution, written out from the plate.
fn annulus(p: &InPlanePlate) -> Annulus {
    Annulus {
        youngs_modulus: p.youngs_modulus,
        poisson_ratio: p.poisson_ratio,
        density: p.density,
        inner_radius: p.inner_radius,
        outer_radius: p.outer_radius,
        inner: exact_edge(p.inner_edge),
        outer: exact_edge(p.outer_edge),
    }
}

fn exact_family(f: InPlaneFamily) -> Family {
    match f {
        InPlaneFamily::Torsional => Family::Torsional,
        InPlaneFamily::Radial => Family::Radial,
        InPlaneFamily::Coupled => Family::Coupled,
    }
}

const EDGE_PAIRS: [(InPlaneEdge, InPlaneEdge); 4] = [
    (InPlaneEdge::Fixed, InPlaneEdge::Free),
    (InPlaneEdge::Free, InPlaneEdge::Free),
    (InPlaneEdge::Fixed, InPlaneEdge::Fixed),
    (InPlaneEdge::Free, InPlaneEdge::Fixed),
];

/// The bench disc (r_i/r_a = 0.46) and a wide annulus (r_i/r_a = 0.2).
const GEOMETRIES: [(f64, f64); 2] = [(0.07, 0.153), (0.03, 0.15)];

/// The largest relative deviation of the first `ORDERS` elastic ω of every
/// k ≤ K_MAX and family from the exact roots, on `splines` per field, with
/// where it is.
fn worst_deviation(p: &InPlanePlate, exact: &[Vec<Vec<f64>>], splines: usize) -> (f64, String) {
    let disc = InPlaneDiscretisation::new(p, splines).unwrap();
    let mut worst = (0.0, String::new());
    for k in 0..=K_MAX {
        for (fi, &family) in InPlaneFamily::of(k).iter().enumerate() {
            let rigid = p.is_rigid_body(k, family, 0) as usize;
            let modes = disc.modes(k, family, ORDERS + rigid).unwrap();
            assert_eq!(modes.len(), ORDERS, "k = {k}: the rigid-body mode left out");
            for (m, &w) in modes.iter().zip(&exact[k as usize][fi]) {
                let e = (m.omega - w).abs() / w;
                if e > worst.0 {
                    worst = (e, format!("k = {k} {} l = {}", family.name(), m.l));
                }
            }
        }
    }
    worst
}

/// The exact roots per k and family (index as `InPlaneFamily::of(k)`).
fn exact_roots(p: &InPlanePlate) -> Vec<Vec<Vec<f64>>> {
    let a = annulus(p);
    (0..=K_MAX)
        .map(|k| {
            InPlaneFamily::of(k)
                .iter()
                .map(|&f| a.roots(k, exact_family(f), ORDERS, 40))
                .collect()
        })
        .collect()
}

#[test]
fn frequencies_match_the_exact_plane_stress_solution() {
    let mut overall: f64 = 0.0;
    for (ri, ra) in GEOMETRIES {
        for (inner, outer) in EDGE_PAIRS {
            let p = plate(ri, ra, inner, outer);
            let exact = exact_roots(&p);
            let (worst, at) = worst_deviation(&p, &exact, DEFAULT_SPLINES);
            println!(
                "r_i/r_a = {:.3}, {}–{}: worst {worst:.2e} at {at} ({DEFAULT_SPLINES} splines)",
                ri / ra,
                inner.name(),
                outer.name()
            );
            assert!(
                worst < TOLERANCE,
                "{}–{}: {worst:e} at {at}",
                inner.name(),
                outer.name()
            );
            overall = overall.max(worst);
        }
    }
    println!("worst over all: {overall:.2e}");
}

/// The frequencies converge as the sixth power of the spline spacing: the
/// worst deviation over both geometries and the four edge pairs per spline
/// count falls by at least 2⁵ per doubling of the count; the count that
/// first meets 1e-6 is printed (docs/in_plane.md).
#[test]
fn the_error_falls_with_the_sixth_power_of_the_spline_spacing() {
    let cases: Vec<(InPlanePlate, Vec<Vec<Vec<f64>>>)> = GEOMETRIES
        .iter()
        .flat_map(|&(ri, ra)| EDGE_PAIRS.map(|(i, o)| plate(ri, ra, i, o)))
        .map(|p| (p, exact_roots(&p)))
        .collect();
    let counts = [15, 20, 25, 30, 40, 60];
    let errors: Vec<f64> = counts
        .iter()
        .map(|&n| {
            cases
                .iter()
                .map(|(p, exact)| worst_deviation(p, exact, n).0)
                .fold(0.0, f64::max)
        })
        .collect();
    for (n, e) in counts.iter().zip(&errors) {
        println!("{n} splines per field: worst {e:.2e}");
    }
    let enough = counts.iter().zip(&errors).find(|(_, &e)| e < TOLERANCE);
    println!(
        "fewest of these counts meeting {TOLERANCE:e}: {:?}",
        enough.map(|c| c.0)
    );
    for (a, b) in [(0, 3), (3, 5)] {
        let order = (errors[a] / errors[b]).log2() / (counts[b] as f64 / counts[a] as f64).log2();
        println!("observed order {} → {}: {order:.2}", counts[a], counts[b]);
        assert!(order > 5.0, "{errors:?}");
    }
}

/// The exact solver's torsional family against the closed form
/// J₁(βr_i) Y₂(βr_a) − Y₁(βr_i) J₂(βr_a) = 0 (fixed hub, free rim), and the
/// bench disc's frequencies quoted in the project's plan: first torsional
/// 5.68 kHz, first k = 1 and k = 2 modes 8.01 and 11.98 kHz.
#[test]
fn the_exact_solver_meets_the_torsional_closed_form_and_the_bench_disc() {
    let p = plate(0.07, 0.153, InPlaneEdge::Fixed, InPlaneEdge::Free);
    let a = annulus(&p);
    let g = p.shear_modulus();
    let torsional = a.roots(0, Family::Torsional, 3, 40);
    for (order, w) in torsional.iter().enumerate() {
        let beta = torsional_fixed_free_beta(0.07, 0.153, order);
        let closed = beta * (g / p.density).sqrt();
        let e = (w - closed).abs() / closed;
        println!(
            "torsional l = {order}: {:.3} Hz, closed form {:.3} Hz ({e:.1e})",
            w / std::f64::consts::TAU,
            closed / std::f64::consts::TAU
        );
        assert!(e < 1e-12, "{e:e}");
    }
    let hz = |w: f64| w / std::f64::consts::TAU;
    let published = [
        (hz(torsional[0]), 5680.0),
        (hz(a.roots(1, Family::Coupled, 1, 40)[0]), 8010.0),
        (hz(a.roots(2, Family::Coupled, 1, 40)[0]), 11980.0),
    ];
    for (f, kilohertz) in published {
        println!("{f:.1} Hz against {kilohertz} Hz (to 10 Hz)");
        assert!((f - kilohertz).abs() <= 5.0, "{f} against {kilohertz}");
    }
}

/// max(|U|, |V|) = 1, positive at the peak; the modal mass is
/// c_k ∫ ρh (U² + V²) r dr by a midpoint sum of the shapes; the fixed edges
/// hold U = V = 0.
#[test]
fn modal_mass_and_normalisation_follow_the_shapes() {
    for (inner, outer) in EDGE_PAIRS {
        let p = plate(0.07, 0.153, inner, outer);
        let disc = InPlaneDiscretisation::new(&p, DEFAULT_SPLINES).unwrap();
        for k in [0, 1, 2, 5] {
            for &family in InPlaneFamily::of(k) {
                for m in disc.modes(k, family, 4).unwrap() {
                    let cells = 20_000;
                    let dr = (p.outer_radius - p.inner_radius) / cells as f64;
                    let (mut mass, mut peak) = (0.0, 0.0f64);
                    let mut signed = 0.0;
                    for i in 0..=cells {
                        let r = p.inner_radius + i as f64 * dr;
                        let v = m.eval(r);
                        for x in [v.u, v.v] {
                            if x.abs() > peak.abs() {
                                peak = x.abs();
                                signed = x;
                            }
                        }
                        if i < cells {
                            let v = m.eval(r + 0.5 * dr);
                            mass += (v.u * v.u + v.v * v.v) * (r + 0.5 * dr) * dr;
                        }
                    }
                    let ck = if k == 0 {
                        std::f64::consts::TAU
                    } else {
                        std::f64::consts::PI
                    };
                    mass *= ck * p.density * p.thickness;
                    let e = (mass - m.modal_mass).abs() / m.modal_mass;
                    assert!(e < 1e-6, "k = {k} l = {}: {e:e}", m.l);
                    assert!((peak - 1.0).abs() < 1e-6 && signed > 0.0, "peak {signed}");
                    for (r, edge) in [(p.inner_radius, inner), (p.outer_radius, outer)] {
                        if edge == InPlaneEdge::Fixed {
                            let v = m.eval(r);
                            assert!(v.u.abs() < 1e-12 && v.v.abs() < 1e-12, "{v:?}");
                        }
                    }
                }
            }
        }
    }
}

/// The sin partner is the cos partner turned by a quarter wave π/(2k):
/// (u_r, u_θ) of `sin` at θ equal those of `cos` at θ − π/(2k).
#[test]
fn the_sin_partner_is_the_cos_partner_turned_by_a_quarter_wave() {
    for k in 1..=8u32 {
        let turn = std::f64::consts::PI / (2.0 * k as f64);
        for i in 0..24 {
            let theta = i as f64 * std::f64::consts::TAU / 24.0;
            let sin = InPlaneShape::Sin.angular(k, theta);
            let cos = InPlaneShape::Cos.angular(k, theta - turn);
            assert!((sin.0 - cos.0).abs() < 1e-12 && (sin.1 - cos.1).abs() < 1e-12);
        }
    }
    assert_eq!(InPlaneShape::Torsional.angular(0, 1.0), (0.0, 1.0));
    assert_eq!(InPlaneShape::Radial.angular(0, 1.0), (1.0, 0.0));
}

fn modes_json(extra: &[&str]) -> serde_json::Value {
    let mut args = vec!["modes", BENCH, "--json"];
    args.extend(extra);
    let (ok, out, err) = run(&args);
    assert!(ok, "{err}");
    serde_json::from_str(&out).unwrap()
}

/// `modes --json` of the bench scene with in-plane k = 0, 1, 2: its bending
/// entries are those without the key; its in-plane entries (`"family":
/// "in_plane"`, shapes torsional/radial/cos/sin) are the exact roots of
/// the fixed–free annulus (`plate.in_plane_inner: auto` fixes the hub of a
/// supported disc) within 1e-6.
#[test]
fn modes_lists_the_in_plane_modes_beside_the_bending_ones() {
    let plain = modes_json(&[]);
    assert!(plain.get("in_plane").is_none());
    let with = modes_json(&["-p", "plate.in_plane_nodal_diameters:=[0, 1, 2]"]);
    let entries = with["modes"].as_array().unwrap();
    let bending: Vec<_> = entries
        .iter()
        .filter(|m| m["family"] == "bending")
        .collect();
    let plain_modes: Vec<_> = plain["modes"].as_array().unwrap().iter().collect();
    assert_eq!(bending, plain_modes, "the bending entries are unchanged");
    assert!(plain_modes.iter().all(|m| m["family"] == "bending"));
    assert_eq!(with["in_plane"]["inner_edge"], "fixed");
    assert_eq!(with["in_plane"]["outer_edge"], "free");
    let in_plane: Vec<_> = entries
        .iter()
        .filter(|m| m["family"] == "in_plane")
        .collect();
    // k = 0: torsional and radial, 3 orders each; k = 1, 2: cos and sin, 3 orders.
    assert_eq!(in_plane.len(), 6 + 12);
    let a = annulus(&plate(0.07, 0.153, InPlaneEdge::Fixed, InPlaneEdge::Free));
    let mut worst: f64 = 0.0;
    for m in in_plane {
        let (k, l) = (
            m["k"].as_u64().unwrap() as u32,
            m["l"].as_u64().unwrap() as usize,
        );
        let family = match m["shape"].as_str().unwrap() {
            "torsional" => Family::Torsional,
            "radial" => Family::Radial,
            "cos" | "sin" => Family::Coupled,
            other => panic!("shape {other}"),
        };
        assert_eq!(k == 0, family != Family::Coupled);
        let exact = a.roots(k, family, l + 1, 40)[l] / std::f64::consts::TAU;
        let f = m["frequency_hz"].as_f64().unwrap();
        worst = worst.max((f - exact).abs() / exact);
        assert!(m["modal_mass_kg"].as_f64().unwrap() > 0.0);
        assert!(m.get("damping").is_none());
    }
    println!("modes --json in-plane entries against the exact roots: worst {worst:.2e}");
    assert!(worst < TOLERANCE);
    let (ok, text, err) = run(&["modes", BENCH, "-p", "plate.in_plane_nodal_diameters:=[0]"]);
    assert!(ok, "{err}");
    assert!(
        text.contains("in-plane (plane stress) modes") && text.contains("torsional"),
        "{text}"
    );
}

/// A free–free annulus's rigid rotation and translations are left out and
/// reported, as the bending table's rigid modes are.
#[test]
fn modes_leaves_out_the_rigid_in_plane_motions_of_a_free_annulus() {
    let with = modes_json(&[
        "-p",
        "plate.in_plane_nodal_diameters:=[0, 1]",
        "-p",
        "plate.in_plane_inner:=free",
    ]);
    let skipped = &with["in_plane"]["skipped_rigid_body_modes"];
    assert_eq!(
        skipped,
        &serde_json::json!([[0, 0, "torsional"], [1, 0, "coupled"]])
    );
    let a = annulus(&plate(0.07, 0.153, InPlaneEdge::Free, InPlaneEdge::Free));
    let first_torsional = with["modes"]
        .as_array()
        .unwrap()
        .iter()
        .find(|m| m["shape"] == "torsional")
        .unwrap();
    assert_eq!(first_torsional["l"], 1);
    let exact = a.roots(0, Family::Torsional, 1, 40)[0] / std::f64::consts::TAU;
    let f = first_torsional["frequency_hz"].as_f64().unwrap();
    assert!((f - exact).abs() / exact < TOLERANCE, "{f} against {exact}");
}

/// simulate and the node refuse the bench scene with in-plane modes (its
/// torque-limited drive with the torsional modes and its pads on
/// `contact_exponential`), naming the key, before any work and writing
/// nothing.
#[test]
fn the_commands_that_would_simulate_refuse_in_plane_modes() {
    let dir = support::cli::scratch_dir("in_plane_refusals");
    let csv = dir.join("out.csv");
    let commands: Vec<(&str, Vec<&str>)> = vec![(
        "simulate",
        vec![
            "simulate",
            BENCH,
            "--duration",
            "0.01",
            "--csv",
            csv.to_str().unwrap(),
        ],
    )];
    for (name, mut args) in commands {
        args.extend(["-p", "plate.in_plane_nodal_diameters:=[0]"]);
        // `study` and `plot` refuse Mindlin plates first (docs/mindlin.md); the
        // bench file ships Mindlin theory.
        args.extend(["-p", "plate.theory:=kirchhoff"]);
        let started = std::time::Instant::now();
        let (ok, out, stderr) = run(&args);
        assert!(!ok, "{name} accepted in-plane modes");
        assert!(
            stderr.contains("plate.in_plane_nodal_diameters"),
            "{name}: {stderr}"
        );
        // The bench's torque-limited drive with a torsional mode and its
        // pads on contact_exponential.
        let why = "joint.max_torque";
        assert!(stderr.contains(why), "{name}: {stderr}");
        assert!(!stderr.contains("panicked"), "{name}: {stderr}");
        assert!(out.is_empty(), "{name} wrote {out}");
        println!(
            "{name} ({:.2} s): {}",
            started.elapsed().as_secs_f64(),
            stderr.lines().last().unwrap_or("")
        );
    }
    assert!(!csv.exists(), "{} was written", csv.display());
    let _ = std::fs::remove_dir_all(&dir);
}

/// The node refuses the bench scene with in-plane modes (its torque-limited
/// drive with the torsional modes and its pads on `contact_exponential`),
/// naming the key.
#[test]
fn the_node_refuses_the_bench_scene_with_in_plane_modes() {
    let mut child = std::process::Command::new(support::cli::BIN)
        .args([
            "run",
            BENCH,
            "--ros-args",
            "-p",
            "plate.in_plane_nodal_diameters:=[0]",
        ])
        .stdout(std::process::Stdio::null())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .unwrap();
    let deadline = std::time::Instant::now() + std::time::Duration::from_secs(60);
    let status = loop {
        if let Some(s) = child.try_wait().unwrap() {
            break s;
        }
        if std::time::Instant::now() > deadline {
            child.kill().unwrap();
            panic!("the node started with in-plane modes");
        }
        std::thread::sleep(std::time::Duration::from_millis(50));
    };
    let mut stderr = String::new();
    std::io::Read::read_to_string(&mut child.stderr.take().unwrap(), &mut stderr).unwrap();
    assert!(!status.success());
    assert!(
        stderr.contains("plate.in_plane_nodal_diameters"),
        "{stderr}"
    );
}

fn config_with(body: &str) -> Result<Config, String> {
    let mut text = String::from("annular_plate:\n  ros__parameters:\n");
    for line in body.lines() {
        text.push_str("    ");
        text.push_str(line);
        text.push('\n');
    }
    Config::from_yaml_str(&text, "annular_plate").map_err(|e| e.to_string())
}

#[test]
fn the_in_plane_keys_have_their_defaults_and_rules() {
    let c = Config::default();
    assert!(c.plate.in_plane_nodal_diameters.is_empty());
    assert_eq!(c.plate.in_plane_orders, vec![0, 1, 2]);
    assert_eq!(c.centrifugal.in_plane_outer, InPlaneOuter::Free);
    let c = config_with("plate.in_plane_nodal_diameters: [3, 0]\nplate.in_plane_orders: [1]\nplate.in_plane_outer: fixed").unwrap();
    assert_eq!(c.plate.in_plane_nodal_diameters, vec![3, 0]);
    assert_eq!(c.plate.in_plane_orders, vec![1]);
    assert_eq!(c.centrifugal.in_plane_outer, InPlaneOuter::Fixed);
    for (body, key) in [
        ("plate.in_plane_outer: auto", "plate.in_plane_outer"),
        ("plate.in_plane_outer: 1", "plate.in_plane_outer"),
        (
            "plate.in_plane_nodal_diameters: [1, 1]",
            "plate.in_plane_nodal_diameters",
        ),
        (
            "plate.in_plane_nodal_diameters: [-1]",
            "plate.in_plane_nodal_diameters",
        ),
        (
            "plate.in_plane_nodal_diameters: [201]",
            "plate.in_plane_nodal_diameters",
        ),
        ("plate.in_plane_orders: []", "plate.in_plane_orders"),
        ("plate.in_plane_orders: [51]", "plate.in_plane_orders"),
        ("plate.in_plane_orders: [0.5]", "plate.in_plane_orders"),
    ] {
        let err = config_with(body).expect_err(body);
        assert!(err.contains(key), "{body}: {err}");
    }
    // Too many orders for the splines: an error naming the keys, no panic.
    let (ok, _, err) = run(&[
        "modes",
        BENCH,
        "-p",
        "plate.in_plane_nodal_diameters:=[0]",
        "-p",
        "plate.in_plane_orders:=[40]",
        "-p",
        "plate.radial_splines:=40",
    ]);
    assert!(
        !ok && err.contains("plate.in_plane_nodal_diameters") && err.contains("orders"),
        "{err}"
    );
}

/// The spin prestress with `plate.in_plane_outer: fixed`: u = 0 at the held
/// rim (and at a fixed hub), and the stresses satisfy the radial equilibrium
/// dσ_r/dr + (σ_r − σ_θ)/r + ρ r = 0 (per unit Ω²), checked by differences.
#[test]
fn the_prestress_holds_a_fixed_rim() {
    let mut c = Config::default();
    for inner in [InPlaneInner::Fixed, InPlaneInner::Free] {
        let edges = CentrifugalConfig {
            stiffening: true,
            in_plane_inner: inner,
            in_plane_outer: InPlaneOuter::Fixed,
        };
        c.centrifugal = edges;
        let lame = LamePrestress::new(&c.plate, &edges);
        let (ri, ra) = (c.plate.inner_radius, c.plate.outer_radius);
        let scale = lame.displacement(0.5 * (ri + ra)).abs();
        assert!(lame.outer_fixed);
        assert!(lame.displacement(ra).abs() < 1e-12 * scale);
        if inner == InPlaneInner::Fixed {
            assert!(lame.displacement(ri).abs() < 1e-12 * scale);
        } else {
            assert!(lame.stresses(ri).0.abs() < 1e-9 * c.plate.density * ra * ra);
        }
        for i in 1..10 {
            let r = ri + (ra - ri) * i as f64 / 10.0;
            let h = 1e-5 * r;
            let dsr = (lame.stresses(r + h).0 - lame.stresses(r - h).0) / (2.0 * h);
            let (sr, st) = lame.stresses(r);
            let residual = dsr + (sr - st) / r + c.plate.density * r;
            assert!(residual.abs() < 1e-6 * c.plate.density * ra, "{residual:e}");
        }
    }
}

/// `plot modes` and `plot mode` draw the bending modes of a scene with
/// in-plane modes, the same bytes as without them (the in-plane shapes are
/// listed by `modes`); `--index` counts the bending modes.
#[test]
fn plot_draws_the_bending_modes_of_a_scene_with_in_plane_modes() {
    let dir = support::cli::scratch_dir("in_plane_plot_modes");
    let scene = concat!(env!("CARGO_MANIFEST_DIR"), "/config/brake_in_plane.yaml");
    let draw = |args: &[&str], name: &str, extra: &[&str]| {
        let out = dir.join(name);
        let mut all: Vec<&str> = args.to_vec();
        all.extend([scene, "--out", out.to_str().unwrap()]);
        all.extend(extra);
        let (ok, _, err) = run(&all);
        assert!(ok, "{err}");
        std::fs::read(&out).unwrap()
    };
    let none = ["-p", "plate.in_plane_nodal_diameters:=[]"];
    for (args, name) in [
        (&["plot", "modes"][..], "grid"),
        (&["plot", "mode", "--index", "9"][..], "mode9"),
    ] {
        let with = draw(args, &format!("{name}_in_plane.png"), &[]);
        let without = draw(args, &format!("{name}_bending.png"), &none);
        assert_eq!(with, without, "{name}");
    }
    let out = dir.join("mode10.png");
    let (ok, _, err) = run(&[
        "plot",
        "mode",
        "--index",
        "10",
        scene,
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(!ok && err.contains("bending modes 1..9"), "{err}");
    let _ = std::fs::remove_dir_all(&dir);
}
