//! `annular_plate modes FILE [--json]`: the mode table, the bending modes
//! and after them the in-plane modes of `plate.in_plane_nodal_diameters`
//! (docs/in_plane.md).

use crate::config::PlateTheory;
use crate::model::in_plane::InPlaneTable;
use crate::model::PlateModel;
use serde::Serialize;
use std::io::Write;

#[derive(Serialize)]
struct JsonMode {
    /// `bending` or `in_plane`.
    family: &'static str,
    k: u32,
    l: u32,
    /// Bending: `axisymmetric`, `cos`, `sin`; in-plane: `torsional`,
    /// `radial` (k = 0), `cos`, `sin`.
    shape: &'static str,
    frequency_hz: f64,
    modal_mass_kg: f64,
    /// The bending modes' ζ (in-plane modes have none yet).
    #[serde(skip_serializing_if = "Option::is_none")]
    damping: Option<f64>,
}

/// The in-plane table's discretisation and edges (present when in-plane
/// modes are requested).
#[derive(Serialize)]
struct JsonInPlane {
    radial_splines: usize,
    inner_edge: &'static str,
    outer_edge: &'static str,
    /// ⟨k, l, family⟩ of the free–free annulus's rigid-body motions left out.
    skipped_rigid_body_modes: Vec<(u32, u32, &'static str)>,
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
    #[serde(skip_serializing_if = "Option::is_none")]
    in_plane: Option<JsonInPlane>,
}

/// Write the table (or JSON) of `model`'s bending modes and the `in_plane`
/// table to `out`.
pub fn write(
    model: &PlateModel,
    in_plane: &InPlaneTable,
    json: bool,
    out: &mut impl Write,
) -> std::io::Result<()> {
    let requested = !model.plate().in_plane_nodal_diameters.is_empty();
    if json {
        let mindlin = model.theory() == PlateTheory::Mindlin;
        let bending = model.modes().iter().map(|m| JsonMode {
            family: "bending",
            k: m.k,
            l: m.l,
            shape: m.shape.name(),
            frequency_hz: m.frequency_hz,
            modal_mass_kg: m.modal_mass,
            damping: Some(m.damping),
        });
        let planar = in_plane.entries.iter().map(|m| JsonMode {
            family: "in_plane",
            k: m.k,
            l: m.l,
            shape: m.shape.name(),
            frequency_hz: m.frequency_hz,
            modal_mass_kg: m.modal_mass,
            damping: None,
        });
        let doc = JsonModes {
            theory: mindlin.then_some("mindlin"),
            shear_correction: mindlin.then_some(model.plate().shear_correction),
            modes: bending.chain(planar).collect(),
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
            in_plane: requested.then(|| JsonInPlane {
                radial_splines: in_plane.splines,
                inner_edge: in_plane.edges[0].name(),
                outer_edge: in_plane.edges[1].name(),
                skipped_rigid_body_modes: in_plane.skipped.clone(),
            }),
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
    if requested {
        write_in_plane(in_plane, out)?;
    }
    Ok(())
}

/// The in-plane table after the bending one (text form).
fn write_in_plane(table: &InPlaneTable, out: &mut impl Write) -> std::io::Result<()> {
    writeln!(
        out,
        "in-plane (plane stress) modes, in-plane edges {}–{}, radial B-splines {} per field",
        table.edges[0].name(),
        table.edges[1].name(),
        table.splines
    )?;
    writeln!(
        out,
        "{:>5} {:>4} {:>4} {:>13} {:>14} {:>15}",
        "index", "k", "l", "shape", "frequency_Hz", "modal_mass_kg"
    )?;
    for (i, m) in table.entries.iter().enumerate() {
        writeln!(
            out,
            "{:>5} {:>4} {:>4} {:>13} {:>14.4} {:>15.6}",
            i + 1,
            m.k,
            m.l,
            m.shape.name(),
            m.frequency_hz,
            m.modal_mass
        )?;
    }
    for (k, l, family) in &table.skipped {
        writeln!(out, "  in-plane ⟨k = {k}, l = {l}⟩ ({family}) is a rigid-body motion of the free–free annulus, not a mode")?;
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
