//! Time histories from a `simulate` CSV: columns by name or pattern, panels, decimation.

use super::render::*;
use super::Size;
use crate::cli::error::{CliError, CliResult};
use plotters::coord::Shift;
use plotters::prelude::*;
use std::path::{Path, PathBuf};

// ---------------------------------------------------------------- CSV

/// The largest CSV a plot reads: 3.5 × 10^6 rows of the 65-column design example (4.5 GB in memory).
pub const MAX_CSV_BYTES: u64 = 512 << 20;

/// A CSV of numbers with a header (as `simulate` writes it).
#[derive(Debug, Clone, PartialEq)]
pub struct CsvData {
    /// The file it was read from.
    pub path: PathBuf,
    /// The column names, in file order.
    pub header: Vec<String>,
    /// Column-major.
    pub columns: Vec<Vec<f64>>,
}

impl CsvData {
    /// Read at most [`MAX_CSV_BYTES`] of `path` (an endless or larger input is refused).
    pub fn read(path: &Path) -> CliResult<CsvData> {
        use std::io::Read;
        let err = |error| CliError::Io {
            what: "read",
            path: path.display().to_string(),
            error,
        };
        let mut text = String::new();
        std::fs::File::open(path)
            .map_err(err)?
            .take(MAX_CSV_BYTES + 1)
            .read_to_string(&mut text)
            .map_err(err)?;
        if text.len() as u64 > MAX_CSV_BYTES {
            return Err(CliError::Usage(format!(
                "{}: more than {} MiB, the most a plot reads (simulate --output-rate writes fewer rows)",
                path.display(),
                MAX_CSV_BYTES >> 20
            )));
        }
        Self::parse(&text, path)
    }

    /// Parse the text of a CSV (`path` names it in errors).
    pub fn parse(text: &str, path: &Path) -> CliResult<CsvData> {
        let mut lines = text
            .lines()
            .enumerate()
            .filter(|(_, l)| !l.trim().is_empty());
        let (_, head) = lines.next().ok_or_else(|| {
            CliError::Usage(format!(
                "{}: empty file, expected a CSV header",
                path.display()
            ))
        })?;
        let header: Vec<String> = head.split(',').map(|s| s.trim().to_string()).collect();
        if header.iter().any(|h| h.parse::<f64>().is_ok()) {
            return Err(CliError::Usage(format!(
                "{}: the first line must be the header (column names), found numbers",
                path.display()
            )));
        }
        let mut columns = vec![Vec::new(); header.len()];
        for (no, line) in lines {
            let cells: Vec<&str> = line.split(',').collect();
            if cells.len() != header.len() {
                return Err(CliError::Usage(format!(
                    "{}:{}: {} cells, the header has {}",
                    path.display(),
                    no + 1,
                    cells.len(),
                    header.len()
                )));
            }
            for (j, c) in cells.iter().enumerate() {
                let v = c.trim().parse::<f64>().map_err(|_| {
                    CliError::Usage(format!(
                        "{}:{}: column {} is not a number: {:?}",
                        path.display(),
                        no + 1,
                        header[j],
                        c.trim()
                    ))
                })?;
                columns[j].push(v);
            }
        }
        if columns.first().is_none_or(|c| c.is_empty()) {
            return Err(CliError::Usage(format!("{}: no data rows", path.display())));
        }
        Ok(CsvData {
            path: path.to_path_buf(),
            header,
            columns,
        })
    }

    /// The column named `name`; an error names the columns there are.
    pub fn column(&self, name: &str) -> CliResult<&[f64]> {
        match self.header.iter().position(|h| h == name) {
            Some(j) => Ok(&self.columns[j]),
            None => Err(CliError::Usage(format!(
                "unknown column {name:?} in {}; it has {}",
                self.path.display(),
                summarize_names(&self.header)
            ))),
        }
    }

    /// Column names of a comma list, `*` patterns expanded (in file order).
    pub fn expand(&self, spec: &str) -> CliResult<Vec<String>> {
        let mut out = Vec::new();
        for item in spec.split(',').map(str::trim).filter(|s| !s.is_empty()) {
            if item.contains('*') {
                let hits: Vec<&String> =
                    self.header.iter().filter(|h| glob_match(item, h)).collect();
                if hits.is_empty() {
                    return Err(CliError::Usage(format!(
                        "no column matches {item:?} in {}; it has {}",
                        self.path.display(),
                        summarize_names(&self.header)
                    )));
                }
                out.extend(hits.into_iter().cloned());
            } else {
                self.column(item)?;
                out.push(item.to_string());
            }
        }
        if out.is_empty() {
            return Err(CliError::Usage(format!("empty column list {spec:?}")));
        }
        Ok(out)
    }
}

/// `*` matches any run of characters.
pub(crate) fn glob_match(pattern: &str, s: &str) -> bool {
    let parts: Vec<&str> = pattern.split('*').collect();
    if parts.len() == 1 {
        return pattern == s;
    }
    let (first, last) = (parts[0], parts[parts.len() - 1]);
    if !s.starts_with(first)
        || !s[first.len()..].ends_with(last)
        || s.len() < first.len() + last.len()
    {
        return false;
    }
    let mut rest = &s[first.len()..s.len() - last.len()];
    for p in &parts[1..parts.len() - 1] {
        match rest.find(p) {
            Some(i) => rest = &rest[i + p.len()..],
            None => return false,
        }
    }
    true
}

/// `time, joint_position, q1..q30, qale1..qale30, ale1_uz` — runs of numbered names shortened.
pub fn summarize_names(names: &[String]) -> String {
    let split = |s: &str| -> (String, Option<u64>, String) {
        // prefix, number, suffix: the first run of digits.
        let b = s.as_bytes();
        match b.iter().position(|c| c.is_ascii_digit()) {
            Some(i) => {
                let j = b[i..]
                    .iter()
                    .position(|c| !c.is_ascii_digit())
                    .map_or(b.len(), |n| i + n);
                (s[..i].to_string(), s[i..j].parse().ok(), s[j..].to_string())
            }
            None => (s.to_string(), None, String::new()),
        }
    };
    let mut out: Vec<String> = Vec::new();
    let mut i = 0;
    while i < names.len() {
        let (p, n, x) = split(&names[i]);
        let mut j = i;
        if let Some(n0) = n {
            while j + 1 < names.len() {
                let (p2, n2, x2) = split(&names[j + 1]);
                if p2 == p && x2 == x && n2 == Some(n0 + (j + 1 - i) as u64) {
                    j += 1;
                } else {
                    break;
                }
            }
        }
        if j > i + 1 {
            out.push(format!("{}..{}", names[i], names[j]));
        } else {
            out.extend(names[i..=j].iter().cloned());
        }
        i = j + 1;
    }
    out.join(", ")
}

/// Default axis label for a panel's columns.
pub fn auto_ylabel(names: &[String]) -> String {
    let all = |f: &dyn Fn(&str) -> bool| names.iter().all(|n| f(n));
    let numbered = |n: &str, prefix: &str| {
        n.strip_prefix(prefix)
            .is_some_and(|r| !r.is_empty() && r.bytes().all(|c| c.is_ascii_digit()))
    };
    if all(&|n| numbered(n, "qale")) {
        "ALE modal amplitude (m)".into()
    } else if all(&|n| numbered(n, "q")) {
        "Lagrangian modal amplitude (m)".into()
    } else if all(&|n| numbered(n, "q") || numbered(n, "qale")) {
        "modal amplitude (m)".into()
    } else if all(&|n| n.ends_with("_uz")) {
        "transverse displacement (m)".into()
    } else if all(&|n| n == "joint_velocity") {
        "joint speed (rad/s)".into()
    } else if all(&|n| n == "joint_position") {
        "joint angle (rad)".into()
    } else {
        with_units(names)
    }
}

/// Column names with their units (`simulate::column_unit`): one unit for
/// all, `pad1_normal_force, pad2_normal_force (N)`; otherwise each its own,
/// `joint_effort (N·m), pad1_normal_force (N)`. A column of another CSV
/// keeps its bare name.
fn with_units(names: &[String]) -> String {
    use crate::cli::simulate::column_unit;
    let units: Vec<Option<&str>> = names.iter().map(|n| column_unit(n)).collect();
    match units.first() {
        Some(Some(u)) if units.iter().all(|x| x == &Some(*u)) => {
            format!("{} ({u})", names.join(", "))
        }
        _ => names
            .iter()
            .zip(&units)
            .map(|(n, u)| u.map_or_else(|| n.clone(), |u| format!("{n} ({u})")))
            .collect::<Vec<_>>()
            .join(", "),
    }
}

/// Pixel geometry of one chart panel.
#[derive(Debug, Clone, PartialEq)]
pub struct PanelGeometry {
    /// Plotting area in pixels: x from left to right, y from top to bottom (exclusive ends).
    pub x_px: (i32, i32),
    /// Plotting area's y pixels, top to bottom (exclusive end).
    pub y_px: (i32, i32),
    /// Data ranges mapped onto it (x left → right, y bottom → top).
    pub x_range: (f64, f64),
    /// Data range of y (bottom → top).
    pub y_range: (f64, f64),
}

impl PanelGeometry {
    /// Pixel of a data point (plotters' own linear mapping).
    pub fn to_px(&self, x: f64, y: f64) -> (f64, f64) {
        let (x0, x1) = (self.x_px.0 as f64, (self.x_px.1 - 1) as f64);
        let (y0, y1) = (self.y_px.0 as f64, (self.y_px.1 - 1) as f64);
        (
            x0 + (x - self.x_range.0) / (self.x_range.1 - self.x_range.0) * (x1 - x0),
            y1 - (y - self.y_range.0) / (self.y_range.1 - self.y_range.0) * (y1 - y0),
        )
    }
}

/// Stacked time-history panels from a CSV.
pub struct CsvPlot<'a> {
    /// The CSV.
    pub data: &'a CsvData,
    /// The column on the horizontal axis.
    pub x: &'a str,
    /// The columns of each panel, top to bottom.
    pub panels: Vec<Vec<String>>,
    /// Axis label per panel (missing ones from the column names).
    pub ylabels: Vec<String>,
    /// Title above the panels.
    pub title: Option<String>,
}

impl CsvPlot<'_> {
    /// Draw to `out` (.png or .svg); where each panel was drawn.
    pub fn render(&self, out: &Path, size: Size) -> CliResult<Vec<PanelGeometry>> {
        self.data.column(self.x)?;
        for p in &self.panels {
            for c in p {
                self.data.column(c)?;
            }
        }
        render(out, size, self)
    }
}

/// A 2-px polyline through pixel vertices: Bresenham per segment, a 2×2 brush,
/// clipped to `clip` = (x0, x1, y0, y1) (exclusive ends).
pub(super) fn thick_polyline<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    pts: &[(i32, i32)],
    color: RGBColor,
    clip: (i32, i32, i32, i32),
) -> CliResult<()> {
    let dot = |x: i32, y: i32| -> CliResult<()> {
        for (dx, dy) in [(0, 0), (1, 0), (0, 1), (1, 1)] {
            let (px, py) = (x + dx, y + dy);
            if px >= clip.0 && px < clip.1 && py >= clip.2 && py < clip.3 {
                area.draw_pixel((px, py), &color).map_err(de)?;
            }
        }
        Ok(())
    };
    if let [only] = pts {
        return dot(only.0, only.1);
    }
    for w in pts.windows(2) {
        let ((mut x, mut y), (x1, y1)) = (w[0], w[1]);
        let (dx, dy) = ((x1 - x).abs(), -(y1 - y).abs());
        let (sx, sy) = (if x < x1 { 1 } else { -1 }, if y < y1 { 1 } else { -1 });
        let mut err = dx + dy;
        loop {
            dot(x, y)?;
            if x == x1 && y == y1 {
                break;
            }
            let e2 = 2 * err;
            if e2 >= dy {
                err += dy;
                x += sx;
            }
            if e2 <= dx {
                err += dx;
                y += sy;
            }
        }
    }
    Ok(())
}

/// At most ~4 points per horizontal pixel: per pixel column the first, lowest,
/// highest and last sample (every vertex is a data point).
pub(super) fn decimate(x: &[f64], y: &[f64], x_range: (f64, f64), px: usize) -> Vec<(f64, f64)> {
    if x.len() <= 4 * px.max(1) {
        return x.iter().copied().zip(y.iter().copied()).collect();
    }
    let bucket = |v: f64| (((v - x_range.0) / (x_range.1 - x_range.0)) * px as f64).floor() as i64;
    let mut out = Vec::new();
    let mut i = 0;
    while i < x.len() {
        let b = bucket(x[i]);
        let mut j = i;
        let (mut lo, mut hi) = (i, i);
        while j + 1 < x.len() && bucket(x[j + 1]) == b {
            j += 1;
            if y[j] < y[lo] {
                lo = j;
            }
            if y[j] > y[hi] {
                hi = j;
            }
        }
        let mut idx = vec![i, lo, hi, j];
        idx.sort_unstable();
        idx.dedup();
        out.extend(idx.into_iter().map(|k| (x[k], y[k])));
        i = j + 1;
    }
    out
}

pub(super) fn padded_range(values: impl Iterator<Item = f64>) -> (f64, f64) {
    let (lo, hi) = values
        .filter(|v| v.is_finite())
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| {
            (a.min(v), b.max(v))
        });
    if !lo.is_finite() {
        return (-1.0, 1.0);
    }
    if hi - lo <= 1e-12 * hi.abs().max(lo.abs()) {
        let d = if lo == 0.0 { 1.0 } else { 0.1 * lo.abs() };
        return (lo - d, hi + d);
    }
    let pad = 0.05 * (hi - lo);
    (lo - pad, hi + pad)
}

impl Painter for CsvPlot<'_> {
    type Out = Vec<PanelGeometry>;
    fn paint<DB: DrawingBackend>(
        &self,
        root: &DrawingArea<DB, Shift>,
        format: Format,
    ) -> CliResult<Vec<PanelGeometry>> {
        let area = match &self.title {
            Some(t) => {
                let (top, rest) = root.split_vertically(44);
                draw_title(&top, t, 24.0)?;
                rest
            }
            None => root.clone(),
        };
        let x = self.data.column(self.x)?;
        let x_range = padded_range(x.iter().copied());
        let x_range = {
            let (lo, hi) = x
                .iter()
                .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &v| {
                    (a.min(v), b.max(v))
                });
            if hi > lo {
                (lo, hi)
            } else {
                x_range
            }
        };
        let x_label = if self.x == "time" {
            "time (s)".to_string()
        } else {
            self.x.to_string()
        };
        let mut geometry = Vec::new();
        let areas = area.split_evenly((self.panels.len(), 1));
        for (pi, (pa, names)) in areas.iter().zip(&self.panels).enumerate() {
            let ys: Vec<&[f64]> = names
                .iter()
                .map(|n| self.data.column(n))
                .collect::<CliResult<_>>()?;
            let y_range = padded_range(ys.iter().flat_map(|c| c.iter().copied()));
            let mut chart = ChartBuilder::on(pa)
                .margin(14)
                .x_label_area_size(48)
                .y_label_area_size(96)
                .build_cartesian_2d(x_range.0..x_range.1, y_range.0..y_range.1)
                .map_err(de)?;
            let (xs, ys_span) = (x_range.1 - x_range.0, y_range.1 - y_range.0);
            let ylabel = self
                .ylabels
                .get(pi)
                .cloned()
                .unwrap_or_else(|| auto_ylabel(names));
            chart
                .configure_mesh()
                .x_desc(x_label.as_str())
                .y_desc(ylabel.as_str())
                .x_label_formatter(&|v| tick(*v, xs))
                .y_label_formatter(&|v| tick(*v, ys_span))
                .label_style((FONT, 15))
                .axis_desc_style((FONT, 17))
                .light_line_style(RGBColor(246, 246, 246))
                .bold_line_style(RGBColor(220, 220, 220))
                .draw()
                .map_err(de)?;
            let (px_x, px_y) = chart.plotting_area().get_pixel_range();
            let width_px = (px_x.end - px_x.start).max(1) as usize;
            for (si, (name, y)) in names.iter().zip(&ys).enumerate() {
                let color = PALETTE[si % PALETTE.len()];
                let mut pts = decimate(x, y, x_range, width_px);
                // No two consecutive vertices on one pixel: plotters widens a
                // zero-length segment of a 2-px line into a spike across the picture.
                let mut last: Option<(i32, i32)> = None;
                pts.retain(|p| {
                    let px = chart.backend_coord(p);
                    let keep = last != Some(px);
                    last = Some(px);
                    keep
                });
                // SVG: one 2-px polyline (viewers join it properly). PNG: plotters
                // fills a >1-px line as a polygon, and its rasteriser turns the sharp
                // reversals of a dense history into spikes across the picture (and
                // its 1-px lines are anti-aliased, dropping end pixels): drawn here
                // pixel by pixel instead, every vertex included.
                let series = match format {
                    Format::Svg => chart.draw_series(LineSeries::new(pts, color.stroke_width(2))),
                    Format::Png => {
                        let px: Vec<(i32, i32)> =
                            pts.iter().map(|p| chart.backend_coord(p)).collect();
                        let clip = (px_x.start, px_x.end, px_y.start, px_y.end);
                        thick_polyline(root, &px, color, clip)?;
                        chart.draw_series(std::iter::empty::<PathElement<(f64, f64)>>())
                    }
                };
                series
                    .map_err(de)?
                    .label(name.as_str())
                    .legend(move |(lx, ly)| {
                        PathElement::new(vec![(lx, ly), (lx + 22, ly)], color.stroke_width(3))
                    });
            }
            chart
                .configure_series_labels()
                .position(SeriesLabelPosition::UpperRight)
                .background_style(WHITE.mix(0.85))
                .border_style(RGBColor(160, 160, 160))
                .label_font((FONT, 15))
                .draw()
                .map_err(de)?;
            geometry.push(PanelGeometry {
                x_px: (px_x.start, px_x.end),
                y_px: (px_y.start, px_y.end),
                x_range,
                y_range,
            });
        }
        Ok(geometry)
    }
}
