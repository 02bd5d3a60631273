//! `annular_plate campbell FILE [--speeds FROM:TO:N] [--json] [--plot F.png]`:
//! the Campbell diagram and the critical speeds (`crate::model::campbell`,
//! docs/rotor_dynamics.md).

use super::error::{CliError, CliResult};
use crate::config::{PlateConfig, RadialSplines};
use crate::model::campbell::{campbell, critical_speeds, CampbellDiagram};
use crate::model::PlateModel;
use std::io::Write;
use std::path::PathBuf;

/// Speeds when `--speeds` is not given.
pub(crate) const DEFAULT_SPEED_COUNT: usize = 121;

/// `annular_plate campbell`: the natural frequencies of the spinning plate
/// over a range of speeds and the critical speeds.
#[derive(clap::Args, Debug, Clone)]
pub struct CampbellArgs {
    /// Params file (ROS 2 format); `plate.centrifugal_stiffening` decides whether the prestress stiffens the plate.
    pub file: PathBuf,
    /// N speeds from FROM to TO rad/s, inclusive (default: 0 to 1.2 × the highest critical speed, 121 speeds).
    #[arg(long, value_name = "FROM:TO:N", allow_hyphen_values = true)]
    pub speeds: Option<String>,
    /// Machine-readable output: {"speeds_rad_s", "modes": [{"k", "l", "rotating_hz", "forward_hz", "backward_hz"}], "critical_speeds": [{"k", "l", "rad_s"}]}, with in-plane modes also "in_plane": [{"k", "order", "rotating_forward_hz", "rotating_backward_hz", "forward_hz", "backward_hz"}] and "in_plane_critical_speeds": [{"k", "order", "rad_s"}].
    #[arg(long)]
    pub json: bool,
    /// Also draw the diagram to this file (.png or .svg).
    #[arg(long, value_name = "OUT")]
    pub plot: Option<PathBuf>,
    /// Parameter overrides `-p NAME:=VALUE` (as after --ros-args), e.g. -p plate.centrifugal_stiffening:=true.
    #[arg(short = 'p', long = "param", value_name = "NAME:=VALUE")]
    pub overrides: Vec<String>,
}

/// The fastest speed of `--speeds`, rad/s (the declared maximum of `limits.max_speed`).
pub(crate) const MAX_SPEED: f64 = 1e6;

/// The most `--speeds` with centrifugal stiffening (an eigensolution per speed):
/// 100,000 took 55 s and 1.6 GB (brake-squeal scene), this many ~6 s.
pub(crate) const MAX_STIFFENED_SPEEDS: usize = 10_000;

/// The most points of a `FROM:TO:N` range.
pub(crate) const MAX_POINTS: usize = 100_000;

/// `FROM:TO:N` → N speeds from FROM to TO inclusive (N = 1: FROM, which must equal TO).
pub(crate) fn parse_range(option: &str, text: &str) -> CliResult<Vec<f64>> {
    let bad = |why: &str| {
        CliError::Usage(format!(
            "{option} {text}: {why} (give FROM:TO:N, e.g. 0:6000:121)"
        ))
    };
    let parts: Vec<&str> = text.split(':').collect();
    let [from, to, n] = parts[..] else {
        return Err(bad("three fields separated by ':' expected"));
    };
    let from: f64 = from
        .trim()
        .parse()
        .map_err(|_| bad("FROM is not a number"))?;
    let to: f64 = to.trim().parse().map_err(|_| bad("TO is not a number"))?;
    let n: usize = n
        .trim()
        .parse()
        .map_err(|_| bad("N is not a whole number ≥ 1"))?;
    if !(from.is_finite() && to.is_finite()) {
        return Err(bad("FROM and TO must be finite"));
    }
    if from < 0.0 || to < from {
        return Err(bad("0 ≤ FROM ≤ TO is required"));
    }
    if n == 0 || n > MAX_POINTS {
        return Err(bad("N must be between 1 and 100000"));
    }
    if n == 1 && to != from {
        return Err(bad("N = 1 needs FROM = TO"));
    }
    Ok(linspace(from, to, n))
}

/// `n` speeds from `from` to `to`, both included (exactly `to` last).
pub(crate) fn linspace(from: f64, to: f64, n: usize) -> Vec<f64> {
    if n == 1 {
        return vec![from];
    }
    (0..n)
        .map(|i| {
            if i + 1 == n {
                to
            } else {
                from + (to - from) * i as f64 / (n - 1) as f64
            }
        })
        .collect()
}

/// Run `annular_plate campbell`.
pub fn main(args: CampbellArgs) -> CliResult<()> {
    let config = super::load_config_with(&args.file, &args.overrides)?;
    if let Some(p) = &args.plot {
        super::plot::check_output_path(p)?;
    }
    // The in-plane waves come from the plate's in-plane keys (`campbell`).
    let model = PlateModel::bending(&config.plate)?;
    let speeds = match &args.speeds {
        Some(text) => {
            let speeds = parse_range("--speeds", text)?;
            if let Some(s) = speeds.iter().find(|s| s.abs() > MAX_SPEED) {
                return Err(CliError::Usage(format!(
                    "--speeds {text}: the speed {s:e} rad/s is above {MAX_SPEED:e} rad/s, the largest limits.max_speed any scene may declare"
                )));
            }
            if config.centrifugal.stiffening && speeds.len() > MAX_STIFFENED_SPEEDS {
                return Err(CliError::Usage(format!(
                    "--speeds {text}: {} speeds with plate.centrifugal_stiffening: true is more than {MAX_STIFFENED_SPEEDS} \
                     (each speed is an eigensolution per nodal-diameter number: ~0.55 ms and ~16 kB a speed for the brake-squeal scene, \
                     {:.0} s and {:.0} MB here); give fewer speeds",
                    speeds.len(),
                    speeds.len() as f64 * 5.5e-4,
                    speeds.len() as f64 * 0.016
                )));
            }
            speeds
        }
        None => {
            let critical = critical_speeds(&model, &config.centrifugal)?;
            // Without any critical speed (only k = 0 modes): up to the highest frequency, in rad/s.
            let top = critical.iter().map(|c| c.rad_s).fold(0.0, f64::max);
            let top = if top > 0.0 {
                top
            } else {
                model.modes().iter().map(|m| m.omega).fold(0.0, f64::max)
            };
            linspace(0.0, 1.2 * top, DEFAULT_SPEED_COUNT)
        }
    };
    bound_in_plane_work(&config.plate, &speeds)?;
    let diagram = campbell(&model, &config.centrifugal, &speeds)?;
    if let Some(p) = &args.plot {
        super::plot::campbell(
            &diagram,
            config.centrifugal.stiffening,
            p,
            super::plot::Size {
                width: 1200,
                height: 800,
            },
        )?;
    }
    let stdout = std::io::stdout();
    write(
        &diagram,
        config.centrifugal.stiffening,
        args.json,
        &mut stdout.lock(),
    )?;
    Ok(())
}

/// The most in-plane eigensolutions (speeds × in-plane k) at 60 B-splines
/// per field, scaled by (splines/60)³ for other counts: one took ~17 ms for
/// the brake bench disc (a dense eigenproblem of 4 × 59 unknowns), so this
/// many ~35 s.
pub(crate) const MAX_IN_PLANE_SOLVES: f64 = 2000.0;

/// Refuse an in-plane diagram whose eigensolutions would take more than
/// [`MAX_IN_PLANE_SOLVES`], before any work.
fn bound_in_plane_work(plate: &PlateConfig, speeds: &[f64]) -> CliResult<()> {
    let ks = plate.in_plane_nodal_diameters.len();
    let splines = match plate.radial_splines {
        RadialSplines::Auto => crate::model::in_plane::DEFAULT_SPLINES,
        RadialSplines::Fixed(n) => n,
    };
    let work = (speeds.len() * ks) as f64 * (splines as f64 / 60.0).powi(3);
    if work > MAX_IN_PLANE_SOLVES {
        return Err(CliError::Usage(format!(
            "{} speeds × {ks} k of plate.in_plane_nodal_diameters at plate.radial_splines = {splines} is {work:.0} \
             in-plane eigensolutions of 60 B-splines' cost (~17 ms each, ~{:.0} s here), more than {MAX_IN_PLANE_SOLVES}; \
             give fewer --speeds or fewer k",
            speeds.len(),
            work * 0.017
        )));
    }
    Ok(())
}

/// The table (or JSON) of `diagram` to `out`.
pub fn write(
    diagram: &CampbellDiagram,
    stiffening: bool,
    json: bool,
    out: &mut impl Write,
) -> std::io::Result<()> {
    if json {
        serde_json::to_writer_pretty(&mut *out, diagram)?;
        writeln!(out)?;
        return Ok(());
    }
    let s = &diagram.speeds_rad_s;
    writeln!(
        out,
        "Campbell diagram, {} speeds from {} to {} rad/s, centrifugal stiffening {}",
        s.len(),
        s.first().copied().unwrap_or(0.0),
        s.last().copied().unwrap_or(0.0),
        if stiffening { "on" } else { "off" }
    )?;
    writeln!(
        out,
        "{:>4} {:>4} {:>16} {:>16} {:>18}",
        "k", "l", "f(Ω=first) Hz", "f(Ω=last) Hz", "critical rad/s"
    )?;
    for m in &diagram.modes {
        let critical = diagram
            .critical_speeds
            .iter()
            .find(|c| c.k == m.k && c.l == m.l)
            .map_or("—".to_string(), |c| format!("{:.3}", c.rad_s));
        let first = m.rotating_hz.first().copied().unwrap_or(f64::NAN);
        let last = m.rotating_hz.last().copied().unwrap_or(f64::NAN);
        writeln!(
            out,
            "{:>4} {:>4} {:>16.4} {:>16.4} {:>18}",
            m.k, m.l, first, last, critical
        )?;
    }
    write_in_plane(diagram, out)
}

/// The in-plane waves' table: turning-frame frequencies at the first and
/// last speed, the critical speed where the backward wave stands still.
fn write_in_plane(diagram: &CampbellDiagram, out: &mut impl Write) -> std::io::Result<()> {
    if diagram.in_plane.is_empty() {
        return Ok(());
    }
    writeln!(
        out,
        "In-plane waves, turning frame (forward / backward), Hz"
    )?;
    writeln!(
        out,
        "{:>4} {:>5} {:>25} {:>25} {:>18}",
        "k", "order", "f(Ω=first) Hz", "f(Ω=last) Hz", "critical rad/s"
    )?;
    let pair = |w: &[f64], b: &[f64], last: bool| {
        let at = |v: &[f64]| {
            if last { v.last() } else { v.first() }
                .copied()
                .unwrap_or(f64::NAN)
        };
        format!("{:.4} / {:.4}", at(w), at(b))
    };
    for w in &diagram.in_plane {
        let critical = diagram
            .in_plane_critical_speeds
            .iter()
            .find(|c| c.k == w.k && c.order == w.order)
            .map_or("—".to_string(), |c| format!("{:.3}", c.rad_s));
        writeln!(
            out,
            "{:>4} {:>5} {:>25} {:>25} {:>18}",
            w.k,
            w.order,
            pair(&w.rotating_forward_hz, &w.rotating_backward_hz, false),
            pair(&w.rotating_forward_hz, &w.rotating_backward_hz, true),
            critical
        )?;
    }
    Ok(())
}
