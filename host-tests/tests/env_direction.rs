//! Cube maps read in an interpolated direction (`Direction`, `DirectionMip`) and the
//! per-pixel reflection (`ReflectPerPixelMip`): GL's cube-map level of detail against the f64 analytic value on a 127-degree wide view (a
//! sky drawn as two triangles and as an 8 x 8 grid, looking across a cube corner so the
//! view crosses three faces), trilinear pixels against the reference, the vertex colour,
//! and hard cases (zero and opposite directions, wild vertices).
//!
//! Figures (printed with `--nocapture`; budgets are these plus a margin). `lambda` error
//! against the analytic value, in levels, 64 x 64 view, 256-texel faces:
//!
//! | what | mean | p99 | max |
//! |---|---|---|---|
//! | `DirectionMip`, LOD per pixel, two triangles | 0.005 | 0.013 | 0.019 |
//! | `DirectionMip`, LOD per pixel, 8 x 8 grid | 0.005 | 0.013 | 0.016 |
//! | `DirectionMip`, LOD per span (first pixel), two triangles | 0.49 | 1.84 | 2.37 |
//! | `DirectionMip`, LOD per span (first pixel), 8 x 8 grid | 0.094 | 0.58 | 0.91 |
//! | `DirectionMip`, LOD per triangle, 8 x 8 grid | 0.10 | 0.47 | 1.10 |
//! | `ReflectPerPixelMip`, `n = v = d`, LOD per pixel, two triangles | 0.005 | 0.014 | 0.018 |
//! | `ReflectPerPixelMip`, `n = v = d`, LOD per pixel, 8 x 8 grid | 0.005 | 0.013 | 0.016 |
//! | `ReflectPerPixelMip`, flat mirror, LOD per pixel, two triangles | 0.005 | 0.013 | 0.019 |
//! | `ReflectPerPixelMip`, flat mirror, LOD per pixel, 8 x 8 grid | 0.005 | 0.013 | 0.017 |
//!
//! (`ReflectPerPixelMip`: the pixels whose reflection is within 0.1 % of a face edge, where
//! either face is GL's choice, are left out: 2 of 4,096 for `n = v = d`, 9 for the mirror.)
//!
//! The trilinear pixels of the two-triangle sky are within 1 LSB of the reference's GL
//! lookup at the analytic `lambda` everywhere.

mod common;
use common::any_bits_env;
use embedded_graphics_core::pixelcolor::{IntoStorage, Rgb565};
use fixel::geometry::{Cull, Vertex, Viewport};
use fixel::math::Fx;
use fixel::pipeline::{DepthLess, Exact, ShadedDraw};
use fixel::shading::env::{
    Direction, DirectionMip, EnvLookupLod, MipCubeMap, ReflectPerPixelMip, WHITE,
};
use fixel::shading::{Fragment, Shader};
use fixel::surface::{Frame, DEPTH_CLEAR};
use fixel::texture::{full_levels, Bilinear, Lod, LodGranularity, MipTexture, Trilinear};
use host_tests::env_scene::{ref_chains, sky_chains};
use host_tests::reference::env::{cube_lambda, cube_sample_lod};
use proptest::prelude::*;

/// The view's side in pixels.
const N: u32 = 64;
/// `tan` of half the view angle: 2.006 is 63.5 degrees, 127 across.
const T: f64 = 2.006;
/// Face side of the mipmapped sky.
const SIZE: u32 = 256;

/// View space to world: yaw 35 degrees then pitch 25 degrees, so the view (down -z)
/// crosses the edges between faces -Z, -X and +Y.
fn rotation() -> [[f64; 3]; 3] {
    let (a, b) = (35f64.to_radians(), 25f64.to_radians());
    let yaw = [
        [a.cos(), 0.0, a.sin()],
        [0.0, 1.0, 0.0],
        [-a.sin(), 0.0, a.cos()],
    ];
    let pitch = [
        [1.0, 0.0, 0.0],
        [0.0, b.cos(), -b.sin()],
        [0.0, b.sin(), b.cos()],
    ];
    mul(yaw, pitch)
}

fn mul(a: [[f64; 3]; 3], b: [[f64; 3]; 3]) -> [[f64; 3]; 3] {
    core::array::from_fn(|i| core::array::from_fn(|j| (0..3).map(|k| a[i][k] * b[k][j]).sum()))
}

fn apply(m: [[f64; 3]; 3], v: [f64; 3]) -> [f64; 3] {
    core::array::from_fn(|i| (0..3).map(|k| m[i][k] * v[k]).sum())
}

/// The view ray (world space) through NDC point `(x, y)`: `R (x T, y T, -1)`.
fn ray(x: f64, y: f64) -> [f64; 3] {
    apply(rotation(), [x * T, y * T, -1.0])
}

/// A vertex at NDC `(x, y)` with clip `w` (so the draw is perspective-correct), its
/// direction the view ray times `w` (a point on it), in units of 2^-20, and `colour`.
fn vertex(x: f64, y: f64, w: f64, colour: [i32; 3]) -> Vertex<6> {
    let d = ray(x, y).map(|c| (c * w * f64::from(1 << 20)) as i32);
    Vertex::new(
        [x * w, y * w, 0.0, w].map(Fx::from_num),
        [d[0], d[1], d[2], colour[0], colour[1], colour[2]],
    )
}

/// The whole view as a `k x k` grid of quads, two triangles each, with `w` varying from 1
/// to 3 across it (the directions stay the view rays: only their perspective changes).
fn wide_view(k: u32) -> Vec<[Vertex<6>; 3]> {
    let at = |i: u32, j: u32| {
        let (x, y) = (
            2.0 * f64::from(i) / f64::from(k) - 1.0,
            2.0 * f64::from(j) / f64::from(k) - 1.0,
        );
        vertex(x, y, 1.0 + (x + 1.0) * 0.6 + (y + 1.0) * 0.4, WHITE)
    };
    let mut tris = Vec::new();
    for j in 0..k {
        for i in 0..k {
            let (a, b, c, d) = (at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1));
            tris.push([a, b, c]);
            tris.push([a, c, d]);
        }
    }
    tris
}

/// The view's pixel `(px, py)` centre as NDC (y up; the sign does not change a length).
fn ndc(px: u32, py: u32) -> (f64, f64) {
    let f = |p: u32| (f64::from(p) + 0.5) * 2.0 / f64::from(N) - 1.0;
    (f(px), -f(py))
}

/// The analytic GL `lambda` at every pixel: the ray and its derivatives per pixel.
fn analytic_lambda(size: u32) -> Vec<f64> {
    let r = rotation();
    let step = 2.0 * T / f64::from(N);
    (0..N * N)
        .map(|k| {
            let (x, y) = ndc(k % N, k / N);
            cube_lambda(
                ray(x, y),
                apply(r, [step, 0.0, 0.0]),
                apply(r, [0.0, step, 0.0]),
                f64::from(size),
            )
        })
        .collect()
}

/// Draws `tris` with `shader` into an `N x N` frame (no culling): raw pixels and coverage.
fn draw<S: Shader<Varyings = [i32; V]>, const V: usize>(
    shader: S,
    tris: &[[Vertex<V>; 3]],
) -> (Vec<u16>, Vec<bool>) {
    let vp = Viewport::new(0, 0, N, N).unwrap();
    let d = ShadedDraw::<_, Exact, DepthLess>::new(shader, vp, Cull::None).unwrap();
    let n = (N * N) as usize;
    let (mut color, mut depth) = (vec![Rgb565::new(0, 0, 0); n], vec![0u16; n]);
    let mut frame = Frame::new(&mut color, N, N)
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
    (
        frame.pixels().iter().map(|c| c.into_storage()).collect(),
        cov,
    )
}

/// Writes `lambda` (Q8.8, offset by 8 levels) instead of a colour: `DirectionMip`'s.
#[derive(Clone, Copy, Debug)]
struct DirLambda<M>(DirectionMip<M>);

impl<M: EnvLookupLod> Shader for DirLambda<M> {
    type Varyings = [i32; 6];
    type Triangle = ();
    const LOD: bool = true;
    const LOD_DIRECTION: Option<usize> = Some(0);
    fn lod_granularity(&self) -> LodGranularity {
        self.0.lod.granularity
    }
    fn triangle(&self, v: &mut [[i32; 6]; 3]) {
        self.0.triangle(v)
    }
    fn shade(&self, f: &Fragment<[i32; 6], ()>) -> Option<u16> {
        Some((self.0.lambda(f.lambda) + 8 * 256).clamp(0, 0xFFFF) as u16)
    }
}

/// The same for `ReflectPerPixelMip` (the level of detail of its per-pixel reflection).
#[derive(Clone, Copy, Debug)]
struct ReflLambda<M>(ReflectPerPixelMip<M>);

impl<M: EnvLookupLod> Shader for ReflLambda<M> {
    type Varyings = [i32; 6];
    type Triangle = ();
    const LOD: bool = true;
    const LOD_REFLECTION: Option<usize> = Some(0);
    fn lod_granularity(&self) -> LodGranularity {
        self.0.lod.granularity
    }
    fn triangle(&self, v: &mut [[i32; 6]; 3]) {
        self.0.triangle(v)
    }
    fn shade(&self, f: &Fragment<[i32; 6], ()>) -> Option<u16> {
        Some((self.0.lambda(f.lambda) + 8 * 256).clamp(0, 0xFFFF) as u16)
    }
}

/// `(mean, p99, max)` of `|got - want|` in levels over covered pixels (a NaN `want` left
/// out).
fn errors(got: &(Vec<u16>, Vec<bool>), want: &[f64]) -> (f64, f64, f64, usize) {
    let mut e: Vec<f64> = (0..want.len())
        .filter(|&i| got.1[i] && !want[i].is_nan())
        .map(|i| (f64::from(got.0[i]) / 256.0 - 8.0 - want[i]).abs())
        .collect();
    e.sort_by(f64::total_cmp);
    let n = e.len();
    let mean = e.iter().sum::<f64>() / n as f64;
    (mean, e[n * 99 / 100], e[n - 1], n)
}

fn chains(c: &[Vec<Rgb565>], size: u32) -> [MipTexture<'_>; 6] {
    let levels = full_levels(size, size);
    core::array::from_fn(|i| MipTexture::new(&c[i], size, size, levels).unwrap())
}

fn lod(granularity: LodGranularity) -> Lod {
    Lod {
        granularity,
        ..Lod::default()
    }
}

/// The bar: per-pixel LOD within 0.1 level at p99 and 0.25 at most of the analytic value,
/// drawn as two triangles and as an 8 x 8 grid, for the direction and the reflection.
#[test]
fn wide_view_lambda_matches_analytic() {
    let c = sky_chains(SIZE);
    let m = chains(&c, SIZE);
    let map = MipCubeMap::new(&m, Trilinear::default()).unwrap();
    let want = analytic_lambda(SIZE);
    for k in [1, 8] {
        let tris = wide_view(k);
        for (name, g) in [
            ("pixel", LodGranularity::Pixel),
            ("span", LodGranularity::Span),
            ("triangle", LodGranularity::Triangle),
        ] {
            let got = draw(DirLambda(DirectionMip { map, lod: lod(g) }), &tris);
            let (mean, p99, max, n) = errors(&got, &want);
            println!(
                "DirectionMip, LOD per {name}, {k}x{k} grid ({n} px): mean {mean:.3}, p99 {p99:.3}, max {max:.3} levels"
            );
            assert_eq!(n, (N * N) as usize);
            if g == LodGranularity::Pixel {
                assert!(p99 <= 0.1 && max <= 0.25, "{k}: p99 {p99} max {max}");
            }
        }
        // ReflectPerPixelMip with n = v = d: the reflection is |d|^2 d, the view ray.
        let same: Vec<[Vertex<6>; 3]> = tris
            .iter()
            .map(|t| {
                t.map(|v| {
                    let a = v.varyings;
                    Vertex::new(v.position, [a[0], a[1], a[2], a[0], a[1], a[2]])
                })
            })
            .collect();
        // And a flat mirror: n constant, v = -d (the eye at the origin), so r is the view
        // ray mirrored in the plane of n.
        let m = MIRROR.map(|c| (c * f64::from(1 << 20)) as i32);
        let mirror: Vec<[Vertex<6>; 3]> = tris
            .iter()
            .map(|t| {
                t.map(|v| {
                    let a = v.varyings;
                    Vertex::new(v.position, [m[0], m[1], m[2], -a[0], -a[1], -a[2]])
                })
            })
            .collect();
        // GL picks either face where the reflection's two largest components tie; the
        // fixed-point reflection (about 11 significant bits) may pick the other face within
        // 0.1 % of an edge, where the two faces' lambda differ: those pixels are left out.
        let near_edge = |d: [f64; 3]| {
            let mut a = d.map(f64::abs);
            a.sort_by(f64::total_cmp);
            a[1] > a[2] * 0.999
        };
        let off_edges = |want: &[f64], dir: &dyn Fn([f64; 3]) -> [f64; 3]| -> Vec<f64> {
            (0..want.len())
                .map(|i| {
                    let (x, y) = ndc(i as u32 % N, i as u32 / N);
                    if near_edge(dir(ray(x, y))) {
                        f64::NAN
                    } else {
                        want[i]
                    }
                })
                .collect()
        };
        let want_same = off_edges(&want, &|d| d);
        let want_mirror = off_edges(&analytic_lambda_mirrored(SIZE), &mirrored);
        for (scene, tris, want) in [
            ("n = v = d", &same, &want_same),
            ("flat mirror", &mirror, &want_mirror),
        ] {
            let edge = want.iter().filter(|l| l.is_nan()).count();
            for (name, g) in [
                ("pixel", LodGranularity::Pixel),
                ("span", LodGranularity::Span),
                ("triangle", LodGranularity::Triangle),
            ] {
                let got = draw(ReflLambda(ReflectPerPixelMip { map, lod: lod(g) }), tris);
                let (mean, p99, max, n) = errors(&got, want);
                println!(
                    "ReflectPerPixelMip ({scene}), LOD per {name}, {k}x{k} grid ({n} px, {edge} on an edge left out): mean {mean:.3}, p99 {p99:.3}, max {max:.3} levels"
                );
                assert_eq!(n + edge, (N * N) as usize);
                assert!(edge <= 16, "{edge}");
                if g == LodGranularity::Pixel {
                    assert!(
                        p99 <= 0.1 && max <= 0.25,
                        "{scene} {k}: p99 {p99} max {max}"
                    );
                }
            }
        }
    }
}

/// The flat mirror's unit normal (world space), not along any axis.
const MIRROR: [f64; 3] = [0.267, 0.535, 0.802];

/// `d` mirrored in the plane of [`MIRROR`]: `d - 2 (m·d) m` (linear, so it mirrors the
/// derivatives too).
fn mirrored(d: [f64; 3]) -> [f64; 3] {
    let len2: f64 = MIRROR.iter().map(|c| c * c).sum();
    let k = 2.0 * (0..3).map(|i| MIRROR[i] * d[i]).sum::<f64>() / len2;
    core::array::from_fn(|i| d[i] - k * MIRROR[i])
}

/// The analytic GL `lambda` at every pixel of the view seen in the flat mirror.
fn analytic_lambda_mirrored(size: u32) -> Vec<f64> {
    let r = rotation();
    let step = 2.0 * T / f64::from(N);
    (0..N * N)
        .map(|k| {
            let (x, y) = ndc(k % N, k / N);
            cube_lambda(
                mirrored(ray(x, y)),
                mirrored(apply(r, [step, 0.0, 0.0])),
                mirrored(apply(r, [0.0, step, 0.0])),
                f64::from(size),
            )
        })
        .collect()
}

/// Trilinear pixels of the two-triangle sky against the reference's GL lookup at the
/// analytic `lambda`, and the vertex colour: a grey vertex colour halves every channel.
#[test]
fn wide_view_pixels_match_reference() {
    let c = sky_chains(SIZE);
    let m = chains(&c, SIZE);
    let map = MipCubeMap::new(&m, Trilinear::default()).unwrap();
    let rc = ref_chains(&c, SIZE);
    let lambda = analytic_lambda(SIZE);
    let got = draw(
        DirectionMip {
            map,
            lod: Lod::default(),
        },
        &wide_view(1),
    );
    let mut over1 = 0;
    let mut worst = 0;
    for (k, &l) in lambda.iter().enumerate() {
        let (x, y) = ndc(k as u32 % N, k as u32 / N);
        let w = cube_sample_lod(&rc, ray(x, y), l);
        let want = [w[0] * 31.0, w[1] * 63.0, w[2] * 31.0];
        let p = got.0[k];
        let ch = [p >> 11, (p >> 5) & 63, p & 31].map(f64::from);
        let d = (0..3)
            .map(|i| (ch[i] - want[i]).abs().round() as u32)
            .max()
            .unwrap();
        over1 += usize::from(d > 1);
        worst = worst.max(d);
    }
    println!("two-triangle trilinear sky vs reference: {over1} px over 1 LSB, max {worst}");
    assert!(
        over1 * 100 <= (N * N) as usize && worst <= 4,
        "{over1} {worst}"
    );
    // The vertex colour: grey (1/2) gives half of each channel, rounded (128.5 at the
    // vertices, so the interpolated colour's integer part is 128 everywhere).
    let half = [(128 << 16) + (1 << 15); 3];
    let tris: Vec<[Vertex<6>; 3]> = wide_view(1)
        .iter()
        .map(|t| {
            t.map(|v| {
                let a = v.varyings;
                Vertex::new(v.position, [a[0], a[1], a[2], half[0], half[1], half[2]])
            })
        })
        .collect();
    let grey = draw(
        DirectionMip {
            map,
            lod: Lod::default(),
        },
        &tris,
    );
    for (a, b) in got.0.iter().zip(&grey.0) {
        let h = |c: u16, sh: u16, m: u16| (((c >> sh) & m) + 1) >> 1;
        assert_eq!(
            [b >> 11, (b >> 5) & 63, b & 31],
            [h(*a, 11, 31), h(*a, 5, 63), h(*a, 0, 31)]
        );
    }
}

/// `EnvVertices::per_vertex_colour` is `per_vertex`'s reflection and the colour.
#[test]
fn per_vertex_colour_vertices() {
    use fixel::math::{Angle, Mat4, Vec3};
    use fixel::shading::env::EnvVertices;
    let proj = Mat4::perspective(
        Angle::from_degrees(Fx::from_num(45)),
        Fx::from_num(1),
        Fx::from_num(0.5),
        Fx::from_num(20),
    )
    .unwrap();
    let s = EnvVertices::new(&Mat4::IDENTITY, &proj, Vec3::ZERO);
    let (p, n) = (Vec3::from_num(0.5, -1, -4), Vec3::from_num(0, 0.6, 0.8));
    let a = s.per_vertex(p, n).unwrap();
    let b = s.per_vertex_colour(p, n, [1, 2, 3]).unwrap();
    assert_eq!(a.position, b.position);
    assert_eq!(
        b.varyings,
        [a.varyings[0], a.varyings[1], a.varyings[2], 1, 2, 3]
    );
}

/// Zero directions, opposite directions across one triangle (the direction passes through
/// zero inside it) and a direction per vertex along each axis: no panic, every pixel drawn.
#[test]
fn hard_cases() {
    let c = sky_chains(16);
    let m = chains(&c, 16);
    let map = MipCubeMap::new(&m, Trilinear::default()).unwrap();
    let one = 1 << 16;
    let v = |x: i32, y: i32, d: [i32; 3]| {
        Vertex::new(
            [x, y, 0, one].map(Fx::from_bits),
            [d[0], d[1], d[2], WHITE[0], WHITE[1], WHITE[2]],
        )
    };
    let tri = |a, b, c| [v(-one, -one, a), v(one, -one, b), v(0, one, c)];
    let big = 1 << 30;
    for t in [
        tri([0; 3], [0; 3], [0; 3]),
        tri([big, 0, 0], [-big, 0, 0], [0, 0, 1]),
        tri([big, 0, 0], [0, big, 0], [0, 0, big]),
        tri(
            [i32::MIN, i32::MAX, 0],
            [i32::MAX, i32::MIN, 1],
            [0, 0, i32::MIN],
        ),
    ] {
        for g in [
            LodGranularity::Pixel,
            LodGranularity::Span,
            LodGranularity::Triangle,
        ] {
            let got = draw(DirectionMip { map, lod: lod(g) }, &[t]);
            assert!(got.1.iter().filter(|&&c| c).count() > 500);
            let seamless = draw(
                DirectionMip {
                    map: map.seamless(),
                    lod: lod(g),
                },
                &[t],
            );
            assert_eq!(got.1, seamless.1);
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: common::cases(256), ..ProptestConfig::default() })]

    /// Wild vertices never panic and never write outside the frame.
    #[test]
    fn wild_triangles_never_panic(
        v in prop::collection::vec(([any_bits_env(), any_bits_env(), any_bits_env(), any_bits_env()], [any_bits_env(), any_bits_env(), any_bits_env(), any_bits_env(), any_bits_env(), any_bits_env()]), 3..8)
    ) {
        let c = sky_chains(8);
        let m = chains(&c, 8);
        let map = MipCubeMap::new(&m, Trilinear::default()).unwrap();
        let verts: Vec<Vertex<6>> = v.iter().map(|(p, a)| Vertex::new(p.map(Fx::from_bits), *a)).collect();
        let tris: Vec<[Vertex<6>; 3]> = verts.windows(3).map(|w| [w[0], w[1], w[2]]).collect();
        for g in [LodGranularity::Pixel, LodGranularity::Span, LodGranularity::Triangle] {
            draw(DirectionMip { map, lod: lod(g) }, &tris);
            draw(DirectionMip { map: map.seamless(), lod: lod(g) }, &tris);
        }
        let flat = host_tests::env_scene::faces(8);
        draw(Direction(host_tests::env_scene::cube(&flat, 8, Bilinear)), &tris);
    }
}
