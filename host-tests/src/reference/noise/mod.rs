//! The f64 reference for fixel's solid textures, written from the published algorithm
//! (Perlin, "Improving Noise", SIGGRAPH 2002, and his Java reference code) and the seeds'
//! formulas (Perlin's turbulence and its truncation at the pixel size; marble as
//! `sin(x + turbulence)`; wood rings). It shares only data with fixel: the permutation
//! table, the colour-ramp keys and pattern constants, and the vertices.
//!
//! Everything here is `f64`: lattice coordinates in cells, noise in about `-1..1`,
//! turbulence `Σ |noise(2^k p)| / 2^k`, colours in `0..=1` per channel.
//!
//! This module holds the noise itself (3D and 4D gradient noise and turbulence); the
//! patterns coloured from it are in `pattern`, the renderers that draw them in `render`
//! (both re-exported here).

mod flame_layers;
mod pattern;
mod render;

pub use flame_layers::{flame_layers, layer_turbulence, noise_tiled, LayerSampling};
pub use pattern::{flame, flame_color, ramp, select_color, RefPattern};
pub use render::{
    footprint_pair, inverse_square, light_map_trilinear, render_flame, render_quad_with,
    render_solid, render_solid_lit, RefLight, RefSolidImage,
};

/// Perlin's doubled permutation table `p[512]` from fixel's 256 entries (data).
pub(crate) fn p() -> &'static [usize; 512] {
    static P: std::sync::OnceLock<[usize; 512]> = std::sync::OnceLock::new();
    P.get_or_init(|| {
        let perm = fixel::shading::noise::PERM;
        core::array::from_fn(|i| usize::from(perm[i % 256]))
    })
}

pub(crate) fn fade(t: f64) -> f64 {
    t * t * t * (t * (t * 6.0 - 15.0) + 10.0)
}

pub(crate) fn lerp(t: f64, a: f64, b: f64) -> f64 {
    a + t * (b - a)
}

/// Perlin's `grad`: the low 4 bits of the hash pick one of 12 gradient directions.
pub(crate) fn grad(hash: usize, x: f64, y: f64, z: f64) -> f64 {
    let h = hash & 15;
    let u = if h < 8 { x } else { y };
    let v = if h < 4 {
        y
    } else if h == 12 || h == 14 {
        x
    } else {
        z
    };
    (if h & 1 == 0 { u } else { -u }) + (if h & 2 == 0 { v } else { -v })
}

/// Perlin's improved noise at `(x, y, z)` in lattice cells.
pub fn noise(x: f64, y: f64, z: f64) -> f64 {
    let p = p();
    let (fx, fy, fz) = (x.floor(), y.floor(), z.floor());
    let cell = |f: f64| (f.rem_euclid(256.0)) as usize;
    let (xi, yi, zi) = (cell(fx), cell(fy), cell(fz));
    let (x, y, z) = (x - fx, y - fy, z - fz);
    let (u, v, w) = (fade(x), fade(y), fade(z));
    let a = p[xi] + yi;
    let aa = p[a] + zi;
    let ab = p[a + 1] + zi;
    let b = p[xi + 1] + yi;
    let ba = p[b] + zi;
    let bb = p[b + 1] + zi;
    lerp(
        w,
        lerp(
            v,
            lerp(u, grad(p[aa], x, y, z), grad(p[ba], x - 1.0, y, z)),
            lerp(
                u,
                grad(p[ab], x, y - 1.0, z),
                grad(p[bb], x - 1.0, y - 1.0, z),
            ),
        ),
        lerp(
            v,
            lerp(
                u,
                grad(p[aa + 1], x, y, z - 1.0),
                grad(p[ba + 1], x - 1.0, y, z - 1.0),
            ),
            lerp(
                u,
                grad(p[ab + 1], x, y - 1.0, z - 1.0),
                grad(p[bb + 1], x - 1.0, y - 1.0, z - 1.0),
            ),
        ),
    )
}

/// The noise at I16F16 lattice-unit bits (read exactly as f64).
pub fn noise_bits(x: i32, y: i32, z: i32) -> f64 {
    let c = |v: i32| f64::from(v) / 65536.0;
    noise(c(x), c(y), c(z))
}

/// How many octaves, and how each is weighted.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum RefOctaves {
    /// Octaves `0..n`, all of weight 1.
    Fixed(u32),
    /// The seeds' truncation at the pixel size with a one-octave fade: octave `k` weighs
    /// `clamp(1 − lambda − bias − k, 0, 1)` (lambda = `log2` of the footprint in cells),
    /// and the rest of it is the mean of `|noise|`, up to `max` octaves.
    Band {
        /// Most octaves.
        max: u32,
        /// Added to lambda.
        bias: f64,
    },
}

/// The mean of `|noise|`, estimated over 128³ points on a grid of step `1/φ ≈ 0.618` cell
/// per axis (not commensurate with the lattice; once, cached).
pub fn abs_noise_mean() -> f64 {
    static M: std::sync::OnceLock<f64> = std::sync::OnceLock::new();
    *M.get_or_init(|| {
        let n = 128;
        let mut sum = 0.0;
        for i in 0..n {
            for j in 0..n {
                for k in 0..n {
                    let f = |a: i32, s: f64| f64::from(a) * 0.618_033_988_749_895 + s;
                    sum += noise(f(i, 0.123), f(j, 0.377), f(k, 0.619)).abs();
                }
            }
        }
        sum / f64::from(n * n * n)
    })
}

/// Turbulence at `p` (cells): `Σ_k w_k |noise(2^k p)| / 2^k + (1 − w_k) mean / 2^k`.
pub fn turbulence(p: [f64; 3], octaves: RefOctaves, lambda: f64) -> f64 {
    let (n, weight): (u32, Box<dyn Fn(u32) -> f64>) = match octaves {
        RefOctaves::Fixed(n) => (n, Box::new(|_| 1.0)),
        RefOctaves::Band { max, bias } => (
            max,
            Box::new(move |k| (1.0 - lambda - bias - f64::from(k)).clamp(0.0, 1.0)),
        ),
    };
    let mean = abs_noise_mean();
    (0..n)
        .map(|k| {
            let s = f64::from(1u32 << k);
            let w = weight(k);
            let v = if w > 0.0 {
                noise(p[0] * s, p[1] * s, p[2] * s).abs()
            } else {
                0.0
            };
            (w * v + (1.0 - w) * mean) / s
        })
        .sum()
}

/// The 32 gradients of 4D gradient noise: the midpoints of the edges of the 4-cube
/// (three components ±1, one 0), in the order of Stefan Gustavson's `grad4` table
/// ("Simplex noise demystified", 2005): the zero at x for 0..8, y for 8..16, z for 16..24,
/// w for 24..32.
const GRAD4: [[f64; 4]; 32] = [
    [0.0, 1.0, 1.0, 1.0],
    [0.0, 1.0, 1.0, -1.0],
    [0.0, 1.0, -1.0, 1.0],
    [0.0, 1.0, -1.0, -1.0],
    [0.0, -1.0, 1.0, 1.0],
    [0.0, -1.0, 1.0, -1.0],
    [0.0, -1.0, -1.0, 1.0],
    [0.0, -1.0, -1.0, -1.0],
    [1.0, 0.0, 1.0, 1.0],
    [1.0, 0.0, 1.0, -1.0],
    [1.0, 0.0, -1.0, 1.0],
    [1.0, 0.0, -1.0, -1.0],
    [-1.0, 0.0, 1.0, 1.0],
    [-1.0, 0.0, 1.0, -1.0],
    [-1.0, 0.0, -1.0, 1.0],
    [-1.0, 0.0, -1.0, -1.0],
    [1.0, 1.0, 0.0, 1.0],
    [1.0, 1.0, 0.0, -1.0],
    [1.0, -1.0, 0.0, 1.0],
    [1.0, -1.0, 0.0, -1.0],
    [-1.0, 1.0, 0.0, 1.0],
    [-1.0, 1.0, 0.0, -1.0],
    [-1.0, -1.0, 0.0, 1.0],
    [-1.0, -1.0, 0.0, -1.0],
    [1.0, 1.0, 1.0, 0.0],
    [1.0, 1.0, -1.0, 0.0],
    [1.0, -1.0, 1.0, 0.0],
    [1.0, -1.0, -1.0, 0.0],
    [-1.0, 1.0, 1.0, 0.0],
    [-1.0, 1.0, -1.0, 0.0],
    [-1.0, -1.0, 1.0, 0.0],
    [-1.0, -1.0, -1.0, 0.0],
];

/// 4D gradient noise at `p` (cells), Perlin's construction one dimension up: the corner
/// `c` of the cell has the gradient `GRAD4[p[p[p[p[c0] + c1] + c2] + c3] mod 32]` (the
/// chained permutation), dotted with the offset to the point, blended by the quintic
/// fade along each axis.
pub fn noise4(p: [f64; 4]) -> f64 {
    let perm = self::p();
    let fl = p.map(f64::floor);
    let c: [usize; 4] = core::array::from_fn(|i| fl[i].rem_euclid(256.0) as usize);
    let f: [f64; 4] = core::array::from_fn(|i| p[i] - fl[i]);
    let mut sum = 0.0;
    for corner in 0..16usize {
        let d: [usize; 4] = core::array::from_fn(|i| (corner >> i) & 1);
        let h = perm[perm[perm[perm[c[0] + d[0]] + c[1] + d[1]] + c[2] + d[2]] + c[3] + d[3]];
        let g = GRAD4[h % 32];
        let dot: f64 = (0..4).map(|i| g[i] * (f[i] - d[i] as f64)).sum();
        let weight: f64 = (0..4)
            .map(|i| {
                let u = fade(f[i]);
                if d[i] == 1 {
                    u
                } else {
                    1.0 - u
                }
            })
            .product();
        sum += weight * dot;
    }
    sum
}

/// Animated turbulence in f64: `Σ_{k<n} |noise4(2^k p)| / 2^k`.
pub fn turbulence4(p: [f64; 4], octaves: u32) -> f64 {
    (0..octaves)
        .map(|k| {
            let s = f64::from(1u32 << k);
            noise4(p.map(|c| c * s)).abs() / s
        })
        .sum()
}
