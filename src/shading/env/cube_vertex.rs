//! A cube map read through face coordinates computed per vertex: the real-time cube-map
//! environment. [`CubeVertex`] takes the vertices of [`ReflectPerVertex`](super::ReflectPerVertex)
//! (the reflection `r` per vertex, [`EnvVertices::per_vertex`](super::EnvVertices::per_vertex)),
//! and in its triangle hook
//!
//! 1. chooses one face for the whole triangle: the face of the sum of its three directions
//!    (GL's table, [`face_coords`](super::face_coords)), when it is each vertex's own face
//!    (otherwise the triangle is drawn as [`ReflectPerVertex`](super::ReflectPerVertex)
//!    draws it, see below);
//! 2. projects each vertex's direction onto that face: `s = (1 + sc / ma) / 2`,
//!    `t = (1 + tc / ma) / 2` with GL's `sc, tc, ma` of that face (not of the vertex's own
//!    major axis), through the reciprocal table of the per-pixel lookup;
//!
//! then draws as a plain textured draw of that face's texture: `s, t` interpolated as
//! texture coordinates (perspective-correct or not, as the draw's projection stage
//! says), clamp-to-edge, any filter. Per pixel: the texture sample and one face index,
//! against the per-pixel face selection and division of
//! [`ReflectPerVertex`](super::ReflectPerVertex).
//!
//! # Where it is exact enough
//!
//! A triangle whose vertices all have the chosen face's axis as their major axis is
//! drawn as a textured triangle of that face: exact at the vertices, and between them
//! the error of interpolating `s, t` rather than the direction (`sc / ma` is a ratio of
//! two interpolated values). A triangle that straddles a cube edge (its vertices' major
//! axes differ) falls back to the per-pixel face choice of
//! [`ReflectPerVertex`](super::ReflectPerVertex): its varyings stay `r` and each pixel
//! selects its face and divides. Projected onto one face, such a triangle would stretch
//! that face's edge texels over the part that belongs to its neighbour (on the benchmark
//! sphere in the sky, 416 of the 2208 triangles straddle an edge, and projecting them
//! onto the centroid's face costs 10 dB: 20.3 dB against the f64 per-pixel reflection).
//! On the benchmark sphere (`host-tests/tests/env_cube_vertex.rs`, 64-texel sky,
//! bilinear) the frame is 28.4 dB from the f64 per-pixel reflection (mean 0.39 LSB), where
//! `ReflectPerVertex` is 30.4 dB and the sphere map per vertex
//! (`scene::SphereMapUvs`, the `env_matcap` scene) 26.3 dB; interpolating `s, t`
//! perspective-correctly or affinely in 64-pixel pieces differs by 0.07 dB.
//!
//! # Cost
//!
//! Per triangle: the face choice, and three projections (a table reciprocal and two
//! multiplies each). Per pixel: a plain texture sample and one face index (the straddling
//! triangles: the per-pixel lookup). In the `env_cube_vertex` firmware scene (the env
//! scenes' bands, vertices transformed per band) 856 / 1900 / 1148 instructions per pixel
//! on Cortex-M4F / M0+ / RV32IMC, 6-7 % below `env_vertex`: the frame's vertex stage
//! (transform, reflection and projection of each triangle's vertices in each band it
//! meets) costs more than the pixels.
//!
//! # Formats
//!
//! Varyings: `r` (any scale, `i32` per component, as [`ReflectPerVertex`](super::ReflectPerVertex)),
//! which the hook replaces by `s, t` (normalized I16F16, `65536` = the face's far edge)
//! and 0 (three varyings, the third stepped as a constant), or, on a triangle that
//! straddles a cube edge, by `r` shifted to 24 bits as [`ReflectPerVertex`](super::ReflectPerVertex) does.
//!
//! # Example
//!
//! ```
//! use fixel::prelude::*;
//! use fixel::math::fx;
//! use fixel::pipeline::{DepthLess, Exact};
//! use fixel::shading::env::{CubeVertex, EnvVertices};
//! use fixel::texture::{Bilinear, Lod, MipTexture};
//!
//! // Six 4x4 faces: +X red, -X green, +Y blue, -Y yellow, +Z white, -Z grey.
//! let colours = [(31, 0, 0), (0, 63, 0), (0, 0, 31), (31, 63, 0), (31, 63, 31), (16, 32, 16)];
//! let texels = colours.map(|(r, g, b)| [Rgb565::new(r, g, b); 16]);
//! let faces = core::array::from_fn(|i| MipTexture::single(Texture::new(&texels[i], 4, 4).unwrap()));
//! let shader = CubeVertex::new(&faces, Bilinear, Lod::default())?;
//! // A mirror facing the camera reflects straight back: +Z, white.
//! let proj = Mat4::perspective(Angle::from_degrees(fx(45)), fx(1), fx(0.5), fx(20))?;
//! let setup = EnvVertices::new(&Mat4::IDENTITY, &proj, Vec3::ZERO);
//! let n = Vec3::from_num(0, 0, 1);
//! let tri = [(-1, -1), (1, -1), (0, 1)]
//!     .map(|(x, y)| setup.per_vertex(Vec3::from_num(x, y, -4), n).unwrap());
//! let draw = ShadedDraw::<_, Exact, DepthLess>::new(shader, Viewport::new(0, 0, 32, 32)?, Cull::Back)?;
//! let (mut color, mut depth) = ([Rgb565::default(); 32 * 32], [0u16; 32 * 32]);
//! let mut frame = Frame::new(&mut color, 32, 32)?.with_depth(&mut depth)?;
//! frame.clear(Rgb565::default());
//! assert!(draw.clip_triangles(&[tri], &mut frame)? > 100);
//! assert!(frame.pixels().iter().all(|&p| p == Rgb565::default() || p == Rgb565::new(31, 63, 31)));
//! # Ok::<(), fixel::Error>(())
//! ```

use super::cube::{recip16, CubeMap, EnvLookup};
use super::reflect::{fit_group, VARYING_BITS};
use crate::shading::{Fragment, Shader, TexBinding, TexTriangle};
use crate::texture::{ClampToEdge, Lod, LodGranularity, MipTexture, Sampler, TexSampler};
use crate::Error;

/// The six faces (GL order), each bound as a clamp-to-edge texture, and the same faces as
/// a cube map for the triangles that straddle an edge.
#[derive(Clone, Copy, Debug)]
pub struct CubeVertex<'a, F> {
    /// Face `k`'s texture binding.
    faces: [TexBinding<'a, F, ClampToEdge, ClampToEdge>; 6],
    /// Level 0 of the faces, read per pixel on the triangles that straddle an edge.
    cube: CubeMap<'a, F>,
}

impl<'a, F: TexSampler + Sampler> CubeVertex<'a, F> {
    /// Binds the six face chains (GL order: +X, −X, +Y, −Y, +Z, −Z, square, one size) with
    /// one sampler ([`Nearest`](crate::texture::Nearest) or
    /// [`Bilinear`](crate::texture::Bilinear)) and level of detail.
    ///
    /// # Errors
    /// As [`TexBinding::new`] for any face, and [`Error::BadCubeMap`] when the faces are
    /// not square textures of one size (as [`CubeMap::new`]).
    pub fn new(faces: &'a [MipTexture<'a>; 6], sampler: F, lod: Lod) -> Result<Self, Error> {
        let b = |k: usize| TexBinding::new(&faces[k], sampler, ClampToEdge, ClampToEdge, lod);
        let t = |k: usize| *faces[k].base();
        Ok(CubeVertex {
            faces: [b(0)?, b(1)?, b(2)?, b(3)?, b(4)?, b(5)?],
            cube: CubeMap::new([t(0), t(1), t(2), t(3), t(4), t(5)], sampler)?,
        })
    }
}

/// [`CubeVertexTriangle::face`] of a triangle that straddles a cube edge: its pixels
/// choose their face.
pub const PER_PIXEL_FACE: u8 = 6;

/// What [`CubeVertex`] keeps per triangle: its face and that face's texture set-up.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct CubeVertexTriangle {
    /// The face (GL order, `0..6`), or [`PER_PIXEL_FACE`].
    pub face: u8,
    /// The face binding's per-triangle data.
    pub tex: TexTriangle,
}

/// The bits directions are shifted to (one shift for the three vertices, magnitudes at
/// most 2^15) before the face choice and the projection: sums of three stay in `i32`,
/// products in `u32`.
const DIR_BITS: u32 = 15;

/// GL's `(sc, tc, ma)` of direction `d` on face `face` (GL's table; `ma` is the component
/// along the face's outward axis, negative behind it).
#[inline(always)]
fn on_face(face: u8, d: [i32; 3]) -> (i32, i32, i32) {
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

/// The face coordinates `(s, t)` (normalized I16F16: `65536` is the far edge) of `d`
/// (components at most 2^15 in magnitude) projected onto face `face`: `(1 + sc / ma) / 2`
/// and `(1 + tc / ma) / 2`, each ratio capped to `[-2, 2]` (so `s, t` in
/// `[-32768, 98304]`); `ma <= 0` gives the cap in the sign of `sc`, `tc` (0 for 0).
#[inline]
pub fn project_onto_face(face: u8, d: [i32; 3]) -> [i32; 2] {
    let (sc, tc, ma) = on_face(face, d);
    let ratio = |c: i32| -> i32 {
        if ma <= 0 {
            return 2 * 65536 * c.signum();
        }
        let ma = ma as u32;
        // ma in [2^15, 2^16) after the shift; |c| capped at 2 ma.
        let n = ma.leading_zeros() - 16;
        let den = ma << n;
        let m = c.unsigned_abs().min(2 * ma) << n;
        // m / den in Q16: m (2^31 / den) / 2^15, with r halved so the product (< 2^17 *
        // 2^15) fits in 32 bits.
        let q = ((m * (recip16(den) >> 1)) >> 14).min(2 << 16) as i32;
        if c < 0 {
            -q
        } else {
            q
        }
    };
    [(65536 + ratio(sc)) >> 1, (65536 + ratio(tc)) >> 1]
}

/// Shifts the three vertices' directions (varyings 0..3) by one shift so the largest
/// magnitude is at most 2^[`DIR_BITS`].
#[inline(always)]
fn fit_dirs(v: &[[i32; 3]; 3]) -> [[i32; 3]; 3] {
    let max = v
        .iter()
        .flat_map(|a| a.iter())
        .fold(0u32, |m, c| m | c.unsigned_abs());
    let bits = 32 - max.leading_zeros();
    let shift = bits.saturating_sub(DIR_BITS);
    v.map(|a| a.map(|c| c >> shift))
}

/// GL's face of direction `d` (ties x before y before z, as [`face_coords`](super::face_coords);
/// the zero direction gives face 0).
#[inline(always)]
pub fn major_face(d: [i32; 3]) -> u8 {
    let [x, y, z] = d;
    let (ax, ay, az) = (x.unsigned_abs(), y.unsigned_abs(), z.unsigned_abs());
    if ax >= ay && ax >= az {
        u8::from(x < 0)
    } else if ay >= az {
        2 + u8::from(y < 0)
    } else {
        4 + u8::from(z < 0)
    }
}

/// The face of a triangle: that of the sum of its (fitted) directions, or
/// [`PER_PIXEL_FACE`] when a vertex's own face is another.
#[inline(always)]
pub fn triangle_face(d: &[[i32; 3]; 3]) -> u8 {
    let sum = [0, 1, 2].map(|k| d[0][k] + d[1][k] + d[2][k]);
    let face = major_face(sum);
    if d.iter().all(|&v| major_face(v) == face) {
        face
    } else {
        PER_PIXEL_FACE
    }
}

impl<F: TexSampler + Sampler> Shader for CubeVertex<'_, F> {
    type Varyings = [i32; 3];
    type Triangle = CubeVertexTriangle;
    const TEXCOORDS: Option<(usize, usize)> = Some((0, 1));
    const LOD: bool = F::LOD;

    #[inline(always)]
    fn lod_granularity(&self) -> LodGranularity {
        self.faces[0].lod().granularity
    }

    #[inline(always)]
    fn can_draw(&self) -> bool {
        self.faces.iter().all(|f| f.can_draw())
    }

    #[inline(always)]
    fn coord_shift(t: &CubeVertexTriangle) -> u32 {
        u32::from(t.tex.shift)
    }

    #[inline]
    fn triangle(&self, v: &mut [[i32; 3]; 3]) -> CubeVertexTriangle {
        let d = fit_dirs(v);
        let face = triangle_face(&d);
        let Some(b) = self.faces.get(usize::from(face)) else {
            fit_group::<3, VARYING_BITS>(v, 0);
            return CubeVertexTriangle {
                face: PER_PIXEL_FACE,
                tex: TexTriangle::default(),
            };
        };
        for (a, d) in v.iter_mut().zip(d) {
            let [s, t] = project_onto_face(face, d);
            *a = [s, t, 0];
        }
        CubeVertexTriangle {
            face,
            tex: b.triangle(v, (0, 1)),
        }
    }

    #[inline(always)]
    fn shade(&self, f: &Fragment<[i32; 3], CubeVertexTriangle>) -> Option<u16> {
        match self.faces.get(usize::from(f.triangle.face)) {
            Some(b) => {
                let [s, t, _] = f.varyings;
                Some(b.sample(f.triangle.tex, s, t, f.lambda))
            }
            None => Some(self.cube.lookup(f.varyings)),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    use crate::shading::env::face_coords;

    #[test]
    fn major_face_is_the_lookup_face() {
        for d in [
            [1, 1, 1],
            [-1, 1, 1],
            [0, -3, 3],
            [0, 0, -1],
            [0, 0, 0],
            [5, -5, 2],
            [i32::MIN, i32::MAX, 0],
        ] {
            assert_eq!(major_face(d), face_coords(d).face, "{d:?}");
        }
        // Vertices on two faces: per pixel.
        assert_eq!(
            triangle_face(&[[100, 0, 10], [100, 0, -10], [10, 100, 0]]),
            PER_PIXEL_FACE
        );
        assert_eq!(
            triangle_face(&[[100, 0, 10], [100, 0, -10], [90, 50, 0]]),
            0
        );
    }

    #[test]
    fn projection_matches_the_lookup_on_the_major_face() {
        // Directions whose major axis is the face: the same (s, t) as the per-pixel lookup,
        // within the reciprocal's rounding.
        for d in [
            [9000, 1200, -3000],
            [-16000, 100, 15000],
            [50, 12000, -700],
            [-3, -9000, 8999],
            [1, 2, 16383],
            [-8000, 4000, -9000],
        ] {
            let fc = face_coords(d);
            let [s, t] = project_onto_face(fc.face, d);
            assert!((s - fc.s as i32).abs() <= 2, "{d:?}: {s} vs {}", fc.s);
            assert!((t - fc.t as i32).abs() <= 2, "{d:?}: {t} vs {}", fc.t);
        }
    }

    #[test]
    fn off_face_directions_cap() {
        // +X face, a direction along +z at 60 degrees off: sc / ma = -tan 60 capped to -2.
        let [s, t] = project_onto_face(0, [1000, 0, 1732]);
        assert!((s - (65536 - 113_512) / 2).abs() <= 4, "{s}");
        assert_eq!(t, 32768);
        // Behind the face: the cap in the sign of sc, tc.
        assert_eq!(project_onto_face(0, [-5, -3, 4]), [-32768, 98304]);
        assert_eq!(project_onto_face(0, [0, 0, 0]), [32768, 32768]);
        // Far past the edge: capped at 2.
        assert_eq!(project_onto_face(4, [16000, 0, 1]), [98304, 32768]);
    }

    #[test]
    fn fit_keeps_directions_below_the_bound() {
        let d = fit_dirs(&[[i32::MIN, i32::MAX, 0], [1, 2, 3], [-7, 0, 0]]);
        assert!(d
            .iter()
            .flatten()
            .all(|c| c.unsigned_abs() <= 1 << DIR_BITS));
        assert_eq!(major_face(d[0]), 1);
    }
}
