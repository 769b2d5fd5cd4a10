//! A draw: a validated mode plus its resources, and the two ways triangles enter it.
//!
//! * [`Draw::clip_triangles`]: the low-level entry point. Triangles in OpenGL clip space
//!   with per-vertex uv and colour: the seam where any other renderer, a GL implementation
//!   included, can be fed exactly the same input.
//! * [`Draw::screen_triangle`]: one already clipped and projected triangle (what the scene
//!   level and the band renderer hand over).
//!
//! The per-pixel code is chosen when the draw is built: [`Draw::new`] for stages chosen as
//! types (a firmware links exactly one span loop), [`Draw::dynamic`] for stages chosen at
//! run time from a [`DrawMode`] (links every combination; for hosts and tests).

use embedded_graphics_core::pixelcolor::Rgb565;

use super::raster::{raster_shaded, RasterParams};
use super::stages::*;
use super::target::RenderTarget;
use super::SetupSlot;
use crate::color::TargetColor;
use crate::geometry::{
    clip_and_project, project_unclipped, ClipVertex, Cull, ScreenTriangle, Viewport,
};
use crate::shading::builtin::Classic;
use crate::shading::TexBinding;
use crate::texture::{
    Bilinear, DynMip, DynWrap, Lod, MipFilter, MipTexture, Nearest, TexSampler, Texture, WrapMode,
};
use crate::Error;

/// A 1x1 black texture for untextured draws (so the span loop never branches on "is there
/// a texture").
static NO_TEXELS: [Rgb565; 1] = [Rgb565::new(0, 0, 0)];

/// Draws a screen triangle, or without one the kept triangle of `slot` (see
/// [`raster_shaded`]).
type RasterFn<'a, C> = fn(
    &Draw<'a, C>,
    Option<&ScreenTriangle>,
    &mut dyn RenderTarget<Color = C>,
    SetupSlot<'_>,
) -> u32;

/// A ready-to-use draw: mode, texture, viewport and the span loop chosen for them.
pub struct Draw<'a, C: TargetColor> {
    mode: DrawMode,
    texture: MipTexture<'a>,
    viewport: Viewport,
    flat: u16,
    raster: RasterFn<'a, C>,
}

impl<C: TargetColor> core::fmt::Debug for Draw<'_, C> {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.debug_struct("Draw")
            .field("mode", &self.mode)
            .field("viewport", &self.viewport)
            .finish()
    }
}

fn check(mode: &DrawMode, texture: &Option<MipTexture<'_>>) -> Result<(), Error> {
    if mode.shading.textured() && texture.is_none() {
        return Err(Error::BadMode("textured shading needs a texture"));
    }
    if let Projection::Subdivided { log2_n } | Projection::Quadratic { log2_n } = mode.projection {
        if !(1..=6).contains(&log2_n) {
            return Err(Error::BadMode(
                "subdivision log2_n must be in 1..=6 (N = 2..64)",
            ));
        }
    }
    Ok(())
}

impl<'a, C: TargetColor + 'a> Draw<'a, C> {
    /// A draw whose stages are the types of `M` (see [`Pipeline`]); only that span loop is
    /// compiled in. `texture` is required when `M`'s shading samples one.
    ///
    /// Everything comes from the types, except two lengths with defaults: [`Subdivided`]
    /// uses N = 8 (change with [`Draw::with_subdivision`]; `docs/report` measures N = 8 within
    /// 0.8 dB of exact on the cube, N = 16 5.8 dB) and [`Adaptive`] a budget of
    /// 1/4 texel ([`Draw::with_adaptive_budget`]).
    pub fn new<M>(
        texture: Option<Texture<'a>>,
        viewport: Viewport,
        cull: Cull,
    ) -> Result<Self, Error>
    where
        M: Stages + 'a,
    {
        Self::new_mip::<M>(texture.map(MipTexture::single), viewport, cull)
    }

    /// Like [`Draw::new`] with a mip chain, for the mipmapped samplers (for example
    /// [`Trilinear`](crate::texture::Trilinear)).
    pub fn new_mip<M>(
        texture: Option<MipTexture<'a>>,
        viewport: Viewport,
        cull: Cull,
    ) -> Result<Self, Error>
    where
        M: Stages + 'a,
    {
        let projection = match <M::P as ProjectionStage>::KIND {
            ProjKind::Affine => Projection::Affine,
            ProjKind::Exact => Projection::Exact,
            ProjKind::Subdivided => Projection::Subdivided {
                log2_n: <M::P as ProjectionStage>::LOG2_N,
            },
            ProjKind::Quadratic => Projection::Quadratic {
                log2_n: <M::P as ProjectionStage>::LOG2_N,
            },
            ProjKind::Adaptive => Projection::Adaptive { budget: 64 },
            ProjKind::Dynamic => Projection::Exact,
        };
        let mode = DrawMode {
            projection,
            filter: <M::F as TexSampler>::FILTER,
            mag_filter: None,
            mip: if <M::F as TexSampler>::LOD {
                MipFilter::Linear
            } else {
                MipFilter::None
            },
            lod: Lod::default(),
            wrap: [<M::WU as WrapMode>::MODE, <M::WV as WrapMode>::MODE],
            shading: <M::S as ShadingStage>::KIND,
            depth: if <M::D as DepthStage>::TEST {
                DepthTest::Less
            } else {
                DepthTest::Off
            },
            cull,
        };
        check(&mode, &texture)?;
        if let Some(t) = &texture {
            crate::shading::check_footprints_bound::<M::F>(t)?;
        }
        Ok(Draw {
            mode,
            texture: texture.unwrap_or(MipTexture::single(Texture::from_static(&NO_TEXELS, 1, 1))),
            viewport,
            flat: 0xFFFF,
            raster: raster_triangle::<M, C>,
        })
    }

    /// A draw whose stages are chosen at run time. Links every combination of span loop
    /// (wrap modes are matched per texel fetch); meant for host tools, tests and demos.
    pub fn dynamic(
        mode: DrawMode,
        texture: Option<Texture<'a>>,
        viewport: Viewport,
    ) -> Result<Self, Error> {
        Self::dynamic_mip(mode, texture.map(MipTexture::single), viewport)
    }

    /// Like [`Draw::dynamic`] with a mip chain (`mode.mip` selects mipmapping).
    pub fn dynamic_mip(
        mode: DrawMode,
        texture: Option<MipTexture<'a>>,
        viewport: Viewport,
    ) -> Result<Self, Error> {
        check(&mode, &texture)?;
        if mode.shading == Shading::ModulateFacet {
            // Its loops would add to every firmware linking the run-time path; a typed
            // draw (`Pipeline<.., ModulateFacet, ..>`) links just the one it uses.
            return Err(Error::BadMode(
                "ModulateFacet is for typed draws (Draw::new); Draw::dynamic interpolates the intensity with ModulateIntensity",
            ));
        }
        Ok(Draw {
            mode,
            texture: texture.unwrap_or(MipTexture::single(Texture::from_static(&NO_TEXELS, 1, 1))),
            viewport,
            flat: 0xFFFF,
            raster: select::<C>(&mode),
        })
    }

    /// Sets the constant colour of [`Shading::Flat`] (RGB565; default white).
    pub fn with_flat_color(mut self, c: Rgb565) -> Self {
        self.flat = embedded_graphics_core::pixelcolor::IntoStorage::into_storage(c);
        self
    }

    /// With a different segment length for [`Projection::Subdivided`] and
    /// [`Projection::Quadratic`] (`log2_n` in `1..=6`; other projections ignore it).
    ///
    /// ```
    /// use embedded_graphics_core::pixelcolor::Rgb565;
    /// use fixel::geometry::{Cull, Viewport};
    /// use fixel::pipeline::*;
    /// use fixel::texture::{Bilinear, Repeat, Texture};
    /// use fixel::Error;
    /// static TEXELS: [Rgb565; 16] = [Rgb565::new(31, 0, 0); 16];
    /// let tex = Texture::new(&TEXELS, 4, 4)?;
    /// let vp = Viewport::new(0, 0, 320, 240)?;
    /// // The benchmark cube's mode: a parabola through exact values every 32 pixels.
    /// type Cube = Pipeline<Quadratic, Bilinear, Repeat, Repeat, ModulateIntensity, DepthLess>;
    /// let draw = Draw::<Rgb565>::new::<Cube>(Some(tex), vp, Cull::Back)?.with_subdivision(5)?;
    /// assert_eq!(draw.mode().projection, Projection::Quadratic { log2_n: 5 });
    /// // 128-pixel segments are refused.
    /// assert!(matches!(draw.with_subdivision(7), Err(Error::BadMode(_))));
    /// # Ok::<(), Error>(())
    /// ```
    ///
    /// # Errors
    /// [`Error::BadMode`] unless `log2_n` is in `1..=6`.
    pub fn with_subdivision(mut self, log2_n: u8) -> Result<Self, Error> {
        if !(1..=6).contains(&log2_n) {
            return Err(Error::BadMode(
                "subdivision log2_n must be in 1..=6 (N = 2..64)",
            ));
        }
        match self.mode.projection {
            Projection::Subdivided { .. } => {
                self.mode.projection = Projection::Subdivided { log2_n };
            }
            Projection::Quadratic { .. } => {
                self.mode.projection = Projection::Quadratic { log2_n };
            }
            _ => {}
        }
        Ok(self)
    }

    /// With a different error budget for [`Projection::Adaptive`] (1/256 texel).
    pub fn with_adaptive_budget(mut self, budget: u16) -> Self {
        if let Projection::Adaptive { .. } = self.mode.projection {
            self.mode.projection = Projection::Adaptive { budget };
        }
        self
    }

    /// With level-of-detail bias, clamps and granularity (mipmapped draws).
    pub fn with_lod(mut self, lod: Lod) -> Self {
        self.mode.lod = lod;
        self
    }

    /// The draw's mode.
    pub fn mode(&self) -> &DrawMode {
        &self.mode
    }

    /// The viewport triangles are mapped to.
    pub fn viewport(&self) -> &Viewport {
        &self.viewport
    }

    /// Whether `target` can take this draw: [`Error::NoDepthBuffer`] when the draw tests
    /// depth and the target has no depth buffer.
    pub fn check_target(&self, target: &dyn RenderTarget<Color = C>) -> Result<(), Error> {
        if self.mode.depth == DepthTest::Less && !target.has_depth() {
            return Err(Error::NoDepthBuffer);
        }
        Ok(())
    }

    /// Draws triangles given in clip space and returns the number of pixels written (with a
    /// depth test: that passed it). Triangles behind the camera, outside the view volume,
    /// culled or of zero area are skipped; the rest are clipped. A depth-testing draw into a
    /// target without depth is refused ([`Error::NoDepthBuffer`]) before anything is drawn.
    pub fn clip_triangles<T: RenderTarget<Color = C>>(
        &self,
        tris: &[[ClipVertex; 3]],
        target: &mut T,
    ) -> Result<u32, Error> {
        self.check_target(target)?;
        let mut pixels = 0u32;
        for tri in tris {
            clip_and_project(
                tri,
                &self.viewport,
                self.mode.cull,
                self.affine(),
                &mut |s| {
                    pixels = pixels.wrapping_add((self.raster)(self, Some(s), target, None));
                },
            );
        }
        Ok(pixels)
    }

    /// Clips, projects and culls one clip-space triangle, handing each resulting screen
    /// triangle to `emit` (for binning).
    pub fn project(&self, tri: &[ClipVertex; 3], emit: &mut impl FnMut(&ScreenTriangle)) {
        clip_and_project(tri, &self.viewport, self.mode.cull, self.affine(), emit);
    }

    /// [`project`](Self::project) for geometry that stays in view: projects and culls one
    /// clip-space triangle as `project` does (the same screen triangle), but never clips.
    /// Returns `false`, emitting nothing, for a triangle that crosses the near or far plane
    /// or the guard band (`project` would have clipped it); count those to know the scene
    /// left the view. A firmware that calls only this links no clipper: about 1.8 KB less
    /// flash on Cortex-M4F (`cargo xtask size`, `size_affine_unclipped`).
    ///
    /// ```
    /// use embedded_graphics_core::pixelcolor::Rgb565;
    /// use fixel::geometry::{ClipVertex, Cull, Viewport};
    /// use fixel::math::Fx;
    /// use fixel::pipeline::*;
    /// use fixel::texture::{Nearest, Repeat, Texture};
    /// use fixel::Error;
    /// static TEXELS: [Rgb565; 16] = [Rgb565::new(31, 0, 0); 16];
    /// let tex = Texture::new(&TEXELS, 4, 4)?;
    /// let vp = Viewport::new(0, 0, 320, 240)?;
    /// type Tiny = Pipeline<Affine, Nearest, Repeat, Repeat, Replace, NoDepth>;
    /// let draw = Draw::<Rgb565>::new::<Tiny>(Some(tex), vp, Cull::None)?;
    /// let at = |x: f32, y: f32, w: f32| {
    ///     let p = [x, y, 0.0, w].map(Fx::from_num);
    ///     ClipVertex::new(p, [Fx::ZERO, Fx::ZERO])
    /// };
    /// let mut screen = 0;
    /// // In view: one screen triangle.
    /// let near = [at(-0.5, -0.5, 1.0), at(0.5, -0.5, 1.0), at(0.0, 0.5, 1.0)];
    /// assert!(draw.project_unclipped(&near, &mut |_| screen += 1));
    /// // One corner behind the camera: it would need clipping, so it is refused.
    /// let behind = [at(-0.5, -0.5, 1.0), at(0.5, -0.5, 1.0), at(0.0, 0.5, -1.0)];
    /// assert!(!draw.project_unclipped(&behind, &mut |_| screen += 1));
    /// assert_eq!(screen, 1);
    /// # Ok::<(), Error>(())
    /// ```
    pub fn project_unclipped(
        &self,
        tri: &[ClipVertex; 3],
        emit: &mut impl FnMut(&ScreenTriangle),
    ) -> bool {
        project_unclipped(tri, &self.viewport, self.mode.cull, emit)
    }

    /// Affine draws interpolate clipped vertices' attributes as GL's `noperspective`.
    fn affine(&self) -> bool {
        self.mode.projection == Projection::Affine
    }

    /// Draws one screen triangle (already clipped, projected and culled); returns the pixels
    /// written, or [`Error::NoDepthBuffer`] as [`clip_triangles`](Self::clip_triangles).
    pub fn screen_triangle(
        &self,
        tri: &ScreenTriangle,
        target: &mut dyn RenderTarget<Color = C>,
    ) -> Result<u32, Error> {
        self.check_target(target)?;
        Ok((self.raster)(self, Some(tri), target, None))
    }

    /// [`screen_triangle`](Self::screen_triangle) for callers that checked the target once.
    pub(crate) fn screen_triangle_checked(
        &self,
        tri: &ScreenTriangle,
        target: &mut dyn RenderTarget<Color = C>,
    ) -> u32 {
        (self.raster)(self, Some(tri), target, None)
    }

    /// [`screen_triangle_checked`](Self::screen_triangle_checked) with the set-up taken
    /// from, or kept in, a band renderer's cache (`slot`); without `tri`, the triangle kept
    /// in `slot`.
    pub(crate) fn screen_triangle_slot(
        &self,
        tri: Option<&ScreenTriangle>,
        target: &mut dyn RenderTarget<Color = C>,
        slot: SetupSlot<'_>,
    ) -> u32 {
        (self.raster)(self, tri, target, slot)
    }
}

/// The classic path: the built-in shader of `M`, fed the classic varyings.
fn raster_triangle<'a, M, C>(
    draw: &Draw<'a, C>,
    tri: Option<&ScreenTriangle>,
    target: &mut dyn RenderTarget<Color = C>,
    slot: SetupSlot<'_>,
) -> u32
where
    M: Stages,
    C: TargetColor,
{
    let mode = &draw.mode;
    let tex = TexBinding::new_unchecked(
        &draw.texture,
        M::F::from_mode(mode),
        M::WU::from_wrap(mode.wrap[0]),
        M::WV::from_wrap(mode.wrap[1]),
        mode.lod,
    );
    let shader = <M::S as ShadingStage>::shader(tex, draw.flat);
    let params = RasterParams::new(
        &draw.viewport,
        mode.projection,
        mode.depth == DepthTest::Less,
    );
    raster_shaded::<_, M::P, M::D, C, { crate::geometry::CLASSIC_VARYINGS }>(
        &shader,
        tri,
        <M::S as ShadingStage>::Shader::<'_, M::F, M::WU, M::WV>::from_classic,
        &params,
        target,
        slot,
    )
}

/// The run-time dispatch table: one instance per (filter, shading); projection, wraps and
/// the depth test are read at run time.
fn select<'a, C: TargetColor + 'a>(mode: &DrawMode) -> RasterFn<'a, C> {
    // One depth-testing loop per combination; `SpanCtx::depth_on` switches the test off at
    // run time (a span loop costs flash, a predictable branch per span costs nothing).
    macro_rules! by_depth {
        ($p:ty, $f:ty, $s:ty) => {
            raster_triangle::<Pipeline<$p, $f, DynWrap, DynWrap, $s, DepthLess>, C>
                as RasterFn<'a, C>
        };
    }
    macro_rules! by_shading {
        ($p:ty, $f:ty) => {
            match mode.shading {
                Shading::Replace => by_depth!($p, $f, Replace),
                Shading::Modulate => by_depth!($p, $f, Modulate),
                // Refused by `dynamic_mip`; the intensity loop draws the same on facets.
                Shading::ModulateIntensity | Shading::ModulateFacet => {
                    by_depth!($p, $f, ModulateIntensity)
                }
                Shading::Gouraud => by_depth!($p, Nearest, Gouraud),
                Shading::Flat => by_depth!($p, Nearest, Flat),
            }
        };
    }
    // A magnification filter other than the minification one needs the level of detail,
    // so it goes through the mipmapping sampler even without mip levels.
    let same_mag = mode.mag_filter.is_none_or(|m| m == mode.filter);
    macro_rules! by_filter {
        ($p:ty) => {
            match (mode.mip, mode.filter) {
                (MipFilter::None, crate::texture::Filter::Nearest) if same_mag => {
                    by_shading!($p, Nearest)
                }
                (MipFilter::None, crate::texture::Filter::Bilinear) if same_mag => {
                    by_shading!($p, Bilinear)
                }
                _ => by_shading!($p, DynMip),
            }
        };
    }
    // The projection is read from the draw at run time: one span loop per filter and
    // shading instead of four.
    by_filter!(DynProjection)
}
