//! Silhouette anti-aliasing from depth: a post-pass over each finished band that touches
//! only the pixels at a depth discontinuity, at a few instructions per pixel.
//!
//! **The rule.** Two 4-neighbours `p`, `q` of the frame are *across an edge* when their
//! depths (the window depth of the depth buffer, `0..=65535`) differ by more than
//! `threshold`. A pixel `p` with `k` such neighbours (`E`, `0 <= k <= 4`) becomes, per RGB565
//! channel,
//!
//! `p' = ((4 - k) p + Σ_{q ∈ E} q + 2) >> 2`
//!
//! from the original (unsmoothed) colours: a quarter of each neighbour across the edge, so
//! a one-pixel step between two surfaces becomes a two-pixel ramp (`3/4 a + 1/4 b`,
//! `1/4 a + 3/4 b`). Pixels with no discontinuity are left exactly as drawn: creases (the
//! depth is continuous across them), shading and texture detail keep their pixels, so the
//! frame's error away from silhouettes and overlaps does not grow. Neighbours outside the
//! frame are the pixel itself (no edge at the frame's border). Like any post-pass it
//! cannot restore coverage that was never sampled: a sliver thinner than a pixel stays
//! broken.
//!
//! **Bands.** A pixel needs the row below it, which a band's last row finds only in the next
//! band, so [`EdgeAa`] holds each band's last row back: [`EdgeAa::band`] writes the held row
//! of the previous band (now smoothed) followed by every row of this band but its last,
//! and the frame's last band in full, handed to the caller (to send or hash) in raster
//! order as runs. Fed in order, the bands give the frame a whole-frame
//! pass gives, bit for bit. The state between bands is the previous band's last two rows,
//! colour and depth (8 bytes per column).
//!
//! **Cost.** The scan tests the bits at and above the threshold's highest: four pixels at
//! a time on 32-bit words of two depths (a group whose masked depths, those above and
//! below it and its west and east neighbours' all agree is at no edge: one XOR per word
//! against the group's first word, ORed, and one AND); the pixels of a group that fails,
//! and the first and last pairs of each row, take the same test per pixel against their
//! four neighbours; only those that pass it take the exact rule, and only those at an edge
//! are blended. The colours are not copied: the runs between re-made pixels are slices of
//! the band. Nothing runs in draws that do not call it. Measured by `cargo xtask mcu`
//! (scene `aa_edge` against `cube`, the same draw: 144.5 against 103.2 instructions per
//! drawn pixel on the Cortex-M4F, 1.40x; 243.5 against 176.0 on the Cortex-M0+, 1.38x;
//! the pass scans all 76,800 pixels of the 320 x 240 frame for the cube's 35,485) and
//! against a 16 x 16 supersampled reference by `cargo xtask report` (`docs/report/aa.md`).
//!
//! ```
//! use fixel::prelude::*;
//! use fixel::surface::EdgeAa;
//!
//! // A 4 x 2 frame in two 1-row bands: a near red surface on the left, a far blue one on
//! // the right.
//! let colour = [Rgb565::RED, Rgb565::RED, Rgb565::BLUE, Rgb565::BLUE];
//! let depth = [1000u16, 1000, 60000, 60000];
//! let (mut held_c, mut held_d) = ([Rgb565::BLACK; 8], [0u16; 8]);
//! let mut aa = EdgeAa::new(4, 256, &mut held_c, &mut held_d)?;
//! let mut sent = [Rgb565::BLACK; 8];
//! let mut at = 0;
//! let mut send = |run: &[Rgb565]| {
//!     sent[at..at + run.len()].copy_from_slice(run);
//!     at += run.len();
//!     Ok::<(), fixel::Error>(())
//! };
//! // The first band's only row is held back: nothing to send yet.
//! assert_eq!(aa.band(&colour, &depth, false, &mut send)?, 0);
//! // The last band: the held row, then this one.
//! assert_eq!(aa.band(&colour, &depth, true, &mut send)?, 8);
//! let out = sent;
//! assert_eq!(out[0], Rgb565::RED);
//! // Across the edge: a quarter of the other side.
//! assert_eq!(out[1], Rgb565::new(23, 0, 8));
//! assert_eq!(out[2], Rgb565::new(8, 0, 23));
//! # Ok::<(), fixel::Error>(())
//! ```

use embedded_graphics_core::pixelcolor::raw::{RawData, RawU16};
use embedded_graphics_core::pixelcolor::Rgb565;

use crate::Error;

/// The raw RGB565 value.
#[inline(always)]
fn raw(c: Rgb565) -> u32 {
    u32::from(RawU16::from(c).into_inner())
}

/// Silhouette anti-aliasing of a frame drawn in bands (see the module docs): holds the
/// previous band's last two rows (colour and depth) from one [`band`](Self::band) to the
/// next. One per frame, or [`reset`](Self::reset) between frames.
#[derive(Debug)]
pub struct EdgeAa<'s> {
    width: usize,
    threshold: u16,
    /// Rows `L - 1` and `L` of the previous band (originals), `L` its last.
    colour: &'s mut [Rgb565],
    depth: &'s mut [u16],
    /// How many of those rows hold frame rows (0 before the first band).
    held: usize,
}

/// A row of the band being smoothed, counted from its first (`-1`, `-2`: the held rows).
#[derive(Clone, Copy)]
struct View<'a> {
    width: usize,
    held_c: &'a [Rgb565],
    held_d: &'a [u16],
    colour: &'a [Rgb565],
    depth: &'a [u16],
}

impl<'a> View<'a> {
    #[inline(always)]
    fn row(&self, r: isize) -> (&'a [Rgb565], &'a [u16]) {
        let w = self.width;
        if r < 0 {
            let at = (2 + r) as usize * w;
            (&self.held_c[at..at + w], &self.held_d[at..at + w])
        } else {
            let at = r as usize * w;
            (&self.colour[at..at + w], &self.depth[at..at + w])
        }
    }
}

impl<'s> EdgeAa<'s> {
    /// A pass over rows of `width` pixels (`1..`); pixels whose depths differ by more than
    /// `threshold` (window depth units, `0..=65535`) are across an edge. `colour` and
    /// `depth` hold the two rows kept between bands (`2 width` each, or more). Errors if
    /// `width` is 0 or a buffer is short.
    pub fn new(
        width: u32,
        threshold: u16,
        colour: &'s mut [Rgb565],
        depth: &'s mut [u16],
    ) -> Result<Self, Error> {
        let w = width as usize;
        if w == 0 {
            return Err(Error::BadSize(width));
        }
        for len in [colour.len(), depth.len()] {
            if len < 2 * w {
                return Err(Error::WrongLength {
                    expected: 2 * w,
                    actual: len,
                });
            }
        }
        Ok(EdgeAa {
            width: w,
            threshold,
            colour: &mut colour[..2 * w],
            depth: &mut depth[..2 * w],
            held: 0,
        })
    }

    /// Starts a new frame: the next band is the frame's first.
    pub fn reset(&mut self) {
        self.held = 0;
    }

    /// Pixels [`band`](Self::band) writes for a band of `rows` rows: the held row (after
    /// the first band), then `rows - 1` rows, or all `rows` for the frame's `last` band.
    pub fn out_len(&self, rows: usize, last: bool) -> usize {
        let held = usize::from(self.held > 0);
        (held + rows - usize::from(!last && rows > 0)) * self.width
    }

    /// Smooths the next band of the frame into `out` (at least
    /// [`out_len`](Self::out_len) pixels): [`band`](Self::band) with the pixels copied
    /// there in order. Returns the pixels written.
    pub fn band_into(
        &mut self,
        colour: &[Rgb565],
        depth: &[u16],
        last: bool,
        out: &mut [Rgb565],
    ) -> Result<usize, Error> {
        let rows = colour.len() / self.width;
        let n = self.out_len(rows, last);
        if out.len() < n {
            return Err(Error::WrongLength {
                expected: n,
                actual: out.len(),
            });
        }
        let mut at = 0;
        self.band(colour, depth, last, |r: &[Rgb565]| {
            out[at..at + r.len()].copy_from_slice(r);
            at += r.len();
            Ok::<(), Error>(())
        })
    }

    /// Smooths the next band of the frame, top to bottom: `colour` and `depth` are its
    /// pixels (whole rows, as drawn); `last` says it is the frame's last band. Hands
    /// `emit` the previous band's held last row, smoothed, then this band's rows but its
    /// last (all of them when `last`), in raster order as runs: slices of the band as
    /// drawn between the re-made pixels, each of those a run of one (no copy, no scratch;
    /// a sender streaming into a display's window takes them as they come). Returns how
    /// many pixels it handed on ([`out_len`](Self::out_len)); a new frame starts after a
    /// `last` band. Errors if `colour` is not whole rows or `depth` is not as long
    /// (nothing is handed on), or with `emit`'s error.
    pub fn band<E: From<Error>>(
        &mut self,
        colour: &[Rgb565],
        depth: &[u16],
        last: bool,
        mut emit: impl FnMut(&[Rgb565]) -> Result<(), E>,
    ) -> Result<usize, E> {
        let w = self.width;
        if colour.is_empty() || !colour.len().is_multiple_of(w) {
            return Err(Error::WrongLength {
                expected: (colour.len() / w).max(1) * w,
                actual: colour.len(),
            }
            .into());
        }
        if depth.len() != colour.len() {
            return Err(Error::WrongLength {
                expected: colour.len(),
                actual: depth.len(),
            }
            .into());
        }
        let h = colour.len() / w;
        let n = self.out_len(h, last);
        let view = View {
            width: w,
            held_c: self.colour,
            held_d: self.depth,
            colour,
            depth,
        };
        // Output rows `first..=end` (band rows; -1 is the held row); rows `lo..=bottom`
        // exist.
        let lo = -(self.held as isize);
        let first = lo.max(-1);
        let end = h as isize - if last { 1 } else { 2 };
        let bottom = h as isize - 1;
        let t = self.threshold;
        // A quick test first: pixels whose depth agrees with its four neighbours' in every
        // bit from `2^k` up (`2^k <= threshold + 1`) differ from them by less than `2^k`,
        // so are at no edge; the rest (edges, and the few interior pixels on either side
        // of a multiple of `2^k`) take the exact rule.
        let k = 31 - (u32::from(t) + 1).leading_zeros();
        let mask = !((1u32 << k) - 1) as u16;
        // The same test on 32-bit words of two depths (see [`flat_from`]).
        let m = u32::from(mask) * 0x1_0001;
        for r in first..=end {
            let (c, d) = view.row(r);
            let up = if r > lo { view.row(r - 1).1 } else { d };
            let down = if r < bottom { view.row(r + 1).1 } else { d };
            let (d, up, down) = (&d[..w], &up[..w], &down[..w]);
            let rows = Words {
                d: d.as_chunks::<2>().0,
                up: up.as_chunks::<2>().0,
                down: down.as_chunks::<2>().0,
            };
            // The row as drawn up to each re-made pixel, then that pixel.
            let mut start = 0;
            let mut x = 0;
            while x < w {
                if x % 2 == 0 {
                    x = 2 * rows.flat_from(x / 2, m);
                }
                if may_edge(d, up, down, x, mask, t) {
                    if let Some(q) = smoothed(&view, r, x, lo, bottom, t) {
                        if start < x {
                            emit(&c[start..x])?;
                        }
                        emit(&[q])?;
                        start = x + 1;
                    }
                }
                x += 1;
            }
            if start < w {
                emit(&c[start..])?;
            }
        }
        // Keep this band's last two rows (originals) for the next band.
        if last {
            self.held = 0;
        } else if h >= 2 {
            let at = (h - 2) * w;
            self.colour.copy_from_slice(&colour[at..at + 2 * w]);
            self.depth.copy_from_slice(&depth[at..at + 2 * w]);
            self.held = 2;
        } else {
            self.colour.copy_within(w.., 0);
            self.depth.copy_within(w.., 0);
            self.colour[w..].copy_from_slice(colour);
            self.depth[w..].copy_from_slice(depth);
            self.held = (self.held + 1).min(2);
        }
        Ok(n)
    }
}

/// Whether the pixel at `x` of row `d` (`up` and `down` the rows above and below, all as
/// long; a missing row is `d` itself) may be at an edge: it differs from a 4-neighbour in a
/// bit of `mask` (the bits at and above the threshold's highest) and by more than `t`. Every
/// pixel at an edge passes; [`smoothed`] decides. `x < d.len()`, or false.
#[inline(always)]
fn may_edge(d: &[u16], up: &[u16], down: &[u16], x: usize, mask: u16, t: u16) -> bool {
    let (Some(&p), Some(&n), Some(&s)) = (d.get(x), up.get(x), down.get(x)) else {
        return false;
    };
    let west = if x > 0 { d[x - 1] } else { p };
    let east = d.get(x + 1).copied().unwrap_or(p);
    ((p ^ west) | (p ^ east) | (p ^ n) | (p ^ s)) & mask != 0
        && (p.abs_diff(west) > t || p.abs_diff(east) > t || p.abs_diff(n) > t || p.abs_diff(s) > t)
}

/// A row and the rows above and below it (a missing one is the row itself) as pairs of
/// depths: pair `j` is pixels `2j` and `2j + 1` (an odd row's last pixel is in none).
struct Words<'a> {
    d: &'a [[u16; 2]],
    up: &'a [[u16; 2]],
    down: &'a [[u16; 2]],
}

/// The pair as one word: the first depth in bits 0..16, the second in 16..32.
#[inline(always)]
fn word(pair: [u16; 2]) -> u32 {
    u32::from(pair[0]) | u32::from(pair[1]) << 16
}

impl Words<'_> {
    /// Skips from pair `j` over groups of two pairs (four pixels) at no edge: returns
    /// `i >= j` such that pixels `2j..2i` are at no edge, stopping at a group that may be
    /// at one, at the last two pairs (a group needs the pair after it), or at once when `j`
    /// is 0 (and the pair before it). A group is at no edge when the masked bits (`m`: the
    /// quick test's mask in both halves) of its depths, the depths above and below them and
    /// its west and east neighbours are all the same (then no pixel of it differs from a
    /// 4-neighbour in those bits): one XOR per word against the group's first word, ORed,
    /// and one AND.
    #[inline(always)]
    fn flat_from(&self, mut j: usize, m: u32) -> usize {
        let n = self.d.len().min(self.up.len()).min(self.down.len());
        let (d, up, down) = (&self.d[..n], &self.up[..n], &self.down[..n]);
        if j == 0 || j + 3 > n {
            return j;
        }
        let mut prev = word(d[j - 1]);
        let mut w0 = word(d[j]);
        while j + 3 <= n {
            let w1 = word(d[j + 1]);
            let w2 = word(d[j + 2]);
            // Both halves of `w0 ^ w0.rotate_left(16)`: the group's first two depths
            // differ; `prev ^ w0` in bits 16..: the west neighbour and the second depth;
            // `w2 ^ w0` in bits 0..16: the east neighbour and the first.
            let diff = (w0 ^ w0.rotate_left(16))
                | (w0 ^ w1)
                | (w0 ^ word(up[j]))
                | (w0 ^ word(up[j + 1]))
                | (w0 ^ word(down[j]))
                | (w0 ^ word(down[j + 1]))
                | ((prev ^ w0) >> 16)
                | ((w2 ^ w0) << 16);
            if diff & m != 0 {
                break;
            }
            prev = w1;
            w0 = w2;
            j += 2;
        }
        j
    }
}

/// The pixel at (`x`, band row `r`) by the rule of the module docs, `None` when it has no
/// neighbour across an edge; rows `lo..=bottom` exist (outside them, and outside the row, a
/// neighbour is the pixel itself).
#[cold]
#[inline(never)]
fn smoothed(
    view: &View<'_>,
    r: isize,
    x: usize,
    lo: isize,
    bottom: isize,
    t: u16,
) -> Option<Rgb565> {
    let w = view.width;
    let (c, d) = view.row(r);
    let (p, dp) = (c[x], d[x]);
    let mut k = 0u32;
    let mut sum = [0u32; 3];
    let mut take = |q: Rgb565, dq: u16| {
        if dp.abs_diff(dq) > t {
            let v = raw(q);
            sum[0] += v >> 11;
            sum[1] += (v >> 5) & 63;
            sum[2] += v & 31;
            k += 1;
        }
    };
    if x > 0 {
        take(c[x - 1], d[x - 1]);
    }
    if x + 1 < w {
        take(c[x + 1], d[x + 1]);
    }
    if r > lo {
        let (cn, dn) = view.row(r - 1);
        take(cn[x], dn[x]);
    }
    if r < bottom {
        let (cs, ds) = view.row(r + 1);
        take(cs[x], ds[x]);
    }
    if k == 0 {
        return None;
    }
    let v = raw(p);
    let ch = |s: u32, own: u32| ((4 - k) * own + s + 2) >> 2;
    Some(Rgb565::new(
        ch(sum[0], v >> 11) as u8,
        ch(sum[1], (v >> 5) & 63) as u8,
        ch(sum[2], v & 31) as u8,
    ))
}

#[cfg(test)]
mod tests {
    extern crate std;
    use super::*;
    use embedded_graphics_core::pixelcolor::RgbColor;
    use std::vec;
    use std::vec::Vec;

    /// The frame smoothed whole (one band) and in bands of `rows`, concatenated.
    fn run(c: &[Rgb565], d: &[u16], w: usize, rows: usize) -> Vec<Rgb565> {
        let (mut hc, mut hd) = (vec![Rgb565::BLACK; 2 * w], vec![0u16; 2 * w]);
        let mut aa = EdgeAa::new(w as u32, 100, &mut hc, &mut hd).unwrap();
        let mut all = Vec::new();
        let h = c.len() / w;
        let mut y = 0;
        while y < h {
            let r = rows.min(h - y);
            let last = y + r == h;
            let mut out = vec![Rgb565::BLACK; (r + 1) * w];
            let band = y * w..(y + r) * w;
            let n = aa
                .band_into(&c[band.clone()], &d[band], last, &mut out)
                .unwrap();
            all.extend_from_slice(&out[..n]);
            y += r;
        }
        all
    }

    #[test]
    fn bands_give_the_whole_frame_and_flat_frames_are_untouched() {
        let (w, h) = (7usize, 9usize);
        let mut c = vec![Rgb565::BLACK; w * h];
        let mut d = vec![u16::MAX; w * h];
        assert_eq!(run(&c, &d, w, 2), c);
        // A near white disc-ish blob.
        for y in 0..h {
            for x in 0..w {
                if (x as i32 - 3).pow(2) + (y as i32 - 4).pow(2) <= 6 {
                    c[y * w + x] = Rgb565::WHITE;
                    d[y * w + x] = 1000 + 10 * x as u16;
                }
            }
        }
        let whole = run(&c, &d, w, h);
        assert_ne!(whole, c);
        for rows in 1..h {
            assert_eq!(run(&c, &d, w, rows), whole, "bands of {rows}");
        }
    }

    #[test]
    fn short_buffers_are_refused() {
        let (mut hc, mut hd) = ([Rgb565::BLACK; 8], [0u16; 7]);
        assert!(EdgeAa::new(4, 1, &mut hc, &mut hd).is_err());
        assert!(EdgeAa::new(0, 1, &mut hc, &mut hd).is_err());
        let mut hd = [0u16; 8];
        let mut aa = EdgeAa::new(4, 1, &mut hc, &mut hd).unwrap();
        let mut out = [Rgb565::BLACK; 8];
        let c = [Rgb565::BLACK; 8];
        assert!(aa.band_into(&c[..7], &[0; 7], false, &mut out).is_err());
        assert!(aa.band_into(&c, &[0; 7], false, &mut out).is_err());
        assert!(aa.band_into(&c, &[0; 8], true, &mut out[..7]).is_err());
        assert!(aa.band_into(&[], &[], true, &mut out).is_err());
    }
}
