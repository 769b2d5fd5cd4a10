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
//!
//! One test binary: the scenes in `cases`, the per-pixel detail in `detail`, the measured
//! rows and their summary in `rows`, the budgets in `budget`; the two tests here.

mod budget;
mod cases;
mod detail;
mod rows;

use std::fmt::Write as _;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::Mutex;
use std::time::Instant;

use budget::{budget, check, describe};
use cases::{all_scenes, bench_scene};
use detail::detail;
use fixel::pipeline::Projection;
use host_tests::reference::{RefFilter, RefProjection};
use host_tests::{adapter, scenes};
use rows::{measure, reference_for, summary};

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
