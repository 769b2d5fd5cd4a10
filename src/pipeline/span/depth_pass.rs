//! The depth pass of the span loop: per chunk of up to 32 pixels, the 16-bit depths
//! (`z >> 14` saturated, `z` the Q14 plane value) tested (`GL_LESS`) and, for shaders that
//! never discard, written, collecting a visibility mask (bit `k` = pixel `k`); and the
//! target's depth floor ([`DepthBound`]), which lets a chunk nearer than everything stored
//! skip reading depth.
//!
//! Kept apart from the shading loops ([`super::shade_loop`]) so each pass keeps few values
//! live: nothing spills on a 13-register Cortex-M core.

use crate::shading::Shader;

/// The mask with the low `n` bits set (`n <= 32`).
#[inline(always)]
pub(super) fn low_bits(n: usize) -> u32 {
    if n >= 32 {
        u32::MAX
    } else {
        (1u32 << n) - 1
    }
}

/// [`low_bits`] for `n` in `1..=32`, as the inlined short path's spans are (the
/// rasterizer emits no empty span; [`super::span_short`] takes at most a chunk): all ones
/// shifted right, two instructions on Cortex-M against six. Any mask for `n = 0`, where
/// the depth mask it is anded with is empty, and the shading loop has no pixel.
///
/// This saves a fraction of a percent of the whole-frame sphere on Cortex-M4F and RV32IMC
/// (measure with `cargo xtask mcu`). ARMv6-M keeps [`low_bits`]: its shifts by a register
/// do not mask the amount, so the wrapping shift costs an `and` and this form costs more.
#[inline(always)]
pub(super) fn low_bits_short(n: usize) -> u32 {
    if crate::math::ARMV6M {
        low_bits(n)
    } else {
        u32::MAX.wrapping_shr(32u32.wrapping_sub(n as u32))
    }
}

/// Depth test of one chunk (`GL_LESS`, depth `z >> 14` saturated to 16 bits): bit `k` of
/// the result is set when pixel `k` passes. With `WRITE`, passing depths are written.
#[inline(always)]
pub(super) fn depth_chunk<const WRITE: bool>(z0: i32, dz: i32, zrow: &mut [u16]) -> u32 {
    if in_depth_range(z0, dz, zrow.len()) {
        depth_chunk_with::<WRITE, false>(z0, dz, zrow)
    } else {
        depth_chunk_with::<WRITE, true>(z0, dz, zrow)
    }
}

#[inline(always)]
fn depth_chunk_with<const WRITE: bool, const CLAMP: bool>(
    z0: i32,
    dz: i32,
    zrow: &mut [u16],
) -> u32 {
    let mut z = z0;
    let mut m = 0u32;
    let mut bit = 1u32;
    for zb in zrow.iter_mut() {
        let d = depth_of::<CLAMP>(z);
        if d < i32::from(*zb) {
            if WRITE {
                *zb = d as u16;
            }
            m |= bit;
        }
        bit <<= 1;
        z = z.wrapping_add(dz);
    }
    m
}

/// Depth-tests chunk `zc` (when `Z`) and returns its visibility mask (`n` pixels). With
/// `FLOOR`, a chunk nearer than the target's depth floor writes its depths without reading
/// them; without, every chunk reads them (the short spans of small triangles: there the
/// test costs more than it saves, see [`super::run_short`]). The chunk lowers `bound.lowest`
/// to its nearest depth, so later draws may rely on the floor, unless `TRI_BOUND` (the short
/// path inlined into the span writer, see [`super::span_short`]): then the triangle lowers
/// it once from its vertices' depths (`raster_shaded`), which saves about 1 % of the
/// whole-frame footprint sphere on Cortex-M4F and RV32IMC and less on Cortex-M0+ (measure
/// with `cargo xtask mcu`). The triangle bound is not used for every draw's triangles: it
/// costs the cube about 2 % (a face's nearest vertex can be far nearer than what a band of
/// it writes); chosen per triangle at run time (by height), it costs the sphere about 3 %.
#[inline(always)]
pub(super) fn chunk_mask<S: Shader, const Z: bool, const FLOOR: bool, const TRI_BOUND: bool>(
    z: i32,
    dz: i32,
    zc: &mut [u16],
    n: usize,
    bound: &mut DepthBound,
) -> u32 {
    // The inlined short path's spans are never empty and at most a chunk long. (A closure,
    // not a choice between two function items: that becomes a function pointer, which costs
    // the Cortex-M0+ shadow scene about 2 %.)
    let low_bits = |n: usize| {
        if TRI_BOUND {
            low_bits_short(n)
        } else {
            low_bits(n)
        }
    };
    if !Z {
        return low_bits(n);
    }
    let (d_lo, d_hi) = chunk_depth_range(z, dz, n);
    let mask = if S::DISCARDS || S::BLENDS {
        // Test only: depth is written for the pixels a discarding shader keeps, and never
        // for a blending one.
        depth_chunk::<false>(z, dz, zc) & low_bits(n)
    } else if FLOOR && d_hi < bound.floor {
        // Nearer than everything stored: every pixel passes, no depth is read.
        depth_fill(z, dz, zc);
        low_bits(n)
    } else {
        depth_chunk::<true>(z, dz, zc) & low_bits(n)
    };
    if !TRI_BOUND && mask != 0 {
        bound.lowest = bound.lowest.min(d_lo);
    }
    mask
}

/// The lowest and highest 16-bit depth among the `n` pixels `z + k dz` (`k < n`,
/// `1 <= n <= 32`) of a chunk, as [`depth_of`] stores them from the wrapping `i32` steps of
/// the span loops.
///
/// Why the bounds hold: when the exact sum `z + (n - 1) dz` is an `i32` (the product is
/// exact in `i32` for `|dz| < 2^26`, checked above), no step wraps (every `z + k dz` lies
/// between the ends, so the wrapping steps compute it exactly). The depth is the plane
/// value shifted and clamped, a non-decreasing function of it, so over a linear run its
/// extremes are at the ends. Otherwise some step may wrap, and a wrapped step can store any
/// depth: the bounds are then the whole range `(0, 0xFFFF)`, so the chunk never takes the
/// floor's fast path and lowers the floor to 0. (Depth planes whose steps wrap come only
/// from triangles clipped near the limits of the clip-space format.)
#[inline(always)]
fn chunk_depth_range(z: i32, dz: i32, n: usize) -> (u16, u16) {
    let d = |z: i32| (z >> 14).clamp(0, 0xFFFF) as u16;
    let steps = n as i32 - 1;
    // Below 2^26 the product is exact (`steps <= 31`): no 64-bit multiply on ARMv6-M.
    let run = if dz.unsigned_abs() < 1 << 26 {
        Some(dz.wrapping_mul(steps))
    } else {
        dz.checked_mul(steps)
    };
    match run.and_then(|run| z.checked_add(run)) {
        Some(z_end) => (d(z.min(z_end)), d(z.max(z_end))),
        None => (0, 0xFFFF),
    }
}

/// Writes the chunk's depths (all of them pass the test).
#[inline(always)]
fn depth_fill(z0: i32, dz: i32, zrow: &mut [u16]) {
    if in_depth_range(z0, dz, zrow.len()) {
        depth_fill_with::<false>(z0, dz, zrow)
    } else {
        depth_fill_with::<true>(z0, dz, zrow)
    }
}

#[inline(always)]
fn depth_fill_with<const CLAMP: bool>(z0: i32, dz: i32, zrow: &mut [u16]) {
    let mut z = z0;
    for zb in zrow.iter_mut() {
        *zb = depth_of::<CLAMP>(z) as u16;
        z = z.wrapping_add(dz);
    }
}

/// Whether the `n` depths `z0 + k dz` of a chunk are all within the 16-bit depth range
/// (`z >> 14` in `0..=0xFFFF`, so `z` in `0..2^30`). Depth is linear along the chunk, so it
/// is enough that both ends are, provided nothing wraps: with `n <= 32` and `|dz| < 2^25`,
/// `|dz (n - 1)| < 2^30` and the end is exact in `i32`. Then the loops skip the clamp (four
/// instructions per pixel on x86-64). Always false on Arm ([`SKIP_CLAMP`]).
#[inline(always)]
fn in_depth_range(z0: i32, dz: i32, n: usize) -> bool {
    const TOP: u32 = 1 << 30;
    let z_end = z0.wrapping_add(dz.wrapping_mul(n as i32 - 1));
    SKIP_CLAMP
        && n <= 32
        && dz.unsigned_abs() < 1 << 25
        && (z0 as u32) < TOP
        && (z_end as u32) < TOP
}

/// Whether depth loops test for a chunk they need not clamp ([`in_depth_range`]): on x86-64
/// and RV32 the loop without the clamp saves about 5-10 % of the nearest floor and 2 % of
/// the cube (measure with `cargo xtask count` and `cargo xtask mcu`). Not on Arm: Armv7-M
/// clamps in one `usat`, and the second loop costs the Cortex-M4F cube and floor about 2-5 %;
/// on Cortex-M0+ the large-span scenes gain but the meshes of small triangles lose a little.
const SKIP_CLAMP: bool = !cfg!(target_arch = "arm");

/// The 16-bit depth of `z` (Q14 above the depth), `0..=0xFFFF`: clamped with `CLAMP`, else
/// `z` must be in range (see [`in_depth_range`]).
#[inline(always)]
pub(super) fn depth_of<const CLAMP: bool>(z: i32) -> i32 {
    if CLAMP {
        (z >> 14).clamp(0, 0xFFFF)
    } else {
        z >> 14
    }
}

/// The target's depth floor for one span (see `RenderTarget::depth_floor`) and the lowest
/// depth the span may have written.
#[derive(Clone, Copy, Debug)]
pub(crate) struct DepthBound {
    /// Every stored depth is at least this when the span starts.
    pub floor: u16,
    /// A lower bound of the depths the span wrote (`u16::MAX` when none), but for the
    /// inlined short path's, which the triangle bounds once ([`super::span_short`]).
    pub lowest: u16,
}

#[cfg(test)]
mod tests {
    extern crate std;
    use super::*;
    use crate::test_rng::Rng;
    use std::vec::Vec;

    /// The short path's mask is [`low_bits`] for every span it takes (1 to 32 pixels).
    #[test]
    fn short_masks_are_low_bits() {
        for n in 1..=32 {
            assert_eq!(low_bits_short(n), low_bits(n), "{n}");
        }
    }

    /// The depth loops that skip the clamp write and test the same bits as the clamped
    /// ones, on chunks in range, across its edges and with steep slopes.
    #[test]
    fn unclamped_depth_loops_match_clamped_ones() {
        let mut rng = Rng(0xDE97_4C1A);
        let r32 = |rng: &mut Rng| (rng.next() >> 32) as u32;
        let edges = [
            0,
            1,
            0x3FFF,
            0x4000,
            (1 << 30) - 1,
            1 << 30,
            i32::MAX,
            -1,
            i32::MIN,
        ];
        let pick = |rng: &mut Rng, spread: u32| {
            let base = edges[(r32(rng) % edges.len() as u32) as usize];
            base.wrapping_add((r32(rng) % (2 * spread + 1)) as i32 - spread as i32)
        };
        let mut skipped = 0;
        for round in 0..200_000 {
            let z0 = if round % 2 == 0 {
                pick(&mut rng, 1 << 20)
            } else {
                r32(&mut rng) as i32
            };
            let dz = match round % 3 {
                0 => (r32(&mut rng) as i32) >> (r32(&mut rng) % 32),
                1 => pick(&mut rng, 1 << 12),
                _ => r32(&mut rng) as i32,
            };
            let n = 1 + (r32(&mut rng) % 32) as usize;
            skipped += usize::from(super::in_depth_range(z0, dz, n));
            let stored: Vec<u16> = (0..n).map(|_| r32(&mut rng) as u16).collect();
            let (mut a, mut b) = (stored.clone(), stored.clone());
            depth_fill(z0, dz, &mut a);
            depth_fill_with::<true>(z0, dz, &mut b);
            assert_eq!(a, b, "fill z0 {z0} dz {dz} n {n}");
            let (mut a, mut b) = (stored.clone(), stored.clone());
            let ma = depth_chunk::<true>(z0, dz, &mut a);
            let mb = depth_chunk_with::<true, true>(z0, dz, &mut b);
            assert_eq!((ma, &a), (mb, &b), "test+write z0 {z0} dz {dz} n {n}");
            let (mut a, mut b) = (stored.clone(), stored);
            let ma = depth_chunk::<false>(z0, dz, &mut a);
            let mb = depth_chunk_with::<false, true>(z0, dz, &mut b);
            assert_eq!((ma, &a), (mb, &b), "test z0 {z0} dz {dz} n {n}");
        }
        // On the host (not Arm) the unclamped loops must actually have run.
        assert!(skipped > 20_000, "only {skipped} chunks skipped the clamp");
    }
}
