//! A [`Game`] as MJAI events: each round walked in the order of play ([`plan`]), with the
//! extras real logs carry (riichi deposits with scores, a win's yaku, fu, han and points, a
//! draw's reason and tenpai seats), in the order the engines emit them:
//!
//! * a closed kan reveals its dora at once: `ankan, dora, tsumo`;
//! * an open or added kan reveals it with the kanner's discard: `daiminkan, tsumo, dora, dahai`
//!   (a rinshan win after it reveals none; a second kan first reveals the pending one);
//! * `reach, dahai, reach_accepted`, with no `reach_accepted` when the discard is ronned;
//! * a double ron is two `hora` in a row, nearest the discarder first, as Tenhou lists them.

use rinshan_engine::hand::{Yaku, YakuHan};
use rinshan_engine::tile::{Tile, TileType};
use rinshan_engine::Variant;

use super::event::{Event, PER_SEAT};
use super::rules::named;
use super::tile::Pai;
use crate::tenhou::log::{points_total, Discard, Draw, Game, LogError, LoggedDraw, LoggedWin, Outcome, Round};
use crate::tenhou::plan::{plan, Played};

/// Han written for each yakuman in a `yakus` list (the original mjai's convention).
pub(crate) const YAKUMAN_HAN: u32 = 13;

/// The reasons MJAI gives a round without a win, by Tenhou's names for it.
pub(crate) const REASONS: [(LoggedDraw, &str); 9] = [
    (LoggedDraw::Exhaustive, "fanpai"),
    (LoggedDraw::AllTenpai, "fanpai"),
    (LoggedDraw::NoTenpai, "fanpai"),
    (LoggedDraw::Nagashi, "nagashimangan"),
    (LoggedDraw::Kyuushu, "kyushukyuhai"),
    (LoggedDraw::FourRiichi, "suchareach"),
    (LoggedDraw::TripleRon, "sanchaho"),
    (LoggedDraw::FourKans, "sukaikan"),
    (LoggedDraw::FourWinds, "sufonrenta"),
];

/// The `start_game` of a game of `variant`: `rule` is Tenhou's name of it (`鳳東喰赤` for East
/// only); a rule set other than Tenhou's is named ([`super::rules`]), so the log replays under it.
pub(crate) fn start_game(names: &[String; 4], rule: &str, red_fives: bool, variant: Variant) -> Event {
    let east_only = rule.contains('東');
    Event::StartGame {
        names: names.clone(),
        id: None,
        kyoku_first: Some(if east_only { 4 } else { 0 }),
        aka_flag: Some(red_fives),
        rule: (!rule.is_empty()).then(|| rule.to_string()),
        variant: named(variant),
        preset: None,
        rules: None,
    }
}

/// Every event of the game, `start_game` to `end_game`.
pub fn game_events(game: &Game) -> Result<Vec<Event>, LogError> {
    let mut events = vec![start_game(&game.names, &game.rule, game.red_fives, game.variant)];
    for round in &game.rounds {
        round_events(round, &mut events).map_err(|message| LogError {
            file: game.path.clone(),
            line: Some(round.line),
            column: None,
            round: Some(round.to_string()),
            field: None,
            message,
        })?;
    }
    events.push(Event::EndGame { scores: None });
    Ok(events)
}

/// The game as an MJAI log: one event per line; a three-player game's per-seat lists hold three
/// seats.
pub fn game_text(game: &Game) -> Result<String, LogError> {
    let seats = game.variant.seats() as usize;
    let mut text = String::new();
    for event in game_events(game)? {
        // An event is plain data (strings, numbers, lists): serialising it cannot fail.
        let line = serde_json::to_string(&event).unwrap_or_default();
        match seats {
            4 => text.push_str(&line),
            _ => text.push_str(&cut_to_seats(&line, seats)),
        }
        text.push('\n');
    }
    Ok(text)
}

/// An event's JSON with its per-seat lists cut to `seats` entries, its fields kept in order.
fn cut_to_seats(line: &str, seats: usize) -> String {
    let Ok(Fields(mut fields)) = serde_json::from_str::<Fields>(line) else {
        return line.to_string();
    };
    let mut out = String::from("{");
    for (i, (key, value)) in fields.iter_mut().enumerate() {
        if let (true, serde_json::Value::Array(list)) = (PER_SEAT.contains(&key.as_str()), &mut *value) {
            list.truncate(seats);
        }
        if i > 0 {
            out.push(',');
        }
        out.push_str(&serde_json::Value::from(key.as_str()).to_string());
        out.push(':');
        out.push_str(&value.to_string());
    }
    out.push('}');
    out
}

/// A JSON object's fields in the order written (serde_json's own map sorts them).
struct Fields(Vec<(String, serde_json::Value)>);

impl<'de> serde::Deserialize<'de> for Fields {
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> Result<Fields, D::Error> {
        struct InOrder;
        impl<'de> serde::de::Visitor<'de> for InOrder {
            type Value = Fields;
            fn expecting(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
                f.write_str("a JSON object")
            }
            fn visit_map<A: serde::de::MapAccess<'de>>(self, mut map: A) -> Result<Fields, A::Error> {
                let mut fields = Vec::new();
                while let Some(entry) = map.next_entry()? {
                    fields.push(entry);
                }
                Ok(Fields(fields))
            }
        }
        d.deserialize_map(InOrder)
    }
}

fn seat(s: usize) -> u8 {
    // Seats come from the log's four lists: always 0..4.
    s as u8
}

fn pais(tiles: &[Tile]) -> Vec<Pai> {
    tiles.iter().copied().map(Pai::known).collect()
}

/// One round's events, `start_kyoku` to `end_kyoku`.
pub(crate) fn round_events(round: &Round, out: &mut Vec<Event>) -> Result<(), String> {
    let plan = plan(round)?;
    let mut walk = Walk::start(round, out)?;
    for played in &plan.order {
        walk.play(played, &plan.riichi_paid, out)?;
    }
    // An indicator the engines' order left unshown (an open kan's, when the kanner wins on its
    // replacement tile) still belongs to the round as logged.
    while walk.doras.len() > 0 {
        walk.reveal(out);
    }
    match &round.outcome {
        Outcome::Wins(wins) => {
            for w in wins {
                let pai = if w.tsumo {
                    walk.last_draw[w.winner]
                } else {
                    walk.last_given
                };
                let ura = (!round.ura.is_empty()).then(|| pais(&round.ura));
                out.push(hora(w, pai, ura, round.seats));
            }
        }
        Outcome::Draw { kind, deltas } => out.push(ryukyoku(*kind, *deltas)),
    }
    out.push(Event::EndKyoku {});
    Ok(())
}

/// The events of a round still in play, from `start_kyoku` to its last entry played (`order`),
/// as the engines send them live: a riichi discard's `reach_accepted` waits until the discard
/// has survived its claims (the next entry), and a seat that has `declared` riichi and not yet
/// discarded has its `reach` sent.
pub(crate) fn round_so_far(
    round: &Round,
    order: &[Played],
    declared: [bool; 4],
    out: &mut Vec<Event>,
) -> Result<(), String> {
    let mut walk = Walk::start(round, out)?;
    let mut paid = [1; 4];
    if let Some(Played::Discard {
        seat: s,
        discard: Discard::Riichi(_),
    }) = order.last()
    {
        paid[*s] = 0;
    }
    for played in order {
        walk.play(played, &paid, out)?;
    }
    for (s, _) in declared.iter().enumerate().filter(|(_, &d)| d) {
        out.push(Event::Reach { actor: seat(s) });
    }
    Ok(())
}

struct Walk<'r> {
    doras: std::slice::Iter<'r, Tile>,
    /// An open or added kan's dora waits for the kanner's discard (or the next kan).
    reveal_at_discard: bool,
    /// A dora moved on by a second kan: revealed with the replacement draw.
    reveal_at_tsumo: bool,
    last_draw: [Option<Tile>; 4],
    /// The last tile given up to the table: a discard, or an added kan's tile (robbed by chankan).
    last_given: Option<Tile>,
    scores: [i32; 4],
}

impl<'r> Walk<'r> {
    /// Writes the round's `start_kyoku` and starts walking it.
    fn start(round: &'r Round, out: &mut Vec<Event>) -> Result<Walk<'r>, String> {
        let first_dora = *round.dora.first().ok_or("the round lists no dora indicator")?;
        let wind = TileType::new(27 + (round.kyoku / 4 % 4) as u8).map(Tile::plain);
        out.push(Event::StartKyoku {
            bakaze: Pai(wind),
            dora_marker: Pai::known(first_dora),
            kyoku: (round.kyoku % 4 + 1) as u8,
            honba: round.honba,
            kyotaku: round.sticks,
            oya: seat(round.dealer()),
            scores: round.scores,
            tehais: std::array::from_fn(|s| pais(&round.hands[s])),
        });
        Ok(Walk {
            doras: round.dora[1..].iter(),
            reveal_at_discard: false,
            reveal_at_tsumo: false,
            last_draw: [None; 4],
            last_given: None,
            scores: round.scores,
        })
    }

    /// The next dora indicator; a log that stops listing them (a converter's) just shows none.
    fn reveal(&mut self, out: &mut Vec<Event>) {
        if let Some(&t) = self.doras.next() {
            out.push(Event::Dora {
                dora_marker: Pai::known(t),
            });
        }
    }

    fn open_kan(&mut self) {
        self.reveal_at_tsumo = self.reveal_at_discard;
        self.reveal_at_discard = true;
    }

    fn play(&mut self, played: &Played, riichi_paid: &[u32; 4], out: &mut Vec<Event>) -> Result<(), String> {
        match *played {
            Played::Draw { seat: s, draw, .. } => {
                let actor = seat(s);
                match draw {
                    Draw::Tile(t) => {
                        if std::mem::take(&mut self.reveal_at_tsumo) {
                            self.reveal(out);
                        }
                        self.last_draw[s] = Some(t);
                        out.push(Event::Tsumo {
                            actor,
                            pai: Pai::known(t),
                        });
                    }
                    Draw::Chi { called, own } => out.push(Event::Chi {
                        actor,
                        target: seat((s + 3) % 4),
                        pai: Pai::known(called),
                        consumed: own.map(Pai::known),
                    }),
                    Draw::Pon { called, own, from } => out.push(Event::Pon {
                        actor,
                        target: seat(from.seat_of(s)),
                        pai: Pai::known(called),
                        consumed: own.map(Pai::known),
                    }),
                    Draw::OpenKan { called, own, from } => {
                        self.open_kan();
                        out.push(Event::Daiminkan {
                            actor,
                            target: seat(from.seat_of(s)),
                            pai: Pai::known(called),
                            consumed: own.map(Pai::known),
                        });
                    }
                }
            }
            Played::Discard { seat: s, discard } => {
                let actor = seat(s);
                match discard {
                    Discard::Tile(t) => self.dahai(s, t, false, out),
                    Discard::Tsumogiri => {
                        let t =
                            self.last_draw[s].ok_or_else(|| format!("seat {s} discards its draw before drawing"))?;
                        self.dahai(s, t, true, out);
                    }
                    Discard::Riichi(t) => {
                        out.push(Event::Reach { actor });
                        let (t, tsumogiri) = match t {
                            Some(t) => (t, false),
                            None => (
                                self.last_draw[s].ok_or_else(|| format!("seat {s} declares riichi before drawing"))?,
                                true,
                            ),
                        };
                        self.dahai(s, t, tsumogiri, out);
                        if riichi_paid[s] > 0 {
                            let mut deltas = [0; 4];
                            deltas[s] = -1000;
                            self.scores[s] -= 1000;
                            out.push(Event::ReachAccepted {
                                actor,
                                deltas: Some(deltas),
                                scores: Some(self.scores),
                            });
                        }
                    }
                    Discard::AddedKan { added, pon, .. } => {
                        self.open_kan();
                        self.last_given = Some(added);
                        out.push(Event::Kakan {
                            actor,
                            pai: Pai::known(added),
                            consumed: pon.map(Pai::known),
                        });
                    }
                    Discard::ClosedKan { tiles } => {
                        if std::mem::take(&mut self.reveal_at_discard) {
                            self.reveal(out);
                        }
                        self.last_given = Some(tiles[0]);
                        out.push(Event::Ankan {
                            actor,
                            consumed: tiles.map(Pai::known),
                        });
                        self.reveal(out);
                    }
                    Discard::Kita => out.push(Event::Kita {
                        actor,
                        pai: Pai::known(Tile::plain(TileType::NORTH)),
                    }),
                    Discard::Nothing => {}
                }
            }
        }
        Ok(())
    }

    fn dahai(&mut self, s: usize, t: Tile, tsumogiri: bool, out: &mut Vec<Event>) {
        if std::mem::take(&mut self.reveal_at_discard) {
            self.reveal(out);
        }
        self.last_given = Some(t);
        out.push(Event::Dahai {
            actor: seat(s),
            pai: Pai::known(t),
            tsumogiri,
        });
    }
}

fn yaku_entry(y: &Yaku) -> (String, u32) {
    let han = match y.han {
        YakuHan::Han(h) => h,
        YakuHan::Yakuman(n) => n * YAKUMAN_HAN,
    };
    (y.name.to_string(), han)
}

fn hora(w: &LoggedWin, pai: Option<Tile>, ura: Option<Vec<Pai>>, seats: usize) -> Event {
    let han_sum: u32 = w
        .yaku
        .iter()
        .map(|y| if let YakuHan::Han(h) = y.han { h } else { 0 })
        .sum();
    let yakuman = w.yaku.iter().any(|y| matches!(y.han, YakuHan::Yakuman(_)));
    if w.computed {
        // The log gave only these: what rinshan scored stays out, as the log was.
        return Event::Hora {
            actor: seat(w.winner),
            target: seat(w.from),
            pai: pai.map(Pai::known),
            deltas: Some(w.deltas),
            ura_markers: ura,
            yakus: None,
            fu: None,
            fan: None,
            hora_points: None,
            pao: (w.pao != w.winner).then(|| seat(w.pao)),
        };
    }
    Event::Hora {
        actor: seat(w.winner),
        target: seat(w.from),
        pai: pai.map(Pai::known),
        deltas: Some(w.deltas),
        ura_markers: ura,
        yakus: Some(w.yaku.iter().map(yaku_entry).collect()),
        fu: w.fu,
        fan: w.han.or((!yakuman).then_some(han_sum)),
        hora_points: points_total(&w.points, seats),
        pao: (w.pao != w.winner).then(|| seat(w.pao)),
    }
}

fn ryukyoku(kind: LoggedDraw, deltas: Option<[i32; 4]>) -> Event {
    let reason = REASONS.iter().find(|(k, _)| *k == kind).map(|(_, r)| r.to_string());
    let tenpais = match kind {
        LoggedDraw::AllTenpai => Some([true; 4]),
        LoggedDraw::NoTenpai => Some([false; 4]),
        LoggedDraw::Exhaustive => deltas.map(|d| d.map(|x| x > 0)),
        _ => None,
    };
    Event::Ryukyoku {
        reason,
        tenpais,
        deltas,
    }
}
