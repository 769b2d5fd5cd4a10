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

pub use edge::EdgeWalker;
pub use gradient::{Plane, PlaneSetup};
pub use triangle::{first_row_at_or_below, rasterize, Rect, SpanSink, COUNT_IN_LOOP};
pub(crate) use triangle::{rasterize_rows, rasterize_shared};

/// Fractional bits of screen coordinates: 4, so one pixel is 16 sub-pixel units.
pub const SUBPIXEL_BITS: u32 = 4;
/// One pixel in sub-pixel units.
pub const SUBPIXEL_ONE: i32 = 1 << SUBPIXEL_BITS;
/// Fractional bits of the screen positions that attribute planes (texture coordinates,
/// depth, every varying) are built from: 8, so attributes are interpolated from vertices
/// within 1/512 pixel of their exact projections, while coverage uses the 1/16-pixel grid of
/// [`SUBPIXEL_BITS`] (as GL: snapping moves the edges, not the texture).
pub const ATTR_SUBPIXEL_BITS: u32 = 12;
/// Largest absolute screen coordinate, in whole pixels, that the raster math accepts.
///
/// Geometry clips triangles to this guard band, so any vertex the rasterizer sees lies in
/// `[-GUARD_BAND_PX, GUARD_BAND_PX]` on both axes. With 4 sub-pixel bits that is
/// `|x| <= 2^16` sub-pixel units: edge and plane set-up products then stay below 2^63
/// (see [`Plane`]) and per-row stepping fits `i32`.
pub const GUARD_BAND_PX: i32 = 4096;
/// Largest viewport side in pixels (the viewport must sit inside the guard band).
pub const MAX_VIEWPORT_PX: u32 = 2048;
