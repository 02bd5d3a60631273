//! Centrifugal stiffening (`plate.centrifugal_stiffening`) and the in-plane
//! edge conditions (`plate.in_plane_inner`, `plate.in_plane_outer`): whether
//! the membrane prestress of the spinning annulus stiffens the plate, and the
//! in-plane conditions of its edges, which the prestress
//! (docs/rotor_dynamics.md) and the in-plane modes (docs/in_plane.md) share.

use super::raw::{read_choice, Reader};
use super::{Boundary, ConfigError};
use serde::Serialize;

/// In-plane condition at r_i for the Lamé prestress and the in-plane modes.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum InPlaneInner {
    /// u(r_i) = 0: the disc sits on a hub.
    Fixed,
    /// σ_rr(r_i) = σ_rθ(r_i) = 0: the hole's edge is traction-free.
    Free,
    /// Fixed when the bending inner edge is clamped or supported, free when it is free.
    Auto,
}

impl InPlaneInner {
    /// The parameter values, as the reference lists them.
    pub const NAMES: &'static [&'static str] = &["auto", "fixed", "free"];

    /// The parameter value (`auto`, `fixed`, `free`).
    pub fn name(self) -> &'static str {
        match self {
            InPlaneInner::Fixed => "fixed",
            InPlaneInner::Free => "free",
            InPlaneInner::Auto => "auto",
        }
    }

    /// From the parameter value; `None` for any other text.
    pub fn from_name(s: &str) -> Option<Self> {
        match s {
            "fixed" => Some(InPlaneInner::Fixed),
            "free" => Some(InPlaneInner::Free),
            "auto" => Some(InPlaneInner::Auto),
            _ => None,
        }
    }

    /// Whether u(r_i) = 0 for a plate with this bending inner edge.
    pub fn is_fixed(self, bending_inner: Boundary) -> bool {
        match self {
            InPlaneInner::Fixed => true,
            InPlaneInner::Free => false,
            InPlaneInner::Auto => bending_inner != Boundary::Free,
        }
    }
}

/// In-plane condition at r_a for the Lamé prestress and the in-plane modes.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum InPlaneOuter {
    /// u(r_a) = 0: the rim is held.
    Fixed,
    /// σ_rr(r_a) = σ_rθ(r_a) = 0: the rim is traction-free.
    Free,
}

impl InPlaneOuter {
    /// The parameter values, as the reference lists them.
    pub const NAMES: &'static [&'static str] = &["fixed", "free"];

    /// The parameter value (`fixed`, `free`).
    pub fn name(self) -> &'static str {
        match self {
            InPlaneOuter::Fixed => "fixed",
            InPlaneOuter::Free => "free",
        }
    }

    /// From the parameter value; `None` for any other text.
    pub fn from_name(s: &str) -> Option<Self> {
        match s {
            "fixed" => Some(InPlaneOuter::Fixed),
            "free" => Some(InPlaneOuter::Free),
            _ => None,
        }
    }

    /// Whether u(r_a) = 0.
    pub fn is_fixed(self) -> bool {
        self == InPlaneOuter::Fixed
    }
}

/// The `plate.centrifugal_stiffening`, `plate.in_plane_inner` and
/// `plate.in_plane_outer` keys.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct CentrifugalConfig {
    /// The geometric stiffness of the spinning prestress, ∝ Ω², acts on the plate.
    pub stiffening: bool,
    /// The in-plane condition at r_i (`plate.in_plane_inner`).
    pub in_plane_inner: InPlaneInner,
    /// The in-plane condition at r_a (`plate.in_plane_outer`).
    pub in_plane_outer: InPlaneOuter,
}

/// The declared defaults of the three keys (`config/table.rs`).
impl Default for CentrifugalConfig {
    fn default() -> Self {
        use super::defaults::{default_bool, default_str};
        CentrifugalConfig {
            stiffening: const { default_bool("plate.centrifugal_stiffening") },
            in_plane_inner: InPlaneInner::from_name(default_str("plate.in_plane_inner"))
                .expect("the declared default is a choice"),
            in_plane_outer: InPlaneOuter::from_name(default_str("plate.in_plane_outer"))
                .expect("the declared default is a choice"),
        }
    }
}

pub(super) fn read_centrifugal(r: &Reader) -> Result<CentrifugalConfig, ConfigError> {
    Ok(CentrifugalConfig {
        stiffening: r.bool("plate.centrifugal_stiffening")?,
        in_plane_inner: read_choice(
            r,
            "plate.in_plane_inner",
            InPlaneInner::NAMES,
            InPlaneInner::from_name,
        )?,
        in_plane_outer: read_choice(
            r,
            "plate.in_plane_outer",
            InPlaneOuter::NAMES,
            InPlaneOuter::from_name,
        )?,
    })
}
