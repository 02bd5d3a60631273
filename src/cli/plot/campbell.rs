//! The Campbell diagram (`annular_plate campbell --plot`): per ⟨k, l⟩ the
//! rotating-frame frequency (thick), the space-fixed forward and backward
//! frequencies f ± kΩ/2π (thin; the backward one as |f − kΩ/2π|, so it
//! touches zero at the critical speed), the speed lines kΩ/2π (grey, dashed)
//! and the critical speeds marked where the rotating frequency meets its
//! speed line (black dots, labelled). With in-plane modes
//! (`plate.in_plane_nodal_diameters`) each in-plane wave ⟨k, order⟩ adds its
//! turning-frame forward and backward frequencies (dashed, medium) and the
//! space-fixed ones (dashed, thin; the backward one as |ω − kΩ|/2π), and each
//! in-plane critical speed, where the backward wave meets its speed line,
//! a hollow black ring.

use super::render::*;
use super::Size;
use crate::cli::error::CliResult;
use crate::model::campbell::CampbellDiagram;
use plotters::coord::Shift;
use plotters::element::DashedPathElement;
use plotters::prelude::*;
use std::f64::consts::TAU;
use std::path::Path;

/// Where the picture put each critical-speed marker: (k, l, pixel x, pixel y).
#[derive(Debug, Clone, PartialEq)]
pub struct CampbellGeometry {
    /// One per critical speed: (k, l, pixel x, pixel y).
    pub markers: Vec<(u32, u32, i32, i32)>,
    /// One per in-plane critical speed: (k, order, pixel x, pixel y).
    pub in_plane_markers: Vec<(u32, u32, i32, i32)>,
}

/// Draw `diagram` to `out` (.png or .svg).
pub fn campbell(
    diagram: &CampbellDiagram,
    stiffening: bool,
    out: &Path,
    size: Size,
) -> CliResult<CampbellGeometry> {
    render(
        out,
        size,
        &CampbellPicture {
            diagram,
            stiffening,
        },
    )
}

struct CampbellPicture<'a> {
    diagram: &'a CampbellDiagram,
    stiffening: bool,
}

/// Marker radius, px.
pub const CRITICAL_MARKER_RADIUS: i32 = 6;

impl Painter for CampbellPicture<'_> {
    type Out = CampbellGeometry;
    fn paint<DB: DrawingBackend>(
        &self,
        root: &DrawingArea<DB, Shift>,
        _format: Format,
    ) -> CliResult<CampbellGeometry> {
        let d = self.diagram;
        let (top, rest) = root.split_vertically(44);
        let mut title = format!(
            "Campbell diagram — centrifugal stiffening {}; thick: rotating frame, thin: forward/backward, dashed: kΩ/2π, dots: critical speeds",
            if self.stiffening { "on" } else { "off" }
        );
        if !d.in_plane.is_empty() {
            title.push_str("; in-plane waves long-dashed, rings: their critical speeds");
        }
        draw_title(&top, &title, 20.0)?;
        let s = &d.speeds_rad_s;
        let (x0, x1) = (
            s.first().copied().unwrap_or(0.0),
            s.last().copied().unwrap_or(1.0),
        );
        let (x0, x1) = if x1 > x0 {
            (x0, x1)
        } else {
            (x0 - 1.0, x0 + 1.0)
        };
        let in_plane = d.in_plane.iter().flat_map(|w| {
            w.rotating_forward_hz
                .iter()
                .chain(&w.rotating_backward_hz)
                .chain(&w.forward_hz)
                .chain(&w.backward_hz)
        });
        let y_max = d
            .modes
            .iter()
            .flat_map(|m| {
                m.rotating_hz
                    .iter()
                    .chain(&m.forward_hz)
                    .chain(&m.backward_hz)
            })
            .chain(in_plane)
            .map(|v| v.abs())
            .fold(0.0, f64::max)
            .max(1e-9)
            * 1.05;
        let mut chart = ChartBuilder::on(&rest)
            .margin(16)
            .x_label_area_size(50)
            .y_label_area_size(80)
            .build_cartesian_2d(x0..x1, 0.0..y_max)
            .map_err(de)?;
        chart
            .configure_mesh()
            .x_desc("spin speed Ω (rad/s)")
            .y_desc("frequency (Hz)")
            .x_label_formatter(&|v| tick(*v, x1 - x0))
            .y_label_formatter(&|v| tick(*v, y_max))
            .label_style((FONT, 14))
            .axis_desc_style((FONT, 16))
            .light_line_style(RGBColor(240, 240, 240))
            .bold_line_style(RGBColor(220, 220, 220))
            .draw()
            .map_err(de)?;
        let in_plane_ks = d.in_plane.iter().map(|w| w.k);
        let mut ks: Vec<u32> = d
            .modes
            .iter()
            .map(|m| m.k)
            .chain(in_plane_ks)
            .filter(|&k| k > 0)
            .collect();
        ks.sort_unstable();
        ks.dedup();
        for &k in &ks {
            let line = vec![(x0, k as f64 * x0 / TAU), (x1, k as f64 * x1 / TAU)];
            chart
                .draw_series(std::iter::once(DashedPathElement::new(
                    line,
                    6,
                    5,
                    RGBColor(150, 150, 150).stroke_width(1),
                )))
                .map_err(de)?;
        }
        for (i, m) in d.modes.iter().enumerate() {
            let color = PALETTE[i % PALETTE.len()];
            let pts = |v: &[f64], abs: bool| -> Vec<(f64, f64)> {
                s.iter()
                    .zip(v)
                    .map(|(&x, &y)| (x, if abs { y.abs() } else { y }))
                    .collect()
            };
            chart
                .draw_series(LineSeries::new(
                    pts(&m.rotating_hz, false),
                    color.stroke_width(3),
                ))
                .map_err(de)?
                .label(format!("⟨{}, {}⟩", m.k, m.l))
                .legend(move |(x, y)| {
                    PathElement::new(vec![(x, y), (x + 20, y)], color.stroke_width(3))
                });
            if m.k > 0 {
                chart
                    .draw_series(LineSeries::new(
                        pts(&m.forward_hz, false),
                        color.mix(0.6).stroke_width(1),
                    ))
                    .map_err(de)?;
                chart
                    .draw_series(LineSeries::new(
                        pts(&m.backward_hz, true),
                        color.mix(0.6).stroke_width(1),
                    ))
                    .map_err(de)?;
            }
        }
        for (i, w) in d.in_plane.iter().enumerate() {
            let color = PALETTE[(d.modes.len() + i) % PALETTE.len()];
            let curves = [
                (&w.rotating_forward_hz, 2),
                (&w.rotating_backward_hz, 2),
                (&w.forward_hz, 1),
                (&w.backward_hz, 1),
            ];
            for (j, (v, width)) in curves.into_iter().enumerate() {
                let pts: Vec<(f64, f64)> = s.iter().zip(v).map(|(&x, &y)| (x, y.abs())).collect();
                let series = chart
                    .draw_series(std::iter::once(DashedPathElement::new(
                        pts,
                        10,
                        4,
                        color.stroke_width(width),
                    )))
                    .map_err(de)?;
                if j == 0 {
                    series
                        .label(format!("in-plane ⟨{}, {}⟩", w.k, w.order))
                        .legend(move |(x, y)| {
                            DashedPathElement::new(
                                vec![(x, y), (x + 20, y)],
                                6,
                                3,
                                color.stroke_width(2),
                            )
                        });
                }
            }
        }
        // A marker on the speed line kΩ/2π at the critical speed, labelled.
        let mut mark = |k: u32, rad_s: f64, style: ShapeStyle| -> CliResult<(i32, i32)> {
            let p = (rad_s, k as f64 * rad_s / TAU);
            chart
                .draw_series(std::iter::once(Circle::new(
                    p,
                    CRITICAL_MARKER_RADIUS,
                    style,
                )))
                .map_err(de)?;
            let (px, py) = chart.backend_coord(&p);
            root.draw(&Text::new(
                format!("{rad_s:.0} rad/s"),
                (px + 8, py + 4),
                (FONT, 13).into_font(),
            ))
            .map_err(de)?;
            Ok((px, py))
        };
        let in_range = |rad_s: f64| rad_s >= x0 && rad_s <= x1;
        let mut markers = Vec::new();
        for c in d.critical_speeds.iter().filter(|c| in_range(c.rad_s)) {
            let (px, py) = mark(c.k, c.rad_s, BLACK.filled())?;
            markers.push((c.k, c.l, px, py));
        }
        let mut in_plane_markers = Vec::new();
        for c in d
            .in_plane_critical_speeds
            .iter()
            .filter(|c| in_range(c.rad_s))
        {
            let (px, py) = mark(c.k, c.rad_s, BLACK.stroke_width(3))?;
            in_plane_markers.push((c.k, c.order, px, py));
        }
        chart
            .configure_series_labels()
            .position(SeriesLabelPosition::UpperLeft)
            .background_style(WHITE.mix(0.85))
            .border_style(RGBColor(160, 160, 160))
            .label_font((FONT, 13))
            .draw()
            .map_err(de)?;
        Ok(CampbellGeometry {
            markers,
            in_plane_markers,
        })
    }
}
