//! Shared helpers of the hard-case suite: the reference modes, [`check_ref`] (fixel against
//! the reference, through the adapter and a guarded target), per-triangle exact coverage,
//! and the bounds the cases assert.

use crate::common::*;
use fixel::geometry::Cull;
use host_tests::adapter;
use host_tests::metrics::{self, Report};
use host_tests::reference::{
    self, RefCull, RefFilter, RefMode, RefProjection, RefShading, RefTexture, RefTriangle, RefWrap,
};

pub const W: usize = 64;
pub const H: usize = 64;

pub fn flat_mode() -> RefMode {
    RefMode {
        projection: RefProjection::Perspective,
        filter: RefFilter::Nearest,
        wrap_u: RefWrap::Repeat,
        wrap_v: RefWrap::Repeat,
        depth_test: false,
        shading: RefShading::Flat([1.0; 3]),
        cull: RefCull::None,
        ..RefMode::default()
    }
}

/// What [`check_ref`] measured.
pub struct Checked {
    pub rep: Report,
    /// Pixels covered by exactly one side.
    pub diff: Vec<(usize, usize)>,
}

/// Renders with the reference and with fixel (through the adapter, and again into a guarded
/// target, which must give the same pixels), prints the report.
pub fn check_ref(
    name: &str,
    tris: &[RefTriangle],
    tex: Option<&RefTexture>,
    mode: &RefMode,
    w: usize,
    h: usize,
) -> Checked {
    let r = reference::render(tris, tex, mode, w as u32, h as u32);
    let clip = adapter::clip_triangles(tris);
    let dm = adapter::draw_mode(mode, None, false);
    let f = adapter::render(&clip, tex, dm, w as u32, h as u32);
    let (g, written) = draw_guarded(&clip, tex, dm, w, h);
    assert_eq!(
        g.pixels(),
        f.pixels,
        "{name}: guarded target differs from Frame"
    );
    assert_eq!(written, f.written, "{name}: pixel counts differ");
    let rep = metrics::compare(&f.pixels, &f.covered, &r);
    println!("{name}: {rep}");
    let diff = (0..w * h)
        .filter(|&i| f.covered[i] != r.covered[i])
        .map(|i| (i % w, i / w))
        .collect();
    Checked { rep, diff }
}

/// Distance in pixels from the centre of pixel `p` to the nearest edge line of the
/// reference's (clipped, snapped) window triangles for `tris`.
pub fn edge_distance(tris: &[RefTriangle], p: (usize, usize), w: usize, h: usize) -> f64 {
    let (cx, cy) = (p.0 as f64 + 0.5, p.1 as f64 + 0.5);
    let mut best = f64::INFINITY;
    for t in tris {
        let poly = reference::clip::clip_triangle(t);
        for sub in reference::clip::fan(&poly) {
            let v = sub
                .0
                .map(|v| reference::raster::to_window(&v, w as u32, h as u32));
            let [Some(a), Some(b), Some(c)] = v else {
                continue;
            };
            for (p0, p1) in [(a, b), (b, c), (c, a)] {
                let (dx, dy) = (p1.x - p0.x, p1.y - p0.y);
                let len = (dx * dx + dy * dy).sqrt();
                if len > 0.0 {
                    best = best.min(((cx - p0.x) * dy - (cy - p0.y) * dx).abs() / len);
                }
            }
        }
    }
    best
}

/// Every pixel covered by one side only lies within `tol` pixels of a reference edge.
pub fn assert_diff_on_edges(
    name: &str,
    tris: &[RefTriangle],
    c: &Checked,
    tol: f64,
    w: usize,
    h: usize,
) {
    for &p in &c.diff {
        let d = edge_distance(tris, p, w, h);
        assert!(
            d <= tol,
            "{name}: pixel {p:?} covered by one side is {d} px from any edge"
        );
    }
}

/// Per triangle: fixel's coverage equals the reference's exactly (both windings drawn).
/// Returns the total number of covered pixels.
pub fn coverage_exact(name: &str, tris: &[RefTriangle], w: usize, h: usize) -> usize {
    let mut total = 0;
    for (k, t) in tris.iter().enumerate() {
        let r = reference::render(
            std::slice::from_ref(t),
            None,
            &flat_mode(),
            w as u32,
            h as u32,
        );
        let counts = write_counts(
            &adapter::clip_triangles(std::slice::from_ref(t)),
            Cull::None,
            w,
            h,
        );
        for (i, (&c, &rc)) in counts.iter().zip(&r.covered).enumerate() {
            assert!(
                c == u32::from(rc),
                "{name}: triangle {k} pixel ({}, {}) written {c} times, reference covers: {rc}\n{t:?}",
                i % w,
                i / w
            );
        }
        total += r.covered_count();
    }
    total
}

pub fn assert_within(name: &str, rep: &Report, coverage: usize, max: u32) {
    assert!(
        rep.only_candidate + rep.only_reference <= coverage,
        "{name}: coverage disagreement {} + {} > {coverage}",
        rep.only_candidate,
        rep.only_reference
    );
    assert!(rep.max <= max, "{name}: max error {} > {max}", rep.max);
}

pub fn gouraud() -> RefMode {
    RefMode {
        shading: RefShading::Gouraud,
        ..flat_mode()
    }
}

pub fn coloured(
    mut v: host_tests::reference::RefVertex,
    c: [f64; 3],
) -> host_tests::reference::RefVertex {
    v.color = c;
    v
}
