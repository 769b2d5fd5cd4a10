//! Span interpolators: how `(u, v, colour)` advance along a span in each projection mode.
//!
//! * [`AffineInterp`]: adds per pixel, nothing else.
//! * [`ExactInterp`]: steps `s = u q`, `t = v q`, `q` (and colour times `q`) linearly and
//!   recovers `u = s / q` at every pixel through one table reciprocal and one 32x32->64
//!   multiply per attribute (the seeds' hyperbolic interpolation).
//! * [`SubdivInterp`]: exact at every `N`-th pixel and at the span end, affine in between;
//!   one reciprocal per `N` pixels. The slope of a short last segment uses a small
//!   reciprocal table instead of a divide.
//!
//! All three are inlined into the span loop, which is monomorphised per projection mode, so
//! a draw pays only for the one it uses.

use super::recip::{mul_q16, recip_q30};
use super::setup::TriSetup;
use crate::texture::mip::lambda_q8;

/// One fragment's interpolated values: texel coordinates (I16F16 bits, before `uv_shift`)
/// and colour channels (Q8 with 16 fraction bits).
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct Frag {
    pub u: i32,
    pub v: i32,
    pub c: [i32; 3],
}

/// Interpolation along one span.
pub(crate) trait Interp {
    /// Starts at pixel `(x, y)` for a span of `len` pixels.
    fn start(s: &TriSetup, x: i32, y: i32, len: u32, log2_n: u32) -> Self;
    /// Values at the current pixel.
    fn frag(&self) -> Frag;
    /// Moves one pixel right.
    fn step(&mut self);
    /// Level of detail `lambda` (Q8.8, before bias) at the current pixel.
    fn lambda(&self, s: &TriSetup) -> i32;
}

/// `lambda` of an affine mapping: constant derivatives, straight from the planes.
#[inline(always)]
pub(crate) fn affine_lambda(s: &TriSetup) -> i32 {
    lambda_q8(s.u.dx, s.v.dx, s.u.dy, s.v.dy) + 256 * s.uv_shift as i32
}

/// `lambda` of a perspective mapping at a pixel with interpolants `h`: the derivative of
/// `u = s / q` along x is `(s_x - u q_x) / q` (and likewise along y and for `v`).
#[inline(always)]
fn hyper_lambda(s: &TriSetup, h: &Hyper) -> i32 {
    let r32 = recip_q30(h.q);
    let r = i64::from(r32);
    let m = |a: i32| mul_q16(a, r32);
    let (u, v) = (m(h.s), m(h.t));
    let d = |sd: i32, qd: i32, a: i32| -> i32 {
        let t = i64::from(sd) - ((i64::from(a) * i64::from(qd)) >> 30);
        (t.saturating_mul(r) >> 16).clamp(i64::from(i32::MIN), i64::from(i32::MAX)) as i32
    };
    let (ux, vx) = (d(s.u.dx, s.q.dx, u), d(s.v.dx, s.q.dx, v));
    let (uy, vy) = (d(s.u.dy, s.q.dy, u), d(s.v.dy, s.q.dy, v));
    lambda_q8(ux, vx, uy, vy) + 256 * s.uv_shift as i32
}

/// `lambda` at pixel `(x, y)` for a perspective set-up (per-triangle level of detail).
pub(crate) fn hyper_lambda_at(s: &TriSetup, x: i32, y: i32) -> i32 {
    hyper_lambda(s, &Hyper::at(s, x, y))
}

#[inline(always)]
fn at(p: &crate::raster::Plane, s: &TriSetup, x: i32, y: i32) -> i32 {
    p.at((s.px_ref, s.py_ref), x, y)
}

/// Screen-linear interpolation.
#[derive(Clone, Copy, Debug)]
pub(crate) struct AffineInterp {
    f: Frag,
    d: Frag,
}

impl Interp for AffineInterp {
    #[inline(always)]
    fn start(s: &TriSetup, x: i32, y: i32, _len: u32, _log2_n: u32) -> Self {
        AffineInterp {
            f: Frag {
                u: at(&s.u, s, x, y),
                v: at(&s.v, s, x, y),
                c: [
                    at(&s.c[0], s, x, y),
                    at(&s.c[1], s, x, y),
                    at(&s.c[2], s, x, y),
                ],
            },
            d: Frag {
                u: s.u.dx,
                v: s.v.dx,
                c: [s.c[0].dx, s.c[1].dx, s.c[2].dx],
            },
        }
    }
    #[inline(always)]
    fn frag(&self) -> Frag {
        self.f
    }
    #[inline(always)]
    fn lambda(&self, s: &TriSetup) -> i32 {
        affine_lambda(s)
    }
    #[inline(always)]
    fn step(&mut self) {
        self.f.u = self.f.u.wrapping_add(self.d.u);
        self.f.v = self.f.v.wrapping_add(self.d.v);
        for k in 0..3 {
            self.f.c[k] = self.f.c[k].wrapping_add(self.d.c[k]);
        }
    }
}

/// The perspective interpolants `s, t, q, c q`.
#[derive(Clone, Copy, Debug)]
struct Hyper {
    s: i32,
    t: i32,
    q: i32,
    c: [i32; 3],
}

impl Hyper {
    #[inline(always)]
    fn at(s: &TriSetup, x: i32, y: i32) -> Self {
        Hyper {
            s: at(&s.u, s, x, y),
            t: at(&s.v, s, x, y),
            q: at(&s.q, s, x, y),
            c: [
                at(&s.c[0], s, x, y),
                at(&s.c[1], s, x, y),
                at(&s.c[2], s, x, y),
            ],
        }
    }
    #[inline(always)]
    fn dx(s: &TriSetup) -> Self {
        Hyper {
            s: s.u.dx,
            t: s.v.dx,
            q: s.q.dx,
            c: [s.c[0].dx, s.c[1].dx, s.c[2].dx],
        }
    }
    #[inline(always)]
    fn add_scaled(&mut self, d: &Hyper, n: i32) {
        self.s = self.s.wrapping_add(d.s.wrapping_mul(n));
        self.t = self.t.wrapping_add(d.t.wrapping_mul(n));
        self.q = self.q.wrapping_add(d.q.wrapping_mul(n));
        for k in 0..3 {
            self.c[k] = self.c[k].wrapping_add(d.c[k].wrapping_mul(n));
        }
    }
    #[inline(always)]
    fn add(&mut self, d: &Hyper) {
        self.s = self.s.wrapping_add(d.s);
        self.t = self.t.wrapping_add(d.t);
        self.q = self.q.wrapping_add(d.q);
        for k in 0..3 {
            self.c[k] = self.c[k].wrapping_add(d.c[k]);
        }
    }
    /// `(s, t, c) / q`.
    #[inline(always)]
    fn resolve(&self) -> Frag {
        let r = recip_q30(self.q);
        let m = |a: i32| mul_q16(a, r);
        Frag {
            u: m(self.s),
            v: m(self.t),
            c: [m(self.c[0]), m(self.c[1]), m(self.c[2])],
        }
    }
}

/// Perspective-correct at every pixel.
#[derive(Clone, Copy, Debug)]
pub(crate) struct ExactInterp {
    h: Hyper,
    d: Hyper,
}

impl Interp for ExactInterp {
    #[inline(always)]
    fn start(s: &TriSetup, x: i32, y: i32, _len: u32, _log2_n: u32) -> Self {
        ExactInterp {
            h: Hyper::at(s, x, y),
            d: Hyper::dx(s),
        }
    }
    #[inline(always)]
    fn frag(&self) -> Frag {
        self.h.resolve()
    }
    #[inline(always)]
    fn step(&mut self) {
        self.h.add(&self.d);
    }
    #[inline(always)]
    fn lambda(&self, s: &TriSetup) -> i32 {
        hyper_lambda(s, &self.h)
    }
}

/// `ceil(2^16 / n)` for `n` in `1..64`: slopes of short segments without a divide.
static INV_SMALL: [u32; 64] = {
    let mut t = [0u32; 64];
    let mut n = 1;
    while n < 64 {
        t[n] = 65536u32.div_ceil(n as u32);
        n += 1;
    }
    t
};

/// Perspective-correct every `2^log2_n` pixels, affine in between.
#[derive(Clone, Copy, Debug)]
pub(crate) struct SubdivInterp {
    cur: Frag,
    slope: Frag,
    end: Frag,
    next: Hyper,
    d: Hyper,
    in_seg: u32,
    left: u32,
    log2_n: u32,
    /// Interpolants at the current segment's first pixel (for the level of detail).
    seg_start: Hyper,
}

impl SubdivInterp {
    /// Sets up the segment from the current values to the exact values `seg` pixels on.
    #[inline(always)]
    fn segment(&mut self, seg: u32) {
        self.seg_start = self.next;
        // The span's last segment ends exactly on its last pixel (never outside the
        // triangle, where the hyperbola can be far from its chord); the others end on the
        // first pixel of the next segment.
        let reach = if self.left == seg && seg > 1 {
            seg - 1
        } else {
            seg
        };
        self.next.add_scaled(&self.d, reach as i32);
        self.end = self.next.resolve();
        let k = reach.min(63);
        let slope = |a: i32, b: i32| -> i32 {
            let diff = b.wrapping_sub(a);
            if reach == 1 << self.log2_n {
                diff >> self.log2_n
            } else {
                ((i64::from(diff) * i64::from(INV_SMALL[k as usize])) >> 16) as i32
            }
        };
        self.slope = Frag {
            u: slope(self.cur.u, self.end.u),
            v: slope(self.cur.v, self.end.v),
            c: [
                slope(self.cur.c[0], self.end.c[0]),
                slope(self.cur.c[1], self.end.c[1]),
                slope(self.cur.c[2], self.end.c[2]),
            ],
        };
        self.in_seg = seg;
        self.left -= seg;
    }
}

impl Interp for SubdivInterp {
    #[inline(always)]
    fn start(s: &TriSetup, x: i32, y: i32, len: u32, log2_n: u32) -> Self {
        let h = Hyper::at(s, x, y);
        let log2_n = log2_n.clamp(1, 6);
        let mut it = SubdivInterp {
            cur: h.resolve(),
            slope: Frag::default(),
            end: Frag::default(),
            next: h,
            d: Hyper::dx(s),
            in_seg: 0,
            left: len,
            log2_n,
            seg_start: h,
        };
        let seg = len.min(1 << log2_n);
        it.segment(seg);
        it
    }
    #[inline(always)]
    fn frag(&self) -> Frag {
        self.cur
    }
    #[inline(always)]
    fn lambda(&self, s: &TriSetup) -> i32 {
        hyper_lambda(s, &self.seg_start)
    }
    #[inline(always)]
    fn step(&mut self) {
        self.in_seg = self.in_seg.wrapping_sub(1);
        if self.in_seg == 0 {
            self.cur = self.end;
            if self.left > 0 {
                let seg = self.left.min(1 << self.log2_n);
                self.segment(seg);
            }
        } else {
            self.cur.u = self.cur.u.wrapping_add(self.slope.u);
            self.cur.v = self.cur.v.wrapping_add(self.slope.v);
            for k in 0..3 {
                self.cur.c[k] = self.cur.c[k].wrapping_add(self.slope.c[k]);
            }
        }
    }
}
