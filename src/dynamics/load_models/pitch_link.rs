//! Pitch links of the swash plate (paper section 5.2, Figs. 11–15).
//!
//! The paper's helicopter model attaches two linkages to material points of
//! the swash plate (Lagrangian nodes); they drive the blades' pitch joints,
//! whose aerodynamic loads are "force-damper elements". Here the linkage
//! loads are **prescribed forces**, not spring-dampers: each link pushes on
//! its node axially with
//!
//!   F_z = F_mean + F_cyc cos(ψ − ψ₀),   ψ = φ + χ,
//!
//! a function of the node's azimuth ψ in the (tilted, non-rotating) reference
//! frame. That is what a cyclically pitched blade transmits when its pitch
//! joint is a spring-damper driven through a rigid link by the tilted plate:
//! the spring part ∝ cos ψ and the damper part ∝ Ω sin ψ combine into one
//! harmonic with amplitude F_cyc and phase ψ₀. Prescribed forces leave the
//! plate's stiffness untouched, so the gravity value of the ⟨k = 0⟩ amplitude
//! stays −C_t g_axial / K (the static check of the swash-plate scene). Two
//! links half a turn apart with F_mean = 0 load only the odd-k modes, and
//! the ⟨k = 1, l = 0⟩ pair — the softest of them — dominates (Fig. 15).

use super::model::{LoadContext, LoadModel, ModelOut, Registration, SceneNodes};
use super::outputs::{ChannelKind, ChannelShape, CsvColumn, OutputChannel, OutputContext, Outputs};
use crate::config::model_sections::{at_most, no_other_keys, node_refs};
use crate::config::table::{param, Section, Ty, Value};
use crate::config::{
    Config, ConfigError, LoadModelSection, ModelParameters, Reader, SectionContext, SectionData,
};
use crate::dynamics::Simulation;
use serde::Serialize;
use std::any::Any;

/// The links' validated section (`links.*`, paper 5.2): prescribed axial
/// forces at Lagrangian nodes, F_z = mean_force + cyclic_force · cos(ψ − cyclic_phase).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct LinksConfig {
    /// Lagrangian nodes, 0-based (`links.lagrange_nodes` counts from 1).
    pub nodes: Vec<usize>,
    /// N.
    pub mean_force: f64,
    /// N.
    pub cyclic_force: f64,
    /// rad.
    pub cyclic_phase: f64,
}

impl LoadModelSection for LinksConfig {
    const SECTION: &'static str = "links";
}

/// The links' keys.
pub const SECTIONS: &[Section] = &[Section {
    name: "links",
    title: "`links` — swash-plate pitch links (paper 5.2; docs/scenes.md)",
    before: "Off unless `links.lagrange_nodes` is given. Each link pushes its node along +z with
F = `links.mean_force` + `links.cyclic_force` · cos(ψ − `links.cyclic_phase`), ψ = φ + χ the node's azimuth.",
    after: "",
    params: &[
        param("links.lagrange_nodes", Ty::IntegerArray, "integer array", "—", Value::Integers(&[]), "[]", "each an existing Lagrangian node (from 1), distinct", "the linkage attachment points"),
        param("links.mean_force", Ty::Double, "double", "N", Value::Double(0.0), "0", "\\|F\\| ≤ `limits.max_force`", "steady part of each link force"),
        param("links.cyclic_force", Ty::Double, "double", "N", Value::Double(0.0), "0", "\\|F\\| ≤ `limits.max_force`", "amplitude of the once-per-revolution part"),
        param("links.cyclic_phase", Ty::Double, "double", "rad", Value::Double(0.0), "0", "finite", "azimuth of the largest push"),
    ],
}];

/// The links' parameters: their keys and their reader.
pub const PARAMETERS: ModelParameters = ModelParameters {
    sections: SECTIONS,
    read,
};

/// `links.*`: the section when `links.lagrange_nodes` names nodes.
fn read(r: &Reader, ctx: &mut SectionContext) -> Result<Option<Box<dyn SectionData>>, ConfigError> {
    let numbers = r.i64_array("links.lagrange_nodes")?;
    if numbers.is_empty() {
        no_other_keys(r, "links", "links.lagrange_nodes")?;
        return Ok(None);
    }
    let nodes = node_refs(
        "links.lagrange_nodes",
        &numbers,
        "lagrange",
        ctx.nodes.lagrange.len(),
    )?;
    let max_force = ctx.limits.max_force;
    let mean_force = at_most("links.mean_force", r.f64("links.mean_force")?, max_force)?;
    let cyclic_force = at_most(
        "links.cyclic_force",
        r.f64("links.cyclic_force")?,
        max_force,
    )?;
    let cyclic_phase = r.f64("links.cyclic_phase")?;
    Ok(Some(
        LinksConfig {
            nodes,
            mean_force,
            cyclic_force,
            cyclic_phase,
        }
        .boxed(),
    ))
}

/// Prescribed link forces at Lagrangian nodes.
#[derive(Debug, Clone, PartialEq)]
pub struct PitchLinks {
    /// Lagrangian nodes, 0-based.
    pub nodes: Vec<usize>,
    /// φ of each node in the plate frame, rad.
    pub angles: Vec<f64>,
    /// Steady part of each link force, N (`links.mean_force`).
    pub mean_force: f64,
    /// Amplitude of the once-per-revolution part, N (`links.cyclic_force`).
    pub cyclic_force: f64,
    /// Its phase, rad (`links.cyclic_phase`).
    pub cyclic_phase: f64,
}

impl PitchLinks {
    /// Axial force of link `j` (N, +z) at joint angle χ.
    #[inline]
    pub fn force(&self, j: usize, chi: f64) -> f64 {
        self.mean_force + self.cyclic_force * (self.angles[j] + chi - self.cyclic_phase).cos()
    }
}

/// The links' declared outputs: each link's force, CSV columns `link{j}_force`.
pub const OUTPUTS: Outputs = Outputs {
    channels: &[OutputChannel {
        name: "force",
        unit: "N",
        kind: ChannelKind::Real,
        shape: ChannelShape::Sequence,
    }],
    column_prefix: "link",
    numbered: true,
    columns: &[CsvColumn::named("force")],
    topic: None,
};

/// The pitch links in the registry.
pub const REGISTRATION: Registration = Registration {
    build,
    outputs: &OUTPUTS,
    parameters: &PARAMETERS,
};

/// The registered builder: links where `links.*` gives their nodes.
pub fn build(config: &Config, nodes: &SceneNodes) -> Option<Box<dyn LoadModel>> {
    let l = config.section::<LinksConfig>()?;
    Some(Box::new(PitchLinks {
        nodes: l.nodes.clone(),
        angles: l.nodes.iter().map(|&j| nodes.lagrange[j].angle).collect(),
        mean_force: l.mean_force,
        cyclic_force: l.cyclic_force,
        cyclic_phase: l.cyclic_phase,
    }))
}

impl LoadModel for PitchLinks {
    fn name(&self) -> &'static str {
        "links"
    }
    /// Prescribed F_z at material points: the same under Mindlin theory.
    fn takes_mindlin_modes(&self) -> bool {
        true
    }
    /// Prescribed F_z alone: no work on the in-plane modes.
    fn attach_in_plane(
        &mut self,
        _ip: &crate::dynamics::in_plane::InPlaneDynamics,
    ) -> Result<(), crate::dynamics::error::SimulationError> {
        Ok(())
    }
    fn as_any(&self) -> &dyn Any {
        self
    }
    /// Prescribed by χ alone; RK4 re-evaluates them at every stage's angle.
    fn stage_dependent(&self) -> bool {
        true
    }
    fn evaluate(&self, ctx: &LoadContext, _slot: &[f64], _commands: &[f64], out: ModelOut) {
        for (j, &node) in self.nodes.iter().enumerate() {
            out.lagrange[node].force[2] += self.force(j, ctx.chi);
        }
    }
    fn channel_len(&self, _channel: usize) -> usize {
        self.nodes.len()
    }
    /// Each link's force at the current joint angle.
    fn write_outputs(&self, at: &OutputContext, out: &mut [f64]) {
        for (j, v) in out.iter_mut().enumerate() {
            *v = self.force(j, at.chi);
        }
    }
}

/// The links' typed view of a simulation (for programs and tests that know
/// they drive a swash plate).
pub trait LinkOutputs {
    /// Number of pitch links (`links.*`; 0 without links).
    fn link_count(&self) -> usize;
    /// Axial force of pitch link `j` (0-based) at the current joint angle, N.
    fn link_force(&self, j: usize) -> f64;
}

impl LinkOutputs for Simulation {
    fn link_count(&self) -> usize {
        self.scene()
            .load_models
            .find::<PitchLinks>()
            .map_or(0, |(_, l)| l.nodes.len())
    }

    fn link_force(&self, j: usize) -> f64 {
        self.scene()
            .load_models
            .find::<PitchLinks>()
            .map_or(0.0, |(_, l)| l.force(j, self.state().chi.angle))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::PI;

    #[test]
    fn links_half_a_turn_apart_carry_opposite_cyclic_forces() {
        let links = PitchLinks {
            nodes: vec![0, 1],
            angles: vec![0.0, PI],
            mean_force: 0.0,
            cyclic_force: 300.0,
            cyclic_phase: 0.4,
        };
        for chi in [0.0, 0.7, 2.0, 5.5] {
            assert!((links.force(0, chi) + links.force(1, chi)).abs() < 1e-9);
        }
        assert!(
            (links.force(0, 0.4) - 300.0).abs() < 1e-12,
            "peak at ψ = ψ₀"
        );
    }
}
