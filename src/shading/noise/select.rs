//! Composition by selection: one of two solid textures at each point, chosen by a third
//! noise with a smooth threshold (the "select" of procedural texturing, beside the
//! "multiply" of [`SolidTimesTexture`](super::SolidTimesTexture)). Veins of one marble
//! through another, patches of moss on granite, clouds over a sky.
//!
//! The selector is [`noise3`] at `2^shift · p + offset` (a noise of its own scale, moved
//! far from the patterns' so it does not correlate with them). Its value `n` (Q15) gives
//! the weight of `b`:
//!
//! ```text
//! w = smoothstep((n − (threshold − width/2)) / width)      (3t² − 2t³, t clamped to 0..1)
//! colour = a · (1 − w) + b · w                              (per RGB565 channel)
//! ```
//!
//! Where `w` is 0 or 1 only one pattern is evaluated, so a select costs one noise call plus
//! the pattern it shows, and both patterns only in the transition band.

use super::noise3;
use super::patterns::Pattern;
use super::turbulence::Octaves;
use crate::texture::lerp565;
use crate::Error;

/// A selector offset of `(97.3, 41.7, 163.1)` cells (I16F16): far from the patterns' own
/// noise, so the selection does not follow their veins.
pub const SELECT_OFFSET: [i32; 3] = [0x61_4CCD, 0x29_B333, 0xA3_1999];

/// Pattern `a` where the selector noise is below the threshold, `b` above it, blended
/// smoothly across `width` (see the module docs). A [`Pattern`] itself, so it draws
/// through [`SolidShader`](super::SolidShader), [`LitSolid`](super::LitSolid) and
/// [`SolidTimesTexture`](super::SolidTimesTexture), and nests.
///
/// ```
/// use fixel::shading::noise::{Fixed, Pattern, Ramps, Select, SELECT_OFFSET};
/// let ramps = Ramps::new()?;
/// // Granite, and marble where the selector noise passes 0.1, blended over ±0.1.
/// let s = Select::new(ramps.granite(), ramps.marble(), 3277, 6554, 0, SELECT_OFFSET)?;
/// let p = [0x1_8000, 0x0_4000, 0x2_C000];
/// let (a, b) = (ramps.granite().color(p, &Fixed(4), 0), ramps.marble().color(p, &Fixed(4), 0));
/// match s.weight(p) {
///     0 => assert_eq!(s.color(p, &Fixed(4), 0), a),
///     256 => assert_eq!(s.color(p, &Fixed(4), 0), b),
///     _ => {}
/// }
/// // A width of 0 is refused where it enters.
/// assert!(Select::new(ramps.granite(), ramps.marble(), 0, 0, 0, SELECT_OFFSET).is_err());
/// # Ok::<(), fixel::Error>(())
/// ```
#[derive(Clone, Copy, Debug)]
pub struct Select<A, B> {
    a: A,
    b: B,
    threshold: i32,
    width: i32,
    /// `2^32 / width`: the blend needs no division per pixel.
    recip: u64,
    shift: u8,
    offset: [i32; 3],
}

impl<A: Pattern, B: Pattern> Select<A, B> {
    /// `a` below `threshold`, `b` above it (selector noise in Q15, `-32768..=32768`),
    /// blended across `width` (Q15, `1..=65536`: from a hard edge to the whole noise
    /// range). The selector is the noise at `2^shift · p + offset` (`shift` in `0..=8`,
    /// `offset` in I16F16 lattice units; [`SELECT_OFFSET`] is a good choice).
    ///
    /// # Errors
    /// [`Error::BadMode`] for a threshold, width or shift out of range.
    pub fn new(
        a: A,
        b: B,
        threshold: i32,
        width: i32,
        shift: u8,
        offset: [i32; 3],
    ) -> Result<Self, Error> {
        if !(-32768..=32768).contains(&threshold) {
            return Err(Error::BadMode(
                "select threshold must be -32768..=32768 (Q15 noise)",
            ));
        }
        if !(1..=65536).contains(&width) {
            return Err(Error::BadMode("select width must be 1..=65536 (Q15)"));
        }
        if shift > 8 {
            return Err(Error::BadMode("select shift must be 0..=8"));
        }
        Ok(Select {
            a,
            b,
            threshold,
            width,
            recip: (1u64 << 32) / width as u64,
            shift,
            offset,
        })
    }

    /// The weight of `b` at `p` (I16F16 lattice units), Q8 (`0..=256`).
    #[inline(always)]
    pub fn weight(&self, p: [i32; 3]) -> u32 {
        let s = u32::from(self.shift);
        let q: [i32; 3] =
            core::array::from_fn(|i| p[i].wrapping_shl(s).wrapping_add(self.offset[i]));
        let n = noise3(q[0], q[1], q[2]);
        let d = n - (self.threshold - self.width / 2);
        if d <= 0 {
            return 0;
        }
        if d >= self.width {
            return 256;
        }
        // t = d / width in Q16, 0..65536 (d < width <= 2^16, recip <= 2^32: the product
        // fits 48 bits).
        let t = ((d as u64 * self.recip) >> 16).min(65536) as i64;
        // smoothstep 3t² − 2t³ in Q16, then Q8.
        let t2 = (t * t) >> 16;
        let w = (t2 * (3 * 65536 - 2 * t)) >> 16;
        ((w + 128) >> 8) as u32
    }
}

impl<A: Pattern, B: Pattern> Pattern for Select<A, B> {
    #[inline(always)]
    fn color<O: Octaves>(&self, p: [i32; 3], octaves: &O, lambda: i32) -> u16 {
        match self.weight(p) {
            0 => self.a.color(p, octaves, lambda),
            256 => self.b.color(p, octaves, lambda),
            w => lerp565(
                self.a.color(p, octaves, lambda),
                self.b.color(p, octaves, lambda),
                w,
            ),
        }
    }
}
