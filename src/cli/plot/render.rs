//! Rendering helpers shared by every picture: output format and path checks, fonts, the
//! PNG/SVG back ends, titles, the palette, tick labels, thick polylines.

use super::Size;
use crate::cli::error::{CliError, CliResult};
use plotters::coord::Shift;
use plotters::prelude::*;
use std::path::Path;

// ---------------------------------------------------------------- output

/// Picture format, from the output's extension.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Format {
    /// PNG.
    Png,
    /// SVG.
    Svg,
}

/// The format of `path` by its extension (.png or .svg); any other is refused.
pub(crate) fn format_of(path: &Path) -> CliResult<Format> {
    match path
        .extension()
        .and_then(|e| e.to_str())
        .map(|e| e.to_ascii_lowercase())
        .as_deref()
    {
        Some("png") => Ok(Format::Png),
        Some("svg") => Ok(Format::Svg),
        _ => Err(CliError::Usage(format!(
            "output {}: the name must end in .png or .svg",
            path.display()
        ))),
    }
}

/// The output's format is known and its folder exists.
pub(crate) fn check_output_path(path: &Path) -> CliResult<()> {
    format_of(path)?;
    if let Some(dir) = path.parent().filter(|d| !d.as_os_str().is_empty()) {
        if !dir.is_dir() {
            return Err(CliError::Usage(format!(
                "output {}: folder {} does not exist",
                path.display(),
                dir.display()
            )));
        }
    }
    Ok(())
}

pub(super) fn de<E: std::fmt::Debug>(e: E) -> CliError {
    CliError::Draw(format!("{e:?}"))
}

pub(super) const FONT: &str = "sans-serif";

/// Register the embedded DejaVu Sans with plotters (once).
pub(crate) fn ensure_fonts() {
    static ONCE: std::sync::Once = std::sync::Once::new();
    ONCE.call_once(|| {
        let _ = plotters::style::register_font(FONT, FontStyle::Normal, dejavu::sans::regular());
        let _ = plotters::style::register_font(FONT, FontStyle::Bold, dejavu::sans::bold());
    });
}

/// Something that draws itself on any plotters backend.
pub(super) trait Painter {
    type Out;
    /// `format`: what the backend writes (PNG and SVG draw thick polylines differently).
    fn paint<DB: DrawingBackend>(
        &self,
        root: &DrawingArea<DB, Shift>,
        format: Format,
    ) -> CliResult<Self::Out>;
}

pub(super) fn render<P: Painter>(path: &Path, size: Size, painter: &P) -> CliResult<P::Out> {
    check_output_path(path)?;
    ensure_fonts();
    let dims = (size.width, size.height);
    let write_err = |e: &dyn std::fmt::Debug| {
        CliError::Usage(format!("cannot write {}: {e:?}", path.display()))
    };
    match format_of(path)? {
        Format::Png => {
            // Drawn into memory, then encoded with the best PNG compression
            // (smooth mode-shape fields compress poorly at plotters' default).
            let mut pixels = vec![0u8; 3 * size.width as usize * size.height as usize];
            let out = {
                let root = BitMapBackend::with_buffer(&mut pixels, dims).into_drawing_area();
                root.fill(&WHITE).map_err(de)?;
                let out = painter.paint(&root, Format::Png)?;
                root.present().map_err(|e| write_err(&e))?;
                out
            };
            let file = std::fs::File::create(path).map_err(|e| write_err(&e))?;
            let encoder = image::codecs::png::PngEncoder::new_with_quality(
                std::io::BufWriter::new(file),
                image::codecs::png::CompressionType::Best,
                image::codecs::png::FilterType::Adaptive,
            );
            image::ImageEncoder::write_image(
                encoder,
                &pixels,
                size.width,
                size.height,
                image::ColorType::Rgb8,
            )
            .map_err(|e| write_err(&e))?;
            Ok(out)
        }
        Format::Svg => {
            let root = SVGBackend::new(path, dims).into_drawing_area();
            root.fill(&WHITE).map_err(de)?;
            let out = painter.paint(&root, Format::Svg)?;
            root.present().map_err(|e| write_err(&e))?;
            Ok(out)
        }
    }
}

/// A title centred on `area`, its font shrunk until it fits the width.
pub(super) fn draw_title<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    text: &str,
    size: f64,
) -> CliResult<()> {
    let (w, h) = area.dim_in_pixel();
    let mut size = size;
    while size > 9.0 {
        let (tw, _) = area
            .estimate_text_size(text, &TextStyle::from((FONT, size).into_font()))
            .map_err(de)?;
        if tw + 24 <= w {
            break;
        }
        size -= 1.0;
    }
    let style =
        TextStyle::from((FONT, size).into_font()).pos(plotters::style::text_anchor::Pos::new(
            plotters::style::text_anchor::HPos::Center,
            plotters::style::text_anchor::VPos::Center,
        ));
    area.draw(&Text::new(
        text.to_string(),
        (w as i32 / 2, h as i32 / 2),
        style,
    ))
    .map_err(de)?;
    Ok(())
}

/// Distinguishable line colours (Tableau 10).
pub const PALETTE: [RGBColor; 10] = [
    RGBColor(31, 119, 180),
    RGBColor(214, 39, 40),
    RGBColor(44, 160, 44),
    RGBColor(255, 127, 14),
    RGBColor(148, 103, 189),
    RGBColor(140, 86, 75),
    RGBColor(227, 119, 194),
    RGBColor(127, 127, 127),
    RGBColor(188, 189, 34),
    RGBColor(23, 190, 207),
];

/// A tick label: plain for moderate magnitudes, otherwise with an exponent.
pub(super) fn tick(v: f64, span: f64) -> String {
    if v.abs() <= 1e-9 * span.abs() {
        return "0".into();
    }
    let mag = v.abs().max(span.abs());
    if (1e-2..1e5).contains(&mag) {
        let decimals = (2.0 - span.abs().log10().floor()).clamp(0.0, 6.0) as usize;
        format!("{v:.decimals$}")
    } else {
        let e = mag.log10().floor() as i32;
        let digits = ((e as f64 - span.abs().log10().floor()) as usize + 1).min(4);
        format!("{:.*}e{e}", digits, v / 10f64.powi(e))
    }
}

pub(super) fn log_tick(v: f64) -> String {
    let e = v.log10().round();
    if (v.log10() - e).abs() < 1e-6 {
        format!("1e{}", e as i32)
    } else {
        format!("{v:.0e}")
    }
}
