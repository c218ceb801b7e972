//! The positions of a logged round: every decision the engine asks for while the round is
//! replayed (the log's own moves, and the claim prompts it passes), each with the game state
//! before it. `rinshan observe` and the observation snapshots look at a log through these. The
//! round is played under the game's own rules ([`Game::variant`]), and actions are its ids.

use super::log::{round_name, Game, Round};
use super::plan::{plan, MoveIds};
use rinshan_engine::env::{Config, Env, Mode};
use rinshan_engine::generated::kernel::GameState;
use rinshan_engine::{with_variant, Variant};

/// One decision of a replayed round.
#[derive(Clone)]
pub struct Position {
    /// 0-based decision index within the round (claim prompts included).
    pub step: usize,
    /// The seat deciding.
    pub seat: u32,
    /// The action played (the log's move, or a pass at a prompt the log does not take).
    pub action: u32,
    /// What the log says for this decision (`pass` at a prompt it does not list).
    pub what: String,
    /// The game state before the decision.
    pub state: GameState,
}

/// For each of a round's `positions` (in order of play, from its first decision), the wall
/// places `seat` had drawn by then: what it knows beyond the table
/// ([`rinshan_engine::observe::OwnDraws`]), which a look-ahead from its seat deals around.
pub fn own_draws(variant: Variant, positions: &[Position], seat: u32) -> Vec<Vec<u32>> {
    let mut own = rinshan_engine::observe::OwnDraws::default();
    positions
        .iter()
        .enumerate()
        .map(|(i, p)| {
            // The first position is followed from itself: the round's start.
            let before = &positions[i.saturating_sub(1)].state;
            own.update(variant, before, &mut p.state.clone(), seat);
            own.positions.clone()
        })
        .collect()
}

/// How a replayed round ended: the step that ended it and the table after it.
#[derive(Clone)]
pub struct RoundEnd {
    /// What the last decision's step reported (events, winners, rewards, ranks).
    pub step: rinshan_engine::env::Step,
    /// The table after it (the win records, the draw, the scores).
    pub table: rinshan_engine::env::Table,
    /// The uma the replaying env pays (none: replays compare the logged payments).
    pub uma: [i32; 4],
    /// The rules the round was played under.
    pub variant: Variant,
}

/// The decisions of round `round` (0-based index into the game's rounds) in order of play.
pub fn round_positions(game: &Game, round: usize) -> Result<Vec<Position>, String> {
    round_replay(game, round).map(|(positions, _)| positions)
}

/// The decisions of round `round` and how the round ended (`None` if the log stops before the
/// engine ends it).
pub fn round_replay(game: &Game, round: usize) -> Result<(Vec<Position>, Option<RoundEnd>), String> {
    let Some(r) = game.rounds.get(round) else {
        return Err(format!(
            "{}: no round {round} (the log has {})",
            game.path,
            game.rounds.len()
        ));
    };
    let mode = super::replay::mode_of(std::slice::from_ref(game));
    play_round(&game.path, r, game.variant, mode, true)
}

/// How round `r` of the log `path` ends when the engine plays its decisions under `variant`
/// (what a reader asks when the log leaves a win's yaku out).
pub(crate) fn round_end(path: &str, r: &Round, variant: Variant, mode: Mode) -> Result<Option<RoundEnd>, String> {
    play_round(path, r, variant, mode, false).map(|(_, end)| end)
}

/// Plays round `r`; `keep` keeps every position's state (a copy per decision, which a reader
/// scoring the round's wins does without).
fn play_round(
    path: &str,
    r: &Round,
    variant: Variant,
    mode: Mode,
    keep: bool,
) -> Result<(Vec<Position>, Option<RoundEnd>), String> {
    let where_ = format!("{path}: line {} ({})", r.line, round_name(r.kyoku, r.honba));
    let p = plan(r).map_err(|e| format!("{where_}: {e}"))?;
    let mut env = Env::new(Config {
        mode,
        uma: Some([0; 4]),
        threads: Some(1),
        ..Config::new(variant, 1)
    })
    .map_err(|e| e.to_string())?;
    let from_red = MoveIds::new(variant);
    let pass = with_variant!(variant, v => v::ACTION_PASS);
    env.reset().map_err(|e| e.to_string())?;
    let deal = p.deal(r, variant).map_err(|e| format!("{where_}: {e}"))?;
    env.deal(&[Some(deal)]).map_err(|e| e.to_string())?;
    let mut out = Vec::new();
    let mut next = 0;
    let mut steps = 0;
    loop {
        let step = env.last().clone();
        let seat = step.current_player[0];
        let claim = step.legal_actions(0).any(|a| a == pass);
        let (action, what) = match p.moves.get(next) {
            Some(m) if m.seat == seat as usize && m.claim == claim => {
                next += 1;
                let action = from_red
                    .get(m.action)
                    .ok_or_else(|| format!("{where_}: step {steps}: {variant} has no action for {}", m.what))?;
                (action, m.what.clone())
            }
            _ if claim => (pass, "pass".to_string()),
            Some(m) => {
                return Err(format!(
                    "{where_}: step {steps}: the log has seat {} {}, the engine asks seat {seat}",
                    m.seat, m.what
                ))
            }
            None => break,
        };
        if keep {
            let state: GameState = env.game_states().map_err(|e| e.to_string())?.remove(0);
            out.push(Position {
                step: steps,
                seat,
                action,
                what,
                state,
            });
        }
        steps += 1;
        let after = env.step(&[action]).map_err(|e| e.to_string())?.clone();
        use rinshan_engine::env::events as e;
        if after.events[0] & e::ROUND_OVER != 0 || after.terminated[0] || after.illegal[0] {
            let table = env.tables().map_err(|e| e.to_string())?.remove(0);
            let uma = env.uma();
            return Ok((
                out,
                Some(RoundEnd {
                    step: after,
                    table,
                    uma,
                    variant,
                }),
            ));
        }
    }
    Ok((out, None))
}
