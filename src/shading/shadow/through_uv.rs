//! Light-space coordinates carried through the texture coordinates: the shadow lookup's
//! real-time form, with no light varyings in the span loop.
//!
//! Across one triangle every varying is an affine function of the barycentric coordinates,
//! so where the texture coordinates `(u, v)` span the triangle (their triangle has an area)
//! each light coordinate is an affine function of them:
//!
//! ```text
//! L(u, v) - L0 = a (u - u0) + b (v - v0)
//! ```
//!
//! with `a`, `b` solved once per triangle from its three vertices (Cramer's rule). The span
//! loop then interpolates only the inner shader's varyings
//! ([`Shader::INTERPOLATED`](crate::shading::Shader::INTERPOLATED)), and each pixel gets its
//! light coordinates from its `u, v` with two 32-bit multiplies per coordinate.
//!
//! # Formats and error
//!
//! `u - u0` and `v - v0` (I16F16 texel units, as the fragment has them) are each shifted
//! right by the smallest shift that brings the triangle's largest vertex difference on that
//! axis below `2^15` ([`COORD_BITS`]); the coefficients are `a 2^q` rounded to `i32` with
//! `q` (per light coordinate, at most 30) the largest that keeps both below `2^15`, so each
//! product and their sum fit `i32`. The solve keeps 7 more bits per axis and divides once
//! per triangle (a 64-bit reciprocal of the determinant). Inside the triangle the result differs from the exact
//! affine map by at most `2^-11 c` of the triangle's largest light-coordinate difference
//! from vertex 0, plus 2 units, where `c = e_u e_v / A` is the conditioning of its texture
//! coordinates (extents `e_u`, `e_v`, area `A`: 2 for a right triangle along the axes;
//! tested up to 64). For a right triangle that spans a whole 64 x 64 map that is 1/16
//! texel, and 64 depth steps across the whole depth range (such a sloped receiver's bias
//! is several hundred steps). The map coordinates `s, t` come out absolute (vertex 0's value
//! folded into the sum, [`ABSOLUTE`]: the lookup adds nothing per pixel), which caps their
//! `q` so that every value of the triangle times `2^q` fits `i32`: that adds at most
//! `2^-14` of the largest value (1/256 texel of a 64 x 64 map). Beyond that the fragment's
//! `u, v` carry the span loop's own interpolation error, as the light varyings would.
//!
//! A triangle whose texture coordinates have no area at this precision (a sliver thinner
//! than `2^-15` of its extent) takes its first vertex's light coordinates for every pixel;
//! slivers lose precision in proportion to `c` before that: give meshes with slivers in
//! texture space the light-varying form.

use crate::math::div_u64;

/// How many light coordinates, from the first, [`UvLight::at`] gives absolute (the map's
/// `s, t`, or a spot light's `a, b`): the lookup then adds no vertex-0 value to them.
pub const ABSOLUTE: usize = 2;

/// Bits of a fragment's `u - u0`, `v - v0` after their shift.
const COORD_BITS: u32 = 15;
/// Bits of a coefficient: with [`COORD_BITS`], each product below `2^30`.
const COEF_BITS: u32 = 30 - COORD_BITS;
/// Bits of the differences the solve keeps (the determinant below `2^(2 SOLVE_BITS + 1)`,
/// a coefficient's numerator times `2^e` below `2^(COEF_BITS + 2 SOLVE_BITS + 1)` = 2^62).
const SOLVE_BITS: u32 = 22;

/// The per-triangle map from a fragment's `(u, v)` to its light coordinates (differences
/// from vertex 0, in the light's formats).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct UvLight {
    /// Vertex 0's `u, v` in the fragment's units (I16F16 texels, wrapping).
    pub(super) origin: [i32; 2],
    /// Right shifts of `u - u0` and of `v - v0`.
    pub(super) p: [u8; 2],
    /// Per light coordinate: right shift of the sum.
    pub(super) q: [u8; 4],
    /// Per light coordinate: `a 2^q` (below `2^15`).
    pub(super) a: [i32; 4],
    /// Per light coordinate: `b 2^q`.
    pub(super) b: [i32; 4],
    /// The first [`ABSOLUTE`] coordinates' vertex-0 value times `2^q`: those come out
    /// absolute, not as differences.
    pub(super) c: [i32; ABSOLUTE],
}

/// `x << k` for `|x| < 2^33`, saturated at `±2^46` (then `>> 31` is below `2^15`).
#[inline(always)]
fn widen(x: i64, k: u32) -> i64 {
    const LIMIT: i64 = 1 << 46;
    x.saturating_mul(1 << k.min(31)).clamp(-LIMIT, LIMIT)
}

impl UvLight {
    /// The map of a triangle whose vertices have texture coordinates `uv` (the inner shader's
    /// values after its [`Shader::triangle`](crate::shading::Shader::triangle) hook, before
    /// the span loop's left shift `shift`) and light coordinates `light` (`n` of them used).
    pub fn solve(uv: [[i32; 2]; 3], shift: u32, light: [[i32; 4]; 3], n: usize) -> UvLight {
        let origin = [uv[0][0].wrapping_shl(shift), uv[0][1].wrapping_shl(shift)];
        let diff = |i: usize, c: usize| {
            let d = i64::from(uv[i][c]) - i64::from(uv[0][c]);
            widen(d, shift)
        };
        let (du1, dv1, du2, dv2) = (diff(1, 0), diff(1, 1), diff(2, 0), diff(2, 1));
        // Per axis, the smallest shift that brings its largest difference below 2^15.
        let shift_of = |a: i64, b: i64| {
            let largest = a.unsigned_abs().max(b.unsigned_abs());
            (64 - largest.leading_zeros())
                .saturating_sub(COORD_BITS)
                .min(31)
        };
        let (pu, pv) = (shift_of(du1, du2), shift_of(dv1, dv2));
        // Without a solve (below), every pixel gets vertex 0's coordinates.
        let mut out = UvLight {
            origin,
            p: [pu as u8, pv as u8],
            c: [light[0][0], light[0][1]],
            ..UvLight::default()
        };
        // The solve keeps 9 more bits per axis than the pixels (differences below 2^24, the
        // determinant below 2^49): its rounding stays far below the pixels'.
        let (su, sv) = (
            pu.saturating_sub(SOLVE_BITS - COORD_BITS),
            pv.saturating_sub(SOLVE_BITS - COORD_BITS),
        );
        let (u1, u2, v1, v2) = (du1 >> su, du2 >> su, dv1 >> sv, dv2 >> sv);
        let det = u1 * v2 - u2 * v1;
        if det == 0 {
            return out;
        }
        let det_abs = det.unsigned_abs();
        let det_bits = 64 - det_abs.leading_zeros();
        // One division per triangle: 2^62 / |det|, at least 2^17 (|det| < 2^45), so each
        // coefficient below 2^15 comes out within a quarter unit plus its rounding.
        let inv = div_u64(1 << 62, det_abs);
        let [l0, l1s, l2s] = light;
        for (c, ((&x0, &x1), &x2)) in l0.iter().zip(&l1s).zip(&l2s).enumerate().take(n) {
            let l1 = i64::from(x1) - i64::from(x0);
            let l2 = i64::from(x2) - i64::from(x0);
            // Below 2^33 x 2^24 x 2: no overflow.
            let na = l1 * v2 - l2 * v1;
            let nb = u1 * l2 - u2 * l1;
            let big = na.unsigned_abs().max(nb.unsigned_abs());
            // The coefficients per pixel unit (2^(pu - su) solve units of u, likewise v) are
            // n 2^e / det with e = q + (pu - su) for a, q + (pv - sv) for b. From the bit
            // lengths, q0 keeps both below 2^15 and q0 + 1 below 2^16: they are computed at
            // q0 + 1 (at most 30) and halved back to q0 when one reaches 2^15. Then
            // |n| 2^e < 2^(16 + bits(det)) <= 2^61.
            let extra = (pu - su).max(pv - sv) as i32;
            let q0 =
                COEF_BITS as i32 - 1 + det_bits as i32 - (64 - big.leading_zeros()) as i32 - extra;
            if q0 < 0 {
                return UvLight {
                    a: [0; 4],
                    b: [0; 4],
                    q: [0; 4],
                    c: [light[0][0], light[0][1]],
                    ..out
                };
            }
            let q = (q0 + 1).min(30) as u32;
            // |n| 2^e / |det|, rounded: |n| 2^e (2^62 / |det|) / 2^62.
            let magnitude = |num: i64, e: u32| {
                let scaled = u128::from(num.unsigned_abs() << e) * u128::from(inv);
                ((scaled + (1 << 61)) >> 62) as u64
            };
            let (mut ma, mut mb) = (magnitude(na, q + (pu - su)), magnitude(nb, q + (pv - sv)));
            let mut q = q;
            if ma.max(mb) >= 1 << COEF_BITS {
                (ma, mb, q) = ((ma + 1) >> 1, (mb + 1) >> 1, q - 1);
            }
            // An absolute coordinate adds its vertex-0 value times 2^q: q is capped so that
            // every value of the triangle times 2^q fits i32 (the sum wraps on the way).
            if c < ABSOLUTE {
                let mag = i64::from(x0)
                    .unsigned_abs()
                    .max(i64::from(x1).unsigned_abs())
                    .max(i64::from(x2).unsigned_abs());
                let cap = 30u32.saturating_sub(64 - mag.leading_zeros());
                if q > cap {
                    let k = q - cap;
                    (ma, mb, q) = ((ma + (1 << (k - 1))) >> k, (mb + (1 << (k - 1))) >> k, cap);
                }
                if let Some(cc) = out.c.get_mut(c) {
                    *cc = (i64::from(x0) << q) as i32;
                }
            }
            let signed = |m: u64, num: i64| {
                let m = m.min(1 << COEF_BITS) as i32;
                if (num < 0) != (det < 0) {
                    -m
                } else {
                    m
                }
            };
            if let (Some(a), Some(b), Some(qc)) =
                (out.a.get_mut(c), out.b.get_mut(c), out.q.get_mut(c))
            {
                *a = signed(ma, na);
                *b = signed(mb, nb);
                *qc = q as u8;
            }
        }
        out
    }

    /// The light coordinates of a fragment with texture coordinates `u, v` (the fragment's
    /// values): the first [`ABSOLUTE`] as they are, the others as differences from vertex 0;
    /// the first `n` are computed, the others 0.
    #[inline(always)]
    pub fn at(&self, u: i32, v: i32, n: usize) -> [i32; 4] {
        let du = u.wrapping_sub(self.origin[0]) >> self.p[0];
        let dv = v.wrapping_sub(self.origin[1]) >> self.p[1];
        core::array::from_fn(|c| {
            if c < n {
                let sum = self.a[c]
                    .wrapping_mul(du)
                    .wrapping_add(self.b[c].wrapping_mul(dv));
                let sum = match self.c.get(c) {
                    Some(&base) => sum.wrapping_add(base),
                    None => sum,
                };
                sum >> self.q[c]
            } else {
                0
            }
        })
    }
}

#[cfg(test)]
mod tests {
    use super::{UvLight, ABSOLUTE};

    /// The exact affine map at `(u, v)` in f64.
    fn exact(uv: [[i32; 2]; 3], light: [[i32; 4]; 3], c: usize, u: f64, v: f64) -> f64 {
        let f = |i: usize, k: usize| f64::from(uv[i][k]);
        let (du1, dv1, du2, dv2) = (
            f(1, 0) - f(0, 0),
            f(1, 1) - f(0, 1),
            f(2, 0) - f(0, 0),
            f(2, 1) - f(0, 1),
        );
        let l1 = f64::from(light[1][c]) - f64::from(light[0][c]);
        let l2 = f64::from(light[2][c]) - f64::from(light[0][c]);
        let det = du1 * dv2 - du2 * dv1;
        let a = (l1 * dv2 - l2 * dv1) / det;
        let b = (du1 * l2 - du2 * l1) / det;
        a * (u - f(0, 0)) + b * (v - f(0, 1))
    }

    #[test]
    fn vertices_and_centre_map_to_their_light_coordinates() {
        // A floor-like triangle: 600 texels of a repeated texture over a whole map.
        let uv = [[0, 0], [600 << 16, 0], [0, 400 << 16]];
        let light = [
            [100 << 10, 200 << 10, 30_000 << 4, 0],
            [1000 << 10, 250 << 10, 50_000 << 4, 0],
            [120 << 10, 1020 << 10, 10_000 << 4, 0],
        ];
        let m = UvLight::solve(uv, 0, light, 3);
        for (u, v) in [
            (0, 0),
            (600 << 16, 0),
            (0, 400 << 16),
            (200 << 16, 133 << 16),
            (5, 7),
        ] {
            let got = m.at(u, v, 3);
            for c in 0..3 {
                let base = if c < ABSOLUTE {
                    f64::from(light[0][c])
                } else {
                    0.0
                };
                let want = exact(uv, light, c, f64::from(u), f64::from(v)) + base;
                let range = (0..3)
                    .map(|i| f64::from(light[i][c] - light[0][c]).abs())
                    .fold(1.0, f64::max);
                let err = (f64::from(got[c]) - want).abs();
                assert!(
                    err <= range / 8192.0 + 2.0,
                    "c={c} u={u} v={v} got={} want={want}",
                    got[c]
                );
            }
        }
    }

    #[test]
    fn a_shift_of_the_coordinates_is_undone() {
        let uv = [[10, 20], [90, 20], [10, 70]];
        let light = [[0, 0, 0, 0], [1 << 20, 0, 0, 0], [0, 1 << 19, 1 << 12, 0]];
        let m = UvLight::solve(uv, 3, light, 3);
        // The fragment sees the coordinates shifted left by 3.
        let got = m.at(90 << 3, 20 << 3, 3);
        assert!((got[0] - (1 << 20)).abs() <= 64, "{got:?}");
        assert!(got[1].abs() <= 64 && got[2].abs() <= 4, "{got:?}");
    }

    #[test]
    fn degenerate_texture_coordinates_give_vertex_zero() {
        let uv = [[0, 0], [100 << 16, 100 << 16], [200 << 16, 200 << 16]];
        let light = [[5, 6, 7, 8], [500, 600, 700, 800], [9, 9, 9, 9]];
        let m = UvLight::solve(uv, 0, light, 4);
        // The absolute coordinates are vertex 0's, the others differences of 0.
        assert_eq!(m.at(123 << 16, 7 << 16, 4), [5, 6, 0, 0]);
    }

    #[test]
    fn extreme_inputs_never_panic() {
        let e = [i32::MIN, -1, 0, 1, i32::MAX];
        for &a in &e {
            for &b in &e {
                let uv = [[a, b], [b, a], [0, a]];
                let light = [[a; 4], [b; 4], [0; 4]];
                for shift in [0, 5, 31] {
                    let m = UvLight::solve(uv, shift, light, 4);
                    let _ = m.at(a, b, 4);
                }
            }
        }
    }
}
