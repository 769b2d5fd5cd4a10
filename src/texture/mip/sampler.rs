//! Sampling a mip chain: the [`TexSampler`] trait the span loop calls, the plain samplers
//! (level 0 only), GL's four mipmapped minification modes ([`Mipmapped`]) and the run-time
//! [`DynMip`], with the level selection and the blend between two levels ([`lerp565`]).

use super::{MipFilter, MipTexture};
use crate::texture::sample::{Bilinear, BilinearFast, Filter, Nearest, Sampler};
use crate::texture::texture::Texture;
use crate::texture::wrap::WrapMode;

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
    /// Level 0's size in texels, `(width, height)`, when the sampler is built for one size
    /// ([`BilinearFootprintSized`](crate::texture::BilinearFootprintSized)): bindings and
    /// draws refuse a chain of another size
    /// ([`Error::TextureSizeMismatch`](crate::Error::TextureSizeMismatch)).
    const LEVEL0_SIZE: Option<(u32, u32)> = None;
    /// The filters as values, `(min, mag, between)`: within a level when minifying, when
    /// magnifying, and between levels. The default: [`TexSampler::FILTER`] both ways and no
    /// mipmaps (the plain samplers).
    #[inline(always)]
    fn filters(self) -> (Filter, Filter, MipFilter) {
        (Self::FILTER, Self::FILTER, MipFilter::None)
    }
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
    /// them; [`BilinearFootprint`](crate::texture::BilinearFootprint) reads them.
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

    /// Writes a whole linear piece of lit samples of level 0 (`base`) as raw RGB565 and
    /// returns true, or returns false, writing nothing, when the sampler has no loop of its
    /// own for it (the default: the span loop then calls
    /// [`TexSampler::sample_level0_scaled`] per pixel). Pixel `k` of `out` must be
    /// `sample_level0_scaled(u0 + k du, v0 + k dv, (i >> 16) & 0xFF)` with `i = i0 + k di`
    /// (wrapping sums), for `start = [u0, v0, i0]` and `slope = [du, dv, di]`: texel
    /// coordinates I16F16, intensity Q8.16. On ARMv7E-M
    /// [`BilinearFootprintSized`](crate::texture::BilinearFootprintSized) and
    /// [`BilinearFootprint`](crate::texture::BilinearFootprint) have one (assembly loops).
    #[inline(always)]
    fn lit_span<WU: WrapMode, WV: WrapMode>(
        self,
        base: &Texture<'_>,
        footprints: &[u64],
        start: &[i32; 3],
        slope: &[i32; 3],
        out: &mut [u16],
    ) -> bool {
        let _ = (base, footprints, start, slope, out);
        false
    }

    /// True when [`TexSampler::lit_span_depth`] has a loop (for both wraps repeating).
    const LIT_SPAN_DEPTH: bool = false;

    /// [`TexSampler::lit_span`] with the depth test in the loop: pixel `k`'s depth is
    /// `clamp(z_k >> 14, 0, 0xFFFF)` with `z_k = z + k dz` (wrapping); where it is below
    /// `zrow[k]` it is written there and the sample to `out[k]`, elsewhere neither. Returns
    /// the pixels that passed, or `None`, writing nothing (the default), when the sampler has
    /// no such loop.
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
        let _ = (base, footprints, start, slope, z, dz, out, zrow);
        None
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
    fn filters(self) -> (Filter, Filter, MipFilter) {
        let between = if LB {
            MipFilter::Linear
        } else {
            MipFilter::Nearest
        };
        (Min::FILTER, Mag::FILTER, between)
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
            // In u32 (lambda > 128 here): no overflow for any clamp a `Lod` holds.
            ((lambda as u32 + 127) >> 8).min(last)
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
    fn filters(self) -> (Filter, Filter, MipFilter) {
        (self.min, self.mag, self.between)
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

/// The fewest footprints a binding of sampler `F` draws with: one, or every texel of the
/// level 0 size `F` is built for ([`TexSampler::LEVEL0_SIZE`]), so that the span loop's
/// test of [`TexBinding::can_draw`](crate::shading::TexBinding::can_draw) also proves
/// every masked footprint index in bounds. The sized sampler
/// ([`BilinearFootprintSized`](crate::texture::BilinearFootprintSized)) masks its index with
/// this count less one: one derivation, so the test and the mask cannot disagree.
pub(crate) const fn footprints_needed<F: TexSampler>() -> usize {
    match F::LEVEL0_SIZE {
        Some((w, h)) => {
            let n = (w as usize).saturating_mul(h as usize);
            if n == 0 {
                1
            } else {
                n
            }
        }
        None => 1,
    }
}

#[cfg(test)]
mod tests {
    extern crate std;
    use super::*;

    #[test]
    fn lerp565_endpoints_and_midpoint() {
        let a = 0xF800; // red
        let b = 0x001F; // blue
        assert_eq!(lerp565(a, b, 0), a);
        assert_eq!(lerp565(a, b, 256), b);
        assert_eq!(lerp565(0, 0xFFFF, 128), (16 << 11) | (32 << 5) | 16);
    }
}
