//! The declared defaults of the configuration's own sections ([`super::table`]) by key, as `const fn`s: a
//! default that a constant or a `Default` impl needs is read from the
//! declaration when the crate compiles (`const { default_f64("joint.speed") }`),
//! so each default is written once; an undeclared key, or a default of
//! another type, does not compile.

use super::table::{Section, Value, AFTER_LOAD_MODELS, BEFORE_LOAD_MODELS};

/// The declared default of `key`.
pub const fn default_of(key: &str) -> Value {
    match default_in(BEFORE_LOAD_MODELS, key) {
        Some(v) => v,
        None => match default_in(AFTER_LOAD_MODELS, key) {
            Some(v) => v,
            None => panic!("default_of: the key is not declared in config/table.rs"),
        },
    }
}

/// The declared default of `key` among `sections` (a load model's own,
/// `const { default_in(SECTIONS, "springs.stiffness") }`), `None` if undeclared there.
pub const fn default_in(sections: &[Section], key: &str) -> Option<Value> {
    let mut s = 0;
    while s < sections.len() {
        let params = sections[s].params;
        let mut i = 0;
        while i < params.len() {
            if same(params[i].key, key) {
                return Some(params[i].default);
            }
            i += 1;
        }
        s += 1;
    }
    None
}

const fn same(a: &str, b: &str) -> bool {
    let (a, b) = (a.as_bytes(), b.as_bytes());
    if a.len() != b.len() {
        return false;
    }
    let mut i = 0;
    while i < a.len() {
        if a[i] != b[i] {
            return false;
        }
        i += 1;
    }
    true
}

/// The declared double default of `key` (compile-time in a const context).
pub const fn default_f64(key: &str) -> f64 {
    match default_of(key) {
        Value::Double(x) => x,
        _ => panic!("default_f64: the key's declared default is not a double"),
    }
}

/// The declared integer default of `key`.
pub const fn default_i64(key: &str) -> i64 {
    match default_of(key) {
        Value::Integer(i) => i,
        _ => panic!("default_i64: the key's declared default is not an integer"),
    }
}

/// The declared bool default of `key`.
pub const fn default_bool(key: &str) -> bool {
    match default_of(key) {
        Value::Bool(b) => b,
        _ => panic!("default_bool: the key's declared default is not a bool"),
    }
}

/// The declared string default of `key`.
pub const fn default_str(key: &str) -> &'static str {
    match default_of(key) {
        Value::Str(s) => s,
        _ => panic!("default_str: the key's declared default is not a string"),
    }
}

/// The declared double-array default of `key`.
pub const fn default_f64s(key: &str) -> &'static [f64] {
    match default_of(key) {
        Value::Doubles(a) => a,
        _ => panic!("default_f64s: the key's declared default is not a double array"),
    }
}

/// The declared integer-array default of `key`.
pub const fn default_i64s(key: &str) -> &'static [i64] {
    match default_of(key) {
        Value::Integers(a) => a,
        _ => panic!("default_i64s: the key's declared default is not an integer array"),
    }
}
