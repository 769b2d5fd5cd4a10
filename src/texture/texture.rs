//! A borrowed, power-of-two RGB565 texture.
//!
//! Units and conventions (OpenGL ES 3.2, texture minification and magnification):
//! - Texels are a row-major `&[Rgb565]` slice: texel `(i, j)` (column `i`, row `j`) is at
//!   index `j * width + i`. Row 0 comes first and is where `t = 0` (`v = 0`) lies.
//! - Sides are powers of two from 1 to 4096 (`log2` 0..=[`MAX_LOG2_SIZE`]); width and height
//!   are independent (1x1, 1xN, Nx1 and 4096x4096 are all valid). The slice length must be
//!   exactly `width * height`.
//! - Texel `i` covers `[i, i + 1)` in texel units and its centre is at `i + 0.5`. Sampling
//!   coordinates are raw I16F16 (`i32` with 16 fractional bits, 65536 = one texel, so
//!   `u = s * width`); see [`super::Sampler`].
//! - The border colour (used by [`ClampToBorder`](super::ClampToBorder)) defaults to black.
//!
//! Because the constructor checks `texels.len() == width * height` and the fields are private,
//! [`Texture::texel_raw`] masks its indices with `size - 1` and can never index out of bounds.

use embedded_graphics_core::pixelcolor::{IntoStorage, Rgb565};

use crate::Error;

/// Largest supported `log2` of a texture side: sides are 1..=4096.
pub const MAX_LOG2_SIZE: u32 = 12;

/// Largest supported texture side, `2^MAX_LOG2_SIZE`.
const MAX_SIDE: u32 = 1 << MAX_LOG2_SIZE;

/// A borrowed RGB565 texture with power-of-two sides, row-major, row 0 first.
///
/// Copying it copies the reference, not the texels.
#[derive(Clone, Copy, Debug)]
pub struct Texture<'a> {
    texels: &'a [Rgb565],
    log2_width: u8,
    log2_height: u8,
    border: u16,
}

/// Checks the sides and the length; returns `(log2_width, log2_height)`.
const fn validate(len: usize, width: u32, height: u32) -> Result<(u8, u8), Error> {
    if width == 0 || width > MAX_SIDE {
        return Err(Error::BadSize(width));
    }
    if height == 0 || height > MAX_SIDE {
        return Err(Error::BadSize(height));
    }
    if !width.is_power_of_two() {
        return Err(Error::NotPowerOfTwo(width));
    }
    if !height.is_power_of_two() {
        return Err(Error::NotPowerOfTwo(height));
    }
    // Both sides <= 4096, so the product <= 2^24 fits u32. Compare in u64 so the check is
    // exact whatever the width of usize (no truncation on 16-bit targets).
    let expected = width * height;
    if len as u64 != expected as u64 {
        return Err(Error::WrongLength {
            expected: if expected as usize as u32 == expected {
                expected as usize
            } else {
                usize::MAX
            },
            actual: len,
        });
    }
    Ok((width.trailing_zeros() as u8, height.trailing_zeros() as u8))
}

impl<'a> Texture<'a> {
    /// Wraps a row-major texel slice of `width * height` texels.
    ///
    /// # Errors
    /// - [`Error::BadSize`] if a side is 0 or larger than 4096 (width is checked first),
    /// - [`Error::NotPowerOfTwo`] if a side is not a power of two,
    /// - [`Error::WrongLength`] if `texels.len() != width * height`.
    pub fn new(texels: &'a [Rgb565], width: u32, height: u32) -> Result<Self, Error> {
        let (log2_width, log2_height) = validate(texels.len(), width, height)?;
        Ok(Texture {
            texels,
            log2_width,
            log2_height,
            border: 0,
        })
    }

    /// Sets the border colour used by [`ClampToBorder`](super::ClampToBorder)
    /// (default black).
    #[must_use]
    pub fn with_border(self, border: Rgb565) -> Self {
        self.with_border_raw(border.into_storage())
    }

    /// Sets the border colour from a raw RGB565 value (usable in `const`/`static`).
    #[must_use]
    pub const fn with_border_raw(mut self, border: u16) -> Self {
        self.border = border;
        self
    }

    /// Width in texels (a power of two, 1..=4096).
    #[inline(always)]
    pub const fn width(&self) -> u32 {
        1 << self.log2_width
    }

    /// Height in texels (a power of two, 1..=4096).
    #[inline(always)]
    pub const fn height(&self) -> u32 {
        1 << self.log2_height
    }

    /// `log2(width)`, 0..=[`MAX_LOG2_SIZE`].
    #[inline(always)]
    pub const fn log2_width(&self) -> u32 {
        self.log2_width as u32
    }

    /// `log2(height)`, 0..=[`MAX_LOG2_SIZE`].
    #[inline(always)]
    pub const fn log2_height(&self) -> u32 {
        self.log2_height as u32
    }

    /// The texel slice, row-major, `width * height` long.
    #[inline(always)]
    pub const fn texels(&self) -> &'a [Rgb565] {
        self.texels
    }

    /// The border colour as raw RGB565.
    #[inline(always)]
    pub const fn border_raw(&self) -> u16 {
        self.border
    }

    /// Raw RGB565 of texel `(i, j)` (column, row). Indices are meant to be in range
    /// (`i < width`, `j < height`); they are masked with `size - 1`, so out-of-range indices
    /// wrap (repeat) instead of panicking.
    #[inline(always)]
    pub fn texel_raw(&self, i: u32, j: u32) -> u16 {
        let i = i & (self.width() - 1);
        let j = j & (self.height() - 1);
        // texels.len() = width * height is a power of two (>= 1), so masking with len - 1
        // keeps idx unchanged and lets the optimiser see idx < len.
        let idx = ((j << self.log2_width) | i) as usize & self.texels.len().wrapping_sub(1);
        // i < width and j < height, so idx < width * height == texels.len() (checked by the
        // constructors; the fields are private). The compiler cannot see that invariant, so
        // `[idx]` would keep a (dead) panic path; `get` costs the same compare and leaves
        // the release binary with no panic path at all. The `None` arm is unreachable.
        debug_assert!(idx < self.texels.len());
        match self.texels.get(idx) {
            Some(c) => c.into_storage(),
            None => self.border,
        }
    }

    /// Raw RGB565 of the texel at row-major index `idx`, taken modulo the texel count (a
    /// power of two): `(j << log2_width) | i` for in-range `i`, `j`; higher bits of a
    /// wrapped row index fall away. Never panics.
    #[inline(always)]
    pub fn texel_at(&self, idx: u32) -> u16 {
        let idx = idx as usize & self.texels.len().wrapping_sub(1);
        match self.texels.get(idx) {
            Some(c) => c.into_storage(),
            None => self.border,
        }
    }
}

impl Texture<'static> {
    /// `const` constructor for textures in flash: same checks as [`Texture::new`], but a bad
    /// size or length panics, which in a `const` or `static` is a **compile-time** error
    /// (like embedded-graphics' `ImageRaw::new`).
    ///
    /// ```
    /// use fixel::Rgb565;
    /// use fixel::texture::Texture;
    ///
    /// static TEXELS: [Rgb565; 8] = [Rgb565::new(31, 0, 0); 8];
    /// static TEX: Texture<'static> = Texture::from_static(&TEXELS, 4, 2);
    /// assert_eq!(TEX.width(), 4);
    /// ```
    ///
    /// A wrong length does not compile:
    ///
    /// ```compile_fail
    /// use fixel::Rgb565;
    /// use fixel::texture::Texture;
    ///
    /// static TEXELS: [Rgb565; 8] = [Rgb565::new(31, 0, 0); 8];
    /// static TEX: Texture<'static> = Texture::from_static(&TEXELS, 4, 4);
    /// ```
    ///
    /// # Panics
    /// If [`Texture::new`] would return an error (at compile time when evaluated in a
    /// `const`/`static`; at run time otherwise — use [`Texture::new`] there).
    pub const fn from_static(texels: &'static [Rgb565], width: u32, height: u32) -> Self {
        match validate(texels.len(), width, height) {
            Ok((log2_width, log2_height)) => Texture {
                texels,
                log2_width,
                log2_height,
                border: 0,
            },
            Err(Error::BadSize(_)) => panic!("texture side is 0 or larger than 4096"),
            Err(Error::NotPowerOfTwo(_)) => panic!("texture side is not a power of two"),
            Err(_) => panic!("texel slice length is not width * height"),
        }
    }
}

#[cfg(test)]
mod tests {
    extern crate std;
    use super::*;
    use crate::color::rgb565;
    use std::vec::Vec;

    fn ramp(n: usize) -> Vec<Rgb565> {
        (0..n)
            .map(|k| {
                Rgb565::from(embedded_graphics_core::pixelcolor::raw::RawU16::new(
                    k as u16,
                ))
            })
            .collect()
    }

    #[test]
    fn constructor_errors() {
        let t = ramp(16);
        assert_eq!(Texture::new(&t, 0, 16).unwrap_err(), Error::BadSize(0));
        assert_eq!(Texture::new(&t, 16, 0).unwrap_err(), Error::BadSize(0));
        assert_eq!(Texture::new(&t, 8192, 1).unwrap_err(), Error::BadSize(8192));
        assert_eq!(Texture::new(&t, 1, 5000).unwrap_err(), Error::BadSize(5000));
        assert_eq!(
            Texture::new(&t, u32::MAX, 1).unwrap_err(),
            Error::BadSize(u32::MAX)
        );
        assert_eq!(Texture::new(&t, 3, 4).unwrap_err(), Error::NotPowerOfTwo(3));
        assert_eq!(Texture::new(&t, 4, 6).unwrap_err(), Error::NotPowerOfTwo(6));
        assert_eq!(
            Texture::new(&t, 4, 8).unwrap_err(),
            Error::WrongLength {
                expected: 32,
                actual: 16
            }
        );
        assert_eq!(
            Texture::new(&t[..15], 4, 4).unwrap_err(),
            Error::WrongLength {
                expected: 16,
                actual: 15
            }
        );
        assert!(Texture::new(&t, 4, 4).is_ok());
        assert!(Texture::new(&t, 16, 1).is_ok());
        assert!(Texture::new(&t, 1, 16).is_ok());
        assert!(Texture::new(&t[..1], 1, 1).is_ok());
        assert!(Texture::new(&[], 1, 1).is_err());
    }

    #[test]
    fn accessors_and_layout() {
        let t = ramp(32);
        let tex = Texture::new(&t, 8, 4).unwrap();
        assert_eq!((tex.width(), tex.height()), (8, 4));
        assert_eq!((tex.log2_width(), tex.log2_height()), (3, 2));
        assert_eq!(tex.texels().len(), 32);
        assert_eq!(tex.border_raw(), 0);
        for j in 0..4 {
            for i in 0..8 {
                assert_eq!(tex.texel_raw(i, j), (j * 8 + i) as u16);
            }
        }
        // Out-of-range indices are masked, never panic.
        assert_eq!(tex.texel_raw(8, 0), 0);
        assert_eq!(tex.texel_raw(u32::MAX, u32::MAX), 31);
        let red = Rgb565::new(31, 0, 0);
        assert_eq!(tex.with_border(red).border_raw(), rgb565(31, 0, 0));
        assert_eq!(tex.with_border_raw(0x1234).border_raw(), 0x1234);
    }

    #[test]
    fn largest_texture() {
        let t = std::vec![Rgb565::new(1, 2, 3); 4096 * 4096];
        let tex = Texture::new(&t, 4096, 4096).unwrap();
        assert_eq!(tex.log2_width(), 12);
        assert_eq!(tex.texel_raw(4095, 4095), rgb565(1, 2, 3));
        assert_eq!(tex.texel_raw(u32::MAX, u32::MAX), rgb565(1, 2, 3));
    }

    static TEXELS: [Rgb565; 8] = [Rgb565::new(0, 63, 0); 8];
    static STATIC_TEX: Texture<'static> =
        Texture::from_static(&TEXELS, 8, 1).with_border_raw(0xF800);

    #[test]
    fn from_static_const() {
        assert_eq!(STATIC_TEX.width(), 8);
        assert_eq!(STATIC_TEX.height(), 1);
        assert_eq!(STATIC_TEX.border_raw(), 0xF800);
        assert_eq!(STATIC_TEX.texel_raw(3, 0), 0x07E0);
    }

    #[test]
    #[should_panic]
    fn from_static_runtime_panics() {
        static T: [Rgb565; 8] = [Rgb565::new(0, 0, 0); 8];
        let _ = Texture::from_static(&T, 3, 1);
    }
}
