//! Stability in every mode: vertices at the fixed-point limits and degenerate triangles
//! (points, repeated vertices, collinear, zero area after snapping) draw without a panic or
//! a write out of bounds, and degenerate ones draw nothing.

use crate::common::*;
use crate::helpers::*;
use fixel::geometry::Cull;
use fixel::pipeline::{DepthTest, DrawMode, Projection, Shading};
use fixel::texture::{Filter, Wrap};
use host_tests::adapter;
use host_tests::reference;

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
