//! The f64 reference for sphere-map (matcap) coordinates per vertex
//! (`fixel::scene::SphereMapUvs`), written from GL's `GL_SPHERE_MAP` formula; it shares only
//! the matrix and vertex bits with fixel.
//!
//! ```text
//! n = model_view · normal (w = 0),  p = model_view · position (w = 1),  v = −p
//! r = 2 (n·v) n − (n·n) v,  (s, t) = sphere_st(r)
//! ```
//!
//! A frame: each vertex's `(s, t)` computed so, interpolated perspective-correctly across
//! each triangle ([`render_varyings`]), and the sphere-map image sampled there with the
//! reference's bilinear filter, clamp-to-edge.

use fixel::geometry::Vertex;
use fixel::math::{Mat4, Vec3};

use super::env::{reflect, render_varyings, sphere_st};
use super::sample::sample;
use super::{RefFilter, RefTexture, RefWrap};

/// Scale of the `(s, t)` varyings handed to [`render_varyings`] (its varyings are `i32`
/// bits: `s · 2^24` keeps 24 bits).
const UV_SCALE: f64 = (1u32 << 24) as f64;

fn f(v: Vec3) -> [f64; 3] {
    [v.x, v.y, v.z].map(|c| c.to_num::<f64>())
}

/// `m · (x, y, z, w)`, first three rows, in f64.
fn apply(m: &Mat4, x: [f64; 3], w: f64) -> [f64; 3] {
    core::array::from_fn(|r| {
        let row = m.m[r].map(|c| c.to_num::<f64>());
        row[0] * x[0] + row[1] * x[1] + row[2] * x[2] + row[3] * w
    })
}

/// The sphere-map `(s, t)` of a model-space vertex `p` with normal `n` under `model_view`.
pub fn sphere_map_uv(model_view: &Mat4, p: Vec3, n: Vec3) -> [f64; 2] {
    let nv = apply(model_view, f(n), 0.0);
    let pv = apply(model_view, f(p), 1.0);
    let (s, t) = sphere_st(reflect(nv, pv.map(|c| -c)));
    [s, t]
}

/// The reference frame (`width x height`, depth-tested, back faces culled) of the mesh
/// (`positions`, `normals`, `indices`) with clip positions from `mvp` (fixel's bits) and
/// `(s, t)` from [`sphere_map_uv`] under `model_view`, sampling `map` bilinearly.
#[allow(clippy::too_many_arguments)]
pub fn render_matcap(
    positions: &[Vec3],
    normals: &[Vec3],
    indices: &[[u16; 3]],
    model_view: &Mat4,
    mvp: &Mat4,
    map: &RefTexture,
    width: u32,
    height: u32,
) -> (Vec<u16>, Vec<bool>) {
    let tris: Vec<[Vertex<2>; 3]> = indices
        .iter()
        .filter_map(|t| {
            let v = |i: u16| {
                let i = usize::from(i);
                let c = mvp.transform_point(positions[i])?;
                let [s, t] = sphere_map_uv(model_view, positions[i], normals[i]);
                Some(Vertex::new(
                    [c.x, c.y, c.z, c.w],
                    [(s * UV_SCALE).round() as i32, (t * UV_SCALE).round() as i32],
                ))
            };
            Some([v(t[0])?, v(t[1])?, v(t[2])?])
        })
        .collect();
    render_varyings(&tris, width, height, |_, _, a| {
        sample(
            map,
            [a[0] / UV_SCALE, a[1] / UV_SCALE],
            RefFilter::Bilinear,
            RefWrap::ClampToEdge,
            RefWrap::ClampToEdge,
        )
    })
}
