//! Palette textures: 8-bit ([`Index8`]) or 4-bit ([`Index4`]) indices into an RGB565
//! palette, for half or a quarter of the flash of an RGB565 texture.
//!
//! Conventions are [`Texture`](super::Texture)'s: power-of-two sides 1..=4096, row-major,
//! row 0 first, texel centres at `i + 0.5`, sampling coordinates raw I16F16 texel units.
//! Storage: one index per byte ([`Index8`]), or two per byte ([`Index4`]: texel `2k` in the
//! low nibble, `2k + 1` in the high one; a level of one texel takes one byte). The palette
//! is a fixed-size array (`[Rgb565; 256]` or `[Rgb565; 16]`), so no index can fall outside
//! it and a lookup needs no bounds test; the baker pads it.
//!
//! Filtering reads the palette first: [`Nearest`] returns the palette colour of the texel
//! it picks; [`Bilinear`] blends the four palette colours around the sample point with
//! [`Bilinear`]'s own Q8 arithmetic (not the indices: they are not colours). Every filter and
//! wrap therefore gives, bit for bit, what the RGB565 texture the palette expands to gives
//! (the tests check it over random coordinates), and inherits its error budget against the
//! f64 reference (at most 1 LSB per channel for bilinear).
//!
//! Mip chains ([`PaletteMips`]) keep each level's indices, level 0 first, and one palette
//! for every level. `cargo xtask bake-palette` measures a palette per level against it: on
//! the benchmark `T(64, 64)` the shared palette reaches 24.4 dB (4-bit) and 35.6 dB (8-bit)
//! over the chain against the RGB565 source, levels 0-3 within 0.5 dB of a palette of their
//! own; only the 2 x 2 and 1 x 1 levels (5 of 5461 texels) lose more (a palette of their own
//! would be exact), and a palette per level costs 32 B (4-bit) or 512 B (8-bit) per level.
//! Levels are chosen as GL's `*_MIPMAP_NEAREST` chooses them.
//!
//! Cost: the index load (and, at 4 bits, a shift and mask) plus the palette load per texel;
//! nothing for draws that do not sample a palette texture (the code is generic and only
//! instantiated where used).

use embedded_graphics_core::pixelcolor::{IntoStorage, Rgb565};

use super::mip::{full_levels, level_side, MAX_LEVELS};
use super::sample::{blend_q8, blend_q8_scaled, split_half, Bilinear, Nearest, Sampler};
use super::texture::MAX_LOG2_SIZE;
use super::wrap::WrapMode;
use crate::Error;

/// How indices are stored: [`Index8`] or [`Index4`].
pub trait IndexFormat: Copy + Default + core::fmt::Debug + 'static {
    /// Bits per index.
    const BITS: u32;
    /// The palette: `[Rgb565; 1 << BITS]`.
    type Palette: core::fmt::Debug + 'static;
    /// Bytes that hold `n` indices.
    fn bytes(n: usize) -> usize;
    /// The index of texel `idx` (row-major) in `data` (0 past its end: unreachable for a
    /// level built by [`PaletteTexture::new`]).
    fn index(data: &[u8], idx: usize) -> usize;
    /// Raw RGB565 of palette entry `i` (taken modulo the palette's length).
    fn color(p: &Self::Palette, i: usize) -> u16;
}

/// One byte per index, a 256-colour palette.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Index8;

/// Two indices per byte (low nibble first), a 16-colour palette.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Index4;

impl IndexFormat for Index8 {
    const BITS: u32 = 8;
    type Palette = [Rgb565; 256];
    #[inline(always)]
    fn bytes(n: usize) -> usize {
        n
    }
    #[inline(always)]
    fn index(data: &[u8], idx: usize) -> usize {
        data.get(idx).map_or(0, |&b| usize::from(b))
    }
    #[inline(always)]
    fn color(p: &[Rgb565; 256], i: usize) -> u16 {
        p[i & 255].into_storage()
    }
}

impl IndexFormat for Index4 {
    const BITS: u32 = 4;
    type Palette = [Rgb565; 16];
    #[inline(always)]
    fn bytes(n: usize) -> usize {
        n.div_ceil(2)
    }
    #[inline(always)]
    fn index(data: &[u8], idx: usize) -> usize {
        let b = data.get(idx >> 1).map_or(0, |&b| usize::from(b));
        (b >> ((idx & 1) * 4)) & 15
    }
    #[inline(always)]
    fn color(p: &[Rgb565; 16], i: usize) -> u16 {
        p[i & 15].into_storage()
    }
}

/// One level of a palette texture: indices, palette, power-of-two sides.
#[derive(Debug)]
pub struct PaletteTexture<'a, I: IndexFormat> {
    indices: &'a [u8],
    palette: &'a I::Palette,
    log2_width: u8,
    log2_height: u8,
    border: u16,
}

impl<I: IndexFormat> Clone for PaletteTexture<'_, I> {
    fn clone(&self) -> Self {
        *self
    }
}

impl<I: IndexFormat> Copy for PaletteTexture<'_, I> {}

/// The log2 of a side, or the error for a side that is zero, above 4096 or not a power of
/// two.
fn log2_side(s: u32) -> Result<u8, Error> {
    if s == 0 || s > 1 << MAX_LOG2_SIZE {
        return Err(Error::BadSize(s));
    }
    if !s.is_power_of_two() {
        return Err(Error::NotPowerOfTwo(s));
    }
    Ok(s.trailing_zeros() as u8)
}

impl<'a, I: IndexFormat> PaletteTexture<'a, I> {
    /// A `width x height` level: `indices` holds exactly `I::bytes(width * height)` bytes.
    ///
    /// # Errors
    /// [`Error::BadSize`] for a side of 0 or above 4096, [`Error::NotPowerOfTwo`],
    /// [`Error::WrongLength`] when `indices` has another length.
    pub fn new(
        indices: &'a [u8],
        palette: &'a I::Palette,
        width: u32,
        height: u32,
    ) -> Result<Self, Error> {
        let (lw, lh) = (log2_side(width)?, log2_side(height)?);
        let expected = I::bytes((width * height) as usize);
        if indices.len() != expected {
            return Err(Error::WrongLength {
                expected,
                actual: indices.len(),
            });
        }
        Ok(PaletteTexture {
            indices,
            palette,
            log2_width: lw,
            log2_height: lh,
            border: 0,
        })
    }

    /// Sets the border colour used by [`ClampToBorder`](super::ClampToBorder) (default
    /// black).
    #[must_use]
    pub fn with_border(mut self, border: Rgb565) -> Self {
        self.border = border.into_storage();
        self
    }

    /// Width in texels.
    #[inline(always)]
    pub fn width(&self) -> u32 {
        1 << self.log2_width
    }

    /// Height in texels.
    #[inline(always)]
    pub fn height(&self) -> u32 {
        1 << self.log2_height
    }

    /// `log2` of the width.
    #[inline(always)]
    pub fn log2_width(&self) -> u32 {
        u32::from(self.log2_width)
    }

    /// `log2` of the height.
    #[inline(always)]
    pub fn log2_height(&self) -> u32 {
        u32::from(self.log2_height)
    }

    /// The palette.
    pub fn palette(&self) -> &'a I::Palette {
        self.palette
    }

    /// The packed indices.
    pub fn indices(&self) -> &'a [u8] {
        self.indices
    }

    /// Raw RGB565 of the texel at row-major index `idx`, taken modulo the texel count (a
    /// power of two). Never panics.
    #[inline(always)]
    pub fn texel_at(&self, idx: u32) -> u16 {
        let n = 1usize << (self.log2_width + self.log2_height);
        I::color(self.palette, I::index(self.indices, idx as usize & (n - 1)))
    }

    /// Raw RGB565 of texel `(i, j)` (column, row), indices masked to the sides.
    #[inline(always)]
    pub fn texel_raw(&self, i: u32, j: u32) -> u16 {
        let i = i & (self.width() - 1);
        let j = j & (self.height() - 1);
        self.texel_at((j << self.log2_width) | i)
    }

    /// Raw texel at wrapped indices, or the border when either is `None`.
    #[inline(always)]
    fn fetch(&self, i: Option<u32>, j: Option<u32>) -> u16 {
        match (i, j) {
            (Some(i), Some(j)) => self.texel_raw(i, j),
            _ => self.border,
        }
    }

    /// The four palette colours around `(u, v)` and the Q8 weights, exactly as
    /// [`Bilinear`] gathers an RGB565 texture's texels.
    #[inline(always)]
    fn gather<WU: WrapMode, WV: WrapMode>(
        &self,
        wu: WU,
        wv: WV,
        u: i32,
        v: i32,
    ) -> ([u16; 4], u32, u32) {
        if WU::REPEAT && WV::REPEAT {
            let tu = u.wrapping_sub(super::sample::REPEAT_SPLIT);
            let tv = v.wrapping_sub(super::sample::REPEAT_SPLIT);
            let (a, b) = ((tu as u32 >> 8) & 0xFF, (tv as u32 >> 8) & 0xFF);
            let mw = self.width() - 1;
            let x0 = (tu >> 16) as u32 & mw;
            let x1 = ((tu >> 16) as u32).wrapping_add(1) & mw;
            let r0 = ((tv >> 16) as u32) << self.log2_width;
            let r1 = r0.wrapping_add(self.width());
            let c = [
                self.texel_at(r0 | x0),
                self.texel_at(r0 | x1),
                self.texel_at(r1 | x0),
                self.texel_at(r1 | x1),
            ];
            return (c, a, b);
        }
        let (i0, fu) = split_half(u);
        let (j0, fv) = split_half(v);
        let (lw, lh) = (self.log2_width(), self.log2_height());
        let (i0w, i1w) = (wu.wrap(i0, lw), wu.wrap(i0 + 1, lw));
        let (j0w, j1w) = (wv.wrap(j0, lh), wv.wrap(j0 + 1, lh));
        let c = [
            self.fetch(i0w, j0w),
            self.fetch(i1w, j0w),
            self.fetch(i0w, j1w),
            self.fetch(i1w, j1w),
        ];
        (c, (fu + 0x80) >> 8, (fv + 0x80) >> 8)
    }

    /// Samples at raw I16F16 texel coordinates with filter `F` ([`Nearest`] or
    /// [`Bilinear`]) and wraps `wu`, `wv`. Raw RGB565; never panics.
    #[inline(always)]
    pub fn sample<F: PaletteFilter, WU: WrapMode, WV: WrapMode>(
        &self,
        wu: WU,
        wv: WV,
        u: i32,
        v: i32,
    ) -> u16 {
        F::sample_palette(self, wu, wv, u, v)
    }

    /// [`PaletteTexture::sample`] times intensity `i` (Q8, `0..=256`; larger is 256), as
    /// [`Sampler::sample_scaled`] does for RGB565 textures.
    #[inline(always)]
    pub fn sample_scaled<F: PaletteFilter, WU: WrapMode, WV: WrapMode>(
        &self,
        wu: WU,
        wv: WV,
        u: i32,
        v: i32,
        i: u16,
    ) -> u16 {
        F::sample_palette_scaled(self, wu, wv, u, v, i)
    }
}

/// A filter that samples palette textures: [`Nearest`] and [`Bilinear`].
pub trait PaletteFilter: Sampler {
    /// The filtered colour at `(u, v)`, raw RGB565.
    fn sample_palette<I: IndexFormat, WU: WrapMode, WV: WrapMode>(
        t: &PaletteTexture<'_, I>,
        wu: WU,
        wv: WV,
        u: i32,
        v: i32,
    ) -> u16;

    /// The filtered colour times intensity `i` (Q8, `0..=256`).
    #[inline(always)]
    fn sample_palette_scaled<I: IndexFormat, WU: WrapMode, WV: WrapMode>(
        t: &PaletteTexture<'_, I>,
        wu: WU,
        wv: WV,
        u: i32,
        v: i32,
        i: u16,
    ) -> u16 {
        crate::color::modulate_scalar(Self::sample_palette(t, wu, wv, u, v), i)
    }
}

impl PaletteFilter for Nearest {
    #[inline(always)]
    fn sample_palette<I: IndexFormat, WU: WrapMode, WV: WrapMode>(
        t: &PaletteTexture<'_, I>,
        wu: WU,
        wv: WV,
        u: i32,
        v: i32,
    ) -> u16 {
        if WU::REPEAT && WV::REPEAT {
            let col = (u >> 16) as u32 & (t.width() - 1);
            let row = ((v >> 16) as u32 & (t.height() - 1)) << t.log2_width;
            return t.texel_at(row | col);
        }
        t.fetch(
            wu.wrap(u >> 16, t.log2_width()),
            wv.wrap(v >> 16, t.log2_height()),
        )
    }
}

impl PaletteFilter for Bilinear {
    #[inline(always)]
    fn sample_palette<I: IndexFormat, WU: WrapMode, WV: WrapMode>(
        t: &PaletteTexture<'_, I>,
        wu: WU,
        wv: WV,
        u: i32,
        v: i32,
    ) -> u16 {
        let (c, a, b) = t.gather(wu, wv, u, v);
        blend_q8(c, a, b)
    }

    #[inline(always)]
    fn sample_palette_scaled<I: IndexFormat, WU: WrapMode, WV: WrapMode>(
        t: &PaletteTexture<'_, I>,
        wu: WU,
        wv: WV,
        u: i32,
        v: i32,
        i: u16,
    ) -> u16 {
        let (c, a, b) = t.gather(wu, wv, u, v);
        blend_q8_scaled(c, a, b, u32::from(i.min(256)))
    }
}

/// A mip chain of palette textures: every level's indices back to back (level 0 first,
/// level `k` `max(1, w >> k) x max(1, h >> k)`, each starting on a byte) and one palette.
#[derive(Clone, Copy, Debug)]
pub struct PaletteMips<'a, I: IndexFormat> {
    levels: [Option<PaletteTexture<'a, I>>; MAX_LEVELS],
    count: u8,
}

/// Bytes of a chain of `levels` levels from `width x height` in format `I`.
pub fn palette_chain_bytes<I: IndexFormat>(width: u32, height: u32, levels: u32) -> usize {
    (0..levels)
        .map(|k| I::bytes((level_side(width, k) * level_side(height, k)) as usize))
        .sum()
}

impl<'a, I: IndexFormat> PaletteMips<'a, I> {
    /// The chain of `levels` levels from a `width x height` level 0 in `indices` (exactly
    /// [`palette_chain_bytes`] long), all read through `palette`.
    ///
    /// # Errors
    /// [`Error::BadSize`] for a side of 0 or above 4096, or for zero levels or more than the
    /// full chain has; [`Error::NotPowerOfTwo`]; [`Error::WrongLength`] when `indices` has
    /// another length.
    pub fn new(
        indices: &'a [u8],
        palette: &'a I::Palette,
        width: u32,
        height: u32,
        levels: u32,
    ) -> Result<Self, Error> {
        log2_side(width)?;
        log2_side(height)?;
        if levels == 0 || levels > full_levels(width, height) || levels as usize > MAX_LEVELS {
            return Err(Error::BadSize(levels));
        }
        let expected = palette_chain_bytes::<I>(width, height, levels);
        if indices.len() != expected {
            return Err(Error::WrongLength {
                expected,
                actual: indices.len(),
            });
        }
        let mut out = PaletteMips {
            levels: [None; MAX_LEVELS],
            count: levels as u8,
        };
        let mut off = 0;
        for k in 0..levels {
            let (w, h) = (level_side(width, k), level_side(height, k));
            let n = I::bytes((w * h) as usize);
            let slice = indices.get(off..off + n).unwrap_or(&[]);
            out.levels[k as usize] = Some(PaletteTexture::new(slice, palette, w, h)?);
            off += n;
        }
        Ok(out)
    }

    /// Number of levels.
    pub fn levels(&self) -> u32 {
        u32::from(self.count)
    }

    /// Level `k` (clamped to the last).
    #[inline(always)]
    pub fn level(&self, k: u32) -> Option<&PaletteTexture<'a, I>> {
        let k = (k as usize).min(usize::from(self.count).saturating_sub(1));
        self.levels.get(k).and_then(Option::as_ref)
    }

    /// Samples with filter `F` within the level GL's `*_MIPMAP_NEAREST` picks for level of
    /// detail `lambda` (Q8.8; `lambda <= 0` magnifies level 0 with `F`): the same level and
    /// coordinates as [`MipTexture`](super::MipTexture) with
    /// [`NearestMipmapNearest`](super::NearestMipmapNearest) or
    /// [`LinearMipmapNearest`](super::LinearMipmapNearest). `(u, v)` are level-0 texel
    /// units (raw I16F16). Raw RGB565; never panics.
    #[inline(always)]
    pub fn sample_mip<F: PaletteFilter, WU: WrapMode, WV: WrapMode>(
        &self,
        wu: WU,
        wv: WV,
        u: i32,
        v: i32,
        lambda: i32,
    ) -> u16 {
        let last = self.levels().saturating_sub(1);
        let d = if lambda <= 128 {
            0
        } else {
            ((lambda as u32 + 127) >> 8).min(last)
        };
        let (Some(base), Some(l)) = (self.level(0), self.level(d)) else {
            return 0;
        };
        let lu = u >> (base.log2_width() - l.log2_width());
        let lv = v >> (base.log2_height() - l.log2_height());
        F::sample_palette(l, wu, wv, lu, lv)
    }
}

#[cfg(test)]
mod tests;
