//! The bump-mapped sphere's lighting resolved into its texture for a light fixed in object
//! space (`fixel::shading::bump::resolve_sphere`, the `bump_fast` scene), as fixel resolves
//! it and as its f64 definition does (per texel: central differences of the brick heights,
//! the sphere's tangent frame, Lambert plus ambient), and the textured sphere drawn with
//! each: for the tests (`tests/bump_fast.rs`) and the surface report.

use embedded_graphics_core::pixelcolor::{IntoStorage, Rgb565};
use fixel::math::Fx;
use fixel::shading::bump::{resolve_sphere, HeightDifferences};
use fixel::shading::lighting::{Material, Specular};
use fixel::texture::{chain_len, Filter, HeightMap, Texture};
use fixel_scenes::surface;

use crate::adapter;
use crate::metrics::{compare, Report};
use crate::reference::{render, rgb565_from_f64, RefShading, RefTexture};
use crate::scenes;

/// Width of the resolved texture.
pub const W: u32 = 256;
/// Height of the resolved texture.
pub const H: u32 = 128;
/// Side of the brick tile.
pub const TILE: u32 = 64;
/// Levels of the height map's chain.
pub const LEVELS: u32 = 7;
/// σ, texel widths per height step (the `bump` scene's 0.02).
pub const STRENGTH: i32 = surface::RESOLVE_STRENGTH;

/// The brick tile's colours and heights.
pub struct Maps {
    /// Colours, `TILE x TILE`.
    pub colours: Vec<Rgb565>,
    /// Heights, the whole chain.
    pub heights: Vec<u8>,
}

/// The brick maps of the `bump` scene.
pub fn maps() -> Maps {
    let n = chain_len(TILE, TILE, LEVELS);
    let mut m = Maps {
        colours: vec![Rgb565::new(0, 0, 0); (TILE * TILE) as usize],
        heights: vec![0; n],
    };
    let mut derivs = vec![Rgb565::new(0, 0, 0); n];
    surface::brick_maps(TILE, LEVELS, &mut m.colours, &mut m.heights, &mut derivs).unwrap();
    m
}

/// The material of the resolve (the `bump` scene's, without a specular term).
pub fn material() -> Material<'static> {
    Material {
        specular: 0,
        ..surface::material(Specular::None)
    }
}

/// fixel's resolve of the tile into the `W x H` sphere texture.
pub fn fixel_resolve(m: &Maps) -> Vec<Rgb565> {
    let tile = Texture::new(&m.colours, TILE, TILE).unwrap();
    let hm = HeightMap::new(&m.heights, TILE, TILE, LEVELS).unwrap();
    let normals = HeightDifferences::new(hm, Fx::from_bits(STRENGTH)).unwrap();
    let mut out = vec![Rgb565::new(0, 0, 0); (W * H) as usize];
    resolve_sphere(
        &tile,
        &normals,
        &material(),
        surface::resolve_light(),
        W,
        H,
        &mut out,
    )
    .unwrap();
    out
}

/// The f64 definition of the resolve.
pub fn reference_resolve(m: &Maps) -> Vec<[f64; 3]> {
    let pi = std::f64::consts::PI;
    let sigma = f64::from(STRENGTH) / 65536.0;
    let l = surface::resolve_light();
    let l = [l.x, l.y, l.z].map(|c| c.to_num::<f64>());
    let norm = |v: [f64; 3]| {
        let len = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
        v.map(|c| c / len)
    };
    let l = norm(l);
    let dot = |a: [f64; 3], b: [f64; 3]| a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    let h = |i: i64, j: i64| {
        let (i, j) = (i.rem_euclid(i64::from(TILE)), j.rem_euclid(i64::from(TILE)));
        f64::from(m.heights[(j * i64::from(TILE) + i) as usize])
    };
    let mat = material();
    let (ka, kd) = (
        f64::from(mat.ambient) / 256.0,
        f64::from(mat.diffuse) / 256.0,
    );
    (0..W * H)
        .map(|k| {
            let (i, j) = (k % W, k / W);
            let th = pi * (f64::from(j) + 0.5) / f64::from(H);
            let ph = 2.0 * pi * (f64::from(i) + 0.5) / f64::from(W);
            let n = [th.sin() * ph.cos(), th.cos(), -th.sin() * ph.sin()];
            let t = [-ph.sin(), 0.0, -ph.cos()];
            let b = [th.cos() * ph.cos(), -th.sin(), -th.cos() * ph.sin()];
            let lt = norm([dot(t, l), dot(b, l), dot(n, l)]);
            let (ii, jj) = (i64::from(i), i64::from(j));
            let du = (h(ii + 1, jj) - h(ii - 1, jj)) / 2.0;
            let dv = (h(ii, jj + 1) - h(ii, jj - 1)) / 2.0;
            let np = norm([-sigma * du, -sigma * dv, 1.0]);
            let intensity = (ka + kd * dot(np, lt).max(0.0)).min(1.0);
            let c = m.colours[((j % TILE) * TILE + i % TILE) as usize].into_storage();
            let ch = [
                f64::from(c >> 11) / 31.0,
                f64::from((c >> 5) & 63) / 63.0,
                f64::from(c & 31) / 31.0,
            ];
            ch.map(|x| x * intensity)
        })
        .collect()
}

/// A `W x H` texture for the reference renderer.
pub fn ref_texture(texels: Vec<u16>) -> RefTexture {
    RefTexture {
        width: W,
        height: H,
        texels,
        border: 0,
    }
}

/// The unlit sphere (frame 0) textured with fixel's resolve, drawn by fixel, against the
/// f64 sphere textured with the f64 resolve: fixel's frame (pixels, coverage) and the
/// comparison.
pub fn resolved_frame(m: &Maps) -> (adapter::FixelImage, Report) {
    let (got, e, _) = resolved_frame_timed(m);
    (got, e)
}

/// [`resolved_frame`], and the seconds fixel's draw took (the resolve not included: it
/// runs once per light, not per frame).
pub fn resolved_frame_timed(m: &Maps) -> (adapter::FixelImage, Report, f64) {
    let mut s = scenes::sphere(0);
    s.lit = false;
    s.mode.shading = RefShading::Replace;
    s.texture = ref_texture(fixel_resolve(m).iter().map(|c| c.into_storage()).collect());
    let mode = fixel::pipeline::DrawMode {
        filter: Filter::Bilinear,
        ..adapter::draw_mode(&s.mode, None, false)
    };
    let tris = scenes::to_ref_triangles(&s);
    let clipped = adapter::clip_triangles(&tris);
    let t0 = std::time::Instant::now();
    let got = adapter::render(&clipped, Some(&s.texture), mode, s.width, s.height);
    let seconds = t0.elapsed().as_secs_f64();
    let f64_tex = ref_texture(
        reference_resolve(m)
            .into_iter()
            .map(rgb565_from_f64)
            .collect(),
    );
    let want = render(&tris, Some(&f64_tex), &s.mode, s.width, s.height);
    let e = compare(&got.pixels, &got.covered, &want);
    (got, e, seconds)
}
