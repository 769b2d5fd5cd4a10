//! The open draw: any [`Shader`], a projection and a depth stage as types, fed clip-space
//! [`Vertex`] triangles whose varyings the shader declares.
//!
//! ```
//! use fixel::prelude::*;
//! use fixel::geometry::Vertex;
//! use fixel::pipeline::{DepthLess, Exact, ShadedDraw};
//! use fixel::shading::Gouraud;
//! use fixel::Rgb565;
//!
//! // A Gouraud triangle: varyings r, g, b in Q8.16 (256 << 16 = 1.0).
//! let one = 256 << 16;
//! let p = |x: f32, y: f32| [fixel::math::fx(x), fixel::math::fx(y), Fx::ZERO, Fx::ONE];
//! let tri = [
//!     Vertex::new(p(-0.8, -0.8), [one, 0, 0]),
//!     Vertex::new(p(0.8, -0.8), [0, one, 0]),
//!     Vertex::new(p(0.0, 0.8), [0, 0, one]),
//! ];
//! let draw = ShadedDraw::<_, Exact, DepthLess>::new(Gouraud, Viewport::new(0, 0, 32, 32)?, Cull::Back)?;
//! let (mut color, mut depth) = ([Rgb565::default(); 32 * 32], [0u16; 32 * 32]);
//! let mut frame = Frame::new(&mut color, 32, 32)?.with_depth(&mut depth)?;
//! frame.clear(Rgb565::default());
//! assert!(draw.clip_triangles(&[tri], &mut frame)? > 300);
//! # Ok::<(), fixel::Error>(())
//! ```

use core::marker::PhantomData;

use super::raster::{raster_shaded, RasterParams};
use super::stages::{DepthStage, ProjKind, Projection, ProjectionStage};
use super::target::RenderTarget;
use super::SetupSlot;
use crate::color::TargetColor;
use crate::geometry::{
    clip_and_project_varyings, project_unclipped_varyings, Cull, ScreenTriangle, Vertex, Viewport,
};
use crate::shading::Shader;
use crate::Error;

/// A draw with a user shader `S`, projection `P` and depth stage `D` chosen as types: a
/// firmware links exactly this span loop.
pub struct ShadedDraw<S, P, D> {
    shader: S,
    viewport: Viewport,
    cull: Cull,
    projection: Projection,
    _stages: PhantomData<(P, D)>,
}

impl<S: core::fmt::Debug, P, D> core::fmt::Debug for ShadedDraw<S, P, D> {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.debug_struct("ShadedDraw")
            .field("shader", &self.shader)
            .field("viewport", &self.viewport)
            .field("projection", &self.projection)
            .finish()
    }
}

impl<S: Shader, P: ProjectionStage, D: DepthStage> ShadedDraw<S, P, D> {
    /// A draw of `shader` into `viewport`, culling `cull` faces. Subdivided projection uses
    /// N = 8 ([`ShadedDraw::with_subdivision`]), adaptive a budget of 1/4 texel
    /// ([`ShadedDraw::with_adaptive_budget`]).
    ///
    /// # Errors
    /// None today; the `Result` keeps room for checks of the shader's bindings.
    pub fn new(shader: S, viewport: Viewport, cull: Cull) -> Result<Self, Error> {
        let projection = match P::KIND {
            ProjKind::Affine => Projection::Affine,
            ProjKind::Exact => Projection::Exact,
            ProjKind::Subdivided => Projection::Subdivided { log2_n: P::LOG2_N },
            ProjKind::Quadratic => Projection::Quadratic { log2_n: P::LOG2_N },
            ProjKind::Adaptive => Projection::Adaptive { budget: 64 },
            ProjKind::Dynamic => Projection::Exact,
        };
        Ok(ShadedDraw {
            shader,
            viewport,
            cull,
            projection,
            _stages: PhantomData,
        })
    }

    /// With segment length `2^log2_n` for the subdivided and quadratic projections.
    ///
    /// # Errors
    /// [`Error::BadMode`] unless `log2_n` is in `1..=6`.
    pub fn with_subdivision(mut self, log2_n: u8) -> Result<Self, Error> {
        if !(1..=6).contains(&log2_n) {
            return Err(Error::BadMode(
                "subdivision log2_n must be in 1..=6 (N = 2..64)",
            ));
        }
        match self.projection {
            Projection::Subdivided { .. } => self.projection = Projection::Subdivided { log2_n },
            Projection::Quadratic { .. } => self.projection = Projection::Quadratic { log2_n },
            _ => {}
        }
        Ok(self)
    }

    /// With a different error budget for the adaptive projection (1/256 texel).
    pub fn with_adaptive_budget(mut self, budget: u16) -> Self {
        if let Projection::Adaptive { .. } = self.projection {
            self.projection = Projection::Adaptive { budget };
        }
        self
    }

    /// The shader.
    pub fn shader(&self) -> &S {
        &self.shader
    }

    /// The viewport triangles are mapped to.
    pub fn viewport(&self) -> &Viewport {
        &self.viewport
    }

    /// Clips, projects and culls one clip-space triangle, handing each resulting screen
    /// triangle to `emit` (for binning).
    pub fn project<const N: usize>(
        &self,
        tri: &[Vertex<N>; 3],
        emit: &mut impl FnMut(&ScreenTriangle<N>),
    ) {
        let noperspective = self.projection == Projection::Affine;
        clip_and_project_varyings(tri, &self.viewport, self.cull, noperspective, emit);
    }

    /// Projects and culls one clip-space triangle that needs no clipping, as
    /// [`project`](Self::project) would (the same screen triangle, bit for bit), without
    /// linking the clipper (about 1.3 KB of flash on Cortex-M4F): for firmware whose
    /// geometry stays in view. Returns `false`, emitting nothing, when the triangle crosses
    /// a plane of the view volume or guard band (it would have to be clipped).
    ///
    /// ```
    /// use fixel::prelude::*;
    /// use fixel::geometry::Vertex;
    /// use fixel::pipeline::{Affine, NoDepth, ShadedDraw};
    /// use fixel::shading::Gouraud;
    /// use fixel::Rgb565;
    ///
    /// let draw = ShadedDraw::<_, Affine, NoDepth>::new(Gouraud, Viewport::new(0, 0, 32, 32)?, Cull::Back)?;
    /// let one = 256 << 16;
    /// let at = |x: f32, y: f32, w: f32| {
    ///     Vertex::new([fixel::math::fx(x), fixel::math::fx(y), Fx::ZERO, fixel::math::fx(w)], [one, one, one])
    /// };
    /// let (mut color, mut drawn) = ([Rgb565::default(); 32 * 32], 0);
    /// let mut frame = Frame::new(&mut color, 32, 32)?;
    /// // In view: drawn without the clipper.
    /// let near = [at(-0.5, -0.5, 1.0), at(0.5, -0.5, 1.0), at(0.0, 0.5, 1.0)];
    /// assert!(draw.project_unclipped(&near, &mut |s| drawn += draw.screen_triangle(s, &mut frame).unwrap_or(0)));
    /// assert!(drawn > 100);
    /// // One corner behind the camera: it would need clipping, so it is refused.
    /// let behind = [at(-0.5, -0.5, 1.0), at(0.5, -0.5, 1.0), at(0.0, 0.5, -1.0)];
    /// assert!(!draw.project_unclipped(&behind, &mut |_| unreachable!()));
    /// # Ok::<(), fixel::Error>(())
    /// ```
    pub fn project_unclipped<const N: usize>(
        &self,
        tri: &[Vertex<N>; 3],
        emit: &mut impl FnMut(&ScreenTriangle<N>),
    ) -> bool {
        project_unclipped_varyings(tri, &self.viewport, self.cull, emit)
    }

    /// Whether `target` can take this draw: [`Error::NoDepthBuffer`] when the draw tests
    /// depth and the target has no depth buffer.
    pub fn check_target<C: TargetColor>(
        &self,
        target: &dyn RenderTarget<Color = C>,
    ) -> Result<(), Error> {
        if D::TEST && !target.has_depth() {
            return Err(Error::NoDepthBuffer);
        }
        Ok(())
    }

    /// Draws triangles given in clip space and returns the pixels written (with a depth
    /// test: that passed it). Triangles behind the camera, outside the view volume, culled
    /// or of zero area are skipped; the rest are clipped. A depth-testing draw into a target
    /// without depth is refused ([`Error::NoDepthBuffer`]) before anything is drawn.
    pub fn clip_triangles<const N: usize, C, T>(
        &self,
        tris: &[[Vertex<N>; 3]],
        target: &mut T,
    ) -> Result<u32, Error>
    where
        S: Shader<Varyings = [i32; N]>,
        C: TargetColor,
        T: RenderTarget<Color = C>,
    {
        self.check_target(target)?;
        let mut pixels = 0u32;
        for tri in tris {
            self.project(tri, &mut |s| {
                pixels = pixels.wrapping_add(self.raster(s, target));
            });
        }
        Ok(pixels)
    }

    /// Draws one screen triangle (already clipped, projected and culled); returns the pixels
    /// written, or [`Error::NoDepthBuffer`] as [`clip_triangles`](Self::clip_triangles).
    pub fn screen_triangle<const N: usize, C: TargetColor>(
        &self,
        tri: &ScreenTriangle<N>,
        target: &mut dyn RenderTarget<Color = C>,
    ) -> Result<u32, Error>
    where
        S: Shader<Varyings = [i32; N]>,
    {
        self.check_target(target)?;
        Ok(self.raster(tri, target))
    }

    fn raster<const N: usize, C: TargetColor>(
        &self,
        tri: &ScreenTriangle<N>,
        target: &mut dyn RenderTarget<Color = C>,
    ) -> u32
    where
        S: Shader<Varyings = [i32; N]>,
    {
        self.raster_slot(Some(tri), target, None)
    }

    /// Draws one screen triangle into a checked target, the set-up taken from, or kept in,
    /// a band renderer's cache (`slot`).
    #[inline]
    pub(crate) fn raster_slot<const N: usize, C: TargetColor>(
        &self,
        tri: Option<&ScreenTriangle<N>>,
        target: &mut dyn RenderTarget<Color = C>,
        slot: SetupSlot<'_>,
    ) -> u32
    where
        S: Shader<Varyings = [i32; N]>,
    {
        let params = RasterParams::new(&self.viewport, self.projection, true);
        raster_shaded::<S, P, D, C, N>(&self.shader, tri, |v| *v, &params, target, slot)
    }
}
