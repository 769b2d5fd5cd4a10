//! Sphere maps (`GL_SPHERE_MAP`): the environment as seen in a mirrored ball
//! from far along `+z`, one texture indexed by
//!
//! ```text
//! m = 2 sqrt(rx² + ry² + (rz + 1)²),   s = rx / m + 1/2,   t = ry / m + 1/2
//! ```
//!
//! for the unit reflection vector `r` in eye space (GL's formulas, so
//! `t = 1` is `+y`: with fixel's `t = 0` at the first row, a sphere-map image is stored with
//! its `-y` row first, as GL's bottom-up images are).
//!
//! # Without a square root or a divide
//!
//! With `θ` the angle between `r` and `+z` and `φ` the angle of `(rx, ry)`, the formula is
//! `s = 1/2 + sin(θ/2) cos φ / 2`, `t = 1/2 + sin(θ/2) sin φ / 2` (since `m = 4 cos(θ/2)`
//! for a unit `r`). fixel computes `φ` and `sqrt(rx² + ry²)` with the table `atan2` of
//! [`angles`](super::angles), then `θ = atan2(sqrt(rx² + ry²), rz)` the same way, and
//! the sines and cosines from fixel's quarter-wave table ([`sin_cos`]): the direction need
//! not be a unit vector, and the precomputed tables replace the square root and the
//! division.
//!
//! # Singularities
//!
//! `r = (0, 0, -1)` (pointing away from the viewer) is the whole rim of the map; fixel reads
//! the rim point at `φ = 0` (`s = 1`, `t = 1/2`), and directions close to it read points
//! close to the rim (clamp-to-edge). The zero direction reads the centre (`θ = 0`).

use super::angles::atan2_hypot;
use super::cube::EnvLookup;
use crate::math::{sin_cos, Angle};
use crate::texture::{ClampToEdge, Sampler, Texture};

/// A sphere map: one power-of-two texture (normally square), sampled with filter `F`,
/// clamp-to-edge.
#[derive(Clone, Copy, Debug)]
pub struct SphereMap<'a, F> {
    tex: Texture<'a>,
    filter: core::marker::PhantomData<F>,
}

impl<'a, F: Sampler> SphereMap<'a, F> {
    /// A sphere map over `tex`, filtered with `filter`.
    pub fn new(tex: Texture<'a>, _filter: F) -> Self {
        SphereMap {
            tex,
            filter: core::marker::PhantomData,
        }
    }

    /// `s`, `t` in Q16 (`0..=65536`) of direction `dir` (any length).
    #[inline(always)]
    pub fn coords(dir: [i32; 3]) -> (u32, u32) {
        let [x, y, z] = dir;
        let (phi, hxy) = atan2_hypot(y.unsigned_abs(), y < 0, x.unsigned_abs(), x < 0);
        // theta in [0, 32768] (half a turn).
        let (theta, _) = atan2_hypot(hxy, false, z.unsigned_abs(), z < 0);
        let (rho, _) = sin_cos(Angle((theta >> 1) as u16));
        let (sp, cp) = sin_cos(Angle(phi as u16));
        let half = |c: i32| {
            // rho, c in Q16 (|.| <= 1): product Q32, halved to Q16: |.| <= 2^15.
            let p = (i64::from(rho.to_bits()) * i64::from(c)) >> 17;
            (32768 + p).clamp(0, 65536) as u32
        };
        (half(cp.to_bits()), half(sp.to_bits()))
    }
}

impl<F: Sampler> EnvLookup for SphereMap<'_, F> {
    #[inline(always)]
    fn lookup(&self, dir: [i32; 3]) -> u16 {
        let (s, t) = Self::coords(dir);
        let (lw, lh) = (self.tex.log2_width(), self.tex.log2_height());
        F::sample(
            &self.tex,
            ClampToEdge,
            ClampToEdge,
            (s << lw) as i32,
            (t << lh) as i32,
        )
    }
}
