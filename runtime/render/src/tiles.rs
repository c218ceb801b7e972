//! One tile drawn in each mode: a procedural body, FluffyStuff's CC0 face art (`ja`, `en`) and an
//! ASCII label (`en` in the corner, `ascii` alone), so no picture depends on the machine's fonts
//! for the ideograms.

use std::fmt::Write as _;

use super::options::TileMode;
use rinshan_engine::Tile;

/// The face art, one file per tile (`assets/tiles/import.py` made them from FluffyStuff's set).
const FACES: [(&str, &str); 37] = [
    ("1m", include_str!("../assets/tiles/1m.svg")),
    ("2m", include_str!("../assets/tiles/2m.svg")),
    ("3m", include_str!("../assets/tiles/3m.svg")),
    ("4m", include_str!("../assets/tiles/4m.svg")),
    ("5m", include_str!("../assets/tiles/5m.svg")),
    ("6m", include_str!("../assets/tiles/6m.svg")),
    ("7m", include_str!("../assets/tiles/7m.svg")),
    ("8m", include_str!("../assets/tiles/8m.svg")),
    ("9m", include_str!("../assets/tiles/9m.svg")),
    ("1p", include_str!("../assets/tiles/1p.svg")),
    ("2p", include_str!("../assets/tiles/2p.svg")),
    ("3p", include_str!("../assets/tiles/3p.svg")),
    ("4p", include_str!("../assets/tiles/4p.svg")),
    ("5p", include_str!("../assets/tiles/5p.svg")),
    ("6p", include_str!("../assets/tiles/6p.svg")),
    ("7p", include_str!("../assets/tiles/7p.svg")),
    ("8p", include_str!("../assets/tiles/8p.svg")),
    ("9p", include_str!("../assets/tiles/9p.svg")),
    ("1s", include_str!("../assets/tiles/1s.svg")),
    ("2s", include_str!("../assets/tiles/2s.svg")),
    ("3s", include_str!("../assets/tiles/3s.svg")),
    ("4s", include_str!("../assets/tiles/4s.svg")),
    ("5s", include_str!("../assets/tiles/5s.svg")),
    ("6s", include_str!("../assets/tiles/6s.svg")),
    ("7s", include_str!("../assets/tiles/7s.svg")),
    ("8s", include_str!("../assets/tiles/8s.svg")),
    ("9s", include_str!("../assets/tiles/9s.svg")),
    ("E", include_str!("../assets/tiles/E.svg")),
    ("S", include_str!("../assets/tiles/S.svg")),
    ("W", include_str!("../assets/tiles/W.svg")),
    ("N", include_str!("../assets/tiles/N.svg")),
    ("P", include_str!("../assets/tiles/P.svg")),
    ("F", include_str!("../assets/tiles/F.svg")),
    ("C", include_str!("../assets/tiles/C.svg")),
    ("0m", include_str!("../assets/tiles/0m.svg")),
    ("0p", include_str!("../assets/tiles/0p.svg")),
    ("0s", include_str!("../assets/tiles/0s.svg")),
];

/// Tiles are drawn as `<use>`s of one symbol per tile in this box, scaled to each place: the
/// picture's markup is then the same in every mode, and only the symbols differ.
const BOX: (f32, f32) = (30.0, 40.0);
/// The symbols: 37 tiles by kernel value, then the back.
const BACK: usize = 37;

fn symbol_name(i: usize) -> String {
    if i == BACK {
        return "back".to_string();
    }
    u8::try_from(i)
        .ok()
        .and_then(Tile::from_value)
        .map_or_else(|| "back".to_string(), |t| t.name())
}

/// Tiles drawn so far, to put each used symbol once in `<defs>`.
pub(super) struct UsedTiles([bool; 38]);

impl Default for UsedTiles {
    fn default() -> UsedTiles {
        UsedTiles([false; 38])
    }
}

impl UsedTiles {
    pub(super) fn all() -> UsedTiles {
        UsedTiles([true; 38])
    }

    /// A `<symbol>` per used tile, drawn in `mode`.
    pub(super) fn write_defs(&self, out: &mut String, mode: TileMode) {
        let (w, h) = BOX;
        for i in (0..38).filter(|&i| self.0[i]) {
            let _ = write!(
                out,
                r#"<symbol id="t-{}" viewBox="0 0 {w} {h}" preserveAspectRatio="none">"#,
                symbol_name(i)
            );
            let tile = u8::try_from(i).ok().and_then(Tile::from_value).filter(|_| i != BACK);
            match tile {
                None => {
                    let _ = write!(
                        out,
                        r##"<rect width="{w}" height="{h}" rx="3.5" fill="#e9d8a6" stroke="#6d5a2c"/><rect x="2" y="2" width="{}" height="{}" rx="3" fill="#2f7a5a"/>"##,
                        w - 4.0,
                        h - 5.0
                    );
                }
                Some(t) => face(out, mode, t),
            }
            out.push_str("</symbol>");
        }
    }
}

/// One face-up tile in the symbol box.
fn face(out: &mut String, mode: TileMode, t: Tile) {
    let (w, h) = BOX;
    let _ = write!(
        out,
        r##"<rect x="0.5" y="0.5" width="{}" height="{}" rx="3.5" fill="#fffdf5" stroke="#6d6250"/><rect x="1" y="{}" width="{}" height="3" fill="#e4d7b4"/>"##,
        w - 1.0,
        h - 1.0,
        h - 4.0,
        w - 2.0
    );
    let (view_box, art) = split_face(FACES[usize::from(t.value())].1);
    let fill = colour(t);
    let text = label(t);
    // FluffyStuff's white dragon is blank; a blue frame tells it from a tile drawn wrong.
    if t.kind().index() == 31 && mode != TileMode::Ascii {
        let (x, y, w, h) = if mode == TileMode::Ja {
            (7.0, 8.0, 16.0, 23.0)
        } else {
            (11.5, 14.0, 13.5, 19.0)
        };
        let _ = write!(
            out,
            r##"<rect x="{x}" y="{y}" width="{w}" height="{h}" rx="1.5" fill="none" stroke="#2a5d9f" stroke-width="1.6"/>"##
        );
    }
    match mode {
        TileMode::Ja => {
            let _ = write!(
                out,
                r#"<svg x="2" y="2.5" width="26" height="34" viewBox="{view_box}">{art}</svg>"#
            );
        }
        TileMode::En => {
            let _ = write!(
                out,
                r#"<svg x="8.5" y="11" width="19.5" height="26" viewBox="{view_box}">{art}</svg><text x="2.5" y="10.5" font-size="9.5" fill="{fill}">{text}</text>"#
            );
        }
        TileMode::Ascii => {
            let size = if text.len() > 1 { 13 } else { 16 };
            let _ = write!(
                out,
                r#"<text x="15" y="25" font-size="{size}" fill="{fill}" text-anchor="middle">{text}</text>"#
            );
        }
    }
    if t.is_red() && mode != TileMode::Ja {
        out.push_str(r##"<circle cx="25" cy="6" r="2.6" fill="#e01b1b"/>"##);
    }
}

/// A face file's viewBox and its drawing.
fn split_face(svg: &str) -> (&str, &str) {
    let view_box = svg
        .split_once("viewBox=\"")
        .and_then(|(_, rest)| rest.split_once('"'))
        .map_or("0 0 300 400", |(v, _)| v);
    let inner = svg
        .split_once('>')
        .map(|(_, rest)| rest.trim_end().trim_end_matches("</svg>"))
        .unwrap_or("");
    (view_box, inner)
}

/// The ASCII label: `5m`, `E`, `Wh`; a red five reads as its five.
pub fn label(t: Tile) -> String {
    let k = t.kind();
    match k.suit() {
        Some(_) => k.name(),
        None => ["E", "S", "W", "N", "Wh", "Gr", "Rd"][k.index() - 27].to_string(),
    }
}

/// The label's colour: the suit's, or the dragon's.
fn colour(t: Tile) -> &'static str {
    if t.is_red() {
        return "#e01b1b";
    }
    match (t.kind().suit(), t.kind().index()) {
        (Some(0), _) => "#b71c1c",
        (Some(1), _) => "#1f3f99",
        (Some(_), _) => "#16703c",
        (None, 31) => "#6b6b6b",
        (None, 32) => "#16703c",
        (None, 33) => "#b71c1c",
        _ => "#202020",
    }
}

/// What a person calls it: `5m`, `red 5m`, `East wind`.
pub(super) fn title(t: Tile) -> String {
    const HONORS: [&str; 7] = [
        "East wind",
        "South wind",
        "West wind",
        "North wind",
        "White dragon",
        "Green dragon",
        "Red dragon",
    ];
    match t.kind().suit() {
        Some(_) if t.is_red() => format!("red {}", t.kind().name()),
        Some(_) => t.kind().name(),
        None => HONORS[t.kind().index() - 27].to_string(),
    }
}

/// Where and how one tile lies.
pub(super) struct Place<'a> {
    pub x: f32,
    pub y: f32,
    pub w: f32,
    pub h: f32,
    /// Turned a quarter to the left (a called tile, a riichi discard): it then takes `h` by `w`.
    pub sideways: bool,
    pub seat: u32,
    pub zone: &'a str,
    pub flags: &'a str,
}

/// Draws `tile` (`None` = face down) at `p`: a group naming the tile in `data-` attributes and a
/// `<title>`, holding a `<use>` of the tile's symbol.
pub(super) fn draw(out: &mut String, used: &mut UsedTiles, tile: Option<Tile>, p: &Place) {
    let (index, name, title) = match tile {
        Some(t) => (usize::from(t.value()), t.name(), title(t)),
        None => (BACK, "back".to_string(), "hidden tile".to_string()),
    };
    used.0[index] = true;
    let _ = write!(
        out,
        r#"<g class="tile" data-tile="{name}" data-seat="{}" data-zone="{}""#,
        p.seat, p.zone
    );
    if !p.flags.is_empty() {
        let _ = write!(out, r#" data-flags="{}""#, p.flags);
    }
    if p.sideways {
        let _ = write!(out, r#" transform="translate({} {}) rotate(-90)""#, p.x, p.y + p.w);
    } else {
        let _ = write!(out, r#" transform="translate({} {})""#, p.x, p.y);
    }
    let dim = if p.flags.contains("called") && p.zone == "river" {
        r#" opacity="0.45""#
    } else {
        ""
    };
    let _ = write!(
        out,
        r##"><title>{title}</title><use href="#t-{name}" width="{}" height="{}"{dim}/></g>"##,
        p.w, p.h
    );
}

#[cfg(test)]
mod tests {
    use super::*;
    use rinshan_engine::TileType;

    #[test]
    fn faces_follow_tile_values() {
        for v in 0..37u8 {
            let t = Tile::from_value(v).expect("a tile");
            let want = match t.kind().suit() {
                Some(_) => t.name(),
                None => ["E", "S", "W", "N", "P", "F", "C"][t.kind().index() - 27].to_string(),
            };
            assert_eq!(FACES[usize::from(v)].0, want);
            assert_eq!(symbol_name(usize::from(v)), t.name());
            let (view_box, inner) = split_face(FACES[usize::from(v)].1);
            // FluffyStuff's white dragon (P) is a blank face: the renderer draws its frame.
            assert!(
                view_box.split(' ').count() == 4 && (!inner.is_empty() || want == "P"),
                "{want}"
            );
        }
        assert_eq!(TileType::new(27).map(|k| label(Tile::plain(k))).as_deref(), Some("E"));
    }
}
