//! The node's services, in the style of Gazebo and mujoco_ros2_control
//! (docs/ros.md, "Services"):
//!
//! | service          | type                    | what it does |
//! |------------------|-------------------------|--------------|
//! | `~/reset`        | std_srvs/srv/Trigger    | back to the initial state of the scene (t = 0, file loads and speed); the ROS clock keeps counting |
//! | `~/set_paused`   | std_srvs/srv/SetBool    | `data: true` pauses, `false` resumes |
//! | `~/step`         | annular_plate/srv/Step  | while paused: advance N steps as fast as possible, publishing each |
//!
//! Each request becomes a [`Command`] for the simulation loop, which
//! answers through a oneshot channel once it has done the work, so a
//! response always describes the state after the request.

use super::inputs::{Input, Source};
use crate::messages::qos;
use crate::messages::types::{
    SetBoolRequest, SetBoolResponse, StepRequest, StepResponse, TriggerRequest, TriggerResponse,
};
use ros2_client::{Message, Name, Node, Server, ServiceMapping, ServiceTypeName};
use std::future::Future;
use std::sync::mpsc::{SyncSender, TrySendError};
use tokio::sync::oneshot;
use tokio::task::JoinHandle;

/// A change accepted at run time, for the simulation loop.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum RuntimeChange {
    /// `simulation.realtime_factor` (0: as fast as possible).
    RealtimeFactor(f64),
    /// `ros.wrench_timeout`, s.
    WrenchTimeout(f64),
}

/// The loop's state, as a status query sees it.
#[derive(Debug, Clone, PartialEq)]
pub struct LoopStatus {
    pub paused: bool,
    /// Why the simulation diverged, if it did (it then takes no step until a reset).
    pub diverged: Option<String>,
    pub step: u64,
    pub sim_time: f64,
}

/// Everything the simulation loop is told, in arrival order.
#[derive(Debug)]
pub enum Command {
    /// A checked input from a topic.
    Input(
        Input,
        Source,
        /* stamp of the input's header, ns (0: none) */ i64,
    ),
    Reset(oneshot::Sender<TriggerResponse>),
    SetPaused(bool, oneshot::Sender<SetBoolResponse>),
    Step(u32, oneshot::Sender<StepResponse>),
    Runtime(RuntimeChange),
    /// A `/clock` message (ns), `use_sim_time: true` only (`clock_input.rs`).
    Clock(i64),
    /// Report the loop's state (`sim_services.rs`, GetSimulationState).
    Status(oneshot::Sender<LoopStatus>),
    Stop,
}

/// Service names of this node, before name resolution.
pub const RESET: &str = "~/reset";
pub const SET_PAUSED: &str = "~/set_paused";
pub const STEP: &str = "~/step";

/// Serve `server` until the task is aborted: each request is answered with
/// `handler(request).await`. Undecodable requests are skipped.
pub fn spawn_server<Req, Resp, F, Fut>(
    server: Server<Req, Resp>,
    name: String,
    mut handler: F,
) -> JoinHandle<()>
where
    Req: Message + Clone + Send + Sync + 'static,
    Resp: Message + Send + Sync + 'static,
    F: FnMut(Req) -> Fut + Send + 'static,
    Fut: Future<Output = Resp> + Send,
{
    tokio::spawn(async move {
        loop {
            match server.async_receive_request().await {
                Ok((id, req)) => {
                    let resp = handler(req).await;
                    if let Err(e) = server.async_send_response(id, resp).await {
                        eprintln!("[annular_plate] {name}: could not send the response: {e:?}");
                    }
                }
                Err(e) => eprintln!("[annular_plate] {name}: undecodable request ignored: {e:?}"),
            }
        }
    })
}

/// Create a server for a service type of this package or std_srvs.
pub fn create_server<Req, Resp>(
    node: &mut Node,
    mapping: ServiceMapping,
    resolved_name: &str,
    package: &str,
    type_name: &str,
) -> Result<Server<Req, Resp>, super::error::NodeError>
where
    Req: Message + Clone + 'static,
    Resp: Message + 'static,
{
    let name = Name::parse(resolved_name)
        .map_err(|e| super::error::NodeError::dds(format!("service name {resolved_name}"), e))?;
    node.create_server::<Req, Resp>(
        mapping,
        &name,
        &ServiceTypeName::new(package, type_name),
        qos::SERVICE,
        qos::SERVICE,
    )
    .map_err(|e| {
        super::error::NodeError::dds(format!("cannot create the service {resolved_name}"), e)
    })
}

pub(crate) fn busy<T>(e: TrySendError<T>) -> String {
    match e {
        TrySendError::Full(_) => {
            "the simulation is busy (command queue full); try again".to_string()
        }
        TrySendError::Disconnected(_) => "the simulation has stopped".to_string(),
    }
}

/// Spawn the three simulation services. `names` = resolved (reset, set_paused, step).
pub fn spawn(
    node: &mut Node,
    mapping: ServiceMapping,
    names: [&str; 3],
    tx: SyncSender<Command>,
) -> Result<Vec<JoinHandle<()>>, super::error::NodeError> {
    let reset = create_server::<TriggerRequest, TriggerResponse>(
        node, mapping, names[0], "std_srvs", "Trigger",
    )?;
    let paused = create_server::<SetBoolRequest, SetBoolResponse>(
        node, mapping, names[1], "std_srvs", "SetBool",
    )?;
    let step = create_server::<StepRequest, StepResponse>(
        node,
        mapping,
        names[2],
        "annular_plate",
        "Step",
    )?;

    let tx1 = tx.clone();
    let h1 = spawn_server(reset, names[0].to_string(), move |_req: TriggerRequest| {
        let (otx, orx) = oneshot::channel();
        let sent = tx1.try_send(Command::Reset(otx)).map_err(busy);
        async move {
            match sent {
                Ok(()) => orx.await.unwrap_or_else(|_| TriggerResponse {
                    success: false,
                    message: "the simulation has stopped".into(),
                }),
                Err(message) => TriggerResponse {
                    success: false,
                    message,
                },
            }
        }
    });
    let tx2 = tx.clone();
    let h2 = spawn_server(paused, names[1].to_string(), move |req: SetBoolRequest| {
        let (otx, orx) = oneshot::channel();
        let sent = tx2
            .try_send(Command::SetPaused(req.data, otx))
            .map_err(busy);
        async move {
            match sent {
                Ok(()) => orx.await.unwrap_or_else(|_| SetBoolResponse {
                    success: false,
                    message: "the simulation has stopped".into(),
                }),
                Err(message) => SetBoolResponse {
                    success: false,
                    message,
                },
            }
        }
    });
    let tx3 = tx;
    let h3 = spawn_server(step, names[2].to_string(), move |req: StepRequest| {
        let (otx, orx) = oneshot::channel();
        let sent = tx3.try_send(Command::Step(req.steps, otx)).map_err(busy);
        async move {
            match sent {
                Ok(()) => orx.await.unwrap_or_else(|_| StepResponse {
                    success: false,
                    message: "the simulation has stopped".into(),
                    ..StepResponse::default()
                }),
                Err(message) => StepResponse {
                    success: false,
                    message,
                    ..StepResponse::default()
                },
            }
        }
    });
    Ok(vec![h1, h2, h3])
}
