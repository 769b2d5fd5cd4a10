//! Quadratic subdivision: along a span, each varying follows the parabola through its exact
//! (perspective-correct) values at the start, middle and end of a segment of `N = 2^log2_n`
//! pixels, stepped with second-order forward differences.
//!
//! The hyperbola `u(x) = s(x) / q(x)` bends with `q`: a chord between exact values (the
//! subdivided mode, [`Linear`](super::interp::Linear)) errs by about `N^2 / 8 |u''|`, a
//! parabola through three of them by about `N^3 / 72 / sqrt(3) |u'''|`, and `u''' / u'' =
//! -3 q_x / q`, which is small wherever `q` changes slowly along the span (every span that
//! does not run to the horizon). So a segment of 16 pixels with two reciprocals (middle and
//! end) is as accurate as four chords of four pixels with four: fewer reciprocals per pixel
//! for the same error, at the price of one more add per varying and pixel.
//!
//! Segment of `reach` pixels (the last one of a span ends on the span's last pixel, as in the
//! subdivided mode; the others end on the next segment's first pixel), middle `m = reach / 2`,
//! exact values `f0`, `fm`, `fr` (I16F16 or the varying's own format; differences wrapping):
//!
//! ```text
//! c1 = (fm - f0) / m,  c2 = ((fr - fm) / (reach - m) - c1) / reach     (floored)
//! f(t) = f0 + c1 t + c2 t (t - m)
//! f(t+1) - f(t) = c1 + c2 (2t + 1 - m),   second difference 2 c2
//! ```
//!
//! Full segments divide by powers of two (shifts); the last one uses the `ceil(2^16 / n)`
//! table of the subdivided mode. Segments shorter than three pixels are chords (a parabola
//! through two points is a line), bit for bit the subdivided mode's. The floors cost at most
//! `reach + reach^2 / 4` units of the varying's last bit at a segment's far end: 288 units
//! (1/228 texel) for `N = 32`.

use super::interp::{hyper_lambda, unshift_piece, FillSpec, Hyper, INV_SMALL};
use super::interp::{scale_q16, unshift, Fill};
use super::tri_setup::TriSetup;
use crate::shading::Varyings;

/// Quadratic interpolation along one span, a segment of up to `2^log2_n` pixels at a time.
/// With `SHARED` the segment set-up is one out-of-line function per varying count (for
/// `Draw::dynamic`, which links a span loop per built-in shader: inlined into each, the
/// copies outgrow 256 KB of flash); without, it is inlined (about 3 instructions per pixel
/// fewer on the Cortex-M4F cube with N = 32).
#[derive(Clone, Copy, Debug)]
pub(crate) struct Quadratic<V, const SHARED: bool> {
    /// Values at the next pixel, their forward difference, and its change per pixel.
    cur: V,
    d: V,
    dd: V,
    /// Pixels left in the current segment.
    in_seg: u32,
    /// Pixels of the span after the current segment.
    left: u32,
    /// Level of detail of the current segment (at its first pixel).
    seg_lambda: i32,
    /// Exact values at the next segment's first pixel and the perspective interpolants
    /// there.
    exact: V,
    next: Hyper<V>,
    step: Hyper<V>,
    log2_n: u32,
}

/// `x / n` (floored) for `n` in `1..64`: a shift when `n = 2^k` is known, else the table.
#[inline(always)]
fn div_small(x: i32, n: u32, log2: Option<u32>) -> i32 {
    match log2 {
        Some(k) => x >> k,
        None => scale_q16(x, INV_SMALL[n.min(63) as usize]),
    }
}

/// `x`, with no instruction emitted, but hidden from the optimizer.
///
/// The fill loop's forward differences are second-order recurrences. Seen through, LLVM
/// unrolls the Cortex-M4F loop four times and rewrites each unrolled pixel as the first one
/// plus a loop-invariant multiple of the second difference: 14 such constants, spilled and
/// reloaded every 8 pixels. Hiding the first difference's new value keeps the loop as
/// written (13 instructions per 2 pixels instead of 56 per 8, and a shorter segment
/// set-up): on the cube (quadratic N = 16) about 1.5 % fewer instructions per pixel on
/// Cortex-M4F, a little fewer on RV32IMC and a little more on Cortex-M0+ (measure with
/// `cargo xtask mcu --profile`). An empty `asm!` is the only zero-cost barrier
/// (`core::hint::black_box` goes through memory).
#[inline(always)]
#[allow(unsafe_code, unused_mut)]
fn opaque(mut x: i32) -> i32 {
    // SAFETY: the template is a comment: no instruction, no memory or stack access, flags
    // preserved (as the options declare); `x` is read and written back unchanged in its
    // register. Tested in `opaque_is_the_identity`. (Elsewhere: the identity.)
    #[cfg(any(
        target_arch = "arm",
        target_arch = "riscv32",
        target_arch = "riscv64",
        target_arch = "x86",
        target_arch = "x86_64",
        target_arch = "aarch64"
    ))]
    #[allow(asm_sub_register)]
    unsafe {
        core::arch::asm!(
            "/* {0} */",
            inout(reg) x,
            options(pure, nomem, nostack, preserves_flags)
        );
    }
    x
}

impl<V: Varyings, const SHARED: bool> Quadratic<V, SHARED> {
    /// [`segment`](Self::segment), out of line.
    #[inline(never)]
    fn segment_shared(&mut self, s: &TriSetup<V>, spec: FillSpec) {
        self.segment(s, spec);
    }

    /// Starts the next segment: the parabola through the exact values at its start, middle
    /// and end (a chord when it is shorter than three pixels).
    #[inline(always)]
    fn segment(&mut self, s: &TriSetup<V>, spec: FillSpec) {
        let n = 1u32 << self.log2_n;
        let seg = self.left.min(n);
        if spec.lod {
            self.seg_lambda = hyper_lambda(s, &self.next, spec.pair.0, spec.pair.1);
        }
        let reach = if self.left == seg && seg > 1 {
            seg - 1
        } else {
            seg
        };
        let f0 = self.exact;
        let mut d = V::zero();
        let mut dd = V::zero();
        if reach < 3 {
            self.next.add_scaled(&self.step, reach as i32);
            let end = self.next.resolve();
            let inv = INV_SMALL[reach as usize];
            for k in 0..V::N {
                let diff = end.as_slice()[k].wrapping_sub(f0.as_slice()[k]);
                d.as_mut_slice()[k] = scale_q16(diff, inv);
            }
            self.exact = end;
        } else {
            let m = reach / 2;
            let mut mid = self.next;
            mid.add_scaled(&self.step, m as i32);
            let fm = mid.resolve();
            self.next.add_scaled(&self.step, reach as i32);
            let fr = self.next.resolve();
            let whole = reach == n;
            let (lm, lr) = if whole {
                (Some(self.log2_n - 1), Some(self.log2_n))
            } else {
                (None, None)
            };
            for k in 0..V::N {
                let (a, b, c) = (f0.as_slice()[k], fm.as_slice()[k], fr.as_slice()[k]);
                let c1 = div_small(b.wrapping_sub(a), m, lm);
                let g = div_small(c.wrapping_sub(b), reach - m, lm);
                let c2 = div_small(g.wrapping_sub(c1), reach, lr);
                d.as_mut_slice()[k] = c1.wrapping_add(c2.wrapping_mul(1 - m as i32));
                dd.as_mut_slice()[k] = c2.wrapping_mul(2);
            }
            self.exact = fr;
        }
        let mut cur = f0;
        unshift_piece(&mut cur, &mut d, spec);
        if spec.shift != 0 {
            unshift(&mut dd, spec.pair, spec.shift);
        }
        self.cur = cur;
        self.d = d;
        self.dd = dd;
        self.in_seg = seg;
        self.left -= seg;
    }
}

impl<V: Varyings, const SHARED: bool> Fill<V> for Quadratic<V, SHARED> {
    #[inline(always)]
    fn start(s: &TriSetup<V>, x: i32, y: i32, len: u32, log2_n: u32) -> Self {
        let h = Hyper::at(s, x, y);
        Quadratic {
            cur: V::zero(),
            d: V::zero(),
            dd: V::zero(),
            in_seg: 0,
            left: len,
            seg_lambda: 0,
            exact: h.resolve(),
            next: h,
            step: Hyper::dx(s),
            log2_n: log2_n.clamp(1, 6),
        }
    }

    #[inline(always)]
    fn lambda(&self, s: &TriSetup<V>, (a, b): (usize, usize)) -> i32 {
        hyper_lambda(s, &self.next, a, b)
    }

    #[inline(always)]
    fn fill(
        &mut self,
        s: &TriSetup<V>,
        vals: &mut [V],
        lambdas: &mut [i32],
        _: u32,
        spec: FillSpec,
    ) {
        let mut off = 0usize;
        while off < vals.len() {
            if self.in_seg == 0 {
                if self.left == 0 {
                    break;
                }
                if SHARED {
                    self.segment_shared(s, spec);
                } else {
                    self.segment(s, spec);
                }
            }
            let end = (off + self.in_seg as usize).min(vals.len());
            let (mut v, mut d, dd) = (self.cur, self.d, self.dd);
            if let Some(vs) = vals.get_mut(off..end) {
                let step = |v: &mut V, d: &mut V| {
                    for k in 0..V::N {
                        v.as_mut_slice()[k] = v.as_slice()[k].wrapping_add(d.as_slice()[k]);
                        d.as_mut_slice()[k] =
                            opaque(d.as_slice()[k].wrapping_add(dd.as_slice()[k]));
                    }
                };
                // Only the interpolated values are stored (a shader's `Varyings` may carry
                // more, read per triangle: `FacetVaryings`).
                let put = |x: &mut V, v: &V| {
                    for k in 0..V::N {
                        x.as_mut_slice()[k] = v.as_slice()[k];
                    }
                };
                let mut pairs = vs.chunks_exact_mut(2);
                for p in &mut pairs {
                    if let [a, b] = p {
                        put(a, &v);
                        step(&mut v, &mut d);
                        put(b, &v);
                        step(&mut v, &mut d);
                    }
                }
                for x in pairs.into_remainder() {
                    put(x, &v);
                    step(&mut v, &mut d);
                }
            }
            if spec.lod {
                if let Some(ls) = lambdas.get_mut(off..end) {
                    ls.fill(self.seg_lambda);
                }
            }
            (self.cur, self.d) = (v, d);
            self.in_seg -= (end - off) as u32;
            off = end;
        }
    }
}

#[cfg(test)]
mod tests {
    extern crate std;

    use super::super::interp::{ExactInterp, Fill, FillSpec, Linear};
    use super::super::setup::setup;
    use super::super::stages::ProjKind;
    use super::Quadratic;
    use crate::raster::{Rect, ATTR_SUBPIXEL_BITS};
    use std::vec::Vec;

    #[test]
    fn opaque_is_the_identity() {
        for x in [0, 1, -1, i32::MIN, i32::MAX, 0x1234_5678, -0x7F80] {
            assert_eq!(super::opaque(x), x);
        }
        let mut r = crate::test_rng::Rng(7);
        for _ in 0..1000 {
            let x = r.next() as i32;
            assert_eq!(super::opaque(x), x);
        }
    }

    const SPEC: FillSpec = FillSpec {
        pair: (0, 1),
        lod: false,
        shift: 0,
        live: usize::MAX,
    };

    /// A right triangle `(0, 0)`, `(w, 0)`, `(0, h)` in pixels whose vertices lie at clip
    /// `w` = `ws`, with texel coordinates `(0, 0)`, `(128, 0)`, `(0, 128)` (I16F16).
    fn triangle(w: i32, h: i32, ws: [f64; 3]) -> super::super::tri_setup::TriSetup<[i32; 2]> {
        let p = |x: i32, y: i32, k: usize| {
            (
                x << ATTR_SUBPIXEL_BITS,
                y << ATTR_SUBPIXEL_BITS,
                0,
                (ws[k] * 65536.0) as i32,
            )
        };
        let vary = [[0, 0], [128 << 16, 0], [0, 128 << 16]];
        let vp = Rect {
            x0: 0,
            y0: 0,
            x1: 320,
            y1: 240,
        };
        setup(
            [p(0, 0, 0), p(w, 0, 1), p(0, h, 2)],
            &vary,
            vp,
            ProjKind::Quadratic,
            false,
            Some((0, 1)),
            0,
            None,
        )
        .expect("a triangle")
    }

    /// The span of row `y` filled by `I`, chunk by chunk as the span loop does.
    fn fill<I: Fill<[i32; 2]>>(
        s: &super::super::tri_setup::TriSetup<[i32; 2]>,
        y: i32,
        len: usize,
        log2_n: u32,
    ) -> Vec<[i32; 2]> {
        let mut it = I::start(s, 0, y, len as u32, log2_n);
        let mut out = std::vec![[0; 2]; len];
        for c in out.chunks_mut(32) {
            it.fill(s, c, &mut [], u32::MAX, SPEC);
        }
        out
    }

    /// Largest difference to the exact mode's values over the rows of the triangle, in
    /// I16F16 units, for interpolator `I`.
    fn worst<I: Fill<[i32; 2]>>(w: i32, h: i32, ws: [f64; 3], log2_n: u32) -> i64 {
        let s = triangle(w, h, ws);
        let mut worst = 0i64;
        for y in (0..h).step_by(7) {
            let len = (f64::from(w) * (1.0 - (f64::from(y) + 0.5) / f64::from(h))) as usize;
            if len == 0 {
                continue;
            }
            let exact = fill::<ExactInterp<[i32; 2]>>(&s, y, len, 0);
            let got = fill::<I>(&s, y, len, log2_n);
            for (e, g) in exact.iter().zip(&got) {
                for k in 0..2 {
                    worst = worst.max((i64::from(e[k]) - i64::from(g[k])).abs());
                }
            }
        }
        worst
    }

    /// The parabola over N pixels is at least as close to the exact values as the chord
    /// over N / 4 (the claim of the module docs), on triangles from mild to steep
    /// perspective (measured: 171 against 308 units for `w` from 1 to 1.5, 1242 against
    /// 3857 from 1 to 4), and within 1/32 texel for N = 16 while `w` changes at most
    /// fourfold along the 300-pixel rows.
    #[test]
    fn sixteen_pixel_parabolas_beat_four_pixel_chords() {
        for ws in [
            [1.0, 1.5, 1.2],
            [1.0, 4.0, 2.0],
            [1.0, 8.0, 1.0],
            [3.0, 1.0, 6.0],
        ] {
            for log2_n in [4u32, 5] {
                let q = worst::<Quadratic<[i32; 2], false>>(300, 200, ws, log2_n);
                let l = worst::<Linear<[i32; 2], true>>(300, 200, ws, log2_n - 2);
                assert!(
                    q <= l.max(64),
                    "w {ws:?} N 2^{log2_n}: parabola {q}, chord {l}"
                );
                if log2_n == 4 && ws[0] == 1.0 && ws[1] <= 4.0 {
                    assert!(q <= 2048, "w {ws:?}: {q} units off");
                }
            }
        }
    }

    /// Every span length from 1 to three segments, at every segment length: the values at
    /// the span's ends are the exact ones (each segment is anchored on exact values, the
    /// last one on the span's last pixel).
    #[test]
    fn spans_end_on_exact_values() {
        let s = triangle(300, 200, [1.0, 4.0, 2.0]);
        for log2_n in 1..=6u32 {
            for len in 1..=(3usize << log2_n).min(250) {
                let exact = fill::<ExactInterp<[i32; 2]>>(&s, 3, len, 0);
                let got = fill::<Quadratic<[i32; 2], false>>(&s, 3, len, log2_n);
                assert_eq!(got[0], exact[0], "N 2^{log2_n}, len {len}: first pixel");
                let tol = 1 + (1i64 << log2_n) * (1 << log2_n);
                for k in 0..2 {
                    let d = (i64::from(got[len - 1][k]) - i64::from(exact[len - 1][k])).abs();
                    assert!(d <= tol, "N 2^{log2_n}, len {len}: last pixel {d} off");
                }
            }
        }
    }
}
