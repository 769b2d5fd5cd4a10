//! The per-pixel loop: depth test, interpolation of the shader's varyings, the shader, and
//! the stores, for one span, monomorphised per shader, projection and depth.
//!
//! A span is processed in chunks of up to 32 pixels, in three passes that each keep few
//! values live (so nothing spills on a 13-register Cortex-M core):
//! 1. depth: test (`GL_LESS`) and, unless the shader can discard, write the 16-bit depth of
//!    the chunk's pixels, collecting a 32-bit visibility mask;
//! 2. interpolation: the chunk's varyings (and levels of detail, when the shader reads them)
//!    into a small stack array; the exact mode computes its reciprocal only for visible
//!    pixels, the linear modes add a slope per pixel;
//! 3. shading (not inlined, so it gets its own registers): the shader for each visible
//!    pixel, and the store.
//!
//! This module picks the loop for a span and runs its chunks and pieces; the depth pass is
//! [`depth_pass`], the shading loops [`shade_loop`].
//!
//! A span that is one chunk and one linear piece (affine, or subdivided with `N >= 16` and
//! at most `N` pixels: the spans of finely tessellated meshes, a few pixels long) skips the
//! chunk and piece bookkeeping: its piece comes from its two ends, then the depth mask and
//! one shading call (`run_short`, the same pixels as the general loop).
//!
//! Nothing is decided per pixel that was known per draw: the projection picks the
//! interpolator type, the shader is a type whose `shade` is inlined, and depth is a const
//! generic chosen once per span (a depth-testing draw into a target without a depth buffer
//! falls back to the untested loop).

use super::dyn_interp::DynInterp;
use super::interp::{lod_pair, ExactInterp, Fill, FillSpec, Linear};
use super::quadratic::Quadratic;
use super::stages::{DepthStage, ProjKind, ProjectionStage};
use super::tri_setup::TriSetup;
use crate::color::TargetColor;
use crate::shading::{Shader, Varyings};
use crate::texture::LodGranularity;

/// Per-draw, per-triangle state the span loop reads.
#[derive(Clone, Copy, Debug)]
pub(crate) struct SpanCtx<'s, S: Shader> {
    /// The triangle's set-up (kept by the caller where [`super::setup::setup`] wrote it).
    pub setup: &'s TriSetup<S::Varyings>,
    pub shader: S,
    pub triangle: S::Triangle,
    /// Level of detail of the whole triangle (for [`LodGranularity::Triangle`]).
    pub tri_lambda: i32,
    pub log2_n: u32,
    /// Left shift to undo on the texture-coordinate pair ([`Shader::coord_shift`]).
    pub coord_shift: u32,
    /// The projection (the draw's, when its marker is the run-time one).
    pub kind: ProjKind,
    /// The draw's run-time depth switch (for the typed path it is always on and the stage's
    /// type decides; the run-time path links one depth-testing loop and turns it off here).
    pub depth_on: bool,
}

/// Pixels per chunk: one word of visibility mask.
pub(crate) const CHUNK: usize = 32;

/// The chunk arrays of the filled modes, owned by the triangle's span writer so they are
/// initialised once per triangle, not once per span, and only by the span loops that fill
/// them (the linear loops, affine and subdivided with N >= 16, never do: zeroing them for
/// each of the benchmark sphere's small triangles cost ~5 instructions per pixel).
#[derive(Clone, Copy, Debug)]
pub(crate) struct Scratch<V> {
    vals: [V; CHUNK],
    /// Only for shaders that read a per-pixel level of detail (not zeroed otherwise).
    lambdas: Option<[i32; CHUNK]>,
}

impl<V: Varyings> Scratch<V> {
    pub fn new() -> Self {
        Scratch {
            vals: [V::zero(); CHUNK],
            lambdas: None,
        }
    }

    /// The triangle's scratch, zeroed in place on first use (out of line: once per
    /// triangle).
    #[inline(always)]
    fn of(slot: &mut Option<Self>) -> &mut Self {
        #[cold]
        #[inline(never)]
        fn fresh<V: Varyings>(slot: &mut Option<Scratch<V>>) {
            *slot = Some(Scratch::new());
        }
        if slot.is_none() {
            fresh(slot);
        }
        // Some by now: the closure never runs.
        slot.get_or_insert_with(Scratch::new)
    }
}

// Declared here, after the span context and before the loops that use them: rustc emits a
// crate's functions in definition order and LLVM's choices follow it. Declared at the top of
// `pipeline`, the same code costs the Cortex-M4F whole sphere a fraction of an instruction
// per pixel more (measure with `cargo xtask mcu`).
mod depth_pass;
mod shade_loop;

pub(crate) use depth_pass::DepthBound;
use depth_pass::{chunk_mask, low_bits};
use shade_loop::{shade_chunk, shade_depth_inline, shade_linear, shade_linear_inline, Pos};

/// The longest span of the inlined short path that tests depth inside its shading loop
/// ([`shade_depth_inline`]) rather than in a depth pass first: the fused loop carries the
/// depth, its step and the depth row through the shader's registers, but saves the mask and
/// the second loop's set-up per span.
///
/// The limit per target, on the whole-frame spheres (measure with `cargo xtask mcu`; x86-64
/// with `cargo xtask count`):
/// - Cortex-M4F: up to 3 pixels, where LLVM unrolls the fused loop whole. That saves about
///   1-3 % of the sphere against no fused loop; 4 pixels costs more on the footprint and
///   plain bilinear spheres, and fusing every span costs more than it saves (the
///   13-register core spills in the loop).
/// - Cortex-M0+: every span (about 1-2 % saved on each sphere).
/// - RV32IMC and x86-64: up to 4 pixels (up to about 1.5 % saved). Fusing every span on
///   RV32IMC saves more on the sized texture but costs about 5 % more on the plain
///   bilinear sphere.
///
/// A shader with a fused loop of its own ([`Shader::PIECE_DEPTH_LOOP`]: the ARMv7E-M
/// assembly loops of `BilinearFootprintSized` and `BilinearFootprint`) takes every short
/// span, whatever its length: about 2-4 % of the Cortex-M4F sphere.
const FUSED_MAX: usize = if crate::math::ARMV6M {
    CHUNK
} else if cfg!(target_arch = "arm") {
    3
} else {
    4
};

/// Affine and subdivided spans: per chunk, the depth mask, then each linear piece of the
/// chunk shaded with its varyings stepped in registers.
#[inline(always)]
fn run_linear<S: Shader, C: TargetColor, D: DepthStage, const SUB: bool, const Z: bool>(
    ctx: &SpanCtx<'_, S>,
    bound: &mut DepthBound,
    x: i32,
    y: i32,
    out: &mut [C],
    zrow: &mut [u16],
) -> u32 {
    let s = &ctx.setup;
    let pair = lod_pair::<S>().unwrap_or((0, 1));
    let mut it = Linear::<S::Varyings, SUB>::start(s, x, y, out.len() as u32, ctx.log2_n);
    let (lambda, per_piece) = lod_policy(ctx, || it.lambda(s, pair));
    let spec = FillSpec {
        pair,
        lod: per_piece,
        shift: ctx.coord_shift,
        live: S::INTERPOLATED,
    };
    let dz = s.z.dx;
    let mut z = s.plane_at(&s.z, x, y);
    let mut px = x;
    let mut written = 0u32;
    let mut zs: &mut [u16] = zrow;
    for os in out.chunks_mut(CHUNK) {
        let n = os.len();
        let (zc, zrest) = if Z {
            if n > zs.len() {
                break;
            }
            core::mem::take(&mut zs).split_at_mut(n)
        } else {
            (&mut [][..], &mut [][..])
        };
        zs = zrest;
        let mask = chunk_mask::<S, Z, true, false>(z, dz, zc, n, bound);
        let mut off = 0usize;
        while off < n {
            let Some(p) = it.piece(s, n - off, spec) else {
                break;
            };
            let end = (off + p.len).min(n);
            let m = mask >> off;
            if m & low_bits(end - off) != 0 {
                let pos = Pos {
                    x: px.wrapping_add(off as i32),
                    y,
                    z: z.wrapping_add(dz.wrapping_mul(off as i32)),
                    dz,
                    lambda: if per_piece { p.lambda } else { lambda },
                    per_pixel: false,
                };
                let (Some(o), Some(zp)) = (
                    os.get_mut(off..end),
                    if Z {
                        zc.get_mut(off..end)
                    } else {
                        Some(&mut [][..])
                    },
                ) else {
                    break;
                };
                let shaded = if Z && S::DISCARDS && !S::BLENDS {
                    shade_linear::<S, C, D, true>(
                        &ctx.shader,
                        ctx.triangle,
                        &p.start,
                        &p.slope,
                        o,
                        zp,
                        m,
                        pos,
                    )
                } else {
                    shade_linear::<S, C, D, false>(
                        &ctx.shader,
                        ctx.triangle,
                        &p.start,
                        &p.slope,
                        o,
                        zp,
                        m,
                        pos,
                    )
                };
                if !Z || S::DISCARDS || S::BLENDS {
                    written += shaded;
                }
            }
            off = end;
        }
        if Z && !S::DISCARDS && !S::BLENDS {
            written += mask.count_ones();
        }
        z = z.wrapping_add(dz.wrapping_mul(n as i32));
        px = px.wrapping_add(n as i32);
    }
    written
}

/// A span that is one linear piece (affine, or subdivided and at most `2^log2_n` pixels)
/// and one chunk: the depth mask, then the piece shaded, with none of the chunk and piece
/// bookkeeping of [`run_linear`] (whose pixels it gives, bit for bit). Most spans of a
/// finely tessellated mesh are a few pixels long: this path is what they cost.
#[inline(always)]
fn run_short<
    S: Shader,
    C: TargetColor,
    D: DepthStage,
    const SUB: bool,
    const Z: bool,
    const INLINE: bool,
>(
    ctx: &SpanCtx<'_, S>,
    bound: &mut DepthBound,
    x: i32,
    y: i32,
    out: &mut [C],
    zrow: &mut [u16],
) -> u32 {
    let s = &ctx.setup;
    let n = out.len();
    if Z && zrow.len() < n {
        return 0;
    }
    // The level of detail at the span's first pixel serves the span and its one piece.
    let at_start = S::LOD && ctx.shader.lod_granularity() != LodGranularity::Triangle;
    let spec = FillSpec {
        pair: lod_pair::<S>().unwrap_or((0, 1)),
        lod: at_start,
        shift: ctx.coord_shift,
        live: S::INTERPOLATED,
    };
    let p = Linear::<S::Varyings, SUB>::only_piece(s, x, y, n as u32, spec);
    let dz = s.z.dx;
    let z = s.plane_at(&s.z, x, y);
    let pos = Pos {
        x,
        y,
        z,
        dz,
        lambda: if at_start { p.lambda } else { ctx.tri_lambda },
        per_pixel: false,
    };
    // A short span of a shader that keeps every pixel: depth tested in the shading loop.
    // Spans of any length when the shader has a loop of its own for them.
    if INLINE && Z && !S::DISCARDS && !S::BLENDS && (n <= FUSED_MAX || S::PIECE_DEPTH_LOOP) {
        return shade_depth_inline::<S, C>(
            &ctx.shader,
            ctx.triangle,
            &p.start,
            &p.slope,
            out,
            zrow,
            pos,
        );
    }
    // The inlined copy leaves the depth floor to the triangle (see `inline_short_path`).
    let mask = chunk_mask::<S, Z, false, INLINE>(z, dz, zrow, n, bound);
    if mask == 0 {
        return 0;
    }
    // The shading loop counts what it writes: for a shader that never discards that is
    // every pixel of the mask (no population count per span).
    let shade = match (Z && S::DISCARDS && !S::BLENDS, INLINE) {
        (true, true) => shade_linear_inline::<S, C, D, true>,
        (false, true) => shade_linear_inline::<S, C, D, false>,
        (true, false) => shade_linear::<S, C, D, true>,
        (false, false) => shade_linear::<S, C, D, false>,
    };
    shade(
        &ctx.shader,
        ctx.triangle,
        &p.start,
        &p.slope,
        out,
        zrow,
        mask,
        pos,
    )
}

/// Whether [`span`] may take [`run_short`]: always, except in this module's tests, which
/// draw the same triangles through both paths and compare.
#[cfg(not(test))]
#[inline(always)]
fn short_path_on() -> bool {
    true
}

#[cfg(test)]
extern crate std;

#[cfg(test)]
std::thread_local! {
    static SHORT_PATH: core::cell::Cell<bool> = const { core::cell::Cell::new(true) };
}

#[cfg(test)]
fn short_path_on() -> bool {
    SHORT_PATH.with(|c| c.get())
}

/// The level of detail handed to the shader: `(fixed value, per pixel or piece?)`.
#[inline(always)]
fn lod_policy<S: Shader>(ctx: &SpanCtx<'_, S>, at_start: impl FnOnce() -> i32) -> (i32, bool) {
    if !S::LOD {
        return (0, false);
    }
    match ctx.shader.lod_granularity() {
        LodGranularity::Triangle => (ctx.tri_lambda, false),
        LodGranularity::Span => (at_start(), false),
        LodGranularity::Pixel => (0, true),
    }
}

#[inline(always)]
fn run<S: Shader, C: TargetColor, D: DepthStage, I: Fill<S::Varyings>, const Z: bool>(
    ctx: &SpanCtx<'_, S>,
    bound: &mut DepthBound,
    scratch: &mut Scratch<S::Varyings>,
    x: i32,
    y: i32,
    out: &mut [C],
    zrow: &mut [u16],
) -> u32 {
    let s = &ctx.setup;
    let pair = lod_pair::<S>().unwrap_or((0, 1));
    let mut it = I::start_as(s, x, y, out.len() as u32, ctx.log2_n, ctx.kind);
    let (lambda, per_pixel) = lod_policy(ctx, || it.lambda(s, pair));
    let spec = FillSpec {
        pair,
        lod: per_pixel,
        shift: ctx.coord_shift,
        live: S::INTERPOLATED,
    };
    let dz = s.z.dx;
    let mut z = s.plane_at(&s.z, x, y);
    let mut px = x;
    let mut written = 0u32;
    let Scratch { vals, lambdas } = scratch;
    if spec.lod && lambdas.is_none() {
        *lambdas = Some([0; CHUNK]);
    }
    // `Z` links the depth code; an empty depth row switches it off at run time (the small
    // span loops use one instance for both).
    let depth = Z && !zrow.is_empty();
    let mut zs: &mut [u16] = zrow;
    for os in out.chunks_mut(CHUNK) {
        let n = os.len();
        let (zc, zrest) = if depth {
            let Some(split) = (n <= zs.len()).then(|| core::mem::take(&mut zs).split_at_mut(n))
            else {
                break;
            };
            split
        } else {
            (&mut [][..], &mut [][..])
        };
        zs = zrest;
        let mask = if depth {
            chunk_mask::<S, true, true, false>(z, dz, zc, n, bound)
        } else {
            low_bits(n)
        };
        let ls: &mut [i32] = match lambdas {
            Some(l) => l.get_mut(..n).unwrap_or_default(),
            None => &mut [],
        };
        let Some(vs) = vals.get_mut(..n) else {
            break;
        };
        it.fill(s, vs, ls, mask, spec);
        if mask != 0 {
            let pos = Pos {
                x: px,
                y,
                z,
                dz,
                lambda,
                per_pixel: spec.lod,
            };
            // The shading loop counts what it writes (a full chunk without a count per
            // pixel), so no population count per chunk.
            written += if depth && S::DISCARDS && !S::BLENDS {
                shade_chunk::<S, C, D, true>(&ctx.shader, ctx.triangle, vs, ls, os, zc, mask, pos)
            } else {
                shade_chunk::<S, C, D, false>(&ctx.shader, ctx.triangle, vs, ls, os, zc, mask, pos)
            };
        }
        z = z.wrapping_add(dz.wrapping_mul(n as i32));
        px = px.wrapping_add(n as i32);
    }
    written
}

/// The projection of a span (the draw's, or the run-time one) and whether it is affine.
#[inline(always)]
fn kind_of<S: Shader, P: ProjectionStage>(ctx: &SpanCtx<'_, S>) -> (ProjKind, bool) {
    let kind = match P::KIND {
        ProjKind::Dynamic => ctx.kind,
        k => k,
    };
    let affine = match kind {
        ProjKind::Affine => true,
        ProjKind::Adaptive => ctx.setup.affine,
        _ => false,
    };
    (kind, affine)
}

/// `Some(affine)` when a span of `len` pixels takes the short path ([`run_short`]): one
/// chunk that is one linear piece. (A quadratic span of at most three pixels is one chord,
/// the subdivided mode's.)
#[inline(always)]
fn short_piece<S: Shader, P: ProjectionStage>(ctx: &SpanCtx<'_, S>, len: usize) -> Option<bool> {
    let long = !S::SMALL && ctx.log2_n >= 4;
    let (kind, affine) = kind_of::<S, P>(ctx);
    let one_piece = affine
        || (kind == ProjKind::Subdivided && long && len <= 1 << ctx.log2_n.clamp(1, 6))
        || (kind == ProjKind::Quadratic && len <= 3);
    (!S::SMALL && one_piece && len <= CHUNK && short_path_on()).then_some(affine)
}

/// [`run_short`] for either interpolation and with or without a depth row.
#[inline(always)]
fn run_short_any<S: Shader, C: TargetColor, D: DepthStage, const INLINE: bool>(
    ctx: &SpanCtx<'_, S>,
    bound: &mut DepthBound,
    x0: i32,
    y: i32,
    out: &mut [C],
    zrow: Option<&mut [u16]>,
    affine: bool,
) -> u32 {
    match (affine, zrow) {
        (true, Some(z)) => run_short::<S, C, D, false, true, INLINE>(ctx, bound, x0, y, out, z),
        (true, None) => run_short::<S, C, D, false, false, INLINE>(ctx, bound, x0, y, out, &mut []),
        (false, Some(z)) => run_short::<S, C, D, true, true, INLINE>(ctx, bound, x0, y, out, z),
        (false, None) => run_short::<S, C, D, true, false, INLINE>(ctx, bound, x0, y, out, &mut []),
    }
}

/// [`span`]'s short path alone, inlined into the rasterizer's span writer: most spans of a
/// finely tessellated mesh are a few pixels long, and this way they cost no call and no
/// reload of the shader's uniforms. `None` for a span it does not take (then [`span`],
/// out of line, draws it, with the shading loops it had).
///
/// The inlined copy of the shading loop costs flash (about 2 KB for the lit footprint
/// loop on Cortex-M4F), so only the draws it serves link it: depth-tested (meshes),
/// without a per-pixel level of detail, and with a projection for meshes of small
/// triangles (affine or adaptive: one piece per span). Subdivided and quadratic draws
/// (floors, big faces) gain nothing from it, and with every mode inlined a multi-mode
/// report firmware of mip modes outgrows the 256 KB of flash.
#[inline(always)]
#[allow(clippy::too_many_arguments)]
pub(crate) fn span_short<S: Shader, P: ProjectionStage, D: DepthStage, C: TargetColor>(
    ctx: &SpanCtx<'_, S>,
    bound: &mut DepthBound,
    y: i32,
    x0: i32,
    out: &mut [C],
    depth: Option<&mut [u16]>,
    known_affine: bool,
) -> Option<u32> {
    if !inline_short_path::<S, P, D>() {
        return None;
    }
    // A triangle known to be affine (`known_affine`, a constant where it is inlined) skips
    // the per-span test of its set-up's flag.
    let affine = if known_affine && !S::SMALL && out.len() <= CHUNK && short_path_on() {
        true
    } else {
        short_piece::<S, P>(ctx, out.len())?
    };
    let zrow = if D::TEST && depth_enabled::<S, P>(ctx) {
        depth
    } else {
        None
    };
    Some(run_short_any::<S, C, D, true>(
        ctx, bound, x0, y, out, zrow, affine,
    ))
}

/// Whether the span writer inlines the short path ([`span_short`]): depth-tested draws
/// without a per-pixel level of detail and with a projection for meshes of small triangles.
/// Their short spans do not keep the depth floor's bound: the triangle takes it from its
/// vertices' depths once (`raster_shaded`).
pub(crate) const fn inline_short_path<S: Shader, P: ProjectionStage, D: DepthStage>() -> bool {
    D::TEST && !S::LOD && matches!(P::KIND, ProjKind::Affine | ProjKind::Adaptive)
}

/// Whether the draw tests depth, given that its depth stage does
/// ([`DepthStage::TEST`]): a typed draw's stages are its mode, so only the run-time
/// projection's draws (`Draw::dynamic`) read their run-time switch (one test fewer per span
/// for the others). `raster_shaded` checks that a typed draw never turns it off.
///
/// With the short path's known affine flag this saves the whole-frame sphere about 1.5 % on
/// Cortex-M4F and 0.5 % on RV32IMC (measure with `cargo xtask mcu`). ARMv6-M reads the
/// switch always: without the read its span writer allocates registers worse and costs a
/// little more. Only the inlined short path ([`span_short`]) uses it: the out-of-line span
/// loop ([`span`]) reads the switch, as without it the span loop's registers allocate worse
/// and the whole-frame cube costs about 1 % more on Cortex-M4F.
#[inline(always)]
pub(crate) fn depth_enabled<S: Shader, P: ProjectionStage>(ctx: &SpanCtx<'_, S>) -> bool {
    (P::KIND != ProjKind::Dynamic && !crate::math::ARMV6M) || ctx.depth_on
}

/// The span's depths when the draw tests depth. On ARMv6-M they are cut to the span's
/// length first (they are the same pixels: the cut only tells the loops that both slices
/// are as long), which there keeps a depth step in a register (about 2 % of the Cortex-M0+
/// nearest floor); on Cortex-M4F and x86-64 the cut costs about 1 % of the floor, so it is
/// not made there (measure with `cargo xtask mcu` and `cargo xtask count`).
#[inline(always)]
fn span_depth<'z, S: Shader, D: DepthStage>(
    ctx: &SpanCtx<'_, S>,
    depth: Option<&'z mut [u16]>,
    len: usize,
) -> Option<&'z mut [u16]> {
    const CUT: bool = cfg!(all(target_arch = "arm", not(target_has_atomic = "32")));
    if !(D::TEST && ctx.depth_on) {
        None
    } else if CUT {
        depth.and_then(|d| d.get_mut(..len))
    } else {
        depth
    }
}

/// Draws the span `out` (pixels `x0..` of row `y`) and its depths `depth` (the same
/// pixels), sliced out of the target by the writer, and returns the pixels written.
#[inline(never)]
#[allow(clippy::too_many_arguments)]
pub(crate) fn span<S: Shader, P: ProjectionStage, D: DepthStage, C: TargetColor>(
    ctx: &SpanCtx<'_, S>,
    bound: &mut DepthBound,
    scratch: &mut Option<Scratch<S::Varyings>>,
    y: i32,
    x0: i32,
    out: &mut [C],
    depth: Option<&mut [u16]>,
) -> u32 {
    let zrow = span_depth::<S, D>(ctx, depth, out.len());
    type E<S> = ExactInterp<<S as Shader>::Varyings>;
    type L<S, const SUB: bool> = Linear<<S as Shader>::Varyings, SUB>;
    type Q<S> = Quadratic<<S as Shader>::Varyings, false>;
    type Dy<S> = DynInterp<<S as Shader>::Varyings>;
    // The run-time projection fills chunks through one loop for every perspective mode.
    let dynamic = P::KIND == ProjKind::Dynamic;
    // Long linear pieces step their varyings inside the shading loop; short ones (N < 16)
    // are filled into the chunk's array first, which costs a store and a load per varying
    // but one shading call per chunk instead of one per piece.
    let long = !S::SMALL && ctx.log2_n >= 4;
    let (kind, affine) = kind_of::<S, P>(ctx);
    if let Some(affine) = short_piece::<S, P>(ctx, out.len()) {
        return run_short_any::<S, C, D, false>(ctx, bound, x0, y, out, zrow, affine);
    }
    match (kind, affine, zrow) {
        (_, true, Some(z)) if S::SMALL => {
            run::<S, C, D, L<S, false>, true>(ctx, bound, Scratch::of(scratch), x0, y, out, z)
        }
        (_, true, None) if S::SMALL => {
            run::<S, C, D, L<S, false>, true>(ctx, bound, Scratch::of(scratch), x0, y, out, &mut [])
        }
        (_, true, Some(z)) => run_linear::<S, C, D, false, true>(ctx, bound, x0, y, out, z),
        (_, true, None) => run_linear::<S, C, D, false, false>(ctx, bound, x0, y, out, &mut []),
        (ProjKind::Subdivided, _, Some(z)) if long => {
            run_linear::<S, C, D, true, true>(ctx, bound, x0, y, out, z)
        }
        (ProjKind::Subdivided, _, None) if long => {
            run_linear::<S, C, D, true, false>(ctx, bound, x0, y, out, &mut [])
        }
        (_, _, Some(z)) if dynamic => {
            run::<S, C, D, Dy<S>, true>(ctx, bound, Scratch::of(scratch), x0, y, out, z)
        }
        (_, _, None) if dynamic && S::SMALL => {
            run::<S, C, D, Dy<S>, true>(ctx, bound, Scratch::of(scratch), x0, y, out, &mut [])
        }
        (_, _, None) if dynamic => {
            run::<S, C, D, Dy<S>, false>(ctx, bound, Scratch::of(scratch), x0, y, out, &mut [])
        }
        (ProjKind::Subdivided, _, Some(z)) => {
            run::<S, C, D, L<S, true>, true>(ctx, bound, Scratch::of(scratch), x0, y, out, z)
        }
        (ProjKind::Subdivided, _, None) if S::SMALL => {
            run::<S, C, D, L<S, true>, true>(ctx, bound, Scratch::of(scratch), x0, y, out, &mut [])
        }
        (ProjKind::Subdivided, _, None) => {
            run::<S, C, D, L<S, true>, false>(ctx, bound, Scratch::of(scratch), x0, y, out, &mut [])
        }
        (ProjKind::Quadratic, _, Some(z)) => {
            run::<S, C, D, Q<S>, true>(ctx, bound, Scratch::of(scratch), x0, y, out, z)
        }
        (ProjKind::Quadratic, _, None) if S::SMALL => {
            run::<S, C, D, Q<S>, true>(ctx, bound, Scratch::of(scratch), x0, y, out, &mut [])
        }
        (ProjKind::Quadratic, _, None) => {
            run::<S, C, D, Q<S>, false>(ctx, bound, Scratch::of(scratch), x0, y, out, &mut [])
        }
        (_, _, Some(z)) => {
            run::<S, C, D, E<S>, true>(ctx, bound, Scratch::of(scratch), x0, y, out, z)
        }
        (_, _, None) if S::SMALL => {
            run::<S, C, D, E<S>, true>(ctx, bound, Scratch::of(scratch), x0, y, out, &mut [])
        }
        (_, _, None) => {
            run::<S, C, D, E<S>, false>(ctx, bound, Scratch::of(scratch), x0, y, out, &mut [])
        }
    }
}

#[cfg(test)]
mod tests;
