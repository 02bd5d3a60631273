//! The node's output topics in a bag: which topics, their types and QoS
//! ([`NodeBag`]), and the background writer of `run --record`
//! ([`Recorder`]).
//!
//! The fixed-rate loop never waits for the disk: it hands each published
//! message — the same `Arc` handle it gave the DDS writer, so nothing is
//! copied or serialized in the loop — to a writer thread through a bounded
//! queue with `try_send`. A full queue drops the message and counts it
//! (`record_dropped` in `/diagnostics`). The thread serializes (CDR) and
//! writes; when the loop ends (SIGINT/SIGTERM), the queue's sender is
//! dropped, the thread writes what is left, finishes the MCAP file and
//! writes metadata.yaml.

use super::writer::{BagError, BagSummary, BagWriter, TopicId};
use crate::dynamics::load_models::StateTopic;
use crate::messages::diagnostics::RecordReport;
use crate::messages::model_states::{type_name as model_type_name, ModelStates};
use crate::messages::names::NameResolver;
use crate::messages::outputs::Shared;
use crate::messages::types::{
    Clock, DiagnosticArray, JointState, ModalAmplitudes, RosType, TFMessage, Time,
};
use crate::messages::visualization::MarkerArray;
use crate::messages::{qos, topics};
use ros2_client::QosProfile;
use std::path::Path;
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::mpsc::{sync_channel, Receiver, SyncSender, TrySendError};
use std::sync::{Arc, Mutex};
use std::thread::JoinHandle;

/// One published message, as the loop holds it.
#[derive(Debug, Clone)]
pub enum Sample {
    JointState(Shared<JointState>),
    Tf(Shared<TFMessage>),
    TfStatic(TFMessage),
    Modal(Shared<ModalAmplitudes>),
    /// The state message of the k-th load model topic ([`NodeTopics::models`]).
    Model(usize, Shared<ModelStates>),
    Clock(Clock),
    Diagnostics(DiagnosticArray),
    Marker(Shared<MarkerArray>),
}

/// The resolved names of the node's outputs (`~` expanded, remaps applied).
#[derive(Debug, Clone, PartialEq)]
pub struct NodeTopics {
    pub joint_states: String,
    pub tf: String,
    pub tf_static: String,
    pub modal_amplitudes: String,
    pub diagnostics: String,
    /// Only with simulated time.
    pub clock: Option<String>,
    /// The load models' state topics (name, `pkg/msg/Type`), registry order.
    pub models: Vec<(String, String)>,
    /// Only when `ros.marker_rate_hz` > 0.
    pub plate_marker: Option<String>,
}

impl NodeTopics {
    /// The names the node publishes under, for `names`, the time mode and
    /// the topics the scene's load models declare.
    pub fn resolve(
        names: &NameResolver,
        sim_time: bool,
        models: &[StateTopic],
        has_marker: bool,
    ) -> Result<NodeTopics, String> {
        let r = |t: &str| names.resolve(t).map_err(|e| e.to_string());
        Ok(NodeTopics {
            joint_states: r(topics::JOINT_STATES)?,
            tf: r(topics::TF)?,
            tf_static: r(topics::TF_STATIC)?,
            modal_amplitudes: r(topics::MODAL_AMPLITUDES)?,
            diagnostics: r(topics::DIAGNOSTICS)?,
            clock: if sim_time {
                Some(r(topics::CLOCK)?)
            } else {
                None
            },
            models: models
                .iter()
                .map(|t| Ok((r(t.topic)?, model_type_name(t))))
                .collect::<Result<_, String>>()?,
            plate_marker: if has_marker {
                Some(r(topics::PLATE_MARKER)?)
            } else {
                None
            },
        })
    }
}

fn type_name<T: RosType>() -> String {
    format!("{}/msg/{}", T::PACKAGE, T::NAME)
}

/// A bag of the node's topics, with the QoS the node offers on each.
pub struct NodeBag {
    writer: BagWriter,
    joint_states: TopicId,
    tf: TopicId,
    tf_static: TopicId,
    modal: TopicId,
    diagnostics: TopicId,
    clock: Option<TopicId>,
    models: Vec<TopicId>,
    plate_marker: Option<TopicId>,
}

impl NodeBag {
    /// Create the bag directory `dir` (it must not exist) with the node's topics.
    pub fn create(dir: &Path, topics: &NodeTopics) -> Result<NodeBag, BagError> {
        let mut writer = BagWriter::create(dir)?;
        let mut add = |name: &str, ty: String, q: &QosProfile| writer.add_topic(name, &ty, q);
        let tf_static = add(&topics.tf_static, type_name::<TFMessage>(), &qos::TF_STATIC)?;
        let joint_states = add(&topics.joint_states, type_name::<JointState>(), &qos::STATE)?;
        let tf = add(&topics.tf, type_name::<TFMessage>(), &qos::TF)?;
        let modal = add(
            &topics.modal_amplitudes,
            type_name::<ModalAmplitudes>(),
            &qos::STATE,
        )?;
        let models = topics
            .models
            .iter()
            .map(|(t, ty)| add(t, ty.clone(), &qos::STATE))
            .collect::<Result<_, _>>()?;
        let plate_marker = match &topics.plate_marker {
            Some(t) => Some(add(t, type_name::<MarkerArray>(), &qos::MARKER)?),
            None => None,
        };
        let diagnostics = add(
            &topics.diagnostics,
            type_name::<DiagnosticArray>(),
            &qos::DIAGNOSTICS,
        )?;
        let clock = match &topics.clock {
            Some(c) => Some(add(c, type_name::<Clock>(), &qos::CLOCK)?),
            None => None,
        };
        Ok(NodeBag {
            writer,
            joint_states,
            tf,
            tf_static,
            modal,
            diagnostics,
            clock,
            models,
            plate_marker,
        })
    }

    pub fn dir(&self) -> &Path {
        self.writer.dir()
    }

    /// Write `sample` with log time `at`. A sample of a topic the bag does
    /// not have (`/clock` in wall time, a model topic beyond its own) is ignored.
    pub fn write(&mut self, sample: &Sample, at: Time) -> Result<(), BagError> {
        let t = at.to_nanos().max(0) as u64;
        let w = &mut self.writer;
        match sample {
            Sample::JointState(m) => w.write(self.joint_states, t, m),
            Sample::Tf(m) => w.write(self.tf, t, m),
            Sample::TfStatic(m) => w.write(self.tf_static, t, m),
            Sample::Modal(m) => w.write(self.modal, t, m),
            Sample::Diagnostics(m) => w.write(self.diagnostics, t, m),
            Sample::Clock(m) => match self.clock {
                Some(id) => w.write(id, t, m),
                None => Ok(()),
            },
            Sample::Model(k, m) => match self.models.get(*k) {
                Some(&id) => w.write(id, t, m),
                None => Ok(()),
            },
            Sample::Marker(m) => match self.plate_marker {
                Some(id) => w.write(id, t, m),
                None => Ok(()),
            },
        }
    }

    pub fn finish(self) -> Result<BagSummary, BagError> {
        self.writer.finish()
    }
}

/// Counters shared by the loop (sender) and the writer thread.
#[derive(Debug, Default)]
struct Counters {
    handed: AtomicU64,
    dropped: AtomicU64,
    written: AtomicU64,
    error: Mutex<Option<String>>,
}

/// The loop's end of a recording: cheap to call every step. A clone (the
/// marker thread's) feeds the same queue.
#[derive(Clone)]
pub struct Recorder {
    tx: SyncSender<(Sample, Time)>,
    counters: Arc<Counters>,
    path: String,
    capacity: usize,
}

/// The writer thread; [`RecorderThread::finish`] waits for the complete bag.
pub struct RecorderThread {
    join: JoinHandle<Result<BagSummary, BagError>>,
    counters: Arc<Counters>,
}

/// Default queue length: two seconds of a 1 kHz loop's four topics (five with pad or tool states).
pub const DEFAULT_QUEUE: usize = 8192;

impl Recorder {
    /// Start the writer thread for `bag` with a queue of `capacity` messages.
    pub fn start(bag: NodeBag, capacity: usize) -> std::io::Result<(Recorder, RecorderThread)> {
        let capacity = capacity.max(1);
        let (tx, rx) = sync_channel::<(Sample, Time)>(capacity);
        let counters = Arc::new(Counters::default());
        let path = bag.dir().display().to_string();
        let c = Arc::clone(&counters);
        let join = std::thread::Builder::new()
            .name("annular_plate-bag".into())
            .spawn(move || write_all(bag, rx, &c))?;
        Ok((
            Recorder {
                tx,
                counters: Arc::clone(&counters),
                path,
                capacity,
            },
            RecorderThread { join, counters },
        ))
    }

    /// Hand one message over; never blocks. Dropped (and counted) if the queue is full.
    pub fn record(&self, sample: Sample, at: Time) {
        self.counters.handed.fetch_add(1, Ordering::Relaxed);
        match self.tx.try_send((sample, at)) {
            Ok(()) => {}
            Err(TrySendError::Full(_)) | Err(TrySendError::Disconnected(_)) => {
                self.counters.dropped.fetch_add(1, Ordering::Relaxed);
            }
        }
    }

    /// The counters for `/diagnostics`; `dropped_before` = `dropped` of the previous report.
    pub fn report(&self, dropped_before: u64) -> RecordReport {
        let dropped = self.counters.dropped.load(Ordering::Relaxed);
        RecordReport {
            path: self.path.clone(),
            handed: self.counters.handed.load(Ordering::Relaxed),
            written: self.counters.written.load(Ordering::Relaxed),
            dropped,
            new_dropped: dropped.saturating_sub(dropped_before),
            capacity: self.capacity,
            error: self
                .counters
                .error
                .lock()
                .map(|e| e.clone())
                .unwrap_or(None),
        }
    }
}

fn write_all(
    mut bag: NodeBag,
    rx: Receiver<(Sample, Time)>,
    c: &Counters,
) -> Result<BagSummary, BagError> {
    let mut failed = false;
    // Ends when every sender is gone (the loop has stopped).
    for (sample, at) in rx {
        if failed {
            continue; // keep draining: the loop must never see a full queue because of us
        }
        match bag.write(&sample, at) {
            Ok(()) => {
                c.written.fetch_add(1, Ordering::Relaxed);
            }
            Err(e) => {
                failed = true;
                if let Ok(mut slot) = c.error.lock() {
                    *slot = Some(e.to_string());
                }
            }
        }
        drop(sample); // release the loop's message as soon as it is written
    }
    bag.finish()
}

/// What a finished recording reports.
#[derive(Debug, Clone)]
pub struct RecordingResult {
    pub summary: Result<BagSummary, String>,
    pub dropped: u64,
    /// A write error that stopped the recording early.
    pub error: Option<String>,
}

impl RecorderThread {
    /// Wait until the queue is drained and the bag finished. Call after the
    /// loop (every [`Recorder`]) is gone.
    pub fn finish(self) -> RecordingResult {
        let summary = match self.join.join() {
            Ok(r) => r.map_err(|e| e.to_string()),
            Err(_) => Err("the bag writer thread panicked".to_string()),
        };
        let c = &self.counters;
        RecordingResult {
            summary,
            dropped: c.dropped.load(Ordering::Relaxed),
            error: c.error.lock().map(|e| e.clone()).unwrap_or(None),
        }
    }
}
