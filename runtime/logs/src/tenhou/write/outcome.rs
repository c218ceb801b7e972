//! The result of a round as Tenhou writes it: the points text of a win, each win's score changes
//! (honba, riichi sticks and pao included), the draw names and their tenpai or nagashi payments.
//!
//! Payments are worked out from han, fu and yakuman by the variant's scoring kernel functions
//! ([`Scoring`]) rather than read off the engine's rewards: a double ron pays
//! two hands in one step, a pao tsumo hides the shares, and a game's last step adds uma. The recorder checks the sum against the scores the
//! engine carries into the next round.

use crate::tenhou::log::{tenhou_yaku, Limit, LoggedDraw, Outcome};
use rinshan_engine::env::{DrawKind, DrawRecord, WinRecord};
use rinshan_engine::generated::kernel::{GameState, ScoreOutput};
use rinshan_engine::hand::{yaku_worth, Payment, Yaku, YakuHan};
use rinshan_engine::Variant;

/// What the writer reads of one variant's scoring: the scoring kernel's own functions
/// (`base_points` with the variant's `kiriage_mangan` and `kazoe_yakuman`, `hand_payments`) and
/// the variant's sticks and pao options.
#[derive(Clone, Copy)]
pub(crate) struct Scoring {
    pub(crate) variant: Variant,
    base: fn(u32, u32, u32) -> u32,
    payments: fn(u32, bool) -> [u32; 3],
    honba_ron: u32,
    honba_tsumo: u32,
    /// Points of one riichi stick.
    pub(crate) stick: u32,
    /// `[liability] pao_pays_honba`.
    pao_pays_honba: bool,
    /// `[draws] noten_pool_points`: what the noten seats pay the tenpai ones together.
    pub(crate) noten_pool: u32,
    /// Players at the table: a tsumo is paid by the others there are.
    seats: usize,
}

impl std::fmt::Debug for Scoring {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "Scoring({})", self.variant)
    }
}

impl Scoring {
    pub(crate) fn of(variant: Variant) -> Scoring {
        rinshan_engine::with_variant!(variant, v => Scoring {
            variant,
            base: v::base_points,
            payments: v::hand_payments,
            honba_ron: v::HONBA_RON_POINTS,
            honba_tsumo: v::HONBA_TSUMO_POINTS,
            stick: v::RIICHI_STICK_POINTS,
            pao_pays_honba: v::PAO_PAYS_HONBA,
            noten_pool: v::NOTEN_POOL_POINTS,
            seats: v::SEATS as usize,
        })
    }

    /// The seat liable for the win of `winner` in the state `before` the winning step, and the
    /// yakuman it is liable for (the scoring kernel's `pao_yaku` and `liable_seat`); `yaku` are
    /// the win's yaku words.
    pub(crate) fn liability(&self, before: &GameState, winner: u32, yaku: [u32; 2]) -> Option<(u32, u32)> {
        let out = ScoreOutput {
            yaku_lo: yaku[0],
            yaku_hi: yaku[1],
            ..bytemuck::Zeroable::zeroed()
        };
        let mut s = *before;
        let (pao, seat) = rinshan_engine::with_variant!(self.variant, v => {
            let pao = v::pao_yaku(&mut s, winner, out);
            (pao, v::liable_seat(&mut s, winner, pao))
        });
        (seat < 4).then_some((seat, pao))
    }

    /// Base points of a hand: fu x 2^(han+2) up to the limits.
    pub(crate) fn base_points(&self, han: u32, fu: u32, yakuman: u32) -> u32 {
        (self.base)(han, fu, yakuman)
    }

    /// What a hand of `base` points costs before honba.
    pub(crate) fn payment(&self, base: u32, dealer: bool, tsumo: bool) -> Payment {
        let [ron, dealer_share, others] = (self.payments)(base, dealer);
        match (tsumo, dealer) {
            (false, _) => Payment::Ron { discarder: ron },
            (true, false) => Payment::Tsumo {
                dealer: Some(dealer_share),
                others,
            },
            (true, true) => Payment::Tsumo { dealer: None, others },
        }
    }

    /// Who pays what for one win: `from` is `None` for a tsumo; `table` is (honba, riichi
    /// deposits collected), counted only for the winner nearest the discarder, so give (0, 0) for
    /// the other ones of a double or triple ron. A liable seat (`pao`, with the share of the hand
    /// it covers, [`pao_share`]) pays half of that share of a ron's value (the discarder the rest
    /// and the honba), and that share of each payment of a tsumo (the payer the rest and its
    /// honba; all of it, honba included, when it covers the whole hand). With `pao_pays_honba`
    /// the liable seat pays the honba the discarder or payer would.
    pub(crate) fn win_deltas(
        &self,
        winner: usize,
        from: Option<usize>,
        dealer: usize,
        pay: Payment,
        (honba, sticks): (u32, u32),
        pao: Option<(usize, [u32; 2])>,
    ) -> [i32; 4] {
        let mut d = [0i64; 4];
        let mut move_points = |payer: usize, points: u32| {
            d[payer] -= i64::from(points);
            d[winner] += i64::from(points);
        };
        let liable_honba = |honba: u32| if self.pao_pays_honba { honba } else { 0 };
        match (pay, from) {
            (Payment::Ron { discarder: value }, Some(from)) => {
                let honba = honba * self.honba_ron;
                match pao {
                    Some((liable, [num, den])) if liable != from => {
                        let covered = value / den * num;
                        move_points(liable, covered / 2 + liable_honba(honba));
                        move_points(from, value - covered / 2 + honba - liable_honba(honba));
                    }
                    _ => move_points(from, value + honba),
                }
            }
            (Payment::Tsumo { dealer: share, others }, _) => {
                for p in (0..self.seats).filter(|&p| p != winner) {
                    let value = match share {
                        Some(d) if p == dealer => d,
                        _ => others,
                    };
                    let honba = honba * self.honba_tsumo;
                    match pao {
                        Some((liable, [num, den])) if num < den => {
                            let covered = value / den * num + liable_honba(honba);
                            move_points(liable, covered);
                            move_points(p, value + honba - covered);
                        }
                        Some((liable, _)) => move_points(liable, value + honba),
                        None => move_points(p, value + honba),
                    }
                }
            }
            // A ron with no discarder cannot be recorded; the caller always names one.
            (Payment::Ron { .. }, None) => {}
        }
        d[winner] += i64::from(sticks * self.stick);
        d.map(|x| x as i32)
    }
}

/// The limit a base reaches, named in the points text instead of fu and han.
pub(crate) fn limit_of(base: u32) -> Option<Limit> {
    match base {
        8000.. => Some(Limit::Yakuman),
        6000.. => Some(Limit::Sanbaiman),
        4000.. => Some(Limit::Baiman),
        3000.. => Some(Limit::Haneman),
        2000.. => Some(Limit::Mangan),
        _ => None,
    }
}

/// `30符4飜7700点`, `30符2飜500-1000点` (a non-dealer's tsumo: non-dealers, dealer),
/// `40符3飜2600点∀` (a dealer's tsumo: each pays), `満貫8000点`.
pub(crate) fn points_text(fu: u32, han: u32, limit: Option<Limit>, pay: Payment) -> String {
    let hand = match limit {
        Some(l) => l.tenhou_name().to_string(),
        None => format!("{fu}符{han}飜"),
    };
    match pay {
        Payment::Ron { discarder } => format!("{hand}{discarder}点"),
        Payment::Tsumo {
            dealer: Some(d),
            others,
        } => format!("{hand}{others}-{d}点"),
        Payment::Tsumo { dealer: None, others } => format!("{hand}{others}点∀"),
    }
}

/// The part of a pao win the liable seat covers, as [numerator, denominator] of its value (the
/// scoring kernel's own rule): the pao yakuman (`pao`, a yaku id) over the hand's yakuman where
/// the variant's `pao_share_only` is set, else the whole hand.
pub(super) fn pao_share(variant: Variant, rec: &WinRecord, pao: u32) -> [u32; 2] {
    rinshan_engine::hand::pao_share(variant, rec.yakuman, pao)
}

/// A win's yaku with what each is worth under `variant`'s spec, then dora, red fives and ura
/// (those with 0 han left out).
pub(crate) fn win_yaku(variant: Variant, rec: &WinRecord) -> Vec<Yaku> {
    let mut yaku: Vec<Yaku> = rec
        .yaku_ids()
        .map(|id| {
            let i = id as usize;
            Yaku {
                name: rinshan_engine::env::yaku_names(variant)[i],
                han: yaku_worth(variant, i, rec.concealed),
            }
        })
        .collect();
    for (name, n) in [("dora", rec.dora), ("aka", rec.aka), ("ura", rec.ura)] {
        if n > 0 {
            yaku.push(Yaku {
                name,
                han: YakuHan::Han(n),
            });
        }
    }
    yaku
}

/// A win's yaku in the order Tenhou lists them, dora, red fives and ura last.
pub(crate) fn yaku_list(variant: Variant, rec: &WinRecord, seat_wind: usize, round_wind: usize) -> Vec<Yaku> {
    let mut yaku = win_yaku(variant, rec);
    yaku.sort_by_key(|y| tenhou_yaku(y.name, seat_wind, round_wind).map_or(usize::MAX, |(_, rank)| rank));
    yaku
}

/// A round without a win at a table of `seats`, in engine seats (`dealer` too): the name and the
/// payments Tenhou lists (the noten `pool` shared for some tenpai seats, nagashi mangan as a
/// mangan tsumo per seat).
pub(super) fn draw_outcome(
    rec: &DrawRecord,
    dealer: usize,
    pool: u32,
    seats: usize,
) -> Option<(LoggedDraw, Option<[i32; 4]>)> {
    let kind = match rec.kind? {
        DrawKind::Exhaustive => {
            let tenpai = rec.tenpai.iter().filter(|&&t| t).count();
            let pool = pool as i32;
            return Some(match tenpai {
                0 => (LoggedDraw::NoTenpai, None),
                n if n == seats => (LoggedDraw::AllTenpai, None),
                n => {
                    let (won, paid) = (pool / n as i32, -pool / (seats - n) as i32);
                    let deltas = std::array::from_fn(|p| match (p < seats, rec.tenpai[p]) {
                        (false, _) => 0,
                        (true, true) => won,
                        (true, false) => paid,
                    });
                    (LoggedDraw::Exhaustive, Some(deltas))
                }
            });
        }
        DrawKind::Nagashi => {
            let mut deltas = [0i32; 4];
            for w in (0..seats).filter(|&w| rec.nagashi[w]) {
                for p in (0..seats).filter(|&p| p != w) {
                    let amount = if p == dealer || w == dealer { 4000 } else { 2000 };
                    deltas[p] -= amount;
                    deltas[w] += amount;
                }
            }
            return Some((LoggedDraw::Nagashi, Some(deltas)));
        }
        DrawKind::Kyuushu => LoggedDraw::Kyuushu,
        DrawKind::FourRiichi => LoggedDraw::FourRiichi,
        DrawKind::TripleRon => LoggedDraw::TripleRon,
        DrawKind::FourKans => LoggedDraw::FourKans,
        DrawKind::FourWinds => LoggedDraw::FourWinds,
    };
    Some((kind, None))
}

/// The score changes of a result by seat: every win's, or the draw's payments.
pub(super) fn outcome_deltas(outcome: &Outcome) -> [i32; 4] {
    let mut sum = [0i32; 4];
    let mut add = |d: &[i32; 4]| (0..4).for_each(|p| sum[p] += d[p]);
    match outcome {
        Outcome::Wins(wins) => wins.iter().for_each(|w| add(&w.deltas)),
        Outcome::Draw { deltas, .. } => deltas.iter().for_each(add),
    }
    sum
}
