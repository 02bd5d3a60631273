//! Undoing one step's changes to the load models' slots without copying them
//! whole: a step that produces a non-finite or implausible state is undone
//! (the stepper's divergence guard), and the tool's slot carries a 4096-bin
//! surface (33 kB) of which a step changes a few bins.
//!
//! Per model, `LoadModel::undo_head` says how much of the slot is copied
//! before the step (by default all of it); the entries beyond that head change
//! only in `LoadModel::commit_substep`, and before each commit the model
//! saves the ones it is about to change (`LoadModel::save_changes` →
//! [`SlotUndo::save`]): each entry once per step, with its value from before
//! the step. Undoing writes the head and the saved entries back. Buffers are
//! sized once (an entry is saved at most once per step, so the log never
//! outgrows the slot): no allocation per step.

use super::{LoadModelState, LoadModels};

/// The undo record of one model's slot over one step.
#[derive(Debug, Default)]
pub struct SlotUndo {
    /// The slot's first [`LoadModel::undo_head`](super::LoadModel::undo_head) entries before the step.
    head: Vec<f64>,
    /// (index, value before the step) of every entry beyond the head the step changed.
    saved: Vec<(usize, f64)>,
    /// Whether the entry is in `saved` already.
    marked: Vec<bool>,
}

impl SlotUndo {
    fn with_capacity(len: usize, head: usize) -> SlotUndo {
        SlotUndo {
            head: Vec::with_capacity(head),
            saved: Vec::with_capacity(len.saturating_sub(head)),
            marked: vec![false; len],
        }
    }

    /// Save `slot[index]` (beyond the head) before the step's first change of it.
    #[inline]
    pub fn save(&mut self, slot: &[f64], index: usize) {
        if index >= self.marked.len() {
            self.marked.resize(slot.len(), false);
        }
        if !self.marked[index] {
            self.marked[index] = true;
            self.saved.push((index, slot[index]));
        }
    }

    /// Entries beyond the head saved in this step.
    pub fn saved(&self) -> usize {
        self.saved.len()
    }

    fn clear_log(&mut self) {
        for &(i, _) in &self.saved {
            self.marked[i] = false;
        }
        self.saved.clear();
    }

    fn begin(&mut self, slot: &[f64], head: usize) {
        self.clear_log();
        self.head.clear();
        self.head.extend_from_slice(&slot[..head.min(slot.len())]);
    }

    fn restore(&mut self, slot: &mut [f64]) {
        slot[..self.head.len()].copy_from_slice(&self.head);
        for &(i, v) in &self.saved {
            slot[i] = v;
        }
        self.clear_log();
    }
}

/// The undo records of all load models over one step (stepper scratch).
#[derive(Debug, Default)]
pub struct LoadModelUndo {
    slots: Vec<SlotUndo>,
}

impl LoadModelUndo {
    /// Buffers for the slots of `models` (sized from their initial state).
    pub fn new(models: &LoadModels) -> LoadModelUndo {
        let initial = models.initial_state();
        let slots = models
            .models()
            .iter()
            .zip(&initial.slots)
            .map(|(m, s)| SlotUndo::with_capacity(s.len(), m.undo_head(s.len())))
            .collect();
        LoadModelUndo { slots }
    }

    /// Before a step: copy the heads, start empty logs.
    pub fn begin(&mut self, models: &LoadModels, state: &LoadModelState) {
        if self.slots.len() != state.slots.len() {
            self.slots.resize_with(state.slots.len(), SlotUndo::default);
        }
        for ((u, m), slot) in self.slots.iter_mut().zip(models.models()).zip(&state.slots) {
            u.begin(slot, m.undo_head(slot.len()));
        }
    }

    /// The record of model `index`.
    pub fn slot(&mut self, index: usize) -> &mut SlotUndo {
        &mut self.slots[index]
    }

    /// Put `state` back to what it was at [`LoadModelUndo::begin`].
    pub fn restore(&mut self, state: &mut LoadModelState) {
        for (u, slot) in self.slots.iter_mut().zip(state.slots.iter_mut()) {
            u.restore(slot);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn restore_writes_back_the_head_and_the_first_value_of_each_saved_entry() {
        let mut slot = vec![1.0, 2.0, 10.0, 11.0, 12.0];
        let mut u = SlotUndo::with_capacity(slot.len(), 2);
        for round in 0..2 {
            u.begin(&slot, 2);
            slot[0] = -1.0;
            u.save(&slot, 3);
            slot[3] = 5.0;
            u.save(&slot, 3); // changed twice in one step: the value before the step is kept
            slot[3] = 4.0;
            u.save(&slot, 4);
            slot[4] = f64::NAN;
            assert_eq!(u.saved(), 2, "round {round}");
            u.restore(&mut slot);
            assert_eq!(slot, vec![1.0, 2.0, 10.0, 11.0, 12.0], "round {round}");
            assert_eq!(u.saved(), 0);
        }
    }
}
