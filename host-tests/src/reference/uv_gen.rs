//! The f64 reference for fixel's texture-coordinate generators (planar,
//! cylindrical and spherical projections), written from the formulas with `f64::atan2` and
//! `f64::asin`; it shares only the conventions (which axis is up, where the seam is) with
//! fixel.
//!
//! For `d = p − center` in the axis frame `(right, up, front)`:
//!
//! ```text
//! u = 1/2 + atan2(right, front) / 2π            (cylinder and sphere; in [0, 1))
//! v = (top − up) / (top − bottom)                (cylinder)
//! v = 1/2 − asin(up / |d|) / π                   (sphere)
//! u = (p − origin)·s,  v = (p − origin)·t        (plane)
//! ```
//!
//! Per triangle, a `u` range wider than one half means the triangle straddles the seam: the
//! corners below one half get `u + 1`. A corner on the axis (a pole) takes the mean `u` of
//! the others.

/// The up axis of a cylindrical or spherical mapping.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum RefAxis {
    X,
    Y,
    Z,
}

impl RefAxis {
    /// `(right, up, front)` of `d`.
    pub fn frame(self, d: [f64; 3]) -> (f64, f64, f64) {
        match self {
            RefAxis::X => (d[2], d[0], d[1]),
            RefAxis::Y => (d[0], d[1], d[2]),
            RefAxis::Z => (d[0], d[2], -d[1]),
        }
    }
}

/// A mapping, in f64.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum RefUvMapping {
    Planar {
        origin: [f64; 3],
        s: [f64; 3],
        t: [f64; 3],
    },
    Cylindrical {
        center: [f64; 3],
        axis: RefAxis,
        top: f64,
        bottom: f64,
    },
    Spherical {
        center: [f64; 3],
        axis: RefAxis,
    },
}

fn sub(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

fn longitude(right: f64, front: f64) -> f64 {
    if right == 0.0 && front == 0.0 {
        return 0.5;
    }
    (0.5 + right.atan2(front) / std::f64::consts::TAU).rem_euclid(1.0)
}

impl RefUvMapping {
    /// `([u, v], on the axis)` of `p`.
    pub fn uv(&self, p: [f64; 3]) -> ([f64; 2], bool) {
        match *self {
            RefUvMapping::Planar { origin, s, t } => {
                let d = sub(p, origin);
                ([dot(d, s), dot(d, t)], false)
            }
            RefUvMapping::Cylindrical {
                center,
                axis,
                top,
                bottom,
            } => {
                let (r, up, f) = axis.frame(sub(p, center));
                (
                    [longitude(r, f), (top - up) / (top - bottom)],
                    r == 0.0 && f == 0.0,
                )
            }
            RefUvMapping::Spherical { center, axis } => {
                let (r, up, f) = axis.frame(sub(p, center));
                let len = (r * r + up * up + f * f).sqrt();
                let v = if len == 0.0 {
                    0.5
                } else {
                    0.5 - (up / len).clamp(-1.0, 1.0).asin() / std::f64::consts::PI
                };
                ([longitude(r, f), v], r == 0.0 && f == 0.0)
            }
        }
    }

    /// Whether `u` wraps around the axis.
    pub fn wraps(&self) -> bool {
        !matches!(self, RefUvMapping::Planar { .. })
    }

    /// The three corners' coordinates after the seam and pole rules.
    pub fn triangle(&self, p: [[f64; 3]; 3]) -> [[f64; 2]; 3] {
        let mut c = p.map(|q| self.uv(q));
        if !self.wraps() {
            return c.map(|x| x.0);
        }
        let us: Vec<f64> = c.iter().filter(|x| !x.1).map(|x| x.0[0]).collect();
        if let (Some(lo), Some(hi)) = (
            us.iter().copied().reduce(f64::min),
            us.iter().copied().reduce(f64::max),
        ) {
            if hi - lo > 0.5 {
                for x in c.iter_mut().filter(|x| !x.1 && x.0[0] < 0.5) {
                    x.0[0] += 1.0;
                }
            }
        }
        let others: Vec<f64> = c.iter().filter(|x| !x.1).map(|x| x.0[0]).collect();
        if !others.is_empty() {
            let mean = others.iter().sum::<f64>() / others.len() as f64;
            for x in c.iter_mut().filter(|x| x.1) {
                x.0[0] = mean;
            }
        }
        c.map(|x| x.0)
    }
}

/// Renders triangles of fixel's per-pixel mapping layout (`Vertex<4>`: model-space point in
/// I16F16, Q8.16 intensity) with coordinates from `mapping` at every pixel's perspective-
/// correct point, sampled with `filter` (repeat along `s`, clamp along `t`), back faces
/// culled, GL_LESS on the window depth.
pub fn render_per_pixel(
    tris: &[[fixel::geometry::Vertex<4>; 3]],
    mapping: &RefUvMapping,
    tex: &super::RefTexture,
    filter: super::RefFilter,
    width: u32,
    height: u32,
) -> super::RefImage {
    use super::raster::{barycentrics, rasterize, signed_area2, window_of};
    use super::sample::sample;
    use super::types::RefWrap;
    let mut img = super::RefImage::new(width, height);
    let mut zbuf = vec![f64::INFINITY; (width * height) as usize];
    for tri in tris {
        let Some(win) = window_of(tri, width, height) else {
            continue;
        };
        if signed_area2(&win) >= 0.0 {
            continue;
        }
        let attr = tri.map(|v| v.varyings.map(f64::from));
        rasterize(&win, width, height, |x, y, _| {
            let l = barycentrics(&win, f64::from(x) + 0.5, f64::from(y) + 0.5);
            let z: f64 = (0..3).map(|i| l[i] * win[i].z).sum();
            let idx = (y * width + x) as usize;
            if z >= zbuf[idx] {
                return;
            }
            zbuf[idx] = z;
            let q = [0, 1, 2].map(|i| l[i] * win[i].inv_w);
            let qs: f64 = q.iter().sum();
            let at = |j: usize| (0..3).map(|i| q[i] * attr[i][j]).sum::<f64>() / qs;
            let p = [at(0), at(1), at(2)].map(|c| c / 65536.0);
            let (uv, _) = mapping.uv(p);
            let k = (at(3) / f64::from(256 << 16)).clamp(0.0, 1.0);
            let c = sample(tex, uv, filter, RefWrap::Repeat, RefWrap::ClampToEdge);
            img.rgb[idx] = c.map(|v| v * k);
            img.covered[idx] = true;
        });
    }
    img
}
