//! The f64 reference for the per-vertex cube map (`fixel::shading::env::CubeVertex`),
//! written from its definition; it shares only the vertex bits with fixel.
//!
//! ```text
//! r = 2 (n·v) n − (n·n) v at each vertex (from the vertex's n and v), unit length
//! face = GL's face of r0 + r1 + r2, when it is GL's face of each ri
//! (s, t) = ((1 + sc / ma) / 2, (1 + tc / ma) / 2) of each r on that face, sc / ma capped
//!          to [-2, 2] (and the cap in the sign of sc for ma <= 0)
//! ```
//!
//! A frame: `(s, t)` interpolated perspective-correctly across each triangle
//! ([`render_varyings`]) and the face sampled there with the reference's bilinear filter,
//! clamp-to-edge; on a triangle whose vertices' faces differ, `r` interpolated and the
//! cube map sampled in that direction per pixel.

use fixel::geometry::Vertex;

use super::env::{cube_face_st, cube_sample, reflect, render_varyings};
use super::sample::sample;
use super::{RefFilter, RefTexture, RefWrap};

/// Scale of the `(s, t)` varyings handed to [`render_varyings`].
const UV_SCALE: f64 = (1u32 << 24) as f64;

/// GL's `(sc, tc, ma)` of `d` on face `face` (`ma` along the face's outward axis).
pub fn on_face(face: usize, d: [f64; 3]) -> (f64, f64, f64) {
    let [x, y, z] = d;
    match face {
        0 => (-z, -y, x),
        1 => (z, -y, -x),
        2 => (x, z, y),
        3 => (x, -z, -y),
        4 => (x, -y, z),
        _ => (-x, -y, -z),
    }
}

/// `(s, t)` of `d` projected onto `face` (see the module docs).
pub fn project(face: usize, d: [f64; 3]) -> [f64; 2] {
    let (sc, tc, ma) = on_face(face, d);
    let q = |c: f64| {
        if ma <= 0.0 {
            2.0 * if c > 0.0 {
                1.0
            } else if c < 0.0 {
                -1.0
            } else {
                0.0
            }
        } else {
            (c / ma).clamp(-2.0, 2.0)
        }
    };
    [0.5 * (1.0 + q(sc)), 0.5 * (1.0 + q(tc))]
}

fn unit(r: [f64; 3]) -> [f64; 3] {
    let l = (r[0] * r[0] + r[1] * r[1] + r[2] * r[2]).sqrt();
    if l > 0.0 {
        r.map(|c| c / l)
    } else {
        r
    }
}

/// The face a triangle of reflections `r` is projected onto: GL's face of the sum of the
/// unit vectors.
pub fn triangle_face(r: [[f64; 3]; 3]) -> usize {
    let u = r.map(unit);
    cube_face_st([0, 1, 2].map(|k| u[0][k] + u[1][k] + u[2][k])).0
}

/// Whether the three reflections' own faces are not all the triangle's face.
pub fn straddles(r: [[f64; 3]; 3]) -> bool {
    let f = triangle_face(r);
    r.iter().any(|&d| cube_face_st(d).0 != f)
}

/// The reference frame of per-pixel-reflection vertices `tris` (`n, v` in varyings 0..6,
/// fixel's bits) drawn with the per-vertex cube map of `faces`.
pub fn render_cube_vertex(
    tris: &[[Vertex<6>; 3]],
    faces: &[RefTexture; 6],
    width: u32,
    height: u32,
) -> (Vec<u16>, Vec<bool>) {
    let r_of = |v: &Vertex<6>| {
        let a = v.varyings.map(f64::from);
        reflect([a[0], a[1], a[2]], [a[3], a[4], a[5]])
    };
    // Varyings: s, t (or r), 0, and the face (6: per pixel), each scaled to i32 bits.
    let st: Vec<[Vertex<4>; 3]> = tris
        .iter()
        .map(|t| {
            let r = t.map(|v| r_of(&v));
            if straddles(r) {
                return core::array::from_fn(|k| {
                    let u = unit(r[k]);
                    let q = |c: f64| (c * UV_SCALE).round() as i32;
                    Vertex::new(t[k].position, [q(u[0]), q(u[1]), q(u[2]), 6 * 65536])
                });
            }
            let face = triangle_face(r);
            core::array::from_fn(|k| {
                let [s, u] = project(face, r[k]);
                Vertex::new(
                    t[k].position,
                    [
                        (s * UV_SCALE).round() as i32,
                        (u * UV_SCALE).round() as i32,
                        0,
                        face as i32 * 65536,
                    ],
                )
            })
        })
        .collect();
    render_varyings(&st, width, height, |_, _, a| {
        let face = (a[3] / 65536.0).round() as usize;
        if face >= 6 {
            return cube_sample(faces, [a[0], a[1], a[2]], RefFilter::Bilinear);
        }
        sample(
            &faces[face],
            [a[0] / UV_SCALE, a[1] / UV_SCALE],
            RefFilter::Bilinear,
            RefWrap::ClampToEdge,
            RefWrap::ClampToEdge,
        )
    })
}
