//! The per-pixel reciprocal of perspective interpolation: `2^46 / q` for the normalized
//! `1/w` interpolant `q` (Q30, in `[2^15, 2^30]`), without a divide instruction.
//!
//! Method: normalise `q` to a mantissa `m` in `[2^31, 2^32)` with `leading_zeros`, look up
//! `2^62 / m` in a 257-entry table indexed by the mantissa's top 8 bits after the leading
//! one, and interpolate linearly with the next 9 bits. Relative error below 2^-16 (the
//! table's own curvature error is about 2^-18, the 9-bit interpolation weight adds the
//! rest), measured over every 2^7-th value of the domain in the test below. The result is
//! at most 2^31, so `s * r` fits `i64` for any `|s| < 2^31`; on Cortex-M4 that product is
//! one `smull`.

/// Smallest `q` the reciprocal accepts (2^15): the perspective set-up clamps to it, which
/// limits the ratio of the largest to the smallest `w` within one triangle to 32768.
pub const Q_FLOOR: u32 = 1 << 15;
/// `q` of the vertex with the smallest `w` (1.0 in Q30).
pub const Q_ONE: u32 = 1 << 30;

use crate::math::recip::recip_mantissa;

/// `2^46 / q` (that is, `1/q` for Q30 `q`, as Q16), for `q` clamped below to
/// `Q_FLOOR + 1`: the result is below 2^31, so it is a non-negative `i32` and [`mul_q16`]
/// is one signed 32x32->64 multiply (`smull`) where the core has one. Values above
/// `Q_ONE` (rounding at the nearest vertex) need no clamp: the table covers every
/// normalised mantissa, so they get their own, correct reciprocal.
#[inline(always)]
pub fn recip_q30(q: i32) -> i32 {
    let q = q.max(Q_FLOOR as i32 + 1) as u32;
    let (n, m) = normalize(q); // n in 1..=16, m = q << n in [2^31, 2^32)
    let y = recip_mantissa(m); // ~ 2^62 / m
                               // 2^46 / q = 2^(46 + n) / m = y / 2^(16 - n).
    (y >> (16 - n)) as i32
}

/// `(q.leading_zeros(), q << q.leading_zeros())` for `q` in `[2^15, 2^31)`.
///
/// ARMv6-M is recognised as an Arm target without compare-and-swap atomics
/// (`not(target_has_atomic = "32")`): stable Rust exposes no Arm architecture-version
/// `target_feature`, and ARMv6-M is the Arm profile that lacks both CAS and `clz`/`smull`.
///
/// ARMv6-M (Cortex-M0/M0+) has no count-leading-zeros instruction, and the library routine
/// costs about 35 instructions per call; five compares do it in about 15, with the same
/// result. Cores with `clz` use it.
#[inline(always)]
fn normalize(q: u32) -> (u32, u32) {
    #[cfg(all(target_arch = "arm", not(target_has_atomic = "32")))]
    {
        normalize_no_clz(q)
    }
    #[cfg(not(all(target_arch = "arm", not(target_has_atomic = "32"))))]
    {
        let n = q.leading_zeros();
        (n, q << n)
    }
}

/// [`normalize`] by five compares (compiled everywhere so every target tests it).
#[cfg_attr(
    not(all(target_arch = "arm", not(target_has_atomic = "32"))),
    allow(dead_code)
)]
#[inline(always)]
fn normalize_no_clz(q: u32) -> (u32, u32) {
    {
        let (mut n, mut m) = (0, q);
        if m < 1 << 16 {
            m <<= 16;
            n += 16;
        }
        if m < 1 << 24 {
            m <<= 8;
            n += 8;
        }
        if m < 1 << 28 {
            m <<= 4;
            n += 4;
        }
        if m < 1 << 30 {
            m <<= 2;
            n += 2;
        }
        if m < 1 << 31 {
            m <<= 1;
            n += 1;
        }
        (n, m)
    }
}

/// `(a * r) >> 16` for `r` in `[0, 2^31)`, truncated to `i32` (wrapping), exactly.
///
/// One `smull` on cores with a 32x32->64 multiply. ARMv6-M has only a 32-bit multiply and
/// would call `__aeabi_lmul` (about 25 instructions); there it is four 16x16 products:
/// with `a = ah 2^16 + al` and `r = rh 2^16 + rl`,
/// `floor(a r / 2^16) = ah rh 2^16 + ah rl + al rh + floor(al rl / 2^16)`, the same bits.
#[inline(always)]
pub fn mul_q16(a: i32, r: i32) -> i32 {
    #[cfg(all(target_arch = "arm", not(target_has_atomic = "32")))]
    {
        mul_q16_split(a, r)
    }
    #[cfg(not(all(target_arch = "arm", not(target_has_atomic = "32"))))]
    {
        ((i64::from(a) * i64::from(r)) >> 16) as i32
    }
}

/// The 32-bit-multiply form of [`mul_q16`] (compiled everywhere so every target tests it).
#[cfg_attr(
    not(all(target_arch = "arm", not(target_has_atomic = "32"))),
    allow(dead_code)
)]
#[inline(always)]
pub(crate) fn mul_q16_split(a: i32, r: i32) -> i32 {
    let (ah, al) = (a >> 16, a & 0xFFFF);
    let (rh, rl) = (r >> 16, r & 0xFFFF);
    let low = ((al as u32).wrapping_mul(rl as u32) >> 16) as i32;
    (ah.wrapping_mul(rh) << 16)
        .wrapping_add(ah.wrapping_mul(rl))
        .wrapping_add(al.wrapping_mul(rh))
        .wrapping_add(low)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn relative_error_below_2_pow_minus_16() {
        let mut worst = 0.0f64;
        let mut q = Q_FLOOR + 1;
        while q <= Q_ONE {
            let got = recip_q30(q as i32) as f64;
            let want = (1u64 << 46) as f64 / q as f64;
            worst = worst.max(((got - want) / want).abs());
            q += 128;
        }
        assert!(worst < 1.0 / 65536.0, "worst relative error {worst}");
    }

    #[test]
    fn split_multiply_equals_the_64_bit_one() {
        let mut x = 0x1234_5678_9abc_def1u64;
        let mut next = || {
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
            x
        };
        let edges = [0, 1, -1, i32::MIN, i32::MAX, 65535, -65536, 1 << 30];
        for &a in &edges {
            for &r in &[0, 1, 65535, 65536, i32::MAX, 1 << 30] {
                assert_eq!(
                    mul_q16_split(a, r),
                    ((i64::from(a) * i64::from(r)) >> 16) as i32
                );
            }
        }
        for _ in 0..200_000 {
            let a = next() as i32;
            let r = (next() as u32 >> 1) as i32;
            assert_eq!(
                mul_q16_split(a, r),
                ((i64::from(a) * i64::from(r)) >> 16) as i32,
                "{a} {r}"
            );
        }
    }

    #[test]
    fn normalize_without_clz_equals_leading_zeros() {
        let mut q = 1u32 << 15;
        while q < 1 << 31 {
            for d in [0, 1, 7, 12345] {
                let x = q.saturating_add(d).min((1 << 31) - 1);
                let n = x.leading_zeros();
                assert_eq!(normalize_no_clz(x), (n, x << n));
            }
            q += q / 997 + 1;
        }
    }

    #[test]
    fn result_fits_a_non_negative_i32() {
        for q in [
            i32::MIN,
            0,
            Q_FLOOR as i32,
            Q_FLOOR as i32 + 1,
            1 << 20,
            Q_ONE as i32,
            i32::MAX,
        ] {
            assert!(recip_q30(q) > 0);
        }
    }

    #[test]
    fn above_one_stays_a_reciprocal() {
        // q slightly above Q_ONE happens by rounding at the nearest vertex; the result has
        // 16 significant bits there.
        let mut q = Q_ONE;
        while q < 2 * Q_ONE - 1 {
            let got = f64::from(recip_q30(q as i32));
            let want = (1u64 << 46) as f64 / f64::from(q);
            assert!(((got - want) / want).abs() < 1.0 / 16384.0, "{q}");
            q += 4099;
        }
    }

    #[test]
    fn clamps_out_of_range_input() {
        assert_eq!(recip_q30(0), recip_q30(Q_FLOOR as i32 + 1));
        assert_eq!(recip_q30(-5), recip_q30(Q_FLOOR as i32 + 1));
        // Above Q_ONE (rounding at the nearest vertex): still the reciprocal, not a clamp.
        let r = recip_q30(i32::MAX);
        assert!((r - (1 << 15)).abs() <= 1, "{r}");
    }
}
