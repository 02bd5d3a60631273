//! The tool's main cutting force (`tool.cutting_specific_force`,
//! `tool.cutting_exponent`): Kienzle's law for the tangential force of the
//! same chip as the feed force of eq. (21),
//!
//!   F_c = k_c1.1 b h^(1−m_c) (1 mm)^(m_c),
//!
//! acting at the tool's node (the mid-plane point of the rim) along the
//! circumferential direction against the material's motion: −sign Ω e_θ.
//! Through the node loads it brakes the joint (the load torque −F_c r_a
//! sign Ω, which a speed-following drive's effort carries) and does the work
//! u_i·F on the in-plane modes (the disc twists under the cut). The paper's
//! model (section 5.1) has the feed force only: k_c1.1 = 0, the default,
//! adds nothing. The radial depth of cut b stays as configured: the in-plane
//! modes' radial displacement at the rim does not change the chip.

use super::tool::Tool;
use crate::dynamics::Wrench;

impl Tool {
    /// F_c for chip thickness h (m), N (0 without a chip or a cutting force).
    pub fn cutting_force(&self, chip: f64) -> f64 {
        let [specific, exponent, reference] = self.cutting;
        if chip <= 0.0 || specific == 0.0 {
            return 0.0;
        }
        specific * self.depth_of_cut * chip.powf(1.0 - exponent) * reference
    }

    /// Add F_c of `chip` at speed Ω to the tool node's wrench (frame A's
    /// axes): −sign Ω F_c e_θ at the node's angle.
    pub(super) fn add_cutting_force(&self, chip: f64, speed: f64, wrench: &mut Wrench) {
        let force = self.cutting_force(chip);
        if force == 0.0 {
            return;
        }
        let (s, c) = self.angle.sin_cos();
        let f = force * speed.signum();
        wrench.force[0] += f * s;
        wrench.force[1] -= f * c;
    }
}
