//! Level of detail: GL's minification controls ([`Lod`], [`MipFilter`], where `lambda` is
//! computed) and `lambda` itself, Q8.8, from the texel coordinates' screen-space
//! derivatives (Heckbert's `rho`, without a square root: see the module above).

/// Filtering between mip levels.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum MipFilter {
    /// No mipmapping: the minification filter samples level 0.
    #[default]
    None,
    /// Nearest level (`*_MIPMAP_NEAREST`).
    Nearest,
    /// Blend of the two nearest levels (`*_MIPMAP_LINEAR`).
    Linear,
}

/// Level-of-detail controls.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Lod {
    /// Added to `lambda`, Q8.8 (256 = one level).
    pub bias: i32,
    /// Smallest `lambda` after the bias, Q8.8.
    pub min: i32,
    /// Largest `lambda` after the bias, Q8.8.
    pub max: i32,
    /// Where `lambda` is computed.
    pub granularity: LodGranularity,
}

/// Bias 0, no clamps (`min`/`max` at ±1000 levels, beyond any chain) and LOD computed at
/// every pixel ([`LodGranularity::Pixel`]), as GL's defaults.
impl Default for Lod {
    fn default() -> Self {
        Lod {
            bias: 0,
            min: -1000 * 256,
            max: 1000 * 256,
            granularity: LodGranularity::Pixel,
        }
    }
}

/// How often the level of detail is computed.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum LodGranularity {
    /// At every pixel (exact derivatives; the most expensive).
    #[default]
    Pixel,
    /// Once per span, at its first pixel.
    Span,
    /// Once per triangle, at the reference pixel (exact for affine mappings, where the
    /// derivatives are constant).
    Triangle,
}

/// `log2(x)` in Q8.8 for `x > 0` (`x = 0` gives `i32::MIN / 2`), within 1/64.
#[inline(always)]
pub fn log2_q8(x: u64) -> i32 {
    if x == 0 {
        return i32::MIN / 2;
    }
    let n = 63 - x.leading_zeros();
    let idx = if n >= 6 {
        (x >> (n - 6)) & 63
    } else {
        (x << (6 - n)) & 63
    };
    (n as i32) * 256 + i32::from(LOG2_FRAC[idx as usize])
}

/// `256 * log2(1 + (i + 0.5) / 64)`, rounded: the mid-point of each 1/64 mantissa bucket.
static LOG2_FRAC: [u8; 64] = [
    3, 9, 14, 20, 25, 30, 36, 41, 46, 51, 56, 61, 66, 71, 75, 80, 85, 89, 94, 98, 103, 107, 111,
    116, 120, 124, 128, 132, 136, 140, 144, 148, 152, 155, 159, 163, 167, 170, 174, 178, 181, 185,
    188, 192, 195, 198, 202, 205, 208, 212, 215, 218, 221, 224, 228, 231, 234, 237, 240, 243, 246,
    249, 252, 255,
];

/// `lambda` (Q8.8) from level-0 texel derivatives per pixel (I16F16 bits):
/// `log2(max(ux^2 + vx^2, uy^2 + vy^2)) / 2`.
#[inline(always)]
pub fn lambda_q8(ux: i32, vx: i32, uy: i32, vy: i32) -> i32 {
    let sq = |a: i32| u64::from(a.unsigned_abs()) * u64::from(a.unsigned_abs());
    let dx = sq(ux).saturating_add(sq(vx));
    let dy = sq(uy).saturating_add(sq(vy));
    // Squares of I16F16 are 32 fraction bits: log2 - 32, halved.
    (log2_q8(dx.max(dy)) - 32 * 256) >> 1
}

#[cfg(test)]
mod tests {
    extern crate std;
    use super::*;

    #[test]
    fn log2_table_within_a_64th() {
        for (i, &got) in LOG2_FRAC.iter().enumerate() {
            let want = (256.0 * (1.0 + (i as f64 + 0.5) / 64.0).log2()).round() as u8;
            assert_eq!(got, want, "entry {i}");
        }
        for x in [1u64, 2, 3, 7, 100, 12345, 1 << 40, u64::MAX] {
            let got = f64::from(log2_q8(x)) / 256.0;
            assert!(
                (got - (x as f64).log2()).abs() <= 1.0 / 64.0 + 1e-9,
                "{x}: {got}"
            );
        }
    }

    #[test]
    fn lambda_of_unit_and_double_derivatives() {
        let one = 1 << 16;
        assert!(lambda_q8(one, 0, 0, one).abs() <= 4);
        assert!((lambda_q8(2 * one, 0, 0, one) - 256).abs() <= 4);
        assert!((lambda_q8(one / 4, 0, 0, one / 4) + 512).abs() <= 4);
    }
}
