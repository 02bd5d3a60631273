//! Every default is written once, in the declaration (`config/table.rs`):
//! for every declared parameter, a scene without the key yields what the
//! same scene with the key set to its declared default yields (the whole
//! validated `Config`, and the node's `RosSettings`), the `Default` impls are
//! what an empty parameter file yields, and the node's parameter service
//! reports the declared default as the value, its type and its description.

#![cfg(feature = "ros")]

use annular_plate::config::table::{Param, Value};
use annular_plate::config::{Config, ParamValue, Params};
use annular_plate::dynamics::load_models::PARAMETERS;
use annular_plate::messages::settings::RosSettings;
use annular_plate::ros::params_service::{effective_parameters, ParamStore};
use ros2_client::parameters::raw::ParameterType;

/// The scene a key of `section` is read in: its load model switched on
/// (every other key of a load-model section is refused without it). A model
/// switched on by nodes (`…ale_node(s)`, `…lagrange_nodes`) gets one node of
/// that kind; any registered model, not a list of them.
fn base(section: &str) -> Params {
    let mut p = Params::new();
    let mut set = |k: &str, v: &str| p.set_override(k, v).unwrap();
    if section == "calipers" {
        set("calipers.angles_deg", "[0.0]");
        set("calipers.inner_radius", "0.1");
        set("calipers.outer_radius", "0.15");
        return p;
    }
    let Some(enabling) = PARAMETERS.enabled_by(section) else {
        return p;
    };
    let kind = if enabling.contains("lagrange_node") {
        "lagrange"
    } else if enabling.contains("ale_node") {
        "ale"
    } else {
        panic!("{section}: switched on by {enabling}, not by nodes: give it a base scene here")
    };
    set(&format!("nodes.{kind}_radial"), "[1.0]");
    set(&format!("nodes.{kind}_angular"), "[0.0]");
    set(enabling, if enabling.ends_with('s') { "[1]" } else { "1" });
    p
}

fn section_of(p: &Param) -> &'static str {
    PARAMETERS
        .sections()
        .find(|s| s.params.iter().any(|q| q.key == p.key))
        .map(|s| s.name)
        .unwrap()
}

/// The base scene a key is compared in: its section's, unless the key is
/// the one that switches the section on (then the plain scene).
fn scene_for(p: &Param) -> Params {
    let section = section_of(p);
    if PARAMETERS.enabled_by(section) == Some(p.key) {
        Params::new()
    } else {
        base(section)
    }
}

#[test]
fn a_scene_without_a_key_gets_the_declared_default_of_every_key() {
    let mut compared = 0;
    for p in PARAMETERS.params() {
        let Some(default) = p.default.to_param() else {
            continue;
        };
        let without = scene_for(p);
        let mut with = without.clone();
        with.set(p.key, default.clone()).unwrap();
        let a = Config::from_params(&without)
            .unwrap_or_else(|e| panic!("{}: the scene without it: {e}", p.key));
        let b = Config::from_params(&with)
            .unwrap_or_else(|e| panic!("{}: the scene with {default}: {e}", p.key));
        assert_eq!(
            a, b,
            "{}: absent is not the declared default {default}",
            p.key
        );
        let a = RosSettings::from_params(&without).unwrap();
        let b = RosSettings::from_params(&with).unwrap();
        assert_eq!(
            a, b,
            "{}: the node's settings: absent is not the declared default {default}",
            p.key
        );
        compared += 1;
    }
    let with_default = PARAMETERS
        .params()
        .filter(|p| p.default != Value::None)
        .count();
    assert_eq!(compared, with_default);
    assert!(compared > 80, "{compared} keys compared");
}

#[test]
fn the_default_impls_are_what_an_empty_parameter_file_yields() {
    let empty = Params::new();
    assert_eq!(Config::from_params(&empty).unwrap(), Config::default());
    assert_eq!(
        RosSettings::from_params(&empty).unwrap(),
        RosSettings::default()
    );
    // The declared defaults also pass their own declaration's check.
    for p in PARAMETERS.params() {
        if let Some(v) = p.default.to_param() {
            PARAMETERS
                .check(p.key, &v)
                .unwrap_or_else(|e| panic!("the declared default of {} is refused: {e}", p.key));
        }
    }
}

fn type_code(v: &ParamValue) -> u8 {
    match v {
        ParamValue::Bool(_) => ParameterType::BOOL,
        ParamValue::Integer(_) => ParameterType::INTEGER,
        ParamValue::Double(_) => ParameterType::DOUBLE,
        ParamValue::String(_) => ParameterType::STRING,
        ParamValue::BoolArray(_) => ParameterType::BOOL_ARRAY,
        ParamValue::IntegerArray(_) => ParameterType::INTEGER_ARRAY,
        ParamValue::DoubleArray(_) => ParameterType::DOUBLE_ARRAY,
        ParamValue::StringArray(_) => ParameterType::STRING_ARRAY,
    }
}

#[test]
fn the_parameter_service_reports_the_declared_default_of_every_key() {
    let mut reported = 0;
    for p in PARAMETERS.params() {
        let given = scene_for(p);
        let settings = RosSettings::from_params(&given).unwrap();
        let store = ParamStore::new(effective_parameters(&given, &settings));
        let name = vec![p.key.to_string()];
        let Some(default) = p.default.to_param() else {
            assert!(
                given.get(p.key).is_some() || store.get(p.key).is_none(),
                "{} declares no default but the service reports {:?}",
                p.key,
                store.get(p.key)
            );
            continue;
        };
        if PARAMETERS.enabled_by(section_of(p)) == Some(p.key) {
            // A load model that is off is not listed (docs/ros.md, parameters).
            assert!(store.get(p.key).is_none(), "{}: listed while off", p.key);
            continue;
        }
        assert_eq!(
            store.get(p.key),
            Some(&default),
            "{}: get_parameters",
            p.key
        );
        assert_eq!(
            store.get_types(&name),
            vec![type_code(&default)],
            "{}: get_parameter_types",
            p.key
        );
        let d = &store.describe(&name)[0];
        assert_eq!(d.r#type, type_code(&default), "{}: descriptor type", p.key);
        assert!(
            d.description
                .contains(&format!("default: {} (", p.default_text)),
            "{}: descriptor {:?} does not state the declared default {}",
            p.key,
            d.description,
            p.default_text
        );
        reported += 1;
    }
    assert!(reported > 80, "{reported} keys reported");
}
