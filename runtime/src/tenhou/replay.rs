//! Replays logged games through the red variant and compares every round with the log.
//!
//! All games of a replay run side by side, one env each, on either backend: each logged round is
//! dealt from the wall [`super::plan`] rebuilds ([`Env::deal`]), the logged decisions are played
//! when the engine asks the logged seat (a claim prompt the log does not take is passed), and when
//! the engine ends the round its outcome (winners, han, fu, yaku, draw kind), score changes and
//! the table it moves on to (round, honba, sticks) are compared with the log.

mod compare;

use serde::Serialize;

use super::log::{Game, Round};
use super::plan::{plan, Plan};
use crate::env::{events, Backend, Config, Deal, Env, EnvError, Mode, Step};
use crate::generated::red as k;
use crate::gpu::Gpu;
use crate::Variant;
use compare::{finish_round, outcome_name};

/// One disagreement between a log and rinshan.
#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
pub struct Mismatch {
    /// The log file.
    pub file: String,
    /// 1-based line of the round in the file.
    pub line: usize,
    /// `East 1, 0 honba`.
    pub round: String,
    /// Engine steps into the round when it was found.
    pub step: usize,
    /// What was compared, e.g. `score changes`.
    pub what: String,
    /// What the log says.
    pub log: String,
    /// What rinshan did.
    pub rinshan: String,
}

impl std::fmt::Display for Mismatch {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "{}:{} ({}), step {}: {}: log says {}; rinshan says {}",
            self.file, self.line, self.round, self.step, self.what, self.log, self.rinshan
        )
    }
}

/// Totals of a replay.
#[derive(Debug, Clone, Default, PartialEq, Eq, Serialize)]
pub struct Report {
    /// Games replayed.
    pub games: usize,
    /// Games that ended exactly where their log ends.
    pub games_ended_right: usize,
    /// Logged rounds.
    pub rounds: usize,
    /// Rounds whose every logged decision was legal and taken, ending where the log ends.
    pub rounds_replayed: usize,
    /// Logged decisions of the rounds that could be planned.
    pub actions: usize,
    /// Logged decisions the engine took.
    pub actions_accepted: usize,
    /// Rounds whose score change of every seat matches the log.
    pub score_changes_matching: usize,
    /// Rounds whose next table (round, dealer, honba, sticks, scores) matches the next logged round.
    pub tables_matching: usize,
    /// Rounds followed by another logged round.
    pub tables: usize,
    /// Logged wins.
    pub wins: usize,
    /// Wins whose winner, han, fu and yaku (with their han) match.
    pub wins_matching: usize,
    /// Logged rounds without a win.
    pub draws: usize,
    /// Drawn rounds that rinshan drew the same way.
    pub draws_matching: usize,
    /// Every disagreement, in the order found.
    pub mismatches: Vec<Mismatch>,
}

impl Report {
    /// Every count agrees: nothing was found wrong.
    pub fn all_agree(&self) -> bool {
        self.mismatches.is_empty()
            && self.games_ended_right == self.games
            && self.rounds_replayed == self.rounds
            && self.actions_accepted == self.actions
            && self.score_changes_matching == self.rounds
            && self.tables_matching == self.tables
            && self.wins_matching == self.wins
            && self.draws_matching == self.draws
    }
}

/// Where one game's replay stands.
struct Run<'g> {
    game: &'g Game,
    /// The round being played (index into `game.rounds`).
    round: usize,
    plan: Option<Plan>,
    next: usize,
    steps: usize,
    /// Engine score change of this round so far, in points.
    change: [i64; 4],
    finished: bool,
}

impl<'g> Run<'g> {
    fn round_log(&self) -> &'g Round {
        &self.game.rounds[self.round]
    }

    fn mismatch(&self, what: &str, log: impl Into<String>, rinshan: impl Into<String>) -> Mismatch {
        let r = self.round_log();
        Mismatch {
            file: self.game.path.clone(),
            line: r.line,
            round: super::log::round_name(r.kyoku, r.honba),
            step: self.steps,
            what: what.into(),
            log: log.into(),
            rinshan: rinshan.into(),
        }
    }

    /// Plans the current round (and the ones after it that cannot be planned are reported and
    /// skipped); the deal to start it, or `None` when the log has no round left.
    fn start_round(&mut self, report: &mut Report) -> Option<Deal> {
        while self.round < self.game.rounds.len() {
            let r = self.round_log();
            report.rounds += 1;
            self.next = 0;
            self.steps = 0;
            self.change = [0; 4];
            match plan(r) {
                Ok(p) => {
                    report.actions += p.moves.len();
                    let deal = p.deal(r);
                    self.plan = Some(p);
                    return Some(deal);
                }
                Err(e) => {
                    let m = self.mismatch("the log cannot be placed in turn order", e, "round not replayed");
                    report.mismatches.push(m);
                    self.round += 1;
                }
            }
        }
        self.finished = true;
        None
    }

    /// The action for the engine's prompt, without consuming the move.
    fn decide(&self, step: &Step, i: usize) -> Result<u32, Box<Mismatch>> {
        let seat = step.current_player[i] as usize;
        let mask = step.legal_action_mask[i];
        let legal = |a: u32| mask[(a / 32) as usize] >> (a % 32) & 1 == 1;
        let claim = legal(k::ACTION_PASS);
        let moves = self.plan.as_ref().map_or(&[][..], |p| p.moves.as_slice());
        let Some(m) = moves.get(self.next) else {
            if claim {
                return Ok(k::ACTION_PASS);
            }
            return Err(Box::new(self.mismatch(
                "round end",
                format!("the round ends here ({})", outcome_name(&self.round_log().outcome)),
                format!("seat {seat} is still to act"),
            )));
        };
        if claim && !(m.claim && m.seat == seat) {
            return Ok(k::ACTION_PASS);
        }
        if m.seat != seat || m.claim != claim {
            let asked = if claim { "a claim" } else { "its turn" };
            return Err(Box::new(self.mismatch(
                "turn order",
                format!("seat {}: {}", m.seat, m.what),
                format!("seat {seat} is asked for {asked}"),
            )));
        }
        if !legal(m.action) {
            return Err(Box::new(self.mismatch(
                "illegal logged action",
                format!("seat {}: {}", m.seat, m.what),
                format!(
                    "not legal; legal actions {:?}",
                    step.legal_actions(i).collect::<Vec<_>>()
                ),
            )));
        }
        Ok(m.action)
    }

    /// Moves past the logged decision `action` of `seat` just played; `false` for a pass the log
    /// does not list.
    fn consume(&mut self, seat: usize, action: u32) -> bool {
        let moves = self.plan.as_ref().map_or(&[][..], |p| p.moves.as_slice());
        let taken = moves
            .get(self.next)
            .is_some_and(|m| m.seat == seat && m.action == action);
        if taken {
            self.next += 1;
        }
        taken
    }
}

/// The length of the games: East only when every log's rule says so (`東`, as in `鳳東喰赤`),
/// else East and South. One replay plays one length: replay East and half games apart.
pub(crate) fn mode_of(games: &[Game]) -> Mode {
    if games.iter().all(|g| g.rule.contains('東')) {
        Mode::East
    } else {
        Mode::Half
    }
}

/// Replays `games` on `backend` (one env per game, all stepped together; the GPU backend opens
/// the first adapter).
pub fn replay(games: &[Game], backend: Backend) -> Result<Report, EnvError> {
    replay_in(games, backend, Env::new)
}

/// As [`replay`], on an already opened GPU.
pub fn replay_on_gpu(games: &[Game], gpu: Gpu) -> Result<Report, EnvError> {
    replay_in(games, Backend::Gpu, |config| Env::with_gpu(config, gpu))
}

fn replay_in(
    games: &[Game],
    backend: Backend,
    make_env: impl FnOnce(Config) -> Result<Env, EnvError>,
) -> Result<Report, EnvError> {
    let mut report = Report {
        games: games.len(),
        ..Report::default()
    };
    if games.is_empty() {
        return Ok(report);
    }
    let n = games.len();
    let mut env = make_env(Config {
        variant: Variant::Red,
        mode: mode_of(games),
        batch: n,
        backend,
        seed: 0,
        // Raw points at the end: logs have no uma.
        uma: Some([0; 4]),
        penalty: None,
        auto_reset: false,
        threads: Some(1),
        observe: Vec::new(),
        agents: Vec::new(),
    })?;
    env.reset()?;
    let mut runs: Vec<Run> = games
        .iter()
        .map(|game| Run {
            game,
            round: 0,
            plan: None,
            next: 0,
            steps: 0,
            change: [0; 4],
            finished: false,
        })
        .collect();
    let mut deals: Vec<Option<Deal>> = runs.iter_mut().map(|r| r.start_round(&mut report)).collect();
    loop {
        if deals.iter().any(Option::is_some) {
            env.deal(&deals)?;
            deals.iter_mut().for_each(|d| *d = None);
        }
        if runs.iter().all(|r| r.finished) {
            break;
        }
        let step = env.last().clone();
        let mut actions = vec![k::ACTION_PASS; n];
        let mut redealt = false;
        for (i, run) in runs.iter_mut().enumerate() {
            actions[i] = step.legal_actions(i).next().unwrap_or(k::ACTION_PASS);
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
                    deals[i] = run.start_round(&mut report);
                    redealt = true;
                }
            }
        }
        if redealt {
            continue;
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
            let round_over =
                after.events[i] & (events::RON | events::TSUMO | events::EXHAUSTIVE_DRAW | events::ABORTIVE_DRAW) != 0;
            if round_over || after.terminated[i] {
                ended.push(i);
            }
        }
        if ended.is_empty() {
            continue;
        }
        let tables = env.tables()?;
        for i in ended {
            let run = &mut runs[i];
            finish_round(run, &after, i, &tables[i], &mut report);
            if !run.finished {
                run.round += 1;
                deals[i] = run.start_round(&mut report);
            }
        }
    }
    Ok(report)
}
