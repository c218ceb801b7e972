//! The games the server holds: a bounded map from id to session, with each game's driver task
//! (the agents' moves) and its change counter for the page's event stream.

use std::collections::HashMap;
use std::hash::BuildHasher as _;
use std::sync::{Arc, Mutex, MutexGuard};
use std::time::{Duration, Instant};

use tokio::sync::{watch, Notify};

use super::session::{Phase, Session, Setup};

/// How much the server keeps.
#[derive(Debug, Clone, Copy)]
pub struct Limits {
    /// Games held at once; a new game past it is refused (503) once idle ones are dropped.
    pub max_games: usize,
    /// A game nobody touched for this long is dropped.
    pub idle: Duration,
}

impl Default for Limits {
    fn default() -> Limits {
        Limits {
            max_games: 256,
            idle: Duration::from_secs(30 * 60),
        }
    }
}

/// One held game: the session, a wake-up for its driver, and a counter bumped on every change.
pub struct Held {
    session: Mutex<Session>,
    wake: Notify,
    changed: watch::Sender<u64>,
    closed: Mutex<bool>,
}

impl Held {
    /// The session, locked. A panic while it was held cannot leave a game half-stepped (the env
    /// steps whole), so a poisoned lock is taken over rather than failing every later request.
    pub fn lock(&self) -> MutexGuard<'_, Session> {
        self.session.lock().unwrap_or_else(|p| p.into_inner())
    }

    /// Tells the page and the driver that the game changed.
    pub fn changed(&self) {
        self.changed.send_modify(|n| *n += 1);
        self.wake.notify_one();
    }

    /// A receiver of the change counter.
    pub fn subscribe(&self) -> watch::Receiver<u64> {
        self.changed.subscribe()
    }

    fn is_closed(&self) -> bool {
        *self.closed.lock().unwrap_or_else(|p| p.into_inner())
    }

    fn close(&self) {
        *self.closed.lock().unwrap_or_else(|p| p.into_inner()) = true;
        self.wake.notify_one();
    }
}

/// The map of games.
#[derive(Clone)]
pub struct Store {
    games: Arc<Mutex<HashMap<u64, Arc<Held>>>>,
    next: Arc<Mutex<u64>>,
    keys: std::hash::RandomState,
    limits: Limits,
}

impl Store {
    pub fn new(limits: Limits) -> Store {
        Store {
            games: Arc::default(),
            next: Arc::new(Mutex::new(1)),
            keys: std::hash::RandomState::new(),
            limits,
        }
    }

    fn map(&self) -> MutexGuard<'_, HashMap<u64, Arc<Held>>> {
        self.games.lock().unwrap_or_else(|p| p.into_inner())
    }

    /// A new game, with its driver started; `Err(None)` when the server is full.
    pub fn create(&self, setup: Setup) -> Result<(u64, Arc<Held>), Option<String>> {
        self.sweep();
        let session = Session::new(setup).map_err(Some)?;
        let mut map = self.map();
        if map.len() >= self.limits.max_games {
            return Err(None);
        }
        let id = loop {
            let mut n = self.next.lock().unwrap_or_else(|p| p.into_inner());
            *n += 1;
            // The id is the counter hashed with this process's random SipHash keys: anyone can
            // play, read or drop a game whose id they know, so ids must not be guessable.
            let id = self.keys.hash_one(*n) >> 11;
            if !map.contains_key(&id) {
                break id;
            }
        };
        let (changed, _) = watch::channel(0);
        let held = Arc::new(Held {
            session: Mutex::new(session),
            wake: Notify::new(),
            changed,
            closed: Mutex::new(false),
        });
        map.insert(id, held.clone());
        drop(map);
        tokio::spawn(drive(held.clone()));
        Ok((id, held))
    }

    /// The game `id`, marked as touched.
    pub fn get(&self, id: u64) -> Option<Arc<Held>> {
        let held = self.map().get(&id).cloned()?;
        held.lock().touched = Instant::now();
        Some(held)
    }

    /// Drops the game `id`; `false` if there was none.
    pub fn remove(&self, id: u64) -> bool {
        let held = self.map().remove(&id);
        held.map(|h| h.close()).is_some()
    }

    /// Drops the games idle for longer than the limit.
    pub fn sweep(&self) {
        let idle = self.limits.idle;
        let mut map = self.map();
        map.retain(|_, h| {
            let keep = h.lock().touched.elapsed() < idle;
            if !keep {
                h.close();
            }
            keep
        });
    }
}

/// Plays a game's agent moves, each after the game's delay, until the game is dropped. A
/// spectated game also moves on past each round's result.
async fn drive(held: Arc<Held>) {
    loop {
        if held.is_closed() {
            return;
        }
        let (phase, delay, spectating) = {
            let s = held.lock();
            (s.phase(), s.setup().delay, s.human().is_none())
        };
        let due = match phase {
            Phase::Agent => Some(delay),
            Phase::Result if spectating => Some(delay * 4 + Duration::from_millis(500)),
            _ => None,
        };
        let Some(wait) = due else {
            held.wake.notified().await;
            continue;
        };
        if !wait.is_zero() {
            tokio::time::sleep(wait).await;
        } else {
            tokio::task::yield_now().await;
        }
        let moved = {
            let mut s = held.lock();
            match s.phase() {
                // An env error cannot be answered to anyone: the game stops where it is, saying so.
                Phase::Agent => s.agent_move().unwrap_or_else(|e| {
                    s.stop(&e);
                    true
                }),
                Phase::Result if spectating => s.next_round().is_ok(),
                _ => false,
            }
        };
        if moved {
            held.changed();
        }
    }
}
