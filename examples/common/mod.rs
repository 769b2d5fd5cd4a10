//! Shared by the host examples: writing RGB565 frames to PNG.

use embedded_graphics_core::pixelcolor::{Rgb565, RgbColor};
use std::path::{Path, PathBuf};

/// Where the examples write their pictures: `$CARGO_TARGET_DIR/pictures` or `target/pictures`.
pub fn out_dir() -> PathBuf {
    let target = std::env::var_os("CARGO_TARGET_DIR")
        .map(PathBuf::from)
        .unwrap_or_else(|| Path::new(env!("CARGO_MANIFEST_DIR")).join("target"));
    let dir = target.join("pictures");
    std::fs::create_dir_all(&dir).expect("create the pictures directory");
    dir
}

/// Writes `pixels` (`w * h`, row-major) as an 8-bit RGB PNG (channels bit-replicated).
pub fn write_png(path: &Path, w: u32, h: u32, pixels: &[Rgb565]) {
    let file = std::fs::File::create(path).expect("create PNG");
    let mut enc = png::Encoder::new(std::io::BufWriter::new(file), w, h);
    enc.set_color(png::ColorType::Rgb);
    enc.set_depth(png::BitDepth::Eight);
    let mut writer = enc.write_header().expect("PNG header");
    let mut data = Vec::with_capacity(pixels.len() * 3);
    for p in pixels {
        let (r, g, b) = (p.r(), p.g(), p.b());
        data.extend_from_slice(&[
            (r << 3) | (r >> 2),
            (g << 2) | (g >> 4),
            (b << 3) | (b >> 2),
        ]);
    }
    writer.write_image_data(&data).expect("PNG data");
}
