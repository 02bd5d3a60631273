//! Space-fixed point dampers: an axial viscous damper c_d between the ground
//! and the plate's mid-plane under ALE nodes (`dampers.*`) — a squeeze-film
//! or eddy-current damper the plate slides under.
//!
//! At a space-fixed point the damper acts on the rate ẇ = ∂w/∂t of the
//! deflection there (ALE amplitudes, eq. 20): F_z = −c_d ẇ, a transverse
//! force at the node; nothing in-plane. For one mode of modal mass m and
//! shape value Φ at the node it adds c_d Φ² to the modal damping: the decay
//! rate c_d Φ²/(2m), a damping ratio c_d Φ²/(2 m ω). Memoryless and
//! dependent on the elastic state, so RK4 re-evaluates it at every stage; it
//! bounds its coupling rate for the integrators' step checks. Its forces show
//! in the ALE node wrenches.
//!
//! Everything the model is lives in this file — its parameters, their
//! reader, the model — and one line of `REGISTRY` registers it
//! (docs/architecture.md, "Adding a load model").

use super::model::{
    ale_contact_rate, surface_kinematics, Coupling, LoadContext, LoadModel, ModelOut, Registration,
    SceneNodes,
};
use super::outputs::NO_OUTPUTS;
use crate::config::model_sections::read_ale_node_list;
use crate::config::table::{param, Section, Ty, Value};
use crate::config::{
    Config, ConfigError, LoadModelSection, ModelParameters, Reader, SectionContext, SectionData,
};
use serde::Serialize;
use std::any::Any;

/// The dampers' validated section (`dampers.*`).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct DampersConfig {
    /// ALE nodes, 0-based (`dampers.ale_nodes` counts from 1).
    pub nodes: Vec<usize>,
    /// c_d of each damper, N·s/m.
    pub damping: f64,
}

impl LoadModelSection for DampersConfig {
    const SECTION: &'static str = "dampers";
}

/// The dampers' keys.
pub const SECTIONS: &[Section] = &[Section {
    name: "dampers",
    title: "`dampers` — space-fixed point dampers",
    before: "Off unless `dampers.ale_nodes` is given. Each damper pushes the plate under its node along z with F = −`dampers.damping` · ∂w/∂t.",
    after: "",
    params: &[
        param("dampers.ale_nodes", Ty::IntegerArray, "integer array", "—", Value::Integers(&[]), "[]", "each an existing ALE node (from 1), distinct", "where the dampers act"),
        param("dampers.damping", Ty::Double, "double", "N·s/m", Value::Double(0.0), "0", "≥ 0", "damping c_d of each damper").min(0.0),
    ],
}];

/// The dampers' parameters: their keys and their reader.
pub const PARAMETERS: ModelParameters = ModelParameters {
    sections: SECTIONS,
    read,
};

/// `dampers.*`: the section when `dampers.ale_nodes` names nodes.
fn read(r: &Reader, ctx: &mut SectionContext) -> Result<Option<Box<dyn SectionData>>, ConfigError> {
    let section = read_ale_node_list(r, ctx, "dampers", "dampers.ale_nodes", ["dampers.damping"])?;
    Ok(section.map(|s| {
        let [damping] = s.values;
        DampersConfig {
            nodes: s.nodes,
            damping,
        }
        .boxed()
    }))
}

/// Dampers under ALE nodes (immutable; in the `Scene`).
#[derive(Debug, Clone, PartialEq)]
pub struct PointDampers {
    /// ALE nodes, 0-based.
    pub nodes: Vec<usize>,
    /// c_d, N·s/m.
    pub damping: f64,
    coupling: Coupling,
}

/// The point dampers in the registry (no outputs of their own: their forces
/// show in the node wrenches).
pub const REGISTRATION: Registration = Registration {
    build,
    outputs: &NO_OUTPUTS,
    parameters: &PARAMETERS,
};

/// The registered builder: dampers where `dampers.ale_nodes` names nodes.
pub fn build(config: &Config, nodes: &SceneNodes) -> Option<Box<dyn LoadModel>> {
    let d = config.section::<DampersConfig>()?;
    let coupling = Coupling {
        stiffness_rate_sq: 0.0,
        damping_rate: d.damping * ale_contact_rate(nodes, &d.nodes),
        relaxation_rate: 0.0,
    };
    Some(Box::new(PointDampers {
        nodes: d.nodes.clone(),
        damping: d.damping,
        coupling,
    }))
}

impl LoadModel for PointDampers {
    fn name(&self) -> &'static str {
        "dampers"
    }
    fn as_any(&self) -> &dyn Any {
        self
    }
    fn stage_dependent(&self) -> bool {
        true
    }
    fn coupling(&self) -> Coupling {
        self.coupling
    }
    fn coupling_keys(&self) -> &'static str {
        "dampers.damping"
    }

    /// F_z from w and ẇ alone: the same under Mindlin theory.
    fn takes_mindlin_modes(&self) -> bool {
        true
    }
    /// F_z alone, at the mid-plane point: no work on the in-plane modes.
    fn attach_in_plane(
        &mut self,
        _ip: &crate::dynamics::in_plane::InPlaneDynamics,
    ) -> Result<(), crate::dynamics::error::SimulationError> {
        Ok(())
    }

    /// F_z = −c_d ẇ at each node.
    fn evaluate(&self, ctx: &LoadContext, _slot: &[f64], _commands: &[f64], out: ModelOut) {
        for &j in &self.nodes {
            let s = surface_kinematics(&ctx.ale_nodes[j], ctx.q_ale, ctx.q_dot_ale);
            out.ale[j].force[2] -= self.damping * s.w_dot;
        }
    }
}
