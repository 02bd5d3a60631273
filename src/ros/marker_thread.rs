//! `~/plate_marker` off the fixed-rate loop: the loop copies the amplitudes
//! and node forces into a pooled [`MarkerInput`] every `every` steps
//! ([`MarkerFeed::offer`], no allocation, never waits); this thread builds
//! the MarkerArray ([`PlateMarker`]), publishes it and, with `run --record`,
//! hands it to the bag writer. Should the thread still be busy with the
//! previous marker, the loop skips one (counted) rather than wait.

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
                if self.tx.try_send(input).is_err() {
                    self.skipped += 1;
                }
            }
            Err(_) => self.skipped += 1,
        }
    }
}

/// Start the marker thread for `sim`'s scene; it ends when the feed is dropped.
pub fn start(
    sim: &Simulation,
    marker: PlateMarker,
    every: u64,
    publisher: Publisher<Shared<MarkerArray>>,
    recorder: Option<Recorder>,
) -> std::io::Result<(MarkerFeed, JoinHandle<()>)> {
    let (tx, rx) = sync_channel::<MarkerInput>(1);
    let (pool_tx, pool) = channel::<MarkerInput>();
    for _ in 0..2 {
        let _ = pool_tx.send(MarkerInput::new(sim));
    }
    let join = std::thread::Builder::new()
        .name("annular_plate-marker".into())
        .spawn(move || serve(marker, rx, pool_tx, publisher, recorder))?;
    Ok((
        MarkerFeed {
            every,
            tx,
            pool,
            skipped: 0,
        },
        join,
    ))
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
