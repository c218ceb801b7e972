//! MJAI tile names: `1m`..`9m`, `1p`..`9p`, `1s`..`9s`, `E S W N` (winds), `P F C` (white,
//! green, red dragon), `5mr 5pr 5sr` (red fives) and `?` for a tile the viewer cannot see.

use std::fmt;

use serde::de::{self, Deserializer, Visitor};
use serde::{Deserialize, Serialize, Serializer};

use rinshan_engine::tile::{Tile, TileType};

const HONORS: [&str; 7] = ["E", "S", "W", "N", "P", "F", "C"];
const SUITS: [char; 3] = ['m', 'p', 's'];

/// A tile as MJAI writes it: a known tile, or `?`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct Pai(pub Option<Tile>);

impl Pai {
    /// A known tile.
    pub fn known(tile: Tile) -> Pai {
        Pai(Some(tile))
    }

    /// `?`.
    pub const HIDDEN: Pai = Pai(None);

    /// The MJAI name of a tile.
    pub fn name_of(tile: Tile) -> String {
        let kind = tile.kind();
        match (kind.suit(), kind.number()) {
            (Some(s), Some(n)) => {
                let red = if tile.is_red() { "r" } else { "" };
                format!("{n}{}{red}", SUITS[usize::from(s)])
            }
            _ => HONORS[kind.index() - 27].to_string(),
        }
    }

    /// The tile an MJAI name stands for; `Some(Pai(None))` for `?`, `None` for anything else.
    pub fn parse(name: &str) -> Option<Pai> {
        if name == "?" {
            return Some(Pai::HIDDEN);
        }
        if let Some(i) = HONORS.iter().position(|h| *h == name) {
            return TileType::new(27 + i as u8).map(|t| Pai::known(Tile::plain(t)));
        }
        let bytes = name.as_bytes();
        let (digit, suit, red) = match bytes {
            [d, s] => (*d, *s, false),
            [d, s, b'r'] => (*d, *s, true),
            _ => return None,
        };
        let n = digit.checked_sub(b'1').filter(|n| *n < 9)?;
        let s = SUITS.iter().position(|c| *c as u8 == suit)? as u8;
        let kind = TileType::new(s * 9 + n)?;
        let tile = if red { Tile::red(kind)? } else { Tile::plain(kind) };
        Some(Pai::known(tile))
    }
}

impl fmt::Display for Pai {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.0 {
            Some(t) => f.write_str(&Pai::name_of(t)),
            None => f.write_str("?"),
        }
    }
}

impl Serialize for Pai {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.collect_str(self)
    }
}

impl<'de> Deserialize<'de> for Pai {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Pai, D::Error> {
        struct Name;
        impl Visitor<'_> for Name {
            type Value = Pai;
            fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
                f.write_str("an MJAI tile (1m..9m, 1p..9p, 1s..9s, E S W N P F C, 5mr 5pr 5sr or ?)")
            }
            fn visit_str<E: de::Error>(self, v: &str) -> Result<Pai, E> {
                Pai::parse(v).ok_or_else(|| E::invalid_value(de::Unexpected::Str(v), &self))
            }
        }
        d.deserialize_str(Name)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_38_names_are_the_protocols_and_round_trip() {
        // The 37 tiles and `?`, as libriichi's MJAI_PAI_STRINGS lists them (its order differs).
        let mut names: Vec<String> = (0..=36u8)
            .map(|v| Pai::name_of(Tile::from_value(v).expect("a tile value")))
            .collect();
        names.push("?".into());
        let expected = "1m 2m 3m 4m 5m 6m 7m 8m 9m 1p 2p 3p 4p 5p 6p 7p 8p 9p 1s 2s 3s 4s 5s 6s 7s 8s 9s \
                        E S W N P F C 5mr 5pr 5sr ?";
        assert_eq!(names.join(" "), expected);
        for name in expected.split(' ') {
            let pai = Pai::parse(name).expect("a protocol name");
            assert_eq!(pai.to_string(), name);
        }
        // Tenhou codes tie the names to physical tiles: 51 is the red 5m, 47 the red dragon.
        assert_eq!(Pai::parse("5mr"), Tile::from_tenhou_code(51).map(Pai::known));
        assert_eq!(Pai::parse("C"), Tile::from_tenhou_code(47).map(Pai::known));
        assert_eq!(Pai::parse("P"), Tile::from_tenhou_code(45).map(Pai::known));
    }

    #[test]
    fn other_names_are_refused() {
        for bad in ["", "0m", "5z", "1z", "4mr", "5m r", "5mrr", "10m", "e", "Wh", "??"] {
            assert_eq!(Pai::parse(bad), None, "{bad:?}");
        }
        let err = serde_json::from_str::<Pai>("\"4mr\"").expect_err("not a tile");
        assert!(err.to_string().contains("an MJAI tile"), "{err}");
    }
}
