//! Texture filters: nearest and bilinear sampling of an RGB565 [`Texture`].
//!
//! Units and conventions (OpenGL ES 3.0 §3.8.10/§3.8.11):
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
use super::wrap::WrapMode;

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

/// The four texels around `(u, v)` with repeat wrapping on both axes, and the Q8 weights
/// `a`, `b` (`0..=255`). Rounding the 16-bit fraction to Q8 is folded into the split:
/// `t = u - 1/2 + 1/512`, `i0 = floor(t)`, `a = frac(t)` in Q8 (truncated). Where the
/// rounded fraction would be 256 this picks the next column with weight 0, which blends
/// the same texels with the same weights. Wrapping is the low bits, so masks alone index.
/// (`BilinearFootprint::gather` splits `u`, `v` the same way; sharing one helper with it
/// cost the plain path 1.2 instructions per pixel on the Cortex-M4F whole sphere.)
#[inline(always)]
fn gather_repeat(tex: &Texture<'_>, u: i32, v: i32) -> ([u16; 4], u32, u32) {
    let tu = u.wrapping_sub(0x7F80);
    let tv = v.wrapping_sub(0x7F80);
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

/// Bilinear filtering with the result scaled by intensity `i` (Q8, `0..=256`) in one
/// rounding: each channel's exact sum `S = sum w c` over the four Q8 weights of
/// [`blend_q8`] (summing to 256) is multiplied by `i` and rounded once,
/// `(S i + 2^15) >> 16`, which is the nearest value to `sum w c i / 65536` (tested). One
/// rounding instead of two (bilinear to RGB565, then modulation), and the weights are not
/// scaled at all: three multiplies more than [`blend_q8`] in place of nine for filtering
/// and modulating in turn. (The weights were once scaled by `i` before the sums, each
/// rounded: 6.5 instructions per pixel more on the Cortex-M4F cube, 6.9 on M0+, and three
/// roundings where this has one.)
#[inline(always)]
pub(crate) fn blend_q8_scaled(c: [u16; 4], a: u32, b: u32, i: u32) -> u16 {
    debug_assert!(a <= 256 && b <= 256 && i <= 256);
    // S <= 63 * 256 < 2^14 in the upper half; S i + 2^15 < 2^23.
    blend_pairs(c, q8_weights(a, b), Scale(i))
}

/// The four Q8 bilinear weights `[w00, w10, w01, w11]` of fractions `a`, `b` in 0..=256:
/// `w11 = round(a b / 256) <= min(a, b)`, so every weight is in 0..=256 and they sum to 256
/// exactly.
#[inline(always)]
fn q8_weights(a: u32, b: u32) -> [u32; 4] {
    let w11 = (a * b + 128) >> 8;
    // Evaluated left to right: 256 + w11 - a >= 0 since a <= 256; the result is w00 >= 0.
    [256 + w11 - a - b, a - w11, b - w11, w11]
}

/// `sum w c` per channel for Q8 weights `w` summing to at most 256, rounded: two texels
/// per multiply. A row's two texels share a word (`c0 | c1 << 16`), its two weights another
/// in the opposite order (`w1 | w0 << 16`), and the product's upper half is `c0 w0 + c1 w1`
/// (its lower half, `c0 w1 < 2^14`, never carries into it; `c1 w0` falls off the top). Six
/// multiplies for three channels where one channel pair per word took eight; the same sums
/// and roundings as the per-texel form kept in the tests, so the same result. Measured
/// against that form (cube / bilinear floor, instructions per pixel): Cortex-M4F 141.95 ->
/// 137.00 / 91.67 -> 87.71, Cortex-M0+ 254.61 -> 232.53 / 177.32 -> 159.58 (one mask
/// register serves all three channels), RV32IMC 163.98 -> 161.07 / 115.18 -> 112.28, x86-64
/// 161.1 -> 161.1 / 118.2 -> 108.2.
#[inline(always)]
fn blend_weights(c: [u16; 4], w: [u32; 4]) -> u16 {
    // Each channel's sum is at most 63 * 256 < 2^14 (weights sum to at most 256), so adding
    // half of 256 to it never overflows (see `Round`).
    blend_pairs(c, w, Round)
}

/// The dot-product sums of [`blend_weights`]: each channel's sum `sum w c`, where the
/// multiply leaves it, handed to `finish` ([`Finish`]), which returns the channel's value
/// (red and blue 0..=31, green 0..=63); packed to RGB565. Two texels per multiply on 32-bit targets
/// ([`blend_pairs_u32`]), four on 64-bit ones ([`blend_pairs_u64`]): the same sums, so the
/// same pixels on every target.
#[inline(always)]
fn blend_pairs(c: [u16; 4], w: [u32; 4], finish: impl Finish) -> u16 {
    #[cfg(target_pointer_width = "64")]
    {
        blend_pairs_u64(c, w, finish)
    }
    #[cfg(not(target_pointer_width = "64"))]
    {
        blend_pairs_u32(c, w, finish)
    }
}

/// How a channel's sum `S = sum w c` (`S < 2^14`) becomes the channel's value, read from
/// the multiply's word where the sum sits above terms that never carry into it.
trait Finish: Copy {
    /// From `s = S << 16 | L`, `L < 2^16` (the 32-bit form).
    #[cfg(any(test, not(target_pointer_width = "64")))]
    fn upper_half(self, s: u32) -> u32;
    /// From `p = S << 48 | L`, `L < 2^48` (the 64-bit form).
    #[cfg(any(test, target_pointer_width = "64"))]
    fn top_lane(self, p: u64) -> u32;
}

/// `S / 256` rounded (the unscaled blend). In the 32-bit form `L` never reaches the next
/// multiple of the divisor: `S << 16 + 2^23` is a multiple of `2^16`, and `L < 2^16`.
#[derive(Clone, Copy)]
struct Round;

impl Finish for Round {
    #[cfg(any(test, not(target_pointer_width = "64")))]
    #[inline(always)]
    fn upper_half(self, s: u32) -> u32 {
        s.wrapping_add(128 << 16) >> 24
    }
    #[cfg(any(test, target_pointer_width = "64"))]
    #[inline(always)]
    fn top_lane(self, p: u64) -> u32 {
        (((p >> 48) as u32) + 128) >> 8
    }
}

/// `S i / 65536` rounded, `i` in 0..=256 (the blend scaled by an intensity).
#[derive(Clone, Copy)]
struct Scale(u32);

impl Finish for Scale {
    #[cfg(any(test, not(target_pointer_width = "64")))]
    #[inline(always)]
    fn upper_half(self, s: u32) -> u32 {
        ((s >> 16) * self.0 + 32768) >> 16
    }
    #[cfg(any(test, target_pointer_width = "64"))]
    #[inline(always)]
    fn top_lane(self, p: u64) -> u32 {
        (((p >> 48) as u32) * self.0 + 32768) >> 16
    }
}

/// [`blend_pairs`] with two texels per 32-bit multiply. A row's two texels share a word
/// (`c0 | c1 << 16`), its two weights another in the opposite order (`w1 | w0 << 16`), and
/// the product's upper half is `c0 w0 + c1 w1` (its lower half, `c0 w1 < 2^14`, never
/// carries into it; `c1 w0` falls off the top).
#[cfg(any(test, not(target_pointer_width = "64")))]
#[inline(always)]
fn blend_pairs_u32(c: [u16; 4], w: [u32; 4], finish: impl Finish) -> u16 {
    let top = c[0] as u32 | (c[1] as u32) << 16;
    let bot = c[2] as u32 | (c[3] as u32) << 16;
    blend_rows_u32(top, bot, (w[1] | w[0] << 16, w[3] | w[2] << 16), finish)
}

/// [`q8_weights`] packed as [`blend_rows_u32`] wants them, `(w10 | w00 << 16,
/// w11 | w01 << 16)`, straight from the fractions `a`, `b` (`0..=256`): with
/// `K = 1 - 2^16` (mod 2^32), the bottom word is `b << 16 + w11 K` and the two words sum to
/// `256 << 16 + a K` (the same integers as packing the four weights, tested for every `a`,
/// `b`). The footprint path uses it: Cortex-M4F cube 111.73 -> 110.37 instructions per
/// pixel, M0+ 192.90 -> 188.83, RV32 128.00 -> 125.17. The four-texel path keeps packing
/// the four weights: there this form cost (M4F whole sphere 275.1 -> 277.3).
#[cfg(any(test, not(target_pointer_width = "64")))]
#[inline(always)]
fn packed_q8_weights(a: u32, b: u32) -> (u32, u32) {
    const K: u32 = 1u32.wrapping_sub(1 << 16);
    let w11 = (a * b + 128) >> 8;
    let wb = (b << 16).wrapping_add(w11.wrapping_mul(K));
    let wt = (256u32 << 16)
        .wrapping_add(a.wrapping_mul(K))
        .wrapping_sub(wb);
    (wt, wb)
}

/// [`blend_pairs_u32`] from the two rows' words as they are packed (`c0 | c1 << 16`,
/// `c2 | c3 << 16`, which is how a texture's footprints store them) and the row weights
/// packed (`(w1 | w0 << 16, w3 | w2 << 16)`).
#[cfg(any(test, not(target_pointer_width = "64")))]
#[inline(always)]
fn blend_rows_u32(top: u32, bot: u32, (wt, wb): (u32, u32), finish: impl Finish) -> u16 {
    let dot = |mask: u32, shift: u32| {
        finish.upper_half(
            ((top >> shift) & mask)
                .wrapping_mul(wt)
                .wrapping_add(((bot >> shift) & mask).wrapping_mul(wb)),
        )
    };
    let r = dot(0x001F_001F, 11);
    let g = dot(0x003F_003F, 5);
    let b = dot(0x001F_001F, 0);
    ((r << 11) | (g << 5) | b) as u16
}

/// [`blend_pairs`] with all four texels in one 64-bit multiply. The texels fill one word's
/// 16-bit lanes (`c0 | c1 << 16 | c2 << 32 | c3 << 48`), the weights another in the
/// opposite order, and lane 3 of the product is `sum c_k w_k`. Each lane of the product
/// sums channel-times-weight terms whose weights are distinct, so it is at most
/// `63 * 256 < 2^14`: no lane carries into the next, and the lanes above lane 3 fall off
/// the top. One multiply per channel where the 32-bit form takes two and an add: x86-64
/// (callgrind, instructions per pixel) bilinear floor 109.2 -> 106.3, cube 151.2 -> 145.2.
#[cfg(any(test, target_pointer_width = "64"))]
#[inline(always)]
fn blend_pairs_u64(c: [u16; 4], w: [u32; 4], finish: impl Finish) -> u16 {
    let top = c[0] as u32 | (c[1] as u32) << 16;
    let bot = c[2] as u32 | (c[3] as u32) << 16;
    blend_rows_u64(top, bot, w, finish)
}

/// [`blend_pairs_u64`] from the two rows' words as they are packed (`c0 | c1 << 16`,
/// `c2 | c3 << 16`).
#[cfg(any(test, target_pointer_width = "64"))]
#[inline(always)]
fn blend_rows_u64(top: u32, bot: u32, w: [u32; 4], finish: impl Finish) -> u16 {
    let texels = top as u64 | (bot as u64) << 32;
    let weights = w[3] as u64 | (w[2] as u64) << 16 | (w[1] as u64) << 32 | (w[0] as u64) << 48;
    let dot =
        |mask: u64, shift: u32| finish.top_lane(((texels >> shift) & mask).wrapping_mul(weights));
    let r = dot(0x001F_001F_001F_001F, 11);
    let g = dot(0x003F_003F_003F_003F, 5);
    let b = dot(0x001F_001F_001F_001F, 0);
    ((r << 11) | (g << 5) | b) as u16
}

/// Bilinear blend of a footprint's two row words (`top = c00 | c10 << 16`,
/// `bot = c01 | c11 << 16`) with Q8 fractions `a`, `b` in 0..=256, scaled by intensity `i`
/// (Q8, `0..=256`) when `Some`: the same sums and roundings as [`blend_q8`] and
/// [`blend_q8_scaled`], so the same result.
#[inline(always)]
pub(crate) fn blend_rows_q8(top: u32, bot: u32, a: u32, b: u32, i: Option<u32>) -> u16 {
    #[inline(always)]
    fn blend(top: u32, bot: u32, a: u32, b: u32, finish: impl Finish) -> u16 {
        #[cfg(target_pointer_width = "64")]
        {
            blend_rows_u64(top, bot, q8_weights(a, b), finish)
        }
        #[cfg(not(target_pointer_width = "64"))]
        {
            blend_rows_u32(top, bot, packed_q8_weights(a, b), finish)
        }
    }
    match i {
        Some(i) => blend(top, bot, a, b, Scale(i)),
        None => blend(top, bot, a, b, Round),
    }
}

/// The per-texel form of [`blend_weights`] (red and blue in one word, green in another; eight
/// multiplies): the reference the tests hold it to.
#[cfg(test)]
fn blend_weights_masks(c: [u16; 4], w: [u32; 4]) -> u16 {
    let rb = |t: u16| {
        let t = t as u32;
        ((t & 0xF800) << 5) | (t & 0x001F)
    };
    let g = |t: u16| t as u32 & 0x07E0;
    let rbs = rb(c[0]) * w[0] + rb(c[1]) * w[1] + rb(c[2]) * w[2] + rb(c[3]) * w[3];
    let gs = g(c[0]) * w[0] + g(c[1]) * w[1] + g(c[2]) * w[2] + g(c[3]) * w[3];
    let rbs = (rbs + 0x0080_0080) >> 8;
    let gs = ((gs + (128 << 5)) >> 8) & 0x07E0;
    (((rbs >> 5) & 0xF800) | gs | (rbs & 0x001F)) as u16
}

/// Bilinear blend of `[c00, c10, c01, c11]` with Q8 fractions `a`, `b` in 0..=256.
/// Four Q8 weights summing to 256, one rounding per channel; 7 multiplies.
#[inline(always)]
pub(crate) fn blend_q8(c: [u16; 4], a: u32, b: u32) -> u16 {
    debug_assert!(a <= 256 && b <= 256);
    blend_weights(c, q8_weights(a, b))
}

/// Spreads RGB565 into `0b00000ggg_ggg00000_rrrrr000_000bbbbb` (G at 21, R at 11, B at 0).
#[inline(always)]
fn spread(c: u16) -> u32 {
    let c = c as u32;
    (c | (c << 16)) & 0x07E0_F81F
}

/// Rounded lerp of two spread colours with a Q5 weight `w` in 0..=32.
/// Lane maxima: G 63*32 + 16 < 2^11 (bits 21..=31), R 31*32 + 16 < 2^10 (bits 11..=20),
/// B 31*32 + 16 < 2^10 (bits 0..=9), so lanes never carry into each other.
#[inline(always)]
fn lerp_q5(x: u32, y: u32, w: u32) -> u32 {
    const HALF: u32 = (16 << 21) | (16 << 11) | 16;
    ((x * (32 - w) + y * w + HALF) >> 5) & 0x07E0_F81F
}

/// Classic packed bilinear with Q5 fractions `a`, `b` in 0..=32; 6 multiplies.
#[inline(always)]
pub(crate) fn blend_q5(c: [u16; 4], a: u32, b: u32) -> u16 {
    debug_assert!(a <= 32 && b <= 32);
    let top = lerp_q5(spread(c[0]), spread(c[1]), a);
    let bot = lerp_q5(spread(c[2]), spread(c[3]), a);
    let m = lerp_q5(top, bot, b);
    (m | (m >> 16)) as u16
}

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

#[cfg(test)]
mod tests {
    extern crate std;
    use super::*;
    use crate::color::rgb565;
    use crate::texture::wrap::{ClampToBorder, ClampToEdge, DynWrap, MirroredRepeat, Repeat, Wrap};
    use embedded_graphics_core::pixelcolor::raw::RawU16;
    use embedded_graphics_core::pixelcolor::{IntoStorage, Rgb565};
    use std::vec::Vec;
    use std::{println, vec};

    struct Rng(u32);
    impl Rng {
        fn next(&mut self) -> u32 {
            self.0 ^= self.0 << 13;
            self.0 ^= self.0 >> 17;
            self.0 ^= self.0 << 5;
            self.0
        }
    }

    fn raw_tex(raws: &[u16]) -> Vec<Rgb565> {
        raws.iter().map(|&r| Rgb565::from(RawU16::new(r))).collect()
    }

    fn chans(t: u16) -> [f64; 3] {
        [(t >> 11) as f64, ((t >> 5) & 63) as f64, (t & 31) as f64]
    }

    /// Independent reference texel fetch: i64 indices, spec formulas with `rem_euclid`.
    fn ref_texel(tex: &Texture<'_>, mode: [Wrap; 2], i: i64, j: i64) -> [f64; 3] {
        let wrap = |m: Wrap, i: i64, size: i64| -> Option<i64> {
            match m {
                Wrap::Repeat => Some(i.rem_euclid(size)),
                Wrap::MirroredRepeat => {
                    let a = i.rem_euclid(2 * size) - size;
                    Some((size - 1) - if a >= 0 { a } else { -(1 + a) })
                }
                Wrap::ClampToEdge => Some(i.clamp(0, size - 1)),
                Wrap::ClampToBorder => (0..size).contains(&i).then_some(i),
            }
        };
        let (w, h) = (tex.width() as i64, tex.height() as i64);
        match (wrap(mode[0], i, w), wrap(mode[1], j, h)) {
            (Some(i), Some(j)) => {
                let idx = (j * w + i) as usize;
                chans(tex.texels()[idx].into_storage())
            }
            _ => chans(tex.border_raw()),
        }
    }

    /// Independent float reference of the whole bilinear sample.
    fn reference_bilinear(tex: &Texture<'_>, mode: [Wrap; 2], u: i32, v: i32) -> [f64; 3] {
        let uf = u as f64 / 65536.0 - 0.5;
        let vf = v as f64 / 65536.0 - 0.5;
        let (i0, j0) = (uf.floor() as i64, vf.floor() as i64);
        let (a, b) = (uf - uf.floor(), vf - vf.floor());
        let texel = |i: i64, j: i64| ref_texel(tex, mode, i, j);
        let (c00, c10, c01, c11) = (
            texel(i0, j0),
            texel(i0 + 1, j0),
            texel(i0, j0 + 1),
            texel(i0 + 1, j0 + 1),
        );
        let mut out = [0.0; 3];
        for k in 0..3 {
            out[k] = (1.0 - a) * (1.0 - b) * c00[k]
                + a * (1.0 - b) * c10[k]
                + (1.0 - a) * b * c01[k]
                + a * b * c11[k];
        }
        out
    }

    fn random_tex(rng: &mut Rng, w: u32, h: u32) -> Vec<Rgb565> {
        (0..w * h)
            .map(|_| Rgb565::from(RawU16::new(rng.next() as u16)))
            .collect()
    }

    /// Error statistics of one sampler against the float reference.
    #[derive(Default)]
    struct Stats {
        n: u64,
        max_abs: [f64; 3],
        // |fast - round(exact)| histogram: 0, 1, 2, >=3 LSB, per channel.
        hist: [[u64; 4]; 3],
        // |fast - exact| (unrounded) histogram in quarter-LSB bins up to 2 LSB, per channel.
        bins: [[u64; 9]; 3],
    }

    impl Stats {
        fn add(&mut self, got: u16, exact: [f64; 3]) {
            self.n += 1;
            let g = chans(got);
            for k in 0..3 {
                let e = (g[k] - exact[k]).abs();
                if e > self.max_abs[k] {
                    self.max_abs[k] = e;
                }
                let r = (g[k] - (exact[k] + 0.5).floor()).abs() as usize;
                self.hist[k][r.min(3)] += 1;
                self.bins[k][((e * 4.0) as usize).min(8)] += 1;
            }
        }
        fn print(&self, name: &str) {
            println!("{name}: {} samples", self.n);
            for (k, ch) in ["R", "G", "B"].iter().enumerate() {
                println!(
                    "  {ch}: max|got-exact| = {:.4} LSB; |got-round(exact)| 0:{} 1:{} 2:{} >=3:{}; \
                     |got-exact| quarter-LSB bins {:?}",
                    self.max_abs[k],
                    self.hist[k][0],
                    self.hist[k][1],
                    self.hist[k][2],
                    self.hist[k][3],
                    self.bins[k]
                );
            }
        }
        fn within_one(&self) -> f64 {
            let ok: u64 = (0..3).map(|k| self.hist[k][0] + self.hist[k][1]).sum();
            ok as f64 / (3 * self.n) as f64
        }
    }

    fn measure(samples: usize) -> (Stats, Stats) {
        let mut rng = Rng(0xDEAD_BEEF);
        let (mut acc, mut fast) = (Stats::default(), Stats::default());
        for &(w, h) in &[(8u32, 8u32), (16, 4), (1, 8), (8, 1), (32, 32)] {
            let texels = random_tex(&mut rng, w, h);
            let tex = Texture::new(&texels, w, h).unwrap().with_border_raw(0xFFFF);
            for _ in 0..samples {
                let u = (rng.next() % ((3 * w) << 16)) as i32 - (w << 16) as i32;
                let v = (rng.next() % ((3 * h) << 16)) as i32 - (h << 16) as i32;
                let exact = reference_bilinear(&tex, [Wrap::Repeat, Wrap::Repeat], u, v);
                acc.add(Bilinear::sample(&tex, Repeat, Repeat, u, v), exact);
                fast.add(BilinearFast::sample(&tex, Repeat, Repeat, u, v), exact);
            }
        }
        (acc, fast)
    }

    #[test]
    fn bilinear_error_distribution() {
        let (acc, fast) = measure(200_000);
        acc.print("Bilinear (Q8 four-weight, 9 mul)");
        fast.print("BilinearFast (Q5 packed lerps, 6 mul)");
        println!(
            "within 1 LSB of round(exact): accurate {:.6}, fast {:.6}",
            acc.within_one(),
            fast.within_one()
        );
        for k in 0..3 {
            // Never more than 1 LSB from the exact value rounded to nearest.
            assert_eq!(acc.hist[k][2] + acc.hist[k][3], 0, "channel {k}");
            assert!(acc.max_abs[k] < 1.0, "channel {k}: {}", acc.max_abs[k]);
        }
        assert!(acc.within_one() >= 0.995);
    }

    /// Worst cases that random sampling may miss: extreme texel pairs at every Q16 fraction
    /// step of 16 (all 4096 alpha x a set of betas).
    #[test]
    fn bilinear_worst_case_sweep() {
        let pairs: [[u16; 4]; 4] = [
            [0x0000, 0xFFFF, 0xFFFF, 0x0000],
            [0xFFFF, 0x0000, 0x0000, 0xFFFF],
            [0x0000, 0x0000, 0x0000, 0xFFFF],
            [0xFFFF, 0xFFFF, 0xFFFF, 0x0000],
        ];
        for p in pairs {
            let texels = raw_tex(&p);
            let tex = Texture::new(&texels, 2, 2).unwrap();
            for fu in (0..0x10000).step_by(16) {
                for fv in (0..0x10000).step_by(1021) {
                    // Sample point inside the 2x2 block: u = 0.5 + frac.
                    let (u, v) = (0x8000 + fu, 0x8000 + fv);
                    let exact = reference_bilinear(&tex, [Wrap::Repeat, Wrap::Repeat], u, v);
                    let got = chans(Bilinear::sample(&tex, Repeat, Repeat, u, v));
                    for k in 0..3 {
                        assert!(
                            (got[k] - exact[k]).abs() < 1.0,
                            "{p:?} fu {fu} fv {fv} ch {k}: {} vs {}",
                            got[k],
                            exact[k]
                        );
                    }
                }
            }
        }
    }

    #[test]
    fn blend_q8_exhaustive_weights_extremes() {
        // Every Q8 (a, b) with the hardest texels: results never leave the channel range and
        // are within 1 LSB of exact.
        let sets: [[u16; 4]; 3] = [
            [0xFFFF, 0xFFFF, 0xFFFF, 0xFFFF],
            [0x0000, 0xFFFF, 0xFFFF, 0x0000],
            [0xF81F, 0x07E0, 0x07E0, 0xF81F],
        ];
        for c in sets {
            for a in 0..=256u32 {
                for b in 0..=256u32 {
                    let got = chans(blend_q8(c, a, b));
                    let (af, bf) = (a as f64 / 256.0, b as f64 / 256.0);
                    let cs: Vec<[f64; 3]> = c.iter().map(|&t| chans(t)).collect();
                    for k in 0..3 {
                        let e = (1.0 - af) * (1.0 - bf) * cs[0][k]
                            + af * (1.0 - bf) * cs[1][k]
                            + (1.0 - af) * bf * cs[2][k]
                            + af * bf * cs[3][k];
                        assert!((got[k] - e).abs() < 1.0, "{c:?} {a} {b} {k}");
                    }
                }
            }
            assert_eq!(blend_q8(c, 0, 0), c[0]);
            assert_eq!(blend_q8(c, 256, 0), c[1]);
            assert_eq!(blend_q8(c, 0, 256), c[2]);
            assert_eq!(blend_q8(c, 256, 256), c[3]);
        }
    }

    #[test]
    fn texel_centres_are_exact() {
        let mut rng = Rng(42);
        let (w, h) = (8u32, 4u32);
        let texels = random_tex(&mut rng, w, h);
        let tex = Texture::new(&texels, w, h).unwrap();
        for j in 0..h {
            for i in 0..w {
                let want = tex.texel_raw(i, j);
                let (u, v) = (((i << 16) + 0x8000) as i32, ((j << 16) + 0x8000) as i32);
                assert_eq!(Nearest::sample(&tex, Repeat, Repeat, u, v), want);
                assert_eq!(Bilinear::sample(&tex, Repeat, Repeat, u, v), want);
                assert_eq!(BilinearFast::sample(&tex, Repeat, Repeat, u, v), want);
                // Nearest anywhere inside the texel.
                for (du, dv) in [(0, 0), (0xFFFF, 0xFFFF), (1, 0x7FFF)] {
                    let (u, v) = (((i << 16) + du) as i32, ((j << 16) + dv) as i32);
                    assert_eq!(Nearest::sample(&tex, Repeat, Repeat, u, v), want);
                }
                // Same texel one tile away, negative side.
                let (u, v) = (u - (w << 16) as i32, v - ((3 * h) << 16) as i32);
                assert_eq!(Nearest::sample(&tex, Repeat, Repeat, u, v), want);
                assert_eq!(Bilinear::sample(&tex, Repeat, Repeat, u, v), want);
            }
        }
    }

    #[test]
    fn bilinear_halfway() {
        // Two texels side by side, sample exactly between their centres: round half up of
        // the average per channel.
        let mut rng = Rng(7);
        for _ in 0..2000 {
            let (a, b) = (rng.next() as u16, rng.next() as u16);
            let texels = raw_tex(&[a, b]);
            let tex = Texture::new(&texels, 2, 1).unwrap();
            let got = Bilinear::sample(&tex, ClampToEdge, ClampToEdge, 0x10000, 0x8000);
            let (ca, cb) = (chans(a), chans(b));
            let want = rgb565(
                ((ca[0] + cb[0] + 1.0) / 2.0).floor() as u8,
                ((ca[1] + cb[1] + 1.0) / 2.0).floor() as u8,
                ((ca[2] + cb[2] + 1.0) / 2.0).floor() as u8,
            );
            assert_eq!(got, want, "{a:#06x} {b:#06x}");
            // Vertical pair (1x2) likewise.
            let tex = Texture::new(&texels, 1, 2).unwrap();
            let got = Bilinear::sample(&tex, ClampToEdge, ClampToEdge, 0x8000, 0x10000);
            assert_eq!(got, want);
        }
        // Quarter way between black and white red channel: 31 * 0.25 = 7.75 -> 8.
        let texels = raw_tex(&[0x0000, 0xF800]);
        let tex = Texture::new(&texels, 2, 1).unwrap();
        let got = Bilinear::sample(&tex, ClampToEdge, ClampToEdge, 0x8000 + 0x4000, 0x8000);
        assert_eq!(got, rgb565(8, 0, 0));
    }

    #[test]
    fn thin_textures() {
        let row = raw_tex(&[1, 2, 3, 4, 5, 6, 7, 8]);
        let wide = Texture::new(&row, 8, 1).unwrap();
        let tall = Texture::new(&row, 1, 8).unwrap();
        let one = Texture::new(&row[..1], 1, 1).unwrap();
        let mut rng = Rng(99);
        for k in 0..8i32 {
            let c = (k << 16) + 0x8000;
            let any = rng.next() as i32;
            assert_eq!(Nearest::sample(&wide, Repeat, Repeat, c, any), row_raw(k));
            assert_eq!(Bilinear::sample(&wide, Repeat, Repeat, c, any), row_raw(k));
            assert_eq!(Nearest::sample(&tall, Repeat, Repeat, any, c), row_raw(k));
            assert_eq!(Bilinear::sample(&tall, Repeat, Repeat, any, c), row_raw(k));
        }
        for _ in 0..1000 {
            let (u, v) = (rng.next() as i32, rng.next() as i32);
            assert_eq!(Nearest::sample(&one, Repeat, MirroredRepeat, u, v), 1);
            assert_eq!(Bilinear::sample(&one, ClampToEdge, Repeat, u, v), 1);
        }
        // 1x1 with border: inside [0,1)^2 nearest is the texel, outside the border.
        let one = one.with_border_raw(0xFFFF);
        assert_eq!(
            Nearest::sample(&one, ClampToBorder, ClampToBorder, 0, 0xFFFF),
            1
        );
        assert_eq!(
            Nearest::sample(&one, ClampToBorder, ClampToBorder, -1, 0),
            0xFFFF
        );
        assert_eq!(
            Nearest::sample(&one, ClampToBorder, ClampToBorder, 0, 0x10000),
            0xFFFF
        );

        fn row_raw(k: i32) -> u16 {
            k as u16 + 1
        }
    }

    #[test]
    fn border_colour() {
        let texels = raw_tex(&[0x0000; 16]);
        let tex = Texture::new(&texels, 4, 4)
            .unwrap()
            .with_border(Rgb565::new(31, 0, 31));
        let border = rgb565(31, 0, 31);
        let b = ClampToBorder;
        for (u, v) in [
            (-1, 0),
            (0, -1),
            (4 << 16, 0),
            (0, 4 << 16),
            (i32::MIN, i32::MAX),
        ] {
            assert_eq!(Nearest::sample(&tex, b, b, u, v), border, "{u} {v}");
        }
        // Only one axis clamps to border: the other repeats.
        assert_eq!(Nearest::sample(&tex, Repeat, b, -1, 0), 0);
        assert_eq!(Nearest::sample(&tex, b, Repeat, -1, 0), border);
        // Bilinear at the left edge (u = 0): half texel, half border.
        let got = Bilinear::sample(&tex, b, b, 0, 0x8000);
        assert_eq!(got, rgb565(16, 0, 16));
        // At a corner: a quarter texel, three quarters border: 31 * 0.75 = 23.25 -> 23.
        let got = Bilinear::sample(&tex, b, b, 0, 0);
        assert_eq!(got, rgb565(23, 0, 23));
        // Far outside: all border.
        assert_eq!(Bilinear::sample(&tex, b, b, -(10 << 16), 0x8000), border);
        // Inside at centres: no border bleed.
        assert_eq!(Bilinear::sample(&tex, b, b, 0x8000, 0x8000), 0);
    }

    #[test]
    fn all_modes_match_reference_any_input() {
        let mut rng = Rng(0x5EED);
        let modes = [
            Wrap::Repeat,
            Wrap::MirroredRepeat,
            Wrap::ClampToEdge,
            Wrap::ClampToBorder,
        ];
        let extremes = [
            i32::MIN,
            i32::MIN + 1,
            -1,
            0,
            1,
            0x7FFF,
            0x8000,
            i32::MAX - 1,
            i32::MAX,
        ];
        for &(w, h) in &[(1u32, 1u32), (1, 8), (8, 1), (4, 16), (32, 2)] {
            let texels = random_tex(&mut rng, w, h);
            let tex = Texture::new(&texels, w, h).unwrap().with_border_raw(0x1234);
            for mu in modes {
                for mv in modes {
                    let mut coords: Vec<(i32, i32)> = vec![];
                    for &a in &extremes {
                        for &b in &extremes {
                            coords.push((a, b));
                        }
                    }
                    for _ in 0..2000 {
                        coords.push((rng.next() as i32, rng.next() as i32));
                        // Near the texture: within +-8 tiles.
                        let nu = (rng.next() % (w << 20)) as i32 - (w << 19) as i32;
                        let nv = (rng.next() % (h << 20)) as i32 - (h << 19) as i32;
                        coords.push((nu, nv));
                    }
                    for (u, v) in coords {
                        let exact = reference_bilinear(&tex, [mu, mv], u, v);
                        let got = chans(tex.sample_dyn(Filter::Bilinear, mu, mv, u, v));
                        for k in 0..3 {
                            assert!(
                                (got[k] - exact[k]).abs() < 1.0,
                                "{mu:?}/{mv:?} {w}x{h} u {u} v {v}"
                            );
                        }
                        // Nearest: the texel containing (u, v), floor in f64.
                        let iu = (u as f64 / 65536.0).floor() as i64;
                        let iv = (v as f64 / 65536.0).floor() as i64;
                        let want = ref_texel(&tex, [mu, mv], iu, iv);
                        let got = chans(tex.sample_dyn(Filter::Nearest, mu, mv, u, v));
                        assert_eq!(got, want, "nearest {mu:?}/{mv:?} u {u} v {v}");
                    }
                }
            }
        }
    }

    #[test]
    fn dyn_matches_markers() {
        let mut rng = Rng(3);
        let texels = random_tex(&mut rng, 16, 8);
        let tex = Texture::new(&texels, 16, 8)
            .unwrap()
            .with_border_raw(0xABCD);
        for _ in 0..20_000 {
            let (u, v) = (
                (rng.next() % (64 << 16)) as i32 - (32 << 16),
                (rng.next() % (32 << 16)) as i32 - (16 << 16),
            );
            assert_eq!(
                tex.sample_dyn(
                    Filter::Bilinear,
                    Wrap::MirroredRepeat,
                    Wrap::ClampToBorder,
                    u,
                    v
                ),
                Bilinear::sample(&tex, MirroredRepeat, ClampToBorder, u, v)
            );
            assert_eq!(
                tex.sample_dyn(Filter::Nearest, Wrap::ClampToEdge, Wrap::Repeat, u, v),
                Nearest::sample(&tex, DynWrap(Wrap::ClampToEdge), Repeat, u, v)
            );
        }
        assert_eq!(Nearest::FILTER, Filter::Nearest);
        assert_eq!(Bilinear::FILTER, Filter::Bilinear);
        assert_eq!(Filter::default(), Filter::Nearest);
    }

    /// The packed weights are the four Q8 weights packed, for every pair of fractions.
    #[test]
    fn packed_weights_match_the_four_weights() {
        for a in 0..=256 {
            for b in 0..=256 {
                let w = q8_weights(a, b);
                assert_eq!(
                    packed_q8_weights(a, b),
                    (w[1] | w[0] << 16, w[3] | w[2] << 16),
                    "a = {a}, b = {b}"
                );
            }
        }
    }

    /// The two- and four-texels-per-multiply blends equal the per-texel form on every texel
    /// and weight set, unscaled and scaled alike.
    #[test]
    fn blend_pair_form_matches_per_texel_form() {
        let mut rng = Rng(0x2545_F491);
        for _ in 0..200_000 {
            let c = [0; 4].map(|_: u16| rng.next() as u16);
            let a = rng.next() % 257;
            let b = rng.next() % 257;
            let i = rng.next() % 257;
            let w11 = (a * b + 128) >> 8;
            let w = [256 + w11 - a - b, a - w11, b - w11, w11];
            let ai = (a * i + 128) >> 8;
            let bi = (b * i + 128) >> 8;
            let w11 = (a * b * i + 32768) >> 16;
            let ws = [(i + w11).saturating_sub(ai + bi), ai - w11, bi - w11, w11];
            for w in [w, ws] {
                let want = blend_weights_masks(c, w);
                assert_eq!(blend_pairs_u32(c, w, Round), want);
                assert_eq!(blend_pairs_u64(c, w, Round), want);
                assert_eq!(
                    blend_pairs_u32(c, w, Scale(i)),
                    blend_pairs_u64(c, w, Scale(i))
                );
            }
        }
        for c in [[0xFFFF; 4], [0; 4], [0xF800, 0x07E0, 0x001F, 0xFFFF]] {
            for w in [[256, 0, 0, 0], [64; 4], [0, 0, 0, 256], [255, 1, 0, 0]] {
                let want = blend_weights_masks(c, w);
                assert_eq!(blend_pairs_u32(c, w, Round), want);
                assert_eq!(blend_pairs_u64(c, w, Round), want);
                for i in [0, 1, 255, 256] {
                    assert_eq!(
                        blend_pairs_u32(c, w, Scale(i)),
                        blend_pairs_u64(c, w, Scale(i))
                    );
                }
            }
        }
    }

    /// The lit blend is the single rounding of `sum w c i / 65536`, channel by channel,
    /// with the sums taken texel by texel here.
    #[test]
    fn scaled_blend_rounds_once() {
        let mut rng = Rng(0x5EED_1234);
        let chans = |t: u16| [(t >> 11) as u32, ((t >> 5) & 63) as u32, (t & 31) as u32];
        for n in 0..300_000 {
            let c = [0; 4].map(|_: u16| rng.next() as u16);
            let (a, b, i) = if n < 8 {
                (
                    [0, 256, 255, 0, 256, 1, 128, 255][n],
                    [0, 256, 0, 255, 256, 1, 128, 255][n],
                    256,
                )
            } else {
                (rng.next() % 257, rng.next() % 257, rng.next() % 257)
            };
            let w = q8_weights(a, b);
            let mut want = [0u32; 3];
            for (k, out) in want.iter_mut().enumerate() {
                let sum: u64 = (0..4).map(|t| u64::from(w[t] * chans(c[t])[k])).sum();
                *out = ((sum * u64::from(i) + 32768) >> 16) as u32;
            }
            let want = ((want[0] << 11) | (want[1] << 5) | want[2]) as u16;
            assert_eq!(
                blend_q8_scaled(c, a, b, i),
                want,
                "c {c:?} a {a} b {b} i {i}"
            );
        }
    }

    #[test]
    fn split_half_matches_float() {
        let mut rng = Rng(11);
        let mut cs: Vec<i32> = vec![i32::MIN, i32::MIN + 1, i32::MAX, -1, 0, 1, 0x8000, 0x7FFF];
        cs.extend((0..100_000).map(|_| rng.next() as i32));
        for c in cs {
            let (i0, f) = split_half(c);
            let x = c as i64 - 0x8000;
            assert_eq!(i0 as i64, x.div_euclid(0x10000), "c = {c}");
            assert_eq!(f as i64, x.rem_euclid(0x10000), "c = {c}");
        }
    }
}
