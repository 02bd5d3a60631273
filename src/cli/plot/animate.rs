//! `plot animate CSV --params FILE --out F.gif|F.mp4`: the deformed plate of
//! a simulated run, frame by frame.
//!
//! Each frame shows the state of the CSV row nearest its time: a top view in
//! the space-fixed frame (the plate turned by the joint angle χ, coloured by
//! the deflection w on the fixed map of [`crate::colour_map`], ALE node
//! frames as squares, Lagrangian ones as circles turning with the plate) and
//! a side view seen from −y (every grid point at x = r cos φ, z = scale·w).
//! The colour reference is the largest |w| of the frames; the side view's
//! magnification draws it as [`SIDE_FRACTION`] of r_a unless `--scale` says.
//! w = Σ q_i w_i(r, φ) from the CSV's Lagrangian amplitudes `q1…qN` and the
//! plate model of the params file (the same modes as the run).
//!
//! Frame count = round(duration × fps) with duration = the run's time span ×
//! `--slowdown`; the first frame is the first row, the last frame the last.
//! The work is bounded before it starts: at most `--max-frames` frames
//! (default [`DEFAULT_MAX_FRAMES`]), the refusal giving the estimate; only
//! the frames' rows are evaluated (the colour reference is the largest |w|
//! of the frames), so a CSV of 10^6 rows costs its reading, not 10^6 grid
//! evaluations.

use super::render::{ensure_fonts, FONT};
use super::{CsvData, Size};
use crate::cli::error::{CliError, CliResult};
use crate::config::Config;
use crate::model::PlateModel;
use plotters::prelude::*;
use std::path::Path;

/// `--max-frames` unless given.
pub const DEFAULT_MAX_FRAMES: usize = 10_000;
/// Rendering time of a frame (960×480 GIF, release build, one core: 0.07 s measured), for estimates.
pub(crate) const FRAME_SECONDS: f64 = 0.08;

/// The largest |w| of the run is drawn this fraction of r_a high in the side view.
pub(crate) const SIDE_FRACTION: f64 = 0.1;
/// Cells of the polar grid the frames are drawn from.
const RINGS: usize = 48;
const SECTORS: usize = 360;

/// What to render.
#[derive(Debug, Clone)]
pub struct Animation {
    /// Frames per second of the animation.
    pub fps: u32,
    /// Refuse more frames than this (`--max-frames`).
    pub max_frames: usize,
    /// Animation seconds per simulated second.
    pub slowdown: f64,
    /// Side-view magnification; None: auto.
    pub scale: Option<f64>,
    /// Picture size.
    pub size: Size,
}

/// The frames' layout and the run's numbers, for tests.
#[derive(Debug, Clone, PartialEq)]
pub struct AnimationInfo {
    /// Frames drawn.
    pub frames: usize,
    /// CSV row of each frame.
    pub rows: Vec<usize>,
    /// Largest |w| of the run (colour reference), m.
    pub w_ref: f64,
    /// The side view's magnification of the deflection.
    pub scale: f64,
    /// Top view: centre (px) and pixels per metre.
    pub top_centre: (f64, f64),
    /// Pixels per metre of the top view.
    pub px_per_m: f64,
}

/// The deflection on a polar grid, from tables built once.
struct Grid {
    radii: Vec<f64>,
    radial: Vec<f64>,
    angular: Vec<f64>,
}

impl Grid {
    fn new(model: &PlateModel) -> Grid {
        let p = model.plate();
        let radii: Vec<f64> = (0..=RINGS)
            .map(|j| p.inner_radius + (p.outer_radius - p.inner_radius) * j as f64 / RINGS as f64)
            .collect();
        let mut radial = Vec::new();
        let mut angular = Vec::new();
        for m in model.modes() {
            let shape = &model.radial_shapes()[m.radial];
            radial.extend(radii.iter().map(|&r| shape.value(r)));
            angular.extend((0..SECTORS).map(|s| {
                m.shape
                    .eval(m.k, std::f64::consts::TAU * s as f64 / SECTORS as f64)
                    .0
            }));
        }
        Grid {
            radii,
            radial,
            angular,
        }
    }

    /// w[j * SECTORS + s] at ring j, material angle 2π s / SECTORS.
    fn deflection(&self, q: &[f64], w: &mut [f64]) {
        let nr = self.radii.len();
        w.fill(0.0);
        for (i, &qi) in q.iter().enumerate() {
            let angular = &self.angular[i * SECTORS..(i + 1) * SECTORS];
            for j in 0..nr {
                let a = qi * self.radial[i * nr + j];
                for (wv, t) in w[j * SECTORS..(j + 1) * SECTORS].iter_mut().zip(angular) {
                    *wv += a * t;
                }
            }
        }
    }
}

/// The Lagrangian amplitudes of the rows `rows`: columns q1…qN.
/// The bending amplitudes q1..qn of `rows`; the CSV's modal columns end at
/// q(n + in_plane) (the in-plane modes follow the bending ones).
fn amplitudes(
    data: &CsvData,
    n: usize,
    in_plane: usize,
    rows: &[usize],
) -> CliResult<Vec<Vec<f64>>> {
    let total = n + in_plane;
    if in_plane > 0 && !data.header.iter().any(|h| h == &format!("q{total}")) {
        return Err(CliError::Usage(format!(
            "{} has no column q{total}: the params file has {n} bending and {in_plane} in-plane modes (is it the scene of this run?)",
            data.path.display()
        )));
    }
    let cols: Vec<&[f64]> = (1..=n)
        .map(|i| data.column(&format!("q{i}")))
        .collect::<CliResult<_>>()
        .map_err(|e| {
            CliError::Usage(format!(
                "{e} (the params file has {n} modes: is it the scene of this run?)"
            ))
        })?;
    if data.header.iter().any(|h| h == &format!("q{}", total + 1)) {
        return Err(CliError::Usage(format!("{} has more modal columns than the {total} modes of the params file: is it the scene of this run?", data.path.display())));
    }
    Ok(rows
        .iter()
        .map(|&row| cols.iter().map(|c| c[row]).collect())
        .collect())
}

/// Rows of the frames: round(span × slowdown × fps) frames, first and last rows included.
pub(crate) fn frame_rows(
    times: &[f64],
    fps: u32,
    slowdown: f64,
    max_frames: usize,
) -> CliResult<Vec<usize>> {
    let (t0, t1) = (times[0], *times.last().unwrap());
    let n = ((t1 - t0) * slowdown * fps as f64).round();
    if n.is_nan() || n < 2.0 {
        return Err(CliError::Usage(format!(
            "the run spans {} s: at --fps {fps} and --slowdown {slowdown} that is {n} frames (at least 2 needed); raise --slowdown",
            t1 - t0
        )));
    }
    if n > max_frames as f64 {
        return Err(CliError::Usage(format!(
            "{n} frames is more than --max-frames {max_frames} (about {:.0} s of rendering at ~{FRAME_SECONDS} s a frame): lower --fps or --slowdown, or raise --max-frames",
            n * FRAME_SECONDS
        )));
    }
    let n = n as usize;
    let mut rows = Vec::with_capacity(n);
    let mut row = 0;
    for k in 0..n {
        let t = t0 + (t1 - t0) * k as f64 / (n - 1) as f64;
        while row + 1 < times.len() && (times[row + 1] - t).abs() <= (times[row] - t).abs() {
            row += 1;
        }
        rows.push(row);
    }
    Ok(rows)
}

/// Render the animation of `data` (a `simulate` CSV of `config`'s scene) to `out`.
/// `progress(done, total)` is called with 0 done before any work, then after each frame.
pub fn animate(
    data: &CsvData,
    config: &Config,
    anim: &Animation,
    out: &Path,
    mut progress: impl FnMut(usize, usize),
) -> CliResult<AnimationInfo> {
    // The bending modes are drawn; the in-plane ones (µm in the plane)
    // are named in the caption, their columns read past.
    let (model, in_plane) = if config.plate.in_plane_nodal_diameters.is_empty() {
        PlateModel::bending(&config.plate).map(|m| (m, 0))
    } else {
        PlateModel::bending_and_in_plane(&config.plate, &config.centrifugal)
            .map(|(m, table)| (m, table.entries.len()))
    }
    .map_err(|e| CliError::Usage(format!("the params file's plate: {e}")))?;
    let times = data.column("time")?;
    let chi = data.column("joint_position")?;
    // The work is the frames' (bounded by --max-frames), not the rows'.
    let rows = frame_rows(times, anim.fps, anim.slowdown, anim.max_frames)?;
    progress(0, rows.len());
    let q = amplitudes(data, model.n_modes(), in_plane, &rows)?;
    let grid = Grid::new(&model);
    let mut w = vec![0.0; grid.radii.len() * SECTORS];
    let mut w_ref: f64 = 0.0;
    for qr in &q {
        grid.deflection(qr, &mut w);
        w_ref = w.iter().fold(w_ref, |m, v| m.max(v.abs()));
    }
    let ra = model.plate().outer_radius;
    let scale = anim.scale.unwrap_or(if w_ref > 0.0 {
        SIDE_FRACTION * ra / w_ref
    } else {
        1.0
    });
    let (width, height) = (anim.size.width as usize, anim.size.height as usize);
    let half = width as f64 / 2.0;
    let px_per_m = 0.42 * half.min(height as f64 - 40.0) / ra;
    let top_centre = (half / 2.0, 30.0 + (height as f64 - 30.0) / 2.0);
    let view = View {
        model: &model,
        grid: &grid,
        config,
        in_plane,
        w_ref,
        scale,
        px_per_m,
        top_centre,
        width,
        height,
    };
    let mut sink = FrameSink::open(out, anim, width, height)?;
    for (k, &row) in rows.iter().enumerate() {
        grid.deflection(&q[k], &mut w);
        let frame = view.frame(&w, &q[k], chi[row], times[row])?;
        sink.push(frame)?;
        progress(k + 1, rows.len());
    }
    sink.finish()?;
    Ok(AnimationInfo {
        frames: rows.len(),
        rows,
        w_ref,
        scale,
        top_centre,
        px_per_m,
    })
}

/// Everything a frame is drawn from.
struct View<'a> {
    model: &'a PlateModel,
    grid: &'a Grid,
    config: &'a Config,
    /// In-plane modes in the run (not drawn; named in the caption).
    in_plane: usize,
    w_ref: f64,
    scale: f64,
    px_per_m: f64,
    top_centre: (f64, f64),
    width: usize,
    height: usize,
}

impl View<'_> {
    /// One RGB frame.
    fn frame(&self, w: &[f64], q: &[f64], chi: f64, t: f64) -> CliResult<Vec<u8>> {
        let mut buf = vec![255u8; self.width * self.height * 3];
        self.top_view(&mut buf, w, chi);
        ensure_fonts();
        {
            let root =
                BitMapBackend::with_buffer(&mut buf, (self.width as u32, self.height as u32))
                    .into_drawing_area();
            self.side_view(&root, w, chi)?;
            self.node_frames(&root, q, chi)?;
            let style = (FONT, 18).into_font().color(&BLACK);
            let mut caption = format!(
                "t = {t:.4} s   top: colour ±{:.3e} m   side: deflection ×{:.3e}",
                self.w_ref, self.scale
            );
            if let Some(theory) = super::modes::theory_text(self.config) {
                caption.push_str("   ");
                caption.push_str(&theory);
            }
            root.draw(&Text::new(caption, (10, 6), style))
                .map_err(super::render::de)?;
            if self.in_plane > 0 {
                let n = self.model.n_modes();
                let note = format!(
                    "bending drawn; in-plane modes q{}–q{} not drawn",
                    n + 1,
                    n + self.in_plane
                );
                let small = (FONT, 14).into_font().color(&BLACK);
                root.draw(&Text::new(note, (10, 28), small))
                    .map_err(super::render::de)?;
            }
            root.present().map_err(super::render::de)?;
        }
        Ok(buf)
    }

    /// The disc from above, in the space-fixed frame: pixel → (r, φ) → material angle φ − χ.
    fn top_view(&self, buf: &mut [u8], w: &[f64], chi: f64) {
        let p = self.model.plate();
        let (ri, ra) = (p.inner_radius, p.outer_radius);
        let (cx, cy) = self.top_centre;
        let reach = (ra * self.px_per_m).ceil() as i64 + 1;
        let nr = self.grid.radii.len();
        for py in (cy as i64 - reach).max(0)..(cy as i64 + reach).min(self.height as i64) {
            for px in (cx as i64 - reach).max(0)..(cx as i64 + reach).min(self.width as i64 / 2) {
                let (x, y) = (
                    (px as f64 + 0.5 - cx) / self.px_per_m,
                    (cy - py as f64 - 0.5) / self.px_per_m,
                );
                let r = x.hypot(y);
                if r < ri || r > ra {
                    continue;
                }
                let phi = (y.atan2(x) - chi).rem_euclid(std::f64::consts::TAU);
                let j = (((r - ri) / (ra - ri)) * (nr - 1) as f64).round() as usize;
                let s = ((phi / std::f64::consts::TAU) * SECTORS as f64).round() as usize % SECTORS;
                let wv = w[j.min(nr - 1) * SECTORS + s];
                let c = crate::colour_map::rgb8(if self.w_ref > 0.0 {
                    wv / self.w_ref
                } else {
                    0.0
                });
                let i = (py as usize * self.width + px as usize) * 3;
                buf[i..i + 3].copy_from_slice(&c);
            }
        }
    }

    /// The plate seen from −y: each grid point at (x, scale·w), coloured.
    fn side_view<DB: DrawingBackend>(
        &self,
        root: &DrawingArea<DB, plotters::coord::Shift>,
        w: &[f64],
        chi: f64,
    ) -> CliResult<()> {
        let ra = self.model.plate().outer_radius;
        let cx = self.width as f64 * 0.75;
        let cy = self.top_centre.1;
        let k = self.px_per_m;
        root.draw(&PathElement::new(
            vec![
                ((cx - ra * k) as i32, cy as i32),
                ((cx + ra * k) as i32, cy as i32),
            ],
            BLACK.mix(0.3),
        ))
        .map_err(super::render::de)?;
        for (j, &r) in self.grid.radii.iter().enumerate() {
            for s in 0..SECTORS {
                let phi = std::f64::consts::TAU * s as f64 / SECTORS as f64 + chi;
                let wv = w[j * SECTORS + s];
                let [red, g, b] = crate::colour_map::rgb8(if self.w_ref > 0.0 {
                    wv / self.w_ref
                } else {
                    0.0
                });
                let px = (cx + r * phi.cos() * k) as i32;
                let py = (cy - self.scale * wv * k) as i32;
                root.draw_pixel((px, py), &RGBColor(red, g, b))
                    .map_err(super::render::de)?;
            }
        }
        Ok(())
    }

    /// ALE frames (space-fixed) as squares, Lagrangian ones (turning with χ) as circles, in both views.
    fn node_frames<DB: DrawingBackend>(
        &self,
        root: &DrawingArea<DB, plotters::coord::Shift>,
        q: &[f64],
        chi: f64,
    ) -> CliResult<()> {
        let (cx, cy) = self.top_centre;
        let (k, side_cx) = (self.px_per_m, self.width as f64 * 0.75);
        let n = &self.config.nodes;
        let nodes = n
            .ale
            .iter()
            .map(|p| (p, true))
            .chain(n.lagrange.iter().map(|p| (p, false)));
        for (pos, ale) in nodes {
            let r = self.model.radius_at(pos.radial);
            let theta = std::f64::consts::TAU * pos.angular;
            // Space angle and the material angle w is taken at.
            let (space, material) = if ale {
                (theta, theta - chi)
            } else {
                (theta + chi, theta)
            };
            let wv = self.model.deflection(q, r, material).w;
            let top = (
                (cx + r * space.cos() * k) as i32,
                (cy - r * space.sin() * k) as i32,
            );
            let side = (
                (side_cx + r * space.cos() * k) as i32,
                (cy - self.scale * wv * k) as i32,
            );
            for at in [top, side] {
                let shape = if ale {
                    root.draw(&Rectangle::new(
                        [(at.0 - 5, at.1 - 5), (at.0 + 5, at.1 + 5)],
                        BLACK.stroke_width(2),
                    ))
                } else {
                    root.draw(&Circle::new(at, 5, BLACK.stroke_width(2)))
                };
                shape.map_err(super::render::de)?;
            }
        }
        Ok(())
    }
}

/// Where frames go: a GIF written as they come, or ffmpeg for MP4.
enum FrameSink {
    Gif(
        image::codecs::gif::GifEncoder<std::io::BufWriter<std::fs::File>>,
        u32,
        u32,
        u32,
    ),
    Mp4(std::process::Child),
}

impl FrameSink {
    fn open(out: &Path, anim: &Animation, width: usize, height: usize) -> CliResult<FrameSink> {
        match out
            .extension()
            .and_then(|e| e.to_str())
            .map(|e| e.to_ascii_lowercase())
            .as_deref()
        {
            Some("gif") => {
                let file = std::fs::File::create(out).map_err(|error| CliError::Io {
                    what: "create",
                    path: out.display().to_string(),
                    error,
                })?;
                let mut enc = image::codecs::gif::GifEncoder::new_with_speed(
                    std::io::BufWriter::new(file),
                    10,
                );
                enc.set_repeat(image::codecs::gif::Repeat::Infinite)
                    .map_err(|e| CliError::Draw(e.to_string()))?;
                Ok(FrameSink::Gif(enc, width as u32, height as u32, anim.fps))
            }
            Some("mp4") => {
                let child = std::process::Command::new("ffmpeg")
                    .args(["-loglevel", "error", "-y", "-f", "rawvideo", "-pix_fmt", "rgb24", "-s", &format!("{width}x{height}"), "-r", &anim.fps.to_string(), "-i", "-", "-pix_fmt", "yuv420p"])
                    .arg(out)
                    .stdin(std::process::Stdio::piped())
                    .spawn()
                    .map_err(|e| CliError::Usage(format!("--out {}: MP4 is encoded by ffmpeg, which could not be started ({e}); install it (Debian: apt install ffmpeg) or write a .gif", out.display())))?;
                Ok(FrameSink::Mp4(child))
            }
            _ => Err(CliError::Usage(format!(
                "--out {}: the name must end in .gif or .mp4",
                out.display()
            ))),
        }
    }

    fn push(&mut self, rgb: Vec<u8>) -> CliResult<()> {
        match self {
            FrameSink::Gif(enc, w, h, fps) => {
                let rgba: Vec<u8> = rgb
                    .chunks_exact(3)
                    .flat_map(|c| [c[0], c[1], c[2], 255])
                    .collect();
                let img = image::RgbaImage::from_raw(*w, *h, rgba).expect("frame size");
                let delay = image::Delay::from_numer_denom_ms(1000, *fps);
                enc.encode_frame(image::Frame::from_parts(img, 0, 0, delay))
                    .map_err(|e| CliError::Draw(e.to_string()))
            }
            FrameSink::Mp4(child) => {
                use std::io::Write;
                let stdin = child.stdin.as_mut().expect("piped");
                stdin
                    .write_all(&rgb)
                    .map_err(|e| CliError::Draw(format!("ffmpeg stopped reading frames: {e}")))
            }
        }
    }

    fn finish(self) -> CliResult<()> {
        match self {
            FrameSink::Gif(enc, ..) => {
                drop(enc);
                Ok(())
            }
            FrameSink::Mp4(mut child) => {
                drop(child.stdin.take());
                let status = child
                    .wait()
                    .map_err(|e| CliError::Draw(format!("ffmpeg: {e}")))?;
                if status.success() {
                    Ok(())
                } else {
                    Err(CliError::Draw(format!("ffmpeg failed ({status})")))
                }
            }
        }
    }
}
