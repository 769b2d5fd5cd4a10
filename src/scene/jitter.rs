//! Sub-pixel sample patterns and the camera offsets that render them: stochastic sampling
//! with jitter (Cook, "Stochastic Sampling in Computer Graphics", ACM TOG 1986) and the
//! accumulation buffer (Haeberli & Akeley, SIGGRAPH 1990).
//!
//! A [`SamplePattern`] gives `n` sample positions inside the pixel, as offsets from its
//! centre in `(−1/2, 1/2)` pixel (I16F16). Rendering the frame once per offset with
//! [`jittered`] (the projection shifted by that many pixels) and averaging the frames in an
//! [`Accumulator`](crate::surface::Accumulator) is supersampling with that pattern, in any
//! RAM that holds one accumulation band: `RotatedGrid4` catches near-horizontal and
//! near-vertical edges four levels each with four samples; `Jittered` spreads the aliasing
//! into noise. Frames stay deterministic: the jitter comes from a fixed seed.
//!
//! ```
//! use fixel::math::{fx, Fx};
//! use fixel::scene::SamplePattern;
//!
//! let mut at = [[Fx::ZERO; 2]; 16];
//! let n = SamplePattern::Jittered { n: 16, seed: 7 }.offsets(&mut at)?;
//! assert_eq!(n, 16);
//! assert!(at.iter().all(|o| o.iter().all(|c| c.abs() < fx(0.5))));
//! # Ok::<(), fixel::Error>(())
//! ```

use crate::geometry::Viewport;
use crate::math::{Fx, Mat4};
use crate::Error;

/// Where the samples of a pixel are.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SamplePattern {
    /// A regular `k x k` grid (`k` in `1..=16`): the centres of the sub-pixel cells.
    Grid(u8),
    /// The four-sample rotated grid (RGSS): offsets `(±1/8, ±3/8)` and `(±3/8, ∓1/8)`, so
    /// no two samples share a row or a column.
    RotatedGrid4,
    /// `n` samples (a perfect square up to 256, else rounded down to one), one uniformly
    /// random point in each cell of a `√n x √n` grid (stratified), from `seed`.
    Jittered {
        /// Sample count.
        n: u16,
        /// Random seed (the same seed gives the same frames).
        seed: u32,
    },
}

/// A small, fixed-seed generator (xorshift32): enough for sample jitter.
fn next(state: &mut u32) -> u32 {
    let mut x = *state;
    x ^= x << 13;
    x ^= x >> 17;
    x ^= x << 5;
    *state = x;
    x
}

impl SamplePattern {
    /// Samples of the pattern.
    pub fn count(&self) -> usize {
        match *self {
            SamplePattern::Grid(k) => usize::from(k).pow(2),
            SamplePattern::RotatedGrid4 => 4,
            SamplePattern::Jittered { n, .. } => {
                let k = (n.min(256) as u32).isqrt() as usize;
                k * k
            }
        }
    }

    /// Writes the sample offsets from the pixel centre (I16F16 pixels, each in
    /// `(−1/2, 1/2)`) into `out` and returns how many. Errors if `out` is shorter than
    /// [`count`](Self::count) or the pattern is empty (`Grid(0)`, `Grid(17..)`, `n = 0`).
    pub fn offsets(&self, out: &mut [[Fx; 2]]) -> Result<usize, Error> {
        let n = self.count();
        if n == 0 || matches!(*self, SamplePattern::Grid(k) if k > 16) {
            return Err(Error::BadSize(n as u32));
        }
        if out.len() < n {
            return Err(Error::WrongLength {
                expected: n,
                actual: out.len(),
            });
        }
        match *self {
            SamplePattern::Grid(k) => {
                let k = i32::from(k);
                for (i, o) in out.iter_mut().take(n).enumerate() {
                    let (x, y) = (i as i32 % k, i as i32 / k);
                    // Cell centre: ((2 x + 1) / 2k − 1/2) pixels.
                    let c = |v: i32| Fx::from_bits(((2 * v + 1) << 15) / k - (1 << 15));
                    *o = [c(x), c(y)];
                }
            }
            SamplePattern::RotatedGrid4 => {
                let e = |v: i32| Fx::from_bits(v << 13); // eighths of a pixel
                out[0] = [e(-1), e(-3)];
                out[1] = [e(3), e(-1)];
                out[2] = [e(1), e(3)];
                out[3] = [e(-3), e(1)];
            }
            SamplePattern::Jittered { seed, .. } => {
                let k = (n as u32).isqrt() as i32;
                let mut state = seed | 1;
                for (i, o) in out.iter_mut().take(n).enumerate() {
                    let (x, y) = (i as i32 % k, i as i32 / k);
                    // A random point strictly inside cell (x, y): 1 .. 2^16 / k − 1.
                    let span = (65536 / k - 2).max(1) as u32;
                    let r = |s: &mut u32| (next(s) % span) as i32 + 1;
                    let (rx, ry) = (r(&mut state), r(&mut state));
                    let c = |v: i32, rv: i32| Fx::from_bits(v * 65536 / k + rv - (1 << 15));
                    *o = [c(x, rx), c(y, ry)];
                }
            }
        }
        Ok(n)
    }
}

/// `projection` shifted on screen by `offset` pixels (`+x` right, `+y` down) in `viewport`:
/// the clip-space translation `x += 2 dx / width · w`, `y −= 2 dy / height · w`. Render
/// each sample of a [`SamplePattern`] with its offset and average the frames.
pub fn jittered(projection: &Mat4, offset: [Fx; 2], viewport: &Viewport) -> Mat4 {
    let r = viewport.rect();
    let (w, h) = ((r.x1 - r.x0).max(1), (r.y1 - r.y0).max(1));
    let tx = Fx::from_bits(((i64::from(offset[0].to_bits()) * 2) / i64::from(w)) as i32);
    let ty = Fx::from_bits((-(i64::from(offset[1].to_bits()) * 2) / i64::from(h)) as i32);
    let (o, z) = (Fx::ONE, Fx::ZERO);
    // Row-major, column vectors: x' = x + tx w, y' = y + ty w, after the projection.
    Mat4::from_rows([[o, z, z, tx], [z, o, z, ty], [z, z, o, z], [z, z, z, o]]).mul(projection)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::math::fx;

    #[test]
    fn patterns_stay_inside_the_pixel_and_fill_their_cells() {
        let mut at = [[Fx::ZERO; 2]; 256];
        for p in [
            SamplePattern::Grid(1),
            SamplePattern::Grid(2),
            SamplePattern::Grid(4),
            SamplePattern::Grid(16),
            SamplePattern::RotatedGrid4,
            SamplePattern::Jittered { n: 4, seed: 1 },
            SamplePattern::Jittered { n: 16, seed: 99 },
            SamplePattern::Jittered { n: 256, seed: 5 },
        ] {
            let n = p.offsets(&mut at).unwrap();
            assert_eq!(n, p.count());
            let half = fx(0.5);
            for o in &at[..n] {
                assert!(
                    o[0] > -half && o[0] < half && o[1] > -half && o[1] < half,
                    "{p:?}"
                );
            }
            // Mean near the centre (within one cell for the jitter).
            let mean =
                |k: usize| at[..n].iter().map(|o| o[k].to_num::<f64>()).sum::<f64>() / n as f64;
            assert!(mean(0).abs() < 0.13 && mean(1).abs() < 0.13, "{p:?}");
        }
        assert_eq!(SamplePattern::Grid(1).offsets(&mut at).unwrap(), 1);
        assert_eq!(at[0], [Fx::ZERO; 2]);
        assert!(SamplePattern::Grid(0).offsets(&mut at).is_err());
        assert!(SamplePattern::Grid(4).offsets(&mut at[..3]).is_err());
        // The same seed gives the same pattern.
        let mut a = [[Fx::ZERO; 2]; 16];
        let mut b = [[Fx::ZERO; 2]; 16];
        SamplePattern::Jittered { n: 16, seed: 3 }
            .offsets(&mut a)
            .unwrap();
        SamplePattern::Jittered { n: 16, seed: 3 }
            .offsets(&mut b)
            .unwrap();
        assert_eq!(a, b);
    }
}
