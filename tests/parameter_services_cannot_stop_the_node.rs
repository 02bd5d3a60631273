//! Every value reaches the node through one check (`config::check`, the
//! declared type and range of `config/table.rs`): a parameter-service
//! request of any name, type and value is answered (refused naming the key,
//! or accepted), and an accepted one is applied to the loop's pacing and
//! wrench timeout the way the simulation thread applies it
//! (`ros::sim_loop::apply_runtime`), after which the plate keeps stepping.
//! The start-up path (`-p`, the params file) refuses what the service
//! refuses, and accepts what it accepts.

use annular_plate::config::{Config, ParamValue, Params};
use annular_plate::dynamics::load_models::PARAMETERS;
use annular_plate::dynamics::Simulation;
use annular_plate::messages::clock::Pacer;
use annular_plate::messages::settings::RosSettings;
use annular_plate::ros::inputs::StaleWrenches;
use annular_plate::ros::params_service::{effective_parameters, ParamStore};
use annular_plate::ros::sim_loop::apply_runtime;
use ros2_client::parameters::raw;
use ros2_client::ParameterValue as RosValue;
use std::time::{Duration, Instant};

fn hostile_values() -> Vec<RosValue> {
    let doubles = [
        5e-324,
        1e-30,
        4.9e-23,
        1e-7,
        -0.0,
        0.0,
        1.0,
        1e6,
        1.1e6,
        1e300,
        f64::MAX,
        -1.0,
        f64::INFINITY,
        f64::NEG_INFINITY,
        f64::NAN,
    ];
    let mut v: Vec<RosValue> = doubles.iter().map(|&x| RosValue::Double(x)).collect();
    v.extend([0, 1, -1, i64::MAX, i64::MIN, 1 << 53].map(RosValue::Integer));
    v.extend([
        RosValue::Boolean(true),
        RosValue::String("fast".into()),
        RosValue::String(String::new()),
        RosValue::DoubleArray(vec![1.0, f64::NAN]),
        RosValue::IntegerArray(vec![i64::MAX]),
        RosValue::StringArray(vec!["auto".into()]),
        RosValue::BooleanArray(vec![true]),
        RosValue::ByteArray(vec![0; 3]),
        RosValue::NotSet,
    ]);
    v
}

fn store() -> ParamStore {
    ParamStore::new(effective_parameters(
        &Params::new(),
        &RosSettings::default(),
    ))
}

fn param(name: &str, value: RosValue) -> raw::Parameter {
    raw::Parameter {
        name: name.into(),
        value: value.into(),
    }
}

fn as_param_value(v: &RosValue) -> Option<ParamValue> {
    Some(match v.clone() {
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

#[test]
fn every_value_of_every_type_sent_to_every_key_is_refused_naming_the_key_or_keeps_the_plate_stepping(
) {
    let mut sim = Simulation::new(
        Config::from_yaml_str(
            include_str!("../config/design_example.yaml"),
            "annular_plate",
        )
        .unwrap(),
    )
    .unwrap();
    let dt = sim.dt();
    let mut realtime_factor = 1.0;
    let mut pacer = Pacer::new(dt, realtime_factor, Instant::now());
    let mut stale = StaleWrenches::new(0.0, sim.n_ale_nodes(), sim.n_lagrange_nodes());
    let mut keys: Vec<&str> = PARAMETERS.params().map(|p| p.key).collect();
    keys.extend([
        "no.such_key",
        "",
        "simulation",
        "simulation.realtime_factor.x",
    ]);
    let started = Instant::now();
    let mut accepted = 0;
    for key in keys {
        for value in hostile_values() {
            let mut st = store();
            let (results, changes) = st.set(vec![param(key, value.clone())]);
            let (atomic, atomic_changes) = store().set_atomically(vec![param(key, value.clone())]);
            assert_eq!(
                results[0].successful, atomic.result.successful,
                "{key} = {value:?}: set and set_atomically disagree"
            );
            assert_eq!(changes, atomic_changes);
            if !results[0].successful {
                assert!(
                    results[0].reason.contains(&format!("`{key}`"))
                        || results[0].reason.contains(key),
                    "{key} = {value:?}: the refusal does not name the key: {}",
                    results[0].reason
                );
                assert!(changes.is_empty());
                continue;
            }
            accepted += 1;
            // What a service accepts, the start-up path accepts too (`-p` of the same value).
            let mut given = Params::new();
            given.set(key, as_param_value(&value).unwrap()).unwrap();
            Config::from_params(&given).unwrap_or_else(|e| {
                panic!("{key} = {value:?}: accepted by the service, refused at start-up: {e}")
            });
            RosSettings::from_params(&given).unwrap_or_else(|e| {
                panic!("{key} = {value:?}: accepted by the service, refused at start-up: {e}")
            });
            for change in changes {
                apply_runtime(
                    change,
                    &mut realtime_factor,
                    &mut pacer,
                    &mut stale,
                    dt,
                    Instant::now(),
                );
            }
            // The loop's next deadline is a time, and the plate steps on.
            let _ = pacer.deadline();
            pacer.stepped(Instant::now());
            sim.step()
                .unwrap_or_else(|e| panic!("{key} = {value:?}: the plate stopped stepping: {e}"));
            stale.expire(sim.time(), |_, _| {});
        }
    }
    assert!(
        accepted >= 4,
        "the run-time keys accept their ordinary values ({accepted} accepted)"
    );
    assert!(started.elapsed() < Duration::from_secs(60), "bounded time");
}

#[test]
fn the_realtime_factor_takes_only_a_double_in_its_declared_range_by_service() {
    let key = "simulation.realtime_factor";
    for (value, ok) in [
        (RosValue::Double(1e-30), false),
        (RosValue::Double(5e-324), false),
        (RosValue::Double(4.9e-23), false),
        (RosValue::Double(f64::NAN), false),
        (RosValue::Double(f64::INFINITY), false),
        (RosValue::Double(-1.0), false),
        (RosValue::Integer(2), false),
        (RosValue::Integer(0), false),
        (RosValue::Double(0.0), true),
        (RosValue::Double(1e-6), true),
        (RosValue::Double(2.0), true),
        (RosValue::Double(1e6), true),
    ] {
        let (r, _) = store().set(vec![param(key, value.clone())]);
        assert_eq!(r[0].successful, ok, "{value:?}: {}", r[0].reason);
        if !ok {
            assert!(r[0].reason.contains(key), "{}", r[0].reason);
        }
    }
    let (r, _) = store().set(vec![param(key, RosValue::Integer(2))]);
    assert!(
        r[0].reason.contains("must be a double, found integer 2"),
        "strict like rclcpp: {}",
        r[0].reason
    );
}

#[test]
fn the_start_up_path_refuses_a_realtime_factor_that_would_stop_the_loop() {
    for text in ["1e-30", "5e-324", "4.9e-23", "-1", ".nan", ".inf", "1e7"] {
        let mut p = Params::new();
        p.set_override("simulation.realtime_factor", text).unwrap();
        let e = Config::from_params(&p).unwrap_err().to_string();
        assert!(e.contains("simulation.realtime_factor"), "{text}: {e}");
    }
    // A file's integer spells a double (`realtime_factor: 2`), and 0 is as fast as possible.
    for text in ["2", "0", "0.5", "1e6"] {
        let mut p = Params::new();
        p.set_override("simulation.realtime_factor", text).unwrap();
        assert!(Config::from_params(&p).is_ok(), "{text}");
    }
}

#[test]
fn every_accepted_pacing_gives_a_deadline_without_overflow() {
    let now = Instant::now();
    for dt in [1e-6, 1e-3, 1.0, 1e3, 1e300, f64::INFINITY, f64::NAN] {
        for f in [
            0.0,
            5e-324,
            1e-30,
            1e-6,
            1.0,
            1e6,
            f64::MAX,
            f64::INFINITY,
            f64::NAN,
        ] {
            let mut p = Pacer::new(dt, f, now);
            p.stepped(now);
            p.stepped(now + Duration::from_secs(1));
            assert!(
                p.period()
                    .is_none_or(|d| d <= annular_plate::messages::clock::MAX_PERIOD),
                "dt {dt}, factor {f}"
            );
        }
    }
}

#[test]
fn the_durations_the_node_builds_from_its_settings_fit_for_every_accepted_value() {
    for key in [
        "ros.diagnostics_period",
        "ros.reject_log_period",
        "ros.wrench_timeout",
        "ros.max_clock_jump",
    ] {
        for text in ["1e300", "1.7e308", "5e-324", "1e6", "0"] {
            let mut p = Params::new();
            p.set_override(key, text).unwrap();
            if let Ok(s) = RosSettings::from_params(&p) {
                // What node.rs builds from them (Duration::from_secs_f64 panics beyond u64 seconds).
                assert!(
                    Duration::try_from_secs_f64(s.diagnostics_period).is_ok()
                        && Duration::try_from_secs_f64(s.reject_log_period).is_ok(),
                    "{key} = {text}"
                );
            }
        }
    }
}
