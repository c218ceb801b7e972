//! Tiles, draws and discards: the entries of a round's hands, draw lists and discard lists, and
//! the call and kan strings among them.

use serde_json::Value;

use super::value::show;
use rinshan_engine::tile::{Tile, TileType};

/// Where a called tile came from, relative to the caller.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Rel {
    /// Kamicha, the player before: seat + 3.
    Left,
    /// Toimen, the player opposite: seat + 2.
    Across,
    /// Shimocha, the player after: seat + 1.
    Right,
}

impl Rel {
    /// The place this direction points at, seen from seat `me`. Tenhou's logs seat every table at
    /// four places, and three players leave the fourth (North's) empty: from seat 0 the place
    /// before is that empty one and seat 2 sits across, so a three-player call between seats 0
    /// and 2 is written as from across (as its mjlog's meld codes count it, (discarder - caller)
    /// mod 4). At three seats the answer is 3 for a direction that points at the empty place.
    pub fn seat_of(self, me: usize) -> usize {
        match self {
            Rel::Left => (me + 3) % 4,
            Rel::Across => (me + 2) % 4,
            Rel::Right => (me + 1) % 4,
        }
    }

    /// The direction of seat `other` seen from seat `me`, at Tenhou's four places.
    pub fn between(me: usize, other: usize) -> Rel {
        match (other + 4 - me) % 4 {
            1 => Rel::Right,
            2 => Rel::Across,
            _ => Rel::Left,
        }
    }
}

/// One entry of a seat's draws: a tile from the wall (or the dead wall after a kan), or a call
/// of another seat's discard.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Draw {
    /// A tile drawn from the wall.
    Tile(Tile),
    /// Always from the left.
    Chi {
        /// The discard taken.
        called: Tile,
        /// The caller's two tiles, in written order.
        own: [Tile; 2],
    },
    /// A triplet on another seat's discard.
    Pon {
        /// The discard taken.
        called: Tile,
        /// The caller's two tiles, in written order.
        own: [Tile; 2],
        /// Who discarded it.
        from: Rel,
    },
    /// Daiminkan; its discard entry is [`Discard::Nothing`] and the next draw is the replacement.
    OpenKan {
        /// The discard taken.
        called: Tile,
        /// The caller's three tiles, in written order.
        own: [Tile; 3],
        /// Who discarded it.
        from: Rel,
    },
}

impl Draw {
    /// Every tile the entry names, the called one first.
    pub fn tiles(&self) -> Vec<Tile> {
        match *self {
            Draw::Tile(t) => vec![t],
            Draw::Chi { called, own } | Draw::Pon { called, own, .. } => vec![called, own[0], own[1]],
            Draw::OpenKan { called, own, .. } => vec![called, own[0], own[1], own[2]],
        }
    }
}

/// One entry of a seat's discards.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Discard {
    /// A tile from the hand.
    Tile(Tile),
    /// The tile just drawn (`60`).
    Tsumogiri,
    /// Riichi declared with this discard; `None` when it is the tile just drawn (`r60`).
    Riichi(Option<Tile>),
    /// Kakan: a tile joins an earlier pon; no discard follows, the next draw is the replacement.
    AddedKan {
        /// The tile added.
        added: Tile,
        /// The pon's tiles, the called one first.
        pon: [Tile; 3],
        /// Who the pon's tile was called from.
        from: Rel,
    },
    /// Ankan; the next draw is the replacement.
    ClosedKan {
        /// The four tiles in written order.
        tiles: [Tile; 4],
    },
    /// The `0` that stands for the missing discard after an open kan.
    Nothing,
    /// Kita: a North set aside (three players), written `f44`; the next draw is the replacement.
    Kita,
}

impl Discard {
    /// Every tile the entry names (none for [`Discard::Tsumogiri`], `r60` and [`Discard::Nothing`];
    /// the North of [`Discard::Kita`]).
    pub fn tiles(&self) -> Vec<Tile> {
        match *self {
            Discard::Tile(t) | Discard::Riichi(Some(t)) => vec![t],
            Discard::AddedKan { added, pon, .. } => vec![added, pon[0], pon[1], pon[2]],
            Discard::ClosedKan { tiles } => tiles.to_vec(),
            Discard::Kita => vec![Tile::plain(TileType::NORTH)],
            Discard::Tsumogiri | Discard::Riichi(None) | Discard::Nothing => Vec::new(),
        }
    }
}

/// How a kita stands among the discards (the convention of the tenhou.net/6 three-player logs).
pub(crate) const KITA: &str = "f44";

pub(super) fn tile(v: &Value) -> Result<Tile, String> {
    let tile = v
        .as_u64()
        .and_then(|c| u8::try_from(c).ok())
        .and_then(Tile::from_tenhou_code);
    tile.ok_or_else(|| format!("{} is not a tile (11-19, 21-29, 31-39, 41-47 or 51-53)", show(v)))
}

pub(super) fn parse_draw(v: &Value) -> Result<Draw, String> {
    match v {
        Value::String(s) => parse_call(s).map_err(|why| format!("{} is not a call: {why}", show(v))),
        _ => tile(v).map(Draw::Tile),
    }
}

pub(super) fn parse_discard(v: &Value) -> Result<Discard, String> {
    match v {
        Value::String(s) => parse_kan_or_riichi(s).map_err(|why| format!("{} is not a discard: {why}", show(v))),
        _ => match v.as_u64() {
            Some(60) => Ok(Discard::Tsumogiri),
            Some(0) => Ok(Discard::Nothing),
            _ => tile(v)
                .map(Discard::Tile)
                .map_err(|m| format!("{m}, 60 (the drawn tile) or 0 (after an open kan)")),
        },
    }
}

/// A call or kan string taken apart.
struct Written {
    letter: char,
    /// Byte position of the letter.
    at: usize,
    /// All tiles in written order.
    tiles: Vec<Tile>,
    /// Index in `tiles` of the tile written right after the letter.
    after: usize,
}

impl Written {
    fn read(s: &str) -> Result<Written, String> {
        let mut letters = s.char_indices().filter(|(_, c)| !c.is_ascii_digit());
        let (at, letter) = letters.next().ok_or("it has no letter")?;
        if let Some((_, second)) = letters.next() {
            return Err(format!("it has a second letter {second:?}"));
        }
        let (before, rest) = (&s[..at], &s[at + letter.len_utf8()..]);
        let mut tiles = codes(before)?;
        let after = tiles.len();
        tiles.extend(codes(rest)?);
        Ok(Written {
            letter,
            at,
            tiles,
            after,
        })
    }

    /// Checks the tile count, for a meld `what` of `n` tiles.
    fn expect(&self, n: usize, what: &str) -> Result<(), String> {
        if self.tiles.len() != n {
            return Err(format!("{what} needs {n} tiles, found {}", self.tiles.len()));
        }
        Ok(())
    }

    /// The `K` tiles written right after the letter and the `N` others in written order.
    fn split<const K: usize, const N: usize>(&self) -> Result<([Tile; K], [Tile; N]), String> {
        let end = self.after + K;
        let picked = self.tiles.get(self.after..end).map(<[Tile; K]>::try_from);
        let others: Vec<Tile> = self
            .tiles
            .iter()
            .take(self.after)
            .chain(self.tiles.iter().skip(end))
            .copied()
            .collect();
        match (picked, <[Tile; N]>::try_from(others.as_slice())) {
            (Some(Ok(picked)), Ok(others)) => Ok((picked, others)),
            _ => Err(format!(
                "expected {K} tiles after the letter {:?} and {N} others",
                self.letter
            )),
        }
    }

    /// The direction given by the letter's position among `positions` (left, across, right).
    fn from(&self, positions: [usize; 3]) -> Result<Rel, String> {
        match positions.iter().position(|&p| p == self.at) {
            Some(0) => Ok(Rel::Left),
            Some(1) => Ok(Rel::Across),
            Some(2) => Ok(Rel::Right),
            _ => Err(format!(
                "the letter {:?} is at position {}, expected {}, {} or {}",
                self.letter, self.at, positions[0], positions[1], positions[2]
            )),
        }
    }
}

/// Two-digit tile codes run together.
fn codes(digits: &str) -> Result<Vec<Tile>, String> {
    digits
        .as_bytes()
        .chunks(2)
        .map(|pair| match *pair {
            [a, b] => {
                let code = (a - b'0') * 10 + (b - b'0');
                Tile::from_tenhou_code(code).ok_or_else(|| format!("{code} is not a tile"))
            }
            _ => Err(format!("{digits:?} is not a run of two-digit tiles")),
        })
        .collect()
}

fn same_kind(tiles: &[Tile]) -> Result<(), String> {
    match tiles.split_first() {
        Some((first, rest)) if rest.iter().any(|t| t.kind() != first.kind()) => {
            let list: Vec<String> = tiles.iter().map(|t| t.tenhou_code().to_string()).collect();
            Err(format!("tiles {} are not all the same", list.join(" ")))
        }
        _ => Ok(()),
    }
}

fn parse_call(s: &str) -> Result<Draw, String> {
    let w = Written::read(s)?;
    match w.letter {
        'c' => {
            w.expect(3, "a chi")?;
            if w.at != 0 {
                return Err(format!("the letter 'c' is at position {}, expected 0", w.at));
            }
            let ([called], own) = w.split::<1, 2>()?;
            let mut kinds = [called.kind(), own[0].kind(), own[1].kind()];
            kinds.sort_unstable();
            let [a, b, c] = kinds;
            if a.up(1) != Some(b) || a.up(2) != Some(c) {
                let [x, y, z] = [called, own[0], own[1]].map(Tile::tenhou_code);
                return Err(format!("tiles {x} {y} {z} are not a run"));
            }
            Ok(Draw::Chi { called, own })
        }
        'p' => {
            w.expect(3, "a pon")?;
            let from = w.from([0, 2, 4])?;
            let ([called], own) = w.split::<1, 2>()?;
            same_kind(&w.tiles)?;
            Ok(Draw::Pon { called, own, from })
        }
        'm' => {
            w.expect(4, "an open kan")?;
            let from = w.from([0, 2, 6])?;
            let ([called], own) = w.split::<1, 3>()?;
            same_kind(&w.tiles)?;
            Ok(Draw::OpenKan { called, own, from })
        }
        other => Err(format!("{other:?} is not a call letter (c chi, p pon, m open kan)")),
    }
}

fn parse_kan_or_riichi(s: &str) -> Result<Discard, String> {
    if s == KITA {
        return Ok(Discard::Kita);
    }
    if let Some(rest) = s.strip_prefix('r') {
        if rest == "60" {
            return Ok(Discard::Riichi(None));
        }
        let code = rest
            .parse::<u8>()
            .ok()
            .filter(|_| rest.len() == 2 && rest.bytes().all(|b| b.is_ascii_digit()));
        let tile = code
            .and_then(Tile::from_tenhou_code)
            .ok_or_else(|| format!("{rest:?} after 'r' is not a tile or 60"))?;
        return Ok(Discard::Riichi(Some(tile)));
    }
    let w = Written::read(s)?;
    match w.letter {
        'k' => {
            w.expect(4, "an added kan")?;
            same_kind(&w.tiles)?;
            let from = w.from([0, 2, 4])?;
            // The added tile follows the letter and the pon's called tile follows it.
            let ([added, called], own) = w.split::<2, 2>()?;
            let pon = [called, own[0], own[1]];
            Ok(Discard::AddedKan { added, pon, from })
        }
        'a' => {
            w.expect(4, "a closed kan")?;
            same_kind(&w.tiles)?;
            let tiles = <[Tile; 4]>::try_from(w.tiles.as_slice()).map_err(|_| "a closed kan needs 4 tiles")?;
            Ok(Discard::ClosedKan { tiles })
        }
        other => Err(format!(
            "{other:?} is not a discard letter (r riichi, k added kan, a closed kan, f44 kita)"
        )),
    }
}
