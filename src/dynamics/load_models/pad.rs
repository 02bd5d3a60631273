//! Brake pads: the contact submodel of the paper's brake-squeal example
//! (section 5.3, Fig. 18).
//!
//! At every contact point — an ALE node, so the pad stays put while the disc
//! slides under it (paper 4.1) — a pad presses on each face of the disc through
//! an axial spring k_c and damper c_c (the prismatic joint with its
//! spring-damper of Fig. 18). With the transverse deflection w under the
//! point and its rate ẇ = ∂w/∂t at the fixed θ (the rate at which the gap to
//! a space-fixed pad closes; the material velocity ∂w/∂t + Ω ∂w/∂θ differs
//! from it by the sliding along the deformed surface), the contact forces are
//!
//! - top face (+z, pushes −z):    N_t = u_t + k_c w + c_c ẇ
//! - bottom face (−z, pushes +z): N_b = u_b − k_c w − c_c ẇ
//!
//! where u = k_c δ + c_c δ̇ comes from the position δ of the pad's backing
//! plate (the caliper side of the springs). Two calipers (`pads.caliper`):
//!
//! - `fixed`: the caliper is held where the clamp force N₀ puts it on an
//!   undeformed disc — with n contact points each spring is compressed by
//!   δ₀ = N₀/(n k_c), u = N₀/n. The disc sees the pads as springs
//!   2k_c and dampers 2c_c to ground.
//! - `floating` (default): the clamp force is a force, as with a hydraulic
//!   piston in a floating caliper: each face's pad is a rigid, massless
//!   backing plate pressed with N₀, so u solves Σ_c N_c = N₀ per pad and face.
//!   The pads then act on the deformation relative to the pad's mean,
//!   N = N₀/n ± (k_c (w − w̄) + c_c (ẇ − ẇ̄)), and push the disc with no net
//!   axial force.
//!
//! With `pads.lift_off` a contact that would pull is released (N = max(N, 0);
//! for the floating caliper u is found for the contacts that stay closed):
//! the "non-linear spring which takes the loss of contact into account" the
//! paper suggests for a more advanced study.
//!
//! Friction: each face drags the disc with μN against its sliding direction,
//! tangential (−sign Ω e_θ), so a contact gives F_θ = −μ (N_t + N_b) sign(Ω)
//! (sign regularised as tanh(Ω r / 1 mm/s) so a disc braked to rest does not
//! chatter). With `pads.follower_friction` (the default) the friction force
//! lies in the deformed surface: the follower-force mechanism of the paper's
//! section 5.3 adds the normal component (F_θ / r) ∂w/∂θ — the direction of
//! the sliding velocity, whose normal part ∂w/∂t|θ is the gap closure, not
//! sliding. Its torque about the axis, r F_θ, goes to the joint. Both faces act
//! at the mid-plane node: a Kirchhoff plate has no through-thickness, and the
//! paper connects its contact submodel to the mid-plane `nodes_ALE` frame.
//!
//! With `pads.contact_surface: faces` each face's friction acts on the face
//! (z = ±h/2) against the sliding velocity of the face point under the pad
//! (`face_friction.rs`): the two faces' normal-force difference then makes a
//! couple h/2 (F_t − F_b) through the face kinematics, and the vibration's
//! in-plane velocity turns the sliding direction (docs/scenes.md). The default
//! `mid_plane` is the paper's model described above.
//!
//! With `pads.mass` > 0 each face's pad is a rigid mass whose compression of
//! its springs is state (`pad_mass.rs`): u then comes from the pad's motion,
//! not from the balance above.
//!
//! Why the floating caliper is the default: with a fixed caliper and
//! lift-off, a face that lifts leaves the other one pressed harder —
//! N_t + N_b = k_c (δ₀ + |w|) once |w| > δ₀ — so friction, and the energy the
//! follower force feeds in, grow faster than the damping with amplitude and
//! squeal diverges instead of settling into a limit cycle
//! (docs/scenes.md). A force-controlled caliper keeps the total friction at
//! 2μN₀ per pad; lift-off then shifts the load to the contacts at the
//! extremes of the wave, where the surface slope and so the follower force
//! vanish, and the growth saturates — the limit cycles of the paper's Fig. 17.

use super::face_friction::{angular_slope, surface_and_face_kinematics, FaceKinematics};
use super::linear::{LinearContext, LinearOut, LinearStates, OperatingPoint};
use super::model::{
    contact_rate, surface_kinematics, CommandRule, CommandSpec, Coupling, LoadContext, LoadModel,
    ModelOut, Registration, SceneNodes, SurfaceKinematics,
};
use super::outputs::OutputContext;
use super::pad_config::{Caliper, ContactSurface, PadsConfig, PARAMETERS};
use super::pad_in_plane::PadInPlane;
use super::pad_patch::{PatchLaw, PatchSlot};
use crate::config::{Config, PlateTheory};
use crate::dynamics::contact_compliance::{ContactCompliance, HeldDeflection, SeriesScratch};
use crate::dynamics::joint::FrictionTorque;
use std::any::Any;

/// Sliding speed below which the friction direction is smoothed, m/s.
pub const FRICTION_REGULARISATION_SPEED: f64 = 1.0e-3;

/// One contact point: an ALE node and the pad it belongs to.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PadContactPoint {
    /// ALE node, 0-based.
    pub node: usize,
    /// Pad, 0-based.
    pub pad: usize,
    /// r of the node, m.
    pub radius: f64,
    /// θ of the node in the ALE frame, rad.
    pub angle: f64,
    /// (sin θ, cos θ).
    pub sin_cos: (f64, f64),
    /// z of the top and bottom face relative to the node frame's own z, m
    /// (the levers of the faces' friction with `pads.contact_surface: faces`).
    pub face_z: [f64; 2],
}

/// The pads of a scene: immutable parameters (commands are in `Inputs`).
#[derive(Debug, Clone, PartialEq)]
pub struct Pads {
    /// The contact points.
    pub contacts: Vec<PadContactPoint>,
    /// Contact points per pad.
    pub contacts_per_pad: Vec<usize>,
    /// k_c per contact point and face, N/m.
    pub stiffness: f64,
    /// c_c per contact point and face, N·s/m.
    pub damping: f64,
    /// Friction coefficient μ.
    pub friction_coefficient: f64,
    /// A face whose normal force would pull is released (N ≥ 0).
    pub lift_off: bool,
    /// Friction follows the deformed surface.
    pub follower_friction: bool,
    /// Fixed or floating caliper.
    pub caliper: Caliper,
    /// Where the pads act: faces or mid-plane.
    pub contact_surface: ContactSurface,
    /// μ_s − μ and v_S of the speed-dependent friction (faces only; 0: constant μ).
    pub friction_excess: f64,
    /// v_S, m/s.
    pub stribeck_speed: f64,
    /// Clamp force per pad the configuration starts with, N (the running
    /// commands are in `Inputs`).
    pub initial_clamp_force: Vec<f64>,
    /// The coupling bound of the contact springs and dampers ([`LoadModel::coupling`]).
    pub coupling: Coupling,
    /// T M⁻¹ Tᵀ of the bending tilt rows among the contact points, 2C × 2C
    /// (`pad_friction_damping.rs`; faces only, else empty).
    pub friction_gram: Vec<f64>,
    /// The residual compliance G among the contact points
    /// (`plate.residual_flexibility`): the contacts act in series with it
    /// (`Pads::series_forces`); None: on the modal deflection.
    pub series: Option<ContactCompliance>,
    /// m_p of each face's pad, kg (0: massless; `pad_mass.rs`).
    pub mass: f64,
    /// k_b behind a fixed caliper's massive pad, N/m (0 otherwise).
    pub backing_stiffness: f64,
    /// The lining's tangential patches (`pad_shear.rs`; None: rigid).
    pub shear: Option<PatchLaw>,
    /// The plate theory of the modes (`plate.theory`): under Mindlin theory a
    /// node's tilt is the rotation ψ of the normal, so the follower
    /// friction's normal part, (F_θ / r) ∂w/∂θ along the deformed surface,
    /// is taken from w ([`angular_slope`]), not from the tilt.
    pub theory: PlateTheory,
    /// The in-plane modes under the contacts (`pad_in_plane.rs`; None without).
    pub in_plane: Option<PadInPlane>,
}

/// Forces at one contact point.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct ContactForces {
    /// Normal force of the top (+z) pad, N (≥ 0 with lift-off).
    pub top: f64,
    /// Normal force of the bottom (−z) pad, N.
    pub bottom: f64,
    /// Net axial force on the disc, N_b − N_t, N.
    pub axial: f64,
    /// Friction along e_θ (negative for Ω > 0), N.
    pub tangential: f64,
    /// The top and bottom normal forces before lift-off, N (finite): the
    /// law's switching functions (> 0: the face is closed).
    pub margin: [f64; 2],
    /// The top and bottom faces' friction damping N max(g/s, |g′|), N·s/m,
    /// where an integrator asked for its bound (`pad_friction_damping.rs`).
    pub damping: [f64; 2],
}

impl Pads {
    /// The number of pads.
    pub fn pad_count(&self) -> usize {
        self.contacts_per_pad.len()
    }

    /// sign(Ω), regularised: tanh(Ω r / v_reg).
    pub fn sliding_sign(speed: f64, radius: f64) -> f64 {
        (speed * radius / FRICTION_REGULARISATION_SPEED).tanh()
    }

    /// g(V)/|V| with g = μ τ(|V|) (τ(s) = tanh(s/v_reg)), at the sliding
    /// speed |V| = `speed`: the radial friction's damping per unit normal
    /// force (the sliding direction's change, docs/scenes.md); μ/v_reg as
    /// V → 0.
    pub fn friction_per_speed(mu: f64, speed: f64) -> f64 {
        let x = speed / FRICTION_REGULARISATION_SPEED;
        if x < 1e-8 {
            mu / FRICTION_REGULARISATION_SPEED
        } else {
            mu * x.tanh() / speed
        }
    }

    /// The friction torque as a function of Ω at the contact forces `forces`:
    /// per contact τ = −μ (N_top + N_bottom) r · tanh(Ω r / v_reg).
    pub fn friction_torque_terms(&self, forces: &[ContactForces], out: &mut [FrictionTorque]) {
        for ((c, f), t) in self.contacts.iter().zip(forces).zip(out.iter_mut()) {
            *t = FrictionTorque {
                capacity: self.friction_coefficient * (f.top + f.bottom) * c.radius,
                slope: c.radius / FRICTION_REGULARISATION_SPEED,
            };
        }
    }
}

/// The pads' scratch: per contact point its surface kinematics and forces at
/// the last evaluation (what ~/pad_states reports).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct PadScratch {
    /// Per contact point, w and ∂w/∂t under it.
    pub kinematics: Vec<SurfaceKinematics>,
    /// The in-plane and normal sliding terms under each contact (faces only).
    pub faces: Vec<FaceKinematics>,
    /// Per contact point, its forces.
    pub forces: Vec<ContactForces>,
    pub(super) closed: Vec<bool>,
    /// The series solve's scratch (`pad_series.rs`): net axial forces, deflections without them, kinematics tried.
    pub(super) series: SeriesScratch,
    pub(super) axial: Vec<f64>,
    pub(super) w_free: Vec<f64>,
    pub(super) tried: Vec<SurfaceKinematics>,
    /// With `pads.shear_stiffness`: each face's speed relative to its patch, m/s.
    pub slip: Vec<[f64; 2]>,
}

/// The pads' one command: a clamp force per pad.
pub const CLAMP_FORCE: CommandSpec = CommandSpec {
    instance: "pad",
    name: "clamp force",
    token: "clamp_force",
    unit: "N",
    indexed: true,
    rule: CommandRule::NonNegativeForce,
};

/// The pads in the registry: their builder and outputs (`pad_outputs.rs`).
pub const REGISTRATION: Registration = Registration {
    build,
    outputs: &Pads::OUTPUTS,
    parameters: &PARAMETERS,
};

/// The registered builder: pads where `pads.*` gives contact points.
pub fn build(config: &Config, nodes: &SceneNodes) -> Option<Box<dyn LoadModel>> {
    let p = config.section::<PadsConfig>()?;
    let mut contacts_per_pad = vec![0; p.pad_count()];
    let contacts = p
        .contacts
        .iter()
        .map(|c| {
            contacts_per_pad[c.pad] += 1;
            let node = &nodes.ale[c.node];
            let h = config.plate.thickness;
            let face_z = [0.5 * h - node.z, -0.5 * h - node.z];
            PadContactPoint {
                node: c.node,
                pad: c.pad,
                radius: node.radius,
                angle: node.angle,
                sin_cos: node.angle.sin_cos(),
                face_z,
            }
        })
        .collect();
    Some(Box::new(
        Pads {
            contacts,
            contacts_per_pad,
            stiffness: p.contact_stiffness,
            damping: p.contact_damping,
            friction_coefficient: p.friction_coefficient,
            lift_off: p.lift_off,
            follower_friction: p.follower_friction,
            caliper: p.caliper,
            contact_surface: p.contact_surface,
            friction_excess: p
                .static_friction_coefficient
                .map_or(0.0, |s| s - p.friction_coefficient),
            stribeck_speed: p.stribeck_speed,
            initial_clamp_force: p.clamp_force.clone(),
            coupling: Coupling::default(),
            friction_gram: Vec::new(),
            series: nodes.residual.map(|r| {
                ContactCompliance::among(r, &p.contacts.iter().map(|c| c.node).collect::<Vec<_>>())
            }),
            mass: p.mass,
            backing_stiffness: p.backing_stiffness.unwrap_or(0.0),
            shear: p.shear.map(|(stiffness, damping)| PatchLaw {
                stiffness,
                damping,
                initial_speed: config.joint.speed,
            }),
            theory: config.plate.theory,
            in_plane: None,
        }
        .with_coupling(nodes)
        .with_friction_gram(nodes)
        .with_patch_coupling(),
    ))
}

impl Pads {
    /// The coupling bound with every contact closed and a fixed caliper
    /// (opening contacts or letting the pads float only removes stiffness).
    fn with_coupling(mut self, nodes: &SceneNodes) -> Pads {
        let shapes: Vec<&[crate::dynamics::node_frame::NodeShape]> = self
            .contacts
            .iter()
            .map(|c| nodes.ale[c.node].shapes.as_slice())
            .collect();
        if let Some(g) = &self.series {
            self.coupling = self.series_coupling(g, &shapes, nodes.modal_mass);
            return self;
        }
        let lam = contact_rate(&shapes, nodes.modal_mass);
        self.coupling = Coupling {
            stiffness_rate_sq: 2.0 * self.stiffness * lam,
            damping_rate: 2.0 * self.damping * lam,
            relaxation_rate: 0.0,
        };
        if self.is_massive() {
            self.coupling = self.massive_coupling(lam);
        }
        self
    }
}

impl LoadModel for Pads {
    fn name(&self) -> &'static str {
        "pads"
    }
    fn as_any(&self) -> &dyn Any {
        self
    }
    fn commands(&self) -> &[CommandSpec] {
        std::slice::from_ref(&CLAMP_FORCE)
    }
    fn instances(&self, _command: usize) -> usize {
        self.pad_count()
    }
    fn initial_commands(&self) -> Vec<f64> {
        self.initial_clamp_force.clone()
    }
    fn initial_state(&self) -> Vec<f64> {
        let mut slot = self.initial_pad_state();
        // The patches start at steady sliding, their states' origin (`pad_shear.rs`).
        slot.resize(self.pad_states() + self.patch_states(), 0.0);
        slot
    }
    fn continuous_states(&self) -> usize {
        self.pad_states() + self.patch_states()
    }
    fn new_scratch(&self) -> Box<dyn Any + Send + Sync> {
        let n = self.contacts.len();
        Box::new(PadScratch {
            kinematics: vec![SurfaceKinematics::default(); n],
            faces: vec![FaceKinematics::default(); n],
            forces: vec![ContactForces::default(); n],
            closed: vec![false; n],
            series: if self.series.is_some() {
                SeriesScratch::new(n, 2 * n)
            } else {
                SeriesScratch::default()
            },
            axial: vec![0.0; n],
            w_free: vec![0.0; n],
            tried: vec![SurfaceKinematics::default(); n],
            slip: vec![[0.0; 2]; n * self.shear.is_some() as usize],
        })
    }
    fn friction_terms(&self) -> usize {
        self.contacts.len()
    }
    fn switching_functions(&self) -> usize {
        if self.lift_off {
            2 * self.contacts.len()
        } else {
            0
        }
    }
    fn stage_dependent(&self) -> bool {
        true
    }
    /// Only the residual deflection of held normal forces is read at χ.
    fn reads_joint_angle(&self, ctx: &LoadContext) -> bool {
        self.series.is_some() && held_normal_forces(ctx).is_some()
    }
    fn coupling(&self) -> Coupling {
        self.coupling
    }
    fn held_damping_rate(&self, ctx: &LoadContext, scratch: &mut dyn Any) -> f64 {
        scratch
            .downcast_mut::<PadScratch>()
            .map_or(0.0, |s| self.friction_damping_rate(ctx.speed, s))
    }
    /// The contact springs act on w; the face kinematics (friction on the
    /// faces, the lining's patches) on the node frames' face displacement,
    /// z ψ under Mindlin theory (`face_friction.rs`); the follower friction's
    /// normal part on ∂w/∂θ. Residual flexibility, the only Kirchhoff-only
    /// term, is refused with the scene.
    fn takes_mindlin_modes(&self) -> bool {
        true
    }
    /// Friction on the faces does work on the in-plane modes, and their rate
    /// enters its sliding velocity (`pad_in_plane.rs`). At the mid-plane the
    /// friction −μN sign Ω e_θ does its work u_i·F through the node loads
    /// alone: its direction reads no sliding velocity.
    fn attach_in_plane(
        &mut self,
        ip: &crate::dynamics::in_plane::InPlaneDynamics,
    ) -> Result<(), crate::dynamics::error::SimulationError> {
        if self.contact_surface == ContactSurface::MidPlane {
            return Ok(());
        }
        let nodes = self.contacts.iter().map(|c| c.node);
        self.in_plane = Some(PadInPlane::attach(ip, nodes));
        Ok(())
    }
    fn channel_len(&self, channel: usize) -> usize {
        self.output_len(channel)
    }
    fn write_outputs(&self, at: &OutputContext, out: &mut [f64]) {
        self.write_output_values(at, out);
    }
    fn linear_states(&self) -> LinearStates {
        self.linear_state_count()
    }
    fn check_linear(&self) -> Result<(), crate::dynamics::error::SimulationError> {
        match (&self.shear, &self.in_plane) {
            (Some(_), Some(_)) => Err(crate::dynamics::error::SimulationError::InPlaneKeyNotWired {
                key: "pads.shear_stiffness",
                why: "the stability analysis linearises the lining's patches on the bending modes only",
            }),
            _ => Ok(()),
        }
    }
    fn add_linear_terms(&self, ctx: &LinearContext, out: LinearOut) {
        self.add_linear(ctx, out);
    }
    fn operating_point(&self) -> Option<OperatingPoint> {
        Some(self.configured_operating_point())
    }
    fn coupling_keys(&self) -> &'static str {
        match (self.is_massive(), self.shear.is_some()) {
            (true, true) => "pads.mass, pads.contact_stiffness, pads.contact_damping, pads.backing_stiffness, pads.shear_stiffness, pads.shear_damping",
            (true, false) => "pads.mass, pads.contact_stiffness, pads.contact_damping, pads.backing_stiffness",
            (false, true) => "pads.contact_stiffness, pads.contact_damping, pads.shear_stiffness, pads.shear_damping",
            (false, false) => "pads.contact_stiffness, pads.contact_damping",
        }
    }

    /// Contact forces from the deflection and its rate under each contact
    /// point (ALE amplitudes), their friction, and the wrenches at the nodes.
    fn evaluate(&self, ctx: &LoadContext, slot: &[f64], clamp_force: &[f64], out: ModelOut) {
        let s = out
            .scratch
            .downcast_mut::<PadScratch>()
            .expect("the pads' scratch");
        let faces = self.contact_surface == ContactSurface::Faces;
        for (ci, ((k, f), c)) in s.kinematics.iter_mut().zip(&mut s.faces).zip(&self.contacts).enumerate() {
            let node = &ctx.ale_nodes[c.node];
            if faces {
                (*k, *f) = surface_and_face_kinematics(node, ctx.q_ale, ctx.q_dot_ale, ctx.speed);
                if let Some(ip) = &self.in_plane {
                    f.in_plane_rate = ip.rate(ci, ctx.q_ale, ctx.q_dot_ale, ctx.speed);
                }
            } else {
                *k = surface_kinematics(node, ctx.q_ale, ctx.q_dot_ale);
            }
        }
        match &self.series {
            Some(g) => self.series_forces(g, ctx, clamp_force, slot, s),
            None if self.is_massive() => {
                self.massive_forces(slot, &s.kinematics, ctx.speed, &mut s.forces)
            }
            None => self.forces(
                clamp_force,
                &s.kinematics,
                ctx.speed,
                &mut s.forces,
                &mut s.closed,
            ),
        }
        if self.is_massive() {
            self.pad_rates(slot, clamp_force, &s.forces, out.rates);
        }
        if self.lift_off {
            for (m, f) in out.switching.chunks_exact_mut(2).zip(&s.forces) {
                m.copy_from_slice(&f.margin);
            }
        }
        // With patches the friction reaches the joint only through the
        // patches' forces in the node loads (`pad_shear.rs`); the rigid
        // law's implicit terms would stand for a force the faces do not carry.
        if self.shear.is_none() {
            self.friction_torque_terms(&s.forces, out.friction);
        }
        if faces {
            let patches = self.pad_states()..self.pad_states() + self.patch_states();
            let (mut x, mut rates) = (slot[patches.clone()].chunks_exact(4), out.rates[patches].chunks_exact_mut(4));
            for (ci, ((c, f), k)) in self
                .contacts
                .iter()
                .zip(s.forces.iter_mut())
                .zip(s.faces.iter())
                .enumerate()
            {
                let w = match (&self.shear, x.next(), rates.next()) {
                    (Some(law), Some(x), Some(r)) => {
                        let slot = PatchSlot {
                            x,
                            rates: r,
                            slip: &mut s.slip[ci],
                        };
                        self.patch_wrench(law, c, f, k, ctx.speed, slot)
                    }
                    _ => self.face_wrench(c, f, k, ctx.speed),
                };
                let slot = &mut out.ale[c.node];
                for a in 0..3 {
                    slot.force[a] += w.force[a];
                    slot.moment[a] += w.moment[a];
                }
                out.ale_follower[c.node] = false; // the normal part is in the sliding velocity
            }
            return;
        }
        // Mindlin node frames tilt by ψ: the follower's normal part from ∂w/∂θ here.
        let slope_from_w = self.follower_friction && self.theory == PlateTheory::Mindlin;
        for (c, f) in self.contacts.iter().zip(&s.forces) {
            let mut w = Pads::wrench(c, f);
            if slope_from_w {
                let node = &ctx.ale_nodes[c.node];
                w.force[2] += f.tangential * angular_slope(node, ctx.q_ale) / c.radius;
            }
            let slot = &mut out.ale[c.node];
            for a in 0..3 {
                slot.force[a] += w.force[a];
            }
            out.ale_follower[c.node] = self.follower_friction && !slope_from_w;
        }
    }
}

/// The residual deflection of the held wrenches when one of them has a
/// normal force (the only part the contacts read; then at the joint angle).
pub(super) fn held_normal_forces<'a>(ctx: &LoadContext<'a>) -> Option<HeldDeflection<'a>> {
    ctx.held
        .filter(|h| h.ale.iter().chain(h.lagrange).any(|w| w.force[2] != 0.0))
}

#[cfg(test)]
#[path = "pad_tests.rs"]
mod tests;
