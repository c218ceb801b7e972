//! The events of one round, each landing in the seat's draw or discard list as Tenhou writes it
//! (a `tsumogiri` discard as `60`, `reach` + `dahai` as `r..`, an open kan followed by `0`), and
//! the round's end. Every event is checked for what the next ones rely on (seats 0-3, tiles
//! known, a call naming the discard just made, a kan on a pon the seat holds). The extras are
//! optional except what a replay checks: a `hora` needs its `deltas`; one without `yakus`
//! (libriichi's) is scored when the round is whole ([`super::unlogged`]).

use rinshan_engine::tile::{Tile, TileType};
use rinshan_engine::Variant;

use super::event::Event;
use super::tile::Pai;
use super::unlogged::unscored;
use super::write::REASONS;
use super::yaku::{hora_yaku, win, DRAGONS};
use crate::tenhou::log::{Discard, Draw, LoggedDraw, LoggedWin, Rel, Round};
use crate::tenhou::write::Scoring;

/// A round being read.
pub(super) struct Open {
    pub(super) round: Round,
    pub(super) wins: Vec<LoggedWin>,
    pub(super) draw: Option<(LoggedDraw, Option<[i32; 4]>)>,
    last_draw: [Option<Tile>; 4],
    riichi: [bool; 4],
    /// The last discard: its seat and tile, while it can still be called.
    last_discard: Option<(usize, Tile)>,
    /// The last tile given up to the table (a discard, or a kan's tile that chankan robs).
    last_given: Option<Tile>,
    /// Kans declared so far (each reveals one more dora indicator).
    kans: usize,
    /// Each seat's tiles by type, melds included (to tell the dragons of a `sangenpai` apart).
    held: [[u8; 34]; 4],
    /// The rules the game is played under (its points texts follow their scoring).
    variant: Variant,
    /// Draws made so far, replacement draws included (the wall's end tells an exhaustive draw).
    drawn: u32,
    /// The seat whose draw was the last event.
    just_drew: Option<usize>,
    /// Riichi sticks put down this round (`reach_accepted`).
    accepted: usize,
    /// Every tile discarded this round, in order (four winds abort the round).
    discarded: Vec<Tile>,
    /// The `ryukyoku` named no reason (libriichi's): its kind was told from the round, and an
    /// exhaustive draw's tenpai seats (or nagashi) are the engine's ([`super::unlogged`]).
    pub(super) unstated: bool,
}

pub(super) fn actor_of(a: u8) -> Result<usize, String> {
    (a < 4)
        .then_some(usize::from(a))
        .ok_or_else(|| format!("seat {a} is not 0-3"))
}

pub(super) fn known(p: Pai, what: &str) -> Result<Tile, String> {
    p.0.ok_or_else(|| format!("{what} is `?`: a log of one seat's view cannot be read as a whole game"))
}

pub(super) fn all_known<const N: usize>(ps: [Pai; N], what: &str) -> Result<[Tile; N], String> {
    let tiles: Vec<Tile> = ps.iter().map(|&p| known(p, what)).collect::<Result<_, _>>()?;
    tiles
        .try_into()
        .map_err(|_| format!("{what} has the wrong number of tiles"))
}

/// Where seat `from` sits seen from `me`.
pub(super) fn rel(me: usize, from: usize) -> Result<Rel, String> {
    if me == from {
        return Err(format!("seat {me} calls its own discard"));
    }
    Ok(Rel::between(me, from))
}

impl Open {
    pub(super) fn new(round: Round, variant: Variant) -> Open {
        let held = std::array::from_fn(|s: usize| {
            let mut counts = [0u8; 34];
            for t in &round.hands[s] {
                counts[t.kind().index()] = counts[t.kind().index()].saturating_add(1);
            }
            counts
        });
        Open {
            round,
            wins: Vec::new(),
            draw: None,
            last_draw: [None; 4],
            riichi: [false; 4],
            last_discard: None,
            last_given: None,
            kans: 0,
            held,
            variant,
            drawn: 0,
            just_drew: None,
            accepted: 0,
            discarded: Vec::new(),
            unstated: false,
        }
    }

    /// Seat `a`, which must sit at the table.
    fn actor(&self, a: u8) -> Result<usize, String> {
        let s = actor_of(a)?;
        match s < self.round.seats {
            true => Ok(s),
            false => Err(format!("seat {a}: three players sit at seats 0-2")),
        }
    }

    fn take(&mut self, s: usize, t: Tile) {
        let count = &mut self.held[s][t.kind().index()];
        *count = count.saturating_add(1);
    }

    /// The yakuhai of the dragons the winner holds three or more of (with the tile won on).
    fn dragons(&self, winner: usize, won: Option<Tile>) -> Vec<&'static str> {
        let mut held = self.held[winner];
        if let Some(t) = won {
            held[t.kind().index()] = held[t.kind().index()].saturating_add(1);
        }
        DRAGONS
            .iter()
            .filter(|(_, kind)| held[*kind] >= 3)
            .map(|(name, _)| *name)
            .collect()
    }

    /// Seat `actor` calls `pai` from `target`: the seat, the tile and where it came from.
    fn call(&mut self, actor: u8, target: u8, pai: Pai) -> Result<(usize, Tile, Rel), String> {
        let s = self.actor(actor)?;
        let called = known(pai, "the tile called")?;
        let from = self.called(s, self.actor(target)?, called)?;
        self.take(s, called);
        Ok((s, called, from))
    }

    fn called(&mut self, actor: usize, target: usize, pai: Tile) -> Result<Rel, String> {
        match self.last_discard.take() {
            Some((s, t)) if s == target && t == pai => rel(actor, target),
            _ => Err(format!(
                "seat {actor} calls {} from seat {target}, which is not the discard just made",
                Pai::known(pai)
            )),
        }
    }

    pub(super) fn play(&mut self, event: Event) -> Result<(), String> {
        let kind = event.kind();
        let just_drew = self.just_drew.take();
        match event {
            Event::Tsumo { actor, pai } => {
                let s = self.actor(actor)?;
                let t = known(pai, "the tile drawn")?;
                self.drawn += 1;
                self.just_drew = Some(s);
                self.last_discard = None;
                self.last_draw[s] = Some(t);
                self.take(s, t);
                self.round.draws[s].push(Draw::Tile(t));
            }
            Event::Dahai { actor, pai, tsumogiri } => {
                let s = self.actor(actor)?;
                let t = known(pai, "the tile discarded")?;
                if tsumogiri && self.last_draw[s] != Some(t) {
                    return Err(format!(
                        "seat {s} discards {pai} as tsumogiri, but did not just draw it"
                    ));
                }
                let entry = match (std::mem::take(&mut self.riichi[s]), tsumogiri) {
                    (true, true) => Discard::Riichi(None),
                    (true, false) => Discard::Riichi(Some(t)),
                    (false, true) => Discard::Tsumogiri,
                    (false, false) => Discard::Tile(t),
                };
                self.last_draw[s] = None;
                self.last_discard = Some((s, t));
                self.discarded.push(t);
                self.last_given = Some(t);
                let count = &mut self.held[s][t.kind().index()];
                *count = count.saturating_sub(1);
                self.round.discards[s].push(entry);
            }
            Event::Chi {
                actor,
                target,
                pai,
                consumed,
            } => {
                let (s, called, from) = self.call(actor, target, pai)?;
                if from != Rel::Left {
                    return Err(format!("seat {s} calls chi from seat {target}, not the seat before it"));
                }
                let own = all_known(consumed, "consumed")?;
                self.round.draws[s].push(Draw::Chi { called, own });
            }
            Event::Pon {
                actor,
                target,
                pai,
                consumed,
            } => {
                let (s, called, from) = self.call(actor, target, pai)?;
                let own = all_known(consumed, "consumed")?;
                self.round.draws[s].push(Draw::Pon { called, own, from });
            }
            Event::Daiminkan {
                actor,
                target,
                pai,
                consumed,
            } => {
                let (s, called, from) = self.call(actor, target, pai)?;
                let own = all_known(consumed, "consumed")?;
                self.kans += 1;
                self.round.draws[s].push(Draw::OpenKan { called, own, from });
                self.round.discards[s].push(Discard::Nothing);
            }
            Event::Kakan { actor, pai, .. } => {
                let s = self.actor(actor)?;
                let added = known(pai, "the tile added")?;
                // The pon as the log recorded it, so the kan is written as Tenhou writes it.
                let pon = self.round.draws[s].iter().rev().find_map(|d| match *d {
                    Draw::Pon { called, own, from } if called.kind() == added.kind() => Some((called, own, from)),
                    _ => None,
                });
                let (called, own, from) =
                    pon.ok_or_else(|| format!("seat {s} adds {pai} to a pon it does not have"))?;
                self.last_discard = None;
                self.last_draw[s] = None;
                self.last_given = Some(added);
                self.kans += 1;
                self.round.discards[s].push(Discard::AddedKan {
                    added,
                    pon: [called, own[0], own[1]],
                    from,
                });
            }
            Event::Ankan { actor, consumed } => {
                let s = self.actor(actor)?;
                let tiles = all_known(consumed, "consumed")?;
                if tiles.iter().any(|t| t.kind() != tiles[0].kind()) {
                    return Err(format!("seat {s}'s ankan is not four of one tile"));
                }
                self.last_discard = None;
                self.last_draw[s] = None;
                self.last_given = Some(tiles[0]);
                self.kans += 1;
                self.round.discards[s].push(Discard::ClosedKan { tiles });
            }
            Event::Kita { actor, .. } => {
                let s = self.actor(actor)?;
                if self.round.seats != 3 {
                    return Err(format!("seat {s} sets North aside (kita) in a four-player game"));
                }
                let north = Tile::plain(TileType::NORTH);
                self.last_discard = None;
                self.last_draw[s] = None;
                // A kita can be ronned, as a discard can.
                self.last_given = Some(north);
                let count = &mut self.held[s][north.kind().index()];
                *count = count.saturating_sub(1);
                self.round.discards[s].push(Discard::Kita);
            }
            Event::Dora { dora_marker } => {
                let t = known(dora_marker, "dora_marker")?;
                if self.round.dora.len() > self.kans {
                    return Err(format!("dora {dora_marker}: no kan is left to reveal it"));
                }
                self.round.dora.push(t);
            }
            Event::Reach { actor } => {
                let s = self.actor(actor)?;
                self.riichi[s] = true;
            }
            Event::ReachAccepted { actor, .. } => {
                self.actor(actor)?;
                self.accepted += 1;
            }
            Event::Hora {
                actor,
                target,
                deltas,
                ura_markers,
                yakus,
                fu,
                fan,
                pao,
                ..
            } => {
                let winner = self.actor(actor)?;
                let from = self.actor(target)?;
                let deltas = deltas.ok_or("hora without deltas: a replay checks every score change")?;
                let pao = pao.map(|a| self.actor(a)).transpose()?.unwrap_or(winner);
                if let (Some(ura), true) = (ura_markers, self.round.ura.is_empty()) {
                    self.round.ura = ura
                        .into_iter()
                        .map(|p| known(p, "ura_markers"))
                        .collect::<Result<_, _>>()?;
                }
                let Some(yakus) = yakus else {
                    // libriichi's hora: scored once the round is whole.
                    self.wins.push(unscored(winner, from, pao, deltas));
                    return Ok(());
                };
                // The tile won on, for a ron: the discard (or the kan tile robbed).
                let won = if winner == from { None } else { self.last_given };
                let yaku = hora_yaku(yakus, fan, || self.dragons(winner, won))?;
                let dealer = winner == self.round.dealer();
                let scoring = Scoring::of(self.variant);
                self.wins
                    .push(win(scoring, winner, from, pao, deltas, fu, fan, yaku, dealer));
            }
            Event::Ryukyoku {
                reason,
                tenpais,
                deltas,
            } => {
                let paid = deltas.is_some_and(|d| d.iter().any(|&x| x != 0));
                if reason.is_none() && tenpais.is_none() {
                    self.unstated = true;
                    if !paid {
                        self.draw = Some((self.unstated_draw(just_drew), None));
                        return Ok(());
                    }
                }
                let reason = reason.as_deref().unwrap_or("fanpai");
                let mut kinds = REASONS.iter().filter(|(_, r)| *r == reason).map(|(k, _)| *k);
                let kind = kinds
                    .next()
                    .ok_or_else(|| format!("unknown ryukyoku reason {reason:?}"))?;
                let (kind, deltas) = match (kind, deltas) {
                    // Payments say who was tenpai (`tenpais`, given too, may not say otherwise);
                    // without any, 0 or 4 seats were.
                    (LoggedDraw::Exhaustive, Some(d)) if d.iter().any(|&x| x != 0) => {
                        let contradicts =
                            tenpais.is_some_and(|t| (0..4).any(|s| (d[s] > 0 && !t[s]) || (d[s] < 0 && t[s])));
                        if contradicts {
                            return Err(format!("tenpais {tenpais:?} contradict the deltas {d:?}"));
                        }
                        (LoggedDraw::Exhaustive, Some(d))
                    }
                    (LoggedDraw::Exhaustive, _) => match tenpais.map_or(0, |t| t.iter().filter(|&&t| t).count()) {
                        0 => (LoggedDraw::NoTenpai, None),
                        n if n == self.round.seats => (LoggedDraw::AllTenpai, None),
                        n => return Err(format!("{n} seats tenpai, but the deltas pay them nothing")),
                    },
                    (kind, deltas) => (
                        kind,
                        deltas.filter(|d| kind == LoggedDraw::Nagashi || d.iter().any(|&x| x != 0)),
                    ),
                };
                self.draw = Some((kind, deltas));
            }
            _ => return Err(format!("{kind} is not an event of a round")),
        }
        Ok(())
    }

    /// The kind of a draw whose `ryukyoku` says neither why nor who was tenpai and pays nothing,
    /// as libriichi writes every abortive draw (and an exhaustive one with no seat or every
    /// seat tenpai), told from the round: `just_drew` is the seat whose draw came last.
    fn unstated_draw(&mut self, just_drew: Option<usize>) -> LoggedDraw {
        let wall = self.variant.wall();
        let wall_draws = wall.live_end - wall.live_start;
        match just_drew {
            // libriichi deals the next draw before it ends the round on the fourth riichi stick;
            // Tenhou's rules (and the log of the round here) end it before that draw.
            Some(s) if self.accepted == 4 => {
                if let Some(Draw::Tile(t)) = self.round.draws[s].pop() {
                    let count = &mut self.held[s][t.kind().index()];
                    *count = count.saturating_sub(1);
                }
                self.last_draw[s] = None;
                self.drawn -= 1;
                LoggedDraw::FourRiichi
            }
            Some(_) => LoggedDraw::Kyuushu,
            None if self.accepted == 4 => LoggedDraw::FourRiichi,
            // Which of no seat and every seat was tenpai: the engine's word ([`Open::unstated`]).
            None if self.drawn >= wall_draws => LoggedDraw::NoTenpai,
            None if self.kans >= 4 => LoggedDraw::FourKans,
            None if self.four_winds() => LoggedDraw::FourWinds,
            // What else ends a round after a discard: three seats ron it.
            None => LoggedDraw::TripleRon,
        }
    }

    /// The round's only discards are four of one wind, and nobody called or declared a kan.
    fn four_winds(&self) -> bool {
        let wind = |t: &Tile| (27..31).contains(&t.kind().index());
        let calls = (0..4).any(|s| self.round.draws[s].iter().any(|d| !matches!(d, Draw::Tile(_))));
        match self.discarded.as_slice() {
            [first, rest @ ..] => {
                self.round.seats == 4
                    && self.kans == 0
                    && !calls
                    && rest.len() == 3
                    && wind(first)
                    && rest.iter().all(|t| t.kind() == first.kind())
            }
            [] => false,
        }
    }
}
