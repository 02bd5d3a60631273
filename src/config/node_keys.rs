//! The ROS node's own keys (`ros.*`): their names, defaults and rules as
//! data. The config layer accepts them (so one scene file serves `simulate`
//! and the node) and refuses unknown `ros.*` names; the node (`ros::settings`)
//! checks their values.

/// Defaults and rules of the `ros.*` keys, one row each: (key, type, default, rule).
pub const ROS_KEYS: &[(&str, &str, &str, &str)] = &[
    ("ros.frame_prefix", "string", "\"\"", "prefix of every frame and joint name; letters, digits, `_`, `/`, `-`, `.`; not starting with `/`"),
    ("ros.world_frame", "string", "\"world\"", "parent of plate_base in /tf_static (not prefixed); non-empty, same characters"),
    ("ros.publish_clock", "bool", "false", "publish /clock and stamp outputs with simulated time (also when use_sim_time is true)"),
    ("ros.wrench_timeout", "double", "0.0", "s of simulated time after which a wrench not renewed drops to zero; 0 = hold forever; finite, >= 0"),
    ("ros.start_paused", "bool", "false", "start paused (resume with ~/set_paused, advance with ~/step)"),
    ("ros.diagnostics_period", "double", "1.0", "s of wall time between /diagnostics messages; finite, > 0"),
    ("ros.reject_log_period", "double", "1.0", "s of wall time between log lines about rejected inputs of one kind; finite, >= 0"),
    ("ros.service_mapping", "string", "\"enhanced\"", "request/reply mapping of all services: enhanced (rmw_fastrtps, the Jazzy default), cyclone (rmw_cyclonedds_cpp) or basic"),
];

