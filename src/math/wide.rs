//! 64-bit shifts, leading-zero counts and 32 x 32-bit products that stay inline on every core.
//!
//! On ARMv6-M (Cortex-M0/M0+) a variable shift of an `i64` or `u64` compiles to a library
//! call (`__aeabi_llsl`, `__aeabi_llsr`, `__aeabi_lasr`: a call, a return and a dozen
//! instructions) and `leading_zeros` to `__clzsi2` (no `CLZ` instruction). The per-triangle
//! set-up does a few dozen of each, once per triangle and band. These functions compute the
//! same bits from 32-bit halves there (a branch and three or four 32-bit shifts) and are the
//! plain operators everywhere else, where the compiler already emits short inline sequences.
//!
//! Every function takes a shift below 64 (larger shifts are reduced modulo 64, as
//! `wrapping_shl` does) and never panics.

/// True on ARMv6-M, where the 32-bit-half forms are used.
const SPLIT: bool = cfg!(all(target_arch = "arm", not(target_has_atomic = "32")));

/// `x << s` (wrapping, `s` modulo 64).
#[inline(always)]
pub(crate) fn shl(x: i64, s: u32) -> i64 {
    if SPLIT {
        split::shl(x, s)
    } else {
        x.wrapping_shl(s)
    }
}

/// `x >> s`, arithmetic (`s` modulo 64).
#[inline(always)]
pub(crate) fn sar(x: i64, s: u32) -> i64 {
    if SPLIT {
        split::sar(x, s)
    } else {
        x.wrapping_shr(s)
    }
}

/// `x >> s`, logical (`s` modulo 64).
#[inline(always)]
pub(crate) fn shr(x: u64, s: u32) -> u64 {
    if SPLIT {
        split::shr(x, s)
    } else {
        x.wrapping_shr(s)
    }
}

/// `a.leading_zeros()`: the instruction where there is one; on ARMv6-M a five-step binary
/// search instead of the `__clzsi2` call.
#[inline(always)]
pub(crate) fn clz32(a: u32) -> u32 {
    if SPLIT {
        split::clz32(a)
    } else {
        a.leading_zeros()
    }
}

/// `a.leading_zeros()` for a `u64`.
#[inline(always)]
pub(crate) fn clz64(a: u64) -> u32 {
    let hi = (a >> 32) as u32;
    if hi != 0 {
        clz32(hi)
    } else {
        32 + clz32(a as u32)
    }
}

/// `a d - b c` (wrapping): the 2 x 2 determinant of edge vectors, whose sign is a screen
/// triangle's winding. On ARMv6-M, where each `i64` product is a `__aeabi_lmul` call (about
/// 35 instructions), operands within `i16` (on-screen differences of 1/16-pixel
/// coordinates, up to 2048 pixels) take two 32-bit products: each is at most 2^30 in
/// magnitude and the difference below 2^31, so the result is the same.
#[inline(always)]
pub(crate) fn det2(a: i64, b: i64, c: i64, d: i64) -> i64 {
    if SPLIT {
        if let Some(v) = split::det2_small(a, b, c, d) {
            return v;
        }
    }
    a.wrapping_mul(d).wrapping_sub(b.wrapping_mul(c))
}

/// `a1 b1 + a2 b2` exactly, for sums that fit `i64` (the barycentric plane gradients'). On
/// ARMv6-M, where a signed 32 x 32 -> 64-bit product is four 16-bit products plus a
/// magnitude and a sign fix-up, the sum is taken from signed 16-bit halves directly
/// (`a = ah 2^16 + al`, `ah` signed, `al` in `0..2^16`): eight products, no magnitudes, the
/// partial sums carried in `i64` (about half the instructions).
#[inline(always)]
pub(crate) fn dot2(a1: i32, a2: i32, b1: i32, b2: i32) -> i64 {
    if SPLIT {
        split::dot2(a1, a2, b1, b2)
    } else {
        (i64::from(a1) * i64::from(b1)).wrapping_add(i64::from(a2) * i64::from(b2))
    }
}

/// The 32-bit-half forms (compiled everywhere, so the host tests them).
#[cfg_attr(
    not(all(target_arch = "arm", not(target_has_atomic = "32"))),
    allow(dead_code)
)]
mod split {
    /// [`super::det2`] in 32-bit products when every operand fits `i16`.
    #[inline(always)]
    pub fn det2_small(a: i64, b: i64, c: i64, d: i64) -> Option<i64> {
        let small = |v: i64| v as i16 as i64 == v;
        if small(a) && small(b) && small(c) && small(d) {
            let (a, b, c, d) = (a as i32, b as i32, c as i32, d as i32);
            Some(i64::from(a * d - b * c))
        } else {
            None
        }
    }

    /// [`super::dot2`] from signed 16-bit halves.
    #[inline(always)]
    pub fn dot2(a1: i32, a2: i32, b1: i32, b2: i32) -> i64 {
        // hi in -2^15..2^15, lo in 0..2^16: |hi hi| <= 2^30, |hi lo| < 2^31, lo lo < 2^32.
        let hi = |x: i32| x >> 16;
        let lo = |x: i32| x & 0xFFFF;
        let hh = i64::from(hi(a1) * hi(b1)) + i64::from(hi(a2) * hi(b2));
        let mid = i64::from(hi(a1) * lo(b1))
            + i64::from(lo(a1) * hi(b1))
            + i64::from(hi(a2) * lo(b2))
            + i64::from(lo(a2) * hi(b2));
        let ll = u64::from((lo(a1) as u32).wrapping_mul(lo(b1) as u32))
            + u64::from((lo(a2) as u32).wrapping_mul(lo(b2) as u32));
        // Modulo 2^64 (the exact sum fits i64): hh 2^32 + mid 2^16 + ll.
        (hh << 32).wrapping_add(mid << 16).wrapping_add(ll as i64)
    }

    #[inline(always)]
    pub fn shl(x: i64, s: u32) -> i64 {
        let s = s & 63;
        let (hi, lo) = ((x >> 32) as u32, x as u32);
        let (hi, lo) = if s == 0 {
            (hi, lo)
        } else if s < 32 {
            ((hi << s) | (lo >> (32 - s)), lo << s)
        } else {
            (lo << (s - 32), 0)
        };
        ((u64::from(hi) << 32) | u64::from(lo)) as i64
    }

    #[inline(always)]
    pub fn sar(x: i64, s: u32) -> i64 {
        let s = s & 63;
        let (hi, lo) = ((x >> 32) as i32, x as u32);
        let (hi, lo) = if s == 0 {
            (hi, lo)
        } else if s < 32 {
            (hi >> s, (lo >> s) | ((hi as u32) << (32 - s)))
        } else {
            (hi >> 31, (hi >> (s - 32)) as u32)
        };
        (i64::from(hi) << 32) | i64::from(lo)
    }

    #[inline(always)]
    pub fn shr(x: u64, s: u32) -> u64 {
        let s = s & 63;
        let (hi, lo) = ((x >> 32) as u32, x as u32);
        let (hi, lo) = if s == 0 {
            (hi, lo)
        } else if s < 32 {
            (hi >> s, (lo >> s) | (hi << (32 - s)))
        } else {
            (0, hi >> (s - 32))
        };
        (u64::from(hi) << 32) | u64::from(lo)
    }

    const fn clz8_table() -> [u8; 256] {
        let mut t = [8u8; 256];
        let mut i = 1;
        while i < 256 {
            t[i] = (i as u8).leading_zeros() as u8;
            i += 1;
        }
        t
    }

    /// Leading zeros of a byte.
    static CLZ8: [u8; 256] = clz8_table();

    /// Two halving steps, then the top byte's count from a 256-byte table (three steps
    /// fewer than the plain binary search; the set-up takes about five per triangle).
    #[inline(always)]
    pub fn clz32(a: u32) -> u32 {
        if a == 0 {
            return 32;
        }
        let (mut a, mut n) = (a, 0);
        for s in [16u32, 8] {
            if a >> (32 - s) == 0 {
                a <<= s;
                n += s;
            }
        }
        n + u32::from(CLZ8[(a >> 24) as usize])
    }
}

/// The full 64-bit product of two `u32`: one `umull` where there is one; on ARMv6-M, which
/// has only a 32-bit `muls`, four 16 x 16-bit products (the library's `__aeabi_lmul` is
/// about 25 instructions and a call).
#[inline(always)]
pub(crate) fn mul_wide(a: u32, b: u32) -> u64 {
    #[cfg(all(target_arch = "arm", not(target_has_atomic = "32")))]
    {
        mul_wide_split(a, b)
    }
    #[cfg(not(all(target_arch = "arm", not(target_has_atomic = "32"))))]
    {
        u64::from(a) * u64::from(b)
    }
}

/// `a * b` as `i64`, exactly: one `smull` where the core has it; on ARMv6-M (no 64-bit
/// product instruction) the 16-bit-split product of the magnitudes instead of the
/// `__aeabi_lmul` library call that `i64` multiplication compiles to.
#[inline(always)]
pub(crate) fn mul_wide_signed(a: i32, b: i32) -> i64 {
    #[cfg(all(target_arch = "arm", not(target_has_atomic = "32")))]
    {
        let p = mul_wide_split(a.unsigned_abs(), b.unsigned_abs()) as i64;
        if (a < 0) != (b < 0) {
            p.wrapping_neg()
        } else {
            p
        }
    }
    #[cfg(not(all(target_arch = "arm", not(target_has_atomic = "32"))))]
    {
        i64::from(a) * i64::from(b)
    }
}

/// The 16-bit-multiply form of [`mul_wide`] (compiled everywhere so every target tests it).
#[cfg_attr(
    not(all(target_arch = "arm", not(target_has_atomic = "32"))),
    allow(dead_code)
)]
#[inline(always)]
pub(crate) fn mul_wide_split(a: u32, b: u32) -> u64 {
    let (ah, al) = (a >> 16, a & 0xFFFF);
    let (bh, bl) = (b >> 16, b & 0xFFFF);
    let (ll, hh) = (al * bl, ah * bh);
    let (mid1, mid2) = (ah * bl, al * bh);
    // mid1 + mid2 may carry into bit 32.
    let (mid, carry) = mid1.overflowing_add(mid2);
    let lo = u64::from(ll) + (u64::from(mid) << 16);
    lo + (u64::from(hh) << 32) + (u64::from(carry) << 48)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn small_determinant_matches_the_wide_one() {
        let edge = || {
            crate::test_rng::I16_EDGES
                .into_iter()
                .chain([1 << 20, -(1 << 31)])
        };
        for a in edge() {
            for b in edge() {
                for c in edge() {
                    for d in edge() {
                        let wide = a.wrapping_mul(d).wrapping_sub(b.wrapping_mul(c));
                        if let Some(v) = split::det2_small(a, b, c, d) {
                            assert_eq!(v, wide, "{a} {b} {c} {d}");
                        }
                        assert_eq!(det2(a, b, c, d), wide);
                    }
                }
            }
        }
    }

    #[test]
    fn split_dot_product_is_exact() {
        let vals = [
            0i32,
            1,
            -1,
            65535,
            65536,
            -65536,
            32767,
            -32768,
            i32::MAX,
            i32::MIN + 1,
            0x7FFF_0000,
            -0x7FFF_FFFF,
        ];
        let want = |a1: i32, a2: i32, b1: i32, b2: i32| {
            i64::from(a1) * i64::from(b1) + i64::from(a2) * i64::from(b2)
        };
        for &a1 in &vals {
            for &a2 in &vals {
                for &b1 in &vals {
                    for &b2 in &vals {
                        assert_eq!(split::dot2(a1, a2, b1, b2), want(a1, a2, b1, b2));
                    }
                }
            }
        }
        let mut x = 0x2545_F491_4F6C_DD1Du64;
        for _ in 0..200_000 {
            let mut next = || {
                x ^= x << 13;
                x ^= x >> 7;
                x ^= x << 17;
                ((x >> 16) as i32) >> (x % 17)
            };
            let (a1, a2, b1, b2) = (next(), next(), next(), next());
            if [a1, a2, b1, b2].contains(&i32::MIN) {
                continue;
            }
            assert_eq!(split::dot2(a1, a2, b1, b2), want(a1, a2, b1, b2));
        }
    }

    #[test]
    fn split_forms_match_the_operators() {
        let mut x = 0x9E37_79B9_7F4A_7C15u64;
        for _ in 0..20_000 {
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
            let v = x >> (x % 64);
            for s in [
                0,
                1,
                5,
                31,
                32,
                33,
                47,
                63,
                (x >> 58) as u32,
                64 + (x >> 59) as u32,
            ] {
                for w in [v, !v] {
                    assert_eq!(split::shl(w as i64, s), (w as i64).wrapping_shl(s));
                    assert_eq!(split::sar(w as i64, s), (w as i64).wrapping_shr(s));
                    assert_eq!(split::shr(w, s), w.wrapping_shr(s));
                    assert_eq!(shl(w as i64, s), (w as i64).wrapping_shl(s));
                }
            }
            assert_eq!(clz64(v), v.leading_zeros());
            assert_eq!(split::clz32(v as u32), (v as u32).leading_zeros());
        }
        assert_eq!(clz64(0), 64);
        assert_eq!(split::clz32(0), 32);
        for b in 0..32 {
            for v in [
                1u32 << b,
                (1 << b) | ((1 << b) - 1),
                (1 << b) | 1,
                (1 << b) | ((1 << b) / 2),
            ] {
                assert_eq!(split::clz32(v), v.leading_zeros(), "{v:#x}");
            }
        }
    }

    #[test]
    fn split_wide_multiply_is_exact() {
        let mut x: u64 = 0x9E37_79B9_7F4A_7C15;
        for _ in 0..200_000 {
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
            let (a, b) = ((x >> 32) as u32, x as u32);
            assert_eq!(mul_wide_split(a, b), u64::from(a) * u64::from(b));
            let (sa, sb) = (a as i32, b as i32);
            assert_eq!(mul_wide_signed(sa, sb), i64::from(sa) * i64::from(sb));
        }
        assert_eq!(
            mul_wide_split(u32::MAX, u32::MAX),
            u64::from(u32::MAX) * u64::from(u32::MAX)
        );
    }
}
