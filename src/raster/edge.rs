//! An exact integer DDA along one triangle edge: for each pixel row it yields the first pixel
//! whose centre lies on or right of the edge.
//!
//! For an edge from `(x0, y0)` (top) to `(x1, y1)` (bottom) in sub-pixel units, the edge's x
//! at the centre of row `py` (`yc = 16 py + 8`) is `x0 + (yc - y0) dx / dy`. The first pixel
//! `px` with `px + 0.5 >= x` is `ceil(N / D)` with
//! `N = (x0 - 8) dy + (yc - y0) dx` and `D = 16 dy`. The same formula gives the exclusive end
//! of a span on a right edge, which is exactly the top-left rule. Stepping one row adds
//! `16 dx` to `N`; the walker keeps `ceil(N / D)` and its remainder, so stepping is two adds
//! and a compare, and the result equals the exact rational one on every row.
//!
//! Ranges: coordinates within the guard band (`|x|, |y| <= 2^16`), so `D <= 2^21` and the
//! remainder fits `i32`; the one `i64` division is at [`EdgeWalker::new`].

use super::{SUBPIXEL_BITS, SUBPIXEL_ONE};
use crate::math::wide::mul_wide_signed;
use crate::math::{div_floor_i64, HW_DIVIDE};

/// Walks one edge row by row; see the module docs for the arithmetic.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct EdgeWalker {
    /// `ceil(N / D)`: the first pixel at or right of the edge on the current row.
    x: i32,
    /// `x * D - N`, in `0..D`.
    rem: i32,
    /// Whole pixels added per row (`ceil(16 dx / D)`).
    step: i32,
    /// `step * D - 16 dx`, in `0..D`.
    step_rem: i32,
    /// `16 dy`, > 0.
    den: i32,
}

/// The ceiling pair from the floor pair: `(q, r)` with `n = q d + r`, `0 <= r < d`, gives
/// `ceil(n / d)` and its remainder `ceil * d - n` (in `0..d`).
#[inline(always)]
fn ceil_from_floor(q: i64, r: i64, d: i64) -> (i64, i64) {
    if r == 0 {
        (q, 0)
    } else {
        (q + 1, d - r)
    }
}

/// `ceil(n / d)` and the non-negative remainder `ceil * d - n`, for `d > 0`. The floor
/// division goes through `math::div` (exact, 32-bit paths: a 64-bit library division per
/// edge and band would be a visible share of small triangles' cost on Cortex-M). Always
/// inlined: out of line, its call costs the Cortex-M4F whole-frame sphere about 1 %.
#[inline(always)]
fn ceil_div_rem(n: i64, d: i64) -> (i64, i64) {
    // On screen (the common case) both fit `i32`: one 32-bit division, inline.
    if let (Ok(n32), Ok(d32)) = (i32::try_from(n), i32::try_from(d)) {
        if d32 > 0 && n32 != i32::MIN {
            let (q, r) = (n32.div_euclid(d32), n32.rem_euclid(d32));
            return ceil_from_floor(i64::from(q), i64::from(r), d);
        }
    }
    let q = div_floor_i64(n, d);
    // floor division: 0 <= r < d.
    let r = n.wrapping_sub(q.wrapping_mul(d));
    ceil_from_floor(q, r, d)
}

/// `ceil(N / D)` and its remainder for a first row whose centre is less than 16 pixels
/// below the top vertex (`0 <= t = yc - y0 < 256`: every edge's first row, or a band's
/// first row cutting a small triangle), from the step's quotient instead of a second
/// division: with `dx = q dy + r` (`0 <= r < dy`), `N = dy ((x0 - 8) + t q) + t r`, and
/// `t r / dy < t` takes four (`t < 16`) or eight compare-and-subtract steps. Exact, the
/// same pair as [`ceil_div_rem`]; `None` outside its range (the caller divides). For cores
/// without a divide instruction, where each division is a library call of about 100
/// instructions.
#[inline(always)]
fn start_near_top(x0: i32, dy: i32, t: i32, step: i32, step_rem: i32) -> Option<(i64, i64)> {
    const ONE: i32 = SUBPIXEL_ONE;
    // t < 2^8, dy and |q| < 2^22: t r, t |q| < 2^30 and dy << 7 < 2^29 (no 64-bit product
    // to check them with on Cortex-M0+).
    if !(0..ONE * ONE).contains(&t) || dy <= 0 || dy >= 1 << 22 {
        return None;
    }
    // floor(dx / dy) and dx - q dy, from ceil(16 dx / 16 dy) and its remainder (a multiple
    // of 16).
    let (q, r) = if step_rem == 0 {
        (step, 0)
    } else {
        (step.wrapping_sub(1), dy - (step_rem >> SUBPIXEL_BITS))
    };
    if q.unsigned_abs() >= 1 << 22 {
        return None;
    }
    // t r < t dy: its quotient by dy is below t, so it has at most 4 or 8 bits.
    let (qb, b) = if t < ONE {
        div_bits::<SUBPIXEL_BITS>(t * r, dy)
    } else {
        div_bits::<{ 2 * SUBPIXEL_BITS }>(t * r, dy)
    };
    let c = x0
        .checked_sub(ONE / 2)?
        .checked_add(t * q)?
        .checked_add(qb)?;
    // N = dy c + b = 16 dy (c >> 4) + (dy (c & 15) + b), the last term in 0..16 dy.
    let rem = dy * (c & (ONE - 1)) + b;
    Some(ceil_from_floor(
        i64::from(c >> SUBPIXEL_BITS),
        i64::from(rem),
        i64::from(ONE * dy),
    ))
}

/// [`ceil_div_rem`] when the quotient is small, `|n| < 16 d` (an edge less than 16 pixels
/// across per row: every edge of a finely tessellated mesh), and `0 < d < 2^26`: four
/// restoring steps instead of a library division on cores without a divide instruction
/// (one per edge and band; about 1 % of the Cortex-M0+ sphere in bands).
/// `None` otherwise. The same quotient and remainder (tested).
#[inline(always)]
fn ceil_div_rem_small(n: i32, d: i32) -> Option<(i64, i64)> {
    if d <= 0 || d >= 1 << 26 {
        return None;
    }
    let m = n.unsigned_abs();
    if m >= (d as u32) << 4 {
        return None;
    }
    // m < 16 d < 2^30: fits `i32`, quotient 0..=15.
    let (q, r) = div_bits::<4>(m as i32, d);
    let (q, r) = (i64::from(q), i64::from(r));
    Some(if n >= 0 {
        ceil_from_floor(q, r, i64::from(d))
    } else {
        // ceil(-m / d) = -floor(m / d); remainder -q d + m = r.
        (-q, r)
    })
}

/// `(b / d, b % d)` for a quotient below `2^BITS` (`b < d 2^BITS < 2^31`): `BITS` steps of
/// restoring division, unrolled.
#[inline(always)]
fn div_bits<const BITS: u32>(mut b: i32, d: i32) -> (i32, i32) {
    let mut q = 0;
    for k in (0..BITS).rev() {
        let dk = d << k;
        if b >= dk {
            b -= dk;
            q |= 1 << k;
        }
    }
    (q, b)
}

impl EdgeWalker {
    /// Starts the walk at pixel row `py` for the edge `top -> bottom` (sub-pixel units,
    /// `top.1 < bottom.1`, both inside the guard band).
    ///
    /// Inlined but on ARMv6-M: the rasterizer calls it at two places (the long edge, and the
    /// short one in its loop over the two halves). That saves about 1 % of the whole-frame
    /// sphere on Cortex-M4F and RV32IMC for about 0.4 KB of flash per rasterizer (measure
    /// with `cargo xtask mcu`); on Cortex-M0+ inlined it costs a little more per pixel and
    /// 0.7 KB per rasterizer (2.2 KB in the shadow firmwares), so there it stays out of
    /// line.
    #[cfg_attr(
        not(all(target_arch = "arm", not(target_has_atomic = "32"))),
        inline(always)
    )]
    pub fn new(top: (i32, i32), bottom: (i32, i32), py: i32) -> Self {
        // Inside the guard band every difference and product operand fits `i32`; the two
        // products are `i32 x i32 -> i64` (no 64-bit library multiply on Cortex-M0+).
        let (x0, y0) = top;
        let dx = bottom.0.wrapping_sub(x0);
        let dy = bottom.1.wrapping_sub(y0);
        debug_assert!(dy > 0, "edges are walked top to bottom");
        let one = SUBPIXEL_ONE;
        let half = one / 2;
        let den = i64::from(one) * i64::from(dy.max(1));
        let yc = py.wrapping_mul(one).wrapping_add(half);
        let n = || {
            mul_wide_signed(x0.wrapping_sub(half), dy)
                .wrapping_add(mul_wide_signed(yc.wrapping_sub(y0), dx))
        };
        // With a divide instruction, the two divisions in the order that measures cheapest on
        // x86 and Cortex-M4F; without, the step first, whose quotient gives the start.
        let ((x, rem), (step, step_rem)) = if HW_DIVIDE {
            let start = ceil_div_rem(n(), den);
            (start, ceil_div_rem(i64::from(one) * i64::from(dx), den))
        } else {
            let (step, step_rem) = ceil_div_rem_small(one.wrapping_mul(dx), den as i32)
                .unwrap_or_else(|| ceil_div_rem(i64::from(one) * i64::from(dx), den));
            let t = yc.wrapping_sub(y0);
            let start = match start_near_top(x0, dy, t, step as i32, step_rem as i32) {
                Some(start) => start,
                None => ceil_div_rem(n(), den),
            };
            (start, (step, step_rem))
        };
        EdgeWalker {
            x: x as i32,
            rem: rem as i32,
            step: step as i32,
            step_rem: step_rem as i32,
            den: den as i32,
        }
    }

    /// First pixel whose centre is on or right of the edge, on the current row.
    #[inline(always)]
    pub fn x(&self) -> i32 {
        self.x
    }

    /// Advances one row down.
    #[inline(always)]
    pub fn step(&mut self) {
        self.x = self.x.wrapping_add(self.step);
        self.rem += self.step_rem;
        if self.rem >= self.den {
            self.rem -= self.den;
            self.x = self.x.wrapping_sub(1);
        }
    }
}

#[cfg(test)]
mod tests {
    extern crate std;
    use super::*;

    #[test]
    fn small_quotients_match_the_division() {
        let mut x: u32 = 0x9E37_79B9;
        let mut next = || {
            x ^= x << 13;
            x ^= x >> 17;
            x ^= x << 5;
            x
        };
        let mut hits = 0;
        for k in 0..400_000 {
            let d = match k % 4 {
                0 => (next() % 64) as i32 + 1,
                1 => (next() % 4096) as i32 + 1,
                2 => (next() % (1 << 26)) as i32,
                _ => (next() % (1 << 27)) as i32,
            };
            let n = match k % 3 {
                0 => (next() as i32) % (16 * d.max(1)).max(1),
                1 => next() as i32,
                _ => -((next() % (16 * d.max(1) as u32 + 2)) as i32),
            };
            if let Some((q, r)) = ceil_div_rem_small(n, d) {
                hits += 1;
                let (q2, r2) = ceil_div_rem(i64::from(n), i64::from(d));
                assert_eq!((q, r), (q2, r2), "n {n} d {d}");
            }
        }
        assert!(hits > 100_000, "{hits}");
        assert_eq!(ceil_div_rem_small(16 * 5, 5), None);
        assert_eq!(ceil_div_rem_small(-16 * 5, 5), None);
        assert_eq!(ceil_div_rem_small(i32::MIN, 5), None);
        assert_eq!(ceil_div_rem_small(3, 0), None);
    }

    /// Exact rational reference: smallest px with 16 px + 8 >= x(yc).
    fn exact(top: (i32, i32), bot: (i32, i32), py: i32) -> i32 {
        let (x0, y0, x1, y1) = (top.0 as i128, top.1 as i128, bot.0 as i128, bot.1 as i128);
        let yc = py as i128 * 16 + 8;
        let n = (x0 - 8) * (y1 - y0) + (yc - y0) * (x1 - x0);
        let d = 16 * (y1 - y0);
        let mut q = n.div_euclid(d);
        if n.rem_euclid(d) != 0 {
            q += 1;
        }
        q as i32
    }

    /// The division-free start equals the divided one wherever it answers.
    #[test]
    fn start_near_top_matches_division() {
        let mut rng = crate::test_rng::Rng(0x9E37_79B9_7F4A_7C15);
        let mut answered = 0;
        for i in 0..400_000 {
            let r = rng.next();
            let span = [1 << 6, 1 << 12, 1 << 17, 1 << 22][i % 4];
            let x0 = (r % (2 * span)) as i32 - span as i32;
            let dy = 1 + ((r >> 24) % span) as i32;
            let dx = ((r >> 40) % (2 * span)) as i32 - span as i32;
            let t = if i % 3 == 0 {
                ((r >> 56) & 255) as i32
            } else {
                ((r >> 60) & 15) as i32
            };
            let one = SUBPIXEL_ONE;
            let den = i64::from(one) * i64::from(dy);
            let n = i64::from(x0 - one / 2) * i64::from(dy) + i64::from(t) * i64::from(dx);
            let (step, step_rem) = ceil_div_rem_small(one.wrapping_mul(dx), den as i32)
                .unwrap_or_else(|| ceil_div_rem(i64::from(one) * i64::from(dx), den));
            if let Some(got) = start_near_top(x0, dy, t, step as i32, step_rem as i32) {
                assert_eq!(got, ceil_div_rem(n, den), "x0 {x0} dy {dy} dx {dx} t {t}");
                answered += 1;
            }
        }
        assert!(answered > 250_000, "{answered}");
    }

    #[test]
    fn walk_matches_exact_rational_on_every_row() {
        let cases: [((i32, i32), (i32, i32)); 6] = [
            ((0, 0), (160, 160)),
            ((37, -5), (-200, 333)),
            ((8, 8), (8, 1000)),
            ((-65536, -65536), (65536, 65536)),
            ((65536, -65536), (-65536, 65535)),
            ((3, 1), (4, 2)),
        ];
        for (top, bot) in cases {
            let first = (top.1 - 8 + 15).div_euclid(16);
            let last = (bot.1 - 8 + 15).div_euclid(16);
            let mut w = EdgeWalker::new(top, bot, first);
            for py in first..last.min(first + 20000) {
                assert_eq!(w.x(), exact(top, bot, py), "edge {top:?}->{bot:?} row {py}");
                w.step();
            }
        }
    }

    #[test]
    fn centre_exactly_on_edge_is_included() {
        // Vertical edge at x = 2.5 px: pixel 2's centre is on it, so the first is 2.
        let w = EdgeWalker::new((40, 0), (40, 160), 3);
        assert_eq!(w.x(), 2);
    }
}
