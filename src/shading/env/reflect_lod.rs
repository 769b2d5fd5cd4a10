//! GL's cube-map level of detail of a reflection computed per pixel from interpolated `n`
//! and `v` ([`reflection_lambda`]): the span loop's `lambda` for
//! [`ReflectPerPixelMip`](super::ReflectPerPixelMip) ([`Shader::LOD_REFLECTION`]).
//!
//! The shader reflects with `r = 2 (n·v) n − (n·n) v` (see [`reflect`](super::reflect)).
//! With `N`, `V` the perspective numerators of `n` and `v` (`n q`, `v q`, which are linear
//! in screen space; an affine draw's `n` and `v` themselves), `R = 2 (N·V) N − (N·N) V`
//! is `q³ r`: the same direction, so the same face coordinates `(sc / ma, tc / ma)`, and a
//! polynomial in quantities whose screen derivatives are the set-up's constant steps
//! `N'`, `V'`. Its derivative along x (and likewise y) is therefore exact:
//!
//! ```text
//! R' = 2 (N'·V + N·V') N + 2 (N·V) N' − 2 (N·N') V − (N·N) V'
//! ```
//!
//! and [`direction_lambda`] of `R`, `R'_x`, `R'_y` is GL's `lambda` of the reflection at the
//! pixel, whatever angle the reflections of a triangle span: no per-triangle projection onto
//! one face plane, no fall to the coarsest level.
//!
//! # Fixed point
//!
//! `N` and `V` are each shifted so their largest component magnitude is in
//! `[2^11, 2^12)` (one shift per vector: `R`'s direction is kept, since it is of degree 2
//! in `n` and 1 in `v`). The four derivative vectors take the shifts of their vectors plus
//! one common extra left shift `k` that brings the largest of them to the same range (a
//! derivative per pixel is far smaller than its value), so `R'` is `2^k` times the scale
//! of `R` and `k` levels are taken off the result. Per pixel, with every component below
//! `2^12`: the dot products are below `2^27`, shifted right by 11 (`2 (a·b) / 2^12`) they
//! are below `2^16`, and every component of `R` and `R'` is a sum of four products below
//! `2^28`: all `i32`, no 64-bit product. Eleven-bit dot products make `lambda` within
//! about 1/50 of a level of the f64 value at the benchmark scales (see the tests and
//! `host-tests`).
//!
//! # Cost
//!
//! Per pixel: four normalising shifts, 34 multiplies, then [`direction_lambda`] (two
//! 3-component cross terms, three `log2` lookups). Per span ([`Lod::granularity`]) the
//! cost is one of these per span.
//!
//! [`Shader::LOD_REFLECTION`]: crate::shading::Shader::LOD_REFLECTION
//! [`Lod::granularity`]: crate::texture::Lod

use crate::texture::direction_lambda;

/// Bits of the components the products use (`< 2^12`).
const BITS: i32 = 12;

/// Significant bits of the largest magnitude of `a` (0 when all are zero).
#[inline(always)]
fn bits(a: &[i32]) -> i32 {
    let m = a.iter().fold(0u32, |m, c| m | c.unsigned_abs());
    32 - m.leading_zeros() as i32
}

/// `c` shifted right by `s` (left when `s` is negative), the count clamped to `-31..=31`
/// (callers keep left shifts within range: see the module docs).
#[inline(always)]
fn shift(c: i32, s: i32) -> i32 {
    if s >= 0 {
        c >> s.min(31)
    } else {
        c.wrapping_shl((-s).min(31) as u32)
    }
}

#[inline(always)]
fn dot(a: [i32; 3], b: [i32; 3]) -> i32 {
    a[0].wrapping_mul(b[0])
        .wrapping_add(a[1].wrapping_mul(b[1]))
        .wrapping_add(a[2].wrapping_mul(b[2]))
}

/// GL's cube-map `lambda` (Q8.8, units of half a face, as [`direction_lambda`]) of the
/// reflection `r = 2 (n·v) n − (n·n) v` at one pixel: `n`, `v` the normal and eye vector
/// there (any scale each; for a perspective draw, the numerators `n q`, `v q`), `ndx`,
/// `vdx` their change per pixel right and `ndy`, `vdy` down (the same scales). A zero `n`
/// or `v` gives 0; no change at all gives `i32::MIN / 4` (magnification). Never panics.
#[inline(always)]
pub fn reflection_lambda(
    n: [i32; 3],
    v: [i32; 3],
    [ndx, vdx]: [[i32; 3]; 2],
    [ndy, vdy]: [[i32; 3]; 2],
) -> i32 {
    let (bn, bv) = (bits(&n), bits(&v));
    if bn == 0 || bv == 0 {
        return 0;
    }
    let (sn, sv) = (bn - BITS, bv - BITS);
    // The derivatives' sizes in units of their vectors' shifted scales.
    let en = bits(&[ndx[0], ndx[1], ndx[2], ndy[0], ndy[1], ndy[2]]);
    let ev = bits(&[vdx[0], vdx[1], vdx[2], vdy[0], vdy[1], vdy[2]]);
    let e = match (en, ev) {
        (0, 0) => return i32::MIN / 4,
        (0, _) => ev - sv,
        (_, 0) => en - sn,
        _ => (en - sn).max(ev - sv),
    };
    // The extra scale of the derivatives: the larger group reaches 12 bits (left shifts
    // of at most 11, see the module docs).
    let k = BITS - e;
    let n = n.map(|c| shift(c, sn));
    let v = v.map(|c| shift(c, sv));
    let nv = dot(n, v) >> (BITS - 1);
    let nn = dot(n, n) >> BITS;
    let r: [i32; 3] =
        core::array::from_fn(|i| nv.wrapping_mul(n[i]).wrapping_sub(nn.wrapping_mul(v[i])));
    let deriv = |nd: [i32; 3], vd: [i32; 3]| -> [i32; 3] {
        let nd = nd.map(|c| shift(c, sn - k));
        let vd = vd.map(|c| shift(c, sv - k));
        let a = dot(nd, v).wrapping_add(dot(n, vd)) >> (BITS - 1);
        let b = dot(n, nd) >> (BITS - 1);
        core::array::from_fn(|i| {
            a.wrapping_mul(n[i])
                .wrapping_add(nv.wrapping_mul(nd[i]))
                .wrapping_sub(b.wrapping_mul(v[i]))
                .wrapping_sub(nn.wrapping_mul(vd[i]))
        })
    };
    let (rx, ry) = (deriv(ndx, vdx), deriv(ndy, vdy));
    direction_lambda(r, rx, ry).saturating_sub(k.saturating_mul(256))
}

#[cfg(test)]
mod tests {
    extern crate std;
    use super::*;
    use crate::test_rng::Rng;

    /// GL's lambda of the reflection in f64: `r` and its derivatives by the product rule.
    fn reference(n: [f64; 3], v: [f64; 3], d: [[f64; 3]; 4]) -> f64 {
        let dot = |a: [f64; 3], b: [f64; 3]| a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
        let r: [f64; 3] = core::array::from_fn(|i| 2.0 * dot(n, v) * n[i] - dot(n, n) * v[i]);
        let rd = |nd: [f64; 3], vd: [f64; 3]| -> [f64; 3] {
            core::array::from_fn(|i| {
                2.0 * (dot(nd, v) + dot(n, vd)) * n[i] + 2.0 * dot(n, v) * nd[i]
                    - 2.0 * dot(n, nd) * v[i]
                    - dot(n, n) * vd[i]
            })
        };
        let (gx, gy) = (rd(d[0], d[1]), rd(d[2], d[3]));
        let [ax, ay, az] = r.map(f64::abs);
        let (m, i, j) = if ax >= ay && ax >= az {
            (0, 1, 2)
        } else if ay >= az {
            (1, 0, 2)
        } else {
            (2, 0, 1)
        };
        let rho = |g: [f64; 3]| {
            let q = |c: usize| (g[c] * r[m] - r[c] * g[m]) / (r[m] * r[m]);
            q(i).hypot(q(j))
        };
        rho(gx).max(rho(gy)).log2()
    }

    /// Three components of at most `bits` significant bits (signed).
    fn vec3(rng: &mut Rng, bits: u32) -> [i32; 3] {
        [0; 3].map(|_| (rng.next() as i32) >> (32 - bits))
    }

    #[test]
    fn matches_f64_over_scales() {
        let mut rng = Rng(0x5EED_0F1E_C7AB);
        let f = |a: [i32; 3]| a.map(f64::from);
        let dot = |a: [f64; 3], b: [f64; 3]| a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
        let (mut worst, mut tested) = (0f64, 0);
        for _ in 0..50_000 {
            let (sn, sv) = (8 + rng.next() as u32 % 23, 8 + rng.next() as u32 % 23);
            let (sdn, sdv) = (1 + rng.next() as u32 % 20, 1 + rng.next() as u32 % 20);
            let (n, v) = (vec3(&mut rng, sn), vec3(&mut rng, sv));
            let (ndx, ndy) = (vec3(&mut rng, sdn.min(sn)), vec3(&mut rng, sdn.min(sn)));
            let (vdx, vdy) = (vec3(&mut rng, sdv.min(sv)), vec3(&mut rng, sdv.min(sv)));
            let want = reference(f(n), f(v), [f(ndx), f(vdx), f(ndy), f(vdy)]);
            // The cases the fixed point is meant for: a reflection not near zero (|r| at
            // least 1/16 of |n|^2 |v|) and a derivative of r's face coordinates not far
            // below those of n and v (no cancellation below the 11-bit products).
            let (nn, vv) = (dot(f(n), f(n)), dot(f(v), f(v)).sqrt());
            let nv = dot(f(n), f(v));
            let r: [f64; 3] = core::array::from_fn(|i| 2.0 * nv * f(n)[i] - nn * f(v)[i]);
            let rel = |a: [i32; 3], b: [i32; 3], len: f64| {
                dot(f(a), f(a)).max(dot(f(b), f(b))).sqrt() / len
            };
            let moving = rel(ndx, ndy, nn.sqrt()).max(rel(vdx, vdy, vv));
            // Nor on a face edge, where GL's lambda jumps between the two faces' values.
            let mut a = r.map(f64::abs);
            a.sort_by(f64::total_cmp);
            let edge = a[1] > a[2] * 0.99;
            if edge
                || dot(r, r).sqrt() < nn * vv / 16.0
                || !want.is_finite()
                || want < moving.log2() - 3.0
            {
                continue;
            }
            let got = f64::from(reflection_lambda(n, v, [ndx, vdx], [ndy, vdy])) / 256.0;
            worst = worst.max((got - want).abs());
            tested += 1;
            assert!(
                (got - want).abs() <= 0.1,
                "n {n:?} v {v:?} d {:?}: {got} vs {want}",
                [ndx, vdx, ndy, vdy]
            );
        }
        std::println!("{tested} cases, worst {worst:.4} levels");
        assert!(tested > 10_000, "{tested}");
    }

    #[test]
    fn degenerate_inputs() {
        let one = [1 << 20, 0, 0];
        assert_eq!(reflection_lambda([0; 3], one, [one; 2], [one; 2]), 0);
        assert_eq!(reflection_lambda(one, [0; 3], [one; 2], [one; 2]), 0);
        assert_eq!(
            reflection_lambda(one, [0, 1 << 20, 0], [[0; 3]; 2], [[0; 3]; 2]),
            i32::MIN / 4
        );
        let ext = [i32::MIN, i32::MAX, -1];
        for a in [ext, one, [1, 0, 0], [0; 3]] {
            for b in [ext, one, [0, 1, 0]] {
                let _ = reflection_lambda(a, b, [a, b], [b, a]);
                let _ = reflection_lambda(a, b, [ext, ext], [[0; 3], ext]);
            }
        }
    }
}
