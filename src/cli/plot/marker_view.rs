//! `plot marker BAG --out F.png [--at S]`: a `~/plate_marker` message of a
//! recorded bag drawn as RViz would draw its triangle list — the same
//! triangles and per-vertex colours, seen from above at an angle in the
//! marker's own frame (`plate_rotor`), back to front — for a look at a
//! recording without RViz or Foxglove (docs/ros.md's pictures come from here).
//! The bag is read with the `mcap` crate; the CDR payload is decoded into the
//! node's own MarkerArray struct.

use super::render::{de, ensure_fonts, FONT};
use super::Size;
use crate::cli::error::{CliError, CliResult};
use crate::messages::visualization::{Marker, MarkerArray, Point};
use byteorder::LittleEndian;
use plotters::prelude::*;
use ros2_client::dds::rustdds::cdr_encoding;
use std::path::{Path, PathBuf};

/// The `.mcap` file of a rosbag2 directory (or the file itself).
fn mcap_file(bag: &Path) -> CliResult<PathBuf> {
    if bag.is_file() {
        return Ok(bag.to_path_buf());
    }
    let entries = std::fs::read_dir(bag).map_err(|error| CliError::Io {
        what: "read",
        path: bag.display().to_string(),
        error,
    })?;
    entries
        .filter_map(|e| e.ok().map(|e| e.path()))
        .find(|p| p.extension().is_some_and(|e| e == "mcap"))
        .ok_or_else(|| {
            CliError::Usage(format!(
                "{}: no .mcap file in this bag directory",
                bag.display()
            ))
        })
}

/// Every message of the topic ending in `/plate_marker`: (log time ns, message).
pub fn read_markers(bag: &Path) -> CliResult<Vec<(u64, MarkerArray)>> {
    let path = mcap_file(bag)?;
    let bytes = std::fs::read(&path).map_err(|error| CliError::Io {
        what: "read",
        path: path.display().to_string(),
        error,
    })?;
    let stream = mcap::MessageStream::new(&bytes).map_err(|e| {
        CliError::Usage(format!("{}: not a readable MCAP file: {e}", path.display()))
    })?;
    let mut out = Vec::new();
    for m in stream {
        let m = m.map_err(|e| CliError::Usage(format!("{}: {e}", path.display())))?;
        if !m.channel.topic.ends_with("/plate_marker") {
            continue;
        }
        let payload = m.data.get(4..).ok_or_else(|| {
            CliError::Usage(format!(
                "{}: a marker message without a CDR header",
                path.display()
            ))
        })?;
        let (array, _) =
            cdr_encoding::from_bytes::<MarkerArray, LittleEndian>(payload).map_err(|e| {
                CliError::Usage(format!(
                    "{}: a marker message does not decode: {e}",
                    path.display()
                ))
            })?;
        out.push((m.log_time, array));
    }
    if out.is_empty() {
        return Err(CliError::Usage(format!(
            "{}: no ~/plate_marker messages (was ros.marker_rate_hz 0?)",
            bag.display()
        )));
    }
    Ok(out)
}

/// A projected triangle: its corners on screen, its depth, its colour.
type ScreenTriangle = ([(f64, f64); 3], f64, RGBColor);

/// The view: azimuth and elevation of the camera, degrees.
const AZIMUTH: f64 = -60.0;
const ELEVATION: f64 = 35.0;

/// Screen coordinates (right, up) and depth (towards the camera) of a point.
fn project(p: &Point) -> (f64, f64, f64) {
    let (a, e) = (AZIMUTH.to_radians(), ELEVATION.to_radians());
    let right = p.x * a.cos() - p.y * a.sin();
    let towards = p.x * a.sin() + p.y * a.cos();
    let up = p.z * e.cos() - towards * e.sin();
    let depth = p.z * e.sin() + towards * e.cos();
    (right, up, -depth)
}

/// Draw the triangle list of `array` (and its text) to `out` (.png or .svg).
pub(crate) fn render_marker(
    array: &MarkerArray,
    caption: &str,
    out: &Path,
    size: Size,
) -> CliResult<()> {
    let mesh = array
        .markers
        .iter()
        .find(|m| m.kind == Marker::TRIANGLE_LIST)
        .ok_or_else(|| CliError::Usage("the marker message has no triangle list".into()))?;
    let mut triangles: Vec<ScreenTriangle> = mesh
        .points
        .chunks_exact(3)
        .zip(mesh.colors.chunks_exact(3))
        .map(|(p, c)| {
            let q = [project(&p[0]), project(&p[1]), project(&p[2])];
            let depth = (q[0].2 + q[1].2 + q[2].2) / 3.0;
            let avg = |f: fn(&crate::messages::visualization::ColorRGBA) -> f32| {
                ((f(&c[0]) + f(&c[1]) + f(&c[2])) / 3.0 * 255.0).round() as u8
            };
            (
                [(q[0].0, q[0].1), (q[1].0, q[1].1), (q[2].0, q[2].1)],
                depth,
                RGBColor(avg(|c| c.r), avg(|c| c.g), avg(|c| c.b)),
            )
        })
        .collect();
    // Back to front.
    triangles.sort_by(|a, b| b.1.total_cmp(&a.1));
    let extent = triangles
        .iter()
        .flat_map(|t| t.0)
        .fold(0.0f64, |m, (x, y)| m.max(x.abs()).max(y.abs()));
    ensure_fonts();
    let draw = |root: DrawingArea<BitMapBackend, plotters::coord::Shift>| -> CliResult<()> {
        root.fill(&WHITE).map_err(de)?;
        let (w, h) = (size.width as f64, size.height as f64);
        let k = 0.45 * w.min(h - 60.0) / extent.max(1e-12);
        let to_px = |(x, y): (f64, f64)| {
            (
                (w / 2.0 + k * x) as i32,
                (30.0 + (h - 30.0) / 2.0 - k * y) as i32,
            )
        };
        for (tri, _, colour) in &triangles {
            let px: Vec<(i32, i32)> = tri.iter().map(|&p| to_px(p)).collect();
            root.draw(&Polygon::new(px.clone(), colour.filled()))
                .map_err(de)?;
            root.draw(&PathElement::new(
                vec![px[0], px[1], px[2], px[0]],
                colour.stroke_width(1),
            ))
            .map_err(de)?;
        }
        root.draw(&Text::new(
            caption.to_string(),
            (10, 8),
            (FONT, 16).into_font().color(&BLACK),
        ))
        .map_err(de)?;
        root.present().map_err(de)
    };
    match out.extension().and_then(|e| e.to_str()) {
        Some("png") => draw(BitMapBackend::new(out, (size.width, size.height)).into_drawing_area()),
        _ => Err(CliError::Usage(format!(
            "--out {}: the name must end in .png",
            out.display()
        ))),
    }
}

/// `plot marker`: the message logged at or just after `at` seconds from the bag's first marker.
pub(crate) fn plot_marker(
    bag: &Path,
    at: Option<f64>,
    out: &Path,
    size: Size,
) -> CliResult<(u64, usize)> {
    let markers = read_markers(bag)?;
    let t0 = markers[0].0;
    let want = at.map_or(markers.last().unwrap().0, |s| {
        t0 + (s.max(0.0) * 1e9) as u64
    });
    let (t, array) = markers
        .iter()
        .find(|(t, _)| *t >= want)
        .unwrap_or(markers.last().unwrap());
    let mesh = array
        .markers
        .iter()
        .find(|m| m.kind == Marker::TRIANGLE_LIST);
    let scale = mesh
        .and_then(|m| m.text.split("scale=").nth(1))
        .and_then(|s| s.split_whitespace().next())
        .and_then(|s| s.parse::<f64>().ok());
    let scale = scale.map_or("?".to_string(), |s| format!("{s:.4}"));
    let caption = format!(
        "~/plate_marker at {:.3} s from {}: deflection drawn x{scale}",
        *t as f64 * 1e-9,
        bag.display()
    );
    render_marker(array, &caption, out, size)?;
    Ok((*t, mesh.map_or(0, |m| m.points.len() / 3)))
}
