//! `simulate FILE --duration S --bag DIR`: the node's topics, recorded from
//! an offline run instead of the wire.
//!
//! The messages come from the builders the node uses too (`messages::outputs`,
//! `messages::diagnostics`) on the node's default names (`/annular_plate`)
//! with the scene's `ros.frame_prefix` and `ros.world_frame`, in simulated time: the initial state
//! and every step are stamped and logged at t = step × dt from 0, `/clock`
//! carries the same time, `/tf_static` is one message at t = 0, and
//! `/diagnostics` comes every `ros.diagnostics_period` (1 s) of simulated
//! time starting at t = 0, `~/plate_marker` with every step whose count is
//! a multiple of round(rate_hz / `ros.marker_rate_hz`) — what
//! `annular_plate run` with `ros.publish_clock: true` would publish for the
//! same scene.

use super::recorder::{NodeBag, NodeTopics, Sample};
use super::writer::{BagError, BagSummary};
use crate::dynamics::Simulation;
use crate::messages::clock::StepClock;
use crate::messages::diagnostics::{self, LoopReport, Timing};
use crate::messages::input_stats::InputStats;
use crate::messages::marker::{MarkerInput, PlateMarker};
use crate::messages::model_states::model_topics;
use crate::messages::names::{NameResolver, RosArgs};
use crate::messages::outputs::{clock_message, static_transforms, FrameNames, OutputMessages};
use crate::messages::settings::RosSettings;
use crate::messages::DEFAULT_NODE_NAME;
use std::path::Path;
use std::time::Instant;

/// Records an offline run; call [`OfflineRecorder::record`] after the
/// initial state and after every step.
pub struct OfflineRecorder {
    bag: NodeBag,
    outputs: OutputMessages,
    clock: StepClock,
    /// Steps between two /diagnostics messages.
    diagnostics_every: u64,
    node_name: String,
    inputs: InputStats,
    timing: Timing,
    last: Option<Instant>,
    recorded_states: u64,
    /// With `ros.marker_rate_hz` > 0: the builder, its input, the steps
    /// between markers and the step of the next one.
    marker: Option<(PlateMarker, MarkerInput, u64, u64)>,
}

impl OfflineRecorder {
    /// Create the bag `dir` (it must not exist) for `sim`'s scene, with the
    /// scene's `ros.*` settings (frame prefix, world frame, diagnostics
    /// period, `ros.marker_*`).
    pub fn create(
        dir: &Path,
        sim: &Simulation,
        settings: &RosSettings,
    ) -> Result<OfflineRecorder, BagError> {
        let marker = &settings.marker;
        let names = NameResolver::new(&RosArgs::default(), DEFAULT_NODE_NAME)
            .expect("the default node name is valid");
        let rate_hz = 1.0 / sim.dt();
        let every = marker.every(rate_hz);
        let models: Vec<_> = model_topics(sim).into_iter().map(|(_, t)| t).collect();
        let topics = NodeTopics::resolve(&names, true, &models, every.is_some())
            .expect("the default topic names are valid");
        let mut bag = NodeBag::create(dir, &topics)?;
        let frames = FrameNames::new(
            &settings.frame_prefix,
            &settings.world_frame,
            sim.n_ale_nodes(),
            sim.n_lagrange_nodes(),
        );
        let clock = StepClock::new(true, sim.dt());
        bag.write(
            &Sample::TfStatic(static_transforms(
                &frames,
                sim.config().reference.tilt,
                clock.sim_time(),
            )),
            clock.sim_time(),
        )?;
        let marker = every.map(|n| {
            (
                PlateMarker::new(sim.model(), &frames, marker, rate_hz / n as f64),
                MarkerInput::new(sim),
                n,
                0,
            )
        });
        Ok(OfflineRecorder {
            marker,
            bag,
            outputs: OutputMessages::new(sim, &frames),
            diagnostics_every: (settings.diagnostics_period / sim.dt()).round().max(1.0) as u64,
            clock,
            node_name: names.fully_qualified_node_name(),
            inputs: InputStats::default(),
            timing: Timing::new(Instant::now()),
            last: None,
            recorded_states: 0,
        })
    }

    /// Record the current state: /clock, /joint_states, /tf, the modal
    /// amplitudes, the load models' states (those that declare a topic) and,
    /// when due, /diagnostics.
    pub fn record(&mut self, sim: &Simulation) -> Result<(), BagError> {
        let now = Instant::now();
        if let Some(last) = self.last {
            self.timing.record(last, None, None, now - last);
        }
        self.last = Some(now);
        while self.clock.total_steps() < sim.step_count() {
            self.clock.advance();
        }
        let stamp = self.clock.stamp();
        self.bag
            .write(&Sample::Clock(clock_message(&self.clock)), stamp)?;
        self.outputs.update(sim, stamp);
        self.bag.write(
            &Sample::JointState(self.outputs.joint_state.handle()),
            stamp,
        )?;
        self.bag
            .write(&Sample::Tf(self.outputs.tf.handle()), stamp)?;
        self.bag
            .write(&Sample::Modal(self.outputs.modal.handle()), stamp)?;
        for (k, (_, m)) in self.outputs.models.iter().enumerate() {
            self.bag.write(&Sample::Model(k, m.handle()), stamp)?;
        }
        // Due at multiples of `every` (the node's steps); with --output-rate
        // the first recorded state at or after one.
        if let Some((marker, input, every, next)) = &mut self.marker {
            if sim.step_count() >= *next {
                input.capture(sim, stamp);
                marker.update(input);
                self.bag
                    .write(&Sample::Marker(marker.message().handle()), stamp)?;
                *next = (sim.step_count() / *every + 1) * *every;
            }
        }
        if sim.step_count().is_multiple_of(self.diagnostics_every) {
            let report = LoopReport {
                diverged: None,
                paused: false,
                overruns: 0,
                new_overruns: 0,
                step: sim.step_count(),
                sim_time: sim.time(),
                ros_time: self.clock.sim_time(),
                rate_hz: 1.0 / sim.dt(),
                // Offline: as fast as possible.
                realtime_factor: 0.0,
                clock_jumps: None,
                new_clock_jumps: 0,
                publish_failures: 0,
                markers_skipped: 0,
                timing: self.timing.report(now),
            };
            let status = vec![
                diagnostics::simulation_status(&self.node_name, &report),
                diagnostics::inputs_status(&self.node_name, &self.inputs, 0, None),
            ];
            self.bag.write(
                &Sample::Diagnostics(diagnostics::diagnostics_message(stamp, status)),
                stamp,
            )?;
        }
        self.recorded_states += 1;
        Ok(())
    }

    /// Finish the MCAP file and write metadata.yaml.
    pub fn finish(self) -> Result<BagSummary, BagError> {
        self.bag.finish()
    }
}
