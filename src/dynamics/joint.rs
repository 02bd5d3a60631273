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
//!
//! Pad friction τ_f(Ω) = −Σ C tanh(Ω s), regularised over a band of a few
//! mrad/s around standstill, would make this explicit update jump across the
//! band and chatter through zero. When a step starts in or would cross that
//! band, the drive solves J_zz (Ω₁ − Ω₀)/h = τ_drive + τ_other + τ_f(Ω₁) instead
//! (backward Euler in the friction; monotone, so bisection): the plate comes
//! to rest. Elsewhere the update is the explicit one, unchanged.
//!
//! A torque-limited drive against stage-dependent loads that declare no such
//! friction term (the lining's patches, `pads.shear_*`: the friction reaches
//! the joint through the patches' forces) is not held over the step: RK4 and
//! `contact_exponential` integrate Ω (and χ) with the elastic state and
//! evaluate the drive's law at every evaluation of the right-hand side
//! ([`StageDrive`]), so the patches' tangential stiffness (k_t r² per contact
//! against J_zz) and the drive meet inside the step.

use crate::config::JointConfig;

/// One friction contribution to the axial torque: τ(Ω) = −capacity · tanh(Ω · slope).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct FrictionTorque {
    /// N·m.
    pub capacity: f64,
    /// s/rad: the inverse width of the regularisation band.
    pub slope: f64,
}

fn friction_torque(friction: &[FrictionTorque], speed: f64) -> f64 {
    friction
        .iter()
        .map(|f| -f.capacity * (speed * f.slope).tanh())
        .sum()
}

/// Beyond |Ω · slope| of this the friction is fully developed (tanh = 1 − 1e-17).
const BAND: f64 = 20.0;

/// Joint acceleration and drive torque held over one (sub)step.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DriveStep {
    pub acceleration: f64,
    pub effort: f64,
}

/// The drive law for a step of length h from speed Ω towards the command.
/// `load_torque` includes the friction `friction` at Ω.
pub fn drive(
    joint: &JointConfig,
    polar_inertia: f64,
    speed: f64,
    command: f64,
    load_torque: f64,
    friction: &[FrictionTorque],
    h: f64,
) -> DriveStep {
    let a_max = joint.max_acceleration;
    let wanted = ((command - speed) / h).clamp(-a_max, a_max);
    let needed = polar_inertia * wanted - load_torque;
    match joint.max_torque {
        None => DriveStep {
            acceleration: wanted,
            effort: needed,
        },
        Some(limit) => {
            let effort = needed.clamp(-limit, limit);
            let explicit = (effort + load_torque) / polar_inertia;
            let end = speed + h * explicit;
            let in_band = |w: f64| friction.iter().any(|f| (w * f.slope).abs() < BAND);
            if friction.is_empty() || !(in_band(speed) || in_band(end) || end * speed < 0.0) {
                return DriveStep {
                    acceleration: explicit,
                    effort,
                };
            }
            // g(w) = J (w − Ω)/h − effort − τ_other − τ_f(w) rises strictly in w;
            // τ_f ∈ [−C, C] brackets the root.
            let other = load_torque - friction_torque(friction, speed);
            let capacity: f64 = friction.iter().map(|f| f.capacity).sum();
            let g = |w: f64| {
                polar_inertia * (w - speed) / h - effort - other - friction_torque(friction, w)
            };
            let (mut lo, mut hi) = (
                speed + h * (effort + other - capacity) / polar_inertia,
                speed + h * (effort + other + capacity) / polar_inertia,
            );
            for _ in 0..100 {
                let mid = 0.5 * (lo + hi);
                if mid == lo || mid == hi {
                    break;
                }
                if g(mid) > 0.0 {
                    hi = mid;
                } else {
                    lo = mid;
                }
            }
            DriveStep {
                acceleration: (0.5 * (lo + hi) - speed) / h,
                effort,
            }
        }
    }
}

/// Whether the joint is integrated with the elastic state inside the step
/// ([`StageDrive`]) rather than held at the drive's acceleration from the
/// step's start: a torque-limited drive (a stiff one follows its profile
/// whatever the loads), stage-dependent loads (the axial torque changes
/// within the step), and no implicit friction term (a term's band, rate
/// C · slope / J_zz ≈ 1e6 1/s on the brake bench, is for the step-end solve
/// of [`drive`], not for explicit stages). A term with zero slope declares no
/// friction.
pub fn integrated_in_step(
    joint: &JointConfig,
    stage_dependent_loads: bool,
    friction: &[FrictionTorque],
) -> bool {
    joint.max_torque.is_some() && stage_dependent_loads && friction.iter().all(|f| f.slope == 0.0)
}

/// The friction terms' damping Σ capacity · slope / J of those whose band
/// |Ω · slope| < [`BAND`] the speed may reach within the step (its least
/// magnitude `speed_min`), 1/s: what an explicit integration of Ω meets.
pub fn friction_band_rate(friction: &[FrictionTorque], polar_inertia: f64, speed_min: f64) -> f64 {
    friction
        .iter()
        .filter(|f| speed_min.max(0.0) * f.slope < BAND)
        .map(|f| f.capacity * f.slope / polar_inertia)
        .sum()
}

/// The drive's law at one instant inside a step of length h: the speed
/// control towards the command over h, the acceleration limit and the torque
/// limit, against the load torque at that instant (the explicit branch of
/// [`drive`]; J_zz dΩ/dt = τ_drive + τ_loads).
#[derive(Debug, Clone, Copy)]
pub struct StageDrive<'a> {
    pub joint: &'a JointConfig,
    pub polar_inertia: f64,
    pub command: f64,
    pub h: f64,
}

/// How many switching functions [`StageDrive::margins`] gives.
pub const DRIVE_SWITCHES: usize = 2;

impl StageDrive<'_> {
    /// The drive law's switching functions at the instant, positive on its
    /// middle piece: the acceleration limit's margin a_max − |Ω_cmd − Ω|/h
    /// and the torque limit's, limit − |J α − τ_loads|. Where the joint rides
    /// in y they select the contact step's pieces with the contacts' (the
    /// law's linearisation differs on each: at the torque limit τ_drive is
    /// fixed, below it J α − τ_loads follows the state).
    pub fn margins(&self, speed: f64, load_torque: f64) -> [f64; DRIVE_SWITCHES] {
        let a_max = self.joint.max_acceleration;
        let wanted = (self.command - speed) / self.h;
        let needed = self.polar_inertia * wanted.clamp(-a_max, a_max) - load_torque;
        [
            a_max - wanted.abs(),
            self.joint
                .max_torque
                .map_or(1.0, |limit| limit - needed.abs()),
        ]
    }

    /// dΩ/dt and the drive torque at speed Ω under the load torque `load_torque`.
    pub fn at(&self, speed: f64, load_torque: f64) -> DriveStep {
        drive(
            self.joint,
            self.polar_inertia,
            speed,
            self.command,
            load_torque,
            &[],
            self.h,
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn joint(max_torque: Option<f64>) -> JointConfig {
        JointConfig {
            speed: 0.0,
            max_acceleration: 10.0,
            max_torque,
            initial_position: 0.0,
        }
    }

    #[test]
    fn stiff_drive_reaches_command_within_acceleration_limit() {
        let d = drive(&joint(None), 2.0, 0.0, 1.0, 0.0, &[], 1e-3);
        assert_eq!(d.acceleration, 10.0);
        assert_eq!(d.effort, 20.0);
        let d = drive(&joint(None), 2.0, 0.999_995, 1.0, -3.0, &[], 1e-3);
        assert!((d.acceleration - 0.005).abs() < 1e-9);
        assert!((d.effort - (2.0 * 0.005 + 3.0)).abs() < 1e-9);
    }

    #[test]
    fn torque_limited_drive_is_slowed_by_a_braking_torque() {
        // Holding speed against −50 N·m needs 50 N·m; the drive has 20.
        let d = drive(&joint(Some(20.0)), 2.0, 5.0, 5.0, -50.0, &[], 1e-3);
        assert_eq!(d.effort, 20.0);
        assert!((d.acceleration - (-30.0 / 2.0)).abs() < 1e-12);
    }

    #[test]
    fn only_a_torque_limited_drive_against_stage_loads_without_implicit_friction_rides_in_the_step()
    {
        let none = [FrictionTorque::default(); 3];
        let rigid_pads = [FrictionTorque {
            capacity: 0.0,
            slope: 100.0,
        }];
        assert!(integrated_in_step(&joint(Some(20.0)), true, &none));
        assert!(integrated_in_step(&joint(Some(20.0)), true, &[]));
        assert!(!integrated_in_step(&joint(None), true, &none));
        assert!(!integrated_in_step(&joint(Some(20.0)), false, &none));
        // Unclamped rigid pads still declare their band: the step-end solve keeps it.
        assert!(!integrated_in_step(&joint(Some(20.0)), true, &rigid_pads));
    }

    #[test]
    fn the_stage_drive_saturates_at_the_torque_limit_against_the_instants_load() {
        let j = joint(Some(20.0));
        let stage = StageDrive {
            joint: &j,
            polar_inertia: 2.0,
            command: 5.0,
            h: 1e-3,
        };
        // Holding 5 rad/s against −50 N·m needs 50 N·m; the drive has 20.
        let d = stage.at(5.0, -50.0);
        assert_eq!(d.effort, 20.0);
        assert!((d.acceleration - (-15.0)).abs() < 1e-12);
        // Below the command it asks 10 rad/s² (the limit): J α = 20 N·m, 4 of them from the load.
        let d = stage.at(4.0, 4.0);
        assert_eq!((d.acceleration, d.effort), (10.0, 16.0));
    }

    #[test]
    fn friction_above_the_torque_limit_brings_the_plate_to_rest_without_reversing_it() {
        // 2 kN·m of friction (band 1e-2 rad/s) against a 1.5 kN·m drive: explicit
        // Euler jumps between ±3 rad/s; solved at the step's end the plate stops.
        let (j, h) = (0.117, 1e-3);
        let friction = [FrictionTorque {
            capacity: 2000.0,
            slope: 100.0,
        }];
        let mut speed: f64 = 25.0;
        let mut history = vec![];
        for _ in 0..200 {
            let load = friction_torque(&friction, speed);
            let d = drive(&joint(Some(1500.0)), j, speed, 25.0, load, &friction, h);
            speed += d.acceleration * h;
            history.push(speed);
        }
        assert!(
            history.windows(2).all(|w| w[1] <= w[0] + 1e-12),
            "not monotone"
        );
        let last = *history.last().unwrap();
        // At rest the drive's 1.5 kN·m is held by static-like friction: tanh(Ω s) = 0.75.
        let expected = (1500.0f64 / 2000.0).atanh() / 100.0;
        assert!((last - expected).abs() < 1e-9, "{last} vs {expected}");
    }
}
