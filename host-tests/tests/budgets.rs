//! Error budgets: fixel against the f64 reference, per feature and mode,
//! each bound set from measurement (run with `--nocapture` to see every
//! figure; the tables are also written to `target/error-budgets.md`).
//!
//! Errors are per-channel RGB565 LSBs against the reference quantised to
//! RGB565 (see `metrics`), over pixels both cover. Each fixel mode is judged
//! against the reference with the SAME interpolation (perspective for Exact
//! and Subdivided, screen-linear for Affine): that is implementation error.
//! Affine is also measured against perspective: the cost of choosing it,
//! reported, bounded only for sanity. Coverage must agree exactly
//! everywhere (both snap vertices to 1/16 pixel and use the top-left rule).
//! The reference interpolates attributes from the EXACT (unsnapped) window
//! positions, as GL specifies; fixel from positions rounded to 1/4096 pixel
//! (`ATTR_SUBPIXEL_BITS`). Affine is GL's `noperspective` in both: linear in
//! screen space over the whole original triangle, clipping included.
//!
//! | case | budget | why it holds |
//! |---|---|---|
//! | Flat | exact (0 LSB) | a constant colour, no arithmetic |
//! | Exact / Affine, Bilinear, Gouraud, Modulate(Intensity), Replace | max 1 LSB | fixel's uv/colour are exact to ~1e-3 texel / 1/256, the 4x8-bit bilinear weights and Q8 modulation round once: the result rounds to the reference's RGB565 value or its neighbour |
//! | Exact + Bilinear (the target) | ≥ 99.5% within 1 LSB, > 2 LSB only where minified | as above; where one pixel spans many texels (the floor, no mipmaps) a sample-point difference of < 0.01 px moves the 2x2 footprint across aliased checker edges |
//! | floor, Exact/Subdivided + Bilinear | max 8, > 1 LSB ≤ 0.2%, > 2 LSB ≤ 0.05% | the floor is minified everywhere (10-70 texels/px); measured against the exact reference: max 3, 0.061% / 0.005% |
//! | floors, Affine (clipped by the guard band or not) | max 2, > 1 LSB ≤ 0.15%, none > 2 | GL's `noperspective` through the clipper; measured max 2 at 0.04% (wide) and 0.09% (narrow) |
//! | Exact / Affine + Nearest | > 1 LSB ≤ 0.6% of pixels, and only within 1/64 px of a texel edge; PSNR ≥ 27 dB | a sample point that close to an edge may round to the neighbouring texel (any colour difference). Near the floor's horizon a pixel spans ~300 texels, so the 1/4096-pixel positions leave ~1/64 texel of doubt: measured 0.545% flips, every one within 1/64 texel of a texel edge (`subpixel.rs` counts the others: 0) |
//! | Subdivided N=4/8/16/32 | > 1 LSB ≤ 1.2% / 5% / 9% / 18%, PSNR ≥ 27 / 26 / 22 / 18 dB | approximation between exact samples; LOOSE: includes the span-end bug (see `subdivided_never_worse_than_its_endpoints`) |
//! | Affine vs perspective reference | sanity: PSNR ≥ 5 dB | the mode's own error (up to 62 LSB on the floor) |

use std::fmt::Write as _;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::Mutex;
use std::time::Instant;

use fixel::pipeline::Projection;
use host_tests::metrics::{self, channel_errors, Report};
use host_tests::reference::{
    self, RefCull, RefFilter, RefImage, RefMode, RefProjection, RefShading, RefTexture,
    RefTriangle, RefWrap,
};
use host_tests::{adapter, scenes, synthetic};

/// One scene under test, with the reference state its fixel mode mirrors.
struct Scene {
    name: String,
    tris: Vec<RefTriangle>,
    tex: Option<RefTexture>,
    mode: RefMode,
    /// Use `ModulateIntensity` for `Modulate` (grey vertex colours).
    intensity: bool,
    width: u32,
    height: u32,
}

impl Scene {
    fn textured(&self) -> bool {
        !matches!(self.mode.shading, RefShading::Gouraud | RefShading::Flat(_))
    }

    fn shading_name(&self) -> &'static str {
        match self.mode.shading {
            RefShading::Replace => "Replace",
            RefShading::Modulate if self.intensity => "ModulateIntensity",
            RefShading::Modulate => "Modulate",
            RefShading::Gouraud => "Gouraud",
            RefShading::Flat(_) => "Flat",
        }
    }
}

fn bench_scene(name: String, s: &scenes::SceneDesc, mode: RefMode, intensity: bool) -> Scene {
    Scene {
        name,
        tris: scenes::to_ref_triangles(s),
        tex: Some(s.texture.clone()),
        mode,
        intensity,
        width: s.width,
        height: s.height,
    }
}

fn synthetic_scene(
    name: &str,
    tris: Vec<RefTriangle>,
    shading: RefShading,
    wrap: RefWrap,
) -> Scene {
    Scene {
        name: name.into(),
        tris,
        tex: Some(synthetic::quad_texture()),
        mode: RefMode {
            wrap_u: wrap,
            wrap_v: wrap,
            shading,
            depth_test: false,
            cull: RefCull::None,
            ..RefMode::default()
        },
        intensity: false,
        width: synthetic::WIDTH,
        height: synthetic::HEIGHT,
    }
}

fn all_scenes() -> Vec<Scene> {
    let mut v = Vec::new();
    for f in [0, 33, 66] {
        let s = scenes::cube(f);
        v.push(bench_scene(format!("cube {f}"), &s, s.mode, true));
    }
    let s = scenes::cube(0);
    v.push(bench_scene("cube 0".into(), &s, s.mode, false));
    v.push(bench_scene(
        "cube 0".into(),
        &s,
        RefMode {
            shading: RefShading::Flat([1.0; 3]),
            ..s.mode
        },
        false,
    ));
    let s = scenes::sphere(0);
    v.push(bench_scene("sphere 0".into(), &s, s.mode, true));
    let s = scenes::floor();
    v.push(bench_scene("floor".into(), &s, s.mode, false));
    let mut narrow = s.clone();
    for p in &mut narrow.mesh.positions {
        p[0] *= 8.0 / 50.0;
    }
    v.push(bench_scene("floor narrow".into(), &narrow, s.mode, false));
    for (name, w) in [
        ("quad Repeat", RefWrap::Repeat),
        ("quad MirroredRepeat", RefWrap::MirroredRepeat),
        ("quad ClampToEdge", RefWrap::ClampToEdge),
        ("quad ClampToBorder", RefWrap::ClampToBorder),
    ] {
        v.push(synthetic_scene(
            name,
            synthetic::wrap_quad(),
            RefShading::Replace,
            w,
        ));
    }
    v.push(synthetic_scene(
        "quad coloured",
        synthetic::colored_quad(),
        RefShading::Modulate,
        RefWrap::Repeat,
    ));
    let mut g = synthetic_scene(
        "triangle",
        synthetic::gouraud_triangle(),
        RefShading::Gouraud,
        RefWrap::Repeat,
    );
    g.tex = None;
    v.push(g);
    v
}

const PROJECTIONS: [(&str, Projection); 8] = [
    ("Exact", Projection::Exact),
    ("Subdivided N=4", Projection::Subdivided { log2_n: 2 }),
    ("Subdivided N=8", Projection::Subdivided { log2_n: 3 }),
    ("Subdivided N=16", Projection::Subdivided { log2_n: 4 }),
    ("Subdivided N=32", Projection::Subdivided { log2_n: 5 }),
    ("Quadratic N=16", Projection::Quadratic { log2_n: 4 }),
    ("Quadratic N=32", Projection::Quadratic { log2_n: 5 }),
    ("Affine", Projection::Affine),
];

/// Per-pixel detail beyond [`Report`], from the exact interpolated uv.
#[derive(Clone, Copy, Debug, Default)]
struct Detail {
    /// Pixels off by more than 1 LSB (with Nearest: texel flips).
    over1: usize,
    /// Of those, pixels whose sample point is NOT within `EPS_PX` pixel of a
    /// texel boundary (must be 0 for Nearest implementation error).
    unexplained: usize,
    /// Largest boundary distance (pixels) among the pixels off by > 1 LSB.
    max_dist_px: f64,
    /// Largest error where the texture is not minified (footprint <= 1 texel/px).
    max_unminified: u32,
    /// Pixels off by more than 2 LSB where the texture IS minified.
    over2_minified: usize,
}

/// A Nearest sample whose exact texel coordinate lies within this many
/// pixels (texel distance / texels per pixel) of a texel boundary may pick
/// the neighbouring texel: fixel's coordinate is exact to a small fraction of
/// a pixel, not to zero.
const EPS_PX: f64 = 1.0 / 64.0;

/// Per covered pixel: (distance in pixels from the sample point to the
/// nearest texel edge, footprint in texels per pixel), from the exact
/// `[u, v]` image. Derivatives are the smaller one-sided difference to a
/// covered neighbour (so a uv seam between triangles does not count).
fn uv_geometry(uv: &RefImage, tex: &RefTexture) -> Vec<(f64, f64)> {
    let (w, h) = (uv.width as usize, uv.height as usize);
    let size = [f64::from(tex.width), f64::from(tex.height)];
    let mut out = vec![(f64::INFINITY, 0.0); w * h];
    for y in 0..h {
        for x in 0..w {
            let k = y * w + x;
            if !uv.covered[k] {
                continue;
            }
            let mut nb = [usize::MAX; 4];
            if x > 0 {
                nb[0] = k - 1;
            }
            if x + 1 < w {
                nb[1] = k + 1;
            }
            if y > 0 {
                nb[2] = k - w;
            }
            if y + 1 < h {
                nb[3] = k + w;
            }
            let (mut dist, mut foot) = (f64::INFINITY, 0.0f64);
            for (c, &sz) in size.iter().enumerate() {
                let t = uv.rgb[k][c] * sz;
                let mut fc = 0.0f64;
                for axis in [&nb[..2], &nb[2..]] {
                    let mut m = f64::INFINITY;
                    for &n in axis {
                        if n != usize::MAX && uv.covered[n] {
                            m = m.min((uv.rgb[n][c] * sz - t).abs());
                        }
                    }
                    if m.is_finite() {
                        fc = fc.max(m);
                    }
                }
                if fc > 0.0 {
                    dist = dist.min((t - t.round()).abs() / fc);
                }
                foot = foot.max(fc);
            }
            out[k] = (dist, foot);
        }
    }
    out
}

fn detail(f: &[u16], cov: &[bool], q: &[u16], rcov: &[bool], geo: &[(f64, f64)]) -> Detail {
    let mut out = Detail::default();
    for k in 0..f.len() {
        if !(cov[k] && rcov[k]) {
            continue;
        }
        let e = channel_errors(f[k], q[k]).into_iter().max().unwrap_or(0);
        let (dist, foot) = geo[k];
        if e > 1 {
            out.over1 += 1;
            out.max_dist_px = out.max_dist_px.max(dist);
            if dist >= EPS_PX {
                out.unexplained += 1;
            }
        }
        if foot <= 1.0 {
            out.max_unminified = out.max_unminified.max(e);
        } else if e > 2 {
            out.over2_minified += 1;
        }
    }
    out
}

fn render_ref(sc: &Scene, filter: RefFilter, proj: RefProjection) -> RefImage {
    let mode = RefMode {
        filter,
        projection: proj,
        ..sc.mode
    };
    reference::render(&sc.tris, sc.tex.as_ref(), &mode, sc.width, sc.height)
}

/// Reference image whose "colour" is the exact interpolated `[u, v, 0]`
/// (the reference interpolates colour and uv with the same formula and does
/// not clamp colours).
fn render_uv(sc: &Scene, proj: RefProjection) -> RefImage {
    let tris: Vec<RefTriangle> = sc
        .tris
        .iter()
        .map(|t| {
            RefTriangle(t.0.map(|mut v| {
                v.color = [v.uv[0], v.uv[1], 0.0];
                v
            }))
        })
        .collect();
    let mode = RefMode {
        projection: proj,
        shading: RefShading::Gouraud,
        ..sc.mode
    };
    reference::render(&tris, None, &mode, sc.width, sc.height)
}

struct Row {
    order: usize,
    scene: String,
    shading: &'static str,
    filter: &'static str,
    projection: &'static str,
    /// Interpolation of the reference: the same as fixel's (implementation
    /// error) or perspective for Affine (the cost of choosing the mode).
    same: bool,
    rep: Report,
    /// Per-pixel detail (textured scenes only).
    detail: Option<Detail>,
}

/// A reference image quantised once, with its uv geometry when textured.
struct Ref {
    q: Vec<u16>,
    covered: Vec<bool>,
    geo: Option<Vec<(f64, f64)>>,
}

fn reference_for(sc: &Scene, filter: RefFilter, proj: RefProjection) -> Ref {
    let r = render_ref(sc, filter, proj);
    Ref {
        q: r.quantize_rgb565(),
        covered: r.covered,
        geo: sc
            .tex
            .as_ref()
            .filter(|_| sc.textured())
            .map(|t| uv_geometry(&render_uv(sc, proj), t)),
    }
}

fn measure(sc: &Scene, si: usize, filter: RefFilter) -> Vec<Row> {
    let clip = adapter::clip_triangles(&sc.tris);
    let ref_p = reference_for(sc, filter, RefProjection::Perspective);
    let ref_a = reference_for(sc, filter, RefProjection::Affine);
    let filter_name = match (sc.textured(), filter) {
        (false, _) => "-",
        (true, RefFilter::Nearest) => "Nearest",
        (true, RefFilter::Bilinear) => "Bilinear",
    };
    let mut rows = Vec::new();
    for &(pname, proj) in &PROJECTIONS {
        let mode = adapter::draw_mode(&RefMode { filter, ..sc.mode }, Some(proj), sc.intensity);
        let f = adapter::render(&clip, sc.tex.as_ref(), mode, sc.width, sc.height);
        let mut push = |same: bool, r: &Ref| {
            rows.push(Row {
                order: si * 2 + usize::from(filter == RefFilter::Nearest),
                scene: sc.name.clone(),
                shading: sc.shading_name(),
                filter: filter_name,
                projection: pname,
                same,
                rep: metrics::compare_rgb565(&f.pixels, &f.covered, &r.q, &r.covered),
                detail: r
                    .geo
                    .as_ref()
                    .filter(|_| same)
                    .map(|g| detail(&f.pixels, &f.covered, &r.q, &r.covered, g)),
            })
        };
        if proj == Projection::Affine {
            push(true, &ref_a);
            push(false, &ref_p);
        } else {
            push(true, &ref_p);
        }
    }
    rows
}

/// A bound on one row. `None` fields are not checked.
#[derive(Clone, Copy, Debug)]
struct Budget {
    /// Largest error in LSB over all pixels covered by both.
    max: u32,
    /// Share of pixels more than 1 LSB off.
    over1: f64,
    /// Share of pixels more than 2 LSB off.
    over2: f64,
    /// Largest error where the texture is not minified.
    max_unminified: Option<u32>,
    /// Nearest: pixels more than 1 LSB off whose sample point is not within
    /// `EPS_PX` of a texel boundary.
    unexplained: Option<usize>,
    /// Lowest PSNR in dB.
    psnr: f64,
}

const SANITY: Budget = Budget {
    max: 63,
    over1: 1.0,
    over2: 1.0,
    max_unminified: None,
    unexplained: None,
    psnr: 5.0,
};

/// Implementation error of Exact/Affine with Bilinear or untextured
/// shading: the value rounds to the reference's RGB565 or a neighbour.
const ONE_LSB: Budget = Budget {
    max: 1,
    over1: 0.0,
    over2: 0.0,
    max_unminified: Some(1),
    unexplained: Some(0),
    psnr: 39.0,
};

/// The floor, Exact (or Subdivided) + Bilinear: minified everywhere
/// (10-70 texels per pixel), so a sample-point error of a few thousandths
/// of a pixel moves the 2x2 footprint across aliased checker edges.
const FLOOR_BILINEAR: Budget = Budget {
    max: 8,
    over1: 0.002,
    over2: 0.0005,
    max_unminified: Some(1),
    unexplained: Some(0),
    psnr: 45.0,
};

/// The floors under Affine (GL's `noperspective`, the wide floor cut by the
/// guard band): positions to 1/4096 px and Q30 clip parameters leave a
/// few pixels one LSB further.
const FLOOR_AFFINE: Budget = Budget {
    max: 2,
    over1: 0.0015,
    over2: 0.0,
    max_unminified: Some(1),
    unexplained: Some(0),
    psnr: 45.0,
};

/// Exact/Affine + Nearest: off by more than 1 LSB only where the sample
/// point is within `EPS_PX` of a texel edge (then any texel difference).
/// Against the exact reference: 0.545% on the floor, all near an edge.
const NEAREST: Budget = Budget {
    max: 63,
    over1: 0.006,
    over2: 0.006,
    max_unminified: None,
    unexplained: Some(0),
    psnr: 27.0,
};

/// Subdivided against the perspective reference, per N (index log2_n - 2):
/// the measured worst case over the scenes with a little headroom. This is
/// the approximation error of the mode (affine between exact points N pixels
/// apart), not an implementation error, so it grows with N. Measured after
/// the span-end fix (see `subdivided_never_worse_than_its_endpoints`): share
/// over 1 LSB 0.8 / 3.4 / 6.3 / 12.2 %, over 2 LSB 0.3 / 2.2 / 5.5 / 10.6 %,
/// lowest PSNR (nearest) 33.2 / 28.3 / 23.1 / 19.0 dB for N = 4 / 8 / 16 / 32.
const SUBDIVIDED: [Budget; 4] = [
    Budget {
        max: 63,
        over1: 0.012,
        over2: 0.006,
        max_unminified: None,
        unexplained: None,
        psnr: 27.0,
    },
    Budget {
        max: 63,
        over1: 0.05,
        over2: 0.032,
        max_unminified: None,
        unexplained: None,
        psnr: 26.0,
    },
    Budget {
        max: 63,
        over1: 0.09,
        over2: 0.08,
        max_unminified: None,
        unexplained: None,
        psnr: 22.0,
    },
    Budget {
        max: 63,
        over1: 0.18,
        over2: 0.15,
        max_unminified: None,
        unexplained: None,
        psnr: 18.0,
    },
];

/// Quadratic + Bilinear against the perspective reference, for N = 16 and 32: the
/// parabola through three exact values per segment. Measured: N = 16 max 3 LSB, 0.203 % of
/// pixels over 1 LSB, 0.047 % over 2, lowest PSNR 39.6 dB (Exact: 0.061 %, 0.005 %, 39.6;
/// Subdivided N = 4: 0.797 %, 0.249 %, 39.4); N = 32 max 7, 1.615 %, 0.879 %, 38.1 dB.
const QUADRATIC_BILINEAR: [Budget; 2] = [
    Budget {
        max: 4,
        over1: 0.003,
        over2: 0.001,
        max_unminified: None,
        unexplained: None,
        psnr: 39.0,
    },
    Budget {
        max: 9,
        over1: 0.02,
        over2: 0.011,
        max_unminified: None,
        unexplained: None,
        psnr: 37.5,
    },
];

/// Quadratic + Nearest (and untextured), N = 16 and 32: texel flips near texel edges, as
/// Exact's (measured 0.550 % of pixels over 1 LSB for both N, Exact 0.548 %; PSNR 27.4).
const QUADRATIC_NEAREST: Budget = Budget {
    max: 63,
    over1: 0.006,
    over2: 0.006,
    max_unminified: None,
    unexplained: None,
    psnr: 27.0,
};

fn budget(r: &Row) -> Budget {
    let floor = r.scene.starts_with("floor");
    if r.shading == "Flat" {
        return Budget {
            max: 0,
            psnr: f64::INFINITY,
            ..ONE_LSB
        };
    }
    if !r.same {
        // Affine against perspective is the cost of the mode.
        return SANITY;
    }
    if let Some(n) = r.projection.strip_prefix("Subdivided N=") {
        let k = n.parse::<u32>().unwrap().trailing_zeros() as usize - 2;
        // The floor too: its long spans are where the chord is furthest from the
        // hyperbola (floor narrow, N = 32: 0.28 % of pixels over 1 LSB, above
        // FLOOR_BILINEAR's exact-mode bound; before the span-end fix it happened to
        // stay under it).
        return SUBDIVIDED[k];
    }
    if let Some(n) = r.projection.strip_prefix("Quadratic N=") {
        let k = usize::from(n == "32");
        return if r.filter == "Bilinear" {
            QUADRATIC_BILINEAR[k]
        } else {
            QUADRATIC_NEAREST
        };
    }
    match (r.filter, floor, r.projection == "Affine") {
        ("Nearest", _, _) => NEAREST,
        ("Bilinear", true, false) => FLOOR_BILINEAR,
        ("Bilinear", true, true) => FLOOR_AFFINE,
        _ => ONE_LSB,
    }
}

#[test]
fn error_budgets() {
    let t0 = Instant::now();
    let scenes = all_scenes();
    let mut work = Vec::new();
    for (si, sc) in scenes.iter().enumerate() {
        work.push((si, RefFilter::Bilinear));
        if sc.textured() {
            work.push((si, RefFilter::Nearest));
        }
    }
    let next = AtomicUsize::new(0);
    let rows = Mutex::new(Vec::new());
    let threads = std::thread::available_parallelism().map_or(2, |n| n.get());
    std::thread::scope(|s| {
        for _ in 0..threads {
            s.spawn(|| loop {
                let i = next.fetch_add(1, Ordering::Relaxed);
                let Some(&(si, filter)) = work.get(i) else {
                    break;
                };
                let t = Instant::now();
                let r = measure(&scenes[si], si, filter);
                if std::env::var_os("FIXEL_BUDGET_TIMES").is_some() {
                    println!("{} {filter:?}: {:?}", scenes[si].name, t.elapsed());
                }
                rows.lock().unwrap().extend(r);
            });
        }
    });
    let mut rows = rows.into_inner().unwrap();
    rows.sort_by_key(|r| r.order);
    let mut failures = Vec::new();
    let mut md = summary(&rows);
    md += "\n### Every case\n\n\
           | scene | shading | filter | projection | reference | px | cov diff | max | p99 \
           | >1 LSB | >2 LSB | PSNR dB | max unminified | >1 LSB off a texel edge | budget |\n\
           |---|---|---|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|\n";
    for r in &rows {
        let b = budget(r);
        let d = r.detail;
        writeln!(
            md,
            "| {} | {} | {} | {} | {} | {} | {} | {} | {} | {:.3}% | {:.3}% | {:.1} | {} | {} | {} |",
            r.scene,
            r.shading,
            r.filter,
            r.projection,
            if r.same { "same" } else { "perspective" },
            r.rep.both_covered,
            r.rep.only_candidate + r.rep.only_reference,
            r.rep.max,
            r.rep.p99,
            100.0 * r.rep.share_over_1,
            100.0 * r.rep.share_over_2,
            r.rep.psnr_db,
            d.map_or("-".into(), |d| d.max_unminified.to_string()),
            d.map_or("-".into(), |d| format!(
                "{} of {} (edge dist ≤ {:.4} px)",
                d.unexplained, d.over1, d.max_dist_px
            )),
            describe(&b),
        )
        .unwrap();
        for f in check(r, &b) {
            failures.push(format!(
                "{} / {} / {} / {} vs {}: {f}",
                r.scene,
                r.shading,
                r.filter,
                r.projection,
                if r.same { "same" } else { "perspective" }
            ));
        }
    }
    println!("{md}");
    let dir = target_dir();
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("error-budgets.md");
    std::fs::write(&path, &md).unwrap();
    println!("wrote {} in {:?}", path.display(), t0.elapsed());
    assert!(
        failures.is_empty(),
        "budgets exceeded:\n{}",
        failures.join("\n")
    );
}

fn target_dir() -> std::path::PathBuf {
    std::env::var_os("CARGO_TARGET_DIR")
        .map(std::path::PathBuf::from)
        .unwrap_or_else(|| std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../target"))
}

fn describe(b: &Budget) -> String {
    let mut s = format!(
        "max {}, >1 {}%, >2 {}%, PSNR ≥ {}",
        b.max,
        100.0 * b.over1,
        100.0 * b.over2,
        b.psnr
    );
    if let Some(m) = b.max_unminified {
        write!(s, ", unminified max {m}").unwrap();
    }
    if let Some(u) = b.unexplained {
        write!(s, ", off-edge {u}").unwrap();
    }
    s
}

fn check(r: &Row, b: &Budget) -> Vec<String> {
    let mut f = Vec::new();
    let rep = &r.rep;
    if rep.only_candidate + rep.only_reference != 0 {
        f.push(format!(
            "coverage differs ({} fixel only, {} reference only)",
            rep.only_candidate, rep.only_reference
        ));
    }
    if rep.max > b.max {
        f.push(format!("max {} > {}", rep.max, b.max));
    }
    if rep.share_over_1 > b.over1 {
        f.push(format!(
            "share >1 LSB {:.5} > {}",
            rep.share_over_1, b.over1
        ));
    }
    if rep.share_over_2 > b.over2 {
        f.push(format!(
            "share >2 LSB {:.5} > {}",
            rep.share_over_2, b.over2
        ));
    }
    if rep.psnr_db < b.psnr {
        f.push(format!("PSNR {:.2} < {}", rep.psnr_db, b.psnr));
    }
    if let (Some(m), Some(d)) = (b.max_unminified, r.detail) {
        if d.max_unminified > m {
            f.push(format!("max where not minified {} > {m}", d.max_unminified));
        }
    }
    // The target for Exact + Bilinear: within 1 LSB on at least 99.5%
    // of the pixels and never above 2 LSB, except where the texture is
    // minified (no mipmaps: aliasing amplifies sub-pixel differences).
    if r.same && r.projection == "Exact" && r.filter == "Bilinear" {
        let over2 = (rep.share_over_2 * rep.both_covered as f64).round() as usize;
        let minified = r.detail.map_or(0, |d| d.over2_minified);
        if rep.share_over_1 > 0.005 || over2 > minified {
            f.push(format!(
                "issue target: >1 LSB {:.4}% (max 0.5%), {} pixels > 2 LSB of which {} minified",
                100.0 * rep.share_over_1,
                over2,
                minified
            ));
        }
    }
    if let (Some(u), Some(d)) = (b.unexplained, r.detail) {
        if d.unexplained > u {
            f.push(format!(
                "{} pixels off by > 1 LSB away from a texel edge (> {u})",
                d.unexplained
            ));
        }
    }
    f
}

/// One line per (reference, filter, projection): the worst case over the
/// scenes (Flat excluded: it is exact everywhere).
fn summary(rows: &[Row]) -> String {
    let mut s = String::from(
        "### Summary (worst case over the scenes)\n\n\
         | projection | filter | reference | max LSB | p99 | >1 LSB | >2 LSB | min PSNR dB | cov diff |\n\
         |---|---|---|---:|---:|---:|---:|---:|---:|\n",
    );
    for same in [true, false] {
        for filter in ["Bilinear", "Nearest", "-"] {
            for &(p, _) in &PROJECTIONS {
                if !same && p != "Affine" {
                    continue;
                }
                let sel: Vec<&Row> = rows
                    .iter()
                    .filter(|r| {
                        r.projection == p
                            && r.filter == filter
                            && r.same == same
                            && r.shading != "Flat"
                            && !(r.scene == "floor" && p == "Affine" && same)
                    })
                    .collect();
                if sel.is_empty() {
                    continue;
                }
                let max = sel.iter().map(|r| r.rep.max).max().unwrap_or(0);
                let p99 = sel.iter().map(|r| r.rep.p99).max().unwrap_or(0);
                let o1 = sel.iter().map(|r| r.rep.share_over_1).fold(0.0, f64::max);
                let o2 = sel.iter().map(|r| r.rep.share_over_2).fold(0.0, f64::max);
                let psnr = sel
                    .iter()
                    .map(|r| r.rep.psnr_db)
                    .fold(f64::INFINITY, f64::min);
                let cov: usize = sel
                    .iter()
                    .map(|r| r.rep.only_candidate + r.rep.only_reference)
                    .sum();
                writeln!(
                    s,
                    "| {p} | {filter} | {} | {max} | {p99} | {:.3}% | {:.3}% | {psnr:.1} | {cov} |",
                    if same && p == "Affine" {
                        "affine"
                    } else {
                        "perspective"
                    },
                    100.0 * o1,
                    100.0 * o2,
                )
                .unwrap();
            }
        }
    }
    s
}

/// Exact values at a span's pixels, interpolated in between, can be no worse
/// than Affine where Affine itself is within 1 LSB of perspective: on the
/// sphere (small triangles) and the cube at N = 4 the approximation error
/// is far below 1 LSB. Fails today with 9-14 LSB: `SubdivInterp` (in
/// `src/pipeline/interp.rs`) ends the last segment of a span at pixel
/// `x0 + len`, ONE PAST the span, i.e. outside the triangle, and steps the
/// last pixels towards that extrapolated value (beyond the triangle uv can
/// leave its range and wrap with Repeat, and for steep triangles the
/// hyperbola is far from its chord there).
#[test]
fn subdivided_never_worse_than_its_endpoints() {
    let mut bad = Vec::new();
    for sc in [
        bench_scene(
            "sphere 0".into(),
            &scenes::sphere(0),
            scenes::sphere(0).mode,
            true,
        ),
        bench_scene(
            "cube 66".into(),
            &scenes::cube(66),
            scenes::cube(66).mode,
            true,
        ),
    ] {
        let r = reference_for(&sc, RefFilter::Bilinear, RefProjection::Perspective);
        let geo = r.geo.as_ref().unwrap();
        let clip = adapter::clip_triangles(&sc.tris);
        let mode = adapter::draw_mode(&sc.mode, Some(Projection::Subdivided { log2_n: 2 }), true);
        let f = adapter::render(&clip, sc.tex.as_ref(), mode, sc.width, sc.height);
        let d = detail(&f.pixels, &f.covered, &r.q, &r.covered, geo);
        println!(
            "{}: N=4 max where not minified {} LSB",
            sc.name, d.max_unminified
        );
        if d.max_unminified > 2 {
            bad.push(format!("{}: {} LSB", sc.name, d.max_unminified));
        }
    }
    assert!(bad.is_empty(), "Subdivided N=4 worse than 2 LSB: {bad:?}");
}
