//! The independent f64 reference renderer: a GL-exact, slow, obviously
//! correct rasterizer written from the formulas (OpenGL ES 3.0 rules and the
//! perspective-correct "hyperbolic" interpolation of the lecture notes), used
//! to judge fixel's fixed-point output. It shares no code with fixel.
//!
//! Pipeline per triangle: clip against near/far in clip space ([`clip`]), fan
//! triangulation, perspective divide + viewport + 1/16-pixel snap ([`raster`]),
//! cull by signed window area, top-left-rule coverage at pixel centres,
//! attribute interpolation (screen-linear or hyperbolic), GL_LESS depth test
//! against 1.0, texture sampling ([`sample`]) and shading.

pub mod clip;
pub mod raster;
pub mod sample;
pub mod types;

pub use types::{
    rgb565_from_f64, rgb565_to_f64, RefCull, RefFilter, RefImage, RefMode, RefProjection,
    RefShading, RefTexture, RefTriangle, RefVertex, RefWrap,
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
pub fn render(
    tris: &[RefTriangle],
    tex: Option<&RefTexture>,
    mode: &RefMode,
    width: u32,
    height: u32,
) -> RefImage {
    let mut img = RefImage::new(width, height);
    for tri in tris {
        for sub in clip::fan(&clip::clip_triangle(tri)) {
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

/// Depth test, attribute interpolation, sampling and shading of one fragment.
fn shade_fragment(
    img: &mut RefImage,
    v: &[WindowVertex; 3],
    x: u32,
    y: u32,
    l: [f64; 3],
    tex: Option<&RefTexture>,
    mode: &RefMode,
) {
    let idx = (y * img.width + x) as usize;
    let z = l[0] * v[0].z + l[1] * v[1].z + l[2] * v[2].z;
    // GL_LESS; a NaN depth fails the test.
    let passes = z.partial_cmp(&img.depth[idx]) == Some(core::cmp::Ordering::Less);
    if mode.depth_test && !passes {
        return;
    }
    let texel = |uv: [f64; 2]| match tex {
        Some(t) => sample::sample(t, uv, mode.filter, mode.wrap_u, mode.wrap_v),
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
