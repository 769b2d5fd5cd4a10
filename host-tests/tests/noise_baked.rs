//! The marble baked into the benchmark sphere's texture (`fixel::shading::noise::bake`,
//! the `noise_baked` scene), the real-time form of the solid texture: the bake against its
//! own f64 definition (the f64 marble at each texel's centre point), the baked sphere frame
//! against the f64 textured-sphere reference with that f64 texture, the frame against the
//! f64 solid texture per pixel (what the accurate `noise` mode draws), and a golden.
//!
//! | what (benchmark sphere, frame 0, 256 x 128 bake, at most 6 octaves) | measured |
//! |---|---|
//! | texels vs the f64 bake | mean 0.149, max 4 LSB (fixel's noise: per-pixel solid 0.245 / 4) |
//! | frame vs f64 textured sphere with the f64 bake | mean 0.167, max 3 LSB, 39.6 dB |
//! | frame vs f64 solid marble per pixel | mean 1.04, max 27 LSB, 26.3 dB (per-pixel: 37.4 dB) |

use embedded_graphics_core::pixelcolor::{IntoStorage, Rgb565};
use fixel::math::Fx;
use fixel::scene::DirectionalLight;
use fixel::shading::noise::{
    bake, bake_mips, BakeSurface, BandLimit, Ramps, SolidMesh, SolidShader, SphereSurface,
};
use fixel::texture::{chain_len, full_levels, Filter};
use host_tests::metrics::{channel_errors, compare, compare_rgb565};
use host_tests::reference::noise::{render_solid, RefOctaves, RefPattern};
use host_tests::reference::{render, rgb565_from_f64, RefTexture};
use host_tests::{adapter, scenes};
use proptest::prelude::*;

mod common;

const W: u32 = 256;
const H: u32 = 128;
const OCTAVES: u32 = 6;

fn fixel_bake() -> Vec<Rgb565> {
    let ramps = Ramps::new().unwrap();
    let mut t = vec![Rgb565::new(0, 0, 0); (W * H) as usize];
    let s = fixel_scenes::noise::baked_sphere_surface();
    bake(
        &ramps.marble(),
        &BandLimit::new(OCTAVES as u8),
        &s,
        W,
        H,
        &mut t,
    )
    .unwrap();
    t
}

/// The f64 definition: texel `(i, j)` is the marble at the sphere point of its centre's
/// `(s, t)`, band-limited to the texel's widest side (on the equator).
fn reference_bake() -> Vec<[f64; 3]> {
    let marble = RefPattern::presets()[0];
    let r = fixel_scenes::noise::baked_sphere_surface()
        .radius
        .to_num::<f64>();
    let pi = std::f64::consts::PI;
    let lambda = (2.0 * pi * r / f64::from(W))
        .max(pi * r / f64::from(H))
        .log2();
    (0..W * H)
        .map(|k| {
            let (i, j) = (k % W, k / W);
            let (s, t) = (
                (f64::from(i) + 0.5) / f64::from(W),
                (f64::from(j) + 0.5) / f64::from(H),
            );
            let (th, ph) = (pi * t, 2.0 * pi * s);
            let p = [th.sin() * ph.cos(), th.cos(), -th.sin() * ph.sin()].map(|c| c * r);
            marble.color(
                p,
                RefOctaves::Band {
                    max: OCTAVES,
                    bias: 0.0,
                },
                lambda,
            )
        })
        .collect()
}

fn ref_texture(texels: Vec<u16>) -> RefTexture {
    RefTexture {
        width: W,
        height: H,
        texels,
        border: 0,
    }
}

/// Every texel against the f64 bake.
#[test]
fn bake_matches_reference() {
    let got = fixel_bake();
    let want = reference_bake();
    let (mut max, mut sum) = (0u32, 0u64);
    for (g, w) in got.iter().zip(&want) {
        let e = channel_errors(g.into_storage(), rgb565_from_f64(*w));
        max = max.max(*e.iter().max().unwrap());
        sum += u64::from(e.iter().sum::<u32>());
    }
    let mean = sum as f64 / (3 * got.len()) as f64;
    println!("baked marble 256 x 128 vs the f64 bake: mean {mean:.4} LSB, max {max}");
    assert!(max <= 4 && mean <= 0.2, "max {max} mean {mean}");
}

/// The sphere scene with fixel's bake, against the f64 sphere with the f64 bake; golden.
#[test]
fn baked_frame_matches_reference() {
    let mut s = scenes::sphere(0);
    s.texture = ref_texture(fixel_bake().iter().map(|c| c.into_storage()).collect());
    let mode = fixel::pipeline::DrawMode {
        filter: Filter::Bilinear,
        ..adapter::draw_mode(&s.mode, None, true)
    };
    let tris = scenes::to_ref_triangles(&s);
    let got = adapter::render(
        &adapter::clip_triangles(&tris),
        Some(&s.texture),
        mode,
        s.width,
        s.height,
    );
    let f64_tex = ref_texture(reference_bake().into_iter().map(rgb565_from_f64).collect());
    let want = render(&tris, Some(&f64_tex), &s.mode, s.width, s.height);
    let e = compare(&got.pixels, &got.covered, &want);
    println!("baked sphere vs f64 textured sphere (f64 bake): {e}");
    assert!(e.max <= 4 && e.mean <= 0.25, "{e}");
    host_tests::golden::assert_golden("noise_baked_sphere", s.width, s.height, &got.pixels);
}

/// The baked sphere against the f64 solid marble evaluated per pixel (band-limited to the
/// pixel), and fixel's per-pixel solid texture against the same, for scale.
#[test]
fn baked_frame_against_solid_texture() {
    let sphere = fixel_scenes::sphere();
    let mesh = SolidMesh::new(
        &sphere.positions,
        Some(&sphere.normals),
        &sphere.indices,
        fixel_scenes::noise::SHOWCASE_SCALE,
    )
    .unwrap();
    let mut tris = Vec::new();
    mesh.triangles(
        &fixel_scenes::sphere_model(0),
        &fixel_scenes::camera(20),
        Some(&DirectionalLight::default()),
        |t| tris.push(*t),
    );
    let octaves = RefOctaves::Band {
        max: OCTAVES,
        bias: 0.0,
    };
    let want = render_solid(&tris, RefPattern::presets()[0], octaves, 1, 320, 240);
    let want565 = want.rgb565();
    // fixel's per-pixel solid marble.
    let ramps = Ramps::new().unwrap();
    let vp = fixel::geometry::Viewport::new(0, 0, 320, 240).unwrap();
    let (mut c, mut z) = (vec![Rgb565::new(0, 0, 0); 320 * 240], vec![0u16; 320 * 240]);
    let mut f = fixel::surface::Frame::new(&mut c, 320, 240)
        .unwrap()
        .with_depth(&mut z)
        .unwrap();
    fixel::pipeline::ShadedDraw::<_, fixel::pipeline::Exact, fixel::pipeline::DepthLess>::new(
        SolidShader::new(ramps.marble(), BandLimit::new(OCTAVES as u8)),
        vp,
        fixel::geometry::Cull::Back,
    )
    .unwrap()
    .clip_triangles(&tris, &mut f)
    .unwrap();
    let cov: Vec<bool> = f
        .depth()
        .unwrap()
        .iter()
        .map(|&d| d != fixel::surface::DEPTH_CLEAR)
        .collect();
    let solid: Vec<u16> = f.pixels().iter().map(|p| p.into_storage()).collect();
    let es = compare_rgb565(&solid, &cov, &want565, &want.covered);
    // The baked sphere.
    let mut s = scenes::sphere(0);
    s.texture = ref_texture(fixel_bake().iter().map(|c| c.into_storage()).collect());
    let mode = fixel::pipeline::DrawMode {
        filter: Filter::Bilinear,
        ..adapter::draw_mode(&s.mode, None, true)
    };
    let got = adapter::render(
        &adapter::clip_triangles(&scenes::to_ref_triangles(&s)),
        Some(&s.texture),
        mode,
        s.width,
        s.height,
    );
    let eb = compare_rgb565(&got.pixels, &got.covered, &want565, &want.covered);
    println!("per-pixel solid marble (noise) vs f64 solid: {es}");
    println!("baked marble (noise_baked) vs f64 solid: {eb}");
    assert!(eb.psnr_db >= 25.5, "{eb}");
}

/// Baking every mip level from the pattern: the chain is filled and valid for any size.
#[test]
fn mip_chain_is_baked_per_level() {
    let ramps = Ramps::new().unwrap();
    let levels = full_levels(W, H);
    let mut chain = vec![Rgb565::new(0, 0, 0); chain_len(W, H, levels)];
    let s = fixel_scenes::noise::baked_sphere_surface();
    bake_mips(
        &ramps.marble(),
        &BandLimit::new(6),
        &s,
        W,
        H,
        levels,
        &mut chain,
    )
    .unwrap();
    fixel::texture::MipTexture::new(&chain, W, H, levels).unwrap();
    // Level 0 is the single-level bake.
    assert_eq!(&chain[..(W * H) as usize], &fixel_bake()[..]);
    // The 1 x 1 level: the pattern with every octave replaced by its mean (one colour).
    assert_ne!(*chain.last().unwrap(), Rgb565::new(0, 0, 0));
}

proptest! {
    #![proptest_config(ProptestConfig { cases: common::cases(512), ..ProptestConfig::default() })]

    /// Sphere points within 2^-12 of the radius (relative) of the f64 point, for any
    /// coordinates and radii up to 1000 cells.
    #[test]
    fn sphere_points_match_reference(s in any::<u16>(), t in 0u32..=65536, r in 1i32..(1000 << 16)) {
        let surface = SphereSurface { radius: Fx::from_bits(r) };
        let p = surface.point(u32::from(s), t);
        let rf = f64::from(r) / 65536.0;
        let pi = std::f64::consts::PI;
        let (th, ph) = (pi * f64::from(t) / 65536.0, 2.0 * pi * f64::from(s) / 65536.0);
        let want = [th.sin() * ph.cos(), th.cos(), -th.sin() * ph.sin()].map(|c| c * rf);
        for k in 0..3 {
            let got = f64::from(p[k]) / 65536.0;
            prop_assert!((got - want[k]).abs() <= rf / 4096.0 + 1e-4, "{k}: {got} {}", want[k]);
        }
        let l = surface.texel_lambda(256, 128);
        let lf = (2.0 * pi * rf / 256.0).max(pi * rf / 128.0).log2();
        prop_assert!((f64::from(l) / 256.0 - lf).abs() <= 1.0 / 32.0, "{l} {lf}");
    }
}
