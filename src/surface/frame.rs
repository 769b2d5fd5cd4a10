//! A framebuffer (or band of one) over borrowed slices: colour and optional 16-bit depth.

use super::RenderTarget;
use crate::color::TargetColor;
use crate::Error;

use crate::geometry::DEPTH_CLEAR;

/// Rows `y0..y0 + height` of a `width`-pixel-wide frame, stored row-major in borrowed
/// slices. Depth is optional: a scene that does not depth-test needs no depth memory.
///
/// ```
/// use fixel::surface::Frame;
/// use fixel::Rgb565;
/// let mut colour = [Rgb565::default(); 320 * 240];
/// let mut depth = [0u16; 320 * 240];
/// let frame = Frame::new(&mut colour, 320, 240).unwrap().with_depth(&mut depth).unwrap();
/// assert_eq!(frame.height(), 240);
/// // A slice of the wrong length is refused with an error that says so.
/// let mut short = [Rgb565::default(); 10];
/// assert!(Frame::new(&mut short, 320, 240).is_err());
/// ```
#[derive(Debug)]
pub struct Frame<'a, C> {
    color: &'a mut [C],
    depth: Option<&'a mut [u16]>,
    width: u32,
    height: u32,
    y0: i32,
    /// Every stored depth is at least this (0 until a `clear` makes it known).
    depth_floor: u16,
    /// Every stored depth is [`DEPTH_CLEAR`]: filled by [`Frame::with_depth`] or
    /// [`Frame::clear`] and not lent since ([`RenderTarget::rows_mut`] turns it off), so the
    /// next `clear` need not fill it again (a frame built with `with_depth` and cleared at
    /// once fills its depth once).
    depth_filled: bool,
}

impl<'a, C: TargetColor> Frame<'a, C> {
    /// A `width` x `height` frame over `color` (exactly `width * height` long).
    pub fn new(color: &'a mut [C], width: u32, height: u32) -> Result<Self, Error> {
        if width == 0 || height == 0 || width > 4096 || height > 4096 {
            return Err(Error::BadSize(if width == 0 || width > 4096 {
                width
            } else {
                height
            }));
        }
        let expected = width as usize * height as usize;
        if color.len() != expected {
            return Err(Error::WrongLength {
                expected,
                actual: color.len(),
            });
        }
        Ok(Frame {
            color,
            depth: None,
            width,
            height,
            y0: 0,
            depth_floor: 0,
            depth_filled: false,
        })
    }

    /// Adds a depth buffer (same size as the colour buffer), filled with [`DEPTH_CLEAR`]
    /// (the far plane) so that a frame drawn without a [`clear`](Self::clear) is still
    /// depth-tested correctly.
    pub fn with_depth(self, depth: &'a mut [u16]) -> Result<Self, Error> {
        let mut frame = self.with_depth_as_is(depth)?;
        if let Some(d) = frame.depth.as_deref_mut() {
            crate::fill::fill(d, DEPTH_CLEAR);
        }
        frame.depth_floor = DEPTH_CLEAR;
        frame.depth_filled = true;
        Ok(frame)
    }

    /// Attaches `depth` as it is, values kept: a later pass over a frame drawn before (the
    /// transparent triangles after the opaque scene, when the frame was rebuilt between
    /// them). The depth floor starts unknown.
    pub fn with_depth_kept(self, depth: &'a mut [u16]) -> Result<Self, Error> {
        self.with_depth_as_is(depth)
    }

    /// [`with_depth`](Self::with_depth) without the fill, for a band that is cleared next.
    pub(crate) fn with_depth_as_is(mut self, depth: &'a mut [u16]) -> Result<Self, Error> {
        if depth.len() != self.color.len() {
            return Err(Error::WrongLength {
                expected: self.color.len(),
                actual: depth.len(),
            });
        }
        self.depth = Some(depth);
        self.depth_floor = 0;
        self.depth_filled = false;
        Ok(self)
    }

    /// Makes this buffer hold frame rows `y0..y0 + height` instead of `0..height`.
    pub fn at_row(mut self, y0: u32) -> Self {
        self.y0 = y0.min(i32::MAX as u32 / 2) as i32;
        self
    }

    /// Height in rows.
    pub fn height(&self) -> u32 {
        self.height
    }

    /// First frame row held.
    pub fn first_row(&self) -> i32 {
        self.y0
    }

    /// Fills colour with `c` and depth (if any) with [`DEPTH_CLEAR`]. A depth buffer that
    /// is still as [`with_depth`](Self::with_depth) or the last `clear` filled it (not lent
    /// to a draw since) is not filled again.
    pub fn clear(&mut self, c: C) {
        crate::fill::fill(self.color, c);
        if let Some(d) = self.depth.as_deref_mut() {
            if !self.depth_filled {
                crate::fill::fill(d, DEPTH_CLEAR);
            }
            self.depth_filled = true;
        }
        self.depth_floor = DEPTH_CLEAR;
    }

    /// The colour pixels, row-major.
    pub fn pixels(&self) -> &[C] {
        self.color
    }

    /// The colour pixels, row-major, to write (a band's resolve before its flush, say).
    pub fn pixels_mut(&mut self) -> &mut [C] {
        self.color
    }

    /// The depth values, row-major, if there is a depth buffer.
    pub fn depth(&self) -> Option<&[u16]> {
        self.depth.as_deref()
    }
}

impl<C: TargetColor> RenderTarget for Frame<'_, C> {
    type Color = C;

    fn width(&self) -> u32 {
        self.width
    }

    fn row_range(&self) -> (i32, i32) {
        (self.y0, self.y0 + self.height as i32)
    }

    fn has_depth(&self) -> bool {
        self.depth.is_some()
    }

    #[inline]
    fn depth_floor(&self) -> u16 {
        self.depth_floor
    }

    #[inline]
    fn lower_depth_floor(&mut self, z: u16) {
        self.depth_floor = self.depth_floor.min(z);
    }

    #[inline]
    fn lend(&mut self) -> crate::pipeline::Lent<'_, C> {
        crate::pipeline::Lent {
            width: self.width,
            row_range: self.row_range(),
            depth_floor: self.depth_floor,
            rows: self.rows_mut(),
        }
    }

    #[inline]
    fn rows_mut(&mut self) -> super::Rows<'_, C> {
        // The depth rows may be written through what is lent.
        self.depth_filled = false;
        super::Rows {
            color: &mut *self.color,
            depth: self.depth.as_deref_mut(),
            width: self.width as usize,
            stride: self.width as usize,
            height: self.height as usize,
            y0: self.y0,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Rgb565;

    /// `row_mut` gives row `y0 + r` as `r * width..`, with and without depth, and `None`
    /// outside the band's rows (for any `y`, far outside included).
    #[test]
    fn rows_are_the_band_rows() {
        let (w, h) = (5u32, 3u32);
        let mut colour = [Rgb565::default(); 15];
        let mut depth = [0u16; 15];
        let base = colour.as_ptr() as usize;
        for with_depth in [false, true] {
            let frame = Frame::new(&mut colour, w, h).unwrap().at_row(7);
            let mut frame = if with_depth {
                frame.with_depth(&mut depth).unwrap()
            } else {
                frame
            };
            for y in [i32::MIN, -1, 0, 6, 7, 8, 9, 10, 11, i32::MAX] {
                let row = frame.row_mut(y).map(|(c, d)| {
                    let at = (c.as_ptr() as usize - base) / 2;
                    (at, c.len(), d.map(|d| d.len()))
                });
                let want = (7..10).contains(&y).then(|| {
                    let r = (y - 7) as usize;
                    (r * 5, 5, with_depth.then_some(5))
                });
                assert_eq!(row, want, "row {y}, depth {with_depth}");
            }
        }
    }

    /// `clear` skips the depth fill only while the depth is as the last fill left it: once
    /// rows are lent (a draw may write them), the next `clear` fills it again.
    #[test]
    fn clear_refills_depth_after_rows_are_lent() {
        let mut colour = [Rgb565::default(); 600];
        let mut depth = [7u16; 600];
        let mut frame = Frame::new(&mut colour, 30, 20)
            .unwrap()
            .with_depth(&mut depth)
            .unwrap();
        frame.clear(Rgb565::new(1, 2, 3));
        assert!(frame.depth().unwrap().iter().all(|&d| d == DEPTH_CLEAR));
        for round in 0..2 {
            if let Some(d) = frame.rows_mut().depth {
                d[5 + round] = 100;
                d[599] = 0;
            }
            frame.clear(Rgb565::new(1, 2, 3));
            assert!(frame.depth().unwrap().iter().all(|&d| d == DEPTH_CLEAR));
            assert!(frame.pixels().iter().all(|&c| c == Rgb565::new(1, 2, 3)));
        }
        // Attached as it is: the first clear fills.
        let mut depth = [7u16; 600];
        let mut colour = [Rgb565::default(); 600];
        let mut frame = Frame::new(&mut colour, 30, 20)
            .unwrap()
            .with_depth_kept(&mut depth)
            .unwrap();
        frame.clear(Rgb565::new(0, 0, 0));
        assert!(frame.depth().unwrap().iter().all(|&d| d == DEPTH_CLEAR));
    }
}
