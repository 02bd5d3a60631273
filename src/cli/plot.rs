//! `annular_plate plot ...`: pictures, PNG or SVG (by the output's extension),
//! drawn with plotters; text in DejaVu Sans embedded in the binary.
//!
//! - `plot csv FILE --columns q2,q3 [--panel qale2,qale3 ...] --out F`: time
//!   histories from a `simulate` CSV, one panel per column list (the paper's
//!   Figs. 9, 15, 17);
//! - `plot modes PARAMS --out F [--k 0,1,2 --l 0,1]`: a grid of ⟨k, l⟩ mode
//!   shapes seen from above, sign-coloured, with their nodal lines (Fig. 2);
//! - `plot mode PARAMS (--index N | --k K --l L) --out F`: one mode as a
//!   shaded surface beside its top view (Fig. 3).
//!
//! The drawing functions return the pixel geometry they used, so tests can
//! check that a curve or a nodal line is where the data puts it.

use crate::config::{Config, Params};
use crate::model::{AngularShape, PlateModel};
use crate::study::StudyReport;
use anyhow::{anyhow, bail, Context};
use plotters::coord::Shift;
use plotters::element::DashedPathElement;
use plotters::prelude::*;
use std::f64::consts::{PI, TAU};
use std::path::{Path, PathBuf};
use std::str::FromStr;

// ---------------------------------------------------------------- CLI

/// Picture size in pixels, `WIDTHxHEIGHT`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Size {
    pub width: u32,
    pub height: u32,
}

impl FromStr for Size {
    type Err = String;
    fn from_str(s: &str) -> Result<Size, String> {
        let bad = || format!("size must be WIDTHxHEIGHT in pixels (e.g. 1200x800), got {s:?}");
        let (w, h) = s.split_once(['x', 'X']).ok_or_else(bad)?;
        let (width, height) = (w.trim().parse::<u32>().map_err(|_| bad())?, h.trim().parse::<u32>().map_err(|_| bad())?);
        if !(100..=10_000).contains(&width) || !(100..=10_000).contains(&height) {
            return Err(format!("size {width}x{height}: each side must be 100..10000 pixels"));
        }
        Ok(Size { width, height })
    }
}

impl std::fmt::Display for Size {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{}x{}", self.width, self.height)
    }
}

#[derive(clap::Subcommand, Debug, Clone)]
pub enum PlotCommand {
    /// Time histories from a `simulate` CSV: one panel per column list, stacked.
    Csv {
        /// The CSV written by `annular_plate simulate`.
        file: PathBuf,
        /// Columns of the first panel, comma-separated; `*` matches any text (e.g. `ale*_uz`).
        #[arg(long, value_name = "LIST")]
        columns: Option<String>,
        /// A further panel below the others (repeatable), columns as for --columns.
        #[arg(long = "panel", value_name = "LIST")]
        panels: Vec<String>,
        /// The column on the horizontal axis.
        #[arg(long, default_value = "time")]
        x: String,
        /// Axis label of each panel, in panel order (repeatable); default from the column names.
        #[arg(long = "ylabel", value_name = "TEXT")]
        ylabels: Vec<String>,
        #[arg(long)]
        title: Option<String>,
        /// Output file, .png or .svg.
        #[arg(long)]
        out: PathBuf,
        #[arg(long, default_value = "1200x800")]
        size: Size,
    },
    /// A grid of mode shapes seen from above (rows: nodal circles l, columns: nodal diameters k).
    Modes {
        /// Params file (ROS 2 format) giving the plate.
        params: PathBuf,
        /// Parameter overrides `-p name:=value` (as after --ros-args), e.g. -p plate.inner_boundary:=supported.
        #[arg(short = 'p', long = "param", value_name = "NAME:=VALUE")]
        overrides: Vec<String>,
        /// Nodal diameters to show (default: the file's, at most 8).
        #[arg(long, value_delimiter = ',')]
        k: Option<Vec<u32>>,
        /// Nodal circles to show (default: the file's, at most 4).
        #[arg(long, value_delimiter = ',')]
        l: Option<Vec<u32>>,
        #[arg(long)]
        title: Option<String>,
        #[arg(long)]
        out: PathBuf,
        /// Picture size; default: 230 × 250 pixels per mode.
        #[arg(long)]
        size: Option<Size>,
    },
    /// One mode as a shaded surface beside its top view.
    Mode {
        params: PathBuf,
        #[arg(short = 'p', long = "param", value_name = "NAME:=VALUE")]
        overrides: Vec<String>,
        /// Mode number as listed by `annular_plate modes` (from 1).
        #[arg(long, conflicts_with_all = ["k", "l"])]
        index: Option<usize>,
        /// Nodal diameters of the mode (with --l).
        #[arg(long, requires = "l")]
        k: Option<u32>,
        /// Nodal circles of the mode (with --k).
        #[arg(long, requires = "k")]
        l: Option<u32>,
        /// cos or sin (for k ≥ 1; default cos).
        #[arg(long, default_value = "cos")]
        shape: String,
        #[arg(long)]
        title: Option<String>,
        #[arg(long)]
        out: PathBuf,
        #[arg(long, default_value = "1400x640")]
        size: Size,
    },
}

pub fn main(cmd: PlotCommand) -> anyhow::Result<()> {
    match cmd {
        PlotCommand::Csv { file, columns, panels, x, ylabels, title, out, size } => {
            let data = CsvData::read(&file)?;
            let mut specs: Vec<String> = columns.into_iter().collect();
            specs.extend(panels);
            if specs.is_empty() {
                bail!("give the columns to plot: --columns LIST (and --panel LIST for more panels); {} has {}", file.display(), summarize_names(&data.header));
            }
            let panels = specs.iter().map(|s| data.expand(s)).collect::<anyhow::Result<Vec<_>>>()?;
            let plot = CsvPlot { data: &data, x: &x, panels, ylabels, title };
            plot.render(&out, size)?;
        }
        PlotCommand::Modes { params, overrides, k, l, title, out, size } => {
            let config = load_with_overrides(&params, &overrides)?;
            let ks = k.unwrap_or_else(|| first_sorted(&config.plate.nodal_diameters, 8));
            let ls = l.unwrap_or_else(|| first_sorted(&config.plate.nodal_circles, 4));
            let size = size.unwrap_or(Size { width: (230 * ks.len() as u32).max(400) + 20, height: 250 * ls.len() as u32 + 70 });
            mode_grid(&config, &ks, &ls, title.as_deref(), &out, size)?;
        }
        PlotCommand::Mode { params, overrides, index, k, l, shape, title, out, size } => {
            let config = load_with_overrides(&params, &overrides)?;
            let which = match (index, k, l) {
                (Some(i), _, _) => ModeChoice::Index(i),
                (None, Some(k), Some(l)) => {
                    let shape = match shape.as_str() {
                        "cos" => AngularShape::Cos,
                        "sin" => AngularShape::Sin,
                        other => bail!("--shape must be cos or sin, got {other:?}"),
                    };
                    ModeChoice::KL { k, l, shape }
                }
                _ => bail!("say which mode: --index N (as numbered by `annular_plate modes`) or --k K --l L"),
            };
            mode_picture(&config, which, title.as_deref(), &out, size)?;
        }
    }
    Ok(())
}

fn first_sorted(v: &[u32], n: usize) -> Vec<u32> {
    let mut v = v.to_vec();
    v.sort_unstable();
    v.truncate(n);
    v
}

/// Read a params file and apply `name:=value` overrides.
pub fn load_with_overrides(path: &Path, overrides: &[String]) -> anyhow::Result<Config> {
    if overrides.is_empty() {
        return super::load_config(path);
    }
    let mut params = Params::from_file(path, super::DEFAULT_NODE_NAME).map_err(|e| anyhow!("{}: {e}", path.display()))?;
    for o in overrides {
        let (name, value) = o.split_once(":=").ok_or_else(|| anyhow!("-p {o:?}: expected NAME:=VALUE"))?;
        params.set_override(name.trim(), value.trim()).map_err(|e| anyhow!("-p {o}: {e}"))?;
    }
    Config::from_params(&params).map_err(|e| anyhow!("{} (with -p overrides): {e}", path.display()))
}

// ---------------------------------------------------------------- output

/// Picture format, from the output's extension.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Format {
    Png,
    Svg,
}

pub fn format_of(path: &Path) -> anyhow::Result<Format> {
    match path.extension().and_then(|e| e.to_str()).map(|e| e.to_ascii_lowercase()).as_deref() {
        Some("png") => Ok(Format::Png),
        Some("svg") => Ok(Format::Svg),
        _ => bail!("output {}: the name must end in .png or .svg", path.display()),
    }
}

/// The output's format is known and its folder exists.
pub fn check_output_path(path: &Path) -> anyhow::Result<()> {
    format_of(path)?;
    if let Some(dir) = path.parent().filter(|d| !d.as_os_str().is_empty()) {
        if !dir.is_dir() {
            bail!("output {}: folder {} does not exist", path.display(), dir.display());
        }
    }
    Ok(())
}

fn de<E: std::fmt::Debug>(e: E) -> anyhow::Error {
    anyhow!("drawing failed: {e:?}")
}

const FONT: &str = "sans-serif";

/// Register the embedded DejaVu Sans with plotters (once).
pub fn ensure_fonts() {
    static ONCE: std::sync::Once = std::sync::Once::new();
    ONCE.call_once(|| {
        let _ = plotters::style::register_font(FONT, FontStyle::Normal, dejavu::sans::regular());
        let _ = plotters::style::register_font(FONT, FontStyle::Bold, dejavu::sans::bold());
    });
}

/// Something that draws itself on any plotters backend.
trait Painter {
    type Out;
    /// `format`: what the backend writes (PNG and SVG draw thick polylines differently).
    fn paint<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>, format: Format) -> anyhow::Result<Self::Out>;
}

fn render<P: Painter>(path: &Path, size: Size, painter: &P) -> anyhow::Result<P::Out> {
    check_output_path(path)?;
    ensure_fonts();
    let dims = (size.width, size.height);
    let write_err = |e: &dyn std::fmt::Debug| anyhow!("cannot write {}: {e:?}", path.display());
    match format_of(path)? {
        Format::Png => {
            // Drawn into memory, then encoded with the best PNG compression
            // (smooth mode-shape fields compress poorly at plotters' default).
            let mut pixels = vec![0u8; 3 * size.width as usize * size.height as usize];
            let out = {
                let root = BitMapBackend::with_buffer(&mut pixels, dims).into_drawing_area();
                root.fill(&WHITE).map_err(de)?;
                let out = painter.paint(&root, Format::Png)?;
                root.present().map_err(|e| write_err(&e))?;
                out
            };
            let file = std::fs::File::create(path).map_err(|e| write_err(&e))?;
            let encoder = image::codecs::png::PngEncoder::new_with_quality(
                std::io::BufWriter::new(file),
                image::codecs::png::CompressionType::Best,
                image::codecs::png::FilterType::Adaptive,
            );
            image::ImageEncoder::write_image(encoder, &pixels, size.width, size.height, image::ColorType::Rgb8).map_err(|e| write_err(&e))?;
            Ok(out)
        }
        Format::Svg => {
            let root = SVGBackend::new(path, dims).into_drawing_area();
            root.fill(&WHITE).map_err(de)?;
            let out = painter.paint(&root, Format::Svg)?;
            root.present().map_err(|e| write_err(&e))?;
            Ok(out)
        }
    }
}

/// A title centred on `area`, its font shrunk until it fits the width.
fn draw_title<DB: DrawingBackend>(area: &DrawingArea<DB, Shift>, text: &str, size: f64) -> anyhow::Result<()> {
    let (w, h) = area.dim_in_pixel();
    let mut size = size;
    while size > 9.0 {
        let (tw, _) = area.estimate_text_size(text, &TextStyle::from((FONT, size).into_font())).map_err(de)?;
        if tw + 24 <= w {
            break;
        }
        size -= 1.0;
    }
    let style = TextStyle::from((FONT, size).into_font()).pos(plotters::style::text_anchor::Pos::new(
        plotters::style::text_anchor::HPos::Center,
        plotters::style::text_anchor::VPos::Center,
    ));
    area.draw(&Text::new(text.to_string(), (w as i32 / 2, h as i32 / 2), style)).map_err(de)?;
    Ok(())
}

/// Distinguishable line colours (Tableau 10).
pub const PALETTE: [RGBColor; 10] = [
    RGBColor(31, 119, 180),
    RGBColor(214, 39, 40),
    RGBColor(44, 160, 44),
    RGBColor(255, 127, 14),
    RGBColor(148, 103, 189),
    RGBColor(140, 86, 75),
    RGBColor(227, 119, 194),
    RGBColor(127, 127, 127),
    RGBColor(188, 189, 34),
    RGBColor(23, 190, 207),
];

/// A tick label: plain for moderate magnitudes, otherwise with an exponent.
fn tick(v: f64, span: f64) -> String {
    if v.abs() <= 1e-9 * span.abs() {
        return "0".into();
    }
    let mag = v.abs().max(span.abs());
    if (1e-2..1e5).contains(&mag) {
        let decimals = (2.0 - span.abs().log10().floor()).clamp(0.0, 6.0) as usize;
        format!("{v:.decimals$}")
    } else {
        let e = mag.log10().floor() as i32;
        let digits = ((e as f64 - span.abs().log10().floor()) as usize + 1).min(4);
        format!("{:.*}e{e}", digits, v / 10f64.powi(e))
    }
}

fn log_tick(v: f64) -> String {
    let e = v.log10().round();
    if (v.log10() - e).abs() < 1e-6 {
        format!("1e{}", e as i32)
    } else {
        format!("{v:.0e}")
    }
}

// ---------------------------------------------------------------- CSV

/// A CSV of numbers with a header (as `simulate` writes it).
#[derive(Debug, Clone, PartialEq)]
pub struct CsvData {
    pub path: PathBuf,
    pub header: Vec<String>,
    /// Column-major.
    pub columns: Vec<Vec<f64>>,
}

impl CsvData {
    pub fn read(path: &Path) -> anyhow::Result<CsvData> {
        let text = std::fs::read_to_string(path).with_context(|| format!("cannot read {}", path.display()))?;
        Self::parse(&text, path)
    }

    pub fn parse(text: &str, path: &Path) -> anyhow::Result<CsvData> {
        let mut lines = text.lines().enumerate().filter(|(_, l)| !l.trim().is_empty());
        let (_, head) = lines.next().ok_or_else(|| anyhow!("{}: empty file, expected a CSV header", path.display()))?;
        let header: Vec<String> = head.split(',').map(|s| s.trim().to_string()).collect();
        if header.iter().any(|h| h.parse::<f64>().is_ok()) {
            bail!("{}: the first line must be the header (column names), found numbers", path.display());
        }
        let mut columns = vec![Vec::new(); header.len()];
        for (no, line) in lines {
            let cells: Vec<&str> = line.split(',').collect();
            if cells.len() != header.len() {
                bail!("{}:{}: {} cells, the header has {}", path.display(), no + 1, cells.len(), header.len());
            }
            for (j, c) in cells.iter().enumerate() {
                let v = c.trim().parse::<f64>().map_err(|_| anyhow!("{}:{}: column {} is not a number: {:?}", path.display(), no + 1, header[j], c.trim()))?;
                columns[j].push(v);
            }
        }
        if columns.first().is_none_or(|c| c.is_empty()) {
            bail!("{}: no data rows", path.display());
        }
        Ok(CsvData { path: path.to_path_buf(), header, columns })
    }

    pub fn column(&self, name: &str) -> anyhow::Result<&[f64]> {
        match self.header.iter().position(|h| h == name) {
            Some(j) => Ok(&self.columns[j]),
            None => bail!("unknown column {name:?} in {}; it has {}", self.path.display(), summarize_names(&self.header)),
        }
    }

    /// Column names of a comma list, `*` patterns expanded (in file order).
    pub fn expand(&self, spec: &str) -> anyhow::Result<Vec<String>> {
        let mut out = Vec::new();
        for item in spec.split(',').map(str::trim).filter(|s| !s.is_empty()) {
            if item.contains('*') {
                let hits: Vec<&String> = self.header.iter().filter(|h| glob_match(item, h)).collect();
                if hits.is_empty() {
                    bail!("no column matches {item:?} in {}; it has {}", self.path.display(), summarize_names(&self.header));
                }
                out.extend(hits.into_iter().cloned());
            } else {
                self.column(item)?;
                out.push(item.to_string());
            }
        }
        if out.is_empty() {
            bail!("empty column list {spec:?}");
        }
        Ok(out)
    }
}

/// `*` matches any run of characters.
pub fn glob_match(pattern: &str, s: &str) -> bool {
    let parts: Vec<&str> = pattern.split('*').collect();
    if parts.len() == 1 {
        return pattern == s;
    }
    let (first, last) = (parts[0], parts[parts.len() - 1]);
    if !s.starts_with(first) || !s[first.len()..].ends_with(last) || s.len() < first.len() + last.len() {
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
                let j = b[i..].iter().position(|c| !c.is_ascii_digit()).map_or(b.len(), |n| i + n);
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
fn auto_ylabel(names: &[String]) -> String {
    let all = |f: &dyn Fn(&str) -> bool| names.iter().all(|n| f(n));
    let numbered = |n: &str, prefix: &str| n.strip_prefix(prefix).is_some_and(|r| !r.is_empty() && r.bytes().all(|c| c.is_ascii_digit()));
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
        names.join(", ")
    }
}

/// Pixel geometry of one chart panel.
#[derive(Debug, Clone, PartialEq)]
pub struct PanelGeometry {
    /// Plotting area in pixels: x from left to right, y from top to bottom (exclusive ends).
    pub x_px: (i32, i32),
    pub y_px: (i32, i32),
    /// Data ranges mapped onto it (x left → right, y bottom → top).
    pub x_range: (f64, f64),
    pub y_range: (f64, f64),
}

impl PanelGeometry {
    /// Pixel of a data point (plotters' own linear mapping).
    pub fn to_px(&self, x: f64, y: f64) -> (f64, f64) {
        let (x0, x1) = (self.x_px.0 as f64, (self.x_px.1 - 1) as f64);
        let (y0, y1) = (self.y_px.0 as f64, (self.y_px.1 - 1) as f64);
        (x0 + (x - self.x_range.0) / (self.x_range.1 - self.x_range.0) * (x1 - x0), y1 - (y - self.y_range.0) / (self.y_range.1 - self.y_range.0) * (y1 - y0))
    }
}

/// Stacked time-history panels from a CSV.
pub struct CsvPlot<'a> {
    pub data: &'a CsvData,
    pub x: &'a str,
    pub panels: Vec<Vec<String>>,
    pub ylabels: Vec<String>,
    pub title: Option<String>,
}

impl CsvPlot<'_> {
    pub fn render(&self, out: &Path, size: Size) -> anyhow::Result<Vec<PanelGeometry>> {
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
fn thick_polyline<DB: DrawingBackend>(area: &DrawingArea<DB, Shift>, pts: &[(i32, i32)], color: RGBColor, clip: (i32, i32, i32, i32)) -> anyhow::Result<()> {
    let dot = |x: i32, y: i32| -> anyhow::Result<()> {
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
fn decimate(x: &[f64], y: &[f64], x_range: (f64, f64), px: usize) -> Vec<(f64, f64)> {
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

fn padded_range(values: impl Iterator<Item = f64>) -> (f64, f64) {
    let (lo, hi) = values.filter(|v| v.is_finite()).fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| (a.min(v), b.max(v)));
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
    fn paint<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>, format: Format) -> anyhow::Result<Vec<PanelGeometry>> {
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
            let (lo, hi) = x.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &v| (a.min(v), b.max(v)));
            if hi > lo {
                (lo, hi)
            } else {
                x_range
            }
        };
        let x_label = if self.x == "time" { "time (s)".to_string() } else { self.x.to_string() };
        let mut geometry = Vec::new();
        let areas = area.split_evenly((self.panels.len(), 1));
        for (pi, (pa, names)) in areas.iter().zip(&self.panels).enumerate() {
            let ys: Vec<&[f64]> = names.iter().map(|n| self.data.column(n)).collect::<anyhow::Result<_>>()?;
            let y_range = padded_range(ys.iter().flat_map(|c| c.iter().copied()));
            let mut chart = ChartBuilder::on(pa)
                .margin(14)
                .x_label_area_size(48)
                .y_label_area_size(96)
                .build_cartesian_2d(x_range.0..x_range.1, y_range.0..y_range.1)
                .map_err(de)?;
            let (xs, ys_span) = (x_range.1 - x_range.0, y_range.1 - y_range.0);
            let ylabel = self.ylabels.get(pi).cloned().unwrap_or_else(|| auto_ylabel(names));
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
                        let px: Vec<(i32, i32)> = pts.iter().map(|p| chart.backend_coord(p)).collect();
                        let clip = (px_x.start, px_x.end, px_y.start, px_y.end);
                        thick_polyline(root, &px, color, clip)?;
                        chart.draw_series(std::iter::empty::<PathElement<(f64, f64)>>())
                    }
                };
                series
                    .map_err(de)?
                    .label(name.as_str())
                    .legend(move |(lx, ly)| PathElement::new(vec![(lx, ly), (lx + 22, ly)], color.stroke_width(3)));
            }
            chart
                .configure_series_labels()
                .position(SeriesLabelPosition::UpperRight)
                .background_style(WHITE.mix(0.85))
                .border_style(RGBColor(160, 160, 160))
                .label_font((FONT, 15))
                .draw()
                .map_err(de)?;
            geometry.push(PanelGeometry { x_px: (px_x.start, px_x.end), y_px: (px_y.start, px_y.end), x_range, y_range });
        }
        Ok(geometry)
    }
}

// ---------------------------------------------------------------- mode shapes

/// Diverging colour for w/max|w| ∈ [−1, 1]: blue below zero, white at zero, red above.
pub fn diverging(t: f64) -> RGBColor {
    let t = t.clamp(-1.0, 1.0);
    let (end, s) = if t >= 0.0 { ((178.0, 24.0, 43.0), t) } else { ((33.0, 102.0, 172.0), -t) };
    let s = s.powf(0.75);
    let mix = |e: f64| (255.0 + (e - 255.0) * s).round() as u8;
    RGBColor(mix(end.0), mix(end.1), mix(end.2))
}

/// Radii of the nodal circles of a radial function: sign changes strictly inside (r_i, r_a).
pub fn nodal_radii(model: &PlateModel, mode: usize) -> Vec<f64> {
    let m = &model.modes()[mode];
    let shape = &model.radial_shapes()[m.radial];
    let (ri, ra) = (model.plate().inner_radius, model.plate().outer_radius);
    let n = 4000;
    let peak = (0..=n).map(|i| shape.value(ri + (ra - ri) * i as f64 / n as f64).abs()).fold(0.0, f64::max);
    let tiny = 1e-9 * peak;
    let mut roots = Vec::new();
    let mut prev: Option<(f64, f64)> = None;
    for i in 0..=n {
        let r = ri + (ra - ri) * i as f64 / n as f64;
        let v = shape.value(r);
        if v.abs() <= tiny {
            continue; // an edge with w = 0, or exactly on a root (picked up by the neighbours)
        }
        if let Some((r0, v0)) = prev {
            if v0.signum() != v.signum() {
                let (mut a, mut b, mut fa) = (r0, r, v0);
                for _ in 0..60 {
                    let c = 0.5 * (a + b);
                    let fc = shape.value(c);
                    if fc.signum() == fa.signum() {
                        a = c;
                        fa = fc;
                    } else {
                        b = c;
                    }
                }
                roots.push(0.5 * (a + b));
            }
        }
        prev = Some((r, v));
    }
    roots
}

/// Angles of the nodal half-diameters of a mode (2k of them for k ≥ 1).
pub fn nodal_angles(k: u32, shape: AngularShape) -> Vec<f64> {
    let kf = k as f64;
    match shape {
        AngularShape::Axisymmetric => vec![],
        AngularShape::Cos => (0..2 * k).map(|j| (0.5 * PI + j as f64 * PI) / kf).collect(),
        AngularShape::Sin => (0..2 * k).map(|j| j as f64 * PI / kf).collect(),
    }
}

/// Where one top view of a mode was drawn.
#[derive(Debug, Clone, PartialEq)]
pub struct TopView {
    pub k: u32,
    pub l: u32,
    /// Index into the model's modes (of the model that drew it), None if ⟨k, l⟩ is a rigid-body motion.
    pub mode: Option<usize>,
    pub shape: Option<AngularShape>,
    /// Disc centre, pixels.
    pub center: (i32, i32),
    /// Pixels per metre.
    pub scale: f64,
    pub inner_radius: f64,
    pub outer_radius: f64,
    pub nodal_radii: Vec<f64>,
    pub nodal_angles: Vec<f64>,
}

impl TopView {
    /// Pixel of the plate point (r, φ) (φ counter-clockwise from +x, y up).
    pub fn to_px(&self, r: f64, phi: f64) -> (f64, f64) {
        (self.center.0 as f64 + r * phi.cos() * self.scale, self.center.1 as f64 - r * phi.sin() * self.scale)
    }
}

const EDGE: RGBColor = RGBColor(90, 90, 90);

/// Draw mode `mode` of `model` seen from above, centred at `center`, `scale` pixels per metre.
fn draw_top_view<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    model: &PlateModel,
    mode: usize,
    center: (i32, i32),
    scale: f64,
) -> anyhow::Result<TopView> {
    let m = &model.modes()[mode];
    let p = model.plate();
    let (ri, ra) = (p.inner_radius, p.outer_radius);
    let half = (ra * scale).ceil() as i32 + 1;
    let side = (2 * half + 1) as u32;
    // Field raster.
    let mut peak = 0.0f64;
    let mut values = vec![f64::NAN; (side * side) as usize];
    for py in 0..side as i32 {
        for px in 0..side as i32 {
            let (x, y) = ((px - half) as f64 / scale, (half - py) as f64 / scale);
            let r = x.hypot(y);
            if r >= ri && r <= ra {
                let w = model.mode_shape(mode, r, y.atan2(x)).w;
                peak = peak.max(w.abs());
                values[(py as u32 * side + px as u32) as usize] = w;
            }
        }
    }
    let mut buf = Vec::with_capacity(values.len() * 3);
    for v in &values {
        // Filled contours: 16 colour bands per sign (and a PNG a third the size of a smooth field).
        let c = if v.is_nan() { WHITE } else { diverging(((v / peak) * 16.0).round() / 16.0) };
        buf.extend_from_slice(&[c.0, c.1, c.2]);
    }
    let element =
        BitMapElement::<(i32, i32)>::with_owned_buffer((center.0 - half, center.1 - half), (side, side), buf).ok_or_else(|| anyhow!("raster size"))?;
    root.draw(&element).map_err(de)?;
    // Nodal lines, exact: diameters at the zeros of cos/sin(kφ), circles at the zeros of R_l.
    let radii = nodal_radii(model, mode);
    let angles = nodal_angles(m.k, m.shape);
    let line = BLACK.stroke_width(2);
    let px = |r: f64, phi: f64| ((center.0 as f64 + r * phi.cos() * scale).round() as i32, (center.1 as f64 - r * phi.sin() * scale).round() as i32);
    for &phi in &angles {
        root.draw(&PathElement::new(vec![px(ri, phi), px(ra, phi)], line)).map_err(de)?;
    }
    for &r in &radii {
        root.draw(&Circle::new(center, (r * scale).round() as i32, line)).map_err(de)?;
    }
    // Edges: a heavier inner edge where it is held (supported or clamped).
    let held = |b: crate::config::Boundary| if b == crate::config::Boundary::Free { 1 } else { 3 };
    root.draw(&Circle::new(center, (ra * scale).round() as i32, EDGE.stroke_width(held(p.outer_boundary)))).map_err(de)?;
    root.draw(&Circle::new(center, (ri * scale).round() as i32, EDGE.stroke_width(held(p.inner_boundary)))).map_err(de)?;
    Ok(TopView {
        k: m.k,
        l: m.l,
        mode: Some(mode),
        shape: Some(m.shape),
        center,
        scale,
        inner_radius: ri,
        outer_radius: ra,
        nodal_radii: radii,
        nodal_angles: angles,
    })
}

fn edges_text(config: &Config) -> String {
    format!("{} inside, {} outside", config.plate.inner_boundary.name(), config.plate.outer_boundary.name())
}

/// The plate of `config` with exactly the ⟨k, l⟩ sets `ks` × `ls`.
fn model_for(config: &Config, ks: &[u32], ls: &[u32]) -> anyhow::Result<PlateModel> {
    let mut plate = config.plate.clone();
    plate.nodal_diameters = ks.to_vec();
    plate.nodal_circles = ls.to_vec();
    plate.damping = vec![0.0];
    plate.radial_splines = plate.radial_splines.max(plate.min_radial_splines());
    if ks.iter().any(|&k| k > 200) || ls.iter().any(|&l| l > 50) {
        bail!("nodal diameters must be ≤ 200 and nodal circles ≤ 50");
    }
    PlateModel::new(&plate).map_err(|e| anyhow!("{e}"))
}

struct ModeGrid<'a> {
    config: &'a Config,
    model: PlateModel,
    ks: Vec<u32>,
    ls: Vec<u32>,
    title: String,
}

/// Draw a grid of ⟨k, l⟩ mode shapes (rows l, columns k; the cos member of each pair).
pub fn mode_grid(config: &Config, ks: &[u32], ls: &[u32], title: Option<&str>, out: &Path, size: Size) -> anyhow::Result<Vec<TopView>> {
    if ks.is_empty() || ls.is_empty() {
        bail!("choose at least one nodal diameter (--k) and one nodal circle (--l)");
    }
    let mut ks = ks.to_vec();
    ks.sort_unstable();
    ks.dedup();
    let mut ls = ls.to_vec();
    ls.sort_unstable();
    ls.dedup();
    let model = model_for(config, &ks, &ls)?;
    let p = &config.plate;
    let title = title.map(str::to_string).unwrap_or_else(|| {
        format!(
            "Mode shapes ⟨k, l⟩: r_i = {} m, r_a = {} m, h = {} m, {}; nodal lines black, red w > 0, blue w < 0",
            p.inner_radius,
            p.outer_radius,
            p.thickness,
            edges_text(config)
        )
    });
    render(out, size, &ModeGrid { config, model, ks, ls, title })
}

impl Painter for ModeGrid<'_> {
    type Out = Vec<TopView>;
    fn paint<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>, _format: Format) -> anyhow::Result<Vec<TopView>> {
        let (w, h) = root.dim_in_pixel();
        let title_h = 44;
        let font_size = (w as f64 / 75.0).clamp(13.0, 22.0);
        draw_title(&root.split_vertically(title_h).0, &self.title, font_size)?;
        let (cols, rows) = (self.ks.len() as i32, self.ls.len() as i32);
        let cw = (w as i32 - 20) / cols;
        let ch = (h as i32 - title_h - 10) / rows;
        let caption_h = 40;
        let d = (cw.min(ch - caption_h) - 14).max(20);
        let scale = d as f64 / (2.0 * self.config.plate.outer_radius);
        let mut views = Vec::new();
        for (ri, &l) in self.ls.iter().enumerate() {
            for (ci, &k) in self.ks.iter().enumerate() {
                let x0 = 10 + ci as i32 * cw;
                let y0 = title_h + ri as i32 * ch;
                let center = (x0 + cw / 2, y0 + caption_h + (ch - caption_h) / 2);
                let mode = self.model.modes().iter().position(|m| m.k == k && m.l == l && m.shape != AngularShape::Sin);
                let caption = match mode {
                    Some(i) => format!("⟨{k}, {l}⟩  {:.0} Hz", self.model.modes()[i].frequency_hz),
                    None => format!("⟨{k}, {l}⟩  rigid body"),
                };
                let style = TextStyle::from((FONT, 17).into_font())
                    .pos(plotters::style::text_anchor::Pos::new(plotters::style::text_anchor::HPos::Center, plotters::style::text_anchor::VPos::Top));
                root.draw(&Text::new(caption, (x0 + cw / 2, y0 + 10), style)).map_err(de)?;
                match mode {
                    Some(i) => views.push(draw_top_view(root, &self.model, i, center, scale)?),
                    None => {
                        let p = self.model.plate();
                        root.draw(&Circle::new(center, (p.outer_radius * scale).round() as i32, EDGE.stroke_width(1))).map_err(de)?;
                        root.draw(&Circle::new(center, (p.inner_radius * scale).round() as i32, EDGE.stroke_width(1))).map_err(de)?;
                        views.push(TopView {
                            k,
                            l,
                            mode: None,
                            shape: None,
                            center,
                            scale,
                            inner_radius: p.inner_radius,
                            outer_radius: p.outer_radius,
                            nodal_radii: vec![],
                            nodal_angles: vec![],
                        });
                    }
                }
            }
        }
        Ok(views)
    }
}

/// Which single mode to draw.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum ModeChoice {
    /// As numbered by `annular_plate modes` (from 1).
    Index(usize),
    KL {
        k: u32,
        l: u32,
        shape: AngularShape,
    },
}

struct ModePicture {
    model: PlateModel,
    mode: usize,
    title: String,
}

/// One mode: a shaded surface (left) and its top view with nodal lines (right).
pub fn mode_picture(config: &Config, which: ModeChoice, title: Option<&str>, out: &Path, size: Size) -> anyhow::Result<TopView> {
    let (model, mode) = match which {
        ModeChoice::Index(i) => {
            let model = PlateModel::new(&config.plate).map_err(|e| anyhow!("{e}"))?;
            if i == 0 || i > model.n_modes() {
                bail!("--index {i}: the model has modes 1..{} (see `annular_plate modes`)", model.n_modes());
            }
            (model, i - 1)
        }
        ModeChoice::KL { k, l, shape } => {
            let model = model_for(config, &[k], &[l])?;
            let shape = if k == 0 { AngularShape::Axisymmetric } else { shape };
            let mode = model
                .modes()
                .iter()
                .position(|m| m.shape == shape)
                .ok_or_else(|| anyhow!("⟨k = {k}, l = {l}⟩ is a rigid-body motion of this free–free plate, not a mode"))?;
            (model, mode)
        }
    };
    let m = &model.modes()[mode];
    let title = title.map(str::to_string).unwrap_or_else(|| {
        format!("Mode ⟨k = {}, l = {}⟩ {}, {:.1} Hz — {}", m.k, m.l, if m.k == 0 { "" } else { m.shape.name() }, m.frequency_hz, edges_text(config))
            .replace("  ", " ")
    });
    render(out, size, &ModePicture { model, mode, title })
}

impl Painter for ModePicture {
    type Out = TopView;
    fn paint<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>, _format: Format) -> anyhow::Result<TopView> {
        let (w, h) = root.dim_in_pixel();
        let (w, h) = (w as i32, h as i32);
        let font_size = (w as f64 / 60.0).clamp(14.0, 24.0);
        let top = 50;
        draw_title(&root.split_vertically(top).0, &self.title, font_size)?;
        let split = (w as f64 * 0.6) as i32;
        // Right: top view.
        let ra = self.model.plate().outer_radius;
        let d = ((w - split).min(h - top - 40) - 30).max(20);
        let scale = d as f64 / (2.0 * ra);
        let center = (split + (w - split) / 2, top + (h - top - 40) / 2 + 10);
        let view = draw_top_view(root, &self.model, self.mode, center, scale)?;
        let legend = TextStyle::from((FONT, 15).into_font())
            .pos(plotters::style::text_anchor::Pos::new(plotters::style::text_anchor::HPos::Center, plotters::style::text_anchor::VPos::Top));
        root.draw(&Text::new("top view: red w > 0, blue w < 0, nodal lines black", (center.0, h - 34), legend)).map_err(de)?;
        // Left: shaded surface.
        draw_surface(root, &self.model, self.mode, (0, top, split, h))?;
        Ok(view)
    }
}

/// The mode as a shaded, sign-coloured surface in an oblique view, painter's
/// algorithm (far quads first), nodal lines traced on the surface.
fn draw_surface<DB: DrawingBackend>(root: &DrawingArea<DB, Shift>, model: &PlateModel, mode: usize, rect: (i32, i32, i32, i32)) -> anyhow::Result<()> {
    let m = &model.modes()[mode];
    let p = model.plate();
    let (ri, ra) = (p.inner_radius, p.outer_radius);
    let (nr, nphi) = (24usize, (16 * m.k as usize + 101).min(401));
    let phi0 = 0.0123;
    let grid_r = |i: usize| ri + (ra - ri) * i as f64 / nr as f64;
    let grid_phi = |j: usize| phi0 + TAU * j as f64 / nphi as f64;
    let mut w = vec![vec![0.0; nphi]; nr + 1];
    let mut peak = 0.0f64;
    for (i, row) in w.iter_mut().enumerate() {
        for (j, v) in row.iter_mut().enumerate() {
            *v = model.mode_shape(mode, grid_r(i), grid_phi(j)).w;
            peak = peak.max(v.abs());
        }
    }
    for v in w.iter_mut().flatten() {
        *v /= peak;
        if v.abs() < 1e-9 {
            *v = 0.0;
        }
    }
    let amp = 0.28 * ra;
    let (az, el) = (-0.9f64, 0.5f64);
    let (sa, ca, se, ce) = (az.sin(), az.cos(), el.sin(), el.cos());
    // World (x, y, z) → (screen X, screen Y, depth); larger depth = farther.
    let project = |x: f64, y: f64, z: f64| {
        let x1 = x * ca - y * sa;
        let y1 = x * sa + y * ca;
        (x1, z * ce + y1 * se, y1 * ce - z * se)
    };
    let (x0, y0, x1, y1) = rect;
    let (width, height) = ((x1 - x0) as f64, (y1 - y0) as f64);
    let s = (0.92 * width / (2.0 * ra)).min(0.9 * height / (2.0 * ra * se + 2.0 * amp * ce));
    let (cx, cy) = (x0 as f64 + width / 2.0, y0 as f64 + height / 2.0);
    let to_px = |(sx, sy, _): (f64, f64, f64)| ((cx + sx * s).round() as i32, (cy - sy * s).round() as i32);
    let point = |i: usize, j: usize| {
        let (r, phi) = (grid_r(i), grid_phi(j));
        (r * phi.cos(), r * phi.sin(), amp * w[i][j])
    };
    let light = {
        let l = (-0.35f64, -0.55, 0.76);
        let n = (l.0 * l.0 + l.1 * l.1 + l.2 * l.2).sqrt();
        (l.0 / n, l.1 / n, l.2 / n)
    };
    struct Quad {
        depth: f64,
        i: usize,
        j: usize,
    }
    let mut quads = Vec::with_capacity(nr * nphi);
    for i in 0..nr {
        for j in 0..nphi {
            let j1 = (j + 1) % nphi;
            let c = [point(i, j), point(i + 1, j), point(i + 1, j1), point(i, j1)];
            let depth = c.iter().map(|&(x, y, z)| project(x, y, z).2).sum::<f64>() / 4.0;
            quads.push(Quad { depth, i, j });
        }
    }
    quads.sort_by(|a, b| b.depth.total_cmp(&a.depth));
    for q in &quads {
        let (i, j) = (q.i, q.j);
        let j1 = (j + 1) % nphi;
        let idx = [(i, j), (i + 1, j), (i + 1, j1), (i, j1)];
        let c: Vec<(f64, f64, f64)> = idx.iter().map(|&(a, b)| point(a, b)).collect();
        let u = (c[2].0 - c[0].0, c[2].1 - c[0].1, c[2].2 - c[0].2);
        let v = (c[3].0 - c[1].0, c[3].1 - c[1].1, c[3].2 - c[1].2);
        let n = (u.1 * v.2 - u.2 * v.1, u.2 * v.0 - u.0 * v.2, u.0 * v.1 - u.1 * v.0);
        let nn = (n.0 * n.0 + n.1 * n.1 + n.2 * n.2).sqrt().max(1e-300);
        let shade = 0.55 + 0.45 * ((n.0 * light.0 + n.1 * light.1 + n.2 * light.2) / nn).abs();
        let wc = idx.iter().map(|&(a, b)| w[a][b]).sum::<f64>() / 4.0;
        let base = diverging(wc);
        let col = RGBColor((base.0 as f64 * shade) as u8, (base.1 as f64 * shade) as u8, (base.2 as f64 * shade) as u8);
        let pts: Vec<(i32, i32)> = c.iter().map(|&(x, y, z)| to_px(project(x, y, z))).collect();
        root.draw(&Polygon::new(pts.clone(), col.filled())).map_err(de)?;
        let mut outline = pts.clone();
        outline.push(pts[0]);
        root.draw(&PathElement::new(outline, col.stroke_width(1))).map_err(de)?;
        // Nodal line through this quad (marching squares on the mesh).
        let mut cross = Vec::new();
        for e in 0..4 {
            let (a, b) = (idx[e], idx[(e + 1) % 4]);
            let (wa, wb) = (w[a.0][a.1], w[b.0][b.1]);
            if wa * wb < 0.0 {
                let t = wa / (wa - wb);
                let (pa, pb) = (point(a.0, a.1), point(b.0, b.1));
                cross.push(to_px(project(pa.0 + t * (pb.0 - pa.0), pa.1 + t * (pb.1 - pa.1), 0.0)));
            }
        }
        for pair in cross.chunks(2).filter(|c| c.len() == 2) {
            root.draw(&PathElement::new(vec![pair[0], pair[1]], BLACK.stroke_width(2))).map_err(de)?;
        }
    }
    Ok(())
}

// ---------------------------------------------------------------- study picture

/// The study's error-vs-cost picture: one log–log panel per axis, the Pareto
/// front, the targets and the recommended settings ringed.
pub fn pareto(report: &StudyReport, out: &Path, size: Size) -> anyhow::Result<()> {
    render(out, size, &ParetoPicture { report })
}

struct ParetoPicture<'a> {
    report: &'a StudyReport,
}

/// One panel's data.
struct Series {
    name: String,
    color: RGBColor,
    /// (cost, error, label)
    points: Vec<(f64, f64, String)>,
}

struct PanelData {
    title: String,
    x_desc: String,
    series: Vec<Series>,
    /// (cost, error) of the front.
    front: Vec<(f64, f64)>,
    /// (target, cost, error, label) of recommendations.
    picks: Vec<(f64, f64, f64, String)>,
    uncertainty: f64,
}

/// Errors below this are drawn at it (exact to round-off).
const ERROR_FLOOR: f64 = 1e-16;

fn panels(r: &StudyReport) -> [PanelData; 3] {
    let floor = |e: f64| e.max(ERROR_FLOOR);
    let a = &r.radial_splines;
    let pa = PanelData {
        title: "1. frequencies vs plate.radial_splines".into(),
        x_desc: "model build time (s)".into(),
        series: vec![Series {
            name: "max frequency error".into(),
            color: PALETTE[0],
            points: a.rows.iter().map(|x| (x.build_time_s, floor(x.max_relative_error), format!("{}", x.radial_splines))).collect(),
        }],
        front: a.rows.iter().filter(|x| x.pareto).map(|x| (x.build_time_s, floor(x.max_relative_error))).collect(),
        picks: a
            .recommendations
            .iter()
            .filter_map(|x| Some((x.target, x.cost?, floor(x.error?), format!("n = {}", x.setting.as_ref()?.radial_splines))))
            .collect(),
        uncertainty: a.reference.uncertainty,
    };
    let b = &r.mode_count;
    let mut ls: Vec<u32> = b.rows.iter().map(|x| x.l_max).collect();
    ls.sort_unstable();
    ls.dedup();
    let pb = PanelData {
        title: "2. load-point response vs mode set".into(),
        x_desc: "wall time per step (s)".into(),
        series: ls
            .iter()
            .enumerate()
            .map(|(i, &l)| Series {
                name: format!("l ≤ {l}"),
                color: PALETTE[i % PALETTE.len()],
                points: b.rows.iter().filter(|x| x.l_max == l).map(|x| (x.step_time_s, floor(x.relative_error), format!("k ≤ {}", x.k_max))).collect(),
            })
            .collect(),
        front: b.rows.iter().filter(|x| x.pareto).map(|x| (x.step_time_s, floor(x.relative_error))).collect(),
        picks: b
            .recommendations
            .iter()
            .filter_map(|x| {
                let s = x.setting.as_ref()?;
                Some((x.target, x.cost?, floor(x.error?), format!("k≤{}, l≤{}", s.k_max, s.l_max)))
            })
            .collect(),
        uncertainty: b.reference.uncertainty,
    };
    let c = &r.integrator;
    let mut names: Vec<&str> = c.rows.iter().map(|x| x.integrator).collect();
    names.dedup();
    let short = |n: &str| match n {
        "exponential" => "exp".to_string(),
        "implicit_midpoint" => "midpoint".to_string(),
        other => other.to_string(),
    };
    let khz = |hz: f64| if hz >= 1e3 { format!("{} kHz", hz / 1e3) } else { format!("{hz} Hz") };
    let pc = PanelData {
        title: "3. trajectory vs integrator and rate".into(),
        x_desc: "wall time per simulated second (s/s)".into(),
        series: names
            .iter()
            .enumerate()
            .map(|(i, &n)| Series {
                name: n.to_string(),
                color: PALETTE[i % PALETTE.len()],
                points: c
                    .rows
                    .iter()
                    .filter(|x| x.integrator == n)
                    .filter_map(|x| Some((x.wall_s_per_simulated_s?, floor(x.relative_error?), khz(x.rate_hz))))
                    .collect(),
            })
            .collect(),
        front: c.rows.iter().filter(|x| x.pareto).filter_map(|x| Some((x.wall_s_per_simulated_s?, floor(x.relative_error?)))).collect(),
        picks: c
            .recommendations
            .iter()
            .filter_map(|x| {
                let s = x.setting.as_ref()?;
                Some((x.target, x.cost?, floor(x.error?), format!("{} {}", short(s.integrator), khz(s.rate_hz))))
            })
            .collect(),
        uncertainty: c.reference.uncertainty,
    };
    [pa, pb, pc]
}

fn decade_range(values: impl Iterator<Item = f64>) -> (f64, f64) {
    let (lo, hi) = values.filter(|v| v.is_finite() && *v > 0.0).fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| (a.min(v), b.max(v)));
    if !lo.is_finite() {
        return (1e-3, 1.0);
    }
    (10f64.powf(lo.log10().floor()), 10f64.powf(hi.log10().ceil().max(lo.log10().floor() + 1.0)))
}

impl Painter for ParetoPicture<'_> {
    type Out = ();
    fn paint<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>, _format: Format) -> anyhow::Result<()> {
        let r = self.report;
        let (top, rest) = root.split_vertically(44);
        draw_title(
            &top,
            &format!("Error against cost — {} ({} modes); targets dashed, recommended settings ringed, Pareto front black", r.scene.source, r.scene.modes),
            20.0,
        )?;
        let areas = rest.split_evenly((1, 3));
        for (area, panel) in areas.iter().zip(panels(r)) {
            let xs = decade_range(panel.series.iter().flat_map(|s| s.points.iter().map(|p| p.0)));
            let mut y_all: Vec<f64> = panel.series.iter().flat_map(|s| s.points.iter().map(|p| p.1)).collect();
            y_all.extend(r.plan.targets.iter().copied());
            let ys = decade_range(y_all.into_iter());
            let ys = (ys.0, ys.1.max(1.0));
            let mut chart = ChartBuilder::on(area)
                .caption(&panel.title, (FONT, 18))
                .margin(12)
                .x_label_area_size(46)
                .y_label_area_size(64)
                .build_cartesian_2d((xs.0..xs.1).log_scale(), (ys.0..ys.1).log_scale())
                .map_err(de)?;
            chart
                .configure_mesh()
                .x_desc(panel.x_desc.as_str())
                .y_desc("relative error")
                .x_label_formatter(&|v| log_tick(*v))
                .y_label_formatter(&|v| log_tick(*v))
                .label_style((FONT, 14))
                .axis_desc_style((FONT, 16))
                .light_line_style(RGBColor(240, 240, 240))
                .bold_line_style(RGBColor(220, 220, 220))
                .draw()
                .map_err(de)?;
            for &t in &r.plan.targets {
                if t >= ys.0 && t <= ys.1 {
                    chart
                        .draw_series(std::iter::once(DashedPathElement::new(
                            vec![(xs.0, t), (xs.1, t)],
                            6,
                            4,
                            RGBColor(120, 120, 120).stroke_width(1),
                        )))
                        .map_err(de)?;
                }
            }
            if panel.uncertainty > ys.0 {
                chart
                    .draw_series(std::iter::once(DashedPathElement::new(
                        vec![(xs.0, panel.uncertainty), (xs.1, panel.uncertainty)],
                        2,
                        3,
                        RGBColor(200, 120, 0).stroke_width(1),
                    )))
                    .map_err(de)?
                    .label("reference uncertainty")
                    .legend(|(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], RGBColor(200, 120, 0).stroke_width(2)));
            }
            for s in &panel.series {
                let color = s.color;
                let mut pts: Vec<(f64, f64)> = s.points.iter().map(|p| (p.0, p.1)).collect();
                pts.sort_by(|a, b| a.0.total_cmp(&b.0));
                chart.draw_series(LineSeries::new(pts.clone(), color.mix(0.5).stroke_width(1))).map_err(de)?;
                chart
                    .draw_series(pts.iter().map(|&p| Circle::new(p, 4, color.filled())))
                    .map_err(de)?
                    .label(s.name.as_str())
                    .legend(move |(x, y)| Circle::new((x + 10, y), 4, color.filled()));
                if panel.series.len() == 1 {
                    for p in &s.points {
                        let (px, py) = chart.backend_coord(&(p.0, p.1));
                        root.draw(&Text::new(p.2.clone(), (px - 6, py + 8), (FONT, 13).into_font())).map_err(de)?;
                    }
                }
            }
            let mut front = panel.front.clone();
            front.sort_by(|a, b| a.0.total_cmp(&b.0));
            chart
                .draw_series(LineSeries::new(front, BLACK.stroke_width(2)))
                .map_err(de)?
                .label("Pareto front")
                .legend(|(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], BLACK.stroke_width(2)));
            // Recommended settings: one ring per setting, its targets listed.
            let mut merged: Vec<(f64, f64, String, Vec<f64>)> = Vec::new();
            for (target, cost, err, label) in &panel.picks {
                match merged.iter_mut().find(|m| m.2 == *label) {
                    Some(m) => m.3.push(*target),
                    None => merged.push((*cost, *err, label.clone(), vec![*target])),
                }
            }
            for (cost, err, label, targets) in &merged {
                chart.draw_series(std::iter::once(Circle::new((*cost, *err), 9, RGBColor(220, 0, 0).stroke_width(2)))).map_err(de)?;
                let list: Vec<String> = targets.iter().map(|t| log_tick(*t)).collect();
                let text =
                    if list.len() > 2 { format!("{label}: ≤ {} … {}", list[0], list[list.len() - 1]) } else { format!("{label}: ≤ {}", list.join(", ")) };
                let style = TextStyle::from((FONT, 13).into_font()).color(&RGBColor(180, 0, 0));
                let (px, py) = chart.backend_coord(&(*cost, *err));
                root.draw(&Text::new(text, (px + 11, py - 20), style)).map_err(de)?;
            }
            // The legend goes into the emptiest corner.
            let (px_x, px_y) = chart.plotting_area().get_pixel_range();
            let mid = ((px_x.start + px_x.end) / 2, (px_y.start + px_y.end) / 2);
            let mut counts = [0usize; 4]; // UL, UR, LL, LR
            let quadrant = |(x, y): (i32, i32)| (usize::from(y > mid.1) << 1) | usize::from(x > mid.0);
            for s in &panel.series {
                for p in &s.points {
                    counts[quadrant(chart.backend_coord(&(p.0, p.1)))] += 1;
                }
            }
            for (cost, err, _, _) in &merged {
                // a label reaches ~150 px to the right of its ring
                let (x, y) = chart.backend_coord(&(*cost, *err));
                counts[quadrant((x, y))] += 5;
                counts[quadrant((x + 150, y))] += 5;
            }
            let corners = [SeriesLabelPosition::UpperLeft, SeriesLabelPosition::UpperRight, SeriesLabelPosition::LowerLeft, SeriesLabelPosition::LowerRight];
            let best = [2usize, 3, 1, 0].into_iter().min_by_key(|&i| counts[i]).unwrap_or(2);
            chart
                .configure_series_labels()
                .position(corners[best].clone())
                .background_style(WHITE.mix(0.85))
                .border_style(RGBColor(160, 160, 160))
                .label_font((FONT, 13))
                .draw()
                .map_err(de)?;
        }
        Ok(())
    }
}
