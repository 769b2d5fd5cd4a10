//! Bilinear footprints: a texture layout for [`BilinearFootprint`], the bilinear filter that
//! reads it.
//!
//! Layout: one `u64` per texel (row-major like the texels) holding the four texels of the
//! bilinear footprint whose top-left texel it is, with repeat wrapping (the row's first
//! texel after its last, row 0 below the last row). With `c(i, j)` raw RGB565 and
//! `i1 = (i + 1) % width`, `j1 = (j + 1) % height`:
//!
//! `footprints[j * width + i] = c(i, j) | c(i1, j) << 16 | c(i, j1) << 32 | c(i1, j1) << 48`.
//!
//! A bilinear sample with repeat wrapping needs exactly those four texels. [`Bilinear`] loads
//! them one by one and packs each row's two into a word for its two-texels-per-multiply sums
//! (see `sample.rs`); [`BilinearFootprint`] loads one word, already packed: one index
//! instead of four, no right column or lower row to wrap, no packing. The weights, sums and
//! roundings are [`Bilinear`]'s, so the pixels are the same bit for bit (tested); only the
//! cost changes.
//!
//! Cost: 8 bytes per texel beside the texels' 2 (a 128 x 128 texture: 128 KiB of footprints
//! beside 32 KiB of texels). Build them once: [`footprint_texels`] in a `static` (flash, at
//! compile time), or [`write_footprints`] into caller storage (RAM, at run time), and hand
//! them to the chain ([`MipTexture::with_footprints`]; level 0 only). Only the chain holds
//! them: a [`Texture`] has no footprint field, so textures, chains and draws that do not
//! sample them carry and link none of this.
//!
//! Other wraps (clamp, mirror, border) read the plain texels as [`Bilinear`] does, since
//! their neighbours at the edges are not the repeat ones.
//!
//! ```
//! use fixel::texture::{footprint_texels, BilinearFootprint, MipTexture, Repeat, Texture};
//! use fixel::texture::{Bilinear, Sampler};
//! use fixel::Rgb565;
//!
//! const RAW: [u16; 4] = [0xF800, 0x07E0, 0x001F, 0xFFFF];
//! static TEXELS: [Rgb565; 4] = [
//!     Rgb565::new(31, 0, 0),
//!     Rgb565::new(0, 63, 0),
//!     Rgb565::new(0, 0, 31),
//!     Rgb565::new(31, 63, 31),
//! ];
//! static FOOTPRINTS: [u64; 4] = footprint_texels(&RAW, 2);
//! static TEX: Texture<'static> = Texture::from_static(&TEXELS, 2, 2);
//! // What a draw or a binding takes (`Draw::new_mip`, `TexBinding::new`).
//! static CHAIN: MipTexture<'static> = MipTexture::single(TEX).with_footprints_static(&FOOTPRINTS);
//!
//! // Texel (1, 1)'s footprint wraps right to (0, 1) and down to row 0.
//! assert_eq!(FOOTPRINTS[3], 0xFFFF | 0x001F << 16 | 0x07E0 << 32 | 0xF800 << 48);
//! // Halfway between all four texel centres: their mean, whatever the layout.
//! let c = BilinearFootprint::sample(&TEX, CHAIN.footprints(), Repeat, Repeat, 0x10000, 0x10000);
//! assert_eq!(c, Bilinear::sample(&TEX, Repeat, Repeat, 0x10000, 0x10000));
//! ```

use super::mip::{MipTexture, TexSampler};
use super::sample::{blend_rows_q8, Bilinear, Sampler, REPEAT_SPLIT};
use super::texture::Texture;
use super::wrap::WrapMode;

/// Bilinear filtering ([`Bilinear`]'s arithmetic and pixels) that reads level 0's
/// footprints ([`MipTexture::with_footprints`]) when both wraps repeat: one 64-bit word per
/// sample.
///
/// A [`TexSampler`] for level 0 only (not a [`Sampler`], so it cannot be
/// part of a [`Mipmapped`](super::Mipmapped) one). Bindings and draws refuse a chain without
/// footprints ([`Error::BadMode`](crate::Error::BadMode)). Its [`TexSampler::FILTER`] is
/// [`Filter::Bilinear`](super::Filter::Bilinear).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct BilinearFootprint;

impl BilinearFootprint {
    /// [`gather_footprint`] with `tex`'s width and the footprints' count, read at run time.
    #[inline(always)]
    fn gather(tex: &Texture<'_>, footprints: &[u64], u: i32, v: i32) -> (u32, u32, u32, u32) {
        gather_footprint(
            footprints,
            u,
            v,
            tex.log2_width(),
            tex.width().wrapping_sub(1),
            footprints.len().wrapping_sub(1),
        )
    }

    /// Samples `tex` (level 0) at raw I16F16 texel coordinates `(u, v)` with wrap modes
    /// `wu`, `wv`, reading `footprints` (`tex`'s, see [`write_footprints`](super::write_footprints)) when both wraps
    /// repeat. Returns raw RGB565, [`Bilinear`]'s pixel. Never panics: footprints of the
    /// wrong length read as black (bindings refuse them before a draw gets here).
    #[inline(always)]
    pub fn sample<WU: WrapMode, WV: WrapMode>(
        tex: &Texture<'_>,
        footprints: &[u64],
        wu: WU,
        wv: WV,
        u: i32,
        v: i32,
    ) -> u16 {
        if WU::REPEAT && WV::REPEAT {
            let (top, bot, a, b) = Self::gather(tex, footprints, u, v);
            return blend_rows_q8(top, bot, a, b, None);
        }
        Bilinear::sample(tex, wu, wv, u, v)
    }

    /// [`BilinearFootprint::sample`] times intensity `i` (Q8, `0..=256`; larger is 256),
    /// as [`Bilinear::sample_scaled`](super::Sampler::sample_scaled): one rounding.
    #[inline(always)]
    pub fn sample_scaled<WU: WrapMode, WV: WrapMode>(
        tex: &Texture<'_>,
        footprints: &[u64],
        wu: WU,
        wv: WV,
        u: i32,
        v: i32,
        i: u16,
    ) -> u16 {
        if WU::REPEAT && WV::REPEAT {
            let (top, bot, a, b) = Self::gather(tex, footprints, u, v);
            return blend_rows_q8(top, bot, a, b, Some(u32::from(i.min(256))));
        }
        Bilinear::sample_scaled(tex, wu, wv, u, v, i)
    }
}

/// The two row words (`c00 | c10 << 16`, `c01 | c11 << 16`) and Q8 weights `a`, `b`
/// (`0..=255`) of a repeat-wrapped sample at `(u, v)` (raw I16F16 texel coordinates), split
/// as `Bilinear`'s `gather_repeat` splits them (`t = u - 1/2 + 1/512`), for a level 0 of
/// `2^log2_w` columns (`col_mask = 2^log2_w - 1`) and `count_mask + 1` footprints (a power
/// of two). The row offset is not wrapped: masking the index with the count wraps the row
/// too. A footprint past the end (footprints of another count) reads as black: never
/// panics. Shared by [`BilinearFootprint`] (the masks from the texture, at run time) and
/// [`BilinearFootprintSized`](super::BilinearFootprintSized) (constants).
#[inline(always)]
pub(super) fn gather_footprint(
    footprints: &[u64],
    u: i32,
    v: i32,
    log2_w: u32,
    col_mask: u32,
    count_mask: usize,
) -> (u32, u32, u32, u32) {
    let tu = u.wrapping_sub(REPEAT_SPLIT);
    let tv = v.wrapping_sub(REPEAT_SPLIT);
    let (a, b) = ((tu as u32 >> 8) & 0xFF, (tv as u32 >> 8) & 0xFF);
    let row = ((tv >> 16) as u32).wrapping_shl(log2_w);
    let idx = (row | ((tu >> 16) as u32 & col_mask)) as usize & count_mask;
    let f = match footprints.get(idx) {
        Some(&w) => w,
        None => 0,
    };
    (f as u32, (f >> 32) as u32, a, b)
}

impl TexSampler for BilinearFootprint {
    const LOD: bool = false;
    const FILTER: super::Filter = super::Filter::Bilinear;
    const FOOTPRINTS: bool = true;

    #[inline(always)]
    fn sample_mip<WU: WrapMode, WV: WrapMode>(
        self,
        t: &MipTexture<'_>,
        wu: WU,
        wv: WV,
        u: i32,
        v: i32,
        _: i32,
    ) -> u16 {
        Self::sample(t.base(), t.footprints(), wu, wv, u, v)
    }

    /// Without the footprints at hand: [`Bilinear`] (the same pixels).
    #[inline(always)]
    fn sample_base<WU: WrapMode, WV: WrapMode>(
        self,
        base: &Texture<'_>,
        wu: WU,
        wv: WV,
        u: i32,
        v: i32,
    ) -> u16 {
        Bilinear::sample(base, wu, wv, u, v)
    }

    /// Without the footprints at hand: [`Bilinear`] (the same pixels).
    #[inline(always)]
    fn sample_base_scaled<WU: WrapMode, WV: WrapMode>(
        self,
        base: &Texture<'_>,
        wu: WU,
        wv: WV,
        u: i32,
        v: i32,
        i: u16,
    ) -> u16 {
        Bilinear::sample_scaled(base, wu, wv, u, v, i)
    }

    #[inline(always)]
    fn sample_level0<WU: WrapMode, WV: WrapMode>(
        self,
        base: &Texture<'_>,
        footprints: &[u64],
        wu: WU,
        wv: WV,
        u: i32,
        v: i32,
    ) -> u16 {
        Self::sample(base, footprints, wu, wv, u, v)
    }

    #[inline(always)]
    fn sample_level0_scaled<WU: WrapMode, WV: WrapMode>(
        self,
        base: &Texture<'_>,
        footprints: &[u64],
        wu: WU,
        wv: WV,
        u: i32,
        v: i32,
        i: u16,
    ) -> u16 {
        Self::sample_scaled(base, footprints, wu, wv, u, v, i)
    }

    /// On ARMv7E-M with both wraps repeating: the assembly loop of `footprint_span_dsp` for
    /// a size read at run time (the same pixels, about 10 % fewer instructions per pixel
    /// on the Cortex-M4F whole sphere than the Rust loop). Elsewhere none.
    #[inline(always)]
    fn lit_span<WU: WrapMode, WV: WrapMode>(
        self,
        base: &Texture<'_>,
        footprints: &[u64],
        start: &[i32; 3],
        slope: &[i32; 3],
        out: &mut [u16],
    ) -> bool {
        #[cfg(fixel_dsp)]
        if WU::REPEAT && WV::REPEAT {
            return super::footprint_span_dsp::lit_span_runtime(
                footprints,
                (base.log2_width(), base.log2_height()),
                start,
                slope,
                out,
            );
        }
        let _ = (base, footprints, start, slope, out);
        false
    }

    const LIT_SPAN_DEPTH: bool = cfg!(fixel_dsp);

    /// On ARMv7E-M with both wraps repeating: the assembly loop with the depth test in it,
    /// for a size read at run time (every short span through it: about 2 % of the
    /// Cortex-M4F whole sphere against a depth pass first). Elsewhere none.
    #[allow(clippy::too_many_arguments)]
    #[inline(always)]
    fn lit_span_depth<WU: WrapMode, WV: WrapMode>(
        self,
        base: &Texture<'_>,
        footprints: &[u64],
        start: &[i32; 3],
        slope: &[i32; 3],
        z: i32,
        dz: i32,
        out: &mut [u16],
        zrow: &mut [u16],
    ) -> Option<u32> {
        #[cfg(fixel_dsp)]
        if WU::REPEAT && WV::REPEAT {
            return super::footprint_span_dsp::lit_span_depth_runtime(
                footprints,
                (base.log2_width(), base.log2_height()),
                start,
                slope,
                z,
                dz,
                out,
                zrow,
            );
        }
        let _ = (base, footprints, start, slope, z, dz, out, zrow);
        None
    }
}

#[cfg(test)]
mod tests {
    extern crate std;
    use super::*;
    use crate::test_rng::Rng;
    use crate::texture::footprint_words::{footprint_texels, write_footprints};
    use crate::texture::wrap::{ClampToBorder, ClampToEdge, MirroredRepeat, Repeat};
    use crate::Error;
    use embedded_graphics_core::pixelcolor::raw::RawU16;
    use embedded_graphics_core::pixelcolor::Rgb565;
    use std::vec::Vec;

    fn texels(raw: &[u16]) -> Vec<Rgb565> {
        raw.iter().map(|&r| Rgb565::from(RawU16::new(r))).collect()
    }

    /// Every wrap pair, every size up to 16 x 16 (including 1-texel rows and columns), any
    /// coordinates: the same pixels as `Bilinear`, plain and scaled.
    #[test]
    fn footprint_samples_equal_bilinear() {
        let mut rng = Rng(0x1234_5678);
        let mut next = || rng.next() as u32;
        for (lw, lh) in [(0, 0), (0, 3), (3, 0), (1, 1), (2, 3), (4, 4), (4, 1)] {
            let (w, h) = (1u32 << lw, 1u32 << lh);
            let raw: Vec<u16> = (0..w * h).map(|_| next() as u16).collect();
            let t = texels(&raw);
            let plain = Texture::new(&t, w, h).unwrap();
            let mut fp = std::vec![0u64; (w * h) as usize];
            write_footprints(&plain, &mut fp).unwrap();
            MipTexture::single(plain).with_footprints(&fp).unwrap();
            for _ in 0..4000 {
                // Mostly near the texture, sometimes anywhere in i32.
                let (u, v) = if next() % 8 == 0 {
                    (next() as i32, next() as i32)
                } else {
                    (
                        (next() % (w << 18)) as i32 - (w << 17) as i32,
                        (next() % (h << 18)) as i32 - (h << 17) as i32,
                    )
                };
                let i = (next() % 300) as u16;
                macro_rules! same {
                    ($wu:expr, $wv:expr) => {
                        assert_eq!(
                            BilinearFootprint::sample(&plain, &fp, $wu, $wv, u, v),
                            Bilinear::sample(&plain, $wu, $wv, u, v),
                            "{w}x{h} at ({u}, {v})"
                        );
                        assert_eq!(
                            BilinearFootprint::sample_scaled(&plain, &fp, $wu, $wv, u, v, i),
                            Bilinear::sample_scaled(&plain, $wu, $wv, u, v, i),
                            "{w}x{h} at ({u}, {v}) scaled by {i}"
                        );
                    };
                }
                same!(Repeat, Repeat);
                same!(Repeat, ClampToEdge);
                same!(MirroredRepeat, Repeat);
                same!(ClampToBorder, ClampToBorder);
            }
        }
    }

    #[test]
    fn const_and_run_time_layouts_agree() {
        const RAW: [u16; 8] = [1, 2, 3, 4, 5, 6, 7, 8];
        const FP: [u64; 8] = footprint_texels(&RAW, 4);
        let word = |a: u64, b: u64, c: u64, d: u64| a | b << 16 | c << 32 | d << 48;
        assert_eq!(FP[0], word(1, 2, 5, 6));
        assert_eq!(FP[3], word(4, 1, 8, 5));
        assert_eq!(FP[7], word(8, 5, 4, 1));
        let t = texels(&RAW);
        let tex = Texture::new(&t, 4, 2).unwrap();
        let mut out = [0u64; 8];
        write_footprints(&tex, &mut out).unwrap();
        assert_eq!(out, FP);
        assert_eq!(footprint_texels(&[9u16], 1), [word(9, 9, 9, 9)]);
        // One row, one column.
        let row = footprint_texels(&[1u16, 2], 2);
        assert_eq!(row, [word(1, 2, 1, 2), word(2, 1, 2, 1)]);
        let col = footprint_texels(&[1u16, 2], 1);
        assert_eq!(col, [word(1, 1, 2, 2), word(2, 2, 1, 1)]);
    }

    #[test]
    fn wrong_footprints_are_refused() {
        let t = texels(&[1, 2, 3, 4]);
        let tex = Texture::new(&t, 2, 2).unwrap();
        let chain = MipTexture::single(tex);
        let mut out = [0u64; 3];
        assert_eq!(
            write_footprints(&tex, &mut out),
            Err(Error::WrongLength {
                expected: 4,
                actual: 3
            })
        );
        assert_eq!(
            chain.with_footprints(&[0; 5]).unwrap_err(),
            Error::WrongLength {
                expected: 4,
                actual: 5
            }
        );
        let mut good = [0u64; 4];
        write_footprints(&tex, &mut good).unwrap();
        assert!(chain.with_footprints(&good).is_ok());
        let mut bad = good;
        bad[2] ^= 1 << 40;
        assert_eq!(
            chain.with_footprints(&bad).unwrap_err(),
            Error::FootprintMismatch { index: 2 }
        );
        // Footprints of the same texels in another width are refused too.
        let other = footprint_texels(&[1, 2, 3, 4], 4);
        assert_eq!(
            chain.with_footprints(&other).unwrap_err(),
            Error::FootprintMismatch { index: 0 }
        );
    }

    /// Missing or short footprints never panic under the footprint sampler (their words
    /// read as 0; bindings refuse them before a draw gets there).
    #[test]
    fn missing_footprints_never_panic() {
        let t = texels(&[0xFFFF; 4]);
        let tex = Texture::new(&t, 2, 2).unwrap();
        for fp in [&[][..], &[0x1234_5678_9ABC_DEF0][..]] {
            for (u, v) in [(0x8000, 0x8000), (i32::MIN, i32::MAX), (-1, 0x7FFF_FFFF)] {
                let _ = BilinearFootprint::sample(&tex, fp, Repeat, Repeat, u, v);
                let _ = BilinearFootprint::sample_scaled(&tex, fp, Repeat, Repeat, u, v, 999);
            }
        }
        assert_eq!(
            BilinearFootprint::sample(&tex, &[], Repeat, Repeat, 0x8000, 0x8000),
            0
        );
        assert_eq!(
            BilinearFootprint::sample(&tex, &[], ClampToEdge, ClampToEdge, 0x8000, 0x8000),
            0xFFFF
        );
    }
}
