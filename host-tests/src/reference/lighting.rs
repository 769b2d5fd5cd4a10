//! The f64 reference for per-pixel lighting and bump mapping,
//! written from the formulas; it shares only data with fixel (the mesh arrays, the
//! matrices, the light, the textures and the height bytes).
//!
//! Per pixel, with perspective-correct barycentrics from the exact window positions:
//!
//! ```text
//! p, N, t, uv        interpolated (view-space position, normal, tangent), N normalised,
//!                    t made orthogonal to N and normalised, Pu = t, Pv = N × t
//! bump (Blinn)       N' = N + (Bu (N × Pv) − Bv (N × Pu))   with Bu = σ ∂h/∂i,
//!                    Bv = handedness · σ ∂h/∂j (a mirrored map runs against Pv)
//! normal map         N' = 2 c − 1 in the frame (t, handedness · Pv, N), c bilinear
//! L = normalize(light − p) (point) or the direction;  V = (0, 0, 1)
//! diffuse  d = max(0, N'·L);  specular s = max(0, R·V)^e or max(0, N'·H)^e, 0 if N'·L <= 0
//! colour   texel · min(1, ka + kd d) + ks s,  clamped to [0, 1]
//! ```
//!
//! Height derivatives are central differences `(h(i+1, j) − h(i−1, j)) / 2^(k+1)` at the
//! nearest texel of the level `k` that GL's `NEAREST_MIPMAP_NEAREST` rule picks from this
//! reference's own `lambda` (levels are the reference's own 2 x 2 box means).

use super::mip::rho;
use super::raster::{barycentrics, rasterize, signed_area2, to_window};
use super::sample::sample;
use super::types::{RefFilter, RefImage, RefTexture, RefVertex, RefWrap};

/// The light, in view space.
#[derive(Clone, Copy, Debug)]
pub enum RefLight {
    /// Unit vector towards the light.
    Directional([f64; 3]),
    /// Position.
    Point([f64; 3]),
}

/// The lighting model's coefficients.
#[derive(Clone, Copy, Debug)]
pub struct RefMaterial {
    pub ka: f64,
    pub kd: f64,
    pub ks: f64,
    pub exponent: f64,
    /// Blinn-Phong (half vector) rather than Phong (reflection).
    pub blinn: bool,
}

/// Where the per-pixel normal comes from.
#[derive(Clone, Copy, Debug)]
pub enum RefNormals<'a> {
    /// The interpolated normal.
    Flat,
    /// Blinn's perturbation from a square height map (level 0, `size x size`).
    Height {
        heights: &'a [u8],
        size: u32,
        strength: f64,
    },
    /// A tangent-space RGB565 normal map, bilinear.
    NormalMap(&'a RefTexture),
}

/// The mesh and its transforms, all f64.
#[derive(Clone, Debug)]
pub struct RefLitScene {
    pub positions: Vec<[f64; 3]>,
    pub normals: Vec<[f64; 3]>,
    pub uvs: Vec<[f64; 2]>,
    /// Tangent and handedness.
    pub tangents: Vec<([f64; 3], f64)>,
    pub indices: Vec<[u16; 3]>,
    /// Model-view, `m[row][col]`.
    pub model_view: [[f64; 4]; 4],
    pub projection: [[f64; 4]; 4],
    pub light: RefLight,
    pub material: RefMaterial,
}

fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}
fn cross(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}
fn norm(a: [f64; 3]) -> [f64; 3] {
    let l = dot(a, a).sqrt();
    if l == 0.0 {
        [0.0; 3]
    } else {
        a.map(|c| c / l)
    }
}
fn add(a: [f64; 3], b: [f64; 3], s: f64) -> [f64; 3] {
    [a[0] + s * b[0], a[1] + s * b[1], a[2] + s * b[2]]
}
fn mul(m: &[[f64; 4]; 4], v: [f64; 4]) -> [f64; 4] {
    core::array::from_fn(|r| (0..4).map(|c| m[r][c] * v[c]).sum())
}

/// `(diffuse intensity, specular)` of the model for unit `n`, `l`, `v`.
pub fn light(m: &RefMaterial, n: [f64; 3], l: [f64; 3], v: [f64; 3]) -> (f64, f64) {
    let ndl = dot(n, l);
    let i = (m.ka + m.kd * ndl.max(0.0)).min(1.0);
    if ndl <= 0.0 {
        return (i, 0.0);
    }
    let x = if m.blinn {
        dot(n, norm(add(l, v, 1.0)))
    } else {
        dot(add(n.map(|c| c * 2.0 * ndl), l, -1.0), v)
    };
    (i, m.ks * x.max(0.0).powf(m.exponent))
}

/// Mean 2 x 2 levels of a square height map, level 0 first.
fn height_levels(heights: &[u8], size: u32) -> Vec<(u32, Vec<f64>)> {
    let mut out = vec![(
        size,
        heights.iter().map(|&h| f64::from(h)).collect::<Vec<_>>(),
    )];
    while out.last().map_or(1, |l| l.0) > 1 {
        let (s, src) = out.last().cloned().unwrap_or((1, vec![0.0]));
        let d = s / 2;
        let mut dst = vec![0.0; (d * d) as usize];
        for j in 0..d {
            for i in 0..d {
                let at = |x: u32, y: u32| src[(y * s + x) as usize];
                let sum = at(2 * i, 2 * j)
                    + at(2 * i + 1, 2 * j)
                    + at(2 * i, 2 * j + 1)
                    + at(2 * i + 1, 2 * j + 1);
                // The same rounding as the stored chain: the levels are data, bytes.
                dst[(j * d + i) as usize] = ((sum + 2.0) / 4.0).floor();
            }
        }
        out.push((d, dst));
    }
    out
}

/// Renders `scene` at `width x height` (the viewport is the whole frame), back faces culled,
/// GL_LESS depth, with colour texture `tex` (repeat, `filter`) and normals from `normals`.
pub fn render(
    scene: &RefLitScene,
    tex: &RefTexture,
    filter: RefFilter,
    normals: RefNormals<'_>,
    width: u32,
    height: u32,
) -> RefImage {
    let mut img = RefImage::new(width, height);
    let mut zbuf = vec![f64::INFINITY; (width * height) as usize];
    let levels = match normals {
        RefNormals::Height { heights, size, .. } => height_levels(heights, size),
        _ => Vec::new(),
    };
    let mv = &scene.model_view;
    let vtx = |i: u16| {
        let i = usize::from(i);
        let p = scene.positions[i];
        let pv = mul(mv, [p[0], p[1], p[2], 1.0]);
        let dir = |d: [f64; 3]| {
            let r = mul(mv, [d[0], d[1], d[2], 0.0]);
            [r[0], r[1], r[2]]
        };
        let n = norm(dir(scene.normals[i]));
        let (t, hand) = scene.tangents[i];
        let t = dir(t);
        let t = norm(add(t, n, -dot(t, n)));
        let clip = mul(&scene.projection, pv);
        (clip, [pv[0], pv[1], pv[2]], n, t, hand, scene.uvs[i])
    };
    for tri in &scene.indices {
        let v = tri.map(vtx);
        let w = |k: usize| {
            to_window(
                &RefVertex {
                    clip: v[k].0,
                    uv: [0.0; 2],
                    color: [0.0; 3],
                },
                width,
                height,
            )
        };
        let (Some(a), Some(b), Some(c)) = (w(0), w(1), w(2)) else {
            continue;
        };
        let win = [a, b, c];
        if signed_area2(&win) >= 0.0 {
            continue;
        }
        // Perspective-correct interpolation at window point (x, y).
        let interp = |x: f64, y: f64| {
            let l = barycentrics(&win, x, y);
            let q = [0, 1, 2].map(|i| l[i] * win[i].inv_w);
            let qs: f64 = q.iter().sum();
            let q = q.map(|c| c / qs);
            let z: f64 = (0..3).map(|i| l[i] * win[i].z).sum();
            let v3 = |f: &dyn Fn(usize) -> [f64; 3]| -> [f64; 3] {
                core::array::from_fn(|k| (0..3).map(|i| q[i] * f(i)[k]).sum())
            };
            let p = v3(&|i| v[i].1);
            let n = v3(&|i| v[i].2);
            let t = v3(&|i| v[i].3);
            let hand: f64 = (0..3).map(|i| q[i] * v[i].4).sum();
            let uv: [f64; 2] = core::array::from_fn(|k| (0..3).map(|i| q[i] * v[i].5[k]).sum());
            (z, p, n, t, hand, uv)
        };
        rasterize(&win, width, height, |x, y, _| {
            let (cx, cy) = (f64::from(x) + 0.5, f64::from(y) + 0.5);
            let (z, p, n, t, hand, uv) = interp(cx, cy);
            let idx = (y * width + x) as usize;
            if z >= zbuf[idx] {
                return;
            }
            zbuf[idx] = z;
            let n = norm(n);
            let t = norm(add(t, n, -dot(t, n)));
            let hand = if hand < 0.0 { -1.0 } else { 1.0 };
            let pu = t;
            let pv = cross(n, t);
            let np = match normals {
                RefNormals::Flat => n,
                RefNormals::Height { size, strength, .. } => {
                    // lambda from the uv derivatives in texels (one pixel right and down).
                    let (.., ux) = interp(cx + 1.0, cy);
                    let (.., uy) = interp(cx, cy + 1.0);
                    let s = f64::from(size);
                    let d = [
                        [(ux[0] - uv[0]) * s, (ux[1] - uv[1]) * s],
                        [(uy[0] - uv[0]) * s, (uy[1] - uv[1]) * s],
                    ];
                    let lambda = rho(d).log2();
                    let k = if lambda <= 0.5 {
                        0
                    } else {
                        ((lambda + 0.5).ceil() as usize - 1).min(levels.len() - 1)
                    };
                    let (ls, hk) = (&levels[k].0, &levels[k].1);
                    let ls = i64::from(*ls);
                    let scale = f64::from(1u32 << k);
                    let (fi, fj) = (
                        (uv[0] * s / scale).floor() as i64,
                        (uv[1] * s / scale).floor() as i64,
                    );
                    let h =
                        |i: i64, j: i64| hk[(j.rem_euclid(ls) * ls + i.rem_euclid(ls)) as usize];
                    let bu = strength * (h(fi + 1, fj) - h(fi - 1, fj)) / (2.0 * scale);
                    let bv = hand * strength * (h(fi, fj + 1) - h(fi, fj - 1)) / (2.0 * scale);
                    add(add(n, cross(n, pv), bu), cross(n, pu), -bv)
                }
                RefNormals::NormalMap(map) => {
                    let c = sample(
                        map,
                        uv,
                        RefFilter::Bilinear,
                        RefWrap::Repeat,
                        RefWrap::Repeat,
                    );
                    let m = c.map(|x| 2.0 * x - 1.0);
                    add(add(n.map(|x| x * m[2]), pu, m[0]), pv, hand * m[1])
                }
            };
            let np = norm(np);
            let l = match scene.light {
                RefLight::Directional(d) => norm(d),
                RefLight::Point(q) => norm(add(q, p, -1.0)),
            };
            let (i, s) = light(&scene.material, np, l, [0.0, 0.0, 1.0]);
            let texel = sample(tex, uv, filter, RefWrap::Repeat, RefWrap::Repeat);
            img.rgb[idx] = texel.map(|c| (c * i + s).clamp(0.0, 1.0));
            img.covered[idx] = true;
        });
    }
    img
}
