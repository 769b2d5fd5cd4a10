//! The shading loops of the span loop: the shader for each visible pixel of a chunk and the
//! store, from varyings filled into the chunk's array ([`shade_chunk`]) or stepped in
//! registers along a linear piece ([`shade_linear`], and [`shade_linear_inline`] for the
//! short path). A blending shader reads the pixel it covers; a discarding one writes its
//! depth here (the depth pass, [`super::depth_pass`], only tested it).

use super::depth_pass::{low_bits, low_bits_short};
use crate::color::TargetColor;
use crate::pipeline::interp::step_live;
use crate::pipeline::stages::DepthStage;
use crate::shading::{Fragment, Shader};

/// The shader's colour for one pixel whose current value is `o`: over it for a blending
/// shader, alone otherwise (decided at compile time).
#[inline(always)]
pub(super) fn color<S: Shader, C: TargetColor>(
    shader: &S,
    f: &Fragment<S::Varyings, S::Triangle>,
    o: &C,
) -> Option<u16> {
    if S::BLENDS {
        shader.shade_over(f, o.to_rgb565())
    } else {
        shader.shade(f)
    }
}

/// Where a chunk starts, for the fragments' position fields and the level of detail.
#[derive(Clone, Copy, Debug)]
pub(super) struct Pos {
    pub x: i32,
    pub y: i32,
    pub z: i32,
    pub dz: i32,
    /// The level of detail when it is not per pixel.
    pub lambda: i32,
    /// Read `lambdas` instead of `lambda`.
    pub per_pixel: bool,
}

/// Shades the pixels of `out` whose bit is set in `mask` (bit 0 = first pixel) from the
/// filled `vals`; with `ZW` (a shader that discards) writes their depth to `zrow` as well.
/// Returns the pixels written. Not inlined: its registers are allocated on their own, so
/// the shader's uniforms stay in registers through the loop. As [`shade_linear`], a draw
/// without a depth stage (`D`) links only one of the two loops.
#[inline(never)]
#[allow(clippy::too_many_arguments)]
pub(super) fn shade_chunk<S: Shader, C: TargetColor, D: DepthStage, const ZW: bool>(
    shader: &S,
    triangle: S::Triangle,
    vals: &[S::Varyings],
    lambdas: &[i32],
    out: &mut [C],
    zrow: &mut [u16],
    mask: u32,
    pos: Pos,
) -> u32 {
    let shader = *shader;
    if !shader.can_draw() {
        return 0;
    }
    let frag = |v: S::Varyings, k: usize| Fragment {
        varyings: v,
        x: pos.x.wrapping_add(k as i32),
        y: pos.y,
        depth: (pos.z.wrapping_add(pos.dz.wrapping_mul(k as i32)) >> 14).clamp(0, 0xFFFF) as u16,
        lambda: if pos.per_pixel {
            lambdas.get(k).copied().unwrap_or(0)
        } else {
            pos.lambda
        },
        triangle,
    };
    let mut written = 0u32;
    if !S::SMALL && !ZW && !S::DISCARDS && (!D::TEST || mask == low_bits(out.len())) {
        for (k, (o, v)) in out.iter_mut().zip(vals).enumerate() {
            if let Some(c) = color(&shader, &frag(*v, k), o) {
                *o = C::from_rgb565(c);
            }
        }
        return out.len().min(vals.len()) as u32;
    }
    let mut m = mask;
    for (k, (o, v)) in out.iter_mut().zip(vals).enumerate() {
        if m & 1 != 0 {
            let f = frag(*v, k);
            if let Some(c) = color(&shader, &f, o) {
                *o = C::from_rgb565(c);
                if ZW {
                    if let Some(zb) = zrow.get_mut(k) {
                        *zb = f.depth;
                    }
                }
                written += 1;
            }
        }
        m >>= 1;
    }
    written
}

/// The unmasked loop of [`shade_linear_fn`]: every pixel of `$out`, a fully visible linear
/// piece whose varyings `$v` change by `$slope` per pixel, shaded by `$colour` (from the
/// fragment `$f` and the pixel `$o`), then returns the pixels written. A macro, not a
/// function taking the shading call as a closure: the closure form costs the Cortex-M0+
/// whole sphere about half a percent, the macro nothing (measure with `cargo xtask mcu`).
macro_rules! shade_every {
    ($out:ident, $v:ident, $slope:ident, $frag:ident, |$f:ident, $o:ident| $colour:expr) => {
        for (k, $o) in $out.iter_mut().enumerate() {
            let $f = &$frag($v, k);
            if let Some(c) = $colour {
                *$o = C::from_rgb565(c);
            }
            step_live(&mut $v, &$slope, S::INTERPOLATED);
        }
        return $out.len() as u32;
    };
}

/// Defines a linear-piece shading loop (`shade_linear` and its inlined twin): one body,
/// two inlining decisions. A body that is itself `#[inline(always)]` inside the
/// out-of-line function costs about one instruction per pixel more on Cortex-M4F (LLVM
/// inlines its callees in another order), so the two are expanded separately.
macro_rules! shade_linear_fn {
    ($(#[$attr:meta])* $name:ident, $full:ident) => {
        $(#[$attr])*
        #[allow(clippy::too_many_arguments)]
        pub(super) fn $name<S: Shader, C: TargetColor, D: DepthStage, const ZW: bool>(
            shader: &S,
            triangle: S::Triangle,
            start: &S::Varyings,
            slope: &S::Varyings,
            out: &mut [C],
            zrow: &mut [u16],
            mask: u32,
            pos: Pos,
        ) -> u32 {
            let shader = *shader;
            if !shader.can_draw() {
                return 0;
            }
            let slope = *slope;
            let mut v = *start;
            let frag = |v: S::Varyings, k: usize| Fragment {
                varyings: v,
                x: pos.x.wrapping_add(k as i32),
                y: pos.y,
                depth: (pos.z.wrapping_add(pos.dz.wrapping_mul(k as i32)) >> 14).clamp(0, 0xFFFF) as u16,
                lambda: pos.lambda,
                triangle,
            };
            let mut written = 0u32;
            if !ZW && !S::DISCARDS && (!D::TEST || mask == $full(out.len())) {
                if !S::BLENDS && shader.piece_in_range(&v, &slope, out.len() as u32) {
                    // Only on targets where a shader can have such a loop (ARMv7E-M).
                    #[cfg(fixel_dsp)]
                    if let Some(raw) = crate::color::raw_rgb565_mut(out) {
                        if shader.shade_piece_rgb565(&v, &slope, raw) {
                            return raw.len() as u32;
                        }
                    }
                    shade_every!(out, v, slope, frag, |f, _o| shader.shade_in_range(f));
                }
                shade_every!(out, v, slope, frag, |f, o| color(&shader, f, o));
            }
            let mut m = mask;
            for (k, o) in out.iter_mut().enumerate() {
                if m & 1 != 0 {
                    let f = frag(v, k);
                    if let Some(c) = color(&shader, &f, o) {
                        *o = C::from_rgb565(c);
                        if ZW {
                            if let Some(zb) = zrow.get_mut(k) {
                                *zb = f.depth;
                            }
                        }
                        written += 1;
                    }
                }
                m >>= 1;
                step_live(&mut v, &slope, S::INTERPOLATED);
            }
            written
        }
    };
}

shade_linear_fn!(
    /// Like [`shade_chunk`] for a linear piece: the varyings start at `start` and change by
    /// `slope` per pixel, stepped here in registers. For a draw without a depth stage (`D`)
    /// and a shader that never discards, every mask is full: only the unmasked loop is
    /// linked (about 0.7 KB less on Cortex-M4F).
    #[inline(never)]
    shade_linear,
    low_bits
);

shade_linear_fn!(
    /// [`shade_linear`] inlined, for the short path ([`span_short`](super::span_short)): a short span then
    /// costs no call and no reload of the shader's uniforms.
    /// Its spans are never empty and at most a chunk long (the full mask is
    /// [`low_bits_short`]).
    #[inline(always)]
    shade_linear_inline,
    low_bits_short
);

/// The inlined short path's loop with the depth test in it: for each pixel, the 16-bit
/// depth (`z >> 14` saturated) tested (`GL_LESS`) and written, then the shader and the
/// store, for a shader that neither discards nor blends. The same pixels and depths as the
/// depth pass ([`super::depth_pass`]) followed by [`shade_linear_inline`], without the mask
/// between them. Returns the pixels that passed the test.
#[inline(always)]
#[allow(clippy::too_many_arguments)]
pub(super) fn shade_depth_inline<S: Shader, C: TargetColor>(
    shader: &S,
    triangle: S::Triangle,
    start: &S::Varyings,
    slope: &S::Varyings,
    out: &mut [C],
    zrow: &mut [u16],
    pos: Pos,
) -> u32 {
    let shader = *shader;
    let (mut z, dz) = (pos.z, pos.dz);
    if !shader.can_draw() {
        // The depths alone, as the depth pass writes them before the shading loop (which
        // then writes nothing).
        super::depth_pass::depth_chunk::<true>(z, dz, zrow);
        return 0;
    }
    let slope = *slope;
    let mut v = *start;
    let mut hidden = 0u32;
    macro_rules! fused {
        (|$f:ident, $o:ident| $colour:expr) => {
            for (k, ($o, zb)) in out.iter_mut().zip(zrow.iter_mut()).enumerate() {
                let d = super::depth_pass::depth_of::<true>(z);
                if d < i32::from(*zb) {
                    *zb = d as u16;
                    let $f = &Fragment {
                        varyings: v,
                        x: pos.x.wrapping_add(k as i32),
                        y: pos.y,
                        depth: d as u16,
                        lambda: pos.lambda,
                        triangle,
                    };
                    if let Some(c) = $colour {
                        *$o = C::from_rgb565(c);
                    }
                } else {
                    hidden += 1;
                }
                z = z.wrapping_add(dz);
                step_live(&mut v, &slope, S::INTERPOLATED);
            }
        };
    }
    if shader.piece_in_range(&v, &slope, out.len() as u32) {
        // The shader's own loop, on targets where it can have one (ARMv7E-M).
        #[cfg(fixel_dsp)]
        if let Some(raw) = crate::color::raw_rgb565_mut(out) {
            if let Some(shown) = shader.shade_piece_depth_rgb565(&v, &slope, (z, dz), raw, zrow) {
                return shown;
            }
        }
        fused!(|f, _o| shader.shade_in_range(f));
    } else {
        fused!(|f, o| color(&shader, f, o));
    }
    (out.len().min(zrow.len()) as u32).wrapping_sub(hidden)
}
