//! Accumulation through bands (the accumulation buffer on a part that cannot hold a
//! frame): the frame's geometry is binned once; then each band is drawn once per sample
//! offset, with the binned screen triangles shifted by the offset, the drawings summed in a
//! band-sized [`Accumulator`] and averaged into the band before it is flushed. RAM: the
//! colour and depth band plus 6 bytes per band pixel of sums; time: the band raster work
//! once per sample, the geometry once per frame.
//!
//! Four forms, the same averaged bands (tested bit for bit): [`render_accumulated`]
//! (blocking flush), [`render_accumulated_to`] (through a [`BandSender`], the next band
//! drawn while the last is sent), [`render_accumulated_async`] (an `async` frame through
//! an [`AsyncBandSender`]) and [`render_accumulated_share_to`] (the bands of one core's
//! [`BandShare`] of a [`BinnedFrame`], built once for every core).
//!
//! [`render_accumulated`]: BandRenderer::render_accumulated
//! [`render_accumulated_to`]: BandRenderer::render_accumulated_to
//! [`render_accumulated_async`]: BandRenderer::render_accumulated_async
//! [`render_accumulated_share_to`]: BandRenderer::render_accumulated_share_to
//!
//! A shift of the screen triangle by `(dx, dy)` pixels is the jittered projection of
//! [`crate::scene::jittered`] done after projection: coverage moves on the 1/16-pixel grid
//! and attributes on the 1/4096-pixel one (rounded there), depth and `w` stay, so the
//! interpolation is the same perspective-correct one at the shifted place.

use embedded_graphics_core::pixelcolor::Rgb565;

use super::band::{BandError, BandStats, Binned, TriangleSink};
use super::band_draw::{each_variant, AnyTriangle, BandDraw, Binnable};
use super::overlap::{BandSender, Blocking};
use super::overlap_async::AsyncBandSender;
use super::share::{BandShare, BinnedFrame};
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

/// Checks an accumulation's inputs for bands of `need` pixels: 1 to
/// [`Accumulator::MAX_FRAMES`] offsets ([`Error::BadSize`] with their count), `sums` of at
/// least `need` entries ([`Error::WrongLength`]).
fn check_samples(offsets: &[[Fx; 2]], sums: &[[u16; 3]], need: usize) -> Result<(), Error> {
    if offsets.is_empty() || offsets.len() > Accumulator::MAX_FRAMES as usize {
        return Err(Error::BadSize(offsets.len() as u32));
    }
    if sums.len() < need {
        return Err(Error::WrongLength {
            expected: need,
            actual: sums.len(),
        });
    }
    Ok(())
}

/// An I16F16 pixel offset in `2^-ATTR_SUBPIXEL_BITS` pixels, rounded.
fn shift(o: Fx) -> i32 {
    (o.to_bits() + (1 << 3)) >> (16 - ATTR_SUBPIXEL_BITS)
}

/// What each band of an accumulated frame is drawn from: the binned triangles (in `parts`
/// order), the sample offsets, the band-sized sums.
struct Samples<'a, 'd> {
    draws: &'a [&'d dyn BandDraw<Rgb565>],
    parts: [&'a [Binned]; 2],
    offsets: &'a [[Fx; 2]],
    sums: &'a mut [[u16; 3]],
    clear: Rgb565,
    /// The first error of the accumulator (none with checked inputs).
    failed: Option<Error>,
}

impl Samples<'_, '_> {
    /// Draws `band` once per offset, sums the drawings and leaves their average in it; the
    /// pixels written, over every sample.
    fn band(&mut self, band: &mut Frame<'_, Rgb565>) -> u32 {
        let (r0, r1) = band.row_range();
        let n = band.pixels().len();
        let Some(Ok(mut acc)) = self.sums.get_mut(..n).map(Accumulator::new) else {
            return 0;
        };
        let mut pixels = 0;
        for o in self.offsets {
            let d = [shift(o[0]), shift(o[1])];
            band.clear(self.clear);
            for b in self.parts.iter().flat_map(|p| p.iter()) {
                // A shift of under a pixel moves a triangle by at most one row.
                if !b.meets(r0 - 1, r1) {
                    continue;
                }
                if let Some(dr) = self.draws.get(usize::from(b.draw)) {
                    pixels = u32::saturating_add(
                        pixels,
                        dr.draw_piece(shifted_any(&b.tri, d).as_ref(), band, None),
                    );
                }
            }
            if let Err(e) = acc.add(band.pixels()) {
                self.failed = Some(e);
            }
        }
        if let Err(e) = acc.resolve(band.pixels_mut()) {
            self.failed = Some(e);
        }
        pixels
    }

    /// `stats` once the bands are drawn: pixels per sample (the same whatever the band
    /// height), or the accumulator's error.
    fn finish<E>(self, mut stats: BandStats) -> Result<BandStats, BandError<E>> {
        stats.pixels /= self.offsets.len() as u32;
        match self.failed {
            Some(e) => Err(BandError::Input(e)),
            None => Ok(stats),
        }
    }
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
        geometry: impl FnMut(&mut TriangleSink<'_, '_, '_, Rgb565>),
        sender: &mut S,
    ) -> Result<BandStats, BandError<S::Error>> {
        let (mut samples, mut stats) =
            self.bin_samples(draws, bins, clear, offsets, sums, geometry)?;
        self.each_band(&mut stats, clear, sender, |band, _| samples.band(band))
            .map_err(BandError::Flush)?;
        samples.finish(stats)
    }

    /// [`render_accumulated`](Self::render_accumulated) as an `async` frame, as
    /// [`render_async`](Self::render_async) is [`render`](Self::render): each averaged band
    /// is sent through `sender` while the next is drawn (with a ring of buffers). The same
    /// bands in the same order with the same pixels.
    ///
    /// ```
    /// # use core::future::Future;
    /// # use core::pin::pin;
    /// # use core::task::{Context, Poll, Waker};
    /// use fixel::prelude::*;
    /// use fixel::geometry::Vertex;
    /// use fixel::pipeline::{Exact, NoDepth, ShadedDraw};
    /// use fixel::scene::SamplePattern;
    /// use fixel::shading::Flat;
    /// use fixel::surface::{AsyncBandSender, BandDraw, Binned};
    /// use fixel::Rgb565;
    ///
    /// /// Counts the pixels sent (a real sender awaits an async SPI write).
    /// struct Count(usize);
    /// impl AsyncBandSender<Rgb565> for Count {
    ///     type Error = core::convert::Infallible;
    ///     async fn send(&mut self, band: &Frame<'_, Rgb565>) -> Result<(), Self::Error> {
    ///         self.0 += band.pixels().len();
    ///         Ok(())
    ///     }
    /// }
    ///
    /// let vp = Viewport::new(0, 0, 16, 16)?;
    /// let draw = ShadedDraw::<_, Exact, NoDepth>::new(Flat(0xF800), vp, Cull::None)?;
    /// let p = |x: f32, y: f32| [fixel::math::fx(x), fixel::math::fx(y), Fx::ZERO, Fx::ONE];
    /// let tri = [Vertex::new(p(-0.9, -0.9), []), Vertex::new(p(0.9, -0.9), []), Vertex::new(p(0.0, 0.9), [])];
    /// let (mut a, mut b) = ([Rgb565::default(); 16 * 4], [Rgb565::default(); 16 * 4]);
    /// let mut buffers = [&mut a[..], &mut b[..]];
    /// let mut bands = BandRenderer::with_buffers(&mut buffers, 16, 4, 16)?;
    /// let draws: [&dyn BandDraw<Rgb565>; 1] = [&draw];
    /// let mut bins = [Binned::default(); 2];
    /// let mut sums = [[0u16; 3]; 16 * 4];
    /// let mut offsets = [[Fx::ZERO; 2]; 4];
    /// let n = SamplePattern::RotatedGrid4.offsets(&mut offsets)?;
    /// let offsets = &offsets[..n];
    /// let mut sender = Count(0);
    /// let frame = bands.render_accumulated_async(&draws, &mut bins, Rgb565::default(), offsets, &mut sums, |sink| {
    ///     draw.project(&tri, &mut |s| sink.push(0, s));
    /// }, &mut sender);
    /// // Any executor runs it; this sender never waits, so one poll finishes the frame.
    /// let Poll::Ready(stats) = pin!(frame).poll(&mut Context::from_waker(Waker::noop())) else {
    ///     unreachable!()
    /// };
    /// assert_eq!((stats?.bands, sender.0), (4, 16 * 16));
    /// # Ok::<(), fixel::Error>(())
    /// ```
    #[allow(clippy::too_many_arguments)]
    pub async fn render_accumulated_async<S: AsyncBandSender<Rgb565>>(
        &mut self,
        draws: &[&dyn BandDraw<Rgb565>],
        bins: &mut [Binned],
        clear: Rgb565,
        offsets: &[[Fx; 2]],
        sums: &mut [[u16; 3]],
        geometry: impl FnMut(&mut TriangleSink<'_, '_, '_, Rgb565>),
        sender: &mut S,
    ) -> Result<BandStats, BandError<S::Error>> {
        let (mut samples, mut stats) =
            self.bin_samples(draws, bins, clear, offsets, sums, geometry)?;
        self.each_band_async(&mut stats, clear, sender, |band, _| samples.band(band))
            .await
            .map_err(BandError::Flush)?;
        samples.finish(stats)
    }

    /// The accumulated bands of `share` (band `k` when `k mod cores = core`) of `frame`,
    /// binned once for every core ([`BinnedFrame::new`]), each started on `sender` once
    /// averaged: the bands and pixels [`render_accumulated_to`](Self::render_accumulated_to)
    /// gives those bands. Each core has its own band buffers, depth band and `sums`.
    ///
    /// Refused before any band is drawn: fewer bands than `share` has cores
    /// ([`Error::TooFewBands`]), and what `render_accumulated` refuses of the draws,
    /// offsets and sums.
    ///
    /// ```
    /// use fixel::prelude::*;
    /// use fixel::geometry::Vertex;
    /// use fixel::pipeline::{Exact, NoDepth, ShadedDraw};
    /// use fixel::scene::SamplePattern;
    /// use fixel::shading::Flat;
    /// use fixel::surface::{BandDraw, BandShare, Binned, BinnedFrame, Blocking};
    /// use fixel::Rgb565;
    ///
    /// let vp = Viewport::new(0, 0, 16, 32)?;
    /// let draw = ShadedDraw::<_, Exact, NoDepth>::new(Flat(0x07E0), vp, Cull::None)?;
    /// let p = |x: f32, y: f32| [fixel::math::fx(x), fixel::math::fx(y), Fx::ZERO, Fx::ONE];
    /// let tri = [Vertex::new(p(-0.9, -0.9), []), Vertex::new(p(0.9, -0.9), []), Vertex::new(p(0.0, 0.9), [])];
    /// let draws: [&dyn BandDraw<Rgb565>; 1] = [&draw];
    /// let mut bins = [Binned::default(); 2];
    /// // Once per frame, on one core.
    /// let frame = BinnedFrame::new(&draws, &mut bins, |sink| {
    ///     draw.project(&tri, &mut |s| sink.push(0, s));
    /// })?;
    /// // On each core: its own band buffer and sums, its share of the bands.
    /// let mut offsets = [[Fx::ZERO; 2]; 4];
    /// let n = SamplePattern::RotatedGrid4.offsets(&mut offsets)?;
    /// let offsets = &offsets[..n];
    /// let mut sent = [0u32; 2];
    /// for core in 0..2 {
    ///     let mut buf = [Rgb565::default(); 16 * 8];
    ///     let mut sums = [[0u16; 3]; 16 * 8];
    ///     let mut bands = BandRenderer::new(&mut buf, 16, 8, 32)?;
    ///     let mut send = Blocking(|band: &Frame<'_, Rgb565>| {
    ///         sent[core as usize] += 1 << (band.first_row() / 8);
    ///         Ok::<(), core::convert::Infallible>(())
    ///     });
    ///     let share = BandShare::new(core, 2)?;
    ///     bands.render_accumulated_share_to(&frame, Rgb565::default(), offsets, &mut sums, share, &mut send)?;
    /// }
    /// assert_eq!(sent, [0b0101, 0b1010]); // core 0 the even bands, core 1 the odd ones
    /// # Ok::<(), fixel::Error>(())
    /// ```
    pub fn render_accumulated_share_to<S: BandSender<Rgb565>>(
        &mut self,
        frame: &BinnedFrame<'_, '_, Rgb565>,
        clear: Rgb565,
        offsets: &[[Fx; 2]],
        sums: &mut [[u16; 3]],
        share: BandShare,
        sender: &mut S,
    ) -> Result<BandStats, BandError<S::Error>> {
        self.check_share(frame, share)?;
        check_samples(offsets, sums, self.width as usize * self.rows as usize)?;
        let (draws, parts) = frame.parts();
        let mut samples = Samples {
            draws,
            parts,
            offsets,
            sums,
            clear,
            failed: None,
        };
        let mut stats = BandStats {
            triangles: frame.triangles() as u32,
            ..BandStats::default()
        };
        self.each_band_of(share, &mut stats, clear, sender, |band, _| {
            samples.band(band)
        })
        .map_err(BandError::Flush)?;
        samples.finish(stats)
    }

    /// The checks and the binning pass of an accumulated frame: what its bands are drawn
    /// from, and the stats so far.
    fn bin_samples<'a, 'd, E>(
        &self,
        draws: &'a [&'d dyn BandDraw<Rgb565>],
        bins: &'a mut [Binned],
        clear: Rgb565,
        offsets: &'a [[Fx; 2]],
        sums: &'a mut [[u16; 3]],
        mut geometry: impl FnMut(&mut TriangleSink<'_, '_, '_, Rgb565>),
    ) -> Result<(Samples<'a, 'd>, BandStats), BandError<E>> {
        self.check_draws(draws)?;
        check_samples(offsets, sums, self.width as usize * self.rows as usize)?;
        let capacity = bins.len();
        let mut sink = TriangleSink::binning(bins, draws);
        geometry(&mut sink);
        let (bins, len, overflow) = sink.into_bins()?;
        if overflow {
            return Err(BandError::Input(Error::CapacityExceeded { capacity }));
        }
        let bins: &'a [Binned] = bins;
        let stats = BandStats {
            triangles: len as u32,
            ..BandStats::default()
        };
        let samples = Samples {
            draws,
            parts: [bins.get(..len).unwrap_or(&[]), &[]],
            offsets,
            sums,
            clear,
            failed: None,
        };
        Ok((samples, stats))
    }
}
