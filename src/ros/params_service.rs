//! The standard parameter services (rcl_interfaces: list_parameters,
//! get_parameters, get_parameter_types, describe_parameters, set_parameters,
//! set_parameters_atomically) under `<node>/…`, served by this node itself.
//!
//! ros2-client would serve them from its `Spinner`, but that Spinner also
//! subscribes `/clock` with the wrong type (see `messages/clock.rs`), so the node
//! runs no Spinner and answers here instead, from a [`ParamStore`] that
//! holds the effective value of every parameter: the ones given (scene
//! file, `--params-file`, `-p`), the defaults of the scalar configuration
//! keys, `use_sim_time` and every `ros.*` key.
//!
//! Parameters are read at start-up. A few may change at run time
//! ([`RUNTIME_KEYS`]); setting any other is refused with a reason that says
//! how to change it (restart with `-p name:=value`).

use crate::config::{table, ParamValue, Params};
use crate::dynamics::load_models::PARAMETERS;
use crate::messages::settings::RosSettings;
use ros2_client::parameters::raw;
use ros2_client::rcl_interfaces::{ListParametersResult, SetParametersAtomicallyResponse};
use ros2_client::ParameterValue as RosValue;
use std::collections::BTreeMap;

/// Keys that `set_parameters` may change while the node runs, with their rule.
pub const RUNTIME_KEYS: &[(&str, &str)] = &[
    (
        "simulation.realtime_factor",
        "a double: 0 (as fast as possible) or in [1e-6, 1e6]",
    ),
    (
        "ros.wrench_timeout",
        "a double, finite and >= 0 s (0 = hold wrenches until replaced)",
    ),
];

pub use super::services::RuntimeChange;

/// A parameter value as the parameter services carry it.
pub fn to_ros_value(v: &ParamValue) -> RosValue {
    match v.clone() {
        ParamValue::Bool(b) => RosValue::Boolean(b),
        ParamValue::Integer(i) => RosValue::Integer(i),
        ParamValue::Double(x) => RosValue::Double(x),
        ParamValue::String(s) => RosValue::String(s),
        ParamValue::BoolArray(a) => RosValue::BooleanArray(a),
        ParamValue::IntegerArray(a) => RosValue::IntegerArray(a),
        ParamValue::DoubleArray(a) => RosValue::DoubleArray(a),
        ParamValue::StringArray(a) => RosValue::StringArray(a),
    }
}

fn from_ros_value(v: RosValue) -> Option<ParamValue> {
    Some(match v {
        RosValue::Boolean(b) => ParamValue::Bool(b),
        RosValue::Integer(i) => ParamValue::Integer(i),
        RosValue::Double(x) => ParamValue::Double(x),
        RosValue::String(s) => ParamValue::String(s),
        RosValue::BooleanArray(a) => ParamValue::BoolArray(a),
        RosValue::IntegerArray(a) => ParamValue::IntegerArray(a),
        RosValue::DoubleArray(a) => ParamValue::DoubleArray(a),
        RosValue::StringArray(a) => ParamValue::StringArray(a),
        RosValue::ByteArray(_) | RosValue::NotSet => return None,
    })
}

fn type_code(v: &ParamValue) -> u8 {
    match v {
        ParamValue::Bool(_) => raw::ParameterType::BOOL,
        ParamValue::Integer(_) => raw::ParameterType::INTEGER,
        ParamValue::Double(_) => raw::ParameterType::DOUBLE,
        ParamValue::String(_) => raw::ParameterType::STRING,
        ParamValue::BoolArray(_) => raw::ParameterType::BOOL_ARRAY,
        ParamValue::IntegerArray(_) => raw::ParameterType::INTEGER_ARRAY,
        ParamValue::DoubleArray(_) => raw::ParameterType::DOUBLE_ARRAY,
        ParamValue::StringArray(_) => raw::ParameterType::STRING_ARRAY,
    }
}

/// The effective parameters: the given values, and every declared key's
/// default (`config::table`; a load model's keys only when its section is
/// on; `use_sim_time` and every `ros.*` key always), then the node's
/// effective `ros.*` settings.
pub fn effective_parameters(
    given: &Params,
    settings: &RosSettings,
) -> BTreeMap<String, ParamValue> {
    let mut out: BTreeMap<String, ParamValue> = given
        .iter()
        .map(|(k, v)| (k.to_string(), v.clone()))
        .collect();
    for section in PARAMETERS.sections() {
        if PARAMETERS
            .enabled_by(section.name)
            .is_some_and(|key| given.get(key).is_none())
        {
            continue;
        }
        for p in section.params {
            if let Some(v) = p.default.to_param() {
                out.entry(p.key.to_string()).or_insert(v);
            }
        }
    }
    for (k, v) in settings.effective_params() {
        out.insert(k.to_string(), v);
    }
    out
}

/// A declared parameter in one line: meaning, unit, rule (docs/parameters.md).
fn describe(p: &table::Param) -> String {
    let unit = if p.unit.is_empty() || p.unit == "—" {
        String::new()
    } else {
        format!(" [{}]", p.unit)
    };
    let meaning = if p.meaning.is_empty() {
        p.rule
    } else {
        p.meaning
    };
    format!(
        "{meaning}{unit}; rule: {}; default: {} (docs/parameters.md)",
        p.rule, p.default_text
    )
}

/// Parameter values and descriptions behind the six services.
#[derive(Debug, Clone)]
pub struct ParamStore {
    values: BTreeMap<String, ParamValue>,
}

impl ParamStore {
    /// A store of the node's effective parameters.
    pub fn new(values: BTreeMap<String, ParamValue>) -> Self {
        ParamStore { values }
    }

    /// The value of `name`, if it is a parameter.
    pub fn get(&self, name: &str) -> Option<&ParamValue> {
        self.values.get(name)
    }

    /// rclcpp's `list_parameters` rule (prefixes, depth; 0 = recursive).
    pub fn list(&self, prefixes: &[String], depth: u64) -> ListParametersResult {
        let dots = |s: &str| s.matches('.').count() as u64;
        let mut names = Vec::new();
        let mut out_prefixes: Vec<String> = Vec::new();
        for name in self.values.keys() {
            let get_all = prefixes.is_empty() && (depth == 0 || dots(name) < depth);
            let prefix_matches = prefixes.iter().any(|p| {
                if name == p {
                    true
                } else if name.starts_with(&format!("{p}.")) {
                    depth == 0 || dots(&name[p.len()..]) < depth
                } else {
                    false
                }
            });
            if get_all || prefix_matches {
                names.push(name.clone());
                if let Some((prefix, _)) = name.rsplit_once('.') {
                    if !out_prefixes.iter().any(|p| p == prefix) {
                        out_prefixes.push(prefix.to_string());
                    }
                }
            }
        }
        ListParametersResult {
            names,
            prefixes: out_prefixes,
        }
    }

    /// `get_parameters`: the value of each name (unset for an unknown one).
    pub fn get_values(&self, names: &[String]) -> Vec<raw::ParameterValue> {
        names
            .iter()
            .map(|n| {
                self.values
                    .get(n)
                    .map_or(RosValue::NotSet, to_ros_value)
                    .into()
            })
            .collect()
    }

    /// `get_parameter_types`: the type of each name (0, unset, for an unknown one).
    pub fn get_types(&self, names: &[String]) -> Vec<u8> {
        names
            .iter()
            .map(|n| {
                self.values
                    .get(n)
                    .map_or(raw::ParameterType::NOT_SET, type_code)
            })
            .collect()
    }

    /// `describe_parameters`: the descriptor of each name (its type, its rule, read-only unless it can change at run time).
    pub fn describe(&self, names: &[String]) -> Vec<raw::ParameterDescriptor> {
        names
            .iter()
            .map(|n| {
                let runtime = RUNTIME_KEYS.iter().find(|(k, _)| k == n);
                let description = PARAMETERS.find(n).map_or_else(String::new, describe);
                raw::ParameterDescriptor {
                    name: n.clone(),
                    r#type: self
                        .values
                        .get(n)
                        .map_or(raw::ParameterType::NOT_SET, type_code),
                    description,
                    additional_constraints: runtime.map_or_else(
                        || {
                            "read at start-up; restart the node with -p name:=value to change it"
                                .to_string()
                        },
                        |(_, rule)| rule.to_string(),
                    ),
                    read_only: runtime.is_none(),
                    dynamic_typing: false,
                    floating_point_range: Vec::new(),
                    integer_range: Vec::new(),
                }
            })
            .collect()
    }

    /// Check one assignment (a raw rcl_interfaces value) without applying it.
    fn check_raw(
        &self,
        name: &str,
        value: raw::ParameterValue,
    ) -> Result<(ParamValue, RuntimeChange), String> {
        if value.ptype > raw::ParameterType::STRING_ARRAY {
            return Err(format!(
                "`{name}`: type code {} is not a ROS 2 parameter type (rcl_interfaces/msg/ParameterType: 0 = not set … 9 = string array)",
                value.ptype
            ));
        }
        self.check(name, value.into())
    }

    /// Check one assignment without applying it: declared by this node, one
    /// of [`RUNTIME_KEYS`], and through `config::check` (the declared type
    /// and range, the same check as the parameter file's and `-p`'s).
    fn check(&self, name: &str, value: RosValue) -> Result<(ParamValue, RuntimeChange), String> {
        if !self.values.contains_key(name) {
            return Err(format!("parameter `{name}` is not declared by this node"));
        }
        if !RUNTIME_KEYS.iter().any(|(k, _)| *k == name) {
            return Err(format!(
                "parameter `{name}` is read only: it is read at start-up; restart the node with `-p {name}:=VALUE` (run-time changes are possible for {})",
                RUNTIME_KEYS.iter().map(|(k, _)| *k).collect::<Vec<_>>().join(", ")
            ));
        }
        let Some(value) = from_ros_value(value) else {
            return Err(format!("`{name}` cannot be unset or given as a byte array"));
        };
        PARAMETERS.check(name, &value).map_err(|e| e.to_string())?;
        let change = match (name, &value) {
            ("simulation.realtime_factor", ParamValue::Double(x)) => {
                RuntimeChange::RealtimeFactor(*x)
            }
            ("ros.wrench_timeout", ParamValue::Double(x)) => RuntimeChange::WrenchTimeout(*x),
            _ => {
                return Err(format!(
                    "`{name}`: {} is not a run-time value of this key",
                    value.type_name()
                ))
            }
        };
        Ok((value, change))
    }

    /// `set_parameters`: each assignment on its own.
    pub fn set(
        &mut self,
        params: Vec<raw::Parameter>,
    ) -> (Vec<raw::SetParametersResult>, Vec<RuntimeChange>) {
        let mut results = Vec::new();
        let mut changes = Vec::new();
        for p in params {
            match self.check_raw(&p.name, p.value) {
                Ok((v, change)) => {
                    self.values.insert(p.name, v);
                    changes.push(change);
                    results.push(raw::SetParametersResult {
                        successful: true,
                        reason: String::new(),
                    });
                }
                Err(reason) => results.push(raw::SetParametersResult {
                    successful: false,
                    reason,
                }),
            }
        }
        (results, changes)
    }

    /// `set_parameters_atomically`: all or none.
    pub fn set_atomically(
        &mut self,
        params: Vec<raw::Parameter>,
    ) -> (SetParametersAtomicallyResponse, Vec<RuntimeChange>) {
        let mut checked = Vec::new();
        for p in params {
            match self.check_raw(&p.name, p.value) {
                Ok((v, change)) => checked.push((p.name, v, change)),
                Err(reason) => {
                    return (
                        SetParametersAtomicallyResponse {
                            result: raw::SetParametersResult {
                                successful: false,
                                reason,
                            },
                        },
                        Vec::new(),
                    )
                }
            }
        }
        let mut changes = Vec::new();
        for (name, v, change) in checked {
            self.values.insert(name, v);
            changes.push(change);
        }
        (
            SetParametersAtomicallyResponse {
                result: raw::SetParametersResult {
                    successful: true,
                    reason: String::new(),
                },
            },
            changes,
        )
    }
}

/// Serve the six parameter services of the node `fqn` (`/ns/node`) from
/// `store`; accepted run-time changes go to the simulation loop.
pub fn spawn(
    node: &mut ros2_client::Node,
    mapping: ros2_client::ServiceMapping,
    fqn: &str,
    store: std::sync::Arc<std::sync::Mutex<ParamStore>>,
    tx: std::sync::mpsc::SyncSender<super::services::Command>,
) -> Result<Vec<tokio::task::JoinHandle<()>>, super::error::NodeError> {
    use super::services::{create_server, spawn_server, Command};
    use ros2_client::rcl_interfaces::*;
    fn lock(s: &std::sync::Mutex<ParamStore>) -> std::sync::MutexGuard<'_, ParamStore> {
        s.lock().unwrap_or_else(|e| e.into_inner())
    }
    let name = |n: &str| format!("{}/{n}", fqn.trim_end_matches('/'));
    let mut handles = Vec::new();

    let server = create_server::<ListParametersRequest, ListParametersResponse>(
        node,
        mapping,
        &name("list_parameters"),
        "rcl_interfaces",
        "ListParameters",
    )?;
    let st = store.clone();
    handles.push(spawn_server(
        server,
        name("list_parameters"),
        move |req: ListParametersRequest| {
            let result = lock(&st).list(&req.prefixes, req.depth);
            async move { ListParametersResponse { result } }
        },
    ));

    let server = create_server::<GetParametersRequest, GetParametersResponse>(
        node,
        mapping,
        &name("get_parameters"),
        "rcl_interfaces",
        "GetParameters",
    )?;
    let st = store.clone();
    handles.push(spawn_server(
        server,
        name("get_parameters"),
        move |req: GetParametersRequest| {
            let values = lock(&st).get_values(&req.names);
            async move { GetParametersResponse { values } }
        },
    ));

    let server = create_server::<GetParameterTypesRequest, GetParameterTypesResponse>(
        node,
        mapping,
        &name("get_parameter_types"),
        "rcl_interfaces",
        "GetParameterTypes",
    )?;
    let st = store.clone();
    handles.push(spawn_server(
        server,
        name("get_parameter_types"),
        move |req: GetParameterTypesRequest| {
            let values = lock(&st).get_types(&req.names);
            async move { GetParameterTypesResponse { values } }
        },
    ));

    let server = create_server::<DescribeParametersRequest, DescribeParametersResponse>(
        node,
        mapping,
        &name("describe_parameters"),
        "rcl_interfaces",
        "DescribeParameters",
    )?;
    let st = store.clone();
    handles.push(spawn_server(
        server,
        name("describe_parameters"),
        move |req: DescribeParametersRequest| {
            let values = lock(&st).describe(&req.names);
            async move { DescribeParametersResponse { values } }
        },
    ));

    let forward = |tx: &std::sync::mpsc::SyncSender<Command>, changes: Vec<RuntimeChange>| {
        for c in changes {
            let _ = tx.try_send(Command::Runtime(c));
        }
    };

    let server = create_server::<SetParametersRequest, SetParametersResponse>(
        node,
        mapping,
        &name("set_parameters"),
        "rcl_interfaces",
        "SetParameters",
    )?;
    let (st, tx1) = (store.clone(), tx.clone());
    handles.push(spawn_server(
        server,
        name("set_parameters"),
        move |req: SetParametersRequest| {
            let (results, changes) = st
                .lock()
                .unwrap_or_else(|e| e.into_inner())
                .set(req.parameter);
            forward(&tx1, changes);
            async move { SetParametersResponse { results } }
        },
    ));

    let server = create_server::<SetParametersRequest, SetParametersAtomicallyResponse>(
        node,
        mapping,
        &name("set_parameters_atomically"),
        "rcl_interfaces",
        "SetParametersAtomically",
    )?;
    let (st, tx2) = (store, tx);
    handles.push(spawn_server(
        server,
        name("set_parameters_atomically"),
        move |req: SetParametersRequest| {
            let (response, changes) = st
                .lock()
                .unwrap_or_else(|e| e.into_inner())
                .set_atomically(req.parameter);
            forward(&tx2, changes);
            async move { response }
        },
    ));
    Ok(handles)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn store() -> ParamStore {
        let mut v = BTreeMap::new();
        for (k, x) in [
            ("a", 0.0),
            ("a.b", 0.0),
            ("a.b.c", 0.0),
            ("ab", 0.0),
            ("x.y", 0.0),
        ] {
            v.insert(k.to_string(), ParamValue::Double(x));
        }
        v.insert("simulation.realtime_factor".into(), ParamValue::Double(1.0));
        ParamStore::new(v)
    }

    fn s(v: &[&str]) -> Vec<String> {
        v.iter().map(|x| x.to_string()).collect()
    }

    #[test]
    fn list_matches_rclcpp() {
        let st = store();
        let all = st.list(&[], 0);
        assert_eq!(
            all.names,
            s(&[
                "a",
                "a.b",
                "a.b.c",
                "ab",
                "simulation.realtime_factor",
                "x.y"
            ])
        );
        assert_eq!(all.prefixes, s(&["a", "a.b", "simulation", "x"]));
        assert_eq!(st.list(&[], 1).names, s(&["a", "ab"]));
        assert_eq!(st.list(&s(&["a"]), 0).names, s(&["a", "a.b", "a.b.c"]));
        assert_eq!(st.list(&s(&["a"]), 1).names, s(&["a"]));
        assert_eq!(st.list(&s(&["a"]), 2).names, s(&["a", "a.b"]));
    }

    #[test]
    fn get_types_and_values() {
        let st = store();
        assert_eq!(
            st.get_types(&s(&["a", "nope"])),
            vec![raw::ParameterType::DOUBLE, raw::ParameterType::NOT_SET]
        );
        let v = st.get_values(&s(&["simulation.realtime_factor", "nope"]));
        assert_eq!(v[0].ptype, raw::ParameterType::DOUBLE);
        assert_eq!(v[0].double_value, 1.0);
        assert_eq!(v[1].ptype, raw::ParameterType::NOT_SET);
        let d = st.describe(&s(&["a", "simulation.realtime_factor"]));
        assert!(d[0].read_only && !d[1].read_only);
    }

    fn param(name: &str, v: RosValue) -> raw::Parameter {
        raw::Parameter {
            name: name.into(),
            value: v.into(),
        }
    }

    #[test]
    fn set_refuses_with_a_reason_and_accepts_runtime_keys() {
        let mut st = store();
        let (r, c) = st.set(vec![
            param("a", RosValue::Double(2.0)),
            param("zzz", RosValue::Double(2.0)),
            param("simulation.realtime_factor", RosValue::Double(0.0)),
            param("simulation.realtime_factor", RosValue::Integer(0)),
            param(
                "simulation.realtime_factor",
                RosValue::String("fast".into()),
            ),
        ]);
        assert!(
            !r[0].successful && r[0].reason.contains("read only") && r[0].reason.contains("-p a:=")
        );
        assert!(!r[1].successful && r[1].reason.contains("not declared"));
        // A type code outside rcl_interfaces' is named as such, not as an unset value.
        let mut bad = raw::Parameter {
            name: "ros.wrench_timeout".into(),
            value: raw::ParameterValue::from(RosValue::Double(1.0)),
        };
        bad.value.ptype = 99;
        let (r99, _) = st.set(vec![bad]);
        assert!(
            !r99[0].successful
                && r99[0]
                    .reason
                    .contains("type code 99 is not a ROS 2 parameter type"),
            "{}",
            r99[0].reason
        );
        assert!(r[2].successful);
        assert!(!r[3].successful && !r[4].successful);
        assert_eq!(c, vec![RuntimeChange::RealtimeFactor(0.0)]);
        assert_eq!(
            st.get("simulation.realtime_factor"),
            Some(&ParamValue::Double(0.0))
        );
    }

    #[test]
    fn atomic_set_is_all_or_nothing() {
        let mut st = store();
        let (r, c) = st.set_atomically(vec![
            param("simulation.realtime_factor", RosValue::Double(2.0)),
            param("a", RosValue::Double(1.0)),
        ]);
        assert!(!r.result.successful && c.is_empty());
        assert_eq!(
            st.get("simulation.realtime_factor"),
            Some(&ParamValue::Double(1.0))
        );
        let (r, c) = st.set_atomically(vec![param(
            "simulation.realtime_factor",
            RosValue::Double(2.0),
        )]);
        assert!(r.result.successful);
        assert_eq!(c, vec![RuntimeChange::RealtimeFactor(2.0)]);
    }

    #[test]
    fn effective_parameters_fill_defaults() {
        let mut given = Params::new();
        given.set_override("joint.speed", "3.0").unwrap();
        let cfg = crate::config::Config::default();
        let eff = effective_parameters(&given, &RosSettings::default());
        assert_eq!(eff.get("joint.speed"), Some(&ParamValue::Double(3.0)));
        assert_eq!(
            eff.get("simulation.rate_hz"),
            Some(&ParamValue::Double(cfg.simulation.rate_hz))
        );
        assert_eq!(eff.get("use_sim_time"), Some(&ParamValue::Bool(false)));
        assert_eq!(
            eff.get("ros.frame_prefix"),
            Some(&ParamValue::String(String::new()))
        );
        assert_eq!(
            eff.get("plate.inner_boundary"),
            Some(&ParamValue::String("clamped".into()))
        );
    }
}
