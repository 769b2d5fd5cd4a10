//! Per-pixel lighting: Phong and Blinn-Phong evaluated at every pixel from interpolated,
//! renormalised vectors, against fixel's per-vertex (Gouraud) lighting (Phong, "Illumination
//! for Computer Generated Pictures", CACM 1975; Blinn, "Models of Light Reflection for
//! Computer Synthesized Pictures", SIGGRAPH 1977).
//!
//! * [`Material`], [`Specular`], [`SpecularTable`]: the lighting model, in Q14 vectors and
//!   Q8 coefficients (see [`material`]);
//! * [`Phong`]: the per-pixel shader over an interpolated normal and light vector, fed by
//!   [`LitMesh::phong_triangles`](crate::scene::LitMesh::phong_triangles);
//! * bump and normal mapping build on the same model in tangent space
//!   ([`crate::shading::bump`]).
//!
//! Nothing here is linked by a draw that does not use it: the shaders are types, and the
//! tables are data the caller owns.
//!
//! ```
//! use fixel::prelude::*;
//! use fixel::math::fx;
//! use fixel::pipeline::{DepthLess, Exact, ShadedDraw};
//! use fixel::scene::{Camera, LitMesh, PixelLight};
//! use fixel::shading::lighting::{Material, Phong, Specular, SpecularTable};
//! use fixel::shading::TexBinding;
//! use fixel::texture::{Lod, MipTexture, Nearest, Repeat, Texture};
//!
//! // A lit, shiny triangle facing the camera; its colour is a 1 x 1 texture.
//! let white = [Rgb565::WHITE];
//! let chain = MipTexture::single(Texture::new(&white, 1, 1)?);
//! let tex = TexBinding::new(&chain, Nearest, Repeat, Repeat, Lod::default())?;
//! let shininess = SpecularTable::new(32)?;
//! let material = Material::new(40, 200, 256, Specular::Blinn, &shininess)?;
//! let positions = [Vec3::from_num(-1, -1, -3), Vec3::from_num(1, -1, -3), Vec3::from_num(0, 1, -3)];
//! let normals = [Vec3::from_num(0, 0, 1); 3];
//! let uvs = [[Fx::ZERO; 2]; 3];
//! let indices = [[0u16, 1, 2]];
//! let mesh = LitMesh::new(&positions, &normals, &uvs, None, &indices)?;
//! let camera = Camera::perspective(Angle::from_degrees(fx(45)), fx(1), fx(0.5), fx(20))?;
//! let light = PixelLight::point(Vec3::from_num(0, 0, -2))?; // just in front, view space
//! let mut tris = Vec::new();
//! mesh.phong_triangles(&Mat4::IDENTITY, &camera, &light, |t| tris.push(*t));
//! let mut px = [Rgb565::BLACK; 32 * 32];
//! let mut depth = [0u16; 32 * 32];
//! let mut frame = Frame::new(&mut px, 32, 32)?.with_depth(&mut depth)?;
//! let draw = ShadedDraw::<_, Exact, DepthLess>::new(
//!     Phong { tex, material },
//!     Viewport::new(0, 0, 32, 32)?,
//!     Cull::Back,
//! )?;
//! frame.clear(Rgb565::BLACK);
//! assert!(draw.clip_triangles(&tris, &mut frame)? > 100);
//! // The highlight is white where the light is straight ahead.
//! assert_eq!(px[16 * 32 + 16], Rgb565::WHITE);
//! # Ok::<(), fixel::Error>(())
//! ```

pub mod material;
mod phong;

pub use material::{lit_texel, Material, Specular, SpecularTable};
pub(crate) use phong::VIEW_Z;
pub use phong::{Phong, PhongVaryings};
