//! `plot animate`: the frames of a simulated run, decoded from the GIF and
//! checked against the plate model evaluated here (w = Σ q_i w_i at the
//! pixel's (r, φ − χ)), the frame count against duration × fps, and the
//! picture against the run: flat at rest, coloured where the plate deflects.

#![cfg(feature = "cli")]

use annular_plate::cli::plot::{animate, Animation, CsvData, Size};
use annular_plate::config::{Config, PlateTheory};
use annular_plate::model::PlateModel;
use image::AnimationDecoder;
use std::path::{Path, PathBuf};
use std::process::Command;

fn dir() -> PathBuf {
    let d = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("target/plot-tests");
    std::fs::create_dir_all(&d).unwrap();
    d
}

fn scene() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("config/swash_plate.yaml")
}

/// 0.3 s of the swash plate (pitch links turning with it), every step; it
/// ends deflected (1.4 mm at the first link).
/// A fresh CSV per call: the tests run in parallel, and one must not read
/// the file while another rewrites it.
fn simulated_csv(overrides: &[&str]) -> PathBuf {
    static CALLS: std::sync::atomic::AtomicUsize = std::sync::atomic::AtomicUsize::new(0);
    let call = CALLS.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
    let csv = dir().join(format!("animate_swash_{call}.csv"));
    let ok = Command::new(env!("CARGO_BIN_EXE_annular_plate"))
        .args(["simulate", "--quiet", "--duration", "0.3", "--csv"])
        .arg(&csv)
        .args(overrides)
        .arg(scene())
        .status()
        .unwrap()
        .success();
    assert!(ok);
    csv
}

fn frames(gif: &Path) -> Vec<image::RgbaImage> {
    let file = std::io::BufReader::new(std::fs::File::open(gif).unwrap());
    let decoder = image::codecs::gif::GifDecoder::new(file).unwrap();
    decoder
        .into_frames()
        .collect_frames()
        .unwrap()
        .into_iter()
        .map(|f| f.into_buffer())
        .collect()
}

/// The documented colour map (docs/ros.md), written out here, as 8-bit RGB.
fn documented_colour(t: f64) -> [f64; 3] {
    let (blue, grey, red) = (
        [0.230, 0.299, 0.754],
        [0.865, 0.865, 0.865],
        [0.706, 0.016, 0.150],
    );
    let t = t.clamp(-1.0, 1.0);
    let (end, u) = if t < 0.0 { (blue, -t) } else { (red, t) };
    std::array::from_fn(|i| 255.0 * (grey[i] + (end[i] - grey[i]) * u))
}

#[test]
fn frames_follow_the_run_and_colour_the_deflection_of_the_model() {
    frames_follow_the_run(PlateTheory::Kirchhoff);
}

/// The same under `plate.theory: mindlin`: the frames colour the Mindlin
/// modes' deflection w (the links act on w in either theory).
#[test]
fn frames_of_a_mindlin_plate_colour_the_deflection_of_its_mindlin_modes() {
    frames_follow_the_run(PlateTheory::Mindlin);
}

fn frames_follow_the_run(theory: PlateTheory) {
    // Mindlin plates take no residual flexibility (a point force's deflection is infinite).
    let residual = theory == PlateTheory::Kirchhoff;
    let csv = simulated_csv(&[
        "-p",
        &format!("plate.theory:={}", theory.name()),
        "-p",
        &format!("plate.residual_flexibility:={residual}"),
    ]);
    let data = CsvData::read(&csv).unwrap();
    let mut config = Config::from_params_file(&scene(), "/annular_plate").unwrap();
    (config.plate.theory, config.plate.residual_flexibility) = (theory, residual);
    let out = dir().join(format!("animate_swash_{}.gif", theory.name()));
    let anim = Animation {
        fps: 20,
        max_frames: 10_000,
        slowdown: 1.0,
        scale: None,
        size: Size {
            width: 480,
            height: 260,
        },
    };
    let mut calls = 0;
    let info = animate(&data, &config, &anim, &out, |done, _| {
        calls += usize::from(done > 0)
    })
    .unwrap();
    let decoded = frames(&out);
    // Duration × fps: 0.3 s × 20 (and one call with 0 done before the first frame).
    assert_eq!((info.frames, decoded.len(), calls), (6, 6, 6));
    let rows = data.columns[0].len();
    assert_eq!(
        (info.rows[0], *info.rows.last().unwrap()),
        (0, rows - 1),
        "first and last frames are the first and last rows"
    );
    if std::env::var_os("ANIM_DUMP").is_some() {
        decoded
            .last()
            .unwrap()
            .save(dir().join(format!("animate_last_{}.png", theory.name())))
            .unwrap();
    }

    let model = PlateModel::new(&config.plate).unwrap();
    let q_of = |row: usize| -> Vec<f64> {
        (1..=model.n_modes())
            .map(|i| data.column(&format!("q{i}")).unwrap()[row])
            .collect()
    };
    let chi = data.column("joint_position").unwrap();
    let (ri, ra) = (model.plate().inner_radius, model.plate().outer_radius);
    let (cx, cy) = info.top_centre;
    let pixel = |img: &image::RgbaImage, r: f64, space: f64| {
        let (px, py) = (
            cx + r * space.cos() * info.px_per_m,
            cy - r * space.sin() * info.px_per_m,
        );
        let p = img.get_pixel(px as u32, py as u32);
        [p[0] as f64, p[1] as f64, p[2] as f64]
    };
    let (first, last) = (&decoded[0], decoded.last().unwrap());
    let (q_first, q_last) = (q_of(0), q_of(rows - 1));
    // Node-frame markers (squares, circles of 5 px) cover a few pixels: skip those.
    let node_pixels = |chi: f64| -> Vec<(f64, f64)> {
        let ale = config.nodes.ale.iter().map(|p| (p, 0.0));
        let lag = config.nodes.lagrange.iter().map(|p| (p, chi));
        ale.chain(lag)
            .map(|(p, turn)| {
                let (r, a) = (
                    model.radius_at(p.radial),
                    std::f64::consts::TAU * p.angular + turn,
                );
                (
                    cx + r * a.cos() * info.px_per_m,
                    cy - r * a.sin() * info.px_per_m,
                )
            })
            .collect()
    };
    let mut checked = 0;
    let mut changed = 0;
    for (img, q, chi) in [(first, &q_first, chi[0]), (last, &q_last, chi[rows - 1])] {
        let nodes = node_pixels(chi);
        for ring in 1..8 {
            let r = ri + (ra - ri) * ring as f64 / 8.0;
            for k in 0..48 {
                let space = std::f64::consts::TAU * (k as f64 + 0.25) / 48.0;
                let (px, py) = (
                    cx + r * space.cos() * info.px_per_m,
                    cy - r * space.sin() * info.px_per_m,
                );
                if nodes.iter().any(|(x, y)| (x - px).hypot(y - py) < 9.0) {
                    continue;
                }
                let w = model.deflection(q, r, space - chi).w;
                let got = pixel(img, r, space);
                let want = documented_colour(w / info.w_ref);
                // GIF palette quantization and the nearest grid cell: a few levels.
                let off = (0..3).map(|i| (got[i] - want[i]).abs()).fold(0.0, f64::max);
                assert!(
                    off <= 24.0,
                    "r = {r}, φ = {space}: pixel {got:?}, w/w_ref = {} wants {want:?}",
                    w / info.w_ref
                );
                checked += 1;
                if std::ptr::eq(img, last)
                    && w.abs() > 0.3 * info.w_ref
                    && pixel(first, r, space) != got
                {
                    changed += 1;
                }
            }
        }
    }
    println!("{checked} of 672 sample points checked (first and last frame); {changed} changed where |w| > 0.3 w_ref (w_ref {:e} m)", info.w_ref);
    assert!(checked >= 600, "{checked}");
    assert!(
        changed >= 20,
        "the picture changes where the plate deflects: {changed}"
    );
    // At rest the plate is flat: every disc pixel of the first frame is the map's grey.
    assert!(q_first.iter().all(|q| *q == 0.0));
    let grey = documented_colour(0.0);
    for ring in 1..8 {
        let r = ri + (ra - ri) * ring as f64 / 8.0;
        for k in 0..48 {
            let got = pixel(first, r, std::f64::consts::TAU * (k as f64 + 0.25) / 48.0);
            assert!((0..3).all(|i| (got[i] - grey[i]).abs() <= 6.0), "{got:?}");
        }
    }
    // Outside the disc and below the caption nothing moves.
    for (x, y) in [(2u32, 250u32), (235, 250), (120, 40)] {
        assert_eq!(
            first.get_pixel(x, y),
            last.get_pixel(x, y),
            "background at ({x}, {y})"
        );
    }
}

#[test]
fn frame_count_is_duration_times_fps_and_mp4_without_ffmpeg_names_the_remedy() {
    let csv = simulated_csv(&[]);
    let data = CsvData::read(&csv).unwrap();
    let config = Config::from_params_file(&scene(), "/annular_plate").unwrap();
    let small = Size {
        width: 200,
        height: 120,
    };
    for (fps, slowdown, want) in [(10, 1.0, 3), (25, 2.0, 15)] {
        let out = dir().join(format!("animate_{fps}_{slowdown}.gif"));
        let info = animate(
            &data,
            &config,
            &Animation {
                fps,
                max_frames: 10_000,
                slowdown,
                scale: Some(20.0),
                size: small,
            },
            &out,
            |_, _| {},
        )
        .unwrap();
        assert_eq!(
            (info.frames, frames(&out).len(), info.scale),
            (want, want, 20.0)
        );
    }
    // Too short for two frames: refused with the numbers and the remedy.
    let err = animate(
        &data,
        &config,
        &Animation {
            fps: 3,
            max_frames: 10_000,
            slowdown: 1.0,
            scale: None,
            size: small,
        },
        &dir().join("x.gif"),
        |_, _| {},
    )
    .unwrap_err();
    assert!(err.to_string().contains("--slowdown"), "{err}");
    // MP4 goes through ffmpeg; without it the error says what to do.
    let out = Command::new(env!("CARGO_BIN_EXE_annular_plate"))
        .args(["plot", "animate", "--quiet", "--params"])
        .arg(scene())
        .arg("--out")
        .arg(dir().join("x.mp4"))
        .arg(&csv)
        .env("PATH", "")
        .output()
        .unwrap();
    let text = String::from_utf8_lossy(&out.stderr);
    assert!(
        !out.status.success() && text.contains("ffmpeg") && text.contains(".gif"),
        "{text}"
    );
}

/// With in-plane modes (`plate.in_plane_nodal_diameters`) the CSV carries
/// their amplitudes after the bending ones. The pitch links push along the
/// axis only, so the bending amplitudes of the swash plate are the same
/// with and without in-plane modes (tests/in_plane_load_models.rs): the
/// frames are the same pixels below the caption, whose second line names
/// the in-plane columns it does not draw. A CSV and a params file that disagree on the
/// in-plane modes are refused, naming the columns.
#[test]
fn frames_with_in_plane_modes_draw_the_bending_and_name_the_in_plane_columns() {
    let in_plane = ["-p", "plate.in_plane_nodal_diameters:=[0, 1]"];
    let csv_with = simulated_csv(&in_plane);
    let csv_without = simulated_csv(&[]);
    let mut config_with = Config::from_params_file(&scene(), "/annular_plate").unwrap();
    config_with.plate.in_plane_nodal_diameters = vec![0, 1];
    let config_without = Config::from_params_file(&scene(), "/annular_plate").unwrap();
    let anim = Animation {
        fps: 10,
        max_frames: 10_000,
        slowdown: 1.0,
        scale: None,
        size: Size {
            width: 400,
            height: 240,
        },
    };
    let draw = |csv: &Path, config: &Config, name: &str| {
        let out = dir().join(name);
        let data = CsvData::read(csv).unwrap();
        animate(&data, config, &anim, &out, |_, _| {}).map(|info| (info, frames(&out)))
    };
    let (info_with, with) = draw(&csv_with, &config_with, "animate_in_plane.gif").unwrap();
    let (info_without, without) =
        draw(&csv_without, &config_without, "animate_bending.gif").unwrap();
    assert_eq!(
        (info_with.rows, info_with.w_ref, info_with.scale),
        (info_without.rows, info_without.w_ref, info_without.scale),
        "the same rows, colour reference and magnification"
    );
    assert_eq!(with.len(), without.len());
    let caption_band = 46;
    let mut differing_caption_pixels = 0;
    // The GIF's palette is quantised per frame, so equal pictures may
    // differ where the caption changed the palette: a few pixels, by a few
    // levels on average.
    let (mut sum_below, mut count_below) = (0u64, 0u64);
    for (a, b) in with.iter().zip(&without) {
        for (x, y, p) in a.enumerate_pixels() {
            if y < caption_band {
                differing_caption_pixels += usize::from(p != b.get_pixel(x, y));
            } else {
                let q = b.get_pixel(x, y);
                sum_below += (0..3).map(|c| u64::from(p[c].abs_diff(q[c]))).sum::<u64>();
                count_below += 3;
            }
        }
    }
    let mean_below = sum_below as f64 / count_below as f64;
    println!("below the caption: mean channel difference {mean_below:.3} of 255");
    assert!(mean_below < 0.5, "{mean_below}");
    assert!(
        differing_caption_pixels > 0,
        "the caption names the in-plane columns"
    );
    for (csv, config) in [(&csv_with, &config_without), (&csv_without, &config_with)] {
        let err = draw(csv, config, "animate_mismatch.gif")
            .unwrap_err()
            .to_string();
        println!("{err}");
        assert!(err.contains("is it the scene of this run?"), "{err}");
    }
}
