//! 3D light maps: the light reaching each point of an object's space,
//! precomputed into a small cube of intensities (for example 16³ = 4 KB) and read back by
//! object-space position with trilinear interpolation. Baked by `cargo xtask bake-light3d`
//! from point lights with inverse-square falloff; independent of the view, free per light
//! at run time (the cost is one trilinear fetch whatever the number of lights).
//!
//! Coordinates are the solid textures' (I16F16 lattice units). Texel `(i, j, k)` covers
//! `origin + (i, j, k) · 2^log2_texel .. + 2^log2_texel` raw units; its value holds the
//! intensity at its centre (GL's texel centres), clamp-to-edge outside the cube.

use super::patterns::Pattern;
use super::solid::SolidTriangle;
use super::turbulence::Octaves;
use crate::color::modulate_scalar;
use crate::shading::{Fragment, Shader};
use crate::texture::LodGranularity;
use crate::Error;

/// A cube of `side³` intensities (`u8`, 255 = 1.0), `x` fastest, then `y`, then `z`.
#[derive(Clone, Copy, Debug)]
pub struct LightMap3d<'a> {
    texels: &'a [u8],
    log2_side: u8,
    origin: [i32; 3],
    log2_texel: u8,
}

impl<'a> LightMap3d<'a> {
    /// A light map of `side³` texels (`side` a power of two, 2 to 64) whose low corner is
    /// at `origin` (I16F16 lattice units) and whose texels are `2^log2_texel` raw units on
    /// a side (`8..=24`: 1/256 to 256 cells).
    ///
    /// # Errors
    /// [`Error::NotPowerOfTwo`] or [`Error::BadSize`] for a bad side,
    /// [`Error::WrongLength`] unless `texels` holds `side³` values, [`Error::BadMode`] for
    /// a texel size out of range.
    pub fn new(
        texels: &'a [u8],
        side: u32,
        origin: [i32; 3],
        log2_texel: u8,
    ) -> Result<Self, Error> {
        if !side.is_power_of_two() {
            return Err(Error::NotPowerOfTwo(side));
        }
        if !(2..=64).contains(&side) {
            return Err(Error::BadSize(side));
        }
        let n = (side * side * side) as usize;
        if texels.len() != n {
            return Err(Error::WrongLength {
                expected: n,
                actual: texels.len(),
            });
        }
        if !(8..=24).contains(&log2_texel) {
            return Err(Error::BadMode(
                "3D light map texel size must be 2^8..=2^24 raw units",
            ));
        }
        Ok(LightMap3d {
            texels,
            log2_side: side.trailing_zeros() as u8,
            origin,
            log2_texel,
        })
    }

    /// The intensity at `p` (I16F16 lattice units), Q8 (`0..=256`), trilinear between the
    /// eight nearest texel centres, clamp-to-edge.
    #[inline]
    pub fn sample(&self, p: [i32; 3]) -> u16 {
        let side = 1i32 << self.log2_side;
        let max = (side - 1) << 8;
        let sh = u32::from(self.log2_texel - 8);
        // Texel coordinates, Q8, relative to texel centres.
        let coord = |a: usize| -> (usize, usize, i32) {
            let d = (i64::from(p[a]) - i64::from(self.origin[a])) >> sh;
            let c = (d - 128).clamp(0, i64::from(max)) as i32;
            let i = c >> 8;
            (i as usize, (i + 1).min(side - 1) as usize, c & 255)
        };
        let (x0, x1, fx) = coord(0);
        let (y0, y1, fy) = coord(1);
        let (z0, z1, fz) = coord(2);
        let s = self.log2_side as usize;
        let at = |x: usize, y: usize, z: usize| {
            i32::from(
                self.texels
                    .get((((z << s) | y) << s) | x)
                    .copied()
                    .unwrap_or(0),
            )
        };
        let lerp = |a: i32, b: i32, f: i32| (a << 8) + (b - a) * f; // Q8 more bits
        let row = |y: usize, z: usize| lerp(at(x0, y, z), at(x1, y, z), fx); // Q8
        let plane = |z: usize| {
            let (a, b) = (row(y0, z), row(y1, z));
            (a << 8) + (b - a) * fy // Q16
        };
        let (a, b) = (plane(z0) >> 8, plane(z1) >> 8); // Q8
        let v = ((a << 8) + (b - a) * fz + (1 << 15)) >> 16; // 0..=255
        ((v * 257 + 128) >> 8) as u16
    }
}

/// A solid texture lit by a [`LightMap3d`] instead of an interpolated intensity.
/// Varyings: `x, y, z` (I16F16 lattice units), as [`SolidShader`](super::SolidShader)'s
/// first three.
#[derive(Clone, Copy, Debug)]
pub struct LitSolid<'a, P, O> {
    /// The pattern.
    pub pattern: P,
    /// The octave policy.
    pub octaves: O,
    /// The light.
    pub light: LightMap3d<'a>,
    /// Where a band-limited pattern measures the footprint.
    pub granularity: LodGranularity,
}

impl<P: Pattern, O: Octaves> Shader for LitSolid<'_, P, O> {
    type Varyings = [i32; 3];
    type Triangle = SolidTriangle;
    const TEXCOORDS: Option<(usize, usize)> = Some((0, 1));
    const LOD: bool = O::LOD;

    #[inline(always)]
    fn lod_granularity(&self) -> LodGranularity {
        self.granularity
    }

    fn triangle(&self, v: &mut [[i32; 3]; 3]) -> SolidTriangle {
        let t = SolidTriangle::of(*v);
        for c in v.iter_mut() {
            *c = t.rotate(*c);
        }
        t
    }

    #[inline(always)]
    fn shade(&self, f: &Fragment<[i32; 3], SolidTriangle>) -> Option<u16> {
        let p = f.triangle.unrotate(f.varyings);
        let color = self.pattern.color(p, &self.octaves, f.lambda);
        Some(modulate_scalar(color, self.light.sample(p)))
    }
}
