//! Typed access to a flat [`Params`] set: each getter returns the value of
//! one key, or its declared default (`config/table.rs`), as a Rust type.
//!
//! Every value goes through the one check (`config::check`): the declared
//! type, strict as rclcpp's (an integer is not a double; a text value written
//! as an integer for a double key was read as that double when it was
//! parsed), finite doubles, the declared range. An empty array of any type
//! is accepted wherever an array is declared. What is left here are the rules
//! a section adds (`read_choice`, `positive` for keys whose range the table
//! does not state alone).

use super::check::{declared_value, given_value, typed, Declared};
use super::{ConfigError, Parameters, Params};

/// Reads keys of one parameter set (the configuration's readers and the
/// load models' section readers). `known` is the table of keys the
/// validator accepts; in debug builds reading a key outside it is a bug.
pub(crate) struct Reader<'a> {
    params: &'a Params,
    decl: &'a Parameters,
    known: &'a [&'a str],
}

impl<'a> Reader<'a> {
    pub(crate) fn new(params: &'a Params, decl: &'a Parameters, known: &'a [&'a str]) -> Self {
        Reader {
            params,
            decl,
            known,
        }
    }

    /// The declarations the values are read against.
    pub(crate) fn parameters(&self) -> &Parameters {
        self.decl
    }

    fn debug_known(&self, key: &str) {
        debug_assert!(
            self.known.contains(&key),
            "config key {key} is read but missing from the table of known keys"
        );
    }

    /// The value of `key`, or its declared default; `MissingValue` when it
    /// has neither.
    fn value<T: Declared>(&self, key: &str) -> Result<T, ConfigError> {
        self.debug_known(key);
        match declared_value(self.decl, self.params, key)? {
            Some(v) => typed(self.decl, key, &v),
            None => Err(ConfigError::MissingValue {
                key: key.to_string(),
            }),
        }
    }

    /// Whether the parameter set gives `key` at all.
    pub(crate) fn has(&self, key: &str) -> bool {
        self.debug_known(key);
        self.params.get(key).is_some()
    }

    /// A double key's value or its declared default.
    pub(crate) fn f64(&self, key: &str) -> Result<f64, ConfigError> {
        self.value(key)
    }

    /// A double key's value when given (its default not applied).
    pub(crate) fn f64_opt(&self, key: &str) -> Result<Option<f64>, ConfigError> {
        self.debug_known(key);
        given_value(self.decl, self.params, key)?
            .map(|v| typed(self.decl, key, &v))
            .transpose()
    }

    /// A double > 0 (value or declared default).
    pub(crate) fn positive(&self, key: &str) -> Result<f64, ConfigError> {
        positive(key, self.f64(key)?)
    }

    /// An integer key's value or its declared default.
    pub(crate) fn i64(&self, key: &str) -> Result<i64, ConfigError> {
        self.value(key)
    }

    /// An integer key's value (or its declared default) as a `u32`; its
    /// declared range was checked by `config::check`.
    pub(crate) fn u32(&self, key: &str) -> Result<u32, ConfigError> {
        let i = self.i64(key)?;
        u32::try_from(i).map_err(|_| ConfigError::AboveMaximum {
            key: key.to_string(),
            value: i as f64,
            max: u32::MAX as f64,
        })
    }

    pub(crate) fn bool(&self, key: &str) -> Result<bool, ConfigError> {
        self.value(key)
    }

    pub(crate) fn string(&self, key: &str) -> Result<String, ConfigError> {
        self.value(key)
    }

    /// A list of strings (empty when neither given nor declared).
    pub(crate) fn string_array(&self, key: &str) -> Result<Vec<String>, ConfigError> {
        self.array(key)
    }

    /// A list of doubles.
    pub(crate) fn f64_array(&self, key: &str) -> Result<Vec<f64>, ConfigError> {
        self.array(key)
    }

    pub(crate) fn i64_array(&self, key: &str) -> Result<Vec<i64>, ConfigError> {
        self.array(key)
    }

    fn array<T>(&self, key: &str) -> Result<Vec<T>, ConfigError>
    where
        Vec<T>: Declared,
    {
        self.debug_known(key);
        match declared_value(self.decl, self.params, key)? {
            Some(v) => typed(self.decl, key, &v),
            None => Ok(Vec::new()),
        }
    }

    /// Exactly three doubles.
    pub(crate) fn vec3(&self, key: &str) -> Result<[f64; 3], ConfigError> {
        let v = self.f64_array(key)?;
        <[f64; 3]>::try_from(v.as_slice()).map_err(|_| ConfigError::WrongLength {
            key: key.to_string(),
            len: v.len(),
            expected: 3,
        })
    }
}

pub(crate) fn positive(key: &str, x: f64) -> Result<f64, ConfigError> {
    if x > 0.0 {
        Ok(x)
    } else {
        Err(ConfigError::NotPositive {
            key: key.to_string(),
            value: x,
        })
    }
}

/// A string key (value or declared default) that must be one of `allowed`,
/// parsed by `parse`.
pub(crate) fn read_choice<T>(
    r: &Reader,
    key: &str,
    allowed: &'static [&'static str],
    parse: impl Fn(&str) -> Option<T>,
) -> Result<T, ConfigError> {
    let name = r.string(key)?;
    parse(name.trim()).ok_or(ConfigError::UnknownChoice {
        key: key.to_string(),
        value: name,
        allowed,
    })
}
