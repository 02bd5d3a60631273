//! The ROS 2 standard simulator-control interfaces the node serves
//! (package `simulation_interfaces`, 1.0/2.0 as released for Humble, Jazzy,
//! Kilted and Rolling): plain serde structs in `.msg` / `.srv` field order
//! like those in [`types`](super::types), so tools written for Gazebo
//! (`/gzserver/step_simulation`, …) drive the plate too.
//! `tests/ros_messages_match_msg_files.rs` checks them against the upstream
//! definitions; docs/ros.md ("Services") says what each call does here.

use ros2_client::Message;
use serde::{Deserialize, Serialize};

/// simulation_interfaces/msg/Result: a result code and a message (named
/// `SimResult` in Rust, beside `std::result::Result`; `Result` to serde).
#[derive(Debug, Clone, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename = "Result")]
pub struct SimResult {
    /// One of the `RESULT_*` codes (or a service's own, above 100).
    pub result: u8,
    /// What went wrong, or what was done.
    pub error_message: String,
}
impl Message for SimResult {}

impl SimResult {
    /// `result`: the call is not supported here.
    pub const RESULT_FEATURE_UNSUPPORTED: u8 = 0;
    /// `result`: done.
    pub const RESULT_OK: u8 = 1;
    /// `result`: what the call names does not exist.
    pub const RESULT_NOT_FOUND: u8 = 2;
    /// `result`: not possible in the simulation's current state.
    pub const RESULT_INCORRECT_STATE: u8 = 3;
    /// `result`: tried and failed.
    pub const RESULT_OPERATION_FAILED: u8 = 4;

    /// [`SimResult::RESULT_OK`] with a message.
    pub fn ok(message: impl Into<String>) -> Self {
        SimResult {
            result: Self::RESULT_OK,
            error_message: message.into(),
        }
    }

    /// Any result code with a message.
    pub fn code(result: u8, message: impl Into<String>) -> Self {
        SimResult {
            result,
            error_message: message.into(),
        }
    }
}

/// simulation_interfaces/msg/SimulationState.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
pub struct SimulationState {
    /// One of the `STATE_*` constants.
    pub state: u8,
}
impl Message for SimulationState {}

impl SimulationState {
    /// Stopped: reset to the start and not running.
    pub const STATE_STOPPED: u8 = 0;
    /// Running.
    pub const STATE_PLAYING: u8 = 1;
    /// Paused: steps only on request.
    pub const STATE_PAUSED: u8 = 2;
    /// Shutting down.
    pub const STATE_QUITTING: u8 = 3;
}

/// simulation_interfaces/srv/ResetSimulation request.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
pub struct ResetSimulationRequest {
    /// What to reset: a `SCOPE_*` constant or a bitwise or of them.
    pub scope: u8,
}
impl Message for ResetSimulationRequest {}

impl ResetSimulationRequest {
    /// `scope`: the simulator's default reset.
    pub const SCOPE_DEFAULT: u8 = 0;
    /// `scope`: the simulated time.
    pub const SCOPE_TIME: u8 = 1;
    /// `scope`: the state of the simulated bodies.
    pub const SCOPE_STATE: u8 = 2;
    /// `scope`: remove spawned entities.
    pub const SCOPE_SPAWNED: u8 = 4;
    /// `scope`: everything.
    pub const SCOPE_ALL: u8 = 255;
}

/// simulation_interfaces/srv/ResetSimulation response.
#[derive(Debug, Clone, PartialEq, Eq, Default, Serialize, Deserialize)]
pub struct ResetSimulationResponse {
    /// The outcome.
    pub result: SimResult,
}
impl Message for ResetSimulationResponse {}

/// simulation_interfaces/srv/StepSimulation request.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
pub struct StepSimulationRequest {
    /// Steps to take, each published; above `u32::MAX` per call is refused.
    pub steps: u64,
}
impl Message for StepSimulationRequest {}

/// simulation_interfaces/srv/StepSimulation response.
#[derive(Debug, Clone, PartialEq, Eq, Default, Serialize, Deserialize)]
pub struct StepSimulationResponse {
    /// The outcome.
    pub result: SimResult,
}
impl Message for StepSimulationResponse {}

/// simulation_interfaces/srv/GetSimulationState request (empty in the
/// .srv; ROS 2's IDL gives an empty structure one
/// `uint8 structure_needs_at_least_one_member`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
pub struct GetSimulationStateRequest {
    /// Always 0: the member ROS 2's IDL gives an empty structure.
    pub structure_needs_at_least_one_member: u8,
}
impl Message for GetSimulationStateRequest {}

/// simulation_interfaces/srv/GetSimulationState response.
#[derive(Debug, Clone, PartialEq, Eq, Default, Serialize, Deserialize)]
pub struct GetSimulationStateResponse {
    /// The simulation's state.
    pub state: SimulationState,
    /// The outcome.
    pub result: SimResult,
}
impl Message for GetSimulationStateResponse {}

/// simulation_interfaces/srv/SetSimulationState request.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
pub struct SetSimulationStateRequest {
    /// The state to go to.
    pub state: SimulationState,
}
impl Message for SetSimulationStateRequest {}

/// simulation_interfaces/srv/SetSimulationState response.
#[derive(Debug, Clone, PartialEq, Eq, Default, Serialize, Deserialize)]
pub struct SetSimulationStateResponse {
    /// The outcome (`result` may hold one of this type's codes).
    pub result: SimResult,
}
impl Message for SetSimulationStateResponse {}

impl SetSimulationStateResponse {
    /// `result.result`: the simulation already is in the requested state.
    pub const ALREADY_IN_TARGET_STATE: u8 = 101;
    /// `result.result`: the transition was tried and failed.
    pub const STATE_TRANSITION_ERROR: u8 = 102;
    /// `result.result`: the transition is not allowed from the current state.
    pub const INCORRECT_TRANSITION: u8 = 103;
}
