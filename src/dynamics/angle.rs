//! The joint angle χ as whole turns plus an angle, so that kχ keeps full
//! precision however far the plate has turned.

use std::f64::consts::TAU;

/// The joint angle χ kept as whole turns plus an angle in [0, 2π), so that
/// kχ for the ALE transform (eq. 20) keeps full precision however far the
/// plate has turned (χ beyond 1e9 rad included).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct JointAngle {
    /// Whole turns.
    pub turns: i64,
    /// In [0, 2π).
    pub angle: f64,
}

impl JointAngle {
    /// The angle χ in radians as whole turns and a remainder.
    pub fn from_radians(chi: f64) -> JointAngle {
        let turns = (chi / TAU).floor();
        let mut a = JointAngle {
            turns: turns as i64,
            angle: chi - turns * TAU,
        };
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
