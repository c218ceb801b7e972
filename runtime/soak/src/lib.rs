//! rinshan-soak: many whole games under every check, behind `rinshan soak`. Each game is played on
//! the native kernel of its variant by the built-in agents (rotated over the seats) or a uniformly
//! random policy, and after every step the engine's invariants hold
//! ([`rinshan_engine::invariants`]), the action played was legal, and every so often the current
//! seat's observation does not change when everything it cannot see is resampled. At the end the
//! rewards add up to each seat's score change, and an east or half game, written as a Tenhou
//! log, reads back and replays through the engine under its rule set exactly. A violation is reported with the
//! game's seed and every action played, which repeat it, and its log when the log is what failed.
//!
//! Depends on `rinshan-engine` and `rinshan-logs` (the Tenhou log round trip).

#![warn(missing_docs)]

mod game;

use std::sync::atomic::{AtomicU64, Ordering};

use rayon::prelude::*;
use rinshan_engine::agents::Agent;
use rinshan_engine::env::{env_seed, Backend, Mode};
use rinshan_engine::Variant;
use rinshan_logs::tenhou::log::{parse_game, Game};
use rinshan_logs::tenhou::write::game_text;
use serde::Serialize;

/// Who plays.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Players {
    /// Four built-in agents, game `g` seating agent `(p + g) % 4` at seat `p`.
    Agents([Agent; 4]),
    /// A uniformly random legal action for every decision.
    Uniform,
}

impl std::fmt::Display for Players {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Players::Agents(a) => write!(f, "{}", a.map(|a| a.name()).join(",")),
            Players::Uniform => f.write_str("uniform"),
        }
    }
}

/// One soak: `games` games of one variant, length and set of players.
#[derive(Debug, Clone)]
pub struct Soak {
    /// The rules.
    pub variant: Variant,
    /// The length of each game.
    pub mode: Mode,
    /// Who plays.
    pub players: Players,
    /// Games to play.
    pub games: u64,
    /// Game `g` is dealt from `env_seed(seed, g, 0)`.
    pub seed: u64,
    /// Every this many decisions the deciding seat's observations are checked against hidden
    /// resampling (0: never).
    pub leak_every: u64,
}

/// A check that failed, with what repeats the game: its seed and the actions played.
#[derive(Debug, Clone, Serialize)]
pub struct Violation {
    /// The rules.
    pub variant: String,
    /// Who played.
    pub players: String,
    /// The game's index in the soak.
    pub game: u64,
    /// The game's 64-bit seed.
    pub seed: u64,
    /// Decisions played before the check failed.
    pub step: u64,
    /// What failed.
    pub what: String,
    /// Every action played, in order: with the seed, the game again.
    pub actions: Vec<u32>,
    /// The game as a tenhou.net/6 log, when the check that failed was on its log.
    #[serde(skip)]
    pub log: Option<String>,
}

/// What a soak did.
#[derive(Debug, Clone, Default, Serialize)]
pub struct Outcome {
    /// Games played.
    pub games: u64,
    /// Decisions played.
    pub steps: u64,
    /// Observations checked against hidden resampling.
    pub leak_checks: u64,
    /// Games written as Tenhou logs, read back and replayed.
    pub replayed: u64,
    /// Every failed check (at most one per game: a game stops at its first).
    pub violations: Vec<Violation>,
}

/// Games replayed through the engine together (the replay steps them as one batch).
const REPLAY_BATCH: usize = 64;

/// Plays the soak, in parallel on rayon's pool; `progress(games_done)` as games finish.
pub fn run(soak: &Soak, progress: &(dyn Fn(u64) + Sync)) -> Outcome {
    let done = AtomicU64::new(0);
    let starting = soak.variant.starting_points() as i32;
    let logged = soak.mode != Mode::Single;
    let chunks: Vec<Outcome> = (0..soak.games)
        .collect::<Vec<u64>>()
        .par_chunks(REPLAY_BATCH)
        .map(|chunk| {
            let mut out = Outcome::default();
            let mut logs: Vec<(u64, u64, Vec<u32>, Game)> = Vec::new();
            for &g in chunk {
                let seed = env_seed(soak.seed, g, 0);
                let played = game::play(soak, g, seed, starting, logged);
                out.games += 1;
                out.steps += played.actions.len() as u64;
                out.leak_checks += played.leak_checks;
                match played.failure {
                    Some((step, what)) => out
                        .violations
                        .push(violation(soak, g, seed, step, what, played.actions)),
                    None => {
                        if let Some(game) = played.log {
                            logs.push((g, seed, played.actions, game));
                        }
                    }
                }
                progress(done.fetch_add(1, Ordering::Relaxed) + 1);
            }
            round_trip(soak, logs, &mut out);
            out
        })
        .collect();
    let mut total = Outcome::default();
    for c in chunks {
        total.games += c.games;
        total.steps += c.steps;
        total.leak_checks += c.leak_checks;
        total.replayed += c.replayed;
        total.violations.extend(c.violations);
    }
    total.violations.sort_by_key(|v| v.game);
    total
}

fn violation(soak: &Soak, game: u64, seed: u64, step: u64, what: String, actions: Vec<u32>) -> Violation {
    Violation {
        variant: soak.variant.to_string(),
        players: soak.players.to_string(),
        game,
        seed,
        step,
        what,
        actions,
        log: None,
    }
}

/// A check on a finished game's log failed: the game, all its actions, and the log.
fn log_violation(soak: &Soak, game: u64, seed: u64, actions: Vec<u32>, log: String, what: String) -> Violation {
    Violation {
        log: Some(log),
        ..violation(soak, game, seed, actions.len() as u64, what, actions)
    }
}

/// Writes each finished game as a Tenhou log, reads it back (it must read as written) and replays
/// them all through the engine (every round must agree with the log).
fn round_trip(soak: &Soak, logs: Vec<(u64, u64, Vec<u32>, Game)>, out: &mut Outcome) {
    let mut read = Vec::new();
    let mut kept = Vec::new();
    for (g, seed, actions, game) in logs {
        let path = format!("game-{g}.json");
        let text = game_text(&game);
        match parse_game(&path, &text) {
            Ok(back)
                if back
                    == Game {
                        path: path.clone(),
                        ..game
                    } =>
            {
                read.push(back);
                kept.push((g, seed, actions, text));
            }
            Ok(_) => out.violations.push(log_violation(
                soak,
                g,
                seed,
                actions,
                text,
                "the Tenhou log reads back as another game".into(),
            )),
            Err(e) => out.violations.push(log_violation(
                soak,
                g,
                seed,
                actions,
                text,
                format!("the Tenhou log does not read back: {e}"),
            )),
        }
    }
    if read.is_empty() {
        return;
    }
    let report = match rinshan_logs::tenhou::replay::replay(&read, Backend::Cpu) {
        Ok(r) => r,
        Err(e) => {
            for (g, seed, actions, text) in kept {
                out.violations.push(log_violation(
                    soak,
                    g,
                    seed,
                    actions,
                    text,
                    format!("the replay failed: {e}"),
                ));
            }
            return;
        }
    };
    out.replayed += read.len() as u64;
    for (g, seed, actions, text) in kept {
        let path = format!("game-{g}.json");
        if let Some(m) = report.mismatches.iter().find(|m| m.file == path) {
            out.violations.push(log_violation(
                soak,
                g,
                seed,
                actions,
                text,
                format!("the Tenhou log does not replay: {m}"),
            ));
        }
    }
    if report.mismatches.is_empty() && report.games_ended_right != report.games {
        out.violations.push(violation(
            soak,
            0,
            soak.seed,
            0,
            format!(
                "{} of {} replayed games ended where their logs end",
                report.games_ended_right, report.games
            ),
            Vec::new(),
        ));
    }
}
