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

/// A vertex after clipping, perspective divide and viewport mapping.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct ScreenVertex {
    /// Screen x, sub-pixel units (4 fractional bits), inside the guard band.
    pub x: i32,
    /// Screen y (down), sub-pixel units (4 fractional bits), inside the guard band.
    pub y: i32,
    /// Window depth in `[0, 65535]` with 14 fractional bits (`0..=65535 << 14`).
    pub z: i32,
    /// Clip-space `w`, I16F16 bits, positive (at least the clipper's minimum `w`).
    pub w: i32,
    /// Normalized texture coordinates, I16F16 bits.
    pub uv: [i32; 2],
    /// Gouraud colour, Q8 per channel.
    pub color: [u16; 3],
}

/// Three screen vertices. Winding is kept as given (culling has already been applied).
pub type ScreenTriangle = [ScreenVertex; 3];
