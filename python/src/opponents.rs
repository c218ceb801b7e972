//! Opponents the Python env asks in `step`, outside the kernel: MJAI bots
//! (`opponents="mjai:COMMAND"`: each game's other seats played by the bot, one process per seat
//! and game) and the look-ahead (`opponents="search"` or `"search:rollouts=N:..."`: it follows
//! every game and decides, in parallel, where its seats act) and trained nets (`opponents="net:PATH"`:
//! one forward pass per step for all the games where its seats act). The caller's action for an env
//! where an opponent acts is ignored (`info["hero"]` is False there).

use std::sync::{Arc, Mutex};
use std::time::Duration;

use pyo3::exceptions::{PyRuntimeError, PyRuntimeWarning, PyValueError};
use pyo3::prelude::*;
use rinshan_engine::env::{Backend, Env, EnvError, Mode};
use rinshan_engine::Variant;
use rinshan_logs::mjai::batch::BatchBots;
use rinshan_logs::mjai::bot::{check_games, wait, BotSpec, Dialect, Unplayable};
use rinshan_logs::mjai::seat::MjaiEntrant;
use rinshan_net::{BatchNet, Net, NetAgent};

use crate::env::{env_error, parse};

/// The most games an env with MJAI opponents may hold (three processes each).
pub(crate) const MAX_BOT_GAMES: usize = 256;

/// How the bots are run: `make`'s `mjai_dialect`, `mjai_timeout`, `mjai_startup`.
pub(crate) struct BotOptions<'a> {
    pub dialect: &'a str,
    pub timeout: f64,
    pub startup: f64,
}

/// The opponents of every env.
pub(crate) struct Opponents {
    players: Players,
    variant: Variant,
}

enum Players {
    Mjai {
        /// A pyclass is shared between threads: the bots' pipe receivers are not `Sync`, so they
        /// sit behind a lock (taken only by the env's `&mut` methods: never contended).
        bots: Option<Mutex<BatchBots>>,
        seating: Vec<[Option<MjaiEntrant>; 4]>,
    },
    Search {
        options: rinshan_search::Options,
        /// Per env, the seats it plays.
        seats: Vec<[bool; 4]>,
        /// Made at the first reset.
        batch: Option<rinshan_search::BatchSearch>,
    },
    Net {
        agent: NetAgent,
        seats: Vec<[bool; 4]>,
        /// Made at the first reset.
        batch: Option<BatchNet>,
    },
}

/// Per env, the seats other than its hero seat (`seats`: one for all, or one per env) at a table
/// of `variant`.
fn others(seats: &[u32], num_envs: usize, variant: Variant) -> Vec<[bool; 4]> {
    (0..num_envs)
        .map(|i| {
            let hero = seats[if seats.len() == 1 { 0 } else { i }];
            // A three-player game's fourth place is never played.
            std::array::from_fn(|p| p as u32 != hero && p < variant.seats() as usize)
        })
        .collect()
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
        let seating = others(seats, num_envs, variant)
            .into_iter()
            .map(|o| o.map(|plays| plays.then(|| entrant.clone())))
            .collect();
        Ok(Opponents {
            players: Players::Mjai { bots: None, seating },
            variant,
        })
    }

    /// The look-ahead `spec` (`search` or `search:rollouts=N:...`) at every seat but each env's
    /// hero seat.
    pub(crate) fn search(
        spec: &str,
        seats: &[u32],
        num_envs: usize,
        (variant, backend): (Variant, Backend),
    ) -> PyResult<Opponents> {
        let options: rinshan_search::Options = spec.parse().map_err(PyValueError::new_err)?;
        if backend != Backend::Cpu {
            return Err(PyValueError::new_err(
                "look-ahead opponents need backend=\"cpu\": they follow every game's state after every step",
            ));
        }
        Ok(Opponents {
            players: Players::Search {
                options,
                seats: others(seats, num_envs, variant),
                batch: None,
            },
            variant,
        })
    }

    /// The trained net exported at `path` (`net:PATH`) at every seat but each env's hero seat.
    pub(crate) fn net(
        path: &str,
        seats: &[u32],
        num_envs: usize,
        (variant, backend): (Variant, Backend),
    ) -> PyResult<Opponents> {
        if backend != Backend::Cpu {
            return Err(PyValueError::new_err(
                "net opponents need backend=\"cpu\": they read every game's state after every step",
            ));
        }
        let net = Net::load(path.trim()).map_err(|e| PyValueError::new_err(e.to_string()))?;
        let agent = NetAgent::new(Arc::new(net), variant).map_err(|e| PyValueError::new_err(e.to_string()))?;
        Ok(Opponents {
            players: Players::Net {
                agent,
                seats: others(seats, num_envs, variant),
                batch: None,
            },
            variant,
        })
    }

    /// New games in every env (after a reset): the bots of the old ones are stopped.
    pub(crate) fn restart(&mut self, py: Python<'_>, env: &Env) -> PyResult<()> {
        let states = env.game_states().map_err(env_error)?;
        let variant = self.variant;
        py.detach(|| match &mut self.players {
            Players::Mjai { bots: Some(b), .. } => b.get_mut().unwrap_or_else(|p| p.into_inner()).restart(states),
            Players::Mjai { bots, seating } => {
                *bots = Some(Mutex::new(BatchBots::new(seating.clone(), states, variant)))
            }
            Players::Search { batch: Some(b), .. } => b.restart(states),
            Players::Search { options, seats, batch } => {
                *batch = Some(rinshan_search::BatchSearch::new(
                    variant,
                    *options,
                    seats.clone(),
                    states,
                ))
            }
            Players::Net { agent, seats, batch } => *batch = Some(BatchNet::new(agent.clone(), seats.clone(), states)),
        });
        Ok(())
    }

    /// Puts the opponents' actions where they act; a failing bot's is illegal (its game ends with
    /// the penalty). Returns the failures, for [`warn`] once the step is taken.
    pub(crate) fn act(&mut self, py: Python<'_>, actions: &mut [u32]) -> PyResult<Vec<String>> {
        match &mut self.players {
            Players::Mjai { bots: Some(bots), .. } => {
                let bots = bots.get_mut().unwrap_or_else(|p| p.into_inner());
                Ok(py.detach(|| bots.act(actions)))
            }
            Players::Search { batch: Some(batch), .. } => {
                py.detach(|| batch.act(actions));
                Ok(Vec::new())
            }
            Players::Net { batch: Some(batch), .. } => {
                py.detach(|| batch.act(actions))
                    .map_err(|e| PyRuntimeError::new_err(e.to_string()))?;
                Ok(Vec::new())
            }
            _ => Err(PyValueError::new_err("reset the env before the first step")),
        }
    }

    /// Tells the opponents the step just taken; returns the failures, as `act` does.
    pub(crate) fn stepped(&mut self, py: Python<'_>, env: &Env, actions: &[u32]) -> PyResult<Vec<String>> {
        py.detach(|| -> Result<Vec<String>, EnvError> {
            match &mut self.players {
                Players::Mjai { bots: Some(bots), .. } => {
                    let bots = bots.get_mut().unwrap_or_else(|p| p.into_inner());
                    let after = env.game_states()?;
                    Ok(bots.stepped(actions, after, &env.last().terminated))
                }
                Players::Search { batch: Some(batch), .. } => {
                    batch.stepped(env.game_states()?, &env.last().terminated);
                    Ok(Vec::new())
                }
                Players::Net { batch: Some(batch), .. } => {
                    batch.stepped(env.game_states()?);
                    Ok(Vec::new())
                }
                _ => Ok(Vec::new()),
            }
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
