//! A brick wall, procedurally: the colour texture and the matching height map of the bump
//! mapping scenes (`examples/surface_detail.rs`, the `bump` firmware scene).
//!
//! On an `n x n` tile (`n` a power of two, 16..=1024): 8 courses of 4 bricks (every other
//! course shifted by half a brick), mortar joints `n / 64` texels wide (at least 1).
//! Heights: mortar 40; a brick rises over a bevel of `n / 32` texels to 200, with a hashed
//! grain of ±4 (plus an occasional chip). Colours: brick red varied per brick and by the
//! same grain, darker on the bevel; mortar a pale grey. Both tile seamlessly.

use embedded_graphics_core::pixelcolor::raw::RawU16;
use embedded_graphics_core::pixelcolor::Rgb565;

use fixel::color::rgb888_to_565;
use fixel::Error;

/// A small integer hash (deterministic grain).
fn hash(x: u32, y: u32, seed: u32) -> u32 {
    let mut h =
        x.wrapping_mul(0x8DA6_B343) ^ y.wrapping_mul(0xD816_3841) ^ seed.wrapping_mul(0xCB1A_B31F);
    h ^= h >> 13;
    h = h.wrapping_mul(0x5bd1_e995);
    h ^ (h >> 15)
}

/// Per texel: `(distance to the nearest joint in texels, brick id)`, or `None` in mortar.
fn layout(n: u32, x: u32, y: u32) -> (u32, u32, u32) {
    let course = n / 8;
    let brick = n / 4;
    let row = y / course;
    let shift = if row % 2 == 1 { brick / 2 } else { 0 };
    let xs = (x + shift) % n;
    let col = xs / brick;
    let (bx, by) = (xs % brick, y % course);
    let half = (n / 64).max(1);
    // Distance from the joint (joints sit on the tile lines of each brick).
    let dx = bx.min(brick - 1 - bx);
    let dy = by.min(course - 1 - by);
    let d = dx.min(dy);
    (d, half, row * 4 + col)
}

fn check(n: u32, len: usize) -> Result<(), Error> {
    if !n.is_power_of_two() {
        return Err(Error::NotPowerOfTwo(n));
    }
    if !(16..=1024).contains(&n) {
        return Err(Error::BadSize(n));
    }
    if len != (n * n) as usize {
        return Err(Error::WrongLength {
            expected: (n * n) as usize,
            actual: len,
        });
    }
    Ok(())
}

/// Heights `0..=255` of the `n x n` brick tile into `out` (`n * n`, row 0 first).
///
/// # Errors
/// [`Error::NotPowerOfTwo`], [`Error::BadSize`] outside 16..=1024,
/// [`Error::WrongLength`].
pub fn brick_heights(n: u32, out: &mut [u8]) -> Result<(), Error> {
    check(n, out.len())?;
    let bevel = (n / 32).max(1);
    for (k, h) in out.iter_mut().enumerate() {
        let (x, y) = (k as u32 % n, k as u32 / n);
        let (d, half, id) = layout(n, x, y);
        *h = if d < half {
            40 + (hash(x, y, 7) % 9) as u8
        } else {
            let rise = ((d - half + 1) * 160 / (bevel + 1)).min(160);
            let grain = (hash(x / 2, y / 2, id) % 9) as i32 - 4;
            let chip = if hash(x / 3, y / 3, id + 99).is_multiple_of(97) {
                -40
            } else {
                0
            };
            (40 + rise as i32 + grain + chip).clamp(0, 255) as u8
        };
    }
    Ok(())
}

/// Colours of the `n x n` brick tile into `out` (`n * n`, row 0 first).
///
/// # Errors
/// As [`brick_heights`].
pub fn brick_colours(n: u32, out: &mut [Rgb565]) -> Result<(), Error> {
    check(n, out.len())?;
    let bevel = (n / 32).max(1);
    for (k, c) in out.iter_mut().enumerate() {
        let (x, y) = (k as u32 % n, k as u32 / n);
        let (d, half, id) = layout(n, x, y);
        let (r, g, b) = if d < half {
            let v = 170 + (hash(x, y, 3) % 20) as i32;
            (v, v - 6, v - 16)
        } else {
            let tone = (hash(id, 0, 11) % 50) as i32 - 25;
            let grain = (hash(x / 2, y / 2, id) % 25) as i32 - 12;
            let edge = if d - half < bevel { -18 } else { 0 };
            let base = 150 + tone + grain + edge;
            (base, base * 45 / 100, base * 32 / 100)
        };
        let q = |v: i32| v.clamp(0, 255) as u8;
        *c = Rgb565::from(RawU16::new(rgb888_to_565(q(r), q(g), q(b))));
    }
    Ok(())
}
