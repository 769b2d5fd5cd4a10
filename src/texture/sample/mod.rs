//! Texture filters: nearest and bilinear sampling of an RGB565 [`Texture`].
//!
//! Units and conventions (OpenGL ES 3.2, texture minification and magnification):
//! - `u`, `v` are raw I16F16 texel coordinates (`i32`, 16 fractional bits, 65536 = one texel,
//!   `u = s * width`, `v = t * height`); `v = 0` is the top edge of row 0 (the first row of the
//!   slice). Any `i32` is accepted (range -32768.0 ..= 32767.99998 texels).
//! - Texel centres are at `i + 0.5`.
//! - NEAREST: `i = wrap(floor(u))`, `j = wrap(floor(v))`.
//! - BILINEAR: `i0 = floor(u - 0.5)`, `i1 = i0 + 1`, `alpha = frac(u - 0.5)`; likewise
//!   `j0`, `j1`, `beta` from `v`. Each of the four integer indices is wrapped separately, and
//!   a texel whose `i` or `j` wraps to the border takes the border colour. The result is
//!   `(1-a)(1-b) c00 + a(1-b) c10 + (1-a) b c01 + a b c11`, per channel.
//! - Results are raw RGB565 `u16`.
//!
//! Bilinear arithmetic ([`Bilinear`]): `alpha` and `beta` are rounded to Q8 (0..=256), the
//! four weights are formed in Q8 so that they sum to exactly 256
//! (`w11 = (a*b + 128) >> 8`, `w10 = a - w11`, `w01 = b - w11`, `w00 = 256 + w11 - a - b`,
//! all provably in 0..=256), and each channel is `(sum w*c + 128) >> 8` — a single rounding.
//! Each channel's sum is two two-term dot products, one per 32-bit multiply: a row's two
//! texels share a word, its two weights another in reverse order, and the product's upper
//! half is the dot product (see `blend_weights`).
//! Cost: 7 32-bit multiplies (1 for the weights, 2 per channel), no division.
//! Measured against an exact f64 bilinear: never more than 1 LSB from the exact value
//! rounded to nearest (see the tests and the module report).
//!
//! [`BilinearFast`] is the classic packed variant: `(c | c << 16) & 0x07E0_F81F` spreads
//! all three channels into one `u32`, alpha/beta are rounded to Q5 (0..=32) and three lerps
//! (`a*(32-w) + b*w`, rounded) cost 6 multiplies; its error reaches 2 LSB.

use super::texture::Texture;
use super::wrap::{DynWrap, Wrap, WrapMode};

/// A filter as a value (for run-time selection, see [`Texture::sample_dyn`]).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Filter {
    /// `GL_NEAREST`: the texel containing the sample point.
    #[default]
    Nearest,
    /// `GL_LINEAR`: bilinear blend of the four nearest texel centres.
    Bilinear,
}

/// A texture filter, selected at compile time by a zero-sized marker.
pub trait Sampler: Copy + Default + core::fmt::Debug {
    /// The filter as a value.
    const FILTER: Filter;

    /// Samples `tex` at raw I16F16 texel coordinates `(u, v)` with wrap modes `wu` (columns)
    /// and `wv` (rows). Returns raw RGB565. Never panics, for any input.
    fn sample<WU: WrapMode, WV: WrapMode>(tex: &Texture<'_>, wu: WU, wv: WV, u: i32, v: i32)
        -> u16;

    /// The sample times intensity `i` (Q8, `0..=256`; larger is 256), raw RGB565. The
    /// default modulates the sample ([`modulate_scalar`](crate::color::modulate_scalar));
    /// [`Bilinear`] scales its exact channel sums by the intensity (one rounding).
    #[inline(always)]
    fn sample_scaled<WU: WrapMode, WV: WrapMode>(
        tex: &Texture<'_>,
        wu: WU,
        wv: WV,
        u: i32,
        v: i32,
        i: u16,
    ) -> u16 {
        crate::color::modulate_scalar(Self::sample(tex, wu, wv, u, v), i)
    }
}

/// `GL_NEAREST` marker.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Nearest;

/// `GL_LINEAR` (bilinear) marker: Q8 weights, single rounding, at most 1 LSB from exact.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Bilinear;

/// Classic packed bilinear with Q5 weights: 6 multiplies, at most 2 LSB from exact.
/// Its [`Sampler::FILTER`] is [`Filter::Bilinear`].
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct BilinearFast;

/// Raw texel at wrapped indices, or the border if either index is `None`.
#[inline(always)]
fn fetch(tex: &Texture<'_>, i: Option<u32>, j: Option<u32>) -> u16 {
    match (i, j) {
        (Some(i), Some(j)) => tex.texel_raw(i, j),
        _ => tex.border_raw(),
    }
}

/// Splits an I16F16 coordinate `c` into `floor(c - 0.5)` and the 16-bit fraction of
/// `c - 0.5`, without overflow for any `i32`.
///
/// `floor((c - 2^15) / 2^16) = floor(((c >> 1) - 2^14) / 2^15)`: dropping the low bit of `c`
/// moves the numerator by half a unit, which cannot cross a multiple of 2^15. `(c >> 1) -
/// 2^14` cannot overflow. The fraction only needs the low 16 bits, so wrapping is fine.
#[inline(always)]
pub(crate) fn split_half(c: i32) -> (i32, u32) {
    let i0 = ((c >> 1) - 0x4000) >> 15;
    let f = (c.wrapping_sub(0x8000) as u32) & 0xFFFF;
    (i0, f)
}

/// The four texels around `(u, v)` for bilinear filtering, plus the 16-bit fractions.
#[inline(always)]
fn gather<WU: WrapMode, WV: WrapMode>(
    tex: &Texture<'_>,
    wu: WU,
    wv: WV,
    u: i32,
    v: i32,
) -> ([u16; 4], u32, u32) {
    let (i0, fu) = split_half(u);
    let (j0, fv) = split_half(v);
    if WU::REPEAT && WV::REPEAT {
        let (c, _, _) = gather_repeat(tex, u, v);
        return (c, fu, fv);
    }
    // i0 >= -32769 and <= 32767, so + 1 cannot overflow.
    let (lw, lh) = (tex.log2_width(), tex.log2_height());
    let (i0w, i1w) = (wu.wrap(i0, lw), wu.wrap(i0 + 1, lw));
    let (j0w, j1w) = (wv.wrap(j0, lh), wv.wrap(j0 + 1, lh));
    let c = [
        fetch(tex, i0w, j0w),
        fetch(tex, i1w, j0w),
        fetch(tex, i0w, j1w),
        fetch(tex, i1w, j1w),
    ];
    (c, fu, fv)
}

/// What the bilinear samplers subtract from a texel coordinate (I16F16) before splitting
/// it into a texel and a Q8 fraction: `1/2 - 1/512`, so that `t = u - 1/2 + 1/512` (see
/// [`gather_repeat`]). Shared by the footprint samplers and their ARMv7E-M span loops.
pub(crate) const REPEAT_SPLIT: i32 = 0x7F80;

/// The four texels around `(u, v)` with repeat wrapping on both axes, and the Q8 weights
/// `a`, `b` (`0..=255`). Rounding the 16-bit fraction to Q8 is folded into the split:
/// `t = u - 1/2 + 1/512`, `i0 = floor(t)`, `a = frac(t)` in Q8 (truncated). Where the
/// rounded fraction would be 256 this picks the next column with weight 0, which blends
/// the same texels with the same weights. Wrapping is the low bits, so masks alone index.
/// (`BilinearFootprint::gather` splits `u`, `v` the same way; one helper shared with it
/// costs the plain path about one instruction per pixel on the Cortex-M4F whole sphere, so
/// each keeps its own.)
#[inline(always)]
fn gather_repeat(tex: &Texture<'_>, u: i32, v: i32) -> ([u16; 4], u32, u32) {
    let tu = u.wrapping_sub(REPEAT_SPLIT);
    let tv = v.wrapping_sub(REPEAT_SPLIT);
    let (a, b) = ((tu as u32 >> 8) & 0xFF, (tv as u32 >> 8) & 0xFF);
    let mw = tex.width() - 1;
    let x0 = (tu >> 16) as u32 & mw;
    let x1 = ((tu >> 16) as u32).wrapping_add(1) & mw;
    // Row offsets: `texel_at` masks with `len - 1`, which wraps the row index too.
    let r0 = ((tv >> 16) as u32) << tex.log2_width();
    let r1 = r0.wrapping_add(tex.width());
    let c = [
        tex.texel_at(r0 | x0),
        tex.texel_at(r0 | x1),
        tex.texel_at(r1 | x0),
        tex.texel_at(r1 | x1),
    ];
    (c, a, b)
}

// Declared where its code stood in one file (rustc emits functions in definition order and
// LLVM's choices follow it).
mod blend;

use blend::blend_q5;
pub(crate) use blend::{blend_q8, blend_q8_scaled, blend_rows_q8};

impl Sampler for Nearest {
    const FILTER: Filter = Filter::Nearest;

    #[inline(always)]
    fn sample<WU: WrapMode, WV: WrapMode>(
        tex: &Texture<'_>,
        wu: WU,
        wv: WV,
        u: i32,
        v: i32,
    ) -> u16 {
        if WU::REPEAT && WV::REPEAT {
            // Row bits straight from v: (v >> (16 - lw)) holds floor(v) << lw plus fraction
            // bits below lw, which `texel_at`'s mask with `len - 1` and the column mask clear.
            let lw = tex.log2_width();
            let row = ((v >> (16 - lw)) as u32) & !(tex.width() - 1);
            let col = (u >> 16) as u32 & (tex.width() - 1);
            return tex.texel_at(row | col);
        }
        // Arithmetic shift = floor for negative coordinates too.
        let i = wu.wrap(u >> 16, tex.log2_width());
        let j = wv.wrap(v >> 16, tex.log2_height());
        fetch(tex, i, j)
    }
}

impl Sampler for Bilinear {
    const FILTER: Filter = Filter::Bilinear;

    #[inline(always)]
    fn sample<WU: WrapMode, WV: WrapMode>(
        tex: &Texture<'_>,
        wu: WU,
        wv: WV,
        u: i32,
        v: i32,
    ) -> u16 {
        if WU::REPEAT && WV::REPEAT {
            let (c, a, b) = gather_repeat(tex, u, v);
            return blend_q8(c, a, b);
        }
        let (c, fu, fv) = gather(tex, wu, wv, u, v);
        // Round the 16-bit fractions to Q8 (0..=256).
        blend_q8(c, (fu + 0x80) >> 8, (fv + 0x80) >> 8)
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
        let i = u32::from(i.min(256));
        if WU::REPEAT && WV::REPEAT {
            let (c, a, b) = gather_repeat(tex, u, v);
            return blend_q8_scaled(c, a, b, i);
        }
        let (c, fu, fv) = gather(tex, wu, wv, u, v);
        blend_q8_scaled(c, (fu + 0x80) >> 8, (fv + 0x80) >> 8, i)
    }
}

impl Sampler for BilinearFast {
    const FILTER: Filter = Filter::Bilinear;

    #[inline(always)]
    fn sample<WU: WrapMode, WV: WrapMode>(
        tex: &Texture<'_>,
        wu: WU,
        wv: WV,
        u: i32,
        v: i32,
    ) -> u16 {
        let (c, fu, fv) = gather(tex, wu, wv, u, v);
        // Round the 16-bit fractions to Q5 (0..=32).
        blend_q5(c, (fu + 0x400) >> 11, (fv + 0x400) >> 11)
    }
}

impl Texture<'_> {
    /// Samples with a filter and wrap modes chosen at run time (host convenience; the
    /// rasterizer uses the monomorphised [`Sampler::sample`]). `u`, `v` are raw I16F16 texel
    /// coordinates. Returns raw RGB565.
    pub fn sample_dyn(&self, filter: Filter, wrap_u: Wrap, wrap_v: Wrap, u: i32, v: i32) -> u16 {
        let (wu, wv) = (DynWrap(wrap_u), DynWrap(wrap_v));
        match filter {
            Filter::Nearest => Nearest::sample(self, wu, wv, u, v),
            Filter::Bilinear => Bilinear::sample(self, wu, wv, u, v),
        }
    }
}

#[cfg(test)]
mod tests;
