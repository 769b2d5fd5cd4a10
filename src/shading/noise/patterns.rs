//! Patterns over noise, a structure and then turbulence to perturb it (Perlin, "An Image
//! Synthesizer", SIGGRAPH 1985): marble, wood and granite, each a colour [`Ramp`] indexed by
//! a function of the point.
//!
//! Every pattern reads the point `p` (I16F16 lattice units) and asks an [`Octaves`] policy
//! for its turbulence, so the same pattern draws with a fixed number of octaves or
//! band-limited by the pixel's footprint.

use super::turbulence::Octaves;
use crate::color::rgb888_to_565;
use crate::math::{isqrt_u32, Angle};
use crate::Error;

/// A 256-entry RGB565 colour table: Perlin's "colour spline" ("An Image Synthesizer"), piecewise linear
/// between keys. 512 bytes; patterns borrow it.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Ramp(pub [u16; 256]);

impl Ramp {
    /// Piecewise-linear colours between `keys` (`(position 0..=255, 0xRRGGBB)`), constant
    /// before the first key and after the last.
    ///
    /// # Errors
    /// [`Error::BadMode`] if `keys` is empty or its positions do not increase.
    pub fn from_keys(keys: &[(u8, u32)]) -> Result<Ramp, Error> {
        let mut lut = [0u16; 256];
        Self::fill(keys, |i| i as u8, &mut lut)?;
        Ok(Ramp(lut))
    }

    /// The keys' ramp seen through a sine wave, for marble: entry `i` is the colour at
    /// `(1 + sin(2π i / 256)) / 2` of the ramp, so a phase in turns indexes it directly.
    ///
    /// # Errors
    /// As [`Ramp::from_keys`].
    pub fn sine(keys: &[(u8, u32)]) -> Result<Ramp, Error> {
        let mut lut = [0u16; 256];
        Self::fill(
            keys,
            |i| {
                let s = Angle::from_turns((i as u16) << 8).sin().to_bits(); // I16F16, ±65536
                ((s + 65536) * 255 / 131072) as u8
            },
            &mut lut,
        )?;
        Ok(Ramp(lut))
    }

    fn fill(
        keys: &[(u8, u32)],
        pos: impl Fn(usize) -> u8,
        lut: &mut [u16; 256],
    ) -> Result<(), Error> {
        if keys.is_empty() {
            return Err(Error::BadMode("a colour ramp needs at least one key"));
        }
        if keys.windows(2).any(|w| w[0].0 >= w[1].0) {
            return Err(Error::BadMode("colour ramp key positions must increase"));
        }
        let ch = |c: u32, s: u32| ((c >> s) & 255) as i32;
        for (i, e) in lut.iter_mut().enumerate() {
            let x = i32::from(pos(i));
            let hi = keys.iter().position(|k| i32::from(k.0) >= x);
            let (a, b) = match hi {
                None => (keys[keys.len() - 1], keys[keys.len() - 1]),
                Some(0) => (keys[0], keys[0]),
                Some(h) => (keys[h - 1], keys[h]),
            };
            let span = (i32::from(b.0) - i32::from(a.0)).max(1);
            let t = (x - i32::from(a.0)).clamp(0, span);
            let mix =
                |s: u32| (ch(a.1, s) + ((ch(b.1, s) - ch(a.1, s)) * t + span / 2) / span) as u8;
            *e = rgb888_to_565(mix(16), mix(8), mix(0));
        }
        Ok(())
    }

    /// The colour at `i`.
    #[inline(always)]
    pub fn at(&self, i: u8) -> u16 {
        self.0[usize::from(i)]
    }
}

/// A solid texture: the colour (raw RGB565) at an object-space point.
pub trait Pattern: Copy + core::fmt::Debug {
    /// The colour at `p` (I16F16 lattice units) for a pixel of level of detail `lambda`
    /// (Q8.8 `log2` of its footprint in cells; 0 when the policy does not use it),
    /// turbulence from `octaves`.
    fn color<O: Octaves>(&self, p: [i32; 3], octaves: &O, lambda: i32) -> u16;
}

/// Perlin's marble: `ramp(sin(2π (f x + a · turbulence(p))))`: veins across x, bent by
/// turbulence. The ramp is built with [`Ramp::sine`].
#[derive(Clone, Copy, Debug)]
pub struct Marble<'a> {
    /// Colour per phase (a [`Ramp::sine`]).
    pub ramp: &'a Ramp,
    /// Stripe frequency `f`, turns per lattice cell, I16F16 bits.
    pub freq: i32,
    /// Turbulence amplitude `a`, turns per unit of turbulence, Q8 (`256` = one turn).
    pub amp: i32,
}

impl Pattern for Marble<'_> {
    #[inline(always)]
    fn color<O: Octaves>(&self, p: [i32; 3], octaves: &O, lambda: i32) -> u16 {
        // Low 32 bits of the Q32 product: bits 16..32 are the phase's fraction of a turn.
        let stripe = (p[0].wrapping_mul(self.freq) as u32) >> 16;
        let t = octaves.turbulence(p, lambda); // Q15, 0..2^16
        let bend = (t.wrapping_mul(self.amp) as u32) >> 7; // Q16 turns
        self.ramp.at((stripe.wrapping_add(bend) >> 8) as u8)
    }
}

/// Wood: rings of the distance to the y axis, `r = sqrt(x² + z²)`, pushed outwards by
/// turbulence: `ramp(frac(rings · r + a · turbulence(p)))`. The ramp is one ring's profile.
#[derive(Clone, Copy, Debug)]
pub struct Wood<'a> {
    /// Colour across one ring (index = fraction of the ring, 0..=255).
    pub ramp: &'a Ramp,
    /// Rings per lattice cell of radius, Q8.
    pub rings: i32,
    /// Rings per unit of turbulence, Q8.
    pub amp: i32,
}

impl Pattern for Wood<'_> {
    #[inline(always)]
    fn color<O: Octaves>(&self, p: [i32; 3], octaves: &O, lambda: i32) -> u16 {
        // Q8 coordinates, clamped to ±181 cells so the sum of squares fits u32.
        let q8 = |v: i32| (v >> 8).clamp(-46_340, 46_340).unsigned_abs();
        let (x, z) = (q8(p[0]), q8(p[2]));
        let r = u32::from(isqrt_u32((x * x).saturating_add(z * z))); // Q8 cells
        let t = octaves.turbulence(p, lambda) as u32; // Q15
        let ring = r.wrapping_mul(self.rings as u32) >> 8; // Q8 rings
        let bend = t.wrapping_mul(self.amp as u32) >> 15; // Q8 rings
        self.ramp.at(ring.wrapping_add(bend) as u8)
    }
}

/// Granite (or clouds, with a soft ramp): the turbulence itself through a ramp,
/// `ramp(turbulence(2^s p))`, turbulence 0..1 across the ramp.
#[derive(Clone, Copy, Debug)]
pub struct Granite<'a> {
    /// Colour per turbulence value (0 = 0.0, 255 = 1.0 and above).
    pub ramp: &'a Ramp,
    /// Frequency scale `s` (the grain is `2^s` times finer than the lattice), `0..=8`.
    pub shift: u8,
}

impl Pattern for Granite<'_> {
    #[inline(always)]
    fn color<O: Octaves>(&self, p: [i32; 3], octaves: &O, lambda: i32) -> u16 {
        let s = u32::from(self.shift.min(8));
        let q = p.map(|v| v.wrapping_shl(s));
        let t = octaves.turbulence(q, lambda.saturating_add((s as i32) << 8));
        self.ramp.at((t >> 7).min(255) as u8)
    }
}
