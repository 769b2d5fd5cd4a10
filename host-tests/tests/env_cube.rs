//! Cube-map environment mapping against the f64 reference (`host_tests::reference::env`):
//! the lookup (face selection, face coordinates, nearest and bilinear), the hard cases
//! (edge and corner ties, tiny components, zero directions and normals, extremes),
//! and whole frames of the benchmark sphere and cube with `r` per pixel and per vertex.
//!
//! Figures (printed with `--nocapture`; the budgets below are these plus a margin):
//!
//! | what | measured (64-texel sky faces) |
//! |---|---|
//! | face coordinates, 200k directions | max error 1.8 Q16 units (2^-16) in s, t |
//! | nearest lookup, 100k directions | 16 differ, all within 2^-15 size texel of a texel edge |
//! | bilinear lookup, 100k directions | max 1 LSB, mean 0.003 |
//! | sphere 24x48, per pixel, nearest | mean 0.017 LSB, > 2 LSB 0.15 % (max 25: face edges) |
//! | sphere, per pixel, bilinear | mean 0.017, > 2 LSB 0.04 % |
//! | cube, per pixel, nearest / bilinear | mean 0.019 / 0.018, > 2 LSB 0.23 % / 0 % |
//! | per-vertex r vs its own reference (interpolated r) | max 1 LSB on sphere and cube |
//! | per-vertex r vs the per-pixel reference, sphere | mean 0.24, > 1 LSB 5.4 %, max 44 |
//! | per-vertex r vs the per-pixel reference, cube | mean 3.03, > 1 LSB 49.5 %, max 20 |

mod common;
use common::any_bits_env;
use embedded_graphics_core::pixelcolor::Rgb565;
use fixel::geometry::{Cull, Vertex, Viewport};
use fixel::math::{Mat4, Vec3};
use fixel::pipeline::{DepthLess, Exact, ShadedDraw};
use fixel::shading::env::{
    face_coords, sky, CubeMap, EnvLookup, EnvVertices, ReflectPerPixel, ReflectPerVertex,
};
use fixel::shading::Shader;
use fixel::surface::{Frame, DEPTH_CLEAR};
use fixel::texture::{Bilinear, Nearest, Sampler, Texture};
use fixel::Error;
use host_tests::env_scene::directions;
use host_tests::metrics::{compare_rgb565, Report};
use host_tests::reference::env::{cube_face_st, cube_sample, reflect, render_varyings};
use host_tests::reference::{RefFilter, RefTexture};
use proptest::prelude::*;

const W: u32 = 320;
const H: u32 = 240;
const SIZE: u32 = 64;

fn faces(size: u32) -> Vec<Vec<Rgb565>> {
    (0..6)
        .map(|f| {
            let mut t = vec![Rgb565::new(0, 0, 0); (size * size) as usize];
            sky::sky_face(f, size, &mut t).unwrap();
            t
        })
        .collect()
}

fn bits(c: Rgb565) -> u16 {
    use embedded_graphics_core::pixelcolor::IntoStorage;
    c.into_storage()
}

fn ref_faces(f: &[Vec<Rgb565>], size: u32) -> [RefTexture; 6] {
    core::array::from_fn(|i| RefTexture {
        width: size,
        height: size,
        texels: f[i].iter().map(|&c| bits(c)).collect(),
        border: 0,
    })
}

fn cube<F: Sampler>(f: &[Vec<Rgb565>], size: u32, filter: F) -> CubeMap<'_, F> {
    CubeMap::new(
        core::array::from_fn(|i| Texture::new(&f[i], size, size).unwrap()),
        filter,
    )
    .unwrap()
}

fn to_f64(d: [i32; 3]) -> [f64; 3] {
    d.map(f64::from)
}

#[test]
fn face_coordinates_match_the_gl_table() {
    let mut worst = 0.0f64;
    for d in directions(200_000) {
        let c = face_coords(d);
        let (f, s, t) = cube_face_st(to_f64(d));
        assert_eq!(usize::from(c.face), f, "{d:?}");
        let e = (f64::from(c.s) / 65536.0 - s)
            .abs()
            .max((f64::from(c.t) / 65536.0 - t).abs());
        worst = worst.max(e);
    }
    println!(
        "face coords: max |error| = {:.3} Q16 units",
        worst * 65536.0
    );
    assert!(worst <= 2.0 / 65536.0, "face coordinates off by {worst}");
}

/// Nearest: the same texel as the reference except where the exact coordinate lies within
/// `2^-15 * size` texel of a texel edge (the face coordinates' error bound).
#[test]
fn nearest_lookup_matches_reference() {
    let f = faces(SIZE);
    let (c, rf) = (cube(&f, SIZE, Nearest), ref_faces(&f, SIZE));
    let (mut diff, mut n) = (0, 0);
    for d in directions(100_000) {
        n += 1;
        let got = c.lookup(d);
        let want =
            host_tests::reference::rgb565_from_f64(cube_sample(&rf, to_f64(d), RefFilter::Nearest));
        if got != want {
            let (_, s, t) = cube_face_st(to_f64(d));
            let edge = |x: f64| {
                let u = x * f64::from(SIZE);
                (u - u.round()).abs()
            };
            assert!(
                edge(s).min(edge(t)) <= 2.0 / 65536.0 * f64::from(SIZE),
                "{d:?}: {got:04x} vs {want:04x} away from a texel edge"
            );
            diff += 1;
        }
    }
    println!("nearest lookup: {diff} of {n} differ (all at texel edges)");
}

#[test]
fn bilinear_lookup_within_one_lsb() {
    let f = faces(SIZE);
    let (c, rf) = (cube(&f, SIZE, Bilinear), ref_faces(&f, SIZE));
    let (mut max, mut sum, mut n) = (0u32, 0u64, 0u64);
    for d in directions(100_000) {
        let got = c.lookup(d);
        let want = host_tests::reference::rgb565_from_f64(cube_sample(
            &rf,
            to_f64(d),
            RefFilter::Bilinear,
        ));
        let e = host_tests::metrics::channel_errors(got, want);
        max = max.max(*e.iter().max().unwrap());
        sum += u64::from(e.iter().sum::<u32>());
        n += 3;
    }
    println!(
        "bilinear lookup: max {max} LSB, mean {:.4}",
        sum as f64 / n as f64
    );
    assert!(max <= 1, "bilinear lookup max error {max}");
}

/// Edges and corners where magnitudes tie: x before y before z, positive or negative by the
/// major component's sign; both fixel and the reference follow it, and the face coordinate
/// on the tied axis is exactly 0 or 1.
#[test]
fn ties_on_edges_and_corners() {
    let k = 12345;
    for sx in [-1, 0, 1] {
        for sy in [-1, 0, 1] {
            for sz in [-1, 0, 1] {
                let d = [sx * k, sy * k, sz * k];
                let c = face_coords(d);
                let (f, s, t) = cube_face_st(to_f64(d));
                assert_eq!(usize::from(c.face), f, "{d:?}");
                assert_eq!(f64::from(c.s) / 65536.0, s, "{d:?}");
                assert_eq!(f64::from(c.t) / 65536.0, t, "{d:?}");
                let expect = if sx != 0 {
                    if sx > 0 {
                        0
                    } else {
                        1
                    }
                } else if sy != 0 {
                    if sy > 0 {
                        2
                    } else {
                        3
                    }
                } else if sz != 0 {
                    if sz > 0 {
                        4
                    } else {
                        5
                    }
                } else {
                    0
                };
                assert_eq!(c.face, expect, "{d:?}");
            }
        }
    }
}

/// Directions whose components are all tiny (a few units) are still exact directions:
/// the lookup normalises by leading zeros, so `(1, 0, 0)` is as good as `(2^30, 0, 0)`.
#[test]
fn tiny_components() {
    for d in [
        [1, 0, 0],
        [0, -1, 0],
        [0, 0, 1],
        [1, 1, 0],
        [3, 2, 1],
        [-1, 2, -3],
        [1, -1, 1],
        [2, 1, 1],
        [-7, 5, 3],
    ] {
        let c = face_coords(d);
        let (f, s, t) = cube_face_st(to_f64(d));
        assert_eq!(usize::from(c.face), f, "{d:?}");
        assert!(
            (f64::from(c.s) / 65536.0 - s).abs() <= 1.0 / 65536.0,
            "{d:?}"
        );
        assert!(
            (f64::from(c.t) / 65536.0 - t).abs() <= 1.0 / 65536.0,
            "{d:?}"
        );
        let big = face_coords(d.map(|v| v << 20));
        assert_eq!(big, c, "{d:?} scaled");
    }
}

#[test]
fn zero_direction_reads_the_centre_of_plus_x() {
    let f = faces(SIZE);
    let c = cube(&f, SIZE, Nearest);
    let (f0, s, t) = cube_face_st([0.0; 3]);
    assert_eq!((f0, s, t), (0, 0.5, 0.5));
    assert_eq!(
        c.lookup([0; 3]),
        bits(f[0][(SIZE / 2 * SIZE + SIZE / 2) as usize])
    );
}

#[test]
fn mismatched_faces_are_refused() {
    let a = vec![Rgb565::new(0, 0, 0); 64];
    let b = vec![Rgb565::new(0, 0, 0); 32];
    let sq = Texture::new(&a, 8, 8).unwrap();
    let wide = Texture::new(&b, 8, 4).unwrap();
    let small = Texture::new(&a[..16], 4, 4).unwrap();
    let e = CubeMap::new([sq, sq, sq, wide, sq, sq], Nearest).unwrap_err();
    assert_eq!(
        e,
        Error::BadCubeMap {
            face: 3,
            width: 8,
            height: 4
        }
    );
    let e = CubeMap::new([sq, sq, sq, sq, sq, small], Nearest).unwrap_err();
    assert_eq!(
        e,
        Error::BadCubeMap {
            face: 5,
            width: 4,
            height: 4
        }
    );
    assert!(e.to_string().contains("face 5"));
}

// ---------------------------------------------------------------------------------------
// Whole frames.
// ---------------------------------------------------------------------------------------

/// A benchmark mesh as triangles of vertices for both shaders.
struct Scene {
    pixel: Vec<[Vertex<6>; 3]>,
    vertex: Vec<[Vertex<3>; 3]>,
}

fn scene<const V: usize, const T: usize>(m: &fixel_scenes::MeshData<V, T>, model: &Mat4) -> Scene {
    let cam = fixel_scenes::camera(20);
    let s = EnvVertices::new(model, &cam.projection.mul(&cam.view), Vec3::ZERO);
    let tri = |t: &[u16; 3]| t.map(|i| (m.positions[usize::from(i)], m.normals[usize::from(i)]));
    Scene {
        pixel: m
            .indices
            .iter()
            .map(|t| tri(t).map(|(p, n)| s.per_pixel(p, n).unwrap()))
            .collect(),
        vertex: m
            .indices
            .iter()
            .map(|t| tri(t).map(|(p, n)| s.per_vertex(p, n).unwrap()))
            .collect(),
    }
}

fn sphere_scene() -> Scene {
    scene(&fixel_scenes::sphere(), &fixel_scenes::sphere_model(0))
}

fn cube_scene() -> Scene {
    scene(&fixel_scenes::cube(), &fixel_scenes::cube_model(0))
}

fn draw<S: Shader<Varyings = [i32; N]>, const N: usize>(
    shader: S,
    tris: &[[Vertex<N>; 3]],
) -> (Vec<u16>, Vec<bool>) {
    let vp = Viewport::new(0, 0, W, H).unwrap();
    let d = ShadedDraw::<_, Exact, DepthLess>::new(shader, vp, Cull::Back).unwrap();
    let n = (W * H) as usize;
    let (mut color, mut depth) = (vec![Rgb565::new(0, 0, 0); n], vec![0u16; n]);
    let mut frame = Frame::new(&mut color, W, H)
        .unwrap()
        .with_depth(&mut depth)
        .unwrap();
    d.clip_triangles(tris, &mut frame).unwrap();
    let cov = frame
        .depth()
        .unwrap()
        .iter()
        .map(|&z| z != DEPTH_CLEAR)
        .collect();
    (frame.pixels().iter().map(|&c| bits(c)).collect(), cov)
}

/// The reference with the reflection per pixel from the interpolated `n`, `v`.
fn ref_per_pixel(
    tris: &[[Vertex<6>; 3]],
    rf: &[RefTexture; 6],
    filter: RefFilter,
) -> (Vec<u16>, Vec<bool>) {
    render_varyings(tris, W, H, |_, _, a| {
        let r = reflect([a[0], a[1], a[2]], [a[3], a[4], a[5]]);
        cube_sample(rf, r, filter)
    })
}

/// The per-vertex technique's own reference: `r` interpolated, then looked up.
fn ref_per_vertex(
    tris: &[[Vertex<3>; 3]],
    rf: &[RefTexture; 6],
    filter: RefFilter,
) -> (Vec<u16>, Vec<bool>) {
    render_varyings(tris, W, H, |_, _, a| cube_sample(rf, a, filter))
}

fn frame_report(name: &str, got: &(Vec<u16>, Vec<bool>), want: &(Vec<u16>, Vec<bool>)) -> Report {
    let r = compare_rgb565(&got.0, &got.1, &want.0, &want.1);
    println!("{name}: {r}");
    r
}

/// Per-pixel `r` on the benchmark sphere and cube: fixel against the f64 reference.
#[test]
fn per_pixel_matches_reference() {
    let f = faces(SIZE);
    let rf = ref_faces(&f, SIZE);
    for (mesh, sc) in [("sphere", sphere_scene()), ("cube", cube_scene())] {
        for (fname, rfil) in [
            ("nearest", RefFilter::Nearest),
            ("bilinear", RefFilter::Bilinear),
        ] {
            let got = if rfil == RefFilter::Nearest {
                draw(ReflectPerPixel(cube(&f, SIZE, Nearest)), &sc.pixel)
            } else {
                draw(ReflectPerPixel(cube(&f, SIZE, Bilinear)), &sc.pixel)
            };
            let want = ref_per_pixel(&sc.pixel, &rf, rfil);
            // Bit for bit too (bless with FIXEL_BLESS=1 after an intended change).
            host_tests::golden::assert_golden(&format!("env_cube_{mesh}_{fname}"), W, H, &got.0);
            let r = frame_report(&format!("per-pixel {mesh} {fname}"), &got, &want);
            assert!(r.both_covered > 10_000, "{r}");
            assert!(
                r.only_candidate + r.only_reference <= r.both_covered / 200,
                "{r}"
            );
            if rfil == RefFilter::Bilinear {
                assert!(
                    r.mean <= 0.03 && r.share_over_2 <= 0.002,
                    "{mesh} {fname}: {r}"
                );
            } else {
                assert!(
                    r.mean <= 0.03 && r.share_over_2 <= 0.005,
                    "{mesh} {fname}: {r}"
                );
            }
        }
    }
}

/// Per-vertex `r`: exact to its own definition (interpolated `r`), and how far that is from
/// the per-pixel reflection on the benchmark meshes.
#[test]
fn per_vertex_error_on_benchmark_meshes() {
    let f = faces(SIZE);
    let rf = ref_faces(&f, SIZE);
    for (mesh, sc) in [("sphere", sphere_scene()), ("cube", cube_scene())] {
        let got = draw(ReflectPerVertex(cube(&f, SIZE, Bilinear)), &sc.vertex);
        host_tests::golden::assert_golden(&format!("env_cube_{mesh}_per_vertex"), W, H, &got.0);
        let own = ref_per_vertex(&sc.vertex, &rf, RefFilter::Bilinear);
        let r = frame_report(
            &format!("per-vertex {mesh} bilinear vs interpolated-r reference"),
            &got,
            &own,
        );
        assert!(r.max <= 2 && r.mean <= 0.02, "{mesh}: {r}");
        let exact = ref_per_pixel(&sc.pixel, &rf, RefFilter::Bilinear);
        let e = frame_report(
            &format!("per-vertex {mesh} bilinear vs per-pixel reference"),
            &got,
            &exact,
        );
        let pp = draw(ReflectPerPixel(cube(&f, SIZE, Bilinear)), &sc.pixel);
        let p = compare_rgb565(&pp.0, &pp.1, &exact.0, &exact.1);
        // Per-vertex r is the less exact of the two.
        assert!(e.mean > p.mean, "{mesh}: per-vertex {e} per-pixel {p}");
    }
}

/// Zero normals (a degenerate mesh): every pixel reads the centre of +X; nothing panics.
#[test]
fn zero_normals_draw_the_plus_x_centre() {
    let f = faces(SIZE);
    let c = cube(&f, SIZE, Nearest);
    let mut sc = sphere_scene();
    for t in sc.pixel.iter_mut() {
        for v in t.iter_mut() {
            v.varyings[0] = 0;
            v.varyings[1] = 0;
            v.varyings[2] = 0;
        }
    }
    let (px, cov) = draw(ReflectPerPixel(c), &sc.pixel);
    let centre = c.lookup([0; 3]);
    let n = cov.iter().filter(|&&c| c).count();
    assert!(n > 10_000);
    assert!(px.iter().zip(&cov).all(|(&p, &c)| !c || p == centre));
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 256, ..ProptestConfig::default() })]

    /// Any direction: a face in range, coordinates in [0, 1], within 2 Q16 units of the
    /// reference (2 units: the mantissas of the major and minor magnitudes are truncated to
    /// 16 bits).
    #[test]
    fn any_direction(d in [any_bits_env(), any_bits_env(), any_bits_env()]) {
        let c = face_coords(d);
        prop_assert!(c.face <= 5 && c.s <= 65536 && c.t <= 65536);
        let (f, s, t) = cube_face_st(to_f64(d));
        prop_assert_eq!(usize::from(c.face), f);
        prop_assert!((f64::from(c.s) / 65536.0 - s).abs() <= 2.0 / 65536.0);
        prop_assert!((f64::from(c.t) / 65536.0 - t).abs() <= 2.0 / 65536.0);
    }

    /// Wild vertices (positions, normals and eye vectors anywhere in i32) never panic and
    /// never write outside the frame.
    #[test]
    fn wild_triangles_never_panic(
        v in prop::collection::vec(([any_bits_env(), any_bits_env(), any_bits_env(), any_bits_env()], [any_bits_env(), any_bits_env(), any_bits_env(), any_bits_env(), any_bits_env(), any_bits_env()]), 3..10)
    ) {
        let f = faces(4);
        let c = cube(&f, 4, Bilinear);
        let verts: Vec<Vertex<6>> = v
            .iter()
            .map(|(p, a)| Vertex::new(p.map(fixel::math::Fx::from_bits), *a))
            .collect();
        let tris: Vec<[Vertex<6>; 3]> = verts.windows(3).map(|w| [w[0], w[1], w[2]]).collect();
        let vp = Viewport::new(0, 0, 48, 40).unwrap();
        let d = ShadedDraw::<_, Exact, DepthLess>::new(ReflectPerPixel(c), vp, Cull::None).unwrap();
        let (mut color, mut depth) = (vec![Rgb565::new(0, 0, 0); 48 * 40], vec![0u16; 48 * 40]);
        let mut frame = Frame::new(&mut color, 48, 40).unwrap().with_depth(&mut depth).unwrap();
        d.clip_triangles(&tris, &mut frame).unwrap();
        let t3: Vec<[Vertex<3>; 3]> = tris.iter().map(|t| t.map(|v| Vertex::new(v.position, [v.varyings[0], v.varyings[1], v.varyings[2]]))).collect();
        let d = ShadedDraw::<_, Exact, DepthLess>::new(ReflectPerVertex(c), vp, Cull::None).unwrap();
        d.clip_triangles(&t3, &mut frame).unwrap();
    }
}
