//! Typed access to a flat [`Params`] set: each getter returns the value of one
//! key (or its default) converted to a Rust type, with errors that name the key.
//!
//! Type rules (ROS 2 parameter types): an integer is accepted where a double is
//! expected (also inside arrays); a double is never silently truncated to an
//! integer; an empty array of any type is accepted wherever an array is expected;
//! every double must be finite.

use super::{ConfigError, ParamValue, Params};

/// Reads keys of one parameter set. `known` is the table of keys the
/// validator accepts; in debug builds reading a key outside it is a bug.
pub(super) struct Reader<'a> {
    params: &'a Params,
    known: &'a [&'a str],
}

impl<'a> Reader<'a> {
    pub(super) fn new(params: &'a Params, known: &'a [&'a str]) -> Self {
        Reader { params, known }
    }

    fn get(&self, key: &str) -> Option<&'a ParamValue> {
        debug_assert!(
            self.known.contains(&key),
            "config key {key} is read but missing from the table of known keys"
        );
        self.params.get(key)
    }

    /// A double key's value or its declared default (`config/table.rs`); its
    /// type and range were checked by `config::check` before any section is read.
    pub(super) fn declared_f64(&self, key: &str) -> Result<f64, ConfigError> {
        match (self.get(key), super::table::find(key).map(|p| p.default)) {
            (Some(ParamValue::Double(x)), _) => Ok(*x),
            (None, Some(super::table::Value::Double(x))) => Ok(x),
            (Some(other), _) => Err(wrong_type(key, "a double", other)),
            (None, _) => Err(ConfigError::MissingValue {
                key: key.to_string(),
            }),
        }
    }

    /// An integer key's value (or its declared default) as a `u32`; its
    /// declared range was checked by `config::check`.
    pub(super) fn declared_u32(&self, key: &str) -> Result<u32, ConfigError> {
        let i = match (self.get(key), super::table::find(key).map(|p| p.default)) {
            (Some(ParamValue::Integer(i)), _) => *i,
            (None, Some(super::table::Value::Integer(i))) => i,
            (Some(other), _) => return Err(wrong_type(key, "an integer", other)),
            (None, _) => {
                return Err(ConfigError::MissingValue {
                    key: key.to_string(),
                })
            }
        };
        u32::try_from(i).map_err(|_| ConfigError::AboveMaximum {
            key: key.to_string(),
            value: i as f64,
            max: u32::MAX as f64,
        })
    }

    /// Whether the parameter set gives `key` at all.
    pub(super) fn has(&self, key: &str) -> bool {
        self.get(key).is_some()
    }

    /// A finite double (an integer is accepted).
    pub(super) fn f64_opt(&self, key: &str) -> Result<Option<f64>, ConfigError> {
        let x = match self.get(key) {
            None => return Ok(None),
            Some(ParamValue::Double(x)) => *x,
            Some(ParamValue::Integer(i)) => *i as f64,
            Some(other) => return Err(wrong_type(key, "a number (double)", other)),
        };
        finite(key, x).map(Some)
    }

    pub(super) fn f64(&self, key: &str, default: f64) -> Result<f64, ConfigError> {
        Ok(self.f64_opt(key)?.unwrap_or(default))
    }

    /// A finite double > 0.
    pub(super) fn positive(&self, key: &str, default: f64) -> Result<f64, ConfigError> {
        let x = self.f64(key, default)?;
        positive(key, x)
    }

    pub(super) fn i64(&self, key: &str, default: i64) -> Result<i64, ConfigError> {
        match self.get(key) {
            None => Ok(default),
            Some(ParamValue::Integer(i)) => Ok(*i),
            Some(other) => Err(wrong_type(key, "an integer", other)),
        }
    }

    pub(super) fn bool(&self, key: &str, default: bool) -> Result<bool, ConfigError> {
        match self.get(key) {
            None => Ok(default),
            Some(ParamValue::Bool(b)) => Ok(*b),
            Some(other) => Err(wrong_type(key, "a bool (true or false)", other)),
        }
    }

    pub(super) fn string(&self, key: &str, default: &str) -> Result<String, ConfigError> {
        match self.get(key) {
            None => Ok(default.to_string()),
            Some(ParamValue::String(s)) => Ok(s.clone()),
            Some(other) => Err(wrong_type(key, "a string", other)),
        }
    }

    /// A list of strings (empty when not given).
    pub(super) fn string_array(&self, key: &str) -> Result<Vec<String>, ConfigError> {
        match self.get(key) {
            None => Ok(Vec::new()),
            Some(ParamValue::StringArray(v)) => Ok(v.clone()),
            Some(other) if other.array_len() == Some(0) => Ok(Vec::new()),
            Some(other) => Err(wrong_type(key, "a list of strings (string array)", other)),
        }
    }

    /// A list of finite doubles (integers accepted); a non-finite element is
    /// reported as `key[index]`.
    pub(super) fn f64_array(&self, key: &str, default: &[f64]) -> Result<Vec<f64>, ConfigError> {
        let values = match self.get(key) {
            None => default.to_vec(),
            Some(ParamValue::DoubleArray(v)) => v.clone(),
            Some(ParamValue::IntegerArray(v)) => v.iter().map(|&i| i as f64).collect(),
            Some(other) if other.array_len() == Some(0) => Vec::new(),
            Some(other) => return Err(wrong_type(key, "a list of numbers (double array)", other)),
        };
        for (index, &x) in values.iter().enumerate() {
            finite(&format!("{key}[{index}]"), x)?;
        }
        Ok(values)
    }

    pub(super) fn i64_array(&self, key: &str, default: &[i64]) -> Result<Vec<i64>, ConfigError> {
        match self.get(key) {
            None => Ok(default.to_vec()),
            Some(ParamValue::IntegerArray(v)) => Ok(v.clone()),
            Some(other) if other.array_len() == Some(0) => Ok(Vec::new()),
            Some(other) => Err(wrong_type(key, "a list of integers (integer array)", other)),
        }
    }

    /// Exactly three finite doubles.
    pub(super) fn vec3(&self, key: &str, default: [f64; 3]) -> Result<[f64; 3], ConfigError> {
        let v = self.f64_array(key, &default)?;
        <[f64; 3]>::try_from(v.as_slice()).map_err(|_| ConfigError::WrongLength {
            key: key.to_string(),
            len: v.len(),
            expected: 3,
        })
    }
}

pub(super) fn finite(key: &str, x: f64) -> Result<f64, ConfigError> {
    if x.is_finite() {
        Ok(x)
    } else {
        Err(ConfigError::NonFinite {
            key: key.to_string(),
        })
    }
}

pub(super) fn positive(key: &str, x: f64) -> Result<f64, ConfigError> {
    if x > 0.0 {
        Ok(x)
    } else {
        Err(ConfigError::NotPositive {
            key: key.to_string(),
            value: x,
        })
    }
}

fn wrong_type(key: &str, expected: &'static str, found: &ParamValue) -> ConfigError {
    ConfigError::WrongType {
        key: key.to_string(),
        expected,
        found: format!("{} {found}", found.type_name()),
    }
}

/// A string key that must be one of `allowed`, parsed by `parse`.
pub(super) fn read_choice<T>(
    r: &Reader,
    key: &str,
    default: &str,
    allowed: &'static [&'static str],
    parse: impl Fn(&str) -> Option<T>,
) -> Result<T, ConfigError> {
    let name = r.string(key, default)?;
    parse(name.trim()).ok_or(ConfigError::UnknownChoice {
        key: key.to_string(),
        value: name,
        allowed,
    })
}
