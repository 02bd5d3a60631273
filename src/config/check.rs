//! The one check of a parameter value against its declaration
//! ([`Parameters`]): known key, declared type (strict, as rclcpp's: an
//! integer is not a double), every double finite, every number in the
//! declared range. Every source of a value goes through it: the parameter
//! file and `-p` (`Config::from_params` and `RosSettings::from_params` read
//! every value through [`declared_value`] and [`typed`]) and the node's
//! parameter services (`ros/params_service.rs`), so nothing the start-up
//! path refuses can arrive by a service, and the refusal reads the same. Rules between keys
//! (`plate.inner_radius` < `plate.outer_radius`, …) stay with their section
//! in `validate.rs`.

use super::table::{Bound, Param, Ty};
use super::{ConfigError, ParamValue, Parameters, Params};

/// Check `value` for `key`: the key is declared, the value has its type and
/// lies in its range. The error names the key (`key[i]` for an array element).
pub fn check(
    decl: &Parameters,
    key: &str,
    value: &ParamValue,
) -> Result<&'static Param, ConfigError> {
    let Some(param) = decl.find(key) else {
        return Err(unknown(decl, key));
    };
    let wrong = || ConfigError::WrongType {
        key: key.to_string(),
        expected: param.ty.expected(),
        found: format!("{} {value}", value.type_name()),
    };
    let empty = value.array_len() == Some(0);
    match (param.ty, value) {
        (Ty::Bool, ParamValue::Bool(_)) | (Ty::String, ParamValue::String(_)) => Ok(param),
        (Ty::AutoOrInteger | Ty::AutoOrDouble, ParamValue::String(_)) => Ok(param),
        (Ty::Integer | Ty::AutoOrInteger, ParamValue::Integer(i)) => {
            in_range(param, key, *i as f64).map(|_| param)
        }
        (Ty::Double | Ty::AutoOrDouble, ParamValue::Double(x)) => {
            in_range(param, key, *x).map(|_| param)
        }
        (Ty::IntegerArray | Ty::DoubleArray | Ty::StringArray, _) if empty => Ok(param),
        (Ty::StringArray, ParamValue::StringArray(_)) => Ok(param),
        (Ty::IntegerArray, ParamValue::IntegerArray(v)) => v
            .iter()
            .enumerate()
            .try_for_each(|(i, &x)| in_range(param, &format!("{key}[{i}]"), x as f64))
            .map(|_| param),
        (Ty::DoubleArray, ParamValue::DoubleArray(v)) => v
            .iter()
            .enumerate()
            .try_for_each(|(i, &x)| in_range(param, &format!("{key}[{i}]"), x))
            .map(|_| param),
        _ => Err(wrong()),
    }
}

fn unknown(decl: &Parameters, key: &str) -> ConfigError {
    let known = decl.known_keys();
    ConfigError::UnknownKey {
        key: key.to_string(),
        suggestion: suggest(key, &known),
    }
}

/// Check every value of a parameter set ([`check`]).
pub fn check_params(decl: &Parameters, params: &Params) -> Result<(), ConfigError> {
    params
        .iter()
        .try_for_each(|(key, value)| check(decl, key, value).map(|_| ()))
}

/// The value of `key` in `params` after [`check`], or its declared default
/// (`None`: the key is not given and declares no default). The readers of
/// the configuration (`config::raw::Reader`) and of the node's settings
/// (`RosSettings::from_params`) take every value through this.
pub(crate) fn declared_value(
    decl: &Parameters,
    params: &Params,
    key: &str,
) -> Result<Option<ParamValue>, ConfigError> {
    match params.get(key) {
        Some(value) => check(decl, key, value).map(|_| Some(value.clone())),
        None => match decl.find(key) {
            Some(param) => Ok(param.default.to_param()),
            None => Err(unknown(decl, key)),
        },
    }
}

/// The given value of `key` after [`check`] (its default not applied).
pub(crate) fn given_value(
    decl: &Parameters,
    params: &Params,
    key: &str,
) -> Result<Option<ParamValue>, ConfigError> {
    match params.get(key) {
        Some(value) => check(decl, key, value).map(|_| Some(value.clone())),
        None => Ok(None),
    }
}

/// A value [`check`] passed, as the Rust type of its declared type: `Double`
/// → f64, `Integer` → i64, arrays → vectors (an empty array of any element
/// type is an empty vector). A value of another type (not reachable after
/// [`check`]) is the same error [`check`] gives.
pub(crate) trait Declared: Sized {
    fn from_value(value: &ParamValue) -> Option<Self>;
}

impl Declared for f64 {
    fn from_value(value: &ParamValue) -> Option<Self> {
        match value {
            ParamValue::Double(x) => Some(*x),
            _ => None,
        }
    }
}

impl Declared for i64 {
    fn from_value(value: &ParamValue) -> Option<Self> {
        match value {
            ParamValue::Integer(i) => Some(*i),
            _ => None,
        }
    }
}

impl Declared for bool {
    fn from_value(value: &ParamValue) -> Option<Self> {
        match value {
            ParamValue::Bool(b) => Some(*b),
            _ => None,
        }
    }
}

impl Declared for String {
    fn from_value(value: &ParamValue) -> Option<Self> {
        match value {
            ParamValue::String(s) => Some(s.clone()),
            _ => None,
        }
    }
}

impl Declared for Vec<f64> {
    fn from_value(value: &ParamValue) -> Option<Self> {
        match value {
            ParamValue::DoubleArray(v) => Some(v.clone()),
            v if v.array_len() == Some(0) => Some(Vec::new()),
            _ => None,
        }
    }
}

impl Declared for Vec<i64> {
    fn from_value(value: &ParamValue) -> Option<Self> {
        match value {
            ParamValue::IntegerArray(v) => Some(v.clone()),
            v if v.array_len() == Some(0) => Some(Vec::new()),
            _ => None,
        }
    }
}

impl Declared for Vec<String> {
    fn from_value(value: &ParamValue) -> Option<Self> {
        match value {
            ParamValue::StringArray(v) => Some(v.clone()),
            v if v.array_len() == Some(0) => Some(Vec::new()),
            _ => None,
        }
    }
}

/// `value` (of `key`) as `T`, or the wrong-type error of [`check`].
pub(crate) fn typed<T: Declared>(
    decl: &Parameters,
    key: &str,
    value: &ParamValue,
) -> Result<T, ConfigError> {
    T::from_value(value).ok_or_else(|| ConfigError::WrongType {
        key: key.to_string(),
        expected: decl
            .find(key)
            .map_or("a declared type", |p| p.ty.expected()),
        found: format!("{} {value}", value.type_name()),
    })
}

/// A text value (file, `-p`) for a key declared double (or double array)
/// written as an integer (`rate_hz: 1000`, `[0, 0, -100]`) is read as the
/// double it spells; a typed value (a parameter service's) is not converted.
pub fn read_as_declared(decl: &Parameters, key: &str, value: ParamValue) -> ParamValue {
    match (decl.find(key).map(|p| p.ty), value) {
        (Some(Ty::Double | Ty::AutoOrDouble), ParamValue::Integer(i)) => {
            ParamValue::Double(i as f64)
        }
        (Some(Ty::DoubleArray), ParamValue::IntegerArray(v)) => {
            ParamValue::DoubleArray(v.into_iter().map(|i| i as f64).collect())
        }
        (_, value) => value,
    }
}

fn in_range(param: &Param, key: &str, x: f64) -> Result<(), ConfigError> {
    if !x.is_finite() {
        return Err(ConfigError::NonFinite {
            key: key.to_string(),
        });
    }
    let r = param.range;
    if r.contains(x) {
        return Ok(());
    }
    let key = key.to_string();
    let min = match r.min {
        Bound::Open => f64::NEG_INFINITY,
        Bound::Inclusive(m) | Bound::Exclusive(m) => m,
    };
    let zero_allowed = r.or_zero || r.min == Bound::Inclusive(0.0);
    Err(match r.max {
        Bound::Inclusive(max) | Bound::Exclusive(max) if x >= max => {
            ConfigError::AboveMaximum { key, value: x, max }
        }
        _ if x < 0.0 && zero_allowed => ConfigError::Negative { key, value: x },
        _ if x <= 0.0 && min >= 0.0 && !zero_allowed => ConfigError::NotPositive { key, value: x },
        _ => ConfigError::OutOfRange {
            key,
            value: x,
            rule: r.text(),
        },
    })
}

/// The known key a typo most likely meant: a close spelling, the same name
/// in another section (`simulation.speed` → `joint.speed`), or a known name
/// the given one abbreviates (`plate.poisson` → `plate.poisson_ratio`).
pub(super) fn suggest(key: &str, known: &[&str]) -> Option<String> {
    let lower = key.to_lowercase();
    let best = known
        .iter()
        .map(|k| (levenshtein(&lower, k), *k))
        .min_by_key(|(d, _)| *d);
    if let Some((d, k)) = best {
        if d <= (k.chars().count() / 6).max(2) {
            return Some(k.to_string());
        }
    }
    let (section, last) = match lower.rsplit_once('.') {
        Some((s, l)) => (s, l),
        None => ("", lower.as_str()),
    };
    let last_of = |k: &str| k.rsplit_once('.').map_or(k, |(_, l)| l).to_string();
    let section_of = |k: &str| k.rsplit_once('.').map_or("", |(s, _)| s).to_string();
    if let Some(k) = known.iter().find(|k| last_of(k) == last) {
        return Some(k.to_string());
    }
    if last.chars().count() >= 4 {
        if let Some(k) = known
            .iter()
            .find(|k| section_of(k) == section && last_of(k).starts_with(last))
        {
            return Some(k.to_string());
        }
    }
    None
}

fn levenshtein(a: &str, b: &str) -> usize {
    let a: Vec<char> = a.chars().collect();
    let b: Vec<char> = b.chars().collect();
    let mut prev: Vec<usize> = (0..=b.len()).collect();
    let mut cur = vec![0; b.len() + 1];
    for i in 1..=a.len() {
        cur[0] = i;
        for j in 1..=b.len() {
            let cost = usize::from(a[i - 1] != b[j - 1]);
            cur[j] = (prev[j] + 1).min(cur[j - 1] + 1).min(prev[j - 1] + cost);
        }
        std::mem::swap(&mut prev, &mut cur);
    }
    prev[b.len()]
}
