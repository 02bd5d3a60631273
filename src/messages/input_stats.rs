//! What the node counts of its inputs: accepted per topic kind, refused per
//! reason. Shared by the node's input tasks, its loop, /diagnostics and the
//! offline recorder (which reports the same counters, all zero).

use crate::dynamics::InputError;
use std::sync::atomic::{AtomicU64, Ordering};

/// Why an input was refused.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum RejectReason {
    /// NaN or ±Inf somewhere.
    NonFinite,
    /// Beyond the `limits.*` plausibility limits.
    Absurd,
    /// A WrenchStamped whose frame_id is not its node's frame.
    UnknownFrame,
    /// A wrench for a node, or a clamp force for a pad, the scene does not have.
    NoSuchNode,
    /// A NodeWrenchArray with an unknown kind or a node named twice; a
    /// PadClampForces array with a pad named twice or arrays of different lengths.
    MalformedBatch,
    /// The sample could not be decoded (wrong type or truncated data).
    Undecodable,
}

impl RejectReason {
    /// Every reason, in the order /diagnostics lists them.
    pub const ALL: [RejectReason; 6] = [
        RejectReason::NonFinite,
        RejectReason::Absurd,
        RejectReason::UnknownFrame,
        RejectReason::NoSuchNode,
        RejectReason::MalformedBatch,
        RejectReason::Undecodable,
    ];

    /// The counter's name in /diagnostics: `rejected_<name>`.
    pub fn name(self) -> &'static str {
        match self {
            RejectReason::NonFinite => "non_finite",
            RejectReason::Absurd => "absurd",
            RejectReason::UnknownFrame => "unknown_frame",
            RejectReason::NoSuchNode => "no_such_node",
            RejectReason::MalformedBatch => "malformed_batch",
            RejectReason::Undecodable => "undecodable",
        }
    }

    pub(crate) fn index(self) -> usize {
        RejectReason::ALL
            .iter()
            .position(|r| *r == self)
            .unwrap_or(0)
    }

    /// The kind of an input refused by the dynamics' rules (a missing pad or
    /// tool counts as a missing node).
    pub fn of_input_error(e: &InputError) -> Self {
        match e {
            InputError::NonFinite { .. } | InputError::SpeedNotFinite { .. } => {
                RejectReason::NonFinite
            }
            InputError::Absurd { .. } | InputError::SpeedBeyondLimit { .. } => RejectReason::Absurd,
            InputError::NoSuchNode { .. }
            | InputError::NoSuchInstance { .. }
            | InputError::NoSuchModel { .. }
            | InputError::NoSuchLoadModel { .. }
            | InputError::NoSuchCommand { .. } => RejectReason::NoSuchNode,
        }
    }
}

/// Which topic an input came from (for counting).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Source {
    /// `~/speed_command` (Ω, rad/s).
    SpeedCommand,
    /// A node's wrench topic (`~/ale_<j>/wrench`, `~/lagrange_<j>/wrench`).
    NodeWrench,
    /// The batch of node wrenches (NodeWrenchArray).
    WrenchArray,
    /// One pad's clamp force (`~/pad_<j>/clamp_force`).
    PadClampForce,
    /// The batch of clamp forces (`~/pad_clamp_forces`).
    PadClampForces,
    /// The tool's feed rate (`~/tool_feed`).
    ToolFeed,
}

impl Source {
    /// Every source, in the order /diagnostics lists them.
    pub const ALL: [Source; 6] = [
        Source::SpeedCommand,
        Source::NodeWrench,
        Source::WrenchArray,
        Source::PadClampForce,
        Source::PadClampForces,
        Source::ToolFeed,
    ];

    /// The counter of a load-model command: numbered instances one at a time
    /// (`pad_clamp_force`), their batch (`pad_clamp_forces`), or a single
    /// instance's command (`tool_feed`).
    pub fn of_load_command(indexed: bool, batch: bool) -> Source {
        match (indexed, batch) {
            (true, false) => Source::PadClampForce,
            (true, true) => Source::PadClampForces,
            (false, _) => Source::ToolFeed,
        }
    }

    /// The counter's name in /diagnostics: `accepted_<name>`.
    pub fn name(self) -> &'static str {
        match self {
            Source::SpeedCommand => "speed_command",
            Source::NodeWrench => "node_wrench",
            Source::WrenchArray => "wrench_array",
            Source::PadClampForce => "pad_clamp_force",
            Source::PadClampForces => "pad_clamp_forces",
            Source::ToolFeed => "tool_feed",
        }
    }

    fn index(self) -> usize {
        Source::ALL.iter().position(|s| *s == self).unwrap_or(0)
    }
}

/// Counters shared by the subscriber tasks, the loop and /diagnostics.
#[derive(Debug, Default)]
pub struct InputStats {
    accepted: [AtomicU64; Source::ALL.len()],
    rejected: [AtomicU64; RejectReason::ALL.len()],
    expired: AtomicU64,
}

impl InputStats {
    /// Count an accepted input from `source`.
    pub fn accept(&self, source: Source) {
        self.accepted[source.index()].fetch_add(1, Ordering::Relaxed);
    }

    /// Count an input refused for `reason`.
    pub fn reject(&self, reason: RejectReason) {
        self.rejected[reason.index()].fetch_add(1, Ordering::Relaxed);
    }

    /// A held wrench dropped to zero by `ros.wrench_timeout`.
    pub fn expire(&self) {
        self.expired.fetch_add(1, Ordering::Relaxed);
    }

    /// Inputs accepted from `source` so far.
    pub fn accepted(&self, source: Source) -> u64 {
        self.accepted[source.index()].load(Ordering::Relaxed)
    }

    /// Inputs accepted from every source.
    pub fn accepted_total(&self) -> u64 {
        self.accepted
            .iter()
            .map(|a| a.load(Ordering::Relaxed))
            .sum()
    }

    /// Inputs refused for `reason` so far.
    pub fn rejected(&self, reason: RejectReason) -> u64 {
        self.rejected[reason.index()].load(Ordering::Relaxed)
    }

    /// Inputs refused for any reason.
    pub fn rejected_total(&self) -> u64 {
        self.rejected
            .iter()
            .map(|a| a.load(Ordering::Relaxed))
            .sum()
    }

    /// Held wrenches dropped to zero by `ros.wrench_timeout`.
    pub fn expired(&self) -> u64 {
        self.expired.load(Ordering::Relaxed)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn stats_count() {
        let s = InputStats::default();
        s.accept(Source::NodeWrench);
        s.accept(Source::NodeWrench);
        s.accept(Source::SpeedCommand);
        s.accept(Source::PadClampForce);
        s.reject(RejectReason::Absurd);
        s.reject(RejectReason::Undecodable);
        s.expire();
        assert_eq!(s.accepted(Source::NodeWrench), 2);
        assert_eq!(s.accepted(Source::PadClampForce), 1);
        assert_eq!(s.accepted(Source::ToolFeed), 0);
        assert_eq!(s.accepted_total(), 4);
        assert_eq!(s.rejected(RejectReason::Absurd), 1);
        assert_eq!(s.rejected_total(), 2);
        assert_eq!(s.expired(), 1);
    }
}
