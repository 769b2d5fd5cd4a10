//! The font the report plots are drawn with (plotters' `ab_glyph` backend has none built in).

/// Where the DejaVu font is on Debian and Ubuntu (`apt-get install fonts-dejavu-core`).
pub const FONT_PATH: &str = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";

/// Registers [`FONT_PATH`] as plotters' "sans-serif", or says what is missing.
pub fn register() -> Result<(), String> {
    let font = std::fs::read(FONT_PATH).map_err(|e| {
        format!("{FONT_PATH}: {e} (apt-get install fonts-dejavu-core); plots need a font")
    })?;
    plotters::style::register_font(
        "sans-serif",
        plotters::style::FontStyle::Normal,
        Box::leak(font.into_boxed_slice()),
    )
    .map_err(|_| format!("{FONT_PATH}: not a usable font"))
}
