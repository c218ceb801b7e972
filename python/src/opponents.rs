//! MJAI bots as the Python env's opponents (`opponents="mjai:COMMAND"`): each game's other seats
//! are played by the bot, one process per seat and game, asked in `step` where they act. The
//! caller's action for an env where a bot acts is ignored (`info["hero"]` is False there).

use std::sync::Mutex;
use std::time::Duration;

use pyo3::exceptions::{PyRuntimeWarning, PyValueError};
use pyo3::prelude::*;
use rinshan_engine::env::{Backend, Env, EnvError, Mode};
use rinshan_engine::Variant;
use rinshan_logs::mjai::batch::BatchBots;
use rinshan_logs::mjai::bot::{check_games, wait, BotSpec, Dialect, Unplayable};
use rinshan_logs::mjai::seat::MjaiEntrant;

use crate::env::{env_error, parse};

/// The most games an env with MJAI opponents may hold (three processes each).
pub(crate) const MAX_BOT_GAMES: usize = 256;

/// How the bots are run: `make`'s `mjai_dialect`, `mjai_timeout`, `mjai_startup`.
pub(crate) struct BotOptions<'a> {
    pub dialect: &'a str,
    pub timeout: f64,
    pub startup: f64,
}

/// The bots of every env, or an error saying why these games cannot have them.
pub(crate) struct Opponents {
    /// A pyclass is shared between threads: the bots' pipe receivers are not `Sync`, so they sit
    /// behind a lock (taken only by the env's `&mut` methods: never contended).
    bots: Option<Mutex<BatchBots>>,
    seating: Vec<[Option<MjaiEntrant>; 4]>,
    variant: Variant,
}

fn seconds(what: &str, s: f64) -> PyResult<Duration> {
    wait(s).ok_or_else(|| PyValueError::new_err(format!("{what} {s} is not a positive number of seconds")))
}

impl Opponents {
    /// The bot `command` at every seat but each env's hero seat (`seats`: one for all, or one per env).
    pub(crate) fn new(
        command: &str,
        seats: &[u32],
        num_envs: usize,
        (variant, mode, backend): (Variant, Mode, Backend),
        options: &BotOptions,
    ) -> PyResult<Opponents> {
        if command.trim().is_empty() {
            return Err(PyValueError::new_err(
                "opponents=\"mjai:COMMAND\" needs the bot's command line",
            ));
        }
        check_games(variant, mode, backend).map_err(|e| {
            PyValueError::new_err(match e {
                Unplayable::Rules => {
                    "MJAI opponents play Tenhou's rules (variant=\"red\", or \"sanma\" for three players) in east or half games"
                }
                Unplayable::Backend => {
                    "MJAI opponents need backend=\"cpu\": each bot follows its game's state after every step"
                }
            })
        })?;
        if num_envs > MAX_BOT_GAMES {
            return Err(PyValueError::new_err(format!(
                "num_envs {num_envs} with MJAI opponents would run {} bot processes; at most \
                 {MAX_BOT_GAMES} envs",
                3 * num_envs
            )));
        }
        let dialect: Dialect = parse("mjai_dialect", options.dialect)?;
        let entrant = MjaiEntrant {
            spec: BotSpec {
                command: command.to_string(),
                dialect,
                timeout: seconds("mjai_timeout", options.timeout)?,
                startup: seconds("mjai_startup", options.startup)?,
            },
        };
        let seating = (0..num_envs)
            .map(|i| {
                let hero = seats[if seats.len() == 1 { 0 } else { i }];
                // A three-player game's fourth place is never played.
                std::array::from_fn(|p| (p as u32 != hero && p < variant.seats() as usize).then(|| entrant.clone()))
            })
            .collect();
        Ok(Opponents {
            bots: None,
            seating,
            variant,
        })
    }

    /// New games in every env (after a reset): the bots of the old ones are stopped.
    pub(crate) fn restart(&mut self, py: Python<'_>, env: &Env) -> PyResult<()> {
        let states = env.game_states().map_err(env_error)?;
        let (bots, seating, variant) = (&mut self.bots, &self.seating, self.variant);
        py.detach(|| match bots {
            Some(b) => b.get_mut().unwrap_or_else(|p| p.into_inner()).restart(states),
            None => *bots = Some(Mutex::new(BatchBots::new(seating.clone(), states, variant))),
        });
        Ok(())
    }

    /// Puts the bots' actions where they act; a failing bot's is illegal (its game ends with
    /// the penalty). Returns the failures, for [`warn`] once the step is taken.
    pub(crate) fn act(&mut self, py: Python<'_>, actions: &mut [u32]) -> PyResult<Vec<String>> {
        let Some(bots) = self.bots.as_mut() else {
            return Err(PyValueError::new_err("reset the env before the first step"));
        };
        let bots = bots.get_mut().unwrap_or_else(|p| p.into_inner());
        Ok(py.detach(|| bots.act(actions)))
    }

    /// Tells the bots the step just taken; returns the failures, as `act` does.
    pub(crate) fn stepped(&mut self, py: Python<'_>, env: &Env, actions: &[u32]) -> PyResult<Vec<String>> {
        let Some(bots) = self.bots.as_mut() else {
            return Ok(Vec::new());
        };
        let bots = bots.get_mut().unwrap_or_else(|p| p.into_inner());
        py.detach(|| -> Result<Vec<String>, EnvError> {
            let after = env.game_states()?;
            Ok(bots.stepped(actions, after, &env.last().terminated))
        })
        .map_err(env_error)
    }
}

/// Reports the bots' failures as RuntimeWarnings. Called after the step: where warnings are
/// errors the first one raises, and the step it belongs to has been taken all the same (the bots
/// and the games stay in step).
pub(crate) fn warn(py: Python<'_>, faults: &[String]) -> PyResult<()> {
    for f in faults {
        let message =
            std::ffi::CString::new(format!("MJAI opponent failed: {f}").replace('\0', " ")).unwrap_or_default();
        PyErr::warn(py, &py.get_type::<PyRuntimeWarning>(), &message, 1)?;
    }
    Ok(())
}
