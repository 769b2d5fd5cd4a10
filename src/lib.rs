//! # fixel
//!
//! A `no_std`, heap-free, fixed-point rasterizer for texture-mapped 3D scenes on
//! microcontroller displays: fast on a Cortex-M0+ without an FPU or a divider, and exact
//! enough to be tested pixel for pixel against an f64 reference.
//!
//! ```
//! use fixel::prelude::*;
//! use fixel::demo;
//! use fixel::pipeline::{DepthLess, Exact, ModulateIntensity};
//! use fixel::scene::{draw_mesh, DirectionalLight};
//! use fixel::texture::{Bilinear, Repeat};
//! use embedded_graphics_core::pixelcolor::Rgb565;
//!
//! // Stages chosen as types: only this span loop is compiled into the firmware.
//! type Lit = Pipeline<Exact, Bilinear, Repeat, Repeat, ModulateIntensity, DepthLess>;
//!
//! let mut texels = [Rgb565::default(); 64 * 64];
//! demo::checker_texture(64, 64, &mut texels)?;
//! let draw = Draw::new::<Lit>(Some(Texture::new(&texels, 64, 64)?), Viewport::new(0, 0, 80, 60)?, Cull::Back)?;
//!
//! let (mut color, mut depth) = ([Rgb565::default(); 80 * 60], [0u16; 80 * 60]);
//! let mut frame = Frame::new(&mut color, 80, 60)?.with_depth(&mut depth)?;
//! frame.clear(Rgb565::default());
//! let cube = demo::cube();
//! let drawn = draw_mesh(&draw, &cube.mesh()?, &demo::cube_model(0), &demo::camera(20),
//!                       Some(&DirectionalLight::default()), &mut frame);
//! assert!(drawn > 500);
//! # Ok::<(), fixel::Error>(())
//! ```
//!
//! ## The pipeline, stage by stage
//!
//! | stage | module | number formats |
//! |---|---|---|
//! | fixed-point math | [`math`] | `I16F16` ([`math::Fx`]) vectors and 4x4 matrices; angles in 1/65536 turn; table sin/cos; division-free reciprocal |
//! | geometry | [`geometry`] | clip space `I16F16`; clipping in `i64`; screen coordinates with 4 sub-pixel bits; depth `0..=65535` with 14 fraction bits |
//! | raster | [`raster`] | exact integer edge DDA (top-left rule) emitting spans to a sink; plane equations with wrapping `i32` stepping |
//! | pipeline | [`pipeline`] | per-triangle set-up; `u, v` in texels as `I16F16` bits; `q = w_min / w` as Q30; colour Q8.16; affine, subdivided, exact or adaptive (per triangle) interpolation |
//! | texture | [`texture`] | power-of-two RGB565 textures; GL wrap modes; nearest and 8-bit-weight bilinear; mip chains with Heckbert's LOD in Q8.8 and GL's mipmapped filters |
//! | colour | [`color`] | RGB565 inside; targets in RGB565, RGB888 or Gray8 |
//! | surfaces (render targets) | [`surface`] | row slices of colour and optional 16-bit depth; bands (screen triangles binned, or a 2-byte band range per mesh triangle for big meshes); embedded-graphics flush |
//! | scene | [`scene`] | meshes, camera, per-vertex directional light; a geometry walker with a cache of projected vertices that culls before lighting |
//!
//! ## Conventions (OpenGL ES unless stated)
//!
//! * Right-handed, column vectors (`p' = M p`), camera looks down `-z`, `+y` up; clip space
//!   visible when `-w <= x, y, z <= w`; NDC depth `[-1, 1]` maps to `[0, 1]`.
//! * Screen y grows **down** (row 0 at the top, as a framebuffer is stored); front faces
//!   are counter-clockwise in NDC.
//! * Pixel centres at half-integers; top-left fill rule; vertices snapped to 1/16 pixel.
//! * Texel centres at `(i + 0.5) / size`; `t = 0` is the first row of the texel slice; wrap
//!   modes and nearest/bilinear as GL ES 3.0 §3.8.10–11 (wrap applied to integer texel
//!   indices).
//! * Depth test `GL_LESS` against a buffer cleared to 65535 (the far plane).
//!
//! ## Model only what a scene needs
//!
//! A draw's stages (projection, filter, wraps, shading, depth) are fixed when it is built.
//! [`pipeline::Draw::new`] takes them as types, so a firmware links exactly one span loop;
//! [`pipeline::Draw::dynamic`] takes a run-time [`pipeline::DrawMode`] and links them all
//! (for host tools). No depth memory is needed without a depth test, no colour interpolant
//! without lighting, no reciprocal without perspective.
//!
//! ## Robustness
//!
//! Drawing never panics and never writes outside a buffer: triangles behind the camera are
//! clipped at the near plane and `w >= 2^-8`, triangles far off screen are clipped to a
//! guard band of ±4096 pixels (so the raster set-up stays within `i64` and its stepping
//! within `i32`), and degenerate triangles are skipped. Everything that can be wrong with
//! input is refused at construction with an [`Error`] that says what is wrong.
#![no_std]
#![forbid(unsafe_code)]
#![warn(missing_docs, missing_debug_implementations)]

pub mod color;
pub mod demo;
pub mod error;
pub mod geometry;
pub mod math;
pub mod pipeline;
pub mod raster;
pub mod scene;
pub mod surface;
pub mod texture;

pub use error::Error;

/// The names most programs need, in one import.
pub mod prelude {
    pub use crate::geometry::{ClipVertex, Cull, Viewport};
    pub use crate::math::{Angle, Fx, Mat4, Vec3};
    pub use crate::pipeline::{DepthTest, Draw, DrawMode, Pipeline, Projection, Shading};
    pub use crate::surface::{BandRenderer, Frame, RenderTarget};
    pub use crate::texture::{Filter, Texture, Wrap};
    pub use crate::Error;
}
