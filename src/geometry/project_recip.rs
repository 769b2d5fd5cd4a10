//! The perspective divide of [`Viewport::project`] without a divide instruction
//! (Cortex-M0+): one reciprocal of `w` per vertex ([`Recip32`]) serves its three quotients
//! (`x`, `y` and depth) and the two sub-pixel offsets, instead of two 32-bit library
//! divisions (~120 instructions each), a 64-by-32-bit division with its own reciprocal and
//! two bit-by-bit offset loops. Cores with a divide instruction keep one division per
//! quotient: there the reciprocal for depth and the set-up alone would save about 1.5 % of
//! the Cortex-M4F whole sphere and this whole form about 2.5 %, but they link about 0.4
//! and 0.9 KB more into the minimal firmware and 1.0 and 1.5 KB more into the perspective
//! one (measure with `cargo xtask mcu` and `cargo xtask size`).
//!
//! Every quotient is the exact floor (or the exact rounding, for depth): the screen
//! vertices are bit-identical on every core and equal to the plain division's (tested
//! against it over random and edge inputs, in the tests below).

use super::viewport::{mul_i32_i64, Viewport, HALF_OFFSET, LIM, OFFSET_BITS};
use crate::math::recip32::Recip32;

impl Viewport {
    /// [`Viewport::project_xy`] given the reciprocal of `w`.
    #[inline(always)]
    pub(crate) fn project_xy_recip(&self, x: i32, y: i32, r: &Recip32) -> (i32, i32, [i16; 2]) {
        let rect = self.rect();
        // In 1/16 pixel, below 2^15 (viewport sides are at most 2^11 pixels).
        let (hw, hh) = ((rect.x1 - rect.x0) * 8, (rect.y1 - rect.y0) * 8);
        let (cx, cy) = (rect.x0 * 16 + hw, rect.y0 * 16 + hh);
        // The common case in 32 bits: `|2 x hw| <= 2^30` and `w < 2^30`, so `2 x hw + w`
        // fits `i32` (one `muls` on Cortex-M0+ instead of a 16-bit-split 64-bit product).
        // `|x| h <= (|x| / 16 + 1) 16 h`, a product below 2^31, with no division.
        let fits = |v: i32, h: i32| {
            let v = v.unsigned_abs();
            v < 1 << 20 && ((v >> 4) + 1) * h as u32 <= 1 << 25
        };
        let w = r.divisor();
        if w < 1 << 30 && fits(x, hw) && fits(y, hh) {
            let (sx, ox) = axis(i64::from(2 * x * hw + w as i32), i64::from(cx), r);
            let (sy, oy) = axis(i64::from(w as i32 - 2 * y * hh), i64::from(cy), r);
            return (sx, sy, [ox, oy]);
        }
        let (hw, hh, cx, cy) = self.scales();
        let num = |n: i64| n.wrapping_mul(2).wrapping_add(i64::from(w));
        let (sx, ox) = axis(num(mul_i32_i64(x, hw)), cx, r);
        let (sy, oy) = axis(num(-mul_i32_i64(y, hh)), cy, r);
        (sx, sy, [ox, oy])
    }
}

/// One axis, given `num = 2n + w` (`|n| < 2^46`): `s = floor(num / 2w)` (the window
/// position in 1/16 pixel, ties towards +x and +y), its remainder `rem = num - 2w s` in
/// `0..2w`, and the sub-pixel offset `floor((2^R rem + w) / 2w) - 2^(R-1)`; a position
/// beyond the guard band is clamped to it with no offset (only vertices the clipper will
/// cut). Quotients by `2w` are those by `w` halved: `floor(floor(t / w) / 2) =
/// floor(t / 2w)`, with remainder `t mod w` plus `w` when the quotient by `w` is odd.
///
/// Out of line: one copy serves both axes and both forms of the numerator (inlined, the
/// four copies cost about 2 KB of flash).
#[inline(never)]
fn axis(num: i64, c: i64, r: &Recip32) -> (i32, i16) {
    let w = r.divisor();
    let by_2w = |m: u64| {
        let (q, rw) = div_rem(r, m)?;
        // rw < w and w < 2^31: the remainder by 2w fits u32.
        Some((q >> 1, rw + (q & 1) * w))
    };
    let (s, rem) = if num >= 0 {
        match by_2w(num as u64) {
            Some((q, rem)) => (i64::from(q), rem),
            // A quotient of 2^32 or more: far past the guard band.
            None => return (LIM as i32, 0),
        }
    } else {
        // -m = 2w (-q) - rem: one less and the complement unless rem is 0.
        match by_2w(num.unsigned_abs()) {
            Some((q, 0)) => (-i64::from(q), 0),
            Some((q, rem)) => (-i64::from(q) - 1, 2 * w - rem),
            None => return (-LIM as i32, 0),
        }
    };
    let s = c + s;
    if s.abs() > LIM {
        return (s.clamp(-LIM, LIM) as i32, 0);
    }
    // 2^R rem + w < (2^(R+1) + 1) w: a quotient below 2^(R+1) + 1, which fits.
    let (q, _) = div_rem(r, (u64::from(rem) << OFFSET_BITS) + u64::from(w)).unwrap_or((0, 0));
    let off = i64::from(q >> 1) - (1 << (OFFSET_BITS - 1));
    (s as i32, off.clamp(-HALF_OFFSET, HALF_OFFSET) as i16)
}

/// `(m / w, m % w)` by the reciprocal: the 32-bit form when `m` fits it, else the wide one
/// (`None` when the quotient does not fit 32 bits).
#[inline(always)]
fn div_rem(r: &Recip32, m: u64) -> Option<(u32, u32)> {
    if let Ok(m) = u32::try_from(m) {
        return Some(r.div_rem(m));
    }
    let q = r.div_wide(m)?;
    // The remainder is below w < 2^32: exact modulo 2^32.
    Some((q, (m as u32).wrapping_sub(q.wrapping_mul(r.divisor()))))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::viewport::{depth_recip, DEPTH_K};
    use crate::math::{div_floor_i64, div_round_i64};
    use crate::test_rng::Rng;

    /// The plain division form of [`Viewport::project`] (the one the cores with a divide
    /// instruction use): the reference the reciprocal form must equal.
    fn project_div(vp: &Viewport, x: i32, y: i32, z: i32, w: i32) -> (i32, i32, [i16; 2], i32) {
        let w = i64::from(w.max(1));
        let (hw, hh, cx, cy) = vp.scales();
        let axis = |n: i64, c: i64| -> (i32, i16) {
            let num = 2 * n + w;
            let s = div_floor_i64(num, 2 * w);
            let r = num - s * 2 * w;
            let off = div_floor_i64(((r - w) << OFFSET_BITS) + w, 2 * w);
            let s = c + s;
            if s.abs() > LIM {
                return (s.clamp(-LIM, LIM) as i32, 0);
            }
            (s as i32, off.clamp(-HALF_OFFSET, HALF_OFFSET) as i16)
        };
        let (sx, ox) = axis(i64::from(x) * hw, cx);
        let (sy, oy) = axis(-i64::from(y) * hh, cy);
        let d = (div_round_i64(i64::from(z) * DEPTH_K, w) + DEPTH_K).clamp(0, 65535 << 14);
        (sx, sy, [ox, oy], d as i32)
    }

    /// The reciprocal form gives the division's screen vertex, for random and edge inputs
    /// on four viewports (clip coordinates near the view, and anywhere).
    #[test]
    fn reciprocal_projection_equals_the_division() {
        let mut rng = Rng(0xC0FF_EE00_1234_5678);
        let vps = [
            Viewport::new(0, 0, 320, 240).unwrap(),
            Viewport::new(7, 3, 64, 64).unwrap(),
            Viewport::new(0, 0, 2048, 2048).unwrap(),
            Viewport::new(100, 50, 1, 1).unwrap(),
        ];
        let edges = [
            0,
            1,
            -1,
            i32::MAX,
            i32::MIN,
            1 << 28,
            -(1 << 28),
            65536,
            -65536,
        ];
        for i in 0..400_000u32 {
            let vp = &vps[i as usize % vps.len()];
            let wbits = (rng.next() % 33) as u32;
            let w = if wbits == 32 {
                edges[(rng.next() % 9) as usize]
            } else {
                (rng.next() as u32 >> (32 - wbits.max(1))) as i32
            };
            let mut c = || match rng.next() % 8 {
                0 => rng.next() as i32,
                1 => edges[(rng.next() % 9) as usize],
                _ => {
                    let f = (rng.next() as i64 >> 40) as i32; // +-2^23
                    ((i64::from(w.max(1)) * i64::from(f)) >> 22) as i32
                }
            };
            let (x, y, z) = (c(), c(), c());
            let want = project_div(vp, x, y, z, w);
            assert_eq!(vp.project(x, y, z, w), want, "{x} {y} {z} {w}");
            let r = Recip32::at_least_one(w);
            let xy = (want.0, want.1, want.2);
            assert_eq!(vp.project_xy_recip(x, y, &r), xy, "{x} {y} {w}");
            assert_eq!(depth_recip(z, &r), want.3, "{z} {w}");
            assert_eq!(vp.project_xy_div(x, y, w), xy, "{x} {y} {w}");
        }
    }

    /// Ties and exact multiples, where the remainder is 0 or `w`.
    #[test]
    fn reciprocal_projection_on_ties() {
        let vp = Viewport::new(0, 0, 64, 64).unwrap();
        for w in [
            1,
            2,
            3,
            255,
            256,
            65536,
            65537,
            (1 << 23) - 1,
            (1 << 28) + 3,
        ] {
            for k in -3000..3000 {
                let x = (i64::from(k) * i64::from(w) / 1024) as i32;
                let want = project_div(&vp, x, -x, x, w);
                assert_eq!(vp.project(x, -x, x, w), want, "{x} {w}");
                let r = Recip32::at_least_one(w);
                assert_eq!(vp.project_xy_recip(x, -x, &r), (want.0, want.1, want.2));
                assert_eq!(depth_recip(x, &r), want.3);
            }
        }
    }
}
