//! Turns at the replay renderer. Drawing every decision of a game holds a core and tens of
//! megabytes for a while, so replays are drawn one at a time, in the order asked (tokio's
//! semaphore is first come, first served); a network has at most one replay waiting or being
//! drawn, and after one is drawn it waits as long as the drawing took before its next: a client
//! looping on many connections gets its fair share, not the renderer.

use std::collections::HashMap;
use std::net::IpAddr;
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

use tokio::sync::{OwnedSemaphorePermit, Semaphore};

/// The queue.
#[derive(Clone)]
pub struct Replays {
    drawing: Arc<Semaphore>,
    networks: Arc<Mutex<HashMap<IpAddr, Entry>>>,
    wait: Duration,
}

#[derive(Clone, Copy)]
enum Entry {
    /// Its replay waits or is being drawn.
    Busy,
    /// Its last replay was drawn; the next may start at this time.
    Resting(Instant),
}

/// Why a replay was not drawn now.
#[derive(Debug, PartialEq, Eq)]
pub enum NoTurn {
    /// The network's last replay is waiting or being drawn (429).
    Busy,
    /// The network's last replay cost this much more waiting (429).
    Resting(Duration),
    /// The queue did not reach this replay in time (503).
    Queue(Duration),
}

/// A turn at the renderer, held while drawing; its cost is counted against the network when it
/// is dropped.
pub struct Turn {
    _permit: OwnedSemaphorePermit,
    networks: Arc<Mutex<HashMap<IpAddr, Entry>>>,
    net: IpAddr,
    started: Instant,
}

impl Drop for Turn {
    fn drop(&mut self) {
        let cost = self.started.elapsed();
        let mut map = self.networks.lock().unwrap_or_else(|p| p.into_inner());
        map.insert(self.net, Entry::Resting(Instant::now() + cost));
    }
}

impl Replays {
    /// A queue in which a replay waits at most `wait` for its turn.
    pub fn new(wait: Duration) -> Replays {
        Replays {
            drawing: Arc::new(Semaphore::new(1)),
            networks: Arc::default(),
            wait,
        }
    }

    /// Waits for `net`'s turn to draw a replay.
    pub async fn turn(&self, net: IpAddr) -> Result<Turn, NoTurn> {
        {
            let now = Instant::now();
            let mut map = self.networks.lock().unwrap_or_else(|p| p.into_inner());
            map.retain(|_, e| !matches!(e, Entry::Resting(until) if *until <= now));
            match map.get(&net) {
                Some(Entry::Busy) => return Err(NoTurn::Busy),
                Some(Entry::Resting(until)) => return Err(NoTurn::Resting(until.duration_since(now))),
                None => map.insert(net, Entry::Busy),
            };
        }
        match tokio::time::timeout(self.wait, self.drawing.clone().acquire_owned()).await {
            Ok(Ok(permit)) => Ok(Turn {
                _permit: permit,
                networks: self.networks.clone(),
                net,
                started: Instant::now(),
            }),
            _ => {
                self.networks.lock().unwrap_or_else(|p| p.into_inner()).remove(&net);
                Err(NoTurn::Queue(self.wait))
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn net(n: u8) -> IpAddr {
        IpAddr::V4(std::net::Ipv4Addr::new(10, 0, n, 0))
    }

    #[tokio::test]
    async fn one_turn_per_network_and_its_cost_is_waited_out() {
        let q = Replays::new(Duration::from_secs(5));
        let first = q.turn(net(1)).await.expect("a turn");
        assert_eq!(q.turn(net(1)).await.err(), Some(NoTurn::Busy));
        // Another network queues behind the drawing and gets the next turn.
        let q2 = q.clone();
        let other = tokio::spawn(async move { q2.turn(net(2)).await.map(|_| ()) });
        tokio::time::sleep(Duration::from_millis(200)).await;
        drop(first);
        assert_eq!(other.await.expect("joined"), Ok(()));
        // The first network drew for 200 ms: it rests about as long.
        match q.turn(net(1)).await.err() {
            Some(NoTurn::Resting(left)) => assert!(left > Duration::from_millis(100), "{left:?}"),
            other => panic!("{other:?}"),
        }
        tokio::time::sleep(Duration::from_millis(250)).await;
        assert!(q.turn(net(1)).await.is_ok(), "rested");
    }

    #[tokio::test]
    async fn a_replay_waits_its_bound_and_no_longer() {
        let q = Replays::new(Duration::from_millis(100));
        let _held = q.turn(net(1)).await.expect("a turn");
        assert_eq!(
            q.turn(net(2)).await.err(),
            Some(NoTurn::Queue(Duration::from_millis(100)))
        );
        // Its network is not left marked busy.
        assert_eq!(
            q.turn(net(2)).await.err(),
            Some(NoTurn::Queue(Duration::from_millis(100)))
        );
    }
}
