//! The squeal stability map (`annular_plate stability --plot`): the grid of
//! speed × friction coefficient as cells coloured by the largest growth rate
//! (red: growing, blue: decaying; the shade grows with |rate| relative to the
//! largest of its sign) and the threshold μ_c(Ω) as a black curve with dots.

use super::render::*;
use super::Size;
use crate::cli::error::CliResult;
use plotters::coord::Shift;
use plotters::prelude::*;
use std::path::Path;

/// The map's data as the picture needs it: `growth_rate[s][m]`.
pub struct StabilityGrid<'a> {
    pub speeds: &'a [f64],
    pub mu: &'a [f64],
    pub growth_rate: &'a [Vec<f64>],
    pub threshold_mu: &'a [Option<f64>],
}

/// Where each cell's centre was drawn and whether it is unstable: (pixel x, pixel y, growing).
#[derive(Debug, Clone, PartialEq)]
pub struct StabilityGeometry {
    pub cells: Vec<(i32, i32, bool)>,
}

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
    fn paint<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>, _format: Format) -> CliResult<StabilityGeometry> {
        let g = self.grid;
        let (top, rest) = root.split_vertically(44);
        draw_title(&top, "Squeal stability map — max Re λ: red growing, blue decaying; black: threshold μ_c(Ω)", 20.0)?;
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
        let max_pos = rates.clone().filter(|r| **r > 0.0).fold(0.0f64, |a, &r| a.max(r));
        let max_neg = rates.filter(|r| **r <= 0.0).fold(0.0f64, |a, &r| a.max(-r));
        let mut cells = Vec::new();
        for (s, row) in g.growth_rate.iter().enumerate() {
            for (m, &rate) in row.iter().enumerate() {
                let growing = rate > 0.0;
                let t = if growing { rate / max_pos } else if max_neg > 0.0 { -rate / max_neg } else { 0.0 };
                let shade = (255.0 * (0.7 - 0.55 * t.clamp(0.0, 1.0))) as u8;
                let color = if growing { RGBColor(230, shade, shade) } else { RGBColor(shade, shade, 230) };
                chart.draw_series(std::iter::once(Rectangle::new([(xe[s], ye[m]), (xe[s + 1], ye[m + 1])], color.filled()))).map_err(de)?;
                let (px, py) = chart.backend_coord(&(g.speeds[s], g.mu[m]));
                cells.push((px, py, growing));
            }
        }
        let curve: Vec<(f64, f64)> = g.speeds.iter().zip(g.threshold_mu).filter_map(|(&s, t)| t.map(|t| (s, t))).collect();
        chart.draw_series(LineSeries::new(curve.clone(), BLACK.stroke_width(2))).map_err(de)?;
        chart.draw_series(curve.iter().map(|&p| Circle::new(p, 4, BLACK.filled()))).map_err(de)?;
        Ok(StabilityGeometry { cells })
    }
}
