//! One game followed on the kernel's states: each step is read from the state before it, the
//! action and the state after it, and becomes the entries Tenhou writes.
//!
//! The state after a step that ends a round already holds the next round (the kernel deals it in
//! the same step), so a round's end is read from the step's events, the win records and the
//! state before; the next round's wall and table from the state after.

use crate::tenhou::log::{round_name, Discard, Game, LoggedDraw, LoggedWin, Outcome, Round};
use crate::tenhou::plan::{MoveIds, Played, KITA};
use rinshan_engine::env::{events, DrawRecord, WinRecord};
use rinshan_engine::generated::kernel::{self, GameState};
// Red's ids: the recorder reads every variant's moves in red's layout (`to_plan`).
use rinshan_engine::generated::red as k;
use rinshan_engine::{with_variant, Variant};

use super::outcome::{draw_outcome, limit_of, outcome_deltas, pao_share, points_text, yaku_list, Scoring};
use super::round::{meld_count, Current};

use events::ROUND_OVER;

/// Engine seats' `d` in the log's seats (East 1's dealer `first` is the log's seat 0); the seats
/// past the table's stay 0.
fn in_log_seats(d: &[i32; 4], first: usize, seats: usize) -> [i32; 4] {
    std::array::from_fn(|i| if i < seats { d[(i + first) % seats] } else { 0 })
}

/// The round being played, for a live event stream: seats are the log's (East 1's dealer is 0).
#[derive(Debug, Clone)]
pub struct InPlay<'a> {
    /// The round so far, with the dora indicators shown so far; its outcome is a placeholder.
    pub round: Round,
    /// Its entries in the order of play.
    pub order: &'a [Played],
    /// Seats that declared riichi and have not made the riichi discard yet.
    pub declared: [bool; 4],
    /// The engine's seat of East 1's dealer (log seat `s` is engine seat `(s + first) % 4`).
    pub first: u32,
}

/// Follows one game (and, with auto-reset, the games after it) and hands out each finished game.
#[derive(Debug, Clone)]
pub struct GameRecorder {
    /// Player names written in every record.
    pub names: [String; 4],
    /// Tenhou's name of the rule: `鳳南喰赤` for half games, `鳳東喰赤` for east games (without
    /// `赤` when the variant has no red fives).
    rule: &'static str,
    rounds: Vec<Round>,
    current: Option<Current>,
    dropped: usize,
    /// The rules the game is played under.
    scoring: Scoring,
    /// The variant's action ids as the plan's (red's layout and kita), in which the log's moves
    /// are read.
    to_plan: MoveIds,
}

impl GameRecorder {
    /// Follows the game of `state`, which must have just dealt a round: right after
    /// [`rinshan_engine::env::Env::reset`] or [`rinshan_engine::env::Env::deal`], or the kernel's `game_new`.
    pub fn new(state: &GameState) -> Result<GameRecorder, String> {
        GameRecorder::for_variant(state, Variant::Red)
    }

    /// As [`GameRecorder::new`], for a game of `variant`.
    pub fn for_variant(state: &GameState, variant: Variant) -> Result<GameRecorder, String> {
        // Tenhou names its three-player rules 三.. (`三鳳南喰赤`).
        let rule = match (variant.seats(), state.mode, variant.red_fives()) {
            (4, kernel::MODE_HALF, true) => "鳳南喰赤",
            (4, kernel::MODE_HALF, false) => "鳳南喰",
            (4, kernel::MODE_EAST, true) => "鳳東喰赤",
            (4, kernel::MODE_EAST, false) => "鳳東喰",
            (_, kernel::MODE_HALF, true) => "三鳳南喰赤",
            (_, kernel::MODE_HALF, false) => "三鳳南喰",
            (_, kernel::MODE_EAST, true) => "三鳳東喰赤",
            (_, kernel::MODE_EAST, false) => "三鳳東喰",
            _ => return Err("Tenhou logs are east or half games: a one-hand game has no Tenhou rule".into()),
        };
        let names = match variant.seats() {
            3 => ["A", "B", "C", ""],
            _ => ["A", "B", "C", "D"],
        };
        Ok(GameRecorder {
            names: names.map(String::from),
            rule,
            rounds: Vec::new(),
            current: Some(Current::start(state, variant)?),
            dropped: 0,
            scoring: Scoring::of(variant),
            to_plan: MoveIds::to_plan(variant),
        })
    }

    /// The rounds of the current game finished so far.
    pub fn rounds(&self) -> &[Round] {
        &self.rounds
    }

    /// Tenhou's name of the game's rule (`鳳南喰赤`).
    pub fn rule(&self) -> &str {
        self.rule
    }

    /// The rules the game is played under.
    pub fn variant(&self) -> Variant {
        self.scoring.variant
    }

    /// The round being played, as far as it has gone; `None` once the game is over.
    pub fn in_play(&self) -> Option<InPlay<'_>> {
        let cur = self.current.as_ref()?;
        let mut round = cur.round.clone();
        let dora = self.scoring.variant.wall().dora as usize;
        round.dora = (0..cur.dora).filter_map(|i| cur.wall_tile(dora + i).ok()).collect();
        Some(InPlay {
            round,
            order: &cur.order,
            declared: cur.riichi_next,
            first: cur.first,
        })
    }

    /// Games that ended with an illegal action, left out (they have no Tenhou ending).
    pub fn dropped(&self) -> usize {
        self.dropped
    }

    /// Records the step that took the game from `before` to `after` with `action` (of
    /// `before.current`); returns the game when the step ended it. With auto-reset, `after`
    /// already holds the next game, which is followed from there.
    pub fn record(&mut self, before: &GameState, action: u32, after: &GameState) -> Result<Option<Game>, String> {
        if before.terminated != 0 && before.auto_reset == 0 {
            // A finished game without auto-reset repeats its last view.
            return Ok(None);
        }
        let Some(cur) = self.current.as_mut() else {
            return Ok(None);
        };
        let name = round_name(cur.round.kyoku, cur.round.honba);
        if after.illegal != 0 {
            self.dropped += 1;
            self.rounds.clear();
            self.current = None;
            self.next_game(after)?;
            return Ok(None);
        }
        self.step(before, action, after).map_err(|e| format!("{name}: {e}"))
    }

    fn next_game(&mut self, after: &GameState) -> Result<(), String> {
        if after.auto_reset != 0 {
            self.current = Some(Current::start(after, self.scoring.variant)?);
        }
        Ok(())
    }

    fn step(&mut self, b: &GameState, action: u32, a: &GameState) -> Result<Option<Game>, String> {
        let Some(cur) = self.current.as_mut() else {
            return Ok(None);
        };
        if a.steps != b.steps + 1 {
            return Err(format!(
                "the state after the step has taken {} steps, the one before {}: the game was stepped or reset without the recorder",
                a.steps, b.steps
            ));
        }
        let in_red = |a: u32| {
            self.to_plan
                .get(a)
                .ok_or_else(|| format!("action {a} is not an action of {}", self.scoring.variant))
        };
        let action = in_red(action)?;
        let p = b.current;
        let seat = cur.at(p);
        let discards = k::ACTION_DISCARD..k::ACTION_DISCARD + k::ACTION_DISCARD_COUNT;
        let discard = discards.contains(&action) || action == k::ACTION_TSUMOGIRI;
        match action {
            _ if discards.contains(&action) => cur.discard(seat, Some(action - k::ACTION_DISCARD))?,
            k::ACTION_TSUMOGIRI => cur.discard(seat, None)?,
            k::ACTION_RIICHI => cur.riichi_next[seat] = true,
            KITA => cur.kita(seat),
            _ if (k::ACTION_SELF_KAN..k::ACTION_SELF_KAN + k::ACTION_SELF_KAN_COUNT).contains(&action) => {
                cur.self_kan(b, p, action - k::ACTION_SELF_KAN)?
            }
            _ => {}
        }
        if a.events & ROUND_OVER == 0 {
            if (k::ACTION_RON..=k::ACTION_PASS).contains(&action) {
                for q in (0..4).filter(|&q| meld_count(a, q) > meld_count(b, q)) {
                    let choice = if q == p {
                        action
                    } else {
                        in_red(b.claim_choices[q as usize])?
                    };
                    cur.call(b, q, choice)?;
                }
            }
            let variant = self.scoring.variant;
            let replaced = |s: &GameState| with_variant!(variant, v => v::replacements_drawn(&mut { *s }));
            let drawn = if replaced(a) > replaced(b) {
                Some((variant.replacement_index(replaced(b)) as usize, true))
            } else {
                (a.next_draw > b.next_draw).then_some((b.next_draw as usize, false))
            };
            if let Some((i, replacement)) = drawn {
                cur.draw(a.current, i, replacement, a.drawn)?;
            }
            cur.dora = a.dora_revealed as usize;
            return Ok(None);
        }
        // The kan dora of an open or added kan turns up with the next discard, which may end the
        // round in the same step (an exhaustive or abortive draw).
        cur.dora = (b.dora_revealed + if discard { b.dora_pending } else { 0 }) as usize;
        let ronned_riichi = self.finish_round(b, a)?;
        if a.terminated != 0 {
            self.current = None;
            let game = Game {
                path: String::new(),
                rule: self.rule.to_string(),
                red_fives: self.scoring.variant.red_fives(),
                variant: self.scoring.variant,
                names: self.names.clone(),
                rounds: std::mem::take(&mut self.rounds),
            };
            self.next_game(a)?;
            return Ok(Some(game));
        }
        let next = Current::start(a, self.scoring.variant)?;
        self.check_next_table(&next, ronned_riichi)?;
        self.current = Some(next);
        Ok(None)
    }

    /// Writes the result of the round that ended between `b` and `a` and files the round;
    /// returns the seat whose riichi discard was ronned (its stick was never paid).
    fn finish_round(&mut self, b: &GameState, a: &GameState) -> Result<Option<usize>, String> {
        let Some(cur) = self.current.as_mut() else {
            return Ok(None);
        };
        let dealer = b.dealer as usize;
        let seats = cur.seats as usize;
        let round_wind = with_variant!(self.scoring.variant, v => v::round_wind_of(b.round)) as usize;
        let mut ronned_riichi = None;
        let outcome = if a.events & (events::RON | events::TSUMO) != 0 {
            let tsumo = a.events & events::TSUMO != 0;
            let from = if tsumo { b.current } else { b.claim_from };
            // Nearest the discarder first: Tenhou's order, and the one who takes honba and sticks.
            let winners: Vec<u32> = (1..=cur.seats)
                .map(|j| (from + j) % cur.seats)
                .filter(|&w| a.winners >> w & 1 == 1)
                .collect();
            let mut wins = Vec::new();
            for (n, &w) in winners.iter().enumerate() {
                let rec = WinRecord::decode(&a.win_yaku, &a.win_score, w as usize);
                let scoring = &self.scoring;
                let liable = scoring.liability(b, w, [a.win_yaku[2 * w as usize], a.win_yaku[2 * w as usize + 1]]);
                let base = scoring.base_points(rec.han, rec.fu, rec.yakuman);
                let limit = limit_of(base);
                let pay = scoring.payment(base, w as usize == dealer, tsumo);
                let table = if n == 0 { (b.honba, b.sticks) } else { (0, 0) };
                let pao = liable.map(|(seat, yaku)| (seat as usize, pao_share(scoring.variant, &rec, yaku)));
                let d = scoring.win_deltas(w as usize, Some(from as usize), dealer, pay, table, pao);
                let seat_wind = (w as usize + seats - dealer) % seats;
                wins.push(LoggedWin {
                    deltas: in_log_seats(&d, cur.first as usize, seats),
                    winner: cur.at(w),
                    from: cur.at(from),
                    pao: cur.at(liable.map_or(w, |(seat, _)| seat)),
                    tsumo,
                    fu: limit.is_none().then_some(rec.fu),
                    han: limit.is_none().then_some(rec.han),
                    limit,
                    points: points_text(rec.fu, rec.han, limit, pay),
                    yaku: yaku_list(scoring.variant, &rec, seat_wind, round_wind),
                    computed: false,
                });
            }
            if !tsumo {
                ronned_riichi = Some(cur.at(from));
            }
            let riichi = |w: &LoggedWin| w.yaku.iter().any(|y| y.name == "riichi" || y.name == "double_riichi");
            if wins.iter().any(riichi) {
                cur.round.ura = (0..cur.dora)
                    .map(|i| cur.wall_tile(self.scoring.variant.wall().ura as usize + i))
                    .collect::<Result<_, _>>()?;
            }
            Outcome::Wins(wins)
        } else {
            let rec = DrawRecord::decode(a.draw_kind);
            let (kind, deltas) = draw_outcome(&rec, dealer, self.scoring.noten_pool, seats)
                .ok_or("the round ended in a draw the state does not name")?;
            let deltas = deltas.map(|d| in_log_seats(&d, cur.first as usize, seats));
            if kind == LoggedDraw::TripleRon {
                ronned_riichi = Some(cur.at(b.claim_from));
            }
            Outcome::Draw { kind, deltas }
        };
        cur.round.dora = (0..cur.dora)
            .map(|i| cur.wall_tile(self.scoring.variant.wall().dora as usize + i))
            .collect::<Result<_, _>>()?;
        cur.round.outcome = outcome;
        cur.round.line = self.rounds.len() + 1;
        // A riichi discard that was ronned was the last discard of its seat.
        let ronned_riichi = ronned_riichi.filter(|&s| matches!(cur.round.discards[s].last(), Some(Discard::Riichi(_))));
        self.rounds.push(cur.round.clone());
        Ok(ronned_riichi)
    }

    /// The scores and sticks the engine starts the next round with must be the last round's
    /// plus its result, less the riichi sticks paid: what a reader of the log will assume.
    fn check_next_table(&self, next: &Current, ronned_riichi: Option<usize>) -> Result<(), String> {
        let (Some(last), Some(cur)) = (self.rounds.last(), self.current.as_ref()) else {
            return Ok(());
        };
        let paid: [bool; 4] = std::array::from_fn(|s| cur.riichi_made[s] && ronned_riichi != Some(s));
        let deltas = outcome_deltas(&last.outcome);
        let scores: [i32; 4] =
            std::array::from_fn(|s| last.scores[s] + deltas[s] - self.scoring.stick as i32 * i32::from(paid[s]));
        let won = matches!(last.outcome, Outcome::Wins(_));
        let sticks = if won {
            0
        } else {
            last.sticks + paid.iter().filter(|&&x| x).count() as u32
        };
        if (scores, sticks) != (next.round.scores, next.round.sticks) {
            return Err(format!(
                "the result gives scores {scores:?} and {sticks} sticks for the next round, but the engine has {:?} and {}",
                next.round.scores, next.round.sticks
            ));
        }
        Ok(())
    }
}
