//! A frame of meshes of any size (a [`BandRange`] of two bytes per triangle, the geometry
//! re-run through a [`MeshSink`] for the triangles each band meets) in every form of the
//! band path: one binning pass ([`SpansFrame::new`]: screen triangles into the bins while
//! they fit, the band range of every triangle id), then the band passes, drawn from the
//! bins or by re-running the geometry for the triangles that meet each band.
//!
//! The forms, the same bands with the same pixels (tested bit for bit):
//! * [`BandRenderer::render_spans`] (a blocking flush) and
//!   [`BandRenderer::render_spans_to`] (a [`BandSender`]: with a ring of buffers, band
//!   `k + 1` is drawn while band `k` is sent);
//! * [`BandRenderer::render_spans_async`]: an `async` frame through an
//!   [`AsyncBandSender`];
//! * [`BandRenderer::render_spans_share_to`]: one core's [`BandShare`] of a
//!   [`SpansFrame`] binned once for every core. Each core passes its own `geometry` (the
//!   one given to the binning pass, or one that pushes the same triangles: its own vertex
//!   cache), which it runs for its bands when the bins do not hold the frame, and its own
//!   set-up cache ([`BandRenderer::with_setup_cache`]). A core's bands are not neighbours,
//!   so a set-up is kept only within a band and the cache saves nothing there.

use super::band::{BandError, BandStats, Binned, PushCheck};
use super::band_draw::BandDraw;
use super::overlap::{BandSender, Blocking};
use super::overlap_async::AsyncBandSender;
use super::setup_queue::{self, QueueState, SetupQueue};
use super::share::BandShare;
use super::spans::{
    BandRange, BandRanges, FrameDivisor, MeshSink, Pass, Windows, LAST_BAND, WINDOWS,
};
use super::{BandRenderer, Frame, RenderTarget};
use crate::color::TargetColor;
use crate::pipeline::KeptSetup;
use crate::Error;

/// A frame's binning pass for bands of `rows` rows over `height` rows: what its band passes
/// draw from, read only (shared by the cores that draw its bands).
pub struct SpansFrame<'f, 'd, C: TargetColor> {
    draws: &'f [&'d dyn BandDraw<C>],
    windows: Windows,
    /// The frame's screen triangles, when they all fit.
    bins: &'f [Binned],
    /// The bins could not hold the frame: the band passes re-run the geometry.
    bins_full: bool,
    ranges: &'f [BandRange],
    /// Triangle ids past the end of `ranges`: wanted in every band.
    ranges_short: bool,
    triangles: u32,
    rows: u32,
    height: u32,
}

impl<C: TargetColor> core::fmt::Debug for SpansFrame<'_, '_, C> {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.debug_struct("SpansFrame")
            .field("triangles", &self.triangles)
            .field("binned", &!self.bins_full)
            .field("rows", &self.rows)
            .field("height", &self.height)
            .finish()
    }
}

impl<'f, 'd, C: TargetColor> SpansFrame<'f, 'd, C> {
    /// Runs `geometry` once (the binning pass, [`MeshSink::fresh`]) for bands of `rows`
    /// rows (at least 1) over `height` rows: screen triangles into `bins` while they fit
    /// (may be empty), a [`BandRange`] per triangle id into `ranges` (may be short: the ids
    /// past it are re-projected in every band). Refused: more than 256 draws
    /// ([`Error::CapacityExceeded`]), a triangle of a draw index past `draws` or of another
    /// varying count ([`Error::BadDrawIndex`], [`Error::WrongVaryings`]).
    pub fn new(
        draws: &'f [&'d dyn BandDraw<C>],
        bins: &'f mut [Binned],
        ranges: &'f mut [BandRange],
        rows: u32,
        height: u32,
        geometry: impl FnMut(&mut MeshSink<'_, '_, '_, C>),
    ) -> Result<Self, Error> {
        let mut frame = SpansFrame::empty(draws, rows, height);
        frame.bin(bins, &mut *ranges, geometry)?;
        frame.ranges = ranges;
        Ok(frame)
    }

    /// A frame with nothing binned yet.
    fn empty(draws: &'f [&'d dyn BandDraw<C>], rows: u32, height: u32) -> Self {
        let rows = rows.max(1);
        SpansFrame {
            draws,
            windows: Windows {
                ids: [(usize::MAX, 0); WINDOWS],
                group: FrameDivisor::new(height.div_ceil(rows).div_ceil(WINDOWS as u32)),
            },
            bins: &[],
            bins_full: false,
            ranges: &[],
            ranges_short: false,
            triangles: 0,
            rows,
            height,
        }
    }

    /// The binning pass (see [`new`](Self::new)) into this frame, in place: the frame
    /// (its id windows are 512 bytes on a 32-bit part) is on the stack once. `ranges` is
    /// filled but not kept: the caller lends it to the band passes, read only
    /// ([`SpansFrame::new`]) or to end ranges (one core drawing every band in order).
    fn bin(
        &mut self,
        bins: &'f mut [Binned],
        ranges: &mut [BandRange],
        mut geometry: impl FnMut(&mut MeshSink<'_, '_, '_, C>),
    ) -> Result<(), Error> {
        if self.draws.len() > usize::from(u8::MAX) + 1 {
            return Err(Error::CapacityExceeded { capacity: 256 });
        }
        ranges.fill(BandRange::EMPTY);
        // The pass borrows the storage; the frame keeps it afterwards, read only.
        let mut sink = MeshSink {
            pass: Pass::Bin {
                windows: &mut self.windows,
                bins: &mut *bins,
                len: 0,
                bins_full: false,
                ranges: &mut *ranges,
                ranges_short: false,
                rows: FrameDivisor::new(self.rows),
                height: self.height,
                triangles: 0,
                draws: self.draws,
                check: PushCheck::NEW,
            },
            attributes: true,
        };
        geometry(&mut sink);
        let Pass::Bin {
            len,
            bins_full,
            ranges_short,
            triangles,
            check,
            ..
        } = sink.pass
        else {
            return Err(Error::BadMode("the binning pass ended in a band pass"));
        };
        if let Some(e) = check.error() {
            return Err(e);
        }
        let bins: &'f [Binned] = bins;
        self.bins = bins.get(..len).unwrap_or(&[]);
        (self.bins_full, self.ranges_short, self.triangles) = (bins_full, ranges_short, triangles);
        Ok(())
    }

    /// Screen triangles the binning pass saw.
    pub fn triangles(&self) -> u32 {
        self.triangles
    }

    /// The stats of a frame before its bands are drawn.
    fn stats(&self) -> BandStats {
        BandStats {
            triangles: self.triangles,
            reprojected: self.bins_full,
            rewalked: self.bins_full && self.ranges_short,
            ..BandStats::default()
        }
    }

    /// Draws band `index` into `band` (cleared): from the bins, or by running `geometry`
    /// for the triangles that meet it. `queue` is the set-up ring's state, handed on from
    /// band to band; `ranges` the frame's band ranges, as the form drawing the bands lends
    /// them. The pixels written.
    #[inline(always)]
    fn draw_band(
        &self,
        ranges: BandRanges<'_>,
        geometry: &mut impl FnMut(&mut MeshSink<'_, '_, '_, C>),
        setups: &mut [KeptSetup],
        queue: &mut QueueState,
        band: &mut Frame<'_, C>,
        index: u32,
    ) -> u32 {
        if self.bins_full {
            let mut s = MeshSink {
                pass: Pass::Band {
                    // Ids without a stored range are wanted in every band.
                    window: if self.ranges_short {
                        (0, usize::MAX)
                    } else {
                        self.windows.window(index)
                    },
                    draws: self.draws,
                    band,
                    ranges,
                    index: index.min(LAST_BAND) as u8,
                    pixels: 0,
                    // The band counted modulo 256.
                    setups: SetupQueue::new(&mut *setups, *queue, index as u8),
                    last: (usize::MAX, 0),
                    whole: false,
                },
                attributes: true,
            };
            geometry(&mut s);
            s.finish_band();
            match s.pass {
                Pass::Band { pixels, setups, .. } => {
                    *queue = setups.state();
                    pixels
                }
                Pass::Bin { .. } => 0,
            }
        } else {
            let (r0, r1) = band.row_range();
            let mut pixels = 0;
            // Bins in index order in every band: the index is the set-up key.
            let mut kept = SetupQueue::new(&mut *setups, *queue, index as u8);
            for (i, b) in self.bins.iter().enumerate() {
                if !b.meets(r0, r1) {
                    continue;
                }
                if let Some(d) = self.draws.get(usize::from(b.draw)) {
                    let slot = setup_queue::key(i, 0)
                        .and_then(|key| kept.slot(key, b.draw, i32::from(b.rows.1) > r1));
                    pixels += d.draw_piece(b.tri.as_ref(), band, slot);
                }
            }
            *queue = kept.state();
            pixels
        }
    }
}

impl<C: TargetColor> BandRenderer<'_, C> {
    /// Draws one frame of meshes of any size (two bytes of storage per triangle id).
    /// `geometry` is called once for binning and then once per band; it must push the same
    /// screen triangles in the same order each time (for each triangle id it
    /// [`wants`](MeshSink::wants)), usually through [`crate::scene::mesh_to_sink`]. `bins`
    /// holds screen triangles while they fit (may be empty); `ranges` one [`BandRange`] per
    /// triangle id (may be shorter than the frame: see [`BandStats::rewalked`]). Each band
    /// is cleared to `clear`, drawn and passed to `flush`; the first flush error stops the
    /// frame and is returned. Input errors are refused before any band is drawn, as for
    /// [`render`](Self::render).
    pub fn render_spans<E>(
        &mut self,
        draws: &[&dyn BandDraw<C>],
        bins: &mut [Binned],
        ranges: &mut [BandRange],
        clear: C,
        geometry: impl FnMut(&mut MeshSink<'_, '_, '_, C>),
        flush: impl FnMut(&Frame<'_, C>) -> Result<(), E>,
    ) -> Result<BandStats, BandError<E>> {
        self.render_spans_to(draws, bins, ranges, clear, geometry, &mut Blocking(flush))
    }

    /// [`render_spans`](Self::render_spans) through a [`BandSender`], as
    /// [`render_to`](Self::render_to) is [`render`](Self::render) through one: the same
    /// bands, the next drawn while the last is sent when the renderer has a ring of buffers.
    pub fn render_spans_to<S: BandSender<C>>(
        &mut self,
        draws: &[&dyn BandDraw<C>],
        bins: &mut [Binned],
        ranges: &mut [BandRange],
        clear: C,
        mut geometry: impl FnMut(&mut MeshSink<'_, '_, '_, C>),
        sender: &mut S,
    ) -> Result<BandStats, BandError<S::Error>> {
        self.check_draws(draws)?;
        let mut frame = SpansFrame::empty(draws, self.rows, self.height);
        frame.bin(bins, &mut *ranges, &mut geometry)?;
        let mut stats = frame.stats();
        // Lent out of the renderer for the band passes (`each_band` borrows it), emptied:
        // what an earlier frame kept is not this frame's.
        let setups = core::mem::take(&mut self.setups);
        setup_queue::clear(setups);
        let mut queue = QueueState::default();
        let result = self.each_band(&mut stats, clear, sender, |band, index| {
            frame.draw_band(
                BandRanges::End(&mut *ranges),
                &mut geometry,
                setups,
                &mut queue,
                band,
                index,
            )
        });
        self.setups = setups;
        result.map_err(BandError::Flush)?;
        Ok(stats)
    }

    /// [`render_spans`](Self::render_spans) as an `async` frame, as
    /// [`render_async`](Self::render_async) is [`render`](Self::render): each band is sent
    /// through `sender` while the next is drawn (with a ring of buffers). The same bands in
    /// the same order with the same pixels.
    ///
    /// ```
    /// # use core::future::Future;
    /// # use core::pin::pin;
    /// # use core::task::{Context, Poll, Waker};
    /// use fixel::prelude::*;
    /// use fixel::geometry::Vertex;
    /// use fixel::pipeline::{Exact, NoDepth, ShadedDraw};
    /// use fixel::shading::Flat;
    /// use fixel::surface::{AsyncBandSender, BandDraw, BandRange};
    /// use fixel::Rgb565;
    ///
    /// /// Counts the bands sent (a real sender awaits an async SPI write).
    /// struct Count(u32);
    /// impl AsyncBandSender<Rgb565> for Count {
    ///     type Error = core::convert::Infallible;
    ///     async fn send(&mut self, _band: &Frame<'_, Rgb565>) -> Result<(), Self::Error> {
    ///         self.0 += 1;
    ///         Ok(())
    ///     }
    /// }
    ///
    /// let vp = Viewport::new(0, 0, 16, 32)?;
    /// let draw = ShadedDraw::<_, Exact, NoDepth>::new(Flat(0xF800), vp, Cull::None)?;
    /// let p = |x: f32, y: f32| [fixel::math::fx(x), fixel::math::fx(y), Fx::ZERO, Fx::ONE];
    /// let v = |x, y| Vertex::new(p(x, y), []);
    /// let mesh = [[v(-0.9, -0.9), v(0.9, -0.9), v(0.0, -0.2)], [v(-0.9, 0.2), v(0.9, 0.2), v(0.0, 0.9)]];
    /// let (mut a, mut b) = ([Rgb565::default(); 16 * 8], [Rgb565::default(); 16 * 8]);
    /// let mut buffers = [&mut a[..], &mut b[..]];
    /// let mut bands = BandRenderer::with_buffers(&mut buffers, 16, 8, 32)?;
    /// let draws: [&dyn BandDraw<Rgb565>; 1] = [&draw];
    /// // No bins: each band re-projects the triangles whose band range covers it.
    /// let mut ranges = [BandRange::EMPTY; 2];
    /// let mut sender = Count(0);
    /// let frame = bands.render_spans_async(&draws, &mut [], &mut ranges, Rgb565::default(), |sink| {
    ///     for (id, tri) in mesh.iter().enumerate() {
    ///         if sink.wants(id) {
    ///             draw.project(tri, &mut |s| sink.push(id, 0, s));
    ///         }
    ///     }
    /// }, &mut sender);
    /// // Any executor runs it; this sender never waits, so one poll finishes the frame.
    /// let Poll::Ready(stats) = pin!(frame).poll(&mut Context::from_waker(Waker::noop())) else {
    ///     unreachable!()
    /// };
    /// assert!(stats?.reprojected);
    /// assert_eq!(sender.0, 4);
    /// # Ok::<(), fixel::Error>(())
    /// ```
    pub async fn render_spans_async<S: AsyncBandSender<C>>(
        &mut self,
        draws: &[&dyn BandDraw<C>],
        bins: &mut [Binned],
        ranges: &mut [BandRange],
        clear: C,
        mut geometry: impl FnMut(&mut MeshSink<'_, '_, '_, C>),
        sender: &mut S,
    ) -> Result<BandStats, BandError<S::Error>> {
        self.check_draws(draws)?;
        let mut frame = SpansFrame::empty(draws, self.rows, self.height);
        frame.bin(bins, &mut *ranges, &mut geometry)?;
        let mut stats = frame.stats();
        let setups = core::mem::take(&mut self.setups);
        setup_queue::clear(setups);
        let mut queue = QueueState::default();
        let result = self
            .each_band_async(&mut stats, clear, sender, |band, index| {
                frame.draw_band(
                    BandRanges::End(&mut *ranges),
                    &mut geometry,
                    setups,
                    &mut queue,
                    band,
                    index,
                )
            })
            .await;
        self.setups = setups;
        result.map_err(BandError::Flush)?;
        Ok(stats)
    }

    /// Draws `share`'s bands of `frame` (band `k` when `k mod cores = core`), each cleared
    /// to `clear` and started on `sender` once drawn, top to bottom: the bands and pixels
    /// [`render_spans_to`](Self::render_spans_to) gives those bands. `geometry` is this
    /// core's, pushing the triangles of the binning pass (see the [module docs](self)); it
    /// runs only when the bins do not hold the frame. [`BandStats`] counts this share's
    /// bands and pixels, and the frame's triangles.
    ///
    /// Refused before any band is drawn: a frame binned for other bands than this
    /// renderer's ([`Error::BadMode`]), fewer bands than `share` has cores
    /// ([`Error::TooFewBands`]), and what `render` refuses of the draws.
    ///
    /// ```
    /// use fixel::prelude::*;
    /// use fixel::geometry::Vertex;
    /// use fixel::pipeline::{Exact, NoDepth, ShadedDraw};
    /// use fixel::shading::Flat;
    /// use fixel::surface::{BandDraw, BandRange, BandShare, Blocking, SpansFrame};
    /// use fixel::Rgb565;
    ///
    /// let vp = Viewport::new(0, 0, 16, 32)?;
    /// let draw = ShadedDraw::<_, Exact, NoDepth>::new(Flat(0x07E0), vp, Cull::None)?;
    /// let p = |x: f32, y: f32| [fixel::math::fx(x), fixel::math::fx(y), Fx::ZERO, Fx::ONE];
    /// let v = |x, y| Vertex::new(p(x, y), []);
    /// let mesh = [[v(-0.9, -0.9), v(0.9, -0.9), v(0.0, -0.2)], [v(-0.9, 0.2), v(0.9, 0.2), v(0.0, 0.9)]];
    /// // The same triangles on every core, each id asked for first.
    /// let geometry = |sink: &mut fixel::surface::MeshSink<'_, '_, '_, Rgb565>| {
    ///     for (id, tri) in mesh.iter().enumerate() {
    ///         if sink.wants(id) {
    ///             draw.project(tri, &mut |s| sink.push(id, 0, s));
    ///         }
    ///     }
    /// };
    /// let draws: [&dyn BandDraw<Rgb565>; 1] = [&draw];
    /// // Once per frame, on one core: no bins, the band range of each triangle.
    /// let mut ranges = [BandRange::EMPTY; 2];
    /// let frame = SpansFrame::new(&draws, &mut [], &mut ranges, 8, 32, geometry)?;
    /// // On each core: its own band buffer, its share of the bands.
    /// let mut sent = [0u32; 2];
    /// for core in 0..2 {
    ///     let mut buf = [Rgb565::default(); 16 * 8];
    ///     let mut bands = BandRenderer::new(&mut buf, 16, 8, 32)?;
    ///     let mut send = Blocking(|band: &Frame<'_, Rgb565>| {
    ///         sent[core as usize] += 1 << (band.first_row() / 8);
    ///         Ok::<(), core::convert::Infallible>(())
    ///     });
    ///     let share = BandShare::new(core, 2)?;
    ///     bands.render_spans_share_to(&frame, Rgb565::default(), share, geometry, &mut send)?;
    /// }
    /// assert_eq!(sent, [0b0101, 0b1010]); // core 0 the even bands, core 1 the odd ones
    /// # Ok::<(), fixel::Error>(())
    /// ```
    pub fn render_spans_share_to<S: BandSender<C>>(
        &mut self,
        frame: &SpansFrame<'_, '_, C>,
        clear: C,
        share: BandShare,
        mut geometry: impl FnMut(&mut MeshSink<'_, '_, '_, C>),
        sender: &mut S,
    ) -> Result<BandStats, BandError<S::Error>> {
        self.check_draws(frame.draws)?;
        if frame.rows != self.rows.max(1) || frame.height != self.height {
            return Err(BandError::Input(Error::BadMode(
                "the spans frame was binned for bands of other rows or height",
            )));
        }
        let bands = self.height.div_ceil(self.rows.max(1));
        if bands < share.cores() {
            return Err(BandError::Input(Error::TooFewBands {
                bands,
                cores: share.cores(),
            }));
        }
        let mut stats = frame.stats();
        let setups = core::mem::take(&mut self.setups);
        setup_queue::clear(setups);
        let mut queue = QueueState::default();
        let result = self.each_band_of(share, &mut stats, clear, sender, |band, index| {
            frame.draw_band(
                BandRanges::Read(frame.ranges),
                &mut geometry,
                setups,
                &mut queue,
                band,
                index,
            )
        });
        self.setups = setups;
        result.map_err(BandError::Flush)?;
        Ok(stats)
    }
}
