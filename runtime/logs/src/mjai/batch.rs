//! The MJAI bots of a batch of games (an env's): per game and seat, the bot playing it in the
//! current game, told every step and asked where its seat acts. Bots of different games work in
//! parallel (rayon); a game that ends gives its seats to the next game's bots.

use rayon::prelude::*;
use rinshan_engine::arena::{refused_action, Seat as _};
use rinshan_engine::generated::kernel::GameState;
use rinshan_engine::Variant;

use super::seat::{MjaiEntrant, MjaiSeat};

/// The bots of every game of a batch.
pub struct BatchBots {
    /// Per game and seat, the bot that plays it (None: the caller or a built-in agent).
    seating: Vec<[Option<MjaiEntrant>; 4]>,
    /// Per game and seat, the bot in the current game.
    seats: Vec<[Option<MjaiSeat>; 4]>,
    /// Each game's state now: after a step it is the state before the next one.
    states: Vec<GameState>,
    /// The games' rules.
    variant: Variant,
}

fn join(seating: &[Option<MjaiEntrant>; 4], state: &GameState, variant: Variant) -> [Option<MjaiSeat>; 4] {
    std::array::from_fn(|p| seating[p].as_ref().map(|e| e.start(p as u32, state, variant)))
}

impl BatchBots {
    /// The bots of `seating`, joining the games of `variant` that start in `states` (one per
    /// game).
    pub fn new(seating: Vec<[Option<MjaiEntrant>; 4]>, states: Vec<GameState>, variant: Variant) -> BatchBots {
        let mut bots = BatchBots {
            seats: Vec::new(),
            seating,
            states: Vec::new(),
            variant,
        };
        bots.restart(states);
        bots
    }

    /// New games in every env, starting in `states`: the bots of the old ones are stopped.
    pub fn restart(&mut self, states: Vec<GameState>) {
        self.seats = self
            .seating
            .par_iter()
            .zip(states.par_iter())
            .map(|(seating, s)| join(seating, s, self.variant))
            .collect();
        self.states = states;
    }

    /// Whether a bot plays seat `seat` of game `i`.
    pub fn plays(&self, i: usize, seat: u32) -> bool {
        self.seating
            .get(i)
            .and_then(|s| s.get(seat as usize))
            .is_some_and(Option::is_some)
    }

    /// Replaces the actions of the games whose current player is a bot by the bot's; returns
    /// the bots' faults (a bot that fails plays an illegal action: its game ends with the penalty).
    pub fn act(&mut self, actions: &mut [u32]) -> Vec<String> {
        self.seats
            .par_iter_mut()
            .zip(actions.par_iter_mut())
            .zip(self.states.par_iter())
            .enumerate()
            .filter_map(|(i, ((seats, a), s))| {
                // A finished game's state asks nothing (with auto-reset, `terminated` marks the
                // first state of the next game, which does ask).
                let seat = seats[s.current as usize].as_mut().filter(|_| s.mask != [0; 3])?;
                match seat.act(s) {
                    Ok(x) => *a = x,
                    Err(e) => {
                        *a = refused_action(&s.mask);
                        return Some(format!("env {i} seat {}: {e}", s.current));
                    }
                }
                None
            })
            .collect()
    }

    /// Tells every bot the step each game took to `after`; a finished game's bots give way to the
    /// next's (`ended`: the step ended the game; with auto-reset `after` is the next game's first
    /// state). Returns the bots' faults.
    pub fn stepped(&mut self, actions: &[u32], after: Vec<GameState>, ended: &[bool]) -> Vec<String> {
        let (seating, before, variant) = (&self.seating, &self.states, self.variant);
        let faults = self
            .seats
            .par_iter_mut()
            .enumerate()
            .flat_map_iter(|(i, seats)| {
                let mut out = Vec::new();
                for (p, seat) in seats.iter_mut().enumerate() {
                    if let Some(Err(e)) = seat.as_mut().map(|s| s.stepped(&before[i], actions[i], &after[i])) {
                        out.push(format!("env {i} seat {p}: {e}"));
                    }
                }
                if ended[i] {
                    *seats = join(&seating[i], &after[i], variant);
                }
                out
            })
            .collect();
        self.states = after;
        faults
    }
}
