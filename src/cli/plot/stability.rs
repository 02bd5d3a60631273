//! The squeal stability map (`annular_plate stability --plot`): the grid of
//! speed × friction coefficient as cells coloured by the largest growth rate
//! (red: growing, blue: decaying; the shade grows with |rate| relative to the
//! largest of its sign) and the threshold μ_c(Ω) as a black curve with dots.
//! A threshold outside the plotted μ range is not drawn on the axis as if it
//! were there: it is an arrow at the edge it lies beyond, labelled with the
//! bound, and the curve is broken there. Unstable already at the first μ,
//! the threshold is at or below it ("≤ 0.2"); stable over the whole range,
//! above the last ("> 0.6").

use super::render::*;
use super::Size;
use crate::cli::error::CliResult;
use plotters::coord::Shift;
use plotters::prelude::*;
use std::path::Path;

/// The map's data as the picture needs it: `growth_rate[s][m]`.
pub struct StabilityGrid<'a> {
    /// The speeds, rad/s.
    pub speeds: &'a [f64],
    /// The friction coefficients μ.
    pub mu: &'a [f64],
    /// Largest real part of the eigenvalues per speed and μ, 1/s.
    pub growth_rate: &'a [Vec<f64>],
    /// Per speed, the smallest unstable μ of the range (None: stable
    /// throughout).
    pub threshold_mu: &'a [Option<f64>],
}

/// Where each cell's centre was drawn and whether it is unstable: (pixel x, pixel y, growing).
#[derive(Debug, Clone, PartialEq)]
pub struct StabilityGeometry {
    /// Per cell: (pixel x, pixel y, unstable).
    pub cells: Vec<(i32, i32, bool)>,
    /// One entry per speed with a threshold: where it was drawn and how.
    pub thresholds: Vec<ThresholdMark>,
}

/// Where a threshold lies against the plotted μ range.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Placement {
    /// Inside the range: a dot.
    Within,
    /// Below the range, or at or below its first μ (unstable there already):
    /// an arrow pointing down at the lower edge, labelled "≤ μ_first" / "< edge".
    Below,
    /// Above the range (stable over all of it): an arrow pointing up at the
    /// upper edge, labelled "> μ_last".
    Above,
}

/// How one speed's threshold μ was drawn.
#[derive(Debug, Clone, PartialEq)]
pub struct ThresholdMark {
    /// The speed, rad/s.
    pub speed: f64,
    /// The map's threshold (∞: stable over the range).
    pub mu: f64,
    /// Where it lies against the range.
    pub placement: Placement,
    /// Pixel of the dot (within) or of the arrow's tip (at the edge).
    pub pixel: (i32, i32),
    /// The edge label ("< 0.2"), for a threshold outside the range.
    pub label: Option<String>,
}

/// Where `t` lies against [lo, hi].
pub fn placement(t: f64, lo: f64, hi: f64) -> Placement {
    if t < lo {
        Placement::Below
    } else if t > hi {
        Placement::Above
    } else {
        Placement::Within
    }
}

/// Draw the map (growth rate over speed and μ, thresholds marked) to `out`.
pub fn stability_map(grid: &StabilityGrid, out: &Path, size: Size) -> CliResult<StabilityGeometry> {
    render(out, size, &MapPicture { grid })
}

struct MapPicture<'a, 'b> {
    grid: &'a StabilityGrid<'b>,
}

/// Cell edges around grid values (midpoints; half a spacing, or ±1/2 for a single value, outside).
fn edges(v: &[f64]) -> Vec<f64> {
    if v.len() == 1 {
        let h = if v[0] == 0.0 { 0.5 } else { 0.5 * v[0].abs() };
        return vec![v[0] - h, v[0] + h];
    }
    let mut e = vec![v[0] - 0.5 * (v[1] - v[0])];
    e.extend(v.windows(2).map(|w| 0.5 * (w[0] + w[1])));
    e.push(v[v.len() - 1] + 0.5 * (v[v.len() - 1] - v[v.len() - 2]));
    e
}

impl Painter for MapPicture<'_, '_> {
    type Out = StabilityGeometry;
    fn paint<DB: DrawingBackend>(
        &self,
        root: &DrawingArea<DB, Shift>,
        _format: Format,
    ) -> CliResult<StabilityGeometry> {
        let g = self.grid;
        let (top, rest) = root.split_vertically(44);
        draw_title(
            &top,
            "Squeal stability map — max Re λ: red growing, blue decaying; black: threshold μ_c(Ω)",
            20.0,
        )?;
        let (xe, ye) = (edges(g.speeds), edges(g.mu));
        let (x0, x1, y0, y1) = (xe[0], xe[xe.len() - 1], ye[0], ye[ye.len() - 1]);
        let mut chart = ChartBuilder::on(&rest)
            .margin(16)
            .x_label_area_size(50)
            .y_label_area_size(80)
            .build_cartesian_2d(x0..x1, y0..y1)
            .map_err(de)?;
        chart
            .configure_mesh()
            .disable_mesh()
            .x_desc("spin speed Ω (rad/s)")
            .y_desc("friction coefficient μ")
            .x_label_formatter(&|v| tick(*v, x1 - x0))
            .y_label_formatter(&|v| tick(*v, y1 - y0))
            .label_style((FONT, 14))
            .axis_desc_style((FONT, 16))
            .draw()
            .map_err(de)?;
        let rates = g.growth_rate.iter().flatten();
        let max_pos = rates
            .clone()
            .filter(|r| **r > 0.0)
            .fold(0.0f64, |a, &r| a.max(r));
        let max_neg = rates.filter(|r| **r <= 0.0).fold(0.0f64, |a, &r| a.max(-r));
        let mut cells = Vec::new();
        for (s, row) in g.growth_rate.iter().enumerate() {
            for (m, &rate) in row.iter().enumerate() {
                let growing = rate > 0.0;
                let t = if growing {
                    rate / max_pos
                } else if max_neg > 0.0 {
                    -rate / max_neg
                } else {
                    0.0
                };
                let shade = (255.0 * (0.7 - 0.55 * t.clamp(0.0, 1.0))) as u8;
                let color = if growing {
                    RGBColor(230, shade, shade)
                } else {
                    RGBColor(shade, shade, 230)
                };
                chart
                    .draw_series(std::iter::once(Rectangle::new(
                        [(xe[s], ye[m]), (xe[s + 1], ye[m + 1])],
                        color.filled(),
                    )))
                    .map_err(de)?;
                let (px, py) = chart.backend_coord(&(g.speeds[s], g.mu[m]));
                cells.push((px, py, growing));
            }
        }
        // The threshold: dots joined where consecutive speeds are within the
        // range; beyond it an arrow at the edge with the bound it passes.
        let mut thresholds = Vec::new();
        let mut runs: Vec<Vec<(f64, f64)>> = vec![Vec::new()];
        let label_style = TextStyle::from((FONT, 14).into_font()).color(&BLACK);
        let (mu_first, mu_last) = (g.mu[0], g.mu[g.mu.len() - 1]);
        for (i, (&s, t)) in g.speeds.iter().zip(g.threshold_mu).enumerate() {
            let unstable_at_first = g
                .growth_rate
                .get(i)
                .and_then(|r| r.first())
                .is_some_and(|&r| r > 0.0);
            // Where the threshold lies and the bound to write at the edge:
            // unstable already at the first μ, it is at or below that μ (the
            // map does not know where); stable over the range, above the last.
            let (place, bound) = match *t {
                None if unstable_at_first => continue,
                None => (Placement::Above, format!("> {mu_last}")),
                Some(t) if unstable_at_first && t <= mu_first => {
                    (Placement::Below, format!("≤ {mu_first}"))
                }
                Some(t) => match placement(t, y0, y1) {
                    Placement::Within => (Placement::Within, String::new()),
                    Placement::Below => (Placement::Below, format!("< {}", tick(y0, y1 - y0))),
                    Placement::Above => (Placement::Above, format!("> {}", tick(y1, y1 - y0))),
                },
            };
            let mu = t.unwrap_or(f64::INFINITY);
            if place == Placement::Within {
                runs.last_mut().expect("one run at least").push((s, mu));
                chart
                    .draw_series(std::iter::once(Circle::new((s, mu), 4, BLACK.filled())))
                    .map_err(de)?;
                thresholds.push(ThresholdMark {
                    speed: s,
                    mu,
                    placement: place,
                    pixel: chart.backend_coord(&(s, mu)),
                    label: None,
                });
                continue;
            }
            runs.push(Vec::new());
            let below = place == Placement::Below;
            let edge = if below { y0 } else { y1 };
            // The tip on the edge, the body inside the plot.
            let tip = chart.backend_coord(&(s, edge));
            let dir = if below { -1 } else { 1 };
            // (pixel y grows downwards: the body of a downward arrow is above its tip)
            let base = tip.1 + dir * 14;
            root.draw(&Polygon::new(
                vec![tip, (tip.0 - 7, base), (tip.0 + 7, base)],
                BLACK.filled(),
            ))
            .map_err(de)?;
            root.draw(&PathElement::new(
                vec![(tip.0, base), (tip.0, base + dir * 12)],
                BLACK.stroke_width(2),
            ))
            .map_err(de)?;
            root.draw(&Text::new(
                bound.clone(),
                (tip.0 + 9, base + dir * 6 - 7),
                label_style.clone(),
            ))
            .map_err(de)?;
            thresholds.push(ThresholdMark {
                speed: s,
                mu,
                placement: place,
                pixel: tip,
                label: Some(bound),
            });
        }
        for run in runs.into_iter().filter(|r| r.len() > 1) {
            chart
                .draw_series(LineSeries::new(run, BLACK.stroke_width(2)))
                .map_err(de)?;
        }
        Ok(StabilityGeometry { cells, thresholds })
    }
}
