//! Wrenches on node frames and the checks every input passes before it may
//! reach the state.

use super::error::InputError;
pub use super::node_frame::NodeKind;

/// Force (N) and moment (N·m) acting at a node frame, in that frame's axes.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Wrench {
    /// Force, N.
    pub force: [f64; 3],
    /// Moment, N·m.
    pub moment: [f64; 3],
}

impl Wrench {
    /// Check finiteness and magnitudes; `what` names the input in the error
    /// (e.g. `ale_2 wrench`) and is only called when there is one.
    pub fn validate(
        &self,
        what: impl Fn() -> String,
        max_force: f64,
        max_moment: f64,
    ) -> Result<(), InputError> {
        const AXES: [&str; 3] = ["x", "y", "z"];
        for (part, values, limit) in [
            ("force", &self.force, max_force),
            ("moment", &self.moment, max_moment),
        ] {
            for (axis, &v) in AXES.iter().zip(values.iter()) {
                if !v.is_finite() {
                    return Err(InputError::NonFinite {
                        what: format!("{} {part}.{axis}", what()),
                        value: v,
                    });
                }
            }
            let norm = values.iter().map(|v| v * v).sum::<f64>().sqrt();
            if norm > limit {
                return Err(InputError::Absurd {
                    what: format!("{} |{part}|", what()),
                    value: norm,
                    limit,
                });
            }
        }
        Ok(())
    }
}
