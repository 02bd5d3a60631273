//! QoS profiles of every endpoint, in one place (documented in docs/ros.md).
//!
//! The choices follow what ROS 2 tools and rclpy/rclcpp defaults expect
//! (see shared/ROS-NOTES.md): a reliable writer serves both reliable and
//! best-effort readers, so every output is reliable. Writers in the step
//! loop never wait for a full send window ([`WhenFull::Fail`]): a sample
//! that cannot be queued is dropped and counted in /diagnostics rather than
//! stalling the fixed-rate loop.

use ros2_client::qos::{Durability, History, Reliability, WhenFull};
use ros2_client::QosProfile;

const fn reliable(depth: usize, durability: Durability) -> QosProfile {
    QosProfile::subscription_default()
        .reliability(Reliability::Reliable {
            when_full: WhenFull::Fail,
        })
        .durability(durability)
        .history(History::KeepLast { depth })
}

/// `/joint_states`, `~/modal_amplitudes`: reliable, volatile, keep last 10.
pub const STATE: QosProfile = reliable(10, Durability::Volatile);

/// `/tf`: reliable, volatile, keep last 100 (as tf2_ros's broadcaster).
pub const TF: QosProfile = reliable(100, Durability::Volatile);

/// `/tf_static`: reliable, transient-local, keep last 1: all static
/// transforms travel in one message that late joiners still receive.
pub const TF_STATIC: QosProfile = reliable(1, Durability::TransientLocal);

/// `~/critical_speeds`: reliable, transient-local, keep last 1, like
/// `/tf_static`: published once, late joiners still receive it.
pub const CRITICAL_SPEEDS: QosProfile = reliable(1, Durability::TransientLocal);

/// `~/plate_marker`: reliable, volatile, keep last 1 (RViz's marker
/// display subscribes reliable; only the newest picture matters).
pub const MARKER: QosProfile = reliable(1, Durability::Volatile);

/// `/clock`: reliable, volatile, keep last 1. Matches rclcpp's
/// best-effort `ClockQoS` readers and rclpy's reliable depth-10 default.
pub const CLOCK: QosProfile = reliable(1, Durability::Volatile);

/// `/clock` as followed with `use_sim_time: true`: best effort, volatile,
/// keep last 1 — rclcpp's `ClockQoS`; it matches reliable and best-effort
/// clock writers alike.
pub const CLOCK_SUBSCRIPTION: QosProfile = QosProfile::subscription_default()
    .reliability(Reliability::BestEffort)
    .durability(Durability::Volatile)
    .history(History::KeepLast { depth: 1 });

/// `/diagnostics`: reliable, volatile, keep last 10.
pub const DIAGNOSTICS: QosProfile = reliable(10, Durability::Volatile);

/// Inputs (`~/speed_command`, wrenches, `~/wrenches`): reliable, volatile,
/// keep last 10 — the rclpy/rclcpp publisher default (`create_publisher(T, name, 10)`).
/// A best-effort publisher does not match; see docs/ros.md.
pub const INPUT: QosProfile = reliable(10, Durability::Volatile);

/// Services (requests and replies): reliable, volatile, keep last 10, as
/// rclcpp's `rmw_qos_profile_services_default`.
pub const SERVICE: QosProfile = QosProfile::subscription_default()
    .reliability(Reliability::Reliable {
        when_full: WhenFull::DEFAULT,
    })
    .durability(Durability::Volatile)
    .history(History::KeepLast { depth: 10 });
