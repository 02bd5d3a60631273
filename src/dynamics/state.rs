//! The plain state: time, joint angle and speed, modal amplitudes and rates
//! in both descriptions, the load models' states. The stepper never owns it,
//! so reset, checkpoint and replay are clones.

use super::ale::{ale_to_lagrange, harmonics, lagrange_to_ale};
use super::load_models::LoadModelState;
use super::scene::{ModeLayout, Scene};
use crate::config::Coordinates;

pub use super::angle::JointAngle;
pub use super::integrators::contact_exponential::ContactSpans;

/// Everything that evolves: time and step count, the joint, the elastic
/// coordinates in both descriptions, the load models' states. The stepper
/// never owns it, so reset, checkpoint and replay are copies: any saved
/// `State` can be stepped again with the same result, bit for bit.
#[derive(Debug, Clone, PartialEq)]
pub struct State {
    /// Output steps since the start (or the last reset).
    pub steps: u64,
    /// Simulated time, s: `steps` × dt at the end of a step (no drift from
    /// repeated addition), intermediate within a step's substeps.
    pub time: f64,
    /// χ.
    pub chi: JointAngle,
    /// Ω = dχ/dt, rad/s.
    pub speed: f64,
    /// dΩ/dt over the last step, rad/s².
    pub acceleration: f64,
    /// Drive torque over the last step, N·m.
    pub effort: f64,
    /// The description `q` and `q_dot` are resolved in: the one integrated.
    pub coordinates: Coordinates,
    /// Modal amplitudes, m (mode order of the model), in `coordinates`.
    pub q: Vec<f64>,
    /// Their rates, m/s.
    pub q_dot: Vec<f64>,
    /// The same elastic state in the other description (eq. 20), kept
    /// consistent by the stepper; after editing `q` or `q_dot` by hand call
    /// [`State::rederive`].
    pub q_other: Vec<f64>,
    /// Their rates, m/s.
    pub q_dot_other: Vec<f64>,
    /// State of the load models (one slot each; the tool's machined surface).
    pub load_models: LoadModelState,
    /// `contact_exponential`'s span length and order at the last step's end,
    /// where the next step starts (docs/dynamics.md, "Stiff contacts").
    pub contact_spans: ContactSpans,
}

impl State {
    /// At rest elastically, turning at `speed` from angle `chi`.
    pub fn new(n_modes: usize, coordinates: Coordinates, chi: f64, speed: f64) -> State {
        State {
            steps: 0,
            time: 0.0,
            chi: JointAngle::from_radians(chi),
            speed,
            acceleration: 0.0,
            effort: 0.0,
            coordinates,
            q: vec![0.0; n_modes],
            q_dot: vec![0.0; n_modes],
            q_other: vec![0.0; n_modes],
            q_dot_other: vec![0.0; n_modes],
            load_models: LoadModelState::default(),
            contact_spans: ContactSpans::default(),
        }
    }

    /// Derive the other description from `q`, `q_dot`, χ and Ω (eq. 20);
    /// `harm` is scratch.
    pub fn rederive_with(&mut self, layout: &ModeLayout, harm: &mut Vec<(f64, f64)>) {
        harmonics(&self.chi, layout.k_max, harm);
        self.q_other.copy_from_slice(&self.q);
        self.q_dot_other.copy_from_slice(&self.q_dot);
        match self.coordinates {
            Coordinates::Lagrangian => lagrange_to_ale(
                layout,
                harm,
                self.speed,
                &mut self.q_other,
                &mut self.q_dot_other,
            ),
            Coordinates::Ale => ale_to_lagrange(
                layout,
                harm,
                self.speed,
                &mut self.q_other,
                &mut self.q_dot_other,
            ),
        }
    }

    /// [`State::rederive_with`] with its own scratch (allocates).
    pub fn rederive(&mut self, scene: &Scene) {
        self.rederive_with(&scene.layout, &mut Vec::new());
    }

    /// Amplitudes and rates in the Lagrangian description (eq. 13).
    pub fn lagrange(&self) -> (&[f64], &[f64]) {
        match self.coordinates {
            Coordinates::Lagrangian => (&self.q, &self.q_dot),
            Coordinates::Ale => (&self.q_other, &self.q_dot_other),
        }
    }

    /// Amplitudes and rates in the ALE description (eq. 20).
    pub fn ale(&self) -> (&[f64], &[f64]) {
        match self.coordinates {
            Coordinates::Ale => (&self.q, &self.q_dot),
            Coordinates::Lagrangian => (&self.q_other, &self.q_dot_other),
        }
    }

    /// The Lagrangian amplitudes and rates, then the ALE ones, to write.
    pub fn lagrange_and_ale_mut(&mut self) -> (&mut [f64], &mut [f64], &mut [f64], &mut [f64]) {
        match self.coordinates {
            Coordinates::Lagrangian => (
                &mut self.q,
                &mut self.q_dot,
                &mut self.q_other,
                &mut self.q_dot_other,
            ),
            Coordinates::Ale => (
                &mut self.q_other,
                &mut self.q_dot_other,
                &mut self.q,
                &mut self.q_dot,
            ),
        }
    }

    /// Copy `other` into `self`, reusing the amplitude buffers (the derived
    /// `clone_from` would allocate).
    pub fn copy_from(&mut self, other: &State) {
        self.copy_from_except_load_models(other);
        self.load_models.copy_from(&other.load_models);
    }

    /// [`State::copy_from`] without the load models' slots (the stepper
    /// undoes those by its log, [`crate::dynamics::load_models::undo`]).
    pub fn copy_from_except_load_models(&mut self, other: &State) {
        self.steps = other.steps;
        self.time = other.time;
        self.chi = other.chi;
        self.speed = other.speed;
        self.acceleration = other.acceleration;
        self.effort = other.effort;
        self.coordinates = other.coordinates;
        self.contact_spans = other.contact_spans;
        for (a, b) in [
            (&mut self.q, &other.q),
            (&mut self.q_dot, &other.q_dot),
            (&mut self.q_other, &other.q_other),
            (&mut self.q_dot_other, &other.q_dot_other),
        ] {
            a.clear();
            a.extend_from_slice(b);
        }
    }

    /// Every value finite, load-model slots included.
    pub fn is_finite(&self) -> bool {
        self.is_finite_except_load_models() && self.load_models.is_finite()
    }

    /// Time, joint and both descriptions finite.
    pub fn is_finite_except_load_models(&self) -> bool {
        self.time.is_finite()
            && self.chi.angle.is_finite()
            && self.speed.is_finite()
            && self.effort.is_finite()
            && [&self.q, &self.q_dot, &self.q_other, &self.q_dot_other]
                .into_iter()
                .all(|v| all_finite(v))
    }
}

/// Every value finite, without an early exit (the divergence guard runs it
/// every step). A double is NaN or ±∞ exactly when its exponent bits are all
/// ones: (bits & exponent mask) + 2⁵² then carries into the sign bit, and for
/// every finite value it does not. OR-ing those words is integer `and`, `add`,
/// `or` per value, which the compiler keeps in vector lanes (the float form
/// v − v summed in four lanes compiled to one scalar chain, ~4 instructions a
/// value).
fn all_finite(values: &[f64]) -> bool {
    const EXPONENT: u64 = 0x7ff0_0000_0000_0000;
    const ONE: u64 = 1 << 52;
    values
        .iter()
        .fold(0u64, |acc, v| acc | ((v.to_bits() & EXPONENT) + ONE))
        >> 63
        == 0
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn one_nan_or_infinity_in_any_description_makes_the_state_non_finite() {
        let clean = State::new(5, Coordinates::Ale, 0.3, 2.0);
        assert!(clean.is_finite());
        for bad in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
            for field in 0..4 {
                for i in [0, 2, 4] {
                    let mut s = clean.clone();
                    let v = match field {
                        0 => &mut s.q,
                        1 => &mut s.q_dot,
                        2 => &mut s.q_other,
                        _ => &mut s.q_dot_other,
                    };
                    v[i] = bad;
                    assert!(
                        !s.is_finite_except_load_models(),
                        "{bad} in field {field}[{i}]"
                    );
                }
            }
        }
        let mut big = clean.clone();
        big.q_dot[3] = f64::MAX;
        big.q[1] = -f64::MAX;
        big.q_other[2] = f64::MIN_POSITIVE / 4.0; // subnormal
        big.q_dot_other[0] = -0.0;
        assert!(big.is_finite());
    }
}
