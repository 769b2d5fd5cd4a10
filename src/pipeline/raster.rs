//! One screen triangle through a shader: the shader's per-triangle hook, the set-up, the
//! edge walker, and the span loop for each span it emits.
//!
//! Shared by the classic [`Draw`](super::Draw) (built-in shaders fed the classic varyings)
//! and the open [`ShadedDraw`](super::ShadedDraw) (any shader). Generic over the shader,
//! projection, depth stage, target colour and varying count: each draw type a firmware
//! uses links exactly one copy.

use super::interp::lambda_at;
use super::setup::{centroid, setup};
use super::setup_cache::SetupSlot;
use super::span::{inline_short_path, span, span_short, DepthBound, Scratch, SpanCtx};
use super::stages::{DepthStage, ProjKind, Projection, ProjectionStage};
use crate::color::TargetColor;
use crate::geometry::{ScreenTriangle, Viewport};
use crate::raster::{rasterize, Rect, SpanSink};
use crate::shading::Shader;
use crate::surface::{RenderTarget, Rows};
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

struct Writer<'t, S: Shader, P, D, C> {
    ctx: SpanCtx<'t, S>,
    scratch: Option<Scratch<S::Varyings>>,
    /// The target's depth floor, read once per triangle: a triangle writes each pixel at
    /// most once, so its own writes never matter to its later spans. Lowered once, after.
    bound: DepthBound,
    /// The target's rows, lent for the triangle.
    rows: Rows<'t, C>,
    pixels: u32,
    _stages: core::marker::PhantomData<(P, D)>,
}

impl<S: Shader, P: ProjectionStage, D: DepthStage, C: TargetColor> SpanSink
    for Writer<'_, S, P, D, C>
{
    // Not inlined into the rasterizer's row loop: one copy per draw type (inlined there, each
    // draw type's `raster_triangle` carried the edge walk and the short path again: +9.8 KB
    // for `Draw::dynamic` on Cortex-M4F).
    #[inline(never)]
    fn span(&mut self, y: i32, x0: i32, x1: i32) {
        // The span's pixels, colour and depth, sliced out of the target's buffers (the
        // rasterizer clipped the span to the target: the slicing checks alone).
        if let Some((out, mut depth)) = self.rows.span_in_clip(y, x0, x1) {
            // The short path inlined here; every other span through `span`, out of line.
            let short = span_short::<S, P, D, C>(
                &self.ctx,
                &mut self.bound,
                y,
                x0,
                out,
                depth.as_deref_mut(),
            );
            let n = match short {
                Some(n) => n,
                None => span::<S, P, D, C>(
                    &self.ctx,
                    &mut self.bound,
                    &mut self.scratch,
                    y,
                    x0,
                    out,
                    depth,
                ),
            };
            self.pixels = self.pixels.wrapping_add(n);
        }
    }
}

/// Rasterizes `tri` with `shader` into `target`; `varyings` maps a vertex's varyings to the
/// shader's. Returns the pixels written.
pub(crate) fn raster_shaded<S, P, D, C, const N: usize>(
    shader: &S,
    tri: &ScreenTriangle<N>,
    varyings: impl Fn(&[i32; N]) -> S::Varyings,
    params: &RasterParams,
    target: &mut dyn RenderTarget<Color = C>,
    slot: SetupSlot<'_>,
) -> u32
where
    S: Shader,
    P: ProjectionStage,
    D: DepthStage,
    C: TargetColor,
{
    let vp = params.viewport;
    let (r0, r1) = target.row_range();
    let clip = Rect {
        x0: vp.x0.max(0),
        x1: vp.x1.min(target.width() as i32),
        ..vp
    }
    .rows(r0, r1);
    if clip.is_empty() {
        return 0;
    }
    let mut vary = [
        varyings(&tri[0].varyings),
        varyings(&tri[1].varyings),
        varyings(&tri[2].varyings),
    ];
    let triangle = shader.triangle(&mut vary);
    let kind = match P::KIND {
        ProjKind::Dynamic => params.kind,
        k => k,
    };
    let pos = tri.map(|v| {
        let (x, y) = v.attr_position();
        (x, y, v.z, v.w)
    });
    // Kept where the call writes it and lent to the span loop (see `setup`, which also takes
    // it from, or keeps it in, a band renderer's cache: `slot`).
    let built = setup(
        pos,
        &vary,
        vp,
        kind,
        D::TEST,
        S::TEXCOORDS,
        params.budget,
        slot,
    );
    // By reference: bound by value, the set-up is copied out of the `Option`.
    let Some(setup) = &built else {
        return 0;
    };
    let mut tri_lambda = 0;
    if let Some((a, b)) = S::TEXCOORDS {
        if S::LOD && shader.lod_granularity() == LodGranularity::Triangle {
            let (cx, cy) = centroid(&pos, vp);
            tri_lambda = lambda_at(setup, cx, cy, a, b);
        }
    }
    let floor = target.depth_floor();
    let mut w = Writer::<S, P, D, C> {
        ctx: SpanCtx {
            setup,
            shader: *shader,
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
        rows: target.rows_mut(),
        pixels: 0,
        _stages: core::marker::PhantomData,
    };
    // Through `dyn`: one copy of the edge walker for every span loop (LLVM calls the
    // writer directly where it sees which it is).
    let sink: &mut dyn SpanSink = &mut w;
    rasterize(
        [
            (tri[0].x, tri[0].y),
            (tri[1].x, tri[1].y),
            (tri[2].x, tri[2].y),
        ],
        clip,
        sink,
    );
    // Read out before the target is borrowed again (the writer lends its rows).
    let (pixels, mut lowest) = (w.pixels, w.bound.lowest);
    if inline_short_path::<S, P, D>() && pixels != 0 {
        lowest = lowest.min(depth_lower_bound(&pos, vp));
    }
    if lowest < floor {
        target.lower_depth_floor(lowest);
    }
    pixels
}

/// A lower bound of every 16-bit depth the triangle `pos` can write in `viewport`, from its
/// vertices' depths alone (Q14, as the set-up reads them): the depth floor's bound for the
/// spans of the inlined short path, which keep none ([`inline_short_path`]).
///
/// A covered pixel centre lies in the triangle, where the exact plane is a convex
/// combination of the vertex depths, so at least their minimum. The set-up's plane is
/// within `2 + (width + height) / 2` units of it anywhere in the viewport (see
/// [`crate::raster::gradient`]); the bound subtracts `2 + width + height`.
fn depth_lower_bound(pos: &[super::setup::SetupVertex; 3], viewport: Rect) -> u16 {
    let z_min = pos[0].2.min(pos[1].2).min(pos[2].2);
    let margin = viewport
        .x1
        .wrapping_sub(viewport.x0)
        .unsigned_abs()
        .saturating_add(viewport.y1.wrapping_sub(viewport.y0).unsigned_abs())
        .saturating_add(2)
        .min(1 << 30) as i32;
    (z_min.saturating_sub(margin) >> 14).clamp(0, 0xFFFF) as u16
}
