//! Plane equations for interpolating a vertex attribute linearly in screen space.
//!
//! An attribute with values `a0, a1, a2` at the three screen vertices is the plane
//! `a(x, y) = a_ref + (px - px_ref) dadx + (py - py_ref) dady` over pixel centres. The
//! pipeline evaluates it once per span start (two multiplies) and steps `dadx` per pixel.
//!
//! # Arithmetic and error budget
//! * Inputs: attribute values `|a| < 2^31` (any fixed-point format: the plane does not care),
//!   vertex positions in 1/256 pixel ([`ATTR_SUBPIXEL_BITS`], the unsnapped projections:
//!   attributes are not moved by the 1/16-pixel snapping of coverage) inside the guard band
//!   (`|x|, |y| <= 2^20`), so vertex differences are `< 2^21`, the doubled area `< 2^43` and
//!   the numerators `Δa·Δy` `< 2^54`.
//! * Gradients are computed once per triangle with 8 extra fraction bits
//!   (`(num << 16) / area2`; when that shift would overflow, as quotient and remainder) and
//!   the reference value at a pixel centre is taken from that high-precision gradient, so it
//!   is within one unit of the exact value wherever the reference lies.
//! * The reference pixel is vertex 0's pixel clamped into the *viewport* (never a band), so
//!   a frame drawn in bands evaluates exactly the same integers as one drawn whole.
//! * Per-pixel values use `i32` **wrapping** arithmetic on purpose: set-up is exact modulo
//!   2^32, so wherever the true value fits `i32` (at every covered pixel centre, which is a
//!   convex combination of the vertex values) the wrapped sum is that value, even when the
//!   reference lies far outside the triangle. Rounding of `dadx`/`dady` adds at most half a
//!   unit per pixel of distance from the reference: at most `(width + height) / 2` units
//!   across the viewport.

use super::{Rect, ATTR_SUBPIXEL_BITS};
use crate::math::Divisor32;

/// Extra fraction bits of the set-up gradient.
const EXTRA: u32 = 8;

/// Shared, per-triangle part of plane set-up: vertex deltas and the reference pixel.
#[derive(Clone, Copy, Debug)]
pub struct PlaneSetup {
    dx1: i64,
    dy1: i64,
    dx2: i64,
    dy2: i64,
    area2: i64,
    /// `area2 >> norm`, below 2^32 in magnitude: the gradients' divisor, so that their
    /// divisions take the 64-by-32-bit path (exact for `norm == 0`, relative error below
    /// 2^-31 otherwise: far under one unit of any gradient that fits `i32`).
    area_n: i64,
    norm: u32,
    /// Offset of the reference pixel centre from vertex 0, 1/256 pixel.
    ref_dx: i64,
    ref_dy: i64,
    /// `|area_n|` as a reciprocal: every gradient divides by it.
    recip: Divisor32,
    /// `|area_n| / 2`, the rounding term of every gradient.
    half_d: u64,
    /// The common gradient path (`norm <= SHIFT`): the numerator's shift `SHIFT - norm`,
    /// and the magnitude below which the shifted numerator fits `i64` (`0` when
    /// `norm > SHIFT`, which sends every gradient down the general path).
    k: u32,
    fast_below: u64,
    /// Reference pixel.
    pub px_ref: i32,
    /// Reference row.
    pub py_ref: i32,
}

impl PlaneSetup {
    /// Prepares plane set-up for the triangle `v` (1/256-pixel units, [`ATTR_SUBPIXEL_BITS`],
    /// guard band) whose doubled signed area is non-zero; the reference pixel is clamped into
    /// `viewport`. Returns `None` for zero area.
    pub fn new(v: [(i32, i32); 3], viewport: Rect) -> Option<Self> {
        let (x0, y0) = (i64::from(v[0].0), i64::from(v[0].1));
        let dx1 = i64::from(v[1].0) - x0;
        let dy1 = i64::from(v[1].1) - y0;
        let dx2 = i64::from(v[2].0) - x0;
        let dy2 = i64::from(v[2].1) - y0;
        let area2 = dx1 * dy2 - dx2 * dy1;
        if area2 == 0 {
            return None;
        }
        let px_ref =
            (v[0].0 >> ATTR_SUBPIXEL_BITS).clamp(viewport.x0, (viewport.x1 - 1).max(viewport.x0));
        let py_ref =
            (v[0].1 >> ATTR_SUBPIXEL_BITS).clamp(viewport.y0, (viewport.y1 - 1).max(viewport.y0));
        let one = 1i64 << ATTR_SUBPIXEL_BITS;
        let half = one / 2;
        let norm = (64 - area2.unsigned_abs().leading_zeros()).saturating_sub(31);
        let area_n = area2 >> norm;
        const SHIFT: u32 = ATTR_SUBPIXEL_BITS + EXTRA;
        let k = SHIFT.saturating_sub(norm);
        Some(PlaneSetup {
            half_d: area_n.unsigned_abs() / 2,
            k,
            fast_below: if norm > SHIFT { 0 } else { 1 << (62 - k) },
            dx1,
            dy1,
            dx2,
            dy2,
            area2,
            area_n,
            norm,
            ref_dx: i64::from(px_ref) * one + half - x0,
            ref_dy: i64::from(py_ref) * one + half - y0,
            recip: Divisor32::new(area_n.unsigned_abs())?,
            px_ref,
            py_ref,
        })
    }

    /// Doubled signed area in 1/256-pixel units squared (positive: clockwise on a y-down
    /// screen).
    pub fn area2(&self) -> i64 {
        self.area2
    }

    /// `n / area_n` rounded to nearest, ties away from zero (as [`div_round`]), through the
    /// reciprocal when the area is small.
    #[inline]
    fn div_round(&self, n: i64) -> i64 {
        let d = self.area_n.unsigned_abs();
        let q = self.recip.div(n.unsigned_abs().wrapping_add(d / 2)) as i64;
        if (n < 0) == (self.area_n < 0) {
            q
        } else {
            q.wrapping_neg()
        }
    }

    /// `n 2^SHIFT / area2` rounded (ties away from zero), `SHIFT = ATTR_SUBPIXEL_BITS +
    /// EXTRA`, as `n 2^(SHIFT - norm) / area_n`: one division by a divisor below 2^32 when
    /// the shifted numerator fits `i64` (the common case), else a long division; for huge
    /// triangles (`norm > SHIFT`) the numerator is shifted right instead. Wraps modulo 2^64
    /// where the result does not fit.
    #[inline(always)]
    fn gradient(&self, n: i64) -> i64 {
        // The common case, with the shift, its bound and the rounding term precomputed
        // per triangle: the same arithmetic as `div_round(n << k)` in the general path.
        let m = n.unsigned_abs();
        if m < self.fast_below {
            let q = self.recip.div((m << self.k).wrapping_add(self.half_d)) as i64;
            if (n < 0) == (self.area_n < 0) {
                q
            } else {
                q.wrapping_neg()
            }
        } else {
            self.gradient_general(n)
        }
    }

    /// [`Self::gradient`] for any numerator (out of line: huge triangles and numerators).
    #[inline(never)]
    fn gradient_general(&self, n: i64) -> i64 {
        const SHIFT: u32 = ATTR_SUBPIXEL_BITS + EXTRA;
        if self.norm > SHIFT {
            let k = (self.norm - SHIFT).min(62);
            return self.div_round((n >> k) + ((n >> (k - 1)) & 1));
        }
        let k = SHIFT - self.norm;
        if n.unsigned_abs() < 1 << (62 - k) {
            return self.div_round(n << k);
        }
        long_div_round(n, self.area_n, k, |x| self.recip.div(x))
    }

    /// The plane through the attribute values `a` at the three vertices.
    pub fn plane(&self, a: [i32; 3]) -> Plane {
        let da1 = i64::from(a[1]) - i64::from(a[0]);
        let da2 = i64::from(a[2]) - i64::from(a[0]);
        // d a / d x and d a / d y in units per 1/256 pixel, times area2.
        let nx = mul(da1, self.dy2) - mul(da2, self.dy1);
        let ny = mul(da2, self.dx1) - mul(da1, self.dx2);
        // Per pixel (<< ATTR_SUBPIXEL_BITS) with EXTRA more fraction bits.
        let gx = self.gradient(nx);
        let gy = self.gradient(ny);
        // Value at the reference centre: a0 + (gx ref_dx + gy ref_dy) / 2^(EXTRA + ATTR_SUBPIXEL_BITS)
        // (gx is per pixel, ref_dx in 1/256 pixel).
        // Wrapping is exact modulo 2^64, hence modulo 2^32 after the shift.
        let off = mul(gx, self.ref_dx).wrapping_add(mul(gy, self.ref_dy));
        let round = 1i64 << (EXTRA + ATTR_SUBPIXEL_BITS - 1);
        let a_ref =
            i64::from(a[0]).wrapping_add(off.wrapping_add(round) >> (EXTRA + ATTR_SUBPIXEL_BITS));
        let half = 1i64 << (EXTRA - 1);
        Plane {
            at_ref: a_ref as i32,
            dx: (gx.wrapping_add(half) >> EXTRA) as i32,
            dy: (gy.wrapping_add(half) >> EXTRA) as i32,
        }
    }
}

/// `n 2^shift / d` rounded to nearest, ties away from zero (`d != 0`), by long division on
/// magnitudes: truncated quotients of `r 2^k / |d|` with every partial remainder
/// `r < |d|` and `r 2^k < 2^63`. The result wraps modulo 2^64 when it does not fit.
fn long_div_round(n: i64, d: i64, shift: u32, div_u64: impl Fn(u64) -> u64) -> i64 {
    let (nm, dm) = (n.unsigned_abs(), d.unsigned_abs());
    let step = 63u32.saturating_sub(64 - dm.leading_zeros()).max(1);
    let mut q = div_u64(nm);
    let mut r = nm - q.wrapping_mul(dm);
    let mut left = shift;
    while left > 0 {
        let k = left.min(step);
        let t = r << k;
        let qq = div_u64(t);
        r = t - qq * dm;
        q = q.wrapping_shl(k).wrapping_add(qq);
        left -= k;
    }
    if 2 * r >= dm {
        q = q.wrapping_add(1);
    }
    let q = q as i64;
    if (n < 0) == (d < 0) {
        q
    } else {
        q.wrapping_neg()
    }
}

/// `a * b` (wrapping), exactly. On ARMv6-M, where a 64-bit product is a library call
/// (`__aeabi_lmul`), the common case of `a` within `i32` and `b` within `i16` is two 32-bit
/// multiplies: with `a = ah 2^16 + al`, `a b = (ah b) 2^16 + al b`, both products in `i32`;
/// both within `i32`, four 16 x 16-bit products.
#[inline(always)]
fn mul(a: i64, b: i64) -> i64 {
    #[cfg(all(target_arch = "arm", not(target_has_atomic = "32")))]
    {
        mul_split(a, b)
    }
    #[cfg(not(all(target_arch = "arm", not(target_has_atomic = "32"))))]
    {
        a.wrapping_mul(b)
    }
}

/// The 32-bit-multiply form of [`mul`] (compiled everywhere so every target tests it).
#[cfg_attr(
    not(all(target_arch = "arm", not(target_has_atomic = "32"))),
    allow(dead_code)
)]
#[inline(always)]
fn mul_split(a: i64, b: i64) -> i64 {
    if a as i32 as i64 == a && b as i16 as i64 == b {
        let (a, b) = (a as i32, b as i32);
        let (ah, al) = (a >> 16, a & 0xFFFF);
        (i64::from(ah * b) << 16) + i64::from(al * b)
    } else if a as i32 as i64 == a && b as i32 as i64 == b {
        // Signed 32 x 32 -> 64 from the unsigned product of the magnitudes.
        let p = crate::math::div::mul_wide_split(a.unsigned_abs() as u32, b.unsigned_abs() as u32)
            as i64;
        if (a < 0) != (b < 0) {
            p.wrapping_neg()
        } else {
            p
        }
    } else {
        a.wrapping_mul(b)
    }
}

/// An attribute's screen-space plane, in the attribute's own fixed-point format.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Plane {
    /// Value at the reference pixel centre.
    pub at_ref: i32,
    /// Change per pixel to the right.
    pub dx: i32,
    /// Change per pixel down.
    pub dy: i32,
}

impl Plane {
    /// Value at the centre of pixel `(px, py)`, given the set-up's reference pixel.
    #[inline(always)]
    pub fn at(&self, setup_ref: (i32, i32), px: i32, py: i32) -> i32 {
        self.at_ref
            .wrapping_add(px.wrapping_sub(setup_ref.0).wrapping_mul(self.dx))
            .wrapping_add(py.wrapping_sub(setup_ref.1).wrapping_mul(self.dy))
    }
}

#[cfg(test)]
mod tests {
    extern crate std;
    use super::*;

    fn exact(v: [(i32, i32); 3], a: [i32; 3], px: i32, py: i32) -> f64 {
        let one = f64::from(1u32 << ATTR_SUBPIXEL_BITS);
        let f = |p: (i32, i32)| (p.0 as f64 / one, p.1 as f64 / one);
        let (p0, p1, p2) = (f(v[0]), f(v[1]), f(v[2]));
        let (x, y) = (px as f64 + 0.5, py as f64 + 0.5);
        let area = (p1.0 - p0.0) * (p2.1 - p0.1) - (p2.0 - p0.0) * (p1.1 - p0.1);
        let l1 = ((x - p0.0) * (p2.1 - p0.1) - (p2.0 - p0.0) * (y - p0.1)) / area;
        let l2 = ((p1.0 - p0.0) * (y - p0.1) - (x - p0.0) * (p1.1 - p0.1)) / area;
        a[0] as f64 + l1 * (a[1] as f64 - a[0] as f64) + l2 * (a[2] as f64 - a[0] as f64)
    }

    /// The per-triangle fast path of `gradient` is the general path's arithmetic with its
    /// shift and rounding precomputed: the same integers for every numerator.
    #[test]
    fn fast_gradient_equals_general_path() {
        let mut x = 0x9E37_79B9_7F4A_7C15u64;
        let vp = Rect {
            x0: 0,
            y0: 0,
            x1: 320,
            y1: 240,
        };
        for _ in 0..20_000 {
            let mut next = || {
                x ^= x << 13;
                x ^= x >> 7;
                x ^= x << 17;
                x
            };
            let scale = 8 + (next() % 13) as u32;
            let mut c = || ((next() as i64 >> 40) as i32) >> (32 - scale);
            let v = [(c(), c()), (c(), c()), (c(), c())];
            let Some(ps) = PlaneSetup::new(v, vp) else {
                continue;
            };
            for _ in 0..8 {
                let n = (next() as i64) >> (next() % 63);
                assert_eq!(ps.gradient(n), ps.gradient_general(n), "{v:?} {n}");
            }
        }
    }

    #[test]
    fn long_division_matches_wide_arithmetic() {
        let mut x = 0x2545_F491_4F6C_DD1Du64;
        for _ in 0..100_000 {
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
            let n = (x as i64) >> (x % 30);
            let d = ((x.rotate_left(17) as i64) >> (14 + x % 40)).max(1)
                * if x & 1 == 0 { 1 } else { -1 };
            for shift in [1, 12, 20, 28] {
                let wide = (i128::from(n) << shift) as f64 / d as f64;
                let exact = {
                    let (nn, dd) = (i128::from(n) << shift, i128::from(d));
                    let q = nn / dd;
                    let r = nn - q * dd;
                    let away = if (nn < 0) == (dd < 0) { 1 } else { -1 };
                    if 2 * r.abs() >= dd.abs() {
                        q + away
                    } else {
                        q
                    }
                };
                assert_eq!(
                    long_div_round(n, d, shift, |x| x / d.unsigned_abs()),
                    exact as i64,
                    "{n} << {shift} / {d} (~{wide})"
                );
            }
        }
    }

    #[test]
    fn split_multiply_is_exact() {
        let vals = [
            0i64,
            1,
            -1,
            32767,
            -32768,
            32768,
            -32769,
            i32::MAX as i64,
            i32::MIN as i64,
        ];
        for &a in vals.iter().chain(&[1 << 40, -(1 << 33) + 7]) {
            for &b in &vals {
                assert_eq!(mul_split(a, b), a.wrapping_mul(b), "{a} * {b}");
            }
        }
        let mut x = 0x2545_F491_4F6C_DD1Du64;
        for _ in 0..100_000 {
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
            let a = (x as i64) >> (x % 40);
            let b = ((x >> 20) as i64) >> (20 + (x >> 60));
            assert_eq!(mul_split(a, b), a.wrapping_mul(b), "{a} * {b}");
        }
    }

    #[test]
    fn plane_matches_exact_inside_the_viewport() {
        let vp = Rect::of_size(320, 240);
        type Case = ([(i32, i32); 3], [i32; 3]);
        let cases: [Case; 3] = [
            (
                [(100, 50), (3000, 400), (900, 3500)],
                [0, 1 << 20, -(1 << 22)],
            ),
            (
                [(-60000, -60000), (60000, -50000), (0, 60000)],
                [i32::MAX - 5, 0, i32::MIN + 5],
            ),
            (
                [(5000, 5000), (5003, 5001), (4999, 5300)],
                [123456, -99999, 7],
            ),
        ];
        for (v, a) in cases {
            // The cases are in 1/16 pixel: to the attribute grid.
            let k = 1 << (ATTR_SUBPIXEL_BITS - 4);
            let v = v.map(|(x, y)| (x * k, y * k));
            let s = PlaneSetup::new(v, vp).unwrap();
            let p = s.plane(a);
            for (px, py) in [(0, 0), (319, 0), (0, 239), (319, 239), (160, 120)] {
                let got = p.at((s.px_ref, s.py_ref), px, py) as f64;
                let want = exact(v, a, px, py);
                if want.abs() < 2f64.powi(31) {
                    assert!(
                        (got - want).abs() <= 300.0,
                        "{v:?} {a:?} ({px},{py}): {got} vs {want}"
                    );
                }
            }
        }
    }
}
