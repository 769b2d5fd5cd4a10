//! The f64 reference for fixel's solid textures, written from the published algorithm
//! (Perlin, "Improving Noise", SIGGRAPH 2002, and his Java reference code) and the seeds'
//! formulas (seed `000` §4.1.1 turbulence and its truncation at the pixel size; marble as
//! `sin(x + turbulence)`; wood rings). It shares only data with fixel: the permutation
//! table, the colour-ramp keys and pattern constants, and the vertices.
//!
//! Everything here is `f64`: lattice coordinates in cells, noise in about `-1..1`,
//! turbulence `Σ |noise(2^k p)| / 2^k`, colours in `0..=1` per channel.

use super::raster::{barycentrics, rasterize, signed_area2, WindowVertex};
use fixel::geometry::Vertex;

/// Perlin's doubled permutation table `p[512]` from fixel's 256 entries (data).
fn p() -> &'static [usize; 512] {
    static P: std::sync::OnceLock<[usize; 512]> = std::sync::OnceLock::new();
    P.get_or_init(|| {
        let perm = fixel::shading::noise::PERM;
        core::array::from_fn(|i| usize::from(perm[i % 256]))
    })
}

fn fade(t: f64) -> f64 {
    t * t * t * (t * (t * 6.0 - 15.0) + 10.0)
}

fn lerp(t: f64, a: f64, b: f64) -> f64 {
    a + t * (b - a)
}

/// Perlin's `grad`: the low 4 bits of the hash pick one of 12 gradient directions.
fn grad(hash: usize, x: f64, y: f64, z: f64) -> f64 {
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

/// The colour of a piecewise-linear ramp (`(position 0..=255, 0xRRGGBB)` keys) at position
/// `x` (`0..=255`, clamped), channels `0..=1`.
pub fn ramp(keys: &[(u8, u32)], x: f64) -> [f64; 3] {
    let ch = |c: u32, s: u32| f64::from((c >> s) & 255) / 255.0;
    let rgb = |c: u32| [ch(c, 16), ch(c, 8), ch(c, 0)];
    let x = x.clamp(0.0, 255.0);
    let first = keys[0];
    if x <= f64::from(first.0) {
        return rgb(first.1);
    }
    for w in keys.windows(2) {
        let (a, b) = (w[0], w[1]);
        if x <= f64::from(b.0) {
            let t = (x - f64::from(a.0)) / (f64::from(b.0) - f64::from(a.0));
            let (ca, cb) = (rgb(a.1), rgb(b.1));
            return core::array::from_fn(|i| ca[i] + t * (cb[i] - ca[i]));
        }
    }
    rgb(keys[keys.len() - 1].1)
}

/// A solid texture in f64: colour at a point (cells), given the turbulence there.
#[derive(Clone, Copy, Debug)]
pub enum RefPattern {
    /// `ramp((1 + sin(2π (f x + a t))) / 2 · 255)`: `f` turns per cell, `a` turns.
    Marble {
        /// Ramp keys.
        keys: &'static [(u8, u32)],
        /// Turns per cell.
        freq: f64,
        /// Turns per unit turbulence.
        amp: f64,
    },
    /// `ramp(frac(rings · sqrt(x² + z²) + a t) · 256)`.
    Wood {
        /// Ramp keys.
        keys: &'static [(u8, u32)],
        /// Rings per cell.
        rings: f64,
        /// Rings per unit turbulence.
        amp: f64,
    },
    /// `ramp(turbulence(2^s p) · 256)`.
    Granite {
        /// Ramp keys.
        keys: &'static [(u8, u32)],
        /// Grain scale `s`.
        shift: u32,
    },
    /// `a` or `b` by a third noise with a smooth threshold: see [`select_color`].
    Select {
        /// Below the threshold.
        a: &'static RefPattern,
        /// Above it.
        b: &'static RefPattern,
        /// Threshold, noise units.
        threshold: f64,
        /// Blend width, noise units.
        width: f64,
        /// Selector scale `2^shift`.
        shift: u32,
        /// Selector offset, cells.
        offset: [f64; 3],
    },
}

impl RefPattern {
    /// The demonstration patterns, from fixel's preset constants (data).
    pub fn presets() -> [RefPattern; 3] {
        use fixel::shading::noise::presets::*;
        [
            RefPattern::Marble {
                keys: &MARBLE_KEYS,
                freq: f64::from(MARBLE_FREQ) / 65536.0,
                amp: f64::from(MARBLE_AMP) / 256.0,
            },
            RefPattern::Wood {
                keys: &WOOD_KEYS,
                rings: f64::from(WOOD_RINGS) / 256.0,
                amp: f64::from(WOOD_AMP) / 256.0,
            },
            RefPattern::Granite {
                keys: &GRANITE_KEYS,
                shift: u32::from(GRANITE_SHIFT),
            },
        ]
    }

    /// The colour at `p` (cells) for a pixel of level of detail `lambda`.
    pub fn color(&self, p: [f64; 3], octaves: RefOctaves, lambda: f64) -> [f64; 3] {
        match *self {
            RefPattern::Marble { keys, freq, amp } => {
                let t = turbulence(p, octaves, lambda);
                let phase = freq * p[0] + amp * t;
                let s = (2.0 * std::f64::consts::PI * phase).sin();
                ramp(keys, (1.0 + s) / 2.0 * 255.0)
            }
            RefPattern::Wood { keys, rings, amp } => {
                let t = turbulence(p, octaves, lambda);
                let r = (p[0] * p[0] + p[2] * p[2]).sqrt();
                let ring = rings * r + amp * t;
                ramp(keys, (ring - ring.floor()) * 256.0)
            }
            RefPattern::Granite { keys, shift } => {
                let s = f64::from(1u32 << shift);
                let t = turbulence(p.map(|c| c * s), octaves, lambda + f64::from(shift));
                ramp(keys, t * 256.0)
            }
            RefPattern::Select {
                a,
                b,
                threshold,
                width,
                shift,
                offset,
            } => select_color(*a, *b, threshold, width, shift, offset, p, octaves, lambda),
        }
    }
}

/// One triangle's vertices seen by the reference: window positions and f64 varyings
/// (point in cells, intensity `0..=1`).
struct RefSolidTri {
    win: [WindowVertex; 3],
    point: [[f64; 3]; 3],
    intensity: [f64; 3],
    /// The axes of the coordinate plane the triangle is most parallel to (footprint pair).
    pair: (usize, usize),
}

impl RefSolidTri {
    /// Barycentric weights at window point `(x, y)` (may be outside the triangle), of the
    /// exact (unsnapped) window positions, as GL interpolates.
    fn bary(&self, x: f64, y: f64) -> [f64; 3] {
        barycentrics(&self.win, x, y)
    }

    /// Perspective-correct point and intensity at window point `(x, y)`.
    fn at(&self, x: f64, y: f64) -> ([f64; 3], f64) {
        let l = self.bary(x, y);
        let q = [0, 1, 2].map(|i| l[i] * self.win[i].inv_w);
        let qs = q[0] + q[1] + q[2];
        let p = core::array::from_fn(|j| (0..3).map(|i| q[i] * self.point[i][j]).sum::<f64>() / qs);
        let k = (0..3).map(|i| q[i] * self.intensity[i]).sum::<f64>() / qs;
        (p, k)
    }

    /// `log2` of the footprint at `(x, y)`: the longer of the screen derivatives of the
    /// footprint pair (central differences).
    fn lambda(&self, x: f64, y: f64) -> f64 {
        let h = 1e-3;
        let (a, b) = self.pair;
        let d = |dx: f64, dy: f64| {
            let (p0, _) = self.at(x - dx, y - dy);
            let (p1, _) = self.at(x + dx, y + dy);
            let (da, db) = ((p1[a] - p0[a]) / (2.0 * h), (p1[b] - p0[b]) / (2.0 * h));
            (da * da + db * db).sqrt()
        };
        d(h, 0.0).max(d(0.0, h)).max(1e-12).log2()
    }
}

/// A rendered reference image: colour per pixel (`0..=1`) and coverage.
pub struct RefSolidImage {
    /// Width.
    pub width: u32,
    /// Height.
    pub height: u32,
    /// Colours, row-major.
    pub rgb: Vec<[f64; 3]>,
    /// Coverage (pixel centre, top-left rule).
    pub covered: Vec<bool>,
}

impl RefSolidImage {
    /// The colours as RGB565 (rounded once).
    pub fn rgb565(&self) -> Vec<u16> {
        self.rgb
            .iter()
            .map(|&c| super::rgb565_from_f64(c))
            .collect()
    }
}

/// Renders front-facing triangles of solid-texture vertices (fixel's `[x, y, z, i]`
/// varyings: I16F16 cells and Q8.16 intensity) with `pattern`: coverage at pixel centres,
/// the pattern sampled on an `ss × ss` grid inside each covered pixel and averaged (`ss =
/// 1`: at the centre). No depth test: meant for one convex object or a plane.
pub fn render_solid(
    tris: &[[Vertex<4>; 3]],
    pattern: RefPattern,
    octaves: RefOctaves,
    ss: u32,
    width: u32,
    height: u32,
) -> RefSolidImage {
    render_solid_lit(tris, pattern, octaves, ss, width, height, RefLight::Vertex)
}

/// Where the light of a solid texture comes from.
#[derive(Clone, Copy)]
pub enum RefLight<'a> {
    /// The interpolated per-vertex intensity (varying 3).
    Vertex,
    /// A function of the object-space point (cells), `0..=1` (a 3D light map: see
    /// [`light_map_trilinear`] and [`inverse_square`]).
    At(&'a dyn Fn([f64; 3]) -> f64),
}

/// [`render_solid`] with the light from `light`.
pub fn render_solid_lit(
    tris: &[[Vertex<4>; 3]],
    pattern: RefPattern,
    octaves: RefOctaves,
    ss: u32,
    width: u32,
    height: u32,
    light: RefLight<'_>,
) -> RefSolidImage {
    let n = (width * height) as usize;
    let mut img = RefSolidImage {
        width,
        height,
        rgb: vec![[0.0; 3]; n],
        covered: vec![false; n],
    };
    for tri in tris {
        let Some(win) = super::raster::window_of(tri, width, height) else {
            continue;
        };
        if signed_area2(&win) >= 0.0 {
            continue; // back face (or degenerate)
        }
        let point = tri.map(|v| [0, 1, 2].map(|j| f64::from(v.varyings[j]) / 65536.0));
        let intensity = tri.map(|v| f64::from(v.varyings[3]) / f64::from(256 << 16));
        let t = RefSolidTri {
            win,
            point,
            intensity,
            pair: footprint_pair(&point),
        };
        rasterize(&win, width, height, |x, y, _| {
            let mut acc = [0.0; 3];
            for sy in 0..ss {
                for sx in 0..ss {
                    let px = f64::from(x) + (f64::from(sx) + 0.5) / f64::from(ss);
                    let py = f64::from(y) + (f64::from(sy) + 0.5) / f64::from(ss);
                    let (p, k) = t.at(px, py);
                    let lambda = match octaves {
                        RefOctaves::Band { .. } => t.lambda(px, py),
                        RefOctaves::Fixed(_) => 0.0,
                    };
                    let c = pattern.color(p, octaves, lambda);
                    let k = match light {
                        RefLight::Vertex => k,
                        RefLight::At(f) => f(p),
                    }
                    .clamp(0.0, 1.0);
                    for i in 0..3 {
                        acc[i] += c[i] * k;
                    }
                }
            }
            let i = (y * width + x) as usize;
            let s2 = f64::from(ss * ss);
            img.rgb[i] = acc.map(|a| a / s2);
            img.covered[i] = true;
        });
    }
    img
}

/// The two axes other than the one the triangle's normal is closest to (ties: z, then x).
pub fn footprint_pair(p: &[[f64; 3]; 3]) -> (usize, usize) {
    let e1: [f64; 3] = core::array::from_fn(|j| p[1][j] - p[0][j]);
    let e2: [f64; 3] = core::array::from_fn(|j| p[2][j] - p[0][j]);
    let n = [
        (e1[1] * e2[2] - e1[2] * e2[1]).abs(),
        (e1[2] * e2[0] - e1[0] * e2[2]).abs(),
        (e1[0] * e2[1] - e1[1] * e2[0]).abs(),
    ];
    if n[2] >= n[0] && n[2] >= n[1] {
        (0, 1)
    } else if n[0] >= n[1] {
        (1, 2)
    } else {
        (2, 0)
    }
}

/// The flame of seed `000` §4.2 as fixel defines it (`fixel::shading::noise::flame`), in
/// f64: turbulence at `(2x, 2y − rise·t, churn·t)`, bend `= gain · (turbulence − mid)`,
/// colour `ramp(|x| + y/2 + bend)` times the fade `1 − y + bend / 2`. `x`, `y` in flame
/// units, `t` in seconds; constants from fixel's (data).
pub fn flame(x: f64, y: f64, t: f64, octaves: u32) -> [f64; 3] {
    use fixel::shading::noise::{FLAME_CHURN, FLAME_GAIN, FLAME_KEYS, FLAME_RISE, FLAME_TURB_MID};
    let rise = f64::from(FLAME_RISE) / 65536.0;
    let churn = f64::from(FLAME_CHURN) / 65536.0;
    let p = [2.0 * x, 2.0 * y - rise * t, churn * t];
    let turb = turbulence(p, RefOctaves::Fixed(octaves), 0.0);
    let bend = f64::from(FLAME_GAIN) / 256.0 * (turb - f64::from(FLAME_TURB_MID) / 32768.0);
    let arg = x.abs().min(2.0) + y.clamp(0.0, 2.0) / 2.0 + bend;
    let c = ramp(&FLAME_KEYS, (arg * 256.0).clamp(0.0, 255.0));
    let fade = (1.0 - y + bend / 2.0).clamp(0.0, 1.0);
    c.map(|v| v * fade)
}

/// A baked 3D light map read back in f64 (seed `000` §4.3): trilinear interpolation of the
/// `side³` texels (`x` fastest, `255` = 1.0) between texel centres `origin + (i + 0.5) ·
/// texel` (cells), clamp-to-edge; `0..=1`.
pub fn light_map_trilinear(
    texels: &[u8],
    side: u32,
    origin: [f64; 3],
    texel: f64,
    p: [f64; 3],
) -> f64 {
    let s = side as i64;
    let at = |i: i64, j: i64, k: i64| {
        let c = |v: i64| v.clamp(0, s - 1) as usize;
        f64::from(texels[(c(k) * s as usize + c(j)) * s as usize + c(i)])
    };
    let u: [f64; 3] =
        core::array::from_fn(|a| ((p[a] - origin[a]) / texel - 0.5).clamp(0.0, (s - 1) as f64));
    let (i, j, k) = (
        u[0].floor() as i64,
        u[1].floor() as i64,
        u[2].floor() as i64,
    );
    let (fx, fy, fz) = (u[0] - i as f64, u[1] - j as f64, u[2] - k as f64);
    let l = |a: f64, b: f64, t: f64| a + (b - a) * t;
    let plane = |k: i64| {
        l(
            l(at(i, j, k), at(i + 1, j, k), fx),
            l(at(i, j + 1, k), at(i + 1, j + 1, k), fx),
            fy,
        )
    };
    l(plane(k), plane(k + 1), fz) / 255.0
}

/// The light a 3D light map is baked from, unbaked (seed `000` §4.3): `min(1, ambient +
/// Σ power / max(d², 1/16))`, `d` the distance in cells from `p` to each light (`[x, y, z,
/// power]`).
pub fn inverse_square(lights: &[[f64; 4]], ambient: f64, p: [f64; 3]) -> f64 {
    let e: f64 = lights
        .iter()
        .map(|l| {
            l[3] / (0..3)
                .map(|a| (p[a] - l[a]).powi(2))
                .sum::<f64>()
                .max(1.0 / 16.0)
        })
        .sum();
    (ambient + e).min(1.0)
}

/// The flame drawn on a quad (fixel's `[x, y]` varyings, Q16 flame units; no culling),
/// at time `t` seconds with `octaves` of turbulence, sampled on an `ss × ss` grid inside
/// each covered pixel and averaged (`ss = 1`: at the centre).
pub fn render_flame(
    tris: &[[Vertex<2>; 3]],
    t: f64,
    octaves: u32,
    ss: u32,
    width: u32,
    height: u32,
) -> RefSolidImage {
    let n = (width * height) as usize;
    let mut img = RefSolidImage {
        width,
        height,
        rgb: vec![[0.0; 3]; n],
        covered: vec![false; n],
    };
    for tri in tris {
        let Some(win) = super::raster::window_of(tri, width, height) else {
            continue;
        };
        let xy = tri.map(|v| [0, 1].map(|j| f64::from(v.varyings[j]) / 65536.0));
        rasterize(&win, width, height, |x, y, _| {
            let mut acc = [0.0; 3];
            for sy in 0..ss {
                for sx in 0..ss {
                    let px = f64::from(x) + (f64::from(sx) + 0.5) / f64::from(ss);
                    let py = f64::from(y) + (f64::from(sy) + 0.5) / f64::from(ss);
                    let l = barycentrics(&win, px, py);
                    let q = [0, 1, 2].map(|i| l[i] * win[i].inv_w);
                    let qs = q[0] + q[1] + q[2];
                    let v: [f64; 2] =
                        core::array::from_fn(|j| (0..3).map(|i| q[i] * xy[i][j]).sum::<f64>() / qs);
                    let c = flame(v[0], v[1], t, octaves);
                    for i in 0..3 {
                        acc[i] += c[i];
                    }
                }
            }
            let i = (y * width + x) as usize;
            img.rgb[i] = acc.map(|a| a / f64::from(ss * ss));
            img.covered[i] = true;
        });
    }
    img
}

/// Composition by selection (fixel's `Select`), in f64: the selector `n = noise(2^shift ·
/// p + offset)`, `t = clamp((n − (threshold − width/2)) / width, 0, 1)`, the weight of `b`
/// `w = 3t² − 2t³`, and the colour `a · (1 − w) + b · w`. Threshold and width in noise
/// units (`-1..1`), offset in cells.
#[allow(clippy::too_many_arguments)]
pub fn select_color(
    a: RefPattern,
    b: RefPattern,
    threshold: f64,
    width: f64,
    shift: u32,
    offset: [f64; 3],
    p: [f64; 3],
    octaves: RefOctaves,
    lambda: f64,
) -> [f64; 3] {
    let s = f64::from(1u32 << shift);
    let n = noise(
        p[0] * s + offset[0],
        p[1] * s + offset[1],
        p[2] * s + offset[2],
    );
    let t = ((n - (threshold - width / 2.0)) / width).clamp(0.0, 1.0);
    let w = t * t * (3.0 - 2.0 * t);
    let (ca, cb) = (a.color(p, octaves, lambda), b.color(p, octaves, lambda));
    core::array::from_fn(|i| ca[i] * (1.0 - w) + cb[i] * w)
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
