//! Centrifugal stiffening (`plate.centrifugal_stiffening`, `plate.in_plane_inner`):
//! whether the membrane prestress of the spinning annulus stiffens the plate,
//! and the in-plane condition of its inner edge (docs/rotor_dynamics.md).

use super::raw::Reader;
use super::{Boundary, ConfigError};
use serde::Serialize;

/// In-plane (radial displacement) condition at r_i for the Lamé prestress.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum InPlaneInner {
    /// u(r_i) = 0: the disc sits on a hub.
    Fixed,
    /// σ_r(r_i) = 0: the hole's edge is traction-free.
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

/// The `plate.centrifugal_stiffening` and `plate.in_plane_inner` keys.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct CentrifugalConfig {
    /// The geometric stiffness of the spinning prestress, ∝ Ω², acts on the plate.
    pub stiffening: bool,
    /// The in-plane condition at r_i for the prestress (`plate.in_plane_inner`).
    pub in_plane_inner: InPlaneInner,
}

/// The declared defaults of the two keys (`config/table.rs`).
impl Default for CentrifugalConfig {
    fn default() -> Self {
        use super::defaults::{default_bool, default_str};
        CentrifugalConfig {
            stiffening: const { default_bool("plate.centrifugal_stiffening") },
            in_plane_inner: InPlaneInner::from_name(default_str("plate.in_plane_inner"))
                .expect("the declared default is a choice"),
        }
    }
}

pub(super) fn read_centrifugal(r: &Reader) -> Result<CentrifugalConfig, ConfigError> {
    let stiffening = r.bool("plate.centrifugal_stiffening")?;
    let key = "plate.in_plane_inner";
    let name = r.string(key)?;
    let in_plane_inner =
        InPlaneInner::from_name(name.trim()).ok_or(ConfigError::UnknownChoice {
            key: key.to_string(),
            value: name,
            allowed: InPlaneInner::NAMES,
        })?;
    Ok(CentrifugalConfig {
        stiffening,
        in_plane_inner,
    })
}
