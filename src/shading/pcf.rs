//! Shadow-map filters: how many map texels a lookup compares against, and how their
//! results are weighted into one lit fraction.
//!
//! Inputs, shared by all filters (see [`shadow`](super::shadow) for where they come from):
//!
//! * `s, t`: the point's position on the map, normalized Q12.20 (`1 << 20` = the whole
//!   map; `t = 0` at row 0), already known to be inside `[0, 1)`;
//! * `d`: the point's depth from the light with the bias subtracted, window depth units
//!   with 4 fraction bits (Q16.4: `16` = one 16-bit depth step).
//!
//! A tap is lit when `d <= texel * 16` (`GL_LEQUAL` against the stored depth). The result
//! is the lit fraction in Q8 (`0..=256`). Taps outside the map clamp to its edge
//! (`CLAMP_TO_EDGE`).
//!
//! | filter | taps | weights | bias slope it needs (texels) |
//! |---|---|---|---|
//! | [`SingleTap`] | the texel under the point | 1 | 0.5 |
//! | [`Pcf2x2`] | the 2 x 2 texels around the point | bilinear, 8-bit (GL `sampler2DShadow` with `LINEAR`) | 1 |
//! | [`Pcf3x3`] | the 3 x 3 texels centred on the texel under the point | 1/9 each | 1.5 |

use crate::texture::ShadowMap;

/// A shadow-map filter: the lit fraction of one point.
pub trait ShadowFilter: Copy + core::fmt::Debug + Default + 'static {
    /// Distance from the point to its farthest tap, in texels per axis (what the
    /// slope-scaled bias must cover): 0.5, 1 or 1.5, as Q8.
    const REACH_Q8: i32;
    /// Name for reports.
    const NAME: &'static str;
    /// Lit fraction, Q8 `0..=256`, of the point `(s, t)` (Q12.20, inside the map) at
    /// biased depth `d` (Q16.4).
    fn lit(map: &ShadowMap<'_>, s: i32, t: i32, d: i32) -> u16;
}

/// One compare against the texel under the point: hard, aliased edges; the cheapest.
#[derive(Clone, Copy, Debug, Default)]
pub struct SingleTap;

/// Percentage-closer filtering over the 2 x 2 texels around the point, bilinearly weighted
/// (8-bit weights), as GL's `sampler2DShadow` with `LINEAR`: smooth edges one texel wide.
#[derive(Clone, Copy, Debug, Default)]
pub struct Pcf2x2;

/// Percentage-closer filtering over the 3 x 3 texels centred on the point's texel, equal
/// weights: softer, wider edges (ten levels), no weights to compute.
#[derive(Clone, Copy, Debug, Default)]
pub struct Pcf3x3;

/// 1 when the tap at `(x, y)` lights a point at depth `d` (Q16.4), else 0.
#[inline(always)]
fn tap(map: &ShadowMap<'_>, x: i32, y: i32, d: i32) -> u32 {
    u32::from(d <= i32::from(map.fetch_clamped(x, y)) << 4)
}

impl ShadowFilter for SingleTap {
    const REACH_Q8: i32 = 128;
    const NAME: &'static str = "single tap";
    #[inline(always)]
    fn lit(map: &ShadowMap<'_>, s: i32, t: i32, d: i32) -> u16 {
        // The point is inside the map: no clamp.
        let sh = 20 - map.log2_size();
        u16::from(d <= i32::from(map.fetch_wrapped(s >> sh, t >> sh)) << 4) << 8
    }
}

impl ShadowFilter for Pcf2x2 {
    const REACH_Q8: i32 = 256;
    const NAME: &'static str = "PCF 2x2 bilinear";
    #[inline(always)]
    fn lit(map: &ShadowMap<'_>, s: i32, t: i32, d: i32) -> u16 {
        // Texel units with 8 fraction bits, minus half a texel: texel centres at i + 0.5.
        let sh = 12 - map.log2_size();
        let (u, v) = ((s >> sh) - 128, (t >> sh) - 128);
        let (x, y, fx, fy) = (u >> 8, v >> 8, (u & 255) as u32, (v & 255) as u32);
        let inner = (1 << map.log2_size()) - 2;
        let [b00, b10, b01, b11] = if (x as u32) <= inner && (y as u32) <= inner {
            // All four taps inside the map: no clamps.
            let t = |x, y| u32::from(d <= i32::from(map.fetch_wrapped(x, y)) << 4);
            [t(x, y), t(x + 1, y), t(x, y + 1), t(x + 1, y + 1)]
        } else {
            [
                tap(map, x, y, d),
                tap(map, x + 1, y, d),
                tap(map, x, y + 1, d),
                tap(map, x + 1, y + 1, d),
            ]
        };
        let top = b00 * (256 - fx) + b10 * fx;
        let bottom = b01 * (256 - fx) + b11 * fx;
        ((top * (256 - fy) + bottom * fy) >> 8) as u16
    }
}

/// `k * 256 / 9` rounded, for `k` lit taps of nine.
const NINTHS: [u16; 10] = [0, 28, 57, 85, 114, 142, 171, 199, 228, 256];

impl ShadowFilter for Pcf3x3 {
    const REACH_Q8: i32 = 384;
    const NAME: &'static str = "PCF 3x3";
    #[inline(always)]
    fn lit(map: &ShadowMap<'_>, s: i32, t: i32, d: i32) -> u16 {
        let sh = 20 - map.log2_size();
        let (x, y) = (s >> sh, t >> sh);
        let mut n = 0usize;
        let inner = (1 << map.log2_size()) - 3;
        if ((x - 1) as u32) <= inner && ((y - 1) as u32) <= inner {
            // All nine taps inside the map: no clamps.
            for dy in -1..=1 {
                for dx in -1..=1 {
                    n += usize::from(d <= i32::from(map.fetch_wrapped(x + dx, y + dy)) << 4);
                }
            }
        } else {
            for dy in -1..=1 {
                for dx in -1..=1 {
                    n += tap(map, x + dx, y + dy, d) as usize;
                }
            }
        }
        NINTHS.get(n).copied().unwrap_or(256)
    }
}
