//! Mipmapped cube maps: a mip chain per face and the level of detail from the derivatives
//! of the reflection's face coordinates (OpenGL ES 3.2's rules for cube maps).
//!
//! GL takes the LOD of a cube-map lookup from the screen derivatives of the face
//! coordinates `s`, `t` on the face the pixel's direction selects. fixel gets them from
//! the span loop's existing level-of-detail machinery ([`Fragment::lambda`]) instead of
//! differentiating the per-pixel reflection: per triangle, [`ReflectPerPixelMip`]'s hook
//! reflects at the three vertices and projects the three `r` onto the face plane of their
//! sum's major axis (`sc / ma`, `tc / ma` on that face's axes, extended beyond the face
//! edges), in texel units. These two extra varyings are interpolated like any other and
//! the span loop computes `lambda` from their derivatives (Heckbert's `log2` of the longer
//! derivative, Q8.8), at each pixel, per span or per triangle as
//! [`Lod::granularity`](crate::texture::Lod) says. The lookup itself still uses the exact
//! per-pixel reflection; only the LOD comes from the projected pair.
//!
//! This is a first-order model of `r`'s face coordinates across the triangle, on one face
//! plane per triangle: good on small triangles (on the benchmark sphere within a fraction
//! of a level of the reference's `lambda`, see `host-tests`), wrong on wide ones (a
//! 127-degree view as two triangles: 4.7 levels off on average). If the three reflections
//! of a triangle span more than about 80° (`ma` of a vertex at most 1/8 of its largest
//! component, or behind the face plane), the triangle's pair spreads over `2^13` texels:
//! the coarsest level. Where `r` is linear across a triangle (a flat mirror, or a sky:
//! the direction per vertex), [`DirectionMip`](super::DirectionMip) with the reflection
//! per vertex ([`EnvVertices::per_vertex`]) has GL's exact per-pixel level of detail at
//! any angle; the per-pixel reflection of a curved surface needs 9 varyings for that (`n`,
//! `v` and a direction), one more than a shader has.
//!
//! # Formats
//!
//! Varyings: `nx, ny, nz, vx, vy, vz` as [`ReflectPerPixel`](super::ReflectPerPixel) (any
//! scale per vector), then two slots the hook fills (`s`, `t` in I16F16 texel units of
//! level 0; give 0 in the vertex, as [`EnvVertices::per_pixel_mip`] does).
//!
//! # Example
//!
//! ```
//! use fixel::prelude::*;
//! use fixel::math::fx;
//! use fixel::pipeline::{DepthLess, Exact};
//! use fixel::shading::env::{EnvVertices, MipCubeMap, ReflectPerPixelMip};
//! use fixel::texture::{chain_len, generate_mips, Lod, MipTexture, Trilinear};
//!
//! // Six 8x8 faces with their 4-level chains (8, 4, 2, 1), each a plain colour.
//! let mut chains = [[Rgb565::new(0, 0, 0); 85]; 6];
//! for (i, c) in chains.iter_mut().enumerate() {
//!     c[..64].fill(Rgb565::new(5 * i as u8, 40, 10));
//!     generate_mips(c, 8, 8, 4)?;
//! }
//! assert_eq!(chain_len(8, 8, 4), 85);
//! let faces = [0, 1, 2, 3, 4, 5].map(|i| MipTexture::new(&chains[i], 8, 8, 4).unwrap());
//! let map = MipCubeMap::new(&faces, Trilinear::default())?;
//! let shader = ReflectPerPixelMip { map, lod: Lod::default() };
//!
//! let proj = Mat4::perspective(Angle::from_degrees(fx(45)), fx(1), fx(0.5), fx(20))?;
//! let setup = EnvVertices::new(&Mat4::IDENTITY, &proj, Vec3::ZERO);
//! let n = Vec3::from_num(0, 0.5, 0.866);
//! let tri = [(-1, -1), (1, -1), (0, 1)].map(|(x, y)| {
//!     setup.per_pixel_mip(Vec3::from_num(x, y, -4), n).unwrap()
//! });
//! let draw = ShadedDraw::<_, Exact, DepthLess>::new(shader, Viewport::new(0, 0, 32, 32)?, Cull::Back)?;
//! let (mut color, mut depth) = ([Rgb565::default(); 32 * 32], [0u16; 32 * 32]);
//! let mut frame = Frame::new(&mut color, 32, 32)?.with_depth(&mut depth)?;
//! assert!(draw.clip_triangles(&[tri], &mut frame)? > 100);
//! # Ok::<(), fixel::Error>(())
//! ```

use super::cube::{face_coords, EnvLookup};
use super::reflect::{fit_group, reflect_fit, EnvVertices, FIT_BITS, VARYING_BITS};
use crate::geometry::Vertex;
use crate::math::Vec3;
use crate::shading::{Fragment, Shader};
use crate::texture::{ClampToEdge, Lod, LodGranularity, MipTexture, TexSampler};
use crate::Error;

/// Six mip chains of one square power-of-two size and level count, GL face order, sampled
/// with `S` (for example [`Trilinear`](crate::texture::Trilinear)) and clamp-to-edge within
/// a face. Holds a reference to the caller's six chains, so copying it is cheap.
#[derive(Clone, Copy, Debug)]
pub struct MipCubeMap<'a, S> {
    faces: &'a [MipTexture<'a>; 6],
    log2_size: u8,
    sampler: S,
}

/// A direction lookup with a level of detail: the mipmapped cube maps ([`MipCubeMap`],
/// [`SeamlessMipCubeMap`](super::SeamlessMipCubeMap)) that [`ReflectPerPixelMip`] reads.
pub trait EnvLookupLod: Copy + core::fmt::Debug {
    /// `log2` of the side of level 0 of every face.
    fn log2_size(&self) -> u32;
    /// The colour (raw RGB565) in direction `dir` (any length) at level of detail
    /// `lambda` (Q8.8, after any bias and clamp; `<= 0` magnifies level 0). Never panics.
    fn lookup_lod(&self, dir: [i32; 3], lambda: i32) -> u16;
}

impl<'a, S: TexSampler> MipCubeMap<'a, S> {
    /// The six chains, GL order.
    pub fn chains(&self) -> &'a [MipTexture<'a>; 6] {
        self.faces
    }

    /// The sampler.
    pub fn sampler(&self) -> S {
        self.sampler
    }

    /// A mipmapped cube map over six chains (GL order), sampled with `sampler`.
    ///
    /// # Errors
    /// [`Error::BadCubeMap`] naming the first face whose level 0 is not square or not the
    /// size of face 0; [`Error::BadSize`] (with the level count) when a face has another
    /// number of levels than face 0.
    pub fn new(faces: &'a [MipTexture<'a>; 6], sampler: S) -> Result<Self, Error> {
        let size = faces[0].base().width();
        for (i, f) in faces.iter().enumerate() {
            let b = f.base();
            if b.width() != size || b.height() != size {
                return Err(Error::BadCubeMap {
                    face: i as u8,
                    width: b.width(),
                    height: b.height(),
                });
            }
            if f.levels() != faces[0].levels() {
                return Err(Error::BadSize(f.levels()));
            }
        }
        Ok(MipCubeMap {
            faces,
            log2_size: size.trailing_zeros() as u8,
            sampler,
        })
    }

    /// The side of level 0 of every face, in texels.
    pub fn size(&self) -> u32 {
        1 << self.log2_size
    }
}

impl<S: TexSampler> EnvLookupLod for MipCubeMap<'_, S> {
    #[inline(always)]
    fn log2_size(&self) -> u32 {
        u32::from(self.log2_size)
    }

    #[inline(always)]
    fn lookup_lod(&self, dir: [i32; 3], lambda: i32) -> u16 {
        let c = face_coords(dir);
        let l = u32::from(self.log2_size);
        let tex = &self.faces[usize::from(c.face) % 6];
        self.sampler.sample_mip(
            tex,
            ClampToEdge,
            ClampToEdge,
            (c.s << l) as i32,
            (c.t << l) as i32,
            lambda,
        )
    }
}

impl<S: TexSampler> EnvLookup for MipCubeMap<'_, S> {
    /// Level 0 (no derivatives here): [`EnvLookupLod::lookup_lod`] with `lambda = 0`.
    #[inline(always)]
    fn lookup(&self, dir: [i32; 3]) -> u16 {
        self.lookup_lod(dir, 0)
    }
}

/// Largest magnitude of the projected pair, I16F16 texels (`2^13` texels): differences of
/// two stay within `i32`.
const PAIR_LIMIT: i64 = 1 << 29;

/// `(sc / ma + 1) size / 2` in I16F16 texels on the face `(axis, sign)` (GL's table), the
/// face plane extended; `None` when `ma` is at most 1/8 of the largest component (or
/// behind the plane).
#[inline]
fn plane_coords(r: [i32; 3], face: u8, log2_size: u32) -> Option<(i64, i64)> {
    let [x, y, z] = r.map(i64::from);
    let (sc, tc, ma) = match face {
        0 => (-z, -y, x),
        1 => (z, -y, -x),
        2 => (x, z, y),
        3 => (x, -z, -y),
        4 => (x, -y, z),
        _ => (-x, -y, -z),
    };
    let big = x.abs().max(y.abs()).max(z.abs());
    if ma <= 0 || ma * 8 <= big {
        return None;
    }
    // 1 / ma through the cube lookup's reciprocal (no divide: a 64-bit division is a long
    // library call on Cortex-M): ma (below 2^32) normalised to a 16-bit mantissa d, then
    // c / ma = (c << n >> 16) (2^31 / d) / 2^31, within 2^-15 relative.
    let n = (ma as u32).leading_zeros();
    let d = ((ma as u32) << n) >> 16;
    let r = i64::from(super::cube::recip16(d));
    // |c| <= 8 ma, so (c << n) >> 16 < 2^19 and the product < 2^36; the result is
    // c / ma in Q16, then scaled to half the face in I16F16 texels.
    let half = 1i64 << (15 + log2_size);
    let q = |c: i64| {
        let ratio = (((c << n) >> 16) * r) >> 15; // Q16
        (((ratio * half) >> 16) + half).clamp(-PAIR_LIMIT, PAIR_LIMIT)
    };
    Some((q(sc), q(tc)))
}

/// Environment mapping with the reflection per pixel and mipmapped cube faces (trilinear
/// or any [`TexSampler`]). Varyings: `n`, `v` (as [`ReflectPerPixel`](super::ReflectPerPixel))
/// and the two slots the hook fills; see the module docs.
#[derive(Clone, Copy, Debug)]
pub struct ReflectPerPixelMip<M> {
    /// The mipmapped cube map ([`MipCubeMap`] or its [`seamless`](MipCubeMap::seamless)
    /// form).
    pub map: M,
    /// Bias, clamps (Q8.8) and where `lambda` is computed.
    pub lod: Lod,
}

impl<M: EnvLookupLod> Shader for ReflectPerPixelMip<M> {
    type Varyings = [i32; 8];
    type Triangle = ();
    const TEXCOORDS: Option<(usize, usize)> = Some((6, 7));
    const LOD: bool = true;

    #[inline(always)]
    fn lod_granularity(&self) -> LodGranularity {
        self.lod.granularity
    }

    #[inline]
    fn triangle(&self, v: &mut [[i32; 8]; 3]) {
        fit_group::<8, VARYING_BITS>(v, 0);
        fit_group::<8, VARYING_BITS>(v, 3);
        const S: u32 = VARYING_BITS - FIT_BITS;
        let r = v.map(|a| {
            reflect_fit(
                [a[0] >> S, a[1] >> S, a[2] >> S],
                [a[3] >> S, a[4] >> S, a[5] >> S],
            )
        });
        // The face of the triangle's mean reflection (each r below 2^30: the sum fits i32
        // after halving), so the projection is centred on the triangle.
        let mean: [i32; 3] =
            core::array::from_fn(|c| (r[0][c] >> 2) + (r[1][c] >> 2) + (r[2][c] >> 2));
        let face = face_coords(mean).face;
        let l = self.map.log2_size();
        // A vertex whose r leaves the face plane's useful range (the triangle's reflections
        // more than about 80 degrees apart): the largest spread of the pair over the whole
        // triangle, so the coarsest level.
        let pairs = match r.map(|ri| plane_coords(ri, face, l)) {
            [Some(a), Some(b), Some(c)] => [a, b, c],
            _ => [(0, 0), (PAIR_LIMIT, 0), (0, PAIR_LIMIT)],
        };
        for (vert, (s, t)) in v.iter_mut().zip(pairs) {
            vert[6] = s as i32;
            vert[7] = t as i32;
        }
    }

    #[inline(always)]
    fn shade(&self, f: &Fragment<[i32; 8], ()>) -> Option<u16> {
        const S: u32 = VARYING_BITS - FIT_BITS;
        let a = f.varyings;
        let r = reflect_fit(
            [a[0] >> S, a[1] >> S, a[2] >> S],
            [a[3] >> S, a[4] >> S, a[5] >> S],
        );
        let lod = &self.lod;
        let lambda = f
            .lambda
            .saturating_add(lod.bias)
            .clamp(lod.min, lod.max.max(lod.min));
        Some(self.map.lookup_lod(r, lambda))
    }
}

impl EnvVertices {
    /// A vertex for [`ReflectPerPixelMip`]: [`EnvVertices::per_pixel`]'s six varyings and two
    /// zero slots for the projected face coordinates. `None` when a component overflows.
    pub fn per_pixel_mip(&self, p: Vec3, n: Vec3) -> Option<Vertex<8>> {
        let v = self.per_pixel(p, n)?;
        let a = v.varyings;
        Some(Vertex::new(
            v.position,
            [a[0], a[1], a[2], a[3], a[4], a[5], 0, 0],
        ))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn plane_coords_match_face_coords_on_the_face() {
        for d in [
            [1000, 200, -300],
            [-50, 900, 10],
            [7, -8, -1000],
            [300, 300, 1000],
        ] {
            let c = face_coords(d);
            let (s, t) = plane_coords(d, c.face, 6).unwrap();
            // face_coords is Q16 of [0, 1]; the plane pair is I16F16 texels of a 64 face.
            assert!((s - (i64::from(c.s) << 6)).abs() <= 256, "{d:?}");
            assert!((t - (i64::from(c.t) << 6)).abs() <= 256, "{d:?}");
        }
        // Behind the plane, or grazing it: no coordinates.
        assert_eq!(plane_coords([-5, 1, 1], 0, 6), None);
        assert_eq!(plane_coords([1, 100, 0], 0, 6), None);
    }
}
