//! The drive of the rotational joint at the plate axis (paper section 4.1:
//! the joint between the reference frame and the plate, angle χ).
//!
//! The drive follows the commanded speed with an acceleration limit. Without
//! a torque limit it is stiff: Ω follows that profile whatever the loads, and
//! the effort is the torque that takes. With `joint.max_torque` the effort
//! saturates and the plate's polar inertia J_zz sees the load torque, so
//! braking torques above the limit really slow the plate:
//! J_zz dΩ/dt = τ_drive + τ_loads. (The elastic coordinates do not enter the
//! axial equation at first order: C_r and J₁ have no z–z part.)

use crate::config::JointConfig;

/// Joint acceleration and drive torque held over one (sub)step.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DriveStep {
    pub acceleration: f64,
    pub effort: f64,
}

/// The drive law for a step of length h from speed Ω towards the command.
pub fn drive(joint: &JointConfig, polar_inertia: f64, speed: f64, command: f64, load_torque: f64, h: f64) -> DriveStep {
    let a_max = joint.max_acceleration;
    let wanted = ((command - speed) / h).clamp(-a_max, a_max);
    let needed = polar_inertia * wanted - load_torque;
    match joint.max_torque {
        None => DriveStep { acceleration: wanted, effort: needed },
        Some(limit) => {
            let effort = needed.clamp(-limit, limit);
            DriveStep { acceleration: (effort + load_torque) / polar_inertia, effort }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn joint(max_torque: Option<f64>) -> JointConfig {
        JointConfig { speed: 0.0, max_acceleration: 10.0, max_torque, initial_position: 0.0 }
    }

    #[test]
    fn stiff_drive_reaches_command_within_acceleration_limit() {
        let d = drive(&joint(None), 2.0, 0.0, 1.0, 0.0, 1e-3);
        assert_eq!(d.acceleration, 10.0);
        assert_eq!(d.effort, 20.0);
        let d = drive(&joint(None), 2.0, 0.999_995, 1.0, -3.0, 1e-3);
        assert!((d.acceleration - 0.005).abs() < 1e-9);
        assert!((d.effort - (2.0 * 0.005 + 3.0)).abs() < 1e-9);
    }

    #[test]
    fn torque_limited_drive_is_slowed_by_a_braking_torque() {
        // Holding speed against −50 N·m needs 50 N·m; the drive has 20.
        let d = drive(&joint(Some(20.0)), 2.0, 5.0, 5.0, -50.0, 1e-3);
        assert_eq!(d.effort, 20.0);
        assert!((d.acceleration - (-30.0 / 2.0)).abs() < 1e-12);
    }
}
