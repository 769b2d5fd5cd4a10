//! A sphere map baked from any environment lookup ([`EnvLookup`]: a cube map, a lat-long
//! map...), at start-up into caller storage or at build time: the texture of the real-time
//! environment map ([`SphereMapUvs`](crate::scene::SphereMapUvs) per vertex, then a plain
//! textured draw), holding the same environment as the accurate per-pixel modes read.
//!
//! Texel `(i, j)` of a `size x size` map has centre `(s, t)`, `(x, y) = (2s − 1, 2t − 1)`
//! and `ρ = |(x, y)| = sin(θ/2)`; its direction is GL's sphere-map inverse
//!
//! ```text
//! r = (2 x sqrt(1 − ρ²), 2 y sqrt(1 − ρ²), 1 − 2 ρ²)
//! ```
//!
//! Texels in the last half texel of the disc and outside it take the direction at
//! `ρ = 1 − 1/(2 size)` on their radius (as [`sky_spheremap`](super::sky::sky_spheremap)
//! does), so a bilinear lookup at the rim blends the colours around the rim, not a border.
//! Integer arithmetic throughout (`Q15` coordinates, `Q30` directions, [`isqrt_u64`]).

use embedded_graphics_core::pixelcolor::raw::RawU16;
use embedded_graphics_core::pixelcolor::Rgb565;

use super::cube::EnvLookup;
use crate::math::isqrt_u64;
use crate::texture::MipTexture;
use crate::Error;

/// The direction (`Q30` components, `|r| = 2^30`) of sphere-map texel `(i, j)` of a
/// `size x size` map (see the module docs).
pub fn sphere_texel_direction(i: u32, j: u32, size: u32) -> [i32; 3] {
    let size = i64::from(size.max(1));
    // Centre in Q15: 2 (i + 1/2) / size − 1.
    let q = |k: u32| ((i64::from(2 * k + 1) << 15) / size) - (1 << 15);
    let (mut x, mut y) = (q(i), q(j));
    let mut rho2 = x * x + y * y; // Q30
    let inner = (1i64 << 15) - (1i64 << 14) / size; // Q15: 1 − 1/(2 size)
    if rho2 > inner * inner {
        let rho = i64::from(isqrt_u64(rho2 as u64)).max(1); // Q15
        x = x * inner / rho;
        y = y * inner / rho;
        rho2 = (x * x + y * y).min(inner * inner);
    }
    let k = 2 * i64::from(isqrt_u64(((1i64 << 30) - rho2).max(0) as u64)); // Q15, 0..=2
    [
        (x * k) as i32,
        (y * k) as i32,
        ((1i64 << 30) - 2 * rho2) as i32,
    ]
}

/// Fills `out` (`size x size`, row 0 first) with the sphere map of `env`: each texel the
/// lookup in its direction. Errors: those of [`MipTexture::new`] for `out` (a side that is
/// not a power of two, or a length other than `size²`).
pub fn bake_sphere_map(env: &impl EnvLookup, size: u32, out: &mut [Rgb565]) -> Result<(), Error> {
    MipTexture::new(out, size, size, 1)?;
    for (k, px) in out.iter_mut().enumerate() {
        let (i, j) = (k as u32 % size, k as u32 / size);
        *px = Rgb565::from(RawU16::new(env.lookup(sphere_texel_direction(i, j, size))));
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn centre_looks_at_the_viewer_and_the_rim_away() {
        // The texel nearest the centre of a 64 map: almost +z.
        let d = sphere_texel_direction(32, 32, 64);
        assert!(d[2] > (1 << 30) - (1 << 24), "{d:?}");
        // A corner (outside the disc): pulled in to just inside the rim, pointing away.
        let d = sphere_texel_direction(0, 0, 64);
        assert!(d[2] < -(1 << 29) && d[0] < 0 && d[1] < 0, "{d:?}");
        let len = d
            .iter()
            .map(|&c| (f64::from(c) / f64::from(1 << 30)).powi(2))
            .sum::<f64>();
        assert!((len - 1.0).abs() < 1e-3, "{len}");
    }

    #[test]
    fn sizes_are_checked() {
        #[derive(Clone, Copy, Debug)]
        struct Grey;
        impl EnvLookup for Grey {
            fn lookup(&self, _: [i32; 3]) -> u16 {
                0x8410
            }
        }
        let mut out = [Rgb565::new(0, 0, 0); 16];
        bake_sphere_map(&Grey, 4, &mut out).unwrap();
        assert!(out.iter().all(|&c| c == Rgb565::from(RawU16::new(0x8410))));
        assert!(bake_sphere_map(&Grey, 3, &mut out[..9]).is_err());
        assert!(bake_sphere_map(&Grey, 4, &mut out[..15]).is_err());
    }
}
