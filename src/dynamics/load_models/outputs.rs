//! What a load model reports, declared in its own file: named, typed
//! channels ([`OutputChannel`]), the CSV columns that show some of them
//! ([`CsvColumn`]) and, optionally, the ROS topic whose message carries them
//! all ([`StateTopic`]). The node, the CSV writer, the recorder and the
//! messages loop over these declarations; none of them knows a model.
//!
//! At each state the model fills one flat `&mut [f64]`: its channels in
//! declared order, each [`LoadModel::channel_len`](super::LoadModel::channel_len)
//! values long ([`LoadModel::write_outputs`](super::LoadModel::write_outputs)).

use std::any::Any;
use std::ops::Range;

/// What one value of a channel is.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ChannelKind {
    /// A physical quantity (`float64` on the wire).
    Real,
    /// A 1-based number: a pad, a node (`uint32` on the wire).
    Number,
}

/// How a channel travels in its message.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ChannelShape {
    /// One value (`float64 feed_rate`).
    Scalar,
    /// A sequence of the scene's length (`float64[] clamp_force`, one per pad).
    Sequence,
}

/// One named, typed output of a model.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct OutputChannel {
    /// Its field in the model's message (`clamp_force`).
    pub name: &'static str,
    /// SI unit of its values (`N`, `N·m`, `m`; `—` for numbers).
    pub unit: &'static str,
    /// A physical quantity or a number.
    pub kind: ChannelKind,
    /// One value or one per instance.
    pub shape: ChannelShape,
}

impl OutputChannel {
    /// A real scalar channel (`float64 feed_rate`).
    pub const fn scalar(name: &'static str, unit: &'static str) -> OutputChannel {
        OutputChannel {
            name,
            unit,
            kind: ChannelKind::Real,
            shape: ChannelShape::Scalar,
        }
    }
}

/// A CSV column per instance: `{prefix}{i}_{quantity}` for numbered models
/// (`pad2_clamp_force`), `{prefix}_{quantity}` otherwise (`tool_tip_z`),
/// showing value i of `channel`. A column of another instance than the
/// model's own (a pad's contact points) names its prefix in `instance`
/// (`contact7_patch_top_tangential`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct CsvColumn {
    /// The channel's name (one of [`Outputs::channels`]).
    pub channel: &'static str,
    /// The quantity part of the column's name.
    pub quantity: &'static str,
    /// The prefix of a numbered column whose instances are not the model's
    /// (None: [`Outputs::column_prefix`]).
    pub instance: Option<&'static str>,
}

impl CsvColumn {
    /// The column of `channel`, named as it.
    pub const fn named(channel: &'static str) -> CsvColumn {
        CsvColumn {
            channel,
            quantity: channel,
            instance: None,
        }
    }
}

/// The topic that carries every channel of a model after each output step:
/// `header`, `step`, `sim_time`, then the channels in declared order (the
/// `.msg` file `definition` states the same fields).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct StateTopic {
    /// Relative name (`~/pad_states`).
    pub topic: &'static str,
    /// Its message package (`annular_plate`).
    pub package: &'static str,
    /// Its message type (`PadStates`).
    pub message: &'static str,
    /// The `.msg` text, as the bag's schema.
    pub definition: &'static str,
}

/// A model's declared outputs (a `static` in its file).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Outputs {
    /// The channels, in the message's field order.
    pub channels: &'static [OutputChannel],
    /// Prefix of its CSV columns (`pad`, `tool`, `link`).
    pub column_prefix: &'static str,
    /// Columns are numbered per instance (`pad1_…`, `pad2_…`).
    pub numbered: bool,
    /// Columns, repeated per instance in this order.
    pub columns: &'static [CsvColumn],
    /// The topic carrying the channels (None: CSV only).
    pub topic: Option<StateTopic>,
}

/// No outputs: the declaration of a model that publishes nothing (its `Registration::outputs`).
pub const NO_OUTPUTS: Outputs = Outputs {
    channels: &[],
    column_prefix: "",
    numbered: false,
    columns: &[],
    topic: None,
};

impl Outputs {
    /// Index of the channel named `name`.
    pub fn channel(&self, name: &str) -> Option<usize> {
        self.channels.iter().position(|c| c.name == name)
    }

    /// The CSV column name of `column` for instance `instance` (0-based).
    pub fn column_name(&self, column: &CsvColumn, instance: usize) -> String {
        match column.instance {
            Some(prefix) => format!("{prefix}{}_{}", instance + 1, column.quantity),
            None if self.numbered => {
                format!("{}{}_{}", self.column_prefix, instance + 1, column.quantity)
            }
            None => format!("{}_{}", self.column_prefix, column.quantity),
        }
    }

    /// The unit of a CSV column called `name`, if it is one of these columns.
    pub fn column_unit(&self, name: &str) -> Option<&'static str> {
        let column = self.columns.iter().find(|c| {
            let numbered = c.instance.is_some() || self.numbered;
            name.strip_prefix(c.instance.unwrap_or(self.column_prefix))
                .and_then(|rest| {
                    let digits = rest.bytes().take_while(u8::is_ascii_digit).count();
                    if numbered != (digits > 0) {
                        return None;
                    }
                    rest[digits..].strip_prefix('_')
                })
                .is_some_and(|quantity| quantity == c.quantity)
        })?;
        let channel = self.channel(column.channel)?;
        Some(self.channels[channel].unit)
    }
}

/// What [`LoadModel::write_outputs`](super::LoadModel::write_outputs) reads:
/// the model's slot, commands and scratch at the current state, and the
/// joint angle χ (wrapped, rad).
pub struct OutputContext<'a> {
    /// The model's state values.
    pub slot: &'a [f64],
    /// The model's command values.
    pub commands: &'a [f64],
    /// The model's scratch at the last evaluation.
    pub scratch: &'a dyn Any,
    /// Joint angle χ (wrapped), rad.
    pub chi: f64,
}

/// Where each channel of one model lies in its flat values.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct ChannelLayout {
    /// Per channel, its range in the model's flat values.
    pub ranges: Vec<Range<usize>>,
}

impl ChannelLayout {
    /// Consecutive ranges of the given lengths.
    pub fn new(lengths: impl IntoIterator<Item = usize>) -> ChannelLayout {
        let mut end = 0;
        let ranges = lengths
            .into_iter()
            .map(|n| {
                let r = end..end + n;
                end = r.end;
                r
            })
            .collect();
        ChannelLayout { ranges }
    }

    /// All values of one model.
    pub fn len(&self) -> usize {
        self.ranges.last().map_or(0, |r| r.end)
    }

    /// Whether the model has no values.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// The CSV values of instance `i` in `values`: per column, value i of its
    /// channel where the channel has one (pads without mass have no
    /// compressions).
    pub fn csv_values<'a>(
        &'a self,
        outputs: &'a Outputs,
        values: &'a [f64],
        i: usize,
    ) -> impl Iterator<Item = (&'a CsvColumn, f64)> + 'a {
        outputs.columns.iter().filter_map(move |c| {
            let r = &self.ranges[outputs.channel(c.channel)?];
            (i < r.len()).then(|| (c, values[r.start + i]))
        })
    }

    /// Instances of the CSV columns: the longest of their channels.
    pub fn csv_instances(&self, outputs: &Outputs) -> usize {
        outputs
            .columns
            .iter()
            .filter_map(|c| outputs.channel(c.channel))
            .map(|ch| self.ranges[ch].len())
            .max()
            .unwrap_or(0)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const CHANNELS: &[OutputChannel] = &[
        OutputChannel {
            name: "clamp_force",
            unit: "N",
            kind: ChannelKind::Real,
            shape: ChannelShape::Sequence,
        },
        OutputChannel {
            name: "compression",
            unit: "m",
            kind: ChannelKind::Real,
            shape: ChannelShape::Sequence,
        },
    ];
    const PADS: Outputs = Outputs {
        channels: CHANNELS,
        column_prefix: "pad",
        numbered: true,
        columns: &[
            CsvColumn::named("clamp_force"),
            CsvColumn {
                channel: "compression",
                quantity: "top_compression",
                instance: None,
            },
            CsvColumn {
                channel: "compression",
                quantity: "patch",
                instance: Some("contact"),
            },
        ],
        topic: None,
    };

    #[test]
    fn columns_are_named_per_instance_and_know_their_units() {
        assert_eq!(PADS.column_name(&PADS.columns[0], 1), "pad2_clamp_force");
        assert_eq!(PADS.column_unit("pad12_clamp_force"), Some("N"));
        assert_eq!(PADS.column_unit("pad3_top_compression"), Some("m"));
        assert_eq!(PADS.column_unit("pad_clamp_force"), None);
        assert_eq!(PADS.column_unit("padx_clamp_force"), None);
        assert_eq!(PADS.column_unit("tool_tip_z"), None);
        assert_eq!(PADS.column_name(&PADS.columns[2], 6), "contact7_patch");
        assert_eq!(PADS.column_unit("contact7_patch"), Some("m"));
        assert_eq!(PADS.column_unit("contact_patch"), None);
        assert_eq!(PADS.column_unit("pad7_patch"), None);
    }

    #[test]
    fn instances_skip_the_channels_they_do_not_reach() {
        let layout = ChannelLayout::new([2, 0]);
        let values = [5.0, 6.0];
        let row: Vec<f64> = layout
            .csv_values(&PADS, &values, 1)
            .map(|(_, v)| v)
            .collect();
        assert_eq!(row, [6.0]);
        assert_eq!(layout.csv_instances(&PADS), 2);
    }
}
