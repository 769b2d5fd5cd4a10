//! Transparency: blending a shader's colour with what the target holds, alpha from the
//! texture (a colour key, an 8-bit alpha plane beside RGB565, or ARGB4444 texels) and/or
//! constant per draw, and alpha-tested cut-outs.
//!
//! Blend modes, per RGB565 channel with alpha `a` in `0..=255` taken as `w = a + a / 128`
//! (`0..=256`, so 255 is exactly opaque and 0 exactly nothing), one rounding each:
//!
//! ```text
//! over      (s w + d (256 − w) + 128) / 256
//! add       min(d + (s w + 128) / 256, channel max)       (saturates)
//! multiply  over, with s replaced by s · d / channel max
//! ```
//!
//! Blending shaders ([`Shader::BLENDS`]) test depth but do not write it: draw the opaque
//! scene first, then the transparent triangles back to front
//! ([`crate::scene::sort_back_to_front`]). Cut-outs ([`AlphaTest`]) are opaque where the
//! alpha passes and discarded elsewhere, and write depth where they draw: no sorting needed.
//!
//! ```
//! use fixel::shading::alpha::{blend, BlendMode};
//!
//! let (red, blue) = (0xF800u16, 0x001Fu16);
//! assert_eq!(blend(BlendMode::Over, red, blue, 255), red); // opaque
//! assert_eq!(blend(BlendMode::Over, red, blue, 0), blue); // nothing
//! assert_eq!(blend(BlendMode::Over, red, blue, 128), 0x800F); // 129/256 red, 127/256 blue
//! assert_eq!(blend(BlendMode::Add, 0xFFFF, 0x8410, 255), 0xFFFF); // saturates
//! ```

use crate::color::modulate_scalar;
use crate::geometry::COLOR_ONE;
use crate::shading::{Fragment, Shader};
use crate::texture::{Repeat, Sampler, Texture, WrapMode};
use crate::Error;

/// How a colour combines with the target's.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum BlendMode {
    /// `s a + d (1 − a)`: ordinary transparency.
    #[default]
    Over,
    /// `d + s a`, saturating: light, fire, glows.
    Add,
    /// `d (s a + 1 − a)`: tinted glass, shadows.
    Multiply,
}

/// `a` (0..=255) as a weight in 0..=256.
#[inline(always)]
fn weight(a: u8) -> u32 {
    u32::from(a) + (u32::from(a) >> 7)
}

/// `src` blended over `dst` (raw RGB565) with alpha `a` in mode `mode`; see the module docs.
#[inline(always)]
pub fn blend(mode: BlendMode, src: u16, dst: u16, a: u8) -> u16 {
    let w = weight(a);
    let ch = |shift: u32, max: u32| {
        let (s, d) = (
            (u32::from(src) >> shift) & max,
            (u32::from(dst) >> shift) & max,
        );
        let v = match mode {
            BlendMode::Over => (s * w + d * (256 - w) + 128) >> 8,
            BlendMode::Add => (d + ((s * w + 128) >> 8)).min(max),
            BlendMode::Multiply => {
                let m = (s * d + max / 2) / max;
                (m * w + d * (256 - w) + 128) >> 8
            }
        };
        v << shift
    };
    (ch(11, 31) | ch(5, 63) | ch(0, 31)) as u16
}

/// Where a texel's alpha comes from.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum AlphaSource<'a> {
    /// Every texel opaque (use the draw's constant alpha).
    Opaque,
    /// Texels of this raw RGB565 colour are fully transparent, the rest opaque (1-bit
    /// colour key).
    Key(u16),
    /// One alpha byte per texel of level 0, row-major, beside the RGB565 texels.
    Plane(&'a [u8]),
}

impl AlphaSource<'_> {
    /// Checks the source against a `w x h` texture.
    fn check(&self, w: u32, h: u32) -> Result<(), Error> {
        if let AlphaSource::Plane(p) = self {
            let need = (w * h) as usize;
            if p.len() != need {
                return Err(Error::WrongLength {
                    expected: need,
                    actual: p.len(),
                });
            }
        }
        Ok(())
    }

    /// Alpha of the texel nearest to I16F16 texel coordinates `(u, v)` (repeating), given
    /// the colour found there.
    #[inline(always)]
    fn at(&self, tex: &Texture<'_>, u: i32, v: i32, color: u16) -> u8 {
        match *self {
            AlphaSource::Opaque => 255,
            AlphaSource::Key(k) => {
                if color == k {
                    0
                } else {
                    255
                }
            }
            AlphaSource::Plane(p) => {
                let (lw, lh) = (tex.log2_width(), tex.log2_height());
                let i = Repeat.wrap(u >> 16, lw).unwrap_or(0);
                let j = Repeat.wrap(v >> 16, lh).unwrap_or(0);
                let idx = ((j << lw) | i) as usize;
                p.get(idx).copied().unwrap_or(255)
            }
        }
    }
}

/// ARGB4444 texels (`aaaa rrrr gggg bbbb`) as an RGB565 texture and an alpha plane, for
/// [`AlphaSource::Plane`]: channels widened by bit replication. `rgb` and `alpha` must be
/// as long as `argb`.
pub fn split_argb4444(
    argb: &[u16],
    rgb: &mut [crate::Rgb565],
    alpha: &mut [u8],
) -> Result<(), Error> {
    if rgb.len() != argb.len() || alpha.len() != argb.len() {
        return Err(Error::WrongLength {
            expected: argb.len(),
            actual: rgb.len().min(alpha.len()),
        });
    }
    for ((&t, c), a) in argb.iter().zip(rgb.iter_mut()).zip(alpha.iter_mut()) {
        let n = |s: u32| ((u32::from(t) >> s) & 15) as u8;
        let (a4, r4, g4, b4) = (n(12), n(8), n(4), n(0));
        *a = a4 << 4 | a4;
        *c = crate::Rgb565::new(r4 << 1 | r4 >> 3, g4 << 2 | g4 >> 2, b4 << 1 | b4 >> 3);
    }
    Ok(())
}

/// Varyings of the alpha shaders: `s, t` (normalized I16F16: 1.0 = one texture) and the
/// Gouraud intensity (Q8.16), as a [`ClipVertex`](crate::geometry::ClipVertex)'s `uv` and
/// colour.
pub type AlphaVaryings = [i32; 3];

/// Texture coordinates of a fragment in I16F16 texels.
#[inline(always)]
fn texel_coords(tex: &Texture<'_>, v: &AlphaVaryings) -> (i32, i32) {
    (
        v[0].wrapping_shl(tex.log2_width()),
        v[1].wrapping_shl(tex.log2_height()),
    )
}

#[inline(always)]
fn intensity(v: &AlphaVaryings) -> u16 {
    (v[2].saturating_add(1 << 15) >> 16).clamp(0, i32::from(COLOR_ONE)) as u16
}

/// A translucent textured surface: the texture (filtered with `F`, repeating) times the
/// Gouraud intensity, with the texel's alpha (from `source`) times the draw's constant
/// `alpha`, blended with the target in `mode`. Tests depth, does not write it.
#[derive(Clone, Copy, Debug)]
pub struct AlphaBlend<'a, F> {
    tex: Texture<'a>,
    source: AlphaSource<'a>,
    alpha: u8,
    mode: BlendMode,
    filter: core::marker::PhantomData<F>,
}

impl<'a, F: Sampler> AlphaBlend<'a, F> {
    /// `tex` with per-texel alpha from `source` (checked against the texture's size), times
    /// constant `alpha`, blended in `mode`.
    pub fn new(
        tex: Texture<'a>,
        source: AlphaSource<'a>,
        alpha: u8,
        mode: BlendMode,
        _filter: F,
    ) -> Result<Self, Error> {
        source.check(tex.width(), tex.height())?;
        Ok(AlphaBlend {
            tex,
            source,
            alpha,
            mode,
            filter: core::marker::PhantomData,
        })
    }
}

impl<F: Sampler> Shader for AlphaBlend<'_, F> {
    type Varyings = AlphaVaryings;
    type Triangle = ();
    const BLENDS: bool = true;

    fn triangle(&self, _: &mut [AlphaVaryings; 3]) {}

    #[inline(always)]
    fn shade(&self, f: &Fragment<AlphaVaryings, ()>) -> Option<u16> {
        self.shade_over(f, 0)
    }

    #[inline(always)]
    fn shade_over(&self, f: &Fragment<AlphaVaryings, ()>, dst: u16) -> Option<u16> {
        let (u, v) = texel_coords(&self.tex, &f.varyings);
        let c = F::sample(&self.tex, Repeat, Repeat, u, v);
        let a = self.source.at(&self.tex, u, v, c);
        let a = ((u32::from(a) * weight(self.alpha)) >> 8) as u8;
        if a == 0 {
            return None;
        }
        Some(blend(
            self.mode,
            modulate_scalar(c, intensity(&f.varyings)),
            dst,
            a,
        ))
    }
}

/// An alpha-tested cut-out (foliage, fences, decals): opaque where the texel's alpha is at
/// least `threshold`, discarded elsewhere; writes depth where it draws, so no sorting.
#[derive(Clone, Copy, Debug)]
pub struct AlphaTest<'a, F> {
    tex: Texture<'a>,
    source: AlphaSource<'a>,
    threshold: u8,
    filter: core::marker::PhantomData<F>,
}

impl<'a, F: Sampler> AlphaTest<'a, F> {
    /// `tex` cut out where `source`'s alpha is below `threshold` (1..=255).
    pub fn new(
        tex: Texture<'a>,
        source: AlphaSource<'a>,
        threshold: u8,
        _filter: F,
    ) -> Result<Self, Error> {
        source.check(tex.width(), tex.height())?;
        if threshold == 0 {
            return Err(Error::OutOfRange {
                what: "alpha-test threshold (0 would keep every texel: use an opaque shader)",
            });
        }
        Ok(AlphaTest {
            tex,
            source,
            threshold,
            filter: core::marker::PhantomData,
        })
    }
}

impl<F: Sampler> Shader for AlphaTest<'_, F> {
    type Varyings = AlphaVaryings;
    type Triangle = ();
    const DISCARDS: bool = true;

    fn triangle(&self, _: &mut [AlphaVaryings; 3]) {}

    #[inline(always)]
    fn shade(&self, f: &Fragment<AlphaVaryings, ()>) -> Option<u16> {
        let (u, v) = texel_coords(&self.tex, &f.varyings);
        let c = F::sample(&self.tex, Repeat, Repeat, u, v);
        if self.source.at(&self.tex, u, v, c) < self.threshold {
            return None;
        }
        Some(modulate_scalar(c, intensity(&f.varyings)))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn alpha_ends_are_exact_and_add_saturates() {
        let mut x = 0x1234_5678u32;
        for _ in 0..20_000 {
            x ^= x << 13;
            x ^= x >> 17;
            x ^= x << 5;
            let (s, d) = (x as u16, (x >> 16) as u16);
            for m in [BlendMode::Over, BlendMode::Add, BlendMode::Multiply] {
                assert_eq!(blend(m, s, d, 0), d, "{m:?} a=0");
            }
            assert_eq!(blend(BlendMode::Over, s, d, 255), s);
            let add = blend(BlendMode::Add, s, d, 255);
            for (sh, max) in [(11, 31u16), (5, 63), (0, 31)] {
                let c = |v: u16| (v >> sh) & max;
                assert_eq!(c(add), (c(s) + c(d)).min(max));
            }
        }
    }

    #[test]
    fn argb4444_widens_by_replication() {
        let argb = [0xF000u16, 0x0FFF, 0x8421];
        let (mut rgb, mut a) = ([crate::Rgb565::new(0, 0, 0); 3], [0u8; 3]);
        split_argb4444(&argb, &mut rgb, &mut a).unwrap();
        assert_eq!(a, [255, 0, 0x88]);
        assert_eq!(rgb[1], crate::Rgb565::new(31, 63, 31));
        assert!(split_argb4444(&argb, &mut rgb[..2], &mut a).is_err());
    }
}
