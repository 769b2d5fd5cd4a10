//! Tests that prove the f64 reference renderer itself right: exact coverage
//! (shared edges, top-left ties, orientation independence), near-plane
//! clipping, perspective-correct interpolation against an analytic plane,
//! and the GL ES wrap and filter rules on hand-computed indices.

use host_tests::reference::sample::{sample, wrap_index};
use host_tests::reference::{
    render, RefCull, RefFilter, RefMode, RefProjection, RefShading, RefTexture, RefTriangle,
    RefVertex, RefWrap,
};

/// A vertex given in window coordinates (y down) of a `size x size`
/// viewport, with w = 1. Exact in f64 for power-of-two sizes.
fn win(x: f64, y: f64, size: u32) -> RefVertex {
    let s = f64::from(size);
    RefVertex {
        clip: [2.0 * x / s - 1.0, 1.0 - 2.0 * y / s, 0.0, 1.0],
        uv: [0.0; 2],
        color: [1.0; 3],
    }
}

fn tri(p: [(f64, f64); 3], size: u32) -> RefTriangle {
    RefTriangle(p.map(|(x, y)| win(x, y, size)))
}

fn flat_mode() -> RefMode {
    RefMode {
        depth_test: false,
        shading: RefShading::Flat([1.0; 3]),
        cull: RefCull::None,
        ..RefMode::default()
    }
}

/// How many of the given triangles cover each pixel (each rendered alone).
fn coverage_counts(tris: &[RefTriangle], size: u32) -> Vec<u32> {
    let mut counts = vec![0; (size * size) as usize];
    for t in tris {
        let img = render(&[*t], None, &flat_mode(), size, size);
        for (c, &cov) in counts.iter_mut().zip(&img.covered) {
            *c += u32::from(cov);
        }
    }
    counts
}

#[test]
fn full_viewport_quad_covers_every_pixel_exactly_once() {
    let s = 32;
    let (a, b, c, d) = ((0.0, 0.0), (32.0, 0.0), (32.0, 32.0), (0.0, 32.0));
    let counts = coverage_counts(&[tri([a, b, c], s), tri([a, c, d], s)], s);
    assert!(counts.iter().all(|&c| c == 1));
}

#[test]
fn irregular_quad_shares_its_diagonal_without_gaps_or_overlap() {
    let s = 32;
    let q = [(3.3, 2.1), (28.7, 5.4), (25.2, 29.9), (1.6, 20.05)];
    let counts = coverage_counts(&[tri([q[0], q[1], q[2]], s), tri([q[0], q[2], q[3]], s)], s);
    assert!(counts.iter().all(|&c| c <= 1), "a pixel covered twice");
    // Every centre strictly inside the (snapped) quad is covered.
    let sn = |v: f64| (v * 16.0 + 0.5).floor() / 16.0;
    let q = q.map(|(x, y)| (sn(x), sn(y)));
    for py in 0..s {
        for px in 0..s {
            let (cx, cy) = (f64::from(px) + 0.5, f64::from(py) + 0.5);
            let inside = (0..4).all(|i| {
                let (a, b) = (q[i], q[(i + 1) % 4]);
                (b.0 - a.0) * (cy - a.1) - (b.1 - a.1) * (cx - a.0) > 0.0
            });
            if inside {
                assert_eq!(counts[(py * s + px) as usize], 1, "hole at {px},{py}");
            }
        }
    }
    let total: u32 = counts.iter().sum();
    println!("irregular quad covers {total} pixels");
}

#[test]
fn fan_with_edges_through_pixel_centres_tiles_exactly() {
    // Eight triangles around (16.5, 16.5); every edge runs through pixel
    // centres (horizontal, vertical, diagonal), so every edge has ties.
    let s = 32;
    let c = (16.5, 16.5);
    let ring = [
        (4.5, 4.5),
        (16.5, 4.5),
        (28.5, 4.5),
        (28.5, 16.5),
        (28.5, 28.5),
        (16.5, 28.5),
        (4.5, 28.5),
        (4.5, 16.5),
    ];
    let tris: Vec<_> = (0..8)
        .map(|i| tri([c, ring[i], ring[(i + 1) % 8]], s))
        .collect();
    let counts = coverage_counts(&tris, s);
    for py in 0..s {
        for px in 0..s {
            // Top and left edges of the square are in, bottom and right out.
            let want = u32::from((4..28).contains(&px) && (4..28).contains(&py));
            assert_eq!(counts[(py * s + px) as usize], want, "pixel {px},{py}");
        }
    }
}

#[test]
fn top_left_rule_on_ties_with_vertices_on_pixel_centres() {
    let s = 16;
    // Upper-left triangle: top edge y = 0.5 and left edge x = 0.5 are in,
    // the hypotenuse x + y = 5 (a right/bottom edge) is out.
    let upper = tri([(0.5, 0.5), (4.5, 0.5), (0.5, 4.5)], s);
    // Lower-right triangle: the hypotenuse is its left edge (in); its right
    // edge x = 4.5 and bottom edge y = 4.5 are out.
    let lower = tri([(4.5, 0.5), (4.5, 4.5), (0.5, 4.5)], s);
    for (t, want) in [
        (upper, (|x: u32, y: u32| x + y <= 3) as fn(u32, u32) -> bool),
        (lower, |x: u32, y: u32| x < 4 && y < 4 && x + y >= 4),
    ] {
        let rev = RefTriangle([t.0[0], t.0[2], t.0[1]]);
        for t in [t, rev] {
            let img = render(&[t], None, &flat_mode(), s, s);
            for y in 0..s {
                for x in 0..s {
                    assert_eq!(img.covered[(y * s + x) as usize], want(x, y), "{x},{y}");
                }
            }
        }
    }
    let counts = coverage_counts(&[upper, lower], s);
    assert_eq!(counts.iter().filter(|&&c| c == 1).count(), 16);
    assert!(counts.iter().all(|&c| c <= 1));
}

#[test]
fn culling_follows_gl_front_face_ccw() {
    let s = 16;
    // Counter-clockwise in NDC (y up) = clockwise in window y-down terms:
    // (2,14) -> (14,14) -> (8,2) goes right along the bottom, then up.
    let front = tri([(2.0, 14.0), (14.0, 14.0), (8.0, 2.0)], s);
    let back = RefTriangle([front.0[0], front.0[2], front.0[1]]);
    let mode = |cull| RefMode {
        cull,
        ..flat_mode()
    };
    let n = |t, cull| render(&[t], None, &mode(cull), s, s).covered_count();
    assert!(n(front, RefCull::Back) > 0);
    assert_eq!(n(front, RefCull::Front), 0);
    assert_eq!(n(back, RefCull::Back), 0);
    assert_eq!(n(back, RefCull::Front), n(front, RefCull::Back));
}

/// Plane y_e = -1 seen with f = 1 (90 degree fovy), aspect 1, near 0.5,
/// far 10: window coordinates of its vertices are exact multiples of 1/16.
fn plane_vertex(x_e: f64, z_e: f64) -> RefVertex {
    let (n, f) = (0.5, 10.0);
    let (a, b) = ((f + n) / (n - f), 2.0 * f * n / (n - f));
    RefVertex {
        clip: [x_e, -1.0, a * z_e + b, -z_e],
        uv: [0.0, -z_e],
        color: [-z_e / 4.0, 0.0, 0.0],
    }
}

fn window_depth(z_e: f64) -> f64 {
    let (n, f) = (0.5, 10.0);
    let (a, b) = ((f + n) / (n - f), 2.0 * f * n / (n - f));
    ((a * z_e + b) / -z_e + 1.0) / 2.0
}

#[test]
fn perspective_interpolation_matches_the_analytic_plane() {
    let s = 64;
    let (a, b) = (plane_vertex(-1.0, -1.0), plane_vertex(1.0, -1.0));
    let (c, d) = (plane_vertex(4.0, -4.0), plane_vertex(-4.0, -4.0));
    let tris = [RefTriangle([a, b, c]), RefTriangle([a, c, d])];
    let mode = |projection| RefMode {
        projection,
        shading: RefShading::Gouraud,
        cull: RefCull::Back,
        ..RefMode::default()
    };
    let img = render(&tris, None, &mode(RefProjection::Perspective), s, s);
    let affine = render(&tris, None, &mode(RefProjection::Affine), s, s);
    // The trapezoid spans rows 40..64 (y_w from 40 to 64) and all columns.
    assert_eq!(img.covered_count(), 64 * 24);
    let mut worst_affine: f64 = 0.0;
    for py in 40..s {
        let y_ndc = 1.0 - 2.0 * (f64::from(py) + 0.5) / f64::from(s);
        let z_e = 1.0 / y_ndc; // y_ndc = y_e / -z_e with y_e = -1.
        for px in 0..s {
            let k = (py * s + px) as usize;
            assert!(img.covered[k]);
            let got = img.rgb[k][0];
            let want = -z_e / 4.0;
            assert!((got - want).abs() < 1e-12, "{px},{py}: {got} vs {want}");
            let dz = img.depth[k] - window_depth(z_e);
            assert!(dz.abs() < 1e-12, "depth {px},{py}: {dz}");
            worst_affine = worst_affine.max((affine.rgb[k][0] - want).abs());
        }
    }
    assert!(
        worst_affine > 0.05,
        "affine should visibly differ: {worst_affine}"
    );
}

#[test]
fn near_plane_clipping_keeps_exactly_the_visible_part() {
    // The plane runs from behind the camera (z_e = +5) to z_e = -8; its far
    // edge is at y_ndc = -1/8 -> y_w = 36 (on the snap grid, so the screen
    // geometry is exactly the analytic one).
    let s = 64;
    let (a, b) = (plane_vertex(-100.0, 5.0), plane_vertex(100.0, 5.0));
    let (c, d) = (plane_vertex(100.0, -8.0), plane_vertex(-100.0, -8.0));
    let tris = [RefTriangle([a, b, c]), RefTriangle([a, c, d])];
    let mode = RefMode {
        shading: RefShading::Gouraud,
        cull: RefCull::None,
        ..RefMode::default()
    };
    let img = render(&tris, None, &mode, s, s);
    for py in 0..s {
        for px in 0..s {
            assert_eq!(img.covered[(py * s + px) as usize], py >= 36, "{px},{py}");
        }
    }
    // Bottom row: y_ndc = -63/64, z_e = -64/63; colour -z_e / 4.
    let got = img.rgb[(63 * s) as usize][0];
    assert!((got - 64.0 / 63.0 / 4.0).abs() < 1e-12, "{got}");
}

#[test]
fn wrap_modes_on_hand_computed_indices() {
    use RefWrap::*;
    type Cases = [(i64, Option<u32>); 7];
    let cases: [(RefWrap, Cases); 4] = [
        (
            Repeat,
            [
                (-5, Some(3)),
                (-1, Some(3)),
                (0, Some(0)),
                (3, Some(3)),
                (4, Some(0)),
                (9, Some(1)),
                (-8, Some(0)),
            ],
        ),
        (
            MirroredRepeat,
            [
                (-1, Some(0)),
                (-4, Some(3)),
                (-5, Some(3)),
                (4, Some(3)),
                (7, Some(0)),
                (9, Some(1)),
                (-8, Some(0)),
            ],
        ),
        (
            ClampToEdge,
            [
                (-3, Some(0)),
                (-1, Some(0)),
                (0, Some(0)),
                (3, Some(3)),
                (4, Some(3)),
                (9, Some(3)),
                (2, Some(2)),
            ],
        ),
        (
            ClampToBorder,
            [
                (-3, None),
                (-1, None),
                (0, Some(0)),
                (3, Some(3)),
                (4, None),
                (9, None),
                (2, Some(2)),
            ],
        ),
    ];
    for (mode, pairs) in cases {
        for (i, want) in pairs {
            assert_eq!(wrap_index(i, 4, mode), want, "{mode:?} {i}");
        }
    }
}

#[test]
fn nearest_and_bilinear_follow_gl_es_texel_centres() {
    // 2x2: red, green / blue, white; border black.
    let (r, g, b, w) = (0xf800u16, 0x07e0, 0x001f, 0xffff);
    let tex = RefTexture {
        width: 2,
        height: 2,
        texels: vec![r, g, b, w],
        border: 0,
    };
    use RefFilter::*;
    use RefWrap::*;
    let s = |uv, f, wrap| sample(&tex, uv, f, wrap, wrap);
    assert_eq!(s([0.25, 0.25], Nearest, Repeat), [1.0, 0.0, 0.0]);
    assert_eq!(s([0.75, 0.25], Nearest, Repeat), [0.0, 1.0, 0.0]);
    assert_eq!(s([0.25, 0.75], Nearest, Repeat), [0.0, 0.0, 1.0]);
    assert_eq!(s([1.25, -0.25], Nearest, Repeat), [0.0, 0.0, 1.0]);
    assert_eq!(s([1.25, 0.25], Nearest, ClampToBorder), [0.0; 3]);
    // Bilinear at a texel centre is that texel.
    assert_eq!(s([0.25, 0.25], Bilinear, Repeat), [1.0, 0.0, 0.0]);
    // Halfway between red and green.
    assert_eq!(s([0.5, 0.25], Bilinear, Repeat), [0.5, 0.5, 0.0]);
    // u = 0: i0 = -1, alpha = 0.5: repeat blends green into red, clamp
    // gives red, border blends black.
    assert_eq!(s([0.0, 0.25], Bilinear, Repeat), [0.5, 0.5, 0.0]);
    assert_eq!(s([0.0, 0.25], Bilinear, ClampToEdge), [1.0, 0.0, 0.0]);
    assert_eq!(s([0.0, 0.25], Bilinear, ClampToBorder), [0.5, 0.0, 0.0]);
    assert_eq!(s([0.0, 0.25], Bilinear, MirroredRepeat), [1.0, 0.0, 0.0]);
    // Centre of the texture: the average of all four.
    assert_eq!(s([0.5, 0.5], Bilinear, Repeat), [0.5, 0.5, 0.5]);
}
