//! Hard-case stability suite (issue 3, item 5): slivers, needles, fill-rule ties, fans and
//! strips, the near plane and w near zero, enormous and limit coordinates, extreme texture
//! coordinates and sizes, depth extremes and precision, degenerate input.
//!
//! Every case draws into a [`common::Guarded`] target (sentinel guard rows and columns around
//! the visible buffers; rows requested outside the frame are errors), so "no panic, no write
//! out of bounds" is checked everywhere. Where the f64 reference applies, the error is
//! measured with `metrics::compare` and held to a documented bound; where coverage must be
//! watertight, writes are counted per pixel.

mod common;

use common::*;
use fixel::geometry::Cull;
use fixel::pipeline::{DepthTest, DrawMode, Projection, Shading};
use fixel::texture::{Filter, Wrap};
use host_tests::adapter;
use host_tests::metrics::{self, Report};
use host_tests::reference::{
    self, RefCull, RefFilter, RefMode, RefProjection, RefShading, RefTexture, RefTriangle, RefWrap,
};

const W: usize = 64;
const H: usize = 64;

fn flat_mode() -> RefMode {
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
struct Checked {
    rep: Report,
    /// Pixels covered by exactly one side.
    diff: Vec<(usize, usize)>,
}

/// Renders with the reference and with fixel (through the adapter, and again into a guarded
/// target, which must give the same pixels), prints the report.
fn check_ref(
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
fn edge_distance(tris: &[RefTriangle], p: (usize, usize), w: usize, h: usize) -> f64 {
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
fn assert_diff_on_edges(
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
fn coverage_exact(name: &str, tris: &[RefTriangle], w: usize, h: usize) -> usize {
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

fn assert_within(name: &str, rep: &Report, coverage: usize, max: u32) {
    assert!(
        rep.only_candidate + rep.only_reference <= coverage,
        "{name}: coverage disagreement {} + {} > {coverage}",
        rep.only_candidate,
        rep.only_reference
    );
    assert!(rep.max <= max, "{name}: max error {} > {max}", rep.max);
}

// ---------------------------------------------------------------------------------------
// Slivers and needles
// ---------------------------------------------------------------------------------------

#[test]
fn slivers_cover_exactly_what_the_reference_covers() {
    let mut rng = Rng(0x5111_7e55);
    let mut tris = Vec::new();
    for _ in 0..150 {
        // Two vertices far apart, the third within a pixel of the segment between them
        // (very obtuse), positions on the 1/16 grid or off it.
        let a = (rng.range(-8.0, 72.0), rng.range(-8.0, 72.0));
        let b = (rng.range(-8.0, 72.0), rng.range(-8.0, 72.0));
        let t = rng.range(0.0, 1.0);
        let (nx, ny) = (-(b.1 - a.1), b.0 - a.0);
        let len = (nx * nx + ny * ny).sqrt().max(1e-9);
        let off = rng.range(-0.9, 0.9) / len;
        let c = (
            a.0 + t * (b.0 - a.0) + off * nx,
            a.1 + t * (b.1 - a.1) + off * ny,
        );
        tris.push(tri(
            at_px(a.0, a.1, 0.0, 1.0, W, H),
            at_px(b.0, b.1, 0.0, 1.0, W, H),
            at_px(c.0, c.1, 0.0, 1.0, W, H),
        ));
        // A short side under a pixel long.
        let d = (a.0 + rng.range(-0.9, 0.9), a.1 + rng.range(-0.9, 0.9));
        tris.push(tri(
            at_px(a.0, a.1, 0.0, 1.0, W, H),
            at_px(d.0, d.1, 0.0, 1.0, W, H),
            at_px(b.0, b.1, 0.0, 1.0, W, H),
        ));
    }
    let n = coverage_exact("slivers", &tris, W, H);
    println!("slivers: {} triangles, {n} covered pixels", tris.len());
    assert!(n > 0);
}

#[test]
fn needles_spanning_the_screen() {
    // Corner-to-corner needles, 1/16 to 1 pixel wide at the far end, both windings, plus
    // perspective needles (w from 0.25 to 8) whose colour is compared with the reference.
    let mut tris = Vec::new();
    for k in 0..24 {
        let wd = (k % 16 + 1) as f64 / 16.0;
        let (x0, y0, x1, y1) = match k % 4 {
            0 => (0.0, 0.0, 64.0, 64.0),
            1 => (64.0, 0.0, 0.0, 64.0),
            2 => (-3.0, 31.7, 67.0, 32.3),
            _ => (32.2, -5.0, 31.9, 70.0),
        };
        let v = [
            at_px(x0, y0, 0.0, 1.0, W, H),
            at_px(x1, y1, 0.0, 1.0, W, H),
            at_px(x1 + wd, y1 - wd, 0.0, 1.0, W, H),
        ];
        tris.push(if k % 2 == 0 {
            tri(v[0], v[1], v[2])
        } else {
            tri(v[0], v[2], v[1])
        });
    }
    let n = coverage_exact("needles", &tris, W, H);
    assert!(n > 0);

    let mut mode = flat_mode();
    mode.shading = RefShading::Gouraud;
    let mut persp = Vec::new();
    for k in 0..8 {
        let wd = 0.3 + k as f64 * 0.1;
        let mut a = at_px(0.0, 2.0 + 7.0 * k as f64, 0.0, 0.25, W, H);
        let mut b = at_px(64.0, 62.0 - 7.0 * k as f64, 0.5, 8.0, W, H);
        let mut c = at_px(64.0, 62.0 - 7.0 * k as f64 + wd, 0.5, 8.0, W, H);
        a.color = [1.0, 0.0, 0.5];
        b.color = [0.0, 1.0, 0.25];
        c.color = [0.0, 1.0, 0.75];
        persp.push(tri(a, b, c));
    }
    let rep = check_ref("perspective needles", &persp, None, &mode, W, H).rep;
    // Snapped vertices identical on both sides: coverage agrees exactly. Gouraud colour:
    // the hyperbolic interpolation over a 32:1 w ratio is within 1 LSB (measured 1).
    assert_within("perspective needles", &rep, 0, 1);
}

// ---------------------------------------------------------------------------------------
// Fill-rule ties, fans, strips
// ---------------------------------------------------------------------------------------

#[test]
fn vertices_on_pixel_centres_and_edges() {
    // Every vertex on a pixel centre (x + 0.5) or a pixel edge (integer): edges through
    // centres are the fill rule's ties.
    let mut rng = Rng(0xCE17_7E55);
    let mut tris = Vec::new();
    for k in 0..120 {
        let snap = |v: f64| {
            if k % 2 == 0 {
                v.floor() + 0.5
            } else {
                v.floor()
            }
        };
        let p = [0, 1, 2].map(|_| (snap(rng.range(-4.0, 68.0)), snap(rng.range(-4.0, 68.0))));
        tris.push(tri(
            at_px(p[0].0, p[0].1, 0.0, 1.0, W, H),
            at_px(p[1].0, p[1].1, 0.0, 1.0, W, H),
            at_px(p[2].0, p[2].1, 0.0, 1.0, W, H),
        ));
    }
    // Axis-aligned right triangles with edges exactly through rows and columns of centres.
    for (x0, y0, s) in [(4.5, 4.5, 20.0), (10.0, 10.0, 30.0), (0.5, 0.5, 63.0)] {
        for (dx, dy) in [(s, s), (-s, s), (s, -s), (-s, -s)] {
            let c = (
                x0 + if dx < 0.0 { s } else { 0.0 },
                y0 + if dy < 0.0 { s } else { 0.0 },
            );
            tris.push(tri(
                at_px(c.0, c.1, 0.0, 1.0, W, H),
                at_px(c.0 + dx, c.1, 0.0, 1.0, W, H),
                at_px(c.0, c.1 + dy, 0.0, 1.0, W, H),
            ));
        }
    }
    let n = coverage_exact("centres and edges", &tris, W, H);
    assert!(n > 0);
}

/// A closed fan of `n` triangles around `centre` whose outer ring walks the border of the
/// `w` x `h` viewport (or beyond it by `out` pixels): the union is the whole viewport.
fn fan(centre: (f64, f64), n: usize, out: f64, wc: impl Fn(usize) -> f64) -> Vec<RefTriangle> {
    let (x0, y0, x1, y1) = (-out, -out, W as f64 + out, H as f64 + out);
    let per = 2.0 * (x1 - x0 + y1 - y0);
    let ring: Vec<(f64, f64)> = (0..n)
        .map(|k| {
            let mut d = per * k as f64 / n as f64;
            for (len, (sx, sy), (dx, dy)) in [
                (x1 - x0, (x0, y0), (1.0, 0.0)),
                (y1 - y0, (x1, y0), (0.0, 1.0)),
                (x1 - x0, (x1, y1), (-1.0, 0.0)),
                (y1 - y0, (x0, y1), (0.0, -1.0)),
            ] {
                if d <= len {
                    return (sx + dx * d, sy + dy * d);
                }
                d -= len;
            }
            (x0, y0)
        })
        .collect();
    let c = at_px(centre.0, centre.1, 0.0, wc(n), W, H);
    (0..n)
        .map(|k| {
            let (a, b) = (ring[k], ring[(k + 1) % n]);
            tri(
                c,
                at_px(a.0, a.1, 0.0, wc(k), W, H),
                at_px(b.0, b.1, 0.0, wc((k + 1) % n), W, H),
            )
        })
        .collect()
}

fn assert_each_pixel_once(name: &str, tris: &[RefTriangle], cull: Cull) {
    let counts = write_counts(&adapter::clip_triangles(tris), cull, W, H);
    let bad: Vec<(usize, u32)> = counts
        .iter()
        .enumerate()
        .filter(|&(_, &c)| c != 1)
        .map(|(i, &c)| (i, c))
        .collect();
    assert!(
        bad.is_empty(),
        "{name}: {} pixels not written exactly once, e.g. {:?}",
        bad.len(),
        bad.iter()
            .take(6)
            .map(|&(i, c)| ((i % W, i / W), c))
            .collect::<Vec<_>>()
    );
}

#[test]
fn fans_of_64_triangles_write_every_pixel_once() {
    for (name, centre) in [
        ("centre on pixel centre", (31.5, 31.5)),
        ("centre on pixel corner", (32.0, 32.0)),
        ("centre off grid", (20.3125, 41.8125)),
        ("centre on border", (0.0, 17.5)),
    ] {
        for out in [0.0, 0.5, 37.25] {
            let flat = fan(centre, 64, out, |_| 1.0);
            assert_each_pixel_once(name, &flat, Cull::None);
            // Per-vertex w from 0.5 to 4 (the same screen positions): shared vertices
            // project identically, so the fan stays watertight under perspective too.
            let persp = fan(centre, 64, out, |k| 0.5 + (k % 8) as f64 * 0.5);
            assert_each_pixel_once(name, &persp, Cull::None);
            // Counter-clockwise on screen (y down) is clockwise in NDC: back faces; culling
            // the front keeps all of them.
            assert_each_pixel_once(name, &flat, Cull::Front);
        }
    }
}

#[test]
fn strips_write_every_pixel_once() {
    // A strip of 64 triangles per band of rows, 4 bands of 16 rows, zig-zagging vertices
    // jittered along x (and the band borders at row edges and centres), covering the frame.
    let mut rng = Rng(0x57819);
    let cols = 32;
    let rows_y: Vec<f64> = vec![-1.0, 16.0, 31.5, 48.0, 65.0];
    let grid: Vec<Vec<f64>> = rows_y
        .iter()
        .map(|_| {
            (0..=cols)
                .map(|i| {
                    if i == 0 {
                        -2.0
                    } else if i == cols {
                        66.0
                    } else {
                        i as f64 * 2.0 + rng.range(-0.9, 0.9)
                    }
                })
                .collect()
        })
        .collect();
    let mut tris = Vec::new();
    for b in 0..4 {
        let (ya, yb) = (rows_y[b], rows_y[b + 1]);
        for i in 0..cols {
            let p =
                |r: usize, c: usize| at_px(grid[r][c], rows_y[r], 0.0, 1.0 + c as f64 / 8.0, W, H);
            let _ = (ya, yb);
            // Strip order (a0 b0 a1) (b0 b1 a1) with consistent winding.
            tris.push(tri(p(b, i), p(b + 1, i), p(b, i + 1)));
            tris.push(tri(p(b + 1, i), p(b + 1, i + 1), p(b, i + 1)));
        }
    }
    assert_eq!(tris.len(), 256);
    assert_each_pixel_once("strip", &tris, Cull::None);
    // All triangles have the same winding: culling one face keeps every pixel or none.
    let front = write_counts(&adapter::clip_triangles(&tris), Cull::Back, W, H);
    let back = write_counts(&adapter::clip_triangles(&tris), Cull::Front, W, H);
    assert!(
        (front.iter().all(|&c| c == 1) && back.iter().all(|&c| c == 0))
            || (front.iter().all(|&c| c == 0) && back.iter().all(|&c| c == 1))
    );
}

// ---------------------------------------------------------------------------------------
// Near plane, w near zero, behind the camera, enormous and limit coordinates
// ---------------------------------------------------------------------------------------

fn gouraud() -> RefMode {
    RefMode {
        shading: RefShading::Gouraud,
        ..flat_mode()
    }
}

fn coloured(
    mut v: host_tests::reference::RefVertex,
    c: [f64; 3],
) -> host_tests::reference::RefVertex {
    v.color = c;
    v
}

#[test]
fn triangles_crossing_the_near_plane() {
    // Physically consistent perspective (w = eye distance, near plane z = -w at w = 0.5):
    // z_clip = (w - 1) * 2 - w... here simply z = w - 1, so z = -w at w = 0.5, and a vertex
    // at w = 1e-4 lies behind the near plane. Both sides cut the edges (f64 vs. Q30 t), and
    // the cut vertices snap to the 1/16 grid: a cut that lands near a snap tie can move by
    // 1/16 px, so coverage may differ on a few pixels along the cut edge.
    let mk = |x: f64, y: f64, w: f64, c: [f64; 3]| coloured(rv([x, y, w - 1.0, w], [0.0, 0.0]), c);
    let mut cases = Vec::new();
    for w0 in [0.3, 0.1, 1e-4, 0.0, -0.5, -30.0] {
        cases.push(tri(
            mk(-0.2, -0.1, w0, [1.0, 0.0, 0.0]),
            mk(1.5, -0.9, 2.0, [0.0, 1.0, 0.0]),
            mk(0.3, 1.8, 3.0, [0.0, 0.0, 1.0]),
        ));
        // Two vertices behind.
        cases.push(tri(
            mk(0.9, 0.4, 2.5, [1.0, 1.0, 0.0]),
            mk(-0.3, -0.2, w0, [0.0, 1.0, 1.0]),
            mk(0.2, 0.05, w0 * 0.5, [1.0, 0.0, 1.0]),
        ));
    }
    let c = check_ref("near plane", &cases, None, &gouraud(), W, H);
    // Measured: 1 pixel covered by the reference only (0.03 px from the cut edge), colour
    // max 1 LSB.
    assert_diff_on_edges("near plane", &cases, &c, 1.0 / 16.0, W, H);
    assert_within("near plane", &c.rep, 2, 1);
}

#[test]
fn vertex_at_w_near_zero_in_front_of_the_near_plane() {
    // A vertex with w below 2^-8 that is still inside the view volume (|x|, |y|, |z| <= w)
    // is what a caller with near < 2^-8 or an unusual matrix can send. fixel clips at
    // w = 2^-8 (W_MIN, documented in geometry::clip: it bounds 1/w), the reference does not:
    // the part with w < 2^-8 projects over most of the triangle's screen area (from the
    // tiny-w vertex almost all the way to the others), and only fixel drops it. So fixel
    // must draw a subset of the reference (up to 1/16 px along the cut), with matching
    // colours where both draw, and never write out of bounds. w = 0 exactly: the reference
    // drops the triangle (no perspective divide), fixel keeps its w >= 2^-8 part.
    for w0 in [0.003, 1e-4, 2.0f64.powi(-16), 0.0] {
        let t = [tri(
            rv([0.0, 0.0, 0.0, w0], [0.0, 0.0]),
            coloured(rv([1.0, -0.5, 0.0, 1.0], [0.0, 0.0]), [0.0, 1.0, 0.0]),
            coloured(rv([-0.5, 1.0, 0.0, 1.0], [0.0, 0.0]), [0.0, 0.0, 1.0]),
        )];
        let c = check_ref(&format!("w0 = {w0}"), &t, None, &gouraud(), W, H);
        if w0 > 0.0 {
            for &p in &c.diff {
                let d = edge_distance(&t, p, W, H);
                // Reference-only pixels are expected (the dropped w < 2^-8 part).
                assert!(d <= 1.0 / 16.0 || c.rep.only_candidate == 0, "{p:?} {d}");
            }
            assert_eq!(c.rep.only_candidate, 0);
            // Measured max 0 (the overlap is next to the w = 1 edge).
            assert!(c.rep.max <= 1, "{}", c.rep);
        }
    }
}

#[test]
fn entirely_behind_the_camera_draws_nothing() {
    let modes = [gouraud(), flat_mode()];
    for mode in modes {
        for (x, y, z, w) in [
            (0.0, 0.0, 0.5, -1.0),
            (0.1, 0.2, -2.0, -1.0),
            (30000.0, -30000.0, 100.0, -0.001),
            (0.0, 0.0, 0.0, 0.0),
        ] {
            let t = [tri(
                rv([x - 0.5, y - 0.5, z, w], [0.0, 0.0]),
                rv([x + 0.5, y - 0.5, z, w], [0.0, 0.0]),
                rv([x, y + 0.5, z, w], [0.0, 0.0]),
            )];
            let clip = adapter::clip_triangles(&t);
            let (g, n) = draw_guarded(&clip, None, adapter::draw_mode(&mode, None, false), W, H);
            assert_eq!(n, 0);
            assert!(g.pixels().iter().all(|&p| p == 0));
            let r = reference::render(&t, None, &mode, W as u32, H as u32);
            assert_eq!(r.covered_count(), 0);
        }
    }
}

#[test]
fn enormous_triangles_far_outside_the_guard_band() {
    let m = 32767.0;
    let mut mode = gouraud();
    mode.projection = RefProjection::Affine;
    // Covers the whole frame; edges far outside.
    let full = [tri(
        coloured(rv([-m, -m, 0.0, 1.0], [0.0, 0.0]), [0.0, 0.0, 0.0]),
        coloured(rv([m, -m, 0.0, 1.0], [0.0, 0.0]), [1.0, 0.0, 0.0]),
        coloured(rv([0.0, m, 0.0, 1.0], [0.0, 0.0]), [0.0, 1.0, 1.0]),
    )];
    let rep = check_ref("enormous, full screen", &full, None, &mode, W, H).rep;
    assert_eq!(rep.both_covered, W * H);
    // Colour: vertices 2^15 NDC away, the gradient is 2^-21 per pixel; the guard-band cut
    // vertices carry Q8 colours rounded to integers (1/256 = 0.12 LSB) and the plane
    // rounding adds < 1/2 unit: within 1 LSB (measured 0).
    assert_within("enormous, full screen", &rep, 0, 1);

    // Edges crossing the screen at shallow angles, vertices at the I16F16 limits. The
    // reference snaps the far vertices, fixel snaps the guard-band cut points (4096 px
    // out): the edges differ by < 1/16 px over the screen, so a few pixels whose centres
    // lie that close to an edge may flip.
    let mut crossing = Vec::new();
    for (k, (a, b)) in [
        ((-m, -0.3), (m, 0.31)),
        ((-0.2, -m), (0.25, m)),
        ((-m, -m + 1.0), (m, m)),
        ((m, -m), (-m, m - 3.0)),
    ]
    .into_iter()
    .enumerate()
    {
        let far = if k % 2 == 0 { (-m, m) } else { (m, m) };
        crossing.push(tri(
            rv([a.0, a.1, 0.0, 1.0], [0.0, 0.0]),
            rv([b.0, b.1, 0.0, 1.0], [0.0, 0.0]),
            rv([far.0, far.1, 0.0, 1.0], [0.0, 0.0]),
        ));
    }
    for (k, t) in crossing.iter().enumerate() {
        let t = std::slice::from_ref(t);
        let c = check_ref(
            &format!("enormous crossing {k}"),
            t,
            None,
            &flat_mode(),
            W,
            H,
        );
        // Measured: cases 2 and 3 (45-degree edges 1.5e-5 off the diagonal, through a row
        // of pixel centres) differ on 8 pixels each; every differing centre is within 1/64 px of
        // the edge, below the 1/16 px snap of the guard-band cut points.
        assert_diff_on_edges("enormous crossing", t, &c, 1.0 / 64.0, W, H);
        assert!(c.diff.len() <= 8, "{}", c.rep);
    }
}

#[test]
fn coordinates_at_the_fixed_point_limits() {
    // Every combination of extreme I16F16 values in x, y, z, w: no panic, no out-of-bounds
    // write, in every projection and with a depth test.
    let vals = [
        -32768.0,
        -32767.99998474121,
        -1.0,
        -2.0f64.powi(-16),
        0.0,
        2.0f64.powi(-16),
        2.0f64.powi(-8),
        1.0,
        32767.99998474121,
    ];
    let mut rng = Rng(0xF1ED);
    let mut pick = || vals[(rng.next() % vals.len() as u64) as usize];
    let mut tris = Vec::new();
    for _ in 0..400 {
        let v = |p: &mut dyn FnMut() -> f64| rv([p(), p(), p(), p()], [p(), p()]);
        tris.push(tri(v(&mut pick), v(&mut pick), v(&mut pick)));
    }
    let clip = adapter::clip_triangles(&tris);
    let tex = noise_texture(8, 4, 1);
    for projection in [
        Projection::Affine,
        Projection::Exact,
        Projection::Subdivided { log2_n: 3 },
        Projection::Quadratic { log2_n: 4 },
    ] {
        for (shading, t) in [(Shading::Modulate, Some(&tex)), (Shading::Gouraud, None)] {
            let mode = DrawMode {
                projection,
                filter: Filter::Bilinear,
                wrap: [Wrap::ClampToBorder, Wrap::MirroredRepeat],
                shading,
                depth: DepthTest::Less,
                cull: Cull::None,
                ..DrawMode::default()
            };
            let (_g, n) = draw_guarded(&clip, t, mode, W, H);
            println!("limits {projection:?} {shading:?}: {n} pixels");
        }
    }
}

// ---------------------------------------------------------------------------------------
// Texture coordinates and sizes
// ---------------------------------------------------------------------------------------

/// The whole viewport as two triangles, with `uv` at the corners (top-left, top-right,
/// bottom-right, bottom-left) and clip `w` per corner (1 everywhere: affine geometry).
fn quad(uv: [[f64; 2]; 4], w: [f64; 4]) -> Vec<RefTriangle> {
    let p = [
        (0.0, 0.0),
        (W as f64, 0.0),
        (W as f64, H as f64),
        (0.0, H as f64),
    ];
    let v: Vec<_> = (0..4)
        .map(|k| {
            let mut v = at_px(p[k].0, p[k].1, 0.0, w[k], W, H);
            v.uv = uv[k].map(q16);
            v
        })
        .collect();
    vec![tri(v[0], v[3], v[2]), tri(v[0], v[2], v[1])]
}

fn uv_rect(u0: f64, v0: f64, u1: f64, v1: f64) -> [[f64; 2]; 4] {
    [[u0, v0], [u1, v0], [u1, v1], [u0, v1]]
}

const WRAPS: [RefWrap; 4] = [
    RefWrap::Repeat,
    RefWrap::MirroredRepeat,
    RefWrap::ClampToEdge,
    RefWrap::ClampToBorder,
];

fn tex_mode(p: RefProjection, f: RefFilter, wrap: RefWrap) -> RefMode {
    RefMode {
        projection: p,
        filter: f,
        wrap_u: wrap,
        wrap_v: wrap,
        depth_test: false,
        shading: RefShading::Replace,
        cull: RefCull::None,
        ..RefMode::default()
    }
}

/// The worst measured report over every wrap mode, for one filter and projection.
fn worst_over_wraps(
    name: &str,
    tris: &[RefTriangle],
    tex: &RefTexture,
    p: RefProjection,
    f: RefFilter,
) -> (u32, f64) {
    let (mut max, mut share) = (0, 0.0f64);
    for wrap in WRAPS {
        let c = check_ref(
            &format!("{name} {p:?} {f:?} {wrap:?}"),
            tris,
            Some(tex),
            &tex_mode(p, f, wrap),
            W,
            H,
        );
        assert!(c.diff.is_empty(), "{name}: coverage differs");
        max = max.max(c.rep.max);
        share = share.max(c.rep.share_over_2);
    }
    (max, share)
}

#[test]
fn huge_and_negative_uv_every_wrap_and_filter() {
    let tex = noise_texture(16, 16, 7);
    // w per corner for the perspective variant: a plane receding 4:1.
    let persp = [1.0, 1.0, 4.0, 4.0];
    for (name, uv) in [
        // Magnified (1/8 texel per pixel) thousands of periods away from 0.
        ("huge offset", uv_rect(1000.1, -2000.3, 1000.6, -1999.8)),
        ("negative", uv_rect(-2.5, -1.75, -1.5, -0.6)),
        ("straddling 0", uv_rect(-0.3, 0.4, 0.35, -0.2)),
    ] {
        for (p, w) in [
            (RefProjection::Affine, [1.0; 4]),
            (RefProjection::Perspective, persp),
        ] {
            let tris = quad(uv, w);
            let (bmax, _) = worst_over_wraps(name, &tris, &tex, p, RefFilter::Bilinear);
            // Bilinear is continuous: uv error ~2^-12 texel and Q8 weights keep it within
            // 1 LSB of the exact value (sampler's own bound); measured 1.
            assert!(bmax <= 2, "{name} {p:?} bilinear max {bmax}");
            let (_, nshare) = worst_over_wraps(name, &tris, &tex, p, RefFilter::Nearest);
            // Nearest flips texel only where the exact uv is within the interpolation error
            // of a texel boundary: measured 0 pixels over 2 LSB.
            assert!(
                nshare <= 0.002,
                "{name} {p:?} nearest share over 2 LSB {nshare}"
            );
        }
    }
}

#[test]
fn extreme_minification_thousands_of_repeats() {
    // 6000 repeats across 64 pixels (about 1500 texels per pixel) without mipmaps: every
    // pixel samples an essentially arbitrary texel, and a uv error of 2^-16 texel per pixel
    // of distance is enough to pick a different one. Colour is therefore not comparable;
    // this checks stability (no panic, no out-of-bounds write, coverage exact) and that the
    // clamp modes, which sample the edge or border everywhere outside [0, 1], still agree.
    let tex = noise_texture(16, 16, 9);
    for (p, w) in [
        (RefProjection::Affine, [1.0; 4]),
        (RefProjection::Perspective, [1.0, 2.0, 8.0, 3.0]),
    ] {
        let tris = quad(uv_rect(-3000.0, 2999.5, 3000.0, -3000.25), w);
        for f in [RefFilter::Nearest, RefFilter::Bilinear] {
            for wrap in WRAPS {
                let c = check_ref(
                    &format!("minified {p:?} {f:?} {wrap:?}"),
                    &tris,
                    Some(&tex),
                    &tex_mode(p, f, wrap),
                    W,
                    H,
                );
                assert!(c.diff.is_empty());
                if matches!(wrap, RefWrap::ClampToBorder) {
                    // Border everywhere except the few pixels whose uv is inside the texture.
                    assert!(c.rep.share_over_2 <= 0.01, "{}", c.rep);
                }
            }
        }
    }
}

#[test]
fn uv_exactly_on_texel_boundaries() {
    let tex = noise_texture(16, 16, 3);
    // Affine, w = 1: 2 texels per pixel, so every pixel centre lies exactly on a texel
    // boundary (u = 2x + 1): the nearest filter's floor() tie. The plane is exact here
    // (integer texel steps), so fixel must agree with the reference bit for bit.
    let tris = quad(uv_rect(0.0, 0.0, 8.0, 8.0), [1.0; 4]);
    for wrap in WRAPS {
        let c = check_ref(
            &format!("boundary ties {wrap:?}"),
            &tris,
            Some(&tex),
            &tex_mode(RefProjection::Affine, RefFilter::Nearest, wrap),
            W,
            H,
        );
        assert_eq!(c.rep.max, 0, "{wrap:?}");
    }
    // One texel per pixel: bilinear at exact texel centres (alpha = beta = 0) and
    // perspective mode with equal w (q = 1 exactly): the texels themselves.
    let tris = quad(uv_rect(-1.0, 3.0, 3.0, 7.0), [2.0; 4]);
    for wrap in WRAPS {
        for f in [RefFilter::Nearest, RefFilter::Bilinear] {
            for p in [RefProjection::Affine, RefProjection::Perspective] {
                let c = check_ref(
                    &format!("texel centres {wrap:?} {f:?} {p:?}"),
                    &tris,
                    Some(&tex),
                    &tex_mode(p, f, wrap),
                    W,
                    H,
                );
                assert_eq!(c.rep.max, 0, "{wrap:?} {f:?} {p:?}");
            }
        }
    }
}

#[test]
fn tiny_and_big_textures() {
    let persp = [1.0, 1.5, 5.0, 2.0];
    for (tw, th) in [(1, 1), (1, 64), (64, 1), (1024, 1024)] {
        let tex = noise_texture(tw, th, tw ^ (th << 8));
        for (p, w) in [
            (RefProjection::Affine, [1.0; 4]),
            (RefProjection::Perspective, persp),
        ] {
            // Slightly more than the texture, off the texel grid, so edges and borders are
            // sampled; for 1024 x 1024 that is 16:1 minification.
            let tris = quad(uv_rect(-0.1373, 1.0917, 1.0741, -0.0629), w);
            let name = format!("{tw}x{th}");
            let (bmax, _) = worst_over_wraps(&name, &tris, &tex, p, RefFilter::Bilinear);
            let (_, nshare) = worst_over_wraps(&name, &tris, &tex, p, RefFilter::Nearest);
            // Bilinear: measured 1 LSB (2 for 1024^2 perspective). Nearest: only boundary
            // flips, measured <= 0.122 % (64x1 perspective, 5 pixels) except 1024^2
            // perspective: the per-pixel reciprocal
            // has a relative error of 2^-16, so u = s / q is off by up to |u| 2^-16 texel,
            // and the periodic modes rebase u into [0, period) (here [884, 2124] texels for
            // Repeat and [1908, 3148] for MirroredRepeat): up to 0.05 texel, so a few % of
            // centres within that of a texel boundary flip (measured 0.95 % and 1.83 %).
            let nbound = if tw >= 1024 && p == RefProjection::Perspective {
                0.02
            } else {
                0.0015
            };
            assert!(bmax <= 2, "{name} {p:?} bilinear max {bmax}");
            assert!(nshare <= nbound, "{name} {p:?} nearest share {nshare}");
        }
    }
}

// ---------------------------------------------------------------------------------------
// Depth
// ---------------------------------------------------------------------------------------

const RED: [f64; 3] = [1.0, 0.0, 0.0];
const GREEN: [f64; 3] = [0.0, 1.0, 0.0];

fn depth_mode(p: RefProjection) -> RefMode {
    RefMode {
        projection: p,
        depth_test: true,
        ..gouraud()
    }
}

fn paint(t: &[RefTriangle], c: [f64; 3]) -> Vec<RefTriangle> {
    t.iter()
        .map(|t| RefTriangle(t.0.map(|v| coloured(v, c))))
        .collect()
}

/// Draws `first` red then `second` green with GL_LESS into a guarded target; returns how
/// many pixels are green.
fn green_pixels(first: &[RefTriangle], second: &[RefTriangle], p: RefProjection) -> usize {
    let mut all = paint(first, RED);
    all.extend(paint(second, GREEN));
    let clip = adapter::clip_triangles(&all);
    let (g, _) = draw_guarded(
        &clip,
        None,
        adapter::draw_mode(&depth_mode(p), None, false),
        W,
        H,
    );
    g.pixels().iter().filter(|&&c| c == 0x07E0).count()
}

#[test]
fn coplanar_second_triangle_does_not_overwrite() {
    let mut rng = Rng(0xC0_91A4);
    for k in 0..40 {
        let z = |r: &mut Rng| r.range(-0.99, 0.99);
        let wv = |r: &mut Rng| if k % 2 == 0 { 1.0 } else { r.range(0.5, 6.0) };
        let t: Vec<RefTriangle> = vec![tri(
            at_px(
                rng.range(-10.0, 74.0),
                rng.range(-10.0, 74.0),
                z(&mut rng),
                wv(&mut rng),
                W,
                H,
            ),
            at_px(
                rng.range(-10.0, 74.0),
                rng.range(-10.0, 74.0),
                z(&mut rng),
                wv(&mut rng),
                W,
                H,
            ),
            at_px(
                rng.range(-10.0, 74.0),
                rng.range(-10.0, 74.0),
                z(&mut rng),
                wv(&mut rng),
                W,
                H,
            ),
        )];
        for p in [RefProjection::Affine, RefProjection::Perspective] {
            // The same triangle again: identical depth at every pixel, GL_LESS fails.
            assert_eq!(green_pixels(&t, &t, p), 0, "triangle {k}");
            // The reference agrees (it keeps the first too).
            let both = [paint(&t, RED), paint(&t, GREEN)].concat();
            let c = check_ref("coplanar", &both, None, &depth_mode(p), W, H);
            assert!(c.diff.is_empty() && c.rep.max == 0, "{}", c.rep);
        }
    }
    // One planar quad split along the other diagonal: the same plane through different
    // triangles. Vertices on whole pixels (snapping is exact) and z from a plane with
    // dyadic coefficients (exact in I16F16 and in the 14-fraction-bit window depth), so
    // both triangulations describe exactly the same depth plane; only the per-triangle
    // plane set-up rounding differs. (With vertices off the 1/16 grid, snapping alone
    // bends a steep quad by many depth steps, in GL too.)
    let zp = |x: f64, y: f64| -0.5 + (x / 32.0 - 1.0) * 0.25 + (1.0 - y / 32.0) * 0.125;
    for w in [1.0, 2.0] {
        let q = [(3.0, 2.0), (61.0, 6.0), (58.0, 60.0), (1.0, 63.0)]
            .map(|(x, y)| at_px(x, y, zp(x, y), w, W, H));
        let first = vec![tri(q[0], q[1], q[2]), tri(q[0], q[2], q[3])];
        let second = vec![tri(q[1], q[2], q[3]), tri(q[1], q[3], q[0])];
        for p in [RefProjection::Affine, RefProjection::Perspective] {
            let g = green_pixels(&first, &second, p);
            println!("coplanar quad, other diagonal, w {w} {p:?}: {g} pixels overwritten");
            assert_eq!(g, 0);
        }
    }
}

#[test]
fn depth_at_the_near_and_far_planes() {
    // z = -w: depth 0, drawn; a second triangle there does not overwrite. z = w: depth 1.0,
    // which is not less than the cleared 1.0: nothing drawn (GL_LESS), on both sides.
    for w in [1.0, 3.0] {
        let at = |z: f64| {
            vec![tri(
                at_px(2.0, 2.0, z, w, W, H),
                at_px(62.0, 30.0, z, w, W, H),
                at_px(20.0, 61.0, z, w, W, H),
            )]
        };
        for p in [RefProjection::Affine, RefProjection::Perspective] {
            let near = at(-1.0);
            let c = check_ref("near plane depth", &near, None, &depth_mode(p), W, H);
            assert!(c.diff.is_empty() && c.rep.both_covered > 0);
            assert_eq!(green_pixels(&near, &near, p), 0);
            // (Not compared with the reference: its f64 barycentric depth is 1.0 give or take
            // an ulp, so it keeps a scatter of pixels; and the adapter's coverage mask is
            // taken without the depth test.)
            let far = adapter::clip_triangles(&at(1.0));
            let mode = adapter::draw_mode(&depth_mode(p), None, false);
            let (g, n) = draw_guarded(&far, None, mode, W, H);
            assert_eq!(n, 0);
            assert!(g.pixels().iter().all(|&c| c == 0));
            // Just inside the far plane: drawn.
            let inside = at(1.0 - 4.0 / 65535.0);
            let c = check_ref("inside far plane", &inside, None, &depth_mode(p), W, H);
            assert!(c.diff.is_empty() && c.rep.both_covered > 0);
        }
    }
}

#[test]
fn depth_precision_of_parallel_planes() {
    // Plane A tilted across the whole depth range (window depth 0.02 .. 0.98), plane B the
    // same shifted towards the viewer by `d` 16-bit steps, drawn second. B must win at every
    // pixel once d >= 1 step (depth is interpolated with 14 fraction bits and truncated:
    // floor(x - d) < floor(x) for d >= 1, up to the 2^-14-step rounding of the set-up).
    let lsb = 2.0 / 65535.0; // one 16-bit step in NDC z
    let plane = |d: f64, w: [f64; 3]| {
        vec![
            tri(
                at_px(-1.0, -1.0, -0.96 - d * lsb, w[0], W, H),
                at_px(65.0, -1.0, 0.0 - d * lsb, w[1], W, H),
                at_px(65.0, 65.0, 0.96 - d * lsb, w[2], W, H),
            ),
            tri(
                at_px(-1.0, -1.0, -0.96 - d * lsb, w[0], W, H),
                at_px(65.0, 65.0, 0.96 - d * lsb, w[2], W, H),
                at_px(-1.0, 65.0, 0.0 - d * lsb, w[1], W, H),
            ),
        ]
    };
    for (name, w) in [("affine", [1.0; 3]), ("perspective", [1.0, 2.5, 7.0])] {
        let a = plane(0.0, w);
        for d in [0.25, 0.5, 1.0, 1.01, 1.5, 2.0] {
            let g = green_pixels(&a, &plane(d, w), RefProjection::Perspective);
            println!(
                "{name}: separation {d} steps: plane B wins on {g} of {} pixels",
                W * H
            );
            if d >= 1.0 {
                // Measured: B wins everywhere from 1 step on, affine and perspective (w 1 to
                // 7); at 0.5 steps on about half the pixels (2016 and 2206 of 4096), at 0.25
                // on 1351 and 677: the 16-bit buffer resolves exactly one step.
                assert_eq!(g, W * H, "{name}, separation {d}");
            }
        }
    }
}

// ---------------------------------------------------------------------------------------
// Degenerate input
// ---------------------------------------------------------------------------------------

#[test]
fn degenerate_triangles_draw_nothing_in_any_mode() {
    let p = |x: f64, y: f64, w: f64| {
        let mut v = at_px(x, y, 0.2, w, W, H);
        v.uv = [x / 7.0, y / 5.0];
        v
    };
    let tris = vec![
        tri(p(10.0, 10.0, 1.0), p(10.0, 10.0, 1.0), p(10.0, 10.0, 1.0)), // a point
        tri(p(10.0, 10.0, 1.0), p(10.0, 10.0, 2.0), p(40.0, 30.0, 1.0)), // repeated
        tri(p(10.0, 10.0, 1.0), p(40.0, 30.0, 1.0), p(10.0, 10.0, 1.0)), // repeated
        tri(p(1.0, 1.0, 1.0), p(33.0, 33.0, 3.0), p(63.0, 63.0, 0.5)),   // collinear
        tri(p(0.0, 20.5, 1.0), p(64.0, 20.5, 2.0), p(30.0, 20.5, 1.0)),  // horizontal
        tri(p(31.5, 0.0, 1.0), p(31.5, 64.0, 1.0), p(31.5, 9.0, 4.0)),   // vertical
        // Collinear after snapping: off the line by less than 1/32 px.
        tri(p(2.0, 2.0, 1.0), p(60.0, 60.0, 1.0), p(31.0, 31.01, 1.0)),
        // Everything at the same clip-space point, w = 0 and w < 0.
        tri(
            rv([0.0; 4], [0.0; 2]),
            rv([0.0; 4], [1.0; 2]),
            rv([0.0; 4], [0.5; 2]),
        ),
        tri(
            rv([1.0, 1.0, 1.0, -1.0], [0.0; 2]),
            rv([1.0, 1.0, 1.0, -1.0], [0.0; 2]),
            rv([2.0, 2.0, 2.0, -1.0], [0.0; 2]),
        ),
    ];
    let clip = adapter::clip_triangles(&tris);
    let tex = noise_texture(4, 4, 5);
    for projection in [
        Projection::Affine,
        Projection::Exact,
        Projection::Subdivided { log2_n: 4 },
        Projection::Quadratic { log2_n: 5 },
    ] {
        for filter in [Filter::Nearest, Filter::Bilinear] {
            for (shading, t) in [
                (Shading::Replace, Some(&tex)),
                (Shading::Modulate, Some(&tex)),
                (Shading::ModulateIntensity, Some(&tex)),
                (Shading::Gouraud, None),
                (Shading::Flat, None),
            ] {
                for depth in [DepthTest::Off, DepthTest::Less] {
                    let mode = DrawMode {
                        projection,
                        filter,
                        wrap: [Wrap::Repeat, Wrap::ClampToBorder],
                        shading,
                        depth,
                        cull: Cull::None,
                        ..DrawMode::default()
                    };
                    let (g, n) = draw_guarded(&clip, t, mode, W, H);
                    assert_eq!(n, 0, "{mode:?}");
                    assert!(g.pixels().iter().all(|&c| c == 0));
                    assert!(g.depths().iter().all(|&d| d == 0xFFFF));
                }
            }
        }
    }
    let r = reference::render(&tris, None, &flat_mode(), W as u32, H as u32);
    assert_eq!(r.covered_count(), 0);
}
