//! Band rendering: a frame drawn as horizontal bands through one small colour (+ depth)
//! buffer, for parts whose RAM cannot hold a whole frame (320 x 240 RGB565 is 150 KiB).
//!
//! Triangles are clipped, projected and *binned once* per frame: [`BandRenderer::render`]
//! runs the scene's geometry a single time, storing each screen triangle with the index of
//! its draw and its row range in caller-provided storage; then each band draws only the
//! binned triangles that overlap it and flushes. The per-triangle raster set-up is redone in
//! each band a triangle touches (a few `i64` divisions), the geometry is not.
//!
//! A frame is any number of draws of any shader types ([`BandDraw`]: the classic
//! [`Draw`](crate::pipeline::Draw) and every [`ShadedDraw`](crate::pipeline::ShadedDraw)),
//! each with its own projection and depth stage, in one list; each binned triangle keeps
//! the varyings of its draw ([`AnyTriangle`](super::AnyTriangle), 168 bytes a bin).
//!
//! When the bin storage is too small for the frame, the renderer falls back to running the
//! geometry once per band (same pixels, more time) and says so in [`BandStats::rewalked`];
//! [`BandRenderer::render_spans`] keeps a 2-byte band range per triangle instead.
//!
//! A band is a [`Frame`] that holds rows `y0..y0 + rows`, and the raster set-up depends only
//! on the viewport, never on the band, so a frame drawn in bands is bit-identical to the
//! frame drawn whole (tested).

use super::band_draw::{AnyTriangle, BandDraw, Binnable};
use super::band_link::{check_ring, BandBuffers, BandSender, Blocking};
use super::{Frame, RenderTarget};
use crate::color::TargetColor;
use crate::geometry::ScreenTriangle;
use crate::pipeline::KeptSetup;
use crate::raster::triangle::first_row_at_or_below;
use crate::Error;

/// One binned triangle: screen vertices with its draw's varyings, the draw it belongs to,
/// and its pixel rows. 168 bytes on 32-bit targets (a triangle of 8 varyings).
#[derive(Clone, Copy, Debug, Default)]
pub struct Binned {
    pub(super) tri: AnyTriangle,
    pub(super) draw: u8,
    pub(super) rows: (i16, i16),
}

/// A pixel row as the bins store it (saturated to `i16`).
fn clamp_row(r: i32) -> i16 {
    r.clamp(i16::MIN.into(), i16::MAX.into()) as i16
}

impl Binned {
    /// An empty bin (the same as `Binned::default()`, usable in constants).
    pub const EMPTY: Binned = Binned {
        tri: AnyTriangle::EMPTY,
        draw: 0,
        rows: (0, 0),
    };

    /// Stores `tri` of draw `draw`, with its conservative pixel-row range, in place.
    #[inline]
    pub(super) fn store<const N: usize>(&mut self, draw: u8, tri: &ScreenTriangle<N>)
    where
        ScreenTriangle<N>: Binnable,
    {
        let (r0, r1) = rows_of(tri);
        self.tri = tri.to_any();
        self.draw = draw;
        self.rows = (clamp_row(r0), clamp_row(r1));
    }

    /// Whether the triangle may cover a row of `first..=last`.
    pub(super) fn meets(&self, first: i32, last: i32) -> bool {
        i32::from(self.rows.1) >= first && i32::from(self.rows.0) <= last
    }
}

/// Pixel rows of a screen triangle: the rasterizer draws rows `r0..r1` (`r1` excluded), the
/// first rows whose centres are at or below its top and its bottom.
pub(super) fn rows_of<const N: usize>(tri: &ScreenTriangle<N>) -> (i32, i32) {
    let top = tri[0].y.min(tri[1].y).min(tri[2].y);
    let bot = tri[0].y.max(tri[1].y).max(tri[2].y);
    (first_row_at_or_below(top), first_row_at_or_below(bot))
}

/// What a frame cost, for reports.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct BandStats {
    /// Bands drawn.
    pub bands: u32,
    /// Screen triangles binned (after clipping and culling).
    pub triangles: u32,
    /// True when the storage overflowed and (some of) the geometry ran in every band: with
    /// [`BandRenderer::render`], the bins were full; with [`BandRenderer::render_spans`],
    /// triangles past the end of the band-range storage.
    pub rewalked: bool,
    /// True when [`BandRenderer::render_spans`] could not keep the screen triangles in the
    /// bins and re-projected each triangle in the bands its stored range covers.
    pub reprojected: bool,
    /// Pixels written (with a depth test: that passed it), saturating at `u32::MAX` (a
    /// frame that writes more than 2^32 pixels, such as a thousand full-screen layers at
    /// 2048 x 2048, reports `u32::MAX`).
    pub pixels: u32,
}

/// Why a banded frame was not drawn: bad input (found before the first band is drawn), or
/// the error of a band's flush (which stops the frame).
///
/// With a flush that cannot fail (`E = Infallible`), `?` turns it into a plain [`Error`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum BandError<E> {
    /// The draws, the storage or the triangles pushed do not fit the renderer.
    Input(Error),
    /// `flush` failed (a display's bus error, say).
    Flush(E),
}

impl<E> From<Error> for BandError<E> {
    fn from(e: Error) -> Self {
        BandError::Input(e)
    }
}

impl From<BandError<core::convert::Infallible>> for Error {
    fn from(e: BandError<core::convert::Infallible>) -> Self {
        match e {
            BandError::Input(e) => e,
            BandError::Flush(never) => match never {},
        }
    }
}

impl<E: core::fmt::Display> core::fmt::Display for BandError<E> {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self {
            BandError::Input(e) => write!(f, "{e}"),
            BandError::Flush(e) => write!(f, "flushing a band failed: {e}"),
        }
    }
}

impl<E: core::fmt::Debug + core::fmt::Display> core::error::Error for BandError<E> {}

/// The binning pass's check of the triangles pushed: the first problem, kept for the error
/// returned before any band is drawn, and the last (draw, varying count) pair found right,
/// which most pushes repeat (one comparison instead of a call through the draw).
#[derive(Debug)]
pub(super) struct PushCheck {
    bad: Option<Error>,
    ok: u32,
}

impl PushCheck {
    /// Nothing checked yet.
    pub(super) const NEW: PushCheck = PushCheck {
        bad: None,
        ok: u32::MAX,
    };

    /// Checks a triangle of `varyings` varyings pushed for draw `draw`.
    #[inline(always)]
    pub(super) fn check<C: TargetColor>(
        &mut self,
        draws: &[&dyn BandDraw<C>],
        draw: u8,
        varyings: usize,
    ) {
        let key = (u32::from(draw) << 8) | (varyings as u32 & 0xFF);
        if key != self.ok {
            self.check_draw(draws, draw, varyings, key);
        }
    }

    #[inline(never)]
    fn check_draw<C: TargetColor>(
        &mut self,
        draws: &[&dyn BandDraw<C>],
        draw: u8,
        varyings: usize,
        key: u32,
    ) {
        if self.bad.is_some() {
            return;
        }
        match draws.get(usize::from(draw)) {
            None => {
                self.bad = Some(Error::BadDrawIndex {
                    index: draw,
                    draws: draws.len(),
                })
            }
            Some(d) if d.varyings() != varyings => {
                self.bad = Some(Error::WrongVaryings {
                    draw,
                    expected: d.varyings() as u8,
                    actual: varyings as u8,
                })
            }
            Some(_) => self.ok = key,
        }
    }

    /// The first problem found.
    pub(super) fn error(&self) -> Option<Error> {
        self.bad
    }
}

/// Receives screen triangles from the scene's geometry pass.
pub struct TriangleSink<'s, 'f, 'd, C: TargetColor> {
    mode: SinkMode<'s, 'f, 'd, C>,
}

impl<C: TargetColor> core::fmt::Debug for TriangleSink<'_, '_, '_, C> {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.write_str(match self.mode {
            SinkMode::Bin { .. } => "TriangleSink(binning)",
            SinkMode::Immediate { .. } => "TriangleSink(band)",
        })
    }
}

enum SinkMode<'s, 'f, 'd, C: TargetColor> {
    Bin {
        bins: &'s mut [Binned],
        len: usize,
        overflow: bool,
        draws: &'s [&'d dyn BandDraw<C>],
        check: PushCheck,
    },
    Immediate {
        draws: &'s [&'d dyn BandDraw<C>],
        band: &'s mut Frame<'f, C>,
        pixels: u32,
    },
}

impl<'s, 'd, C: TargetColor> TriangleSink<'s, '_, 'd, C> {
    /// A sink that bins into `bins` (for `draws`).
    pub(super) fn binning(bins: &'s mut [Binned], draws: &'s [&'d dyn BandDraw<C>]) -> Self {
        TriangleSink {
            mode: SinkMode::Bin {
                bins,
                len: 0,
                overflow: false,
                draws,
                check: PushCheck::NEW,
            },
        }
    }

    /// The bins after a binning pass: `(bins, len, overflow)`, or the first bad push.
    pub(super) fn into_bins(self) -> Result<(&'s mut [Binned], usize, bool), Error> {
        match self.mode {
            SinkMode::Bin {
                bins,
                len,
                overflow,
                check,
                ..
            } => match check.error() {
                Some(e) => Err(e),
                None => Ok((bins, len, overflow)),
            },
            SinkMode::Immediate { .. } => Ok((&mut [], 0, true)),
        }
    }

    /// True in the binning pass, which starts a frame (the geometry runs again, in each
    /// band, only when the bins overflowed).
    #[inline]
    pub fn fresh(&self) -> bool {
        matches!(self.mode, SinkMode::Bin { .. })
    }

    /// Hands over one screen triangle of draw number `draw` (an index into the draws given
    /// to [`BandRenderer::render`]), carrying that draw's varyings. An index past the draws
    /// makes `render` return [`Error::BadDrawIndex`], a triangle whose varying count is not
    /// its draw's [`Error::WrongVaryings`], both before anything is drawn.
    pub fn push<const N: usize>(&mut self, draw: u8, tri: &ScreenTriangle<N>)
    where
        ScreenTriangle<N>: Binnable,
    {
        match &mut self.mode {
            SinkMode::Bin {
                bins,
                len,
                overflow,
                draws,
                check,
            } => {
                check.check(draws, draw, N);
                if let Some(slot) = bins.get_mut(*len) {
                    slot.store(draw, tri);
                    *len += 1;
                } else {
                    *overflow = true;
                }
            }
            SinkMode::Immediate {
                draws,
                band,
                pixels,
            } => {
                if let Some(d) = draws.get(usize::from(draw)) {
                    *pixels = pixels.saturating_add(d.draw_piece(tri.as_any(), *band, None));
                }
            }
        }
    }
}

/// Checks a frame of `width` x `height` in bands of `rows` through buffers of `len`
/// pixels; the band height (at most the frame's).
fn check_band(len: usize, width: u32, rows: u32, height: u32) -> Result<u32, Error> {
    if width == 0 || width > 4096 || height == 0 || height > 4096 {
        return Err(Error::BadSize(if width == 0 || width > 4096 {
            width
        } else {
            height
        }));
    }
    let capacity = len / width as usize;
    if rows == 0 || rows as usize > capacity {
        return Err(Error::BandTooTall {
            rows: rows.min(u32::from(u16::MAX)) as u16,
            capacity: capacity.min(usize::from(u16::MAX)) as u16,
        });
    }
    Ok(rows.min(height))
}

/// Draws frames band by band through a small buffer.
#[derive(Debug)]
pub struct BandRenderer<'b, C> {
    pub(super) color: BandBuffers<'b, C>,
    pub(super) depth: Option<&'b mut [u16]>,
    pub(super) width: u32,
    pub(super) rows: u32,
    pub(super) height: u32,
    /// Set-ups kept from one band for the next ([`BandRenderer::with_setup_cache`]).
    pub(super) setups: &'b mut [KeptSetup],
}

impl<'b, C: TargetColor> BandRenderer<'b, C> {
    /// Bands of `rows` rows of a `width` x `height` frame, through `color` (at least
    /// `width * rows` long).
    ///
    /// ```
    /// use fixel::surface::BandRenderer;
    /// use fixel::Rgb565;
    /// let mut buf = [Rgb565::default(); 320 * 16];
    /// assert!(BandRenderer::new(&mut buf, 320, 16, 240).is_ok());
    /// let mut buf = [Rgb565::default(); 320 * 16];
    /// assert!(BandRenderer::new(&mut buf, 320, 17, 240).is_err()); // band taller than buffer
    /// ```
    pub fn new(color: &'b mut [C], width: u32, rows: u32, height: u32) -> Result<Self, Error> {
        let rows = check_band(color.len(), width, rows, height)?;
        Ok(BandRenderer {
            color: BandBuffers::One(color),
            depth: None,
            width,
            rows,
            height,
            setups: &mut [],
        })
    }

    /// Bands of `rows` rows of a `width` x `height` frame drawn in turn into the buffers of
    /// `buffers` (band `k` into buffer `k mod n`), each at least `width * rows` long: with a
    /// sender that returns before the band is sent ([`render_to`](Self::render_to) and
    /// [`Dma`](super::Dma)), band `k` is sent while band `k + 1` is drawn. The pixels
    /// are those of [`new`](Self::new) (tested).
    ///
    /// Refused: fewer than two buffers ([`Error::TooFewBandBuffers`]), buffers of different
    /// lengths ([`Error::BandBuffersDiffer`]), and what [`new`](Self::new) refuses.
    ///
    /// ```
    /// use fixel::surface::BandRenderer;
    /// use fixel::{Error, Rgb565};
    /// let (mut a, mut b) = ([Rgb565::default(); 320 * 8], [Rgb565::default(); 320 * 8]);
    /// let mut two = [&mut a[..], &mut b[..]];
    /// assert!(BandRenderer::with_buffers(&mut two, 320, 8, 240).is_ok());
    /// let mut one = [&mut a[..]];
    /// let e = BandRenderer::with_buffers(&mut one, 320, 8, 240).unwrap_err();
    /// assert_eq!(e, Error::TooFewBandBuffers { given: 1 });
    /// let mut odd = [&mut a[..], &mut b[..320 * 4]];
    /// let e = BandRenderer::with_buffers(&mut odd, 320, 4, 240).unwrap_err();
    /// assert_eq!(e, Error::BandBuffersDiffer { index: 1, len: 320 * 4, first: 320 * 8 });
    /// ```
    pub fn with_buffers(
        buffers: &'b mut [&'b mut [C]],
        width: u32,
        rows: u32,
        height: u32,
    ) -> Result<Self, Error> {
        check_ring(buffers)?;
        let rows = check_band(buffers[0].len(), width, rows, height)?;
        Ok(BandRenderer {
            color: BandBuffers::Ring(buffers),
            depth: None,
            width,
            rows,
            height,
            setups: &mut [],
        })
    }

    /// Adds a depth band (at least `width * rows` long).
    pub fn with_depth(mut self, depth: &'b mut [u16]) -> Result<Self, Error> {
        let need = self.width as usize * self.rows as usize;
        if depth.len() < need {
            return Err(Error::WrongLength {
                expected: need,
                actual: depth.len(),
            });
        }
        self.depth = Some(depth);
        Ok(self)
    }

    /// Adds room for raster set-ups kept from one band for the next
    /// ([`render_spans`](Self::render_spans), from its bins or re-projecting a mesh per
    /// band). A triangle that crosses a band boundary is drawn in both bands; with this, the
    /// second band takes the set-up the first one built instead of building it again (about 2,900
    /// instructions on Cortex-M0+, 830 on Cortex-M4F). When re-projecting a mesh, an entry
    /// also keeps the rest of the triangle's raster (its corners, the shader's
    /// [`pack_triangle`](crate::shading::Shader::pack_triangle)ed data, its range proof), and
    /// the next band draws the triangle from it without projecting it again. Each entry
    /// holds one triangle (100 bytes, shaders of up to
    /// [`KEPT_VARYINGS`](crate::pipeline::KEPT_VARYINGS) varyings); the first
    /// `setups.len()` triangles crossing each boundary are kept. The pixels are the same
    /// with any length, empty included (the default).
    ///
    /// ```
    /// use fixel::pipeline::KeptSetup;
    /// use fixel::surface::BandRenderer;
    /// use fixel::Rgb565;
    /// let mut buf = [Rgb565::default(); 320 * 8];
    /// let mut setups = [KeptSetup::EMPTY; 24];
    /// let bands = BandRenderer::new(&mut buf, 320, 8, 240)?.with_setup_cache(&mut setups);
    /// # let _ = bands;
    /// # Ok::<(), fixel::Error>(())
    /// ```
    pub fn with_setup_cache(mut self, setups: &'b mut [KeptSetup]) -> Self {
        self.setups = setups;
        self
    }

    /// Refuses draws that test depth when the bands have no depth buffer.
    pub(super) fn check_draws(&self, draws: &[&dyn BandDraw<C>]) -> Result<(), Error> {
        if draws.len() > usize::from(u8::MAX) + 1 {
            return Err(Error::CapacityExceeded { capacity: 256 });
        }
        let tests_depth = draws.iter().any(|d| d.tests_depth());
        if tests_depth && self.depth.is_none() {
            return Err(Error::NoDepthBuffer);
        }
        Ok(())
    }

    /// Draws one frame. `geometry` is called with a [`TriangleSink`] and must push every
    /// screen triangle of the frame (usually via [`Draw::project`](crate::pipeline::Draw::project)
    /// or [`ShadedDraw::project`](crate::pipeline::ShadedDraw::project)), tagged with the
    /// index of its draw in `draws`; the draws may be of any shader types. Each band is
    /// cleared to `clear`, drawn and passed to `flush`; the first flush error stops the frame
    /// and is returned as [`BandError::Flush`].
    ///
    /// When the frame's screen triangles do not fit `bins`, the geometry runs again in
    /// every band (the same pixels, the geometry's time once per band) and
    /// [`BandStats::rewalked`] says so: size `bins` from [`BandStats::triangles`], or use
    /// [`render_spans`](Self::render_spans) for meshes too large to bin.
    ///
    /// Refused before any band is drawn, as [`BandError::Input`]: a draw that tests depth
    /// when the renderer has no depth band ([`Error::NoDepthBuffer`]), more than 256 draws
    /// ([`Error::CapacityExceeded`]), a triangle pushed with a draw index past `draws`
    /// ([`Error::BadDrawIndex`]) or with a varying count other than its draw's
    /// ([`Error::WrongVaryings`]).
    pub fn render<E>(
        &mut self,
        draws: &[&dyn BandDraw<C>],
        bins: &mut [Binned],
        clear: C,
        geometry: impl FnMut(&mut TriangleSink<'_, '_, '_, C>),
        flush: impl FnMut(&Frame<'_, C>) -> Result<(), E>,
    ) -> Result<BandStats, BandError<E>> {
        self.render_to(draws, bins, clear, geometry, &mut Blocking(flush))
    }

    /// [`render`](Self::render) through a [`BandSender`]: each band is started on `sender`
    /// once drawn; with a ring of buffers ([`with_buffers`](Self::with_buffers)) and a
    /// sender that returns before the band is sent (a DMA channel, [`Dma`](super::Dma)),
    /// the next band is drawn meanwhile. The same bands in the same order with the same
    /// pixels as `render`; the first error of the sender stops the frame
    /// ([`BandError::Flush`]) once the transfers started have been waited for.
    pub fn render_to<S: BandSender<C>>(
        &mut self,
        draws: &[&dyn BandDraw<C>],
        bins: &mut [Binned],
        clear: C,
        mut geometry: impl FnMut(&mut TriangleSink<'_, '_, '_, C>),
        sender: &mut S,
    ) -> Result<BandStats, BandError<S::Error>> {
        self.check_draws(draws)?;
        let (bins, len, overflow) = Self::bin(draws, bins, &mut geometry)?;
        let mut stats = BandStats {
            rewalked: overflow,
            triangles: len as u32,
            ..BandStats::default()
        };
        let bins: &[Binned] = &bins[..len];
        self.each_band(&mut stats, clear, sender, |band, _| {
            Self::draw_binned(draws, bins, overflow, &mut geometry, band)
        })
        .map_err(BandError::Flush)?;
        Ok(stats)
    }

    /// The binning pass of [`render`](Self::render): the geometry's screen triangles into
    /// `bins`; `(bins, triangles binned, overflowed)`, or the first bad push.
    pub(super) fn bin<'s>(
        draws: &'s [&'s dyn BandDraw<C>],
        bins: &'s mut [Binned],
        geometry: &mut impl FnMut(&mut TriangleSink<'_, '_, '_, C>),
    ) -> Result<(&'s mut [Binned], usize, bool), Error> {
        let mut sink = TriangleSink::binning(bins, draws);
        geometry(&mut sink);
        sink.into_bins()
    }

    /// One band of [`render`](Self::render): the binned triangles that meet it or, when
    /// the bins overflowed, the whole geometry again; the pixels written.
    pub(super) fn draw_binned(
        draws: &[&dyn BandDraw<C>],
        bins: &[Binned],
        overflow: bool,
        geometry: &mut impl FnMut(&mut TriangleSink<'_, '_, '_, C>),
        band: &mut Frame<'_, C>,
    ) -> u32 {
        if overflow {
            let mut s = TriangleSink {
                mode: SinkMode::Immediate {
                    draws,
                    band,
                    pixels: 0,
                },
            };
            geometry(&mut s);
            match s.mode {
                SinkMode::Immediate { pixels, .. } => pixels,
                SinkMode::Bin { .. } => 0,
            }
        } else {
            let (r0, r1) = band.row_range();
            let mut pixels = 0;
            for b in bins.iter() {
                if !b.meets(r0, r1) {
                    continue;
                }
                if let Some(d) = draws.get(usize::from(b.draw)) {
                    pixels = u32::saturating_add(pixels, d.draw_piece(b.tri.as_ref(), band, None));
                }
            }
            pixels
        }
    }
}
