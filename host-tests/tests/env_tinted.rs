//! The per-pixel reflection shaders times a vertex colour (`Tinted`): the benchmark sphere
//! with a colour per vertex against the f64 reference (the reflection's texel times the
//! perspective-correct colour), white leaving every pixel of the untinted shader as it is,
//! one half halving every channel, and wild vertices.
//!
//! Figures (printed with `--nocapture`; budgets are these plus a margin), against the
//! reference, 64-texel sky faces:
//!
//! | what | mean | > 2 LSB | max |
//! |---|---|---|---|
//! | `Tinted(ReflectPerPixel)`, bilinear | 0.108 LSB | 0.069 % | 17 |
//! | `Tinted(ReflectPerPixelMip)`, trilinear | 0.129 LSB | 0.077 % | 17 |
//!
//! (The untinted shaders against their reference: 0.023 / 0.062 LSB mean, the same few
//! pixels over 2 LSB on face edges; the colour adds the truncation of the Q8.16 colour to
//! 1/256, as every modulating shader of fixel, and one more rounding per channel.)

mod common;
use common::any_bits_env;
use embedded_graphics_core::pixelcolor::Rgb565;
use fixel::geometry::{Cull, Vertex, Viewport};
use fixel::math::{Fx, Vec3};
use fixel::pipeline::{DepthLess, Exact, ShadedDraw};
use fixel::shading::env::{
    EnvVertices, MipCubeMap, ReflectPerPixel, ReflectPerPixelMip, Tinted, WHITE,
};
use fixel::surface::Frame;
use fixel::texture::{full_levels, Bilinear, Lod, MipTexture, Trilinear};
use host_tests::env_scene::{self, cube, faces, ref_chains, ref_faces, sky_chains, H, W};
use host_tests::metrics::compare_rgb565;
use host_tests::reference::env::{
    cube_sample, cube_sample_trilinear, reflect, render_varyings, render_varyings_with_derivatives,
};
use host_tests::reference::RefFilter;
use proptest::prelude::*;

const SIZE: u32 = 64;

/// Q8.16 of 1.0.
const ONE: f64 = (256 << 16) as f64;

/// The colour of a vertex from its normal: each channel in `[0.25, 1]`, Q8.16.
fn colour_of(n: Vec3) -> [i32; 3] {
    let c = |x: Fx| ((0.625 + 0.375 * x.to_num::<f64>()) * ONE) as i32;
    [c(n.x), c(n.y), c(n.z)]
}

/// The benchmark sphere's triangles with a colour per vertex (or `colour` everywhere).
fn sphere(colour: Option<[i32; 3]>) -> Vec<[Vertex<9>; 3]> {
    env_scene::triangles(
        &fixel_scenes::sphere(),
        &fixel_scenes::sphere_model(0),
        |s: &EnvVertices, p, n| s.per_pixel_colour(p, n, colour.unwrap_or(colour_of(n))),
    )
}

/// The first six varyings (the untinted shaders' vertices).
fn six(t: &[[Vertex<9>; 3]]) -> Vec<[Vertex<6>; 3]> {
    t.iter()
        .map(|t| {
            t.map(|v| {
                let a = v.varyings;
                Vertex::new(v.position, [a[0], a[1], a[2], a[3], a[4], a[5]])
            })
        })
        .collect()
}

/// `rgb` times the interpolated colour of varyings 6..9.
fn tint(rgb: [f64; 3], a: &[f64; 9]) -> [f64; 3] {
    core::array::from_fn(|i| rgb[i] * (a[6 + i] / ONE).clamp(0.0, 1.0))
}

fn mips(c: &[Vec<Rgb565>], size: u32) -> [MipTexture<'_>; 6] {
    let levels = full_levels(size, size);
    core::array::from_fn(|i| MipTexture::new(&c[i], size, size, levels).unwrap())
}

#[test]
fn tinted_sphere_matches_reference() {
    let tris = sphere(None);
    let f = faces(SIZE);
    let rf = ref_faces(&f, SIZE);
    let got = env_scene::draw(Tinted(ReflectPerPixel(cube(&f, SIZE, Bilinear))), &tris);
    let want = render_varyings(&tris, W, H, |_, _, a| {
        let r = reflect([a[0], a[1], a[2]], [a[3], a[4], a[5]]);
        tint(cube_sample(&rf, r, RefFilter::Bilinear), &a)
    });
    let r = compare_rgb565(&got.0, &got.1, &want.0, &want.1);
    println!("Tinted(ReflectPerPixel), bilinear: {r}");
    assert!(r.both_covered > 10_000, "{r}");
    assert!(r.mean <= 0.13 && r.share_over_2 <= 0.0012, "{r}");

    let c = sky_chains(SIZE);
    let m = mips(&c, SIZE);
    let map = MipCubeMap::new(&m, Trilinear::default()).unwrap();
    let rc = ref_chains(&c, SIZE);
    let got = env_scene::draw(
        Tinted(ReflectPerPixelMip {
            map,
            lod: Lod::default(),
        }),
        &tris,
    );
    let rr = |a: &[f64; 9]| reflect([a[0], a[1], a[2]], [a[3], a[4], a[5]]);
    let want = render_varyings_with_derivatives(&tris, W, H, |_, _, a, around| {
        tint(
            cube_sample_trilinear(&rc, rr(&a), around.map(|b| rr(&b))),
            &a,
        )
    });
    let r = compare_rgb565(&got.0, &got.1, &want.0, &want.1);
    println!("Tinted(ReflectPerPixelMip), trilinear: {r}");
    assert!(r.both_covered > 10_000, "{r}");
    assert!(r.mean <= 0.15 && r.share_over_2 <= 0.0012, "{r}");
}

/// White leaves the untinted shaders' frames bit for bit; one half (128.5 at the vertices,
/// so 128 everywhere once truncated) halves every channel, rounded.
#[test]
fn white_is_the_texel_and_half_halves_it() {
    let f = faces(SIZE);
    let c = sky_chains(SIZE);
    let m = mips(&c, SIZE);
    let map = MipCubeMap::new(&m, Trilinear::default()).unwrap();
    let white = sphere(Some(WHITE));
    let half = sphere(Some([(128 << 16) + (1 << 15); 3]));
    let plain = six(&white);
    let lod = Lod::default();
    let frames = [
        (
            env_scene::draw(ReflectPerPixel(cube(&f, SIZE, Bilinear)), &plain),
            env_scene::draw(Tinted(ReflectPerPixel(cube(&f, SIZE, Bilinear))), &white),
            env_scene::draw(Tinted(ReflectPerPixel(cube(&f, SIZE, Bilinear))), &half),
        ),
        (
            env_scene::draw(ReflectPerPixelMip { map, lod }, &plain),
            env_scene::draw(Tinted(ReflectPerPixelMip { map, lod }), &white),
            env_scene::draw(Tinted(ReflectPerPixelMip { map, lod }), &half),
        ),
    ];
    for (plain, white, half) in frames {
        assert_eq!(plain, white);
        assert_eq!(plain.1, half.1);
        let h = |c: u16, sh: u16, m: u16| (((c >> sh) & m) + 1) >> 1;
        for (a, b) in plain.0.iter().zip(&half.0) {
            assert_eq!(
                [b >> 11, (b >> 5) & 63, b & 31],
                [h(*a, 11, 31), h(*a, 5, 63), h(*a, 0, 31)]
            );
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: common::cases(256), ..ProptestConfig::default() })]

    /// Wild vertices (positions, vectors and colours) never panic and never write outside
    /// the frame.
    #[test]
    fn wild_triangles_never_panic(
        v in prop::collection::vec(([any_bits_env(), any_bits_env(), any_bits_env(), any_bits_env()], prop::array::uniform9(any_bits_env())), 3..8)
    ) {
        let f = faces(8);
        let c = sky_chains(8);
        let m = mips(&c, 8);
        let map = MipCubeMap::new(&m, Trilinear::default()).unwrap();
        let verts: Vec<Vertex<9>> = v.iter().map(|(p, a)| Vertex::new(p.map(Fx::from_bits), *a)).collect();
        let tris: Vec<[Vertex<9>; 3]> = verts.windows(3).map(|w| [w[0], w[1], w[2]]).collect();
        let vp = Viewport::new(0, 0, 40, 32).unwrap();
        let (mut color, mut depth) = (vec![Rgb565::new(0, 0, 0); 40 * 32], vec![0u16; 40 * 32]);
        let mut frame = Frame::new(&mut color, 40, 32).unwrap().with_depth(&mut depth).unwrap();
        let d = ShadedDraw::<_, Exact, DepthLess>::new(Tinted(ReflectPerPixel(cube(&f, 8, Bilinear))), vp, Cull::None).unwrap();
        d.clip_triangles(&tris, &mut frame).unwrap();
        let d = ShadedDraw::<_, Exact, DepthLess>::new(Tinted(ReflectPerPixelMip { map, lod: Lod::default() }), vp, Cull::None).unwrap();
        d.clip_triangles(&tris, &mut frame).unwrap();
        let d = ShadedDraw::<_, Exact, DepthLess>::new(Tinted(ReflectPerPixelMip { map: map.seamless(), lod: Lod::default() }), vp, Cull::None).unwrap();
        d.clip_triangles(&tris, &mut frame).unwrap();
    }
}
