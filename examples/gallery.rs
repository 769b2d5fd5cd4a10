//! The README's gallery: six pictures the other examples drew, as one 960 x 480 image
//! (three tiles of 320 x 240 a row). `cargo xtask render` runs it last; on its own, run the
//! examples it reads first.
//!
//! Tiles, left to right, top to bottom: the environment-mapped sphere and torus
//! (`envmap`), marble, wood and granite from Perlin noise (`noise`), bump-mapped bricks
//! (`surface_detail`, one sphere of its panel), a shadow-mapped teapot (`shadow`'s left panel),
//! projective quads (`quads`), and alpha blending and testing (`transparency`).

mod common;

use std::fs::File;
use std::io::BufReader;
use std::path::Path;

const TILE_W: usize = 320;
const TILE_H: usize = 240;

/// An 8-bit RGB picture.
struct Picture {
    w: usize,
    h: usize,
    rgb: Vec<[u8; 3]>,
}

fn read(path: &Path) -> Result<Picture, String> {
    let file =
        File::open(path).map_err(|e| format!("{}: {e} (run its example first)", path.display()))?;
    let mut decoder = png::Decoder::new(BufReader::new(file));
    decoder.set_transformations(png::Transformations::EXPAND | png::Transformations::STRIP_16);
    let mut reader = decoder
        .read_info()
        .map_err(|e| format!("{}: {e}", path.display()))?;
    let mut buf = vec![0; reader.output_buffer_size().unwrap_or(0)];
    let info = reader
        .next_frame(&mut buf)
        .map_err(|e| format!("{}: {e}", path.display()))?;
    let step = match info.color_type {
        png::ColorType::Rgb => 3,
        png::ColorType::Rgba => 4,
        other => return Err(format!("{}: colour type {other:?}", path.display())),
    };
    let rgb = buf[..info.buffer_size()]
        .chunks_exact(step)
        .map(|p| [p[0], p[1], p[2]])
        .collect();
    Ok(Picture {
        w: info.width as usize,
        h: info.height as usize,
        rgb,
    })
}

/// The `k`-th object (left to right) of the top row of a panel of objects on a plain
/// background, alone in a 320 x 240 tile centred on it (the background fills the rest).
fn one_sphere(p: &Picture, k: usize) -> Result<Picture, String> {
    let bg = p.rgb[0];
    let differs = |c: [u8; 3]| (0..3).any(|i| c[i].abs_diff(bg[i]) > 8);
    let rows = TILE_H.min(p.h);
    let used: Vec<bool> = (0..p.w)
        .map(|x| (0..rows).any(|y| differs(p.rgb[y * p.w + x])))
        .collect();
    // Runs of columns holding an object.
    let mut runs = Vec::new();
    let mut start = None;
    for (x, &u) in used.iter().chain(&[false]).enumerate() {
        match (u, start) {
            (true, None) => start = Some(x),
            (false, Some(s)) => {
                runs.push((s, x));
                start = None;
            }
            _ => {}
        }
    }
    let &(a, b) = runs
        .get(k)
        .ok_or_else(|| format!("the panel has {} objects, not {}", runs.len(), k + 1))?;
    let x0 = ((a + b) / 2).saturating_sub(TILE_W / 2).min(p.w - TILE_W);
    let mut t = window(p, x0, 0)?;
    for y in 0..TILE_H {
        for x in 0..TILE_W {
            if !(a..b).contains(&(x0 + x)) {
                t.rgb[y * TILE_W + x] = bg;
            }
        }
    }
    Ok(t)
}

/// The 320 x 240 window of `p` whose top-left corner is `(x0, y0)`.
fn window(p: &Picture, x0: usize, y0: usize) -> Result<Picture, String> {
    if x0 + TILE_W > p.w || y0 + TILE_H > p.h {
        return Err(format!(
            "a {}x{} picture has no tile at ({x0}, {y0})",
            p.w, p.h
        ));
    }
    let rgb = (0..TILE_H)
        .flat_map(|y| p.rgb[(y0 + y) * p.w + x0..(y0 + y) * p.w + x0 + TILE_W].to_vec())
        .collect();
    Ok(Picture {
        w: TILE_W,
        h: TILE_H,
        rgb,
    })
}

fn main() -> Result<(), String> {
    let dir = common::out_dir();
    let pic = |name: &str| read(&dir.join(name));
    let tiles = [
        window(&pic("envmap.png")?, 0, 0)?,
        window(&pic("noise.png")?, 0, 0)?,
        one_sphere(&pic("bump.png")?, 2)?,
        window(&pic("shadow-teapot.png")?, 0, 0)?,
        window(&pic("quads.png")?, 0, 0)?,
        window(&pic("transparency.png")?, 0, 0)?,
    ];
    let (cols, rows) = (3, 2);
    let (w, h) = (cols * TILE_W, rows * TILE_H);
    let mut out = vec![embedded_graphics_core::pixelcolor::Rgb565::new(0, 0, 0); w * h];
    for (k, t) in tiles.iter().enumerate() {
        let (tx, ty) = ((k % cols) * TILE_W, (k / cols) * TILE_H);
        for y in 0..TILE_H {
            for x in 0..TILE_W {
                let [r, g, b] = t.rgb[y * TILE_W + x];
                out[(ty + y) * w + tx + x] =
                    embedded_graphics_core::pixelcolor::Rgb565::new(r >> 3, g >> 2, b >> 3);
            }
        }
    }
    let path = dir.join("gallery.png");
    common::write_png(&path, w as u32, h as u32, &out);
    println!("wrote {}", path.display());
    Ok(())
}
