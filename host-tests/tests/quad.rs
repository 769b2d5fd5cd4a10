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
