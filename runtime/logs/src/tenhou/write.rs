//! Writes games played in rinshan (any rule set) as tenhou.net/6 logs, the format
//! [`super::log`] reads and `rinshan replay` replays.
//!
//! A [`Recorder`] follows every game of an [`Env`]: after each [`Env::step`], hand it the actions
//! (`observe`); it reads the games' states, turns each step into the entries Tenhou writes
//! (draws, calls, discards, kans, riichi) and, when a round ends, its result (yaku in Tenhou's
//! names and order, points text, score changes with honba, sticks and pao, draw names). Finished
//! games come out as [`Game`] values; [`game_text`] writes one as a file: one record per round,
//! one line each, as Tenhou does.
//!
//! ```no_run
//! use rinshan_engine::env::{Config, Env};
//! use rinshan_logs::tenhou::write::{game_text, Recorder};
//! let mut env = Env::new(Config::new(rinshan_engine::Variant::Red, 8)).unwrap();
//! env.reset().unwrap();
//! let mut recorder = Recorder::new(&env).unwrap();
//! # let actions = vec![0u32; 8];
//! env.step(&actions).unwrap();
//! recorder.observe(&env, &actions).unwrap();
//! for done in recorder.take_finished() {
//!     std::fs::write(format!("game-{}.json", done.env), game_text(&done.game)).unwrap();
//! }
//! ```
//!
//! Seats are rotated so that seat 0 is East 1's dealer, as in Tenhou's logs. A game that an
//! illegal action ended is left out (counted in [`Recorder::dropped`]). [`GameRecorder`] does the
//! same for one game stepped on the kernel directly (`generated::red::game_step`).
//!
//! A game of a rule set other than Tenhou's names it in the rule (`"variant":"mleague"`), so the
//! replay plays it under those rules; the moves are Tenhou's either way.

mod game;
mod json;
mod outcome;
mod round;
#[cfg(test)]
pub(crate) mod tests;

use std::fmt;

use rinshan_engine::env::{Env, EnvError};
use rinshan_engine::generated::kernel::GameState;

use super::log::Game;

pub use game::{GameRecorder, InPlay};
pub use json::game_text;
pub(crate) use json::round_value;
pub(crate) use outcome::{limit_of, points_text, win_yaku, yaku_list, Scoring};

/// Why a game could not be recorded.
#[derive(Debug, Clone, PartialEq)]
pub enum WriteError {
    /// Reading the env's states failed (the GPU backend).
    Env(EnvError),
    /// `observe` got a different number of actions than the env has games.
    WrongLength {
        /// The batch size.
        expected: usize,
        /// The actions given.
        got: usize,
    },
    /// A game's state cannot be followed (the recorder was made after the game's first step, or
    /// the env was reset or stepped without it), or contradicts what was recorded.
    State {
        /// The env whose game it is.
        env: usize,
        /// What does not fit.
        message: String,
    },
}

impl fmt::Display for WriteError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            WriteError::Env(e) => write!(f, "{e}"),
            WriteError::WrongLength { expected, got } => {
                write!(
                    f,
                    "{got} actions for a batch of {expected}: give the actions of the step just taken"
                )
            }
            WriteError::State { env, message } => write!(f, "env {env}: {message}"),
        }
    }
}

impl std::error::Error for WriteError {}

impl From<EnvError> for WriteError {
    fn from(e: EnvError) -> Self {
        WriteError::Env(e)
    }
}

/// A finished game and the env that played it.
#[derive(Debug, Clone, PartialEq)]
pub struct Finished {
    /// The env that played it.
    pub env: usize,
    /// The game's log.
    pub game: Game,
}

/// Records every game of an [`Env`] (either backend; on the GPU each `observe` reads
/// every game's state back from the device).
pub struct Recorder {
    games: Vec<GameRecorder>,
    states: Vec<GameState>,
    finished: Vec<Finished>,
}

fn states(env: &Env) -> Result<Vec<GameState>, WriteError> {
    let words = env.states_words()?;
    Ok(bytemuck::cast_slice::<u32, GameState>(&words).to_vec())
}

impl Recorder {
    /// Follows `env`'s games from where they stand, which must be the start of a round: call it
    /// right after [`Env::reset`] (or [`Env::reset_with_walls`], [`Env::deal`]), and again after
    /// any later reset.
    pub fn new(env: &Env) -> Result<Recorder, WriteError> {
        let variant = env.variant();
        let states = states(env)?;
        let games = states
            .iter()
            .enumerate()
            .map(|(env, s)| GameRecorder::for_variant(s, variant).map_err(|message| WriteError::State { env, message }))
            .collect::<Result<_, _>>()?;
        Ok(Recorder {
            games,
            states,
            finished: Vec::new(),
        })
    }

    /// Sets the player names written in every record (default `A`, `B`, `C`, `D`), by seat
    /// from East 1's dealer.
    pub fn set_names(&mut self, names: [String; 4]) {
        for g in &mut self.games {
            g.names = names.clone();
        }
    }

    /// Records the step `env` has just taken with `actions`.
    pub fn observe(&mut self, env: &Env, actions: &[u32]) -> Result<(), WriteError> {
        if actions.len() != self.games.len() {
            return Err(WriteError::WrongLength {
                expected: self.games.len(),
                got: actions.len(),
            });
        }
        let after = states(env)?;
        for (i, game) in self.games.iter_mut().enumerate() {
            let done = game
                .record(&self.states[i], actions[i], &after[i])
                .map_err(|message| WriteError::State { env: i, message })?;
            if let Some(game) = done {
                self.finished.push(Finished { env: i, game });
            }
        }
        self.states = after;
        Ok(())
    }

    /// The games finished since the last call, in the order they ended (env order within a step).
    pub fn take_finished(&mut self) -> Vec<Finished> {
        std::mem::take(&mut self.finished)
    }

    /// Games ended by an illegal action, which are not written.
    pub fn dropped(&self) -> usize {
        self.games.iter().map(GameRecorder::dropped).sum()
    }
}
