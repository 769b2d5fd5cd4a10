//! The fused per-pixel loop: depth test, interpolation, texture sampling, shading and the
//! store, for one span, monomorphised per [`Stages`] combination.
//!
//! Nothing is decided per pixel that was known per draw: the projection mode picks the
//! interpolator type, the shading and filter are associated constants matched at compile
//! time, and depth is a const generic chosen once per span (a depth-testing draw into a
//! target without a depth buffer falls back to the untested loop).

use super::interp::{AffineInterp, ExactInterp, Frag, Interp, SubdivInterp};
use super::setup::TriSetup;
use super::stages::{DepthStage, ProjKind, ProjectionStage, Shading, ShadingStage, Stages};
use crate::color::{modulate_rgb, modulate_scalar, rgb565, TargetColor};
use crate::geometry::COLOR_ONE;
use crate::texture::{Lod, LodGranularity, MipTexture, TexSampler, Texture};

/// Per-draw, per-triangle state the span loop reads.
#[derive(Clone, Copy, Debug)]
pub(crate) struct SpanCtx<'a, M: Stages> {
    pub setup: TriSetup,
    pub tex: &'a MipTexture<'a>,
    pub sampler: M::F,
    pub lod: Lod,
    /// Level of detail of the whole triangle (for [`LodGranularity::Triangle`]).
    pub tri_lambda: i32,
    pub wu: M::WU,
    pub wv: M::WV,
    pub log2_n: u32,
    pub flat: u16,
    /// Per axis: true for the periodic wrap modes (see `setup` on `uv_shift`).
    pub periodic: [bool; 2],
    /// The draw's run-time depth switch (for the typed path it is always on and the stage's
    /// type decides; the run-time path links one depth-testing loop and turns it off here).
    pub depth_on: bool,
}

/// Undoes the per-triangle texel-coordinate shift (rare: only huge uv extents).
#[inline(always)]
fn unshift(x: i32, k: u32, periodic: bool) -> i32 {
    if k == 0 {
        x
    } else if periodic {
        x.wrapping_shl(k)
    } else {
        let lim = (1i32 << 30) >> k.min(30);
        x.clamp(-lim, lim) << k.min(30)
    }
}

/// Colour channel (Q8.16) to Q8 in `0..=256`.
#[inline(always)]
fn q8(c: i32) -> u16 {
    (c >> 16).clamp(0, i32::from(COLOR_ONE)) as u16
}

/// The filtered texel at `f`. A function, not a closure in `shade`: LLVM did not inline
/// the closure (a call, register saves and reloads of the texture fields per pixel).
#[inline(always)]
fn texel<M: Stages>(ctx: &SpanCtx<'_, M>, base: &Texture<'_>, f: &Frag, lambda: i32) -> u16 {
    let k = ctx.setup.uv_shift;
    let u = unshift(f.u, k, ctx.periodic[0]);
    let v = unshift(f.v, k, ctx.periodic[1]);
    if <M::F as TexSampler>::LOD {
        ctx.sampler
            .sample_mip(ctx.tex, ctx.wu, ctx.wv, u, v, lambda)
    } else {
        ctx.sampler.sample_base(base, ctx.wu, ctx.wv, u, v)
    }
}

#[inline(always)]
fn shade<M: Stages>(ctx: &SpanCtx<'_, M>, base: &Texture<'_>, f: Frag, lambda: i32) -> u16 {
    let texel = || texel(ctx, base, &f, lambda);
    match M::S::KIND {
        Shading::Replace => texel(),
        Shading::ModulateIntensity => modulate_scalar(texel(), q8(f.c[0])),
        Shading::Modulate => modulate_rgb(texel(), q8(f.c[0]), q8(f.c[1]), q8(f.c[2])),
        Shading::Gouraud => {
            let ch = |c: i32, max: u32| ((u32::from(q8(c)) * max + 128) >> 8) as u8;
            rgb565(ch(f.c[0], 31), ch(f.c[1], 63), ch(f.c[2], 31))
        }
        Shading::Flat => ctx.flat,
    }
}

#[inline(always)]
fn run<M: Stages, C: TargetColor, I: Interp, const Z: bool>(
    ctx: &SpanCtx<'_, M>,
    x: i32,
    y: i32,
    out: &mut [C],
    zrow: &mut [u16],
) -> u32 {
    let s = &ctx.setup;
    let mut it = I::start(s, x, y, out.len() as u32, ctx.log2_n);
    // Level 0 in a local: its pointer and sizes can live in registers through the loop.
    let base = *ctx.tex.base();
    let lod = ctx.lod;
    let per_pixel = <M::F as TexSampler>::LOD && lod.granularity == LodGranularity::Pixel;
    let fixed_lambda = if !<M::F as TexSampler>::LOD {
        0
    } else {
        match lod.granularity {
            LodGranularity::Triangle => ctx.tri_lambda,
            _ => it.lambda(s),
        }
    };
    let lambda = |it: &I| -> i32 {
        let l = if per_pixel {
            it.lambda(s)
        } else {
            fixed_lambda
        };
        l.saturating_add(lod.bias)
            .clamp(lod.min, lod.max.max(lod.min))
    };
    if Z {
        let mut z = s.z.at((s.px_ref, s.py_ref), x, y);
        let mut written = 0u32;
        for (px, zb) in out.iter_mut().zip(zrow.iter_mut()) {
            let d = (z >> 14).clamp(0, 0xFFFF) as u16;
            if d < *zb {
                *zb = d;
                *px = C::from_rgb565(shade(ctx, &base, it.frag(), lambda(&it)));
                written += 1;
            }
            z = z.wrapping_add(s.z.dx);
            it.step();
        }
        written
    } else {
        for px in out.iter_mut() {
            *px = C::from_rgb565(shade(ctx, &base, it.frag(), lambda(&it)));
            it.step();
        }
        out.len() as u32
    }
}

/// Draws pixels `x0..x1` of row `y` into `row` (and `depth`), for a span the rasterizer
/// emitted, and returns the pixels written. Out-of-range spans are ignored (they cannot
/// happen; this keeps it panic-free).
#[inline(never)]
pub(crate) fn span<M: Stages, C: TargetColor>(
    ctx: &SpanCtx<'_, M>,
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
    let zrow = if M::D::TEST && ctx.depth_on {
        depth.and_then(|d| d.get_mut(a..b))
    } else {
        None
    };
    match (M::P::KIND, zrow) {
        (ProjKind::Affine, Some(z)) => run::<M, C, AffineInterp, true>(ctx, x0, y, out, z),
        (ProjKind::Affine, None) => run::<M, C, AffineInterp, false>(ctx, x0, y, out, &mut []),
        (ProjKind::Exact, Some(z)) => run::<M, C, ExactInterp, true>(ctx, x0, y, out, z),
        (ProjKind::Exact, None) => run::<M, C, ExactInterp, false>(ctx, x0, y, out, &mut []),
        (ProjKind::Subdivided, Some(z)) => run::<M, C, SubdivInterp, true>(ctx, x0, y, out, z),
        (ProjKind::Subdivided, None) => run::<M, C, SubdivInterp, false>(ctx, x0, y, out, &mut []),
        (ProjKind::Adaptive, Some(z)) if ctx.setup.affine => {
            run::<M, C, AffineInterp, true>(ctx, x0, y, out, z)
        }
        (ProjKind::Adaptive, None) if ctx.setup.affine => {
            run::<M, C, AffineInterp, false>(ctx, x0, y, out, &mut [])
        }
        (ProjKind::Adaptive, Some(z)) => run::<M, C, ExactInterp, true>(ctx, x0, y, out, z),
        (ProjKind::Adaptive, None) => run::<M, C, ExactInterp, false>(ctx, x0, y, out, &mut []),
    }
}
