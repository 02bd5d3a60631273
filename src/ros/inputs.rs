//! Checking and counting what arrives on the input topics, before anything
//! may reach the simulation. No ROS types: the subscriber tasks hand over
//! plain values, so all of this is unit-tested without DDS.
//!
//! The rules themselves are the dynamics' (`dynamics::commands`, docs/ros.md
//! "Bad input"): each message is converted once to `Command`s and checked
//! there; this file adds only what is ROS's own:
//! - a WrenchStamped's `header.frame_id` is empty or the frame of the
//!   topic's node (`<prefix>plate_ale_<j>`); anything else is an unknown frame;
//! - array messages number nodes and pads from 1 and name a node kind by a
//!   byte (NodeWrench.ALE / LAGRANGE); a NodeWrenchArray or PadClampForces is
//!   checked whole and applied whole or not at all (`check_batch`);
//! - a sample that cannot be decoded is counted as undecodable.
//!
//! A rejected input changes nothing; it is counted (visible in
//! /diagnostics) and logged at most once per `ros.reject_log_period` per kind.

use crate::dynamics::{
    check, check_batch, BatchError, Checked, CheckedBatch, Command, InputError, InputRules,
    NodeKind, Wrench,
};
pub use crate::messages::input_stats::{InputStats, RejectReason, Source};
use std::sync::Mutex;
use std::time::{Duration, Instant};

/// An input refused, with a sentence for the log.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Rejection {
    pub reason: RejectReason,
    pub detail: String,
}

impl Rejection {
    fn new(reason: RejectReason, detail: impl Into<String>) -> Self {
        Rejection {
            reason,
            detail: detail.into(),
        }
    }

    pub fn from_input_error(e: InputError) -> Self {
        Rejection::new(RejectReason::of_input_error(&e), e.to_string())
    }
}

/// A checked input, ready for the simulation: it is applied without another check.
#[derive(Debug, Clone, PartialEq)]
pub enum Input {
    /// One command.
    One(Checked),
    /// Applied whole.
    Batch(CheckedBatch),
}

/// `NodeWrench.kind` values of msg/NodeWrench.msg.
pub(crate) const KIND_ALE: u8 = 0;
pub(crate) const KIND_LAGRANGE: u8 = 1;

/// Converts input messages to checked commands: the scene's rules plus the
/// node frames' names.
#[derive(Debug, Clone)]
pub(crate) struct InputValidator {
    ale_frames: Vec<String>,
    lagrange_frames: Vec<String>,
    rules: InputRules,
}

impl InputValidator {
    /// `ale_frames[j]` / `lagrange_frames[j]`: the frame id of node j + 1.
    pub fn new(ale_frames: Vec<String>, lagrange_frames: Vec<String>, rules: InputRules) -> Self {
        InputValidator {
            ale_frames,
            lagrange_frames,
            rules,
        }
    }

    fn frames(&self, kind: NodeKind) -> &[String] {
        match kind {
            NodeKind::Ale => &self.ale_frames,
            NodeKind::Lagrange => &self.lagrange_frames,
        }
    }

    fn one(&self, command: Command) -> Result<Input, Rejection> {
        check(&self.rules, command)
            .map(Input::One)
            .map_err(Rejection::from_input_error)
    }

    pub fn speed(&self, omega: f64) -> Result<Input, Rejection> {
        self.one(Command::Speed(omega))
    }

    /// A WrenchStamped on the topic of node `node` (0-based).
    pub fn wrench_stamped(
        &self,
        kind: NodeKind,
        node: usize,
        frame_id: &str,
        wrench: Wrench,
    ) -> Result<Input, Rejection> {
        if let Some(expected) = self.frames(kind).get(node) {
            if !frame_id.is_empty() && frame_id != expected {
                return Err(Rejection::new(
                    RejectReason::UnknownFrame,
                    format!(
                        "{}_{} wrench has frame_id `{frame_id}`; it must be empty or `{expected}` (the wrench is expressed in the node's own frame)",
                        kind.name(),
                        node + 1
                    ),
                ));
            }
        }
        self.one(Command::Wrench { kind, node, wrench })
    }

    /// A NodeWrenchArray: (kind, 1-based index, wrench) per element.
    pub fn batch(
        &self,
        entries: impl IntoIterator<Item = (u8, u32, Wrench)>,
    ) -> Result<Input, Rejection> {
        let mut commands = Vec::new();
        for (position, (kind, index, wrench)) in entries.into_iter().enumerate() {
            let kind = match kind {
                KIND_ALE => NodeKind::Ale,
                KIND_LAGRANGE => NodeKind::Lagrange,
                other => {
                    return Err(Rejection::new(
                        RejectReason::MalformedBatch,
                        format!("wrenches[{position}].kind = {other} is neither ALE (0) nor LAGRANGE (1); the array was not applied"),
                    ))
                }
            };
            if index == 0 {
                return Err(Rejection::new(
                    RejectReason::NoSuchNode,
                    format!("wrenches[{position}].index = 0, but node numbers start at 1; the array was not applied"),
                ));
            }
            commands.push(Command::Wrench {
                kind,
                node: index as usize - 1,
                wrench,
            });
        }
        check_batch(&self.rules, commands.iter().copied())
            .map(Input::Batch)
            .map_err(|e| {
                batch_rejection(e, "wrenches", |position| match commands[position] {
                    Command::Wrench { kind, node, .. } => format!(
                        "wrenches[{position}] names {}_{} a second time",
                        kind.name(),
                        node + 1
                    ),
                    _ => unreachable!("a wrench array holds wrenches"),
                })
            })
    }

    /// Command `command` of load model `model` for instance `instance` (0-based).
    pub fn load_command(
        &self,
        model: usize,
        command: usize,
        instance: usize,
        value: f64,
    ) -> Result<Input, Rejection> {
        self.one(Command::Load {
            model,
            command,
            instance,
            value,
        })
    }

    /// A batch of one indexed load-model command: instance numbers (from 1)
    /// and their values (a PadClampForces message), applied whole or not at all.
    pub fn load_batch(
        &self,
        model: usize,
        command: usize,
        numbers: &[u32],
        values: &[f64],
    ) -> Result<Input, Rejection> {
        let instance = self
            .rules
            .load_commands()
            .find(|c| c.0 == model && c.1 == command)
            .map_or("entry", |c| c.2.instance);
        if numbers.len() != values.len() {
            return Err(Rejection::new(
                RejectReason::MalformedBatch,
                format!(
                    "{instance} has {} entries but the values {}; the array was not applied",
                    numbers.len(),
                    values.len()
                ),
            ));
        }
        if let Some(position) = numbers.iter().position(|&p| p == 0) {
            return Err(Rejection::new(
                RejectReason::NoSuchNode,
                format!("{instance}[{position}] = 0, but {instance} numbers start at 1; the array was not applied"),
            ));
        }
        let commands = numbers
            .iter()
            .zip(values)
            .map(|(&n, &value)| Command::Load {
                model,
                command,
                instance: n as usize - 1,
                value,
            });
        check_batch(&self.rules, commands)
            .map(Input::Batch)
            .map_err(|e| {
                batch_rejection(e, "entry", |position| {
                    format!(
                        "{instance}[{position}] names {instance} {} a second time",
                        numbers[position]
                    )
                })
            })
    }
}

/// The rejection of a refused batch: `what[position]: why` (or `entry position: why`),
/// or the duplicate's own sentence; "the array was not applied".
fn batch_rejection(e: BatchError, what: &str, duplicate: impl Fn(usize) -> String) -> Rejection {
    match e {
        BatchError::Invalid { position, error } => {
            let place = if what == "entry" {
                format!("entry {position}")
            } else {
                format!("{what}[{position}]")
            };
            let r = Rejection::from_input_error(error);
            Rejection {
                detail: format!("{place}: {}; the array was not applied", r.detail),
                ..r
            }
        }
        BatchError::Duplicate { position, .. } => Rejection::new(
            RejectReason::MalformedBatch,
            format!("{}; the array was not applied", duplicate(position)),
        ),
    }
}

/// At most one log line per reason per period; the next line says how many
/// were suppressed in between.
#[derive(Debug)]
pub(crate) struct RateLimiter {
    period: Duration,
    state: Mutex<[(Option<Instant>, u64); RejectReason::ALL.len()]>,
}

impl RateLimiter {
    pub fn new(period: Duration) -> Self {
        RateLimiter {
            period,
            state: Mutex::new([(None, 0); RejectReason::ALL.len()]),
        }
    }

    /// `Some(suppressed since the last line)` when a line may be written now.
    pub fn permit(&self, reason: RejectReason, now: Instant) -> Option<u64> {
        let mut state = self.state.lock().unwrap_or_else(|e| e.into_inner());
        let (last, suppressed) = &mut state[reason.index()];
        match last {
            Some(t) if now.duration_since(*t) < self.period => {
                *suppressed += 1;
                None
            }
            _ => {
                *last = Some(now);
                Some(std::mem::take(suppressed))
            }
        }
    }
}

/// Drops held wrenches that were not renewed within `ros.wrench_timeout` of
/// simulated time. Indexed by node; allocation only at construction.
#[derive(Debug, Clone)]
pub struct StaleWrenches {
    timeout: f64,
    ale: Vec<Option<f64>>,
    lagrange: Vec<Option<f64>>,
}

impl StaleWrenches {
    /// `timeout` in s; 0 disables.
    pub fn new(timeout: f64, n_ale: usize, n_lagrange: usize) -> Self {
        StaleWrenches {
            timeout,
            ale: vec![None; n_ale],
            lagrange: vec![None; n_lagrange],
        }
    }

    fn slots(&mut self, kind: NodeKind) -> &mut Vec<Option<f64>> {
        match kind {
            NodeKind::Ale => &mut self.ale,
            NodeKind::Lagrange => &mut self.lagrange,
        }
    }

    /// Change the timeout (0 disables).
    pub fn set_timeout(&mut self, timeout: f64) {
        self.timeout = timeout;
    }

    /// A wrench was set at simulated time `t`.
    pub fn touched(&mut self, kind: NodeKind, node: usize, t: f64) {
        if let Some(slot) = self.slots(kind).get_mut(node) {
            *slot = Some(t);
        }
    }

    /// Forget every set time (after a reset: the file's loads are held again).
    pub fn clear(&mut self) {
        self.ale
            .iter_mut()
            .chain(self.lagrange.iter_mut())
            .for_each(|s| *s = None);
    }

    /// Call `expire(kind, node)` for each wrench older than the timeout at
    /// time `t` and forget it.
    pub fn expire(&mut self, t: f64, mut expire: impl FnMut(NodeKind, usize)) {
        if self.timeout <= 0.0 {
            return;
        }
        for (kind, slots) in [
            (NodeKind::Ale, &mut self.ale),
            (NodeKind::Lagrange, &mut self.lagrange),
        ] {
            for (node, slot) in slots.iter_mut().enumerate() {
                if let Some(set_at) = *slot {
                    // A small tolerance keeps "timeout = k steps" exact in floating point.
                    if t - set_at >= self.timeout - 1e-9 {
                        *slot = None;
                        expire(kind, node);
                    }
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    use crate::config::LimitsConfig;
    use crate::dynamics::load_models::{pad::CLAMP_FORCE, tool::FEED_RATE};

    fn rules(pads: usize, tool: bool) -> InputRules {
        let limits = LimitsConfig {
            max_force: 1e4,
            max_moment: 1e3,
            max_speed: 500.0,
            ..LimitsConfig::default()
        };
        let pad_commands = [(CLAMP_FORCE, pads)];
        let tool_commands = [(FEED_RATE, 1)];
        let mut models: Vec<(&'static str, &[_])> = Vec::new();
        if pads > 0 {
            models.push(("pads", &pad_commands));
        }
        if tool {
            models.push(("tool", &tool_commands));
        }
        InputRules::from_parts(&limits, 2, 1, &models)
    }

    fn validator_with(pads: usize, tool: bool) -> InputValidator {
        InputValidator::new(
            vec!["plate_ale_1".into(), "plate_ale_2".into()],
            vec!["plate_lagrange_1".into()],
            rules(pads, tool),
        )
    }

    fn validator() -> InputValidator {
        validator_with(0, false)
    }

    /// The commands a checked input holds (0-based indices).
    fn cmds(r: Result<Input, Rejection>) -> Result<Vec<Command>, Rejection> {
        r.map(|i| match i {
            Input::One(c) => vec![c.command()],
            Input::Batch(b) => b.iter().map(|c| c.command()).collect(),
        })
    }

    /// The index of the model named `name` in the scene's rules (what the
    /// node's subscriptions carry with each topic).
    fn model(v: &InputValidator, name: &str) -> usize {
        v.rules.model(name).expect("the scene has the model").0
    }

    fn w(fz: f64) -> Wrench {
        Wrench {
            force: [0.0, 0.0, fz],
            moment: [0.0; 3],
        }
    }

    #[test]
    fn speed_rules() {
        let v = validator();
        assert_eq!(cmds(v.speed(25.0)), Ok(vec![Command::Speed(25.0)]));
        assert_eq!(cmds(v.speed(-500.0)), Ok(vec![Command::Speed(-500.0)]));
        assert_eq!(
            v.speed(f64::NAN).unwrap_err().reason,
            RejectReason::NonFinite
        );
        assert_eq!(
            v.speed(f64::INFINITY).unwrap_err().reason,
            RejectReason::NonFinite
        );
        assert_eq!(v.speed(501.0).unwrap_err().reason, RejectReason::Absurd);
    }

    #[test]
    fn wrench_stamped_rules() {
        let v = validator();
        assert!(v.wrench_stamped(NodeKind::Ale, 0, "", w(-100.0)).is_ok());
        assert!(v
            .wrench_stamped(NodeKind::Ale, 1, "plate_ale_2", w(-100.0))
            .is_ok());
        assert_eq!(
            v.wrench_stamped(NodeKind::Ale, 0, "plate_ale_2", w(1.0))
                .unwrap_err()
                .reason,
            RejectReason::UnknownFrame
        );
        assert_eq!(
            v.wrench_stamped(NodeKind::Ale, 0, "map", w(1.0))
                .unwrap_err()
                .reason,
            RejectReason::UnknownFrame
        );
        assert_eq!(
            v.wrench_stamped(NodeKind::Ale, 0, "", w(f64::NAN))
                .unwrap_err()
                .reason,
            RejectReason::NonFinite
        );
        assert_eq!(
            v.wrench_stamped(NodeKind::Ale, 0, "", w(2e4))
                .unwrap_err()
                .reason,
            RejectReason::Absurd
        );
        let moment = Wrench {
            force: [0.0; 3],
            moment: [2e3, 0.0, 0.0],
        };
        assert_eq!(
            v.wrench_stamped(NodeKind::Lagrange, 0, "", moment)
                .unwrap_err()
                .reason,
            RejectReason::Absurd
        );
        assert_eq!(
            v.wrench_stamped(NodeKind::Lagrange, 1, "", w(1.0))
                .unwrap_err()
                .reason,
            RejectReason::NoSuchNode
        );
    }

    #[test]
    fn batch_is_all_or_nothing() {
        let v = validator();
        let ok = cmds(v.batch([
            (KIND_ALE, 1, w(-10.0)),
            (KIND_ALE, 2, w(-20.0)),
            (KIND_LAGRANGE, 1, w(5.0)),
        ]))
        .unwrap();
        let wrench = |kind, node, wrench| Command::Wrench { kind, node, wrench };
        assert_eq!(
            ok,
            vec![
                wrench(NodeKind::Ale, 0, w(-10.0)),
                wrench(NodeKind::Ale, 1, w(-20.0)),
                wrench(NodeKind::Lagrange, 0, w(5.0))
            ]
        );
        assert_eq!(cmds(v.batch([])), Ok(vec![]));
        let reason = |entries: Vec<(u8, u32, Wrench)>| v.batch(entries).unwrap_err().reason;
        assert_eq!(
            reason(vec![(KIND_ALE, 1, w(1.0)), (7, 1, w(1.0))]),
            RejectReason::MalformedBatch
        );
        assert_eq!(
            reason(vec![(KIND_ALE, 1, w(1.0)), (KIND_ALE, 1, w(2.0))]),
            RejectReason::MalformedBatch
        );
        assert_eq!(
            reason(vec![(KIND_ALE, 0, w(1.0))]),
            RejectReason::NoSuchNode
        );
        assert_eq!(
            reason(vec![(KIND_ALE, 3, w(1.0))]),
            RejectReason::NoSuchNode
        );
        assert_eq!(
            reason(vec![
                (KIND_ALE, 1, w(1.0)),
                (KIND_LAGRANGE, 1, w(f64::NEG_INFINITY))
            ]),
            RejectReason::NonFinite
        );
        let e = v
            .batch([(KIND_ALE, 2, w(1.0)), (KIND_ALE, 3, w(1.0))])
            .unwrap_err();
        assert!(
            e.detail.contains("wrenches[1]") && e.detail.contains("not applied"),
            "{}",
            e.detail
        );
    }

    #[test]
    fn load_model_commands_follow_the_dynamics_rules() {
        let v = validator_with(2, false);
        let pads = model(&v, "pads");
        let clamp_force = |pad, newtons| v.load_command(pads, 0, pad, newtons);
        let clamp = |instance, value| {
            Ok(vec![Command::Load {
                model: 0,
                command: 0,
                instance,
                value,
            }])
        };
        assert_eq!(cmds(clamp_force(1, 5000.0)), clamp(1, 5000.0));
        assert_eq!(cmds(clamp_force(0, 0.0)), clamp(0, 0.0));
        assert_eq!(
            cmds(clamp_force(0, 1e4)),
            clamp(0, 1e4),
            "limits.max_force itself is allowed"
        );
        let reason = |r: Result<Input, Rejection>| r.unwrap_err().reason;
        assert_eq!(reason(clamp_force(0, f64::NAN)), RejectReason::NonFinite);
        assert_eq!(
            reason(clamp_force(0, f64::NEG_INFINITY)),
            RejectReason::NonFinite
        );
        assert_eq!(reason(clamp_force(0, -1.0)), RejectReason::Absurd);
        assert_eq!(reason(clamp_force(0, 1.5e4)), RejectReason::Absurd);
        assert_eq!(reason(clamp_force(2, 1.0)), RejectReason::NoSuchNode);
        let e = clamp_force(0, -1.0).unwrap_err();
        assert!(e.detail.contains("pad_1 clamp force"), "{}", e.detail);
        // The tool's feed rate, by the same path.
        let t = validator_with(0, true);
        let tool = model(&t, "tool");
        let tool_feed = |rate| t.load_command(tool, 0, 0, rate);
        assert_eq!(
            cmds(tool_feed(-2e-3)),
            Ok(vec![Command::Load {
                model: 0,
                command: 0,
                instance: 0,
                value: -2e-3
            }])
        );
        assert_eq!(reason(tool_feed(f64::NAN)), RejectReason::NonFinite);
        assert_eq!(reason(tool_feed(1.5)), RejectReason::Absurd);
    }

    #[test]
    fn clamp_force_arrays_are_all_or_nothing() {
        let v = validator_with(2, false);
        let pads = model(&v, "pads");
        let clamp_forces = |p: &[u32], f: &[f64]| v.load_batch(pads, 0, p, f);
        let clamp = |instance, value| Command::Load {
            model: 0,
            command: 0,
            instance,
            value,
        };
        assert_eq!(
            cmds(clamp_forces(&[2, 1], &[10.0, 20.0])),
            Ok(vec![clamp(1, 10.0), clamp(0, 20.0)])
        );
        assert_eq!(cmds(clamp_forces(&[], &[])), Ok(vec![]));
        let reason = |p: &[u32], f: &[f64]| clamp_forces(p, f).unwrap_err().reason;
        assert_eq!(reason(&[1], &[1.0, 2.0]), RejectReason::MalformedBatch);
        assert_eq!(reason(&[1, 1], &[1.0, 2.0]), RejectReason::MalformedBatch);
        assert_eq!(reason(&[0], &[1.0]), RejectReason::NoSuchNode);
        assert_eq!(reason(&[1, 3], &[1.0, 1.0]), RejectReason::NoSuchNode);
        assert_eq!(reason(&[1, 2], &[1.0, f64::NAN]), RejectReason::NonFinite);
        assert_eq!(reason(&[1, 2], &[1.0, -5.0]), RejectReason::Absurd);
        let e = clamp_forces(&[1, 2], &[1.0, 2e4]).unwrap_err();
        assert!(
            e.detail.contains("entry 1") && e.detail.contains("not applied"),
            "{}",
            e.detail
        );
    }

    #[test]
    fn rate_limiter_suppresses_and_reports() {
        let r = RateLimiter::new(Duration::from_secs(1));
        let t0 = Instant::now();
        assert_eq!(r.permit(RejectReason::NonFinite, t0), Some(0));
        assert_eq!(
            r.permit(RejectReason::NonFinite, t0 + Duration::from_millis(10)),
            None
        );
        assert_eq!(
            r.permit(RejectReason::NonFinite, t0 + Duration::from_millis(20)),
            None
        );
        // Other reasons have their own budget.
        assert_eq!(
            r.permit(RejectReason::Absurd, t0 + Duration::from_millis(20)),
            Some(0)
        );
        assert_eq!(
            r.permit(RejectReason::NonFinite, t0 + Duration::from_millis(1001)),
            Some(2)
        );
    }

    #[test]
    fn stale_wrenches_expire_after_timeout() {
        let mut s = StaleWrenches::new(0.01, 2, 1);
        s.touched(NodeKind::Ale, 1, 0.0);
        s.touched(NodeKind::Lagrange, 0, 0.005);
        let mut expired = vec![];
        s.expire(0.009, |k, n| expired.push((k, n)));
        assert!(expired.is_empty());
        s.expire(0.010, |k, n| expired.push((k, n)));
        assert_eq!(expired, vec![(NodeKind::Ale, 1)]);
        s.expire(0.015, |k, n| expired.push((k, n)));
        assert_eq!(expired, vec![(NodeKind::Ale, 1), (NodeKind::Lagrange, 0)]);
        // Once expired, nothing more.
        s.expire(1.0, |k, n| expired.push((k, n)));
        assert_eq!(expired.len(), 2);
        // Disabled.
        let mut off = StaleWrenches::new(0.0, 1, 0);
        off.touched(NodeKind::Ale, 0, 0.0);
        off.expire(100.0, |_, _| panic!("disabled"));
    }
}
