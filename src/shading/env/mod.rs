//! Environment mapping (Blinn & Newell, "Texture and Reflection in Computer Generated
//! Images", CACM 1976): a shiny surface shows its surroundings in the direction of the
//! reflection vector `r = 2 (n·v) n − v`.
//!
//! * [`cube`]: [`CubeMap`], six square faces with GL's face selection, the division by the
//!   major axis through a reciprocal table, nearest or bilinear within a face;
//!   [`seamless`]: [`SeamlessCubeMap`], bilinear across face edges (nearest stays
//!   nearest); [`cube_mip`]: [`MipCubeMap`] and [`ReflectPerPixelMip`], a mip chain per
//!   face with GL's LOD per pixel ([`reflect_lod`]) ([`SeamlessMipCubeMap`]: seamless on every level, the sampler's
//!   filters kept).
//! * [`cube_vertex`]: [`CubeVertex`], the real-time cube map: face coordinates computed
//!   per vertex on one face per triangle, then a plain textured draw of that face.
//! * [`direction`]: [`Direction`] and [`DirectionMip`], a cube map read in an interpolated
//!   direction (sky boxes, GL's `samplerCube`), the latter with GL's cube-map level of
//!   detail per pixel, both times a vertex colour.
//! * [`sphere`]: [`SphereMap`], GL's sphere map, and [`latlong`]: [`LatLongMap`],
//!   the equirectangular map, both through table `atan2` ([`angles`]) and fixel's sine
//!   table: no square root, no divide.
//! * [`convolve`]: diffuse (irradiance) and glossy (Phong-lobe) maps baked from a cube map
//!   ([`convolve_face`]) and [`EnvLit`]: base texture × diffuse + glossy.
//! * [`reflect`]: the reflection per pixel ([`ReflectPerPixel`], from interpolated `n` and
//!   `v`, no square root) or per vertex ([`ReflectPerVertex`], interpolated `r`), and
//!   [`EnvVertices`], which builds their vertices from a mesh's positions and normals;
//!   [`tinted`]: [`Tinted`], the per-pixel reflections times a vertex colour.
//!
//! Every lookup implements [`EnvLookup`]: a colour for a direction given as three `i32` of
//! any scale. Nothing here is linked by a draw that does not use it.
//!
//! # Example
//!
//! A reflective triangle in a cube map whose faces are plain colours:
//!
//! ```
//! use fixel::prelude::*;
//! use fixel::pipeline::{DepthLess, Exact, ShadedDraw};
//! use fixel::shading::env::{CubeMap, EnvVertices, ReflectPerPixel};
//! use fixel::texture::Bilinear;
//! use fixel::math::fx;
//!
//! // Six 4x4 faces: +X red, -X green, +Y blue, -Y yellow, +Z white, -Z grey.
//! let colours = [(31, 0, 0), (0, 63, 0), (0, 0, 31), (31, 63, 0), (31, 63, 31), (16, 32, 16)];
//! let texels = colours.map(|(r, g, b)| [Rgb565::new(r, g, b); 16]);
//! let faces = core::array::from_fn(|i| Texture::new(&texels[i], 4, 4).unwrap());
//! let cube = CubeMap::new(faces, Bilinear)?;
//!
//! // Camera at the origin looking down -z; the triangle faces it, tilted up.
//! let proj = Mat4::perspective(Angle::from_degrees(fx(45)), fx(1), fx(0.5), fx(20))?;
//! let setup = EnvVertices::new(&Mat4::IDENTITY, &proj, Vec3::ZERO);
//! let n = Vec3::from_num(0, 0.5, 0.866);
//! let tri = [(-1, -1), (1, -1), (0, 1)].map(|(x, y)| {
//!     setup.per_pixel(Vec3::from_num(x, y, -4), n).unwrap()
//! });
//! let draw = ShadedDraw::<_, Exact, DepthLess>::new(ReflectPerPixel(cube), Viewport::new(0, 0, 32, 32)?, Cull::Back)?;
//! let (mut color, mut depth) = ([Rgb565::default(); 32 * 32], [0u16; 32 * 32]);
//! let mut frame = Frame::new(&mut color, 32, 32)?.with_depth(&mut depth)?;
//! frame.clear(Rgb565::default());
//! assert!(draw.clip_triangles(&[tri], &mut frame)? > 100);
//! # Ok::<(), fixel::Error>(())
//! ```

pub mod angles;
pub mod convolve;
pub mod cube;
pub mod cube_mip;
pub mod cube_vertex;
pub mod direction;
pub mod latlong;
pub mod reflect;
pub mod reflect_lod;
pub mod seamless;
pub mod sphere_bake;
pub mod tinted;

pub use convolve::{convolve_face, EnvLit, Lobe};
pub use cube::{face_coords, CubeMap, EnvLookup, FaceCoords, FACE_NAMES};
pub use cube_mip::{EnvLookupLod, MipCubeMap, ReflectPerPixelMip};
pub use cube_vertex::{CubeVertex, CubeVertexTriangle};
pub use direction::{Direction, DirectionMip, WHITE};
pub use latlong::LatLongMap;
pub use reflect::{reflect_fit, reflect_unit, EnvVertices, ReflectPerPixel, ReflectPerVertex};
pub use reflect_lod::reflection_lambda;
pub use seamless::{SeamlessCubeMap, SeamlessMipCubeMap};
pub use sphere::SphereMap;
pub use sphere_bake::{bake_sphere_map, sphere_texel_direction};
pub use tinted::Tinted;
pub mod sky;
pub mod sphere;
