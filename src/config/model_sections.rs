//! The load models' sections as the configuration holds them: what a
//! model's reader sees (`SectionContext`), what it makes (its validated
//! section, any type implementing [`LoadModelSection`], held type-erased in
//! [`LoadModelSections`]) and the rules several sections share (node
//! references, signs, maxima, keys without their enabling key).
//!
//! A model declares its keys with [`super::table::Param`]s and its reader in
//! a [`super::ModelParameters`] in its own file; the validation
//! (`validate.rs`) calls every reader the registry hands over, in the
//! registry's order, after `plate`, `limits`, `nodes` and `simulation`.

use super::raw::Reader;
pub(crate) use super::raw::{positive, read_choice};
use super::{ConfigError, LimitsConfig, NodesConfig, PlateConfig, SimulationConfig};
use serde::Serialize;
use std::any::Any;
use std::fmt::Debug;

/// A model's reader: its validated section, `None` when its enabling key is
/// not given (then no other key of its sections may be).
pub(crate) type ReadModel =
    fn(&Reader, &mut SectionContext) -> Result<Option<Box<dyn SectionData>>, ConfigError>;

/// What a model's reader sees of the sections read before it.
pub(crate) struct SectionContext<'a> {
    pub(crate) plate: &'a PlateConfig,
    pub(crate) limits: &'a LimitsConfig,
    pub(crate) simulation: &'a SimulationConfig,
    /// The node frames; a reader may append space-fixed nodes (the calipers' contact points).
    pub(crate) nodes: &'a mut NodesConfig,
}

/// A load model's validated section (defined in the model's own file).
pub trait LoadModelSection:
    Any + Debug + Clone + PartialEq + Serialize + Send + Sync + Sized
{
    /// The section's name (`pads`, `springs`).
    const SECTION: &'static str;

    /// Whether the model's friction can make the plate squeal: the linear
    /// stability analysis (`dynamics::stability`) maps over its friction
    /// coefficient and clamp forces. Default: no.
    const CAN_SQUEAL: bool = false;

    /// Boxed as the configuration holds it.
    fn boxed(self) -> Box<dyn SectionData> {
        Box::new(self)
    }
}

/// A validated section, type-erased (implemented for every [`LoadModelSection`]).
pub trait SectionData: Any + Debug + Send + Sync {
    /// The section's name ([`LoadModelSection::SECTION`]).
    fn name(&self) -> &'static str;
    /// [`LoadModelSection::CAN_SQUEAL`].
    fn can_squeal(&self) -> bool;
    /// A boxed copy.
    fn clone_box(&self) -> Box<dyn SectionData>;
    /// Whether `other` is a section of the same type with equal values.
    fn eq_box(&self, other: &dyn SectionData) -> bool;
    /// The section's values as JSON (the effective-parameter dump).
    fn to_json(&self) -> serde_json::Value;
    /// For downcasting to the model's own section type.
    fn as_any(&self) -> &dyn Any;
    /// For downcasting to the model's own section type, to change it.
    fn as_any_mut(&mut self) -> &mut dyn Any;
}

impl<T: LoadModelSection> SectionData for T {
    fn name(&self) -> &'static str {
        T::SECTION
    }
    fn can_squeal(&self) -> bool {
        T::CAN_SQUEAL
    }
    fn clone_box(&self) -> Box<dyn SectionData> {
        Box::new(self.clone())
    }
    fn eq_box(&self, other: &dyn SectionData) -> bool {
        other.as_any().downcast_ref::<T>() == Some(self)
    }
    fn to_json(&self) -> serde_json::Value {
        serde_json::to_value(self).unwrap_or(serde_json::Value::Null)
    }
    fn as_any(&self) -> &dyn Any {
        self
    }
    fn as_any_mut(&mut self) -> &mut dyn Any {
        self
    }
}

/// The validated sections of the load models a scene switches on, at most
/// one of each type, in the registry's order.
#[derive(Debug, Default)]
pub struct LoadModelSections {
    sections: Vec<Box<dyn SectionData>>,
}

impl LoadModelSections {
    /// The section of type `T`, if the scene has it.
    pub fn get<T: LoadModelSection>(&self) -> Option<&T> {
        self.sections
            .iter()
            .find_map(|s| s.as_any().downcast_ref::<T>())
    }

    /// The section of type `T`, to change (a test's variant of a scene).
    pub fn get_mut<T: LoadModelSection>(&mut self) -> Option<&mut T> {
        self.sections
            .iter_mut()
            .find_map(|s| s.as_any_mut().downcast_mut::<T>())
    }

    /// Set (or replace) a section.
    pub fn set(&mut self, section: Box<dyn SectionData>) {
        match self
            .sections
            .iter_mut()
            .find(|s| s.name() == section.name())
        {
            Some(slot) => *slot = section,
            None => self.sections.push(section),
        }
    }

    /// Remove the section named `name` (`pads`); the scene then runs without that model.
    pub fn remove(&mut self, name: &str) {
        self.sections.retain(|s| s.name() != name);
    }

    /// Whether the section named `name` is on.
    pub fn has(&self, name: &str) -> bool {
        self.sections.iter().any(|s| s.name() == name)
    }

    /// Whether a section is on whose model's friction can make the plate
    /// squeal ([`LoadModelSection::CAN_SQUEAL`]).
    pub fn can_squeal(&self) -> bool {
        self.sections.iter().any(|s| s.can_squeal())
    }
}

impl Clone for LoadModelSections {
    fn clone(&self) -> Self {
        LoadModelSections {
            sections: self.sections.iter().map(|s| s.clone_box()).collect(),
        }
    }
}

/// Equal when the same sections are on with equal values (in any order).
impl PartialEq for LoadModelSections {
    fn eq(&self, other: &Self) -> bool {
        self.sections.len() == other.sections.len()
            && self.sections.iter().all(|a| {
                other
                    .sections
                    .iter()
                    .any(|b| a.name() == b.name() && a.eq_box(b.as_ref()))
            })
    }
}

/// Serialised as a map of section name → its values.
impl Serialize for LoadModelSections {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        use serde::ser::SerializeMap;
        let mut map = s.serialize_map(Some(self.sections.len()))?;
        for section in &self.sections {
            map.serialize_entry(section.name(), &section.to_json())?;
        }
        map.end()
    }
}

/// A load model whose enabling key is empty must not be given other keys of `section`.
pub(crate) fn no_other_keys(
    r: &Reader,
    section: &str,
    enabling_key: &'static str,
) -> Result<(), ConfigError> {
    let keys = r.parameters().keys(section);
    match keys.iter().find(|k| **k != enabling_key && r.has(k)) {
        Some(key) => Err(ConfigError::KeyWithoutSection {
            key: key.to_string(),
            enabling_key,
        }),
        None => Ok(()),
    }
}

/// A section of point elements read by [`read_ale_node_list`].
pub(crate) struct AleNodeList<const N: usize> {
    /// The ALE nodes, 0-based.
    pub(crate) nodes: Vec<usize>,
    /// The coefficients, in the order of their keys.
    pub(crate) values: [f64; N],
}

/// The section of point elements under ALE nodes (`springs.*`,
/// `dampers.*`): `enabling_key` lists the nodes (from 1, existing and
/// distinct), each key of `coefficients` a non-negative coefficient, read in
/// that order. `None` when the list is empty (then no other key of `section`
/// may be given).
pub(crate) fn read_ale_node_list<const N: usize>(
    r: &Reader,
    ctx: &SectionContext,
    section: &str,
    enabling_key: &'static str,
    coefficients: [&str; N],
) -> Result<Option<AleNodeList<N>>, ConfigError> {
    let numbers = r.i64_array(enabling_key)?;
    if numbers.is_empty() {
        no_other_keys(r, section, enabling_key)?;
        return Ok(None);
    }
    let nodes = node_refs(enabling_key, &numbers, "ale", ctx.nodes.ale.len())?;
    let mut values = [0.0; N];
    for (value, key) in values.iter_mut().zip(coefficients) {
        *value = non_negative(key, r.f64(key)?)?;
    }
    Ok(Some(AleNodeList { nodes, values }))
}

/// Node numbers (from 1) of existing, distinct nodes of one kind → 0-based indices.
pub(crate) fn node_refs(
    key: &str,
    values: &[i64],
    kind: &'static str,
    count: usize,
) -> Result<Vec<usize>, ConfigError> {
    let mut out: Vec<usize> = Vec::with_capacity(values.len());
    for (index, &v) in values.iter().enumerate() {
        if v < 1 {
            return Err(ConfigError::NotPositive {
                key: format!("{key}[{index}]"),
                value: v as f64,
            });
        }
        if v as usize > count {
            return Err(ConfigError::NoSuchNode {
                key: format!("{key}[{index}]"),
                node: v,
                kind,
                count,
            });
        }
        if out.contains(&(v as usize - 1)) {
            return Err(ConfigError::Duplicate {
                key: key.to_string(),
                value: v,
            });
        }
        out.push(v as usize - 1);
    }
    Ok(out)
}

/// `x` ≥ 0, else an error naming `key`.
pub(crate) fn non_negative(key: &str, x: f64) -> Result<f64, ConfigError> {
    if x < 0.0 {
        Err(ConfigError::Negative {
            key: key.to_string(),
            value: x,
        })
    } else {
        Ok(x)
    }
}

/// |x| ≤ `max`, else an error naming `key`.
pub(crate) fn at_most(key: &str, x: f64, max: f64) -> Result<f64, ConfigError> {
    if x.abs() > max {
        Err(ConfigError::AboveMaximum {
            key: key.to_string(),
            value: x,
            max,
        })
    } else {
        Ok(x)
    }
}
