//! The level of detail itself on the benchmark floor (320 x 240, 64-texel texture, exact
//! perspective): fixel's `lambda` (Q8.8, from the span loop's perspective derivatives and
//! the 64-entry `log2` table) against the f64 analytic value of the reference
//! (`reference::lambda_map`: exact derivatives of the texture coordinates, `log2` of
//! Heckbert's `rho`), per pixel, per span and per triangle.
//!
//! Figures (printed with `--nocapture`; budgets are these plus a margin), in levels, over
//! the pixels the reference minifies (`lambda > 0`):
//!
//! | LOD per | mean | p99 | max |
//! |---|---|---|---|
//! | pixel | 0.0023 | 0.0065 | 0.0074 |
//! | span (first pixel) | 0.11 | 0.19 | 0.20 |
//! | triangle (centroid) | 3.0 | 8.6 | 10.4 |
//!
//! (Per triangle is one value for a triangle reaching from the camera to the horizon.)
//! The trilinear floor's remaining disagreement with GL is not `lambda`: it is the mip
//! chain (levels filtered at full precision now) and the 8-bit blend weight.

use embedded_graphics_core::pixelcolor::{IntoStorage, Rgb565};
use fixel::geometry::{Cull, Vertex, Viewport};
use fixel::pipeline::{DepthLess, Exact, ShadedDraw};
use fixel::shading::{Fragment, Shader, TexBinding, TexTriangle};
use fixel::surface::{Frame, DEPTH_CLEAR};
use fixel::texture::{full_levels, Lod, LodGranularity, MipTexture, Repeat, Trilinear};
use host_tests::adapter;
use host_tests::reference::{self, RefFilter, RefMip, RefMode};
use host_tests::scenes;

/// Writes `lambda` (Q8.8, offset by 8 levels) instead of a colour.
#[derive(Clone, Copy, Debug)]
struct LambdaOut<'a>(TexBinding<'a, Trilinear, Repeat, Repeat>);

impl Shader for LambdaOut<'_> {
    type Varyings = [i32; 5];
    type Triangle = TexTriangle;
    const TEXCOORDS: Option<(usize, usize)> = Some((0, 1));
    const LOD: bool = true;
    fn lod_granularity(&self) -> LodGranularity {
        self.0.lod().granularity
    }
    fn coord_shift(t: &TexTriangle) -> u32 {
        u32::from(t.shift)
    }
    fn triangle(&self, v: &mut [[i32; 5]; 3]) -> TexTriangle {
        self.0.triangle(v, (0, 1))
    }
    fn shade(&self, f: &Fragment<[i32; 5], TexTriangle>) -> Option<u16> {
        Some((f.lambda + 8 * 256).clamp(0, 0xFFFF) as u16)
    }
}

#[test]
fn floor_lambda_matches_analytic() {
    let s = scenes::floor();
    let rt = scenes::to_ref_triangles(&s);
    let mode = RefMode {
        filter: RefFilter::Bilinear,
        mip: RefMip::Linear,
        ..s.mode
    };
    let (tw, th) = (s.texture.width, s.texture.height);
    let want = reference::lambda_map(&rt, (tw, th), &mode, s.width, s.height);
    let tris: Vec<[Vertex<5>; 3]> = adapter::clip_triangles(&rt)
        .iter()
        .map(|t| t.map(|v| v.to_vertex()))
        .collect();
    let chain = adapter::mip_chain(&s.texture, None);
    let mip = MipTexture::new(&chain, tw, th, full_levels(tw, th)).unwrap();
    let vp = Viewport::new(0, 0, s.width, s.height).unwrap();
    for (name, g, p99_budget) in [
        ("pixel", LodGranularity::Pixel, 0.01),
        ("span", LodGranularity::Span, 0.22),
        ("triangle", LodGranularity::Triangle, 9.0),
    ] {
        let lod = Lod {
            granularity: g,
            ..Lod::default()
        };
        let tex = TexBinding::new(&mip, Trilinear::default(), Repeat, Repeat, lod).unwrap();
        let d = ShadedDraw::<_, Exact, DepthLess>::new(LambdaOut(tex), vp, Cull::Back).unwrap();
        let n = (s.width * s.height) as usize;
        let (mut color, mut depth) = (vec![Rgb565::new(0, 0, 0); n], vec![0u16; n]);
        let mut frame = Frame::new(&mut color, s.width, s.height)
            .unwrap()
            .with_depth(&mut depth)
            .unwrap();
        d.clip_triangles(&tris, &mut frame).unwrap();
        let covered: Vec<bool> = frame
            .depth()
            .unwrap()
            .iter()
            .map(|&z| z != DEPTH_CLEAR)
            .collect();
        let mut e: Vec<f64> = frame
            .pixels()
            .iter()
            .zip(&covered)
            .zip(&want)
            .filter(|((_, &c), &w)| c && w > 0.0)
            .map(|((p, _), &w)| (f64::from(p.into_storage()) / 256.0 - 8.0 - w).abs())
            .collect();
        e.sort_by(f64::total_cmp);
        let k = e.len();
        let mean = e.iter().sum::<f64>() / k as f64;
        let (p99, max) = (e[k * 99 / 100], e[k - 1]);
        println!(
            "floor lambda, LOD per {name} ({k} minified px): mean {mean:.4}, p99 {p99:.4}, max {max:.4} levels"
        );
        assert!(k > 10_000, "{k}");
        assert!(p99 <= p99_budget, "{name}: p99 {p99}");
    }
}
