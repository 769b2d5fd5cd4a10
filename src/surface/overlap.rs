//! Sending a band while the next one is drawn: two or more band buffers, given by the
//! caller, and a [`BandSender`] that may still be sending band `k` when band `k + 1` is
//! drawn into another buffer.
//!
//! A frame on a display is band work plus link time: a 320 x 240 RGB565 frame is 153,600
//! bytes, 19.7 ms over SPI at 62.5 MHz. Drawn and sent one after the other the two add up;
//! with a DMA channel (or an async SPI bus) sending band `k` while the processor draws band
//! `k + 1`, the frame takes about the larger of the two. The renderer draws the bands in the
//! same order with the same pixels whatever the sender (tested bit for bit); only the buffer
//! a band is drawn into changes, in turn through the ring given to
//! [`BandRenderer::with_buffers`].
//!
//! The contract a sender is given: after [`start`](BandSender::start) of a band, the
//! renderer neither writes to that band's buffer nor hands the buffers back to the caller
//! (returns from the frame) until a [`wait`](BandSender::wait) has returned for it;
//! transfers end in the order they started (each `wait` is for the oldest one still
//! running). A frame that stops on an error still waits for every transfer it started.
//!
//! Senders:
//! * [`Blocking`]: a closure that sends the band before it returns (the plain
//!   [`BandRenderer::render`] flush; also [`DrawTargetFlush`](super::DrawTargetFlush) for any embedded-graphics
//!   `DrawTarget`, and `SpiSender` for an `embedded-hal` 1.0
//!   `SpiDevice`, feature `embedded-hal`);
//! * [`Dma`]: a pair of closures, `start` (point a DMA channel at the band's pixels and
//!   start it) and `wait` (until the oldest transfer has finished);
//! * [`AsyncBandSender`](super::AsyncBandSender) and
//!   [`BandRenderer::render_async`]: an `async` frame that awaits the previous band's
//!   transfer only when it needs that buffer back (`SpiSender` over an
//!   `embedded-hal-async` 1.0 `SpiDevice`, feature `embedded-hal-async`).
//!
//! ```
//! use fixel::prelude::*;
//! use fixel::geometry::Vertex;
//! use fixel::pipeline::{Exact, NoDepth, ShadedDraw};
//! use fixel::shading::Gouraud;
//! use fixel::surface::{BandDraw, Binned, Dma};
//! use fixel::Rgb565;
//!
//! let vp = Viewport::new(0, 0, 32, 32)?;
//! let draw = ShadedDraw::<_, Exact, NoDepth>::new(Gouraud, vp, Cull::None)?;
//! let one = 256 << 16;
//! let p = |x: f32, y: f32| [fixel::math::fx(x), fixel::math::fx(y), Fx::ZERO, Fx::ONE];
//! let tri = [
//!     Vertex::new(p(-0.9, -0.9), [one, 0, 0]),
//!     Vertex::new(p(0.9, -0.9), [0, one, 0]),
//!     Vertex::new(p(0.0, 0.9), [0, 0, one]),
//! ];
//! // Two band buffers of 32 x 8 pixels: one is sent while the other is drawn.
//! let (mut a, mut b) = ([Rgb565::default(); 32 * 8], [Rgb565::default(); 32 * 8]);
//! let mut buffers = [&mut a[..], &mut b[..]];
//! let mut bands = BandRenderer::with_buffers(&mut buffers, 32, 8, 32)?;
//! // A stand-in for a DMA channel: `start` would point it at the band and return at once,
//! // `wait` would spin until the oldest transfer is done.
//! let (mut started, mut waited) = (0, 0);
//! let mut dma = Dma::new(
//!     |band: &Frame<'_, Rgb565>| {
//!         started += band.pixels().len();
//!         Ok::<(), core::convert::Infallible>(())
//!     },
//!     || {
//!         waited += 1;
//!         Ok(())
//!     },
//! );
//! let mut bins = [Binned::default(); 4];
//! let draws: [&dyn BandDraw<Rgb565>; 1] = [&draw];
//! let stats = bands.render_to(&draws, &mut bins, Rgb565::default(), |sink| {
//!     draw.project(&tri, &mut |s| sink.push(0, s));
//! }, &mut dma)?;
//! assert_eq!((stats.bands, started, waited), (4, 32 * 32, 4));
//! # Ok::<(), fixel::Error>(())
//! ```

use super::band::{BandRenderer, BandStats};
pub use super::band_link::{BandSender, Blocking, Dma};
use super::share::BandShare;
use super::Frame;
use crate::color::TargetColor;

impl<C: TargetColor> BandRenderer<'_, C> {
    /// Runs `draw_band` on each band in turn (band index from 0, frame rows `y0..`), after
    /// clearing it to `clear`, in the next buffer of the ring, then starts sending it;
    /// before a buffer is drawn into again, and before returning, waits for its transfer.
    /// Counts bands and pixels in `stats`. The first error stops the frame (after the
    /// transfers already started are waited for).
    pub(super) fn each_band<S: BandSender<C>>(
        &mut self,
        stats: &mut BandStats,
        clear: C,
        sender: &mut S,
        draw_band: impl FnMut(&mut Frame<'_, C>, u32) -> u32,
    ) -> Result<(), S::Error> {
        self.each_band_of(BandShare::ALL, stats, clear, sender, draw_band)
    }

    /// [`each_band`](Self::each_band) for the bands of `share` only (the others are
    /// neither cleared, drawn nor sent).
    pub(super) fn each_band_of<S: BandSender<C>>(
        &mut self,
        share: BandShare,
        stats: &mut BandStats,
        clear: C,
        sender: &mut S,
        mut draw_band: impl FnMut(&mut Frame<'_, C>, u32) -> u32,
    ) -> Result<(), S::Error> {
        let need = self.width as usize * self.rows as usize;
        let slots = self.color.count();
        let (mut busy, mut slot) = (0, 0);
        let (core, cores) = (share.core(), share.cores());
        let mut turn = 0;
        let mut result = Ok(());
        let mut y0 = 0;
        let mut index = 0;
        while y0 < self.height {
            let rows = self.rows.min(self.height - y0);
            let mine = turn == core;
            turn += 1;
            if turn == cores {
                turn = 0;
            }
            if !mine {
                index += 1;
                y0 += rows;
                continue;
            }
            if busy == slots {
                busy -= 1;
                if let Err(e) = sender.wait() {
                    result = Err(e);
                    break;
                }
            }
            let n = self.width as usize * rows as usize;
            let Some(color) = self.color.get(slot).and_then(|c| c.get_mut(..n.min(need))) else {
                break;
            };
            let Ok(mut band) = Frame::new(color, self.width, rows) else {
                break;
            };
            if let Some(d) = self.depth.as_deref_mut() {
                match band.with_depth_as_is(&mut d[..n.min(need)]) {
                    Ok(b) => band = b,
                    Err(_) => break,
                }
            }
            let mut band = band.at_row(y0);
            band.clear(clear);
            stats.pixels = stats.pixels.saturating_add(draw_band(&mut band, index));
            if let Err(e) = sender.start(&band) {
                result = Err(e);
                break;
            }
            busy += 1;
            slot += 1;
            if slot == slots {
                slot = 0;
            }
            stats.bands += 1;
            index += 1;
            y0 += rows;
        }
        // The buffers go back to the caller only when no transfer reads them.
        while busy > 0 {
            busy -= 1;
            let waited = sender.wait();
            if result.is_ok() {
                result = waited;
            }
        }
        result
    }
}
