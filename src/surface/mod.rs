//! Surfaces (render targets): where spans of finished pixels go.
//!
//! The span writer needs rows, not pixels: [`RenderTarget::row_mut`] hands out one colour
//! row slice (and its depth row, when the target has a depth buffer) per span, so the
//! per-pixel loop is a plain slice walk with no call per pixel.
//!
//! * [`Frame`]: a colour slice (`&mut [C]`) plus an optional 16-bit depth slice, covering
//!   rows `y0..y0 + height` of a frame. With `y0 = 0` and the full height it is an ordinary
//!   framebuffer; with fewer rows it is a *band* (see [`BandRenderer`]).
//! * [`BandRenderer::render`]: draws a frame as horizontal bands through a small buffer and flushes each to
//!   any embedded-graphics `DrawTarget` through `fill_contiguous`.
//! * [`BandRenderer::render_spans`]: bands for meshes of any size, with two bytes of storage per triangle.

pub(crate) mod accum_bands;
pub(crate) mod band;
pub(crate) mod depth_map;
pub(crate) mod frame;
pub(crate) mod resample;
pub(crate) mod smooth;
pub(crate) mod spans;

pub use band::{BandError, BandRenderer, BandStats, Binned, DrawTargetFlush, TriangleSink};
pub use depth_map::{DepthMap, ShadowMap, MAX_MAP_SIZE, MIN_MAP_SIZE};
pub use frame::{Frame, DEPTH_CLEAR};
pub use resample::{resolve_box, Accumulator};
pub use smooth::smooth_edges;
pub use spans::{BandRange, MeshSink};

use crate::color::TargetColor;

/// One row of a target: its colour pixels and, if the target has one, its depth values.
pub type Row<'r, C> = (&'r mut [C], Option<&'r mut [u16]>);

/// Something the span writer can fill row by row.
pub trait RenderTarget {
    /// Pixel colour type.
    type Color: TargetColor;
    /// Width in pixels.
    fn width(&self) -> u32;
    /// Frame rows this target holds: `first..end` (a band holds a sub-range).
    fn row_range(&self) -> (i32, i32);
    /// The colour row `y` (frame coordinates) and its depth row, if the target has a depth
    /// buffer. `None` when `y` is outside [`row_range`](Self::row_range).
    fn row_mut(&mut self, y: i32) -> Option<Row<'_, Self::Color>>;
    /// Whether [`row_mut`](Self::row_mut) hands out depth rows. A depth-testing draw into
    /// a target without depth is refused with [`Error::NoDepthBuffer`](crate::Error).
    fn has_depth(&self) -> bool;

    /// A lower bound of every depth value stored in the target (a one-value hierarchical
    /// depth buffer): a span whose depths all lie below it passes the depth test without
    /// reading the buffer. `0`, the default, means unknown and skips nothing; [`Frame`]
    /// keeps a real bound from its [`Frame::clear`] on.
    #[inline]
    fn depth_floor(&self) -> u16 {
        0
    }

    /// Lowers the bound of [`RenderTarget::depth_floor`] after depths of at least `z` were
    /// written. The default does nothing.
    #[inline]
    fn lower_depth_floor(&mut self, z: u16) {
        let _ = z;
    }
}
