//! Projective quads (`fixel::geometry::Homography`, `fixel::scene::draw_quad`) against the
//! f64 reference (`host_tests::reference::quad`): the fixed-point homography and its
//! inverse, the drawn quad against the reference render, and the refused and far-off
//! quads.

use embedded_graphics_core::pixelcolor::raw::RawData;
use fixel::geometry::Homography;
use fixel::math::Fx;
use fixel::pipeline::{Draw, DrawMode, Projection};
use fixel::scene::draw_quad;
use fixel::texture::Texture;
use fixel::Error;
use host_tests::adapter;
use host_tests::metrics::compare;
use host_tests::reference::{self, quad, RefCull, RefMode};
use host_tests::scenes::procedural_texture;
use proptest::prelude::*;

const W: u32 = 320;
const H: u32 = 240;

fn fxp(p: [[f64; 2]; 4]) -> [[Fx; 2]; 4] {
    p.map(|c| c.map(Fx::from_num))
}

/// A card (a rectangle in 3D) rotated about x and y and projected: a convex quad with
/// real perspective.
fn card(ax: f64, ay: f64, dist: f64, cx: f64, cy: f64) -> [[f64; 2]; 4] {
    [(-1.0, -0.75), (1.0, -0.75), (1.0, 0.75), (-1.0, 0.75)].map(|(x, y)| {
        let (sx, cxr) = ax.sin_cos();
        let (sy, cyr) = ay.sin_cos();
        // Ry then Rx, then pushed back along -z.
        let (x1, z1) = (x * cyr, -x * sy);
        let (y2, z2) = (y * cxr - z1 * sx, y * sx + z1 * cxr);
        let z = z2 - dist;
        let f = 200.0 / -z;
        [cx + x1 * f, cy - y2 * f]
    })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(500))]
    /// The fixed-point map within 1/64 pixel and its inverse within 2^-12 texture of f64.
    #[test]
    fn homography_and_inverse_within_budget(
        ax in -1.2f64..1.2, ay in -1.2f64..1.2, dist in 1.6f64..8.0,
        cx in 60.0f64..260.0, cy in 40.0f64..200.0, u in 0.0f64..1.0, v in 0.0f64..1.0,
    ) {
        let p = card(ax, ay, dist, cx, cy);
        let (h, _) = Homography::square_to_quad(fxp(p)).unwrap();
        // The reference from the same (rounded) corners.
        let pr = fxp(p).map(|c| c.map(|x| x.to_num::<f64>()));
        let href = quad::square_to_quad(pr).unwrap();
        let got = h.map(Fx::from_num(u), Fx::from_num(v)).unwrap();
        let want = quad::map(&href, u, v);
        for k in 0..2 {
            prop_assert!((got[k].to_num::<f64>() - want[k]).abs() < 1.0 / 64.0, "{got:?} {want:?}");
        }
        let back = h.inverse().map(Fx::from_num(want[0]), Fx::from_num(want[1])).unwrap();
        let uv = quad::map(&quad::inverse(&href), want[0], want[1]);
        prop_assert!((uv[0] - u).abs() < 1e-9 && (uv[1] - v).abs() < 1e-9);
        for k in 0..2 {
            prop_assert!((back[k].to_num::<f64>() - uv[k]).abs() < 1.0 / 4096.0, "{back:?} {uv:?}");
        }
    }
}

fn render_both(p: [[f64; 2]; 4], projection: Projection) -> host_tests::metrics::Report {
    let rt = procedural_texture(128, 128);
    let mode = RefMode {
        cull: RefCull::None,
        depth_test: false,
        ..RefMode::default()
    };
    let pr = fxp(p).map(|c| c.map(|x| x.to_num::<f64>()));
    let tris = quad::triangles(pr, f64::from(W), f64::from(H)).unwrap();
    let reference = reference::render(&tris, Some(&rt), &mode, W, H);
    let texels = adapter::texels(&rt);
    let tex = Texture::new(&texels, 128, 128).unwrap();
    let dm: DrawMode = adapter::draw_mode(&mode, Some(projection), false);
    let draw = Draw::dynamic(
        dm,
        Some(tex),
        fixel::geometry::Viewport::new(0, 0, W, H).unwrap(),
    )
    .unwrap();
    let (mut px, mut cov) = (
        vec![fixel::Rgb565::new(0, 0, 0); (W * H) as usize],
        vec![false; (W * H) as usize],
    );
    let mut frame = fixel::surface::Frame::new(&mut px, W, H).unwrap();
    frame.clear(fixel::Rgb565::new(0, 0, 0));
    draw_quad(&draw, fxp(p), &mut frame).unwrap();
    // Coverage: a second pass in white over a cleared frame.
    let white = [fixel::Rgb565::new(31, 63, 31)];
    let wt = Texture::new(&white, 1, 1).unwrap();
    let wdraw = Draw::dynamic(
        dm,
        Some(wt),
        fixel::geometry::Viewport::new(0, 0, W, H).unwrap(),
    )
    .unwrap();
    let mut mask = vec![fixel::Rgb565::new(0, 0, 0); (W * H) as usize];
    let mut mframe = fixel::surface::Frame::new(&mut mask, W, H).unwrap();
    draw_quad(&wdraw, fxp(p), &mut mframe).unwrap();
    for (c, m) in cov.iter_mut().zip(&mask) {
        *c = *m != fixel::Rgb565::new(0, 0, 0);
    }
    let raw: Vec<u16> = px
        .iter()
        .map(|c| embedded_graphics_core::pixelcolor::raw::RawU16::from(*c).into_inner())
        .collect();
    compare(&raw, &cov, &reference)
}

/// A strongly foreshortened card, drawn exact: within the exact-bilinear budget of the
/// benchmark scenes against the reference's hyperbolic interpolation of the f64 map.
/// Affine (the classic two-triangle seam) is far off.
#[test]
fn drawn_quad_matches_the_reference() {
    let p = card(1.05, 0.35, 2.2, 160.0, 120.0);
    let exact = render_both(p, Projection::Exact);
    println!("quad, exact: {exact}");
    assert!(
        exact.p99 <= 1 && exact.max <= 4 && exact.psnr_db > 40.0,
        "{exact}"
    );
    let covered = exact.only_candidate + exact.only_reference;
    assert!(covered * 1000 <= exact.both_covered, "{exact}");
    let affine = render_both(p, Projection::Affine);
    println!("quad, affine: {affine}");
    assert!(
        affine.psnr_db + 6.0 < exact.psnr_db,
        "affine should show the seam: {affine}"
    );
}

#[test]
fn degenerate_quads_are_refused() {
    let q = |p: [[f64; 2]; 4]| Homography::square_to_quad(fxp(p)).map(|_| ());
    // Three collinear corners (p1 on the segment p0-p2).
    assert_eq!(
        q([[0.0, 0.0], [10.0, 0.0], [20.0, 0.0], [0.0, 10.0]]),
        Err(Error::BadQuad("three corners are collinear"))
    );
    // A bow-tie: p2 and p3 swapped.
    assert_eq!(
        q([[0.0, 0.0], [10.0, 0.0], [0.0, 10.0], [10.0, 10.0]]),
        Err(Error::BadQuad("the corners cross (a bow-tie)"))
    );
    // Concave: p2 pushed inside.
    assert_eq!(
        q([[0.0, 0.0], [10.0, 0.0], [3.0, 3.0], [0.0, 10.0]]),
        Err(Error::BadQuad("the quad is concave"))
    );
    // All four corners on one point.
    assert!(q([[5.0, 5.0]; 4]).is_err());
    // Both windings are fine.
    assert!(q([[0.0, 0.0], [0.0, 10.0], [10.0, 10.0], [10.0, 0.0]]).is_ok());
}

/// Corners thousands of pixels off screen: drawn (the visible part), no panic, and the
/// pixels match the reference.
#[test]
fn quad_far_off_screen() {
    let p = [
        [-3000.0, -2000.0],
        [400.0, -50.0],
        [300.0, 200.0],
        [-20000.0, 30000.0],
    ];
    let rep = render_both(p, Projection::Exact);
    println!("far quad: {rep}");
    assert!(rep.both_covered > 10_000 && rep.p99 <= 2, "{rep}");
}

/// Pixels of a `w` x `h` frame written by `draw_quad` in white over black, with viewport
/// `vp` (x0, y0, width, height); `None` when the quad is refused.
fn coverage(p: [[Fx; 2]; 4], w: u32, h: u32, vp: (u32, u32, u32, u32)) -> Option<Vec<bool>> {
    let white = [fixel::Rgb565::new(31, 63, 31)];
    let tex = Texture::new(&white, 1, 1).unwrap();
    let mode = DrawMode {
        projection: Projection::Exact,
        shading: fixel::pipeline::Shading::Replace,
        cull: fixel::geometry::Cull::None,
        depth: fixel::pipeline::DepthTest::Off,
        ..DrawMode::default()
    };
    let viewport = fixel::geometry::Viewport::new(vp.0, vp.1, vp.2, vp.3).unwrap();
    let draw = Draw::dynamic(mode, Some(tex), viewport).unwrap();
    let mut px = vec![fixel::Rgb565::new(0, 0, 0); (w * h) as usize];
    let mut frame = fixel::surface::Frame::new(&mut px, w, h).unwrap();
    let n = draw_quad(&draw, p, &mut frame).ok()?;
    let cov: Vec<bool> = px
        .iter()
        .map(|c| *c != fixel::Rgb565::new(0, 0, 0))
        .collect();
    assert_eq!(n as usize, cov.iter().filter(|&&c| c).count());
    Some(cov)
}

/// Compares `draw_quad`'s coverage with the pixel centres inside the quad (f64 edge
/// functions of the rounded corners) within the viewport: every centre more than 1/8
/// pixel inside is written, nothing more than that outside is (the raster snaps corners to
/// 1/16 pixel). Returns the
/// pixels written and the count inside.
fn check_coverage(p: [[Fx; 2]; 4], w: u32, h: u32, vp: (u32, u32, u32, u32)) -> (usize, usize) {
    let cov = coverage(p, w, h, vp).expect("a convex quad is drawn");
    let c = p.map(|k| k.map(|v| v.to_num::<f64>()));
    let area2: f64 = (0..4)
        .map(|k| c[k][0] * c[(k + 1) % 4][1] - c[(k + 1) % 4][0] * c[k][1])
        .sum();
    let s = area2.signum();
    let (mut written, mut inside) = (0, 0);
    for y in 0..h {
        for x in 0..w {
            let (px, py) = (f64::from(x) + 0.5, f64::from(y) + 0.5);
            let in_vp = x >= vp.0 && x < vp.0 + vp.2 && y >= vp.1 && y < vp.1 + vp.3;
            // Signed distance of the centre to each edge, positive inside.
            let d = (0..4)
                .map(|k| {
                    let (a, b) = (c[k], c[(k + 1) % 4]);
                    let (ex, ey) = (b[0] - a[0], b[1] - a[1]);
                    s * (ex * (py - a[1]) - ey * (px - a[0])) / ex.hypot(ey)
                })
                .fold(f64::INFINITY, f64::min);
            let got = cov[(y * w + x) as usize];
            written += usize::from(got);
            if in_vp && d > EDGE {
                inside += 1;
                assert!(
                    got,
                    "pixel ({x}, {y}) inside the quad by {d} is not drawn: {p:?}"
                );
            }
            if !in_vp || d < -EDGE {
                assert!(!got, "pixel ({x}, {y}) outside by {d} is drawn: {p:?}");
            }
        }
    }
    (written, inside)
}

/// How far from an edge a pixel centre must be for its coverage to be certain, pixels.
const EDGE: f64 = 0.125;

fn bits(p: [[i32; 2]; 4]) -> [[Fx; 2]; 4] {
    p.map(|c| c.map(Fx::from_bits))
}

/// A quad covering the whole viewport whose corner weights span more than the clip-space
/// `w` range: drawn whole (it drew nothing when the weights went into clip space before
/// clipping).
#[test]
fn quad_with_a_tiny_corner_weight_covers_the_viewport() {
    let p = bits([
        [1987302982, 1152181155],
        [1106930555, 1050351317],
        [-973093556, 809530851],
        [-2109929551, -2059735825],
    ]);
    let cov = coverage(p, 40, 30, (3, 2, 32, 24)).unwrap();
    assert_eq!(cov.iter().filter(|&&c| c).count(), 768);
    check_coverage(p, 40, 30, (3, 2, 32, 24));
}

/// A quad with one corner one bit off the diagonal of the other three (nearly a triangle
/// of 384 square pixels): every pixel inside is drawn.
#[test]
fn nearly_triangular_quad_draws_its_area() {
    let p = bits([
        [196608, 131072],
        [2293760, 131072],
        [1209939, 943938],
        [196608, 1703936],
    ]);
    let (written, inside) = check_coverage(p, 40, 30, (0, 0, 40, 30));
    assert!(
        (inside as i64 - 384).abs() <= 24 && written >= inside,
        "{written} {inside}"
    );
}

/// Corners near the I16F16 limits and nearly collinear, whose 62-bit map took corner 3 to
/// (16384.5, 0.002) instead of (32768, 0.0039): refused, not mapped wrong.
#[test]
fn quad_too_extreme_for_the_map_is_refused() {
    let p = bits([
        [65535, i32::MIN],
        [-i32::MAX, -1],
        [-i32::MAX, 1],
        [i32::MAX, 256],
    ]);
    let r = Homography::square_to_quad(p);
    assert!(
        matches!(r, Err(Error::BadQuad(why)) if why.contains("too extreme")),
        "{r:?}"
    );
}

/// Four points sorted by angle about their centroid: a simple quad, convex most of the time.
fn sorted_quad(mut p: [[i32; 2]; 4]) -> [[Fx; 2]; 4] {
    let c = p.iter().fold([0f64; 2], |a, q| {
        [a[0] + f64::from(q[0]), a[1] + f64::from(q[1])]
    });
    let ang = |q: &[i32; 2]| (f64::from(q[1]) - c[1] / 4.0).atan2(f64::from(q[0]) - c[0] / 4.0);
    p.sort_by(|a, b| ang(a).total_cmp(&ang(b)));
    bits(p)
}

/// A coordinate in I16F16 bits: on screen, near it, or anywhere in the format.
fn coord() -> impl Strategy<Value = i32> {
    prop_oneof![
        -(4 << 16)..(70 << 16),
        -(2000 << 16)..(2000 << 16),
        i32::MIN..=i32::MAX,
    ]
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(400))]
    /// Any convex quad `square_to_quad` accepts draws every pixel whose centre it covers
    /// within the viewport, and nothing outside it or the viewport.
    #[test]
    fn convex_quad_draws_its_area(p in prop::array::uniform4([coord(), coord()]),
                                  vx in 0u32..8, vy in 0u32..8, vw in 1u32..56, vh in 1u32..40) {
        let q = sorted_quad(p);
        // Refused only as too extreme for the forward map; drawn through the inverse.
        match coverage(q, 64, 48, (vx, vy, vw, vh)) {
            Some(_) => { check_coverage(q, 64, 48, (vx, vy, vw, vh)); }
            None => prop_assert!(matches!(Homography::square_to_quad(q), Err(Error::BadQuad(_)))),
        }
    }

    /// A corner a few bits off the diagonal through its neighbours (nearly a triangle, a
    /// corner weight far below the others): still drawn whole.
    #[test]
    fn nearly_triangular_quads_draw_their_area(
        a in prop::array::uniform2(-(8 << 16)..(72i32 << 16)),
        b in prop::array::uniform2(-(8 << 16)..(72i32 << 16)),
        d in prop::array::uniform2(-(8 << 16)..(72i32 << 16)),
        t in 0.05f64..0.95, off in 1i32..64, vw in 1u32..64, vh in 1u32..48,
    ) {
        // Corner 2 on segment b-d, pushed `off` bits away from a.
        let m = [0, 1].map(|k| f64::from(b[k]) + t * f64::from(d[k] - b[k]));
        let n = [f64::from(d[1] - b[1]), -f64::from(d[0] - b[0])];
        let side = (m[0] - f64::from(a[0])) * n[0] + (m[1] - f64::from(a[1])) * n[1];
        let len = n[0].hypot(n[1]).max(1.0);
        let k = side.signum() * f64::from(off) / len;
        let c = [0, 1].map(|i| (m[i] + k * n[i]).round() as i32);
        let q = bits([a, b, c, d]);
        prop_assume!(Homography::square_to_quad(q).is_ok());
        check_coverage(q, 64, 48, (0, 0, vw, vh));
    }

    /// Accepted quads anywhere in I16F16 take the square's corners to theirs and back
    /// within `CORNER_TOLERANCE`.
    #[test]
    fn accepted_maps_hold_their_corners(p in prop::array::uniform4([coord(), coord()])) {
        let q = sorted_quad(p);
        let Ok((h, _)) = Homography::square_to_quad(q) else { return Ok(()) };
        let tol = fixel::geometry::CORNER_TOLERANCE.to_bits().unsigned_abs();
        let inv = h.inverse();
        let square = [[0, 0], [1, 0], [1, 1], [0, 1]].map(|c: [i32; 2]| c.map(Fx::from_num));
        for (uv, c) in square.iter().zip(q) {
            let img = h.map(uv[0], uv[1]).unwrap();
            let back = inv.map(c[0], c[1]).unwrap();
            for k in 0..2 {
                prop_assert!(img[k].to_bits().abs_diff(c[k].to_bits()) <= tol, "{img:?} {c:?}");
                prop_assert!(back[k].to_bits().abs_diff(uv[k].to_bits()) <= tol, "{back:?} {uv:?}");
            }
        }
    }
}
