//! Turbulence (Perlin, "An Image Synthesizer", SIGGRAPH 1985):
//! `Σ_{k=0}^{n−1} |noise(2^k p)| / 2^k`, and its
//! band-limited form, where the octaves finer than the pixel are not summed.
//!
//! The classic clamping of procedural textures (Ebert et al., "Texturing and Modeling: A
//! Procedural Approach") truncates the sum at the smallest `k` with `1 / 2^(k+1) <` the pixel size: an
//! octave whose cells are smaller than the pixel's footprint would alias (sparkle, and
//! crawl in animation). [`BandLimit`] does that from the level of detail the span loop
//! computes ([`Fragment::lambda`](crate::shading::Fragment::lambda): `log2` of the pixel's
//! footprint in lattice cells, Q8.8) with two refinements:
//!
//! * the last octave fades in over one octave of footprint instead of popping in;
//! * an octave left out is replaced by its mean, [`ABS_NOISE_MEAN_Q15`]` / 2^k`, which is
//!   what a box filter over many cells converges to. So a view so distant that one pixel
//!   covers many cells gives the flat average colour, not noise and not black.
//!
//! Octaves skipped are not evaluated: band-limiting is also what makes distant solid
//! textures cheap.

/// The most octaves summed ([`turbulence`] clamps `octaves` to it).
pub const MAX_OCTAVES: u32 = 8;

/// The mean of `|noise3|` over space, Q15 (0.2207; measured over 128³ points in
/// `host-tests/tests/noise.rs`, which checks this constant against its f64 reference).
pub const ABS_NOISE_MEAN_Q15: i32 = 7233;

/// `Σ_{k<octaves} |noise3(2^k p)| >> k` (Q15, in `0..2^16`), `p` I16F16 lattice units.
/// Octave `k` scales the raw bits with a wrapping shift, which is exact modulo the noise
/// period (see the [module docs](super)). `octaves` is clamped to [`MAX_OCTAVES`]; 0 gives 0.
#[inline]
pub fn turbulence(p: [i32; 3], octaves: u32) -> i32 {
    let mut sum = 0;
    for k in 0..octaves.min(MAX_OCTAVES) {
        let n = super::noise3(
            p[0].wrapping_shl(k),
            p[1].wrapping_shl(k),
            p[2].wrapping_shl(k),
        );
        sum += n.abs() >> k;
    }
    sum
}

/// How many octaves a band-limited turbulence sums: at most `max_octaves`, and none finer
/// than the pixel's footprint (scaled by `2^-bias`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct BandLimit {
    /// The octaves summed when the pixel is small enough for all of them (`1..=8`).
    pub max_octaves: u8,
    /// Added to `lambda` (Q8.8) before the octave count is taken: positive is blurrier
    /// and cheaper. 0 is the classic truncation rule.
    pub bias: i16,
}

impl BandLimit {
    /// The classic truncation rule with at most `max_octaves` octaves (clamped to `1..=8`).
    pub const fn new(max_octaves: u8) -> BandLimit {
        let m = if max_octaves < 1 {
            1
        } else if max_octaves > MAX_OCTAVES as u8 {
            MAX_OCTAVES as u8
        } else {
            max_octaves
        };
        BandLimit {
            max_octaves: m,
            bias: 0,
        }
    }

    /// The weight of octave `k` (Q8, `0..=256`) for a pixel of level of detail `lambda`
    /// (Q8.8, `log2` of the footprint in lattice cells): `clamp(1 − lambda − k, 0, 1)`,
    /// full for the octaves whose cells are at least as large as the footprint (the classic
    /// truncation) and fading in over the octave before.
    #[inline(always)]
    pub fn weight(&self, lambda: i32, k: u32) -> i32 {
        256i32
            .saturating_sub(lambda.saturating_add(i32::from(self.bias)))
            .saturating_sub((k as i32) << 8)
            .clamp(0, 256)
    }

    /// The band-limited turbulence at `p` (I16F16 lattice units) for a pixel of level of
    /// detail `lambda` (Q8.8): Q15, `0..2^16`. Octave `k` counts `|noise| >> k` times its
    /// [`BandLimit::weight`] `w`, and [`ABS_NOISE_MEAN_Q15`]` >> k` times `1 − w`; octaves
    /// of weight 0 are not evaluated.
    #[inline]
    pub fn turbulence(&self, p: [i32; 3], lambda: i32) -> i32 {
        let mut sum = 0;
        let mut k = 0;
        let max = u32::from(self.max_octaves).min(MAX_OCTAVES);
        while k < max {
            let w = self.weight(lambda, k);
            if w == 0 {
                break;
            }
            let n = super::noise3(
                p[0].wrapping_shl(k),
                p[1].wrapping_shl(k),
                p[2].wrapping_shl(k),
            )
            .abs();
            let v = if w == 256 {
                n
            } else {
                (n * w + ABS_NOISE_MEAN_Q15 * (256 - w)) >> 8
            };
            sum += v >> k;
            k += 1;
        }
        while k < max {
            sum += ABS_NOISE_MEAN_Q15 >> k;
            k += 1;
        }
        sum
    }
}

/// How many octaves of turbulence a pattern sums.
pub trait Octaves: Copy + core::fmt::Debug {
    /// True when the count depends on the pixel (the span loop then computes `lambda`).
    const LOD: bool;
    /// The turbulence at `p` (I16F16 lattice units) for a pixel of level of detail
    /// `lambda` (Q8.8): Q15, `0..2^16`.
    fn turbulence(&self, p: [i32; 3], lambda: i32) -> i32;
}

/// A fixed number of octaves (clamped to `0..=8`), whatever the pixel's size.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Fixed(pub u8);

impl Octaves for Fixed {
    const LOD: bool = false;
    #[inline(always)]
    fn turbulence(&self, p: [i32; 3], _lambda: i32) -> i32 {
        turbulence(p, u32::from(self.0))
    }
}

impl Octaves for BandLimit {
    const LOD: bool = true;
    #[inline(always)]
    fn turbulence(&self, p: [i32; 3], lambda: i32) -> i32 {
        BandLimit::turbulence(self, p, lambda)
    }
}
