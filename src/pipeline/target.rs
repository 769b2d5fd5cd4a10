//! What the span writer draws into: a target that lends its rows as one row-major buffer
//! ([`RenderTarget::rows_mut`], [`Rows`]: colour, and depth when the target has a depth
//! buffer) once per triangle; the writer slices each span's row out of it, so the per-pixel
//! loop is a plain slice walk with no call per span or pixel. The targets themselves (frames,
//! bands) are the surface stage's.

use crate::color::TargetColor;

/// One row of a target: its colour pixels and, if the target has one, its depth values.
pub type Row<'r, C> = (&'r mut [C], Option<&'r mut [u16]>);

/// A target's rows as one row-major buffer, lent by [`RenderTarget::rows_mut`]: row `r`
/// (frame row `y0 + r`, `r < height`) is `color[r * stride..][..width]`, and its depth row
/// the same range of `depth`. The span writer slices each span's row itself, with no call.
#[derive(Debug)]
pub struct Rows<'r, C> {
    /// Colour pixels.
    pub color: &'r mut [C],
    /// Depth values laid out as `color`, if the target has a depth buffer.
    pub depth: Option<&'r mut [u16]>,
    /// Pixels per row handed out (at least the target's [`RenderTarget::width`]).
    pub width: usize,
    /// Distance from one row's first pixel to the next row's, in pixels.
    pub stride: usize,
    /// Rows held.
    pub height: usize,
    /// Frame row of the first row.
    pub y0: i32,
}

impl<'r, C> Rows<'r, C> {
    /// Row `y` (frame coordinates); `None` outside `y0..y0 + height`, or where either
    /// slice is too short for it. Never panics.
    #[inline(always)]
    pub fn row(&mut self, y: i32) -> Option<Row<'_, C>> {
        let (start, end) = self.range(y)?;
        let color = self.color.get_mut(start..end)?;
        let depth = match self.depth.as_deref_mut() {
            Some(d) => Some(d.get_mut(start..end)?),
            None => None,
        };
        Some((color, depth))
    }

    /// Pixels `x0..x1` of row `y` (frame coordinates), colour and depth: the span the
    /// writer fills. `None` outside the rows, for columns outside `0..width` or `x0 > x1`,
    /// or where either slice is too short. Never panics.
    ///
    /// It slices the buffers itself rather than sharing a helper with [`row`](Self::row):
    /// written through a shared `cut(a, b)`, the same code costs the Cortex-M4F whole-frame
    /// sphere about 3 % more (code layout in the span writer; measure with
    /// `cargo xtask mcu`).
    #[inline(always)]
    pub fn span(&mut self, y: i32, x0: i32, x1: i32) -> Option<Row<'_, C>> {
        let (start, _) = self.range(y)?;
        let (Ok(a), Ok(b)) = (usize::try_from(x0), usize::try_from(x1)) else {
            return None;
        };
        if b > self.width {
            return None;
        }
        let (a, b) = (start.wrapping_add(a), start.wrapping_add(b));
        let color = self.color.get_mut(a..b)?;
        let depth = match self.depth.as_deref_mut() {
            Some(d) => Some(d.get_mut(a..b)?),
            None => None,
        };
        Some((color, depth))
    }

    /// [`span`](Self::span) for a span the rasterizer clipped to the target (`0 <= x0 < x1
    /// <= width`, `y` one of the rows): only the slicing checks, which keep every access
    /// inside the buffers whatever the arguments.
    #[inline(always)]
    pub(crate) fn span_in_clip(&mut self, y: i32, x0: i32, x1: i32) -> Option<Row<'_, C>> {
        let r = y.wrapping_sub(self.y0) as u32 as usize;
        let a = r.wrapping_mul(self.stride).wrapping_add(x0 as u32 as usize);
        let b = a.wrapping_add(x1.wrapping_sub(x0) as u32 as usize);
        let color = self.color.get_mut(a..b)?;
        let depth = match self.depth.as_deref_mut() {
            Some(d) => Some(d.get_mut(a..b)?),
            None => None,
        };
        Some((color, depth))
    }

    /// [`row`](Self::row), keeping the whole borrow.
    #[inline]
    pub fn into_row(self, y: i32) -> Option<Row<'r, C>> {
        let (start, end) = self.range(y)?;
        let color = self.color.get_mut(start..end)?;
        let depth = match self.depth {
            Some(d) => Some(d.get_mut(start..end)?),
            None => None,
        };
        Some((color, depth))
    }

    #[inline(always)]
    fn range(&self, y: i32) -> Option<(usize, usize)> {
        let r = usize::try_from(y.wrapping_sub(self.y0)).ok()?;
        if r >= self.height {
            return None;
        }
        // Wrapping, not checked (on Cortex-M0+ a checked product is a 64-bit library
        // multiply): a range that wrapped is refused by the slicing.
        let start = r.wrapping_mul(self.stride);
        Some((start, start.wrapping_add(self.width)))
    }
}

/// Something the span writer can fill: rows of colour (and optionally 16-bit depth)
/// pixels in one row-major buffer.
pub trait RenderTarget {
    /// Pixel colour type.
    type Color: TargetColor;
    /// Width in pixels.
    fn width(&self) -> u32;
    /// Frame rows this target holds: `first..end` (a band holds a sub-range).
    fn row_range(&self) -> (i32, i32);
    /// The rows, as one row-major buffer (see [`Rows`]): exactly the rows of
    /// [`row_range`](Self::row_range), each at least [`width`](Self::width) pixels, with
    /// depth rows when [`has_depth`](Self::has_depth). The span writer slices each span's
    /// row out of it itself: no call per span (a call per span cost about 30 instructions on
    /// Cortex-M4F, several per pixel on a finely tessellated mesh).
    fn rows_mut(&mut self) -> Rows<'_, Self::Color>;
    /// Whether [`rows_mut`](Self::rows_mut) hands out depth rows. A depth-testing draw into
    /// a target without depth is refused with [`Error::NoDepthBuffer`](crate::Error).
    fn has_depth(&self) -> bool;

    /// The colour row `y` (frame coordinates) and its depth row, if the target has a depth
    /// buffer. `None` when `y` is outside [`row_range`](Self::row_range).
    #[inline]
    fn row_mut(&mut self, y: i32) -> Option<Row<'_, Self::Color>> {
        self.rows_mut().into_row(y)
    }

    /// A lower bound of every depth value stored in the target (a one-value hierarchical
    /// depth buffer): a span whose depths all lie below it passes the depth test without
    /// reading the buffer. `0`, the default, means unknown and skips nothing; [`Frame`](crate::surface::Frame)
    /// keeps a real bound from its [`Frame::clear`](crate::surface::Frame::clear) on.
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

    /// What one triangle's raster reads of the target, in one call: its
    /// [`width`](Self::width), [`row_range`](Self::row_range) and
    /// [`depth_floor`](Self::depth_floor), and its [`rows_mut`](Self::rows_mut). The
    /// default asks each method in turn; a target drawn through `dyn RenderTarget` (a band)
    /// answers in one call, which saves the span writer three indirect calls per triangle
    /// (about 1 % of the Cortex-M4F sphere in bands; measure with `cargo xtask mcu`).
    #[inline]
    fn lend(&mut self) -> Lent<'_, Self::Color> {
        Lent {
            width: self.width(),
            row_range: self.row_range(),
            depth_floor: self.depth_floor(),
            rows: self.rows_mut(),
        }
    }
}

/// A target as one triangle's raster reads it ([`RenderTarget::lend`]).
#[derive(Debug)]
pub struct Lent<'r, C> {
    /// [`RenderTarget::width`].
    pub width: u32,
    /// [`RenderTarget::row_range`].
    pub row_range: (i32, i32),
    /// [`RenderTarget::depth_floor`].
    pub depth_floor: u16,
    /// [`RenderTarget::rows_mut`].
    pub rows: Rows<'r, C>,
}

#[cfg(test)]
mod tests {
    use super::Rows;

    /// A 3-row target (frame rows 10..13) of width 4 in a stride of 5, pixel `i` holding `i`.
    fn rows<'a>(color: &'a mut [u16; 15], depth: &'a mut [u16; 15]) -> Rows<'a, u16> {
        for (i, (c, d)) in color.iter_mut().zip(depth.iter_mut()).enumerate() {
            (*c, *d) = (i as u16, 100 + i as u16);
        }
        Rows {
            color,
            depth: Some(depth),
            width: 4,
            stride: 5,
            height: 3,
            y0: 10,
        }
    }

    #[test]
    fn span_is_the_rows_pixels_and_refuses_what_lies_outside() {
        let (mut c, mut d) = ([0; 15], [0; 15]);
        let mut r = rows(&mut c, &mut d);
        let (col, dep) = r.span(11, 1, 4).unwrap();
        assert_eq!(col, &[6, 7, 8]);
        assert_eq!(dep.unwrap(), &[106, 107, 108]);
        assert_eq!(r.span(12, 2, 2).unwrap().0, &[] as &[u16]);
        // The span of a whole row is the row.
        let whole = r.span(10, 0, 4).map(|(c, _)| c.to_vec());
        assert_eq!(whole, r.row(10).map(|(c, _)| c.to_vec()));
        // Outside the rows, past the width, negative or reversed columns: refused.
        for (y, x0, x1) in [(9, 0, 1), (13, 0, 1), (11, 0, 5), (11, -1, 2), (11, 3, 2)] {
            assert!(r.span(y, x0, x1).is_none(), "{y} {x0}..{x1}");
        }
        for (y, x0, x1) in [(i32::MIN, 0, 1), (i32::MAX, i32::MIN, i32::MAX)] {
            assert!(r.span(y, x0, x1).is_none());
        }
    }

    /// Inside the clip, `span_in_clip` is `span`; outside it (which the rasterizer never
    /// asks for) it may give other pixels of the buffers but never reaches past them.
    #[test]
    fn span_in_clip_is_span_inside_and_stays_in_the_buffers() {
        let (mut c, mut d) = ([0; 15], [0; 15]);
        let mut r = rows(&mut c, &mut d);
        for y in 10..13 {
            for x0 in 0..4 {
                for x1 in x0 + 1..=4 {
                    let a = r
                        .span(y, x0, x1)
                        .map(|(c, d)| (c.to_vec(), d.map(|d| d.to_vec())));
                    let b = r
                        .span_in_clip(y, x0, x1)
                        .map(|(c, d)| (c.to_vec(), d.map(|d| d.to_vec())));
                    assert_eq!(a, b, "{y} {x0}..{x1}");
                }
            }
        }
        let edges = [i32::MIN, -7, -1, 0, 3, 13, 14, 15, i32::MAX];
        for y in edges.iter().map(|&v| v.wrapping_add(10)) {
            for &x0 in &edges {
                for &x1 in &edges {
                    if let Some((col, dep)) = r.span_in_clip(y, x0, x1) {
                        assert!(col.len() <= 15 && dep.map_or(0, |d| d.len()) == col.len());
                    }
                }
            }
        }
    }

    #[test]
    fn span_refuses_a_depth_slice_too_short() {
        let mut color = [0u16; 15];
        let mut depth = [0u16; 7];
        let mut r = Rows {
            color: &mut color,
            depth: Some(&mut depth),
            width: 4,
            stride: 5,
            height: 3,
            y0: 0,
        };
        assert!(r.span(1, 0, 2).is_some());
        assert!(r.span(1, 0, 3).is_none());
    }
}
