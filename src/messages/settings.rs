//! The node's own parameters (`ros.*`, plus the standard `use_sim_time`),
//! read and checked from the flat parameter set.
//!
//! The config layer declares the `ros.*` keys (`config::table`, so
//! `modes` and `simulate` accept a scene file that carries them and refuse
//! typos); their values are the node's business and are checked here, from
//! the same parameter set the config reads. Every rule below is listed in
//! docs/ros.md.

use crate::config::{declared_value, typed, Declared, ParamValue, Params};
use ros2_client::ServiceMapping;
use std::fmt;

use super::marker::{MarkerScale, MarkerSettings, MAX_CELLS};
use crate::dynamics::load_models::PARAMETERS;

/// Validated `ros.*` settings.
#[derive(Debug, Clone, PartialEq)]
pub struct RosSettings {
    /// `ros.frame_prefix`: prefix of every frame and joint name.
    pub frame_prefix: String,
    /// `ros.world_frame`: parent of plate_base in /tf_static (not prefixed).
    pub world_frame: String,
    /// `ros.publish_clock`: the node's own simulated time, published on `/clock`.
    pub sim_time: bool,
    /// `use_sim_time`: stamps follow an external `/clock` and the loop steps
    /// with it (never together with `sim_time`).
    pub use_sim_time: bool,
    /// s; 0 = never.
    pub wrench_timeout: f64,
    /// `ros.max_clock_jump`, s: a larger forward step of the followed
    /// `/clock` re-anchors the stamps instead of being stepped through.
    pub max_clock_jump: f64,
    /// `ros.start_paused`: the node starts paused.
    pub start_paused: bool,
    /// `ros.diagnostics_period`: wall time between /diagnostics messages, s.
    pub diagnostics_period: f64,
    /// `ros.reject_log_period`: wall time between log lines about rejected inputs of one kind, s.
    pub reject_log_period: f64,
    /// `ros.service_mapping`: the request/reply mapping of every service.
    pub service_mapping: ServiceMapping,
    /// `ros.input_reception`: `step_aligned` reads the input datagrams at step
    /// boundaries while they are many (`ros/step_aligned_receive.rs`).
    pub step_aligned_reception: bool,
    /// `ros.marker_*`: `~/plate_marker`.
    pub marker: MarkerSettings,
}

/// The declared defaults of the `ros.*` keys and `use_sim_time`
/// (`config/table.rs`): what an empty parameter set yields.
impl Default for RosSettings {
    fn default() -> Self {
        RosSettings::from_params(&Params::new()).expect("the declared ros.* defaults are valid")
    }
}

/// A rejected `ros.*` value; names the key and the rule.
#[derive(Debug, Clone, PartialEq)]
pub struct SettingsError {
    /// The key refused.
    pub key: String,
    /// The whole refusal, naming the key (for a declared type or range: the
    /// text of `config::check`, as the parameter file and services give it).
    pub message: String,
}

impl fmt::Display for SettingsError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.message)
    }
}

impl std::error::Error for SettingsError {}

fn err(key: &str, message: impl Into<String>) -> SettingsError {
    SettingsError {
        key: key.to_string(),
        message: format!("{key}: {}", message.into()),
    }
}

/// `key`'s value (or its declared default) through the one check of
/// `config::check`: declared type and range.
fn value<T: Declared>(params: &Params, key: &str) -> Result<T, SettingsError> {
    let from_config = |e: crate::config::ConfigError| SettingsError {
        key: key.to_string(),
        message: e.to_string(),
    };
    match declared_value(&PARAMETERS, params, key).map_err(from_config)? {
        Some(v) => typed(&PARAMETERS, key, &v).map_err(from_config),
        None => Err(err(key, "has no value and no declared default")),
    }
}

fn frame_chars_ok(s: &str) -> bool {
    s.chars()
        .all(|c| c.is_ascii_alphanumeric() || matches!(c, '_' | '/' | '-' | '.'))
        && !s.starts_with('/')
}

impl RosSettings {
    /// Read the `ros.*` keys (and `use_sim_time`) of `params`, each through
    /// `config::check` (declared type and range) with its declared default;
    /// unknown `ros.*` keys are refused with the list of known ones.
    pub fn from_params(params: &Params) -> Result<RosSettings, SettingsError> {
        for (name, _) in params.iter() {
            if name.starts_with("ros.") && PARAMETERS.find(name).is_none() {
                let known = PARAMETERS.keys("ros");
                return Err(err(
                    name,
                    format!(
                        "unknown parameter (the ros.* keys are {})",
                        known.join(", ")
                    ),
                ));
            }
        }
        let frame_prefix: String = value(params, "ros.frame_prefix")?;
        if !frame_chars_ok(&frame_prefix) {
            return Err(err("ros.frame_prefix", format!("`{frame_prefix}` may hold only letters, digits, `_`, `/`, `-`, `.` and must not start with `/` (tf2 frame ids are relative)")));
        }
        let world_frame: String = value(params, "ros.world_frame")?;
        if world_frame.is_empty() || !frame_chars_ok(&world_frame) {
            return Err(err("ros.world_frame", format!("`{world_frame}` must be a non-empty frame id of letters, digits, `_`, `/`, `-`, `.`, not starting with `/`")));
        }
        let publish_clock: bool = value(params, "ros.publish_clock")?;
        let use_sim_time: bool = value(params, "use_sim_time")?;
        if publish_clock && use_sim_time {
            return Err(err(
                "ros.publish_clock",
                "true together with use_sim_time: true is refused: a node that follows an external /clock must not publish a second one (set one of them false)",
            ));
        }
        let mapping: String = value(params, "ros.service_mapping")?;
        let service_mapping = match mapping.as_str() {
            "enhanced" => ServiceMapping::Enhanced,
            "cyclone" => ServiceMapping::Cyclone,
            "basic" => ServiceMapping::Basic,
            other => {
                return Err(err(
                    "ros.service_mapping",
                    format!("`{other}` is not one of enhanced, cyclone, basic"),
                ))
            }
        };
        let reception: String = value(params, "ros.input_reception")?;
        let step_aligned_reception = match reception.as_str() {
            "on_arrival" => false,
            "step_aligned" => true,
            other => {
                return Err(err(
                    "ros.input_reception",
                    format!("`{other}` is not one of on_arrival, step_aligned"),
                ))
            }
        };
        Ok(RosSettings {
            frame_prefix,
            world_frame,
            sim_time: publish_clock,
            use_sim_time,
            wrench_timeout: value(params, "ros.wrench_timeout")?,
            max_clock_jump: value(params, "ros.max_clock_jump")?,
            start_paused: value(params, "ros.start_paused")?,
            diagnostics_period: value(params, "ros.diagnostics_period")?,
            reject_log_period: value(params, "ros.reject_log_period")?,
            service_mapping,
            step_aligned_reception,
            marker: read_marker(params)?,
        })
    }

    /// Refuse a marker faster than the loop (`ros.marker_rate_hz` ≤ `simulation.rate_hz`).
    pub fn check_against_rate(&self, rate_hz: f64) -> Result<(), SettingsError> {
        if self.marker.rate_hz > rate_hz {
            return Err(err("ros.marker_rate_hz", format!("{} Hz is above simulation.rate_hz = {rate_hz} Hz (one marker per step at most)", self.marker.rate_hz)));
        }
        Ok(())
    }

    /// The effective value of every `ros.*` key, for the parameter services.
    pub fn effective_params(&self) -> Vec<(&'static str, ParamValue)> {
        vec![
            (
                "ros.frame_prefix",
                ParamValue::String(self.frame_prefix.clone()),
            ),
            (
                "ros.world_frame",
                ParamValue::String(self.world_frame.clone()),
            ),
            (
                "ros.wrench_timeout",
                ParamValue::Double(self.wrench_timeout),
            ),
            (
                "ros.max_clock_jump",
                ParamValue::Double(self.max_clock_jump),
            ),
            ("ros.start_paused", ParamValue::Bool(self.start_paused)),
            (
                "ros.diagnostics_period",
                ParamValue::Double(self.diagnostics_period),
            ),
            (
                "ros.reject_log_period",
                ParamValue::Double(self.reject_log_period),
            ),
            (
                "ros.service_mapping",
                ParamValue::String(
                    match self.service_mapping {
                        ServiceMapping::Enhanced => "enhanced",
                        ServiceMapping::Cyclone => "cyclone",
                        ServiceMapping::Basic => "basic",
                    }
                    .to_string(),
                ),
            ),
            (
                "ros.input_reception",
                ParamValue::String(
                    if self.step_aligned_reception {
                        "step_aligned"
                    } else {
                        "on_arrival"
                    }
                    .to_string(),
                ),
            ),
            (
                "ros.marker_rate_hz",
                ParamValue::Double(self.marker.rate_hz),
            ),
            (
                "ros.marker_rings",
                ParamValue::Integer(self.marker.rings as i64),
            ),
            (
                "ros.marker_sectors",
                ParamValue::Integer(self.marker.sectors as i64),
            ),
            (
                "ros.marker_scale",
                match self.marker.scale {
                    MarkerScale::Auto => ParamValue::String("auto".into()),
                    MarkerScale::Fixed(v) => ParamValue::Double(v),
                },
            ),
        ]
    }
}

/// The `ros.marker_*` keys (declared types and ranges: `config::check`).
fn read_marker(params: &Params) -> Result<MarkerSettings, SettingsError> {
    let rings: i64 = value(params, "ros.marker_rings")?;
    let sectors: i64 = value(params, "ros.marker_sectors")?;
    let cells = rings.saturating_mul(sectors);
    if cells > i64::from(MAX_CELLS) {
        return Err(err("ros.marker_rings", format!("rings × sectors = {rings} × {sectors} exceeds {MAX_CELLS} cells (lower ros.marker_rings or ros.marker_sectors)")));
    }
    let key = "ros.marker_scale";
    let scale = match declared_value(&PARAMETERS, params, key).map_err(|e| SettingsError {
        key: key.to_string(),
        message: e.to_string(),
    })? {
        Some(ParamValue::Double(v)) => MarkerScale::Fixed(v),
        Some(ParamValue::String(s)) if s == "auto" => MarkerScale::Auto,
        Some(other) => {
            return Err(err(
                key,
                format!("{other} must be `auto` or a finite number > 0"),
            ))
        }
        None => MarkerScale::Auto,
    };
    Ok(MarkerSettings {
        rate_hz: value(params, "ros.marker_rate_hz")?,
        rings: rings as u32,
        sectors: sectors as u32,
        scale,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn params(pairs: &[(&str, &str)]) -> Params {
        let mut p = Params::new();
        for (k, v) in pairs {
            p.set_override(k, v).unwrap();
        }
        p
    }

    #[test]
    fn defaults() {
        assert_eq!(
            RosSettings::from_params(&Params::new()).unwrap(),
            RosSettings::default()
        );
    }

    #[test]
    fn values_are_read_and_checked() {
        let s = RosSettings::from_params(&params(&[
            ("ros.frame_prefix", "left_"),
            ("ros.publish_clock", "true"),
            ("ros.wrench_timeout", "0.5"),
            ("ros.start_paused", "true"),
            ("ros.diagnostics_period", "2"),
            ("ros.service_mapping", "cyclone"),
            ("ros.input_reception", "step_aligned"),
        ]))
        .unwrap();
        assert_eq!(s.frame_prefix, "left_");
        assert!(s.sim_time && s.start_paused && !s.use_sim_time);
        assert_eq!(s.wrench_timeout, 0.5);
        assert_eq!(s.diagnostics_period, 2.0);
        assert_eq!(s.service_mapping, ServiceMapping::Cyclone);
        assert!(s.step_aligned_reception);
        assert!(
            !RosSettings::default().step_aligned_reception,
            "inputs are read on arrival unless asked"
        );
        let follow = RosSettings::from_params(&params(&[("use_sim_time", "true")])).unwrap();
        assert!(
            follow.use_sim_time && !follow.sim_time,
            "use_sim_time follows /clock, it does not publish one"
        );
    }

    #[test]
    fn use_sim_time_and_publish_clock_together_are_refused() {
        let e = RosSettings::from_params(&params(&[
            ("use_sim_time", "true"),
            ("ros.publish_clock", "true"),
        ]))
        .unwrap_err();
        assert_eq!(e.key, "ros.publish_clock");
        assert!(e.message.contains("use_sim_time"), "{e}");
        let s = RosSettings::from_params(&params(&[
            ("use_sim_time", "true"),
            ("ros.publish_clock", "false"),
        ]))
        .unwrap();
        assert!(s.use_sim_time && !s.sim_time);
    }

    #[test]
    fn bad_values_name_the_key() {
        for (k, v) in [
            ("ros.frame_prefix", "/abs"),
            ("ros.frame_prefix", "a b"),
            ("ros.world_frame", "\"\""),
            ("ros.publish_clock", "1"),
            ("ros.wrench_timeout", "-1"),
            ("ros.diagnostics_period", "0"),
            ("ros.service_mapping", "zenoh"),
            ("ros.input_reception", "sometimes"),
            ("ros.frame_prefx", "a"),
            ("ros.marker_rate_hz", "-1"),
            ("ros.marker_rings", "0"),
            ("ros.marker_sectors", "100000"),
            ("ros.marker_scale", "big"),
            ("ros.marker_scale", "0"),
        ] {
            let e = RosSettings::from_params(&params(&[(k, v)])).unwrap_err();
            assert_eq!(e.key, k, "{e}");
        }
    }

    #[test]
    fn reads_its_keys_from_the_whole_parameter_set() {
        let p = params(&[
            ("ros.frame_prefix", "a"),
            ("plate.thickness", "0.01"),
            ("use_sim_time", "true"),
        ]);
        let s = RosSettings::from_params(&p).unwrap();
        assert_eq!(s.frame_prefix, "a");
        assert!(s.use_sim_time);
        assert!(
            crate::config::Config::from_params(&p).is_ok(),
            "the config accepts the ros.* names too"
        );
    }
}
