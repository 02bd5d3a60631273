//! `annular_plate stability FILE --mu FROM:TO:N --speeds FROM:TO:N [--json] [--plot F] [--shard i/n] [--threads T]`
//! and `annular_plate stability merge SHARD.json...`: the squeal stability map
//! (`crate::dynamics::stability_map`, docs/rotor_dynamics.md).

use super::campbell::parse_range;
use super::error::{CliError, CliResult};
use crate::config::Params;
use crate::dynamics::stability;
use crate::dynamics::stability_map::{shard_rows, stability_map, SpeedRow};
use crate::dynamics::Simulation;
use serde::{Deserialize, Serialize};
use std::io::Read;
use std::io::Write;
use std::path::{Path, PathBuf};

/// The largest friction coefficient (`pads.friction_coefficient`'s rule).
const MAX_MU: f64 = 2.0;

/// `annular_plate stability`: the linear stability map over speed and
/// friction coefficient μ (or `stability merge` of its shards).
#[derive(clap::Args, Debug, Clone)]
#[command(args_conflicts_with_subcommands = true, subcommand_negates_reqs = true)]
pub struct StabilityArgs {
    /// `stability merge SHARDS…` instead of a map.
    #[command(subcommand)]
    pub merge: Option<MergeCommand>,
    /// Params file (ROS 2 format) of a scene with pads.
    #[arg(required = true)]
    pub file: Option<PathBuf>,
    /// N friction coefficients from FROM to TO, inclusive.
    #[arg(
        long,
        value_name = "FROM:TO:N",
        allow_hyphen_values = true,
        required = true
    )]
    pub mu: Option<String>,
    /// N speeds from FROM to TO rad/s, inclusive (a single speed: S:S:1).
    #[arg(
        long,
        value_name = "FROM:TO:N",
        allow_hyphen_values = true,
        required = true
    )]
    pub speeds: Option<String>,
    /// Machine-readable output (always, with --shard).
    #[arg(long)]
    pub json: bool,
    /// Compute shard i of n (1-based): a contiguous block of the speed rows; join with `stability merge`.
    #[arg(long, value_name = "i/n")]
    pub shard: Option<String>,
    /// Also draw the map to this file (.png or .svg).
    #[arg(long, value_name = "OUT")]
    pub plot: Option<PathBuf>,
    /// Worker threads (default: the machine's cores; at most 1024).
    #[arg(long)]
    pub threads: Option<usize>,
    /// Refuse a grid of more μ × speed cells than this (each cell is one
    /// eigendecomposition; the error gives the estimate of time and memory).
    #[arg(long, value_name = "CELLS", default_value_t = DEFAULT_MAX_CELLS)]
    pub max_cells: usize,
    /// Parameter overrides `-p NAME:=VALUE` (as after --ros-args), e.g. -p plate.residual_flexibility:=false.
    #[arg(short = 'p', long = "param", value_name = "NAME:=VALUE")]
    pub overrides: Vec<String>,
}

/// The subcommand of `stability`.
#[derive(clap::Subcommand, Debug, Clone)]
pub enum MergeCommand {
    /// Join the JSON of all shards of one map into the single run's JSON.
    Merge {
        /// The shards' JSON files, all of one map.
        shards: Vec<PathBuf>,
    },
}

/// The least stable mode of a grid point.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct UnstableMode {
    /// Nodal diameters k of the plate mode with the largest amplitude in
    /// its eigenvector.
    pub k: u32,
    /// Nodal circles l (the order l of an in-plane mode).
    pub l: u32,
    /// An in-plane mode (written only when true).
    #[serde(default, skip_serializing_if = "std::ops::Not::not")]
    pub in_plane: bool,
    /// Its frequency |Im λ| / 2π in the space-fixed frame, Hz.
    pub frequency_hz: f64,
}

/// `--max-cells` unless given: about 200 MB of results and ~10 minutes of
/// eigendecompositions on one core for the brake-squeal scene (0.35 ms a cell measured).
pub const DEFAULT_MAX_CELLS: usize = 1_000_000;
/// The most `--threads`.
pub const MAX_THREADS: usize = 1024;
/// Memory of one cell: its grid point while computed and its share of the document.
const BYTES_PER_CELL: usize = 200;
/// `stability merge` reads at most this much of a shard (a map of
/// `DEFAULT_MAX_CELLS` cells is about 150 MB of JSON).
pub const MAX_SHARD_BYTES: u64 = 256 << 20;

/// Which part of the map a document holds, and the whole grid it is part of.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Shard {
    /// Which shard (from 0).
    pub index: usize,
    /// Shards of the whole map.
    pub count: usize,
    /// Speeds of the whole map.
    pub speeds_total: usize,
    /// `--speeds FROM:TO:N` of the whole map (N = `speeds_total`).
    pub speeds_from: f64,
    /// `TO` of `--speeds FROM:TO:N` of the whole map, rad/s.
    pub speeds_to: f64,
}

/// The JSON document: `growth_rate[s][m]` and `mode[s][m]` for speed s and μ m.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct StabilityMap {
    /// FNV-1a 64 of the effective parameters (every declared key's value or
    /// default) the map was computed with: shards of one map carry the same.
    pub params_digest: String,
    /// The speeds, rad/s.
    pub speeds_rad_s: Vec<f64>,
    /// The friction coefficients μ.
    pub mu: Vec<f64>,
    /// Largest real part of the eigenvalues at speed s and μ m, 1/s (> 0: unstable).
    pub growth_rate: Vec<Vec<f64>>,
    /// Per speed, the smallest μ of the range where max Re λ > 0, bisected
    /// between grid points (None: stable throughout).
    pub threshold_mu: Vec<Option<f64>>,
    /// The least stable mode at speed s and μ m.
    pub mode: Vec<Vec<UnstableMode>>,
    /// The part of the map this document holds (None: all of it).
    #[serde(skip_serializing_if = "Option::is_none", default)]
    pub shard: Option<Shard>,
}

impl StabilityMap {
    fn from_rows(
        rows: &[SpeedRow],
        mu: &[f64],
        shard: Option<Shard>,
        params_digest: String,
    ) -> StabilityMap {
        StabilityMap {
            params_digest,
            speeds_rad_s: rows.iter().map(|r| r.speed).collect(),
            mu: mu.to_vec(),
            growth_rate: rows
                .iter()
                .map(|r| r.points.iter().map(|p| p.growth_rate).collect())
                .collect(),
            threshold_mu: rows.iter().map(|r| r.threshold_mu).collect(),
            mode: rows
                .iter()
                .map(|r| {
                    r.points
                        .iter()
                        .map(|p| UnstableMode {
                            k: p.k,
                            l: p.l,
                            in_plane: p.in_plane,
                            frequency_hz: p.frequency_hz,
                        })
                        .collect()
                })
                .collect(),
            shard,
        }
    }
}

/// FNV-1a 64 (hex) of the effective parameters: every declared key with its
/// given value or its default, in the table's order.
pub fn params_digest(params: &Params) -> String {
    let mut h: u64 = 0xcbf2_9ce4_8422_2325;
    for p in crate::dynamics::load_models::PARAMETERS.params() {
        let value = params.get(p.key).cloned().or_else(|| p.default.to_param());
        for b in format!("{}={value:?}\n", p.key).bytes() {
            h = (h ^ u64::from(b)).wrapping_mul(0x0100_0000_01b3);
        }
    }
    format!("{h:016x}")
}

/// Refuse a grid beyond `max_cells`, naming the limit, the flag and the estimate.
fn check_grid(mu: usize, speeds: usize, max_cells: usize) -> CliResult<usize> {
    let cells = mu.saturating_mul(speeds);
    if cells > max_cells {
        return Err(CliError::Usage(format!(
            "--mu × --speeds = {mu} × {speeds} = {cells} cells, more than the limit of {max_cells} (--max-cells): \
             about {:.1} GB of results and {cells} eigendecompositions (~{:.1} core-hours at ~0.5 ms each for the brake-squeal scene, more with more modes); \
             split it into shards (--shard i/n) or raise --max-cells",
            cells as f64 * BYTES_PER_CELL as f64 / 1e9,
            cells as f64 * 5e-4 / 3600.0
        )));
    }
    Ok(cells)
}

/// Every speed within the scene's `limits.max_speed` (the node refuses faster commands too).
fn check_speeds(option: &str, speeds: &[f64], max_speed: f64) -> CliResult<()> {
    if let Some(s) = speeds.iter().find(|s| s.abs() > max_speed) {
        return Err(CliError::Usage(format!(
            "{option}: the speed {s:e} rad/s is above limits.max_speed = {max_speed:e} rad/s of the scene (the linearisation is not built beyond it; raise limits.max_speed with -p, at most 1e6)"
        )));
    }
    Ok(())
}

fn parse_shard(text: &str) -> CliResult<(usize, usize)> {
    let bad = || {
        CliError::Usage(format!(
            "--shard {text}: give i/n with 1 ≤ i ≤ n (e.g. 3/8)"
        ))
    };
    let (i, n) = text.split_once('/').ok_or_else(bad)?;
    let (i, n): (usize, usize) = (
        i.trim().parse().map_err(|_| bad())?,
        n.trim().parse().map_err(|_| bad())?,
    );
    if n == 0 || i == 0 || i > n {
        return Err(bad());
    }
    Ok((i, n))
}

/// Run `annular_plate stability`.
pub fn main(args: StabilityArgs) -> CliResult<()> {
    if let Some(MergeCommand::Merge { shards }) = args.merge {
        let merged = merge(&shards)?;
        let stdout = std::io::stdout();
        let mut out = stdout.lock();
        serde_json::to_writer_pretty(&mut out, &merged).map_err(std::io::Error::from)?;
        writeln!(out)?;
        return Ok(());
    }
    let file = args.file.expect("clap requires FILE");
    let mu = parse_range("--mu", args.mu.as_deref().expect("clap requires --mu"))?;
    let speeds = parse_range(
        "--speeds",
        args.speeds.as_deref().expect("clap requires --speeds"),
    )?;
    let params = super::params_with_overrides(&file, &args.overrides)?;
    let digest = params_digest(&params);
    let config = super::load_config_with(&file, &args.overrides)?;
    if let Some(p) = &args.plot {
        super::plot::check_output_path(p)?;
    }
    if !stability::can_squeal(&config) {
        return Err(CliError::Usage(format!(
            "{}: the scene has no pads (pads.*): nothing can squeal",
            file.display()
        )));
    }
    check_speeds("--speeds", &speeds, config.limits.max_speed)?;
    if let Some(m) = mu.iter().find(|&&m| m > MAX_MU) {
        return Err(CliError::Usage(format!("--mu: the friction coefficient {m} is above {MAX_MU} (the rule of pads.friction_coefficient)")));
    }
    let shard = args.shard.as_deref().map(parse_shard).transpose()?;
    if let Some((_, n)) = shard {
        if n > speeds.len() {
            return Err(CliError::Usage(format!(
                "--shard {}: {n} shards of {} speed rows would leave shards empty; give n ≤ {} (the number of --speeds)",
                args.shard.as_deref().unwrap_or_default(),
                speeds.len(),
                speeds.len()
            )));
        }
    }
    let rows = shard.map_or(speeds.len(), |(i, n)| {
        shard_rows(speeds.len(), i - 1, n).len()
    });
    let cells = check_grid(mu.len(), rows, args.max_cells)?;
    let threads = args
        .threads
        .unwrap_or_else(|| std::thread::available_parallelism().map_or(1, |n| n.get()));
    if threads == 0 || threads > MAX_THREADS {
        return Err(CliError::Usage(format!(
            "--threads must be between 1 and {MAX_THREADS}"
        )));
    }
    if cells >= 100_000 {
        eprintln!(
            "stability: {cells} cells on {threads} thread(s): about {:.0} s at ~0.5 ms per cell (brake-squeal scene), {:.0} MB of results",
            cells as f64 * 5e-4 / threads as f64,
            cells as f64 * BYTES_PER_CELL as f64 / 1e6
        );
    }
    let sim =
        Simulation::new(config).map_err(|e| CliError::Usage(format!("{}: {e}", file.display())))?;
    sim.scene()
        .load_models
        .check_linear()
        .map_err(|e| CliError::Usage(format!("{}: {e}", file.display())))?;
    let (rows, shard) = match shard {
        Some((i, n)) => {
            let range = shard_rows(speeds.len(), i - 1, n);
            let whole = Shard {
                index: i,
                count: n,
                speeds_total: speeds.len(),
                speeds_from: speeds[0],
                speeds_to: speeds[speeds.len() - 1],
            };
            (
                stability_map(sim.scene(), &speeds[range], &mu, threads),
                Some(whole),
            )
        }
        None => (stability_map(sim.scene(), &speeds, &mu, threads), None),
    };
    let map = StabilityMap::from_rows(&rows, &mu, shard, digest);
    if let Some(p) = &args.plot {
        let grid = super::plot::StabilityGrid {
            speeds: &map.speeds_rad_s,
            mu: &map.mu,
            growth_rate: &map.growth_rate,
            threshold_mu: &map.threshold_mu,
        };
        super::plot::stability_map(
            &grid,
            p,
            super::plot::Size {
                width: 1200,
                height: 800,
            },
        )?;
    }
    let stdout = std::io::stdout();
    let mut out = stdout.lock();
    if args.json || shard.is_some() {
        serde_json::to_writer_pretty(&mut out, &map).map_err(std::io::Error::from)?;
        writeln!(out)?;
        return Ok(());
    }
    writeln!(
        out,
        "{:>12} {:>14} {:>16} {:>14}",
        "speed_rad_s", "threshold_mu", "max_rate_1/s", "at_mu"
    )?;
    for (s, &speed) in map.speeds_rad_s.iter().enumerate() {
        let (m, rate) =
            map.growth_rate[s]
                .iter()
                .enumerate()
                .fold(
                    (0, f64::NEG_INFINITY),
                    |b, (m, &r)| if r > b.1 { (m, r) } else { b },
                );
        let threshold = map.threshold_mu[s].map_or("—".to_string(), |t| format!("{t:.6}"));
        writeln!(
            out,
            "{speed:>12.4} {threshold:>14} {rate:>16.6} {:>14.4}",
            map.mu[m]
        )?;
    }
    Ok(())
}

/// Read one shard: at most [`MAX_SHARD_BYTES`], parsed as it is read.
fn read_shard(p: &Path) -> CliResult<StabilityMap> {
    let file = std::fs::File::open(p).map_err(|error| CliError::Io {
        what: "read",
        path: p.display().to_string(),
        error,
    })?;
    let mut reader = std::io::BufReader::new(file.take(MAX_SHARD_BYTES + 1));
    let doc: Result<StabilityMap, _> = serde_json::from_reader(&mut reader);
    let read_all = reader.get_ref().limit() == 0;
    match doc {
        _ if read_all => Err(CliError::Usage(format!("{}: more than {MAX_SHARD_BYTES} bytes, larger than any shard of a map within --max-cells", p.display()))),
        Ok(doc) => Ok(doc),
        Err(e) => Err(CliError::Usage(format!("{}: not a stability shard: {e}", p.display()))),
    }
}

/// What is wrong with one shard's arrays (lengths, finite values), if anything.
fn malformed(doc: &StabilityMap) -> Option<String> {
    let (rows, cols) = (doc.speeds_rad_s.len(), doc.mu.len());
    if doc.growth_rate.len() != rows || doc.mode.len() != rows || doc.threshold_mu.len() != rows {
        return Some(format!(
            "{rows} speeds but {} growth_rate rows, {} mode rows, {} threshold_mu values",
            doc.growth_rate.len(),
            doc.mode.len(),
            doc.threshold_mu.len()
        ));
    }
    if let Some(r) =
        (0..rows).find(|&r| doc.growth_rate[r].len() != cols || doc.mode[r].len() != cols)
    {
        return Some(format!(
            "row {r} has {} growth rates and {} modes for {cols} μ",
            doc.growth_rate[r].len(),
            doc.mode[r].len()
        ));
    }
    if doc
        .speeds_rad_s
        .iter()
        .chain(&doc.mu)
        .chain(doc.growth_rate.iter().flatten())
        .any(|x| !x.is_finite())
    {
        return Some("a speed, μ or growth rate is not a finite number".into());
    }
    None
}

/// Join shard documents (any order) into the single run's document. They
/// must be all shards of one map: the same parameters (digest), μ grid and
/// speed grid, each well formed, their speeds disjoint and together the
/// whole grid; otherwise the error names the shard and the difference.
pub fn merge(paths: &[PathBuf]) -> CliResult<StabilityMap> {
    if paths.is_empty() {
        return Err(CliError::Usage(
            "stability merge: give the shard JSON files".into(),
        ));
    }
    let mut docs = Vec::new();
    for p in paths {
        let doc = read_shard(p)?;
        let shard = doc.shard.ok_or_else(|| {
            CliError::Usage(format!("{}: a complete map, not a shard", p.display()))
        })?;
        if let Some(why) = malformed(&doc) {
            return Err(CliError::Usage(format!(
                "{}: a malformed shard: {why}",
                p.display()
            )));
        }
        docs.push((shard, doc, p));
    }
    docs.sort_by_key(|(s, ..)| s.index);
    let (first, first_path) = (docs[0].0, docs[0].2.clone());
    let (first_mu, first_digest) = (docs[0].1.mu.clone(), docs[0].1.params_digest.clone());
    let other = |p: &Path, what: String| {
        CliError::Usage(format!(
            "{}: a shard of another map than {}: {what}",
            p.display(),
            first_path.display()
        ))
    };
    for (s, doc, p) in &docs {
        if doc.params_digest != first_digest {
            return Err(other(p, format!("computed with other parameters (digest {} ≠ {first_digest}: scene or -p differ)", doc.params_digest)));
        }
        if doc.mu != first_mu {
            return Err(other(p, "the μ grid (--mu) differs".into()));
        }
        if s.count != first.count
            || s.speeds_total != first.speeds_total
            || s.speeds_from != first.speeds_from
            || s.speeds_to != first.speeds_to
        {
            return Err(other(
                p,
                format!(
                    "shard {}/{} of --speeds {}:{}:{} against {}/{} of {}:{}:{}",
                    s.index,
                    s.count,
                    s.speeds_from,
                    s.speeds_to,
                    s.speeds_total,
                    first.index,
                    first.count,
                    first.speeds_from,
                    first.speeds_to,
                    first.speeds_total
                ),
            ));
        }
    }
    let indices: Vec<usize> = docs.iter().map(|(s, ..)| s.index).collect();
    if first.count != docs.len() || !indices.iter().enumerate().all(|(i, &index)| index == i + 1) {
        return Err(CliError::Usage(format!(
            "stability merge: shards {indices:?} given, all of 1..={} needed once each",
            first.count
        )));
    }
    if first.speeds_total > super::campbell::MAX_POINTS {
        return Err(CliError::Usage(format!(
            "{}: speeds_total {} is above {}",
            first_path.display(),
            first.speeds_total,
            super::campbell::MAX_POINTS
        )));
    }
    let whole = super::campbell::linspace(first.speeds_from, first.speeds_to, first.speeds_total);
    let mut merged = StabilityMap {
        params_digest: first_digest,
        speeds_rad_s: vec![],
        mu: first_mu.clone(),
        growth_rate: vec![],
        threshold_mu: vec![],
        mode: vec![],
        shard: None,
    };
    for (s, doc, p) in docs {
        let range = shard_rows(first.speeds_total, s.index - 1, s.count);
        if doc.speeds_rad_s != whole[range.clone()] {
            return Err(CliError::Usage(format!(
                "{}: shard {}/{} holds speeds {:?}, not rows {}..{} of --speeds {}:{}:{} (speeds overlap, are missing or were edited)",
                p.display(), s.index, s.count, doc.speeds_rad_s.iter().take(4).collect::<Vec<_>>(), range.start + 1, range.end, first.speeds_from, first.speeds_to, first.speeds_total
            )));
        }
        merged.speeds_rad_s.extend(doc.speeds_rad_s);
        merged.growth_rate.extend(doc.growth_rate);
        merged.threshold_mu.extend(doc.threshold_mu);
        merged.mode.extend(doc.mode);
    }
    Ok(merged)
}
