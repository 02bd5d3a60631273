//! When a Kirchhoff plate is too thick: the model error of Kirchhoff theory
//! in the lowest retained modes, measured against the Mindlin modes of the
//! same plate (docs/mindlin.md "When Kirchhoff is too thick").
//!
//! Criterion: for the [`CHECKED_PAIRS`] lowest distinct ⟨k, l⟩ of the mode
//! table, e = ω_Kirchhoff / ω_Mindlin − 1 with the same edges (`supported` is
//! the hard support, Kirchhoff's) and `plate.shear_correction`; a warning
//! when the largest e exceeds [`THICKNESS_WARNING_LEVEL`]. Mindlin is within
//! 0.1–0.9 % of 3-D elasticity for the bench disc where Kirchhoff is 0.9–12 %
//! above it, so e is Kirchhoff's model error to that accuracy.

use super::{MindlinDiscretisation, DEFAULT_SPLINES};
use crate::config::PlateTheory;
use crate::model::{ModelError, PlateModel};
use std::fmt;

/// The relative model error above which `modes` and the node warn.
pub const THICKNESS_WARNING_LEVEL: f64 = 0.01;
/// How many of the lowest distinct ⟨k, l⟩ are compared.
pub const CHECKED_PAIRS: usize = 3;

/// Kirchhoff's largest frequency error among the lowest retained ⟨k, l⟩.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ThicknessError {
    /// Nodal diameters of the worst ⟨k, l⟩.
    pub k: u32,
    /// Nodal circles of the worst ⟨k, l⟩.
    pub l: u32,
    /// Its Kirchhoff frequency, Hz.
    pub kirchhoff_hz: f64,
    /// Its Mindlin frequency, Hz.
    pub mindlin_hz: f64,
    /// h / (r_a − r_i).
    pub thickness_ratio: f64,
}

impl ThicknessError {
    /// ω_Kirchhoff / ω_Mindlin − 1.
    pub fn relative_error(&self) -> f64 {
        self.kirchhoff_hz / self.mindlin_hz - 1.0
    }
}

impl fmt::Display for ThicknessError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "plate.theory = kirchhoff on a thick plate (h/(r_a − r_i) = {:.3}): ⟨k = {}, l = {}⟩ at {:.1} Hz is {:.1} % above its Mindlin frequency {:.1} Hz, over the {:.0} % this warning allows in the lowest {} retained ⟨k, l⟩; `modes -p plate.theory:=mindlin` lists the Mindlin modes (docs/mindlin.md)",
            self.thickness_ratio,
            self.k,
            self.l,
            self.kirchhoff_hz,
            100.0 * self.relative_error(),
            self.mindlin_hz,
            100.0 * THICKNESS_WARNING_LEVEL,
            CHECKED_PAIRS
        )
    }
}

impl PlateModel {
    /// Kirchhoff's largest frequency error among the lowest
    /// [`CHECKED_PAIRS`] retained ⟨k, l⟩ against Mindlin theory, when it is
    /// above [`THICKNESS_WARNING_LEVEL`]; `None` otherwise and for a Mindlin
    /// model. Costs one Mindlin eigenproblem per distinct k checked.
    pub fn thickness_warning(&self) -> Result<Option<ThicknessError>, ModelError> {
        let worst = self.kirchhoff_thickness_error()?;
        Ok(worst.filter(|e| e.relative_error() > THICKNESS_WARNING_LEVEL))
    }

    /// The text `modes` and the node print for [`Self::thickness_warning`]
    /// (a failed check is reported as such, not fatal).
    pub fn thickness_warning_text(&self) -> Option<String> {
        match self.thickness_warning() {
            Ok(warning) => warning.map(|w| w.to_string()),
            Err(e) => Some(format!(
                "plate.theory = kirchhoff: the check of the thickness against Mindlin theory failed: {e}"
            )),
        }
    }

    /// The largest e of the lowest [`CHECKED_PAIRS`] ⟨k, l⟩ (`None` under
    /// Mindlin theory).
    pub fn kirchhoff_thickness_error(&self) -> Result<Option<ThicknessError>, ModelError> {
        if self.theory() == PlateTheory::Mindlin {
            return Ok(None);
        }
        let plate = self.plate();
        let mut pairs: Vec<(u32, u32, f64)> = Vec::new();
        for m in self.modes() {
            if pairs.len() < CHECKED_PAIRS && !pairs.iter().any(|p| (p.0, p.1) == (m.k, m.l)) {
                pairs.push((m.k, m.l, m.frequency_hz));
            }
        }
        let disc = MindlinDiscretisation::new(&super::mindlin_plate(plate), DEFAULT_SPLINES)?;
        let mut worst: Option<ThicknessError> = None;
        for &(k, l, kirchhoff_hz) in &pairs {
            let modes = disc.modes(k, l as usize + 1)?;
            let Some(mode) = modes.iter().find(|m| m.l == l) else {
                continue;
            };
            let e = ThicknessError {
                k,
                l,
                kirchhoff_hz,
                mindlin_hz: mode.frequency_hz,
                thickness_ratio: plate.thickness / (plate.outer_radius - plate.inner_radius),
            };
            if worst.is_none_or(|w| e.relative_error() > w.relative_error()) {
                worst = Some(e);
            }
        }
        Ok(worst)
    }
}
