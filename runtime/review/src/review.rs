//! A player's decisions valued by the look-ahead.
//!
//! Each decision is judged by [`Search::appraise`] with the action played kept through the
//! halving: the best other action then meets it in worlds that played no part in choosing that
//! action, so the loss is not inflated by picking the luckiest of many estimates. A decision is a
//! mistake when that paired loss is `margin` standard errors above zero (the look-ahead's own
//! rule for playing other than its base agent): a loss within the noise is reported, but not
//! counted against the player.

use rayon::prelude::*;
use rinshan_engine::env::action_names;
use rinshan_engine::generated::kernel::GameState;
use rinshan_logs::tenhou::log::Game;
use rinshan_logs::tenhou::position::{own_draws, round_positions};
use rinshan_search::{Candidate, Options, Search};
use serde::Serialize;

/// A decision of the reviewed seat with a choice, replayed.
#[derive(Clone)]
pub struct Spot {
    /// The round: index into the log's rounds.
    pub round: usize,
    /// The decision within the round (every seat's, claim prompts included; as `rinshan observe
    /// --step` counts them).
    pub step: usize,
    /// The action the log played.
    pub action: u32,
    /// What the log says for it.
    pub what: String,
    /// The state before it.
    pub state: GameState,
    /// The wall places the seat drew this round up to it.
    pub own_draws: Vec<u32>,
}

/// The decisions of `seat` in `game` with two or more legal actions, in order of play (in round
/// `round` only, where given: an index into the log's rounds).
pub fn spots(game: &Game, seat: u32, round: Option<usize>) -> Result<Vec<Spot>, String> {
    let variant = game.variant;
    if seat >= variant.seats() {
        return Err(format!(
            "seat {seat}: a {}-player game has seats 0..{}",
            variant.seats(),
            variant.seats() - 1
        ));
    }
    if let Some(r) = round.filter(|&r| r >= game.rounds.len()) {
        return Err(format!(
            "{}: no round {r} (the log has {})",
            game.path,
            game.rounds.len()
        ));
    }
    let mut out = Vec::new();
    for round in (0..game.rounds.len()).filter(|&r| round.is_none_or(|only| only == r)) {
        let positions = round_positions(game, round)?;
        for (p, own_draws) in positions.iter().zip(own_draws(variant, &positions, seat)) {
            let choices: u32 = p.state.mask.iter().map(|w| w.count_ones()).sum();
            if p.seat == seat && choices >= 2 {
                out.push(Spot {
                    round,
                    step: p.step,
                    action: p.action,
                    what: p.what.clone(),
                    state: p.state,
                    own_draws,
                });
            }
        }
    }
    Ok(out)
}

/// The seat to review: `seat` itself, or that of the player called `player`; one of the two.
pub fn seat_for(game: &Game, seat: Option<u32>, player: Option<&str>) -> Result<u32, String> {
    match (seat, player) {
        (Some(_), Some(_)) => Err("give a seat or a player, not both".into()),
        (Some(s), None) => Ok(s),
        (None, Some(name)) => seat_of(game, name),
        (None, None) => Err("give the seat to review, or the player's name".into()),
    }
}

/// The seat of the player called `name` in `game`.
pub fn seat_of(game: &Game, name: &str) -> Result<u32, String> {
    let seats = game.variant.seats() as usize;
    match game.names[..seats].iter().position(|n| n == name) {
        Some(s) => Ok(s as u32),
        None => Err(format!(
            "{}: no player `{name}` (the players: {})",
            game.path,
            game.names[..seats]
                .iter()
                .enumerate()
                .map(|(s, n)| format!("seat {s} `{n}`"))
                .collect::<Vec<_>>()
                .join(", ")
        )),
    }
}

/// One action's value at a decision.
#[derive(Debug, Clone, Serialize)]
pub struct Valued {
    /// Its name (`discard_5m`, `riichi`, `pon_...`, `pass`).
    pub action: String,
    /// Its id in the rule set's action layout.
    pub id: u32,
    /// Minus the expected final place (0 = first) after it, over its play-outs.
    pub value: f64,
    /// The standard error of `value` (none under two play-outs).
    pub stderr: Option<f64>,
    /// Its play-outs.
    pub rollouts: u32,
}

/// One decision, judged.
#[derive(Clone, Serialize)]
pub struct Reviewed {
    /// The round: index into the log's rounds.
    pub round: usize,
    /// Its name (`East 2, 1 honba`).
    pub round_name: String,
    /// The decision within the round ([`Spot::step`]).
    pub step: usize,
    /// What the log says.
    pub logged: String,
    /// The action played.
    pub played: String,
    /// The action the look-ahead would play: the best other one where the played one is a
    /// mistake, the played one otherwise.
    pub best: String,
    /// The best other action's paired gain over the played one in fresh worlds, where above 0
    /// (expected places).
    pub loss: f64,
    /// The paired gain itself, below zero too (where the played action did better in the duel).
    pub gain: f64,
    /// Their standard error (none where there was no duel).
    pub loss_stderr: Option<f64>,
    /// The loss is `margin` standard errors above zero.
    pub mistake: bool,
    /// Every legal action's value: the longest in the halving first, by value within each stage.
    pub candidates: Vec<Valued>,
    /// Play-outs spent on the decision.
    pub rollouts: u32,
    /// The state before the decision (for the report's pictures).
    #[serde(skip)]
    pub state: GameState,
}

/// Totals over decisions.
#[derive(Debug, Clone, Default, PartialEq, Serialize)]
pub struct Summary {
    /// Decisions with a choice reviewed.
    pub decisions: usize,
    /// Of them, mistakes.
    pub mistakes: usize,
    /// The share of decisions that are not mistakes.
    pub agreement: f64,
    /// The losses of the mistakes, summed (expected places): what the look-ahead, switching where
    /// it is sure, would have gained.
    pub loss: f64,
    /// `loss` per decision.
    pub loss_per_decision: f64,
    /// How far the actions played were ahead of the best other action, summed over the decisions
    /// (expected places; the duels' paired differences, not cut at zero, so noise cancels over
    /// many decisions): above zero where the player mostly chose what the look-ahead rates best,
    /// by the gap to the runner-up; below where other actions were better.
    pub edge: f64,
    /// The standard error of `edge`.
    pub edge_stderr: f64,
}

impl Summary {
    fn of<'a>(decisions: impl Iterator<Item = &'a Reviewed>) -> Summary {
        let mut s = Summary::default();
        let mut variance = 0.0;
        for d in decisions {
            s.decisions += 1;
            if let Some(se) = d.loss_stderr {
                s.edge -= d.gain;
                variance += se * se;
            }
            if d.mistake {
                s.mistakes += 1;
                s.loss += d.loss;
            }
        }
        s.edge_stderr = variance.sqrt();
        if s.decisions > 0 {
            s.agreement = 1.0 - s.mistakes as f64 / s.decisions as f64;
            s.loss_per_decision = s.loss / s.decisions as f64;
        }
        s
    }
}

/// A round's totals.
#[derive(Debug, Clone, Serialize)]
pub struct RoundSummary {
    /// Index into the log's rounds.
    pub round: usize,
    /// Its name.
    pub name: String,
    /// Its totals.
    #[serde(flatten)]
    pub summary: Summary,
}

/// A player's game, reviewed.
#[derive(Clone, Serialize)]
pub struct Review {
    /// The log, as named.
    pub log: String,
    /// The rule set it was replayed under.
    pub variant: String,
    /// The reviewed seat (0 = East 1's dealer).
    pub seat: u32,
    /// Its player's name in the log.
    pub player: String,
    /// The look-ahead's settings (`search:rollouts=...`).
    pub search: String,
    /// Its budget: play-outs per decision.
    pub rollouts_per_decision: u32,
    /// Every decision with a choice, in order of play.
    pub decisions: Vec<Reviewed>,
    /// Totals per round (rounds where the player had no choice left out).
    pub rounds: Vec<RoundSummary>,
    /// Totals over the game.
    pub game: Summary,
    /// Play-outs played, over all decisions.
    pub rollouts: u64,
}

/// splitmix64's finaliser: a decision's worlds seeded by where it is in the game, the same in any
/// format the game is logged in.
fn nonce(round: usize, step: usize) -> u64 {
    let mut z = (round as u64) << 32 | step as u64;
    z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    z ^ (z >> 31)
}

/// The candidates as far as they got: those that survived the halving longest (the most
/// play-outs) first, by value within each stage. An action dropped after a world or two can show
/// a lucky mean; it is listed below the ones compared over many.
fn ranked(candidates: &[Candidate]) -> Vec<Candidate> {
    let mut out = candidates.to_vec();
    out.sort_by(|a, b| b.rollouts.cmp(&a.rollouts).then(b.mean.total_cmp(&a.mean)));
    out
}

fn finite(x: f64) -> Option<f64> {
    x.is_finite().then_some(x)
}

/// Reviews `seat`'s decisions in `game` (in round `round` only, where given) with the look-ahead
/// of `options` (its budget, seed, base agent and margin; its focus is not used: every decision
/// with a choice is judged).
pub fn review(game: &Game, seat: u32, round: Option<usize>, options: Options) -> Result<Review, String> {
    Ok(review_spots(game, seat, &spots(game, seat, round)?, options, &|| ()))
}

/// Reviews `spots`, decisions of `seat` in `game` ([`spots`]), in parallel (rayon), calling
/// `progress` once per decision judged.
pub fn review_spots(game: &Game, seat: u32, spots: &[Spot], options: Options, progress: &(dyn Fn() + Sync)) -> Review {
    let search = Search::new(game.variant, options);
    let names = action_names(game.variant);
    let name = |a: u32| names.get(a as usize).cloned().unwrap_or_else(|| format!("action {a}"));
    let decisions: Vec<Reviewed> = spots
        .par_iter()
        .map(|spot| {
            // The base agent's action is kept through the halving too: a sound challenger that
            // the halving's first rounds, a few worlds per action, could otherwise drop.
            let base = search.base_action(&spot.state);
            let kept = [spot.action, base];
            let a = search.appraise(&spot.state, seat, &spot.own_draws, nonce(spot.round, spot.step), &kept);
            progress();
            let (gain, se) = a.duel.unwrap_or((0.0, f64::INFINITY));
            let mistake = gain > 0.0 && gain > options.margin.max(0.0) * se;
            let best = match (mistake, a.challenger) {
                (true, Some(c)) => c,
                _ => spot.action,
            };
            Reviewed {
                round: spot.round,
                round_name: game.rounds[spot.round].to_string(),
                step: spot.step,
                logged: spot.what.clone(),
                played: name(spot.action),
                best: name(best),
                loss: gain.max(0.0),
                gain,
                loss_stderr: a.duel.and_then(|(_, se)| finite(se)),
                mistake,
                candidates: ranked(&a.candidates)
                    .iter()
                    .map(|c| Valued {
                        action: name(c.action),
                        id: c.action,
                        value: c.mean,
                        stderr: finite(c.stderr),
                        rollouts: c.rollouts,
                    })
                    .collect(),
                rollouts: a.rollouts,
                state: spot.state,
            }
        })
        .collect();
    let mut rounds = Vec::new();
    for (r, round) in game.rounds.iter().enumerate() {
        let summary = Summary::of(decisions.iter().filter(|d| d.round == r));
        if summary.decisions > 0 {
            rounds.push(RoundSummary {
                round: r,
                name: round.to_string(),
                summary,
            });
        }
    }
    Review {
        log: game.path.clone(),
        variant: game.variant.to_string(),
        seat,
        player: game.names[seat as usize].clone(),
        search: options.name(),
        rollouts_per_decision: options.rollouts,
        game: Summary::of(decisions.iter()),
        rollouts: decisions.iter().map(|d| u64::from(d.rollouts)).sum(),
        decisions,
        rounds,
    }
}
