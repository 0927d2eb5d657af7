//! SVG to PDF (svg2pdf: text stays text, curves stay paths) and to PNG (resvg).
use anyhow::{Context, Result};
use resvg::{tiny_skia, usvg};

/// Parse an SVG document with the system fonts.
pub(crate) fn tree(svg: &str) -> Result<usvg::Tree> {
    let options = usvg::Options {
        fontdb: crate::i18n::fonts::system(),
        ..usvg::Options::default()
    };
    usvg::Tree::from_str(svg, &options).context("the plot's SVG could not be parsed")
}

/// Refuse a figure path that does not end in `.svg`, `.pdf` or `.png`.
pub(crate) fn check_extension(path: &std::path::Path) -> Result<()> {
    match crate::output::extension(path).as_deref() {
        Some("svg" | "pdf" | "png") => Ok(()),
        _ => anyhow::bail!(
            "`{}`: the plot file must end in .svg, .pdf or .png",
            path.display()
        ),
    }
}

/// `svg` in the format `path` ends in: SVG as it is (text stays text), PDF (vector) or
/// PNG at 300 dpi.
pub(crate) fn by_extension(svg: String, path: &std::path::Path) -> Result<Vec<u8>> {
    check_extension(path)?;
    match crate::output::extension(path).as_deref() {
        Some("pdf") => pdf(&svg),
        // 3.125 × 96 dpi = 300 dpi.
        Some("png") => png(&svg, 3.125),
        _ => Ok(svg.into_bytes()),
    }
}

/// The SVG as a one-page PDF of the same size.
pub(crate) fn pdf(svg: &str) -> Result<Vec<u8>> {
    // svg2pdf's usvg is the same version as resvg's, so one tree serves both.
    let tree = tree(svg)?;
    svg2pdf::to_pdf(
        &tree,
        svg2pdf::ConversionOptions::default(),
        svg2pdf::PageOptions::default(),
    )
    .map_err(|e| anyhow::anyhow!("the plot could not be converted to PDF: {e}"))
}

/// The SVG as a PNG at `scale` × its CSS-pixel size (scale 3.125 ≈ 300 dpi), on white.
pub(crate) fn png(svg: &str, scale: f32) -> Result<Vec<u8>> {
    let tree = tree(svg)?;
    let size = tree.size();
    let (w, h) = (
        (size.width() * scale).ceil() as u32,
        (size.height() * scale).ceil() as u32,
    );
    let mut pixmap = tiny_skia::Pixmap::new(w, h).context("the plot image size is invalid")?;
    pixmap.fill(tiny_skia::Color::WHITE);
    resvg::render(
        &tree,
        tiny_skia::Transform::from_scale(scale, scale),
        &mut pixmap.as_mut(),
    );
    pixmap
        .encode_png()
        .context("the plot could not be encoded as PNG")
}

/// The SVG rasterised into a white `width × height` RGBA image, scaled uniformly to fit
/// and centred (for video composites). Returns the pixels, the scale and the offset.
pub(crate) fn rgba_fit(svg: &str, width: u32, height: u32) -> Result<(Vec<u8>, f32, (f32, f32))> {
    let tree = tree(svg)?;
    let size = tree.size();
    let scale = (width as f32 / size.width()).min(height as f32 / size.height());
    let offset = (
        0.5 * (width as f32 - scale * size.width()),
        0.5 * (height as f32 - scale * size.height()),
    );
    let mut pixmap =
        tiny_skia::Pixmap::new(width, height).context("the plot image size is invalid")?;
    pixmap.fill(tiny_skia::Color::WHITE);
    let transform = tiny_skia::Transform::from_row(scale, 0.0, 0.0, scale, offset.0, offset.1);
    resvg::render(&tree, transform, &mut pixmap.as_mut());
    Ok((pixmap.take(), scale, offset))
}
