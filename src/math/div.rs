//! Exact 64-bit by 64-bit unsigned division that takes 32-bit paths when the operands
//! allow: the geometry's projections and the raster set-up's plane gradients divide 64-bit
//! numerators by small divisors (`w`, a triangle's doubled area), and a full 64-bit
//! division is a library call of a few hundred instructions on 32-bit cores (Cortex-M4F:
//! `__aeabi_uldivmod`, ~250 instructions measured; Cortex-M0+: more, it has no divide
//! instruction at all). The result is always the exact `n / d` (tested against `u64` `/`
//! on random and edge operands), so callers stay bit-identical.
//!
//! Paths, by operand size:
//!
//! * `n < 2^32`, `d < 2^32`: one 32-bit division (one `udiv` on Cortex-M4F and RV32IM);
//! * `d < 2^16`: schoolbook long division in base 2^16 (the high word, then two 16-bit
//!   digits): three 32-bit divisions, each of a value below `d * 2^16 < 2^32`;
//! * `d < 2^32` and a quotient below 2^32 (`n < d * 2^32`, the set-up's `w_min / w` and most
//!   plane gradients): two 16-bit quotient digits on the normalized divisor (Knuth's
//!   algorithm D as in Hacker's Delight's `divlu`): two 32-bit divisions and at most two
//!   corrections each;
//! * otherwise: the 64-bit division.
//!
//! [`Divisor32`] divides many numerators by one divisor below 2^32 through a reciprocal.

use super::wide::mul_wide;
/// True on cores with a 32-bit divide instruction (Cortex-M3/M4/M7, RV32IM, hosts); false on
/// ARMv6-M (Cortex-M0/M0+), where division is a library call.
pub const HW_DIVIDE: bool = !cfg!(all(target_arch = "arm", not(target_has_atomic = "32")));

/// `n / d` rounded towards zero, exactly; `d` must not be zero (then `0` is returned, never
/// a panic).
///
/// Out of line: every caller calls it anyway, and an `#[inline]` function gets a copy in
/// each crate that instantiates a generic caller (a firmware linked two identical ~490-byte
/// copies).
#[inline(never)]
pub fn div_u64(n: u64, d: u64) -> u64 {
    if d == 0 {
        return 0;
    }
    if d >> 16 == 0 {
        let d = d as u32;
        let hi = (n >> 32) as u32;
        let lo = n as u32;
        if hi == 0 {
            return u64::from(lo / d);
        }
        let q1 = hi / d;
        let r1 = hi - q1 * d; // < d < 2^16
        let t2 = (r1 << 16) | (lo >> 16); // < d * 2^16
        let q2 = t2 / d;
        let r2 = t2 - q2 * d;
        let t3 = (r2 << 16) | (lo & 0xFFFF);
        let q3 = t3 / d;
        return (u64::from(q1) << 32) | (u64::from(q2) << 16) | u64::from(q3);
    }
    if (n | d) >> 32 == 0 {
        return u64::from(n as u32 / d as u32);
    }
    if d >> 32 == 0 && n >> 32 < d {
        return u64::from(div_64_32(n, d as u32));
    }
    div_wide(n, d)
}

/// [`div_u64`]'s rare cases (a divisor of 2^32 or more, or a quotient of 2^32 or more), out
/// of line and without the 64-bit library division (which links ~1 KB of library code on
/// 32-bit cores): for a divisor below 2^32 two word-sized steps; otherwise restoring binary
/// long division, one quotient bit per step from the divisor's first fitting shift (at most
/// 33 steps, a few instructions each).
#[inline(never)]
fn div_wide(n: u64, d: u64) -> u64 {
    if d >> 32 == 0 {
        // A divisor below 2^32 (and a quotient of 2^32 or more): the high word by a 32-bit
        // division, the low word by `div_u64`'s 64-by-32 path (its quotient fits 32 bits).
        let (hi, d32) = ((n >> 32) as u32, d as u32);
        let (qh, rh) = (hi / d32, hi % d32);
        let lo = div_u64((u64::from(rh) << 32) | (n & 0xFFFF_FFFF), d);
        return (u64::from(qh) << 32) | lo;
    }
    // The quotient has at most `clz(d) - clz(n) + 1` bits.
    let s = d.leading_zeros().saturating_sub(n.leading_zeros());
    let (mut r, mut q) = (n, 0u64);
    let mut dd = d << s;
    let mut bit = 1u64 << s;
    while bit != 0 {
        if r >= dd {
            r -= dd;
            q |= bit;
        }
        dd >>= 1;
        bit >>= 1;
    }
    q
}

/// `n / d` for `2^16 <= d < 2^32` and `n < d * 2^32` (so the quotient fits `u32`), exactly.
///
/// With a divide instruction: two base-2^16 digits of long division on the normalized
/// divisor, each estimated by a 32-bit division by the divisor's high half and corrected at
/// most twice. On ARMv6-M, where each of those divisions is a ~120-instruction library
/// call: [`div_64_32_newton`].
#[inline]
pub(crate) fn div_64_32(n: u64, d: u32) -> u32 {
    if HW_DIVIDE {
        div_64_32_digits(n, d)
    } else {
        div_64_32_newton(n, d)
    }
}

/// [`div_64_32`] without a division: the 16-bit-product form of
/// [`RecipForm`](super::recip32::RecipForm) (a reciprocal from the interpolated mantissa
/// table and one Newton step, the quotient estimate, then the exact remainder correction).
/// Same result as the digit form (tested); `d >= 2^16` and `n < d 2^32` here, so the
/// reciprocal's quotient always exists (0 otherwise, never a panic).
#[cfg_attr(
    not(all(target_arch = "arm", not(target_has_atomic = "32"))),
    allow(dead_code)
)]
#[inline]
fn div_64_32_newton(n: u64, d: u32) -> u32 {
    super::recip32::RecipForm::<true>::new(d)
        .and_then(|r| r.div_wide(n))
        .unwrap_or(0)
}

/// The long-division form of [`div_64_32`].
#[inline]
fn div_64_32_digits(n: u64, d: u32) -> u32 {
    const B: u32 = 1 << 16;
    let s = d.leading_zeros();
    let v = d << s;
    let (vh, vl) = (v >> 16, v & 0xFFFF);
    // n < d 2^32, so n << s < v 2^32 <= 2^64: no bits are lost.
    let n = n << s;
    let (un32, un10) = ((n >> 32) as u32, n as u32);
    let (un1, un0) = (un10 >> 16, un10 & 0xFFFF);
    // First digit. vh >= 2^15 (v is normalized), so the estimate is at most 2 too large.
    let mut q1 = un32 / vh;
    let mut rhat = un32 - q1 * vh;
    while q1 >= B || q1 * vl > (rhat << 16 | un1) {
        q1 -= 1;
        rhat += vh;
        if rhat >= B {
            break;
        }
    }
    // The partial remainder (< v) modulo 2^32.
    let un21 = (un32 << 16 | un1).wrapping_sub(q1.wrapping_mul(v));
    let mut q0 = un21 / vh;
    let mut rhat = un21 - q0 * vh;
    while q0 >= B || q0 * vl > (rhat << 16 | un0) {
        q0 -= 1;
        rhat += vh;
        if rhat >= B {
            break;
        }
    }
    q1 << 16 | q0
}

/// `n / d` for signed `n` and positive `d`, rounded to nearest with ties away from zero
/// (`d <= 0` gives 0). The same result as `(n + d/2) / d` for `n >= 0` and
/// `-((d/2 - n) / d)` below, in `i64` (with the same wrapping at the ends of the range).
#[inline]
pub fn div_round_i64(n: i64, d: i64) -> i64 {
    if d <= 0 {
        return 0;
    }
    let half = d / 2;
    if n >= 0 {
        div_u64(n.wrapping_add(half) as u64, d as u64) as i64
    } else {
        (div_u64(half.wrapping_sub(n) as u64, d as u64) as i64).wrapping_neg()
    }
}

/// `floor(n / d)` for signed `n` and positive `d` (`i64::div_euclid` for `d > 0`); `d <= 0`
/// gives 0.
#[inline(never)]
pub fn div_floor_i64(n: i64, d: i64) -> i64 {
    if d <= 0 {
        return 0;
    }
    // Both within `i32` (on-screen projections): one 32-bit division instruction, inline,
    // on cores that have one (on Cortex-M0+ the unsigned paths below are faster).
    if let (true, Ok(n32), Ok(d32)) = (HW_DIVIDE, i32::try_from(n), i32::try_from(d)) {
        if n32 != i32::MIN {
            return i64::from(n32.div_euclid(d32));
        }
    }
    if n >= 0 {
        div_u64(n as u64, d as u64) as i64
    } else {
        // floor(n / d) = -ceil(-n / d) = -((-n + d - 1) / d)
        let m = n.unsigned_abs() + (d as u64 - 1);
        (div_u64(m, d as u64) as i64).wrapping_neg()
    }
}

/// Exact division of many 64-bit numerators by one divisor below 2^32 (a triangle's doubled
/// area, normalized, in the plane set-up): a 64-bit reciprocal computed once, so each
/// division is the high half of a 64 x 64-bit product and at most two corrections, instead
/// of a 64-by-32-bit long division (two or three 32-bit divisions, which Cortex-M0+ does in
/// software).
#[derive(Clone, Copy, Debug)]
pub struct Divisor32 {
    d: u64,
    /// `floor((2^64 - 1) / d)`.
    m: u64,
}

impl Divisor32 {
    /// `None` unless `0 < d < 2^32`.
    #[inline]
    pub fn new(d: u64) -> Option<Self> {
        if d == 0 || d >> 32 != 0 {
            return None;
        }
        // floor((2^64 - 1) / d) in two digits: a 32-bit division, then one whose quotient
        // fits 32 bits (the 64-by-32 path of `div_u64`), not a 64-bit library division.
        let hi = u64::from(u32::MAX) / d;
        let r = u64::from(u32::MAX) - hi * d;
        let lo = div_u64((r << 32) | u64::from(u32::MAX), d);
        Some(Divisor32 {
            d,
            m: (hi << 32) | lo,
        })
    }

    /// `n / d` rounded towards zero, exactly.
    #[inline]
    pub fn div(&self, n: u64) -> u64 {
        // n m / 2^64 > n / d - n / 2^64 - n / (d 2^64)... > n / d - 2: two corrections at most.
        let mut q = mul_hi64(n, self.m);
        // The low 64 bits of q d (d < 2^32), in 32-bit products.
        let d = self.d as u32;
        let qd =
            mul_wide(q as u32, d).wrapping_add(u64::from(((q >> 32) as u32).wrapping_mul(d)) << 32);
        let mut r = n.wrapping_sub(qd);
        while r >= self.d {
            q += 1;
            r -= self.d;
        }
        q
    }
}

/// High 64 bits of the 96-bit product `a b` for `a < 2^32`: two 32 x 32-bit products
/// (`a bh + floor(a bl / 2^32)` stays below 2^64).
#[inline(always)]
fn mul_hi64_32(a: u32, b: u64) -> u64 {
    let (bh, bl) = ((b >> 32) as u32, b as u32);
    (mul_wide(a, bh) + (mul_wide(a, bl) >> 32)) >> 32
}

/// High 64 bits of the 128-bit product `a b`, from four 32 x 32-bit products.
#[inline(always)]
fn mul_hi64(a: u64, b: u64) -> u64 {
    let (ah, al) = ((a >> 32) as u32, a as u32);
    if !HW_DIVIDE && ah == 0 {
        // ARMv6-M, `a < 2^32`: two of the four products (each 4 `muls` there) are zero.
        return mul_hi64_32(al, b);
    }
    let (bh, bl) = ((b >> 32) as u32, b as u32);
    let ll = mul_wide(al, bl);
    let lh = mul_wide(al, bh);
    let hl = mul_wide(ah, bl);
    let mid = (ll >> 32) + (lh & 0xFFFF_FFFF) + (hl & 0xFFFF_FFFF);
    mul_wide(ah, bh) + (lh >> 32) + (hl >> 32) + (mid >> 32)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reciprocal_division_is_exact() {
        let mut x: u64 = 0x2545_F491_4F6C_DD1D;
        let mut next = || {
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
            x
        };
        for _ in 0..200_000 {
            let d = (next() >> (32 + next() % 32)).max(1);
            let r = Divisor32::new(d).unwrap();
            for n in [
                next(),
                next() >> (next() % 64),
                d - 1,
                d,
                d * 3 + 1,
                u64::MAX,
            ] {
                assert_eq!(r.div(n), n / d, "{n} / {d}");
            }
        }
        assert!(Divisor32::new(0).is_none() && Divisor32::new(1 << 32).is_none());
        assert_eq!(Divisor32::new(1).unwrap().div(u64::MAX), u64::MAX);
    }

    #[test]
    fn the_newton_form_equals_the_plain_division() {
        let mut x = 0x2545_F491_4F6C_DD1Du64;
        let check = |n: u64, d: u32| {
            if d >> 16 != 0 && n >> 32 < u64::from(d) {
                assert_eq!(
                    u64::from(div_64_32_newton(n, d)),
                    n / u64::from(d),
                    "{n} / {d}"
                );
            }
        };
        for d in [
            1u32 << 16,
            (1 << 16) + 1,
            1 << 31,
            (1 << 31) + 1,
            u32::MAX,
            u32::MAX - 1,
        ] {
            for n in [
                0,
                1,
                u64::from(d) - 1,
                u64::from(d),
                (u64::from(d) << 32) - 1,
            ] {
                check(n, d);
            }
        }
        for _ in 0..400_000 {
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
            let d = ((x >> 32) as u32) >> (x % 16);
            let n = (x.rotate_left(23)) % (u64::from(d.max(1)) << 32);
            check(n, d);
            check((u64::from(d) << 32).wrapping_sub(1 + (x & 0xFF)), d);
        }
    }

    #[test]
    fn the_two_digit_path_equals_the_plain_division() {
        let mut x: u64 = 0x9E37_79B9_7F4A_7C15;
        let mut next = || {
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
            x
        };
        let check = |n: u64, d: u64| assert_eq!(div_u64(n, d), n / d, "{n} / {d}");
        for d in [
            1u64 << 16,
            (1 << 16) + 1,
            0x8000_0000,
            0xFFFF_FFFF,
            0x1_0000_0001,
            123_456_789,
        ] {
            for n in [0, 1, d - 1, d, d * 0xFFFF_FFFF, (d << 32) - 1, u64::MAX] {
                check(n, d);
            }
        }
        for _ in 0..500_000 {
            let d = (next() >> (next() % 48)).max(1);
            let n = next() >> (next() % 64);
            check(n, d);
            // Quotients just below 2^32, where the digit estimates need their corrections.
            let q = next() >> 32;
            let r = next() % d;
            if let Some(n) = d.checked_mul(q).and_then(|m| m.checked_add(r)) {
                check(n, d);
            }
        }
    }

    #[test]
    fn equals_the_plain_division() {
        let mut x: u64 = 0x9E37_79B9_7F4A_7C15;
        let mut next = || {
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
            x
        };
        let ds = [
            1u64,
            2,
            3,
            255,
            256,
            65535,
            65536,
            65537,
            1 << 31,
            u32::MAX as u64,
            1 << 32,
            (1 << 32) + 1,
            (1 << 63) + 12345,
            u64::MAX,
        ];
        let ns = [
            0u64,
            1,
            u32::MAX as u64,
            1 << 32,
            u64::MAX,
            u64::MAX - 1,
            1 << 63,
        ];
        for &d in &ds {
            for &n in &ns {
                assert_eq!(div_u64(n, d), n / d, "{n} / {d}");
            }
        }
        for _ in 0..200_000 {
            let n = next() >> (next() % 64);
            let d = (next() >> (next() % 64)).max(1);
            assert_eq!(div_u64(n, d), n / d, "{n} / {d}");
            let (sn, sd) = (n as i64, (d >> 1).max(1) as i64);
            assert_eq!(div_floor_i64(sn, sd), sn.div_euclid(sd), "{sn} / {sd}");
            let half = sd / 2;
            let want = if sn >= 0 {
                sn.wrapping_add(half) / sd
            } else {
                -(half.wrapping_sub(sn) / sd)
            };
            if sn.checked_add(half).is_some() && half.checked_sub(sn).is_some() {
                assert_eq!(div_round_i64(sn, sd), want, "{sn} / {sd}");
            }
        }
    }

    #[test]
    fn high_products_are_exact() {
        let mut x = 0x0123_4567_89AB_CDEFu64;
        let mut next = || {
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
            x
        };
        for i in 0..200_000 {
            let (a, b) = (next(), next());
            let a = if i % 2 == 0 { a >> 32 } else { a };
            let exact = ((u128::from(a) * u128::from(b)) >> 64) as u64;
            assert_eq!(mul_hi64(a, b), exact);
            if a >> 32 == 0 {
                assert_eq!(mul_hi64_32(a as u32, b), exact);
            }
        }
        assert_eq!(
            mul_hi64_32(u32::MAX, u64::MAX),
            ((u128::from(u32::MAX) * u128::from(u64::MAX)) >> 64) as u64
        );
    }
}
