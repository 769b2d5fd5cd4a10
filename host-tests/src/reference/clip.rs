//! Clip-space clipping of the reference renderer: Sutherland–Hodgman against
//! the near plane `z >= -w` and the far plane `z <= w`, then a fan
//! triangulation. Attributes are interpolated linearly in clip space, which is
//! exact there (clip space is linear in the object; the division by w comes
//! later). The side planes are not clipped: the rasterizer only visits pixels
//! inside the viewport, which gives the same pixels as GL's ideal clipping.

use super::types::{RefTriangle, RefVertex};

/// Signed distance of a vertex to the near plane (`>= 0` is inside).
fn near_distance(v: &RefVertex) -> f64 {
    v.clip[2] + v.clip[3]
}

/// Signed distance of a vertex to the far plane (`>= 0` is inside).
fn far_distance(v: &RefVertex) -> f64 {
    v.clip[3] - v.clip[2]
}

/// `a + t (b - a)` for every field of a vertex.
pub fn lerp_vertex(a: &RefVertex, b: &RefVertex, t: f64) -> RefVertex {
    let l = |x: f64, y: f64| x + t * (y - x);
    RefVertex {
        clip: core::array::from_fn(|i| l(a.clip[i], b.clip[i])),
        uv: core::array::from_fn(|i| l(a.uv[i], b.uv[i])),
        color: core::array::from_fn(|i| l(a.color[i], b.color[i])),
    }
}

/// The clipped vertex at `t` along `a -> b`: its position in clip space, its
/// attributes likewise (perspective) or, with `noperspective` (GL's
/// `noperspective`, for affine interpolation), at the fraction of the screen
/// distance from `a` to `b` that the new vertex lies at, `t' = t w_b / w(t)`,
/// so that they stay linear in screen space over the original triangle (an
/// end with `w <= 0` has no screen position: `t` is kept).
pub fn cut(a: &RefVertex, b: &RefVertex, t: f64, noperspective: bool) -> RefVertex {
    let mut v = lerp_vertex(a, b, t);
    let (wa, wb, wt) = (a.clip[3], b.clip[3], v.clip[3]);
    if noperspective && wa > 0.0 && wb > 0.0 && wt > 0.0 {
        let attrs = lerp_vertex(a, b, (t * wb / wt).clamp(0.0, 1.0));
        v.uv = attrs.uv;
        v.color = attrs.color;
    }
    v
}

/// One Sutherland–Hodgman pass: keeps the part of `poly` where `dist >= 0`.
/// Vertices already inside are passed through unchanged (bit for bit).
fn clip_polygon(
    poly: &[RefVertex],
    dist: fn(&RefVertex) -> f64,
    noperspective: bool,
) -> Vec<RefVertex> {
    let mut out = Vec::with_capacity(poly.len() + 2);
    for (k, cur) in poly.iter().enumerate() {
        let next = &poly[(k + 1) % poly.len()];
        let (dc, dn) = (dist(cur), dist(next));
        if dc >= 0.0 {
            out.push(*cur);
        }
        if (dc >= 0.0) != (dn >= 0.0) {
            // Always interpolate from the inside vertex, so an edge shared by
            // two triangles (walked in opposite directions) gives the same
            // point bit for bit and no crack opens.
            if dc >= 0.0 {
                out.push(cut(cur, next, dc / (dc - dn), noperspective));
            } else {
                out.push(cut(next, cur, dn / (dn - dc), noperspective));
            }
        }
    }
    out
}

/// Clips a triangle against near and far; returns the resulting convex
/// polygon (empty when the triangle is entirely outside), in the input order.
/// Attributes of new vertices are perspective-correct (see [`clip_triangle_with`]).
pub fn clip_triangle(tri: &RefTriangle) -> Vec<RefVertex> {
    clip_triangle_with(tri, false)
}

/// [`clip_triangle`], with the attributes of new vertices interpolated as GL's
/// `noperspective` when `noperspective` (affine interpolation; see [`cut`]).
pub fn clip_triangle_with(tri: &RefTriangle, noperspective: bool) -> Vec<RefVertex> {
    let all_inside = tri
        .0
        .iter()
        .all(|v| near_distance(v) >= 0.0 && far_distance(v) >= 0.0);
    if all_inside {
        return tri.0.to_vec();
    }
    let poly = clip_polygon(&tri.0, near_distance, noperspective);
    if poly.len() < 3 {
        return Vec::new();
    }
    let poly = clip_polygon(&poly, far_distance, noperspective);
    if poly.len() < 3 {
        return Vec::new();
    }
    poly
}

/// Fan triangulation `(p0, pk, pk+1)` of a convex polygon; keeps the winding.
pub fn fan(poly: &[RefVertex]) -> Vec<RefTriangle> {
    (1..poly.len().saturating_sub(1))
        .map(|k| RefTriangle([poly[0], poly[k], poly[k + 1]]))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn v(z: f64, w: f64) -> RefVertex {
        RefVertex {
            clip: [0.0, 0.0, z, w],
            uv: [z, w],
            color: [0.0; 3],
        }
    }

    #[test]
    fn inside_triangle_is_untouched() {
        let t = RefTriangle([v(0.0, 1.0), v(0.5, 1.0), v(-0.5, 2.0)]);
        assert_eq!(clip_triangle(&t), t.0.to_vec());
    }

    #[test]
    fn one_vertex_behind_near_gives_a_quad_on_the_plane() {
        let t = RefTriangle([v(0.0, 1.0), v(-3.0, 1.0), v(0.0, 2.0)]);
        let p = clip_triangle(&t);
        assert_eq!(p.len(), 4);
        for q in &p {
            assert!(near_distance(q) >= -1e-12 && far_distance(q) >= -1e-12);
        }
        assert_eq!(fan(&p).len(), 2);
    }

    #[test]
    fn fully_beyond_far_is_dropped() {
        let t = RefTriangle([v(2.0, 1.0), v(3.0, 1.0), v(5.0, 2.0)]);
        assert!(clip_triangle(&t).is_empty());
    }
}
