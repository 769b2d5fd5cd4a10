//! Band rendering for meshes of any size: two bytes per triangle instead of a screen
//! triangle per bin.
//!
//! [`BandRenderer::render`](super::BandRenderer::render) keeps every screen triangle of the frame (168 bytes each);
//! a mesh of a thousand visible triangles does not fit a small part's RAM, and the fallback
//! runs the whole geometry once per band. [`BandRenderer::render_spans`](super::BandRenderer::render_spans) keeps, per mesh
//! triangle, only the range of bands it touches ([`BandRange`], 2 bytes), found by one
//! geometry pass over the frame; each band then runs the geometry again for the triangles
//! whose range covers it and skips the others *before transforming anything* (the
//! geometry asks [`MeshSink::next_wanted`] for the next triangle that meets the band, a
//! scan of the ranges). With 8-row bands a small triangle is
//! re-projected in one or two bands, so the geometry costs about two whole-frame passes
//! instead of one per band; with [`BandRenderer::with_setup_cache`](super::BandRenderer::with_setup_cache) a triangle crossing
//! into the next band is set up once for both, and the next band draws it from the kept
//! set-up without projecting it again (the benchmark sphere in bands against the same
//! frame whole: `sphere_sized` in the README's bands table, written by
//! `cargo xtask mcu --docs`).
//!
//! Ladder of storage (same pixels on every rung, tested):
//!
//! 1. the frame's screen triangles fit `bins`: they are drawn from the bins, the geometry runs
//!    once (as [`BandRenderer::render`](super::BandRenderer::render));
//! 2. they do not, but every triangle id has a [`BandRange`]: one binning pass, then each
//!    band re-projects the triangles it meets ([`BandStats::reprojected`](super::BandStats::reprojected));
//! 3. triangle ids past the end of `ranges` have no stored range: they are projected in
//!    every band ([`BandStats::rewalked`](super::BandStats::rewalked)); with empty `ranges` this is the plain per-band
//!    re-walk.
//!
//! Storage (bytes; 32-bit targets): a screen triangle in `bins` 168, a [`BandRange`] 2, a
//! prepared vertex of the walker's cache ([`crate::scene::CachedVertex`]) 32, a kept set-up
//! ([`KeptSetup`](crate::pipeline::KeptSetup), optional, see
//! [`BandRenderer::with_setup_cache`](super::BandRenderer::with_setup_cache)) 100, plus 512 on the stack for the per-band id
//! windows. For a 320 x 8 band with 16-bit depth (10,240):
//!
//! | mesh | triangles | rung | storage besides the band | measured RAM (firmware) |
//! |---|---:|---|---:|---:|
//! | cube | 12 (6 on screen) | bins (16) | 2,688 + cache 32 x 32 = 1,024 + set-ups 16 x 100 = 1,600 | 21.1 KB |
//! | benchmark sphere (`sphere_sized`) | 2,208 (656 on screen) | ranges | 4,416 + cache 64 x 32 = 2,048 + set-ups 40 x 100 = 4,000 (every triangle crossing a band boundary; 35 on Cortex-M0+) | 24.2 KB (Cortex-M4F) |
//! | fine sphere | 10,080 | ranges | 20,160 + cache | over 24 KB: give `ranges` what fits, the rest is re-walked per band (flagged) |
//! | any | n | bins | 168 per screen triangle | |
//!
//! Bit-exactness: the band pass gets the very same screen triangles as a whole-frame draw
//! (the geometry is deterministic), in the same order (triangle ids ascending within each
//! mesh; ties in the depth test resolve the same way), and the raster set-up depends on the
//! viewport only.

use super::band::{rows_of, Binned, PushCheck};
use super::band_draw::{BandDraw, Binnable};
use super::setup_queue::{self, SetupQueue};
use super::{Frame, RenderTarget};
use crate::color::TargetColor;
use crate::geometry::ScreenTriangle;

/// The bands one triangle touches: band indices `first..end`, saturated at 254 (a
/// triangle below band 254 is then looked at in every band from 254 on: conservative).
/// [`BandRange::EMPTY`] (the default, all zero bits so arrays of it start zeroed) when the
/// triangle emits nothing visible.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct BandRange {
    first: u8,
    end: u8,
}

impl Default for BandRange {
    fn default() -> Self {
        BandRange::EMPTY
    }
}

/// Largest band index a range stores; later bands share it.
pub(super) const LAST_BAND: u32 = 254;

impl BandRange {
    /// No band (culled, clipped away or outside the frame's rows).
    pub const EMPTY: BandRange = BandRange { first: 0, end: 0 };

    /// True when no band is covered.
    pub fn is_empty(self) -> bool {
        self.first >= self.end
    }

    /// Whether band `index` (saturated at 254) is covered.
    #[inline]
    pub fn covers(self, index: u32) -> bool {
        let b = index.min(LAST_BAND) as u8;
        self.first <= b && b < self.end
    }

    /// Whether band `b` (already saturated at 254) is covered.
    #[inline]
    fn covers_saturated(self, b: u8) -> bool {
        self.first <= b && b < self.end
    }

    /// Grows the range to include bands `first..=last` (each at most 254).
    fn include(&mut self, first: u8, last: u8) {
        let end = last.saturating_add(1);
        if self.is_empty() {
            *self = BandRange { first, end };
        } else {
            self.first = self.first.min(first);
            self.end = self.end.max(end);
        }
    }
}

/// Receives the screen triangles of a frame's geometry, tagged with a triangle id (the
/// triangle's index in its mesh plus the mesh's first id) and the index of their draw.
pub struct MeshSink<'s, 'f, 'd, C: TargetColor> {
    pub(super) pass: Pass<'s, 'f, 'd, C>,
    /// What [`MeshSink::attributes`] says (false once the binning pass's bins are full).
    pub(super) attributes: bool,
}

impl<C: TargetColor> core::fmt::Debug for MeshSink<'_, '_, '_, C> {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.write_str(match self.pass {
            Pass::Bin { .. } => "MeshSink(binning)",
            Pass::Band { .. } => "MeshSink(band)",
        })
    }
}

pub(super) enum Pass<'s, 'f, 'd, C: TargetColor> {
    /// The binning pass: screen triangles to `bins` while they fit, band ranges always.
    Bin {
        windows: &'s mut Windows,
        bins: &'s mut [Binned],
        len: usize,
        bins_full: bool,
        ranges: &'s mut [BandRange],
        ranges_short: bool,
        rows: FrameDivisor,
        height: u32,
        triangles: u32,
        draws: &'s [&'d dyn BandDraw<C>],
        check: PushCheck,
    },
    /// One band: draw what covers it.
    Band {
        window: (usize, usize),
        draws: &'s [&'d dyn BandDraw<C>],
        band: &'s mut Frame<'f, C>,
        /// The band ranges; in a serial frame a triangle kept whole for the next band ends
        /// its range here.
        ranges: BandRanges<'s>,
        /// Band index, saturated at 254 as the ranges are.
        index: u8,
        pixels: u32,
        /// Set-ups kept across bands (an empty ring without a set-up cache).
        setups: SetupQueue<'s>,
        /// The last id pushed and the index of its last screen triangle (clipped pieces),
        /// for the set-up keys.
        last: (usize, u32),
        /// Whether every screen triangle of the last id that goes on below the band is
        /// kept resumable (the next band then draws them from the set-up cache, and need
        /// not project the triangle).
        whole: bool,
    },
}

/// The band ranges as a band pass sees them.
pub(super) enum BandRanges<'s> {
    /// Read only: the bands are shared between cores, so a band cannot count on the one
    /// above it having run on the same core (nothing kept is resumed across them).
    Read(&'s [BandRange]),
    /// One core draws every band in order: a triangle kept whole for the next band (see
    /// [`SetupQueue::resume_before`]) ends its range in the band that kept it, so the
    /// geometry skips it afterwards.
    End(&'s mut [BandRange]),
}

impl BandRanges<'_> {
    /// The ranges, one per triangle id.
    #[inline(always)]
    fn all(&self) -> &[BandRange] {
        match self {
            BandRanges::Read(r) => r,
            BandRanges::End(r) => r,
        }
    }
}

/// Per group of bands, the lowest and highest triangle id that meets it (so a band pass
/// need not ask about the ids outside). 64 groups of `group` consecutive bands.
#[derive(Debug)]
pub(super) struct Windows {
    pub(super) ids: [(usize, usize); WINDOWS],
    pub(super) group: FrameDivisor,
}

/// `x / d` for a divisor fixed for the frame (rows per band, bands per window group): a
/// shift when it is a power of two, as it usually is. The binning pass divides twice per
/// triangle for each, and on Cortex-M0+ a 32-bit division is a library call of about 100
/// instructions.
#[derive(Clone, Copy, Debug)]
pub(super) struct FrameDivisor {
    d: u32,
    shift: u32,
    pow2: bool,
}

impl FrameDivisor {
    pub(super) fn new(d: u32) -> Self {
        let d = d.max(1);
        FrameDivisor {
            d,
            shift: d.trailing_zeros(),
            pow2: d.is_power_of_two(),
        }
    }

    #[inline(always)]
    fn div(self, x: u32) -> u32 {
        if self.pow2 {
            x >> self.shift
        } else {
            x / self.d
        }
    }
}

pub(super) const WINDOWS: usize = 64;

impl Windows {
    pub(super) fn window(&self, band: u32) -> (usize, usize) {
        self.ids
            .get(self.group.div(band) as usize)
            .copied()
            .unwrap_or((0, usize::MAX))
    }
}

impl<C: TargetColor> MeshSink<'_, '_, '_, C> {
    /// The triangle ids this pass may want, `lo..=hi` (the whole range in the binning
    /// pass; in a band pass, the ids of the triangles that met the band's group). The
    /// geometry may skip the ids outside without asking [`wants`](Self::wants).
    #[inline]
    pub fn window(&self) -> (usize, usize) {
        match &self.pass {
            Pass::Bin { .. } => (0, usize::MAX),
            Pass::Band { window, .. } => *window,
        }
    }

    /// True in the binning pass, which starts a frame: caches of transformed vertices
    /// kept across the band passes must be emptied then (the matrices may have changed).
    #[inline]
    pub fn fresh(&self) -> bool {
        matches!(self.pass, Pass::Bin { .. })
    }

    /// Whether triangle `id` must be projected in this pass; when `false` the geometry
    /// should skip it before transforming its vertices.
    #[inline]
    pub fn wants(&self, id: usize) -> bool {
        match &self.pass {
            Pass::Bin { .. } => true,
            Pass::Band { ranges, index, .. } => ranges
                .all()
                .get(id)
                .is_none_or(|r| r.covers_saturated(*index)),
        }
    }

    /// The first id in `id..end` that [`wants`](Self::wants) says yes to, or `end`: in a
    /// band pass a tight scan of the band ranges (ids past the stored ranges are always
    /// wanted).
    #[inline]
    pub fn next_wanted(&self, id: usize, end: usize) -> usize {
        match &self.pass {
            Pass::Bin { .. } => id,
            Pass::Band { ranges, index, .. } => {
                let ranges = ranges.all();
                let stop = end.min(ranges.len());
                let Some(stored) = ranges.get(id..stop) else {
                    return id; // past the stored ranges (or at the end)
                };
                match stored.iter().position(|r| r.covers_saturated(*index)) {
                    Some(k) => id + k,
                    None => stop,
                }
            }
        }
    }

    /// True in a band pass for a triangle the binning pass pushed (it has a band range): it
    /// passed the cull test then, on the same screen positions, so the geometry may skip
    /// the test now.
    #[inline]
    pub fn binned(&self, id: usize) -> bool {
        match &self.pass {
            Pass::Bin { .. } => false,
            Pass::Band { ranges, .. } => ranges.all().get(id).is_some_and(|r| !r.is_empty()),
        }
    }

    /// Whether the screen triangles pushed now need their attributes (texture coordinates
    /// and lighting): `false` in the binning pass once the bins are full, where only their
    /// rows count, so the geometry may skip per-vertex lighting.
    #[inline]
    pub fn attributes(&self) -> bool {
        self.attributes
    }

    /// Hands over one screen triangle of triangle `id`, drawn by `draws[draw]` and carrying
    /// that draw's varyings (an index past the draws makes `render_spans` return
    /// [`Error::BadDrawIndex`](crate::Error::BadDrawIndex), another varying count
    /// [`Error::WrongVaryings`](crate::Error::WrongVaryings), both before
    /// drawing).
    pub fn push<const N: usize>(&mut self, id: usize, draw: u8, tri: &ScreenTriangle<N>)
    where
        ScreenTriangle<N>: Binnable,
    {
        match &mut self.pass {
            Pass::Bin {
                windows,
                bins,
                len,
                bins_full,
                ranges,
                ranges_short,
                rows,
                height,
                triangles,
                draws,
                check,
            } => {
                check.check(draws, draw, N);
                *triangles += 1;
                if !*bins_full {
                    match bins.get_mut(*len) {
                        Some(slot) => {
                            slot.store(draw, tri);
                            *len += 1;
                        }
                        None => {
                            *bins_full = true;
                            self.attributes = false;
                        }
                    }
                }
                note_rows(
                    windows,
                    ranges,
                    ranges_short,
                    *rows,
                    *height,
                    id,
                    rows_of(tri),
                );
            }
            Pass::Band {
                draws,
                band,
                ranges,
                index,
                pixels,
                setups,
                last,
                whole,
                ..
            } => {
                // Which of the id's screen triangles this is, counted before any skip so
                // every band numbers them alike.
                let piece = if last.0 == id {
                    last.1.wrapping_add(1)
                } else {
                    end_range_if_kept(ranges, *last, *whole, *index);
                    *whole = true;
                    0
                };
                *last = (id, piece);
                let key = setup_queue::key(id, piece);
                // Rows r0..r1 against the band's first..end (both ends excluded): a
                // triangle that only touches the band's edge costs no set-up.
                let (first, end) = band.row_range();
                let (r0, r1) = rows_of(tri);
                // What the band above kept for the triangles before this one, in order.
                if key.is_some() && setups.waits_before(key) {
                    *pixels = pixels.saturating_add(resume(draws, setups, band, key, end));
                }
                let goes_on = r1 > end;
                if r1 <= first || r0 >= end || r1 <= r0 {
                    *whole &= !goes_on;
                    return;
                }
                if let Some(d) = draws.get(usize::from(draw)) {
                    // Kept while the triangle goes on below this band.
                    let mut slot = match key {
                        Some(key) => setups.slot(key, draw, goes_on),
                        None => None,
                    };
                    let drawn = d.draw_piece(tri.as_any(), *band, slot.as_deref_mut());
                    *pixels = pixels.saturating_add(drawn);
                    *whole &= !goes_on || slot.is_some_and(|e| e.resumable());
                } else {
                    *whole &= !goes_on;
                }
            }
        }
    }
}

/// Draws, through their draws, what the band above kept resumable for the screen
/// triangles before `key` (all of them with `None`); the pixels written.
fn resume<C: TargetColor>(
    draws: &[&dyn BandDraw<C>],
    setups: &mut SetupQueue<'_>,
    band: &mut Frame<'_, C>,
    key: Option<u32>,
    end: i32,
) -> u32 {
    setups.resume_before(key, end, |e| match draws.get(usize::from(e.draw)) {
        Some(d) => d.resume_piece(e, band),
        None => 0,
    })
}

/// Ends the band range of triangle `last.0` at band `index` when every screen triangle
/// of it that goes on below the band is kept resumable (`whole`): the next bands draw
/// them from the set-up cache, and the geometry need not project the triangle again.
#[inline(always)]
fn end_range_if_kept(ranges: &mut BandRanges<'_>, last: (usize, u32), whole: bool, index: u8) {
    let BandRanges::End(ranges) = ranges else {
        return;
    };
    if !whole || index >= LAST_BAND as u8 {
        return;
    }
    if let Some(r) = ranges.get_mut(last.0) {
        if r.covers_saturated(index) {
            r.end = index + 1;
        }
    }
}

impl<C: TargetColor> MeshSink<'_, '_, '_, C> {
    /// Ends a band pass: the last triangle's range (see [`end_range_if_kept`]), then what
    /// the band above kept and this band has not drawn yet.
    pub(super) fn finish_band(&mut self) {
        if let Pass::Band {
            draws,
            band,
            ranges,
            index,
            pixels,
            setups,
            last,
            whole,
            ..
        } = &mut self.pass
        {
            end_range_if_kept(ranges, *last, *whole, *index);
            *last = (usize::MAX, 0);
            let end = band.row_range().1;
            *pixels = pixels.saturating_add(resume(draws, setups, band, None, end));
        }
    }
}

/// Grows triangle `id`'s band range (and its window groups) by the pixel rows
/// `r0..r1` (`r1` excluded) its screen triangle draws.
#[inline(always)]
fn note_rows(
    windows: &mut Windows,
    ranges: &mut [BandRange],
    ranges_short: &mut bool,
    rows: FrameDivisor,
    height: u32,
    id: usize,
    (r0, r1): (i32, i32),
) {
    // The rasterizer draws rows r0..r1 (r1 excluded) and no other.
    let last_row = height as i32 - 1;
    if r1 <= r0 || r1 <= 0 || r0 > last_row {
        return; // no row of the frame
    }
    let band = |r: i32| rows.div(r.clamp(0, last_row) as u32);
    let (b0, b1) = (band(r0), band(r1 - 1));
    let sat = |b: u32| b.min(LAST_BAND) as u8;
    match ranges.get_mut(id) {
        Some(r) => r.include(sat(b0), sat(b1)),
        None => *ranges_short = true,
    }
    for g in windows.group.div(b0)..=windows.group.div(b1) {
        if let Some(w) = windows.ids.get_mut(g as usize) {
            *w = (w.0.min(id), w.1.max(id));
        }
    }
}

impl<C: TargetColor> MeshSink<'_, '_, '_, C> {
    /// [`push`](Self::push) for a pass that needs the rows only ([`attributes`](Self::attributes)
    /// is `false`): the screen triangle of a draw of `N` varyings, projected without them
    /// (the same positions, so the same rows). Anywhere else it gives up the bins for the
    /// frame (the bands then re-project every triangle: the same pixels).
    pub(crate) fn push_rows<const N: usize>(
        &mut self,
        id: usize,
        draw: u8,
        tri: &ScreenTriangle<0>,
    ) {
        if let Pass::Bin {
            windows,
            bins_full,
            ranges,
            ranges_short,
            rows,
            height,
            triangles,
            draws,
            check,
            ..
        } = &mut self.pass
        {
            check.check(draws, draw, N);
            *triangles += 1;
            *bins_full = true;
            self.attributes = false;
            note_rows(
                windows,
                ranges,
                ranges_short,
                *rows,
                *height,
                id,
                rows_of(tri),
            );
        }
    }
}

#[cfg(test)]
mod tests {
    use super::super::setup_queue::QueueState;
    use super::*;

    #[test]
    fn ranges_grow_and_saturate() {
        let mut r = BandRange::EMPTY;
        assert!(r.is_empty() && !r.covers(0));
        r.include(3, 4);
        r.include(2, 2);
        assert!(r.covers(2) && r.covers(4) && !r.covers(5) && !r.covers(1));
        let mut far = BandRange::EMPTY;
        far.include(254, 254);
        assert!(far.covers(300) && far.covers(254) && !far.covers(253));
    }

    /// In a band pass, `next_wanted(id, end)` is the first id in `id..end` that `wants`
    /// says yes to (ids past the stored ranges are always wanted), or `end`.
    #[test]
    fn next_wanted_is_the_first_wanted_id() {
        use embedded_graphics_core::pixelcolor::Rgb565;
        let mut pixels = [Rgb565::default(); 8];
        let mut band = Frame::new(&mut pixels, 4, 2).expect("a frame");
        let mut ranges = [BandRange::EMPTY; 9];
        for (i, r) in ranges.iter_mut().enumerate() {
            if i % 3 != 1 {
                r.include((i % 4) as u8, (i % 4 + i % 2) as u8);
            }
        }
        for index in 0..6u8 {
            let sink: MeshSink<'_, '_, '_, Rgb565> = MeshSink {
                pass: Pass::Band {
                    window: (0, usize::MAX),
                    draws: &[],
                    band: &mut band,
                    ranges: BandRanges::End(&mut ranges),
                    index,
                    pixels: 0,
                    setups: SetupQueue::new(&mut [], QueueState::default(), index),
                    last: (usize::MAX, 0),
                    whole: false,
                },
                attributes: true,
            };
            for id in 0..13 {
                for end in id..13 {
                    let want = (id..end).find(|&i| sink.wants(i)).unwrap_or(end);
                    assert_eq!(sink.next_wanted(id, end), want, "band {index} {id}..{end}");
                }
            }
        }
    }
}
