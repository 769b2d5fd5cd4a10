//! Bands to an SPI display through `embedded-hal` 1.0 (`SpiDevice`, feature `embedded-hal`)
//! or `embedded-hal-async` 1.0 (feature `embedded-hal-async`): each band's pixels as
//! big-endian RGB565 bytes (the ST7789's and ILI9341's 16-bit colour), through a byte buffer
//! the caller gives.
//!
//! The sender writes pixel data only. Bands arrive in order, top to bottom, so one window
//! command for the whole frame (CASET, RASET, RAMWR, sent by the display driver before the
//! frame, with the data/command pin left on data) takes every band: the controller goes on
//! writing memory across chip-select pulses until the next command.
//!
//! A scratch buffer of 2 bytes per band pixel sends a band in one write; a shorter one
//! sends it in chunks of `scratch.len() / 2` pixels (one `SpiDevice` transaction each). With
//! the async frame, only the first chunk's transfer overlaps the drawing of the next band:
//! give it the whole band's bytes.
//!
//! ```
//! # #[cfg(feature = "embedded-hal")] {
//! use embedded_hal::spi::{ErrorType, Operation, SpiDevice};
//! use fixel::surface::{BandSender, Frame, SpiSender};
//! use fixel::Rgb565;
//!
//! /// A bus that keeps what it is sent.
//! struct Wire(Vec<u8>);
//! impl ErrorType for Wire {
//!     type Error = core::convert::Infallible;
//! }
//! impl SpiDevice for Wire {
//!     fn transaction(&mut self, ops: &mut [Operation<'_, u8>]) -> Result<(), Self::Error> {
//!         for op in ops {
//!             if let Operation::Write(bytes) = op {
//!                 self.0.extend_from_slice(bytes);
//!             }
//!         }
//!         Ok(())
//!     }
//! }
//!
//! let mut scratch = [0u8; 8];
//! let mut spi = SpiSender::new(Wire(Vec::new()), &mut scratch)?;
//! let mut pixels = [Rgb565::new(31, 0, 0); 6];
//! let band = Frame::new(&mut pixels, 3, 2)?;
//! spi.start(&band).unwrap();
//! assert_eq!(spi.into_inner().0, [0xF8, 0x00].repeat(6));
//! # }
//! # Ok::<(), fixel::Error>(())
//! ```

use super::Frame;
use crate::color::TargetColor;
use crate::Error;

/// Sends bands over an SPI device as big-endian RGB565, through `scratch` (see the
/// [module docs](self)).
#[derive(Debug)]
pub struct SpiSender<'s, D> {
    spi: D,
    scratch: &'s mut [u8],
}

impl<'s, D> SpiSender<'s, D> {
    /// A sender over `spi` converting through `scratch` (at least 2 bytes; 2 per band pixel
    /// sends each band in one write). A shorter one is refused with [`Error::WrongLength`].
    pub fn new(spi: D, scratch: &'s mut [u8]) -> Result<Self, Error> {
        if scratch.len() < 2 {
            return Err(Error::WrongLength {
                expected: 2,
                actual: scratch.len(),
            });
        }
        Ok(SpiSender { spi, scratch })
    }

    /// The SPI device back.
    pub fn into_inner(self) -> D {
        self.spi
    }

    /// The bytes of the pixels `pixels[at..]` that fit the scratch buffer, written into it;
    /// their count (0 when `at` is past the end).
    fn fill<C: TargetColor>(&mut self, pixels: &[C], at: usize) -> usize {
        let rest = pixels.get(at..).unwrap_or(&[]);
        let mut n = 0;
        for (out, c) in self.scratch.chunks_exact_mut(2).zip(rest) {
            out.copy_from_slice(&c.to_rgb565().to_be_bytes());
            n += 2;
        }
        n
    }
}

#[cfg(feature = "embedded-hal")]
impl<C: TargetColor, D: embedded_hal::spi::SpiDevice> super::BandSender<C> for SpiSender<'_, D> {
    type Error = D::Error;

    /// Writes the band (blocking: it is on the wire when this returns).
    fn start(&mut self, band: &Frame<'_, C>) -> Result<(), D::Error> {
        let pixels = band.pixels();
        let mut at = 0;
        loop {
            let n = self.fill(pixels, at);
            if n == 0 {
                return Ok(());
            }
            self.spi.write(&self.scratch[..n])?;
            at += n / 2;
        }
    }

    fn wait(&mut self) -> Result<(), D::Error> {
        Ok(())
    }
}

#[cfg(feature = "embedded-hal-async")]
impl<C: TargetColor, D: embedded_hal_async::spi::SpiDevice> super::AsyncBandSender<C>
    for SpiSender<'_, D>
{
    type Error = D::Error;

    async fn send(&mut self, band: &Frame<'_, C>) -> Result<(), D::Error> {
        let pixels = band.pixels();
        let mut at = 0;
        loop {
            let n = self.fill(pixels, at);
            if n == 0 {
                return Ok(());
            }
            self.spi.write(&self.scratch[..n]).await?;
            at += n / 2;
        }
    }
}
