//! What the brake pads report (one of the pads' files): the channels of
//! ~/pad_states (`msg/PadStates.msg`, field for field) and the pads' CSV
//! columns, filled from the pads' commands, slot and scratch; and
//! [`PadOutputs`], the pads' typed view of a [`Simulation`].
//!
//! With `pads.shear_stiffness` the lining's patches (`pad_shear.rs`) report
//! per contact point their deflections — the slot's patch states plus their
//! steady-sliding origin (`Pads::patch_deflections`) — and each face's speed
//! relative to its patch (stick: below a few v_reg); without the key these
//! channels are empty.

use super::outputs::{
    ChannelKind, ChannelShape, CsvColumn, OutputChannel, OutputContext, Outputs, StateTopic,
};
use super::pad::{ContactForces, PadScratch, Pads};
use crate::dynamics::error::LoadCommandError;
use crate::dynamics::{Command, Simulation};

const fn channel(name: &'static str, unit: &'static str, kind: ChannelKind) -> OutputChannel {
    OutputChannel {
        name,
        unit,
        kind,
        shape: ChannelShape::Sequence,
    }
}

const fn column(channel: &'static str, quantity: &'static str) -> CsvColumn {
    CsvColumn {
        channel,
        quantity,
        instance: None,
    }
}

/// A per-contact column `contact{c}_{channel without "contact_"}`.
const fn contact_column(channel: &'static str, quantity: &'static str) -> CsvColumn {
    CsvColumn {
        channel,
        quantity,
        instance: Some("contact"),
    }
}

/// Channels per pad (index p − 1 is pad p), per contact point (order of
/// `pads.ale_nodes`), per pad with `pads.mass` (empty without), and per
/// contact point with `pads.shear_stiffness` (empty without).
const CHANNELS: &[OutputChannel] = &[
    channel("clamp_force", "N", ChannelKind::Real),
    channel("normal_force", "N", ChannelKind::Real),
    channel("friction_force", "N", ChannelKind::Real),
    channel("friction_torque", "N·m", ChannelKind::Real),
    channel("contact_pad", "—", ChannelKind::Number),
    channel("contact_ale_node", "—", ChannelKind::Number),
    channel("contact_normal_top", "N", ChannelKind::Real),
    channel("contact_normal_bottom", "N", ChannelKind::Real),
    channel("contact_friction", "N", ChannelKind::Real),
    channel("pad_compression_top", "m", ChannelKind::Real),
    channel("pad_compression_bottom", "m", ChannelKind::Real),
    channel("contact_patch_top_radial", "m", ChannelKind::Real),
    channel("contact_patch_top_tangential", "m", ChannelKind::Real),
    channel("contact_patch_bottom_radial", "m", ChannelKind::Real),
    channel("contact_patch_bottom_tangential", "m", ChannelKind::Real),
    channel("contact_slip_top", "m/s", ChannelKind::Real),
    channel("contact_slip_bottom", "m/s", ChannelKind::Real),
];

/// Channels 0–3 are per pad, 4–8 per contact point, 9–10 per massive pad,
/// 11–16 per contact point with patches.
const PER_CONTACT: std::ops::Range<usize> = 4..9;
const MASSIVE: std::ops::Range<usize> = 9..11;

impl Pads {
    /// The pads' declared outputs (their registration's).
    pub const OUTPUTS: Outputs = Outputs {
        channels: CHANNELS,
        column_prefix: "pad",
        numbered: true,
        columns: &[
            column("clamp_force", "clamp_force"),
            column("normal_force", "normal_force"),
            column("friction_torque", "friction_torque"),
            column("pad_compression_top", "top_compression"),
            column("pad_compression_bottom", "bottom_compression"),
            contact_column("contact_patch_top_radial", "patch_top_radial"),
            contact_column("contact_patch_top_tangential", "patch_top_tangential"),
            contact_column("contact_patch_bottom_radial", "patch_bottom_radial"),
            contact_column("contact_patch_bottom_tangential", "patch_bottom_tangential"),
            contact_column("contact_slip_top", "slip_top"),
            contact_column("contact_slip_bottom", "slip_bottom"),
        ],
        topic: Some(StateTopic {
            topic: "~/pad_states",
            package: "annular_plate",
            message: "PadStates",
            definition: include_str!("../../../msg/PadStates.msg"),
        }),
    };

    /// Values of output channel `channel` ([`Pads::OUTPUTS`]).
    pub(super) fn output_len(&self, channel: usize) -> usize {
        match channel {
            c if PER_CONTACT.contains(&c) => self.contacts.len(),
            c if c < PER_CONTACT.start => self.pad_count(),
            c if MASSIVE.contains(&c) => self.pad_count() * self.is_massive() as usize,
            _ => self.contacts.len() * self.shear.is_some() as usize,
        }
    }

    /// Every channel at the current state, in [`Pads::OUTPUTS`] order.
    pub(super) fn write_output_values(&self, at: &OutputContext, out: &mut [f64]) {
        let (p, c) = (self.pad_count(), self.contacts.len());
        let forces = at
            .scratch
            .downcast_ref::<PadScratch>()
            .map_or(&[][..], |s| &s.forces);
        let (per_pad, rest) = out.split_at_mut(4 * p);
        let (per_contact, rest) = rest.split_at_mut(5 * c);
        self.write_per_pad(at.commands, forces, per_pad);
        self.write_per_contact(forces, per_contact);
        let (massive, patches) = rest.split_at_mut(2 * p * self.is_massive() as usize);
        if self.is_massive() {
            for pad in 0..p {
                massive[pad] = at.slot[2 * pad];
                massive[p + pad] = at.slot[2 * pad + 1];
            }
        }
        if self.shear.is_some() {
            let slip = at
                .scratch
                .downcast_ref::<PadScratch>()
                .map_or(&[][..], |s| &s.slip);
            self.write_patches(&at.slot[self.pad_states()..], slip, patches);
        }
    }

    /// Per contact point its four patch deflections (top radial, top
    /// tangential, bottom radial, bottom tangential: the slot's patch states
    /// from their steady-sliding origin, `Pads::patch_deflections`) and its
    /// faces' speeds relative to their patches.
    fn write_patches(&self, x: &[f64], slip: &[[f64; 2]], out: &mut [f64]) {
        let c = self.contacts.len();
        for (k, (contact, x)) in self.contacts.iter().zip(x.chunks_exact(4)).enumerate() {
            for (a, v) in self.patch_deflections(contact, x).iter().enumerate() {
                out[a * c + k] = *v;
            }
        }
        for (k, s) in slip.iter().enumerate().take(c) {
            out[4 * c + k] = s[0];
            out[5 * c + k] = s[1];
        }
    }

    /// Clamp, normal and friction force and friction torque per pad, summed
    /// over its contact points in their order.
    fn write_per_pad(&self, clamp_force: &[f64], forces: &[ContactForces], out: &mut [f64]) {
        let p = self.pad_count();
        out[..p].copy_from_slice(&clamp_force[..p]);
        out[p..].iter_mut().for_each(|v| *v = 0.0);
        for (contact, f) in self.contacts.iter().zip(forces) {
            let j = contact.pad;
            out[p + j] += 0.5 * (f.top + f.bottom);
            out[2 * p + j] += f.tangential;
            out[3 * p + j] += contact.radius * f.tangential;
        }
    }

    /// Pad and node numbers (from 1) and forces per contact point.
    fn write_per_contact(&self, forces: &[ContactForces], out: &mut [f64]) {
        let c = self.contacts.len();
        for (k, contact) in self.contacts.iter().enumerate() {
            out[k] = (contact.pad + 1) as f64;
            out[c + k] = (contact.node + 1) as f64;
        }
        for (k, f) in forces.iter().enumerate().take(c) {
            out[2 * c + k] = f.top;
            out[3 * c + k] = f.bottom;
            out[4 * c + k] = f.tangential;
        }
    }
}

/// Forces of one pad at the current state (both faces, all its contact points).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct PadOutput {
    /// Commanded clamp force, N.
    pub clamp_force: f64,
    /// Mean normal force of the two faces, summed over the contact points, N
    /// (equals the clamp force on an undeformed disc).
    pub normal_force: f64,
    /// Friction force along e_θ, summed over contacts and faces, N.
    pub friction_force: f64,
    /// Friction torque about the axis, N·m (brakes the plate: opposite to Ω).
    pub friction_torque: f64,
}

/// The pads' typed view of a simulation (for programs and tests that know
/// they drive a brake; the node and the writers read the declared channels).
pub trait PadOutputs {
    /// Number of brake pads (`pads.*`; 0 without pads).
    fn pad_count(&self) -> usize;
    /// Forces of pad `pad` (0-based) at the current state (zero without pads).
    fn pad_output(&self, pad: usize) -> PadOutput;
    /// With massive pads (`pads.mass`): the compressions x of pad `pad`'s
    /// contact springs by its top and bottom face's pad, m (x₀ = N₀/(n k_c)
    /// at rest); `None` for massless pads.
    fn pad_compression(&self, pad: usize) -> Option<[f64; 2]>;
    /// Forces at every pad contact point (order of `pads.ale_nodes`).
    fn pad_contact_forces(&self) -> &[ContactForces];
    /// With `pads.shear_stiffness`: the lining's patch deflections, per
    /// contact point (top radial, top tangential, bottom radial, bottom
    /// tangential), m; empty without.
    fn pad_patch_deflections(&self) -> Vec<[f64; 4]>;
    /// Hold the clamp force of pad `pad` (0-based), N: the force each disc
    /// face is pressed with, shared by the pad's contact points. Refused (and
    /// the held commands unchanged) if the pad does not exist or the force is
    /// not finite, negative or above `limits.max_force`.
    fn set_pad_clamp_force(&mut self, pad: usize, newtons: f64) -> Result<(), LoadCommandError>;
}

fn pads(sim: &Simulation) -> Option<(usize, &Pads)> {
    sim.scene().load_models.find::<Pads>()
}

impl PadOutputs for Simulation {
    fn pad_count(&self) -> usize {
        pads(self).map_or(0, |(_, p)| p.pad_count())
    }

    fn pad_output(&self, pad: usize) -> PadOutput {
        let Some((model, p)) = pads(self) else {
            return PadOutput::default();
        };
        let v = self.output_values(model);
        let n = p.pad_count();
        PadOutput {
            clamp_force: v[pad],
            normal_force: v[n + pad],
            friction_force: v[2 * n + pad],
            friction_torque: v[3 * n + pad],
        }
    }

    fn pad_compression(&self, pad: usize) -> Option<[f64; 2]> {
        let (model, p) = pads(self)?;
        let slot = &self.state().load_models.slots[model];
        (p.is_massive() && pad < p.pad_count()).then(|| [slot[2 * pad], slot[2 * pad + 1]])
    }

    fn pad_contact_forces(&self) -> &[ContactForces] {
        pads(self)
            .and_then(|(i, _)| self.model_wrenches().scratch::<PadScratch>(i))
            .map_or(&[], |s| &s.forces)
    }

    fn pad_patch_deflections(&self) -> Vec<[f64; 4]> {
        let Some((model, p)) = pads(self) else {
            return Vec::new();
        };
        let slot = &self.state().load_models.slots[model];
        let x = &slot[p.pad_states()..p.pad_states() + p.patch_states()];
        (p.contacts.iter().zip(x.chunks_exact(4)))
            .map(|(c, x)| p.patch_deflections(c, x))
            .collect()
    }

    fn set_pad_clamp_force(&mut self, pad: usize, newtons: f64) -> Result<(), LoadCommandError> {
        let Some((model, _)) = pads(self) else {
            return Err(LoadCommandError::NoSuchPad {
                index: pad + 1,
                count: 0,
            });
        };
        self.command(Command::Load {
            model,
            command: 0,
            instance: pad,
            value: newtons,
        })
        .map_err(LoadCommandError::from_input)
    }
}
