//! `use_sim_time: true`: the node's time follows an external `/clock`
//! (rosgraph_msgs/msg/Clock, from Gazebo, `ros2 bag play --clock` or any
//! clock node), and the loop steps in lockstep with it (docs/ros.md, "Time").
//!
//! The first `/clock` message fixes the origin: the plate's state at that
//! moment is stamped with that time. From then on the plate owes as many of
//! its fixed steps `dt` as fit into the time the clock has advanced since
//! the origin: a clock that advances by 5·dt is answered with 5 steps, one
//! that advances by half a step with none (the half is kept for the next
//! advance), a clock that stands still (paused) with none. Each step's
//! outputs are stamped `origin + steps·dt`: the clock's time on the step
//! grid, never ahead of the clock. While the node itself is paused (or has
//! diverged) the clock's advance is skipped rather than owed, so a resume
//! does not race to catch up. A clock that goes back behind the last stamp
//! (a bag played in a loop) starts a new origin at its new time. A clock
//! that jumps forward, further ahead of its previous message than
//! `ros.max_clock_jump` (a bag played from a later start, a simulator that
//! skipped), is not worked off step by step either: the follower re-anchors
//! at the new time (the plate's state is kept, the stamps continue from
//! there), and counts the jump; the node logs it and reports it on
//! /diagnostics (WARN).
//!
//! Pure bookkeeping, no I/O: the node feeds it the clock's messages, the
//! loop asks what is due.

/// What one `/clock` message did to the follower.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ClockUpdate {
    /// The first message: the origin.
    Started,
    /// At or after the last stamp (some steps may now be due).
    Forward,
    /// Behind the last stamp: a new origin at this time.
    Backwards,
    /// More than the jump limit ahead of the previous message: a new origin
    /// at this time; `gap_ns` is the advance that was not stepped through.
    JumpedForward { gap_ns: i64 },
}

/// Follows an external clock; see the module documentation.
#[derive(Debug, Clone)]
pub struct ClockFollower {
    dt_ns: f64,
    /// Clock time (ns) of the state when following began or was re-based.
    origin: Option<i64>,
    /// The newest clock time (ns).
    latest: i64,
    /// Steps taken or skipped since the origin.
    steps: u64,
    jumps_back: u64,
    /// Largest forward advance between two messages that is stepped through (ns).
    max_jump_ns: i64,
    jumps_forward: u64,
}

impl ClockFollower {
    /// `dt`: the plate's step, s.
    pub fn new(dt: f64) -> Self {
        ClockFollower {
            dt_ns: dt * 1e9,
            origin: None,
            latest: 0,
            steps: 0,
            jumps_back: 0,
            max_jump_ns: i64::MAX,
            jumps_forward: 0,
        }
    }

    /// A forward advance of more than `max_jump` s between two messages
    /// re-anchors instead of owing its steps (`ros.max_clock_jump`; a value
    /// that is not a positive number leaves the limit off).
    pub fn with_max_jump(mut self, max_jump: f64) -> Self {
        if max_jump > 0.0 {
            self.max_jump_ns = (max_jump * 1e9).min(i64::MAX as f64) as i64;
        }
        self
    }

    /// A `/clock` message with time `t_ns`.
    pub fn observe(&mut self, t_ns: i64) -> ClockUpdate {
        match self.origin {
            None => {
                self.rebase(t_ns);
                ClockUpdate::Started
            }
            Some(_) if t_ns < self.stamp_ns() => {
                self.rebase(t_ns);
                self.jumps_back += 1;
                ClockUpdate::Backwards
            }
            Some(_) if t_ns.saturating_sub(self.latest) > self.max_jump_ns => {
                let gap_ns = t_ns.saturating_sub(self.latest);
                self.rebase(t_ns);
                self.jumps_forward += 1;
                ClockUpdate::JumpedForward { gap_ns }
            }
            Some(_) => {
                self.latest = t_ns;
                ClockUpdate::Forward
            }
        }
    }

    fn rebase(&mut self, t_ns: i64) {
        self.origin = Some(t_ns);
        self.latest = t_ns;
        self.steps = 0;
    }

    /// Whole steps between the origin and the newest clock time. The 1e-6
    /// step of slack absorbs the rounding of a clock that counts in whole
    /// nanoseconds at a rate whose period is not one (3 kHz).
    fn steps_to_latest(&self) -> u64 {
        match self.origin {
            None => 0,
            Some(o) => (self.latest.saturating_sub(o) as f64 / self.dt_ns + 1e-6)
                .floor()
                .max(0.0) as u64,
        }
    }

    /// Steps owed to the clock.
    pub fn due(&self) -> u64 {
        self.steps_to_latest().saturating_sub(self.steps)
    }

    /// One step taken.
    pub fn stepped(&mut self) {
        self.steps += 1;
    }

    /// Forgo the steps owed (the node is paused): the stamps jump with the clock.
    pub fn skip(&mut self) {
        self.steps = self.steps.max(self.steps_to_latest());
    }

    /// The stamp of the current state: `origin + steps·dt` (0 before any clock).
    pub fn stamp_ns(&self) -> i64 {
        self.origin
            .unwrap_or(0)
            .saturating_add((self.steps as f64 * self.dt_ns).round() as i64)
    }

    /// Whether a clock message has been seen.
    pub fn started(&self) -> bool {
        self.origin.is_some()
    }

    /// How often the clock went back behind the last stamp.
    pub fn jumps_back(&self) -> u64 {
        self.jumps_back
    }

    /// How often the clock jumped forward beyond the limit (re-anchored).
    pub fn jumps_forward(&self) -> u64 {
        self.jumps_forward
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const MS: i64 = 1_000_000;

    #[test]
    fn nothing_is_due_before_the_first_clock_and_at_its_origin() {
        let mut f = ClockFollower::new(1e-3);
        assert_eq!((f.due(), f.stamp_ns(), f.started()), (0, 0, false));
        assert_eq!(f.observe(100_000 * MS), ClockUpdate::Started);
        assert_eq!((f.due(), f.stamp_ns()), (0, 100_000 * MS));
    }

    #[test]
    fn an_advance_owes_the_whole_steps_it_holds_and_keeps_the_rest() {
        let mut f = ClockFollower::new(1e-3);
        f.observe(7 * MS);
        assert_eq!(f.observe(12 * MS + MS / 2), ClockUpdate::Forward);
        assert_eq!(f.due(), 5);
        for k in 1..=5 {
            f.stepped();
            assert_eq!(f.stamp_ns(), 7 * MS + k * MS);
        }
        assert_eq!(f.due(), 0);
        // The half step left over completes with the next half.
        f.observe(13 * MS);
        assert_eq!(f.due(), 1);
        // A clock standing still owes nothing more.
        f.stepped();
        f.observe(13 * MS);
        assert_eq!(f.due(), 0);
    }

    #[test]
    fn a_rate_without_a_whole_nanosecond_period_does_not_drift() {
        let mut f = ClockFollower::new(1.0 / 3000.0);
        f.observe(0);
        f.observe(1_000_000_000);
        assert_eq!(f.due(), 3000);
        (0..3000).for_each(|_| f.stepped());
        assert_eq!(f.stamp_ns(), 1_000_000_000);
    }

    #[test]
    fn a_skipped_advance_is_not_owed_later() {
        let mut f = ClockFollower::new(1e-3);
        f.observe(0);
        f.observe(10 * MS);
        f.skip();
        assert_eq!((f.due(), f.stamp_ns()), (0, 10 * MS));
        f.observe(13 * MS);
        assert_eq!(f.due(), 3);
    }

    #[test]
    fn a_clock_going_back_behind_the_stamp_starts_a_new_origin() {
        let mut f = ClockFollower::new(1e-3);
        f.observe(50 * MS);
        f.observe(60 * MS);
        (0..10).for_each(|_| f.stepped());
        assert_eq!(f.observe(5 * MS), ClockUpdate::Backwards);
        assert_eq!((f.due(), f.stamp_ns(), f.jumps_back()), (0, 5 * MS, 1));
        f.observe(7 * MS);
        assert_eq!(f.due(), 2);
    }

    #[test]
    fn a_jump_beyond_the_limit_re_anchors_instead_of_owing_its_steps() {
        let mut f = ClockFollower::new(1e-3).with_max_jump(1.0);
        f.observe(0);
        f.observe(500 * MS);
        assert_eq!(
            f.due(),
            500,
            "an advance within the limit is stepped through"
        );
        (0..500).for_each(|_| f.stepped());
        // 1e6 s ahead: 1e9 steps would be owed; none are, the stamps follow the clock.
        let t = 1_000_000 * 1_000 * MS;
        assert_eq!(
            f.observe(t),
            ClockUpdate::JumpedForward {
                gap_ns: t - 500 * MS
            }
        );
        assert_eq!((f.due(), f.stamp_ns(), f.jumps_forward()), (0, t, 1));
        f.observe(t + 3 * MS);
        assert_eq!(f.due(), 3);
        // Just within the limit: stepped through.
        f.observe(t + 3 * MS + 1_000 * MS);
        assert_eq!((f.due(), f.jumps_forward()), (1003, 1));
    }

    #[test]
    fn extreme_clock_times_neither_overflow_nor_owe_absurd_steps() {
        let mut f = ClockFollower::new(1e-3).with_max_jump(1.0);
        f.observe(i64::MIN);
        assert_eq!(
            f.observe(i64::MAX),
            ClockUpdate::JumpedForward { gap_ns: i64::MAX }
        );
        assert_eq!(f.due(), 0);
        assert_eq!(f.observe(i64::MIN), ClockUpdate::Backwards);
        assert_eq!(f.due(), 0);
    }
}
