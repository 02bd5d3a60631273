//! Space-fixed point springs: a linear spring k_s and damper c_s between the
//! ground and the plate's mid-plane under ALE nodes (`springs.*`) — a support
//! roller, a displacement sensor's probe, a test rig's stop.
//!
//! At a space-fixed point the plate slides under, the spring acts on the
//! deflection w and its rate ẇ there (ALE amplitudes, eq. 20):
//! F_z = −k_s w − c_s ẇ, a transverse force at the node; nothing in-plane.
//! It is memoryless and depends on the elastic state, so RK4 re-evaluates it
//! at every stage, and it bounds its coupling rate for the integrators'
//! step checks like the pad contacts do.
//!
//! This file is the worked example of docs/architecture.md ("adding a load
//! model"): the model, its builder and one line in `REGISTRY`.

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

/// The springs' validated section (`springs.*`): a spring-damper between the
/// ground and the plate under each listed ALE node, F_z = −k_s w − c_s ẇ.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct SpringsConfig {
    /// ALE nodes, 0-based (`springs.ale_nodes` counts from 1).
    pub nodes: Vec<usize>,
    /// k_s, N/m.
    pub stiffness: f64,
    /// c_s, N·s/m.
    pub damping: f64,
}

impl LoadModelSection for SpringsConfig {
    const SECTION: &'static str = "springs";
}

/// The springs' keys.
pub const SECTIONS: &[Section] = &[Section {
    name: "springs",
    title: "`springs` — space-fixed point springs (the load-model example of docs/architecture.md)",
    before: "Off unless `springs.ale_nodes` is given. Each spring pushes the plate under its node along z with F = −`springs.stiffness` · w − `springs.damping` · ∂w/∂t.",
    after: "",
    params: &[
        param("springs.ale_nodes", Ty::IntegerArray, "integer array", "—", Value::Integers(&[]), "[]", "each an existing ALE node (from 1), distinct", "where the springs act"),
        param("springs.stiffness", Ty::Double, "double", "N/m", Value::Double(0.0), "0", "≥ 0", "stiffness k_s of each spring").min(0.0),
        param("springs.damping", Ty::Double, "double", "N·s/m", Value::Double(0.0), "0", "≥ 0", "damping c_s of each spring").min(0.0),
    ],
}];

/// The springs' parameters: their keys and their reader.
pub const PARAMETERS: ModelParameters = ModelParameters {
    sections: SECTIONS,
    read,
};

/// `springs.*`: the section when `springs.ale_nodes` names nodes.
fn read(r: &Reader, ctx: &mut SectionContext) -> Result<Option<Box<dyn SectionData>>, ConfigError> {
    let keys = ["springs.stiffness", "springs.damping"];
    let section = read_ale_node_list(r, ctx, "springs", "springs.ale_nodes", keys)?;
    Ok(section.map(|s| {
        let [stiffness, damping] = s.values;
        SpringsConfig {
            nodes: s.nodes,
            stiffness,
            damping,
        }
        .boxed()
    }))
}

/// Springs under ALE nodes (immutable; in the `Scene`).
#[derive(Debug, Clone, PartialEq)]
pub struct PointSprings {
    /// ALE nodes, 0-based.
    pub nodes: Vec<usize>,
    /// k_s, N/m.
    pub stiffness: f64,
    /// c_s, N·s/m.
    pub damping: f64,
    coupling: Coupling,
}

/// The point springs in the registry (no outputs of their own: their forces
/// show in the node wrenches).
pub const REGISTRATION: Registration = Registration {
    build,
    outputs: &NO_OUTPUTS,
    parameters: &PARAMETERS,
};

/// The registered builder: springs where `springs.ale_nodes` names nodes.
pub fn build(config: &Config, nodes: &SceneNodes) -> Option<Box<dyn LoadModel>> {
    let s = config.section::<SpringsConfig>()?;
    let lam = ale_contact_rate(nodes, &s.nodes);
    let coupling = Coupling {
        stiffness_rate_sq: s.stiffness * lam,
        damping_rate: s.damping * lam,
        relaxation_rate: 0.0,
    };
    Some(Box::new(PointSprings {
        nodes: s.nodes.clone(),
        stiffness: s.stiffness,
        damping: s.damping,
        coupling,
    }))
}

impl LoadModel for PointSprings {
    fn name(&self) -> &'static str {
        "springs"
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
        "springs.stiffness, springs.damping"
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

    /// F_z = −k_s w − c_s ẇ at each node.
    fn evaluate(&self, ctx: &LoadContext, _slot: &[f64], _commands: &[f64], out: ModelOut) {
        for &j in &self.nodes {
            let s = surface_kinematics(&ctx.ale_nodes[j], ctx.q_ale, ctx.q_dot_ale);
            out.ale[j].force[2] -= self.stiffness * s.w + self.damping * s.w_dot;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A scene with two ALE nodes and the given `springs.*` entries.
    fn read(springs: &str) -> Result<Config, ConfigError> {
        let yaml = format!(
            "/**:
  ros__parameters:
    nodes:
      ale_radial: [1.0, 0.5]
      ale_angular: [0.0, 0.25]
    springs:
{springs}
"
        );
        Config::from_yaml_str(&yaml, "annular_plate")
    }

    #[test]
    fn each_key_reaches_its_own_field() {
        let c = read("      ale_nodes: [2, 1]\n      stiffness: 3.0e5\n      damping: 7.0").unwrap();
        assert_eq!(
            c.section::<SpringsConfig>(),
            Some(&SpringsConfig {
                nodes: vec![1, 0],
                stiffness: 3.0e5,
                damping: 7.0,
            })
        );
    }

    #[test]
    fn bad_keys_are_refused_naming_the_key() {
        let negative = read("      ale_nodes: [1]\n      stiffness: -1.0").unwrap_err();
        assert!(
            matches!(&negative, ConfigError::Negative { key, .. } if key == "springs.stiffness"),
            "{negative:?}"
        );
        let negative = read("      ale_nodes: [1]\n      damping: -1.0").unwrap_err();
        assert!(
            matches!(&negative, ConfigError::Negative { key, .. } if key == "springs.damping"),
            "{negative:?}"
        );
        let no_node = read("      ale_nodes: [3]").unwrap_err();
        assert!(no_node.to_string().contains("springs.ale_nodes"), "{no_node}");
        let without = read("      damping: 1.0").unwrap_err();
        assert!(
            matches!(&without, ConfigError::KeyWithoutSection { enabling_key, .. } if *enabling_key == "springs.ale_nodes"),
            "{without:?}"
        );
        assert_eq!(read("      ale_nodes: []").unwrap().section::<SpringsConfig>(), None);
    }
}
