//! Tiles, in one vocabulary: a [`TileType`] is one of the 34 kinds of tile, a [`Tile`] is a
//! physical tile (a type, and for a five of a suit whether it is the red copy). Each encoding the
//! project meets converts here, fallibly: the type index 0..33, the kernel's tile value 0..36
//! (34..36 = red 5m 5p 5s) and Tenhou's two-digit codes. Notation (`5m`, `0p`, `7z`) is read by
//! [`crate::notation`] and written by `name()`.

use std::fmt;

/// The suits of the numbered tiles, in type order.
const SUITS: [char; 3] = ['m', 'p', 's'];

/// One of the 34 kinds of tile: 0-8 = 1m-9m, 9-17 = 1p-9p, 18-26 = 1s-9s, 27-30 = East South
/// West North, 31-33 = white green red dragon.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct TileType(u8);

/// A number that stands for no tile in the encoding it was read in.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct NotATile(pub u32);

impl fmt::Display for NotATile {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{} is not a tile", self.0)
    }
}

impl std::error::Error for NotATile {}

impl TileType {
    /// How many types there are.
    pub const COUNT: usize = 34;

    /// North, the tile three players set aside (kita).
    pub const NORTH: TileType = TileType(30);

    /// The type of index `index`, `None` past 33.
    pub const fn new(index: u8) -> Option<TileType> {
        if (index as usize) < TileType::COUNT {
            Some(TileType(index))
        } else {
            None
        }
    }

    /// Every type in index order.
    pub fn all() -> impl Iterator<Item = TileType> {
        (0..TileType::COUNT as u8).map(TileType)
    }

    /// The index 0..33, e.g. into a count per type.
    pub fn index(self) -> usize {
        usize::from(self.0)
    }

    /// The suit 0..2 (man, pin, sou) of a numbered tile, `None` for an honor.
    pub fn suit(self) -> Option<u8> {
        (self.0 < 27).then_some(self.0 / 9)
    }

    /// The number 1..9 of a numbered tile, `None` for an honor.
    pub fn number(self) -> Option<u8> {
        (self.0 < 27).then_some(self.0 % 9 + 1)
    }

    /// A wind or a dragon.
    pub fn is_honor(self) -> bool {
        self.0 >= 27
    }

    /// A five of a suit: the types that have a red copy in a variant with red fives.
    pub fn is_five(self) -> bool {
        self.number() == Some(5)
    }

    /// The type `steps` numbers higher in the same suit (a run's next tiles), `None` past 9 or
    /// for an honor.
    pub fn up(self, steps: u8) -> Option<TileType> {
        let n = self.number()?;
        (n + steps <= 9).then_some(TileType(self.0 + steps))
    }

    /// The type written in notation: `5m`, `7z`.
    pub fn name(self) -> String {
        match self.suit() {
            Some(s) => format!("{}{}", self.0 % 9 + 1, SUITS[usize::from(s)]),
            None => format!("{}z", self.0 - 26),
        }
    }
}

impl TryFrom<u8> for TileType {
    type Error = NotATile;

    fn try_from(index: u8) -> Result<TileType, NotATile> {
        TileType::new(index).ok_or(NotATile(u32::from(index)))
    }
}

impl From<TileType> for u8 {
    fn from(t: TileType) -> u8 {
        t.0
    }
}

impl From<TileType> for u32 {
    fn from(t: TileType) -> u32 {
        u32::from(t.0)
    }
}

impl fmt::Display for TileType {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.name())
    }
}

/// A physical tile: its type, and for a five of a suit whether it is the red copy. Ordered by
/// type, each red five after the 1s-9s and honors (by value, as Tenhou's codes order them).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct Tile(u8);

impl Tile {
    /// The plain (not red) copy of a type.
    pub const fn plain(kind: TileType) -> Tile {
        Tile(kind.0)
    }

    /// The red copy of a five, `None` for any other type.
    pub fn red(kind: TileType) -> Option<Tile> {
        let suit = kind.suit().filter(|_| kind.is_five())?;
        Some(Tile(34 + suit))
    }

    /// The tile of a kernel tile value: the type 0..33, or 34/35/36 for a red 5m/5p/5s; `None` past 36.
    pub fn from_value(value: u8) -> Option<Tile> {
        (value <= 36).then_some(Tile(value))
    }

    /// The kernel's tile value (see [`Tile::from_value`]).
    pub fn value(self) -> u8 {
        self.0
    }

    /// The tile's type, a red five counting as a five.
    pub fn kind(self) -> TileType {
        match self.0 {
            34..=36 => TileType((self.0 - 34) * 9 + 4),
            v => TileType(v),
        }
    }

    /// Whether it is a red five.
    pub fn is_red(self) -> bool {
        self.0 >= 34
    }

    /// The tile of a Tenhou code: 11-19 man 1-9, 21-29 pin, 31-39 sou, 41-47 E S W N white green
    /// red, 51/52/53 red 5m/5p/5s. `None` for anything else (60, 0 and 10 are not tiles).
    pub fn from_tenhou_code(code: u8) -> Option<Tile> {
        match code {
            11..=19 | 21..=29 | 31..=39 | 41..=47 => Some(Tile((code / 10 - 1) * 9 + code % 10 - 1)),
            51..=53 => Some(Tile(code - 51 + 34)),
            _ => None,
        }
    }

    /// The Tenhou code (see [`Tile::from_tenhou_code`]).
    pub fn tenhou_code(self) -> u8 {
        match self.0 {
            34..=36 => self.0 - 34 + 51,
            v => (v / 9 + 1) * 10 + v % 9 + 1,
        }
    }

    /// The tile written in notation: its type's name, or `0m`, `0p`, `0s` for a red five.
    pub fn name(self) -> String {
        match self.0 {
            34..=36 => format!("0{}", SUITS[usize::from(self.0 - 34)]),
            _ => self.kind().name(),
        }
    }
}

impl From<TileType> for Tile {
    fn from(kind: TileType) -> Tile {
        Tile::plain(kind)
    }
}

impl fmt::Display for Tile {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.name())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_encoding_round_trips() {
        for v in 0..=36u8 {
            let t = Tile::from_value(v).expect("a value");
            assert_eq!(Tile::from_tenhou_code(t.tenhou_code()), Some(t), "{v}");
            assert_eq!(
                t.kind().index(),
                if v >= 34 {
                    usize::from(v - 34) * 9 + 4
                } else {
                    usize::from(v)
                }
            );
        }
        assert_eq!(Tile::from_value(37), None);
        assert_eq!(TileType::try_from(34), Err(NotATile(34)));
        assert_eq!(TileType::all().map(|t| t.name()).nth(27).as_deref(), Some("1z"));
        let red5p = Tile::red(TileType::new(13).expect("5p")).expect("a red 5p");
        assert_eq!(
            (red5p.value(), red5p.tenhou_code(), red5p.name()),
            (35, 52, "0p".to_string())
        );
        assert_eq!(Tile::red(TileType::new(12).expect("4p")), None);
        assert_eq!(TileType::new(6).and_then(|t| t.up(2)), TileType::new(8));
        assert_eq!(TileType::new(7).and_then(|t| t.up(2)), None);
    }
}
