//! Topic names, before resolution (`~` = the node's name, see `args.rs`).
//! Remap any of them with `-r from:=to`.

use crate::dynamics::NodeKind;

pub const SPEED_COMMAND: &str = "~/speed_command";
pub const WRENCHES: &str = "~/wrenches";
pub const JOINT_STATES: &str = "/joint_states";
pub const TF: &str = "/tf";
pub const TF_STATIC: &str = "/tf_static";
pub const MODAL_AMPLITUDES: &str = "~/modal_amplitudes";
pub const CLOCK: &str = "/clock";
pub const DIAGNOSTICS: &str = "/diagnostics";
/// Only when the scene has pads (`pads.*`).
pub const PAD_CLAMP_FORCES: &str = "~/pad_clamp_forces";
pub const PAD_STATES: &str = "~/pad_states";
/// Only when the scene has a tool (`tool.*`).
pub const TOOL_FEED: &str = "~/tool_feed";
pub const TOOL_STATE: &str = "~/tool_state";

/// `~/ale_<j>/wrench` or `~/lagrange_<j>/wrench`, j from 1 (a ROS name
/// token may not start with a digit, so not `~/ale/1/wrench`).
pub fn node_wrench(kind: NodeKind, j: usize) -> String {
    format!("~/{}_{j}/wrench", kind.name())
}

/// `~/pad_<j>/clamp_force`, pad j from 1.
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
    }
}
