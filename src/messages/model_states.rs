//! The message of a load model's topic, built from its declaration
//! (`dynamics::load_models::outputs`): `header`, `step`, `sim_time`, then
//! every declared channel as a field in declared order — `float64` or
//! `uint32`, scalar or sequence. It serializes exactly as a struct with those
//! fields would (CDR ignores names), so on the wire it is the model's `.msg`
//! type (`PadStates`, `ToolState`) whatever the model.

use super::types::{Header, Time};
use crate::dynamics::load_models::{
    ChannelKind, ChannelLayout, ChannelShape, OutputChannel, Outputs, StateTopic,
};
use crate::dynamics::Simulation;
use serde::ser::SerializeStruct;
use serde::{Serialize, Serializer};

/// The values of one channel, typed as its message field.
#[derive(Debug, Clone, PartialEq)]
pub enum FieldValues {
    /// `float64`.
    Real(f64),
    /// `float64[]`.
    Reals(Vec<f64>),
    /// `uint32`.
    Number(u32),
    /// `uint32[]`.
    Numbers(Vec<u32>),
}

impl FieldValues {
    /// Zeros for `channel` with `len` values.
    fn zeros(channel: &OutputChannel, len: usize) -> FieldValues {
        match (channel.kind, channel.shape) {
            (ChannelKind::Real, ChannelShape::Scalar) => FieldValues::Real(0.0),
            (ChannelKind::Real, ChannelShape::Sequence) => FieldValues::Reals(vec![0.0; len]),
            (ChannelKind::Number, ChannelShape::Scalar) => FieldValues::Number(0),
            (ChannelKind::Number, ChannelShape::Sequence) => FieldValues::Numbers(vec![0; len]),
        }
    }

    /// Overwrite in place from the channel's values (numbers are whole and ≥ 0).
    fn copy_from(&mut self, values: &[f64]) {
        match self {
            FieldValues::Real(v) => *v = values[0],
            FieldValues::Reals(v) => v.copy_from_slice(values),
            FieldValues::Number(v) => *v = values[0] as u32,
            FieldValues::Numbers(v) => {
                for (n, &x) in v.iter_mut().zip(values) {
                    *n = x as u32;
                }
            }
        }
    }
}

impl Serialize for FieldValues {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        match self {
            FieldValues::Real(v) => v.serialize(s),
            FieldValues::Reals(v) => v.serialize(s),
            FieldValues::Number(v) => v.serialize(s),
            FieldValues::Numbers(v) => v.serialize(s),
        }
    }
}

/// One named field of a [`ModelStates`] message.
#[derive(Debug, Clone, PartialEq)]
pub struct Field {
    pub name: &'static str,
    pub values: FieldValues,
}

/// A load model's state message (see the module docs).
#[derive(Debug, Clone, PartialEq)]
pub struct ModelStates {
    pub header: Header,
    /// Output steps since start or the last reset.
    pub step: u64,
    /// Simulated time, s.
    pub sim_time: f64,
    pub fields: Vec<Field>,
}

impl Serialize for ModelStates {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let mut m = s.serialize_struct("ModelStates", 3 + self.fields.len())?;
        m.serialize_field("header", &self.header)?;
        m.serialize_field("step", &self.step)?;
        m.serialize_field("sim_time", &self.sim_time)?;
        for f in &self.fields {
            m.serialize_field(f.name, &f.values)?;
        }
        m.end()
    }
}

impl ModelStates {
    /// The message of a model with `outputs` laid out as `layout`, zero, in `frame_id`.
    pub fn new(outputs: &Outputs, layout: &ChannelLayout, frame_id: &str) -> ModelStates {
        ModelStates {
            header: Header {
                stamp: Time::default(),
                frame_id: frame_id.to_string(),
            },
            step: 0,
            sim_time: 0.0,
            fields: outputs
                .channels
                .iter()
                .zip(&layout.ranges)
                .map(|(c, r)| Field {
                    name: c.name,
                    values: FieldValues::zeros(c, r.len()),
                })
                .collect(),
        }
    }

    /// Overwrite every field from `values` (the model's flat outputs).
    pub fn update(&mut self, layout: &ChannelLayout, values: &[f64], stamp: Time) {
        self.header.stamp = stamp;
        for (f, r) in self.fields.iter_mut().zip(&layout.ranges) {
            f.values.copy_from(&values[r.clone()]);
        }
    }
}

/// The models of `sim`'s scene that publish a topic: index and topic, in registry order.
pub fn model_topics(sim: &Simulation) -> Vec<(usize, StateTopic)> {
    let lm = &sim.scene().load_models;
    (0..lm.models().len())
        .filter_map(|i| lm.outputs(i).0.topic.map(|t| (i, t)))
        .collect()
}

/// `pkg/msg/Type` of a model topic.
pub fn type_name(topic: &StateTopic) -> String {
    format!("{}/msg/{}", topic.package, topic.message)
}
