//! One screen triangle through a shader: the shader's per-triangle hook, the set-up, the
//! edge walker, and the span loop for each span it emits.
//!
//! Shared by the classic [`Draw`](super::Draw) (built-in shaders fed the classic varyings)
//! and the open [`ShadedDraw`](super::ShadedDraw) (any shader). Generic over the shader,
//! projection, depth stage, target colour and varying count: each draw type a firmware
//! uses links exactly one copy.

use super::in_range::{Proven, RangeProof, Unproven};
use super::interp::{lambda_at, lod_pair};
use super::setup::{centroid, setup, setup_inline};
use super::setup_cache::{Resume, SetupSlot};
use super::span::{inline_short_path, span, span_short, DepthBound, Scratch, SpanCtx};
use super::stages::{DepthStage, ProjKind, Projection, ProjectionStage};
use super::target::{RenderTarget, Rows};
use super::tri_setup::TriSetup;
use crate::color::TargetColor;
use crate::geometry::{ScreenTriangle, Viewport};
use crate::raster::{rasterize_rows, rasterize_shared, Rect, SpanSink, SUBPIXEL_BITS};
use crate::shading::{Shader, Varyings};
use crate::texture::LodGranularity;

/// The per-draw numbers the rasterization of one triangle needs.
#[derive(Clone, Copy, Debug)]
pub(crate) struct RasterParams {
    pub viewport: Rect,
    /// Subdivision length, log2 (for [`Projection::Subdivided`]).
    pub log2_n: u32,
    /// Adaptive budget in I16F16 texel units.
    pub budget: i64,
    /// The run-time depth switch.
    pub depth_on: bool,
    /// The projection (for the run-time projection marker).
    pub kind: ProjKind,
}

impl RasterParams {
    pub fn new(viewport: &Viewport, projection: Projection, depth_on: bool) -> Self {
        RasterParams {
            viewport: viewport.rect(),
            log2_n: match projection {
                Projection::Subdivided { log2_n } | Projection::Quadratic { log2_n } => {
                    u32::from(log2_n)
                }
                _ => 4,
            },
            budget: match projection {
                // Q8 texels to the I16F16 texel units of the set-up.
                Projection::Adaptive { budget } => i64::from(budget) << 8,
                _ => 0,
            },
            depth_on,
            kind: match projection {
                Projection::Affine => ProjKind::Affine,
                Projection::Subdivided { .. } => ProjKind::Subdivided,
                Projection::Quadratic { .. } => ProjKind::Quadratic,
                Projection::Exact => ProjKind::Exact,
                Projection::Adaptive { .. } => ProjKind::Adaptive,
            },
        }
    }
}

/// Whether a kept triangle a band resumes is drawn by a raster of its own (a second inlined
/// copy of [`draw_set_up`]) rather than through the join with a fresh triangle's, where
/// the loaded set-up is copied once more. On Cortex-M4F that saves about 1.4 instructions
/// per pixel of the sphere in bands (`sphere_sized` in `cargo xtask mcu`) for about 3 KB of
/// flash; on Cortex-M0+ it costs about 2.8 (and 90 bytes of stack), on RV32IMC it is
/// about even, so there the join stays.
const SPLIT_RESUME: bool = cfg!(all(target_arch = "arm", target_has_atomic = "32"));

/// `K`: what is known of the triangle's range ([`RangeProof`]): its short spans run
/// `K::Short<S>`, its other spans `S`.
struct Writer<'t, S: Shader, P, D, C, K: RangeProof> {
    ctx: SpanCtx<'t, K::Short<S>>,
    scratch: Option<Scratch<S::Varyings>>,
    /// The target's depth floor, read once per triangle: a triangle writes each pixel at
    /// most once, so its own writes never matter to its later spans. Lowered once, after.
    bound: DepthBound,
    /// The target's rows, lent for the triangle.
    rows: Rows<'t, C>,
    pixels: u32,
    _stages: core::marker::PhantomData<(P, D, K)>,
}

/// The body of the writer's span functions: the span `$x0..$x1` of row `$y` sliced out of
/// the target's buffers (the rasterizer clipped the span to the target: the slicing checks
/// alone) and drawn, then `$drawn` with the pixels written bound to `$n`; `$none` when the
/// slicing refuses it. One body, two functions ([`COUNT_IN_LOOP`](crate::raster::COUNT_IN_LOOP)
/// picks which one the row loop calls): as a shared inlined method, the Cortex-M0+ span
/// writer allocates its registers worse (about 1 % more on the whole-frame sphere).
macro_rules! draw_span {
    ($w:ident, $y:ident, $x0:ident, $x1:ident, |$n:ident| $drawn:expr, $none:expr) => {
        if let Some((out, mut depth)) = $w.rows.span_in_clip($y, $x0, $x1) {
            // The short path inlined here; every other span through `span`, out of line.
            let short = span_short::<K::Short<S>, P, D, C>(
                &$w.ctx,
                &mut $w.bound,
                $y,
                $x0,
                out,
                depth.as_deref_mut(),
                K::AFFINE,
            );
            let $n = match short {
                Some(n) => n,
                None => K::with_plain(&$w.ctx, |ctx| {
                    span::<S, P, D, C>(ctx, &mut $w.bound, &mut $w.scratch, $y, $x0, out, depth)
                }),
            };
            $drawn
        } else {
            $none
        }
    };
}

impl<S: Shader, P: ProjectionStage, D: DepthStage, C: TargetColor, K: RangeProof> SpanSink
    for Writer<'_, S, P, D, C, K>
{
    // Not inlined into the rasterizer's row loop: one copy per draw type (inlined there, each
    // draw type's `raster_triangle` carries the edge walk and the short path again: about
    // 10 KB more for `Draw::dynamic` on Cortex-M4F).
    #[inline(never)]
    fn span(&mut self, y: i32, x0: i32, x1: i32) {
        draw_span!(
            self,
            y,
            x0,
            x1,
            |n| self.pixels = self.pixels.wrapping_add(n),
            ()
        )
    }

    /// [`span`](SpanSink::span) returning the pixels written, which the row loop sums in a
    /// register where it calls this ([`COUNT_IN_LOOP`](crate::raster::COUNT_IN_LOOP)).
    #[inline(never)]
    fn span_counted(&mut self, y: i32, x0: i32, x1: i32) -> u32 {
        draw_span!(self, y, x0, x1, |n| n, 0)
    }
}

/// Rasterizes `tri` with `shader` into `target`; `varyings` maps a vertex's varyings to the
/// shader's. Returns the pixels written.
///
/// Without `tri`, draws the triangle a band renderer kept in `slot` (a
/// [`KeptSetup::resumable`](super::KeptSetup) entry, see
/// [`setup_cache`](super::setup_cache)): the same pixels as with its screen triangle, from
/// the entry alone. A `slot` that holds a set-up also receives what resuming needs.
pub(crate) fn raster_shaded<S, P, D, C, const N: usize>(
    shader: &S,
    tri: Option<&ScreenTriangle<N>>,
    varyings: impl Fn(&[i32; N]) -> S::Varyings,
    params: &RasterParams,
    target: &mut dyn RenderTarget<Color = C>,
    mut slot: SetupSlot<'_>,
) -> u32
where
    S: Shader,
    P: ProjectionStage,
    D: DepthStage,
    C: TargetColor,
{
    // A typed draw's depth stage is its mode: only the run-time projection's draws switch
    // the test off at run time (the span loops read the switch for those alone).
    debug_assert!(P::KIND == ProjKind::Dynamic || !D::TEST || params.depth_on);
    let vp = params.viewport;
    let kind = match P::KIND {
        ProjKind::Dynamic => params.kind,
        k => k,
    };
    // Kept where the call writes it and lent to the span loop (see `setup`, which also takes
    // it from, or keeps it in, a band renderer's cache: `slot`).
    let built;
    let rest;
    match tri {
        // A kept triangle, drawn from its entry: on ARMv7-M straight from what it loads
        // (see `SPLIT_RESUME`), elsewhere through the join below.
        None if SPLIT_RESUME => {
            let Some(entry) = slot else {
                return 0;
            };
            let (Some(setup), Some(rest)) = (entry.load::<S::Varyings>(), entry.resume::<S>())
            else {
                return 0;
            };
            return draw_set_up::<S, P, D, C>(shader, &setup, &rest, kind, params, target);
        }
        None => {
            let Some(entry) = slot else {
                return 0;
            };
            built = entry.load::<S::Varyings>();
            rest = match entry.resume::<S>() {
                Some(r) => r,
                None => return 0,
            };
        }
        Some(tri) => {
            let mut vary = [
                varyings(&tri[0].varyings),
                varyings(&tri[1].varyings),
                varyings(&tri[2].varyings),
            ];
            let triangle = shader.triangle(&mut vary);
            let pos = tri.map(|v| {
                let (x, y) = v.attr_position();
                (x, y, v.z, v.w)
            });
            // Inlined into the mesh draws (see `setup_inline`), shared by the others.
            macro_rules! set_up {
                ($f:ident) => {
                    $f(
                        pos,
                        &vary,
                        vp,
                        kind,
                        D::TEST,
                        S::TEXCOORDS,
                        params.budget,
                        slot.as_deref_mut(),
                    )
                };
            }
            built = if inline_short_path::<S, P, D>() && !crate::math::ARMV6M {
                set_up!(setup_inline)
            } else {
                set_up!(setup)
            };
            // By reference: bound by value, the set-up is copied out of the `Option`.
            let Some(setup) = &built else {
                return 0;
            };
            let mut tri_lambda = 0;
            if let Some((a, b)) = lod_pair::<S>() {
                if S::LOD && shader.lod_granularity() == LodGranularity::Triangle {
                    let (cx, cy) = centroid(&pos, vp);
                    tri_lambda = lambda_at(setup, cx, cy, a, b);
                }
            }
            let corners = [
                (tri[0].x, tri[0].y),
                (tri[1].x, tri[1].y),
                (tri[2].x, tri[2].y),
            ];
            rest = Resume {
                corners,
                triangle,
                lambda: tri_lambda,
                proven: range_known::<S, P, D>(shader, &vary, setup, &corners),
            };
            if let Some(entry) = slot {
                entry.keep_rest::<S>(&rest);
            }
        }
    }
    let Some(setup) = &built else {
        return 0;
    };
    draw_set_up::<S, P, D, C>(shader, setup, &rest, kind, params, target)
}

/// The raster of a set-up triangle (`setup`, and `rest`: corners, the shader's data, level
/// of detail, range proof) within the viewport and the target's rows; the pixels written.
/// The target is read in one call ([`RenderTarget::lend`]).
#[inline(always)]
fn draw_set_up<S, P, D, C>(
    shader: &S,
    setup: &TriSetup<S::Varyings>,
    rest: &Resume<S::Triangle>,
    kind: ProjKind,
    params: &RasterParams,
    target: &mut dyn RenderTarget<Color = C>,
) -> u32
where
    S: Shader,
    P: ProjectionStage,
    D: DepthStage,
    C: TargetColor,
{
    let (corners, triangle, tri_lambda) = (rest.corners, rest.triangle, rest.lambda);
    let view = target.lend();
    let vp = params.viewport;
    let clip = Rect {
        x0: vp.x0.max(0),
        x1: vp.x1.min(view.width as i32),
        ..vp
    }
    .rows(view.row_range.0, view.row_range.1);
    if clip.is_empty() {
        return 0;
    }
    let (rows, floor) = (view.rows, view.depth_floor);
    // Meshes of small triangles skip the row loop's clamp for triangles within the clip's
    // columns (not on ARMv6-M: there the band scenes lose a little; measure with
    // `cargo xtask mcu`).
    let unclamped_rows = inline_short_path::<S, P, D>() && !crate::math::ARMV6M;
    // The writer for what is known of the triangle's range (`$proof`: `Unproven`, or
    // `Proven`, whose short spans run `InRange<S>`), built in place.
    macro_rules! draw_with {
        ($proof:ty) => {{
            let mut w = Writer::<S, P, D, C, $proof> {
                ctx: SpanCtx {
                    setup,
                    shader: <$proof>::short(*shader),
                    triangle,
                    tri_lambda,
                    log2_n: params.log2_n,
                    coord_shift: S::coord_shift(&triangle),
                    kind,
                    depth_on: params.depth_on,
                },
                scratch: None,
                bound: DepthBound {
                    floor,
                    lowest: u16::MAX,
                },
                rows,
                pixels: 0,
                _stages: core::marker::PhantomData,
            };
            // The pixels written, summed by the row loop.
            let pixels = if let Some(_) = S::RANGE_VARYING {
                // Two writers (`S` and `InRange<S>`): each with its own rasterizer, which
                // calls it directly (behind one `dyn` sink the rasterizer stays out of
                // line, with an indirect call per row: about 1 % more on the Cortex-M4F
                // sphere).
                rasterize_rows(corners, clip, &mut w, unclamped_rows)
            } else {
                // Through `dyn`: one copy of the edge walker for every span loop (LLVM
                // calls the writer directly where it sees which it is).
                let sink: &mut dyn SpanSink = &mut w;
                // The run-time draw's many draw types share one rasterizer.
                if P::KIND == ProjKind::Dynamic {
                    rasterize_shared(corners, clip, sink)
                } else {
                    rasterize_rows(corners, clip, sink, unclamped_rows)
                }
            };
            // Read out before the target is borrowed again (the writer lends its rows). The
            // row loop summed the pixels, or the writer did (`COUNT_IN_LOOP`).
            (pixels.wrapping_add(w.pixels), w.bound.lowest)
        }};
    }
    // A match on the constant, so that a shader without a range-checked varying does not
    // even instantiate `InRange` (the compiler collects only the reachable arm).
    let (pixels, mut lowest) = match S::RANGE_VARYING {
        Some(_) if rest.proven => draw_with!(Proven),
        _ => draw_with!(Unproven),
    };
    if inline_short_path::<S, P, D>() && pixels != 0 {
        lowest = lowest.min(depth_lower_bound(&corners, setup, clip));
    }
    if lowest < floor {
        target.lower_depth_floor(lowest);
    }
    pixels
}

/// Whether the triangle may be drawn with its shader wrapped in [`InRange`]: it is
/// affine and every value of the shader's [`Shader::RANGE_VARYING`] at a pixel it covers
/// lies within [`affine_bounds`], which the shader accepts ([`Shader::values_in_range`]).
/// The same pixels either way; a few instructions per triangle instead of a check per span.
#[inline(always)]
fn range_known<S: Shader, P: ProjectionStage, D: DepthStage>(
    shader: &S,
    vary: &[S::Varyings; 3],
    setup: &TriSetup<S::Varyings>,
    corners: &[(i32, i32); 3],
) -> bool {
    let Some(k) = S::RANGE_VARYING else {
        return false;
    };
    if !inline_short_path::<S, P, D>() || !setup.affine {
        return false;
    }
    match affine_bounds(vary, setup, k, corners) {
        Some((lo, hi)) => shader.values_in_range(lo, hi),
        None => false,
    }
}

/// Bounds of varying `k` at every pixel centre an affine triangle covers, as the span loop
/// evaluates it from `setup` (`None` when `k` is not a varying). The vertex values, widened
/// by a margin for
/// - coverage testing the corners snapped to 1/16 pixel (`corners`, sub-pixel units) while
///   the planes interpolate the unsnapped ones: a covered centre lies within 1/32 pixel per
///   axis of the matching point of the unsnapped triangle, where the exact value lies
///   between the vertex values, so at most `(|dx| + |dy|) / 32` units (plus one for the
///   gradients' rounding) outside them;
/// - the plane's own rounding ([`crate::raster::gradient`]): within a unit or two at the
///   reference pixel, plus half a unit per pixel of its distance from vertex 0 and at most
///   1.5 units per pixel of distance stepped (`dx`, `dy` within 1.5 units of the exact
///   gradient), each distance at most the corners' box plus a pixel: `4 (w + h) + 32`.
///
/// The first term is the one that matters on slivers, and it is tight: in the test below
/// a covered pixel of a steep sliver lies 98 % of it outside the vertex values.
/// In `i64` (corners in the guard band, `|x|, |y| <= 2^24`): no overflow.
fn affine_bounds<V: Varyings>(
    vary: &[V; 3],
    setup: &TriSetup<V>,
    k: usize,
    corners: &[(i32, i32); 3],
) -> Option<(i64, i64)> {
    let a = [
        i64::from(*vary[0].as_slice().get(k)?),
        i64::from(*vary[1].as_slice().get(k)?),
        i64::from(*vary[2].as_slice().get(k)?),
    ];
    let dx = setup.dx.as_slice().get(k)?.unsigned_abs();
    let dy = setup.dy.as_slice().get(k)?.unsigned_abs();
    // In `u32`: `|dx| / 32 + |dy| / 32 + 1` (at least `(|dx| + |dy|) / 32`, below 2^27),
    // each extent below 2^28 (the difference of two `i32`, shifted), so the margin is below
    // `2^27 + 2^31 + 33` (in `i64` throughout, it costs the Cortex-M4F sphere about half an
    // instruction per pixel more). A wider bound only proves fewer triangles, with the same pixels.
    let extent = |c: [i32; 3]| {
        let (lo, hi) = (c[0].min(c[1]).min(c[2]), c[0].max(c[1]).max(c[2]));
        (hi.wrapping_sub(lo) as u32) >> SUBPIXEL_BITS
    };
    let w = extent(corners.map(|c| c.0));
    let h = extent(corners.map(|c| c.1));
    let slope = (dx >> 5) + (dy >> 5) + 1;
    let margin = i64::from(slope + 4 * (w + h) + 32);
    let lo = a[0].min(a[1]).min(a[2]) - margin;
    let hi = a[0].max(a[1]).max(a[2]) + margin;
    Some((lo, hi))
}

/// A lower bound of every 16-bit depth the triangle can write: the depth floor's bound for
/// the spans of the inlined short path, which keep none ([`inline_short_path`]).
///
/// Why it holds, by construction rather than by an error estimate: every span loop stores
/// at pixel `(x, y)` the depth `clamp((z >> 14), 0, 0xFFFF)` of `z`, the set-up's depth
/// plane `at_ref + (x - px_ref) dz/dx + (y - py_ref) dz/dy` evaluated with wrapping `i32`
/// steps from [`crate::raster::Plane::at`]. A covered pixel's centre lies in the box of
/// the triangle's snapped corners (`corners`, sub-pixel units) and in `clip`, so its
/// column lies in `(x_min - 8) >> 4 ..= (x_max - 8) >> 4` and in the clip's columns, and
/// likewise its row. Over that box the exact plane is linear, so its least and greatest
/// values are at two opposite corners chosen by the signs of the gradients. When both are
/// `i32`, every value in the box is, no step wraps, and each stored depth, a
/// non-decreasing function of the exact value, is at least the depth of the least corner.
/// Otherwise a step may wrap and store any depth: the bound is 0. An empty box (nothing
/// covered) bounds nothing: `u16::MAX`.
fn depth_lower_bound(
    corners: &[(i32, i32); 3],
    setup: &TriSetup<impl Varyings>,
    clip: Rect,
) -> u16 {
    const HALF: i32 = 1 << (SUBPIXEL_BITS - 1);
    let span = |c0: i32, c1: i32, c2: i32, lo: i32, hi: i32| {
        let first = (c0.min(c1).min(c2).saturating_sub(HALF) >> SUBPIXEL_BITS).max(lo);
        let last = (c0.max(c1).max(c2).saturating_sub(HALF) >> SUBPIXEL_BITS).min(hi - 1);
        (first, last)
    };
    let (x0, x1) = span(corners[0].0, corners[1].0, corners[2].0, clip.x0, clip.x1);
    let (y0, y1) = span(corners[0].1, corners[1].1, corners[2].1, clip.y0, clip.y1);
    if x0 > x1 || y0 > y1 {
        return u16::MAX;
    }
    let z = &setup.z;
    let (x_lo, x_hi) = if z.dx >= 0 { (x0, x1) } else { (x1, x0) };
    let (y_lo, y_hi) = if z.dy >= 0 { (y0, y1) } else { (y1, y0) };
    let off = |a: i32, r: i32| a.wrapping_sub(r);
    let (ax, ay) = (off(x_lo, setup.px_ref), off(y_lo, setup.py_ref));
    let (bx, by) = (off(x_hi, setup.px_ref), off(y_hi, setup.py_ref));
    // On ARMv6-M (no 64-bit multiply), small triangles: gradients below 2^20 and corners
    // within 2^10 pixels of the reference make each product exact in `i32` (below 2^30),
    // and the sums' overflow flags say whether the exact values are `i32`. Elsewhere the
    // 64-bit products cost less than those checks (about 1.2 % of the Cortex-M4F sphere in
    // bands, 0.9 % whole; measure with `cargo xtask mcu`).
    let small = |v: i32, bits: u32| v.unsigned_abs() < 1 << bits;
    let least = if crate::math::ARMV6M
        && small(z.dx, 20)
        && small(z.dy, 20)
        && small(ax, 10)
        && small(ay, 10)
        && small(bx, 10)
        && small(by, 10)
    {
        let at = |x: i32, y: i32| {
            z.at_ref
                .checked_add(x * z.dx)
                .and_then(|v| v.checked_add(y * z.dy))
        };
        match (at(ax, ay), at(bx, by)) {
            (Some(least), Some(_)) => least,
            _ => return 0,
        }
    } else {
        let at = |x: i32, y: i32| {
            i64::from(z.at_ref) + i64::from(x) * i64::from(z.dx) + i64::from(y) * i64::from(z.dy)
        };
        let (least, greatest) = (at(ax, ay), at(bx, by));
        if least < i64::from(i32::MIN) || greatest > i64::from(i32::MAX) {
            return 0;
        }
        least as i32
    };
    (least >> 14).clamp(0, 0xFFFF) as u16
}

#[cfg(test)]
mod tests {
    extern crate std;
    use super::*;
    use crate::geometry::ScreenVertex;
    use crate::raster::rasterize;
    use crate::test_rng::Rng;
    use std::vec::Vec;

    /// Every covered pixel, as the rasterizer hands spans to the writer.
    struct Covered(Vec<(i32, i32)>);

    impl SpanSink for Covered {
        fn span(&mut self, y: i32, x0: i32, x1: i32) {
            self.0.extend((x0..x1).map(|x| (x, y)));
        }
    }

    /// The bound behind [`InRange`] holds: at every pixel an affine triangle covers, the
    /// value the span loop evaluates (`TriSetup::at`, which its stepping reproduces exactly)
    /// lies within [`affine_bounds`]. Random triangles from slivers to larger than the
    /// viewport, corners off screen (the reference pixel then clamped), vertex values small
    /// and large, gradients gentle and steep.
    #[test]
    fn affine_bounds_hold_at_every_covered_pixel() {
        let mut rng = Rng(0xB00D_51A7);
        let vp = Rect::of_size(96, 64);
        let (mut pixels, mut tight) = (0u64, 0u64);
        for round in 0..30_000u32 {
            let r = |rng: &mut Rng, n: i64| (rng.next() % n as u64) as i64;
            // Extent 2^0..2^11 pixels, in 1/4096 pixel.
            let scale = 4096i64 << (round % 12);
            let (cx, cy) = (r(&mut rng, 96 * 4096), r(&mut rng, 64 * 4096));
            let corner = |rng: &mut Rng| {
                let fine = |c: i64, rng: &mut Rng| (c + r(rng, 2 * scale) - scale) as i32;
                let (fx, fy) = (fine(cx, rng), fine(cy, rng));
                // Snapped to 1/16 pixel, the rest in `sub` (at most half a sub-pixel).
                let snap = |f: i32| ((f + 128) >> 8, (f - (((f + 128) >> 8) << 8)) as i16);
                let ((x, sx), (y, sy)) = (snap(fx), snap(fy));
                ScreenVertex::<1> {
                    x,
                    y,
                    sub: [sx, sy],
                    z: 0,
                    w: 1 << 16,
                    varyings: [0],
                }
            };
            let mut tri = [corner(&mut rng), corner(&mut rng), corner(&mut rng)];
            // Values within 2^(8..30) of each other, around zero or the top of a range.
            let spread = 1i64 << (8 + round % 23);
            let base = [0, 256 << 16, 1 << 29][(round % 3) as usize];
            for v in &mut tri {
                v.varyings[0] = (base + r(&mut rng, spread) - spread / 2) as i32;
            }
            let vary = tri.map(|v| v.varyings);
            let pos = tri.map(|v| {
                let (x, y) = v.attr_position();
                (x, y, 0, v.w)
            });
            let Some(s) = setup(pos, &vary, vp, ProjKind::Affine, false, None, 0, None) else {
                continue;
            };
            let corners = tri.map(|v| (v.x, v.y));
            let (lo, hi) = affine_bounds(&vary, &s, 0, &corners).unwrap();
            let mut covered = Covered(Vec::new());
            rasterize(corners, vp, &mut covered);
            for (x, y) in covered.0 {
                let v = i64::from(s.at(x, y)[0]);
                assert!(
                    (lo..=hi).contains(&v),
                    "round {round}: {v} at ({x}, {y}) outside {lo}..={hi}, {tri:?}"
                );
                pixels += 1;
                let (a_lo, a_hi) = (
                    vary.iter().map(|a| a[0]).min(),
                    vary.iter().map(|a| a[0]).max(),
                );
                if i64::from(a_lo.unwrap()) > v || v > i64::from(a_hi.unwrap()) {
                    tight += 1;
                }
            }
        }
        // The margin is needed: some covered pixels do lie outside the vertex values.
        assert!(
            pixels > 1_000_000 && tight > 100,
            "{pixels} pixels, {tight} outside"
        );
    }
}
