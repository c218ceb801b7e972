//! The usual written form of tiles: digits followed by their suit letter, `123m456p789s1234567z`.
//! `m` man, `p` pin, `s` sou, `z` honors (1-4 = E S W N, 5-7 = white green red); `0` is a red five.
//! Melds are `kind:tiles` with kind `chi`, `pon`, `kan` (open), `ankan` (closed) or `kakan` (added).

use std::fmt;

/// A tile type 0..33 (1m..9m, 1p..9p, 1s..9s, E S W N, white green red).
pub type Tile = u8;

/// Why a piece of notation could not be read: the input, the 0-based character position and what
/// is wrong.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct NotationError {
    pub input: String,
    pub position: usize,
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

/// Tiles in written order, each as (type, is red five).
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct Tiles {
    pub tiles: Vec<(Tile, bool)>,
}

impl Tiles {
    /// Counts per type, red fives folded into their type.
    pub fn counts(&self) -> [u8; 34] {
        let mut c = [0u8; 34];
        for &(t, _) in &self.tiles {
            c[t as usize] += 1;
        }
        c
    }

    /// Number of red fives.
    pub fn red(&self) -> u8 {
        self.tiles.iter().filter(|(_, r)| *r).count() as u8
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
                            (27 + d - 1, false)
                        }
                        _ => {
                            let base = match ch {
                                'm' => 0,
                                'p' => 9,
                                _ => 18,
                            };
                            if d == 0 {
                                (base + 4, true)
                            } else {
                                (base + d - 1, false)
                            }
                        }
                    };
                    tiles.push(tile);
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
pub fn parse_tile(input: &str) -> Result<(Tile, bool), NotationError> {
    let tiles = parse_tiles(input)?;
    match tiles.tiles.as_slice() {
        [one] => Ok(*one),
        _ => Err(err(input, 0, format!("expected one tile, found {}", tiles.tiles.len()))),
    }
}

/// How a meld was made.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum MeldKind {
    Chi,
    Pon,
    /// Open kan (daiminkan) on a discard.
    Kan,
    /// Closed kan (ankan); the hand stays concealed.
    Ankan,
    /// Added kan (kakan / shouminkan) on an earlier pon.
    Kakan,
}

/// A called or declared set. `tile` is the set's tile type (the lowest one for a chi).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Meld {
    pub kind: MeldKind,
    pub tile: Tile,
    /// Red fives inside the meld.
    pub red: u8,
}

impl Meld {
    /// The meld's tile types, 3 or 4 of them.
    pub fn tiles(&self) -> Vec<Tile> {
        match self.kind {
            MeldKind::Chi => vec![self.tile, self.tile + 1, self.tile + 2],
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
    let mut types: Vec<Tile> = tiles.tiles.iter().map(|t| t.0).collect();
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
        let run = types[0] < 27 && types[0] % 9 <= 6 && types[1] == types[0] + 1 && types[2] == types[0] + 2;
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

/// Writes a tile type back in notation, e.g. `5m`, `7z`.
pub fn tile_name(t: Tile) -> String {
    if t >= 27 {
        format!("{}z", t - 26)
    } else {
        format!("{}{}", t % 9 + 1, ['m', 'p', 's'][(t / 9) as usize])
    }
}

/// Writes a tile value back in notation: a type as [`tile_name`] does, a red five (34, 35, 36)
/// as `0m`, `0p`, `0s`.
pub fn value_name(v: u8) -> String {
    match v {
        34..=36 => format!("0{}", ['m', 'p', 's'][usize::from(v - 34)]),
        _ => tile_name(v),
    }
}

/// A wind as written on the command line: E, S, W or N.
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
        assert_eq!(
            t.tiles,
            vec![(0, false), (1, false), (4, true), (17, false), (33, false), (33, false)]
        );
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
                tile: 0,
                red: 0
            }
        );
        assert_eq!(
            parse_meld("pon:550p").unwrap(),
            Meld {
                kind: MeldKind::Pon,
                tile: 13,
                red: 1
            }
        );
        assert_eq!(parse_meld("ankan:1111s").unwrap().kind, MeldKind::Ankan);
        assert!(parse_meld("chi:135m").is_err());
        assert!(parse_meld("chi:123z").is_err());
        assert!(parse_meld("pon:556m").is_err());
        assert!(parse_meld("kan:555m").is_err());
        assert!(parse_meld("hold:555m")
            .unwrap_err()
            .message
            .contains("unknown meld kind"));
        assert_eq!(parse_meld("pon:55m").unwrap_err().position, 4);
    }
}
