//! Raster stage: turns a screen-space triangle into horizontal spans of covered pixels.
//!
//! The rasterizer knows nothing of textures, colours or depth: it emits `(y, x0..x1)` spans
//! to a [`SpanSink`], which is what makes coverage rules testable with tiny ASCII grids.
//! Attribute interpolation (plane equations) lives in [`Plane`], and is used by the
//! pipeline's span writers, not by the rasterizer.
//!
//! # Conventions (OpenGL ES)
//! * Screen coordinates are sub-pixel integers with [`SUBPIXEL_BITS`] = 4 fractional bits
//!   (1/16 pixel, as GL hardware commonly snaps), x to the right, y **down** (row 0 at the
//!   top, as a framebuffer is stored).
//! * Pixel centres are at half-integers: pixel `(px, py)` is sampled at
//!   `(px + 0.5, py + 0.5)`.
//! * Top-left fill rule: a centre exactly on a left edge or a flat top edge is covered; one
//!   exactly on a right or flat bottom edge is not. Two triangles that share an edge therefore
//!   cover every pixel along it exactly once.
//!
//! # Exactness
//! Edges are walked with an exact integer DDA (quotient and remainder), so the covered span
//! of every row equals what exact rational arithmetic gives: there is no accumulated error,
//! and a shared edge is evaluated identically whichever triangle it belongs to (edges are
//! always walked top to bottom).

pub(crate) mod edge;
pub(crate) mod gradient;
pub(crate) mod triangle;

pub use crate::geometry::{
    Rect, ATTR_SUBPIXEL_BITS, GUARD_BAND_PX, MAX_VIEWPORT_PX, SUBPIXEL_BITS, SUBPIXEL_ONE,
};
pub use edge::EdgeWalker;
pub use gradient::{Plane, PlaneSetup};
pub use triangle::{first_row_at_or_below, rasterize, SpanSink, COUNT_IN_LOOP};
pub(crate) use triangle::{rasterize_rows, rasterize_shared};
