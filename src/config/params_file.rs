//! ROS 2 parameter files, read into a flat map of dotted names → values.
//!
//! A parameter file is a YAML map whose top-level keys are node names
//! (`annular_plate`, `/annular_plate`, `/ns/annular_plate`, wildcards `*` for
//! one name token and `**` for any number) each holding `ros__parameters:`.
//! Inside `ros__parameters` nested maps and dotted names are equivalent
//! (`plate: {inner_radius: 0.075}` ≡ `plate.inner_radius: 0.075`). Values
//! are the ROS 2 parameter types: scalars and flat arrays only.

use super::text_limits::{check_depth, MAX_FILE_BYTES};
use std::collections::BTreeMap;
use std::fmt;
use std::path::Path;

use serde_yaml_ng::Value;

use super::{ConfigError, Parameters};

/// A ROS 2 parameter value.
///
/// An empty YAML list `[]` is read as an empty [`ParamValue::DoubleArray`];
/// validation accepts an empty array of any type wherever an array is expected.
#[derive(Debug, Clone, PartialEq)]
pub enum ParamValue {
    /// `bool`.
    Bool(bool),
    /// `integer`.
    Integer(i64),
    /// `double`.
    Double(f64),
    /// `string`.
    String(String),
    /// `bool[]`.
    BoolArray(Vec<bool>),
    /// `integer[]`.
    IntegerArray(Vec<i64>),
    /// `double[]`.
    DoubleArray(Vec<f64>),
    /// `string[]`.
    StringArray(Vec<String>),
}

impl ParamValue {
    /// The ROS 2 type name, for messages (`integer`, `double array`, …).
    pub fn type_name(&self) -> &'static str {
        match self {
            ParamValue::Bool(_) => "bool",
            ParamValue::Integer(_) => "integer",
            ParamValue::Double(_) => "double",
            ParamValue::String(_) => "string",
            ParamValue::BoolArray(_) => "bool array",
            ParamValue::IntegerArray(_) => "integer array",
            ParamValue::DoubleArray(_) => "double array",
            ParamValue::StringArray(_) => "string array",
        }
    }

    /// Number of elements of an array value; `None` for a scalar.
    pub fn array_len(&self) -> Option<usize> {
        match self {
            ParamValue::BoolArray(v) => Some(v.len()),
            ParamValue::IntegerArray(v) => Some(v.len()),
            ParamValue::DoubleArray(v) => Some(v.len()),
            ParamValue::StringArray(v) => Some(v.len()),
            _ => None,
        }
    }
}

fn write_list<T>(
    f: &mut fmt::Formatter<'_>,
    items: &[T],
    one: impl Fn(&mut fmt::Formatter<'_>, &T) -> fmt::Result,
) -> fmt::Result {
    f.write_str("[")?;
    for (i, item) in items.iter().enumerate() {
        if i > 0 {
            f.write_str(", ")?;
        }
        one(f, item)?;
    }
    f.write_str("]")
}

fn write_double(f: &mut fmt::Formatter<'_>, x: f64) -> fmt::Result {
    if x.is_finite() && x.fract() == 0.0 && x.abs() < 1e15 {
        write!(f, "{x:.1}")
    } else {
        write!(f, "{x}")
    }
}

/// YAML-like text of the value (`0.5`, `"abc"`, `[1, 2]`).
impl fmt::Display for ParamValue {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ParamValue::Bool(b) => write!(f, "{b}"),
            ParamValue::Integer(i) => write!(f, "{i}"),
            ParamValue::Double(x) => write_double(f, *x),
            ParamValue::String(s) => write!(f, "{s:?}"),
            ParamValue::BoolArray(v) => write_list(f, v, |f, b| write!(f, "{b}")),
            ParamValue::IntegerArray(v) => write_list(f, v, |f, i| write!(f, "{i}")),
            ParamValue::DoubleArray(v) => write_list(f, v, |f, x| write_double(f, *x)),
            ParamValue::StringArray(v) => write_list(f, v, |f, s| write!(f, "{s:?}")),
        }
    }
}

/// A flat parameter set: dotted names (`plate.inner_radius`) → values, sorted by name.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Params {
    values: BTreeMap<String, ParamValue>,
}

impl Params {
    /// An empty parameter set (every key at its default).
    pub fn new() -> Params {
        Params::default()
    }

    /// Read a ROS 2 parameter file for the node `node_name`, text values
    /// read as `decl` declares them (`Params::from_file` with every
    /// declaration is defined with the registry).
    pub fn read_file(
        path: &Path,
        node_name: &str,
        decl: &Parameters,
    ) -> Result<Params, ConfigError> {
        let io = |e: std::io::Error| ConfigError::Io {
            path: path.to_path_buf(),
            message: e.to_string(),
        };
        let bytes = std::fs::metadata(path).map_err(io)?.len();
        if bytes > MAX_FILE_BYTES {
            return Err(ConfigError::TooLarge {
                path: path.to_path_buf(),
                bytes,
                limit: MAX_FILE_BYTES,
            });
        }
        // The size again while reading: a device or pipe (/dev/zero) has no length beforehand.
        let mut text = String::new();
        std::io::Read::read_to_string(
            &mut std::io::Read::take(std::fs::File::open(path).map_err(io)?, MAX_FILE_BYTES + 1),
            &mut text,
        )
        .map_err(|e| ConfigError::Io {
            path: path.to_path_buf(),
            message: e.to_string(),
        })?;
        if text.len() as u64 > MAX_FILE_BYTES {
            return Err(ConfigError::TooLarge {
                path: path.to_path_buf(),
                bytes: text.len() as u64,
                limit: MAX_FILE_BYTES,
            });
        }
        Params::parse_yaml(&text, node_name, decl).map_err(|e| match e {
            ConfigError::Yaml { message } => ConfigError::Yaml {
                message: format!("{}: {message}", path.display()),
            },
            other => other,
        })
    }

    /// Parse the text of a ROS 2 parameter file for the node `node_name`
    /// (`annular_plate`, `/annular_plate` or `/ns/annular_plate`).
    ///
    /// Entries apply in this order, later ones overriding earlier ones: `/**`,
    /// other wildcard entries matching the node (file order), then the node's
    /// own entries (file order).
    ///
    /// A value written as an integer for a key `decl` declares double is
    /// read as that double (`super::check::read_as_declared`).
    pub fn parse_yaml(
        text: &str,
        node_name: &str,
        decl: &Parameters,
    ) -> Result<Params, ConfigError> {
        check_depth(text)?;
        let doc: Value = serde_yaml_ng::from_str(text).map_err(|e| ConfigError::Yaml {
            message: e.to_string(),
        })?;
        let top = match doc {
            Value::Mapping(m) => m,
            Value::Null => serde_yaml_ng::Mapping::new(),
            other => {
                return Err(ConfigError::Yaml {
                    message: format!(
                        "the top level must be a map of node names (`{node_name}:` or `/**:`), found {}",
                        yaml_kind(&other)
                    ),
                })
            }
        };

        let node = node_name.trim();
        let mut found = Vec::new();
        // (priority, file index, entry name, entry value)
        let mut matching: Vec<(u8, usize, String, &Value)> = Vec::new();
        for (index, (key, value)) in top.iter().enumerate() {
            let entry = match key {
                Value::String(s) => s.clone(),
                other => {
                    return Err(ConfigError::Yaml {
                        message: format!(
                            "top-level keys must be node names, found {}",
                            yaml_kind(other)
                        ),
                    })
                }
            };
            found.push(entry.clone());
            if let Some(priority) = entry_priority(&entry, node) {
                matching.push((priority, index, entry, value));
            }
        }
        if matching.is_empty() {
            return Err(ConfigError::NoEntryForNode {
                node: node.to_string(),
                found,
            });
        }
        matching.sort_by_key(|(priority, index, _, _)| (*priority, *index));

        let mut params = Params::new();
        for (_, _, entry, value) in matching {
            let ros_parameters = ros_parameters_of(&entry, value)?;
            let mut own = BTreeMap::new();
            if let Some(map) = ros_parameters {
                flatten_map("", map, &mut own)?;
            }
            params.values.extend(own.into_iter().map(|(k, v)| {
                let v = super::check::read_as_declared(decl, &k, v);
                (k, v)
            }));
        }
        Ok(params)
    }

    /// Apply a command-line override `-p name:=value`; the value text is read
    /// as a YAML scalar or flat list (`0.1`, `clamped`, `[0, 1, 2]`, `true`).
    pub fn override_with(
        &mut self,
        name: &str,
        value_text: &str,
        decl: &Parameters,
    ) -> Result<(), ConfigError> {
        check_name(name)?;
        check_depth(value_text)?;
        let value: Value =
            serde_yaml_ng::from_str(value_text).map_err(|e| ConfigError::BadOverride {
                key: name.to_string(),
                text: value_text.to_string(),
                message: e.to_string(),
            })?;
        if let Value::Mapping(_) = value {
            return Err(ConfigError::BadOverride {
                key: name.to_string(),
                text: value_text.to_string(),
                message: "a parameter value is a scalar or a flat list, not a map".to_string(),
            });
        }
        let value = super::check::read_as_declared(decl, name, convert_value(name, &value)?);
        self.values.insert(name.to_string(), value);
        Ok(())
    }

    /// Set one parameter (replacing any earlier value).
    pub fn set(&mut self, name: &str, value: ParamValue) -> Result<(), ConfigError> {
        check_name(name)?;
        self.values.insert(name.to_string(), value);
        Ok(())
    }

    /// The value of a parameter, if given.
    pub fn get(&self, name: &str) -> Option<&ParamValue> {
        self.values.get(name)
    }

    /// All parameters, sorted by name.
    pub fn iter(&self) -> impl Iterator<Item = (&str, &ParamValue)> {
        self.values.iter().map(|(k, v)| (k.as_str(), v))
    }

    /// The number of parameters.
    pub fn len(&self) -> usize {
        self.values.len()
    }

    /// Whether there are none.
    pub fn is_empty(&self) -> bool {
        self.values.is_empty()
    }
}

/// `None` if `entry` does not apply to `node`; otherwise its rank (lower applies first).
fn entry_priority(entry: &str, node: &str) -> Option<u8> {
    // As rcl's YAML parser and rclcpp: a name without a leading `/` is in
    // the root namespace (`annular_plate` ≡ `/annular_plate`), and an entry
    // applies to the node whose fully qualified name it is — or matches as a
    // wildcard pattern.
    let entry_tokens = tokens(entry);
    let node_tokens = tokens(node);
    if entry_tokens == ["**"] {
        return Some(0);
    }
    if entry_tokens.iter().any(|t| t.contains('*')) {
        return glob_match(&entry_tokens, &node_tokens).then_some(1);
    }
    (!entry_tokens.is_empty() && entry_tokens == node_tokens).then_some(2)
}

fn tokens(name: &str) -> Vec<&str> {
    name.trim().split('/').filter(|t| !t.is_empty()).collect()
}

/// ROS 2 node-name wildcards: `*` matches one token, `**` any number (also none).
fn glob_match(pattern: &[&str], name: &[&str]) -> bool {
    match pattern.split_first() {
        None => name.is_empty(),
        Some((&"**", rest)) => (0..=name.len()).any(|skip| glob_match(rest, &name[skip..])),
        Some((p, rest)) => match name.split_first() {
            Some((n, name_rest)) => token_match(p, n) && glob_match(rest, name_rest),
            None => false,
        },
    }
}

/// One token with `*` wildcards inside (`annular_*`).
fn token_match(pattern: &str, token: &str) -> bool {
    if !pattern.contains('*') {
        return pattern == token;
    }
    let parts: Vec<&str> = pattern.split('*').collect();
    let (first, last) = (parts[0], parts[parts.len() - 1]);
    if !token.starts_with(first) || token.len() < first.len() + last.len() || !token.ends_with(last)
    {
        return false;
    }
    let mut rest = &token[first.len()..token.len() - last.len()];
    for part in &parts[1..parts.len() - 1] {
        match rest.find(part) {
            Some(pos) => rest = &rest[pos + part.len()..],
            None => return false,
        }
    }
    true
}

fn ros_parameters_of<'a>(
    entry: &str,
    value: &'a Value,
) -> Result<Option<&'a serde_yaml_ng::Mapping>, ConfigError> {
    let map = match value {
        Value::Mapping(m) => m,
        _ => {
            return Err(ConfigError::MissingRosParameters {
                entry: entry.to_string(),
            })
        }
    };
    let mut result = None;
    let mut seen = false;
    for (key, inner) in map {
        match key {
            Value::String(k) if k == "ros__parameters" => {
                seen = true;
                result = match inner {
                    Value::Mapping(m) => Some(m),
                    Value::Null => None,
                    other => {
                        return Err(ConfigError::Yaml {
                            message: format!(
                                "`{entry}: ros__parameters:` must be a map, found {}",
                                yaml_kind(other)
                            ),
                        })
                    }
                };
            }
            other => {
                return Err(ConfigError::UnexpectedEntryKey {
                    entry: entry.to_string(),
                    key: key_text(other),
                });
            }
        }
    }
    if !seen {
        return Err(ConfigError::MissingRosParameters {
            entry: entry.to_string(),
        });
    }
    Ok(result)
}

fn flatten_map(
    prefix: &str,
    map: &serde_yaml_ng::Mapping,
    out: &mut BTreeMap<String, ParamValue>,
) -> Result<(), ConfigError> {
    for (key, value) in map {
        let name_part = match key {
            Value::String(s) => s.clone(),
            Value::Number(n) => n.to_string(),
            Value::Bool(b) => b.to_string(),
            other => {
                return Err(ConfigError::BadParameterName {
                    name: format!("{prefix}{}", key_text(other)),
                    reason: format!(
                        "a parameter name must be a string, found {}",
                        yaml_kind(other)
                    ),
                })
            }
        };
        let name = format!("{prefix}{name_part}");
        match value {
            Value::Mapping(inner) => flatten_map(&format!("{name}."), inner, out)?,
            other => {
                check_name(&name)?;
                let converted = convert_value(&name, other)?;
                if out.insert(name.clone(), converted).is_some() {
                    return Err(ConfigError::DuplicateKey { key: name });
                }
            }
        }
    }
    Ok(())
}

fn check_name(name: &str) -> Result<(), ConfigError> {
    let bad = |reason: &str| {
        Err(ConfigError::BadParameterName {
            name: name.to_string(),
            reason: reason.to_string(),
        })
    };
    if name.is_empty() {
        return bad("the name is empty");
    }
    if name.chars().any(char::is_whitespace) {
        return bad("it contains whitespace");
    }
    if name.split('.').any(str::is_empty) {
        return bad("it has an empty part between dots");
    }
    Ok(())
}

#[derive(Clone, Copy, PartialEq)]
enum ElemKind {
    Bool,
    Integer,
    Double,
    String,
}

impl ElemKind {
    fn name(self) -> &'static str {
        match self {
            ElemKind::Bool => "bool",
            ElemKind::Integer => "integer",
            ElemKind::Double => "double",
            ElemKind::String => "string",
        }
    }
}

fn convert_value(key: &str, value: &Value) -> Result<ParamValue, ConfigError> {
    match value {
        Value::Null => Err(ConfigError::MissingValue {
            key: key.to_string(),
        }),
        Value::Bool(b) => Ok(ParamValue::Bool(*b)),
        Value::Number(_) => match number(key, value)? {
            Scalar::Integer(i) => Ok(ParamValue::Integer(i)),
            Scalar::Double(x) => Ok(ParamValue::Double(x)),
        },
        Value::String(s) => Ok(ParamValue::String(s.clone())),
        Value::Sequence(items) => convert_list(key, items),
        Value::Mapping(_) => Err(ConfigError::Yaml {
            message: format!("{key}: unexpected map"),
        }),
        Value::Tagged(t) => Err(ConfigError::WrongType {
            key: key.to_string(),
            expected: "a ROS 2 parameter value (no YAML tags)",
            found: format!("the tagged value !{}", t.tag),
        }),
    }
}

enum Scalar {
    Integer(i64),
    Double(f64),
}

fn number(key: &str, value: &Value) -> Result<Scalar, ConfigError> {
    let Value::Number(n) = value else {
        unreachable!("number() is only called on numbers")
    };
    if let Some(i) = n.as_i64() {
        Ok(Scalar::Integer(i))
    } else if n.is_f64() {
        Ok(Scalar::Double(n.as_f64().unwrap_or(f64::NAN)))
    } else {
        Err(ConfigError::WrongType {
            key: key.to_string(),
            expected: "an integer that fits in 64 signed bits",
            found: format!("integer {n}"),
        })
    }
}

fn convert_list(key: &str, items: &[Value]) -> Result<ParamValue, ConfigError> {
    let mut kind: Option<ElemKind> = None;
    for item in items {
        let this = match item {
            Value::Bool(_) => ElemKind::Bool,
            Value::Number(_) => match number(key, item)? {
                Scalar::Integer(_) => ElemKind::Integer,
                Scalar::Double(_) => ElemKind::Double,
            },
            Value::String(_) => ElemKind::String,
            Value::Sequence(_) | Value::Mapping(_) => {
                return Err(ConfigError::NestedList {
                    key: key.to_string(),
                })
            }
            Value::Null => {
                return Err(ConfigError::MissingValue {
                    key: key.to_string(),
                })
            }
            Value::Tagged(t) => {
                return Err(ConfigError::WrongType {
                    key: key.to_string(),
                    expected: "a flat list of ROS 2 parameter values (no YAML tags)",
                    found: format!("the tagged value !{}", t.tag),
                })
            }
        };
        kind = Some(match (kind, this) {
            (None, k) => k,
            (Some(a), b) if a == b => a,
            (Some(ElemKind::Integer), ElemKind::Double)
            | (Some(ElemKind::Double), ElemKind::Integer) => ElemKind::Double,
            (Some(a), b) => {
                return Err(ConfigError::MixedList {
                    key: key.to_string(),
                    first: a.name(),
                    other: b.name(),
                })
            }
        });
    }
    Ok(match kind {
        None => ParamValue::DoubleArray(Vec::new()),
        Some(ElemKind::Bool) => {
            ParamValue::BoolArray(items.iter().filter_map(Value::as_bool).collect())
        }
        Some(ElemKind::Integer) => {
            ParamValue::IntegerArray(items.iter().filter_map(Value::as_i64).collect())
        }
        Some(ElemKind::Double) => {
            ParamValue::DoubleArray(items.iter().filter_map(Value::as_f64).collect())
        }
        Some(ElemKind::String) => ParamValue::StringArray(
            items
                .iter()
                .filter_map(|v| v.as_str().map(str::to_string))
                .collect(),
        ),
    })
}

fn yaml_kind(value: &Value) -> String {
    match value {
        Value::Null => "null".to_string(),
        Value::Bool(b) => format!("the bool {b}"),
        Value::Number(n) => format!("the number {n}"),
        Value::String(s) => format!("the string {s:?}"),
        Value::Sequence(_) => "a list".to_string(),
        Value::Mapping(_) => "a map".to_string(),
        Value::Tagged(t) => format!("the tagged value !{}", t.tag),
    }
}

fn key_text(value: &Value) -> String {
    match value {
        Value::String(s) => s.clone(),
        other => yaml_kind(other),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn node_entry_matching() {
        assert_eq!(entry_priority("/**", "annular_plate"), Some(0));
        assert_eq!(entry_priority("annular_plate", "annular_plate"), Some(2));
        assert_eq!(entry_priority("/annular_plate", "annular_plate"), Some(2));
        assert_eq!(entry_priority("annular_plate", "/annular_plate"), Some(2));
        // rclcpp: an entry without a namespace is the root namespace's node only.
        assert_eq!(entry_priority("/ns/annular_plate", "annular_plate"), None);
        assert_eq!(entry_priority("annular_plate", "/ns/annular_plate"), None);
        assert_eq!(
            entry_priority("/ns/annular_plate", "/ns/annular_plate"),
            Some(2)
        );
        assert_eq!(
            entry_priority("/other/annular_plate", "/ns/annular_plate"),
            None
        );
        assert_eq!(entry_priority("other_node", "annular_plate"), None);
        assert_eq!(
            entry_priority("/**/annular_plate", "/a/b/annular_plate"),
            Some(1)
        );
        assert_eq!(
            entry_priority("/*/annular_plate", "/a/annular_plate"),
            Some(1)
        );
        assert_eq!(
            entry_priority("/*/annular_plate", "/a/b/annular_plate"),
            None
        );
        assert_eq!(entry_priority("/annular_*", "/annular_plate"), Some(1));
    }
}
