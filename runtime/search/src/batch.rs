//! The look-ahead playing seats of a batch of games stepped by someone else (Python's env with
//! `opponents="search"`): it follows each game step by step, as an arena seat does, to know the
//! wall places its seats drew, and decides in parallel for the games whose seat to act is its.

use rayon::prelude::*;
use rinshan_engine::generated::kernel::GameState;
use rinshan_engine::observe::OwnDraws;
use rinshan_engine::Variant;

use crate::decide::Search;
use crate::options::Options;

/// One game's look-ahead seats.
#[derive(Clone)]
struct Game {
    /// The seats it plays.
    seats: [bool; 4],
    /// The state now: after a step, the state before the next one.
    state: GameState,
    /// Per seat, the wall places it drew this round.
    own: [OwnDraws; 4],
    /// Decisions taken in this game (seeds each one's worlds apart).
    decisions: u64,
    /// Games started in this slot (seeds each game's decisions apart).
    games: u64,
}

impl Game {
    fn start(&mut self, state: GameState, variant: Variant) {
        self.state = state;
        self.own = Default::default();
        for q in 0..variant.seats() {
            self.own[q as usize].update(variant, &state, &mut state.clone(), q);
        }
        self.decisions = 0;
        self.games += 1;
    }
}

/// The look-ahead at the chosen seats of every game of a batch.
#[derive(Clone)]
pub struct BatchSearch {
    search: Search,
    variant: Variant,
    games: Vec<Game>,
}

impl BatchSearch {
    /// The look-ahead of `options` at `seats` (per game, the seats it plays) of the games of
    /// `variant` that start in `states`.
    pub fn new(variant: Variant, options: Options, seats: Vec<[bool; 4]>, states: Vec<GameState>) -> BatchSearch {
        let games = seats
            .into_iter()
            .zip(states)
            .map(|(seats, state)| {
                let mut g = Game {
                    seats,
                    state,
                    own: Default::default(),
                    decisions: 0,
                    games: 0,
                };
                g.start(state, variant);
                g
            })
            .collect();
        BatchSearch {
            search: Search::new(variant, options),
            variant,
            games,
        }
    }

    /// New games in every slot, starting in `states`.
    pub fn restart(&mut self, states: Vec<GameState>) {
        let variant = self.variant;
        for (g, s) in self.games.iter_mut().zip(states) {
            g.start(s, variant);
        }
    }

    /// Whether the look-ahead plays seat `seat` of game `i`.
    pub fn plays(&self, i: usize, seat: u32) -> bool {
        self.games
            .get(i)
            .is_some_and(|g| g.seats.get(seat as usize) == Some(&true))
    }

    /// Replaces the actions of the games whose seat to act is the look-ahead's by its own.
    pub fn act(&mut self, actions: &mut [u32]) {
        let search = &self.search;
        self.games
            .par_iter_mut()
            .zip(actions.par_iter_mut())
            .enumerate()
            .for_each(|(i, (g, a))| {
                let s = &g.state;
                // A finished game's state asks nothing.
                if !g.seats[s.current as usize] || s.mask == [0; 3] {
                    return;
                }
                let nonce = (i as u64) << 48 ^ g.games << 32 ^ g.decisions;
                g.decisions += 1;
                *a = search
                    .decide(s, s.current, &g.own[s.current as usize].positions, nonce)
                    .action;
            });
    }

    /// Follows the step each game took to `after`; `ended`: the step ended the game (with
    /// auto-reset `after` is then the next game's first state).
    pub fn stepped(&mut self, after: Vec<GameState>, ended: &[bool]) {
        let variant = self.variant;
        for ((g, a), &end) in self.games.iter_mut().zip(after).zip(ended) {
            if end {
                g.start(a, variant);
                continue;
            }
            for q in 0..variant.seats() {
                g.own[q as usize].update(variant, &g.state, &mut a.clone(), q);
            }
            g.state = a;
        }
    }
}
