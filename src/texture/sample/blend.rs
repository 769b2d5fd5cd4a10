//! Bilinear arithmetic on RGB565: the four Q8 weights of a sample (summing to exactly
//! 256), the channel sums formed two texels per 32-bit multiply (or four per 64-bit one on
//! 64-bit hosts), one rounding, optionally scaled by an intensity in the same rounding; and
//! [`BilinearFast`](super::BilinearFast)'s Q5 lerps on spread pixels. The samplers of
//! [`super`] gather the texels and call these.

/// Bilinear filtering with the result scaled by intensity `i` (Q8, `0..=256`) in one
/// rounding: each channel's exact sum `S = sum w c` over the four Q8 weights of
/// [`blend_q8`] (summing to 256) is multiplied by `i` and rounded once,
/// `(S i + 2^15) >> 16`, which is the nearest value to `sum w c i / 65536` (tested). One
/// rounding instead of two (bilinear to RGB565, then modulation), and the weights are not
/// scaled at all: three multiplies more than [`blend_q8`] in place of nine for filtering
/// and modulating in turn. (Scaling the weights by `i` before the sums, each rounded,
/// costs about 5 % more on the Cortex-M4F cube and 4 % on Cortex-M0+, and rounds three
/// times where this rounds once; measure with `cargo xtask mcu`.)
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
pub(super) fn q8_weights(a: u32, b: u32) -> [u32; 4] {
    let w11 = (a * b + 128) >> 8;
    // Evaluated left to right: 256 + w11 - a >= 0 since a <= 256; the result is w00 >= 0.
    [256 + w11 - a - b, a - w11, b - w11, w11]
}

/// `sum w c` per channel for Q8 weights `w` summing to at most 256, rounded: two texels
/// per multiply. A row's two texels share a word (`c0 | c1 << 16`), its two weights another
/// in the opposite order (`w1 | w0 << 16`), and the product's upper half is `c0 w0 + c1 w1`
/// (its lower half, `c0 w1 < 2^14`, never carries into it; `c1 w0` falls off the top). Six
/// multiplies for three channels where one channel pair per word takes eight; the same sums
/// and roundings as the per-texel form kept in the tests, so the same result. Against
/// that form it saves about 4 % of the cube and the bilinear floor on Cortex-M4F, 9-10 %
/// on Cortex-M0+ (one mask register serves all three channels), 2 % on RV32IMC, and up to
/// 8 % of the floor on x86-64 (measure with `cargo xtask mcu` and `cargo xtask count`).
#[inline(always)]
pub(super) fn blend_weights(c: [u16; 4], w: [u32; 4]) -> u16 {
    // Each channel's sum is at most 63 * 256 < 2^14 (weights sum to at most 256), so adding
    // half of 256 to it never overflows (see `Round`).
    blend_pairs(c, w, Round)
}

/// The dot-product sums of [`blend_weights`]: each channel's sum `sum w c`, where the
/// multiply leaves it, handed to `finish` ([`Finish`]), which returns the channel's value
/// (red and blue 0..=31, green 0..=63); packed to RGB565. Two texels per multiply on 32-bit targets
/// (`blend_pairs_u32`), four on 64-bit ones ([`blend_pairs_u64`]): the same sums, so the
/// same pixels on every target.
#[inline(always)]
pub(super) fn blend_pairs(c: [u16; 4], w: [u32; 4], finish: impl Finish) -> u16 {
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
pub(super) trait Finish: Copy {
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
pub(super) struct Round;

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
pub(super) struct Scale(pub(super) u32);

impl Finish for Scale {
    /// Written with an arithmetic shift and signed operands (`s < 2^30` and `i <= 256`, so
    /// the value is the same): on Cortex-M0+ this saves about 0.5-1 % of the footprint
    /// sphere and the cube, though the plain-bilinear adaptive sphere costs about 1 % more
    /// (register allocation); Cortex-M4F is the same either way (LLVM does not take the top
    /// half in the multiply, `smultb`), RV32IMC within about 1 % (measure with
    /// `cargo xtask mcu`).
    #[cfg(any(test, not(target_pointer_width = "64")))]
    #[inline(always)]
    fn upper_half(self, s: u32) -> u32 {
        ((((s as i32) >> 16) * (self.0 as i32) + 32768) as u32) >> 16
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
pub(super) fn blend_pairs_u32(c: [u16; 4], w: [u32; 4], finish: impl Finish) -> u16 {
    let top = c[0] as u32 | (c[1] as u32) << 16;
    let bot = c[2] as u32 | (c[3] as u32) << 16;
    blend_rows_u32(top, bot, (w[1] | w[0] << 16, w[3] | w[2] << 16), finish)
}

/// [`q8_weights`] packed as [`blend_rows_u32`] wants them, `(w10 | w00 << 16,
/// w11 | w01 << 16)`, straight from the fractions `a`, `b` (`0..=256`): with
/// `K = 1 - 2^16` (mod 2^32), the bottom word is `b << 16 + w11 K` and the two words sum to
/// `256 << 16 + a K` (the same integers as packing the four weights, tested for every `a`,
/// `b`). The footprint path uses it: about 1-2 % of the cube on Cortex-M4F, Cortex-M0+
/// and RV32IMC. The four-texel path keeps packing the four weights: there this form costs
/// about 1 % more on the Cortex-M4F sphere (measure with `cargo xtask mcu`).
#[cfg(any(test, not(target_pointer_width = "64")))]
#[inline(always)]
pub(super) fn packed_q8_weights(a: u32, b: u32) -> (u32, u32) {
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
pub(super) fn blend_rows_u32(top: u32, bot: u32, (wt, wb): (u32, u32), finish: impl Finish) -> u16 {
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
/// the top. One multiply per channel where the 32-bit form takes two and an add: on
/// x86-64 about 3 % of the bilinear floor and 4 % of the cube (`cargo xtask count`).
#[cfg(any(test, target_pointer_width = "64"))]
#[inline(always)]
pub(super) fn blend_pairs_u64(c: [u16; 4], w: [u32; 4], finish: impl Finish) -> u16 {
    let top = c[0] as u32 | (c[1] as u32) << 16;
    let bot = c[2] as u32 | (c[3] as u32) << 16;
    blend_rows_u64(top, bot, w, finish)
}

/// [`blend_pairs_u64`] from the two rows' words as they are packed (`c0 | c1 << 16`,
/// `c2 | c3 << 16`).
#[cfg(any(test, target_pointer_width = "64"))]
#[inline(always)]
pub(super) fn blend_rows_u64(top: u32, bot: u32, w: [u32; 4], finish: impl Finish) -> u16 {
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
pub(super) fn blend_weights_masks(c: [u16; 4], w: [u32; 4]) -> u16 {
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
pub(super) fn spread(c: u16) -> u32 {
    let c = c as u32;
    (c | (c << 16)) & 0x07E0_F81F
}

/// Rounded lerp of two spread colours with a Q5 weight `w` in 0..=32.
/// Lane maxima: G 63*32 + 16 < 2^11 (bits 21..=31), R 31*32 + 16 < 2^10 (bits 11..=20),
/// B 31*32 + 16 < 2^10 (bits 0..=9), so lanes never carry into each other.
#[inline(always)]
pub(super) fn lerp_q5(x: u32, y: u32, w: u32) -> u32 {
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
