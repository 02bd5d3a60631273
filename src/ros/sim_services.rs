//! The ROS 2 standard simulator services (package `simulation_interfaces`),
//! beside the node's own `~/reset`, `~/set_paused`, `~/step`, under the names
//! Gazebo gives them (`/gzserver/step_simulation` → `~/step_simulation`):
//!
//! | service | type | here |
//! |---|---|---|
//! | `~/reset_simulation` | ResetSimulation | scope DEFAULT, ALL or one with SCOPE_STATE: as `~/reset` (the plate to t = 0; ROS time keeps counting); TIME or SPAWNED alone: RESULT_FEATURE_UNSUPPORTED |
//! | `~/step_simulation` | StepSimulation | while paused: `steps` steps, each published, answered when done; running: RESULT_OPERATION_FAILED (as the standard says) |
//! | `~/get_simulation_state` | GetSimulationState | STATE_PAUSED (paused or diverged) or STATE_PLAYING |
//! | `~/set_simulation_state` | SetSimulationState | PLAYING resumes, PAUSED pauses (ALREADY_IN_TARGET_STATE if it was), STOPPED pauses and resets, QUITTING: RESULT_FEATURE_UNSUPPORTED (stop the node with SIGINT) |
//!
//! Every call becomes commands for the simulation loop, in arrival order
//! with the inputs, answered once the loop has done the work — the same
//! commands as the node's own services, so both kinds agree.

use super::error::NodeError;
use super::services::{busy, create_server, spawn_server, Command, LoopStatus};
use crate::messages::simulation_interfaces::{
    GetSimulationStateRequest, GetSimulationStateResponse, ResetSimulationRequest,
    ResetSimulationResponse, SetSimulationStateRequest, SetSimulationStateResponse, SimResult,
    SimulationState, StepSimulationRequest, StepSimulationResponse,
};
use ros2_client::{Node, ServiceMapping};
use std::sync::mpsc::SyncSender;
use tokio::sync::oneshot;
use tokio::task::JoinHandle;

/// Service names of this node, before name resolution.
pub const RESET_SIMULATION: &str = "~/reset_simulation";
pub const STEP_SIMULATION: &str = "~/step_simulation";
pub const GET_SIMULATION_STATE: &str = "~/get_simulation_state";
pub const SET_SIMULATION_STATE: &str = "~/set_simulation_state";

const PACKAGE: &str = "simulation_interfaces";

/// Hand the loop one command and wait for its answer.
async fn ask<R>(
    tx: &SyncSender<Command>,
    command: impl FnOnce(oneshot::Sender<R>) -> Command,
) -> Result<R, String> {
    let (otx, orx) = oneshot::channel();
    tx.try_send(command(otx)).map_err(busy)?;
    orx.await
        .map_err(|_| "the simulation has stopped".to_string())
}

fn failed(message: String) -> SimResult {
    SimResult::code(SimResult::RESULT_OPERATION_FAILED, message)
}

async fn reset(tx: &SyncSender<Command>, scope: u8) -> SimResult {
    let resets_state = scope == ResetSimulationRequest::SCOPE_DEFAULT
        || scope & ResetSimulationRequest::SCOPE_STATE != 0;
    if !resets_state {
        return SimResult::code(
            SimResult::RESULT_FEATURE_UNSUPPORTED,
            format!("scope {scope}: this simulator resets the plate's state (SCOPE_DEFAULT, SCOPE_STATE or SCOPE_ALL); ROS time never goes back and nothing is spawned"),
        );
    }
    match ask(tx, Command::Reset).await {
        Ok(r) if r.success => SimResult::ok(r.message),
        Ok(r) => failed(r.message),
        Err(e) => failed(e),
    }
}

async fn step(tx: &SyncSender<Command>, steps: u64) -> SimResult {
    let Ok(n) = u32::try_from(steps) else {
        return failed(format!("steps = {steps}: at most {} per call", u32::MAX));
    };
    match ask(tx, |reply| Command::Step(n, reply)).await {
        Ok(r) if r.success => SimResult::ok(format!("at step {} (t = {} s)", r.step, r.sim_time)),
        Ok(r) => failed(r.message),
        Err(e) => failed(e),
    }
}

/// The standard's state for the loop's.
pub fn state_of(status: &LoopStatus) -> u8 {
    if status.paused || status.diverged.is_some() {
        SimulationState::STATE_PAUSED
    } else {
        SimulationState::STATE_PLAYING
    }
}

async fn get_state(tx: &SyncSender<Command>) -> GetSimulationStateResponse {
    match ask(tx, Command::Status).await {
        Ok(s) => {
            let mut message = format!("step {}, t = {} s", s.step, s.sim_time);
            if let Some(why) = &s.diverged {
                message.push_str(&format!("; diverged ({why}): reset it"));
            }
            GetSimulationStateResponse {
                state: SimulationState {
                    state: state_of(&s),
                },
                result: SimResult::ok(message),
            }
        }
        Err(e) => GetSimulationStateResponse {
            state: SimulationState::default(),
            result: failed(e),
        },
    }
}

/// Pause or resume; ALREADY_IN_TARGET_STATE when nothing changed.
async fn set_paused(tx: &SyncSender<Command>, pause: bool) -> SimResult {
    let before = match ask(tx, Command::Status).await {
        Ok(s) => s.paused,
        Err(e) => return failed(e),
    };
    match ask(tx, |reply| Command::SetPaused(pause, reply)).await {
        Ok(r) if before == pause => SimResult::code(
            SetSimulationStateResponse::ALREADY_IN_TARGET_STATE,
            r.message,
        ),
        Ok(r) => SimResult::ok(r.message),
        Err(e) => failed(e),
    }
}

async fn set_state(tx: &SyncSender<Command>, state: u8) -> SimResult {
    match state {
        SimulationState::STATE_PLAYING => set_paused(tx, false).await,
        SimulationState::STATE_PAUSED => set_paused(tx, true).await,
        SimulationState::STATE_STOPPED => {
            if let Err(e) = ask(tx, |reply| Command::SetPaused(true, reply)).await {
                return failed(e);
            }
            match reset(tx, ResetSimulationRequest::SCOPE_ALL).await {
                r if r.result == SimResult::RESULT_OK => SimResult::ok(format!("stopped: paused and {}", r.error_message)),
                r => r,
            }
        }
        SimulationState::STATE_QUITTING => SimResult::code(
            SimResult::RESULT_FEATURE_UNSUPPORTED,
            "STATE_QUITTING: stop the node with SIGINT or SIGTERM (its launch file or process manager)",
        ),
        other => failed(format!(
            "state.state = {other} is not one of STATE_STOPPED (0), STATE_PLAYING (1), STATE_PAUSED (2), STATE_QUITTING (3)"
        )),
    }
}

/// Spawn the four services. `names` = resolved (reset, step, get state, set state).
pub fn spawn(
    node: &mut Node,
    mapping: ServiceMapping,
    names: [&str; 4],
    tx: SyncSender<Command>,
) -> Result<Vec<JoinHandle<()>>, NodeError> {
    let reset_srv = create_server::<ResetSimulationRequest, ResetSimulationResponse>(
        node,
        mapping,
        names[0],
        PACKAGE,
        "ResetSimulation",
    )?;
    let step_srv = create_server::<StepSimulationRequest, StepSimulationResponse>(
        node,
        mapping,
        names[1],
        PACKAGE,
        "StepSimulation",
    )?;
    let get_srv = create_server::<GetSimulationStateRequest, GetSimulationStateResponse>(
        node,
        mapping,
        names[2],
        PACKAGE,
        "GetSimulationState",
    )?;
    let set_srv = create_server::<SetSimulationStateRequest, SetSimulationStateResponse>(
        node,
        mapping,
        names[3],
        PACKAGE,
        "SetSimulationState",
    )?;
    let (t1, t2, t3, t4) = (tx.clone(), tx.clone(), tx.clone(), tx);
    Ok(vec![
        spawn_server(
            reset_srv,
            names[0].to_string(),
            move |req: ResetSimulationRequest| {
                let tx = t1.clone();
                async move {
                    ResetSimulationResponse {
                        result: reset(&tx, req.scope).await,
                    }
                }
            },
        ),
        spawn_server(
            step_srv,
            names[1].to_string(),
            move |req: StepSimulationRequest| {
                let tx = t2.clone();
                async move {
                    StepSimulationResponse {
                        result: step(&tx, req.steps).await,
                    }
                }
            },
        ),
        spawn_server(
            get_srv,
            names[2].to_string(),
            move |_req: GetSimulationStateRequest| {
                let tx = t3.clone();
                async move { get_state(&tx).await }
            },
        ),
        spawn_server(
            set_srv,
            names[3].to_string(),
            move |req: SetSimulationStateRequest| {
                let tx = t4.clone();
                async move {
                    SetSimulationStateResponse {
                        result: set_state(&tx, req.state.state).await,
                    }
                }
            },
        ),
    ])
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_paused_or_diverged_loop_is_paused_a_running_one_playing() {
        let s = |paused, diverged: Option<&str>| LoopStatus {
            paused,
            diverged: diverged.map(String::from),
            step: 0,
            sim_time: 0.0,
        };
        assert_eq!(state_of(&s(true, None)), SimulationState::STATE_PAUSED);
        assert_eq!(
            state_of(&s(false, Some("NaN"))),
            SimulationState::STATE_PAUSED
        );
        assert_eq!(state_of(&s(false, None)), SimulationState::STATE_PLAYING);
    }
}
