//! Per-pixel detail from the exact interpolated uv: how far each sample point lies from a
//! texel edge and how minified the texture is there, and the errors that explains.

use host_tests::metrics::channel_errors;
use host_tests::reference::{
    self, RefImage, RefMode, RefProjection, RefShading, RefTexture, RefTriangle,
};

use crate::cases::Scene;

/// Per-pixel detail beyond [`Report`], from the exact interpolated uv.
#[derive(Clone, Copy, Debug, Default)]
pub struct Detail {
    /// Pixels off by more than 1 LSB (with Nearest: texel flips).
    pub over1: usize,
    /// Of those, pixels whose sample point is NOT within `EPS_PX` pixel of a
    /// texel boundary (must be 0 for Nearest implementation error).
    pub unexplained: usize,
    /// Largest boundary distance (pixels) among the pixels off by > 1 LSB.
    pub max_dist_px: f64,
    /// Largest error where the texture is not minified (footprint <= 1 texel/px).
    pub max_unminified: u32,
    /// Pixels off by more than 2 LSB where the texture IS minified.
    pub over2_minified: usize,
}

/// A Nearest sample whose exact texel coordinate lies within this many
/// pixels (texel distance / texels per pixel) of a texel boundary may pick
/// the neighbouring texel: fixel's coordinate is exact to a small fraction of
/// a pixel, not to zero.
const EPS_PX: f64 = 1.0 / 64.0;

/// Per covered pixel: (distance in pixels from the sample point to the
/// nearest texel edge, footprint in texels per pixel), from the exact
/// `[u, v]` image. Derivatives are the smaller one-sided difference to a
/// covered neighbour (so a uv seam between triangles does not count).
pub fn uv_geometry(uv: &RefImage, tex: &RefTexture) -> Vec<(f64, f64)> {
    let (w, h) = (uv.width as usize, uv.height as usize);
    let size = [f64::from(tex.width), f64::from(tex.height)];
    let mut out = vec![(f64::INFINITY, 0.0); w * h];
    for y in 0..h {
        for x in 0..w {
            let k = y * w + x;
            if !uv.covered[k] {
                continue;
            }
            let mut nb = [usize::MAX; 4];
            if x > 0 {
                nb[0] = k - 1;
            }
            if x + 1 < w {
                nb[1] = k + 1;
            }
            if y > 0 {
                nb[2] = k - w;
            }
            if y + 1 < h {
                nb[3] = k + w;
            }
            let (mut dist, mut foot) = (f64::INFINITY, 0.0f64);
            for (c, &sz) in size.iter().enumerate() {
                let t = uv.rgb[k][c] * sz;
                let mut fc = 0.0f64;
                for axis in [&nb[..2], &nb[2..]] {
                    let mut m = f64::INFINITY;
                    for &n in axis {
                        if n != usize::MAX && uv.covered[n] {
                            m = m.min((uv.rgb[n][c] * sz - t).abs());
                        }
                    }
                    if m.is_finite() {
                        fc = fc.max(m);
                    }
                }
                if fc > 0.0 {
                    dist = dist.min((t - t.round()).abs() / fc);
                }
                foot = foot.max(fc);
            }
            out[k] = (dist, foot);
        }
    }
    out
}

pub fn detail(f: &[u16], cov: &[bool], q: &[u16], rcov: &[bool], geo: &[(f64, f64)]) -> Detail {
    let mut out = Detail::default();
    for k in 0..f.len() {
        if !(cov[k] && rcov[k]) {
            continue;
        }
        let e = channel_errors(f[k], q[k]).into_iter().max().unwrap_or(0);
        let (dist, foot) = geo[k];
        if e > 1 {
            out.over1 += 1;
            out.max_dist_px = out.max_dist_px.max(dist);
            if dist >= EPS_PX {
                out.unexplained += 1;
            }
        }
        if foot <= 1.0 {
            out.max_unminified = out.max_unminified.max(e);
        } else if e > 2 {
            out.over2_minified += 1;
        }
    }
    out
}

/// Reference image whose "colour" is the exact interpolated `[u, v, 0]`
/// (the reference interpolates colour and uv with the same formula and does
/// not clamp colours).
pub fn render_uv(sc: &Scene, proj: RefProjection) -> RefImage {
    let tris: Vec<RefTriangle> = sc
        .tris
        .iter()
        .map(|t| {
            RefTriangle(t.0.map(|mut v| {
                v.color = [v.uv[0], v.uv[1], 0.0];
                v
            }))
        })
        .collect();
    let mode = RefMode {
        projection: proj,
        shading: RefShading::Gouraud,
        ..sc.mode
    };
    reference::render(&tris, None, &mode, sc.width, sc.height)
}
