//! Several exact quotients by one 32-bit divisor through one reciprocal: the projection
//! divides three numerators by the same `w`, the set-up two by each vertex's `w`. On
//! Cortex-M0+, which has no divide instruction, a 32-bit division is a library call of
//! about 120 instructions and a 64-by-32-bit one about 220.
//!
//! [`RecipForm::at_least_one`] normalizes the divisor `d` to `v = d 2^s`
//! (`2^31 <= v < 2^32`) and takes `y ~ 2^63 / v` from a seed (the interpolated mantissa
//! table on ARMv6-M, one 32-bit division by `v`'s top half elsewhere) and one Newton-Raphson
//! step (on ARMv6-M from high words only, three 16-bit products each): `y` never exceeds
//! `2^63 / v` and is within a relative 2^-28 of it. Each quotient is then an estimate from
//! `y` that is at most the true quotient and a few units below it, stepped up by an exact
//! remainder test. The results are the exact floors (tested against `/` on random and edge
//! operands, in both forms on every target), so a caller's output does not depend on which
//! core computed it.

use super::recip::recip_mantissa;
use super::wide::mul_wide;
use super::wide::{clz32, shl};

/// ARMv6-M: no 32 x 32 -> 64-bit product instruction.
const SPLIT_MUL: bool = cfg!(all(target_arch = "arm", not(target_has_atomic = "32")));

/// The high word of `a b`, or up to 2 less: on Cortex-M0+, three 16 x 16-bit products
/// without the low partial product and the carries into the high word (a full 64-bit
/// product there is four products and carry fix-ups); elsewhere the exact high word of one
/// 32 x 32-bit product. Callers correct their estimates upwards.
#[inline(always)]
fn mul_hi_at_most<const SPLIT: bool>(a: u32, b: u32) -> u32 {
    if SPLIT {
        mul_hi_split(a, b)
    } else {
        (mul_wide(a, b) >> 32) as u32
    }
}

/// The split form of [`mul_hi_at_most`] (compiled everywhere so every target tests it).
#[inline(always)]
fn mul_hi_split(a: u32, b: u32) -> u32 {
    let (ah, al) = (a >> 16, a & 0xFFFF);
    let (bh, bl) = (b >> 16, b & 0xFFFF);
    // The true high word adds (ah bl mod 2^16 + al bh mod 2^16 + al bl / 2^16) / 2^16 < 3.
    ah * bh + ((ah * bl) >> 16) + ((al * bh) >> 16)
}

/// [`RecipForm`] in this target's form.
pub(crate) type Recip32 = RecipForm<SPLIT_MUL>;

/// A divisor `1 <= d < 2^32` prepared for exact quotients without a division. `SPLIT`
/// chooses the 16-bit-product forms of the estimates (the default on ARMv6-M; tests run
/// both forms everywhere).
#[derive(Clone, Copy, Debug)]
pub(crate) struct RecipForm<const SPLIT: bool> {
    d: u32,
    /// `d << s`, in `[2^31, 2^32)`.
    v: u32,
    /// `clz(d)`.
    s: u32,
    /// `~2^63 / v`, never above it (relative error below 2^-28).
    y: u32,
}

impl<const SPLIT: bool> RecipForm<SPLIT> {
    /// `None` for `d == 0`.
    #[inline]
    pub(crate) fn new(d: u32) -> Option<Self> {
        (d != 0).then(|| Self::nonzero(d))
    }

    /// [`RecipForm::at_least_one`] for a divisor with its top bit set (`d >= 2^31`, no shift).
    #[inline(always)]
    pub(crate) fn new_normalized(d: u32) -> Self {
        debug_assert!(d >> 31 == 1);
        Self::normalized(d, d, 0)
    }

    /// The reciprocal of `w` raised to 1 (a clip `w`).
    #[inline]
    pub(crate) fn at_least_one(w: i32) -> Self {
        Self::nonzero(w.max(1) as u32)
    }

    /// `d >= 1`, normalized by its leading zeros.
    #[inline(always)]
    fn nonzero(d: u32) -> Self {
        let s = clz32(d);
        Self::normalized(d, d << s, s)
    }

    #[inline(always)]
    fn normalized(d: u32, v: u32, s: u32) -> Self {
        // ~2^63 / v within 2^-15, below 2^32 (2^63 / v is 2^32 itself for v = 2^31): from
        // the interpolated mantissa table without a divide instruction, else one 32-bit
        // division by the top half of v (at most 2^-15 above 2^63 / v, no table linked).
        let y = if SPLIT {
            recip_mantissa(v).min((1 << 31) - 1) << 1
        } else {
            (u32::MAX / (v >> 16)) << 15
        };
        // One Newton step, y (2 - v y / 2^63), with `2^64 - v y` truncated to its high
        // word, rounded down: from below or above the seed it lands at or below 2^63 / v
        // (y (2 - v y) <= 1 / v for any y, and rounding down only lowers it), within a
        // relative 2^-28 of it (2^-30 in the exact form).
        let y = if SPLIT {
            // Cortex-M0+: high words only (three 16-bit products each instead of four
            // and the carries). `v y < 2^64`; its high word is at most `h + 2`, so
            // `2^32 - h - 3` is at most the high word of `2^64 - v y`.
            let t = 0u32.wrapping_sub(mul_hi_split(v, y)).wrapping_sub(3);
            mul_hi_split(y, t) << 1
        } else {
            let t = mul_wide(v, y).wrapping_neg();
            (mul_wide(y, (t >> 32) as u32) >> 31) as u32
        };
        RecipForm { d, v, s, y }
    }

    /// The divisor.
    #[inline(always)]
    pub(crate) fn divisor(&self) -> u32 {
        self.d
    }

    /// `(n / d, n % d)`, exactly, for any `n < 2^32`.
    #[inline(always)]
    pub(crate) fn div_rem(&self, n: u32) -> (u32, u32) {
        // n y / 2^(63 - s) <= n / d: the high word, then 31 - s more bits.
        let mut q = mul_hi_at_most::<SPLIT>(n, self.y) >> (31 - self.s);
        // q <= n / d, so q d <= n: the remainder is exact in u32.
        let mut r = n.wrapping_sub(q.wrapping_mul(self.d));
        while r >= self.d {
            q += 1;
            r -= self.d;
        }
        (q, r)
    }

    /// `floor((a k + bias) / d)` for `a < d < 2^28`, `k <= 2^30` and `bias < d`: a
    /// fraction `a / d` of `k` (rounded to nearest, ties up, with `bias = d / 2`). The
    /// estimate `((a 2^s y) >> 31) k / 2^32` is at most the true quotient and at most 11
    /// below it (`k` times the reciprocal's 2^-28, plus the truncations); the remainder of
    /// the estimate lies in `0..12d`, below 2^32, so it is exact in wrapping `u32`
    /// arithmetic.
    #[inline(always)]
    pub(crate) fn fraction_of(&self, a: u32, k: u32, bias: u32) -> u32 {
        debug_assert!(a < self.d && self.d < 1 << 28 && k <= 1 << 30 && bias < self.d);
        // a 2^s < d 2^s = v: (a 2^s) y / 2^31 < 2^32 is the fraction a / d in 32 bits,
        // rounded down (and up to 5 less from the high word's estimate).
        let f = mul_hi_at_most::<SPLIT>(a << self.s, self.y) << 1;
        let mut q = mul_hi_at_most::<SPLIT>(f, k);
        let mut r = a
            .wrapping_mul(k)
            .wrapping_add(bias)
            .wrapping_sub(q.wrapping_mul(self.d));
        while r >= self.d {
            q += 1;
            r -= self.d;
        }
        q
    }

    /// `floor((2^63 - 1) / d)` for a normalized divisor (`2^31 <= d`): the reciprocal
    /// corrected up by the exact 64-bit remainder.
    #[inline(always)]
    pub(crate) fn recip63(&self) -> u32 {
        debug_assert!(self.s == 0);
        let mut q = self.y;
        let v = u64::from(self.v);
        let mut r = (u64::MAX >> 1).wrapping_sub(mul_wide(q, self.v));
        while r >= v {
            q += 1;
            r -= v;
        }
        q
    }

    /// `n / d` rounded towards zero, exactly, for `n < d 2^32` (the quotient fits `u32`);
    /// `None` otherwise. Out of line: the projection's rare path for 64-bit numerators
    /// (inlined at each of its call sites it costs about 1.5 KB of flash).
    #[inline(never)]
    pub(crate) fn div_wide(&self, n: u64) -> Option<u32> {
        if (n >> 32) >= u64::from(self.d) {
            return None;
        }
        // n < d 2^32, so n << s < v 2^32 <= 2^64: no bits are lost.
        let n = shl(n as i64, self.s) as u64;
        let (u1, u0) = ((n >> 32) as u32, n as u32);
        // u1 < v and y <= 2^63 / v: u1 y < 2^63, no overflow; the estimate is <= n / v.
        let mut q = ((mul_wide(u1, self.y) + (mul_wide(u0, self.y) >> 32)) >> 31) as u32;
        let v = u64::from(self.v);
        let mut r = n.wrapping_sub(mul_wide(q, self.v));
        while r >= v {
            q = q.wrapping_add(1);
            r -= v;
        }
        Some(q)
    }
}

#[cfg(test)]
mod tests {
    extern crate std;
    use super::*;
    use crate::test_rng::Rng;
    use std::vec::Vec;

    fn divisors(seed: u64) -> Vec<u32> {
        let mut rng = Rng(seed);
        [
            1,
            2,
            3,
            7,
            1 << 16,
            (1 << 16) + 1,
            1 << 31,
            (1 << 31) + 1,
            u32::MAX - 1,
            u32::MAX,
        ]
        .into_iter()
        .chain((0..4000).map(|_| {
            let bits = 1 + (rng.next() % 32) as u32;
            ((rng.next() as u32) >> (32 - bits)).max(1)
        }))
        .collect()
    }

    fn div_rem_is_exact<const S: bool>() {
        let mut rng = Rng(0x5EED_0032);
        for d in divisors(7) {
            let r = RecipForm::<S>::new(d).unwrap();
            assert_eq!(r.divisor(), d);
            for n in [
                0,
                1,
                d - 1,
                d,
                d.wrapping_add(1),
                u32::MAX,
                u32::MAX - d / 2,
            ] {
                assert_eq!(r.div_rem(n), (n / d, n % d), "{n} / {d}");
            }
            for _ in 0..64 {
                let n = (rng.next() as u32) >> (rng.next() % 32);
                assert_eq!(r.div_rem(n), (n / d, n % d), "{n} / {d}");
            }
        }
        assert!(RecipForm::<S>::new(0).is_none());
    }

    #[test]
    fn div_rem_is_exact_in_both_forms() {
        div_rem_is_exact::<false>();
        div_rem_is_exact::<true>();
    }

    #[test]
    fn split_high_word_is_at_most_2_below() {
        let mut rng = Rng(0x5EED_0016);
        for i in 0..1_000_000u32 {
            let (a, b) = if i < 4 {
                ([0, 1, u32::MAX, 0xFFFF][i as usize], u32::MAX)
            } else {
                (rng.next() as u32, rng.next() as u32 >> (rng.next() % 32))
            };
            let hi = ((u64::from(a) * u64::from(b)) >> 32) as u32;
            let est = mul_hi_split(a, b);
            assert!(est <= hi && hi - est <= 2, "{a} {b}");
        }
    }

    /// Both forms of the reciprocal stay at or below `2^63 / v`, within 2^-28 of it.
    #[test]
    fn reciprocal_is_below_and_close_in_both_forms() {
        fn check<const S: bool>(d: u32) {
            let r = RecipForm::<S>::new(d).unwrap();
            let exact = (1u128 << 63) as f64 / f64::from(r.v);
            let y = f64::from(r.y);
            assert!(
                y <= exact && (exact - y) / exact < 1.0 / (1u64 << 28) as f64,
                "{d} {S} {y} {exact}"
            );
        }
        for d in divisors(11) {
            check::<false>(d);
            check::<true>(d);
        }
    }

    fn fraction_of_floors<const S: bool>() {
        let mut rng = Rng(0x5EED_0030);
        for i in 0..300_000u32 {
            let dbits = 1 + (rng.next() % 28) as u32;
            let d = ((rng.next() as u32) >> (32 - dbits)).max(1);
            let a = if i % 3 == 0 {
                d - 1
            } else {
                (rng.next() as u32) % d
            };
            let k = match i % 3 {
                0 => 1 << 30,
                1 => 65535 << 13,
                _ => (rng.next() as u32) >> 2,
            };
            let bias = [0, d - 1, d / 2, (rng.next() as u32) % d][i as usize % 4];
            let r = RecipForm::<S>::new(d).unwrap();
            let want = (u64::from(a) * u64::from(k) + u64::from(bias)) / u64::from(d);
            assert_eq!(
                u64::from(r.fraction_of(a, k, bias)),
                want,
                "{a} {k} {bias} {d}"
            );
        }
    }

    #[test]
    fn fraction_of_floors_in_both_forms() {
        fraction_of_floors::<false>();
        fraction_of_floors::<true>();
    }

    fn recip63_is_the_floor<const S: bool>() {
        let mut rng = Rng(0x5EED_0063);
        for i in 0..200_000u32 {
            let d = match i {
                0 => 1 << 31,
                1 => u32::MAX,
                2 => (1 << 31) + 1,
                _ => (rng.next() as u32) | 1 << 31,
            };
            let want = (u64::MAX >> 1) / u64::from(d);
            assert_eq!(
                u64::from(RecipForm::<S>::new_normalized(d).recip63()),
                want,
                "{d}"
            );
        }
    }

    #[test]
    fn recip63_is_the_floor_in_both_forms() {
        recip63_is_the_floor::<false>();
        recip63_is_the_floor::<true>();
    }

    fn div_wide_is_exact<const S: bool>() {
        let mut rng = Rng(0x5EED_0064);
        for d in divisors(9) {
            let r = RecipForm::<S>::new(d).unwrap();
            let top = (u64::from(d) << 32) - 1;
            for n in [0, 1, u64::from(d), top, top - u64::from(d), top / 2] {
                assert_eq!(r.div_wide(n), Some((n / u64::from(d)) as u32), "{n} / {d}");
            }
            assert_eq!(r.div_wide(top + 1), None);
            assert_eq!(r.div_wide(u64::MAX), None);
            for _ in 0..64 {
                let n = (rng.next() >> (rng.next() % 64)) % (top + 1);
                assert_eq!(r.div_wide(n), Some((n / u64::from(d)) as u32), "{n} / {d}");
            }
        }
    }

    #[test]
    fn div_wide_is_exact_where_the_quotient_fits_in_both_forms() {
        div_wide_is_exact::<false>();
        div_wide_is_exact::<true>();
    }
}
