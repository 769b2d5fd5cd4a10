//! Slivers and needles, fill-rule ties, fans and strips: coverage exactly the reference's,
//! and every pixel of a closed mesh written exactly once.

use crate::common::*;
use crate::helpers::*;
use fixel::geometry::Cull;
use host_tests::adapter;
use host_tests::reference::{RefShading, RefTriangle};

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
