//! The guide, one chapter per topic: from `Cargo.toml` to a first frame, then to a display
//! in bands, then the choices a program makes (projection, filter, mipmaps), each technique
//! built on the open fragment stage, what each chip spends, how close the pixels are to an
//! f64 reference, and what the errors mean. Every code block of every chapter is a doctest,
//! compiled and run by `cargo test`.
//!
//! Start here:
//!
//! 1. [`first_frame`]: the dependency, a mesh, a camera, a light, a texture, a draw, and a
//!    whole frame written as a PNG on the desktop.
//! 2. [`bands`]: the same frame on a display through a buffer of a few rows; meshes larger
//!    than the bins; techniques in bands.
//! 3. [`projection_and_filter`]: perspective-correct, subdivided, quadratic, adaptive or
//!    affine; nearest, bilinear or bilinear from footprints: speed against error.
//! 4. [`mipmaps`]: minified textures, GL's mipmapped filters and where the level of detail
//!    is taken.
//!
//! The techniques, each a shader (or a wrapper of one) on the open fragment stage; a draw
//! that does not use one links none of its code:
//!
//! - [`environment_maps`]: cube, sphere and lat-long maps; seamless filtering and mip chains;
//!   diffuse and glossy maps, and baking them.
//! - [`shadow_maps`]: a depth pass from the light and a wrapper over any shader, with PCF.
//! - [`solid_textures`]: Perlin noise, turbulence, marble, wood, granite, flames, 4D noise and
//!   3D light maps.
//! - [`texture_coordinates`]: planar, cylindrical and spherical coordinates, two-stage
//!   mapping, triplanar mapping, projective quads and models baked from OBJ.
//! - [`anti_aliasing`]: supersampling and accumulation in bands, and edge smoothing.
//! - [`transparency`]: alpha test, blending and back-to-front sorting.
//! - [`lighting`]: per-pixel lighting, bump maps and normal maps.
//! - [`displacement`]: subdivision and displacement of meshes into caller storage.
//!
//! Then:
//!
//! - [`performance`]: what a frame costs on Cortex-M0+, Cortex-M4F and RV32IMC, in flash,
//!   RAM and instructions, and the commands that measure it.
//! - [`accuracy`]: the f64 reference renderer, the error budgets and what they mean.
//! - [`troubleshooting`]: the errors a program meets, what they mean and what to do.
//!
//! The figures quoted in the repository's `docs/` (instruction counts, flash, RAM, error) are
//! written there by the commands that measure them, never copied by hand; each chapter says
//! which command.

#[doc = include_str!("first_frame.md")]
pub mod first_frame {}

#[doc = include_str!("bands.md")]
pub mod bands {}

#[doc = include_str!("projection_and_filter.md")]
pub mod projection_and_filter {}

#[doc = include_str!("mipmaps.md")]
pub mod mipmaps {}

#[doc = include_str!("environment_maps.md")]
pub mod environment_maps {}

#[doc = include_str!("shadow_maps.md")]
pub mod shadow_maps {}

#[doc = include_str!("solid_textures.md")]
pub mod solid_textures {}

#[doc = include_str!("texture_coordinates.md")]
pub mod texture_coordinates {}

#[doc = include_str!("anti_aliasing.md")]
pub mod anti_aliasing {}

#[doc = include_str!("transparency.md")]
pub mod transparency {}

#[doc = include_str!("lighting.md")]
pub mod lighting {}

#[doc = include_str!("displacement.md")]
pub mod displacement {}

#[doc = include_str!("performance.md")]
pub mod performance {}

#[doc = include_str!("accuracy.md")]
pub mod accuracy {}

#[doc = include_str!("troubleshooting.md")]
pub mod troubleshooting {}
