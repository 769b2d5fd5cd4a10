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
/// `i64` product compiles to (the vertex transforms' 12 products per vertex were the
/// largest single cost of the banded environment-mapping scene on Cortex-M0+).
#[inline]
pub(crate) fn prod(a: Fx, b: Fx) -> i64 {
    super::div::mul_wide_signed(a.to_bits(), b.to_bits())
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
}
