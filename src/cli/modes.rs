//! `annular_plate modes FILE [--json]`: the mode table.

use crate::config::PlateTheory;
use crate::model::PlateModel;
use serde::Serialize;
use std::io::Write;

#[derive(Serialize)]
struct JsonMode {
    k: u32,
    l: u32,
    shape: &'static str,
    frequency_hz: f64,
    modal_mass_kg: f64,
    damping: f64,
}

/// The radial spline count used for one k (`plate.radial_splines`; with
/// `auto` also the estimated relative frequency error of the requested l).
#[derive(Serialize)]
struct JsonRadialResolution {
    k: u32,
    radial_splines: usize,
    estimated_relative_error: Option<f64>,
}

#[derive(Serialize)]
struct JsonModes {
    /// `mindlin` (absent for the default `kirchhoff`, whose output is unchanged).
    #[serde(skip_serializing_if = "Option::is_none")]
    theory: Option<&'static str>,
    /// κ under Mindlin theory.
    #[serde(skip_serializing_if = "Option::is_none")]
    shear_correction: Option<f64>,
    modes: Vec<JsonMode>,
    skipped_rigid_body_modes: Vec<(u32, u32)>,
    /// `"auto"` or the fixed count, as configured.
    radial_splines: crate::config::RadialSplines,
    frequency_tolerance: f64,
    radial_splines_per_k: Vec<JsonRadialResolution>,
}

/// Write the table (or JSON) for `model` to `out`.
pub fn write(model: &PlateModel, json: bool, out: &mut impl Write) -> std::io::Result<()> {
    if json {
        let mindlin = model.theory() == PlateTheory::Mindlin;
        let doc = JsonModes {
            theory: mindlin.then_some("mindlin"),
            shear_correction: mindlin.then_some(model.plate().shear_correction),
            modes: model
                .modes()
                .iter()
                .map(|m| JsonMode {
                    k: m.k,
                    l: m.l,
                    shape: m.shape.name(),
                    frequency_hz: m.frequency_hz,
                    modal_mass_kg: m.modal_mass,
                    damping: m.damping,
                })
                .collect(),
            skipped_rigid_body_modes: model.skipped_rigid_body_modes().to_vec(),
            radial_splines: model.plate().radial_splines,
            frequency_tolerance: model.plate().frequency_tolerance,
            radial_splines_per_k: model
                .radial_resolution()
                .iter()
                .map(|r| JsonRadialResolution {
                    k: r.k,
                    radial_splines: r.splines,
                    estimated_relative_error: r.estimated_error,
                })
                .collect(),
        };
        serde_json::to_writer_pretty(&mut *out, &doc)?;
        writeln!(out)?;
        return Ok(());
    }
    let p = model.plate();
    if model.theory() == PlateTheory::Mindlin {
        write!(
            out,
            "Mindlin (shear correction κ = {}, rotary inertia in the modal mass) ",
            p.shear_correction
        )?;
    }
    writeln!(
        out,
        "annular plate r_i = {} m, r_a = {} m, h = {} m, {}–{}, radial B-splines {}, D = {:.6e} N·m",
        p.inner_radius,
        p.outer_radius,
        p.thickness,
        p.inner_boundary.name(),
        p.outer_boundary.name(),
        splines_text(model),
        model.rigidity()
    )?;
    writeln!(
        out,
        "{:>5} {:>4} {:>4} {:>13} {:>14} {:>15} {:>8}",
        "index", "k", "l", "shape", "frequency_Hz", "modal_mass_kg", "damping"
    )?;
    for (i, m) in model.modes().iter().enumerate() {
        writeln!(
            out,
            "{:>5} {:>4} {:>4} {:>13} {:>14.4} {:>15.6} {:>8}",
            i + 1,
            m.k,
            m.l,
            m.shape.name(),
            m.frequency_hz,
            m.modal_mass,
            m.damping
        )?;
    }
    for (k, l) in model.skipped_rigid_body_modes() {
        writeln!(out, "  ⟨k = {k}, l = {l}⟩ is a rigid-body motion of the free–free plate: carried by the floating frame and joint, not a mode")?;
    }
    Ok(())
}

/// `32`, or for `auto` the range of counts over k with the tolerance
/// (`auto (26–58 over k, tolerance 1e-6)`).
fn splines_text(model: &PlateModel) -> String {
    let p = model.plate();
    if let Some(n) = p.radial_splines.fixed() {
        return n.to_string();
    }
    if model.theory() == PlateTheory::Mindlin {
        return format!(
            "auto ({} per field)",
            crate::model::mindlin::DEFAULT_SPLINES
        );
    }
    let counts = model.radial_resolution().iter().map(|r| r.splines);
    let (lo, hi) = (counts.clone().min().unwrap_or(0), counts.max().unwrap_or(0));
    let range = if lo == hi {
        lo.to_string()
    } else {
        format!("{lo}–{hi}")
    };
    format!(
        "auto ({range} over k, tolerance {:e})",
        p.frequency_tolerance
    )
}
