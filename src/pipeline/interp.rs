//! Span interpolators: how a shader's varyings advance along a span in each projection mode.
//!
//! * [`Linear`] (affine, `SUBDIVIDED = false`): adds per pixel, nothing else.
//! * [`ExactInterp`]: steps `s = u q`, `t = v q`, `q` (and colour times `q`) linearly and
//!   recovers `u = s / q` at every pixel through one table reciprocal and one 32x32->64
//!   multiply per attribute (hyperbolic interpolation, as in Blinn, "Hyperbolic Interpolation", IEEE CG&A 1992).
//! * [`Linear`] with `SUBDIVIDED = true`: exact at every `N`-th pixel and at the span end, affine in between;
//!   one reciprocal per `N` pixels. The slope of a short last segment uses a small
//!   reciprocal table instead of a divide.
//!
//! All three are inlined into the span loop, which is monomorphised per projection mode, so
//! a draw pays only for the one it uses.

use super::stages::ProjKind;
use super::tri_setup::TriSetup;
use crate::math::recip_q30::{mul_q16, recip_q30};
use crate::math::wide::mul_wide_signed;
use crate::shading::env::reflection_lambda;
use crate::shading::{Shader, Varyings};
use crate::texture::mip::{direction_lambda, lambda_q8};

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

/// [`add`] of the first `live` varyings only (a shader's
/// [`Shader::INTERPOLATED`](crate::shading::Shader::INTERPOLATED), a constant: with the
/// default, all of them, it is [`add`]); the others go stale.
#[inline(always)]
fn add_live<V: Varyings>(v: &mut V, d: &V, live: usize) {
    if live >= V::N {
        add(v, d);
    } else {
        for k in 0..live {
            if let (Some(a), Some(b)) = (v.as_mut_slice().get_mut(k), d.as_slice().get(k)) {
                *a = a.wrapping_add(*b);
            }
        }
    }
}

/// The second index of the pair [`lod_pair`] gives for a reflection: `(a, REFLECTION)`
/// names `n` at varyings `a..a + 3` and `v` at `a + 3..a + 6` ([`Shader::LOD_REFLECTION`]).
/// Past every varying, so code that reads the pair as texel coordinates reads 0 there.
pub(crate) const REFLECTION: usize = usize::MAX;

/// The varying pair whose level of detail the span loop computes for shader `S`: its
/// [`Shader::TEXCOORDS`] pair, `(a, a)` for a direction at varyings `a..a + 3`
/// ([`Shader::LOD_DIRECTION`]), or `(a, REFLECTION)` for a reflection of `n` and `v` from
/// varying `a` ([`Shader::LOD_REFLECTION`]). A pair of equal indices always names a
/// direction.
#[inline(always)]
pub(crate) fn lod_pair<S: Shader>() -> Option<(usize, usize)> {
    match (S::LOD_DIRECTION, S::LOD_REFLECTION) {
        (Some(a), _) => Some((a, a)),
        (None, Some(a)) => Some((a, REFLECTION)),
        (None, None) => S::TEXCOORDS,
    }
}

/// Three varyings from `a` (zero past the end).
#[inline(always)]
fn get3<V: Varyings>(v: &V, a: usize) -> [i32; 3] {
    [get(v, a), get(v, a + 1), get(v, a + 2)]
}

/// [`reflection_lambda`] of `n`, `v` at varyings `a..a + 6` of `at` (values or perspective
/// numerators) with the set-up's steps `dx`, `dy` of the same.
#[inline(always)]
fn reflection_at<V: Varyings>(at: &V, dx: &V, dy: &V, a: usize) -> i32 {
    let b = a.wrapping_add(3);
    reflection_lambda(
        get3(at, a),
        get3(at, b),
        [get3(dx, a), get3(dx, b)],
        [get3(dy, a), get3(dy, b)],
    )
}

/// `lambda` of an affine mapping: constant derivatives, straight from the planes. A
/// direction (`a == b`) also needs its value at the pixel, `at()`.
#[inline(always)]
pub(crate) fn affine_lambda<V: Varyings>(
    s: &TriSetup<V>,
    at: impl FnOnce() -> V,
    a: usize,
    b: usize,
) -> i32 {
    if a == b {
        return direction_lambda(get3(&at(), a), get3(&s.dx, a), get3(&s.dy, a));
    }
    if b == REFLECTION {
        return reflection_at(&at(), &s.dx, &s.dy, a);
    }
    lambda_q8(get(&s.dx, a), get(&s.dx, b), get(&s.dy, a), get(&s.dy, b))
}

/// `lambda` of a perspective mapping at a pixel with interpolants `h`: the derivative of
/// `u = s / q` along x is `(s_x - u q_x) / q` (and likewise along y and for `v`). For a
/// direction (`a == b`) the numerators `d q` are themselves the direction and linear in
/// screen space, so [`direction_lambda`] takes them and their planes' steps as they are.
#[inline(always)]
pub(super) fn hyper_lambda<V: Varyings>(s: &TriSetup<V>, h: &Hyper<V>, a: usize, b: usize) -> i32 {
    if a == b {
        return direction_lambda(get3(&h.s, a), get3(&s.dx, a), get3(&s.dy, a));
    }
    if b == REFLECTION {
        return reflection_at(&h.s, &s.dx, &s.dy, a);
    }
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
        affine_lambda(s, || s.at(x, y), a, b)
    } else {
        hyper_lambda(s, &Hyper::at(s, x, y), a, b)
    }
}

/// The perspective interpolants: varyings times `q`, and `q`.
#[derive(Clone, Copy, Debug)]
pub(super) struct Hyper<V> {
    s: V,
    q: i32,
}

impl<V: Varyings> Hyper<V> {
    #[inline(always)]
    pub(super) fn at(s: &TriSetup<V>, x: i32, y: i32) -> Self {
        Hyper {
            s: s.at(x, y),
            q: s.plane_at(&s.q, x, y),
        }
    }
    #[inline(always)]
    pub(super) fn dx(s: &TriSetup<V>) -> Self {
        Hyper { s: s.dx, q: s.q.dx }
    }
    #[inline(always)]
    pub(super) fn add_scaled(&mut self, d: &Hyper<V>, n: i32) {
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
    /// [`Hyper::add`] of `q` and the first `live` varyings only (the others go stale).
    #[inline(always)]
    fn add_live(&mut self, d: &Hyper<V>, live: usize) {
        add_live(&mut self.s, &d.s, live);
        self.q = self.q.wrapping_add(d.q);
    }
    /// [`Hyper::resolve`] of the first `live` varyings into `out` (the others untouched).
    #[inline(always)]
    fn resolve_live(&self, out: &mut V, live: usize) {
        let r = recip_q30(self.q);
        for k in 0..V::N.min(live) {
            out.as_mut_slice()[k] = mul_q16(self.s.as_slice()[k], r);
        }
    }
    /// The varyings: `s / q`.
    #[inline(always)]
    pub(super) fn resolve(&self) -> V {
        let r = recip_q30(self.q);
        let mut out = self.s;
        for k in 0..V::N {
            out.as_mut_slice()[k] = mul_q16(self.s.as_slice()[k], r);
        }
        out
    }
}

/// Where the span loop wants varyings and levels of detail filled.
#[derive(Clone, Copy, Debug)]
pub(crate) struct FillSpec {
    /// The texture-coordinate pair, when the shader has one ([`lod_pair`]: equal indices
    /// name a direction).
    pub pair: (usize, usize),
    /// Fill a level of detail per pixel (per segment for the linear modes).
    pub lod: bool,
    /// Left shift to undo on the pair (wrapping), see `Shader::coord_shift`.
    pub shift: u32,
    /// The varyings the shader reads ([`Shader::INTERPOLATED`](crate::shading::Shader::INTERPOLATED)):
    /// the exact and linear fills step only the first `live` (the others are left stale).
    pub live: usize,
}

/// Interpolation along one span, a chunk of pixels at a time.
pub(crate) trait Fill<V: Varyings> {
    /// Starts at pixel `(x, y)` for a span of `len` pixels.
    fn start(s: &TriSetup<V>, x: i32, y: i32, len: u32, log2_n: u32) -> Self;
    /// [`start`](Self::start) for projection `kind` (the run-time interpolator picks its
    /// mode from it; the others have one mode and ignore it).
    #[inline(always)]
    fn start_as(s: &TriSetup<V>, x: i32, y: i32, len: u32, log2_n: u32, kind: ProjKind) -> Self
    where
        Self: Sized,
    {
        let _ = kind;
        Self::start(s, x, y, len, log2_n)
    }
    /// Level of detail (Q8.8, before bias) of `pair` at the next pixel.
    fn lambda(&self, s: &TriSetup<V>, pair: (usize, usize)) -> i32;
    /// Writes the varyings of the next `vals.len()` pixels into `vals` (and, with
    /// `spec.lod`, their levels of detail into `lambdas`) and moves past them. Entries whose
    /// bit in `mask` is clear may be left stale: the exact mode skips their reciprocal.
    fn fill(
        &mut self,
        s: &TriSetup<V>,
        vals: &mut [V],
        lambdas: &mut [i32],
        mask: u32,
        spec: FillSpec,
    );
}

/// Shifts the pair `(a, b)` of `v` left by `k`, wrapping.
#[inline(always)]
pub(crate) fn unshift<V: Varyings>(v: &mut V, (a, b): (usize, usize), k: u32) {
    for i in [a, b] {
        if let Some(x) = v.as_mut_slice().get_mut(i) {
            *x = x.wrapping_shl(k);
        }
    }
}

/// Perspective-correct at every pixel.
#[derive(Clone, Copy, Debug)]
pub(crate) struct ExactInterp<V> {
    h: Hyper<V>,
    d: Hyper<V>,
}

impl<V: Varyings> Fill<V> for ExactInterp<V> {
    #[inline(always)]
    fn start(s: &TriSetup<V>, x: i32, y: i32, _len: u32, _log2_n: u32) -> Self {
        ExactInterp {
            h: Hyper::at(s, x, y),
            d: Hyper::dx(s),
        }
    }
    #[inline(always)]
    fn lambda(&self, s: &TriSetup<V>, (a, b): (usize, usize)) -> i32 {
        hyper_lambda(s, &self.h, a, b)
    }
    #[inline(always)]
    fn fill(
        &mut self,
        s: &TriSetup<V>,
        vals: &mut [V],
        lambdas: &mut [i32],
        mask: u32,
        spec: FillSpec,
    ) {
        let mut m = mask;
        for (k, v) in vals.iter_mut().enumerate() {
            if m & 1 != 0 {
                if spec.live >= V::N {
                    *v = self.h.resolve();
                } else {
                    self.h.resolve_live(v, spec.live);
                }
                if spec.shift != 0 {
                    unshift(v, spec.pair, spec.shift);
                }
                if spec.lod {
                    if let Some(l) = lambdas.get_mut(k) {
                        *l = hyper_lambda(s, &self.h, spec.pair.0, spec.pair.1);
                    }
                }
            }
            m >>= 1;
            if spec.live >= V::N {
                self.h.add(&self.d);
            } else {
                self.h.add_live(&self.d, spec.live);
            }
        }
    }
}

/// The change per pixel from `from` to `to`, per varying: `per` applied to `to - from`
/// (wrapping).
#[inline(always)]
fn chord_slope<V: Varyings>(from: &V, to: &V, per: impl Fn(i32) -> i32) -> V {
    let mut slope = *to;
    for i in 0..V::N {
        slope.as_mut_slice()[i] = per(to.as_slice()[i].wrapping_sub(from.as_slice()[i]));
    }
    slope
}

/// Undoes the coordinate shift on a linear piece's start and slope:
/// `(a + i d) << k = (a << k) + i (d << k)` modulo 2^32, so once per piece.
#[inline(always)]
pub(super) fn unshift_piece<V: Varyings>(start: &mut V, slope: &mut V, spec: FillSpec) {
    if spec.shift != 0 {
        unshift(start, spec.pair, spec.shift);
        unshift(slope, spec.pair, spec.shift);
    }
}

/// `ceil(2^16 / n)` for `n` in `1..64`: slopes of short segments without a divide.
pub(super) static INV_SMALL: [u32; 64] = {
    let mut t = [0u32; 64];
    let mut n = 1;
    while n < 64 {
        t[n] = 65536u32.div_ceil(n as u32);
        n += 1;
    }
    t
};

/// `diff * inv / 2^16` (floor) for `inv < 2^17`: on ARMv6-M a 32 x 32-bit product instead of
/// the `__aeabi_lmul` call of an `i64` product; elsewhere the `i64` product (which is
/// cheaper on Cortex-M4F than the signed 32-bit form).
#[inline(always)]
pub(super) fn scale_q16(diff: i32, inv: u32) -> i32 {
    #[cfg(all(target_arch = "arm", not(target_has_atomic = "32")))]
    {
        (mul_wide_signed(diff, inv as i32) >> 16) as i32
    }
    #[cfg(not(all(target_arch = "arm", not(target_has_atomic = "32"))))]
    {
        ((i64::from(diff) * i64::from(inv)) >> 16) as i32
    }
}

/// [`scale_q16`] for the one-piece spans of [`Linear::only_piece`]: on ARMv6-M two 32-bit
/// products ([`scale_q16_split`]; about 6 % fewer instructions per pixel on the sphere,
/// whose spans are all one piece, but about 1 % more on the cube's fill loop, which keeps
/// the wide form; measure with `cargo xtask mcu`), elsewhere [`scale_q16`].
#[inline(always)]
fn scale_q16_short(diff: i32, inv: u32) -> i32 {
    #[cfg(all(target_arch = "arm", not(target_has_atomic = "32")))]
    {
        scale_q16_split(diff, inv)
    }
    #[cfg(not(all(target_arch = "arm", not(target_has_atomic = "32"))))]
    {
        scale_q16(diff, inv)
    }
}

/// [`scale_q16`] from two 32-bit products, exactly: with `diff = dh 2^16 + dl`
/// (`0 <= dl < 2^16`), `floor(diff inv / 2^16) = dh inv + floor(dl inv / 2^16)`, and for
/// `inv <= 2^15` (every segment of two or more pixels) both products fit 32 bits; a longer
/// reach's `inv = 2^16` (one pixel) is `diff` itself. Compiled everywhere so every target
/// tests it.
#[cfg_attr(
    not(all(target_arch = "arm", not(target_has_atomic = "32"))),
    allow(dead_code)
)]
#[inline(always)]
fn scale_q16_split(diff: i32, inv: u32) -> i32 {
    if inv <= 1 << 15 {
        let (dh, dl) = (diff >> 16, (diff & 0xFFFF) as u32);
        dh.wrapping_mul(inv as i32)
            .wrapping_add(((dl * inv) >> 16) as i32)
    } else if inv == 1 << 16 {
        diff
    } else {
        (mul_wide_signed(diff, inv as i32) >> 16) as i32
    }
}

/// Linear interpolation in segments: affine (one segment per span) or subdivided (exact
/// every `2^log2_n` pixels and at the span's last pixel, linear in between; one reciprocal
/// per segment).
#[derive(Clone, Copy, Debug)]
pub(crate) struct Linear<V, const SUBDIVIDED: bool> {
    /// Values at the next pixel and their change per pixel.
    cur: V,
    slope: V,
    /// Pixels left in the current segment.
    in_seg: u32,
    /// Pixels of the span after the current segment.
    left: u32,
    /// Level of detail of the current segment (subdivided: at its first pixel).
    seg_lambda: i32,
    /// Subdivided: exact values at the next segment's first pixel and the perspective
    /// interpolants there.
    exact: V,
    next: Hyper<V>,
    d: Hyper<V>,
    log2_n: u32,
    /// Affine: whether the coordinate shift has been undone on the span's segment.
    shifted: bool,
}

impl<V: Varyings, const SUBDIVIDED: bool> Linear<V, SUBDIVIDED> {
    /// Starts the next segment of the span (subdivided only: the affine span is one
    /// segment from the start). The segment runs from the current exact values to the exact
    /// values `seg` pixels on.
    #[inline(always)]
    fn segment(&mut self, s: &TriSetup<V>, spec: FillSpec) {
        let seg = self.left.min(1 << self.log2_n);
        if spec.lod {
            self.seg_lambda = hyper_lambda(s, &self.next, spec.pair.0, spec.pair.1);
        }
        // The span's last segment ends exactly on its last pixel (never outside the
        // triangle, where the hyperbola can be far from its chord); the others end on the
        // first pixel of the next segment.
        let reach = if self.left == seg && seg > 1 {
            seg - 1
        } else {
            seg
        };
        self.next.add_scaled(&self.d, reach as i32);
        let end = self.next.resolve();
        let k = reach.min(63);
        let whole = reach == 1 << self.log2_n;
        let slope = chord_slope(&self.exact, &end, |diff| {
            if whole {
                diff >> self.log2_n
            } else {
                scale_q16(diff, INV_SMALL[k as usize])
            }
        });
        self.cur = self.exact;
        self.slope = slope;
        unshift_piece(&mut self.cur, &mut self.slope, spec);
        self.exact = end;
        self.in_seg = seg;
        self.left -= seg;
    }
}

/// One linear piece of a span: values at its first pixel, their change per pixel, its
/// length, and its level of detail (when asked for).
#[derive(Clone, Copy, Debug)]
pub(crate) struct Piece<V> {
    pub start: V,
    pub slope: V,
    pub len: usize,
    pub lambda: i32,
}

impl<V: Varyings, const SUBDIVIDED: bool> Linear<V, SUBDIVIDED> {
    /// Starts at pixel `(x, y)` for a span of `len` pixels.
    #[inline(always)]
    pub fn start(s: &TriSetup<V>, x: i32, y: i32, len: u32, log2_n: u32) -> Self {
        if SUBDIVIDED {
            let h = Hyper::at(s, x, y);
            Linear {
                cur: V::zero(),
                slope: V::zero(),
                in_seg: 0,
                left: len,
                seg_lambda: 0,
                exact: h.resolve(),
                next: h,
                d: Hyper::dx(s),
                log2_n: log2_n.clamp(1, 6),
                shifted: true,
            }
        } else {
            Linear {
                cur: s.at(x, y),
                slope: s.dx,
                in_seg: len,
                left: 0,
                seg_lambda: 0,
                exact: V::zero(),
                next: Hyper { s: V::zero(), q: 0 },
                d: Hyper { s: V::zero(), q: 0 },
                log2_n: 0,
                shifted: false,
            }
        }
    }

    /// The only piece of a span of `len` pixels starting at `(x, y)` that is one segment
    /// (`len` in `1..=2^log2_n` when subdivided): the piece [`start`](Self::start) then
    /// [`piece`](Self::piece) give, bit for bit, without the iterator's state. `lambda` is
    /// the level of detail at the first pixel when `spec.lod`, else 0.
    #[inline(always)]
    pub fn only_piece(s: &TriSetup<V>, x: i32, y: i32, len: u32, spec: FillSpec) -> Piece<V> {
        let (a, b) = spec.pair;
        let (mut start, mut slope, lambda) = if SUBDIVIDED {
            let h = Hyper::at(s, x, y);
            let lambda = if spec.lod {
                hyper_lambda(s, &h, a, b)
            } else {
                0
            };
            let first = h.resolve();
            if len <= 1 {
                // One pixel: its value is all the span needs (the slope is never stepped
                // into a pixel), so no second reciprocal. About one span in five of a finely
                // tessellated mesh. (A return of its own: folded into the slope below as a
                // branch, it costs the M4F sphere about one instruction per pixel more.)
                let mut start = first;
                let mut slope = V::zero();
                unshift_piece(&mut start, &mut slope, spec);
                return Piece {
                    start,
                    slope,
                    len: len as usize,
                    lambda,
                };
            }
            // As `segment`: the last segment ends on the span's last pixel.
            let reach = len - 1;
            let mut next = h;
            next.add_scaled(&Hyper::dx(s), reach as i32);
            let end = next.resolve();
            let inv = INV_SMALL[reach.min(63) as usize];
            let slope = chord_slope(&first, &end, |diff| scale_q16_short(diff, inv));
            (first, slope, lambda)
        } else {
            let lambda = if spec.lod {
                affine_lambda(s, || s.at(x, y), a, b)
            } else {
                0
            };
            (s.at(x, y), s.dx, lambda)
        };
        unshift_piece(&mut start, &mut slope, spec);
        Piece {
            start,
            slope,
            len: len as usize,
            lambda,
        }
    }

    /// Level of detail (Q8.8, before bias) of `pair` at the next pixel.
    #[inline(always)]
    pub fn lambda(&self, s: &TriSetup<V>, (a, b): (usize, usize)) -> i32 {
        if SUBDIVIDED {
            hyper_lambda(s, &self.next, a, b)
        } else {
            affine_lambda(s, || self.cur, a, b)
        }
    }

    /// The next linear piece, at most `max` pixels long, or `None` at the end of the span.
    #[inline(always)]
    pub fn piece(&mut self, s: &TriSetup<V>, max: usize, spec: FillSpec) -> Option<Piece<V>> {
        if !SUBDIVIDED && !self.shifted {
            // The affine span's only segment: undo the coordinate shift once, and take its
            // (constant) level of detail.
            self.shifted = true;
            unshift_piece(&mut self.cur, &mut self.slope, spec);
            if spec.lod {
                let cur = self.cur;
                self.seg_lambda = affine_lambda(s, || cur, spec.pair.0, spec.pair.1);
            }
        }
        if self.in_seg == 0 {
            if !SUBDIVIDED || self.left == 0 {
                return None;
            }
            self.segment(s, spec);
        }
        let len = (self.in_seg as usize).min(max);
        let p = Piece {
            start: self.cur,
            slope: self.slope,
            len,
            lambda: self.seg_lambda,
        };
        for i in 0..V::N {
            let d = self.slope.as_slice()[i].wrapping_mul(len as i32);
            self.cur.as_mut_slice()[i] = self.cur.as_slice()[i].wrapping_add(d);
        }
        self.in_seg -= len as u32;
        Some(p)
    }
}

impl<V: Varyings, const SUBDIVIDED: bool> Fill<V> for Linear<V, SUBDIVIDED> {
    #[inline(always)]
    fn start(s: &TriSetup<V>, x: i32, y: i32, len: u32, log2_n: u32) -> Self {
        Linear::start(s, x, y, len, log2_n)
    }
    #[inline(always)]
    fn lambda(&self, s: &TriSetup<V>, pair: (usize, usize)) -> i32 {
        Linear::lambda(self, s, pair)
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
            let Some(p) = self.piece(s, vals.len() - off, spec) else {
                break;
            };
            let end = (off + p.len).min(vals.len());
            let mut v = p.start;
            if let Some(vs) = vals.get_mut(off..end) {
                for x in vs.iter_mut() {
                    // The interpolated values only (see `Quadratic::fill`).
                    for k in 0..V::N {
                        x.as_mut_slice()[k] = v.as_slice()[k];
                    }
                    step_live(&mut v, &p.slope, spec.live);
                }
            }
            if spec.lod {
                if let Some(ls) = lambdas.get_mut(off..end) {
                    ls.fill(p.lambda);
                }
            }
            off = end;
        }
    }
}

/// `v += d` for the first `live` varyings, wrapping (see [`add_live`]): a span loop's step
/// from one pixel to the next.
#[inline(always)]
pub(crate) fn step_live<V: Varyings>(v: &mut V, d: &V, live: usize) {
    add_live(v, d, live);
}

#[cfg(test)]
mod tests {
    use super::{scale_q16_split, INV_SMALL};
    use crate::test_rng::Rng;

    /// The two-product form equals the 64-bit product for every segment length and for
    /// differences over the whole `i32` range.
    #[test]
    fn scale_split_matches_wide_product() {
        let mut rng = Rng(0x1234_5678_9ABC_DEF1);
        let wide = |d: i32, inv: u32| ((i64::from(d) * i64::from(inv)) >> 16) as i32;
        for &inv in &INV_SMALL[1..] {
            for d in [0, 1, -1, 0xFFFF, -0x10000, i32::MAX, i32::MIN, 0x7FFF_0000] {
                assert_eq!(scale_q16_split(d, inv), wide(d, inv), "d {d} inv {inv}");
            }
            for _ in 0..20_000 {
                let d = rng.next() as i32 >> (rng.next() % 24);
                assert_eq!(scale_q16_split(d, inv), wide(d, inv), "d {d} inv {inv}");
            }
        }
    }
}
