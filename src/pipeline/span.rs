//! The fused per-pixel loop: depth test, interpolation of the shader's varyings, the
//! shader, and the store, for one span, monomorphised per shader, projection and depth.
//!
//! Nothing is decided per pixel that was known per draw: the projection picks the
//! interpolator type, the shader is a type whose `shade` is inlined, and depth is a const
//! generic chosen once per span (a depth-testing draw into a target without a depth buffer
//! falls back to the untested loop). The depth test runs before the varyings are resolved,
//! so a hidden pixel costs no reciprocal and no texel fetch.

use super::interp::{AffineInterp, ExactInterp, Interp, SubdivInterp};
use super::setup::TriSetup;
use super::stages::{DepthStage, ProjKind, ProjectionStage};
use crate::color::TargetColor;
use crate::shading::{Fragment, Shader};
use crate::texture::LodGranularity;

/// Per-draw, per-triangle state the span loop reads.
#[derive(Clone, Copy, Debug)]
pub(crate) struct SpanCtx<S: Shader> {
    pub setup: TriSetup<S::Varyings>,
    pub shader: S,
    pub triangle: S::Triangle,
    /// Level of detail of the whole triangle (for [`LodGranularity::Triangle`]).
    pub tri_lambda: i32,
    pub log2_n: u32,
    /// The draw's run-time depth switch (for the typed path it is always on and the stage's
    /// type decides; the run-time path links one depth-testing loop and turns it off here).
    pub depth_on: bool,
}

#[inline(always)]
fn run<S: Shader, C: TargetColor, I: Interp<S::Varyings>, const Z: bool>(
    ctx: &SpanCtx<S>,
    x: i32,
    y: i32,
    out: &mut [C],
    zrow: &mut [u16],
) -> u32 {
    let s = &ctx.setup;
    // The shader in a local: its uniforms can live in registers through the loop.
    let shader = ctx.shader;
    let mut it = I::start(s, x, y, out.len() as u32, ctx.log2_n);
    let (a, b) = S::TEXCOORDS.unwrap_or((0, 1));
    let granularity = if S::LOD {
        shader.lod_granularity()
    } else {
        LodGranularity::Triangle
    };
    let per_pixel = S::LOD && granularity == LodGranularity::Pixel;
    let fixed_lambda = if !S::LOD {
        0
    } else {
        match granularity {
            LodGranularity::Triangle => ctx.tri_lambda,
            _ => it.lambda(s, a, b),
        }
    };
    let lambda = |it: &I| -> i32 {
        if per_pixel {
            it.lambda(s, a, b)
        } else {
            fixed_lambda
        }
    };
    let mut z = s.plane_at(&s.z, x, y);
    let mut written = 0u32;
    let mut px = x;
    if Z {
        for (o, zb) in out.iter_mut().zip(zrow.iter_mut()) {
            let d = (z >> 14).clamp(0, 0xFFFF) as u16;
            if d < *zb {
                let f = Fragment {
                    varyings: it.frag(),
                    x: px,
                    y,
                    depth: d,
                    lambda: lambda(&it),
                    triangle: ctx.triangle,
                };
                if let Some(c) = shader.shade(&f) {
                    *zb = d;
                    *o = C::from_rgb565(c);
                    written += 1;
                }
            }
            z = z.wrapping_add(s.z.dx);
            px = px.wrapping_add(1);
            it.step();
        }
    } else {
        for o in out.iter_mut() {
            let f = Fragment {
                varyings: it.frag(),
                x: px,
                y,
                depth: (z >> 14).clamp(0, 0xFFFF) as u16,
                lambda: lambda(&it),
                triangle: ctx.triangle,
            };
            if let Some(c) = shader.shade(&f) {
                *o = C::from_rgb565(c);
                written += 1;
            }
            z = z.wrapping_add(s.z.dx);
            px = px.wrapping_add(1);
            it.step();
        }
    }
    written
}

/// Draws pixels `x0..x1` of row `y` into `row` (and `depth`), for a span the rasterizer
/// emitted, and returns the pixels written. Out-of-range spans are ignored (they cannot
/// happen; this keeps it panic-free).
#[inline(never)]
pub(crate) fn span<S: Shader, P: ProjectionStage, D: DepthStage, C: TargetColor>(
    ctx: &SpanCtx<S>,
    y: i32,
    x0: i32,
    x1: i32,
    row: &mut [C],
    depth: Option<&mut [u16]>,
) -> u32 {
    let (Ok(a), Ok(b)) = (usize::try_from(x0), usize::try_from(x1)) else {
        return 0;
    };
    let Some(out) = row.get_mut(a..b) else {
        return 0;
    };
    let zrow = if D::TEST && ctx.depth_on {
        depth.and_then(|d| d.get_mut(a..b))
    } else {
        None
    };
    type A<S> = AffineInterp<<S as Shader>::Varyings>;
    type E<S> = ExactInterp<<S as Shader>::Varyings>;
    type Sd<S> = SubdivInterp<<S as Shader>::Varyings>;
    match (P::KIND, zrow) {
        (ProjKind::Affine, Some(z)) => run::<S, C, A<S>, true>(ctx, x0, y, out, z),
        (ProjKind::Affine, None) => run::<S, C, A<S>, false>(ctx, x0, y, out, &mut []),
        (ProjKind::Exact, Some(z)) => run::<S, C, E<S>, true>(ctx, x0, y, out, z),
        (ProjKind::Exact, None) => run::<S, C, E<S>, false>(ctx, x0, y, out, &mut []),
        (ProjKind::Subdivided, Some(z)) => run::<S, C, Sd<S>, true>(ctx, x0, y, out, z),
        (ProjKind::Subdivided, None) => run::<S, C, Sd<S>, false>(ctx, x0, y, out, &mut []),
        (ProjKind::Adaptive, Some(z)) if ctx.setup.affine => {
            run::<S, C, A<S>, true>(ctx, x0, y, out, z)
        }
        (ProjKind::Adaptive, None) if ctx.setup.affine => {
            run::<S, C, A<S>, false>(ctx, x0, y, out, &mut [])
        }
        (ProjKind::Adaptive, Some(z)) => run::<S, C, E<S>, true>(ctx, x0, y, out, z),
        (ProjKind::Adaptive, None) => run::<S, C, E<S>, false>(ctx, x0, y, out, &mut []),
    }
}
