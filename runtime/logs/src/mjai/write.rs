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

use super::event::Event;
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

/// Every event of the game, `start_game` to `end_game`.
pub fn game_events(game: &Game) -> Result<Vec<Event>, LogError> {
    let east_only = game.rule.contains('東');
    let mut events = vec![Event::StartGame {
        names: game.names.clone(),
        id: None,
        kyoku_first: Some(if east_only { 4 } else { 0 }),
        aka_flag: Some(game.red_fives),
        rule: (!game.rule.is_empty()).then(|| game.rule.clone()),
    }];
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

/// The game as an MJAI log: one event per line.
pub fn game_text(game: &Game) -> Result<String, LogError> {
    let mut text = String::new();
    for event in game_events(game)? {
        // An event is plain data (strings, numbers, lists): serialising it cannot fail.
        text.push_str(&serde_json::to_string(&event).unwrap_or_default());
        text.push('\n');
    }
    Ok(text)
}

fn seat(s: usize) -> u8 {
    // Seats come from the log's four lists: always 0..4.
    s as u8
}

fn pais(tiles: &[Tile]) -> Vec<Pai> {
    tiles.iter().copied().map(Pai::known).collect()
}

/// One round's events, `start_kyoku` to `end_kyoku`.
fn round_events(round: &Round, out: &mut Vec<Event>) -> Result<(), String> {
    let plan = plan(round)?;
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
    let mut walk = Walk {
        out,
        doras: round.dora[1..].iter(),
        reveal_at_discard: false,
        reveal_at_tsumo: false,
        last_draw: [None; 4],
        last_given: None,
        scores: round.scores,
    };
    for played in &plan.order {
        walk.play(played, &plan.riichi_paid)?;
    }
    // An indicator the engines' order left unshown (an open kan's, when the kanner wins on its
    // replacement tile) still belongs to the round as logged.
    while walk.doras.len() > 0 {
        walk.reveal();
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
                walk.out.push(hora(w, pai, ura));
            }
        }
        Outcome::Draw { kind, deltas } => walk.out.push(ryukyoku(*kind, *deltas)),
    }
    walk.out.push(Event::EndKyoku {});
    Ok(())
}

struct Walk<'a, 'r> {
    out: &'a mut Vec<Event>,
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

impl Walk<'_, '_> {
    /// The next dora indicator; a log that stops listing them (a converter's) just shows none.
    fn reveal(&mut self) {
        if let Some(&t) = self.doras.next() {
            self.out.push(Event::Dora {
                dora_marker: Pai::known(t),
            });
        }
    }

    fn open_kan(&mut self) {
        self.reveal_at_tsumo = self.reveal_at_discard;
        self.reveal_at_discard = true;
    }

    fn play(&mut self, played: &Played, riichi_paid: &[u32; 4]) -> Result<(), String> {
        match *played {
            Played::Draw { seat: s, draw, .. } => {
                let actor = seat(s);
                match draw {
                    Draw::Tile(t) => {
                        if std::mem::take(&mut self.reveal_at_tsumo) {
                            self.reveal();
                        }
                        self.last_draw[s] = Some(t);
                        self.out.push(Event::Tsumo {
                            actor,
                            pai: Pai::known(t),
                        });
                    }
                    Draw::Chi { called, own } => self.out.push(Event::Chi {
                        actor,
                        target: seat((s + 3) % 4),
                        pai: Pai::known(called),
                        consumed: own.map(Pai::known),
                    }),
                    Draw::Pon { called, own, from } => self.out.push(Event::Pon {
                        actor,
                        target: seat(from.seat_of(s)),
                        pai: Pai::known(called),
                        consumed: own.map(Pai::known),
                    }),
                    Draw::OpenKan { called, own, from } => {
                        self.open_kan();
                        self.out.push(Event::Daiminkan {
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
                    Discard::Tile(t) => self.dahai(s, t, false),
                    Discard::Tsumogiri => {
                        let t =
                            self.last_draw[s].ok_or_else(|| format!("seat {s} discards its draw before drawing"))?;
                        self.dahai(s, t, true);
                    }
                    Discard::Riichi(t) => {
                        self.out.push(Event::Reach { actor });
                        let (t, tsumogiri) = match t {
                            Some(t) => (t, false),
                            None => (
                                self.last_draw[s].ok_or_else(|| format!("seat {s} declares riichi before drawing"))?,
                                true,
                            ),
                        };
                        self.dahai(s, t, tsumogiri);
                        if riichi_paid[s] > 0 {
                            let mut deltas = [0; 4];
                            deltas[s] = -1000;
                            self.scores[s] -= 1000;
                            self.out.push(Event::ReachAccepted {
                                actor,
                                deltas: Some(deltas),
                                scores: Some(self.scores),
                            });
                        }
                    }
                    Discard::AddedKan { added, pon, .. } => {
                        self.open_kan();
                        self.last_given = Some(added);
                        self.out.push(Event::Kakan {
                            actor,
                            pai: Pai::known(added),
                            consumed: pon.map(Pai::known),
                        });
                    }
                    Discard::ClosedKan { tiles } => {
                        if std::mem::take(&mut self.reveal_at_discard) {
                            self.reveal();
                        }
                        self.last_given = Some(tiles[0]);
                        self.out.push(Event::Ankan {
                            actor,
                            consumed: tiles.map(Pai::known),
                        });
                        self.reveal();
                    }
                    Discard::Nothing => {}
                }
            }
        }
        Ok(())
    }

    fn dahai(&mut self, s: usize, t: Tile, tsumogiri: bool) {
        if std::mem::take(&mut self.reveal_at_discard) {
            self.reveal();
        }
        self.last_given = Some(t);
        self.out.push(Event::Dahai {
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

fn hora(w: &LoggedWin, pai: Option<Tile>, ura: Option<Vec<Pai>>) -> Event {
    let han_sum: u32 = w
        .yaku
        .iter()
        .map(|y| if let YakuHan::Han(h) = y.han { h } else { 0 })
        .sum();
    let yakuman = w.yaku.iter().any(|y| matches!(y.han, YakuHan::Yakuman(_)));
    Event::Hora {
        actor: seat(w.winner),
        target: seat(w.from),
        pai: pai.map(Pai::known),
        deltas: Some(w.deltas),
        ura_markers: ura,
        yakus: Some(w.yaku.iter().map(yaku_entry).collect()),
        fu: w.fu,
        fan: w.han.or((!yakuman).then_some(han_sum)),
        hora_points: points_total(&w.points),
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
