//! Solid textures baked into image textures: the real-time form of a solid texture. The
//! pattern is evaluated once per texel, at the object-space point the texel covers on a
//! surface, into caller storage (at run time) or into flash (at build time, by the same
//! function in a build script); drawing is then a plain textured draw of the mesh with its
//! object-space texture coordinates, costing what any textured draw costs.
//!
//! * [`SphereSurface`]: the texture coordinates of a UV sphere about the origin
//!   (`fixel_scenes::uv_sphere`'s convention): `u` the azimuth in turns from `+x` towards
//!   `−z`, `v` the polar angle from `+y` in half turns, so texel `(i, j)` lies at
//!   `(sin θ cos φ, cos θ, −sin θ sin φ) · radius` with `φ = 2π (i + ½) / w`,
//!   `θ = π (j + ½) / h`.
//! * [`PlaneSurface`]: a flat patch `origin + s · u + t · v`, planar object-space texture
//!   coordinates (a floor, a wall, a cube face).
//! * [`bake`]: one texture of any [`Pattern`] over a [`BakeSurface`], band-limited to the
//!   texel's footprint when the octaves are a [`BandLimit`]; [`bake_mips`]: the same
//!   with a full mip chain, every level baked from the pattern at its own footprint (not
//!   box-filtered from level 0), so a minified level holds the pattern's mean colour where
//!   its finest octaves are smaller than a texel.
//!
//! The baked texel is the solid texture's colour at the texel's centre point: the error of
//! the baked draw against the solid one is that of sampling the texture (a bilinear blend of
//! four texel centres) instead of the pattern at the pixel's own point. `host-tests`
//! measures it against the f64 solid texture.
//!
//! # Baking at run time into caller storage
//!
//! ```
//! use embedded_graphics_core::pixelcolor::Rgb565;
//! use fixel::math::Fx;
//! use fixel::shading::noise::{bake, BandLimit, Ramps, SphereSurface};
//! use fixel::texture::Texture;
//!
//! // The demonstration wood and granite on a sphere of radius 2.7 lattice cells, each
//! // into a 64 x 32 texture (4 KB of RGB565): band-limited to the texel, at most 6 octaves.
//! let ramps = Ramps::new()?;
//! let sphere = SphereSurface { radius: Fx::from_num(2.7) };
//! let (mut wood, mut granite) = ([Rgb565::new(0, 0, 0); 64 * 32], [Rgb565::new(0, 0, 0); 64 * 32]);
//! bake(&ramps.wood(), &BandLimit::new(6), &sphere, 64, 32, &mut wood)?;
//! bake(&ramps.granite(), &BandLimit::new(6), &sphere, 64, 32, &mut granite)?;
//! // Then each is a plain texture for the sphere's own texture coordinates.
//! let tex = Texture::new(&wood, 64, 32)?;
//! assert_eq!(tex.width(), 64);
//! // Rings and grain: neither texture is one flat colour.
//! assert!(wood.iter().any(|&c| c != wood[0]) && granite.iter().any(|&c| c != granite[0]));
//! // Storage of the wrong size is refused.
//! assert!(bake(&ramps.wood(), &BandLimit::new(6), &sphere, 64, 16, &mut wood).is_err());
//! # Ok::<(), fixel::Error>(())
//! ```
//!
//! At build time the same call runs in a build script: the firmware's `build.rs` bakes the
//! marble, wood and granite of the `noise_baked`, `noise_baked_wood` and
//! `noise_baked_granite` scenes into flash.
//!
//! [`BandLimit`]: super::BandLimit

use embedded_graphics_core::pixelcolor::raw::RawU16;
use embedded_graphics_core::pixelcolor::Rgb565;

use super::patterns::Pattern;
use super::turbulence::Octaves;
use crate::math::{sin_cos, Angle, Fx};
use crate::texture::{level_side, log2_q8, MipTexture};
use crate::Error;

/// Where a texture's texels lie on an object.
pub trait BakeSurface {
    /// The object-space point (I16F16 bits in lattice units) of texture coordinates
    /// `(s, t)` (Q16, `65536` = 1).
    fn point(&self, s: u32, t: u32) -> [i32; 3];
    /// The size of one texel of a `width x height` texture in lattice cells, as
    /// `log2` in Q8.8 (the `lambda` of the band-limited turbulence).
    fn texel_lambda(&self, width: u32, height: u32) -> i32;
}

/// A sphere about the origin in the UV sphere's texture coordinates (see the module docs),
/// `radius` in lattice cells (I16F16: the model radius times the lattice scale).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct SphereSurface {
    /// Radius in lattice cells.
    pub radius: Fx,
}

impl BakeSurface for SphereSurface {
    fn point(&self, s: u32, t: u32) -> [i32; 3] {
        // Polar angle: t half turns (Q16 turns = t / 2); azimuth: s turns.
        let (st, ct) = sin_cos(Angle((t >> 1) as u16));
        let (sp, cp) = sin_cos(Angle(s as u16));
        let r = i64::from(self.radius.to_bits());
        let q = |a: Fx, b: Fx| {
            ((((i64::from(a.to_bits()) * i64::from(b.to_bits())) >> 16) * r) >> 16) as i32
        };
        let y = ((i64::from(ct.to_bits()) * r) >> 16) as i32;
        [q(st, cp), y, q(st, sp).wrapping_neg()]
    }

    fn texel_lambda(&self, width: u32, height: u32) -> i32 {
        // The widest texel, on the equator: max(2π r / w, π r / h) cells; π in Q16.
        const PI_Q16: u64 = 205_887;
        let r = u64::from(self.radius.to_bits().unsigned_abs());
        let around = (2 * PI_Q16 * r) / u64::from(width.max(1));
        let down = (PI_Q16 * r) / u64::from(height.max(1));
        // Q32 cells: log2 minus 32.
        log2_q8(around.max(down)) - 32 * 256
    }
}

/// A flat patch: texture coordinates `(s, t)` in `0..1` lie at `origin + s · u + t · v`
/// (every vector I16F16 lattice units), the planar object-space uv of a floor, a wall or
/// a cube face: a texture baked over it is drawn with the patch's planar coordinates
/// (for example `uv = ((p − origin) · u / |u|², (p − origin) · v / |v|²)` for `u ⊥ v`).
/// The sums wrap, which the noise's period makes exact (see the [module docs](super)).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct PlaneSurface {
    /// The point of `(0, 0)`.
    pub origin: [i32; 3],
    /// The edge along `s`: from `(0, 0)` to `(1, 0)`.
    pub u: [i32; 3],
    /// The edge along `t`: from `(0, 0)` to `(0, 1)`.
    pub v: [i32; 3],
}

impl PlaneSurface {
    /// `|e|` (Q16 cells) of an edge.
    fn length(e: [i32; 3]) -> u64 {
        // Each square below 2^62: three fit u64.
        let sq = e.map(|c| u64::from(c.unsigned_abs()).pow(2));
        u64::from(crate::math::isqrt_u64(sq[0] + sq[1] + sq[2]))
    }
}

impl BakeSurface for PlaneSurface {
    fn point(&self, s: u32, t: u32) -> [i32; 3] {
        let at = |k: usize| {
            let du = (i64::from(self.u[k]) * i64::from(s)) >> 16;
            let dv = (i64::from(self.v[k]) * i64::from(t)) >> 16;
            self.origin[k]
                .wrapping_add(du as i32)
                .wrapping_add(dv as i32)
        };
        [at(0), at(1), at(2)]
    }

    fn texel_lambda(&self, width: u32, height: u32) -> i32 {
        // The longer texel side, |u| / w or |v| / h cells, in Q32: log2 minus 32.
        let along = (Self::length(self.u) << 16) / u64::from(width.max(1));
        let down = (Self::length(self.v) << 16) / u64::from(height.max(1));
        log2_q8(along.max(down)) - 32 * 256
    }
}

/// Bakes `pattern` (turbulence from `octaves`) over `surface` into `out`, a
/// `width x height` texture (row-major), each texel its centre point's colour, band-limited
/// to one texel when `octaves` is a band limit. Errors: those of [`MipTexture::new`] for
/// `out` (sides not powers of two, or a length other than `width · height`).
pub fn bake<P: Pattern, O: Octaves>(
    pattern: &P,
    octaves: &O,
    surface: &impl BakeSurface,
    width: u32,
    height: u32,
    out: &mut [Rgb565],
) -> Result<(), Error> {
    bake_mips(pattern, octaves, surface, width, height, 1, out)
}

/// [`bake`] with `levels` mip levels in `out` (the layout of [`MipTexture::new`]), each
/// level baked from the pattern at its own texel size. Errors: those of
/// [`MipTexture::new`] for `out` (its length must be
/// [`chain_len`](crate::texture::chain_len)`(width, height, levels)`).
pub fn bake_mips<P: Pattern, O: Octaves>(
    pattern: &P,
    octaves: &O,
    surface: &impl BakeSurface,
    width: u32,
    height: u32,
    levels: u32,
    out: &mut [Rgb565],
) -> Result<(), Error> {
    MipTexture::new(out, width, height, levels)?;
    let mut off = 0usize;
    for k in 0..levels {
        let (w, h) = (level_side(width, k), level_side(height, k));
        let len = (w * h) as usize;
        if let Some(level) = out.get_mut(off..off + len) {
            bake_level(pattern, octaves, surface, w, h, level);
        }
        off += len;
    }
    Ok(())
}

/// One level (`out.len() == width · height`, checked by the callers).
fn bake_level<P: Pattern, O: Octaves>(
    pattern: &P,
    octaves: &O,
    surface: &impl BakeSurface,
    width: u32,
    height: u32,
    out: &mut [Rgb565],
) {
    let lambda = if O::LOD {
        surface.texel_lambda(width, height)
    } else {
        0
    };
    let centre = |i: u32, size: u32| ((u64::from(2 * i + 1) << 16) / u64::from(2 * size)) as u32;
    for (k, px) in out.iter_mut().enumerate() {
        let (i, j) = (k as u32 % width, k as u32 / width);
        let p = surface.point(centre(i, width), centre(j, height));
        *px = Rgb565::from(RawU16::new(pattern.color(p, octaves, lambda)));
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::shading::noise::{BandLimit, Fixed, Ramps};

    #[test]
    fn sphere_points_lie_on_the_sphere_where_the_uv_sphere_puts_them() {
        let s = SphereSurface {
            radius: Fx::from_num(2),
        };
        // u = 0, v = 1/2: the equator at +x.
        let p = s.point(0, 32768);
        assert!(
            (p[0] - (2 << 16)).abs() <= 2 && p[1].abs() <= 2 && p[2].abs() <= 2,
            "{p:?}"
        );
        // u = 1/4: the equator at -z.
        let p = s.point(16384, 32768);
        assert!((p[2] + (2 << 16)).abs() <= 2 && p[0].abs() <= 2, "{p:?}");
        // v = 0: the +y pole.
        let p = s.point(12345, 0);
        assert_eq!(p[1], 2 << 16);
    }

    #[test]
    fn plane_points_and_texel_size() {
        let p = PlaneSurface {
            origin: [1 << 16, -(2 << 16), 3 << 16],
            u: [4 << 16, 0, 0],
            v: [0, 0, -(2 << 16)],
        };
        assert_eq!(p.point(0, 0), p.origin);
        assert_eq!(p.point(32768, 0), [3 << 16, -(2 << 16), 3 << 16]);
        assert_eq!(p.point(0, 65536), [1 << 16, -(2 << 16), 1 << 16]);
        // 16 texels over 4 cells: a quarter cell, log2 = -2 (Q8.8; `log2_q8` is within
        // 1/64 octave).
        assert!((p.texel_lambda(16, 16) + 512).abs() <= 4);
        // 2 cells over 2 texels: one cell.
        assert!(p.texel_lambda(64, 2).abs() <= 4);
    }

    #[test]
    fn mips_are_baked_and_sizes_checked() {
        let ramps = Ramps::new().unwrap();
        let s = SphereSurface {
            radius: Fx::from_num(3),
        };
        let mut out = [Rgb565::new(0, 0, 0); 16 * 8 + 8 * 4 + 4 * 2 + 2 + 1];
        bake_mips(&ramps.marble(), &BandLimit::new(6), &s, 16, 8, 5, &mut out).unwrap();
        assert!(out.iter().any(|&c| c != Rgb565::new(0, 0, 0)));
        let mut short = [Rgb565::new(0, 0, 0); 10];
        assert!(bake(&ramps.marble(), &Fixed(3), &s, 16, 8, &mut short).is_err());
        assert!(bake(&ramps.marble(), &Fixed(3), &s, 16, 8, &mut out[..128]).is_ok());
        assert!(bake(&ramps.marble(), &Fixed(3), &s, 15, 8, &mut out[..120]).is_err());
    }
}
