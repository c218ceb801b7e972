//! What an MJAI log leaves out of a round's end. libriichi's arena (mjai.app, Mortal's self-play)
//! and the Tenhou-to-MJAI converters write a `hora` as its deltas and ura markers only, and
//! libriichi writes every `ryukyoku` without its reason or tenpai seats. The reader plays such a
//! round through the engine from the log's own tiles: a win's yaku, fu and han are the engine's
//! under the game's rule set (so the game converts to tenhou.net/6, whose results need them), as
//! are the tenpai seats of an exhaustive draw that pays nothing (none or all of them) and a
//! nagashi mangan. A replay then judges the win by its winner, score changes and next round
//! ([`LoggedWin::computed`]).

use rinshan_engine::env::Mode;
use rinshan_engine::Variant;

use rinshan_engine::env::DrawKind;

use crate::tenhou::log::{LoggedDraw, LoggedWin, Outcome, Round};
use crate::tenhou::position::round_end;
use crate::tenhou::write::{limit_of, points_text, yaku_list, Scoring};

/// A win whose yaku, fu and han the log leaves out, to be scored when its round is whole.
pub(super) fn unscored(winner: usize, from: usize, pao: usize, deltas: [i32; 4]) -> LoggedWin {
    LoggedWin {
        deltas,
        winner,
        from,
        pao,
        tsumo: winner == from,
        fu: None,
        han: None,
        limit: None,
        points: String::new(),
        yaku: Vec::new(),
        computed: true,
    }
}

/// The seats of a bit set of winners, for messages.
fn seats_of(bits: u32) -> Vec<usize> {
    (0..4).filter(|p| bits >> p & 1 == 1).collect()
}

/// Fills in what round `round` of the log `path` leaves out by playing it under `variant` in a
/// game of `mode`: the wins left unscored ([`unscored`]) and, where `unstated_draw`, an
/// exhaustive draw's tenpai seats or nagashi.
pub(super) fn fill_in(
    path: &str,
    round: &mut Round,
    unstated_draw: bool,
    variant: Variant,
    mode: Mode,
) -> Result<(), String> {
    let needed = match &round.outcome {
        Outcome::Wins(wins) => wins.iter().any(|w| w.computed),
        Outcome::Draw { kind, .. } => {
            unstated_draw
                && matches!(
                    kind,
                    LoggedDraw::Exhaustive | LoggedDraw::NoTenpai | LoggedDraw::AllTenpai
                )
        }
    };
    if !needed {
        return Ok(());
    }
    let end =
        round_end(path, round, variant, mode)?.ok_or("the log's decisions run out before the engine ends the round")?;
    let seats = round.seats;
    let dealer = round.dealer();
    let round_wind = (round.kyoku / 4) as usize;
    match &mut round.outcome {
        Outcome::Wins(wins) => {
            let logged: u32 = wins.iter().map(|w| 1u32 << w.winner).sum();
            let played = end.step.winners[0];
            if played != logged {
                return Err(format!(
                    "the log's winners are seats {:?}, the engine's {:?}",
                    seats_of(logged),
                    seats_of(played)
                ));
            }
            let scoring = Scoring::of(variant);
            for w in wins.iter_mut().filter(|w| w.computed) {
                let rec = &end.table.wins[w.winner];
                let base = scoring.base_points(rec.han, rec.fu, rec.yakuman);
                let limit = limit_of(base);
                let pay = scoring.payment(base, w.winner == dealer, w.tsumo);
                w.fu = limit.is_none().then_some(rec.fu);
                w.han = limit.is_none().then_some(rec.han);
                w.limit = limit;
                w.points = points_text(rec.fu, rec.han, limit, pay);
                w.yaku = yaku_list(variant, rec, (w.winner + seats - dealer) % seats, round_wind);
            }
        }
        Outcome::Draw { kind, deltas } => {
            let tenpai = end.table.draw.tenpai.iter().filter(|&&t| t).count();
            let paid = deltas.is_some_and(|d| d.iter().any(|&x| x != 0));
            *kind = match (end.table.draw.kind, paid) {
                (Some(DrawKind::Nagashi), _) => LoggedDraw::Nagashi,
                (Some(DrawKind::Exhaustive), false) if tenpai == seats => LoggedDraw::AllTenpai,
                (Some(DrawKind::Exhaustive), false) if tenpai == 0 => LoggedDraw::NoTenpai,
                // The payments say who was tenpai; a replay compares them with the engine's.
                (Some(DrawKind::Exhaustive), true) => LoggedDraw::Exhaustive,
                (played, _) => {
                    return Err(format!(
                        "the log's exhaustive draw pays {deltas:?}; the engine's round ends {played:?} with {tenpai} seats tenpai"
                    ))
                }
            };
        }
    }
    Ok(())
}
