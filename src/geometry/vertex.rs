//! Vertices at the two ends of the geometry stage.

use crate::math::Fx;

/// Full intensity of a colour channel in the Q8 colour format used by vertices (`256`).
pub const COLOR_ONE: u16 = 256;

/// A vertex in OpenGL clip space: the low-level entry point's input, and the seam where any
/// other renderer (a GL implementation included) can be fed exactly the same data.
///
/// * `position`: `(x, y, z, w)` in clip space, I16F16 (±32768, resolution 2^-16).
/// * `uv`: texture coordinates, I16F16, in *normalized* units (1.0 = one whole texture;
///   values outside `[0, 1]` are handled by the draw's wrap modes).
/// * `color`: per-channel Gouraud factor, Q8 (`0..=256`, [`COLOR_ONE`] = full). Larger
///   values are clamped to `COLOR_ONE` where they are used.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct ClipVertex {
    /// Clip-space position `(x, y, z, w)`.
    pub position: [Fx; 4],
    /// Normalized texture coordinates `(s, t)`; t = 0 is the texture's first row.
    pub uv: [Fx; 2],
    /// Red, green, blue factors, Q8 (256 = 1.0).
    pub color: [u16; 3],
}

impl ClipVertex {
    /// A white vertex at `position` with texture coordinates `uv`.
    pub const fn new(position: [Fx; 4], uv: [Fx; 2]) -> Self {
        ClipVertex {
            position,
            uv,
            color: [COLOR_ONE; 3],
        }
    }

    /// The same vertex with its Gouraud colour set from 8-bit channels (255 maps to 256).
    pub const fn with_rgb8(mut self, r: u8, g: u8, b: u8) -> Self {
        self.color = [q8(r), q8(g), q8(b)];
        self
    }
}

/// 8-bit channel to Q8 with 255 -> 256: `(c * 257 + 128) >> 8`.
const fn q8(c: u8) -> u16 {
    ((c as u32 * 257 + 128) >> 8) as u16
}

/// A clip-space vertex with `N` varyings: the open pipeline's input.
///
/// * `position`: `(x, y, z, w)` in clip space, I16F16 (±32768, resolution 2^-16).
/// * `varyings`: `N` attributes in whatever fixed-point format the shader documents for
///   them (raw `i32` bits). They are interpolated linearly in clip space by the clipper and
///   perspective-correctly (or as the draw's projection says) across the triangle, so any
///   format works as long as each varying's values and their differences fit `i32`.
///   Textured built-in shaders take normalized texture coordinates as I16F16 bits (1.0 = one
///   whole texture) and colours as Q8 with 16 more fraction bits (`256 << 16` = 1.0).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Vertex<const N: usize> {
    /// Clip-space position `(x, y, z, w)`.
    pub position: [Fx; 4],
    /// The shader's varyings, raw fixed-point bits.
    pub varyings: [i32; N],
}

impl<const N: usize> Vertex<N> {
    /// A vertex at `position` with `varyings`.
    pub const fn new(position: [Fx; 4], varyings: [i32; N]) -> Self {
        Vertex { position, varyings }
    }
}

/// The number of varyings of a [`ClipVertex`] (`u, v, r, g, b`).
pub const CLASSIC_VARYINGS: usize = 5;

impl ClipVertex {
    /// The classic vertex as an open-pipeline [`Vertex`]: `[u, v, r, g, b]` with `u, v` the
    /// I16F16 bits of `uv` and each colour channel clamped to [`COLOR_ONE`] and shifted to
    /// Q8.16 (`256 << 16` = 1.0).
    #[inline]
    pub fn to_vertex(&self) -> Vertex<CLASSIC_VARYINGS> {
        let c = |k: usize| i32::from(self.color[k].min(COLOR_ONE)) << 16;
        Vertex {
            position: self.position,
            varyings: [self.uv[0].to_bits(), self.uv[1].to_bits(), c(0), c(1), c(2)],
        }
    }
}

/// A vertex after clipping, perspective divide and viewport mapping.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ScreenVertex<const N: usize = CLASSIC_VARYINGS> {
    /// Screen x, sub-pixel units (4 fractional bits), inside the guard band.
    pub x: i32,
    /// Screen y (down), sub-pixel units (4 fractional bits), inside the guard band.
    pub y: i32,
    /// Where the vertex projects within its sub-pixel: the offset of its position rounded to
    /// `2^-ATTR_SUBPIXEL_BITS` pixel from `(x, y)`, in that unit (at most half a sub-pixel
    /// either way). Coverage uses `(x, y)`; attribute planes use
    /// `(x, y) 2^(ATTR_SUBPIXEL_BITS - SUBPIXEL_BITS) + sub`, so snapping moves edges, not
    /// textures (see [`crate::raster::ATTR_SUBPIXEL_BITS`]).
    pub sub: [i16; 2],
    /// Window depth in `[0, 65535]` with 14 fractional bits (`0..=65535 << 14`).
    pub z: i32,
    /// Clip-space `w`, I16F16 bits, positive (at least the clipper's minimum `w`).
    pub w: i32,
    /// The varyings, in the vertex's formats (for a [`ClipVertex`]: `u, v` as normalized
    /// I16F16 bits and `r, g, b` as Q8.16).
    pub varyings: [i32; N],
}

impl<const N: usize> Default for ScreenVertex<N> {
    fn default() -> Self {
        ScreenVertex {
            x: 0,
            y: 0,
            sub: [0; 2],
            z: 0,
            w: 0,
            varyings: [0; N],
        }
    }
}

impl<const N: usize> ScreenVertex<N> {
    /// The position attribute planes are built from: `(x, y)` plus [`sub`](Self::sub), in
    /// `2^-ATTR_SUBPIXEL_BITS` pixel ([`crate::raster::ATTR_SUBPIXEL_BITS`]).
    #[inline]
    pub fn attr_position(&self) -> (i32, i32) {
        use super::screen::{ATTR_SUBPIXEL_BITS, SUBPIXEL_BITS};
        let fine = |p: i32, sub: i16| {
            p.wrapping_shl(ATTR_SUBPIXEL_BITS - SUBPIXEL_BITS)
                .wrapping_add(i32::from(sub))
        };
        (fine(self.x, self.sub[0]), fine(self.y, self.sub[1]))
    }
}

/// Three screen vertices. Winding is kept as given (culling has already been applied).
pub type ScreenTriangle<const N: usize = CLASSIC_VARYINGS> = [ScreenVertex<N>; 3];
