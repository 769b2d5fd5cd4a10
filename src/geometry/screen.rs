//! Screen coordinates as geometry hands them to the rasterizer: their fixed-point formats
//! (sub-pixel bits for coverage and for attributes), the guard band that bounds them, and
//! the pixel rectangle the raster stage clips to.

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
/// (see [`Plane`](crate::raster::Plane)) and per-row stepping fits `i32`.
pub const GUARD_BAND_PX: i32 = 4096;
/// Largest viewport side in pixels (the viewport must sit inside the guard band).
pub const MAX_VIEWPORT_PX: u32 = 2048;

/// A pixel rectangle, half-open: columns `x0..x1`, rows `y0..y1`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub struct Rect {
    /// First column.
    pub x0: i32,
    /// First row.
    pub y0: i32,
    /// One past the last column.
    pub x1: i32,
    /// One past the last row.
    pub y1: i32,
}

impl Rect {
    /// The rectangle `0..width` by `0..height`.
    pub const fn of_size(width: u32, height: u32) -> Rect {
        Rect {
            x0: 0,
            y0: 0,
            x1: width as i32,
            y1: height as i32,
        }
    }

    /// Rows `y0..y1` of this rectangle (clamped to it).
    pub fn rows(self, y0: i32, y1: i32) -> Rect {
        Rect {
            y0: y0.max(self.y0),
            y1: y1.min(self.y1),
            ..self
        }
    }

    /// True when the rectangle contains no pixel.
    pub fn is_empty(self) -> bool {
        self.x0 >= self.x1 || self.y0 >= self.y1
    }
}

/// Value a depth buffer is cleared to: the far plane (depth 1.0 = 65535).
pub const DEPTH_CLEAR: u16 = u16::MAX;
