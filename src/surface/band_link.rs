//! The link between a band renderer and the display: [`BandSender`], where finished bands
//! go (blocking, caller-driven DMA, any embedded-graphics `DrawTarget`), and the band buffers
//! a renderer draws into (one, or a ring of two or more so a band is drawn while the one
//! before it is sent). The band loop that drives them is [`overlap`](super::overlap)'s.

use embedded_graphics_core::draw_target::DrawTarget;
use embedded_graphics_core::geometry::{Point, Size};
use embedded_graphics_core::primitives::Rectangle;

use super::{Frame, RenderTarget};
use crate::color::TargetColor;
use crate::Error;

/// Flushes bands to an embedded-graphics [`DrawTarget`] through `fill_contiguous`, so a
/// display driver can stream a whole band in one transaction.
#[derive(Debug)]
pub struct DrawTargetFlush<'d, D>(pub &'d mut D);

impl<D: DrawTarget> DrawTargetFlush<'_, D>
where
    D::Color: TargetColor,
{
    /// Writes `band` at its rows.
    pub fn flush(&mut self, band: &Frame<'_, D::Color>) -> Result<(), D::Error> {
        let area = Rectangle::new(
            Point::new(0, band.first_row()),
            Size::new(band.width(), band.height()),
        );
        self.0.fill_contiguous(&area, band.pixels().iter().copied())
    }
}

/// Where finished bands go: started one at a time, in band order, each finished (waited
/// for) before its buffer is drawn into again. See the [`overlap` module docs](super::overlap) for the
/// contract, which a DMA sender relies on.
pub trait BandSender<C> {
    /// What a failed transfer reports (a bus error, say); it stops the frame.
    type Error;

    /// Starts sending `band` (frame rows `band.first_row()..` of `band.height()` rows,
    /// `band.pixels()` row-major). It may return before the transfer ends: the renderer
    /// leaves the band's buffer alone until [`wait`](Self::wait) returned for it.
    fn start(&mut self, band: &Frame<'_, C>) -> Result<(), Self::Error>;

    /// Returns once the oldest transfer still running has finished with its buffer.
    fn wait(&mut self) -> Result<(), Self::Error>;
}

/// A sender that has sent the band when `start` returns: a closure over the band (a
/// display driver's blocking write, a checksum). The sender of [`BandRenderer::render`](super::BandRenderer::render).
#[derive(Clone, Copy, Debug)]
pub struct Blocking<F>(pub F);

impl<C, E, F: FnMut(&Frame<'_, C>) -> Result<(), E>> BandSender<C> for Blocking<F> {
    type Error = E;

    #[inline]
    fn start(&mut self, band: &Frame<'_, C>) -> Result<(), E> {
        (self.0)(band)
    }

    #[inline(always)]
    fn wait(&mut self) -> Result<(), E> {
        Ok(())
    }
}

/// A sender driven by the caller's DMA: `start` begins a transfer of the band's pixels
/// (and returns at once), `wait` returns when the oldest transfer running has finished.
/// The renderer keeps to the contract of the [`overlap` module docs](super::overlap), which is what makes it
/// sound to hand `band.pixels().as_ptr()` to a DMA channel in `start`.
#[derive(Clone, Copy, Debug)]
pub struct Dma<S, W> {
    start: S,
    wait: W,
}

impl<S, W> Dma<S, W> {
    /// A sender of these two closures.
    pub fn new(start: S, wait: W) -> Self {
        Dma { start, wait }
    }
}

impl<C, E, S, W> BandSender<C> for Dma<S, W>
where
    S: FnMut(&Frame<'_, C>) -> Result<(), E>,
    W: FnMut() -> Result<(), E>,
{
    type Error = E;

    #[inline]
    fn start(&mut self, band: &Frame<'_, C>) -> Result<(), E> {
        (self.start)(band)
    }

    #[inline]
    fn wait(&mut self) -> Result<(), E> {
        (self.wait)()
    }
}

/// A blocking write of each band to an embedded-graphics `DrawTarget`
/// (`fill_contiguous` of the band's rectangle).
impl<D: DrawTarget> BandSender<D::Color> for DrawTargetFlush<'_, D>
where
    D::Color: TargetColor,
{
    type Error = D::Error;

    fn start(&mut self, band: &Frame<'_, D::Color>) -> Result<(), D::Error> {
        self.flush(band)
    }

    fn wait(&mut self) -> Result<(), D::Error> {
        Ok(())
    }
}

/// A band renderer's colour storage: one buffer (drawn, sent, drawn again) or a ring of
/// two or more of the same length (band `k` drawn into buffer `k mod n`).
#[derive(Debug)]
pub(super) enum BandBuffers<'b, C> {
    One(&'b mut [C]),
    Ring(&'b mut [&'b mut [C]]),
}

impl<C> BandBuffers<'_, C> {
    /// How many buffers there are (bands that may be in flight plus the one drawn).
    pub(super) fn count(&self) -> usize {
        match self {
            BandBuffers::One(_) => 1,
            BandBuffers::Ring(r) => r.len(),
        }
    }

    /// Buffer `i` (`None` past the last).
    #[inline]
    pub(super) fn get(&mut self, i: usize) -> Option<&mut [C]> {
        match self {
            BandBuffers::One(b) => (i == 0).then_some(&mut **b),
            BandBuffers::Ring(r) => r.get_mut(i).map(|b| &mut **b),
        }
    }
}

/// Checks a ring of band buffers: at least two, all of one length.
pub(super) fn check_ring<C>(buffers: &[&mut [C]]) -> Result<(), Error> {
    let Some(first) = buffers.first() else {
        return Err(Error::TooFewBandBuffers { given: 0 });
    };
    if buffers.len() < 2 {
        return Err(Error::TooFewBandBuffers {
            given: buffers.len(),
        });
    }
    match buffers.iter().position(|b| b.len() != first.len()) {
        Some(index) => Err(Error::BandBuffersDiffer {
            index,
            len: buffers[index].len(),
            first: first.len(),
        }),
        None => Ok(()),
    }
}
