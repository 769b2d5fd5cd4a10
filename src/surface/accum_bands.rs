//! Accumulation through bands (the accumulation buffer on a part that cannot hold a
//! frame): the frame's geometry is binned once; then each band is drawn once per sample
//! offset, with the binned screen triangles shifted by the offset, the drawings summed in a
//! band-sized [`Accumulator`] and averaged into the band before it is flushed. RAM: the
//! colour and depth band plus 6 bytes per band pixel of sums; time: the band raster work
//! once per sample, the geometry once per frame.
//!
//! A shift of the screen triangle by `(dx, dy)` pixels is the jittered projection of
//! [`crate::scene::jittered`] done after projection: coverage moves on the 1/16-pixel grid
//! and attributes on the 1/4096-pixel one (rounded there), depth and `w` stay, so the
//! interpolation is the same perspective-correct one at the shifted place.

use embedded_graphics_core::pixelcolor::Rgb565;

use super::band::{BandError, BandStats, Binned, TriangleSink};
use super::band_draw::{each_variant, AnyTriangle, BandDraw, Binnable};
use super::overlap::{BandSender, Blocking};
use super::{Accumulator, BandRenderer, Frame, RenderTarget};
use crate::geometry::ScreenTriangle;
use crate::math::Fx;
use crate::raster::{ATTR_SUBPIXEL_BITS, SUBPIXEL_BITS};
use crate::Error;

/// `tri` moved by `d` (`2^-ATTR_SUBPIXEL_BITS` pixel units), re-split into the coverage grid
/// and the attribute offset as the projection does (`x = floor(p / 256 + 1/2)`).
fn shifted<const N: usize>(tri: &ScreenTriangle<N>, d: [i32; 2]) -> ScreenTriangle<N> {
    const K: u32 = ATTR_SUBPIXEL_BITS - SUBPIXEL_BITS;
    let mut t = *tri;
    if d == [0, 0] {
        return t; // exactly the projection's own split
    }
    for v in t.iter_mut() {
        let (px, py) = v.attr_position();
        let split = |p: i32| {
            let c = p.wrapping_add(1 << (K - 1)) >> K;
            (c, (p - (c << K)) as i16)
        };
        let ((x, sx), (y, sy)) = (split(px.wrapping_add(d[0])), split(py.wrapping_add(d[1])));
        v.x = x;
        v.y = y;
        v.sub = [sx, sy];
    }
    t
}

/// [`shifted`] for a binned triangle of any varying count.
fn shifted_any(tri: &AnyTriangle, d: [i32; 2]) -> AnyTriangle {
    each_variant!(AnyTriangle, tri, t => shifted(t, d).to_any())
}

impl BandRenderer<'_, Rgb565> {
    /// Draws one frame with `offsets.len()` samples per pixel (sub-pixel offsets in I16F16
    /// pixels, for example from [`crate::scene::SamplePattern::offsets`]), averaged per band
    /// through `sums` (at least `width · rows` entries) before each band is flushed. The
    /// geometry is binned once into `bins` as by [`BandRenderer::render`]; when the bins
    /// cannot hold the frame this is refused ([`Error::CapacityExceeded`] with their size),
    /// as are no offsets, more than [`Accumulator::MAX_FRAMES`], or short `sums`.
    #[allow(clippy::too_many_arguments)]
    pub fn render_accumulated<E>(
        &mut self,
        draws: &[&dyn BandDraw<Rgb565>],
        bins: &mut [Binned],
        clear: Rgb565,
        offsets: &[[Fx; 2]],
        sums: &mut [[u16; 3]],
        geometry: impl FnMut(&mut TriangleSink<'_, '_, '_, Rgb565>),
        flush: impl FnMut(&Frame<'_, Rgb565>) -> Result<(), E>,
    ) -> Result<BandStats, BandError<E>> {
        let mut sender = Blocking(flush);
        self.render_accumulated_to(draws, bins, clear, offsets, sums, geometry, &mut sender)
    }

    /// [`render_accumulated`](Self::render_accumulated) through a [`BandSender`], as
    /// [`render_to`](Self::render_to) is [`render`](Self::render) through one: the same
    /// averaged bands, the next drawn while the last is sent when the renderer has a ring
    /// of buffers.
    #[allow(clippy::too_many_arguments)]
    pub fn render_accumulated_to<S: BandSender<Rgb565>>(
        &mut self,
        draws: &[&dyn BandDraw<Rgb565>],
        bins: &mut [Binned],
        clear: Rgb565,
        offsets: &[[Fx; 2]],
        sums: &mut [[u16; 3]],
        mut geometry: impl FnMut(&mut TriangleSink<'_, '_, '_, Rgb565>),
        sender: &mut S,
    ) -> Result<BandStats, BandError<S::Error>> {
        self.check_draws(draws)?;
        let need = self.width as usize * self.rows as usize;
        if offsets.is_empty() || offsets.len() > Accumulator::MAX_FRAMES as usize {
            return Err(BandError::Input(Error::BadSize(offsets.len() as u32)));
        }
        if sums.len() < need {
            return Err(BandError::Input(Error::WrongLength {
                expected: need,
                actual: sums.len(),
            }));
        }
        let capacity = bins.len();
        let mut sink = TriangleSink::binning(bins, draws);
        geometry(&mut sink);
        let (bins, len, overflow) = sink.into_bins()?;
        if overflow {
            return Err(BandError::Input(Error::CapacityExceeded { capacity }));
        }
        let shift = |o: Fx| {
            let b = o.to_bits();
            // I16F16 to 2^-12 pixel, rounded.
            (b + (1 << 3)) >> (16 - ATTR_SUBPIXEL_BITS)
        };
        let deltas = offsets.iter().map(|o| [shift(o[0]), shift(o[1])]);
        let mut stats = BandStats {
            triangles: len as u32,
            ..BandStats::default()
        };
        let mut failed = None;
        self.each_band(&mut stats, clear, sender, |band, _| {
            let (r0, r1) = band.row_range();
            let n = band.pixels().len();
            let Ok(mut acc) = Accumulator::new(&mut sums[..n]) else {
                return 0;
            };
            let mut pixels = 0;
            for d in deltas.clone() {
                band.clear(clear);
                for b in bins[..len].iter() {
                    // A shift of under a pixel moves a triangle by at most one row.
                    if !b.meets(r0 - 1, r1) {
                        continue;
                    }
                    if let Some(dr) = draws.get(usize::from(b.draw)) {
                        pixels = u32::saturating_add(
                            pixels,
                            dr.draw_piece(shifted_any(&b.tri, d).as_ref(), band, None),
                        );
                    }
                }
                if let Err(e) = acc.add(band.pixels()) {
                    failed = Some(e);
                }
            }
            if let Err(e) = acc.resolve(band.pixels_mut()) {
                failed = Some(e);
            }
            pixels
        })
        .map_err(BandError::Flush)?;
        // Pixels per sample over the frame: the same whatever the band height.
        stats.pixels /= offsets.len() as u32;
        if let Some(e) = failed {
            return Err(BandError::Input(e));
        }
        Ok(stats)
    }
}
