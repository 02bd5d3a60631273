//! One input contract: every input the simulation holds — the speed command,
//! node wrenches, load-model commands — passes [`check`] (or [`check_batch`])
//! once and becomes a [`Checked`] value, the only thing [`Inputs::apply`]
//! accepts. The rules live here and nowhere else; the ROS node converts each
//! message to [`Command`]s and adds only what is ROS's own (frame ids, 1-based
//! numbering). A batch is checked whole before any of it is applied, so it is
//! all or nothing by construction.
//!
//! Rules: a speed command is finite with |Ω| ≤ `limits.max_speed`; a wrench
//! is finite with |F| ≤ `limits.max_force`, |M| ≤ `limits.max_moment`, on an
//! existing node; a load-model command meets its [`CommandSpec`]'s rule for an
//! existing instance; a batch names no target twice.

use super::error::{BatchError, InputError};
use super::load_models::{CommandSpec, LoadCommands, LoadModels};
use super::wrench::{NodeKind, Wrench};
use crate::config::LimitsConfig;

/// Inputs held over a step, until replaced.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Inputs {
    /// Commanded joint speed Ω, rad/s.
    pub speed_command: f64,
    /// The user's held wrenches (the load models' wrenches come on top).
    pub ale: Vec<Wrench>,
    /// The user's held wrenches on the Lagrangian nodes.
    pub lagrange: Vec<Wrench>,
    /// Commands of the load models (pad clamp forces, tool feed).
    pub commands: LoadCommands,
}

/// The commands of one load model, as the rules need them.
#[derive(Debug, Clone, PartialEq)]
struct ModelCommands {
    name: &'static str,
    specs: Vec<CommandSpec>,
    /// Per command, its first index in the model's values and its instances.
    layout: Vec<(usize, usize)>,
}

/// Everything the rules need of a scene (cheap to clone and share with the
/// threads that receive inputs).
#[derive(Debug, Clone, PartialEq)]
pub struct InputRules {
    /// The plausibility limits (`limits.*`).
    pub limits: LimitsConfig,
    /// ALE nodes of the scene.
    pub ale_nodes: usize,
    /// Lagrangian nodes of the scene.
    pub lagrange_nodes: usize,
    models: Vec<ModelCommands>,
}

impl InputRules {
    /// The rules of a scene: its limits, its node counts and its load models' commands.
    pub fn new(
        limits: &LimitsConfig,
        ale_nodes: usize,
        lagrange_nodes: usize,
        load_models: &LoadModels,
    ) -> InputRules {
        let models = load_models
            .models()
            .iter()
            .enumerate()
            .map(|(i, m)| ModelCommands {
                name: m.name(),
                specs: m.commands().to_vec(),
                layout: (0..m.commands().len())
                    .map(|c| {
                        (
                            load_models.command_index(i, c, 0).unwrap_or(0),
                            load_models.instances(i, c),
                        )
                    })
                    .collect(),
            })
            .collect();
        InputRules {
            limits: limits.clone(),
            ale_nodes,
            lagrange_nodes,
            models,
        }
    }

    /// Rules for explicitly given load-model commands: per model its name and
    /// (spec, instances) per command (tests and tools without a scene).
    pub fn from_parts(
        limits: &LimitsConfig,
        ale_nodes: usize,
        lagrange_nodes: usize,
        models: &[(&'static str, &[(CommandSpec, usize)])],
    ) -> InputRules {
        let models = models
            .iter()
            .map(|(name, commands)| {
                let mut first = 0;
                let layout = commands
                    .iter()
                    .map(|(_, n)| {
                        first += n;
                        (first - n, *n)
                    })
                    .collect();
                ModelCommands {
                    name,
                    specs: commands.iter().map(|(s, _)| *s).collect(),
                    layout,
                }
            })
            .collect();
        InputRules {
            limits: limits.clone(),
            ale_nodes,
            lagrange_nodes,
            models,
        }
    }

    /// Index of the model named `name` (`pads`, `tool`) and its command specs.
    pub fn model(&self, name: &str) -> Option<(usize, &[CommandSpec])> {
        self.models
            .iter()
            .position(|m| m.name == name)
            .map(|i| (i, self.models[i].specs.as_slice()))
    }

    /// Every load-model command: (model, command, spec, instances).
    pub fn load_commands(&self) -> impl Iterator<Item = (usize, usize, &CommandSpec, usize)> {
        self.models.iter().enumerate().flat_map(|(i, m)| {
            m.specs
                .iter()
                .zip(&m.layout)
                .enumerate()
                .map(move |(c, (s, l))| (i, c, s, l.1))
        })
    }

    /// Instances of command `command` of model `model` (0 if either does not exist).
    pub fn instances(&self, model: usize, command: usize) -> usize {
        self.models
            .get(model)
            .and_then(|m| m.layout.get(command))
            .map_or(0, |l| l.1)
    }
}

/// An input as it arrives (0-based node, model, command and instance indices).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Command {
    /// Commanded joint speed Ω, rad/s.
    Speed(f64),
    /// A wrench held on a node until replaced, in the node frame's axes.
    Wrench {
        /// Lagrangian or ALE.
        kind: NodeKind,
        /// The node (from 0).
        node: usize,
        /// Force (N) and moment (N m) in the node frame's axes.
        wrench: Wrench,
    },
    /// Command `command` of load model `model` (see [`LoadModels::models`](super::load_models::LoadModels::models)) for one instance.
    Load {
        /// The load model (from 0).
        model: usize,
        /// Its command (from 0).
        command: usize,
        /// The instance (from 0; 0 for a model of one).
        instance: usize,
        /// The commanded value, in the command's unit.
        value: f64,
    },
}

/// A command that passed the rules; only [`check`] makes one.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Checked(Target, Command);

/// Where a checked command goes (for duplicate detection and applying).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Target {
    Speed,
    Wrench(NodeKind, usize),
    /// Model and index into its command values.
    Load(usize, usize),
}

impl Checked {
    /// The command that passed.
    pub fn command(&self) -> Command {
        self.1
    }
}

/// A batch whose every entry passed the rules, no target named twice.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct CheckedBatch(Vec<Checked>);

impl CheckedBatch {
    /// Entries in the batch.
    pub fn len(&self) -> usize {
        self.0.len()
    }
    /// Whether the batch has no entries.
    pub fn is_empty(&self) -> bool {
        self.0.is_empty()
    }
    /// The entries, in the batch's order.
    pub fn iter(&self) -> impl Iterator<Item = &Checked> {
        self.0.iter()
    }
}

/// Check one command against the scene's rules.
pub fn check(rules: &InputRules, command: Command) -> Result<Checked, InputError> {
    let limits = &rules.limits;
    let target =
        match command {
            Command::Speed(value) => {
                if !value.is_finite() {
                    return Err(InputError::SpeedNotFinite { value });
                }
                if value.abs() > limits.max_speed {
                    return Err(InputError::SpeedBeyondLimit {
                        value,
                        limit: limits.max_speed,
                    });
                }
                Target::Speed
            }
            Command::Wrench { kind, node, wrench } => {
                let count = match kind {
                    NodeKind::Ale => rules.ale_nodes,
                    NodeKind::Lagrange => rules.lagrange_nodes,
                };
                if node >= count {
                    return Err(InputError::NoSuchNode {
                        kind,
                        index: node + 1,
                        count,
                    });
                }
                wrench.validate(
                    || format!("{}_{} wrench", kind.name(), node + 1),
                    limits.max_force,
                    limits.max_moment,
                )?;
                Target::Wrench(kind, node)
            }
            Command::Load {
                model,
                command,
                instance,
                value,
            } => {
                let m = rules.models.get(model).ok_or(InputError::NoSuchLoadModel {
                    index: model,
                    count: rules.models.len(),
                })?;
                let (spec, &(first, count)) = m.specs.iter().zip(&m.layout).nth(command).ok_or(
                    InputError::NoSuchCommand {
                        model: m.name,
                        index: command,
                        count: m.specs.len(),
                    },
                )?;
                if instance >= count {
                    return Err(InputError::NoSuchInstance {
                        instance: spec.instance,
                        index: instance + 1,
                        count,
                    });
                }
                spec.check(instance, value, limits)?;
                Target::Load(model, first + instance)
            }
        };
    Ok(Checked(target, command))
}

/// Check a batch whole: every entry, and no target named twice.
pub fn check_batch(
    rules: &InputRules,
    commands: impl IntoIterator<Item = Command>,
) -> Result<CheckedBatch, BatchError> {
    let mut out: Vec<Checked> = Vec::new();
    for (position, command) in commands.into_iter().enumerate() {
        let checked =
            check(rules, command).map_err(|error| BatchError::Invalid { position, error })?;
        if let Some(first) = out.iter().position(|c| c.0 == checked.0) {
            return Err(BatchError::Duplicate { position, first });
        }
        out.push(checked);
    }
    Ok(CheckedBatch(out))
}

impl Inputs {
    /// Hold a checked command until replaced.
    pub fn apply(&mut self, checked: Checked) {
        match (checked.0, checked.1) {
            (Target::Speed, Command::Speed(omega)) => self.speed_command = omega,
            (Target::Wrench(NodeKind::Ale, j), Command::Wrench { wrench, .. }) => {
                self.ale[j] = wrench
            }
            (Target::Wrench(NodeKind::Lagrange, j), Command::Wrench { wrench, .. }) => {
                self.lagrange[j] = wrench
            }
            (Target::Load(model, index), Command::Load { value, .. }) => {
                self.commands.values[model][index] = value
            }
            _ => unreachable!("a Checked pairs its target with its command"),
        }
    }

    /// Hold every command of a checked batch.
    pub fn apply_batch(&mut self, batch: &CheckedBatch) {
        for &c in &batch.0 {
            self.apply(c);
        }
    }
}
