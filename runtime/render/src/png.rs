//! PNG pictures through resvg, with bundled fonts so a board rasterises the same on every machine
//! (the tile faces are paths; only the labels, the table's text and the players' names are text).
//! No system font is read: a name that drew on one machine and not on another would be worse than
//! a name drawn the same everywhere.
//!
//! Two fonts: DejaVu Sans Bold cut to ASCII (and `·`, `×`) for everything rinshan writes, and
//! Droid Sans Fallback cut to Japanese (kana, CJK punctuation, full-width forms and the 6,355 kanji
//! of JIS X 0208) for players' names, which resvg reaches by its font fallback. A character neither
//! font has (Hangul, emoji, a kanji outside JIS X 0208) is drawn as `?`: resvg would leave a blank,
//! and a name of blanks reads as no name at all.

use std::borrow::Cow;
use std::collections::BTreeSet;
use std::io::Read as _;
use std::sync::{Arc, OnceLock};

use resvg::usvg::fontdb;
use skrifa::MetadataProvider as _;

/// DejaVu Sans Bold cut to printable ASCII, `·` and `×` (`assets/fonts/subset.sh`).
const FONT: &[u8] = include_bytes!("../assets/fonts/DejaVuSans-Bold-latin.ttf");
/// Droid Sans Fallback cut to Japanese, gzipped (`assets/fonts/subset.sh`): 1 MB as it is.
const NAMES_FONT_GZ: &[u8] = include_bytes!("../assets/fonts/DroidSansFallback-names.ttf.gz");

/// What a picture can draw: the fonts, and every character they have.
struct Fonts {
    db: Arc<fontdb::Database>,
    chars: BTreeSet<char>,
}

fn fonts() -> &'static Fonts {
    static FONTS: OnceLock<Fonts> = OnceLock::new();
    FONTS.get_or_init(|| {
        let mut names = Vec::new();
        // The bytes are the crate's own: a failure here is a broken build, and the pictures then
        // fall back to the ASCII font (every name drawn as `?`), which a test would show.
        if flate2::read::GzDecoder::new(NAMES_FONT_GZ)
            .read_to_end(&mut names)
            .is_err()
        {
            names.clear();
        }
        let mut chars = BTreeSet::new();
        for data in [FONT, names.as_slice()] {
            if let Ok(font) = skrifa::FontRef::new(data) {
                chars.extend(font.charmap().mappings().filter_map(|(c, _)| char::from_u32(c)));
            }
        }
        let mut db = fontdb::Database::new();
        db.load_font_data(FONT.to_vec());
        if !names.is_empty() {
            db.load_font_data(names);
        }
        Fonts {
            db: Arc::new(db),
            chars,
        }
    })
}

/// Whether the bundled fonts draw `c` (white space needs no glyph).
pub fn drawable(c: char) -> bool {
    c.is_whitespace() || fonts().chars.contains(&c)
}

/// `svg` with each character of its text that no bundled font has replaced by `?`. Only
/// character data is read (between a `>` and the next `<`), so markup and attributes stay as
/// they are; character references (`&#...;`) are left to resvg.
fn with_drawable_text(svg: &str) -> Cow<'_, str> {
    let mut in_data = false;
    let mut missing = false;
    for c in svg.chars() {
        match c {
            '<' => in_data = false,
            '>' => in_data = true,
            c if in_data && !drawable(c) => {
                missing = true;
                break;
            }
            _ => {}
        }
    }
    if !missing {
        return Cow::Borrowed(svg);
    }
    let mut in_data = false;
    Cow::Owned(
        svg.chars()
            .map(|c| match c {
                '<' => {
                    in_data = false;
                    c
                }
                '>' => {
                    in_data = true;
                    c
                }
                c if in_data && !drawable(c) => '?',
                c => c,
            })
            .collect(),
    )
}

/// `svg` rasterised at `scale` (1.0 = its own size) as PNG bytes.
pub fn png(svg: &str, scale: f32) -> Result<Vec<u8>, String> {
    use resvg::{tiny_skia, usvg};
    let options = usvg::Options {
        font_family: "DejaVu Sans".to_string(),
        fontdb: fonts().db.clone(),
        ..usvg::Options::default()
    };
    let svg = with_drawable_text(svg);
    let tree = usvg::Tree::from_str(&svg, &options).map_err(|e| format!("not a picture: {e}"))?;
    let size = tree
        .size()
        .to_int_size()
        .scale_by(scale)
        .ok_or("the picture has no size")?;
    let mut pixmap = tiny_skia::Pixmap::new(size.width(), size.height()).ok_or("the picture has no size")?;
    resvg::render(
        &tree,
        tiny_skia::Transform::from_scale(scale, scale),
        &mut pixmap.as_mut(),
    );
    pixmap.encode_png().map_err(|e| format!("PNG encoding failed: {e}"))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_fonts_draw_ascii_and_japanese_names() {
        for c in "Az09 ·×あアー漢字麻雀鳳凰".chars() {
            assert!(drawable(c), "{c}");
        }
        // Hangul and emoji are in neither font.
        for c in "김🀄".chars() {
            assert!(!drawable(c), "{c}");
        }
    }

    #[test]
    fn only_text_the_fonts_lack_is_replaced() {
        let svg = r#"<svg data-x="김"><text>麻雀 김철수</text></svg>"#;
        assert_eq!(
            with_drawable_text(svg),
            r#"<svg data-x="김"><text>麻雀 ???</text></svg>"#
        );
        assert!(matches!(with_drawable_text("<text>ok</text>"), Cow::Borrowed(_)));
    }
}
