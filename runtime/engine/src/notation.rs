//! The usual written form of tiles: digits followed by their suit letter, `123m456p789s1234567z`.
//! `m` man, `p` pin, `s` sou, `z` honors (1-4 = E S W N, 5-7 = white green red); `0` is a red five.
//! Melds are `kind:tiles` with kind `chi`, `pon`, `kan` (open), `ankan` (closed) or `kakan` (added).

use std::fmt;

use crate::tile::{Tile, TileType};

/// Why a piece of notation could not be read: the input, the 0-based character position and what
/// is wrong.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct NotationError {
    /// The text as given.
    pub input: String,
    /// Where in it (0-based, in characters) reading stopped.
    pub position: usize,
    /// What is wrong there.
    pub message: String,
}

impl fmt::Display for NotationError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "in `{}` at character {}: {}",
            self.input,
            self.position + 1,
            self.message
        )
    }
}

impl std::error::Error for NotationError {}

/// Tiles as written, in written order.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct Tiles {
    /// The tiles, red fives marked.
    pub tiles: Vec<Tile>,
}

impl Tiles {
    /// Counts per type, red fives folded into their type (at most 255: a longer run of one tile
    /// is still too many, and the callers refuse more than 4).
    pub fn counts(&self) -> [u8; 34] {
        let mut c = [0u8; 34];
        for t in &self.tiles {
            let n = &mut c[t.kind().index()];
            *n = n.saturating_add(1);
        }
        c
    }

    /// Number of red fives.
    pub fn red(&self) -> u8 {
        self.tiles.iter().filter(|t| t.is_red()).count() as u8
    }
}

fn err(input: &str, position: usize, message: impl Into<String>) -> NotationError {
    NotationError {
        input: input.to_string(),
        position,
        message: message.into(),
    }
}

/// Parses a run of tiles such as `123m0p77z`.
pub fn parse_tiles(input: &str) -> Result<Tiles, NotationError> {
    let mut tiles = Vec::new();
    let mut pending: Vec<(usize, u8)> = Vec::new();
    for (i, ch) in input.chars().enumerate() {
        match ch {
            '0'..='9' => pending.push((i, ch as u8 - b'0')),
            'm' | 'p' | 's' | 'z' => {
                if pending.is_empty() {
                    return Err(err(
                        input,
                        i,
                        format!("suit letter `{ch}` has no digits before it (write e.g. `123{ch}`)"),
                    ));
                }
                for &(pos, d) in &pending {
                    let tile = match ch {
                        'z' => {
                            if !(1..=7).contains(&d) {
                                return Err(err(
                                    input,
                                    pos,
                                    format!("honor `{d}z` does not exist: honors are 1z-7z (E S W N white green red)"),
                                ));
                            }
                            27 + d - 1
                        }
                        _ => {
                            let base = match ch {
                                'm' => 0,
                                'p' => 9,
                                _ => 18,
                            };
                            if d == 0 {
                                34 + base / 9
                            } else {
                                base + d - 1
                            }
                        }
                    };
                    // Every digit with its suit letter is a value 0..36: nothing is dropped here.
                    tiles.extend(Tile::from_value(tile));
                }
                pending.clear();
            }
            c if c.is_whitespace() => {
                return Err(err(
                    input,
                    i,
                    "unexpected space: write tiles without spaces, e.g. `123m456p`",
                ));
            }
            c => {
                return Err(err(
                    input,
                    i,
                    format!("unexpected `{c}`: expected a digit or a suit letter m, p, s, z"),
                ));
            }
        }
    }
    if let Some(&(pos, _)) = pending.first() {
        return Err(err(
            input,
            pos,
            "digits without a suit letter: end them with m, p, s or z",
        ));
    }
    if tiles.is_empty() {
        return Err(err(input, 0, "no tiles"));
    }
    Ok(Tiles { tiles })
}

/// Parses exactly one tile, e.g. `5m` or `0p`.
pub fn parse_tile(input: &str) -> Result<Tile, NotationError> {
    let tiles = parse_tiles(input)?;
    match tiles.tiles.as_slice() {
        [one] => Ok(*one),
        _ => Err(err(input, 0, format!("expected one tile, found {}", tiles.tiles.len()))),
    }
}

/// How a meld was made.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum MeldKind {
    /// A run called from the player on the left.
    Chi,
    /// A triplet called from any player.
    Pon,
    /// Open kan (daiminkan) on a discard.
    Kan,
    /// Closed kan (ankan); the hand stays concealed.
    Ankan,
    /// Added kan (kakan / shouminkan) on an earlier pon.
    Kakan,
}

/// A called or declared set.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Meld {
    /// How it was made.
    pub kind: MeldKind,
    /// The set's tile type (the lowest one for a chi).
    pub tile: TileType,
    /// Red fives inside the meld.
    pub red: u8,
}

impl Meld {
    /// The meld's tile types, 3 or 4 of them (fewer for a chi that is no run, which scoring rejects).
    pub fn tiles(&self) -> Vec<TileType> {
        match self.kind {
            MeldKind::Chi => (0..3).filter_map(|i| self.tile.up(i)).collect(),
            MeldKind::Pon => vec![self.tile; 3],
            _ => vec![self.tile; 4],
        }
    }
}

/// Parses `chi:123m`, `pon:555z`, `kan:2222p`, `ankan:1111s` or `kakan:3333m`.
pub fn parse_meld(input: &str) -> Result<Meld, NotationError> {
    let Some((kind, tiles_src)) = input.split_once(':') else {
        return Err(err(
            input,
            0,
            "a meld is `kind:tiles`, e.g. `pon:555z`, `chi:123m`, `ankan:1111s`",
        ));
    };
    let kind = match kind {
        "chi" => MeldKind::Chi,
        "pon" => MeldKind::Pon,
        "kan" | "minkan" | "daiminkan" => MeldKind::Kan,
        "ankan" => MeldKind::Ankan,
        "kakan" | "shouminkan" => MeldKind::Kakan,
        other => {
            return Err(err(
                input,
                0,
                format!("unknown meld kind `{other}`: use chi, pon, kan (open), ankan (closed) or kakan (added)"),
            ));
        }
    };
    let at = kind_len(input);
    let tiles = parse_tiles(tiles_src).map_err(|e| err(input, at + e.position, e.message))?;
    let mut types: Vec<TileType> = tiles.tiles.iter().map(|t| t.kind()).collect();
    types.sort_unstable();
    let red = tiles.red();
    let want = if kind == MeldKind::Chi || kind == MeldKind::Pon {
        3
    } else {
        4
    };
    if types.len() != want {
        return Err(err(
            input,
            at,
            format!("a {} has {want} tiles, found {}", kind_name(kind), types.len()),
        ));
    }
    if kind == MeldKind::Chi {
        let run = types[0].up(1) == Some(types[1]) && types[0].up(2) == Some(types[2]);
        if !run {
            return Err(err(
                input,
                at,
                "a chi is three consecutive numbers of one suit, e.g. `chi:345p`",
            ));
        }
    } else if types.iter().any(|&t| t != types[0]) {
        return Err(err(
            input,
            at,
            format!(
                "a {} is {want} identical tiles, e.g. `{}:{}`",
                kind_name(kind),
                kind_name(kind),
                "5".repeat(want) + "z"
            ),
        ));
    }
    Ok(Meld {
        kind,
        tile: types[0],
        red,
    })
}

fn kind_len(input: &str) -> usize {
    input.find(':').map_or(0, |i| i + 1)
}

fn kind_name(kind: MeldKind) -> &'static str {
    match kind {
        MeldKind::Chi => "chi",
        MeldKind::Pon => "pon",
        MeldKind::Kan => "kan",
        MeldKind::Ankan => "ankan",
        MeldKind::Kakan => "kakan",
    }
}

/// A wind as written on the command line: E, S, W or N, read as 0..3.
pub fn parse_wind(input: &str) -> Result<u8, NotationError> {
    match input.to_ascii_uppercase().as_str() {
        "E" | "EAST" => Ok(0),
        "S" | "SOUTH" => Ok(1),
        "W" | "WEST" => Ok(2),
        "N" | "NORTH" => Ok(3),
        _ => Err(err(input, 0, "a wind is E, S, W or N")),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reads_suits_honors_and_red_fives() {
        let t = parse_tiles("120m9p77z").unwrap();
        let values: Vec<u8> = t.tiles.iter().map(|t| t.value()).collect();
        assert_eq!(values, vec![0, 1, 34, 17, 33, 33]);
        assert_eq!(t.red(), 1);
        assert_eq!(t.counts()[33], 2);
    }

    #[test]
    fn rejects_malformed_tiles_with_position() {
        assert_eq!(parse_tiles("123").unwrap_err().position, 0);
        assert_eq!(parse_tiles("12x").unwrap_err().position, 2);
        assert!(parse_tiles("8z").unwrap_err().message.contains("1z-7z"));
        assert!(parse_tiles("m").unwrap_err().message.contains("no digits"));
    }

    #[test]
    fn reads_and_checks_melds() {
        assert_eq!(
            parse_meld("chi:312m").unwrap(),
            Meld {
                kind: MeldKind::Chi,
                tile: TileType::new(0).unwrap(),
                red: 0
            }
        );
        assert_eq!(
            parse_meld("pon:550p").unwrap(),
            Meld {
                kind: MeldKind::Pon,
                tile: TileType::new(13).unwrap(),
                red: 1
            }
        );
        assert_eq!(parse_meld("ankan:1111s").unwrap().kind, MeldKind::Ankan);
        assert!(parse_meld("chi:135m").is_err());
        assert!(parse_meld("chi:123z").is_err());
        assert!(parse_meld("chi:789m").is_ok() && parse_meld("chi:891m").is_err());
        assert!(parse_meld("pon:556m").is_err());
        assert!(parse_meld("kan:555m").is_err());
        assert!(parse_meld("hold:555m")
            .unwrap_err()
            .message
            .contains("unknown meld kind"));
        assert_eq!(parse_meld("pon:55m").unwrap_err().position, 4);
    }
}
