//! A cube map indexed by an interpolated direction (GL's `texture(samplerCube, dir)` with
//! `dir` a varying): sky boxes, and per-vertex reflections with mipmaps. The texel is
//! multiplied by an interpolated vertex colour (GL's `texel * colour`; give white for the
//! texel alone).
//!
//! * [`Direction`]: any [`EnvLookup`] (no level of detail).
//! * [`EnvVertices::per_vertex_colour`]: their vertices for a reflection per vertex.
//! * [`DirectionMip`]: a mipmapped cube map ([`EnvLookupLod`]) with GL's cube-map level of
//!   detail computed by the span loop at every pixel (or span, or triangle, as
//!   [`Lod::granularity`] says) from the screen derivatives of the direction on the face
//!   the pixel's direction selects ([`Shader::LOD_DIRECTION`],
//!   [`direction_lambda`](crate::texture::direction_lambda)). Exact for a
//!   perspective-correct direction whatever angle a triangle spans: a full-screen sky of
//!   two triangles gets the same levels as one of many. Its cost: per pixel, two
//!   3-component cross terms and three `log2` lookups.
//!
//! # Cost
//!
//! The benchmark sphere mirroring the 64-texel sky (2,208 triangles, exact perspective,
//! 8-row bands, 25,976 pixels), the reflection per vertex, measured under QEMU
//! (instructions per pixel, Cortex-M4F / Cortex-M0+ / RV32IMC):
//!
//! | shader | M4F | M0+ | RV32IMC |
//! |---|---:|---:|---:|
//! | [`ReflectPerVertex`](super::ReflectPerVertex), bilinear | 914.6 | 2040.1 | 1233.7 |
//! | [`DirectionMip`], trilinear, LOD per span | 1290.7 | 2679.5 | 1731.3 |
//! | [`DirectionMip`], trilinear, LOD per pixel | 1556.9 | 3267.5 | 2078.3 |
//!
//! Per span, `lambda` is the span's first pixel's: exact along a span whose direction
//! turns little, 0.49 level off on average (p99 1.84) on a 127-degree view drawn as two
//! triangles, 0.09 (p99 0.58) as an 8 x 8 grid.
//!
//! # Formats
//!
//! Varyings: `dx, dy, dz` (the direction, any common scale: the triangle hook rescales the
//! three vertices' directions together to 24 significant bits, as
//! [`ReflectPerVertex`](super::ReflectPerVertex) does), then `r, g, b` in Q8.16 (`256 << 16`
//! is 1.0, clamped to `0..=1.0` per pixel, as [`Modulate`](crate::shading::Modulate)).
//!
//! # Example
//!
//! ```
//! use fixel::prelude::*;
//! use fixel::math::fx;
//! use fixel::pipeline::{DepthLess, Exact};
//! use fixel::shading::env::{DirectionMip, MipCubeMap, WHITE};
//! use fixel::texture::{chain_len, generate_mips, Lod, MipTexture, Trilinear};
//!
//! let mut chains = [[Rgb565::new(0, 0, 0); 85]; 6];
//! for (i, c) in chains.iter_mut().enumerate() {
//!     c[..64].fill(Rgb565::new(5 * i as u8, 40, 10));
//!     generate_mips(c, 8, 8, 4)?;
//! }
//! let faces = [0, 1, 2, 3, 4, 5].map(|i| MipTexture::new(&chains[i], 8, 8, 4).unwrap());
//! let map = MipCubeMap::new(&faces, Trilinear::default())?;
//! let sky = DirectionMip { map, lod: Lod::default() };
//!
//! // A full-screen quad at the far side of the view, its direction the view ray.
//! let one = 1 << 16;
//! let v = |x: i32, y: i32| {
//!     Vertex::new([x, y, 0, one].map(fixel::math::Fx::from_bits), {
//!         let [r, g, b] = WHITE;
//!         [x, -y, -one, r, g, b]
//!     })
//! };
//! let quad = [[v(-one, -one), v(one, -one), v(one, one)], [v(-one, -one), v(one, one), v(-one, one)]];
//! let draw = ShadedDraw::<_, Exact, DepthLess>::new(sky, Viewport::new(0, 0, 32, 32)?, Cull::None)?;
//! let (mut color, mut depth) = ([Rgb565::default(); 32 * 32], [0u16; 32 * 32]);
//! let mut frame = Frame::new(&mut color, 32, 32)?.with_depth(&mut depth)?;
//! assert_eq!(draw.clip_triangles(&quad, &mut frame)?, 32 * 32);
//! # Ok::<(), fixel::Error>(())
//! ```

use super::cube::EnvLookup;
use super::cube_mip::EnvLookupLod;
use super::reflect::{fit_group, EnvVertices, VARYING_BITS};
use crate::color::modulate_rgb;
use crate::geometry::Vertex;
use crate::math::Vec3;
use crate::shading::{q8, Fragment, Shader};
use crate::texture::{Lod, LodGranularity};

/// The vertex colour that leaves the texel as it is: `r, g, b` = 1.0 in Q8.16.
pub const WHITE: [i32; 3] = [256 << 16; 3];

/// A cube map (any [`EnvLookup`]) read in an interpolated direction, times the vertex
/// colour. Varyings: `dx, dy, dz, r, g, b` (see the module docs).
#[derive(Clone, Copy, Debug)]
pub struct Direction<M>(pub M);

impl<M: EnvLookup> Shader for Direction<M> {
    type Varyings = [i32; 6];
    type Triangle = ();

    #[inline]
    fn triangle(&self, v: &mut [[i32; 6]; 3]) {
        fit_group::<6, VARYING_BITS>(v, 0);
    }

    #[inline(always)]
    fn shade(&self, f: &Fragment<[i32; 6], ()>) -> Option<u16> {
        let [x, y, z, r, g, b] = f.varyings;
        Some(modulate_rgb(self.0.lookup([x, y, z]), q8(r), q8(g), q8(b)))
    }
}

/// A mipmapped cube map read in an interpolated direction with GL's cube-map level of
/// detail, times the vertex colour. Varyings: `dx, dy, dz, r, g, b` (see the module docs).
#[derive(Clone, Copy, Debug)]
pub struct DirectionMip<M> {
    /// The mipmapped cube map ([`MipCubeMap`](super::MipCubeMap) or its
    /// [`seamless`](super::MipCubeMap::seamless) form).
    pub map: M,
    /// Bias, clamps (Q8.8) and where `lambda` is computed.
    pub lod: Lod,
}

impl<M: EnvLookupLod> DirectionMip<M> {
    /// The level of detail (Q8.8, after bias and clamps) for the span loop's `lambda` of
    /// the direction (half-face units): the face size's `log2 - 1` levels added.
    #[inline(always)]
    pub fn lambda(&self, direction_lambda: i32) -> i32 {
        let l = self.map.log2_size() as i32 - 1;
        direction_lambda
            .saturating_add(l * 256)
            .saturating_add(self.lod.bias)
            .clamp(self.lod.min, self.lod.max.max(self.lod.min))
    }
}

impl<M: EnvLookupLod> Shader for DirectionMip<M> {
    type Varyings = [i32; 6];
    type Triangle = ();
    const LOD: bool = true;
    const LOD_DIRECTION: Option<usize> = Some(0);

    #[inline(always)]
    fn lod_granularity(&self) -> LodGranularity {
        self.lod.granularity
    }

    #[inline]
    fn triangle(&self, v: &mut [[i32; 6]; 3]) {
        fit_group::<6, VARYING_BITS>(v, 0);
    }

    #[inline(always)]
    fn shade(&self, f: &Fragment<[i32; 6], ()>) -> Option<u16> {
        let [x, y, z, r, g, b] = f.varyings;
        let texel = self.map.lookup_lod([x, y, z], self.lambda(f.lambda));
        Some(modulate_rgb(texel, q8(r), q8(g), q8(b)))
    }
}

impl EnvVertices {
    /// A vertex for [`Direction`] or [`DirectionMip`] reading the reflection per vertex:
    /// varyings the unit `r` in Q14 ([`reflect_unit`](super::reflect_unit), world space)
    /// and `colour` (`r, g, b` Q8.16, [`WHITE`] for the texel alone). On a flat mirror `r` is linear across each
    /// triangle, so the interpolated `r` and [`DirectionMip`]'s level of detail are exact;
    /// on a curved one `r` is interpolated (see [`ReflectPerVertex`](super::ReflectPerVertex)).
    /// `None` when a component overflows.
    pub fn per_vertex_colour(&self, p: Vec3, n: Vec3, colour: [i32; 3]) -> Option<Vertex<6>> {
        let v = self.per_vertex(p, n)?;
        let [x, y, z] = v.varyings;
        let [r, g, b] = colour;
        Some(Vertex::new(v.position, [x, y, z, r, g, b]))
    }
}
