//! Topic names, before resolution (`~` = the node's name, see `names.rs`).
//! Remap any of them with `-r from:=to`.
//!
//! `joint_states` is relative, as joint_state_publisher's: a namespace
//! (`-r __ns:=/bench`) moves it, so two discs in two namespaces do not mix
//! their joints. `/tf` and `/tf_static` stay absolute, as tf2's broadcasters
//! have them (one transform tree; `ros.frame_prefix` keeps the frames apart;
//! `-r /tf:=tf` moves them too).

use crate::dynamics::{CommandSpec, NodeKind};

pub const SPEED_COMMAND: &str = "~/speed_command";
pub const WRENCHES: &str = "~/wrenches";
pub const JOINT_STATES: &str = "joint_states";
pub const TF: &str = "/tf";
pub const TF_STATIC: &str = "/tf_static";
pub const MODAL_AMPLITUDES: &str = "~/modal_amplitudes";
/// The critical speeds, once at start (latched).
pub const CRITICAL_SPEEDS: &str = "~/critical_speeds";
/// The deformed plate for RViz / Foxglove (visualization_msgs/MarkerArray).
pub const PLATE_MARKER: &str = "~/plate_marker";
pub const CLOCK: &str = "/clock";
pub const DIAGNOSTICS: &str = "/diagnostics";
/// Only when the scene has pads (`pads.*`).
#[cfg(test)]
pub const PAD_CLAMP_FORCES: &str = "~/pad_clamp_forces";
/// Only when the scene has a tool (`tool.*`).
#[cfg(test)]
pub const TOOL_FEED: &str = "~/tool_feed";
// The load models' state topics (`~/pad_states`, `~/tool_state`) are
// declared by the models (`dynamics::load_models::outputs::StateTopic`).

/// `~/ale_<j>/wrench` or `~/lagrange_<j>/wrench`, j from 1 (a ROS name
/// token may not start with a digit, so not `~/ale/1/wrench`).
pub fn node_wrench(kind: NodeKind, j: usize) -> String {
    format!("~/{}_{j}/wrench", kind.name())
}

/// The topic of a load-model command for instance j (from 1): `~/<instance>_<j>/<token>`
/// for numbered instances (`~/pad_2/clamp_force`), `~/<instance>_<token>` otherwise (`~/tool_feed`).
pub fn load_command(spec: &CommandSpec, j: usize) -> String {
    if spec.indexed {
        format!("~/{}_{j}/{}", spec.instance, spec.token)
    } else {
        format!("~/{}_{}", spec.instance, spec.token)
    }
}

/// The batch topic of a numbered load-model command: `~/<instance>_<token>s` (`~/pad_clamp_forces`).
pub fn load_batch(spec: &CommandSpec) -> String {
    format!("~/{}_{}s", spec.instance, spec.token)
}

/// `~/pad_<j>/clamp_force`, pad j from 1.
#[cfg(test)]
pub fn pad_clamp_force(j: usize) -> String {
    format!("~/pad_{j}/clamp_force")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn node_wrench_topics() {
        assert_eq!(node_wrench(NodeKind::Ale, 3), "~/ale_3/wrench");
        assert_eq!(node_wrench(NodeKind::Lagrange, 1), "~/lagrange_1/wrench");
        assert_eq!(pad_clamp_force(1), "~/pad_1/clamp_force");
        // The load models' command topics, discovered from their specs, keep these names.
        use crate::dynamics::load_models::{pad::CLAMP_FORCE, tool::FEED_RATE};
        assert_eq!(load_command(&CLAMP_FORCE, 2), pad_clamp_force(2));
        assert_eq!(load_batch(&CLAMP_FORCE), PAD_CLAMP_FORCES);
        assert_eq!(load_command(&FEED_RATE, 1), TOOL_FEED);
    }

    #[test]
    fn a_namespace_moves_joint_states_but_not_the_transform_tree() {
        use crate::messages::names::{NameResolver, RosArgs};
        let resolve = |args: &[&str], topic: &str| {
            let a = RosArgs::parse(args).unwrap();
            NameResolver::new(&a, "annular_plate")
                .unwrap()
                .resolve(topic)
                .unwrap()
        };
        assert_eq!(resolve(&[], JOINT_STATES), "/joint_states");
        assert_eq!(
            resolve(&["--ros-args", "-r", "__ns:=/bench"], JOINT_STATES),
            "/bench/joint_states"
        );
        assert_eq!(resolve(&["--ros-args", "-r", "__ns:=/bench"], TF), "/tf");
        assert_eq!(
            resolve(
                &[
                    "--ros-args",
                    "-r",
                    "__ns:=/bench",
                    "-r",
                    "/bench/joint_states:=/joint_states"
                ],
                JOINT_STATES
            ),
            "/joint_states"
        );
    }
}
