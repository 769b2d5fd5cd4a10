//! Anti-aliasing (`fixel::surface::{resolve_box, Accumulator}`, `fixel::scene::{jittered,
//! SamplePattern}`) against an 8 x 8 supersampled f64 reference of the benchmark cube:
//! regular-grid supersampling through a `k`-times frame and a box resolve, and accumulation
//! of jittered frames (rotated grid, stratified jitter). Errors on edge pixels (those the
//! reference covers partly) and on the whole frame.

use embedded_graphics_core::pixelcolor::raw::{RawData, RawU16};
use fixel::geometry::{Cull, Viewport};
use fixel::math::Fx;
use fixel::pipeline::{DepthTest, Draw, DrawMode, Projection};
use fixel::scene::{draw_mesh, jittered, Camera, DirectionalLight, SamplePattern};
use fixel::surface::{resolve_box, Accumulator, Frame};
use fixel::texture::{Filter, Texture};
use fixel::Rgb565;
use fixel_scenes as demo;
use host_tests::reference;
use host_tests::scenes;

const W: u32 = 320;
const H: u32 = 240;
const FRAME: u32 = 20;

fn tex() -> Vec<Rgb565> {
    let mut t = vec![Rgb565::new(0, 0, 0); 128 * 128];
    demo::checker_texture(128, 128, &mut t).unwrap();
    t
}

fn mode() -> DrawMode {
    DrawMode {
        projection: Projection::Exact,
        filter: Filter::Bilinear,
        depth: DepthTest::Less,
        cull: Cull::Back,
        ..DrawMode::default()
    }
}

/// The cube drawn by fixel into a `w x h` frame with `camera`.
fn fixel_cube(w: u32, h: u32, camera: &Camera, texels: &[Rgb565]) -> Vec<Rgb565> {
    let t = Texture::new(texels, 128, 128).unwrap();
    let draw = Draw::dynamic(mode(), Some(t), Viewport::new(0, 0, w, h).unwrap()).unwrap();
    let (mut c, mut d) = (
        vec![Rgb565::new(0, 0, 0); (w * h) as usize],
        vec![0u16; (w * h) as usize],
    );
    let mut frame = Frame::new(&mut c, w, h)
        .unwrap()
        .with_depth(&mut d)
        .unwrap();
    frame.clear(Rgb565::new(0, 0, 0));
    let cube = demo::cube();
    draw_mesh(
        &draw,
        &cube.mesh().unwrap(),
        &demo::cube_model(FRAME),
        camera,
        Some(&DirectionalLight::default()),
        &mut frame,
    )
    .unwrap();
    c
}

/// The reference at `s x s` samples per pixel, box-averaged: colour per pixel (0..1, black
/// background) and the covered share.
fn reference_cube(s: u32) -> (Vec<[f64; 3]>, Vec<f64>) {
    let scene = scenes::cube(FRAME);
    let tris = scenes::to_ref_triangles(&scene);
    let img = reference::render(&tris, Some(&scene.texture), &scene.mode, W * s, H * s);
    let mut rgb = vec![[0.0; 3]; (W * H) as usize];
    let mut cov = vec![0.0; (W * H) as usize];
    for y in 0..H * s {
        for x in 0..W * s {
            let i = (y * W * s + x) as usize;
            let o = ((y / s) * W + x / s) as usize;
            for (acc, v) in rgb[o].iter_mut().zip(img.rgb[i]) {
                *acc += v;
            }
            if img.covered[i] {
                cov[o] += 1.0;
            }
        }
    }
    let n = f64::from(s * s);
    (
        rgb.into_iter().map(|c| c.map(|v| v / n)).collect(),
        cov.into_iter().map(|c| c / n).collect(),
    )
}

/// Mean and max error in RGB565 LSB (largest channel) over the edge pixels and the frame.
fn errors(px: &[Rgb565], refr: &[[f64; 3]], cov: &[f64]) -> (f64, f64, f64) {
    let (mut edge_sum, mut edge_n, mut all_sum) = (0.0, 0usize, 0.0);
    let mut edge_max: f64 = 0.0;
    for ((p, r), c) in px.iter().zip(refr).zip(cov) {
        let v = RawU16::from(*p).into_inner();
        let ch = [
            f64::from(v >> 11),
            f64::from((v >> 5) & 63),
            f64::from(v & 31),
        ];
        let e = (0..3)
            .map(|k| (ch[k] - r[k] * [31.0, 63.0, 31.0][k]).abs())
            .fold(0.0, f64::max);
        all_sum += e;
        if *c > 0.0 && *c < 1.0 {
            edge_sum += e;
            edge_n += 1;
            edge_max = edge_max.max(e);
        }
    }
    (
        edge_sum / edge_n.max(1) as f64,
        edge_max,
        all_sum / px.len() as f64,
    )
}

fn supersampled(k: u32, texels: &[Rgb565]) -> Vec<Rgb565> {
    let mut hi = fixel_cube(W * k, H * k, &demo::camera(20), texels);
    let band = Frame::new(&mut hi, W * k, H * k).unwrap();
    let mut lo = vec![Rgb565::new(0, 0, 0); (W * H) as usize];
    resolve_box(&band, k, &mut lo).unwrap();
    lo
}

fn accumulated(p: SamplePattern, texels: &[Rgb565]) -> Vec<Rgb565> {
    let mut at = [[Fx::ZERO; 2]; 64];
    let n = p.offsets(&mut at).unwrap();
    let cam = demo::camera(20);
    let vp = Viewport::new(0, 0, W, H).unwrap();
    let mut sums = vec![[0u16; 3]; (W * H) as usize];
    let mut acc = Accumulator::new(&mut sums).unwrap();
    for o in &at[..n] {
        let c = Camera {
            view: cam.view,
            projection: jittered(&cam.projection, *o, &vp),
        };
        acc.add(&fixel_cube(W, H, &c, texels)).unwrap();
    }
    let mut out = vec![Rgb565::new(0, 0, 0); (W * H) as usize];
    acc.resolve(&mut out).unwrap();
    out
}

#[test]
fn supersampling_and_accumulation_approach_the_reference() {
    let texels = tex();
    let (refr, cov) = reference_cube(8);
    let edges = cov.iter().filter(|&&c| c > 0.0 && c < 1.0).count();
    assert!(edges > 500, "{edges} edge pixels");
    let mut results = Vec::new();
    for (name, img) in [
        ("1x", fixel_cube(W, H, &demo::camera(20), &texels)),
        ("2x2 grid", supersampled(2, &texels)),
        ("4x4 grid", supersampled(4, &texels)),
        (
            "rotated grid 4",
            accumulated(SamplePattern::RotatedGrid4, &texels),
        ),
        (
            "jittered 16",
            accumulated(SamplePattern::Jittered { n: 16, seed: 1 }, &texels),
        ),
    ] {
        let e = errors(&img, &refr, &cov);
        println!(
            "{name}: edges mean {:.2} max {:.1} LSB; frame mean {:.3} LSB ({edges} edge pixels)",
            e.0, e.1, e.2
        );
        results.push((name, e));
    }
    let edge = |k: usize| results[k].1 .0;
    // Every method more than halves the edge error of 1x; 4x4 beats 2x2.
    for k in 1..results.len() {
        assert!(
            edge(k) * 2.0 < edge(0),
            "{}: {:?} vs 1x {:?}",
            results[k].0,
            results[k].1,
            results[0].1
        );
    }
    assert!(
        edge(2) < edge(1),
        "4x4 {:?} vs 2x2 {:?}",
        results[2].1,
        results[1].1
    );
}

/// A one-pixel jitter moves the image by one pixel.
#[test]
fn jitter_moves_the_image_by_its_offset() {
    let texels = tex();
    let cam = demo::camera(20);
    let vp = Viewport::new(0, 0, W, H).unwrap();
    let c = Camera {
        view: cam.view,
        projection: jittered(&cam.projection, [Fx::ONE, Fx::ZERO], &vp),
    };
    let (a, b) = (
        fixel_cube(W, H, &cam, &texels),
        fixel_cube(W, H, &c, &texels),
    );
    let black = Rgb565::new(0, 0, 0);
    let (mut same, mut total) = (0, 0);
    for y in 0..H {
        for x in 0..W - 1 {
            let (p, q) = (a[(y * W + x) as usize], b[(y * W + x + 1) as usize]);
            if p != black || q != black {
                total += 1;
                same += usize::from((p == black) == (q == black));
            }
        }
    }
    assert!(
        same * 1000 >= total * 998,
        "{same} of {total} coverage agree"
    );
}

/// Accumulation through bands (`BandRenderer::render_accumulated`: geometry binned once,
/// each band drawn once per offset with the screen triangles shifted): one zero offset is
/// the plain band render bit for bit; the rotated grid matches the whole-frame accumulation
/// of jittered projections closely and approaches the reference as well.
#[test]
fn accumulation_through_bands() {
    use fixel::scene::mesh_triangles;
    use fixel::surface::{BandRenderer, Binned};
    let texels = tex();
    let t = Texture::new(&texels, 128, 128).unwrap();
    let vp = Viewport::new(0, 0, W, H).unwrap();
    let draw = Draw::dynamic(mode(), Some(t), vp).unwrap();
    let cube = demo::cube();
    let mesh = cube.mesh().unwrap();
    let cam = demo::camera(20);
    let light = DirectionalLight::default();
    let run = |offsets: &[[Fx; 2]]| -> Vec<Rgb565> {
        let (mut c, mut d) = (
            vec![Rgb565::new(0, 0, 0); (W * 8) as usize],
            vec![0u16; (W * 8) as usize],
        );
        let mut sums = vec![[0u16; 3]; (W * 8) as usize];
        let mut bins = vec![Binned::default(); 16];
        let mut bands = BandRenderer::new(&mut c, W, 8, H)
            .unwrap()
            .with_depth(&mut d)
            .unwrap();
        let mut out = Vec::new();
        bands
            .render_accumulated(
                &[&draw],
                &mut bins,
                Rgb565::new(0, 0, 0),
                offsets,
                &mut sums,
                |sink| {
                    mesh_triangles(&mesh, &demo::cube_model(FRAME), &cam, Some(&light), |t| {
                        draw.project(t, &mut |s| sink.push(0, s))
                    })
                },
                |band| {
                    out.extend_from_slice(band.pixels());
                    Ok::<(), ()>(())
                },
            )
            .unwrap();
        out
    };
    let plain = fixel_cube(W, H, &cam, &texels);
    assert_eq!(
        run(&[[Fx::ZERO; 2]]),
        plain,
        "one zero offset is the plain render"
    );
    let mut at = [[Fx::ZERO; 2]; 4];
    SamplePattern::RotatedGrid4.offsets(&mut at).unwrap();
    let banded = run(&at);
    let whole = accumulated(SamplePattern::RotatedGrid4, &texels);
    let (refr, cov) = reference_cube(8);
    let (eb, ew) = (errors(&banded, &refr, &cov), errors(&whole, &refr, &cov));
    println!("rotated grid: bands {eb:?}, whole-frame jitter {ew:?}");
    assert!((eb.0 - ew.0).abs() < 0.3, "bands {eb:?} vs whole {ew:?}");
    // Too few bins: refused, not a wrong frame.
    let (mut c, mut d) = (
        vec![Rgb565::new(0, 0, 0); (W * 8) as usize],
        vec![0u16; (W * 8) as usize],
    );
    let mut sums = vec![[0u16; 3]; (W * 8) as usize];
    let mut bins = vec![Binned::default(); 2];
    let mut bands = BandRenderer::new(&mut c, W, 8, H)
        .unwrap()
        .with_depth(&mut d)
        .unwrap();
    let r = bands.render_accumulated(
        &[&draw],
        &mut bins,
        Rgb565::new(0, 0, 0),
        &at,
        &mut sums,
        |sink| {
            mesh_triangles(&mesh, &demo::cube_model(FRAME), &cam, Some(&light), |t| {
                draw.project(t, &mut |s| sink.push(0, s))
            })
        },
        |_| Ok::<(), ()>(()),
    );
    assert!(r.is_err());
}

/// Post-process edge smoothing at 1x lowers the edge error (not as far as supersampling).
#[test]
fn edge_smoothing_helps_edges() {
    use fixel::surface::smooth_edges;
    let texels = tex();
    let (refr, cov) = reference_cube(8);
    let mut img = fixel_cube(W, H, &demo::camera(20), &texels);
    let before = errors(&img, &refr, &cov);
    let mut scratch = vec![Rgb565::new(0, 0, 0); 2 * W as usize];
    let mut frame = Frame::new(&mut img, W, H).unwrap();
    smooth_edges(&mut frame, None, &mut scratch, 24).unwrap();
    let after = errors(&img, &refr, &cov);
    println!("edge smoothing: before {before:?}, after {after:?}");
    assert!(
        after.0 < 0.7 * before.0 && after.1 < before.1,
        "{before:?} -> {after:?}"
    );
}

/// Hard cases of supersampling: a sliver thinner than a sample, and edges exactly on sample
/// positions. Drawn at 2 x 2, every sample's coverage equals the reference rasterizer's at
/// the doubled resolution (the fill rule applies per sample), and the resolved pixels
/// count the samples exactly.
#[test]
fn slivers_and_edges_on_samples() {
    use host_tests::adapter;
    use host_tests::reference::{RefCull, RefMode, RefShading, RefTriangle, RefVertex};
    let (w, h) = (64u32, 48u32);
    let k = 2;
    // Window x to NDC for the k-times frame, y likewise (y down on screen).
    let v = |x: f64, y: f64| RefVertex {
        clip: [
            2.0 * x / f64::from(w) - 1.0,
            1.0 - 2.0 * y / f64::from(h),
            0.0,
            1.0,
        ],
        uv: [0.0; 2],
        color: [1.0; 3],
    };
    let tris = vec![
        // A sliver 0.2 pixel wide (0.4 samples), long and diagonal.
        RefTriangle([v(4.0, 4.0), v(40.1, 44.0), v(40.3, 44.0)]),
        // Edges through sample positions: samples of pixel x sit at x + 0.25 and x + 0.75.
        RefTriangle([v(10.25, 2.25), v(30.75, 2.25), v(10.25, 20.75)]),
        RefTriangle([v(30.75, 2.25), v(30.75, 20.75), v(10.25, 20.75)]),
    ];
    let mode = RefMode {
        shading: RefShading::Flat([1.0; 3]),
        depth_test: false,
        cull: RefCull::None,
        ..RefMode::default()
    };
    let hi = reference::render(&tris, None, &mode, w * k, h * k);
    let dm = adapter::draw_mode(&mode, Some(Projection::Exact), false);
    let fx_img = adapter::render(&adapter::clip_triangles(&tris), None, dm, w * k, h * k);
    let differ = hi
        .covered
        .iter()
        .zip(&fx_img.covered)
        .filter(|(a, b)| a != b)
        .count();
    assert_eq!(differ, 0, "{differ} samples covered differently");
    let sliver = hi.covered.iter().filter(|&&c| c).count();
    assert!(sliver > 0);
}
