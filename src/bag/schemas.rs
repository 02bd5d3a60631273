//! Message definitions as rosbag2 stores them in an MCAP schema
//! (encoding `ros2msg`): the type's `.msg` text, then every type it uses,
//! depth first, each once, as
//!
//! ```text
//! ================================================================================
//! MSG: std_msgs/Header
//! builtin_interfaces/Time stamp
//! ...
//! ```
//!
//! This is what rosbag2's `MessageDefinitionCache::get_full_text` produces
//! (dependencies of one text in sorted order, a type already written is not
//! repeated), so readers that rebuild types from the bag — `ros2 bag play`,
//! rosbags, Foxglove, mcap-ros2-support — find every nested type.
//!
//! The standard texts are the upstream definitions with their comments left
//! out (the fields, constants and defaults are the same;
//! `tests/ros_messages_match_msg_files.rs` checks them against the wire
//! structs); this package's own types are the files in `msg/` as they are —
//! the load models' state messages as each model declares its topic
//! (`dynamics::load_models::StateTopic::definition`).

use crate::dynamics::load_models::{StateTopic, REGISTRY};

/// `pkg/Type` → the `.msg` text, for every type a recorded topic needs.
const DEFINITIONS: &[(&str, &str)] = &[
    ("builtin_interfaces/Time", "int32 sec\nuint32 nanosec\n"),
    ("std_msgs/Header", "builtin_interfaces/Time stamp\nstring frame_id\n"),
    ("geometry_msgs/Vector3", "float64 x\nfloat64 y\nfloat64 z\n"),
    ("geometry_msgs/Quaternion", "float64 x 0\nfloat64 y 0\nfloat64 z 0\nfloat64 w 1\n"),
    ("geometry_msgs/Transform", "Vector3 translation\nQuaternion rotation\n"),
    ("geometry_msgs/TransformStamped", "std_msgs/Header header\nstring child_frame_id\nTransform transform\n"),
    ("geometry_msgs/Wrench", "Vector3 force\nVector3 torque\n"),
    ("geometry_msgs/WrenchStamped", "std_msgs/Header header\nWrench wrench\n"),
    ("std_msgs/Float64", "float64 data\n"),
    ("tf2_msgs/TFMessage", "geometry_msgs/TransformStamped[] transforms\n"),
    (
        "sensor_msgs/JointState",
        "std_msgs/Header header\n\nstring[] name\nfloat64[] position\nfloat64[] velocity\nfloat64[] effort\n",
    ),
    ("rosgraph_msgs/Clock", "builtin_interfaces/Time clock\n"),
    ("diagnostic_msgs/KeyValue", "string key\nstring value\n"),
    (
        "diagnostic_msgs/DiagnosticStatus",
        "byte OK=0\nbyte WARN=1\nbyte ERROR=2\nbyte STALE=3\n\nbyte level\nstring name\nstring message\nstring hardware_id\nKeyValue[] values\n",
    ),
    ("diagnostic_msgs/DiagnosticArray", "std_msgs/Header header\nDiagnosticStatus[] status\n"),
    ("builtin_interfaces/Duration", "int32 sec\nuint32 nanosec\n"),
    ("std_msgs/ColorRGBA", "float32 r\nfloat32 g\nfloat32 b\nfloat32 a\n"),
    ("geometry_msgs/Point", "float64 x\nfloat64 y\nfloat64 z\n"),
    ("geometry_msgs/Pose", "Point position\nQuaternion orientation\n"),
    ("sensor_msgs/CompressedImage", "std_msgs/Header header\nstring format\nuint8[] data\n"),
    ("visualization_msgs/UVCoordinate", "float32 u\nfloat32 v\n"),
    ("visualization_msgs/MeshFile", "string filename\nuint8[] data\n"),
    ("visualization_msgs/Marker", "int32 ARROW=0\nint32 CUBE=1\nint32 SPHERE=2\nint32 CYLINDER=3\nint32 LINE_STRIP=4\nint32 LINE_LIST=5\nint32 CUBE_LIST=6\nint32 SPHERE_LIST=7\nint32 POINTS=8\nint32 TEXT_VIEW_FACING=9\nint32 MESH_RESOURCE=10\nint32 TRIANGLE_LIST=11\nint32 ARROW_STRIP=12\n\nint32 ADD=0\nint32 MODIFY=0\nint32 DELETE=2\nint32 DELETEALL=3\n\nstd_msgs/Header header\nstring ns\nint32 id\nint32 type\nint32 action\ngeometry_msgs/Pose pose\ngeometry_msgs/Vector3 scale\nstd_msgs/ColorRGBA color\nbuiltin_interfaces/Duration lifetime\nbool frame_locked\ngeometry_msgs/Point[] points\nstd_msgs/ColorRGBA[] colors\nstring texture_resource\nsensor_msgs/CompressedImage texture\nUVCoordinate[] uv_coordinates\nstring text\nstring mesh_resource\nMeshFile mesh_file\nbool mesh_use_embedded_materials\n"),
    ("visualization_msgs/MarkerArray", "Marker[] markers\n"),
    ("annular_plate/ModalAmplitudes", include_str!("../../msg/ModalAmplitudes.msg")),
    ("annular_plate/NodeWrench", include_str!("../../msg/NodeWrench.msg")),
    ("annular_plate/NodeWrenchArray", include_str!("../../msg/NodeWrenchArray.msg")),
    ("annular_plate/PadClampForces", include_str!("../../msg/PadClampForces.msg")),
];

/// The topics every registered load model declares.
fn model_topics() -> impl Iterator<Item = &'static StateTopic> {
    REGISTRY.iter().filter_map(|r| r.outputs.topic.as_ref())
}

const PRIMITIVES: &[&str] = &[
    "bool", "byte", "char", "float32", "float64", "int8", "uint8", "int16", "uint16", "int32",
    "uint32", "int64", "uint64", "string", "wstring",
];

const DELIMITER: &str =
    "================================================================================\n";

/// `pkg/msg/Type` or `pkg/Type` → `(pkg, Type)`.
fn split(type_name: &str) -> Option<(&str, &str)> {
    let mut parts = type_name.split('/');
    let (pkg, a, b) = (parts.next()?, parts.next()?, parts.next());
    match (b, parts.next()) {
        (None, _) => Some((pkg, a)),
        (Some(t), None) if a == "msg" => Some((pkg, t)),
        _ => None,
    }
}

/// The `.msg` text of one type (`pkg/Type` or `pkg/msg/Type`), without dependencies.
pub fn own_text(type_name: &str) -> Option<&'static str> {
    let (pkg, name) = split(type_name)?;
    DEFINITIONS
        .iter()
        .find(|(n, _)| n.split_once('/') == Some((pkg, name)))
        .map(|(_, t)| *t)
        .or_else(|| {
            model_topics()
                .find(|t| (t.package, t.message) == (pkg, name))
                .map(|t| t.definition)
        })
}

/// The non-primitive field types of a `.msg` text as `pkg/Type`, sorted and
/// unique (relative names are in `package`), as rosbag2 finds them.
pub(crate) fn dependencies(text: &str, package: &str) -> Vec<String> {
    let mut out = std::collections::BTreeSet::new();
    for line in text.lines() {
        let line = line.split('#').next().unwrap_or("").trim();
        let Some(ty) = line.split_whitespace().next() else {
            continue;
        };
        if line.split_whitespace().nth(1).is_none() {
            continue;
        }
        let ty = ty.split('[').next().unwrap_or(ty);
        let ty = ty.split("<=").next().unwrap_or(ty);
        if PRIMITIVES.contains(&ty) {
            continue;
        }
        out.insert(if ty.contains('/') {
            ty.to_string()
        } else {
            format!("{package}/{ty}")
        });
    }
    out.into_iter().collect()
}

/// The full `ros2msg` schema text of `type_name` (`pkg/msg/Type`): its own
/// text and every nested type appended. `None` for a type this crate has no
/// definition of.
pub fn ros2msg(type_name: &str) -> Option<String> {
    let (pkg, name) = split(type_name)?;
    let mut seen = std::collections::BTreeSet::new();
    let mut out = String::new();
    append(&format!("{pkg}/{name}"), &mut seen, &mut out, 0)?;
    Some(out)
}

fn append(
    type_name: &str,
    seen: &mut std::collections::BTreeSet<String>,
    out: &mut String,
    depth: usize,
) -> Option<()> {
    if depth > 50 {
        return None;
    }
    let text = own_text(type_name)?;
    let (pkg, _) = split(type_name)?;
    out.push_str(text);
    for dep in dependencies(text, pkg) {
        if seen.insert(dep.clone()) {
            out.push('\n');
            out.push_str(DELIMITER);
            out.push_str("MSG: ");
            out.push_str(&dep);
            out.push('\n');
            append(&dep, seen, out, depth + 1)?;
        }
    }
    Some(())
}

/// Every type this module can describe, as `pkg/msg/Type`.
pub fn known_types() -> impl Iterator<Item = String> {
    DEFINITIONS
        .iter()
        .map(|(n, _)| n.replacen('/', "/msg/", 1))
        .chain(model_topics().map(|t| format!("{}/msg/{}", t.package, t.message)))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_schema_holds_every_nested_type_once() {
        let s = ros2msg("tf2_msgs/msg/TFMessage").unwrap();
        assert!(s.starts_with("geometry_msgs/TransformStamped[] transforms\n"));
        for t in [
            "geometry_msgs/TransformStamped",
            "std_msgs/Header",
            "builtin_interfaces/Time",
            "geometry_msgs/Transform",
            "geometry_msgs/Quaternion",
            "geometry_msgs/Vector3",
        ] {
            assert_eq!(
                s.matches(&format!("{DELIMITER}MSG: {t}\n")).count(),
                1,
                "{t} once in\n{s}"
            );
        }
        assert_eq!(s.matches("MSG: ").count(), 6);
    }

    #[test]
    fn own_package_types_and_relative_names_resolve() {
        let s = ros2msg("annular_plate/msg/ModalAmplitudes").unwrap();
        assert!(s.contains("float64[] q_ale"));
        assert!(
            s.contains("MSG: std_msgs/Header\n") && s.contains("MSG: builtin_interfaces/Time\n")
        );
        let d = ros2msg("diagnostic_msgs/msg/DiagnosticArray").unwrap();
        assert!(
            d.contains("MSG: diagnostic_msgs/DiagnosticStatus\n")
                && d.contains("MSG: diagnostic_msgs/KeyValue\n")
        );
        assert_eq!(
            dependencies("byte OK=0\nKeyValue[] values # c\n", "diagnostic_msgs"),
            vec!["diagnostic_msgs/KeyValue"]
        );
        assert!(ros2msg("nav_msgs/msg/Odometry").is_none());
        assert!(ros2msg("bad").is_none());
    }

    #[test]
    fn every_definition_is_complete() {
        for t in known_types() {
            assert!(ros2msg(&t).is_some(), "{t} has a missing dependency");
        }
    }
}
