//! The lathe tool's parameters (`tool.*`, paper 5.1): their declaration
//! and the reader that checks their rules into the tool's validated section
//! ([`ToolConfig`], from which the registered builder makes the model).

use crate::config::model_sections::{at_most, no_other_keys, node_refs, non_negative};
use crate::config::table::{param, Section, Ty, Value};
use crate::config::{
    ConfigError, LoadModelSection, ModelParameters, Reader, SectionContext, SectionData,
};
use serde::Serialize;

/// The lathe tool (`tool.*`, paper 5.1): fed parallel to the axis onto the
/// rim, on a spring-damper, with the feed force of eq. (21) from the chip.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ToolConfig {
    /// ALE node on the rim the feed force acts at, 0-based (`tool.ale_node` counts from 1).
    pub node: usize,
    /// Chip width b = radial depth of cut, m.
    pub depth_of_cut: f64,
    /// Initial feed rate, m/s (towards −z, from the +z face through the disc).
    pub feed_rate: f64,
    /// Axial gap between the tool tip and the +z face at t = 0, m.
    pub start_clearance: f64,
    /// Spring between tool holder and tool tip, N/m.
    pub stiffness: f64,
    /// Damper between tool holder and tool tip, N·s/m.
    pub damping: f64,
    /// k_f1.1 of eq. (21): specific feed force at a 1 mm × 1 mm chip, Pa (351 N/mm² = 3.51e8 Pa).
    pub specific_force: f64,
    /// m_f of eq. (21).
    pub force_exponent: f64,
    /// k_c1.1 of Kienzle's main cutting force (tangential), Pa; 0: none.
    pub cutting_specific_force: f64,
    /// m_c of Kienzle's main cutting force.
    pub cutting_exponent: f64,
}

impl LoadModelSection for ToolConfig {
    const SECTION: &'static str = "tool";
}

/// Largest plausible tool feed rate, m/s (60 m/min): `tool.feed_rate` and the feed command.
pub const MAX_TOOL_FEED_RATE: f64 = 1.0;

/// The tool's keys.
pub const SECTIONS: &[Section] = &[Section {
    name: "tool",
    title: "`tool` — lathe tool (paper 5.1; docs/scenes.md)",
    before: "Off unless `tool.ale_node` is given (0 or absent: no tool).",
    after: "",
    params: &[
        param(
            "tool.ale_node",
            Ty::Integer,
            "integer",
            "—",
            Value::Integer(0),
            "0 (no tool)",
            "an existing ALE node (from 1) at ξ_r = 1 (the rim)",
            "where the feed force acts",
        ),
        param(
            "tool.depth_of_cut",
            Ty::Double,
            "double",
            "m",
            Value::Double(0.002),
            "0.002",
            "> 0, < r_a − r_i",
            "radial depth of cut = chip width b",
        ),
        param(
            "tool.feed_rate",
            Ty::Double,
            "double",
            "m/s",
            Value::Double(0.002),
            "0.002 (120 mm/min)",
            "\\|v\\| ≤ 1",
            "feed along −z at t = 0 (the command `set_tool_feed` changes it; negative retracts)",
        ),
        param(
            "tool.start_clearance",
            Ty::Double,
            "double",
            "m",
            Value::Double(0.0),
            "0",
            "≥ 0",
            "gap between the tool tip and the +z face at t = 0",
        )
        .min(0.0),
        param(
            "tool.stiffness",
            Ty::Double,
            "double",
            "N/m",
            Value::Double(20000000.0),
            "2e7",
            "> 0",
            "spring between tool holder and tip",
        )
        .above(0.0),
        param(
            "tool.damping",
            Ty::Double,
            "double",
            "N·s/m",
            Value::Double(2000.0),
            "2e3",
            "≥ 0",
            "damper between tool holder and tip (no tip mass)",
        )
        .min(0.0),
        param(
            "tool.specific_force",
            Ty::Double,
            "double",
            "Pa",
            Value::Double(351000000.0),
            "3.51e8",
            "> 0",
            "k_f1.1 of eq. (21): 351 N/mm² for a 1 mm × 1 mm chip",
        )
        .above(0.0),
        param(
            "tool.force_exponent",
            Ty::Double,
            "double",
            "—",
            Value::Double(0.7013),
            "0.7013",
            "≥ 0, < 1",
            "m_f of eq. (21)",
        ),
        param(
            "tool.cutting_specific_force",
            Ty::Double,
            "double",
            "Pa",
            Value::Double(0.0),
            "0 (none: the paper's model)",
            "≥ 0",
            "k_c1.1 of the main cutting force F_c = k_c1.1 b h^(1−m_c) (1 mm)^m_c, tangential at the tool's node against the rotation: it brakes the joint (its effort carries F_c r_a) and twists the in-plane modes (docs/scenes.md); for steel about 1.5e9–2.2e9 (1500–2200 N/mm²)",
        )
        .min(0.0),
        param(
            "tool.cutting_exponent",
            Ty::Double,
            "double",
            "—",
            Value::Double(0.25),
            "0.25",
            "≥ 0, < 1",
            "m_c of the main cutting force (steel about 0.2–0.3)",
        ),
    ],
}];

/// The tool's parameters: its keys and its reader.
pub const PARAMETERS: ModelParameters = ModelParameters {
    sections: SECTIONS,
    read,
};

/// `tool.*`: the section when `tool.ale_node` names a node on the rim.
fn read(r: &Reader, ctx: &mut SectionContext) -> Result<Option<Box<dyn SectionData>>, ConfigError> {
    let number = r.i64("tool.ale_node")?;
    if number == 0 {
        no_other_keys(r, "tool", "tool.ale_node")?;
        return Ok(None);
    }
    let node = tool_node(number, ctx)?;
    let depth_of_cut = r.positive("tool.depth_of_cut")?;
    let width = ctx.plate.outer_radius - ctx.plate.inner_radius;
    if depth_of_cut >= width {
        return Err(ConfigError::DepthOfCutBeyondPlate {
            depth: depth_of_cut,
            width,
        });
    }
    let feed_rate = at_most(
        "tool.feed_rate",
        r.f64("tool.feed_rate")?,
        MAX_TOOL_FEED_RATE,
    )?;
    let start_clearance = non_negative("tool.start_clearance", r.f64("tool.start_clearance")?)?;
    let stiffness = r.positive("tool.stiffness")?;
    let damping = non_negative("tool.damping", r.f64("tool.damping")?)?;
    let specific_force = r.positive("tool.specific_force")?;
    let force_exponent = exponent(r, "tool.force_exponent")?;
    let cutting_specific_force = non_negative(
        "tool.cutting_specific_force",
        r.f64("tool.cutting_specific_force")?,
    )?;
    let cutting_exponent = exponent(r, "tool.cutting_exponent")?;
    Ok(Some(
        ToolConfig {
            node,
            depth_of_cut,
            feed_rate,
            start_clearance,
            stiffness,
            damping,
            specific_force,
            force_exponent,
            cutting_specific_force,
            cutting_exponent,
        }
        .boxed(),
    ))
}

/// A Kienzle exponent `key`: ≥ 0 and < 1.
fn exponent(r: &Reader, key: &'static str) -> Result<f64, ConfigError> {
    let value = non_negative(key, r.f64(key)?)?;
    if value >= 1.0 {
        return Err(ConfigError::AboveMaximum {
            key: key.into(),
            value,
            max: 1.0,
        });
    }
    Ok(value)
}

/// `tool.ale_node` (≥ 1) → the 0-based ALE node, which must lie on the rim.
fn tool_node(number: i64, ctx: &SectionContext) -> Result<usize, ConfigError> {
    let node =
        node_refs("tool.ale_node", &[number], "ale", ctx.nodes.ale.len()).map_err(|e| match e {
            ConfigError::NotPositive { value, .. } => ConfigError::Negative {
                key: "tool.ale_node".into(),
                value,
            },
            ConfigError::NoSuchNode {
                node, kind, count, ..
            } => ConfigError::NoSuchNode {
                key: "tool.ale_node".into(),
                node,
                kind,
                count,
            },
            other => other,
        })?[0];
    let radial = ctx.nodes.ale[node].radial;
    if (radial - 1.0).abs() > 1e-12 {
        return Err(ConfigError::ToolNotOnRim {
            node: node + 1,
            radial,
        });
    }
    Ok(node)
}
