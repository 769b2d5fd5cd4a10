//! # fixel
//!
//! A `no_std`, heap-free, fixed-point rasterizer for texture-mapped 3D scenes on
//! microcontroller displays: fast on a Cortex-M0+ without an FPU or a divider, and exact
//! enough to be tested pixel for pixel against an f64 reference.
//!
//! ```
//! use fixel::prelude::*;
//! use fixel::math::fx;
//! use fixel::pipeline::{DepthLess, Exact, ModulateIntensity};
//! use fixel::scene::{draw_mesh, Camera, DirectionalLight, Mesh};
//! use fixel::texture::{Bilinear, Repeat};
//!
//! // Stages chosen as types: only this span loop is compiled into the firmware.
//! type Lit = Pipeline<Exact, Bilinear, Repeat, Repeat, ModulateIntensity, DepthLess>;
//!
//! // A 64 x 64 texture and a lit, bilinear, perspective-correct draw into an 80 x 60 frame.
//! let mut texels = [Rgb565::BLACK; 64 * 64];
//! fixel_scenes::checker_texture(64, 64, &mut texels)?;
//! let draw = Draw::new::<Lit>(Some(Texture::new(&texels, 64, 64)?), Viewport::new(0, 0, 80, 60)?, Cull::Back)?;
//!
//! // A square of side 2 with normals and uv, turned 30 degrees and 3 units away.
//! let positions = [Vec3::from_num(-1, -1, 0), Vec3::from_num(1, -1, 0), Vec3::from_num(1, 1, 0), Vec3::from_num(-1, 1, 0)];
//! let normals = [Vec3::from_num(0, 0, 1); 4];
//! let uvs = [[fx(0), fx(1)], [fx(1), fx(1)], [fx(1), fx(0)], [fx(0), fx(0)]];
//! let square = Mesh::new(&positions, Some(&normals), &uvs, &[[0, 1, 2], [0, 2, 3]])?;
//! let model = Mat4::translation(Vec3::from_num(0, 0, -3)).mul(&Mat4::rotation_y(Angle::from_degrees(fx(30))));
//! let camera = Camera::perspective(Angle::from_degrees(fx(45)), fx(4) / 3, fx(0.5), fx(20))?;
//! let light = DirectionalLight::new(Vec3::from_num(-0.4, 0.6, 1.0), fx(0.3), fx(0.7))?;
//!
//! let (mut color, mut depth) = ([Rgb565::BLACK; 80 * 60], [0u16; 80 * 60]);
//! let mut frame = Frame::new(&mut color, 80, 60)?.with_depth(&mut depth)?;
//! let drawn = draw_mesh(&draw, &square, &model, &camera, Some(&light), &mut frame)?;
//! assert!(drawn > 500);
//! # Ok::<(), fixel::Error>(())
//! ```
//!
//! The [`guide`] has a chapter per topic: from `Cargo.toml` to a PNG on the desktop
//! ([`guide::first_frame`]) and to an SPI display in bands ([`guide::bands`]), choosing a
//! projection and filter, mipmaps, each technique, performance on each chip, accuracy
//! against the f64 reference, and troubleshooting. The examples take the benchmark meshes (cube,
//! sphere, floor) and their checker texture from the repository's `fixel-scenes` crate.
//!
//! ## The pipeline, stage by stage
//!
//! | stage | module | number formats |
//! |---|---|---|
//! | fixed-point math | [`math`] | `I16F16` ([`math::Fx`]) vectors and 4x4 matrices; angles in 1/65536 turn; table sin/cos; division-free reciprocal |
//! | geometry | [`geometry`] | clip space `I16F16`; clipping in `i64`; screen coordinates with 4 sub-pixel bits; depth `0..=65535` with 14 fraction bits |
//! | raster | [`raster`] | exact integer edge DDA (top-left rule) emitting spans to a sink; plane equations with wrapping `i32` stepping |
//! | pipeline | [`pipeline`] | per-triangle set-up of a plane per varying (`i32` bits in the shader's formats, times `q = w_min / w` (Q30) for perspective); spans in 32-pixel chunks: depth mask, varyings, shader; affine, subdivided (chords), quadratic (parabolas by forward differences), exact or adaptive (per triangle) interpolation |
//! | texture | [`texture`] | power-of-two RGB565 textures; GL wrap modes; nearest and 8-bit-weight bilinear; mip chains with Heckbert's LOD in Q8.8 and GL's mipmapped filters |
//! | shading | [`shading`] | the [`shading::Shader`] trait (varyings `[i32; N]`, `N <= 9`, 8 in the band renderer's bins; RGB565 out or discard); [`shading::TexBinding`] (a texture, filter and wraps as a shader uses them); the built-in shaders (with [`shading::facet`]: light read once per triangle on faceted meshes); per-pixel lighting ([`shading::lighting`]: unit vectors in Q14 renormalised through a `1/sqrt` table, Q8 coefficients, specular power by table) and bump / normal mapping ([`shading::bump`]: tangent-space normals in Q12) |
//! | colour | [`color`] | RGB565 inside; targets in RGB565, RGB888 or Gray8 |
//! | surfaces (render targets) | [`surface`] | row slices of colour and optional 16-bit depth; bands (screen triangles binned, or a 2-byte band range per mesh triangle for big meshes); embedded-graphics flush |
//! | scene | [`scene`] | meshes, camera, per-vertex directional light; a geometry walker with a cache of projected vertices that culls before lighting; per-pixel light vectors and tangent frames for the lighting shaders ([`scene::LitMesh`], [`scene::tangents`]) |
//!
//! The modules depend one way, in the order `math -> geometry -> raster -> texture ->
//! shading -> pipeline -> surface -> scene`: a type two stages need lives in the lower one,
//! and no two files import each other. A test (`xtask`'s `layers`) fails on a reference that
//! runs against the order and on two files that name each other.
//!
//! ## Writing a shader
//!
//! A pixel's colour comes from a [`shading::Shader`]: a `Copy` value holding its uniforms
//! (textures, tables, constants; borrowed, no heap) that declares its varyings as `[i32; N]`
//! (raw fixed-point bits in formats it documents), rescales them once per triangle in
//! [`shading::Shader::triangle`], and returns raw RGB565 (or `None` to discard) from
//! [`shading::Shader::shade`]. [`pipeline::ShadedDraw`] draws it from clip-space
//! [`geometry::Vertex`] triangles in any projection mode; the span loop is monomorphised for
//! the shader, so a varying it does not declare costs nothing. The classic
//! [`pipeline::Draw`] API is built on the same stage ([`shading::Classic`]).
//!
//! A light-mapped wall: a base texture times a second, smaller light map with its own
//! coordinates, dimmed by an extra varying (`k`, Q8.16):
//!
//! ```
//! use fixel::prelude::*;
//! use fixel::geometry::Vertex;
//! use fixel::pipeline::{DepthLess, Exact, ShadedDraw};
//! use fixel::shading::{Fragment, Shader, TexBinding, TexTriangle};
//! use fixel::texture::{Bilinear, ClampToEdge, Lod, MipTexture, Repeat};
//! use fixel::Rgb565;
//!
//! #[derive(Clone, Copy, Debug)]
//! struct LightMapped<'a> {
//!     base: TexBinding<'a, Bilinear, Repeat, Repeat>,
//!     light: TexBinding<'a, Bilinear, ClampToEdge, ClampToEdge>,
//! }
//!
//! impl Shader for LightMapped<'_> {
//!     /// `u0, v0` (base), `u1, v1` (light map): normalized I16F16; `k`: Q8.16 (1.0 = 256 << 16).
//!     type Varyings = [i32; 5];
//!     type Triangle = (TexTriangle, TexTriangle);
//!     const TEXCOORDS: Option<(usize, usize)> = Some((0, 1));
//!     fn coord_shift(t: &Self::Triangle) -> u32 {
//!         u32::from(t.0.shift)
//!     }
//!     fn triangle(&self, v: &mut [[i32; 5]; 3]) -> Self::Triangle {
//!         (self.base.triangle(v, (0, 1)), self.light.triangle(v, (2, 3)))
//!     }
//!     fn shade(&self, f: &Fragment<[i32; 5], Self::Triangle>) -> Option<u16> {
//!         let [u0, v0, u1, v1, k] = f.varyings;
//!         let texel = self.base.sample(f.triangle.0, u0, v0, f.lambda);
//!         // The light map's green channel (6 bits) times k, as one Q8 intensity.
//!         // The span loop undid the base pair's shift; the light map's is ours to undo.
//!         let (lt, u1, v1) = (f.triangle.1, f.triangle.1.unshift(u1), f.triangle.1.unshift(v1));
//!         let light = self.light.sample(lt, u1, v1, 0);
//!         let g = u32::from((light >> 5) & 0x3F);
//!         let i = (g * 256 / 63) * ((k >> 16).clamp(0, 256) as u32) / 256;
//!         Some(fixel::color::modulate_scalar(texel, i as u16))
//!     }
//! }
//!
//! let mut base_texels = [Rgb565::default(); 32 * 32];
//! fixel_scenes::checker_texture(32, 32, &mut base_texels)?;
//! let light_texels: [Rgb565; 4] = [Rgb565::new(31, 63, 31), Rgb565::new(8, 16, 8),
//!                                  Rgb565::new(8, 16, 8), Rgb565::new(31, 63, 31)];
//! let (base, light) = (MipTexture::single(Texture::new(&base_texels, 32, 32)?),
//!                      MipTexture::single(Texture::new(&light_texels, 2, 2)?));
//! let shader = LightMapped {
//!     base: TexBinding::new(&base, Bilinear, Repeat, Repeat, Lod::default())?,
//!     light: TexBinding::new(&light, Bilinear, ClampToEdge, ClampToEdge, Lod::default())?,
//! };
//! let draw = ShadedDraw::<_, Exact, DepthLess>::new(shader, Viewport::new(0, 0, 64, 48)?, Cull::None)?;
//!
//! // A wall receding to the right (w from 1 to 3), base repeated 4 times, light map once.
//! let (one, k) = (1 << 16, 200 << 16);
//! let p = |x: f32, y: f32, w: f32| [fixel::math::fx(x * w), fixel::math::fx(y * w), Fx::ZERO, fixel::math::fx(w)];
//! let v = |x: f32, y: f32, w: f32, s: i32, t: i32| Vertex::new(p(x, y, w), [4 * s, 4 * t, s, t, k]);
//! let wall = [v(-0.9, 0.9, 1.0, 0, 0), v(-0.9, -0.9, 1.0, 0, one), v(0.9, -0.9, 3.0, one, one), v(0.9, 0.9, 3.0, one, 0)];
//! let (mut color, mut depth) = ([Rgb565::default(); 64 * 48], [0u16; 64 * 48]);
//! let mut frame = Frame::new(&mut color, 64, 48)?.with_depth(&mut depth)?;
//! frame.clear(Rgb565::default());
//! let drawn = draw.clip_triangles(&[[wall[0], wall[1], wall[2]], [wall[0], wall[2], wall[3]]], &mut frame)?;
//! assert!(drawn > 2000);
//! # Ok::<(), fixel::Error>(())
//! ```
//!
//! ## Conventions (OpenGL ES unless stated)
//!
//! * Right-handed, column vectors (`p' = M p`), camera looks down `-z`, `+y` up; clip space
//!   visible when `-w <= x, y, z <= w`; NDC depth `[-1, 1]` maps to `[0, 1]`.
//! * Screen y grows **down** (row 0 at the top, as a framebuffer is stored); front faces
//!   are counter-clockwise in NDC.
//! * Pixel centres at half-integers; top-left fill rule; vertices snapped to 1/16 pixel for
//!   coverage, while attributes (texture coordinates, colours, depth) are interpolated from
//!   positions rounded to 1/4096 pixel (GL: snapping moves edges, not textures). Affine
//!   interpolation is GL's `noperspective`, clipping included.
//! * Texel centres at `(i + 0.5) / size`; `t = 0` is the first row of the texel slice; wrap
//!   modes and nearest/bilinear as OpenGL ES 3.2 defines them (wrap applied to integer texel
//!   indices).
//! * Depth test `GL_LESS` against a buffer cleared to 65535 (the far plane).
//!
//! ## Model only what a scene needs
//!
//! A draw's stages (projection, shader, depth) are fixed when it is built.
//! [`pipeline::Draw::new`] takes them as types, so a firmware links exactly one span loop;
//! [`pipeline::Draw::dynamic`] takes a run-time [`pipeline::DrawMode`] and links them all
//! (for host tools). No depth memory is needed without a depth test, no colour interpolant
//! without lighting, no reciprocal without perspective.
//!
//! Memory can also buy speed where a firmware has it to spare:
//! [`texture::BilinearFootprint`] gives [`texture::Bilinear`]'s pixels from a texture that also
//! holds each texel's bilinear footprint ([`texture::MipTexture::with_footprints`], 8 bytes
//! per texel more, built in flash by [`texture::footprint_texels`]): one 64-bit load per
//! sample instead of four texel loads. Only a chain that is given footprints holds them, and
//! a draw that does not sample them does not link them. [`texture::BilinearFootprintSized`]
//! does the same for a texture whose size is fixed at compile time (type parameters), with
//! the footprint's index from instruction immediates; a chain of another size is refused
//! ([`Error::TextureSizeMismatch`]).
//!
//! ## Robustness
//!
//! Drawing never panics and never writes outside a buffer: triangles behind the camera are
//! clipped at the near plane and `w >= 2^-8`, triangles far off screen are clipped to a
//! guard band of ±4096 pixels (so the raster set-up stays within `i64` and its stepping
//! within `i32`), and degenerate triangles are skipped. Everything that can be wrong with
//! input is refused at construction with an [`Error`] that says what is wrong.
#![no_std]
#![deny(unsafe_code)]
#![warn(missing_docs, missing_debug_implementations)]

pub mod color;
pub mod error;
pub(crate) mod fill;
pub mod geometry;
pub mod guide;
pub mod math;
pub mod pipeline;
pub mod raster;
pub mod scene;
pub mod shading;
pub mod surface;
#[cfg(test)]
mod test_rng;
/// The benchmark scenes (`examples/scenes`, the `fixel-scenes` crate) compiled into the unit
/// tests, which cannot link that crate: it depends on the published `fixel`, not on this test
/// build. Its `fixel::` paths name this crate through the `extern crate self` below.
#[cfg(test)]
#[allow(unused_attributes, missing_docs, dead_code)]
#[path = "../examples/scenes/src/lib.rs"]
mod test_scenes;
#[cfg(test)]
extern crate self as fixel;
pub mod texture;

pub use error::Error;

/// Every code block of `README.md` is compiled and run as a doctest.
#[cfg(doctest)]
#[doc = include_str!("../README.md")]
pub struct ReadmeDoctests;

/// The colour types fixel draws in (from `embedded-graphics-core`, re-exported so that a
/// program needs no extra dependency to name them), and the trait that gives `Rgb565` its
/// named colours (`Rgb565::BLACK`) and channels.
pub use embedded_graphics_core::pixelcolor::{Gray8, Rgb565, Rgb888, RgbColor};

/// The `embedded-graphics-core` crate fixel is built on (its `DrawTarget` is what
/// [`surface::DrawTargetFlush`] writes to), at the version fixel uses.
pub use embedded_graphics_core;

/// The names most programs need, in one import: the colour types, the draw, target,
/// geometry and math types, and the shader trait.
pub mod prelude {
    pub use crate::geometry::{ClipVertex, Cull, Vertex, Viewport};
    pub use crate::math::{Angle, Fx, Mat4, Vec3};
    pub use crate::pipeline::{
        DepthTest, Draw, DrawMode, Pipeline, Projection, ShadedDraw, Shading,
    };
    pub use crate::shading::{Fragment, Shader, TexBinding, TexTriangle};
    pub use crate::surface::{BandRenderer, Frame, RenderTarget};
    pub use crate::texture::{Filter, Texture, Wrap};
    pub use crate::Error;
    pub use crate::{Rgb565, RgbColor};
}
