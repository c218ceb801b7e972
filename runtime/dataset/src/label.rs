//! The look-ahead's labels: at each row's decision, what `rinshan-search` plays from the deciding
//! seat's view (the table and the wall places that seat drew, never the log's hidden tiles) and
//! the value it gave each action it played out. The same labels come from any log: the look-ahead's
//! own self-play, another agent's, or people's games.

use rayon::prelude::*;
use rinshan_engine::Variant;
use rinshan_logs::tenhou::log::Game;
use rinshan_logs::tenhou::position::{own_draws, round_positions, Position};
use rinshan_search::{Decision, Search};

/// The look-ahead's decision at each of a round's `positions` (round `round` of its game),
/// in parallel. The worlds of decision `step` are seeded by the options' seed, the round and the
/// step, so a label is reproducible and independent of the order or threads it was made in.
pub fn look_ahead(search: &Search, variant: Variant, positions: &[Position], round: usize) -> Vec<Decision> {
    look_ahead_at(
        search,
        variant,
        positions,
        round,
        &(0..positions.len()).collect::<Vec<_>>(),
    )
}

/// The look-ahead's decision at the positions `at` (indices into `positions`) only.
pub fn look_ahead_at(
    search: &Search,
    variant: Variant,
    positions: &[Position],
    round: usize,
    at: &[usize],
) -> Vec<Decision> {
    let own: Vec<Vec<Vec<u32>>> = (0..variant.seats()).map(|q| own_draws(variant, positions, q)).collect();
    at.par_iter()
        .map(|&i| {
            let p = &positions[i];
            let nonce = (round as u64) << 32 | p.step as u64;
            search.decide(&p.state, p.seat, &own[p.seat as usize][i], nonce)
        })
        .collect()
}

/// Each row's label, from the rows' `(round, step, seat, action)`: the look-ahead's action and
/// its value per action id (`num_actions` each; NaN for an action it did not play out, so all
/// NaN where it left the decision to its base agent). `Err` if a row is not the decision its
/// round's replay has at that step: rinshan's bug.
pub fn label_rows(
    search: &Search,
    game: &Game,
    rows: &[(usize, usize, u8, u8)],
    num_actions: usize,
) -> Result<(Vec<u8>, Vec<f32>), String> {
    let mut action = Vec::with_capacity(rows.len());
    let mut value = Vec::with_capacity(rows.len() * num_actions);
    let mut start = 0;
    while start < rows.len() {
        let round = rows[start].0;
        let end = start + rows[start..].iter().take_while(|r| r.0 == round).count();
        let positions = round_positions(game, round)?;
        let mut at = Vec::with_capacity(end - start);
        for &(_, step, seat, played) in &rows[start..end] {
            match positions.get(step) {
                Some(p) if p.seat == u32::from(seat) && p.action == u32::from(played) => at.push(step),
                _ => {
                    return Err(format!(
                        "rinshan bug, please report: {}: round {round}: decision {step} of the \
                         replay is not the row's (seat {seat}, action {played})",
                        game.path
                    ))
                }
            }
        }
        for d in look_ahead_at(search, game.variant, &positions, round, &at) {
            action.push(d.action as u8);
            let mut v = vec![f32::NAN; num_actions];
            for c in &d.candidates {
                if let Some(slot) = v.get_mut(c.action as usize) {
                    *slot = c.mean as f32;
                }
            }
            value.extend(v);
        }
        start = end;
    }
    Ok((action, value))
}
