//! The bump-mapped sphere's lighting resolved into its texture for a light fixed in object
//! space (`fixel::shading::bump::resolve_sphere`, the `bump_fast` scene), the real-time
//! form of bump mapping: the resolve against its own f64 definition (per texel: central
//! differences of the brick heights, the sphere's tangent frame, Lambert plus ambient),
//! the unlit textured sphere against the f64 sphere with the f64 texture, and a golden.
//!
//! | what (256 x 128 resolve of the 64² brick tile, light fixed in object space) | measured |
//! |---|---|
//! | texels vs the f64 resolve | mean 0.0097, max 1 LSB |
//! | frame vs f64 textured sphere with the f64 resolve | mean 0.022, max 1 LSB, 48.3 dB |
//! | frame vs fixel's per-pixel bump (same light and material) | mean 0.89, max 16 LSB, 27.9 dB |

use embedded_graphics_core::pixelcolor::{IntoStorage, Rgb565};
use fixel::math::Fx;
use fixel::shading::bump::HeightDifferences;
use fixel::texture::{Filter, HeightMap, Texture};
use fixel_scenes::surface;
use host_tests::bump_fast_scene::{
    fixel_resolve, maps, material, ref_texture, reference_resolve, resolved_frame, LEVELS,
    STRENGTH, TILE,
};
use host_tests::metrics::channel_errors;
use host_tests::reference::{rgb565_from_f64, RefShading};
use host_tests::{adapter, scenes};

/// Every texel against the f64 resolve.
#[test]
fn resolve_matches_reference() {
    let m = maps();
    let got = fixel_resolve(&m);
    let want = reference_resolve(&m);
    let (mut max, mut sum) = (0u32, 0u64);
    for (g, w) in got.iter().zip(&want) {
        let e = channel_errors(g.into_storage(), rgb565_from_f64(*w));
        max = max.max(*e.iter().max().unwrap());
        sum += u64::from(e.iter().sum::<u32>());
    }
    let mean = sum as f64 / (3 * got.len()) as f64;
    println!("resolved bricks 256 x 128 vs the f64 resolve: mean {mean:.4} LSB, max {max}");
    assert!(max <= 1 && mean <= 0.05, "max {max} mean {mean}");
}

/// The unlit sphere with fixel's resolve against the f64 sphere with the f64 resolve;
/// golden.
#[test]
fn resolved_frame_matches_reference() {
    let m = maps();
    let (got, e) = resolved_frame(&m);
    println!("resolved sphere vs f64 textured sphere (f64 resolve): {e}");
    assert!(e.max <= 2 && e.mean <= 0.05, "{e}");
    let s = scenes::sphere(0);
    host_tests::golden::assert_golden("bump_fast_sphere", s.width, s.height, &got.pixels);
}

/// The resolved sphere against fixel's per-pixel bump mapping of the same sphere, light
/// and material (`Bumped` with the same height differences, the tile repeated (4, 2)
/// times, the light as a directional one in view space, which is object space in frame
/// 0): what the real-time form loses (the per-pixel frame is itself tested against the f64
/// reference in `surface_detail`).
#[test]
fn resolved_frame_against_per_pixel_bump() {
    use fixel::geometry::{Cull, Vertex, Viewport};
    use fixel::pipeline::{DepthLess, Exact, ShadedDraw};
    use fixel::scene::{LitMesh, PixelLight};
    use fixel::shading::bump::Bumped;
    use fixel::shading::TexBinding;
    use fixel::surface::{Frame, DEPTH_CLEAR};
    use fixel::texture::{Bilinear, Lod, MipTexture, Repeat};
    let m = maps();
    let (sphere, tangents) = surface::sphere().unwrap();
    let mesh = LitMesh::new(
        &sphere.positions,
        &sphere.normals,
        &sphere.uvs,
        Some(&tangents),
        &sphere.indices,
    )
    .unwrap();
    let chain = MipTexture::single(Texture::new(&m.colours, TILE, TILE).unwrap());
    let tex = TexBinding::new(&chain, Bilinear, Repeat, Repeat, Lod::default()).unwrap();
    let hm = HeightMap::new(&m.heights, TILE, TILE, LEVELS).unwrap();
    let normals = HeightDifferences::new(hm, Fx::from_bits(STRENGTH)).unwrap();
    let shader = Bumped::new(tex, normals, (TILE, TILE), material()).unwrap();
    let draw = ShadedDraw::<_, Exact, DepthLess>::new(
        shader,
        Viewport::new(0, 0, 320, 240).unwrap(),
        Cull::Back,
    )
    .unwrap();
    let mut vertices = vec![Vertex::new([Fx::ZERO; 4], [0; 8]); sphere.positions.len()];
    let light = PixelLight::directional(surface::resolve_light()).unwrap();
    mesh.bump_vertices(
        &fixel_scenes::sphere_model(0),
        &fixel_scenes::camera(20),
        &light,
        &mut vertices,
    )
    .unwrap();
    let (mut c, mut z) = (vec![Rgb565::new(0, 0, 0); 320 * 240], vec![0u16; 320 * 240]);
    let mut f = Frame::new(&mut c, 320, 240)
        .unwrap()
        .with_depth(&mut z)
        .unwrap();
    f.clear(Rgb565::new(0, 0, 0));
    mesh.draw_indexed(&draw, &vertices, &mut f).unwrap();
    let cov: Vec<bool> = f
        .depth()
        .unwrap()
        .iter()
        .map(|&d| d != DEPTH_CLEAR)
        .collect();
    let per_pixel: Vec<u16> = f.pixels().iter().map(|p| p.into_storage()).collect();
    // The resolved sphere.
    let mut s = scenes::sphere(0);
    s.lit = false;
    s.mode.shading = RefShading::Replace;
    s.texture = ref_texture(fixel_resolve(&m).iter().map(|c| c.into_storage()).collect());
    let mode = fixel::pipeline::DrawMode {
        filter: Filter::Bilinear,
        ..adapter::draw_mode(&s.mode, None, false)
    };
    let got = adapter::render(
        &adapter::clip_triangles(&scenes::to_ref_triangles(&s)),
        Some(&s.texture),
        mode,
        s.width,
        s.height,
    );
    let e = host_tests::metrics::compare_rgb565(&got.pixels, &got.covered, &per_pixel, &cov);
    println!("resolved sphere vs fixel's per-pixel bump (same light, material): {e}");
    assert!(e.psnr_db >= 27.0, "{e}");
}
