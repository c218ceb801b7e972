//! Replays logged games, each under the rules it was played by ([`Game::variant`]: red for
//! Tenhou's logs), and compares every round with the log.
//!
//! All games of a rule set run side by side, one env each, on either backend: each logged round is
//! dealt from the wall [`super::plan`] rebuilds ([`Env::deal`]), the logged decisions are played
//! when the engine asks the logged seat (a claim prompt the log does not take is passed), and when
//! the engine ends the round its outcome (winners, han, fu, yaku, draw kind), score changes and
//! the table it moves on to (round, honba, sticks) are compared with the log (han, fu and yaku
//! only where the log gives them: an MJAI log from libriichi gives none).

mod compare;
mod report;
mod run;

use super::log::Game;
use compare::finish_round;
pub use report::{Mismatch, Report};
use rinshan_engine::env::{events, Backend, Config, Deal, Env, EnvError, Mode, Step, Table};
use rinshan_engine::gpu::Gpu;
use rinshan_engine::observe::Form;
use rinshan_engine::{with_variant, Variant};
use run::Run;

/// The length of the games: East only when every log's rule says so (`東`, as in `鳳東喰赤`),
/// else East and South. One replay plays one length: replay East and half games apart.
pub fn mode_of(games: &[Game]) -> Mode {
    mode_of_games(&games.iter().collect::<Vec<_>>())
}

fn mode_of_games(games: &[&Game]) -> Mode {
    if games.iter().all(|g| mode_of_rule(&g.rule) == Mode::East) {
        Mode::East
    } else {
        Mode::Half
    }
}

/// The length of a game by its rule's name: East only for `東` (`鳳東喰赤`), else East and South.
pub(crate) fn mode_of_rule(rule: &str) -> Mode {
    if rule.contains('東') {
        Mode::East
    } else {
        Mode::Half
    }
}

/// A decision of a logged game, as the replay is about to play it.
pub struct Decision<'a> {
    /// The game (index into the replayed games).
    pub game: usize,
    /// The game's index in `step` and `env`: the games of each rule set are replayed together in
    /// an env of that rule set, apart from the others.
    pub slot: usize,
    /// The round (index into the game's rounds).
    pub round: usize,
    /// The step before the decision: the deciding seat (`current_player`) and its legal mask.
    pub step: &'a Step,
    /// The action played: the log's move, or a pass at a claim prompt the log does not take.
    pub action: u32,
    /// The env, holding the deciding seat's observations in the forms the replay was asked for
    /// ([`Env::observation`]; game `game` is env `slot`).
    pub env: &'a Env,
}

/// What a replay shows its caller as it goes (the dataset builder records decisions through it).
/// A game whose replay finds a mismatch is still shown up to its end: the caller tells good games
/// from the report.
pub trait Visitor {
    /// A decision about to be played.
    fn decision(&mut self, d: &Decision);
    /// Game `game` ended by the rules: each seat's final place (0 = first, [`Step::ranks`]) and
    /// its table (final `scores`).
    fn game_over(&mut self, game: usize, ranks: [u8; 4], table: &Table);
}

struct Nothing;

impl Visitor for Nothing {
    fn decision(&mut self, _: &Decision) {}
    fn game_over(&mut self, _: usize, _: [u8; 4], _: &Table) {}
}

/// Replays `games` on `backend` (one env per game, all stepped together; the GPU backend opens
/// the first adapter).
pub fn replay(games: &[Game], backend: Backend) -> Result<Report, EnvError> {
    replay_in(games, backend, &[], &mut Nothing, Env::new)
}

/// As [`replay`], on an already opened GPU (the first rule set's games; another's open the first
/// adapter).
pub fn replay_on_gpu(games: &[Game], gpu: Gpu) -> Result<Report, EnvError> {
    let mut gpu = Some(gpu);
    // Games of a second rule set open the first adapter again (an env owns its GPU).
    replay_in(games, Backend::Gpu, &[], &mut Nothing, |config| match gpu.take() {
        Some(gpu) => Env::with_gpu(config, gpu),
        None => Env::new(config),
    })
}

/// As [`replay`] on the CPU with one thread, showing `visitor` every decision with the deciding
/// seat's observation in each of `observe`, and every game's end.
pub fn replay_visiting(games: &[Game], observe: &[Form], visitor: &mut dyn Visitor) -> Result<Report, EnvError> {
    replay_in(games, Backend::Cpu, observe, visitor, Env::new)
}

fn replay_in(
    games: &[Game],
    backend: Backend,
    observe: &[Form],
    visitor: &mut dyn Visitor,
    mut make_env: impl FnMut(Config) -> Result<Env, EnvError>,
) -> Result<Report, EnvError> {
    let mut report = Report {
        games: games.len(),
        ..Report::default()
    };
    for &variant in Variant::ALL {
        let picked: Vec<usize> = (0..games.len()).filter(|&g| games[g].variant == variant).collect();
        if !picked.is_empty() {
            let config = Config {
                observe: observe.to_vec(),
                ..Config::new(variant, picked.len())
            };
            replay_rule_set(games, &picked, backend, config, visitor, &mut make_env, &mut report)?;
        }
    }
    Ok(report)
}

/// Replays the games `picked` of one rule set, `config`'s variant, adding to `report`.
fn replay_rule_set(
    all: &[Game],
    picked: &[usize],
    backend: Backend,
    config: Config,
    visitor: &mut dyn Visitor,
    make_env: &mut impl FnMut(Config) -> Result<Env, EnvError>,
    report: &mut Report,
) -> Result<(), EnvError> {
    let games: Vec<&Game> = picked.iter().map(|&g| &all[g]).collect();
    let n = games.len();
    let variant = config.variant;
    let pass = with_variant!(variant, v => v::ACTION_PASS);
    let mut env = make_env(Config {
        mode: mode_of_games(&games),
        batch: n,
        backend,
        seed: 0,
        // Raw points at the end: logs have no uma.
        uma: Some([0; 4]),
        penalty: None,
        auto_reset: false,
        threads: Some(1),
        agents: Vec::new(),
        ..config
    })?;
    env.reset()?;
    let mut runs: Vec<Run> = games.iter().map(|g| Run::new(g, variant)).collect();
    let mut deals: Vec<Option<Deal>> = runs.iter_mut().map(|r| r.start_round(report)).collect();
    loop {
        if deals.iter().any(Option::is_some) {
            env.deal(&deals)?;
            deals.iter_mut().for_each(|d| *d = None);
        }
        if runs.iter().all(|r| r.finished) {
            break;
        }
        let step = env.last().clone();
        let mut actions = vec![pass; n];
        let mut redealt = false;
        for (i, run) in runs.iter_mut().enumerate() {
            actions[i] = step.legal_actions(i).next().unwrap_or(pass);
            if run.finished {
                continue;
            }
            match run.decide(&step, i) {
                Ok(a) => actions[i] = a,
                Err(m) => {
                    let m = *m;
                    // The rest of this round cannot be replayed; the next logged round is dealt
                    // from its own table, so one disagreement does not spoil the rest of the game.
                    report.mismatches.push(m);
                    run.round += 1;
                    deals[i] = run.start_round(report);
                    redealt = true;
                }
            }
        }
        if redealt {
            continue;
        }
        for (i, run) in runs.iter().enumerate() {
            if !run.finished {
                visitor.decision(&Decision {
                    game: picked[i],
                    slot: i,
                    round: run.round,
                    step: &step,
                    action: actions[i],
                    env: &env,
                });
            }
        }
        let after = env.step(&actions)?.clone();
        let mut ended = Vec::new();
        for (i, run) in runs.iter_mut().enumerate() {
            if run.finished {
                continue;
            }
            if run.consume(step.current_player[i] as usize, actions[i]) {
                report.actions_accepted += 1;
            }
            run.steps += 1;
            for p in 0..4 {
                run.change[p] += (after.rewards[i][p] * 100.0).round() as i64;
            }
            if after.events[i] & events::ROUND_OVER != 0 || after.terminated[i] {
                ended.push(i);
            }
        }
        if ended.is_empty() {
            continue;
        }
        let tables = env.tables()?;
        for i in ended {
            let run = &mut runs[i];
            finish_round(run, &after, i, &tables[i], report);
            if after.terminated[i] {
                visitor.game_over(picked[i], after.ranks[i], &tables[i]);
            }
            if !run.finished {
                run.round += 1;
                deals[i] = run.start_round(report);
            }
        }
    }
    Ok(())
}
