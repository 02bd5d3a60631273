//! `use_sim_time: true`: the `/clock` subscription. Each message's time
//! goes to the simulation loop as [`Command::Clock`]; the loop's
//! `ClockFollower` (messages/clock_follower.rs) turns it into steps.
//!
//! QoS as rclcpp's `TimeSource` (`rclcpp::ClockQoS`): best effort, keep
//! last 1, volatile — it matches reliable and best-effort clock publishers
//! (Gazebo, `ros2 bag play --clock`, another annular_plate with
//! `ros.publish_clock: true`). A message that does not fit the loop's
//! queue is dropped: the next one carries the newer time, and only the
//! newest time decides what is due.

use super::error::NodeError;
use super::services::Command;
use crate::messages::types::Clock;
use crate::messages::RosType;
use futures::StreamExt;
use ros2_client::{MessageTypeName, Name, Node};
use std::sync::mpsc::{SyncSender, TrySendError};
use tokio::task::JoinHandle;

/// Subscribe `resolved` (normally `/clock`) and feed the loop.
pub fn spawn(
    node: &mut Node,
    resolved: &str,
    tx: SyncSender<Command>,
) -> Result<JoinHandle<()>, NodeError> {
    let name = Name::parse(resolved).map_err(|e| NodeError::dds(format!("topic {resolved}"), e))?;
    let topic = node
        .create_topic(
            &name,
            MessageTypeName::new(Clock::PACKAGE, Clock::NAME),
            &crate::messages::qos::CLOCK_SUBSCRIPTION,
        )
        .map_err(|e| NodeError::dds(format!("cannot create the topic {resolved}"), e))?;
    let sub = node
        .create_subscription::<Clock>(&topic, Some(crate::messages::qos::CLOCK_SUBSCRIPTION))
        .map_err(|e| NodeError::dds(format!("cannot subscribe {resolved}"), e))?;
    Ok(tokio::spawn(async move {
        let stream = sub.async_stream();
        futures::pin_mut!(stream);
        while let Some(item) = stream.next().await {
            // An undecodable sample carries no time: nothing to follow.
            let Ok((msg, _info)) = item else { continue };
            match tx.try_send(Command::Clock(msg.clock.to_nanos())) {
                Ok(()) | Err(TrySendError::Full(_)) => {}
                Err(TrySendError::Disconnected(_)) => return,
            }
        }
    }))
}
