//! The fixed-rate loop: one OS thread owns the [`Simulation`], applies the
//! checked inputs and service commands in arrival order between steps,
//! steps, and publishes. A dedicated thread (not a tokio timer, whose
//! resolution is 1 ms) keeps the step period. Waiting for a step at most
//! `SLEEP_THROUGH_INPUTS` away it sleeps, and the inputs that arrive
//! meanwhile wait in the queue for the step boundary: one wakeup per step
//! however many samples arrive; a longer wait (a slow rate, paused) is a
//! `recv_timeout`, so an input or a service call wakes it at once.
//!
//! Per step (nothing allocated on our side): drop stale wrenches, step,
//! advance the clock, overwrite the preallocated messages, publish — and,
//! with `run --record`, hand the same message handles to the bag writer
//! thread without waiting (`bag::recorder`).

use super::input_polling::PolledInput;
use super::inputs::{Input, InputStats, Source, StaleWrenches};
use super::logging::Logger;
use super::marker_thread::MarkerFeed;
use super::params_service::RuntimeChange;
use super::services::{Command, LoopStatus};
use super::step_aligned_receive::{StepAlignedReceive, ON_ARRIVAL};
use crate::bag::recorder::{Recorder, Sample};
use crate::dynamics::{Checked, Command as SimCommand, NodeKind, Simulation, Wrench};
use crate::messages::clock::{Pacer, StepClock};
use crate::messages::clock_follower::ClockUpdate;
use crate::messages::diagnostics::{self, LoopReport, Timing};
use crate::messages::model_states::ModelStates;
use crate::messages::outputs::{clock_message, OutputMessages, Shared};
use crate::messages::types::{
    Clock, DiagnosticArray, JointState, ModalAmplitudes, SetBoolResponse, StepResponse, TFMessage,
    Time, TriggerResponse,
};
use ros2_client::dds::rustdds::defer_wakes;
use ros2_client::Publisher;
use std::collections::VecDeque;
use std::sync::mpsc::{Receiver, RecvTimeoutError};
use std::sync::Arc;
use std::time::{Duration, Instant};

/// A wait for the next step at most this long sleeps through arriving inputs
/// and service calls (they queue, and are handled in arrival order at the
/// step boundary, where an input takes effect anyway); a longer one wakes for
/// each, so a slow loop still answers services at once.
const SLEEP_THROUGH_INPUTS: Duration = Duration::from_millis(2);

/// Paused or diverged, the loop reads the input topics this often.
const PAUSED_INPUT_POLL: Duration = Duration::from_millis(5);
use tokio::sync::oneshot;

/// The loop's writers.
pub(crate) struct Publishers {
    pub joint_states: Publisher<Shared<JointState>>,
    pub tf: Publisher<Shared<TFMessage>>,
    pub modal: Publisher<Shared<ModalAmplitudes>>,
    /// The load models' state topics, as `OutputMessages::models`.
    pub models: Vec<Publisher<Shared<ModelStates>>>,
    /// Only with simulated time.
    pub clock: Option<Publisher<Clock>>,
    pub diagnostics: Publisher<DiagnosticArray>,
}

/// Settings of the loop (from the config and `ros.*`).
#[derive(Debug, Clone)]
pub(crate) struct LoopSettings {
    pub publish_divisor: u32,
    pub realtime_factor: f64,
    pub start_paused: bool,
    pub sim_time: bool,
    /// `use_sim_time`: step as an external `/clock` advances (`Command::Clock`).
    pub follow_clock: bool,
    /// `ros.max_clock_jump`, s (with `follow_clock`).
    pub max_clock_jump: f64,
    pub wrench_timeout: f64,
    pub diagnostics_period: Duration,
    /// `/ns/node`, for diagnostics names.
    pub node_name: String,
}

/// The loop's state.
pub(crate) struct SimLoop {
    sim: Simulation,
    clock: StepClock,
    pacer: Pacer,
    outputs: OutputMessages,
    pubs: Publishers,
    rx: Receiver<Command>,
    stats: Arc<InputStats>,
    stale: StaleWrenches,
    logger: Arc<Logger>,
    settings: LoopSettings,
    paused: bool,
    step_requests: VecDeque<(u32, oneshot::Sender<StepResponse>)>,
    diverged: Option<String>,
    /// Unlocated `contact_exponential` substeps at the last warning (warned
    /// at the first and each time the count doubles).
    unlocated_warned: u64,
    publish_failures: u64,
    /// Header stamp of the newest input applied (ns; 0 = none).
    input_stamp: i64,
    timing: Timing,
    next_diagnostics: Instant,
    rejected_at_last_report: u64,
    overruns_at_last_report: u64,
    clock_jumps_at_last_report: u64,
    /// `run --record`: every published message also goes to the bag writer.
    recorder: Option<Recorder>,
    dropped_at_last_report: u64,
    stop: bool,
    /// `~/plate_marker`: the state goes to the marker thread every so many steps.
    marker: Option<MarkerFeed>,
    /// The input topics, read at step boundaries (`ros/input_polling.rs`).
    inputs: Vec<Box<dyn PolledInput>>,
    /// Inputs taken at a boundary: (reception time ns, order taken, input),
    /// applied in reception order (reused: no allocation once grown).
    taken: Vec<(i64, u32, Command)>,
    /// Input datagrams read at step boundaries (`ros/step_aligned_receive.rs`).
    receive: Option<StepAlignedReceive>,
    /// The critical speeds (`~/critical_speeds`) for the near-critical status.
    critical_speeds: Vec<crate::model::campbell::CriticalSpeed>,
}

impl SimLoop {
    pub fn new(
        sim: Simulation,
        outputs: OutputMessages,
        pubs: Publishers,
        rx: Receiver<Command>,
        stats: Arc<InputStats>,
        logger: Arc<Logger>,
        settings: LoopSettings,
    ) -> Self {
        let now = Instant::now();
        let dt = sim.dt();
        SimLoop {
            clock: if settings.follow_clock {
                StepClock::following(dt, settings.max_clock_jump)
            } else {
                StepClock::new(settings.sim_time, dt)
            },
            pacer: Pacer::new(dt, settings.realtime_factor, now),
            stale: StaleWrenches::new(
                settings.wrench_timeout,
                sim.n_ale_nodes(),
                sim.n_lagrange_nodes(),
            ),
            paused: settings.start_paused,
            sim,
            outputs,
            pubs,
            rx,
            stats,
            logger,
            step_requests: VecDeque::new(),
            diverged: None,
            unlocated_warned: 0,
            publish_failures: 0,
            input_stamp: 0,
            timing: Timing::new(now),
            next_diagnostics: now,
            rejected_at_last_report: 0,
            overruns_at_last_report: 0,
            clock_jumps_at_last_report: 0,
            recorder: None,
            dropped_at_last_report: 0,
            stop: false,
            marker: None,
            inputs: Vec::new(),
            taken: Vec::new(),
            receive: None,
            critical_speeds: Vec::new(),
            settings,
        }
    }

    /// Read these input topics at every step boundary.
    pub fn with_inputs(mut self, inputs: Vec<Box<dyn PolledInput>>) -> Self {
        self.inputs = inputs;
        self
    }

    /// Read the input datagrams at step boundaries while they are many.
    pub fn with_step_aligned_receive(mut self, receive: StepAlignedReceive) -> Self {
        self.receive = Some(receive);
        self
    }

    /// Report `<node>: critical speeds` against these (`ros/critical_speeds.rs`).
    pub fn with_critical_speeds(
        mut self,
        speeds: Vec<crate::model::campbell::CriticalSpeed>,
    ) -> Self {
        self.critical_speeds = speeds;
        self
    }

    /// The simulation the loop owns (for setting up what it feeds).
    pub fn simulation(&self) -> &Simulation {
        &self.sim
    }

    /// Offer the state to the marker thread on its steps.
    pub fn with_marker(mut self, feed: MarkerFeed) -> Self {
        self.marker = Some(feed);
        self
    }

    /// Also hand every published message to `recorder` (`run --record`).
    pub fn with_recorder(mut self, recorder: Recorder) -> Self {
        self.recorder = Some(recorder);
        self
    }

    /// Run until a [`Command::Stop`] arrives or every sender is gone.
    pub fn run(mut self) {
        // The initial state (t = 0), so subscribers see the plate at once.
        self.publish_state();
        self.publish_clock();
        self.offer_marker();
        self.logger.info(&format!(
            "simulating at {} Hz ({}), {}",
            1.0 / self.sim.dt(),
            match (self.clock.follower(), self.pacer.period()) {
                (Some(_), _) => "following /clock".to_string(),
                (None, Some(_)) => format!("realtime_factor {}", self.settings.realtime_factor),
                (None, None) => "as fast as possible".to_string(),
            },
            if self.paused { "paused" } else { "running" }
        ));
        while !self.stop {
            let now = Instant::now();
            if now >= self.next_diagnostics {
                self.publish_diagnostics(now);
            }
            if !self.step_requests.is_empty() {
                // Stepping on request: as fast as possible, commands in between.
                self.release_receive();
                self.drain_commands();
                if self.stop || self.paused_steps_cancelled() {
                    continue;
                }
                self.timing.interrupt();
                self.step_once(None);
                self.finish_step_request();
            } else if self.paused || self.diverged.is_some() {
                self.timing.interrupt();
                self.release_receive();
                // Not stepping: the input topics are read every
                // PAUSED_INPUT_POLL, so inputs take hold (and are counted)
                // before the next ~/step.
                let wait = self
                    .next_diagnostics
                    .saturating_duration_since(Instant::now());
                self.wait_command(wait.min(PAUSED_INPUT_POLL));
                self.take_inputs();
                if !self.paused && self.diverged.is_none() {
                    self.pacer.restart(Instant::now());
                }
            } else if let Some(due) = self.clock.follower().map(|f| f.due()) {
                // use_sim_time: the steps the external clock's advance holds.
                self.release_receive();
                if due == 0 {
                    let wait = self
                        .next_diagnostics
                        .saturating_duration_since(Instant::now());
                    self.wait_command(wait);
                    continue;
                }
                self.drain_commands();
                if self.stop || self.paused {
                    continue;
                }
                self.step_once(None);
            } else {
                let deadline = self.pacer.deadline();
                let now = Instant::now();
                if now < deadline {
                    let wait = deadline.min(self.next_diagnostics) - now;
                    if wait <= SLEEP_THROUGH_INPUTS {
                        // Inputs take effect at the step anyway: queue them
                        // and wake once per step, not once per sample.
                        std::thread::sleep(wait);
                    } else {
                        self.wait_command(wait);
                    }
                    continue;
                }
                // Apply everything that arrived before the deadline.
                if let Some(receive) = &self.receive {
                    receive.before_take();
                }
                let taken = self.drain_commands();
                if let Some(receive) = &mut self.receive {
                    receive.after_take(taken);
                }
                if self.stop || self.paused {
                    continue;
                }
                let start = Instant::now();
                self.step_once(Some(deadline));
                self.pacer.stepped(start);
            }
        }
        self.logger.info("simulation loop stopped");
    }

    fn wait_command(&mut self, timeout: Duration) {
        match self.rx.recv_timeout(timeout) {
            Ok(cmd) => self.handle(cmd),
            Err(RecvTimeoutError::Timeout) => {}
            Err(RecvTimeoutError::Disconnected) => self.stop = true,
        }
    }

    /// The queued service calls in arrival order, then the samples waiting
    /// on the input topics in DDS reception order; how many samples.
    fn drain_commands(&mut self) -> usize {
        while let Ok(cmd) = self.rx.try_recv() {
            self.handle(cmd);
            if self.stop {
                return 0;
            }
        }
        self.take_inputs()
    }

    /// The samples waiting on the input topics, applied; how many.
    fn take_inputs(&mut self) -> usize {
        let mut taken = std::mem::take(&mut self.taken);
        for input in &mut self.inputs {
            input.drain(&mut |received, cmd| {
                let order = taken.len() as u32;
                taken.push((received, order, cmd));
            });
        }
        let count = taken.len();
        taken.sort_unstable_by_key(|&(received, order, _)| (received, order));
        for (_, _, cmd) in taken.drain(..) {
            if !self.stop {
                self.handle(cmd);
            }
        }
        self.taken = taken;
        count
    }

    fn release_receive(&mut self) {
        if let Some(receive) = &mut self.receive {
            receive.release();
        }
    }

    /// A resume while steps were requested ends those requests.
    fn paused_steps_cancelled(&mut self) -> bool {
        if self.paused && self.diverged.is_none() {
            return false;
        }
        let reason = if self.diverged.is_some() {
            "the simulation diverged"
        } else {
            "the simulation was resumed"
        };
        while let Some((left, reply)) = self.step_requests.pop_front() {
            let _ = reply.send(self.step_response(
                false,
                format!("{reason}; {left} requested steps were not taken"),
            ));
        }
        true
    }

    fn finish_step_request(&mut self) {
        if let Some(front) = self.step_requests.front_mut() {
            front.0 = front.0.saturating_sub(1);
            if front.0 == 0 {
                let (_, reply) = self.step_requests.pop_front().expect("front exists");
                let resp = self.step_response(self.diverged.is_none(), String::new());
                let _ = reply.send(resp);
            }
        }
    }

    fn step_response(&self, success: bool, message: String) -> StepResponse {
        let message = if message.is_empty() {
            format!(
                "at step {} (t = {} s)",
                self.sim.step_count(),
                self.sim.time()
            )
        } else {
            message
        };
        StepResponse {
            success,
            message,
            step: self.sim.step_count(),
            sim_time: self.sim.time(),
        }
    }

    fn handle(&mut self, cmd: Command) {
        match cmd {
            Command::Input(input, source, stamp) => self.apply(input, source, stamp),
            Command::Reset(reply) => {
                self.sim.reset();
                self.stale.clear();
                self.diverged = None;
                self.pacer.restart(Instant::now());
                self.logger.info("reset to the initial state");
                let _ = reply.send(TriggerResponse {
                    success: true,
                    message: "reset to t = 0 (the ROS clock keeps counting)".into(),
                });
            }
            Command::SetPaused(pause, reply) => {
                let was = self.paused;
                self.paused = pause;
                if !pause && was {
                    self.pacer.restart(Instant::now());
                }
                let message = match (was, pause) {
                    (false, true) => "paused".to_string(),
                    (true, false) => "resumed".to_string(),
                    (_, true) => "already paused".to_string(),
                    (_, false) => "already running".to_string(),
                };
                let _ = reply.send(SetBoolResponse {
                    success: true,
                    message,
                });
            }
            Command::Step(n, reply) => {
                if self.clock.follower().is_some() {
                    let msg = "use_sim_time is true: the external /clock drives the steps (pause it, or this node with ~/set_paused)";
                    let _ = reply.send(self.step_response(false, msg.into()));
                } else if !self.paused {
                    let _ = reply.send(self.step_response(
                        false,
                        "the simulation is running; pause it first (~/set_paused with data: true)".into(),
                    ));
                } else if let Some(why) = &self.diverged {
                    let msg = format!("the simulation diverged ({why}); call ~/reset first");
                    let _ = reply.send(self.step_response(false, msg));
                } else if n == 0 {
                    let _ = reply.send(self.step_response(true, String::new()));
                } else {
                    self.step_requests.push_back((n, reply));
                }
            }
            Command::Runtime(change) => {
                let line = apply_runtime(
                    change,
                    &mut self.settings.realtime_factor,
                    &mut self.pacer,
                    &mut self.stale,
                    self.sim.dt(),
                    Instant::now(),
                );
                self.logger.info(&line);
            }
            Command::Clock(t_ns) => self.follow_clock(t_ns),
            Command::Status(reply) => {
                let _ = reply.send(LoopStatus {
                    paused: self.paused,
                    diverged: self.diverged.clone(),
                    step: self.sim.step_count(),
                    sim_time: self.sim.time(),
                });
            }
            Command::Stop => self.stop = true,
        }
    }

    /// A `/clock` message: what it makes due (skipped while paused or diverged).
    fn follow_clock(&mut self, t_ns: i64) {
        let (paused, diverged) = (self.paused, self.diverged.is_some());
        let Some(f) = self.clock.follower_mut() else {
            return;
        };
        let update = f.observe(t_ns);
        if paused || diverged {
            f.skip();
        }
        match update {
            ClockUpdate::Started => self.logger.info(&format!("following /clock from t = {} s", t_ns as f64 * 1e-9)),
            ClockUpdate::Backwards => self.logger.warn(&format!(
                "/clock went back to t = {} s: stamps follow it from there (the plate's state is kept)",
                t_ns as f64 * 1e-9
            )),
            ClockUpdate::JumpedForward { gap_ns } => self.logger.warn(&format!(
                "/clock jumped {} s ahead to t = {} s, beyond ros.max_clock_jump = {} s: stamps re-anchored there without stepping through the gap (the plate's state is kept; {} jump(s) so far)",
                gap_ns as f64 * 1e-9,
                t_ns as f64 * 1e-9,
                self.settings.max_clock_jump,
                f.jumps_forward()
            )),
            ClockUpdate::Forward => {}
        }
    }

    /// Hold an input checked on arrival (`inputs::InputValidator`, the
    /// dynamics' rules): applied as it is, a batch whole.
    fn apply(&mut self, input: Input, source: Source, stamp: i64) {
        let t = self.sim.time();
        let mut touch = |c: &Checked| {
            if let SimCommand::Wrench { kind, node, .. } = c.command() {
                self.stale.touched(kind, node, t);
            }
        };
        match &input {
            Input::One(c) => {
                touch(c);
                self.sim.apply(*c);
            }
            Input::Batch(batch) => {
                batch.iter().for_each(&mut touch);
                self.sim.apply_batch(batch);
            }
        }
        self.stats.accept(source);
        if stamp != 0 {
            self.input_stamp = stamp;
        }
    }

    fn step_once(&mut self, deadline: Option<Instant>) {
        let start = Instant::now();
        let t = self.sim.time();
        {
            let (sim, stats) = (&mut self.sim, &self.stats);
            self.stale.expire(t, |kind, node| {
                let _ = match kind {
                    NodeKind::Ale => sim.set_ale_wrench(node, Wrench::default()),
                    NodeKind::Lagrange => sim.set_lagrange_wrench(node, Wrench::default()),
                };
                stats.expire();
            });
        }
        match self.sim.step() {
            Ok(()) => {
                self.clock.advance();
                // The step's samples wake the RustDDS event loop once, after
                // the last of them (vendor/rustdds/PATCH.md §10), not at the
                // first while the others are still being written.
                defer_wakes(|| {
                    self.publish_clock();
                    if self
                        .clock
                        .total_steps()
                        .is_multiple_of(self.settings.publish_divisor.max(1) as u64)
                    {
                        self.publish_state();
                    }
                });
                self.offer_marker();
                self.warn_unlocated();
            }
            Err(e) => {
                let msg = e.to_string();
                self.logger.error(&format!("{msg}; the simulation is paused with its last good state; call ~/reset to start again"));
                self.diverged = Some(msg);
            }
        }
        self.timing.record(
            start,
            deadline,
            deadline.and(self.pacer.period()),
            start.elapsed(),
        );
    }

    /// Warn of `contact_exponential` substeps finished without locating
    /// their switches: at the first, then each time their count doubles.
    fn warn_unlocated(&mut self) {
        let unlocated = self.sim.unlocated_substeps();
        if unlocated > 0 && unlocated >= 2 * self.unlocated_warned {
            self.logger.warn(&self.sim.unlocated_warning());
            self.unlocated_warned = unlocated;
        }
    }

    fn offer_marker(&mut self) {
        if let Some(m) = &mut self.marker {
            m.offer(&self.sim, self.clock.stamp());
        }
    }

    fn publish_clock(&mut self) {
        if let Some(p) = &self.pubs.clock {
            let msg = clock_message(&self.clock);
            if p.publish(msg).is_err() {
                self.publish_failures += 1;
            }
            if let Some(r) = &self.recorder {
                r.record(Sample::Clock(msg), msg.clock);
            }
        }
    }

    fn publish_state(&mut self) {
        let stamp = self.clock.stamp();
        self.outputs.update(&self.sim, stamp);
        self.outputs.modal.get_mut().input_stamp = Time::from_nanos(self.input_stamp);
        let failures = [
            self.pubs
                .joint_states
                .publish(self.outputs.joint_state.handle())
                .is_err(),
            self.pubs.tf.publish(self.outputs.tf.handle()).is_err(),
            self.pubs
                .modal
                .publish(self.outputs.modal.handle())
                .is_err(),
        ];
        self.publish_failures += failures.iter().filter(|f| **f).count() as u64;
        for (p, (_, m)) in self.pubs.models.iter().zip(&self.outputs.models) {
            self.publish_failures += p.publish(m.handle()).is_err() as u64;
        }
        if let Some(r) = &self.recorder {
            // Handles, not copies: the writer thread serializes them.
            r.record(Sample::JointState(self.outputs.joint_state.handle()), stamp);
            r.record(Sample::Tf(self.outputs.tf.handle()), stamp);
            r.record(Sample::Modal(self.outputs.modal.handle()), stamp);
            for (k, (_, m)) in self.outputs.models.iter().enumerate() {
                r.record(Sample::Model(k, m.handle()), stamp);
            }
        }
    }

    fn publish_diagnostics(&mut self, now: Instant) {
        self.next_diagnostics = now + self.settings.diagnostics_period;
        let name = &self.settings.node_name;
        let overruns = self.pacer.overruns();
        let report = LoopReport {
            diverged: self.diverged.clone(),
            paused: self.paused,
            overruns,
            new_overruns: overruns - self.overruns_at_last_report,
            step: self.sim.step_count(),
            sim_time: self.sim.time(),
            ros_time: self.clock.sim_time(),
            rate_hz: 1.0 / self.sim.dt(),
            realtime_factor: self.settings.realtime_factor,
            clock_jumps: self.clock.follower().map(|f| f.jumps_forward()),
            new_clock_jumps: self
                .clock
                .follower()
                .map_or(0, |f| f.jumps_forward() - self.clock_jumps_at_last_report),
            publish_failures: self.publish_failures,
            markers_skipped: self.marker.as_ref().map_or(0, |m| m.skipped),
            timing: self.timing.report(now),
        };
        self.overruns_at_last_report = overruns;
        self.clock_jumps_at_last_report = self.clock.follower().map_or(0, |f| f.jumps_forward());
        let rejected = self.stats.rejected_total();
        let new_rejected = rejected - self.rejected_at_last_report;
        self.rejected_at_last_report = rejected;
        let reception = self.receive.as_ref().map_or(ON_ARRIVAL, |r| r.reception());
        let mut status = vec![
            diagnostics::simulation_status(name, &report),
            diagnostics::inputs_status(name, &self.stats, new_rejected, Some(reception)),
        ];
        status.push(crate::messages::critical_speeds::status(
            name,
            &self.critical_speeds,
            self.sim.joint().velocity,
        ));
        if let Some(r) = &self.recorder {
            let rec = r.report(self.dropped_at_last_report);
            self.dropped_at_last_report = rec.dropped;
            if rec.new_dropped > 0 {
                self.logger.warn(&format!(
                    "recording: {} messages dropped (the bag writer fell behind)",
                    rec.new_dropped
                ));
            }
            status.push(diagnostics::recording_status(name, &rec));
        }
        let stamp = self.clock.stamp();
        let msg: DiagnosticArray = diagnostics::diagnostics_message(stamp, status);
        if let Some(r) = &self.recorder {
            r.record(Sample::Diagnostics(msg.clone()), stamp);
        }
        if self.pubs.diagnostics.publish(msg).is_err() {
            self.publish_failures += 1;
        }
    }
}

/// Apply an accepted run-time parameter change (checked by the parameter
/// service through `config::check`) to the loop's pacing and wrench
/// timeout; the log line it makes. Every accepted value keeps the loop
/// stepping (`tests/parameter_services_cannot_stop_the_node.rs`).
pub fn apply_runtime(
    change: RuntimeChange,
    realtime_factor: &mut f64,
    pacer: &mut Pacer,
    stale: &mut StaleWrenches,
    dt: f64,
    now: Instant,
) -> String {
    match change {
        RuntimeChange::RealtimeFactor(f) => {
            *realtime_factor = f;
            pacer.set_realtime_factor(dt, f, now);
            format!("simulation.realtime_factor set to {f}")
        }
        RuntimeChange::WrenchTimeout(t) => {
            stale.set_timeout(t);
            format!("ros.wrench_timeout set to {t} s")
        }
    }
}
