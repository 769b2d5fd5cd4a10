//! Mipmapped cube maps: a mip chain per face and the level of detail from the derivatives
//! of the reflection's face coordinates (OpenGL ES 3.2's rules for cube maps).
//!
//! GL takes the LOD of a cube-map lookup from the screen derivatives of the face
//! coordinates `sc / ma`, `tc / ma` on the face the pixel's direction selects.
//! [`ReflectPerPixelMip`] has the span loop compute them at every pixel (or span, or
//! triangle, as [`Lod::granularity`](crate::texture::Lod) says) from the exact screen
//! derivatives of its reflection `r = 2 (n·v) n − (n·n) v`, through the interpolated `n`
//! and `v` and their constant steps ([`Shader::LOD_REFLECTION`],
//! [`reflection_lambda`](super::reflection_lambda)): GL's rule at any angle the
//! reflections of a triangle span, a full-screen mirror of two triangles included.
//! [`DirectionMip`](super::DirectionMip) does the same for a direction per vertex.
//!
//! # Formats
//!
//! Varyings: `nx, ny, nz, vx, vy, vz` as [`ReflectPerPixel`](super::ReflectPerPixel) (any
//! scale per vector, [`EnvVertices::per_pixel`](super::EnvVertices::per_pixel)).
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
//!     setup.per_pixel(Vec3::from_num(x, y, -4), n).unwrap()
//! });
//! let draw = ShadedDraw::<_, Exact, DepthLess>::new(shader, Viewport::new(0, 0, 32, 32)?, Cull::Back)?;
//! let (mut color, mut depth) = ([Rgb565::default(); 32 * 32], [0u16; 32 * 32]);
//! let mut frame = Frame::new(&mut color, 32, 32)?.with_depth(&mut depth)?;
//! assert!(draw.clip_triangles(&[tri], &mut frame)? > 100);
//! # Ok::<(), fixel::Error>(())
//! ```

use super::cube::{face_coords, EnvLookup};
use super::reflect::{fit_group, reflect_fit, FIT_BITS, VARYING_BITS};
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

/// Environment mapping with the reflection per pixel and mipmapped cube faces (trilinear
/// or any [`TexSampler`]), GL's level of detail per pixel. Varyings: `n`, `v` (as
/// [`ReflectPerPixel`](super::ReflectPerPixel)); see the module docs.
#[derive(Clone, Copy, Debug)]
pub struct ReflectPerPixelMip<M> {
    /// The mipmapped cube map ([`MipCubeMap`] or its [`seamless`](MipCubeMap::seamless)
    /// form).
    pub map: M,
    /// Bias, clamps (Q8.8) and where `lambda` is computed.
    pub lod: Lod,
}

impl<M: EnvLookupLod> ReflectPerPixelMip<M> {
    /// The level of detail (Q8.8, after bias and clamps) for the span loop's `lambda` of
    /// the reflection (half-face units): the face size's `log2 - 1` levels added.
    #[inline(always)]
    pub fn lambda(&self, reflection_lambda: i32) -> i32 {
        let l = self.map.log2_size() as i32 - 1;
        reflection_lambda
            .saturating_add(l * 256)
            .saturating_add(self.lod.bias)
            .clamp(self.lod.min, self.lod.max.max(self.lod.min))
    }
}

impl<M: EnvLookupLod> Shader for ReflectPerPixelMip<M> {
    type Varyings = [i32; 6];
    type Triangle = ();
    const LOD: bool = true;
    const LOD_REFLECTION: Option<usize> = Some(0);

    #[inline(always)]
    fn lod_granularity(&self) -> LodGranularity {
        self.lod.granularity
    }

    #[inline]
    fn triangle(&self, v: &mut [[i32; 6]; 3]) {
        fit_group::<6, VARYING_BITS>(v, 0);
        fit_group::<6, VARYING_BITS>(v, 3);
    }

    #[inline(always)]
    fn shade(&self, f: &Fragment<[i32; 6], ()>) -> Option<u16> {
        const S: u32 = VARYING_BITS - FIT_BITS;
        let [nx, ny, nz, vx, vy, vz] = f.varyings.map(|c| c >> S);
        let r = reflect_fit([nx, ny, nz], [vx, vy, vz]);
        Some(self.map.lookup_lod(r, self.lambda(f.lambda)))
    }
}
