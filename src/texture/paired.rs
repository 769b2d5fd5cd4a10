//! The paired texel layout and [`BilinearPaired`], the bilinear filter that reads it.
//!
//! Layout: word `i` of a `&[u32]` (one word per texel, row-major like the texels) holds
//! texel `i` in its low half and its right neighbour in its high half, the row's first
//! texel at the row's end (repeat wrapping along `u`):
//! `pairs[j * width + i] = c(i, j) | c((i + 1) % width, j) << 16`.
//!
//! A bilinear sample with repeat wrapping needs the texels at `(i0, j0)`, `(i0 + 1, j0)`,
//! `(i0, j0 + 1)`, `(i0 + 1, j0 + 1)`. [`Bilinear`] loads the four and packs each row's two
//! into one word for its two-texels-per-multiply sums (see `sample.rs`). [`BilinearPaired`]
//! loads those two words as they are stored: two loads instead of four, no right-hand column
//! to wrap and no packing. The sums, weights and roundings are [`Bilinear`]'s, so the pixels
//! are the same bit for bit (tested); only the cost changes.
//!
//! Cost: the pairs take 4 bytes per texel beside the texels' 2 (a 128 x 128 texture: 64 KiB
//! of pairs beside 32 KiB of texels). Build them once: [`pair_texels`] in a `static` (flash,
//! at compile time), or [`write_pairs`] into caller storage (RAM, at run time).
//!
//! Other wraps (clamp, mirror, border) read the plain texels as [`Bilinear`] does, since
//! their right neighbour at the row's end is not the row's first texel.
//!
//! ```
//! use fixel::texture::{pair_texels, BilinearPaired, Repeat, Sampler, Texture};
//! use fixel::Rgb565;
//!
//! const RAW: [u16; 4] = [0xF800, 0x07E0, 0x001F, 0xFFFF];
//! static TEXELS: [Rgb565; 4] = [
//!     Rgb565::new(31, 0, 0),
//!     Rgb565::new(0, 63, 0),
//!     Rgb565::new(0, 0, 31),
//!     Rgb565::new(31, 63, 31),
//! ];
//! static PAIRS: [u32; 4] = pair_texels(&RAW, 2);
//! static TEX: Texture<'static> = Texture::from_static(&TEXELS, 2, 2).with_pairs_static(&PAIRS);
//!
//! // Texel (1, 0)'s right neighbour wraps to (0, 0).
//! assert_eq!(PAIRS[1], 0x07E0 | 0xF800 << 16);
//! // The centre of texel (0, 0) is texel (0, 0), whatever the layout.
//! let c = BilinearPaired::sample(&TEX, Repeat, Repeat, 0x8000, 0x8000);
//! assert_eq!(c, 0xF800);
//! ```

use embedded_graphics_core::pixelcolor::IntoStorage;

use super::sample::{blend_rows_q8, repeat_rows, Bilinear, Sampler};
use super::texture::Texture;
use super::wrap::WrapMode;
use crate::Error;

/// Bilinear filtering ([`Bilinear`]'s arithmetic and pixels) that reads a texture's paired
/// layout ([`Texture::with_pairs`]) when both wraps repeat: two words per sample.
///
/// Bindings and draws refuse a texture without pairs ([`Error::BadMode`]), and a mipmapped
/// sampler built on it (the levels past 0 have no pairs). Its [`Sampler::FILTER`] is
/// [`Filter::Bilinear`](super::Filter::Bilinear).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct BilinearPaired;

impl BilinearPaired {
    /// The two row words and Q8 weights of a repeat-wrapped sample at `(u, v)`.
    #[inline(always)]
    fn gather(tex: &Texture<'_>, u: i32, v: i32) -> (u32, u32, u32, u32) {
        let (i0, r0, r1, a, b) = repeat_rows(tex, u, v);
        let x0 = i0 & (tex.width() - 1);
        (tex.pair_at(r0 | x0), tex.pair_at(r1 | x0), a, b)
    }
}

impl Sampler for BilinearPaired {
    const FILTER: super::Filter = super::Filter::Bilinear;
    const PAIRED: bool = true;

    #[inline(always)]
    fn sample<WU: WrapMode, WV: WrapMode>(
        tex: &Texture<'_>,
        wu: WU,
        wv: WV,
        u: i32,
        v: i32,
    ) -> u16 {
        if WU::REPEAT && WV::REPEAT {
            let (top, bot, a, b) = Self::gather(tex, u, v);
            return blend_rows_q8(top, bot, a, b, None);
        }
        Bilinear::sample(tex, wu, wv, u, v)
    }

    #[inline(always)]
    fn sample_scaled<WU: WrapMode, WV: WrapMode>(
        tex: &Texture<'_>,
        wu: WU,
        wv: WV,
        u: i32,
        v: i32,
        i: u16,
    ) -> u16 {
        if WU::REPEAT && WV::REPEAT {
            let (top, bot, a, b) = Self::gather(tex, u, v);
            return blend_rows_q8(top, bot, a, b, Some(u32::from(i.min(256))));
        }
        Bilinear::sample_scaled(tex, wu, wv, u, v, i)
    }
}

/// Index of the right neighbour of texel `i` in rows of `width` (a power of two) texels,
/// wrapping to the row's first texel.
#[inline(always)]
const fn right_of(i: usize, width: usize) -> usize {
    (i & !(width - 1)) | ((i + 1) & (width - 1))
}

/// The paired layout of raw RGB565 texels in rows of `width`, at compile time:
/// `static PAIRS: [u32; N] = pair_texels(&RAW, W);` puts it in flash.
///
/// # Panics
/// If `width` is not a power of two dividing `N` (a compile error in a `static`).
pub const fn pair_texels<const N: usize>(raw: &[u16; N], width: u32) -> [u32; N] {
    let w = width as usize;
    assert!(
        width.is_power_of_two() && N & (w - 1) == 0,
        "width must be a power of two dividing the texel count"
    );
    let mut out = [0u32; N];
    let mut i = 0;
    while i < N {
        out[i] = raw[i] as u32 | (raw[right_of(i, w)] as u32) << 16;
        i += 1;
    }
    out
}

/// Writes `tex`'s paired layout into `out` (one word per texel), at run time.
///
/// # Errors
/// [`Error::WrongLength`] if `out.len() != width * height`.
pub fn write_pairs(tex: &Texture<'_>, out: &mut [u32]) -> Result<(), Error> {
    let texels = tex.texels();
    if out.len() != texels.len() {
        return Err(Error::WrongLength {
            expected: texels.len(),
            actual: out.len(),
        });
    }
    let w = tex.width() as usize;
    for (i, word) in out.iter_mut().enumerate() {
        *word = pair_word(tex, i, w);
    }
    Ok(())
}

/// Word `i` of `tex`'s paired layout (`i < texels.len()`, else 0).
fn pair_word(tex: &Texture<'_>, i: usize, width: usize) -> u32 {
    let texels = tex.texels();
    let at = |k: usize| texels.get(k).map_or(0, |c| u32::from(c.into_storage()));
    at(i) | at(right_of(i, width)) << 16
}

/// Checks that `pairs` is `tex`'s paired layout ([`Texture::with_pairs`]).
pub(crate) fn check_pairs(tex: &Texture<'_>, pairs: &[u32]) -> Result<(), Error> {
    if pairs.len() != tex.texels().len() {
        return Err(Error::WrongLength {
            expected: tex.texels().len(),
            actual: pairs.len(),
        });
    }
    let w = tex.width() as usize;
    match (0..pairs.len()).find(|&i| pairs[i] != pair_word(tex, i, w)) {
        Some(index) => Err(Error::PairsMismatch { index }),
        None => Ok(()),
    }
}

#[cfg(test)]
mod tests {
    extern crate std;
    use super::*;
    use crate::texture::wrap::{ClampToBorder, ClampToEdge, MirroredRepeat, Repeat};
    use embedded_graphics_core::pixelcolor::raw::RawU16;
    use embedded_graphics_core::pixelcolor::Rgb565;
    use std::vec::Vec;

    struct Rng(u32);
    impl Rng {
        fn next(&mut self) -> u32 {
            self.0 ^= self.0 << 13;
            self.0 ^= self.0 >> 17;
            self.0 ^= self.0 << 5;
            self.0
        }
    }

    fn texels(raw: &[u16]) -> Vec<Rgb565> {
        raw.iter().map(|&r| Rgb565::from(RawU16::new(r))).collect()
    }

    /// Every wrap pair, every size up to 16 x 16 (including 1-texel rows and columns), any
    /// coordinates: the same pixels as `Bilinear`, plain and scaled.
    #[test]
    fn paired_samples_equal_bilinear() {
        let mut rng = Rng(0x1234_5678);
        for (lw, lh) in [(0, 0), (0, 3), (3, 0), (1, 1), (2, 3), (4, 4), (4, 1)] {
            let (w, h) = (1u32 << lw, 1u32 << lh);
            let raw: Vec<u16> = (0..w * h).map(|_| rng.next() as u16).collect();
            let t = texels(&raw);
            let plain = Texture::new(&t, w, h).unwrap();
            let mut pairs = std::vec![0u32; (w * h) as usize];
            write_pairs(&plain, &mut pairs).unwrap();
            let tex = plain.with_pairs(&pairs).unwrap();
            for _ in 0..4000 {
                // Mostly near the texture, sometimes anywhere in i32.
                let (u, v) = if rng.next() % 8 == 0 {
                    (rng.next() as i32, rng.next() as i32)
                } else {
                    (
                        (rng.next() % (w << 18)) as i32 - (w << 17) as i32,
                        (rng.next() % (h << 18)) as i32 - (h << 17) as i32,
                    )
                };
                let i = (rng.next() % 300) as u16;
                macro_rules! same {
                    ($wu:expr, $wv:expr) => {
                        assert_eq!(
                            BilinearPaired::sample(&tex, $wu, $wv, u, v),
                            Bilinear::sample(&plain, $wu, $wv, u, v),
                            "{w}x{h} at ({u}, {v})"
                        );
                        assert_eq!(
                            BilinearPaired::sample_scaled(&tex, $wu, $wv, u, v, i),
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
        const PAIRS: [u32; 8] = pair_texels(&RAW, 4);
        assert_eq!(PAIRS[0], 1 | 2 << 16);
        assert_eq!(PAIRS[3], 4 | 1 << 16);
        assert_eq!(PAIRS[7], 8 | 5 << 16);
        let t = texels(&RAW);
        let tex = Texture::new(&t, 4, 2).unwrap();
        let mut out = [0u32; 8];
        write_pairs(&tex, &mut out).unwrap();
        assert_eq!(out, PAIRS);
        assert_eq!(pair_texels(&[9u16], 1), [9 | 9 << 16]);
    }

    #[test]
    fn wrong_pairs_are_refused() {
        let t = texels(&[1, 2, 3, 4]);
        let tex = Texture::new(&t, 2, 2).unwrap();
        let mut out = [0u32; 3];
        assert_eq!(
            write_pairs(&tex, &mut out),
            Err(Error::WrongLength {
                expected: 4,
                actual: 3
            })
        );
        assert_eq!(
            tex.with_pairs(&[0; 5]).unwrap_err(),
            Error::WrongLength {
                expected: 4,
                actual: 5
            }
        );
        let mut good = [0u32; 4];
        write_pairs(&tex, &mut good).unwrap();
        assert!(tex.with_pairs(&good).is_ok());
        let mut bad = good;
        bad[2] ^= 1 << 16;
        assert_eq!(
            tex.with_pairs(&bad).unwrap_err(),
            Error::PairsMismatch { index: 2 }
        );
        // Pairs of the same texels in another width are refused too.
        let other = pair_texels(&[1, 2, 3, 4], 4);
        assert_eq!(
            tex.with_pairs(&other).unwrap_err(),
            Error::PairsMismatch { index: 1 }
        );
    }

    /// A texture without pairs never panics under the paired sampler (its words read as 0;
    /// bindings refuse it before a draw gets there).
    #[test]
    fn missing_pairs_never_panic() {
        let t = texels(&[0xFFFF; 4]);
        let tex = Texture::new(&t, 2, 2).unwrap();
        assert_eq!(
            BilinearPaired::sample(&tex, Repeat, Repeat, 0x8000, 0x8000),
            0
        );
        assert_eq!(
            BilinearPaired::sample(&tex, ClampToEdge, ClampToEdge, 0x8000, 0x8000),
            0xFFFF
        );
    }

    /// Draws and bindings refuse the paired filter on a texture without pairs, and inside a
    /// mipmapped sampler, with errors that say so; with pairs they accept it.
    #[test]
    fn bindings_refuse_missing_pairs() {
        use crate::geometry::{Cull, Viewport};
        use crate::pipeline::{Affine, Draw, NoDepth, Pipeline, Replace};
        use crate::shading::TexBinding;
        use crate::texture::{Lod, MipTexture, Mipmapped};
        type Paired = Pipeline<Affine, BilinearPaired, Repeat, Repeat, Replace, NoDepth>;
        let t = texels(&[1, 2, 3, 4]);
        let plain = Texture::new(&t, 2, 2).unwrap();
        let vp = Viewport::new(0, 0, 8, 8).unwrap();
        let needs =
            Error::BadMode("BilinearPaired needs a texture with pairs (Texture::with_pairs)");
        assert_eq!(
            Draw::<Rgb565>::new::<Paired>(Some(plain), vp, Cull::None).unwrap_err(),
            needs
        );
        let chain = MipTexture::single(plain);
        assert_eq!(
            TexBinding::new(&chain, BilinearPaired, Repeat, Repeat, Lod::default()).unwrap_err(),
            needs
        );
        let mut pairs = [0u32; 4];
        write_pairs(&plain, &mut pairs).unwrap();
        let tex = plain.with_pairs(&pairs).unwrap();
        assert!(Draw::<Rgb565>::new::<Paired>(Some(tex), vp, Cull::None).is_ok());
        let chain = MipTexture::single(tex);
        assert!(TexBinding::new(&chain, BilinearPaired, Repeat, Repeat, Lod::default()).is_ok());
        let mip = Mipmapped::<BilinearPaired, Bilinear, true>::default();
        assert!(matches!(
            TexBinding::new(&chain, mip, Repeat, Repeat, Lod::default()),
            Err(Error::BadMode(m)) if m.contains("mipmapped")
        ));
    }
}
