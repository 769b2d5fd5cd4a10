//! The flame from baked layers: the real-time form of [`flame`](super::flame). Its
//! turbulence is not summed per pixel from five octaves of noise; it is read from two small
//! tileable textures baked once, each holding a band of octaves, scrolled upwards per frame.
//! A pixel costs two texel reads and the flame's colour arithmetic.
//!
//! # Definition
//!
//! Layer `l` (a [`FlameLayer`]) holds the partial turbulence
//! `T_l(u, v) = Σ_{k = first}^{first + octaves − 1} |noise_P(2^k u, 2^k v, z_l)| / 2^k`
//! over a square of `P = 2^period_log2` lattice cells, where `noise_P` is Perlin's improved
//! noise ([`noise3`](super::noise3)) with the lattice cells of `x` and `y` taken modulo the
//! octave's period `2^k P` before hashing ([`noise3_tiled`]), so the layer tiles. Texel
//! `(i, j)` of a `side x side` layer is `T_l` at its centre, `((i + ½), (j + ½)) · P / side`
//! cells, as Q15 in a `u16`.
//!
//! At the flame point `(x, y)` (Q16 flame units, as [`flame`](super::flame)) and time `t`,
//! layer `l` is read, nearest texel, at `(2x, 2y − rise_l · t)` cells, and the turbulence
//! is the sum of the layers: [`FLAME_LAYERS`] puts octaves 0 and 1 in a 4-cell tile rising
//! at [`FLAME_RISE`](super::FLAME_RISE) and octaves 2 to 4 in a 2-cell tile rising twice as
//! fast (the fine tongues outrun the body of the flame, which stands in for the per-pixel
//! flame's change of shape along its time axis). The colour is then the per-pixel flame's,
//! from that turbulence.
//!
//! # Example
//!
//! ```
//! use fixel::shading::noise::{
//!     bake_flame_layer, BakedFlame, Ramp, FLAME_KEYS, FLAME_LAYERS, FLAME_LAYER_SIDE,
//! };
//!
//! // Bake the two layers once into caller storage (2 x 8 KB)...
//! const N: usize = (FLAME_LAYER_SIDE * FLAME_LAYER_SIDE) as usize;
//! let (mut l0, mut l1) = ([0u16; N], [0u16; N]);
//! bake_flame_layer(&FLAME_LAYERS[0], FLAME_LAYER_SIDE, &mut l0)?;
//! bake_flame_layer(&FLAME_LAYERS[1], FLAME_LAYER_SIDE, &mut l1)?;
//! // ...then each frame is a shader over the flame's quad (varyings x, y in Q16 flame
//! // units), here at t = 0.25 s.
//! let ramp = Ramp::from_keys(&FLAME_KEYS)?;
//! let flame = BakedFlame::new(&ramp, &FLAME_LAYERS, [&l0, &l1], FLAME_LAYER_SIDE, 1 << 14)?;
//! // Hot in the middle near the base, black above the tip.
//! let (core, air) = (flame.color(0, 6_554), flame.color(0, 2 << 16));
//! assert!(core >> 11 > 20 && air == 0);
//! // Tiles of the wrong size are refused.
//! assert!(BakedFlame::new(&ramp, &FLAME_LAYERS, [&l0, &l1[..100]], FLAME_LAYER_SIDE, 0).is_err());
//! # Ok::<(), fixel::Error>(())
//! ```
//!
//! # Cost
//!
//! Flash (or caller RAM when baked at run time): `side² · 2` bytes per layer, 16 KB for
//! the two 64 x 64 layers of [`FLAME_LAYERS`]. Per pixel: two texel reads and the flame's
//! colour arithmetic: **132.4 instructions on Cortex-M4F, 265.3 on Cortex-M0+, 164.1 on
//! RV32IMC** (firmware scene `noise_flame_baked`, `cargo xtask mcu`), 1.12 / 1.02 / 1.02
//! times the same quad as a plain bilinear textured draw (`flame_plain`: 118.4 / 261.4 /
//! 160.4), and a ninth of the per-pixel flame's 1,185 / 1,751 / 1,326 (5 octaves).

use super::flame::{flame_color, FLAME_RISE};
use super::patterns::Ramp;
use super::{fade_q14, grad, lerp, perm};
use crate::shading::{Fragment, Shader};
use crate::Error;

/// One baked band of octaves (see the module docs).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct FlameLayer {
    /// The first octave `k` (`0..=7`).
    pub first: u8,
    /// Octaves summed (`1..=8 − first`).
    pub octaves: u8,
    /// `log2` of the tile's side in lattice cells (`0..=4`).
    pub period_log2: u8,
    /// The noise's third coordinate, I16F16 lattice units: each layer its own slice.
    pub z: i32,
    /// Upward scroll, lattice cells per second (Q16).
    pub rise: i32,
}

/// Side of each layer of [`FLAME_LAYERS`], texels.
pub const FLAME_LAYER_SIDE: u32 = 64;

/// The two layers of the baked flame: octaves 0 and 1 in a 4-cell tile rising at
/// [`FLAME_RISE`], octaves 2 to 4 in a 2-cell tile rising at twice that; 64 x 64 texels
/// each (16 and 32 texels per cell).
pub const FLAME_LAYERS: [FlameLayer; 2] = [
    FlameLayer {
        first: 0,
        octaves: 2,
        period_log2: 2,
        z: 0x2_8000,
        rise: FLAME_RISE,
    },
    FlameLayer {
        first: 2,
        octaves: 3,
        period_log2: 1,
        z: 0x7_4000,
        rise: 2 * FLAME_RISE,
    },
];

impl FlameLayer {
    /// Checks the fields' ranges.
    fn check(&self) -> Result<(), Error> {
        if self.octaves == 0 || u32::from(self.first) + u32::from(self.octaves) > 8 {
            return Err(Error::BadMode(
                "a flame layer sums 1 to 8 octaves, none past the eighth",
            ));
        }
        if self.period_log2 > 4 {
            return Err(Error::BadMode(
                "a flame layer's tile is at most 16 lattice cells",
            ));
        }
        Ok(())
    }

    /// The layer's partial turbulence at `(u, v)` (I16F16 lattice units): Q15.
    pub fn turbulence(&self, u: i32, v: i32) -> i32 {
        let mut sum = 0;
        for k in u32::from(self.first)..u32::from(self.first) + u32::from(self.octaves) {
            let mask = (1u32 << (u32::from(self.period_log2) + k)) - 1;
            let n = noise3_tiled(u.wrapping_shl(k), v.wrapping_shl(k), self.z, mask.min(255));
            sum += n.abs() >> k;
        }
        sum
    }
}

/// [`noise3`](super::noise3) with the lattice cells of `x` and `y` taken modulo
/// `mask + 1` (a power of two up to 256; `mask` is clamped to 255) before hashing: a noise
/// that tiles every `mask + 1` cells in `x` and `y`. With `mask = 255` it is `noise3`.
/// Q15; `x`, `y`, `z` I16F16 lattice units, any `i32`.
pub fn noise3_tiled(x: i32, y: i32, z: i32, mask: u32) -> i32 {
    let m = mask.min(255);
    let cell = |c: i32| ((c >> 16) & 255) as u32;
    let (xi, yi, zi) = (cell(x) & m, cell(y) & m, cell(z));
    let (xj, yj) = ((xi + 1) & m, (yi + 1) & m);
    let (xf, yf, zf) = (x as u32 & 0xFFFF, y as u32 & 0xFFFF, z as u32 & 0xFFFF);
    let (u, v, w) = (fade_q14(xf), fade_q14(yf), fade_q14(zf));
    let (x0, y0, z0) = ((xf >> 1) as i32, (yf >> 1) as i32, (zf >> 1) as i32);
    let (x1, y1, z1) = (x0 - 32768, y0 - 32768, z0 - 32768);
    // Perlin's hashes with the next cell of x and y wrapped: A = p[X] + Y, AA = p[A] + Z...
    let (pa, pb) = (perm(xi), perm(xj));
    let (aa, ab) = (perm(pa + yi) + zi, perm(pa + yj) + zi);
    let (ba, bb) = (perm(pb + yi) + zi, perm(pb + yj) + zi);
    let near = lerp(
        lerp(grad(perm(aa), x0, y0, z0), grad(perm(ba), x1, y0, z0), u),
        lerp(grad(perm(ab), x0, y1, z0), grad(perm(bb), x1, y1, z0), u),
        v,
    );
    let far = lerp(
        lerp(
            grad(perm(aa + 1), x0, y0, z1),
            grad(perm(ba + 1), x1, y0, z1),
            u,
        ),
        lerp(
            grad(perm(ab + 1), x0, y1, z1),
            grad(perm(bb + 1), x1, y1, z1),
            u,
        ),
        v,
    );
    lerp(near, far, w)
}

/// Bakes `layer` into `out`, a `side x side` tile (row-major, Q15 partial turbulence per
/// texel at its centre; see the module docs), at run time into caller storage or in a build
/// script into flash.
///
/// # Errors
/// [`Error::BadMode`] when `side` is not a power of two in `2..=1024` or the layer's fields
/// are out of range; [`Error::WrongLength`] when `out` is not `side²` long.
pub fn bake_flame_layer(layer: &FlameLayer, side: u32, out: &mut [u16]) -> Result<(), Error> {
    check_side(side)?;
    layer.check()?;
    let n = (side * side) as usize;
    if out.len() != n {
        return Err(Error::WrongLength {
            expected: n,
            actual: out.len(),
        });
    }
    // Texel centre in I16F16 cells: (2 i + 1) · P / (2 side).
    let period = 1u64 << (16 + u32::from(layer.period_log2));
    let centre = |i: u32| ((u64::from(2 * i + 1) * period) / u64::from(2 * side)) as i32;
    for (k, t) in out.iter_mut().enumerate() {
        let (i, j) = (k as u32 % side, k as u32 / side);
        *t = layer.turbulence(centre(i), centre(j)) as u16;
    }
    Ok(())
}

fn check_side(side: u32) -> Result<(), Error> {
    if !side.is_power_of_two() || !(2..=1024).contains(&side) {
        return Err(Error::BadMode(
            "a flame layer's side is a power of two in 2..=1024 texels",
        ));
    }
    Ok(())
}

/// One baked layer as the shader reads it: the tile, its side and where it is this frame.
#[derive(Clone, Copy, Debug)]
struct Tile<'a> {
    texels: &'a [u16],
    /// `log2(side)`.
    side_log2: u32,
    /// I16F16 cells to texels: `16 + period_log2 − side_log2` bits right.
    shift: u32,
    /// This frame's scroll, I16F16 cells (subtracted from `v`).
    scroll: i32,
}

impl Tile<'_> {
    /// The nearest texel at `(u, v)` (I16F16 cells), wrapped: Q15.
    #[inline(always)]
    fn at(&self, u: i32, v: i32) -> i32 {
        let mask = (1u32 << self.side_log2) - 1;
        let i = ((u as u32) >> self.shift) & mask;
        let j = ((v.wrapping_sub(self.scroll) as u32) >> self.shift) & mask;
        // In range: i, j < side and the length is side² (checked by `BakedFlame::new`).
        self.texels
            .get(((j << self.side_log2) | i) as usize)
            .map_or(0, |&t| i32::from(t))
    }
}

/// The flame at time `t` from two baked layers, as a shader over a quad: varyings `x, y`
/// (Q16 flame units), as [`FlameShader`](super::FlameShader).
#[derive(Clone, Copy, Debug)]
pub struct BakedFlame<'a> {
    ramp: &'a Ramp,
    tiles: [Tile<'a>; 2],
}

impl<'a> BakedFlame<'a> {
    /// The flame at `t` (Q16 seconds) from `layers` baked by [`bake_flame_layer`] into
    /// `texels` (`side x side` each), colours from `ramp`.
    ///
    /// # Errors
    /// [`Error::BadMode`] when `side` is not a power of two in `2..=1024` or a layer's fields
    /// are out of range; [`Error::WrongLength`] when a layer's texels are not `side²`.
    pub fn new(
        ramp: &'a Ramp,
        layers: &[FlameLayer; 2],
        texels: [&'a [u16]; 2],
        side: u32,
        t: i32,
    ) -> Result<Self, Error> {
        check_side(side)?;
        let side_log2 = side.trailing_zeros();
        let n = (side * side) as usize;
        let tile = |l: &FlameLayer, tx: &'a [u16]| -> Result<Tile<'a>, Error> {
            l.check()?;
            if tx.len() != n {
                return Err(Error::WrongLength {
                    expected: n,
                    actual: tx.len(),
                });
            }
            // 16..=20 bits of cell less 1..=10 of side: a shift of 6..=19.
            Ok(Tile {
                texels: tx,
                side_log2,
                shift: 16 + u32::from(l.period_log2) - side_log2,
                scroll: ((i64::from(t) * i64::from(l.rise)) >> 16) as i32,
            })
        };
        Ok(BakedFlame {
            ramp,
            tiles: [tile(&layers[0], texels[0])?, tile(&layers[1], texels[1])?],
        })
    }

    /// The flame's colour (raw RGB565) at `(x, y)` (Q16 flame units).
    #[inline(always)]
    pub fn color(&self, x: i32, y: i32) -> u16 {
        let (u, v) = (x.wrapping_mul(2), y.wrapping_mul(2));
        let turb = self.tiles[0].at(u, v) + self.tiles[1].at(u, v);
        flame_color(self.ramp, x, y, turb)
    }
}

impl Shader for BakedFlame<'_> {
    type Varyings = [i32; 2];
    type Triangle = ();
    fn triangle(&self, _: &mut [[i32; 2]; 3]) {}
    #[inline(always)]
    fn shade(&self, f: &Fragment<[i32; 2], ()>) -> Option<u16> {
        let [x, y] = f.varyings;
        Some(self.color(x, y))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::shading::noise::noise3;

    #[test]
    fn tiled_noise_is_noise3_at_full_period_and_tiles() {
        for (x, y, z) in [(0x1_8000, 0x0_4000, 0x2_C000), (-0x35_1234, 0x7F_0F0F, 3)] {
            assert_eq!(noise3_tiled(x, y, z, 255), noise3(x, y, z));
            let p = 4 << 16;
            let a = noise3_tiled(x, y, z, 3);
            assert_eq!(noise3_tiled(x.wrapping_add(p), y, z, 3), a);
            assert_eq!(noise3_tiled(x, y.wrapping_sub(p), z, 3), a);
        }
    }

    #[test]
    fn bad_layers_and_sizes_are_refused() {
        let mut out = [0u16; 16];
        let bad = FlameLayer {
            first: 6,
            octaves: 3,
            ..FLAME_LAYERS[0]
        };
        assert!(bake_flame_layer(&bad, 4, &mut out).is_err());
        assert!(bake_flame_layer(&FLAME_LAYERS[0], 3, &mut out[..9]).is_err());
        assert!(bake_flame_layer(&FLAME_LAYERS[0], 4, &mut out[..15]).is_err());
        assert!(bake_flame_layer(&FLAME_LAYERS[0], 4, &mut out).is_ok());
        let ramp = Ramp::from_keys(&super::super::FLAME_KEYS).unwrap();
        assert!(BakedFlame::new(&ramp, &FLAME_LAYERS, [&out, &out[..8]], 4, 0).is_err());
        assert!(BakedFlame::new(&ramp, &FLAME_LAYERS, [&out, &out], 4, 0).is_ok());
    }
}
