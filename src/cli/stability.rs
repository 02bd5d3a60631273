//! `annular_plate stability FILE --mu FROM:TO:N --speeds FROM:TO:N [--json] [--plot F] [--shard i/n] [--threads T]`
//! and `annular_plate stability merge SHARD.json...`: the squeal stability map
//! (`crate::dynamics::stability_map`, docs/rotor_dynamics.md).

use super::campbell::parse_range;
use super::error::{CliError, CliResult};
use crate::dynamics::stability_map::{shard_rows, stability_map, SpeedRow};
use crate::dynamics::Simulation;
use serde::{Deserialize, Serialize};
use std::io::Write;
use std::path::PathBuf;

#[derive(clap::Args, Debug, Clone)]
#[command(args_conflicts_with_subcommands = true, subcommand_negates_reqs = true)]
pub struct StabilityArgs {
    #[command(subcommand)]
    pub merge: Option<MergeCommand>,
    /// Params file (ROS 2 format) of a scene with pads.
    #[arg(required = true)]
    pub file: Option<PathBuf>,
    /// N friction coefficients from FROM to TO, inclusive.
    #[arg(long, value_name = "FROM:TO:N", allow_hyphen_values = true, required = true)]
    pub mu: Option<String>,
    /// N speeds from FROM to TO rad/s, inclusive (a single speed: S:S:1).
    #[arg(long, value_name = "FROM:TO:N", allow_hyphen_values = true, required = true)]
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
    /// Worker threads (default: the machine's cores).
    #[arg(long)]
    pub threads: Option<usize>,
    /// Parameter overrides `-p NAME:=VALUE` (as after --ros-args), e.g. -p plate.residual_flexibility:=false.
    #[arg(short = 'p', long = "param", value_name = "NAME:=VALUE")]
    pub overrides: Vec<String>,
}

#[derive(clap::Subcommand, Debug, Clone)]
pub enum MergeCommand {
    /// Join the JSON of all shards of one map into the single run's JSON.
    Merge { shards: Vec<PathBuf> },
}

/// The least stable mode of a grid point.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct UnstableMode {
    pub k: u32,
    pub l: u32,
    pub frequency_hz: f64,
}

/// Which part of the map a document holds.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Shard {
    pub index: usize,
    pub count: usize,
    pub speeds_total: usize,
}

/// The JSON document: `growth_rate[s][m]` and `mode[s][m]` for speed s and μ m.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct StabilityMap {
    pub speeds_rad_s: Vec<f64>,
    pub mu: Vec<f64>,
    pub growth_rate: Vec<Vec<f64>>,
    pub threshold_mu: Vec<Option<f64>>,
    pub mode: Vec<Vec<UnstableMode>>,
    #[serde(skip_serializing_if = "Option::is_none", default)]
    pub shard: Option<Shard>,
}

impl StabilityMap {
    fn from_rows(rows: &[SpeedRow], mu: &[f64], shard: Option<Shard>) -> StabilityMap {
        StabilityMap {
            speeds_rad_s: rows.iter().map(|r| r.speed).collect(),
            mu: mu.to_vec(),
            growth_rate: rows.iter().map(|r| r.points.iter().map(|p| p.growth_rate).collect()).collect(),
            threshold_mu: rows.iter().map(|r| r.threshold_mu).collect(),
            mode: rows.iter().map(|r| r.points.iter().map(|p| UnstableMode { k: p.k, l: p.l, frequency_hz: p.frequency_hz }).collect()).collect(),
            shard,
        }
    }
}

fn parse_shard(text: &str) -> CliResult<(usize, usize)> {
    let bad = || CliError::Usage(format!("--shard {text}: give i/n with 1 ≤ i ≤ n (e.g. 3/8)"));
    let (i, n) = text.split_once('/').ok_or_else(bad)?;
    let (i, n): (usize, usize) = (i.trim().parse().map_err(|_| bad())?, n.trim().parse().map_err(|_| bad())?);
    if n == 0 || i == 0 || i > n {
        return Err(bad());
    }
    Ok((i, n))
}

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
    let speeds = parse_range("--speeds", args.speeds.as_deref().expect("clap requires --speeds"))?;
    let config = super::load_config_with(&file, &args.overrides)?;
    if let Some(p) = &args.plot {
        super::plot::check_output_path(p)?;
    }
    if config.pads.is_none() {
        return Err(CliError::Usage(format!("{}: the scene has no pads (pads.*): nothing can squeal", file.display())));
    }
    let shard = args.shard.as_deref().map(parse_shard).transpose()?;
    let threads = args.threads.unwrap_or_else(|| std::thread::available_parallelism().map_or(1, |n| n.get()));
    if threads == 0 {
        return Err(CliError::Usage("--threads must be at least 1".into()));
    }
    let sim = Simulation::new(config).map_err(|e| CliError::Usage(format!("{}: {e}", file.display())))?;
    let (rows, shard) = match shard {
        Some((i, n)) => {
            let range = shard_rows(speeds.len(), i - 1, n);
            (stability_map(sim.scene(), &speeds[range], &mu, threads), Some(Shard { index: i, count: n, speeds_total: speeds.len() }))
        }
        None => (stability_map(sim.scene(), &speeds, &mu, threads), None),
    };
    let map = StabilityMap::from_rows(&rows, &mu, shard);
    if let Some(p) = &args.plot {
        let grid = super::plot::StabilityGrid { speeds: &map.speeds_rad_s, mu: &map.mu, growth_rate: &map.growth_rate, threshold_mu: &map.threshold_mu };
        super::plot::stability_map(&grid, p, super::plot::Size { width: 1200, height: 800 })?;
    }
    let stdout = std::io::stdout();
    let mut out = stdout.lock();
    if args.json || shard.is_some() {
        serde_json::to_writer_pretty(&mut out, &map).map_err(std::io::Error::from)?;
        writeln!(out)?;
        return Ok(());
    }
    writeln!(out, "{:>12} {:>14} {:>16} {:>14}", "speed_rad_s", "threshold_mu", "max_rate_1/s", "at_mu")?;
    for (s, &speed) in map.speeds_rad_s.iter().enumerate() {
        let (m, rate) = map.growth_rate[s].iter().enumerate().fold((0, f64::NEG_INFINITY), |b, (m, &r)| if r > b.1 { (m, r) } else { b });
        let threshold = map.threshold_mu[s].map_or("—".to_string(), |t| format!("{t:.6}"));
        writeln!(out, "{speed:>12.4} {threshold:>14} {rate:>16.6} {:>14.4}", map.mu[m])?;
    }
    Ok(())
}

/// Join shard documents (any order) into the single run's document.
pub fn merge(paths: &[PathBuf]) -> CliResult<StabilityMap> {
    if paths.is_empty() {
        return Err(CliError::Usage("stability merge: give the shard JSON files".into()));
    }
    let mut docs = Vec::new();
    for p in paths {
        let text = std::fs::read_to_string(p).map_err(|error| CliError::Io { what: "read", path: p.display().to_string(), error })?;
        let doc: StabilityMap = serde_json::from_str(&text).map_err(|e| CliError::Usage(format!("{}: not a stability shard: {e}", p.display())))?;
        let shard = doc.shard.ok_or_else(|| CliError::Usage(format!("{}: a complete map, not a shard", p.display())))?;
        docs.push((shard, doc, p));
    }
    docs.sort_by_key(|(s, ..)| s.index);
    let (first, first_mu, first_path) = (docs[0].0, docs[0].1.mu.clone(), docs[0].2.clone());
    let indices: Vec<usize> = docs.iter().map(|(s, ..)| s.index).collect();
    if indices != (1..=first.count).collect::<Vec<_>>() {
        return Err(CliError::Usage(format!("stability merge: shards {indices:?} given, all of 1..={} needed once each", first.count)));
    }
    let mut merged = StabilityMap { speeds_rad_s: vec![], mu: first_mu.clone(), growth_rate: vec![], threshold_mu: vec![], mode: vec![], shard: None };
    for (s, doc, p) in docs {
        if s.count != first.count || s.speeds_total != first.speeds_total || doc.mu != first_mu {
            return Err(CliError::Usage(format!("{}: a shard of another map than {} (shard count, speeds or μ differ)", p.display(), first_path.display())));
        }
        merged.speeds_rad_s.extend(doc.speeds_rad_s);
        merged.growth_rate.extend(doc.growth_rate);
        merged.threshold_mu.extend(doc.threshold_mu);
        merged.mode.extend(doc.mode);
    }
    if merged.speeds_rad_s.len() != first.speeds_total {
        return Err(CliError::Usage(format!("stability merge: {} speeds joined, the map has {}", merged.speeds_rad_s.len(), first.speeds_total)));
    }
    Ok(merged)
}
