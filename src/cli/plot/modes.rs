//! Mode pictures: the grid of top views with nodal lines, one mode in 3-D.

use super::render::*;
use super::Size;
use crate::cli::error::{CliError, CliResult};
use crate::config::{Config, PlateTheory};
use crate::model::nodal_lines::{nodal_angles, nodal_radii};
use crate::model::{AngularShape, PlateModel};
use plotters::coord::Shift;
use plotters::prelude::*;
use std::f64::consts::TAU;
use std::path::Path;

// ---------------------------------------------------------------- mode shapes

/// Diverging colour for w/max|w| ∈ [−1, 1]: blue below zero, white at zero, red above.
pub(crate) fn diverging(t: f64) -> RGBColor {
    let t = t.clamp(-1.0, 1.0);
    let (end, s) = if t >= 0.0 {
        ((178.0, 24.0, 43.0), t)
    } else {
        ((33.0, 102.0, 172.0), -t)
    };
    let s = s.powf(0.75);
    let mix = |e: f64| (255.0 + (e - 255.0) * s).round() as u8;
    RGBColor(mix(end.0), mix(end.1), mix(end.2))
}

/// Where one top view of a mode was drawn.
#[derive(Debug, Clone, PartialEq)]
pub struct TopView {
    /// Nodal diameters k.
    pub k: u32,
    /// Nodal circles l.
    pub l: u32,
    /// Index into the model's modes (of the model that drew it), None if ⟨k, l⟩ is a rigid-body motion.
    pub mode: Option<usize>,
    /// cos or sin (None for k = 0).
    pub shape: Option<AngularShape>,
    /// Disc centre, pixels.
    pub center: (i32, i32),
    /// Pixels per metre.
    pub scale: f64,
    /// r_i, m.
    pub inner_radius: f64,
    /// r_a, m.
    pub outer_radius: f64,
    /// Radii of the nodal circles, m.
    pub nodal_radii: Vec<f64>,
    /// Angles of the nodal half-diameters, rad.
    pub nodal_angles: Vec<f64>,
}

impl TopView {
    /// Pixel of the plate point (r, φ) (φ counter-clockwise from +x, y up).
    pub fn to_px(&self, r: f64, phi: f64) -> (f64, f64) {
        (
            self.center.0 as f64 + r * phi.cos() * self.scale,
            self.center.1 as f64 - r * phi.sin() * self.scale,
        )
    }
}

pub(super) const EDGE: RGBColor = RGBColor(90, 90, 90);

/// Draw mode `mode` of `model` seen from above, centred at `center`, `scale` pixels per metre.
pub(super) fn draw_top_view<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    model: &PlateModel,
    mode: usize,
    center: (i32, i32),
    scale: f64,
) -> CliResult<TopView> {
    let m = &model.modes()[mode];
    let p = model.plate();
    let (ri, ra) = (p.inner_radius, p.outer_radius);
    let half = (ra * scale).ceil() as i32 + 1;
    let side = (2 * half + 1) as u32;
    // Field raster.
    let mut peak = 0.0f64;
    let mut values = vec![f64::NAN; (side * side) as usize];
    for py in 0..side as i32 {
        for px in 0..side as i32 {
            let (x, y) = ((px - half) as f64 / scale, (half - py) as f64 / scale);
            let r = x.hypot(y);
            if r >= ri && r <= ra {
                let w = model.mode_shape(mode, r, y.atan2(x)).w;
                peak = peak.max(w.abs());
                values[(py as u32 * side + px as u32) as usize] = w;
            }
        }
    }
    let mut buf = Vec::with_capacity(values.len() * 3);
    for v in &values {
        // Filled contours: 16 colour bands per sign (and a PNG a third the size of a smooth field).
        let c = if v.is_nan() {
            WHITE
        } else {
            diverging(((v / peak) * 16.0).round() / 16.0)
        };
        buf.extend_from_slice(&[c.0, c.1, c.2]);
    }
    let element = BitMapElement::<(i32, i32)>::with_owned_buffer(
        (center.0 - half, center.1 - half),
        (side, side),
        buf,
    )
    .ok_or_else(|| CliError::Usage("raster size".to_string()))?;
    root.draw(&element).map_err(de)?;
    // Nodal lines, exact: diameters at the zeros of cos/sin(kφ), circles at the zeros of R_l.
    let radii = nodal_radii(model, mode);
    let angles = nodal_angles(m.k, m.shape);
    let line = BLACK.stroke_width(2);
    let px = |r: f64, phi: f64| {
        (
            (center.0 as f64 + r * phi.cos() * scale).round() as i32,
            (center.1 as f64 - r * phi.sin() * scale).round() as i32,
        )
    };
    for &phi in &angles {
        root.draw(&PathElement::new(vec![px(ri, phi), px(ra, phi)], line))
            .map_err(de)?;
    }
    for &r in &radii {
        root.draw(&Circle::new(center, (r * scale).round() as i32, line))
            .map_err(de)?;
    }
    // Edges: a heavier inner edge where it is held (supported or clamped).
    let held = |b: crate::config::Boundary| {
        if b == crate::config::Boundary::Free {
            1
        } else {
            3
        }
    };
    root.draw(&Circle::new(
        center,
        (ra * scale).round() as i32,
        EDGE.stroke_width(held(p.outer_boundary)),
    ))
    .map_err(de)?;
    root.draw(&Circle::new(
        center,
        (ri * scale).round() as i32,
        EDGE.stroke_width(held(p.inner_boundary)),
    ))
    .map_err(de)?;
    Ok(TopView {
        k: m.k,
        l: m.l,
        mode: Some(mode),
        shape: Some(m.shape),
        center,
        scale,
        inner_radius: ri,
        outer_radius: ra,
        nodal_radii: radii,
        nodal_angles: angles,
    })
}

/// The edges, and under Mindlin theory the theory (a Mindlin picture draws
/// the deflection w of the Mindlin modes; a Kirchhoff title is unchanged).
pub(super) fn edges_text(config: &Config) -> String {
    let edges = format!(
        "{} inside, {} outside",
        config.plate.inner_boundary.name(),
        config.plate.outer_boundary.name()
    );
    match theory_text(config) {
        Some(theory) => format!("{edges}; {theory}"),
        None => edges,
    }
}

/// "Mindlin plate (κ = …), w shown" under `plate.theory: mindlin`, None under Kirchhoff.
pub(super) fn theory_text(config: &Config) -> Option<String> {
    match config.plate.theory {
        PlateTheory::Kirchhoff => None,
        PlateTheory::Mindlin => Some(format!(
            "Mindlin plate (κ = {:.4}), w shown",
            config.plate.shear_correction
        )),
    }
}

/// The plate of `config` with exactly the ⟨k, l⟩ sets `ks` × `ls`.
pub(super) fn model_for(config: &Config, ks: &[u32], ls: &[u32]) -> CliResult<PlateModel> {
    let mut plate = config.plate.clone();
    plate.nodal_diameters = ks.to_vec();
    plate.nodal_circles = ls.to_vec();
    plate.damping = vec![0.0];
    plate.radial_splines = plate.radial_splines.at_least(plate.min_radial_splines());
    if ks.iter().any(|&k| k > 200) || ls.iter().any(|&l| l > 50) {
        return Err(CliError::Usage(
            "nodal diameters must be ≤ 200 and nodal circles ≤ 50".to_string(),
        ));
    }
    // The bending modes' shapes; the in-plane ones are listed by `modes`.
    PlateModel::bending(&plate).map_err(|e| CliError::Usage(format!("{e}")))
}

pub(super) struct ModeGrid<'a> {
    config: &'a Config,
    model: PlateModel,
    ks: Vec<u32>,
    ls: Vec<u32>,
    title: String,
}

/// Draw a grid of ⟨k, l⟩ mode shapes (rows l, columns k; the cos member of each pair).
pub fn mode_grid(
    config: &Config,
    ks: &[u32],
    ls: &[u32],
    title: Option<&str>,
    out: &Path,
    size: Size,
) -> CliResult<Vec<TopView>> {
    if ks.is_empty() || ls.is_empty() {
        return Err(CliError::Usage(
            "choose at least one nodal diameter (--k) and one nodal circle (--l)".to_string(),
        ));
    }
    let mut ks = ks.to_vec();
    ks.sort_unstable();
    ks.dedup();
    let mut ls = ls.to_vec();
    ls.sort_unstable();
    ls.dedup();
    let model = model_for(config, &ks, &ls)?;
    let p = &config.plate;
    let title = title.map(str::to_string).unwrap_or_else(|| {
        format!(
            "Mode shapes ⟨k, l⟩: r_i = {} m, r_a = {} m, h = {} m, {}; nodal lines black, red w > 0, blue w < 0",
            p.inner_radius,
            p.outer_radius,
            p.thickness,
            edges_text(config)
        )
    });
    render(
        out,
        size,
        &ModeGrid {
            config,
            model,
            ks,
            ls,
            title,
        },
    )
}

impl Painter for ModeGrid<'_> {
    type Out = Vec<TopView>;
    fn paint<DB: DrawingBackend>(
        &self,
        root: &DrawingArea<DB, Shift>,
        _format: Format,
    ) -> CliResult<Vec<TopView>> {
        let (w, h) = root.dim_in_pixel();
        let title_h = 44;
        let font_size = (w as f64 / 75.0).clamp(13.0, 22.0);
        draw_title(&root.split_vertically(title_h).0, &self.title, font_size)?;
        let (cols, rows) = (self.ks.len() as i32, self.ls.len() as i32);
        let cw = (w as i32 - 20) / cols;
        let ch = (h as i32 - title_h - 10) / rows;
        let caption_h = 40;
        let d = (cw.min(ch - caption_h) - 14).max(20);
        let scale = d as f64 / (2.0 * self.config.plate.outer_radius);
        let mut views = Vec::new();
        for (ri, &l) in self.ls.iter().enumerate() {
            for (ci, &k) in self.ks.iter().enumerate() {
                let x0 = 10 + ci as i32 * cw;
                let y0 = title_h + ri as i32 * ch;
                let center = (x0 + cw / 2, y0 + caption_h + (ch - caption_h) / 2);
                let mode = self
                    .model
                    .modes()
                    .iter()
                    .position(|m| m.k == k && m.l == l && m.shape != AngularShape::Sin);
                let caption = match mode {
                    Some(i) => format!("⟨{k}, {l}⟩  {:.0} Hz", self.model.modes()[i].frequency_hz),
                    None => format!("⟨{k}, {l}⟩  rigid body"),
                };
                let style = TextStyle::from((FONT, 17).into_font()).pos(
                    plotters::style::text_anchor::Pos::new(
                        plotters::style::text_anchor::HPos::Center,
                        plotters::style::text_anchor::VPos::Top,
                    ),
                );
                root.draw(&Text::new(caption, (x0 + cw / 2, y0 + 10), style))
                    .map_err(de)?;
                match mode {
                    Some(i) => views.push(draw_top_view(root, &self.model, i, center, scale)?),
                    None => {
                        let p = self.model.plate();
                        root.draw(&Circle::new(
                            center,
                            (p.outer_radius * scale).round() as i32,
                            EDGE.stroke_width(1),
                        ))
                        .map_err(de)?;
                        root.draw(&Circle::new(
                            center,
                            (p.inner_radius * scale).round() as i32,
                            EDGE.stroke_width(1),
                        ))
                        .map_err(de)?;
                        views.push(TopView {
                            k,
                            l,
                            mode: None,
                            shape: None,
                            center,
                            scale,
                            inner_radius: p.inner_radius,
                            outer_radius: p.outer_radius,
                            nodal_radii: vec![],
                            nodal_angles: vec![],
                        });
                    }
                }
            }
        }
        Ok(views)
    }
}

/// Which single mode to draw.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum ModeChoice {
    /// As numbered by `annular_plate modes` (from 1).
    Index(usize),
    /// By ⟨k, l⟩ and shape.
    KL {
        /// Nodal diameters k.
        k: u32,
        /// Nodal circles l.
        l: u32,
        /// cos or sin.
        shape: AngularShape,
    },
}

pub(super) struct ModePicture {
    model: PlateModel,
    mode: usize,
    title: String,
}

/// One mode: a shaded surface (left) and its top view with nodal lines (right).
pub fn mode_picture(
    config: &Config,
    which: ModeChoice,
    title: Option<&str>,
    out: &Path,
    size: Size,
) -> CliResult<TopView> {
    let (model, mode) = match which {
        ModeChoice::Index(i) => {
            let model =
                PlateModel::bending(&config.plate).map_err(|e| CliError::Usage(format!("{e}")))?;
            if i == 0 || i > model.n_modes() {
                return Err(CliError::Usage(format!(
                    "--index {i}: the model has bending modes 1..{} (see `annular_plate modes`)",
                    model.n_modes()
                )));
            }
            (model, i - 1)
        }
        ModeChoice::KL { k, l, shape } => {
            let model = model_for(config, &[k], &[l])?;
            let shape = if k == 0 {
                AngularShape::Axisymmetric
            } else {
                shape
            };
            let mode = model
                .modes()
                .iter()
                .position(|m| m.shape == shape)
                .ok_or_else(|| CliError::Usage(format!("⟨k = {k}, l = {l}⟩ is a rigid-body motion of this free–free plate, not a mode")))?;
            (model, mode)
        }
    };
    let m = &model.modes()[mode];
    let title = title.map(str::to_string).unwrap_or_else(|| {
        format!(
            "Mode ⟨k = {}, l = {}⟩ {}, {:.1} Hz — {}",
            m.k,
            m.l,
            if m.k == 0 { "" } else { m.shape.name() },
            m.frequency_hz,
            edges_text(config)
        )
        .replace("  ", " ")
    });
    render(out, size, &ModePicture { model, mode, title })
}

impl Painter for ModePicture {
    type Out = TopView;
    fn paint<DB: DrawingBackend>(
        &self,
        root: &DrawingArea<DB, Shift>,
        _format: Format,
    ) -> CliResult<TopView> {
        let (w, h) = root.dim_in_pixel();
        let (w, h) = (w as i32, h as i32);
        let font_size = (w as f64 / 60.0).clamp(14.0, 24.0);
        let top = 50;
        draw_title(&root.split_vertically(top).0, &self.title, font_size)?;
        let split = (w as f64 * 0.6) as i32;
        // Right: top view.
        let ra = self.model.plate().outer_radius;
        let d = ((w - split).min(h - top - 40) - 30).max(20);
        let scale = d as f64 / (2.0 * ra);
        let center = (split + (w - split) / 2, top + (h - top - 40) / 2 + 10);
        let view = draw_top_view(root, &self.model, self.mode, center, scale)?;
        let legend =
            TextStyle::from((FONT, 15).into_font()).pos(plotters::style::text_anchor::Pos::new(
                plotters::style::text_anchor::HPos::Center,
                plotters::style::text_anchor::VPos::Top,
            ));
        root.draw(&Text::new(
            "top view: red w > 0, blue w < 0, nodal lines black",
            (center.0, h - 34),
            legend,
        ))
        .map_err(de)?;
        // Left: shaded surface.
        draw_surface(root, &self.model, self.mode, (0, top, split, h))?;
        Ok(view)
    }
}

/// The mode as a shaded, sign-coloured surface in an oblique view, painter's
/// algorithm (far quads first), nodal lines traced on the surface.
pub(super) fn draw_surface<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    model: &PlateModel,
    mode: usize,
    rect: (i32, i32, i32, i32),
) -> CliResult<()> {
    let m = &model.modes()[mode];
    let p = model.plate();
    let (ri, ra) = (p.inner_radius, p.outer_radius);
    let (nr, nphi) = (24usize, (16 * m.k as usize + 101).min(401));
    let phi0 = 0.0123;
    let grid_r = |i: usize| ri + (ra - ri) * i as f64 / nr as f64;
    let grid_phi = |j: usize| phi0 + TAU * j as f64 / nphi as f64;
    let mut w = vec![vec![0.0; nphi]; nr + 1];
    let mut peak = 0.0f64;
    for (i, row) in w.iter_mut().enumerate() {
        for (j, v) in row.iter_mut().enumerate() {
            *v = model.mode_shape(mode, grid_r(i), grid_phi(j)).w;
            peak = peak.max(v.abs());
        }
    }
    for v in w.iter_mut().flatten() {
        *v /= peak;
        if v.abs() < 1e-9 {
            *v = 0.0;
        }
    }
    let amp = 0.28 * ra;
    let (az, el) = (-0.9f64, 0.5f64);
    let (sa, ca, se, ce) = (az.sin(), az.cos(), el.sin(), el.cos());
    // World (x, y, z) → (screen X, screen Y, depth); larger depth = farther.
    let project = |x: f64, y: f64, z: f64| {
        let x1 = x * ca - y * sa;
        let y1 = x * sa + y * ca;
        (x1, z * ce + y1 * se, y1 * ce - z * se)
    };
    let (x0, y0, x1, y1) = rect;
    let (width, height) = ((x1 - x0) as f64, (y1 - y0) as f64);
    let s = (0.92 * width / (2.0 * ra)).min(0.9 * height / (2.0 * ra * se + 2.0 * amp * ce));
    let (cx, cy) = (x0 as f64 + width / 2.0, y0 as f64 + height / 2.0);
    let to_px =
        |(sx, sy, _): (f64, f64, f64)| ((cx + sx * s).round() as i32, (cy - sy * s).round() as i32);
    let point = |i: usize, j: usize| {
        let (r, phi) = (grid_r(i), grid_phi(j));
        (r * phi.cos(), r * phi.sin(), amp * w[i][j])
    };
    let light = {
        let l = (-0.35f64, -0.55, 0.76);
        let n = (l.0 * l.0 + l.1 * l.1 + l.2 * l.2).sqrt();
        (l.0 / n, l.1 / n, l.2 / n)
    };
    struct Quad {
        depth: f64,
        i: usize,
        j: usize,
    }
    let mut quads = Vec::with_capacity(nr * nphi);
    for i in 0..nr {
        for j in 0..nphi {
            let j1 = (j + 1) % nphi;
            let c = [point(i, j), point(i + 1, j), point(i + 1, j1), point(i, j1)];
            let depth = c.iter().map(|&(x, y, z)| project(x, y, z).2).sum::<f64>() / 4.0;
            quads.push(Quad { depth, i, j });
        }
    }
    quads.sort_by(|a, b| b.depth.total_cmp(&a.depth));
    for q in &quads {
        let (i, j) = (q.i, q.j);
        let j1 = (j + 1) % nphi;
        let idx = [(i, j), (i + 1, j), (i + 1, j1), (i, j1)];
        let c: Vec<(f64, f64, f64)> = idx.iter().map(|&(a, b)| point(a, b)).collect();
        let u = (c[2].0 - c[0].0, c[2].1 - c[0].1, c[2].2 - c[0].2);
        let v = (c[3].0 - c[1].0, c[3].1 - c[1].1, c[3].2 - c[1].2);
        let n = (
            u.1 * v.2 - u.2 * v.1,
            u.2 * v.0 - u.0 * v.2,
            u.0 * v.1 - u.1 * v.0,
        );
        let nn = (n.0 * n.0 + n.1 * n.1 + n.2 * n.2).sqrt().max(1e-300);
        let shade = 0.55 + 0.45 * ((n.0 * light.0 + n.1 * light.1 + n.2 * light.2) / nn).abs();
        let wc = idx.iter().map(|&(a, b)| w[a][b]).sum::<f64>() / 4.0;
        let base = diverging(wc);
        let col = RGBColor(
            (base.0 as f64 * shade) as u8,
            (base.1 as f64 * shade) as u8,
            (base.2 as f64 * shade) as u8,
        );
        let pts: Vec<(i32, i32)> = c.iter().map(|&(x, y, z)| to_px(project(x, y, z))).collect();
        root.draw(&Polygon::new(pts.clone(), col.filled()))
            .map_err(de)?;
        let mut outline = pts.clone();
        outline.push(pts[0]);
        root.draw(&PathElement::new(outline, col.stroke_width(1)))
            .map_err(de)?;
        // Nodal line through this quad (marching squares on the mesh).
        let mut cross = Vec::new();
        for e in 0..4 {
            let (a, b) = (idx[e], idx[(e + 1) % 4]);
            let (wa, wb) = (w[a.0][a.1], w[b.0][b.1]);
            if wa * wb < 0.0 {
                let t = wa / (wa - wb);
                let (pa, pb) = (point(a.0, a.1), point(b.0, b.1));
                cross.push(to_px(project(
                    pa.0 + t * (pb.0 - pa.0),
                    pa.1 + t * (pb.1 - pa.1),
                    0.0,
                )));
            }
        }
        for pair in cross.chunks(2).filter(|c| c.len() == 2) {
            root.draw(&PathElement::new(
                vec![pair[0], pair[1]],
                BLACK.stroke_width(2),
            ))
            .map_err(de)?;
        }
    }
    Ok(())
}
