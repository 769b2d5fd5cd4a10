//! Anti-aliasing by supersampling and accumulation: averaging several samples
//! per pixel, in RGB565 channels with one rounding.
//!
//! * **Supersampling on a regular grid** through bands: render the frame at `k` times the
//!   resolution (a `k·W x k·H` viewport, bands of `k·rows` rows) and let the band flush
//!   [`resolve_box`] each `k·W x k·rows` band into a `W x rows` band before it goes to the
//!   display. RAM grows with `k²` times one band, never with the frame: a 320-pixel-wide,
//!   8-row band with depth is 10 KB at 1x, 40 KB at 2 x 2 and 160 KB at 4 x 4.
//! * **Accumulation** ([`Accumulator`]): any number of frames (or bands) rendered with
//!   sub-pixel camera offsets ([`crate::scene::SamplePattern`],
//!   [`crate::scene::jittered`]) summed per channel and averaged: progressive
//!   anti-aliasing of a still scene with any sample pattern (rotated grid, stratified
//!   jitter), and motion blur as the same sum over time.
//!
//! Both average each RGB565 channel exactly (`round(Σ c / n)`), so `n` equal samples give
//! that colour back bit for bit.
//!
//! ```
//! use fixel::prelude::*;
//! use fixel::surface::{resolve_box, Accumulator};
//!
//! // A 4 x 2 band at 2 x 2: the left half red, the right half blue.
//! let mut hi = [Rgb565::RED; 8 * 4];
//! for y in 0..4 { for x in 4..8 { hi[y * 8 + x] = Rgb565::BLUE; } }
//! let band = Frame::new(&mut hi, 8, 4)?;
//! let mut lo = [Rgb565::BLACK; 4 * 2];
//! resolve_box(&band, 2, &mut lo)?;
//! assert_eq!((lo[0], lo[3]), (Rgb565::RED, Rgb565::BLUE));
//!
//! // Two frames averaged: red and blue give purple.
//! let mut sums = [[0u16; 3]; 4];
//! let mut acc = Accumulator::new(&mut sums)?;
//! acc.add(&[Rgb565::RED; 4])?;
//! acc.add(&[Rgb565::BLUE; 4])?;
//! let mut out = [Rgb565::BLACK; 4];
//! acc.resolve(&mut out)?;
//! assert_eq!(out[0], Rgb565::new(16, 0, 16));
//! # Ok::<(), fixel::Error>(())
//! ```

use embedded_graphics_core::pixelcolor::raw::{RawData, RawU16};
use embedded_graphics_core::pixelcolor::Rgb565;

use super::{Frame, RenderTarget};
use crate::Error;

/// The three channels of a raw RGB565 value: `[r5, g6, b5]`.
#[inline(always)]
fn channels(c: Rgb565) -> [u32; 3] {
    let v = u32::from(RawU16::from(c).into_inner());
    [v >> 11, (v >> 5) & 63, v & 31]
}

/// `round(sum / n)` per channel (`n > 0`), packed.
#[inline(always)]
fn average(sum: [u32; 3], n: u32) -> Rgb565 {
    let q = |s: u32, max: u32| ((2 * s + n) / (2 * n)).min(max);
    Rgb565::new(
        q(sum[0], 31) as u8,
        q(sum[1], 63) as u8,
        q(sum[2], 31) as u8,
    )
}

/// Averages each `k x k` block of the band `hi` (`k·w x k·r` pixels) into `out` (`w x r`,
/// row-major): the box filter of regular-grid supersampling. Errors if `k` is 0 or does
/// not divide the band, or `out` is shorter than `w · r`.
pub fn resolve_box(hi: &Frame<'_, Rgb565>, k: u32, out: &mut [Rgb565]) -> Result<(), Error> {
    let (hw, hh) = (hi.width(), hi.height());
    if k == 0 || k > 16 || hw % k != 0 || hh % k != 0 {
        return Err(Error::BadSize(k));
    }
    let (w, r) = (hw / k, hh / k);
    let need = (w * r) as usize;
    if out.len() < need {
        return Err(Error::WrongLength {
            expected: need,
            actual: out.len(),
        });
    }
    let px = hi.pixels();
    let n = k * k;
    for y in 0..r {
        for x in 0..w {
            let mut sum = [0u32; 3];
            for sy in 0..k {
                let row = ((y * k + sy) * hw + x * k) as usize;
                for c in px.get(row..row + k as usize).unwrap_or(&[]) {
                    let ch = channels(*c);
                    for i in 0..3 {
                        sum[i] += ch[i];
                    }
                }
            }
            out[(y * w + x) as usize] = average(sum, n);
        }
    }
    Ok(())
}

/// Sums of RGB565 channels over several frames (or bands) of the same size, in caller
/// storage (`[r, g, b]` per pixel, 6 bytes), and their average. Up to 1040 frames fit the
/// `u16` sums (`63 · 1040 < 65536`); more are refused.
#[derive(Debug)]
pub struct Accumulator<'a> {
    sums: &'a mut [[u16; 3]],
    count: u32,
}

impl<'a> Accumulator<'a> {
    /// Most frames the sums hold.
    pub const MAX_FRAMES: u32 = 1040;

    /// An accumulator over `sums` (one entry per pixel), cleared.
    pub fn new(sums: &'a mut [[u16; 3]]) -> Result<Self, Error> {
        if sums.is_empty() {
            return Err(Error::BadSize(0));
        }
        sums.fill([0; 3]);
        Ok(Accumulator { sums, count: 0 })
    }

    /// Frames added so far.
    pub fn count(&self) -> u32 {
        self.count
    }

    /// Empties the sums.
    pub fn clear(&mut self) {
        self.sums.fill([0; 3]);
        self.count = 0;
    }

    /// Adds one frame (as long as the sums).
    pub fn add(&mut self, frame: &[Rgb565]) -> Result<(), Error> {
        if frame.len() != self.sums.len() {
            return Err(Error::WrongLength {
                expected: self.sums.len(),
                actual: frame.len(),
            });
        }
        if self.count >= Self::MAX_FRAMES {
            return Err(Error::CapacityExceeded {
                capacity: Self::MAX_FRAMES as usize,
            });
        }
        for (s, c) in self.sums.iter_mut().zip(frame) {
            let ch = channels(*c);
            for i in 0..3 {
                s[i] += ch[i] as u16;
            }
        }
        self.count += 1;
        Ok(())
    }

    /// The average of the frames added (`round(Σ / n)` per channel) into `out` (as long as
    /// the sums). Errors before any frame was added.
    pub fn resolve(&self, out: &mut [Rgb565]) -> Result<(), Error> {
        if out.len() != self.sums.len() {
            return Err(Error::WrongLength {
                expected: self.sums.len(),
                actual: out.len(),
            });
        }
        if self.count == 0 {
            return Err(Error::CapacityExceeded { capacity: 0 });
        }
        for (o, s) in out.iter_mut().zip(self.sums.iter()) {
            *o = average(s.map(u32::from), self.count);
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use embedded_graphics_core::pixelcolor::RgbColor;

    #[test]
    fn equal_samples_give_the_colour_back() {
        for v in [0u16, 1, 0x7BEF, 0xFFFF, 0x1234, 0xF800] {
            let c = Rgb565::from(RawU16::new(v));
            let mut hi = [c; 16];
            let band = Frame::new(&mut hi, 4, 4).unwrap();
            let mut lo = [Rgb565::BLACK; 4];
            resolve_box(&band, 2, &mut lo).unwrap();
            assert_eq!(lo, [c; 4]);
            let mut sums = [[0u16; 3]; 2];
            let mut acc = Accumulator::new(&mut sums).unwrap();
            for _ in 0..7 {
                acc.add(&[c, c]).unwrap();
            }
            let mut out = [Rgb565::BLACK; 2];
            acc.resolve(&mut out).unwrap();
            assert_eq!(out, [c, c]);
        }
    }

    #[test]
    fn bad_sizes_are_refused() {
        let mut hi = [Rgb565::BLACK; 12];
        let band = Frame::new(&mut hi, 4, 3).unwrap();
        let mut lo = [Rgb565::BLACK; 4];
        assert!(resolve_box(&band, 2, &mut lo).is_err()); // 3 rows: not a multiple of 2
        assert!(resolve_box(&band, 0, &mut lo).is_err());
        let mut sums = [[0u16; 3]; 2];
        let mut acc = Accumulator::new(&mut sums).unwrap();
        assert!(acc.add(&[Rgb565::BLACK; 3]).is_err());
        assert!(acc.resolve(&mut [Rgb565::BLACK; 2]).is_err()); // nothing added
        for _ in 0..Accumulator::MAX_FRAMES {
            acc.add(&[Rgb565::WHITE; 2]).unwrap();
        }
        assert!(acc.add(&[Rgb565::WHITE; 2]).is_err());
        let mut out = [Rgb565::BLACK; 2];
        acc.resolve(&mut out).unwrap();
        assert_eq!(out, [Rgb565::WHITE; 2]);
    }
}
