//! Per-triangle set-up: from three screen vertices to the planes the span loop steps.
//!
//! Interpolant formats (all `i32`, stepped with wrapping adds, see
//! [`crate::raster::gradient`]):
//!
//! | interpolant | format | used by |
//! |---|---|---|
//! | `z` | window depth `0..=65535`, 14 fraction bits | depth test |
//! | `q` | `w_min / w`, Q30 (`1.0` at the nearest vertex) | perspective |
//! | varying `k` | the shader's format for it (after its `triangle` hook) | affine |
//! | varying `k` times `q` | same units | perspective |
//!
//! The shader's per-triangle hook has already rescaled and rebased the varyings (texture
//! coordinates to texel units: see [`TexBinding`](crate::shading::TexBinding)).

use super::setup_cache::SetupSlot;
use super::stages::ProjKind;
use super::tri_setup::TriSetup;
use crate::math::div::HW_DIVIDE;
use crate::math::div_u64;
use crate::math::recip32::Recip32;
use crate::math::recip_q30::{Q_FLOOR, Q_ONE};
use crate::math::wide::{mul_wide, mul_wide_signed};
use crate::raster::gradient::PlaneSetup;
use crate::raster::{Plane, Rect, ATTR_SUBPIXEL_BITS};
use crate::shading::Varyings;

/// Whether a bound on the difference between affine and perspective-correct interpolation
/// exceeds `budget` (units of `extent`), over a triangle whose clip `w` values range over
/// `[w_min, w_max]` (`1..2^31`) and whose attribute spans `extent`.
///
/// With barycentrics `b` and perspective ones `b' = b q / sum(b q)` (`q = 1 / w`), the
/// difference is `sum((b - b') a)`, at most `extent` times the positive part of `b - b'`,
/// which is largest for two groups of vertices at `q = 1` and `q = rho = w_min / w_max`:
/// `(1 - sqrt(rho)) / (1 + sqrt(rho))`. Since `sqrt(rho) >= rho` this is below
/// `(1 - rho) / (1 + rho) = (w_max - w_min) / (w_max + w_min)`, used here: the test
/// `extent (w_max - w_min) > budget (w_max + w_min)` needs no square root and no division.
/// Both products are exact 32 x 32 -> 64-bit ones (no 64-bit library multiply on 32-bit
/// cores, no saturation: each is below 2^64).
pub(crate) fn affine_error_exceeds(extent: u32, w_min: u32, w_max: u32, budget: u32) -> bool {
    // w < 2^31: the sum fits u32.
    mul_wide(extent, w_max.wrapping_sub(w_min)) > mul_wide(budget, w_max.wrapping_add(w_min))
}

/// One screen vertex as the set-up reads it: `x, y` in 1/4096 pixel (unsnapped: see
/// [`ScreenVertex::sub`](crate::geometry::ScreenVertex)), depth, clip `w`.
pub(crate) type SetupVertex = (i32, i32, i32, i32);

/// The pixel nearest the centroid of `pos`, clamped into `viewport` (where per-triangle
/// level of detail is taken; computed only by the shaders that use it).
pub(crate) fn centroid(pos: &[SetupVertex; 3], viewport: Rect) -> (i32, i32) {
    // Coordinates lie in the guard band (|x|, |y| <= 2^24), so the sums fit i32 (a 64-bit
    // division by a constant is still a library call on 32-bit cores).
    let sum = |k: fn(&SetupVertex) -> i32| pos.iter().map(k).fold(0i32, i32::wrapping_add);
    let cx = sum(|p| p.0) / (3 << ATTR_SUBPIXEL_BITS);
    let cy = sum(|p| p.1) / (3 << ATTR_SUBPIXEL_BITS);
    (
        cx.clamp(viewport.x0, (viewport.x1 - 1).max(viewport.x0)),
        cy.clamp(viewport.y0, (viewport.y1 - 1).max(viewport.y0)),
    )
}

/// Builds the set-up, or `None` for a zero-area triangle. `texcoords` is the shader's
/// [`Shader::TEXCOORDS`](crate::shading::Shader::TEXCOORDS) pair, `adaptive_budget` the
/// adaptive projection's budget in I16F16 texel units.
///
/// Not inlined: it runs once per triangle, and one shared copy (per varying count) keeps
/// every span loop a firmware links from carrying its own (about 3 KB each on Cortex-M).
/// The draws of meshes of small triangles inline it ([`setup_inline`]).
/// The caller keeps the result where it lands and lends it to the span loop by reference:
/// moved into the span context, the set-up (about 70 bytes for three varyings) cost two
/// `memcpy` calls per triangle on Cortex-M0+ (~90 instructions each), and zero-filled there
/// to be written in place, one `memclr` call (~40).
///
/// `slot` is a band renderer's kept set-up for this triangle (see
/// [`SetupSlot`]): one that holds it is returned as is, an empty one receives the set-up
/// built here. Handled here, once per varying count, rather than in every raster function.
#[inline(never)]
#[allow(clippy::too_many_arguments)]
pub(crate) fn setup<V: Varyings>(
    pos: [SetupVertex; 3],
    vary: &[V; 3],
    viewport: Rect,
    proj: ProjKind,
    depth: bool,
    texcoords: Option<(usize, usize)>,
    adaptive_budget: i64,
    slot: SetupSlot<'_>,
) -> Option<TriSetup<V>> {
    setup_inline(
        pos,
        vary,
        viewport,
        proj,
        depth,
        texcoords,
        adaptive_budget,
        slot,
    )
}

/// [`setup`], inlined: the draws of meshes of small triangles (the ones that inline the
/// short span path) take it so, where one draw type is all a mesh firmware links. That
/// saves about 0.5 % of the whole-frame sphere on Cortex-M4F and RV32IMC; on ARMv6-M it
/// saves nothing (measure with `cargo xtask mcu`).
#[inline(always)]
#[allow(clippy::too_many_arguments)]
pub(crate) fn setup_inline<V: Varyings>(
    pos: [SetupVertex; 3],
    vary: &[V; 3],
    viewport: Rect,
    proj: ProjKind,
    depth: bool,
    texcoords: Option<(usize, usize)>,
    adaptive_budget: i64,
    slot: SetupSlot<'_>,
) -> Option<TriSetup<V>> {
    if let Some(kept) = &slot {
        if kept.holds::<V>() {
            return kept.load::<V>();
        }
    }
    let ps = PlaneSetup::new(
        [
            (pos[0].0, pos[0].1),
            (pos[1].0, pos[1].1),
            (pos[2].0, pos[2].1),
        ],
        viewport,
    )?;
    let z = if depth {
        ps.plane([pos[0].2, pos[1].2, pos[2].2])
    } else {
        Plane::default()
    };
    let value = |k: usize| vary.each_ref().map(|v| i64::from(v.as_slice()[k]));
    // A varying's range over the three vertices (exact: the difference of two `i32`).
    let extent = |k: usize| {
        let a = vary.each_ref().map(|v| v.as_slice()[k]);
        a[0].max(a[1]).max(a[2]).abs_diff(a[0].min(a[1]).min(a[2]))
    };
    let w = pos.map(|v| i64::from(v.3.max(1)));
    let (w_min, w_max) = (w[0].min(w[1]).min(w[2]), w[0].max(w[1]).max(w[2]));
    // In 1..2^31.
    let (w_lo, w_hi) = (w_min as u32, w_max as u32);
    let perspective = match proj {
        ProjKind::Affine => false,
        ProjKind::Exact | ProjKind::Subdivided | ProjKind::Quadratic | ProjKind::Dynamic => true,
        ProjKind::Adaptive => match texcoords {
            Some((a, b)) if a < V::N && b < V::N => {
                let extent = extent(a).max(extent(b));
                let budget = adaptive_budget.clamp(0, i64::from(u32::MAX)) as u32;
                // Shifted coordinates (extents near 2^30) stay perspective.
                extent >= 1 << 29 || affine_error_exceeds(extent, w_lo, w_hi, budget)
            }
            // No texture: every varying against one RGB565 step of a Q8.16 colour.
            _ => (0..V::N).any(|k| affine_error_exceeds(extent(k), w_lo, w_hi, 1 << 19)),
        },
    };
    // q = w_min / w per vertex, Q30, clamped to the reciprocal's domain (perspective
    // triangles only: an adaptive triangle drawn affinely needs no division).
    let q = if perspective {
        w.map(|w| {
            if w == w_min {
                // The nearest vertex: exactly 1.0, no division.
                return i64::from(Q_ONE);
            }
            // Both positive, w_min < w: floor(w_min 2^30 / w) by division, or without a
            // divide instruction from a reciprocal of `w` (below 2^28, as every w of the
            // benchmark scenes).
            let q = if !HW_DIVIDE && w < 1 << 28 {
                Recip32::new(w as u32)
                    .map_or(0, |r| i64::from(r.fraction_of(w_min as u32, 1 << 30, 0)))
            } else {
                div_u64((w_min << 30) as u64, w as u64) as i64
            };
            q.clamp(i64::from(Q_FLOOR), i64::from(Q_ONE))
        })
    } else {
        [i64::from(Q_ONE); 3]
    };
    let q_plane = if perspective {
        ps.plane([q[0] as i32, q[1] as i32, q[2] as i32])
    } else {
        Plane::default()
    };
    let (mut at_ref, mut dx, mut dy) = (V::zero(), V::zero(), V::zero());
    for k in 0..V::N {
        let a = value(k);
        let a = if perspective {
            // a within i32, q in 0..=2^30: a 32 x 32-bit product (no 64-bit library
            // multiply on Cortex-M0+).
            // The nearest vertex's q is exactly 1.0: on Cortex-M0+ (a 16-bit-split
            // product of ~35 instructions) its product is skipped.
            [0, 1, 2].map(|i| {
                if !HW_DIVIDE && q[i] == i64::from(Q_ONE) {
                    a[i] as i32
                } else {
                    (mul_wide_signed(a[i] as i32, q[i] as i32) >> 30) as i32
                }
            })
        } else {
            a.map(|x| x as i32)
        };
        let p = ps.plane(a);
        at_ref.as_mut_slice()[k] = p.at_ref;
        dx.as_mut_slice()[k] = p.dx;
        dy.as_mut_slice()[k] = p.dy;
    }
    let built = TriSetup {
        px_ref: ps.px_ref,
        py_ref: ps.py_ref,
        z,
        q: q_plane,
        at_ref,
        dx,
        dy,
        affine: !perspective,
    };
    if let Some(entry) = slot {
        entry.store(Some(&built));
    }
    Some(built)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::test_rng::Rng;

    /// The test decides as the bound in exact rational arithmetic,
    /// `extent (1 - rho) / (1 + rho) > budget` with `rho = w_min / w_max`, for extents across
    /// the whole `u32` range, `w` over all of `1..2^31` and budgets up to a draw's largest.
    #[test]
    fn the_error_test_equals_the_exact_bound() {
        let mut rng = Rng(0x5eed_a11e);
        for i in 0..200_000u32 {
            let extent = (rng.next() >> (32 + i % 32)) as u32;
            let w_max = ((rng.next() >> (33 + i % 31)) as u32).max(1);
            let w_min = match i % 4 {
                0 => w_max,
                1 => w_max.saturating_sub(i % 3).max(1),
                _ => (rng.next() % u64::from(w_max)) as u32 + 1,
            };
            let budget = match i % 3 {
                0 => (rng.next() % (1 << 24)) as u32,
                1 => 1 << 19,
                // At and around the bound itself.
                _ => {
                    let b = u64::from(extent) * u64::from(w_max - w_min)
                        / (u64::from(w_max) + u64::from(w_min));
                    (b as u32).wrapping_sub(i % 2)
                }
            };
            let exact = i128::from(extent) * i128::from(w_max - w_min)
                > i128::from(budget) * (i128::from(w_max) + i128::from(w_min));
            assert_eq!(
                affine_error_exceeds(extent, w_min, w_max, budget),
                exact,
                "extent {extent}, w {w_min}..{w_max}, budget {budget}"
            );
        }
    }
}
