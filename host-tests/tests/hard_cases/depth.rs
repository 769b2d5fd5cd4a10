//! Depth: a coplanar second triangle does not overwrite, depth at the near and far planes,
//! and the precision that separates parallel planes.

use crate::common::*;
use crate::helpers::*;
use host_tests::adapter;
use host_tests::reference::{RefMode, RefProjection, RefTriangle};

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

/// A triangle clipped at the far plane with clip coordinates near the I16F16 limits, drawn
/// with `GL_LESS` into a depth buffer cleared to 65535: its depth plane steps by more than
/// 2^30 per pixel, so the depth wraps within a 32-pixel chunk. No pixel whose depth is not
/// below the stored 65535 may be written: the same picture as over a buffer whose floor is
/// unknown (`with_depth_kept`), and nothing written where the stored depth is not beaten.
#[test]
fn far_plane_triangle_writes_no_colour_where_the_depth_test_fails() {
    use fixel::geometry::{ClipVertex, Cull, Viewport};
    use fixel::math::Fx;
    use fixel::pipeline::{DepthTest, Draw, DrawMode, Projection, Shading};
    use fixel::surface::Frame;
    use fixel::Rgb565;
    let v = |p: [i32; 4]| ClipVertex {
        position: p.map(Fx::from_bits),
        uv: [Fx::ZERO; 2],
        color: [256, 128, 64],
    };
    let tri = [
        v([-71336, -18578, 232050, 282373]),
        v([-1261220764, 435315991, -1697722636, -765177693]),
        v([1874167182, -646984291, 2147483647, 1137859497]),
    ];
    let mode = DrawMode {
        projection: Projection::Exact,
        shading: Shading::Gouraud,
        depth: DepthTest::Less,
        cull: Cull::None,
        ..DrawMode::default()
    };
    let (w, h) = (127u32, 1u32);
    let vp = Viewport::new(0, 0, w, h).unwrap();
    let draw = Draw::dynamic(mode, None, vp).unwrap();
    let draw_into = |kept: bool| {
        let mut color = vec![Rgb565::new(0, 0, 0); (w * h) as usize];
        let mut depth = vec![u16::MAX; (w * h) as usize];
        let frame = Frame::new(&mut color, w, h).unwrap();
        let mut frame = if kept {
            frame.with_depth_kept(&mut depth).unwrap()
        } else {
            frame.with_depth(&mut depth).unwrap()
        };
        draw.clip_triangles(&[tri], &mut frame).unwrap();
        (color, depth)
    };
    let (color, depth) = draw_into(false);
    let written: Vec<usize> = (0..color.len())
        .filter(|&i| color[i] != Rgb565::new(0, 0, 0))
        .collect();
    for &i in &written {
        assert!(
            depth[i] < u16::MAX,
            "column {i} written at depth {}",
            depth[i]
        );
    }
    assert_eq!(
        (color, depth),
        draw_into(true),
        "the floor changed the picture"
    );
}

/// A typed affine draw of a triangle whose vertices have `w` between 0.0023 and 0.0104 (one
/// behind the `w >= 2^-8` plane) into a 33 x 27 frame: the frame's depth floor stays at or
/// below every depth stored (it once ended at 29824 over a stored 21172).
#[test]
fn depth_floor_of_a_clipped_tiny_w_triangle_is_below_its_depths() {
    use fixel::geometry::{ClipVertex, Cull, Viewport};
    use fixel::math::Fx;
    use fixel::pipeline::{Affine, DepthLess, Draw, ModulateIntensity, Pipeline};
    use fixel::surface::{Frame, RenderTarget};
    use fixel::texture::{Bilinear, Repeat, Texture};
    use fixel::Rgb565;
    let v = |p: [f64; 4]| ClipVertex {
        position: p.map(Fx::from_num),
        uv: [Fx::ZERO; 2],
        color: [0, 0, 0],
    };
    let tri = [
        v([-0.00679, -0.00845, 0.0, 0.00536]),
        v([0.02647, -0.00305, 0.0, 0.01036]),
        v([-0.00204, -0.00334, 0.00114, 0.0023]),
    ];
    let texels = [Rgb565::new(31, 0, 0); 64];
    let tex = Texture::new(&texels, 8, 8).unwrap();
    let (w, h) = (33u32, 27u32);
    let vp = Viewport::new(0, 0, w, h).unwrap();
    type TypedAffine = Pipeline<Affine, Bilinear, Repeat, Repeat, ModulateIntensity, DepthLess>;
    let draw = Draw::<Rgb565>::new::<TypedAffine>(Some(tex), vp, Cull::None).unwrap();
    let mut color = vec![Rgb565::new(0, 0, 0); (w * h) as usize];
    let mut depth = vec![0u16; (w * h) as usize];
    let mut frame = Frame::new(&mut color, w, h)
        .unwrap()
        .with_depth(&mut depth)
        .unwrap();
    let drawn = draw.clip_triangles(&[tri], &mut frame).unwrap();
    let floor = frame.depth_floor();
    let lowest = frame.depth().unwrap().iter().copied().min().unwrap();
    assert!(drawn > 0);
    assert!(
        floor <= lowest,
        "floor {floor} above a stored depth {lowest}"
    );
}
