//! The load models' last evaluation, kept with everything it was made of.
//!
//! A step evaluates the pads at its start (the drive's friction torque), at
//! the integrator's start and end, and the outputs read them once more at
//! the step's end: often at the same elastic state, speed and commands (the
//! joint angle apart, which the pads read only through held normal forces).
//! An evaluation whose inputs equal the last one's bit for bit is not made
//! again: the wrenches (and the models' scratch) in the one buffer are
//! already its result. Kept where a scene's models include one RK4
//! re-evaluates at every stage (pads, springs, links: short keys). Nothing of it is state: a fresh [`Stepper`](super::Stepper)
//! makes the same evaluation and gets the same bits.

use super::{load_context, Stepper};
use crate::dynamics::commands::Inputs;
use crate::dynamics::load_models::{
    LoadCommands, LoadContext, LoadModelState, LoadModels, ModelWrenches,
};
use crate::dynamics::scene::Scene;
use crate::dynamics::state::State;

/// The inputs of the evaluation in the buffer, as bit patterns.
#[derive(Debug, Clone, Default)]
pub(super) struct ModelEvaluation {
    /// The key of what `out` holds (empty: nothing known).
    key: Vec<u64>,
    /// The key being compared (scratch).
    next: Vec<u64>,
}

impl ModelEvaluation {
    /// Room for the keys of a scene: no allocation per step.
    pub fn with_capacity(n: usize) -> ModelEvaluation {
        ModelEvaluation {
            key: Vec::with_capacity(n),
            next: Vec::with_capacity(n),
        }
    }

    /// `out` ← the models' wrenches at `ctx`: evaluated, unless `out`
    /// already holds the evaluation of the same inputs.
    pub fn evaluate(
        &mut self,
        models: &LoadModels,
        ctx: &LoadContext,
        slots: &LoadModelState,
        commands: &LoadCommands,
        out: &mut ModelWrenches,
    ) {
        if !models.stage_dependent() {
            // Models with memory (the tool's machined surface) are evaluated
            // once a substep, each time at a new state: keys would cost alone.
            self.key.clear();
            return models.evaluate(ctx, slots, commands, out);
        }
        key_of(models, ctx, slots, commands, &mut self.next);
        if !self.key.is_empty() && self.key == self.next {
            return;
        }
        models.evaluate(ctx, slots, commands, out);
        std::mem::swap(&mut self.key, &mut self.next);
    }
}

impl Stepper {
    /// The load models' wrenches (and scratch, for their outputs) at
    /// `state`: its ALE description, χ, Ω and slots, under `inputs`.
    pub fn model_wrenches_at(
        &mut self,
        scene: &Scene,
        state: &State,
        inputs: &Inputs,
    ) -> &ModelWrenches {
        let ctx = load_context(scene, state, inputs);
        self.evaluation.evaluate(
            &scene.load_models,
            &ctx,
            &state.load_models,
            &inputs.commands,
            &mut self.model_wrenches,
        );
        &self.model_wrenches
    }

    /// The load models' wrenches and scratch of the last evaluation.
    pub fn model_wrenches(&self) -> &ModelWrenches {
        &self.model_wrenches
    }
}

/// The length of a key on `scene` (its capacity: no allocation per step).
pub(super) fn key_len(scene: &Scene) -> usize {
    let models = &scene.load_models;
    let commands: usize = models.initial_commands().values.iter().map(Vec::len).sum();
    let slots: usize = models.initial_state().slots.iter().map(Vec::len).sum();
    let nodes = scene.ale_nodes.len() + scene.lagrange_nodes.len();
    2 * scene.n_modes() + 6 * nodes + slots + commands + 2 * models.names().count() + 8
}

/// Everything an evaluation reads besides the scene's node frames: the ALE
/// amplitudes and rates, Ω, χ where a model reads it, the held wrenches
/// where the residual deflection enters, the models' slots and commands;
/// the node frames by address.
fn key_of(
    models: &LoadModels,
    ctx: &LoadContext,
    slots: &LoadModelState,
    commands: &LoadCommands,
    key: &mut Vec<u64>,
) {
    key.clear();
    key.push(ctx.ale_nodes.as_ptr() as u64);
    key.push(ctx.lagrange_nodes.as_ptr() as u64);
    key.push(ctx.q_ale.len() as u64);
    key.extend(ctx.q_ale.iter().chain(ctx.q_dot_ale).map(|v| v.to_bits()));
    key.push(ctx.speed.to_bits());
    // χ's bits when read, else a NaN pattern no angle in [0, 2π) has.
    key.push(if models.reads_joint_angle(ctx) {
        ctx.chi.to_bits()
    } else {
        u64::MAX
    });
    match &ctx.held {
        Some(h) => {
            key.push(1);
            for w in h.ale.iter().chain(h.lagrange) {
                key.extend(w.force.iter().chain(&w.moment).map(|v| v.to_bits()));
            }
        }
        None => key.push(0),
    }
    for (slot, c) in slots.slots.iter().zip(&commands.values) {
        key.push(slot.len() as u64);
        key.extend(slot.iter().map(|v| v.to_bits()));
        key.push(c.len() as u64);
        key.extend(c.iter().map(|v| v.to_bits()));
    }
}
