//! The MJAI events as JSON objects (`{"type":"dahai","actor":0,"pai":"C","tsumogiri":false}`),
//! in the schema of Mortal's libriichi, with the optional extras real logs carry (the original
//! mjai server's and akochan's). Fields are written in the order the engines write them; a
//! reader ignores fields it does not know, as libriichi does.
//!
//! The per-seat lists hold four seats here; a three-player log lists three
//! ([`super::write::game_text`] cuts them) and sets North aside with `kita`.

use serde::{Deserialize, Serialize};

use super::tile::Pai;

/// The fields that list one entry per seat (four in [`Event`]; a three-player log lists three).
pub(crate) const PER_SEAT: [&str; 5] = ["names", "scores", "tehais", "deltas", "tenpais"];

/// An event's JSON object with its per-seat lists cut to `seats` entries (the order of its fields
/// is `serde_json`'s map order; [`super::write::game_text`] keeps the engines' order for logs).
pub(crate) fn seat_lists_cut(mut event: serde_json::Value, seats: usize) -> serde_json::Value {
    for key in PER_SEAT {
        if let Some(serde_json::Value::Array(list)) = event.get_mut(key) {
            list.truncate(seats);
        }
    }
    event
}

/// One MJAI event. Seats (`actor`, `target`, `oya`) count from East 1's dealer.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(tag = "type", rename_all = "snake_case")]
pub enum Event {
    /// A reaction that does nothing (also seen in logs carrying a bot's meta data).
    None {},
    /// The game starts.
    StartGame {
        /// Player names by seat.
        #[serde(default)]
        names: [String; 4],
        /// The receiving bot's seat (mjai.app, original mjai).
        #[serde(default, skip_serializing_if = "Option::is_none")]
        id: Option<u8>,
        /// akochan's game length: 0 for a half game (East and South), 4 for East only.
        #[serde(default, skip_serializing_if = "Option::is_none")]
        kyoku_first: Option<u8>,
        /// Red fives in play.
        #[serde(default, skip_serializing_if = "Option::is_none")]
        aka_flag: Option<bool>,
        /// The rule's name in a Tenhou log (`鳳南喰赤`), kept so a converted log converts back.
        #[serde(default, skip_serializing_if = "Option::is_none")]
        rule: Option<String>,
        /// rinshan's rule set (`mleague`, `sanma`), written for every one but Tenhou's.
        #[serde(default, skip_serializing_if = "Option::is_none")]
        variant: Option<String>,
        /// jansou's preset (`tenhou`, `m-league`, `mahjong-soul-3p`).
        #[serde(default, skip_serializing_if = "Option::is_none")]
        preset: Option<String>,
        /// jansou's whole rules configuration, one flat object.
        #[serde(default, skip_serializing_if = "Option::is_none")]
        rules: Option<serde_json::Map<String, serde_json::Value>>,
    },
    /// A round (kyoku) is dealt.
    StartKyoku {
        /// The round wind: `E`, `S`, `W`, `N`.
        bakaze: Pai,
        /// The first dora indicator.
        dora_marker: Pai,
        /// 1 to 4 within the wind.
        kyoku: u8,
        /// Repeat counters.
        honba: u32,
        /// Riichi sticks on the table.
        kyotaku: u32,
        /// The dealer.
        oya: u8,
        /// Scores at the start.
        scores: [i32; 4],
        /// Starting hands, 13 tiles each (`?` for hands the viewer cannot see).
        tehais: [Vec<Pai>; 4],
    },
    /// A draw, from the wall or (after a kan) the dead wall.
    Tsumo {
        /// The seat drawing.
        actor: u8,
        /// The tile drawn (`?` for others' draws in a seat's view).
        pai: Pai,
    },
    /// A discard.
    Dahai {
        /// The seat discarding.
        actor: u8,
        /// The tile.
        pai: Pai,
        /// The tile just drawn.
        tsumogiri: bool,
    },
    /// A sequence called from the seat before.
    Chi {
        /// The caller.
        actor: u8,
        /// The discarder.
        target: u8,
        /// The called tile.
        pai: Pai,
        /// The caller's two tiles.
        consumed: [Pai; 2],
    },
    /// A triplet called.
    Pon {
        /// The caller.
        actor: u8,
        /// The discarder.
        target: u8,
        /// The called tile.
        pai: Pai,
        /// The caller's two tiles.
        consumed: [Pai; 2],
    },
    /// An open kan on a discard.
    Daiminkan {
        /// The caller.
        actor: u8,
        /// The discarder.
        target: u8,
        /// The called tile.
        pai: Pai,
        /// The caller's three tiles.
        consumed: [Pai; 3],
    },
    /// A tile added to a pon.
    Kakan {
        /// The seat.
        actor: u8,
        /// The tile added.
        pai: Pai,
        /// The pon's three tiles.
        consumed: [Pai; 3],
    },
    /// A closed kan.
    Ankan {
        /// The seat.
        actor: u8,
        /// The four tiles.
        consumed: [Pai; 4],
    },
    /// A North set aside (three players); the seat's next event is its replacement draw. The
    /// three-player forks of Mortal and mjai-reviewer name it `nukidora`.
    #[serde(alias = "nukidora")]
    Kita {
        /// The seat.
        actor: u8,
        /// The tile, always `N`.
        pai: Pai,
    },
    /// A new dora indicator after a kan.
    Dora {
        /// The indicator.
        dora_marker: Pai,
    },
    /// Riichi declared; the seat's next event is its discard.
    Reach {
        /// The seat.
        actor: u8,
    },
    /// The riichi discard passed: the stick is on the table.
    ReachAccepted {
        /// The seat.
        actor: u8,
        /// The score changes (-1000 for the seat).
        #[serde(default, skip_serializing_if = "Option::is_none")]
        deltas: Option<[i32; 4]>,
        /// The scores after.
        #[serde(default, skip_serializing_if = "Option::is_none")]
        scores: Option<[i32; 4]>,
    },
    /// A win; a double ron is two in a row.
    Hora {
        /// The winner.
        actor: u8,
        /// The discarder, or the winner for a tsumo.
        target: u8,
        /// The winning tile.
        #[serde(default, skip_serializing_if = "Option::is_none")]
        pai: Option<Pai>,
        /// Score changes, honba, sticks and pao included.
        #[serde(default, skip_serializing_if = "Option::is_none")]
        deltas: Option<[i32; 4]>,
        /// Ura dora indicators, for a winner in riichi.
        #[serde(default, skip_serializing_if = "Option::is_none")]
        ura_markers: Option<Vec<Pai>>,
        /// The yaku with their han (13 per yakuman), dora last.
        #[serde(default, skip_serializing_if = "Option::is_none")]
        yakus: Option<Vec<(String, u32)>>,
        /// Fu.
        #[serde(default, skip_serializing_if = "Option::is_none")]
        fu: Option<u32>,
        /// Han.
        #[serde(default, skip_serializing_if = "Option::is_none")]
        fan: Option<u32>,
        /// The hand's value before honba and sticks (a tsumo's payments summed).
        #[serde(default, skip_serializing_if = "Option::is_none")]
        hora_points: Option<u32>,
        /// The seat liable for a yakuman (pao), when another than the discarder.
        #[serde(default, skip_serializing_if = "Option::is_none")]
        pao: Option<u8>,
    },
    /// A round without a win.
    Ryukyoku {
        /// Why: `fanpai` (the wall ran out), `nagashimangan`, `kyushukyuhai`, `suchareach`,
        /// `sanchaho`, `sukaikan`, `sufonrenta`.
        #[serde(default, skip_serializing_if = "Option::is_none")]
        reason: Option<String>,
        /// Which seats were tenpai (at an exhaustive draw).
        #[serde(default, skip_serializing_if = "Option::is_none")]
        tenpais: Option<[bool; 4]>,
        /// Score changes.
        #[serde(default, skip_serializing_if = "Option::is_none")]
        deltas: Option<[i32; 4]>,
    },
    /// The round is over.
    EndKyoku {},
    /// The game is over.
    EndGame {
        /// Final scores.
        #[serde(default, skip_serializing_if = "Option::is_none")]
        scores: Option<[i32; 4]>,
    },
}

impl Event {
    /// The protocol's name of the event (`start_kyoku`, `dahai`, ..).
    pub fn kind(&self) -> &'static str {
        match self {
            Event::None {} => "none",
            Event::StartGame { .. } => "start_game",
            Event::StartKyoku { .. } => "start_kyoku",
            Event::Tsumo { .. } => "tsumo",
            Event::Dahai { .. } => "dahai",
            Event::Chi { .. } => "chi",
            Event::Pon { .. } => "pon",
            Event::Daiminkan { .. } => "daiminkan",
            Event::Kakan { .. } => "kakan",
            Event::Ankan { .. } => "ankan",
            Event::Kita { .. } => "kita",
            Event::Dora { .. } => "dora",
            Event::Reach { .. } => "reach",
            Event::ReachAccepted { .. } => "reach_accepted",
            Event::Hora { .. } => "hora",
            Event::Ryukyoku { .. } => "ryukyoku",
            Event::EndKyoku {} => "end_kyoku",
            Event::EndGame { .. } => "end_game",
        }
    }
}
