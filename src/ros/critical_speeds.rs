//! `~/critical_speeds` (docs/ros.md): computed once when the node
//! starts, as `annular_plate campbell` does (honouring
//! `plate.centrifugal_stiffening`), and published latched — reliable,
//! transient local, keep last 1 — so a late joiner still receives it. The
//! list also goes to the loop for the `<node>: critical speeds` status.

use super::logging::Logger;
use crate::config::Config;
use crate::dynamics::Simulation;
use crate::messages::critical_speeds::message;
use crate::messages::types::CriticalSpeeds;
use crate::model::campbell::{critical_speeds, CriticalSpeed};
use ros2_client::Publisher;

/// Compute the critical speeds and publish them once on `publisher` (created
/// by the node with `qos::CRITICAL_SPEEDS`;
/// it must live as long as the node: a transient-local writer serves late
/// joiners from its history). Returns the list for the loop's status.
pub fn publish(
    publisher: &Publisher<CriticalSpeeds>,
    sim: &Simulation,
    config: &Config,
    logger: &Logger,
) -> Vec<CriticalSpeed> {
    let speeds = critical_speeds(sim.model(), &config.centrifugal).unwrap_or_else(|e| {
        logger.warn(&format!(
            "~/critical_speeds: cannot compute the critical speeds ({e}); publishing none"
        ));
        Vec::new()
    });
    if let Err(e) = publisher.publish(message(&speeds, config.centrifugal.stiffening)) {
        logger.warn(&format!("could not publish ~/critical_speeds: {e:?}"));
    }
    speeds
}
