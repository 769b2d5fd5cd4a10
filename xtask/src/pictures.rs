//! The pictures in `docs/images` against what the code draws now: decoded pixels compared
//! (PNG files of the same name in `target/pictures`), so a re-encoded file with the same
//! pixels is not a change. `cargo xtask render --check` fails on a difference;
//! `cargo xtask render --docs` copies the changed pictures in.

use std::fs;
use std::path::{Path, PathBuf};

use crate::cmd::{root, target_dir};

/// How one picture of `docs/images` compares with the fresh render.
#[derive(Debug, PartialEq, Eq)]
pub(crate) enum Verdict {
    /// The same pixels.
    Same,
    /// Different pixels: how many of how many, or a different size.
    Differs { pixels: usize, of: usize },
    /// A different size (width, height) now.
    Resized { was: (u32, u32), now: (u32, u32) },
    /// Not drawn by `render` (host-tests reports and plots draw these; a GIF is not compared).
    NotRendered,
}

/// A decoded PNG: size and 8-bit RGBA pixels.
struct Decoded {
    size: (u32, u32),
    rgba: Vec<[u8; 4]>,
}

fn decode(path: &Path) -> Result<Decoded, String> {
    let file = fs::File::open(path).map_err(|e| format!("{}: {e}", path.display()))?;
    let mut decoder = png::Decoder::new(std::io::BufReader::new(file));
    decoder.set_transformations(png::Transformations::EXPAND | png::Transformations::STRIP_16);
    let mut reader = decoder
        .read_info()
        .map_err(|e| format!("{}: {e}", path.display()))?;
    let mut buf = vec![0; reader.output_buffer_size().unwrap_or(0)];
    let info = reader
        .next_frame(&mut buf)
        .map_err(|e| format!("{}: {e}", path.display()))?;
    let bytes = &buf[..info.buffer_size()];
    let rgba = match info.color_type {
        png::ColorType::Rgba => bytes
            .chunks_exact(4)
            .map(|p| [p[0], p[1], p[2], p[3]])
            .collect(),
        png::ColorType::Rgb => bytes
            .chunks_exact(3)
            .map(|p| [p[0], p[1], p[2], 255])
            .collect(),
        png::ColorType::GrayscaleAlpha => bytes
            .chunks_exact(2)
            .map(|p| [p[0], p[0], p[0], p[1]])
            .collect(),
        png::ColorType::Grayscale => bytes.iter().map(|&g| [g, g, g, 255]).collect(),
        png::ColorType::Indexed => {
            return Err(format!("{}: palette left after EXPAND", path.display()))
        }
    };
    Ok(Decoded {
        size: (info.width, info.height),
        rgba,
    })
}

/// Compares `docs` (a committed picture) with `fresh` (the same name, just rendered).
pub(crate) fn compare(docs: &Path, fresh: &Path) -> Result<Verdict, String> {
    if docs.extension().and_then(|e| e.to_str()) != Some("png") || !fresh.is_file() {
        return Ok(Verdict::NotRendered);
    }
    let (a, b) = (decode(docs)?, decode(fresh)?);
    if a.size != b.size {
        return Ok(Verdict::Resized {
            was: a.size,
            now: b.size,
        });
    }
    let pixels = a.rgba.iter().zip(&b.rgba).filter(|(p, q)| p != q).count();
    Ok(if pixels == 0 {
        Verdict::Same
    } else {
        Verdict::Differs {
            pixels,
            of: a.rgba.len(),
        }
    })
}

/// `docs/images` and the render's output directory.
fn dirs() -> (PathBuf, PathBuf) {
    (root().join("docs/images"), target_dir().join("pictures"))
}

/// Compares every picture of `docs/images` with the fresh render; with `update`, copies
/// each changed one in. Returns the names that differ (before any copy), or an error.
pub(crate) fn check_docs(update: bool) -> Result<Vec<String>, String> {
    let (docs, fresh) = dirs();
    let mut names: Vec<String> = fs::read_dir(&docs)
        .map_err(|e| format!("{}: {e}", docs.display()))?
        .filter_map(|e| e.ok())
        .map(|e| e.file_name().to_string_lossy().into_owned())
        .collect();
    names.sort();
    let mut changed = Vec::new();
    for name in names {
        let (d, f) = (docs.join(&name), fresh.join(&name));
        let verdict = compare(&d, &f)?;
        let shown = match &verdict {
            Verdict::Same => "same pixels".to_string(),
            Verdict::Differs { pixels, of } => format!(
                "{pixels} of {of} pixels differ ({:.2} %)",
                100.0 * *pixels as f64 / *of as f64
            ),
            Verdict::Resized { was, now } => {
                format!("was {}x{}, now {}x{}", was.0, was.1, now.0, now.1)
            }
            Verdict::NotRendered => "not drawn by render: not compared".to_string(),
        };
        println!("  {name:<34} {shown}");
        if matches!(verdict, Verdict::Differs { .. } | Verdict::Resized { .. }) {
            if update {
                fs::copy(&f, &d).map_err(|e| format!("{} -> {}: {e}", f.display(), d.display()))?;
            }
            changed.push(name);
        }
    }
    Ok(changed)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn write_png(path: &Path, w: u32, h: u32, rgb: &[u8]) {
        let file = fs::File::create(path).unwrap();
        let mut enc = png::Encoder::new(std::io::BufWriter::new(file), w, h);
        enc.set_color(png::ColorType::Rgb);
        enc.set_depth(png::BitDepth::Eight);
        enc.write_header().unwrap().write_image_data(rgb).unwrap();
    }

    /// Pixels are compared, not bytes; sizes and other files are told apart.
    #[test]
    fn compares_decoded_pixels() {
        let dir = std::env::temp_dir().join(format!("fixel-pictures-{}", std::process::id()));
        fs::create_dir_all(&dir).unwrap();
        let (a, b, c) = (dir.join("a.png"), dir.join("b.png"), dir.join("c.png"));
        let px = [10u8, 20, 30, 40, 50, 60];
        write_png(&a, 2, 1, &px);
        write_png(&b, 2, 1, &px);
        assert_eq!(compare(&a, &b).unwrap(), Verdict::Same);
        write_png(&b, 2, 1, &[10, 20, 30, 40, 50, 61]);
        assert_eq!(
            compare(&a, &b).unwrap(),
            Verdict::Differs { pixels: 1, of: 2 }
        );
        write_png(&b, 1, 2, &px);
        assert_eq!(
            compare(&a, &b).unwrap(),
            Verdict::Resized {
                was: (2, 1),
                now: (1, 2)
            }
        );
        assert_eq!(compare(&a, &c).unwrap(), Verdict::NotRendered);
        fs::remove_dir_all(&dir).unwrap();
    }
}
