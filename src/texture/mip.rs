//! Mipmaps: a power-of-two pyramid of a texture (Williams), level selection from the
//! screen-space derivatives of the texel coordinates (Heckbert), and GL's minification
//! filters.
//!
//! # Storage
//! A chain is one contiguous, row-major `&[Rgb565]`: level 0 (`w x h`), then level 1
//! (`max(1, w/2) x max(1, h/2)`), and so on, down to 1 x 1 or to a chosen number of levels:
//! at most 4/3 of the base size. [`MipTexture`] views each level as a [`Texture`]. Chains are
//! built at compile time (`cargo xtask bake`) or at run time by [`generate_mips`] into
//! caller-provided storage with a 2 x 2 box filter (per channel `(a + b + c + d + 2) >> 2`;
//! where a side is already 1 the two texels along the other side are averaged,
//! `(a + b + 1) >> 1`).
//!
//! # Level of detail (GL ES 3.0 §3.8.11)
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

use super::sample::{Bilinear, BilinearFast, Filter, Nearest, Sampler};
use super::texture::{Texture, MAX_LOG2_SIZE};
use super::wrap::WrapMode;
use crate::Error;

/// Most levels a chain can have (4096 down to 1).
pub const MAX_LEVELS: usize = MAX_LOG2_SIZE as usize + 1;

/// Number of texels in a chain of `levels` levels from a `width x height` base.
pub const fn chain_len(width: u32, height: u32, levels: u32) -> usize {
    let mut n = 0usize;
    let mut k = 0;
    while k < levels {
        n += level_side(width, k) as usize * level_side(height, k) as usize;
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
        super::footprint::check_footprints(self.base(), footprints)?;
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
    /// `width x height` base. Errors: the base's [`Texture::new`] errors,
    /// [`Error::BadSize`] for zero levels or more than the full chain has,
    /// [`Error::WrongLength`] when `chain` is not exactly [`chain_len`] long.
    pub fn new(chain: &'a [Rgb565], width: u32, height: u32, levels: u32) -> Result<Self, Error> {
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
            &chain[..(width * height) as usize],
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

/// Fills levels `1..levels` of `chain` from level 0 (which the caller has written) with a
/// 2 x 2 box filter. Same layout and errors as [`MipTexture::new`].
pub fn generate_mips(
    chain: &mut [Rgb565],
    width: u32,
    height: u32,
    levels: u32,
) -> Result<(), Error> {
    // Validates sizes and the length.
    MipTexture::new(chain, width, height, levels)?;
    let mut src_off = 0usize;
    for k in 1..levels {
        let (sw, sh) = (level_side(width, k - 1), level_side(height, k - 1));
        let (dw, dh) = (level_side(width, k), level_side(height, k));
        let dst_off = src_off + (sw * sh) as usize;
        let (src_part, dst_part) = chain.split_at_mut(dst_off);
        let src = &src_part[src_off..];
        for j in 0..dh {
            for i in 0..dw {
                let (x0, y0) = (2 * i, 2 * j);
                let (x1, y1) = ((x0 + 1).min(sw - 1), (y0 + 1).min(sh - 1));
                let at = |x: u32, y: u32| {
                    src.get((y * sw + x) as usize)
                        .map_or(0, |c| c.into_storage())
                };
                let texels = [at(x0, y0), at(x1, y0), at(x0, y1), at(x1, y1)];
                let n = if sw == 1 || sh == 1 { 2 } else { 4 };
                let avg = |shift: u32, mask: u16| -> u16 {
                    let sum: u32 = if n == 4 {
                        texels.iter().map(|t| u32::from((t >> shift) & mask)).sum()
                    } else {
                        // One side is 1: x1 == x0 or y1 == y0, so texels[0] and texels[3]
                        // are the two distinct texels.
                        2 * (u32::from((texels[0] >> shift) & mask)
                            + u32::from((texels[3] >> shift) & mask))
                    };
                    ((sum + 2) >> 2) as u16 & mask
                };
                let c = (avg(11, 0x1F) << 11) | (avg(5, 0x3F) << 5) | avg(0, 0x1F);
                if let Some(d) = dst_part.get_mut((j * dw + i) as usize) {
                    *d = Rgb565::from(RawU16::new(c));
                }
            }
        }
        src_off = dst_off;
    }
    Ok(())
}

/// Filtering between mip levels.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum MipFilter {
    /// No mipmapping: the minification filter samples level 0.
    #[default]
    None,
    /// Nearest level (`*_MIPMAP_NEAREST`).
    Nearest,
    /// Blend of the two nearest levels (`*_MIPMAP_LINEAR`).
    Linear,
}

/// Level-of-detail controls.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Lod {
    /// Added to `lambda`, Q8.8 (256 = one level).
    pub bias: i32,
    /// Smallest `lambda` after the bias, Q8.8.
    pub min: i32,
    /// Largest `lambda` after the bias, Q8.8.
    pub max: i32,
    /// Where `lambda` is computed.
    pub granularity: LodGranularity,
}

/// Bias 0, no clamps (`min`/`max` at ±1000 levels, beyond any chain) and LOD computed at
/// every pixel ([`LodGranularity::Pixel`]), as GL's defaults.
impl Default for Lod {
    fn default() -> Self {
        Lod {
            bias: 0,
            min: -1000 * 256,
            max: 1000 * 256,
            granularity: LodGranularity::Pixel,
        }
    }
}

/// How often the level of detail is computed.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum LodGranularity {
    /// At every pixel (exact derivatives; the most expensive).
    #[default]
    Pixel,
    /// Once per span, at its first pixel.
    Span,
    /// Once per triangle, at the reference pixel (exact for affine mappings, where the
    /// derivatives are constant).
    Triangle,
}

/// A sampler for the span loop: plain samplers ignore the level of detail, mipmapped ones
/// use it.
pub trait TexSampler: Copy + Default + core::fmt::Debug {
    /// True when the sampler needs `lambda`.
    const LOD: bool;
    /// Magnification filter (for reports).
    const FILTER: Filter;
    /// True when the sampler reads level 0's footprints ([`MipTexture::with_footprints`]):
    /// bindings and draws refuse a chain without them.
    const FOOTPRINTS: bool = false;
    /// Samples at level-0 texel coordinates `u, v` (I16F16 bits) with `lambda` (Q8.8,
    /// already biased and clamped; ignored unless `LOD`).
    fn sample_mip<WU: WrapMode, WV: WrapMode>(
        self,
        tex: &MipTexture<'_>,
        wu: WU,
        wv: WV,
        u: i32,
        v: i32,
        lambda: i32,
    ) -> u16;

    /// [`TexSampler::sample_base`] times intensity `i` (Q8, `0..=256`). The default
    /// modulates the sample; the plain samplers use [`Sampler::sample_scaled`].
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
        crate::color::modulate_scalar(self.sample_base(base, wu, wv, u, v), i)
    }

    /// Samples level 0 only (what the span loop calls when `LOD` is false, with the level
    /// copied into a local so its fields stay in registers).
    fn sample_base<WU: WrapMode, WV: WrapMode>(
        self,
        base: &Texture<'_>,
        wu: WU,
        wv: WV,
        u: i32,
        v: i32,
    ) -> u16;

    /// [`TexSampler::sample_base`] with level 0's footprints at hand (empty unless
    /// [`TexSampler::FOOTPRINTS`]; see [`MipTexture::with_footprints`]). The default ignores
    /// them; [`BilinearFootprint`](super::BilinearFootprint) reads them.
    #[inline(always)]
    fn sample_level0<WU: WrapMode, WV: WrapMode>(
        self,
        base: &Texture<'_>,
        _footprints: &[u64],
        wu: WU,
        wv: WV,
        u: i32,
        v: i32,
    ) -> u16 {
        self.sample_base(base, wu, wv, u, v)
    }

    /// [`TexSampler::sample_base_scaled`] with level 0's footprints at hand (see
    /// [`TexSampler::sample_level0`]).
    #[allow(clippy::too_many_arguments)]
    #[inline(always)]
    fn sample_level0_scaled<WU: WrapMode, WV: WrapMode>(
        self,
        base: &Texture<'_>,
        _footprints: &[u64],
        wu: WU,
        wv: WV,
        u: i32,
        v: i32,
        i: u16,
    ) -> u16 {
        self.sample_base_scaled(base, wu, wv, u, v, i)
    }
}

/// The plain samplers: no level of detail, always level 0.
/// (`sample_base_scaled` goes through [`Sampler::sample_scaled`], fused for bilinear.)
macro_rules! plain_sampler {
    ($($t:ident => $f:expr),* $(,)?) => {$(
        impl TexSampler for $t {
            const LOD: bool = false;
            const FILTER: Filter = $f;
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
                $t::sample(t.base(), wu, wv, u, v)
            }
            #[inline(always)]
            fn sample_base<WU: WrapMode, WV: WrapMode>(
                self,
                base: &Texture<'_>,
                wu: WU,
                wv: WV,
                u: i32,
                v: i32,
            ) -> u16 {
                $t::sample(base, wu, wv, u, v)
            }
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
                $t::sample_scaled(base, wu, wv, u, v, i)
            }
        }
    )*};
}
plain_sampler!(
    Nearest => Filter::Nearest,
    Bilinear => Filter::Bilinear,
    BilinearFast => Filter::Bilinear,
);

/// Blends two RGB565 colours, `f` in `0..=256` (weight of `b`), per channel, rounded.
#[inline(always)]
pub fn lerp565(a: u16, b: u16, f: u32) -> u16 {
    let f = f.min(256);
    let spread = |c: u16| -> (u32, u32) {
        let c = u32::from(c);
        (((c & 0xF800) << 5) | (c & 0x1F), (c >> 5) & 0x3F)
    };
    let ((arb, ag), (brb, bg)) = (spread(a), spread(b));
    let rb = (arb * (256 - f) + brb * f + 0x0080_0080) >> 8;
    let g = (ag * (256 - f) + bg * f + 0x80) >> 8;
    (((rb >> 5) & 0xF800) | ((g & 0x3F) << 5) | (rb & 0x1F)) as u16
}

/// Level-0 coordinates scaled to level `k` (sides of level k may stop at 1).
#[inline(always)]
fn at_level(t: &MipTexture<'_>, k: u32, u: i32, v: i32) -> (i32, i32) {
    let b = t.base();
    let l = t.level(k);
    (
        u >> (b.log2_width() - l.log2_width()),
        v >> (b.log2_height() - l.log2_height()),
    )
}

#[inline(always)]
fn sample_level<S: Sampler, WU: WrapMode, WV: WrapMode>(
    t: &MipTexture<'_>,
    k: u32,
    wu: WU,
    wv: WV,
    u: i32,
    v: i32,
) -> u16 {
    let (lu, lv) = at_level(t, k, u, v);
    S::sample(t.level(k), wu, wv, lu, lv)
}

/// GL's mipmapped minification with magnification filter `Mag`: `Min` filters within a
/// level, `MIP` between levels. Type aliases name GL's four modes.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Mipmapped<Min, Mag, const LINEAR_BETWEEN: bool>(core::marker::PhantomData<(Min, Mag)>);

/// `GL_NEAREST_MIPMAP_NEAREST` (magnification nearest).
pub type NearestMipmapNearest = Mipmapped<Nearest, Nearest, false>;
/// `GL_LINEAR_MIPMAP_NEAREST` (magnification linear).
pub type LinearMipmapNearest = Mipmapped<Bilinear, Bilinear, false>;
/// `GL_NEAREST_MIPMAP_LINEAR` (magnification nearest).
pub type NearestMipmapLinear = Mipmapped<Nearest, Nearest, true>;
/// `GL_LINEAR_MIPMAP_LINEAR`: trilinear (magnification linear).
pub type Trilinear = Mipmapped<Bilinear, Bilinear, true>;

impl<Min: Sampler, Mag: Sampler, const LB: bool> TexSampler for Mipmapped<Min, Mag, LB> {
    const LOD: bool = true;
    const FILTER: Filter = Mag::FILTER;
    #[inline(always)]
    fn sample_base<WU: WrapMode, WV: WrapMode>(
        self,
        base: &Texture<'_>,
        wu: WU,
        wv: WV,
        u: i32,
        v: i32,
    ) -> u16 {
        Mag::sample(base, wu, wv, u, v)
    }
    #[inline(always)]
    fn sample_mip<WU: WrapMode, WV: WrapMode>(
        self,
        t: &MipTexture<'_>,
        wu: WU,
        wv: WV,
        u: i32,
        v: i32,
        lambda: i32,
    ) -> u16 {
        mip_sample::<Min, Mag, WU, WV>(t, wu, wv, u, v, lambda, LB)
    }
}

/// GL's `*_MIPMAP_LINEAR` level pair for `lambda > 0` (Q8.8) and a chain whose last level
/// is `last`: the first level `floor(lambda)` (at most `last`) and the weight of the next one
/// (Q8, 0 at or beyond the last level).
#[inline(always)]
pub(crate) fn linear_levels(lambda: i32, last: u32) -> (u32, u32) {
    let d1 = ((lambda >> 8) as u32).min(last);
    let f = if d1 >= last {
        0
    } else {
        (lambda & 0xFF) as u32
    };
    (d1, f)
}

#[inline(always)]
fn mip_sample<Min: Sampler, Mag: Sampler, WU: WrapMode, WV: WrapMode>(
    t: &MipTexture<'_>,
    wu: WU,
    wv: WV,
    u: i32,
    v: i32,
    lambda: i32,
    linear_between: bool,
) -> u16 {
    if lambda <= 0 {
        return Mag::sample(t.base(), wu, wv, u, v);
    }
    let last = t.levels().saturating_sub(1);
    if linear_between {
        let (d1, f) = linear_levels(lambda, last);
        let a = sample_level::<Min, WU, WV>(t, d1, wu, wv, u, v);
        if f == 0 {
            return a;
        }
        let b = sample_level::<Min, WU, WV>(t, d1 + 1, wu, wv, u, v);
        lerp565(a, b, f)
    } else {
        // Level 0 up to lambda = 1/2, else ceil(lambda + 1/2) - 1 = floor(lambda + 1/2) when
        // lambda + 1/2 is not an integer; at exact halves GL's formula picks the lower level.
        let d = if lambda <= 128 {
            0
        } else {
            (((lambda + 128 - 1) >> 8) as u32).min(last)
        };
        sample_level::<Min, WU, WV>(t, d, wu, wv, u, v)
    }
}

/// Mipmapping with filters chosen at run time (host convenience).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct DynMip {
    /// Filter within a level.
    pub min: Filter,
    /// Magnification filter.
    pub mag: Filter,
    /// Between levels.
    pub between: MipFilter,
}

impl TexSampler for DynMip {
    const LOD: bool = true;
    const FILTER: Filter = Filter::Nearest;
    #[inline(always)]
    fn sample_base<WU: WrapMode, WV: WrapMode>(
        self,
        base: &Texture<'_>,
        wu: WU,
        wv: WV,
        u: i32,
        v: i32,
    ) -> u16 {
        match self.mag {
            Filter::Nearest => Nearest::sample(base, wu, wv, u, v),
            Filter::Bilinear => Bilinear::sample(base, wu, wv, u, v),
        }
    }
    // Not inlined: the run-time path instantiates it in every span loop, and four
    // inlined mip samplers each would overflow a 256 KB part (`cargo xtask size`).
    fn sample_mip<WU: WrapMode, WV: WrapMode>(
        self,
        t: &MipTexture<'_>,
        wu: WU,
        wv: WV,
        u: i32,
        v: i32,
        lambda: i32,
    ) -> u16 {
        let lb = self.between == MipFilter::Linear;
        if self.between == MipFilter::None {
            // Minification without mipmaps: the min filter on level 0.
            let f = if lambda > 0 { self.min } else { self.mag };
            return match f {
                Filter::Nearest => Nearest::sample(t.base(), wu, wv, u, v),
                Filter::Bilinear => Bilinear::sample(t.base(), wu, wv, u, v),
            };
        }
        match (self.min, self.mag) {
            (Filter::Nearest, Filter::Nearest) => {
                mip_sample::<Nearest, Nearest, WU, WV>(t, wu, wv, u, v, lambda, lb)
            }
            (Filter::Nearest, Filter::Bilinear) => {
                mip_sample::<Nearest, Bilinear, WU, WV>(t, wu, wv, u, v, lambda, lb)
            }
            (Filter::Bilinear, Filter::Nearest) => {
                mip_sample::<Bilinear, Nearest, WU, WV>(t, wu, wv, u, v, lambda, lb)
            }
            (Filter::Bilinear, Filter::Bilinear) => {
                mip_sample::<Bilinear, Bilinear, WU, WV>(t, wu, wv, u, v, lambda, lb)
            }
        }
    }
}

/// `log2(x)` in Q8.8 for `x > 0` (`x = 0` gives `i32::MIN / 2`), within 1/64.
#[inline(always)]
pub fn log2_q8(x: u64) -> i32 {
    if x == 0 {
        return i32::MIN / 2;
    }
    let n = 63 - x.leading_zeros();
    let idx = if n >= 6 {
        (x >> (n - 6)) & 63
    } else {
        (x << (6 - n)) & 63
    };
    (n as i32) * 256 + i32::from(LOG2_FRAC[idx as usize])
}

/// `256 * log2(1 + (i + 0.5) / 64)`, rounded: the mid-point of each 1/64 mantissa bucket.
static LOG2_FRAC: [u8; 64] = [
    3, 9, 14, 20, 25, 30, 36, 41, 46, 51, 56, 61, 66, 71, 75, 80, 85, 89, 94, 98, 103, 107, 111,
    116, 120, 124, 128, 132, 136, 140, 144, 148, 152, 155, 159, 163, 167, 170, 174, 178, 181, 185,
    188, 192, 195, 198, 202, 205, 208, 212, 215, 218, 221, 224, 228, 231, 234, 237, 240, 243, 246,
    249, 252, 255,
];

/// `lambda` (Q8.8) from level-0 texel derivatives per pixel (I16F16 bits):
/// `log2(max(ux^2 + vx^2, uy^2 + vy^2)) / 2`.
#[inline(always)]
pub fn lambda_q8(ux: i32, vx: i32, uy: i32, vy: i32) -> i32 {
    let sq = |a: i32| u64::from(a.unsigned_abs()) * u64::from(a.unsigned_abs());
    let dx = sq(ux).saturating_add(sq(vx));
    let dy = sq(uy).saturating_add(sq(vy));
    // Squares of I16F16 are 32 fraction bits: log2 - 32, halved.
    (log2_q8(dx.max(dy)) - 32 * 256) >> 1
}

#[cfg(test)]
mod tests {
    extern crate std;
    use super::*;
    use std::vec;

    #[test]
    fn log2_table_within_a_64th() {
        for (i, &got) in LOG2_FRAC.iter().enumerate() {
            let want = (256.0 * (1.0 + (i as f64 + 0.5) / 64.0).log2()).round() as u8;
            assert_eq!(got, want, "entry {i}");
        }
        for x in [1u64, 2, 3, 7, 100, 12345, 1 << 40, u64::MAX] {
            let got = f64::from(log2_q8(x)) / 256.0;
            assert!(
                (got - (x as f64).log2()).abs() <= 1.0 / 64.0 + 1e-9,
                "{x}: {got}"
            );
        }
    }

    #[test]
    fn lambda_of_unit_and_double_derivatives() {
        let one = 1 << 16;
        assert!(lambda_q8(one, 0, 0, one).abs() <= 4);
        assert!((lambda_q8(2 * one, 0, 0, one) - 256).abs() <= 4);
        assert!((lambda_q8(one / 4, 0, 0, one / 4) + 512).abs() <= 4);
    }

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

    #[test]
    fn lerp565_endpoints_and_midpoint() {
        let a = 0xF800; // red
        let b = 0x001F; // blue
        assert_eq!(lerp565(a, b, 0), a);
        assert_eq!(lerp565(a, b, 256), b);
        assert_eq!(lerp565(0, 0xFFFF, 128), (16 << 11) | (32 << 5) | 16);
    }
}
