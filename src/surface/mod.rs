//! Surfaces (render targets): where spans of finished pixels go.
//!
//! The span writer needs rows, not pixels: [`RenderTarget::rows_mut`] lends the target's
//! row-major buffer ([`Rows`]: colour, and depth when the target has a depth buffer) once
//! per triangle, and the writer slices each span's row out of it, so the per-pixel loop is
//! a plain slice walk with no call per span or pixel.
//!
//! * [`Frame`]: a colour slice (`&mut [C]`) plus an optional 16-bit depth slice, covering
//!   rows `y0..y0 + height` of a frame. With `y0 = 0` and the full height it is an ordinary
//!   framebuffer; with fewer rows it is a *band* (see [`BandRenderer`]).
//! * [`BandRenderer::render`]: draws a frame as horizontal bands through a small buffer and flushes each to
//!   any embedded-graphics `DrawTarget` through `fill_contiguous`.
//! * [`BandRenderer::render_spans`]: bands for meshes of any size, with two bytes of storage per triangle
//!   ([`spans_frame`]: its binning pass, [`SpansFrame`], and its forms: sender, `async`, cores).
//! * [`overlap`]: a ring of band buffers and a [`BandSender`] (a DMA channel, say): band `k`
//!   is sent while band `k + 1` is drawn; [`overlap_async`]: the same as an `async` frame;
//!   [`share`]: one frame's bands drawn by two cores from bins built once;
//!   `spi_send`: senders over `embedded-hal` 1.0 SPI devices (features `embedded-hal`,
//!   `embedded-hal-async`).

pub(crate) mod accum_bands;
pub(crate) mod band;
mod band_draw;
mod band_link;
pub(crate) mod edge_aa;

pub(crate) mod frame;
pub mod overlap;
pub mod overlap_async;
pub(crate) mod resample;
mod setup_queue;
pub mod share;
pub(crate) mod smooth;
pub(crate) mod spans;
pub mod spans_frame;
#[cfg(any(feature = "embedded-hal", feature = "embedded-hal-async"))]
pub mod spi_send;

pub use crate::geometry::DEPTH_CLEAR;
pub use crate::pipeline::{RenderTarget, Row, Rows};
pub use crate::texture::{DepthMap, ShadowMap, MAX_MAP_SIZE, MIN_MAP_SIZE};
pub use band::{BandError, BandRenderer, BandStats, Binned, TriangleSink};
pub use band_draw::{AnyTriangle, AnyTriangleRef, BandDraw, Binnable, BINNED_VARYINGS};
pub use band_link::DrawTargetFlush;
pub use edge_aa::EdgeAa;
pub use frame::Frame;
pub use overlap::{BandSender, Blocking, Dma};
pub use overlap_async::AsyncBandSender;
pub use resample::{resolve_box, Accumulator};
pub use share::{BandShare, BinnedFrame};
pub use smooth::smooth_edges;
pub use spans::{BandRange, MeshSink};
pub use spans_frame::SpansFrame;
#[cfg(any(feature = "embedded-hal", feature = "embedded-hal-async"))]
pub use spi_send::SpiSender;
