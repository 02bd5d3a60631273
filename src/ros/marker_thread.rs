//! `~/plate_marker` off the fixed-rate loop: the loop copies the amplitudes
//! and node forces into a pooled `MarkerInput` every `every` steps
//! ([`MarkerFeed::offer`], no allocation, never waits); this thread builds
//! the MarkerArray (`PlateMarker`), publishes it and, with `run --record`,
//! hands it to the bag writer. Two inputs circulate: a marker step that
//! comes while the thread is still building the previous marker, or has not
//! yet been scheduled to pick it up (`~/step` while paused runs its steps in
//! a burst), waits for it; only when one is being built and another already
//! waits does the loop skip a marker (counted) rather than wait.

use crate::bag::recorder::{Recorder, Sample};
use crate::dynamics::Simulation;
use crate::messages::marker::{MarkerInput, PlateMarker};
use crate::messages::outputs::Shared;
use crate::messages::types::Time;
use crate::messages::visualization::MarkerArray;
use ros2_client::Publisher;
use std::sync::mpsc::{channel, sync_channel, Receiver, Sender, SyncSender};
use std::thread::JoinHandle;

/// The loop's end.
pub struct MarkerFeed {
    every: u64,
    tx: SyncSender<MarkerInput>,
    pool: Receiver<MarkerInput>,
    /// Markers skipped because the thread was still busy.
    pub skipped: u64,
}

impl MarkerFeed {
    /// Hand the state over if this step is a marker step.
    pub fn offer(&mut self, sim: &Simulation, stamp: Time) {
        if !sim.step_count().is_multiple_of(self.every) {
            return;
        }
        match self.pool.try_recv() {
            Ok(mut input) => {
                input.capture(sim, stamp);
                // The queue holds every input there is, so it is never full
                // here: an error means the thread has ended.
                if self.tx.try_send(input).is_err() {
                    self.skipped += 1;
                }
            }
            // Both inputs are with the thread: one being built, one waiting.
            Err(_) => self.skipped += 1,
        }
    }
}

/// Inputs in circulation: one the thread builds from, one waiting for it.
const INPUTS: usize = 2;

/// The loop's end, the thread's queue and the pool it returns inputs to.
/// The queue has room for every input, so one taken from the pool is never
/// refused (and lost to the pool).
fn feed(sim: &Simulation, every: u64) -> (MarkerFeed, Receiver<MarkerInput>, Sender<MarkerInput>) {
    let (tx, rx) = sync_channel::<MarkerInput>(INPUTS);
    let (pool_tx, pool) = channel::<MarkerInput>();
    for _ in 0..INPUTS {
        let _ = pool_tx.send(MarkerInput::new(sim));
    }
    let feed = MarkerFeed {
        every,
        tx,
        pool,
        skipped: 0,
    };
    (feed, rx, pool_tx)
}

/// Start the marker thread for `sim`'s scene; it ends when the feed is dropped.
pub fn start(
    sim: &Simulation,
    marker: PlateMarker,
    every: u64,
    publisher: Publisher<Shared<MarkerArray>>,
    recorder: Option<Recorder>,
) -> std::io::Result<(MarkerFeed, JoinHandle<()>)> {
    let (feed, rx, pool_tx) = feed(sim, every);
    let join = std::thread::Builder::new()
        .name("annular_plate-marker".into())
        .spawn(move || serve(marker, rx, pool_tx, publisher, recorder))?;
    Ok((feed, join))
}

fn serve(
    mut marker: PlateMarker,
    rx: Receiver<MarkerInput>,
    pool: Sender<MarkerInput>,
    publisher: Publisher<Shared<MarkerArray>>,
    recorder: Option<Recorder>,
) {
    for input in rx {
        marker.update(&input);
        let _ = publisher.publish(marker.message().handle());
        if let Some(r) = &recorder {
            r.record(Sample::Marker(marker.message().handle()), input.stamp);
        }
        let _ = pool.send(input);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::config::Config;

    /// Steps `sim` to its next marker step and offers it, stamped with the step.
    fn step_and_offer(sim: &mut Simulation, feed: &mut MarkerFeed) {
        sim.step().unwrap();
        while !sim.step_count().is_multiple_of(feed.every) {
            sim.step().unwrap();
        }
        feed.offer(sim, Time::from_nanos(sim.step_count() as i64));
    }

    /// What the thread has been handed, by stamp; the inputs go back to the pool.
    fn drain(rx: &Receiver<MarkerInput>, pool: &Sender<MarkerInput>) -> Vec<i64> {
        rx.try_iter()
            .map(|input| {
                let stamp = input.stamp.to_nanos();
                pool.send(input).unwrap();
                stamp
            })
            .collect()
    }

    #[test]
    fn a_burst_of_marker_steps_waits_for_the_thread_and_a_skip_loses_no_input() {
        let mut sim = Simulation::new(Config::default()).unwrap();
        let (mut feed, rx, pool) = feed(&sim, 3);
        for round in 0..3 {
            // The thread has not run: two marker steps in a burst both wait
            // for it, a third is skipped.
            for _ in 0..3 {
                step_and_offer(&mut sim, &mut feed);
            }
            let n = sim.step_count() as i64;
            assert_eq!(drain(&rx, &pool), vec![n - 6, n - 3], "round {round}");
            assert_eq!(feed.skipped, round + 1, "round {round}");
        }
    }
}
