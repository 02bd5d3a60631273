//! The node: reads the scene and the ROS arguments, creates the DDS
//! entities, spawns the input and service tasks and the simulation thread,
//! and shuts everything down in order on SIGINT or SIGTERM.

use super::error::{NodeError, StopReason};
use super::input_polling::{polled, InputContext, PolledInput};
use super::inputs::{InputStats, InputValidator, Source};
use super::logging::{parse_level, Logger};
use super::marker_thread::MarkerFeed;
use super::params_service::{effective_parameters, ParamStore};
use super::services::{self, Command};
use super::sim_loop::{LoopSettings, Publishers, SimLoop};
use super::step_aligned_receive::StepAlignedReceive;
use crate::bag::recorder::{NodeBag, NodeTopics, Recorder, RecorderThread, Sample};
use crate::config::{Config, ConfigError, Params};
use crate::dynamics::{InputRules, NodeKind, Simulation, Wrench};
use crate::messages::marker::PlateMarker;
use crate::messages::model_states::{model_topics, ModelStates};
use crate::messages::names::{domain_id_from_env, NameResolver, RosArgs};
use crate::messages::outputs::{static_transforms, FrameNames, OutputMessages, Shared};
use crate::messages::settings::RosSettings;
use crate::messages::types::{
    Clock, CriticalSpeeds, DiagnosticArray, Float64, JointState, ModalAmplitudes, NodeWrenchArray,
    PadClampForces, RosType, TFMessage, Time, WrenchStamped,
};
use crate::messages::visualization::MarkerArray;
use crate::messages::{qos, topics};
use ros2_client::{
    Context, ContextOptions, MessageTypeName, Name, Node, NodeName, NodeOptions, Publisher,
    QosProfile, Subscription,
};
use serde::Serialize;
use std::path::{Path, PathBuf};
use std::sync::mpsc::{sync_channel, SyncSender};
use std::sync::{Arc, Mutex};
use std::time::Duration;
use tokio::task::JoinHandle;

/// The node's name unless remapped with `-r __node:=NAME`.
pub use crate::messages::DEFAULT_NODE_NAME;

/// The built-in default scene (a brake test bench), used when no file is given.
pub const DEFAULT_SCENE: &str = include_str!("../../config/brake_bench.yaml");

/// Commands (inputs and service calls) waiting for the simulation loop.
const COMMAND_QUEUE: usize = 4096;

/// Messages waiting for the bag writer (`run --record`).
const RECORD_QUEUE: usize = crate::bag::recorder::DEFAULT_QUEUE;

/// Everything the node needs before any DDS traffic: resolved names, the
/// effective parameters, the validated configuration and `ros.*` settings.
#[derive(Debug, Clone)]
pub struct NodeSetup {
    /// The parsed `--ros-args`.
    pub args: RosArgs,
    /// Resolves `~/` and relative names against the node's namespace and name (remappings applied).
    pub names: NameResolver,
    /// Parameters as given (scene file, `--params-file`, `-p`), `ros.*` included.
    pub params: Params,
    /// The validated scene.
    pub config: Config,
    /// The node's `ros.*` settings.
    pub settings: RosSettings,
    /// Where the scene came from, for the log.
    pub scene: String,
}

/// Whether a parameter set describes a scene: any key besides the node's own
/// (`ros.*`) and `use_sim_time`, which launch files set for every node.
fn holds_a_scene(params: &Params) -> bool {
    params
        .iter()
        .any(|(k, _)| !k.starts_with("ros.") && k != "use_sim_time")
}

fn config_error(source: &str, e: ConfigError) -> NodeError {
    NodeError::Config {
        source_name: source.to_string(),
        error: e,
    }
}

impl NodeSetup {
    /// Read the scene and the ROS arguments. The scene is `scene` (`run
    /// FILE`); without it, the first `--params-file` whose entry for this
    /// node holds scene keys (anything besides `ros.*` and `use_sim_time`),
    /// as `ros2 run … --params-file` and launch files give it; without one,
    /// the built-in brake bench. The other parameter files, then `-p`, override
    /// keys of that scene.
    pub fn load(scene: Option<&Path>, ros_args: &[String]) -> Result<NodeSetup, NodeError> {
        let args = RosArgs::parse(ros_args)?;
        let names = NameResolver::new(&args, DEFAULT_NODE_NAME)?;
        let fqn = names.fully_qualified_node_name();
        let mut files = Vec::new();
        for file in &args.params_files {
            match Params::from_file(file, &fqn) {
                Ok(p) => files.push((file.display().to_string(), p)),
                // A launch file's parameter file may hold only other nodes.
                Err(ConfigError::NoEntryForNode { .. }) => {}
                Err(e) => return Err(config_error(&file.display().to_string(), e)),
            }
        }
        let (mut params, scene_name) = match scene {
            Some(path) => (
                Params::from_file(path, &fqn)
                    .map_err(|e| config_error(&path.display().to_string(), e))?,
                path.display().to_string(),
            ),
            None => match files.iter().position(|(_, p)| holds_a_scene(p)) {
                Some(i) => {
                    let (name, p) = files.remove(i);
                    (p, name)
                }
                None => (
                    Params::from_yaml_str(DEFAULT_SCENE, &fqn)
                        .map_err(|e| config_error("built-in config/brake_bench.yaml", e))?,
                    "built-in config/brake_bench.yaml".to_string(),
                ),
            },
        };
        for (file, extra) in &files {
            for (k, v) in extra.iter() {
                params
                    .set(k, v.clone())
                    .map_err(|e| config_error(file, e))?;
            }
        }
        for p in args.params_for(names.node_name(), DEFAULT_NODE_NAME) {
            params
                .set_override(&p.name, &p.value)
                .map_err(|e| config_error("-p", e))?;
        }
        // One parameter set for both: the config accepts the `ros.*` names, the
        // node's settings read only theirs (and `use_sim_time`).
        let settings = RosSettings::from_params(&params).map_err(|error| NodeError::Settings {
            scene: scene_name.clone(),
            error,
        })?;
        let config = Config::from_params(&params).map_err(|e| config_error(&scene_name, e))?;
        settings
            .check_against_rate(config.simulation.rate_hz)
            .map_err(|error| NodeError::Settings {
                scene: scene_name.clone(),
                error,
            })?;
        Ok(NodeSetup {
            args,
            names,
            params,
            config,
            settings,
            scene: scene_name,
        })
    }

    /// The frame and joint names of the scene, with `ros.frame_prefix`.
    pub fn frame_names(&self) -> FrameNames {
        FrameNames::new(
            &self.settings.frame_prefix,
            &self.settings.world_frame,
            self.config.nodes.ale.len(),
            self.config.nodes.lagrange.len(),
        )
    }
}

/// Run the node until SIGINT or SIGTERM (see the module documentation of
/// `ros`); with `record`, also write its topics into that new rosbag2
/// directory (`run --record DIR`).
pub fn run_node(
    scene: Option<PathBuf>,
    ros_args: &[String],
    record: Option<PathBuf>,
) -> Result<(), NodeError> {
    let setup = NodeSetup::load(scene.as_deref(), ros_args)?;
    let domain = domain_id_from_env(std::env::var("ROS_DOMAIN_ID").ok().as_deref())?;
    let sim = Simulation::new(setup.config.clone()).map_err(|error| NodeError::Simulation {
        scene: setup.scene.clone(),
        error,
    })?;
    if let Some(text) = sim.model().thickness_warning_text() {
        eprintln!("[annular_plate] warning: {text}");
    }
    // The bag first: a directory that exists is refused before any DDS traffic.
    let bag = match &record {
        Some(dir) => {
            let models: Vec<_> = model_topics(&sim).into_iter().map(|(_, t)| t).collect();
            let topics = NodeTopics::resolve(
                &setup.names,
                setup.settings.sim_time,
                &models,
                setup.settings.marker.every(1.0 / sim.dt()).is_some(),
            )
            .map_err(NodeError::Record)?;
            Some(NodeBag::create(dir, &topics)?)
        }
        None => None,
    };
    let rt = tokio::runtime::Builder::new_multi_thread()
        .worker_threads(2)
        .thread_name("annular_plate-io")
        .enable_all()
        .build()
        .map_err(|error| NodeError::System {
            what: "cannot start the tokio runtime",
            error,
        })?;
    rt.block_on(serve(setup, sim, domain, bag))
}

fn publisher<T: RosType, P: Serialize>(
    node: &mut Node,
    names: &NameResolver,
    topic: &str,
    qos: &QosProfile,
) -> Result<Publisher<P>, NodeError> {
    typed_publisher(
        node,
        names,
        topic,
        MessageTypeName::new(T::PACKAGE, T::NAME),
        qos,
    )
}

/// A publisher of `P` on `topic` with the ROS type `type_name`.
fn typed_publisher<P: Serialize>(
    node: &mut Node,
    names: &NameResolver,
    topic: &str,
    type_name: MessageTypeName,
    qos: &QosProfile,
) -> Result<Publisher<P>, NodeError> {
    let resolved = names.resolve(topic)?;
    let name =
        Name::parse(&resolved).map_err(|e| NodeError::dds(format!("topic {resolved}"), e))?;
    let t = node
        .create_topic(&name, type_name, qos)
        .map_err(|e| NodeError::dds(format!("cannot create the topic {resolved}"), e))?;
    node.create_publisher::<P>(&t, Some(qos.clone()))
        .map_err(|e| NodeError::dds(format!("cannot publish {resolved}"), e))
}

fn subscription<T: RosType + 'static>(
    node: &mut Node,
    resolved: &str,
    qos: &QosProfile,
) -> Result<Subscription<T>, NodeError> {
    let name = Name::parse(resolved).map_err(|e| NodeError::dds(format!("topic {resolved}"), e))?;
    let t = node
        .create_topic(&name, MessageTypeName::new(T::PACKAGE, T::NAME), qos)
        .map_err(|e| NodeError::dds(format!("cannot create the topic {resolved}"), e))?;
    node.create_subscription::<T>(&t, Some(qos.clone()))
        .map_err(|e| NodeError::dds(format!("cannot subscribe {resolved}"), e))
}

fn to_wrench(w: &crate::messages::types::Wrench) -> Wrench {
    Wrench {
        force: w.force.to_array(),
        moment: w.torque.to_array(),
    }
}

/// The node's output publishers (a load model's state topic only for a scene with it).
fn create_publishers(
    node: &mut Node,
    names: &NameResolver,
    settings: &RosSettings,
    sim: &Simulation,
) -> Result<Publishers, NodeError> {
    Ok(Publishers {
        joint_states: publisher::<JointState, Shared<JointState>>(
            node,
            names,
            topics::JOINT_STATES,
            &qos::STATE,
        )?,
        tf: publisher::<TFMessage, Shared<TFMessage>>(node, names, topics::TF, &qos::TF)?,
        modal: publisher::<ModalAmplitudes, Shared<ModalAmplitudes>>(
            node,
            names,
            topics::MODAL_AMPLITUDES,
            &qos::STATE,
        )?,
        models: model_topics(sim)
            .iter()
            .map(|(_, t)| {
                let ty = MessageTypeName::new(t.package, t.message);
                typed_publisher::<Shared<ModelStates>>(node, names, t.topic, ty, &qos::STATE)
            })
            .collect::<Result<_, _>>()?,
        clock: settings
            .sim_time
            .then(|| publisher::<Clock, Clock>(node, names, topics::CLOCK, &qos::CLOCK))
            .transpose()?,
        diagnostics: publisher::<DiagnosticArray, DiagnosticArray>(
            node,
            names,
            topics::DIAGNOSTICS,
            &qos::DIAGNOSTICS,
        )?,
    })
}

/// `~/plate_marker` (unless `ros.marker_rate_hz` is 0): its publisher and thread.
fn start_marker(
    node: &mut Node,
    setup: &NodeSetup,
    sim: &Simulation,
    frames: &FrameNames,
    recorder: Option<Recorder>,
) -> Result<Option<(MarkerFeed, std::thread::JoinHandle<()>)>, NodeError> {
    let rate_hz = 1.0 / sim.dt();
    let Some(every) = setup.settings.marker.every(rate_hz) else {
        return Ok(None);
    };
    let publisher = publisher::<MarkerArray, Shared<MarkerArray>>(
        node,
        &setup.names,
        topics::PLATE_MARKER,
        &qos::MARKER,
    )?;
    let marker = PlateMarker::new(
        sim.model(),
        frames,
        &setup.settings.marker,
        rate_hz / every as f64,
    );
    let started =
        super::marker_thread::start(sim, marker, every, publisher, recorder).map_err(|error| {
            NodeError::System {
                what: "cannot start the marker thread",
                error,
            }
        })?;
    Ok(Some(started))
}

/// `run --record`: the writer thread, fed by the loop; /tf_static goes first.
fn start_recording(
    bag: Option<NodeBag>,
    static_msg: &TFMessage,
    stamp: Time,
    logger: &Logger,
) -> Result<Option<(Recorder, RecorderThread)>, NodeError> {
    let Some(bag) = bag else { return Ok(None) };
    let dir = bag.dir().display().to_string();
    let (recorder, thread) =
        Recorder::start(bag, RECORD_QUEUE).map_err(|error| NodeError::System {
            what: "cannot start the bag writer thread",
            error,
        })?;
    recorder.record(Sample::TfStatic(static_msg.clone()), stamp);
    logger.info(&format!("recording the node's topics to {dir}"));
    Ok(Some((recorder, thread)))
}

/// The input topics the loop reads (`ros/input_polling.rs`): the speed command, the node wrenches, the wrench array.
fn subscribe_inputs(
    node: &mut Node,
    names: &NameResolver,
    frames: &FrameNames,
    ctx: &InputContext,
) -> Result<Vec<Box<dyn PolledInput>>, NodeError> {
    let mut inputs = Vec::new();
    let topic = names.resolve(topics::SPEED_COMMAND)?;
    let sub = subscription::<Float64>(node, &topic, &qos::INPUT)?;
    inputs.push(polled(
        sub,
        topic,
        Source::SpeedCommand,
        ctx.clone(),
        |v, m: Float64| Ok((v.speed(m.data)?, 0)),
    ));
    for (kind, count) in [
        (NodeKind::Ale, frames.ale.len()),
        (NodeKind::Lagrange, frames.lagrange.len()),
    ] {
        for node_index in 0..count {
            let topic = names.resolve(&topics::node_wrench(kind, node_index + 1))?;
            let sub = subscription::<WrenchStamped>(node, &topic, &qos::INPUT)?;
            inputs.push(polled(
                sub,
                topic,
                Source::NodeWrench,
                ctx.clone(),
                move |v, m: WrenchStamped| {
                    let stamp = m.header.stamp.to_nanos();
                    Ok((
                        v.wrench_stamped(
                            kind,
                            node_index,
                            &m.header.frame_id,
                            to_wrench(&m.wrench),
                        )?,
                        stamp,
                    ))
                },
            ));
        }
    }
    let topic = names.resolve(topics::WRENCHES)?;
    let sub = subscription::<NodeWrenchArray>(node, &topic, &qos::INPUT)?;
    inputs.push(polled(
        sub,
        topic,
        Source::WrenchArray,
        ctx.clone(),
        |v, m: NodeWrenchArray| {
            let stamp = m.header.stamp.to_nanos();
            Ok((
                v.batch(
                    m.wrenches
                        .iter()
                        .map(|w| (w.kind, w.index, to_wrench(&w.wrench))),
                )?,
                stamp,
            ))
        },
    ));
    Ok(inputs)
}

/// The load models' commands, discovered from their specs: a std_msgs/Float64
/// topic per instance (`~/pad_<j>/clamp_force`, `~/tool_feed`) and, for
/// numbered instances, one batch topic (`~/pad_clamp_forces`, PadClampForces).
fn subscribe_load_commands(
    node: &mut Node,
    names: &NameResolver,
    rules: &InputRules,
    ctx: &InputContext,
) -> Result<Vec<Box<dyn PolledInput>>, NodeError> {
    let mut inputs = Vec::new();
    for (model, command, spec, instances) in rules.load_commands() {
        let source = Source::of_load_command(spec.indexed, false);
        for instance in 0..instances {
            let topic = names.resolve(&topics::load_command(spec, instance + 1))?;
            let sub = subscription::<Float64>(node, &topic, &qos::INPUT)?;
            inputs.push(polled(
                sub,
                topic,
                source,
                ctx.clone(),
                move |v, m: Float64| Ok((v.load_command(model, command, instance, m.data)?, 0)),
            ));
        }
        if spec.indexed {
            let topic = names.resolve(&topics::load_batch(spec))?;
            let sub = subscription::<PadClampForces>(node, &topic, &qos::INPUT)?;
            inputs.push(polled(
                sub,
                topic,
                Source::of_load_command(true, true),
                ctx.clone(),
                move |v, m: PadClampForces| {
                    Ok((
                        v.load_batch(model, command, &m.pad, &m.clamp_force)?,
                        m.header.stamp.to_nanos(),
                    ))
                },
            ));
        }
    }
    Ok(inputs)
}

/// Reset, pause and step services and the six parameter services.
fn start_services(
    node: &mut Node,
    setup: &NodeSetup,
    tx: &SyncSender<Command>,
) -> Result<Vec<JoinHandle<()>>, NodeError> {
    let (names, settings) = (&setup.names, &setup.settings);
    let service_names = [
        names.resolve(services::RESET)?,
        names.resolve(services::SET_PAUSED)?,
        names.resolve(services::STEP)?,
    ];
    let mut tasks = services::spawn(
        node,
        settings.service_mapping,
        [&service_names[0], &service_names[1], &service_names[2]],
        tx.clone(),
    )?;
    use super::sim_services as si;
    let si_names = [
        names.resolve(si::RESET_SIMULATION)?,
        names.resolve(si::STEP_SIMULATION)?,
        names.resolve(si::GET_SIMULATION_STATE)?,
        names.resolve(si::SET_SIMULATION_STATE)?,
    ];
    tasks.extend(si::spawn(
        node,
        settings.service_mapping,
        [&si_names[0], &si_names[1], &si_names[2], &si_names[3]],
        tx.clone(),
    )?);
    let store = Arc::new(Mutex::new(ParamStore::new(effective_parameters(
        &setup.params,
        settings,
    ))));
    tasks.extend(super::params_service::spawn(
        node,
        settings.service_mapping,
        &names.fully_qualified_node_name(),
        store,
        tx.clone(),
    )?);
    Ok(tasks)
}

/// The loop's settings from the scene and the node's `ros.*` settings.
fn loop_settings(setup: &NodeSetup) -> LoopSettings {
    let (settings, simulation) = (&setup.settings, &setup.config.simulation);
    LoopSettings {
        publish_divisor: simulation.publish_divisor,
        realtime_factor: simulation.realtime_factor,
        start_paused: settings.start_paused,
        sim_time: settings.sim_time,
        follow_clock: settings.use_sim_time,
        max_clock_jump: settings.max_clock_jump,
        wrench_timeout: settings.wrench_timeout,
        diagnostics_period: Duration::from_secs_f64(settings.diagnostics_period),
        node_name: setup.names.fully_qualified_node_name(),
    }
}

/// The simulation thread; the receiver fires when its loop ends.
fn start_loop(
    sim_loop: SimLoop,
) -> Result<
    (
        std::thread::JoinHandle<()>,
        tokio::sync::oneshot::Receiver<()>,
    ),
    NodeError,
> {
    let (done_tx, done_rx) = tokio::sync::oneshot::channel::<()>();
    let thread = std::thread::Builder::new()
        .name("annular_plate-sim".into())
        .spawn(move || {
            sim_loop.run();
            let _ = done_tx.send(());
        })
        .map_err(|error| NodeError::System {
            what: "cannot start the simulation thread",
            error,
        })?;
    Ok((thread, done_rx))
}

/// The start-up line: scene, nodes, modes, load models, clock.
fn startup_line(setup: &NodeSetup, sim: &Simulation, domain: u16) -> String {
    let frames = setup.frame_names();
    let models: Vec<&str> = sim.scene().load_models.names().collect();
    format!(
        "{} up on ROS_DOMAIN_ID {domain}: scene {}, {} ALE and {} Lagrangian nodes, {} modes, load models: {}, {} time",
        setup.names.fully_qualified_node_name(),
        setup.scene,
        frames.ale.len(),
        frames.lagrange.len(),
        sim.model().n_modes(),
        if models.is_empty() { "none".to_string() } else { models.join(", ") },
        match (setup.settings.sim_time, setup.settings.use_sim_time) {
            (true, _) => "simulated (publishing /clock)",
            (_, true) => "following /clock (use_sim_time)",
            _ => "wall-clock",
        }
    )
}

/// Wait for SIGINT, SIGTERM or the loop's end; say which.
async fn wait_for_stop(
    done_rx: tokio::sync::oneshot::Receiver<()>,
) -> Result<StopReason, NodeError> {
    use tokio::signal::unix::{signal, SignalKind};
    let mut sigint = signal(SignalKind::interrupt()).map_err(|error| NodeError::System {
        what: "cannot handle SIGINT",
        error,
    })?;
    let mut sigterm = signal(SignalKind::terminate()).map_err(|error| NodeError::System {
        what: "cannot handle SIGTERM",
        error,
    })?;
    Ok(tokio::select! {
        _ = sigint.recv() => StopReason::Signal("SIGINT"),
        _ = sigterm.recv() => StopReason::Signal("SIGTERM"),
        _ = done_rx => StopReason::LoopEnded,
    })
}

/// Let the writer thread finish the bag; `Err` with the reason if it could not.
async fn finish_recording(thread: RecorderThread, logger: &Logger) -> Result<(), String> {
    let r = tokio::task::spawn_blocking(move || thread.finish())
        .await
        .map_err(|e| format!("the bag writer thread failed: {e}"))?;
    match &r.summary {
        Ok(s) => {
            let msg = format!(
                "recorded {} messages on {} topics ({:.3} s, {} bytes) to {}; {} dropped",
                s.message_count,
                s.topics.len(),
                s.duration as f64 * 1e-9,
                s.bytes,
                s.dir.display(),
                r.dropped
            );
            if r.dropped > 0 || r.error.is_some() {
                logger.warn(&format!(
                    "{msg}{}",
                    r.error
                        .as_ref()
                        .map(|e| format!("; stopped early: {e}"))
                        .unwrap_or_default()
                ));
            } else {
                logger.info(&msg);
            }
            Ok(())
        }
        Err(e) => {
            logger.error(&format!("the bag could not be finished: {e}"));
            Err(e.clone())
        }
    }
}

async fn serve(
    setup: NodeSetup,
    sim: Simulation,
    domain: u16,
    bag: Option<NodeBag>,
) -> Result<(), NodeError> {
    let (names, settings) = (&setup.names, &setup.settings);
    let context = Context::with_options(ContextOptions::new().domain_id(domain))
        .map_err(|e| NodeError::dds(format!("cannot join DDS domain {domain}"), e))?;
    let mut node = context
        .new_node(
            NodeName::new(names.namespace(), names.node_name())
                .map_err(|e| NodeError::dds("node name", e))?,
            // No Spinner and no built-in parameter services: see messages/clock.rs.
            NodeOptions::new()
                .enable_rosout(setup.args.rosout_logs)
                .start_parameter_services(false),
        )
        .map_err(|e| NodeError::dds("cannot create the node", e))?;
    let logger = Arc::new(Logger::new(
        setup.args.rosout_logs.then(|| node.logging_handle()),
        names.node_name(),
        setup.args.stdout_logs,
        parse_level(setup.args.log_level.as_deref()),
        Duration::from_secs_f64(settings.reject_log_period),
    ));
    let frames = setup.frame_names();

    let pubs = create_publishers(&mut node, names, settings, &sim)?;
    let tf_static =
        publisher::<TFMessage, TFMessage>(&mut node, names, topics::TF_STATIC, &qos::TF_STATIC)?;
    let static_stamp = if settings.sim_time || settings.use_sim_time {
        Time::default()
    } else {
        Time::wall_now()
    };
    let static_msg = static_transforms(&frames, setup.config.reference.tilt, static_stamp);
    let recording = start_recording(bag, &static_msg, static_stamp, &logger)?;
    if let Err(e) = tf_static.publish(static_msg) {
        logger.warn(&format!("could not publish /tf_static: {e:?}"));
    }
    let critical_pub = publisher::<CriticalSpeeds, CriticalSpeeds>(
        &mut node,
        names,
        topics::CRITICAL_SPEEDS,
        &qos::CRITICAL_SPEEDS,
    )?;
    let critical = super::critical_speeds::publish(&critical_pub, &sim, &setup.config, &logger);

    // The loop's queue, shared by inputs and services.
    let (tx, rx) = sync_channel::<Command>(COMMAND_QUEUE);
    let stats = Arc::new(InputStats::default());
    let ctx = InputContext {
        validator: Arc::new(InputValidator::new(
            frames.ale.clone(),
            frames.lagrange.clone(),
            sim.scene().rules.clone(),
        )),
        stats: Arc::clone(&stats),
        logger: Arc::clone(&logger),
    };
    let mut inputs = subscribe_inputs(&mut node, names, &frames, &ctx)?;
    inputs.extend(subscribe_load_commands(
        &mut node,
        names,
        &sim.scene().rules,
        &ctx,
    )?);
    let mut tasks = start_services(&mut node, &setup, &tx)?;
    if settings.use_sim_time {
        tasks.push(super::clock_input::spawn(
            &mut node,
            &names.resolve(topics::CLOCK)?,
            tx.clone(),
        )?);
    }

    let line = startup_line(&setup, &sim, domain);
    let outputs = OutputMessages::new(&sim, &frames);
    let mut sim_loop = SimLoop::new(
        sim,
        outputs,
        pubs,
        rx,
        Arc::clone(&stats),
        Arc::clone(&logger),
        loop_settings(&setup),
    )
    .with_inputs(inputs)
    .with_critical_speeds(critical);
    if settings.step_aligned_reception {
        sim_loop = sim_loop.with_step_aligned_receive(StepAlignedReceive::new(
            context.domain_participant().receive_gate(),
        ));
    }
    let (recorder, record_thread) = recording.unzip();
    let marker_thread = match start_marker(
        &mut node,
        &setup,
        sim_loop.simulation(),
        &frames,
        recorder.clone(),
    )? {
        Some((feed, join)) => {
            sim_loop = sim_loop.with_marker(feed);
            Some(join)
        }
        None => None,
    };
    if let Some(recorder) = recorder {
        sim_loop = sim_loop.with_recorder(recorder);
    }
    let (sim_thread, done_rx) = start_loop(sim_loop)?;
    super::heap::spawn_trimmer().map_err(|error| NodeError::System {
        what: "cannot start the heap-trimming thread",
        error,
    })?;
    logger.info(&line);

    let why = wait_for_stop(done_rx).await?;
    logger.info(&format!("{why}: shutting down"));
    // A hung shutdown must not keep the process: give it two seconds.
    std::thread::spawn(|| {
        std::thread::sleep(Duration::from_secs(2));
        eprintln!("[annular_plate] shutdown took too long; exiting");
        std::process::exit(1);
    });

    // Order: service tasks (they hold servers and senders), then the loop (it
    // holds the publishers and the input subscriptions), then the node and
    // the context.
    for t in &tasks {
        t.abort();
    }
    for t in tasks {
        let _ = t.await;
    }
    let _ = tx.try_send(Command::Stop);
    drop(tx);
    drop(ctx);
    let joined = tokio::task::spawn_blocking(move || sim_thread.join()).await;
    // The loop dropped the marker feed: the marker thread ends (and with it
    // its handle on the recorder's queue).
    if let Some(t) = marker_thread {
        let _ = tokio::task::spawn_blocking(move || t.join()).await;
    }
    // The loop (and with it the recorder's queue) is gone: the writer
    // thread drains the queue, finishes the MCAP file and metadata.yaml.
    let record_failed = match record_thread {
        Some(thread) => finish_recording(thread, &logger).await.err(),
        None => None,
    };
    let result = if !matches!(joined, Ok(Ok(()))) {
        logger.error("the simulation thread ended abnormally");
        Err(NodeError::SimulationThread)
    } else if let Some(e) = record_failed {
        Err(NodeError::Record(e))
    } else {
        match why {
            StopReason::Signal(_) => Ok(()),
            StopReason::LoopEnded => Err(NodeError::Stopped(why)),
        }
    };
    drop(tf_static);
    drop(critical_pub);
    drop(logger);
    drop(node);
    drop(context);
    result
}
