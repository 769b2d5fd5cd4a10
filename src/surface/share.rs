//! One frame's bands drawn by two (or more) cores: the frame is binned once
//! ([`BinnedFrame::new`], on one core), then each core draws its share of the bands
//! ([`BandRenderer::render_share_to`]) from the same bins, read only, into its own band
//! buffers, with its own depth band and sender. The other draws of the band path split the
//! same way: the accumulated frame from a [`BinnedFrame`]
//! ([`BandRenderer::render_accumulated_share_to`]), the frame of meshes of any size from a
//! [`SpansFrame`](super::SpansFrame) ([`BandRenderer::render_spans_share_to`]).
//!
//! The split is static and interleaved ([`BandShare`]: core `c` of `n` draws the bands `k`
//! with `k mod n = c`), for three reasons:
//!
//! * no atomics: each core knows its bands before the frame starts, so nothing is claimed
//!   at run time. ARMv6-M (the RP2040's Cortex-M0+) has no compare-and-swap, and a work
//!   queue would need one (or a lock through `critical-section`, whose hardware spinlock
//!   serialises the cores at every band);
//! * order on the wire: the display takes the bands top to bottom, so band `k + 1` is
//!   useful only once band `k` is sent. Interleaved, the two cores finish neighbouring bands
//!   at about the same time and each needs two band buffers; split into halves, core 1's
//!   finished bands would wait for all of core 0's, with half a frame of buffers;
//! * balance: the work per band changes slowly down the screen, so the even and the odd
//!   bands carry about the same work (the benchmark cube, sphere and teapot on two RISC-V
//!   harts, `cargo xtask cores`: the busier one does 50.0 to 50.9 % of the instructions).
//!
//! The binning pass may be split too: each core bins part of the meshes into bins of its
//! own, and [`BinnedFrame::join`] makes one frame of the two (the first part's triangles
//! first in each band, as one pass would have binned them).
//!
//! The cores hand finished bands to the link in band order; that hand-off is the caller's
//! (on an RP2040, core 1 passes each finished band through the SIO FIFO, which needs no
//! atomics, to the core that drives the DMA). The pixels of every band are those of the
//! one-core frame (tested): the raster set-up depends on the viewport only.
//!
//! ```
//! use fixel::prelude::*;
//! use fixel::geometry::Vertex;
//! use fixel::pipeline::{Exact, NoDepth, ShadedDraw};
//! use fixel::shading::Flat;
//! use fixel::surface::{BandDraw, BandShare, Binned, BinnedFrame, Blocking};
//! use fixel::Rgb565;
//!
//! let vp = Viewport::new(0, 0, 16, 32)?;
//! let draw = ShadedDraw::<_, Exact, NoDepth>::new(Flat(0x07E0), vp, Cull::None)?;
//! let p = |x: f32, y: f32| [fixel::math::fx(x), fixel::math::fx(y), Fx::ZERO, Fx::ONE];
//! let tri = [Vertex::new(p(-0.9, -0.9), []), Vertex::new(p(0.9, -0.9), []), Vertex::new(p(0.0, 0.9), [])];
//! let draws: [&dyn BandDraw<Rgb565>; 1] = [&draw];
//! let mut bins = [Binned::default(); 2];
//! // Once per frame, on one core.
//! let frame = BinnedFrame::new(&draws, &mut bins, |sink| {
//!     draw.project(&tri, &mut |s| sink.push(0, s));
//! })?;
//! // On each core: its own band buffer (two with a DMA sender), its share of the bands.
//! let mut sent = [0u32; 2];
//! for core in 0..2 {
//!     let mut buf = [Rgb565::default(); 16 * 8];
//!     let mut bands = BandRenderer::new(&mut buf, 16, 8, 32)?;
//!     let share = BandShare::new(core, 2)?;
//!     let mut send = Blocking(|band: &Frame<'_, Rgb565>| {
//!         sent[core as usize] += 1 << (band.first_row() / 8);
//!         Ok::<(), core::convert::Infallible>(())
//!     });
//!     bands.render_share_to(&frame, Rgb565::default(), share, &mut send)?;
//! }
//! assert_eq!(sent, [0b0101, 0b1010]); // core 0 the even bands, core 1 the odd ones
//! # Ok::<(), fixel::Error>(())
//! ```

use super::band::{BandError, BandRenderer, BandStats, Binned, TriangleSink};
use super::band_draw::BandDraw;
use super::band_link::BandSender;
use crate::color::TargetColor;
use crate::Error;

/// Which bands of a frame one core draws: band `k` when `k mod cores = core`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct BandShare {
    core: u8,
    cores: u8,
}

impl BandShare {
    /// Every band: one core.
    pub const ALL: BandShare = BandShare { core: 0, cores: 1 };

    /// Core `core` of `cores` (`core < cores <= 255`); anything else is refused with
    /// [`Error::BadBandShare`].
    pub fn new(core: u32, cores: u32) -> Result<Self, Error> {
        if cores == 0 || cores > u32::from(u8::MAX) || core >= cores {
            return Err(Error::BadBandShare { core, cores });
        }
        Ok(BandShare {
            core: core as u8,
            cores: cores as u8,
        })
    }

    /// This core's index.
    pub fn core(self) -> u32 {
        self.core.into()
    }

    /// How many cores share the frame.
    pub fn cores(self) -> u32 {
        self.cores.into()
    }
}

/// A frame's screen triangles, binned once (the geometry's one pass), for the cores that
/// draw its bands: read only from then on.
#[derive(Clone, Copy)]
pub struct BinnedFrame<'f, 'd, C: TargetColor> {
    draws: &'f [&'d dyn BandDraw<C>],
    bins: &'f [Binned],
    /// The triangles binned after `bins` ([`BinnedFrame::join`]).
    later: &'f [Binned],
}

impl<C: TargetColor> core::fmt::Debug for BinnedFrame<'_, '_, C> {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.debug_struct("BinnedFrame")
            .field("draws", &self.draws.len())
            .field("triangles", &self.triangles())
            .finish()
    }
}

impl<'f, 'd, C: TargetColor> BinnedFrame<'f, 'd, C> {
    /// Runs `geometry` once, binning its screen triangles (tagged with their draw's index
    /// in `draws`, as for [`BandRenderer::render`]) into `bins`. Refused: triangles that do
    /// not fit `bins` ([`Error::CapacityExceeded`]: the cores would each run the geometry
    /// again), more than 256 draws, and what `render` refuses of the triangles pushed.
    pub fn new(
        draws: &'f [&'d dyn BandDraw<C>],
        bins: &'f mut [Binned],
        mut geometry: impl FnMut(&mut TriangleSink<'_, '_, '_, C>),
    ) -> Result<Self, Error> {
        if draws.len() > usize::from(u8::MAX) + 1 {
            return Err(Error::CapacityExceeded { capacity: 256 });
        }
        let capacity = bins.len();
        let (bins, len, overflow) = BandRenderer::bin(draws, bins, &mut geometry)?;
        if overflow {
            return Err(Error::CapacityExceeded { capacity });
        }
        let bins: &'f [Binned] = bins;
        Ok(BinnedFrame {
            draws,
            bins: bins.get(..len).unwrap_or(&[]),
            later: &[],
        })
    }

    /// This frame's triangles followed by `later`'s, drawn in that order in each band:
    /// the binning pass split between cores (each core bins part of the meshes, in the
    /// order of the whole pass, into its own bins). Refused when `later` has other draws
    /// or either frame is already a join ([`Error::BadMode`]).
    pub fn join(self, later: BinnedFrame<'f, 'd, C>) -> Result<Self, Error> {
        if !core::ptr::eq(self.draws, later.draws) {
            return Err(Error::BadMode(
                "binned frames joined must share their draws",
            ));
        }
        if !self.later.is_empty() || !later.later.is_empty() {
            return Err(Error::BadMode("a binned frame joins two parts at most"));
        }
        Ok(BinnedFrame {
            later: later.bins,
            ..self
        })
    }

    /// Screen triangles binned.
    pub fn triangles(&self) -> usize {
        self.bins.len() + self.later.len()
    }

    /// The draws, and the binned triangles in drawing order (the first part, then the
    /// joined one).
    pub(super) fn parts(&self) -> (&'f [&'d dyn BandDraw<C>], [&'f [Binned]; 2]) {
        (self.draws, [self.bins, self.later])
    }
}

impl<C: TargetColor> BandRenderer<'_, C> {
    /// Draws `share`'s bands of `frame` (band `k` when `k mod cores = core`), each cleared
    /// to `clear` and started on `sender` once drawn, top to bottom: the bands and pixels
    /// [`render_to`](Self::render_to) gives those bands. [`BandStats`] counts this
    /// share's bands and pixels, and the frame's triangles.
    ///
    /// Refused before any band is drawn: a frame with fewer bands than `share` has cores
    /// ([`Error::TooFewBands`]), and what `render` refuses of the draws.
    pub fn render_share_to<S: BandSender<C>>(
        &mut self,
        frame: &BinnedFrame<'_, '_, C>,
        clear: C,
        share: BandShare,
        sender: &mut S,
    ) -> Result<BandStats, BandError<S::Error>> {
        self.check_share(frame, share)?;
        let mut stats = BandStats {
            triangles: frame.triangles() as u32,
            ..BandStats::default()
        };
        let (draws, bins, later) = (frame.draws, frame.bins, frame.later);
        let mut no_geometry = |_: &mut TriangleSink<'_, '_, '_, C>| {};
        self.each_band_of(share, &mut stats, clear, sender, |band, _| {
            let first = Self::draw_binned(draws, bins, false, &mut no_geometry, band);
            first.saturating_add(Self::draw_binned(
                draws,
                later,
                false,
                &mut no_geometry,
                band,
            ))
        })
        .map_err(BandError::Flush)?;
        Ok(stats)
    }

    /// What every form of a share refuses: draws this renderer cannot draw (as `render`),
    /// fewer bands than `share` has cores ([`Error::TooFewBands`]).
    pub(super) fn check_share(
        &self,
        frame: &BinnedFrame<'_, '_, C>,
        share: BandShare,
    ) -> Result<(), Error> {
        self.check_draws(frame.draws)?;
        let bands = self.height.div_ceil(self.rows.max(1));
        if bands < share.cores() {
            return Err(Error::TooFewBands {
                bands,
                cores: share.cores(),
            });
        }
        Ok(())
    }
}
