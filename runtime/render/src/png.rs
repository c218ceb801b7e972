//! PNG pictures through resvg, with a bundled Latin font so a board rasterises the same on every
//! machine (the tile faces are paths; only the labels and the table's text are text).

/// DejaVu Sans Bold cut to printable ASCII (`assets/fonts/subset.sh`).
const FONT: &[u8] = include_bytes!("../assets/fonts/DejaVuSans-Bold-latin.ttf");

/// `svg` rasterised at `scale` (1.0 = its own size) as PNG bytes.
pub fn png(svg: &str, scale: f32) -> Result<Vec<u8>, String> {
    use resvg::{tiny_skia, usvg};
    let mut options = usvg::Options {
        font_family: "DejaVu Sans".to_string(),
        ..usvg::Options::default()
    };
    options.fontdb_mut().load_font_data(FONT.to_vec());
    let tree = usvg::Tree::from_str(svg, &options).map_err(|e| format!("not a picture: {e}"))?;
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
