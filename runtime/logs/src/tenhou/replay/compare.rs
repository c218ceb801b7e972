//! Comparing a finished round with its log: winners, han, fu and yaku of each win, the kind of a
//! draw, score changes, the next round's table and the end of the game.

use super::super::log::{LoggedDraw, LoggedWin, Outcome, Round};
use super::super::plan::Plan;
use super::report::{outcome_name, Report};
use super::run::Run;
use crate::tenhou::write::win_yaku;
use rinshan_engine::env::{events, DrawKind, Step, Table, WinRecord};
use rinshan_engine::hand::YakuHan;
use rinshan_engine::{with_variant, Variant};

/// The yaku of an engine win as (name, han) in the log's terms, sorted; dora kinds with 0 han left out.
fn engine_yaku(variant: Variant, w: &WinRecord) -> Vec<(String, YakuHan)> {
    let mut out: Vec<(String, YakuHan)> = win_yaku(variant, w)
        .into_iter()
        .map(|y| (y.name.to_string(), y.han))
        .collect();
    out.sort_by(|a, b| a.0.cmp(&b.0));
    out
}

fn log_yaku(w: &LoggedWin) -> Vec<(String, YakuHan)> {
    let mut out: Vec<(String, YakuHan)> = w
        .yaku
        .iter()
        .filter(|y| !matches!(y.han, YakuHan::Han(0)))
        .map(|y| (y.name.to_string(), y.han))
        .collect();
    out.sort_by(|a, b| a.0.cmp(&b.0));
    out
}

fn yaku_text(list: &[(String, YakuHan)]) -> String {
    list.iter()
        .map(|(n, h)| match h {
            YakuHan::Han(x) => format!("{n} {x}"),
            YakuHan::Yakuman(x) => format!("{n} yakuman x{x}"),
        })
        .collect::<Vec<_>>()
        .join(", ")
}

/// Compares one logged win with the engine's record of it under `variant`'s rules; `None` when
/// they agree.
fn compare_win(variant: Variant, w: &LoggedWin, r: &WinRecord) -> Option<(String, String)> {
    let (ly, ey) = (log_yaku(w), engine_yaku(variant, r));
    let mut log_yakuman: u32 = ly
        .iter()
        .map(|(_, h)| if let YakuHan::Yakuman(x) = h { *x } else { 0 })
        .sum();
    if !with_variant!(variant, v => v::MULTIPLE_YAKUMAN) {
        // Several yakuman in the hand score one (WRC); the log lists each.
        log_yakuman = log_yakuman.min(1);
    }
    let log_han: u32 = w.han.unwrap_or_else(|| {
        ly.iter()
            .map(|(_, h)| if let YakuHan::Han(x) = h { *x } else { 0 })
            .sum()
    });
    let han_ok = if log_yakuman > 0 {
        r.yakuman == log_yakuman
    } else {
        r.yakuman == 0 && r.han == log_han
    };
    let fu_ok = w.fu.is_none_or(|fu| fu == r.fu);
    if han_ok && fu_ok && ly == ey {
        return None;
    }
    let fu = |f: Option<u32>| f.map_or(String::new(), |f| format!("{f} fu "));
    Some((
        format!("seat {}: {}{} han [{}]", w.winner, fu(w.fu), log_han, yaku_text(&ly)),
        format!(
            "{}{} han{} [{}]",
            fu(Some(r.fu)),
            r.han,
            if r.yakuman > 0 {
                format!(" yakuman x{}", r.yakuman)
            } else {
                String::new()
            },
            yaku_text(&ey)
        ),
    ))
}

fn draw_matches(log: LoggedDraw, table: &Table, seats: usize) -> bool {
    let tenpai = table.draw.tenpai.iter().filter(|&&t| t).count();
    match (log, table.draw.kind) {
        (LoggedDraw::Exhaustive, Some(DrawKind::Exhaustive)) => (1..seats).contains(&tenpai),
        (LoggedDraw::AllTenpai, Some(DrawKind::Exhaustive)) => tenpai == seats,
        (LoggedDraw::NoTenpai, Some(DrawKind::Exhaustive)) => tenpai == 0,
        (LoggedDraw::Nagashi, Some(DrawKind::Nagashi)) => true,
        (LoggedDraw::Kyuushu, Some(DrawKind::Kyuushu)) => true,
        (LoggedDraw::FourRiichi, Some(DrawKind::FourRiichi)) => true,
        (LoggedDraw::TripleRon, Some(DrawKind::TripleRon)) => true,
        (LoggedDraw::FourKans, Some(DrawKind::FourKans)) => true,
        (LoggedDraw::FourWinds, Some(DrawKind::FourWinds)) => true,
        _ => false,
    }
}

/// What the engine reported for a finished round, for messages.
fn engine_outcome(step: &Step, i: usize, table: &Table) -> String {
    let ev = step.events[i];
    if ev & (events::RON | events::TSUMO) != 0 {
        let seats: Vec<usize> = (0..4).filter(|p| step.winners[i] >> p & 1 == 1).collect();
        let how = if ev & events::TSUMO != 0 { "tsumo" } else { "ron" };
        return format!("{how} by seats {seats:?}");
    }
    let tenpai: Vec<usize> = (0..4).filter(|&p| table.draw.tenpai[p]).collect();
    format!("draw: {:?}, tenpai seats {tenpai:?}", table.draw.kind)
}

/// The score change of a round by the log: the changes its result lists less the riichi sticks
/// paid; after the last round of a game, sticks left on the table go to the top seat (ties: the
/// seat nearer East 1's dealer).
fn log_change(r: &Round, plan: &Plan, last: bool, stick: u32) -> [i64; 4] {
    let stick = i64::from(stick);
    let mut change = [0i64; 4];
    let mut add = |d: &[i32; 4]| (0..4).for_each(|p| change[p] += i64::from(d[p]));
    let won = match &r.outcome {
        Outcome::Wins(ws) => {
            ws.iter().for_each(|w| add(&w.deltas));
            true
        }
        Outcome::Draw { deltas, .. } => {
            deltas.iter().for_each(&mut add);
            false
        }
    };
    for (c, &paid) in change.iter_mut().zip(&plan.riichi_paid) {
        *c -= stick * i64::from(paid);
    }
    if last && !won {
        let sticks = i64::from(r.sticks) + plan.riichi_paid.iter().map(|&x| i64::from(x)).sum::<i64>();
        let scores: [i64; 4] = std::array::from_fn(|p| i64::from(r.scores[p]) + change[p]);
        let top = (0..r.seats).fold(0, |best, p| if scores[p] > scores[best] { p } else { best });
        change[top] += stick * sticks;
    }
    change
}

/// Compares the round `run` just finished with its log.
pub(super) fn finish_round(run: &mut Run, step: &Step, i: usize, table: &Table, report: &mut Report) {
    let r = run.round_log();
    let moves_left = run.plan.as_ref().map_or(0, |p| p.moves.len()) - run.next;
    if moves_left == 0 {
        report.rounds_replayed += 1;
    } else {
        let m = run.mismatch(
            "round end",
            format!("{moves_left} more decisions, then {}", outcome_name(&r.outcome)),
            format!("the round ended: {}", engine_outcome(step, i, table)),
        );
        report.mismatches.push(m);
    }
    let ev = step.events[i];
    match &r.outcome {
        Outcome::Wins(ws) => {
            let won_by: u32 = ws.iter().map(|w| 1u32 << w.winner).sum();
            for w in ws {
                report.wins += 1;
                let tsumo_ok = if w.tsumo {
                    ev & events::TSUMO != 0
                } else {
                    ev & events::RON != 0
                };
                if !tsumo_ok || step.winners[i] != won_by {
                    let m = run.mismatch("winners", outcome_name(&r.outcome), engine_outcome(step, i, table));
                    report.mismatches.push(m);
                    continue;
                }
                if w.computed {
                    report.wins_yaku_not_logged += 1;
                    continue;
                }
                match compare_win(run.variant, w, &table.wins[w.winner]) {
                    None => report.wins_matching += 1,
                    Some((log, ours)) => {
                        let m = run.mismatch("han, fu and yaku", log, ours);
                        report.mismatches.push(m);
                    }
                }
            }
        }
        Outcome::Draw { kind, .. } => {
            report.draws += 1;
            let drawn = ev & (events::EXHAUSTIVE_DRAW | events::ABORTIVE_DRAW) != 0;
            if drawn && draw_matches(*kind, table, r.seats) {
                report.draws_matching += 1;
            } else {
                let m = run.mismatch("draw kind", format!("{kind:?}"), engine_outcome(step, i, table));
                report.mismatches.push(m);
            }
        }
    }
    let next = run.game.rounds.get(run.round + 1);
    let stick = with_variant!(run.variant, v => v::RIICHI_STICK_POINTS);
    let expected = run
        .plan
        .as_ref()
        .map_or([0; 4], |plan| log_change(r, plan, next.is_none(), stick));
    if let Some(n) = next {
        let by_scores: [i64; 4] = std::array::from_fn(|p| i64::from(n.scores[p]) - i64::from(r.scores[p]));
        if by_scores != expected {
            let m = run.mismatch(
                "the log contradicts itself",
                format!("result {expected:?}, but the next round starts {by_scores:?} from this one"),
                "(not compared)",
            );
            report.mismatches.push(m);
        }
    }
    if expected == run.change {
        report.score_changes_matching += 1;
    } else {
        let m = run.mismatch("score changes", format!("{expected:?}"), format!("{:?}", run.change));
        report.mismatches.push(m);
    }
    match next {
        Some(n) => {
            report.tables += 1;
            let log_table = (n.table_round(), n.dealer() as u32, n.honba, n.sticks, n.scores);
            let ours = (table.round, table.dealer, table.honba, table.sticks, table.scores);
            if table.over {
                let m = run.mismatch(
                    "game end",
                    format!(
                        "the game goes on ({} more rounds)",
                        run.game.rounds.len() - run.round - 1
                    ),
                    "the game is over",
                );
                report.mismatches.push(m);
                run.finished = true;
            } else if log_table == ours {
                report.tables_matching += 1;
            } else {
                let show = |(round, dealer, honba, sticks, scores): (u32, u32, u32, u32, [i32; 4])| {
                    format!("round {round}, dealer {dealer}, {honba} honba, {sticks} sticks, scores {scores:?}")
                };
                let m = run.mismatch("next round", show(log_table), show(ours));
                report.mismatches.push(m);
            }
        }
        None => {
            if table.over {
                report.games_ended_right += 1;
            } else {
                let m = run.mismatch("game end", "the game ends here", "the game goes on");
                report.mismatches.push(m);
            }
            run.finished = true;
        }
    }
}
