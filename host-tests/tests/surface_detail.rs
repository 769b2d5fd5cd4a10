//! Per-pixel lighting, bump and normal mapping against the f64 reference
//! (`host_tests::reference::lighting`): error budgets per variant, the gain of per-pixel
//! lighting over Gouraud on the highlight, and the hard cases.

use fixel::math::{fx, Vec3};
use fixel::scene::PixelLight;
use fixel_scenes::surface;
use host_tests::metrics::{compare, Report};
use host_tests::surface_scene::{
    render_fixel, render_reference, sphere, wall, Assets, MeshArrays, Variant, SIZE,
};
use proptest::prelude::*;

const W: u32 = 160;
const H: u32 = 160;

/// Light frames in front of the sphere: front-left, front, and grazing from the left.
const FRAMES: [u32; 3] = [0, 14, 2];

fn run(v: Variant, i: u32, light: &PixelLight, a: &Assets, s: &MeshArrays) -> Report {
    let (px, cov) = render_fixel(v, i, light, a, s, W, H);
    let r = render_reference(v, i, light, a, s, W, H);
    compare(&px, &cov, &r)
}

/// `(p99 max, share over 2 LSB max, PSNR min)` per variant.
fn budget(v: Variant) -> (u32, f64, f64) {
    match v {
        // Gouraud is measured against the per-pixel ideal: no budget but coverage.
        Variant::Gouraud => (u32::MAX, 1.0, 0.0),
        Variant::PhongPlain | Variant::BlinnPlain | Variant::Textured => (1, 0.001, 38.0),
        // Texel boundaries at the brick edges: a pixel whose centre falls on the other side
        // of a step than the reference's gets the other slope.
        Variant::BumpDerivatives | Variant::BumpHeights => (1, 0.005, 36.0),
        // The normal map is filtered in RGB565: the blend is rounded to 5/6 bits per axis.
        Variant::NormalMap => (3, 0.02, 35.0),
    }
}

#[test]
fn every_variant_within_its_budget() {
    let a = Assets::new();
    let s = sphere();
    for v in Variant::ALL {
        for i in FRAMES {
            let rep = run(v, i, &surface::light(i), &a, &s);
            println!("{:>18} light {i:>2}: {rep}", v.name());
            let (p99, over2, psnr) = budget(v);
            assert!(rep.only_candidate + rep.only_reference <= 8, "{v:?}: {rep}");
            assert!(rep.p99 <= p99, "{v:?} light {i}: {rep}");
            assert!(rep.share_over_2 <= over2, "{v:?} light {i}: {rep}");
            assert!(rep.psnr_db >= psnr, "{v:?} light {i}: {rep}");
        }
    }
}

#[test]
fn per_pixel_lighting_keeps_the_highlight_gouraud_loses() {
    let a = Assets::new();
    let s = sphere();
    let light = surface::light(0);
    let g = run(Variant::Gouraud, 0, &light, &a, &s);
    let p = run(Variant::BlinnPlain, 0, &light, &a, &s);
    println!("gouraud {g}\nblinn   {p}");
    assert!(g.max >= 4 * p.max.max(1), "gouraud {g} vs per-pixel {p}");
    assert!(g.psnr_db + 3.0 < p.psnr_db, "gouraud {g} vs per-pixel {p}");
}

#[test]
fn specular_exponents_1_to_128() {
    let s = sphere();
    for e in [1u8, 2, 8, 32, 64, 128] {
        let mut a = Assets::new();
        a.exponent = e;
        for v in [Variant::PhongPlain, Variant::BlinnPlain] {
            let rep = run(v, 0, &surface::light(0), &a, &s);
            println!("e = {e:>3} {:>6}: {rep}", v.name());
            // At e = 1 the highlight is still bright where n·l crosses 0, where the model
            // cuts it: a pixel on either side of the terminator may differ.
            assert!(
                rep.p99 <= 1 && rep.share_over_2 <= 0.0005,
                "e = {e} {v:?}: {rep}"
            );
        }
    }
}

#[test]
fn light_exactly_along_the_normal() {
    let a = Assets::new();
    let s = wall([[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]]);
    // Along the wall's normal (view +z) for a directional light, and straight in front of
    // the centre for a point light: n·l = 1, and the Blinn highlight peaks where h = n.
    for light in [
        PixelLight::directional(Vec3::from_num(0, 0, 1)).unwrap(),
        PixelLight::point(Vec3::from_num(0, 0, -1)).unwrap(),
    ] {
        for v in [
            Variant::BlinnPlain,
            Variant::PhongPlain,
            Variant::BumpHeights,
        ] {
            let rep = run(v, 0, &light, &a, &s);
            println!("{light:?} {:>12}: {rep}", v.name());
            assert!(
                rep.p99 <= 1 && rep.psnr_db >= 36.0,
                "{light:?} {v:?}: {rep}"
            );
        }
        let (px, _) = render_fixel(Variant::BlinnPlain, 0, &light, &a, &s, W, H);
        // The centre is full diffuse plus the full highlight: saturated white.
        assert_eq!(px[(H / 2 * W + W / 2) as usize], 0xFFFF, "{light:?}");
    }
}

#[test]
fn mirrored_and_collapsed_uvs() {
    let a = Assets::new();
    let light = PixelLight::point(Vec3::from_num(-1.5, 1, -2)).unwrap();
    let cases = [
        ("normal", [[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0]]),
        (
            "mirrored u",
            [[2.0, 0.0], [0.0, 0.0], [0.0, 2.0], [2.0, 2.0]],
        ),
        (
            "mirrored v",
            [[0.0, 2.0], [2.0, 2.0], [2.0, 0.0], [0.0, 0.0]],
        ),
        (
            "v collapsed",
            [[0.0, 0.5], [2.0, 0.5], [2.0, 0.5], [0.0, 0.5]],
        ),
        ("all collapsed", [[0.3, 0.3]; 4]),
    ];
    for (name, uv) in cases {
        let s = wall(uv);
        for v in [
            Variant::BumpDerivatives,
            Variant::BumpHeights,
            Variant::NormalMap,
        ] {
            let rep = run(v, 0, &light, &a, &s);
            println!("{name:>14} {:>16}: {rep}", v.name());
            let (p99, over2, psnr) = budget(v);
            // Collapsed uvs magnify one row (or one texel) over the whole wall: the normal
            // map's RGB565 blend error is then everywhere instead of at a few pixels.
            let slack = if name.contains("collapsed") { 1 } else { 0 };
            assert!(rep.p99 <= p99 + slack, "{name} {v:?}: {rep}");
            assert!(
                rep.share_over_2 <= over2 * f64::from(1 + 3 * slack),
                "{name} {v:?}: {rep}"
            );
            assert!(rep.psnr_db >= psnr - 4.0, "{name} {v:?}: {rep}");
        }
    }
}

#[test]
fn steep_steps_and_normals_past_the_horizon() {
    // A 0/255 checker of 4-texel squares: every step is the steepest an 8-bit map has.
    let steps: Vec<u8> = (0..SIZE * SIZE)
        .map(|k| {
            if ((k % SIZE) / 4 + (k / SIZE) / 4).is_multiple_of(2) {
                0
            } else {
                255
            }
        })
        .collect();
    let s = sphere();
    for strength in [0.02, 0.5, 8.0] {
        // 8 steps per texel width: the perturbed normals at the steps point far past the
        // horizon of the light (n·l < 0): ambient only there, never a highlight.
        let a = Assets::with_heights(&steps, strength);
        for i in [0u32, 2] {
            for v in [
                Variant::BumpDerivatives,
                Variant::BumpHeights,
                Variant::NormalMap,
            ] {
                let rep = run(v, i, &surface::light(i), &a, &s);
                println!("strength {strength:>4} light {i} {:>16}: {rep}", v.name());
                assert!(rep.only_candidate + rep.only_reference <= 8, "{v:?}: {rep}");
                // Derivative maps quantise the steepest slope to 127 levels; normal maps
                // to RGB565: bounded, not exact.
                let p99 = if strength > 1.0 { 12 } else { 6 };
                assert!(rep.p99 <= p99, "strength {strength} {v:?}: {rep}");
            }
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(12))]

    /// Any point light in front of the sphere, any moderate strength: the per-pixel
    /// variants stay within their budgets.
    #[test]
    fn any_light_and_strength(
        lx in -4.0f64..4.0, ly in -4.0f64..4.0, lz in -3.0f64..0.0,
        strength in 0.0f64..0.05,
    ) {
        let mut heights = vec![0u8; (SIZE * SIZE) as usize];
        fixel_scenes::bricks::brick_heights(SIZE, &mut heights).unwrap();
        let a = Assets::with_heights(&heights, strength);
        let s = sphere();
        let light = PixelLight::point(Vec3::new(fx(lx), fx(ly), fx(lz))).unwrap();
        for v in [Variant::BlinnPlain, Variant::BumpHeights, Variant::NormalMap] {
            let rep = run(v, 0, &light, &a, &s);
            let (p99, _, _) = budget(v);
            prop_assert!(rep.p99 <= p99 + 1, "{:?} {}", v, rep);
        }
    }
}

/// Golden images of every variant (light 0) and of the derivative-mapped sphere under the
/// grazing light: bit for bit, so any change to the per-pixel arithmetic shows. Bless with
/// `FIXEL_BLESS=1 cargo test --release -p host-tests --test surface_detail goldens` (and
/// look at the images in `host-tests/golden/`).
#[test]
fn goldens() {
    let a = Assets::new();
    let s = sphere();
    for v in Variant::ALL {
        let (px, _) = render_fixel(v, 0, &surface::light(0), &a, &s, W, H);
        host_tests::golden::assert_golden(&format!("surface_{}", v.name()), W, H, &px);
    }
    let (px, _) = render_fixel(
        Variant::BumpDerivatives,
        0,
        &surface::light(2),
        &a,
        &s,
        W,
        H,
    );
    host_tests::golden::assert_golden("surface_bump_grazing", W, H, &px);
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    /// Drawing never panics: any clip-space triangle with any varyings (extreme values
    /// included) through the Phong and bump shaders.
    #[test]
    fn drawing_never_panics(
        pos in proptest::collection::vec(-40_000i32..40_000, 12),
        vary in proptest::collection::vec(any::<i32>(), 24),
    ) {
        use fixel::geometry::{Cull, Vertex, Viewport};
        use fixel::pipeline::{DepthLess, Exact, ShadedDraw};
        use fixel::shading::bump::{Bumped, HeightDifferences, NormalMap};
        use fixel::shading::lighting::{Phong, Specular};
        use fixel::shading::TexBinding;
        use fixel::surface::Frame;
        use fixel::texture::{Bilinear, HeightMap, Lod, MipTexture, Repeat, Texture, Trilinear};
        use fixel::Rgb565;
        let a = Assets::new();
        let tri: [Vertex<8>; 3] = core::array::from_fn(|k| {
            let p: [fixel::math::Fx; 4] = core::array::from_fn(|c| {
                fixel::math::Fx::from_bits(pos[4 * k + c].wrapping_mul(64))
            });
            Vertex::new(p, core::array::from_fn(|c| vary[(8 * k + c) % 24]))
        });
        let (w, h) = (48u32, 40u32);
        let mut px = vec![Rgb565::new(0, 0, 0); (w * h) as usize];
        let mut d = vec![0xFFFFu16; (w * h) as usize];
        let mut frame = Frame::new(&mut px, w, h).unwrap().with_depth(&mut d).unwrap();
        let vp = Viewport::new(0, 0, w, h).unwrap();
        let chain = MipTexture::single(Texture::new(&a.colours, SIZE, SIZE).unwrap());
        let tex = TexBinding::new(&chain, Bilinear, Repeat, Repeat, Lod::default()).unwrap();
        let m = host_tests::surface_scene::material(Specular::Phong, 64);
        ShadedDraw::<_, Exact, DepthLess>::new(Phong { tex, material: m }, vp, Cull::None)
            .unwrap()
            .clip_triangles(&[tri], &mut frame)
            .unwrap();
        let map = HeightMap::new(&a.heights, SIZE, SIZE, a.levels).unwrap();
        let n = HeightDifferences::new(map, fx(31.0)).unwrap();
        let s = Bumped::new(tex, n, (SIZE, SIZE), m).unwrap();
        ShadedDraw::<_, Exact, DepthLess>::new(s, vp, Cull::None)
            .unwrap()
            .clip_triangles(&[tri], &mut frame)
            .unwrap();
        let nchain = MipTexture::new(&a.derivs, SIZE, SIZE, a.levels).unwrap();
        let nb = TexBinding::new(&nchain, Trilinear::default(), Repeat, Repeat, Lod::default()).unwrap();
        let s = Bumped::new(tex, NormalMap { map: nb }, (SIZE, SIZE), m).unwrap();
        ShadedDraw::<_, Exact, DepthLess>::new(s, vp, Cull::None)
            .unwrap()
            .clip_triangles(&[tri], &mut frame)
            .unwrap();
    }
}

#[test]
fn bad_input_is_refused() {
    use fixel::shading::bump::{Bumped, DerivativeMap, HeightDifferences};
    use fixel::shading::lighting::{Material, Specular, SpecularTable};
    use fixel::shading::TexBinding;
    use fixel::texture::{HeightMap, Lod, MipTexture, Nearest, Repeat, Texture};
    let a = Assets::new();
    assert!(SpecularTable::new(0).is_err() && SpecularTable::new(129).is_err());
    let t = SpecularTable::new(8).unwrap();
    assert!(Material::new(257, 0, 0, Specular::Blinn, &t).is_err());
    let map = HeightMap::new(&a.heights, SIZE, SIZE, a.levels).unwrap();
    assert!(HeightDifferences::new(map, fx(32.0)).is_err());
    let chain = MipTexture::new(&a.derivs, SIZE, SIZE, a.levels).unwrap();
    let b = TexBinding::new(&chain, Nearest, Repeat, Repeat, Lod::default()).unwrap();
    assert!(DerivativeMap::new(b, fx(1.0), fx(200.0)).is_err());
    // A colour texture of another size than the normal source.
    let small = [fixel::Rgb565::new(0, 0, 0); 16];
    let sc = MipTexture::single(Texture::new(&small, 4, 4).unwrap());
    let tex = TexBinding::new(&sc, Nearest, Repeat, Repeat, Lod::default()).unwrap();
    let n = HeightDifferences::new(map, fx(0.02)).unwrap();
    let m = Material::new(64, 128, 128, Specular::Blinn, &t).unwrap();
    let e = Bumped::new(tex, n, (SIZE, SIZE), m).err();
    assert!(format!("{e:?}").contains("colour texture's size"), "{e:?}");
    assert!(PixelLight::directional(Vec3::ZERO).is_err());
    let s = sphere();
    let short = &s.tangents[..3];
    assert!(
        fixel::scene::LitMesh::new(&s.positions, &s.normals, &s.uvs, Some(short), &s.indices)
            .is_err()
    );
}
