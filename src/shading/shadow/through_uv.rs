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
//! `u - u0` and `v - v0` (I16F16 texel units, as the fragment has them) are shifted right by
//! `p`, the smallest shift that brings the triangle's largest vertex difference below
//! `2^15`; the coefficients are `a 2^q` rounded to `i32` with `q` (per light coordinate, at
//! most 30) the largest, to a bit, that keeps both below `2^15`, so each product and their
//! sum fit `i32`. Inside the triangle the result differs from the exact affine map by at
//! most `2^-13` of the triangle's largest light-coordinate difference from vertex 0, plus 2
//! units (tested): for a triangle that spans a whole 64 x 64 map, 1/128 texel, and 8 depth
//! steps over the whole depth range, far inside the bias such a sloped receiver gets. Beyond
//! that the fragment's `u, v` carry the span loop's own interpolation error, as the light
//! varyings would.
//!
//! A triangle whose texture coordinates have no area at this precision (`det = 0`), or
//! whose slope does not fit (`q < 0`), takes its first vertex's light coordinates for every
//! pixel.

use crate::math::div_u64;

/// The per-triangle map from a fragment's `(u, v)` to its light coordinates (differences
/// from vertex 0, in the light's formats).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct UvLight {
    /// Vertex 0's `u, v` in the fragment's units (I16F16 texels, wrapping).
    pub(super) origin: [i32; 2],
    /// Right shift of `u - u0`, `v - v0`.
    pub(super) p: u8,
    /// Per light coordinate: right shift of the sum.
    pub(super) q: [u8; 4],
    /// Per light coordinate: `a 2^q` (below `2^15`).
    pub(super) a: [i32; 4],
    /// Per light coordinate: `b 2^q`.
    pub(super) b: [i32; 4],
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
        let largest = du1
            .unsigned_abs()
            .max(dv1.unsigned_abs())
            .max(du2.unsigned_abs())
            .max(dv2.unsigned_abs());
        let p = (64 - largest.leading_zeros()).saturating_sub(15).min(31);
        let r = |d: i64| d >> p.min(63);
        let (u1, v1, u2, v2) = (r(du1), r(dv1), r(du2), r(dv2));
        let det = u1 * v2 - u2 * v1;
        let mut out = UvLight {
            origin,
            p: p as u8,
            ..UvLight::default()
        };
        if det == 0 {
            return out;
        }
        // One division per triangle: 2^62 / |det| (at least 2^31, as |det| < 2^31).
        let det_abs = det.unsigned_abs();
        let inv = div_u64(1 << 62, det_abs);
        let det_bits = 64 - det_abs.leading_zeros();
        let [l0, l1s, l2s] = light;
        for (c, ((&x0, &x1), &x2)) in l0.iter().zip(&l1s).zip(&l2s).enumerate().take(n) {
            let l1 = i64::from(x1) - i64::from(x0);
            let l2 = i64::from(x2) - i64::from(x0);
            // Below 2^33 x 2^15 x 2: no overflow.
            let na = l1 * v2 - l2 * v1;
            let nb = u1 * l2 - u2 * l1;
            let big = na.unsigned_abs().max(nb.unsigned_abs());
            // A q with |n| 2^q < 2^14 |det| (so the coefficient is below 2^15, and
            // |n| 2^q below 2^45), at most 30.
            let q = (14 + det_bits as i32 - (64 - big.leading_zeros()) as i32).min(30);
            if q < 0 {
                return UvLight {
                    a: [0; 4],
                    b: [0; 4],
                    ..out
                };
            }
            // n 2^q / det, rounded: (|n| 2^q) (2^62 / |det|) / 2^62.
            let coef = |num: i64| {
                let m = ((u128::from(num.unsigned_abs() << q) * u128::from(inv) + (1 << 61)) >> 62)
                    as i64;
                let m = m.min(1 << 15);
                if (num < 0) != (det < 0) {
                    -m as i32
                } else {
                    m as i32
                }
            };
            if let (Some(a), Some(b), Some(qc)) =
                (out.a.get_mut(c), out.b.get_mut(c), out.q.get_mut(c))
            {
                *a = coef(na);
                *b = coef(nb);
                *qc = q as u8;
            }
        }
        out
    }

    /// The light coordinates (differences from vertex 0) of a fragment with texture
    /// coordinates `u, v` (the fragment's values); the first `n` are computed, the others 0.
    #[inline(always)]
    pub fn at(&self, u: i32, v: i32, n: usize) -> [i32; 4] {
        let du = u.wrapping_sub(self.origin[0]) >> self.p;
        let dv = v.wrapping_sub(self.origin[1]) >> self.p;
        core::array::from_fn(|c| {
            if c < n {
                self.a[c]
                    .wrapping_mul(du)
                    .wrapping_add(self.b[c].wrapping_mul(dv))
                    >> self.q[c]
            } else {
                0
            }
        })
    }
}

#[cfg(test)]
mod tests {
    use super::UvLight;

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
                let want = exact(uv, light, c, f64::from(u), f64::from(v));
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
        assert_eq!(m.at(123 << 16, 7 << 16, 4), [0; 4]);
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
