//! Step-aligned reception of the input topics (`ros.input_reception:
//! step_aligned`; vendor/rustdds/PATCH.md §16).
//!
//! Every sample a peer writes on its own topic is its own datagram, and the
//! participant's event loop wakes for each one, or for every few: an rclpy
//! script with one publisher per pad sends 18 datagrams a millisecond, and
//! the loop thread woke about 9,000 times a second for them. The simulation
//! takes its inputs only at step boundaries, so nothing is gained by reading
//! them earlier. While the input topics bring more than a couple of samples a
//! step, the loop engages the participant's `ReceiveGate`: the event loop no
//! longer wakes for user datagrams, and right before the loop takes its inputs
//! it has them all read in one wake-up (`receive_now`). A sample that arrived
//! before the boundary is applied at that step, as before. Services and
//! acknowledgements wait at most one step, or the gate's 2-ms hold.
//!
//! The loop releases the gate whenever it does not step at its own rate
//! (paused, diverged, stepping on request, following `/clock`), and while
//! inputs are sparse (one batch sample a step gains nothing and would cost
//! a wake-up). It is opt-in: the step starts once the burst is read, so the
//! step period varies with it (docs/ros.md has the measured trade).

use ros2_client::dds::rustdds::ReceiveGate;
use std::time::Duration;

/// Engage once the average exceeds this many samples taken a step…
const ENGAGE_ABOVE: f64 = 2.5;
/// …and release once it falls below this.
const RELEASE_BELOW: f64 = 1.5;
/// Weight of the newest step in the average (about the last 32 steps).
const WEIGHT: f64 = 1.0 / 32.0;
/// The longest the loop waits for the event loop to read (it reads on its own
/// after the gate's hold anyway).
const RECEIVE_WAIT: Duration = Duration::from_millis(2);

/// `input_reception` on `/diagnostics` while datagrams are read as they arrive.
pub const ON_ARRIVAL: &str = "on arrival";

/// The loop's use of the participant's receive gate.
pub struct StepAlignedReceive {
    gate: ReceiveGate,
    /// What this loop last set the gate to (nothing else sets it): the node
    /// needs only the gate's `set_engaged` and `receive_now`.
    engaged: bool,
    /// Samples taken per step, exponentially averaged.
    mean: f64,
}

impl StepAlignedReceive {
    pub fn new(gate: ReceiveGate) -> Self {
        gate.set_engaged(false);
        StepAlignedReceive {
            gate,
            engaged: false,
            mean: 0.0,
        }
    }

    /// Right before the inputs are taken at a step boundary: have everything
    /// that arrived read.
    pub fn before_take(&self) {
        if self.engaged {
            self.gate.receive_now(RECEIVE_WAIT);
        }
    }

    /// After `samples` were taken at a step boundary.
    pub fn after_take(&mut self, samples: usize) {
        self.mean += WEIGHT * (samples as f64 - self.mean);
        if self.engaged != engage(self.engaged, self.mean) {
            self.set_engaged(!self.engaged);
        }
    }

    /// `input_reception` on `/diagnostics`.
    pub fn reception(&self) -> &'static str {
        if self.engaged {
            "at step boundaries"
        } else {
            ON_ARRIVAL
        }
    }

    /// Not stepping at the loop's own rate: read on arrival again.
    pub fn release(&mut self) {
        self.mean = 0.0;
        if self.engaged {
            self.set_engaged(false);
        }
    }

    fn set_engaged(&mut self, engaged: bool) {
        self.gate.set_engaged(engaged);
        self.engaged = engaged;
    }
}

/// Whether the gate should be engaged, with hysteresis.
fn engage(engaged: bool, mean_samples_per_step: f64) -> bool {
    if engaged {
        mean_samples_per_step >= RELEASE_BELOW
    } else {
        mean_samples_per_step > ENGAGE_ABOVE
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn many_samples_a_step_engage_and_one_a_step_releases() {
        let mut mean = 0.0;
        let mut engaged = false;
        // 18 per-topic wrenches a step: engaged within a few steps.
        for _ in 0..5 {
            mean += WEIGHT * (18.0 - mean);
            engaged = engage(engaged, mean);
        }
        assert!(engaged);
        // One batch sample a step: released, and stays so.
        for _ in 0..200 {
            mean += WEIGHT * (1.0 - mean);
            engaged = engage(engaged, mean);
        }
        assert!(!engaged);
        assert!(!engage(false, 1.0) && !engage(false, 2.5) && engage(false, 3.0));
        // Hysteresis: 2 a step keeps the state it has.
        assert!(engage(true, 2.0) && !engage(false, 2.0));
    }
}
