//! Diffuse (irradiance) and glossy (Phong) environment maps: fixel's baked maps
//! (`convolve_face`) against the f64 brute-force convolution of the reference, and the
//! `EnvLit` shader (base × diffuse + glossy) on the benchmark sphere against the f64
//! reference of the same formula.
//!
//! | what (sky 6 x 32² -> 6 x 16²) | measured |
//! |---|---|
//! | irradiance map vs f64 | max 1 LSB, mean 0.008 |
//! | glossy map (e = 16) vs f64 | max 1 LSB, mean 0.008 |
//! | EnvLit frame (benchmark sphere, T(256, 128) base, ks = 0.5) vs f64 | max 2, mean 0.29, > 1 LSB 0.17 %, 36.8 dB |
//!
//! The mean is three roundings (base × E, ks × G, their sum) against one in the reference.

use embedded_graphics_core::pixelcolor::{IntoStorage, Rgb565};
use fixel::geometry::{Cull, Vertex, Viewport};
use fixel::math::Vec3;
use fixel::pipeline::{DepthLess, Exact, ShadedDraw};
use fixel::shading::env::{convolve_face, sky, CubeMap, EnvLit, EnvVertices, Lobe};
use fixel::shading::TexBinding;
use fixel::surface::{Frame, DEPTH_CLEAR};
use fixel::texture::{Bilinear, Lod, MipTexture, Repeat, Texture};
use fixel::Error;
use host_tests::metrics::{channel_errors, compare_rgb565};
use host_tests::reference::env::{convolve, cube_sample, reflect, render_varyings, texel_dir};
use host_tests::reference::sample::sample;
use host_tests::reference::{rgb565_from_f64, RefFilter, RefTexture, RefWrap};

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

#[test]
fn env_lit_frame_matches_reference() {
    let src = sky_faces();
    let (diff, glos) = (bake(&src, Lobe::Cosine), bake(&src, Lobe::Phong(EXP)));
    fn cube(m: &[Vec<Rgb565>]) -> CubeMap<'_, Bilinear> {
        let faces: [Texture<'_>; 6] =
            core::array::from_fn(|i| Texture::new(&m[i], OUT, OUT).unwrap());
        CubeMap::new(faces, Bilinear).unwrap()
    }
    let mut base = vec![Rgb565::new(0, 0, 0); 256 * 128];
    fixel_scenes::checker_texture(256, 128, &mut base).unwrap();
    let mip = MipTexture::single(Texture::new(&base, 256, 128).unwrap());
    let shader = EnvLit {
        base: TexBinding::new(&mip, Bilinear, Repeat, Repeat, Lod::default()).unwrap(),
        diffuse: cube(&diff),
        glossy: cube(&glos),
        specular: 128,
    };
    let m = fixel_scenes::sphere();
    let cam = fixel_scenes::camera(20);
    let s = EnvVertices::new(
        &fixel_scenes::sphere_model(0),
        &cam.projection.mul(&cam.view),
        Vec3::ZERO,
    );
    let tris: Vec<[Vertex<8>; 3]> = m
        .indices
        .iter()
        .map(|t| {
            t.map(|i| {
                let i = usize::from(i);
                let v = s.per_pixel(m.positions[i], m.normals[i]).unwrap();
                let a = v.varyings;
                let uv = m.uvs[i].map(|c| c.to_bits());
                Vertex::new(
                    v.position,
                    [a[0], a[1], a[2], a[3], a[4], a[5], uv[0], uv[1]],
                )
            })
        })
        .collect();
    let vp = Viewport::new(0, 0, 320, 240).unwrap();
    let d = ShadedDraw::<_, Exact, DepthLess>::new(shader, vp, Cull::Back).unwrap();
    let (mut c, mut z) = (vec![Rgb565::new(0, 0, 0); 320 * 240], vec![0u16; 320 * 240]);
    let mut fr = Frame::new(&mut c, 320, 240)
        .unwrap()
        .with_depth(&mut z)
        .unwrap();
    d.clip_triangles(&tris, &mut fr).unwrap();
    let cov: Vec<bool> = fr
        .depth()
        .unwrap()
        .iter()
        .map(|&v| v != DEPTH_CLEAR)
        .collect();
    let px: Vec<u16> = fr.pixels().iter().map(|c| c.into_storage()).collect();
    let rd: [RefTexture; 6] = core::array::from_fn(|i| {
        reft(
            &diff[i].iter().map(|c| c.into_storage()).collect::<Vec<_>>(),
            OUT,
        )
    });
    let rg: [RefTexture; 6] = core::array::from_fn(|i| {
        reft(
            &glos[i].iter().map(|c| c.into_storage()).collect::<Vec<_>>(),
            OUT,
        )
    });
    let rb = RefTexture {
        width: 256,
        height: 128,
        texels: base.iter().map(|c| c.into_storage()).collect(),
        border: 0,
    };
    let want = render_varyings(&tris, 320, 240, |_, _, a| {
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
        [0, 1, 2].map(|k| (b[k] * e[k] + 0.5 * g[k]).min(1.0))
    });
    let r = compare_rgb565(&px, &cov, &want.0, &want.1);
    println!("EnvLit sphere (base x irradiance + 0.5 glossy e=16): {r}");
    assert!(
        r.both_covered > 20_000 && r.max <= 3 && r.mean <= 0.35 && r.share_over_2 <= 0.001,
        "{r}"
    );
}
