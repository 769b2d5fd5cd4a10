//! [`InRange`]: a shader that, for one triangle, is known to keep the varying it
//! range-checks ([`Shader::RANGE_VARYING`]) in range at every pixel the triangle covers, so
//! its spans skip [`Shader::piece_in_range`].
//!
//! The rasterizer bounds that varying over a whole affine triangle once
//! (`raster::affine_bounds`, a few dozen instructions) and, when the shader accepts the
//! bounds ([`Shader::values_in_range`]), draws the triangle with the shader wrapped in
//! [`InRange`]. Every span of the triangle then shades with [`Shader::shade_in_range`]
//! without the check of its two ends (about 20 instructions per span on Cortex-M4F). The
//! pixels are the same: `shade_in_range` shades in-range fragments exactly as `shade`.
//!
//! A wrapper type rather than a flag: a run-time flag in the span context makes the
//! Cortex-M4F shading loop spill, and a const parameter threaded through the span loop
//! changes the Cortex-M0+ code (about 1.5 % more on the sphere) although that core never
//! takes the path. A shader without a range-checked varying never builds an
//! `InRange`, so nothing of it is linked.

#[cfg(doc)]
use super::span::span;
use super::span::SpanCtx;
use crate::shading::{Fragment, Shader};
use crate::texture::LodGranularity;

/// What the rasterizer knows of a triangle's range ([`Unproven`] or [`Proven`]): the
/// shader type its short spans run (`S`, or `InRange<S>`), and how its other spans run.
/// Those always run the plain shader, so a proven triangle links no second copy of the
/// long-span loops (about 8 KB on Cortex-M4F), only of the short path.
pub(crate) trait RangeProof {
    /// Whether the triangle is known to be affine (a proof is only ever made for an affine
    /// triangle: its short spans then skip the per-span test of it).
    const AFFINE: bool;

    /// The shader of the triangle's short spans.
    type Short<S: Shader>: Shader<Varyings = S::Varyings, Triangle = S::Triangle>;

    /// `shader` as the short spans run it.
    fn short<S: Shader>(shader: S) -> Self::Short<S>;

    /// Calls `f` with the triangle's span context around the plain shader: the one its
    /// spans that the short path does not take run with ([`span`]).
    fn with_plain<'s, S: Shader, R>(
        ctx: &SpanCtx<'s, Self::Short<S>>,
        f: impl FnOnce(&SpanCtx<'s, S>) -> R,
    ) -> R;
}

/// Nothing known: the plain shader everywhere.
pub(crate) struct Unproven;

impl RangeProof for Unproven {
    const AFFINE: bool = false;
    type Short<S: Shader> = S;

    #[inline(always)]
    fn short<S: Shader>(shader: S) -> S {
        shader
    }

    #[inline(always)]
    fn with_plain<'s, S: Shader, R>(
        ctx: &SpanCtx<'s, S>,
        f: impl FnOnce(&SpanCtx<'s, S>) -> R,
    ) -> R {
        f(ctx)
    }
}

/// In range throughout: [`InRange`] on the short spans.
pub(crate) struct Proven;

impl RangeProof for Proven {
    const AFFINE: bool = true;
    type Short<S: Shader> = InRange<S>;

    #[inline(always)]
    fn short<S: Shader>(shader: S) -> InRange<S> {
        InRange(shader)
    }

    /// The span context rebuilt around the plain shader (a few word copies, for the rare
    /// span longer than a chunk).
    #[inline(always)]
    fn with_plain<'s, S: Shader, R>(
        ctx: &SpanCtx<'s, InRange<S>>,
        f: impl FnOnce(&SpanCtx<'s, S>) -> R,
    ) -> R {
        f(&SpanCtx {
            setup: ctx.setup,
            shader: ctx.shader.0,
            triangle: ctx.triangle,
            tri_lambda: ctx.tri_lambda,
            log2_n: ctx.log2_n,
            coord_shift: ctx.coord_shift,
            kind: ctx.kind,
            depth_on: ctx.depth_on,
        })
    }
}

/// `S`, known in range for the triangle being drawn (see the module docs).
#[derive(Clone, Copy, Debug)]
pub(crate) struct InRange<S>(pub S);

impl<S: Shader> Shader for InRange<S> {
    type Varyings = S::Varyings;
    type Triangle = S::Triangle;
    const TEXCOORDS: Option<(usize, usize)> = S::TEXCOORDS;
    const DISCARDS: bool = S::DISCARDS;
    const BLENDS: bool = S::BLENDS;
    const SMALL: bool = S::SMALL;
    const LOD: bool = S::LOD;
    const LOD_DIRECTION: Option<usize> = S::LOD_DIRECTION;
    const LOD_REFLECTION: Option<usize> = S::LOD_REFLECTION;
    const RANGE_VARYING: Option<usize> = S::RANGE_VARYING;

    #[inline(always)]
    fn lod_granularity(&self) -> LodGranularity {
        self.0.lod_granularity()
    }

    #[inline(always)]
    fn coord_shift(triangle: &Self::Triangle) -> u32 {
        S::coord_shift(triangle)
    }

    /// Every piece of the triangle is in range: proven for all its pixels at once.
    #[inline(always)]
    fn piece_in_range(&self, _: &Self::Varyings, _: &Self::Varyings, _: u32) -> bool {
        true
    }

    #[inline(always)]
    fn values_in_range(&self, lo: i64, hi: i64) -> bool {
        self.0.values_in_range(lo, hi)
    }

    #[inline(always)]
    fn shade_in_range(&self, fragment: &Fragment<Self::Varyings, Self::Triangle>) -> Option<u16> {
        self.0.shade_in_range(fragment)
    }

    #[inline(always)]
    fn shade_piece_rgb565(
        &self,
        start: &Self::Varyings,
        slope: &Self::Varyings,
        out: &mut [u16],
    ) -> bool {
        self.0.shade_piece_rgb565(start, slope, out)
    }

    const PIECE_DEPTH_LOOP: bool = S::PIECE_DEPTH_LOOP;

    #[inline(always)]
    fn shade_piece_depth_rgb565(
        &self,
        start: &Self::Varyings,
        slope: &Self::Varyings,
        depth: (i32, i32),
        out: &mut [u16],
        zrow: &mut [u16],
    ) -> Option<u32> {
        self.0
            .shade_piece_depth_rgb565(start, slope, depth, out, zrow)
    }

    #[inline(always)]
    fn can_draw(&self) -> bool {
        self.0.can_draw()
    }

    #[inline(always)]
    fn triangle(&self, varyings: &mut [Self::Varyings; 3]) -> Self::Triangle {
        self.0.triangle(varyings)
    }

    #[inline(always)]
    fn shade(&self, fragment: &Fragment<Self::Varyings, Self::Triangle>) -> Option<u16> {
        self.0.shade(fragment)
    }

    #[inline(always)]
    fn shade_over(
        &self,
        fragment: &Fragment<Self::Varyings, Self::Triangle>,
        dst: u16,
    ) -> Option<u16> {
        self.0.shade_over(fragment, dst)
    }
}
