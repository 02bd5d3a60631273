//! `annular_plate study [FILE]`: accuracy against cost, measured (see `crate::study`).
//!
//! Prints a table (or `--json`), optionally draws the Pareto picture
//! (`--plot OUT.png|OUT.svg`), shows a progress bar on a terminal.

use super::error::{CliError, CliResult};
use crate::study::{self, Recommendation, StudyPlan, StudyReport};
use std::fmt::Write as _;
use std::io::{IsTerminal, Write};
use std::path::PathBuf;

/// `annular_plate study`: the scene's natural frequencies, critical speeds
/// and recommendations.
#[derive(clap::Args, Debug, Clone)]
pub struct StudyArgs {
    /// Params file (ROS 2 format); omitted: the built-in lathe disc of the paper's section 5.1.
    pub file: Option<PathBuf>,
    /// Machine-readable output (schema "annular_plate.study/1") instead of the table.
    #[arg(long)]
    pub json: bool,
    /// A small grid (0.2 s instead of 8 s for the default study, measured on 2 shared vCPUs): for a first look and for tests.
    #[arg(long)]
    pub quick: bool,
    /// Also draw the error-vs-cost (Pareto) picture to this file (.png or .svg).
    #[arg(long, value_name = "OUT")]
    pub plot: Option<PathBuf>,
    /// Target relative errors for the recommendations, e.g. 1e-2,1e-3,1e-4.
    #[arg(long, value_delimiter = ',', value_name = "LIST")]
    pub targets: Option<Vec<f64>>,
    /// Simulated time of the trajectory axis, s (default 0.05; --quick 0.02).
    #[arg(long, value_name = "S")]
    pub duration: Option<f64>,
    /// No progress bar.
    #[arg(long)]
    pub quiet: bool,
    /// Parameter overrides `-p NAME:=VALUE` on FILE (as after --ros-args), e.g. -p plate.thickness:=0.01.
    #[arg(
        short = 'p',
        long = "param",
        value_name = "NAME:=VALUE",
        requires = "file"
    )]
    pub overrides: Vec<String>,
}

/// The plan the arguments ask for.
pub fn plan(args: &StudyArgs) -> CliResult<StudyPlan> {
    let mut plan = if args.quick {
        StudyPlan::quick()
    } else {
        StudyPlan::full()
    };
    if let Some(t) = &args.targets {
        if t.is_empty() || !t.iter().all(|x| x.is_finite() && *x > 0.0 && *x < 1.0) {
            return Err(CliError::Usage(format!(
                "--targets must be numbers in (0, 1), got {t:?}"
            )));
        };
        plan.targets = t.clone();
    }
    if let Some(d) = args.duration {
        if !(d.is_finite() && d * plan.sample_rate_hz >= 1.0 && d <= 10.0) {
            return Err(CliError::Usage(format!(
                "--duration must be between {} s and 10 s, got {d}",
                1.0 / plan.sample_rate_hz
            )));
        };
        plan.duration_s = d;
    }
    Ok(plan)
}

/// Run `annular_plate study`.
pub fn main(args: StudyArgs) -> CliResult<()> {
    let plan = plan(&args)?;
    let (config, source) = match &args.file {
        Some(f) => (
            super::load_config_with(f, &args.overrides)?,
            f.display().to_string(),
        ),
        None => (study::lathe_scene(), "built-in lathe disc".to_string()),
    };
    if let Some(p) = &args.plot {
        super::plot::check_output_path(p)?;
    }
    let show = !args.quiet && std::io::stderr().is_terminal();
    let bar = indicatif::ProgressBar::new(plan.units(&config) as u64);
    if show {
        bar.set_style(
            indicatif::ProgressStyle::with_template("{bar:30} {pos}/{len} {elapsed_precise} {msg}")
                .expect("valid template"),
        );
    } else {
        bar.set_draw_target(indicatif::ProgressDrawTarget::hidden());
    }
    let report = study::run(&config, &source, &plan, &mut |done, _total, what| {
        bar.set_position(done as u64);
        bar.set_message(what.to_string());
    })
    .map_err(|error| CliError::Study {
        source_name: source.clone(),
        error,
    })?;
    bar.finish_and_clear();
    let stdout = std::io::stdout();
    let mut out = stdout.lock();
    if args.json {
        serde_json::to_writer_pretty(&mut out, &report).map_err(std::io::Error::from)?;
        writeln!(out)?;
    } else {
        out.write_all(table(&report).as_bytes())?;
    }
    if let Some(p) = &args.plot {
        super::plot::pareto(
            &report,
            p,
            super::plot::Size {
                width: 1500,
                height: 560,
            },
        )?;
        if !args.json {
            writeln!(out, "\nPareto picture: {}", p.display())?;
        }
    }
    Ok(())
}

/// A duration, s, in readable units.
pub(crate) fn fmt_time(s: f64) -> String {
    if !s.is_finite() {
        return "—".into();
    }
    if s >= 1.0 {
        format!("{s:.2} s")
    } else if s >= 1e-3 {
        format!("{:.3} ms", s * 1e3)
    } else if s >= 1e-6 {
        format!("{:.3} µs", s * 1e6)
    } else {
        format!("{:.1} ns", s * 1e9)
    }
}

fn fmt_rate(hz: f64) -> String {
    if hz >= 1e6 {
        format!("{} MHz", hz / 1e6)
    } else if hz >= 1e3 {
        format!("{} kHz", hz / 1e3)
    } else {
        format!("{hz} Hz")
    }
}

fn fmt_rec<S>(
    r: &Recommendation<S>,
    setting: impl Fn(&S) -> String,
    cost: impl Fn(f64) -> String,
) -> String {
    match (&r.setting, r.claimed_error, r.cost) {
        (Some(s), Some(e), Some(c)) => format!(
            "{}{} (≤ {e:.1e}; {})",
            setting(s),
            if r.is_default { " [default]" } else { "" },
            cost(c)
        ),
        _ => "not reached in the grid".into(),
    }
}

/// A mode set as the recommendations name it.
pub(crate) fn fmt_mode_set(k_max: u32, l_max: u32, residual_flexibility: bool) -> String {
    format!(
        "k ≤ {k_max}, l ≤ {l_max}{}",
        if residual_flexibility {
            " + residual"
        } else {
            ", modes only"
        }
    )
}

/// The human-readable report.
pub fn table(r: &StudyReport) -> String {
    let mut o = String::new();
    let s = &r.scene;
    let _ = writeln!(
        o,
        "Study of {}: r_i = {} m, r_a = {} m, h = {} m, {}–{}, {} modes (k ∈ {:?}, l ∈ {:?}), {} radial splines, Ω = {:.4} rad/s, {} at {}",
        s.source,
        s.inner_radius,
        s.outer_radius,
        s.thickness,
        s.inner_boundary,
        s.outer_boundary,
        s.modes,
        s.nodal_diameters,
        s.nodal_circles,
        s.radial_splines,
        s.speed_rad_s,
        s.integrator,
        fmt_rate(s.rate_hz)
    );
    let _ = writeln!(o, "Errors are relative and reproducible to the last bit; times are the fastest of repeats on this machine and vary. * = on the error-vs-cost Pareto front.");

    // Axis 1.
    let a = &r.radial_splines;
    let _ = writeln!(o, "\n1. Natural frequencies vs plate.radial_splines");
    let reference = match a.reference.finer_check_radial_splines {
        None => format!(
            "{} splines; its difference from {} splines",
            a.reference.radial_splines, a.reference.check_radial_splines
        ),
        Some(finer) => format!(
            "{} splines per field (Mindlin); its larger difference from {} and {} (round-off)",
            a.reference.radial_splines, a.reference.check_radial_splines, finer
        ),
    };
    let _ = writeln!(
        o,
        "   error: {}\n   reference: {reference}, {:.1e}, bounds its own error",
        a.error_measure, a.reference.uncertainty
    );
    let _ = writeln!(
        o,
        "   {:>14} {:>14} {:>11} {:>14}",
        "radial_splines", "max rel error", "worst ⟨k,l⟩", "build time"
    );
    for row in &a.rows {
        let _ = writeln!(
            o,
            "   {:>14} {:>14.3e} {:>11} {:>14} {}",
            row.radial_splines.to_string(),
            row.max_relative_error,
            format!("⟨{},{}⟩", row.worst_mode.k, row.worst_mode.l),
            fmt_time(row.build_time_s),
            if row.pareto { "*" } else { "" }
        );
    }

    if let Some(a) = &r.in_plane_radial_splines {
        in_plane_table(&mut o, a);
    }

    // Axis 2.
    match &r.mode_count {
        Some(b) => mode_count_table(&mut o, b),
        None => {
            let _ = writeln!(
                o,
                "\n2. Steady deflection at the load point vs mode set: skipped (notes)"
            );
        }
    }

    if let Some(a) = &r.in_plane_mode_count {
        in_plane_response_table(&mut o, a);
    }

    // Axis 3.
    let c = &r.integrator;
    let _ = writeln!(
        o,
        "\n3. Trajectory vs integrator and output rate ({} s from rest, sampled at {}, {} modes)",
        c.duration_s,
        fmt_rate(c.sample_rate_hz),
        c.modes
    );
    let checks: Vec<String> = c
        .reference
        .checks
        .iter()
        .map(|k| {
            format!(
                "{} at {}: {:.1e}",
                k.integrator,
                fmt_rate(k.rate_hz),
                k.difference
            )
        })
        .collect();
    let _ = writeln!(
        o,
        "   error: {}\n   reference: {} at {}; checks {}; the larger difference bounds the reference's error; peak ‖q‖ = {:.3e} m",
        c.error_measure,
        c.reference.integrator,
        fmt_rate(c.reference.rate_hz),
        checks.join(", "),
        c.reference.peak_amplitude_m
    );
    for n in &c.notes {
        let _ = writeln!(o, "   note: {n}");
    }
    let _ = writeln!(
        o,
        "   {:>18} {:>9} {:>14} {:>16}",
        "integrator", "rate", "rel error", "wall / sim s"
    );
    for row in &c.rows {
        match (row.relative_error, row.wall_s_per_simulated_s) {
            (Some(e), Some(w)) => {
                let in_plane = row
                    .in_plane_relative_error
                    .map_or(String::new(), |e| format!(" (in-plane alone {e:.3e})"));
                let _ = writeln!(
                    o,
                    "   {:>18} {:>9} {:>14.3e} {:>16} {}{in_plane}",
                    row.integrator,
                    fmt_rate(row.rate_hz),
                    e,
                    fmt_time(w),
                    if row.pareto { "*" } else { "" }
                );
            }
            _ => {
                let _ = writeln!(
                    o,
                    "   {:>18} {:>9} {:>14?}: {}",
                    row.integrator,
                    fmt_rate(row.rate_hz),
                    row.status,
                    row.detail.as_deref().unwrap_or("")
                );
            }
        }
    }

    theory_table(&mut o, &r.theory);
    for n in &r.notes {
        let _ = writeln!(o, "\nnote: {n}");
    }

    // Recommendations.
    let _ = writeln!(
        o,
        "\nRecommended: the cheapest measured setting whose error plus the reference's uncertainty is within the target (≤ claimed error; cost); [default] = the scene's own setting"
    );
    let default_set = match r.mode_count.as_ref().map(|b| &b.default_setting) {
        Some(Some(d)) => fmt_mode_set(d.k_max, d.l_max, d.residual_flexibility),
        Some(None) => "not a rectangular set".into(),
        None => "not studied".into(),
    };
    let _ = writeln!(
        o,
        "   the scene's own settings: plate.radial_splines {}; mode set {}; {} {}",
        r.radial_splines.default_setting.radial_splines,
        default_set,
        r.integrator.default_setting.integrator,
        fmt_rate(r.integrator.default_setting.rate_hz)
    );
    if let Some(b) = &r.mode_count {
        let _ = writeln!(
            o,
            "   mode set: each set competes with and without plate.residual_flexibility (residual reference uncertainty {:.1e}, modal {:.1e}); it decides the deflection under the load, not which vibrations are resolved",
            b.reference.uncertainty_with_residual,
            b.reference.uncertainty
        );
    }
    let _ = writeln!(
        o,
        "   {:>7}  {:<44} {:<64} integrator and rate",
        "target", "plate.radial_splines", "mode set"
    );
    for i in 0..r.plan.targets.len() {
        let a = fmt_rec(
            &r.radial_splines.recommendations[i],
            |s| s.radial_splines.to_string(),
            |c| format!("build {}", fmt_time(c)),
        );
        let b = r.mode_count.as_ref().map_or("—".into(), |b| {
            fmt_rec(
                &b.recommendations[i],
                |s| {
                    format!(
                        "{} ({} modes)",
                        fmt_mode_set(s.k_max, s.l_max, s.residual_flexibility),
                        s.modes
                    )
                },
                |c| format!("{}/step", fmt_time(c)),
            )
        });
        let c = fmt_rec(
            &r.integrator.recommendations[i],
            |s| format!("{} {}", s.integrator, fmt_rate(s.rate_hz)),
            |c| format!("{}/sim s", fmt_time(c)),
        );
        let _ = writeln!(
            o,
            "   {:>7.0e}  {:<44} {:<64} {}",
            r.plan.targets[i], a, b, c
        );
    }
    let _ = writeln!(o, "\n(study wall time {:.1} s)", r.wall_time_s);
    o
}

/// Axis 2's tables.
fn mode_count_table(o: &mut String, b: &study::ResponseAxis) {
    let lc = &b.load_case;
    let _ = writeln!(
        o,
        "\n2. Steady deflection at the load point vs mode set k = 0..k_max, l = 0..l_max"
    );
    let _ = writeln!(
        o,
        "   load point: ALE node {} at ξ = ({}, {}), {} loaded node(s), Ω = {:.4} rad/s, ζ = {}",
        lc.ale_node,
        lc.point.radial,
        lc.point.angular,
        lc.loads.len(),
        lc.speed_rad_s,
        b.damping
    );
    let rf = &b.reference;
    let _ = writeln!(
        o,
        "   reference: k ≤ {}, l ≤ {} ({} modes, {} radial splines): w = {:.9e} m; estimated own error {:.1e} ({})",
        rf.k_max, rf.l_max, rf.modes, rf.radial_splines, rf.response_m, rf.uncertainty, rf.uncertainty_method
    );
    for n in &b.notes {
        let _ = writeln!(o, "   note: {n}");
    }
    let mut ks: Vec<u32> = b.rows.iter().map(|x| x.k_max).collect();
    ks.sort_unstable();
    ks.dedup();
    let mut ls: Vec<u32> = b.rows.iter().map(|x| x.l_max).collect();
    ls.sort_unstable();
    ls.dedup();
    for (title, cell) in [
        (
            "relative error",
            &(|x: &study::response::ResponseRow| format!("{:.2e}{}", x.relative_error, if x.pareto { "*" } else { " " }))
                as &dyn Fn(&study::response::ResponseRow) -> String,
        ),
        (
            "relative error with residual flexibility (docs/residual_flexibility.md; reference plus its own residual)",
            &|x: &study::response::ResponseRow| format!("{:.2e}{}", x.relative_error_with_residual, if x.pareto_with_residual { "*" } else { " " }),
        ),
        ("wall time per step, modes only", &|x: &study::response::ResponseRow| x.step_time_s.map_or("refused".into(), fmt_time)),
        ("wall time per step with residual flexibility", &|x: &study::response::ResponseRow| x.step_time_with_residual_s.map_or("refused".into(), fmt_time)),
        ("modes", &|x: &study::response::ResponseRow| x.modes.to_string()),
    ] {
        let _ = writeln!(o, "   {title}:");
        let mut line = format!("   {:>13}", "l_max \\ k_max");
        for k in &ks {
            let _ = write!(line, " {k:>10}");
        }
        let _ = writeln!(o, "{line}");
        for l in &ls {
            let mut line = format!("   {l:>13}");
            for k in &ks {
                let c = b.rows.iter().find(|x| x.k_max == *k && x.l_max == *l).map(cell).unwrap_or_default();
                let _ = write!(line, " {c:>10}");
            }
            let _ = writeln!(o, "{line}");
        }
    }
}

/// The theory lever: Kirchhoff against converged Mindlin frequencies, with each theory's build time.
fn theory_table(o: &mut String, t: &study::TheoryComparison) {
    let rf = &t.mindlin_reference;
    let _ = writeln!(
        o,
        "\nPlate theory: Kirchhoff against Mindlin (κ = {:.4}), same edges; the scene is {}",
        t.shear_correction, t.scene_theory
    );
    let _ = writeln!(
        o,
        "   error: {}\n   reference: Mindlin, {} splines per field; its difference from {} and {}, {:.1e}, bounds its own error",
        t.error_measure, rf.radial_splines, rf.check_radial_splines[0], rf.check_radial_splines[1], rf.uncertainty
    );
    if let Some(n) = &t.note {
        let _ = writeln!(o, "   note: {n}");
    }
    let _ = writeln!(
        o,
        "   {:>8} {:>14} {:>14} {:>16}",
        "⟨k,l⟩", "Kirchhoff Hz", "Mindlin Hz", "Kirchhoff error"
    );
    for row in &t.rows {
        let _ = writeln!(
            o,
            "   {:>8} {:>14} {:>14.3} {:>16}",
            format!("⟨{},{}⟩", row.mode.k, row.mode.l),
            row.kirchhoff_hz.map_or("—".into(), |f| format!("{f:.3}")),
            row.mindlin_hz,
            row.kirchhoff_error
                .map_or("—".into(), |e| format!("{:+.3}%", 100.0 * e))
        );
    }
    for c in t.kirchhoff.iter().chain(std::iter::once(&t.mindlin)) {
        let _ = writeln!(
            o,
            "   {} ({} radial splines): build {}",
            c.theory,
            c.radial_splines,
            fmt_time(c.build_time_s)
        );
    }
    if let (Some(e), Some(m), Some(ratio)) =
        (t.max_kirchhoff_error, t.worst_mode, t.mindlin_cost_ratio)
    {
        let _ = writeln!(
            o,
            "   Kirchhoff's largest error {:.3}% at ⟨{},{}⟩; Mindlin costs {ratio:.1}× its build time",
            100.0 * e,
            m.k,
            m.l
        );
    }
}

/// The in-plane frequency axis (`study::in_plane_frequency`), after axis 1.
fn in_plane_table(o: &mut String, a: &study::InPlaneFrequencyAxis) {
    let _ = writeln!(
        o,
        "\n1b. In-plane frequencies vs plate.radial_splines (B-splines per field)\n   error: {}\n   reference: {} splines per field; its difference from {}, {:.1e}, bounds its own error",
        a.error_measure,
        a.reference.radial_splines,
        a.reference.check_radial_splines,
        a.reference.uncertainty
    );
    let _ = writeln!(
        o,
        "   {:>14} {:>14} {:>20} {:>14}",
        "radial_splines", "max rel error", "worst ⟨k,l⟩ family", "build time"
    );
    for row in &a.rows {
        let w = row.worst_mode;
        let _ = writeln!(
            o,
            "   {:>14} {:>14.3e} {:>20} {:>14} {}",
            row.radial_splines.to_string(),
            row.max_relative_error,
            format!("⟨{},{}⟩ {}", w.k, w.l, w.family),
            fmt_time(row.build_time_s),
            if row.pareto { "*" } else { "" }
        );
    }
}

/// The in-plane response axis (`study::in_plane_response`), after axis 2,
/// with its recommendations.
fn in_plane_response_table(o: &mut String, a: &study::InPlaneResponseAxis) {
    let (lc, rf) = (&a.load_case, &a.reference);
    let _ = writeln!(
        o,
        "\n2b. In-plane static displacement vs plate.in_plane_orders 0..l_max (k = {:?}), at rest\n   load point: ALE node {} at ξ = ({}, {}), {} in-plane loaded node(s), patch half-width {} m\n   reference: k ≤ {}, l ≤ {} ({} splines per field): (u_r, u_θ) = ({:.9e}, {:.9e}) m; estimated own error {:.1e} ({}); with its residual {:.1e} (static series against {} splines)",
        a.nodal_diameters, lc.ale_node, lc.point.radial, lc.point.angular, lc.loads.len(),
        lc.patch_half_width_m, rf.k_max, rf.l_max, rf.radial_splines, rf.response_m[0],
        rf.response_m[1], rf.uncertainty, rf.uncertainty_method, rf.uncertainty_with_residual,
        rf.check_radial_splines
    );
    for n in &a.notes {
        let _ = writeln!(o, "   note: {n}");
    }
    let _ = writeln!(
        o,
        "   {:>6} {:>6} {:>14} {:>14} {:>16} {:>16}",
        "l_max", "modes", "rel error", "with residual", "step", "step w/ residual"
    );
    let time = |t: Option<f64>| t.map_or("refused".into(), fmt_time);
    for x in &a.rows {
        let mark = |p: bool| if p { "*" } else { " " };
        let _ = writeln!(
            o,
            "   {:>6} {:>6} {:>13.2e}{} {:>13.2e}{} {:>16} {:>16}",
            x.l_max,
            x.modes,
            x.relative_error,
            mark(x.pareto),
            x.relative_error_with_residual,
            mark(x.pareto_with_residual),
            time(x.step_time_s),
            time(x.step_time_with_residual_s)
        );
    }
    for rec in &a.recommendations {
        let line = fmt_rec(
            rec,
            |s| {
                format!(
                    "l ≤ {} ({} modes), residual flexibility {}",
                    s.l_max, s.modes, s.residual_flexibility
                )
            },
            |c| format!("{}/step", fmt_time(c)),
        );
        let _ = writeln!(o, "   target {:>7.0e}: {line}", rec.target);
    }
}
