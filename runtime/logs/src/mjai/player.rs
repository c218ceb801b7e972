//! rinshan as an MJAI player: events in, the engine's state of the seat's decision out, and the
//! decision's action id back as a reaction. What the `rinshan mjai-bot` command and the Python
//! package's `rinshan.mjai.Bot` run; the policy is the caller's.

use rinshan_engine::generated::kernel::{self, GameState};
use rinshan_engine::generated::red as k;
use rinshan_engine::tile::{Tile, TileType};

use super::event::Event;
use super::rebuild::rebuild;
use super::tile::Pai;

/// One seat's game as it has been told so far.
#[derive(Debug, Clone, Default)]
pub struct Player {
    seat: Option<u8>,
    east_only: bool,
    /// The round's events from `start_kyoku` on.
    round: Vec<Event>,
    /// The seat's own hidden tiles, as the events left them.
    hand: Vec<Tile>,
    last_draw: Option<Tile>,
}

fn pais(tiles: &[Tile]) -> Vec<Pai> {
    tiles.iter().copied().map(Pai::known).collect()
}

impl Player {
    /// A player for MJAI seat `seat`, or for the seat `start_game`'s `id` names.
    pub fn new(seat: Option<u8>) -> Player {
        Player {
            seat: seat.filter(|&s| s < 4),
            ..Player::default()
        }
    }

    /// The seat played, once known.
    pub fn seat(&self) -> Option<u8> {
        self.seat
    }

    fn remove(&mut self, t: Tile) -> Result<(), String> {
        let i = self
            .hand
            .iter()
            .position(|&h| h == t)
            .ok_or_else(|| format!("the seat's hand holds no {t}"))?;
        self.hand.remove(i);
        Ok(())
    }

    /// Takes the next event.
    pub fn update(&mut self, event: Event) -> Result<(), String> {
        match &event {
            Event::StartGame { id, kyoku_first, .. } => {
                if let Some(id) = id.filter(|&i| i < 4) {
                    self.seat = Some(id);
                }
                self.east_only = *kyoku_first == Some(4);
                self.round.clear();
                return Ok(());
            }
            Event::StartKyoku { tehais, .. } => {
                let seat = self
                    .seat
                    .ok_or("start_kyoku before the seat is known (give it, or send start_game with id)")?;
                self.hand = tehais[usize::from(seat)]
                    .iter()
                    .map(|p| p.0.ok_or("the seat's own starting hand has `?`"))
                    .collect::<Result<_, _>>()?;
                self.round.clear();
            }
            _ if self.round.is_empty() => return Ok(()),
            _ => {}
        }
        let me = self.seat;
        match &event {
            Event::Tsumo { actor, pai } if Some(*actor) == me => {
                let t = pai.0.ok_or("the seat's own draw is `?`")?;
                self.hand.push(t);
                self.last_draw = Some(t);
            }
            Event::Dahai { actor, pai, .. } if Some(*actor) == me => {
                self.remove(pai.0.ok_or("the seat's own discard is `?`")?)?;
            }
            Event::Chi { actor, consumed, .. } | Event::Pon { actor, consumed, .. } if Some(*actor) == me => {
                for c in consumed {
                    self.remove(c.0.ok_or("a call's tile is `?`")?)?;
                }
            }
            Event::Daiminkan { actor, consumed, .. } if Some(*actor) == me => {
                for c in consumed {
                    self.remove(c.0.ok_or("a kan's tile is `?`")?)?;
                }
            }
            Event::Ankan { actor, consumed } if Some(*actor) == me => {
                for c in consumed {
                    self.remove(c.0.ok_or("a kan's tile is `?`")?)?;
                }
            }
            Event::Kakan { actor, pai, .. } if Some(*actor) == me => {
                self.remove(pai.0.ok_or("an added kan's tile is `?`")?)?;
            }
            _ => {}
        }
        self.round.push(event);
        Ok(())
    }

    /// The engine's state where the seat is to decide, after the events so far; `None` when it
    /// has nothing to decide (another seat's turn, nothing to claim, the round over).
    pub fn decision(&self) -> Result<Option<GameState>, String> {
        let (Some(seat), false) = (self.seat, self.round.is_empty()) else {
            return Ok(None);
        };
        let mode = if self.east_only {
            kernel::MODE_EAST
        } else {
            kernel::MODE_HALF
        };
        let state = rebuild(seat, mode, &self.round)?;
        Ok(state.filter(|s| s.current == u32::from(seat) && s.terminated == 0 && s.mask != [0; 3]))
    }

    fn of_kind(&self, kind: TileType, red: bool, n: usize) -> Vec<Tile> {
        // Black copies first, or the red one first when the call uses it.
        let mut tiles: Vec<Tile> = self.hand.iter().copied().filter(|t| t.kind() == kind).collect();
        tiles.sort_by_key(|t| t.is_red() != red);
        tiles.truncate(n);
        tiles
    }

    /// The reaction that plays action `a` (the red rules' id) in `state`, a decision of this seat.
    pub fn reaction(&self, state: &GameState, a: u32) -> Result<Event, String> {
        let seat = self.seat.ok_or("the seat is not known")?;
        let tile = |v: u32| {
            u8::try_from(v)
                .ok()
                .and_then(Tile::from_value)
                .ok_or(format!("tile value {v}"))
        };
        let kind = |v: u32| tile(v).map(|t| t.kind());
        let claimed = || tile(state.claim_tile);
        let target = state.claim_from as u8;
        let called = |n: usize, red: bool| -> Result<(Tile, Vec<Pai>), String> {
            let c = claimed()?;
            Ok((c, pais(&self.of_kind(c.kind(), red, n))))
        };
        Ok(match a {
            _ if a < k::ACTION_DISCARD + k::ACTION_DISCARD_COUNT => Event::Dahai {
                actor: seat,
                pai: Pai::known(tile(a - k::ACTION_DISCARD)?),
                tsumogiri: false,
            },
            k::ACTION_TSUMOGIRI => Event::Dahai {
                actor: seat,
                pai: Pai::known(tile(state.drawn)?),
                tsumogiri: true,
            },
            k::ACTION_RIICHI => Event::Reach { actor: seat },
            k::ACTION_TSUMO | k::ACTION_RON => Event::Hora {
                actor: seat,
                target: if a == k::ACTION_TSUMO { seat } else { target },
                pai: Some(Pai::known(if a == k::ACTION_TSUMO {
                    tile(state.drawn)?
                } else {
                    claimed()?
                })),
                deltas: None,
                ura_markers: None,
                yakus: None,
                fu: None,
                fan: None,
                hora_points: None,
                pao: None,
            },
            k::ACTION_PON | k::ACTION_PON_RED => {
                let (c, consumed) = called(2, a == k::ACTION_PON_RED)?;
                Event::Pon {
                    actor: seat,
                    target,
                    pai: Pai::known(c),
                    consumed: <[Pai; 2]>::try_from(consumed).map_err(|_| "the hand holds no pair to pon")?,
                }
            }
            k::ACTION_OPEN_KAN => {
                let (c, consumed) = called(3, true)?;
                Event::Daiminkan {
                    actor: seat,
                    target,
                    pai: Pai::known(c),
                    consumed: <[Pai; 3]>::try_from(consumed).map_err(|_| "the hand holds no triplet to kan")?,
                }
            }
            k::ACTION_CHI_LEFT..=k::ACTION_CHI_RIGHT_RED => {
                let c = claimed()?;
                let t = u8::from(c.kind());
                let step = (a - k::ACTION_CHI_LEFT) / 2;
                let red = (a - k::ACTION_CHI_LEFT) % 2 == 1;
                let low = t.checked_sub(step as u8).ok_or("chi off the suit")?;
                let mut consumed = Vec::new();
                for j in (low..low + 3).filter(|&j| j != t) {
                    let kind = TileType::try_from(j).map_err(|_| "chi off the suit")?;
                    consumed.extend(self.of_kind(kind, red, 1));
                }
                Event::Chi {
                    actor: seat,
                    target,
                    pai: Pai::known(c),
                    consumed: <[Pai; 2]>::try_from(pais(&consumed)).map_err(|_| "the hand lacks the chi's tiles")?,
                }
            }
            _ if (k::ACTION_SELF_KAN..k::ACTION_SELF_KAN + k::ACTION_SELF_KAN_COUNT).contains(&a) => {
                let t = kind(a - k::ACTION_SELF_KAN)?;
                let pon = self.round.iter().find_map(|e| match e {
                    Event::Pon {
                        actor, pai, consumed, ..
                    } if *actor == seat && pai.0.map(|p| p.kind()) == Some(t) => Some([*pai, consumed[0], consumed[1]]),
                    _ => None,
                });
                match pon {
                    Some(pon) => Event::Kakan {
                        actor: seat,
                        pai: Pai::known(*self.of_kind(t, true, 1).first().ok_or("no tile to add to the pon")?),
                        consumed: pon,
                    },
                    None => Event::Ankan {
                        actor: seat,
                        consumed: <[Pai; 4]>::try_from(pais(&self.of_kind(t, true, 4)))
                            .map_err(|_| "the hand holds no four to kan")?,
                    },
                }
            }
            k::ACTION_KYUUSHU => Event::Ryukyoku {
                reason: None,
                tenpais: None,
                deltas: None,
            },
            k::ACTION_PASS => Event::None {},
            other => return Err(format!("action {other} is not a decision")),
        })
    }

    /// A legal reaction found without the engine, for when the state cannot be rebuilt: discard
    /// the draw on the seat's turn (a tile of another kind than the called one after a call),
    /// pass otherwise.
    pub fn fallback(&self) -> Event {
        let Some(seat) = self.seat else { return Event::None {} };
        match self.round.last() {
            Some(Event::Tsumo { actor, .. } | Event::Reach { actor }) if *actor == seat => match self.last_draw {
                Some(t) => Event::Dahai {
                    actor: seat,
                    pai: Pai::known(t),
                    tsumogiri: true,
                },
                None => Event::None {},
            },
            Some(Event::Chi { actor, pai, .. } | Event::Pon { actor, pai, .. }) if *actor == seat => {
                let called = pai.0.map(|p| p.kind());
                match self.hand.iter().rev().find(|t| Some(t.kind()) != called) {
                    Some(&t) => Event::Dahai {
                        actor: seat,
                        pai: Pai::known(t),
                        tsumogiri: false,
                    },
                    None => Event::None {},
                }
            }
            _ => Event::None {},
        }
    }
}

/// One line from the host: its events, and what the last one says of `can_act` (Mortal's hint).
fn parse_line(line: &str) -> Result<(Vec<Event>, Option<bool>), String> {
    let value: serde_json::Value = serde_json::from_str(line).map_err(|e| format!("not JSON: {e}"))?;
    let items = match value {
        serde_json::Value::Array(items) => items,
        other => vec![other],
    };
    let can_act = items
        .last()
        .and_then(|v| v.get("can_act"))
        .and_then(serde_json::Value::as_bool);
    if items.iter().any(|v| super::read::listed_seats(v) == Some(3)) {
        return Err("an event of a three-player game: rinshan plays MJAI as a four-player seat (red rules)".into());
    }
    let events = items
        .into_iter()
        .map(|v| serde_json::from_value::<Event>(v).map_err(|e| format!("not an MJAI event: {e}")))
        .collect::<Result<Vec<_>, _>>()?;
    Ok((events, can_act))
}

impl Player {
    /// Answers one line from the host in `dialect`: the reply line, if one is due. `decide` gives
    /// the action id for a decision's state; what goes wrong is passed to `log` and answered with
    /// the [`Player::fallback`] (or `none`), so a bot never stops answering.
    pub fn respond(
        &mut self,
        line: &str,
        dialect: super::bot::Dialect,
        decide: &mut dyn FnMut(&GameState) -> Result<u32, String>,
        log: &mut dyn FnMut(String),
    ) -> Option<String> {
        let stdio = dialect == super::bot::Dialect::Stdio;
        let (events, can_act) = match parse_line(line.trim()) {
            Ok(parsed) => parsed,
            Err(e) => {
                log(format!(
                    "line ignored, {e}: {}",
                    line.chars().take(200).collect::<String>()
                ));
                return (!stdio).then(|| r#"{"type":"none"}"#.to_string());
            }
        };
        for e in events {
            if let Err(err) = self.update(e) {
                log(format!("event ignored: {err}"));
            }
        }
        if stdio && can_act == Some(false) {
            return None;
        }
        let reaction = match self.decision() {
            Ok(Some(state)) => Some(
                decide(&state)
                    .and_then(|a| self.reaction(&state, a))
                    .unwrap_or_else(|e| {
                        log(format!("no decision ({e}): answering {}", self.fallback().kind()));
                        self.fallback()
                    }),
            ),
            Ok(None) => None,
            Err(e) => {
                let fallback = self.fallback();
                log(format!(
                    "the state cannot be rebuilt ({e}): answering {}",
                    fallback.kind()
                ));
                (fallback != Event::None {}).then_some(fallback)
            }
        };
        let reply = match (reaction, stdio && can_act.is_none()) {
            (Some(r), _) => r,
            (None, true) => return None,
            (None, false) => Event::None {},
        };
        serde_json::to_string(&reply).ok()
    }
}
