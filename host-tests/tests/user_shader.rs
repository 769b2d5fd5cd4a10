//! A *user-written* shader on fixel's open fragment stage, judged against an f64 reference
//! written in this file from the same formulas.
//!
//! The shader ([`LightMapped`]) is what a firmware author would write for a light-mapped
//! wall: two textures and one extra scalar varying. Varyings (raw `i32` bits):
//!
//! | index | name | format | meaning |
//! |---|---|---|---|
//! | 0, 1 | `u0, v0` | normalized I16F16 (1.0 = whole texture) | base texture, repeat, bilinear |
//! | 2, 3 | `u1, v1` | normalized I16F16 | light map, clamp-to-edge, bilinear |
//! | 4 | `k` | Q8.16 (`256 << 16` = 1.0) | distance darkening (fog-like) factor |
//!
//! Colour, per channel `c` of the base sample (RGB565 channel value):
//!
//! ```text
//! L    = (77 R + 150 G + 29 B) / 256    light-map luminance, R, G, B in 0..=1
//! out  = c * L * clamp(k, 0, 1)         rounded to the channel's RGB565 range
//! ```
//!
//! In the shader this is integer arithmetic: `L` in Q16 from the light map's RGB565 sample
//! (each channel scaled by `65536 / 31` or `65536 / 63`, truncated), `k` shifted to Q16,
//! their product in Q16 (rounded), and each channel `(c * m + 2^15) >> 16`. The reference
//! does the same in f64 on f64 bilinear samples and rounds to RGB565 once, at the end.
//!
//! The f64 reference shares only data with fixel (texel arrays, the I16F16 vertex positions
//! and varying bits, read back exactly as f64). It uses the host-tests reference rasterizer
//! (`to_window`, snapped to 1/16 pixel, top-left coverage at pixel centres) for coverage and
//! screen-space barycentrics, interpolates all five varyings perspective-correctly
//! (`a = Σ λi ai / wi / Σ λi / wi`) and samples both textures with the reference's GL
//! bilinear (`sample`: texel centres at `(i + 0.5) / size`, repeat / clamp-to-edge).

mod common;

use common::{bits, raw, Guarded};
use embedded_graphics_core::pixelcolor::Rgb565;
use fixel::color::rgb565;
use fixel::geometry::{Cull, Vertex, Viewport};
use fixel::math::Fx;
use fixel::pipeline::{
    Affine, DepthLess, Exact, ProjectionStage, ShadedDraw, Subdivided, SubdividedBy,
};
use fixel::shading::{Fragment, Shader, TexBinding, TexTriangle};
use fixel::surface::{Frame, DEPTH_CLEAR};
use fixel::texture::{Bilinear, ClampToEdge, Lod, MipTexture, Repeat, Texture};
use host_tests::metrics::{compare_rgb565, Report};
use host_tests::reference::raster::{rasterize, to_window};
use host_tests::reference::sample::sample;
use host_tests::reference::{rgb565_from_f64, RefFilter, RefTexture, RefVertex, RefWrap};
use proptest::prelude::*;

// ---------------------------------------------------------------------------------------
// The user's shader.
// ---------------------------------------------------------------------------------------

/// Varyings of [`LightMapped`]: `u0, v0, u1, v1, k` (see the module docs).
const VARYINGS: usize = 5;

/// A light-mapped, distance-darkened wall: base texture (repeat, bilinear) times the light
/// map's luminance (clamp-to-edge, bilinear) times the varying `k`.
#[derive(Clone, Copy, Debug)]
struct LightMapped<'a> {
    base: TexBinding<'a, Bilinear, Repeat, Repeat>,
    light: TexBinding<'a, Bilinear, ClampToEdge, ClampToEdge>,
}

/// Luminance of a raw RGB565 colour, Q16 (`0..=65536`): `(77 R + 150 G + 29 B) / 256`.
fn luminance_q16(c: u16) -> u32 {
    let (r5, g6, b5) = (
        u32::from(c >> 11),
        u32::from((c >> 5) & 63),
        u32::from(c & 31),
    );
    let (r, g, b) = (r5 * 65536 / 31, g6 * 65536 / 63, b5 * 65536 / 31);
    (77 * r + 150 * g + 29 * b + 128) >> 8
}

impl Shader for LightMapped<'_> {
    type Varyings = [i32; VARYINGS];
    /// The per-triangle data of the base binding, then the light map's.
    type Triangle = (TexTriangle, TexTriangle);

    // The base pair drives the adaptive projection's error bound and the (unused) LOD.
    const TEXCOORDS: Option<(usize, usize)> = Some((0, 1));

    fn can_draw(&self) -> bool {
        self.base.can_draw() && self.light.can_draw()
    }

    // The span loop undoes this shift on the TEXCOORDS pair only.
    fn coord_shift(t: &Self::Triangle) -> u32 {
        u32::from(t.0.shift)
    }

    fn triangle(&self, v: &mut [[i32; VARYINGS]; 3]) -> Self::Triangle {
        // Each binding rescales its own pair to texel units in place.
        (
            self.base.triangle(v, (0, 1)),
            self.light.triangle(v, (2, 3)),
        )
    }

    fn shade(&self, f: &Fragment<[i32; VARYINGS], Self::Triangle>) -> Option<u16> {
        let [u0, v0, u1, v1, k] = f.varyings;
        let (tb, tl) = f.triangle;
        let base = self.base.sample(tb, u0, v0, f.lambda);
        // The span loop undid the base pair's shift only; the light map's (0 unless a
        // clamp axis saturated) is ours to undo.
        let light = self.light.sample(tl, tl.unshift(u1), tl.unshift(v1), 0);
        let k16 = u64::from((k.clamp(0, 1 << 24) >> 8) as u32); // Q16, 0..=65536
        let m = (u64::from(luminance_q16(light)) * k16 + (1 << 15)) >> 16; // Q16
        let ch = |c: u16| ((u64::from(c) * m + (1 << 15)) >> 16) as u8;
        Some(rgb565(ch(base >> 11), ch((base >> 5) & 63), ch(base & 31)))
    }
}

// ---------------------------------------------------------------------------------------
// Data shared by fixel and the reference: textures, vertices.
// ---------------------------------------------------------------------------------------

const W: u32 = 160;
const H: u32 = 120;

/// 32 x 32 checker of 4-texel cells, with a gradient inside each colour so every channel
/// varies: warm cells `(28, 30 + j, 4 + i / 2)`, cool cells `(4 + j / 2, 12 + i, 26)`.
fn base_texels() -> Vec<u16> {
    let mut t = Vec::with_capacity(32 * 32);
    for j in 0..32u8 {
        for i in 0..32u8 {
            t.push(if ((i / 4) + (j / 4)) % 2 == 0 {
                rgb565(28, 30 + j, 4 + i / 2)
            } else {
                rgb565(4 + j / 2, 12 + i, 26)
            });
        }
    }
    t
}

/// 16 x 16 smooth light map: an elliptic warm spot off the centre (so a swapped or
/// mirrored pair shows), `l = 0.25 + 0.75 exp(-2 d²)` with `d² = ((x - 5) / 6)² + ((y - 9.5)
/// / 9)²` in texels at texel centres; colour `(l, 0.9 l, 0.7 l)` so all three luminance
/// weights matter.
fn light_texels() -> Vec<u16> {
    let mut t = Vec::with_capacity(16 * 16);
    for j in 0..16 {
        for i in 0..16 {
            let (x, y) = (
                (f64::from(i) + 0.5 - 5.0) / 6.0,
                (f64::from(j) + 0.5 - 9.5) / 9.0,
            );
            let l = 0.25 + 0.75 * (-2.0 * (x * x + y * y)).exp();
            t.push(rgb565_from_f64([l, 0.9 * l, 0.7 * l]));
        }
    }
    t
}

fn ref_texture(texels: &[u16], size: u32) -> RefTexture {
    RefTexture {
        width: size,
        height: size,
        texels: texels.to_vec(),
        border: 0,
    }
}

fn to_rgb565(t: &[u16]) -> Vec<Rgb565> {
    t.iter().map(|&c| raw(c)).collect()
}

/// I16F16 bits of `x` (rounded).
fn fx_bits(x: f64) -> i32 {
    (x * 65536.0).round() as i32
}

/// The wall: a quad with its left edge at `w = 1` and its right edge at `w = 4`,
/// counter-clockwise in NDC, as two triangles. The base texture repeats 4 x 2 times across
/// it, the light map spans `-0.1..1.1` on both axes (so clamp-to-edge shows at the rim), and
/// `k` falls from 1.0 (near) to 0.55 (far).
fn wall() -> [[Vertex<VARYINGS>; 3]; 2] {
    // (x_ndc, y_ndc, w, u0, v0, u1, v1, k)
    let corner = |xn: f64, yn: f64, w: f64, u0: f64, v0: f64, u1: f64, v1: f64, k: f64| {
        let z = 0.5 * w - 0.3;
        Vertex::new(
            [xn * w, yn * w, z, w].map(Fx::from_num),
            [
                fx_bits(u0),
                fx_bits(v0),
                fx_bits(u1),
                fx_bits(v1),
                (k * f64::from(256 << 16)).round() as i32,
            ],
        )
    };
    let a = corner(-0.9, 0.8, 1.0, 0.0, 0.0, -0.1, -0.1, 1.0);
    let b = corner(-0.9, -0.8, 1.0, 0.0, 2.0, -0.1, 1.1, 1.0);
    let c = corner(0.9, -0.2, 4.0, 4.0, 2.0, 1.1, 1.1, 0.55);
    let d = corner(0.9, 0.2, 4.0, 4.0, 0.0, 1.1, -0.1, 0.55);
    [[a, b, c], [a, c, d]]
}

// ---------------------------------------------------------------------------------------
// The f64 reference.
// ---------------------------------------------------------------------------------------

/// The reference image: RGB565 per pixel and coverage (no clipping needed: the wall lies
/// inside the view volume; its two triangles do not overlap, so no depth test either).
fn reference(
    tris: &[[Vertex<VARYINGS>; 3]],
    base: &RefTexture,
    light: &RefTexture,
) -> (Vec<u16>, Vec<bool>) {
    let n = (W * H) as usize;
    let (mut rgb, mut cov) = (vec![0u16; n], vec![false; n]);
    for tri in tris {
        let win = tri.map(|v| {
            let rv = RefVertex {
                clip: v.position.map(|c| c.to_num::<f64>()),
                uv: [0.0; 2],
                color: [0.0; 3],
            };
            to_window(&rv, W, H).expect("w > 0")
        });
        let vary = tri.map(|v| {
            let [u0, v0, u1, v1, k] = v.varyings.map(f64::from);
            [
                u0 / 65536.0,
                v0 / 65536.0,
                u1 / 65536.0,
                v1 / 65536.0,
                k / f64::from(1 << 24),
            ]
        });
        rasterize(&win, W, H, |x, y, l| {
            // Hyperbolic interpolation: weights λi / wi, normalised.
            let q = [0, 1, 2].map(|i| l[i] * win[i].inv_w);
            let qs = q[0] + q[1] + q[2];
            let a: [f64; VARYINGS] =
                core::array::from_fn(|j| (0..3).map(|i| q[i] * vary[i][j]).sum::<f64>() / qs);
            let [u0, v0, u1, v1, k] = a;
            let b = sample(
                base,
                [u0, v0],
                RefFilter::Bilinear,
                RefWrap::Repeat,
                RefWrap::Repeat,
            );
            let [lr, lg, lb] = sample(
                light,
                [u1, v1],
                RefFilter::Bilinear,
                RefWrap::ClampToEdge,
                RefWrap::ClampToEdge,
            );
            let lum = (77.0 * lr + 150.0 * lg + 29.0 * lb) / 256.0;
            let m = lum * k.clamp(0.0, 1.0);
            let i = (y * W + x) as usize;
            rgb[i] = rgb565_from_f64(b.map(|c| c * m));
            cov[i] = true;
        });
    }
    (rgb, cov)
}

// ---------------------------------------------------------------------------------------
// Drawing with fixel and measuring.
// ---------------------------------------------------------------------------------------

/// Draws `tris` with the light-mapped shader under projection `P` into a cleared 160 x 120
/// frame with depth; returns the pixels (raw RGB565), the coverage (depth written) and the
/// count `clip_triangles` reported.
fn draw_fixel<P: ProjectionStage>(
    tris: &[[Vertex<VARYINGS>; 3]],
    base: &[Rgb565],
    light: &[Rgb565],
) -> (Vec<u16>, Vec<bool>, u32) {
    let base = MipTexture::single(Texture::new(base, 32, 32).unwrap());
    let light = MipTexture::single(Texture::new(light, 16, 16).unwrap());
    let shader = LightMapped {
        base: TexBinding::new(&base, Bilinear, Repeat, Repeat, Lod::default()).unwrap(),
        light: TexBinding::new(&light, Bilinear, ClampToEdge, ClampToEdge, Lod::default()).unwrap(),
    };
    let vp = Viewport::new(0, 0, W, H).unwrap();
    let draw = ShadedDraw::<_, P, DepthLess>::new(shader, vp, Cull::Back).unwrap();
    let n = (W * H) as usize;
    let (mut color, mut depth) = (vec![Rgb565::default(); n], vec![0u16; n]);
    let mut frame = Frame::new(&mut color, W, H)
        .unwrap()
        .with_depth(&mut depth)
        .unwrap();
    frame.clear(Rgb565::default());
    let written = draw.clip_triangles(tris, &mut frame).unwrap();
    let px = frame.pixels().iter().map(|&c| bits(c)).collect();
    let cov = frame
        .depth()
        .unwrap()
        .iter()
        .map(|&d| d != DEPTH_CLEAR)
        .collect();
    (px, cov, written)
}

/// Pixels covered by exactly one side, and how many of them are *not* on the reference's
/// edge (a pixel is on the edge when one of its 4-neighbours differs in reference coverage,
/// or it is at the frame border).
fn coverage_diff(cov: &[bool], rcov: &[bool]) -> (usize, usize) {
    let (w, h) = (W as usize, H as usize);
    let at = |x: usize, y: usize| rcov[y * w + x];
    let (mut diff, mut interior) = (0, 0);
    for y in 0..h {
        for x in 0..w {
            let i = y * w + x;
            if cov[i] == rcov[i] {
                continue;
            }
            diff += 1;
            let edge = x == 0
                || y == 0
                || x + 1 == w
                || y + 1 == h
                || [(x - 1, y), (x + 1, y), (x, y - 1), (x, y + 1)]
                    .iter()
                    .any(|&(a, b)| at(a, b) != rcov[i]);
            if !edge {
                interior += 1;
            }
        }
    }
    (diff, interior)
}

struct Measured {
    report: Report,
    written: u32,
    /// Pixels covered by exactly one of fixel and the reference.
    cov_diff: usize,
}

fn measure<P: ProjectionStage>(name: &str) -> Measured {
    let (bt, lt) = (base_texels(), light_texels());
    let tris = wall();
    let (px, cov, written) = draw_fixel::<P>(&tris, &to_rgb565(&bt), &to_rgb565(&lt));
    let (rpx, rcov) = reference(&tris, &ref_texture(&bt, 32), &ref_texture(&lt, 16));
    let report = compare_rgb565(&px, &cov, &rpx, &rcov);
    let (cov_diff, cov_interior) = coverage_diff(&cov, &rcov);
    println!(
        "user_shader {name}: written={written} coverage-diff={cov_diff} \
         (off-edge {cov_interior}) | {report}"
    );
    Measured {
        report,
        written,
        cov_diff,
    }
}

// Budgets, measured on this wall (160 x 120, 8640 covered pixels), errors in RGB565 LSBs
// against the f64 reference rounded to RGB565 (host_tests::metrics::compare_rgb565):
//
// | projection | coverage diff | max | mean | > 1 LSB | > 2 LSB | budget |
// |---|---|---|---|---|---|---|
// | Exact | 0 | 1 | 0.1008 | 0 % | 0 % | identical, max 2, mean 0.12, > 1 LSB <= 0.1 % |
// | Subdivided N=2 | 0 | 1 | 0.1012 | 0 % | 0 % | ladder: max 2, > 1 LSB <= 0.1 % |
// | Subdivided N=4 | 0 | 2 | 0.1100 | 0.01 % | 0 % | ladder |
// | Subdivided N=8 (marker `Subdivided`) | 0 | 5 | 0.1621 | 1.78 % | 0.49 % | identical, max 6, mean 0.18, > 1 LSB <= 2 %, > 2 LSB <= 0.6 % |
// | Subdivided N=16 | 0 | 17 | 0.408 | 10.2 % | 5.79 % | ladder |
// | Subdivided N=32 | 0 | 31 | 1.21 | 31.2 % | 22.7 % | ladder |
// | Affine | 0 | 37 | 5.22 | 93.6 % | 86.5 % | must be far outside the exact budget |
//
// Exact's error is the two RGB565 roundings of the bilinear samples (base and light map)
// plus the final rounding of the integer colour formula: at most 1 LSB. The mean budget is
// what catches a wrong luminance formula (weights 85/150/21 instead of 77/150/29 give
// max 1 but mean 0.13); a transposed light-map pair gives max 21, an ignored `k` max 9.
// The subdivided error is the affine approximation between exact samples: its worst
// pixels (5, 4, 4 LSB at x = 128, 142, 109 near row 58; spans run x = 8..=151) lie in the
// far, minified half of the wall (w 2.5 to 4, up to 3 texels per pixel), where a small texel
// coordinate error moves a sample across a checker edge; none is at a span end.

/// Exact (per-pixel perspective-correct) projection: see the budget table above.
#[test]
fn light_mapped_exact_matches_f64_reference() {
    let m = measure::<Exact>("exact");
    let r = &m.report;
    assert!(r.both_covered > 8000, "the wall covers too little: {r}");
    assert_eq!(m.written as usize, r.both_covered + r.only_candidate);
    assert_eq!(m.cov_diff, 0, "coverage differs from the reference: {r}");
    assert!(r.max <= 2, "max error over budget: {r}");
    assert!(r.mean <= 0.12, "mean error over budget: {r}");
    assert!(r.share_over_1 <= 0.001, "too many pixels over 1 LSB: {r}");
}

/// Subdivided projection (the `Subdivided` marker: N = 8, exact every 8 pixels, affine
/// between): see the budget table above.
#[test]
fn light_mapped_subdivided_within_budget() {
    let m = measure::<Subdivided>("subdivided");
    let r = &m.report;
    assert!(r.both_covered > 8000, "the wall covers too little: {r}");
    assert_eq!(m.written as usize, r.both_covered + r.only_candidate);
    assert_eq!(m.cov_diff, 0, "coverage differs from the reference: {r}");
    assert!(r.max <= 6, "max error over budget: {r}");
    assert!(r.mean <= 0.18, "mean error over budget: {r}");
    assert!(r.share_over_1 <= 0.02, "too many pixels over 1 LSB: {r}");
    assert!(r.share_over_2 <= 0.006, "too many pixels over 2 LSB: {r}");
}

/// The subdivided error is the affine error between exact samples: it grows with the
/// subdivision length (N = 2, 4, 8, 16, 32), N = 2 is as good as exact, and coverage never
/// depends on the projection.
#[test]
fn light_mapped_subdivision_ladder() {
    let m = [
        measure::<SubdividedBy<1>>("subdivided N=2"),
        measure::<SubdividedBy<2>>("subdivided N=4"),
        measure::<SubdividedBy<3>>("subdivided N=8"),
        measure::<SubdividedBy<4>>("subdivided N=16"),
        measure::<SubdividedBy<5>>("subdivided N=32"),
    ];
    for w in m.windows(2) {
        let (a, b) = (&w[0].report, &w[1].report);
        assert!(
            a.mean < b.mean,
            "mean error not growing with N: {a} then {b}"
        );
        assert!(a.share_over_1 <= b.share_over_1, "{a} then {b}");
    }
    assert!(m.iter().all(|x| x.cov_diff == 0));
    let n2 = &m[0].report;
    assert!(n2.max <= 2 && n2.share_over_1 <= 0.001, "N=2: {n2}");
}

/// Sanity check of the reference and of the budget's power: the affine projection on this
/// strongly perspective wall must be far off.
#[test]
fn affine_is_caught_by_the_reference() {
    let m = measure::<Affine>("affine (expected bad)");
    assert!(
        m.report.max > 20 && m.report.share_over_1 > 0.5,
        "{}",
        m.report
    );
}

// ---------------------------------------------------------------------------------------
// Robustness: extreme input never panics and never writes outside the buffers.
// ---------------------------------------------------------------------------------------

fn any_bits() -> impl Strategy<Value = i32> {
    prop_oneof![
        4 => any::<i32>(),
        2 => -(1i32 << 18)..(1 << 18),
        1 => prop::sample::select(vec![
            0, 1, -1, 65535, 65536, -65536, i32::MAX, i32::MIN, 1 << 30, -(1 << 30),
        ]),
    ]
}

/// A vertex anywhere in the I16F16 range, texture coordinates anywhere in `i32` and `k`
/// within ±2^30 (the shader's contract: every varying difference must fit `i32`).
fn wild_vertex() -> impl Strategy<Value = Vertex<VARYINGS>> {
    (
        [any_bits(), any_bits(), any_bits(), any_bits()],
        [any_bits(), any_bits(), any_bits(), any_bits()],
        -(1i32 << 30)..(1 << 30),
    )
        .prop_map(|(p, t, k)| Vertex::new(p.map(Fx::from_bits), [t[0], t[1], t[2], t[3], k]))
}

/// Draws with `P` into a guarded 48 x 40 target and checks the guard.
fn draw_guarded<P: ProjectionStage>(tris: &[[Vertex<VARYINGS>; 3]], cull: Cull) {
    let (bt, lt) = (to_rgb565(&base_texels()), to_rgb565(&light_texels()));
    let base = MipTexture::single(Texture::new(&bt, 32, 32).unwrap());
    let light = MipTexture::single(Texture::new(&lt, 16, 16).unwrap());
    let shader = LightMapped {
        base: TexBinding::new(&base, Bilinear, Repeat, Repeat, Lod::default()).unwrap(),
        light: TexBinding::new(&light, Bilinear, ClampToEdge, ClampToEdge, Lod::default()).unwrap(),
    };
    let vp = Viewport::new(0, 0, 48, 40).unwrap();
    let draw = ShadedDraw::<_, P, DepthLess>::new(shader, vp, cull).unwrap();
    let mut g = Guarded::new(48, 40, true);
    let n = draw.clip_triangles(tris, &mut g).unwrap();
    assert!(n <= 48 * 40 * tris.len() as u32 * 8);
    g.check("user shader");
}

/// Hand-picked extremes: thousands of repeats with coordinates near `i32::MAX`, light-map
/// coordinates that saturate the clamp axes, vertices behind the camera and far outside.
#[test]
fn extreme_hand_picked_never_panic() {
    let p = |x: f64, y: f64, z: f64, w: f64| [x, y, z, w].map(Fx::from_num);
    let big = [
        i32::MAX,
        i32::MIN,
        i32::MAX - 1,
        i32::MIN + 1,
        1 << 30,
        -(1 << 30),
    ];
    let mut tris = Vec::new();
    for &a in &big {
        for &b in &big {
            let vary = |s: i32| [a, b.wrapping_mul(s), b, a.wrapping_mul(s), 1 << 24];
            tris.push([
                Vertex::new(p(-0.9, -0.9, 0.0, 1.0), vary(1)),
                Vertex::new(p(0.9, -0.9, 0.0, 1.0), vary(-1)),
                Vertex::new(p(0.0, 0.9, 0.0, 1.0), [0, 0, 0, 0, 0]),
            ]);
            tris.push([
                Vertex::new(p(-30000.0, -30000.0, 0.0, 0.004), vary(1)),
                Vertex::new(p(30000.0, -1.0, -5.0, -3.0), vary(-1)),
                Vertex::new(p(0.0, 32767.0, 32767.0, 32767.0), [a, a, b, b, -(1 << 30)]),
            ]);
        }
    }
    draw_guarded::<Exact>(&tris, Cull::None);
    draw_guarded::<Subdivided>(&tris, Cull::None);
    draw_guarded::<Affine>(&tris, Cull::None);
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 256, ..ProptestConfig::default() })]

    #[test]
    fn wild_triangles_never_panic(
        tris in prop::collection::vec([wild_vertex(), wild_vertex(), wild_vertex()], 1..4),
    ) {
        draw_guarded::<Exact>(&tris, Cull::None);
        draw_guarded::<Subdivided>(&tris, Cull::None);
    }
}
