//! The load models' validated sections (paper section 5; docs/scenes.md):
//! brake pads (`pads.*`), the lathe tool (`tool.*`), pitch links (`links.*`)
//! and point springs (`springs.*`). Read and checked in `load_model_sections.rs`.

use serde::Serialize;

/// One pad contact point: an ALE node with a pad on each face of the disc.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct PadContact {
    /// ALE node, 0-based (`pads.ale_nodes` counts from 1).
    pub node: usize,
    /// Pad it belongs to, 0-based (`pads.contact_pad` counts from 1).
    pub pad: usize,
}

/// How a pad's clamp force is applied (`pads.caliper`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Caliper {
    /// The caliper is held where the clamp force puts it on an undeformed disc.
    Fixed,
    /// The clamp force is a force (hydraulic piston, floating caliper): each
    /// face's pad is a rigid backing plate pressed with it.
    Floating,
}

impl Caliper {
    pub fn name(self) -> &'static str {
        match self {
            Caliper::Fixed => "fixed",
            Caliper::Floating => "floating",
        }
    }
}

/// Where the pads' friction acts (`pads.contact_surface`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum ContactSurface {
    /// On the faces z = ±h/2, from the sliding velocity of the face point
    /// (the friction couple and the sliding-direction terms; docs/scenes.md).
    Faces,
    /// At the mid-plane node, along −sign Ω e_θ (the paper's model).
    MidPlane,
}

impl ContactSurface {
    pub fn name(self) -> &'static str {
        match self {
            ContactSurface::Faces => "faces",
            ContactSurface::MidPlane => "mid_plane",
        }
    }
}

/// Brake pads (`pads.*`, paper 5.3 and Fig. 18): at every contact point an
/// axial spring-damper on each face against the pad's backing plate, pressed
/// with the pad's clamp force, and friction μN along the deformed surface.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct PadsConfig {
    pub contacts: Vec<PadContact>,
    /// Initial clamp force of each pad, N: the force each face of the disc is
    /// pressed with, shared equally by the pad's contact points.
    pub clamp_force: Vec<f64>,
    /// Axial contact stiffness k_c per contact point and face, N/m.
    pub contact_stiffness: f64,
    /// Axial contact damping c_c per contact point and face, N·s/m.
    pub contact_damping: f64,
    /// Friction coefficient μ.
    pub friction_coefficient: f64,
    /// A face whose normal force would pull is released (N ≥ 0).
    pub lift_off: bool,
    /// Friction follows the deformed surface (the paper's follower forces).
    pub follower_friction: bool,
    pub caliper: Caliper,
    pub contact_surface: ContactSurface,
    /// μ_s of the speed-dependent friction law μ(v) = μ + (μ_s − μ) e^(−v/v_S)
    /// (`pads.static_friction_coefficient`; `None`: constant μ; faces only).
    pub static_friction_coefficient: Option<f64>,
    /// v_S of that law, m/s (`pads.stribeck_speed`).
    pub stribeck_speed: f64,
    /// Mass of each face's pad, kg (`pads.mass`; 0: massless pads).
    pub mass: f64,
    /// k_b behind a fixed caliper's massive pad, N/m (`pads.backing_stiffness`).
    pub backing_stiffness: Option<f64>,
}

impl PadsConfig {
    /// Number of pads (the largest pad index + 1).
    pub fn pad_count(&self) -> usize {
        self.contacts.iter().map(|c| c.pad + 1).max().unwrap_or(0)
    }
}

/// The lathe tool (`tool.*`, paper 5.1): fed parallel to the axis onto the
/// rim, on a spring-damper, with the feed force of eq. (21) from the chip.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ToolConfig {
    /// ALE node on the rim the feed force acts at, 0-based (`tool.ale_node` counts from 1).
    pub node: usize,
    /// Chip width b = radial depth of cut, m.
    pub depth_of_cut: f64,
    /// Initial feed rate, m/s (towards −z, from the +z face through the disc).
    pub feed_rate: f64,
    /// Axial gap between the tool tip and the +z face at t = 0, m.
    pub start_clearance: f64,
    /// Spring between tool holder and tool tip, N/m.
    pub stiffness: f64,
    /// Damper between tool holder and tool tip, N·s/m.
    pub damping: f64,
    /// k_f1.1 of eq. (21): specific feed force at a 1 mm × 1 mm chip, Pa (351 N/mm² = 3.51e8 Pa).
    pub specific_force: f64,
    /// m_f of eq. (21).
    pub force_exponent: f64,
}

/// Largest plausible tool feed rate, m/s (60 m/min): `tool.feed_rate` and the feed command.
pub const MAX_TOOL_FEED_RATE: f64 = 1.0;

/// Pitch links of the swash plate (`links.*`, paper 5.2): prescribed axial
/// forces at Lagrangian nodes, cyclic in the azimuth ψ = φ + χ of the node:
/// F_z = mean_force + cyclic_force · cos(ψ − cyclic_phase).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct LinksConfig {
    /// Lagrangian nodes, 0-based (`links.lagrange_nodes` counts from 1).
    pub nodes: Vec<usize>,
    /// N.
    pub mean_force: f64,
    /// N.
    pub cyclic_force: f64,
    /// rad.
    pub cyclic_phase: f64,
}

/// Space-fixed point springs (`springs.*`): a spring-damper between the
/// ground and the plate under each listed ALE node, F_z = −k_s w − c_s ẇ.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct SpringsConfig {
    /// ALE nodes, 0-based (`springs.ale_nodes` counts from 1).
    pub nodes: Vec<usize>,
    /// k_s, N/m.
    pub stiffness: f64,
    /// c_s, N·s/m.
    pub damping: f64,
}
