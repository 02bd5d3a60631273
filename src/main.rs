//! `annular_plate`: the node (default), `modes`, `simulate`.

use annular_plate::cli;
use annular_plate::dynamics::Simulation;
use anyhow::Context;
use clap::{Parser, Subcommand};
use signal_hook::consts::{SIGINT, SIGTERM};
use std::io::{BufWriter, IsTerminal, Write};
use std::path::PathBuf;
use std::sync::atomic::AtomicBool;
use std::sync::Arc;

#[derive(Parser)]
#[command(
    name = "annular_plate",
    version,
    about = "A rotating annular Kirchhoff plate as a ROS 2 node (DLR FlexibleBodies AnnularPlate)"
)]
struct Cli {
    #[command(subcommand)]
    command: Option<Command>,
}

#[derive(Subcommand)]
enum Command {
    /// Print the mode table of a params file.
    Modes {
        file: PathBuf,
        /// Machine-readable output: {"modes": [{"k", "l", "shape", "frequency_hz", ...}]}.
        #[arg(long)]
        json: bool,
        /// Parameter overrides `-p NAME:=VALUE` (as after --ros-args), e.g. -p plate.inner_boundary:=supported.
        #[arg(short = 'p', long = "param", value_name = "NAME:=VALUE")]
        overrides: Vec<String>,
    },
    /// Simulate offline and write a CSV and/or a rosbag2 bag.
    Simulate {
        file: PathBuf,
        /// Simulated time, s (at least one step, 1/simulation.rate_hz).
        #[arg(long, allow_negative_numbers = true)]
        duration: f64,
        /// Output CSV file ("-" for stdout).
        #[arg(long)]
        csv: Option<PathBuf>,
        /// Also (or only) write the node's topics, in simulated time, to this new rosbag2 directory (MCAP).
        #[arg(long, value_name = "DIR")]
        bag: Option<PathBuf>,
        /// Rows and bag messages at this rate, Hz (it must divide simulation.rate_hz); default: every step.
        #[arg(long, value_name = "HZ", allow_negative_numbers = true)]
        output_rate: Option<f64>,
        /// Let --output-rate go below twice the squeal frequency of a scene with pads (refused otherwise: the rows would alias it).
        #[arg(long)]
        allow_aliasing: bool,
        /// No progress bar.
        #[arg(long)]
        quiet: bool,
        /// Parameter overrides `-p NAME:=VALUE` (as after --ros-args), e.g. -p joint.speed:=40.0.
        #[arg(short = 'p', long = "param", value_name = "NAME:=VALUE")]
        overrides: Vec<String>,
    },
    /// Draw pictures (PNG or SVG): time histories from a `simulate` CSV, mode shapes.
    Plot {
        #[command(subcommand)]
        what: cli::plot::PlotCommand,
    },
    /// Measure accuracy against cost (radial splines, mode count, integrator and step) and recommend settings.
    Study(cli::study::StudyArgs),
    /// The Campbell diagram: frequencies over spin speed, critical speeds (docs/rotor_dynamics.md).
    Campbell(cli::campbell::CampbellArgs),
    /// The squeal stability map over friction coefficient × speed; `stability merge` joins shards.
    Stability(cli::stability::StabilityArgs),
    /// Work on a recorded bag: `bag repair DIR` makes a killed recording readable.
    Bag {
        #[command(subcommand)]
        what: BagCommand,
    },
    /// Run the ROS 2 node (default scene: a brake test bench).
    Run {
        /// Params file (ROS 2 format); omitted: the built-in brake test bench.
        file: Option<PathBuf>,
        /// Record the node's topics into this new rosbag2 directory (MCAP) until shutdown.
        #[arg(long, value_name = "DIR")]
        record: Option<PathBuf>,
        /// ROS arguments: --ros-args -r __node:=NAME -p name:=value --params-file F ...
        #[arg(trailing_var_arg = true, allow_hyphen_values = true)]
        ros_args: Vec<String>,
    },
}

#[derive(Subcommand)]
enum BagCommand {
    /// Rewrite a bag whose recording was killed (no MCAP summary) with every
    /// message up to where the file breaks off, and a fresh metadata.yaml;
    /// the damaged file is kept as `<name>.broken`.
    Repair { dir: PathBuf },
}

/// Errors go to stderr as one readable message (with its causes), exit status 1.
/// A closed pipe on the output (`simulate --csv - | head`) ends the program quietly.
/// Whether fd 1 was closed when the process started: Rust's runtime then
/// opens /dev/null read-write in its place (a shell's `>/dev/null` opens it
/// write-only), and writes to it succeed without a trace.
fn stdout_was_closed() -> bool {
    let null =
        std::fs::read_link("/proc/self/fd/1").is_ok_and(|p| p == std::path::Path::new("/dev/null"));
    let flags = std::fs::read_to_string("/proc/self/fdinfo/1")
        .ok()
        .and_then(|t| {
            t.lines().find_map(|l| {
                l.strip_prefix("flags:")
                    .and_then(|v| u32::from_str_radix(v.trim(), 8).ok())
            })
        });
    null && flags.is_some_and(|f| f & 0o3 == 0o2)
}

fn main() -> std::process::ExitCode {
    match run() {
        Ok(()) => std::process::ExitCode::SUCCESS,
        Err(e) if is_broken_pipe(&e) => std::process::ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e:#}");
            std::process::ExitCode::FAILURE
        }
    }
}

/// Steps between two output rows for `--output-rate HZ`: a whole number n with
/// HZ = simulation.rate_hz / n, otherwise refused naming both rates.
fn output_every(output_rate: Option<f64>, rate_hz: f64) -> anyhow::Result<u64> {
    let Some(out) = output_rate else { return Ok(1) };
    let n = (rate_hz / out).round();
    anyhow::ensure!(
        out.is_finite() && out > 0.0 && n >= 1.0 && (n * out - rate_hz).abs() <= 1e-9 * rate_hz,
        "--output-rate {out} Hz does not divide simulation.rate_hz = {rate_hz} Hz: give rate_hz / n for a whole n ≥ 1 (e.g. {} Hz)",
        rate_hz / (rate_hz / 1000.0).round().max(1.0)
    );
    Ok(n as u64)
}

fn is_broken_pipe(e: &anyhow::Error) -> bool {
    let pipe = |io: &std::io::Error| io.kind() == std::io::ErrorKind::BrokenPipe;
    e.chain().any(|c| {
        c.downcast_ref::<std::io::Error>().is_some_and(pipe)
            || matches!(c.downcast_ref::<cli::error::CliError>(), Some(cli::error::CliError::Write(io)) if pipe(io))
    })
}

fn run() -> anyhow::Result<()> {
    // `ros2 run` and launch files append `--ros-args ...`: split it off before clap.
    let args: Vec<String> = std::env::args().collect();
    let split = args
        .iter()
        .position(|a| a == "--ros-args")
        .unwrap_or(args.len());
    let (own, ros_args) = args.split_at(split);
    let cli = Cli::parse_from(own);
    match cli.command {
        None => run_node(None, ros_args, None),
        Some(Command::Run {
            file,
            record,
            ros_args: mut extra,
        }) => {
            extra.extend_from_slice(ros_args);
            run_node(file, &extra, record)
        }
        Some(Command::Modes {
            file,
            json,
            overrides,
        }) => {
            let config = cli::load_config_with(&file, &overrides)?;
            let (model, in_plane) = annular_plate::model::PlateModel::bending_and_in_plane(
                &config.plate,
                &config.centrifugal,
            )
            .with_context(|| format!("{}", file.display()))?;
            if let Some(text) = model.thickness_warning_text() {
                eprintln!("warning: {text}");
            }
            let stdout = std::io::stdout();
            cli::modes::write(&model, &in_plane, json, &mut stdout.lock())?;
            Ok(())
        }
        Some(Command::Bag {
            what: BagCommand::Repair { dir },
        }) => {
            match annular_plate::bag::repair::repair(&dir)
                .with_context(|| format!("bag repair {}", dir.display()))?
            {
                annular_plate::bag::repair::Repair::AlreadyComplete { files } => {
                    eprintln!(
                        "{}: {} .mcap file(s), each complete or repaired before: nothing to repair",
                        dir.display(),
                        files.len()
                    )
                }
                annular_plate::bag::repair::Repair::Repaired { repaired } => {
                    for (source, summary) in &repaired {
                        eprintln!(
                            "repaired {}: {} messages on {} topics ({:.3} s) in {}; the damaged file is left as it was",
                            source.display(),
                            summary.message_count,
                            summary.topics.len(),
                            summary.duration as f64 * 1e-9,
                            summary.dir.join(&summary.file).display()
                        );
                    }
                }
            }
            Ok(())
        }
        Some(Command::Plot { what }) => Ok(cli::plot::main(what)?),
        Some(Command::Study(args)) => Ok(cli::study::main(args)?),
        Some(Command::Campbell(args)) => Ok(cli::campbell::main(args)?),
        Some(Command::Stability(args)) => Ok(cli::stability::main(args)?),
        Some(Command::Simulate {
            file,
            duration,
            csv,
            bag,
            output_rate,
            allow_aliasing,
            quiet,
            overrides,
        }) => {
            anyhow::ensure!(
                csv.is_some() || bag.is_some(),
                "simulate writes --csv OUT, --bag DIR or both: give at least one"
            );
            anyhow::ensure!(
                duration.is_finite() && duration >= 0.0,
                "--duration must be a finite number ≥ 0 s, got {duration}"
            );
            let config = cli::load_config_with(&file, &overrides)?;
            let dt = 1.0 / config.simulation.rate_hz;
            anyhow::ensure!(
                duration == 0.0 || duration >= 0.5 * dt,
                "--duration {duration} s is shorter than one step (1/simulation.rate_hz = {dt} s): give 0 (the initial state only) or at least {dt} s"
            );
            let every = output_every(output_rate, config.simulation.rate_hz)?;
            let rate_hz = config.simulation.rate_hz;
            let mut sim = Simulation::new(config).with_context(|| format!("{}", file.display()))?;
            if output_rate.is_some() {
                cli::simulate::check_output_rate(&sim, rate_hz / every as f64, allow_aliasing)
                    .with_context(|| format!("{}", file.display()))?;
            }
            let show = !quiet && std::io::stderr().is_terminal();
            let bar = indicatif::ProgressBar::new(1000);
            if !show {
                bar.set_draw_target(indicatif::ProgressDrawTarget::hidden());
            }
            let progress = |f: f64| bar.set_position((f * 1000.0) as u64);
            let started = std::time::Instant::now();
            let mut out: Option<Box<dyn Write>> = match &csv {
                None => None,
                // Its own descriptor: std's stdout reports writes to a closed fd 1 as done.
                Some(p) if p.as_os_str() == "-" => {
                    use std::os::fd::AsFd;
                    if stdout_was_closed() {
                        anyhow::bail!("--csv -: stdout is closed (the process started without it), nothing to write the CSV to; give --csv FILE or redirect stdout");
                    }
                    let fd = std::io::stdout()
                        .as_fd()
                        .try_clone_to_owned()
                        .context("--csv -: stdout is closed, nothing to write the CSV to")?;
                    Some(Box::new(BufWriter::with_capacity(
                        1 << 18,
                        std::fs::File::from(fd),
                    )))
                }
                Some(p) => Some(Box::new(BufWriter::with_capacity(
                    1 << 18,
                    std::fs::File::create(p)
                        .with_context(|| format!("cannot create {}", p.display()))?,
                ))),
            };
            let mut bag = bag
                .map(|dir| cli::record::BagOutput::create(&dir, &sim, &file, &overrides))
                .transpose()?;
            let record = |s: &Simulation| bag.as_mut().map_or(Ok(()), |b| b.record(s));
            // SIGINT / SIGTERM end the run after the current step and the bag is
            // finished as after a full run; a second signal ends the process at once.
            let stop = Arc::new(AtomicBool::new(false));
            for signal in [SIGINT, SIGTERM] {
                signal_hook::flag::register_conditional_shutdown(signal, 1, Arc::clone(&stop))
                    .context("cannot handle signals")?;
                signal_hook::flag::register(signal, Arc::clone(&stop))
                    .context("cannot handle signals")?;
            }
            let result = cli::simulate::run_with(
                &mut sim,
                duration,
                every,
                out.as_deref_mut(),
                record,
                progress,
                &stop,
            );
            bar.finish_and_clear();
            drop(out);
            let bag_line = bag.map(|b| b.finish()).transpose()?;
            let steps = result?;
            if sim.unlocated_substeps() > 0 {
                eprintln!("warning: {}", sim.unlocated_warning());
            }
            if stop.load(std::sync::atomic::Ordering::Relaxed) {
                if let Some(line) = bag_line {
                    eprintln!("{line}");
                }
                return Err(cli::error::CliError::Interrupted {
                    time: sim.time(),
                    steps,
                }
                .into());
            }
            if !quiet {
                eprintln!(
                    "{steps} steps, {duration} s simulated in {:.3} s wall",
                    started.elapsed().as_secs_f64()
                );
                if let Some(line) = bag_line {
                    eprintln!("{line}");
                }
            }
            Ok(())
        }
    }
}

fn run_node(
    file: Option<PathBuf>,
    ros_args: &[String],
    record: Option<PathBuf>,
) -> anyhow::Result<()> {
    Ok(annular_plate::ros::run_node(file, ros_args, record)?)
}
