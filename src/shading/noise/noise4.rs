//! Gradient noise in 4D, for animation: a solid texture that changes shape over time is
//! a function of `(x, y, z, t)`. (A texture of the plane, like the flame, needs only 3D:
//! time is its third axis; a solid texture needs the fourth.)
//!
//! The same construction as [`noise3`](super::noise3), one dimension up: the lattice
//! hash is Perlin's chained permutation (`p[p[p[p[X] + Y] + Z] + W]` at each of the 16
//! corners of the cell), the 32 gradients are the midpoints of the edges of the 4-cube
//! (three components ±1, one 0, in Gustavson's order: `hash & 31`, the zero at `x`, `y`,
//! `z` or `w` for `hash >> 3 = 0, 1, 2, 3`, the signs of the other three from bits 2, 1,
//! 0), and the weights are the quintic fade. A dot product is a sum of three offsets: no
//! multiply.
//!
//! # Formats
//! Coordinates as [`noise3`](super::noise3)'s: I16F16 bits in lattice units, any `i32`,
//! period [`PERIOD`](super::PERIOD) on every axis; the result is Q15 (`32768` = 1.0), 0 at
//! every lattice point; measured range −1.22..1.28 (`host-tests/tests/noise4.rs`,
//! `noise4_extremes`), ±3 proven; within 9.2 Q15 LSB of the f64 noise (budget 11).
//!
//! # Cost
//! One [`noise4`] call: **417 instructions on Cortex-M4F, 574 on Cortex-M0+** (exact
//! QEMU counts, firmware bin `noise4_cost`, loop included), 1.9 and 2.0 times a
//! [`noise3`](super::noise3) call (16 corners instead of 8).
//!
//! ```
//! use fixel::shading::noise::{noise4, turbulence4};
//! assert_eq!(noise4(1 << 16, 2 << 16, -3 << 16, 9 << 16), 0);
//! // A point moving through time: w = t · speed.
//! let p = [0x1_8000, 0x0_4000, 0x2_C000];
//! let frames: Vec<i32> = (0..4).map(|i| noise4(p[0], p[1], p[2], i * 0x2000)).collect();
//! assert!(frames.windows(2).all(|f| (f[0] - f[1]).abs() < 16_000)); // smooth in time
//! assert!((0..65_536).contains(&turbulence4([p[0], p[1], p[2], 0x4000], 4)));
//! ```

use super::{fade_q14, turbulence::MAX_OCTAVES, PERM};

/// `PERM[i mod 256]`.
#[inline(always)]
fn perm(i: u32) -> u32 {
    u32::from(PERM[(i & 255) as usize])
}

/// The 4-cube edge gradient `hash & 31` dotted with the offset (Q15 each, `|·| <= 32768`):
/// `|result| <= 98304`.
#[inline(always)]
fn grad4(hash: u32, x: i32, y: i32, z: i32, w: i32) -> i32 {
    // One arm per gradient (a jump table): no multiply, no branch on the signs.
    match hash & 31 {
        0 => y + z + w,
        1 => y + z - w,
        2 => y - z + w,
        3 => y - z - w,
        4 => -y + z + w,
        5 => -y + z - w,
        6 => -y - z + w,
        7 => -y - z - w,
        8 => x + z + w,
        9 => x + z - w,
        10 => x - z + w,
        11 => x - z - w,
        12 => -x + z + w,
        13 => -x + z - w,
        14 => -x - z + w,
        15 => -x - z - w,
        16 => x + y + w,
        17 => x + y - w,
        18 => x - y + w,
        19 => x - y - w,
        20 => -x + y + w,
        21 => -x + y - w,
        22 => -x - y + w,
        23 => -x - y - w,
        24 => x + y + z,
        25 => x + y - z,
        26 => x - y + z,
        27 => x - y - z,
        28 => -x + y + z,
        29 => -x + y - z,
        30 => -x - y + z,
        _ => -x - y - z,
    }
}

/// `a + (b − a) · w`, Q14 weight; `|a|, |b| <= 98304`, so `(b − a) / 2 · w < 2^31`.
#[inline(always)]
fn lerp(a: i32, b: i32, w: i32) -> i32 {
    a + ((((b - a) >> 1) * w) >> 13)
}

/// The blend along `w` of the two corners whose hash prefix is `h` (offsets `x, y, z`
/// and `w` from the low corner).
#[inline(always)]
fn along_w(h: u32, x: i32, y: i32, z: i32, w: i32, fw: i32) -> i32 {
    let g0 = grad4(perm(h), x, y, z, w);
    let g1 = grad4(perm(h + 1), x, y, z, w - 32768);
    lerp(g0, g1, fw)
}

/// The blend along `z` then `w` of the four corners below prefix `h`.
#[inline(always)]
fn along_z(h: u32, cw: u32, x: i32, y: i32, z: i32, w: i32, f: [i32; 4]) -> i32 {
    let a = along_w(perm(h) + cw, x, y, z, w, f[3]);
    let b = along_w(perm(h + 1) + cw, x, y, z - 32768, w, f[3]);
    lerp(a, b, f[2])
}

/// The blend along `y`, `z`, `w` of the eight corners below prefix `h`.
#[inline(always)]
fn along_y(h: u32, c: [u32; 4], x: i32, o: [i32; 4], f: [i32; 4]) -> i32 {
    let a = along_z(perm(h) + c[2], c[3], x, o[1], o[2], o[3], f);
    let b = along_z(perm(h + 1) + c[2], c[3], x, o[1] - 32768, o[2], o[3], f);
    lerp(a, b, f[1])
}

/// Gradient noise at `(x, y, z, w)` (I16F16 bits, lattice units; any `i32`): Q15, 0 at
/// every lattice point, period 256 cells on each axis, smooth between cells. Never panics;
/// no overflow for any input.
#[inline]
pub fn noise4(x: i32, y: i32, z: i32, w: i32) -> i32 {
    let cell = |c: i32| ((c >> 16) & 255) as u32;
    let c = [cell(x), cell(y), cell(z), cell(w)];
    let f = [x, y, z, w].map(|v| v as u32 & 0xFFFF);
    let fw = f.map(fade_q14);
    // Offsets from the low corner (Q15, 0..32767); the high corner's are 32768 less.
    let o = f.map(|v| (v >> 1) as i32);
    // Chained hash p[p[p[p[X + dx] + Y + dy] + Z + dz] + W + dw], each prefix computed once
    // where it is used (30 table reads instead of 64), blended w innermost so few values
    // are live at a time. Cells are masked to 0..=255, so every sum stays under 512.
    let a = along_y(perm(c[0]) + c[1], c, o[0], o, fw);
    let b = along_y(perm(c[0] + 1) + c[1], c, o[0] - 32768, o, fw);
    lerp(a, b, fw[0])
}

/// `Σ_{k<octaves} |noise4(2^k p)| >> k` (Q15, non-negative, below `2^17`: at most twice
/// the largest `|noise4|`, 83,694; as
/// [`turbulence`](fn@super::turbulence) one dimension up): animated turbulence, `p[3]` the
/// time axis. `octaves` is clamped to 8; 0 gives 0.
#[inline]
pub fn turbulence4(p: [i32; 4], octaves: u32) -> i32 {
    let mut sum = 0;
    for k in 0..octaves.min(MAX_OCTAVES) {
        let q = p.map(|v| v.wrapping_shl(k));
        sum += noise4(q[0], q[1], q[2], q[3]).abs() >> k;
    }
    sum
}

/// Octaves of 4D turbulence at time `t`: any [`Pattern`](super::Pattern) drawn with it
/// changes shape over time, where a 3D turbulence could only move it. `t` is the fourth
/// noise coordinate (I16F16 lattice units: `t = seconds · speed`); `octaves` as
/// [`turbulence4`], the sum clamped to `0..2^16` (the [`Octaves`](super::Octaves)
/// contract; it passes 2.0 only near the rare extremes of the noise).
///
/// ```
/// use fixel::shading::noise::{Animated, Octaves, Pattern, Ramps};
/// let ramps = Ramps::new()?;
/// let p = [0x1_8000, 0x0_4000, 0x2_C000];
/// // The same point of a marble, a quarter of a cell of time apart.
/// let a = ramps.marble().color(p, &Animated { octaves: 5, t: 0 }, 0);
/// let b = ramps.marble().color(p, &Animated { octaves: 5, t: 0x4000 }, 0);
/// assert_eq!(Animated { octaves: 5, t: 0 }.turbulence(p, 0),
///            fixel::shading::noise::turbulence4([p[0], p[1], p[2], 0], 5));
/// # let _ = (a, b);
/// # Ok::<(), fixel::Error>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Animated {
    /// Octaves summed (clamped to 8).
    pub octaves: u8,
    /// Time: the fourth noise coordinate, I16F16 lattice units.
    pub t: i32,
}

impl super::Octaves for Animated {
    const LOD: bool = false;
    #[inline(always)]
    fn turbulence(&self, p: [i32; 3], _lambda: i32) -> i32 {
        turbulence4([p[0], p[1], p[2], self.t], u32::from(self.octaves)).min(65_535)
    }
}
