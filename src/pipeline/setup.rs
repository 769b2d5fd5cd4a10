//! Per-triangle set-up: from three screen vertices to the planes the span loop steps.
//!
//! Interpolant formats (all `i32`, stepped with wrapping adds, see
//! [`crate::raster::gradient`]):
//!
//! | interpolant | format | used by |
//! |---|---|---|
//! | `z` | window depth `0..=65535`, 14 fraction bits | depth test |
//! | `u`, `v` | texel units, 16 fraction bits (I16F16 bits), shifted right by `uv_shift` | affine |
//! | `q` | `w_min / w`, Q30 (`1.0` at the nearest vertex) | perspective |
//! | `s`, `t` | `u q`, `v q`, same units as `u`, `v` | perspective |
//! | `c[k]` | colour channel Q8 (`256` = 1.0) with 16 more fraction bits, times `q` when perspective | shading |
//!
//! Texture coordinates are rebased per triangle: for the periodic wrap modes (repeat,
//! mirrored repeat) a whole number of periods is subtracted so that the smallest vertex value
//! lies in `[0, period)`; this keeps thousands of repeats exact. When a triangle's texel
//! coordinates still exceed `2^30` (16384 texels), they are shifted right by `uv_shift` bits
//! and shifted back before sampling: wrapping for periodic modes (exact modulo the period),
//! clamped for the clamp modes (where every value beyond the edge samples the same).

use super::recip::{Q_FLOOR, Q_ONE};
use super::stages::{ProjKind, Shading};
use crate::geometry::ScreenTriangle;
use crate::geometry::COLOR_ONE;
use crate::raster::gradient::PlaneSetup;
use crate::raster::{Plane, Rect};
use crate::texture::Wrap;

/// Everything the span loop needs for one triangle.
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct TriSetup {
    pub px_ref: i32,
    pub py_ref: i32,
    pub z: Plane,
    /// `u` (affine) or `s` (perspective).
    pub u: Plane,
    /// `v` (affine) or `t` (perspective).
    pub v: Plane,
    /// `q` (perspective only).
    pub q: Plane,
    /// Colour channels (times `q` for perspective). Intensity shading uses `c[0]` only.
    pub c: [Plane; 3],
    /// Right shift applied to texel coordinates (see the module docs).
    pub uv_shift: u32,
    /// The pixel nearest the centroid (where per-triangle level of detail is taken).
    pub centroid: (i32, i32),
    /// True when the planes are affine (`u`, `v`, colour) rather than perspective (`s`, `t`,
    /// `q`): always for [`ProjKind::Affine`], per triangle for [`ProjKind::Adaptive`].
    pub affine: bool,
}

/// Upper bound, in the units of `extent`, of the difference between affine and
/// perspective-correct interpolation over a triangle whose normalized `1/w` values range
/// over `[q_min, 1]` (Q30) and whose attribute spans `extent`.
///
/// With barycentrics `b` and perspective ones `b' = b q / sum(b q)`, the difference is
/// `sum((b - b') a)`, at most `extent` times the positive part of `b - b'`, which is largest
/// for two groups of vertices at `q = 1` and `q = rho`: `(1 - sqrt(rho)) / (1 + sqrt(rho))`.
/// Since `sqrt(rho) >= rho` this is below `(1 - rho) / (1 + rho)`, used here (no square root).
pub(crate) fn affine_error_bound(extent: i64, q_min: i64) -> i64 {
    let one = i64::from(Q_ONE);
    let q = q_min.clamp(0, one);
    // extent < 2^33, (one - q) <= 2^30: the product fits i64.
    extent.saturating_mul(one - q) / (one + q)
}

fn periodic(w: Wrap) -> bool {
    matches!(w, Wrap::Repeat | Wrap::MirroredRepeat)
}

/// Texel coordinates (I16F16 bits) of the three vertices on one axis, rebased.
fn texel_coords(uv: [i32; 3], log2_size: u32, wrap: Wrap) -> [i64; 3] {
    let mut t = uv.map(|x| i64::from(x) << log2_size);
    if periodic(wrap) {
        let period_log2 = 16 + log2_size + u32::from(wrap == Wrap::MirroredRepeat);
        let min = t[0].min(t[1]).min(t[2]);
        let base = (min >> period_log2) << period_log2;
        for x in &mut t {
            *x -= base;
        }
    }
    t
}

/// Builds the set-up, or `None` for a zero-area triangle.
///
/// Not inlined: it runs once per triangle, and one shared copy keeps every span loop a
/// firmware links from carrying its own (about 3 KB each on Cortex-M).
#[inline(never)]
#[allow(clippy::too_many_arguments)]
pub(crate) fn setup(
    tri: &ScreenTriangle,
    viewport: Rect,
    proj: ProjKind,
    shading: Shading,
    depth: bool,
    tex_log2: (u32, u32),
    wrap: [Wrap; 2],
    adaptive_budget: i64,
) -> Option<TriSetup> {
    let ps = PlaneSetup::new(
        [
            (tri[0].x, tri[0].y),
            (tri[1].x, tri[1].y),
            (tri[2].x, tri[2].y),
        ],
        viewport,
    )?;
    let cx = (i64::from(tri[0].x) + i64::from(tri[1].x) + i64::from(tri[2].x)) / 48;
    let cy = (i64::from(tri[0].y) + i64::from(tri[1].y) + i64::from(tri[2].y)) / 48;
    let centroid = (
        (cx as i32).clamp(viewport.x0, (viewport.x1 - 1).max(viewport.x0)),
        (cy as i32).clamp(viewport.y0, (viewport.y1 - 1).max(viewport.y0)),
    );
    let mut s = TriSetup {
        px_ref: ps.px_ref,
        py_ref: ps.py_ref,
        centroid,
        ..TriSetup::default()
    };
    if depth {
        s.z = ps.plane([tri[0].z, tri[1].z, tri[2].z]);
    }
    // q = w_min / w per vertex, Q30, clamped to the reciprocal's domain.
    let q = if proj != ProjKind::Affine {
        let wmin = i64::from(tri[0].w.min(tri[1].w).min(tri[2].w).max(1));
        tri.map(|v| {
            let w = i64::from(v.w.max(1));
            ((wmin << 30) / w).clamp(i64::from(Q_FLOOR), i64::from(Q_ONE))
        })
    } else {
        [i64::from(Q_ONE); 3]
    };
    let textured = shading.textured();
    let uv = if textured {
        let u = texel_coords(
            [tri[0].uv[0], tri[1].uv[0], tri[2].uv[0]],
            tex_log2.0,
            wrap[0],
        );
        let v = texel_coords(
            [tri[0].uv[1], tri[1].uv[1], tri[2].uv[1]],
            tex_log2.1,
            wrap[1],
        );
        Some((u, v))
    } else {
        None
    };
    let perspective = match proj {
        ProjKind::Affine => false,
        ProjKind::Exact | ProjKind::Subdivided => true,
        ProjKind::Adaptive => {
            let span = |a: [i64; 3]| a.iter().max().unwrap_or(&0) - a.iter().min().unwrap_or(&0);
            let q_min = q[0].min(q[1]).min(q[2]);
            match uv {
                Some((u, v)) => affine_error_bound(span(u).max(span(v)), q_min) > adaptive_budget,
                // Untextured: colour error against one RGB565 step (1/32 of full scale).
                None => {
                    let c =
                        |k: usize| span(tri.map(|v| i64::from(v.color[k].min(COLOR_ONE)) << 16));
                    affine_error_bound(c(0).max(c(1)).max(c(2)), q_min) > (1 << 19)
                }
            }
        }
    };
    s.affine = !perspective;
    if perspective {
        s.q = ps.plane([q[0] as i32, q[1] as i32, q[2] as i32]);
    }
    let times_q = |a: [i64; 3]| -> [i32; 3] {
        if perspective {
            [0, 1, 2].map(|k| ((a[k] * q[k]) >> 30) as i32)
        } else {
            a.map(|x| x as i32)
        }
    };
    if let Some((u, v)) = uv {
        let max = u
            .iter()
            .chain(v.iter())
            .map(|x| x.unsigned_abs())
            .max()
            .unwrap_or(0);
        let shift = (64 - max.leading_zeros()).saturating_sub(30);
        s.uv_shift = shift;
        s.u = ps.plane(times_q(u.map(|x| x >> shift)));
        s.v = ps.plane(times_q(v.map(|x| x >> shift)));
    }
    let channels = match shading {
        Shading::Modulate | Shading::Gouraud => 3,
        Shading::ModulateIntensity => 1,
        Shading::Replace | Shading::Flat => 0,
    };
    for k in 0..channels {
        let c = tri.map(|v| i64::from(v.color[k].min(COLOR_ONE)) << 16);
        s.c[k] = ps.plane(times_q(c));
    }
    Some(s)
}
