//! Exact sums of I16F16 products, for dot products, cross products and matrix rows.
//!
//! A product of two `Fx` is a Q32 value of up to 2^62 in magnitude, so four of them can
//! overflow an `i64`. Each product is therefore split into its Q16 integer part
//! (`p >> 16`, at most 2^46) and its low 16 bits (`p & 0xFFFF`, in [0, 2^16)); the parts are
//! summed separately and recombined, which is exact for any number of terms up to 2^16.
//! The result is the sum rounded to Q16 (round half up, i.e. toward +∞ on exact ties) as
//! an `i64`, which the caller saturates ([`saturate`]) or checks ([`fit`]).

use super::Fx;

/// The exact Q32 product of two `Fx` (|p| <= 2^62). On ARMv6-M, which has no 64-bit
/// product instruction, four 16 x 16-bit products instead of the `__aeabi_lmul` call an
/// `i64` product compiles to (with that call, the vertex transforms' 12 products per vertex
/// are the largest single cost of the banded environment-mapping scene on Cortex-M0+).
#[inline]
pub(crate) fn prod(a: Fx, b: Fx) -> i64 {
    super::wide::mul_wide_signed(a.to_bits(), b.to_bits())
}

/// `round(Σ products / 2^16)` computed exactly; `products` are Q32 values with |p| <= 2^62.
#[inline]
pub(crate) fn sum_q32<const N: usize>(products: [i64; N]) -> i64 {
    let mut hi = 0i64;
    let mut lo = 0i64;
    for p in products {
        hi += p >> 16;
        lo += p & 0xFFFF;
    }
    hi + ((lo + (1 << 15)) >> 16)
}

/// `round(Σ a_i b_i / 2^16)` (round half up, exactly as [`sum_q32`] of the [`prod`]s) for
/// raw I16F16 operands: the row of a matrix times a vector, a dot product.
///
/// On ARMv6-M (no 64-bit product instruction) each product is split into 16-bit halves,
/// `a b = ah bh 2^32 + (ah bl + al bh) 2^16 + al bl` with `ah = a >> 16` (signed) and
/// `al = a & 0xFFFF`, so every partial product is one 32-bit `muls` that cannot overflow
/// (`|ah bh| <= 2^30`, `|ah bl| < 2^31`, `al bl < 2^32`), and the three sums are combined
/// once: `2^16 Σ ah bh + Σ (ah bl + al bh) + floor((Σ al bl + 2^15) / 2^16)`. About 40 % of
/// the instructions of the `i64` products and sums there; elsewhere the `i64` form.
#[inline]
pub(crate) fn dot_q16<const N: usize>(a: [i32; N], b: [i32; N]) -> i64 {
    #[cfg(all(target_arch = "arm", not(target_has_atomic = "32")))]
    {
        dot_q16_split(a, b)
    }
    #[cfg(not(all(target_arch = "arm", not(target_has_atomic = "32"))))]
    {
        dot_q16_i64(a, b)
    }
}

/// [`dot_q16`] out of line on ARMv6-M (one copy for the callers that are not per-vertex hot
/// paths, such as normal transforms and dot products: flash, not speed, matters there).
#[cfg_attr(not(all(target_arch = "arm", not(target_has_atomic = "32"))), inline)]
#[cfg_attr(all(target_arch = "arm", not(target_has_atomic = "32")), inline(never))]
pub(crate) fn dot3_q16_shared(a: [i32; 3], b: [i32; 3]) -> i64 {
    dot_q16(a, b)
}

/// The `i64` form of [`dot_q16`]: exact products, [`sum_q32`].
#[cfg_attr(
    all(target_arch = "arm", not(target_has_atomic = "32")),
    allow(dead_code)
)]
#[inline(always)]
fn dot_q16_i64<const N: usize>(a: [i32; N], b: [i32; N]) -> i64 {
    {
        sum_q32(core::array::from_fn::<i64, N, _>(|k| {
            prod(Fx::from_bits(a[k]), Fx::from_bits(b[k]))
        }))
    }
}

/// The 16-bit-split form of [`dot_q16`] (compiled everywhere so every target tests it).
#[cfg_attr(
    not(all(target_arch = "arm", not(target_has_atomic = "32"))),
    allow(dead_code)
)]
#[inline(always)]
pub(crate) fn dot_q16_split<const N: usize>(a: [i32; N], b: [i32; N]) -> i64 {
    let mut hh = 0i64;
    let mut mid = 0i64;
    let mut ll = 0u64;
    for k in 0..N {
        let (ah, al) = (a[k] >> 16, a[k] & 0xFFFF);
        let (bh, bl) = (b[k] >> 16, b[k] & 0xFFFF);
        hh += i64::from(ah * bh);
        mid += i64::from(ah * bl) + i64::from(al * bh);
        ll += u64::from((al as u32) * (bl as u32));
    }
    (hh << 16) + mid + ((ll + (1 << 15)) >> 16) as i64
}

/// `fit(dot_q16(a, b) + t)`: a three-term row of a matrix plus its translation, as `Fx`,
/// or `None` when it does not fit.
///
/// Where a 64-bit product is one instruction (every target but ARMv6-M) the three products
/// are summed in wrapping `i64` (multiply-accumulate) and rounded once. That is exact
/// whenever the result fits: each product is at most 2^62 in magnitude, so the true sum
/// `S` is below `0.75 x 2^64`, and a wrapped sum differs from `S` only when `|S| >= 2^63`,
/// and is then at least `2^62` in magnitude itself, far outside `Fx` after the shift (both
/// give `None`). Four terms could wrap to a small value, so this is for three.
#[inline(always)]
pub(crate) fn dot3_plus_fit(a: [i32; 3], b: [i32; 3], t: i32) -> Option<Fx> {
    #[cfg(all(target_arch = "arm", not(target_has_atomic = "32")))]
    {
        fit(dot_q16_split(a, b) + i64::from(t))
    }
    #[cfg(not(all(target_arch = "arm", not(target_has_atomic = "32"))))]
    {
        fit(dot3_wrapping(a, b) + i64::from(t))
    }
}

/// `floor((Σ a_i b_i + 2^15) / 2^16)` with the sum wrapping modulo 2^64 ([`dot3_plus_fit`]).
#[cfg_attr(
    all(target_arch = "arm", not(target_has_atomic = "32")),
    allow(dead_code)
)]
#[inline(always)]
fn dot3_wrapping(a: [i32; 3], b: [i32; 3]) -> i64 {
    let p = |k: usize| i64::from(a[k]) * i64::from(b[k]);
    p(0).wrapping_add(p(1))
        .wrapping_add(p(2))
        .wrapping_add(1 << 15)
        >> 16
}

/// Clamps a Q16 value held in an `i64` to the `Fx` range.
#[inline]
pub(crate) fn saturate(bits: i64) -> Fx {
    Fx::from_bits(bits.clamp(i64::from(i32::MIN), i64::from(i32::MAX)) as i32)
}

/// A Q16 value held in an `i64` as `Fx`, or `None` if it is out of range.
#[inline]
pub(crate) fn fit(bits: i64) -> Option<Fx> {
    i32::try_from(bits).ok().map(Fx::from_bits)
}

#[cfg(test)]
mod tests {
    extern crate std;
    use super::*;

    #[test]
    fn sums_are_exact_at_the_extremes() {
        let m = Fx::MIN;
        let x = Fx::MAX;
        // 4 * 2^62 / 2^16 = 2^48: would overflow a plain i64 accumulator.
        assert_eq!(sum_q32([prod(m, m); 4]), 1 << 48);
        assert_eq!(
            sum_q32([prod(m, x); 4]),
            -4 * (((1i64 << 31) * ((1 << 31) - 1)) >> 16)
        );
        assert_eq!(saturate(sum_q32([prod(m, m); 4])), Fx::MAX);
        // Three extreme products wrap an i64 sum: still refused, as the exact sum is.
        let (mb, xb) = (m.to_bits(), x.to_bits());
        for (a, b) in [
            ([mb; 3], [mb; 3]),
            ([mb; 3], [xb; 3]),
            ([xb, mb, xb], [xb, mb, mb]),
        ] {
            assert_eq!(fit(dot3_wrapping(a, b)), None);
            assert_eq!(dot3_plus_fit(a, b, i32::MIN), None);
        }
        assert_eq!(fit(sum_q32([prod(m, m); 4])), None);
        // Rounding: 0.5 ulp rounds up, -0.5 ulp rounds up (toward +inf).
        assert_eq!(sum_q32([1 << 15]), 1);
        assert_eq!(sum_q32([-(1 << 15)]), 0);
        assert_eq!(sum_q32([(1 << 15) - 1]), 0);
        let h = Fx::from_num(0.5);
        let t = Fx::from_num(3);
        assert_eq!(
            fit(sum_q32([prod(h, t), prod(t, t)])),
            Some(Fx::from_num(10.5))
        );
    }

    #[test]
    fn split_dot_products_match_the_exact_sums() {
        let mut x = 0x9E37_79B9_7F4A_7C15u64;
        let mut next = || {
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
            x as i32
        };
        let edge = [
            0,
            1,
            -1,
            0xFFFF,
            0x10000,
            -0x10000,
            i32::MAX,
            i32::MIN,
            0x7FFF_0000,
        ];
        for i in 0..400_000 {
            let pick = |k: usize, r: i32| {
                if k.is_multiple_of(3) {
                    edge[(r as u32 as usize) % edge.len()]
                } else {
                    r
                }
            };
            let a = [pick(i, next()), pick(i + 1, next()), pick(i + 2, next())];
            let b = [pick(i + 1, next()), pick(i, next()), next() >> (i % 20)];
            let exact = sum_q32([0, 1, 2].map(|k| prod(Fx::from_bits(a[k]), Fx::from_bits(b[k]))));
            assert_eq!(dot_q16_split(a, b), exact, "{a:?} . {b:?}");
            assert_eq!(dot_q16(a, b), exact, "{a:?} . {b:?}");
            let t = pick(i + 2, next());
            let want = fit(exact + i64::from(t));
            assert_eq!(dot3_plus_fit(a, b, t), want, "{a:?} . {b:?} + {t}");
            assert_eq!(
                fit(dot3_wrapping(a, b) + i64::from(t)),
                want,
                "{a:?} . {b:?} + {t}"
            );
            assert_eq!(
                dot_q16_split([a[0]], [b[0]]),
                sum_q32([prod(Fx::from_bits(a[0]), Fx::from_bits(b[0]))])
            );
        }
    }
}
