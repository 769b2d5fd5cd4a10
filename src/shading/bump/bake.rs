//! Precomputed maps from a [`HeightMap`]: derivative maps (for
//! [`DerivativeMap`](super::DerivativeMap)) and tangent-space normal maps (for
//! [`NormalMap`](super::NormalMap)), level by level, into caller storage laid out as a
//! texture mip chain ([`MipTexture`](crate::texture::MipTexture)). Run them once at start-up
//! or at bake time; they are not per-frame work.
//!
//! Both use central differences at each level `k`, in height steps per level-0 texel:
//! `∂h/∂i = (h(i+1, j) − h(i−1, j)) / 2^(k+1)` (repeating), the same as
//! [`HeightDifferences`](super::HeightDifferences) computes per pixel.

use embedded_graphics_core::pixelcolor::raw::RawU16;
use embedded_graphics_core::pixelcolor::Rgb565;

use crate::math::{unit_q14, Fx};
use crate::texture::{chain_len, HeightMap};
use crate::Error;

/// Central differences of level `k` at `(i, j)`, in steps per level-0 texel, times
/// `2^(k+1)` (integers).
fn differences(h: &HeightMap<'_>, k: u32, i: i32, j: i32) -> (i32, i32) {
    let at = |di: i32, dj: i32| i32::from(h.height(k, i + di, j + dj));
    (at(1, 0) - at(-1, 0), at(0, 1) - at(0, -1))
}

/// Visits every texel of every level: `(offset in the chain, level, i, j)`.
fn each_texel(h: &HeightMap<'_>, mut f: impl FnMut(usize, u32, i32, i32)) {
    let mut off = 0usize;
    for k in 0..h.levels() {
        let (lw, lh) = h.level_log2(k);
        for j in 0..1i32 << lh {
            for i in 0..1i32 << lw {
                f(off + ((j << lw) + i) as usize, k, i, j);
            }
        }
        off += 1usize << (lw + lh);
    }
}

fn check(h: &HeightMap<'_>, len: usize) -> Result<(), Error> {
    let expected = chain_len(h.width(), h.height_texels(), h.levels());
    if len != expected {
        return Err(Error::WrongLength {
            expected,
            actual: len,
        });
    }
    Ok(())
}

/// Writes the derivative map of `height` into `out` (as long as the height map's chain) and
/// returns its scale: texel `(du, dv)` as `i8` in the high and low byte, with
/// `∂h/∂i = du · scale` steps per level-0 texel. The scale makes the steepest derivative
/// of the map 127 (finest resolution for the map at hand).
///
/// # Errors
/// [`Error::WrongLength`] when `out` is not the chain's length.
pub fn derivative_map(height: &HeightMap<'_>, out: &mut [Rgb565]) -> Result<Fx, Error> {
    check(height, out.len())?;
    // Largest |difference| / 2^(k+1), compared as fractions over 2^13 (levels <= 13).
    let mut max_q = 0i64; // steps per texel, Q16
    each_texel(height, |_, k, i, j| {
        let (dx, dy) = differences(height, k, i, j);
        let m = i64::from(dx.unsigned_abs().max(dy.unsigned_abs()));
        max_q = max_q.max((m << 16) >> (k + 1));
    });
    // scale (Q16) = max / 127, at least one LSB.
    let scale = ((max_q + 63) / 127).max(1);
    each_texel(height, |idx, k, i, j| {
        let (dx, dy) = differences(height, k, i, j);
        // (d / 2^(k+1)) / scale, rounded, in i8.
        let q = |d: i32| {
            let num = i64::from(d) << 16;
            let den = scale << (k + 1);
            let r = (num + den.signum() * (den / 2) * num.signum()) / den;
            r.clamp(-127, 127) as i8 as u8
        };
        if let Some(t) = out.get_mut(idx) {
            *t = Rgb565::from(RawU16::new(u16::from(q(dx)) << 8 | u16::from(q(dy))));
        }
    });
    Ok(Fx::from_bits(scale.min(i64::from(i32::MAX)) as i32))
}

/// Writes the RGB565 tangent-space normal map of `height` at `strength` σ (texel widths per
/// height step) into `out`: `n = normalize(−σ ∂h/∂i, −σ ∂h/∂j, 1)`, each channel
/// `round((n + 1) / 2 · max)`.
///
/// # Errors
/// [`Error::WrongLength`] when `out` is not the chain's length.
pub fn normal_map(height: &HeightMap<'_>, strength: Fx, out: &mut [Rgb565]) -> Result<(), Error> {
    check(height, out.len())?;
    let s = i64::from(strength.to_bits());
    each_texel(height, |idx, k, i, j| {
        let (dx, dy) = differences(height, k, i, j);
        // -σ d in Q16 with d = dx / 2^(k+1); the normal in Q12 units of z = 1.
        let c = |d: i32| ((-(i64::from(d) * s) >> (k + 1)) >> 4).clamp(-(1 << 28), 1 << 28) as i32;
        let n = unit_q14([c(dx), c(dy), 1 << 12]);
        let enc = |x: i32, max: i32| ((x + (1 << 14)) * max + (1 << 14)) >> 15;
        let raw = (enc(n[0], 31) << 11) | (enc(n[1], 63) << 5) | enc(n[2], 31);
        if let Some(t) = out.get_mut(idx) {
            *t = Rgb565::from(RawU16::new(raw as u16));
        }
    });
    Ok(())
}
