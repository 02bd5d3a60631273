//! `annular_plate plot ...`: pictures, PNG or SVG (by the output's extension),
//! drawn with plotters; text in DejaVu Sans embedded in the binary.
//!
//! - `plot csv FILE --columns q2,q3 [--panel qale2,qale3 ...] --out F`: time
//!   histories from a `simulate` CSV, one panel per column list (the paper's
//!   Figs. 9, 15, 17);
//! - `plot modes PARAMS --out F [--k 0,1,2 --l 0,1]`: a grid of ⟨k, l⟩ mode
//!   shapes seen from above, sign-coloured, with their nodal lines (Fig. 2);
//! - `plot mode PARAMS (--index N | --k K --l L) --out F`: one mode as a
//!   shaded surface beside its top view (Fig. 3);
//! - `plot animate CSV --params FILE --out F.gif|F.mp4`: the deformed plate
//!   of a simulated run, top and side view, frame by frame;
//! - `plot marker BAG --out F.png [--at S]`: a recorded `~/plate_marker` as
//!   RViz draws its triangles (without RViz).
//!
//! The drawing functions return the pixel geometry they used, so tests can
//! check that a curve or a nodal line is where the data puts it.

use crate::cli::error::{CliError, CliResult};
use crate::config::Config;
use crate::model::AngularShape;
use std::path::{Path, PathBuf};
use std::str::FromStr;

mod animate;
mod campbell;
mod csv;
#[cfg(feature = "ros")]
mod marker_view;
mod modes;
mod pareto;
mod render;
mod stability;

pub use self::animate::*;
pub use self::campbell::*;
pub use self::csv::*;
#[cfg(feature = "ros")]
pub use self::marker_view::*;
pub use self::modes::*;
pub use self::pareto::*;
pub use self::render::*;
pub use self::stability::*;
pub use crate::model::nodal_lines::{nodal_angles, nodal_radii};

// ---------------------------------------------------------------- CLI

/// Picture size in pixels, `WIDTHxHEIGHT`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Size {
    /// Width, pixels.
    pub width: u32,
    /// Height, pixels.
    pub height: u32,
}

impl FromStr for Size {
    type Err = String;
    fn from_str(s: &str) -> Result<Size, String> {
        let bad = || format!("size must be WIDTHxHEIGHT in pixels (e.g. 1200x800), got {s:?}");
        let (w, h) = s.split_once(['x', 'X']).ok_or_else(bad)?;
        let (width, height) = (
            w.trim().parse::<u32>().map_err(|_| bad())?,
            h.trim().parse::<u32>().map_err(|_| bad())?,
        );
        if !(100..=10_000).contains(&width) || !(100..=10_000).contains(&height) {
            return Err(format!(
                "size {width}x{height}: each side must be 100..10000 pixels"
            ));
        }
        Ok(Size { width, height })
    }
}

impl std::fmt::Display for Size {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{}x{}", self.width, self.height)
    }
}

/// `annular_plate plot`: pictures of a run or a scene.
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
        /// Title above the picture.
        title: Option<String>,
        /// Output file, .png or .svg.
        #[arg(long)]
        out: PathBuf,
        #[arg(long, default_value = "1200x800")]
        /// Picture size, `WIDTHxHEIGHT` in pixels.
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
        /// Title above the picture.
        title: Option<String>,
        #[arg(long)]
        /// Output file, .png or .svg.
        out: PathBuf,
        /// Picture size; default: 230 × 250 pixels per mode.
        #[arg(long)]
        size: Option<Size>,
    },
    /// One mode as a shaded surface beside its top view.
    Mode {
        /// Params file (ROS 2 format) giving the plate.
        params: PathBuf,
        #[arg(short = 'p', long = "param", value_name = "NAME:=VALUE")]
        /// Parameter overrides `-p name:=value` (as after --ros-args).
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
        /// Title above the picture.
        title: Option<String>,
        #[arg(long)]
        /// Output file, .png or .svg.
        out: PathBuf,
        #[arg(long, default_value = "1400x640")]
        /// Picture size, `WIDTHxHEIGHT` in pixels.
        size: Size,
    },
    /// The deformed plate of a `simulate` run as an animation (top and side view, node frames, time).
    Animate {
        /// The CSV written by `annular_plate simulate` (its q1…qN columns).
        csv: PathBuf,
        /// The params file the run was simulated from (the same modes).
        #[arg(long)]
        params: PathBuf,
        /// .gif (written here) or .mp4 (needs ffmpeg on PATH).
        #[arg(long)]
        out: PathBuf,
        /// Frames per second of the animation.
        #[arg(long, default_value_t = 25)]
        fps: u32,
        /// Animation seconds per simulated second (slow motion > 1).
        #[arg(long, default_value_t = 1.0)]
        slowdown: f64,
        /// Side-view magnification of the deflection; default: the run's largest |w| drawn as 10 % of r_a.
        #[arg(long)]
        scale: Option<f64>,
        #[arg(long, default_value = "960x480")]
        /// Picture size, `WIDTHxHEIGHT` in pixels.
        size: Size,
        /// Refuse an animation of more frames than this (the refusal gives the estimate).
        #[arg(long, default_value_t = animate::DEFAULT_MAX_FRAMES)]
        max_frames: usize,
        /// No progress bar, no estimate.
        #[arg(long)]
        quiet: bool,
    },
    /// A recorded `~/plate_marker` (from `simulate --bag` or `run --record`) drawn as RViz draws its triangles.
    #[cfg(feature = "ros")]
    Marker {
        /// The bag directory (or its .mcap file).
        bag: PathBuf,
        /// Seconds after the bag's first marker; default: the last marker.
        #[arg(long)]
        at: Option<f64>,
        /// Output file, .png.
        #[arg(long)]
        out: PathBuf,
        #[arg(long, default_value = "900x640")]
        /// Picture size, `WIDTHxHEIGHT` in pixels.
        size: Size,
    },
}

/// Run `annular_plate plot`.
pub fn main(cmd: PlotCommand) -> CliResult<()> {
    match cmd {
        PlotCommand::Csv {
            file,
            columns,
            panels,
            x,
            ylabels,
            title,
            out,
            size,
        } => {
            let data = CsvData::read(&file)?;
            let mut specs: Vec<String> = columns.into_iter().collect();
            specs.extend(panels);
            if specs.is_empty() {
                return Err(CliError::Usage(format!("give the columns to plot: --columns LIST (and --panel LIST for more panels); {} has {}", file.display(), summarize_names(&data.header))));
            }
            let panels = specs
                .iter()
                .map(|s| data.expand(s))
                .collect::<CliResult<Vec<_>>>()?;
            let plot = CsvPlot {
                data: &data,
                x: &x,
                panels,
                ylabels,
                title,
            };
            plot.render(&out, size)?;
        }
        PlotCommand::Modes {
            params,
            overrides,
            k,
            l,
            title,
            out,
            size,
        } => {
            let config = load_with_overrides(&params, &overrides)?;
            let ks = k.unwrap_or_else(|| first_sorted(&config.plate.nodal_diameters, 8));
            let ls = l.unwrap_or_else(|| first_sorted(&config.plate.nodal_circles, 4));
            let size = size.unwrap_or(Size {
                width: (230 * ks.len() as u32).max(400) + 20,
                height: 250 * ls.len() as u32 + 70,
            });
            mode_grid(&config, &ks, &ls, title.as_deref(), &out, size)?;
        }
        PlotCommand::Mode {
            params,
            overrides,
            index,
            k,
            l,
            shape,
            title,
            out,
            size,
        } => {
            let config = load_with_overrides(&params, &overrides)?;
            let which = match (index, k, l) {
                (Some(i), _, _) => ModeChoice::Index(i),
                (None, Some(k), Some(l)) => {
                    let shape = match shape.as_str() {
                        "cos" => AngularShape::Cos,
                        "sin" => AngularShape::Sin,
                        other => return Err(CliError::Usage(format!("--shape must be cos or sin, got {other:?}"))),
                    };
                    ModeChoice::KL { k, l, shape }
                }
                _ => return Err(CliError::Usage("say which mode: --index N (as numbered by `annular_plate modes`) or --k K --l L".to_string())),
            };
            mode_picture(&config, which, title.as_deref(), &out, size)?;
        }
        #[cfg(feature = "ros")]
        PlotCommand::Marker { bag, at, out, size } => {
            let (t, triangles) = plot_marker(&bag, at, &out, size)?;
            eprintln!(
                "{}: the marker logged at {:.3} s, {triangles} triangles",
                out.display(),
                t as f64 * 1e-9
            );
        }
        PlotCommand::Animate {
            csv,
            params,
            out,
            fps,
            slowdown,
            scale,
            size,
            max_frames,
            quiet,
        } => {
            if fps == 0 || fps > 100 {
                return Err(CliError::Usage(format!("--fps {fps}: must be 1 ..= 100")));
            }
            if !(slowdown.is_finite() && slowdown > 0.0)
                || scale.is_some_and(|s| !(s.is_finite() && s > 0.0))
            {
                return Err(CliError::Usage(
                    "--slowdown and --scale must be finite numbers > 0".into(),
                ));
            }
            let data = CsvData::read(&csv)?;
            let config = super::load_config(&params)?;
            let bar = if quiet {
                indicatif::ProgressBar::hidden()
            } else {
                indicatif::ProgressBar::new(0)
            };
            let anim = Animation {
                fps,
                max_frames,
                slowdown,
                scale,
                size,
            };
            let mut estimated = quiet;
            let info = animate(&data, &config, &anim, &out, |done, total| {
                if !estimated {
                    eprintln!(
                        "{}: {total} frames from {} rows, about {:.0} s",
                        out.display(),
                        data.columns[0].len(),
                        total as f64 * animate::FRAME_SECONDS
                    );
                    estimated = true;
                }
                bar.set_length(total as u64);
                bar.set_position(done as u64);
            })?;
            bar.finish_and_clear();
            if !quiet {
                eprintln!(
                    "{}: {} frames at {fps} fps, colour ±{:.3e} m, side view ×{:.3e}",
                    out.display(),
                    info.frames,
                    info.w_ref,
                    info.scale
                );
            }
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
pub(crate) fn load_with_overrides(path: &Path, overrides: &[String]) -> CliResult<Config> {
    super::load_config_with(path, overrides)
}
