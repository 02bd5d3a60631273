//! Time: the stamps of the outputs, `/clock`, and the pacing of the loop.
//!
//! Two time sources (docs/ros.md, "Time"):
//! - **wall** (default): outputs are stamped with the system clock; the loop
//!   runs at `simulation.rate_hz × simulation.realtime_factor` steps per
//!   second (0 = as fast as possible);
//! - **sim** (`ros.publish_clock: true` or `use_sim_time: true`): outputs are
//!   stamped with simulated time, which starts at 0 and advances by exactly
//!   1/rate_hz per step, and `/clock` (rosgraph_msgs/msg/Clock) carries it
//!   after every step. ROS time never goes backwards: a `~/reset` returns
//!   the plate to its initial state, but the clock keeps counting (as
//!   Gazebo's reset_world), so tf buffers and bag files stay consistent.
//! - **followed** (`use_sim_time: true`): outputs are stamped with an
//!   external `/clock`, and the loop steps as that clock advances
//!   (`clock_follower::ClockFollower`); the node publishes no `/clock` of its own.
//!
//! **The /clock type trap.** ros2-client's `Spinner` subscribes `/clock`
//! typed `builtin_interfaces/msg/Time`; a Clock-typed writer in the same
//! participant would leave two types on one topic (DDS tools flag it,
//! rosbag2 refuses to record it). This node therefore never creates a
//! Spinner: it serves the parameter services itself (`params_service.rs`),
//! so `/clock` only ever carries `rosgraph_msgs::msg::dds_::Clock_`. The
//! wire test `clock_has_one_type_and_monotonic_stamps` checks exactly that.

use super::clock_follower::ClockFollower;
use super::types::Time;
use std::time::{Duration, Instant};

/// Stamps for the outputs: simulated (from the total step count), an
/// external clock's, or wall.
#[derive(Debug, Clone)]
pub struct StepClock {
    sim: bool,
    dt: f64,
    /// Steps since the node started (not reset by `~/reset`).
    total_steps: u64,
    /// `use_sim_time`: the external `/clock` (stamps and the steps due).
    follow: Option<ClockFollower>,
}

impl StepClock {
    /// A clock for steps of `dt` seconds: simulated stamps if `sim`, wall stamps otherwise.
    pub fn new(sim: bool, dt: f64) -> Self {
        StepClock {
            sim,
            dt,
            total_steps: 0,
            follow: None,
        }
    }

    /// Stamps from an external `/clock` (`use_sim_time: true`).
    /// `max_jump`: `ros.max_clock_jump`, s (`ClockFollower::with_max_jump`).
    pub fn following(dt: f64, max_jump: f64) -> Self {
        StepClock {
            sim: false,
            dt,
            total_steps: 0,
            follow: Some(ClockFollower::new(dt).with_max_jump(max_jump)),
        }
    }

    /// The external clock being followed, if any.
    pub fn follower(&self) -> Option<&ClockFollower> {
        self.follow.as_ref()
    }

    /// The follower of the external `/clock` (`use_sim_time`), if there is one.
    pub fn follower_mut(&mut self) -> Option<&mut ClockFollower> {
        self.follow.as_mut()
    }

    /// Whether the stamps are simulated time (steps × dt).
    pub fn is_sim(&self) -> bool {
        self.sim
    }

    /// One step taken.
    pub fn advance(&mut self) {
        self.total_steps += 1;
        if let Some(f) = &mut self.follow {
            f.stepped();
        }
    }

    /// Steps since the node started (not reset by `~/reset`).
    pub fn total_steps(&self) -> u64 {
        self.total_steps
    }

    /// Simulated ROS time: total steps × dt, rounded to the nanosecond (no
    /// drift for rates whose period is not a whole number of nanoseconds);
    /// following an external clock, that clock's time on the step grid.
    pub fn sim_time(&self) -> Time {
        match &self.follow {
            Some(f) => Time::from_nanos(f.stamp_ns()),
            None => Time::from_nanos((self.total_steps as f64 * self.dt * 1e9).round() as i64),
        }
    }

    /// The stamp for outputs of the current step.
    pub fn stamp(&self) -> Time {
        if self.sim || self.follow.is_some() {
            self.sim_time()
        } else {
            Time::wall_now()
        }
    }
}

/// The longest step period of a paced loop (a year): longer ones are held at it.
pub const MAX_PERIOD: Duration = Duration::from_secs(365 * 24 * 3600);

/// Deadlines of a fixed-rate loop. When the loop falls more than one period
/// behind it does not try to catch up with a burst: it counts an overrun and
/// restarts the schedule from now.
#[derive(Debug, Clone)]
pub struct Pacer {
    /// None: as fast as possible.
    period: Option<Duration>,
    next: Instant,
    overruns: u64,
}

impl Pacer {
    /// `dt` simulated seconds per step, `realtime_factor` as in the config.
    /// Any pair of numbers gives a period: the declared ranges keep it within
    /// a day or so, and a period beyond [`MAX_PERIOD`] (or not a number) is
    /// held at it rather than overflowing a `Duration` or `Instant`.
    pub fn new(dt: f64, realtime_factor: f64, now: Instant) -> Self {
        let period = (realtime_factor > 0.0).then(|| {
            let p = dt / realtime_factor;
            if p.is_nan() {
                MAX_PERIOD
            } else {
                Duration::try_from_secs_f64(p.max(0.0)).map_or(MAX_PERIOD, |d| d.min(MAX_PERIOD))
            }
        });
        Pacer {
            period,
            next: now,
            overruns: 0,
        }
    }

    /// The wall-clock period between deadlines (None: as fast as possible).
    pub fn period(&self) -> Option<Duration> {
        self.period
    }

    /// Change the real-time factor (takes effect from now).
    pub fn set_realtime_factor(&mut self, dt: f64, realtime_factor: f64, now: Instant) {
        *self = Pacer {
            overruns: self.overruns,
            ..Pacer::new(dt, realtime_factor, now)
        };
    }

    /// When the next step is due.
    pub fn deadline(&self) -> Instant {
        self.next
    }

    /// The step due at `deadline()` was taken at `now`; schedule the next one.
    pub fn stepped(&mut self, now: Instant) {
        match self.period {
            None => self.next = now,
            Some(p) => {
                self.next += p;
                if now > self.next + p {
                    self.overruns += 1;
                    self.next = now;
                }
            }
        }
    }

    /// Restart the schedule from `now` (after a pause).
    pub fn restart(&mut self, now: Instant) {
        self.next = now;
    }

    /// Times the loop fell more than one period behind and restarted its schedule.
    pub fn overruns(&self) -> u64 {
        self.overruns
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sim_time_counts_steps_without_drift() {
        let mut c = StepClock::new(true, 1.0 / 3000.0);
        assert_eq!(c.stamp(), Time::default());
        for _ in 0..3000 {
            c.advance();
        }
        assert_eq!(c.stamp(), Time { sec: 1, nanosec: 0 });
        let mut c = StepClock::new(true, 1e-3);
        c.advance();
        assert_eq!(
            c.stamp(),
            Time {
                sec: 0,
                nanosec: 1_000_000
            }
        );
    }

    #[test]
    fn a_followed_clock_stamps_each_step_on_its_grid() {
        let mut c = StepClock::following(1e-3, 1.0);
        c.follower_mut().unwrap().observe(2_000_000_000);
        c.follower_mut().unwrap().observe(2_003_000_000);
        assert_eq!(c.follower().unwrap().due(), 3);
        c.advance();
        assert_eq!(
            c.stamp(),
            Time {
                sec: 2,
                nanosec: 1_000_000
            }
        );
        assert_eq!(c.follower().unwrap().due(), 2);
    }

    #[test]
    fn wall_stamps_are_recent() {
        let c = StepClock::new(false, 1e-3);
        assert!(c.stamp().sec > 1_600_000_000);
    }

    #[test]
    fn pacer_keeps_the_period_and_counts_overruns() {
        let t0 = Instant::now();
        let mut p = Pacer::new(1e-3, 1.0, t0);
        assert_eq!(p.deadline(), t0);
        p.stepped(t0);
        assert_eq!(p.deadline(), t0 + Duration::from_millis(1));
        // A little late: no overrun, the schedule holds.
        p.stepped(t0 + Duration::from_micros(1200));
        assert_eq!(p.deadline(), t0 + Duration::from_millis(2));
        assert_eq!(p.overruns(), 0);
        // Far behind: restart from now.
        let late = t0 + Duration::from_millis(10);
        p.stepped(late);
        assert_eq!(p.overruns(), 1);
        assert_eq!(p.deadline(), late);
    }

    #[test]
    fn realtime_factor_scales_the_period() {
        let t0 = Instant::now();
        assert_eq!(
            Pacer::new(1e-3, 2.0, t0).period(),
            Some(Duration::from_micros(500))
        );
        assert_eq!(Pacer::new(1e-3, 0.0, t0).period(), None);
        let mut p = Pacer::new(1e-3, 0.0, t0);
        p.stepped(t0 + Duration::from_secs(1));
        assert_eq!(p.overruns(), 0);
    }
}
