//! Mipmapping: fixel's chains, level of detail and the four GL mipmapped
//! minification filters against the independent f64 reference, goldens of the floor with
//! every filter and LOD granularity, wrap modes at every level, LOD bias and clamps.
//!
//! # Error budgets (measured on the floor scene, 320 x 240, see `floor_each_filter`)
//!
//! Errors are in RGB565 LSBs against the reference quantised to RGB565, over pixels both
//! cover. fixel differs from the reference for three reasons, each bounded by measurement:
//! * texel coordinates are I16F16 after a perspective reciprocal: a nearest fetch flips to
//!   the neighbouring texel where the exact `u` lies within ~1e-4 texel of a texel edge
//!   (a whole texel-to-texel difference, any size, on a few pixels);
//! * `lambda` is Q8.8 from a 64-entry log2 table (within 1/64 of a level) and from
//!   fixed-point derivatives: `*_MIPMAP_NEAREST` switches level a little early or late
//!   near the `n + 1/2` boundaries (a level-to-level difference on the pixels there), and
//!   `*_MIPMAP_LINEAR`'s blend weight moves by up to ~1/64;
//! * the between-level blend weight is 8 bits and rounded per channel; bilinear weights are
//!   Q8 (at most 1 LSB, see `texture::sample`).
//!
//! The budgets are [`Budget`] per filter (largest error, mean, share of pixels more than
//! 1 LSB off, PSNR floor), set a little beyond the measured values quoted there.

use fixel::geometry::ClipVertex;
use fixel::texture::{Filter, Lod, LodGranularity, MipFilter, MipTexture};
use host_tests::adapter::{self, FixelImage};
use host_tests::golden::assert_golden;
use host_tests::metrics::{self, Report};
use host_tests::reference::mip::{self as refmip, RefMipChain};
use host_tests::reference::{
    self, RefCull, RefFilter, RefLod, RefMip, RefMode, RefProjection, RefShading, RefTexture,
    RefTriangle, RefVertex, RefWrap,
};
use host_tests::scenes;

use embedded_graphics_core::pixelcolor::raw::{RawData, RawU16};
use embedded_graphics_core::pixelcolor::Rgb565;

struct Rng(u32);
impl Rng {
    fn next(&mut self) -> u32 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 17;
        self.0 ^= self.0 << 5;
        self.0
    }
}

fn random_texture(w: u32, h: u32, seed: u32) -> RefTexture {
    let mut rng = Rng(seed);
    RefTexture {
        width: w,
        height: h,
        texels: (0..w * h).map(|_| rng.next() as u16).collect(),
        border: 0,
    }
}

#[test]
fn reference_chain_equals_generate_mips() {
    let cases = [
        scenes::procedural_texture(64, 64),
        random_texture(64, 64, 1),
        scenes::procedural_texture(256, 128),
        random_texture(256, 128, 2),
        random_texture(1, 8, 3),
        random_texture(8, 1, 4),
        random_texture(2, 16, 5),
    ];
    for t in &cases {
        for levels in [None, Some(2)] {
            let want = RefMipChain::build(t, levels).flatten();
            let got: Vec<u16> = adapter::mip_chain(t, levels)
                .iter()
                .map(|&c| RawU16::from(c).into_inner())
                .collect();
            assert_eq!(got, want, "{}x{} {levels:?}", t.width, t.height);
        }
    }
    // Sizes: 64x64 has 7 levels, 4/3 of the base minus 1/3 texel.
    let c = RefMipChain::build(&cases[0], None);
    assert_eq!(c.levels.len(), 7);
    assert_eq!(c.flatten().len(), 4096 + 1024 + 256 + 64 + 16 + 4 + 1);
    let c = RefMipChain::build(&cases[2], None);
    let sides: Vec<(u32, u32)> = c.levels.iter().map(|l| (l.width, l.height)).collect();
    assert_eq!(
        sides,
        [
            (256, 128),
            (128, 64),
            (64, 32),
            (32, 16),
            (16, 8),
            (8, 4),
            (4, 2),
            (2, 1),
            (1, 1)
        ]
    );
}

/// Every level of `generate_mips` is within half an LSB of the exact mean of the level-0
/// texels it covers (the floor's texture, the sky faces, random texels); box-filtering the
/// rounded level above, the rule before, compounds roundings (always up at ties). Measured
/// (mean / max |level - exact mean| per channel, LSB, levels 2 and deeper):
///
/// | texture | box of rounded levels | from level 0, rounded once |
/// |---|---|---|
/// | floor 64 x 64 | 0.415 / 1.16 | 0.259 / 0.50 |
/// | random 256 x 128 | 0.350 / 1.36 | 0.251 / 0.50 |
#[test]
fn levels_round_once_from_level_zero() {
    let chans = |t: u16| [t >> 11, (t >> 5) & 63, t & 31].map(f64::from);
    // The rule before: each level a 2 x 2 box of the rounded level above.
    let boxed = |base: &RefTexture, levels: u32| -> Vec<RefTexture> {
        let mut out = vec![base.clone()];
        for _ in 1..levels {
            let src = out.last().unwrap();
            let (w, h) = ((src.width / 2).max(1), (src.height / 2).max(1));
            let mut texels = Vec::new();
            for j in 0..h {
                for i in 0..w {
                    let xs = if src.width > 1 {
                        vec![2 * i, 2 * i + 1]
                    } else {
                        vec![0]
                    };
                    let ys = if src.height > 1 {
                        vec![2 * j, 2 * j + 1]
                    } else {
                        vec![0]
                    };
                    let mut sum = [0u32; 3];
                    for &y in &ys {
                        for &x in &xs {
                            let c = chans(src.texel(x, y));
                            (0..3).for_each(|k| sum[k] += c[k] as u32);
                        }
                    }
                    let n = (xs.len() * ys.len()) as u32;
                    let a = sum.map(|v| (v + n / 2) / n);
                    texels.push(((a[0] << 11) | (a[1] << 5) | a[2]) as u16);
                }
            }
            out.push(RefTexture {
                width: w,
                height: h,
                texels,
                border: 0,
            });
        }
        out
    };
    for (name, t) in [
        ("floor 64x64", scenes::procedural_texture(64, 64)),
        ("random 256x128", random_texture(256, 128, 7)),
    ] {
        let levels = refmip::full_levels(t.width, t.height);
        let new = RefMipChain::build(&t, None).levels;
        let old = boxed(&t, levels);
        let got: Vec<u16> = adapter::mip_chain(&t, None)
            .iter()
            .map(|&c| RawU16::from(c).into_inner())
            .collect();
        assert_eq!(got, RefMipChain::build(&t, None).flatten(), "{name}");
        let mut stats = [(0.0f64, 0.0f64, 0usize); 2];
        for k in 2..levels {
            let (w, h) = (new[k as usize].width, new[k as usize].height);
            let (bw, bh) = (t.width / w, t.height / h);
            for j in 0..h {
                for i in 0..w {
                    let mut mean = [0.0; 3];
                    for y in j * bh..(j + 1) * bh {
                        for x in i * bw..(i + 1) * bw {
                            let c = chans(t.texel(x, y));
                            (0..3).for_each(|q| mean[q] += c[q] / f64::from(bw * bh));
                        }
                    }
                    for (s, chain) in stats.iter_mut().zip([&old, &new]) {
                        let c = chans(chain[k as usize].texel(i, j));
                        for q in 0..3 {
                            let e = (c[q] - mean[q]).abs();
                            s.0 += e;
                            s.1 = s.1.max(e);
                            s.2 += 1;
                        }
                    }
                }
            }
        }
        let [o, n] = stats.map(|(sum, max, k)| (sum / k as f64, max));
        println!(
            "{name}: |level - exact mean|, levels 2+: box of rounded levels mean {:.3} max {:.2}; from level 0 mean {:.3} max {:.2} LSB",
            o.0, o.1, n.0, n.1
        );
        assert!(n.1 <= 0.5 && n.0 < o.0, "{name}");
    }
}

/// The GL level selection of the reference, on hand-computed values.
#[test]
fn reference_level_selection() {
    use refmip::select;
    let s = |l: f64, m: RefMip| {
        let s = select(l, m, 7);
        (s.magnify, s.a, s.b, (s.frac * 1000.0).round() / 1000.0)
    };
    assert_eq!(s(0.0, RefMip::Nearest), (true, 0, 0, 0.0));
    assert_eq!(s(0.5, RefMip::Nearest), (false, 0, 0, 0.0));
    assert_eq!(s(0.51, RefMip::Nearest), (false, 1, 1, 0.0));
    assert_eq!(s(1.5, RefMip::Nearest), (false, 1, 1, 0.0));
    assert_eq!(s(1.501, RefMip::Nearest), (false, 2, 2, 0.0));
    assert_eq!(s(20.0, RefMip::Nearest), (false, 6, 6, 0.0));
    assert_eq!(s(0.25, RefMip::Linear), (false, 0, 1, 0.25));
    assert_eq!(s(2.75, RefMip::Linear), (false, 2, 3, 0.75));
    assert_eq!(s(5.9, RefMip::Linear), (false, 5, 6, 0.9));
    assert_eq!(s(6.2, RefMip::Linear), (false, 6, 6, 0.0));
    assert_eq!(s(3.0, RefMip::None), (false, 0, 0, 0.0));
    // rho of a pure scale and of a rotation + anisotropy.
    assert!((refmip::rho([[4.0, 0.0], [0.0, 4.0]]) - 4.0).abs() < 1e-12);
    assert!((refmip::rho([[3.0, 4.0], [0.0, 1.0]]) - 5.0).abs() < 1e-12);
}

/// The reference's analytic derivatives against central differences of its own
/// interpolation on the floor.
#[test]
fn reference_derivatives_match_finite_differences() {
    let s = scenes::floor();
    let tris = scenes::to_ref_triangles(&s);
    let clipped = reference::clip::fan(&reference::clip::clip_triangle(&tris[0]));
    let sub = clipped[0];
    let v = sub
        .0
        .map(|v| reference::raster::to_window(&v, 320, 240).unwrap());
    // Attributes use the exact (unsnapped) positions.
    let bary = |x: f64, y: f64| -> [f64; 3] { reference::raster::barycentrics(&v, x, y) };
    let uv = |x: f64, y: f64| -> [f64; 2] {
        let l = bary(x, y);
        let q: f64 = (0..3).map(|i| l[i] * v[i].inv_w).sum();
        core::array::from_fn(|c| (0..3).map(|i| l[i] * v[i].inv_w * v[i].uv[c]).sum::<f64>() / q)
    };
    for (x, y) in [
        (160.5, 130.5),
        (40.5, 200.5),
        (300.5, 235.5),
        (100.5, 124.5),
    ] {
        let d = reference::uv_derivatives(&v, bary(x, y), RefProjection::Perspective);
        let h = 1e-4;
        let (px, mx, py, my) = (uv(x + h, y), uv(x - h, y), uv(x, y + h), uv(x, y - h));
        for c in 0..2 {
            let fx = (px[c] - mx[c]) / (2.0 * h);
            let fy = (py[c] - my[c]) / (2.0 * h);
            assert!((d[0][c] - fx).abs() <= 1e-6 * (1.0 + fx.abs()), "{x},{y}");
            assert!((d[1][c] - fy).abs() <= 1e-6 * (1.0 + fy.abs()), "{x},{y}");
        }
    }
}

/// The six filter combinations (GL names) of the floor comparisons.
const FILTERS: [(&str, RefFilter, RefMip); 6] = [
    ("nearest", RefFilter::Nearest, RefMip::None),
    ("bilinear", RefFilter::Bilinear, RefMip::None),
    (
        "nearest-mipmap-nearest",
        RefFilter::Nearest,
        RefMip::Nearest,
    ),
    (
        "linear-mipmap-nearest",
        RefFilter::Bilinear,
        RefMip::Nearest,
    ),
    ("nearest-mipmap-linear", RefFilter::Nearest, RefMip::Linear),
    ("trilinear", RefFilter::Bilinear, RefMip::Linear),
];

fn floor_mode(filter: RefFilter, mip: RefMip) -> RefMode {
    RefMode {
        filter,
        mip,
        ..scenes::floor().mode
    }
}

fn render_floor(mode: &RefMode, g: LodGranularity) -> FixelImage {
    let s = scenes::floor();
    let tris = adapter::clip_triangles(&scenes::to_ref_triangles(&s));
    let mut dm = adapter::draw_mode(mode, None, false);
    dm.lod.granularity = g;
    adapter::render_mip(&tris, Some(&s.texture), None, dm, s.width, s.height)
}

/// Budget of one filter on the floor: largest error, mean error, share of pixels more than
/// 1 LSB off, PSNR floor. Measured (debug and release agree: all integer on fixel's side):
///
/// | filter                 | max | mean   | >1 LSB | PSNR     |
/// |------------------------|-----|--------|--------|----------|
/// | nearest                | 31  | 0.0182 | 0.123% | 33.76 dB |
/// | bilinear               | 6   | 0.0190 | 0.120% | 47.21 dB |
/// | nearest-mipmap-nearest | 31  | 0.0103 | 0.093% | 36.23 dB |
/// | linear-mipmap-nearest  | 8   | 0.0181 | 0.005% | 49.07 dB |
/// | nearest-mipmap-linear  | 31  | 0.0130 | 0.099% | 36.24 dB |
/// | trilinear              | 1   | 0.0609 | 0      | 43.38 dB |
///
/// The nearest-filtered modes' 31-LSB outliers are texel flips (blue squares are 0 or 31)
/// where the I16F16 `u` of a distant pixel lands on the other side of a texel edge; bilinear
/// and linear-mipmap-nearest have the same coordinate error times a steep gradient (up to
/// 6-8 LSB on a few dozen pixels near the horizon). Trilinear's extra mean error (~1 pixel
/// in 16 off by 1 LSB) is the 1/64-level lambda and the 8-bit blend weight; it never
/// exceeds 1 LSB.
struct Budget {
    max: u32,
    mean: f64,
    over1: f64,
    psnr: f64,
}

fn budget(name: &str) -> Budget {
    let b = |max, mean, over1, psnr| Budget {
        max,
        mean,
        over1,
        psnr,
    };
    match name {
        // Against the exact (unsnapped) reference: texel flips within 1/64 texel of an edge
        // near the horizon (see subpixel.rs), 0.545% / 0.262% / 0.286% measured.
        "nearest" => b(31, 0.07, 0.006, 27.0),
        "bilinear" => b(10, 0.03, 0.0025, 44.0),
        "nearest-mipmap-nearest" => b(31, 0.035, 0.003, 30.0),
        "linear-mipmap-nearest" => b(12, 0.03, 0.0005, 46.0),
        "nearest-mipmap-linear" => b(31, 0.035, 0.003, 30.0),
        "trilinear" => b(1, 0.09, 0.0, 41.0),
        _ => unreachable!("{name}"),
    }
}

/// Checks a report against its budget (`MEASURE=1` prints instead of asserting).
fn check(name: &str, r: &Report) {
    let b = budget(name);
    println!("{name:24} {r}");
    if std::env::var_os("MEASURE").is_some() {
        return;
    }
    assert!(
        r.only_candidate + r.only_reference == 0,
        "{name}: coverage {r}"
    );
    assert!(r.max <= b.max, "{name}: max {r}");
    assert!(r.mean <= b.mean, "{name}: mean {r}");
    assert!(r.share_over_1 <= b.over1, "{name}: >1 LSB {r}");
    assert!(r.psnr_db >= b.psnr, "{name}: psnr {r}");
}

#[test]
fn floor_each_filter_against_reference() {
    let s = scenes::floor();
    let tris = scenes::to_ref_triangles(&s);
    for (name, filter, mip) in FILTERS {
        let mode = floor_mode(filter, mip);
        let r = reference::render(&tris, Some(&s.texture), &mode, s.width, s.height);
        let f = render_floor(&mode, LodGranularity::Pixel);
        check(name, &metrics::compare(&f.pixels, &f.covered, &r));
    }
}

#[test]
fn floor_goldens() {
    for (name, filter, mip) in FILTERS {
        let f = render_floor(&floor_mode(filter, mip), LodGranularity::Pixel);
        assert_golden(&format!("mip/floor-{name}"), 320, 240, &f.pixels);
    }
    let tri = floor_mode(RefFilter::Bilinear, RefMip::Linear);
    for (g, name) in [
        (LodGranularity::Span, "span"),
        (LodGranularity::Triangle, "triangle"),
    ] {
        let f = render_floor(&tri, g);
        assert_golden(
            &format!("mip/floor-trilinear-lod-{name}"),
            320,
            240,
            &f.pixels,
        );
    }
}

// ---------------------------------------------------------------------------------------
// Screen-aligned quads
// ---------------------------------------------------------------------------------------

/// A vertex at window position `(x, y)` of a `w x h` viewport (w_clip = 1).
fn win(x: f64, y: f64, w: u32, h: u32, uv: [f64; 2]) -> RefVertex {
    RefVertex {
        clip: [
            2.0 * x / f64::from(w) - 1.0,
            1.0 - 2.0 * y / f64::from(h),
            0.0,
            1.0,
        ],
        uv,
        color: [1.0; 3],
    }
}

/// The window rectangle `[x0, x1] x [y0, y1]` with texture coordinates `uv0` at the top
/// left and `uv1` at the bottom right; two triangles, counter-clockwise in NDC.
fn quad(r: [f64; 4], uv0: [f64; 2], uv1: [f64; 2], w: u32, h: u32) -> Vec<RefTriangle> {
    let [x0, y0, x1, y1] = r;
    let a = win(x0, y0, w, h, uv0);
    let b = win(x0, y1, w, h, [uv0[0], uv1[1]]);
    let c = win(x1, y1, w, h, uv1);
    let d = win(x1, y0, w, h, [uv1[0], uv0[1]]);
    vec![RefTriangle([a, b, c]), RefTriangle([a, c, d])]
}

fn quad_mode(filter: RefFilter, mip: RefMip, wrap: RefWrap, lod: RefLod) -> RefMode {
    RefMode {
        projection: RefProjection::Affine,
        filter,
        mip,
        lod,
        wrap_u: wrap,
        wrap_v: wrap,
        depth_test: false,
        shading: RefShading::Replace,
        cull: RefCull::None,
        ..RefMode::default()
    }
}

/// Non-square chain (256 x 128, 9 levels) on a minified, perspective quad: trilinear
/// against the reference.
#[test]
fn non_square_chain_trilinear() {
    let t = scenes::procedural_texture(256, 128);
    // A receding quad: the top edge far (w = 4), the bottom near (w = 1).
    let v = |x: f64, y: f64, w: f64, uv: [f64; 2]| RefVertex {
        clip: [x * w, y * w, 0.0, w],
        uv,
        color: [1.0; 3],
    };
    let a = v(-0.9, 0.9, 4.0, [0.0, 0.0]);
    let b = v(-0.9, -0.9, 1.0, [0.0, 3.0]);
    let c = v(0.9, -0.9, 1.0, [3.0, 3.0]);
    let d = v(0.9, 0.9, 4.0, [3.0, 0.0]);
    let tris = vec![RefTriangle([a, b, c]), RefTriangle([a, c, d])];
    for (name, filter, mip) in FILTERS {
        let mode = RefMode {
            filter,
            mip,
            shading: RefShading::Replace,
            cull: RefCull::None,
            ..RefMode::default()
        };
        let r = reference::render(&tris, Some(&t), &mode, 128, 96);
        let dm = adapter::draw_mode(&mode, None, false);
        let f = adapter::render_mip(&adapter::clip_triangles(&tris), Some(&t), None, dm, 128, 96);
        let rep = metrics::compare(&f.pixels, &f.covered, &r);
        println!("256x128 {name:24} {rep}");
        assert_eq!(rep.only_candidate + rep.only_reference, 0);
        assert!(
            rep.mean <= 0.25 && rep.share_over_1 <= 0.03,
            "{name}: {rep}"
        );
    }
}

/// Every wrap mode at every level of a 32 x 32 chain: the level is forced with
/// `min = max = k` and the quad shows the texture 4 times around (uv from -1.5 to 2.5).
#[test]
fn wrap_modes_at_every_level() {
    let mut t = scenes::procedural_texture(32, 32);
    t.border = 0xF81F; // magenta
    let tris = quad([0.0, 0.0, 64.0, 64.0], [-1.5, -1.5], [2.5, 2.5], 64, 64);
    let ftris = adapter::clip_triangles(&tris);
    for wrap in [
        RefWrap::Repeat,
        RefWrap::MirroredRepeat,
        RefWrap::ClampToEdge,
        RefWrap::ClampToBorder,
    ] {
        for k in 0..=5 {
            for (filter, mip) in [
                (RefFilter::Nearest, RefMip::Nearest),
                (RefFilter::Bilinear, RefMip::Linear),
            ] {
                let lod = RefLod {
                    bias: 0.0,
                    min: f64::from(k),
                    max: f64::from(k),
                };
                let mode = quad_mode(filter, mip, wrap, lod);
                let r = reference::render(&tris, Some(&t), &mode, 64, 64);
                let dm = adapter::draw_mode(&mode, None, false);
                let f = adapter::render_mip(&ftris, Some(&t), None, dm, 64, 64);
                let rep = metrics::compare(&f.pixels, &f.covered, &r);
                let what = format!("{wrap:?} level {k} {filter:?}");
                assert_eq!(rep.both_covered, 64 * 64, "{what}");
                // Exact texel positions (uv steps of 1/16 texel): nearest is exact, bilinear
                // within its 1 LSB.
                let max = if filter == RefFilter::Nearest { 0 } else { 1 };
                assert!(rep.max <= max, "{what}: {rep}");
                if wrap == RefWrap::ClampToBorder {
                    let border = f.pixels.iter().filter(|&&p| p == 0xF81F).count();
                    assert!(border > 64 * 64 / 2, "{what}: {border} border pixels");
                }
            }
        }
    }
}

/// A 64 x 64 chain whose levels are distinct solid colours, so the level sampled can be
/// read off the picture.
fn coloured_chain() -> (Vec<Rgb565>, RefMipChain) {
    let colours: [u16; 7] = [0xF800, 0x07E0, 0x001F, 0xFFE0, 0x07FF, 0xF81F, 0xFFFF];
    let mut levels = vec![];
    let mut chain = vec![];
    for (k, &c) in colours.iter().enumerate() {
        let s = 64 >> k;
        levels.push(RefTexture {
            width: s,
            height: s,
            texels: vec![c; (s * s) as usize],
            border: 0,
        });
        chain.extend(std::iter::repeat_n(
            Rgb565::from(RawU16::new(c)),
            (s * s) as usize,
        ));
    }
    (chain, RefMipChain { levels })
}

/// LOD bias and min/max clamps move the level as GL says: the whole 64-texel texture on a
/// 16 x 16 pixel quad has `rho = 4`, `lambda = 2`.
#[test]
fn lod_bias_and_clamps_select_levels() {
    let (chain, rchain) = coloured_chain();
    let mips = MipTexture::new(&chain, 64, 64, 7).unwrap();
    let tris = quad([0.0, 0.0, 16.0, 16.0], [0.0, 0.0], [1.0, 1.0], 16, 16);
    let ftris: Vec<[ClipVertex; 3]> = adapter::clip_triangles(&tris);
    let level = |k: usize| rchain.levels[k].texels[0];
    let mix = |a: usize, b: usize, f: f64| {
        let (ca, cb) = (
            reference::rgb565_to_f64(level(a)),
            reference::rgb565_to_f64(level(b)),
        );
        reference::rgb565_from_f64(core::array::from_fn(|c| (1.0 - f) * ca[c] + f * cb[c]))
    };
    let cases: [(RefMip, f64, f64, f64, u16); 11] = [
        (RefMip::Nearest, 0.0, -99.0, 99.0, level(2)),
        (RefMip::Nearest, 1.0, -99.0, 99.0, level(3)),
        (RefMip::Nearest, -1.25, -99.0, 99.0, level(1)),
        (RefMip::Nearest, -1.75, -99.0, 99.0, level(0)),
        (RefMip::Nearest, -3.0, -99.0, 99.0, level(0)), // magnified
        (RefMip::Nearest, 0.0, 4.0, 99.0, level(4)),
        (RefMip::Nearest, 0.0, -99.0, 1.0, level(1)),
        (RefMip::Nearest, 10.0, -99.0, 99.0, level(6)), // beyond the chain: the last level
        (RefMip::Linear, 0.5, -99.0, 99.0, mix(2, 3, 0.5)),
        (RefMip::Linear, 0.25, -99.0, 1.75, mix(1, 2, 0.75)),
        (RefMip::Linear, 0.0, 5.5, 99.0, mix(5, 6, 0.5)),
    ];
    for (mip, bias, min, max, want) in cases {
        let lod = RefLod { bias, min, max };
        let mode = quad_mode(RefFilter::Nearest, mip, RefWrap::Repeat, lod);
        let r = reference::render_chain(&tris, Some(&rchain), &mode, 16, 16);
        let rq = r.quantize_rgb565();
        for g in [
            LodGranularity::Pixel,
            LodGranularity::Span,
            LodGranularity::Triangle,
        ] {
            let mut dm = adapter::draw_mode(&mode, None, false);
            dm.lod.granularity = g;
            let f = adapter::render_tex(&ftris, Some(mips), dm, 16, 16);
            let what = format!("{mip:?} bias {bias} [{min}, {max}] {g:?}");
            assert!(rq.iter().all(|&p| p == want), "reference {what}");
            for &p in &f.pixels {
                let e = metrics::channel_errors(p, want);
                assert!(e.iter().all(|&e| e <= 1), "{what}: {p:04x} vs {want:04x}");
            }
        }
    }
}

/// The filters as fixel's run-time mode: the adapter maps them one to one.
#[test]
fn draw_mode_mapping() {
    let m = adapter::draw_mode(
        &RefMode {
            mip: RefMip::Linear,
            lod: RefLod {
                bias: 0.5,
                min: 1.0,
                max: f64::INFINITY,
            },
            ..RefMode::default()
        },
        None,
        false,
    );
    assert_eq!(m.mip, MipFilter::Linear);
    assert_eq!(m.filter, Filter::Bilinear);
    assert_eq!(
        m.lod,
        Lod {
            bias: 128,
            min: 256,
            max: Lod::default().max,
            granularity: LodGranularity::Pixel
        }
    );
}
