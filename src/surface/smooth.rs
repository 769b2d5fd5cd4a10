//! Post-process edge smoothing: anti-aliasing for a frame or band that is already drawn, at
//! a few tens of instructions per pixel, where supersampling is too dear.
//!
//! For each pixel, the luma `Y = 2 r5 + g6 + b5` (0..=156) of it and its four neighbours
//! gives the local contrast `max − min`; below `threshold` the pixel is left alone. On an
//! edge, the second differences across rows (`|Y_n + Y_s − 2 Y|`) and across columns
//! (`|Y_w + Y_e − 2 Y|`) say which way the edge runs; the pixel is then blended with its two
//! neighbours across the edge, `(2 p + a + b) / 4` per RGB565 channel, which turns a
//! staircase step into a two-level ramp. This is a cheap cousin of FXAA: it cannot recover
//! coverage that was never sampled (a sliver thinner than a pixel stays broken), and it
//! softens texture detail that crosses the threshold.
//!
//! In bands, the rows at a band's top and bottom see only their own band (clamped): pass
//! the previous band's last row as `above` to smooth across the seam upward. Measured
//! against 4 x 4 supersampling by `cargo xtask report` (`docs/report/aa.md`); the guide's
//! anti-aliasing chapter says when to use it.

use embedded_graphics_core::pixelcolor::raw::{RawData, RawU16};
use embedded_graphics_core::pixelcolor::Rgb565;

use super::{Frame, RenderTarget};
use crate::Error;

#[inline(always)]
fn raw(c: Rgb565) -> u32 {
    u32::from(RawU16::from(c).into_inner())
}

#[inline(always)]
fn luma(v: u32) -> i32 {
    (2 * (v >> 11) + ((v >> 5) & 63) + (v & 31)) as i32
}

/// `(2 p + a + b) / 4` per channel, rounded.
#[inline(always)]
fn blend(p: u32, a: u32, b: u32) -> Rgb565 {
    let ch = |s: u32, m: u32| ((2 * ((p >> s) & m) + ((a >> s) & m) + ((b >> s) & m) + 2) >> 2) & m;
    Rgb565::new(ch(11, 31) as u8, ch(5, 63) as u8, ch(0, 31) as u8)
}

/// Smooths the edges of `frame` in place (see the module docs); `above` is the row above
/// the frame's first one (the previous band's last row), if any, and `scratch` holds one
/// row (at least the frame's width) for the original of the previous row. `threshold`:
/// the luma contrast (0..=156) below which a pixel is left alone; 16 to 32 suits most
/// scenes. Errors if `scratch` or `above` is shorter than a row.
pub fn smooth_edges(
    frame: &mut Frame<'_, Rgb565>,
    above: Option<&[Rgb565]>,
    scratch: &mut [Rgb565],
    threshold: u8,
) -> Result<(), Error> {
    let (w, h) = (frame.width() as usize, frame.height() as usize);
    if scratch.len() < 2 * w {
        return Err(Error::WrongLength {
            expected: 2 * w,
            actual: scratch.len(),
        });
    }
    if let Some(a) = above {
        if a.len() < w {
            return Err(Error::WrongLength {
                expected: w,
                actual: a.len(),
            });
        }
    }
    let t = i32::from(threshold);
    let (prev, cur) = scratch.split_at_mut(w);
    let cur = &mut cur[..w];
    let px = frame.pixels_mut();
    // `prev`: the original row above the current one; `cur`: the original current row.
    match above {
        Some(a) => prev.copy_from_slice(&a[..w]),
        None => prev.copy_from_slice(&px[..w]),
    }
    for y in 0..h {
        let row = y * w;
        cur.copy_from_slice(&px[row..row + w]);
        let below = if y + 1 < h { row + w } else { row };
        for x in 0..w {
            let p = raw(cur[x]);
            let (n, s) = (raw(prev[x]), raw(px[below + x]));
            let (wv, ev) = (raw(cur[x.saturating_sub(1)]), raw(cur[(x + 1).min(w - 1)]));
            let (lp, ln, ls, lw, le) = (luma(p), luma(n), luma(s), luma(wv), luma(ev));
            let hi = lp.max(ln).max(ls).max(lw).max(le);
            let lo = lp.min(ln).min(ls).min(lw).min(le);
            if hi - lo < t {
                continue;
            }
            // A horizontal edge changes across rows: blend with the pixels above and below.
            px[row + x] = if (ln + ls - 2 * lp).abs() >= (lw + le - 2 * lp).abs() {
                blend(p, n, s)
            } else {
                blend(p, wv, ev)
            };
        }
        prev.copy_from_slice(cur);
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use embedded_graphics_core::pixelcolor::RgbColor;

    #[test]
    fn flat_areas_are_untouched_and_steps_become_ramps() {
        let mut px = [Rgb565::BLACK; 16];
        let mut frame = Frame::new(&mut px, 4, 4).unwrap();
        let mut scratch = [Rgb565::BLACK; 8];
        smooth_edges(&mut frame, None, &mut scratch, 16).unwrap();
        assert!(frame.pixels().iter().all(|&c| c == Rgb565::BLACK));
        // A vertical black-white step: the pixels next to it are blended.
        let mut px = [Rgb565::BLACK; 16];
        for y in 0..4 {
            for x in 2..4 {
                px[y * 4 + x] = Rgb565::WHITE;
            }
        }
        let mut frame = Frame::new(&mut px, 4, 4).unwrap();
        smooth_edges(&mut frame, None, &mut scratch, 16).unwrap();
        let p = frame.pixels();
        assert!(p[1] != Rgb565::BLACK && p[1] != Rgb565::WHITE, "{:?}", p[1]);
        assert_eq!(p[0], Rgb565::BLACK);
        assert!(smooth_edges(&mut frame, None, &mut scratch[..7], 16).is_err());
    }
}
