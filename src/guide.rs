//! A walk from `Cargo.toml` to pixels: a frame on the desktop as a PNG, then the same frame
//! on an SPI display in bands. Every step below is a doctest, compiled and run by
//! `cargo test`.
//!
//! # 1. Add the dependency
//!
//! fixel is `no_std`, needs no allocator and has no features to choose. From crates.io, or
//! from a checkout of its repository:
//!
//! ```toml
//! [dependencies]
//! fixel = "0.1"                     # from crates.io
//! # fixel = { path = "../fixel" }   # or from a checkout
//! ```
//!
//! Everything a program names is in [`crate::prelude`], including the colour type
//! [`Rgb565`](crate::Rgb565) and [`RgbColor`](crate::RgbColor) (for `Rgb565::BLACK`).
//!
//! # 2. A mesh, a camera, a light
//!
//! Meshes borrow their arrays, so they can live in flash (`static`) or on the stack. Numbers
//! become fixed point through [`fx`](crate::math::fx) and [`Vec3::from_num`](crate::math::Vec3::from_num),
//! which saturate and never panic (see [`crate::math`] for every conversion). Here, a square
//! of side 2 facing the camera, with uv over the whole texture:
//!
//! ```
//! use fixel::prelude::*;
//! use fixel::math::fx;
//! use fixel::scene::{Camera, DirectionalLight, Mesh};
//!
//! let positions = [Vec3::from_num(-1, -1, 0), Vec3::from_num(1, -1, 0),
//!                  Vec3::from_num(1, 1, 0), Vec3::from_num(-1, 1, 0)];
//! let normals = [Vec3::from_num(0, 0, 1); 4];
//! let uvs = [[fx(0), fx(1)], [fx(1), fx(1)], [fx(1), fx(0)], [fx(0), fx(0)]];
//! let indices = [[0u16, 1, 2], [0, 2, 3]]; // counter-clockwise: front faces
//! let square = Mesh::new(&positions, Some(&normals), &uvs, &indices)?;
//!
//! // 45 degrees vertical field of view, 4:3, near 0.5, far 20; looking down -z from the origin.
//! let camera = Camera::perspective(Angle::from_degrees(fx(45)), fx(4) / 3, fx(0.5), fx(20))?;
//! // The model: 3 units in front of the camera, turned 30 degrees about y.
//! let model = Mat4::translation(Vec3::from_num(0, 0, -3))
//!     .mul(&Mat4::rotation_y(Angle::from_degrees(fx(30))));
//! // Light from the upper left (any length but zero), ambient 0.3, diffuse 0.7.
//! let light = DirectionalLight::new(Vec3::from_num(-0.4, 0.6, 1.0), fx(0.3), fx(0.7))?;
//! # let _ = (square, camera, model, light);
//! # Ok::<(), fixel::Error>(())
//! ```
//!
//! # 3. A texture and a draw
//!
//! Textures are RGB565 with power-of-two sides. In firmware, bake a PNG into a `static`
//! with `cargo xtask bake wood.png src/wood.rs` and wrap it with the `const`
//! [`Texture::from_static`](crate::texture::Texture::from_static) (checked at compile
//! time); at run time, [`Texture::new`](crate::texture::Texture::new) checks a slice.
//!
//! A draw fixes its stages as types, so the firmware links exactly one span loop:
//! projection ([`Exact`](crate::pipeline::Exact) perspective-correct, or cheaper), filter,
//! wraps, shading and depth test.
//!
//! ```
//! use fixel::prelude::*;
//! use fixel::pipeline::{DepthLess, Exact, ModulateIntensity};
//! use fixel::texture::{Bilinear, Repeat};
//!
//! type Lit = Pipeline<Exact, Bilinear, Repeat, Repeat, ModulateIntensity, DepthLess>;
//!
//! let mut texels = [Rgb565::BLACK; 64 * 64];
//! fixel::demo::checker_texture(64, 64, &mut texels)?; // or your baked texture
//! let texture = Texture::new(&texels, 64, 64)?;
//! // Drawing into RGB565 (Rgb888 and Gray8 targets also work).
//! let draw: Draw<'_, Rgb565> =
//!     Draw::new::<Lit>(Some(texture), Viewport::new(0, 0, 320, 240)?, Cull::Back)?;
//! # let _ = draw;
//! // Bad input is refused where it enters, with an error that says what is wrong:
//! let err = Texture::new(&texels[..100], 10, 10).unwrap_err();
//! assert_eq!(err.to_string(), "size 10 is not a power of two");
//! # Ok::<(), fixel::Error>(())
//! ```
//!
//! # 4. On the desktop: a whole frame, written as a PNG
//!
//! A [`Frame`](crate::surface::Frame) is a colour slice and an optional depth slice. Its
//! depth is filled with the far plane when it is attached; [`Frame::clear`](crate::surface::Frame::clear)
//! resets both between frames. The `png` crate (or `image`) writes the pixels:
//!
//! ```
//! use fixel::prelude::*;
//! use fixel::math::fx;
//! use fixel::pipeline::{DepthLess, Exact, ModulateIntensity};
//! use fixel::scene::{draw_mesh, Camera, DirectionalLight};
//! use fixel::texture::{Bilinear, Repeat};
//!
//! type Lit = Pipeline<Exact, Bilinear, Repeat, Repeat, ModulateIntensity, DepthLess>;
//! let (w, h) = (320, 240);
//! let mut texels = vec![Rgb565::BLACK; 128 * 128];
//! fixel::demo::checker_texture(128, 128, &mut texels)?;
//! let draw = Draw::new::<Lit>(Some(Texture::new(&texels, 128, 128)?), Viewport::new(0, 0, w, h)?, Cull::Back)?;
//! let cube = fixel::demo::cube(); // 24 vertices, 12 triangles, normals and uv
//! let camera = Camera::perspective(Angle::from_degrees(fx(45)), fx(4) / 3, fx(0.5), fx(20))?;
//! let model = Mat4::translation(Vec3::from_num(0, 0, -4))
//!     .mul(&Mat4::rotation_x(Angle::from_degrees(fx(20))))
//!     .mul(&Mat4::rotation_y(Angle::from_degrees(fx(40))));
//! let light = DirectionalLight::default();
//!
//! let (mut color, mut depth) = (vec![Rgb565::BLACK; (w * h) as usize], vec![0u16; (w * h) as usize]);
//! let mut frame = Frame::new(&mut color, w, h)?.with_depth(&mut depth)?;
//! let drawn = draw_mesh(&draw, &cube.mesh()?, &model, &camera, Some(&light), &mut frame)?;
//! assert!(drawn > 10_000);
//!
//! // RGB565 to 8-bit RGB, then PNG.
//! let rgb: Vec<u8> = frame.pixels().iter()
//!     .flat_map(|c| [c.r() << 3 | c.r() >> 2, c.g() << 2 | c.g() >> 4, c.b() << 3 | c.b() >> 2])
//!     .collect();
//! let path = std::env::temp_dir().join("fixel-guide-cube.png");
//! let mut png = png::Encoder::new(std::fs::File::create(&path).unwrap(), w, h);
//! png.set_color(png::ColorType::Rgb);
//! png.set_depth(png::BitDepth::Eight);
//! png.write_header().unwrap().write_image_data(&rgb).unwrap();
//! # Ok::<(), fixel::Error>(())
//! ```
//!
//! `cargo run --release --example preview` does the same and writes
//! `target/pictures/preview.png`.
//!
//! # 5. On the display: bands
//!
//! A 320x240 RGB565 frame is 150 KB, more than most microcontrollers have. A
//! [`BandRenderer`](crate::surface::BandRenderer) draws the frame in bands of a few rows
//! through one small buffer, and hands each band to a flush, here an embedded-graphics
//! `DrawTarget` (a display driver such as `mipidsi`'s ST7789) through
//! [`DrawTargetFlush`](crate::surface::DrawTargetFlush). The geometry runs once per frame:
//! its screen triangles are kept in `bins` between the bands.
//!
//! ```
//! # use fixel::embedded_graphics_core::{draw_target::DrawTarget, geometry::{OriginDimensions, Size}, Pixel};
//! # /// Counts the pixels it is sent: a stand-in for an SPI display.
//! # struct Display(u32);
//! # impl OriginDimensions for Display { fn size(&self) -> Size { Size::new(320, 240) } }
//! # impl DrawTarget for Display {
//! #     type Color = fixel::Rgb565;
//! #     type Error = core::convert::Infallible;
//! #     fn draw_iter<I: IntoIterator<Item = Pixel<fixel::Rgb565>>>(&mut self, p: I) -> Result<(), Self::Error> {
//! #         self.0 += p.into_iter().count() as u32;
//! #         Ok(())
//! #     }
//! # }
//! use fixel::prelude::*;
//! use fixel::math::fx;
//! use fixel::pipeline::{DepthLess, Exact, ModulateIntensity};
//! use fixel::scene::{mesh_triangles, Camera, DirectionalLight};
//! use fixel::surface::{BandError, Binned, DrawTargetFlush};
//! use fixel::texture::{Bilinear, Repeat};
//!
//! type Lit = Pipeline<Exact, Bilinear, Repeat, Repeat, ModulateIntensity, DepthLess>;
//! let mut texels = [Rgb565::BLACK; 128 * 128];
//! fixel::demo::checker_texture(128, 128, &mut texels)?;
//! let draw = Draw::new::<Lit>(Some(Texture::new(&texels, 128, 128)?), Viewport::new(0, 0, 320, 240)?, Cull::Back)?;
//! let cube = fixel::demo::cube();
//! let mesh = cube.mesh()?;
//! let camera = Camera::perspective(Angle::from_degrees(fx(45)), fx(4) / 3, fx(0.5), fx(20))?;
//! let light = DirectionalLight::default();
//!
//! // 8 rows of colour and depth (5 KB each) and 16 bins, for the whole program.
//! let (mut color, mut depth) = ([Rgb565::BLACK; 320 * 8], [0u16; 320 * 8]);
//! let mut bins = [Binned::default(); 16];
//! let mut bands = BandRenderer::new(&mut color, 320, 8, 240)?.with_depth(&mut depth)?;
//! let mut display = Display(0);
//! for frame in 0..3 {
//!     let model = Mat4::translation(Vec3::from_num(0, 0, -4))
//!         .mul(&Mat4::rotation_y(Angle::from_degrees(fx(10 * frame))));
//!     let mut out = DrawTargetFlush(&mut display);
//!     let drawn = bands.render(
//!         &[&draw],
//!         &mut bins,
//!         Rgb565::BLACK,
//!         |sink| mesh_triangles(&mesh, &model, &camera, Some(&light),
//!                               |t| draw.project(t, &mut |s| sink.push(0, s))),
//!         |band| out.flush(band),
//!     );
//!     match drawn {
//!         Ok(stats) => assert_eq!(stats.bands, 30),
//!         Err(BandError::Input(e)) => return Err(e), // a bug in this program
//!         Err(BandError::Flush(_)) => {}            // a bus error: the next frame redraws
//!     }
//! }
//! assert_eq!(display.0, 3 * 320 * 240);
//! # Ok::<(), fixel::Error>(())
//! ```
//!
//! Meshes with more screen triangles than bins (the 2,208-triangle sphere) go through
//! [`BandRenderer::render_spans`](crate::surface::BandRenderer::render_spans), which keeps
//! 2 bytes per triangle instead: one binning pass records the bands each triangle meets, then
//! each band re-projects only those triangles through a small cache of projected vertices;
//! with [`with_setup_cache`](crate::surface::BandRenderer::with_setup_cache) a triangle that
//! crosses into the next band is not set up again there.
//! Build the [`MeshTransform`](crate::scene::MeshTransform) once per frame, outside the band
//! closure (it multiplies the matrices), and pass the light as a constant `None` when the
//! draw is unlit (then no lighting code is linked):
//!
//! ```
//! use fixel::prelude::*;
//! use fixel::pipeline::{DepthLess, ModulateIntensity, SubdividedBy};
//! use fixel::pipeline::KeptSetup;
//! use fixel::scene::{mesh_to_sink, CachedVertex, DirectionalLight, MeshTransform};
//! use fixel::surface::BandRange;
//! use fixel::texture::{Bilinear, Repeat};
//!
//! type Lit = Pipeline<SubdividedBy<64>, Bilinear, Repeat, Repeat, ModulateIntensity, DepthLess>;
//! let mut texels = [Rgb565::BLACK; 64 * 64];
//! fixel::demo::checker_texture(64, 64, &mut texels)?;
//! let draw = Draw::new::<Lit>(Some(Texture::new(&texels, 64, 64)?), Viewport::new(0, 0, 320, 240)?, Cull::Back)?;
//! let sphere = fixel::demo::sphere(); // 2,208 triangles
//! let mesh = sphere.mesh()?;
//! let light = DirectionalLight::default();
//!
//! // 8 rows of colour and depth, 2 bytes per triangle, 64 cached vertices, 36 kept
//! // set-ups: 19.9 KB of buffers.
//! let (mut color, mut depth) = ([Rgb565::BLACK; 320 * 8], [0u16; 320 * 8]);
//! let mut ranges = [BandRange::EMPTY; fixel::demo::SPHERE_TRIANGLES];
//! let mut cache = [CachedVertex::EMPTY; 64];
//! let mut setups = [KeptSetup::EMPTY; 36];
//! let mut bands = BandRenderer::new(&mut color, 320, 8, 240)?
//!     .with_depth(&mut depth)?
//!     .with_setup_cache(&mut setups);
//! let transform = MeshTransform::new(&fixel::demo::sphere_model(0), &fixel::demo::camera(20));
//! let mut lit_pixels = 0;
//! let stats = bands
//!     .render_spans(
//!         &[&draw],
//!         &mut [], // no bins: the ranges carry the frame
//!         &mut ranges,
//!         Rgb565::BLACK,
//!         |sink| {
//!             mesh_to_sink(&draw, 0, &mesh, &transform, Some(&light), &mut cache, 0, sink);
//!         },
//!         |band| {
//!             lit_pixels += band.pixels().iter().filter(|&&c| c != Rgb565::BLACK).count();
//!             Ok::<(), ()>(()) // send the band to the display here
//!         },
//!     )
//!     .map_err(|_| fixel::Error::BadMode("example"))?;
//! assert_eq!(stats.bands, 30);
//! assert!(!stats.rewalked); // every triangle had a range
//! assert!(lit_pixels > 20_000);
//! # Ok::<(), fixel::Error>(())
//! ```
//!
//! A technique goes through the same path: the band renderer takes any list of draws,
//! the classic [`Draw`](crate::pipeline::Draw) and open
//! [`ShadedDraw`](crate::pipeline::ShadedDraw)s of any shader types side by side
//! ([`BandDraw`](crate::surface::BandDraw)), each screen triangle carrying its own draw's
//! varyings. Here the environment-mapped sphere (a mirror in a sky cube map, the reflection
//! computed per pixel) in bands, sent to a display; its triangles are handed over by id with
//! [`triangles_to_sink`](crate::scene::triangles_to_sink), so each band computes the
//! vertices of only the triangles it meets:
//!
//! ```
//! # use fixel::embedded_graphics_core::{draw_target::DrawTarget, geometry::{OriginDimensions, Size}, Pixel};
//! # struct Display(u32);
//! # impl OriginDimensions for Display { fn size(&self) -> Size { Size::new(320, 240) } }
//! # impl DrawTarget for Display {
//! #     type Color = fixel::Rgb565;
//! #     type Error = core::convert::Infallible;
//! #     fn draw_iter<I: IntoIterator<Item = Pixel<fixel::Rgb565>>>(&mut self, p: I) -> Result<(), Self::Error> {
//! #         self.0 += p.into_iter().count() as u32;
//! #         Ok(())
//! #     }
//! # }
//! use fixel::prelude::*;
//! use fixel::geometry::Vertex;
//! use fixel::pipeline::{DepthLess, Exact, ShadedDraw};
//! use fixel::scene::triangles_to_sink;
//! use fixel::shading::env::{sky, CubeMap, EnvVertices, ReflectPerPixel};
//! use fixel::surface::{BandRange, Binned, DrawTargetFlush};
//! use fixel::texture::Bilinear;
//!
//! // The sky cube map: six 16 x 16 faces (GL order).
//! let mut faces = [[Rgb565::BLACK; 16 * 16]; 6];
//! for (f, face) in faces.iter_mut().enumerate() {
//!     sky::sky_face(f, 16, face)?;
//! }
//! let face = |f: usize| Texture::new(&faces[f], 16, 16);
//! let sky = CubeMap::new([face(0)?, face(1)?, face(2)?, face(3)?, face(4)?, face(5)?], Bilinear)?;
//! let vp = Viewport::new(0, 0, 320, 240)?;
//! let draw = ShadedDraw::<_, Exact, DepthLess>::new(ReflectPerPixel(sky), vp, Cull::Back)?;
//!
//! // Triangle k of the sphere: clip positions, and the normal and view vector to reflect
//! // (when the pass needs the attributes; the binning pass, once the bins are full, needs
//! // the positions only).
//! let sphere = fixel::demo::sphere();
//! let camera = fixel::demo::camera(20);
//! let view_proj = camera.projection.mul(&camera.view);
//! let setup = EnvVertices::new(&fixel::demo::sphere_model(0), &view_proj, Vec3::ZERO);
//! let triangle = |k: usize, attributes: bool| {
//!     let v = |i: u16| {
//!         let (p, n) = (sphere.positions[usize::from(i)], sphere.normals[usize::from(i)]);
//!         if attributes {
//!             setup.per_pixel(p, n)
//!         } else {
//!             let c = setup.mvp.transform_point(p)?;
//!             Some(Vertex::new([c.x, c.y, c.z, c.w], [0; 6]))
//!         }
//!     };
//!     let t = sphere.indices.get(k)?;
//!     Some([v(t[0])?, v(t[1])?, v(t[2])?])
//! };
//!
//! // 8 rows of colour and depth, 2 bytes per triangle: 14.6 KB.
//! let (mut color, mut depth) = ([Rgb565::BLACK; 320 * 8], [0u16; 320 * 8]);
//! let mut ranges = [BandRange::EMPTY; fixel::demo::SPHERE_TRIANGLES];
//! let mut bands = BandRenderer::new(&mut color, 320, 8, 240)?.with_depth(&mut depth)?;
//! let mut display = Display(0);
//! let mut out = DrawTargetFlush(&mut display);
//! let stats = bands.render_spans(
//!     &[&draw],
//!     &mut [] as &mut [Binned],
//!     &mut ranges,
//!     Rgb565::BLACK,
//!     |sink| {
//!         triangles_to_sink(&draw, 0, sphere.indices.len(), 0, triangle, sink);
//!     },
//!     |band| out.flush(band),
//! )?;
//! assert!(stats.pixels > 20_000 && !stats.rewalked);
//! assert_eq!(display.0, 320 * 240);
//! # Ok::<(), fixel::Error>(())
//! ```
//!
//! `examples/firmware` has complete firmwares for Cortex-M0+, Cortex-M4F and RV32IMC, and
//! `examples/display` the same wired to an ST7789.
//!
//! # 6. What goes wrong, and what you get
//!
//! | mistake | result |
//! |---|---|
//! | a depth-testing draw into a target without depth | [`Error::NoDepthBuffer`](crate::Error::NoDepthBuffer), nothing drawn |
//! | forgetting [`Frame::clear`](crate::surface::Frame::clear) before the first frame | nothing: depth is filled when attached |
//! | `sink.push(i, ..)` with `i` past the draws | [`Error::BadDrawIndex`](crate::Error::BadDrawIndex) before any band is flushed |
//! | `sink.push(i, tri)` with a triangle of another draw's varyings | [`Error::WrongVaryings`](crate::Error::WrongVaryings) before any band is flushed |
//! | more screen triangles than bins | the same pixels, the geometry run once per band ([`BandStats::rewalked`](crate::surface::BandStats::rewalked)) |
//! | a viewport larger than the target | the target shows the viewport's top-left part, exactly (GL's window clipping) |
//! | a zero light direction | [`Error::ZeroVector`](crate::Error::ZeroVector) |
//! | `40000` or NaN through [`fx`](crate::math::fx) | `Fx::MAX` or zero; [`try_fx`](crate::math::try_fx) refuses them |
//! | a texture side that is not a power of two | [`Error::NotPowerOfTwo`](crate::Error::NotPowerOfTwo) |
//!
//! Drawing itself never panics and never writes outside a buffer, whatever the triangles.
