//! Wrenches on node frames and the checks every input passes before it may
//! reach the state.

use thiserror::Error;

/// Kind of node frame (paper section 4.1).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum NodeKind {
    /// Material point turning with the plate (`nodes_Lagrange`).
    Lagrange,
    /// Space-fixed point the plate slides under (`nodes_ALE`).
    Ale,
}

impl NodeKind {
    pub fn name(self) -> &'static str {
        match self {
            NodeKind::Lagrange => "lagrange",
            NodeKind::Ale => "ale",
        }
    }
}

/// Force (N) and moment (N·m) acting at a node frame, in that frame's axes.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Wrench {
    pub force: [f64; 3],
    pub moment: [f64; 3],
}

/// An input refused before it reached the state. The state and every other
/// held input are unchanged.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum InputError {
    #[error("{what} is not finite ({value})")]
    NonFinite { what: String, value: f64 },
    #[error("{what} = {value:e} exceeds the plausibility limit {limit:e} (limits.*)")]
    Absurd { what: String, value: f64, limit: f64 },
    #[error("there is no {} node {index} (1-based; this scene has {count})", kind.name())]
    NoSuchNode { kind: NodeKind, index: usize, count: usize },
}

impl Wrench {
    /// Check finiteness and magnitudes; `what` names the input in the error
    /// (e.g. `ale_2 wrench`) and is only called when there is one.
    pub fn validate(&self, what: impl Fn() -> String, max_force: f64, max_moment: f64) -> Result<(), InputError> {
        const AXES: [&str; 3] = ["x", "y", "z"];
        for (part, values, limit) in [("force", &self.force, max_force), ("moment", &self.moment, max_moment)] {
            for (axis, &v) in AXES.iter().zip(values.iter()) {
                if !v.is_finite() {
                    return Err(InputError::NonFinite { what: format!("{} {part}.{axis}", what()), value: v });
                }
            }
            let norm = values.iter().map(|v| v * v).sum::<f64>().sqrt();
            if norm > limit {
                return Err(InputError::Absurd { what: format!("{} |{part}|", what()), value: norm, limit });
            }
        }
        Ok(())
    }
}
