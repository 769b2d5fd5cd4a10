//! Per-pixel renormalisation without a square root or a divide: [`unit_q14`] turns an
//! interpolated vector of any length into a unit vector in Q14 (`16384` = 1.0) through a
//! 193-entry table of `1/sqrt`, linearly interpolated.
//!
//! Steps, for `v` with components below `2^31` in magnitude:
//!
//! 1. shift `v` (by `leading_zeros` of its largest component, rounding) so that component
//!    lies in `[2^14, 2^15]`; then `s = |v|^2` lies in `[2^28, 3 * 2^30]`;
//! 2. `r = 2^30 / sqrt(s)` (Q16) from the table at `s >> 22` with the next 16 bits as the
//!    interpolation weight (for `s >= 2^30`, half the table's value at `s / 4`);
//! 3. `v_i * r / 2^16`, rounded.
//!
//! Error: the table's interpolation error is below `3e-6` relative; with the truncations the
//! result's length is `1 ± 2^-13` and each component is within 1.25 LSB (Q14) of the exact
//! unit vector (a test sweeps it). Cost: one `leading_zeros`, three multiplies for `s`,
//! one table lerp (one multiply), three multiplies for the result: no divide.

/// `1.0` in the Q14 format of unit vectors.
pub const UNIT_Q14: i32 = 1 << 14;

/// Entries of the `1/sqrt` table: `s` in `[2^28, 2^30]` in steps of `2^22`.
const RSQRT_ENTRIES: usize = 193;

const fn isqrt_u128(x: u128) -> u128 {
    if x == 0 {
        return 0;
    }
    // Newton from above: x0 >= sqrt(x).
    let mut r = 1u128 << ((128 - x.leading_zeros()).div_ceil(2));
    loop {
        let n = (r + x / r) / 2;
        if n >= r {
            return r;
        }
        r = n;
    }
}

/// `round(2^30 / sqrt((64 + k) 2^22)) - 2^15` for `k` in `0..=192`.
const RSQRT: [u16; RSQRT_ENTRIES] = {
    let mut t = [0u16; RSQRT_ENTRIES];
    let mut k = 0;
    while k < RSQRT_ENTRIES {
        let s = ((64 + k) as u128) << 22;
        // 2^30 / sqrt(s) = sqrt(2^60 / s); with 8 more bits for rounding.
        let r = isqrt_u128((1u128 << 76) / s); // = 2^30 / sqrt(s) * 2^8
        t[k] = (((r + 128) >> 8) - (1 << 15)) as u16;
        k += 1;
    }
    t
};

/// `2^30 / sqrt(s)` in Q16 for `s` in `[2^28, 2^30)`: `(2^15, 2^16]`.
#[inline(always)]
fn rsqrt_q16(s: u32) -> u32 {
    let i = ((s >> 22) as usize)
        .saturating_sub(64)
        .min(RSQRT_ENTRIES - 2);
    let frac = (s >> 6) & 0xFFFF;
    let a = RSQRT.get(i).copied().unwrap_or(0) as i32;
    let b = RSQRT.get(i + 1).copied().unwrap_or(0) as i32;
    // b <= a; |b - a| < 2^9, so the product fits i32.
    let r = a + (((b - a) * frac as i32) >> 16);
    (r + (1 << 15)) as u32
}

/// `v / |v|` in Q14 (`16384` = 1.0); the zero vector stays zero. Any component magnitude
/// below `2^31` is accepted (`i32::MIN` is treated as `-i32::MAX`). Never panics.
#[inline(always)]
pub fn unit_q14(v: [i32; 3]) -> [i32; 3] {
    let v = v.map(|c| c.max(-i32::MAX));
    let a = v[0].unsigned_abs() | v[1].unsigned_abs() | v[2].unsigned_abs();
    if a == 0 {
        return [0; 3];
    }
    // The OR has the largest component's top bit: shift it into [2^14, 2^15), rounding.
    let sh = super::wide::clz32(a) as i32 - 17;
    let v = if sh >= 0 {
        v.map(|c| c << sh)
    } else {
        let k = (-sh) as u32;
        v.map(|c| ((c >> (k - 1)) + 1) >> 1)
    };
    // |v_i| <= 2^15 after rounding: s <= 3 * 2^30 fits u32.
    let s = v
        .iter()
        .map(|&c| (c * c) as u32)
        .fold(0u32, u32::wrapping_add);
    let r = if s >= 1 << 30 {
        // 1/sqrt(s) = 1/sqrt(s/4) / 2.
        (rsqrt_q16(s >> 2) >> 1) as i32
    } else {
        rsqrt_q16(s) as i32
    };
    v.map(|c| (c * r + (1 << 15)) >> 16)
}

/// Dot product of two Q14 vectors, Q14 (`16384` = 1.0 for equal unit vectors).
#[inline(always)]
pub fn dot_q14(a: [i32; 3], b: [i32; 3]) -> i32 {
    (a[0] * b[0] + a[1] * b[1] + a[2] * b[2]) >> 14
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn table_ends() {
        assert_eq!(RSQRT[0], 1 << 15); // 2^30 / 2^14 = 2^16
        assert_eq!(RSQRT[192], 0); // 2^30 / 2^15
    }

    #[test]
    fn unit_vectors_are_within_one_lsb() {
        let mut worst = 0f64;
        let mut x: u64 = 12345;
        for n in 0..200_000 {
            x = x
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            let bits = (x >> 59) as u32 + 1; // component magnitudes below 2^bits, 1..=32
            let c = |k: u32| ((x >> k) as u32 as i32) >> (32 - bits);
            let v = if n == 0 {
                [i32::MAX, i32::MIN, 7]
            } else {
                [c(0), c(11), c(22)]
            };
            let u = unit_q14(v);
            let f = v.map(|c| c.max(-i32::MAX) as f64);
            let len = (f[0] * f[0] + f[1] * f[1] + f[2] * f[2]).sqrt();
            if len == 0.0 {
                assert_eq!(u, [0; 3]);
                continue;
            }
            for k in 0..3 {
                worst = worst.max((u[k] as f64 - f[k] / len * 16384.0).abs());
            }
        }
        assert!(worst <= 1.25, "worst component error {worst} LSB");
    }
}
