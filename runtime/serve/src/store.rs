//! The games the server holds: a bounded map from id to session, with each game's driver task
//! (the agents' moves) and its change counter for the page's event stream. Games are bounded in
//! number, per client, in idle time (only a client's requests count as activity, not the agents'
//! moves) and in total duration; event streams are bounded per client.

use std::collections::HashMap;
use std::hash::BuildHasher as _;
use std::net::IpAddr;
use std::path::PathBuf;
use std::sync::{Arc, Mutex, MutexGuard};
use std::time::{Duration, Instant};

use tokio::sync::{watch, Notify};

use super::archive::Archive;
use super::bots::NamedBot;
use super::counted::{Counted, PerAddress};
use super::extract::network;
use super::replays::Replays;
use super::session::{Phase, Session, Setup};

/// How much the server keeps, and for whom. A client is an IP address; a network is an IPv4 /24
/// or an IPv6 /64 (what one machine or household can hold many addresses of).
#[derive(Debug, Clone)]
pub struct Limits {
    /// Games held at once; a new game past it is refused (503) once idle ones are dropped and no
    /// game without a person is left to make way.
    pub max_games: usize,
    /// Games one client (IP address) may hold at once; past it its new games are refused (429).
    pub games_per_client: usize,
    /// Games one network may hold at once (429 past it).
    pub games_per_network: usize,
    /// A game no client request touched for this long is dropped.
    pub idle: Duration,
    /// A game is dropped this long after it started, touched or not.
    pub max_duration: Duration,
    /// Event streams one client may hold open at once (429 past it).
    pub streams_per_client: usize,
    /// Connections served at once (lowered to what the descriptor limit leaves); further ones
    /// wait to be accepted. Held connections cost little (a task and a small buffer each), and
    /// every one that waits in the kernel's queue makes a newcomer wait: the cap is high.
    pub max_connections: usize,
    /// Connections one network may hold open; further ones are closed at once.
    pub connections_per_network: usize,
    /// A connection that has not sent a request's headers (or, HTTP/2, its preface) within this
    /// time is closed; so is an idle one, and an HTTP/2 peer that leaves a ping unanswered as long.
    pub header_timeout: Duration,
    /// A request's body must arrive, and its answer be ready, within this time (408 past it).
    pub request_timeout: Duration,
    /// MJAI bot processes running at once, server-wide (each bot seat of a game runs one).
    pub bot_processes: usize,
    /// MJAI bot processes one client's games may run at once.
    pub bot_processes_per_client: usize,
    /// Where finished games are written as Tenhou logs (`games/` inside); `None`: nowhere.
    pub data_dir: Option<PathBuf>,
    /// Saved games kept at most; past it (or past `saved_bytes`) the oldest are deleted.
    pub saved_games: usize,
    /// Bytes of saved games kept at most.
    pub saved_bytes: u64,
    /// Games one network's clients may have saved in any hour; past it a game is played but not
    /// kept (the game says so).
    pub saves_per_network_hour: usize,
    /// Every game deals from this seed instead of the OS random source: for tests and demos that
    /// must repeat a game (clients never choose the seed of a game they play in).
    pub fixed_seed: Option<u64>,
    /// The MJAI bots a game may seat, by name (each seat runs its own process of the command).
    pub bots: Vec<NamedBot>,
    /// The trained nets a game may seat, by name (`net:NAME`).
    pub nets: Vec<(String, Arc<rinshan_net::Net>)>,
    /// The look-ahead's play-outs per decision in a review on the page: a half game costs about
    /// 3 s of 2 cores at 256, and a review must be drawn within `request_timeout`.
    pub review_rollouts: u32,
}

impl Default for Limits {
    fn default() -> Limits {
        Limits {
            max_games: 256,
            games_per_client: 8,
            games_per_network: 16,
            idle: Duration::from_secs(30 * 60),
            max_duration: Duration::from_secs(4 * 60 * 60),
            streams_per_client: 16,
            max_connections: 16_384,
            connections_per_network: 64,
            header_timeout: Duration::from_secs(10),
            request_timeout: Duration::from_secs(30),
            bot_processes: 48,
            bot_processes_per_client: 6,
            data_dir: None,
            saved_games: 10_000,
            saved_bytes: 1 << 30,
            saves_per_network_hour: 120,
            fixed_seed: None,
            bots: Vec::new(),
            nets: Vec::new(),
            review_rollouts: 256,
        }
    }
}

/// Why a new game was refused.
#[derive(Debug)]
pub enum Refused {
    /// The setup cannot be played.
    Invalid(String),
    /// The server holds as many games as it may, none of which may make way (503).
    Full,
    /// The last part of the table is kept for networks that hold no game yet (503).
    Reserved(usize),
    /// This client holds as many games as it may.
    ClientFull(usize),
    /// This client's network holds as many games as it may.
    NetworkFull(usize),
    /// The game's MJAI bot processes would pass the client's share (429).
    ClientBots { running: usize, wanted: usize, cap: usize },
    /// The game's MJAI bot processes would pass the server's cap (503).
    ServerBots { running: usize, wanted: usize, cap: usize },
}

/// Why a game was not dropped on request.
#[derive(Debug, PartialEq, Eq)]
pub enum NotRemoved {
    /// No such game.
    Missing,
    /// Another client started it.
    NotYours,
}

/// One held game: the session, a wake-up for its driver, a counter bumped on every change, who
/// made it and when.
pub struct Held {
    session: Mutex<Session>,
    wake: Notify,
    changed: watch::Sender<u64>,
    closed: Mutex<bool>,
    client: IpAddr,
    /// Its MJAI bot seats (a process each).
    bots: usize,
    /// Whether a person sits at it (games without one are the first to make way).
    person: bool,
    created: Instant,
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
    limits: Arc<Limits>,
    archive: Option<Archive>,
    /// Open event streams per client.
    streams: PerAddress,
    replays: Replays,
}

impl Store {
    pub fn new(limits: Limits) -> Store {
        let limits_request_timeout = limits.request_timeout;
        Store {
            games: Arc::default(),
            next: Arc::new(Mutex::new(1)),
            keys: std::hash::RandomState::new(),
            archive: limits.data_dir.as_deref().map(|d| Archive::new(d, &limits)),
            limits: Arc::new(limits),
            streams: PerAddress::default(),
            // A replay waits for its turn at most a third of a request's time, leaving the rest
            // for the drawing.
            replays: Replays::new(limits_request_timeout / 3),
        }
    }

    /// Turns at the replay renderer.
    pub fn replays(&self) -> &Replays {
        &self.replays
    }

    /// The limits the store keeps.
    pub fn limits(&self) -> &Limits {
        &self.limits
    }

    /// The saved games, where a data directory is set.
    pub fn archive(&self) -> Option<&Archive> {
        self.archive.as_ref()
    }

    fn map(&self) -> MutexGuard<'_, HashMap<u64, Arc<Held>>> {
        self.games.lock().unwrap_or_else(|p| p.into_inner())
    }

    /// Whether `client` may start a game with `bots` MJAI bot seats now: checked before the game
    /// is built (building one costs more than refusing it), and again as it is stored. A full
    /// table first drops its idlest game without a person, or already over, to make way.
    /// Nothing is dropped here: a request that is refused later (a bad setup) must not have
    /// made anyone's game make way.
    pub fn admit(&self, client: IpAddr, bots: usize) -> Result<(), Refused> {
        self.sweep();
        self.admit_in(&mut self.map(), client, bots, false)
    }

    /// As [`Store::admit`]; with `evict`, a game that makes way is dropped, otherwise it is only
    /// found.
    fn admit_in(
        &self,
        map: &mut HashMap<u64, Arc<Held>>,
        client: IpAddr,
        bots: usize,
        evict: bool,
    ) -> Result<(), Refused> {
        let l = &*self.limits;
        let net = network(client);
        let (mut own, mut own_net, mut own_bots) = (0, 0, 0);
        for h in map.values() {
            if h.client == client {
                own += 1;
                own_bots += h.bots;
            }
            own_net += usize::from(network(h.client) == net);
        }
        if own >= l.games_per_client {
            return Err(Refused::ClientFull(own));
        }
        if own_net >= l.games_per_network {
            return Err(Refused::NetworkFull(own_net));
        }
        if own_bots + bots > l.bot_processes_per_client {
            return Err(Refused::ClientBots {
                running: own_bots,
                wanted: bots,
                cap: l.bot_processes_per_client,
            });
        }
        let mut games = map.len();
        if games >= l.max_games {
            if !make_way(map, evict) {
                return Err(Refused::Full);
            }
            games -= 1;
        }
        // A quarter of the table is kept for networks that hold no game, so that a few networks
        // cannot fill it for everyone who comes after. (The check without dropping may count
        // one game as making way twice; the check that drops is exact.)
        let reserve = l.max_games / 4;
        if reserve > 0 && own_net > 0 && games >= l.max_games - reserve && !make_way(map, evict) {
            return Err(Refused::Reserved(own_net));
        }
        let all_bots: usize = map.values().map(|h| h.bots).sum();
        if all_bots + bots > l.bot_processes {
            return Err(Refused::ServerBots {
                running: all_bots,
                wanted: bots,
                cap: l.bot_processes,
            });
        }
        Ok(())
    }

    /// A new game for `client`, with its driver started. The caller has checked [`Store::admit`]
    /// before building the setup.
    pub fn create(&self, setup: Setup, client: IpAddr) -> Result<(u64, Arc<Held>), Refused> {
        let bots = setup.bot_seats();
        let person = setup.seats.iter().any(Option::is_none);
        let session = Session::new(setup).map_err(Refused::Invalid)?;
        let mut map = self.map();
        // Checked again, now dropping a game to make way if one must: others may have come in
        // since the caller's `admit`.
        self.admit_in(&mut map, client, bots, true)?;
        let id = loop {
            let mut n = self.next.lock().unwrap_or_else(|p| p.into_inner());
            *n += 1;
            // The id is the counter hashed with this process's random SipHash keys: anyone can
            // play or read a game whose id they know, so ids must not be guessable.
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
            client,
            bots,
            person,
            created: Instant::now(),
        });
        map.insert(id, held.clone());
        drop(map);
        tokio::spawn(drive(held.clone(), self.archive.clone()));
        Ok((id, held))
    }

    /// Counts an event stream against `client` until the returned count is dropped (the client
    /// went away or the game ended); `None` when it holds as many as it may.
    pub fn open_stream(&self, client: IpAddr) -> Option<Counted> {
        self.streams.take(client, self.limits.streams_per_client)
    }

    /// The game `id`, marked as touched.
    pub fn get(&self, id: u64) -> Option<Arc<Held>> {
        let held = self.map().get(&id).cloned()?;
        held.lock().touched = Instant::now();
        Some(held)
    }

    /// Drops the game `id` at the request of `client`: only the client that started it may.
    pub fn remove(&self, id: u64, client: IpAddr) -> Result<(), NotRemoved> {
        let mut map = self.map();
        match map.get(&id) {
            None => Err(NotRemoved::Missing),
            Some(h) if h.client != client => Err(NotRemoved::NotYours),
            Some(_) => {
                if let Some(h) = map.remove(&id) {
                    h.close();
                }
                Ok(())
            }
        }
    }

    /// Drops the games idle for longer than the limit, and those held longer than the longest
    /// game.
    pub fn sweep(&self) {
        let (idle, longest) = (self.limits.idle, self.limits.max_duration);
        let mut map = self.map();
        map.retain(|_, h| {
            let keep = h.lock().touched.elapsed() < idle && h.created.elapsed() < longest;
            if !keep {
                h.close();
            }
            keep
        });
    }
}

/// Finds (and with `evict` drops) the idlest game that no person plays, or that is over, to make
/// way for a new one; `false` when every game has a person still playing.
fn make_way(map: &mut HashMap<u64, Arc<Held>>, evict: bool) -> bool {
    let idlest = map
        .iter()
        .filter_map(|(id, h)| {
            let s = h.lock();
            (!h.person || s.phase() == Phase::Over).then_some((s.touched, *id))
        })
        .min();
    let Some((_, id)) = idlest else { return false };
    if evict {
        if let Some(h) = map.remove(&id) {
            h.close();
        }
    }
    true
}

/// Runs `work` on a blocking thread, then hands its answer to the session with `done`; an error,
/// or a panic of `who`'s, stops the game where it is, saying so (it cannot go on without them).
async fn off_thread<T: Send + 'static>(
    held: &Held,
    work: impl FnOnce() -> T + Send + 'static,
    done: fn(&mut Session, T) -> Result<bool, String>,
    who: &str,
) {
    let answer = tokio::task::spawn_blocking(work).await;
    let moved = {
        let mut s = held.lock();
        match answer {
            Ok(answer) => done(&mut s, answer).unwrap_or_else(|e| {
                s.stop(&e);
                true
            }),
            Err(e) => {
                s.stop(&format!("{who} failed: {e}"));
                true
            }
        }
    };
    if moved {
        held.changed();
    }
}

/// Plays a game's agent moves, each after the game's delay, until the game is dropped. A
/// spectated game also moves on past each round's result. The MJAI bots hear each step as soon as
/// it is played and answer on a blocking thread, the session unlocked meanwhile (a bot may take
/// its whole timeout; the page is not held). Once the game is over its log is written to the
/// archive.
async fn drive(held: Arc<Held>, archive: Option<Archive>) {
    let mut saved = false;
    loop {
        if held.is_closed() {
            return;
        }
        if !saved {
            let log = held.lock().log().ok().map(str::to_string);
            if let (Some(log), Some(archive)) = (log, &archive) {
                saved = true;
                // Off the async threads: a slow disk must not stall other games.
                let archive = archive.clone();
                let net = network(held.client);
                let written = tokio::task::spawn_blocking(move || archive.save(net, &log)).await;
                if let Ok(Err(e)) | Err(e) = written.map_err(std::io::Error::other) {
                    held.lock().note(&format!("the game could not be saved: {e}"));
                }
            }
        }
        let (phase, delay, spectating, bots, claim) = {
            let s = held.lock();
            (
                s.phase(),
                s.setup().delay,
                s.human().is_none(),
                s.bot_due(),
                s.claim_pending(),
            )
        };
        let due = match phase {
            // Calls are considered out of sight: no pause shows that one was possible.
            Phase::Agent if claim => Some(Duration::ZERO),
            Phase::Agent => Some(delay),
            Phase::Result if spectating => Some(delay * 4 + Duration::from_millis(500)),
            _ if bots => Some(Duration::ZERO),
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
        // The bots answer, and the look-ahead thinks, on a blocking thread with the session
        // unlocked: other games and the page's requests go on meanwhile.
        let work = held.lock().bot_work();
        if let Some(work) = work {
            off_thread(&held, move || work.run(), Session::bot_done, "the MJAI bots").await;
            continue;
        }
        let thinking = held.lock().search_work();
        if let Some(thinking) = thinking {
            off_thread(&held, move || thinking.run(), Session::search_done, "the look-ahead").await;
            continue;
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
