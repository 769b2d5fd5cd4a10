//! The `async` frame (no feature needed; the `embedded-hal-async` feature adds `SpiSender`): band `k` is sent by an
//! [`AsyncBandSender`] (an async SPI bus with DMA under an executor, say) while band
//! `k + 1` is drawn; the frame awaits band `k`'s transfer only when it needs the buffer
//! back. Every draw of the band path has this form: [`BandRenderer::render_async`],
//! [`BandRenderer::render_spans_async`] and [`BandRenderer::render_accumulated_async`].
//!
//! The sender's future for band `k` is polled once (which starts the transfer), band
//! `k + 1` is drawn into the other buffer of the ring, then the future is awaited. The
//! bands, their order and their pixels are those of [`BandRenderer::render`] (tested). A
//! frame future dropped before it ends drops the pending transfer's future: the sender (the
//! HAL's DMA future) must stop its transfer when dropped, as `embedded-hal-async` buses do.
//!
//! ```
//! use core::future::Future;
//! use core::pin::pin;
//! use core::task::{Context, Poll, Waker};
//! use fixel::prelude::*;
//! use fixel::geometry::Vertex;
//! use fixel::pipeline::{Exact, NoDepth, ShadedDraw};
//! use fixel::shading::Flat;
//! use fixel::surface::{AsyncBandSender, BandDraw, Binned};
//! use fixel::Rgb565;
//!
//! /// Counts the pixels sent (a real sender awaits an async SPI write).
//! struct Count(usize);
//! impl AsyncBandSender<Rgb565> for Count {
//!     type Error = core::convert::Infallible;
//!     async fn send(&mut self, band: &Frame<'_, Rgb565>) -> Result<(), Self::Error> {
//!         self.0 += band.pixels().len();
//!         Ok(())
//!     }
//! }
//!
//! let vp = Viewport::new(0, 0, 16, 16)?;
//! let draw = ShadedDraw::<_, Exact, NoDepth>::new(Flat(0xF800), vp, Cull::None)?;
//! let p = |x: f32, y: f32| [fixel::math::fx(x), fixel::math::fx(y), Fx::ZERO, Fx::ONE];
//! let tri = [Vertex::new(p(-0.9, -0.9), []), Vertex::new(p(0.9, -0.9), []), Vertex::new(p(0.0, 0.9), [])];
//! let (mut a, mut b) = ([Rgb565::default(); 16 * 4], [Rgb565::default(); 16 * 4]);
//! let mut buffers = [&mut a[..], &mut b[..]];
//! let mut bands = BandRenderer::with_buffers(&mut buffers, 16, 4, 16)?;
//! let draws: [&dyn BandDraw<Rgb565>; 1] = [&draw];
//! let mut bins = [Binned::default(); 2];
//! let mut sender = Count(0);
//! let frame = bands.render_async(&draws, &mut bins, Rgb565::default(), |sink| {
//!     draw.project(&tri, &mut |s| sink.push(0, s));
//! }, &mut sender);
//! // Any executor runs it; this sender never waits, so one poll finishes the frame.
//! let Poll::Ready(stats) = pin!(frame).poll(&mut Context::from_waker(Waker::noop())) else {
//!     unreachable!()
//! };
//! assert_eq!(stats?.bands, 4);
//! assert_eq!(sender.0, 16 * 16);
//! # Ok::<(), fixel::Error>(())
//! ```

use core::future::{poll_fn, Future};
use core::pin::pin;
use core::task::Poll;

use super::band::{BandError, BandRenderer, BandStats, Binned, TriangleSink};
use super::band_draw::BandDraw;
use super::band_link::BandBuffers;
use super::Frame;
use crate::color::TargetColor;

/// Where the bands of an `async` frame go: one at a time, in band order.
pub trait AsyncBandSender<C> {
    /// What a failed transfer reports; it stops the frame.
    type Error;

    /// Sends `band` (frame rows `band.first_row()..`, `band.pixels()` row-major); the
    /// future ends when the transfer has finished with the band's pixels. Its first poll
    /// should start the transfer (the frame polls it once, draws the next band, then
    /// awaits it).
    fn send(&mut self, band: &Frame<'_, C>) -> impl Future<Output = Result<(), Self::Error>>;
}

impl<C: TargetColor> BandRenderer<'_, C> {
    /// [`render`](Self::render) as an `async` frame: each band is sent through `sender`
    /// while the next is drawn (with a ring of buffers, [`with_buffers`](Self::with_buffers);
    /// with one buffer each transfer is awaited before the next band is drawn). The same
    /// bands in the same order with the same pixels as `render`; input errors are refused
    /// before any band is drawn, and the first error of the sender stops the frame.
    pub async fn render_async<S: AsyncBandSender<C>>(
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
        self.each_band_async(&mut stats, clear, sender, |band, _| {
            Self::draw_binned(draws, bins, overflow, &mut geometry, band)
        })
        .await
        .map_err(BandError::Flush)?;
        Ok(stats)
    }

    /// [`each_band`](Self::each_band) for an [`AsyncBandSender`]: two buffers of the ring
    /// in turn, the band in one sent while the next is drawn into the other.
    pub(super) async fn each_band_async<S: AsyncBandSender<C>>(
        &mut self,
        stats: &mut BandStats,
        clear: C,
        sender: &mut S,
        mut draw_band: impl FnMut(&mut Frame<'_, C>, u32) -> u32,
    ) -> Result<(), S::Error> {
        let (width, rows_max, height) = (self.width, self.rows, self.height);
        let need = width as usize * rows_max as usize;
        let mut depth = self.depth.as_deref_mut();
        let (mut cur, mut spare): (&mut [C], Option<&mut [C]>) = match &mut self.color {
            BandBuffers::One(b) => (&mut **b, None),
            BandBuffers::Ring(r) => match &mut **r {
                [a, b, ..] => (&mut **a, Some(&mut **b)),
                [a] => (&mut **a, None),
                [] => return Ok(()),
            },
        };
        // The band held by `spare`, still to be sent: (first row, rows).
        let mut pending: Option<(u32, u32)> = None;
        let mut y0 = 0;
        let mut index = 0;
        while y0 < height {
            let rows = rows_max.min(height - y0);
            let n = width as usize * rows as usize;
            // Draws band `index` into `cur` (the renderer's band: clear, draw).
            let mut draw = |color: &mut [C], depth: Option<&mut [u16]>| -> Option<u32> {
                let band = Frame::new(color.get_mut(..n.min(need))?, width, rows).ok()?;
                let band = match depth {
                    Some(d) => band.with_depth_as_is(d.get_mut(..n.min(need))?).ok()?,
                    None => band,
                };
                let mut band = band.at_row(y0);
                band.clear(clear);
                Some(draw_band(&mut band, index))
            };
            let drawn = match (pending.take(), spare.as_deref_mut()) {
                (Some((py0, prows)), Some(sp)) => {
                    let pn = width as usize * prows as usize;
                    let Some(Ok(sent)) = sp.get_mut(..pn).map(|s| Frame::new(s, width, prows))
                    else {
                        break;
                    };
                    let sent = sent.at_row(py0);
                    let mut transfer = pin!(sender.send(&sent));
                    let first = poll_fn(|cx| Poll::Ready(transfer.as_mut().poll(cx))).await;
                    let drawn = draw(cur, depth.as_deref_mut());
                    match first {
                        Poll::Ready(r) => r?,
                        Poll::Pending => transfer.await?,
                    }
                    drawn
                }
                _ => draw(cur, depth.as_deref_mut()),
            };
            let Some(pixels) = drawn else {
                break;
            };
            stats.pixels = stats.pixels.saturating_add(pixels);
            match spare.take() {
                Some(sp) => {
                    // The band just drawn waits in `spare`, sent while the next is drawn.
                    spare = Some(core::mem::replace(&mut cur, sp));
                    pending = Some((y0, rows));
                }
                None => {
                    let Ok(band) = Frame::new(&mut cur[..n.min(need)], width, rows) else {
                        break;
                    };
                    sender.send(&band.at_row(y0)).await?;
                }
            }
            stats.bands += 1;
            index += 1;
            y0 += rows;
        }
        if let (Some((py0, prows)), Some(sp)) = (pending, spare) {
            let pn = width as usize * prows as usize;
            if let Some(Ok(sent)) = sp.get_mut(..pn).map(|s| Frame::new(s, width, prows)) {
                sender.send(&sent.at_row(py0)).await?;
            }
        }
        Ok(())
    }
}
