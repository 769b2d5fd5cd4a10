//! PNG reading and writing for RGB565 frames and RGB8 images. RGB565 is
//! stored as 8-bit RGB with bit replication (`r8 = r5 << 3 | r5 >> 2`,
//! `g8 = g6 << 2 | g6 >> 4`) and read back by keeping the top bits, so a
//! write/read round trip is exact. Parent directories are created on write.

use std::fs::File;
use std::io::{self, BufReader, BufWriter};
use std::path::Path;

fn to_io(e: impl std::error::Error + Send + Sync + 'static) -> io::Error {
    io::Error::other(e)
}

/// Expands an RGB565 value to 8-bit RGB by bit replication.
pub fn rgb565_to_rgb8(p: u16) -> [u8; 3] {
    let (r, g, b) = ((p >> 11) & 31, (p >> 5) & 63, p & 31);
    [
        ((r << 3) | (r >> 2)) as u8,
        ((g << 2) | (g >> 4)) as u8,
        ((b << 3) | (b >> 2)) as u8,
    ]
}

/// Packs 8-bit RGB into RGB565 by keeping the top bits (inverse of
/// [`rgb565_to_rgb8`]).
pub fn rgb8_to_rgb565(c: [u8; 3]) -> u16 {
    (u16::from(c[0] >> 3) << 11) | (u16::from(c[1] >> 2) << 5) | u16::from(c[2] >> 3)
}

/// Writes `w x h` RGB8 pixels (`3 * w * h` bytes, row 0 at the top).
pub fn write_png_rgb8(path: impl AsRef<Path>, w: u32, h: u32, rgb: &[u8]) -> io::Result<()> {
    let path = path.as_ref();
    if rgb.len() != 3 * (w as usize) * (h as usize) {
        return Err(io::Error::new(
            io::ErrorKind::InvalidInput,
            format!("{} bytes for a {w}x{h} RGB8 image", rgb.len()),
        ));
    }
    if let Some(dir) = path.parent() {
        std::fs::create_dir_all(dir)?;
    }
    let mut enc = png::Encoder::new(BufWriter::new(File::create(path)?), w, h);
    enc.set_color(png::ColorType::Rgb);
    enc.set_depth(png::BitDepth::Eight);
    let mut writer = enc.write_header().map_err(to_io)?;
    writer.write_image_data(rgb).map_err(to_io)?;
    writer.finish().map_err(to_io)
}

/// Writes `w x h` RGB565 pixels (row 0 at the top) as an 8-bit RGB PNG.
pub fn write_png_rgb565(path: impl AsRef<Path>, w: u32, h: u32, px: &[u16]) -> io::Result<()> {
    let rgb: Vec<u8> = px.iter().flat_map(|&p| rgb565_to_rgb8(p)).collect();
    write_png_rgb8(path, w, h, &rgb)
}

/// Reads an 8-bit RGB (or RGBA, alpha ignored; palette and grey are
/// expanded) PNG as `(width, height, RGB565 pixels)`.
pub fn read_png_rgb565(path: impl AsRef<Path>) -> io::Result<(u32, u32, Vec<u16>)> {
    let file = BufReader::new(File::open(path)?);
    let mut dec = png::Decoder::new(file);
    dec.set_transformations(png::Transformations::EXPAND | png::Transformations::STRIP_16);
    let mut reader = dec.read_info().map_err(to_io)?;
    let size = reader
        .output_buffer_size()
        .ok_or_else(|| io::Error::new(io::ErrorKind::InvalidData, "PNG too large"))?;
    let mut buf = vec![0; size];
    let info = reader.next_frame(&mut buf).map_err(to_io)?;
    let bytes = &buf[..info.buffer_size()];
    let stride = match info.color_type {
        png::ColorType::Rgb => 3,
        png::ColorType::Rgba => 4,
        png::ColorType::Grayscale => 1,
        png::ColorType::GrayscaleAlpha => 2,
        png::ColorType::Indexed => {
            return Err(io::Error::new(
                io::ErrorKind::InvalidData,
                "unexpanded palette",
            ))
        }
    };
    let (w, h) = (info.width, info.height);
    let line = info.line_size;
    let mut px = Vec::with_capacity((w * h) as usize);
    for row in bytes.chunks(line).take(h as usize) {
        for p in row[..stride * w as usize].chunks(stride) {
            let c = if stride >= 3 {
                [p[0], p[1], p[2]]
            } else {
                [p[0]; 3]
            };
            px.push(rgb8_to_rgb565(c));
        }
    }
    Ok((w, h, px))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bit_replication_round_trips_every_value() {
        for p in 0..=u16::MAX {
            assert_eq!(rgb8_to_rgb565(rgb565_to_rgb8(p)), p);
        }
        assert_eq!(rgb565_to_rgb8(0xffff), [255; 3]);
    }

    #[test]
    fn png_round_trip_is_exact() {
        let dir = std::env::temp_dir().join(format!("fixel-png-{}", std::process::id()));
        let path = dir.join("rt.png");
        let px: Vec<u16> = (0..37 * 23)
            .map(|i: u32| i.wrapping_mul(2654435761) as u16)
            .collect();
        write_png_rgb565(&path, 37, 23, &px).unwrap();
        let (w, h, back) = read_png_rgb565(&path).unwrap();
        assert_eq!((w, h), (37, 23));
        assert_eq!(back, px);
        std::fs::remove_dir_all(dir).unwrap();
    }
}
