//! Diffuse (irradiance) and glossy (Phong) environment maps: fixel's baked maps
//! (`convolve_face`) against the f64 brute-force convolution of the reference, and the
//! `EnvLit` shader (base × diffuse + glossy) on the benchmark sphere against the f64
//! reference of the same formula, and `Tinted<EnvLit>` (the base times a vertex colour) with
//! a colour per vertex against the same reference times the perspective-correct colour.
//!
//! | what (sky 6 x 32² -> 6 x 16²) | measured |
//! |---|---|
//! | irradiance map vs f64 | max 1 LSB, mean 0.008 |
//! | glossy map (e = 16) vs f64 | max 1 LSB, mean 0.008 |
//! | EnvLit frame (benchmark sphere, T(256, 128) base, ks = 0.5) vs f64 | max 2, mean 0.29, > 1 LSB 0.19 %, 36.8 dB |
//! | `Tinted<EnvLit>` frame (colour per vertex from the normal, channels 0.25..1) vs f64 | max 2, mean 0.28, > 1 LSB 0.06 %, 36.9 dB |
//!
//! The mean is three roundings (base × E, ks × G, their sum) against one in the reference.

mod common;
use common::any_bits_env;
use embedded_graphics_core::pixelcolor::{IntoStorage, Rgb565};
use fixel::geometry::{Cull, Vertex, Viewport};
use fixel::math::Vec3;
use fixel::pipeline::{DepthLess, Exact, ShadedDraw};
use fixel::shading::env::{convolve_face, sky, CubeMap, EnvLit, EnvVertices, Lobe, Tinted, WHITE};
use fixel::shading::TexBinding;
use fixel::surface::{Frame, DEPTH_CLEAR};
use fixel::texture::{Bilinear, Lod, MipTexture, Repeat, Texture};
use fixel::Error;
use host_tests::metrics::{channel_errors, compare_rgb565};
use host_tests::reference::env::{convolve, cube_sample, reflect, render_varyings, texel_dir};
use host_tests::reference::sample::sample;
use host_tests::reference::{rgb565_from_f64, RefFilter, RefTexture, RefWrap};
use proptest::prelude::*;

const SRC: u32 = 32;
const OUT: u32 = 16;
const EXP: u16 = 16;

fn sky_faces() -> Vec<Vec<u16>> {
    (0..6)
        .map(|f| {
            let mut t = vec![Rgb565::new(0, 0, 0); (SRC * SRC) as usize];
            sky::sky_face(f, SRC, &mut t).unwrap();
            t.iter().map(|c| c.into_storage()).collect()
        })
        .collect()
}

fn bake(src: &[Vec<u16>], lobe: Lobe) -> Vec<Vec<Rgb565>> {
    let s: [&[u16]; 6] = core::array::from_fn(|i| &src[i][..]);
    (0..6)
        .map(|f| {
            let mut o = vec![Rgb565::new(0, 0, 0); (OUT * OUT) as usize];
            convolve_face(s, SRC, lobe, f, OUT, &mut o).unwrap();
            o
        })
        .collect()
}

fn reft(t: &[u16], size: u32) -> RefTexture {
    RefTexture {
        width: size,
        height: size,
        texels: t.to_vec(),
        border: 0,
    }
}

#[test]
fn baked_maps_match_reference() {
    let src = sky_faces();
    let rsrc: [RefTexture; 6] = core::array::from_fn(|i| reft(&src[i], SRC));
    for (name, lobe, e) in [
        ("irradiance", Lobe::Cosine, None),
        ("glossy e=16", Lobe::Phong(EXP), Some(u32::from(EXP))),
    ] {
        let maps = bake(&src, lobe);
        let (mut max, mut sum, mut n) = (0, 0u64, 0u64);
        for (f, m) in maps.iter().enumerate() {
            for j in 0..OUT {
                for i in 0..OUT {
                    let want = rgb565_from_f64(convolve(&rsrc, texel_dir(f, i, j, OUT), e));
                    let got = m[(j * OUT + i) as usize].into_storage();
                    let ce = channel_errors(got, want);
                    max = max.max(*ce.iter().max().unwrap());
                    sum += u64::from(ce.iter().sum::<u32>());
                    n += 3;
                }
            }
        }
        println!("{name}: max {max} LSB, mean {:.3}", sum as f64 / n as f64);
        assert!(max <= 1, "{name}: max {max}");
    }
}

#[test]
fn bad_input_is_refused() {
    let a = vec![0u16; 16];
    let s: [&[u16]; 6] = [&a, &a, &a, &a, &a, &a];
    let mut out = vec![Rgb565::new(0, 0, 0); 4];
    assert_eq!(
        convolve_face(s, 4, Lobe::Phong(0), 0, 2, &mut out),
        Err(Error::BadMode("Phong exponent must be in 1..=1000"))
    );
    assert!(matches!(
        convolve_face(s, 4, Lobe::Cosine, 6, 2, &mut out),
        Err(Error::BadCubeMap { face: 6, .. })
    ));
    assert!(matches!(
        convolve_face(s, 8, Lobe::Cosine, 0, 2, &mut out),
        Err(Error::WrongLength { .. })
    ));
    // A uniform sky stays uniform.
    let w = vec![0xFFFFu16; 16];
    let s: [&[u16]; 6] = [&w, &w, &w, &w, &w, &w];
    convolve_face(s, 4, Lobe::Phong(8), 3, 2, &mut out).unwrap();
    assert!(out.iter().all(|c| c.into_storage() == 0xFFFF));
}

/// The scene's maps and base texture: the sky's irradiance and glossy (e = 16) maps, and
/// the checker base.
struct Scene {
    diff: Vec<Vec<Rgb565>>,
    glos: Vec<Vec<Rgb565>>,
    base: Vec<Rgb565>,
}

impl Scene {
    fn new() -> Self {
        let src = sky_faces();
        let mut base = vec![Rgb565::new(0, 0, 0); 256 * 128];
        fixel_scenes::checker_texture(256, 128, &mut base).unwrap();
        Scene {
            diff: bake(&src, Lobe::Cosine),
            glos: bake(&src, Lobe::Phong(EXP)),
            base,
        }
    }

    /// The f64 reference of a pixel from its varyings (`n`, `v`, `u, v`) and the colour
    /// factors: `base × colour × E(n) + 0.5 G(r)`.
    fn reference(&self) -> impl Fn(&[f64], [f64; 3]) -> [f64; 3] {
        let to_ref = |m: &Vec<Vec<Rgb565>>| -> [RefTexture; 6] {
            core::array::from_fn(|i| {
                reft(
                    &m[i].iter().map(|c| c.into_storage()).collect::<Vec<_>>(),
                    OUT,
                )
            })
        };
        let (rd, rg) = (to_ref(&self.diff), to_ref(&self.glos));
        let rb = RefTexture {
            width: 256,
            height: 128,
            texels: self.base.iter().map(|c| c.into_storage()).collect(),
            border: 0,
        };
        move |a, c| {
            let n = [a[0], a[1], a[2]];
            let e = cube_sample(&rd, n, RefFilter::Bilinear);
            let g = cube_sample(&rg, reflect(n, [a[3], a[4], a[5]]), RefFilter::Bilinear);
            let b = sample(
                &rb,
                [a[6] / 65536.0, a[7] / 65536.0],
                RefFilter::Bilinear,
                RefWrap::Repeat,
                RefWrap::Repeat,
            );
            [0, 1, 2].map(|k| (b[k] * c[k] * e[k] + 0.5 * g[k]).min(1.0))
        }
    }
}

fn cube(m: &[Vec<Rgb565>]) -> CubeMap<'_, Bilinear> {
    let faces: [Texture<'_>; 6] = core::array::from_fn(|i| Texture::new(&m[i], OUT, OUT).unwrap());
    CubeMap::new(faces, Bilinear).unwrap()
}

/// The benchmark sphere's vertices for `Tinted<EnvLit>`, the colour of each from
/// `colour(normal)`.
fn sphere_lit(colour: impl Fn(Vec3) -> [i32; 3]) -> Vec<[Vertex<11>; 3]> {
    let m = fixel_scenes::sphere();
    let cam = fixel_scenes::camera(20);
    let s = EnvVertices::new(
        &fixel_scenes::sphere_model(0),
        &cam.projection.mul(&cam.view),
        Vec3::ZERO,
    );
    m.indices
        .iter()
        .map(|t| {
            t.map(|i| {
                let i = usize::from(i);
                let (p, n) = (m.positions[i], m.normals[i]);
                let uv = m.uvs[i].map(|c| c.to_bits());
                s.per_pixel_lit(p, n, uv, colour(n)).unwrap()
            })
        })
        .collect()
}

/// The first eight varyings (the untinted shader's vertices).
fn eight(t: &[[Vertex<11>; 3]]) -> Vec<[Vertex<8>; 3]> {
    t.iter()
        .map(|t| t.map(|v| Vertex::new(v.position, core::array::from_fn(|k| v.varyings[k]))))
        .collect()
}

/// Draws `tris` with `shader` on a 320 x 240 frame: the pixels and the covered mask.
fn draw<S: fixel::shading::Shader<Varyings = [i32; N]>, const N: usize>(
    shader: S,
    tris: &[[Vertex<N>; 3]],
) -> (Vec<u16>, Vec<bool>) {
    let vp = Viewport::new(0, 0, 320, 240).unwrap();
    let d = ShadedDraw::<_, Exact, DepthLess>::new(shader, vp, Cull::Back).unwrap();
    let (mut c, mut z) = (vec![Rgb565::new(0, 0, 0); 320 * 240], vec![0u16; 320 * 240]);
    let mut fr = Frame::new(&mut c, 320, 240)
        .unwrap()
        .with_depth(&mut z)
        .unwrap();
    d.clip_triangles(tris, &mut fr).unwrap();
    let cov = fr
        .depth()
        .unwrap()
        .iter()
        .map(|&v| v != DEPTH_CLEAR)
        .collect();
    (fr.pixels().iter().map(|c| c.into_storage()).collect(), cov)
}

/// Q8.16 of 1.0.
const ONE: f64 = (256 << 16) as f64;

/// A vertex colour from the normal: each channel in `[0.25, 1]`, Q8.16.
fn colour_of(n: Vec3) -> [i32; 3] {
    let c = |x: fixel::math::Fx| ((0.625 + 0.375 * x.to_num::<f64>()) * ONE) as i32;
    [c(n.x), c(n.y), c(n.z)]
}

#[test]
fn env_lit_frame_matches_reference() {
    let sc = Scene::new();
    let mip = MipTexture::single(Texture::new(&sc.base, 256, 128).unwrap());
    let shader = EnvLit {
        base: TexBinding::new(&mip, Bilinear, Repeat, Repeat, Lod::default()).unwrap(),
        diffuse: cube(&sc.diff),
        glossy: cube(&sc.glos),
        specular: 128,
    };
    let tris = eight(&sphere_lit(|_| WHITE));
    let got = draw(shader, &tris);
    let f = sc.reference();
    let want = render_varyings(&tris, 320, 240, |_, _, a| f(&a, [1.0; 3]));
    let r = compare_rgb565(&got.0, &got.1, &want.0, &want.1);
    println!("EnvLit sphere (base x irradiance + 0.5 glossy e=16): {r}");
    assert!(
        r.both_covered > 20_000 && r.max <= 3 && r.mean <= 0.35 && r.share_over_2 <= 0.001,
        "{r}"
    );
}

/// `Tinted<EnvLit>` with a colour per vertex against the f64 reference (the base times the
/// perspective-correct colour times the irradiance, plus the glossy term).
#[test]
fn tinted_env_lit_frame_matches_reference() {
    let sc = Scene::new();
    let mip = MipTexture::single(Texture::new(&sc.base, 256, 128).unwrap());
    let shader = EnvLit {
        base: TexBinding::new(&mip, Bilinear, Repeat, Repeat, Lod::default()).unwrap(),
        diffuse: cube(&sc.diff),
        glossy: cube(&sc.glos),
        specular: 128,
    };
    let tris = sphere_lit(colour_of);
    let got = draw(Tinted(shader), &tris);
    let f = sc.reference();
    let want = render_varyings(&tris, 320, 240, |_, _, a| {
        f(&a, [8, 9, 10].map(|k| (a[k] / ONE).clamp(0.0, 1.0)))
    });
    let r = compare_rgb565(&got.0, &got.1, &want.0, &want.1);
    println!("Tinted<EnvLit> sphere (colour per vertex): {r}");
    assert!(
        r.both_covered > 20_000 && r.max <= 3 && r.mean <= 0.45 && r.share_over_2 <= 0.002,
        "{r}"
    );
}

/// White leaves every pixel of the untinted shader as it is; a colour of one half halves
/// the base term only (the glossy term is added untinted).
#[test]
fn tinted_env_lit_white_is_env_lit() {
    let sc = Scene::new();
    let mip = MipTexture::single(Texture::new(&sc.base, 256, 128).unwrap());
    let shader = |specular| EnvLit {
        base: TexBinding::new(&mip, Bilinear, Repeat, Repeat, Lod::default()).unwrap(),
        diffuse: cube(&sc.diff),
        glossy: cube(&sc.glos),
        specular,
    };
    let white = sphere_lit(|_| WHITE);
    let plain = draw(shader(128), &eight(&white));
    assert!(plain.1.iter().filter(|&&c| c).count() > 20_000);
    let tinted = draw(Tinted(shader(128)), &white);
    assert!(tinted.1 == plain.1, "coverage differs");
    let diff: Vec<_> = (0..plain.0.len())
        .filter(|&i| plain.0[i] != tinted.0[i])
        .map(|i| (i, plain.0[i], tinted.0[i]))
        .collect();
    assert!(
        diff.is_empty(),
        "{} pixels differ: {:?}",
        diff.len(),
        &diff[..diff.len().min(8)]
    );
    // No gloss, a colour of one half (128.5 at the vertices, 128 once truncated): the
    // channels of the lit base, halved with one rounding of the Q8 product.
    let half = sphere_lit(|_| [(128 << 16) + (1 << 15); 3]);
    let (full, halved) = (
        draw(shader(0), &eight(&white)),
        draw(Tinted(shader(0)), &half),
    );
    assert!(full.1 == halved.1, "coverage differs");
    let mut differ = 0;
    for (a, b) in full.0.iter().zip(&halved.0) {
        for (sh, m) in [(11, 31), (5, 63), (0, 31)] {
            let (a, b) = ((a >> sh) & m, (b >> sh) & m);
            // Halving the factor before the base's rounding: within 1 of half the channel.
            assert!(b.abs_diff(a / 2) <= 1, "{a} -> {b}");
            differ += usize::from(b != a.div_ceil(2));
        }
    }
    println!("half tint: {differ} channels differ from the rounded half of the untinted");
}

proptest! {
    #![proptest_config(ProptestConfig { cases: common::cases(256), ..ProptestConfig::default() })]

    /// Wild vertices (positions, vectors, texture coordinates and colours) never panic and
    /// never write outside the frame.
    #[test]
    fn tinted_env_lit_wild_triangles_never_panic(
        v in prop::collection::vec(([any_bits_env(), any_bits_env(), any_bits_env(), any_bits_env()], prop::array::uniform11(any_bits_env())), 3..8)
    ) {
        let w = [Rgb565::new(31, 63, 31); 16];
        let t = Texture::new(&w, 4, 4).unwrap();
        let sky = CubeMap::new([t; 6], Bilinear).unwrap();
        let mip = MipTexture::single(t);
        let shader = EnvLit {
            base: TexBinding::new(&mip, Bilinear, Repeat, Repeat, Lod::default()).unwrap(),
            diffuse: sky,
            glossy: sky,
            specular: 200,
        };
        let verts: Vec<Vertex<11>> = v.iter().map(|(p, a)| Vertex::new(p.map(fixel::math::Fx::from_bits), *a)).collect();
        let tris: Vec<[Vertex<11>; 3]> = verts.windows(3).map(|w| [w[0], w[1], w[2]]).collect();
        let vp = Viewport::new(0, 0, 40, 32).unwrap();
        let (mut color, mut depth) = (vec![Rgb565::new(0, 0, 0); 40 * 32], vec![0u16; 40 * 32]);
        let mut frame = Frame::new(&mut color, 40, 32).unwrap().with_depth(&mut depth).unwrap();
        let d = ShadedDraw::<_, Exact, DepthLess>::new(Tinted(shader), vp, Cull::None).unwrap();
        d.clip_triangles(&tris, &mut frame).unwrap();
    }
}
