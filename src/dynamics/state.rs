//! The plain state: joint angle and speed, modal amplitudes and rates.
//! The stepper never owns it, so reset, checkpoint and replay are clones.

use super::load_models::LoadModelState;
use crate::config::Coordinates;
use std::f64::consts::TAU;

/// The joint angle χ kept as whole turns plus an angle in [0, 2π), so that
/// kχ for the ALE transform (eq. 20) keeps full precision however far the
/// plate has turned (χ beyond 1e9 rad included).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct JointAngle {
    pub turns: i64,
    /// In [0, 2π).
    pub angle: f64,
}

impl JointAngle {
    pub fn from_radians(chi: f64) -> JointAngle {
        let turns = (chi / TAU).floor();
        let mut a = JointAngle { turns: turns as i64, angle: chi - turns * TAU };
        a.normalize();
        a
    }

    /// χ as one number (loses precision beyond ~1e9 rad, as any f64 does).
    pub fn radians(&self) -> f64 {
        self.turns as f64 * TAU + self.angle
    }

    /// Advance by δ (rad).
    pub fn advance(&mut self, delta: f64) {
        self.angle += delta;
        self.normalize();
    }

    fn normalize(&mut self) {
        if !(0.0..TAU).contains(&self.angle) {
            let t = (self.angle / TAU).floor();
            self.turns += t as i64;
            self.angle -= t * TAU;
            if self.angle >= TAU {
                self.angle -= TAU;
                self.turns += 1;
            }
            if self.angle < 0.0 {
                self.angle += TAU;
                self.turns -= 1;
            }
        }
    }

    /// χ wrapped to (−π, π].
    pub fn wrapped(&self) -> f64 {
        if self.angle > std::f64::consts::PI {
            self.angle - TAU
        } else {
            self.angle
        }
    }
}

/// State of the joint and the elastic coordinates.
#[derive(Debug, Clone, PartialEq)]
pub struct State {
    /// Simulated time, s.
    pub time: f64,
    /// χ.
    pub chi: JointAngle,
    /// Ω = dχ/dt, rad/s.
    pub speed: f64,
    /// dΩ/dt over the last step, rad/s².
    pub acceleration: f64,
    /// Drive torque over the last step, N·m.
    pub effort: f64,
    /// The description `q` and `q_dot` are resolved in.
    pub coordinates: Coordinates,
    /// Modal amplitudes, m (mode order of the model).
    pub q: Vec<f64>,
    pub q_dot: Vec<f64>,
    /// State of the load models (the tool's machined surface).
    pub load_models: LoadModelState,
}

impl State {
    /// At rest elastically, turning at `speed` from angle `chi`.
    pub fn new(n_modes: usize, coordinates: Coordinates, chi: f64, speed: f64) -> State {
        State {
            time: 0.0,
            chi: JointAngle::from_radians(chi),
            speed,
            acceleration: 0.0,
            effort: 0.0,
            coordinates,
            q: vec![0.0; n_modes],
            q_dot: vec![0.0; n_modes],
            load_models: LoadModelState::default(),
        }
    }

    /// Copy `other` into `self`, reusing the amplitude buffers (the derived
    /// `clone_from` would allocate).
    pub fn copy_from(&mut self, other: &State) {
        self.time = other.time;
        self.chi = other.chi;
        self.speed = other.speed;
        self.acceleration = other.acceleration;
        self.effort = other.effort;
        self.coordinates = other.coordinates;
        self.q.clear();
        self.q.extend_from_slice(&other.q);
        self.q_dot.clear();
        self.q_dot.extend_from_slice(&other.q_dot);
        self.load_models.copy_from(&other.load_models);
    }

    pub fn is_finite(&self) -> bool {
        self.time.is_finite()
            && self.chi.angle.is_finite()
            && self.speed.is_finite()
            && self.effort.is_finite()
            && self.q.iter().chain(&self.q_dot).all(|v| v.is_finite())
            && self.load_models.tool.as_ref().is_none_or(|t| t.holder.is_finite() && t.deflection.is_finite() && t.force.is_finite())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn joint_angle_keeps_sub_microradian_precision_beyond_1e9_rad() {
        let mut a = JointAngle::from_radians(0.25);
        a.turns += 200_000_000; // ≈ 1.26e9 rad
        for _ in 0..1000 {
            a.advance(1e-3);
        }
        assert!((a.angle - 1.25).abs() < 1e-12, "{}", a.angle);
        assert_eq!(a.turns, 200_000_000);
    }

    #[test]
    fn negative_angles_wrap_into_range() {
        let a = JointAngle::from_radians(-0.5);
        assert_eq!(a.turns, -1);
        assert!((a.angle - (TAU - 0.5)).abs() < 1e-15);
        assert!((a.wrapped() + 0.5).abs() < 1e-15);
    }
}
