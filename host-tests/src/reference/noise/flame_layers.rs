//! The flame from baked layers (fixel's `BakedFlame`), in f64, from its definition: each
//! layer the partial turbulence `Σ_k |noise_P(2^k u, 2^k v, z)| / 2^k` of a noise whose
//! lattice tiles every `2^k P` cells in `x` and `y`, read at `(2x, 2y − rise · t)` cells,
//! the layers summed, then the flame's colour of that turbulence. Shares only data with
//! fixel (the permutation, the layers' constants, the ramp keys).

use super::pattern::flame_color;
use super::{fade, grad, lerp, p};
use fixel::shading::noise::FlameLayer;

/// Perlin's improved noise at `(x, y, z)` (cells) with the cells of `x` and `y` taken
/// modulo `period` (a power of two up to 256) before hashing.
pub fn noise_tiled(x: f64, y: f64, z: f64, period: usize) -> f64 {
    let p = p();
    let (fx, fy, fz) = (x.floor(), y.floor(), z.floor());
    let cell = |f: f64, m: usize| (f.rem_euclid(256.0) as usize) % m;
    let (xi, yi, zi) = (cell(fx, period), cell(fy, period), cell(fz, 256));
    let (xj, yj) = ((xi + 1) % period, (yi + 1) % period);
    let (x, y, z) = (x - fx, y - fy, z - fz);
    let (u, v, w) = (fade(x), fade(y), fade(z));
    let (pa, pb) = (p[xi], p[xj]);
    let (aa, ab) = (p[pa + yi] + zi, p[pa + yj] + zi);
    let (ba, bb) = (p[pb + yi] + zi, p[pb + yj] + zi);
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

/// A layer's partial turbulence at `(u, v)` cells (in about `0..2`).
pub fn layer_turbulence(layer: &FlameLayer, u: f64, v: f64) -> f64 {
    let z = f64::from(layer.z) / 65536.0;
    (u32::from(layer.first)..u32::from(layer.first) + u32::from(layer.octaves))
        .map(|k| {
            let s = f64::from(1u32 << k);
            let period = (1usize << (u32::from(layer.period_log2) + k)).min(256);
            noise_tiled(u * s, v * s, z, period).abs() / s
        })
        .sum()
}

/// Where the layers are read.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum LayerSampling {
    /// At the point itself: the flame of the definition.
    Continuous,
    /// At the centre of the nearest texel of a `side x side` tile: the baked draw's
    /// sampling, with exact texels.
    Nearest(u32),
}

/// The flame from `layers` at `(x, y)` (flame units) and time `t` (seconds).
pub fn flame_layers(
    layers: &[FlameLayer],
    x: f64,
    y: f64,
    t: f64,
    sampling: LayerSampling,
) -> [f64; 3] {
    let turb: f64 = layers
        .iter()
        .map(|l| {
            let (u, v) = (2.0 * x, 2.0 * y - f64::from(l.rise) / 65536.0 * t);
            match sampling {
                LayerSampling::Continuous => layer_turbulence(l, u, v),
                LayerSampling::Nearest(side) => {
                    let period = f64::from(1u32 << l.period_log2);
                    let texel = period / f64::from(side);
                    let centre = |c: f64| ((c / texel).floor() + 0.5) * texel;
                    layer_turbulence(l, centre(u), centre(v))
                }
            }
        })
        .sum();
    flame_color(x, y, turb)
}
