//! Span interpolators: how a shader's varyings advance along a span in each projection mode.
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
use crate::shading::Varyings;
use crate::texture::mip::lambda_q8;

/// Interpolation of the varyings `V` along one span.
pub(crate) trait Interp<V: Varyings> {
    /// Starts at pixel `(x, y)` for a span of `len` pixels.
    fn start(s: &TriSetup<V>, x: i32, y: i32, len: u32, log2_n: u32) -> Self;
    /// Values at the current pixel.
    fn frag(&self) -> V;
    /// Moves one pixel right.
    fn step(&mut self);
    /// Level of detail `lambda` (Q8.8, before bias) of the varying pair `(a, b)` at the
    /// current pixel.
    fn lambda(&self, s: &TriSetup<V>, a: usize, b: usize) -> i32;
}

#[inline(always)]
fn get<V: Varyings>(v: &V, k: usize) -> i32 {
    v.as_slice().get(k).copied().unwrap_or(0)
}

/// `v += d` per varying, wrapping.
#[inline(always)]
fn add<V: Varyings>(v: &mut V, d: &V) {
    for k in 0..V::N {
        v.as_mut_slice()[k] = v.as_slice()[k].wrapping_add(d.as_slice()[k]);
    }
}

/// `lambda` of an affine mapping: constant derivatives, straight from the planes.
#[inline(always)]
pub(crate) fn affine_lambda<V: Varyings>(s: &TriSetup<V>, a: usize, b: usize) -> i32 {
    lambda_q8(get(&s.dx, a), get(&s.dx, b), get(&s.dy, a), get(&s.dy, b))
}

/// `lambda` of a perspective mapping at a pixel with interpolants `h`: the derivative of
/// `u = s / q` along x is `(s_x - u q_x) / q` (and likewise along y and for `v`).
#[inline(always)]
fn hyper_lambda<V: Varyings>(s: &TriSetup<V>, h: &Hyper<V>, a: usize, b: usize) -> i32 {
    let r32 = recip_q30(h.q);
    let r = i64::from(r32);
    let m = |x: i32| mul_q16(x, r32);
    let (u, v) = (m(get(&h.s, a)), m(get(&h.s, b)));
    let d = |sd: i32, qd: i32, a: i32| -> i32 {
        let t = i64::from(sd) - ((i64::from(a) * i64::from(qd)) >> 30);
        (t.saturating_mul(r) >> 16).clamp(i64::from(i32::MIN), i64::from(i32::MAX)) as i32
    };
    let (ux, vx) = (d(get(&s.dx, a), s.q.dx, u), d(get(&s.dx, b), s.q.dx, v));
    let (uy, vy) = (d(get(&s.dy, a), s.q.dy, u), d(get(&s.dy, b), s.q.dy, v));
    lambda_q8(ux, vx, uy, vy)
}

/// `lambda` of the pair `(a, b)` at pixel `(x, y)`, whichever the set-up's planes are (for
/// per-triangle level of detail).
pub(crate) fn lambda_at<V: Varyings>(s: &TriSetup<V>, x: i32, y: i32, a: usize, b: usize) -> i32 {
    if s.affine {
        affine_lambda(s, a, b)
    } else {
        hyper_lambda(s, &Hyper::at(s, x, y), a, b)
    }
}

/// Screen-linear interpolation.
#[derive(Clone, Copy, Debug)]
pub(crate) struct AffineInterp<V> {
    f: V,
    d: V,
}

impl<V: Varyings> Interp<V> for AffineInterp<V> {
    #[inline(always)]
    fn start(s: &TriSetup<V>, x: i32, y: i32, _len: u32, _log2_n: u32) -> Self {
        AffineInterp {
            f: s.at(x, y),
            d: s.dx,
        }
    }
    #[inline(always)]
    fn frag(&self) -> V {
        self.f
    }
    #[inline(always)]
    fn lambda(&self, s: &TriSetup<V>, a: usize, b: usize) -> i32 {
        affine_lambda(s, a, b)
    }
    #[inline(always)]
    fn step(&mut self) {
        add(&mut self.f, &self.d);
    }
}

/// The perspective interpolants: varyings times `q`, and `q`.
#[derive(Clone, Copy, Debug)]
struct Hyper<V> {
    s: V,
    q: i32,
}

impl<V: Varyings> Hyper<V> {
    #[inline(always)]
    fn at(s: &TriSetup<V>, x: i32, y: i32) -> Self {
        Hyper {
            s: s.at(x, y),
            q: s.plane_at(&s.q, x, y),
        }
    }
    #[inline(always)]
    fn dx(s: &TriSetup<V>) -> Self {
        Hyper { s: s.dx, q: s.q.dx }
    }
    #[inline(always)]
    fn add_scaled(&mut self, d: &Hyper<V>, n: i32) {
        for k in 0..V::N {
            self.s.as_mut_slice()[k] =
                self.s.as_slice()[k].wrapping_add(d.s.as_slice()[k].wrapping_mul(n));
        }
        self.q = self.q.wrapping_add(d.q.wrapping_mul(n));
    }
    #[inline(always)]
    fn add(&mut self, d: &Hyper<V>) {
        add(&mut self.s, &d.s);
        self.q = self.q.wrapping_add(d.q);
    }
    /// The varyings: `s / q`.
    #[inline(always)]
    fn resolve(&self) -> V {
        let r = recip_q30(self.q);
        let mut out = self.s;
        for k in 0..V::N {
            out.as_mut_slice()[k] = mul_q16(self.s.as_slice()[k], r);
        }
        out
    }
}

/// Perspective-correct at every pixel.
#[derive(Clone, Copy, Debug)]
pub(crate) struct ExactInterp<V> {
    h: Hyper<V>,
    d: Hyper<V>,
}

impl<V: Varyings> Interp<V> for ExactInterp<V> {
    #[inline(always)]
    fn start(s: &TriSetup<V>, x: i32, y: i32, _len: u32, _log2_n: u32) -> Self {
        ExactInterp {
            h: Hyper::at(s, x, y),
            d: Hyper::dx(s),
        }
    }
    #[inline(always)]
    fn frag(&self) -> V {
        self.h.resolve()
    }
    #[inline(always)]
    fn step(&mut self) {
        self.h.add(&self.d);
    }
    #[inline(always)]
    fn lambda(&self, s: &TriSetup<V>, a: usize, b: usize) -> i32 {
        hyper_lambda(s, &self.h, a, b)
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
pub(crate) struct SubdivInterp<V> {
    cur: V,
    slope: V,
    end: V,
    next: Hyper<V>,
    d: Hyper<V>,
    in_seg: u32,
    left: u32,
    log2_n: u32,
    /// Interpolants at the current segment's first pixel (for the level of detail).
    seg_start: Hyper<V>,
}

impl<V: Varyings> SubdivInterp<V> {
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
        for i in 0..V::N {
            let diff = self.end.as_slice()[i].wrapping_sub(self.cur.as_slice()[i]);
            self.slope.as_mut_slice()[i] = if reach == 1 << self.log2_n {
                diff >> self.log2_n
            } else {
                ((i64::from(diff) * i64::from(INV_SMALL[k as usize])) >> 16) as i32
            };
        }
        self.in_seg = seg;
        self.left -= seg;
    }
}

impl<V: Varyings> Interp<V> for SubdivInterp<V> {
    #[inline(always)]
    fn start(s: &TriSetup<V>, x: i32, y: i32, len: u32, log2_n: u32) -> Self {
        let h = Hyper::at(s, x, y);
        let log2_n = log2_n.clamp(1, 6);
        let mut it = SubdivInterp {
            cur: h.resolve(),
            slope: V::zero(),
            end: V::zero(),
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
    fn frag(&self) -> V {
        self.cur
    }
    #[inline(always)]
    fn lambda(&self, s: &TriSetup<V>, a: usize, b: usize) -> i32 {
        hyper_lambda(s, &self.seg_start, a, b)
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
            add(&mut self.cur, &self.slope);
        }
    }
}
