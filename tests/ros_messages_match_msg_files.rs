//! The node's wire structs (src/messages/types.rs) match the interface
//! definitions field for field, in order and type: this package's own
//! `msg/*.msg` and `srv/*.srv` (parsed here), and the standard ROS 2 types
//! the node speaks (their upstream definitions are quoted below).
//!
//! The Rust side is read through serde itself — a tracing deserializer
//! records the field names and primitive types each struct asks for — so
//! the check covers exactly what goes on the wire (CDR is positional). The
//! load models' state messages have no struct: their fields are the
//! channels each model declares (`dynamics::load_models::outputs`), checked
//! against their `.msg` files here, and serialized field by field as a
//! struct would be (checked against structs written out below).

#![cfg(feature = "ros")]

use annular_plate::dynamics::load_models::{ChannelKind, ChannelShape, Outputs, REGISTRY};
use annular_plate::messages::types as m;
use annular_plate::ros::RosType;
use serde::de::{self, DeserializeOwned, DeserializeSeed, SeqAccess, Visitor};
use std::collections::BTreeMap;
use std::path::PathBuf;

// ---- the Rust side: serde tracing ------------------------------------------------

#[derive(Debug, Clone, PartialEq)]
enum Shape {
    Prim(&'static str),
    Seq(Box<Shape>),
    Struct(&'static str, Vec<(&'static str, Shape)>),
}

type Error = de::value::Error;

struct Tracer<'a> {
    out: &'a mut Option<Shape>,
}

macro_rules! prim {
    ($method:ident, $visit:ident, $val:expr, $name:literal) => {
        fn $method<V: Visitor<'de>>(self, v: V) -> Result<V::Value, Error> {
            *self.out = Some(Shape::Prim($name));
            v.$visit($val)
        }
    };
}

impl<'de> de::Deserializer<'de> for Tracer<'_> {
    type Error = Error;
    prim!(deserialize_bool, visit_bool, false, "bool");
    prim!(deserialize_i8, visit_i8, 0, "int8");
    prim!(deserialize_i16, visit_i16, 0, "int16");
    prim!(deserialize_i32, visit_i32, 0, "int32");
    prim!(deserialize_i64, visit_i64, 0, "int64");
    prim!(deserialize_u8, visit_u8, 0, "uint8");
    prim!(deserialize_u16, visit_u16, 0, "uint16");
    prim!(deserialize_u32, visit_u32, 0, "uint32");
    prim!(deserialize_u64, visit_u64, 0, "uint64");
    prim!(deserialize_f32, visit_f32, 0.0, "float32");
    prim!(deserialize_f64, visit_f64, 0.0, "float64");
    prim!(deserialize_string, visit_string, String::new(), "string");
    prim!(deserialize_str, visit_string, String::new(), "string");

    fn deserialize_seq<V: Visitor<'de>>(self, v: V) -> Result<V::Value, Error> {
        let mut elem = None;
        let value = v.visit_seq(OneElement {
            done: false,
            out: &mut elem,
        })?;
        *self.out = Some(Shape::Seq(Box::new(elem.expect("sequence element traced"))));
        Ok(value)
    }

    fn deserialize_struct<V: Visitor<'de>>(
        self,
        name: &'static str,
        fields: &'static [&'static str],
        v: V,
    ) -> Result<V::Value, Error> {
        let mut shapes = Vec::new();
        let value = v.visit_seq(Fields {
            remaining: fields.len(),
            shapes: &mut shapes,
        })?;
        *self.out = Some(Shape::Struct(
            name,
            fields.iter().copied().zip(shapes).collect(),
        ));
        Ok(value)
    }

    fn deserialize_any<V: Visitor<'de>>(self, _v: V) -> Result<V::Value, Error> {
        Err(de::Error::custom("self-describing formats are not CDR"))
    }

    serde::forward_to_deserialize_any! {
        i128 u128 char bytes byte_buf option unit unit_struct newtype_struct tuple
        tuple_struct map enum identifier ignored_any
    }
}

struct OneElement<'a> {
    done: bool,
    out: &'a mut Option<Shape>,
}

impl<'de> SeqAccess<'de> for OneElement<'_> {
    type Error = Error;
    fn next_element_seed<T: DeserializeSeed<'de>>(
        &mut self,
        seed: T,
    ) -> Result<Option<T::Value>, Error> {
        if self.done {
            return Ok(None);
        }
        self.done = true;
        seed.deserialize(Tracer { out: self.out }).map(Some)
    }
}

struct Fields<'a> {
    remaining: usize,
    shapes: &'a mut Vec<Shape>,
}

impl<'de> SeqAccess<'de> for Fields<'_> {
    type Error = Error;
    fn next_element_seed<T: DeserializeSeed<'de>>(
        &mut self,
        seed: T,
    ) -> Result<Option<T::Value>, Error> {
        if self.remaining == 0 {
            return Ok(None);
        }
        self.remaining -= 1;
        let mut out = None;
        let v = seed.deserialize(Tracer { out: &mut out })?;
        self.shapes.push(out.expect("field traced"));
        Ok(Some(v))
    }
}

fn trace<T: DeserializeOwned>() -> Shape {
    let mut out = None;
    T::deserialize(Tracer { out: &mut out }).expect("traced");
    out.expect("a shape")
}

// ---- the definitions ----------------------------------------------------------------

/// Upstream definitions of the standard types the node speaks (comments and
/// constants dropped; defaults kept where upstream has them).
const STANDARD: &[(&str, &str)] = &[
    ("builtin_interfaces/Time", "int32 sec\nuint32 nanosec"),
    ("std_msgs/Header", "builtin_interfaces/Time stamp\nstring frame_id"),
    ("std_msgs/Float64", "float64 data"),
    ("geometry_msgs/Vector3", "float64 x\nfloat64 y\nfloat64 z"),
    ("geometry_msgs/Quaternion", "float64 x 0\nfloat64 y 0\nfloat64 z 0\nfloat64 w 1"),
    ("geometry_msgs/Transform", "Vector3 translation\nQuaternion rotation"),
    ("geometry_msgs/TransformStamped", "std_msgs/Header header\nstring child_frame_id\nTransform transform"),
    ("geometry_msgs/Wrench", "Vector3 force\nVector3 torque"),
    ("geometry_msgs/WrenchStamped", "std_msgs/Header header\nWrench wrench"),
    ("tf2_msgs/TFMessage", "geometry_msgs/TransformStamped[] transforms"),
    ("sensor_msgs/JointState", "std_msgs/Header header\n\nstring[] name\nfloat64[] position\nfloat64[] velocity\nfloat64[] effort"),
    ("rosgraph_msgs/Clock", "builtin_interfaces/Time clock"),
    ("diagnostic_msgs/KeyValue", "string key\nstring value"),
    (
        "diagnostic_msgs/DiagnosticStatus",
        "byte OK=0\nbyte WARN=1\nbyte ERROR=2\nbyte STALE=3\nbyte level\nstring name\nstring message\nstring hardware_id\nKeyValue[] values",
    ),
    ("diagnostic_msgs/DiagnosticArray", "std_msgs/Header header\nDiagnosticStatus[] status"),
    ("builtin_interfaces/Duration", "int32 sec\nuint32 nanosec"),
    ("std_msgs/ColorRGBA", "float32 r\nfloat32 g\nfloat32 b\nfloat32 a"),
    ("geometry_msgs/Point", "float64 x\nfloat64 y\nfloat64 z"),
    ("geometry_msgs/Pose", "Point position\nQuaternion orientation"),
    ("sensor_msgs/CompressedImage", "std_msgs/Header header\nstring format\nuint8[] data"),
    ("visualization_msgs/UVCoordinate", "float32 u\nfloat32 v"),
    ("visualization_msgs/MeshFile", "string filename\nuint8[] data"),
    (
        "visualization_msgs/Marker",
        "int32 ARROW=0\nint32 TRIANGLE_LIST=11\nint32 DELETEALL=3\nstd_msgs/Header header\nstring ns\nint32 id\nint32 type\nint32 action\ngeometry_msgs/Pose pose\ngeometry_msgs/Vector3 scale\nstd_msgs/ColorRGBA color\nbuiltin_interfaces/Duration lifetime\nbool frame_locked\ngeometry_msgs/Point[] points\nstd_msgs/ColorRGBA[] colors\nstring texture_resource\nsensor_msgs/CompressedImage texture\nUVCoordinate[] uv_coordinates\nstring text\nstring mesh_resource\nMeshFile mesh_file\nbool mesh_use_embedded_materials",
    ),
    ("visualization_msgs/MarkerArray", "Marker[] markers"),
    ("std_srvs/Trigger_Request", ""),
    ("std_srvs/Trigger_Response", "bool success\nstring message"),
    ("std_srvs/SetBool_Request", "bool data"),
    ("std_srvs/SetBool_Response", "bool success\nstring message"),
    // simulation_interfaces 1.0/2.0 (Humble to Rolling).
    ("simulation_interfaces/Result", "uint8 RESULT_FEATURE_UNSUPPORTED=0\nuint8 RESULT_OK=1\nuint8 result\nstring error_message"),
    ("simulation_interfaces/SimulationState", "uint8 STATE_STOPPED=0\nuint8 state"),
    ("simulation_interfaces/ResetSimulation_Request", "uint8 SCOPE_DEFAULT=0\nuint8 scope"),
    ("simulation_interfaces/ResetSimulation_Response", "Result result"),
    ("simulation_interfaces/StepSimulation_Request", "uint64 steps 1"),
    ("simulation_interfaces/StepSimulation_Response", "Result result"),
    ("simulation_interfaces/GetSimulationState_Request", ""),
    ("simulation_interfaces/GetSimulationState_Response", "SimulationState state\n\nResult result"),
    ("simulation_interfaces/SetSimulationState_Request", "SimulationState state"),
    ("simulation_interfaces/SetSimulationState_Response", "uint8 ALREADY_IN_TARGET_STATE=101\nResult result"),
];

#[derive(Debug, Clone)]
struct Field {
    ty: String,
    array: bool,
    name: String,
}

fn repo() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// Parse the text of a .msg (or one half of a .srv).
fn parse(text: &str) -> Vec<Field> {
    let mut out = Vec::new();
    for line in text.lines() {
        let line = line.split('#').next().unwrap().trim();
        if line.is_empty() {
            continue;
        }
        let mut parts = line.split_whitespace();
        let ty = parts.next().unwrap();
        let name = parts
            .next()
            .unwrap_or_else(|| panic!("no field name in `{line}`"));
        if line.contains('=') {
            continue; // a constant
        }
        let (ty, array) = match ty.strip_suffix("[]") {
            Some(t) => (t, true),
            None => {
                assert!(
                    !ty.contains('['),
                    "fixed-size or bounded arrays are not used: `{line}`"
                );
                (ty, false)
            }
        };
        assert!(!ty.contains("<="), "bounded strings are not used: `{line}`");
        out.push(Field {
            ty: ty.to_string(),
            array,
            name: name.to_string(),
        });
    }
    out
}

struct Definitions {
    by_name: BTreeMap<String, Vec<Field>>,
}

impl Definitions {
    fn load() -> Definitions {
        let mut by_name = BTreeMap::new();
        for (name, text) in STANDARD {
            by_name.insert(name.to_string(), parse(text));
        }
        for entry in std::fs::read_dir(repo().join("msg")).expect("msg/") {
            let path = entry.unwrap().path();
            if path.extension().is_some_and(|e| e == "msg") {
                let stem = path.file_stem().unwrap().to_string_lossy().to_string();
                by_name.insert(
                    format!("annular_plate/{stem}"),
                    parse(&std::fs::read_to_string(&path).unwrap()),
                );
            }
        }
        for entry in std::fs::read_dir(repo().join("srv")).expect("srv/") {
            let path = entry.unwrap().path();
            if path.extension().is_some_and(|e| e == "srv") {
                let stem = path.file_stem().unwrap().to_string_lossy().to_string();
                let text = std::fs::read_to_string(&path).unwrap();
                let (req, resp) = text
                    .split_once("\n---")
                    .unwrap_or_else(|| panic!("{} has no ---", path.display()));
                by_name.insert(format!("annular_plate/{stem}_Request"), parse(req));
                by_name.insert(format!("annular_plate/{stem}_Response"), parse(resp));
            }
        }
        Definitions { by_name }
    }

    /// The full name of a field type used inside package `pkg`.
    fn resolve(&self, pkg: &str, ty: &str) -> String {
        if ty.contains('/') {
            ty.to_string()
        } else {
            format!("{pkg}/{ty}")
        }
    }

    fn check(&self, full: &str, shape: &Shape, path: &str) {
        let fields = self
            .by_name
            .get(full)
            .unwrap_or_else(|| panic!("{path}: no definition of {full}"));
        let Shape::Struct(struct_name, members) = shape else {
            panic!("{path}: {full} is not a struct in Rust")
        };
        let base = full.rsplit('/').next().unwrap();
        assert_eq!(
            struct_name
                .trim_end_matches("Request")
                .trim_end_matches("Response"),
            base.trim_end_matches("_Request")
                .trim_end_matches("_Response"),
            "{path}: Rust struct name"
        );
        if fields.is_empty() {
            // ROS 2's IDL gives an empty structure one member.
            assert_eq!(
                members,
                &vec![("structure_needs_at_least_one_member", Shape::Prim("uint8"))],
                "{path}: empty {full}"
            );
            return;
        }
        let names: Vec<&str> = members.iter().map(|(n, _)| *n).collect();
        let expected: Vec<&str> = fields.iter().map(|f| f.name.as_str()).collect();
        assert_eq!(names, expected, "{path}: fields of {full}, in order");
        let pkg = full.split('/').next().unwrap();
        for (field, (name, shape)) in fields.iter().zip(members) {
            let here = format!("{path}.{name}");
            let inner = if field.array {
                match shape {
                    Shape::Seq(e) => e.as_ref(),
                    other => panic!(
                        "{here}: {}[] is an array in the .msg, Rust has {other:?}",
                        field.ty
                    ),
                }
            } else {
                shape
            };
            let prim = match field.ty.as_str() {
                "byte" => Some("uint8"),
                "char" => Some("uint8"),
                t @ ("bool" | "int8" | "int16" | "int32" | "int64" | "uint8" | "uint16"
                | "uint32" | "uint64" | "float32" | "float64" | "string") => Some(t),
                _ => None,
            };
            match prim {
                Some(p) => assert_eq!(
                    inner,
                    &Shape::Prim(match p {
                        "bool" => "bool",
                        "int8" => "int8",
                        "int16" => "int16",
                        "int32" => "int32",
                        "int64" => "int64",
                        "uint8" => "uint8",
                        "uint16" => "uint16",
                        "uint32" => "uint32",
                        "uint64" => "uint64",
                        "float32" => "float32",
                        "float64" => "float64",
                        _ => "string",
                    }),
                    "{here}: type {}",
                    field.ty
                ),
                None => self.check(&self.resolve(pkg, &field.ty), inner, &here),
            }
        }
    }
}

fn check<T: DeserializeOwned>(defs: &Definitions, full: &str) {
    defs.check(full, &trace::<T>(), full);
}

/// The wire shape of a model's state message, from its declaration.
fn declared_shape(o: &Outputs) -> Shape {
    let mut fields = vec![
        ("header", trace::<m::Header>()),
        ("step", Shape::Prim("uint64")),
        ("sim_time", Shape::Prim("float64")),
    ];
    for c in o.channels {
        let p = Shape::Prim(match c.kind {
            ChannelKind::Real => "float64",
            ChannelKind::Number => "uint32",
        });
        fields.push((
            c.name,
            match c.shape {
                ChannelShape::Scalar => p,
                ChannelShape::Sequence => Shape::Seq(Box::new(p)),
            },
        ));
    }
    Shape::Struct(o.topic.expect("a model with a topic").message, fields)
}

/// Every registered model's topic message: `pkg/Type` and its declared shape.
fn model_messages() -> Vec<(String, Shape)> {
    REGISTRY
        .iter()
        .filter_map(|r| r.outputs.topic.map(|t| (r.outputs, t)))
        .map(|(o, t)| (format!("{}/{}", t.package, t.message), declared_shape(o)))
        .collect()
}

fn check_msg<T: DeserializeOwned + RosType>(defs: &Definitions) -> String {
    let full = format!("{}/{}", T::PACKAGE, T::NAME);
    check::<T>(defs, &full);
    full
}

#[test]
fn own_messages_match_msg_files() {
    let defs = Definitions::load();
    let mut checked = vec![
        check_msg::<m::CriticalSpeeds>(&defs),
        check_msg::<m::ModalAmplitudes>(&defs),
        check_msg::<m::NodeWrench>(&defs),
        check_msg::<m::NodeWrenchArray>(&defs),
        check_msg::<m::PadClampForces>(&defs),
    ];
    for (full, shape) in model_messages() {
        defs.check(&full, &shape, &full);
        checked.push(full);
    }
    // Every .msg of the package has its Rust struct.
    let own: Vec<&String> = defs
        .by_name
        .keys()
        .filter(|k| {
            k.strip_prefix("annular_plate/")
                .is_some_and(|t| !t.contains('_'))
        })
        .collect();
    let mut checked_sorted: Vec<&String> = checked.iter().collect();
    checked_sorted.sort();
    assert_eq!(
        own, checked_sorted,
        "a msg/*.msg without a Rust struct (or the other way round)"
    );
    // ... and colcon generates every one of them for rclpy / rclcpp users.
    let cmake = std::fs::read_to_string(repo().join("CMakeLists.txt")).expect("CMakeLists.txt");
    for name in &own {
        let file = format!("\"msg/{}.msg\"", name.trim_start_matches("annular_plate/"));
        assert!(
            cmake.contains(&file),
            "CMakeLists.txt's rosidl_generate_interfaces does not list {file}"
        );
    }
}

#[test]
fn own_services_match_srv_files() {
    let defs = Definitions::load();
    check::<m::StepRequest>(&defs, "annular_plate/Step_Request");
    check::<m::StepResponse>(&defs, "annular_plate/Step_Response");
}

#[test]
fn standard_messages_match_their_ros2_definitions() {
    let defs = Definitions::load();
    check_msg::<m::Header>(&defs);
    check_msg::<m::Float64>(&defs);
    check_msg::<m::TransformStamped>(&defs);
    check_msg::<m::Wrench>(&defs);
    check_msg::<m::WrenchStamped>(&defs);
    check_msg::<m::TFMessage>(&defs);
    check_msg::<m::JointState>(&defs);
    check_msg::<m::Clock>(&defs);
    check_msg::<m::DiagnosticArray>(&defs);
    check_msg::<annular_plate::messages::visualization::MarkerArray>(&defs);
    check::<m::TriggerRequest>(&defs, "std_srvs/Trigger_Request");
    check::<m::TriggerResponse>(&defs, "std_srvs/Trigger_Response");
    check::<m::SetBoolRequest>(&defs, "std_srvs/SetBool_Request");
    check::<m::SetBoolResponse>(&defs, "std_srvs/SetBool_Response");
}

#[test]
fn simulation_interfaces_match_their_ros2_definitions() {
    use annular_plate::messages::simulation_interfaces as si;
    let defs = Definitions::load();
    check::<si::SimResult>(&defs, "simulation_interfaces/Result");
    check::<si::SimulationState>(&defs, "simulation_interfaces/SimulationState");
    check::<si::ResetSimulationRequest>(&defs, "simulation_interfaces/ResetSimulation_Request");
    check::<si::ResetSimulationResponse>(&defs, "simulation_interfaces/ResetSimulation_Response");
    check::<si::StepSimulationRequest>(&defs, "simulation_interfaces/StepSimulation_Request");
    check::<si::StepSimulationResponse>(&defs, "simulation_interfaces/StepSimulation_Response");
    check::<si::GetSimulationStateRequest>(
        &defs,
        "simulation_interfaces/GetSimulationState_Request",
    );
    check::<si::GetSimulationStateResponse>(
        &defs,
        "simulation_interfaces/GetSimulationState_Response",
    );
    check::<si::SetSimulationStateRequest>(
        &defs,
        "simulation_interfaces/SetSimulationState_Request",
    );
    check::<si::SetSimulationStateResponse>(
        &defs,
        "simulation_interfaces/SetSimulationState_Response",
    );
}

#[test]
fn the_checker_catches_a_mismatch() {
    let defs = Definitions::load();
    // Header against the Float64 definition must fail.
    let r = std::panic::catch_unwind(|| check::<m::Header>(&defs, "std_msgs/Float64"));
    assert!(r.is_err());
    // A parsed .msg skips constants and comments.
    let f = parse("uint8 A=1\nuint8 B = 2 # c\n# x\nfloat64[] v  # m\n");
    assert_eq!(f.len(), 1);
    assert!(f[0].array && f[0].ty == "float64" && f[0].name == "v");
}

/// The definitions recorded into bags (`bag::schemas`, MCAP schemas of
/// encoding ros2msg) are the ones checked above, and each recorded type's
/// full schema text — its own text and the appended `MSG:` blocks — is on
/// its own enough to describe the wire struct.
#[test]
fn bag_schemas_describe_the_wire_structs() {
    use annular_plate::bag::schemas;
    let defs = Definitions::load();
    let key = |f: &Field| (f.ty.clone(), f.array, f.name.clone());
    for t in schemas::known_types() {
        let short = t.replacen("/msg/", "/", 1);
        let want = defs
            .by_name
            .get(&short)
            .unwrap_or_else(|| panic!("{short}: not among the checked definitions"));
        let got = parse(schemas::own_text(&t).unwrap());
        assert_eq!(
            got.iter().map(key).collect::<Vec<_>>(),
            want.iter().map(key).collect::<Vec<_>>(),
            "{t}"
        );
    }
    let delimiter = format!("\n{}\nMSG: ", "=".repeat(80));
    let from_schema = |full: &str| {
        let text = schemas::ros2msg(&full.replacen('/', "/msg/", 1)).unwrap();
        let mut blocks = text.split(delimiter.as_str());
        let mut by_name = BTreeMap::new();
        by_name.insert(full.to_string(), parse(blocks.next().unwrap()));
        for b in blocks {
            let (name, body) = b.split_once('\n').unwrap_or((b, ""));
            assert!(
                by_name.insert(name.to_string(), parse(body)).is_none(),
                "{full}: {name} twice"
            );
        }
        Definitions { by_name }
    };
    let mut recorded = vec![
        (
            "sensor_msgs/JointState".to_string(),
            trace::<m::JointState>(),
        ),
        ("tf2_msgs/TFMessage".into(), trace::<m::TFMessage>()),
        (
            "annular_plate/ModalAmplitudes".into(),
            trace::<m::ModalAmplitudes>(),
        ),
        ("rosgraph_msgs/Clock".into(), trace::<m::Clock>()),
        (
            "diagnostic_msgs/DiagnosticArray".into(),
            trace::<m::DiagnosticArray>(),
        ),
        (
            "visualization_msgs/MarkerArray".into(),
            trace::<annular_plate::messages::visualization::MarkerArray>(),
        ),
    ];
    recorded.extend(model_messages());
    for (full, shape) in recorded {
        from_schema(&full).check(&full, &shape, &full);
    }
}
