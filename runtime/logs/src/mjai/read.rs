//! MJAI logs (one event per line, a whole game from `start_game` to `end_game`) read into the
//! same [`Game`] the tenhou.net/6 reader gives, so that replaying, converting and rendering work
//! on either. Each event lands in the seat's draw or discard list as Tenhou writes it (a
//! `tsumogiri` discard as `60`, `reach` + `dahai` as `r..`, an open kan followed by `0`).
//!
//! The extras are optional except what a replay checks: a `hora` needs its `deltas`. A win's
//! points text is rebuilt from `fu`, `fan` and the yaku by the scoring kernel's rules (a hand
//! with under 5 han and no fu is taken for a mangan, as Tenhou writes no fu for limit hands).
//! Every event is checked for what the next ones rely on (seats 0-3, tiles known, a call naming
//! the discard just made, a kan on a pon the seat holds); an error names the line.

use rinshan_engine::hand::{Yaku, YakuHan};
use rinshan_engine::tile::Tile;

use super::event::Event;
use super::tile::Pai;
use super::write::{REASONS, YAKUMAN_HAN};
use crate::tenhou::log::{
    our_yaku, parse_round_value, round_name, Discard, Draw, Game, LogError, LoggedDraw, LoggedWin, Outcome, Rel, Round,
};
use crate::tenhou::write::{base_points, limit_of, payment, points_text, round_value};

/// The original mjai server's yaku names (also written by the Tenhou-to-MJAI converters) and
/// ours. Its `sangenpai` sums the dragon triplets; the reader tells them apart from the hand.
pub(crate) const MJAI_YAKU: [(&str, &str); 41] = [
    ("reach", "riichi"),
    ("double_reach", "double_riichi"),
    ("ippatsu", "ippatsu"),
    ("menzenchin_tsumoho", "menzen_tsumo"),
    ("tanyaochu", "tanyao"),
    ("pinfu", "pinfu"),
    ("ipeko", "iipeikou"),
    ("bakaze", "yakuhai_round_wind"),
    ("jikaze", "yakuhai_seat_wind"),
    ("rinshankaiho", "rinshan"),
    ("chankan", "chankan"),
    ("haiteiraoyue", "haitei"),
    ("hoteiraoyui", "houtei"),
    ("sanshokudojun", "sanshoku_doujun"),
    ("ikkitsukan", "ittsu"),
    ("honchantaiyao", "chanta"),
    ("chitoitsu", "chiitoitsu"),
    ("toitoiho", "toitoi"),
    ("sananko", "sanankou"),
    ("honroto", "honroutou"),
    ("sanshokudoko", "sanshoku_doukou"),
    ("sankantsu", "sankantsu"),
    ("shosangen", "shousangen"),
    ("honiso", "honitsu"),
    ("junchantaiyao", "junchan"),
    ("ryanpeko", "ryanpeikou"),
    ("chiniso", "chinitsu"),
    ("tenho", "tenhou"),
    ("chiho", "chiihou"),
    ("kokushimuso", "kokushi"),
    ("daisangen", "daisangen"),
    ("suanko", "suuankou"),
    ("tsuiso", "tsuuiisou"),
    ("ryuiso", "ryuuiisou"),
    ("chinroto", "chinroutou"),
    ("daisushi", "daisuushi"),
    ("shosushi", "shousuushi"),
    ("sukantsu", "suukantsu"),
    ("churenpoton", "chuuren"),
    ("uradora", "ura"),
    ("akadora", "aka"),
];

/// The dragons' yakuhai with their tile types, in the order Tenhou lists them.
pub(crate) const DRAGONS: [(&str, usize); 3] = [("yakuhai_red", 33), ("yakuhai_green", 32), ("yakuhai_white", 31)];

/// Our name for a yaku named in our words or the original mjai's.
fn yaku_name(name: &str) -> Option<&'static str> {
    our_yaku(name)
        .or_else(|| MJAI_YAKU.iter().find(|(m, _)| *m == name).map(|(_, ours)| *ours))
        .or_else(|| ["dora", "aka", "ura"].into_iter().find(|d| *d == name))
}

/// Whether a text looks like an MJAI log: its first non-blank line is an object with a `type`.
pub fn is_mjai(text: &str) -> bool {
    let first = text.lines().map(str::trim).find(|l| !l.is_empty());
    first.is_some_and(|l| {
        serde_json::from_str::<serde_json::Map<String, serde_json::Value>>(l).is_ok_and(|m| m.contains_key("type"))
    })
}

/// Reads the text of an MJAI log; `path` only names it in messages.
pub fn parse_game(path: &str, text: &str) -> Result<Game, LogError> {
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    let mut builder = GameBuilder::new(path);
    for (index, line) in text.lines().enumerate() {
        if line.trim().is_empty() {
            continue;
        }
        let event: Event = serde_json::from_str(line).map_err(|e| {
            let position = format!(" at line {} column {}", e.line(), e.column());
            let full = e.to_string();
            let message = full.strip_suffix(&position).unwrap_or(&full).to_string();
            LogError {
                line: Some(index + 1),
                column: u32::try_from(e.column()).ok(),
                ..file_error(path, format!("not an MJAI event: {message}"))
            }
        })?;
        builder.event(event, index + 1)?;
    }
    builder.finish()
}

fn file_error(path: &str, message: String) -> LogError {
    LogError {
        file: path.to_string(),
        line: None,
        column: None,
        round: None,
        field: None,
        message,
    }
}

/// A game put together from MJAI events in the order of play, by any front end that can say
/// its format's moves as MJAI events (the MJAI text reader, the mjlog reader).
pub struct GameBuilder {
    reader: Reader,
}

impl GameBuilder {
    /// An empty game; `path` names the source in messages.
    pub fn new(path: &str) -> GameBuilder {
        GameBuilder {
            reader: Reader {
                game: Game {
                    path: path.to_string(),
                    rule: String::new(),
                    red_fives: true,
                    names: Default::default(),
                    rounds: Vec::new(),
                },
                round: None,
                finished: None,
                started: false,
                ended: false,
            },
        }
    }

    /// The next event, found at `line` of the source (1-based; a single-line format gives the
    /// position it has).
    pub fn event(&mut self, event: Event, line: usize) -> Result<(), LogError> {
        let reader = &mut self.reader;
        let path = reader.game.path.clone();
        let err = |message: String, round: Option<String>| LogError {
            line: Some(line),
            round,
            ..file_error(&path, message)
        };
        let round = reader.round.as_ref().map(|r| round_name(r.round.kyoku, r.round.honba));
        reader.event(event, line).map_err(|m| err(m, round))?;
        if let Some(done) = reader.finished.take() {
            // A round holds to the rules of a tenhou.net/6 round (a draw before each discard,
            // calls of real melds, a han count the yaku add up to), checked by that reader.
            let back = parse_round_value(&path, done.line, &round_value(&done), reader.game.red_fives)?;
            if back != done {
                return Err(err(
                    "the round's events do not read back as one round".into(),
                    Some(done.to_string()),
                ));
            }
            reader.game.rounds.push(done);
        }
        Ok(())
    }

    /// The game, once every event is in.
    pub fn finish(self) -> Result<Game, LogError> {
        let reader = self.reader;
        let path = &reader.game.path;
        if reader.round.is_some() {
            return Err(file_error(path, "the log stops inside a round (no end_kyoku)".into()));
        }
        if !reader.started {
            return Err(file_error(
                path,
                "no start_game event: not an MJAI log of a game".into(),
            ));
        }
        if reader.game.rounds.is_empty() {
            return Err(file_error(path, "the log holds no round (no start_kyoku)".into()));
        }
        Ok(reader.game)
    }
}

struct Reader {
    game: Game,
    round: Option<Open>,
    /// The round an `end_kyoku` just closed, to check before it joins the game.
    finished: Option<Round>,
    started: bool,
    ended: bool,
}

/// A round being read.
struct Open {
    round: Round,
    wins: Vec<LoggedWin>,
    draw: Option<(LoggedDraw, Option<[i32; 4]>)>,
    last_draw: [Option<Tile>; 4],
    riichi: [bool; 4],
    /// The last discard: its seat and tile, while it can still be called.
    last_discard: Option<(usize, Tile)>,
    /// The last tile given up to the table (a discard, or a kan's tile that chankan robs).
    last_given: Option<Tile>,
    /// Each seat's tiles by type, melds included (to tell the dragons of a `sangenpai` apart).
    held: [[u8; 34]; 4],
}

fn actor_of(a: u8) -> Result<usize, String> {
    (a < 4)
        .then_some(usize::from(a))
        .ok_or_else(|| format!("seat {a} is not 0-3"))
}

fn known(p: Pai, what: &str) -> Result<Tile, String> {
    p.0.ok_or_else(|| format!("{what} is `?`: a log of one seat's view cannot be read as a whole game"))
}

fn all_known<const N: usize>(ps: [Pai; N], what: &str) -> Result<[Tile; N], String> {
    let tiles: Vec<Tile> = ps.iter().map(|&p| known(p, what)).collect::<Result<_, _>>()?;
    tiles
        .try_into()
        .map_err(|_| format!("{what} has the wrong number of tiles"))
}

/// Where seat `from` sits seen from `me`.
fn rel(me: usize, from: usize) -> Result<Rel, String> {
    match (from + 4 - me) % 4 {
        1 => Ok(Rel::Right),
        2 => Ok(Rel::Across),
        3 => Ok(Rel::Left),
        _ => Err(format!("seat {me} calls its own discard")),
    }
}

impl Reader {
    fn event(&mut self, event: Event, line: usize) -> Result<(), String> {
        if self.ended {
            return Err(format!("{} after end_game: one file is one game", event.kind()));
        }
        match event {
            Event::None {} => Ok(()),
            Event::StartGame {
                names,
                kyoku_first,
                aka_flag,
                rule,
                ..
            } => {
                if self.started {
                    return Err("a second start_game: one file is one game".into());
                }
                self.started = true;
                self.game.names = names;
                self.game.red_fives = aka_flag.unwrap_or(true);
                let length = if kyoku_first == Some(4) { "東" } else { "南" };
                let red = if self.game.red_fives { "喰赤" } else { "喰" };
                self.game.rule = rule.unwrap_or_else(|| format!("{length}{red}"));
                Ok(())
            }
            Event::StartKyoku {
                bakaze,
                dora_marker,
                kyoku,
                honba,
                kyotaku,
                oya,
                scores,
                tehais,
            } => {
                if !self.started {
                    return Err("start_kyoku before start_game".into());
                }
                if self.round.is_some() {
                    return Err("start_kyoku inside a round (no end_kyoku before it)".into());
                }
                let wind = known(bakaze, "bakaze")?.kind().index();
                if !(27..31).contains(&wind) {
                    return Err(format!("bakaze {bakaze} is not a wind (E, S, W, N)"));
                }
                if !(1..=4).contains(&kyoku) {
                    return Err(format!("kyoku {kyoku} is not 1-4"));
                }
                let k = (wind as u32 - 27) * 4 + u32::from(kyoku) - 1;
                if actor_of(oya)? != (k % 4) as usize {
                    return Err(format!("oya {oya} is not the dealer of kyoku {kyoku} (seat {})", k % 4));
                }
                let mut hands: [Vec<Tile>; 4] = Default::default();
                for (s, tehai) in tehais.into_iter().enumerate() {
                    if tehai.len() != 13 {
                        return Err(format!("tehais of seat {s} has {} tiles, not 13", tehai.len()));
                    }
                    hands[s] = tehai
                        .into_iter()
                        .map(|p| known(p, &format!("a tile of seat {s}'s tehai")))
                        .collect::<Result<_, _>>()?;
                }
                let held = std::array::from_fn(|s: usize| {
                    let mut counts = [0u8; 34];
                    for t in &hands[s] {
                        counts[t.kind().index()] = counts[t.kind().index()].saturating_add(1);
                    }
                    counts
                });
                self.round = Some(Open {
                    round: Round {
                        line,
                        kyoku: k,
                        honba,
                        sticks: kyotaku,
                        scores,
                        dora: vec![known(dora_marker, "dora_marker")?],
                        ura: Vec::new(),
                        hands,
                        draws: Default::default(),
                        discards: Default::default(),
                        outcome: Outcome::Wins(Vec::new()),
                    },
                    wins: Vec::new(),
                    draw: None,
                    last_draw: [None; 4],
                    riichi: [false; 4],
                    last_discard: None,
                    last_given: None,
                    held,
                });
                Ok(())
            }
            Event::EndGame { .. } => {
                if self.round.is_some() {
                    return Err("end_game inside a round (no end_kyoku before it)".into());
                }
                self.ended = true;
                Ok(())
            }
            Event::EndKyoku {} => {
                let open = self.round.take().ok_or("end_kyoku outside a round")?;
                let mut round = open.round;
                round.outcome = match (open.wins.is_empty(), open.draw) {
                    (false, None) => Outcome::Wins(open.wins),
                    (true, Some((kind, deltas))) => Outcome::Draw { kind, deltas },
                    (true, None) => return Err("the round ends with neither hora nor ryukyoku".into()),
                    (false, Some(_)) => return Err("the round has both hora and ryukyoku".into()),
                };
                self.finished = Some(round);
                Ok(())
            }
            other => {
                let open = self
                    .round
                    .as_mut()
                    .ok_or_else(|| format!("{} outside a round (before start_kyoku)", other.kind()))?;
                if !open.wins.is_empty() && !matches!(other, Event::Hora { .. }) {
                    return Err(format!(
                        "{} after hora: only another hora or end_kyoku may follow",
                        other.kind()
                    ));
                }
                if open.draw.is_some() {
                    return Err(format!("{} after ryukyoku: only end_kyoku may follow", other.kind()));
                }
                open.play(other)
            }
        }
    }
}

impl Open {
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
        let s = actor_of(actor)?;
        let called = known(pai, "the tile called")?;
        let from = self.called(s, actor_of(target)?, called)?;
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

    fn play(&mut self, event: Event) -> Result<(), String> {
        let kind = event.kind();
        match event {
            Event::Tsumo { actor, pai } => {
                let s = actor_of(actor)?;
                let t = known(pai, "the tile drawn")?;
                self.last_discard = None;
                self.last_draw[s] = Some(t);
                self.take(s, t);
                self.round.draws[s].push(Draw::Tile(t));
            }
            Event::Dahai { actor, pai, tsumogiri } => {
                let s = actor_of(actor)?;
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
                self.round.draws[s].push(Draw::OpenKan { called, own, from });
                self.round.discards[s].push(Discard::Nothing);
            }
            Event::Kakan { actor, pai, .. } => {
                let s = actor_of(actor)?;
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
                self.round.discards[s].push(Discard::AddedKan {
                    added,
                    pon: [called, own[0], own[1]],
                    from,
                });
            }
            Event::Ankan { actor, consumed } => {
                let s = actor_of(actor)?;
                let tiles = all_known(consumed, "consumed")?;
                if tiles.iter().any(|t| t.kind() != tiles[0].kind()) {
                    return Err(format!("seat {s}'s ankan is not four of one tile"));
                }
                self.last_discard = None;
                self.last_draw[s] = None;
                self.last_given = Some(tiles[0]);
                self.round.discards[s].push(Discard::ClosedKan { tiles });
            }
            Event::Dora { dora_marker } => {
                let t = known(dora_marker, "dora_marker")?;
                self.round.dora.push(t);
            }
            Event::Reach { actor } => {
                let s = actor_of(actor)?;
                self.riichi[s] = true;
            }
            Event::ReachAccepted { actor, .. } => {
                actor_of(actor)?;
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
                let winner = actor_of(actor)?;
                let from = actor_of(target)?;
                let deltas = deltas.ok_or("hora without deltas: a replay checks every score change")?;
                let pao = pao.map(actor_of).transpose()?.unwrap_or(winner);
                if let (Some(ura), true) = (ura_markers, self.round.ura.is_empty()) {
                    self.round.ura = ura
                        .into_iter()
                        .map(|p| known(p, "ura_markers"))
                        .collect::<Result<_, _>>()?;
                }
                let yakus = yakus.ok_or("hora without yakus: a replay checks every win's yaku")?;
                // The tile won on, for a ron: the discard (or the kan tile robbed).
                let won = if winner == from { None } else { self.last_given };
                let mut yaku = Vec::new();
                for (name, han) in yakus {
                    if name == "sangenpai" {
                        let dragons = self.dragons(winner, won);
                        if dragons.len() as u32 != han {
                            return Err(format!(
                                "sangenpai {han}, but seat {winner} holds {} dragon triplets",
                                dragons.len()
                            ));
                        }
                        yaku.extend(dragons.into_iter().map(|name| Yaku {
                            name,
                            han: YakuHan::Han(1),
                        }));
                        continue;
                    }
                    let name = yaku_name(&name).ok_or_else(|| format!("unknown yaku {name:?}"))?;
                    let han = if han >= YAKUMAN_HAN && !["dora", "aka", "ura"].contains(&name) {
                        YakuHan::Yakuman(han / YAKUMAN_HAN)
                    } else {
                        YakuHan::Han(han)
                    };
                    yaku.push(Yaku { name, han });
                }
                let han_sum: u32 = yaku
                    .iter()
                    .map(|y| if let YakuHan::Han(h) = y.han { h } else { 0 })
                    .sum();
                let yakuman = yaku.iter().any(|y| matches!(y.han, YakuHan::Yakuman(_)));
                if let (Some(fan), false) = (fan, yakuman) {
                    if fan != han_sum {
                        return Err(format!("fan {fan}, but the yakus add up to {han_sum} han"));
                    }
                }
                let dealer = winner == self.round.dealer();
                self.wins.push(win(winner, from, pao, deltas, fu, fan, yaku, dealer));
            }
            Event::Ryukyoku {
                reason,
                tenpais,
                deltas,
            } => {
                let reason = reason.as_deref().unwrap_or("fanpai");
                let mut kinds = REASONS.iter().filter(|(_, r)| *r == reason).map(|(k, _)| *k);
                let kind = kinds
                    .next()
                    .ok_or_else(|| format!("unknown ryukyoku reason {reason:?}"))?;
                let (kind, deltas) = if kind == LoggedDraw::Exhaustive {
                    let tenpai = match (tenpais, deltas) {
                        (Some(t), _) => t.iter().filter(|&&t| t).count(),
                        (None, Some(d)) => d.iter().filter(|&&d| d > 0).count(),
                        (None, None) => 0,
                    };
                    match tenpai {
                        0 => (LoggedDraw::NoTenpai, None),
                        4 => (LoggedDraw::AllTenpai, None),
                        _ => (LoggedDraw::Exhaustive, deltas),
                    }
                } else {
                    (
                        kind,
                        deltas.filter(|d| kind == LoggedDraw::Nagashi || d.iter().any(|&x| x != 0)),
                    )
                };
                self.draw = Some((kind, deltas));
            }
            _ => return Err(format!("{kind} is not an event of a round")),
        }
        Ok(())
    }
}

/// A logged win from an MJAI `hora`: the points text as Tenhou writes it, rebuilt from the
/// yaku, fu and han by the scoring kernel's rules.
#[allow(clippy::too_many_arguments)]
fn win(
    winner: usize,
    from: usize,
    pao: usize,
    deltas: [i32; 4],
    fu: Option<u32>,
    fan: Option<u32>,
    yaku: Vec<Yaku>,
    dealer: bool,
) -> LoggedWin {
    let yakuman: u32 = yaku
        .iter()
        .map(|y| if let YakuHan::Yakuman(n) = y.han { n } else { 0 })
        .sum();
    let han_sum: u32 = yaku
        .iter()
        .map(|y| if let YakuHan::Han(h) = y.han { h } else { 0 })
        .sum();
    let han = fan.unwrap_or(han_sum);
    let base = match (yakuman, fu) {
        (0, Some(fu)) => base_points(han, fu, 0),
        (0, None) => base_points(han.max(5), 30, 0),
        (n, _) => base_points(0, 0, n),
    };
    let limit = limit_of(base);
    let tsumo = winner == from;
    let points = points_text(fu.unwrap_or(0), han, limit, payment(base, dealer, tsumo));
    LoggedWin {
        deltas,
        winner,
        from,
        pao,
        tsumo,
        fu: if limit.is_none() { fu } else { None },
        han: if limit.is_none() { Some(han) } else { None },
        limit,
        points,
        yaku,
    }
}
