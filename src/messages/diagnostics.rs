//! The `/diagnostics` message: built here, from plain values, by the node's
//! loop (`sim_loop.rs`) and by the offline recorder of `simulate --bag`
//! (`bag/offline.rs`), so both put the same statuses in the same shape.
//!
//! Statuses (docs/ros.md, "Diagnostics"): `<node>: simulation`,
//! `<node>: inputs`, and `<node>: recording` while a bag is recorded.

use super::input_stats::{InputStats, RejectReason, Source};
use super::types::{DiagnosticArray, DiagnosticStatus, Header, KeyValue, Time};
use std::time::{Duration, Instant};

/// Step timing statistics between two diagnostics messages.
#[derive(Debug)]
pub struct Timing {
    /// |actual period − nominal| of consecutive paced steps, µs.
    period_dev_us: Vec<f32>,
    /// Start of a paced step after its deadline, µs.
    late_us: Vec<f32>,
    /// Step + publish time, µs.
    work_us_sum: f64,
    work_us_max: f64,
    steps: u64,
    last_start: Option<Instant>,
    since: Instant,
}

const TIMING_CAPACITY: usize = 1 << 15;

impl Timing {
    pub fn new(now: Instant) -> Self {
        Timing {
            period_dev_us: Vec::with_capacity(TIMING_CAPACITY),
            late_us: Vec::with_capacity(TIMING_CAPACITY),
            work_us_sum: 0.0,
            work_us_max: 0.0,
            steps: 0,
            last_start: None,
            since: now,
        }
    }

    /// A step that started at `start` and took `work`; `deadline` and
    /// `nominal` period when paced.
    pub fn record(
        &mut self,
        start: Instant,
        deadline: Option<Instant>,
        nominal: Option<Duration>,
        work: Duration,
    ) {
        let us = work.as_secs_f64() * 1e6;
        self.work_us_sum += us;
        self.work_us_max = self.work_us_max.max(us);
        self.steps += 1;
        if let (Some(deadline), Some(nominal)) = (deadline, nominal) {
            if self.late_us.len() < TIMING_CAPACITY {
                self.late_us
                    .push(start.saturating_duration_since(deadline).as_secs_f32() * 1e6);
            }
            if let Some(last) = self.last_start {
                if self.period_dev_us.len() < TIMING_CAPACITY {
                    let period = start.duration_since(last).as_secs_f64();
                    self.period_dev_us
                        .push(((period - nominal.as_secs_f64()).abs() * 1e6) as f32);
                }
            }
            self.last_start = Some(start);
        } else {
            self.last_start = None;
        }
    }

    /// Not paced right now (paused or stepping on request): the next paced
    /// step starts a new period measurement.
    pub fn interrupt(&mut self) {
        self.last_start = None;
    }

    fn percentile(v: &mut [f32], p: f64) -> f64 {
        if v.is_empty() {
            return 0.0;
        }
        v.sort_unstable_by(|a, b| a.total_cmp(b));
        let i = ((v.len() - 1) as f64 * p).round() as usize;
        v[i] as f64
    }

    /// (key, value) pairs and reset for the next period.
    pub fn report(&mut self, now: Instant) -> Vec<(String, String)> {
        let wall = now.duration_since(self.since).as_secs_f64();
        let out = vec![
            ("steps_in_period".into(), self.steps.to_string()),
            (
                "achieved_rate_hz".into(),
                format!(
                    "{:.1}",
                    if wall > 0.0 {
                        self.steps as f64 / wall
                    } else {
                        0.0
                    }
                ),
            ),
            (
                "step_time_mean_us".into(),
                format!(
                    "{:.1}",
                    if self.steps > 0 {
                        self.work_us_sum / self.steps as f64
                    } else {
                        0.0
                    }
                ),
            ),
            (
                "step_time_max_us".into(),
                format!("{:.1}", self.work_us_max),
            ),
            (
                "period_jitter_p50_us".into(),
                format!("{:.1}", Self::percentile(&mut self.period_dev_us, 0.5)),
            ),
            (
                "period_jitter_p99_us".into(),
                format!("{:.1}", Self::percentile(&mut self.period_dev_us, 0.99)),
            ),
            (
                "lateness_p99_us".into(),
                format!("{:.1}", Self::percentile(&mut self.late_us, 0.99)),
            ),
        ];
        self.period_dev_us.clear();
        self.late_us.clear();
        self.work_us_sum = 0.0;
        self.work_us_max = 0.0;
        self.steps = 0;
        self.since = now;
        out
    }
}

/// The loop's state for `<node>: simulation`.
#[derive(Debug, Clone)]
pub struct LoopReport {
    /// `Some(reason)` once the simulation diverged.
    pub diverged: Option<String>,
    pub paused: bool,
    /// Overruns in total and since the last report.
    pub overruns: u64,
    pub new_overruns: u64,
    pub step: u64,
    pub sim_time: f64,
    pub ros_time: Time,
    pub rate_hz: f64,
    pub realtime_factor: f64,
    /// With use_sim_time: /clock jumps forward re-anchored, in total and since the last report.
    pub clock_jumps: Option<u64>,
    pub new_clock_jumps: u64,
    pub publish_failures: u64,
    /// `~/plate_marker` messages skipped because the previous one was still being built.
    pub markers_skipped: u64,
    /// From [`Timing::report`].
    pub timing: Vec<(String, String)>,
}

/// The recorder's counters for `<node>: recording`.
#[derive(Debug, Clone, PartialEq)]
pub struct RecordReport {
    pub path: String,
    /// Messages handed to the recorder, written to the bag, dropped because
    /// its queue was full, and dropped since the last report.
    pub handed: u64,
    pub written: u64,
    pub dropped: u64,
    pub new_dropped: u64,
    /// Queue capacity, messages.
    pub capacity: usize,
    /// Why writing stopped (disk full, ...), if it did.
    pub error: Option<String>,
}

fn kv(k: &str, v: String) -> KeyValue {
    KeyValue {
        key: k.to_string(),
        value: v,
    }
}

/// `<node>: simulation`.
pub fn simulation_status(node_name: &str, r: &LoopReport) -> DiagnosticStatus {
    let (level, message) = match (&r.diverged, r.paused) {
        (Some(why), _) => (DiagnosticStatus::ERROR, format!("diverged: {why}")),
        (None, true) => (DiagnosticStatus::OK, "paused".to_string()),
        (None, false) if r.new_clock_jumps > 0 => (
            DiagnosticStatus::WARN,
            format!("/clock jumped forward {} time(s) beyond ros.max_clock_jump: stamps re-anchored without stepping through", r.new_clock_jumps),
        ),
        (None, false) if r.new_overruns > 0 => {
            (DiagnosticStatus::WARN, format!("{} overruns: the loop fell behind real time", r.new_overruns))
        }
        (None, false) => (DiagnosticStatus::OK, "running".to_string()),
    };
    let state = if r.diverged.is_some() {
        "diverged"
    } else if r.paused {
        "paused"
    } else {
        "running"
    };
    let mut values = vec![
        kv("state", state.into()),
        kv("step", r.step.to_string()),
        kv("sim_time", format!("{}", r.sim_time)),
        kv("ros_time", format!("{}", r.ros_time.to_secs())),
        kv("rate_hz", format!("{}", r.rate_hz)),
        kv("realtime_factor", format!("{}", r.realtime_factor)),
        kv("overruns", r.overruns.to_string()),
        kv("publish_failures", r.publish_failures.to_string()),
        kv("markers_skipped", r.markers_skipped.to_string()),
    ];
    if let Some(j) = r.clock_jumps {
        values.push(kv("clock_jumps_forward", j.to_string()));
    }
    values.extend(r.timing.iter().map(|(k, v)| kv(k, v.clone())));
    DiagnosticStatus {
        level,
        name: format!("{node_name}: simulation"),
        message,
        hardware_id: node_name.to_string(),
        values,
    }
}

/// `<node>: inputs`; `new_rejected` = rejections since the last report.
/// `reception` (the node only): how the input datagrams are read,
/// `ros/step_aligned_receive.rs`.
pub fn inputs_status(
    node_name: &str,
    s: &InputStats,
    new_rejected: u64,
    reception: Option<&str>,
) -> DiagnosticStatus {
    let mut values: Vec<KeyValue> = Source::ALL
        .iter()
        .map(|src| {
            kv(
                &format!("accepted_{}", src.name()),
                s.accepted(*src).to_string(),
            )
        })
        .collect();
    values.push(kv("accepted_total", s.accepted_total().to_string()));
    values.push(kv("rejected_total", s.rejected_total().to_string()));
    values.extend(RejectReason::ALL.iter().map(|r| {
        kv(
            &format!("rejected_{}", r.name()),
            s.rejected(*r).to_string(),
        )
    }));
    values.push(kv("expired_wrenches", s.expired().to_string()));
    if let Some(reception) = reception {
        values.push(kv("input_reception", reception.to_string()));
    }
    DiagnosticStatus {
        level: if new_rejected > 0 {
            DiagnosticStatus::WARN
        } else {
            DiagnosticStatus::OK
        },
        name: format!("{node_name}: inputs"),
        message: if new_rejected > 0 {
            format!("{new_rejected} inputs rejected since the last report")
        } else {
            "all inputs accepted".to_string()
        },
        hardware_id: node_name.to_string(),
        values,
    }
}

/// `<node>: recording`: OK, WARN after drops since the last report, ERROR
/// once writing failed.
pub fn recording_status(node_name: &str, r: &RecordReport) -> DiagnosticStatus {
    let (level, message) = match &r.error {
        Some(e) => (DiagnosticStatus::ERROR, format!("recording stopped: {e}")),
        None if r.new_dropped > 0 => (
            DiagnosticStatus::WARN,
            format!(
                "{} messages dropped since the last report: the bag writer fell behind",
                r.new_dropped
            ),
        ),
        None => (DiagnosticStatus::OK, format!("recording to {}", r.path)),
    };
    DiagnosticStatus {
        level,
        name: format!("{node_name}: recording"),
        message,
        hardware_id: node_name.to_string(),
        values: vec![
            kv("record_path", r.path.clone()),
            kv("record_handed", r.handed.to_string()),
            kv("record_written", r.written.to_string()),
            kv(
                "record_queued",
                r.handed.saturating_sub(r.written + r.dropped).to_string(),
            ),
            kv("record_dropped", r.dropped.to_string()),
            kv("record_queue_capacity", r.capacity.to_string()),
            kv("record_error", r.error.clone().unwrap_or_default()),
        ],
    }
}

/// The whole message.
pub fn diagnostics_message(stamp: Time, status: Vec<DiagnosticStatus>) -> DiagnosticArray {
    DiagnosticArray {
        header: Header {
            stamp,
            frame_id: String::new(),
        },
        status,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn report() -> LoopReport {
        LoopReport {
            diverged: None,
            paused: false,
            overruns: 3,
            new_overruns: 0,
            step: 10,
            sim_time: 0.01,
            ros_time: Time::from_nanos(10_000_000),
            rate_hz: 1000.0,
            realtime_factor: 1.0,
            clock_jumps: None,
            new_clock_jumps: 0,
            publish_failures: 0,
            markers_skipped: 0,
            timing: vec![("steps_in_period".into(), "10".into())],
        }
    }

    #[test]
    fn simulation_levels() {
        let mut r = report();
        assert_eq!(simulation_status("/n", &r).level, DiagnosticStatus::OK);
        r.new_overruns = 1;
        assert_eq!(simulation_status("/n", &r).level, DiagnosticStatus::WARN);
        r.diverged = Some("NaN".into());
        let s = simulation_status("/n", &r);
        assert_eq!(
            (s.level, s.name.as_str()),
            (DiagnosticStatus::ERROR, "/n: simulation")
        );
        assert!(s.values.iter().any(|v| v.key == "steps_in_period"));
    }

    #[test]
    fn a_clock_jump_forward_warns_once_and_is_counted() {
        let mut r = report();
        r.clock_jumps = Some(1);
        r.new_clock_jumps = 1;
        let s = simulation_status("/n", &r);
        assert_eq!(s.level, DiagnosticStatus::WARN);
        assert!(s.message.contains("ros.max_clock_jump"), "{}", s.message);
        assert!(s.values.contains(&KeyValue {
            key: "clock_jumps_forward".into(),
            value: "1".into()
        }));
        r.new_clock_jumps = 0;
        let s = simulation_status("/n", &r);
        assert_eq!(
            s.level,
            DiagnosticStatus::OK,
            "the next report is OK, the count stays"
        );
        assert!(s.values.contains(&KeyValue {
            key: "clock_jumps_forward".into(),
            value: "1".into()
        }));
    }

    #[test]
    fn recording_levels() {
        let mut r = RecordReport {
            path: "b".into(),
            handed: 10,
            written: 7,
            dropped: 1,
            new_dropped: 0,
            capacity: 8,
            error: None,
        };
        let s = recording_status("/n", &r);
        assert_eq!(s.level, DiagnosticStatus::OK);
        assert!(s.values.contains(&KeyValue {
            key: "record_queued".into(),
            value: "2".into()
        }));
        r.new_dropped = 1;
        assert_eq!(recording_status("/n", &r).level, DiagnosticStatus::WARN);
        r.error = Some("disk full".into());
        assert_eq!(recording_status("/n", &r).level, DiagnosticStatus::ERROR);
    }
}
