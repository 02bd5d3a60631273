//! `annular_plate plot ...` draws what the data says.
//!
//! * The files are valid PNG (decoded) and SVG (parsed as XML) of the requested size.
//! * A time history: every vertex of the curve's SVG polyline, and the PNG
//!   pixels under the data points, sit where the plotted panel maps the CSV values.
//! * Mode shapes: on the rendered raster, a circle around the disc crosses 2k
//!   black nodal lines and 2k red/blue sign changes (k nodal diameters), a radius
//!   crosses l nodal circles and l sign changes — counted on the picture itself.
//! * Bad input (unknown column, unreadable file, wrong extension, missing folder)
//!   gives a message naming it and a non-zero exit.

mod support;

use annular_plate::cli::plot::{self, CsvData, CsvPlot, ModeChoice, Size, TopView, PALETTE};
use annular_plate::config::{Boundary, Config};
use annular_plate::model::AngularShape;
use std::f64::consts::TAU;
use std::path::PathBuf;

fn dir() -> PathBuf {
    support::cli::scratch_dir("plot")
}

fn png(path: &std::path::Path) -> image::RgbImage {
    image::open(path)
        .unwrap_or_else(|e| panic!("{} is not a readable PNG: {e}", path.display()))
        .to_rgb8()
}

fn svg_root_size(path: &std::path::Path) -> (String, (u32, u32)) {
    let text = std::fs::read_to_string(path).unwrap();
    let doc = roxmltree::Document::parse(&text)
        .unwrap_or_else(|e| panic!("{} is not well-formed XML: {e}", path.display()));
    let root = doc.root_element();
    assert_eq!(root.tag_name().name(), "svg");
    let w: u32 = root.attribute("width").unwrap().parse().unwrap();
    let h: u32 = root.attribute("height").unwrap().parse().unwrap();
    drop(doc);
    (text, (w, h))
}

/// A CSV like `simulate` writes: two damped sines of different scale.
/// Each test writes its own copy (tests run in parallel).
fn history_csv(name: &str) -> (PathBuf, Vec<f64>, Vec<f64>, Vec<f64>) {
    let n = 120;
    let t: Vec<f64> = (0..n).map(|i| i as f64 * 1e-3).collect();
    let a: Vec<f64> = t
        .iter()
        .map(|&t| 2e-6 * (-20.0 * t).exp() * (TAU * 25.0 * t).sin())
        .collect();
    let b: Vec<f64> = t
        .iter()
        .map(|&t| -1.5e-6 + 0.4e-6 * (TAU * 10.0 * t).cos())
        .collect();
    let mut text = String::from("time,joint_position,joint_velocity,q1,qale1\n");
    for i in 0..n {
        text.push_str(&format!(
            "{},{},{},{:e},{:e}\n",
            t[i], 0.0, 11.1, a[i], b[i]
        ));
    }
    let p = dir().join(format!("{name}.csv"));
    std::fs::write(&p, text).unwrap();
    (p, t, a, b)
}

#[test]
fn csv_history_svg_polylines_follow_the_data() {
    let (csv, t, a, b) = history_csv("svg_case");
    let data = CsvData::read(&csv).unwrap();
    let out = dir().join("history.svg");
    let size = Size {
        width: 900,
        height: 700,
    };
    let plot = CsvPlot {
        data: &data,
        x: "time",
        panels: vec![vec!["q1".into()], vec!["qale1".into()]],
        ylabels: vec![],
        title: Some("test".into()),
    };
    let panels = plot.render(&out, size).unwrap();
    assert_eq!(panels.len(), 2);
    let (text, dims) = svg_root_size(&out);
    assert_eq!(dims, (900, 700));
    let doc = roxmltree::Document::parse(&text).unwrap();
    let color = format!(
        "#{:02X}{:02X}{:02X}",
        PALETTE[0].0, PALETTE[0].1, PALETTE[0].2
    );
    // The data curves: polylines in the first series colour with a vertex per data point.
    let curves: Vec<Vec<(f64, f64)>> = doc
        .descendants()
        .filter(|n| n.has_tag_name("polyline") && n.attribute("stroke") == Some(color.as_str()))
        .map(|n| {
            n.attribute("points")
                .unwrap()
                .split_whitespace()
                .map(|p| {
                    let (x, y) = p.split_once(',').unwrap();
                    (x.parse().unwrap(), y.parse().unwrap())
                })
                .collect::<Vec<(f64, f64)>>()
        })
        .filter(|v| v.len() == t.len())
        .collect();
    assert_eq!(curves.len(), 2, "one curve per panel");
    let mut worst: f64 = 0.0;
    for (curve, (panel, values)) in curves.iter().zip(panels.iter().zip([&a, &b])) {
        for ((px, py), (ti, vi)) in curve.iter().zip(t.iter().zip(values.iter())) {
            let (ex, ey) = panel.to_px(*ti, *vi);
            worst = worst.max((px - ex).abs()).max((py - ey).abs());
        }
        // and the panel spans the data: the extreme values sit near its top and bottom edges
        let top = curve.iter().map(|p| p.1).fold(f64::INFINITY, f64::min);
        let bottom = curve.iter().map(|p| p.1).fold(0.0, f64::max);
        let height = (panel.y_px.1 - panel.y_px.0) as f64;
        assert!(
            top - panel.y_px.0 as f64 <= 0.06 * height
                && panel.y_px.1 as f64 - bottom <= 0.06 * height,
            "curve fills its panel"
        );
    }
    // plotters rounds each coordinate to a whole pixel
    assert!(
        worst <= 1.0,
        "a vertex is {worst} px from where the data puts it"
    );
}

#[test]
fn csv_history_png_has_the_curve_colour_at_the_data_points() {
    let (csv, t, a, _) = history_csv("png_case");
    let data = CsvData::read(&csv).unwrap();
    let out = dir().join("history.png");
    let size = Size {
        width: 800,
        height: 500,
    };
    let plot = CsvPlot {
        data: &data,
        x: "time",
        panels: vec![vec!["q1".into()]],
        ylabels: vec![],
        title: None,
    };
    let panel = plot.render(&out, size).unwrap().remove(0);
    let img = png(&out);
    assert_eq!(img.dimensions(), (800, 500));
    let c = PALETTE[0];
    let near = |x: f64, y: f64| {
        let (x, y) = (x.round() as i64, y.round() as i64);
        (-1..=1).any(|dx| {
            (-1..=1).any(|dy| {
                let p = img.get_pixel((x + dx) as u32, (y + dy) as u32);
                (p[0] as i32 - c.0 as i32).abs() < 20
                    && (p[1] as i32 - c.1 as i32).abs() < 20
                    && (p[2] as i32 - c.2 as i32).abs() < 20
            })
        })
    };
    let misses: Vec<(f64, f64, (f64, f64))> = t
        .iter()
        .zip(&a)
        .map(|(ti, vi)| (*ti, *vi, panel.to_px(*ti, *vi)))
        .filter(|(_, _, (x, y))| !near(*x, *y))
        .collect();
    assert!(
        misses.is_empty(),
        "every data point lies on the drawn curve; off it: {misses:?}"
    );
    // and the curve's colour appears nowhere far from the data (sampled off the curve: mid-panel above the peak)
    let (x, y) = panel.to_px(
        0.1,
        panel.y_range.0 + 0.9 * (panel.y_range.1 - panel.y_range.0),
    );
    assert!(!near(x, y), "no curve where there is no data");
}

#[test]
fn csv_columns_expand_patterns_and_unknown_columns_are_named() {
    let (csv, ..) = history_csv("columns_case");
    let data = CsvData::read(&csv).unwrap();
    assert_eq!(data.expand("q*").unwrap(), vec!["q1", "qale1"]);
    assert_eq!(data.expand("qale*").unwrap(), vec!["qale1"]);
    assert_eq!(
        data.expand("joint_*,q1").unwrap(),
        vec!["joint_position", "joint_velocity", "q1"]
    );
    let e = data.expand("q1,q9").unwrap_err().to_string();
    assert!(
        e.contains("\"q9\"") && e.contains("columns_case.csv") && e.contains("qale1"),
        "{e}"
    );
    let e = data.expand("zz*").unwrap_err().to_string();
    assert!(e.contains("zz*"), "{e}");
    let names: Vec<String> = [
        "time", "q1", "q2", "q3", "q4", "qale1", "qale2", "ale1_uz", "ale2_uz", "ale3_uz",
    ]
    .iter()
    .map(|s| s.to_string())
    .collect();
    assert_eq!(
        plot::summarize_names(&names),
        "time, q1..q4, qale1, qale2, ale1_uz..ale3_uz"
    );
}

#[test]
fn bad_plot_input_is_named_with_a_non_zero_exit() {
    let (csv, ..) = history_csv("bad_case");
    let out = dir().join("x.png");
    let run = |args: &[&str]| {
        let (ok, _, err) = support::cli::run(args);
        (ok, err)
    };
    let csv = csv.to_str().unwrap();
    let (ok, err) = run(&[
        "plot",
        "csv",
        csv,
        "--columns",
        "q1,nope",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(!ok && err.contains("unknown column \"nope\""), "{err}");
    let (ok, err) = run(&[
        "plot",
        "csv",
        "/nonexistent/run.csv",
        "--columns",
        "q1",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(
        !ok && err.contains("cannot read /nonexistent/run.csv"),
        "{err}"
    );
    let (ok, err) = run(&["plot", "csv", csv, "--columns", "q1", "--out", "/tmp/x.gif"]);
    assert!(!ok && err.contains(".png or .svg"), "{err}");
    let (ok, err) = run(&[
        "plot",
        "csv",
        csv,
        "--columns",
        "q1",
        "--out",
        "/nonexistent_dir/x.png",
    ]);
    assert!(
        !ok && err.contains("/nonexistent_dir") && err.contains("does not exist"),
        "{err}"
    );
    let (ok, err) = run(&["plot", "csv", csv, "--out", out.to_str().unwrap()]);
    assert!(!ok && err.contains("--columns"), "{err}");
    let (ok, err) = run(&[
        "plot",
        "modes",
        "/nonexistent/p.yaml",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(!ok && err.contains("/nonexistent/p.yaml"), "{err}");
    let params = dir().join("lathe.yaml");
    std::fs::write(&params, "annular_plate:\n  ros__parameters:\n    plate:\n      nodal_diameters: [0, 1, 2, 3, 4, 5, 6, 7]\n      nodal_circles: [0, 1]\n").unwrap();
    let (ok, err) = run(&[
        "plot",
        "mode",
        params.to_str().unwrap(),
        "--index",
        "99",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(
        !ok && err.contains("--index 99") && err.contains("1..30"),
        "{err}"
    );
    let bad_text = dir().join("bad.csv");
    std::fs::write(&bad_text, "time,q1\n0,1\n0.1,abc\n").unwrap();
    let (ok, err) = run(&[
        "plot",
        "csv",
        bad_text.to_str().unwrap(),
        "--columns",
        "q1",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(
        !ok && err.contains("bad.csv:3") && err.contains("q1"),
        "{err}"
    );
    // and a good call works, writing the file
    let (ok, err) = run(&[
        "plot",
        "csv",
        csv,
        "--columns",
        "q1",
        "--panel",
        "qale1",
        "--out",
        out.to_str().unwrap(),
        "--size",
        "640x480",
    ]);
    assert!(ok, "{err}");
    assert_eq!(png(&out).dimensions(), (640, 480));
}

// ------------------------------------------------------------- mode pictures

/// Runs of dark (nodal-line black) pixels and red↔blue sign changes along a closed or open path.
fn scan(img: &image::RgbImage, pts: &[(f64, f64)], closed: bool) -> (usize, usize) {
    let class = |p: &image::Rgb<u8>| -> i8 {
        let (r, g, b) = (p[0] as i32, p[1] as i32, p[2] as i32);
        if r.max(g).max(b) < 60 {
            2 // black
        } else if r > b + 25 {
            1
        } else if b > r + 25 {
            -1
        } else {
            0
        }
    };
    let cls: Vec<i8> = pts
        .iter()
        .map(|&(x, y)| class(img.get_pixel(x.round() as u32, y.round() as u32)))
        .collect();
    let mut dark_runs = 0;
    for i in 0..cls.len() {
        let prev = if i == 0 {
            if closed {
                cls[cls.len() - 1]
            } else {
                0
            }
        } else {
            cls[i - 1]
        };
        if cls[i] == 2 && prev != 2 {
            dark_runs += 1;
        }
    }
    let signs: Vec<i8> = cls
        .iter()
        .copied()
        .filter(|c| *c == 1 || *c == -1)
        .collect();
    let mut changes = signs.windows(2).filter(|w| w[0] != w[1]).count();
    if closed && signs.len() > 1 && signs[0] != signs[signs.len() - 1] {
        changes += 1;
    }
    if closed && dark_runs == 1 && cls.iter().all(|c| *c == 2) {
        dark_runs = 0;
    }
    (dark_runs, changes)
}

/// Count nodal diameters and circles on the raster of one top view.
fn count_on_raster(img: &image::RgbImage, v: &TopView) -> (usize, usize) {
    let (ri, ra) = (v.inner_radius, v.outer_radius);
    let px = 1.0 / v.scale; // one pixel in metres
                            // A circle between the edges and away from every nodal circle (the largest gap).
    let mut marks = vec![ri];
    marks.extend(v.nodal_radii.iter().copied());
    marks.push(ra);
    let (a, b) = marks
        .windows(2)
        .map(|w| (w[0], w[1]))
        .max_by(|x, y| (x.1 - x.0).total_cmp(&(y.1 - y.0)))
        .unwrap();
    let rc = 0.5 * (a + b);
    let n = (TAU * rc * v.scale * 3.0) as usize;
    let circle: Vec<(f64, f64)> = (0..n)
        .map(|i| v.to_px(rc, TAU * i as f64 / n as f64))
        .collect();
    let (diameter_lines, circle_changes) = scan(img, &circle, true);
    // A radius through an antinode of the angular factor, from just outside the inner edge to just inside the outer one.
    let phi = match (v.shape.unwrap(), v.k) {
        (AngularShape::Sin, k) => TAU / (4.0 * k as f64),
        _ => 0.0,
    };
    let m = ((ra - ri) * v.scale * 3.0) as usize;
    let radius: Vec<(f64, f64)> = (0..=m)
        .map(|i| ri + 4.0 * px + (ra - ri - 8.0 * px) * i as f64 / m as f64)
        .map(|r| v.to_px(r, phi))
        .collect();
    let (circle_lines, radius_changes) = scan(img, &radius, false);
    assert_eq!(
        diameter_lines, circle_changes,
        "⟨{}, {}⟩: black lines and colour changes agree around the circle",
        v.k, v.l
    );
    assert_eq!(
        circle_lines, radius_changes,
        "⟨{}, {}⟩: black lines and colour changes agree along the radius",
        v.k, v.l
    );
    (diameter_lines, circle_lines)
}

fn fig2_plate() -> Config {
    // Fig. 2 of the paper: supported inner edge.
    let mut c = Config::default();
    c.plate.inner_boundary = Boundary::Supported;
    c
}

#[test]
fn mode_grid_shows_k_nodal_diameters_and_l_nodal_circles() {
    let ks = [0, 1, 2, 3, 5];
    let ls = [0, 1, 2];
    for (name, config) in [("supported", fig2_plate()), ("lathe", Config::default())] {
        let out = dir().join(format!("grid_{name}.png"));
        let size = Size {
            width: 5 * 260,
            height: 3 * 290 + 60,
        };
        let views = plot::mode_grid(&config, &ks, &ls, None, &out, size).unwrap();
        let img = png(&out);
        assert_eq!(img.dimensions(), (size.width, size.height));
        assert_eq!(views.len(), ks.len() * ls.len());
        for v in &views {
            let (diameter_crossings, circles) = count_on_raster(&img, v);
            assert_eq!(
                diameter_crossings,
                2 * v.k as usize,
                "{name} ⟨{}, {}⟩: 2k crossings of nodal diameters around the disc",
                v.k,
                v.l
            );
            assert_eq!(
                circles, v.l as usize,
                "{name} ⟨{}, {}⟩: l nodal circles along a radius",
                v.k, v.l
            );
        }
    }
}

#[test]
fn free_free_grid_marks_rigid_body_motions_and_svg_is_valid() {
    let mut c = Config::default();
    c.plate.inner_boundary = Boundary::Free;
    let out = dir().join("grid_free.svg");
    let size = Size {
        width: 700,
        height: 600,
    };
    let views = plot::mode_grid(&c, &[0, 1, 2], &[0, 1], None, &out, size).unwrap();
    assert_eq!(
        views
            .iter()
            .filter(|v| v.mode.is_none())
            .map(|v| (v.k, v.l))
            .collect::<Vec<_>>(),
        vec![(0, 0), (1, 0)]
    );
    let (text, dims) = svg_root_size(&out);
    assert_eq!(dims, (700, 600));
    assert!(text.contains("rigid body"));
    // the fields are embedded rasters (4 elastic modes), the nodal lines vectors
    assert_eq!(text.matches("<image").count(), 4);
}

#[test]
fn single_mode_picture_shows_the_nodal_pattern_in_its_top_view() {
    for (shape, k, l) in [
        (AngularShape::Cos, 2, 2),
        (AngularShape::Sin, 3, 1),
        (AngularShape::Axisymmetric, 0, 1),
    ] {
        let out = dir().join(format!("mode_{k}_{l}.png"));
        let size = Size {
            width: 1200,
            height: 560,
        };
        let view = plot::mode_picture(
            &fig2_plate(),
            ModeChoice::KL { k, l, shape },
            None,
            &out,
            size,
        )
        .unwrap();
        let img = png(&out);
        assert_eq!(img.dimensions(), (1200, 560));
        assert_eq!(view.shape, Some(shape));
        let (d, c) = count_on_raster(&img, &view);
        assert_eq!((d, c), (2 * k as usize, l as usize), "⟨{k}, {l}⟩ {shape:?}");
        // the surface on the left is drawn: red and blue pixels there
        let (mut red, mut blue) = (0, 0);
        for y in (60..540).step_by(4) {
            for x in (20..700).step_by(4) {
                let p = img.get_pixel(x, y);
                if p[0] as i32 > p[2] as i32 + 40 {
                    red += 1;
                } else if p[2] as i32 > p[0] as i32 + 40 {
                    blue += 1;
                }
            }
        }
        assert!(
            red > 500 && (blue > 500 || k == 0 && l == 0),
            "surface drawn: {red} red, {blue} blue samples"
        );
    }
    // by index, as `modes` numbers them; SVG
    let out = dir().join("mode_index.svg");
    let view = plot::mode_picture(
        &Config::default(),
        ModeChoice::Index(4),
        None,
        &out,
        Size {
            width: 1000,
            height: 480,
        },
    )
    .unwrap();
    assert_eq!((view.k, view.l), (2, 0));
    assert_eq!(svg_root_size(&out).1, (1000, 480));
}

/// The bench disc of config/brake_bench.yaml (steel, r_i = 0.07 m, r_a = 0.153 m,
/// h = 18.1 mm: h/(r_a − r_i) = 0.22, supported inside, free outside) as a Mindlin plate.
fn mindlin_bench_disc() -> (Config, support::mindlin_exact::MindlinAnnulus) {
    let mut c = Config::default();
    let p = &mut c.plate;
    (p.youngs_modulus, p.poisson_ratio, p.density) = (2.1e11, 0.3, 7850.0);
    (p.inner_radius, p.outer_radius, p.thickness) = (0.07, 0.153, 0.0181);
    (p.inner_boundary, p.outer_boundary) = (Boundary::Supported, Boundary::Free);
    p.theory = annular_plate::config::PlateTheory::Mindlin;
    let exact = support::mindlin_exact::MindlinAnnulus::of_plate(p);
    (c, exact)
}

/// The radius strictly inside (r_i, r_a) where the exact Mindlin W of ⟨k, l = 1⟩ changes sign.
fn exact_nodal_radius(exact: &support::mindlin_exact::MindlinAnnulus, k: u32) -> f64 {
    let omega = exact.roots(k, 2, 64)[1];
    let mode = exact.mode(k, omega);
    let (ri, ra) = (exact.inner_radius, exact.outer_radius);
    let w = |r: f64| mode.fields(r).w;
    let n = 2000;
    let grid: Vec<f64> = (1..n)
        .map(|i| ri + (ra - ri) * i as f64 / n as f64)
        .collect();
    let i = grid
        .windows(2)
        .position(|p| w(p[0]).signum() != w(p[1]).signum())
        .expect("one nodal circle");
    let (mut a, mut b) = (grid[i], grid[i + 1]);
    for _ in 0..60 {
        let c = 0.5 * (a + b);
        if w(c).signum() == w(a).signum() {
            a = c;
        } else {
            b = c;
        }
    }
    0.5 * (a + b)
}

/// A Mindlin plate's mode picture draws the Mindlin mode's deflection w: its
/// nodal circle is the exact Mindlin W's (`tests/support/mindlin_exact.rs`,
/// the 6×6 edge matrix's null vector) — not Kirchhoff's, which for this thick
/// disc lies hundreds of tolerances away — the raster shows 2k diameters and
/// one circle, and the title names the theory.
#[test]
fn mindlin_mode_picture_draws_the_exact_mindlin_nodal_circle() {
    let (config, exact) = mindlin_bench_disc();
    let width = exact.outer_radius - exact.inner_radius;
    let tolerance = 1e-7 * width;
    for k in [0u32, 2, 4] {
        let shape = if k == 0 {
            AngularShape::Axisymmetric
        } else {
            AngularShape::Cos
        };
        let out = dir().join(format!("mindlin_mode_{k}_1.png"));
        let size = Size {
            width: 1200,
            height: 560,
        };
        let view = plot::mode_picture(&config, ModeChoice::KL { k, l: 1, shape }, None, &out, size)
            .unwrap();
        let (d, c) = count_on_raster(&png(&out), &view);
        assert_eq!((d, c), (2 * k as usize, 1), "Mindlin ⟨{k}, 1⟩");
        let want = exact_nodal_radius(&exact, k);
        let drawn = view.nodal_radii[0];
        let mut kirchhoff = config.plate.clone();
        kirchhoff.theory = annular_plate::config::PlateTheory::Kirchhoff;
        (kirchhoff.nodal_diameters, kirchhoff.nodal_circles) = (vec![k], vec![1]);
        let kirchhoff = annular_plate::model::PlateModel::new(&kirchhoff).unwrap();
        let kirchhoff_radius = annular_plate::model::nodal_lines::nodal_radii(&kirchhoff, 0)[0];
        println!(
            "⟨{k}, 1⟩ nodal circle: drawn {drawn:.9} m, exact Mindlin {want:.9} m ({:.1e} of r_a − r_i), Kirchhoff {kirchhoff_radius:.6} m",
            (drawn - want).abs() / width
        );
        assert!(
            (drawn - want).abs() < tolerance,
            "⟨{k}, 1⟩: drawn {drawn}, exact Mindlin {want}"
        );
        assert!(
            (kirchhoff_radius - want).abs() > 100.0 * tolerance,
            "⟨{k}, 1⟩: the test tells Kirchhoff's circle ({kirchhoff_radius}) from Mindlin's"
        );
    }
    // The title (SVG text) and the grid name the theory.
    let out = dir().join("mindlin_grid.svg");
    let views = plot::mode_grid(
        &config,
        &[0, 2],
        &[0, 1],
        None,
        &out,
        Size {
            width: 700,
            height: 600,
        },
    )
    .unwrap();
    assert_eq!(views.len(), 4);
    let (text, _) = svg_root_size(&out);
    assert!(text.contains("Mindlin plate"), "the title names the theory");
}
