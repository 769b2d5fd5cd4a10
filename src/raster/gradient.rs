//! Plane equations for interpolating a vertex attribute linearly in screen space.
//!
//! An attribute with values `a0, a1, a2` at the three screen vertices is the plane
//! `a(x, y) = a_ref + (px - px_ref) dadx + (py - py_ref) dady` over pixel centres. The
//! pipeline evaluates it once per span start (two multiplies) and steps `dadx` per pixel.
//!
//! # Arithmetic and error budget
//! * Inputs: attribute values `|a| < 2^31` (any fixed-point format: the plane does not care),
//!   vertex positions in 1/4096 pixel ([`ATTR_SUBPIXEL_BITS`], the unsnapped projections:
//!   attributes are not moved by the 1/16-pixel snapping of coverage) inside the guard band
//!   (`|x|, |y| <= 2^24`), so vertex differences are `< 2^25`, the doubled area `< 2^51` and
//!   the numerators `Δa·Δy` `< 2^58`.
//! * Per triangle, the screen-space derivatives of two barycentric weights are computed once,
//!   each the rounded quotient `Δy 2^K / area2` (a reciprocal of the area, no division
//!   instruction per quotient) with `K` chosen so the largest uses 31 bits. A plane's
//!   gradient, with 8 extra fraction bits, is then `Δa1 dl1 + Δa2 dl2`: two `i32` products
//!   per axis. Its relative error is below 2^-30, orders of magnitude under what the
//!   1/4096-pixel positions decide; slivers (weights changing by more than ~2^20 per pixel)
//!   and attribute differences beyond `i32` take the exactly rounded quotient
//!   `(Δa·Δy) 2^20 / area2` instead (when that shift would overflow, as quotient and
//!   remainder).
//! * The reference value at a pixel centre is taken from that high-precision gradient, so it
//!   is within one unit of the plane's value wherever the reference lies (for the
//!   barycentric path, plus the gradient's error times the distance, under a unit within a
//!   pixel of vertex 0).
//! * The reference pixel is vertex 0's pixel clamped into the *viewport* (never a band), so
//!   a frame drawn in bands evaluates exactly the same integers as one drawn whole.
//! * Per-pixel values use `i32` **wrapping** arithmetic on purpose: set-up is exact modulo
//!   2^32, so wherever the true value fits `i32` (at every covered pixel centre, which is a
//!   convex combination of the vertex values) the wrapped sum is that value, even when the
//!   reference lies far outside the triangle. Rounding of `dadx`/`dady` adds at most half a
//!   unit per pixel of distance from the reference: at most `(width + height) / 2` units
//!   across the viewport.

use super::{Rect, ATTR_SUBPIXEL_BITS};
use crate::math::div_u64;
use crate::math::recip32::Recip32;
use crate::math::wide;
use crate::math::wide::{mul_wide, mul_wide_signed};

/// Extra fraction bits of the set-up gradient.
const EXTRA: u32 = 8;

/// Fraction bits of a gradient per pixel as set up: the positions' sub-pixel bits (the area
/// is in their units squared) plus [`EXTRA`].
const SHIFT: u32 = ATTR_SUBPIXEL_BITS + EXTRA;

/// Shared, per-triangle part of plane set-up: vertex deltas, the barycentric weights'
/// derivatives and the reference pixel.
#[derive(Clone, Copy, Debug)]
pub struct PlaneSetup {
    /// Vertices 1 and 2 minus vertex 0, 1/4096 pixel (`|.| < 2^25` in the guard band).
    dx1: i32,
    dy1: i32,
    dx2: i32,
    dy2: i32,
    area2: i64,
    /// Offset of the reference pixel centre from vertex 0, 1/4096 pixel.
    ref_dx: i32,
    ref_dy: i32,
    /// The screen-space derivatives of the barycentric weights of vertices 1 and 2,
    /// `[dl1/dx, dl2/dx, dl1/dy, dl2/dy]` per pixel, times `2^(EXTRA + cshift)`, each within
    /// three units of the exact ratio and below 2^31 in magnitude (the largest uses 30 or
    /// 31 of the bits): a plane's gradient is then two `i32 x i32` products, no division.
    bary: [i32; 4],
    /// Fraction bits of `bary` beyond `EXTRA`, `1..=62`; `0` disables the barycentric path
    /// (slivers whose weights change by more than ~2^20 per pixel), which sends every plane
    /// down the exact division path.
    cshift: u32,
    /// `2^(EXTRA + cshift - 4)` capped at 2^31: attribute differences below it keep the
    /// barycentric gradient within half a unit per pixel of the exact one (before both are
    /// rounded); larger ones take the exact path.
    bary_below: u32,
    /// `2^(cshift - 1)`, the rounding term of the barycentric gradients.
    bary_round: i64,
    /// Reference pixel.
    pub px_ref: i32,
    /// Reference row.
    pub py_ref: i32,
}

impl PlaneSetup {
    /// Prepares plane set-up for the triangle `v` (1/4096-pixel units, [`ATTR_SUBPIXEL_BITS`],
    /// guard band) whose doubled signed area is non-zero; the reference pixel is clamped into
    /// `viewport`. Returns `None` for zero area.
    pub fn new(v: [(i32, i32); 3], viewport: Rect) -> Option<Self> {
        let dx1 = v[1].0.wrapping_sub(v[0].0);
        let dy1 = v[1].1.wrapping_sub(v[0].1);
        let dx2 = v[2].0.wrapping_sub(v[0].0);
        let dy2 = v[2].1.wrapping_sub(v[0].1);
        let area2 = mul_wide_signed(dx1, dy2).wrapping_sub(mul_wide_signed(dx2, dy1));
        if area2 == 0 {
            return None;
        }
        let px_ref =
            (v[0].0 >> ATTR_SUBPIXEL_BITS).clamp(viewport.x0, (viewport.x1 - 1).max(viewport.x0));
        let py_ref =
            (v[0].1 >> ATTR_SUBPIXEL_BITS).clamp(viewport.y0, (viewport.y1 - 1).max(viewport.y0));
        // The reference lies in the viewport (at most 2^11 pixels): its centre fits i32.
        let centre = |p: i32| (p << ATTR_SUBPIXEL_BITS) + (1 << (ATTR_SUBPIXEL_BITS - 1));
        let (bary, cshift) =
            barycentric_derivatives([dy2, dy1.wrapping_neg(), dx2.wrapping_neg(), dx1], area2);
        Some(PlaneSetup {
            dx1,
            dy1,
            dx2,
            dy2,
            area2,
            ref_dx: centre(px_ref).wrapping_sub(v[0].0),
            ref_dy: centre(py_ref).wrapping_sub(v[0].1),
            bary,
            cshift,
            bary_below: 1u32 << (EXTRA + cshift).saturating_sub(4).min(31),
            bary_round: wide::shl(1, cshift.wrapping_sub(1)),
            px_ref,
            py_ref,
        })
    }

    /// Doubled signed area in 1/4096-pixel units squared (positive: clockwise on a y-down
    /// screen).
    pub fn area2(&self) -> i64 {
        self.area2
    }

    /// The plane through the attribute values `a` at the three vertices.
    ///
    /// Its gradient is `(a1 - a0) dl1 + (a2 - a0) dl2` from the per-triangle barycentric
    /// derivatives (two `i32 x i32` products per axis). Each derivative is within three
    /// units of `2^(EXTRA + cshift)`, so the gradient is off by at most
    /// `3 (|a1 - a0| + |a2 - a0|) 2^-(EXTRA + cshift)` units per pixel before its final
    /// rounding: the differences are held below `2^(EXTRA + cshift - 4)` for this path, which
    /// bounds that by half a unit (the rounded `dx`, `dy` are then within one unit of the
    /// exact path's); on the benchmark meshes it is under 2^-8 unit. Slivers and larger
    /// differences take the exactly rounded quotient ([`Self::plane_exact`]).
    #[inline(never)]
    pub fn plane(&self, a: [i32; 3]) -> Plane {
        let cs = self.cshift;
        let (d1, o1) = a[1].overflowing_sub(a[0]);
        let (d2, o2) = a[2].overflowing_sub(a[0]);
        // On 32-bit cores both tests in one sign bit (fewer instructions than two overflow
        // flags there): a difference overflowed when both operands' signs differ and the
        // result's differs from the minuend's.
        let wrapped = if cfg!(target_pointer_width = "64") {
            o1 | o2
        } else {
            ((a[1] ^ a[0]) & (a[1] ^ d1)) | ((a[2] ^ a[0]) & (a[2] ^ d2)) < 0
        };
        let (gx, gy) =
            if cs != 0 && !wrapped && (d1.unsigned_abs() | d2.unsigned_abs()) < self.bary_below {
                let c = &self.bary;
                // Each product is below 2^62 in magnitude: the sums fit i64.
                let gxw = wide::dot2(d1, d2, c[0], c[1]);
                let gyw = wide::dot2(d1, d2, c[2], c[3]);
                let round = self.bary_round;
                // `cs` is in 1..=62: on 32-bit cores each half of the shift written for
                // its range (see `sar_below_32`).
                if cfg!(target_pointer_width = "64") {
                    (
                        wide::sar(gxw.wrapping_add(round), cs),
                        wide::sar(gyw.wrapping_add(round), cs),
                    )
                } else if cs >= 32 {
                    (
                        i64::from(sar_high(gxw.wrapping_add(round), cs)),
                        i64::from(sar_high(gyw.wrapping_add(round), cs)),
                    )
                } else {
                    (
                        sar_below_32(gxw.wrapping_add(round), cs),
                        sar_below_32(gyw.wrapping_add(round), cs),
                    )
                }
            } else {
                self.exact_gradients(a)
            };
        self.finish(a[0], gx, gy)
    }

    /// [`Self::plane`] with the gradient as the exactly rounded quotient `n 2^SHIFT / area2`
    /// (the path for slivers and attribute differences beyond the barycentric path's bound;
    /// also the reference the tests hold that path to).
    pub fn plane_exact(&self, a: [i32; 3]) -> Plane {
        let (gx, gy) = self.exact_gradients(a);
        self.finish(a[0], gx, gy)
    }

    /// The gradients of [`Self::plane_exact`] (per pixel, `EXTRA` more fraction bits), `(0,
    /// 0)` for zero area. Out of line, apart from [`Self::finish`]: [`Self::plane`] shares
    /// its copy of that with the fast path.
    #[cold]
    #[inline(never)]
    fn exact_gradients(&self, a: [i32; 3]) -> (i64, i64) {
        let Some(div) = ExactDivisor::new(self.area2) else {
            return (0, 0);
        };
        let da1 = i64::from(a[1]) - i64::from(a[0]);
        let da2 = i64::from(a[2]) - i64::from(a[0]);
        let (dx1, dy1, dx2, dy2) = (
            i64::from(self.dx1),
            i64::from(self.dy1),
            i64::from(self.dx2),
            i64::from(self.dy2),
        );
        // d a / d x and d a / d y in units per 1/4096 pixel, times area2.
        let nx = mul(da1, dy2) - mul(da2, dy1);
        let ny = mul(da2, dx1) - mul(da1, dx2);
        // Per pixel (<< ATTR_SUBPIXEL_BITS) with EXTRA more fraction bits.
        (div.gradient(nx), div.gradient(ny))
    }

    /// The plane from its gradient `gx, gy` (per pixel, `EXTRA` more fraction bits) and its
    /// value `a0` at vertex 0.
    #[inline(always)]
    fn finish(&self, a0: i32, gx: i64, gy: i64) -> Plane {
        // Value at the reference centre: a0 + (gx ref_dx + gy ref_dy) / 2^(EXTRA + ATTR_SUBPIXEL_BITS)
        // (gx is per pixel, ref_dx in 1/4096 pixel).
        // Wrapping is exact modulo 2^64, hence modulo 2^32 after the shift.
        let off = mul(gx, i64::from(self.ref_dx)).wrapping_add(mul(gy, i64::from(self.ref_dy)));
        let round = 1i64 << (SHIFT - 1);
        let a_ref = i64::from(a0).wrapping_add(off.wrapping_add(round) >> SHIFT);
        let half = 1i64 << (EXTRA - 1);
        Plane {
            at_ref: a_ref as i32,
            dx: (gx.wrapping_add(half) >> EXTRA) as i32,
            dy: (gy.wrapping_add(half) >> EXTRA) as i32,
        }
    }
}

/// `x >> s` (arithmetic) for `s` in `32..=63`: the high word shifted by `s - 32` (the
/// value fits `i32`), in two instructions on 32-bit cores.
#[inline(always)]
fn sar_high(x: i64, s: u32) -> i32 {
    ((x >> 32) as i32) >> (s.wrapping_sub(32) & 31)
}

/// `x >> s` (arithmetic) for `s` in `1..=31`, word by word: five instructions on 32-bit
/// cores, where LLVM's 64-bit shift by a register tests for shifts past 32 (eleven). With
/// [`sar_high`], the barycentric planes' shift (`cs`, `1..=62`) of
/// [`PlaneSetup::plane`]: about 0.5 % of the Cortex-M4F whole-frame sphere and a little
/// less on Cortex-M0+ and RV32IMC (measure with `cargo xtask mcu`).
#[inline(always)]
fn sar_below_32(x: i64, s: u32) -> i64 {
    let (hi, lo) = ((x >> 32) as i32, x as u32);
    let s = s & 31;
    let lo = (lo >> s) | (hi as u32).wrapping_shl(32 - s);
    (i64::from(hi >> s) << 32) | i64::from(lo)
}

/// `num 2^(SHIFT + cshift) / area2` for the four numerators (the barycentric weights'
/// derivatives per pixel, see [`PlaneSetup::bary`]) with the largest `cshift` that keeps
/// them below 2^31, from one 32-bit reciprocal of the area: `|area2|` normalized to
/// `2^31 <= an < 2^32` (dropping bits below its top 32: relative error under 2^-31), `R =
/// floor((2^63 - 1) / an)` (`2^31 <= R < 2^32`, relative error under 2^-31), then
/// `|num| R / 2^(bn + 1)` rounded, where `2^bn > max |num|`: below 2^31, and within
/// `0.5 + 2^31 (2^-31 + 2^-31)` < 3 units of the exact ratio. `cshift = 0` when no shift in
/// `1..=62` fits (slivers; never for a triangle wider than 2^-21 pixel).
fn barycentric_derivatives(nums: [i32; 4], area2: i64) -> ([i32; 4], u32) {
    let a = area2.unsigned_abs();
    let ba = 64 - wide::clz64(a);
    let an = if ba >= 32 {
        wide::shr(a, ba - 32) as u32
    } else {
        (a as u32).wrapping_shl(32 - ba)
    };
    let num_max = nums.iter().fold(0u32, |m, n| m | n.unsigned_abs());
    let bn = 32 - wide::clz32(num_max);
    // num / area2 2^(SHIFT + cs) = |num| R 2^(SHIFT + cs - 63 - (ba - 32)), which is
    // |num| R / 2^(bn + 1) for:
    let cs = (63 + ba).wrapping_sub(32 + SHIFT + 1 + bn);
    if an < 1 << 31 || !(1..=62).contains(&cs) {
        return ([0; 4], 0);
    }
    // floor((2^63 - 1) / an) from a reciprocal (an is normalized: no shift).
    let r = Recip32::new_normalized(an).recip63();
    // The sign of each quotient: all ones where `n` and the area differ in sign.
    let area_sign = (area2 >> 32) as i32;
    let signed = |q: u32, n: i32| {
        let s = (n ^ area_sign) >> 31;
        ((q as i32) ^ s).wrapping_sub(s)
    };
    let c = if bn <= 30 {
        // In the guard band `bn <= 26` (vertex differences below 2^25): the shift is at
        // most 31, so the quotient (below 2^31) is the low word of two words shifted.
        let round = u64::from(1u32 << bn);
        nums.map(|n| {
            signed(
                low_word_shr(mul_wide(n.unsigned_abs(), r) + round, bn + 1),
                n,
            )
        })
    } else {
        nums.map(|n| {
            let q = wide::shr(mul_wide(n.unsigned_abs(), r).wrapping_add(1 << bn), bn + 1);
            signed(q as u32, n)
        })
    };
    (c, cs)
}

/// The low word of `x >> s` for `s` in `1..=31`, from the two words: three instructions on
/// 32-bit cores, where LLVM's 64-bit shift by a register tests for shifts past 32. In
/// [`barycentric_derivatives`] (four per triangle), with the rounding term as a 32-bit
/// shift and the signs applied by mask: about 0.4 % of the whole-frame sphere on
/// Cortex-M4F and Cortex-M0+, a little less on RV32IMC (measure with `cargo xtask mcu`).
#[inline(always)]
fn low_word_shr(x: u64, s: u32) -> u32 {
    let (hi, lo) = ((x >> 32) as u32, x as u32);
    (lo >> (s & 31)) | hi.wrapping_shl(32u32.wrapping_sub(s))
}

/// The exact division by the doubled area behind [`PlaneSetup::plane_exact`]: the rare
/// path (slivers, large attribute differences), so it is written for flash, not speed
/// ([`div_u64`] for every quotient).
#[derive(Clone, Copy, Debug)]
struct ExactDivisor {
    /// `area2 >> norm`, below 2^32 in magnitude: the gradients' divisor (exact for
    /// `norm == 0`, relative error below 2^-31 otherwise: far under one unit of any
    /// gradient that fits `i32`).
    area_n: i64,
    norm: u32,
}

impl ExactDivisor {
    /// `None` for zero area.
    fn new(area2: i64) -> Option<Self> {
        let norm = (64 - area2.unsigned_abs().leading_zeros()).saturating_sub(31);
        let area_n = area2 >> norm;
        (area_n != 0).then_some(ExactDivisor { area_n, norm })
    }

    /// `n 2^SHIFT / area2` rounded (ties away from zero), `SHIFT = ATTR_SUBPIXEL_BITS +
    /// EXTRA`, as `n 2^(SHIFT - norm) / area_n`. On magnitudes, with `k = SHIFT - norm`:
    /// `m = q1 area_n + r1` (one division), then `m 2^k / area_n = q1 2^k + r1 2^k /
    /// area_n`, whose rounding is `q1 2^k` plus the rounded second quotient (a second
    /// division: `r1 < 2^31`, so `r1 2^k < 2^52`). Exact for every `n`, wrapping modulo 2^64
    /// where the quotient does not fit. For huge triangles (`norm > SHIFT`) the numerator is
    /// shifted right (rounded) instead and `k = 0`. Out of line: one copy for both axes.
    #[inline(never)]
    fn gradient(&self, n: i64) -> i64 {
        let (n, k) = if self.norm > SHIFT {
            let j = (self.norm - SHIFT).min(62);
            ((n >> j) + ((n >> (j - 1)) & 1), 0)
        } else {
            (n, SHIFT - self.norm)
        };
        let d = self.area_n.unsigned_abs();
        let m = n.unsigned_abs();
        let q1 = div_u64(m, d);
        let r1 = m - q1 * d;
        let q = (q1 << k).wrapping_add(div_u64((r1 << k) + d / 2, d)) as i64;
        if (n < 0) == (self.area_n < 0) {
            q
        } else {
            q.wrapping_neg()
        }
    }
}

/// `a * b` (wrapping), exactly. On ARMv6-M, where a 64-bit product is a library call
/// (`__aeabi_lmul`), the common case of `a` within `i32` and `b` within `i16` is two 32-bit
/// multiplies: with `a = ah 2^16 + al`, `a b = (ah b) 2^16 + al b`, both products in `i32`;
/// both within `i32`, four 16 x 16-bit products.
#[inline(always)]
fn mul(a: i64, b: i64) -> i64 {
    #[cfg(all(target_arch = "arm", not(target_has_atomic = "32")))]
    {
        mul_split(a, b)
    }
    #[cfg(not(all(target_arch = "arm", not(target_has_atomic = "32"))))]
    {
        a.wrapping_mul(b)
    }
}

/// The 32-bit-multiply form of [`mul`] (compiled everywhere so every target tests it).
#[cfg_attr(
    not(all(target_arch = "arm", not(target_has_atomic = "32"))),
    allow(dead_code)
)]
#[inline(always)]
fn mul_split(a: i64, b: i64) -> i64 {
    if a as i32 as i64 == a && b as i16 as i64 == b {
        let (a, b) = (a as i32, b as i32);
        let (ah, al) = (a >> 16, a & 0xFFFF);
        (i64::from(ah * b) << 16) + i64::from(al * b)
    } else if a as i32 as i64 == a && b as i32 as i64 == b {
        // Signed 32 x 32 -> 64 from the unsigned product of the magnitudes.
        let p = crate::math::wide::mul_wide_split(a.unsigned_abs() as u32, b.unsigned_abs() as u32)
            as i64;
        if (a < 0) != (b < 0) {
            p.wrapping_neg()
        } else {
            p
        }
    } else {
        a.wrapping_mul(b)
    }
}

/// An attribute's screen-space plane, in the attribute's own fixed-point format.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Plane {
    /// Value at the reference pixel centre.
    pub at_ref: i32,
    /// Change per pixel to the right.
    pub dx: i32,
    /// Change per pixel down.
    pub dy: i32,
}

impl Plane {
    /// Value at the centre of pixel `(px, py)`, given the set-up's reference pixel.
    #[inline(always)]
    pub fn at(&self, setup_ref: (i32, i32), px: i32, py: i32) -> i32 {
        self.at_ref
            .wrapping_add(px.wrapping_sub(setup_ref.0).wrapping_mul(self.dx))
            .wrapping_add(py.wrapping_sub(setup_ref.1).wrapping_mul(self.dy))
    }
}

#[cfg(test)]
mod tests {
    extern crate std;
    use super::*;
    use crate::test_rng::Rng;

    /// The plane's one-sign-bit test of its two differences is their overflow flags'.
    #[test]
    fn wrapped_differences_are_the_overflow_flags() {
        let mut rng = crate::test_rng::Rng(0x0F1_0A7);
        let edges = [i32::MIN, i32::MIN + 1, -1, 0, 1, i32::MAX - 1, i32::MAX];
        for i in 0..300_000u32 {
            let pick = |rng: &mut crate::test_rng::Rng| match i % 3 {
                0 => edges[(rng.next() % 7) as usize],
                _ => (rng.next() >> (32 + i % 32)) as u32 as i32,
            };
            let a = [pick(&mut rng), pick(&mut rng), pick(&mut rng)];
            let (d1, o1) = a[1].overflowing_sub(a[0]);
            let (d2, o2) = a[2].overflowing_sub(a[0]);
            let wrapped = ((a[1] ^ a[0]) & (a[1] ^ d1)) | ((a[2] ^ a[0]) & (a[2] ^ d2));
            assert_eq!(wrapped < 0, o1 | o2, "{a:?}");
        }
    }

    /// The plane's two word-wise shifts are `wide::sar` over their ranges of `s`.
    #[test]
    fn split_shifts_equal_the_64_bit_shift() {
        let mut rng = crate::test_rng::Rng(0x5A5_1F7);
        for i in 0..200_000u32 {
            let x = (rng.next() as i64) >> (i % 40);
            let s = 1 + i % 62;
            let want = wide::sar(x, s);
            if s >= 32 {
                assert_eq!(i64::from(sar_high(x, s)), want, "{x} >> {s}");
            } else {
                assert_eq!(sar_below_32(x, s), want, "{x} >> {s}");
            }
        }
    }

    fn exact(v: [(i32, i32); 3], a: [i32; 3], px: i32, py: i32) -> f64 {
        let one = f64::from(1u32 << ATTR_SUBPIXEL_BITS);
        let f = |p: (i32, i32)| (p.0 as f64 / one, p.1 as f64 / one);
        let (p0, p1, p2) = (f(v[0]), f(v[1]), f(v[2]));
        let (x, y) = (px as f64 + 0.5, py as f64 + 0.5);
        let area = (p1.0 - p0.0) * (p2.1 - p0.1) - (p2.0 - p0.0) * (p1.1 - p0.1);
        let l1 = ((x - p0.0) * (p2.1 - p0.1) - (p2.0 - p0.0) * (y - p0.1)) / area;
        let l2 = ((p1.0 - p0.0) * (y - p0.1) - (x - p0.0) * (p1.1 - p0.1)) / area;
        a[0] as f64 + l1 * (a[1] as f64 - a[0] as f64) + l2 * (a[2] as f64 - a[0] as f64)
    }

    /// The exact path's gradient is `n 2^(SHIFT - norm) / area_n` rounded to nearest, ties
    /// away from zero, as `i128` arithmetic gives it.
    #[test]
    fn exact_gradient_is_the_rounded_quotient() {
        let mut x = 0x9E37_79B9_7F4A_7C15u64;
        let vp = Rect::of_size(320, 240);
        for _ in 0..20_000 {
            let mut next = || {
                x ^= x << 13;
                x ^= x >> 7;
                x ^= x << 17;
                x
            };
            let scale = 8 + (next() % 17) as u32;
            let mut c = || ((next() as i64 >> 40) as i32) >> (32 - scale);
            let v = [(c(), c()), (c(), c()), (c(), c())];
            let Some(ps) = PlaneSetup::new(v, vp) else {
                continue;
            };
            let div = ExactDivisor::new(ps.area2).unwrap();
            for _ in 0..8 {
                let n = (next() as i64) >> (next() % 63);
                let (nn, d) = if div.norm > SHIFT {
                    let k = (div.norm - SHIFT).min(62);
                    (
                        i128::from((n >> k) + ((n >> (k - 1)) & 1)),
                        i128::from(div.area_n),
                    )
                } else {
                    (i128::from(n) << (SHIFT - div.norm), i128::from(div.area_n))
                };
                let q = nn / d;
                let r = nn - q * d;
                let away = if (nn < 0) == (d < 0) { 1 } else { -1 };
                let want = if 2 * r.abs() >= d.abs() { q + away } else { q };
                assert_eq!(div.gradient(n), want as i64, "{v:?} {n}");
            }
        }
    }

    /// The barycentric path agrees with the exactly rounded quotient: `dx`, `dy` within one
    /// unit, the reference value within one unit plus the gradient's error over the
    /// reference's distance from vertex 0.
    /// The word-wise shift equals the 64-bit one wherever the result fits a word.
    #[test]
    fn low_word_shifts_equal_the_64_bit_shift() {
        let mut rng = Rng(0x10_57_0D);
        for _ in 0..200_000 {
            let s = 1 + (rng.next() % 31) as u32;
            // Below 2^(31 + s): the quotient fits 31 bits, as in the barycentric path.
            let x = rng.next() >> (64 - 31 - s);
            assert_eq!(u64::from(low_word_shr(x, s)), x >> s, "{x:#x} >> {s}");
        }
    }

    #[test]
    fn barycentric_planes_match_the_exact_quotient() {
        let mut x = 0x51AF_D7ED_558C_CD27u64;
        let vp = Rect::of_size(320, 240);
        let (mut fast, mut worst) = (0u32, 0i64);
        for _ in 0..40_000 {
            let mut next = || {
                x ^= x << 13;
                x ^= x >> 7;
                x ^= x << 17;
                x
            };
            // Triangles from 1/16 pixel to the whole guard band, near and far from the
            // viewport; attributes from a few units to the whole i32 range.
            let scale = 6 + (next() % 19) as u32;
            let base = ((next() % 400) as i32 - 40) << ATTR_SUBPIXEL_BITS;
            let mut c = |b: i32| b + (((next() as i64 >> 40) as i32) >> (32 - scale));
            let v = [(c(base), c(base)), (c(base), c(base)), (c(base), c(base))];
            let bits = 2 + (next() % 30) as u32;
            let mut a = || ((next() >> 32) as i32) >> (32 - bits);
            let attr = [a(), a(), a()];
            let Some(ps) = PlaneSetup::new(v, vp) else {
                continue;
            };
            let (p, e) = (ps.plane(attr), ps.plane_exact(attr));
            let d_max = (attr[1].wrapping_sub(attr[0]).unsigned_abs())
                .max(attr[2].wrapping_sub(attr[0]).unsigned_abs());
            if ps.cshift != 0 && d_max < ps.bary_below {
                fast += 1;
            }
            assert!((p.dx - e.dx).abs() <= 1, "{v:?} {attr:?}: {p:?} vs {e:?}");
            assert!((p.dy - e.dy).abs() <= 1, "{v:?} {attr:?}: {p:?} vs {e:?}");
            // Gradient error (units/pixel, before rounding) times the distance in pixels.
            let spread = (i64::from(attr[1]) - i64::from(attr[0])).abs()
                + (i64::from(attr[2]) - i64::from(attr[0])).abs();
            let err_px = spread as f64 / 2f64.powi((EXTRA + ps.cshift + 1) as i32) + 1.0 / 512.0;
            let err_px = err_px.min(0.5 + 1.0 / 512.0);
            let dist = (ps.ref_dx.unsigned_abs() + ps.ref_dy.unsigned_abs()) as f64
                / f64::from(1 << ATTR_SUBPIXEL_BITS);
            let d = i64::from(p.at_ref.wrapping_sub(e.at_ref)).abs();
            assert!(
                d as f64 <= 1.0 + err_px * dist,
                "{v:?} {attr:?}: {p:?} vs {e:?}"
            );
            if dist <= 1.5 {
                worst = worst.max(d);
            }
        }
        assert!(fast > 20_000, "barycentric path taken {fast} times");
        assert!(worst <= 1, "reference value off by {worst} near vertex 0");
    }

    #[test]
    fn split_multiply_is_exact() {
        let vals = || {
            let ends = [i64::from(i32::MAX), i64::from(i32::MIN)];
            crate::test_rng::I16_EDGES.into_iter().chain(ends)
        };
        for a in vals().chain([1 << 40, -(1 << 33) + 7]) {
            for b in vals() {
                assert_eq!(mul_split(a, b), a.wrapping_mul(b), "{a} * {b}");
            }
        }
        let mut x = 0x2545_F491_4F6C_DD1Du64;
        for _ in 0..100_000 {
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
            let a = (x as i64) >> (x % 40);
            let b = ((x >> 20) as i64) >> (20 + (x >> 60));
            assert_eq!(mul_split(a, b), a.wrapping_mul(b), "{a} * {b}");
        }
    }

    #[test]
    fn plane_matches_exact_inside_the_viewport() {
        let vp = Rect::of_size(320, 240);
        type Case = ([(i32, i32); 3], [i32; 3]);
        let cases: [Case; 3] = [
            (
                [(100, 50), (3000, 400), (900, 3500)],
                [0, 1 << 20, -(1 << 22)],
            ),
            (
                [(-60000, -60000), (60000, -50000), (0, 60000)],
                [i32::MAX - 5, 0, i32::MIN + 5],
            ),
            (
                [(5000, 5000), (5003, 5001), (4999, 5300)],
                [123456, -99999, 7],
            ),
        ];
        for (v, a) in cases {
            // The cases are in 1/16 pixel: to the attribute grid.
            let k = 1 << (ATTR_SUBPIXEL_BITS - 4);
            let v = v.map(|(x, y)| (x * k, y * k));
            let s = PlaneSetup::new(v, vp).unwrap();
            let p = s.plane(a);
            for (px, py) in [(0, 0), (319, 0), (0, 239), (319, 239), (160, 120)] {
                let got = p.at((s.px_ref, s.py_ref), px, py) as f64;
                let want = exact(v, a, px, py);
                if want.abs() < 2f64.powi(31) {
                    assert!(
                        (got - want).abs() <= 300.0,
                        "{v:?} {a:?} ({px},{py}): {got} vs {want}"
                    );
                }
            }
        }
    }
}
