//! Every declared parameter: the configuration's own sections
//! ([`super::table`]) joined with the load models' ([`ModelParameters`],
//! each declared in its model's own file and handed over by the registry).
//!
//! `config` cannot see the load models (data flows config → model →
//! dynamics), so whatever needs every key takes a [`Parameters`] value: the
//! one check ([`Parameters::check`]), the readers, the validation
//! ([`Parameters::config`]), the node's parameter services and the reference
//! in docs/parameters.md. The registry builds the one value the program uses
//! (`dynamics::load_models::PARAMETERS`) as a constant; nothing is set at run
//! time.

use super::model_sections::ReadModel;
use super::table::{Param, Section, AFTER_LOAD_MODELS, BEFORE_LOAD_MODELS};
use super::{Config, ConfigError, ParamValue, Params};

/// What a load model declares of its parameters: its sections (each off
/// unless its first key is given) and the reader that checks their rules and
/// makes the model's validated section ([`super::model_sections`]).
#[derive(Debug, Clone, Copy)]
pub struct ModelParameters {
    pub(crate) sections: &'static [Section],
    pub(crate) read: ReadModel,
}

/// The declarations of every key: the configuration's sections and the load
/// models' (in the registry's order, between `limits` and `initial`).
#[derive(Debug, Clone, Copy)]
pub struct Parameters {
    pub(crate) models: &'static [&'static ModelParameters],
}

impl Parameters {
    /// Every section, in the reference's order.
    pub fn sections(&self) -> impl Iterator<Item = &'static Section> + '_ {
        BEFORE_LOAD_MODELS
            .iter()
            .chain(self.models.iter().flat_map(|m| m.sections.iter()))
            .chain(AFTER_LOAD_MODELS.iter())
    }

    /// Every parameter, section by section.
    pub fn params(&self) -> impl Iterator<Item = &'static Param> + '_ {
        self.sections().flat_map(|s| s.params.iter())
    }

    /// The declaration of `key`.
    pub fn find(&self, key: &str) -> Option<&'static Param> {
        self.params().find(|p| p.key == key)
    }

    /// The section named `name` (`pads`, `ros`; `""`: top level).
    pub fn section(&self, name: &str) -> Option<&'static Section> {
        self.sections().find(|s| s.name == name)
    }

    /// The keys of section `name`.
    pub fn keys(&self, name: &str) -> Vec<&'static str> {
        self.section(name)
            .map_or_else(Vec::new, |s| s.params.iter().map(|p| p.key).collect())
    }

    /// Every accepted parameter name.
    pub fn known_keys(&self) -> Vec<&'static str> {
        self.params().map(|p| p.key).collect()
    }

    /// The load models' sections are off unless their first key is given:
    /// their other keys have no effect, and no default, without it.
    pub fn enabled_by(&self, section_name: &str) -> Option<&'static str> {
        self.models
            .iter()
            .flat_map(|m| m.sections.iter())
            .find(|s| s.name == section_name)
            .and_then(|s| s.params.first())
            .map(|p| p.key)
    }

    /// Check `value` for `key` against its declaration: known key, declared
    /// type, finite, in the declared range (`config/check.rs`).
    pub fn check(&self, key: &str, value: &ParamValue) -> Result<&'static Param, ConfigError> {
        super::check::check(self, key, value)
    }

    /// Check every value of a parameter set.
    pub fn check_params(&self, params: &Params) -> Result<(), ConfigError> {
        super::check::check_params(self, params)
    }

    /// Validate a flat parameter set (dotted names → values) into a [`Config`].
    pub fn config(&self, params: &Params) -> Result<Config, ConfigError> {
        super::validate::config_from_params(self, params)
    }

    /// The reference of docs/parameters.md: per section its text and a table
    /// of key, type, unit, default, rule and meaning.
    pub fn reference_markdown(&self) -> String {
        let mut out = String::new();
        for s in self.sections() {
            out.push_str(&format!("### {}\n\n", s.title));
            if !s.before.is_empty() {
                out.push_str(&format!("{}\n\n", s.before));
            }
            out.push_str(
                "| Key | Type | Unit | Default | Rule | Meaning |\n|---|---|---|---|---|---|\n",
            );
            for p in s.params {
                out.push_str(&format!(
                    "| `{}` | {} | {} | {} | {} | {} |\n",
                    p.key,
                    p.type_text,
                    cell(p.unit),
                    cell(p.default_text),
                    cell(p.rule),
                    cell(p.meaning)
                ));
            }
            if !s.after.is_empty() {
                out.push_str(&format!("\n{}\n", s.after));
            }
            out.push('\n');
        }
        out
    }

    /// The README's key index: per section the keys, linking to the reference.
    pub fn key_index_markdown(&self) -> String {
        let mut out = String::from("| Section | Keys |\n|---|---|\n");
        for s in self.sections() {
            let anchor: String = s
                .title
                .to_lowercase()
                .chars()
                .filter(|c| c.is_alphanumeric() || *c == ' ' || *c == '-' || *c == '_')
                .map(|c| if c == ' ' { '-' } else { c })
                .collect();
            let name = if s.name.is_empty() {
                "top level".to_string()
            } else {
                format!("`{}`", s.name)
            };
            let keys: Vec<String> = s.params.iter().map(|p| format!("`{}`", p.key)).collect();
            out.push_str(&format!(
                "| [{name}](docs/parameters.md#{anchor}) | {} |\n",
                keys.join(", ")
            ));
        }
        out
    }
}

fn cell(text: &str) -> &str {
    if text.is_empty() {
        "—"
    } else {
        text
    }
}
