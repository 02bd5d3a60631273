//! The study's accuracy-against-cost picture (Pareto fronts).

use super::render::*;
use super::Size;
use crate::cli::error::CliResult;
use crate::study::StudyReport;
use plotters::coord::Shift;
use plotters::element::DashedPathElement;
use plotters::prelude::*;
use std::path::Path;

// ---------------------------------------------------------------- study picture

/// The study's error-vs-cost picture: one log–log panel per axis, the Pareto
/// front, the targets and the recommended settings ringed.
pub fn pareto(report: &StudyReport, out: &Path, size: Size) -> CliResult<()> {
    render(out, size, &ParetoPicture { report })
}

pub(super) struct ParetoPicture<'a> {
    report: &'a StudyReport,
}

/// One panel's data.
pub(super) struct Series {
    name: String,
    color: RGBColor,
    /// (cost, error, label)
    points: Vec<(f64, f64, String)>,
}

pub(super) struct PanelData {
    title: String,
    x_desc: String,
    series: Vec<Series>,
    /// (cost, error) of the front.
    front: Vec<(f64, f64)>,
    /// (target, cost, error, label) of recommendations.
    picks: Vec<(f64, f64, f64, String)>,
    uncertainty: f64,
}

/// Errors below this are drawn at it, hollow (exact to round-off; a log axis has no 0).
pub(super) const ERROR_FLOOR: f64 = 1e-16;

pub(super) fn panels(r: &StudyReport) -> [PanelData; 3] {
    let floor = |e: f64| e.max(ERROR_FLOOR);
    let a = &r.radial_splines;
    let pa = PanelData {
        title: "1. frequencies vs plate.radial_splines".into(),
        x_desc: "model build time (s)".into(),
        series: vec![Series {
            name: "max frequency error".into(),
            color: PALETTE[0],
            points: a
                .rows
                .iter()
                .map(|x| {
                    (
                        x.build_time_s,
                        floor(x.max_relative_error),
                        format!("{}", x.radial_splines),
                    )
                })
                .collect(),
        }],
        front: a
            .rows
            .iter()
            .filter(|x| x.pareto)
            .map(|x| (x.build_time_s, floor(x.max_relative_error)))
            .collect(),
        picks: a
            .recommendations
            .iter()
            .filter_map(|x| {
                Some((
                    x.target,
                    x.cost?,
                    floor(x.error?),
                    format!("n = {}", x.setting.as_ref()?.radial_splines),
                ))
            })
            .collect(),
        uncertainty: a.reference.uncertainty,
    };
    let pb = match &r.mode_count {
        Some(b) => response_panel(b),
        None => theory_panel(&r.theory),
    };
    let c = &r.integrator;
    let mut names: Vec<&str> = c.rows.iter().map(|x| x.integrator).collect();
    names.dedup();
    let short = |n: &str| match n {
        "exponential" => "exp".to_string(),
        "implicit_midpoint" => "midpoint".to_string(),
        other => other.to_string(),
    };
    let khz = |hz: f64| {
        if hz >= 1e3 {
            format!("{} kHz", hz / 1e3)
        } else {
            format!("{hz} Hz")
        }
    };
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
                    .filter_map(|x| {
                        Some((
                            x.wall_s_per_simulated_s?,
                            floor(x.relative_error?),
                            khz(x.rate_hz),
                        ))
                    })
                    .collect(),
            })
            .collect(),
        front: c
            .rows
            .iter()
            .filter(|x| x.pareto)
            .filter_map(|x| Some((x.wall_s_per_simulated_s?, floor(x.relative_error?))))
            .collect(),
        picks: c
            .recommendations
            .iter()
            .filter_map(|x| {
                let s = x.setting.as_ref()?;
                Some((
                    x.target,
                    x.cost?,
                    floor(x.error?),
                    format!("{} {}", short(s.integrator), khz(s.rate_hz)),
                ))
            })
            .collect(),
        uncertainty: c.reference.uncertainty,
    };
    [pa, pb, pc]
}

pub(super) fn decade_range(values: impl Iterator<Item = f64>) -> (f64, f64) {
    let (lo, hi) = values
        .filter(|v| v.is_finite() && *v > 0.0)
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| {
            (a.min(v), b.max(v))
        });
    if !lo.is_finite() {
        return (1e-3, 1.0);
    }
    (
        10f64.powf(lo.log10().floor()),
        10f64.powf(hi.log10().ceil().max(lo.log10().floor() + 1.0)),
    )
}

impl Painter for ParetoPicture<'_> {
    type Out = ();
    fn paint<DB: DrawingBackend>(
        &self,
        root: &DrawingArea<DB, Shift>,
        _format: Format,
    ) -> CliResult<()> {
        let r = self.report;
        let (top, rest) = root.split_vertically(44);
        draw_title(
            &top,
            &format!(
                "Error against cost — {} ({} modes); targets dashed, recommended settings ringed, Pareto front black; hollow: error below {ERROR_FLOOR:e}, drawn at it",
                r.scene.source, r.scene.modes
            ),
            20.0,
        )?;
        let areas = rest.split_evenly((1, 3));
        for (area, panel) in areas.iter().zip(panels(r)) {
            let xs = decade_range(
                panel
                    .series
                    .iter()
                    .flat_map(|s| s.points.iter().map(|p| p.0)),
            );
            let mut y_all: Vec<f64> = panel
                .series
                .iter()
                .flat_map(|s| s.points.iter().map(|p| p.1))
                .collect();
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
                    .legend(|(x, y)| {
                        PathElement::new(
                            vec![(x, y), (x + 20, y)],
                            RGBColor(200, 120, 0).stroke_width(2),
                        )
                    });
            }
            for s in &panel.series {
                let color = s.color;
                let mut pts: Vec<(f64, f64)> = s.points.iter().map(|p| (p.0, p.1)).collect();
                pts.sort_by(|a, b| a.0.total_cmp(&b.0));
                chart
                    .draw_series(LineSeries::new(pts.clone(), color.mix(0.5).stroke_width(1)))
                    .map_err(de)?;
                chart
                    // An error below the floor is not on the axis: drawn at the floor, hollow.
                    .draw_series(pts.iter().map(|&p| {
                        Circle::new(
                            p,
                            4,
                            if p.1 <= ERROR_FLOOR {
                                color.stroke_width(2)
                            } else {
                                color.filled()
                            },
                        )
                    }))
                    .map_err(de)?
                    .label(s.name.as_str())
                    .legend(move |(x, y)| Circle::new((x + 10, y), 4, color.filled()));
                if panel.series.len() == 1 {
                    for p in &s.points {
                        let (px, py) = chart.backend_coord(&(p.0, p.1));
                        root.draw(&Text::new(
                            p.2.clone(),
                            (px - 6, py + 8),
                            (FONT, 13).into_font(),
                        ))
                        .map_err(de)?;
                    }
                }
            }
            let mut front = panel.front.clone();
            front.sort_by(|a, b| a.0.total_cmp(&b.0));
            chart
                .draw_series(LineSeries::new(front, BLACK.stroke_width(2)))
                .map_err(de)?
                .label("Pareto front")
                .legend(|(x, y)| {
                    PathElement::new(vec![(x, y), (x + 20, y)], BLACK.stroke_width(2))
                });
            // Recommended settings: one ring per setting, its targets listed.
            let mut merged: Vec<(f64, f64, String, Vec<f64>)> = Vec::new();
            for (target, cost, err, label) in &panel.picks {
                match merged.iter_mut().find(|m| m.2 == *label) {
                    Some(m) => m.3.push(*target),
                    None => merged.push((*cost, *err, label.clone(), vec![*target])),
                }
            }
            for (cost, err, label, targets) in &merged {
                chart
                    .draw_series(std::iter::once(Circle::new(
                        (*cost, *err),
                        9,
                        RGBColor(220, 0, 0).stroke_width(2),
                    )))
                    .map_err(de)?;
                let list: Vec<String> = targets.iter().map(|t| log_tick(*t)).collect();
                let text = if list.len() > 2 {
                    format!("{label}: ≤ {} … {}", list[0], list[list.len() - 1])
                } else {
                    format!("{label}: ≤ {}", list.join(", "))
                };
                let style = TextStyle::from((FONT, 13).into_font()).color(&RGBColor(180, 0, 0));
                let (px, py) = chart.backend_coord(&(*cost, *err));
                root.draw(&Text::new(text, (px + 11, py - 20), style))
                    .map_err(de)?;
            }
            // The legend goes into the emptiest corner.
            let (px_x, px_y) = chart.plotting_area().get_pixel_range();
            let mid = ((px_x.start + px_x.end) / 2, (px_y.start + px_y.end) / 2);
            let mut counts = [0usize; 4]; // UL, UR, LL, LR
            let quadrant =
                |(x, y): (i32, i32)| (usize::from(y > mid.1) << 1) | usize::from(x > mid.0);
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
            let corners = [
                SeriesLabelPosition::UpperLeft,
                SeriesLabelPosition::UpperRight,
                SeriesLabelPosition::LowerLeft,
                SeriesLabelPosition::LowerRight,
            ];
            let best = [2usize, 3, 1, 0]
                .into_iter()
                .min_by_key(|&i| counts[i])
                .unwrap_or(2);
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

/// Axis 2's panel: the load-point response against the mode set.
fn response_panel(b: &crate::study::ResponseAxis) -> PanelData {
    let floor = |e: f64| e.max(ERROR_FLOOR);
    let mut ls: Vec<u32> = b.rows.iter().map(|x| x.l_max).collect();
    ls.sort_unstable();
    ls.dedup();
    PanelData {
        title: "2. load-point response vs mode set".into(),
        x_desc: "wall time per step (s)".into(),
        series: ls
            .iter()
            .enumerate()
            .map(|(i, &l)| Series {
                name: format!("l ≤ {l}"),
                color: PALETTE[i % PALETTE.len()],
                points: b
                    .rows
                    .iter()
                    .filter(|x| x.l_max == l)
                    .filter_map(|x| {
                        Some((
                            x.step_time_s?,
                            floor(x.relative_error),
                            format!("k ≤ {}", x.k_max),
                        ))
                    })
                    .collect(),
            })
            .chain(ls.iter().enumerate().map(|(i, &l)| {
                Series {
                    name: format!("l ≤ {l} + residual"),
                    color: PALETTE[(i + ls.len()) % PALETTE.len()],
                    points: b
                        .rows
                        .iter()
                        .filter(|x| x.l_max == l)
                        .filter_map(|x| {
                            Some((
                                x.step_time_with_residual_s?,
                                floor(x.relative_error_with_residual),
                                format!("k ≤ {}", x.k_max),
                            ))
                        })
                        .collect(),
                }
            }))
            .collect(),
        // One front over both variants of every set.
        front: b
            .rows
            .iter()
            .filter(|x| x.pareto)
            .filter_map(|x| Some((x.step_time_s?, floor(x.relative_error))))
            .chain(
                b.rows
                    .iter()
                    .filter(|x| x.pareto_with_residual)
                    .filter_map(|x| {
                        Some((
                            x.step_time_with_residual_s?,
                            floor(x.relative_error_with_residual),
                        ))
                    }),
            )
            .collect(),
        picks: b
            .recommendations
            .iter()
            .filter_map(|x| {
                let s = x.setting.as_ref()?;
                let residual = if s.residual_flexibility {
                    " + res."
                } else {
                    ""
                };
                Some((
                    x.target,
                    x.cost?,
                    floor(x.error?),
                    format!("k≤{}, l≤{}{residual}", s.k_max, s.l_max),
                ))
            })
            .collect(),
        uncertainty: b
            .reference
            .uncertainty_with_residual
            .min(b.reference.uncertainty),
    }
}

/// Under Mindlin theory (axis 2 skipped) the second panel is the theory
/// lever: Kirchhoff's largest frequency error against its build time, and
/// Mindlin's (its reference uncertainty) against its own.
fn theory_panel(t: &crate::study::TheoryComparison) -> PanelData {
    let floor = |e: f64| e.max(ERROR_FLOOR);
    let mut points = vec![(
        t.mindlin.build_time_s,
        floor(t.mindlin_reference.uncertainty),
        "mindlin".to_string(),
    )];
    if let (Some(k), Some(e)) = (&t.kirchhoff, t.max_kirchhoff_error) {
        points.push((k.build_time_s, floor(e), "kirchhoff".to_string()));
    }
    PanelData {
        title: "2. plate theory (mode set skipped under Mindlin)".into(),
        x_desc: "model build time (s)".into(),
        front: {
            let xy: Vec<(f64, f64)> = points.iter().map(|p| (p.1, p.0)).collect();
            crate::study::mark_pareto(&xy)
                .into_iter()
                .zip(&points)
                .filter(|(on, _)| *on)
                .map(|(_, p)| (p.0, p.1))
                .collect()
        },
        series: vec![Series {
            name: "max frequency error vs Mindlin".into(),
            color: PALETTE[0],
            points,
        }],
        picks: vec![],
        uncertainty: t.mindlin_reference.uncertainty,
    }
}
