//! Clipping: triangles crossing the near plane, a vertex at w near zero, triangles entirely
//! behind the camera, and enormous triangles far outside the guard band.

use crate::common::*;
use crate::helpers::*;
use host_tests::adapter;
use host_tests::reference::{self, RefProjection};

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
