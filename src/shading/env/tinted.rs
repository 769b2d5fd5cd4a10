//! The per-pixel reflection shaders times an interpolated vertex colour (GL's
//! `texel * colour`): [`Tinted`] around [`ReflectPerPixel`] or [`ReflectPerPixelMip`], and
//! around [`EnvLit`], whose base texture the colour modulates.
//!
//! The other env shaders take a colour already: [`Direction`](super::Direction) and
//! [`DirectionMip`](super::DirectionMip) (a direction per vertex, or the reflection per
//! vertex through [`EnvVertices::per_vertex_colour`]).
//!
//! # Formats
//!
//! Varyings: the inner shader's six (`nx, ny, nz, vx, vy, vz`, see
//! [`reflect`](super::reflect)), then `r, g, b` in Q8.16 (`256 << 16` is 1.0, clamped to
//! `0..=1.0` per pixel, as [`Modulate`](crate::shading::Modulate)): nine, which
//! [`MAX_VARYINGS`](crate::shading::MAX_VARYINGS) allows a draw. The band renderer's bins
//! hold triangles of at most eight varyings
//! ([`AnyTriangle`](crate::surface::AnyTriangle)), so a tinted draw fills whole frames
//! or a [`Frame`](crate::surface::Frame) per band, not a binned band list.
//!
//! `Tinted<EnvLit>` takes [`EnvLit`]'s eight varyings (`n`, `v`, then the base texture's
//! `u, v`) and the colour: eleven, [`MAX_VARYINGS`](crate::shading::MAX_VARYINGS)
//! (build them with [`EnvVertices::per_pixel_lit`]). The colour multiplies the base
//! texel, the diffuse albedo, and the glossy reflection is added after it, untinted (GL's
//! `texture(base, uv) * colour * E(n) + ks * G(r)`, the specular added after texturing as
//! GL's separate specular colour does):
//!
//! ```text
//! colour = base × c × E(n) + ks G(r)   per channel, clamped
//! ```
//!
//! `c` and `E(n)` multiply in Q8 (`min(256, (e · (c + 1)) >> 8)`, `e` itself for `c` =
//! 255 and 256), then the base once, so white ([`WHITE`](super::WHITE), which the
//! interpolation may bring one Q8 step below 1.0) leaves every pixel of the untinted
//! [`EnvLit`] as it is.
//!
//! # Example
//!
//! ```
//! use fixel::prelude::*;
//! use fixel::math::fx;
//! use fixel::pipeline::{DepthLess, Exact};
//! use fixel::shading::env::{CubeMap, EnvVertices, ReflectPerPixel, Tinted};
//! use fixel::texture::Bilinear;
//!
//! let texels = [Rgb565::new(31, 63, 31); 16];
//! let cube = CubeMap::new([Texture::new(&texels, 4, 4)?; 6], Bilinear)?;
//! let proj = Mat4::perspective(Angle::from_degrees(fx(45)), fx(1), fx(0.5), fx(20))?;
//! let setup = EnvVertices::new(&Mat4::IDENTITY, &proj, Vec3::ZERO);
//! let (n, half) = (Vec3::from_num(0, 0, 1), [128 << 16; 3]);
//! let tri = [(-1, -1), (1, -1), (0, 1)]
//!     .map(|(x, y)| setup.per_pixel_colour(Vec3::from_num(x, y, -4), n, half).unwrap());
//! let draw = ShadedDraw::<_, Exact, DepthLess>::new(Tinted(ReflectPerPixel(cube)), Viewport::new(0, 0, 32, 32)?, Cull::Back)?;
//! let (mut color, mut depth) = ([Rgb565::default(); 32 * 32], [0u16; 32 * 32]);
//! let mut frame = Frame::new(&mut color, 32, 32)?.with_depth(&mut depth)?;
//! frame.clear(Rgb565::default());
//! assert!(draw.clip_triangles(&[tri], &mut frame)? > 100);
//! // White times one half: (16, 32, 16) wherever the triangle is drawn.
//! assert!(frame.pixels().iter().all(|&p| p == Rgb565::default() || p == Rgb565::new(16, 32, 16)));
//! # Ok::<(), fixel::Error>(())
//! ```
//!
//! A white base under a white sky, no gloss, a red vertex colour: red.
//!
//! ```
//! use fixel::prelude::*;
//! use fixel::math::fx;
//! use fixel::pipeline::{DepthLess, Exact};
//! use fixel::shading::env::{CubeMap, EnvLit, EnvVertices, Tinted};
//! use fixel::shading::TexBinding;
//! use fixel::texture::{Bilinear, Lod, MipTexture, Repeat};
//!
//! let white = [Rgb565::new(31, 63, 31); 16];
//! let sky = CubeMap::new([Texture::new(&white, 4, 4)?; 6], Bilinear)?;
//! let base = MipTexture::single(Texture::new(&white, 4, 4)?);
//! let shader = EnvLit {
//!     base: TexBinding::new(&base, Bilinear, Repeat, Repeat, Lod::default())?,
//!     diffuse: sky,
//!     glossy: sky,
//!     specular: 0,
//! };
//! let proj = Mat4::perspective(Angle::from_degrees(fx(45)), fx(1), fx(0.5), fx(20))?;
//! let setup = EnvVertices::new(&Mat4::IDENTITY, &proj, Vec3::ZERO);
//! let (n, red) = (Vec3::from_num(0, 0, 1), [256 << 16, 0, 0]);
//! let tri = [(-1, -1), (1, -1), (0, 1)].map(|(x, y)| {
//!     setup.per_pixel_lit(Vec3::from_num(x, y, -4), n, [0, 0], red).unwrap()
//! });
//! let draw = ShadedDraw::<_, Exact, DepthLess>::new(Tinted(shader), Viewport::new(0, 0, 32, 32)?, Cull::Back)?;
//! let (mut color, mut depth) = ([Rgb565::default(); 32 * 32], [0u16; 32 * 32]);
//! let mut frame = Frame::new(&mut color, 32, 32)?.with_depth(&mut depth)?;
//! frame.clear(Rgb565::default());
//! assert!(draw.clip_triangles(&[tri], &mut frame)? > 100);
//! assert!(frame.pixels().iter().all(|&p| p == Rgb565::default() || p == Rgb565::new(31, 0, 0)));
//! # Ok::<(), fixel::Error>(())
//! ```

use super::convolve::EnvLit;
use super::cube::EnvLookup;
use super::cube_mip::{EnvLookupLod, ReflectPerPixelMip};
use super::reflect::{fit_group, EnvVertices, ReflectPerPixel, VARYING_BITS};
use crate::color::modulate_rgb;
use crate::geometry::Vertex;
use crate::math::Vec3;
use crate::shading::{q8, Fragment, Shader, TexTriangle};
use crate::texture::{LodGranularity, TexSampler, WrapMode};

/// A reflection shader times the vertex colour: varyings the inner shader's six, then
/// `r, g, b` (Q8.16; see the module docs).
#[derive(Clone, Copy, Debug)]
pub struct Tinted<S>(pub S);

/// The inner shader's six varyings of each vertex, its hook applied, copied back.
#[inline(always)]
fn inner_triangle(v: &mut [[i32; 9]; 3], hook: impl Fn(&mut [[i32; 6]; 3])) {
    let mut six = v.map(|a| [a[0], a[1], a[2], a[3], a[4], a[5]]);
    hook(&mut six);
    for (a, b) in v.iter_mut().zip(six) {
        a[..6].copy_from_slice(&b);
    }
}

/// The inner shader's fragment: the first six varyings.
#[inline(always)]
fn inner(f: &Fragment<[i32; 9], ()>) -> Fragment<[i32; 6], ()> {
    let a = f.varyings;
    Fragment {
        varyings: [a[0], a[1], a[2], a[3], a[4], a[5]],
        x: f.x,
        y: f.y,
        depth: f.depth,
        lambda: f.lambda,
        triangle: (),
    }
}

/// `texel` times the colour in varyings 6..9.
#[inline(always)]
fn tint(texel: u16, f: &Fragment<[i32; 9], ()>) -> u16 {
    let [.., r, g, b] = f.varyings;
    modulate_rgb(texel, q8(r), q8(g), q8(b))
}

impl<M: EnvLookup> Shader for Tinted<ReflectPerPixel<M>> {
    type Varyings = [i32; 9];
    type Triangle = ();

    #[inline]
    fn triangle(&self, v: &mut [[i32; 9]; 3]) {
        inner_triangle(v, |six| self.0.triangle(six));
    }

    #[inline(always)]
    fn shade(&self, f: &Fragment<[i32; 9], ()>) -> Option<u16> {
        Some(tint(self.0.shade(&inner(f))?, f))
    }
}

impl<M: EnvLookupLod> Shader for Tinted<ReflectPerPixelMip<M>> {
    type Varyings = [i32; 9];
    type Triangle = ();
    const LOD: bool = true;
    const LOD_REFLECTION: Option<usize> = Some(0);

    #[inline(always)]
    fn lod_granularity(&self) -> LodGranularity {
        self.0.lod.granularity
    }

    #[inline]
    fn triangle(&self, v: &mut [[i32; 9]; 3]) {
        inner_triangle(v, |six| self.0.triangle(six));
    }

    #[inline(always)]
    fn shade(&self, f: &Fragment<[i32; 9], ()>) -> Option<u16> {
        Some(tint(self.0.shade(&inner(f))?, f))
    }
}

impl<D: EnvLookup, G: EnvLookup, F: TexSampler, WU: WrapMode, WV: WrapMode> Shader
    for Tinted<EnvLit<'_, D, G, F, WU, WV>>
{
    type Varyings = [i32; 11];
    type Triangle = TexTriangle;
    const TEXCOORDS: Option<(usize, usize)> = Some((6, 7));
    const LOD: bool = F::LOD;

    #[inline(always)]
    fn lod_granularity(&self) -> LodGranularity {
        self.0.base.lod().granularity
    }

    #[inline(always)]
    fn can_draw(&self) -> bool {
        self.0.base.can_draw()
    }

    #[inline(always)]
    fn coord_shift(t: &TexTriangle) -> u32 {
        u32::from(t.shift)
    }

    #[inline]
    fn triangle(&self, v: &mut [[i32; 11]; 3]) -> TexTriangle {
        fit_group::<11, VARYING_BITS>(v, 0);
        fit_group::<11, VARYING_BITS>(v, 3);
        self.0.base.triangle(v, (6, 7))
    }

    #[inline(always)]
    fn shade(&self, f: &Fragment<[i32; 11], TexTriangle>) -> Option<u16> {
        let [a0, a1, a2, a3, a4, a5, a6, a7, r, g, b] = f.varyings;
        let eight = [a0, a1, a2, a3, a4, a5, a6, a7];
        Some(
            self.0
                .lit(f.triangle, &eight, f.lambda, Some([q8(r), q8(g), q8(b)])),
        )
    }
}

impl EnvVertices {
    /// A vertex for [`Tinted`] reflection shaders: [`EnvVertices::per_pixel`]'s `n` and
    /// `v`, then `colour` (`r, g, b` Q8.16, [`WHITE`](super::WHITE) for the texel alone).
    /// `None` when a component overflows.
    pub fn per_pixel_colour(&self, p: Vec3, n: Vec3, colour: [i32; 3]) -> Option<Vertex<9>> {
        let v = self.per_pixel(p, n)?;
        let [a, b, c, d, e, f] = v.varyings;
        let [r, g, bl] = colour;
        Some(Vertex::new(v.position, [a, b, c, d, e, f, r, g, bl]))
    }

    /// A vertex for `Tinted<EnvLit>`: [`EnvVertices::per_pixel`]'s `n` and `v`, the base
    /// texture's `uv` (normalized I16F16 bits, as [`TexBinding`](crate::shading::TexBinding)
    /// takes them), then `colour` (`r, g, b` Q8.16, [`WHITE`](super::WHITE) for the lit
    /// texel alone). `None` when a component overflows.
    pub fn per_pixel_lit(
        &self,
        p: Vec3,
        n: Vec3,
        uv: [i32; 2],
        colour: [i32; 3],
    ) -> Option<Vertex<11>> {
        let v = self.per_pixel(p, n)?;
        let [a, b, c, d, e, f] = v.varyings;
        let [r, g, bl] = colour;
        Some(Vertex::new(
            v.position,
            [a, b, c, d, e, f, uv[0], uv[1], r, g, bl],
        ))
    }
}
