// Internal polling primitives for the two reactors (dp_event_loop and Discovery).
//
// Sockets are registered with mio 1.2. Everything that is not a socket — command
// queues, writer doorbells, reader commands, discovery sample readiness — shares
// one `Waker` per poll. `wake()` is coalesced (at most one eventfd write per
// loop iteration, see `LoopWaker`), so the token only means "drain the queues":
// the sender enqueues the payload (or entity id) and then wakes.
// Timers are an in-loop deadline map. The poll timeout is the sooner of the next
// deadline and the loop's idle cap. Nothing here is registered as a mio 0.6
// `Evented` source; user-visible sample and status channels stay mio-extras.

use std::{
  cell::RefCell,
  collections::BTreeMap,
  sync::{
    atomic::{AtomicBool, Ordering},
    mpsc, Arc, OnceLock,
  },
  time::{Duration, Instant},
};

use mio1::{Poll, Token, Waker};

use crate::structure::guid::EntityId;

/// One waker for one `Poll`. Share clones freely. `wake` before [`install`](Self::install)
/// is a no-op; the event loop drains its queues once after installing so anything
/// enqueued earlier is still observed.
///
/// Wakes are coalesced before the system call: `wake` writes the poll's eventfd
/// only when no earlier wake is still pending, i.e. not yet taken by the loop
/// with [`rearm`](Self::rearm). A thread publishing N samples between two
/// iterations of the loop therefore costs one `eventfd` write, not N. The loop
/// must call `rearm` after `poll` returns and before it drains its queues, so a
/// value enqueued after the drain looked is always followed by a real wake.
#[derive(Clone)]
pub(crate) struct LoopWaker {
  slot: Arc<OnceLock<Waker>>,
  pending: Arc<AtomicBool>,
}

impl LoopWaker {
  pub(crate) fn new() -> Self {
    Self {
      slot: Arc::new(OnceLock::new()),
      pending: Arc::new(AtomicBool::new(false)),
    }
  }

  /// Register the single waker of `poll` under `token`. Debug builds assert this
  /// happens once: mio 1.2 allows only one `Waker` per `Poll`.
  pub(crate) fn install(&self, poll: &Poll, token: Token) -> std::io::Result<()> {
    let waker = Waker::new(poll.registry(), token)?;
    if self.slot.set(waker).is_err() {
      debug_assert!(false, "LoopWaker::install called twice for one poll");
    }
    Ok(())
  }

  /// Wake the poll unless a wake is already pending. Call after enqueuing: the
  /// `AcqRel` swap publishes the enqueue to the loop's `rearm`. Inside
  /// [`defer_wakes`] the wake is held until that scope ends.
  pub(crate) fn wake(&self) {
    if !hold_wake(self) {
      self.wake_now();
    }
  }

  /// Wake the poll now, even inside [`defer_wakes`].
  pub(crate) fn wake_now(&self) {
    if let Some(waker) = self.slot.get() {
      if self.pending.swap(true, Ordering::AcqRel) {
        return; // the loop has not yet rearmed: it will drain what we enqueued
      }
      if let Err(e) = waker.wake() {
        self.pending.store(false, Ordering::Release);
        log::debug!("LoopWaker::wake: {e}");
      }
    }
  }

  /// Take the pending wake: called by the loop once per iteration, after `poll`
  /// returns and before it drains its queues. Anything enqueued before a wake
  /// that this swap observes is visible to the drain that follows; anything
  /// enqueued later wakes the poll again.
  pub(crate) fn rearm(&self) {
    self.pending.swap(false, Ordering::AcqRel);
  }
}

thread_local! {
  /// The wakes [`defer_wakes`] holds on this thread, one per poll (`None`
  /// outside such a scope).
  static HELD_WAKES: RefCell<Option<Vec<LoopWaker>>> = const { RefCell::new(None) };
}

/// Hold `waker`'s wake if this thread is inside [`defer_wakes`].
fn hold_wake(waker: &LoopWaker) -> bool {
  HELD_WAKES.with(|held| match held.try_borrow_mut().as_deref_mut() {
    Ok(Some(wakers)) => {
      if !wakers.iter().any(|w| Arc::ptr_eq(&w.pending, &waker.pending)) {
        wakers.push(waker.clone());
      }
      true
    }
    _ => false,
  })
}

/// Wake now every poll whose wake this thread holds (the scope stays open).
/// Called before a write blocks for room: the samples it waits on may be the
/// ones whose wake is held.
pub(crate) fn release_held_wakes() {
  let wakers = HELD_WAKES.with(|held| held.borrow_mut().as_mut().map(std::mem::take));
  for waker in wakers.into_iter().flatten() {
    waker.wake_now();
  }
}

/// Run `f`, holding back the event-loop wake-ups that its writes would cause
/// until it returns; then wake each participant's event loop once.
///
/// Every `DataWriter::write` wakes the participant's event-loop thread. A
/// thread that writes several samples in a row (a fixed-rate loop publishing
/// one sample per topic at every step) wakes it at the first write, and the
/// loop, running on another core or preempting the writer, often drains
/// before the next write and must be woken again: two or three thread
/// wake-ups per step instead of one. Inside `f` the samples are queued as
/// before and nothing is sent before `f` returns (a write that must block
/// for room releases the held wakes first). Nested calls belong to the
/// outermost one; the wakes are also released if `f` panics.
pub fn defer_wakes<R>(f: impl FnOnce() -> R) -> R {
  struct Release;
  impl Drop for Release {
    fn drop(&mut self) {
      release_held_wakes();
      HELD_WAKES.with(|held| *held.borrow_mut() = None);
    }
  }
  let outermost = HELD_WAKES.with(|held| {
    let mut held = held.borrow_mut();
    held.is_none() && {
      *held = Some(Vec::new());
      true
    }
  });
  let _release = outermost.then(|| Release); // (`then_some` would build, and drop, one for an inner scope)
  f()
}

/// Bounded queue whose send wakes `waker`'s poll.
pub(crate) struct WakeSender<T> {
  tx: mpsc::SyncSender<T>,
  waker: LoopWaker,
}

impl<T> Clone for WakeSender<T> {
  fn clone(&self) -> Self {
    Self {
      tx: self.tx.clone(),
      waker: self.waker.clone(),
    }
  }
}

impl<T> WakeSender<T> {
  pub(crate) fn try_send(&self, value: T) -> Result<(), mpsc::TrySendError<T>> {
    match self.tx.try_send(value) {
      Ok(()) => {
        self.waker.wake();
        Ok(())
      }
      Err(e) => Err(e),
    }
  }

  pub(crate) fn send(&self, value: T) -> Result<(), mpsc::SendError<T>> {
    match self.tx.send(value) {
      Ok(()) => {
        self.waker.wake();
        Ok(())
      }
      Err(e) => Err(e),
    }
  }

  /// Retry a full bounded send for a short time. Wakes the poll on success.
  pub(crate) fn try_send_timeout(
    &self,
    value: T,
    timeout: Duration,
  ) -> Result<(), mpsc::TrySendError<T>> {
    let mut value = value;
    match self.try_send(value) {
      Ok(()) => Ok(()),
      Err(mpsc::TrySendError::Disconnected(v)) => Err(mpsc::TrySendError::Disconnected(v)),
      Err(mpsc::TrySendError::Full(v)) => {
        value = v;
        let start = Instant::now();
        let mut delay = Duration::from_micros(1);
        while start.elapsed() < timeout {
          std::thread::sleep(delay);
          match self.try_send(value) {
            Ok(()) => return Ok(()),
            Err(mpsc::TrySendError::Full(v)) => {
              value = v;
              delay = (delay * 2).min(Duration::from_millis(2));
            }
            Err(other) => return Err(other),
          }
        }
        Err(mpsc::TrySendError::Full(value))
      }
    }
  }
}

pub(crate) struct WakeReceiver<T> {
  rx: mpsc::Receiver<T>,
}

impl<T> WakeReceiver<T> {
  pub(crate) fn try_recv(&self) -> Result<T, mpsc::TryRecvError> {
    self.rx.try_recv()
  }
}

pub(crate) fn wake_channel<T>(
  capacity: usize,
  waker: &LoopWaker,
) -> (WakeSender<T>, WakeReceiver<T>) {
  let (tx, rx) = mpsc::sync_channel(capacity);
  (
    WakeSender {
      tx,
      waker: waker.clone(),
    },
    WakeReceiver { rx },
  )
}

/// Unbounded queue whose send wakes `waker`'s poll. Used for stop commands.
#[derive(Clone)]
pub(crate) struct WakeUnboundedSender<T> {
  tx: mpsc::Sender<T>,
  waker: LoopWaker,
}

impl<T> WakeUnboundedSender<T> {
  pub(crate) fn send(&self, value: T) -> Result<(), mpsc::SendError<T>> {
    match self.tx.send(value) {
      Ok(()) => {
        self.waker.wake();
        Ok(())
      }
      Err(e) => Err(e),
    }
  }
}

pub(crate) fn wake_channel_unbounded<T>(
  waker: &LoopWaker,
) -> (WakeUnboundedSender<T>, WakeReceiver<T>) {
  let (tx, rx) = mpsc::channel();
  (
    WakeUnboundedSender {
      tx,
      waker: waker.clone(),
    },
    WakeReceiver { rx },
  )
}

/// Unbounded "something became ready" queue. The payload is the reason (an
/// entity id or a discovery token). Duplicate reasons in one drain are collapsed.
#[derive(Clone)]
pub(crate) struct ReadySender<T> {
  tx: mpsc::Sender<T>,
  waker: LoopWaker,
}

impl<T> ReadySender<T> {
  pub(crate) fn waker(&self) -> LoopWaker {
    self.waker.clone()
  }

  pub(crate) fn notify(&self, value: T) {
    if self.tx.send(value).is_ok() {
      self.waker.wake();
    }
  }
}

pub(crate) struct ReadyReceiver<T> {
  rx: mpsc::Receiver<T>,
}

impl<T: Eq> ReadyReceiver<T> {
  /// Drain every queued reason, keeping the first occurrence of each.
  pub(crate) fn drain_unique(&self) -> Vec<T> {
    let mut out = Vec::new();
    while let Ok(value) = self.rx.try_recv() {
      if !out.contains(&value) {
        out.push(value);
      }
    }
    out
  }
}

pub(crate) fn ready_channel<T>(waker: &LoopWaker) -> (ReadySender<T>, ReadyReceiver<T>) {
  let (tx, rx) = mpsc::channel();
  (
    ReadySender {
      tx,
      waker: waker.clone(),
    },
    ReadyReceiver { rx },
  )
}

/// Bounded command queue plus a shared ready-queue of entity ids. A successful
/// send records `entity_id` so the event loop, which has only one waker, knows
/// which endpoint to drain.
/// Reader commands are not sent today (`ResetRequestedDeadlineStatus` is
/// unimplemented). The sender stays so a future send still wakes the right
/// reader.
#[allow(dead_code)]
#[derive(Clone)]
pub(crate) struct BoundSender<T> {
  tx: WakeSender<T>,
  ready: ReadySender<EntityId>,
  entity_id: EntityId,
}

#[allow(dead_code)]
impl<T> BoundSender<T> {
  pub(crate) fn new(tx: WakeSender<T>, ready: ReadySender<EntityId>, entity_id: EntityId) -> Self {
    Self {
      tx,
      ready,
      entity_id,
    }
  }

  pub(crate) fn try_send(&self, value: T) -> Result<(), mpsc::TrySendError<T>> {
    self.tx.try_send(value)?;
    self.ready.notify(self.entity_id);
    Ok(())
  }
}

/// Writer doorbell. Ringing enqueues the writer's entity id and wakes the
/// participant poll. Replaces the mio 0.6 `Registration` previously registered
/// under the writer token.
#[derive(Clone)]
pub(crate) struct Doorbell {
  entity_id: EntityId,
  ready: ReadySender<EntityId>,
}

impl Doorbell {
  pub(crate) fn new(entity_id: EntityId, ready: ReadySender<EntityId>) -> Self {
    Self { entity_id, ready }
  }

  pub(crate) fn ring(&self) {
    self.ready.notify(self.entity_id);
  }
}

/// In-loop deadlines. Not registered with `Poll`. `set_timeout` / `poll` keep
/// the call pattern readers, writers, and tests already use. Deadlines are
/// absolute `Instant`s, so there is no timer-wheel tick to round them up.
pub(crate) struct Timer<E> {
  next_id: u64,
  deadlines: BTreeMap<(Instant, u64), E>,
}

impl<E> Timer<E> {
  pub(crate) fn new() -> Self {
    Self {
      next_id: 0,
      deadlines: BTreeMap::new(),
    }
  }

  pub(crate) fn set_timeout(&mut self, delay: Duration, event: E) {
    let when = Instant::now()
      .checked_add(delay)
      .unwrap_or_else(Instant::now);
    let id = self.next_id;
    self.next_id = self.next_id.wrapping_add(1);
    self.deadlines.insert((when, id), event);
  }

  /// The earliest event whose deadline has passed, if any.
  pub(crate) fn poll(&mut self) -> Option<E> {
    let key = *self.deadlines.keys().next()?;
    if key.0 <= Instant::now() {
      self.deadlines.remove(&key)
    } else {
      None
    }
  }

  pub(crate) fn next_deadline(&self) -> Option<Instant> {
    self.deadlines.keys().next().map(|(when, _)| *when)
  }
}

pub(crate) type SharedTimer<E> = std::rc::Rc<std::cell::RefCell<Timer<E>>>;

pub(crate) fn new_shared_timer<E>() -> SharedTimer<E> {
  std::rc::Rc::new(std::cell::RefCell::new(Timer::new()))
}

/// Poll timeout: the sooner of `deadline` and `cap`. A deadline already due
/// yields a zero timeout so the loop drains it immediately.
pub(crate) fn timeout_until(deadline: Option<Instant>, cap: Duration) -> Duration {
  match deadline {
    Some(when) => {
      let now = Instant::now();
      if when <= now {
        Duration::ZERO
      } else {
        (when - now).min(cap)
      }
    }
    None => cap,
  }
}

#[cfg(test)]
mod tests {
  use mio1::{Events, Poll, Token};

  use super::*;

  const TOKEN: Token = Token(7);

  // How many times `poll` reports the waker within a zero timeout, rearming
  // after each report as the event loop does.
  fn wakes(poll: &mut Poll, waker: &LoopWaker) -> usize {
    let mut events = Events::with_capacity(4);
    let mut count = 0;
    loop {
      poll.poll(&mut events, Some(Duration::ZERO)).unwrap();
      if events.is_empty() {
        return count;
      }
      count += events.iter().filter(|e| e.token() == TOKEN).count();
      waker.rearm();
    }
  }

  // Inside `defer_wakes` a wake writes nothing; at the end of the outermost
  // scope each poll is woken once, however many wakes were held.
  #[test]
  fn defer_wakes_holds_the_wakes_of_its_scope_and_wakes_each_poll_once_at_its_end() {
    let mut poll = Poll::new().unwrap();
    let waker = LoopWaker::new();
    waker.install(&poll, TOKEN).unwrap();
    defer_wakes(|| {
      waker.wake();
      waker.clone().wake();
      defer_wakes(|| waker.wake()); // nested: part of the outer scope
      assert_eq!(wakes(&mut poll, &waker), 0, "a wake escaped the scope");
    });
    assert_eq!(wakes(&mut poll, &waker), 1);
    // Outside any scope a wake is immediate again.
    waker.wake();
    assert_eq!(wakes(&mut poll, &waker), 1);
  }

  // A write about to block for room wakes the loop first (the samples it
  // waits on may be the held ones); the scope stays open.
  #[test]
  fn release_held_wakes_wakes_now_and_keeps_the_scope() {
    let mut poll = Poll::new().unwrap();
    let waker = LoopWaker::new();
    waker.install(&poll, TOKEN).unwrap();
    defer_wakes(|| {
      waker.wake();
      release_held_wakes();
      assert_eq!(wakes(&mut poll, &waker), 1);
      waker.wake();
      assert_eq!(wakes(&mut poll, &waker), 0, "the scope ended early");
    });
    assert_eq!(wakes(&mut poll, &waker), 1);
  }

  // A panic inside the scope still releases the held wakes.
  #[test]
  fn defer_wakes_releases_on_panic() {
    let mut poll = Poll::new().unwrap();
    let waker = LoopWaker::new();
    waker.install(&poll, TOKEN).unwrap();
    let result = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
      defer_wakes(|| {
        waker.wake();
        panic!("inside the scope");
      })
    }));
    assert!(result.is_err());
    assert_eq!(wakes(&mut poll, &waker), 1);
    waker.wake();
    assert_eq!(wakes(&mut poll, &waker), 1, "the scope outlived the panic");
  }
}
