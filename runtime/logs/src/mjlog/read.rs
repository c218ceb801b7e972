//! Tenhou's mjlog XML (`<mjloggm ver="2.3">`, the Phoenix-room archive's format) read into the
//! same [`Game`] as the other formats: each tag is said as the MJAI event it stands for and fed
//! to the MJAI reader's [`GameBuilder`], which holds every round to the tenhou.net/6 rules.
//!
//! | tag | event |
//! |---|---|
//! | `GO type` | the rule: bit 0x02 no red fives, 0x08 half game (else East only), 0x10 three players, room bits 0x20/0x80; no kuitan (0x04) is refused by name |
//! | `UN n0..n3` | the names (URL-encoded); a later `UN` is a reconnect |
//! | `INIT seed ten oya hai0..3` | `start_kyoku` (seed: round, honba, sticks, dice, dora id; ten: scores / 100) |
//! | `T/U/V/W<id>`, `D/E/F/G<id>` | draws and discards of seats 0-3; a discard of the id just drawn is tsumogiri |
//! | `N who m` | a call, a kan or (three players) a kita ([`super::meld`]) |
//! | `REACH step=1/2`, `DORA hai` | `reach` / `reach_accepted`, `dora` |
//! | `AGARI`, `RYUUKYOKU` | `hora` (deltas from `sc`, yaku by Tenhou's ids, ura) / `ryukyoku` (its `type`, tenpai hands) |
//!
//! Three players keep Tenhou's four places with the fourth empty: `hai3` is empty, the fourth
//! score 0, and a meld's direction counts places mod 4 (so seats 0 and 2 sit across).
//!
//! `SHUFFLE`, `TAIKYOKU`, `BYE` and `FURITEN` change nothing a replay needs.

use percent_encoding::percent_decode_str;
use quick_xml::events::{BytesStart, Event as Xml};
use quick_xml::XmlVersion;

use rinshan_engine::tile::{Tile, TileType};

use super::meld::{decode, Meld, TileId};
use crate::mjai::event::Event;
use crate::mjai::read::GameBuilder;
use crate::mjai::tile::Pai;
use crate::tenhou::log::{tenhou_yaku_name, Game, LogError};

/// Tenhou's yaku ids (AGARI's `yaku` and `yakuman`), by the names its JSON logs write.
const YAKU_IDS: [&str; 55] = [
    "門前清自摸和",
    "立直",
    "一発",
    "槍槓",
    "嶺上開花",
    "海底摸月",
    "河底撈魚",
    "平和",
    "断幺九",
    "一盃口",
    "自風 東",
    "自風 南",
    "自風 西",
    "自風 北",
    "場風 東",
    "場風 南",
    "場風 西",
    "場風 北",
    "役牌 白",
    "役牌 發",
    "役牌 中",
    "両立直",
    "七対子",
    "混全帯幺九",
    "一気通貫",
    "三色同順",
    "三色同刻",
    "三槓子",
    "対々和",
    "三暗刻",
    "小三元",
    "混老頭",
    "二盃口",
    "純全帯幺九",
    "混一色",
    "清一色",
    "人和",
    "天和",
    "地和",
    "大三元",
    "四暗刻",
    "四暗刻単騎",
    "字一色",
    "緑一色",
    "清老頭",
    "九蓮宝燈",
    "純正九蓮宝燈",
    "国士無双",
    "国士無双１３面",
    "大四喜",
    "小四喜",
    "四槓子",
    "ドラ",
    "裏ドラ",
    "赤ドラ",
];

/// RYUUKYOKU `type` and the MJAI reason (no type: the wall ran out).
const DRAWS: [(&str, &str); 6] = [
    ("yao9", "kyushukyuhai"),
    ("reach4", "suchareach"),
    ("ron3", "sanchaho"),
    ("kan4", "sukaikan"),
    ("kaze4", "sufonrenta"),
    ("nm", "nagashimangan"),
];

/// The rooms of `GO type`, as Tenhou's rule names begin.
const ROOMS: [&str; 4] = ["般", "上", "特", "鳳"];

/// Whether a text looks like an mjlog: its first tag is `<mjloggm` (after an XML declaration).
pub fn is_mjlog(text: &str) -> bool {
    let text = text.trim_start_matches('\u{feff}').trim_start();
    let text = match text.strip_prefix("<?xml") {
        Some(rest) => rest.split_once("?>").map_or("", |(_, r)| r).trim_start(),
        None => text,
    };
    text.starts_with("<mjloggm")
}

/// Reads the text of an mjlog; `path` only names it in messages.
pub fn parse_game(path: &str, text: &str) -> Result<Game, LogError> {
    let mut reader = quick_xml::Reader::from_str(text);
    let mut state = State {
        builder: GameBuilder::new(path),
        red: true,
        rule: String::new(),
        east_only: false,
        seats: 4,
        names: Default::default(),
        named: false,
        started: false,
        in_round: false,
        last_draw: [None; 4],
    };
    let mut where_ = Position::default();
    loop {
        let (line, column) = where_.advance(text, reader.buffer_position());
        let err = |message: String| LogError {
            file: path.to_string(),
            line: Some(line),
            column: Some(column),
            round: None,
            field: None,
            message,
        };
        match reader.read_event() {
            Ok(Xml::Eof) => break,
            Ok(Xml::Start(tag) | Xml::Empty(tag)) => {
                let name: String = AsRef::<str>::as_ref(&tag.name()).to_owned();
                let attrs = attributes(&tag).map_err(|m| err(format!("<{name}>: {m}")))?;
                let tag = Tag { name: &name, attrs };
                for event in state.tag(&tag).map_err(|m| err(format!("<{name}>: {m}")))? {
                    state.builder.event(event, line)?;
                }
            }
            Ok(_) => {}
            Err(e) => return Err(err(format!("not XML: {e}"))),
        }
    }
    if state.in_round {
        state.builder.event(Event::EndKyoku {}, 0)?;
    }
    if state.started {
        state.builder.event(Event::EndGame { scores: None }, 0)?;
    }
    state.builder.finish()
}

/// Line and column (1-based, in bytes) of the reader's offset, counted from the last offset asked
/// (mjlog files are often one long line: counting from the start at every tag was quadratic).
#[derive(Default)]
struct Position {
    at: usize,
    /// Newlines before `at`.
    newlines: usize,
    /// Offset just after the last newline before `at`.
    line_start: usize,
}

impl Position {
    fn advance(&mut self, text: &str, to: u64) -> (usize, u32) {
        let to = usize::try_from(to).unwrap_or(usize::MAX).min(text.len()).max(self.at);
        for (i, &b) in text.as_bytes()[self.at..to].iter().enumerate() {
            if b == b'\n' {
                self.newlines += 1;
                self.line_start = self.at + i + 1;
            }
        }
        self.at = to;
        let column = to - self.line_start + 1;
        (self.newlines + 1, u32::try_from(column).unwrap_or(u32::MAX))
    }
}

fn attributes(tag: &BytesStart) -> Result<Vec<(String, String)>, String> {
    let mut out = Vec::new();
    for a in tag.attributes() {
        let a = a.map_err(|e| e.to_string())?;
        let value = a.normalized_value(XmlVersion::Implicit1_0).map_err(|e| e.to_string())?;
        out.push((AsRef::<str>::as_ref(&a.key).to_owned(), value.into_owned()));
    }
    Ok(out)
}

struct Tag<'a> {
    name: &'a str,
    attrs: Vec<(String, String)>,
}

impl Tag<'_> {
    fn get(&self, key: &str) -> Option<&str> {
        self.attrs.iter().find(|(k, _)| k == key).map(|(_, v)| v.as_str())
    }

    fn need(&self, key: &str) -> Result<&str, String> {
        self.get(key).ok_or_else(|| format!("no `{key}`"))
    }

    /// A comma-separated list of integers.
    fn numbers(&self, key: &str) -> Result<Vec<i64>, String> {
        numbers(self.need(key)?).map_err(|m| format!("`{key}`: {m}"))
    }

    fn seat(&self, key: &str) -> Result<u8, String> {
        match self.need(key)?.parse::<u8>() {
            Ok(s) if s < 4 => Ok(s),
            _ => Err(format!(
                "`{key}` {:?} is not a seat 0-3",
                self.get(key).unwrap_or_default()
            )),
        }
    }
}

fn numbers(list: &str) -> Result<Vec<i64>, String> {
    if list.trim().is_empty() {
        return Ok(Vec::new());
    }
    list.split(',')
        .map(|n| {
            n.trim()
                .parse::<i64>()
                .map_err(|_| format!("{n:?} in {list:?} is not an integer"))
        })
        .collect()
}

/// Hundreds of points as points (`ten`, `sc`).
fn points(hundreds: i64) -> Result<i32, String> {
    i32::try_from(hundreds.saturating_mul(100)).map_err(|_| format!("{hundreds}00 points is out of range"))
}

struct State {
    builder: GameBuilder,
    red: bool,
    rule: String,
    east_only: bool,
    /// Players at the table (`GO`'s flag 0x10: three).
    seats: u8,
    names: [String; 4],
    named: bool,
    started: bool,
    in_round: bool,
    last_draw: [Option<TileId>; 4],
}

impl State {
    fn tile(&self, id: i64) -> Result<Tile, String> {
        let id = u8::try_from(id)
            .ok()
            .filter(|&i| i < 136)
            .ok_or_else(|| format!("tile id {id} is not 0-135"))?;
        let kind = TileType::new(id / 4).ok_or_else(|| format!("tile id {id} is not 0-135"))?;
        // With red fives the first copy of each five (ids 16, 52, 88) is the red one.
        Ok(match Tile::red(kind) {
            Some(red) if self.red && id % 4 == 0 => red,
            _ => Tile::plain(kind),
        })
    }

    fn pai(&self, id: i64) -> Result<Pai, String> {
        self.tile(id).map(Pai::known)
    }

    /// A meld's tiles in the order Tenhou's JSON logs write them: by type, a red five after the
    /// plain ones.
    fn pais<const N: usize>(&self, ids: [TileId; N]) -> Result<[Pai; N], String> {
        let mut tiles = Vec::with_capacity(N);
        for id in ids {
            tiles.push(self.tile(i64::from(id))?);
        }
        tiles.sort_by_key(|t| (t.kind(), t.is_red()));
        let mut out = [Pai::HIDDEN; N];
        for (slot, t) in out.iter_mut().zip(tiles) {
            *slot = Pai::known(t);
        }
        Ok(out)
    }

    /// Refuses a move of the fourth place at a three-player table.
    fn sits(&self, seat: usize) -> Result<(), String> {
        if seat >= usize::from(self.seats) {
            return Err(format!("seat {seat} moves at a table of {} players", self.seats));
        }
        Ok(())
    }

    /// The events a tag stands for.
    fn tag(&mut self, tag: &Tag) -> Result<Vec<Event>, String> {
        let name = tag.name;
        let mut chars = name.chars();
        let (first, rest) = (chars.next().unwrap_or(' '), chars.as_str());
        if !rest.is_empty() && rest.bytes().all(|b| b.is_ascii_digit()) {
            let id: i64 = rest.parse().map_err(|_| format!("{rest:?} is not a tile id"))?;
            if let Some(seat) = "TUVW".find(first) {
                self.sits(seat)?;
                self.last_draw[seat] = u8::try_from(id).ok();
                return Ok(vec![Event::Tsumo {
                    actor: seat as u8,
                    pai: self.pai(id)?,
                }]);
            }
            if let Some(seat) = "DEFG".find(first.to_ascii_uppercase()) {
                self.sits(seat)?;
                let tsumogiri = first.is_ascii_lowercase() || self.last_draw[seat] == u8::try_from(id).ok();
                self.last_draw[seat] = None;
                return Ok(vec![Event::Dahai {
                    actor: seat as u8,
                    pai: self.pai(id)?,
                    tsumogiri,
                }]);
            }
        }
        match name {
            "GO" => self.go(tag).map(|()| Vec::new()),
            "UN" => {
                if !self.named {
                    for (seat, name) in self.names.iter_mut().enumerate() {
                        let raw = tag.get(&format!("n{seat}")).unwrap_or_default();
                        *name = percent_decode_str(raw).decode_utf8_lossy().into_owned();
                    }
                    self.named = true;
                }
                Ok(Vec::new())
            }
            "INIT" => self.init(tag),
            "N" => self.meld(tag),
            "REACH" => {
                let actor = tag.seat("who")?;
                match tag.need("step")? {
                    "1" => Ok(vec![Event::Reach { actor }]),
                    "2" => {
                        let scores = match tag.get("ten") {
                            Some(_) => {
                                let ten = tag.numbers("ten")?;
                                let s: Vec<i32> = ten.into_iter().map(points).collect::<Result<_, _>>()?;
                                s.try_into().ok()
                            }
                            None => None,
                        };
                        Ok(vec![Event::ReachAccepted {
                            actor,
                            deltas: None,
                            scores,
                        }])
                    }
                    step => Err(format!("step {step:?} is neither 1 nor 2")),
                }
            }
            "DORA" => {
                let id = tag
                    .need("hai")?
                    .parse::<i64>()
                    .map_err(|_| "`hai` is not a tile id".to_string())?;
                Ok(vec![Event::Dora {
                    dora_marker: self.pai(id)?,
                }])
            }
            "AGARI" => self.agari(tag),
            "RYUUKYOKU" => self.ryuukyoku(tag),
            "mjloggm" | "SHUFFLE" | "TAIKYOKU" | "BYE" | "FURITEN" => Ok(Vec::new()),
            _ => Err("not a tag of Tenhou's mjlog format".into()),
        }
    }

    fn go(&mut self, tag: &Tag) -> Result<(), String> {
        let flags: u32 = tag
            .need("type")?
            .parse()
            .map_err(|_| "`type` is not a number".to_string())?;
        if flags & 0x10 != 0 {
            self.seats = 3;
            self.builder.three_players();
        }
        if flags & 0x04 != 0 {
            return Err(format!(
                "type {flags}: no kuitan (flag 0x04) is not a rule rinshan plays"
            ));
        }
        self.red = flags & 0x02 == 0;
        self.east_only = flags & 0x08 == 0;
        let room = ((flags & 0x20) >> 4 | (flags & 0x80) >> 7) as usize;
        self.rule = format!(
            "{}{}{}喰{}{}",
            if self.seats == 3 { "三" } else { "" },
            ROOMS[room],
            if self.east_only { "東" } else { "南" },
            if self.red { "赤" } else { "" },
            if flags & 0x40 != 0 { "速" } else { "" },
        );
        Ok(())
    }

    fn init(&mut self, tag: &Tag) -> Result<Vec<Event>, String> {
        let mut events = Vec::new();
        if !self.started {
            self.started = true;
            events.push(Event::StartGame {
                names: self.names.clone(),
                id: None,
                kyoku_first: Some(if self.east_only { 4 } else { 0 }),
                aka_flag: Some(self.red),
                rule: (!self.rule.is_empty()).then(|| self.rule.clone()),
                variant: None,
                preset: None,
                rules: None,
            });
        }
        if self.in_round {
            events.push(Event::EndKyoku {});
        }
        let seed = tag.numbers("seed")?;
        let [round, honba, sticks, _, _, dora] = seed[..] else {
            return Err(format!(
                "`seed` has {} numbers, not 6 (round, honba, sticks, dice, dice, dora)",
                seed.len()
            ));
        };
        let ten = tag.numbers("ten")?;
        let scores: Vec<i32> = ten.into_iter().map(points).collect::<Result<_, _>>()?;
        let scores: [i32; 4] = scores
            .try_into()
            .map_err(|_| "`ten` does not hold 4 scores".to_string())?;
        let count = |n: i64, what: &str| u32::try_from(n).map_err(|_| format!("{what} {n} is not a count"));
        let round = u8::try_from(round)
            .ok()
            .filter(|&r| r < 16)
            .ok_or_else(|| format!("round {round} is not 0-15"))?;
        let mut tehais: [Vec<Pai>; 4] = Default::default();
        for (seat, tehai) in tehais.iter_mut().enumerate() {
            // Very old logs name seat 0's hand `hai`.
            let key = format!("hai{seat}");
            let list = match (tag.get(&key), seat) {
                (Some(list), _) => list,
                (None, 0) => tag.need("hai")?,
                // Tenhou writes `hai3=""` for three players' empty place; edited logs drop it.
                (None, 3) if self.seats == 3 => "",
                (None, _) => return Err(format!("no `{key}`")),
            };
            let mut hand: Vec<Tile> = numbers(list)?
                .into_iter()
                .map(|id| self.tile(id))
                .collect::<Result<_, _>>()?;
            // Tenhou's JSON logs list a hand by type, a red five after the plain ones.
            hand.sort_by_key(|t| (t.kind(), t.is_red()));
            *tehai = hand.into_iter().map(Pai::known).collect();
        }
        if self.seats == 3 && !tehais[3].is_empty() {
            return Err("`hai3` deals a hand to the fourth place, which three players leave empty".into());
        }
        self.in_round = true;
        self.last_draw = [None; 4];
        events.push(Event::StartKyoku {
            bakaze: Pai(TileType::new(27 + round / 4 % 4).map(Tile::plain)),
            dora_marker: self.pai(dora)?,
            kyoku: round % 4 + 1,
            honba: count(honba, "honba")?,
            kyotaku: count(sticks, "sticks")?,
            oya: round % 4,
            scores,
            tehais,
        });
        Ok(events)
    }

    fn meld(&mut self, tag: &Tag) -> Result<Vec<Event>, String> {
        let actor = tag.seat("who")?;
        self.sits(usize::from(actor))?;
        let code: u16 = tag
            .need("m")?
            .parse()
            .map_err(|_| "`m` is not a 16-bit meld code".to_string())?;
        let meld = decode(code).ok_or_else(|| format!("m={code} names no tile"))?;
        let target = |from: u8| (actor + from) % 4;
        self.last_draw[usize::from(actor)] = None;
        Ok(vec![match meld {
            Meld::Chi { called, own } => Event::Chi {
                actor,
                target: target(3),
                pai: self.pai(i64::from(called))?,
                consumed: self.pais(own)?,
            },
            Meld::Pon { called, own, from } => Event::Pon {
                actor,
                target: target(from),
                pai: self.pai(i64::from(called))?,
                consumed: self.pais(own)?,
            },
            Meld::OpenKan { called, own, from } => Event::Daiminkan {
                actor,
                target: target(from),
                pai: self.pai(i64::from(called))?,
                consumed: self.pais(own)?,
            },
            Meld::AddedKan { added, called, own, .. } => Event::Kakan {
                actor,
                pai: self.pai(i64::from(added))?,
                consumed: self.pais([called, own[0], own[1]])?,
            },
            Meld::ClosedKan { tiles } => Event::Ankan {
                actor,
                consumed: self.pais(tiles)?,
            },
            Meld::North { tile } => {
                if self.seats == 4 {
                    return Err("a North set aside (kita) in a four-player game".into());
                }
                let pai = self.pai(i64::from(tile))?;
                if pai != Pai::known(Tile::plain(TileType::NORTH)) {
                    return Err(format!("a kita of {pai}, not North"));
                }
                Event::Kita { actor, pai }
            }
        }])
    }

    /// `sc="s0,d0,s1,d1,.."`: the score changes.
    fn deltas(tag: &Tag) -> Result<[i32; 4], String> {
        let sc = tag.numbers("sc")?;
        if sc.len() != 8 {
            return Err(format!("`sc` has {} numbers, not 8", sc.len()));
        }
        let d: Vec<i32> = sc
            .iter()
            .skip(1)
            .step_by(2)
            .map(|&d| points(d))
            .collect::<Result<_, _>>()?;
        d.try_into().map_err(|_| "`sc` does not hold 4 changes".to_string())
    }

    fn agari(&mut self, tag: &Tag) -> Result<Vec<Event>, String> {
        if !self.in_round {
            return Err("a win outside a round".into());
        }
        let (actor, target) = (tag.seat("who")?, tag.seat("fromWho")?);
        let pao = tag.get("paoWho").map(|_| tag.seat("paoWho")).transpose()?;
        let ten = tag.numbers("ten")?;
        let fu = ten.first().and_then(|&f| u32::try_from(f).ok());
        let mut yakus = Vec::new();
        let name = |id: i64| {
            let tenhou = usize::try_from(id).ok().and_then(|i| YAKU_IDS.get(i)).copied();
            let ours = tenhou.and_then(tenhou_yaku_name);
            ours.ok_or_else(|| format!("yaku id {id} is not one rinshan scores"))
        };
        if tag.get("yaku").is_some() {
            for pair in tag.numbers("yaku")?.chunks(2) {
                let [id, han] = pair else {
                    return Err("`yaku` is not pairs of id and han".into());
                };
                // Tenhou lists ura dora at 0 han for a riichi winner without any; its JSON omits it.
                if *han > 0 {
                    let han = u32::try_from(*han).map_err(|_| format!("han {han} is not a count"))?;
                    yakus.push((name(*id)?.to_string(), han));
                }
            }
        }
        if tag.get("yakuman").is_some() {
            for id in tag.numbers("yakuman")? {
                yakus.push((name(id)?.to_string(), crate::mjai::write::YAKUMAN_HAN));
            }
        }
        let ura = match tag.get("doraHaiUra") {
            Some(_) => Some(
                tag.numbers("doraHaiUra")?
                    .into_iter()
                    .map(|id| self.pai(id))
                    .collect::<Result<_, _>>()?,
            ),
            None => None,
        };
        let won = tag
            .need("machi")?
            .parse::<i64>()
            .map_err(|_| "`machi` is not a tile id".to_string())?;
        Ok(vec![Event::Hora {
            actor,
            target,
            pai: Some(self.pai(won)?),
            deltas: Some(Self::deltas(tag)?),
            ura_markers: ura,
            yakus: Some(yakus),
            fu,
            fan: None,
            hora_points: None,
            pao: pao.filter(|&p| p != actor),
        }])
    }

    fn ryuukyoku(&mut self, tag: &Tag) -> Result<Vec<Event>, String> {
        if !self.in_round {
            return Err("a draw outside a round".into());
        }
        let reason = match tag.get("type") {
            None => "fanpai",
            Some(kind) => DRAWS
                .iter()
                .find(|(t, _)| *t == kind)
                .map(|(_, r)| *r)
                .ok_or_else(|| format!("type {kind:?} is not a known draw"))?,
        };
        let tenpais = (reason == "fanpai").then(|| std::array::from_fn(|s| tag.get(&format!("hai{s}")).is_some()));
        Ok(vec![Event::Ryukyoku {
            reason: Some(reason.to_string()),
            tenpais,
            deltas: Some(Self::deltas(tag)?),
        }])
    }
}
