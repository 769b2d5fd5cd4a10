//! Seamless cube-map filtering (`SeamlessCubeMap`, GL's `TEXTURE_CUBE_MAP_SEAMLESS`)
//! against the f64 reference's own seamless filter (`reference::env::cube_sample_seamless`):
//! the lookup over many directions and any direction, the edge and corner hard cases
//! (two or three faces averaged where GL clamps to one), continuity across all twelve edges
//! of a smooth environment, and the benchmark sphere.
//!
//! Figures (printed with `--nocapture`; the budgets are these plus a margin):
//!
//! | what | measured |
//! |---|---|
//! | lookup, 100k directions, 64-texel sky | max 1 LSB, mean 0.003 |
//! | largest step across an edge, smooth 4-texel cube, 1/256-texel steps | seamless 1 LSB, clamped 6 LSB |
//! | sphere 24x48, `r` per pixel, seamless 64-texel sky | max 1 LSB, mean 0.011, 51.3 dB |
//! | the same frame with GL's clamped filter, against the seamless reference | max 20, > 2 LSB 0.55 %, 35.6 dB |
//! | (and against its own, clamped, reference) | max 21, > 2 LSB 0.07 %, 36.9 dB |

mod common;
use common::any_bits_env;
use embedded_graphics_core::pixelcolor::{IntoStorage, Rgb565};
use fixel::shading::env::{sky, CubeMap, EnvLookup, ReflectPerPixel};
use fixel::texture::{Bilinear, Texture};
use host_tests::env_scene::{self, cube, directions, faces, ref_faces};
use host_tests::metrics::{channel_errors, compare_rgb565};
use host_tests::reference::env::{cube_sample, cube_sample_seamless};
use host_tests::reference::{rgb565_from_f64, RefFilter};
use proptest::prelude::*;

const SIZE: u32 = 64;

fn to_f64(d: [i32; 3]) -> [f64; 3] {
    d.map(f64::from)
}

#[test]
fn seamless_lookup_matches_reference() {
    let f = faces(SIZE);
    let (c, rf) = (cube(&f, SIZE, Bilinear).seamless(), ref_faces(&f, SIZE));
    let (mut max, mut sum, mut n) = (0u32, 0u64, 0u64);
    for d in directions(100_000) {
        let got = c.lookup(d);
        let want = rgb565_from_f64(cube_sample_seamless(&rf, to_f64(d)));
        let e = channel_errors(got, want);
        max = max.max(*e.iter().max().unwrap());
        sum += u64::from(e.iter().sum::<u32>());
        n += 3;
    }
    println!(
        "seamless lookup: max {max} LSB, mean {:.4}",
        sum as f64 / n as f64
    );
    assert!(max <= 1, "seamless lookup max error {max}");
}

/// Faces of one plain colour each: on an edge the seamless filter blends the two faces
/// half and half, at a corner the three faces a third each; GL's clamped filter reads one.
#[test]
fn edges_and_corners_blend_their_faces() {
    let colours = env_scene::PLAIN_FACES;
    let texels: Vec<Vec<Rgb565>> = colours.iter().map(|&c| vec![c; 16]).collect();
    let cm = CubeMap::new(
        core::array::from_fn(|i| Texture::new(&texels[i], 4, 4).unwrap()),
        Bilinear,
    )
    .unwrap();
    let sm = cm.seamless();
    let s = 1 << 20;
    // The twelve edges (ties: x before y before z picks the face GL's clamp reads).
    for (d, fs) in [
        ([s, s, 0], [0, 2]),
        ([s, -s, 0], [0, 3]),
        ([s, 0, s], [0, 4]),
        ([s, 0, -s], [0, 5]),
        ([-s, s, 0], [1, 2]),
        ([-s, -s, 0], [1, 3]),
        ([-s, 0, s], [1, 4]),
        ([-s, 0, -s], [1, 5]),
        ([0, s, s], [2, 4]),
        ([0, s, -s], [2, 5]),
        ([0, -s, s], [3, 4]),
        ([0, -s, -s], [3, 5]),
    ] {
        let got = sm.lookup(d);
        assert!(env_scene::is_plain_blend(got, &fs), "edge {d:?}: {got:04x}");
        assert_eq!(cm.lookup(d), colours[fs[0]].into_storage(), "clamped {d:?}");
    }
    // The eight corners.
    for x in [s, -s] {
        for y in [s, -s] {
            for z in [s, -s] {
                let fs = [
                    if x > 0 { 0 } else { 1 },
                    if y > 0 { 2 } else { 3 },
                    if z > 0 { 4 } else { 5 },
                ];
                let got = sm.lookup([x, y, z]);
                assert!(
                    env_scene::is_plain_blend(got, &fs),
                    "corner {:?}: {got:04x}",
                    [x, y, z]
                );
            }
        }
    }
}

/// A smooth environment (colour a linear function of the texel's direction) at 4 texels a
/// face: walking across each of the twelve edges in 1/256-texel steps, the seamless filter
/// never jumps more than 1 LSB; the clamped one jumps by a texel's worth of gradient.
#[test]
fn continuous_across_every_edge() {
    let n = 4u32;
    let texels: Vec<Vec<Rgb565>> = (0..6)
        .map(|f| {
            (0..n * n)
                .map(|k| {
                    let d = sky::texel_direction(f, k % n, k / n, n);
                    let l = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt();
                    let q = |c: f32, m: f32| ((c / l * 0.5 + 0.5) * m).round() as u8;
                    Rgb565::new(q(d[0], 31.0), q(d[1], 63.0), q(d[2], 31.0))
                })
                .collect()
        })
        .collect();
    let cm = CubeMap::new(
        core::array::from_fn(|i| Texture::new(&texels[i], n, n).unwrap()),
        Bilinear,
    )
    .unwrap();
    let sm = cm.seamless();
    let (mut worst_seamless, mut worst_clamped) = (0u32, 0u32);
    // Each edge midpoint e and a direction t across it (e ± t stay on the two faces).
    let s = 1i64 << 24;
    let edges: [([i64; 3], [i64; 3]); 12] = [
        ([1, 1, 0], [1, -1, 0]),
        ([1, -1, 0], [1, 1, 0]),
        ([1, 0, 1], [1, 0, -1]),
        ([1, 0, -1], [1, 0, 1]),
        ([-1, 1, 0], [1, 1, 0]),
        ([-1, -1, 0], [1, -1, 0]),
        ([-1, 0, 1], [1, 0, 1]),
        ([-1, 0, -1], [1, 0, -1]),
        ([0, 1, 1], [0, 1, -1]),
        ([0, 1, -1], [0, 1, 1]),
        ([0, -1, 1], [0, 1, 1]),
        ([0, -1, -1], [0, 1, -1]),
    ];
    for (e, t) in edges {
        // Plus a little along the edge, so the walk is not through the face centre line.
        let along = [1 - e[0].abs(), 1 - e[1].abs(), 1 - e[2].abs()];
        let step = s / 512; // 1/256 texel at 4 texels a face (a face is 2 s wide)
        let mut prev: Option<(u16, u16)> = None;
        for k in -128i64..=128 {
            let d: [i32; 3] =
                core::array::from_fn(|c| (e[c] * s + t[c] * k * step + along[c] * s / 3) as i32);
            let (a, b) = (sm.lookup(d), cm.lookup(d));
            if let Some((pa, pb)) = prev {
                worst_seamless = worst_seamless.max(*channel_errors(a, pa).iter().max().unwrap());
                worst_clamped = worst_clamped.max(*channel_errors(b, pb).iter().max().unwrap());
            }
            prev = Some((a, b));
        }
    }
    println!(
        "largest step across an edge: seamless {worst_seamless} LSB, clamped {worst_clamped} LSB"
    );
    assert!(worst_seamless <= 1, "seamless jumps {worst_seamless}");
    assert!(
        worst_clamped >= 3,
        "the clamped filter should show its seams"
    );
}

/// The zero direction and the extremes: no panic, a colour of the map.
#[test]
fn zero_and_extreme_directions() {
    let f = faces(8);
    let sm = cube(&f, 8, Bilinear).seamless();
    let _ = sm.lookup([0, 0, 0]);
    for d in [
        [i32::MIN, i32::MIN, i32::MIN],
        [i32::MAX, i32::MIN, 0],
        [1, 1, 1],
        [-1, 0, 0],
        [0, 0, i32::MIN],
    ] {
        let _ = sm.lookup(d);
    }
}

/// The benchmark sphere mirroring the 64-texel sky, `r` per pixel, seamless: against the
/// reference's seamless filter; and how far GL's clamped filter is from it.
#[test]
fn seamless_sphere_matches_reference() {
    let f = faces(SIZE);
    let rf = ref_faces(&f, SIZE);
    let tris = env_scene::sphere_pixel();
    let got = env_scene::draw(ReflectPerPixel(cube(&f, SIZE, Bilinear).seamless()), &tris);
    host_tests::golden::assert_golden(
        "env_cube_sphere_seamless",
        env_scene::W,
        env_scene::H,
        &got.0,
    );
    let want = env_scene::reference_per_pixel(&tris, |r| cube_sample_seamless(&rf, r));
    let r = compare_rgb565(&got.0, &got.1, &want.0, &want.1);
    println!("seamless sphere vs seamless reference: {r}");
    assert!(r.both_covered > 10_000, "{r}");
    assert!(r.max <= 2 && r.mean <= 0.03, "{r}");
    let clamped = env_scene::draw(ReflectPerPixel(cube(&f, SIZE, Bilinear)), &tris);
    let c = compare_rgb565(&clamped.0, &clamped.1, &want.0, &want.1);
    println!("clamped sphere vs seamless reference: {c}");
    let own = env_scene::reference_per_pixel(&tris, |r| cube_sample(&rf, r, RefFilter::Bilinear));
    let o = compare_rgb565(&clamped.0, &clamped.1, &own.0, &own.1);
    println!("clamped sphere vs clamped reference: {o}");
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 512, ..ProptestConfig::default() })]

    /// Any direction whose major magnitude is at least 2^12 (so the direction is resolved
    /// finer than a texel): within 1 LSB of the reference.
    #[test]
    fn any_direction_within_one_lsb(d in [any_bits_env(), any_bits_env(), any_bits_env()]) {
        prop_assume!(d.iter().map(|c| c.unsigned_abs()).max().unwrap() >= 1 << 12);
        let f = faces(16);
        let (c, rf) = (cube(&f, 16, Bilinear).seamless(), ref_faces(&f, 16));
        let got = c.lookup(d);
        let want = rgb565_from_f64(cube_sample_seamless(&rf, to_f64(d)));
        let e = channel_errors(got, want);
        prop_assert!(e.iter().all(|&x| x <= 1), "{:?}: {:04x} vs {:04x}", d, got, want);
    }
}

/// The filter chosen survives `.seamless()`: nearest stays nearest (it never reads past a
/// face edge, so it is GL's clamped nearest everywhere), a mipmapped map keeps its filter
/// within a level and between levels (`LINEAR_MIPMAP_NEAREST` never blends two levels,
/// `NEAREST_MIPMAP_NEAREST` equals its clamped form).
#[test]
fn seamless_keeps_the_filter() {
    use fixel::shading::env::{EnvLookupLod, MipCubeMap};
    use fixel::texture::{
        full_levels, LinearMipmapNearest, MipTexture, Nearest, NearestMipmapNearest, Trilinear,
    };
    let f = faces(SIZE);
    let nearest = cube(&f, SIZE, Nearest);
    let seamless = nearest.seamless();
    for d in directions(20_000) {
        assert_eq!(seamless.lookup(d), nearest.lookup(d), "{d:?}");
    }
    // Chains whose levels are plain colours, level k of face i: (4 i + k) in red, k in blue.
    let levels = full_levels(16, 16);
    let chains: Vec<Vec<Rgb565>> = (0..6u8)
        .map(|i| {
            (0..levels)
                .flat_map(|k| {
                    let side = (16 >> k) as usize;
                    vec![Rgb565::new(4 * i + k as u8, 0, 3 * k as u8); side * side]
                })
                .collect()
        })
        .collect();
    let m: [MipTexture<'_>; 6] =
        core::array::from_fn(|i| MipTexture::new(&chains[i], 16, 16, levels).unwrap());
    let nn = MipCubeMap::new(&m, NearestMipmapNearest::default()).unwrap();
    let ln = MipCubeMap::new(&m, LinearMipmapNearest::default()).unwrap();
    let tri = MipCubeMap::new(&m, Trilinear::default()).unwrap();
    for d in directions(4_000) {
        for lambda in [-300, 0, 100, 129, 300, 383, 640, 900, 2000] {
            assert_eq!(
                nn.seamless().lookup_lod(d, lambda),
                nn.lookup_lod(d, lambda),
                "{d:?} {lambda}"
            );
        }
    }
    // Away from the edges every face is one colour per level: LINEAR_MIPMAP_NEAREST reads
    // one level (lambda 1.4 -> level 1), trilinear blends levels 1 and 2.
    let centre = [1 << 20, 3, -7]; // +X
    let one = |k: u8| Rgb565::new(k, 0, 3 * k).into_storage();
    assert_eq!(ln.seamless().lookup_lod(centre, 358), one(1));
    let blended = tri.seamless().lookup_lod(centre, 358);
    assert_ne!(blended, one(1));
    assert_ne!(blended, one(2));
}
