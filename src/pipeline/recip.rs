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

const fn table() -> [u32; 257] {
    let mut t = [0u32; 257];
    let mut i = 0;
    while i < 257 {
        // 2^62 / (2^31 (1 + i/256)) = 2^39 / (256 + i), rounded.
        t[i] = (((1u64 << 39) + (256 + i as u64) / 2) / (256 + i as u64)) as u32;
        i += 1;
    }
    t
}

static RECIP_TABLE: [u32; 257] = table();

/// `2^46 / q` (that is, `1/q` for Q30 `q`, as Q16), for `q` clamped into
/// `[Q_FLOOR, Q_ONE]`.
#[inline(always)]
pub fn recip_q30(q: i32) -> u32 {
    let q = q.clamp(Q_FLOOR as i32, Q_ONE as i32) as u32;
    let n = q.leading_zeros(); // 1..=16
    let m = q << n; // [2^31, 2^32)
    let f = m - (1 << 31);
    let idx = (f >> 23) as usize; // 0..=255
    let frac = (f >> 14) & 0x1FF; // 9 bits
    let a = RECIP_TABLE[idx & 0xFF];
    let b = RECIP_TABLE[(idx & 0xFF) + 1];
    let y = a - (((a - b) * frac) >> 9); // ~ 2^62 / m
                                         // 2^46 / q = 2^(46 + n) / m = y / 2^(16 - n).
    y >> (16 - n)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn relative_error_below_2_pow_minus_16() {
        let mut worst = 0.0f64;
        let mut q = Q_FLOOR;
        while q <= Q_ONE {
            let got = recip_q30(q as i32) as f64;
            let want = (1u64 << 46) as f64 / q as f64;
            worst = worst.max(((got - want) / want).abs());
            q += 128;
        }
        assert!(worst < 1.0 / 65536.0, "worst relative error {worst}");
    }

    #[test]
    fn clamps_out_of_range_input() {
        assert_eq!(recip_q30(0), recip_q30(Q_FLOOR as i32));
        assert_eq!(recip_q30(-5), recip_q30(Q_FLOOR as i32));
        assert_eq!(recip_q30(i32::MAX), recip_q30(Q_ONE as i32));
    }
}
