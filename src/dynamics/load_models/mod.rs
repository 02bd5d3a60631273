//! Load models of the paper's three applications (section 5): brake pads
//! ([`pad`], 5.3), the lathe tool ([`tool`], 5.1) and the swash plate's pitch
//! links ([`pitch_link`], 5.2).
//!
//! They act at the integration rate, inside the step — which a ROS topic
//! cannot — and topics only set their commands (a pad's clamp force, the tool
//! feed). The split follows the rest of `dynamics`: parameters in the
//! immutable [`Scene`](super::Scene) ([`LoadModels`]), mutable state in the
//! [`State`](super::State) ([`LoadModelState`]: the tool's machined surface,
//! so reset and replay stay clones), commands in the
//! [`Inputs`](super::Inputs) ([`LoadCommands`]).
//!
//! Every substep the stepper evaluates the models from the node kinematics
//! (deflection and its rate under ALE nodes, the joint angle for Lagrangian
//! nodes) into [`ModelWrenches`], which the node-load computation adds on top
//! of the user's held wrenches, each with its own follower choice (the pads'
//! friction follows the deformed surface; a held user wrench follows only with
//! `loads.follower`). Pads and links are memoryless: RK4 evaluates them at
//! every stage, the other integrators at the substep start. The tool has
//! memory (the surface it cut one revolution earlier): its force is computed
//! at the substep start, held over the substep, and its state advanced after it.

pub mod pad;
pub mod pitch_link;
pub mod tool;

pub use pad::{ContactForces, PadContactPoint, Pads, SurfaceKinematics};
pub use pitch_link::PitchLinks;
pub use tool::{Tool, ToolState, ToolStep};

use crate::dynamics::joint::FrictionTorque;
use super::scene::NodeFrame;
use super::wrench::{InputError, Wrench};
use crate::config::{Config, LimitsConfig};
use thiserror::Error;

/// Immutable load-model parameters of a scene.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct LoadModels {
    pub pads: Option<Pads>,
    pub tool: Option<Tool>,
    pub links: Option<PitchLinks>,
    /// Largest eigenvalue of M^(−½) K_pads M^(−½) with every contact closed
    /// and a fixed caliper, 1/s² — a bound for any caliper and any set of
    /// closed contacts (opening contacts or letting the pads float only
    /// removes stiffness). Zero without pads.
    pub pad_stiffness_rate_sq: f64,
    /// The same for the pads' damping, M^(−½) C_pads M^(−½), 1/s.
    pub pad_damping_rate: f64,
}

/// Mutable load-model state (part of [`State`](super::State)).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct LoadModelState {
    pub tool: Option<ToolState>,
}

impl LoadModelState {
    /// Copy `other` into `self` reusing the buffers (allocates only the first
    /// time a model's state appears in `self`).
    pub fn copy_from(&mut self, other: &LoadModelState) {
        match (&mut self.tool, &other.tool) {
            (Some(a), Some(b)) => a.copy_from(b),
            (slot, b) => *slot = b.clone(),
        }
    }
}

/// Commands of the load models (part of [`Inputs`](super::Inputs)).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct LoadCommands {
    /// Clamp force per pad, N.
    pub clamp_force: Vec<f64>,
    /// Tool feed rate, m/s (towards −z).
    pub feed_rate: f64,
}

/// Wrenches the load models apply at one instant, per node, with the
/// follower choice per node, and the pads' contact forces behind them
/// (scratch space allocated once).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct ModelWrenches {
    pub ale: Vec<Wrench>,
    pub lagrange: Vec<Wrench>,
    pub ale_follower: Vec<bool>,
    pub lagrange_follower: Vec<bool>,
    /// Per pad contact point (order of `Pads::contacts`): surface kinematics and forces.
    pub kinematics: Vec<SurfaceKinematics>,
    pub contact_forces: Vec<ContactForces>,
    /// The pads' friction torque as a function of Ω, per contact point:
    /// τ_f(Ω) = −Σ capacity · tanh(Ω · slope) (see [`Pads::friction_torque_terms`]),
    /// so the joint can solve its step with the friction at the step's end.
    pub friction: Vec<FrictionTorque>,
    closed: Vec<bool>,
}

impl ModelWrenches {
    /// Scratch for the nodes of `scene` and its pad contact points.
    pub fn new(scene: &super::Scene) -> ModelWrenches {
        let (n_ale, n_lagrange) = (scene.ale_nodes.len(), scene.lagrange_nodes.len());
        let contacts = scene.load_models.pads.as_ref().map_or(0, |p| p.contacts.len());
        ModelWrenches {
            ale: vec![Wrench::default(); n_ale],
            lagrange: vec![Wrench::default(); n_lagrange],
            ale_follower: vec![false; n_ale],
            lagrange_follower: vec![false; n_lagrange],
            kinematics: vec![SurfaceKinematics::default(); contacts],
            contact_forces: vec![ContactForces::default(); contacts],
            friction: vec![FrictionTorque::default(); contacts],
            closed: vec![false; contacts],
        }
    }

    fn clear(&mut self) {
        self.ale.iter_mut().for_each(|w| *w = Wrench::default());
        self.lagrange.iter_mut().for_each(|w| *w = Wrench::default());
        self.friction.iter_mut().for_each(|f| *f = FrictionTorque::default());
    }
}

/// A load-model command that was refused; the held commands are unchanged.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum LoadCommandError {
    #[error(transparent)]
    Input(#[from] InputError),
    #[error("there is no pad {index} (pads count from 1; this scene has {count})")]
    NoSuchPad { index: usize, count: usize },
    #[error("this scene has no tool (tool.ale_node)")]
    NoTool,
}

/// Deflection and its rate at a fixed point for amplitudes in the node's own description.
#[inline]
pub fn surface_kinematics(node: &NodeFrame, q: &[f64], q_dot: &[f64]) -> SurfaceKinematics {
    let mut s = SurfaceKinematics::default();
    for ((shape, &qi), &vi) in node.shapes.iter().zip(q).zip(q_dot) {
        s.w += shape.w * qi;
        s.w_dot += shape.w * vi;
    }
    s
}

/// Largest eigenvalue of M^(−½) (Σ_c w_c w_cᵀ) M^(−½), w_c the mode shapes at contact c.
fn pad_rate(shapes: &[&[super::scene::NodeShape]], modal_mass: &[f64]) -> f64 {
    let n = modal_mass.len();
    let mut a = faer::Mat::<f64>::zeros(n, n);
    for s in shapes {
        for i in 0..n {
            for m in 0..n {
                a[(i, m)] += s[i].w * s[m].w / (modal_mass[i] * modal_mass[m]).sqrt();
            }
        }
    }
    a.self_adjoint_eigenvalues(faer::Side::Lower).ok().and_then(|ev| ev.last().copied()).unwrap_or(0.0).max(0.0)
}

impl LoadModels {
    /// The load models a configuration switches on, for its node frames and modal masses.
    pub fn new(config: &Config, ale_nodes: &[NodeFrame], lagrange_nodes: &[NodeFrame], modal_mass: &[f64]) -> LoadModels {
        let pads = config.pads.as_ref().map(|p| {
            let mut contacts_per_pad = vec![0; p.pad_count()];
            let contacts = p
                .contacts
                .iter()
                .map(|c| {
                    contacts_per_pad[c.pad] += 1;
                    let angle = ale_nodes[c.node].angle;
                    PadContactPoint { node: c.node, pad: c.pad, radius: ale_nodes[c.node].radius, angle, sin_cos: angle.sin_cos() }
                })
                .collect();
            Pads {
                contacts,
                contacts_per_pad,
                stiffness: p.contact_stiffness,
                damping: p.contact_damping,
                friction_coefficient: p.friction_coefficient,
                lift_off: p.lift_off,
                follower_friction: p.follower_friction,
                caliper: p.caliper,
                initial_clamp_force: p.clamp_force.clone(),
            }
        });
        let tool = config.tool.as_ref().map(|t| Tool {
            node: t.node,
            angle: ale_nodes[t.node].angle,
            depth_of_cut: t.depth_of_cut,
            stiffness: t.stiffness,
            damping: t.damping,
            specific_force: t.specific_force,
            force_exponent: t.force_exponent,
            thickness: config.plate.thickness,
            start_height: 0.5 * config.plate.thickness + t.start_clearance,
        });
        let links = config.links.as_ref().map(|l| PitchLinks {
            nodes: l.nodes.clone(),
            angles: l.nodes.iter().map(|&j| lagrange_nodes[j].angle).collect(),
            mean_force: l.mean_force,
            cyclic_force: l.cyclic_force,
            cyclic_phase: l.cyclic_phase,
        });
        let (pad_stiffness_rate_sq, pad_damping_rate) = match &pads {
            Some(p) => {
                let shapes: Vec<&[super::scene::NodeShape]> = p.contacts.iter().map(|c| ale_nodes[c.node].shapes.as_slice()).collect();
                let lam = pad_rate(&shapes, modal_mass);
                (2.0 * p.stiffness * lam, 2.0 * p.damping * lam)
            }
            None => (0.0, 0.0),
        };
        LoadModels { pads, tool, links, pad_stiffness_rate_sq, pad_damping_rate }
    }

    pub fn is_empty(&self) -> bool {
        self.pads.is_none() && self.tool.is_none() && self.links.is_none()
    }

    /// Models that RK4 evaluates at every stage (memoryless: pads, links).
    pub fn stage_dependent(&self) -> bool {
        self.pads.is_some() || self.links.is_some()
    }

    /// The commands a configuration starts with.
    pub fn initial_commands(config: &Config) -> LoadCommands {
        LoadCommands {
            clamp_force: config.pads.as_ref().map(|p| p.clamp_force.clone()).unwrap_or_default(),
            feed_rate: config.tool.as_ref().map_or(0.0, |t| t.feed_rate),
        }
    }

    /// Put `commands` back to the configuration's, reusing its buffer.
    pub fn reset_commands(config: &Config, commands: &mut LoadCommands) {
        commands.clamp_force.clear();
        if let Some(p) = &config.pads {
            commands.clamp_force.extend_from_slice(&p.clamp_force);
        }
        commands.feed_rate = config.tool.as_ref().map_or(0.0, |t| t.feed_rate);
    }

    /// The state a scene starts with.
    pub fn initial_state(&self) -> LoadModelState {
        LoadModelState { tool: self.tool.as_ref().map(Tool::initial_state) }
    }

    /// Fill `out` with the wrenches of all models at one instant: pads from the
    /// ALE amplitudes and rates, links from the joint angle χ, the tool's held
    /// force `tool_force` (N) at its node.
    #[allow(clippy::too_many_arguments)]
    pub fn evaluate(
        &self,
        ale_nodes: &[NodeFrame],
        q_ale: &[f64],
        q_dot_ale: &[f64],
        chi: f64,
        speed: f64,
        commands: &LoadCommands,
        tool_force: f64,
        out: &mut ModelWrenches,
    ) {
        out.clear();
        if let Some(p) = &self.pads {
            let ModelWrenches { ale, ale_follower, kinematics, contact_forces, closed, .. } = out;
            for (k, c) in kinematics.iter_mut().zip(&p.contacts) {
                *k = surface_kinematics(&ale_nodes[c.node], q_ale, q_dot_ale);
            }
            p.forces(&commands.clamp_force, kinematics, speed, contact_forces, closed);
            p.friction_torque_terms(contact_forces, &mut out.friction);
            for (c, f) in p.contacts.iter().zip(contact_forces.iter()) {
                let w = Pads::wrench(c, f);
                let slot = &mut ale[c.node];
                for a in 0..3 {
                    slot.force[a] += w.force[a];
                }
                ale_follower[c.node] = p.follower_friction;
            }
        }
        if let Some(t) = &self.tool {
            out.ale[t.node].force[2] -= tool_force;
        }
        if let Some(l) = &self.links {
            for (j, &node) in l.nodes.iter().enumerate() {
                out.lagrange[node].force[2] += l.force(j, chi);
            }
        }
    }

    /// Check and apply a pad clamp force (`pad` 0-based).
    pub fn set_clamp_force(&self, commands: &mut LoadCommands, pad: usize, newtons: f64, limits: &LimitsConfig) -> Result<(), LoadCommandError> {
        let count = self.pads.as_ref().map_or(0, |p| p.pad_count());
        check_clamp_force(pad, count, newtons, limits.max_force)?;
        commands.clamp_force[pad] = newtons;
        Ok(())
    }

    /// Check and apply the tool feed rate (m/s, towards −z; negative retracts).
    pub fn set_feed_rate(&self, commands: &mut LoadCommands, rate: f64) -> Result<(), LoadCommandError> {
        check_feed_rate(self.tool.is_some(), rate)?;
        commands.feed_rate = rate;
        Ok(())
    }
}

/// The rule for a clamp force command on pad `pad` (0-based) of a scene with
/// `count` pads: the pad exists, the force is finite and in [0, `max_force`].
/// Shared by [`LoadModels::set_clamp_force`] and the ROS node's input checks,
/// so both refuse the same commands for the same reason.
pub fn check_clamp_force(pad: usize, count: usize, newtons: f64, max_force: f64) -> Result<(), LoadCommandError> {
    if pad >= count {
        return Err(LoadCommandError::NoSuchPad { index: pad + 1, count });
    }
    let what = || format!("pad_{} clamp force", pad + 1);
    if !newtons.is_finite() {
        return Err(InputError::NonFinite { what: what(), value: newtons }.into());
    }
    if !(0.0..=max_force).contains(&newtons) {
        return Err(InputError::Absurd { what: format!("{} (must lie in [0, limits.max_force])", what()), value: newtons, limit: max_force }.into());
    }
    Ok(())
}

/// The rule for a tool feed rate command (m/s): the scene has a tool, the
/// rate is finite and at most [`MAX_TOOL_FEED_RATE`](crate::config::MAX_TOOL_FEED_RATE)
/// in magnitude. Shared like [`check_clamp_force`].
pub fn check_feed_rate(has_tool: bool, rate: f64) -> Result<(), LoadCommandError> {
    if !has_tool {
        return Err(LoadCommandError::NoTool);
    }
    if !rate.is_finite() {
        return Err(InputError::NonFinite { what: "tool feed rate".into(), value: rate }.into());
    }
    if rate.abs() > crate::config::MAX_TOOL_FEED_RATE {
        return Err(InputError::Absurd { what: "tool feed rate".into(), value: rate, limit: crate::config::MAX_TOOL_FEED_RATE }.into());
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::config::{Caliper, LimitsConfig};
    use crate::dynamics::scene::NodeShape;

    fn one_pad() -> LoadModels {
        let contact = PadContactPoint { node: 0, pad: 0, radius: 0.1, angle: 0.0, sin_cos: (0.0, 1.0) };
        LoadModels {
            pads: Some(Pads {
                contacts: vec![contact],
                contacts_per_pad: vec![1],
                stiffness: 1e6,
                damping: 0.0,
                friction_coefficient: 0.4,
                lift_off: false,
                follower_friction: true,
                caliper: Caliper::Floating,
                initial_clamp_force: vec![100.0],
            }),
            ..LoadModels::default()
        }
    }

    #[test]
    fn commands_are_checked_before_they_are_held() {
        let lm = one_pad();
        let limits = LimitsConfig::default();
        let mut cmd = LoadCommands { clamp_force: vec![100.0], feed_rate: 0.0 };
        lm.set_clamp_force(&mut cmd, 0, 250.0, &limits).unwrap();
        assert_eq!(cmd.clamp_force, [250.0]);
        for bad in [f64::NAN, f64::INFINITY, -1.0, 2.0 * limits.max_force] {
            let e = lm.set_clamp_force(&mut cmd, 0, bad, &limits).unwrap_err();
            assert!(e.to_string().contains("pad_1 clamp force"), "{e}");
        }
        assert_eq!(lm.set_clamp_force(&mut cmd, 3, 1.0, &limits), Err(LoadCommandError::NoSuchPad { index: 4, count: 1 }));
        assert_eq!(lm.set_feed_rate(&mut cmd, 0.001), Err(LoadCommandError::NoTool));
        assert_eq!(cmd, LoadCommands { clamp_force: vec![250.0], feed_rate: 0.0 }, "refused commands change nothing");
    }

    #[test]
    fn the_pad_rate_is_the_largest_eigenvalue_of_the_mass_scaled_contact_stiffness() {
        // Two modes, two contacts: Σ w wᵀ = [[1, 0], [0, 4]] + [[1, 1], [1, 1]] over masses (2, 1).
        let shapes = [
            vec![NodeShape { w: 1.0, tilt: [0.0; 2] }, NodeShape { w: 2.0, tilt: [0.0; 2] }],
            vec![NodeShape { w: 1.0, tilt: [0.0; 2] }, NodeShape { w: -1.0, tilt: [0.0; 2] }],
        ];
        let refs: Vec<&[NodeShape]> = shapes.iter().map(|s| s.as_slice()).collect();
        let lam = pad_rate(&refs, &[2.0, 1.0]);
        // M^(−½) A M^(−½) = [[1, 1/√2], [1/√2, 5]]: eigenvalues 3 ± √(4 + 1/2).
        let expected = 3.0 + 4.5f64.sqrt();
        assert!((lam - expected).abs() < 1e-12, "{lam} vs {expected}");
    }
}
