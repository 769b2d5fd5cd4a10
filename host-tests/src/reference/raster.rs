//! Window-space triangle setup and coverage of the reference renderer:
//! perspective divide, viewport, snapping to 1/16 pixel, signed area, and
//! edge functions with the top-left fill rule evaluated at pixel centres.
//!
//! Window coordinates (as a framebuffer is stored, y grows DOWN):
//! `x_w = (x_ndc + 1) * width / 2`, `y_w = (1 - y_ndc) * height / 2`,
//! `z_w = (z_ndc + 1) / 2`. Pixel `(x, y)` has its centre at `(x + 0.5, y + 0.5)`.
//! For **coverage** `x_w` and `y_w` are snapped to the nearest multiple of 1/16
//! (ties upward, `floor(16 v + 0.5) / 16`), like the fixed-point renderer's 4
//! sub-pixel bits, so coverage ties are decided the same way. With snapped
//! coordinates and half-integer centres every edge-function value is a
//! multiple of 1/256 and, for coordinates below 2^20 pixels, exactly
//! representable in f64: coverage here is exact, not approximate.
//!
//! **Attributes** (barycentrics, hence texture coordinates, colours and depth)
//! come from the exact, unsnapped window positions, as GL specifies: snapping
//! moves the edges, not the texture. The reference therefore does not share
//! the renderer's snapping of attribute positions.

use super::types::RefVertex;

/// Number of sub-pixel steps per pixel used for snapping (4 bits).
pub const SUBPIXEL_STEPS: f64 = 16.0;

/// A vertex after perspective divide and viewport transform.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct WindowVertex {
    /// Snapped window x (pixels, grows right): coverage only.
    pub x: f64,
    /// Snapped window y (pixels, grows down): coverage only.
    pub y: f64,
    /// Exact window x: attributes.
    pub ex: f64,
    /// Exact window y: attributes.
    pub ey: f64,
    /// Window depth `z_w` in `[0, 1]` (not snapped).
    pub z: f64,
    /// `1 / w_clip`, for perspective-correct interpolation.
    pub inv_w: f64,
    /// Texture coordinates, as given.
    pub uv: [f64; 2],
    /// Vertex colour, as given.
    pub color: [f64; 3],
}

/// Rounds a window coordinate to the nearest multiple of 1/16 (ties upward).
pub fn snap(v: f64) -> f64 {
    (v * SUBPIXEL_STEPS + 0.5).floor() / SUBPIXEL_STEPS
}

/// Perspective divide, viewport and snap. `None` if `w <= 0` (cannot happen
/// after near/far clipping, but guards degenerate input).
pub fn to_window(v: &RefVertex, width: u32, height: u32) -> Option<WindowVertex> {
    let [x, y, z, w] = v.clip;
    if w.partial_cmp(&0.0) != Some(core::cmp::Ordering::Greater) {
        return None;
    }
    let (xn, yn, zn) = (x / w, y / w, z / w);
    let (ex, ey) = (
        (xn + 1.0) * f64::from(width) / 2.0,
        (1.0 - yn) * f64::from(height) / 2.0,
    );
    Some(WindowVertex {
        x: snap(ex),
        y: snap(ey),
        ex,
        ey,
        z: (zn + 1.0) / 2.0,
        inv_w: 1.0 / w,
        uv: v.uv,
        color: v.color,
    })
}

/// Edge function of edge `a -> b` at `(px, py)`:
/// `(b.x - a.x)(py - a.y) - (b.y - a.y)(px - a.x)`.
fn edge(a: &WindowVertex, b: &WindowVertex, px: f64, py: f64) -> f64 {
    (b.x - a.x) * (py - a.y) - (b.y - a.y) * (px - a.x)
}

/// Twice the signed area in window coordinates (y down). It is NEGATIVE for a
/// triangle that is counter-clockwise in NDC (y up), i.e. for a GL front face.
pub fn signed_area2(v: &[WindowVertex; 3]) -> f64 {
    edge(&v[0], &v[1], v[2].x, v[2].y)
}

/// Edge function of the exact (unsnapped) positions.
fn edge_exact(a: &WindowVertex, b: &WindowVertex, px: f64, py: f64) -> f64 {
    (b.ex - a.ex) * (py - a.ey) - (b.ey - a.ey) * (px - a.ex)
}

/// [`signed_area2`] of the exact (unsnapped) positions: the attributes' area.
pub fn exact_area2(v: &[WindowVertex; 3]) -> f64 {
    edge_exact(&v[0], &v[1], v[2].ex, v[2].ey)
}

/// Barycentric weights of the pixel centre `(cx, cy)` in the exact triangle (they sum to
/// 1; outside `[0, 1]` where coverage and the exact triangle disagree by the snapping).
pub fn barycentrics(v: &[WindowVertex; 3], cx: f64, cy: f64) -> [f64; 3] {
    let area = exact_area2(v);
    [(1, 2), (2, 0), (0, 1)].map(|(a, b)| edge_exact(&v[a], &v[b], cx, cy) / area)
}

/// Whether edge `a -> b` is a top or left edge, for a triangle whose
/// orientation sign is `s` (sign of [`signed_area2`]). In the positive
/// orientation (interior where all edge functions are > 0), a top edge is
/// exactly horizontal with `dx > 0` (the interior lies below it, y down) and
/// a left edge has `dy < 0` (the interior lies to its right).
fn is_top_left(a: &WindowVertex, b: &WindowVertex, s: f64) -> bool {
    let (dx, dy) = (s * (b.x - a.x), s * (b.y - a.y));
    (dy == 0.0 && dx > 0.0) || dy < 0.0
}

/// Calls `f(x, y, λ)` for every pixel of the `width x height` viewport whose
/// centre is covered by the (snapped) triangle under the top-left rule. `λ[i]`
/// is the barycentric weight of `v[i]` at the pixel centre in the exact
/// (unsnapped) triangle (they sum to 1). Both windings are rasterized;
/// zero-area triangles cover nothing.
pub fn rasterize(
    v: &[WindowVertex; 3],
    width: u32,
    height: u32,
    mut f: impl FnMut(u32, u32, [f64; 3]),
) {
    let area = signed_area2(v);
    if area == 0.0 || !area.is_finite() {
        return;
    }
    let s = area.signum();
    // Edge i is opposite vertex i.
    let edges = [(1, 2), (2, 0), (0, 1)];
    let top_left = edges.map(|(a, b)| is_top_left(&v[a], &v[b], s));

    let min_x = v[0].x.min(v[1].x).min(v[2].x);
    let max_x = v[0].x.max(v[1].x).max(v[2].x);
    let min_y = v[0].y.min(v[1].y).min(v[2].y);
    let max_y = v[0].y.max(v[1].y).max(v[2].y);
    // Pixels whose centre c = p + 0.5 lies in [min, max].
    let x0 = (min_x - 0.5).ceil().max(0.0);
    let x1 = (max_x - 0.5).floor().min(f64::from(width) - 1.0);
    let y0 = (min_y - 0.5).ceil().max(0.0);
    let y1 = (max_y - 0.5).floor().min(f64::from(height) - 1.0);
    if x0 > x1 || y0 > y1 {
        return;
    }
    for py in (y0 as u32)..=(y1 as u32) {
        let cy = f64::from(py) + 0.5;
        for px in (x0 as u32)..=(x1 as u32) {
            let cx = f64::from(px) + 0.5;
            let e = edges.map(|(a, b)| edge(&v[a], &v[b], cx, cy));
            let inside = (0..3).all(|i| {
                let w = s * e[i];
                w > 0.0 || (w == 0.0 && top_left[i])
            });
            if inside {
                f(px, py, barycentrics(v, cx, cy));
            }
        }
    }
}

/// The window vertices of a fixel clip-space triangle (any varyings; only the positions
/// are read), or `None` when a vertex is at or behind `w = 0`.
pub fn window_of<const N: usize>(
    tri: &[fixel::geometry::Vertex<N>; 3],
    width: u32,
    height: u32,
) -> Option<[WindowVertex; 3]> {
    let w = |v: &fixel::geometry::Vertex<N>| {
        to_window(
            &RefVertex {
                clip: v.position.map(|c| c.to_num::<f64>()),
                uv: [0.0; 2],
                color: [0.0; 3],
            },
            width,
            height,
        )
    };
    Some([w(&tri[0])?, w(&tri[1])?, w(&tri[2])?])
}
