//! The f64 reference of shadow mapping (Williams, SIGGRAPH 1978): the scene's depth rasterized from
//! the light into an f64 map by this module's own pass (the reference's clipper and
//! top-left coverage at texel centres, depth interpolated linearly in window space, no
//! quantization), then, per camera pixel, the point's light-space position interpolated
//! perspective-correctly from the vertices' light clip coordinates, divided by its `w`, and
//! compared, with the bias, against the map through the same three filters as fixel.
//!
//! Formulas (GL conventions; `size` the map side, depth in 16-bit steps `0..=65535`):
//!
//! ```text
//! light clip (x, y, z, w) = L · p_world
//! s = (x/w + 1) / 2,  t = (1 - y/w) / 2,  d = 65535 (z/w + 1) / 2
//! outside:  w <= 0, s or t outside [0, 1), d outside [0, 65535]
//! bias = c + min(max, k (|∂d/∂X| + |∂d/∂Y|)),  X = s size, Y = t size, per triangle
//! own shade (lit 0 inside the frustum): det[(x, y, w) of the three vertices] <= 0, the
//!           triangle turned away from the light or edge-on (counter-clockwise = front)
//! tap (i, j) lit  <=>  d - bias <= map[clamp(j)][clamp(i)]
//! single: tap(floor(X), floor(Y))
//! 2x2:    bilinear weights of X - 0.5, Y - 0.5 over the four taps around
//! 3x3:    mean of the nine taps centred on (floor(X), floor(Y))
//! ```
//!
//! It shares only data with fixel (matrices and mesh positions read back as f64).

use super::clip::{clip_triangle, fan};
use super::raster::{rasterize, signed_area2, to_window};
use super::types::{RefTriangle, RefVertex};

/// A 4x4 matrix, row-major, on column vectors.
pub type M4 = [[f64; 4]; 4];

/// `m · (p, 1)`.
pub fn transform(m: &M4, p: [f64; 3]) -> [f64; 4] {
    core::array::from_fn(|r| m[r][0] * p[0] + m[r][1] * p[1] + m[r][2] * p[2] + m[r][3])
}

/// `a · b`.
pub fn mul(a: &M4, b: &M4) -> M4 {
    core::array::from_fn(|r| core::array::from_fn(|c| (0..4).map(|k| a[r][k] * b[k][c]).sum()))
}

/// A scene for the reference: world-space triangles (counter-clockwise from their front),
/// the camera's world-to-clip matrix and frame size, the light's world-to-clip matrix.
#[derive(Clone, Debug)]
pub struct ShadowScene {
    /// Triangles, world space.
    pub tris: Vec<[[f64; 3]; 3]>,
    /// Camera projection times view.
    pub camera: M4,
    /// Light projection times view.
    pub light: M4,
    /// Frame width.
    pub width: u32,
    /// Frame height.
    pub height: u32,
}

/// The reference's filters.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum RefShadowFilter {
    /// One tap.
    Single,
    /// 2 x 2 taps, bilinear weights.
    Pcf2x2,
    /// 3 x 3 taps, equal weights.
    Pcf3x3,
}

/// Bias in depth steps: `constant + min(max, slope * (|∂d/∂X| + |∂d/∂Y|))`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RefBias {
    /// Constant, steps.
    pub constant: f64,
    /// Slope factor.
    pub slope: f64,
    /// Cap of the slope term, steps.
    pub max: f64,
}

/// A light's depth map: `size * size` depths in steps (65535 where nothing was drawn).
#[derive(Clone, Debug)]
pub struct RefMap {
    /// Side.
    pub size: u32,
    /// Depths, row-major, row 0 at the top (light `+y`).
    pub depth: Vec<f64>,
}

impl RefMap {
    fn at(&self, i: i64, j: i64) -> f64 {
        let n = i64::from(self.size);
        let (i, j) = (i.clamp(0, n - 1), j.clamp(0, n - 1));
        self.depth[(j * n + i) as usize]
    }
}

fn ref_vertex(clip: [f64; 4], extra: [f64; 4]) -> RefVertex {
    RefVertex {
        clip,
        uv: [extra[0], extra[1]],
        color: [extra[2], extra[3], 0.0],
    }
}

/// The light pass: every triangle clipped to the light's near and far planes, mapped to
/// the `size x size` map, culled (`cull_front`: keep back faces instead of front faces),
/// and its depth `65535 z_w` kept where nearer at each covered texel centre.
pub fn light_map(scene: &ShadowScene, size: u32, cull_front: bool) -> RefMap {
    let mut depth = vec![65535.0; (size * size) as usize];
    for t in &scene.tris {
        let tri = RefTriangle(t.map(|p| ref_vertex(transform(&scene.light, p), [0.0; 4])));
        for sub in fan(&clip_triangle(&tri)) {
            let w = sub.0.map(|v| to_window(&v, size, size));
            let [Some(a), Some(b), Some(c)] = w else {
                continue;
            };
            let v = [a, b, c];
            let front = signed_area2(&v) < 0.0;
            if front == cull_front {
                continue;
            }
            rasterize(&v, size, size, |x, y, l| {
                let z = 65535.0 * (l[0] * v[0].z + l[1] * v[1].z + l[2] * v[2].z);
                let k = (y * size + x) as usize;
                if z < depth[k] {
                    depth[k] = z;
                }
            });
        }
    }
    RefMap { size, depth }
}

/// Map position `(X, Y)` in texels and depth in steps of light clip `c`, or `None` outside.
pub fn project(c: [f64; 4], size: u32) -> Option<(f64, f64, f64)> {
    let [x, y, z, w] = c;
    if w <= 0.0 {
        return None;
    }
    let (s, t, d) = (
        (x / w + 1.0) / 2.0,
        (1.0 - y / w) / 2.0,
        65535.0 * (z / w + 1.0) / 2.0,
    );
    let inside = (0.0..1.0).contains(&s) && (0.0..1.0).contains(&t) && (0.0..=65535.0).contains(&d);
    inside.then(|| (s * f64::from(size), t * f64::from(size), d))
}

/// The bias of a triangle whose vertices have light clip coordinates `c`.
pub fn triangle_bias(c: &[[f64; 4]; 3], size: u32, bias: &RefBias) -> f64 {
    let p = c.map(|v| project(v, size));
    let slope = match p {
        [Some(a), Some(b), Some(c)] => {
            let (x1, y1, z1) = (b.0 - a.0, b.1 - a.1, b.2 - a.2);
            let (x2, y2, z2) = (c.0 - a.0, c.1 - a.1, c.2 - a.2);
            let det = x1 * y2 - x2 * y1;
            if det == 0.0 {
                f64::INFINITY
            } else {
                ((z1 * y2 - z2 * y1).abs() + (x1 * z2 - x2 * z1).abs()) / det.abs()
            }
        }
        _ => f64::INFINITY,
    };
    bias.constant + (bias.slope * slope).min(bias.max)
}

/// Whether a triangle with light clip coordinates `c` faces the light: the determinant of
/// its homogeneous `(x, y, w)` is positive (counter-clockwise seen from the light, for any
/// signs of `w`).
pub fn faces_light(c: &[[f64; 4]; 3]) -> bool {
    let [a, b, d] = c.map(|v| [v[0], v[1], v[3]]);
    let det = a[0] * (b[1] * d[2] - b[2] * d[1]) - a[1] * (b[0] * d[2] - b[2] * d[0])
        + a[2] * (b[0] * d[1] - b[1] * d[0]);
    det > 0.0
}

/// Lit fraction (0..=1) of a point at `(X, Y)` texels, biased depth `d`.
pub fn filter(map: &RefMap, x: f64, y: f64, d: f64, f: RefShadowFilter) -> f64 {
    let tap = |i: i64, j: i64| if d <= map.at(i, j) { 1.0 } else { 0.0 };
    match f {
        RefShadowFilter::Single => tap(x.floor() as i64, y.floor() as i64),
        RefShadowFilter::Pcf2x2 => {
            let (u, v) = (x - 0.5, y - 0.5);
            let (i, j) = (u.floor() as i64, v.floor() as i64);
            let (fx, fy) = (u - u.floor(), v - v.floor());
            (tap(i, j) * (1.0 - fx) + tap(i + 1, j) * fx) * (1.0 - fy)
                + (tap(i, j + 1) * (1.0 - fx) + tap(i + 1, j + 1) * fx) * fy
        }
        RefShadowFilter::Pcf3x3 => {
            let (i, j) = (x.floor() as i64, y.floor() as i64);
            let mut n = 0.0;
            for dj in -1..=1 {
                for di in -1..=1 {
                    n += tap(i + di, j + dj);
                }
            }
            n / 9.0
        }
    }
}

/// Per camera pixel: the lit fraction (`outside` for points outside the light's frustum)
/// and whether a triangle covers it; back faces culled, `GL_LESS` depth.
#[derive(Clone, Debug)]
pub struct RefShadowImage {
    /// Lit fraction, 0..=1.
    pub lit: Vec<f64>,
    /// Covered.
    pub covered: Vec<bool>,
}

/// The lit pass: see the module docs.
pub fn lit_pass(
    scene: &ShadowScene,
    map: &RefMap,
    f: RefShadowFilter,
    bias: &RefBias,
    outside: f64,
) -> RefShadowImage {
    let (w, h) = (scene.width, scene.height);
    let n = (w * h) as usize;
    let mut img = RefShadowImage {
        lit: vec![0.0; n],
        covered: vec![false; n],
    };
    let mut zbuf = vec![1.0f64; n];
    for t in &scene.tris {
        let lc = t.map(|p| transform(&scene.light, p));
        let tb = triangle_bias(&lc, map.size, bias);
        let own_shade = !faces_light(&lc);
        let tri = RefTriangle([0, 1, 2].map(|k| ref_vertex(transform(&scene.camera, t[k]), lc[k])));
        for sub in fan(&clip_triangle(&tri)) {
            let win = sub.0.map(|v| to_window(&v, w, h));
            let [Some(a), Some(b), Some(c)] = win else {
                continue;
            };
            let v = [a, b, c];
            let area = signed_area2(&v);
            if area >= 0.0 {
                continue; // back face or degenerate
            }
            let extra = sub.0.map(|v| [v.uv[0], v.uv[1], v.color[0], v.color[1]]);
            rasterize(&v, w, h, |x, y, l| {
                let k = (y * w + x) as usize;
                let z = l[0] * v[0].z + l[1] * v[1].z + l[2] * v[2].z;
                if z >= zbuf[k] {
                    return;
                }
                zbuf[k] = z;
                let q = [0, 1, 2].map(|i| l[i] * v[i].inv_w);
                let qs = q[0] + q[1] + q[2];
                let c: [f64; 4] =
                    core::array::from_fn(|j| (0..3).map(|i| q[i] * extra[i][j]).sum::<f64>() / qs);
                img.covered[k] = true;
                img.lit[k] = match project(c, map.size) {
                    Some(_) if own_shade => 0.0,
                    Some((sx, sy, d)) => filter(map, sx, sy, d - tb, f),
                    None => outside,
                };
            });
        }
    }
    img
}
