//! An animated flame: a flame shape in the plane, `(1 − y/h) ·
//! flame_colour(|x/b|)`, set in motion by turbulence over 3D + time,
//! `flame_colour(|x/b| + turbulence(x, t))`.
//!
//! Here the plane point enters as `(x, y)` in Q16 flame units (`x` across, `−1..1` is the
//! flame's width `2b`; `y` up, `0..1` its height `h`), time `t` in Q16 seconds. The
//! turbulence is evaluated at `(2x, 2y − rise·t, churn·t)`: the pattern rises and changes
//! shape over time (time as the third noise coordinate: "3D + time" rather than 4D noise).
//! The colour argument is `|x| + y/2 + gain · (turbulence − mid)` (the flame narrows
//! upwards) and the height fade `1 − y + gain · (turbulence − mid) / 2`, so tongues of
//! flame lick upwards and sideways.

use super::patterns::Ramp;
use super::turbulence::turbulence;
use crate::color::modulate_scalar;
use crate::shading::{Fragment, Shader};

/// Flame colour keys along `|x/b| + turbulence` (white-yellow core to black air).
pub const FLAME_KEYS: [(u8, u32); 6] = [
    (0, 0xFF_F8_D0),
    (50, 0xFF_E0_60),
    (100, 0xFF_A0_20),
    (150, 0xE0_40_10),
    (200, 0x70_10_08),
    (255, 0x00_00_00),
];

/// Rise speed of the pattern: lattice cells per second (Q16): 1.5.
pub const FLAME_RISE: i32 = 0x1_8000;
/// Churn: lattice cells of the time axis per second (Q16): 0.6.
pub const FLAME_CHURN: i32 = 0x0_999A;
/// Turbulence gain on the colour argument (Q8): 0.9.
pub const FLAME_GAIN: i32 = 230;

/// The turbulence level that leaves the flame's shape in place (Q15): about the mean of
/// five octaves, so the turbulence bends the flame both ways.
pub const FLAME_TURB_MID: i32 = 14_000;

/// The flame's colour (raw RGB565) at `(x, y)` (Q16 flame units) and time `t` (Q16
/// seconds), with `octaves` of turbulence (clamped to 8) and colours from `ramp` (a
/// [`Ramp::from_keys`] of [`FLAME_KEYS`] or any other). Black outside the flame.
#[inline]
pub fn flame(ramp: &Ramp, x: i32, y: i32, t: i32, octaves: u32) -> u16 {
    // Turbulence point, lattice units (I16F16): 2 cells across the width, 2 up the height.
    let rise = ((i64::from(t) * i64::from(FLAME_RISE)) >> 16) as i32;
    let churn = ((i64::from(t) * i64::from(FLAME_CHURN)) >> 16) as i32;
    let p = [
        x.wrapping_mul(2),
        y.wrapping_mul(2).wrapping_sub(rise),
        churn,
    ];
    flame_color(ramp, x, y, turbulence(p, octaves))
}

/// The flame's colour (raw RGB565) at `(x, y)` (Q16 flame units) for the turbulence `turb`
/// there (Q15): shared by [`flame`] and the flame from baked layers.
#[inline(always)]
pub(super) fn flame_color(ramp: &Ramp, x: i32, y: i32, turb: i32) -> u16 {
    let bend = ((turb - FLAME_TURB_MID) * FLAME_GAIN) >> 7; // Q16, signed
                                                            // Colour argument |x/b| + y/2 + gain·(turbulence − mid), 0..1 across the ramp: the
                                                            // flame narrows upwards.
    let arg = x.unsigned_abs().min(1 << 17) as i32 + (y.clamp(0, 1 << 17) >> 1) + bend;
    let index = (arg >> 8).clamp(0, 255) as u8;
    // Height fade 1 − y'/h with the height pushed by the turbulence too.
    let fade = (65_536 - y.clamp(-65_536, 1 << 17) + (bend >> 1)).clamp(0, 65_536);
    modulate_scalar(ramp.at(index), (fade >> 8) as u16)
}

/// [`flame`] as a shader over a quad: varyings `x, y` (Q16 flame units).
#[derive(Clone, Copy, Debug)]
pub struct FlameShader<'a> {
    /// Colours along the flame's argument.
    pub ramp: &'a Ramp,
    /// Time, Q16 seconds.
    pub t: i32,
    /// Octaves of turbulence.
    pub octaves: u8,
}

impl Shader for FlameShader<'_> {
    type Varyings = [i32; 2];
    type Triangle = ();
    fn triangle(&self, _: &mut [[i32; 2]; 3]) {}
    #[inline(always)]
    fn shade(&self, f: &Fragment<[i32; 2], ()>) -> Option<u16> {
        let [x, y] = f.varyings;
        Some(flame(self.ramp, x, y, self.t, u32::from(self.octaves)))
    }
}
