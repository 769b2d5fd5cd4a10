//! Projective quads for user interfaces: a clock dial and a photo drawn onto
//! arbitrary four-corner shapes with `fixel::scene::draw_quad` (exact projective mapping, no
//! 3D set-up), beside the same photo drawn as two affine triangles (the classic seam).
//!
//! `cargo run --release --example quads` (picture in `target/pictures/quads.png`).

#[path = "common/mod.rs"]
mod common;

use embedded_graphics_core::pixelcolor::Rgb565;
use fixel::geometry::{Cull, Viewport};
use fixel::math::Fx;
use fixel::pipeline::{DepthTest, Draw, DrawMode, Projection, Shading};
use fixel::scene::draw_quad;
use fixel::surface::Frame;
use fixel::texture::{Filter, Texture, Wrap};
use fixel::Error;

const W: u32 = 320;
const H: u32 = 240;

fn rgb(r: f64, g: f64, b: f64) -> Rgb565 {
    let q = |v: f64, m: f64| (v.clamp(0.0, 1.0) * m).round() as u8;
    Rgb565::new(q(r, 31.0), q(g, 63.0), q(b, 31.0))
}

/// A clock face at ten past ten: white dial, twelve ticks, two hands, a blue rim.
fn dial(n: u32) -> Vec<Rgb565> {
    let hand = |x: f64, y: f64, angle: f64, len: f64, width: f64| {
        // Angle clockwise from 12 o'clock; the hand runs from the centre to `len`.
        let (dx, dy) = (angle.sin(), -angle.cos());
        let along = x * dx + y * dy;
        let across = (x * dy - y * dx).abs();
        along > -0.08 && along < len && across < width
    };
    (0..n * n)
        .map(|k| {
            let x = (f64::from(k % n) + 0.5) / f64::from(n) * 2.0 - 1.0;
            let y = (f64::from(k / n) + 0.5) / f64::from(n) * 2.0 - 1.0;
            let r = x.hypot(y);
            if r > 1.0 {
                return rgb(0.12, 0.14, 0.2);
            }
            if r > 0.92 {
                return rgb(0.1, 0.25, 0.6);
            }
            let a = x.atan2(-y).rem_euclid(std::f64::consts::TAU);
            let tick = (a / (std::f64::consts::TAU / 12.0)).round() * std::f64::consts::TAU / 12.0;
            let major = (0.75..0.88).contains(&r) && ((a - tick).abs() * r) < 0.035;
            let minute = hand(x, y, std::f64::consts::TAU * 10.0 / 60.0, 0.8, 0.03);
            let hour = hand(
                x,
                y,
                std::f64::consts::TAU * (10.0 + 10.0 / 60.0) / 12.0,
                0.5,
                0.05,
            );
            if r < 0.06 {
                rgb(0.8, 0.1, 0.1)
            } else if major || minute || hour {
                rgb(0.08, 0.08, 0.1)
            } else {
                rgb(0.97, 0.96, 0.92)
            }
        })
        .collect()
}

/// A photo-like landscape: sky, sun, mountains, a lake and a shore.
fn photo(n: u32) -> Vec<Rgb565> {
    (0..n * n)
        .map(|k| {
            let x = (f64::from(k % n) + 0.5) / f64::from(n);
            let y = (f64::from(k / n) + 0.5) / f64::from(n);
            let ridge = 0.45 - 0.12 * (x * 9.0).sin().abs() - 0.06 * (x * 23.0 + 1.0).sin();
            let sun = (x - 0.72).hypot(y - 0.22);
            if y < ridge {
                if sun < 0.08 {
                    rgb(1.0, 0.9, 0.5)
                } else {
                    let t = y / ridge;
                    rgb(0.35 + 0.55 * t, 0.55 + 0.3 * t, 0.9 - 0.2 * t)
                }
            } else if y < 0.62 {
                let shade = 0.5 + 0.5 * ((x * 40.0).sin() * 0.5 + 0.5) * (0.62 - y) * 5.0;
                rgb(0.25 * shade, 0.35 * shade, 0.3 * shade)
            } else if y < 0.85 {
                let wave = 0.05 * ((y * 120.0).sin() + 1.0);
                rgb(0.15 + wave, 0.35 + wave, 0.55 + wave)
            } else {
                rgb(0.55, 0.45, 0.25)
            }
        })
        .collect()
}

fn main() -> Result<(), Error> {
    let (dial_px, photo_px) = (dial(128), photo(128));
    let dial_tex = Texture::new(&dial_px, 128, 128)?;
    let photo_tex = Texture::new(&photo_px, 128, 128)?;
    let mut color = vec![Rgb565::new(0, 0, 0); (W * H) as usize];
    let mut frame = Frame::new(&mut color, W, H)?;
    // A dark blue-grey background with a lighter band, like a dashboard.
    frame.clear(Rgb565::new(4, 9, 7));
    let vp = Viewport::new(0, 0, W, H)?;
    let mode = |projection| DrawMode {
        projection,
        filter: Filter::Bilinear,
        wrap: [Wrap::ClampToEdge, Wrap::ClampToEdge],
        shading: Shading::Replace,
        depth: DepthTest::Off,
        cull: Cull::None,
        ..DrawMode::default()
    };
    let exact = |t| Draw::dynamic(mode(Projection::Exact), Some(t), vp);
    let p = |x: f64, y: f64| [Fx::from_num(x), Fx::from_num(y)];
    // The photo on a card seen in perspective (its right edge further away).
    draw_quad(
        &exact(photo_tex)?,
        [
            p(12.0, 30.0),
            p(150.0, 52.0),
            p(150.0, 150.0),
            p(12.0, 180.0),
        ],
        &mut frame,
    )?;
    // The dial tilted back.
    draw_quad(
        &exact(dial_tex)?,
        [
            p(190.0, 40.0),
            p(292.0, 40.0),
            p(312.0, 150.0),
            p(170.0, 150.0),
        ],
        &mut frame,
    )?;
    // Small copies: the dial rotated flat (a sprite); the photo on a long card drawn as two
    // affine triangles (bottom left: the kink along the diagonal is the classic seam).
    draw_quad(
        &exact(dial_tex)?,
        [
            p(200.0, 168.0),
            p(258.0, 178.0),
            p(248.0, 236.0),
            p(190.0, 226.0),
        ],
        &mut frame,
    )?;
    let affine = Draw::dynamic(mode(Projection::Affine), Some(photo_tex), vp)?;
    draw_quad(
        &affine,
        [
            p(14.0, 192.0),
            p(170.0, 206.0),
            p(170.0, 224.0),
            p(14.0, 238.0),
        ],
        &mut frame,
    )?;
    draw_quad(
        &exact(photo_tex)?,
        [
            p(270.0, 178.0),
            p(312.0, 170.0),
            p(312.0, 236.0),
            p(270.0, 228.0),
        ],
        &mut frame,
    )?;
    let path = common::out_dir().join("quads.png");
    common::write_png(&path, W, H, &color);
    println!("wrote {}", path.display());
    Ok(())
}
