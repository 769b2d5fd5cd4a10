//! The f64 renderers of solid textures and of the flame (coverage at pixel centres,
//! perspective-correct varyings, supersampled patterns), and the 3D light they can be lit by.

use super::{flame, RefOctaves, RefPattern};
use crate::reference::raster::{barycentrics, rasterize, signed_area2, WindowVertex};
use fixel::geometry::Vertex;

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
            .map(|&c| crate::reference::rgb565_from_f64(c))
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
        let Some(win) = crate::reference::raster::window_of(tri, width, height) else {
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

/// A baked 3D light map read back in f64: trilinear interpolation of the
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

/// The light a 3D light map is baked from, unbaked: `min(1, ambient +
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
    render_quad_with(tris, ss, width, height, |x, y| flame(x, y, t, octaves))
}

/// [`render_flame`] with any colour of the flame point `(x, y)` (flame units): the flame
/// from baked layers draws through it too.
pub fn render_quad_with(
    tris: &[[Vertex<2>; 3]],
    ss: u32,
    width: u32,
    height: u32,
    color: impl Fn(f64, f64) -> [f64; 3],
) -> RefSolidImage {
    let n = (width * height) as usize;
    let mut img = RefSolidImage {
        width,
        height,
        rgb: vec![[0.0; 3]; n],
        covered: vec![false; n],
    };
    for tri in tris {
        let Some(win) = crate::reference::raster::window_of(tri, width, height) else {
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
                    let c = color(v[0], v[1]);
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
