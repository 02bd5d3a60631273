//! Input subscriptions read by the simulation thread at step boundaries.
//!
//! Each input topic is a [`PolledInput`]: at a step boundary the loop takes
//! every sample waiting in the subscription's reader (`Subscription::take`,
//! no async task, no channel per sample), converts and checks it
//! (`ros/inputs.rs`) and applies them all, in DDS reception order, before the
//! step — where an input takes effect anyway. Rejections are counted and
//! logged as they are taken.

use super::inputs::{Input, InputStats, InputValidator, Rejection, Source};
use super::logging::Logger;
use super::services::Command;
use crate::messages::input_stats::RejectReason;
use ros2_client::Subscription;
use serde::de::DeserializeOwned;
use std::sync::Arc;

/// At most this many samples are taken from one topic per step boundary (a
/// reader that never runs dry cannot hold the loop).
pub const MAX_SAMPLES_PER_STEP: usize = 4096;

/// What every input topic shares.
#[derive(Clone)]
pub struct InputContext {
    pub validator: Arc<InputValidator>,
    pub stats: Arc<InputStats>,
    pub logger: Arc<Logger>,
}

impl InputContext {
    fn reject(&self, topic: &str, r: Rejection) {
        self.stats.reject(r.reason);
        self.logger.rejection(topic, &r);
    }
}

/// An input topic the loop reads at step boundaries.
pub trait PolledInput: Send {
    /// Take the waiting samples; hand each accepted one to `sink` with its
    /// DDS reception time (ns, 0 when unknown).
    fn drain(&mut self, sink: &mut dyn FnMut(i64, Command));
}

struct Polled<M: 'static, F> {
    sub: Subscription<M>,
    topic: String,
    source: Source,
    ctx: InputContext,
    check: F,
}

impl<M, F> PolledInput for Polled<M, F>
where
    M: DeserializeOwned + Send + 'static,
    F: Fn(&InputValidator, M) -> Result<(Input, i64), Rejection> + Send,
    Subscription<M>: Send,
{
    fn drain(&mut self, sink: &mut dyn FnMut(i64, Command)) {
        for _ in 0..MAX_SAMPLES_PER_STEP {
            match self.sub.take() {
                Ok(Some((msg, info))) => match (self.check)(&self.ctx.validator, msg) {
                    Ok((input, stamp)) => {
                        let received = info.received_timestamp().map_or(0, |t| t.to_nanos());
                        sink(received, Command::Input(input, self.source, stamp));
                    }
                    Err(r) => self.ctx.reject(&self.topic, r),
                },
                Ok(None) => return,
                Err(e) => self.ctx.reject(
                    &self.topic,
                    Rejection {
                        reason: RejectReason::Undecodable,
                        detail: format!("{e:?}"),
                    },
                ),
            }
        }
    }
}

/// The input topic `topic` read through `sub`: `check` converts and checks a
/// message into an input and its header stamp (ns, 0: none).
pub fn polled<M, F>(
    sub: Subscription<M>,
    topic: String,
    source: Source,
    ctx: InputContext,
    check: F,
) -> Box<dyn PolledInput>
where
    M: DeserializeOwned + Send + 'static,
    F: Fn(&InputValidator, M) -> Result<(Input, i64), Rejection> + Send + 'static,
    Subscription<M>: Send,
{
    Box::new(Polled {
        sub,
        topic,
        source,
        ctx,
        check,
    })
}
