//! The viewport mapping without a divide instruction (Cortex-M0+): one reciprocal of `w`
//! per vertex ([`Recip32`]) serves the three quotients of [`Viewport::project`] (`x`, `y`
//! and depth) and the two sub-pixel offsets, instead of two 32-bit library divisions, one
//! 64-by-32-bit division with its own reciprocal and two bit-by-bit offset loops.
//!
//! Every quotient is the exact floor (or the exact rounding, for depth) that the division
//! path computes, so the screen vertices are bit-identical on every core (tested against
//! that path over random and edge inputs). Only a quotient beyond 32 bits (a vertex far
//! outside the guard band) answers `None`, and the caller takes the division path.

use super::viewport::{mul_i32_i64, Viewport, DEPTH_K, HALF_OFFSET, LIM, OFFSET_BITS};
use crate::math::recip32::Recip32;

impl Viewport {
    /// [`Viewport::project`] through one reciprocal of `w` (raised to 1); `None` where a
    /// numerator does not fit the reciprocal's range.
    #[inline]
    pub(crate) fn project_recip(
        &self,
        x: i32,
        y: i32,
        z: i32,
        w: i32,
    ) -> Option<(i32, i32, [i16; 2], i32)> {
        let r = Recip32::new(w.max(1) as u32)?;
        let (sx, sy, sub) = self.project_xy_recip(x, y, &r)?;
        Some((sx, sy, sub, depth_recip(z, &r)?))
    }

    /// [`Viewport::project_xy`] given the reciprocal of `w`.
    #[inline(always)]
    pub(crate) fn project_xy_recip(
        &self,
        x: i32,
        y: i32,
        r: &Recip32,
    ) -> Option<(i32, i32, [i16; 2])> {
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
            let (sx, ox) = axis(i64::from(2 * x * hw + w as i32), i64::from(cx), r)?;
            let (sy, oy) = axis(i64::from(w as i32 - 2 * y * hh), i64::from(cy), r)?;
            return Some((sx, sy, [ox, oy]));
        }
        let (hw, hh, cx, cy) = self.scales();
        let num = |n: i64| n.wrapping_mul(2).wrapping_add(i64::from(w));
        let (sx, ox) = axis(num(mul_i32_i64(x, hw)), cx, r)?;
        let (sy, oy) = axis(num(-mul_i32_i64(y, hh)), cy, r)?;
        Some((sx, sy, [ox, oy]))
    }
}

/// One axis, given `num = 2n + w`: `s = floor(num / 2w)` (the window position in 1/16
/// pixel, ties towards +x and +y), its remainder `rem = num - 2w s` in `0..2w`, and the
/// sub-pixel offset
/// `floor((2^R rem + w) / 2w) - 2^(R-1)`, with the division path's guard-band clamp.
/// Quotients by `2w` are those by `w` halved: `floor(floor(t / w) / 2) = floor(t / 2w)`,
/// with remainder `t mod w` plus `w` when the quotient by `w` is odd.
#[inline(always)]
fn axis(num: i64, c: i64, r: &Recip32) -> Option<(i32, i16)> {
    let w = r.divisor();
    let by_2w = |m: u64| {
        let (q, rw) = div_rem(r, m)?;
        // rw < w and w < 2^31: the remainder by 2w fits u32.
        Some((q >> 1, rw + (q & 1) * w))
    };
    let (s, rem) = if num >= 0 {
        let (q, rem) = by_2w(num as u64)?;
        (i64::from(q), rem)
    } else {
        // -m = 2w (-q) - rem: one less and the complement unless rem is 0.
        let (q, rem) = by_2w(num.unsigned_abs())?;
        if rem == 0 {
            (-i64::from(q), 0)
        } else {
            (-i64::from(q) - 1, 2 * w - rem)
        }
    };
    let s = c + s;
    if s.abs() > LIM {
        return Some((s.clamp(-LIM, LIM) as i32, 0));
    }
    // 2^R rem + w < (2^(R+1) + 1) w: a quotient below 2^(R+1) + 1.
    let (q, _) = div_rem(r, (u64::from(rem) << OFFSET_BITS) + u64::from(w))?;
    let off = i64::from(q >> 1) - (1 << (OFFSET_BITS - 1));
    Some((s as i32, off.clamp(-HALF_OFFSET, HALF_OFFSET) as i16))
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

/// The window depth of clip `z` (see `depth` in the viewport): `z k / w` rounded to
/// nearest, ties away from zero, plus `k`, clamped to `0..=2k`; `None` for `w >= 2^28`
/// (4096.0).
///
/// `|z| >= w` lands on the clamps (`2k = 65535 << 14` exactly); inside, the rounded
/// fraction `|z| / w` of `k` from the reciprocal, with no 64-bit division.
#[inline(always)]
pub(crate) fn depth_recip(z: i32, r: &Recip32) -> Option<i32> {
    let w = r.divisor();
    if w >= 1 << 28 {
        return None;
    }
    let a = z.unsigned_abs();
    let k = DEPTH_K as i32;
    if a >= w {
        return Some(if z > 0 { 2 * k } else { 0 });
    }
    let q = r.fraction_of(a, k as u32, w / 2) as i32;
    Some(if z < 0 { k - q } else { k + q })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::test_rng::Rng;

    /// The reciprocal path gives the division path's screen vertex wherever it answers, and
    /// answers for every vertex of a sensible scene.
    #[test]
    fn reciprocal_projection_equals_the_division() {
        let mut rng = Rng(0xC0FF_EE00_1234_5678);
        let vps = [
            Viewport::new(0, 0, 320, 240).unwrap(),
            Viewport::new(7, 3, 64, 64).unwrap(),
            Viewport::new(0, 0, 2048, 2048).unwrap(),
            Viewport::new(100, 50, 1, 1).unwrap(),
        ];
        let (mut answered, mut in_view) = (0u32, 0u32);
        for i in 0..400_000u32 {
            let vp = &vps[i as usize % vps.len()];
            let wbits = 1 + (rng.next() % 31) as u32;
            let w = ((rng.next() as u32 >> (32 - wbits)) as i32).max(1);
            // Coordinates around the view (|x| <= ~2w) and anywhere.
            let mut c = || {
                if rng.next() % 4 == 0 {
                    rng.next() as i32
                } else {
                    let f = (rng.next() as i64 >> 40) as i32; // +-2^23
                    ((i64::from(w) * i64::from(f)) >> 22) as i32
                }
            };
            let (x, y, z) = (c(), c(), c());
            let want = vp.project_div(x, y, z, w);
            if let Some(got) = vp.project_recip(x, y, z, w) {
                answered += 1;
                assert_eq!(got, want, "{x} {y} {z} {w}");
            }
            if w < 1 << 28 && x.unsigned_abs() <= w as u32 && y.unsigned_abs() <= w as u32 {
                in_view += 1;
                assert!(vp.project_recip(x, y, z.clamp(-w, w), w).is_some());
            }
        }
        assert!(
            answered > 200_000 && in_view > 10_000,
            "{answered} {in_view}"
        );
    }

    /// Ties and exact multiples, where the remainder is 0 or `w`.
    #[test]
    fn reciprocal_projection_on_ties() {
        let vp = Viewport::new(0, 0, 64, 64).unwrap();
        for w in [1, 2, 3, 255, 256, 65536, 65537, (1 << 23) - 1] {
            for k in -3000..3000 {
                let x = (i64::from(k) * i64::from(w) / 1024) as i32;
                let want = vp.project_div(x, -x, x, w);
                if let Some(got) = vp.project_recip(x, -x, x, w) {
                    assert_eq!(got, want, "{x} {w}");
                }
            }
        }
    }
}
