//! From one logged round to what the replayer feeds the engine: the wall the round was dealt from
//! and the decisions in the order the game took them.
//!
//! A tenhou.net/6 round lists each seat's draws and discards separately; the order of play across
//! seats follows from the rules of turn order: after a discard, a seat whose next "draw" is a
//! call on that tile (pon or kan before chi) takes it, a ron on a seat's last discard ends the
//! round, and otherwise the next seat draws. A kan is followed by a replacement draw from the
//! dead wall. Walking the round this way gives the live draws and replacement tiles in wall order.
//!
//! The log does not say when a seat passed a call, so a seat's next call on a tile code from the
//! discarder may belong to a later discard of the same code (the seat passed this one, and a pon
//! elsewhere skipped its draw in between). Each discard some seat's next entry could call is a
//! decision (each such call, or none); the walk takes the first choice of each, and when the rest
//! of the log then cannot be placed, the decisions are searched depth first until it can.

use super::log::{Discard, Draw, LoggedDraw, Outcome, Round};
use rinshan_engine::generated::red as k;
use rinshan_engine::tile::Tile;
use rinshan_engine::Variant;

pub(crate) mod wall;

use wall::build_wall;

/// The plan's id of kita, which red's layout (four players) has no place for: one past its ids.
pub const KITA: u32 = k::NUM_ACTIONS;

/// The plan's action ids (red's, and [`KITA`]) in a variant's layout, or the other way.
#[derive(Debug, Clone)]
pub struct MoveIds {
    map: rinshan_engine::env::ActionMap,
    /// Kita on the side mapped from, and on the side mapped to (`ACTION_ABSENT` where that
    /// side has none: four players).
    kita: (u32, u32),
}

impl MoveIds {
    /// The plan's ids in `variant`'s layout (what a replay plays).
    pub fn new(variant: Variant) -> MoveIds {
        MoveIds {
            map: rinshan_engine::env::ActionMap::new(Variant::Red, variant),
            kita: (KITA, rinshan_engine::with_variant!(variant, v => v::ACTION_KITA)),
        }
    }

    /// `variant`'s ids as the plan's (what a recorder writes).
    pub fn to_plan(variant: Variant) -> MoveIds {
        MoveIds {
            map: rinshan_engine::env::ActionMap::new(variant, Variant::Red),
            kita: (rinshan_engine::with_variant!(variant, v => v::ACTION_KITA), KITA),
        }
    }

    /// The id of `action` on the other side; `None` where that side has no such action.
    pub fn get(&self, action: u32) -> Option<u32> {
        match self.kita {
            (from, to) if action == from => (to != k::ACTION_ABSENT).then_some(to),
            _ => self.map.get(action),
        }
    }
}

/// One decision of the logged game.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Move {
    /// The seat deciding.
    pub seat: usize,
    /// Action id of the red variant, or [`KITA`].
    pub action: u32,
    /// A claim on a discard (or on a kan tile): the engine may ask other seats first.
    pub claim: bool,
    /// What the log says, for messages (`discard 5m`, `pon 7z from seat 2`).
    pub what: String,
}

/// One entry of the log, placed in the order of play.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Played {
    /// Seat's draw entry: a tile from the wall (`replacement`: from the dead wall after a kan)
    /// or a call.
    Draw {
        /// The seat.
        seat: usize,
        /// The entry.
        draw: Draw,
        /// A replacement draw after a kan.
        replacement: bool,
    },
    /// Seat's discard entry (a discard, riichi, a kan, a kita, or the `0` after an open kan).
    Discard {
        /// The seat.
        seat: usize,
        /// The entry.
        discard: Discard,
    },
}

/// A round ready to replay.
#[derive(Debug, Clone)]
pub struct Plan {
    /// The tiles in the engine's dealing order (`WALL_*` in rules/kernel/game_round.rs; three
    /// players fill the first 108).
    pub wall: [Tile; 136],
    /// The logged decisions in the order of play.
    pub moves: Vec<Move>,
    /// Riichi sticks each seat put on the table (declarations whose discard was not ronned).
    pub riichi_paid: [u32; 4],
    /// Every entry of the log in the order of play (what an event log such as MJAI lists).
    pub order: Vec<Played>,
}

impl Plan {
    /// The deal that starts `round` (logged as this plan's round) from the plan's wall, for a
    /// game of `variant`: without red fives, the unseen tiles that fill the wall are black too
    /// (the logged ones are, [`crate::tenhou::log`] checks); with them, a round that shows four
    /// black copies of a five cannot be dealt.
    pub fn deal(&self, round: &Round, variant: Variant) -> Result<rinshan_engine::env::Deal, String> {
        let in_play = |t: Tile| variant.tile_in_play(u32::from(t.kind().index() as u8));
        let wall = if variant.red_fives() {
            for red in (34..37).filter_map(Tile::from_value).filter(|&t| in_play(t)) {
                if !self.wall.contains(&red) {
                    let black = Tile::plain(red.kind());
                    return Err(format!(
                        "four black {black} shown: {variant} has a red one among the four"
                    ));
                }
            }
            self.wall
        } else {
            self.wall.map(|t| Tile::plain(t.kind()))
        };
        Ok(rinshan_engine::env::Deal {
            round: round.table_round(),
            dealer: round.dealer() as u32,
            honba: round.honba,
            sticks: round.sticks,
            scores: round.scores,
            wall,
        })
    }
}

/// Walks tried per round before giving up (a wrong call decision is usually caught within a
/// few turns, so the search stays small).
const MAX_WALKS: usize = 4096;

struct Walker<'a> {
    round: &'a Round,
    /// The option to take at each call decision met (index by decision), 0 past the end.
    choices: &'a [usize],
    /// How many options each call decision met had.
    options: Vec<usize>,
    drawn: [usize; 4],
    discarded: [usize; 4],
    live: Vec<Tile>,
    rinshan: Vec<Tile>,
    moves: Vec<Move>,
    riichi: [Option<usize>; 4],
    /// The seat whose discard (or kan) the round's rons took, once the walk meets it.
    ronned: Option<usize>,
    order: Vec<Played>,
}

impl<'a> Walker<'a> {
    fn push(&mut self, seat: usize, action: u32, claim: bool, what: String) {
        self.moves.push(Move {
            seat,
            action,
            claim,
            what,
        });
    }

    /// Seat `p` draws (a replacement tile after a kan); `false` when its draws are used up.
    fn draw(&mut self, p: usize, replacement: bool) -> Result<bool, String> {
        let Some(d) = self.round.draws[p].get(self.drawn[p]) else {
            return Ok(false);
        };
        let Draw::Tile(t) = d else {
            return Err(format!(
                "draws of seat {p}, entry {}: seat {p} is to draw here, but the log has a call",
                self.drawn[p] + 1
            ));
        };
        self.drawn[p] += 1;
        self.order.push(Played::Draw {
            seat: p,
            draw: *d,
            replacement,
        });
        if replacement {
            self.rinshan.push(*t);
        } else {
            self.live.push(*t);
        }
        Ok(true)
    }

    /// The rons on the tile seat `p` just gave up (its last discard or kan), if the round ended so.
    fn rons_on(&self, p: usize) -> Vec<usize> {
        let seats = self.round.seats;
        if self.discarded[p] != self.round.discards[p].len() {
            return Vec::new();
        }
        match &self.round.outcome {
            Outcome::Wins(wins) => {
                let mut winners: Vec<usize> = wins
                    .iter()
                    .filter(|w| !w.tsumo && w.from == p)
                    .map(|w| w.winner)
                    .collect();
                winners.sort_by_key(|&q| (q + seats - p) % seats);
                winners
            }
            // The log of a triple ron names no discarder: the ronned tile is the round's last
            // one, so every other seat's entries are used up by then (a seat's last discard
            // can come a go-around before the round ends).
            Outcome::Draw {
                kind: LoggedDraw::TripleRon,
                ..
            } if (0..4).all(|q| {
                q == p
                    || (self.drawn[q] == self.round.draws[q].len() && self.discarded[q] == self.round.discards[q].len())
            }) =>
            {
                (1..4).map(|j| (p + j) % 4).collect()
            }
            Outcome::Draw { .. } => Vec::new(),
        }
    }

    /// The seat that calls tile `t` discarded by `p`, if any: the seats whose next draw entry
    /// calls it (pon and kan first, then chi) and nobody are the options of a decision.
    fn caller(&mut self, p: usize, t: Tile) -> Option<(usize, Draw)> {
        let seats = self.round.seats;
        let mut callers = Vec::new();
        let mut chi = None;
        for j in 1..seats {
            let q = (p + j) % seats;
            let Some(d) = self.round.draws[q].get(self.drawn[q]) else {
                continue;
            };
            match d {
                Draw::Pon { called, from, .. } | Draw::OpenKan { called, from, .. }
                    if from.seat_of(q) == p && *called == t =>
                {
                    callers.push((q, *d));
                }
                Draw::Chi { called, .. } if j == 1 && *called == t => chi = Some((q, *d)),
                _ => {}
            }
        }
        callers.extend(chi);
        if callers.is_empty() {
            return None;
        }
        let decision = self.options.len();
        self.options.push(callers.len() + 1);
        callers.get(self.choices.get(decision).copied().unwrap_or(0)).copied()
    }

    /// Plays seat `p`'s turn from its next discard entry on; returns the seat that draws next
    /// (with `true` for a replacement draw), or `None` when the round ends.
    fn turn(&mut self, mut p: usize) -> Result<Option<(usize, bool)>, String> {
        loop {
            let entry = self.round.discards[p].get(self.discarded[p]).copied();
            let at = self.discarded[p] + 1;
            let Some(entry) = entry else {
                return self.end_of_turns(p).map(|()| None);
            };
            self.discarded[p] += 1;
            self.order.push(Played::Discard {
                seat: p,
                discard: entry,
            });
            let (tile, tsumogiri) = match entry {
                Discard::Tile(t) => (Some(t), false),
                Discard::Tsumogiri => (None, true),
                Discard::Riichi(t) => {
                    self.push(p, k::ACTION_RIICHI, false, "riichi".into());
                    self.riichi[p] = Some(self.discarded[p]);
                    (t, t.is_none())
                }
                Discard::AddedKan { added, .. } | Discard::ClosedKan { tiles: [added, ..] } => {
                    let kind = if matches!(entry, Discard::AddedKan { .. }) {
                        "added"
                    } else {
                        "closed"
                    };
                    self.push(
                        p,
                        k::ACTION_SELF_KAN + u32::from(added.kind()),
                        false,
                        format!("{kind} kan {}", added.name()),
                    );
                    let rons = self.rons_on(p);
                    if !rons.is_empty() {
                        self.ronned = Some(p);
                        for q in rons {
                            self.push(q, k::ACTION_RON, true, format!("ron (chankan) on {}", added.name()));
                        }
                        return Ok(None);
                    }
                    return Ok(Some((p, true)));
                }
                Discard::Kita => {
                    self.push(p, KITA, false, "kita".into());
                    let rons = self.rons_on(p);
                    if !rons.is_empty() {
                        self.ronned = Some(p);
                        for q in rons {
                            self.push(q, k::ACTION_RON, true, "ron on a kita".into());
                        }
                        return Ok(None);
                    }
                    return Ok(Some((p, true)));
                }
                Discard::Nothing => {
                    return Err(format!(
                        "discards of seat {p}, entry {at}: `0` stands only after an open kan"
                    ))
                }
            };
            let discarded = match (tile, tsumogiri) {
                (Some(t), false) => {
                    self.push(
                        p,
                        k::ACTION_DISCARD + u32::from(t.value()),
                        false,
                        format!("discard {}", t.name()),
                    );
                    t
                }
                _ => {
                    self.push(p, k::ACTION_TSUMOGIRI, false, "tsumogiri".into());
                    match self.last_draw(p) {
                        Some(t) => t,
                        None => {
                            return Err(format!(
                                "discards of seat {p}, entry {at}: tsumogiri (60) without a drawn tile"
                            ))
                        }
                    }
                }
            };
            let rons = self.rons_on(p);
            if !rons.is_empty() {
                self.ronned = Some(p);
                for q in rons {
                    self.push(q, k::ACTION_RON, true, format!("ron on {}", discarded.name()));
                }
                return Ok(None);
            }
            let Some((q, call)) = self.caller(p, discarded) else {
                return Ok(Some(((p + 1) % self.round.seats, false)));
            };
            self.drawn[q] += 1;
            self.order.push(Played::Draw {
                seat: q,
                draw: call,
                replacement: false,
            });
            let name = discarded.name();
            match call {
                Draw::Chi { called, own } => {
                    let (a, b) = (own[0].kind(), own[1].kind());
                    let c = called.kind();
                    let red = own.iter().any(|t| t.is_red());
                    let (plain, reds, shape) = if a > c && b > c {
                        (k::ACTION_CHI_LEFT, k::ACTION_CHI_LEFT_RED, "left")
                    } else if a < c && b < c {
                        (k::ACTION_CHI_RIGHT, k::ACTION_CHI_RIGHT_RED, "right")
                    } else {
                        (k::ACTION_CHI_MIDDLE, k::ACTION_CHI_MIDDLE_RED, "middle")
                    };
                    let action = if red { reds } else { plain };
                    self.push(q, action, true, format!("chi ({shape}) {name} from seat {p}"));
                }
                Draw::Pon { own, .. } => {
                    let action = if own.iter().any(|t| t.is_red()) {
                        k::ACTION_PON_RED
                    } else {
                        k::ACTION_PON
                    };
                    self.push(q, action, true, format!("pon {name} from seat {p}"));
                }
                Draw::OpenKan { .. } => {
                    self.push(q, k::ACTION_OPEN_KAN, true, format!("open kan {name} from seat {p}"));
                    match self.round.discards[q].get(self.discarded[q]) {
                        Some(Discard::Nothing) => {
                            self.discarded[q] += 1;
                            self.order.push(Played::Discard {
                                seat: q,
                                discard: Discard::Nothing,
                            });
                        }
                        _ => {
                            return Err(format!(
                                "discards of seat {q}, entry {}: an open kan is followed by `0`",
                                self.discarded[q] + 1
                            ))
                        }
                    }
                    return Ok(Some((q, true)));
                }
                Draw::Tile(_) => unreachable!("`caller` returns calls only"),
            }
            p = q;
        }
    }

    fn last_draw(&self, p: usize) -> Option<Tile> {
        match self.round.draws[p].get(self.drawn[p].checked_sub(1)?) {
            Some(Draw::Tile(t)) => Some(*t),
            _ => None,
        }
    }

    /// Seat `p` has no discard left on its turn: it won by tsumo or declared kyuushu.
    fn end_of_turns(&mut self, p: usize) -> Result<(), String> {
        match &self.round.outcome {
            Outcome::Wins(wins) if wins.iter().any(|w| w.tsumo && w.winner == p) => {
                self.push(p, k::ACTION_TSUMO, false, "tsumo".into());
                Ok(())
            }
            Outcome::Draw {
                kind: LoggedDraw::Kyuushu,
                ..
            } => {
                self.push(p, k::ACTION_KYUUSHU, false, "kyuushu kyuuhai".into());
                Ok(())
            }
            _ => Err(format!(
                "discards of seat {p}: the log stops on seat {p}'s turn, but the round did not end by its tsumo or kyuushu"
            )),
        }
    }

    /// Plays the whole round; `Err` when the log cannot be placed with these call decisions.
    fn walk(&mut self) -> Result<(), String> {
        let round = self.round;
        let mut next = Some((round.dealer(), false));
        while let Some((p, replacement)) = next {
            if !self.draw(p, replacement)? {
                if replacement {
                    return Err(format!("draws of seat {p}: a kan with no replacement tile after it"));
                }
                break;
            }
            next = self.turn(p)?;
        }
        for p in 0..4 {
            if self.drawn[p] != round.draws[p].len() || self.discarded[p] != round.discards[p].len() {
                return Err(format!(
                    "seat {p}: {} of {} draws and {} of {} discards are reached in turn order; the rest cannot be placed",
                    self.drawn[p],
                    round.draws[p].len(),
                    self.discarded[p],
                    round.discards[p].len()
                ));
            }
        }
        Ok(())
    }
}

/// Walks `round` in the order of play and builds its wall.
pub fn plan(round: &Round) -> Result<Plan, String> {
    let mut choices: Vec<usize> = Vec::new();
    let mut first_error = None;
    for _ in 0..MAX_WALKS {
        let mut w = Walker {
            round,
            choices: &choices,
            options: Vec::new(),
            drawn: [0; 4],
            discarded: [0; 4],
            live: Vec::new(),
            rinshan: Vec::new(),
            moves: Vec::new(),
            riichi: [None; 4],
            ronned: None,
            order: Vec::new(),
        };
        match w.walk() {
            Ok(()) => return finish(w),
            Err(e) => {
                // The first walk's error is the one to report: it says where the log stops
                // fitting the plainest order of play.
                first_error.get_or_insert(e);
                // The next decisions depth first: the last decision with an option left takes
                // its next option, the ones after it start over.
                let mut next = choices.clone();
                next.resize(w.options.len(), 0);
                match (0..next.len()).rev().find(|&i| next[i] + 1 < w.options[i]) {
                    Some(i) => {
                        next.truncate(i + 1);
                        next[i] += 1;
                        choices = next;
                    }
                    None => break,
                }
            }
        }
    }
    Err(first_error.unwrap_or_default())
}

/// The plan of a walk that placed the whole log.
fn finish(w: Walker) -> Result<Plan, String> {
    let round = w.round;
    let riichi_paid: [u32; 4] = std::array::from_fn(|p| match w.riichi[p] {
        // Asking `rons_on` here would be wrong for a triple ron: once the walk is over every
        // seat's entries are used up, so each seat would look like the one ronned.
        Some(at) => u32::from(at != round.discards[p].len() || w.ronned != Some(p)),
        None => 0,
    });
    Ok(Plan {
        wall: build_wall(round, &w.live, &w.rinshan)?,
        moves: w.moves,
        riichi_paid,
        order: w.order,
    })
}
