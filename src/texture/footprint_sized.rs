//! [`BilinearFootprintSized`]: [`BilinearFootprint`] for a texture whose size is fixed at
//! compile time.
//!
//! [`BilinearFootprint`] finds a sample's footprint from the texture's width, read at run
//! time: a shift by its base-2 logarithm, a mask of its columns and a mask of the
//! footprints' count. In the span loop these are three values more to keep, which on a
//! 13-register Cortex-M core are reloaded from the stack at every pixel. Here the width
//! and height are type parameters (`LOG2_W`, `LOG2_H`, base-2 logarithms of the sides in
//! texels), so the shift and masks are instruction immediates.
//!
//! The pixels are [`BilinearFootprint`]'s, bit for bit, on a texture of that size (the same
//! index, weights and blend; tested). A binding or a draw refuses a chain of another size
//! with [`Error::TextureSizeMismatch`](crate::Error::TextureSizeMismatch) (or whose
//! footprints are missing, as for [`BilinearFootprint`]), so a wrong texture is an error
//! where it enters, never a wrong image.
//!
//! A binding of it draws only with every footprint of that size there
//! ([`TexBinding::can_draw`](crate::shading::TexBinding::can_draw), which the span loop tests
//! once per span), so the masked index needs no bounds test per pixel either.
//!
//! Against a run-time size, on the benchmark sphere drawn whole (a 256 x 128 texture;
//! `whole_sphere_sized` against `whole_sphere_footprint` in `cargo xtask mcu`), the fixed
//! size saves about 4 % of the instructions per drawn pixel on Cortex-M4F and about 2 % on
//! Cortex-M0+ and RV32IMC.

use super::footprint::{gather_footprint, BilinearFootprint};
use super::mip::{footprints_needed, MipTexture, TexSampler};
use super::sample::{blend_rows_q8, Bilinear, Sampler};
use super::texture::Texture;
use super::wrap::WrapMode;
use crate::Error;

/// [`BilinearFootprint`] for a level 0 of `2^LOG2_W x 2^LOG2_H` texels, fixed at compile
/// time: the same pixels, with the footprint's row shift and masks as instruction
/// immediates instead of three more values for the span loop to keep (on a 13-register
/// Cortex-M core it reloads them from the stack at every pixel), and no bounds test per
/// pixel: about 4 % of the benchmark sphere drawn whole on Cortex-M4F, 2 % on Cortex-M0+
/// and RV32IMC (see the module docs).
///
/// ```
/// use fixel::shading::TexBinding;
/// use fixel::texture::{footprint_texels, BilinearFootprint, BilinearFootprintSized};
/// use fixel::texture::{MipTexture, Repeat, Texture};
/// use fixel::{Error, Rgb565};
/// use embedded_graphics_core::pixelcolor::IntoStorage;
///
/// const RAW: [u16; 8] = [0xF800, 0x07E0, 0x001F, 0xFFFF, 0x0000, 0x8410, 0x1234, 0xFEDC];
/// // The same texels as colours (footprints must be built from a texture's own texels).
/// static TEXELS: [Rgb565; 8] = [
///     Rgb565::new(31, 0, 0),
///     Rgb565::new(0, 63, 0),
///     Rgb565::new(0, 0, 31),
///     Rgb565::new(31, 63, 31),
///     Rgb565::new(0, 0, 0),
///     Rgb565::new(16, 32, 16),
///     Rgb565::new(2, 17, 20),
///     Rgb565::new(31, 54, 28),
/// ];
/// static FOOTPRINTS: [u64; 8] = footprint_texels(&RAW, 4);
/// // 4 x 2 texels: `LOG2_W = 2`, `LOG2_H = 1`.
/// static TEX: Texture<'static> = Texture::from_static(&TEXELS, 4, 2);
/// static CHAIN: MipTexture<'static> = MipTexture::single(TEX).with_footprints_static(&FOOTPRINTS);
///
/// type Sized4x2 = BilinearFootprintSized<2, 1>;
/// // The texels and the footprints agree.
/// for (c, raw) in TEXELS.iter().zip(RAW) {
///     assert_eq!(c.into_storage(), raw);
/// }
/// // The same pixel as `BilinearFootprint` anywhere on the texture.
/// for (u, v) in [(0, 0), (0x1_8000, 0x8000), (0x3_C123, 0x1_7F00), (-0x5000, 0x2_4000)] {
///     assert_eq!(
///         Sized4x2::sample(CHAIN.footprints(), Repeat, Repeat, &TEX, u, v),
///         BilinearFootprint::sample(&TEX, CHAIN.footprints(), Repeat, Repeat, u, v),
///     );
/// }
/// // A binding checks the size.
/// assert!(TexBinding::new(&CHAIN, Sized4x2::default(), Repeat, Repeat, Default::default()).is_ok());
/// let wrong = TexBinding::new(&CHAIN, BilinearFootprintSized::<3, 1>, Repeat, Repeat, Default::default());
/// assert_eq!(
///     wrong.err(),
///     Some(Error::TextureSizeMismatch { width: 8, height: 2 })
/// );
/// ```
///
/// Bindings and draws refuse a chain of another size
/// ([`Error::TextureSizeMismatch`](crate::Error::TextureSizeMismatch)) or without footprints
/// ([`Error::BadMode`](crate::Error::BadMode)). Other wraps than repeat on both axes read
/// the texels as [`Bilinear`] does, as [`BilinearFootprint`] does.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct BilinearFootprintSized<const LOG2_W: u32, const LOG2_H: u32>;

/// `2^k`, or 0 when it does not fit `u32` (such a size matches no texture).
const fn pow2(k: u32) -> u32 {
    match 1u32.checked_shl(k) {
        Some(p) => p,
        None => 0,
    }
}

impl<const LOG2_W: u32, const LOG2_H: u32> BilinearFootprintSized<LOG2_W, LOG2_H> {
    /// Width of the texture it samples, in texels (0 when `2^LOG2_W` does not fit `u32`).
    pub const WIDTH: u32 = pow2(LOG2_W);
    /// Height of the texture it samples, in texels (0 when `2^LOG2_H` does not fit `u32`).
    pub const HEIGHT: u32 = pow2(LOG2_H);

    /// [`gather_footprint`] with the width and the footprints' count as constants: the same
    /// row words and Q8 weights for a texture of this size.
    #[inline(always)]
    fn gather(footprints: &[u64], u: i32, v: i32) -> (u32, u32, u32, u32) {
        gather_footprint(
            footprints,
            u,
            v,
            LOG2_W,
            Self::WIDTH.wrapping_sub(1),
            // What a binding requires (`can_draw`), less one: every masked index in bounds.
            footprints_needed::<Self>() - 1,
        )
    }

    /// Samples `tex` (level 0, `2^LOG2_W x 2^LOG2_H` texels) at raw I16F16 texel
    /// coordinates `(u, v)` with wrap modes `wu`, `wv`, reading `footprints` when both wraps
    /// repeat. Returns raw RGB565, [`BilinearFootprint::sample`]'s pixel. Never panics:
    /// footprints of another count read as black past their end (bindings refuse them
    /// before a draw gets here).
    #[inline(always)]
    pub fn sample<WU: WrapMode, WV: WrapMode>(
        footprints: &[u64],
        wu: WU,
        wv: WV,
        tex: &Texture<'_>,
        u: i32,
        v: i32,
    ) -> u16 {
        if WU::REPEAT && WV::REPEAT {
            let (top, bot, a, b) = Self::gather(footprints, u, v);
            return blend_rows_q8(top, bot, a, b, None);
        }
        Bilinear::sample(tex, wu, wv, u, v)
    }

    /// [`Self::sample`] times intensity `i` (Q8, `0..=256`; larger is 256), as
    /// [`BilinearFootprint::sample_scaled`]: one rounding.
    #[inline(always)]
    pub fn sample_scaled<WU: WrapMode, WV: WrapMode>(
        footprints: &[u64],
        wu: WU,
        wv: WV,
        tex: &Texture<'_>,
        u: i32,
        v: i32,
        i: u16,
    ) -> u16 {
        if WU::REPEAT && WV::REPEAT {
            let (top, bot, a, b) = Self::gather(footprints, u, v);
            return blend_rows_q8(top, bot, a, b, Some(u32::from(i.min(256))));
        }
        Bilinear::sample_scaled(tex, wu, wv, u, v, i)
    }
}

impl<const LOG2_W: u32, const LOG2_H: u32> TexSampler for BilinearFootprintSized<LOG2_W, LOG2_H> {
    const LOD: bool = false;
    const FILTER: super::Filter = super::Filter::Bilinear;
    const FOOTPRINTS: bool = true;
    const LEVEL0_SIZE: Option<(u32, u32)> = Some((Self::WIDTH, Self::HEIGHT));

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
        Self::sample(t.footprints(), wu, wv, t.base(), u, v)
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
        BilinearFootprint.sample_base(base, wu, wv, u, v)
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
        BilinearFootprint.sample_base_scaled(base, wu, wv, u, v, i)
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
        Self::sample(footprints, wu, wv, base, u, v)
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
        Self::sample_scaled(footprints, wu, wv, base, u, v, i)
    }

    /// On ARMv7E-M with both wraps repeating: the assembly loop of
    /// `footprint_span_dsp` (the same pixels, about 8 % fewer instructions per pixel on
    /// the Cortex-M4F whole sphere than the Rust loop). Elsewhere none.
    #[inline(always)]
    fn lit_span<WU: WrapMode, WV: WrapMode>(
        self,
        _base: &Texture<'_>,
        footprints: &[u64],
        start: &[i32; 3],
        slope: &[i32; 3],
        out: &mut [u16],
    ) -> bool {
        #[cfg(fixel_dsp)]
        if WU::REPEAT && WV::REPEAT {
            return super::footprint_span_dsp::lit_span::<LOG2_W, LOG2_H>(
                footprints, start, slope, out,
            );
        }
        let _ = (footprints, start, slope, out);
        false
    }

    const LIT_SPAN_DEPTH: bool = cfg!(fixel_dsp);

    /// On ARMv7E-M with both wraps repeating: the assembly loop of `footprint_span_dsp`
    /// with the depth test in it (every short span through it: about 4 % of the
    /// Cortex-M4F whole sphere against a depth pass first). Elsewhere none.
    #[allow(clippy::too_many_arguments)]
    #[inline(always)]
    fn lit_span_depth<WU: WrapMode, WV: WrapMode>(
        self,
        _base: &Texture<'_>,
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
            return super::footprint_span_dsp::lit_span_depth::<LOG2_W, LOG2_H>(
                footprints, start, slope, z, dz, out, zrow,
            );
        }
        let _ = (footprints, start, slope, z, dz, out, zrow);
        None
    }
}

/// Refuses a chain whose level 0 is not `size` texels (`(width, height)`): what
/// [`TexSampler::LEVEL0_SIZE`] asks of a binding. (A chain's footprints, when it has any,
/// are one per texel of level 0: [`MipTexture::with_footprints`] checks them.)
pub(crate) fn check_level0_size(chain: &MipTexture<'_>, size: (u32, u32)) -> Result<(), Error> {
    let base = chain.base();
    if (base.width(), base.height()) != size {
        return Err(Error::TextureSizeMismatch {
            width: size.0,
            height: size.1,
        });
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::test_rng::Rng;
    use crate::texture::{write_footprints, ClampToEdge, Repeat};
    use crate::Rgb565;

    /// The pixels of `BilinearFootprint` on textures of the sampler's size, over random
    /// coordinates (negative and far outside included), plain and scaled, and `Bilinear`'s
    /// for a wrap other than repeat.
    fn same_pixels<const LW: u32, const LH: u32>(seed: u64) {
        let (w, h) = (1usize << LW, 1usize << LH);
        let mut rng = Rng(seed);
        let raw: std::vec::Vec<u16> = (0..w * h).map(|_| rng.next() as u16).collect();
        let texels: std::vec::Vec<Rgb565> = raw
            .iter()
            .map(|&c| Rgb565::new((c >> 11) as u8, ((c >> 5) & 63) as u8, (c & 31) as u8))
            .collect();
        let tex = Texture::new(&texels, w as u32, h as u32).unwrap();
        let mut fp = std::vec![0u64; w * h];
        write_footprints(&tex, &mut fp).unwrap();
        type S<const A: u32, const B: u32> = BilinearFootprintSized<A, B>;
        for k in 0..20_000u32 {
            let r = rng.next();
            let (u, v) = ((r as i32) >> (k % 9), ((r >> 32) as i32) >> (k % 11));
            let i = (k % 300) as u16;
            assert_eq!(
                S::<LW, LH>::sample(&fp, Repeat, Repeat, &tex, u, v),
                BilinearFootprint::sample(&tex, &fp, Repeat, Repeat, u, v),
                "{u} {v}"
            );
            assert_eq!(
                S::<LW, LH>::sample_scaled(&fp, Repeat, Repeat, &tex, u, v, i),
                BilinearFootprint::sample_scaled(&tex, &fp, Repeat, Repeat, u, v, i),
                "{u} {v} {i}"
            );
            assert_eq!(
                S::<LW, LH>::sample(&fp, ClampToEdge, Repeat, &tex, u, v),
                Bilinear::sample(&tex, ClampToEdge, Repeat, u, v),
            );
        }
    }

    extern crate std;

    #[test]
    fn the_pixels_are_bilinear_footprints() {
        same_pixels::<0, 0>(1);
        same_pixels::<2, 1>(2);
        same_pixels::<3, 5>(3);
        same_pixels::<6, 6>(4);
        same_pixels::<8, 7>(5);
    }

    #[test]
    fn a_chain_of_another_size_is_refused() {
        static T: [Rgb565; 8] = [Rgb565::new(0, 0, 0); 8];
        static F: [u64; 8] = [0; 8];
        let tex = Texture::from_static(&T, 4, 2);
        let chain = MipTexture::single(tex).with_footprints_static(&F);
        assert_eq!(check_level0_size(&chain, (4, 2)), Ok(()));
        assert_eq!(
            check_level0_size(&chain, (2, 4)),
            Err(Error::TextureSizeMismatch {
                width: 2,
                height: 4
            })
        );
        // Sizes beyond `u32` match no texture, and sampling with them never panics.
        type Huge = BilinearFootprintSized<40, 40>;
        assert_eq!((Huge::WIDTH, Huge::HEIGHT), (0, 0));
        assert_eq!(Huge::sample(&F, Repeat, Repeat, &tex, 0x7FFF_FFFF, -1), 0);
    }
}
