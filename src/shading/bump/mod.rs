//! Bump mapping (Blinn, "Simulation of Wrinkled Surfaces", SIGGRAPH 1978) and normal
//! mapping: per-pixel lighting with a normal perturbed by a height map, no new geometry.
//!
//! * [`Bumped`]: the shader (colour texture, normal source, [`Material`](crate::shading::lighting::Material)),
//!   fed by [`LitMesh::bump_triangles`](crate::scene::LitMesh::bump_triangles);
//! * normal sources ([`TangentNormals`]): [`DerivativeMap`] (precomputed `∂h/∂i, ∂h/∂j`,
//!   one fetch), [`HeightDifferences`] (four height fetches per pixel), [`NormalMap`]
//!   (RGB565 tangent-space normals, any filter);
//! * [`resolve_sphere`]: the lighting of a bump-mapped sphere resolved into its texture
//!   for a light fixed in object space (the real-time form: then a plain textured draw);
//! * bakers: [`derivative_map`] and [`normal_map`] from a
//!   [`HeightMap`](crate::texture::HeightMap), per mip level.
//!
//! The strength σ is in texel widths per height step: a height map is the surface
//! `z = σ h(i, j)` over its texel grid. Mip levels of every source follow the fragment
//! stage's level of detail ([`Fragment::lambda`](crate::shading::Fragment::lambda)).
//!
//! ```
//! use fixel::math::fx;
//! use fixel::shading::bump::{derivative_map, normal_map, HeightDifferences};
//! use fixel::texture::{chain_len, generate_height_mips, HeightMap};
//! use fixel::{Rgb565, RgbColor};
//! // A 8 x 8 ramp, 3 levels.
//! let mut heights = [0u8; chain_len(8, 8, 3)];
//! for (i, h) in heights[..64].iter_mut().enumerate() {
//!     *h = (i % 8) as u8 * 30;
//! }
//! generate_height_mips(&mut heights, 8, 8, 3)?;
//! let map = HeightMap::new(&heights, 8, 8, 3)?;
//! let mut derivs = [Rgb565::BLACK; chain_len(8, 8, 3)];
//! let scale = derivative_map(&map, &mut derivs)?;
//! let mut normals = [Rgb565::BLACK; chain_len(8, 8, 3)];
//! normal_map(&map, fx(0.02), &mut normals)?;
//! let per_pixel = HeightDifferences::new(map, fx(0.02))?;
//! assert!(scale > fx(0));
//! assert!(HeightDifferences::new(map, fx(40)).is_err()); // absurdly steep
//! # let _ = per_pixel;
//! # Ok::<(), fixel::Error>(())
//! ```

mod bake;
mod normals;
mod resolve;
mod shader;

pub use bake::{derivative_map, normal_map};
pub use normals::{DerivativeMap, HeightDifferences, NormalMap, TangentNormals, TexelFetch};
pub use resolve::resolve_sphere;
pub use shader::{BumpVaryings, Bumped};
