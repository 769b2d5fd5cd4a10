//! The independent f64 reference renderer: a GL-exact, slow, obviously
//! correct rasterizer written from the formulas (OpenGL ES 3.0 rules and the
//! perspective-correct "hyperbolic" interpolation of the lecture notes), used
//! to judge fixel's fixed-point output. It shares no code with fixel.
//!
//! Pipeline per triangle: clip against near/far in clip space ([`clip`]), fan
//! triangulation, perspective divide + viewport + 1/16-pixel snap ([`raster`]),
//! cull by signed window area, top-left-rule coverage at pixel centres,
//! attribute interpolation (screen-linear or hyperbolic), GL_LESS depth test
//! against 1.0, texture sampling ([`sample`], mipmapped in [`mip`] from the
//! exact derivatives of [`uv_derivatives`]) and shading.

pub mod clip;
pub mod displace;
pub mod env;
pub mod mip;
pub mod raster;
pub mod sample;
pub mod types;

pub use mip::RefMipChain;
pub use types::{
    rgb565_from_f64, rgb565_to_f64, RefCull, RefFilter, RefImage, RefLod, RefMip, RefMode,
    RefProjection, RefShading, RefTexture, RefTriangle, RefVertex, RefWrap,
};

use raster::WindowVertex;

/// White, used as the texel colour when no texture is bound.
const WHITE: [f64; 3] = [1.0; 3];

/// Renders `tris` in order into a fresh `width x height` image (black,
/// uncovered, depth 1.0). Without a texture, texel colours are white.
///
/// With `depth_test` a fragment is kept only if `z_w < depth` (GL_LESS);
/// without it every later fragment overwrites. `RefImage::depth` records the
/// `z_w` of the fragment that was kept in either case.
///
/// With `mode.mip` other than `RefMip::None` the texture gets a full mip chain
/// ([`RefMipChain::build`]); see [`render_chain`] for a chosen chain.
pub fn render(
    tris: &[RefTriangle],
    tex: Option<&RefTexture>,
    mode: &RefMode,
    width: u32,
    height: u32,
) -> RefImage {
    let chain = tex.map(|t| match mode.mip {
        RefMip::None => RefMipChain::single(t),
        _ => RefMipChain::build(t, None),
    });
    render_chain(tris, chain.as_ref(), mode, width, height)
}

/// [`render`] with a given mip chain (its level 0 is the texture).
pub fn render_chain(
    tris: &[RefTriangle],
    tex: Option<&RefMipChain>,
    mode: &RefMode,
    width: u32,
    height: u32,
) -> RefImage {
    let mut img = RefImage::new(width, height);
    for tri in tris {
        let noperspective = mode.projection == RefProjection::Affine;
        for sub in clip::fan(&clip::clip_triangle_with(tri, noperspective)) {
            let w = sub.0.map(|v| raster::to_window(&v, width, height));
            let [Some(a), Some(b), Some(c)] = w else {
                continue;
            };
            let v = [a, b, c];
            let area = raster::signed_area2(&v);
            // Negative window area (y down) = counter-clockwise in NDC = front.
            let front = area < 0.0;
            let culled = match mode.cull {
                RefCull::None => false,
                RefCull::Back => !front,
                RefCull::Front => front,
            };
            if culled || area == 0.0 {
                continue;
            }
            raster::rasterize(&v, width, height, |x, y, l| {
                shade_fragment(&mut img, &v, x, y, l, tex, mode);
            });
        }
    }
    img
}

/// GL's `lambda` (`log2` of Heckbert's `rho`, before any bias) of a `tex_w x tex_h`
/// texture at every pixel, from the exact derivatives ([`uv_derivatives`]) of the last
/// triangle covering it (`NaN` where none): the analytic level of detail a mipmapped draw
/// of `tris` should use. Clipping, culling and projection as [`render_chain`].
pub fn lambda_map(
    tris: &[RefTriangle],
    (tex_w, tex_h): (u32, u32),
    mode: &RefMode,
    width: u32,
    height: u32,
) -> Vec<f64> {
    let mut out = vec![f64::NAN; (width * height) as usize];
    for tri in tris {
        let noperspective = mode.projection == RefProjection::Affine;
        for sub in clip::fan(&clip::clip_triangle_with(tri, noperspective)) {
            let w = sub.0.map(|v| raster::to_window(&v, width, height));
            let [Some(a), Some(b), Some(c)] = w else {
                continue;
            };
            let v = [a, b, c];
            let area = raster::signed_area2(&v);
            let culled = match mode.cull {
                RefCull::None => false,
                RefCull::Back => area >= 0.0,
                RefCull::Front => area < 0.0,
            };
            if culled || area == 0.0 {
                continue;
            }
            raster::rasterize(&v, width, height, |x, y, l| {
                let d = uv_derivatives(&v, l, mode.projection);
                let d = texel_derivatives(d, tex_w, tex_h);
                out[(y * width + x) as usize] = mip::rho(d).log2();
            });
        }
    }
    out
}

/// Interpolates one attribute of `n` channels at barycentrics `l`.
fn interpolate<const N: usize>(
    v: &[WindowVertex; 3],
    l: [f64; 3],
    proj: RefProjection,
    attr: impl Fn(&WindowVertex) -> [f64; N],
) -> [f64; N] {
    let a = v.map(|vi| attr(&vi));
    match proj {
        RefProjection::Affine => {
            core::array::from_fn(|c| l[0] * a[0][c] + l[1] * a[1][c] + l[2] * a[2][c])
        }
        RefProjection::Perspective => {
            let q = [0, 1, 2].map(|i| l[i] * v[i].inv_w);
            let den = q[0] + q[1] + q[2];
            core::array::from_fn(|c| (q[0] * a[0][c] + q[1] * a[1][c] + q[2] * a[2][c]) / den)
        }
    }
}

/// Exact window-space derivatives `[[ds/dx, dt/dx], [ds/dy, dt/dy]]` of the
/// interpolated texture coordinates at barycentrics `l` (x right, y down, in
/// pixels; `s`, `t` normalised).
///
/// `l_i = e_i(x, y) / A` is affine in the window position, with
/// `de_i/dx = -(b.ey - a.ey)` and `de_i/dy = b.ex - a.ex` for the edge `a -> b`
/// opposite vertex `i`. Affine: `ds/dx = Σ (dl_i/dx) s_i`. Perspective:
/// `s = S / Q` with `S = Σ l_i q_i s_i`, `Q = Σ l_i q_i` (`q_i = 1 / w_i`),
/// so `ds/dx = (S_x - s Q_x) / Q`.
pub fn uv_derivatives(v: &[WindowVertex; 3], l: [f64; 3], proj: RefProjection) -> [[f64; 2]; 2] {
    // Of the exact (unsnapped) positions, as the barycentrics.
    let area = raster::exact_area2(v);
    let edges = [(1usize, 2usize), (2, 0), (0, 1)];
    let dl = [
        edges.map(|(a, b)| -(v[b].ey - v[a].ey) / area),
        edges.map(|(a, b)| (v[b].ex - v[a].ex) / area),
    ];
    match proj {
        RefProjection::Affine => dl.map(|d| {
            core::array::from_fn(|c| d[0] * v[0].uv[c] + d[1] * v[1].uv[c] + d[2] * v[2].uv[c])
        }),
        RefProjection::Perspective => {
            let q = [v[0].inv_w, v[1].inv_w, v[2].inv_w];
            let qq: f64 = (0..3).map(|i| l[i] * q[i]).sum();
            let st: [f64; 2] = core::array::from_fn(|c| {
                (0..3).map(|i| l[i] * q[i] * v[i].uv[c]).sum::<f64>() / qq
            });
            dl.map(|d| {
                let qd: f64 = (0..3).map(|i| d[i] * q[i]).sum();
                core::array::from_fn(|c| {
                    let sd: f64 = (0..3).map(|i| d[i] * q[i] * v[i].uv[c]).sum();
                    (sd - st[c] * qd) / qq
                })
            })
        }
    }
}

/// Level-0 texel derivatives `[[ux, vx], [uy, vy]]` of `uv_derivatives` for a
/// `width x height` base level.
pub fn texel_derivatives(d: [[f64; 2]; 2], width: u32, height: u32) -> [[f64; 2]; 2] {
    d.map(|r| [r[0] * f64::from(width), r[1] * f64::from(height)])
}

/// `n x n` supersampled reference: renders at `n` times the resolution and
/// box-filters each `n x n` block (the regular grid of sample positions
/// `(x + (i + 1/2) / n, y + (j + 1/2) / n)`). A pixel is `covered` only when
/// all `n²` samples are; its colour is the mean over its covered samples and
/// its depth the mean depth.
pub fn render_supersampled(
    tris: &[RefTriangle],
    tex: Option<&RefTexture>,
    mode: &RefMode,
    width: u32,
    height: u32,
    n: u32,
) -> RefImage {
    let hi = render(tris, tex, mode, width * n, height * n);
    let mut out = RefImage::new(width, height);
    for y in 0..height {
        for x in 0..width {
            let (mut rgb, mut depth, mut count) = ([0.0; 3], 0.0, 0u32);
            for j in 0..n {
                for i in 0..n {
                    let k = ((y * n + j) * hi.width + x * n + i) as usize;
                    if hi.covered[k] {
                        count += 1;
                        for (a, h) in rgb.iter_mut().zip(hi.rgb[k]) {
                            *a += h;
                        }
                        depth += hi.depth[k];
                    }
                }
            }
            let o = (y * width + x) as usize;
            if count > 0 {
                out.rgb[o] = rgb.map(|c| c / f64::from(count));
                out.depth[o] = depth / f64::from(count);
            }
            out.covered[o] = count == n * n;
        }
    }
    out
}

/// Depth test, attribute interpolation, sampling and shading of one fragment.
fn shade_fragment(
    img: &mut RefImage,
    v: &[WindowVertex; 3],
    x: u32,
    y: u32,
    l: [f64; 3],
    tex: Option<&RefMipChain>,
    mode: &RefMode,
) {
    let idx = (y * img.width + x) as usize;
    let z = l[0] * v[0].z + l[1] * v[1].z + l[2] * v[2].z;
    // GL_LESS; a NaN depth fails the test.
    let passes = z.partial_cmp(&img.depth[idx]) == Some(core::cmp::Ordering::Less);
    if mode.depth_test && !passes {
        return;
    }
    let mag = mode.mag.unwrap_or(mode.filter);
    let texel = |uv: [f64; 2]| match tex {
        Some(t) if mode.mip == RefMip::None && mag == mode.filter => {
            sample::sample(t.base(), uv, mode.filter, mode.wrap_u, mode.wrap_v)
        }
        Some(t) => {
            let d = uv_derivatives(v, l, mode.projection);
            let d = texel_derivatives(d, t.base().width, t.base().height);
            mip::sample_mip(
                t,
                uv,
                d,
                mode.filter,
                mag,
                mode.mip,
                &mode.lod,
                [mode.wrap_u, mode.wrap_v],
            )
        }
        None => WHITE,
    };
    let uv = || interpolate(v, l, mode.projection, |w| w.uv);
    let colour = || interpolate(v, l, mode.projection, |w| w.color);
    let rgb = match mode.shading {
        RefShading::Replace => texel(uv()),
        RefShading::Modulate => {
            let (t, c) = (texel(uv()), colour());
            [t[0] * c[0], t[1] * c[1], t[2] * c[2]]
        }
        RefShading::Gouraud => colour(),
        RefShading::Flat(c) => c,
    };
    img.rgb[idx] = rgb;
    img.covered[idx] = true;
    img.depth[idx] = z;
}
pub mod cube_vertex;
pub mod lighting;
pub mod matcap;
pub mod noise;
pub mod quad;
pub mod shadow;
pub mod triplanar;
pub mod two_stage;
pub mod uv_gen;
