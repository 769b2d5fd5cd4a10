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

/// GL's cube-map `lambda` (Q8.8, OpenGL ES 3.2 sections 8.13 and 8.14) of a direction
/// field at one pixel, in units of half a face: `log2` of the larger of the screen
/// derivative lengths of `(sc / ma, tc / ma)` on the face `d` selects (ties x before y
/// before z, as [`face_coords`](crate::shading::env::face_coords)). A face of side
/// `2^l` texels adds `(l - 1) * 256`.
///
/// `d` is the direction at the pixel and `dx`, `dy` its change per pixel right and down,
/// all of one common but arbitrary scale (only the direction matters): the varyings of an
/// affine mapping, or the perspective numerators `d q`, which are linear in screen space.
/// With `M` the major component and `c` a minor one, `d(c / M) = (c' M - c M') / M^2`.
///
/// Fixed point: `d` is shifted so `|M|` is in `[2^14, 2^15)` and the six derivatives
/// share a shift that brings the largest into the same range, so every product fits
/// `i32` and the two sums of squares `u64`; three `log2` lookups make the result within
/// about 1/40 of a level (see the tests). The zero direction gives 0; derivatives all
/// zero give `i32::MIN / 4` (magnification).
#[inline(always)]
pub fn direction_lambda(d: [i32; 3], dx: [i32; 3], dy: [i32; 3]) -> i32 {
    let [ax, ay, az] = d.map(i32::unsigned_abs);
    let (m, i, j) = if ax >= ay && ax >= az {
        (0, 1, 2)
    } else if ay >= az {
        (1, 0, 2)
    } else {
        (2, 0, 1)
    };
    let ma = d[m].unsigned_abs();
    if ma == 0 {
        return 0;
    }
    let big = dx
        .iter()
        .chain(dy.iter())
        .fold(0u32, |b, c| b.max(c.unsigned_abs()));
    if big == 0 {
        return i32::MIN / 4;
    }
    // Shifts that bring |M| and the largest derivative to [2^14, 2^15): right for larger
    // values, left (|c| <= |M| and |c'| <= big, so no overflow) for smaller ones.
    let sv = 17 - ma.leading_zeros() as i32;
    let sd = 17 - big.leading_zeros() as i32;
    let norm = |c: i32, sh: i32| if sh >= 0 { c >> sh } else { c << -sh };
    let (mv, iv, jv) = (norm(d[m], sv), norm(d[i], sv), norm(d[j], sv));
    // |c' M - c M'| < 2^15 2^15 + 2^15 2^15 = 2^31; squares below 2^62, their sum 2^63.
    let rho2 = |g: [i32; 3]| {
        let (gm, gi, gj) = (norm(g[m], sd), norm(g[i], sd), norm(g[j], sd));
        let ni = i64::from(gi * mv) - i64::from(iv * gm);
        let nj = i64::from(gj * mv) - i64::from(jv * gm);
        let sq = |n: i64| n.unsigned_abs() * n.unsigned_abs();
        sq(ni) + sq(nj)
    };
    let r2 = rho2(dx).max(rho2(dy));
    let m2 = (mv.unsigned_abs() * mv.unsigned_abs()) as u64;
    // log2(sqrt(r2) / M^2) + (sd - sv): the shifts of the numerator (sd + sv) and of M^2
    // (2 sv).
    (log2_q8(r2) >> 1) - log2_q8(m2) + (sd - sv) * 256
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

    /// GL's cube-map lambda in f64 from the same inputs, half-face units.
    fn direction_lambda_f64(d: [i32; 3], dx: [i32; 3], dy: [i32; 3]) -> f64 {
        let f = |a: [i32; 3]| a.map(f64::from);
        let (d, dx, dy) = (f(d), f(dx), f(dy));
        let [ax, ay, az] = d.map(f64::abs);
        let (m, i, j) = if ax >= ay && ax >= az {
            (0, 1, 2)
        } else if ay >= az {
            (1, 0, 2)
        } else {
            (2, 0, 1)
        };
        let rho = |g: [f64; 3]| {
            let a = (g[i] * d[m] - d[i] * g[m]) / (d[m] * d[m]);
            let b = (g[j] * d[m] - d[j] * g[m]) / (d[m] * d[m]);
            a.hypot(b)
        };
        rho(dx).max(rho(dy)).log2()
    }

    #[test]
    fn direction_lambda_matches_f64() {
        let mut rng = crate::test_rng::Rng(0x5EED_CAFE_0123_4567);
        let mut worst = 0.0f64;
        for _ in 0..200_000 {
            let (vb, db) = (2 + (rng.next() % 30) as u32, 2 + (rng.next() % 30) as u32);
            let mut r = |bits: u32| (rng.next() as i32) >> (32 - bits.clamp(2, 32));
            let d = [r(vb), r(vb), r(vb)];
            let dx = [r(db), r(db), r(db)];
            let dy = [r(db), r(db), r(db)];
            let want = direction_lambda_f64(d, dx, dy);
            let got = f64::from(direction_lambda(d, dx, dy)) / 256.0;
            // Only where the value has enough bits to define a direction and the
            // derivative is not lost against it (a level range that matters: -16..16).
            let ma = d.iter().map(|c| c.unsigned_abs()).max().unwrap();
            if ma < 1 << 12 || !(-16.0..16.0).contains(&want) {
                continue;
            }
            let e = (got - want).abs();
            worst = worst.max(e);
            assert!(e <= 0.04, "{d:?} {dx:?} {dy:?}: {got} vs {want}");
        }
        assert!(worst > 0.0);
        // Edge cases: the zero direction, zero derivatives, extremes.
        assert_eq!(direction_lambda([0; 3], [1, 2, 3], [4, 5, 6]), 0);
        assert_eq!(direction_lambda([5, 0, 0], [0; 3], [0; 3]), i32::MIN / 4);
        let ext = [i32::MIN, i32::MAX, i32::MIN];
        let _ = direction_lambda(ext, ext, ext);
        let _ = direction_lambda([1, 0, 0], ext, ext);
    }

    #[test]
    fn lambda_of_unit_and_double_derivatives() {
        let one = 1 << 16;
        assert!(lambda_q8(one, 0, 0, one).abs() <= 4);
        assert!((lambda_q8(2 * one, 0, 0, one) - 256).abs() <= 4);
        assert!((lambda_q8(one / 4, 0, 0, one / 4) + 512).abs() <= 4);
    }
}
