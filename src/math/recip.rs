//! Division-free reciprocal, quotient and integer square root.
//!
//! Cortex-M0+ has no divide instruction, so every quotient in fixel goes through
//! [`reciprocal_u32`]: normalise the divisor to `xn` in [2^31, 2^32) (so `xn / 2^32` is
//! in [0.5, 1)), look up an 8-bit seed for `1 / (xn / 2^32)` in Q1.15 (a 512-byte table),
//! refine it with two Newton–Raphson steps `y <- y (2 - d y)` on `u64` products (seed
//! error 2^-9, then 2^-18, then ~2^-31, limited by truncation), and finally correct the
//! last bits with an exact remainder check, so the mantissa is `2^63 / xn` rounded to
//! nearest: relative error <= 2^-32.
//!
//! Quotients (`div_fx`, `recip_fx`, and the crate-internal `div_round` used by the
//! trigonometry and the projection matrix) multiply by that reciprocal and then fix the
//! estimate with one exact `u64` remainder test, so they are *correctly rounded*
//! (to nearest, ties away from zero) — not 1-ulp approximations, and not truncating
//! like `fixed`'s own `/`.
//!
//! Square roots are the classic bit-by-bit (digit-by-digit) method: exact floor,
//! shifts and adds only.
//!
//! Q-formats: `Fx` is I16F16 (value = bits / 2^16). The reciprocal mantissa is an
//! unsigned Q0.32-style integer with an explicit exponent, `1/x ≈ m / 2^e`.

use super::Fx;

/// Seeds for `1/d`, `d = 0.5 + (i + 0.5) / 512` (the middle of the table cell), in Q1.15.
/// Index `i` is bits 30..23 of the normalised divisor. Max relative seed error 2^-9.
pub(crate) const SEED: [u16; 256] = [
    65408, 65154, 64902, 64652, 64404, 64158, 63913, 63671, 63430, 63191, 62954, 62719, 62485,
    62253, 62023, 61795, 61568, 61343, 61119, 60897, 60677, 60458, 60241, 60026, 59812, 59599,
    59388, 59179, 58971, 58764, 58559, 58356, 58153, 57952, 57753, 57555, 57358, 57163, 56968,
    56776, 56584, 56394, 56205, 56017, 55831, 55646, 55462, 55279, 55098, 54917, 54738, 54560,
    54383, 54207, 54033, 53859, 53687, 53516, 53346, 53177, 53009, 52842, 52676, 52511, 52347,
    52184, 52022, 51862, 51702, 51543, 51385, 51228, 51072, 50917, 50763, 50610, 50458, 50306,
    50156, 50007, 49858, 49710, 49563, 49417, 49272, 49128, 48985, 48842, 48700, 48559, 48419,
    48280, 48141, 48003, 47867, 47730, 47595, 47460, 47326, 47193, 47061, 46929, 46798, 46668,
    46539, 46410, 46282, 46155, 46028, 45902, 45777, 45652, 45528, 45405, 45283, 45161, 45040,
    44919, 44799, 44680, 44561, 44443, 44326, 44209, 44093, 43977, 43862, 43748, 43634, 43521,
    43408, 43296, 43185, 43074, 42963, 42854, 42744, 42636, 42528, 42420, 42313, 42207, 42101,
    41996, 41891, 41786, 41683, 41579, 41476, 41374, 41272, 41171, 41070, 40970, 40870, 40771,
    40672, 40574, 40476, 40378, 40281, 40185, 40089, 39993, 39898, 39804, 39709, 39616, 39522,
    39429, 39337, 39245, 39153, 39062, 38971, 38881, 38791, 38702, 38613, 38524, 38436, 38348,
    38260, 38173, 38087, 38000, 37915, 37829, 37744, 37659, 37575, 37491, 37407, 37324, 37241,
    37159, 37077, 36995, 36914, 36833, 36752, 36672, 36592, 36512, 36433, 36354, 36275, 36197,
    36119, 36041, 35964, 35887, 35810, 35734, 35658, 35583, 35507, 35432, 35358, 35283, 35209,
    35136, 35062, 34989, 34916, 34844, 34771, 34700, 34628, 34557, 34486, 34415, 34344, 34274,
    34204, 34135, 34065, 33996, 33928, 33859, 33791, 33723, 33655, 33588, 33521, 33454, 33387,
    33321, 33255, 33189, 33124, 33059, 32994, 32929, 32864, 32800,
];

const fn mantissa_table() -> [u32; 257] {
    let mut t = [0u32; 257];
    let mut i = 0;
    while i < 257 {
        // 2^62 / (2^31 (1 + i/256)) = 2^39 / (256 + i), rounded.
        t[i] = (((1u64 << 39) + (256 + i as u64) / 2) / (256 + i as u64)) as u32;
        i += 1;
    }
    t
}

/// `2^39 / (256 + i)` rounded, `i` in `0..=256`: `2^62 / m` at the 257 mantissas
/// `m = 2^31 + i 2^23`.
static RECIP_TABLE: [u32; 257] = mantissa_table();

/// `2^62 / m` for a normalised mantissa `m` in `[2^31, 2^32)`, in `(2^30, 2^31]`: the table
/// entry of `m`'s top 8 bits after the leading one, interpolated linearly with the next 9.
/// Relative error below 2^-16 (about 2^-18 of curvature, the rest from the 9-bit weight).
/// The per-pixel reciprocal of perspective interpolation, and the seed of
/// [`div_64_32`](super::div)'s Newton form.
#[inline(always)]
pub(crate) fn recip_mantissa(m: u32) -> u32 {
    let f = m.wrapping_sub(1 << 31);
    let idx = ((f >> 23) & 0xFF) as usize;
    let frac = (f >> 14) & 0x1FF; // 9 bits
    let a = RECIP_TABLE[idx];
    let b = RECIP_TABLE[idx + 1];
    // a - b < 2^23, so the product fits u32.
    a - (((a - b) * frac) >> 9)
}

/// `1 / x` as a mantissa and exponent: returns `(m, e)` with `m` in [2^31, 2^32) and
/// `1/x ≈ m / 2^e`, `m` rounded to nearest (relative error <= 2^-32; exact for powers of two).
///
/// `e` is in `31..=63` for `x >= 1`. `x == 0` saturates: returns `(u32::MAX, 0)`.
/// Uses no division: `leading_zeros`, a 256-entry seed table, two Newton–Raphson steps
/// and an exact remainder correction (at most a couple of increments).
pub fn reciprocal_u32(x: u32) -> (u32, u32) {
    if x == 0 {
        return (u32::MAX, 0);
    }
    let n = x.leading_zeros();
    let xn = x << n;
    if xn == 1 << 31 {
        // Power of two: 1/x = 2^31 / 2^(62 - n) exactly.
        return (1 << 31, 62 - n);
    }
    let d = u64::from(xn);
    // y approximates 2^63 / xn, i.e. 1 / (xn / 2^32) in Q1.31; always < 2^32 here.
    let mut y = u64::from(SEED[((xn >> 23) & 0xFF) as usize]) << 16;
    for _ in 0..2 {
        // d*y is (d/2^32)(y/2^31) in Q63, close to 2^63; both factors < 2^32.
        let p = d * y;
        // 2 - d y in Q63 (2 is 2^64, which wraps to 0): in (0, 2^64).
        let t = p.wrapping_neg();
        // y (2 - d y): Q31 * Q31 = Q62, back to Q31. Never exceeds 1/d, so stays < 2^32.
        y = (y * (t >> 32)) >> 31;
    }
    // Exact correction to m = floor(2^63 / xn), then round to nearest.
    const TWO63: u64 = 1 << 63;
    let mut m = y;
    while m * d > TWO63 {
        m -= 1;
    }
    while (m + 1) * d <= TWO63 {
        m += 1;
    }
    if 2 * (TWO63 - m * d) >= d {
        m += 1;
    }
    // xn > 2^31 so 2^63 / xn < 2^32 - 1: m fits.
    (m as u32, 63 - n)
}

/// `num / den` rounded to nearest (ties up), for `num < den * 2^32`; otherwise (or when
/// `den == 0`) returns `u64::MAX`. Any non-saturated result is `<= 2^32`.
///
/// Uses [`reciprocal_u32`] and one exact remainder correction: no division instruction.
pub(crate) fn div_round(num: u64, den: u32) -> u64 {
    let d = u64::from(den);
    if den == 0 || num >= d << 32 {
        return u64::MAX;
    }
    let (m, e) = reciprocal_u32(den);
    // Keep the top 32 significant bits of num so that nn * m fits in u64.
    let sh = 32u32.saturating_sub(num.leading_zeros());
    let nn = num >> sh;
    // num < den * 2^32 implies e - sh >= 30; the checked shift only guards the proof.
    let mut q = (nn * u64::from(m))
        .checked_shr(e.saturating_sub(sh))
        .unwrap_or(0);
    // The estimate is within a few units; walk it to floor(num / den).
    while q.saturating_mul(d) > num {
        q -= 1;
    }
    // Now q * d <= num, so q < 2^32 and q * d cannot overflow.
    while num - q * d >= d {
        q += 1;
    }
    if 2 * (num - q * d) >= d {
        q += 1;
    }
    q
}

/// Applies a sign to a magnitude in Q16 bits; `None` if the result does not fit in `Fx`.
pub(crate) fn signed_fx(mag: u64, negative: bool) -> Option<Fx> {
    let mag = i64::try_from(mag).ok()?;
    let v = if negative { -mag } else { mag };
    i32::try_from(v).ok().map(Fx::from_bits)
}

/// `a / b` in I16F16, correctly rounded (to nearest, ties away from zero).
///
/// `None` if `b == 0` or the quotient does not fit in `Fx`. Implemented with
/// [`reciprocal_u32`], a `u64` multiply and an exact remainder correction — no division
/// instruction. Note that it rounds, whereas `fixed`'s `/` truncates, so results can
/// differ from `a / b` by one ulp.
pub fn div_fx(a: Fx, b: Fx) -> Option<Fx> {
    let (a, b) = (a.to_bits(), b.to_bits());
    if b == 0 {
        return None;
    }
    let q = div_round(u64::from(a.unsigned_abs()) << 16, b.unsigned_abs());
    signed_fx(q, (a < 0) != (b < 0))
}

/// `1 / x` in I16F16, correctly rounded (to nearest, ties away from zero).
///
/// Saturates: `x == 0` gives `Fx::MAX`; `|x| <= 2^-15` (where `1/x` leaves the
/// ±32768 range) gives `Fx::MAX` or `Fx::MIN` by sign (`-2^-15` is exactly `Fx::MIN`).
pub fn recip_fx(x: Fx) -> Fx {
    if x == Fx::ZERO {
        return Fx::MAX;
    }
    match div_fx(Fx::ONE, x) {
        Some(v) => v,
        None if x > Fx::ZERO => Fx::MAX,
        None => Fx::MIN,
    }
}

/// Floor of the square root of `x`, exact for every `u32`. Bit-by-bit: shifts, adds and
/// compares on `u32` only (16 iterations at most).
pub fn isqrt_u32(x: u32) -> u16 {
    if x == 0 {
        return 0;
    }
    let mut rem = x;
    let mut res = 0u32;
    let mut bit = 1u32 << ((31 - x.leading_zeros()) & !1);
    while bit != 0 {
        if rem >= res + bit {
            rem -= res + bit;
            res = (res >> 1) + bit;
        } else {
            res >>= 1;
        }
        bit >>= 2;
    }
    res as u16
}

/// Floor of the square root of `x`, exact for every `u64`. Bit-by-bit like
/// [`isqrt_u32`], on `u64` (32 iterations at most).
pub fn isqrt_u64(x: u64) -> u32 {
    if x == 0 {
        return 0;
    }
    let mut rem = x;
    let mut res = 0u64;
    let mut bit = 1u64 << ((63 - x.leading_zeros()) & !1);
    while bit != 0 {
        if rem >= res + bit {
            rem -= res + bit;
            res = (res >> 1) + bit;
        } else {
            res >>= 1;
        }
        bit >>= 2;
    }
    res as u32
}

#[cfg(test)]
mod tests {
    extern crate std;
    use super::*;

    use crate::test_rng::Rng;

    /// Relative error of `m / 2^e` against `1 / x`, in units of 2^-32, computed exactly.
    fn rel_err_units(x: u32, m: u32, e: u32) -> f64 {
        let prod = u128::from(m) * u128::from(x);
        let one = 1u128 << e;
        let diff = prod.abs_diff(one);
        (diff as f64) / (one as f64) * 2f64.powi(32)
    }

    fn check_recip(x: u32, worst: &mut f64) {
        let (m, e) = reciprocal_u32(x);
        assert!(m >= 1 << 31, "x={x} m={m}");
        let err = rel_err_units(x, m, e);
        assert!(err <= 1.0, "x={x} m={m} e={e} err={err} (2^-32 units)");
        if err > *worst {
            *worst = err;
        }
    }

    #[test]
    fn reciprocal_relative_error() {
        let mut worst = 0.0f64;
        for x in 1..=200_000u32 {
            check_recip(x, &mut worst);
        }
        for k in 0..32 {
            for d in [-2i64, -1, 0, 1, 2] {
                let x = (1i64 << k) + d;
                if (1..=i64::from(u32::MAX)).contains(&x) {
                    check_recip(x as u32, &mut worst);
                }
            }
        }
        let mut rng = Rng(0x1234_5678_9abc_def1);
        for _ in 0..500_000 {
            let x = (rng.next() >> 32) as u32 >> (rng.next() % 32);
            if x != 0 {
                check_recip(x, &mut worst);
            }
        }
        check_recip(u32::MAX, &mut worst);
        // Round-to-nearest mantissa: |m x - 2^e| <= x/2, i.e. < 2^-32 relative.
        std::println!("reciprocal_u32 max rel err = {worst} * 2^-32");
        assert!(worst <= 1.0);
        assert_eq!(reciprocal_u32(0), (u32::MAX, 0));
        assert_eq!(reciprocal_u32(1), (1 << 31, 31));
    }

    #[test]
    fn div_round_exact() {
        let mut rng = Rng(0xdead_beef_cafe_f00d);
        for _ in 0..300_000 {
            let den = ((rng.next() >> 32) as u32 >> (rng.next() % 32)).max(1);
            let num = rng.next() >> (rng.next() % 64);
            let q = div_round(num, den);
            let (n, d) = (u128::from(num), u128::from(den));
            if n >= d << 32 {
                assert_eq!(q, u64::MAX);
            } else {
                let want = (2 * n + d) / (2 * d);
                assert_eq!(u128::from(q), want, "num={num} den={den}");
            }
        }
        assert_eq!(div_round(5, 0), u64::MAX);
        assert_eq!(div_round(u64::MAX, u32::MAX), u64::MAX);
        assert_eq!(
            div_round((u64::from(u32::MAX) << 32) - 1, u32::MAX),
            1 << 32
        );
    }

    /// Exact a/b in Q16 bits, rounded to nearest with ties away from zero.
    fn exact_div_bits(a: i32, b: i32) -> i64 {
        let n = i128::from(a) << 16;
        let d = i128::from(b);
        let q = (2 * n.abs() + d.abs()) / (2 * d.abs());
        (if (n < 0) != (d < 0) { -q } else { q }) as i64
    }

    #[test]
    fn div_fx_matches_exact() {
        let mut rng = Rng(42);
        for _ in 0..300_000 {
            let a = (rng.next() as i32) >> (rng.next() % 32);
            let b = (rng.next() as i32) >> (rng.next() % 32);
            let got = div_fx(Fx::from_bits(a), Fx::from_bits(b));
            if b == 0 {
                assert_eq!(got, None);
                continue;
            }
            let want = exact_div_bits(a, b);
            match i32::try_from(want) {
                Ok(w) => assert_eq!(got, Some(Fx::from_bits(w)), "a={a} b={b}"),
                Err(_) => assert_eq!(got, None, "a={a} b={b}"),
            }
        }
        let f = |x: f64| Fx::from_num(x);
        assert_eq!(div_fx(f(1.0), f(4.0)), Some(f(0.25)));
        assert_eq!(div_fx(f(-3.0), f(2.0)), Some(f(-1.5)));
        assert_eq!(div_fx(Fx::MIN, -Fx::ONE), None);
        assert_eq!(div_fx(Fx::MIN, Fx::ONE), Some(Fx::MIN));
    }

    #[test]
    fn recip_fx_within_one_ulp() {
        let mut worst = 0i64;
        let mut check = |bits: i32| {
            let got = recip_fx(Fx::from_bits(bits)).to_bits();
            let exact = (1i128 << 32) as f64 / f64::from(bits);
            let sat = exact.clamp(f64::from(i32::MIN), f64::from(i32::MAX));
            let err = (f64::from(got) - sat).abs();
            assert!(err <= 0.5, "bits={bits} got={got} exact={exact}");
            worst = worst.max(
                i64::from(got)
                    - exact_div_bits(1 << 16, bits).clamp(i64::from(i32::MIN), i64::from(i32::MAX)),
            );
        };
        for b in -70_000..=70_000 {
            if b != 0 {
                check(b);
            }
        }
        let mut rng = Rng(7);
        for _ in 0..200_000 {
            let b = (rng.next() as i32) >> (rng.next() % 32);
            if b != 0 {
                check(b);
            }
        }
        check(i32::MIN);
        check(i32::MAX);
        assert_eq!(worst, 0);
        assert_eq!(recip_fx(Fx::ZERO), Fx::MAX);
        assert_eq!(recip_fx(Fx::from_bits(1)), Fx::MAX);
        assert_eq!(recip_fx(Fx::from_bits(-1)), Fx::MIN);
        assert_eq!(recip_fx(Fx::from_bits(-2)), Fx::MIN);
        assert_eq!(recip_fx(Fx::from_num(2)), Fx::from_num(0.5));
    }

    #[test]
    fn isqrt_exact() {
        for x in 0..=(1u32 << 20) {
            assert_eq!(u32::from(isqrt_u32(x)), x.isqrt(), "x={x}");
            assert_eq!(isqrt_u64(u64::from(x)), x.isqrt(), "x={x}");
        }
        for r in 0..=u32::from(u16::MAX) {
            let s = r * r;
            for x in [s.saturating_sub(1), s, s.saturating_add(1)] {
                assert_eq!(u32::from(isqrt_u32(x)), x.isqrt(), "x={x}");
            }
        }
        let mut rng = Rng(99);
        for _ in 0..200_000 {
            let r = (rng.next() >> 32) as u32;
            let s = u64::from(r) * u64::from(r);
            for x in [s.saturating_sub(1), s, s.saturating_add(1), rng.next()] {
                assert_eq!(isqrt_u64(x), x.isqrt() as u32, "x={x}");
            }
            let y = rng.next() as u32 >> (rng.next() % 32);
            assert_eq!(u32::from(isqrt_u32(y)), y.isqrt());
        }
        assert_eq!(isqrt_u32(u32::MAX), u16::MAX);
        assert_eq!(isqrt_u64(u64::MAX), u32::MAX);
        assert_eq!(
            isqrt_u64(u64::from(u32::MAX) * u64::from(u32::MAX)),
            u32::MAX
        );
    }
}
