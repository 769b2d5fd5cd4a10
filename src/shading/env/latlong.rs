//! Latitude-longitude (equirectangular) maps: one texture whose columns are longitude and
//! rows latitude, through table `atan2` (no square root, no divide: see
//! [`angles`](super::angles)).
//!
//! For a direction `r` (any length):
//!
//! ```text
//! λ = atan2(rx, −rz)                    longitude, 0 looking down −z, growing towards +x
//! β = atan2(ry, sqrt(rx² + rz²))        latitude (= asin(ry / |r|))
//! s = λ / 2π + 1/2  (mod 1)             −z at the centre column, the seam at +z
//! t = 1/2 − β / π                       t = 0 (the first row) at the zenith +y
//! ```
//!
//! Sampling repeats along `s` (so bilinear filtering crosses the seam) and clamps along `t`.
//!
//! # Singularities
//!
//! At the poles (`rx = rz = 0`) every longitude is the same point; fixel takes `λ = 0`
//! (`s = 1/2`) and `t = 0` or `1`, the first or last row. The zero direction reads
//! `s = t = 1/2`.

use super::angles::atan2_hypot;
use super::cube::EnvLookup;
use crate::texture::{ClampToEdge, Repeat, Sampler, Texture};

/// A latitude-longitude map: one power-of-two texture (normally twice as wide as tall),
/// sampled with filter `F`, repeat along `s`, clamp-to-edge along `t`.
#[derive(Clone, Copy, Debug)]
pub struct LatLongMap<'a, F> {
    tex: Texture<'a>,
    filter: core::marker::PhantomData<F>,
}

impl<'a, F: Sampler> LatLongMap<'a, F> {
    /// A latitude-longitude map over `tex`, filtered with `filter`.
    pub fn new(tex: Texture<'a>, _filter: F) -> Self {
        LatLongMap {
            tex,
            filter: core::marker::PhantomData,
        }
    }

    /// `s` (Q16, `0..65536`, wrapping) and `t` (Q16, `0..=65536`) of direction `dir`.
    #[inline(always)]
    pub fn coords(dir: [i32; 3]) -> (u32, u32) {
        let [x, y, z] = dir;
        // The 2-vector (−z, x): −z is longitude 0.
        let (lambda, h) = atan2_hypot(x.unsigned_abs(), x < 0, z.unsigned_abs(), z > 0);
        let (beta, _) = atan2_hypot(y.unsigned_abs(), y < 0, h, false);
        // beta in [0, 16384] (north) or [49152, 65536) (south): signed quarter turns.
        let beta = if beta >= 32768 {
            beta as i32 - 65536
        } else {
            beta as i32
        };
        let s = (lambda + 32768) & 0xFFFF;
        let t = (32768 - 2 * beta).clamp(0, 65536) as u32;
        if x == 0 && y == 0 && z == 0 {
            return (32768, 32768);
        }
        (s, t)
    }
}

impl<F: Sampler> EnvLookup for LatLongMap<'_, F> {
    #[inline(always)]
    fn lookup(&self, dir: [i32; 3]) -> u16 {
        let (s, t) = Self::coords(dir);
        let (lw, lh) = (self.tex.log2_width(), self.tex.log2_height());
        F::sample(
            &self.tex,
            Repeat,
            ClampToEdge,
            (s << lw) as i32,
            (t << lh) as i32,
        )
    }
}
