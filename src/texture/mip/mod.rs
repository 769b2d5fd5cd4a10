//! Mipmaps: a power-of-two pyramid of a texture (Williams), level selection from the
//! screen-space derivatives of the texel coordinates (Heckbert), and GL's minification
//! filters.
//!
//! # Storage
//! A chain is one contiguous, row-major `&[Rgb565]`: level 0 (`w x h`), then level 1
//! (`max(1, w/2) x max(1, h/2)`), and so on, down to 1 x 1 or to a chosen number of levels:
//! at most 4/3 of the base size. [`MipTexture`] views each level as a [`Texture`]. Chains are
//! built at compile time (`cargo xtask bake`, from the 8-bit source image) or at run time
//! by [`generate_mips`] into caller-provided storage, every level straight from level 0
//! at full precision: the mean of the block of texels it covers, rounded once (at level 1
//! the 2 x 2 box filter `(a + b + c + d + 2) >> 2`, `(a + b + 1) >> 1` where a side is
//! already 1).
//!
//! # Level of detail (OpenGL ES 3.2, scale factor and level of detail)
//! `lambda = log2(rho)` with Heckbert's
//! `rho = max(sqrt(ux^2 + vx^2), sqrt(uy^2 + vy^2))` (derivatives of the level-0 texel
//! coordinates per pixel), computed without a square root as `log2(max(...)) / 2`, with
//! `leading_zeros` and a 64-entry table: `lambda` is Q8.8 (256 = one level), within 1/64
//! of a level. Then `lambda' = clamp(lambda + bias, min, max)`; `lambda' <= 0` magnifies
//! (the magnification filter on level 0); otherwise:
//! * `*_MIPMAP_NEAREST`: level `0` when `lambda' <= 1/2`, else `ceil(lambda' + 1/2) - 1`;
//! * `*_MIPMAP_LINEAR`: levels `floor(lambda')` and the next, blended by `frac(lambda')`
//!   (8-bit weight, per channel, rounded).
//!
//! Levels beyond the chain are clamped to the last.

use embedded_graphics_core::pixelcolor::raw::RawU16;
use embedded_graphics_core::pixelcolor::{IntoStorage, Rgb565};

use super::texture::{Texture, MAX_LOG2_SIZE};
use crate::Error;

mod lod;
mod sampler;

pub use lod::{direction_lambda, lambda_q8, log2_q8, Lod, LodGranularity, MipFilter};
pub(crate) use sampler::{footprints_needed, linear_levels};
pub use sampler::{
    lerp565, DynMip, LinearMipmapNearest, Mipmapped, NearestMipmapLinear, NearestMipmapNearest,
    TexSampler, Trilinear,
};

/// Most levels a chain can have (4096 down to 1).
pub const MAX_LEVELS: usize = MAX_LOG2_SIZE as usize + 1;

/// Number of texels in a chain of `levels` levels from a `width x height` base, saturating
/// at `usize::MAX` (sides beyond the 4096 a [`Texture`] takes can need more texels than a
/// `usize` counts on a 32-bit target; [`MipTexture::new`] refuses those sides first).
pub const fn chain_len(width: u32, height: u32, levels: u32) -> usize {
    let mut n = 0usize;
    let mut k = 0;
    while k < levels {
        let level = (level_side(width, k) as usize).saturating_mul(level_side(height, k) as usize);
        n = n.saturating_add(level);
        k += 1;
    }
    n
}

/// Side of level `k` for a base side `s`: `max(1, s >> k)`.
pub const fn level_side(s: u32, k: u32) -> u32 {
    let v = if k >= 32 { 0 } else { s >> k };
    if v == 0 {
        1
    } else {
        v
    }
}

/// Levels of a full chain down to 1 x 1: `log2(max(width, height)) + 1`.
pub const fn full_levels(width: u32, height: u32) -> u32 {
    let m = if width > height { width } else { height };
    if m == 0 {
        0
    } else {
        32 - m.leading_zeros()
    }
}

/// A texture with a mip chain: level `k` is a [`Texture`] view into one contiguous slice.
#[derive(Clone, Copy, Debug)]
pub struct MipTexture<'a> {
    levels: [Texture<'a>; MAX_LEVELS],
    count: u8,
    /// Level 0's bilinear footprints (see [`BilinearFootprint`](super::BilinearFootprint)),
    /// or empty. Here, not in [`Texture`], so that textures and chains that do not carry
    /// them pay nothing: 8 bytes per chain instead of 8 per level.
    footprints: &'a [u64],
}

impl<'a> MipTexture<'a> {
    /// A one-level "chain": plain sampling, no mipmapping.
    ///
    /// In a firmware, make it a `static` when the texture is one (`static CHAIN:
    /// MipTexture<'static> = MipTexture::single(Texture::from_static(&TEXELS, 8, 8));`):
    /// built at run time it fills all [`MAX_LEVELS`] level slots on the stack, which on
    /// Cortex-M links `memcpy` (about 0.9 KB of flash in the `size_open` firmware of
    /// `cargo xtask size`).
    pub const fn single(t: Texture<'a>) -> Self {
        MipTexture {
            levels: [t; MAX_LEVELS],
            count: 1,
            footprints: &[],
        }
    }

    /// Adds level 0's bilinear footprints (word `i` holds texel `i`, its right neighbour,
    /// and the two texels below them, built by [`footprint_texels`](super::footprint_texels)
    /// or [`write_footprints`](super::write_footprints)), which
    /// [`BilinearFootprint`](super::BilinearFootprint) reads: one 64-bit word per bilinear
    /// sample instead of four texels.
    ///
    /// # Errors
    /// - [`Error::WrongLength`] if `footprints.len()` is not level 0's `width * height`,
    /// - [`Error::FootprintMismatch`] at the first word that is not texel `i`'s footprint
    ///   (the check reads every word once).
    pub fn with_footprints(mut self, footprints: &'a [u64]) -> Result<Self, Error> {
        super::footprint_words::check_footprints(self.base(), footprints)?;
        self.footprints = footprints;
        Ok(self)
    }

    /// [`MipTexture::with_footprints`] for statics, checked at compile time when evaluated
    /// in a `const`/`static` (at run time otherwise):
    /// `static T: MipTexture = MipTexture::single(TEX).with_footprints_static(&FOOTPRINTS);`.
    ///
    /// Only the length can be checked in a `const` (the texels are `Rgb565`, whose value a
    /// `const fn` cannot read): build `footprints` with
    /// [`footprint_texels`](super::footprint_texels) from the same raw texels. Words that
    /// do not match draw their own colours under
    /// [`BilinearFootprint`](super::BilinearFootprint); nothing panics or reads out of
    /// bounds.
    ///
    /// # Panics
    /// If `footprints.len()` is not level 0's `width * height`.
    #[must_use]
    pub const fn with_footprints_static(mut self, footprints: &'a [u64]) -> Self {
        assert!(
            footprints.len() == self.levels[0].texels().len(),
            "footprints must hold one word per texel of level 0"
        );
        self.footprints = footprints;
        self
    }

    /// Level 0's footprints, or an empty slice when none were added.
    #[inline(always)]
    pub const fn footprints(&self) -> &'a [u64] {
        self.footprints
    }

    /// Views `chain` (laid out as in the module docs) as `levels` levels of a
    /// `width x height` base. Errors: [`Error::BadSize`] for a side of 0 or above 4096
    /// (checked first), the base's [`Texture::new`] errors,
    /// [`Error::BadSize`] for zero levels or more than the full chain has,
    /// [`Error::WrongLength`] when `chain` is not exactly [`chain_len`] long.
    pub fn new(chain: &'a [Rgb565], width: u32, height: u32, levels: u32) -> Result<Self, Error> {
        // The sides first, so the expected length below is computed for sides of at most
        // 4096 (no saturation, and the error names the side).
        for side in [width, height] {
            if side == 0 || side > 1 << MAX_LOG2_SIZE {
                return Err(Error::BadSize(side));
            }
        }
        let full = full_levels(width, height);
        if levels == 0 || levels > full || levels as usize > MAX_LEVELS {
            return Err(Error::BadSize(levels));
        }
        let expected = chain_len(width, height, levels);
        if chain.len() != expected {
            return Err(Error::WrongLength {
                expected,
                actual: chain.len(),
            });
        }
        let mut out = MipTexture::single(Texture::new(
            chain.get(..(width * height) as usize).unwrap_or(&[]),
            width,
            height,
        )?);
        let mut off = 0usize;
        for k in 0..levels {
            let (w, h) = (level_side(width, k), level_side(height, k));
            let n = (w * h) as usize;
            let slice = chain.get(off..off + n).ok_or(Error::WrongLength {
                expected,
                actual: chain.len(),
            })?;
            out.levels[k as usize] = Texture::new(slice, w, h)?;
            off += n;
        }
        out.count = levels as u8;
        Ok(out)
    }

    /// The same chain with border colour `c` on every level.
    pub fn with_border(mut self, c: Rgb565) -> Self {
        for l in self.levels.iter_mut() {
            *l = l.with_border(c);
        }
        self
    }

    /// Number of levels.
    pub fn levels(&self) -> u32 {
        u32::from(self.count)
    }

    /// Level `k`, clamped to the last level.
    #[inline(always)]
    pub fn level(&self, k: u32) -> &Texture<'a> {
        let k = (k as usize)
            .min(usize::from(self.count).saturating_sub(1))
            .min(MAX_LEVELS - 1);
        &self.levels[k]
    }

    /// Level 0.
    #[inline(always)]
    pub fn base(&self) -> &Texture<'a> {
        &self.levels[0]
    }
}

/// Fills levels `1..levels` of `chain` from level 0 (which the caller has written), each
/// level straight from level 0 at full precision: texel `(i, j)` of level `k` is the mean
/// of the `bw x bh` block of level-0 texels it covers (`bw = width / side_k`, likewise
/// `bh`), per channel, rounded once (half up): `(sum + n / 2) >> log2(n)`. Level 1 is the
/// 2 x 2 box filter (`(a + b + c + d + 2) >> 2`, `(a + b + 1) >> 1` where a side is
/// already 1); deeper levels do not compound its rounding, as box-filtering each level
/// from the rounded one before does (up to half an LSB per level, always up at ties).
/// Cost: `width x height` texel reads per level. Same layout and errors as
/// [`MipTexture::new`].
pub fn generate_mips(
    chain: &mut [Rgb565],
    width: u32,
    height: u32,
    levels: u32,
) -> Result<(), Error> {
    // Validates sizes and the length.
    MipTexture::new(chain, width, height, levels)?;
    let (base, rest) = chain.split_at_mut((width * height) as usize);
    let mut off = 0usize;
    for k in 1..levels {
        let (dw, dh) = (level_side(width, k), level_side(height, k));
        // Powers of two: the block of level-0 texels under one level-k texel.
        let (bw, bh) = (width / dw, height / dh);
        let shift = (bw * bh).trailing_zeros();
        let half = (1u32 << shift) >> 1;
        for j in 0..dh {
            for i in 0..dw {
                // At most 2^24 texels of at most 63: sums below 2^30.
                let mut sum = [0u32; 3];
                for y in j * bh..(j + 1) * bh {
                    let row = (y * width) as usize;
                    for x in i * bw..(i + 1) * bw {
                        let t = base.get(row + x as usize).map_or(0, |c| c.into_storage());
                        sum[0] += u32::from(t >> 11);
                        sum[1] += u32::from((t >> 5) & 0x3F);
                        sum[2] += u32::from(t & 0x1F);
                    }
                }
                let [r, g, b] = sum.map(|s| (s + half) >> shift);
                let c = ((r & 0x1F) << 11) | ((g & 0x3F) << 5) | (b & 0x1F);
                if let Some(d) = rest.get_mut(off + (j * dw + i) as usize) {
                    *d = Rgb565::from(RawU16::new(c as u16));
                }
            }
        }
        off += (dw * dh) as usize;
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    extern crate std;
    use super::*;
    use std::vec;
    #[test]
    fn chain_layout_and_box_filter() {
        assert_eq!(chain_len(4, 2, 3), 8 + 2 + 1);
        assert_eq!(full_levels(64, 64), 7);
        assert_eq!(full_levels(256, 128), 9);
        let px = |r: u8, g: u8, b: u8| Rgb565::new(r, g, b);
        let mut chain = vec![px(0, 0, 0); chain_len(4, 2, 3)];
        chain[..8].copy_from_slice(&[
            px(4, 0, 0),
            px(8, 0, 0),
            px(0, 4, 0),
            px(0, 8, 0),
            px(4, 0, 0),
            px(8, 0, 1),
            px(0, 4, 0),
            px(0, 8, 3),
        ]);
        generate_mips(&mut chain, 4, 2, 3).unwrap();
        assert_eq!(chain[8], px(6, 0, 0)); // (4+8+4+8+2)/4 = 6; blue (0+0+0+1+2)/4 = 0
        assert_eq!(chain[9], px(0, 6, 1)); // blue (0+0+0+3+2)/4 = 1
        assert_eq!(chain[10], px(3, 3, 1)); // 2x1 -> 1x1: (6+0+1)/2 = 3 (r), 3 (g), 1 (b)
        let mip = MipTexture::new(&chain, 4, 2, 3).unwrap();
        assert_eq!(mip.levels(), 3);
        assert_eq!(mip.level(2).width(), 1);
        assert!(MipTexture::new(&chain[..10], 4, 2, 3).is_err());
        assert!(MipTexture::new(&chain, 4, 2, 4).is_err());
    }

    /// Deeper levels are the rounded mean of level 0, not of the rounded level above: two
    /// 2 x 2 blocks of mean 1/2 (level 1 rounds them up to 1) and two of 0 average 1/4,
    /// level 2 is 0 (box-filtering level 1 gave (1 + 1 + 0 + 0 + 2) >> 2 = 1).
    #[test]
    fn deeper_levels_round_once() {
        let px = |r: u8| Rgb565::new(r, 0, 0);
        let mut chain = vec![px(0); chain_len(4, 4, 3)];
        chain[5] = px(2); // block (0, 0): [0, 0, 0, 2]
        chain[7] = px(2); // block (1, 0): [0, 0, 0, 2]
        generate_mips(&mut chain, 4, 4, 3).unwrap();
        assert_eq!(&chain[16..20], &[px(1), px(1), px(0), px(0)]);
        assert_eq!(chain[20], px(0));
        // Against the exact mean over random 16 x 8 images: within half an LSB.
        let mut rng = crate::test_rng::Rng(0x0123_4567_89AB_CDEF);
        for _ in 0..50 {
            let mut chain = vec![px(0); chain_len(16, 8, 5)];
            for c in chain.iter_mut().take(128) {
                let v = rng.next();
                *c = Rgb565::new(
                    (v & 31) as u8,
                    ((v >> 5) & 63) as u8,
                    ((v >> 11) & 31) as u8,
                );
            }
            let base: std::vec::Vec<u16> = chain[..128].iter().map(|c| c.into_storage()).collect();
            generate_mips(&mut chain, 16, 8, 5).unwrap();
            let mip = MipTexture::new(&chain, 16, 8, 5).unwrap();
            for k in 1..5u32 {
                let l = mip.level(k);
                let (bw, bh) = (16 / l.width(), 8 / l.height());
                for j in 0..l.height() {
                    for i in 0..l.width() {
                        let mut sum = [0f64; 3];
                        for y in j * bh..(j + 1) * bh {
                            for x in i * bw..(i + 1) * bw {
                                let t = base[(y * 16 + x) as usize];
                                sum[0] += f64::from(t >> 11);
                                sum[1] += f64::from((t >> 5) & 63);
                                sum[2] += f64::from(t & 31);
                            }
                        }
                        let t = l.texel_raw(i, j);
                        let got = [t >> 11, (t >> 5) & 63, t & 31].map(f64::from);
                        for c in 0..3 {
                            let mean = sum[c] / f64::from(bw * bh);
                            assert!((got[c] - mean).abs() <= 0.5, "level {k} ({i}, {j})");
                        }
                    }
                }
            }
        }
    }

    /// Sides past 4096 are refused by name before any length is computed, and the length
    /// itself saturates instead of overflowing (a `const` use compiles on 32-bit targets).
    #[test]
    fn huge_sides_are_refused_without_overflow() {
        const BIG: usize = chain_len(65536, 65536, 1);
        assert_eq!(BIG as u64, (1u64 << 32).min(usize::MAX as u64));
        assert_eq!(chain_len(u32::MAX, u32::MAX, 32), usize::MAX);
        assert_eq!(chain_len(u32::MAX, 1, 1), u32::MAX as usize);
        let e = MipTexture::new(&[], u32::MAX, u32::MAX, 32).unwrap_err();
        assert_eq!(e, Error::BadSize(u32::MAX));
        assert_eq!(
            MipTexture::new(&[], 8, 8192, 1).unwrap_err(),
            Error::BadSize(8192)
        );
        assert_eq!(
            MipTexture::new(&[], 0, 8, 1).unwrap_err(),
            Error::BadSize(0)
        );
        let mut none: [Rgb565; 0] = [];
        let e = generate_mips(&mut none, u32::MAX, u32::MAX, 32).unwrap_err();
        assert_eq!(e, Error::BadSize(u32::MAX));
    }
}
