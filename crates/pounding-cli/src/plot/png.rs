//! PNG rasterisation of the SVG figures with resvg, at twice the SVG's size, in the bundled DejaVu Sans
//! (`assets/`), so the result is the same on every machine, fonts installed or not.

use resvg::{tiny_skia, usvg};

/// The embedded font (48 kB subset of DejaVu Sans; licence in `assets/DejaVuSans-LICENSE.txt`).
const FONT: &[u8] = include_bytes!("../../assets/DejaVuSans-subset.ttf");

/// Pixels per SVG px.
const SCALE: f32 = 2.0;

/// The SVG document `svg` as a PNG file's bytes.
pub fn render(svg: &str) -> Result<Vec<u8>, String> {
    let mut opt = usvg::Options {
        font_family: "DejaVu Sans".into(),
        ..usvg::Options::default()
    };
    opt.fontdb_mut().load_font_data(FONT.to_vec());
    let tree = usvg::Tree::from_str(svg, &opt).map_err(|e| format!("SVG not readable: {e}"))?;
    let size = tree
        .size()
        .to_int_size()
        .scale_by(SCALE)
        .ok_or("figure too large for a PNG")?;
    let mut pixmap =
        tiny_skia::Pixmap::new(size.width(), size.height()).ok_or("figure too large for a PNG")?;
    resvg::render(
        &tree,
        tiny_skia::Transform::from_scale(SCALE, SCALE),
        &mut pixmap.as_mut(),
    );
    pixmap
        .encode_png()
        .map_err(|e| format!("PNG encoding: {e}"))
}
