// Step-aligned reception of user traffic (annular_plate PATCH.md §16).
//
// A participant's event loop reads its user-traffic sockets as datagrams
// arrive: one thread wake-up per datagram, or per few, when a peer writes
// many samples on many topics in a burst (each writer's sample is its own
// datagram). An application that consumes its samples only at fixed points
// — a fixed-rate loop taking its inputs at each step — gains nothing from
// that: the samples wait in the topic cache for the step anyway.
//
// An *engaged* gate takes the user-traffic sockets out of the event loop's
// poll. Datagrams then wait in the socket's kernel buffer until the
// application calls `receive_now` (right before it takes its samples), which
// has the loop read and handle them all in one wake-up, or until the gate has
// held them for `RECEIVE_GATE_MAX_HOLD`, after which the loop reads them on
// its own (services, acknowledgements and heartbeats are never left waiting
// longer than that). A released gate puts the sockets back in the poll; one
// never engaged changes nothing. Discovery traffic is not gated.

use std::{
  sync::{
    atomic::{AtomicBool, AtomicU64, Ordering},
    Arc, Condvar, Mutex,
  },
  time::{Duration, Instant},
};

use crate::polling::LoopWaker;

/// The longest an engaged gate leaves user datagrams unread when nobody calls
/// [`ReceiveGate::receive_now`].
pub const RECEIVE_GATE_MAX_HOLD: Duration = Duration::from_millis(2);

#[derive(Default)]
struct Shared {
  engaged: AtomicBool,
  /// Tickets handed out by `receive_now`.
  requested: AtomicU64,
  /// The newest ticket whose datagrams the loop has handled.
  served: Mutex<u64>,
  served_changed: Condvar,
}

/// The handle an application uses to align the reception of user traffic with
/// the points where it takes its samples. Clones share one gate.
#[derive(Clone)]
pub struct ReceiveGate {
  shared: Arc<Shared>,
  waker: LoopWaker,
}

impl ReceiveGate {
  pub(crate) fn new(waker: LoopWaker) -> Self {
    Self {
      shared: Arc::new(Shared::default()),
      waker,
    }
  }

  /// Engage (`true`) or release the gate. While engaged, user datagrams are
  /// read at [`receive_now`](Self::receive_now) or after at most
  /// [`RECEIVE_GATE_MAX_HOLD`]; released, as they arrive.
  pub fn set_engaged(&self, engaged: bool) {
    if self.shared.engaged.swap(engaged, Ordering::AcqRel) != engaged {
      self.waker.wake_now();
    }
  }

  pub fn is_engaged(&self) -> bool {
    self.shared.engaged.load(Ordering::Acquire)
  }

  /// Have the event loop read and handle every datagram waiting on the
  /// user-traffic sockets, and wait until it has: the samples they carried
  /// are then in their readers' caches. False if `timeout` passed first.
  pub fn receive_now(&self, timeout: Duration) -> bool {
    let ticket = self.shared.requested.fetch_add(1, Ordering::AcqRel) + 1;
    self.waker.wake_now();
    let deadline = Instant::now() + timeout;
    let mut served = self.shared.served.lock().unwrap_or_else(|e| e.into_inner());
    while *served < ticket {
      let now = Instant::now();
      if now >= deadline {
        return false;
      }
      served = self
        .shared
        .served_changed
        .wait_timeout(served, deadline - now)
        .unwrap_or_else(|e| e.into_inner())
        .0;
    }
    true
  }

  pub(crate) fn loop_side(&self) -> GateLoopSide {
    GateLoopSide {
      shared: Arc::clone(&self.shared),
      held: false,
      served: 0,
      last_read: Instant::now(),
    }
  }
}

/// What the loop does about the user-traffic sockets in one iteration.
#[derive(Debug, PartialEq, Eq)]
pub(crate) enum GateAction {
  /// Nothing: the sockets are in the poll (released) or still held.
  None,
  /// Take the sockets out of the poll (the gate was engaged).
  Hold,
  /// Put them back (the gate was released).
  Release,
  /// Read them now; then report `Some(ticket)` served.
  Read(Option<u64>),
}

/// The event loop's side of a [`ReceiveGate`].
pub(crate) struct GateLoopSide {
  shared: Arc<Shared>,
  /// The sockets are out of the poll.
  held: bool,
  served: u64,
  last_read: Instant,
}

impl GateLoopSide {
  /// The next thing to do (call until it returns `None`, after each poll).
  pub(crate) fn next_action(&mut self, now: Instant) -> GateAction {
    let engaged = self.shared.engaged.load(Ordering::Acquire);
    if engaged && !self.held {
      self.held = true;
      self.last_read = now;
      return GateAction::Hold;
    }
    if !engaged && self.held {
      self.held = false;
      return GateAction::Release;
    }
    let requested = self.shared.requested.load(Ordering::Acquire);
    if requested != self.served {
      return GateAction::Read(Some(requested));
    }
    if self.held && now >= self.last_read + RECEIVE_GATE_MAX_HOLD {
      return GateAction::Read(None);
    }
    GateAction::None
  }

  /// The sockets were read at `now`; wake whoever waits for `ticket`.
  pub(crate) fn did_read(&mut self, now: Instant, ticket: Option<u64>) {
    self.last_read = now;
    if let Some(ticket) = ticket {
      self.served = ticket;
      let mut served = self.shared.served.lock().unwrap_or_else(|e| e.into_inner());
      *served = (*served).max(ticket);
      self.shared.served_changed.notify_all();
    }
  }

  /// When the held sockets must be read at the latest (None: not held).
  pub(crate) fn deadline(&self) -> Option<Instant> {
    self.held.then(|| self.last_read + RECEIVE_GATE_MAX_HOLD)
  }
}

#[cfg(test)]
mod tests {
  use super::*;

  #[test]
  fn an_engaged_gate_holds_then_reads_on_request_and_after_the_hold() {
    let gate = ReceiveGate::new(LoopWaker::new());
    let mut side = gate.loop_side();
    let t0 = Instant::now();
    assert_eq!(side.next_action(t0), GateAction::None);
    assert_eq!(side.deadline(), None);
    gate.set_engaged(true);
    assert_eq!(side.next_action(t0), GateAction::Hold);
    assert_eq!(side.next_action(t0), GateAction::None);
    assert_eq!(side.deadline(), Some(t0 + RECEIVE_GATE_MAX_HOLD));
    // Nobody asks: read once the hold is over, and hold again from there.
    let t1 = t0 + RECEIVE_GATE_MAX_HOLD;
    assert_eq!(side.next_action(t1), GateAction::Read(None));
    side.did_read(t1, None);
    assert_eq!(side.next_action(t1), GateAction::None);
    assert_eq!(side.deadline(), Some(t1 + RECEIVE_GATE_MAX_HOLD));
    gate.set_engaged(false);
    assert_eq!(side.next_action(t1), GateAction::Release);
    assert_eq!(side.next_action(t1 + 10 * RECEIVE_GATE_MAX_HOLD), GateAction::None);
    assert_eq!(side.deadline(), None);
  }

  #[test]
  fn receive_now_returns_once_the_loop_has_read_for_its_ticket() {
    let gate = ReceiveGate::new(LoopWaker::new());
    let mut side = gate.loop_side();
    gate.set_engaged(true);
    let loop_thread = std::thread::spawn(move || {
      // The event loop: hold, then serve the first request it sees.
      let start = Instant::now();
      loop {
        match side.next_action(Instant::now()) {
          GateAction::Read(Some(ticket)) => {
            side.did_read(Instant::now(), Some(ticket));
            return ticket;
          }
          _ if start.elapsed() > Duration::from_secs(5) => return 0,
          _ => std::thread::sleep(Duration::from_micros(100)),
        }
      }
    });
    assert!(gate.receive_now(Duration::from_secs(5)));
    assert_eq!(loop_thread.join().unwrap(), 1);
    // Nobody serves the second ticket: the wait ends at its timeout.
    let t = Instant::now();
    assert!(!gate.receive_now(Duration::from_millis(20)));
    assert!(t.elapsed() >= Duration::from_millis(20));
  }
}
