//! Every declared parameter, the load models' with the configuration's: the
//! registry hands each model's declaration ([`Registration::parameters`](super::Registration::parameters)) to
//! `config` as the constant [`PARAMETERS`], and the readers every program
//! uses (`Config::from_params`, `Params::from_file`, …) are defined here, on
//! top of `config`'s, because only here are both visible (data flows config
//! → model → dynamics; `config` cannot name a model).

use super::REGISTRY;
use crate::config::{Config, ConfigError, ModelParameters, Parameters, Params};
use std::path::Path;

/// The models' declarations in the registry's order.
const MODELS: [&ModelParameters; REGISTRY.len()] = {
    let mut out = [REGISTRY[0].parameters; REGISTRY.len()];
    let mut i = 0;
    while i < REGISTRY.len() {
        out[i] = REGISTRY[i].parameters;
        i += 1;
    }
    out
};

/// Every parameter: the configuration's sections and every registered
/// model's (the table, the one check, the parameter services and
/// docs/parameters.md read it).
pub const PARAMETERS: Parameters = Parameters { models: &MODELS };

impl Config {
    /// Read and validate a ROS 2 parameter file for the node `node_name`
    /// (entries under `/**` apply to every node; a node's own entry wins).
    pub fn from_params_file(path: &Path, node_name: &str) -> Result<Config, ConfigError> {
        Config::from_params(&Params::from_file(path, node_name)?)
    }

    /// Read and validate the text of a ROS 2 parameter file for the node `node_name`.
    pub fn from_yaml_str(text: &str, node_name: &str) -> Result<Config, ConfigError> {
        Config::from_params(&Params::from_yaml_str(text, node_name)?)
    }

    /// Validate a flat parameter set (dotted names → values).
    pub fn from_params(params: &Params) -> Result<Config, ConfigError> {
        PARAMETERS.config(params)
    }

    /// Every parameter name the configuration accepts (`plate.inner_radius`, …).
    pub fn known_keys() -> Vec<&'static str> {
        PARAMETERS.known_keys()
    }
}

impl Params {
    /// Read a ROS 2 parameter file for the node `node_name` ([`Params::read_file`]
    /// with every declaration).
    pub fn from_file(path: &Path, node_name: &str) -> Result<Params, ConfigError> {
        Params::read_file(path, node_name, &PARAMETERS)
    }

    /// Parse the text of a ROS 2 parameter file for the node `node_name`
    /// ([`Params::parse_yaml`] with every declaration).
    pub fn from_yaml_str(text: &str, node_name: &str) -> Result<Params, ConfigError> {
        Params::parse_yaml(text, node_name, &PARAMETERS)
    }

    /// Apply a command-line override `-p name:=value` ([`Params::override_with`]
    /// with every declaration).
    pub fn set_override(&mut self, name: &str, value_text: &str) -> Result<(), ConfigError> {
        self.override_with(name, value_text, &PARAMETERS)
    }
}
