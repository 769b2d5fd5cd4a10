//! Solid textures from table-based Perlin noise (Perlin, "An Image Synthesizer", SIGGRAPH
//! 1985): a colour as a function of the 3D object-space point, with no seams, no distortion
//! and no texture memory.
//!
//! * [`noise3`]: Perlin's improved gradient noise in 3D, all in `i32` fixed point;
//!   [`noise4`](fn@noise4), [`turbulence4`] and [`Animated`]: the same in 4D, for solid textures that
//!   change shape over time.
//! * [`turbulence`](fn@turbulence) and [`BandLimit`]: `Σ |noise(2^k p)| / 2^k`, with the octaves finer than
//!   a pixel replaced by their mean (the clamping of procedural textures).
//! * [`Ramp`], [`Marble`], [`Wood`], [`Granite`]: patterns over the noise, and
//!   [`SolidShader`], the fragment shader that draws any [`Pattern`] on a mesh with the
//!   object-space point as three varyings and a light intensity as the fourth.
//! * [`flame`](fn@flame) and [`FlameShader`]: an animated flame (a texture of
//!   the plane: 2D + time through [`noise3`], time as the third axis); [`BakedFlame`]: the
//!   same flame from two baked tileable layers of octaves ([`bake_flame_layer`]), scrolled
//!   per frame, two texel reads per pixel.
//! * [`bake`] and [`bake_mips`]: any pattern baked into an image texture over a
//!   [`SphereSurface`] (a UV sphere's own coordinates) or a [`PlaneSurface`] (planar
//!   coordinates), drawn as a plain textured draw: the real-time form of a solid texture.
//! * [`LightMap3d`] and [`LitSolid`]: a baked 3D light map, trilinear
//!   (`cargo xtask bake-light3d`).
//! * [`SolidTimesTexture`]: a solid texture multiplied with an image texture and the light;
//!   [`Select`]: one of two solid textures, chosen by a third noise with a smooth threshold.
//! * [`SolidMesh`]: mesh vertices with the object-space point as varyings; [`presets`]: the
//!   demonstration colours and parameters.
//!
//! # Formats
//!
//! A point `p` is three `i32`: **I16F16 bits in lattice units** (`65536` = one noise cell).
//! The noise repeats every [`PERIOD`] = 256 cells on each axis, and `2^32` raw units are
//! exactly 256 periods, so any `i32` is a valid coordinate: wrapping arithmetic on the raw
//! bits (`x.wrapping_shl(k)` for octave `k`, `x.wrapping_add(t)` for motion) gives exactly
//! the noise of the true, unwrapped point. There is no overflow and no loss of statistics
//! anywhere in the `i32` range.
//!
//! [`noise3`] returns **Q15** (`32768` = 1.0). The lattice offsets inside a cell are Q15,
//! the fade weights Q14, the twelve gradients of the improved noise are edge midpoints of
//! the cube (two components ±1, one 0), so a gradient dot product is a sum of two offsets
//! and needs no multiply. Measured range (test `noise_extremes`): about ±1.0 (the extremes
//! are found by a search in `host-tests/tests/noise.rs`; the proven bound is ±2).
//!
//! # Cost
//!
//! One [`noise3`] call: **218 instructions on Cortex-M4F, 292 on Cortex-M0+** (exact QEMU
//! counts, firmware bin `noise_cost`, loop included). One octave of turbulence adds about
//! 194 (M4F) and 295 (M0+) instructions per pixel; `docs/report/noise.md` (written by
//! `cargo xtask report --docs`) has the per-octave figures and the errors, and
//! [the guide's chapter](crate::guide::solid_textures) what to choose. Flash: about 1.9 KB for
//! band-limited turbulence with the noise inlined, plus the 256-byte permutation and the
//! 514-byte fade table; nothing for draws that do not use it.
//!
//! # Drawing a solid texture
//!
//! ```
//! use fixel::prelude::*;
//! use fixel::math::fx;
//! use fixel_scenes as demo;
//! use fixel::pipeline::{DepthLess, Exact, ShadedDraw};
//! use fixel::scene::DirectionalLight;
//! use fixel::shading::noise::{BandLimit, Ramps, SolidMesh, SolidShader};
//! use embedded_graphics_core::pixelcolor::Rgb565;
//!
//! // A marble cube: the colour tables (1.5 KB), band-limited turbulence of at most 5
//! // octaves (the pixel's footprint measured once per span).
//! let ramps = Ramps::new()?;
//! let shader = SolidShader::new(ramps.marble(), BandLimit::new(5));
//! let draw = ShadedDraw::<_, Exact, DepthLess>::new(shader, Viewport::new(0, 0, 80, 60)?, Cull::Back)?;
//!
//! let cube = demo::cube();
//! // Two noise cells per model unit; lit per vertex.
//! let mesh = SolidMesh::new(&cube.positions, Some(&cube.normals), &cube.indices, fx(2))?;
//! let (mut color, mut depth) = ([Rgb565::default(); 80 * 60], [0u16; 80 * 60]);
//! let mut frame = Frame::new(&mut color, 80, 60)?.with_depth(&mut depth)?;
//! frame.clear(Rgb565::default());
//! let mut tris = Vec::new();
//! mesh.triangles(&demo::cube_model(0), &demo::camera(20), Some(&DirectionalLight::default()),
//!                |t| tris.push(*t));
//! let drawn = draw.clip_triangles(&tris, &mut frame)?;
//! assert!(drawn > 500);
//! # Ok::<(), fixel::Error>(())
//! ```
//!
//! ```
//! use fixel::shading::noise::{noise3, turbulence};
//! // Lattice points are zeros of the noise.
//! assert_eq!(noise3(3 << 16, -7 << 16, 200 << 16), 0);
//! // Between them it is a smooth value in about -1..1 (Q15).
//! let n = noise3(0x1_8000, 0x0_4000, 0x2_C000);
//! assert!(n.abs() < 40_000);
//! // Turbulence of 4 octaves is non-negative, below 2.0 (Q15).
//! let t = turbulence([0x1_8000, 0x0_4000, 0x2_C000], 4);
//! assert!((0..65_536).contains(&t));
//! ```

mod bake;
mod compose;
mod flame;
mod flame_baked;
mod lightmap3d;
mod noise4;
mod patterns;
pub mod presets;
mod scene;
mod select;
mod solid;
mod turbulence;

pub use bake::{bake, bake_mips, BakeSurface, PlaneSurface, SphereSurface};
pub use compose::SolidTimesTexture;
pub use flame::{
    flame, FlameShader, FLAME_CHURN, FLAME_GAIN, FLAME_KEYS, FLAME_RISE, FLAME_TURB_MID,
};
pub use flame_baked::{
    bake_flame_layer, noise3_tiled, BakedFlame, FlameLayer, FLAME_LAYERS, FLAME_LAYER_SIDE,
};
pub use lightmap3d::{LightMap3d, LitSolid};
pub use noise4::{noise4, turbulence4, Animated};
pub use patterns::{Granite, Marble, Pattern, Ramp, Wood};
pub use presets::Ramps;
pub use scene::{lattice_point, SolidMesh};
pub use select::{Select, SELECT_OFFSET};
pub use solid::{SolidShader, SolidTriangle};
pub use turbulence::{turbulence, BandLimit, Fixed, Octaves, ABS_NOISE_MEAN_Q15, MAX_OCTAVES};

/// The noise period in lattice cells, on each axis.
pub const PERIOD: i32 = 256;

/// One noise cell in the I16F16 point format.
pub const CELL: i32 = 1 << 16;

/// Ken Perlin's permutation of `0..=255` (the table of his reference implementation of
/// improved noise, 2002). Indexing wraps at 256, which is what his doubled 512-entry table
/// does.
pub const PERM: [u8; 256] = [
    151, 160, 137, 91, 90, 15, 131, 13, 201, 95, 96, 53, 194, 233, 7, 225, 140, 36, 103, 30, 69,
    142, 8, 99, 37, 240, 21, 10, 23, 190, 6, 148, 247, 120, 234, 75, 0, 26, 197, 62, 94, 252, 219,
    203, 117, 35, 11, 32, 57, 177, 33, 88, 237, 149, 56, 87, 174, 20, 125, 136, 171, 168, 68, 175,
    74, 165, 71, 134, 139, 48, 27, 166, 77, 146, 158, 231, 83, 111, 229, 122, 60, 211, 133, 230,
    220, 105, 92, 41, 55, 46, 245, 40, 244, 102, 143, 54, 65, 25, 63, 161, 1, 216, 80, 73, 209, 76,
    132, 187, 208, 89, 18, 169, 200, 196, 135, 130, 116, 188, 159, 86, 164, 100, 109, 198, 173,
    186, 3, 64, 52, 217, 226, 250, 124, 123, 5, 202, 38, 147, 118, 126, 255, 82, 85, 212, 207, 206,
    59, 227, 47, 16, 58, 17, 182, 189, 28, 42, 223, 183, 170, 213, 119, 248, 152, 2, 44, 154, 163,
    70, 221, 153, 101, 155, 167, 43, 172, 9, 129, 22, 39, 253, 19, 98, 108, 110, 79, 113, 224, 232,
    178, 185, 112, 104, 218, 246, 97, 228, 251, 34, 242, 193, 238, 210, 144, 12, 191, 179, 162,
    241, 81, 51, 145, 235, 249, 14, 239, 107, 49, 192, 214, 31, 181, 199, 106, 157, 184, 84, 204,
    176, 115, 121, 50, 45, 127, 4, 150, 254, 138, 236, 205, 93, 222, 114, 67, 29, 24, 72, 243, 141,
    128, 195, 78, 66, 215, 61, 156, 180,
];

/// `PERM[i mod 256]`.
#[inline(always)]
fn perm(i: u32) -> u32 {
    u32::from(PERM[(i & 255) as usize])
}

/// The quintic fade `6t⁵ − 15t⁴ + 10t³` at `t = i / 256`, `i = 0..=256`, Q15 (rounded from
/// the exact rational value; 514 bytes of flash).
pub const FADE_Q15: [u16; 257] = {
    let mut t = [0u16; 257];
    let mut i = 0u64;
    while i <= 256 {
        // fade(i/256) = i³ (10·256² − 15·256 i + 6 i²) / 256⁵; times 2^15 is / 2^25.
        let num = i * i * i * (655_360 + 6 * i * i - 3840 * i);
        t[i as usize] = ((num + (1 << 24)) >> 25) as u16;
        i += 1;
    }
    t
};

/// The quintic fade of a Q16 cell fraction (`0..65536`), as a Q14 weight (`0..=16384`):
/// [`FADE_Q15`] interpolated linearly on the low 8 bits. Within 1 Q14 LSB of the exact
/// fade (tested for every input); 0 at 0, monotonic.
#[inline(always)]
pub fn fade_q14(f: u32) -> i32 {
    let i = ((f >> 8) & 255) as usize;
    let frac = (f & 255) as i32;
    let (a, b) = (i32::from(FADE_Q15[i]), i32::from(FADE_Q15[i + 1]));
    ((a << 8) + (b - a) * frac + 256) >> 9
}

/// Perlin's improved-noise gradient `hash & 15` (twelve cube-edge directions, four of
/// them twice) dotted with the offset `(x, y, z)` (Q15 each, `|·| <= 32768`): Q15,
/// `|result| <= 65536`.
#[inline(always)]
fn grad(hash: u32, x: i32, y: i32, z: i32) -> i32 {
    match hash & 15 {
        0 => x + y,
        1 => -x + y,
        2 => x - y,
        3 => -x - y,
        4 => x + z,
        5 => -x + z,
        6 => x - z,
        7 => -x - z,
        8 => y + z,
        9 => -y + z,
        10 => y - z,
        11 => -y - z,
        12 => y + x,
        13 => -y + z,
        14 => y - x,
        _ => -y - z,
    }
}

/// `a + (b − a) · w` with a Q14 weight `w` in `0..=16384`. `a`, `b` are dot products or
/// blends of them, `|·| <= 65536`, so `|b − a| <= 131072`; halving the difference first
/// keeps the product within `2^30` for every input (one Q15 LSB of rounding).
#[inline(always)]
fn lerp(a: i32, b: i32, w: i32) -> i32 {
    a + ((((b - a) >> 1) * w) >> 13)
}

/// Perlin's improved gradient noise at `(x, y, z)` (I16F16 bits, lattice units; any `i32`):
/// Q15, `0` at every lattice point, period [`PERIOD`] cells on each axis, smooth (C²)
/// between cells. Never panics; no overflow for any input.
#[inline]
pub fn noise3(x: i32, y: i32, z: i32) -> i32 {
    // Cell (mod 256) and Q16 fraction; arithmetic shift floors negative coordinates.
    // Cells masked to 0..=255 first, so every hash sum below stays under 512.
    let cell = |c: i32| ((c >> 16) & 255) as u32;
    let (xi, yi, zi) = (cell(x), cell(y), cell(z));
    let (xf, yf, zf) = (x as u32 & 0xFFFF, y as u32 & 0xFFFF, z as u32 & 0xFFFF);
    let (u, v, w) = (fade_q14(xf), fade_q14(yf), fade_q14(zf));
    // Offsets from the low corner (Q15, 0..32767) and from the high one (−32768..−1).
    let (x0, y0, z0) = ((xf >> 1) as i32, (yf >> 1) as i32, (zf >> 1) as i32);
    let (x1, y1, z1) = (x0 - 32768, y0 - 32768, z0 - 32768);
    // Perlin's hashes: A = p[X] + Y, AA = p[A] + Z, AB = p[A + 1] + Z, and B likewise.
    let a = perm(xi) + yi;
    let b = perm(xi + 1) + yi;
    let (aa, ab) = (perm(a) + zi, perm(a + 1) + zi);
    let (ba, bb) = (perm(b) + zi, perm(b + 1) + zi);
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn perm_is_a_permutation() {
        let mut seen = [false; 256];
        for &p in PERM.iter() {
            assert!(!seen[usize::from(p)]);
            seen[usize::from(p)] = true;
        }
    }

    #[test]
    fn fade_ends_and_middle() {
        assert_eq!(fade_q14(0), 0);
        assert_eq!(fade_q14(32768), 8192);
        assert!(fade_q14(65535) >= 16383);
        for f in 0..65536u32 {
            let t = f64::from(f) / 65536.0;
            let exact = t * t * t * (10.0 + t * (6.0 * t - 15.0)) * 16384.0;
            let w = fade_q14(f);
            assert!(
                (f64::from(w) - exact).abs() <= 1.0,
                "fade {f}: {w} vs {exact}"
            );
        }
    }

    #[test]
    fn lattice_points_are_zero() {
        for (x, y, z) in [
            (0, 0, 0),
            (1, 2, 3),
            (-1, -200, 77),
            (255, 256, -32768),
            (32767, -32768, 0),
        ] {
            assert_eq!(noise3(x << 16, y << 16, z << 16), 0);
        }
    }
}
