//! The f64 reference for triplanar mapping (three planar projections, blended
//! by the normal): its own perspective-correct interpolation of the point, normal and
//! intensity from the exact window positions, the weights from the formula, and the
//! reference bilinear sampler. Shares only data with fixel (the vertices and the texture).
//!
//! ```text
//! X: (z, −y)   Y: (x, z)   Z: (x, −y)          (model-space point in texels)
//! a_i = max(0, |n_i| − k max|n|),  w_i = a_i / Σ a,  colour = Σ w_i T_i · intensity
//! ```

use super::raster::{barycentrics, rasterize, signed_area2, window_of};
use super::sample::sample;
use super::types::{RefFilter, RefImage, RefTexture, RefWrap};
use fixel::geometry::Vertex;

/// The blend weights for normal `n` and threshold `k` (`0..1`).
pub fn weights(n: [f64; 3], k: f64) -> [f64; 3] {
    let a = n.map(f64::abs);
    let m = a[0].max(a[1]).max(a[2]);
    if m == 0.0 {
        return [0.0; 3];
    }
    let b = a.map(|c| (c - k * m).max(0.0));
    let s: f64 = b.iter().sum();
    b.map(|c| c / s)
}

/// Renders triplanar-mapped triangles (fixel's [`Vertex<7>`] layout: point in I16F16
/// texels, normal, Q8.16 intensity), back faces culled, with GL_LESS on the window depth.
pub fn render(
    tris: &[[Vertex<7>; 3]],
    tex: &RefTexture,
    filter: RefFilter,
    k: f64,
    width: u32,
    height: u32,
) -> RefImage {
    let mut img = RefImage::new(width, height);
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
            let wts = weights([at(3), at(4), at(5)], k);
            let intensity = (at(6) / f64::from(256 << 16)).clamp(0.0, 1.0);
            let proj = [[p[2], -p[1]], [p[0], p[2]], [p[0], -p[1]]];
            let mut col = [0.0; 3];
            for i in 0..3 {
                if wts[i] > 0.0 {
                    let uv = [
                        proj[i][0] / f64::from(tex.width),
                        proj[i][1] / f64::from(tex.height),
                    ];
                    let c = sample(tex, uv, filter, RefWrap::Repeat, RefWrap::Repeat);
                    for ch in 0..3 {
                        col[ch] += wts[i] * c[ch];
                    }
                }
            }
            img.rgb[idx] = col.map(|c| c * intensity);
            img.covered[idx] = true;
        });
    }
    img
}
